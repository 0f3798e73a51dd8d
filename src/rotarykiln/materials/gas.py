r"""Gas properties for the kiln freeboard, precomputed from Cantera into fitted tables.

Cantera is called once per composition (when a :class:`GasPropertyTable` is built); a hot
solver loop then evaluates piecewise-cubic fits, never Cantera. The specific heat is a cubic
spline in :math:`T` and the enthalpy is its exact antiderivative, so

.. math:: h(T) = h(T_{ref}) + \int_{T_{ref}}^{T} c_p\,dT

holds to round-off and an energy balance written with :meth:`GasPropertyTable.enthalpy` is
consistent with :meth:`GasPropertyTable.cp`. Conductivity and viscosity are cubic splines of
the Cantera mixture-averaged transport values. The density follows the ideal-gas law.

The fits are evaluated with numpy, not through scipy's ``PPoly.__call__`` (whose per-call
overhead dominated the solvers): the breakpoints are the uniform 25 K grid of :data:`T_GRID`, so
the interval is found by index arithmetic, and several polynomials stacked on a last axis (the
species of a mixture) share one interval search and one Horner evaluation
(:class:`PiecewisePolynomials`). The coefficients are scipy's, unchanged.

Reference state: :math:`h = 0` at 298.15 K for the *fixed* composition of the table (sensible
enthalpy; no reactions inside the table).

Start-up and caches: Cantera and scipy are imported only to compute a table or a flame, with
one GRI-Mech 3.0 solution per thread (loading one costs ~0.05 s; the state is always set in
full before use). Tables, burnt gases and the species list are kept in memory per input and
on disk (:mod:`rotarykiln.materials._cache`, keyed on everything they depend on), so a run
whose tables were computed before needs neither Cantera nor scipy's splines: the numbers read
back are the ones computed, to the last bit.

A new composition (the products of a new fuel flow in a sweep) costs little more than its
thermochemistry: the specific heat is sampled on a thermo-only Cantera phase of the
composition's species alone (:func:`_thermo_phase`, built once per species set and thread:
absent species add exact zeros to Cantera's sums, so the numbers are the full mechanism's to
the last bit), and the transport fits, which need GRI-Mech 3.0's mixture-averaged model (the
Wilke viscosity is most of a table's cost) and which a burner's products seldom need, are
computed on first use (:attr:`GasPropertyTable._k`, :attr:`GasPropertyTable._mu`), exactly as
before, and kept with the table and on disk.
"""

from __future__ import annotations

import bisect
import difflib
import hashlib
import math
import threading
from dataclasses import dataclass, field
from functools import cached_property, lru_cache

import numpy as np

from rotarykiln.errors import InputError, check_positive, warn_out_of_range
from rotarykiln.materials import _cache

__all__ = [
    "AIR",
    "AIR_MOLAR_MASS",
    "AIR_O2",
    "GasPropertyTable",
    "gas_table",
    "air_table",
    "parse_composition",
    "BurntGas",
    "burn_fuel",
    "check_composition",
    "fuel_data",
    "molar_mass",
]

#: Dry air by mole (the standard atmosphere's N2, O2 and Ar; CO2 and traces counted as N2):
#: the one air of the package, of the burner's air streams and of an air-heated kiln's gas.
AIR = "O2:0.2095, N2:0.7808, AR:0.0097"
#: O2 mole fraction of :data:`AIR`.
AIR_O2 = 0.2095
#: Molar mass of :data:`AIR`, kg/mol (O2 31.998, N2 28.0134, Ar 39.948 g/mol).
AIR_MOLAR_MASS = 0.2095 * 0.031998 + 0.7808 * 0.0280134 + 0.0097 * 0.039948

R_UNIVERSAL = 8.314462618  # J/(mol K)
T_REF = 298.15  # K
MECHANISM = "gri30.yaml"
T_MIN, T_MAX = 200.0, 3200.0
#: Temperatures (K) at which Cantera is sampled: the breakpoints of every fitted table.
T_GRID = np.concatenate([np.linspace(T_MIN, 1000.0, 33), np.linspace(1025.0, T_MAX, 88)])

_thread = threading.local()


def gri30():
    """This thread's Cantera solution of :data:`MECHANISM` (loaded once per thread).

    Callers set its state in full (``TPX``) before reading it; thermodynamic and transport
    properties and equilibria depend on the state only, so sharing it gives the same numbers
    as a fresh solution, without loading the mechanism again (~0.05 s).
    """
    gas = getattr(_thread, "gri30", None)
    if gas is None:
        import cantera as ct

        gas = _thread.gri30 = ct.Solution(MECHANISM)
    return gas


#: At most this many thermo-only phases (:func:`_thermo_phase`) are kept per thread.
THERMO_PHASES = 32


def _thermo_phase(species: tuple[str, ...], gas=None):
    """A thermo-only Cantera phase (ideal gas, no kinetics, no transport) of ``species``.

    ``species``: GRI-Mech 3.0 names in the mechanism's order; ``gas``: the GRI-Mech 3.0
    solution the species are taken from (default :func:`gri30`, and then the phase is kept for
    this thread, up to :data:`THERMO_PHASES` of them, the oldest dropped). Its state is always
    set in full (``TPX``) before use. Building one costs ~0.1 ms against ~0.05 s for the
    mechanism; sampling it costs a fraction of the mechanism's 53 species: its mixture
    properties are the mechanism's to the last bit, since the species left out hold exact zero
    mole fractions there (zero terms in Cantera's sums, in the same order).
    """
    import cantera as ct

    if gas is not None:
        return ct.Solution(thermo="ideal-gas", species=[gas.species(s) for s in species])
    phases = getattr(_thread, "thermo_phases", None)
    if phases is None:
        phases = _thread.thermo_phases = {}
    phase = phases.get(species)
    if phase is None:
        full = gri30()
        phase = ct.Solution(thermo="ideal-gas", species=[full.species(s) for s in species])
        if len(phases) >= THERMO_PHASES:
            del phases[next(iter(phases))]
        phases[species] = phase
    return phase


