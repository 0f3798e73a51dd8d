"""A set of reactions evaluated on many kiln cells at once: the interface for the kiln solver.

Per cell the kiln solver gives the bed and gas temperatures, the bed species mass flows, the
bed mass per length, the gas partial pressures over the bed and a few extra inputs the rate laws
need (steam flow, drying conductance, net bed heat input); :meth:`Mechanism.rates` returns the
species production rates (kg/(s m), bed and gas species) and the heat absorbed by the
reactions (W/m), all vectorised over cells.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

from rotarykiln.chemistry.balance import check_element_balance
from rotarykiln.chemistry.ratelaws import RateContext
from rotarykiln.chemistry.reaction import Reaction, builtin_reactions, load_reactions
from rotarykiln.chemistry.species import SpeciesTable, check_mass_fractions, default_species
from rotarykiln.errors import InputError, check_nonnegative, check_positive
from rotarykiln.tables import with_units

__all__ = ["CellState", "CellRates", "Mechanism"]


def _arr(field_name: str, value, n: int | None) -> np.ndarray:
    a = np.atleast_1d(np.asarray(value, dtype=float))
    if a.ndim != 1:
        raise InputError(field_name, f"shape {a.shape}", "a scalar or a 1-D array over cells")
    if n is not None and a.shape[0] not in (1, n):
        raise InputError(field_name, f"length {a.shape[0]}", f"length 1 or {n} (number of cells)")
    if not np.all(np.isfinite(a)):
        raise InputError(field_name, "non-finite value", "finite")
    return a if n is None or a.shape[0] == n else np.broadcast_to(a, (n,)).copy()


@dataclass(frozen=True)
class CellState:
    """State of ``n`` kiln cells as the chemistry needs it (SI units, arrays of shape (n,)).

    Attributes
    ----------
    T_bed, T_gas : ndarray
        Bed and gas temperatures, K.
    bed_mass_flow : dict
        Bed species -> mass flow, kg/s (species not listed are 0).
    bed_mass_per_length : ndarray
        Bed hold-up, kg/m.
    partial_pressure : dict
        Gas species -> partial pressure over the bed, Pa.
    bed_mass_flow_in : dict
        Bed species -> inlet mass flow, kg/s (the reference of conversions, scalars).
    inputs : dict
        Extra inputs read by some rate laws: ``steam_mass_flow`` (kg/s),
        ``drying_conductance`` (W/(m K)), ``bed_heat_input`` (W/m).
    """

    T_bed: np.ndarray
    T_gas: np.ndarray
    bed_mass_flow: Mapping[str, np.ndarray]
    bed_mass_per_length: np.ndarray
    partial_pressure: Mapping[str, np.ndarray] = field(default_factory=dict)
    bed_mass_flow_in: Mapping[str, float] = field(default_factory=dict)
    inputs: Mapping[str, np.ndarray] = field(default_factory=dict)

    @classmethod
    def build(
        cls,
        T_bed,
        T_gas,
        bed_mass_flow: Mapping,
        bed_mass_per_length,
        partial_pressure: Mapping | None = None,
        bed_mass_flow_in: Mapping | None = None,
        inputs: Mapping | None = None,
        species: SpeciesTable | None = None,
    ) -> CellState:
        """Validate and broadcast inputs to arrays of one length.

        Unknown species, negative flows, non-positive temperatures: :class:`InputError`.
        """
        sp = species or default_species()
        Tb = np.atleast_1d(np.asarray(T_bed, dtype=float))
        n = max(
            [
                Tb.shape[0],
                np.atleast_1d(T_gas).shape[0],
                np.atleast_1d(bed_mass_per_length).shape[0],
            ]
            + [np.atleast_1d(v).shape[0] for v in bed_mass_flow.values()]
        )
        Tb = _arr("cell_state.T_bed", T_bed, n)
        Tg = _arr("cell_state.T_gas", T_gas, n)
        check_positive("cell_state.T_bed", Tb, "K")
        check_positive("cell_state.T_gas", Tg, "K")
        m = _arr("cell_state.bed_mass_per_length", bed_mass_per_length, n)
        check_nonnegative("cell_state.bed_mass_per_length", m, "kg/m")
        flows = {}
        for name, v in bed_mass_flow.items():
            f = f"cell_state.bed_mass_flow.{name}"
            if name not in sp or sp[name].phase != "bed":
                raise InputError(f, name, f"a bed species ({', '.join(sp.bed_names)})")
            a = _arr(f, v, n)
            check_nonnegative(f, a, "kg/s")
            flows[name] = a
        pp = {}
        for name, v in (partial_pressure or {}).items():
            f = f"cell_state.partial_pressure.{name}"
            if name not in sp or sp[name].phase != "gas":
                raise InputError(f, name, f"a gas species ({', '.join(sp.gas_names)})")
            a = _arr(f, v, n)
            check_nonnegative(f, a, "Pa")
            pp[name] = a
        fin = {}
        for name, v in (bed_mass_flow_in or {}).items():
            f = f"cell_state.bed_mass_flow_in.{name}"
            if name not in sp or sp[name].phase != "bed":
                raise InputError(f, name, "a bed species")
            check_nonnegative(f, v, "kg/s")
            fin[name] = float(v)
        extra = {k: _arr(f"cell_state.inputs.{k}", v, n) for k, v in (inputs or {}).items()}
        return cls(Tb, Tg, flows, m, pp, fin, extra)

    @classmethod
    def from_fractions(
        cls,
        T_bed,
        T_gas,
        bed_mass_fractions: Mapping,
        bed_mass_per_length,
        bed_mass_flow=1.0,
        **kwargs,
    ) -> CellState:
        """Build a state from bed mass fractions (validated: >= 0, sum 1, known bed species).

        ``bed_mass_flow`` (kg/s) is the total bed flow; species flows are fractions times it.
        """
        sp = kwargs.get("species") or default_species()
        w = check_mass_fractions("bed_mass_fractions", bed_mass_fractions, sp, phase="bed")
        q = np.atleast_1d(np.asarray(bed_mass_flow, dtype=float))
        return cls.build(
            T_bed, T_gas, {k: v * q for k, v in w.items()}, bed_mass_per_length, **kwargs
        )


@dataclass(frozen=True)
class CellRates:
    """Reaction results on ``n`` cells.

    Attributes
    ----------
    species : tuple of str
        Species order of ``production`` columns (bed species first).
    reactions : tuple of str
    reaction_rate : ndarray
        (n, n_reactions): basis species consumed, kg/(s m).
    production : ndarray
        (n, n_species): net production of each species, kg/(s m) (negative: consumed).
    reaction_heat : ndarray
        (n, n_reactions): heat absorbed by each reaction, W/m (> 0 endothermic).
    heat_absorbed : ndarray
        (n,): total heat absorbed by the bed reactions, W/m.
    gas_species : tuple of str
    heat_absorbed_gas : ndarray or float
        (n,): heat absorbed by the gas-phase (freeboard) reactions, W/m (0 without any;
        their heat is the standard heat at 298.15 K, see :mod:`.gas_phase`).
    production_gas_phase : ndarray or float
        (n, n_species): the part of ``production`` made by the gas-phase reactions, kg/(s m).
    """

    species: tuple[str, ...]
    reactions: tuple[str, ...]
    reaction_rate: np.ndarray
    production: np.ndarray
    reaction_heat: np.ndarray
    heat_absorbed: np.ndarray
    gas_species: tuple[str, ...] = ()
    heat_absorbed_gas: np.ndarray | float = 0.0
    production_gas_phase: np.ndarray | float = 0.0

    def of(self, name: str) -> np.ndarray:
        """Production rate of one species, kg/(s m)."""
        if name not in self.species:
            raise InputError("species", name, f"one of {', '.join(self.species)}")
        return self.production[:, self.species.index(name)]

    @property
    def gas_release(self) -> np.ndarray:
        """Net mass the bed gives to the gas, kg/(s m) (sum over gas species)."""
        idx = [self.species.index(g) for g in self.gas_species]
        return self.production[:, idx].sum(axis=1)

    def to_frame(self) -> pd.DataFrame:
        cols = {f"rate_{r}_kg_s_m": self.reaction_rate[:, j] for j, r in enumerate(self.reactions)}
        cols.update(
            {f"production_{s}_kg_s_m": self.production[:, i] for i, s in enumerate(self.species)}
        )
        cols["heat_absorbed_W_m"] = self.heat_absorbed
        import pandas as pd

        return with_units(pd.DataFrame(cols), "chemistry.mechanism")

    def plot(self, x=None, ax=None):
        """Reaction rates against ``x`` (cell index by default); returns the Figure."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots()
        xs = np.arange(self.reaction_rate.shape[0]) if x is None else np.asarray(x)
        for j, r in enumerate(self.reactions):
            ax.plot(xs, self.reaction_rate[:, j], label=r)
        ax.set_xlabel("cell" if x is None else "z (m)")
        ax.set_ylabel("rate (kg/(s m))")
        ax.legend()
        return ax.figure


