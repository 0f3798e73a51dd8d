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