@lru_cache(maxsize=1)
def _grid_digest() -> str:
    """SHA-256 of :data:`T_GRID`'s bytes (for the disk-cache keys)."""
    return hashlib.sha256(T_GRID.tobytes()).hexdigest()


def _cache_key(kind: str, *inputs) -> str:
    """Disk-cache key of a result of this module: its inputs (exact reprs), the temperature
    grid and the environment (:func:`rotarykiln.materials._cache.environment_key`)."""
    grid = _grid_digest()
    env = _cache.environment_key(MECHANISM, ("gas.py",))
    return f"{kind};{inputs!r};T_GRID={grid};T_MIN={T_MIN!r};T_MAX={T_MAX!r};{env}"


def _clamp(T):
    """``T`` (K) clamped to [T_MIN, T_MAX], NaN kept (np.clip's overhead avoided)."""
    return np.minimum(np.maximum(T, T_MIN), T_MAX)


class PiecewisePolynomials:
    """Piecewise polynomials on shared breakpoints, evaluated with numpy (internal helper).

    ``x``: breakpoints (K, increasing); ``c``: coefficients in scipy's ``PPoly`` layout,
    shape ``(order + 1, len(x) - 1) + trailing`` (highest power first, local variable
    ``T - x[i]``); the trailing axes stack several polynomials (e.g. one per species).
    :meth:`interval` locates the pieces (the interval ``x[i] <= T < x[i+1]``, the last one
    closed, as ``PPoly``, to round-off); :meth:`evaluate` does Horner's rule on them. ``T`` must lie in
    ``[x[0], x[-1]]`` (the tables clamp it).

    Examples
    --------
    >>> from scipy.interpolate import CubicSpline
    >>> f = CubicSpline([0.0, 1.0, 2.0, 4.0], [0.0, 1.0, 4.0, 16.0])
    >>> p = PiecewisePolynomials(f.x, f.c)
    >>> i, s = p.interval(np.array([0.5, 3.0, 4.0]))
    >>> bool(np.allclose(p.evaluate(i, s), f([0.5, 3.0, 4.0]), rtol=1e-15))
    True
    """

    def __init__(self, x, c):
        x = np.asarray(x, dtype=float)
        c = np.asarray(c, dtype=float)
        self.x = x
        self.c = c
        self.order = c.shape[0] - 1
        self._last = len(x) - 2
        # one contiguous (pieces, ...) array per power: np.take gathers them fastest
        self._coef = [np.ascontiguousarray(c[p]) for p in range(c.shape[0])]
        step = (x[-1] - x[0]) / (len(x) - 1)
        uniform = np.array_equal(x, x[0] + step * np.arange(len(x)))
        self._step = step if uniform else None

    def interval(self, T):
        """Piece index ``i`` and local variable ``s = T - x[i]`` (K) of each ``T`` (K)."""
        T = np.asarray(T, dtype=float)
        if T.ndim == 0:
            i, s = self.interval(T.reshape(1))
            return i.reshape(()), s.reshape(())
        if self._step is None:
            i = np.searchsorted(self.x, T, side="right") - 1
            np.clip(i, 0, self._last, out=i)
        else:
            # uniform grid: index arithmetic (NaN to piece 0, where it stays NaN); a T within
            # round-off below a breakpoint may get the next piece, at s ~ -1e-13 K: the same
            # value to round-off (the pieces join with continuous derivatives)
            u = (T - self.x[0]) / self._step
            np.fmax(u, 0.0, out=u)
            np.minimum(u, self._last, out=u)
            i = u.astype(np.intp)
        return i, T - self.x[i]

    def evaluate(self, i, s):
        """Values at pieces ``i`` and local variables ``s`` (from :meth:`interval`), shape
        ``s.shape + trailing``."""
        coef = self._coef
        trailing = coef[0].ndim - 1
        s = s.reshape(s.shape + (1,) * trailing)
        out = coef[0].take(i, axis=0)
        for c in coef[1:]:
            out *= s
            out += c.take(i, axis=0)
        return out

    @cached_property
    def _floats(self) -> tuple[list[float], list[list[float]]]:
        """Breakpoints and coefficients as Python floats (for :meth:`value`)."""
        return self.x.tolist(), [c.tolist() for c in self._coef]

    def value(self, T: float) -> float:
        """The value at one temperature ``T`` (K, in ``[x[0], x[-1]]``) of a single polynomial
        (no trailing axes), as a float.

        The operations of :meth:`interval` and :meth:`evaluate`, one by one, in Python floats:
        the same number to the last bit, without numpy's overhead per call (a root finder
        calls it some fifty times).

        Examples
        --------
        >>> p = PiecewisePolynomials([0.0, 1.0, 2.0], [[1.0, 2.0], [0.0, 1.0]])
        >>> p.value(1.5) == float(p.evaluate(*p.interval(1.5)))
        True
        """
        x, coef = self._floats
        if self._step is None:
            i = min(max(bisect.bisect_right(x, T) - 1, 0), self._last)
        else:
            u = (T - x[0]) / self._step
            u = u if u > 0.0 else 0.0  # np.fmax(u, 0.0)
            i = int(min(u, self._last))
        s = T - x[i]
        out = coef[0][i]
        for c in coef[1:]:
            out = out * s + c[i]
        return out


