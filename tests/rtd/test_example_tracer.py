"""The shipped example tracer curve (examples/tracer_synthetic.csv) fits back to its generator."""

from pathlib import Path

import pytest

from rotarykiln.cli import main

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "tracer_synthetic.csv"


def test_example_tracer_fits_back(capsys):
    import json

    assert main(["rtd", "fit", str(EXAMPLE), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["tau_s"] == pytest.approx(40 * 60, rel=0.02)  # 2 % noise in the samples
    assert data["peclet"] == pytest.approx(60, rel=0.1)
