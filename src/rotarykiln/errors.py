"""Error and warning types of rotarykiln.

- :class:`InputError`: a bad value. The message names the field, the value and what is accepted,
  on one line, e.g. ``kiln.diameter: -0.4 m is not > 0``.
- :class:`ConvergenceError`: a solver failed. The message says where and by how much; the
  ``diagnostics`` dict carries the numbers (iterations, residual norm, location).
- :class:`OutOfRangeWarning`: a correlation or model used outside the range its source validated.
"""

from __future__ import annotations

import math
import warnings
from typing import Any

import numpy as np

__all__ = [
    "ConvergenceError",
    "InputError",
    "OutOfRangeWarning",
    "check_positive",
    "check_nonnegative",
    "check_range",
    "warn_out_of_range",
]


class InputError(ValueError):
    """A value given by the user is not acceptable.

    Parameters
    ----------
    field : str
        Dotted path of the offending field (``"kiln.diameter"``) or argument name.
    value : object
        The value as given (a string with its unit is fine).
    accepted : str
        What would have been accepted, e.g. ``"> 0"`` or ``"in (0, 1)"``.
    """

    def __init__(self, field: str, value: Any = None, accepted: str = "", message: str = ""):
        self.field = field
        self.value = value
        self.accepted = accepted
        if (
            not message
            and (value is None or (isinstance(value, str) and value == "missing"))
            and accepted
        ):
            message = f"{field}: {_missing(accepted)}"  # not "x: missing is not given"
        if not message:
            message = (
                f"{field}: {_fmt(value)} is not {accepted}" if accepted else f"{field}: {value}"
            )
        # one line whatever the value held: a newline typed in a value is shown, not obeyed
        message = message.replace("\r", "\\r").replace("\n", "\\n")
        super().__init__(message)


class ConvergenceError(RuntimeError):
    """A solver did not converge.

    Parameters
    ----------
    message : str
        What failed, where and by how much.
    **diagnostics
        Numbers a caller may want: ``iterations``, ``residual``, ``location`` ...
    """

    def __init__(self, message: str, **diagnostics: Any):
        self.diagnostics = diagnostics
        if diagnostics:
            details = ", ".join(f"{k}={_fmt(v)}" for k, v in diagnostics.items())
            message = f"{message} ({details})"
        super().__init__(message)


class OutOfRangeWarning(UserWarning):
    """A model or correlation is used outside the range its source validated.

    Raised by :func:`warn_out_of_range`, which also sets what a run needs to tell the user more
    than the text (all None when not known): ``quantity`` (the name checked, with its unit in
    brackets, ``"d_p [um]"``), ``outside`` (the smallest and largest value outside the range),
    ``low`` and ``high`` (the range), ``source`` (author and year), ``closure`` (the closure
    that checked it, ``"covered_wall.li2005"``: see :mod:`rotarykiln.kiln.results.closure_warnings`)
    and ``mask`` (where the values checked were outside: a boolean array of their shape, None
    for a single value).
    """

    def __init__(
        self,
        *args: Any,
        quantity: str | None = None,
        outside: tuple[float, float] | None = None,
        low: float | None = None,
        high: float | None = None,
        source: str | None = None,
        closure: str | None = None,
        mask: np.ndarray | None = None,
    ):
        super().__init__(*args)
        self.mask = mask
        self.quantity = quantity
        self.outside = outside
        self.low = low
        self.high = high
        self.source = source
        self.closure = closure


def _missing(accepted: str) -> str:
    """The message "missing (required ...)" for a value not given, from what was accepted."""
    word, _, rest = accepted.partition(" ")
    if word not in ("given", "present"):
        return f"missing (required: {accepted})"
    if not rest:
        return "missing (required)"
    if rest.startswith("(") and rest.endswith(")") and rest.count("(") == 1:
        return f"missing (required: {rest[1:-1]})"
    return f"missing (required {rest})"


def _fmt(value: Any) -> str:
    if isinstance(value, float | np.floating):
        return f"{value:.6g}"
    if isinstance(value, np.ndarray):
        return np.array2string(value, precision=6, threshold=6)
    return str(value)


