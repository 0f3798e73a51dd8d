import os
import stat

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
