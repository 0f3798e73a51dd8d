"""The two built-in case files of seed 004 are complete, consistent and loadable."""

from pathlib import Path

import pytest
import yaml

import rotarykiln
from rotarykiln.chemistry.mechanism import Mechanism
from rotarykiln.chemistry.species import check_mass_fractions
from rotarykiln.units import to_si

RPM = 2 * 3.141592653589793 / 60  # rad/s per rpm
CASES = Path(rotarykiln.__file__).parent / "cases"


def _load(name):
    return yaml.safe_load((CASES / f"{name}.yaml").read_text())


@pytest.mark.parametrize("name", ["charcoal_activation", "limestone_calcination"])
def test_case_file_is_consistent(name):
    c = _load(name)
    check_mass_fractions(f"{name}.feed.composition", c["feed"]["composition"], phase="bed")
    check_mass_fractions(
        f"{name}.gas.inlet_composition", c["gas"]["inlet_composition"], phase="gas"
    )
    Mechanism.builtin(*c["chemistry"]["reactions"])
    assert to_si("length", c["kiln"]["length"], "length") > 0
    assert to_si("speed", c["operation"]["speed"], "rotation rate") > 0
    assert to_si("flow", c["feed"]["mass_flow"], "mass flow") > 0
    assert to_si("t", c["operation"]["residence_time"], "time") > 0
    assert to_si("Tg", c["gas"]["inlet_temperature"], "temperature") > 1000
    assert to_si("U", c["kiln"]["shell_loss"]["U"], "heat transfer coefficient") > 0


def test_values_given_by_seed_004():
    # Issue 7 item 3 lists the seed-004 inputs of both cases.
    ch = _load("charcoal_activation")
    assert to_si("L", ch["kiln"]["length"], "length") == pytest.approx(3.7)
    assert to_si("D", ch["kiln"]["diameter"], "length") == pytest.approx(0.3)
    assert to_si("N", ch["operation"]["speed"], "rotation rate") == pytest.approx(
        2 * 2 * 3.14159265 / 60
    )
    assert to_si("Qs", ch["feed"]["mass_flow"], "mass flow") == pytest.approx(0.00333)
    assert to_si("Qa", ch["gas"]["steam_mass_flow"], "mass flow") == pytest.approx(0.005)
    assert to_si("Ts", ch["feed"]["temperature"], "temperature") == pytest.approx(500.0)
    ls = _load("limestone_calcination")
    assert to_si("L", ls["kiln"]["length"], "length") == pytest.approx(5.5)
    assert to_si("D", ls["kiln"]["diameter"], "length") == pytest.approx(0.406)
    assert to_si("Qs", ls["feed"]["mass_flow"], "mass flow") == pytest.approx(42 / 3600)
    assert to_si("N", ls["operation"]["speed"], "rotation rate") == pytest.approx(
        1.5 * 2 * 3.14159265 / 60
    )
