r"""A burner's products for any flows without Cantera per case: complete combustion by elements,
and the dissociation heat tabulated once per fuel and oxidiser over the equivalence ratio.

**Complete combustion** (:func:`complete_combustion`). A lean fuel-oxidiser mixture burns to
CO2, H2O, N2, Ar and the excess O2, by an element balance linear in the stream flows:

.. math::
    \dot n_{CO_2} = \dot N_C,\quad \dot n_{H_2O} = \tfrac12\dot N_H,\quad
    \dot n_{N_2} = \tfrac12\dot N_N,\quad \dot n_{Ar} = \dot N_{Ar},\quad
    \dot n_{O_2} = \tfrac12\dot N_O - \dot N_C - \tfrac14\dot N_H \;(\ge 0)

with :math:`\dot N_e` the element flows of the fuel and the oxidiser streams (water as vapour,
no dissociation, no nitrogen oxides: the complete products of the heating values, of the
solid fuels' products, :mod:`rotarykiln.kiln.combustion.fired_fuels`, and of the
dissociation's frozen state, :mod:`rotarykiln.materials.dissociation`). The temperature of
the unburnt streams mixed at constant pressure and enthalpy (:func:`mixing_temperature`) and
the heat of combustion at it,

.. math:: Q = \sum_{s} \dot H_s(T_s) - \sum_k \dot n_k\,h_k(T_{in}),

use GRI-Mech 3.0's NASA-7 polynomials of the species (evaluated here: Cantera's numbers to
round-off), read once per species; the frozen adiabatic temperature solves
:math:`h_p(T_{ad}) = h_p(T_{in}) + Q/\dot m` on the products' property table mixed from the
per-species tables (:func:`rotarykiln.materials.gas.gas_table` of each species: the cubic
splines are linear in their data, so the mixed table is the products' own
:func:`~rotarykiln.materials.gas.gas_table` to round-off). A rich mixture (too little free O2)
is not handled here: :func:`complete_combustion` returns None and the caller burns it with
Cantera (:func:`rotarykiln.materials.gas.burn_fuel`).

**Dissociation table** (:func:`dissociation_table`). For one fuel and one oxidiser
composition the products' composition is a function of the equivalence ratio alone,
:math:`\phi = 1/\lambda` (fuel O2 demand over the oxidiser's free O2, 0 to 1 when lean), and
so is their dissociation heat per kg of products,
:math:`\Delta h_d(T, \phi)` (:func:`~rotarykiln.materials.dissociation.dissociation_enthalpy`).
It is computed with Cantera once, on :data:`~rotarykiln.materials.gas.T_GRID` at
:data:`TABLE_NODES` nodes in :math:`\phi` uniform in

.. math:: v(\phi) = \sqrt{\phi} + c\,\big[\ln(1 + \phi/\epsilon) - \ln(1 - \phi + \epsilon)\big],
          \qquad c = 0.06,\ \epsilon = 10^{-6}

(the square root resolves the :math:`\sqrt{\phi}` of the OH of dilute water, the logarithms
the scales near :math:`\phi = 0`, where hot air's own O atoms give way to the products', and
near :math:`\phi = 1`, where CO and H2 rise steeply as the excess O2 vanishes: both scales
shrink as the temperature falls), and interpolated in :math:`v` by not-a-knot cubic splines,
one per temperature of the grid. A case's
:class:`~rotarykiln.materials.dissociation.DissociationHeat` is then the cubic spline in
:math:`T` through the interpolated values (negatives set to 0) over the products'
:math:`Y_{CO_2} + Y_{H_2O}`, as Cantera's is through its own values. Against Cantera at 71
equivalence ratios off the nodes (0 to 1, a third of them within 0.1 of each end, down to
1e-9 from it) and every temperature of the grid (200-3200 K), the largest error is 0.86 J/kg
of products for CH4 in air (1.2e-5 of the value there), 0.85 natural gas, 1.0 H2, 0.65 CO,
0.77 H2-CO in air, 1.2 CH4 in 30 % O2, 0.22 CH4 in a flue gas with 5 % O2, 3.2 CH4 in pure O2:
within 1e-3 K of gas temperature (c_p 1300-2000 J/(kg K)); a hot kiln near stoichiometric
(equilibrium adiabatic temperature 2403 K) enters 4e-4 K apart and leaves 4e-5 K apart
(``tests/materials/test_combustion.py``). Building a table costs :data:`TABLE_NODES` x 121
Cantera equilibria, 0.5-1 s, once per pair; it is kept in memory and on disk
(:mod:`rotarykiln.materials._cache`). :meth:`DissociationTable.enthalpy` refuses an
equivalence ratio outside [0, 1] (a rich mixture: the caller computes it exactly).

The **equilibrium adiabatic temperature** (:func:`dissociated_adiabatic_temperature`) is the
root of :math:`h_p(T) + (Y_{CO_2} + Y_{H_2O})\,\Delta h'_d(T) = h_p(T_{ad})` on the same
splines the kiln's gas carries (within 6e-6 K of Cantera's ``equilibrate('HP')``).

References
----------
D.G. Goodwin et al., Cantera 3 (https://cantera.org): NASA-7 species thermochemistry,
``equilibrate('TP')``; G.P. Smith et al., GRI-Mech 3.0; S.R. Turns, *An Introduction to
Combustion*, 3rd ed., McGraw-Hill (2012), ch. 2 (complete combustion, equivalence ratio,
adiabatic temperatures); C. de Boor, *A Practical Guide to Splines* (1978) (not-a-knot cubic
splines).
"""

