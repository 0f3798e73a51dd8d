"""``case_with``: a case with a few fields changed, equal to the parse of the changed case file
(issue 25, item 2: the per-variant set-up of studies)."""

from __future__ import annotations

import copy
import textwrap

import pytest

import rotarykiln.case as case_module
from rotarykiln.case import (
    case_with,
    change_fields,
    load_case,
    parse_case,
    read_case_data,
)
from rotarykiln.case_io import dump_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.errors import InputError
from rotarykiln.units import gas_flow, to_si

# One case of each kind: lined hot-air kiln, fired kilns, reacting kilns (U wall, Kramers bed,
# jacket), the transverse retort, an RTD case.
CASES = [
    "tscheng_A16",
    "tscheng_A40",
    "barr_T4",
    "barr_T2",
    "ubc_pilot_flame",
    "charcoal_activation",
    "charcoal_activation_kramers",
    "limestone_calcination",
    "limestone_fired",
    "rotary_pyrolysis",
    "retort/case01",
    "rtd/bongo_njeng_sand_rl",
]

CHANGES = [
    {"operation.speed": "2.1 rpm"},
    {"operation.feed": "20 kg/h"},
    {"operation.speed": "2.5 rpm", "gas.flow": "30 kg/h"},
    {"gas.temperature": "600 K"},
    {"gas.flow": 0.01},
    {"operation.feed_temperature": "30 degC", "operation.counter_current": False},
    {"kiln.slope": "2 deg", "kiln.length": "3 m"},
    {"kiln": {"length": "3 m", "diameter": "0.5 m"}},
    {"bed.fill": 0.1},
    {"bed.fill": [0.1, 0.12, 0.15]},
    {"bed.fill": None, "bed.residence_time": "20 min"},
    {"bed.residence_time": "20 min", "bed.fill": None},
    {"bed.axial_dispersion": 20},
    {"burner.fuel_flow": "2.1 L/s"},
    {"burner.primary_air.flow": "20 L/s"},
    {"burner.primary_air": {"flow": "20 L/s", "temperature": "300 K"}},
    {"burner.fuel_flow": "2.5 L/s", "burner.secondary_air.flow": "60 L/s"},
    {"burner.nozzle_diameter": "20 mm", "burner.combustion": "burnout"},
    {"burner.air_ingress": {"flow": "1 kg/h"}},
    {"wall.lining[0].thickness": "80 mm"},
    {"wall.lining.1.thickness": "7 mm", "wall.lining.0.absent": [["0.5 m", "1 m"]]},
    {"wall.lining[0]": {"material": "fireclay_brick", "thickness": "0.1 m"}},
    {"wall.lining[0].material.emissivity": 0.7},
    {"wall.lining": [{"material": "fireclay_brick", "thickness": "0.1 m"}]},
    {"wall.ambient_temperature": "20 degC", "wall.wind_speed": "2 m/s"},
    {"wall.emissivity": None},
    {"wall.U": "6 W/m2/K"},
    {"wall.jacket.flow": "150 kg/h"},
    {"wall.heaters": [{"start": "1 m", "end": "2 m", "power": "5 kW"}]},
    {"material.particle_size": "1 mm", "material.bulk_density": "1500 kg/m3"},
    {"material.composition": {"CaCO3": 1.0}},
    {"material.solid": "limestone"},
    {"measurements.wall_interface": 0},
    {"measurements.z_gas": None, "measurements.t_gas": None},
    {"measurements.t_gas": ["400 K"]},
    {"closures.preset": "seed004"},
    {"closures.radiation_model": "banded", "closures.near_bed_mixing": "5 W/m2/K"},
    {"closures": None},
    {"rtd.peclet": 50},
    {"rtd": {"peclet": 50, "lifters": {"type": "straight", "count": 6}}},
    {"rtd.lifters.count": 6},
    {"solver.cells": 60},
    {"solver": {"cells": 1e3}},
    {"name": "variant", "description": "a variant"},
    {"transport.dam_height": "5 cm"},
    {"transport.volume": "bulk"},
    {"chemistry.onset_width": 5.0, "chemistry.kirchhoff": True},
    {"chemistry.reactions": ["drying_ahmad"]},
    {"gas.mass_fractions": {"N2": 1.0}},
    {"gas.composition": "N2:0.79, O2:0.21"},
    {"transverse.duration": "100 s", "transverse.grid.zones": 30},
    {"transverse.shale.mean_size": "2 mm"},
    {"transverse.snapshot_times": ["5 s", "50 s"]},
    {"operation.speed": "2 rpm", "operation": {"speed": "3 rpm"}},  # a later change replaces
    {"operation": {"speed": "3 rpm"}, "operation.feed": "1 kg/h"},  # inside an earlier value
    {
        "wall.lining[0].thickness": "80 mm",
        "wall.lining": [{"material": "fireclay_brick", "thickness": "80 mm"}],
    },
    {"bed.fill": 0.1, "bed": {"residence_time": "1 h"}},  # fields changed, then replaced
]