@dataclass(frozen=True)
class Mechanism:
    """A set of bed reactions on a species table.

    Parameters
    ----------
    reactions : sequence of Reaction
    species : SpeciesTable
    kirchhoff : bool
        False (default, seed 004 assumption 8): heats at their reference temperature. True:
        shifted to the bed temperature with the species' mean c_p (see
        :meth:`Reaction.heat_at`).

    Examples
    --------
    >>> mech = Mechanism.builtin("calcination_equilibrium")
    >>> st = CellState.from_fractions([1100.0, 1250.0], 1500.0, {"CaCO3": 1.0}, 10.0,
    ...     bed_mass_flow=0.01, bed_mass_flow_in={"CaCO3": 0.01},
    ...     partial_pressure={"CO2": 0.2 * 101325})
    >>> out = mech.rates(st)
    >>> [round(float(v), 4) for v in out.of("CO2")]        # kg CO2/(s m)
    [0.0315, 0.4649]
    >>> [round(float(v) / 1e3, 1) for v in out.heat_absorbed]  # kW/m
    [121.9, 1797.3]
    """

    reactions: tuple[Reaction, ...]
    species: SpeciesTable = field(default_factory=default_species)
    kirchhoff: bool = False

    def __post_init__(self):
        names = [r.name for r in self.reactions]
        if len(set(names)) != len(names):
            raise InputError("mechanism.reactions", names, "unique reaction names")
        for r in self.reactions:
            if r.species is not self.species and r.species.names != self.species.names:
                raise InputError(
                    f"mechanism.{r.name}", "other species table", "the mechanism's species table"
                )
        object.__setattr__(self, "reactions", tuple(self.reactions))
        S = np.array([r.mass_stoichiometry for r in self.reactions]).reshape(
            len(self.reactions), len(self.species.names)
        )
        object.__setattr__(self, "_S", S)
        object.__setattr__(self, "_dh", np.array([r.heat for r in self.reactions]))
        object.__setattr__(self, "_dcp", np.array([r.delta_cp for r in self.reactions]))
        object.__setattr__(self, "_tref", np.array([r.T_ref for r in self.reactions]))
        gas = np.array([r.phase == "gas" for r in self.reactions], dtype=bool)
        object.__setattr__(self, "_gas", gas)

    # --- construction ------------------------------------------------------------------
    @classmethod
    def builtin(cls, *names: str, kirchhoff: bool = False) -> Mechanism:
        """Mechanism from built-in reaction names (``chemistry/reactions/*.yaml``)."""
        sp = default_species()
        known = builtin_reactions(sp)
        chosen = []
        for n in names:
            if n not in known:
                raise InputError(
                    "mechanism.reactions", n, f"a built-in reaction ({', '.join(sorted(known))})"
                )
            chosen.append(known[n])
        return cls(tuple(chosen), sp, kirchhoff)

    @classmethod
    def from_yaml(
        cls,
        paths: str | Path | Iterable,
        names: Sequence[str] | None = None,
        kirchhoff: bool = False,
    ):
        """Mechanism from one or more YAML reaction files (all reactions, or ``names``)."""
        sp = default_species()
        if isinstance(paths, str | Path):
            paths = [paths]
        pool: dict[str, Reaction] = {}
        for p in paths:
            for n, r in load_reactions(p, sp).items():
                if n in pool:
                    raise InputError(f"{Path(p).name}:reactions.{n}", n, "a unique reaction name")
                pool[n] = r
        if names is None:
            return cls(tuple(pool.values()), sp, kirchhoff)
        missing = [n for n in names if n not in pool]
        if missing:
            raise InputError("mechanism.reactions", missing[0], f"one of {', '.join(pool)}")
        return cls(tuple(pool[n] for n in names), sp, kirchhoff)

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(r.name for r in self.reactions)

    @property
    def mass_stoichiometry(self) -> np.ndarray:
        """(n_reactions, n_species): kg of species produced per kg of basis consumed."""
        return self._S.copy()

    # --- evaluation --------------------------------------------------------------------
    def rates(self, state: CellState, *, check: bool = False) -> CellRates:
        """Species production rates and reaction heat on every cell.

        Parameters
        ----------
        state : CellState
        check : bool
            Also check the element balance of the result (1e-8 relative).

        Returns
        -------
        CellRates
        """
        ctx = RateContext(state, self.species)
        n = ctx.n
        R = np.empty((n, len(self.reactions)))
        for j, r in enumerate(self.reactions):
            v = np.asarray(r.law.func(ctx, r.basis, r.params), dtype=float)
            if not np.all(np.isfinite(v)):
                i = int(np.flatnonzero(~np.isfinite(v))[0])
                raise InputError(
                    f"reaction {r.name}",
                    f"non-finite rate at cell {i} (T_bed {ctx.T_bed[i]:.6g} K)",
                    "a finite rate: check the cell state",
                )
            R[:, j] = np.maximum(v, 0.0)
        if self.kirchhoff:
            # Kirchhoff shift of the bed reactions only: a gas-phase heat is the 298.15 K value
            dcp = np.where(self._gas, 0.0, self._dcp)
            dh = self._dh[None, :] + dcp[None, :] * (ctx.T_bed[:, None] - self._tref[None, :])
        else:
            dh = np.broadcast_to(self._dh, R.shape)
        heat = R * dh
        prod = R @ self._S
        gas_heat, gas_prod = 0.0, 0.0
        if self._gas.any():
            gas_heat = heat[:, self._gas].sum(axis=1)
            gas_prod = R[:, self._gas] @ self._S[self._gas]
        out = CellRates(
            species=self.species.names,
            reactions=self.names,
            reaction_rate=R,
            production=prod,
            reaction_heat=heat,
            heat_absorbed=heat[:, ~self._gas].sum(axis=1),
            gas_species=self.species.gas_names,
            heat_absorbed_gas=gas_heat,
            production_gas_phase=gas_prod,
        )
        if check:
            check_element_balance(out.production, self.species)
        return out
