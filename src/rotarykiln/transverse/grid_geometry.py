r"""Control-volume network of the transverse grid simulation (Van Puyvelde 1999, ch. 8).

The thesis gives the structure of its grid but not every equation (the interface and the
"modified annulus" areas are described, not printed). The choices made here:

* **Stagnant layer**: ``layers`` layers equidistant between the centre of rotation O (on the
  active/stagnant interface at mid-chord) and the wall; layer areas follow the annulus about O,
  :math:`A_j \propto s_{out}^2 - s_{in}^2` with s the fractional distance from O, scaled to sum to
  :math:`A_{SL}`. Each layer is cut into ``zones`` CVs of equal area; every stagnant CV holds its
  material for :math:`\tau_{SL} = 2\theta/(\omega\,n_{zones})` (solid-body rotation with the
  drum through the bed angle 2θ), the same for all, as the thesis states.
* **Active layer**: ``active_zones`` zones of equal width along the chord, thickness
  :math:`X_{AL}\,h(x)` (h the local bed depth), so their areas sum to :math:`A_{AL}`. Layer j
  (j = 0 at the wall) discharges into zone j of the upper half and is refilled from zone
  ``active_zones - 1 - j`` of the lower half, so ``active_zones = 2 layers``. Zone flux = previous
  zone flux ± exchange with the stagnant layer (thesis). Zones are split in height into 1 (end
  zones) or alternately 2 and 3 CVs (the 1-2-3-2-3-2-3-2-3-1 pattern, 22 CVs), of equal area and
  flux shares :math:`(2i+1)/n^2` (velocity linear in height, slow at the interface).
* **Interlacing**: between two zones, sources and targets (bottom to top, the stagnant stream
  lowest) are laid on a cumulative-flux axis and connected by their overlaps, so that the
  steady CV contents equal the CV areas exactly and material of different levels meets.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from rotarykiln.errors import InputError, check_positive, check_range
from rotarykiln.geometry import half_angle_from_fill
from rotarykiln.transverse.active_layer import (
    vanpuyvelde_active_layer_proportion,
    vanpuyvelde_active_layer_velocity,
    warn_if_not_rolling,
)

__all__ = ["GridGeometry", "build_grid", "default_level_pattern"]


def default_level_pattern(active_zones: int) -> list[int]:
    """CVs per active zone: 1 at both ends, alternately 2 and 3 between (thesis: 22 for 10).

    Examples
    --------
    >>> default_level_pattern(10)
    [1, 2, 3, 2, 3, 2, 3, 2, 3, 1]
    """
    if active_zones < 2:
        raise InputError("grid.active_zones", active_zones, ">= 2")
    inner = [2 if k % 2 == 0 else 3 for k in range(active_zones - 2)]
    return [1, *inner, 1]


@dataclass(frozen=True)
class GridGeometry:
    """The CV network: areas, fluxes, residence times, routing and drawing coordinates (SI).

    Active CVs are numbered zone by zone, bottom to top; stagnant CVs are ``[layer, zone]``
    with layer 0 at the wall and zone 0 where material enters from the active layer.
    """

    radius: float
    omega: float
    fill: float
    theta: float
    x_al: float
    bed_area: float
    active_area: float
    stagnant_area: float
    v_al: float
    layers: int
    zones: int
    levels: tuple[int, ...]
    zone_of_cv: np.ndarray  # (n_act,)
    level_of_cv: np.ndarray  # (n_act,)
    cv_area: np.ndarray  # (n_act,) m2
    cv_flux: np.ndarray  # (n_act,) m2/s
    cv_residence: np.ndarray  # (n_act,) s
    cv_velocity: np.ndarray  # (n_act,) m/s, transport velocity (zone width / residence time)
    velocity_factor: float  # V_AL (eq 5.6) / area-weighted mean transport velocity
    layer_area: np.ndarray  # (layers,) m2
    layer_flux: np.ndarray  # (layers,) m2/s
    stagnant_residence: float  # s per stagnant CV
    # routing: weights[src, dest] of flux; dest = active CVs then stagnant layer entries
    weights: np.ndarray  # (n_act, n_act + layers), rows sum to 1
    bottom: np.ndarray  # (n_act, n_act + layers) weights of the bottom group, rows sum to 1 or 0
    top: np.ndarray  # (n_act, n_act + layers) weights of the top group
    bottom_share: np.ndarray  # (n_act,) flux share of the bottom group
    feed: np.ndarray  # (layers, n_act) share of each stagnant layer's discharge per CV
    cv_centroid: np.ndarray  # (n_act, 2) m
    stagnant_centroid: np.ndarray  # (layers, zones, 2) m
    extra: dict = field(default_factory=dict)

    @property
    def n_active(self) -> int:
        return len(self.cv_area)

    @property
    def chord(self) -> float:
        return 2 * self.radius * np.sin(self.theta)

    def time_step(self) -> tuple[float, int]:
        r"""Sampling time step of eq 8.2 and the number of steps per stagnant shift.

        .. math:: \tau_{SAMP} = \tau_{SL} / (\operatorname{int}(\tau_{SL}/\tau_{min}) + 1)
        """
        tau_min = min(float(self.cv_residence.min()), self.stagnant_residence)
        n = int(self.stagnant_residence / tau_min) + 1
        return self.stagnant_residence / n, n


def _depth_integral(x, radius, c):
    """Integral of the local bed depth sqrt(R^2 - x^2) - c from 0 to x."""
    r2 = radius * radius
    return 0.5 * (x * np.sqrt(np.maximum(r2 - x * x, 0.0)) + r2 * np.arcsin(x / radius)) - c * x


def _overlap_weights(src_flux, tgt_flux):
    """Flux matrix between sources and targets laid bottom-to-top on a cumulative-flux axis."""
    s_edges = np.concatenate([[0.0], np.cumsum(src_flux)])
    t_edges = np.concatenate([[0.0], np.cumsum(tgt_flux)])
    lo = np.maximum(s_edges[:-1, None], t_edges[None, :-1])
    hi = np.minimum(s_edges[1:, None], t_edges[None, 1:])
    w = np.maximum(hi - lo, 0.0)
    w[w < 1e-14 * s_edges[-1]] = 0.0
    return w


def build_grid(
    radius: float,
    omega: float,
    fill: float,
    *,
    layers: int = 5,
    zones: int = 20,
    levels: list[int] | None = None,
    convention: str = "tables",
) -> GridGeometry:
    """Build the CV network of the grid simulation for a drum cross-section.

    Parameters
    ----------
    radius : float, m
        Drum inner radius.
    omega : float, rad/s
        Drum rotation rate.
    fill : float, -
        Fractional fill.
    layers : int
        Stagnant layers (thesis 5); the active layer has ``2 layers`` zones.
    zones : int
        Stagnant CVs per layer (thesis 20).
    levels : list of int, optional
        CVs per active zone (default 1-2-3-...-1).
    convention : {"tables", "eq5.3"}
        V_AL convention used to scale CV velocities for the correlations.

    Returns
    -------
    GridGeometry

    Raises
    ------
    InputError
        When the grid is too coarse to resolve the active layer: fewer than 2 layers or 4
        stagnant zones, or stagnant layers at mid-chord more than twice as thick as the active
        layer (``layers >= (1 - X_AL)/(2 X_AL)``).

    Examples
    --------
    >>> g = build_grid(0.285, 9 / 60 * 2 * np.pi, 0.25)
    >>> g.n_active, round(float(g.cv_area.sum() / g.active_area), 12)
    (22, 1.0)

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS.
    """
    check_positive("radius", radius, "m")
    check_positive("omega", omega, "rad/s")
    check_range("fill", fill, 0.0, 0.5, closed_high=True)
    if int(layers) != layers or layers < 2:
        raise InputError("grid.layers", layers, ">= 2 (too coarse to resolve the active layer)")
    if int(zones) != zones or zones < 4:
        raise InputError("grid.zones", zones, ">= 4 (too coarse to resolve the bed circulation)")
    warn_if_not_rolling(omega, radius, fill)
    x_al = float(vanpuyvelde_active_layer_proportion(omega, fill))
    need = int(np.ceil((1 - x_al) / (2 * x_al) - 1e-9))
    if layers < need:
        raise InputError(
            "grid.layers",
            layers,
            f">= {need}: with X_AL = {x_al:.3f} each stagnant layer would be more than twice as "
            "thick as the active layer (grid too coarse to resolve the active layer)",
        )
    n_az = 2 * layers
    levels = default_level_pattern(n_az) if levels is None else [int(v) for v in levels]
    if len(levels) != n_az or min(levels) < 1:
        raise InputError("grid.levels", levels, f"{n_az} positive integers (2 per layer)")

    theta = float(half_angle_from_fill(fill))
    c = radius * np.cos(theta)
    half = radius * np.sin(theta)
    a_bed = fill * np.pi * radius**2
    a_al = x_al * a_bed
    a_sl = a_bed - a_al
    v_al = float(vanpuyvelde_active_layer_velocity(omega, radius, x_al, convention=convention))

    # stagnant layers: annulus about the centre of rotation, layer 0 at the wall
    s = 1.0 - np.arange(layers + 1) / layers  # s_out of layer j = s[j], s_in = s[j+1]
    layer_area = a_sl * (s[:-1] ** 2 - s[1:] ** 2)
    tau_sl = 2.0 * theta / (omega * zones)
    layer_flux = layer_area / (zones * tau_sl)
    g_total = layer_flux.sum()

    # active zones along the chord (zone 0 at the upper apex, x = -half)
    x_edges = np.linspace(-half, half, n_az + 1)
    zone_area = x_al * np.diff(_depth_integral(x_edges, radius, c))
    zone_area *= a_al / zone_area.sum()  # exact closure
    zone_flux = np.empty(n_az)
    for z in range(n_az):
        if z < layers:
            zone_flux[z] = layer_flux[: z + 1].sum()
        else:
            zone_flux[z] = g_total - layer_flux[n_az - z : layers].sum()
    # CVs
    zone_of_cv = np.concatenate([np.full(n, z) for z, n in enumerate(levels)])
    level_of_cv = np.concatenate([np.arange(n) for n in levels])
    n_of_cv = np.array([levels[z] for z in zone_of_cv])
    cv_area = zone_area[zone_of_cv] / n_of_cv
    cv_flux = zone_flux[zone_of_cv] * (2 * level_of_cv + 1) / n_of_cv**2
    cv_res = cv_area / cv_flux
    width = 2 * half / n_az
    cv_vel = width / cv_res
    velocity_factor = v_al / (np.sum(cv_area * cv_vel) / a_al)
    first_cv = np.concatenate([[0], np.cumsum(levels)[:-1]])

    # routing across zone boundaries b = 0..n_az
    n_act = len(cv_area)
    n_dest = n_act + layers
    flux = np.zeros((n_act, n_dest))
    bottom = np.zeros((n_act, n_dest))
    top = np.zeros((n_act, n_dest))
    feed = np.zeros((layers, len(cv_area)))
    for b in range(n_az + 1):
        src_ids, src_flux = [], []
        if b < layers:  # stagnant layer b discharges at the bottom of zone b
            src_ids.append(-1)
            src_flux.append(layer_flux[b])
        if b > 0:
            ids = list(range(first_cv[b - 1], first_cv[b - 1] + levels[b - 1]))
            src_ids += ids
            src_flux += list(cv_flux[ids])
        tgt_ids, tgt_flux = [], []
        if b - 1 >= layers:  # zone b-1 (lower half) refills layer n_az-1-(b-1)
            j = n_az - b
            tgt_ids.append(n_act + j)
            tgt_flux.append(layer_flux[j])
        if b < n_az:
            ids = list(range(first_cv[b], first_cv[b] + levels[b]))
            tgt_ids += ids
            tgt_flux += list(cv_flux[ids])
        w = _overlap_weights(np.array(src_flux), np.array(tgt_flux))
        for si, sid in enumerate(src_ids):
            row = w[si]
            if sid == -1:
                for ti, tid in enumerate(tgt_ids):
                    feed[b, tid] += row[ti] / layer_flux[b]
                continue
            for ti, tid in enumerate(tgt_ids):
                flux[sid, tid] += row[ti]
    out = flux.sum(axis=1)
    if not np.allclose(out, cv_flux, rtol=1e-10):
        raise InputError("grid", "routing", "consistent (internal error: flux not closed)")
    weights = flux / out[:, None]
    # bottom group = the lowest destination of each source; top group = the rest
    for i in range(n_act):
        dests = np.flatnonzero(weights[i])
        # order destinations bottom-up: stagnant entries first, then by CV number
        order = sorted(dests, key=lambda d: (0, d) if d >= n_act else (1, d))
        low = order[0]
        bottom[i, low] = 1.0
        if len(order) > 1:
            rest = weights[i].copy()
            rest[low] = 0.0
            top[i] = rest / rest.sum()
    bottom_share = np.array(
        [weights[i, np.flatnonzero(bottom[i])[0]] if top[i].any() else 1.0 for i in range(n_act)]
    )

    # drawing coordinates: drum centre at the origin, flat bed surface at y = -c
    x_mid = 0.5 * (x_edges[:-1] + x_edges[1:])
    depth = np.sqrt(radius**2 - x_mid**2) - c
    xc = x_mid[zone_of_cv]
    yc = -c - x_al * depth[zone_of_cv] * (1 - (level_of_cv + 0.5) / n_of_cv)
    y_o = -c - x_al * (radius - c)
    phi = theta - (np.arange(zones) + 0.5) * 2 * theta / zones  # zone 0 at the lower apex
    wall = np.stack([radius * np.sin(phi), -radius * np.cos(phi)], axis=-1)
    s_mid = 0.5 * (s[:-1] + s[1:])
    origin = np.array([0.0, y_o])
    stag_c = origin + s_mid[:, None, None] * (wall[None, :, :] - origin)
    return GridGeometry(
        radius=float(radius),
        omega=float(omega),
        fill=float(fill),
        theta=theta,
        x_al=x_al,
        bed_area=float(a_bed),
        active_area=float(a_al),
        stagnant_area=float(a_sl),
        v_al=v_al,
        layers=int(layers),
        zones=int(zones),
        levels=tuple(levels),
        zone_of_cv=zone_of_cv,
        level_of_cv=level_of_cv,
        cv_area=cv_area,
        cv_flux=cv_flux,
        cv_residence=cv_res,
        cv_velocity=cv_vel,
        velocity_factor=float(velocity_factor),
        layer_area=layer_area,
        layer_flux=layer_flux,
        stagnant_residence=float(tau_sl),
        weights=weights,
        bottom=bottom,
        top=top,
        bottom_share=bottom_share,
        feed=feed,
        cv_centroid=np.stack([xc, yc], axis=-1),
        stagnant_centroid=stag_c,
        extra={"s_edges": s, "x_edges": x_edges, "origin": origin},
    )
