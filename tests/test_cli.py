import json
import subprocess
import sys

import pytest

from rotarykiln.cli import main


def run_cli(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_regime_check_point(capsys):
    code, out, _ = run_cli(
        capsys, "regime", "--diameter", "6", "m", "--speed", "5", "rpm", "--fill", "0.3", "--json"
    )
    assert code == 0
    data = json.loads(out)
    assert round(data["froude"], 3) == 0.084
    assert round(data["fraction_of_critical"], 2) == 0.29
    assert data["regime"] == "cascading" and data["criterion"].startswith("mellmann")
    assert data["regime_by_henein"] == "rolling"
    assert data["regime_note"].startswith("the criteria disagree: mellmann's applies")


def test_regime_text_and_plot(capsys, tmp_path):
    png = tmp_path / "map.png"
    code, out, _ = run_cli(
        capsys,
        "regime",
        "--radius",
        "0.2m",
        "--speed",
        "3rpm",
        "--depth",
        "5 cm",
        "--plot",
        str(png),
    )
    assert code == 0 and "froude" in out and png.stat().st_size > 1000


def test_geometry_json(capsys):
    code, out, _ = run_cli(
        capsys, "geometry", "--diameter", "2", "m", "--depth", "1", "m", "--json"
    )
    assert code == 0
    assert json.loads(out)["fill"] == pytest.approx(0.5)


@pytest.mark.parametrize(
    ("argv", "needle"),
    [
        (["regime", "--diameter", "6", "m", "--speed", "3", "m", "--fill", "0.3"], "is a length"),
        (["regime", "--diameter", "6", "m", "--speed", "-5", "rpm", "--fill", "0.3"], "--speed"),
        (["regime", "--diameter", "-6", "m", "--speed", "5", "rpm", "--fill", "0.3"], "not > 0"),
        (["regime", "--diameter", "6", "m", "--speed", "5", "rpm", "--fill", "1.0"], "(0, 1)"),
        (["geometry", "--diameter", "1", "m"], "give exactly one"),
        (
            ["geometry", "--diameter", "1", "m", "--fill", "0.2", "--depth", "0.1", "m"],
            "exactly one",
        ),
        (["run", "does-not-exist.yaml"], "no such case file"),
    ],
)
def test_bad_input_exits_2_with_one_line(capsys, argv, needle):
    code, _, err = run_cli(capsys, *argv)
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and needle in lines[0]
    assert "Traceback" not in err


def test_bad_case_file_through_cli(capsys, tmp_path):
    p = tmp_path / "c.yaml"
    p.write_text("kiln: {length: 5 m, diameter: 0.4 m, colour: red}\noperation: {speed: 2 rpm}\n")
    code, _, err = run_cli(capsys, "run", str(p))
    assert code == 2 and "kiln.colour: unknown key" in err
    p.write_text("kiln: [\n")
    code, _, err = run_cli(capsys, "run", str(p))
    assert code == 2 and "malformed YAML" in err


def test_run_writes_summary(capsys, tmp_path):
    p = tmp_path / "c.yaml"
    p.write_text(
        "kiln: {length: 5 m, diameter: 0.4 m, slope: 1 deg}\n"
        "operation: {speed: 2 rpm, feed: 50 kg/h}\nbed: {fill: 0.1}\n"
    )
    code, out, _ = run_cli(capsys, "run", str(p), "--out", str(tmp_path / "res"))
    assert code == 0
    summary = json.loads((tmp_path / "res" / "summary.json").read_text())
    assert summary["fill"] == pytest.approx(0.1)
    assert (tmp_path / "res" / "regime_map.png").exists()
    assert not list((tmp_path / "res").glob(".*"))  # no temporary files left behind


def test_demo(capsys, tmp_path):
    code, out, _ = run_cli(capsys, "demo", "--out", str(tmp_path / "demo"))
    assert code == 0
    assert (tmp_path / "demo" / "summary.json").exists()


def test_console_entry_point_usage_error_exit_code():
    proc = subprocess.run(
        [sys.executable, "-m", "rotarykiln", "regime", "--bogus"], capture_output=True, text=True
    )
    assert proc.returncode == 2
    assert "Traceback" not in proc.stderr and len(proc.stderr.strip().splitlines()) == 1


@pytest.mark.parametrize(
    ("line", "message"),
    [
        ("kiln: {length: 5 m, diameter: -0.4 m}", "kiln.diameter: -0.4 m is not in [1 um, 10 km]"),
        ("kiln: {length: 5 m, diameter: 0.4 m}\noperation: {speed: 3 m}", '"3 m" is a length'),
        (
            "kiln: {length: 5 m, diameter: 0.4 m}\noperation: {speed: -2 rpm}",
            "speed: -2 rpm is not in [1e-5 rpm, 955 rpm]",
        ),
        (
            "kiln: {length: 5 m, diameter: 0.4 m}\nbed: {fill: 1}",
            "bed.fill: 1 is not in [0.001, 1)",
        ),
    ],
)
def test_case_value_errors_through_cli(capsys, tmp_path, line, message):
    p = tmp_path / "c.yaml"
    if "operation" not in line:
        line += "\noperation: {speed: 2 rpm}"
    p.write_text(line + "\n")
    code, _, err = run_cli(capsys, "run", str(p))
    assert code == 2
    assert len(err.strip().splitlines()) == 1 and message in err


def _all_subcommand_paths():
    import argparse

    from rotarykiln.cli import build_parser

    paths = []

    def walk(parser, prefix):
        for action in parser._actions:
            if isinstance(action, argparse._SubParsersAction):
                for name, sub in action.choices.items():
                    paths.append([*prefix, name])
                    walk(sub, [*prefix, name])

    walk(build_parser(), [])
    return paths


@pytest.mark.parametrize("path", _all_subcommand_paths(), ids=" ".join)
def test_every_subcommand_help_renders(capsys, path):
    with pytest.raises(SystemExit) as info:
        main([*path, "--help"])
    assert info.value.code == 0
    assert "usage:" in capsys.readouterr().out


def test_run_accepts_a_builtin_case_name(capsys, tmp_path):
    code, out, _ = run_cli(capsys, "run", "tscheng_A16", "--out", str(tmp_path), "--no-plots")
    assert code == 0
    assert json.loads((tmp_path / "summary.json").read_text())["name"] == "Tscheng 1978 run A16"


def test_readme_first_lines_name_the_two_setup_commands():
    from pathlib import Path

    readme = Path(__file__).resolve().parents[1] / "README.md"
    head = readme.read_text().splitlines()[:6]
    assert any(line.startswith("make demo") for line in head)
    assert any(line.startswith("make test") for line in head)


REGIME = ["regime", "--diameter", "6", "m", "--fill", "0.3"]


@pytest.mark.parametrize(
    ("argv", "needle"),
    [
        ([*REGIME, "--speed", "1.5", "rmp"], '--speed: "1.5 rmp" has an unknown unit "rmp"'),
        ([*REGIME, "--speed", "1.5"], '--speed: "1.5" needs a unit, expected a rotation rate'),
        ([*REGIME, "--speed", "1.5", "1/min"], "does not say revolutions or radians"),
        (
            ["regime", "--diameter", "0,4", "m", "--speed", "2", "rpm", "--fill", "0.3"],
            '--diameter: "0,4 m" has a comma',  # used to run with a 0 m diameter
        ),
        ([*REGIME, "--speed", "5", "rpm", "--plot", "map.txt"], '".txt" is not a figure format'),
    ],
)
def test_engineer_typos_exit_2_with_one_line(capsys, argv, needle):
    code, _, err = run_cli(capsys, *argv)
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and needle in lines[0], err


@pytest.mark.parametrize("spelling", [["1.5", "RPM"], ["1.5", "rev/min"], ["1.5rpm"]])
def test_rpm_spellings(capsys, spelling):
    code, out, _ = run_cli(capsys, *REGIME, "--speed", *spelling, "--json")
    assert code == 0 and json.loads(out)["speed_rpm"] == pytest.approx(1.5)


def test_out_that_is_a_file(capsys, tmp_path):
    f = tmp_path / "results"
    f.write_text("")
    code, _, err = run_cli(capsys, "run", "tscheng_A16", "--out", str(f), "--no-plots")
    assert code == 2 and err.strip().endswith("is a file, not a folder")


def test_transverse_duration_takes_value_and_unit(capsys, tmp_path):
    # "--duration 1 s" (two words, like every other quantity option) used to be a usage error
    code, out, _ = run_cli(
        capsys, "transverse", "retort/case02", "--duration", "1", "s", "--no-plots",
        "--out", str(tmp_path), "--json",
    )  # fmt: skip
    assert code == 0 and (tmp_path / "summary.json").is_file()


def test_rtd_predict_accepts_a_builtin_case_name(capsys):
    code, out, _ = run_cli(capsys, "rtd", "predict", "rtd/bongo_njeng_sand_rl", "--json")
    assert code == 0 and json.loads(out)["rtd_mean_residence_time_s"] > 0


def test_run_says_the_transverse_section_needs_its_command(capsys, tmp_path):
    code, _, err = run_cli(capsys, "run", "retort/case02", "--out", str(tmp_path), "--no-plots")
    assert code == 0 and "rotarykiln transverse retort/case02" in err


def test_help_is_plain_text_and_quantities_read_value_unit(capsys):
    for path in _all_subcommand_paths():
        with pytest.raises(SystemExit):
            main([*path, "--help"])
        out = capsys.readouterr().out
        assert "``" not in out and ":data:" not in out, path
        assert "VALUE UNIT [VALUE UNIT" not in out, path


def test_a_repeated_warning_is_printed_once(capsys):
    import warnings

    from rotarykiln import cli

    def func(args):
        for _ in range(2):
            warnings.warn("Re = 100 is outside the range", stacklevel=1)
        return 0

    parser = cli.build_parser
    try:
        cli.build_parser = lambda *a, **k: _FakeParser(func)
        assert cli.main([]) == 0
    finally:
        cli.build_parser = parser
    assert capsys.readouterr().err.count("Re = 100") == 1


class _FakeParser:
    def __init__(self, func):
        self.func = func

    def parse_args(self, argv):
        import argparse

        return argparse.Namespace(func=self.func, command="fake")


def test_run_unknown_name_lists_the_builtin_cases(capsys):
    code, _, err = run_cli(capsys, "run", "limestone")
    assert code == 2
    assert "limestone_calcination" in err and len(err.strip().splitlines()) == 1


def test_the_command_table_matches_each_command_module():
    import argparse

    from rotarykiln.cli import COMMANDS, build_parser

    (sub,) = (a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction))
    helps = {c.dest: c.help for c in sub._choices_actions}
    assert helps == COMMANDS


