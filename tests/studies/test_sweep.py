import math

import numpy as np
import pandas as pd
import pytest

from rotarykiln.cases import builtin_case
from rotarykiln.errors import InputError
from rotarykiln.studies import grid, one_at_a_time, run_sweep, set_path, with_values
from rotarykiln.studies.ahmad2006 import CHAPTER5_DIRECTIONS, ahmad_chapter5_design
from rotarykiln.studies.examples import (
    failing_model,
    first_order_conversion,
    ortiz_isothermal_burn_off,
)

BASE = {"reaction": {"rate_constant": "0.01 1/s"}, "operation": {"residence_time": "100 s"}}


def test_paths_and_lists():
    c = {"kiln": {"layers": [{"k": 1.0}, {"k": 2.0}]}}
    c2 = with_values(c, {"kiln.layers.1.k": 5.0})
    assert c2["kiln"]["layers"][1]["k"] == 5.0 and c["kiln"]["layers"][1]["k"] == 2.0
    with pytest.raises(InputError, match="list index"):
        set_path(c, "kiln.layers.7.k", 1.0)
    with pytest.raises(InputError, match="dotted field path"):
        set_path(c, "kiln..k", 1.0)
    c3 = with_values(c, {"new.field": 1}, create=True)
    assert c3["new"]["field"] == 1


def test_grid_sweep_in_processes_matches_closed_form():
    design = grid(
        {
            "operation.residence_time": ["10 s", "1 min", "100 s"],
            "reaction.rate_constant": [0.01, 0.02],
        }
    )
    res = run_sweep(first_order_conversion, BASE, design, executor="process", max_workers=2)
    df = res.frame
    assert len(df) == 6 and res.n_failed == 0
    expected = 1 - np.exp(-df["operation.residence_time [SI]"] * df["reaction.rate_constant [SI]"])
    assert np.allclose(df["conversion"], expected, rtol=1e-12)
    assert df["operation.residence_time"].tolist()[:2] == ["10 s", "10 s"]  # values as given
    assert df["operation.residence_time [SI]"].iloc[2] == pytest.approx(60.0)
    assert list(df["case_id"]) == list(range(6))


def test_errors_are_captured_per_case_not_raised():
    base = {"x": 1.0}
    res = run_sweep(
        failing_model, base, grid({"x": [-1.0, 0.0, 2.0, "abc"]}), executor="process", max_workers=2
    )
    df = res.frame.set_index("case_id")
    assert "ValueError: x = -1.0 < 0" in df.loc[0, "error"]
    assert "not a dict of scalars" in df.loc[1, "error"]
    assert df.loc[2, "error"] == "" and df.loc[2, "y"] == 4.0
    assert "ValueError" in df.loc[3, "error"]
    assert res.n_failed == 3 and len(res.failed) == 3


def test_unknown_path_refused_before_running():
    with pytest.raises(InputError, match="operation.sped"):
        run_sweep(first_order_conversion, BASE, grid({"operation.sped": [1]}), executor="serial")


def test_unpicklable_function_refused_for_processes():
    with pytest.raises(InputError, match="picklable"):
        run_sweep(lambda c: {"a": 1}, BASE, grid({"operation.residence_time": [1]}))
    res = run_sweep(
        lambda c: {"a": 1}, BASE, grid({"operation.residence_time": [1]}), executor="serial"
    )
    assert res.frame["a"].tolist() == [1]


def test_non_finite_output_flagged():
    res = run_sweep(
        lambda c: {"a": math.nan}, BASE, grid({"operation.residence_time": [1]}), executor="serial"
    )
    assert "non-finite output: a" in res.frame["error"].iloc[0]


@pytest.mark.parametrize("scheduler", ["synchronous", "threads"])
def test_dask_executor(scheduler):
    design = grid({"operation.residence_time": ["50 s", "100 s", "200 s"]})
    res = run_sweep(first_order_conversion, BASE, design, executor="dask", dask_scheduler=scheduler)
    serial = run_sweep(first_order_conversion, BASE, design, executor="serial")
    assert np.allclose(res.frame["conversion"], serial.frame["conversion"])


