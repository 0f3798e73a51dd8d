"""gas_flow: burner and air flows as engineers type them (issue 10), and molar_volume."""

import math
import re

import numpy as np
import pytest

from rotarykiln.errors import InputError
from rotarykiln.units import (
    NORMAL_STATE,
    R_GAS,
    SCF_STATE,
    STANDARD_STATE,
    GasFlow,
    gas_flow,
    molar_volume,
)

V_N = 0.022414  # m3/mol at 0 degC, 1 atm (DIN 1343)
V_S = 0.023645  # m3/mol at 15 degC, 1 atm (ISO 13443)
FT3 = 0.3048**3  # m3
V_SCF = R_GAS * ((60 - 32) / 1.8 + 273.15) / (14.696 * 4.4482216152605 / 0.0254**2)
FIELD = "burner.air_flow"


@pytest.mark.parametrize(
    ("text", "kind", "expected"),
    [
        # mass flows, kg/s
        ("2.2 kg/h", "mass", 2.2 / 3600),
        ("0.5 g/s", "mass", 0.5e-3),
        ("1 t/h", "mass", 1000 / 3600),
        ("62 kg/hr", "mass", 62 / 3600),
        # molar flows, mol/s
        ("0.1 mol/s", "molar", 0.1),
        ("3 kmol/h", "molar", 3000 / 3600),
        # normal volume flows: 0 degC, 101325 Pa
        ("12 Nm3/h", "molar", 12 / 3600 / V_N),
        ("12 Nm³/h", "molar", 12 / 3600 / V_N),
        ("12 Nm^3/h", "molar", 12 / 3600 / V_N),
        ("12 N m3 / h", "molar", 12 / 3600 / V_N),
        ("0.83 NL/s", "molar", 0.83e-3 / V_N),
        ("5 Nl/min", "molar", 5e-3 / 60 / V_N),
        ("24 Nm3/d", "molar", 24 / 86400 / V_N),
        # standard volume flows: 15 degC, 101325 Pa; scf at 60 degF, 14.696 psia
        ("12 Sm3/h", "molar", 12 / 3600 / V_S),
        ("0.8 SL/s", "molar", 0.8e-3 / V_S),
        ("10 scfm", "molar", 10 * FT3 / 60 / V_SCF),
        ("600 SCFH", "molar", 600 * FT3 / 3600 / V_SCF),
    ],
)
def test_accepted_spellings_and_their_si_values(text, kind, expected):
    flow = gas_flow(text, FIELD)
    assert isinstance(flow, GasFlow)
    assert flow.kind == kind
    assert flow.value == pytest.approx(expected, rel=1e-4)


def test_the_reference_state_is_the_one_the_unit_names():
    assert gas_flow("1 Nm3/h", FIELD).reference_temperature == 273.15
    assert gas_flow("1 Nm3/h", FIELD).reference_pressure == 101325.0
    s = gas_flow("1 Sm3/h", FIELD)
    assert (s.reference_temperature, s.reference_pressure) == STANDARD_STATE == (288.15, 101325.0)
    f = gas_flow("1 scfm", FIELD)
    assert f.reference_temperature == pytest.approx(288.7056, abs=1e-4)
    assert f.reference_pressure == pytest.approx(101325.35, abs=0.01)
    assert (f.reference_temperature, f.reference_pressure) == SCF_STATE
    m = gas_flow("1 kg/h", FIELD, reference_temperature=298.15)
    assert (m.reference_temperature, m.reference_pressure) == (None, None)


def test_plain_volume_flow_with_a_reference_temperature():
    flow = gas_flow("1.42 L/s", FIELD, reference_temperature=298.15)
    assert flow.kind == "molar"
    assert flow.value == pytest.approx(101325 * 1.42e-3 / (8.314462618 * 298.15), rel=1e-9)
    assert (flow.reference_temperature, flow.reference_pressure) == (298.15, 101325.0)
    # strings with units, and a reference pressure
    flow = gas_flow("3 m3/h", FIELD, reference_temperature="25 degC", reference_pressure="1 bar")
    assert flow.value == pytest.approx(1e5 * 3 / 3600 / (8.314462618 * 298.15), rel=1e-9)
    # a reference state that agrees with the unit's own is not a contradiction
    agree = gas_flow("12 Nm3/h", FIELD, reference_temperature="0 degC", reference_pressure="1 atm")
    assert agree == gas_flow("12 Nm3/h", FIELD)


def test_the_mass_and_molar_views_of_a_flow():
    air = 0.028964  # kg/mol
    n = gas_flow("12 Nm3/h", FIELD)
    assert n.mass_flow(air) == pytest.approx(n.value * air)
    assert n.molar_flow(air) == n.value
    m = gas_flow("2 kg/s", FIELD)
    assert m.molar_flow(air) == pytest.approx(2 / air)
    assert m.mass_flow(air) == 2.0


def test_zero_only_when_allowed():
    with pytest.raises(InputError, match=re.escape('burner.air_flow: "0 Nm3/h" is zero')):
        gas_flow("0 Nm3/h", FIELD)
    with pytest.raises(InputError, match="burner.air_flow: 0 is zero"):
        gas_flow(0, FIELD)
    assert gas_flow("0 Nm3/h", FIELD, allow_zero=True).value == 0.0
    assert gas_flow(0, FIELD, allow_zero=True) == GasFlow("mass", 0.0)


