import json
import os
import stat

import numpy as np
import pandas as pd
import pytest

from rotarykiln.outputs import write_frame_atomic, write_json_atomic, write_text_atomic


def test_atomic_writes_leave_no_temporaries_and_usual_mode(tmp_path):
    write_text_atomic(tmp_path / "a.txt", "hello")
    write_json_atomic(tmp_path / "b.json", {"x": float("nan"), "y": [1, 2]})
    write_frame_atomic(tmp_path / "c.csv", pd.DataFrame({"a": [1.0]}))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.txt", "b.json", "c.csv"]
    mode = stat.S_IMODE(os.stat(tmp_path / "a.txt").st_mode)
    assert mode & stat.S_IRGRP  # readable by others, not 0600
    assert '"x": null' in (tmp_path / "b.json").read_text()


def test_failed_write_keeps_previous_file(tmp_path):
    target = tmp_path / "keep.csv"
    target.write_text("old")

    class Boom(pd.DataFrame):
        def to_csv(self, *a, **k):
            raise RuntimeError("disk full")

    with pytest.raises(RuntimeError):
        write_frame_atomic(target, Boom({"a": [1]}))
    assert target.read_text() == "old"
    assert [p.name for p in tmp_path.iterdir()] == ["keep.csv"]


def test_no_plots_writes_no_figure(tmp_path):
    from rotarykiln import cli

    assert cli.main(["run", "tscheng_A16", "--out", str(tmp_path), "--no-plots"]) == 0
    names = {p.name for p in tmp_path.iterdir()}
    assert "kiln_profiles.csv" in names and "summary.json" in names
    assert not any(n.endswith((".png", ".svg", ".pdf")) for n in names)


def test_a_failing_figure_keeps_the_tables(tmp_path, monkeypatch, capsys):
    import matplotlib.figure

    from rotarykiln import cli

    def broken(self, *args, **kwargs):
        raise RuntimeError("renderer exploded")

    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", broken)
    assert cli.main(["run", "tscheng_A16", "--out", str(tmp_path)]) == 0
    assert "figure kiln_profiles.png not written: renderer exploded" in capsys.readouterr().err
    names = {p.name for p in tmp_path.iterdir()}
    assert {"kiln_profiles.csv", "kiln_summary.json", "summary.json"} <= names
    assert not any(n.endswith(".png") for n in names)


def test_a_second_run_into_the_same_folder_leaves_no_file_of_the_first(tmp_path):
    from rotarykiln import cli

    mine = tmp_path / "notes.txt"  # a user's own file in the folder is never touched
    mine.write_text("keep me")
    assert cli.main(["run", "limestone_fired", "--out", str(tmp_path)]) == 0
    assert (tmp_path / "kiln_rtd.png").is_file()  # the residence-time effects of a reacting bed
    assert cli.main(["run", "tscheng_A16", "--out", str(tmp_path)]) == 0
    names = {p.name for p in tmp_path.iterdir()}
    assert "kiln_profiles.csv" in names and "kiln_rtd.png" not in names
    assert mine.read_text() == "keep me"


def test_tables_are_written_with_their_units_and_version(tmp_path):
    import json

    import pandas as pd

    from rotarykiln import __version__, cli

    assert cli.main(["run", "tscheng_A16", "--out", str(tmp_path), "--no-plots"]) == 0
    meta = json.loads((tmp_path / "kiln_profiles_units.json").read_text())
    columns = list(pd.read_csv(tmp_path / "kiln_profiles.csv").columns)
    assert meta["table"] == "kiln_profiles.csv" and list(meta["units"]) == columns
    assert meta["units"]["T_bed_K"] == "K" and meta["units"]["z_m"] == "m"
    assert meta["rotarykiln_version"] == __version__ and meta["model"]
    assert (
        "kiln_profiles_units.json" in json.loads((tmp_path / "run_files.json").read_text())["files"]
    )


def test_writes_never_touch_the_process_umask(tmp_path, monkeypatch):
    """Issue 21: os.umask(0) then back is process-wide, racy in the threaded app server (a file
    another thread creates meanwhile gets mode 0666). The writers create their files with mode
    0666 and let the kernel apply the umask; the folders of a run set likewise."""
    from rotarykiln import outputs

    mask = os.umask(0o027)  # a umask other than the usual 022: the modes must follow it
    try:

        def forbidden(*args):
            raise AssertionError("os.umask called during a write")

        monkeypatch.setattr(os, "umask", forbidden)
        write_text_atomic(tmp_path / "a.txt", "hello")
        write_frame_atomic(tmp_path / "c.csv", pd.DataFrame({"a": [1.0]}))
        with outputs.output_set(tmp_path / "fresh") as staging:  # a fresh folder, committed
            write_json_atomic(staging / "s.json", {"x": 1})
        with outputs.output_set(tmp_path / "fresh") as staging:  # an existing one
            write_json_atomic(staging / "t.json", {"x": 2})
    finally:
        monkeypatch.undo()
        os.umask(mask)
    for name in ("a.txt", "c.csv", "fresh/t.json", "fresh/run_files.json"):
        assert stat.S_IMODE(os.stat(tmp_path / name).st_mode) == 0o640, name
    assert stat.S_IMODE(os.stat(tmp_path / "fresh").st_mode) == 0o750


def test_columns_written_without_pandas_are_the_frames_file_byte_for_byte(tmp_path):
    """The kiln profiles written from the solution's columns (no pandas import) are exactly
    what pandas writes for its to_frame(), the units file included."""
    import warnings

    from rotarykiln.case import load_case
    from rotarykiln.cases import builtin_case_path
    from rotarykiln.commands.kiln_runs import run_kiln_case
    from rotarykiln.outputs import write_columns_atomic, write_frame_atomic

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sol = run_kiln_case(load_case(builtin_case_path("limestone_fired")))
    columns = dict(sol.columns())
    columns["with_nan"] = np.where(np.arange(len(sol.z_nodes)) % 3 == 0, np.nan, 1e-300)
    frame = sol.to_frame()
    frame["with_nan"] = columns["with_nan"]
    from rotarykiln.tables import with_units

    frame = with_units(frame, "kiln")
    a = write_frame_atomic(tmp_path / "a.csv", frame)
    b = write_columns_atomic(tmp_path / "b.csv", columns, "kiln")
    assert a.read_bytes() == b.read_bytes()
    ua = json.loads((tmp_path / "a_units.json").read_text())
    ub = json.loads((tmp_path / "b_units.json").read_text())
    assert {**ua, "table": ""} == {**ub, "table": ""}
