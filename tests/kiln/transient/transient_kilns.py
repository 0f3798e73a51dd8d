"""The kilns and wall heat capacities of the transient tests (Barr's lined kiln, the fired
limestone kiln with a constant-U wall), shared by their test modules."""

import warnings

import pytest

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.kiln.from_case import kiln_from_case

BARR_WALL = {
    "layers": [
        {"density": "1300 kg/m3", "specific_heat": "1000 J/kg/K"},
        {"density": "7850 kg/m3", "specific_heat": "490 J/kg/K"},
    ]
}
U_WALL = {"thickness": "50 mm", "density": "2000 kg/m3", "specific_heat": "1000 J/kg/K"}


def built_kiln(name):
    """The kiln of the built-in case ``name`` (its closure warnings silenced)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        kiln, _ = kiln_from_case(load_case(builtin_case_path(name)))
    return kiln


@pytest.fixture(scope="module", name="barr")
def barr_fixture():
    """Barr's lined, gas-fired pilot kiln (trial T4)."""
    return built_kiln("barr_T4")


@pytest.fixture(scope="module", name="limestone")
def limestone_fixture():
    """The fired limestone kiln (constant-U wall, calcination)."""
    return built_kiln("limestone_fired")
