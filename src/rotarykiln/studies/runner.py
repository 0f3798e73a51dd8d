"""Run a user function on every case of a sweep, in parallel local processes or on Dask.

The function takes a case (a nested dict, the base case with the swept fields set) and returns a
dict of scalar outputs. It can be any picklable callable, e.g. the kiln model wrapped as
``lambda``-free module-level function. An exception or a bad return value in one case is recorded
in that case's row (column ``error``) and the sweep goes on.
"""

from __future__ import annotations

import math
import numbers
import os
import pickle
import time
import traceback
from collections.abc import Callable, Mapping, Sequence
from concurrent.futures import ProcessPoolExecutor, as_completed
from typing import Any

from rotarykiln.errors import InputError
from rotarykiln.studies.design import CaseSpec
from rotarykiln.studies.paths import with_values
from rotarykiln.studies.result import SweepResult

__all__ = ["run_sweep", "run_case", "EXECUTORS"]

EXECUTORS = ("process", "serial", "dask")


def _scalar(v: Any) -> bool:
    return v is None or isinstance(v, numbers.Number | str | bool)


def run_case(func: Callable, base: Mapping, spec: CaseSpec, create: bool = False) -> dict:
    """Run one case; never raises: failures are returned in the ``error`` field.

    Returns
    -------
    dict
        ``case_id``, ``group``, ``outputs`` (dict), ``error`` (str, "" if fine), ``elapsed_s``.
    """
    t0 = time.perf_counter()
    row = {"case_id": spec.case_id, "group": spec.group, "outputs": {}, "error": ""}
    try:
        case = with_values(base, spec.values, create=create)
        out = func(case)
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
    except Exception as exc:  # recorded per case, the sweep goes on
        tb = traceback.extract_tb(exc.__traceback__)
        where = f" ({tb[-1].name}:{tb[-1].lineno})" if tb else ""
        row["error"] = f"{type(exc).__name__}: {exc}{where}"
    row["elapsed_s"] = time.perf_counter() - t0
    return row


def _run_chunk(func, base, specs, create):
    return [run_case(func, base, s, create) for s in specs]


def _chunks(seq: Sequence, n: int) -> list[list]:
    size = max(1, math.ceil(len(seq) / n))
    return [list(seq[i : i + size]) for i in range(0, len(seq), size)]


def _dask_compute(tasks, scheduler):
    import dask

    if scheduler is None:
        try:
            from distributed import get_client  # a running cluster client, if any

            return dask.compute(*tasks, scheduler=get_client())
        except (ImportError, ValueError):
            return dask.compute(*tasks, scheduler="processes")
    if isinstance(scheduler, str) and scheduler.startswith(("tcp://", "tls://", "inproc://")):
        try:
            from distributed import Client
        except ImportError:
            raise InputError(
                "sweep.dask_scheduler",
                scheduler,
                "a local scheduler name (dask.distributed is not installed)",
            ) from None
        with Client(scheduler) as client:
            return dask.compute(*tasks, scheduler=client)
    return dask.compute(*tasks, scheduler=scheduler)


def run_sweep(
    func: Callable[[dict], Mapping],
    base_case: Mapping,
    cases: Sequence[CaseSpec],
    *,
    executor: str = "process",
    max_workers: int | None = None,
    chunks_per_worker: int = 4,
    dask_scheduler: Any = None,
    create: bool = False,
) -> SweepResult:
    """Run ``func`` on every case of a design and gather one table.

    Parameters
    ----------
    func : callable
        ``func(case: dict) -> dict`` of scalar outputs. Must be picklable (a module-level function)
        for ``executor="process"`` and ``"dask"`` with a process scheduler.
    base_case : mapping
        The nested case the design modifies (field values as in a case file).
    cases : sequence of CaseSpec
        From :func:`~rotarykiln.studies.design.grid` or :func:`one_at_a_time`.
    executor : {"process", "serial", "dask"}
        ``process``: concurrent.futures.ProcessPoolExecutor on this machine (default);
        ``serial``: in this process (debugging, unpicklable functions); ``dask``:
        dask.delayed + dask.compute on ``dask_scheduler``.
    max_workers : int, optional
        Processes (default: the number of CPUs, at most the number of cases).
    chunks_per_worker : int
        Cases are sent in chunks (fewer round trips for cheap functions).
    dask_scheduler : None, str or Client
        None: the active dask.distributed client if one exists, else the local "processes"
        scheduler; "threads", "processes", "synchronous"; a "tcp://host:port" address or a
        Client.
    create : bool
        Allow paths absent from the base case.

    Returns
    -------
    SweepResult
        One row per case: ``case_id``, ``group``, each swept path (value as given) and its SI
        value, the outputs, ``error`` and ``elapsed_s``.

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
    for c in cases:
        with_values(base_case, c.values, create=create)
    t0 = time.perf_counter()
    if executor == "serial":
        rows = [run_case(func, base_case, c, create) for c in cases]
    elif executor == "process":
        try:
            pickle.dumps(func)
        except Exception:
            raise InputError(
                "sweep.function",
                getattr(func, "__name__", repr(func)),
                "picklable (a module-level function) for executor='process'; use executor='serial'",
            ) from None
        workers = max(1, min(max_workers or os.cpu_count() or 1, len(cases)))
        rows = []
        with ProcessPoolExecutor(max_workers=workers) as pool:
            futures = {
                pool.submit(_run_chunk, func, base_case, ch, create): ch
                for ch in _chunks(cases, workers * max(1, chunks_per_worker))
            }
            for fut in as_completed(futures):
                try:
                    rows.extend(fut.result())
                except Exception as exc:  # a worker died: record it for each case of the chunk
                    for c in futures[fut]:
                        rows.append(
                            {
                                "case_id": c.case_id,
                                "group": c.group,
                                "outputs": {},
                                "error": f"{type(exc).__name__}: {exc}",
                                "elapsed_s": float("nan"),
                            }
                        )
    else:
        try:
            import dask
        except ImportError:
            raise InputError(
                "sweep.executor", "dask", "available (dask is not installed)"
            ) from None
        tasks = [
            dask.delayed(_run_chunk)(func, base_case, ch, create)
            for ch in _chunks(
                cases, (max_workers or os.cpu_count() or 1) * max(1, chunks_per_worker)
            )
        ]
        rows = [r for chunk in _dask_compute(tasks, dask_scheduler) for r in chunk]
    wall = time.perf_counter() - t0
    return SweepResult.from_rows(rows, cases, wall_time=wall, executor=executor, base=base_case)
