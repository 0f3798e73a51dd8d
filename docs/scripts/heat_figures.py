"""Figures and the per-run table of docs/heat.md and docs/validation.md.

Run from the repository root:  PYTHONPATH=src python docs/scripts/heat_figures.py
Writes docs/figures/heat_*.png and prints the markdown table of the 44 Tscheng runs.
"""

import sys
import warnings
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from rotarykiln.case import load_case  # noqa: E402
from rotarykiln.cases import builtin_case_path  # noqa: E402
from rotarykiln.kiln import solve_kiln  # noqa: E402
from rotarykiln.kiln.from_case import kiln_from_case  # noqa: E402
from rotarykiln.studies.tscheng1978 import tscheng_runs  # noqa: E402

# the scoring of the validation test: each run is its built-in case (tests/validation/)
sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tests" / "validation"))
from tscheng_scoring import WINDOW, score, solve_run  # noqa: E402

OUT = Path("docs/figures")
warnings.simplefilter("ignore")


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    # 1. one run with its measurements
    sol = solve_run("A16")
    fig = sol.plot()
    fig.axes[0].axvspan(*WINDOW, color="0.9", zorder=0)
    fig.savefig(OUT / "kiln_tscheng_A16.png", dpi=90, bbox_inches="tight")
    plt.close(fig)

    # 2. parity of all 44 runs, and the per-run table
    fig, axes = plt.subplots(1, 2, figsize=(9, 4.2))
    rows = []
    for run in tscheng_runs().index:
        s = solve_run(run)
        m = s.measurements
        z = m["z_bed"]  # bed and gas are read at the same positions
        win = (z >= WINDOW[0] - 1e-9) & (z <= WINDOW[1] + 1e-9)
        rows.append(score(run, s))
        for ax, key, fn in (
            (axes[0], "bed", s.bed_temperature_at),
            (axes[1], "gas", s.gas_temperature_at),
        ):
            pred = fn(z)
            ax.plot(m[f"t_{key}"][~win], pred[~win], "o", mfc="none", color="0.6", ms=4)
            ax.plot(m[f"t_{key}"][win], pred[win], "o", color="tab:red", ms=4)
    for ax, key in zip(axes, ("bed", "gas"), strict=True):
        lo, hi = ax.get_xlim()
        ax.plot([lo, hi], [lo, hi], "k-", lw=0.8)
        ax.set_xlabel(f"measured {key} temperature (K)")
        ax.set_ylabel(f"predicted {key} temperature (K)")
        ax.set_title(f"{key}: red = 1.25-1.78 m window, grey = other points")
    fig.tight_layout()
    fig.savefig(OUT / "kiln_tscheng_parity.png", dpi=80)
    plt.close(fig)

    # 3. flame case, radiation on and off
    kiln, cells = kiln_from_case(load_case(builtin_case_path("ubc_pilot_flame")))
    on = solve_kiln(kiln, cells)
    off = solve_kiln(kiln.replace(closures__radiation=False), cells)
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for sol_, ls, lab in ((on, "-", "radiation on"), (off, "--", "radiation off")):
        ax.plot(sol_.z_nodes, sol_.t_gas_nodes, ls, color="tab:red", label=f"gas, {lab}")
        ax.plot(sol_.z_nodes, sol_.t_bed_nodes, ls, color="tab:brown", label=f"bed, {lab}")
        ax.plot(sol_.z, sol_.t_wall, ls, color="tab:gray", label=f"wall, {lab}")
    ax.set_xlabel("z from solids inlet (m)")
    ax.set_ylabel("temperature (K)")
    ax.set_title("UBC-geometry pilot kiln, natural gas burner at z = 5.5 m")
    ax.legend(fontsize=7, ncol=2)
    fig.savefig(OUT / "kiln_flame_radiation.png", dpi=90, bbox_inches="tight")
    plt.close(fig)

    print("| run | bed window | gas window | bed all | gas all | wall all |")
    print("|---|---|---|---|---|---|")
    for r in rows:
        print(
            f"| {r.run} | {r.bed_window:.1f} | {r.gas_window:.1f} | {r.bed_all:.1f} | "
            f"{r.gas_all:.1f} | {r.wall_all:.1f} |"
        )
    mean = {
        k: np.mean([getattr(r, k) for r in rows])
        for k in ("bed_window", "gas_window", "bed_all", "gas_all", "wall_all")
    }
    print(
        f"| **mean** | **{mean['bed_window']:.2f}** | **{mean['gas_window']:.2f}** | "
        f"**{mean['bed_all']:.2f}** | **{mean['gas_all']:.2f}** | **{mean['wall_all']:.2f}** |"
    )
    dz = on.z[1] - on.z[0]
    for name, s_ in (("on", on), ("off", off)):
        print(
            name,
            {k: round(v, 4) if isinstance(v, float) else v for k, v in s_.summary().items()},
            "rad to bed W",
            round(float(np.sum(s_.fluxes["q_rad_to_bed"]) * dz)),
            "conv to bed W",
            round(float(np.sum(s_.fluxes["q_gas_bed_conv"]) * dz)),
            "cw to bed W",
            round(float(np.sum(s_.fluxes["q_covered_wall_bed"]) * dz)),
        )


if __name__ == "__main__":
    main()
