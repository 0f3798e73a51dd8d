"""Bad burner input is refused at load with one line naming the field (issue 10)."""

from __future__ import annotations

import pytest
import yaml

from rotarykiln import cli
from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.errors import InputError
from rotarykiln.kiln.combustion.flame import AirStream, Burner, fire
from rotarykiln.kiln.from_case import kiln_from_case


def _barr(**burner):
    data = yaml.safe_load(builtin_case_path("barr_T4").read_text())
    b = data["burner"]
    for key, value in burner.items():
        if value is None:
            b.pop(key, None)
        else:
            b[key] = value
    return data


@pytest.mark.parametrize(
    ("change", "match"),
    [
        ({"primary_air": None, "secondary_air": None}, "burner: fuel without air"),
        (
            {"primary_air": {"flow": "0 L/s"}, "secondary_air": {"flow": "0 L/s"}},
            "air flows sum to 0",
        ),
        ({"fuel_flow": None}, "burner.fuel_flow: missing"),
        ({"fuel_flow": "0 L/s"}, "fuel_flow.*zero"),
        ({"fuel_flow": "-1 kg/h"}, "fuel_flow.*negative"),
        ({"fuel": "CH4:0.9, N2:0.05"}, "burner.fuel.*summing to 0.95"),
        ({"fuel": "C2H8:1"}, "burner.fuel.*unknown species"),
        ({"fuel": "CH4:1, N2:nan"}, "burner.fuel.*not a finite number"),
        ({"reference_temperature": None}, "fuel_flow.*unstated temperature"),
        ({"fuel_flow": "2 Sm3/h"}, "fuel_flow.*ambiguous"),
        ({"fuel_temperature": "-5 K"}, "burner.fuel_temperature"),
        ({"secondary_air": {"flow": "40 L/s", "temperature": "-3 K"}}, "secondary_air"),
        ({"combustion": "magic"}, "burner.combustion"),
        ({"flame_length": "0 m"}, "burner.flame_length"),
    ],
)
def test_refused_at_load(change, match):
    with pytest.raises(InputError, match=match) as exc:
        parse_case(_barr(**change))
    assert "\n" not in str(exc.value)


def test_ar_and_AR_both_accepted():
    for spelling in ("Ar", "AR"):
        case = parse_case(_barr(fuel=f"CH4:0.99, {spelling}:0.01"))
        assert "AR" in case.burner.fuel


def test_flame_override_longer_than_the_kiln():
    with pytest.raises(InputError, match="burner.flame_length.*kiln length"):
        kiln_from_case(parse_case(_barr(combustion="burnout", flame_length="7 m")))


def test_burnout_without_flame_length_or_nozzle():
    with pytest.raises(InputError, match="burner.flame_length.*nozzle_diameter"):
        kiln_from_case(parse_case(_barr(combustion="burnout")))


def test_normal_volume_flow_is_accepted():
    data = _barr(reference_temperature=None)
    b = data["burner"]
    b["fuel_flow"] = "7.092 Nm3/h"  # 1.97 NL/s
    b["primary_air"] = {"flow": "62.64 Nm3/h"}
    b["secondary_air"] = {"flow": "154.8 Nm3/h"}
    case = parse_case(data)
    kiln, _ = kiln_from_case(case)
    assert kiln.firing.flame.fuel_lhv == pytest.approx(70.5e3, rel=2e-3)
    assert case is not None


def test_cli_exit_code_2_and_one_line(tmp_path, capsys):
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(_barr(fuel="C2H8:1")))
    assert cli.main(["run", str(path), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip()
    assert "burner.fuel" in err and "Traceback" not in err and len(err.splitlines()) == 1


def test_burner_dataclass_checks():
    with pytest.raises(InputError, match="burner.fuel_flow"):
        Burner("CH4:1", 0.0, AirStream(0.01))
    with pytest.raises(InputError, match="burner.primary_air.flow"):
        Burner("CH4:1", 1e-3, AirStream(0.0))
    with pytest.raises(InputError, match="kiln.diameter"):
        fire(Burner("CH4:1", 1e-3, AirStream(0.02)), -1.0)


def test_heat_gas_composition_checked_at_load():
    data = yaml.safe_load(builtin_case_path("tscheng_A16").read_text())
    data["gas"]["composition"] = "O2:0.21, N2:nan"
    with pytest.raises(InputError, match="gas.composition"):
        parse_case(data)


def test_air_streams_that_cannot_burn_the_fuel_are_refused_at_load():
    """Primary + secondary air below the fuel's stoichiometric air: one line naming the burner,
    the two flows and the air ratio; the built-in fired cases (air ratio > 1) load."""
    import yaml

    from rotarykiln.case import parse_case
    from rotarykiln.cases import builtin_case_path
    from rotarykiln.errors import InputError

    raw = yaml.safe_load(builtin_case_path("barr_T4").read_text())
    raw["burner"]["primary_air"]["flow"] = "1.0 L/s"
    raw["burner"]["secondary_air"]["flow"] = "2.0 L/s"
    with pytest.raises(InputError) as info:
        parse_case(raw)
    text = str(info.value)
    assert "burner" in text and "cannot burn the fuel" in text and "\n" not in text
    assert "air ratio of 0.16" in text  # 3 L/s of air for 1.97 L/s of CH4 (9.52 needed a litre)
    raw["burner"]["secondary_air"]["flow"] = "17.5 L/s"  # 18.5 L/s: just under 9.52 x 1.97
    with pytest.raises(InputError, match="cannot burn the fuel"):
        parse_case(raw)
    raw["burner"]["secondary_air"]["flow"] = "18.0 L/s"  # 19.0 L/s: an air ratio of 1.01
    assert parse_case(raw).burner is not None
