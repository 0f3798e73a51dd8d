"""check_composition and molar_mass: fuel and gas compositions checked against GRI-Mech 3.0
(issue 10)."""

import math
import re

import pytest

from rotarykiln.errors import InputError
from rotarykiln.materials.gas import check_composition, gas_table, molar_mass

FIELD = "burner.fuel"
NATURAL_GAS = "CH4:0.95, C2H6:0.03, N2:0.01, CO2:0.01"


def test_a_natural_gas_is_returned_sorted_in_gri30_spelling():
    assert check_composition(NATURAL_GAS, FIELD) == (
        ("C2H6", 0.03),
        ("CH4", 0.95),
        ("CO2", 0.01),
        ("N2", 0.01),
    )


@pytest.mark.parametrize("text", ["Ar:0.01, N2:0.99", "AR:0.01, N2:0.99", "ar:0.01, n2:0.99"])
def test_species_are_matched_ignoring_case(text):
    assert check_composition(text, FIELD) == (("AR", 0.01), ("N2", 0.99))


def test_other_accepted_forms():
    # a mapping (YAML), the returned tuple itself, odd spacing, zeros, gri30 names with brackets
    assert check_composition({"CH4": 0.9, "n2": "0.1"}, FIELD) == (("CH4", 0.9), ("N2", 0.1))
    checked = check_composition(NATURAL_GAS, FIELD)
    assert check_composition(checked, FIELD) == checked
    assert check_composition(" CH4 : 1 ,  N2:0 ,", FIELD) == (("CH4", 1.0),)
    assert check_composition("CH2(S):1", FIELD) == (("CH2(S)", 1.0),)


def test_a_sum_within_the_tolerance_is_normalised():
    ((name, x),) = check_composition("CH4:0.9995", FIELD)
    assert name == "CH4" and x == 1.0
    pairs = check_composition("CH4:0.5, N2:0.5005", FIELD)
    assert math.fsum(x for _, x in pairs) == pytest.approx(1.0, abs=1e-12)


@pytest.mark.parametrize(
    ("value", "message"),
    [
        ("", 'burner.fuel: "" is empty; expected mole fractions summing to 1'),
        (" , ", 'burner.fuel: " , " is empty'),
        ({}, "burner.fuel: {} is empty"),
        (
            "CH4:0.95, Methane:0.05",
            'burner.fuel: "CH4:0.95, Methane:0.05" has unknown species "Methane"; expected '
            "species of gri30.yaml (case ignored), e.g. CH4",
        ),
        ("CH5:1", 'has unknown species "CH5" (did you mean'),
        ("CH4:nan", 'burner.fuel: "CH4:nan": the fraction nan of CH4 is not a finite number >= 0'),
        ("CH4:inf", "the fraction inf of CH4 is not a finite number >= 0"),
        ("CH4:-0.1, N2:1.1", "the fraction -0.1 of CH4 is not a finite number >= 0"),
        ({"CH4": math.nan}, "the fraction nan of CH4 is not a finite number"),
        ("CH4:abc", 'the fraction "abc" of CH4 is not a number'),
        ("CH4:95%, N2:5%", 'the fraction "95%" of CH4 is not a number'),
        (
            "CH4:0.95, C2H6:0.03",
            'burner.fuel: "CH4:0.95, C2H6:0.03" has mole fractions summing to 0.98, expected 1 '
            "(within 0.001)",
        ),
        ("CH4:0.5, N2:0.502", "summing to 1.002, expected 1"),
        ("CH4:95, N2:5", "summing to 100, expected 1 (within 0.001) (percentages?"),
        ("CH4:1, N2:0, CH4:0", 'burner.fuel: "CH4:1, N2:0, CH4:0" gives CH4 twice'),
        ("Ar:0.5, AR:0.5", "gives AR twice"),
        ("CH4", 'burner.fuel: "CH4" has "CH4", not "species:fraction"'),
        ("CH4:0.5:0.5", 'has "CH4:0.5:0.5", not "species:fraction"'),
        (5, "burner.fuel: 5 is not a composition"),
    ],
)
def test_refusals_name_the_field_the_value_and_what_is_accepted(value, message):
    with pytest.raises(InputError, match=re.escape(message)) as info:
        check_composition(value, FIELD)
    assert "\n" not in str(info.value)
    assert info.value.field == FIELD


def test_molar_mass_of_pure_species_and_mixtures():
    assert molar_mass("CH4:1") == pytest.approx(16.043e-3, rel=1e-4)
    assert molar_mass("N2:1") == pytest.approx(28.014e-3, rel=1e-4)
    assert molar_mass("ar:1") == pytest.approx(39.948e-3, rel=1e-4)
    expected = 0.95 * 16.043e-3 + 0.03 * 30.070e-3 + 0.01 * 28.014e-3 + 0.01 * 44.010e-3
    assert molar_mass(NATURAL_GAS) == pytest.approx(expected, rel=1e-4)
    assert molar_mass(check_composition(NATURAL_GAS, FIELD)) == molar_mass(NATURAL_GAS)
    # agrees with the mixture Cantera builds for the property tables
    air = "O2:0.2095, N2:0.7808, AR:0.0097"
    assert molar_mass(air) == pytest.approx(gas_table(air).molar_mass, rel=1e-9)


def test_molar_mass_refuses_a_bad_composition():
    with pytest.raises(InputError, match=r'^composition: "CH4:0.5" has mole fractions summing'):
        molar_mass("CH4:0.5")
