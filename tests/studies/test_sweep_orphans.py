"""Workers die with their sweep (issue 21): a ``rotarykiln sweep`` with 2 worker processes,
killed by SIGKILL while its pool computes, leaves no worker behind (they were left alive,
re-parented to init, idle for minutes). The model sleeps, so the test costs no CPU."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from rotarykiln.studies import runner

EXE = Path(sys.executable).with_name("rotarykiln")
MODEL = """\
import time


def slow(case):
    time.sleep(60.0)
    return {"x": 1.0}
"""

pytestmark = pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="needs /proc")


def _stat(pid: int) -> tuple[str, int] | None:
    """(state, parent pid) of a process, None if it is gone."""
    try:
        text = Path(f"/proc/{pid}/stat").read_text()
    except (FileNotFoundError, ProcessLookupError):
        return None
    fields = text[text.rindex(")") + 2 :].split()
    return fields[0], int(fields[1])


def _children(pid: int) -> list[int]:
    out = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            st = _stat(int(entry.name))
            if st is not None and st[1] == pid and st[0] != "Z":
                out.append(int(entry.name))
    return out


def _alive(pids) -> list[int]:
    return [p for p in pids if (st := _stat(p)) is not None and st[0] != "Z"]


def start_sweep(folder: Path) -> subprocess.Popen:
    """A sweep of 4 sleeping cases on 2 worker processes, as a subprocess."""
    (folder / "rk_slow_model.py").write_text(MODEL)
    cmd = [
        str(EXE),
        "sweep",
        "--case",
        "tscheng_A16",
        "--model",
        "rk_slow_model:slow",
        "--grid",
        "operation.speed=1 rpm,1.5 rpm,2 rpm,2.5 rpm",
        "--executor",
        "process",
        "--workers",
        "2",
        "--no-progress",
        "--out",
        str(folder / "out"),
    ]
    env = dict(os.environ, PYTHONPATH=str(folder), MPLBACKEND="Agg")
    return subprocess.Popen(
        cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env, cwd=folder
    )


def wait_for_workers(p: subprocess.Popen, n: int, timeout: float = 60.0) -> list[int]:
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        kids = _children(p.pid)
        if len(kids) >= n:
            return kids
        assert p.poll() is None, f"the sweep ended (exit {p.returncode}) before its workers ran"
        time.sleep(0.05)
    raise AssertionError(f"no {n} workers after {timeout} s")


def wait_gone(pids, timeout: float) -> list[int]:
    end = time.monotonic() + timeout
    while _alive(pids) and time.monotonic() < end:
        time.sleep(0.05)
    return _alive(pids)


def test_sigkill_of_a_sweep_leaves_no_worker(tmp_path):
    p = start_sweep(tmp_path)
    workers: list[int] = []
    try:
        workers = wait_for_workers(p, 2)
        time.sleep(0.3)  # the workers are in the model now
        p.send_signal(signal.SIGKILL)
        p.wait(timeout=10)
        orphans = wait_gone(workers, timeout=5.0)
    finally:
        p.kill()
        for pid in _alive(workers):  # clean up after a failure
            os.kill(pid, signal.SIGKILL)
    assert orphans == [], f"orphaned workers: {orphans}"


def test_a_worker_whose_parent_is_gone_exits_at_once(monkeypatch):
    # the race the initializer closes: the sweep died before the death signal was armed
    exits = []

    class Exited(BaseException):
        pass

    def fake_exit(code):
        exits.append(code)
        raise Exited

    monkeypatch.setattr(runner.os, "_exit", fake_exit)
    gone = 2**22 + 12345  # above the default pid_max: no such process
    with pytest.raises(Exited):
        runner._die_with_parent(gone)
    assert exits == [1]
    assert runner._alive(os.getpid()) and not runner._alive(gone)
