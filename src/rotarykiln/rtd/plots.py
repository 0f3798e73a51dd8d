"""Figures in the style of seed 003: parity plots with +/-20 % bands (Figs 3 and 10)."""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import InputError

__all__ = ["parity_plot"]


def parity_plot(
    measured, predicted, ax=None, *, band=0.2, label=None, quantity="", log=False, limits=None
):
    """Predicted against measured values with the y = x line and +/- ``band`` lines.

    Parameters
    ----------
    measured, predicted : array_like
        Values to compare (same unit, > 0 when ``log``).
    ax : matplotlib Axes, optional
    band : float
        Relative band drawn around y = x (0.2: the paper's +/-20 %).
    label : str, optional
        Legend label of the points.
    quantity : str
        Axis label text, e.g. "D [m2/s]".
    log : bool
        Logarithmic axes.
    limits : (low, high), optional
        Axis range (default: from the data).

    Returns
    -------
    matplotlib Figure
        The figure of ``ax`` (a new one when ``ax`` is None).
    """
    import matplotlib.pyplot as plt

    x = np.asarray(measured, dtype=float).ravel()
    y = np.asarray(predicted, dtype=float).ravel()
    if x.shape != y.shape or x.size == 0:
        raise InputError("predicted", f"{y.size} values for {x.size}", "one per measured value")
    if ax is None:
        _, ax = plt.subplots(figsize=(4.5, 4.5))
    ax.plot(x, y, "o", label=label)
    both = np.concatenate([x, y])
    if limits is not None:
        lo, hi = limits
    elif log:
        lo, hi = both[both > 0].min() / 1.5, both.max() * 1.5
    else:
        lo, hi = 0.0, both.max() * 1.1
    line = np.linspace(lo, hi, 50) if not log else np.geomspace(lo, hi, 50)
    ax.plot(line, line, "k-", lw=0.8)
    for f in (1 - band, 1 + band):
        ax.plot(line, f * line, "k--", lw=0.6)
    ax.set_xlim(lo, hi)
    ax.set_ylim(lo, hi)
    if log:
        ax.set_xscale("log")
        ax.set_yscale("log")
    ax.set_xlabel(f"measured {quantity}".strip())
    ax.set_ylabel(f"predicted {quantity}".strip())
    ax.set_title(f"+/-{100 * band:.0f} % lines", fontsize="small")
    if label:
        ax.legend()
    return ax.figure
