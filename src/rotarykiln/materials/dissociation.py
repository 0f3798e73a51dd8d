r"""Dissociation of hot combustion products: the heat held in CO, H2, OH, H and O at equilibrium.

Above about 1800 K the products of a flame are not CO2, H2O, O2 and N2 alone: part of the CO2
and water is dissociated, and the heat of that dissociation is missing from the sensible heat.
A gas kept at chemical equilibrium as it cools (recombination is fast at these temperatures)
therefore has an **equilibrium enthalpy** above the frozen one by

.. math:: \Delta h_d(T) = h_{eq}(T, p) - h_{fr}(T)\quad[\mathrm{J/kg}] \;\ge 0

where :math:`h_{fr}` is the enthalpy of the complete-combustion products and :math:`h_{eq}`
that of the same elements at equilibrium at :math:`T` and :math:`p` (Cantera, GRI-Mech 3.0
thermochemistry, over the species :data:`DISSOCIATION_SPECIES`: nitric oxide is left out, its
formation being kinetically slow, thermal-NOx, and of no weight in the energy balance).
Carrying :math:`\Delta h_d` in the gas enthalpy makes the instant burn-out's inlet temperature
the equilibrium adiabatic temperature, and gives the recombination heat back where the gas
cools. Below about 1500 K :math:`\Delta h_d` vanishes (< 1e-4 of the sensible heat).

References
----------
D.G. Goodwin et al., Cantera 3 (https://cantera.org), ``equilibrate('TP')``; GRI-Mech 3.0
thermochemistry; S.R. Turns, *An Introduction to Combustion*, 3rd ed., McGraw-Hill (2012),
ch. 2 (dissociation and the equilibrium adiabatic flame temperature).
"""

from __future__ import annotations

import threading
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from rotarykiln.errors import InputError
from rotarykiln.materials import _cache
from rotarykiln.materials.gas import MECHANISM, T_GRID, T_REF, parse_composition

__all__ = [
    "DISSOCIATION_SPECIES",
    "DissociationHeat",
    "dissociation_enthalpy",
    "dissociation_heat",
    "equilibrium_adiabatic_temperature",
]

#: Species of the equilibrium (GRI-Mech 3.0 names): the major products and the minor species
#: of CO2 and H2O dissociation; no nitrogen oxides.
DISSOCIATION_SPECIES = ("N2", "O2", "CO2", "H2O", "CO", "H2", "OH", "H", "O", "AR")


@lru_cache(maxsize=1)
def _species():
    import cantera as ct

    return [s for s in ct.Species.list_from_file(MECHANISM) if s.name in DISSOCIATION_SPECIES]


_thread = threading.local()


def _solution():
    """This thread's Cantera solution of :data:`DISSOCIATION_SPECIES` (its state is always set
    in full, ``TPX``, before use: the same numbers as a fresh one)."""
    gas = getattr(_thread, "gas", None)
    if gas is None:
        import cantera as ct

        gas = _thread.gas = ct.Solution(thermo="ideal-gas", species=_species())
    return gas


def _cache_key(kind: str, *inputs) -> str:
    import hashlib

    grid = hashlib.sha256(T_GRID.tobytes()).hexdigest()
    env = _cache.environment_key(MECHANISM, ("gas.py", "dissociation.py"))
    return f"{kind};{inputs!r};T_GRID={grid};{env}"


def _checked(composition):
    pairs = parse_composition(composition)
    unknown = [s for s, _ in pairs if s not in DISSOCIATION_SPECIES]
    if unknown:
        raise InputError(
            "products.composition",
            ", ".join(unknown),
            f"species of the dissociation equilibrium ({', '.join(DISSOCIATION_SPECIES)})",
        )
    return pairs


