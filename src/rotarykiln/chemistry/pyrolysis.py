"""Oil-shale pyrolysis: kerogen kinetics and the Table 9.1 shale of seed 000.

- :func:`wen_yen_rate_constants` and :func:`wen_yen_kerogen_rates`: the five-rate kerogen scheme
  of Wen & Yen (1977) with the parameters of Carrasco & Banga (1997) (closures.md 5d):
  kerogen (x1) -> pyrolytic bitumen (x2) -> oil + gas (x3), and kerogen -> organic carbon (x4).
- :func:`oil_shale_table`, :func:`berkovich_conversion` and :func:`berkovich_reaction_enthalpy`:
  the Stuart shale of seed 000 Table 9.1 (Berkovich 1999): composition, reaction temperature
  ranges, reaction heats (J per g of original shale) and the exponential conversion curves.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

from rotarykiln.errors import InputError, check_nonnegative, check_positive, warn_out_of_range
from rotarykiln.tables import with_units

__all__ = [
    "WEN_YEN_PARAMETERS",
    "wen_yen_rate_constants",
    "wen_yen_kerogen_rates",
    "ShaleTable",
    "oil_shale_table",
    "berkovich_conversion",
    "berkovich_reaction_enthalpy",
    "kerogen_reaction_heat",
    "oil_shale_feed_composition",
]

#: R in kcal/(mol K), as used with the kcal/mol activation energies of the scheme.
_R_KCAL = 1.9872e-3

#: (a_i, E_i [kcal/mol]) of k_i = exp(a_i - E_i/(R T)) in 1/min, i = 1..5 (Carrasco & Banga 1997).
WEN_YEN_PARAMETERS = (
    (8.86, 20.3),
    (24.25, 37.4),
    (23.67, 33.8),
    (18.75, 28.2),
    (20.70, 31.0),
)

_DATA = Path(__file__).resolve().parents[1] / "data" / "chemistry" / "oil_shale_table_9_1.csv"


def wen_yen_rate_constants(T):
    r"""Rate constants k1..k5 of the Wen & Yen kerogen scheme, 1/s.

    .. math:: k_i = \exp\!\left(a_i - \frac{E_i}{R T}\right)\ \mathrm{min^{-1}}

    =====  ======  ===============
    i      a_i     E_i (kcal/mol)
    =====  ======  ===============
    1      8.86    20.3
    2      24.25   37.4
    3      23.67   33.8
    4      18.75   28.2
    5      20.70   31.0
    =====  ======  ===============

    The parameters give k in 1/min (time unit of the Carrasco & Banga benchmark, closures.md
    5d, [MEMORY, verify]); this function returns 1/s (divided by 60).

    Parameters
    ----------
    T : float or array
        Temperature, K.

    Returns
    -------
    ndarray
        Shape ``(5,) + shape(T)``, 1/s.

    Notes
    -----
    Validated over 698.15-748.15 K (the benchmark's temperature bounds); a warning is issued
    outside 650-800 K.

    Examples
    --------
    >>> k = wen_yen_rate_constants(723.0) * 60.0     # back to 1/min
    >>> [round(float(v), 3) for v in k]
    [0.005, 0.168, 1.156, 0.416, 0.416]

    References
    ----------
    C.Y. Wen, T.F. Yen, Optimization of oil shale pyrolysis, Chem. Eng. Sci. 32 (1977) 346-349;
    E.F. Carrasco, J.R. Banga, Dynamic optimization of batch reactors using adaptive stochastic
    algorithms, Ind. Eng. Chem. Res. 36 (1997) 2252-2261.
    """
    T = np.asarray(T, dtype=float)
    check_positive("pyrolysis.T", T, "K")
    warn_out_of_range("T [K]", T, 650.0, 800.0, "Wen & Yen (1977) / Carrasco & Banga (1997)")
    return _wen_yen_k(T)


def _wen_yen_k(T):
    T = np.asarray(T, dtype=float)
    a = np.array([p[0] for p in WEN_YEN_PARAMETERS]).reshape((5,) + (1,) * T.ndim)
    E = np.array([p[1] for p in WEN_YEN_PARAMETERS]).reshape((5,) + (1,) * T.ndim)
    return np.exp(a - E / (_R_KCAL * T)) / 60.0


def wen_yen_kerogen_rates(x1, x2, T):
    r"""Time derivatives of the Wen & Yen kerogen scheme (mass fractions of the initial kerogen).

    .. math::
        \dot x_1 &= -k_1 x_1 - (k_3 + k_4 + k_5) x_1 x_2 \\
        \dot x_2 &= k_1 x_1 - k_2 x_2 + k_3 x_1 x_2 \\
        \dot x_3 &= k_2 x_2 + k_4 x_1 x_2 \\
        \dot x_4 &= k_5 x_1 x_2

    Parameters
    ----------
    x1, x2 : float or array
        Kerogen and bitumen mass fractions of the initial kerogen, [-].
    T : float or array
        Temperature, K.

    Returns
    -------
    tuple of ndarray
        (dx1/dt, dx2/dt, dx3/dt, dx4/dt), 1/s; they sum to zero (mass conserved).

    Examples
    --------
    >>> d = wen_yen_kerogen_rates(1.0, 0.0, 723.0)
    >>> [round(float(v) * 60, 5) for v in d]    # per minute
    [-0.00515, 0.00515, 0.0, 0.0]

    References
    ----------
    C.Y. Wen, T.F. Yen, Optimization of oil shale pyrolysis, Chem. Eng. Sci. 32 (1977) 346-349;
    parameters of Carrasco & Banga (1997) (see :func:`wen_yen_rate_constants`).
    """
    check_nonnegative("x1", x1)
    check_nonnegative("x2", x2)
    k1, k2, k3, k4, k5 = wen_yen_rate_constants(T)
    x1 = np.asarray(x1, dtype=float)
    x2 = np.asarray(x2, dtype=float)
    d1 = -k1 * x1 - (k3 + k4 + k5) * x1 * x2
    d2 = k1 * x1 - k2 * x2 + k3 * x1 * x2
    d3 = k2 * x2 + k4 * x1 * x2
    d4 = k5 * x1 * x2
    return d1, d2, d3, d4


@dataclass(frozen=True)
class ShaleTable:
    """Seed 000 Table 9.1 as arrays (one entry per material)."""

    material: tuple[str, ...]
    mass_fraction: np.ndarray  # [-]
    T_low: np.ndarray  # K (NaN: no reaction)
    T_high: np.ndarray  # K (NaN: not printed)
    enthalpy: np.ndarray  # J per kg of original shale (0: none)
    decay_constant: np.ndarray  # K

    def to_frame(self) -> pd.DataFrame:
        """The table; ``enthalpy_J_kg`` per kg of shale."""
        import pandas as pd

        frame = pd.DataFrame(
            {
                "material": self.material,
                "mass_fraction": self.mass_fraction,
                "T_low_K": self.T_low,
                "T_high_K": self.T_high,
                "enthalpy_J_kg": self.enthalpy,
                "decay_constant_K": self.decay_constant,
            }
        )
        return with_units(frame, "chemistry.pyrolysis.oil_shale")


@lru_cache(maxsize=1)
def oil_shale_table() -> ShaleTable:
    """Seed 000 Table 9.1 (Stuart oil shale, Berkovich 1999), from ``data/chemistry``.

    Examples
    --------
    >>> t = oil_shale_table()
    >>> round(float(t.mass_fraction.sum()), 6), round(float(t.enthalpy.sum()) / 1000, 2)
    (1.0, 896.66)
    """
    import pandas as pd

    df = pd.read_csv(_DATA)
    return ShaleTable(
        material=tuple(df["material"]),
        mass_fraction=df["wt_percent"].to_numpy(float) / 100.0,
        T_low=df["T_low_K"].to_numpy(float),
        T_high=df["T_high_K"].to_numpy(float),
        enthalpy=df["reaction_enthalpy_J_per_g_original"].fillna(0.0).to_numpy(float) * 1000.0,
        decay_constant=df["decay_constant_K"].to_numpy(float),
    )


def berkovich_conversion(T, T_low, decay_constant):
    r"""Conversion of a Table 9.1 reaction vs temperature (seed 000, after Berkovich 1999).

    .. math:: X(T) = 1 - \exp\!\left(-\frac{T - T_{lo}}{\tau}\right),\ T > T_{lo};\quad 0
              \text{ otherwise}

    The reaction starts at :math:`T_{lo}` and is 90 % complete at the top of its range when
    :math:`\tau = \Delta T/\ln 10`. Quasi-equilibrium: no time dependence.

    Parameters
    ----------
    T : float or array
        Temperature, K.
    T_low : float
        Start of the reaction range, K.
    decay_constant : float
        :math:`\tau`, K.

    Returns
    -------
    ndarray, -
        Conversion X in [0, 1).

    Examples
    --------
    >>> round(float(berkovich_conversion(793.0, 743.0, 21.71)), 3)   # kerogen, top of range
    0.9

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, Table 9.1
    (after Berkovich 1999).
    """
    check_positive("pyrolysis.decay_constant", decay_constant, "K")
    check_positive("T", T, "K")
    check_positive("T_low", T_low, "K")
    T = np.asarray(T, dtype=float)
    return np.where(T > T_low, 1.0 - np.exp(-(T - T_low) / decay_constant), 0.0)


def berkovich_reaction_enthalpy(T, table: ShaleTable | None = None):
    r"""Cumulative reaction enthalpy of the Table 9.1 shale at temperature T, J/kg shale.

    .. math:: H_r(T) = \sum_k \Delta H_k\, X_k(T)

    Parameters
    ----------
    T : float or array
        Shale temperature, K.
    table : ShaleTable, optional
        Defaults to :func:`oil_shale_table`.

    Returns
    -------
    ndarray
        J per kg of original shale; tends to 896.66 kJ/kg at high temperature.

    Examples
    --------
    >>> round(float(berkovich_reaction_enthalpy(3000.0)) / 1000, 2)
    896.66

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, Table 9.1
    (after Berkovich 1999).
    """
    t = table or oil_shale_table()
    check_positive("T", T, "K")
    T = np.asarray(T, dtype=float)
    h = np.zeros_like(T)
    for lo, tau, dh in zip(t.T_low, t.decay_constant, t.enthalpy, strict=True):
        if np.isfinite(lo) and dh != 0.0:
            h = h + dh * berkovich_conversion(T, lo, tau)
    return h


def kerogen_reaction_heat(table: ShaleTable | None = None) -> float:
    """Kerogen pyrolysis heat per kg of kerogen, J/kg (Table 9.1 row / kerogen fraction).

    Includes the clay reactions of the same temperature range (source note 1).

    Parameters
    ----------
    table : ShaleTable, optional
        Defaults to :func:`oil_shale_table`.

    Returns
    -------
    float, J/kg
        Per kg of kerogen.

    Examples
    --------
    >>> round(kerogen_reaction_heat() / 1000, 2)    # kJ/kg kerogen
    799.25

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, Table 9.1
    (after Berkovich 1999).
    """
    t = table or oil_shale_table()
    if "kerogen" not in t.material:
        raise InputError("oil_shale_table", "no kerogen row", "a table with a kerogen row")
    i = t.material.index("kerogen")
    return float(t.enthalpy[i] / t.mass_fraction[i])


def oil_shale_feed_composition(table: ShaleTable | None = None) -> dict[str, float]:
    """Bed-species mass fractions of the Table 9.1 shale (seed 000).

    Water -> ``H2O(l)``, kerogen -> ``kerogen``, calcite -> ``CaCO3``; the clays, quartz,
    pyrite, gypsum, siderite and dolomite are lumped as ``inert`` (their small reaction heats are
    not modelled as reactions; :func:`berkovich_reaction_enthalpy` has them all).

    Parameters
    ----------
    table : ShaleTable, optional
        Defaults to :func:`oil_shale_table`.

    Returns
    -------
    dict of str to float, -
        Mass fraction of each bed species (sums to 1).

    Examples
    --------
    >>> oil_shale_feed_composition()
    {'H2O(l)': 0.25, 'kerogen': 0.2, 'CaCO3': 0.06, 'inert': 0.49}

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, Table 9.1
    (after Berkovich 1999).
    """
    t = table or oil_shale_table()
    w = dict(zip(t.material, t.mass_fraction, strict=True))
    out = {
        "H2O(l)": float(w.get("water", 0.0)),
        "kerogen": float(w.get("kerogen", 0.0)),
        "CaCO3": float(w.get("calcite", 0.0)),
    }
    out["inert"] = round(1.0 - sum(out.values()), 12)
    return {k: round(v, 12) for k, v in out.items()}
