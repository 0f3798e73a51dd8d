r"""Hold-ups of the transient kiln: what each balance of a cell stores, and how fast.

The steady residual :class:`~rotarykiln.kiln.residual.KilnResidual` gives, per cell, the net
outflow of every balance (W for energy, kg/s for species, scaled). The transient model stores

- **solids**: plug flow at the solids speed of the case, so the hold-up of bed species *i* in
  cell *j* is its outlet flow times the cell's solids residence time,

  .. math:: M_{ij} = \tau_j\,\dot m_{ij},\qquad
            \tau_j = \frac{\rho_b A_{bed,j}\,\Delta z}{\dot m_{feed}}

  (:math:`\rho_b` bulk density, :math:`A_{bed,j}` the bed cross-section of the cell's fill,
  :math:`\dot m_{feed}` the feed of the case; :math:`\sum_j \tau_j` is the mean residence time
  of the bed profile, L/u for a constant fill), and its energy
  :math:`U_{b,j} = \tau_j \sum_i \dot m_{ij}\,h_i(T_{b,j+1})` at the cell's outlet
  temperature (a cell is a stirred tank: the box scheme's upwind state);
- **gas**: its real hold-up, the freeboard gas mass of the cell
  :math:`m_{g,j} = \rho_g A_{fb,j}\Delta z` at the initial state, as a gas residence time
  :math:`\tau_{g,j} = m_{g,j}/\dot m_g` (frozen: about a second over the kiln, it only sets the
  fast mode of the gas; every time of interest is minutes to hours);
- **wall**: the lining nodes (inner surface, interfaces, shell) carry half of the heat capacity
  of each layer they bound, :math:`\rho_k c_k \pi (r_{k+1}^2 - r_k^2)\Delta z / 2`
  (a layer is first cut into sub-layers no thicker than ``max_node_spacing``, see
  :func:`refine_lining`, so the heat wave through a thick refractory is resolved; the steady
  conduction through sub-layers of one material is the same, exactly, by the Kirchhoff
  transform); a U-value wall (no lining) is one lumped layer of given thickness, density and
  specific heat.

References
----------
W.E. Schiesser, The Numerical Method of Lines, Academic Press (1991) (semi-discretisation);
O. Levenspiel, Chemical Reaction Engineering, 3rd ed., ch. 14 (tanks in series).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rotarykiln.errors import InputError, check_positive
from rotarykiln.materials.gas import R_UNIVERSAL

__all__ = [
    "WallProperties",
    "Holdup",
    "refine_lining",
    "lining_node_capacity",
    "DEFAULT_NODE_SPACING",
]

#: Thickest sub-layer of a lining in the transient model, m.
DEFAULT_NODE_SPACING = 0.025


@dataclass(frozen=True)
class WallProperties:
    """Heat capacity of the wall (SI).

    ``layers``: per lining layer (inner to outer) a pair (density kg/m3, specific heat
    J/(kg K)); ``lumped``: for a U-value wall, (thickness m, density kg/m3, specific heat
    J/(kg K)) of one lumped layer on the inner radius; ``max_node_spacing`` (m): thickest
    sub-layer.
    """

    layers: tuple[tuple[float, float], ...] = ()
    lumped: tuple[float, float, float] | None = None
    max_node_spacing: float = DEFAULT_NODE_SPACING

    def __post_init__(self):
        for i, (rho, cp) in enumerate(self.layers):
            check_positive(f"wall.layers[{i}].density", rho, "kg/m3")
            check_positive(f"wall.layers[{i}].specific_heat", cp, "J/(kg K)")
        if self.lumped is not None:
            for name, v, unit in zip(
                ("thickness", "density", "specific_heat"),
                self.lumped,
                ("m", "kg/m3", "J/(kg K)"),
                strict=True,
            ):
                check_positive(f"wall.{name}", v, unit)
        check_positive("wall.max_node_spacing", self.max_node_spacing, "m")


def refine_lining(layers, max_spacing: float = DEFAULT_NODE_SPACING):
    """Cut each lining layer into equal sub-layers no thicker than ``max_spacing`` (m).

    The steady conduction is unchanged: a layer's Kirchhoff heat flow is exact for any
    subdivision.

    Parameters
    ----------
    layers : tuple of Layer
        Lining, inner to outer.
    max_spacing : float, m
        Thickest sub-layer.

    Returns
    -------
    layers : tuple of Layer
        The sub-layers, inner to outer.
    parent : tuple of int
        For each sub-layer, the index of the layer it came from.

    Examples
    --------
    >>> from rotarykiln.materials.lining import Layer, load_lining_material
    >>> brick = Layer(load_lining_material("fireclay_brick"), 0.09)
    >>> new, parent = refine_lining((brick,), 0.025)
    >>> len(new), round(new[0].thickness, 4), parent
    (4, 0.0225, (0, 0, 0, 0))

    References
    ----------
    H.S. Carslaw, J.C. Jaeger, Conduction of Heat in Solids, 2nd ed., Oxford (1959) (the
    Kirchhoff transformation of conduction with k(T)).
    """
    check_positive("wall.max_node_spacing", max_spacing, "m")
    out, parent = [], []
    for i, layer in enumerate(layers):
        m = max(1, math.ceil(layer.thickness / max_spacing - 1e-9))
        out += [layer.divided(m)] * m
        parent += [i] * m
    return tuple(out), tuple(parent)


def lining_node_capacity(radii, rho_cp):
    r"""Heat capacity of the lining nodes per metre of kiln, J/(m K).

    .. math:: C_k = \tfrac12 (\rho c)_{k-1}\pi(r_k^2 - r_{k-1}^2)
              + \tfrac12 (\rho c)_k \pi(r_{k+1}^2 - r_k^2)

    Parameters
    ----------
    radii : array (n_layers + 1, n_cells), m
        Interface radii, inner surface first.
    rho_cp : array (n_layers,), J/(m3 K)
        Volumetric heat capacity of each layer.

    Returns
    -------
    array (n_cells, n_layers + 1), J/(m K)

    Examples
    --------
    >>> c = lining_node_capacity(np.array([[1.0], [2.0]]), np.array([2.0 / np.pi]))
    >>> c.tolist()  # 2 J/(m3 K) * pi (4 - 1) m2 / pi, split over the two nodes
    [[3.0, 3.0]]

    References
    ----------
    S.V. Patankar, Numerical Heat Transfer and Fluid Flow, Hemisphere (1980), ch. 4 (control
    volumes about the nodes, half a layer on each side).
    """
    r = np.asarray(radii, dtype=float)
    layer = np.asarray(rho_cp, dtype=float)[:, None] * np.pi * (r[1:] ** 2 - r[:-1] ** 2)
    node = np.zeros_like(r)
    node[:-1] += 0.5 * layer
    node[1:] += 0.5 * layer
    return node.T


@dataclass(frozen=True)
class Holdup:
    """Capacities of every row of the transient kiln (arrays over cells).

    ``tau_bed`` (s): solids residence time of each cell (hold-up over flow);
    ``tau_gas`` (s): gas residence time of each cell; ``wall`` (J/K per cell, ``(n,
    n_wall)``): heat capacity of each wall node.
    """

    tau_bed: np.ndarray
    tau_gas: np.ndarray
    wall: np.ndarray

    @classmethod
    def of(cls, res, wall: WallProperties, t_gas_cells, layer_parent=None) -> Holdup:
        """The hold-ups of a :class:`~rotarykiln.kiln.residual.KilnResidual` ``res``.

        ``t_gas_cells`` (K): gas temperature of each cell for the gas hold-up;
        ``layer_parent``: the original layer of each (sub-)layer of ``res`` (see
        :func:`refine_lining`).
        """
        k, g = res.kiln, res.grid
        tau_bed = k.bed.bulk_density * g.bed_area * g.dz / k.feed_flow * np.ones(g.n)
        mm = res.mixture.mean_molar_mass(res.gas_inlet)
        rho_g = k.gas.pressure * mm / (R_UNIVERSAL * np.asarray(t_gas_cells, dtype=float))
        tau_gas = rho_g * g.freeboard_area * g.dz / k.gas_flow
        if k.wall.layers:
            parent = layer_parent or tuple(range(len(k.wall.layers)))
            n_orig = max(parent) + 1
            if len(wall.layers) != n_orig:
                raise InputError(
                    "wall.layers",
                    f"{len(wall.layers)} given",
                    f"one density and specific heat per lining layer ({n_orig})",
                )
            rc = np.array([wall.layers[p][0] * wall.layers[p][1] for p in parent])
            cap = lining_node_capacity(g.radii, rc) * g.dz
        else:
            if wall.lumped is None:
                raise InputError(
                    "wall.thickness",
                    None,
                    "given (with density and specific_heat): a U-value wall has no lining to "
                    "give it a heat capacity",
                )
            d, rho, cp = wall.lumped
            r = k.drum.radius
            cap = (rho * cp * np.pi * ((r + d) ** 2 - r**2) * g.dz * np.ones(g.n))[:, None]
        return cls(tau_bed, tau_gas, cap)
