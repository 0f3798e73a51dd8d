"""What the kiln's ends receive, which may change in time, and the continuation parameters.

:class:`BoundaryInputs` are the inputs of the residual that a transient run varies (the
feed, the gas inlet, the heat released, the rotation): the steady solve takes them from the
:class:`~rotarykiln.kiln.inputs.kiln.Kiln`, the transient from its event schedule
(:class:`~rotarykiln.kiln.transient.events.Schedule`), and both hand them to the residual as
an argument. :class:`Scales` are the continuation parameters the steady solver ramps.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

__all__ = ["BoundaryInputs", "Scales", "FULL"]


@dataclass(frozen=True)
class BoundaryInputs:
    """Boundary inputs of the kiln at one time (SI).

    ``feed``: bed feed per bed species of the residual (kg/s); ``feed_temperature`` (K);
    ``gas``: gas inlet flow per gas species of the residual (kg/s); ``gas_temperature`` (K);
    ``heat_release``: heat released along the flame (W); ``omega``: rotation rate (rad/s);
    ``speed_factor``: solids speed over that of the kiln's inputs (-); ``tracer``: tracer
    feed (kg/s); ``bed_velocity``: the axial solids speed of the bed's hold-up (m/s; None:
    the kiln's); ``release_cells``: the heat released per metre of each cell (W/m; None: the
    kiln's release profile scaled to ``heat_release``); ``dispersion``: the bed's axial
    dispersion coefficient (m2/s; None: the kiln's; it may follow the rotation).

    :meth:`stack` makes one set of inputs of several kilns (a batch): each field then has a
    leading case axis, shaped to broadcast against the residual's ``(case, colour, cell)``
    arrays.
    """

    feed: np.ndarray
    feed_temperature: float
    gas: np.ndarray
    gas_temperature: float
    heat_release: float
    omega: float
    speed_factor: float = 1.0
    tracer: float = 0.0
    bed_velocity: float | None = None
    release_cells: np.ndarray | None = None
    dispersion: float | None = None

    @classmethod
    def of(cls, kiln, bed_names, gas_names) -> BoundaryInputs:
        """The steady inputs of ``kiln`` (a :class:`~rotarykiln.kiln.inputs.kiln.Kiln`) for
        the bed and gas species ``bed_names`` and ``gas_names`` of a residual."""
        return cls(
            feed=np.array([kiln.feed.flows.get(s, 0.0) for s in bed_names]),
            feed_temperature=kiln.feed.temperature,
            gas=np.array([kiln.gas.flows.get(s, 0.0) for s in gas_names]),
            gas_temperature=kiln.gas.temperature,
            heat_release=kiln.firing.heat_release,
            omega=kiln.drum.omega,
        )

    @classmethod
    def stack(cls, inputs) -> BoundaryInputs:
        """The inputs of several kilns of one model structure as one batch: scalars shaped
        ``(B, 1, 1)``, the feed and gas flows ``(B, 1, 1, k)``, ``release_cells`` ``(B, 1,
        n)``, to broadcast against the unknowns ``(B, colours, n, nv)`` of a batched residual.

        Examples
        --------
        >>> a = BoundaryInputs(np.array([1.0]), 300.0, np.array([2.0, 3.0]), 900.0, 0.0, 0.1)
        >>> b = BoundaryInputs.stack([a, a])
        >>> b.feed.shape, b.gas.shape, b.gas_temperature.shape
        ((2, 1, 1, 1), (2, 1, 1, 2), (2, 1, 1))
        """
        inputs = list(inputs)

        def scalars(name):
            return np.array([float(getattr(u, name)) for u in inputs]).reshape(-1, 1, 1)

        def rows(name):
            return np.stack([np.asarray(getattr(u, name), float) for u in inputs])[:, None, None]

        velocity = dispersion = None
        if any(u.bed_velocity is not None for u in inputs):
            velocity = scalars("bed_velocity")
        if any(u.dispersion is not None for u in inputs):
            dispersion = scalars("dispersion")
        cells = None
        if any(u.release_cells is not None for u in inputs):
            cells = np.stack([np.asarray(u.release_cells, float) for u in inputs])[:, None, :]
        return cls(
            feed=rows("feed"),
            feed_temperature=scalars("feed_temperature"),
            gas=rows("gas"),
            gas_temperature=scalars("gas_temperature"),
            heat_release=scalars("heat_release"),
            omega=scalars("omega"),
            speed_factor=scalars("speed_factor"),
            tracer=scalars("tracer"),
            bed_velocity=velocity,
            release_cells=cells,
            dispersion=dispersion,
        )

    def take(self, index) -> BoundaryInputs:
        """The cases ``index`` (an index array) of a stacked batch (:meth:`stack`)."""
        changes = {}
        for f in dataclasses.fields(self):
            v = getattr(self, f.name)
            changes[f.name] = None if v is None else np.asarray(v)[index]
        return dataclasses.replace(self, **changes)

    def vector(self) -> np.ndarray:
        """The inputs as one vector (feed, feed temperature, gas, gas temperature, heat
        release, rotation, speed factor, tracer), for interpolation in time."""
        return np.concatenate(
            [
                self.feed,
                [self.feed_temperature],
                self.gas,
                [self.gas_temperature, self.heat_release, self.omega, self.speed_factor],
                [self.tracer],
            ]
        )


@dataclass(frozen=True)
class Scales:
    """Continuation parameters of the residual (1 and inf: the model as it is).

    ``reaction``: factor on the reaction rates; ``radiation``: on the radiative exchange;
    ``release``: on the heat released in the gas; ``rate_temperature_cap`` (K): the
    temperature the rate laws see is a smooth minimum of the local one and this cap.
    """

    reaction: float = 1.0
    radiation: float = 1.0
    release: float = 1.0
    rate_temperature_cap: float = np.inf


#: The model without continuation.
FULL = Scales()
