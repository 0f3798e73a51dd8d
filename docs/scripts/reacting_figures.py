"""Figures and numbers of docs/reacting.md and docs/validation.md.

Run: PYTHONPATH=src MPLBACKEND=Agg python docs/scripts/reacting_figures.py
Writes docs/figures/reacting_*.png and docs/figures/reacting_chapter5.csv, prints the numbers.
"""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import yaml  # noqa: E402

from rotarykiln.case import parse_case  # noqa: E402
from rotarykiln.cases import builtin_case_path  # noqa: E402
from rotarykiln.commands.kiln_runs import bed_peclet  # noqa: E402
from rotarykiln.kiln.bed.residence import residence_time_effects  # noqa: E402
from rotarykiln.kiln.from_case import kiln_from_case  # noqa: E402
from rotarykiln.kiln.steady.solve import solve_kiln  # noqa: E402
from rotarykiln.outputs import write_frame_atomic  # noqa: E402
from rotarykiln.studies.ahmad2006 import chapter5_directions, run_chapter5  # noqa: E402

OUT = Path(__file__).resolve().parents[1] / "figures"
OUT.mkdir(exist_ok=True)


def _data(name):
    return yaml.safe_load(builtin_case_path(name).read_text(encoding="utf-8"))


def solve(data):
    case = parse_case(data)
    kiln, cells = kiln_from_case(case)
    return case, kiln, solve_kiln(kiln, cells)


for name in ("charcoal_activation", "limestone_calcination"):
    case, kiln, sol = solve(_data(name))
    fig = sol.plot()
    fig.savefig(OUT / f"reacting_{name}.png", dpi=80)
    plt.close(fig)
    print(name)
    for k, v in sol.summary().items():
        print(f"  {k}: {v}")
    rtd = residence_time_effects(kiln, sol, peclet=bed_peclet(case, sol.residence_time)[0])
    print("  ", rtd.summary())
    fig = rtd.plot()
    fig.savefig(OUT / f"kiln_rtd_{name}.png", dpi=80)
    plt.close(fig)

# residence-time effects with incomplete calcination: less gas (0.018 kg/s), Sherritt Pe and Pe 20
for pe in (None, 20.0):
    data = _data("limestone_calcination")
    data["gas"]["flow"] = "0.018 kg/s"
    if pe is not None:
        data["chemistry"]["peclet"] = pe
    case, kiln, sol = solve(data)
    rtd = residence_time_effects(kiln, sol, peclet=bed_peclet(case, sol.residence_time)[0])
    print("limestone 0.018 kg/s gas, Pe", pe, rtd.summary())
    if pe is not None:
        fig = rtd.plot()
        fig.savefig(OUT / "kiln_rtd_limestone_partial.png", dpi=80)
        plt.close(fig)

# limestone with the CO2-equilibrium rate
data = _data("limestone_calcination")
data["chemistry"]["reactions"] = ["drying_ahmad", "calcination_equilibrium"]
data["name"] = "limestone, equilibrium rate"
_, _, sol = solve(data)
print("limestone equilibrium:", {k: v for k, v in sol.summary().items() if "CaCO3" in k})
print("  bed max", sol.t_bed_nodes.max(), "gas out", sol.gas_outlet_temperature)
fig = sol.plot()
fig.savefig(OUT / "kiln_limestone_equilibrium.png", dpi=80)
plt.close(fig)

# seed 004 chapter 5 on the kiln model
res = run_chapter5(max_workers=2)
keep = [c for c in res.frame.columns if c.endswith("[SI]")] + [
    "group",
    "burn_off_percent",
    "production_percent",
    "bed_max_temperature_K",
    "gas_outlet_temperature_K",
]
write_frame_atomic(OUT / "kiln_chapter5.csv", res.frame[keep], index=False)
print(chapter5_directions(res))
fig = res.plot(outputs=["burn_off_percent", "production_percent"])
fig = fig if hasattr(fig, "savefig") else fig.figure
fig.set_size_inches(14, 5)
fig.savefig(OUT / "kiln_chapter5.png", dpi=70)
plt.close(fig)
