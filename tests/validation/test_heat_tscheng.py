"""Tscheng's (1978) pilot kiln, all 44 runs, from measured inputs only (issue 6).

Each run is its built-in YAML case ``tscheng_<run>`` run through the public path (load_case,
kiln_from_case, solve_kiln; tests/validation/tscheng_scoring.py), and scored by RMSE at the
measured points (docs/validation.md).

Where the bounds come from. Tscheng's thesis is the source of the data, but its statement of the
thermocouples' accuracy is not available to this project: neither the shipped data nor their
README (src/rotarykiln/data/tscheng1978/README.md) give one, and of the thesis only the abstract
was at hand. No bound here is therefore derived from the source's measurement accuracy; each test
says which documented figure it holds instead. The exact numbers of every run are held, as
regression, by tests/test_golden_outputs.py, not by bounds here.
"""

import warnings

import numpy as np
import pytest
from tscheng_scoring import score_all

from rotarykiln.errors import OutOfRangeWarning
from rotarykiln.studies.tscheng1978 import tscheng_runs


@pytest.fixture(scope="module")
def scores():
    with warnings.catch_warnings():  # the closures' range warnings: listed in the cases' headers
        warnings.simplefilter("ignore", OutOfRangeWarning)
        return score_all()


def test_all_44_runs_solved_and_closed(scores):
    """Every run of the data has its case and solves; its energy balance closes to 1e-6 of the
    heat to the solids (the solver's requirement, issue 6: a numerical bound, not a measured one).
    """
    assert len(scores) == 44 == len(tscheng_runs())
    assert np.all(np.abs(scores["closure"]) < 1e-6)


def test_overall_window_rmse(scores):
    """Mean over the 44 runs of the RMSE in the 1.25-1.78 m window that the thesis recommends
    (data README): bed <= 10 K, gas <= 15 K. These are the goal issue 6 set for this validation
    (docs/validation.md, "goal" row), not a measurement accuracy of the source, which is not
    available here (module docstring).
    """
    assert scores["bed_window"].mean() <= 10.0
    assert scores["gas_window"].mean() <= 15.0
