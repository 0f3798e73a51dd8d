"""Load test of ``rotarykiln app``: many clients posting heavy runs, one light run measured.

Starts ``rotarykiln app --port 0`` on 127.0.0.1 in a process of its own, then for ``--seconds``
runs ``--clients`` threads that each post the Run callback with a heavy case (the
rotary_pyrolysis case at the most cells the app runs) as fast as they are answered (pausing
``--pause`` s after a busy answer), while one more client posts a light run (tscheng_A16) every
``--light-every`` s and times its answer. Every request's answer is counted by kind; the server's
resident memory and its two workers' (the heavy runs' and the light runs', told apart by their
command line) are sampled every 0.2 s.

Reported: the light run's answer time (median, max) and outcomes, the heavy runs' outcomes, the
server's and the workers' peak memory, and whether the server answered every request (a request with no HTTP
answer, a timeout or a refused connection, is counted as unanswered).

    python docs/scripts/app_load_test.py                   # 20 clients, 60 s
    python docs/scripts/app_load_test.py --clients 5 --seconds 10 --json

Standard library only (urllib to 127.0.0.1); Linux (memory from /proc).
"""

from __future__ import annotations

import argparse
import collections
import json
import re
import signal
import statistics
import subprocess
import sys
import threading
import time
from pathlib import Path

import yaml

from rotarykiln.app.checks import MAX_APP_CELLS
from rotarykiln.app.client import AppClient
from rotarykiln.cases import builtin_case_path


def _rss(pid: int) -> int:
    """Resident memory of a process, bytes (0 when it is gone)."""
    try:
        text = Path(f"/proc/{pid}/status").read_text()
    except OSError:
        return 0
    match = re.search(r"VmRSS:\s+(\d+) kB", text)
    return int(match.group(1)) * 1024 if match else 0


def _children(pid: int) -> list[int]:
    out = []
    for task in Path(f"/proc/{pid}/task").glob("*/children"):
        try:
            out += [int(p) for p in task.read_text().split()]
        except OSError:
            pass
    return out


def _worker_name(pid: int) -> str:
    """The name a worker has on its command line (``heavy``, ``light``), else ``worker``."""
    try:
        args = Path(f"/proc/{pid}/cmdline").read_bytes().split(b"\0")
    except OSError:
        return "worker"
    names = [a.decode() for a in args if a in (b"heavy", b"light")]
    return names[0] if names else "worker"


def _kind(answer) -> str:
    """What an answer says: finished, busy, stopped (over a bound), refused, error, http NNN."""
    if answer.status != 200:
        return f"http {answer.status}"
    status = answer.output("run-status") or ""
    if "finished" in status:
        return "finished"
    if "busy" in status:
        return "busy"
    if "stopped" in status:
        return "stopped"
    if "not done" in status:
        return "refused"
    return "error"


def _state(name: str, cells: int | None = None) -> dict:
    raw = yaml.safe_load(builtin_case_path(name).read_text(encoding="utf-8"))
    if cells:
        raw.setdefault("solver", {})["cells"] = cells
    return {"yaml": yaml.safe_dump(raw, sort_keys=False), "source": name}


def start_server() -> tuple[subprocess.Popen, str]:
    """``rotarykiln app --port 0`` in a new process; it and its URL."""
    process = subprocess.Popen(
        [sys.executable, "-m", "rotarykiln", "app", "--host", "127.0.0.1", "--port", "0"],
        stdout=subprocess.PIPE,
        text=True,
    )
    line = process.stdout.readline()
    match = re.search(r"(http://127\.0\.0\.1:\d+/)", line)
    if not match:
        process.kill()
        raise SystemExit(f"the server did not start: {line!r}")
    return process, match.group(1)


