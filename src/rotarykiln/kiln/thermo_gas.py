r"""Freeboard gas with species of the user's (or lumped) thermochemistry.

:class:`~rotarykiln.kiln.gas_mixture.GasMixture` takes each gas species' properties from a
Cantera table, or a constant mean :math:`c_p` for species without one. A species whose
:math:`c_p(T)` is given as NASA-7, Shomate or polynomial (:mod:`rotarykiln.chemistry.thermo`;
the tar and pyrolysis gas of wood pyrolysis, or a user species) gets here its own pieces on the
table breakpoints: on every interval of :data:`~rotarykiln.materials.gas.T_GRID` its
:math:`c_p` is fitted by a cubic (least squares on 9 points: the fits are exact for polynomials
up to the cubic and within 1e-6 relative for NASA-7 and Shomate forms) and its enthalpy is the
integral of that cubic from the exact value at the interval's left end, so :math:`h` and
:math:`c_p` stay consistent. Such species take no part in the transport mixing (conductivity
and viscosity come from the species with tables), as the lumped ``volatiles`` before them.
:func:`mixture_of` returns the plain :class:`GasMixture` when no species needs this.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property, lru_cache

import numpy as np

from rotarykiln.chemistry.species import SpeciesTable, default_species
from rotarykiln.kiln.gas_mixture import CANTERA_NAMES, GasMixture
from rotarykiln.materials.gas import T_GRID, T_MAX, T_MIN, PiecewisePolynomials, gas_table

__all__ = ["ThermoGasMixture", "mixture_of", "fit_pieces"]


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
    built-in table without a c_p(T); otherwise a :class:`ThermoGasMixture`. ``dissociation``:
    the dissociation heat of a burner's products, carried by CO2 and H2O (or None).

    Examples
    --------
    >>> type(mixture_of(("N2", "CO2"))).__name__
    'GasMixture'
    >>> g = mixture_of(("N2", "tar"))
    >>> round(float(g.species_cp(np.array([700.0]))[0, 1]))   # -100 + 4.4 T - 1.57e-3 T^2
    2211
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
