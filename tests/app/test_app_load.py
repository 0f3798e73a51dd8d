"""The app under load, briefly (docs/scripts/app_load_test.py is the long version): clients
posting heavy runs get an answer each, a busy one at once; a run over its time bound is stopped
and the server goes on; the run's process dies with the server."""

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
        worker = store.worker_pid()
    time.sleep(0.2)
    assert worker is None or not _alive(worker)  # the server stopped, its worker ended


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    status = Path(f"/proc/{pid}/status")
    return not (status.exists() and "zombie" in status.read_text())


def test_the_run_process_dies_with_the_server(tmp_path):
    """A server killed (SIGKILL: no clean-up of its own) leaves no worker behind."""
    script = (
        "from rotarykiln.app.running import RunStore\n"
        f"store = RunStore({str(tmp_path)!r}).start()\n"
        "print(store.worker_pid(), flush=True)\n"
        "import time; time.sleep(60)\n"
    )
    server = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    try:
        worker = int(server.stdout.readline())
        assert _alive(worker)
    finally:
        server.send_signal(signal.SIGKILL)
        server.wait(timeout=10)
    deadline = time.monotonic() + 10
    while _alive(worker) and time.monotonic() < deadline:
        time.sleep(0.1)
    assert not _alive(worker)


def test_light_runs_have_a_lane_of_their_own_and_go_first(tmp_path):
    """The queue alone (no run): one heavy run waits behind the one running, one more heavy run
    is busy, light runs still get in and go before the waiting heavy one."""
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
        with pytest.raises(ServerBusy, match="the server is busy"):
            store.check_free(False)
        store.check_free(None)  # the light lane is free
        for i in range(LIGHT_WAITING + 1):
            store.check_free(True)
            threads.append(threading.Thread(target=take_turn, args=(True, f"light {i}")))
            threads[-1].start()
            until(lambda n=i + 1: len(store._light) == n)
        for light in (True, False, None):
            with pytest.raises(ServerBusy):
                store.check_free(light)
        assert order == []
    for thread in threads:
        thread.join(timeout=10)
    assert order == [f"light {i}" for i in range(LIGHT_WAITING + 1)] + ["heavy"]
    store.check_free(False)
    store.check_free(True)
