import math
import textwrap

import pytest
import yaml

from rotarykiln.case import load_case, parse_case
from rotarykiln.cases import builtin_case_path, list_builtin_cases
from rotarykiln.errors import InputError

GOOD = {
    "kiln": {"length": "5.5 m", "diameter": "0.406 m", "slope": "2 deg"},
    "operation": {"speed": "1.5 rpm", "feed": "62 kg/h"},
    "material": {"bulk_density": "1500 kg/m3", "repose_angle": "35 deg"},
    "bed": {"fill": "12 %"},
}


def with_change(path: str, value):
    data = yaml.safe_load(yaml.safe_dump(GOOD))
    keys = path.split(".")
    node = data
    for k in keys[:-1]:
        node = node[k]
    node[keys[-1]] = value
    return data


def test_good_case_is_converted_to_si():
    case = parse_case(GOOD)
    assert case.kiln.slope == pytest.approx(math.radians(2))
    assert case.operation.speed == pytest.approx(1.5 * 2 * math.pi / 60)
    assert case.operation.feed == pytest.approx(62 / 3600)
    assert case.bed.fill == pytest.approx(0.12)


@pytest.mark.parametrize(
    ("path", "value", "message"),
    [
        ("kiln.diameter", "-0.4 m", "kiln.diameter: -0.4 m is not in [1 um, 10 km]"),
        ("operation.speed", "3 m", 'operation.speed: "3 m" is a length, expected a rotation rate'),
        ("operation.speed", "-1 rpm", "operation.speed: -1 rpm is not in [1e-5 rpm, 955 rpm]"),
        ("bed.fill", 1.0, "bed.fill: 1.0 is not in [0.001, 1)"),
        ("bed.fill", "120 %", "bed.fill: 120 % is not in [0.001, 1)"),
        ("bed.fill", 1e-308, "bed.fill: 1e-308 is not in [0.001, 1)"),
        (
            "operation.feed_temperature",
            "1 K",
            "operation.feed_temperature: 1 K is not in [150 K, 10000 K]",
        ),
        (
            "kiln.diamter",
            "0.4 m",
            'kiln.diamter: unknown key, did you mean "diameter"? '
            "(accepted keys: length, diameter, slope)",
        ),
        ("material.repose_angle", "95 deg", "material.repose_angle: 95 deg is not in (0, 90) deg"),
    ],
)
def test_bad_values_give_one_clear_line(path, value, message):
    with pytest.raises(InputError) as info:
        parse_case(with_change(path, value))
    text = str(info.value)
    assert "\n" not in text
    assert text.startswith(message)


def test_missing_section():
    data = dict(GOOD)
    del data["kiln"]
    with pytest.raises(InputError, match="^kiln: missing"):
        parse_case(data)


def test_malformed_yaml(tmp_path):
    p = tmp_path / "bad.yaml"
    p.write_text("kiln:\n  length: 5 m\n   diameter: [0.4 m\n")
    with pytest.raises(InputError, match="malformed YAML at line"):
        load_case(p)


def test_missing_file(tmp_path):
    with pytest.raises(InputError, match="no such case file"):
        load_case(tmp_path / "nope.yaml")


def test_not_a_mapping(tmp_path):
    p = tmp_path / "list.yaml"
    p.write_text("- a\n- b\n")
    with pytest.raises(InputError, match="expected a mapping"):
        load_case(p)


def test_every_builtin_case_validates():
    names = list_builtin_cases()
    assert "tscheng_A16" in names
    for name in names:
        text = builtin_case_path(name).read_text()
        data = yaml.safe_load(text)
        if isinstance(data, dict) and "kiln" in data:
            parse_case(data)


def test_load_case_from_file(tmp_path):
    p = tmp_path / "c.yaml"
    p.write_text(textwrap.dedent(yaml.safe_dump(GOOD)))
    assert load_case(p).kiln.length == 5.5


def renamed(path: str, new_key: str):
    """GOOD with the key at ``path`` renamed (a typo in a key: the real key becomes missing)."""
    data = yaml.safe_load(yaml.safe_dump(GOOD))
    keys = path.split(".")
    node = data
    for k in keys[:-1]:
        node = node[k]
    node[new_key] = node.pop(keys[-1])
    return data


@pytest.mark.parametrize(
    ("path", "typo", "message"),
    [
        # the typo is reported, not the "missing" key it causes
        ("kiln", "kilm", 'kilm: unknown key, did you mean "kiln"?'),
        ("kiln.diameter", "diamter", 'kiln.diamter: unknown key, did you mean "diameter"?'),
        ("operation.speed", "sped", 'operation.sped: unknown key, did you mean "speed"?'),
    ],
)
def test_misspelt_key_is_reported_before_the_missing_one(path, typo, message):
    with pytest.raises(InputError) as info:
        parse_case(renamed(path, typo))
    assert str(info.value).startswith(message)


WALL = {"lining": [{"material": "fireclay_brick", "thickness": "50 mm"}]}


def test_misspelt_key_in_a_list_item_lists_the_accepted_keys():
    # the accepted keys used to be empty for keys inside list items (wall.lining.N)
    data = dict(GOOD, wall={"lining": [{"material": "fireclay_brick", "thicknes": "5 cm"}]})
    with pytest.raises(InputError) as info:
        parse_case(data)
    assert str(info.value).startswith(
        'wall.lining.0.thicknes: unknown key, did you mean "thickness"? '
        "(accepted keys: material, thickness, absent, thickness_profile)"
    )


@pytest.mark.parametrize(
    ("edit", "message"),
    [
        # used to be reported as "material.solid" / "lining.material" at run time
        (
            {"material": {"solid": "sandd"}, "wall": WALL},
            'material.solid: "sandd" is not one of charcoal, lime,',
        ),
        (
            {"wall": {"lining": [{"material": "fire brick", "thickness": "50 mm"}]}},
            'wall.lining.0.material: "fire brick" is not one of carbon_steel,',
        ),
    ],
)
def test_unknown_library_names_are_reported_at_their_path(edit, message):
    with pytest.raises(InputError) as info:
        parse_case(dict(GOOD, **edit))
    assert str(info.value).startswith(message)


def test_empty_case_file(tmp_path):
    p = tmp_path / "empty.yaml"
    p.write_text("")
    with pytest.raises(InputError, match="empty.yaml: the case is empty"):
        load_case(p)


@pytest.mark.parametrize("value", [1e-308, 1e300])
def test_a_bed_peclet_number_outside_the_rtd_models_range_is_refused_at_load(value):
    """A Peclet number of 1e-308 reached the kiln's Newton as NaN at its first step (the case
    fuzz campaign): the bed's and the RTD section's Peclet numbers take the RTD models' range."""
    import yaml

    from rotarykiln.case import PECLET_RANGE, parse_case
    from rotarykiln.cases import builtin_case_path
    from rotarykiln.errors import InputError
    from rotarykiln.rtd.dispersion import SHAPE_RANGE

    assert PECLET_RANGE == SHAPE_RANGE
    raw = yaml.safe_load(builtin_case_path("limestone_fired").read_text())
    raw.setdefault("bed", {})["axial_dispersion"] = value
    with pytest.raises(InputError, match=r"bed.axial_dispersion: .* is not in \[1e-06, 1e\+10\]"):
        parse_case(raw)
