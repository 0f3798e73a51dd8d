r"""Grid (control-volume) simulation of transverse mixing, segregation and heating (ch. 8-9).

A transverse slice of bed (1 m of drum) is followed in time on the CV network of
:mod:`rotarykiln.transverse.grid_geometry`. Every CV holds, for each material (index 0: the
first material, e.g. ash or black shale; index 1: the second, e.g. raw shale or orange shale) and
each size class, its volume (m3 per m of drum), its enthalpy (J per m), the volatiles released
(kg per m, second material only) and the contact distance of the cell (m). All of these are
extensive and are moved by the same fractions, so mass and energy are conserved to rounding.

Per time step :math:`\tau_{SAMP}` (eq 8.2):

1. each active CV passes the fraction :math:`\tau_{SAMP}/\tau_{CV}` of its content on along the
   network; the part going to the lowest destination (the stagnant layer, or the lower CV of
   the next zone) is enriched in the classes finer than the CV mean by the proportion
   :math:`P_{in}(\bar d/d_i, V_{CV})` of eq 7.3; coarser classes fill the rest, so every
   outflow keeps its volume (thesis, ch 8);
2. each stagnant layer releases, evenly over the steps of one stagnant residence time, the CV
   that reached its end, and collects what the active layer returns (pure delay);
3. mixing in the active CVs (eq 8.1): :math:`l \leftarrow \min(l_{f,CV}, l + \alpha_{CV}\tau)`
   with α and l_f of eqs 6.8-6.11 on the CV's own area, mean size, material ratio and velocity
   (the transport velocity scaled so that its area mean equals V_AL of eq 5.6).

Every stagnant shift (``steps_per_shift`` steps) the stagnant CVs move on by one zone and, when
heating is on, every cell exchanges heat (eqs 9.1-9.7) over that interval, enthalpies are
updated, temperatures follow from H(T) and the released volatiles are raised to the yield at
the new temperature (never lowered). Totals are checked every step.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

from rotarykiln.errors import ConvergenceError, InputError, check_nonnegative, check_positive
from rotarykiln.progress import progress_bar
from rotarykiln.tables import with_units
from rotarykiln.transverse.grid_geometry import GridGeometry
from rotarykiln.transverse.heating import cell_heat_exchange
from rotarykiln.transverse.mixing import (
    D_LIMIT_FINAL,
    D_LIMIT_RATE,
    K_FINAL,
    K_RATE,
    RATIO_LIMIT_FINAL,
    RATIO_LIMIT_RATE,
)
from rotarykiln.transverse.pyrolysis import Thermochemistry
from rotarykiln.transverse.segregation import segregation_coefficients

__all__ = ["GridMaterial", "GridResult", "HeatingOptions", "simulate_grid"]

log = logging.getLogger(__name__)

_MASS_TOL = 1e-12


@dataclass(frozen=True)
class GridMaterial:
    """One granular material of the grid simulation.

    Parameters
    ----------
    name : str
    volume : float, m3 per m of drum (= cross-section area, m2)
        Bulk volume of this material in the slice.
    fractions : array (K,), -
        Volume fraction of each size class (normalised).
    bulk_density : float, kg/m3
        Bulk density in the bed (mass per bulk volume).
    particle_density : float, kg/m3
        Particle density (for the particle surface, 6 m / (rho_p d)).
    temperature : float, K
        Initial temperature (uniform over classes).
    thermo : Thermochemistry, optional
        H(T) and volatiles; needed when heating is on.
    """

    name: str
    volume: float
    fractions: np.ndarray
    bulk_density: float = 700.0
    particle_density: float = 1300.0
    temperature: float = 300.0
    thermo: Thermochemistry | None = None


@dataclass(frozen=True)
class HeatingOptions:
    """Switches of the heat-transfer model (ch 9)."""

    emissivity: float = 0.9
    balance: str = "pairwise"


@dataclass(frozen=True)
class GridResult:
    """Time series and snapshots of a grid simulation (SI units; sizes in m)."""

    geometry: GridGeometry
    sizes: np.ndarray
    names: tuple[str, str]
    t: np.ndarray
    contact: np.ndarray
    final_contact_bed: float
    extent: np.ndarray
    temperature: np.ndarray  # (nt, 2) mass-weighted mean temperature of each material
    volatiles: np.ndarray  # (nt,) fraction of the second material's original mass
    layer_sizes: np.ndarray  # (nt, layers) mean size of each stagnant layer (0 = wall)
    inner_size: np.ndarray
    outer_size: np.ndarray
    mass_error: float
    energy_error: float
    time_step: float
    snapshots: dict = field(default_factory=dict)
    name: str = ""  # the case, for titles

    @property
    def mixing_time(self) -> float:
        """Time to reach 95 % of the largest contact distance of the run [s]."""
        peak = float(np.max(self.contact))
        if peak <= 0:
            return float("inf")
        return float(self.t[np.argmax(self.contact >= 0.95 * peak)])

    @property
    def final_contact(self) -> float:
        """Contact distance at the end of the run [m]."""
        return float(self.contact[-1])

    def volatile_rate(self, t_end: float) -> float:
        """Mean rate of volatile evolution over [0, t_end] [fraction of shale feed per s]."""
        return float(np.interp(t_end, self.t, self.volatiles)) / t_end

    def to_frame(self) -> pd.DataFrame:
        """Time series as a DataFrame (temperatures in K, sizes in m)."""
        import pandas as pd

        df = pd.DataFrame(
            {
                "t_s": self.t,
                "contact_m": self.contact,
                "extent_percent": 100 * self.extent,
                f"T_{self.names[0]}_K": self.temperature[:, 0],
                f"T_{self.names[1]}_K": self.temperature[:, 1],
                "volatiles_percent": 100 * self.volatiles,
                "inner_size_m": self.inner_size,
                "outer_size_m": self.outer_size,
            }
        )
        for j in range(self.layer_sizes.shape[1]):
            df[f"layer{j + 1}_size_m"] = self.layer_sizes[:, j]
        return with_units(df, "transverse.grid")

    def plot(self, ax=None):
        """Extent of mixing, mean temperature of the second material and volatiles against t."""
        from rotarykiln.transverse.grid_plot import plot_time_series

        return plot_time_series(self, ax)


def _initial_fill(geom: GridGeometry, share: float, initial: str):
    """Volume share of material 1 in each active CV and stagnant CV (layer, zone)."""
    a_act = geom.cv_area
    a_st = np.repeat(geom.layer_area[:, None] / geom.zones, geom.zones, axis=1)
    areas = np.concatenate([a_act, a_st.ravel()])
    if initial == "layer":  # material 1 on top
        key = -np.concatenate([geom.cv_centroid[:, 1], geom.stagnant_centroid[..., 1].ravel()])
    elif initial == "smile":  # material 1 first, along the wall
        s_mid = 0.5 * (geom.extra["s_edges"][:-1] + geom.extra["s_edges"][1:])
        key = np.concatenate([np.full(len(a_act), 2.0), np.repeat(-s_mid, geom.zones)])
    else:
        raise InputError("initial", initial, "one of 'layer', 'smile'")
    order = np.argsort(key, kind="stable")
    need = share * areas.sum()
    cum = np.cumsum(areas[order])
    take = np.clip(need - (cum - areas[order]), 0.0, areas[order])
    frac = np.zeros_like(areas)
    frac[order] = take / areas[order]
    return a_act, a_st, frac[: len(a_act)], frac[len(a_act) :].reshape(a_st.shape)


def simulate_grid(
    geometry: GridGeometry,
    sizes,
    materials: tuple[GridMaterial, GridMaterial],
    *,
    duration: float,
    initial: str = "layer",
    segregation: bool = True,
    segregation_set: str | dict = "backfit",
    heating: HeatingOptions | None = None,
    snapshot_times=(),
    limits: dict | None = None,
) -> GridResult:
    """Run the grid simulation of a drum slice.

    Parameters
    ----------
    geometry : GridGeometry
        CV network (:func:`~rotarykiln.transverse.grid_geometry.build_grid`).
    sizes : array (K,), m
        Size classes shared by both materials.
    materials : (GridMaterial, GridMaterial)
        Their volumes are rescaled to fill the bed area exactly, keeping their ratio.
    duration : float, s
        Simulated time.
    initial : {"layer", "smile"}
        Material 1 on top ("layer") or along the wall under material 0 ("smile").
    segregation : bool
        Apply the segregation routing.
    segregation_set : {"backfit", "printed"} or dict
        Table 7.3 coefficient set of the routing (see
        :func:`~rotarykiln.transverse.segregation.segregation_coefficients`).
    heating : HeatingOptions, optional
        Heat transfer and pyrolysis (both materials need ``thermo``).
    snapshot_times : sequence of float, s
        Times at which the CV fields are stored (for colour maps).
    limits : dict, optional
        Mixing constants ``d_limit_rate``, ``ratio_limit_rate``, ``d_limit_final``,
        ``ratio_limit_final`` (SI).

    Returns
    -------
    GridResult

    Examples
    --------
    >>> from rotarykiln.transverse.grid_geometry import build_grid
    >>> g = build_grid(0.285, 9 / 60 * 2 * np.pi, 0.25)
    >>> mats = (GridMaterial("black", 1.06, [1.0]), GridMaterial("orange", 1.0, [1.0]))
    >>> r = simulate_grid(g, [2.51e-3], mats, duration=90.0)
    >>> r.mass_error < 1e-12, round(r.final_contact / r.final_contact_bed, 2)
    (True, 1.0)

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS.
    """
    d = np.atleast_1d(np.asarray(sizes, dtype=float))
    check_positive("sizes", d, "m")
    check_positive("duration", duration, "s")
    segregation_coefficients(1.0, segregation_set)  # InputError on an unknown set
    k_cls = len(d)
    lim = {
        "d_limit_rate": D_LIMIT_RATE,
        "ratio_limit_rate": RATIO_LIMIT_RATE,
        "d_limit_final": D_LIMIT_FINAL,
        "ratio_limit_final": RATIO_LIMIT_FINAL,
    } | (limits or {})
    fr = np.zeros((2, k_cls))
    for i, m in enumerate(materials):
        f = np.atleast_1d(np.asarray(m.fractions, dtype=float))
        check_nonnegative(f"{m.name}.fractions", f)
        if f.shape != (k_cls,) or f.sum() <= 0:
            raise InputError(f"{m.name}.fractions", f, f"{k_cls} non-negative values, not all 0")
        fr[i] = f / f.sum()
        check_positive(f"{m.name}.volume", m.volume, "m3/m")
    if heating is not None and any(m.thermo is None for m in materials):
        raise InputError("heating", "on", "used with a thermochemistry for both materials")
    share = materials[1].volume / (materials[0].volume + materials[1].volume)

    geom = geometry
    n_act, n_lay, n_zon = geom.n_active, geom.layers, geom.zones
    tau, n_sub = geom.time_step()
    # column layout: vol (2K) | enthalpy (2K) | volatiles (K) | contact (1)
    iv, ie, ivol, ic = 0, 2 * k_cls, 4 * k_cls, 5 * k_cls
    n_q = 5 * k_cls + 1
    a_act, a_st, f_act, f_st = _initial_fill(geom, share, initial)
    act = np.zeros((n_act, n_q))
    stag = np.zeros((n_lay, n_zon, n_q))
    for i, fi in enumerate((1 - f_act, f_act)):
        act[:, iv + i * k_cls : iv + (i + 1) * k_cls] = (a_act * fi)[:, None] * fr[i]
    for i, fi in enumerate((1 - f_st, f_st)):
        stag[:, :, iv + i * k_cls : iv + (i + 1) * k_cls] = (a_st * fi)[..., None] * fr[i]
    rho_b = np.repeat([materials[0].bulk_density, materials[1].bulk_density], k_cls)
    if heating is not None:
        h0 = np.concatenate(
            [
                np.full(k_cls, float(m.thermo.enthalpy(m.temperature)))
                for m in materials  # type: ignore[union-attr]
            ]
        )
        act[:, ie:ivol] = act[:, iv:ie] * rho_b * h0
        stag[..., ie:ivol] = stag[..., iv:ie] * rho_b * h0
    entry = np.zeros((n_lay, n_q))
    exit_rem = np.zeros((n_lay, n_q))
    exit_step = np.zeros((n_lay, n_q))
    head = 0  # stagnant zone z is stored at index (z + head) % n_zon

    # constant operators
    phi = tau / geom.cv_residence
    bottom_t = geom.bottom.T.copy()
    top_t = geom.top.T.copy()
    has_top = geom.top.any(axis=1)
    b_share = geom.bottom_share
    v_cv = geom.cv_velocity * geom.velocity_factor
    feed_t = geom.feed.T.copy()
    cls_cols = np.concatenate([np.arange(k_cls)] * 5)  # class of each of the first 5K columns

    total0 = act.sum(axis=0) + stag.sum(axis=(0, 1))
    scale0 = np.maximum(np.abs(total0), 1e-300)
    vol_tot = total0[iv:ie].reshape(2, k_cls).sum(axis=1)
    d_bed = float((total0[iv:ie].reshape(2, k_cls).sum(0) * d).sum() / vol_tot.sum())
    lf_bed = _final_contact(vol_tot.sum(), d_bed, vol_tot[0], vol_tot[1], lim)

    n_steps = int(np.ceil(duration / tau))
    n_rec = n_steps // n_sub + 1
    rec = {k: np.zeros(n_rec) for k in ("t", "contact", "vol")}
    rec_t = np.zeros((n_rec, 2))
    rec_layers = np.zeros((n_rec, n_lay))
    rec_io = np.zeros((n_rec, 2))
    snaps = {}
    snap_times = sorted(float(s) for s in snapshot_times)
    mass_err = 0.0
    energy_err = 0.0
    shale_mass0 = total0[iv + k_cls : ie].sum() * materials[1].bulk_density

    def cells():
        st = np.roll(stag, -head, axis=1)  # physical zone order
        return act, st

    def record(r, t_now):
        a_, st = cells()
        allc = np.concatenate([a_, st.reshape(-1, n_q), entry, exit_rem])
        tot = allc.sum(axis=0)
        rec["t"][r] = t_now
        rec["contact"][r] = tot[ic]
        rec["vol"][r] = tot[ivol:ic].sum() / shale_mass0 if shale_mass0 > 0 else 0.0
        if heating is not None:
            for i, m in enumerate(materials):
                vol = allc[:, iv + i * k_cls : iv + (i + 1) * k_cls]
                en = allc[:, ie + i * k_cls : ie + (i + 1) * k_cls]
                mass = vol * m.bulk_density
                with np.errstate(invalid="ignore", divide="ignore"):
                    temp = m.thermo.temperature(np.where(mass > 0, en / mass, 0.0))
                rec_t[r, i] = np.sum(np.where(mass > 0, mass * temp, 0.0)) / max(mass.sum(), 1e-300)
        lv = st[..., iv:ie].reshape(n_lay, n_zon, 2, k_cls).sum(axis=(1, 2))
        rec_layers[r] = (lv * d).sum(axis=1) / np.maximum(lv.sum(axis=1), 1e-300)
        outer_w = np.zeros(n_lay)
        cut = 0.75 * geom.stagnant_area
        acc = 0.0
        for j in range(n_lay):
            outer_w[j] = np.clip((cut - acc) / geom.layer_area[j], 0.0, 1.0)
            acc += geom.layer_area[j]
        lo = (lv * outer_w[:, None]).sum(0)
        li = (lv * (1 - outer_w[:, None])).sum(0)
        rec_io[r] = [(li * d).sum() / max(li.sum(), 1e-300), (lo * d).sum() / max(lo.sum(), 1e-300)]
        while snap_times and snap_times[0] <= t_now + 0.5 * tau * n_sub:
            ts = snap_times.pop(0)
            snaps[ts] = _snapshot(a_, st, d, k_cls, materials, lim, heating is not None, t_now)

    record(0, 0.0)
    r = 1
    log.info(
        "transverse grid: %d active and %d stagnant CVs, %d steps of %.3g s (%.3g s simulated)",
        n_act,
        stag.shape[0] * stag.shape[1],
        n_steps,
        tau,
        duration,
    )
    bar = progress_bar(n_steps * tau, desc="transverse grid", unit="s")
    for step in range(1, n_steps + 1):
        # 1. active-layer transport with segregation routing
        out = act * phi[:, None]
        act -= out
        vk = out[:, :k_cls] + out[:, k_cls : 2 * k_cls]
        if segregation:
            beta = _segregation_split(
                act[:, :k_cls] + act[:, k_cls:ie], d, v_cv, b_share, segregation_set
            )
        else:
            beta = np.broadcast_to(b_share[:, None], vk.shape)
        beta = np.where(has_top[:, None], beta, 1.0)
        beta_full = np.empty((n_act, n_q))
        beta_full[:, :ic] = beta[:, cls_cols]
        beta_full[:, ic] = np.where(has_top, b_share, 1.0)
        low = out * beta_full
        flows = bottom_t @ low + top_t @ (out - low)
        act += flows[:n_act]
        entry += flows[n_act:]
        # 2. stagnant discharge into the active layer
        sub = step % n_sub
        if sub == 0:
            act += feed_t @ exit_rem
            exit_rem[:] = 0.0
        else:
            act += feed_t @ exit_step
            exit_rem -= exit_step
        # 3. mixing in the active CVs
        _mix(act, d, k_cls, v_cv, tau, lim)
        # conservation check
        tot = act.sum(axis=0) + stag.sum(axis=(0, 1)) + entry.sum(axis=0) + exit_rem.sum(axis=0)
        err = float(np.max(np.abs(tot[iv:ie] - total0[iv:ie]) / scale0[iv:ie]))
        mass_err = max(mass_err, err)
        if err > _MASS_TOL:
            bar.close()
            raise ConvergenceError("grid mass balance violated", step=step, relative_error=err)
        if sub == 0:
            bar.update(tau * n_sub)
            # stagnant shift: the last zone leaves, the entry accumulator becomes zone 0
            last = (n_zon - 1 + head) % n_zon
            exit_rem[:] = stag[:, last]
            exit_step[:] = exit_rem / n_sub
            stag[:, last] = entry
            entry[:] = 0.0
            head = last
            if heating is not None:
                energy_err = max(
                    energy_err,
                    _heat_all(
                        act,
                        stag,
                        entry,
                        exit_rem,
                        d,
                        k_cls,
                        materials,
                        rho_b,
                        heating,
                        tau * n_sub,
                        lim,
                        ie,
                        ivol,
                        ic,
                    ),
                )
                exit_step[:] = exit_rem / n_sub
            if r < n_rec:
                record(r, step * tau)
                r += 1
    bar.close()
    tot = act.sum(axis=0) + stag.sum(axis=(0, 1)) + entry.sum(axis=0) + exit_rem.sum(axis=0)
    log.info("transverse grid: mass balance within %.2g (relative)", mass_err)
    if heating is not None:
        e0 = total0[ie:ivol].sum()
        energy_err = max(energy_err, abs(tot[ie:ivol].sum() - e0) / abs(e0))
    n = r
    return GridResult(
        geometry=geom,
        sizes=d,
        names=(materials[0].name, materials[1].name),
        t=rec["t"][:n],
        contact=rec["contact"][:n],
        final_contact_bed=float(lf_bed),
        extent=rec["contact"][:n] / lf_bed if lf_bed > 0 else np.zeros(n),
        temperature=rec_t[:n],
        volatiles=rec["vol"][:n],
        layer_sizes=rec_layers[:n],
        inner_size=rec_io[:n, 0],
        outer_size=rec_io[:n, 1],
        mass_error=mass_err,
        energy_error=energy_err,
        time_step=tau,
        snapshots=snaps,
    )


def _final_contact(area, d_mean, v0, v1, lim):
    """Eq 6.11 for arrays of cells, zero where a material is absent (silently clamped)."""
    with np.errstate(invalid="ignore", divide="ignore"):
        r = np.where((v0 > 0) & (v1 > 0), np.maximum(v0, v1) / np.minimum(v0, v1), np.inf)
    dd = np.maximum(lim["d_limit_final"] - d_mean, 0.0)
    de = np.maximum(lim["ratio_limit_final"] - r, 0.0)
    return K_FINAL * area * dd * de


def _mix(act, d, k, v_cv, tau, lim):
    """Eq 8.1 in every active CV (in place on the contact column)."""
    v0 = act[:, :k].sum(axis=1)
    v1 = act[:, k : 2 * k].sum(axis=1)
    a = v0 + v1
    with np.errstate(invalid="ignore", divide="ignore"):
        dm = np.where(a > 0, ((act[:, :k] + act[:, k : 2 * k]) @ d) / a, 0.0)
        r = np.where((v0 > 0) & (v1 > 0), np.maximum(v0, v1) / np.minimum(v0, v1), np.inf)
    both = np.isfinite(r)
    rate = (
        K_RATE
        * v_cv
        * np.sqrt(a)
        * np.maximum(lim["d_limit_rate"] - dm, 0.0)
        * np.maximum(lim["ratio_limit_rate"] - r, 0.0)
    )
    lf = np.where(
        both,
        K_FINAL
        * a
        * np.maximum(lim["d_limit_final"] - dm, 0.0)
        * np.maximum(lim["ratio_limit_final"] - r, 0.0),
        0.0,
    )
    act[:, -1] = np.minimum(lf, act[:, -1] + np.where(both, rate, 0.0) * tau)


def _segregation_split(vk, d, v_cv, b, coefficients="backfit"):
    """Share of each class's outflow sent to the bottom destination of each CV."""
    tot = vk.sum(axis=1)
    with np.errstate(invalid="ignore", divide="ignore"):
        dm = np.where(tot > 0, (vk @ d) / tot, 0.0)
        fine = (d[None, :] < dm[:, None]) & (vk > 0)
        psr = np.where(fine, dm[:, None] / d[None, :], 1.0)
    m_in, i_in, _, _ = segregation_coefficients(psr, coefficients)
    p_in = np.maximum(1.0, m_in * v_cv[:, None] + i_in)
    bb = b[:, None]
    share_f = np.where(fine, np.minimum(1.0, bb * p_in), 0.0)
    fine_low = (share_f * vk).sum(axis=1)
    coarse = np.where(fine, 0.0, vk).sum(axis=1)
    quota = b * tot
    with np.errstate(invalid="ignore", divide="ignore"):
        s_c = np.where(coarse > 0, np.clip((quota - fine_low) / coarse, 0.0, 1.0), 0.0)
        over = np.where(fine_low > quota, quota / fine_low, 1.0)
    beta = np.where(fine, share_f * over[:, None], s_c[:, None])
    return np.where(tot[:, None] > 0, beta, bb)


