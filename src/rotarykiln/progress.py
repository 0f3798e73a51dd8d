"""Progress bars of long loops: tqdm on stderr, shown only to a person watching.

:func:`progress_bar` is the one way the package makes a bar. A bar is shown when the caller
asks for one (``enabled=True``), else when the environment variable ``ROTARYKILN_PROGRESS`` is
``1`` (``0`` turns every bar off), else when stderr is a terminal. Bars write to stderr only, so
the ``--json`` output of a command on stdout stays clean; a disabled bar is a no-op object with
the same ``update``/``close`` methods, so a loop never tests whether it has one.
"""

from __future__ import annotations

import os
import sys

__all__ = ["progress_bar", "progress_enabled"]

_ENV = "ROTARYKILN_PROGRESS"


def progress_enabled(enabled: bool | None = None) -> bool:
    """Whether a bar is shown: ``enabled`` if given, else ``$ROTARYKILN_PROGRESS``, else a tty.

    Examples
    --------
    >>> progress_enabled(False), progress_enabled(True)
    (False, True)
    """
    if enabled is not None:
        return bool(enabled)
    env = os.environ.get(_ENV, "").strip().lower()
    if env in ("1", "true", "yes", "on"):
        return True
    if env in ("0", "false", "no", "off"):
        return False
    try:
        return sys.stderr.isatty()
    except (AttributeError, ValueError):  # a closed or replaced stderr
        return False


class _NoBar:
    """A bar that shows nothing (same methods as the tqdm ones used here)."""

    n = 0

    def update(self, n=1):
        self.n += n

    def set_postfix(self, *args, **kwargs):
        pass

    def set_postfix_str(self, *args, **kwargs):
        pass

    def refresh(self):
        pass

    def close(self):
        pass

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False


def progress_bar(
    total: float | None = None,
    *,
    desc: str = "",
    unit: str = "it",
    enabled: bool | None = None,
    leave: bool = False,
):
    """A tqdm bar on stderr, or a no-op bar when :func:`progress_enabled` says no.

    Parameters
    ----------
    total : float, optional
        The count (or amount: simulated seconds, metres...) at the end.
    desc, unit : str
        Label and unit of the bar.
    enabled : bool, optional
        True or False to force; None: ``$ROTARYKILN_PROGRESS``, else whether stderr is a tty.
    leave : bool
        Keep the finished bar on screen.

    Returns
    -------
    object
        A ``tqdm`` instance, or an object with the same ``update``/``set_postfix``/``close``.

    Examples
    --------
    >>> with progress_bar(3, desc="cases", enabled=False) as bar:
    ...     for _ in range(3):
    ...         bar.update(1)
    >>> bar.n
    3
    """
    if not progress_enabled(enabled):
        return _NoBar()
    from tqdm import tqdm

    kwargs = {}
    if total is not None and float(total) != int(total):  # an amount (s, m): 3 digits
        kwargs["bar_format"] = (
            "{desc}: {percentage:3.0f}%|{bar}| {n:.3g}/{total:.3g} "
            + unit
            + " [{elapsed}<{remaining}]"
        )
    return tqdm(
        total=total, desc=desc, unit=unit, leave=leave, file=sys.stderr, mininterval=0.2, **kwargs
    )
