import textwrap

import pytest

from rotarykiln.chemistry.mechanism import Mechanism
from rotarykiln.chemistry.reaction import builtin_reactions, load_reactions, reaction_from_dict
from rotarykiln.errors import InputError

GOOD = {
    "name": "calc",
    "stoichiometry": {"CaCO3": -1, "CaO": 1, "CO2": 1},
    "basis": "CaCO3",
    "rate": {"law": "arrhenius", "A": 1e5, "E": 1.5e5},
    "heat": "178 kJ/mol",
}


def test_all_builtin_reactions_load_and_balance():
    rx = builtin_reactions()
    assert {
        "drying_ahmad",
        "drying_heat_limited",
        "calcination_luisser",
        "calcination_equilibrium",
        "activation_ortiz",
    } <= set(rx)
    assert sum(n.startswith("pyrolysis_wen_yen") for n in rx) == 5
    for r in rx.values():
        assert all(abs(v) < 1e-12 for v in r.element_residual().values()), r.name


def test_heat_units_molar_and_specific():
    r = reaction_from_dict(GOOD)
    assert r.heat == pytest.approx(178e3 / 0.100086, rel=1e-6)
    r2 = reaction_from_dict({**GOOD, "heat": {"value": "1.7 MJ/kg", "T_ref": "600 degC"}})
    assert r2.heat == pytest.approx(1.7e6) and r2.T_ref == pytest.approx(873.15)
    r3 = reaction_from_dict({**GOOD, "heat": 1.0e6})
    assert r3.heat == 1.0e6 and r3.T_ref == 298.15


@pytest.mark.parametrize(
    "change, match",
    [
        ({"stoichiometry": {"CaCO3": -1, "CaO": 1}}, "not element-balanced"),
        (
            {"stoichiometry": {"CaCO3": -1, "CaO": 1, "CO2": 1, "foo": 1}},
            r"stoichiometry\.foo: foo is not a known species",
        ),
        ({"basis": "CaO"}, "not a reactant"),
        ({"basis": "CO2"}, "not a reactant"),
        ({"rate": {"law": "nope"}}, "not a known rate law"),
        ({"rate": {"law": "arrhenius", "Q": 1}}, r"rate\.Q: given is not a parameter of arrhenius"),
        ({"rate": {"law": "arrhenius", "A": -1}}, r"rate\.A: -1 is not > 0"),
        ({"rate": {"law": "arrhenius", "pressure_orders": {"CaO": 1}}}, "a gas species"),
        ({"heat": "3 m"}, "expected a molar energy"),
        ({"heat": [1]}, "heat.value"),
        ({"stoichiometry": {"CaCO3": -1, "CaO": 0, "CO2": 1}}, "non-zero"),
    ],
)
def test_bad_reactions_refused_at_load(change, match):
    with pytest.raises(InputError, match=match):
        reaction_from_dict({**GOOD, **change})


def test_missing_key_refused():
    d = dict(GOOD)
    del d["heat"]
    with pytest.raises(InputError, match="calc.heat: missing"):
        reaction_from_dict(d)


def test_user_reaction_from_yaml(tmp_path):
    p = tmp_path / "user.yaml"
    p.write_text(
        textwrap.dedent("""
        reactions:
          - name: char_oxidation
            equation: C + O2 -> CO2
            stoichiometry: {C: -1, O2: -1, CO2: 1}
            basis: C
            rate: {law: arrhenius, A: 2.0, E: 80000.0, pressure_orders: {O2: 1.0}}
            heat: -393.5 kJ/mol
            source: test
    """)
    )
    mech = Mechanism.from_yaml(p)
    assert mech.names == ("char_oxidation",)
    assert mech.reactions[0].heat == pytest.approx(-393.5e3 / 0.012011, rel=1e-6)


def test_bad_yaml_file(tmp_path):
    p = tmp_path / "bad.yaml"
    p.write_text("reactions: {a: 1}\n")
    with pytest.raises(InputError, match="reactions' list"):
        load_reactions(p)
    p.write_text("reactions:\n  - name: [\n")
    with pytest.raises(InputError, match="malformed YAML"):
        load_reactions(p)
    with pytest.raises(InputError, match="no such reaction file"):
        load_reactions(tmp_path / "missing.yaml")
    item = (
        "  - {name: a, stoichiometry: {H2O(l): -1, H2O: 1}, basis: H2O(l),"
        " rate: heat_limited_drying, heat: 0}\n"
    )
    p.write_text("reactions:\n" + item + item)
    with pytest.raises(InputError, match="unique reaction name"):
        load_reactions(p)


def test_kirchhoff_shift_of_heat():
    r = builtin_reactions()["calcination_luisser"]
    # products' c_p lower than the reactant's: endothermic heat falls with T
    assert r.delta_cp < 0
    assert r.heat_at(1173.15) < r.heat < r.heat_at(298.15)
    assert r.heat_at(r.T_ref) == pytest.approx(r.heat)
