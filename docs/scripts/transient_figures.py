"""Figures and numbers of docs/transient.md: a cold start-up of Barr's kiln (T4 inputs) and a
feed step of the fired limestone kiln.

Run: PYTHONPATH=src MPLBACKEND=Agg python docs/scripts/transient_figures.py
Writes docs/figures/transient_*.png and prints the time constants.
"""

import warnings
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from rotarykiln.case import load_case  # noqa: E402
from rotarykiln.cases import builtin_case_path  # noqa: E402
from rotarykiln.kiln.from_case import kiln_from_case  # noqa: E402
from rotarykiln.kiln.transient.integrate import simulate  # noqa: E402
from rotarykiln.transient_file import parse_transient  # noqa: E402

OUT = Path(__file__).resolve().parents[1] / "figures"
OUT.mkdir(exist_ok=True)
warnings.simplefilter("ignore")

#: ASSUMED lining heat capacities of Barr's kiln (the source gives conductivities only): an
#: insulating castable of 1300 kg/m3 (k = 0.25-0.4 W/(m K) is that class) and a steel shell.
BARR_WALL = {
    "layers": [
        {"density": "1300 kg/m3", "specific_heat": "1000 J/kg/K"},
        {"density": "7850 kg/m3", "specific_heat": "490 J/kg/K"},
    ]
}
#: ASSUMED heat capacity of the limestone kiln's U-value wall: 150 mm of refractory brick.
LIME_WALL = {"thickness": "150 mm", "density": "2100 kg/m3", "specific_heat": "1000 J/kg/K"}


def time_constant(t, y, t0=0.0):
    """Time (s) after ``t0`` to reach 63.2 % of the change from y(t0) to the last value."""
    keep = t >= t0
    t, y = t[keep], y[keep]
    target = y[0] + (1.0 - np.exp(-1.0)) * (y[-1] - y[0])
    above = (y - target) * np.sign(y[-1] - y[0]) >= 0
    return float(t[np.argmax(above)] - t0)


def save(fig, name):
    fig.savefig(OUT / name, dpi=110, bbox_inches="tight")
    plt.close(fig)


def barr_cold_start():
    kiln, cells = kiln_from_case(load_case(builtin_case_path("barr_T4")))
    until = 12 * 3600.0
    tr = parse_transient({"start": "cold", "wall": BARR_WALL, "output_every": "5 min"}, kiln, until)
    sol = simulate(kiln, cells, tr, until)
    save(sol.plot_heatmap(), "transient_barr_startup_heatmap.png")
    save(sol.plot_outlets(), "transient_barr_startup_outlets.png")
    df = sol.outlet_frame()
    t = df["t_s"].to_numpy()
    rho_c, d, k = 1300.0 * 1000.0, 0.093, 0.3
    out = {
        "wall time (s)": sol.wall_time,
        "solids residence time (h)": sol.summary()["solids_residence_time_s"] / 3600,
        "gas residence time (s)": sol.summary()["gas_residence_time_s"],
        "bed outlet tau63 (h)": time_constant(t, df["bed_outlet_temperature_K"].to_numpy()) / 3600,
        "gas outlet tau63 (h)": time_constant(t, df["gas_outlet_temperature_K"].to_numpy()) / 3600,
        "shell loss tau63 (h)": time_constant(t, df["shell_loss_W"].to_numpy()) / 3600,
        "refractory rho c d^2 / k (h)": rho_c * d * d / k / 3600,
        "bed outlet at 1 h, 12 h (K)": (
            float(np.interp(3600, t, df["bed_outlet_temperature_K"])),
            float(df["bed_outlet_temperature_K"].iloc[-1]),
        ),
        "energy closure": float(sol.energy_conservation()[-1]),
    }
    print("Barr T4 cold start-up:", out)


def limestone_feed_step():
    kiln, cells = kiln_from_case(load_case(builtin_case_path("limestone_fired")))
    until = 40 * 3600.0
    spec = {
        "wall": LIME_WALL,
        "events": [{"at": "1 h", "variable": "feed", "to": "84 kg/h"}],
        "output_every": "5 min",
    }
    tr = parse_transient(spec, kiln, until)
    sol = simulate(kiln, cells, tr, until)
    save(sol.plot_heatmap(), "transient_limestone_feedstep_heatmap.png")
    df = sol.outlet_frame()
    t = df["t_s"].to_numpy()
    left = df["bed_out_CaCO3_kg_s"].clip(lower=0.0)  # -1e-9 kg/s: the integrator's tolerance
    conv = 1.0 - left / (left + df["bed_out_CaO_kg_s"] * 100.09 / 56.08)
    fig, (a0, a1) = plt.subplots(1, 2, figsize=(11, 4.2))
    th = t / 3600.0
    a0.plot(th, df["bed_outlet_temperature_K"], color="tab:brown", label="solids discharge")
    a0.plot(th, df["gas_outlet_temperature_K"], color="tab:red", label="gas outlet")
    a0.plot(th, sol.t_wall[:, :, 0].mean(-1), color="tab:purple", ls="--", label="wall, mean")
    a0.set_xlabel("time (h)")
    a0.set_ylabel("temperature (K)")
    a0.legend(fontsize=8)
    a1.plot(th, 100.0 * conv, color="k")
    a1.set_xlabel("time (h)")
    a1.set_ylabel("calcination at the discharge (%)")
    fig.suptitle("limestone_fired: feed 42 -> 84 kg/h at 1 h")
    fig.tight_layout()
    save(fig, "transient_limestone_feedstep_outlets.png")
    s = sol.summary()
    out = {
        "wall time (s)": sol.wall_time,
        "solids residence time (h)": s["solids_residence_time_s"] / 3600,
        "bed outlet tau63 after the step (h)": time_constant(
            t, df["bed_outlet_temperature_K"].to_numpy(), 3600.0
        )
        / 3600,
        "gas outlet tau63 after the step (h)": time_constant(
            t, df["gas_outlet_temperature_K"].to_numpy(), 3600.0
        )
        / 3600,
        "conversion before, min, end (%)": (
            float(100 * conv.iloc[0]),
            float(100 * conv.min()),
            float(100 * conv.iloc[-1]),
        ),
        "bed outlet before, end (K)": (
            float(df["bed_outlet_temperature_K"].iloc[0]),
            float(df["bed_outlet_temperature_K"].iloc[-1]),
        ),
        "wall C/U (h)": 0.15 * 2100 * 1000 / kiln.wall.loss_u / 3600,
        "energy closure": float(sol.energy_conservation()[-1]),
        "element closure": max(sol.element_conservation().values()),
    }
    print("limestone_fired feed step:", out)


if __name__ == "__main__":
    barr_cold_start()
    limestone_feed_step()
