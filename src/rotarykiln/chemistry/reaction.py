"""The :class:`Reaction` type and loading of reactions from YAML.

A reaction is data: molar stoichiometry by species, a basis species (a reactant whose mass
consumption rate the rate law returns, kg/(s m)), a named rate law with its parameters, a heat of
reaction per kg of basis consumed at a reference temperature, and its source. Validation happens
at load: unknown species, a basis that is not a reactant, stoichiometry that does not balance its
elements, an unknown rate law or parameter, a non-numeric heat: each an :class:`InputError`.

YAML form (one file may hold several reactions)::

    reactions:
      - name: calcination_equilibrium
        equation: CaCO3 -> CaO + CO2          # informative only
        stoichiometry: {CaCO3: -1, CaO: 1, CO2: 1}
        basis: CaCO3
        rate: {law: equilibrium_calcination, A: 9.8e4, E: 142000, order: 0.5}
        heat: {value: 1.7 MJ/kg, T_ref: 873.15}   # or J/kg as a number, or "178 kJ/mol"
        source: Ahmad (2006) eq. 3.22; Baker (1962)

Heat of reaction and sensible enthalpy: ``heat`` is :math:`\\Delta H_r(T_{ref})` per kg of
basis consumed (positive = endothermic). At another temperature
:math:`\\Delta H_r(T) = \\Delta H_r(T_{ref}) + \\sum_i s_i c_{p,i} (T - T_{ref})` (Kirchhoff, with
:math:`s_i` the mass stoichiometry and the species' mean :math:`c_p`): this is the heat a
temperature-form energy balance must remove when reactants vanish and products appear at the
local temperature. A solver that instead carries each species' sensible enthalpy
:math:`c_{p,i}(T - T_{ref})` in its enthalpy flows must use :math:`\\Delta H_r(T_{ref})` (it would
count the Kirchhoff term twice otherwise). See docs/chemistry.md.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from rotarykiln.chemistry import gas_phase as _gas_phase  # noqa: F401  (registers its laws)
from rotarykiln.chemistry.ratelaws import RATE_LAWS, RateLaw
from rotarykiln.chemistry.species import SpeciesTable, default_species
from rotarykiln.chemistry.yaml_files import read_yaml
from rotarykiln.errors import InputError
from rotarykiln.units import to_si

__all__ = [
    "Reaction",
    "reaction_from_dict",
    "load_reactions",
    "builtin_reactions",
    "REACTIONS_DIR",
    "BALANCE_RTOL",
]

REACTIONS_DIR = Path(__file__).with_name("reactions")

#: Relative tolerance on the element balance of a stoichiometry at load.
BALANCE_RTOL = 1e-9


@dataclass(frozen=True)
class Reaction:
    """A reaction of the bed.

    Attributes
    ----------
    name : str
    stoichiometry : dict
        Species -> molar coefficient (negative for reactants).
    basis : str
        Reactant species whose consumption rate (kg/(s m)) the rate law returns.
    law : RateLaw
        The named rate law.
    params : dict
        Parameters of the rate law (defaults filled in).
    heat : float
        Heat of reaction at ``T_ref``, J per kg of basis consumed (> 0 endothermic).
    T_ref : float
        Reference temperature of ``heat``, K.
    phase : str
        ``bed`` (default: rates per bed hold-up, heat taken from the bed) or ``gas`` (a
        freeboard reaction of gas species: rate per freeboard volume at the gas temperature,
        heat released into the gas; ``heat`` then at 298.15 K).
    source : str
    equation : str
    mass_stoichiometry : ndarray
        kg of each species of ``species`` produced per kg of basis consumed (basis: -1).
    """

    name: str
    stoichiometry: dict[str, float]
    basis: str
    law: RateLaw
    params: dict
    heat: float
    T_ref: float
    species: SpeciesTable = field(repr=False)
    source: str = ""
    equation: str = ""
    phase: str = "bed"
    mass_stoichiometry: np.ndarray = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        sp = self.species
        s = np.zeros(len(sp.species))
        nb = self.stoichiometry[self.basis]
        mb = sp[self.basis].molar_mass
        for name, nu in self.stoichiometry.items():
            s[sp.index(name)] = nu * sp[name].molar_mass / (abs(nb) * mb)
        object.__setattr__(self, "mass_stoichiometry", s)

    @property
    def delta_cp(self) -> float:
        """Sum of s_i c_p,i: change of heat capacity per kg basis reacted, J/(kg K)."""
        return float(self.mass_stoichiometry @ self.species.cps)

    def heat_at(self, T):
        r"""Heat of reaction at T (Kirchhoff with mean c_p), J/kg basis.

        .. math:: \Delta H_r(T) = \Delta H_r(T_{ref}) + \sum_i s_i c_{p,i}\,(T - T_{ref})

        Parameters
        ----------
        T : float or array
            K.

        Returns
        -------
        float or ndarray
            J per kg of basis consumed.
        """
        h = self.heat + self.delta_cp * (np.asarray(T, dtype=float) - self.T_ref)
        return h if np.ndim(h) else float(h)

    def standard_heat(self) -> float | None:
        """Heat of reaction at 298.15 K from formation enthalpies, J/kg basis (None if unknown)."""
        total = 0.0
        for name, nu in self.stoichiometry.items():
            hf = self.species[name].h_f
            if hf is None:
                return None
            total += nu * hf
        return total / (abs(self.stoichiometry[self.basis]) * self.species[self.basis].molar_mass)

    def element_residual(self) -> dict[str, float]:
        """Net atoms of each element per reaction event (should be 0)."""
        out = {}
        for e in self.species.elements:
            out[e] = sum(
                nu * self.species[n].elements.get(e, 0.0) for n, nu in self.stoichiometry.items()
            )
        return out


def _heat_from(field_name: str, heat, basis_molar_mass: float) -> tuple[float, float]:
    """Parse a heat entry -> (J/kg basis, T_ref K)."""
    T_ref = 298.15
    value = heat
    if isinstance(heat, Mapping):
        unknown = set(heat) - {"value", "T_ref"}
        if unknown:
            raise InputError(f"{field_name}.{sorted(unknown)[0]}", "given", "one of value, T_ref")
        if "value" not in heat:
            raise InputError(f"{field_name}.value", "missing", "given")
        value = heat["value"]
        if "T_ref" in heat:
            T_ref = to_si(f"{field_name}.T_ref", heat["T_ref"], "temperature")
            if T_ref <= 0:
                raise InputError(f"{field_name}.T_ref", T_ref, "> 0 K")
    if isinstance(value, str):
        try:
            h = to_si(f"{field_name}.value", value, "specific energy")
        except InputError:
            h = to_si(f"{field_name}.value", value, "molar energy") / basis_molar_mass
    elif isinstance(value, int | float) and not isinstance(value, bool):
        h = float(value)
        if not np.isfinite(h):
            raise InputError(f"{field_name}.value", value, "a finite number (J/kg)")
    else:
        raise InputError(
            f"{field_name}.value", value, 'a number in J/kg or a quantity ("1.7 MJ/kg")'
        )
    return h, T_ref


def reaction_from_dict(
    data: Mapping, species: SpeciesTable | None = None, where: str = "reactions"
) -> Reaction:
    """Build and validate one :class:`Reaction` from its YAML mapping.

    Parameters
    ----------
    data : mapping
        Keys ``name``, ``stoichiometry``, ``basis``, ``rate``, ``heat``, optional ``source``,
        ``equation``.
    species : SpeciesTable, optional
        Defaults to :func:`default_species`.
    where : str
        Prefix of field names in error messages.

    Examples
    --------
    >>> r = reaction_from_dict({"name": "calc", "stoichiometry": {"CaCO3": -1, "CaO": 1, "CO2": 1},
    ...     "basis": "CaCO3", "rate": {"law": "luisser_calcination"}, "heat": "1.7 MJ/kg"})
    >>> round(float(r.mass_stoichiometry[r.species.index("CO2")]), 4)    # kg CO2 per kg CaCO3
    0.4397
    >>> bad = {"name": "bad", "stoichiometry": {"CaCO3": -1, "CaO": 1},
    ...        "basis": "CaCO3", "rate": {"law": "luisser_calcination"}, "heat": 0.0}
    >>> reaction_from_dict(bad)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: reactions.bad.stoichiometry: O -2, C -1 atoms per event ...
    """
    sp = species or default_species()
    if not isinstance(data, Mapping):
        raise InputError(where, data, "a mapping with name, stoichiometry, basis, rate, heat")
    name = data.get("name")
    if not isinstance(name, str) or not name:
        raise InputError(f"{where}.name", name, "a non-empty string")
    f = f"{where}.{name}"
    allowed = {"name", "stoichiometry", "basis", "rate", "heat", "source", "equation", "phase"}
    extra = set(data) - allowed
    if extra:
        raise InputError(f"{f}.{sorted(extra)[0]}", "given", f"one of {', '.join(sorted(allowed))}")
    for key in ("stoichiometry", "basis", "rate", "heat"):
        if key not in data:
            raise InputError(f"{f}.{key}", "missing", "given")
    stoich_in = data["stoichiometry"]
    if not isinstance(stoich_in, Mapping) or len(stoich_in) < 2:
        raise InputError(
            f"{f}.stoichiometry", stoich_in, "a mapping of at least two species -> coefficients"
        )
    stoich: dict[str, float] = {}
    for s_name, nu in stoich_in.items():
        if s_name not in sp:
            raise InputError(
                f"{f}.stoichiometry.{s_name}", s_name, f"a known species ({', '.join(sp.names)})"
            )
        try:
            v = float(nu)
        except (TypeError, ValueError):
            raise InputError(f"{f}.stoichiometry.{s_name}", nu, "a number") from None
        if not np.isfinite(v) or v == 0:
            raise InputError(f"{f}.stoichiometry.{s_name}", nu, "a finite non-zero coefficient")
        stoich[s_name] = v
    basis = data["basis"]
    if not isinstance(basis, str) or basis not in stoich or stoich[basis] >= 0:
        raise InputError(
            f"{f}.basis", basis, "a reactant of the stoichiometry (negative coefficient)"
        )
    phase = data.get("phase", "bed")
    if phase not in ("bed", "gas"):
        raise InputError(f"{f}.phase", phase, "bed or gas")
    if phase == "bed" and sp[basis].phase != "bed":
        raise InputError(f"{f}.basis", basis, "a bed species (rates are per bed hold-up)")
    if phase == "gas":
        solids = [n for n in stoich if sp[n].phase != "gas"]
        if solids:
            raise InputError(f"{f}.stoichiometry.{solids[0]}", solids[0], "a gas species")
    # element balance
    bad = []
    for e in sp.elements:
        terms = [nu * sp[n].elements.get(e, 0.0) for n, nu in stoich.items()]
        scale = sum(abs(t) for t in terms)
        net = sum(terms)
        if scale > 0 and abs(net) > BALANCE_RTOL * scale:
            bad.append(f"{e} {net:+.6g}")
    if bad:
        raise InputError(
            f"{f}.stoichiometry",
            ", ".join(bad).replace("+", "") + " atoms per event",
            "element-balanced (C, H, O, Ca, N, ... conserved)",
        )
    # rate law
    rate = data["rate"]
    if isinstance(rate, str):
        rate = {"law": rate}
    if not isinstance(rate, Mapping) or "law" not in rate:
        raise InputError(f"{f}.rate", rate, "a mapping with a 'law' key")
    law_name = rate["law"]
    if not isinstance(law_name, str) or law_name not in RATE_LAWS:
        raise InputError(
            f"{f}.rate.law", law_name, f"a known rate law ({', '.join(sorted(RATE_LAWS))})"
        )
    law = RATE_LAWS[law_name]
    params = law.validate_params({k: v for k, v in rate.items() if k != "law"}, f"{f}.rate", basis)
    for gas in params.get("pressure_orders", {}):
        if gas not in sp or sp[gas].phase != "gas":
            raise InputError(
                f"{f}.rate.pressure_orders.{gas}", gas, f"a gas species ({', '.join(sp.gas_names)})"
            )
    heat, T_ref = _heat_from(f"{f}.heat", data["heat"], sp[basis].molar_mass)
    if phase == "gas" and abs(T_ref - 298.15) > 1e-9:
        raise InputError(f"{f}.heat.T_ref", T_ref, "298.15 K for a gas-phase reaction")
    return Reaction(
        name=name,
        stoichiometry=stoich,
        basis=basis,
        law=law,
        params=params,
        heat=heat,
        T_ref=T_ref,
        species=sp,
        source=str(data.get("source", "")),
        equation=str(data.get("equation", "")),
        phase=phase,
    )


def load_reactions(path, species: SpeciesTable | None = None) -> dict[str, Reaction]:
    """Load and validate every reaction of a YAML file; returns name -> Reaction.

    Parameters
    ----------
    path : str or Path
        YAML file with a top-level ``reactions:`` list.
    species : SpeciesTable, optional
    """
    path = Path(path)
    data = read_yaml(path, "reaction file")
    if not isinstance(data, Mapping) or not isinstance(data.get("reactions"), list):
        raise InputError(str(path), "content", "a mapping with a 'reactions' list")
    out: dict[str, Reaction] = {}
    for item in data["reactions"]:
        r = reaction_from_dict(item, species, where=f"{path.name}:reactions")
        if r.name in out:
            raise InputError(f"{path.name}:reactions.{r.name}", r.name, "a unique reaction name")
        out[r.name] = r
    return out


def builtin_reactions(species: SpeciesTable | None = None) -> dict[str, Reaction]:
    """All built-in reactions (``chemistry/reactions/*.yaml``), name -> Reaction.

    Examples
    --------
    >>> [n for n in sorted(builtin_reactions()) if n.startswith("calcination")]
    ['calcination_bed_co2', 'calcination_equilibrium', 'calcination_luisser']
    """
    out: dict[str, Reaction] = {}
    for p in sorted(REACTIONS_DIR.glob("*.yaml")):
        for name, r in load_reactions(p, species).items():
            if name in out:
                raise InputError(f"{p.name}:reactions.{name}", name, "a unique reaction name")
            out[name] = r
    return out
