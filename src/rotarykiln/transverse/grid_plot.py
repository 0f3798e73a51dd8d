"""Figures of a grid simulation: time series, layer sizes, CV colour maps and an animation."""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import InputError

__all__ = [
    "animate_grid",
    "plot_colour_map",
    "plot_layer_sizes",
    "plot_time_series",
    "raster_cells",
]

_FIELDS = {
    "extent": ("extent of mixing (-)", "Blues", (0.0, 1.0)),
    "size": ("mean particle size (mm)", "Greens", (0.0, 6.3)),
    "temperature": ("mean temperature (K)", "Reds", None),
    "share": ("share of second material (-)", "Oranges", (0.0, 1.0)),
}


def plot_time_series(result, ax=None):
    """Extent of mixing, mean temperatures and volatile evolution against time.

    Returns the Figure (three stacked Axes; with ``ax``, the extent of mixing on that Axes).
    """
    import matplotlib.pyplot as plt

    if ax is not None:
        ax.plot(result.t, 100 * result.extent)
        ax.set_xlabel("time (s)")
        ax.set_ylabel("extent of mixing (% of maximum)")
        return ax.figure
    fig, axes = plt.subplots(3, 1, sharex=True, figsize=(6, 7))
    axes[0].plot(result.t, 100 * result.extent)
    axes[0].set_ylabel("extent of mixing\n(% of max)")
    for i, name in enumerate(result.names):
        axes[1].plot(result.t, result.temperature[:, i], label=f"mean {name}")
    axes[1].set_ylabel("temperature (K)")
    axes[1].legend()
    axes[2].plot(result.t, 100 * result.volatiles)
    axes[2].set_ylabel(f"volatiles\n(% of {result.names[1]} feed)")
    axes[2].set_xlabel("time (s)")
    _name_case(fig, result)
    fig.tight_layout()
    return fig


def plot_layer_sizes(result, ax=None):
    """Mean particle size of each stagnant layer (1 = wall) and of the inner/outer layers."""
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots()
    for j in range(result.layer_sizes.shape[1]):
        ax.plot(result.t, 1e3 * result.layer_sizes[:, j], label=f"layer {j + 1}")
    ax.plot(result.t, 1e3 * result.inner_size, "k--", label="inner")
    ax.plot(result.t, 1e3 * result.outer_size, "k:", label="outer")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("mean particle size (mm)")
    ax.legend(
        fontsize="small", ncol=4, loc="upper center", bbox_to_anchor=(0.5, -0.13), frameon=False
    )
    _name_case(ax.figure, result)
    ax.figure.tight_layout()
    return ax.figure


def _name_case(fig, result) -> None:
    """Title the figure with the case's name (when the result has one and no title is set)."""
    name = getattr(result, "name", "")
    if name and not fig.get_suptitle():
        fig.suptitle(name, fontsize="medium")


def raster_cells(geom, n: int = 160):
    """Pixel map of the cross-section: index of the CV under each pixel (-1 outside the bed).

    Active CVs are numbered 0..n_active-1, stagnant CVs n_active + layer*zones + zone.
    Returns (index array (n, n), extent [xmin, xmax, ymin, ymax]).
    """
    r = geom.radius
    c = r * np.cos(geom.theta)
    half = r * np.sin(geom.theta)
    xs = np.linspace(-r, r, n)
    ys = np.linspace(-r, -c + 0.02 * r, n)
    x, y = np.meshgrid(xs, ys)
    inside = (x * x + y * y <= r * r) & (y <= -c)
    depth = np.sqrt(np.maximum(r * r - x * x, 0.0)) - c
    y_i = -c - geom.x_al * depth
    idx = np.full(x.shape, -1, dtype=int)
    n_az = len(geom.levels)
    first = np.concatenate([[0], np.cumsum(geom.levels)[:-1]])
    act = inside & (y > y_i)
    zone = np.clip(((x + half) / (2 * half) * n_az).astype(int), 0, n_az - 1)
    lev_n = np.asarray(geom.levels)[zone]
    with np.errstate(invalid="ignore", divide="ignore"):
        frac = np.where(depth > 0, (y - y_i) / (geom.x_al * depth), 0.0)
    level = np.clip((frac * lev_n).astype(int), 0, lev_n - 1)
    idx[act] = (first[zone] + level)[act]
    st = inside & ~act
    o = geom.extra["origin"]
    px, py = x - o[0], y - o[1]
    dist = np.hypot(px, py)
    with np.errstate(invalid="ignore", divide="ignore"):
        ux, uy = px / dist, py / dist
    b = o[0] * ux + o[1] * uy
    t = -b + np.sqrt(np.maximum(b * b - (o @ o - r * r), 0.0))
    s = np.clip(dist / t, 0.0, 1.0)
    layer = np.clip(((1 - s) * geom.layers).astype(int), 0, geom.layers - 1)
    wx, wy = o[0] + t * ux, o[1] + t * uy
    phi = np.arctan2(wx, -wy)
    zz = np.clip(
        ((geom.theta - phi) / (2 * geom.theta) * geom.zones).astype(int), 0, geom.zones - 1
    )
    idx[st] = (geom.n_active + layer * geom.zones + zz)[st]
    return idx, [-r, r, ys[0], ys[-1]]


