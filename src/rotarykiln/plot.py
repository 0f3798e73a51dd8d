"""Figures for people. Models give ``.plot()`` on their results; this module composes figures."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg", force=False)

import matplotlib.pyplot as plt  # noqa: E402

from rotarykiln.geometry import CrossSection  # noqa: E402
from rotarykiln.regimes import plot_regime_map  # noqa: E402

__all__ = ["cross_section_figure", "regime_map_figure"]


def regime_map_figure(fill, froude, name: str | None = None):
    """A figure with the Mellmann regime map and the operating point(s); ``name`` (the case)
    titles it."""
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    plot_regime_map(fill, froude, ax=ax)
    if name:
        fig.suptitle(name)
    fig.tight_layout()
    return fig


def cross_section_figure(fill: float, radius: float, name: str | None = None):
    """A figure of the partly filled cross-section; ``name`` (the case) titles it."""
    fig, ax = plt.subplots(figsize=(4.5, 4.5))
    CrossSection.from_fill(fill, radius).plot(ax=ax)
    where = f"{name}: " if name else ""
    ax.set_title(f"{where}cross-section, R = {radius:g} m", fontsize=10)
    fig.tight_layout()
    return fig