BAD = [
    {"operation.speed": "3 m"},
    {"operation.speed": "1e6 rpm"},
    {"operation.speed": 2},
    {"operation.feed": "-1 kg/h"},
    {"gas.flow": "x"},
    {"gas.temperature": "100 K"},
    {"bed.fill": 1.5},
    {"bed.fill": [0.1, "x"]},
    {"bed.fill": []},
    {"bed.residence_time": "20 min"},  # with a fill: one or the other
    {"burner.fuel_flow": "20 L/s"},  # the air cannot burn it
    {"burner.primary_air.flow": "1 m"},
    {"wall.lining[0].thickness": "-1 mm"},
    {"wall.lining[0].thickness": None},
    {"wall.lining[5].thickness": "1 mm"},
    {"wall.lining[0].material": "unobtainium"},
    {"wall.U": "5 W/m2/K"},  # with a lining: one of them
    {"operation.sped": "1 rpm"},
    {"operation.speed.value": 1},
    {"kiln.length": None},
    {"kiln": None},
    {"operation.speed": "3 m", "gas.flow": "x", "kiln.length": "-1 m"},
    {"material.composition": {"nothing": 1.0}},
    {"chemistry.reactions": ["no_such_reaction"]},
    {"measurements.t_gas": ["400 K", "500 K"]},
    {"closures.preset": "best"},
    {"solver.cells": 3},
    {"rtd.lifters.count": 0},
    {"bad path": 1},
    {"wall.lining.x": 1},
    {"operation[0]": 1},
]


def _expected(name: str, changes: dict):
    """The parse of the case file with ``changes`` made: a case, or the InputError's text."""
    try:
        data = change_fields(read_case_data(builtin_case_path(name)), changes)
        return parse_case(data)
    except InputError as exc:
        return str(exc)


def _got(base, changes: dict):
    try:
        return case_with(base, changes)
    except InputError as exc:
        return str(exc)


def _same_case(got, want) -> None:
    """Equal values (bit for bit, -0.0 and NaN included) and the same fields given."""
    assert type(got) is type(want)
    assert got == want
    assert got.model_dump_json() == want.model_dump_json()
    assert dump_case(got) == dump_case(want)  # the fields given (defaults left implicit)


@pytest.fixture(scope="module")
def bases():
    return {name: load_case(builtin_case_path(name)) for name in CASES}


@pytest.mark.parametrize("name", CASES)
def test_case_with_equals_the_parse_of_the_changed_file(name, bases):
    base = bases[name]
    before = copy.deepcopy(base)
    for changes in CHANGES:
        want, got = _expected(name, changes), _got(base, changes)
        if isinstance(want, str):
            assert got == want, changes
        else:
            assert not isinstance(got, str), (changes, got)
            _same_case(got, want)
    assert base == before and dump_case(base) == dump_case(before)  # the base is not changed


@pytest.mark.parametrize("name", ["tscheng_A16", "barr_T4", "limestone_fired", "rotary_pyrolysis"])
def test_case_with_refuses_as_the_parse_of_the_changed_file(name, bases):
    refused = 0
    for changes in BAD:
        want, got = _expected(name, changes), _got(bases[name], changes)
        if isinstance(want, str):
            refused += 1
            assert got == want, changes
        else:  # a change bad for another case (a residence time where no fill is given)
            _same_case(got, want)
    assert refused >= len(BAD) - 3


@pytest.mark.parametrize(
    ("name", "changes"),
    [
        ("tscheng_A16", {"operation.speed": "2.7 rpm", "gas.flow": "21 kg/h"}),
        ("tscheng_A16", {"gas.temperature": "600 K", "bed.fill": 0.12}),
        ("tscheng_A16", {"wall.lining[2].thickness": "20 mm", "kiln.slope": "1 deg"}),
        ("tscheng_A16", {"wall.lining.0.thickness": "20 mm", "material.particle_size": "1 mm"}),
        ("barr_T4", {"operation.feed": "70 kg/h", "burner.fuel_flow": "2.1 L/s"}),
        ("barr_T4", {"burner.primary_air.flow": "20 L/s", "burner.secondary_air.flow": "50 L/s"}),
        ("barr_T4", {"burner.fuel_flow": "2.6 L/s", "burner.secondary_air.flow": "60 L/s"}),
        ("limestone_calcination", {"bed.residence_time": "1 h", "gas.flow": "0.06 kg/s"}),
        ("limestone_calcination", {"material.composition": {"CaCO3": 0.8, "H2O(l)": 0.2}}),
        ("rotary_pyrolysis", {"wall.jacket.temperature": "600 degC", "transport.shrinkage": 0.3}),
        ("tscheng_A16", {"rtd.peclet": 20, "closures.preset": "seed004"}),
        ("tscheng_A16", {"bed.fill": None, "bed.residence_time": "30 min"}),
    ],
)
def test_common_fields_take_the_fast_path(name, changes, bases, monkeypatch):
    """Operating fields are validated alone: no parse of the whole case, no writing back."""
    want = _expected(name, changes)

    def refused(*args, **kwargs):
        raise AssertionError("the whole case was parsed")

    monkeypatch.setattr(case_module, "parse_case", refused)
    monkeypatch.setattr(case_module, "change_fields", refused)
    _same_case(case_with(bases[name], changes), want)


