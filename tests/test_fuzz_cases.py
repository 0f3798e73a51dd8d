"""Seeded fuzz of the case files (issue 15): every mutated built-in case is either a valid case or
refused with one InputError line, never another exception; the refusal is fast and in words.

Budget: a fixed seed, a few hundred mutations (about 5 s). A longer campaign (18,972 mutations,
0 tracebacks, 0 raw pydantic texts) is described in docs/validation.md."""

from __future__ import annotations

import random
import re
import time

import pytest
import yaml

from fuzz_helpers import mutate
from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path, list_builtin_cases
from rotarykiln.errors import ConvergenceError, InputError

VALUES = [
    None,
    1,
    -1,
    0,
    1.5,
    True,
    "abc",
    "",
    [1, 2],
    [],
    {"a": 1},
    {},
    "1 m",
    float("nan"),
    1e308,
    1e-308,
    "-3 K",
    "9**9**9 m",
    "m",
    "1e400 kg/h",
    "0 rpm",
    "C2H8:1",
    "N2:nan",
    "/etc/hostname",  # a case given as data names no file (issue 21)
    "../species.yaml",
]
RAW = re.compile(r"Input should|None is not|is not an? rtd|given is not|Value error|\[type=")


def _mutations(n, seed):
    rng = random.Random(seed)
    names = list_builtin_cases()
    for _ in range(n):
        name = rng.choice(names)
        base = yaml.safe_load(builtin_case_path(name).read_text())
        d, p, _ = mutate(base, VALUES, rng)
        yield name, p, d


@pytest.mark.parametrize("seed", [1, 2])
def test_mutated_cases_are_valid_or_refused_in_one_line(seed):
    for name, path, data in _mutations(200, seed):
        t = time.perf_counter()
        try:
            parse_case(data)
        except InputError as exc:
            msg = str(exc)
            assert "\n" not in msg, (name, path, msg)
            assert not RAW.search(msg), (name, path, msg)
        assert time.perf_counter() - t < 2.0, (name, path)


def test_random_operating_points_converge_or_fail_cleanly():
    # operating points around the fired and air-heated built-in kilns: speed, feed and firing
    # within a factor 0.6-1.6 of the nominal; each converges (closed balances) or raises
    # ConvergenceError, never anything else, never an unphysical solution
    from rotarykiln.commands.kiln_runs import run_kiln_case

    rng = random.Random(7)

    def scale(text, f):
        number, unit = text.split(" ", 1)
        return f"{float(number) * f:.6g} {unit}"

    ok = 0
    for i in range(12):
        name = ("barr_T4", "tscheng_A16", "limestone_fired")[i % 3]
        d = yaml.safe_load(builtin_case_path(name).read_text())
        d["operation"]["feed"] = scale(d["operation"]["feed"], rng.uniform(0.6, 1.6))
        d["operation"]["speed"] = scale(d["operation"]["speed"], rng.uniform(0.6, 1.6))
        if name == "barr_T4":
            b = d["burner"]
            b["fuel_flow"] = scale(b["fuel_flow"], rng.uniform(0.7, 1.3))
        elif name == "tscheng_A16":
            d["gas"]["flow"] = scale(d["gas"]["flow"], rng.uniform(0.6, 1.6))
        else:
            b = d["burner"]
            b["fuel_flow"] = scale(b["fuel_flow"], rng.uniform(0.8, 1.3))
        case = parse_case(d)
        try:
            sol = run_kiln_case(case) if "heat" in d else run_kiln_case(case)
        except ConvergenceError:
            continue
        assert abs(sol.energy_closure) < 1e-6
        ok += 1
    # all converge today (125 of 125 in a longer seeded run); one of these 12 stalled at 1.16x
    # the tolerance before Newton accepted round-off stagnation (kiln/steady/newton.py)
    assert ok == 12
