r"""Burn-out of a cloud of pulverised solid fuel carried by the gas along a path (a flame axis).

- :class:`ParticleSizeDistribution`: the fuel's fineness, from a Rosin-Rammler law
  (:math:`x'`, :math:`n`; :func:`rosin_rammler_retained`, :func:`rosin_rammler_x_prime` from a
  sieve residue such as R90) or a table of (size, mass fraction), checked, in a few size classes.
- :func:`pulverised_fuel_burnout`: given the gas temperature and O2 partial pressure along the
  path and the gas velocity (or the residence time), integrates per size class drying,
  devolatilisation (Kobayashi two competing rates or Badzioch-Hawksley) and char burn-out
  (Baum & Street kinetic/diffusion rate, shrinking sphere of constant density) with a stiff
  integrator; returns burn-out, volatile release, char burning, heat release, oxygen demand and
  the C, H, O, N, S, Cl released along the path, the unburnt char and the ash
  (:class:`FuelBurnoutResult`).

Assumptions, said once: the particles move with the gas (no slip) and are at the gas
temperature (no energy balance: the reference note gives none; a burner that has one passes
``T_particle``); the gas O2 is given, not depleted here (the caller couples it through
:attr:`FuelBurnoutResult.oxygen_demand_rate`); volatiles burn where they are released (their
mixing with the air is the burner's model); char is the combustible left by devolatilisation,
burning at the Baum & Street carbon rate whatever heteroatoms it holds; ash is inert and leaves
the burning sphere (it does not shield it). Data (kinetic constants, densities, heats) in
``data/fuels/burnout.yaml``. Reference note: team source folder reference/cement_lime.md 5.3,
5.4 and 5.6.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

import numpy as np
import yaml
from scipy.integrate import solve_ivp

from rotarykiln.chemistry.clinker import element_molar_mass
from rotarykiln.chemistry.drying import boiling_evaporation_rate
from rotarykiln.chemistry.solid_fuels import (
    H_FG_25C,
    SolidFuel,
    baum_street_kinetic_rate_coefficient,
    load_kiln_fuel,
    stoichiometric_oxygen_demand,
)
from rotarykiln.errors import ConvergenceError, InputError, check_positive

__all__ = [
    "ELEMENTS",
    "BurnoutParameters",
    "FuelBurnoutResult",
    "ParticleSizeDistribution",
    "load_burnout_parameters",
    "pulverised_fuel_burnout",
    "rosin_rammler_retained",
    "rosin_rammler_x_prime",
]

#: Elements tracked (those of the ultimate analysis).
ELEMENTS = ("C", "H", "O", "N", "S", "Cl")
_DATA = Path(__file__).resolve().parent.parent / "data" / "fuels" / "burnout.yaml"
_SUM_TOL = 1e-6


# --------------------------------------------------------------------------------------------
# Particle size distribution
# --------------------------------------------------------------------------------------------


def rosin_rammler_retained(d, x_prime, n):
    r"""Mass fraction of a Rosin-Rammler powder coarser than a size (the sieve residue).

    .. math:: R(d) = \exp\left[-\left(\frac{d}{x'}\right)^n\right]

    Parameters
    ----------
    d : float or array, m
        Size (sieve aperture), >= 0.
    x_prime : float, m
        Characteristic size :math:`x'` (R = 1/e = 36.8 % retained).
    n : float, -
        Uniformity (spread) exponent, > 0 (about 1 for kiln coal).

    Returns
    -------
    float or ndarray, -
        Mass fraction retained.

    Examples
    --------
    >>> round(rosin_rammler_retained(90e-6, 40e-6, 1.1), 4)
    0.0872

    References
    ----------
    P. Rosin, E. Rammler, The laws governing the fineness of powdered coal, J. Inst. Fuel 7
    (1933) 29-36; team source folder reference/cement_lime.md 5.6 (kiln fineness as R90).
    """
    check_positive("psd.x_prime", x_prime, "m")
    check_positive("psd.n", n)
    d = np.asarray(d, dtype=float)
    if not np.all(np.isfinite(d) & (d >= 0)):
        raise InputError("d", d, ">= 0 m")
    out = np.exp(-((d / x_prime) ** n))
    return out if out.ndim else float(out)


def rosin_rammler_x_prime(d_sieve, residue, n):
    r"""Characteristic size of a Rosin-Rammler powder from one sieve residue (e.g. R90), m.

    .. math:: x' = d_s\,(-\ln R_s)^{-1/n}

    Parameters
    ----------
    d_sieve : float, m
        Sieve aperture (90 um for R90).
    residue : float, -
        Mass fraction retained on it, in (0, 1) (coal for kilns: R90 about 0.10-0.15, petcoke
        0.02-0.05 [recalled, cement_lime.md 5.6]).
    n : float, -
        Uniformity exponent, > 0.

    Returns
    -------
    float, m

    Examples
    --------
    >>> round(rosin_rammler_x_prime(90e-6, 0.12, 1.0) * 1e6, 1)
    42.4

    References
    ----------
    Rosin & Rammler (1933); team source folder reference/cement_lime.md 5.6.
    """
    check_positive("d_sieve", d_sieve, "m")
    r = float(residue)
    if not (math.isfinite(r) and 0.0 < r < 1.0):
        raise InputError("residue", r, "a mass fraction in (0, 1) (not a percentage)")
    check_positive("n", n)
    return float(d_sieve) * (-math.log(r)) ** (-1.0 / float(n))


@dataclass(frozen=True)
class ParticleSizeDistribution:
    """A powder in size classes: representative sizes (m) and mass fractions (sum 1).

    Build with :meth:`from_table` (a discrete table, checked) or :meth:`rosin_rammler` (the law
    cut into classes). Each class burns as particles of its size.

    Attributes
    ----------
    sizes : ndarray, m
        Representative diameters of the classes, > 0 and increasing.
    mass_fractions : ndarray, -
        Mass fraction of each class, >= 0, sum 1.
    label : str
        How it was built.
    """

    sizes: np.ndarray
    mass_fractions: np.ndarray
    label: str = "table"

    @classmethod
    def from_table(cls, sizes, mass_fractions, label="table") -> ParticleSizeDistribution:
        """A distribution from a table of sizes (m) and mass fractions, checked.

        Sizes must be finite, > 0 and strictly increasing; fractions finite, >= 0 and summing
        to 1 within 1e-6 (they are then rescaled to sum 1 exactly); one fraction per size.
        """
        d = np.atleast_1d(np.asarray(sizes, dtype=float))
        w = np.atleast_1d(np.asarray(mass_fractions, dtype=float))
        if d.ndim != 1 or d.size == 0:
            raise InputError("psd.sizes", d, "a non-empty list of sizes in m")
        if w.shape != d.shape:
            raise InputError(
                "psd.mass_fractions", f"{w.size} values", f"{d.size} values, one per size"
            )
        bad = ~np.isfinite(d) | (d <= 0)
        if np.any(bad):
            raise InputError("psd.sizes", f"{d[bad][0]:.6g} m", "> 0 m")
        if np.any(np.diff(d) <= 0):
            i = int(np.argmax(np.diff(d) <= 0))
            raise InputError(
                "psd.sizes",
                f"{d[i + 1]:.6g} m after {d[i]:.6g} m",
                "strictly increasing sizes",
            )
        bad = ~np.isfinite(w) | (w < 0)
        if np.any(bad):
            raise InputError("psd.mass_fractions", f"{w[bad][0]:.6g}", ">= 0 (a mass fraction)")
        total = float(w.sum())
        if abs(total - 1.0) > _SUM_TOL:
            raise InputError(
                "psd.mass_fractions",
                f"sum {total:.8g}",
                f"1 +- {_SUM_TOL:g} (fractions of the whole, not percentages)",
            )
        d.setflags(write=False)
        w = w / total
        w.setflags(write=False)
        return cls(d, w, label)

    @classmethod
    def rosin_rammler(
        cls, x_prime, n, n_classes=8, *, lower_cut=0.01, upper_cut=0.99
    ) -> ParticleSizeDistribution:
        r"""A Rosin-Rammler powder cut into ``n_classes`` size classes.

        The span between the sizes with ``lower_cut`` and ``upper_cut`` of the mass passing
        (:math:`F = 1 - R`) is cut into ``n_classes`` log-spaced intervals, and the two tails
        join the end classes, so the fractions are the law's own and sum to 1. Each class is
        represented by its mass-median size (where F is half-way between its edges). The
        coarse tail sets the unburnt carbon: use enough classes (8 or more) for it.
        """
        check_positive("psd.x_prime", x_prime, "m")
        check_positive("psd.n", n)
        k = int(n_classes)
        if k != n_classes or k < 1:
            raise InputError("psd.n_classes", n_classes, "an integer >= 1")
        if not (0.0 < lower_cut < upper_cut < 1.0):
            raise InputError(
                "psd.lower_cut, upper_cut", (lower_cut, upper_cut), "0 < lower < upper < 1"
            )

        def size(F):
            return x_prime * (-np.log1p(-np.asarray(F, dtype=float))) ** (1.0 / n)

        if k == 1:
            F_edges = np.array([0.0, 1.0])
        else:
            inner = np.geomspace(size(lower_cut), size(upper_cut), k + 1)[1:-1]
            F_edges = np.concatenate(([0.0], 1.0 - np.exp(-((inner / x_prime) ** n)), [1.0]))
        w = np.diff(F_edges)
        d = size(0.5 * (F_edges[:-1] + F_edges[1:]))
        return cls.from_table(d, w / w.sum(), label=f"Rosin-Rammler x'={x_prime:.4g} m n={n:g}")

    @property
    def n_classes(self) -> int:
        """Number of size classes."""
        return int(self.sizes.size)


# --------------------------------------------------------------------------------------------
# Parameters
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class BurnoutParameters:
    """Constants of the burn-out model (defaults: ``data/fuels/burnout.yaml``).

    Change one with :func:`dataclasses.replace`. Devolatilisation: Kobayashi ``A1``, ``E1``,
    ``A2``, ``E2`` (1/s, J/mol), ``alpha1`` (None: the fuel's VM daf), ``alpha2``;
    Badzioch-Hawksley ``sfor_A``, ``sfor_E`` and ``sfor_yield_factor`` (V* = factor x VM daf).
    Char: Baum & Street ``C1`` (kg/(m s Pa K^0.75)), ``C2`` (kg/(m2 s Pa)), ``E_char``
    (J/mol), ``kinetic_temperature`` (``carrier`` or ``particle``). Particles: ``coal_density``
    and ``char_density`` (kg/m3; None: coal density x as-received fixed carbon). Drying:
    ``T_boil`` (K), ``k_boil`` (1/(s K)), ``boil_width`` (K). Product formation enthalpies
    ``h_f_CO2``, ``h_f_H2O_l``, ``h_f_SO2`` (J/mol).
    """

    A1: float
    E1: float
    A2: float
    E2: float
    alpha1: float | None
    alpha2: float
    sfor_A: float
    sfor_E: float
    sfor_yield_factor: float
    C1: float
    C2: float
    E_char: float
    kinetic_temperature: str
    coal_density: float
    char_density: float | None
    T_boil: float
    k_boil: float
    boil_width: float
    h_f_CO2: float
    h_f_H2O_l: float
    h_f_SO2: float


@lru_cache(maxsize=1)
def load_burnout_parameters() -> BurnoutParameters:
    """The default constants of the burn-out model, from ``data/fuels/burnout.yaml``."""
    with open(_DATA, encoding="utf-8") as fh:
        d = yaml.safe_load(fh)
    kob = d["devolatilisation"]["kobayashi"]
    bh = d["devolatilisation"]["badzioch_hawksley"]
    ch = d["char_oxidation"]
    p = d["particles"]
    dr = d["drying"]
    hf = d["formation_enthalpy"]
    return BurnoutParameters(
        A1=float(kob["A1"]),
        E1=float(kob["E1"]),
        A2=float(kob["A2"]),
        E2=float(kob["E2"]),
        alpha1=None if kob["alpha1"] is None else float(kob["alpha1"]),
        alpha2=float(kob["alpha2"]),
        sfor_A=float(bh["A"]),
        sfor_E=float(bh["E"]),
        sfor_yield_factor=float(bh["yield_factor"]),
        C1=float(ch["C1"]),
        C2=float(ch["C2"]),
        E_char=float(ch["E"]),
        kinetic_temperature=str(ch["kinetic_temperature"]),
        coal_density=float(p["coal_density"]),
        char_density=None if p["char_density"] is None else float(p["char_density"]),
        T_boil=float(dr["T_boil"]),
        k_boil=float(dr["k_boil"]),
        boil_width=float(dr["width"]),
        h_f_CO2=float(hf["CO2_g"]),
        h_f_H2O_l=float(hf["H2O_l"]),
        h_f_SO2=float(hf["SO2_g"]),
    )


# --------------------------------------------------------------------------------------------
# Result
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class FuelBurnoutResult:
    """Burn-out of a pulverised fuel along a path; arrays over the path's points (n_z).

    Rates are per metre of path (kg/(s m), W/m), flows kg/s or W; element arrays have a last
    axis over :data:`ELEMENTS`. "Burnt" counts volatiles when they are released.

    Attributes
    ----------
    z, t : ndarray, m and s
        Path positions and particle residence time.
    fuel_mass_flow : float, kg/s
        Fuel fed, as received.
    psd : ParticleSizeDistribution
        The size classes.
    burnout : ndarray, -
        Fraction of the combustible (daf fuel) released or burnt (clipped to [0, 1]: the
        integrator may overshoot a burnt-out particle by its tolerance, ~1e-11).
    burnout_by_class : ndarray (n_z, n_classes), -
        The same per size class.
    volatile_release_rate, char_burning_rate, drying_rate : ndarray, kg/(s m)
        Volatiles released, char burnt, moisture evaporated.
    heat_release_rate : ndarray, W/m
        Total: volatiles + char + drying (negative; 0 on the HHV basis).
    heat_release_volatiles, heat_release_char, heat_of_drying : ndarray, W/m
        Its parts.
    cumulative_heat_release : ndarray, W
        Heat released from the start of the path (differences give a cell's heat exactly;
        the rates are point values).
    volatiles_released, char_burnt : ndarray, kg/s
        Volatiles released and char burnt from the start of the path.
    oxygen_demand_rate : ndarray, kg/(s m)
        O2 needed to burn completely what is released (char: what it consumes; CO2 product).
    volatile_element_rate, char_element_rate : ndarray (n_z, 6), kg/(s m)
        Elements released by devolatilisation and by char burning.
    released_elements : ndarray (n_z, 6), kg/s
        Elements released from the start (volatiles + char burnt).
    unreleased_elements : ndarray (n_z, 6), kg/s
        Elements still in the particles (raw fuel + char).
    char_flow, raw_fuel_flow, moisture_flow : ndarray, kg/s
        Char, undevolatilised daf fuel and moisture still carried.
    ash_flow : float, kg/s
        Ash carried (inert), for the bed or the dust.
    unburnt_carbon : float, kg/s
        Carbon left in the particles at the end of the path.
    particle_number_flow : ndarray (n_classes,), 1/s
        Particles fed per second in each size class (fuel flow in the class / particle mass).
    particle_diameter : ndarray (n_z, n_classes), m
        Diameter of a sphere holding the particle's combustible: its undevolatilised fuel at
        the coal density and its char at the char density (moisture and ash not counted: the
        feed size times the cube root of the dry ash-free fraction at the start; 0 once burnt
        out): what radiates (:func:`~rotarykiln.heat.gas_radiation.\
particle_absorption_coefficient`).
    unburnt_combustible : float, kg/s
        Combustible left at the end (char + raw fuel).
    heating_value : float, J/kg
        Heating value of the fuel as received on the chosen basis (HHV or LHV).
    heat_basis : str
        ``"lhv"`` or ``"hhv"``.
    element_closure_error, energy_closure_error : float, -
        Largest |released + unreleased - fed| / fuel fed over the elements and path points;
        |heat released + heat left - fed| / heat fed.
    success : bool
        The integrator's verdict.
    message : str
        The integrator's message.
    nfev : int
        Right-hand-side evaluations.
    """

    z: np.ndarray
    t: np.ndarray
    fuel_mass_flow: float
    psd: ParticleSizeDistribution
    burnout: np.ndarray
    burnout_by_class: np.ndarray
    volatile_release_rate: np.ndarray
    char_burning_rate: np.ndarray
    drying_rate: np.ndarray
    heat_release_rate: np.ndarray
    heat_release_volatiles: np.ndarray
    heat_release_char: np.ndarray
    heat_of_drying: np.ndarray
    cumulative_heat_release: np.ndarray
    volatiles_released: np.ndarray
    char_burnt: np.ndarray
    oxygen_demand_rate: np.ndarray
    volatile_element_rate: np.ndarray
    char_element_rate: np.ndarray
    released_elements: np.ndarray
    unreleased_elements: np.ndarray
    char_flow: np.ndarray
    raw_fuel_flow: np.ndarray
    moisture_flow: np.ndarray
    ash_flow: float
    unburnt_carbon: float
    unburnt_combustible: float
    heating_value: float
    heat_basis: str
    element_closure_error: float
    energy_closure_error: float
    success: bool
    message: str
    nfev: int
    devolatilisation: str = "kobayashi"
    extra: dict = field(default_factory=dict)
    particle_number_flow: np.ndarray | None = None
    particle_diameter: np.ndarray | None = None

    @property
    def loss_on_ignition(self) -> float:
        """Combustible in the solid residue at the end (unburnt / (unburnt + ash)), -."""
        total = self.unburnt_combustible + self.ash_flow
        return self.unburnt_combustible / total if total > 0 else 0.0

    def to_frame(self):
        """The profiles as a pandas DataFrame (one row per path point, units in the names)."""
        import pandas as pd

        from rotarykiln.tables import with_units

        cols = {
            "z_m": self.z,
            "t_s": self.t,
            "burnout": self.burnout,
            "volatile_release_kg_s_m": self.volatile_release_rate,
            "char_burning_kg_s_m": self.char_burning_rate,
            "drying_kg_s_m": self.drying_rate,
            "heat_release_W_m": self.heat_release_rate,
            "heat_release_volatiles_W_m": self.heat_release_volatiles,
            "heat_release_char_W_m": self.heat_release_char,
            "heat_of_drying_W_m": self.heat_of_drying,
            "cumulative_heat_release_W": self.cumulative_heat_release,
            "volatiles_released_kg_s": self.volatiles_released,
            "char_burnt_kg_s": self.char_burnt,
            "oxygen_demand_kg_s_m": self.oxygen_demand_rate,
            "char_flow_kg_s": self.char_flow,
            "raw_fuel_flow_kg_s": self.raw_fuel_flow,
        }
        for j, e in enumerate(ELEMENTS):
            cols[f"released_{e}_kg_s"] = self.released_elements[:, j]
        return with_units(pd.DataFrame(cols), "chemistry.fuel_burnout")

    def plot(self, ax=None):
        """Burn-out and heat release along the path; returns the Figure."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots()
        ax.plot(self.z, self.burnout, label="burn-out")
        for i, d in enumerate(self.psd.sizes):
            ax.plot(
                self.z, self.burnout_by_class[:, i], lw=0.6, alpha=0.6, label=f"{d * 1e6:.0f} um"
            )
        ax.set_xlabel("z (m)")
        ax.set_ylabel("burn-out (-)")
        ax.set_ylim(0, 1.02)
        ax2 = ax.twinx()
        ax2.plot(self.z, self.heat_release_rate / 1e6, "k--", label="heat release")
        ax2.set_ylabel("heat release (MW/m)")
        ax.legend(fontsize="small", loc="center right")
        return ax.figure


# --------------------------------------------------------------------------------------------
# The model
# --------------------------------------------------------------------------------------------


def _path(z, T_gas, p_o2, velocity, time, T_particle):
    z = np.asarray(z, dtype=float)
    if z.ndim != 1 or z.size < 2:
        raise InputError("z", z, "a 1-D array of at least 2 path positions in m")
    if not np.all(np.isfinite(z)) or np.any(np.diff(z) <= 0):
        raise InputError("z", z, "finite and strictly increasing (m)")
    out = {}
    for name, v, lo_ok in (("T_gas", T_gas, "> 0 K"), ("p_o2", p_o2, ">= 0 Pa")):
        a = (
            np.broadcast_to(np.asarray(v, dtype=float), z.shape).copy()
            if np.ndim(v) == 0
            else np.asarray(v, dtype=float)
        )
        if a.shape != z.shape:
            raise InputError(name, f"{a.size} values", f"{z.size} values, one per z")
        bad = ~np.isfinite(a) | ((a <= 0) if name == "T_gas" else (a < 0))
        if np.any(bad):
            raise InputError(name, f"{a[bad][0]:.6g}", lo_ok)
        out[name] = a
    if T_particle is None:
        out["T_particle"] = out["T_gas"]
    else:
        a = np.asarray(T_particle, dtype=float)
        a = np.broadcast_to(a, z.shape).copy() if a.ndim == 0 else a
        if a.shape != z.shape:
            raise InputError("T_particle", f"{a.size} values", f"{z.size} values, one per z")
        check_positive("T_particle", a, "K")
        out["T_particle"] = a
    if (velocity is None) == (time is None):
        raise InputError("velocity, time", "both or neither", "exactly one of them given")
    if velocity is not None:
        u = np.asarray(velocity, dtype=float)
        u = np.broadcast_to(u, z.shape).copy() if u.ndim == 0 else u
        if u.shape != z.shape:
            raise InputError("velocity", f"{u.size} values", f"{z.size} values, one per z")
        check_positive("velocity", u, "m/s")
        inv = 1.0 / u
        t = np.concatenate(([0.0], np.cumsum(0.5 * (inv[1:] + inv[:-1]) * np.diff(z))))
    else:
        t = np.asarray(time, dtype=float)
        if t.shape != z.shape:
            raise InputError("time", f"{t.size} values", f"{z.size} values, one per z")
        if not np.all(np.isfinite(t)) or np.any(np.diff(t) <= 0):
            raise InputError("time", t, "finite and strictly increasing (s)")
        t = t - t[0]
        u = np.gradient(z, t)
    out["t"], out["u"], out["z"] = t, u, z
    return out


def _split(y, alphas):
    """Element split of the devolatilisation reactions, per kg of daf fuel consumed.

    Reaction j gives ``alpha_j`` volatiles and ``1 - alpha_j`` char. The volatiles take the
    heteroatoms (H, O, N, S, Cl) first and then carbon; when ``alpha_j`` is smaller than the
    heteroatom content they take each heteroatom in proportion and the char keeps the rest.
    Returns (a, b): element masses to the volatiles and to the char, shape (n_reactions, 6).
    """
    h = 1.0 - y[0]
    a = np.zeros((len(alphas), len(ELEMENTS)))
    for j, al in enumerate(alphas):
        if al >= h:
            a[j, 1:] = y[1:]
            a[j, 0] = al - h
        else:
            a[j, 1:] = y[1:] * (al / h)
    return a, y[None, :] - a


def pulverised_fuel_burnout(
    fuel,
    psd,
    fuel_mass_flow,
    z,
    T_gas,
    p_o2,
    velocity=None,
    time=None,
    T_particle=None,
    devolatilisation="kobayashi",
    parameters=None,
    heating_value="lhv",
    *,
    method="BDF",
    rtol=1e-8,
):
    r"""Burn-out of a cloud of pulverised fuel particles carried by the gas along a path.

    Per size class i (particles of diameter :math:`d_{0,i}` and apparent density
    :math:`\rho_{coal}`, mass :math:`m_0`), with the particle at the gas temperature and moving
    with the gas (:math:`dt = dz/u`), the masses per particle obey

    .. math::
        \frac{dW}{dt} = -k_b w \ln(1 + e^{(T - T_{boil})/w})\,W \quad\text{(drying)}

        \frac{dm_c}{dt} = -\sum_j k_j m_c,\quad k_j = A_j e^{-E_j/RT} \quad
        \text{(daf fuel; Kobayashi: } j = 1, 2\text{; Badzioch-Hawksley: one, }
        \alpha = V^*)

        \frac{dV}{dt} = \sum_j \alpha_j k_j m_c,\qquad
        \frac{dm_{ch}}{dt} = \sum_j (1 - \alpha_j) k_j m_c - \pi d^2 p_{O_2}
        \frac{D_0 R_k}{D_0 + R_k}

    with :math:`D_0 = C_1 T^{0.75}/d` and :math:`R_k = C_2 e^{-E/RT}` (Baum & Street), the
    char a sphere of constant density, :math:`d = (6 m_{ch}/(\pi\rho_{ch}))^{1/3}`. Elements:
    each reaction's volatiles take the heteroatoms first, then carbon; the char burns its
    elements in proportion. Heat: char elements release their heats of combustion (C -> CO2,
    H -> H2O, S -> SO2), and each reaction's volatiles the rest of the fuel's heating value,
    :math:`H_{daf} - \sum_e h_e b_{je}` per kg, so that released + left = the fuel's heating
    value exactly; on the LHV basis drying absorbs :math:`h_{fg}` (25 degC) per kg of water.
    Integrated with ``scipy.integrate.solve_ivp`` (BDF), vectorised over the size classes.

    Parameters
    ----------
    fuel : SolidFuel or str
        The fuel (a name of ``data/fuels/kiln_fuels.yaml`` loads it); its proximate volatile
        matter sets the yields unless ``parameters.alpha1`` is given.
    psd : ParticleSizeDistribution
        Size classes: sizes [m] and mass fractions [-].
    fuel_mass_flow : float, kg/s
        Fuel fed, as received.
    z : array, m
        Path positions, strictly increasing (at least 2).
    T_gas : float or array, K
        Gas temperature at z.
    p_o2 : float or array, Pa
        O2 partial pressure far from the particles at z, >= 0.
    velocity : float or array, m/s
        Gas (and particle) velocity at z; or give ``time``.
    time : array, s
        Particle residence time at z, strictly increasing; or give ``velocity``.
    T_particle : float or array, K
        Particle temperature at z (default: the gas temperature).
    devolatilisation : str
        ``"kobayashi"`` (two competing rates) or ``"badzioch_hawksley"`` (single first order).
    parameters : BurnoutParameters
        Constants (default :func:`load_burnout_parameters`).
    heating_value : str
        ``"lhv"`` (water leaves as vapour; drying absorbs its latent heat) or ``"hhv"``.
    method : str
        ``"BDF"`` or ``"Radau"``.
    rtol : float, -
        Relative tolerance of the integrator.

    Returns
    -------
    FuelBurnoutResult
        Profiles along z: burn-out [-], rates [kg/(s m)], heat release [W/m], elements, the
        unburnt char and the ash [kg/s].

    Raises
    ------
    InputError
        A bad path, fuel, distribution or constant (one line naming it).
    ConvergenceError
        The integrator failed.

    Examples
    --------
    Pittsburgh No. 8 ground to R90 = 8.7 % (x' = 40 um, n = 1.1), 1 s at 1400 K in 5 % O2:

    >>> psd = ParticleSizeDistribution.rosin_rammler(40e-6, 1.1)
    >>> z = np.linspace(0.0, 10.0, 41)
    >>> r = pulverised_fuel_burnout("pittsburgh_8", psd, 1.0, z, 1400.0, 0.05 * 101325.0,
    ...                             velocity=10.0)
    >>> round(float(r.burnout[-1]), 3), round(r.unburnt_carbon, 4), r.element_closure_error < 1e-8
    (0.973, 0.024, True)

    References
    ----------
    Kobayashi, Howard & Sarofim (1977) and Ubhayakar et al. (1977), constants as in pkpcoal and
    Uintah; Badzioch & Hawksley (1970); M.M. Baum, P.J. Street, Combust. Sci. Technol. 3 (1971)
    231-243 as in OpenFOAM-dev ``COxidationKineticDiffusionLimitedRate``; Rosin & Rammler
    (1933); CODATA key values (Cox, Wagman & Medvedev 1989); team source folder
    reference/cement_lime.md 5.3, 5.4, 5.6.
    """
    # ---- inputs
    if isinstance(fuel, str):
        fuel = load_kiln_fuel(fuel)
    if not isinstance(fuel, SolidFuel):
        raise InputError("fuel", type(fuel).__name__, "a SolidFuel or the name of a kiln fuel")
    if not isinstance(psd, ParticleSizeDistribution):
        raise InputError(
            "psd", type(psd).__name__, "a ParticleSizeDistribution (from_table or rosin_rammler)"
        )
    check_positive("fuel_mass_flow", fuel_mass_flow, "kg/s")
    if devolatilisation not in ("kobayashi", "badzioch_hawksley"):
        raise InputError(
            "devolatilisation", devolatilisation, "one of kobayashi, badzioch_hawksley"
        )
    if heating_value not in ("lhv", "hhv"):
        raise InputError("heating_value", heating_value, "one of lhv, hhv")
    if method not in ("BDF", "Radau"):
        raise InputError("method", method, "one of BDF, Radau (stiff integrators)")
    P = load_burnout_parameters() if parameters is None else parameters
    if not isinstance(P, BurnoutParameters):
        raise InputError("parameters", type(P).__name__, "a BurnoutParameters")
    if P.kinetic_temperature not in ("carrier", "particle"):
        raise InputError(
            "parameters.kinetic_temperature", P.kinetic_temperature, "one of carrier, particle"
        )
    for name in ("A1", "E1", "A2", "E2", "sfor_A", "sfor_E", "C1", "C2", "E_char",
                 "coal_density", "T_boil", "k_boil", "boil_width"):  # fmt: skip
        check_positive(f"parameters.{name}", getattr(P, name))
    path = _path(z, T_gas, p_o2, velocity, time, T_particle)
    mdot = float(fuel_mass_flow)

    # ---- fuel
    u_ar = fuel.ultimate("ar")
    W0, A0 = u_ar["moisture"], u_ar["ash"]
    daf = 1.0 - W0 - A0
    if daf <= 0.0:
        raise InputError("fuel", f"combustible {daf:.4g} kg/kg", "> 0 (moisture + ash < 1)")
    y = np.array([u_ar[e] for e in ELEMENTS]) / daf  # daf composition
    vm_daf = fuel.proximate("daf")["volatiles"]
    if devolatilisation == "kobayashi":
        alpha1 = P.alpha1
        if alpha1 is None:
            if not math.isfinite(vm_daf):
                raise InputError(
                    "fuel.proximate",
                    "missing",
                    "given (its volatile matter sets Kobayashi's alpha1; or set parameters.alpha1)",
                )
            alpha1 = vm_daf
        alphas = [alpha1, P.alpha2]
        A = np.array([P.A1, P.A2])
        E = np.array([P.E1, P.E2])
        names = ("parameters.alpha1", "parameters.alpha2")
    else:
        if not math.isfinite(vm_daf):
            raise InputError(
                "fuel.proximate", "missing", "given (its volatile matter sets the yield V*)"
            )
        alphas = [P.sfor_yield_factor * vm_daf]
        A = np.array([P.sfor_A])
        E = np.array([P.sfor_E])
        names = ("parameters.sfor_yield_factor x VM_daf",)
    for nm, al in zip(names, alphas, strict=True):
        if not (math.isfinite(al) and 0.0 <= al <= 1.0):
            raise InputError(nm, al, "in [0, 1] (volatiles per kg of daf fuel)")
    nr = len(alphas)
    a_split, b_split = _split(y, alphas)

    M = {e: element_molar_mass(e) for e in ELEMENTS}
    ratio = (2.0 * M["H"] + M["O"]) / (2.0 * M["H"])
    h_el = np.zeros(len(ELEMENTS))
    h_el[0] = -P.h_f_CO2 / M["C"]
    h_el[1] = -P.h_f_H2O_l / (2.0 * M["H"])
    h_el[4] = -P.h_f_SO2 / M["S"]
    hhv_daf = fuel.hhv("daf")
    if heating_value == "lhv":
        h_el[1] -= H_FG_25C * ratio
        H_daf = hhv_daf - H_FG_25C * ratio * y[1]
        h_w = H_FG_25C
    else:
        H_daf = hhv_daf
        h_w = 0.0
    # J per kg daf fuel consumed by each reaction: the volatiles' heat of combustion (with no
    # volatiles, alpha = 0, the fuel's heating value less its char's, so that energy closes)
    q_vol = H_daf - b_split @ h_el
    neg = (q_vol < 0) & (np.asarray(alphas) > 0)
    if np.any(neg):
        j = int(np.argmax(neg))
        raise InputError(
            "fuel",
            f"heating value {H_daf:.4g} J/kg daf below its char's {b_split[j] @ h_el:.4g}",
            "a heating value that leaves the volatiles >= 0 J/kg",
        )
    heat_fed = mdot * (daf * H_daf - h_w * W0)

    # ---- particles
    d0 = np.asarray(psd.sizes, dtype=float)
    w = np.asarray(psd.mass_fractions, dtype=float)
    N = d0.size
    m0 = P.coal_density * math.pi * d0**3 / 6.0
    if P.char_density is None:
        fc_ar = daf * (1.0 - (vm_daf if math.isfinite(vm_daf) else alphas[0]))
        rho_char = P.coal_density * fc_ar
        if rho_char <= 0:
            raise InputError(
                "parameters.char_density", "None", "given (the fuel has no fixed carbon)"
            )
    else:
        rho_char = float(P.char_density)
        check_positive("parameters.char_density", rho_char, "kg/m3")

    # state layout (per kg of fuel fed in the class): W, R, X_j (nr), char elements (6),
    # char-burnt elements (6), cumulative heat (MJ/kg)
    iW, iR, iX = 0, 1, 2
    iC = 2 + nr
    iB = iC + 6
    iQ = iB + 6
    nv = iQ + 1
    t_nodes, Tg_n, Tp_n, p_n = path["t"], path["T_gas"], path["T_particle"], path["p_o2"]
    R_GAS = 8.314462618
    size_factor = 6.0 / (math.pi * rho_char)  # d^3 per kg of char

    def rates(Tg, Tp, p, Y):
        """Rates per kg of fuel fed, 1/s; Y (nv, N, k); T, p broadcast over k."""
        Wm = Y[iW]
        R = np.maximum(Y[iR], 0.0)
        dry = boiling_evaporation_rate(Tp, Wm, P.T_boil, P.k_boil, P.boil_width)
        k = A[:, None, None] * np.exp(-E[:, None, None] / (R_GAS * Tp))  # (nr, 1, k)
        dev = k * R[None]  # (nr, N, k)
        ch = np.maximum(Y[iC:iB], 0.0)
        mch = ch.sum(axis=0)
        d = np.cbrt(size_factor * mch * m0[:, None])
        Tm = 0.5 * (Tp + Tg)
        Cm = P.C1 * Tm**0.75
        Rk = baum_street_kinetic_rate_coefficient(
            Tg if P.kinetic_temperature == "carrier" else Tp, P.C2, P.E_char
        )
        burn = math.pi * p * d**2 * Rk * Cm / (Cm + Rk * d) / m0[:, None]
        frac = np.divide(ch, mch, out=np.zeros_like(ch), where=mch > 0)
        burn_e = burn * frac  # (6, N, k)
        vol_e = np.einsum("je,jnk->enk", a_split, dev)
        char_e = np.einsum("je,jnk->enk", b_split, dev)
        q_v = np.einsum("j,jnk->nk", q_vol, dev)
        q_c = np.einsum("e,enk->nk", h_el, burn_e)
        return dry, dev, vol_e, char_e, burn_e, q_v, q_c

    def rhs(t, yv):
        k = 1 if yv.ndim == 1 else yv.shape[1]
        Y = yv.reshape(nv, N, k)
        Tg = np.interp(t, t_nodes, Tg_n)
        Tp = np.interp(t, t_nodes, Tp_n)
        p = np.interp(t, t_nodes, p_n)
        dry, dev, vol_e, char_e, burn_e, q_v, q_c = rates(Tg, Tp, p, Y)
        dY = np.empty_like(Y)
        dY[iW] = -dry
        dY[iR] = -dev.sum(axis=0)
        dY[iX:iC] = dev
        dY[iC:iB] = char_e - burn_e
        dY[iB:iQ] = burn_e
        dY[iQ] = (q_v + q_c - h_w * dry) * 1e-6
        return dY.reshape(yv.shape)

    y0 = np.zeros((nv, N))
    y0[iW] = W0
    y0[iR] = daf
    sparsity = np.kron(np.ones((nv, nv)), np.eye(N))
    t_end = float(t_nodes[-1])
    dt = np.diff(t_nodes)
    max_step = max(float(dt.min()), t_end / 5000.0)
    sol = solve_ivp(
        rhs,
        (0.0, t_end),
        y0.ravel(),
        method=method,
        t_eval=t_nodes,
        rtol=rtol,
        atol=1e-13,
        vectorized=True,
        jac_sparsity=sparsity,
        max_step=max_step,
    )
    if not sol.success or sol.y.shape[1] != t_nodes.size:
        raise ConvergenceError(
            f"pulverised_fuel_burnout: {method} failed: {sol.message}",
            t_reached=float(sol.t[-1]) if sol.t.size else 0.0,
            t_end=t_end,
        )
    Y = sol.y.reshape(nv, N, t_nodes.size)

    # ---- outputs
    dry, dev, vol_e, char_e, burn_e, q_v, q_c = rates(Tg_n, Tp_n, p_n, Y)
    wf = mdot * w[:, None]  # kg/s of fuel in each class
    per_m = 1.0 / path["u"]

    def flow(x):  # (N, nz) per kg -> kg/s
        return np.sum(wf * x, axis=0)

    def flow_e(x):  # (6, N, nz) -> (nz, 6)
        return np.einsum("n,enk->ke", mdot * w, x)

    vol_rate = flow(np.einsum("j,jnk->nk", np.asarray(alphas), dev)) * per_m
    char_rate = flow(burn_e.sum(axis=0)) * per_m
    dry_rate = flow(dry) * per_m
    hv = flow(q_v) * per_m
    hc = flow(q_c) * per_m
    hd = -h_w * dry_rate
    vol_el = flow_e(vol_e) * per_m[:, None]
    char_el = flow_e(burn_e) * per_m[:, None]
    o2 = stoichiometric_oxygen_demand(
        *(vol_el[:, ELEMENTS.index(e)] + char_el[:, ELEMENTS.index(e)] for e in "CHOS"),
        Cl=vol_el[:, 5] + char_el[:, 5],
    )
    X = Y[iX:iC]
    released = flow_e(np.einsum("je,jnk->enk", a_split, X)) + flow_e(Y[iB:iQ])
    raw = np.sum(wf * Y[iR], axis=0)
    char = flow_e(Y[iC:iB])
    unreleased = raw[:, None] * y[None, :] + char
    fed = mdot * daf * y
    el_err = float(np.max(np.abs(released + unreleased - fed[None, :]))) / mdot
    q_cum = flow(Y[iQ]) * 1e6
    left = raw * H_daf + char @ h_el - h_w * flow(Y[iW])
    en_err = float(np.max(np.abs(q_cum + left - heat_fed))) / abs(heat_fed)
    comb_class = Y[iR] + Y[iC:iB].sum(axis=0)  # (N, nz)
    volume = m0[:, None] * (
        np.maximum(Y[iR], 0.0) / P.coal_density + np.maximum(Y[iC:iB], 0.0).sum(axis=0) / rho_char
    )  # m3 per particle, (N, nz)
    burnout_class = 1.0 - comb_class / daf
    return FuelBurnoutResult(
        z=path["z"],
        t=t_nodes,
        fuel_mass_flow=mdot,
        psd=psd,
        burnout=np.clip(1.0 - flow(comb_class) / (mdot * daf), 0.0, 1.0),
        burnout_by_class=np.clip(burnout_class.T, 0.0, 1.0),
        volatile_release_rate=vol_rate,
        char_burning_rate=char_rate,
        drying_rate=dry_rate,
        heat_release_rate=hv + hc + hd,
        heat_release_volatiles=hv,
        heat_release_char=hc,
        heat_of_drying=hd,
        cumulative_heat_release=q_cum,
        volatiles_released=flow(np.einsum("j,jnk->nk", np.asarray(alphas), X)),
        char_burnt=flow(Y[iB:iQ].sum(axis=0)),
        oxygen_demand_rate=np.asarray(o2, dtype=float),
        volatile_element_rate=vol_el,
        char_element_rate=char_el,
        released_elements=released,
        unreleased_elements=unreleased,
        char_flow=char.sum(axis=1),
        raw_fuel_flow=raw,
        moisture_flow=flow(Y[iW]),
        ash_flow=mdot * A0,
        unburnt_carbon=max(float(unreleased[-1, 0]), 0.0),
        unburnt_combustible=max(float(unreleased[-1].sum()), 0.0),
        heating_value=heat_fed / mdot,
        heat_basis=heating_value,
        element_closure_error=el_err,
        energy_closure_error=en_err,
        success=bool(sol.success),
        message=str(sol.message),
        nfev=int(sol.nfev),
        devolatilisation=devolatilisation,
        extra={"char_density": rho_char, "alphas": tuple(alphas), "heat_of_volatiles": q_vol},
        particle_number_flow=mdot * w / m0,
        particle_diameter=np.cbrt(6.0 * volume / math.pi).T,
    )