from __future__ import annotations

import math
import threading
from dataclasses import dataclass
from functools import cached_property, lru_cache

import numpy as np

from rotarykiln.errors import InputError
from rotarykiln.materials import _cache
from rotarykiln.materials.gas import (
    MECHANISM,
    T_GRID,
    T_MAX,
    T_MIN,
    T_REF,
    BurntGas,
    GasPropertyTable,
    PiecewisePolynomials,
    gas_table,
    parse_composition,
)

__all__ = [
    "ELEMENTS",
    "TABLE_NODES",
    "DissociationTable",
    "complete_combustion",
    "dissociated_adiabatic_temperature",
    "dissociation_table",
    "equivalence_ratio",
    "mixing_temperature",
]

#: Elements of GRI-Mech 3.0, in the order of the element arrays.
ELEMENTS = ("C", "H", "O", "N", "Ar")
#: The complete-combustion product of each element (and O2, the excess), in that order.
_PRODUCTS = ("CO2", "H2O", "O2", "N2", "AR")
R_CANTERA = 8314.46261815324  # J/(kmol K), Cantera's gas constant (NASA-7 h = h/RT R T)
#: The interpolation variable of the dissociation table, v = sqrt(phi) - c ln(1 - phi + eps).
TABLE_LOG_WEIGHT = 0.06
TABLE_LOG_OFFSET = 1.0e-6
#: Nodes of the dissociation table in the equivalence ratio, 0 to 1, uniform in v.
TABLE_NODES = 90
#: Relative tolerance of the element balance's O2 at stoichiometric (round-off of the flows).
_STOICHIOMETRIC_TOL = 1e-12
#: Temperature tolerance of the roots (mixing, adiabatic temperatures), K.
_T_TOL = 1e-10


def _cache_key(kind: str, *inputs) -> str:
    """Disk-cache key of a result of this module (its inputs, the grid, the environment)."""
    import hashlib

    grid = hashlib.sha256(T_GRID.tobytes()).hexdigest()
    env = _cache.environment_key(MECHANISM, ("gas.py", "dissociation.py", "combustion.py"))
    return f"{kind};{inputs!r};T_GRID={grid};{env}"


# ---------------------------------------------------------------------------------------------
# Species data: molar masses, elements, NASA-7 polynomials (Cantera once, then the disk cache)


@dataclass(frozen=True, eq=False)
class _Species:
    """Per-species arrays of GRI-Mech 3.0 species ``names``: ``molar_mass`` (kg/mol),
    ``elements`` (atoms of :data:`ELEMENTS` per molecule, shape (n, 5)), ``nasa`` (NASA-7:
    ``[T_mid, 7 high-range, 7 low-range coefficients]`` per species, Cantera's layout)."""

    names: tuple[str, ...]
    molar_mass: np.ndarray
    elements: np.ndarray
    nasa: np.ndarray

    @cached_property
    def _floats(self):
        """(T_mid, high, low) per species as Python floats (the hot loops)."""
        return [(float(c[0]), c[1:8].tolist(), c[8:15].tolist()) for c in self.nasa]

    def enthalpy_cp(self, moles, T: float) -> tuple[float, float]:
        """Enthalpy (J/s, formation included) and heat capacity (W/K) of the mole flows
        ``moles`` (mol/s per species, a sequence) at ``T`` (K): NASA-7 as Cantera evaluates it."""
        h = cp = 0.0
        t2, t3, t4 = T * T, T * T * T, T * T * T * T
        for n, (t_mid, hi, lo) in zip(moles, self._floats, strict=True):
            if n == 0.0:
                continue
            a = lo if T <= t_mid else hi
            ct1, ct2, ct3, ct4 = a[1] * T, a[2] * t2, a[3] * t3, a[4] * t4
            cp += n * (a[0] + ct1 + ct2 + ct3 + ct4)
            h += n * (a[0] + 0.5 * ct1 + ct2 / 3.0 + 0.25 * ct3 + 0.2 * ct4 + a[5] / T)
        r = R_CANTERA / 1000.0  # J/(mol K)
        return h * r * T, cp * r

    @cached_property
    def tables(self) -> tuple[np.ndarray, np.ndarray]:
        """The species' cp (J/(kg K)) and h (J/kg) spline coefficients on T_GRID stacked on a
        last axis, shapes (4, m, n) and (4, m, n) (:func:`gas_table` of each species)."""
        fits = [gas_table(f"{s}:1") for s in self.names]
        cp = np.stack([f._cp.c for f in fits], axis=-1)
        h = np.stack([f._h.c for f in fits], axis=-1)
        return cp, h


