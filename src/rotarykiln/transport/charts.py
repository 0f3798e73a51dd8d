r"""Design charts for a user kiln, like Boateng's Figs. 2.7/2.8 (McTait et al. 1995).

Against the relative bed depth :math:`y/R` of a uniform bed: the dimensionless residence time
(eq. 2.15) and flow (eqs. 2.16 and 2.17, corrected), and in physical units the mean residence
time (surface-path, eq. 2.15, and hold-up based, :math:`LA_s/q` with the uniform-bed flow of
eq. 2.17), the volumetric and mass flow that keeps that depth, and the spread of the path
residence times (the flux-weighted standard deviation of :math:`L/u(r)` over the paths, a
reproducible stand-in for McTait's undefined variance; notes 002 section 2.5, speculative).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

from rotarykiln.tables import with_units
from rotarykiln.transport.saeman import (
    mctait_flow_dimensionless,
    mctait_residence_time_dimensionless,
    mctait_uniform_flow_dimensionless,
)

__all__ = ["DesignChart", "design_chart"]


@dataclass(frozen=True)
class DesignChart:
    """Chart data (SI): ``y_over_r``, ``fill``, ``tau_d``, ``q_d`` (2.16), ``q_d_uniform``
    (2.17), ``residence_time`` (s, eq. 2.15), ``residence_time_holdup`` (s), ``flow`` (m3/s,
    eq. 2.16 with q tau = L A), ``mass_flow`` (kg/s or None), ``residence_time_std`` (s)."""

    y_over_r: np.ndarray
    fill: np.ndarray
    tau_d: np.ndarray
    q_d: np.ndarray
    q_d_uniform: np.ndarray
    residence_time: np.ndarray
    residence_time_holdup: np.ndarray
    flow: np.ndarray
    mass_flow: np.ndarray | None
    residence_time_std: np.ndarray
    title: str = ""

    def to_frame(self) -> pd.DataFrame:
        import pandas as pd

        d = {
            "y_over_r": self.y_over_r,
            "fill": self.fill,
            "tau_d": self.tau_d,
            "q_d": self.q_d,
            "q_d_uniform": self.q_d_uniform,
            "residence_time_s": self.residence_time,
            "residence_time_holdup_s": self.residence_time_holdup,
            "flow_m3_s": self.flow,
            "residence_time_std_s": self.residence_time_std,
        }
        if self.mass_flow is not None:
            d["mass_flow_kg_s"] = self.mass_flow
        return with_units(pd.DataFrame(d), "transport.design_chart")

    def plot(self, ax=None):
        """Two panels: dimensionless groups, and residence time with its spread. Returns Figure."""
        import matplotlib.pyplot as plt

        if ax is None:
            fig, ax = plt.subplots(1, 2, figsize=(9, 3.5))
        fig = ax[0].figure
        a, b = ax
        a.plot(self.y_over_r, self.tau_d, label=r"$\bar\tau_d$ (2.15)")
        a.plot(self.y_over_r, self.q_d, label="$q_d$ (2.16)")
        a.plot(self.y_over_r, self.q_d_uniform, "--", label="$q_d$ uniform (2.17)")
        a.set_xlabel("y/R")
        a.set_ylabel("dimensionless")
        a.legend(fontsize=8)
        m = self.residence_time / 60
        b.plot(self.y_over_r, m, label="mean (2.15)")
        b.plot(self.y_over_r, self.residence_time_holdup / 60, "--", label="hold-up / flow")
        s = self.residence_time_std / 60
        t = self.residence_time_holdup / 60
        b.fill_between(self.y_over_r, t - s, t + s, alpha=0.2, label="path spread (1 sd)")
        b.set_xlabel("y/R")
        b.set_ylabel("residence time (min)")
        b.legend(fontsize=8)
        fig.suptitle(self.title, fontsize=9)
        fig.tight_layout()
        return fig


def design_chart(length, diameter, speed, slope, repose, *, density=None, n=50):
    r"""Design chart data for a kiln (uniform bed, no dam).

    Parameters
    ----------
    length, diameter : float, m
    speed : float, rad/s
    slope : float, rad
    repose : float, rad
        Dynamic angle of repose.
    density : float, kg/m3, optional
    n : int
        Number of depths in (0, 1].

    Returns
    -------
    DesignChart

    Examples
    --------
    Boateng's kiln (3.66 m, L/D 10, 3 deg, 40 deg, 1 rpm) at half fill: 61.3 min (eq. 2.15)

    >>> c = design_chart(36.6, 3.66, np.pi / 30, np.radians(3), np.radians(40), n=10)
    >>> round(float(c.residence_time[-1] / 60), 1)
    61.3
    """
    y = np.linspace(1.0 / n, 1.0, n)
    th = np.arcsin(np.sqrt((2 - y) * y))
    fill = (th - np.sin(th) * np.cos(th)) / np.pi
    rps = speed / (2 * np.pi)
    scale_t = length * np.sin(repose) / (rps * diameter * np.tan(slope))
    scale_q = rps * diameter**3 * np.tan(slope) / np.sin(repose)
    tau_d = mctait_residence_time_dimensionless(y)
    q_d = mctait_flow_dimensionless(y)
    q_u = mctait_uniform_flow_dimensionless(y)
    area = np.pi * diameter**2 / 4 * fill
    t_hold = length * area / (q_u * scale_q)
    # spread of path residence times L/u(r), weighted by the flux through each path
    radius = diameter / 2
    u = np.linspace(0.0, 1.0, 401)[1:]
    stds = np.empty(n)
    for k, r_o in enumerate(radius * (1 - y)):
        r = r_o + (radius - r_o) * u
        chord = 2 * np.sqrt(np.maximum(r * r - r_o * r_o, 0.0))
        vel = rps * chord * np.tan(slope) / np.sin(repose) * np.pi / np.arcsin(chord / (2 * r))
        w = chord * r
        tr = length / vel
        mean = np.sum(w * tr) / np.sum(w)
        stds[k] = np.sqrt(np.sum(w * (tr - mean) ** 2) / np.sum(w))
    return DesignChart(
        y_over_r=y,
        fill=fill,
        tau_d=tau_d,
        q_d=q_d,
        q_d_uniform=q_u,
        residence_time=tau_d * scale_t,
        residence_time_holdup=t_hold,
        flow=q_d * scale_q,
        mass_flow=None if density is None else q_d * scale_q * density,
        residence_time_std=stds,
        title=f"L {length:g} m, D {diameter:g} m, slope {np.degrees(slope):.3g} deg, "
        f"repose {np.degrees(repose):.3g} deg, {speed * 30 / np.pi:.3g} rpm",
    )
