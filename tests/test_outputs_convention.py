"""The outputs' conventions (docs/dev/architecture.md, "Outputs"): every result table carries its
units, the package version and the model in ``DataFrame.attrs``; every ``plot()`` returns a
matplotlib Figure; progress bars never reach the ``--json`` output."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from functools import cache

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

import rotarykiln  # noqa: E402
from rotarykiln.tables import UNIT_SUFFIXES, column_unit, split_unit, with_units  # noqa: E402

RPM = 2 * np.pi / 60  # rad/s per rpm


@cache
def _kiln(name: str):
    from rotarykiln.case import load_case
    from rotarykiln.cases import builtin_case_path
    from rotarykiln.kiln.from_case import kiln_from_case
    from rotarykiln.kiln.steady.solve import solve_kiln

    case = load_case(builtin_case_path(name))
    kiln, cells = kiln_from_case(case)
    return case, kiln, solve_kiln(kiln, 30)


def _tracer():
    from rotarykiln.rtd.tracer import analyse_tracer

    t = np.arange(0.0, 61.0) * 60.0
    return analyse_tracer(t, np.exp(-((t / 60.0 - 30.0) ** 2) / 8.0))


def _fit():
    from rotarykiln.rtd.dispersion import open_open_exit_age
    from rotarykiln.rtd.fitting import fit_rtd

    t = np.linspace(30.0, 60.0, 61) * 60
    return fit_rtd(t, open_open_exit_age(t, 2520.0, 600.0), length=1.95)


def _prediction():
    from rotarykiln.rtd.predict import predict_rtd

    return predict_rtd(43.34 * 60, dispersion=2.8e-6, length=1.95)


def _dispersion_pde():
    from rotarykiln.rtd.dispersion_pde import dirac_inlet, solve_dispersion_pde

    return solve_dispersion_pde(10.0, dirac_inlet(), 3.0, cells_per_length=40, n_out=61)


def _segregated():
    from rotarykiln.chemistry.segregated import segregated_average

    return segregated_average(
        lambda t: 1 - np.exp(-0.01 * t), lambda t: np.exp(-t / 100) / 100, t_max=1000.0, n=201
    )


def _plug_flow():
    from rotarykiln.chemistry.mechanism import Mechanism
    from rotarykiln.chemistry.plugflow import integrate_plug_flow

    return integrate_plug_flow(
        Mechanism.builtin("calcination_luisser"), {"CaCO3": 0.01}, 0.5, 0.01, 1100.0
    )


def _rates():
    from rotarykiln.chemistry.mechanism import CellState, Mechanism

    state = CellState.build(
        T_bed=np.linspace(900.0, 1200.0, 3),
        T_gas=np.full(3, 1300.0),
        bed_mass_flow={"CaCO3": 5e-3, "CaO": 1e-3, "H2O(l)": 1e-3},
        bed_mass_per_length=20.0,
        partial_pressure={"CO2": 2e4, "H2O": 3e4},
        bed_mass_flow_in={"CaCO3": 6e-3},
        inputs={
            "steam_mass_flow": 5e-3,
            "drying_conductance": 30.0,
            "bed_heat_input": 1e4,
            "freeboard_area": 0.1,
        },
    )
    return Mechanism.builtin("calcination_luisser", "drying_ahmad").rates(state)


def _bed():
    from rotarykiln.transport import kramers_profile

    return kramers_profile(
        1e-5,
        length=2.0,
        dam_height=0.05,
        n_points=30,
        radius=0.2,
        speed=3 * RPM,
        slope=np.radians(1),
        repose=np.radians(35),
    )


def _chart():
    from rotarykiln.transport.charts import design_chart

    return design_chart(36.6, 3.66, np.pi / 30, np.radians(3), np.radians(40), n=10)


def _section():
    from rotarykiln.geometry import CrossSection

    return CrossSection.from_fill(0.15, 0.2)


def _regime():
    from rotarykiln.regimes import classify_regime

    return classify_regime(0.084, 0.3)


def _active_layer():
    from rotarykiln.transverse.active_layer import active_layer

    return active_layer(0.285, np.array([5, 10]) * RPM, 0.25)


def _mixing():
    from rotarykiln.transverse.mixing import vanpuyvelde_mixing

    return vanpuyvelde_mixing(0.285, 9 * RPM, 0.25, 2.51e-3, 1.06)


def _layers():
    from rotarykiln.transverse.segregation import vanpuyvelde_layer_mean_sizes

    return vanpuyvelde_layer_mean_sizes([1e-3, 2e-3], [0.5, 0.5], 0.4)


@cache
def _grid():
    from rotarykiln.transverse.retort import retort_case, run_retort

    return run_retort(retort_case(2, duration=1.0, snapshot_times=(0.0, 1.0)))


def _kiln_solution():
    return _kiln("tscheng_A16")[2]


def _residence():
    from rotarykiln.commands.kiln_runs import bed_peclet
    from rotarykiln.kiln.bed.residence import residence_time_effects

    case, kiln, sol = _kiln("limestone_calcination")
    return residence_time_effects(
        kiln, sol, n_tau=6, peclet=bed_peclet(case, sol.residence_time)[0]
    )


def _sweep():
    import pandas as pd

    from rotarykiln.studies.result import SI_SUFFIX, SweepResult

    frame = pd.DataFrame(
        {
            "case_id": ["a", "b"],
            "group": ["grid", "grid"],
            "operation.speed": ["1 rpm", "3 rpm"],
            "operation.speed" + SI_SUFFIX: [1 * RPM, 3 * RPM],
            "kiln_bed_outlet_temperature_K": [500.0, 520.0],
            "bed_temperature@0.0000": [300.0, 300.0],
            "error": ["", ""],
            "warnings": ["", ""],
            "elapsed_s": [0.1, 0.1],
            "hash": ["x", "y"],
        }
    )
    return SweepResult(
        frame,
        ("operation.speed",),
        ("kiln_bed_outlet_temperature_K", "bed_temperature@0.0000"),
    )


FRAMES = {
    "kiln": _kiln_solution,
    "tracer": _tracer,
    "rtd fit": _fit,
    "rtd prediction": _prediction,
    "dispersion pde": _dispersion_pde,
    "segregated": _segregated,
    "plug flow": _plug_flow,
    "rates": _rates,
    "bed profile": _bed,
    "design chart": _chart,
    "cross-section": _section,
    "regime": _regime,
    "active layer": _active_layer,
    "mixing": _mixing,
    "layer sizes": _layers,
    "transverse grid": _grid,
    "sweep": _sweep,
}

PLOTS = {k: v for k, v in FRAMES.items() if k != "sweep"} | {"residence time": _residence}


# --- tables --------------------------------------------------------------------------------
def test_kiln_profiles_frame_has_a_unit_for_every_column():
    df = _kiln_solution().to_frame()
    units = df.attrs["units"]
    assert list(units) == list(df.columns)
    assert all(units.values()), {c: u for c, u in units.items() if not u}
    assert units["z_m"] == "m" and units["T_bed_K"] == "K"
    assert units["q_shell_loss_W_m"] == "W/m"
    assert {units[c] for c in df if c.startswith(("bed_", "gas_"))} == {"kg/s"}
    assert df.attrs["rotarykiln_version"] == rotarykiln.__version__
    assert df.attrs["model"] == "kiln"


def test_reacting_kiln_columns_have_units():
    units = _kiln("limestone_calcination")[2].to_frame().attrs["units"]
    rates = [c for c in units if c.startswith("rate_")]
    assert rates and {units[c] for c in rates} == {"kg/(s m)"}


@pytest.mark.parametrize("name", list(FRAMES))
def test_every_result_table_carries_units_version_and_model(name):
    df = FRAMES[name]().to_frame()
    attrs = df.attrs
    assert set(attrs) >= {"units", "rotarykiln_version", "model"}
    assert attrs["rotarykiln_version"] == rotarykiln.__version__
    assert attrs["model"]
    assert list(attrs["units"]) == [str(c) for c in df.columns]
    for column, unit in attrs["units"].items():  # a number named with a unit gets that unit
        suffix_unit = split_unit(column)[1]
        if suffix_unit and not unit.startswith("@"):
            assert unit == suffix_unit, column


def test_sweep_units_from_the_values_as_given():
    units = _sweep().to_frame().attrs["units"]
    assert units["operation.speed [SI]"] == "rad/s"
    assert units["operation.speed"] == ""
    assert units["bed_temperature@0.0000"] == "K"
    assert units["kiln_bed_outlet_temperature_K"] == "K"


def test_suffix_table_and_column_units():
    suffixes = [s for s, _ in UNIT_SUFFIXES]
    assert len(set(suffixes)) == len(suffixes)
    for i, (s, _) in enumerate(UNIT_SUFFIXES):  # no suffix is shadowed by an earlier one
        assert not any(s.endswith(t) for t in suffixes[:i]), s
    import pandas as pd

    assert column_unit("regime", pd.Series(["a"])) == ""
    assert column_unit("fill", pd.Series([0.1])) == "1"
    assert column_unit("cell", pd.Series([1])) == ""
    df = with_units(pd.DataFrame({"signal": [1.0]}), "x", {"signal": "a.u."})
    assert df.attrs["units"] == {"signal": "a.u."}
    assert df.copy().attrs["units"] == {"signal": "a.u."}


def test_report_reads_the_same_suffix_table():
    from rotarykiln import report_html

    assert report_html.split_unit is split_unit


# --- plots ---------------------------------------------------------------------------------
@pytest.mark.parametrize("name", list(PLOTS))
def test_every_plot_returns_a_figure(name):
    result = PLOTS[name]()
    fig = result.plot()
    try:
        assert isinstance(fig, Figure)
        assert fig.axes
        # the line outputs.write_solution_files keeps for an Axes or a Figure
        assert getattr(fig, "figure", fig) is fig
    finally:
        plt.close(fig)
    fig, ax = plt.subplots()
    try:
        if name not in ("kiln", "transverse grid", "design chart"):  # several panels
            assert result.plot(ax=ax) is fig
    finally:
        plt.close(fig)


def test_module_plot_helpers_and_plot_methods_return_figures():
    from rotarykiln.kiln.results.plots import plot_temperature_profiles
    from rotarykiln.regimes import plot_regime_map
    from rotarykiln.rtd.plots import parity_plot
    from rotarykiln.transverse.grid_plot import (
        plot_colour_map,
        plot_layer_sizes,
        plot_time_series,
    )

    grid = _grid()
    figures = [
        plot_regime_map(0.1, 0.01),
        parity_plot([1.0, 2.0], [1.1, 1.9]),
        plot_temperature_profiles(_kiln_solution()),
        plot_layer_sizes(grid),
        plot_time_series(grid),
        plot_colour_map(grid, 1.0, "temperature"),
    ]
    try:
        assert all(isinstance(f, Figure) for f in figures)
        assert "case 2" in figures[3].get_suptitle()
    finally:
        for f in figures:
            plt.close(f)


def test_bed_and_wall_drawn_in_distinct_colours():
    from matplotlib.colors import to_rgb

    fig = _kiln_solution().plot()
    try:
        lines = {ln.get_label(): ln for ln in fig.axes[0].get_lines()}
        assert to_rgb(lines["bed"].get_color()) != to_rgb(lines["inner wall"].get_color())
        assert fig.axes[0].get_ylabel() == "temperature (K)"
        assert "tscheng" in fig.axes[0].get_title().lower() or fig.get_suptitle()
    finally:
        plt.close(fig)


# --- progress ------------------------------------------------------------------------------
def test_progress_bar_off_is_a_no_op(monkeypatch):
    from rotarykiln.progress import progress_bar, progress_enabled

    monkeypatch.setenv("ROTARYKILN_PROGRESS", "0")
    assert not progress_enabled()
    assert progress_enabled(True)
    monkeypatch.setenv("ROTARYKILN_PROGRESS", "1")
    assert progress_enabled()
    assert not progress_enabled(False)
    with progress_bar(2.5, desc="x", unit="s", enabled=False) as bar:
        bar.update(2.5)


def test_json_output_stays_clean_with_progress_and_logging(tmp_path):
    """A bar and log records on stderr; stdout is one JSON document."""
    env = dict(os.environ, ROTARYKILN_PROGRESS="1", PYTHONWARNINGS="ignore")
    cmd = [sys.executable, "-m", "rotarykiln", "-v", "transverse", "retort/case02"]
    cmd += ["--duration", "2", "s", "--no-plots", "--json", "--out", str(tmp_path / "tr")]
    done = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=120)
    assert done.returncode == 0, done.stderr
    summary = json.loads(done.stdout)
    assert summary["case"].startswith("ATP retort zone")
    assert "transverse grid" in done.stderr  # the bar
    assert "INFO rotarykiln.transverse.grid" in done.stderr  # the log
    assert "\r" not in done.stdout and "%|" not in done.stdout


def test_library_configures_no_log_handler():
    import logging

    import rotarykiln.chemistry.segregated  # noqa: F401
    import rotarykiln.transverse.grid  # noqa: F401

    assert not logging.getLogger("rotarykiln").handlers
    assert not logging.getLogger("rotarykiln.transverse.grid").handlers