def parse_composition(composition) -> tuple[tuple[str, float], ...]:
    """Normalised mole fractions as a sorted tuple of ``(species, x)`` pairs.

    Accepts ``"O2:0.21, N2:0.79"`` or a mapping (or its items). A text or a tuple of pairs is
    parsed once and kept (a kiln's set-up asks for its gases' compositions a dozen times).

    Examples
    --------
    >>> parse_composition("N2:79, O2:21")
    (('N2', 0.79), ('O2', 0.21))
    """
    if isinstance(composition, (str, tuple)):
        try:
            return _parse_kept(composition)
        except TypeError:  # a tuple holding something unhashable
            pass
    return _parse_composition(composition)


@lru_cache(maxsize=1024)
def _parse_kept(composition) -> tuple[tuple[str, float], ...]:
    return _parse_composition(composition)


def _parse_composition(composition) -> tuple[tuple[str, float], ...]:
    if isinstance(composition, str):
        items = {}
        for part in composition.split(","):
            part = part.strip()
            if not part:
                continue
            try:
                name, value = part.split(":")
                items[name.strip()] = float(value)
            except ValueError as exc:
                raise InputError(
                    "gas.composition", composition, "of the form 'N2:0.79, O2:0.21'"
                ) from exc
    else:
        items = {str(k): float(v) for k, v in dict(composition).items()}
    total = sum(items.values())
    if not items or total <= 0 or any(v < 0 for v in items.values()):
        raise InputError("gas.composition", composition, "a set of non-negative mole fractions")
    return tuple(sorted((k, round(v / total, 12)) for k, v in items.items() if v > 0))


@dataclass(frozen=True)
class GasPropertyTable:
    """Fitted property table of a gas mixture of fixed composition (SI units).

    Build it with :func:`gas_table` (cached per composition). Attributes: ``composition``
    (mole fractions), ``molar_mass`` (kg/mol), ``x_co2``, ``x_h2o`` (mole fractions used by the
    gas radiation models), and the fitted splines (:class:`PiecewisePolynomials` with scipy's
    ``CubicSpline`` coefficients ``c`` on the breakpoints ``x``). Valid 200-3200 K (the sampled range);
    outside it cp, conductivity and viscosity are clamped to the end values and the enthalpy is
    extended linearly, without a warning in the hot loop: call :meth:`check_range` once on a
    converged state to be warned.

    The transport fits (conductivity, viscosity) are the ``_transport`` pair when given, else
    computed from ``composition`` on first use (Cantera's mixture-averaged transport, kept with
    the table and on disk): the same numbers whenever they are computed.
    """

    composition: tuple[tuple[str, float], ...]
    molar_mass: float
    x_co2: float
    x_h2o: float
    _cp: PiecewisePolynomials = field(repr=False)
    _h: PiecewisePolynomials = field(repr=False)
    _transport: tuple[PiecewisePolynomials, PiecewisePolynomials] | None = field(
        default=None, repr=False, compare=False
    )

    @cached_property
    def _transport_fits(self) -> tuple[PiecewisePolynomials, PiecewisePolynomials]:
        """Conductivity (W/(m K)) and viscosity (Pa s) fits: given, or computed once."""
        if self._transport is not None:
            return self._transport
        return _transport_fits(self.composition)

    @property
    def _k(self) -> PiecewisePolynomials:
        """Conductivity fit, W/(m K) (computed on first use)."""
        return self._transport_fits[0]

    @property
    def _mu(self) -> PiecewisePolynomials:
        """Viscosity fit, Pa s (computed on first use)."""
        return self._transport_fits[1]

    @property
    def _fits(self):
        """cp, h, k, mu as :class:`PiecewisePolynomials` (numpy evaluation of the splines)."""
        return (self._cp, self._h, self._k, self._mu)

    @cached_property
    def _cp_ends(self) -> tuple[float, float]:
        """cp (J/(kg K)) at T_MIN and T_MAX: the slopes of the enthalpy's linear extensions."""
        cp = self._cp
        lo, hi = cp.evaluate(*cp.interval(np.array([T_MIN, T_MAX])))
        return float(lo), float(hi)

    def _eval(self, which: int, T):
        fit = self._cp if which == 0 else self._h if which == 1 else self._fits[which]
        return fit.evaluate(*fit.interval(_clamp(T)))

    def check_range(self, T) -> bool:
        """Warn once if any ``T`` (K) lies outside the fitted 200-3200 K (values clamped there).

        Returns True when an :class:`~rotarykiln.errors.OutOfRangeWarning` was issued; it
        shows the span outside the range. Not called by the property methods (solver loops).

        Examples
        --------
        >>> import warnings
        >>> with warnings.catch_warnings():
        ...     warnings.simplefilter("error")
        ...     air_table().check_range([300.0, 1500.0])
        False
        """
        return warn_out_of_range(
            "gas temperature [K]",
            T,
            T_MIN,
            T_MAX,
            f"the Cantera property table ({MECHANISM}; clamped outside)",
        )

    def cp(self, T):
        """Specific heat at constant pressure, J/(kg K), at temperature ``T`` (K)."""
        return self._eval(0, T)

    def enthalpy(self, T):
        """Sensible enthalpy relative to 298.15 K, J/kg (exact integral of :meth:`cp`)."""
        T = np.asarray(T, dtype=float)
        # linear extension outside the table keeps h monotone and consistent with cp
        cp_lo, cp_hi = self._cp_ends
        return (
            self._eval(1, T)
            + cp_lo * np.minimum(T - T_MIN, 0.0)
            + cp_hi * np.maximum(T - T_MAX, 0.0)
        )

    def _enthalpy_at(self, T: float) -> float:
        """:meth:`enthalpy` at one temperature ``T`` (K), as a float: the same number to the
        last bit, ~10 times faster (for root finding)."""
        cp_lo, cp_hi = self._cp_ends
        t = min(max(T, T_MIN), T_MAX)  # _clamp
        return self._h.value(t) + cp_lo * min(T - T_MIN, 0.0) + cp_hi * max(T - T_MAX, 0.0)

    def conductivity(self, T):
        """Thermal conductivity, W/(m K)."""
        return self._eval(2, T)

    def viscosity(self, T):
        """Dynamic viscosity, Pa s."""
        return self._eval(3, T)

    @cached_property
    def _shared_breakpoints(self) -> bool:
        """Whether the cp, conductivity and viscosity fits share their breakpoints."""
        x = self._cp.x
        return all(np.array_equal(f.x, x) for f in (self._k, self._mu))

    def cp_conductivity_viscosity(self, T):
        """:meth:`cp` (J/(kg K)), :meth:`conductivity` (W/(m K)) and :meth:`viscosity` (Pa s)
        at ``T`` (K), the pieces located once (the same numbers as the three calls).

        Examples
        --------
        >>> air = air_table()
        >>> T = np.array([300.0, 900.0])
        >>> cp, k, mu = air.cp_conductivity_viscosity(T)
        >>> all(np.array_equal(a, b) for a, b in zip((cp, k, mu), (air.cp(T),
        ...     air.conductivity(T), air.viscosity(T))))
        True
        """
        if not self._shared_breakpoints:
            return self.cp(T), self.conductivity(T), self.viscosity(T)
        piece = self._cp.interval(_clamp(T))
        return tuple(f.evaluate(*piece) for f in (self._cp, self._k, self._mu))

    def density(self, T, pressure=101325.0):
        """Ideal-gas density, kg/m3, at ``T`` (K) and ``pressure`` (Pa)."""
        return pressure * self.molar_mass / (R_UNIVERSAL * np.asarray(T, dtype=float))

    def prandtl(self, T):
        """Prandtl number, -."""
        return self.cp(T) * self.viscosity(T) / self.conductivity(T)


