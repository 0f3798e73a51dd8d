"""Tables of Van Puyvelde (1999) shipped as CSV in ``rotarykiln/data/vanpuyvelde1999``.

See the README.md in that folder for provenance and reconstructed cells.
"""

from __future__ import annotations

from importlib import resources

import pandas as pd

from rotarykiln.errors import InputError

__all__ = ["TABLES", "load_table"]

TABLES = (
    "active_layer_deviation_small_drums",
    "bulk_density_loose",
    "grid_mixing_selected",
    "grid_mixing_speed",
    "grid_segregation_layer_sizes",
    "mixing_experiments",
    "particle_size_distribution",
    "retort_cases",
    "segregation_coefficients",
    "segregation_experiments",
    "segregation_validation_deviations",
    "shale_composition",
)


def load_table(name: str) -> pd.DataFrame:
    """Load one table of the thesis as a DataFrame (columns carry their units in the name).

    Examples
    --------
    >>> len(load_table("mixing_experiments"))
    27
    """
    if name not in TABLES:
        raise InputError("table", name, f"one of {', '.join(TABLES)}")
    path = resources.files("rotarykiln").joinpath("data", "vanpuyvelde1999", f"{name}.csv")
    with resources.as_file(path) as p:
        return pd.read_csv(p, dtype={"exp": str})
