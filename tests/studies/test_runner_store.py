"""The persistent runner: Parquet store, resume, no lost case, atomic parts, Dask."""

import os
import signal
import subprocess
import sys
import textwrap
import time

import pandas as pd
import pytest

from rotarykiln.errors import InputError
from rotarykiln.studies import grid, run_sweep
from rotarykiln.studies.examples import crash_once, failing_model, sleepy_square, trivial_model
from rotarykiln.studies.store import ResultStore

X = [float(i) for i in range(20)]


def test_rows_are_stored_and_a_rerun_runs_nothing(tmp_path):
    store = tmp_path / "runs"
    res = run_sweep(sleepy_square, {"x": 0.0}, grid({"x": X}), executor="serial", store=store)
    assert (res.meta["ran"], res.meta["reused"]) == (20, 0) and res.n_failed == 0
    back = ResultStore(store).read()
    assert len(back) == 20 and set(back["hash"]) == set(res.frame["hash"])
    assert sorted(back["y"]) == [x * x for x in X]
    again = run_sweep(sleepy_square, {"x": 0.0}, grid({"x": X}), executor="serial", store=store)
    assert (again.meta["ran"], again.meta["reused"]) == (0, 20)
    cols = ["case_id", "x", "y", "error", "hash"]
    pd.testing.assert_frame_equal(again.frame[cols], res.frame[cols])
    # another base case is another case: run again
    other = run_sweep(
        sleepy_square,
        {"x": 0.0, "sleep_s": 0.0},
        grid({"x": X[:3]}),
        store=store,
        executor="serial",
    )
    assert other.meta["ran"] == 3


def test_interrupted_sweep_resumes_with_only_the_missing_cases(tmp_path):
    store = tmp_path / "runs"

    def stop(done, failed, total):
        if done == 7:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        run_sweep(
            sleepy_square, {"x": 0.0}, grid({"x": X}), executor="serial", store=store, callback=stop
        )
    assert len(ResultStore(store).read()) == 7  # what arrived before Ctrl-C was kept
    res = run_sweep(
        sleepy_square, {"x": 0.0}, grid({"x": X}), executor="process", max_workers=2, store=store
    )
    assert (res.meta["ran"], res.meta["reused"]) == (13, 7) and len(res.frame) == 20
    assert list(res.frame["y"]) == [x * x for x in X]
    assert len(ResultStore(store).read()) == 20


def test_failed_cases_are_stored_with_their_error_and_not_rerun(tmp_path):
    store = tmp_path / "runs"
    res = run_sweep(
        failing_model, {"x": 1.0}, grid({"x": [-1.0, 2.0]}), executor="serial", store=store
    )
    stored = ResultStore(store).read().set_index("x")
    assert "x = -1.0 < 0" in stored.loc[-1.0, "error"] and stored.loc[2.0, "error"] == ""
    assert res.n_failed == 1
    again = run_sweep(
        failing_model, {"x": 1.0}, grid({"x": [-1.0, 2.0]}), executor="serial", store=store
    )
    assert again.meta["ran"] == 0 and again.n_failed == 1


def test_a_dead_worker_process_loses_no_case(tmp_path):
    base = {"x": 0.0, "crash_at": 5.0, "marker": str(tmp_path / "crashed")}
    res = run_sweep(
        crash_once,
        base,
        grid({"x": X}),
        executor="process",
        max_workers=2,
        chunk_size=2,
        store=tmp_path / "runs",
    )
    assert (tmp_path / "crashed").exists()  # the worker did die
    assert res.n_failed == 0 and list(res.frame["y"]) == [2 * x for x in X]


def test_progress_bar_shows_done_failed_remaining(tmp_path, capsys):
    run_sweep(
        failing_model, {"x": 1.0}, grid({"x": [-1.0, 2.0, 3.0]}), executor="serial", progress=True
    )
    err = capsys.readouterr().err
    assert "3/3" in err and "failed=1" in err and "remaining=0" in err and "case/s" in err


def test_no_partly_written_part_survives_a_kill(tmp_path):
    store = tmp_path / "runs"
    script = textwrap.dedent(f"""
        from rotarykiln.studies import grid, run_sweep
        from rotarykiln.studies.examples import sleepy_square
        run_sweep(sleepy_square, {{"x": 0.0, "sleep_s": 0.01}},
                  grid({{"x": [float(i) for i in range(2000)]}}), executor="serial",
                  store={str(store)!r}, flush_every=5)
    """)
    proc = subprocess.Popen([sys.executable, "-c", script])
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline and len(list(store.glob("part-*.parquet"))) < 5:
        time.sleep(0.05)
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    parts = list(store.glob("part-*.parquet"))
    assert len(parts) >= 5
    for p in parts:  # every part that exists is whole
        assert len(pd.read_parquet(p)) == 5
    ResultStore(store)  # reopening removes any temporary file the kill left
    assert not [p for p in store.iterdir() if p.name.startswith(".")]