def test_unchanged_sections_are_shared(bases):
    base = bases["barr_T4"]
    case = case_with(base, {"operation.feed": "70 kg/h"})
    assert case.burner is base.burner and case.wall is base.wall and case.kiln is base.kiln
    assert case.operation is not base.operation
    assert case_with(base, {}) is base


def test_case_with_own_species(tmp_path):
    """A case with its own species: compositions and reactions checked against them."""
    (tmp_path / "sp.yaml").write_text(
        textwrap.dedent(
            """
            bed:
              polymer:
                elements: {C: 2, H: 4}
                cp: {polynomial: {T_range: [250, 1000], coefficients: [1200.0, 2.0]}}
            gas:
              C2H4_user:
                elements: {C: 2, H: 4}
                h_f: 52.5 kJ/mol
                cp: {polynomial: {T_range: [250, 3000], coefficients: [1500.0]}}
            """
        ),
        encoding="utf-8",
    )
    path = tmp_path / "case.yaml"
    path.write_text(
        textwrap.dedent(
            """
            kiln: {length: 4 m, diameter: 0.5 m, slope: 2 deg}
            operation: {speed: 1.91 rpm, feed: 36 kg/h}
            material: {bulk_density: 500 kg/m3, composition: {polymer: 1.0}}
            bed: {residence_time: 1800 s}
            gas: {flow: 180 kg/h, temperature: 1000 K, mass_fractions: {N2: 1.0}}
            wall: {U: 5 W/m2/K}
            chemistry:
              species: sp.yaml
              reactions:
                - name: cracking
                  stoichiometry: {polymer: -1, C2H4_user: 1}
                  basis: polymer
                  rate: {law: arrhenius, A: 1.0e14, E: 220000.0}
                  heat: 1.0 MJ/kg
            """
        ),
        encoding="utf-8",
    )
    base, data = load_case(path), read_case_data(path)
    for changes in [
        {"operation.feed": "40 kg/h"},
        {"gas.mass_fractions": {"N2": 0.9, "C2H4_user": 0.1}},
        {"material.composition": {"polymer": 1.0}},
        {"material.composition": {"nothing": 1.0}},
        {"chemistry.kirchhoff": True},
        {"chemistry.species": None},
        {"chemistry.species.bed.polymer.elements.C": 3},
    ]:
        try:
            want = parse_case(change_fields(data, changes))
        except InputError as exc:
            want = str(exc)
        got = _got(base, changes)
        if isinstance(want, str):
            assert got == want, changes
        else:
            _same_case(got, want)


def test_replace_is_case_with(bases):
    base = bases["barr_T4"]
    changes = {"operation.speed": "3 rpm", "wall.lining[0].thickness": "90 mm"}
    _same_case(base.replace(changes), case_with(base, changes))
    _same_case(base.replace(bed={"fill": 0.1}), case_with(base, {"bed": {"fill": 0.1}}))


def test_case_with_refuses_what_is_not_a_case():
    with pytest.raises(TypeError, match="not a validated case"):
        case_with({"operation": {}}, {"operation.speed": "1 rpm"})
    base = load_case(builtin_case_path("tscheng_A16"))
    with pytest.raises(TypeError, match="not a mapping"):
        case_with(base, [("operation.speed", "1 rpm")])


def test_cached_conversions_give_the_same_values_and_messages():
    """to_si and gas_flow keep the SI value of a text; a refusal still names its field."""
    for _ in range(2):
        assert to_si("a", "1.5 rpm", "rotation rate") == 1.5 * 2 * 3.141592653589793 / 60
        for field in ("a", "b"):
            with pytest.raises(InputError, match=f'^{field}: "3 m" is a length'):
                to_si(field, "3 m", "rotation rate")
            with pytest.raises(InputError, match=f"^burner.{field}: "):
                gas_flow("3 m3/h", f"burner.{field}")
    first = gas_flow("12 Nm3/h", "burner.fuel_flow")
    assert gas_flow("12 Nm3/h", "x") == first
    plain = gas_flow("1.42 L/s", "x", reference_temperature=298.15)
    assert gas_flow("1.42 L/s", "x", reference_temperature=298.15) == plain
    with pytest.raises(InputError, match="unstated temperature"):
        gas_flow("1.42 L/s", "x")
    with pytest.raises(InputError, match="zero"):
        gas_flow("0 kg/h", "x")
    assert gas_flow("0 kg/h", "x", allow_zero=True).value == 0.0


@pytest.mark.parametrize("name", ["tscheng_A16", "barr_T4", "limestone_fired", "retort/case03"])
def test_case_with_random_combinations(name, bases):
    """Several changes at once, good and bad, in any order: as the parse of the changed file."""
    import random

    rng = random.Random(name)
    pool = CHANGES + BAD
    base = bases.get(name) or load_case(builtin_case_path(name))
    for _ in range(60):
        changes = {}
        for c in rng.sample(pool, rng.randint(2, 5)):
            changes.update(c)
        want, got = _expected(name, changes), _got(base, changes)
        if isinstance(want, str):
            assert got == want, changes
        else:
            _same_case(got, want)