def _species_of(composition, gas) -> tuple[str, ...]:
    """The species of ``composition`` in the order of ``gas`` (GRI-Mech 3.0); an unknown one
    is refused (:class:`~rotarykiln.errors.InputError`)."""
    names = gas.species_names
    unknown = [s for s, _ in composition if s not in names]
    if unknown:
        raise InputError("gas.composition", ",".join(unknown), f"a species of {MECHANISM}")
    return tuple(sorted((s for s, _ in composition), key=names.index))


def _thermo_arrays(composition: tuple[tuple[str, float], ...], gas=None) -> dict:
    """The thermodynamic arrays of a :class:`GasPropertyTable`: molar mass (kg/mol), CO2 and
    H2O mole fractions, and the cp (J/(kg K)) and h (J/kg) splines (``x``, ``c``).

    Cantera's cp of the composition sampled on :data:`T_GRID` (on :func:`_thermo_phase` of its
    species: GRI-Mech 3.0's numbers to the last bit), fitted by scipy's ``CubicSpline``, the
    enthalpy its antiderivative shifted to 0 at :data:`T_REF`. ``gas``: the GRI-Mech 3.0
    solution the species come from (default :func:`gri30`).
    """
    from scipy.interpolate import CubicSpline

    full = gri30() if gas is None else gas
    phase = _thermo_phase(_species_of(composition, full), gas)
    X = dict(composition)
    temps = T_GRID
    cp = np.empty_like(temps)
    phase.TPX = temps[0], 101325.0, X  # then the temperature alone: the same states
    for i, T in enumerate(temps):
        phase.TP = T, 101325.0
        cp[i] = phase.cp_mass
    cp_fit = CubicSpline(temps, cp)
    h_fit = cp_fit.antiderivative()
    offset = float(h_fit(T_REF))
    h_fit.c[-1, :] -= offset  # h(T_REF) = 0; PPoly is piecewise: shift every piece
    phase.TPX = 300.0, 101325.0, X
    x = dict(zip(phase.species_names, phase.X, strict=True))
    return {
        "molar_mass": np.float64(phase.mean_molecular_weight / 1000.0),
        "x_co2": np.float64(x.get("CO2", 0.0)),
        "x_h2o": np.float64(x.get("H2O", 0.0)),
        **{f"{n}_x": f.x for n, f in (("cp", cp_fit), ("h", h_fit))},
        **{f"{n}_c": f.c for n, f in (("cp", cp_fit), ("h", h_fit))},
    }


