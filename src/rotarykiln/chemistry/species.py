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
from functools import cached_property, lru_cache
from pathlib import Path

import numpy as np

from rotarykiln.chemistry.yaml_files import read_yaml
from rotarykiln.errors import InputError
from rotarykiln.yaml_limits import short_repr

__all__ = [
    "Species",
    "SpeciesTable",
    "default_species",
    "check_mass_fractions",
    "load_species",
]

SPECIES_FILE = Path(__file__).with_name("species.yaml")

#: Tolerance on the sum of mass fractions (absolute).
FRACTION_SUM_TOL = 1e-6
#: Molar masses of a species, kg/mol: from 0.1 g/mol (below hydrogen) to 1e6 g/mol (a lumped
#: polymer); outside, a typing error (1e308 atoms) rather than a species.
MOLAR_MASS_RANGE = (1e-4, 1e3)
_MM_TEXT = "a molar mass in [0.1, 1e6] g/mol"
#: Most atoms of one element per formula unit.
MAX_ATOMS = 1e6


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
    thermo : SpeciesThermo or None
        Temperature-dependent c_p (:mod:`rotarykiln.chemistry.thermo`) of a user species given
        as NASA-7, Shomate or polynomial; ``cp`` is then its mean over 298.15-1000 K.
    """

    name: str
    phase: str
    elements: dict[str, float]
    molar_mass: float
    cp: float
    h_f: float | None = None
    description: str = ""
    thermo: object | None = field(default=None, compare=False)


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

    @cached_property
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
        """Mass of element e per kg of species i, shape (n_elements, n_species), read-only
        (computed once per table).

        Multiplying species mass rates (kg/s/m) by this matrix gives element mass rates.
        """
        return self._element_mass_fractions

    @cached_property
    def _element_mass_fractions(self) -> np.ndarray:
        a = self.element_matrix()
        m_el = np.array([self.element_masses[e] for e in self.elements])
        w = a * m_el[:, None] / self.molar_masses[None, :]
        w.setflags(write=False)
        return w


def _molar_mass(name: str, elements: Mapping[str, float], masses: Mapping[str, float]) -> float:
    total = 0.0
    for e, n in elements.items():
        if e not in masses:
            raise InputError(
                f"species.{name}.elements", e, f"a known element ({', '.join(masses)})"
            )
        if not np.isfinite(n) or not 0 < n <= MAX_ATOMS:
            raise InputError(f"species.{name}.elements.{e}", n, f"in (0, {MAX_ATOMS:g}]")
        total += n * masses[e]
    mm = total * 1e-3
    if not MOLAR_MASS_RANGE[0] <= mm <= MOLAR_MASS_RANGE[1]:
        raise InputError(
            f"species.{name}.elements", f"a molar mass of {mm * 1e3:.6g} g/mol", _MM_TEXT
        )
    return mm


def _molar_mass_si(field_name: str, value) -> float:
    """A molar mass given as a number (kg/mol) or a quantity ("24 g/mol"), kg/mol."""
    if isinstance(value, str):
        from rotarykiln.units import ureg

        try:
            q = ureg.Quantity(value).to("kg/mol").magnitude
        except Exception:  # noqa: BLE001  (pint raises several types)
            raise InputError(field_name, value, "a molar mass (kg/mol, g/mol)") from None
        value = float(q)
    if isinstance(value, bool) or not isinstance(value, int | float) or not np.isfinite(value):
        raise InputError(field_name, value, 'a molar mass > 0 (kg/mol or "24 g/mol")')
    if not MOLAR_MASS_RANGE[0] <= value <= MOLAR_MASS_RANGE[1]:
        raise InputError(field_name, value, _MM_TEXT)
    return float(value)


_SPECIES_KEYS = {"elements", "composition", "molar_mass", "cp", "h_f", "description"}


def _species_from_spec(
    name: str, phase: str, spec, masses: Mapping[str, float], strict: bool = True
) -> Species:
    """One :class:`Species` from its YAML mapping (checked; see :func:`load_species`).

    ``strict``: refuse keys other than those of a species (user files; the built-in file is
    read as before, extra keys ignored)."""
    from rotarykiln.chemistry.thermo import thermo_from_dict
    from rotarykiln.units import to_si

    f = f"species.{name}"
    if not isinstance(spec, Mapping):
        raise InputError(f, short_repr(spec), "a mapping with elements (or composition), cp, h_f")
    extra = sorted(map(str, set(spec) - _SPECIES_KEYS))
    if extra and strict:
        raise InputError(f"{f}.{extra[0]}", "given", "one of " + ", ".join(sorted(_SPECIES_KEYS)))
    has_el, has_comp = spec.get("elements") is not None, spec.get("composition") is not None
    if has_el == has_comp:
        raise InputError(
            f"{f}.elements",
            "both given" if has_el else "missing",
            "exactly one of elements (atoms per formula unit) or composition (element mass "
            "fractions, with molar_mass)",
        )
    if has_el:
        raw = spec["elements"]
        if not isinstance(raw, Mapping) or not raw:
            raise InputError(f"{f}.elements", raw, "a non-empty mapping element -> atoms")
        elements = {}
        for e, n in raw.items():
            if isinstance(n, bool) or not isinstance(n, int | float):
                raise InputError(f"{f}.elements.{e}", n, "a number of atoms > 0")
            elements[str(e)] = float(n)
        mm = _molar_mass(name, elements, masses)
        if spec.get("molar_mass") is not None:
            given = _molar_mass_si(f"{f}.molar_mass", spec["molar_mass"])
            if abs(given - mm) > 1e-3 * mm:
                raise InputError(
                    f"{f}.molar_mass", spec["molar_mass"], f"{mm * 1e3:.6g} g/mol (from elements)"
                )
    else:
        raw = spec["composition"]
        if not isinstance(raw, Mapping) or not raw:
            raise InputError(
                f"{f}.composition", raw, "a non-empty mapping element -> mass fraction"
            )
        if spec.get("molar_mass") is None:
            raise InputError(
                f"{f}.molar_mass",
                "missing",
                "given with a composition (nominal, e.g. 0.024 kg/mol)",
            )
        mm = _molar_mass_si(f"{f}.molar_mass", spec["molar_mass"])
        w = {}
        for e, v in raw.items():
            if e not in masses:
                raise InputError(
                    f"{f}.composition.{e}", e, f"a known element ({', '.join(masses)})"
                )
            if isinstance(v, bool) or not isinstance(v, int | float) or not 0 < v <= 1:
                raise InputError(f"{f}.composition.{e}", v, "a mass fraction in (0, 1]")
            w[str(e)] = float(v)
        total = sum(w.values())
        if abs(total - 1.0) > 1e-6:
            raise InputError(
                f"{f}.composition", f"fractions summing to {total:.6g}", "summing to 1"
            )
        elements = {e: v * mm / (masses[e] * 1e-3) for e, v in w.items()}
    cp_spec = spec.get("cp", 1000.0)
    thermo = None
    if isinstance(cp_spec, Mapping):
        thermo = thermo_from_dict(name, cp_spec, mm)
        cp = thermo.mean_cp(298.15, min(max(thermo.T_high, 400.0), 1000.0))
    else:
        cp = to_si(f"{f}.cp", cp_spec, "specific heat") if isinstance(cp_spec, str) else cp_spec
        if isinstance(cp, bool) or not isinstance(cp, int | float):
            raise InputError(
                f"{f}.cp", cp_spec, "a number in J/(kg K) or a nasa7/shomate/polynomial mapping"
            )
        cp = float(cp)
        if not np.isfinite(cp) or cp <= 0:
            raise InputError(f"{f}.cp", cp, "> 0")
    h_f = spec.get("h_f")
    if h_f is not None:
        if isinstance(h_f, str):
            h_f = to_si(f"{f}.h_f", h_f, "molar energy")
        elif isinstance(h_f, bool) or not isinstance(h_f, int | float) or not np.isfinite(h_f):
            raise InputError(f"{f}.h_f", h_f, 'a number in J/mol or a quantity ("-110.5 kJ/mol")')
        h_f = float(h_f)
    return Species(
        name=name,
        phase=phase,
        elements=elements,
        molar_mass=mm,
        cp=cp,
        h_f=h_f,
        description=str(spec.get("description", "")),
        thermo=thermo,
    )


def species_table_from_dict(
    data: Mapping, base: SpeciesTable | None = None, *, strict: bool = False
) -> SpeciesTable:
    """Build a :class:`SpeciesTable` from the ``species.yaml`` structure.

    The dict has keys ``bed`` and ``gas`` (name -> {elements or composition, molar_mass, cp,
    h_f, description}) and ``elements`` (symbol -> atomic mass in g/mol). With ``base`` the
    species are appended to that table (names must be new; elements may be added). ``strict``
    refuses unknown keys (user species).
    """
    if not isinstance(data, Mapping):
        raise InputError(
            "species", short_repr(data), "a mapping with bed, gas (and elements) sections"
        )
    extra = sorted(map(str, set(data) - {"bed", "gas", "elements"}))
    if extra:
        raise InputError(f"species.{extra[0]}", "given", "one of bed, gas, elements")
    masses = {} if base is None else {e: m * 1e3 for e, m in base.element_masses.items()}
    elements = data.get("elements") or {}
    if not isinstance(elements, Mapping):
        raise InputError("species.elements", short_repr(elements), "a mapping element -> g/mol")
    for e, m in elements.items():
        if isinstance(m, bool) or not isinstance(m, int | float) or not np.isfinite(m) or m <= 0:
            raise InputError(f"species.elements.{e}", m, "an atomic mass > 0 g/mol")
        if e in masses and abs(masses[e] - float(m)) > 1e-9 * masses[e]:
            raise InputError(f"species.elements.{e}", m, f"{masses[e]} g/mol (already defined)")
        masses[str(e)] = float(m)
    species = list(base.species) if base is not None else []
    for phase in ("bed", "gas"):
        section = data.get(phase) or {}
        if not isinstance(section, Mapping):
            raise InputError(f"species.{phase}", short_repr(section), "a mapping name -> species")
        for name, spec in section.items():
            if not isinstance(name, str) or not name:
                raise InputError(f"species.{phase}", short_repr(name), "a non-empty species name")
            if name in [s.name for s in species]:
                raise InputError(f"species.{name}", name, "a unique (new) species name")
            species.append(_species_from_spec(name, phase, spec, masses, strict))
    # bed species first, then gas (the order every table keeps)
    species.sort(key=lambda s: 0 if s.phase == "bed" else 1)
    return SpeciesTable(tuple(species), {e: m * 1e-3 for e, m in masses.items()})


def load_species(source, base: SpeciesTable | None = None) -> SpeciesTable:
    """Species table extended by user species from a YAML file or mapping.

    Parameters
    ----------
    source : str, Path or mapping
        A YAML file (or its content as a mapping) with ``bed:`` and/or ``gas:`` sections,
        name -> {``elements`` (atoms per formula unit) or ``composition`` (element mass
        fractions of a lumped species, with a nominal ``molar_mass``), ``cp`` (J/(kg K), or a
        ``nasa7``, ``shomate`` or ``polynomial`` mapping with its ``T_range``,
        :mod:`rotarykiln.chemistry.thermo`), ``h_f`` (J/mol at 298.15 K, optional),
        ``description``}, and optionally ``elements:`` (new element -> g/mol). A file may
        also hold the species under a top-level ``species:`` key.
    base : SpeciesTable, optional
        The table to extend (default :func:`default_species`).

    Returns
    -------
    SpeciesTable
        ``base`` followed by the new species (bed species first).

    Raises
    ------
    InputError
        One line naming the field: a species without elements, an unknown element, fractions
        not summing to 1, a c_p form negative in its range, a name already taken.

    Examples
    --------
    >>> sp = load_species({"bed": {"lignin": {"composition": {"C": 0.63, "H": 0.06,
    ...     "O": 0.31}, "molar_mass": "180 g/mol", "cp": 1500.0}}})
    >>> round(sp["lignin"].elements["C"], 2), "CaCO3" in sp
    (9.44, True)
    >>> load_species({"gas": {"X": {"cp": 1000.0}}})
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: species.X.elements: missing (required: exactly one of elements (atoms per formula unit) or composition (element mass fractions, with molar_mass))
    """
    if isinstance(source, Mapping):
        data = source
    else:
        data = read_yaml(source, "species file")
    if isinstance(data, Mapping) and "species" in data and not ({"bed", "gas"} & set(data)):
        data = data["species"]
    if not isinstance(source, Mapping) and not isinstance(data, Mapping):
        # a file that is not a species file: say so without showing its content
        raise InputError(
            str(source),
            message=f"{source}: not a species file (a YAML mapping with bed:, gas: and "
            "elements: sections)",
        )
    return species_table_from_dict(data, default_species() if base is None else base, strict=True)


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
    return species_table_from_dict(read_yaml(SPECIES_FILE, "species file"))


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
