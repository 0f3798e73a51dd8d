"""The output set of a run (rotarykiln.outputs.output_set, issue 15): staged beside the output
folder, committed as a whole; signals held during the commit; a commit cut by SIGKILL completed
by the next run; stale staging folders removed; the user's files never touched."""

from __future__ import annotations

import json
import os
import signal

import pytest
import yaml

from rotarykiln import outputs
from rotarykiln.commands._signals import Terminated, handled
from rotarykiln.errors import InputError
from rotarykiln.outputs import MANIFEST, output_set, prepare_output_folder, write_text_atomic

STAGING = ".rotarykiln-staging-"


def _names(folder):
    return sorted(p.name for p in folder.iterdir())


def _stagings(parent):
    return [p.name for p in parent.iterdir() if p.name.startswith(STAGING)]


def _write(staging, names):
    for n in names:
        write_text_atomic(staging / n, f"new {n}")


@pytest.fixture
def folder(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "mine.txt").write_text("mine")
    # an earlier run's set: a.csv, old.png (+ manifest)
    with output_set(out) as staging:
        _write(staging, ["a.csv", "old.png"])
    return out


def test_a_committed_set_replaces_the_previous_one_and_keeps_the_users_files(folder):
    assert _names(folder) == ["a.csv", "mine.txt", "old.png", MANIFEST]
    with output_set(folder) as staging:
        assert staging.parent.parent == folder.parent  # staged beside the folder
        _write(staging, ["a.csv", "b.json"])
        assert _names(folder) == ["a.csv", "mine.txt", "old.png", MANIFEST]  # nothing yet
    assert _names(folder) == ["a.csv", "b.json", "mine.txt", MANIFEST]
    assert (folder / "a.csv").read_text() == "new a.csv"
    assert json.loads((folder / MANIFEST).read_text()) == {"files": ["a.csv", "b.json"]}
    assert (folder / "mine.txt").read_text() == "mine"
    assert _stagings(folder.parent) == []


def test_a_failed_or_interrupted_run_changes_nothing(folder):
    for exc in (RuntimeError("solver exploded"), KeyboardInterrupt()):
        with pytest.raises(type(exc)), output_set(folder) as staging:
            _write(staging, ["a.csv", "b.json"])
            raise exc
        assert _names(folder) == ["a.csv", "mine.txt", "old.png", MANIFEST]
        assert (folder / "a.csv").read_text() == "new a.csv"  # the fixture's run
        assert _stagings(folder.parent) == []


def test_sigterm_during_the_commit_waits_for_its_end(folder, monkeypatch):
    real = outputs._roll_forward

    def signalled(staging, target):
        signal.raise_signal(signal.SIGTERM)  # arrives in the middle of the renames
        real(staging, target)

    monkeypatch.setattr(outputs, "_roll_forward", signalled)
    with pytest.raises(Terminated), handled(at_exit_ignore=False):
        with output_set(folder) as staging:
            _write(staging, ["b.json"])
    assert _names(folder) == ["b.json", "mine.txt", MANIFEST]  # the whole new set
    assert _stagings(folder.parent) == []


def test_a_commit_cut_by_sigkill_is_completed_by_the_next_run(folder, monkeypatch):
    class Killed(BaseException):
        """Stands for SIGKILL: nothing after it runs in the process (no cleanup either)."""

    def cut(staging, target):  # one file moved, then the process dies
        os.replace(staging / "files" / "b.json", target / "b.json")
        raise Killed

    monkeypatch.setattr(outputs, "_roll_forward", cut)
    monkeypatch.setattr(outputs.shutil, "rmtree", lambda *a, **k: None)  # a dead process
    with pytest.raises(Killed), output_set(folder) as staging:
        _write(staging, ["b.json", "c.txt"])
    monkeypatch.undo()
    assert _names(folder) == ["a.csv", "b.json", "mine.txt", "old.png", MANIFEST]  # cut
    assert len(_stagings(folder.parent)) == 1
    prepare_output_folder(folder)  # the next run, before it solves anything
    assert _names(folder) == ["b.json", "c.txt", "mine.txt", MANIFEST]
    assert json.loads((folder / MANIFEST).read_text()) == {"files": ["b.json", "c.txt"]}
    assert _stagings(folder.parent) == []


