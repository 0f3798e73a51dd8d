"""Run a user function on every case of a study: local processes or a Dask cluster, persistently.

The function takes a case (a nested dict, the base case with the design's fields set) and returns
a dict of scalar outputs; any picklable (module-level) callable will do. An exception or a bad
return value in one case is recorded in that case's row (column ``error``) and the study goes
on: no case is ever dropped.

With ``store=FOLDER`` the rows are appended to a Parquet dataset as they arrive
(:class:`~rotarykiln.studies.store.ResultStore`), keyed by a hash of the case: a study run again
on the same folder runs only the cases not yet stored (an interrupted sweep resumes). A progress
bar (tqdm, on stderr) shows done / failed / remaining and the rate.
"""

from __future__ import annotations

import logging
import math
import numbers
import os
import pickle
import signal
import sys
import time
import traceback
import warnings
from collections.abc import Callable, Iterator, Mapping, Sequence
from concurrent.futures import ProcessPoolExecutor, as_completed
from concurrent.futures.process import BrokenProcessPool
from typing import Any

import numpy as np

from rotarykiln.errors import InputError
from rotarykiln.studies.design import CaseSpec, si_value
from rotarykiln.studies.paths import get_path, with_values
from rotarykiln.studies.result import SI_SUFFIX, SweepResult
from rotarykiln.studies.store import FIXED_COLUMNS, ResultStore, case_hash

log = logging.getLogger(__name__)

__all__ = ["run_sweep", "run_case", "EXECUTORS", "model_id", "dask_client"]

EXECUTORS = ("process", "serial", "dask")
#: Most cases of a model with a batched form solved together by default (one chunk).
BATCH_CASES = 256
#: Most cases of a batched model solved together by default with ``executor="serial"``: the
#: design split evenly into chunks of at most this many. A 200-case sweep of Barr T4 in two
#: chunks took 0.47 s, in one 0.50 s, in four (as two workers would) 0.66 s: each chunk's
#: first case is solved alone, and its other cases start from a nearer solved one in a larger
#: chunk. Smaller chunks show the progress more often.
SERIAL_BATCH = 128
_LOCAL_SCHEDULERS = ("synchronous", "threads", "processes", "single-threaded", "sync")


def _scalar(v: Any) -> bool:
    return v is None or isinstance(v, numbers.Number | str | bool)


def run_case(func: Callable, base: Mapping, spec: CaseSpec, create: bool = False) -> dict:
    """Run one case; never raises: failures are returned in the ``error`` field.

    Warnings raised by the model are recorded (each distinct message once) in ``warnings``,
    not printed: a study of thousands of cases would otherwise flood the terminal.

    Returns
    -------
    dict
        ``case_id``, ``group``, ``outputs`` (dict), ``error`` (str, "" if fine), ``warnings``
        (str), ``elapsed_s``.
    """
    t0 = time.perf_counter()
    row = {"case_id": spec.case_id, "group": spec.group, "outputs": {}, "error": ""}
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        _run_into(row, func, base, spec, create)
    row["warnings"] = _warning_text(caught)
    row["elapsed_s"] = time.perf_counter() - t0
    return row


def _run_into(row: dict, func: Callable, base: Mapping, spec: CaseSpec, create: bool) -> None:
    try:
        case = with_values(base, spec.values, create=create)
        _outputs_into(row, func(case))
    except Exception as exc:  # recorded per case, the sweep goes on
        _error_into(row, exc)


def _outputs_into(row: dict, out) -> None:
    """The outputs of a model into ``row``: scalars only, non-finite ones an error."""
    if isinstance(out, Exception):
        raise out
    if not isinstance(out, Mapping):
        raise TypeError(f"the function returned {type(out).__name__}, not a dict of scalars")
    clean = {}
    bad = []
    for k, v in out.items():
        if hasattr(v, "item") and getattr(v, "ndim", 1) == 0:
            v = v.item()  # numpy scalar
        if not _scalar(v):
            raise TypeError(f"output {k!r} is a {type(v).__name__}, not a scalar")
        if isinstance(v, float) and not math.isfinite(v):
            bad.append(str(k))
        clean[str(k)] = v
    row["outputs"] = clean
    if bad:
        row["error"] = f"non-finite output: {', '.join(bad)}"


