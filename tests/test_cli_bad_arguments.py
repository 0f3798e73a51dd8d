"""Every command refuses a user's mistake the same way (issue 15): exit code 2 and one line on
stderr naming the option and the value, never a traceback and never a model run first.

Bad arguments of each kind are thrown at bed, regime, geometry, rtd, transverse, sweep,
sensitivity, calibrate, schema and demo: non-numbers, numbers without a unit, units of the wrong
kind, zero, negative, non-finite, tiny and huge values, missing and unreadable files, and an --out
that cannot be written. A signal alarm bounds each call: a refusal must come before any solve.
"""

from __future__ import annotations

import shlex
import signal
from pathlib import Path

import pytest

from rotarykiln import cli

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
TRACER = str(EXAMPLES / "tracer_synthetic.csv")

# a valid command of each kind; {X} marks where a bad value goes
BED = (
    "bed --diameter 0.4 m --length 2 m --speed 3 rpm --slope 1 deg --feed 62 kg/h "
    "--density 1500 kg/m3 --repose 35 deg"
)
BED_QUANTITIES = {
    "diameter": "0.4 m",
    "length": "2 m",
    "speed": "3 rpm",
    "slope": "1 deg",
    "feed": "62 kg/h",
    "density": "1500 kg/m3",
    "repose": "35 deg",
}
BAD_QUANTITIES = [
    "abc",  # not a number
    "m",  # a unit with no number
    "1 kg",  # a unit of the wrong kind for every option below
    "-1 {unit}",
    "0 {unit}",
    "nan {unit}",
    "inf {unit}",
    "1e-308 {unit}",
    "1e300 {unit}",
    "2**9 {unit}",
    "1 {unit} 2",
    "1,5 {unit}",
    "x" * 10_000,
]


def _replace_quantity(base: str, name: str, value: str) -> list[str]:
    argv = shlex.split(base)
    i = argv.index(f"--{name}")
    j = i + 1
    while j < len(argv) and not argv[j].startswith("--"):
        j += 1
    return argv[: i + 1] + value.split() + argv[j:]