def _species_arrays(names: tuple[str, ...]) -> dict:
    """Cantera's part of :func:`_species`: molar masses, elements and NASA-7 coefficients."""
    from rotarykiln.materials.gas import gri30

    gas = gri30()
    unknown = [s for s in names if s not in gas.species_names]
    if unknown:
        raise InputError("gas.composition", ",".join(unknown), f"a species of {MECHANISM}")
    mm, elements, nasa = [], [], []
    for s in names:
        k = gas.species_index(s)
        sp = gas.species(k)
        if sp.input_data.get("thermo", {}).get("model") != "NASA7":
            raise InputError("gas.composition", s, "a species with NASA-7 thermochemistry")
        mm.append(float(gas.molecular_weights[k]) / 1000.0)
        elements.append([gas.n_atoms(k, e) if e in gas.element_names else 0.0 for e in ELEMENTS])
        c = np.asarray(sp.thermo.coeffs, dtype=float)
        if c.shape != (15,):
            raise InputError("gas.composition", s, "a species with one NASA-7 breakpoint")
        nasa.append(c)
    return {
        "molar_mass": np.array(mm, dtype=float),
        "elements": np.array(elements, dtype=float),
        "nasa": np.array(nasa, dtype=float),
    }


@lru_cache(maxsize=64)
def _species(names: tuple[str, ...]) -> _Species:
    """The :class:`_Species` of ``names`` (memory, else disk, else Cantera)."""
    key = _cache_key("species-data", names)
    a = _cache.load("combustion", key)
    if a is None:
        a = _species_arrays(names)
        _cache.store("combustion", key, a)
    return _Species(names, a["molar_mass"], a["elements"], a["nasa"])


@lru_cache(maxsize=256)
def _stream_vector(composition: str | tuple, names: tuple[str, ...]) -> tuple[float, ...]:
    """Mole fractions of ``composition`` on ``names`` (zeros for the others)."""
    x = dict(parse_composition(composition))
    return tuple(float(x.get(s, 0.0)) for s in names)


@lru_cache(maxsize=256)
def _names_of(compositions: tuple) -> tuple[str, ...]:
    """Every species of ``compositions`` and of the complete products, sorted."""
    names = set(_PRODUCTS)
    for c in compositions:
        names.update(s for s, _ in parse_composition(c))
    return tuple(sorted(names))


# ---------------------------------------------------------------------------------------------
# Roots in temperature: safeguarded Newton (no scipy needed)


def _solve_temperature(f, lo: float, hi: float, x0: float) -> float:
    """The root in [lo, hi] (K) of an increasing ``f`` (returning value and slope), by Newton
    steps kept inside a bracket that bisection shrinks when a step leaves it."""
    x = min(max(x0, lo), hi)
    for _ in range(200):
        fx, dfx = f(x)
        if fx == 0.0:
            return x
        if fx > 0.0:
            hi = x
        else:
            lo = x
        step = fx / dfx if dfx > 0.0 else math.inf
        if abs(step) <= _T_TOL:
            return float(x - step)
        new = x - step
        if not (lo < new < hi):
            new = 0.5 * (lo + hi)
        if hi - lo <= _T_TOL:
            return float(new)
        x = new
    return x  # pragma: no cover - 200 safeguarded steps always converge first


