r"""Enthalpy and volatile release of Stuart oil shale and its ash (Van Puyvelde 1999, §9.1.5).

There are no Arrhenius kinetics in the thesis: every reaction of Table 9.1 (Berkovich 1999) is a
function of temperature only, smoothed by an exponential that starts at the lower temperature of
its range and is 90 % complete at the upper one:

.. math::

    X_k(T) = 1 - \exp\left(-\frac{T - T_{lo,k}}{\tau_k}\right) \; (T > T_{lo,k}), \qquad
    H(T) = \int_{T_{ref}}^{T} c_p\,dT + \sum_k \Delta H_k\,X_k(T)

per unit mass of *original* (unreacted) material (eq 9.8). Volatiles: the kerogen fraction
(20 wt %) released as :math:`w_{ker} X_{ker}(T)`; moisture (lost below 523 K, the retort inlet)
is not counted. The thesis's TGA curve (Fig 9.2) is lost; the text says ~20 % between 523 K and
~750 K, which the kerogen step reproduces. The sensible heat capacities (Fig 9.1) are lost too:
constant defaults (shale 1150, ash 1000 J/(kg K)) are used and are parameters.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from rotarykiln.errors import check_positive

__all__ = [
    "Thermochemistry",
    "berkovich_shale",
    "reaction_extent",
    "sensible_solid",
]

#: Table 9.1 reaction steps: name -> (mass fraction, T_lo [K], enthalpy [J/kg original], tau [K])
TABLE_9_1 = {
    "water": (0.25, 343.0, 564.75e3, 17.37),
    "kerogen": (0.20, 743.0, 159.85e3, 21.71),
    "quartz": (0.10, 844.0, -1.04e3, 4.34),
    "pyrite": (0.02, 738.0, 5.81e3, 4.34),
    "gypsum": (0.01, 400.0, 5.91e3, 4.34),
    "siderite": (0.03, 740.0, 17.55e3, 4.34),
    "dolomite": (0.03, 950.0, 41.94e3, 21.71),
    "calcite": (0.06, 990.0, 101.89e3, 21.71),
}


def reaction_extent(temperature, t_low, tau):
    r"""Extent of a temperature-controlled reaction step, :math:`1 - e^{-(T - T_{lo})/\tau}`.

    Parameters
    ----------
    temperature : float or array, K
    t_low : float, K
        Temperature at which the step starts.
    tau : float, K
        Decay constant (ΔT/ln 10 makes the step 90 % complete after ΔT).

    Returns
    -------
    float or array, -
        Extent in [0, 1).

    Examples
    --------
    >>> round(float(reaction_extent(793.0, 743.0, 50 / np.log(10))), 3)
    0.9

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS.
    """
    check_positive("tau", tau, "K")
    check_positive("temperature", temperature, "K")
    check_positive("t_low", t_low, "K")
    dt = np.maximum(np.asarray(temperature, dtype=float) - t_low, 0.0)
    return -np.expm1(-dt / tau)


@dataclass(frozen=True)
class Thermochemistry:
    """Enthalpy H(T) [J/kg original], its inverse, and volatile yield Y(T) [kg/kg original].

    The inverse is tabulated on ``t_grid`` and evaluated by linear interpolation (vectorised);
    H is monotone because c_p exceeds the slope of the one endothermic-negative step (quartz).
    """

    name: str
    cp: float
    steps: dict = field(default_factory=dict)
    volatile_steps: tuple[str, ...] = ()
    t_ref: float = 298.15
    t_grid: np.ndarray = field(default_factory=lambda: np.linspace(250.0, 2000.0, 7001))

    def __post_init__(self):
        check_positive(f"{self.name}.cp", self.cp, "J/(kg K)")
        h = self.enthalpy(self.t_grid)
        if np.any(np.diff(h) <= 0):
            raise ValueError(f"{self.name}: enthalpy is not monotone in temperature")
        object.__setattr__(self, "_h_grid", h)
        object.__setattr__(self, "_dh_grid", np.gradient(h, self.t_grid))

    def enthalpy(self, temperature):
        """Specific enthalpy [J/kg of original material] at ``temperature`` [K]."""
        t = np.asarray(temperature, dtype=float)
        h = self.cp * (t - self.t_ref)
        for _w, t_lo, dh, tau in self.steps.values():
            h = h + dh * reaction_extent(t, t_lo, tau)
        return h

    def temperature(self, enthalpy):
        """Temperature [K] from specific enthalpy [J/kg original] (interpolated inverse)."""
        h = np.asarray(enthalpy, dtype=float)
        return np.interp(h, self._h_grid, self.t_grid, left=np.nan, right=np.nan)

    def heat_capacity(self, temperature):
        """Apparent heat capacity dH/dT [J/(kg K)] including the reaction steps."""
        return np.interp(temperature, self.t_grid, self._dh_grid)

    def volatile_yield(self, temperature):
        """Volatile mass released [kg/kg original] at ``temperature`` [K] (moisture excluded)."""
        t = np.asarray(temperature, dtype=float)
        y = np.zeros_like(t)
        for name in self.volatile_steps:
            w, t_lo, _, tau = self.steps[name]
            y = y + w * reaction_extent(t, t_lo, tau)
        return y

    @property
    def max_volatiles(self) -> float:
        """Total volatile fraction when every volatile step is complete."""
        return float(sum(self.steps[n][0] for n in self.volatile_steps))


def berkovich_shale(cp: float = 1150.0) -> Thermochemistry:
    """Stuart oil shale of Table 9.1 (Berkovich 1999): enthalpy steps and kerogen volatiles.

    Parameters
    ----------
    cp : float, J/(kg K)
        Sensible heat capacity (the thesis's Fig 9.1 values are lost).

    Returns
    -------
    Thermochemistry
        Enthalpy (J/kg) and reaction extent of the Table 9.1 shale.

    Examples
    --------
    >>> sh = berkovich_shale()
    >>> round(float(sh.volatile_yield(900.0)), 4)
    0.1999
    >>> round(float(sh.temperature(sh.enthalpy(760.0))), 3)
    760.0

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, Table 9.1
    (after Berkovich 1999).
    """
    return Thermochemistry("shale", cp, dict(TABLE_9_1), volatile_steps=("kerogen",))


def sensible_solid(name: str = "ash", cp: float = 1000.0) -> Thermochemistry:
    """A solid with sensible heat only (the recycled ash: its reactions are irreversible).

    Parameters
    ----------
    name : str
        Name of the solid.
    cp : float, J/(kg K)
        Heat capacity, > 0.

    Returns
    -------
    Thermochemistry
        Enthalpy :math:`c_p (T - 298.15)` J/kg, no reactions.

    Examples
    --------
    >>> round(float(sensible_solid().enthalpy(1298.15)), 1)
    1000000.0

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, ch. 9.
    """
    return Thermochemistry(name, cp, {}, ())
