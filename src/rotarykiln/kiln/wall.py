r"""The kiln wall of the steady kilns: a lined wall with shell loss, or a constant U.

Both kilns solve the inner-wall temperature of every cell; the wall model says how many more
temperatures it has and which balances close them. Per metre of kiln, with
:math:`Q_{in} = Q_{gw} + Q_{rw} - Q_{cw}` the heat the inner surface receives:

- :class:`LinedWall` (the heat model's wall): layers with :math:`k(T)` between radii
  :math:`r_k`, temperatures at the inner surface, every interface and the shell;
  :math:`q_k = 2\pi[K(T_k) - K(T_{k+1})]/\ln(r_{k+1}/r_k)`, shell loss by natural (and
  wind) convection plus radiation (:func:`rotarykiln.heat.wall.shell_heat_loss`):

  .. math:: 0 = Q_{in} - q_1,\quad 0 = q_k - q_{k+1},\quad 0 = q_n - Q_{loss}(T_{sh})

- :class:`ConstantUWall` (seed 004's wall): one temperature,
  :math:`0 = Q_{in} - U \pi D (T_w - T_a)`, U referred to the inner wall.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from rotarykiln.heat.wall import cylinder_layer_heat_flow, shell_heat_loss
from rotarykiln.materials.gas import GasPropertyTable, air_table
from rotarykiln.materials.lining import Layer

__all__ = ["LinedWall", "ConstantUWall", "layers_from_case"]


def layers_from_case(lining, section: str = "heat") -> tuple[Layer, ...]:
    """Lining layers of a case file's ``lining`` list (:class:`rotarykiln.case.LiningLayer`).

    Raises :class:`~rotarykiln.errors.InputError` (``<section>.lining``) for an empty list.

    Examples
    --------
    >>> from rotarykiln.case import LiningLayer
    >>> (layer,) = layers_from_case([LiningLayer(material="fireclay_brick", thickness="0.1 m")])
    >>> layer.material.name, layer.thickness
    ('fireclay_brick', 0.1)
    """
    from rotarykiln.errors import InputError
    from rotarykiln.materials.lining import LiningMaterial, load_lining_material

    def material(spec):
        if isinstance(spec, str):
            return load_lining_material(spec)
        return LiningMaterial(spec.name, tuple(spec.k), spec.emissivity, spec.t_max)

    layers = tuple(
        Layer(
            material(layer.material),
            layer.thickness,
            absent=tuple(tuple(a) for a in layer.absent),
        )
        for layer in lining or ()
    )
    if not layers:
        raise InputError(f"{section}.lining", "[]", "a list of at least one layer")
    return layers


@dataclass(frozen=True)
class LinedWall:
    """Lining layers with :math:`k(T)` and the shell loss to ambient.

    ``layers`` (inner to outer), ``radii`` (m, shape ``(n_layers + 1, n_cells)``: inner
    surface first, see :class:`~rotarykiln.kiln.discretisation.Grid`), ``eps_shell`` (-),
    ``ambient_temperature`` (K), ``wind_speed`` (m/s), ``air`` (property table).

    Examples
    --------
    >>> from rotarykiln.materials.lining import load_lining_material
    >>> w = LinedWall((Layer(load_lining_material("fireclay_brick"), 0.1),),
    ...               np.array([[0.5], [0.6]]), 0.8, 300.0)
    >>> rows, loss = w.balance(np.array([3000.0]), np.array([[700.0, 450.0]]))
    >>> w.n_temperatures, w.labels()
    (2, ['inner wall', 'shell'])
    >>> round(float(sum(rows)[0] - (3000.0 - loss[0])), 9)  # the rows telescope
    0.0
    """

    layers: tuple[Layer, ...]
    radii: np.ndarray
    eps_shell: float
    ambient_temperature: float
    wind_speed: float = 0.0
    air: GasPropertyTable = field(default_factory=air_table, repr=False)

    @classmethod
    def of(cls, kiln, grid) -> LinedWall:
        """The wall of a kiln model with ``layers``, ``eps_shell``, ``ambient_temperature``,
        ``wind_speed``, on ``grid`` (its lining radii)."""
        return cls(
            kiln.layers, grid.radii, kiln.eps_shell, kiln.ambient_temperature, kiln.wind_speed
        )

    @property
    def n_temperatures(self) -> int:
        """Temperatures per cell: inner surface, each interface, shell."""
        return len(self.layers) + 1

    def labels(self) -> list[str]:
        """Name of each wall balance (inner wall, lining interface k, shell)."""
        n = len(self.layers)
        return ["inner wall"] + [f"lining interface {i}" for i in range(1, n)] + ["shell"]

    def balance(self, q_in, t_wall):
        """Residuals of the wall balances (W/m, list) and the shell loss (W/m).

        ``q_in``: heat received by the inner surface (W/m, ``(..., n)``); ``t_wall``: the wall
        temperatures (K, ``(..., n, n_temperatures)``).
        """
        tl = t_wall
        q_layers = []
        for i, layer in enumerate(self.layers):
            mat = layer.material
            q_layers.append(
                cylinder_layer_heat_flow(
                    mat.conductivity_integral(tl[..., i]),
                    mat.conductivity_integral(tl[..., i + 1]),
                    self.radii[i],
                    self.radii[i + 1],
                    check=False,  # layer thicknesses are checked > 0 when the layers are built
                )
            )
        q_loss = shell_heat_loss(
            tl[..., -1],
            self.ambient_temperature,
            2.0 * self.radii[-1],
            self.eps_shell,
            self.air,
            self.wind_speed,
        )
        rows = [q_in - q_layers[0]]
        for i in range(1, len(self.layers)):
            rows.append(q_layers[i - 1] - q_layers[i])
        rows.append(q_layers[-1] - q_loss)
        return rows, q_loss

    def initial_guess(self, t_wall):
        """Wall temperatures (K, ``(n, n_temperatures)``) from an inner-wall guess (K)."""
        nl = len(self.layers)
        ta = self.ambient_temperature
        return np.stack([t_wall - (t_wall - ta) * 0.8 * i / nl for i in range(nl + 1)], axis=-1)


@dataclass(frozen=True)
class ConstantUWall:
    """One wall temperature; loss :math:`U \\pi D (T_w - T_a)` per metre.

    ``u`` (W/(m2 K), on the inner wall), ``perimeter`` (m, :math:`\\pi D`),
    ``ambient_temperature`` (K).

    Examples
    --------
    >>> w = ConstantUWall(5.0, np.pi * 0.3, 298.15)
    >>> rows, loss = w.balance(np.array([100.0]), np.array([[600.0]]))
    >>> round(float(loss[0]), 1), round(float(rows[0][0]), 1)
    (1422.4, -1322.4)
    """

    u: float
    perimeter: float
    ambient_temperature: float

    n_temperatures = 1

    def labels(self) -> list[str]:
        return ["inner wall"]

    def balance(self, q_in, t_wall):
        """Residual of the inner-wall balance (W/m, list of one) and the loss (W/m)."""
        q_loss = self.u * self.perimeter * (t_wall[..., 0] - self.ambient_temperature)
        return [q_in - q_loss], q_loss

    def initial_guess(self, t_wall):
        """The inner-wall guess as an ``(n, 1)`` array, K."""
        return np.asarray(t_wall, dtype=float)[..., None]
