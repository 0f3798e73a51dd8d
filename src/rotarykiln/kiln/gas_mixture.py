r"""Freeboard gas of changing composition: properties mixed from per-species fitted tables.

Cantera is called once per pure species (:func:`rotarykiln.materials.gas.gas_table`, cached);
inside the Newton loop the mixture properties are mixed from those fitted splines by the local
composition, never by calling Cantera:

.. math::
    h = \sum_k y_k h_k(T),\qquad c_p = \sum_k y_k c_{p,k}(T),\qquad
    k = \sum_k x_k k_k(T),\qquad
    \mu = \frac{\sum_k x_k \mu_k(T)\sqrt{M_k}}{\sum_k x_k\sqrt{M_k}}

(ideal-gas mixing for h and c_p, exact; mole-fraction average for the conductivity and the
Herning-Zipperer rule for the viscosity, both within ~10 % of Cantera's mixture-averaged values
for flue gases). Species without a Cantera entry (the lumped ``volatiles``) carry their mean c_p
from ``chemistry/species.yaml`` and are left out of the transport mixing.

With a burner whose products dissociate (``burner.products: equilibrium``), the CO2 and H2O
of the gas also carry the products' dissociation heat per kg of CO2 + H2O
(:class:`~rotarykiln.materials.dissociation.DissociationHeat`): the gas enthalpy is then the
equilibrium one, exactly as before below about 1500 K.

A species whose :math:`c_p(T)` is given as NASA-7, Shomate or polynomial
(:mod:`rotarykiln.chemistry.thermo`; the tar and pyrolysis gas of wood pyrolysis, or a user
species) and has no Cantera table gets its own pieces on the table breakpoints
(:func:`fit_pieces`): on every interval of :data:`~rotarykiln.materials.gas.T_GRID` its
:math:`c_p` is fitted by a cubic (least squares on 9 points: the fits are exact for polynomials
up to the cubic and within 1e-6 relative for NASA-7 and Shomate forms) and its enthalpy is the
integral of that cubic from the exact value at the interval's left end, so :math:`h` and
:math:`c_p` stay consistent (:class:`ThermoGasMixture`). Such species take no part in the
transport mixing either. :func:`mixture_of` picks the model of a list of species: the plain
:class:`GasMixture` when no species needs its own pieces.

For speed the species fits (all on the breakpoints of
:data:`~rotarykiln.materials.gas.T_GRID`) are stacked on a last axis: one interval search and
one Horner evaluation give every species at once (the constant-c_p species are stacked as
polynomials too, c_p constant and h linear).

References
----------
F. Herning, L. Zipperer, Gas- und Wasserfach 79 (1936) 49-54, 69-73 (viscosity of gas
mixtures); B.E. Poling, J.M. Prausnitz, J.P. O'Connell, The Properties of Gases and Liquids,
5th ed., McGraw-Hill (2001), ch. 9-10 (mixing rules of viscosity and conductivity).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from functools import cached_property, lru_cache

import numpy as np

from rotarykiln.chemistry.species import SpeciesTable, default_species
from rotarykiln.materials.gas import (
    R_UNIVERSAL,
    T_GRID,
    T_MAX,
    T_MIN,
    T_REF,
    PiecewisePolynomials,
    gas_table,
)

__all__ = [
    "CaseMixtures",
    "GasMixture",
    "ThermoGasMixture",
    "MixtureGas",
    "CANTERA_NAMES",
    "mixture_of",
    "temperature_of_enthalpy",
    "fit_pieces",
]

#: Species of the chemistry table -> GRI-Mech 3.0 name (None: no Cantera entry).
CANTERA_NAMES = {
    "N2": "N2",
    "O2": "O2",
    "CO2": "CO2",
    "H2O": "H2O",
    "CO": "CO",
    "H2": "H2",
    "CH4": "CH4",
    "AR": "AR",
    "volatiles": None,
}


def fit_pieces(thermo, x=None):
    """Cubic c_p and quartic h pieces (scipy PPoly layout, highest power first) of ``thermo``
    on the breakpoints ``x`` (K, default :data:`~rotarykiln.materials.gas.T_GRID`, cached):
    shapes (4, m) and (5, m).

    Examples
    --------
    >>> from rotarykiln.chemistry.thermo import thermo_from_dict
    >>> th = thermo_from_dict("t", {"polynomial": {"T_range": [250, 1500],
    ...     "coefficients": [-100.0, 4.4, -1.57e-3]}}, 0.1)
    >>> cp, h = fit_pieces(th)
    >>> p = PiecewisePolynomials(T_GRID, h)
    >>> bool(abs(p.evaluate(*p.interval(np.array([700.0])))[0] - th.enthalpy(700.0)) < 1e-6)
    True
    """
    if x is None:
        if hasattr(thermo, "grid_pieces"):  # already cubic pieces on T_GRID (dissociation)
            return thermo.grid_pieces()
        return _fit_on_grid(thermo)
    x = np.asarray(x, dtype=float)
    m = len(x) - 1
    cp = np.zeros((4, m))
    h = np.zeros((5, m))
    u = np.linspace(0.0, 1.0, 9)
    for i in range(m):
        w = x[i + 1] - x[i]
        s = u * w
        c = np.polyfit(s, thermo.cp(x[i] + s), 3)  # highest power first
        cp[:, i] = c
        h[:4, i] = c / np.array([4.0, 3.0, 2.0, 1.0])
        h[4, i] = thermo.enthalpy(x[i])
    return cp, h


@lru_cache(maxsize=64)
def _fit_on_grid(thermo):
    return fit_pieces(thermo, T_GRID)


#: Tables of fixed gas compositions a mixture keeps (GasMixture.transport_tables and its
#: kind): more are made anew (a study's cases each have theirs; a solve asks for one).
FIXED_TABLES_KEPT = 64


@dataclass(frozen=True)
class GasMixture:
    """Property model of a gas made of ``names`` (chemistry gas species), mixed by composition.

    Attributes: ``names`` (tuple), ``molar_mass`` (kg/mol per species, array),
    ``dissociation`` (a :class:`~rotarykiln.materials.dissociation.DissociationHeat` added to
    the enthalpy and c_p of CO2 and H2O, or None).
    Methods take species mass flows or mass fractions on the last axis.

    Examples
    --------
    >>> g = GasMixture.of(("N2", "CO2"))
    >>> h = g.species_enthalpy(np.array([1000.0]))   # J/kg of each species
    >>> [round(float(v) / 1e3) for v in h[0]]
    [766, 759]
    """

    names: tuple[str, ...]
    molar_mass: np.ndarray
    _tables: tuple
    dissociation: object = None

    @classmethod
    def of(cls, names, species: SpeciesTable | None = None, dissociation=None) -> GasMixture:
        """Mixture model of the gas species ``names``."""
        sp = species or default_species()
        tables = []
        for n in names:
            ct_name = CANTERA_NAMES.get(n)
            tables.append(None if ct_name is None else gas_table(f"{ct_name}:1"))
        mm = np.array([sp[n].molar_mass for n in names])
        return cls(tuple(names), mm, tuple(tables), dissociation)

    def _fallback_cp(self, i: int) -> float:
        return default_species()[self.names[i]].cp

    def with_dissociation(self, dissociation) -> GasMixture:
        """This mixture with another dissociation heat (a burner's other products): the same
        species and tables, their stacked pieces reused (the same floats as building it)."""
        new = dataclasses.replace(self, dissociation=dissociation)
        new.__dict__["_table_pieces"] = self._table_pieces  # (cached_property storage)
        return new

    @cached_property
    def _table_pieces(self):
        """The species tables' pieces stacked, without a dissociation heat: c_p (4, m, n), h
        (5, m, n) and the conductivities and viscosities side by side (4, m, 2 n)."""
        n = len(self.names)
        m = len(T_GRID) - 1
        cp = np.zeros((4, m, n))
        h = np.zeros((5, m, n))
        tr = np.zeros((4, m, 2 * n))
        for i, tab in enumerate(self._tables):
            if tab is None:
                c = self._fallback_cp(i)
                cp[3, :, i] = c
                h[3, :, i] = c
                h[4, :, i] = c * (T_GRID[:-1] - T_REF)
                continue
            for f in (tab._cp, tab._h, tab._k, tab._mu):
                if not np.array_equal(f.x, T_GRID):
                    raise ValueError(f"gas table of {self.names[i]} not on the T_GRID breakpoints")
            cp[:, :, i] = tab._cp.c
            h[:, :, i] = tab._h.c
            tr[:, :, i] = tab._k.c
            tr[:, :, n + i] = tab._mu.c
        return cp, h, tr

    @cached_property
    def _fits(self):
        """Stacked fits: (cp, h, conductivity and viscosity side by side), the cp at T_MIN and
        T_MAX (slopes of the enthalpy's linear extensions) and the transport weights."""
        cp, h, tr = (a.copy() for a in self._table_pieces)
        if self.dissociation is not None:
            cp_d, h_d = fit_pieces(self.dissociation)
            for i, name in enumerate(self.names):
                if name in ("CO2", "H2O"):
                    cp[:, :, i] += cp_d
                    h[:, :, i] += h_d
        cp_fit = PiecewisePolynomials(T_GRID, cp)
        ends = cp_fit.evaluate(*cp_fit.interval(np.array([T_MIN, T_MAX])))
        has_table = np.array([tab is not None for tab in self._tables], dtype=float)
        # transport weights: mole fraction (conductivity), x sqrt(M) (viscosity), tables only
        has_table = np.stack([has_table, has_table * np.sqrt(self.molar_mass)])
        return (
            cp_fit,
            PiecewisePolynomials(T_GRID, h),
            PiecewisePolynomials(T_GRID, tr),
            ends[0],
            ends[1],
            has_table,
        )

    def _interval(self, T):
        return self._fits[0].interval(np.minimum(np.maximum(T, T_MIN), T_MAX))

    def species_enthalpy(self, T) -> np.ndarray:
        """Sensible enthalpy of each species (J/kg, 0 at 298.15 K), shape ``T.shape + (n,)``."""
        T = np.asarray(T, dtype=float)
        _, h, _, cp_lo, cp_hi, _ = self._fits
        out = h.evaluate(*self._interval(T))
        # linear extension outside the tables, as GasPropertyTable.enthalpy (NaN goes this way)
        if not (T.size and T_MIN <= T.min() and T.max() <= T_MAX):
            out += cp_lo * np.minimum(T - T_MIN, 0.0)[..., None]
            out += cp_hi * np.maximum(T - T_MAX, 0.0)[..., None]
        return out

    def species_cp(self, T) -> np.ndarray:
        """Specific heat of each species, J/(kg K), shape ``T.shape + (n,)``."""
        T = np.asarray(T, dtype=float)
        out = self._fits[0].evaluate(*self._interval(T))
        return out

    def mole_fractions(self, mass) -> np.ndarray:
        """Mole fractions from mass flows or fractions on the last axis (negatives taken as 0)."""
        m = np.maximum(np.asarray(mass, dtype=float), 0.0)
        moles = m / self.molar_mass
        tot = moles.sum(axis=-1, keepdims=True)
        return moles / np.where(tot > 0, tot, 1.0)

    def transport(self, T, mass) -> tuple[np.ndarray, np.ndarray]:
        """Conductivity (W/(m K)) and viscosity (Pa s) of the mixture at ``T`` (K).

        ``mass``: species mass flows or fractions, shape ``T.shape + (n,)``.
        """
        return self.transport_x(T, self.mole_fractions(mass))

    def transport_x(self, T, x, *, viscosity=True):
        """:meth:`transport` from the mole fractions ``x`` (-, ``T.shape + (n,)``); with
        ``viscosity=False`` only the conductivity (W/(m K)) is returned."""
        T = np.asarray(T, dtype=float)
        n = len(self.names)
        _, _, tr, _, _, weights = self._fits
        props = tr.evaluate(*self._interval(T))  # (..., 2n): conductivities, viscosities
        xt = x * weights[0]
        wsum = xt.sum(-1)
        k = np.einsum("...i,...i->...", xt, props[..., :n])
        k /= np.where(wsum > 0, wsum, 1.0)
        if not viscosity:
            return k
        xs = x * weights[1]
        den = xs.sum(-1)
        num = np.einsum("...i,...i->...", xs, props[..., n:])
        num /= np.where(den > 0, den, 1.0)
        return k, num

    def transport_tables(self, x) -> tuple[list[np.ndarray], int]:
        """The conductivity and viscosity of gases of fixed compositions as their own piecewise
        polynomials: the species' pieces mixed once by the mole fractions ``x`` (-, ``(L,
        n)``, one composition a row), by the rules of :meth:`transport_x`. Returns the
        coefficients of each power (``(pieces * L, 2)``: row ``i L + r`` is piece ``i`` of
        composition ``r``; conductivity and viscosity side by side) and ``L``
        (:meth:`transport_fixed` evaluates them)."""
        n = len(self.names)
        x = np.asarray(x, dtype=float).reshape(-1, n)
        key = ("transport", x.tobytes())
        if (hit := self._fixed_cache.get(key)) is not None:
            return hit
        _, _, tr, _, _, weights = self._fits
        ak, am = x * weights[0], x * weights[1]
        ak = ak / np.where((sk := ak.sum(-1, keepdims=True)) > 0, sk, 1.0)
        am = am / np.where((sm := am.sum(-1, keepdims=True)) > 0, sm, 1.0)
        coef = [np.stack([c[:, :n] @ ak.T, c[:, n:] @ am.T], -1).reshape(-1, 2) for c in tr._coef]
        return self._cached(key, (coef, x.shape[0]))

    @property
    def _fixed_cache(self) -> dict:
        """The tables of fixed compositions made so far (a solve asks for its inlet gas's at
        every residual call)."""
        return self.__dict__.setdefault("_fixed_tables", {})

    def _cached(self, key, value):
        cache = self._fixed_cache
        if len(cache) >= FIXED_TABLES_KEPT:
            cache.clear()
        cache[key] = value
        return value

    def cp_tables(self, y) -> tuple[list[np.ndarray], int]:
        """The specific heat of gases of fixed compositions as their own piecewise polynomials:
        the species' pieces mixed once by the mass fractions ``y`` (-, ``(L, n)``), as
        :meth:`transport_tables` (one column)."""
        y = np.asarray(y, dtype=float).reshape(-1, len(self.names))
        key = ("cp", y.tobytes())
        if (hit := self._fixed_cache.get(key)) is not None:
            return hit
        return self._cached(key, ([(c @ y.T).reshape(-1, 1) for c in self._fits[0]._coef], len(y)))

    def enthalpy_tables(self, q) -> tuple[list[np.ndarray], int, np.ndarray, np.ndarray]:
        """The sensible enthalpy flow of gases of fixed species flows ``q`` (kg/s, ``(L, n)``)
        as piecewise polynomials (W), as :meth:`cp_tables`, with the slopes of its linear
        extensions below T_MIN and above T_MAX (W/K, ``(L,)`` each)."""
        q = np.asarray(q, dtype=float).reshape(-1, len(self.names))
        key = ("h", q.tobytes())
        if (hit := self._fixed_cache.get(key)) is not None:
            return hit
        _, h, _, cp_lo, cp_hi, _ = self._fits
        coef = [(c @ q.T).reshape(-1, 1) for c in h._coef]
        return self._cached(key, (coef, q.shape[0], q @ cp_lo, q @ cp_hi))

    def fixed_enthalpy(self, T, tables, rows=None) -> np.ndarray:
        """The enthalpy flows of :meth:`enthalpy_tables` at ``T`` (K; compositions ``rows`` as
        :meth:`fixed_value`), W: :math:`\\sum_k \\dot m_k h_k(T)` of
        :meth:`species_enthalpy`, to round-off."""
        T = np.asarray(T, dtype=float)
        coef, L, lo, hi = tables
        out = self.fixed_value(T, (coef, L), rows)[..., 0]
        if not (T.size and T_MIN <= T.min() and T.max() <= T_MAX):
            slope_lo, slope_hi = (lo[0], hi[0]) if rows is None else (lo[rows], hi[rows])
            out += slope_lo * np.minimum(T - T_MIN, 0.0)
            out += slope_hi * np.maximum(T - T_MAX, 0.0)
        return out

    def fixed_value(self, T, tables, rows=None) -> np.ndarray:
        """The properties of :meth:`transport_tables` or :meth:`cp_tables` at ``T`` (K), for
        the compositions ``rows`` (int array broadcasting with ``T``; None: the one
        composition): shape ``T.shape + (columns,)``."""
        coef, L = tables
        i, s = self._interval(np.asarray(T, dtype=float))
        return _horner(coef, i if rows is None else i * L + rows, s)

    def transport_fixed(self, T, tables, rows=None, *, viscosity=True):
        """:meth:`transport_x` of gases of fixed compositions from their :meth:`transport_tables`
        ``tables``: at ``T`` (K), composition ``rows`` (int array broadcasting with ``T``;
        None: the one composition). The same mixing rules, the species summed before the
        powers of T instead of after (the same values to round-off), two columns evaluated
        instead of two per species."""
        out = self.fixed_value(T, tables, rows)
        if not viscosity:
            return out[..., 0]
        return out[..., 0], out[..., 1]

    def mean_molar_mass(self, mass) -> np.ndarray:
        """Mean molar mass, kg/mol, from mass flows or fractions on the last axis."""
        m = np.maximum(np.asarray(mass, dtype=float), 0.0)
        tot = m.sum(axis=-1)
        moles = (m / self.molar_mass).sum(axis=-1)
        return tot / np.where(moles > 0, moles, 1.0)


@dataclass(frozen=True)
class ThermoGasMixture(GasMixture):
    """A :class:`GasMixture` whose species without a Cantera table use their own c_p(T)
    (``thermos``: per species a :class:`~rotarykiln.chemistry.thermo.SpeciesThermo` or None)
    or their table's mean c_p (``species``)."""

    thermos: tuple = ()
    species: SpeciesTable | None = None

    def _fallback_cp(self, i: int) -> float:
        sp = self.species or default_species()
        return sp[self.names[i]].cp

    @cached_property
    def _fits(self):
        cp_fit, h_fit, tr, _, _, weights = GasMixture._fits.func(self)
        n = len(self.names)
        cp_c = np.stack([cp_fit._coef[p] for p in range(4)])
        h_c = np.stack([h_fit._coef[p] for p in range(5)])
        for i, th in enumerate(self.thermos):
            if th is None or self._tables[i] is not None:
                continue
            cp_c[:, :, i], h_c[:, :, i] = fit_pieces(th)
        cp_new = PiecewisePolynomials(T_GRID, cp_c.reshape(4, -1, n))
        ends = cp_new.evaluate(*cp_new.interval(np.array([T_MIN, T_MAX])))
        return (cp_new, PiecewisePolynomials(T_GRID, h_c), tr, ends[0], ends[1], weights)


def mixture_of(names, species: SpeciesTable | None = None, dissociation=None) -> GasMixture:
    """The gas mixture model of the gas species ``names`` of ``species``.

    A plain :class:`GasMixture` when every species has a Cantera table or is a species of the
    built-in table without a c_p(T); otherwise a :class:`ThermoGasMixture`.

    Parameters
    ----------
    names : sequence of str
        Gas species, names of ``species``.
    species : SpeciesTable, optional
        Species data (default: the built-in table).
    dissociation : DissociationHeat or None
        The dissociation heat of a burner's products, carried by CO2 and H2O.

    Returns
    -------
    GasMixture
        Property model: enthalpy (J/kg), c_p (J/(kg K)), conductivity (W/(m K)) and viscosity
        (Pa s) mixed by composition.

    Examples
    --------
    >>> type(mixture_of(("N2", "CO2"))).__name__
    'GasMixture'
    >>> g = mixture_of(("N2", "tar"))
    >>> round(float(g.species_cp(np.array([700.0]))[0, 1]))   # -100 + 4.4 T - 1.57e-3 T^2
    2211

    References
    ----------
    Mixing rules: see the module (ideal-gas mixing; Herning & Zipperer 1936).
    """
    sp = species or default_species()
    builtin = default_species()
    thermos = tuple(None if CANTERA_NAMES.get(n) else sp[n].thermo for n in names)
    custom = any(t is not None for t in thermos) or any(n not in builtin for n in names)
    if not custom:
        return GasMixture.of(names, sp, dissociation)
    tables = tuple(
        None if CANTERA_NAMES.get(n) is None else gas_table(f"{CANTERA_NAMES[n]}:1") for n in names
    )
    mm = np.array([sp[n].molar_mass for n in names])
    return ThermoGasMixture(tuple(names), mm, tables, dissociation, thermos, sp)


class CaseMixtures:
    """The gas mixtures of a batch of kilns whose gases differ only in the dissociation heat
    their CO2 and H2O carry (a burner at other fuel or air flows: other products), for a
    residual with a leading case axis.

    ``mixtures``: one :class:`GasMixture` per case, of the same species and tables. Their
    stacked enthalpy and c_p pieces (those of each case's own mixture, dissociation included)
    are kept side by side, case after case, so that one gather evaluates every case at its
    own; :meth:`take` gives the mixture of the cases a residual call evaluates (its leading
    axis), which evaluates ``h`` and ``c_p`` as each case's own mixture does, to the last bit,
    and everything else (transport, molar masses) as the first.

    Examples
    --------
    >>> from rotarykiln.materials.dissociation import dissociation_heat
    >>> mixes = [GasMixture.of(("N2", "CO2", "H2O"), dissociation=dissociation_heat(x))
    ...          for x in ("CO2:1, H2O:2, N2:7.52", "CO2:1, H2O:2, O2:2, N2:15")]
    >>> T = np.array([[2000.0, 2200.0], [2000.0, 2200.0]])   # case 0, case 1
    >>> h = CaseMixtures(mixes).take(np.array([0, 1])).species_enthalpy(T)
    >>> bool((h[0] == mixes[0].species_enthalpy(T[0])).all()), bool(
    ...     (h[1] == mixes[1].species_enthalpy(T[1])).all())
    (True, True)
    """

    def __init__(self, mixtures):
        self.mixtures = list(mixtures)
        first = self.mixtures[0]
        m = len(T_GRID) - 1
        self.pieces = m
        fits = [mix._fits for mix in self.mixtures]
        # per power, the pieces of every case one after the other: (cases x pieces, species)
        self._cp = [np.concatenate([f[0]._coef[p] for f in fits]) for p in range(4)]
        self._h = [np.concatenate([f[1]._coef[p] for f in fits]) for p in range(5)]
        self._cp_lo = np.stack([f[3] for f in fits])
        self._cp_hi = np.stack([f[4] for f in fits])
        self.base = first

    def take(self, cases) -> _CasesMixture:
        """The mixture of the cases ``cases`` (index array into :attr:`mixtures`): the
        leading axis of the temperatures it is given runs over them."""
        return _CasesMixture(self, np.asarray(cases, dtype=np.intp))


class _CasesMixture:
    """:meth:`CaseMixtures.take`: a :class:`GasMixture` of several cases (leading axis)."""

    def __init__(self, stack: CaseMixtures, cases: np.ndarray):
        self._stack = stack
        self._cases = cases
        self._base = stack.base

    def __getattr__(self, name):  # transport, molar masses, names: the same for every case
        return getattr(self._base, name)

    def _located(self, T):
        T = np.asarray(T, dtype=float)
        i, s = self._base._interval(T)
        lead = self._cases.reshape((-1,) + (1,) * (T.ndim - 1))
        return T, i + lead * self._stack.pieces, s, lead

    def species_enthalpy(self, T) -> np.ndarray:
        """Each case's :meth:`GasMixture.species_enthalpy` at its temperatures ``T`` (leading
        axis: the cases), J/kg."""
        T, i, s, lead = self._located(T)
        out = _horner(self._stack._h, i, s)
        if not (T.size and T_MIN <= T.min() and T.max() <= T_MAX):
            out += self._stack._cp_lo[lead] * np.minimum(T - T_MIN, 0.0)[..., None]
            out += self._stack._cp_hi[lead] * np.maximum(T - T_MAX, 0.0)[..., None]
        return out

    def species_cp(self, T) -> np.ndarray:
        """Each case's :meth:`GasMixture.species_cp` at ``T`` (leading axis: the cases),
        J/(kg K)."""
        _, i, s, _ = self._located(T)
        return _horner(self._stack._cp, i, s)


def _horner(coef, i, s):
    """Stacked piecewise polynomials at pieces ``i`` and local variables ``s``: ``coef`` the
    coefficients of each power, highest first (pieces on the first axis, columns after)."""
    s = s[..., None]
    out = coef[0].take(i, axis=0)
    for c in coef[1:]:
        out *= s
        out += c.take(i, axis=0)
    return out


@dataclass(frozen=True)
class MixtureGas:
    """The freeboard gas of every cell for the exchange closures (a
    :class:`~rotarykiln.kiln.exchange.FreeboardGas`): ``mixture``, the cell-mean species mass
    flows ``flows`` (kg/s, ``(..., n, n_species)``), ``pressure`` (Pa) and the freeboard area
    (m2).

    Examples
    --------
    >>> g = MixtureGas.of(GasMixture.of(("N2", "CO2")), np.array([[0.9, 0.1]]), 101325.0, 0.1)
    >>> round(float(g.mass_flux[0]), 3), [round(float(p[0])) for p in g.partial_pressures()]
    (10.0, [0, 6693])
    """

    mixture: GasMixture
    flows: np.ndarray
    pressure: float
    mass_flux: np.ndarray
    total: np.ndarray

    @classmethod
    def of(cls, mixture: GasMixture, flows, pressure: float, freeboard_area) -> MixtureGas:
        """State of the cells from their mean species flows (kg/s)."""
        total = np.maximum(flows.sum(-1), 1e-12)
        return cls(mixture, flows, pressure, total / freeboard_area, total)

    @cached_property
    def _x(self) -> np.ndarray:
        """Mole fractions of the cells (computed once per state)."""
        return self.mixture.mole_fractions(self.flows)

    @cached_property
    def _fixed(self):
        """The transport tables of the gas when every cell carries one composition (its
        flows given once, on a cell axis of 1, as the kiln's residual does without gas
        species): ``(tables, rows)`` (:meth:`GasMixture.transport_tables`; rows None when every
        leading index holds the same composition), or None."""
        x = self._x
        if x.ndim < 2 or x.shape[-2] != 1:
            return None
        rows = x.reshape(-1, x.shape[-1])
        if (rows == rows[:1]).all():
            return self.mixture.transport_tables(rows[:1]), None
        index = np.arange(rows.shape[0]).reshape(x.shape[:-2] + (1,))
        return self.mixture.transport_tables(rows), index

    @cached_property
    def _fixed_cp(self):
        """The specific heat tables of a gas of one composition in every cell (as
        :attr:`_fixed`; a mixture of its own only: the cases of a batch with their own
        dissociation heats mix theirs per case), or None."""
        if self._fixed is None or not isinstance(self.mixture, GasMixture):
            return None
        y = self.flows / self.total[..., None]
        rows = y.reshape(-1, y.shape[-1])
        if self._fixed[1] is None:
            return self.mixture.cp_tables(rows[:1]), None
        return self.mixture.cp_tables(rows), self._fixed[1]

    def transport(self, T):
        """Conductivity (W/(m K)) and viscosity (Pa s) of the cells at ``T`` (K)."""
        if self._fixed is not None:
            return self.mixture.transport_fixed(T, *self._fixed)
        return self.mixture.transport_x(T, self._x)

    def conductivity(self, T):
        """Conductivity of the cells at ``T`` (K), W/(m K)."""
        if self._fixed is not None:
            return self.mixture.transport_fixed(T, *self._fixed, viscosity=False)
        return self.mixture.transport_x(T, self._x, viscosity=False)

    def density(self, T):
        """Density of the cells at ``T`` (K), kg/m3 (ideal gas)."""
        return self.pressure * self.mixture.mean_molar_mass(self.flows) / (R_UNIVERSAL * T)

    def enthalpy_flow(self, T):
        """The sensible enthalpy flow (W) of each cell's gas flows at ``T`` (K): for a gas of
        one composition from its flows' own tables (:meth:`GasMixture.enthalpy_tables`),
        else :math:`\\sum_k \\dot m_k h_k(T)` species by species."""
        if self._fixed_cp is not None:
            # one composition, but not one flow: cases of a batch may carry it at their own
            # rates, so the flows (not the mole fractions) decide whether one table serves all
            q = self.flows.reshape(-1, self.flows.shape[-1])
            if (q == q[:1]).all():
                return self.mixture.fixed_enthalpy(T, self.mixture.enthalpy_tables(q[:1]))
            rows = np.arange(q.shape[0]).reshape(self.flows.shape[:-2] + (1,))
            return self.mixture.fixed_enthalpy(T, self.mixture.enthalpy_tables(q), rows)
        return (self.flows * self.mixture.species_enthalpy(T)).sum(-1)

    def cp(self, T):
        """Specific heat of the cells at ``T`` (K), J/(kg K)."""
        if self._fixed_cp is not None:
            return self.mixture.fixed_value(T, *self._fixed_cp)[..., 0]
        return np.einsum("...i,...i->...", self.mixture.species_cp(T), self.flows) / self.total

    def partial_pressures(self):
        """H2O and CO2 partial pressures of the cells, Pa (0 for a species not in the gas)."""
        names = self.mixture.names
        x = self._x
        zero = 0.0 * x[..., 0]
        p_w = self.pressure * x[..., names.index("H2O")] if "H2O" in names else zero
        p_c = self.pressure * x[..., names.index("CO2")] if "CO2" in names else zero
        return p_w, p_c


def temperature_of_enthalpy(mixture, flows, enthalpy, low: float, high: float, points: int):
    r"""Temperature (K) at which the gas ``flows`` carry the sensible ``enthalpy``: the inverse of
    the mixture's h(T), linear between ``points`` temperatures from ``low`` to ``high``.

    .. math:: \sum_k \dot m_k h_k(T) = \dot H

    Parameters
    ----------
    mixture : GasMixture
        The gas's property tables (:func:`mixture_of`).
    flows : array, kg/s
        Species mass flows, in the mixture's order.
    enthalpy : float, W
        Sensible enthalpy flow (0 at 298.15 K).
    low, high : float, K
        The temperatures bracketing the answer (the grid's ends; outside them it is clipped).
    points : int
        Grid points of the inversion.

    Returns
    -------
    float, K

    Examples
    --------
    >>> mix = GasMixture.of(("N2",))
    >>> h = float(mix.species_enthalpy(np.array(1000.0)) @ np.array([1.0]))
    >>> round(temperature_of_enthalpy(mix, np.array([1.0]), h, 300.0, 2000.0, 1701), 3)
    1000.0

    References
    ----------
    The sensible enthalpy tables of :mod:`rotarykiln.materials.gas` (Cantera, GRI-Mech 3.0).
    """
    grid = np.linspace(low, high, points) if high > low else np.array([low, low + 1.0])
    h = mixture.species_enthalpy(grid) @ np.asarray(flows, dtype=float)
    return float(np.interp(enthalpy, h, grid))
