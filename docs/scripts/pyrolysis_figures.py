"""Figures of docs/pyrolysis.md: run ``PYTHONPATH=src python docs/scripts/pyrolysis_figures.py``.

The rotaryPyrolysis default case (cases/rotary_pyrolysis.yaml), ours (solid lines) over the
anchor script's profiles (dots): plug flow (the override ``bed.axial_dispersion: plug``), and the
RTD (ours: the case as given, axial dispersion at Pe 5 inside the balances; the script: 41
segregated classes at one bed temperature).
"""

from __future__ import annotations

import warnings
from importlib.resources import files
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402

from rotarykiln.case import load_case  # noqa: E402
from rotarykiln.cases import builtin_case_path  # noqa: E402
from rotarykiln.errors import OutOfRangeWarning  # noqa: E402
from rotarykiln.kiln.from_case import kiln_from_case  # noqa: E402
from rotarykiln.kiln.steady.solve import solve_kiln  # noqa: E402

OUT = Path(__file__).resolve().parents[1] / "figures"
ANCHOR = pd.read_csv(
    files("rotarykiln.data") / "rotary_pyrolysis" / "rotary_pyrolysis_anchor_profiles.csv"
)


def main():
    warnings.simplefilter("ignore", OutOfRangeWarning)
    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5), sharex=True)
    pyrolysis = load_case(builtin_case_path("rotary_pyrolysis"))
    for col, (case, changes, title) in enumerate(
        (
            ("plug_flow_nt1", {"bed.axial_dispersion": "plug"}, "plug flow"),
            ("adm_Pe5_nt40", {}, "RTD, Pe 5 (ours: dispersion in the balances)"),
        )
    ):
        kiln, cells = kiln_from_case(pyrolysis.replace(changes))
        sol = solve_kiln(kiln, cells)
        ref = ANCHOR[ANCHOR["case"] == case]
        jacket = sol.fluxes["x"][:, 3]
        ax = axes[0, col]
        ax.plot(sol.z_nodes, sol.t_bed_nodes, color="tab:brown", label="bed")
        ax.plot(sol.z_nodes, sol.t_gas_nodes, color="tab:blue", label="gas")
        ax.plot(sol.z_nodes[1:], jacket, color="tab:red", label="jacket gas (= wall)")
        ax.plot(ref["z_m"], ref["T_bed_K"], "o", color="tab:brown", ms=4, label="anchor bed")
        ax.plot(ref["z_m"], ref["T_gas_K"], "o", color="tab:blue", ms=4, label="anchor gas")
        ax.plot(ref["z_m"], ref["T_wall_K"], "o", color="tab:red", ms=4, label="anchor wall")
        ax.set_title(title)
        ax.set_ylabel("temperature (K)")
        ax = axes[1, col]
        for name, column, colour in (
            ("wood", "F_dry_wood_kg_h", "tab:olive"),
            ("intermediate_solid", "F_intermediate_solid_kg_h", "tab:orange"),
            ("char", "F_char_kg_h", "black"),
            ("tar(l)", "F_reactive_tar_in_bed_kg_h", "tab:purple"),
        ):
            ax.plot(sol.z_nodes, 3600 * sol.bed_flows[name], color=colour, label=name)
            anchor = ref[column] + (ref["F_wet_wood_kg_h"] if name == "wood" else 0.0)
            ax.plot(ref["z_m"], anchor, "o", color=colour, ms=4)
        ax.set_xlabel("z from the feed end (m)")
        ax.set_ylabel("bed species flow (kg/h)")
    axes[0, 0].legend(fontsize=8, ncol=2)
    axes[1, 0].legend(fontsize=8)
    fig.suptitle("rotaryPyrolysis default case: rotarykiln (lines) and the anchor script (dots)")
    fig.tight_layout()
    OUT.mkdir(exist_ok=True)
    fig.savefig(OUT / "pyrolysis_rotary_pyrolysis.png", dpi=110)


if __name__ == "__main__":
    main()