def test_write_csv_atomically_and_plot(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    design = one_at_a_time(
        {
            "operation.residence_time": ["50 s", "100 s", "200 s"],
            "reaction.rate_constant": [0.005, 0.02],
        }
    )
    res = run_sweep(first_order_conversion, BASE, design, executor="serial")
    paths = res.write(tmp_path / "out", name="study")
    csv = tmp_path / "out" / "study.csv"
    assert csv in paths and not [p for p in (tmp_path / "out").iterdir() if p.name.startswith(".")]
    back = pd.read_csv(csv, keep_default_na=False)
    assert len(back) == len(res.frame) and "conversion" in back
    fig = res.plot()
    assert len(fig.axes) == 2 * 2
    png = res.save_plot(tmp_path / "out" / "study.png")
    assert png.stat().st_size > 1000
    with pytest.raises(InputError):
        res.plot(outputs=["nope"])


def test_parquet_required_but_missing_is_clear(tmp_path):
    from rotarykiln.studies.io import parquet_available

    res = run_sweep(
        first_order_conversion, BASE, grid({"operation.residence_time": [1]}), executor="serial"
    )
    if parquet_available():
        assert any(p.suffix == ".parquet" for p in res.write(tmp_path, parquet=True))
    else:
        with pytest.raises(InputError, match="pyarrow"):
            res.write(tmp_path, parquet=True)


def test_bad_designs():
    with pytest.raises(InputError):
        grid({})
    with pytest.raises(InputError):
        grid({"a": "123"})
    with pytest.raises(InputError, match="executor"):
        run_sweep(
            first_order_conversion, BASE, grid({"operation.residence_time": [1]}), executor="mpi"
        )


def test_chapter5_design_on_builtin_case_with_toy_model():
    # The design addresses fields that exist in the built-in charcoal case, and a stand-in model
    # (isothermal reaction zone) gives seed 004's directions for residence time and steam flow.
    case = builtin_case("charcoal_activation")
    case["standin"] = {"reaction_zone_temperature": "1150 K"}
    res = run_sweep(ortiz_isothermal_burn_off, case, ahmad_chapter5_design(), executor="serial")
    assert res.n_failed == 0
    df = res.frame
    for path in ("bed.residence_time", "gas.steam_flow"):
        sub = df[df["group"] == path].sort_values(path + " [SI]")
        assert np.all(np.diff(sub["burn_off"]) > 0) and CHAPTER5_DIRECTIONS[path] == 1
        assert np.allclose(sub["burn_off"] + sub["production"], 100.0)


def test_oat_rows_show_base_values_for_unswept_parameters():
    design = one_at_a_time(
        {"operation.residence_time": ["50 s"], "reaction.rate_constant": ["0.02 1/s"]}
    )
    df = run_sweep(first_order_conversion, BASE, design, executor="serial").frame
    assert df.loc[1, "reaction.rate_constant"] == "0.01 1/s"  # base value
    assert df.loc[2, "operation.residence_time"] == "100 s"
    assert df.loc[2, "conversion"] == pytest.approx(1 - np.exp(-2.0))


def kiln_like(case: dict) -> dict:
    """A stand-in with a kiln's output names, some repeating others, from a speed in rpm."""
    from rotarykiln.units import to_si

    speed = to_si("operation.speed", case["operation"]["speed"], "rotation rate")
    feed = to_si("operation.feed", case["operation"]["feed"], "mass flow")
    t = 60.0 / speed / (1.0 + 50.0 * feed)
    return {
        "bed_outlet_temperature_K": 900.0 + 0.01 * t,
        "bed_max_temperature_K": 900.0 + 0.01 * t,  # the same column under another name
        "gas_outlet_temperature_K": 700.0 - 0.005 * t,
        "newton_iterations": 4,
        "residence_time_s": t,
        "fill": 0.1 * t / 600.0,
        "burn_off_percent": 100.0 * (1.0 - math.exp(-t / 3000.0)),
        "conversion_C": 1.0 - math.exp(-t / 3000.0),
        "energy_shell_loss_W": 1000.0 + t,
    }


KILN = {"operation": {"speed": "2 rpm", "feed": "62 kg/h"}}


def test_plot_has_one_panel_per_output_with_the_parameter_as_typed():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    design = grid(
        {"operation.speed": ["1 rpm", "2 rpm", "4 rpm"], "operation.feed": ["40 kg/h", "90 kg/h"]}
    )
    res = run_sweep(kiln_like, KILN, design, executor="serial")
    keys = res.key_outputs()
    assert keys == [
        "bed_outlet_temperature_K",
        "gas_outlet_temperature_K",
        "residence_time_s",
        "fill",
        "burn_off_percent",
    ]
    fig = res.plot()
    assert len(fig.axes) == len(keys)  # one panel per output, the feed as lines
    labels = {ax.get_ylabel() for ax in fig.axes}
    assert len(labels) == len(keys)  # no output drawn twice
    for ax in fig.axes:
        assert ax.get_xlabel() == "operation.speed (rpm)"
        assert len(ax.lines) == 2  # one line per feed
        assert list(ax.lines[0].get_xdata()) == [1.0, 2.0, 4.0]  # rpm, not rad/s
    plt.close(fig)
    fig = res.plot(outputs=["fill", "energy_shell_loss_W"])
    assert len(fig.axes) == 2
    plt.close(fig)
    with pytest.raises(InputError, match="did you mean fill"):
        res.plot(outputs=["fil"])


def test_key_outputs_of_another_model_leave_out_repeats_and_bookkeeping():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    def repeats(case):
        out = first_order_conversion(case)
        out["conversion_again"] = out["conversion"]
        out["newton_iterations"] = 3
        return out

    design = grid({"operation.residence_time": ["1 min", "2 min", "5 min"]})
    res = run_sweep(repeats, BASE, design, executor="serial")
    assert res.key_outputs() == ["conversion", "damkohler"]
    fig = res.plot()
    assert len(fig.axes) == 2
    assert fig.axes[0].get_xlabel() == "operation.residence_time (min)"
    assert list(fig.axes[0].lines[0].get_xdata()) == [1.0, 2.0, 5.0]
    plt.close(fig)


def test_table_in_typed_units_fits_the_width():
    design = grid(
        {
            "operation.speed": ["1 rpm", "1.5 rpm", "3 rpm"],
            "operation.feed": ["40 kg/h", "0.025 kg/s"],
        }
    )
    res = run_sweep(kiln_like, KILN, design, executor="serial")
    table = res.table()
    assert list(table.columns) == [
        "case_id",
        "operation.speed [rpm]",
        "operation.feed [kg/h]",
        *res.key_outputs(),
    ]
    assert list(table["operation.speed [rpm]"]) == [1.0, 1.0, 1.5, 1.5, 3.0, 3.0]
    assert list(table["operation.feed [kg/h]"]) == pytest.approx([40.0, 90.0] * 3)
    for width in (80, 100):
        text = res.format_table(width=width)
        assert all(len(line) <= width for line in text.splitlines())
        for name in res.key_outputs():  # every chosen output is shown, wrapped or in a block
            head = name.split("_")[0]
            assert head in text
    assert "bed_max" not in res.format_table(width=100)
    wide = res.format_table(width=100).splitlines()
    assert len(wide) == 3 + 6  # three header lines, one line per case: no second block


def test_sampled_design_plots_each_parameter_without_a_legend_per_sample():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from rotarykiln.studies.design import latin_hypercube

    design = latin_hypercube(
        ["operation.speed=uniform(1 rpm, 4 rpm)", "operation.feed=uniform(40 kg/h, 90 kg/h)"], 12
    )
    res = run_sweep(kiln_like, KILN, design, executor="serial")
    fig = res.plot(outputs=["residence_time_s"])
    assert len(fig.axes) == 2  # the output against each parameter
    assert [ax.get_xlabel() for ax in fig.axes] == [
        "operation.speed (rpm)",
        "operation.feed (kg/h)",
    ]
    speeds = fig.axes[0].lines[0].get_xdata()
    assert len(speeds) == 12 and 1.0 <= min(speeds) and max(speeds) <= 4.0
    assert not fig.legends and all(ax.get_legend() is None for ax in fig.axes)
    plt.close(fig)


def test_one_at_a_time_shows_each_parameter_in_the_unit_of_its_design_values():
    design = one_at_a_time(
        {"operation.residence_time": ["1 min", "5 min"], "reaction.rate_constant": ["0.6 1/min"]}
    )
    res = run_sweep(first_order_conversion, BASE, design, executor="serial")  # base: 100 s
    assert res.parameter_units() == {
        "operation.residence_time": "min",
        "reaction.rate_constant": "1/min",
    }
    table = res.table(["conversion"])
    assert list(table["operation.residence_time [min]"]) == pytest.approx(
        [100 / 60, 1, 5, 100 / 60]
    )
    assert list(table["reaction.rate_constant [1/min]"]) == pytest.approx([0.6, 0.6, 0.6, 0.6])
    assert list(table.columns)[-1] == "conversion"
