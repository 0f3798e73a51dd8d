"""Active-layer proportion and velocity against Van Puyvelde (1999) Tables 6.2 and 7.2."""

import numpy as np
import pytest

from rotarykiln.transverse.active_layer import (
    active_layer,
    vanpuyvelde_active_layer_proportion,
    vanpuyvelde_active_layer_velocity,
)
from rotarykiln.transverse.data import load_table

RPM = 2 * np.pi / 60


def test_table_6_2_x_al_and_v_al():
    d = load_table("mixing_experiments")
    w = d.speed_rpm.to_numpy() * RPM
    fill = d.fill_percent.to_numpy() / 100
    radius = d.drum_diameter_mm.to_numpy() / 2000
    x = vanpuyvelde_active_layer_proportion(w, fill)
    v = vanpuyvelde_active_layer_velocity(w, radius, x)
    # X_AL is printed as a whole percent: 1 % of the bed is the resolution of the table.
    assert np.all(np.abs(100 * x - d.x_al_percent) <= 1.0)
    # V_AL within 1 % on average and for all rows but two; exps 2 (1.1 %) and 22 (1.05 %) exceed
    # it only because N (0.1 rpm) and L (1 %) are printed rounded: the printed value must then lie
    # inside the band spanned by the half-units of N and L.
    rel = np.abs(v * 1000 / d.v_al_mm_s - 1)
    assert rel.mean() < 0.005
    for k in np.flatnonzero(rel > 0.01):
        corners = []
        for dn in (-0.05, 0.05):
            for dl in (-0.005, 0.005):
                xx = vanpuyvelde_active_layer_proportion(w[k] + dn * RPM, fill[k] + dl)
                corners.append(
                    1000 * vanpuyvelde_active_layer_velocity(w[k] + dn * RPM, radius[k], xx)
                )
        assert min(corners) <= d.v_al_mm_s[k] <= max(corners), d.exp[k]
    assert (rel > 0.01).sum() <= 2


# Loadings of the segregation series are not printed; one loading per series, fitted to its
# X_AL and V_AL columns (the text confirms 15 % for series 30). The test below is therefore a
# provenance check of that reconstruction, not a validation of eqs 5.2/5.6.
SERIES_FILL = {
    "28": 0.1459,
    "29": 0.1483,
    "30": 0.1531,
    "31": 0.1998,
    "32": 0.1497,
    "33": 0.1444,
    "34": 0.2205,
    "35": 0.1474,
    "36": 0.1911,
}


def test_table_7_2_x_al_and_v_al():
    """Provenance of the reconstructed loadings (SERIES_FILL), not a validation: they were fitted
    to these X_AL and V_AL columns, one loading per series (1-10 speeds, two columns each); the
    check shows one loading reproduces every row of its series within the printing, and that
    series 30's is the 15 % the text states (printed as a whole percent: +-0.5 %)."""
    d = load_table("segregation_experiments")
    fill = np.array([SERIES_FILL[e[:2]] for e in d.exp])
    assert abs(SERIES_FILL["30"] - 0.15) < 0.005
    w = d.speed_rpm.to_numpy() * RPM
    x = vanpuyvelde_active_layer_proportion(w, fill)
    v = vanpuyvelde_active_layer_velocity(w, 0.285, x)
    assert np.all(np.abs(100 * x - d.x_al_percent) <= 1.0)
    # V_AL is printed to 0.01 m/s: within 1 % or within the half unit of printing (+0.001).
    tol = np.maximum(0.01 * d.v_al_m_s, 0.006)
    assert np.all(np.abs(v - d.v_al_m_s) <= tol)


def test_retort_base_case_velocity():
    """Provenance, not a validation: case 2 of Table 9.2 (6 m drum, 5 rpm) has no printed fill;
    the 30 % of the retort cases is reconstructed from the V_AL = 7.01 m/s the text gives
    (data/vanpuyvelde1999/README.md). A round 30 % reproduces it to the printed 0.01 m/s."""
    al = active_layer(3.0, 5 * RPM, 0.30)
    assert al.active_velocity == pytest.approx(7.01, abs=0.005)


def test_small_drum_deviations_are_within_table_5_1():
    """Provenance, not a validation: Table 5.1 gives only the % deviations of eq 5.2 on the
    200/400 mm drums, not their measured X_AL, so eq 5.2 cannot be scored on them here; the
    shipped table carries the 1.4-10.7 % the thesis states for the smaller drums."""
    dev = load_table("active_layer_deviation_small_drums")
    values = dev[["dev_200mm_percent", "dev_400mm_percent"]].to_numpy()
    assert (values.min(), values.max()) == (1.4, 10.7)