def _heat_all(act, stag, entry, exit_rem, d, k, materials, rho_b, heating, dt, lim, ie, ivol, ic):
    """Heat exchange in every cell over dt; returns the relative energy imbalance of the step."""
    n_lay, n_zon, n_q = stag.shape
    allc = np.concatenate([act, stag.reshape(-1, n_q), entry, exit_rem])
    vol = allc[:, :ie].reshape(-1, 2, k)
    mass = vol * np.array([materials[0].bulk_density, materials[1].bulk_density])[None, :, None]
    en = allc[:, ie:ivol].reshape(-1, 2, k)
    ok = mass > 0
    with np.errstate(invalid="ignore", divide="ignore"):
        h = np.where(ok, en / np.where(ok, mass, 1.0), 0.0)
    temp = np.empty_like(h)
    cap = np.empty_like(h)
    for i, m in enumerate(materials):
        t_i = m.thermo.temperature(h[:, i, :])
        if np.any(ok[:, i, :] & ~np.isfinite(t_i)):
            raise ConvergenceError("enthalpy outside the H(T) table", material=m.name)
        temp[:, i, :] = np.where(ok[:, i, :], t_i, 300.0)
        cap[:, i, :] = m.thermo.heat_capacity(temp[:, i, :])
    rho_p = np.array([materials[0].particle_density, materials[1].particle_density])
    area = 6.0 * mass / (rho_p[None, :, None] * d[None, None, :])
    v0 = vol[:, 0, :].sum(axis=1)
    v1 = vol[:, 1, :].sum(axis=1)
    a = v0 + v1
    with np.errstate(invalid="ignore", divide="ignore"):
        dm = np.where(a > 0, (vol.sum(axis=1) @ d) / a, 0.0)
        lf = _final_contact(a, dm, v0, v1, lim)
        extent = np.where(lf > 0, np.minimum(allc[:, ic] / np.where(lf > 0, lf, 1.0), 1.0), 0.0)
    q = cell_heat_exchange(
        mass,
        cap,
        area,
        temp,
        d,
        extent,
        dt,
        emissivity=heating.emissivity,
        balance=heating.balance,
    )
    e_before = en.sum()
    en_new = en + q
    allc[:, ie:ivol] = en_new.reshape(-1, 2 * k)
    # volatiles of the second material never decrease
    m1 = mass[:, 1, :]
    with np.errstate(invalid="ignore", divide="ignore"):
        t1 = materials[1].thermo.temperature(
            np.where(m1 > 0, en_new[:, 1, :] / np.where(m1 > 0, m1, 1), 0.0)
        )
    y = np.where(m1 > 0, m1 * materials[1].thermo.volatile_yield(np.nan_to_num(t1, nan=0.0)), 0.0)
    allc[:, ivol:ic] = np.maximum(allc[:, ivol:ic], y)
    n_a = act.shape[0]
    n_s = n_lay * n_zon
    act[:] = allc[:n_a]
    stag[:] = allc[n_a : n_a + n_s].reshape(n_lay, n_zon, n_q)
    entry[:] = allc[n_a + n_s : n_a + n_s + n_lay]
    exit_rem[:] = allc[n_a + n_s + n_lay :]
    return abs(float(q.sum())) / max(abs(float(e_before)), 1e-300)


