import math

import numpy as np
import pandas as pd
import pytest

from rotarykiln.errors import InputError
from rotarykiln.studies import grid, one_at_a_time, run_sweep, set_path, with_values
from rotarykiln.studies.ahmad2006 import CHAPTER5_DIRECTIONS, ahmad_chapter5_design, builtin_case
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
