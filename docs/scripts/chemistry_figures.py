"""Figures and numbers of docs/chemistry.md, docs/studies.md and docs/validation.md.

Run: PYTHONPATH=src MPLBACKEND=Agg python docs/scripts/chemistry_figures.py
Writes docs/figures/chemistry_*.png and prints the numbers quoted in the docs.
"""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy.special import gamma  # noqa: E402

from rotarykiln.cases import builtin_case  # noqa: E402
from rotarykiln.chemistry.calcination import (  # noqa: E402
    baker_co2_equilibrium_pressure,
    garcia_labiano_co2_equilibrium_pressure,
)
from rotarykiln.chemistry.mechanism import Mechanism  # noqa: E402
from rotarykiln.chemistry.plugflow import integrate_plug_flow  # noqa: E402
from rotarykiln.chemistry.segregated import kiln_segregated_conversion  # noqa: E402
from rotarykiln.studies import run_sweep  # noqa: E402
from rotarykiln.studies.ahmad2006 import ahmad_chapter5_design  # noqa: E402
from rotarykiln.studies.examples import ortiz_isothermal_burn_off  # noqa: E402

OUT = Path(__file__).resolve().parents[1] / "figures"
OUT.mkdir(exist_ok=True)

# An assumed limestone bed temperature profile (NOT a kiln solution): 550 K in, 900 K at 1 m,
# 1200 K at 3 m, 1600 K at the outlet: the shape seed 004 describes in words.
L, t_res = 5.5, 5400.0
zT = np.array([0.0, 1.0, 3.0, 4.0, 5.5])
TT = np.array([550.0, 900.0, 1200.0, 1450.0, 1600.0])
feed = {"CaCO3": 0.9 * 42 / 3600, "H2O(l)": 0.1 * 42 / 3600}

# 1. calcination along z: Luisser vs equilibrium-limited (p_CO2 = 0.2 and 1 atm)
fig, ax = plt.subplots(figsize=(5.5, 3.6))
for name, pco2, label in [
    ("calcination_luisser", 0.0, "Luisser (seed 004)"),
    ("calcination_equilibrium", 0.2 * 101325, "equilibrium, p_CO2 = 0.2 atm"),
    ("calcination_equilibrium", 101325.0, "equilibrium, p_CO2 = 1 atm"),
]:
    mech = Mechanism.builtin(name)
    res = integrate_plug_flow(mech, feed, L, L / t_res, (zT, TT), partial_pressure={"CO2": pco2})
    x = res.conversion("CaCO3")
    i5 = np.argmax(x > 0.01)
    i99 = np.argmax(x > 0.99)
    print(
        f"{label}: X > 1 % at z = {res.z[i5]:.2f} m (T = {res.T_bed[i5]:.0f} K), "
        f"X > 99 % at z = {res.z[i99]:.2f} m, X_out = {x[-1]:.5f}"
    )
    ax.plot(res.z, x, label=label)
ax2 = ax.twinx()
ax2.plot(zT, TT, "k:", lw=1)
ax2.set_ylabel("assumed T_bed [K] (dotted)")
ax.set_xlabel("z [m]")
ax.set_ylabel("CaCO3 conversion [-]")
ax.legend(fontsize="small", loc="center right")
fig.tight_layout()
fig.savefig(OUT / "chemistry_calcination_profile.png", dpi=90)
plt.close(fig)

# 2. equilibrium pressure correlations
T = np.linspace(950.0, 1300.0, 100)
fig, ax = plt.subplots(figsize=(5.0, 3.4))
ax.semilogy(T, baker_co2_equilibrium_pressure(T) / 101325, label="Baker (1962)")
p_gl = garcia_labiano_co2_equilibrium_pressure(T) / 101325
ax.semilogy(T, p_gl, "--", label="Garcia-Labiano (2002)")
ax.axhline(1.0, color="grey", lw=0.8)
ax.axvline(1173.6, color="grey", lw=0.8)
ax.set_xlabel("T [K]")
ax.set_ylabel("p_eq CO2 [atm]")
ax.legend(fontsize="small")
fig.tight_layout()
fig.savefig(OUT / "chemistry_co2_equilibrium.png", dpi=90)
plt.close(fig)

# 3. segregated flow vs plug flow over a tanks-in-series RTD (N = 10 and 40). With the hot
# profile above calcination is complete either way; a colder kiln (peak 880 K, Luisser kinetics
# are fast) leaves CaCO3 unconverted and shows the RTD effect.
mech = Mechanism.builtin("calcination_luisser")
T_cold = np.array([550.0, 750.0, 820.0, 860.0, 880.0])
for label, prof in [("hot", (zT, TT)), ("cold", (zT, T_cold))]:
    for N in (10, 40):
        E = lambda t, N=N: (N / t_res) ** N * t ** (N - 1) * np.exp(-N * t / t_res) / gamma(N)  # noqa: E731
        res = kiln_segregated_conversion(
            mech, {"CaCO3": feed["CaCO3"]}, "CaCO3", L, E, prof, t_max=4 * t_res, n=2001, n_tau=30
        )
        print(
            f"{label} profile, tanks-in-series N = {N}: plug X = {res.plug:.5f}, "
            f"segregated X = {res.segregated:.5f}"
        )
        if label == "cold" and N == 10:
            fig = res.plot()
            fig.axes[0].set_title("cold profile, tanks-in-series N = 10", fontsize="small")
            fig.set_size_inches(5.5, 3.6)
            fig.tight_layout()
            fig.savefig(OUT / "chemistry_segregated_flow.png", dpi=90)
            plt.close(fig)

# 4. chapter-5 design with the isothermal stand-in model
case = builtin_case("charcoal_activation")
case["standin"] = {"reaction_zone_temperature": "1150 K"}
sweep = run_sweep(ortiz_isothermal_burn_off, case, ahmad_chapter5_design(), max_workers=2)
print(
    "chapter-5 stand-in sweep:",
    len(sweep.frame),
    "cases,",
    sweep.n_failed,
    "failed,",
    f"{sweep.wall_time:.2f} s",
)
sweep.save_plot(OUT / "studies_chapter5_standin.png", outputs=["burn_off"])
