"""The app under load, briefly (docs/scripts/app_load_test.py is the long version): clients
posting heavy runs get an answer each, a busy one at once; a run over its time bound is stopped
and the server goes on; a light run is answered within seconds while a heavy run is in progress
(each lane has a worker of its own); the run processes die with the server."""

from __future__ import annotations

import collections
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest
import yaml

from rotarykiln.cases import builtin_case_path

pytest.importorskip("dash")

from rotarykiln.app.checks import MAX_APP_CELLS  # noqa: E402
from rotarykiln.app.client import AppClient  # noqa: E402
from rotarykiln.app.running import RunStore  # noqa: E402
from rotarykiln.app.server import AppServer  # noqa: E402

CLIENTS = 5
SECONDS = 5.0
BOUND = 1.5  # s: a run of the test's server (the heavy case takes several seconds)
LANE_BOUND = 6.0  # s: a run of the lanes' test (a light run takes 1-2.5 s on a busy machine)


def _state(name: str, cells: int | None = None) -> dict:
    raw = yaml.safe_load(builtin_case_path(name).read_text(encoding="utf-8"))
    if cells:
        raw.setdefault("solver", {})["cells"] = cells
    return {"yaml": yaml.safe_dump(raw, sort_keys=False), "source": name}


def _kind(answer) -> str:
    status = answer.output("run-status") or ""
    for kind in ("finished", "busy", "stopped"):
        if kind in status:
            return kind
    return f"{answer.status}: {status} {answer.output('run-error')}"


