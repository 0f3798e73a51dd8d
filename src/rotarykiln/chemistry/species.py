"""Species and element bookkeeping of the reacting kiln.

A :class:`SpeciesTable` holds the bed (condensed) and gas species, their element composition,
molar mass, mean specific heat and formation enthalpy, read from ``species.yaml`` beside this
module (data, not code). Lumped species without a formula (``ash``, ``inert``) are their own
conserved pseudo-element, so an element balance also checks that they are conserved.

Bed species names and gas species names are distinct: liquid moisture is ``H2O(l)`` in the bed,
steam is ``H2O`` in the gas.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

import numpy as np
import yaml

from rotarykiln.errors import InputError

__all__ = [
    "Species",
    "SpeciesTable",
    "default_species",
    "check_mass_fractions",
]

SPECIES_FILE = Path(__file__).with_name("species.yaml")

#: Tolerance on the sum of mass fractions (absolute).
FRACTION_SUM_TOL = 1e-6


@dataclass(frozen=True)
class Species:
    """One species.

    Attributes
    ----------
    name : str
        Unique name (``"CaCO3"``, ``"H2O(l)"``, ``"H2O"``).
    phase : str
        ``"bed"`` or ``"gas"``.
    elements : dict
        Atoms per formula unit, e.g. ``{"Ca": 1, "C": 1, "O": 3}``.
    molar_mass : float
        kg/mol.
    cp : float
        Mean specific heat, J/(kg K) (only used to shift reaction heats in temperature).
    h_f : float or None
        Standard formation enthalpy at 298.15 K, J/mol, when known.
    """

    name: str
    phase: str
    elements: dict[str, float]
    molar_mass: float
    cp: float
    h_f: float | None = None
    description: str = ""


@dataclass(frozen=True)
class SpeciesTable:
    """The species of a mechanism, bed species first then gas species.

    Attributes
    ----------
    species : tuple of Species
    element_masses : dict
        Atomic mass of every element and pseudo-element, kg/mol.
    """

    species: tuple[Species, ...]
    element_masses: dict[str, float]
    _index: dict[str, int] = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        object.__setattr__(self, "_index", {s.name: i for i, s in enumerate(self.species)})

    # --- lookups -------------------------------------------------------------------------
    @property
    def names(self) -> tuple[str, ...]:
        return tuple(s.name for s in self.species)

    @property
    def bed_names(self) -> tuple[str, ...]:
        return tuple(s.name for s in self.species if s.phase == "bed")

    @property
    def gas_names(self) -> tuple[str, ...]:
        return tuple(s.name for s in self.species if s.phase == "gas")

    @property
    def elements(self) -> tuple[str, ...]:
        """Elements present in at least one species, in a stable order."""
        seen: list[str] = []
        for s in self.species:
            for e in s.elements:
                if e not in seen:
                    seen.append(e)
        return tuple(seen)

    def __contains__(self, name: str) -> bool:
        return name in self._index

    def __getitem__(self, name: str) -> Species:
        return self.species[self.index(name)]

    def index(self, name: str, field: str = "species") -> int:
        """Position of species ``name``; :class:`InputError` if unknown."""
        try:
            return self._index[name]
        except KeyError:
            raise InputError(field, name, f"a known species ({', '.join(self.names)})") from None

    @property
    def molar_masses(self) -> np.ndarray:
        """Molar masses in table order, kg/mol."""
        return np.array([s.molar_mass for s in self.species])

    @property
    def cps(self) -> np.ndarray:
        """Mean specific heats in table order, J/(kg K)."""
        return np.array([s.cp for s in self.species])

    def element_matrix(self) -> np.ndarray:
        """Atoms of element e per molecule of species i, shape (n_elements, n_species)."""
        els = self.elements
        a = np.zeros((len(els), len(self.species)))
        for j, s in enumerate(self.species):
            for e, n in s.elements.items():
                a[els.index(e), j] = n
        return a

    def element_mass_fractions(self) -> np.ndarray:
        """Mass of element e per kg of species i, shape (n_elements, n_species).

        Multiplying species mass rates (kg/s/m) by this matrix gives element mass rates.
        """
        a = self.element_matrix()
        m_el = np.array([self.element_masses[e] for e in self.elements])
        return a * m_el[:, None] / self.molar_masses[None, :]


def _molar_mass(name: str, elements: Mapping[str, float], masses: Mapping[str, float]) -> float:
    total = 0.0
    for e, n in elements.items():
        if e not in masses:
            raise InputError(
                f"species.{name}.elements", e, f"a known element ({', '.join(masses)})"
            )
        if not np.isfinite(n) or n <= 0:
            raise InputError(f"species.{name}.elements.{e}", n, "> 0")
        total += n * masses[e]
    return total * 1e-3


def species_table_from_dict(data: Mapping) -> SpeciesTable:
    """Build a :class:`SpeciesTable` from the ``species.yaml`` structure.

    The dict has keys ``bed`` and ``gas`` (name -> {elements, cp, h_f, description}) and
    ``elements`` (symbol -> atomic mass in g/mol).
    """
    masses = {e: float(m) for e, m in data.get("elements", {}).items()}
    species = []
    for phase in ("bed", "gas"):
        for name, spec in (data.get(phase) or {}).items():
            if name in [s.name for s in species]:
                raise InputError(f"species.{name}", name, "a unique name")
            elements = {e: float(n) for e, n in spec["elements"].items()}
            mm = _molar_mass(name, elements, masses)
            cp = float(spec.get("cp", 1000.0))
            if cp <= 0:
                raise InputError(f"species.{name}.cp", cp, "> 0")
            h_f = spec.get("h_f")
            species.append(
                Species(
                    name=name,
                    phase=phase,
                    elements=elements,
                    molar_mass=mm,
                    cp=cp,
                    h_f=None if h_f is None else float(h_f),
                    description=str(spec.get("description", "")),
                )
            )
    return SpeciesTable(tuple(species), {e: m * 1e-3 for e, m in masses.items()})


@lru_cache(maxsize=1)
def default_species() -> SpeciesTable:
    """The built-in species table (``chemistry/species.yaml``).

    Examples
    --------
    >>> sp = default_species()
    >>> round(sp["CaCO3"].molar_mass * 1000, 3)   # g/mol
    100.086
    >>> sp.bed_names[:3]
    ('H2O(l)', 'CaCO3', 'CaO')
    """
    with open(SPECIES_FILE, encoding="utf-8") as fh:
        return species_table_from_dict(yaml.safe_load(fh))


def check_mass_fractions(
    field: str,
    fractions: Mapping[str, float],
    species: SpeciesTable | None = None,
    *,
    phase: str | None = None,
    tol: float = FRACTION_SUM_TOL,
) -> dict[str, float]:
    """Validate a composition given as mass fractions; return it as a dict of floats.

    Refused with :class:`InputError`: an unknown species (or one of the wrong phase), a
    negative or non-finite fraction, fractions that do not sum to 1 within ``tol``.

    Parameters
    ----------
    field : str
        Name of the composition in messages (``"feed.composition"``).
    fractions : mapping
        Species name -> mass fraction [-].
    species : SpeciesTable, optional
        Defaults to :func:`default_species`.
    phase : {"bed", "gas"}, optional
        If given, every species must belong to that phase.
    tol : float
        Accepted absolute deviation of the sum from 1.

    Examples
    --------
    >>> check_mass_fractions("feed", {"CaCO3": 0.9, "H2O(l)": 0.1})
    {'CaCO3': 0.9, 'H2O(l)': 0.1}
    >>> check_mass_fractions("feed", {"CaCO3": 0.9, "H2O(l)": 0.2})
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: feed: fractions summing to 1.1 is not summing to 1 (+-1e-06)
    """
    sp = species or default_species()
    if not isinstance(fractions, Mapping) or not fractions:
        raise InputError(field, fractions, "a non-empty mapping species -> mass fraction")
    out: dict[str, float] = {}
    for name, value in fractions.items():
        if name not in sp:
            raise InputError(f"{field}.{name}", name, f"a known species ({', '.join(sp.names)})")
        if phase is not None and sp[name].phase != phase:
            raise InputError(f"{field}.{name}", name, f"a {phase} species")
        try:
            v = float(value)
        except (TypeError, ValueError):
            raise InputError(f"{field}.{name}", value, "a number in [0, 1]") from None
        if not np.isfinite(v) or v < 0 or v > 1:
            raise InputError(f"{field}.{name}", v, "a mass fraction in [0, 1]")
        out[name] = v
    total = sum(out.values())
    if abs(total - 1.0) > tol:
        raise InputError(field, f"fractions summing to {total:.6g}", f"summing to 1 (+-{tol:g})")
    return out
