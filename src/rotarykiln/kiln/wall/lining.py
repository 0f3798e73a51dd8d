r"""The kiln wall: a lined wall with shell loss, or a constant U.

The kiln solves the inner-wall temperature of every cell; the wall model says how many more
temperatures it has and which balances close them. Per metre of kiln, with
:math:`Q_{in} = Q_{gw} + Q_{rw} - Q_{cw}` the heat the inner surface receives:

- :class:`LinedWall` (a wall with ``layers``): layers with :math:`k(T)` between radii
  :math:`r_k`, temperatures at the inner surface, every interface and the shell;
  :math:`q_k = 2\pi[K(T_k) - K(T_{k+1})]/\ln(r_{k+1}/r_k)`, shell loss by natural (and
  wind) convection plus radiation (:func:`rotarykiln.heat.wall.shell_heat_loss`):

  .. math:: 0 = Q_{in} - q_1,\quad 0 = q_k - q_{k+1},\quad 0 = q_n - Q_{loss}(T_{sh})

- :class:`ConstantUWall` (seed 004's wall): one temperature,
  :math:`0 = Q_{in} - U \pi D (T_w - T_a)`, U referred to the inner wall.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from rotarykiln.errors import (
    OutOfRangeWarning,
    check_nonnegative,
    check_positive,
    check_range,
)
from rotarykiln.heat.wall import cylinder_layer_heat_flow, shell_heat_loss
from rotarykiln.materials.gas import GasPropertyTable, air_table
from rotarykiln.materials.lining import Layer

__all__ = ["LinedWall", "ConstantUWall", "HeaterZone"]


@dataclass(frozen=True)
class HeaterZone:
    """An electric heater zone on the shell, from ``start`` to ``end`` (m from the solids inlet).

    Either ``power`` (W, delivered to the shell over the zone, uniformly per metre) or
    ``shell_temperature`` (K, a set-point held by the heater; its power is an output).
    """

    start: float
    end: float
    power: float | None = None
    shell_temperature: float | None = None

    def __post_init__(self):
        from rotarykiln.errors import InputError

        if not (np.isfinite(self.start) and np.isfinite(self.end) and self.end > self.start >= 0):
            raise InputError("heaters", (self.start, self.end), "a zone with 0 <= start < end")
        if (self.power is None) == (self.shell_temperature is None):
            raise InputError(
                "heaters", self, "a zone with either a power or a shell_temperature set-point"
            )
        if self.power is not None and not (np.isfinite(self.power) and self.power >= 0):
            raise InputError("heaters.power", self.power, ">= 0 W")
        if self.shell_temperature is not None and not (
            np.isfinite(self.shell_temperature) and self.shell_temperature > 0
        ):
            raise InputError("heaters.shell_temperature", self.shell_temperature, "> 0 K")


def heater_arrays(zones, z_nodes):
    """Per-cell heater power (W/m) and shell set-point (K, NaN where none) of ``zones``.

    Examples
    --------
    >>> p, t = heater_arrays([HeaterZone(0.0, 1.0, power=1000.0)], np.linspace(0, 2, 5))
    >>> p.tolist(), bool(np.isnan(t).all())
    ([1000.0, 1000.0, 0.0, 0.0], True)
    """
    zn = np.asarray(z_nodes, dtype=float)
    lo, hi = zn[:-1], zn[1:]
    power = np.zeros(lo.size)
    setpoint = np.full(lo.size, np.nan)
    for zone in zones:
        overlap = np.clip(np.minimum(hi, zone.end) - np.maximum(lo, zone.start), 0.0, None)
        if zone.power is not None:
            power += zone.power / (zone.end - zone.start) * overlap / (hi - lo)
        else:
            setpoint = np.where(overlap > 0.5 * (hi - lo), zone.shell_temperature, setpoint)
    return power, setpoint


@dataclass(frozen=True)
class LinedWall:
    """Lining layers with :math:`k(T)` and the shell loss to ambient.

    ``layers`` (inner to outer), ``radii`` (m, shape ``(n_layers + 1, n_cells)``: inner
    surface first, see :class:`~rotarykiln.kiln.grid.Grid`), ``eps_shell`` (-),
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
    heater_power: np.ndarray | None = None
    heater_setpoint: np.ndarray | None = None

    def __post_init__(self):
        # checked once here: the shell loss of the residual's balance does not check again
        check_range("shell.emissivity", self.eps_shell, 0.0, 1.0, closed_high=True)
        check_nonnegative("shell.wind_speed", self.wind_speed, "m/s")
        check_positive("shell.outer_diameter", self.radii[-1], "m")
        check_positive("t_ambient", self.ambient_temperature, "K")

    @classmethod
    def of(cls, kiln, grid) -> LinedWall:
        """The wall of a kiln model with ``layers``, ``eps_shell``, ``ambient_temperature``,
        ``wind_speed`` and ``heaters``, on ``grid`` (its lining radii and faces)."""
        power = setpoint = None
        if kiln.wall.heaters:
            power, setpoint = heater_arrays(kiln.wall.heaters, grid.z_nodes)
        return cls(
            kiln.wall.layers,
            grid.radii,
            kiln.wall.outer_emissivity,
            kiln.wall.ambient_temperature,
            kiln.wall.wind_speed,
            heater_power=power,
            heater_setpoint=setpoint,
        )

    def heating(self, t_wall):
        """Electric heating of the shell (W/m per cell) at the wall temperatures ``t_wall``:
        the given power, or in set-point cells the power that holds the shell at its
        set-point (the shell's loss less what the lining takes in from it)."""
        tl = np.asarray(t_wall, dtype=float)
        if self.heater_power is None:
            return np.zeros(tl.shape[:-1])
        q_last = self._layer_flow(tl, len(self.layers) - 1)
        q_loss = self._shell_loss(tl)
        held = ~np.isnan(self.heater_setpoint)
        return np.where(held, q_loss - q_last, self.heater_power)

    @cached_property
    def _conduction(self):
        """The runs of consecutive layers of one material, ``(first, end, material)`` (layers
        ``first`` to ``end - 1``), and ln(r_out / r_in) of every layer, shape
        ``(n_cells, n_layers)``: what :meth:`balance` needs of the geometry, computed once (a
        lining cut into sub-layers is a few runs of one material)."""
        runs, first = [], 0
        for i in range(1, len(self.layers) + 1):
            if i == len(self.layers) or self.layers[i].material != self.layers[first].material:
                runs.append((first, i, self.layers[first].material))
                first = i
        radii = np.asarray(self.radii, dtype=float)
        return tuple(runs), np.log(radii[1:] / radii[:-1]).T

    def layer_flows(self, tl):
        """Heat conducted through every lining layer (W/m, ``(..., n, n_layers)``) at the wall
        temperatures ``tl``: :func:`~rotarykiln.heat.wall.cylinder_layer_heat_flow` of each
        layer, the Kirchhoff potential of a run of layers of one material in one call (the
        same numbers as layer by layer)."""
        runs, log_ratio = self._conduction
        parts = []
        for first, end, material in runs:
            K = material.conductivity_integral(tl[..., first : end + 1])
            parts.append(2.0 * np.pi * (K[..., :-1] - K[..., 1:]) / log_ratio[:, first:end])
        return parts[0] if len(parts) == 1 else np.concatenate(parts, -1)

    def _layer_flow(self, tl, i):
        """Heat conducted through lining layer ``i`` (W/m) at the wall temperatures ``tl``."""
        mat = self.layers[i].material
        return cylinder_layer_heat_flow(
            mat.conductivity_integral(tl[..., i]),
            mat.conductivity_integral(tl[..., i + 1]),
            self.radii[i],
            self.radii[i + 1],
            check=False,  # layer thicknesses are checked > 0 when the layers are built
        )

    def _shell_loss(self, tl, check=True):
        """Loss of the shell to the ambient (W/m) at the wall temperatures ``tl``."""
        return shell_heat_loss(
            tl[..., -1],
            self.ambient_temperature,
            2.0 * self.radii[-1],
            self.eps_shell,
            self.air,
            self.wind_speed,
            check=check,
        )

    @property
    def n_temperatures(self) -> int:
        """Temperatures per cell: inner surface, each interface, shell."""
        return len(self.layers) + 1

    @property
    def local(self) -> tuple[bool, ...]:
        """Which wall temperatures act on their own cell's balances only: all (the lining
        conducts radially)."""
        return (True,) * self.n_temperatures

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
        q_layers = self.layer_flows(tl)
        # the residual's wall temperatures are floored (T_FLOOR), the wall checked when built
        q_loss = self._shell_loss(tl, check=False)
        # what each interface receives from the layer inside less what it passes on
        between = q_layers[..., :-1] - q_layers[..., 1:]
        rows = [q_in - q_layers[..., 0]]
        rows += [between[..., i] for i in range(len(self.layers) - 1)]
        shell = q_layers[..., -1] - q_loss
        if self.heater_power is not None:
            held = ~np.isnan(self.heater_setpoint)
            # set-point cells: the shell temperature is held (residual in W/m through a
            # conductance of 2 pi r_shell 100 W/(m2 K)); other cells receive their power
            g = 2.0 * np.pi * self.radii[-1] * 100.0
            shell = np.where(
                held,
                g * (tl[..., -1] - np.nan_to_num(self.heater_setpoint)),
                shell + self.heater_power,
            )
        rows.append(shell)
        return rows, q_loss

    def check_service_limits(self, t_wall, z) -> bool:
        """Warn (:class:`~rotarykiln.errors.OutOfRangeWarning`) for each lining layer whose hot
        face is above its material's service limit ``t_max``, where the layer is present.

        ``t_wall``: the wall temperatures (K, ``(n, n_temperatures)``); ``z``: the cells'
        centres (m). The limit is also the top of the range of the material's k(T), so such a
        lining conducts at an extrapolated conductivity. Returns True when a layer warned.

        Examples
        --------
        >>> import warnings
        >>> from rotarykiln.materials.lining import load_lining_material
        >>> w = LinedWall((Layer(load_lining_material("fireclay_brick"), 0.1, ((0.0, 0.5),)),),
        ...               np.array([[0.5, 0.5], [0.6, 0.6]]), 0.8, 300.0)
        >>> with warnings.catch_warnings(record=True) as caught:
        ...     warnings.simplefilter("always")
        ...     w.check_service_limits(np.array([[1800.0, 400.0], [1750.0, 450.0]]),
        ...                            np.array([0.25, 2.0]))  # absent at 0.25 m
        True
        >>> print(caught[0].message)
        lining layer 1 (fireclay_brick): its hot face reaches 1750 K at z = 2 m, above the fireclay_brick t_max of 1700 K (its service limit, and the top of its k(T))

        References
        ----------
        Service limits of the lining materials: materials/refractories.yaml (manufacturer-class
        values) or the case's ``wall.lining[i].material.t_max``.
        """
        t = np.asarray(t_wall, dtype=float)
        z = np.asarray(z, dtype=float)
        warned = False
        for i, layer in enumerate(self.layers):
            limit = layer.material.t_max
            hot = np.maximum(t[:, i], t[:, i + 1])
            over = layer.present(z) & (hot > limit)
            if not over.any():
                continue
            name = layer.material.name
            zs = z[over]
            where = f"{zs[0]:.3g} m" if zs.size == 1 else f"{zs[0]:.3g}-{zs[-1]:.3g} m"
            source = f"{name} t_max"
            warnings.warn(
                OutOfRangeWarning(
                    f"lining layer {i + 1} ({name}): its hot face reaches "
                    f"{hot[over].max():.0f} K at z = {where}, above the {source} of "
                    f"{limit:.0f} K (its service limit, and the top of its k(T))",
                    quantity=f"lining layer {i + 1} hot face [K]",
                    outside=(float(hot[over].min()), float(hot[over].max())),
                    high=float(limit),
                    source=source,
                    mask=over,
                ),
                stacklevel=2,
            )
            warned = True
        return warned

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
    #: the inner wall acts on its own cell's balances only
    local = (True,)

    def labels(self) -> list[str]:
        """Name of the wall balance (the inner wall)."""
        return ["inner wall"]

    def balance(self, q_in, t_wall):
        """Residual of the inner-wall balance (W/m, list of one) and the loss (W/m)."""
        q_loss = self.u * self.perimeter * (t_wall[..., 0] - self.ambient_temperature)
        return [q_in - q_loss], q_loss

    def initial_guess(self, t_wall):
        """The inner-wall guess as an ``(n, 1)`` array, K."""
        return np.asarray(t_wall, dtype=float)[..., None]
