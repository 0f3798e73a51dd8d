"""Unit tests of the active-layer, mixing and segregation functions (bad input, limits)."""

import warnings

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from rotarykiln.errors import InputError, OutOfRangeWarning
from rotarykiln.transverse.active_layer import (
    active_layer,
    vanpuyvelde_active_layer_velocity,
    vanpuyvelde_centre_of_rotation,
)
from rotarykiln.transverse.mixing import (
    contact_distance,
    material_ratio,
    vanpuyvelde_final_contact,
    vanpuyvelde_mixing,
    vanpuyvelde_mixing_rate,
)
from rotarykiln.transverse.segregation import (
    vanpuyvelde_concentration_proportion,
    vanpuyvelde_layer_mean_sizes,
)

RPM = 2 * np.pi / 60


@pytest.mark.parametrize("ratio", [0.0, -1.0, np.nan])
def test_material_ratio_must_be_positive(ratio):
    with pytest.raises(InputError, match="material_ratio"):
        material_ratio(ratio)


def test_ratio_is_folded():
    a = vanpuyvelde_mixing_rate(0.8, 0.01, 2e-3, 0.5)
    b = vanpuyvelde_mixing_rate(0.8, 0.01, 2e-3, 2.0)
    assert a == pytest.approx(b)


def test_size_beyond_limit_clamps_and_warns():
    with pytest.warns(OutOfRangeWarning, match="limiting"):
        a = vanpuyvelde_mixing_rate(0.8, 0.01, 8e-3, 1.0)
    assert a == 0.0
    with pytest.warns(OutOfRangeWarning, match="limiting"):
        assert vanpuyvelde_final_contact(0.05, 2e-3, 5.0) == 0.0


def test_eq53_convention_is_half():
    v1 = vanpuyvelde_active_layer_velocity(1.0, 0.3, 0.25)
    v2 = vanpuyvelde_active_layer_velocity(1.0, 0.3, 0.25, convention="eq5.3")
    assert v2 == pytest.approx(0.5 * v1)
    with pytest.raises(InputError):
        vanpuyvelde_active_layer_velocity(1.0, 0.3, 0.25, convention="other")


def test_mixing_wrapper_warns_outside_fit_range():
    with pytest.warns(OutOfRangeWarning, match="drum speed"):
        vanpuyvelde_mixing(0.285, 25 * RPM, 0.25, 2.51e-3, 1.0)


def test_active_layer_frame_and_plot():
    import matplotlib

    matplotlib.use("Agg")
    al = active_layer(0.285, np.array([5, 10]) * RPM, 0.25)
    df = al.to_frame()
    assert len(df) == 2
    assert np.allclose(df.active_area_m2 + df.stagnant_area_m2, df.bed_area_m2)
    assert al.plot() is not None


def test_centre_of_rotation_below_chord():
    xo, yo = vanpuyvelde_centre_of_rotation((0.0, 0.0), (0.5, 0.1), 0.25, np.radians(12))
    assert yo < 0.1 * xo / 0.5  # below the line A-B


@given(st.floats(0.0, 1.2), st.floats(1.0, 6.0), st.sampled_from(["backfit", "printed"]))
def test_proportions_bounded(v, psr, coefficients):
    p_in, p_out = vanpuyvelde_concentration_proportion(
        psr, v, warn=False, coefficients=coefficients
    )
    assert p_in >= 1.0 and p_out <= 1.0
    # bounded by the upper limit of i_in and the lower limit of i_out (2.29 / 0.53 printed)
    assert p_in <= 2.295 and p_out >= 0.5282


def test_unknown_coefficient_set_is_rejected():
    with pytest.raises(InputError, match="coefficients"):
        vanpuyvelde_concentration_proportion(2.0, 0.5, coefficients="table")


def test_segregation_vanishes_at_high_velocity():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        p_in, p_out = vanpuyvelde_concentration_proportion(2.0, 1.6)
    assert p_in == 1.0 and p_out == 1.0


def test_layer_sizes_conserve_feed():
    r = vanpuyvelde_layer_mean_sizes([0.5e-3, 1e-3, 2e-3, 4e-3], [0.2, 0.3, 0.3, 0.2], 0.4)
    feed = 0.25 * r.inner_fractions + 0.75 * r.outer_fractions
    assert np.allclose(feed, r.feed_fractions)
    assert r.inner_mean < r.outer_mean
    assert len(r.to_frame()) == 4


def test_contact_distance_caps():
    t = np.linspace(0, 100, 11)
    l = contact_distance(t, 1.0, 30.0)
    assert l.max() == 30.0 and np.all(np.diff(l) >= 0)