def mixing_temperature(streams) -> float:
    r"""Temperature of gas streams mixed at constant pressure and enthalpy, K.

    .. math:: \sum_s \dot m_s h_s(T_s) = \Big(\sum_s \dot m_s\Big) h_{mix}(T)

    on GRI-Mech 3.0's NASA-7 polynomials, solved to 1e-10 K (Cantera's ``Quantity`` mixing at
    ``HP``, without Cantera; Cantera's own solution stops within about 1e-6 K). Streams at one
    temperature mix at it.

    Parameters
    ----------
    streams : sequence of (float, float, str)
        ``(flow, temperature, composition)`` of each stream: mass flow (kg/s), temperature (K),
        mole fractions (Cantera text or pairs).

    Returns
    -------
    float, K
        The mixed temperature (298.15 K when nothing flows).

    Examples
    --------
    >>> from rotarykiln.materials.gas import AIR
    >>> round(mixing_temperature(((1.0, 300.0, AIR), (1.0, 1100.0, AIR))), 2)  # c_p rises
    716.05

    References
    ----------
    Ideal-gas mixing, e.g. S.R. Turns, An Introduction to Combustion, 3rd ed. (2012), ch. 2;
    GRI-Mech 3.0 thermochemistry (Cantera).
    """
    flowing = [(float(m), float(t), c) for m, t, c in streams if m > 0]
    if not flowing:
        return T_REF
    temps = {t for _, t, _ in flowing}
    if len(temps) == 1:
        return flowing[0][1]
    names = _names_of(tuple(c for _, _, c in flowing))
    sp = _species(names)
    total = np.zeros(len(names))
    enthalpy = 0.0
    for m, t, c in flowing:
        moles = _moles(c, names, sp, m)
        enthalpy += sp.enthalpy_cp(moles.tolist(), t)[0]
        total += moles
    n = total.tolist()
    return _solve_temperature(
        lambda T: _shifted(sp.enthalpy_cp(n, T), enthalpy),
        min(temps),
        max(temps),
        sum(m * t for m, t, _ in flowing) / sum(m for m, _, _ in flowing),
    )


def _shifted(value_slope, target):
    return value_slope[0] - target, value_slope[1]


def _moles(composition, names, sp: _Species, flow: float) -> np.ndarray:
    """Mole flows (mol/s) on ``names`` of ``flow`` kg/s of ``composition``."""
    x = np.array(_stream_vector(composition, names))
    return x * (flow / float(x @ sp.molar_mass))


# ---------------------------------------------------------------------------------------------
# Complete combustion by elements


def _demand(elements: np.ndarray) -> np.ndarray:
    """O2 demand (mol O2 per mol) of element rows: C + H/4 - O/2."""
    return elements[..., 0] + 0.25 * elements[..., 1] - 0.5 * elements[..., 2]


def equivalence_ratio(fuel, fuel_flow: float, oxidisers) -> float:
    r"""Equivalence ratio of a fuel and its oxidiser streams, :math:`\phi = 1/\lambda`.

    .. math:: \phi = \frac{\sum \dot n_{fuel}\,d_{fuel}}{-\sum_s \dot n_s\,d_s},\qquad
              d = N_C + \tfrac14 N_H - \tfrac12 N_O

    (:math:`d`: the O2 demand per mole, negative for an oxidiser: its free O2).

    Parameters
    ----------
    fuel : str or pairs
        Fuel composition by mole.
    fuel_flow : float, kg/s
    oxidisers : sequence of (float, float, str)
        ``(flow kg/s, temperature K, composition)`` of each oxidiser stream.

    Returns
    -------
    float
        The equivalence ratio, dimensionless: 0 to 1 lean, above 1 rich (inf without free O2).

    Examples
    --------
    >>> from rotarykiln.materials.gas import AIR, AIR_MOLAR_MASS
    >>> air = ((2.0 / 0.2095 * AIR_MOLAR_MASS, 298.15, AIR),)  # 2 mol/s of O2
    >>> round(equivalence_ratio("CH4:1", 0.01604276, air), 4)  # 1 mol/s of CH4
    1.0

    References
    ----------
    S.R. Turns, An Introduction to Combustion, 3rd ed. (2012), ch. 2.
    """
    names = _names_of((fuel, *(c for _, _, c in oxidisers)))
    sp = _species(names)
    d = _demand(sp.elements)
    need = float(_moles(fuel, names, sp, float(fuel_flow)) @ d)
    free = -sum(float(_moles(c, names, sp, float(m)) @ d) for m, _, c in oxidisers if m > 0)
    return need / free if free > 0 else math.inf


def complete_combustion(fuel, fuel_flow: float, fuel_temperature: float, oxidisers):
    r"""A lean fuel burnt completely with oxidiser streams, by elements: the products, their
    temperatures and the heat of combustion (see the module), without Cantera.

    Parameters
    ----------
    fuel : str or pairs
        Fuel composition by mole (GRI-Mech 3.0 species).
    fuel_flow : float, kg/s
    fuel_temperature : float, K
    oxidisers : sequence of (float, float, str)
        ``(flow kg/s, temperature K, composition)`` of each oxidiser stream.

    Returns
    -------
    BurntGas or None
        The products (``composition`` by mole, ``mass_flow`` kg/s, ``inlet_temperature`` K of
        the unburnt streams mixed, ``heat_release`` W at it, frozen ``adiabatic_temperature``
        K, ``table`` mixed from the species' tables); None for a rich mixture (too little free
        O2: burn it with :func:`rotarykiln.materials.gas.burn_fuel`).

    Examples
    --------
    >>> from rotarykiln.materials.gas import AIR
    >>> b = complete_combustion("CH4:1", 1.0e-3, 298.15, ((1.0e-3 * 17.2 * 1.1, 298.15, AIR),))
    >>> round(b.heat_release / 1.0e-3 / 1e6, 2), round(b.adiabatic_temperature, -1)  # the LHV
    (50.03, 2190.0)

    References
    ----------
    See the module docstring.
    """
    oxidisers = tuple((float(m), float(t), c) for m, t, c in oxidisers)
    return _complete(fuel, float(fuel_flow), float(fuel_temperature), oxidisers)