def _inside(value: Any, low: float, closed_low: bool, high: float, closed_high: bool) -> bool:
    """Fast path of the checks: True when every element is finite and inside the interval.

    Two reductions (min and max, which propagate NaN) instead of boolean temporaries, and no
    numpy dispatch for Python scalars, so that the checks stay cheap in inner loops and on
    large arrays; False sends the caller to the slow path that finds the offending element.
    """
    if type(value) is float or type(value) is int:
        lo = hi = value
    else:
        arr = (
            value
            if type(value) is np.ndarray and value.dtype == np.float64
            else np.asarray(value, dtype=float)
        )
        if arr.size == 0:
            return True
        lo, hi = arr.min(), arr.max()
    ok_low = lo >= low if closed_low else lo > low
    ok_high = hi <= high if closed_high else hi < high
    return bool(ok_low and ok_high) and math.isfinite(lo) and math.isfinite(hi)


def check_positive(field: str, value: Any, unit: str = "") -> None:
    """Raise :class:`InputError` unless every element of ``value`` is finite and > 0."""
    if _inside(value, 0.0, False, np.inf, False):
        return
    arr = np.asarray(value, dtype=float)
    bad = ~np.isfinite(arr) | (arr <= 0)
    if np.any(bad):
        v = arr[bad].flat[0] if arr.ndim else float(arr)
        raise InputError(field, f"{_fmt(float(v))}{' ' + unit if unit else ''}", "> 0")


def check_nonnegative(field: str, value: Any, unit: str = "") -> None:
    """Raise :class:`InputError` unless every element of ``value`` is finite and >= 0."""
    if _inside(value, 0.0, True, np.inf, False):
        return
    arr = np.asarray(value, dtype=float)
    bad = ~np.isfinite(arr) | (arr < 0)
    if np.any(bad):
        v = arr[bad].flat[0] if arr.ndim else float(arr)
        raise InputError(field, f"{_fmt(float(v))}{' ' + unit if unit else ''}", ">= 0")


def check_range(
    field: str,
    value: Any,
    low: float,
    high: float,
    *,
    closed_low: bool = False,
    closed_high: bool = False,
    unit: str = "",
) -> None:
    """Raise :class:`InputError` unless ``low < value < high`` (ends closed on request)."""
    if _inside(value, low, closed_low, high, closed_high):
        return
    arr = np.asarray(value, dtype=float)
    ok_low = arr >= low if closed_low else arr > low
    ok_high = arr <= high if closed_high else arr < high
    bad = ~np.isfinite(arr) | ~ok_low | ~ok_high
    if np.any(bad):
        v = arr[bad].flat[0] if arr.ndim else float(arr)
        interval = f"in {'[' if closed_low else '('}{low:g}, {high:g}{']' if closed_high else ')'}"
        raise InputError(field, f"{_fmt(float(v))}{' ' + unit if unit else ''}", interval)


def warn_out_of_range(
    what: str,
    value: Any,
    low: float,
    high: float,
    source: str,
    *,
    closure: str | None = None,
) -> bool:
    """Warn with :class:`OutOfRangeWarning` if any of ``value`` lies outside [low, high].

    ``closure`` (optional): the closure checking it (``"covered_wall.li2005"``, the case-file
    field under ``closures:`` and its value), kept on the warning with the range and the values
    outside it (and where: pass the values of every cell, not their span), for a kiln run to say
    which heat flow the closure feeds
    (:mod:`rotarykiln.kiln.results.closure_warnings`). Returns True when a warning was issued.
    """
    arr = np.asarray(value, dtype=float)
    if np.any((arr < low) | (arr > high)):
        mask = (arr < low) | (arr > high)
        outside = arr[mask]
        lo, hi = float(outside.min()), float(outside.max())
        if arr.ndim and arr.size > 1:
            shown = f"{_fmt(lo)}" if lo == hi else f"{_fmt(lo)} to {_fmt(hi)}"
        else:
            shown = _fmt(float(arr.ravel()[0]) if arr.ndim else float(arr))
        warnings.warn(
            OutOfRangeWarning(
                f"{what} = {shown} is outside the range [{low:g}, {high:g}] validated by {source}",
                quantity=what,
                outside=(lo, hi),
                low=float(low),
                high=float(high),
                source=source,
                closure=closure,
                mask=mask if arr.ndim else None,
            ),
            stacklevel=3,
        )
        return True
    return False
