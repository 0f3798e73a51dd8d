"""User species (YAML) for bed and gas: loading, checks at load, reactions on the extended table."""

import numpy as np
import pytest

from rotarykiln.chemistry import Mechanism
from rotarykiln.chemistry.biomass import (
    WOOD_PYROLYSIS,
    mechanism_from_files,
    tar_escape_fraction,
    wood_pyrolysis_mechanism,
)
from rotarykiln.chemistry.mechanism import CellState
from rotarykiln.chemistry.reaction import reaction_from_dict
from rotarykiln.chemistry.species import default_species, load_species
from rotarykiln.chemistry.thermo import thermo_from_dict
from rotarykiln.errors import InputError

# CO from the GRI-Mech 3.0 NASA polynomials, under another name so it is a new species
NASA_CO = {
    "nasa7": {
        "T_range": [200.0, 1000.0, 3500.0],
        "coefficients": [
            [3.57953347, -6.1035368e-4, 1.01681433e-6, 9.07005884e-10, -9.04424499e-13],
            [2.71518561, 2.06252743e-3, -9.98825771e-7, 2.30053008e-10, -2.03647716e-14],
        ],
    }
}
# CO2, NIST WebBook Shomate (298-1200 K), J/(mol K)
SHOMATE_CO2 = {
    "shomate": {
        "T_range": [298.0, 1200.0],
        "coefficients": [24.99735, 55.18696, -33.69137, 7.948387, -0.136638],
    }
}

USER = {
    "bed": {
        "straw": {
            "composition": {"C": 0.47, "H": 0.06, "O": 0.47},
            "molar_mass": "25.55 g/mol",
            "cp": {"polynomial": {"T_range": [250, 1000], "coefficients": [1500.0, 1.0]}},
            "description": "wheat straw, dry ash-free (lumped)",
        },
    },
    "gas": {
        "CO_user": {"elements": {"C": 1, "O": 1}, "cp": NASA_CO, "h_f": "-110.53 kJ/mol"},
        "CO2_user": {"elements": {"C": 1, "O": 2}, "cp": SHOMATE_CO2, "h_f": -393510.0},
    },
}


def test_user_species_extend_the_builtin_table():
    sp = load_species(USER)
    assert "CaCO3" in sp and "straw" in sp and "CO_user" in sp
    assert sp["straw"].phase == "bed" and sp["CO_user"].phase == "gas"
    # bed species first, then gas, as every table
    phases = [s.phase for s in sp.species]
    assert phases == sorted(phases)
    assert sp["straw"].molar_mass == pytest.approx(0.02555)
    assert sum(sp["straw"].elements[e] * sp.element_masses[e] for e in "CHO") == pytest.approx(
        0.02555
    )


def test_nasa_and_shomate_match_the_gas_tables():
    sp = load_species(USER)
    from rotarykiln.kiln.gas_mixture import GasMixture

    ref = GasMixture.of(("CO", "CO2"))
    T = np.array([400.0, 800.0, 1100.0])
    h_ref = ref.species_enthalpy(T)
    assert sp["CO_user"].thermo.enthalpy(T) == pytest.approx(h_ref[:, 0], rel=2e-3)
    assert sp["CO2_user"].thermo.enthalpy(T) == pytest.approx(h_ref[:, 1], rel=5e-3)


def test_user_gas_species_in_the_kiln_mixture():
    from rotarykiln.kiln.gas_mixture import mixture_of

    sp = load_species(USER)
    g = mixture_of(("N2", "CO_user"), sp)
    T = np.array([500.0, 900.0])
    h = g.species_enthalpy(T)[:, 1]
    assert h == pytest.approx(sp["CO_user"].thermo.enthalpy(T), rel=1e-6)


@pytest.mark.parametrize(
    "spec, match",
    [
        ({"bed": {"x": {"cp": 1000.0}}}, r"species\.x\.elements: missing"),
        ({"bed": {"x": {"elements": {}}}}, r"species\.x\.elements: .* non-empty"),
        (
            {"bed": {"x": {"elements": {"Zz": 1}}}},
            r"species\.x\.elements: \"?Zz\"? is not a known element",
        ),
        ({"bed": {"x": {"composition": {"C": 0.5, "O": 0.4}, "molar_mass": 0.03}}}, "summing to 1"),
        ({"bed": {"x": {"composition": {"C": 1.0}}}}, r"species\.x\.molar_mass: missing"),
        ({"bed": {"CaO": {"elements": {"Ca": 1, "O": 1}}}}, "unique"),
        ({"gas": {"x": {"elements": {"C": 1}, "cp": -5.0}}}, r"species\.x\.cp: -5 is not > 0"),
        (
            {
                "gas": {
                    "x": {
                        "elements": {"C": 1},
                        "cp": {
                            "polynomial": {
                                "T_range": [300, 1200],
                                "coefficients": [420.0, 2.09, -6.85e-3],
                            }
                        },
                    }
                }
            },
            r"species\.x\.cp\.polynomial: c_p -6936 J/\(kg K\) at 1200 K is not positive",
        ),
        (
            {
                "gas": {
                    "x": {
                        "elements": {"C": 1},
                        "cp": {"nasa7": {"T_range": [300, 1000], "coefficients": [1.0, 2.0]}},
                    }
                }
            },
            r"species\.x\.cp\.nasa7\.coefficients: 2 numbers is not 5 or 7",
        ),
        (
            {
                "gas": {
                    "x": {
                        "elements": {"C": 1},
                        "cp": {"shomate": {"T_range": [900, 300], "coefficients": [1, 2, 3, 4, 5]}},
                    }
                }
            },
            "increasing",
        ),
        ({"gas": {"x": {"elements": {"C": 1}, "cp": {"janaf": {}}}}}, "one of nasa7"),
        ({"bed": {"x": {"elements": {"C": 1}, "colour": "red"}}}, r"species\.x\.colour"),
    ],
)
def test_bad_species_refused_in_one_line(spec, match):
    with pytest.raises(InputError, match=match) as err:
        load_species(spec)
    assert "\n" not in str(err.value)


