r"""Back-fit of the Table 7.3 segregation coefficients to the thesis's own predictions.

Table 7.3 prints its twelve numbers (four lines slope·PSR + intercept and their clamps) to two
decimals. Evaluated with them, eq 7.3 falls about 0.015 (inner) and 0.005 (outer) below the
*predicted* P_in, P_out that the thesis prints in Table 7.2 for the same runs. This module fits
the twelve numbers to that predicted column by least squares, the way the notes back-fit the
limiting constants of the mixing model: it reproduces the thesis's model and never looks at the
measured proportions. Each number is kept within the half unit (0.005) of its printed value:
the fit looks for the unrounded coefficients that round to Table 7.3. V_AL is recomputed from
the drum speed and the series loading (eqs 5.2 and 5.6 on the 570 mm drum), i.e. unrounded as the
thesis computed it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd
from scipy.optimize import least_squares

from rotarykiln.errors import ConvergenceError, InputError
from rotarykiln.transverse.active_layer import (
    vanpuyvelde_active_layer_proportion,
    vanpuyvelde_active_layer_velocity,
)
from rotarykiln.transverse.segregation import COEFFICIENT_SETS, vanpuyvelde_concentration_proportion

__all__ = ["backfit_segregation_coefficients", "segregation_run_velocity"]

_KEYS = (("inner", "m"), ("inner", "i"), ("outer", "m"), ("outer", "i"))
# free parameters: (key, index in (lower, slope, intercept, upper)); the four bounds that do not
# act on the data (m_in <= 0, i_in >= 1, m_out >= 0, i_out <= 1) stay at their physical values
_FREE = (
    (("inner", "m"), 0),
    (("inner", "m"), 1),
    (("inner", "m"), 2),
    (("inner", "i"), 1),
    (("inner", "i"), 2),
    (("inner", "i"), 3),
    (("outer", "m"), 1),
    (("outer", "m"), 2),
    (("outer", "m"), 3),
    (("outer", "i"), 0),
    (("outer", "i"), 1),
    (("outer", "i"), 2),
)
_DRUM_RADIUS = 0.285  # m, the 570 mm drum of all segregation runs


def segregation_run_velocity(speed_rpm, fill):
    r"""Unrounded V_AL of a segregation run from its speed and loading (eqs 5.2, 5.6; 570 mm).

    .. math:: V_{AL} = \omega R\,(1 - X_{AL})/X_{AL}

    Parameters
    ----------
    speed_rpm : float or array, rpm
        Drum speed (as tabulated).
    fill : float or array, -
        Fractional loading.

    Returns
    -------
    float or array, m/s

    Examples
    --------
    Run 30a (2.90 rpm, loading 15.3 %; Table 7.2 prints 0.36 m/s):

    >>> round(float(segregation_run_velocity(2.90, 0.1531)), 3)
    0.356

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, eqs 5.2, 5.6.
    """
    w = np.asarray(speed_rpm, dtype=float) * 2 * np.pi / 60
    x = vanpuyvelde_active_layer_proportion(w, fill)
    return vanpuyvelde_active_layer_velocity(w, _DRUM_RADIUS, x)


def _unpack(q):
    table = {k: list(v) for k, v in COEFFICIENT_SETS["printed"].items()}
    for (key, j), val in zip(_FREE, q, strict=True):
        table[key][j] = float(val)
    return {k: tuple(v) for k, v in table.items()}


def backfit_segregation_coefficients(
    runs: pd.DataFrame, *, decimals: int = 4, half_unit: float = 0.005
) -> dict:
    r"""Fit the Table 7.3 numbers to the thesis's predicted proportions of Table 7.2.

    Minimises :math:`\sum (P_{in} - P_{in,pred})^2 + (P_{out} - P_{out,pred})^2` over the runs,
    with eq 7.3 evaluated at the unrounded V_AL of each run, each of the twelve numbers that act
    on the data bounded to the printed value :math:`\pm` ``half_unit``.

    Parameters
    ----------
    runs : DataFrame
        Columns ``psr``, ``speed_rpm``, ``fill_fitted_percent``, ``p_in_pred``, ``p_out_pred``
        (the shipped table ``segregation_experiments``).
    decimals : int
        Rounding of the returned numbers.
    half_unit : float
        Bound on the change of each printed number (0.005: they round to the print).

    Returns
    -------
    dict
        ``(layer, "m"|"i") -> (lower, slope, intercept, upper)``, usable as ``coefficients=``.

    Raises
    ------
    ConvergenceError
        When the least-squares fit does not converge.

    Examples
    --------
    >>> from rotarykiln.transverse.data import load_table
    >>> c = backfit_segregation_coefficients(load_table("segregation_experiments"))
    >>> c[("inner", "i")]
    (1.0, 0.6146, 0.3718, 2.295)

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, Table 7.3.
    """
    need = {"psr", "speed_rpm", "fill_fitted_percent", "p_in_pred", "p_out_pred"}
    if not need <= set(runs.columns):
        raise InputError("runs", sorted(runs.columns), f"a table with columns {sorted(need)}")
    psr = runs.psr.to_numpy(float)
    v = segregation_run_velocity(runs.speed_rpm.to_numpy(float), runs.fill_fitted_percent / 100)
    target = np.concatenate([runs.p_in_pred.to_numpy(float), runs.p_out_pred.to_numpy(float)])

    def residual(q):
        p_in, p_out = vanpuyvelde_concentration_proportion(
            psr, v, warn=False, coefficients=_unpack(q)
        )
        return np.concatenate([p_in, p_out]) - target

    q0 = np.array([COEFFICIENT_SETS["printed"][k][j] for k, j in _FREE])
    fit = least_squares(
        residual,
        q0,
        bounds=(q0 - half_unit, q0 + half_unit),
        x_scale=0.01,
        xtol=1e-12,
        ftol=1e-12,
    )
    if not fit.success:
        raise ConvergenceError(
            f"segregation back-fit did not converge: {fit.message}",
            iterations=fit.nfev,
            residual=float(np.sqrt(np.mean(fit.fun**2))),
            location="Table 7.2 predicted proportions",
        )
    return {k: tuple(round(c, decimals) for c in v) for k, v in _unpack(fit.x).items()}
