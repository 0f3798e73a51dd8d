"""The result of an axial bed-depth calculation: :class:`BedProfile`."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

from rotarykiln.tables import with_units

__all__ = ["BedProfile", "REGIONS"]

#: region codes used in :attr:`BedProfile.region`
REGIONS = ("transport", "limiting", "pool", "saturated")


@dataclass(frozen=True)
class BedProfile:
    """Axial bed profile of a rotating drum (all SI).

    Arrays are ordered from the feed end (``z = 0``) to the discharge end (``z = length``); at a
    weir the same ``z`` appears twice (the depth jumps).

    Attributes
    ----------
    model : str
        ``"kramers"`` or ``"scott"`` (with variant).
    z : array, m
        Distance from the feed end.
    depth : array, m
        Bed depth at the middle of the chord.
    radius : array, m
        Drum radius.
    half_angle : array, rad
        Half the angle subtended by the bed surface.
    fill : array, -
        Local fractional filling of the cross-section.
    bed_area : array, m2
        Bed cross-sectional area.
    residence_time : array, s
        Time for the solids to travel from the feed end to ``z``, :math:`\\int_0^z A/q\\,dz`.
    region : array of int
        0 transport (integrated), 1 limiting (uniform) filling, 2 pool behind a dam or weir,
        3 held at half fill (Scott's ``beyond_half="saturate"``).
    length : float, m
    volumetric_flow : float, m3/s
        Volumetric feed at the feed end.
    holdup_volume : float, m3
    density : float or None, kg/m3
    mean_fill : float, -
        Overall (length-averaged) filling.
    mean_residence_time : float, s
        Hold-up over flow, :math:`\\int A/q\\,dz`.
    discharge_radius : float, m
        Radius of the discharge opening (= drum radius when open).
    weirs : tuple of (position from discharge m, opening radius m)
    section_fills : tuple of (x_start m, x_end m, fill -)
        Per section between weirs, x measured from the discharge.
    limiting_depth : float or None, m
        Uniform (limiting) depth of an inclined drum, None if horizontal or none exists.
    """

    model: str
    z: np.ndarray
    depth: np.ndarray
    radius: np.ndarray
    half_angle: np.ndarray
    fill: np.ndarray
    bed_area: np.ndarray
    residence_time: np.ndarray
    region: np.ndarray
    length: float
    volumetric_flow: float
    holdup_volume: float
    mean_fill: float
    mean_residence_time: float
    density: float | None = None
    discharge_radius: float | None = None
    weirs: tuple = ()
    section_fills: tuple = ()
    limiting_depth: float | None = None
    info: dict = field(default_factory=dict)

    @property
    def holdup_mass(self) -> float | None:
        """Hold-up mass, kg (None when no density was given)."""
        return None if self.density is None else self.holdup_volume * self.density

    @property
    def discharge_fill(self) -> float:
        """Filling at the discharge end, -."""
        return float(self.fill[-1])

    @property
    def mean_residence_time_min(self) -> float:
        """Mean residence time in minutes (convenience for reports)."""
        return self.mean_residence_time / 60.0

    def summary(self) -> dict:
        """Scalar results keyed by name with the SI unit in the key."""
        out = {
            "model": self.model,
            "length_m": self.length,
            "volumetric_flow_m3_s": self.volumetric_flow,
            "mean_fill": self.mean_fill,
            "holdup_volume_m3": self.holdup_volume,
            "holdup_mass_kg": self.holdup_mass,
            "mean_residence_time_s": self.mean_residence_time,
            "discharge_fill": self.discharge_fill,
            "feed_end_fill": float(self.fill[0]),
            "discharge_depth_m": float(self.depth[-1]),
            "feed_end_depth_m": float(self.depth[0]),
            "limiting_depth_m": self.limiting_depth,
            "section_fills": [
                {"x_start_m": a, "x_end_m": b, "fill": f} for a, b, f in self.section_fills
            ],
        }
        out.update(self.info)
        return out

    def to_frame(self) -> pd.DataFrame:
        """One row per axial point."""
        import pandas as pd

        frame = pd.DataFrame(
            {
                "z_m": self.z,
                "x_from_discharge_m": self.length - self.z,
                "depth_m": self.depth,
                "radius_m": self.radius,
                "half_angle_rad": self.half_angle,
                "fill": self.fill,
                "bed_area_m2": self.bed_area,
                "residence_time_s": self.residence_time,
                "region": np.asarray(REGIONS, dtype=object)[self.region],
            }
        )
        return with_units(frame, f"transport.{self.model}")

    def plot(self, ax=None):
        """Draw the bed to scale along the drum (feed end left), with dams and weirs.

        Limiting-filling (uniform) regions are shaded green, pools behind dams blue.
        Returns the matplotlib Figure.
        """
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(8, 3))
        z = self.z
        ax.fill_between(z, 0.0, self.depth, color="tan", label="bed", zorder=2)
        ax.plot(z, 2 * self.radius, color="0.2", lw=1.5)
        ax.plot(z, 0 * z, color="0.2", lw=1.5)
        ax.plot(z, self.radius, color="0.6", lw=0.8, ls="-.", label="axis")
        r_end = float(self.radius[-1])
        if self.discharge_radius is not None and self.discharge_radius < r_end:
            h = r_end - self.discharge_radius
            ax.plot([self.length] * 2, [0, h], color="k", lw=4, label="dam")
            ax.plot([self.length] * 2, [2 * r_end - h, 2 * r_end], color="k", lw=4)
        for pos, rc in self.weirs:
            zw = self.length - pos
            rw = float(np.interp(zw, z, self.radius))
            ax.plot([zw] * 2, [0, rw - rc], color="k", lw=3)
            ax.plot([zw] * 2, [rw + rc, 2 * rw], color="k", lw=3)
        for code, colour, label in ((1, "tab:green", "limiting filling"), (2, "tab:blue", "pool")):
            mask = self.region == code
            if np.any(mask):
                idx = np.flatnonzero(mask)
                splits = np.flatnonzero(np.diff(idx) > 1) + 1
                for k, part in enumerate(np.split(idx, splits)):
                    ax.axvspan(
                        z[part[0]],
                        z[part[-1]],
                        color=colour,
                        alpha=0.15,
                        label=label if k == 0 else None,
                        zorder=1,
                    )
        if self.length / (2 * float(np.max(self.radius))) < 15:
            ax.set_aspect("equal")
        ax.set_xlim(0, self.length)
        ax.set_xlabel("distance from feed end z (m)")
        ax.set_ylabel("height (m)")
        ax.set_title(f"{self.model}: mean fill {100 * self.mean_fill:.2f} %", fontsize=9)
        ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5), frameon=False)
        return ax.figure