@lru_cache(maxsize=1024)
def _complete(fuel, fuel_flow: float, fuel_temperature: float, oxidisers: tuple):
    """:func:`complete_combustion` (kept in memory per exact inputs)."""
    if not (np.isfinite(fuel_flow) and fuel_flow > 0):
        raise InputError("gas.fuel_flow", fuel_flow, "> 0 kg/s")
    flowing = [s for s in oxidisers if s[0] > 0]
    if not flowing:
        raise InputError("gas.air_flow", 0.0, "> 0 kg/s")
    names = _names_of((fuel, *(c for _, _, c in flowing)))
    sp = _species(names)
    fuel_moles = _moles(fuel, names, sp, fuel_flow)
    streams = [(fuel_moles, fuel_temperature)]
    streams += [(_moles(c, names, sp, m), t) for m, t, c in flowing]
    reactants = sum(n for n, _ in streams)
    elements = reactants @ sp.elements  # mol/s of C, H, O, N, Ar
    c, h, o, n, ar = elements.tolist()
    o2 = 0.5 * o - c - 0.25 * h
    if o2 < -_STOICHIOMETRIC_TOL * 0.5 * o:
        return None  # rich
    product_moles = dict(zip(_PRODUCTS, (c, 0.5 * h, max(o2, 0.0), 0.5 * n, ar), strict=True))
    products = np.array([product_moles.get(s, 0.0) for s in names])
    # the unburnt streams mixed at constant enthalpy (NASA-7), then the heat of combustion
    enthalpy = sum(sp.enthalpy_cp(m.tolist(), t)[0] for m, t in streams)
    temps = [t for _, t in streams]
    if len(set(temps)) == 1:
        t_in = temps[0]
    else:
        r = reactants.tolist()
        t_in = _solve_temperature(
            lambda T: _shifted(sp.enthalpy_cp(r, T), enthalpy),
            min(temps),
            max(temps),
            sum(float(m @ sp.molar_mass) * t for m, t in streams) / (fuel_flow + _air(flowing)),
        )
    mass_flow = fuel_flow + _air(flowing)
    q = enthalpy - sp.enthalpy_cp(products.tolist(), t_in)[0]
    mass = products * sp.molar_mass
    table = _mixed_table(sp, products, mass / mass.sum())
    target = table._enthalpy_at(t_in) + q / mass_flow
    lo, hi = T_MIN, 2 * T_MAX
    if table._enthalpy_at(lo) > target or table._enthalpy_at(hi) < target:
        raise InputError(
            "air_flow",
            f"{_air(flowing):.6g} kg/s",
            f"enough to burn {fuel_flow:.6g} kg/s of fuel (air/fuel mass ratio "
            f"{_air(flowing) / fuel_flow:.4g}: the products would leave outside [{lo:g}, {hi:g}] K)",
        )
    t_ad = _solve_temperature(lambda T: _table_slope(table, T, target), lo, hi, t_in)
    return BurntGas(table.composition, mass_flow, t_in, t_ad, q, table)


def _air(streams) -> float:
    return sum(m for m, _, _ in streams)


def _table_slope(table: GasPropertyTable, T: float, target: float) -> tuple[float, float]:
    """``table``'s enthalpy at ``T`` less ``target`` (J/kg) and its c_p (J/(kg K))."""
    lo, hi = table._cp_ends
    cp = lo if T < T_MIN else hi if T > T_MAX else table._cp.value(T)
    return table._enthalpy_at(T) - target, cp


def _mixed_table(sp: _Species, moles: np.ndarray, mass_fractions: np.ndarray) -> GasPropertyTable:
    """The :class:`GasPropertyTable` of a mixture of ``sp``'s species: cp and h mixed from the
    species' tables by mass fraction (the mixture's own table to round-off; the transport
    fits computed on first use, :attr:`GasPropertyTable._transport_fits`)."""
    keep = moles > 0
    composition = parse_composition(
        {s: float(v) for s, v, k in zip(sp.names, moles, keep, strict=True) if k}
    )
    cp_c, h_c = sp.tables
    x = dict(composition)
    total = sum(x.values())
    return GasPropertyTable(
        composition=composition,
        molar_mass=float(moles @ sp.molar_mass / moles.sum()),
        x_co2=x.get("CO2", 0.0) / total,
        x_h2o=x.get("H2O", 0.0) / total,
        _cp=PiecewisePolynomials(T_GRID, cp_c @ mass_fractions),
        _h=PiecewisePolynomials(T_GRID, h_c @ mass_fractions),
    )