def _error_into(row: dict, exc: BaseException) -> None:
    tb = traceback.extract_tb(exc.__traceback__)
    where = f" ({tb[-1].name}:{tb[-1].lineno})" if tb else ""
    row["error"] = f"{type(exc).__name__}: {exc}{where}".replace("\n", " ")


def _warning_text(caught) -> str:
    seen: list[str] = []
    for w in caught:
        text = f"{w.category.__name__}: {w.message}".replace("\n", " ")
        if text not in seen:
            seen.append(text)
    return "; ".join(seen)


def _run_batched(func, base, specs, create) -> list[dict]:
    """Run the cases ``specs`` of one chunk by the model's batched form
    (``func.batched(cases, warnings_out, base=, changes=)``: every case solved together
    where the model can; ``changes`` the fields each case changes in ``base``); never
    raises: a case's failure is its row's ``error``."""
    t0 = time.perf_counter()
    rows = [
        {"case_id": s.case_id, "group": s.group, "outputs": {}, "error": "", "warnings": ""}
        for s in specs
    ]
    where = list(range(len(specs)))  # run_sweep checked every path set up front
    cases = _CaseDicts(base, [s.values for s in specs], create)
    caught: list[list] = [[] for _ in range(len(cases))]  # (not iterated: made when asked)
    with warnings.catch_warnings(record=True) as shared:
        warnings.simplefilter("always")
        try:
            changes = [specs[i].values for i in where]
            outs = list(func.batched(cases, caught, base=base, changes=changes))
        except Exception as exc:  # the batch itself broke: each case alone
            log.warning("batched model failed (%s); its cases run one at a time", exc)
            outs = None
    if outs is None:
        return [run_case(func, base, s, create) for s in specs]
    elapsed = (time.perf_counter() - t0) / max(1, len(specs))
    for k, i in enumerate(where):
        try:
            _outputs_into(rows[i], outs[k])
        except Exception as exc:
            _error_into(rows[i], exc)
        rows[i]["warnings"] = _warning_text([*caught[k], *shared])
    for r in rows:
        r["elapsed_s"] = elapsed
    return rows


class _CaseDicts(Sequence):
    """The case dicts of a chunk (the base with each case's values set), each made when
    asked for: a batched model that builds its cases from the base and their changes
    (:func:`rotarykiln.studies.models.kiln_solutions`) never asks, and a thousand deep
    copies of the base are saved."""

    def __init__(self, base: Mapping, values: list, create: bool):
        self.base, self.values, self.create = base, values, create

    def __len__(self) -> int:
        return len(self.values)

    def __getitem__(self, i):
        if isinstance(i, slice):
            return [self[k] for k in range(*i.indices(len(self)))]
        return with_values(self.base, self.values[i], create=self.create)


class _unbatched:
    """A model with its batched form hidden (``batch=1``): picklable, the same model id."""

    def __init__(self, func):
        self.func = func
        self.__module__ = getattr(func, "__module__", "")
        self.__qualname__ = getattr(func, "__qualname__", repr(func))

    def __call__(self, case):
        return self.func(case)


def _run_chunk(func, base, specs, create):
    if getattr(func, "batched", None) is not None and len(specs) > 1:
        return _run_batched(func, base, specs, create)
    return [run_case(func, base, s, create) for s in specs]


def _failed_rows(specs, message: str) -> list[dict]:
    return [
        {
            "case_id": c.case_id,
            "group": c.group,
            "outputs": {},
            "error": message,
            "warnings": "",
            "elapsed_s": float("nan"),
        }
        for c in specs
    ]


def _chunks(seq: Sequence, size: int) -> list[list]:
    return [list(seq[i : i + size]) for i in range(0, len(seq), size)]


def model_id(func: Callable) -> str:
    """``module:qualname`` of a model function (part of every case hash)."""
    mod = getattr(func, "__module__", "") or ""
    name = getattr(func, "__qualname__", None) or getattr(func, "__name__", None) or repr(func)
    return f"{mod}:{name}"


