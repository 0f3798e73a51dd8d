"""Atomic output writers: a file is either written whole or not at all; a run's files as a set.

Each writer writes to a temporary file in the destination folder, then ``os.replace`` s it over the
target, so an interrupted run never leaves a truncated result behind.

:func:`output_set` goes one step further for a whole run (``rotarykiln run``): the run writes into a
staging folder, and only a complete set of files is moved into the output folder, replacing the
files of the previous run there (named in its manifest ``run_files.json``); see docs/dev/hardening.md
for the exact guarantee under SIGINT, SIGTERM and SIGKILL.
"""

from __future__ import annotations

import contextlib
import contextvars
import errno
import hashlib
import json
import os
import secrets
import shutil
import signal
import tempfile
import threading
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:  # pandas is imported by the callers that write tables
    import pandas as pd

from rotarykiln.errors import InputError

__all__ = [
    "MANIFEST",
    "atomic_path",
    "figures_wanted",
    "output_set",
    "prepare_output_folder",
    "save_figure_atomic",
    "write_columns_atomic",
    "write_frame_atomic",
    "write_json_atomic",
    "write_solution_files",
    "write_text_atomic",
]


def atomic_path(path: str | os.PathLike, writer: Callable[[Path], None]) -> Path:
    """Call ``writer(tmp_path)`` then move ``tmp_path`` onto ``path`` atomically."""
    path = Path(path)
    if os.path.isdir(path):  # (False, not an error, for a name too long)
        raise InputError(str(path), message=f"{path}: is a folder, expected a file name")
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = _new_file(path.parent, f".{path.name}.", path.suffix)
    except OSError as exc:  # a user's path that cannot be written: one line, not a traceback
        raise InputError(
            str(path), message=f"{path}: cannot write there ({exc.strerror or exc})"
        ) from None
    try:
        writer(tmp)
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    return path


def _new_file(folder: Path, prefix: str, suffix: str) -> Path:
    """Create a new empty file of a random name in ``folder`` (``O_EXCL``), of mode 0o666 less
    the umask, applied by the kernel: the usual mode of a new file, without reading the umask
    (``os.umask`` is process-wide: changing it, even to read it, races the other threads of
    the app server)."""
    for _ in range(100):
        tmp = folder / f"{prefix}{secrets.token_hex(4)}{suffix}"
        try:
            fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_CLOEXEC, 0o666)
        except FileExistsError:
            continue
        os.close(fd)
        return tmp
    raise FileExistsError(errno.EEXIST, "no free temporary name", str(folder))


def write_text_atomic(path: str | os.PathLike, text: str) -> Path:
    """Write ``text`` (UTF-8) to ``path`` atomically."""
    return atomic_path(path, lambda p: p.write_text(text, encoding="utf-8"))