def load_test(url: str, pid: int, clients: int, seconds: float, pause: float, light_every: float):
    """Run the load on the server at ``url`` (process ``pid``); the report as a dict."""
    heavy_state = _state("rotary_pyrolysis", MAX_APP_CELLS)
    light_state = _state("tscheng_A16")
    deadline = time.monotonic() + seconds
    lock = threading.Lock()
    heavy: collections.Counter = collections.Counter()
    busy_times: list[float] = []
    light: list[tuple[str, float]] = []
    unanswered: list[str] = []
    peaks = {"server": _rss(pid), "heavy": 0, "light": 0, "worker": 0, "workers": 0}
    workers: set[int] = set()
    stop = threading.Event()

    def sample():
        while not stop.is_set():
            peaks["server"] = max(peaks["server"], _rss(pid))
            total = 0
            for child in _children(pid):
                workers.add(child)
                rss = _rss(child)
                total += rss
                name = _worker_name(child)
                peaks[name] = max(peaks[name], rss)
            peaks["workers"] = max(peaks["workers"], total)  # both at the same moment
            stop.wait(0.2)

    def heavy_client(i: int):
        client = AppClient(url, timeout=300)
        n = 0
        while time.monotonic() < deadline:
            n += 1
            try:
                answer = client.run(heavy_state, {"operation.speed": f"{1.5 + i / 100} rpm"}, n=n)
            except OSError as exc:
                with lock:
                    unanswered.append(f"heavy {i}: {type(exc).__name__}: {exc}")
                continue
            kind = _kind(answer)
            with lock:
                heavy[kind] += 1
                if kind == "busy":
                    busy_times.append(answer.seconds)
            if kind == "busy":
                time.sleep(pause)

    def light_client():
        client = AppClient(url, timeout=300)
        n = 0
        time.sleep(min(2.0, seconds / 4))  # the heavy clients first
        while time.monotonic() < deadline:
            n += 1
            try:
                answer = client.run(light_state, {"operation.speed": "2 rpm"}, n=n)
            except OSError as exc:
                with lock:
                    unanswered.append(f"light: {type(exc).__name__}: {exc}")
                continue
            light.append((_kind(answer), answer.seconds))
            time.sleep(light_every)

    sampler = threading.Thread(target=sample, daemon=True)
    sampler.start()
    threads = [threading.Thread(target=heavy_client, args=(i,)) for i in range(clients)]
    threads.append(threading.Thread(target=light_client))
    started = time.monotonic()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    elapsed = time.monotonic() - started
    stop.set()
    sampler.join()
    times = [s for _, s in light]
    done = [s for k, s in light if k == "finished"]
    return {
        "clients": clients,
        "seconds": round(elapsed, 1),
        "heavy_case": f"rotary_pyrolysis at {MAX_APP_CELLS} cells",
        "heavy_answers": dict(heavy),
        "busy_answer_s": {
            "median": round(statistics.median(busy_times), 4) if busy_times else None,
            "max": round(max(busy_times), 4) if busy_times else None,
        },
        "light_answers": dict(collections.Counter(k for k, _ in light)),
        "light_answer_s": {
            "median": round(statistics.median(times), 2) if times else None,
            "max": round(max(times), 2) if times else None,
        },
        "light_finished_s": {
            "median": round(statistics.median(done), 2) if done else None,
            "max": round(max(done), 2) if done else None,
        },
        "server_peak_rss_MB": round(peaks["server"] / 1e6, 1),
        "worker_peak_rss_MB": {
            name: round(peaks[name] / 1e6, 1)
            for name in ("heavy", "light", "worker")
            if peaks[name] or name != "worker"
        },
        "workers_peak_total_MB": round(peaks["workers"] / 1e6, 1),
        "unanswered": len(unanswered),
        "unanswered_examples": unanswered[:5],
        "worker_pids": sorted(workers),
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--clients", type=int, default=20, help="heavy clients (default 20)")
    parser.add_argument("--seconds", type=float, default=60.0, help="duration (default 60 s)")
    parser.add_argument(
        "--pause", type=float, default=0.25, help="pause after a busy answer, s (default 0.25)"
    )
    parser.add_argument(
        "--light-every", type=float, default=1.0, help="pause between light runs, s (default 1)"
    )
    parser.add_argument("--json", action="store_true", help="print the report as JSON")
    args = parser.parse_args(argv)
    if not 1 <= args.clients <= 100 or not 1 <= args.seconds <= 600:
        parser.error("--clients in [1, 100], --seconds in [1, 600]")
    process, url = start_server()
    try:
        time.sleep(3)  # the workers' imports
        report = load_test(
            url, process.pid, args.clients, args.seconds, args.pause, args.light_every
        )
        report["server_alive"] = process.poll() is None
    finally:
        process.send_signal(signal.SIGINT)  # Ctrl+C: the server stops its workers
        try:
            process.wait(timeout=20)
        except subprocess.TimeoutExpired:
            process.kill()
    time.sleep(1.5)  # a worker left alone ends within 0.5 s
    report["workers_left"] = sum(Path(f"/proc/{p}").exists() for p in report.pop("worker_pids"))
    if args.json:
        print(json.dumps(report, indent=2))
    else:
        for key, value in report.items():
            print(f"{key:>22}: {value}")
    ok = report["unanswered"] == 0 and report["server_alive"] and report["workers_left"] == 0
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