def _transport_arrays(composition: tuple[tuple[str, float], ...], gas=None) -> dict:
    """The transport arrays of a :class:`GasPropertyTable`: the conductivity (W/(m K)) and
    viscosity (Pa s) splines (``x``, ``c``): Cantera's mixture-averaged values (GRI-Mech 3.0,
    ``gas``, default :func:`gri30`) on :data:`T_GRID`, fitted by scipy's ``CubicSpline``.

    The composition is set once and the temperature alone changed after (the same state, so
    the same numbers as setting it in full at every temperature).
    """
    from scipy.interpolate import CubicSpline

    gas = gri30() if gas is None else gas
    _species_of(composition, gas)
    temps = T_GRID
    k = np.empty_like(temps)
    mu = np.empty_like(temps)
    gas.TPX = temps[0], 101325.0, dict(composition)
    for i, T in enumerate(temps):
        gas.TP = T, 101325.0
        k[i] = gas.thermal_conductivity
        mu[i] = gas.viscosity
    k_fit, mu_fit = CubicSpline(temps, k), CubicSpline(temps, mu)
    return {
        **{f"{n}_x": f.x for n, f in (("k", k_fit), ("mu", mu_fit))},
        **{f"{n}_c": f.c for n, f in (("k", k_fit), ("mu", mu_fit))},
    }


def _table_arrays(composition: tuple[tuple[str, float], ...], gas=None) -> dict:
    """Cantera sampled on :data:`T_GRID` and fitted (scipy's ``CubicSpline``): every array of
    a :class:`GasPropertyTable` (:func:`_thermo_arrays` and :func:`_transport_arrays`;
    ``gas``: a GRI-Mech 3.0 solution, default :func:`gri30`)."""
    return {**_thermo_arrays(composition, gas), **_transport_arrays(composition, gas)}


def _fit_pair(a: dict, name: str) -> PiecewisePolynomials:
    """The fit ``name`` (``cp``, ``h``, ``k``, ``mu``) of the arrays ``a``: breakpoints
    ``<name>_x`` (K) and coefficients ``<name>_c``."""
    return PiecewisePolynomials(a[f"{name}_x"], a[f"{name}_c"])


def _table_from_arrays(composition, a: dict) -> GasPropertyTable:
    """The table of arrays ``a`` (:func:`_thermo_arrays`, with or without the transport ones:
    computed on first use when absent)."""
    transport = (_fit_pair(a, "k"), _fit_pair(a, "mu")) if "k_c" in a else None
    return GasPropertyTable(
        composition=composition,
        molar_mass=float(a["molar_mass"]),
        x_co2=float(a["x_co2"]),
        x_h2o=float(a["x_h2o"]),
        _cp=_fit_pair(a, "cp"),
        _h=_fit_pair(a, "h"),
        _transport=transport,
    )


@lru_cache(maxsize=256)
def _cantera_table(composition: tuple[tuple[str, float], ...]) -> GasPropertyTable:
    key = _cache_key("thermo", composition)
    arrays = _cache.load("table", key)
    if arrays is None:
        arrays = _thermo_arrays(composition)
        _cache.store("table", key, arrays)
    return _table_from_arrays(composition, arrays)


def _transport_fits(composition) -> tuple[PiecewisePolynomials, PiecewisePolynomials]:
    """Conductivity and viscosity fits of ``composition`` (from the disk cache, else computed:
    :func:`_transport_arrays`); kept in memory by the table that asks
    (:attr:`GasPropertyTable._transport_fits`)."""
    key = _cache_key("transport", composition)
    arrays = _cache.load("transport", key)
    if arrays is None:
        arrays = _transport_arrays(composition)
        _cache.store("transport", key, arrays)
    return _fit_pair(arrays, "k"), _fit_pair(arrays, "mu")


def gas_table(composition) -> GasPropertyTable:
    """Fitted property table for a gas of given composition (Cantera, GRI-Mech 3.0 species).

    Parameters
    ----------
    composition : str or mapping
        Mole fractions, e.g. ``"O2:0.21, N2:0.79"``; normalised.

    Returns
    -------
    GasPropertyTable

    Examples
    --------
    >>> air = gas_table("O2:0.21, N2:0.79")
    >>> round(float(air.cp(1000.0)), 0)
    1151.0
    >>> abs(round(float(air.enthalpy(298.15)), 6))
    0.0

    References
    ----------
    D.G. Goodwin et al., Cantera 3 (https://cantera.org); GRI-Mech 3.0 thermo and transport.
    """
    return _cantera_table(parse_composition(composition))


def air_table() -> GasPropertyTable:
    """Property table of dry air (:data:`AIR`)."""
    return gas_table(AIR)


@dataclass(frozen=True)
class BurntGas:
    """Products of a fuel burnt completely with air (water as vapour).

    Attributes: ``composition`` (mole fractions of the products, from a Cantera equilibrium at
    1200 K, i.e. complete combustion without dissociation), ``mass_flow`` (kg/s),
    ``inlet_temperature`` (K, of the unburnt mixture), ``heat_release`` (W, the heat of
    combustion at the inlet temperature, lower heating value basis), ``adiabatic_temperature``
    (K, of the frozen products; above the dissociating equilibrium value by a few tens of K),
    ``table`` (fitted properties of the products). By construction
    ``mass_flow * (table.enthalpy(T_ad) - table.enthalpy(T_in)) == heat_release``.
    """

    composition: tuple[tuple[str, float], ...]
    mass_flow: float
    inlet_temperature: float
    adiabatic_temperature: float
    heat_release: float
    table: GasPropertyTable


