"""Sweeps of the kiln models solve their cases in batches (issue 25): the same outputs as one
case at a time, warnings kept per case, a bad batch size refused."""

import pytest
import yaml

from rotarykiln.cases import builtin_case_path
from rotarykiln.errors import InputError
from rotarykiln.studies import grid, run_sweep
from rotarykiln.studies.models import kiln_model

DESIGN = grid(
    {
        "operation.speed": ["1.2 rpm", "1.5 rpm", "2.4 rpm"],
        "gas.flow": ["21 kg/h", "27 kg/h"],
    }
)


@pytest.fixture(scope="module")
def base():
    case = yaml.safe_load(builtin_case_path("tscheng_A16").read_text())
    case["solver"] = {"cells": 40}
    return case


def test_a_batched_sweep_gives_the_outputs_of_one_case_at_a_time(base):
    batched = run_sweep(kiln_model, base, DESIGN, executor="serial").frame
    alone = run_sweep(kiln_model, base, DESIGN, executor="serial", batch=1).frame
    assert (batched["error"] == "").all() and (alone["error"] == "").all()
    for col in ("bed_outlet_temperature_K", "gas_outlet_temperature_K", "shell_loss_W"):
        # each solve converged to its tolerance (1e-11 of the reference heat) from its own start
        assert batched[col].tolist() == pytest.approx(alone[col].tolist(), rel=1e-9, abs=1e-6)
    assert batched["newton_iterations"].tolist() != alone["newton_iterations"].tolist()
    assert batched["warnings"].tolist() == alone["warnings"].tolist()


def test_a_bad_case_in_a_batched_sweep_fails_alone(base):
    design = grid({"gas.temperature": ["530 K", "-5 K", "540 K"]})
    frame = run_sweep(kiln_model, base, design, executor="serial").frame
    errors = frame["error"].tolist()
    assert errors[0] == "" and errors[2] == ""
    assert "gas.temperature" in errors[1]


@pytest.mark.parametrize("bad", [0, -2, 1.5, True])
def test_a_batch_size_below_one_is_refused(base, bad):
    with pytest.raises(InputError, match="sweep.batch"):
        run_sweep(kiln_model, base, DESIGN, executor="serial", batch=bad)


def test_a_batched_chunk_makes_no_case_dict_it_does_not_need(monkeypatch):
    """A chunk's cases are made from the base and their changes (case_with): the deep copies
    of the base as case dicts are made only when asked for (a case case_with cannot take)."""
    from rotarykiln.studies import runner

    made = []
    real = runner.with_values
    monkeypatch.setattr(runner, "with_values", lambda *a, **k: made.append(1) or real(*a, **k))
    base = yaml.safe_load(builtin_case_path("tscheng_A16").read_text())
    design = grid({"operation.speed": ["1.5 rpm", "2 rpm", "2.5 rpm"]})
    rows = runner._run_chunk(kiln_model, base, design, False)
    assert all(not r["error"] for r in rows) and len(rows) == 3
    assert made == []


def _recording_model(sizes):
    """A cheap batched model that records the size of each chunk it is given."""

    def model(case):
        return {"speed": float(str(case["operation"]["speed"]).split()[0])}

    def batched(cases, warnings_out=None, *, base=None, changes=None):
        sizes.append(len(cases))
        return [model(c) for c in cases]

    model.batched = batched
    return model


@pytest.mark.parametrize(
    ("cases", "batch", "expected"),
    [
        (200, None, [100, 100]),
        (300, None, [100, 100, 100]),
        (90, None, [90]),
        (10, 4, [4, 4, 2]),
        (2, None, [2]),
    ],
)
def test_a_serial_sweep_solves_even_chunks_of_at_most_its_batch(cases, batch, expected):
    """In one process a batched model gets chunks of even sizes, at most SERIAL_BATCH cases
    (or --batch): not the two chunks per worker a pool would take (each chunk's first case is
    solved alone, and the others start nearer in a larger chunk)."""
    from rotarykiln.studies import runner

    assert runner.SERIAL_BATCH == 128
    sizes: list[int] = []
    design = grid({"operation.speed": [f"{1 + k / 1000:.4f} rpm" for k in range(cases)]})
    base = {"operation": {"speed": "1 rpm"}}
    res = run_sweep(_recording_model(sizes), base, design, executor="serial", batch=batch)
    assert sizes == expected
    assert res.frame["speed"].tolist() == pytest.approx([1 + k / 1000 for k in range(cases)])
