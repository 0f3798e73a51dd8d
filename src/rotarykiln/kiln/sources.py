"""Hook for per-cell source terms (reactions, drying, flames) and extra unknowns (species).

A :class:`SourceTerms` object is passed to :func:`rotarykiln.kiln.solve_heat`. At every residual
evaluation the solver calls it with a :class:`CellState` and adds the returned heat release to
the bed and gas energy balances of each cell. It may also declare ``n_extra`` additional
unknowns per cell (e.g. species flows or a conversion at the cell outlet); it then supplies their
initial guess and their residuals, which the Newton solver drives to zero together with the
temperatures. See docs/heat.md, "Source-term hook".

Rules for implementers:

- every array in :class:`CellState` may carry leading batch axes (the solver evaluates many
  perturbed states at once to build its Jacobian): use elementwise numpy operations and index
  the cell axis as the last one (``[..., j]``);
- a cell's residual may depend on its own cell and its two neighbours only (j-1, j, j+1);
- heat release is in W per metre of kiln (positive = heat added to that phase);
- residuals of the extra unknowns should be scaled to order 1 (the solver converges them to
  ``tol``, the same relative tolerance as the energy residuals scaled by the reference heat).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol, runtime_checkable

import numpy as np

__all__ = ["CellState", "SourceResult", "SourceTerms"]


@dataclass(frozen=True)
class CellState:
    """State of every cell handed to a source term (SI units; arrays ``(..., n_cells)``).

    Attributes: ``z`` cell centres (m), ``dz`` cell length (m), ``t_gas``, ``t_bed``, ``t_wall``
    cell-mean temperatures (K), ``t_bed_nodes``, ``t_gas_nodes`` face temperatures
    ``(..., n_cells + 1)`` (K), ``extra`` the extra unknowns ``(..., n_cells, n_extra)``,
    ``fill`` (-), ``bed_area`` (m2, cross-section), ``chord`` (m), ``solids_flow``,
    ``gas_flow`` (kg/s).
    """

    z: np.ndarray
    dz: float
    t_gas: np.ndarray
    t_bed: np.ndarray
    t_wall: np.ndarray
    t_bed_nodes: np.ndarray
    t_gas_nodes: np.ndarray
    extra: np.ndarray
    fill: np.ndarray
    bed_area: np.ndarray
    chord: np.ndarray
    solids_flow: float
    gas_flow: float


@dataclass(frozen=True)
class SourceResult:
    """What a source term returns for every cell.

    ``q_bed``, ``q_gas``: heat added to bed and gas, W/m, shape ``(..., n_cells)``.
    ``extra_residual``: residuals of the extra unknowns, ``(..., n_cells, n_extra)``, or None.
    """

    q_bed: np.ndarray | float = 0.0
    q_gas: np.ndarray | float = 0.0
    extra_residual: np.ndarray | None = None


@runtime_checkable
class SourceTerms(Protocol):
    """Protocol of a per-cell source term (see the module docstring)."""

    n_extra: int

    def initial_extra(self, z: np.ndarray) -> np.ndarray:
        """Initial guess of the extra unknowns, shape ``(n_cells, n_extra)``."""

    def __call__(self, state: CellState) -> SourceResult:
        """Heat release and extra residuals for ``state``."""