def dissociation_enthalpy(composition, T, pressure=101325.0):
    r"""Heat held by dissociation in combustion products at equilibrium, J/kg of products.

    .. math:: \Delta h_d(T) = h_{eq}(T, p) - h_{fr}(T)

    Parameters
    ----------
    composition : str or mapping
        Mole fractions of the complete-combustion products (CO2, H2O, O2, N2, Ar; the species
        of :data:`DISSOCIATION_SPECIES`).
    T : float or array, K
        Temperature, 200-3200 K.
    pressure : float, Pa

    Returns
    -------
    float or array, J/kg
        Never negative.

    Examples
    --------
    Stoichiometric methane-air products (CO2 1, H2O 2, N2 7.52 by mole): 32 J/kg at 1200 K
    (3e-5 of their sensible heat), 126 kJ/kg at 2200 K (2.2 MJ per kg of methane burnt, 4 % of
    its heating value):

    >>> x = "CO2:1, H2O:2, N2:7.52"
    >>> round(float(dissociation_enthalpy(x, 1200.0)))
    32
    >>> round(float(dissociation_enthalpy(x, 2200.0)) / 1e3)
    126

    References
    ----------
    See the module docstring.
    """
    X = dict(_checked(composition))
    if not np.isfinite(pressure) or pressure <= 0:
        raise InputError("pressure", pressure, "> 0 Pa")
    T = np.asarray(T, dtype=float)
    gas = _solution()
    out = np.empty(T.shape)
    for i, t in np.ndenumerate(T):
        gas.TPX = t, pressure, X
        h_frozen = gas.enthalpy_mass
        gas.equilibrate("TP")
        out[i] = max(gas.enthalpy_mass - h_frozen, 0.0)
    return out if out.ndim else float(out)


def equilibrium_adiabatic_temperature(composition, T_frozen, pressure=101325.0) -> float:
    r"""Adiabatic temperature of products that dissociate, K.

    The products of complete combustion at their frozen adiabatic temperature ``T_frozen``
    hold the heat of combustion as sensible heat; at equilibrium at the same enthalpy part of
    it is held by dissociation and the temperature is lower
    (:math:`h_{fr}(T_{ad,eq}) + \Delta h_d(T_{ad,eq}) = h_{fr}(T_{fr})`).

    Parameters
    ----------
    composition : str or mapping
        Mole fractions of the complete-combustion products.
    T_frozen : float, K
        Their frozen adiabatic temperature.
    pressure : float, Pa

    Returns
    -------
    float, K

    Examples
    --------
    Stoichiometric methane-air from 298.15 K: about 2330 K frozen, 2225 K at equilibrium:

    >>> round(equilibrium_adiabatic_temperature("CO2:1, H2O:2, N2:7.52", 2328.0), -1)
    2230.0

    References
    ----------
    Turns (2012) ch. 2; Cantera ``equilibrate('HP')``.
    """
    return _adiabatic(_checked(composition), float(T_frozen), float(pressure))


@lru_cache(maxsize=1024)
def _adiabatic(composition, T_frozen: float, pressure: float) -> float:
    key = _cache_key("tad", composition, T_frozen, pressure)
    a = _cache.load("dissociation", key)
    if a is None:
        a = {"T": np.float64(_adiabatic_state(composition, T_frozen, pressure))}
        _cache.store("dissociation", key, a)
    return float(a["T"])


def _adiabatic_state(composition, T_frozen, pressure, gas=None) -> float:
    gas = _solution() if gas is None else gas
    gas.TPX = T_frozen, pressure, dict(composition)
    gas.equilibrate("HP")
    return float(gas.T)


class PPolyValues:
    """A piecewise polynomial evaluated as scipy's ``PPoly.__call__`` does, term for term.

    ``x``: breakpoints; ``c``: coefficients in ``PPoly`` layout ``(order + 1, len(x) - 1)``.
    ``self(T, nu)`` (``nu`` 0 or 1: the value or the first derivative) finds the interval
    ``x[i] <= T < x[i+1]`` (the last closed, the end pieces extrapolated) and sums the powers
    of ``T - x[i]`` from the lowest up with the same operations in the same order as scipy's
    compiled loop, so the floats are the same (checked in the tests against ``CubicSpline``);
    scipy's interpolate package (~0.3 s to import) is not needed to evaluate a stored spline.
    """

    def __init__(self, x, c):
        self.x = np.asarray(x, dtype=float)
        self.c = np.asarray(c, dtype=float)

    def __call__(self, T, nu: int = 0):
        if nu not in (0, 1):
            raise ValueError("nu must be 0 or 1")
        T = np.asarray(T, dtype=float)
        t = T.reshape(-1)
        i = np.searchsorted(self.x, t, side="right") - 1
        np.clip(i, 0, len(self.x) - 2, out=i)
        s = t - self.x[i]
        c = self.c
        n = c.shape[0]
        res = np.zeros_like(s)
        z = np.ones_like(s)
        for kp in range(n):
            if kp < nu:
                continue
            term = c[n - kp - 1].take(i) * z
            if nu == 1:
                term = term * float(kp)
            res = res + term
            if kp < n - 1:
                z = z * s
        return res.reshape(T.shape)