@pytest.mark.parametrize(
    ("value", "kwargs", "message"),
    [
        # a bare number: kg/s? Nm3/h? refused, like MassFlow
        (62, {}, 'burner.air_flow: bare number 62 needs a unit (e.g. "62 kg/h", "62 Nm3/h")'),
        (0.5, {}, "burner.air_flow: bare number 0.5 needs a unit"),
        ("12", {}, 'burner.air_flow: "12" needs a unit, expected a mass flow (kg/h'),
        (True, {}, "burner.air_flow: True is not a gas flow with a unit"),
        (None, {}, "burner.air_flow: None is not a gas flow with a unit"),
        # a plain volume flow needs its reference state
        (
            "3 m3/h",
            {},
            'burner.air_flow: "3 m3/h" is a volume flow at an unstated temperature and pressure; '
            "expected a normal volume flow such as 12 Nm3/h, a mass flow (kg/h) or a molar flow "
            "(mol/s), or give burner.reference_temperature",
        ),
        ("1.42 L/s", {"reference_pressure": 1e5}, "or give burner.reference_temperature"),
        # the unit's reference state contradicts the one given: ambiguous, refused
        (
            "12 Nm3/h",
            {"reference_temperature": 298.15},
            'burner.air_flow: "12 Nm3/h" is a normal volume flow (0 degC, 101325 Pa, DIN 1343) '
            "but burner.reference_temperature is 298.15 K: ambiguous",
        ),
        (
            "12 Sm3/h",
            {"reference_pressure": "1 bar"},
            "but burner.reference_pressure is 100000 Pa: ambiguous",
        ),
        ("10 scfm", {"reference_temperature": 288.15}, "(60 degF, 14.696 psia) but"),
        # bad numbers
        ("-2 kg/h", {}, 'burner.air_flow: "-2 kg/h" is negative, expected a flow > 0'),
        ("-2 kg/h", {"allow_zero": True}, "is negative, expected a flow >= 0"),
        ("nan kg/h", {}, 'burner.air_flow: "nan kg/h" is not a finite number'),
        ("inf Nm3/h", {}, 'burner.air_flow: "inf Nm3/h" is not a finite number'),
        ("1e400 kg/h", {}, "is not a finite number"),
        (math.nan, {}, "burner.air_flow: nan is not a finite number"),
        ("2,5 kg/h", {}, 'burner.air_flow: "2,5 kg/h" has a comma'),
        # bad units
        ("3 m", {}, 'burner.air_flow: "3 m" is a length, expected a mass flow'),
        ("12 Nm3", {}, 'burner.air_flow: "12 Nm3" is not a normal or standard volume per time'),
        ("12 nm3/h", {}, 'write "Nm3/h" for a normal volume flow'),
        ("5 sccm", {}, "the reference state of sccm differs between makers"),
        ("12 blorps/h", {}, 'has an unknown unit "blorps/h"'),
        ("fast", {}, 'burner.air_flow: "fast" is not a flow with a unit'),
        # the reference values themselves
        (
            "3 m3/h",
            {"reference_temperature": -3.0},
            "burner.reference_temperature: -3.0 is not > 0",
        ),
        ("3 m3/h", {"reference_temperature": "2 m"}, "burner.reference_temperature: "),
    ],
)
def test_refusals_name_the_field_the_value_and_what_is_accepted(value, kwargs, message):
    with pytest.raises(InputError, match=re.escape(message)) as info:
        gas_flow(value, FIELD, **kwargs)
    assert "\n" not in str(info.value)


def test_the_section_of_a_nested_or_bare_field():
    with pytest.raises(InputError, match=r"give kiln\.burner\.reference_temperature$"):
        gas_flow("3 m3/h", "kiln.burner.primary_air")
    with pytest.raises(InputError, match=r"^air_flow: .* or give reference_temperature$"):
        gas_flow("3 m3/h", "air_flow")


def test_molar_volume():
    # the tabulated values at 1 atm, to the half unit of their last printed digit
    assert molar_volume(273.15) == pytest.approx(22.414e-3, abs=0.5e-6)
    assert molar_volume(288.15) == pytest.approx(23.645e-3, abs=0.5e-6)
    assert molar_volume(298.15) == pytest.approx(24.465e-3, abs=0.5e-6)
    assert molar_volume(*NORMAL_STATE) == pytest.approx(V_N, rel=1e-5)
    assert molar_volume(273.15, 2 * 101325.0) == pytest.approx(V_N / 2, rel=1e-5)
    v = molar_volume(np.array([273.15, 298.15]))
    assert isinstance(v, np.ndarray) and v.shape == (2,)
    with pytest.raises(InputError, match="T: -1 K is not > 0"):
        molar_volume(-1.0)
    with pytest.raises(InputError, match="p: "):
        molar_volume(300.0, math.nan)


@pytest.mark.parametrize(
    "unit", ["kg/h", "g/s", "t/h", "mol/s", "kmol/h", "Nm3/h", "NL/s", "Sm3/h", "scfm", "L/min"]
)
def test_a_flow_unit_read_once_converts_its_next_texts_as_pint_does(unit, monkeypatch):
    """A study's sampled flows are new texts with a known unit: converted by that unit's
    factor, to the same floats as pint's conversion of the whole text."""
    from rotarykiln import units

    ref_t = 298.15 if unit == "L/min" else None
    texts = [f"{v:.9g} {unit}" for v in np.random.default_rng(1).uniform(1e-3, 3000.0, 200)]
    fast = [units._gas_flow(t, "f", reference_temperature=ref_t) for t in texts]
    monkeypatch.setattr(units, "_flow_unit", lambda pint_unit: None)  # through pint each time
    slow = [units._gas_flow(t, "f", reference_temperature=ref_t) for t in texts]
    assert fast == slow