# ---------------------------------------------------------------------------------------------
# Not-a-knot cubic splines as linear maps (numpy only: scipy's CubicSpline to round-off)


def _spline_map(x: np.ndarray) -> np.ndarray:
    """The linear map (shape (4, m, n)) from values ``y`` at the ``n`` breakpoints ``x`` to
    the coefficients of their not-a-knot cubic spline (scipy's ``PPoly`` layout, highest power
    first): ``c = np.tensordot(M, y, 1)``, scipy's ``CubicSpline(x, y).c`` to round-off."""
    x = np.asarray(x, dtype=float)
    return _spline_coefficients(x, np.eye(len(x)))


def _spline_coefficients(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Coefficients (4, m, k) of the not-a-knot cubic splines through the columns of ``y``
    (shape (n, k)) at the ``n`` breakpoints ``x``: scipy's ``CubicSpline(x, y).c`` to
    round-off.

    The slopes at the breakpoints solve scipy's tridiagonal system (its not-a-knot end rows
    are tridiagonal too), by elimination without pivoting, for every column at once: no
    LAPACK call (whose first call in a process costs tens of ms)."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    n = len(x)
    if n < 4:
        raise ValueError("a not-a-knot spline needs at least 4 breakpoints")
    dx = np.diff(x)
    slope = (y[1:] - y[:-1]) / dx[:, None]
    sub, diag, sup = np.zeros(n), np.zeros(n), np.zeros(n)
    rhs = np.empty(y.shape)
    sub[1:-1], diag[1:-1], sup[1:-1] = dx[1:], 2.0 * (dx[:-1] + dx[1:]), dx[:-1]
    rhs[1:-1] = 3.0 * (dx[1:, None] * slope[:-1] + dx[:-1, None] * slope[1:])
    d = x[2] - x[0]
    diag[0], sup[0] = dx[1], d
    rhs[0] = ((dx[0] + 2.0 * d) * dx[1] * slope[0] + dx[0] ** 2 * slope[1]) / d
    d = x[-1] - x[-3]
    sub[-1], diag[-1] = d, dx[-2]
    rhs[-1] = (dx[-1] ** 2 * slope[-2] + (2.0 * d + dx[-1]) * dx[-2] * slope[-1]) / d
    for i in range(1, n):  # forward elimination
        w = sub[i] / diag[i - 1]
        diag[i] -= w * sup[i - 1]
        rhs[i] -= w * rhs[i - 1]
    s = np.empty(y.shape)  # slopes at the breakpoints
    s[-1] = rhs[-1] / diag[-1]
    for i in range(n - 2, -1, -1):
        s[i] = (rhs[i] - sup[i] * s[i + 1]) / diag[i]
    t = (s[:-1] + s[1:] - 2.0 * slope) / dx[:, None]
    out = np.empty((4, n - 1, y.shape[1]))
    out[0] = t / dx[:, None]
    out[1] = (slope - s[:-1]) / dx[:, None] - t
    out[2] = s[:-1]
    out[3] = y[:-1]
    return out


@lru_cache(maxsize=1)
def _grid_map() -> np.ndarray:
    """:func:`_spline_map` of :data:`T_GRID`, flattened to (4 * m, n)."""
    m = _spline_map(T_GRID)
    return m.reshape(-1, m.shape[-1])


# ---------------------------------------------------------------------------------------------
# The dissociation table


def _table_variable(phi):
    """The table's interpolation variable v(phi) (see the module)."""
    phi = np.asarray(phi, dtype=float)
    c, eps = TABLE_LOG_WEIGHT, TABLE_LOG_OFFSET
    return np.sqrt(phi) + c * (np.log1p(phi / eps) - np.log1p(eps - phi))


def _table_nodes() -> np.ndarray:
    """The equivalence ratios of the table's nodes: uniform in v from phi = 0 to 1 (bisection:
    v is increasing)."""
    v = np.linspace(0.0, float(_table_variable(1.0)), TABLE_NODES)
    phi = np.empty_like(v)
    phi[0], phi[-1] = 0.0, 1.0
    for i, target in enumerate(v[1:-1], start=1):
        lo, hi = 0.0, 1.0
        for _ in range(80):
            mid = 0.5 * (lo + hi)
            if _table_variable(mid) < target:
                lo = mid
            else:
                hi = mid
        phi[i] = 0.5 * (lo + hi)
    return phi


