"""Transient files: bad events refused with one line; the transient command end to end."""

import warnings

import pandas as pd
import pytest

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.cli import main
from rotarykiln.errors import InputError
from rotarykiln.kiln.build import kiln_from_case
from rotarykiln.kiln.events import parse_transient


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
        (_events(("-1 h", "feed", "30 kg/h")), "events[0].at: -1 h is not >= 0 s"),
        (_events(("3 h", "feed", "30 kg/h")), "<= the end of the run"),
        (_events(("1 h", "feed", "-30 kg/h")), "events[0].to: -30 kg/h is not > 0 kg/s"),
        (_events(("1 h", "feed", "0 kg/h")), "drum, to: stop"),
        (_events(("1 h", "colour", "red")), "events[0].variable: 'colour' is not one of"),
        (_events(("1 h", "fuel_flow", "2 kg/h")), "'fuel_flow' is not one of"),
        (_events(("1 h", "drum", "pause")), "events[0].to: 'pause' is not stop or run"),
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
        ({"start": "warm"}, "start: 'warm' is not one of"),
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
