"""Kill test of ``rotarykiln sweep`` (issue 21): SIGKILL a sweep of 2 worker processes at random
moments and count the worker processes it leaves behind (orphans, re-parented to init).

Each round starts ``rotarykiln sweep --case tscheng_A16 --model kiln`` over a grid of 8 speeds
with ``--workers 2`` into a fresh folder, kills it with SIGKILL at a random moment (seeded) from
its start-up to the middle of its pool phase, and then looks, for 5 s, for the processes that were
its children at the moment of the kill. Linux only (reads /proc).

    python docs/scripts/kill_sweeps.py --n 20

Prints one line per kill and the totals; the exit code is 1 if any orphan remained.
"""

from __future__ import annotations

import argparse
import os
import random
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

EXE = Path(sys.executable).with_name("rotarykiln")
SPEEDS = ",".join(f"{v:g} rpm" for v in (1.0, 1.25, 1.5, 1.75, 2.0, 2.25, 2.5, 2.75))


def stat(pid: int):
    """(state, parent pid) of a process, None if it is gone."""
    try:
        text = Path(f"/proc/{pid}/stat").read_text()
    except (FileNotFoundError, ProcessLookupError):
        return None
    fields = text[text.rindex(")") + 2 :].split()
    return fields[0], int(fields[1])


def children(pid: int) -> list[int]:
    out = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            st = stat(int(entry.name))
            if st is not None and st[1] == pid and st[0] != "Z":
                out.append(int(entry.name))
    return out


def alive(pids) -> list[int]:
    return [p for p in pids if (st := stat(p)) is not None and st[0] != "Z"]


def one_kill(folder: Path, delay: float) -> tuple[int, list[int], float]:
    """(workers at the kill, orphans after 5 s, seconds the last worker took to go)."""
    cmd = [
        str(EXE),
        "sweep",
        "--case",
        "tscheng_A16",
        "--model",
        "kiln",
        "--grid",
        f"operation.speed={SPEEDS}",
        "--workers",
        "2",
        "--no-progress",
        "--out",
        str(folder),
    ]
    env = dict(os.environ, MPLBACKEND="Agg")
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    end = time.monotonic() + delay
    seen: set[int] = set()
    while time.monotonic() < end and p.poll() is None:
        seen.update(children(p.pid))
        time.sleep(0.02)
    seen.update(children(p.pid))
    workers = alive(seen)
    p.send_signal(signal.SIGKILL)
    p.wait()
    t0 = time.monotonic()
    deadline = t0 + 5.0
    while alive(workers) and time.monotonic() < deadline:
        time.sleep(0.02)
    gone_after = time.monotonic() - t0
    orphans = alive(workers)
    for pid in orphans:  # do not leave them running
        os.kill(pid, signal.SIGKILL)
    return len(workers), orphans, gone_after


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=20, help="number of kills")
    parser.add_argument("--seed", type=int, default=21)
    parser.add_argument("--earliest", type=float, default=1.0, help="s after the start")
    parser.add_argument("--latest", type=float, default=8.0, help="s after the start")
    args = parser.parse_args(argv)
    rng = random.Random(args.seed)
    total_orphans = in_pool = 0
    slowest = 0.0
    with tempfile.TemporaryDirectory(prefix="kill_sweeps-") as tmp:
        for i in range(args.n):
            delay = rng.uniform(args.earliest, args.latest)
            n_workers, orphans, gone = one_kill(Path(tmp) / f"sweep{i}", delay)
            in_pool += n_workers > 0
            total_orphans += len(orphans)
            if n_workers:
                slowest = max(slowest, gone)
            print(
                f"kill {i + 1:2d} at {delay:5.2f} s: {n_workers} worker(s) alive, "
                f"{len(orphans)} orphan(s), gone after {gone:.2f} s",
                flush=True,
            )
    print(
        f"{args.n} kills, {in_pool} during the pool phase; orphans: {total_orphans}; "
        f"the last worker gone at most {slowest:.2f} s after its sweep's SIGKILL"
    )
    return 1 if total_orphans else 0


if __name__ == "__main__":
    sys.exit(main())
