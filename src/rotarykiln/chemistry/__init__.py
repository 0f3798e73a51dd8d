"""Reactions of the kiln bed: species, rate laws, heats, element balances, 0-D integrators.

Physics (pure functions, SI): :mod:`.drying`, :mod:`.calcination`, :mod:`.activation`,
:mod:`.pyrolysis`. Data: ``species.yaml`` and ``reactions/*.yaml``. Bookkeeping:
:mod:`.species`, :mod:`.reaction`, :mod:`.mechanism` (the per-cell interface for the kiln
solver), :mod:`.balance`. Residence-time effects without a kiln solver: :mod:`.plugflow`,
:mod:`.segregated`.
"""

from rotarykiln.chemistry.balance import (
    check_element_balance,
    check_stream_balance,
    element_flows,
    element_production,
)
from rotarykiln.chemistry.mechanism import CellRates, CellState, Mechanism
from rotarykiln.chemistry.ratelaws import RATE_LAWS, register_rate_law
from rotarykiln.chemistry.reaction import Reaction, builtin_reactions, load_reactions
from rotarykiln.chemistry.species import (
    Species,
    SpeciesTable,
    check_mass_fractions,
    default_species,
)

__all__ = [
    "CellRates",
    "CellState",
    "Mechanism",
    "RATE_LAWS",
    "Reaction",
    "Species",
    "SpeciesTable",
    "builtin_reactions",
    "check_element_balance",
    "check_mass_fractions",
    "check_stream_balance",
    "default_species",
    "element_flows",
    "element_production",
    "load_reactions",
    "register_rate_law",
]