@dataclass(frozen=True, eq=False)
class DissociationHeat:
    r"""Dissociation heat of a burner's products per kg of their CO2 and H2O, as a species
    property (the kiln gas adds it to the enthalpy of its CO2 and H2O).

    ``enthalpy(T)`` (J/kg of CO2 + H2O) is :math:`\Delta h_d / (Y_{CO_2} + Y_{H_2O})`, a cubic
    spline through the equilibrium values on :data:`~rotarykiln.materials.gas.T_GRID`;
    ``cp(T)`` (J/(kg K)) is its derivative. ``composition``: the products' mole fractions.
    """

    composition: tuple[tuple[str, float], ...]
    spline: PPolyValues

    def enthalpy(self, T):
        return self.spline(np.clip(np.asarray(T, dtype=float), T_GRID[0], T_GRID[-1]))

    def cp(self, T):
        T = np.asarray(T, dtype=float)
        inside = (T >= T_GRID[0]) & (T <= T_GRID[-1])
        return np.where(inside, self.spline(T, 1), 0.0)

    def grid_pieces(self):
        """The cubic c_p and quartic h pieces of :func:`~rotarykiln.kiln.gas_mixture.fit_pieces`
        on :data:`T_GRID` (shapes (4, m), (5, m), PPoly layout), read off the spline itself:
        its pieces are those polynomials already (h the spline with a zero quartic term, c_p
        its derivative), which a least-squares fit would only recover to round-off."""
        c = self.spline.c  # (4, m): a s^3 + b s^2 + c s + d on each interval
        if not np.array_equal(self.spline.x, T_GRID) or c.shape[0] != 4:
            raise ValueError("the dissociation spline is not a cubic on the T_GRID breakpoints")
        m = c.shape[1]
        cp = np.zeros((4, m))
        cp[1:] = c[:3] * np.array([3.0, 2.0, 1.0])[:, None]
        h = np.zeros((5, m))
        h[1:] = c
        return cp, h


@lru_cache(maxsize=256)
def _heat(composition: tuple[tuple[str, float], ...], pressure: float) -> DissociationHeat:
    key = _cache_key("heat", composition, pressure)
    a = _cache.load("dissociation", key)
    if a is None:
        a = _heat_arrays(composition, pressure)
        _cache.store("dissociation", key, a)
    return DissociationHeat(composition, PPolyValues(a["x"], a["c"]))


def _heat_arrays(composition, pressure: float) -> dict:
    """The spline of :class:`DissociationHeat` (Cantera's equilibria on :data:`T_GRID`,
    scipy's ``CubicSpline``) as arrays ``x`` and ``c``."""
    from scipy.interpolate import CubicSpline

    gas = _solution()
    gas.TPX = T_REF, pressure, dict(composition)
    y = dict(zip(gas.species_names, gas.Y, strict=True))
    carriers = y.get("CO2", 0.0) + y.get("H2O", 0.0)
    if carriers <= 0:
        raise InputError("products.composition", composition, "with CO2 or H2O")
    dh = dissociation_enthalpy(composition, T_GRID, pressure) / carriers
    spline = CubicSpline(T_GRID, dh)
    return {"x": spline.x, "c": spline.c}


def dissociation_heat(composition, pressure=101325.0) -> DissociationHeat:
    r"""The dissociation heat of products of ``composition`` per kg of their CO2 and H2O.

    .. math:: \Delta h'_d(T) = \frac{\Delta h_d(T)}{Y_{CO_2} + Y_{H_2O}}

    Parameters
    ----------
    composition : str or mapping
        Mole fractions of the complete-combustion products.
    pressure : float, Pa

    Returns
    -------
    DissociationHeat
        ``enthalpy(T)`` in J/kg of CO2 + H2O and ``cp(T)`` in J/(kg K), 200-3200 K (cached).

    Examples
    --------
    Per kg of CO2 + H2O of stoichiometric methane-air products: 3.5 J/kg at 1000 K, 0.46 MJ/kg
    at 2200 K:

    >>> d = dissociation_heat("CO2:1, H2O:2, N2:7.52")
    >>> round(float(d.enthalpy(1000.0)), 1), round(float(d.enthalpy(2200.0)) / 1e6, 2)
    (3.5, 0.46)

    References
    ----------
    See the module docstring.
    """
    return _heat(_checked(composition), float(pressure))