def _jsonable(obj: Any) -> Any:
    if isinstance(obj, dict):
        return {str(k): _jsonable(v) for k, v in obj.items()}
    if isinstance(obj, list | tuple):
        return [_jsonable(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return _jsonable(obj.tolist())
    if isinstance(obj, np.generic):
        return obj.item()
    if isinstance(obj, float) and not np.isfinite(obj):
        return None
    return obj


def to_json(data: Any) -> str:
    """JSON text of ``data`` (numpy arrays and scalars converted, non-finite floats as null)."""
    return json.dumps(_jsonable(data), indent=2, sort_keys=False)


def write_json_atomic(path: str | os.PathLike, data: Any) -> Path:
    """Write ``data`` as indented JSON atomically."""
    return write_text_atomic(path, to_json(data) + "\n")


def write_frame_atomic(path: str | os.PathLike, frame: pd.DataFrame, **to_csv_kwargs) -> Path:
    """Write a DataFrame to CSV atomically (index omitted unless asked).

    A frame that carries its units (``frame.attrs["units"]``, :mod:`rotarykiln.tables`) also
    gets ``<name>_units.json`` beside it: the unit of every column, the model and the
    rotarykiln version that wrote it (a CSV has no place for them).
    """
    to_csv_kwargs.setdefault("index", False)
    written = atomic_path(path, lambda p: frame.to_csv(p, **to_csv_kwargs))
    units = frame.attrs.get("units")
    if units:
        meta = {
            "table": written.name,
            "units": {str(c): units.get(str(c), units.get(c, "")) for c in frame.columns},
            "model": frame.attrs.get("model", ""),
            "rotarykiln_version": frame.attrs.get("rotarykiln_version", ""),
        }
        write_json_atomic(written.with_name(written.stem + "_units.json"), meta)
    return written


def _csv_cell(value) -> str:
    """A float as pandas' ``to_csv`` writes it: the shortest text that reads back to the same
    float (numpy's and Python's repr), an empty cell for NaN."""
    v = float(value)
    if v != v:  # NaN
        return ""
    return repr(v)


def write_columns_atomic(path: str | os.PathLike, columns: dict, model: str) -> Path:
    """Write numeric columns (name -> 1-D array of equal length) as CSV atomically, with
    ``<name>_units.json`` beside it: the file :func:`write_frame_atomic` writes for the same
    table as a DataFrame with its units (:func:`rotarykiln.tables.with_units`), byte for byte,
    without importing pandas (a command that writes one table starts faster).
    """
    import csv
    import io

    import rotarykiln
    from rotarykiln.tables import column_unit

    names = [str(c) for c in columns]
    arrays = [np.asarray(columns[c], dtype=float) for c in columns]
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(names)
    for row in zip(*arrays, strict=True):
        writer.writerow([_csv_cell(v) for v in row])
    written = write_text_atomic(path, buffer.getvalue())
    units = {n: column_unit(n, float_column=True) for n in names}
    meta = {
        "table": written.name,
        "units": units,
        "model": model,
        "rotarykiln_version": rotarykiln.__version__,
    }
    write_json_atomic(written.with_name(written.stem + "_units.json"), meta)
    return written


#: False inside :func:`no_figures`: :func:`save_figure_atomic` then writes nothing.
_FIGURES = contextvars.ContextVar("rotarykiln_figures", default=True)


@contextlib.contextmanager
def no_figures():
    """Within this context :func:`save_figure_atomic` writes no figure (``--no-plots``)."""
    token = _FIGURES.set(False)
    try:
        yield
    finally:
        _FIGURES.reset(token)


def figures_wanted() -> bool:
    """False inside :func:`no_figures`: a caller skips drawing a figure nobody will see."""
    return _FIGURES.get()


def save_figure_atomic(path: str | os.PathLike, fig, **savefig_kwargs) -> Path | None:
    """Save a matplotlib figure atomically; the format follows the suffix of ``path``.

    Inside :func:`no_figures` nothing is written (returns None). A figure that fails to render
    is reported as a warning and skipped: the tables written before it are kept.
    """
    if not _FIGURES.get():
        return None
    savefig_kwargs.setdefault("dpi", 120)
    savefig_kwargs.setdefault("bbox_inches", "tight")
    fmt = Path(path).suffix.lstrip(".").lower() or "png"
    supported = fig.canvas.get_supported_filetypes()
    if fmt not in supported:
        raise InputError(
            str(path),
            message=f'{path}: ".{fmt}" is not a figure format (use .png, .pdf or .svg)',
        )
    try:
        return atomic_path(path, lambda p: fig.savefig(p, format=fmt, **savefig_kwargs))
    except (OSError, InputError):
        raise
    except Exception as exc:  # a rendering failure must not lose the run's tables
        warnings.warn(f"figure {Path(path).name} not written: {exc}", RuntimeWarning, stacklevel=2)
        return None


# --------------------------------------------------------------------------------------------
# A run's output set: staged beside the output folder, committed as a whole.

#: The manifest a committed run leaves in its output folder: ``{"files": [...]}``, the names of
#: the files of that run (the manifest itself not included). The next run into the folder
#: replaces exactly these files; every other file there (the user's) is never touched.
MANIFEST = "run_files.json"

_STAGING = ".rotarykiln-staging-"  # + <key of the output folder>-<pid>-<random>
_JOURNAL = "commit.json"  # in the staging folder: written at the commit point
_FILES = "files"  # in the staging folder: the run's outputs


def _folder_key(folder: Path) -> str:
    return hashlib.sha1(str(folder).encode("utf-8", "surrogateescape")).hexdigest()[:12]


def _existing_ancestor(folder: Path) -> tuple[Path, list[Path]]:
    """The nearest ancestor of ``folder`` (itself included) that exists, and the missing folders
    from it down to ``folder`` (top first)."""
    missing = []
    q = folder
    while not os.path.lexists(q) and q.parent != q:
        missing.append(q)
        q = q.parent
    return q, missing[::-1]


def _staging_base(folder: Path) -> Path:
    """Where the staging folders of ``folder`` live: beside it (same file system, so a rename
    moves a file in atomically, and a SIGKILL leaves nothing inside ``folder``), or inside it when
    its parent cannot be written or lies on another file system (``folder`` is a mount point).
    A ``folder`` that does not exist yet: in its nearest existing ancestor (the folder is
    created by the commit, by renaming the staged files into place)."""
    if not folder.exists():
        return _existing_ancestor(folder)[0]
    parent = folder.parent
    if parent == folder:
        return folder
    try:
        same_device = parent.stat().st_dev == folder.stat().st_dev
    except OSError:
        return folder
    if same_device and os.access(parent, os.W_OK | os.X_OK):
        return parent
    return folder


@contextlib.contextmanager
def _locked(path: Path):
    """An exclusive ``flock`` on the folder ``path`` (released on exit or when the process dies)."""
    import fcntl

    fd = os.open(path, os.O_RDONLY | os.O_DIRECTORY)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        yield
    finally:
        os.close(fd)  # releases the lock


def _try_lock(path: Path) -> int | None:
    """An fd holding an exclusive non-blocking ``flock`` on ``path``, or None if it is held."""
    import fcntl

    try:
        fd = os.open(path, os.O_RDONLY | os.O_DIRECTORY)
    except OSError:
        return None
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        os.close(fd)
        return None
    return fd


@contextlib.contextmanager
def _signals_deferred():
    """SIGINT and SIGTERM received inside are held and delivered on exit (main thread only):
    the few renames of a commit are never cut in the middle by them."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    pending: list[int] = []
    sigs = (signal.SIGINT, signal.SIGTERM)
    previous = {s: signal.getsignal(s) for s in sigs}
    try:
        for s in sigs:
            signal.signal(s, lambda signum, frame: pending.append(signum))
        yield
    finally:
        for s in sigs:
            signal.signal(s, previous[s])
        for s in dict.fromkeys(pending):  # delivered now, to the handlers of the program
            signal.raise_signal(s)


def _manifest_names(folder: Path) -> list[str]:
    """Files the previous run wrote into ``folder`` (its manifest), [] if none or unreadable."""
    try:
        names = json.loads((folder / MANIFEST).read_text(encoding="utf-8")).get("files", [])
    except (OSError, ValueError, AttributeError):
        return []
    if not isinstance(names, list):
        return []
    return [
        n
        for n in names
        if isinstance(n, str)
        and n
        and "/" not in n
        and "\0" not in n
        and n[0] != "."
        and n != MANIFEST
    ]


def _roll_forward(staging: Path, folder: Path) -> None:
    """Finish the commit journaled in ``staging`` (idempotent): move its files into ``folder``
    (the manifest last), remove the previous run's files it replaces."""
    journal = json.loads((staging / _JOURNAL).read_text(encoding="utf-8"))
    for name in journal["files"]:
        src = staging / _FILES / name
        if src.exists():
            os.replace(src, folder / name)
    for name in journal["remove"]:
        (folder / name).unlink(missing_ok=True)


def _recover(folder: Path, base: Path) -> None:
    """Deal with the staging folders of ``folder`` left by runs that died (SIGKILL, power loss):
    one that had reached its commit point is completed, any other removed. Called with the lock
    of ``folder`` held; a staging folder still locked belongs to a live run and is left alone."""
    prefix = f"{_STAGING}{_folder_key(folder)}-"
    try:
        entries = [p for p in base.iterdir() if p.name.startswith(prefix) and p.is_dir()]
    except OSError:
        return
    for staging in entries:
        fd = _try_lock(staging)
        if fd is None:
            continue
        try:
            if (staging / _JOURNAL).is_file():
                with contextlib.suppress(OSError, ValueError, KeyError, TypeError):
                    _roll_forward(staging, folder)
            shutil.rmtree(staging, ignore_errors=True)
        finally:
            os.close(fd)


def _probe_creation(p: Path, field: str) -> None:
    """Check that the missing folder ``p`` can be created (its missing parents too) by creating
    and removing it at once: a fresh output folder appears only with the files of its run."""
    top, missing = _existing_ancestor(p.absolute())
    if not top.is_dir():
        raise InputError(
            field, str(p), message=f"{field}: cannot create {p} ({top} is not a folder)"
        )
    made = []
    try:
        for q in missing:
            os.mkdir(q)
            made.append(q)
    except OSError as exc:
        raise InputError(
            field, str(p), message=f"{field}: cannot create {p} ({exc.strerror})"
        ) from None
    finally:
        for q in reversed(made):
            with contextlib.suppress(OSError):  # (filled meanwhile by another run's commit)
                os.rmdir(q)


def prepare_output_folder(path: str | os.PathLike, field: str = "--out") -> Path:
    """Check, before any model runs, that a run can write its set into the output folder
    ``path``; complete or remove what runs killed earlier left (:func:`output_set`).

    An existing folder must be writable; a missing one must be creatable (it is not created
    here: :func:`output_set` creates it with its files, at the commit, so that a run killed
    before leaves no empty folder behind). Writes no file inside the folder. Raises
    :class:`InputError` naming ``field`` otherwise.
    """
    p = Path(path)
    try:
        exists = p.exists()
    except OSError as exc:  # a name too long, ...
        raise InputError(
            field, str(p), message=f"{field}: cannot create {p} ({exc.strerror})"
        ) from None
    if exists and not p.is_dir():
        raise InputError(field, str(p), message=f"{field}: {p} is a file, not a folder")
    if not exists:
        _probe_creation(p, field)
    elif not os.access(p, os.W_OK | os.X_OK):
        raise InputError(
            field, str(p), message=f"{field}: cannot write in {p} (no write permission)"
        )
    folder = p.resolve()
    base = _staging_base(folder)
    try:
        with _locked(folder if folder.is_dir() else base):
            _recover(folder, base)
    except OSError as exc:
        raise InputError(
            field, str(p), message=f"{field}: cannot use {p} ({exc.strerror})"
        ) from None
    return p


def _commit_fresh(staging: Path, names: list[str], folder: Path) -> bool:
    """Commit into a ``folder`` that does not exist: the staged files folder, manifest
    included, is renamed into place (one atomic rename: the folder appears whole, or not at
    all). False, with nothing changed, if ``folder`` exists by now (the caller then merges the
    set into it). Called with the lock of the staging base held."""
    if folder.exists():
        return False
    files = staging / _FILES
    write_json_atomic(files / MANIFEST, {"files": names})
    folder.parent.mkdir(parents=True, exist_ok=True)
    with _signals_deferred():
        try:
            os.rename(files, folder)  # the commit point
        except OSError:
            if folder.exists():  # created meanwhile (not empty): merge instead
                return False
            raise
        shutil.rmtree(staging, ignore_errors=True)
    return True


@contextlib.contextmanager
def output_set(path: str | os.PathLike, field: str = "--out"):
    """Stage the files of one run and commit them into the folder ``path`` as a whole.

    Yields the staging folder, where the run writes its files (flat: regular files only). When
    the block ends normally, the files are moved into ``path`` and the manifest
    :data:`MANIFEST` names them; the files the previous run's manifest named and this run did
    not write are removed; nothing else in ``path`` is touched. When the block raises
    (an error, a failed solve, KeyboardInterrupt), nothing in ``path`` changes and the staging
    folder is removed.

    The commit point is the journal written into the staging folder: SIGINT and SIGTERM are
    held from just before it to the end of the renames, so they leave the previous set or the new
    one. A SIGKILL (which nothing can hold) in those few renames leaves the journal, and the next
    :func:`prepare_output_folder` of the folder completes the commit first. The staging folder
    lives beside ``path`` (``.rotarykiln-staging-*``), inside it only when its parent cannot be
    written; one left by a SIGKILL is removed by the next run into ``path``. A ``path`` that does
    not exist is created by the commit itself, the staged folder renamed into place (its missing
    parents are created then too): a run stopped before its commit leaves no folder behind.
    """
    p = prepare_output_folder(path, field)
    folder = p.resolve()
    base = _staging_base(folder)
    staging: Path | None = None
    lock: int | None = None
    committing = False
    try:
        try:
            with _locked(folder if folder.is_dir() else base):
                staging = Path(
                    tempfile.mkdtemp(
                        prefix=f"{_STAGING}{_folder_key(folder)}-{os.getpid()}-", dir=base
                    )
                )
                lock = _try_lock(staging)  # held for the life of the run: a live staging folder
                (staging / _FILES).mkdir()
        except OSError as exc:
            raise InputError(
                field, str(p), message=f"{field}: cannot write beside or in {p} ({exc.strerror})"
            ) from None
        files = staging / _FILES
        yield files
        names = sorted(
            q.name
            for q in files.iterdir()
            if q.is_file() and q.name[0] != "." and q.name != MANIFEST
        )
        if not folder.exists():
            with _locked(base):
                committing = _commit_fresh(staging, names, folder)
            if committing:  # the folder appeared with the whole set in it
                committing = False
                return
        with _locked(folder):
            _recover(folder, base)  # an older commit cut by SIGKILL meanwhile goes in first
            previous = _manifest_names(folder)
            write_json_atomic(files / MANIFEST, {"files": names})
            journal = {
                "files": [*names, MANIFEST],
                "remove": [n for n in previous if n not in names],
            }
            with _signals_deferred():
                write_json_atomic(staging / _JOURNAL, journal)  # the commit point
                committing = True
                _roll_forward(staging, folder)
                shutil.rmtree(staging, ignore_errors=True)
                committing = False
    finally:
        if lock is not None:
            os.close(lock)
        if staging is not None and not committing:
            # a commit cut by an error (not a signal: they are held) stays for the next run
            shutil.rmtree(staging, ignore_errors=True)


def write_solution_files(solution, out, prefix: str, *, extra: dict | None = None, dpi=100):
    """Write ``<prefix>_profiles.csv``, ``<prefix>_summary.json`` and ``<prefix>_profiles.png``.

    The summary is ``solution.summary()`` (without the name) and ``extra``, every key prefixed
    with ``<prefix>_``; returned as a dict. Files are written atomically into ``out``.
    """
    out = Path(out)
    # the table of solution.to_frame(), written without pandas (a faster start)
    write_columns_atomic(out / f"{prefix}_profiles.csv", solution.columns(), "kiln")
    summary = {f"{prefix}_{k}": v for k, v in solution.summary().items() if k != "name"}
    summary.update({f"{prefix}_{k}": v for k, v in (extra or {}).items()})
    write_json_atomic(out / f"{prefix}_summary.json", summary)
    if not figures_wanted():  # --no-plots: matplotlib is not even imported
        return summary
    import matplotlib.pyplot as plt

    drawn = solution.plot()
    fig = getattr(drawn, "figure", drawn)  # an Axes or a Figure
    save_figure_atomic(out / f"{prefix}_profiles.png", fig, dpi=dpi)
    plt.close(fig)
    return summary