def _cases(tmp_path_factory=None):
    cases = []
    for name, good in BED_QUANTITIES.items():
        unit = good.split()[1]
        for bad in BAD_QUANTITIES:
            value = bad.format(unit=unit)
            if name == "slope" and value.split()[0] in ("0", "1e-308"):
                continue  # a horizontal drum is valid, as in a case file (slope in [0, 45) deg)
            cases.append((f"bed --{name} {value[:20]}", _replace_quantity(BED, name, value)))
    for opt in ("--points 0", "--points 1e8", "--points abc", "--points -5", "--friction wet"):
        cases.append((f"bed {opt}", shlex.split(BED) + opt.split() + ["--model", "scott"]))
    cases.append(("bed --weir", shlex.split(BED) + ["--model", "scott", "--weir", "x", "1 cm"]))
    cases.append(("bed --dam", shlex.split(BED) + ["--dam", "1 kg"]))
    cases.append(("bed missing --feed", _replace_quantity(BED, "feed", "62 kg/h")[:-2]))

    regime = "regime --diameter 6 m --speed 5 rpm --fill 0.3"
    for name, unit in (("diameter", "m"), ("speed", "rpm"), ("fill", "")):
        for bad in ("abc", "1 kg", "-1 {unit}", "0 {unit}", "nan {unit}", "1e300 {unit}"):
            value = bad.format(unit=unit).strip()
            cases.append((f"regime --{name} {value}", _replace_quantity(regime, name, value)))
    for extra in (
        "--wall-friction -1",
        "--wall-friction abc",
        "--wall-friction nan",
        "--wall-friction 1e300",
        "--repose 100 deg",
        "--repose 1 kg",
        "--depth 10 m",
        "--criterion foo",
        "--plot map.xyz",
    ):
        cases.append((f"regime {extra}", shlex.split(regime) + extra.split()))

    geometry = "geometry --diameter 0.4 m --fill 0.15"
    for name, unit in (("diameter", "m"), ("fill", "")):
        for bad in ("abc", "1 kg", "-1 {unit}", "0 {unit}", "nan {unit}", "1e300 {unit}", "2"):
            value = bad.format(unit=unit).strip()
            if name == "diameter" and value == "2":
                continue  # a number alone is SI: 2 m
            cases.append((f"geometry --{name} {value}", _replace_quantity(geometry, name, value)))
    for extra in ("--depth 1 m", "--half-angle 1 m", "--chord -1 m", "--half-angle nan deg"):
        cases.append((f"geometry {extra}", ["geometry", "--diameter", "0.4", "m", *extra.split()]))
    cases.append(("geometry two of fill/depth", shlex.split(geometry) + ["--depth", "0.1", "m"]))

    for extra in (
        "--time-unit parsec",
        "--time-unit kg",
        "--baseline abc",
        "--baseline nan",
        "--baseline 1e300",
        "--length -1 m",
        "--length 1 kg",
        "--length abc",
        "--kind foo",
        "--baseline inf",
        "--baseline -inf",
    ):
        cases.append((f"rtd fit {extra}", ["rtd", "fit", TRACER, *extra.split()]))
    # a value with a newline is escaped: still one line (issue 21)
    cases.append(("rtd fit --baseline newline", ["rtd", "fit", TRACER, "--baseline", "1\n2"]))
    cases.append(("rtd fit --time-unit newline", ["rtd", "fit", TRACER, "--time-unit", "mi\nn"]))
    cases.append(("rtd fit file name newline", ["rtd", "fit", "no/such\nfile.csv"]))
    cases.append(("rtd fit missing file", ["rtd", "fit", "no/such/file.csv"]))
    cases.append(("rtd predict missing case", ["rtd", "predict", "no_such_case"]))
    cases.append(("rtd predict no rtd section", ["rtd", "predict", "tscheng_A16"]))

    for extra in (
        "--duration abc",
        "--duration -1 s",
        "--duration 0 s",
        "--duration 1 kg",
        "--duration 1e300 s",
        "--duration nan s",
    ):
        cases.append(
            (f"transverse {extra}", ["transverse", "retort/case02", "--no-plots", *extra.split()])
        )
    cases.append(("transverse missing case", ["transverse", "no/such.yaml"]))
    cases.append(("transverse not transverse", ["transverse", "tscheng_A16"]))

    sweep = ["sweep", "--case", "tscheng_A16", "--model", "kiln", "--executor", "serial"]
    for extra in (
        ["--grid", "operation.speed"],
        ["--grid", "operation.speed="],
        ["--grid", "no.such=1,2"],
        ["--grid", "operation.speed=1 kg,2 kg"],
        ["--grid", "operation.speed=-1 rpm,2 rpm"],
        ["--grid", "operation.speed=abc,2 rpm"],
        ["--oat", "operation.speed=nan rpm"],
        ["--lhs", "0", "--param", "operation.speed=uniform(1 rpm, 2 rpm)"],
        ["--lhs", "-3", "--param", "operation.speed=uniform(1 rpm, 2 rpm)"],
        ["--lhs", "1000000000", "--param", "operation.speed=uniform(1 rpm, 2 rpm)"],
        ["--lhs", "abc"],
        ["--lhs", "4", "--param", "operation.speed=uniform(2 rpm, 1 rpm)"],
        ["--lhs", "4", "--param", "operation.speed=foo(1 rpm)"],
        ["--lhs", "4", "--param", "operation.speed=uniform(1 kg, 2 kg)"],
        ["--lhs", "4", "--param", "operation.speed"],
        ["--lhs", "4"],
        ["--grid", "operation.speed=1 rpm,2 rpm", "--workers", "0"],
        ["--grid", "operation.speed=1 rpm,2 rpm", "--workers", "-2"],
        ["--grid", "operation.speed=1 rpm,2 rpm", "--workers", "abc"],
        ["--grid", "operation.speed=1 rpm,2 rpm", "--batch", "0"],
        ["--grid", "operation.speed=1 rpm,2 rpm", "--batch", "-4"],
        ["--grid", "operation.speed=1 rpm,2 rpm", "--batch", "abc"],
        ["--grid", "operation.speed=1 rpm,2 rpm", "--seed", "-1"],
        ["--grid", "operation.speed=1 rpm,2 rpm", "--name", "../x"],
        # issue 21: one cap for every design, before it is built; a path given twice
        ["--grid", "operation.speed=" + ",".join(f"{1 + i / 1000:g} rpm" for i in range(1000))]
        + ["--grid", "gas.flow=" + ",".join(f"{20 + i / 100:g} kg/h" for i in range(1000))],
        ["--grid", "operation.speed=1 rpm", "--grid", "operation.speed=2 rpm"],
        ["--oat", "operation.speed=1 rpm", "--oat", "operation.speed=2 rpm"],
        ["--grid", "operation.speed=1 rpm\n2 rpm,x"],
    ):
        cases.append((f"sweep {' '.join(extra)[:40]}", sweep + extra))
    cases.append(("sweep missing case", ["sweep", "--case", "nope.yaml", "--model", "kiln"]))
    cases.append(
        (
            "sweep unknown model",
            ["sweep", "--case", "tscheng_A16", "--model", "nope", "--grid", "kiln.length=1 m"],
        )
    )

    sens = ["sensitivity", "tscheng_A16", "--model", "kiln", "--executor", "serial"]
    param = ["--param", "operation.speed=uniform(1 rpm, 2 rpm)"]
    out = ["--output", "bed_outlet_temperature_K"]
    for extra in (
        [],
        param,
        param + out + ["--n", "0"],
        param + out + ["--n", "-4"],
        param + out + ["--n", "abc"],
        param + out + ["--n", "1000000000"],
        param + out + ["--method", "morris", "--levels", "1"],
        param + out + ["--method", "morris", "--levels", "-1"],
        param + out + ["--workers", "0"],
        param + out + ["--batch", "0"],
        ["--param", "operation.speed=uniform(2 rpm, 1 rpm)", *out],
        ["--param", "operation.speed=normal(1 rpm, -1 rpm)", *out],
        ["--param", "no.such=uniform(1, 2)", *out],
        ["--param", "operation.speed=uniform(1 rpm)", *out],
        # issue 21: below each method's minimum (was an IndexError traceback), over the cap
        param + ["--method", "uncertainty", "--n", "1"],
        param + out + ["--n", "1"],
        param + out + ["--method", "morris", "--n", "1"],
        param + out + ["--n", "50000"],
    ):
        cases.append((f"sensitivity {' '.join(extra)[:40]}", sens + extra))
    cases.append(("sensitivity missing case", ["sensitivity", "nope.yaml", "--model", "kiln"]))

    return cases


