"""Transient events files and the transient command within the case file's ranges and bounded
sizes (issue 21): values the case file refuses are refused in an events file with the same
range, times need a unit, the output times, cells x output times and events are bounded before
anything is allocated or solved."""

from __future__ import annotations

import time
import warnings

import pytest
import yaml

from rotarykiln.case import load_case, parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.cli import main
from rotarykiln.errors import InputError
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.transient.events import MAX_OUTPUT_TIMES
from rotarykiln.kiln.transient.integrate import simulate
from rotarykiln.transient_file import MAX_EVENTS, parse_transient, read_transient_file


@pytest.fixture(scope="module")
def tscheng():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return kiln_from_case(load_case(builtin_case_path("tscheng_A16")))[0]


@pytest.fixture(scope="module")
def barr():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return kiln_from_case(load_case(builtin_case_path("barr_T4")))[0]


def _refused(data, kiln, until=7200.0) -> str:
    start = time.perf_counter()
    with pytest.raises(InputError) as err:
        parse_transient(data, kiln, until)
    text = str(err.value)
    assert "\n" not in text and len(text) < 400, text
    assert time.perf_counter() - start < 2.0
    return text


def _case_message(section: str, key: str, value: str) -> str:
    """The message of the tscheng_A16 case file with ``section.key`` set to ``value``."""
    data = yaml.safe_load(builtin_case_path("tscheng_A16").read_text())
    data[section][key] = value
    with pytest.raises(InputError) as err:
        parse_case(data)
    return str(err.value).split(": ", 1)[1]


@pytest.mark.parametrize(
    ("variable", "value", "section", "key"),
    [
        ("speed", "1e6 rpm", "operation", "speed"),
        ("feed_temperature", "1e-6 K", "operation", "feed_temperature"),
        ("feed", "1e9 kg/s", "operation", "feed"),
        ("gas_inlet_temperature", "20000 K", "gas", "temperature"),
        ("gas_flow", "1e7 kg/s", "gas", "flow"),
    ],
)
def test_event_values_have_the_case_files_ranges(tscheng, variable, value, section, key):
    text = _refused({"events": [{"at": "1 h", "variable": variable, "to": value}]}, tscheng)
    # the same words (value, range) as the case file's refusal of that value
    assert text == f"events[0].to: {_case_message(section, key, value)}"


@pytest.mark.parametrize(
    ("data", "message"),
    [
        ({"events": [{"at": 3600, "variable": "feed", "to": "30 kg/h"}]}, "bare number 3600"),
        (
            {"events": [{"at": "1 h", "variable": "feed", "to": "30 kg/h", "over": 600}]},
            "events[0].over: bare number 600 needs a unit",
        ),
        ({"output_every": 60}, "output_every: bare number 60 needs a unit"),
        ({"tracer": {"at": 10, "duration": "1 min"}}, "tracer.at: bare number 10"),
        ({"output_every": "1e-3 s"}, f"at most {MAX_OUTPUT_TIMES}"),
        ({"tracer": {"duration": "1 min", "mass": "1e9 kg"}}, "tracer.mass: 1e9 kg is not in"),
        ({"events": [{"at": [1] * 5000, "variable": "feed", "to": "1 kg/h"}]}, "events[0].at"),
        ({"events": "x" * 100_000}, "events: "),
    ],
)
def test_times_need_a_unit_and_sizes_are_bounded(tscheng, data, message):
    assert message in _refused(data, tscheng)


def test_a_time_of_zero_needs_no_unit(tscheng):
    t = parse_transient({"events": [{"at": 0, "variable": "feed", "to": "30 kg/h"}]}, tscheng, 60)
    assert t.events[0].time == 0.0


def test_too_many_events_are_refused_before_they_are_checked(tscheng):
    event = {"at": "1 h", "variable": "feed", "to": "30 kg/h"}
    text = _refused({"events": [event] * 10_000}, tscheng)
    assert text == f"events: 10000 events is too many (at most {MAX_EVENTS})"
    assert "at most" in _refused({"events": [event] * (MAX_EVENTS + 1)}, tscheng)
    # the limit itself is accepted (steps of one variable, in time order)
    many = [
        {"at": f"{i} s", "variable": "feed", "to": f"{30 + i % 2} kg/h"} for i in range(MAX_EVENTS)
    ]
    assert len(parse_transient({"events": many}, tscheng, 7200.0).events) == MAX_EVENTS


def test_a_lining_cut_too_finely_is_refused(barr):
    wall = {
        "layers": [
            {"density": "1300 kg/m3", "specific_heat": "1000 J/kg/K"},
            {"density": "7850 kg/m3", "specific_heat": "490 J/kg/K"},
        ]
    }
    text = _refused({"wall": {**wall, "max_node_spacing": "1 um"}}, barr)
    assert text.startswith("wall.max_node_spacing:") and "at most 200" in text
    bad = {"layers": [{"density": "1e9 kg/m3", "specific_heat": "1000 J/kg/K"}] * 2}
    assert "wall.layers[0].density" in _refused({"wall": bad}, barr)


def test_simulate_bounds_cells_x_output_times_before_allocating(tscheng):
    tr = parse_transient({"output_every": "1 min"}, tscheng, 36_000.0)
    start = time.perf_counter()
    with pytest.raises(InputError, match=r"20000 cells x \d+ output times is too many"):
        simulate(tscheng, 20_000, tr, 36_000.0)
    assert time.perf_counter() - start < 1.0
    with pytest.raises(InputError, match="too many"):
        simulate(tscheng, 10, tr, 36_000.0, times=range(2_000_000))


def test_a_duplicate_events_key_is_refused(tmp_path):
    path = tmp_path / "ev.yaml"
    path.write_text(
        "events:\n  - {at: 1 h, variable: feed, to: 30 kg/h}\n"
        "output_every: 5 min\n"
        "events:\n  - {at: 2 h, variable: feed, to: 40 kg/h}\n"
    )
    with pytest.raises(InputError, match=r'key "events" given twice \(line 4\)'):
        read_transient_file(path)
    path.write_text("- 1\n- 2\n")
    with pytest.raises(InputError, match="not an events file"):
        read_transient_file(path)


@pytest.mark.parametrize(
    ("options", "events", "message"),
    [
        (["--until", "1e9 h"], None, "--until: 1e9 h is not in [1 us, 1e10 s]"),
        (["--until", "3600"], None, '--until: "3600" needs a unit'),
        (["--until", "1 h", "--cells", "100000"], None, "--cells: 100000 is not an integer in"),
        (["--until", "10 h", "--cells", "20000"], None, "--cells: 20000 cells x"),
        (["--until", "1 h"], "output_every: 1e-3 s\n", "output_every: 3600001 output times"),
        (["--until", "1 h"], "events:\n  - {at: 3600, variable: feed, to: 30 kg/h}\n", "unit"),
        (["--until", "1 h"], "events:\n  - {at: 1 h, variable: speed, to: 1e6 rpm}\n", "955"),
    ],
)
def test_the_transient_command_refuses_in_one_line(tmp_path, capsys, options, events, message):
    argv = ["transient", "tscheng_A16", "--out", str(tmp_path / "out"), "--no-plots", *options]
    if events is not None:
        (tmp_path / "ev.yaml").write_text(events)
        argv += ["--events", str(tmp_path / "ev.yaml")]
    start = time.perf_counter()
    code = main(argv)
    err = capsys.readouterr().err.strip()
    assert code == 2 and len(err.splitlines()) == 1 and message in err, err
    assert time.perf_counter() - start < 5.0
    assert not (tmp_path / "out").exists()
