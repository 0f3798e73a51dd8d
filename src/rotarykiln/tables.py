"""Tables that carry their units: the naming convention of columns and summary keys, and the
``DataFrame.attrs`` every ``to_frame()`` of a result sets.

The convention (docs/dev/architecture.md, "Names and units of outputs"): a column is
``<quantity>_<unit>`` and a summary key ``<model>_<quantity>_<unit>``, the unit last, written
with underscores for the spaces and slashes of the unit (``kg_s`` is kg/s, ``W_m2_K`` is
W/(m2 K), ``kg_s_m`` is kg/(s m), ``1_s`` is 1/s). A dimensionless number has no suffix
(``fill``, ``froude``, ``conversion``); a percentage ends in ``_percent``. :data:`UNIT_SUFFIXES`
is the one table of the suffixes; :func:`split_unit` reads it and :func:`frame_attrs` builds
the attrs ``{"units": {column: unit}, "rotarykiln_version": ..., "model": ...}`` (unit ``"1"``
for a dimensionless number, ``""`` for a column of text, flags or indices).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pandas comes with the first table: split_unit stays light for the CLI
    import pandas as pd

__all__ = ["UNIT_SUFFIXES", "column_unit", "frame_attrs", "split_unit", "with_units"]

#: Key suffix -> unit, longest first where one suffix ends another (``_kg_s_m`` before ``_m``).
UNIT_SUFFIXES: tuple[tuple[str, str], ...] = (
    ("_J_kg_K", "J/(kg K)"),
    ("_percent", "%"),
    ("_kg_s_m", "kg/(s m)"),
    ("_m2_s", "m2/s"),
    ("_m3_s", "m3/s"),
    ("_m3_h", "m3/h"),
    ("_W_m2_K", "W/(m2 K)"),
    ("_W_m_K", "W/(m K)"),
    ("_kg_m3", "kg/m3"),
    ("_rad_s", "rad/s"),
    ("_kg_s", "kg/s"),
    ("_kg_h", "kg/h"),
    ("_W_m2", "W/m2"),
    ("_J_kg", "J/kg"),
    ("_W_m", "W/m"),
    ("_m_s", "m/s"),
    ("_rpm", "rpm"),
    ("_deg", "deg"),
    ("_rad", "rad"),
    ("_min", "min"),
    ("_1_s", "1/s"),
    ("_kW", "kW"),
    ("_MW", "MW"),
    ("_s2", "s2"),
    ("_Pa", "Pa"),
    ("_m2", "m2"),
    ("_m3", "m3"),
    ("_mm", "mm"),
    ("_kg", "kg"),
    ("_K", "K"),
    ("_W", "W"),
    ("_J", "J"),
    ("_m", "m"),
    ("_s", "s"),
    ("_h", "h"),
)

#: The unit of a dimensionless number in :func:`frame_attrs`.
DIMENSIONLESS = "1"


def split_unit(key: str) -> tuple[str, str]:
    """Split a key into its name and its unit (``"length_m"`` -> ``("length", "m")``).

    Parameters
    ----------
    key : str
        A summary key or column name following the convention ``<name>_<unit>``.

    Returns
    -------
    tuple of str
        The name with spaces for underscores, and the unit (``""`` when the key has none).

    Examples
    --------
    >>> split_unit("kiln_gas_outlet_flow_kg_s")
    ('kiln gas outlet flow', 'kg/s')
    >>> split_unit("rtd_dispersion_m2_s")
    ('rtd dispersion', 'm2/s')
    >>> split_unit("drying_ahmad_onset_T_bed_K")
    ('drying ahmad onset T bed', 'K')
    >>> split_unit("rate_calcination_luisser_kg_s_m")
    ('rate calcination luisser', 'kg/(s m)')
    >>> split_unit("froude")
    ('froude', '')
    """
    for suffix, unit in UNIT_SUFFIXES:
        if key.endswith(suffix) and len(key) > len(suffix):
            return key[: -len(suffix)].replace("_", " "), unit
    return key.replace("_", " "), ""


def column_unit(name: str, series: pd.Series | None = None, *, float_column: bool = False) -> str:
    """The unit of a column from its name: the suffix's unit, else ``"1"`` for numbers and
    ``""`` for text, flags and integer indices.

    Examples
    --------
    >>> import pandas as pd
    >>> column_unit("T_bed_K"), column_unit("fill", pd.Series([0.1])), column_unit("regime")
    ('K', '1', '')
    """
    unit = split_unit(str(name))[1]
    if unit:
        return unit
    if float_column:  # a numeric column known to hold floats (no pandas needed)
        return DIMENSIONLESS
    from pandas.api.types import is_float_dtype

    if series is not None and is_float_dtype(series.dtype):
        return DIMENSIONLESS
    return ""


def frame_attrs(
    frame: pd.DataFrame, model: str, units: Mapping[str, str] | None = None
) -> dict[str, object]:
    """The attrs of a result table: the unit of every column, the package version, the model.

    Parameters
    ----------
    frame : pandas.DataFrame
        The table.
    model : str
        The model that made it (``"kiln"``, ``"transport.kramers"``...).
    units : mapping, optional
        Units of the columns whose name does not say it (override the suffix).

    Returns
    -------
    dict
        ``{"units": {column: unit}, "rotarykiln_version": str, "model": str}``.
    """
    import rotarykiln

    given = dict(units or {})
    return {
        "units": {str(c): given.get(str(c), column_unit(str(c), frame[c])) for c in frame.columns},
        "rotarykiln_version": rotarykiln.__version__,
        "model": model,
    }


def with_units(
    frame: pd.DataFrame, model: str, units: Mapping[str, str] | None = None
) -> pd.DataFrame:
    """Set :func:`frame_attrs` on ``frame`` and return it (the last line of a ``to_frame()``).

    Examples
    --------
    >>> import pandas as pd
    >>> df = with_units(pd.DataFrame({"z_m": [0.0, 1.0], "fill": [0.1, 0.1]}), "example")
    >>> df.attrs["units"], df.attrs["model"]
    ({'z_m': 'm', 'fill': '1'}, 'example')
    """
    frame.attrs.update(frame_attrs(frame, model, units))
    return frame