def burn_fuel(
    fuel,
    fuel_flow: float,
    air_flow: float,
    fuel_temperature=298.15,
    air_temperature=298.15,
    air=AIR,
) -> BurntGas:
    """Burn ``fuel`` completely with air (Cantera, GRI-Mech 3.0 thermochemistry), 1 atm.

    Parameters
    ----------
    fuel : str or mapping
        Fuel composition by mole, e.g. ``"CH4:0.95, C2H6:0.03, N2:0.02"`` (natural gas).
    fuel_flow, air_flow : float, kg/s
        Mass flows of fuel and combustion air.
    fuel_temperature, air_temperature : float, K
    air : str
        The oxidiser's composition by mole (default :data:`AIR`; O2-enriched air, O2, ...).

    Returns
    -------
    BurntGas
        The products (frozen at their equilibrium composition) and the heat release.

    Examples
    --------
    >>> b = burn_fuel("CH4:1", 1.0e-3, 1.0e-3 * 17.2 * 1.1)
    >>> round(b.heat_release / 1.0e-3 / 1e6, 1)  # MJ per kg of CH4: the LHV
    50.0
    >>> round(b.adiabatic_temperature, -1)
    2190.0

    References
    ----------
    D.G. Goodwin et al., Cantera 3 (https://cantera.org): equilibrium of the fuel-air mixture;
    GRI-Mech 3.0 thermo.
    """
    check_positive("gas.fuel_flow", fuel_flow, "kg/s")
    check_positive("gas.air_flow", air_flow, "kg/s")
    comp, t_in, t_ad, q = _burn(
        parse_composition(fuel),
        float(fuel_flow),
        float(air_flow),
        float(fuel_temperature),
        float(air_temperature),
        *(() if air == AIR else (parse_composition(air),)),
    )
    return BurntGas(comp, fuel_flow + air_flow, t_in, t_ad, q, gas_table(comp))


@lru_cache(maxsize=1024)
def _burn(fuel, fuel_flow, air_flow, fuel_temperature, air_temperature, *air):
    """Products, inlet and adiabatic temperatures (K) and heat release (W) of
    :func:`burn_fuel`: in memory, else on disk, else computed (:func:`_burn_state`).
    ``air``: the oxidiser's (species, mole fraction) pairs when it is not :data:`AIR`."""
    key = _cache_key("burn", fuel, fuel_flow, air_flow, fuel_temperature, air_temperature, *air)
    a = _cache.load("burn", key)
    if a is None:
        comp, t_in, t_ad, q = _burn_state(
            fuel,
            fuel_flow,
            air_flow,
            fuel_temperature,
            air_temperature,
            air=dict(air[0]) if air else AIR,
        )
        a = {
            "species": np.array([k for k, _ in comp]),
            "x": np.array([x for _, x in comp], dtype=float),
            "values": np.array([t_in, t_ad, q], dtype=float),
        }
        _cache.store("burn", key, a)
    comp = tuple((str(k), float(x)) for k, x in zip(a["species"], a["x"], strict=True))
    t_in, t_ad, q = (float(v) for v in a["values"])
    return comp, t_in, t_ad, q


def _burn_state(fuel, fuel_flow, air_flow, fuel_temperature, air_temperature, gas=None, air=AIR):
    """Cantera's part of :func:`burn_fuel` (``gas``: a GRI-Mech 3.0 solution, default
    :func:`gri30`; ``air``: the oxidiser by mole): the products' composition, ``t_in``,
    ``t_ad`` (K) and heat release (W)."""
    import cantera as ct
    from scipy.optimize import brentq

    gas = gri30() if gas is None else gas
    fuel_x = dict(fuel)
    # constant="HP": streams mixing at constant pressure and enthalpy (Cantera's default, UV,
    # is a rigid vessel: wrong by ~15 K for air preheated to 1100 K). A Quantity keeps its own
    # state: both streams can share one solution.
    gas.TPX = fuel_temperature, 101325.0, fuel_x
    qf = ct.Quantity(gas, mass=fuel_flow, constant="HP")
    gas.TPX = air_temperature, 101325.0, air
    qa = ct.Quantity(gas, mass=air_flow, constant="HP")
    mix = qf + qa
    t_in = float(mix.T)
    h_reactants = float(mix.enthalpy_mass)
    # products: equilibrium at 1200 K (complete combustion, no dissociation), frozen after
    mix.TP = 1200.0, 101325.0
    mix.equilibrate("TP")
    x = {s: float(v) for s, v in zip(mix.species_names, mix.X, strict=True) if v > 1e-7}
    mix.TP = t_in, 101325.0
    h_products = float(mix.enthalpy_mass)
    comp = parse_composition(x)
    table = gas_table(comp)
    # table._enthalpy_at(t) is float(table.enthalpy(t)) to the last bit, without numpy's
    # overhead per call (the root finding calls it some fifty times): the same root
    enthalpy = table._enthalpy_at
    m = fuel_flow + air_flow
    q = m * (h_reactants - h_products)
    target = enthalpy(t_in) + q / m
    # bracket from T_MIN, not t_in: a very lean mixture releases a hair less than nothing
    # (equilibrium NO at 1200 K is endothermic) and its products sit just below t_in
    lo, hi = T_MIN, 2 * T_MAX
    if enthalpy(lo) > target or enthalpy(hi) < target:
        raise InputError(
            "air_flow",
            f"{air_flow:.6g} kg/s",
            f"enough to burn {fuel_flow:.6g} kg/s of fuel (air/fuel mass ratio "
            f"{air_flow / fuel_flow:.4g}: the products would leave outside [{lo:g}, {hi:g}] K)",
        )
    t_ad = float(brentq(lambda t: enthalpy(t) - target, lo, hi))
    return comp, t_in, t_ad, q


