import numpy as np
import pytest

from rotarykiln.chemistry.species import (
    check_mass_fractions,
    default_species,
    species_table_from_dict,
)
from rotarykiln.errors import InputError


def test_molar_masses_match_standard_values():
    sp = default_species()
    # IUPAC-based molar masses, g/mol (CRC handbook values)
    expected = {
        "CaCO3": 100.086,
        "CaO": 56.077,
        "CO2": 44.009,
        "H2O": 18.015,
        "CO": 28.010,
        "CH4": 16.043,
    }
    for name, m in expected.items():
        assert sp[name].molar_mass * 1000 == pytest.approx(m, abs=2e-3)


def test_phases_and_required_species_present():
    sp = default_species()
    for s in ["H2O(l)", "CaCO3", "CaO", "C", "ash", "kerogen", "inert"]:
        assert sp[s].phase == "bed"
    for s in ["N2", "O2", "CO2", "H2O", "CO", "H2", "CH4", "volatiles"]:
        assert sp[s].phase == "gas"
    for e in ["C", "H", "O", "Ca", "N"]:
        assert e in sp.elements


def test_element_mass_fractions_sum_to_one_per_species():
    sp = default_species()
    W = sp.element_mass_fractions()
    assert np.allclose(W.sum(axis=0), 1.0, rtol=1e-12)


def test_unknown_element_refused():
    with pytest.raises(InputError, match="Xx"):
        species_table_from_dict({"bed": {"A": {"elements": {"Xx": 1}}}, "elements": {"C": 12.0}})


def test_composition_refusals():
    with pytest.raises(InputError, match=r"feed\.CaCO3: -0\.1 is not a mass fraction in \[0, 1\]"):
        check_mass_fractions("feed", {"CaCO3": -0.1, "CaO": 1.1})
    with pytest.raises(InputError, match="summing to 1"):
        check_mass_fractions("feed", {"CaCO3": 0.5, "CaO": 0.4})
    with pytest.raises(InputError, match=r"feed\.unobtainium: unobtainium is not a known species"):
        check_mass_fractions("feed", {"unobtainium": 1.0})
    with pytest.raises(InputError, match="a bed species"):
        check_mass_fractions("feed", {"CO2": 1.0}, phase="bed")
    assert check_mass_fractions("feed", {"CaCO3": 0.9, "inert": 0.1}, phase="bed") == {
        "CaCO3": 0.9,
        "inert": 0.1,
    }