def _snapshot(act, st, d, k, materials, lim, heat, t_now):
    """CV fields for colour maps: extent of mixing, mean size, mean temperature, share of 1."""
    out = {"t": t_now}
    for name, arr in (("active", act), ("stagnant", st.reshape(-1, act.shape[1]))):
        vol = arr[:, : 2 * k].reshape(-1, 2, k)
        v0, v1 = vol[:, 0].sum(1), vol[:, 1].sum(1)
        a = v0 + v1
        with np.errstate(invalid="ignore", divide="ignore"):
            dm = np.where(a > 0, (vol.sum(1) @ d) / a, 0.0)
            lf = _final_contact(a, dm, v0, v1, lim)
            ext = np.where(lf > 0, np.minimum(arr[:, -1] / np.where(lf > 0, lf, 1), 1.0), 0.0)
            fields = {"extent": ext, "size": dm, "share": np.where(a > 0, v1 / a, 0.0)}
            if heat:
                mass_t = 0.0
                m_tot = 0.0
                for i, m in enumerate(materials):
                    mass = vol[:, i] * m.bulk_density
                    en = arr[:, 2 * k + i * k : 2 * k + (i + 1) * k]
                    t_i = m.thermo.temperature(
                        np.where(mass > 0, en / np.where(mass > 0, mass, 1), 0.0)
                    )
                    mass_t = mass_t + np.where(mass > 0, mass * np.nan_to_num(t_i), 0.0).sum(1)
                    m_tot = m_tot + mass.sum(1)
                fields["temperature"] = np.where(
                    m_tot > 0, mass_t / np.where(m_tot > 0, m_tot, 1), np.nan
                )
        if name == "stagnant":
            fields = {kk: v.reshape(st.shape[0], st.shape[1]) for kk, v in fields.items()}
        out[name] = fields
    return out