def plot_colour_map(result, time: float, field: str = "extent", ax=None, n: int = 160):
    """Colour map of one CV field of the snapshot nearest to ``time``; returns the Figure."""
    import matplotlib.pyplot as plt

    if not result.snapshots:
        raise InputError("snapshot_times", "()", "non-empty to draw colour maps")
    if field not in _FIELDS:
        raise InputError("field", field, f"one of {', '.join(_FIELDS)}")
    ts = np.array(sorted(result.snapshots))
    snap = result.snapshots[float(ts[np.argmin(np.abs(ts - time))])]
    if field not in snap["active"]:
        raise InputError("field", field, "'temperature' only for runs with heating")
    label, cmap, lims = _FIELDS[field]
    values = np.concatenate([snap["active"][field], snap["stagnant"][field].ravel()])
    if field == "size":
        values = 1e3 * values
    idx, ext = raster_cells(result.geometry, n)
    img = np.where(idx >= 0, values[np.maximum(idx, 0)], np.nan)
    if ax is None:
        _, ax = plt.subplots(figsize=(5, 3.2))
    vmin, vmax = lims if lims else (np.nanmin(values), np.nanmax(values))
    im = ax.imshow(img, origin="lower", extent=ext, cmap=cmap, vmin=vmin, vmax=vmax)
    r = result.geometry.radius
    th = np.linspace(0, 2 * np.pi, 200)
    ax.plot(r * np.cos(th), r * np.sin(th), "k-", lw=0.5)
    ax.set_ylim(ext[2], ext[3])
    ax.set_aspect("equal")
    ax.set_axis_off()
    ax.set_title(f"t = {snap['t']:.1f} s")
    ax.figure.colorbar(im, ax=ax, label=label, shrink=0.8)
    _name_case(ax.figure, result)
    return ax.figure


def animate_grid(result, path, field: str = "extent", fps: int = 4) -> bool:
    """Write an animated GIF of a CV field over the stored snapshots (needs Pillow).

    Returns False (and writes nothing) when Pillow is not installed.
    """
    try:
        import PIL  # noqa: F401
    except ImportError:
        return False
    import os
    import tempfile

    import matplotlib.pyplot as plt
    from matplotlib.animation import FuncAnimation, PillowWriter

    times = sorted(result.snapshots)
    fig, ax = plt.subplots(figsize=(5, 3.2))
    plot_colour_map(result, times[0], field, ax=ax)

    def update(k):
        for im in ax.images:
            im.remove()
        snap = result.snapshots[times[k]]
        values = np.concatenate([snap["active"][field], snap["stagnant"][field].ravel()])
        if field == "size":
            values = 1e3 * values
        idx, ext = raster_cells(result.geometry)
        img = np.where(idx >= 0, values[np.maximum(idx, 0)], np.nan)
        label, cmap, lims = _FIELDS[field]
        vmin, vmax = lims if lims else (np.nanmin(values), np.nanmax(values))
        ax.imshow(img, origin="lower", extent=ext, cmap=cmap, vmin=vmin, vmax=vmax)
        ax.set_title(f"t = {snap['t']:.1f} s")
        return ax.images

    anim = FuncAnimation(fig, update, frames=len(times))
    folder = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(suffix=".gif", dir=folder)
    os.close(fd)
    try:
        anim.save(tmp, writer=PillowWriter(fps=fps))
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)
        plt.close(fig)
    return True