def test_every_client_gets_an_answer_and_busy_ones_at_once(tmp_path):
    store = RunStore(tmp_path, max_seconds=BOUND, max_waiting=1)
    heavy = _state("rotary_pyrolysis", MAX_APP_CELLS)
    answers: list[tuple[str, float, str]] = []
    failures: list[str] = []
    lock = threading.Lock()
    with AppServer(port=0, store=store) as server:
        deadline = time.monotonic() + SECONDS

        def client(i: int) -> None:
            app = AppClient(server.url, timeout=120)
            n = 0
            while time.monotonic() < deadline:
                n += 1
                try:
                    answer = app.run(heavy, {"operation.speed": f"{2 + i / 10} rpm"}, n=n)
                except OSError as exc:  # no HTTP answer
                    with lock:
                        failures.append(f"{type(exc).__name__}: {exc}")
                    continue
                with lock:
                    answers.append((_kind(answer), answer.seconds, answer.output("run-error")))
                time.sleep(0.25)  # a client retrying at once, 4 times a second

        threads = [threading.Thread(target=client, args=(i,)) for i in range(CLIENTS)]
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join(timeout=120)
        assert not any(t.is_alive() for t in threads)

        assert failures == []
        kinds = collections.Counter(kind for kind, _, _ in answers)
        assert set(kinds) <= {"busy", "stopped"}, kinds  # no heavy run ends within the bound
        busy = sorted(s for kind, s, _ in answers if kind == "busy")
        assert busy and busy[len(busy) // 2] < 0.5 and busy[-1] < 3.0, busy
        stopped = [(s, m) for kind, s, m in answers if kind == "stopped"]
        assert stopped, kinds
        assert all(f"took longer than {BOUND:g} s" in m for _, m in stopped), stopped[0]

        # the server goes on: a light run finishes, in a worker started again
        light = AppClient(server.url, timeout=120).run(_state("tscheng_A16"), {}, n=1)
        assert _kind(light) == "finished" or "stopped" in _kind(light), _kind(light)
        assert store.worker_pid() is None or Path(f"/proc/{store.worker_pid()}").exists()
        workers = store.worker_pids()  # none when both were stopped by their last run
    time.sleep(0.2)
    assert not any(_alive(w) for w in workers)  # the server stopped, its workers ended


def test_a_light_run_is_answered_while_a_heavy_run_is_in_progress(tmp_path):
    """The light lane has a worker of its own: a light run posted while a heavy run is in
    progress is answered before the heavy run ends (it used to wait for it). The order is
    asserted, not a time: the heavy run (2,000 cells) outlasts a light one (about 1-2 s) by far
    and is stopped at the bound at the earliest."""
    store = RunStore(tmp_path, max_seconds=LANE_BOUND)
    heavy_answers: list[tuple[float, str]] = []
    with AppServer(port=0, store=store) as server:
        light_client = AppClient(server.url, timeout=120)
        first = light_client.run(_state("tscheng_A16"), {}, n=1)  # the light worker is ready
        assert _kind(first) == "finished", _kind(first)
        light_worker = store.worker_pid(light=True)
        assert light_worker and light_worker != store.worker_pid()

        def heavy_client() -> None:
            app = AppClient(server.url, timeout=120)
            answer = app.run(_state("rotary_pyrolysis", MAX_APP_CELLS), {}, n=1)
            heavy_answers.append((time.monotonic(), _kind(answer)))

        heavy = threading.Thread(target=heavy_client)
        heavy.start()
        deadline = time.monotonic() + 10
        while not store._heavy and time.monotonic() < deadline:
            time.sleep(0.01)
        in_progress = store._heavy[0]
        time.sleep(0.2)  # the heavy run is in its worker
        light = light_client.run(_state("tscheng_A16"), {"operation.speed": "2 rpm"}, n=2)
        answered = time.monotonic()
        assert _kind(light) == "finished", _kind(light)
        assert store._heavy and store._heavy[0] is in_progress  # the same heavy run goes on
        assert heavy_answers == []
        heavy.join(timeout=60)
        assert not heavy.is_alive()
        ((ended, kind),) = heavy_answers
        assert kind in ("finished", "stopped") and ended > answered, heavy_answers
        assert store.worker_pid(light=True) == light_worker  # not replaced with the heavy one


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    status = Path(f"/proc/{pid}/status")
    return not (status.exists() and "zombie" in status.read_text())


def test_the_run_process_dies_with_the_server(tmp_path):
    """A server killed (SIGKILL: no clean-up of its own) leaves no worker behind (neither the
    heavy runs' nor the light runs')."""
    script = (
        "from rotarykiln.app.running import RunStore\n"
        f"store = RunStore({str(tmp_path)!r}).start()\n"
        "print(*store.worker_pids(), flush=True)\n"
        "import time; time.sleep(60)\n"
    )
    server = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    try:
        workers = [int(pid) for pid in server.stdout.readline().split()]
        assert len(workers) == 2 and all(_alive(w) for w in workers)
    finally:
        server.send_signal(signal.SIGKILL)
        server.wait(timeout=10)
    deadline = time.monotonic() + 10
    while any(_alive(w) for w in workers) and time.monotonic() < deadline:
        time.sleep(0.1)
    assert not any(_alive(w) for w in workers)


def test_light_runs_have_a_lane_of_their_own(tmp_path):
    """The queue alone (no run): one heavy run waits behind the one running, one more heavy run
    is busy; light runs do not wait for the heavy one in progress, only for the light one, and
    their lane is busy in its turn."""
    from rotarykiln.app.running import LIGHT_WAITING, ServerBusy

    store = RunStore(tmp_path, max_waiting=1)
    order: list[str] = []

    def take_turn(light: bool, name: str) -> None:
        with store._turn(light):
            order.append(name)

    def until(condition) -> None:
        deadline = time.monotonic() + 10
        while not condition() and time.monotonic() < deadline:
            time.sleep(0.01)
        assert condition()

    threads = []
    with store._turn(False):  # a heavy run in progress
        threads.append(threading.Thread(target=take_turn, args=(False, "heavy")))
        threads[-1].start()
        until(lambda: len(store._heavy) == 2)
        with pytest.raises(ServerBusy, match=r"the server is busy \(a run and 1 waiting\)"):
            store.check_free(False)
        store.check_free(None)  # the light lane is free
        with store._turn(True):  # a light run in progress beside the heavy one, at once
            for i in range(LIGHT_WAITING):
                store.check_free(True)
                threads.append(threading.Thread(target=take_turn, args=(True, f"light {i}")))
                threads[-1].start()
                until(lambda n=i + 2: len(store._light) == n)
            for light in (True, False, None):
                with pytest.raises(ServerBusy):
                    store.check_free(light)
            assert order == []
        until(lambda: len(order) == LIGHT_WAITING)  # the light runs, the heavy one still on
        assert order == [f"light {i}" for i in range(LIGHT_WAITING)]
        store.check_free(True)
        assert len(store._heavy) == 2
    for thread in threads:
        thread.join(timeout=10)
    assert order == [f"light {i}" for i in range(LIGHT_WAITING)] + ["heavy"]
    store.check_free(False)
    store.check_free(True)
