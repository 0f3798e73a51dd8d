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
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rotarykiln.chemistry.species import SpeciesTable, default_species
from rotarykiln.materials.gas import R_UNIVERSAL, T_REF, gas_table

__all__ = ["GasMixture", "MixtureGas", "CANTERA_NAMES"]

#: Species of the chemistry table -> GRI-Mech 3.0 name (None: no Cantera entry).
CANTERA_NAMES = {
    "N2": "N2",
    "O2": "O2",
    "CO2": "CO2",
    "H2O": "H2O",
    "CO": "CO",
    "H2": "H2",
    "CH4": "CH4",
    "volatiles": None,
}


@dataclass(frozen=True)
class GasMixture:
    """Property model of a gas made of ``names`` (chemistry gas species), mixed by composition.

    Attributes: ``names`` (tuple), ``molar_mass`` (kg/mol per species, array).
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

    @classmethod
    def of(cls, names, species: SpeciesTable | None = None) -> GasMixture:
        """Mixture model of the gas species ``names``."""
        sp = species or default_species()
        tables = []
        for n in names:
            ct_name = CANTERA_NAMES.get(n)
            tables.append(None if ct_name is None else gas_table(f"{ct_name}:1"))
        mm = np.array([sp[n].molar_mass for n in names])
        return cls(tuple(names), mm, tuple(tables))

    def _fallback_cp(self, i: int) -> float:
        return default_species()[self.names[i]].cp

    def species_enthalpy(self, T) -> np.ndarray:
        """Sensible enthalpy of each species (J/kg, 0 at 298.15 K), shape ``T.shape + (n,)``."""
        T = np.asarray(T, dtype=float)
        out = np.empty(T.shape + (len(self.names),))
        for i, tab in enumerate(self._tables):
            if tab is None:
                out[..., i] = self._fallback_cp(i) * (T - T_REF)
            else:
                out[..., i] = tab.enthalpy(T)
        return out

    def species_cp(self, T) -> np.ndarray:
        """Specific heat of each species, J/(kg K), shape ``T.shape + (n,)``."""
        T = np.asarray(T, dtype=float)
        out = np.empty(T.shape + (len(self.names),))
        for i, tab in enumerate(self._tables):
            out[..., i] = self._fallback_cp(i) if tab is None else tab.cp(T)
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
        T = np.asarray(T, dtype=float)
        x = self.mole_fractions(mass)
        k = np.zeros(T.shape)
        num = np.zeros(T.shape)
        den = np.zeros(T.shape)
        wsum = np.zeros(T.shape)
        sq = np.sqrt(self.molar_mass)
        for i, tab in enumerate(self._tables):
            if tab is None:
                continue
            xi = x[..., i]
            k = k + xi * tab.conductivity(T)
            num = num + xi * tab.viscosity(T) * sq[i]
            den = den + xi * sq[i]
            wsum = wsum + xi
        wsum = np.where(wsum > 0, wsum, 1.0)
        den = np.where(den > 0, den, 1.0)
        return k / wsum, num / den

    def mean_molar_mass(self, mass) -> np.ndarray:
        """Mean molar mass, kg/mol, from mass flows or fractions on the last axis."""
        m = np.maximum(np.asarray(mass, dtype=float), 0.0)
        tot = m.sum(axis=-1)
        moles = (m / self.molar_mass).sum(axis=-1)
        return tot / np.where(moles > 0, moles, 1.0)


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

    def transport(self, T):
        return self.mixture.transport(T, self.flows)

    def conductivity(self, T):
        return self.mixture.transport(T, self.flows)[0]

    def density(self, T):
        return self.pressure * self.mixture.mean_molar_mass(self.flows) / (R_UNIVERSAL * T)

    def cp(self, T):
        return (self.mixture.species_cp(T) * self.flows).sum(-1) / self.total

    def partial_pressures(self):
        names = self.mixture.names
        x = self.mixture.mole_fractions(self.flows)
        zero = 0.0 * x[..., 0]
        p_w = self.pressure * x[..., names.index("H2O")] if "H2O" in names else zero
        p_c = self.pressure * x[..., names.index("CO2")] if "CO2" in names else zero
        return p_w, p_c
