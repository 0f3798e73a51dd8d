r"""Coating (or lining) thickness along a kiln estimated from a shell scan.

The knots of a lining layer's ``thickness_profile`` are fields of the case; the scan (shell
temperatures at stations z, with the scanner's uncertainty) is fitted by the calibration
machinery (:func:`rotarykiln.studies.calibration.calibrate`, weighted least squares on the kiln
model's shell-temperature profile), which gives each knot's value and standard error. The
intervals are joint over the knots (Sidak: each at :math:`1 - (1 - p)^{1/m}` for m knots), so the
whole profile lies inside them with probability p when the model and the stated uncertainty
hold. Checked on synthetic scans: tests/validation/test_coating_estimate.py.

The estimate is as good as the coating's conductivity (the quantity it is most sensitive to)
and the model's inner temperatures; give the plant's conductivity.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["CoatingEstimate", "estimate_coating"]


@dataclass(frozen=True)
class CoatingEstimate:
    """Thickness of a lining layer at its profile's knots, from a shell scan.

    ``z`` (m) and ``thickness`` (m) of the fitted knots, ``low``/``high`` (m) their joint
    interval at ``level``, ``result`` the :class:`~rotarykiln.studies.calibration.CalibrationResult`
    (the calibrated case, residuals with the measured and computed shell temperatures).
    """

    z: np.ndarray
    thickness: np.ndarray
    low: np.ndarray
    high: np.ndarray
    level: float
    result: object

    def plot(self):
        """The scan against the computed shell temperatures (top) and the estimated thickness
        with its intervals (bottom); returns the Figure."""
        import matplotlib.pyplot as plt

        r = self.result.residuals
        s = r[r["quantity"] == "shell_temperature"].sort_values("z_m")
        fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(6.4, 5.6), sharex=True)
        ax1.errorbar(
            s["z_m"], s["value"], yerr=s["uncertainty"], fmt="o", ms=3, color="tab:blue",
            label="shell, measured",
        )  # fmt: skip
        ax1.plot(s["z_m"], s["model"], color="k", label="shell, computed (estimate)")
        ax1.set_ylabel("temperature (K)")
        ax1.legend(fontsize="small")
        mm = 1e3
        err = [mm * (self.thickness - self.low), mm * (self.high - self.thickness)]
        ax2.errorbar(self.z, mm * self.thickness, yerr=err, fmt="s-", capsize=4, color="tab:brown")
        ax2.set_ylabel(f"thickness (mm), {self.level:.0%} joint intervals")
        ax2.set_xlabel("z (m)")
        ax2.set_ylim(bottom=0.0)
        fig.tight_layout()
        return fig


def estimate_coating(
    case: dict,
    scan,
    *,
    layer: int = 0,
    knots=None,
    start: str = "50 mm",
    bounds: tuple[str, str] = ("0 mm", "500 mm"),
    level: float = 0.95,
) -> CoatingEstimate:
    r"""Estimate the thickness of a lining layer at the knots of its ``thickness_profile``.

    .. math:: \min_{\delta} \sum_i \left[\frac{T_{sh}(z_i;\delta) - T_i}{\sigma_i}\right]^2

    Parameters
    ----------
    case : dict
        The case (a mapping as in a YAML file) whose ``wall.lining[layer]`` has a
        ``thickness_profile`` (its values are the start where ``start`` is None).
    scan : DataFrame or path
        The shell scan: columns ``quantity`` (``shell_temperature``), ``z`` (m), ``value`` (K)
        and ``uncertainty`` (K, one standard deviation).
    layer : int
        Index of the layer in ``wall.lining``.
    knots : sequence of int, optional
        The profile points fitted (default: every point whose thickness is not 0 in ``case``).
    start : str
        Start thickness of every fitted knot (None: the case's).
    bounds : (str, str)
        Bounds of the thickness.
    level : float
        Joint probability of the intervals, dimensionless, in (0, 1).

    Returns
    -------
    CoatingEstimate
        z (m), thickness (m) and its joint interval (m) at each knot.

    Examples
    --------
    >>> import copy, warnings, yaml, numpy as np, pandas as pd
    >>> from rotarykiln.cases import builtin_case_path
    >>> case = yaml.safe_load(builtin_case_path("barr_T4").read_text())
    >>> case["solver"] = {"cells": 20}
    >>> coat = {"material": {"name": "coating", "k": [1.0]}, "thickness_profile":
    ...         [["0 m", "0 mm"], ["3 m", "60 mm"], ["4.5 m", "0 mm"]]}
    >>> case["wall"]["lining"].insert(0, coat)
    >>> from rotarykiln.studies.models import kiln_profile_model
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore")
    ...     out = kiln_profile_model(case)
    ...     z = [float(k.split("@")[1]) for k in out if k.startswith("shell_temperature@")]
    ...     t = [v for k, v in out.items() if k.startswith("shell_temperature@")]
    ...     scan = pd.DataFrame({"quantity": "shell_temperature", "z": z, "value": t,
    ...                          "uncertainty": 5.0})
    ...     est = estimate_coating(case, scan)
    >>> round(float(est.thickness[0]) * 1e3)
    60

    References
    ----------
    Cylindrical conduction through the lining in series (reference note on cement and lime
    kilns, section 6.3, the scanner's inverse principle); Z. Sidak, J. Am. Stat. Assoc. 62
    (1967) 626 (joint intervals).
    """
    from scipy.stats import norm

    from rotarykiln.errors import InputError
    from rotarykiln.studies.calibration import calibrate
    from rotarykiln.studies.models import kiln_profile_model
    from rotarykiln.units import to_si

    if not 0.0 < level < 1.0:
        raise InputError("level", level, "in (0, 1)")
    try:
        profile = case["wall"]["lining"][layer]["thickness_profile"]
    except (KeyError, IndexError, TypeError):
        raise InputError(
            f"wall.lining[{layer}].thickness_profile", None, "a layer with a thickness profile"
        ) from None
    if knots is None:
        knots = [i for i, (_, t) in enumerate(profile) if to_si("thickness", t, "length") > 0]
    if not knots:
        raise InputError("knots", knots, "at least one profile point to fit")
    base = f"wall.lining.{layer}.thickness_profile"
    params = [
        f"{base}.{i}.1={start if start is not None else profile[i][1]} [{bounds[0]}, {bounds[1]}]"
        for i in knots
    ]
    result = calibrate(kiln_profile_model, case, params, scan)
    scale = np.array([to_si("thickness", f"1 {p.unit}", "length") for p in result.params])
    si = np.asarray(result.x, dtype=float) * scale  # m
    half = norm.ppf(1.0 - (1.0 - level ** (1.0 / len(knots))) / 2.0) * result.stderr * scale
    z = np.array([to_si("z", profile[i][0], "length") for i in knots])
    return CoatingEstimate(z, si, np.maximum(si - half, 0.0), si + half, level, result)