@dataclass(frozen=True, eq=False)
class DissociationTable:
    r"""The dissociation heat of one fuel's complete products with one oxidiser, tabulated
    over the equivalence ratio (see the module).

    Attributes
    ----------
    fuel, oxidiser : tuple of (str, float)
        Compositions by mole (:func:`~rotarykiln.materials.gas.parse_composition` form).
    pressure : float, Pa
    phi : ndarray
        Equivalence ratios of the nodes, dimensionless, 0 to 1.
    values : ndarray
        :math:`\Delta h_d` (J/kg of products) at the nodes (rows) on T_GRID (columns).

    Examples
    --------
    >>> from rotarykiln.materials.gas import AIR
    >>> t = dissociation_table("CH4:1", AIR)  # about 0.7 s, or from the disk cache
    >>> round(float(t.enthalpy(0.9)[T_GRID == 2200.0][0]) / 1e3)  # kJ/kg of products
    74

    References
    ----------
    See the module docstring.
    """

    fuel: tuple[tuple[str, float], ...]
    oxidiser: tuple[tuple[str, float], ...]
    pressure: float
    phi: np.ndarray
    values: np.ndarray

    @cached_property
    def _spline(self) -> PiecewisePolynomials:
        """The values' splines in v (one per temperature of the grid)."""
        v = _table_variable(self.phi)
        return PiecewisePolynomials(v, _spline_coefficients(v, self.values))

    def enthalpy(self, phi: float) -> np.ndarray:
        """:math:`\\Delta h_d` (J/kg of products, >= 0) on T_GRID at the equivalence ratio
        ``phi`` (dimensionless, in [0, 1]: outside it, :class:`ValueError`)."""
        phi = float(phi)
        if not 0.0 <= phi <= 1.0:
            raise ValueError(
                f"equivalence ratio {phi!r} outside the dissociation table's [0, 1] (a rich "
                "mixture: compute its dissociation heat exactly)"
            )
        s = self._spline
        out = s.evaluate(*s.interval(np.array([float(_table_variable(phi))])))[0]
        return np.maximum(out, 0.0)

    def heat(self, phi: float, composition):
        """The :class:`~rotarykiln.materials.dissociation.DissociationHeat` of the products of
        equivalence ratio ``phi`` (dimensionless, [0, 1]) and ``composition`` (their mole
        fractions, the complete products at ``phi``): J/kg of CO2 + H2O."""
        from rotarykiln.materials.dissociation import (
            DissociationHeat,
            PPolyValues,
            _checked,
        )

        comp = _checked(composition)
        names = tuple(s for s, _ in comp)
        sp = _species(_names_of((comp,)))
        x = np.array(_stream_vector(comp, sp.names))
        mass = x * sp.molar_mass
        y = dict(zip(sp.names, (mass / mass.sum()).tolist(), strict=True))
        carriers = y.get("CO2", 0.0) + y.get("H2O", 0.0)
        if carriers <= 0 or not names:
            raise InputError("products.composition", comp, "with CO2 or H2O")
        c = (_grid_map() @ (self.enthalpy(phi) / carriers)).reshape(4, len(T_GRID) - 1)
        return DissociationHeat(comp, PPolyValues(T_GRID, c))


def _table_arrays(fuel, oxidiser, pressure: float) -> dict:
    """Cantera's part of :func:`dissociation_table`: the nodes and their dissociation heat.

    Each value is :func:`~rotarykiln.materials.dissociation.dissociation_enthalpy`'s, with
    Cantera's ``gibbs`` (VCS) equilibrium solver called directly: the default (``auto``)
    tries the element-potential solver first, which fails on these mixtures before falling
    back to it, slowly near stoichiometric (ten times the cost); the two agree within 1e-9 of
    the value (1e-3 J/kg). Where ``gibbs`` fails (e.g. a fuel without hydrogen), the default.
    """
    import cantera as ct

    from rotarykiln.materials.dissociation import _solution

    gas = _solution()
    phi = _table_nodes()
    values = np.empty((len(phi), len(T_GRID)))
    for i, p in enumerate(phi):
        x = _products_at(fuel, oxidiser, p)
        for j, t in enumerate(T_GRID):
            gas.TPX = t, pressure, x
            h_frozen = gas.enthalpy_mass
            try:
                gas.equilibrate("TP", solver="gibbs")
            except ct.CanteraError:  # e.g. a fuel without hydrogen: the default solvers
                gas.TPX = t, pressure, x
                gas.equilibrate("TP")
            values[i, j] = max(gas.enthalpy_mass - h_frozen, 0.0)
    return {"phi": phi, "values": values}