def test_unreachable_scheduler_is_one_line_error():
    with pytest.raises(InputError, match="reachable Dask scheduler") as e:
        run_sweep(
            trivial_model,
            {"x": 0},
            grid({"x": [1, 2]}),
            executor="dask",
            dask_scheduler="tcp://127.0.0.1:9",
            dask_timeout=1.0,
        )
    assert "\n" not in str(e.value)


def test_1000_cases_on_a_local_cluster_survive_a_killed_worker(tmp_path):
    distributed = pytest.importorskip("distributed")
    with (
        distributed.LocalCluster(
            n_workers=2, threads_per_worker=1, dashboard_address=None, silence_logs=50
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        pids = list(client.run(os.getpid).values())
        killed = []

        def kill_one(done, failed, total):
            if done >= 300 and not killed:
                os.kill(pids[0], signal.SIGKILL)
                killed.append(pids[0])

        res = run_sweep(
            sleepy_square,
            {"x": 0.0, "sleep_s": 0.002},
            grid({"x": [float(i) for i in range(1000)]}),
            executor="dask",
            dask_scheduler=client,
            chunk_size=10,
            store=tmp_path / "runs",
            callback=kill_one,
        )
    assert killed and len(res.frame) == 1000 and res.n_failed == 0
    assert len(ResultStore(tmp_path / "runs").read()) == 1000
    assert list(res.frame["y"]) == [float(i) ** 2 for i in range(1000)]


def test_sigint_then_restart_runs_only_the_missing_cases(tmp_path):
    store = tmp_path / "runs"
    script = textwrap.dedent(f"""
        from rotarykiln.studies import grid, run_sweep
        from rotarykiln.studies.examples import sleepy_square
        run_sweep(sleepy_square, {{"x": 0.0, "sleep_s": 0.005}},
                  grid({{"x": [float(i) for i in range(400)]}}), executor="process",
                  max_workers=2, chunk_size=4, store={str(store)!r}, flush_every=10)
    """)
    proc = subprocess.Popen(
        [sys.executable, "-c", script],
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
        stderr=subprocess.PIPE,
    )
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline and len(list(store.glob("part-*.parquet"))) < 3:
        time.sleep(0.05)
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=30)
    assert proc.returncode != 0 and b"KeyboardInterrupt" in err
    stored = len(ResultStore(store).read())
    assert 30 <= stored < 400
    res = run_sweep(
        sleepy_square,
        {"x": 0.0, "sleep_s": 0.005},
        grid({"x": [float(i) for i in range(400)]}),
        executor="process",
        max_workers=2,
        store=store,
    )
    assert res.meta["reused"] == stored and res.meta["ran"] == 400 - stored
    assert res.n_failed == 0 and len(ResultStore(store).read()) == 400


def test_a_case_that_always_kills_its_worker_fails_alone(tmp_path):
    base = {"x": 0.0, "crash_at": 5.0, "marker": str(tmp_path / "m"), "always": True}
    res = run_sweep(
        crash_once, base, grid({"x": X}), executor="process", max_workers=2, chunk_size=3
    )
    df = res.frame.set_index("x")
    assert res.n_failed == 1 and "worker process died" in df.loc[5.0, "error"]
    assert (df.drop(index=5.0)["y"] == 2 * df.drop(index=5.0).index).all()


def test_on_dask_a_case_that_always_kills_its_worker_fails_alone(tmp_path):
    pytest.importorskip("distributed")
    base = {"x": 0.0, "crash_at": 5.0, "marker": str(tmp_path / "m"), "always": True}
    res = run_sweep(
        crash_once,
        base,
        grid({"x": X}),
        executor="dask",
        max_workers=2,
        chunk_size=3,
        store=tmp_path / "runs",
    )
    df = res.frame.set_index("x")
    assert "KilledWorker" in df.loc[5.0, "error"]
    # Dask reschedules the tasks of a dead worker; an innocent case that keeps landing beside
    # the killer can also exhaust its retries (seen once in 5 CI runs under load): it is then
    # stored as failed with the same error, never lost
    failed = df[df["error"].notna() & (df["error"] != "")]
    assert 1 <= res.n_failed <= 2 and all("KilledWorker" in e for e in failed["error"])
    ok = df.drop(index=failed.index)
    assert (ok["y"] == 2 * ok.index).all()
    assert len(ResultStore(tmp_path / "runs").read()) == 20
