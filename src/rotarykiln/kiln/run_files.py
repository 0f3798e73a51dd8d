"""Files of a kiln run (``rotarykiln run``): profiles CSV, summary JSON and figure."""

from __future__ import annotations

from pathlib import Path

__all__ = ["write_solution_files"]


def write_solution_files(solution, out, prefix: str, *, extra: dict | None = None, dpi=100):
    """Write ``<prefix>_profiles.csv``, ``<prefix>_summary.json`` and ``<prefix>_profiles.png``.

    The summary is ``solution.summary()`` (without the name) and ``extra``, every key prefixed
    with ``<prefix>_``; returned as a dict. Files are written atomically into ``out``.
    """
    from rotarykiln.outputs import (
        figures_wanted,
        save_figure_atomic,
        write_columns_atomic,
        write_json_atomic,
    )

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