def _products_at(fuel, oxidiser, phi: float) -> dict[str, float]:
    """Complete products (mol per mol of oxidiser) of ``fuel`` and ``oxidiser`` at the
    equivalence ratio ``phi``."""
    names = _names_of((fuel, oxidiser))
    sp = _species(names)
    d = _demand(sp.elements)
    xf = np.array(_stream_vector(fuel, names))
    xa = np.array(_stream_vector(oxidiser, names))
    ratio = phi * -float(xa @ d) / float(xf @ d)  # mol of fuel per mol of oxidiser
    c, h, o, n, ar = ((xa + ratio * xf) @ sp.elements).tolist()
    o2 = max(0.5 * o - c - 0.25 * h, 0.0)
    out = dict(zip(_PRODUCTS, (c, 0.5 * h, o2, 0.5 * n, ar), strict=True))
    return {k: v for k, v in out.items() if v > 0}


def table_pair(fuel, oxidiser) -> bool:
    """Whether ``fuel`` and ``oxidiser`` can have a :class:`DissociationTable`: the fuel has
    an O2 demand and the oxidiser free O2 (their products then depend on phi alone)."""
    names = _names_of((fuel, oxidiser))
    sp = _species(names)
    d = _demand(sp.elements)
    return (
        float(np.array(_stream_vector(fuel, names)) @ d) > 0
        and float(np.array(_stream_vector(oxidiser, names)) @ d) < 0
    )


_lock = threading.Lock()


def dissociation_table(fuel, oxidiser, pressure: float = 101325.0) -> DissociationTable:
    """The :class:`DissociationTable` of ``fuel`` and ``oxidiser`` (compositions by mole) at
    ``pressure`` (Pa): kept in memory and on disk, computed once (about 0.3 s)."""
    if not table_pair(fuel, oxidiser):
        raise InputError(
            "burner.fuel", fuel, "a fuel with an O2 demand burnt with an oxidiser with free O2"
        )
    return _table(parse_composition(fuel), parse_composition(oxidiser), float(pressure))


@lru_cache(maxsize=32)
def _table(fuel, oxidiser, pressure: float) -> DissociationTable:
    key = _cache_key(
        "dissociation-table", fuel, oxidiser, pressure, TABLE_NODES, TABLE_LOG_WEIGHT,
        TABLE_LOG_OFFSET,
    )  # fmt: skip
    with _lock:
        a = _cache.load("dissociation", key)
        if a is None:
            a = _table_arrays(fuel, oxidiser, pressure)
            _cache.store("dissociation", key, a)
    return DissociationTable(fuel, oxidiser, pressure, a["phi"], a["values"])


def dissociated_adiabatic_temperature(products: BurntGas, heat) -> float:
    r"""Adiabatic temperature of products that dissociate, on the kiln's own splines, K.

    The root of :math:`h_p(T) + (Y_{CO_2} + Y_{H_2O})\,\Delta h'_d(T) = h_p(T_{ad})`, with
    :math:`h_p` the products' table and :math:`\Delta h'_d` the dissociation heat per kg of
    CO2 + H2O: the gas the kiln carries holds at it the enthalpy of the frozen products at
    their adiabatic temperature (within 6e-6 K of Cantera's ``equilibrate('HP')``).

    Parameters
    ----------
    products : BurntGas
        The frozen products (their table and adiabatic temperature, K).
    heat : DissociationHeat
        Their dissociation heat (J/kg of CO2 + H2O).

    Returns
    -------
    float, K

    Examples
    --------
    >>> from rotarykiln.materials.dissociation import dissociation_heat
    >>> from rotarykiln.materials.gas import AIR
    >>> b = complete_combustion("CH4:1", 1.0e-3, 298.15, ((1.0e-3 * 17.2 * 1.1, 298.15, AIR),))
    >>> d = dissociation_heat([(k, x) for k, x in b.composition])
    >>> round(b.adiabatic_temperature - dissociated_adiabatic_temperature(b, d))
    39

    References
    ----------
    Turns (2012) ch. 2 (the equilibrium adiabatic flame temperature).
    """
    table = products.table
    sp = _species(_names_of((table.composition,)))
    x = np.array(_stream_vector(table.composition, sp.names))
    mass = x * sp.molar_mass
    y = dict(zip(sp.names, (mass / mass.sum()).tolist(), strict=True))
    carriers = y.get("CO2", 0.0) + y.get("H2O", 0.0)
    c = np.asarray(heat.spline.c, dtype=float)
    h_d = PiecewisePolynomials(T_GRID, c)
    cp_d = PiecewisePolynomials(T_GRID, c[:3] * np.array([3.0, 2.0, 1.0])[:, None])
    t_fr = float(products.adiabatic_temperature)
    target = table._enthalpy_at(t_fr)

    def f(T):
        value, slope = _table_slope(table, T, target)
        t = min(max(T, T_GRID[0]), T_GRID[-1])
        inside = T_GRID[0] <= T <= T_GRID[-1]
        return value + carriers * h_d.value(t), slope + (carriers * cp_d.value(t) if inside else 0)

    if f(t_fr)[0] <= 0.0:
        return t_fr
    return _solve_temperature(f, T_MIN, t_fr, t_fr)
