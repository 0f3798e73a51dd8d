"""Scott's (1986) appendix tables A4.1-A4.16 and Table 5.1, shipped as CSV, and a runner.

The CSV files live in ``rotarykiln/data/scott1986/`` (provenance and OCR decisions in the
README.md there). :func:`scott1986_table` loads one table; :func:`scott1986_model_fill` runs the
model variant named in a row's ``model_variant`` column with that row's inputs.
"""

from __future__ import annotations

import warnings
from importlib import resources
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

from rotarykiln.errors import OutOfRangeWarning
from rotarykiln.transport.scott import bachmann_dynamic_angle, scott_profile
from rotarykiln.transport.weirs import Weir

__all__ = ["SCOTT1986_TABLES", "scott1986_table", "scott1986_model_fill", "VARIANTS"]

SCOTT1986_TABLES = tuple(f"a4_{k:02d}" for k in range(1, 17)) + ("table_5_1",)

#: model_variant column -> keyword arguments of :func:`scott_profile`
VARIANTS = {
    "scott": {},
    "mu0": {"friction": "zero"},
    "mu_dyn": {"friction": "dynamic"},
    "initvel_mu0": {"friction": "zero", "cascade": "initial_velocity"},
    "fixed_path": {"path": "fixed"},
    "bachmann": {},
}


def scott1986_table(name: str) -> pd.DataFrame:
    """Load one transcribed table, e.g. ``"a4_07"`` or ``"table_5_1"``.

    Examples
    --------
    >>> len(scott1986_table("a4_07"))
    16
    """
    import pandas as pd

    if name not in SCOTT1986_TABLES:
        raise KeyError(f"{name!r} is not one of {SCOTT1986_TABLES}")
    path = resources.files("rotarykiln.data").joinpath("scott1986", f"{name}.csv")
    with path.open("r", encoding="utf-8") as fh:
        return pd.read_csv(fh)


def scott1986_model_fill(row, *, sections: bool = False, beyond_half: str = "saturate"):
    """Run the model variant of one table row; return the mean filling in %.

    With ``sections=True`` (Table 5.1) return ``(inlet %, discharge %, overall %)``.
    ``beyond_half="saturate"`` (default here) reproduces the thesis program, which holds the
    local fill at 50 %. Warnings about the validated range (speeds above half critical in
    A4.11) are silenced: the thesis itself runs those points.
    """
    rpm = np.pi / 30.0
    radius = float(row["radius_m"])
    if "weir_radius_m" in row:  # Table 5.1 gives the speed as % of critical only
        omega = float(row["pct_critical"]) / 100.0 * np.sqrt(9.81 / radius)
    else:
        omega = float(row["speed_rpm"]) * rpm
    variant = row.get("model_variant", "scott")
    if not isinstance(variant, str) or not variant:
        variant = "scott"
    alpha_s = np.radians(float(row["alpha_s_deg"]))
    if variant == "bachmann":
        alpha_d = float(bachmann_dynamic_angle(alpha_s, omega, radius))
    else:
        alpha_d = np.radians(float(row["alpha_d_deg"]))
    weirs = []
    if "weir_radius_m" in row:
        weirs = [Weir(float(row["weir_position_m"]), float(row["weir_radius_m"]))]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OutOfRangeWarning)
        prof = scott_profile(
            float(row["feed_kg_s"]),
            density=float(row["density_kg_m3"]),
            length=float(row["length_m"]),
            radius=radius,
            speed=omega,
            slope=np.radians(float(row["slope_deg"])),
            dynamic_angle=alpha_d,
            static_angle=alpha_s,
            discharge_radius=float(row["rc_m"]),
            weirs=weirs,
            beyond_half=beyond_half,
            **VARIANTS[variant],
        )
    if sections:
        fills = [100.0 * f for _, _, f in prof.section_fills]
        return fills[-1], fills[0], 100.0 * prof.mean_fill
    return 100.0 * prof.mean_fill
