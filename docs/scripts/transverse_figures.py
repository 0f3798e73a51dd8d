"""Figures and validation numbers of docs/transverse.md and docs/validation.md.

Run from the repository root:  PYTHONPATH=src python docs/scripts/transverse_figures.py
"""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from rotarykiln.outputs import save_figure_atomic  # noqa: E402
from rotarykiln.transverse.data import load_table  # noqa: E402
from rotarykiln.transverse.grid import GridMaterial, simulate_grid  # noqa: E402
from rotarykiln.transverse.grid_geometry import build_grid  # noqa: E402
from rotarykiln.transverse.grid_plot import plot_colour_map, plot_layer_sizes  # noqa: E402
from rotarykiln.transverse.retort import retort_case, run_retort  # noqa: E402

OUT = Path("docs/figures")
RPM = 2 * np.pi / 60


def main():
    base = run_retort(retort_case(2, snapshot_times=(0.0, 5.0, 10.0, 20.0, 40.0, 220.0)))
    fig = base.plot()
    save_figure_atomic(OUT / "transverse_base_case.png", fig, dpi=80)
    plt.close(fig)
    peak = 100 * base.extent.max()
    t_peak = base.t[np.argmax(base.extent)]
    print(
        f"base case: peak extent {peak:.0f} % at {t_peak:.1f} s, "
        f"T_shale(220 s) {base.temperature[-1, 1]:.1f} K, volatiles {100 * base.volatiles[-1]:.2f} %"
    )

    fig, axes = plt.subplots(2, 2, figsize=(10, 5.5))
    for ax, (t, f) in zip(
        axes.ravel(),
        [(0, "share"), (10, "extent"), (10, "temperature"), (40, "temperature")],
        strict=True,
    ):
        plot_colour_map(base, t, f, ax=ax, n=120)
    fig.tight_layout()
    save_figure_atomic(OUT / "transverse_colour_maps.png", fig, dpi=70)
    plt.close(fig)

    # trends: volatiles against time per group
    groups = {
        "size": (1, 3, 4, 5, 6),
        "temperature": (7, 2, 8),
        "ratio": (9, 2, 10, 11, 12),
        "speed": (13, 14, 2, 15, 16),
    }
    cases = load_table("retort_cases").set_index("case")
    fig, axes = plt.subplots(2, 2, figsize=(10, 7), sharex=True, sharey=True)
    for ax, (g, cs) in zip(axes.ravel(), groups.items(), strict=True):
        for c in cs:
            r = run_retort(retort_case(c, duration=120.0, snapshot_times=()))
            row = cases.loc[c]
            lab = {
                "size": f"{row.shale_size_mm}/{row.ash_size_mm} mm",
                "temperature": f"{row.shale_T_K:g}/{row.ash_T_K:g} K",
                "ratio": f"shale:ash {row.shale_to_ash}",
                "speed": f"{row.speed_rpm:g} rpm",
            }[g]
            ax.plot(r.t, 100 * r.volatiles, label=f"case {c}: {lab}")
            print(
                f"case {c:2d}: volatiles at 30 s {100 * np.interp(30, r.t, r.volatiles):5.2f} %,"
                f" at 120 s {100 * r.volatiles[-1]:5.2f} %"
            )
        ax.set_title(g)
        ax.legend(fontsize="x-small")
        ax.set_ylabel("volatiles [% of shale]")
    for ax in axes[1]:
        ax.set_xlabel("time [s]")
    fig.tight_layout()
    save_figure_atomic(OUT / "transverse_trends.png", fig, dpi=70)
    plt.close(fig)

    # layer sizes: segregation run 35 (570 mm drum)
    g = build_grid(0.285, 10.55 * RPM, 0.1474)
    mats = (GridMaterial("black", 0.612, [0.0, 1.0]), GridMaterial("orange", 0.388, [1.0, 0.0]))
    r35 = simulate_grid(g, [0.89e-3, 3.44e-3], mats, duration=30.0, snapshot_times=(30.0,))
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.5))
    plot_layer_sizes(r35, ax=axes[0])
    axes[0].set_title("exp 35 (570 mm drum, 10.55 rpm)")
    plot_colour_map(r35, 30.0, "size", ax=axes[1], n=120)
    fig.tight_layout()
    save_figure_atomic(OUT / "transverse_segregation.png", fig, dpi=70)
    plt.close(fig)

    # grid mixing time against Table 8.2
    speed = load_table("grid_mixing_speed")
    mix = load_table("mixing_experiments").set_index("exp")
    rows = []
    for _, s in speed.iterrows():
        row = mix.loc[s.exp]
        g = build_grid(0.285, row.speed_rpm * RPM, row.fill_percent / 100)
        res = simulate_grid(
            g,
            [row.dp_mm * 1e-3],
            (GridMaterial("b", row.ratio_used, [1.0]), GridMaterial("o", 1.0, [1.0])),
            duration=120.0,
        )
        t_exp = row.lf_exp_mm / row.alpha_exp_mm_s
        rows.append((s.v_al_mm_s, t_exp, s.tm_sim_s, res.mixing_time, res.final_contact))
        print(
            f"exp {s.exp:>2}: V_AL {s.v_al_mm_s:5.0f} mm/s, t_m exp {t_exp:5.1f} s, thesis sim "
            f"{s.tm_sim_s:3.0f} s, ours {res.mixing_time:5.1f} s; l_f ours {res.final_contact:5.1f} m"
        )
    rows = np.array(rows)
    fig, ax = plt.subplots(figsize=(5.5, 3.5))
    ax.plot(rows[:, 0], 100 * (rows[:, 2] / rows[:, 1] - 1), "s", label="thesis simulation")
    ax.plot(rows[:, 0], 100 * (rows[:, 3] / rows[:, 1] - 1), "o", label="this grid")
    ax.set_xlabel("V$_{AL}$ [mm/s]")
    ax.set_ylabel("mixing-time over-prediction [%]")
    ax.legend()
    fig.tight_layout()
    save_figure_atomic(OUT / "transverse_mixing_time.png", fig, dpi=80)
    plt.close(fig)


if __name__ == "__main__":
    main()
