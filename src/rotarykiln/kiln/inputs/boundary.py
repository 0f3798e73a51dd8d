"""What the kiln's ends receive, which may change in time, and the continuation parameters.

:class:`BoundaryInputs` are the inputs of the residual that a transient run varies (the
feed, the gas inlet, the heat released, the rotation): the steady solve takes them from the
:class:`~rotarykiln.kiln.inputs.kiln.Kiln`, the transient from its event schedule
(:class:`~rotarykiln.kiln.transient.events.Schedule`), and both hand them to the residual as
an argument. :class:`Scales` are the continuation parameters the steady solver ramps.
"""

from __future__ import annotations

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
    feed (kg/s).
    """

    feed: np.ndarray
    feed_temperature: float
    gas: np.ndarray
    gas_temperature: float
    heat_release: float
    omega: float
    speed_factor: float = 1.0
    tracer: float = 0.0

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