# --- executors: each yields worker rows as they arrive ------------------------------------------
#: Seconds between two looks of a worker at its parent (the portable watch, :func:`_watch_parent`).
PARENT_WATCH_S = 0.5
_PR_SET_PDEATHSIG = 1  # linux/prctl.h


def _die_with_parent(parent: int) -> None:
    """Make this worker process end when the process ``parent`` (the sweep) does, however it
    ends (SIGKILL included, which leaves no chance to stop the pool): on Linux the kernel's
    parent-death signal (``prctl(PR_SET_PDEATHSIG, SIGKILL)``, when the sweep forked the worker
    itself); everywhere a daemon thread that exits the worker once the sweep is gone or the
    worker has been re-parented (to init or a subreaper)."""
    ppid = os.getppid()
    if ppid == parent and sys.platform.startswith("linux"):
        try:
            import ctypes

            libc = ctypes.CDLL(None, use_errno=True)
            libc.prctl(_PR_SET_PDEATHSIG, int(signal.SIGKILL), 0, 0, 0)
        except (OSError, AttributeError):  # no libc prctl: the watch below still holds
            pass
    if os.getppid() != ppid or not _alive(parent):  # died before the signal was armed
        os._exit(1)
    import threading

    threading.Thread(
        target=_watch_parent, args=(parent, ppid), name="rotarykiln-parent-watch", daemon=True
    ).start()


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # exists, not ours
        return True
    return True


def _watch_parent(parent: int, ppid: int) -> None:
    while True:
        time.sleep(PARENT_WATCH_S)
        if os.getppid() != ppid or not _alive(parent):
            os._exit(1)


