"""Scott (1986): the model reproduces the thesis's own model columns (Appendix 4, Table 5.1).

Tolerance 0.5 percentage points of filling (the issue's requirement). The thesis prints two
decimals; its step size and quadrature are not stated, and its zero-feed value for R_c = 0.0262
(16.37 %) implies R_c = 0.0260, i.e. a ~0.25 pp offset in the A4.7 upper curve. Rows whose
printed value is OCR-illegible or contradicted by the thesis itself are excluded by their
``status`` in the CSV (reasons in data/scott1986/README.md and docs/validation.md).
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from rotarykiln.transport.scaleup import abouzeid_psi, scott_psi
from rotarykiln.transport.scott1986 import scott1986_model_fill, scott1986_table

LEGIBLE = ("printed", "ocr_fixed")
TABLES = [f"a4_{k:02d}" for k in (1, 2, 3, 4, 5, 6, 7, 8, 10, 11, 12, 13, 14, 16)]

# Legible thesis values our model does not reach within the 0.5 pp of the issue, with the reason
# (documented in docs/validation.md): strict xfail at the same 0.5 pp, so that reaching them is
# noticed (a bound at today's deviation plus a margin would rest on nothing in the source).
KNOWN = {
    # Bachmann alpha_d at 53.5 and 66.9 % of critical speed (above the 50 % limit): alpha_d
    # rises to 65-73 deg; the thesis column is not reproduced (0.6 and 1.05 pp).
    ("A4.11", 4, "bachmann"): "Bachmann alpha_d above 50 % of critical speed (0.6 pp off)",
    ("A4.11", 5, "bachmann"): "Bachmann alpha_d above 50 % of critical speed (1.05 pp off)",
}


def _key(row):
    variant = row.get("model_variant", "scott")
    return (row["table"], int(row["row"]), variant if isinstance(variant, str) else "scott")


def _rows():
    for name in TABLES:
        df = scott1986_table(name)
        for _, row in df.iterrows():
            if row["status"] not in LEGIBLE or pd.isna(row["model_fill_pct"]):
                continue
            variant = row.get("model_variant", "scott")
            variant = variant if isinstance(variant, str) else "scott"
            curve = row.get("curve", row.get("group", ""))
            reason = KNOWN.get(_key(row))
            marks = [pytest.mark.xfail(strict=True, reason=reason)] if reason else []
            yield pytest.param(
                row, id=f"{row['table']}-{curve}-{row['row']}-{variant}", marks=marks
            )


@pytest.mark.parametrize("row", list(_rows()))
def test_thesis_model_column(row):
    # 0.5 percentage points of filling: the requirement (module docstring)
    assert scott1986_model_fill(row) == pytest.approx(row["model_fill_pct"], abs=0.5)


def test_check_value():
    # F 0.00337 kg/s, rho 1780, 28/24.5 deg, L 0.216, R 0.0465, R_c 0.0262, 38.5 rpm:
    # about 20.3 % (independent re-implementation, notes 001 App. Z), thesis 20.50 %.
    row = scott1986_table("a4_07").query("curve == 'upper' and row == 2").iloc[0]
    fill = scott1986_model_fill(row)
    assert fill == pytest.approx(20.3, abs=0.05)
    assert fill == pytest.approx(20.50, abs=0.25)


def test_zero_feed_is_geometric():
    # b = R_c at zero feed: fc = (t - sin t cos t)/pi with cos t = R_c/R_d = 5.37 % (A4.7 lower)
    row = scott1986_table("a4_07").query("curve == 'lower' and row == 1").iloc[0]
    t = np.arccos(0.037 / 0.0465)
    assert scott1986_model_fill(row) == pytest.approx(100 * (t - np.sin(t) * np.cos(t)) / np.pi)


@pytest.mark.parametrize("k", [0, 2])
def test_table_5_1_internal_weirs(k):
    # thesis prints one decimal; +-0.5 pp plus the 0.05 rounding of the printed value
    row = scott1986_table("table_5_1").iloc[k]
    inlet, discharge, overall = scott1986_model_fill(row, sections=True)
    assert overall == pytest.approx(row["model_overall_pct"], abs=0.55)
    assert inlet == pytest.approx(row["model_inlet_pct"], abs=0.55)
    assert discharge == pytest.approx(row["model_discharge_pct"], abs=0.55)


def test_table_5_1_row_2_inconsistent_in_thesis():
    # rows 2 and 3 share the discharge geometry and nearly the feed (5.00 vs 4.95 g/s), so the
    # discharge sections must agree; the thesis prints 17.9 vs 19.0. We follow row 3: row 2's
    # discharge section against row 3's printed one within the 0.5 pp of the issue plus the
    # 0.05 of the one-decimal print. Row 2's printed overall (24.5 %) is not asserted: the row
    # is inconsistent in the thesis, and no accuracy supports a bound on it.
    t = scott1986_table("table_5_1")
    d2 = scott1986_model_fill(t.iloc[1], sections=True)
    d3 = scott1986_model_fill(t.iloc[2], sections=True)
    assert d2[1] == pytest.approx(d3[1], abs=0.2)
    assert d2[1] == pytest.approx(t.iloc[2]["model_discharge_pct"], abs=0.55)


def _deviations(name, variant="scott", curve=None):
    df = scott1986_table(name)
    df = df[(df.model_variant == variant) & df.status.isin(LEGIBLE)]
    if curve is not None:
        df = df[df.curve == curve]
    ours = np.array([scott1986_model_fill(r) for _, r in df.iterrows()])
    exp = df.exp_fill_pct.to_numpy()
    thesis = df.model_fill_pct.to_numpy()
    return np.abs(ours - exp) / exp, np.abs(thesis - exp) / exp


@pytest.mark.parametrize(
    "name,variant,curve",
    [
        ("a4_04", "scott", None),
        ("a4_06", "scott", None),
        ("a4_07", "scott", "lower"),
        ("a4_07", "scott", "upper"),
        ("a4_08", "scott", None),
        ("a4_12", "scott", None),
        ("a4_13", "scott", None),
        ("a4_14", "scott", "K3"),
        ("a4_03", "mu0", None),
    ],
)
def test_deviation_from_measured_matches_thesis(name, variant, curve):
    # Match the thesis model's own deviations from the measurements, do not tune past them:
    # the mean relative deviation agrees with the thesis's within 2 % (points are on the same
    # rows; the 0.5 pp model tolerance is at most 2-10 % relative at fills of 5-25 %).
    ours, thesis = _deviations(name, variant, curve)
    assert np.mean(ours) == pytest.approx(np.mean(thesis), abs=0.02)
    assert np.max(ours) == pytest.approx(np.max(thesis), abs=0.05)


def test_psi_a4_15_literature():
    t = scott1986_table("a4_15")
    lit = t[t.curve == "literature"]
    psi = abouzeid_psi(
        lit.feed_kg_s / lit.density_kg_m3,
        lit.length_m,
        lit.diameter_m,
        lit.speed_rpm * np.pi / 30,
        np.radians(lit.alpha_d_deg),
    )
    # printed to 3 significant figures
    np.testing.assert_allclose(psi, lit.psi_printed, atol=1e-5)


def test_psi_a4_15_experimental_needs_d_0094():
    t = scott1986_table("a4_15")
    ex = t[t.curve == "experimental"]
    psi = abouzeid_psi(
        ex.feed_kg_s / ex.density_kg_m3,
        ex.length_m,
        ex.diameter_m,
        ex.speed_rpm * np.pi / 30,
        np.radians(ex.alpha_d_deg),
    )
    np.testing.assert_allclose(psi, ex.psi_printed, rtol=0.005)


def test_psi_a4_16():
    t = scott1986_table("a4_16")
    t = t[t.status != "illegible"]
    args = (
        t.feed_kg_s / t.density_kg_m3,
        t.length_m,
        2 * t.radius_m,
        t.speed_rpm * np.pi / 30,
        np.radians(t.alpha_d_deg),
    )
    # printed to 2 decimals (abs 0.006) or 3-4 significant figures; 215.00 (214.64) is the coarsest
    np.testing.assert_allclose(1000 * abouzeid_psi(*args), t.psi_a5_x1000, rtol=0.002, atol=0.006)
    np.testing.assert_allclose(1000 * scott_psi(*args), t.psi_scott_x1000, rtol=0.002, atol=0.006)


def test_a4_16_unreachable_rows_raise():
    from rotarykiln.errors import InputError

    t = scott1986_table("a4_16")
    for _, row in t[t.status == "unreachable"].iterrows():
        with pytest.raises(InputError, match="no steady solution"):
            scott1986_model_fill(row)