# --------------------------------------------------------------------------------------------
# Checked fuel and gas compositions (issue 10): every species a GRI-Mech 3.0 species, every
# fraction finite and >= 0, the fractions summing to 1.

COMPOSITION_TOLERANCE = 1e-3
"""How far from 1 the mole fractions given to :func:`check_composition` may sum."""

_COMPOSITION_FORM = 'mole fractions summing to 1 as "CH4:0.95, C2H6:0.03, N2:0.01, CO2:0.01"'


@lru_cache(maxsize=1)
def _gri30_species() -> dict[str, tuple[str, float]]:
    """GRI-Mech 3.0 species: lower-case name -> (gri30 spelling, molar mass in kg/mol).

    Read from the disk cache, else from Cantera (loaded once per process: a few tenths of a
    second).
    """
    key = _cache_key("species")
    a = _cache.load("species", key)
    if a is None:
        gas = gri30()
        a = {
            "names": np.array(gas.species_names),
            "molar_mass": np.array([float(w) / 1000.0 for w in gas.molecular_weights]),
        }
        _cache.store("species", key, a)
    return {
        str(name).lower(): (str(name), float(w))
        for name, w in zip(a["names"], a["molar_mass"], strict=True)
    }


H2O_VAPORISATION = 44.004e3
"""Enthalpy of vaporisation of water at 298.15 K, J/mol (the HHV - LHV gap per mol of H2O)."""


@lru_cache(maxsize=64)
def fuel_data(fuel) -> tuple[float, float, float, float]:
    """Molar mass (kg/mol), O2 demand (mol/mol), LHV and HHV (J/kg) of a fuel at 298.15 K.

    Complete combustion to CO2 and H2O (vapour for the LHV; liquid for the HHV, with
    :data:`H2O_VAPORISATION`), GRI-Mech 3.0 thermochemistry (Cantera). Kept in memory and on
    disk per fuel (:func:`parse_composition` form); computed as ``kiln.flame`` did.

    Examples
    --------
    >>> mm, o2, lhv, hhv = fuel_data(parse_composition("CH4:1"))
    >>> round(mm * 1e3, 3), o2, round(lhv / 1e6, 2), round(hhv / 1e6, 2)
    (16.043, 2.0, 50.03, 55.51)
    """
    fuel = parse_composition(fuel) if not isinstance(fuel, tuple) else fuel
    key = _cache_key("fuel", fuel, H2O_VAPORISATION)
    a = _cache.load("fuel", key)
    if a is None:
        a = {"values": np.array(_fuel_state(fuel), dtype=float)}
        _cache.store("fuel", key, a)
    mm, o2, lhv, hhv = (float(v) for v in a["values"])
    return mm, o2, lhv, hhv


def _fuel_state(fuel, gas=None) -> tuple[float, float, float, float]:
    """Cantera's part of :func:`fuel_data` (``gas``: a GRI-Mech 3.0 solution, default
    :func:`gri30`)."""
    gas = gri30() if gas is None else gas
    x = dict(fuel)
    gas.TPX = T_REF, 101325.0, x
    mm = gas.mean_molecular_weight / 1000.0
    o2 = 0.0
    c = h = 0.0
    for name, xi in x.items():
        k = gas.species_index(name)
        nc = gas.n_atoms(k, "C") if "C" in gas.element_names else 0.0
        nh = gas.n_atoms(k, "H")
        no = gas.n_atoms(k, "O")
        o2 += xi * (nc + nh / 4.0 - no / 2.0)
        c += xi * nc
        h += xi * nh
    h_fuel = gas.enthalpy_mole  # J/kmol
    n_o2 = gas.n_atoms(gas.species_index("O2"), "O") / 2.0  # 1
    comp = {"CO2": c, "H2O": h / 2.0}
    for name, xi in x.items():
        if name in ("N2", "AR", "Ar", "HE"):
            comp[name] = comp.get(name, 0.0) + xi
    total = sum(comp.values())
    gas.TPX = T_REF, 101325.0, {k: v / total for k, v in comp.items() if v > 0}
    h_prod = gas.enthalpy_mole * total
    gas.TPX = T_REF, 101325.0, "O2:1"
    h_react = h_fuel + o2 * gas.enthalpy_mole * n_o2
    lhv = (h_react - h_prod) / 1000.0 / mm  # J/kg of fuel
    hhv = lhv + (h / 2.0) * H2O_VAPORISATION / mm
    return mm, o2, lhv, hhv


def _composition_items(composition, field: str) -> list[tuple[str, object]]:
    shown = f'"{composition}"' if isinstance(composition, str) else repr(composition)
    if isinstance(composition, str):
        items = []
        for part in composition.split(","):
            if not part.strip():
                continue
            if part.count(":") != 1:
                raise InputError(
                    field,
                    composition,
                    message=f'{field}: {shown} has "{part.strip()}", not "species:fraction"; '
                    f"expected {_COMPOSITION_FORM}",
                )
            name, value = part.split(":")
            items.append((name.strip(), value.strip()))
        return items
    try:
        pairs = composition.items() if hasattr(composition, "items") else composition
        return [(str(name).strip(), value) for name, value in pairs]
    except (TypeError, ValueError):
        raise InputError(
            field,
            composition,
            message=f"{field}: {shown} is not a composition; expected {_COMPOSITION_FORM}",
        ) from None