def test_stale_staging_folders_are_removed_live_ones_kept(folder):
    key = outputs._folder_key(folder.resolve())
    stale = folder.parent / f"{STAGING}{key}-99999-abc"  # a run killed before its commit
    (stale / "files").mkdir(parents=True)
    (stale / "files" / "a.csv").write_text("half")
    other = folder.parent / f"{STAGING}000000000000-1-x"  # another folder's: not ours
    other.mkdir()
    with output_set(folder) as staging:
        live = staging.parent
        prepare_output_folder(folder)  # a second run starting meanwhile
        assert live.is_dir()  # locked by this run: left alone
        assert not stale.exists()
    assert other.is_dir()
    assert _names(folder) == ["mine.txt", MANIFEST]  # an empty set replaced the fixture's


def test_staging_inside_the_folder_when_its_parent_is_not_writable(folder, monkeypatch):
    real = os.access
    monkeypatch.setattr(
        outputs.os, "access", lambda p, m: False if p == folder.parent.resolve() else real(p, m)
    )
    with output_set(folder) as staging:
        assert staging.parent.parent == folder.resolve()
        _write(staging, ["z.txt"])
    assert _names(folder) == ["mine.txt", MANIFEST, "z.txt"]  # no hidden folder left


def test_output_folder_refusals_are_one_line(tmp_path):
    (tmp_path / "file").write_text("x")
    for bad, words in (
        (tmp_path / "file", "is a file, not a folder"),
        (tmp_path / "file" / "sub", "cannot create"),
        (tmp_path / ("x" * 300), "cannot create"),
    ):
        with pytest.raises(InputError, match=words) as info:
            prepare_output_folder(bad)
        assert "\n" not in str(info.value)


def test_summary_paths_name_the_output_folder_not_the_staging(tmp_path):
    from rotarykiln import cli

    case = {
        "name": "coupled",
        "kiln": {"length": "2.44 m", "diameter": "0.1885 m", "slope": "1.2 deg"},
        "operation": {"speed": "1.5 rpm", "feed": "14.2 kg/h"},
        "material": {"bulk_density": "1650 kg/m3", "repose_angle": "27 deg", "solid": "sand"},
        "transport": {"model": "kramers", "dam_height": "6 cm"},
    }
    path = tmp_path / "c.yaml"
    path.write_text(yaml.safe_dump(case))
    out = tmp_path / "res"
    assert cli.main(["run", str(path), "--out", str(out), "--no-plots"]) == 0
    summary = json.loads((out / "summary.json").read_text())
    assert summary["transport_profile_csv"] == str(out / "profile.csv")
    assert STAGING not in (out / "summary.txt").read_text()


def test_an_older_cut_commit_goes_in_before_a_newer_run_commits(folder, monkeypatch):
    class Killed(BaseException):
        pass

    real_roll, real_rmtree = outputs._roll_forward, outputs.shutil.rmtree

    def cut(staging, target):
        os.replace(staging / "files" / "old_a.txt", target / "old_a.txt")
        raise Killed

    with output_set(folder) as newer:  # run B starts ...
        _write(newer, ["b.txt"])
        monkeypatch.setattr(outputs, "_roll_forward", cut)
        monkeypatch.setattr(outputs.shutil, "rmtree", lambda *a, **k: None)
        with pytest.raises(Killed), output_set(folder) as older:  # ... run A commits, is killed
            _write(older, ["old_a.txt", "old_b.txt"])
        monkeypatch.setattr(outputs, "_roll_forward", real_roll)
        monkeypatch.setattr(outputs.shutil, "rmtree", real_rmtree)
    assert _names(folder) == ["b.txt", "mine.txt", MANIFEST]  # B's set, A's completed first
    assert _stagings(folder.parent) == []


def test_an_interrupt_that_surfaces_as_another_error_is_still_one_line(monkeypatch, capsys):
    # SIGINT inside a C extension's initialisation (matplotlib's ft2font while a run imports
    # it) reaches Python as "ImportError: initialization failed", not as KeyboardInterrupt
    from rotarykiln import cli

    def interrupted_import(args):
        try:
            signal.raise_signal(signal.SIGINT)
        except KeyboardInterrupt:
            raise ImportError("initialization failed") from None

    monkeypatch.setattr(cli, "_main", interrupted_import)
    assert cli.main(["run", "x"]) == 128 + signal.SIGINT
    err = capsys.readouterr().err
    assert err == "rotarykiln: interrupted\n"


def test_an_error_without_a_signal_is_not_taken_for_an_interrupt(monkeypatch):
    from rotarykiln import cli

    def broken(args):
        raise ImportError("a real bug")

    monkeypatch.setattr(cli, "_main", broken)
    with pytest.raises(ImportError, match="a real bug"):
        cli.main(["run", "x"])
