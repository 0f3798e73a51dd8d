"""A disk cache of the Cantera-derived numbers (gas tables, burnt gas, dissociation heat).

Computing a gas table or a flame state needs Cantera (0.2 s to import, ~0.05 s per loaded
GRI-Mech 3.0 solution) and scipy's splines: seconds at every start of the command line for a
few kilobytes of numbers. They are kept here, one ``.npz`` file per result, in the user's cache
folder (``platformdirs.user_cache_dir("rotarykiln")``, e.g. ``~/.cache/rotarykiln``; the
environment variable ``ROTARYKILN_CACHE_DIR`` names another folder, ``off`` turns the cache
off).

A cache must never change a result. An entry holds the arrays and floats computed the first
time, stored exactly (binary ``.npz``), and its key is everything the result depends on:
the inputs (compositions, flows, temperatures as exact floats), the temperature grid, the
versions of Cantera, scipy, numpy and Python, the machine, the SHA-256 of the mechanism file
Cantera loads and of the rotarykiln modules that compute the result. The full key is stored in
the file and compared on reading (a hash collision or a stale file is a miss). Files are
written atomically (a temporary file renamed); a missing, damaged or unreadable entry, or a
folder that cannot be written, falls back to computing, with the same result.
"""

from __future__ import annotations

import hashlib
import os
import sys
import tempfile
from functools import lru_cache
from pathlib import Path

import numpy as np

__all__ = ["cache_dir", "load", "store", "environment_key"]

FORMAT = 1
"""Version of the file layout (bump to invalidate every entry)."""

_HERE = Path(__file__).parent


def cache_dir() -> Path | None:
    """The cache folder (not created here), or None when the cache is off."""
    env = os.environ.get("ROTARYKILN_CACHE_DIR")
    if env is not None:
        if env.strip().lower() in ("", "off", "0", "none", "false"):
            return None
        return Path(env).expanduser()
    return _default_dir()


@lru_cache(maxsize=1)
def _default_dir() -> Path:
    try:
        from platformdirs import user_cache_dir

        return Path(user_cache_dir("rotarykiln", appauthor=False))
    except Exception:  # pragma: no cover - platformdirs missing (pint brings it)
        base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
        return Path(base) / "rotarykiln"


def _sha256(path: Path) -> str:
    try:
        return hashlib.sha256(path.read_bytes()).hexdigest()
    except OSError:
        return "missing"


def _version(dist: str) -> str:
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version(dist)
    except PackageNotFoundError:  # pragma: no cover
        return "none"


def _mechanism_file(name: str) -> Path | None:
    """The file Cantera would load for ``name``: the first of its data directories that has it
    (the working folder, ``CANTERA_DATA``, the package's data; Cantera not imported)."""
    from importlib.util import find_spec

    folders = [Path.cwd()]
    folders += [Path(p) for p in os.environ.get("CANTERA_DATA", "").split(os.pathsep) if p]
    spec = find_spec("cantera")
    if spec is not None and spec.submodule_search_locations:
        folders += [Path(p) / "data" for p in spec.submodule_search_locations]
    for folder in folders:
        if (folder / name).is_file():
            return folder / name
    return None


@lru_cache(maxsize=8)
def _environment_key(mechanism: str, modules: tuple[str, ...], cwd: str, data: str) -> str:
    import platform

    mech = _mechanism_file(mechanism)
    parts = [
        f"format={FORMAT}",
        f"python={sys.version}",
        f"machine={platform.machine()}",
        f"cantera={_version('cantera')}",
        f"scipy={_version('scipy')}",
        f"numpy={np.__version__}",
        f"mechanism={mechanism}:{_sha256(mech) if mech is not None else 'missing'}",
    ]
    parts += [f"{m}={_sha256(_HERE / m)}" for m in modules]
    return ";".join(parts)


def environment_key(mechanism: str, modules: tuple[str, ...]) -> str:
    """What a result depends on beyond its inputs (versions, machine, mechanism and module
    hashes), as one string."""
    return _environment_key(mechanism, modules, os.getcwd(), os.environ.get("CANTERA_DATA", ""))


def _path(kind: str, key: str) -> Path | None:
    folder = cache_dir()
    if folder is None:
        return None
    digest = hashlib.sha256(key.encode()).hexdigest()[:40]
    return folder / f"{kind}-{digest}.npz"


def load(kind: str, key: str) -> dict[str, np.ndarray] | None:
    """The arrays stored under ``key``, or None (absent, damaged, another key, cache off)."""
    path = _path(kind, key)
    if path is None:
        return None
    try:
        with np.load(path, allow_pickle=False) as data:
            if str(data["__key__"]) != key:
                return None
            return {k: data[k] for k in data.files if k != "__key__"}
    except Exception:  # absent, truncated, not a zip, a missing array: compute again
        return None


def store(kind: str, key: str, arrays: dict) -> None:
    """Store ``arrays`` under ``key`` atomically; silently nothing if the cache cannot be written."""
    path = _path(kind, key)
    if path is None:
        return
    tmp = None
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{path.stem}-", suffix=".tmp", dir=path.parent)
        with os.fdopen(fd, "wb") as fh:
            np.savez(fh, __key__=np.array(key), **arrays)
        os.replace(tmp, path)
        tmp = None
    except Exception:  # read-only or full disk, a folder that is a file...: not cached
        pass
    finally:
        if tmp is not None:
            try:
                os.unlink(tmp)
            except OSError:
                pass