def check_composition(text, field: str) -> tuple[tuple[str, float], ...]:
    """Check a gas or fuel composition and return it normalised, in GRI-Mech 3.0 spelling.

    Species are matched to the GRI-Mech 3.0 (``gri30.yaml``) names ignoring case (``"Ar"`` ->
    ``"AR"``, ``"ch4"`` -> ``"CH4"``). Refused with :class:`~rotarykiln.errors.InputError`, on
    one line naming ``field``, the value and what is accepted: an empty composition, a part
    that is not ``species:fraction``, an unknown or repeated species, a fraction that is not a
    finite number >= 0, and fractions that do not sum to 1 within 1e-3.

    Parameters
    ----------
    text : str
        Mole fractions, e.g. ``"CH4:0.95, C2H6:0.03, N2:0.01, CO2:0.01"``; a mapping or a
        sequence of ``(species, fraction)`` pairs is also accepted.
    field : str
        Dotted path of the field (``"burner.fuel"``), named in error messages.

    Returns
    -------
    tuple of (str, float)
        ``(gri30 name, mole fraction)`` pairs sorted by name, fractions [-] divided by their
        sum, zero fractions dropped (the form :func:`parse_composition` returns).

    Examples
    --------
    >>> check_composition("CH4:0.95, C2H6:0.03, N2:0.01, co2:0.01", "burner.fuel")
    (('C2H6', 0.03), ('CH4', 0.95), ('CO2', 0.01), ('N2', 0.01))
    >>> check_composition("CH4:0.95, C2H6:0.03", "burner.fuel")
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: burner.fuel: "CH4:0.95, C2H6:0.03" has mole fractions summing to 0.98, expected 1 (within 0.001)

    References
    ----------
    G.P. Smith et al., GRI-Mech 3.0 (http://combustion.berkeley.edu/gri-mech/), as shipped
    with Cantera (https://cantera.org).
    """
    shown = f'"{text}"' if isinstance(text, str) else repr(text)
    items = _composition_items(text, field)
    if not items:
        raise InputError(
            field, text, message=f"{field}: {shown} is empty; expected {_COMPOSITION_FORM}"
        )
    species = _gri30_species()
    unknown = [name for name, _ in items if name.lower() not in species]
    if unknown:
        hints = []
        for name in unknown:
            close = difflib.get_close_matches(name.upper(), [s for s, _ in species.values()], 1)
            hints.append(f'"{name}"' + (f' (did you mean "{close[0]}"?)' if close else ""))
        raise InputError(
            field,
            text,
            message=f"{field}: {shown} has unknown species {', '.join(hints)}; expected species "
            f"of {MECHANISM} (case ignored), e.g. CH4, C2H6, C3H8, H2, CO, CO2, H2O, N2, O2, AR",
        )
    fractions: dict[str, float] = {}
    for name, value in items:
        gri = species[name.lower()][0]
        if gri in fractions:
            raise InputError(
                field, text, message=f"{field}: {shown} gives {gri} twice; give each species once"
            )
        try:
            if isinstance(value, bool):
                raise TypeError
            x = float(value)
        except (TypeError, ValueError):
            raise InputError(
                field,
                text,
                message=f'{field}: {shown}: the fraction "{value}" of {gri} is not a number; '
                f"expected {_COMPOSITION_FORM}",
            ) from None
        if not math.isfinite(x) or x < 0:
            raise InputError(
                field,
                text,
                message=f"{field}: {shown}: the fraction {x:g} of {gri} is not a finite number "
                f">= 0; expected {_COMPOSITION_FORM}",
            )
        fractions[gri] = x
    total = math.fsum(fractions.values())
    if abs(total - 1.0) > COMPOSITION_TOLERANCE:
        hint = " (percentages? divide them by 100)" if abs(total - 100.0) <= 0.1 else ""
        raise InputError(
            field,
            text,
            message=f"{field}: {shown} has mole fractions summing to {total:.6g}, expected 1 "
            f"(within {COMPOSITION_TOLERANCE:g}){hint}",
        )
    return parse_composition(fractions)


def molar_mass(composition) -> float:
    """Molar mass of a mixture of GRI-Mech 3.0 species, :math:`M = \\sum_i x_i M_i`.

    The composition is checked by :func:`check_composition` (field ``"composition"``); the
    species molar masses :math:`M_i` are Cantera's, from the elements of ``gri30.yaml``.

    Parameters
    ----------
    composition : str or mapping
        Mole fractions [-] summing to 1, e.g. ``"CH4:0.95, C2H6:0.03, N2:0.01, CO2:0.01"``,
        or the tuple :func:`check_composition` returns.

    Returns
    -------
    float, kg/mol
        Mean molar mass of the mixture.

    Examples
    --------
    >>> round(molar_mass("CH4:1") * 1e3, 3)  # g/mol
    16.043
    >>> round(molar_mass("O2:0.2095, N2:0.7808, Ar:0.0097"), 5)  # dry air, kg/mol
    0.02896

    References
    ----------
    G.P. Smith et al., GRI-Mech 3.0 (http://combustion.berkeley.edu/gri-mech/); molar masses
    from Cantera (https://cantera.org).
    """
    species = _gri30_species()
    pairs = check_composition(composition, "composition")
    return math.fsum(x * species[name.lower()][1] for name, x in pairs)