def test_reactions_on_user_species_are_checked_at_load():
    sp = load_species(USER)
    good = {
        "name": "straw_to_gas",
        "stoichiometry": {"straw": -1, "CO_user": 0.3, "CO2_user": 0.2, "H2O": 0.766},
        "basis": "straw",
        "rate": {"law": "arrhenius", "A": 1e8, "E": 1.4e5},
        "heat": "100 kJ/kg",
    }
    # an element-unbalanced stoichiometry is refused
    bad = dict(good, stoichiometry={"straw": -1, "CO_user": 1})
    with pytest.raises(InputError, match=r"straw_to_gas\.stoichiometry: .* element-balanced"):
        reaction_from_dict(bad, sp)
    # a reaction naming an undefined species
    undefined = dict(good, stoichiometry={"straw": -1, "CO_missing": 1})
    with pytest.raises(InputError, match=r"CO_missing\"? is not a known species"):
        reaction_from_dict(undefined, sp)
    # the same reaction against the built-in table: straw is undefined there
    with pytest.raises(InputError, match=r"straw\"? is not a known species"):
        reaction_from_dict(dict(good, stoichiometry={"straw": -1, "char": 1}), default_species())


def test_mechanism_from_files_with_a_species_section(tmp_path):
    f = tmp_path / "straw.yaml"
    f.write_text(
        """
species:
  bed:
    straw: {composition: {C: 0.5, H: 0.06, O: 0.44}, molar_mass: 0.024022, cp: 1400.0}
reactions:
  - name: straw_to_char
    stoichiometry: {straw: -1, char: 1}
    basis: straw
    rate: {law: arrhenius, A: 1.0e8, E: 1.4e5}
    heat: -100 kJ/kg
""",
        encoding="utf-8",
    )
    m = mechanism_from_files(files=[f], reactions=["wood_to_gas"])
    assert m.names == ("wood_to_gas", "straw_to_char")
    st = CellState.build(700.0, 700.0, {"straw": 0.01, "wood": 0.01}, 5.0, species=m.species)
    out = m.rates(st, check=True)
    assert out.of("char")[0] > 0 and out.of("pyrolysis_gas")[0] > 0
    # an unbalanced reaction in the file is refused at load
    f.write_text(f.read_text().replace("char: 1", "CO: 1"), encoding="utf-8")
    with pytest.raises(InputError, match="element-balanced"):
        mechanism_from_files(files=[f])


def test_builtin_wood_pyrolysis_mechanism():
    m = wood_pyrolysis_mechanism(tar_escape_fraction(2.0))
    assert m.names == WOOD_PYROLYSIS
    assert isinstance(m, Mechanism)
    # the two tar steps carry psi and 1 - psi of Di Blasi & Branca's 1.08e10 1/s
    A = {r.name: r.params["A"] for r in m.reactions}
    assert A["wood_to_tar_vapour"] + A["wood_to_tar_bed"] == pytest.approx(1.08e10)
    assert A["wood_to_tar_vapour"] / 1.08e10 == pytest.approx(0.69)
    # mass-based: every step moves 1 kg to 1 kg, and conserves the elements
    S = m.mass_stoichiometry
    assert np.allclose(S.sum(axis=1), 0.0, atol=1e-12)
    st = CellState.build(
        650.0,
        650.0,
        {"wood": 0.008, "intermediate_solid": 0.001, "tar(l)": 0.0005, "H2O(l)": 1e-5},
        2.0,
    )
    out = m.rates(st, check=True)
    assert out.production.sum() == pytest.approx(0.0, abs=1e-15)
    assert out.heat_absorbed[0] != 0.0
    # psi is bounded to [0, 1] (the script's formula passes 1 above 7.2 rpm)
    assert tar_escape_fraction(8.0) == 1.0
    with pytest.raises(InputError):
        wood_pyrolysis_mechanism(1.2)


def test_thermo_forms_are_consistent():
    th = thermo_from_dict(
        "tar", {"polynomial": {"T_range": [250, 1500], "coefficients": [-100, 4.4, -1.57e-3]}}, 0.1
    )
    T = np.linspace(300.0, 1400.0, 12)
    dh = (th.enthalpy(T + 0.01) - th.enthalpy(T - 0.01)) / 0.02
    assert dh == pytest.approx(th.cp(T), rel=1e-6)
    # beyond the range c_p is held at its end value
    assert th.cp(2000.0) == pytest.approx(th.cp(1500.0))
    assert th.enthalpy(298.15) == 0.0