CASES = _cases()


def _call(argv: list[str]) -> int:
    def too_long(signum, frame):
        raise TimeoutError(f"not refused within 20 s: {argv}")

    previous = signal.signal(signal.SIGALRM, too_long)
    signal.alarm(20)
    try:
        return cli.main(argv)
    except SystemExit as exc:  # argparse
        return exc.code
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)


def _check(argv, capsys):
    code = _call(argv)
    out, err = capsys.readouterr()
    lines = [x for x in err.splitlines() if x.strip() and not x.startswith("warning: ")]
    assert code == 2, (argv, code, err[-2000:])
    assert len(lines) == 1, (argv, err[-2000:])
    assert "Traceback" not in err
    return lines[0]


@pytest.mark.parametrize(("label", "argv"), CASES, ids=[c[0] for c in CASES])
def test_bad_arguments_exit_2_with_one_line(label, argv, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # default output folders (sensitivity/, ...) land here
    _check(argv, capsys)
    assert not any(tmp_path.iterdir()), f"a refused command wrote {list(tmp_path.iterdir())}"


def test_files_and_out_folders(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    a_file = tmp_path / "file"
    a_file.write_text("x")
    long = str(tmp_path / ("x" * 300))
    under_file = str(a_file / "sub")
    not_utf8 = tmp_path / "latin1.csv"
    not_utf8.write_bytes("time [min],mass fraction\n1,\xe9\n".encode("latin-1"))
    empty = tmp_path / "empty.csv"
    empty.write_text("")
    data = tmp_path / "data.csv"
    data.write_text("quantity,z,value,uncertainty\nbed,1.0,500,5\n")
    fit = ["--fit", "gas.flow=20 kg/h [5 kg/h, 60 kg/h]"]
    calibrate = ["calibrate", "tscheng_A16", "--data", str(data), *fit]
    argvs = [
        ["bed", *shlex.split(BED), "--out", under_file][1:],
        ["bed", *shlex.split(BED), "--out", long][1:],
        ["bed", *shlex.split(BED), "--out", str(a_file)][1:],
        ["regime", "--diameter", "6", "m", "--speed", "5", "rpm", "--fill", "0.3", "--plot"]
        + [str(a_file / "map.png")],
        ["regime", "--diameter", "6", "m", "--speed", "5", "rpm", "--fill", "0.3", "--plot", long]
        + [],
        ["rtd", "fit", TRACER, "--out", under_file],
        ["rtd", "fit", str(not_utf8)],
        ["rtd", "fit", str(empty)],
        ["rtd", "fit", str(tmp_path)],
        ["rtd", "predict", "rtd/bongo_njeng_sand_rl", "--out", long],
        ["transverse", "retort/case02", "--out", under_file],
        ["sweep", "--case", "tscheng_A16", "--model", "kiln", "--grid"]
        + ["operation.speed=1 rpm,2 rpm", "--out", under_file],
        ["sensitivity", "tscheng_A16", "--model", "kiln", "--param"]
        + ["operation.speed=uniform(1 rpm, 2 rpm)", "--output", "x", "--out", long],
        ["calibrate", "tscheng_A16", "--data", "no/such.csv", *fit],
        ["calibrate", "tscheng_A16", "--data", str(not_utf8), *fit],
        ["calibrate", "tscheng_A16", "--data", str(empty), *fit],
        ["calibrate", "nope.yaml", "--data", str(data), *fit],
        [*calibrate, "--out", under_file],
        [*calibrate[:-2], "--fit", "gas.flow"],
        [*calibrate[:-2], "--fit", "gas.flow=abc"],
        [*calibrate[:-2], "--fit", "gas.flow=20 kg/h [60 kg/h, 5 kg/h]"],
        [*calibrate[:-2], "--fit", "gas.flow=20 kg [5 kg, 60 kg]"],
        [*calibrate[:-2], "--fit", "no.such=1"],
        [*calibrate, "--workers", "0"],
        [*calibrate, "--max-evaluations", "0"],
        [*calibrate, "--max-evaluations", "-5"],
        ["schema", "--out", under_file],
        ["schema", "--out", long],
        ["schema", "--out", str(tmp_path)],
        ["demo", "--out", under_file],
        ["demo", "--out", long],
        ["run", "tscheng_A16", "--out", under_file],
        ["run", "no/such.yaml"],
        ["run", str(not_utf8)],
    ]
    failures = []
    for argv in argvs:
        try:
            _check(argv, capsys)
        except AssertionError as exc:
            failures.append(str(exc)[:600])
    assert not failures, "\n".join(failures)
