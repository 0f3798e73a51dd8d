r"""Axial dispersion of the bed inside the kiln's balances (a dispersion term, one Newton system).

The bed is mixed along the kiln by the tumbling of its particles; in a one-dimensional model this
is an axial dispersion coefficient :math:`D` (m2/s) acting on the bed's composition and
enthalpy. Per metre of bed hold-up :math:`m = \rho_b A_{bed}` (kg/m), the dispersive fluxes are

.. math:: J_i = -D\,m\,\frac{\partial w_i}{\partial z},\qquad
          G = -D\,m\,\sum_i w_i\,\frac{\partial h_i}{\partial z} + \sum_i J_i h_i

(:math:`w_i` mass fractions, :math:`h_i` sensible enthalpies). The bed unknowns live on the
faces (each cell's solids outlet), so the fluxes are evaluated at the cell centres from the two
faces of the cell and enter the balance of the face between two centres (a dual cell):
:math:`G_j - G_{j+1}` is added to the energy balance of cell j (and likewise :math:`J`), which
keeps the system block-tridiagonal. Both ends are closed (Danckwerts): no dispersive flux
enters with the feed or leaves at the discharge (:math:`G_0 = G_n = 0`), so every flux
telescopes and mass, elements and energy stay exactly conserved. Plug flow is :math:`D = 0`
(:math:`Pe = uL/D \to \infty`). Species that no reaction touches keep their inlet flow and do
not disperse.

References
----------
P.V. Danckwerts, Chem. Eng. Sci. 2 (1953) 1-13 (boundary conditions); O. Levenspiel, Chemical
Reaction Engineering, 3rd ed., ch. 13 (dispersion model); the Peclet number of a kiln bed from
:mod:`rotarykiln.rtd.correlations` (Sherritt et al. 2003).
"""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import check_nonnegative

__all__ = ["dispersion_sources"]


def dispersion_sources(D, holdup, q_faces, h_faces, dz, variable=None):
    r"""Net dispersive inflow of enthalpy (W) and of each species (kg/s) into every cell.

    .. math:: S^E_j = G_j - G_{j+1},\quad S^i_j = J_{i,j} - J_{i,j+1},\qquad
              G_0 = G_n = J_0 = J_n = 0

    Parameters
    ----------
    D : float, m2/s
        Axial dispersion coefficient of the bed (>= 0).
    holdup : array (..., n), kg/m
        Bed mass per metre of kiln in each cell.
    q_faces : array (..., n + 1, n_species), kg/s
        Bed species flows at the faces.
    h_faces : array (..., n + 1, n_species), J/kg
        Sensible enthalpy of each bed species at the face temperatures.
    dz : float, m
        Cell length.
    variable : array of bool (n_species,), optional
        Species that disperse (the others keep their flow); all when None.

    Returns
    -------
    energy : array (..., n), W
        Net dispersive enthalpy flow into each cell.
    species : array (..., n, n_species), kg/s
        Net dispersive flow of each species into each cell (0 for the fixed ones).

    Examples
    --------
    A linear temperature profile in a single-species bed: no net flux inside, zero total.

    >>> q = np.full((5, 1), 0.01)
    >>> h = 1000.0 * np.arange(5.0)[:, None]  # J/kg rising by 1 kJ/kg per face
    >>> e, s = dispersion_sources(1e-4, np.full(4, 20.0), q, h, 0.5)
    >>> e.round(3).tolist(), float(e.sum())
    ([4.0, 0.0, 0.0, -4.0], 0.0)

    References
    ----------
    P.V. Danckwerts, Chem. Eng. Sci. 2 (1953) 1-13.
    """
    check_nonnegative("axial dispersion coefficient", D, "m2/s")
    q = np.maximum(np.asarray(q_faces, dtype=float), 0.0)
    h = np.asarray(h_faces, dtype=float)
    total = q.sum(-1, keepdims=True)
    w = np.divide(q, total, out=np.zeros_like(q), where=total > 0)
    w_mean = 0.5 * (w[..., 1:, :] + w[..., :-1, :])
    dm = D * np.asarray(holdup, dtype=float) / dz  # kg/s per unit of w (or of h in J/kg)
    # fluxes at the cell centres j = 0 .. n-1 (between faces j and j+1)
    J = -dm[..., None] * (w[..., 1:, :] - w[..., :-1, :])
    if variable is not None:
        J = J * np.asarray(variable, dtype=float)
    h_mean = 0.5 * (h[..., 1:, :] + h[..., :-1, :])
    G = -dm * (w_mean * (h[..., 1:, :] - h[..., :-1, :])).sum(-1) + (J * h_mean).sum(-1)
    # closed ends: the centre flux of cell 0 stands for the inlet half-cell (no dispersive
    # flux with the feed); beyond the last centre nothing leaves (G and J are new arrays)
    G[..., 0] = 0.0
    J[..., 0, :] = 0.0
    energy, species = G.copy(), J.copy()
    energy[..., :-1] -= G[..., 1:]
    species[..., :-1, :] -= J[..., 1:, :]
    return energy, species
