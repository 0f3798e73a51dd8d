"""Transient files: bad events refused with one line; the transient command end to end."""

import warnings

import pandas as pd
import pytest

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.cli import main
from rotarykiln.errors import InputError
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.transient_file import parse_transient


@pytest.fixture(scope="module")
def tscheng():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return kiln_from_case(load_case(builtin_case_path("tscheng_A16")))[0]


def _events(*events):
    return {"events": [dict(zip(("at", "variable", "to"), e, strict=False)) for e in events]}


@pytest.mark.parametrize(
    "data, message",
    [
        (_events(("2 h", "feed", "30 kg/h"), ("1 h", "feed", "40 kg/h")), "events[1].at"),
        (_events(("-1 h", "feed", "30 kg/h")), "events[0].at: -1 h is not in [0, 1e10 s]"),
        (_events(("3 h", "feed", "30 kg/h")), "<= the end of the run"),
        (_events(("1 h", "feed", "-30 kg/h")), "events[0].to: -30 kg/h is not in [0, 1e5 kg/s]"),
        (_events(("1 h", "feed", "0 kg/h")), "drum, to: stop"),
        (_events(("1 h", "colour", "red")), 'events[0].variable: "colour" is not one of'),
        (_events(("1 h", "fuel_flow", "2 kg/h")), '"fuel_flow" is not one of'),
        (_events(("1 h", "drum", "pause")), 'events[0].to: "pause" is not stop or run'),
        (_events(("1 h", "feed", "30 m")), "events[0].to"),
        ({"events": [{"at": "1 h", "variable": "feed", "to": "30 kg/h", "over": "2 h"}]}, "ramp"),
        (
            {
                "events": [
                    {"at": "0 h", "variable": "feed", "to": "30 kg/h", "over": "1 h"},
                    {"at": "30 min", "variable": "feed", "to": "40 kg/h"},
                ]
            },
            "after the ramp of feed",
        ),
        ({"tracer": {"duration": "-1 min"}}, "tracer.duration"),
        ({"start": "warm"}, 'start: "warm" is not one of'),
        ({"evnts": []}, "evnts: unknown key"),
    ],
)
def test_bad_events_refused_in_one_line(tscheng, data, message):
    with pytest.raises(InputError) as err:
        parse_transient(data, tscheng, 7200.0)
    text = str(err.value)
    assert message in text and "\n" not in text


def test_custom_lining_needs_its_heat_capacity():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        barr = kiln_from_case(load_case(builtin_case_path("barr_T4")))[0]
    with pytest.raises(InputError, match=r"wall.layers\[0\].*barr_refractory"):
        parse_transient({}, barr, 3600.0)


def test_transient_command(tmp_path, capsys):
    events = tmp_path / "events.yaml"
    events.write_text(
        "events:\n"
        "  - {at: 10 min, variable: gas_inlet_temperature, to: 600 K}\n"
        "  - {at: 20 min, variable: drum, to: stop}\n"
        "  - {at: 30 min, variable: drum, to: run}\n"
        "output_every: 5 min\n"
    )
    out = tmp_path / "out"
    argv = ["transient", "tscheng_A16", "--events", str(events), "--until", "1 h"]
    rc = main(argv + ["--cells", "12", "--out", str(out), "--no-plots"])
    assert rc == 0
    frame = pd.read_parquet(out / "transient_profiles.parquet")
    assert {"t_s", "z_m", "T_bed_K", "T_gas_K", "T_inner_wall_K"} <= set(frame.columns)
    assert len(frame) == 13 * 12
    assert (out / "transient_outlets.csv").is_file()
    bad = tmp_path / "bad.yaml"
    bad.write_text("events:\n  - {at: 2 h, variable: feed, to: 30 kg/h}\n")
    rc = main(argv[:3] + [str(bad), "--until", "1 h", "--out", str(out)])
    err = capsys.readouterr().err.strip()
    assert rc == 2 and "events[0].at" in err and len(err.splitlines()) == 1


def test_transient_without_pyarrow_writes_its_profiles_as_csv(tmp_path, monkeypatch):
    """A light install (no ``studies`` extra): the same table as CSV, not a pyarrow error."""
    import sys

    monkeypatch.setitem(sys.modules, "pyarrow", None)  # import pyarrow -> ImportError
    out = tmp_path / "out"
    argv = ["transient", "tscheng_A16", "--until", "20 min", "--cells", "8"]
    assert main(argv + ["--out", str(out), "--no-plots"]) == 0
    frame = pd.read_csv(out / "transient_profiles.csv")
    assert {"t_s", "z_m", "T_bed_K"} <= set(frame.columns) and len(frame) > 8
    assert not (out / "transient_profiles.parquet").exists()


def test_a_new_burner_state_enters_with_the_energy_of_its_flame_in_the_starting_tables():
    # the transient's gas tables carry the dissociation heat of the flame it starts with; a
    # fuel step changes the products, which must enter with their own energy in those tables
    import dataclasses

    import numpy as np
    import yaml

    from rotarykiln.case import parse_case
    from rotarykiln.kiln.gas_mixture import GasMixture
    from rotarykiln.kiln.transient.events import _flame_gas

    data = yaml.safe_load(builtin_case_path("limestone_fired").read_text())
    b = data["burner"]
    b["secondary_air"]["temperature"] = "1000 K"  # a hot flame: dissociation matters
    # 15 % excess air (12 Nm3/h of natural gas needs about 116 Nm3/h)
    b["primary_air"]["flow"], b["secondary_air"]["flow"] = "33 Nm3/h", "100 Nm3/h"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        kiln = kiln_from_case(parse_case(data))[0]
    flame = kiln.firing.flame
    names = ("N2", "O2", "CO2", "H2O")
    d0 = flame.dissociation
    # the starting burner: Cantera's equilibrium adiabatic temperature, unchanged
    _, t0, _ = _flame_gas(flame.burner, 0.406, 5.5, names, d0)
    assert t0 == flame.inlet_temperature
    # 8 % more fuel (5 % excess air): other products; they enter where the old tables hold
    # their enthalpy
    richer = dataclasses.replace(flame.burner, fuel_flow=1.08 * flame.burner.fuel_flow)
    flows, t1, _ = _flame_gas(richer, 0.406, 5.5, names, d0)
    from rotarykiln.kiln.combustion.flame import fire

    new = fire(richer, 0.406, 5.5)
    frozen = GasMixture.of(names).species_enthalpy(np.array(new.products.adiabatic_temperature))
    tables = GasMixture.of(names, None, d0).species_enthalpy(np.array(t1))
    assert tables @ flows == pytest.approx(frozen @ flows, rel=1e-6)
    # close to the new flame's own equilibrium temperature (the tables' dissociation differs)
    assert t1 == pytest.approx(new.adiabatic_temperature, abs=15.0)
    assert t1 < new.products.adiabatic_temperature - 50.0