@pytest.mark.parametrize(
    "argv, light",
    [(["--version"], True), (["--help"], True), (["-v", "regime", "--help"], False)],
)
def test_version_and_help_import_no_command_module(argv, light):
    """``--version`` and ``--help`` build no subcommand parser: no model, numpy or pint import."""
    import subprocess
    import sys

    code = (
        "import sys\n"
        "from rotarykiln.cli import main\n"
        f"try:\n    main({argv!r})\nexcept SystemExit:\n    pass\n"
        "heavy = [m for m in ('numpy', 'pint', 'rotarykiln.commands.run', 'rotarykiln.commands.regime')"
        " if m in sys.modules]\n"
        "print('HEAVY', heavy)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    heavy = out.stdout.rsplit("HEAVY", 1)[1]
    assert (heavy.strip() == "[]") is light, heavy
    if argv == ["--version"]:
        assert out.stdout.startswith("rotarykiln "), out  # on stdout, as argparse prints it
    if argv == ["--help"]:
        for name in ("run", "sweep", "transient"):
            assert name in out.stdout


def test_a_missing_extra_names_the_pip_install(monkeypatch):
    """An optional package that is not installed: one line naming the extra to install."""
    import builtins

    from rotarykiln.errors import InputError
    from rotarykiln.extras import require

    real_import = builtins.__import__

    def no_salib(name, *args, **kwargs):
        if name.split(".")[0] == "SALib":
            raise ImportError(f"No module named {name!r}", name=name)
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_salib)
    for mod in [m for m in __import__("sys").modules if m.split(".")[0] == "SALib"]:
        monkeypatch.delitem(__import__("sys").modules, mod)
    with pytest.raises(InputError) as info:
        require("SALib.sample.sobol", "a Sobol sensitivity study")
    text = str(info.value)
    assert 'pip install "rotarykiln[studies]"' in text and "\n" not in text


