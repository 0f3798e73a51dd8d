"""Figures of docs/rtd.md: run ``PYTHONPATH=src python docs/scripts/rtd_figures.py``."""

from __future__ import annotations

import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from rotarykiln.rtd.correlations import (  # noqa: E402
    bongo_njeng_dispersion,
    holdup_fraction,
    sai_dispersion_number,
    sherritt_dispersion,
)
from rotarykiln.rtd.dispersion import MODELS  # noqa: E402
from rotarykiln.rtd.fitting import fit_rtd, moment_method  # noqa: E402
from rotarykiln.rtd.internals import lifter_cross_section, loading_lifter_area  # noqa: E402
from rotarykiln.rtd.plots import parity_plot  # noqa: E402
from rotarykiln.rtd.reference_data import bongo_njeng_table  # noqa: E402

OUT = Path(__file__).resolve().parents[1] / "figures"
RPM = 2 * math.pi / 60
L, DIAM = 1.95, 0.1013


def models():
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.8), sharey=False)
    theta = np.linspace(0.001, 2.5, 600)
    for ax, pe in zip(axes, (10.0, 200.0), strict=True):
        for name in ("open-open", "open-closed", "closed-closed", "gaussian"):
            ax.plot(theta, MODELS[name].exit_age(theta, 1.0, pe), label=name)
        ax.plot(
            theta,
            MODELS["tanks-in-series"].exit_age(theta, 1.0, pe / 2),
            ":",
            label="tanks, N = Pe/2",
        )
        ax.set_title(f"Pe = {pe:g}")
        ax.set_xlabel(r"$\theta = t/\tau$")
        ax.set_ylabel(r"$E(\theta)$")
    axes[0].legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(OUT / "rtd_models.png", dpi=90)


def fit_example():
    # synthetic curve at the sand benchmark of Table 3 (replicate 1: 43.39 min, 6.91 min2),
    # sampled every 30 s with 3 % noise: the paper prints no E(t) data
    m = moment_method(43.39 * 60, 6.91 * 3600, convention="rigorous")
    t = np.arange(34.0, 53.0, 0.5) * 60
    rng = np.random.default_rng(4)
    e = MODELS["open-open"].exit_age(t, m.tau, m.peclet) * (1 + 0.03 * rng.standard_normal(t.size))
    fit = fit_rtd(t, e, length=L)
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4))
    fit.plot(a1)
    a1.set_title("synthetic sand benchmark: fit (solid), moments (dashed)", fontsize="small")
    mask = fit.data > 0.05 * fit.data.max()
    parity_plot(fit.data[mask] * 60, fit.fitted[mask] * 60, a2, quantity="E(t) [1/min]")
    fig.tight_layout()
    fig.savefig(OUT / "rtd_fit.png", dpi=90)


def parity():
    t3 = bongo_njeng_table("table3_replicates")
    mats = bongo_njeng_table("table2_materials").set_index("material")
    fig, ax = plt.subplots(figsize=(5, 5))
    groups = t3.groupby(["material", "speed_rpm", "slope_deg"], sort=False)
    series = {"Eq. 18, SL": [], "Eq. 18, RL": [], "Sherritt (16)": [], "Sai (15)": []}
    measured = []
    for (material, rpm, slope), g in groups:
        mrt, vrt = g["mrt_min"].mean() * 60, g["vrt_min2"].mean() * 3600
        measured.append(moment_method(mrt, vrt, length=L).dispersion)
        p = mats.loc[material]
        beta = math.radians(p["repose_angle_deg"])
        for lifter, arm in (("SL", 0.0), ("RL", 0.01)):
            ls = loading_lifter_area(4, lifter_cross_section(DIAM / 2, 0.01, beta, arm=arm))
            series[f"Eq. 18, {lifter}"].append(
                bongo_njeng_dispersion(
                    2.5 / 3600,
                    p["bulk_density_kg_m3"],
                    rpm * RPM,
                    math.radians(slope),
                    beta,
                    p["particle_size_mm"] / 1000,
                    ls,
                    DIAM,
                )
            )
        x = holdup_fraction(2.5 / 3600, mrt, p["bulk_density_kg_m3"], DIAM, L)
        series["Sherritt (16)"].append(
            sherritt_dispersion(rpm * RPM, DIAM, p["particle_size_mm"] / 1000, x)
        )
        tracer = mats.loc["NaCl"] if material == "sand" else p
        pe = 1 / sai_dispersion_number(
            math.radians(tracer["repose_angle_deg"]),
            math.radians(slope),
            rpm * RPM,
            tracer["bulk_density_kg_m3"],
        )
        series["Sai (15)"].append(L**2 / (pe * mrt))
    for label, pred in series.items():
        parity_plot(
            measured, pred, ax, label=label, quantity="D [m2/s]", log=True, limits=(3e-7, 2e-4)
        )
    ax.set_xlabel("D by moments, Table 3 replicates [m2/s]")
    ax.legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(OUT / "rtd_parity.png", dpi=90)


def lifters():
    r, beta = DIAM / 2, math.radians(39)
    gamma = np.linspace(-30, 90, 121)
    fig, ax = plt.subplots(figsize=(5.5, 3.8))
    for name, arm in (("straight (SL)", 0.0), ("rectangular (RL)", 0.01)):
        v = [
            lifter_cross_section(r, 0.01, beta, arm=arm, position=math.radians(g)) * L * 1e6
            for g in gamma
        ]
        ax.plot(gamma, v, label=name)
    ax.plot([0, 0], [75.8, 242.0], "ko", label="seed 003: 75.8 and 242 cm3")
    ax.set_xlabel("lifter position above the horizontal [deg]")
    ax.set_ylabel("hold-up per lifter over 1.95 m [cm3]")
    ax.legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(OUT / "rtd_lifters.png", dpi=90)


if __name__ == "__main__":
    OUT.mkdir(parents=True, exist_ok=True)
    models()
    fit_example()
    parity()
    lifters()
