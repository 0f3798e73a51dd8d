r"""Numerical solution of the axial dispersion equation for an arbitrary inlet signal.

.. math::

    \frac{\partial C}{\partial\theta} = \frac{1}{Pe}\frac{\partial^2 C}{\partial z^2}
        - \frac{\partial C}{\partial z} + \delta(z)\,c_{in}(\theta)\ [\text{open}],

solved by the method of lines: a conservative vertex-centred finite-volume grid (central fluxes,
second order, nodes on z = 0 and z = 1) integrated in time by an adaptive implicit BDF scheme
(``scipy.integrate.solve_ivp``), restarted at every discontinuity of the inlet signal.

Boundaries:

- ``"closed-closed"`` (Danckwerts): the feed flux :math:`C - C_z/Pe = c_{in}` enters at z = 0,
  :math:`C_z = 0` at z = 1; the response is the outlet concentration (= flux).
- ``"open-open"``: the domain is extended upstream and downstream by ``40/Pe + 0.2`` (beyond which
  the tracer concentration is below ~e^-40 of its peak), the tracer enters as a plane source at
  z = 0 and the response is the concentration at z = 1.

With a unit-area inlet signal of mean :math:`\mu_{in}` and variance :math:`\sigma^2_{in}`, the
response has mean :math:`\mu_{in} + \bar\theta` and variance :math:`\sigma^2_{in} + \sigma^2_\theta`
of the model (moments of a convolution add); the tests check this against the closed forms.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd
from scipy import integrate, sparse

from rotarykiln.errors import ConvergenceError, InputError, check_positive
from rotarykiln.tables import with_units

__all__ = [
    "InletSignal",
    "PDEResult",
    "dirac_inlet",
    "pulse_inlet",
    "solve_dispersion_pde",
    "step_inlet",
]


@dataclass(frozen=True)
class InletSignal:
    """A tracer inlet signal in normalised time: piecewise constant ``levels`` on the intervals
    between ``breaks`` (the last level holds for ever), or a Dirac pulse of unit area.

    Use :func:`pulse_inlet`, :func:`step_inlet` or :func:`dirac_inlet` to build one.
    """

    breaks: tuple[float, ...]
    levels: tuple[float, ...]
    dirac: bool = False
    name: str = ""

    def level(self, theta: float) -> float:
        i = np.searchsorted(self.breaks, theta, side="right") - 1
        return float(self.levels[i]) if i >= 0 else 0.0


def pulse_inlet(width: float) -> InletSignal:
    """Rectangular pulse of unit area lasting ``width`` (normalised time t/tau, > 0).

    Examples
    --------
    >>> pulse_inlet(0.01).level(0.005)
    100.0
    """
    check_positive("width", width)
    return InletSignal((0.0, float(width)), (1.0 / width, 0.0), name=f"pulse of width {width:g}")


def step_inlet() -> InletSignal:
    """Unit step at theta = 0 (the response is F(theta))."""
    return InletSignal((0.0,), (1.0,), name="step")


def dirac_inlet() -> InletSignal:
    """Unit Dirac pulse at theta = 0 (the response is E(theta))."""
    return InletSignal((0.0,), (0.0,), dirac=True, name="dirac")


@dataclass(frozen=True)
class PDEResult:
    """Outlet response of the numerical dispersion model (normalised units)."""

    theta: np.ndarray
    outlet: np.ndarray
    peclet: float
    boundaries: str
    inlet: str
    n_nodes: int
    n_steps: int

    def to_frame(self) -> pd.DataFrame:
        import pandas as pd

        return with_units(
            pd.DataFrame({"theta": self.theta, "outlet": self.outlet}), "rtd.dispersion_pde"
        )

    def plot(self, ax=None):
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots()
        ax.plot(self.theta, self.outlet, label=f"{self.boundaries}, Pe = {self.peclet:g}")
        ax.set_xlabel(r"$\theta = t/\tau$")
        ax.set_ylabel("outlet response")
        ax.legend()
        return ax.figure


def _operator(pe: float, n: int, h: float, volumes: np.ndarray):
    """Sparse matrix of the semi-discrete system dC/dtheta = A C (interior faces + outlet)."""
    # flux across face j+1/2: (c_j + c_{j+1})/2 - (c_{j+1} - c_j)/(Pe h)
    a = 0.5 + 1.0 / (pe * h)  # weight of c_j (upstream node) in the face flux
    b = 0.5 - 1.0 / (pe * h)  # weight of c_{j+1}
    main = np.zeros(n)
    upper = np.zeros(n - 1)  # coefficient of c_{j+1} in row j
    lower = np.zeros(n - 1)  # coefficient of c_{j-1} in row j
    main[:-1] -= a  # out through the face on the right of j
    upper -= b
    main[1:] += b  # in through the face on the left of j
    lower += a
    main[-1] -= 1.0  # outlet face: pure convection (C_z = 0)
    mat = sparse.diags([lower, main, upper], [-1, 0, 1], format="csr")
    return sparse.diags(1.0 / volumes) @ mat


def solve_dispersion_pde(
    peclet: float,
    inlet: InletSignal,
    theta_end: float,
    *,
    boundaries: str = "closed-closed",
    cells_per_length: int = 800,
    n_out: int = 2001,
    rtol: float = 1e-9,
) -> PDEResult:
    r"""Outlet response of the axial dispersion equation to an arbitrary inlet signal.

    Parameters
    ----------
    peclet : float
        Peclet number uL/D [-].
    inlet : InletSignal
        Inlet signal in normalised time (:func:`pulse_inlet`, :func:`step_inlet`,
        :func:`dirac_inlet`).
    theta_end : float
        End of the simulation, t/tau [-].
    boundaries : {"closed-closed", "open-open"}
        Danckwerts boundaries, or an unbounded domain (see module docstring).
    cells_per_length : int
        Grid cells per kiln length; the cell Peclet number Pe/cells must stay below 2.
    n_out : int
        Number of equally spaced output times in [0, theta_end].
    rtol : float
        Relative tolerance of the time integrator.

    Returns
    -------
    PDEResult
        ``theta`` [-] and ``outlet`` response (E(theta) for a Dirac inlet, F(theta) for a step).

    Raises
    ------
    ConvergenceError
        If the time integrator fails.

    Examples
    --------
    >>> res = solve_dispersion_pde(10.0, dirac_inlet(), 6.0, cells_per_length=200, n_out=601)
    >>> round(float(np.trapezoid(res.outlet, res.theta)), 4)  # all the tracer leaves
    1.0

    References
    ----------
    Bongo Njeng, A. S. et al. (2015) Powder Technol. 269, 554-565, eq. 8; Danckwerts, P. V. (1953)
    Chem. Eng. Sci. 2, 1-13 (boundary conditions).
    """
    check_positive("peclet", peclet)
    check_positive("theta_end", theta_end)
    if boundaries not in ("closed-closed", "open-open"):
        raise InputError("boundaries", boundaries, "closed-closed or open-open")
    for name, value in (("cells_per_length", cells_per_length), ("n_out", n_out)):
        if not isinstance(value, int | np.integer) or value < 2:
            raise InputError(name, value, "an integer >= 2")
    check_positive("rtol", rtol)
    if peclet / cells_per_length >= 2.0:
        raise InputError(
            "cells_per_length",
            cells_per_length,
            f"> Pe/2 = {peclet / 2:g} (cell Peclet number below 2, no wiggles)",
        )
    h = 1.0 / cells_per_length
    ext = 0 if boundaries == "closed-closed" else int(np.ceil((40.0 / peclet + 0.2) / h))
    n = cells_per_length + 1 + 2 * ext
    volumes = np.full(n, h)
    volumes[[0, -1]] = h / 2
    mat = _operator(peclet, n, h, volumes)
    src = np.zeros(n)
    src[ext] = 1.0 / volumes[ext]  # feed at the inlet face (closed) or plane source at z = 0
    probe = ext + cells_per_length

    theta_out = np.linspace(0.0, theta_end, n_out)
    c = np.zeros(n)
    if inlet.dirac:
        c[ext] = 1.0 / volumes[ext]
    breaks = [b for b in inlet.breaks if 0.0 < b < theta_end] + [theta_end]
    outlet = np.zeros(n_out)
    outlet[0] = c[probe]
    start, n_steps = 0.0, 0
    for stop in breaks:
        level = inlet.level(start)
        forcing = src * level

        def rhs(_theta, y, forcing=forcing):
            return mat @ y + forcing

        sel = (theta_out > start) & (theta_out <= stop)
        times = np.union1d(theta_out[sel], [stop])
        sol = integrate.solve_ivp(
            rhs,
            (start, stop),
            c,
            method="BDF",
            jac=mat,
            t_eval=times,
            rtol=rtol,
            atol=rtol * 1e-3 * max(1.0, float(np.abs(c).max(initial=0.0)), abs(level)),
        )
        if not sol.success:
            raise ConvergenceError(
                f"dispersion PDE time integration failed: {sol.message}",
                location=f"theta in [{start:g}, {stop:g}]",
                evaluations=n_steps + int(sol.nfev),
            )
        outlet[sel] = sol.y[probe, : int(sel.sum())]
        n_steps += int(sol.nfev)
        c = sol.y[:, -1]
        start = stop
    return PDEResult(theta_out, outlet, float(peclet), boundaries, inlet.name, n, n_steps)