def test_verbose_run_logs_its_steps_and_newton_iterations(tmp_path):
    """``-v``: the models run, the kiln's Newton iterations and its balances, on stderr."""
    import subprocess
    import sys

    out = subprocess.run(
        [sys.executable, "-m", "rotarykiln", "-v", "run", "tscheng_A16", "--no-plots"]
        + ["--out", str(tmp_path / "r")],
        capture_output=True,
        text=True,
        env={**__import__("os").environ, "MPLBACKEND": "Agg"},
    )
    assert out.returncode == 0, out.stderr
    assert "the kiln model" in out.stderr
    assert "Newton iteration 1:" in out.stderr and "Newton converged in" in out.stderr
    assert "kiln solved: bed out" in out.stderr
    quiet = subprocess.run(
        [sys.executable, "-m", "rotarykiln", "run", "tscheng_A16", "--no-plots"]
        + ["--out", str(tmp_path / "q")],
        capture_output=True,
        text=True,
    )
    assert "Newton" not in quiet.stderr


def test_a_signal_lost_in_a_finaliser_still_ends_the_command_as_interrupted(capsys):
    """A SIGTERM whose handler runs inside a ``__del__`` (the garbage collector calls them
    anywhere) raises where Python cannot propagate it; the command must not then exit 0 with an
    "Exception ignored" traceback: it ends with its one line and 143."""
    import os
    import signal

    from rotarykiln import cli

    class Finalised:
        def __del__(self):
            os.kill(os.getpid(), signal.SIGTERM)  # the handler runs here, inside __del__

    def func(args):
        x = Finalised()
        del x
        return 0

    parser = cli.build_parser
    try:
        cli.build_parser = lambda *a, **k: _FakeParser(func)
        code = cli.main([])
    finally:
        cli.build_parser = parser
    err = capsys.readouterr().err
    assert code == 143 and "rotarykiln: terminated" in err, (code, err)
    assert "Traceback" not in err and "Exception ignored" not in err, err
