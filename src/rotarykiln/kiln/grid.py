r"""Finite-volume discretisation of the kiln along z.

The kiln ``[0, L]`` is cut into ``n`` equal cells with faces (nodes) ``z_0 = 0 ... z_n = L``.
Bed and gas temperatures live on the faces (where the enthalpy flows are evaluated); the wall
and lining temperatures live in the cells. Each cell balance is

.. math::
    \dot m_s [h_s(T_{b,j+1}) - h_s(T_{b,j})] = \Delta z\,(Q_{gb} + Q_{rb} + Q_{cwb} + S_b)

and the analogous gas balance (upwind in the gas direction), with the exchange terms evaluated
at the cell-mean temperatures (average of the two faces: the box scheme, second order). Every
exchange term enters the two balances it connects with opposite signs and the same value, so
summing all cell equations telescopes to the global energy balance: the scheme is discretely
conservative and the balance closes to the solver tolerance.

The geometry of each cell (fill, angles, arcs, chord, freeboard area, hydraulic diameter, beam
length, lining radii) is precomputed once here.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rotarykiln.geometry import CrossSection
from rotarykiln.heat.gas_radiation import gorog_mean_beam_length

__all__ = ["Grid", "cell_grid", "release_per_cell", "section_fields"]

ABSENT_LAYER_THICKNESS = 1.0e-6  # m: a layer absent on a stretch is given this thickness


@dataclass(frozen=True)
class Grid:
    """Cell geometry of a discretised kiln (arrays over cells, SI units)."""

    n: int
    z_nodes: np.ndarray
    z: np.ndarray
    dz: float
    fill: np.ndarray
    half_angle: np.ndarray
    full_angle: np.ndarray
    chord: np.ndarray  # exposed bed width, m2/m
    exposed_wall: np.ndarray  # m2/m
    covered_wall: np.ndarray  # m2/m
    freeboard_area: np.ndarray  # m2
    bed_area: np.ndarray  # m2
    hydraulic_diameter: np.ndarray  # m
    depth: np.ndarray  # m
    beam_length: np.ndarray  # m
    radii: np.ndarray  # (n_layers + 1, n): interface radii, inner surface first
    present: np.ndarray  # (n_layers, n) bool
    heat_release: np.ndarray  # W/m per cell (sums to the total over the kiln)


def section_fields(cs: CrossSection, radius: float) -> dict:
    """The cross-section fields of a :class:`Grid` (all but fill) from a :class:`CrossSection`.

    Parameters
    ----------
    cs : CrossSection
        Bed cross-section of each cell (from its fill).
    radius : float, m
        Inner radius of the kiln.

    Returns
    -------
    dict
        Arrays over cells: ``half_angle``, ``full_angle`` (rad), ``chord``, ``exposed_wall``,
        ``covered_wall`` (m2/m), ``freeboard_area``, ``bed_area`` (m2),
        ``hydraulic_diameter``, ``depth`` and ``beam_length`` (m).

    Examples
    --------
    >>> f = section_fields(CrossSection.from_fill(0.15, 0.1), 0.1)
    >>> round(float(f["chord"]), 4), round(float(f["beam_length"]), 4)
    (0.1622, 0.1506)

    References
    ----------
    Segment geometry: :class:`rotarykiln.geometry.CrossSection`; mean beam length of the
    freeboard: J.P. Gorog, J.K. Brimacombe, T.N. Adams, Metall. Trans. B 12B (1981) 55-70.
    """
    return dict(
        half_angle=cs.theta,
        full_angle=2.0 * cs.theta,
        chord=cs.chord,
        exposed_wall=cs.exposed_wall_arc,
        covered_wall=cs.covered_wall_arc,
        freeboard_area=cs.freeboard_area,
        bed_area=cs.bed_area,
        hydraulic_diameter=cs.hydraulic_diameter,
        depth=cs.depth,
        beam_length=gorog_mean_beam_length(2.0 * radius, cs.depth),
    )


def cell_grid(
    length: float,
    radius: float,
    n_cells: int,
    fill_at,
    layers=(),
    *,
    heat_release: float = 0.0,
    heat_release_profile=None,
) -> Grid:
    """Precompute the geometry of ``n_cells`` equal cells of a kiln.

    Parameters
    ----------
    length, radius : float, m
        Kiln length and inner radius.
    n_cells : int
        Number of equal cells (>= 4).
    fill_at : callable
        Fill fraction (-) at positions z (m).
    layers : tuple of Layer
        Lining, inner to outer (empty: no lining radii beyond the inner surface).
    heat_release : float, W
        Heat released in the gas over the kiln.
    heat_release_profile : callable, optional
        Weights of the heat release at the cell centres z (m), normalised here (None:
        uniform).

    Returns
    -------
    Grid
        Cell geometry (m, m2/m, m2, rad per cell) and the heat release (W/m per cell).

    Examples
    --------
    >>> g = cell_grid(2.0, 0.1, 4, lambda z: np.full_like(z, 0.15))
    >>> round(float(g.chord[0]), 4), g.radii.shape
    (0.1622, (1, 4))

    References
    ----------
    Segment geometry: :class:`rotarykiln.geometry.CrossSection`; mean beam length: J.P. Gorog,
    J.K. Brimacombe, T.N. Adams, Metall. Trans. B 12B (1981) 55-70; the box scheme on these
    cells: H.B. Keller, in Numerical Solution of Partial Differential Equations II, Academic
    Press (1971) 327-350.
    """
    from rotarykiln.errors import InputError

    if int(n_cells) != n_cells or n_cells < 4:
        raise InputError("solver.cells", n_cells, "an integer >= 4")
    n = int(n_cells)
    zn = np.linspace(0.0, length, n + 1)
    z = 0.5 * (zn[:-1] + zn[1:])
    dz = length / n
    fill = fill_at(z)
    if np.any(fill <= 0.0):
        j = int(np.argmax(fill <= 0.0))
        raise InputError(f"bed.fill (cell {j}, z = {z[j]:.4g} m)", float(fill[j]), "> 0")
    cs = CrossSection.from_fill(fill, radius)
    R = radius
    present = np.array([layer.present(z) for layer in layers]).reshape(len(layers), n)
    thick = np.array(
        [
            np.where(p, layer.thickness_at(z), ABSENT_LAYER_THICKNESS)
            for layer, p in zip(layers, present, strict=True)
        ]
    ).reshape(len(layers), n)
    radii = R + np.vstack([np.zeros((1, n)), np.cumsum(thick, axis=0)])
    q_rel = release_per_cell(heat_release, heat_release_profile, z, dz)
    return Grid(
        n=n,
        z_nodes=zn,
        z=z,
        dz=dz,
        **section_fields(cs, R),
        fill=fill,
        radii=radii,
        present=present,
        heat_release=q_rel,
    )


def release_per_cell(heat_release: float, profile, z: np.ndarray, dz: float) -> np.ndarray:
    r"""Heat released in the gas per metre of each cell, normalised over the cells.

    .. math:: q_j = \frac{Q\,w(z_j)}{\Delta z \sum_k w(z_k)}

    Parameters
    ----------
    heat_release : float, W
        Heat released over the kiln, Q.
    profile : callable or None
        Weights w (-) of the release at the cell centres (None: uniform).
    z : array, m
        Cell centres.
    dz : float, m
        Cell length.

    Returns
    -------
    array, W/m
        Per cell; the cells times ``dz`` sum to ``heat_release`` (zeros when it is 0).

    Examples
    --------
    >>> release_per_cell(1000.0, lambda z: z, np.array([0.5, 1.5]), 1.0).tolist()
    [250.0, 750.0]

    References
    ----------
    The finite-volume cells of this module (:func:`cell_grid`).
    """
    from rotarykiln.errors import InputError

    n = len(z)
    if not heat_release > 0:
        return np.zeros(n)
    if profile is None:
        w = np.ones(n)
    else:
        w = np.asarray(profile(z), dtype=float) * np.ones(n)
        if np.any(~np.isfinite(w)) or np.any(w < 0) or w.sum() <= 0:
            raise InputError(
                "burner (heat release profile)", "profile", "finite, >= 0 and not all zero"
            )
    return heat_release * w / (w.sum() * dz)