def _worker_init(parent: int, log_level: int = logging.NOTSET) -> None:
    """Pool initializer: Ctrl-C is left to the parent (which saves and stops the workers), and
    the worker dies with its parent (no orphan keeps computing or idling when the sweep is
    killed); with the parent's log level (``-v``), the worker's solves log on stderr too."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    _die_with_parent(parent)
    if log_level and not logging.getLogger("rotarykiln").handlers:
        handler = logging.StreamHandler(sys.stderr)
        handler.setFormatter(
            logging.Formatter(f"%(levelname)s worker {os.getpid()} %(name)s: %(message)s")
        )
        logger = logging.getLogger("rotarykiln")
        logger.addHandler(handler)
        logger.setLevel(log_level)


def _pool(workers: int) -> ProcessPoolExecutor:
    level = logging.getLogger("rotarykiln").getEffectiveLevel()
    level = level if level < logging.WARNING else logging.NOTSET
    return ProcessPoolExecutor(
        max_workers=workers, initializer=_worker_init, initargs=(os.getpid(), level)
    )


def _serial_rows(func, base, chunks, create) -> Iterator[dict]:
    for ch in chunks:
        yield from _run_chunk(func, base, ch, create)


def _isolated_rows(func, base, chunks, create) -> Iterator[dict]:
    """Chunks that were in a pool when it broke, several times: one at a time in a one-worker
    pool, so that a chunk that kills its worker is the only one marked failed."""
    pool = None
    try:
        for ch in chunks:
            if pool is None:
                pool = _pool(1)
            try:
                rows = pool.submit(_run_chunk, func, base, ch, create).result()
            except BrokenProcessPool as exc:
                pool.shutdown(wait=False, cancel_futures=True)
                pool = None
                if len(ch) > 1:  # find the case: each alone
                    yield from _isolated_rows(func, base, [[c] for c in ch], create)
                    continue
                rows = _failed_rows(ch, f"worker process died: {exc}".replace("\n", " "))
            except Exception as exc:
                rows = _failed_rows(ch, f"{type(exc).__name__}: {exc}".replace("\n", " "))
            yield from rows
    except BaseException:
        if pool is not None:
            for p in list(getattr(pool, "_processes", {}).values()):
                p.terminate()
            pool.shutdown(wait=False, cancel_futures=True)
            pool = None
        raise
    finally:
        if pool is not None:
            pool.shutdown(wait=True)


def _process_rows(func, base, chunks, create, workers, max_retries=2) -> Iterator[dict]:
    pending = [(ch, 0) for ch in chunks]
    while pending:
        suspects = [ch for ch, a in pending if a >= max_retries]
        pending = [(ch, a) for ch, a in pending if a < max_retries]
        if suspects:  # the pool broke repeatedly with these in it: find the culprit
            yield from _isolated_rows(func, base, suspects, create)
        if not pending:
            break
        pool = _pool(workers)
        try:
            futures = {
                pool.submit(_run_chunk, func, base, ch, create): (ch, a) for ch, a in pending
            }
            pending = []
            for fut in as_completed(futures):
                ch, attempts = futures[fut]
                try:
                    rows = fut.result()
                except BrokenProcessPool:  # a worker died (killed, out of memory, a crash)
                    pending.append((ch, attempts + 1))  # a new pool runs them again
                    continue
                except Exception as exc:  # e.g. an output that cannot be pickled back
                    rows = _failed_rows(ch, f"{type(exc).__name__}: {exc}".replace("\n", " "))
                yield from rows
        except BaseException:
            for p in list(getattr(pool, "_processes", {}).values()):  # stop now, not after chunks
                p.terminate()
            pool.shutdown(wait=False, cancel_futures=True)
            raise
        pool.shutdown(wait=True)


def dask_client(scheduler=None, workers: int | None = None, timeout: float = 10.0):
    """A ``distributed.Client``: the given one, one at ``scheduler`` or a new LocalCluster.

    Parameters
    ----------
    scheduler : None, str or Client
        None: the active client if any, else a LocalCluster of ``workers`` single-threaded
        processes; ``"tcp://host:port"``: connect; a Client: used as is.
    workers : int, optional
        Worker processes of the LocalCluster (default: CPUs).
    timeout : float
        Seconds to wait for a scheduler address, s.

    Returns
    -------
    tuple
        ``(client, owned)``: ``owned`` is True when the caller must close the client (and its
        cluster).
    """
    try:
        from distributed import Client, LocalCluster, get_client
    except ImportError:
        raise InputError(
            "sweep.executor", "dask", "available: pip install 'dask[distributed]'"
        ) from None
    if scheduler is None:
        try:
            return get_client(), False
        except ValueError:
            import logging

            cluster = LocalCluster(
                n_workers=max(1, workers or os.cpu_count() or 1),
                threads_per_worker=1,
                processes=True,
                dashboard_address=None,
                silence_logs=logging.CRITICAL,
            )
            return Client(cluster), True
    if isinstance(scheduler, str):
        try:
            return Client(scheduler, timeout=f"{timeout}s"), True
        except (OSError, TimeoutError, ValueError) as exc:
            reason = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
            raise InputError(
                "--scheduler", scheduler, f"a reachable Dask scheduler ({reason[:120]})"
            ) from None
    return scheduler, False


def _dask_rows(func, base, chunks, create, scheduler, workers, timeout) -> Iterator[dict]:
    if isinstance(scheduler, str) and scheduler in _LOCAL_SCHEDULERS:  # dask.compute, no cluster
        import dask

        tasks = [dask.delayed(_run_chunk)(func, base, ch, create) for ch in chunks]
        for rows in dask.compute(*tasks, scheduler=scheduler):
            yield from rows
        return
    from distributed import as_completed as dask_as_completed

    client, owned = dask_client(scheduler, workers, timeout)
    futures = []
    try:
        # the base case goes with each task (a few kB): scattered data would be lost for good
        # when every worker holding it dies, failing the rest of the study
        base_f = base
        futures = [
            client.submit(_run_chunk, func, base_f, ch, create, pure=False, retries=2)
            for ch in chunks
        ]
        specs = {f.key: ch for f, ch in zip(futures, chunks, strict=True)}
        ac = dask_as_completed(futures)
        for fut in ac:
            try:
                rows = fut.result()
            except Exception as exc:  # KilledWorker after repeated worker deaths, ...
                ch = specs[fut.key]
                if len(ch) > 1 and type(exc).__name__ == "KilledWorker":
                    for c in ch:  # find the case that kills its worker: each alone
                        f1 = client.submit(_run_chunk, func, base_f, [c], create, pure=False)
                        specs[f1.key] = [c]
                        futures.append(f1)
                        ac.add(f1)
                    fut.release()
                    continue
                rows = _failed_rows(ch, f"{type(exc).__name__}: {exc}".replace("\n", " "))
            fut.release()
            yield from rows
    finally:
        if futures:
            client.cancel([f for f in futures if not f.done()])
        if owned:
            cluster = getattr(client, "cluster", None)
            client.close()
            if cluster is not None:
                cluster.close()


# --- progress ---------------------------------------------------------------------------------
class _Progress:
    def __init__(self, total: int, done: int, failed: int, enabled: bool | None, desc: str):
        from rotarykiln.progress import progress_enabled

        enabled = progress_enabled(enabled)  # None: $ROTARYKILN_PROGRESS, else a tty
        self.bar = None
        self.failed = failed
        self.total = total
        self.done = done
        if enabled:
            from tqdm import tqdm

            self.bar = tqdm(
                total=total, initial=done, desc=desc, unit="case", file=sys.stderr, mininterval=0.2
            )
            self._postfix()

    def _postfix(self):
        self.bar.set_postfix(failed=self.failed, remaining=self.total - self.done, refresh=False)

    def update(self, failed: bool):
        self.done += 1
        self.failed += bool(failed)
        if self.bar is not None:
            self._postfix()
            self.bar.update(1)

    def close(self):
        if self.bar is not None:
            self._postfix()
            self.bar.refresh()
            self.bar.close()


# --- records ----------------------------------------------------------------------------------
def _base_values(base: Mapping, params: Sequence[str]) -> dict:
    out = {}
    for p in params:
        try:
            out[p] = get_path(base, p)
        except InputError:  # a path created by the sweep
            out[p] = None
    return out


def _record(row: dict, spec: CaseSpec, h: str, base_values: Mapping) -> dict:
    rec = {"hash": h, "case_id": spec.case_id, "group": spec.group}
    for p, bv in base_values.items():
        v = spec.values.get(p, bv)
        rec[p] = v
        rec[p + SI_SUFFIX] = si_value(v) if v is not None else np.nan
    outs = row["outputs"]
    rec.update(outs)
    rec["error"] = row["error"]
    rec["warnings"] = row.get("warnings") or ""
    rec["elapsed_s"] = row["elapsed_s"]
    rec["output_names"] = ",".join(outs)
    return rec


def _check_names(outputs, params):
    reserved = set(FIXED_COLUMNS) | set(params) | {p + SI_SUFFIX for p in params}
    clash = [o for o in outputs if o in reserved]
    if clash:
        raise InputError(
            "sweep.outputs", clash[0], "an output name distinct from parameters and columns"
        )


def run_sweep(
    func: Callable[[dict], Mapping],
    base_case: Mapping,
    cases: Sequence[CaseSpec],
    *,
    executor: str = "process",
    max_workers: int | None = None,
    chunks_per_worker: int = 4,
    chunk_size: int | None = None,
    dask_scheduler: Any = None,
    create: bool = False,
    store=None,
    progress: bool | None = False,
    flush_every: int = 1000,
    flush_seconds: float = 2.0,
    callback: Callable[[int, int, int], None] | None = None,
    dask_timeout: float = 10.0,
    batch: int | None = None,
) -> SweepResult:
    """Run ``func`` on every case of a design and gather one table (optionally persisted).

    Parameters
    ----------
    func : callable
        ``func(case: dict) -> dict`` of scalar outputs. Must be picklable (a module-level function)
        for ``executor="process"`` and ``"dask"``.
    base_case : mapping
        The nested case the design modifies (field values as in a case file).
    cases : sequence of CaseSpec
        From :mod:`rotarykiln.studies.design` (grid, one-at-a-time, Latin hypercube, Sobol...).
    executor : {"process", "serial", "dask"}
        ``process``: concurrent.futures.ProcessPoolExecutor on this machine (default; when a
        worker dies the unfinished chunks run again in a new pool; chunks that were in a broken
        pool twice then run one at a time, and a case that still kills its worker is stored as
        failed, alone); ``serial``: in this
        process; ``dask``: a dask.distributed cluster (see ``dask_scheduler``).
    max_workers : int, optional
        Processes (default: the number of CPUs, at most the number of chunks); the workers of
        a LocalCluster.
    chunks_per_worker : int
        With ``chunk_size`` None: cases per chunk = cases / (workers * chunks_per_worker), at
        most 32 (a chunk is the unit of work sent to a worker).
    chunk_size : int, optional
        Cases per chunk.
    dask_scheduler : None, str or Client
        None: the active dask.distributed client if one exists, else a LocalCluster of
        ``max_workers`` processes; a ``"tcp://host:port"`` address (an unreachable one is an
        InputError); a Client; or a local dask scheduler name ("synchronous", "threads",
        "processes": dask.compute, no streaming).
    create : bool
        Allow paths absent from the base case.
    store : path, optional
        Parquet dataset folder: rows are appended as they arrive and cases already stored (same
        case hash) are not run again. Without it the rows stay in memory.
    progress : bool or None
        Progress bar on stderr (None: when stderr is a terminal).
    flush_every, flush_seconds : int, float
        Write a part after this many new rows or seconds (s), whichever first.
    callback : callable, optional
        ``callback(done, failed, total)`` after each row (in the calling process).
    dask_timeout : float
        Seconds to wait for a scheduler address, s.
    batch : int, optional
        For a model with a batched form (``func.batched``, as the kiln models of
        :mod:`rotarykiln.studies.models`): the most cases solved together, a chunk (default:
        the cases over two chunks per worker, at most :data:`BATCH_CASES`; serial: chunks of
        even sizes, at most :data:`SERIAL_BATCH`); 1: one case at a time. Ignored for other
        models.

    Returns
    -------
    SweepResult
        One row per case: ``case_id``, ``group``, each swept path (value as given) and its SI
        value, the outputs, ``error``, ``elapsed_s`` and ``hash``; ``meta["ran"]`` and
        ``meta["reused"]`` count the cases run now and those taken from the store.

    Examples
    --------
    >>> from rotarykiln.studies.design import grid
    >>> from rotarykiln.studies.examples import first_order_conversion
    >>> base = {"reaction": {"rate_constant": "0.01 1/s"}, "operation": {"residence_time": "100 s"}}
    >>> res = run_sweep(first_order_conversion, base,
    ...                 grid({"operation.residence_time": ["50 s", "100 s"]}), executor="serial")
    >>> [round(x, 4) for x in res.frame["conversion"]]
    [0.3935, 0.6321]
    """
    if not callable(func):
        raise InputError("sweep.function", func, "a callable case -> dict")
    if executor not in EXECUTORS:
        raise InputError("sweep.executor", executor, f"one of {', '.join(EXECUTORS)}")
    cases = list(cases)
    if not cases:
        raise InputError("sweep.cases", "[]", "at least one case")
    ids = [c.case_id for c in cases]
    if len(set(ids)) != len(ids):
        raise InputError("sweep.cases", "duplicate case ids", "unique case ids")
    # validate every path once, up front (a typo should not cost a whole sweep)
    checked: set = set()
    for c in cases:
        key = tuple(sorted(c.values))
        if key not in checked:
            checked.add(key)
            with_values(base_case, c.values, create=create)
    if executor != "serial" and not (
        executor == "dask" and dask_scheduler in ("synchronous", "threads", "sync")
    ):
        try:
            pickle.dumps(func)
        except Exception:
            raise InputError(
                "sweep.function",
                getattr(func, "__name__", repr(func)),
                f"picklable (a module-level function) for executor={executor!r}; "
                "use executor='serial'",
            ) from None
    params: list[str] = []
    for c in cases:
        for p in c.values:
            if p not in params:
                params.append(p)
    base_values = _base_values(base_case, params)
    digest = ResultStore.digest(base_case)
    mid = model_id(func)
    hashes = {c.case_id: case_hash(digest, c.values, mid) for c in cases}

    st = ResultStore(store) if store is not None else None
    stored = st.hashes() if st is not None else set()
    todo = [c for c in cases if hashes[c.case_id] not in stored]
    # identical cases in one design run once
    seen: set = set()
    unique = []
    for c in todo:
        if hashes[c.case_id] not in seen:
            seen.add(hashes[c.case_id])
            unique.append(c)
    reused = len(cases) - len(todo)

    workers = max(1, max_workers or os.cpu_count() or 1)
    batched = getattr(func, "batched", None) is not None and batch != 1
    if batch is not None and (isinstance(batch, bool) or int(batch) != batch or batch < 1):
        raise InputError("sweep.batch", batch, "an integer >= 1 (cases solved together)")
    if batched and chunk_size is None and executor == "serial":
        # in this process: batches of at most SERIAL_BATCH cases, of even sizes
        parts = max(1, math.ceil(len(unique) / (batch or SERIAL_BATCH)))
        size = max(1, math.ceil(len(unique) / parts))
    elif batched and chunk_size is None:
        # a chunk is a batch: few, large chunks (two per worker)
        size = max(1, min(batch or BATCH_CASES, math.ceil(len(unique) / (workers * 2))))
    else:
        size = chunk_size or max(
            1, min(32, math.ceil(len(unique) / (workers * max(1, chunks_per_worker))))
        )
    if not batched and getattr(func, "batched", None) is not None:
        func = _unbatched(func)
    chunks = _chunks(unique, size)
    if executor == "process":
        workers = min(workers, max(1, len(chunks)))
    by_id = {c.case_id: c for c in cases}

    t0 = time.perf_counter()
    records: dict[str, dict] = {}
    buffer: list[dict] = []
    last_flush = time.monotonic()
    failed_before = 0
    bar = _Progress(len(cases), reused, failed_before, progress, "sweep")
    log.info(
        "sweep: %d cases (%d stored already, %d to run in %d chunks), executor %s, %s workers",
        len(cases),
        reused,
        len(unique),
        len(chunks),
        executor,
        workers,
    )
    try:
        if not unique:
            rows: Iterator[dict] = iter(())
        elif executor == "serial":
            rows = _serial_rows(func, base_case, chunks, create)
        elif executor == "process":
            rows = _process_rows(func, base_case, chunks, create, workers)
        else:
            rows = _dask_rows(
                func, base_case, chunks, create, dask_scheduler, max_workers, dask_timeout
            )
        for row in rows:
            spec = by_id[row["case_id"]]
            _check_names(row["outputs"], params)
            rec = _record(row, spec, hashes[spec.case_id], base_values)
            records[rec["hash"]] = rec
            bar.update(rec["error"] != "")
            log.info(
                "case %s (%d of %d): %s in %.3g s",
                spec.case_id,
                bar.done,
                len(cases),
                f"failed: {rec['error']}" if rec["error"] else "done",
                rec["elapsed_s"],
            )
            if st is not None:
                buffer.append(rec)
                if len(buffer) >= flush_every or time.monotonic() - last_flush > flush_seconds:
                    st.append(buffer)
                    buffer = []
                    last_flush = time.monotonic()
            if callback is not None:
                callback(bar.done, bar.failed, len(cases))
    finally:
        if st is not None and buffer:
            st.append(buffer)  # what has arrived is kept, also on Ctrl-C
        bar.close()
    wall = time.perf_counter() - t0

    if st is not None and reused:
        old = st.read()
        old = old[old["hash"].isin(set(hashes.values()) - set(records))]
        for rec in old.drop_duplicates("hash", keep="last").to_dict(orient="records"):
            names = [n for n in str(rec.get("output_names") or "").split(",") if n]
            row = {
                "outputs": {n: rec.get(n) for n in names},
                "error": rec.get("error") or "",
                "warnings": rec.get("warnings") or "",
                "elapsed_s": rec.get("elapsed_s", float("nan")),
            }
            records[rec["hash"]] = row
    frame_rows = []
    for c in sorted(cases, key=lambda c: c.case_id):
        r = records[hashes[c.case_id]]
        row = {
            "outputs": {n: r[n] for n in r["output_names"].split(",") if n}
            if "output_names" in r
            else r["outputs"],
            "error": r["error"],
            "warnings": r.get("warnings") or "",
            "elapsed_s": r["elapsed_s"],
        }
        frame_rows.append(_record(row, by_id[c.case_id], hashes[c.case_id], base_values))
    res = SweepResult.from_records(
        frame_rows,
        params,
        wall_time=wall,
        executor=executor,
        meta={"ran": len(unique), "reused": reused, "store": str(st.folder) if st else None},
    )
    return res
