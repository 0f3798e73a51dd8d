import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rotarykiln.errors import InputError, OutOfRangeWarning
from rotarykiln.transport.kramers import (
    kramers_max_uniform_flow,
    kramers_profile,
    kramers_uniform_depth,
)

RPM = np.pi / 30
BASE = dict(radius=0.2, speed=3 * RPM, slope=np.radians(1), repose=np.radians(35))


def _rhs(h, q, radius, speed, slope, repose):
    """dh/dx of the Kramers equation, written independently from the module."""
    n = speed / (2 * np.pi)
    hr = h / radius
    return 3 * q * np.tan(repose) / (4 * np.pi * n * radius**3) * (hr * (2 - hr)) ** -1.5 - np.tan(
        slope
    ) / np.cos(repose)


def test_uniform_depth_zero_slope_of_ode():
    q = 1e-5
    h = kramers_uniform_depth(q, **BASE)
    assert _rhs(h, q, **BASE) == pytest.approx(0.0, abs=1e-12)


@settings(max_examples=40, deadline=None)
@given(
    frac=st.floats(0.01, 0.99),
    radius=st.floats(0.05, 2.0),
    rpm=st.floats(0.5, 10.0),
    slope=st.floats(0.2, 5.0),
    repose=st.floats(25.0, 50.0),
)
def test_uniform_depth_property(frac, radius, rpm, slope, repose):
    args = dict(radius=radius, speed=rpm * RPM, slope=np.radians(slope), repose=np.radians(repose))
    q = frac * kramers_max_uniform_flow(**args)
    h = kramers_uniform_depth(q, **args)
    assert 0 < h <= radius
    assert _rhs(h, q, **args) == pytest.approx(0.0, abs=1e-8 * np.tan(np.radians(slope)))


def test_uniform_depth_vectorised():
    q = np.linspace(1e-6, 4e-5, 100_000)
    h = kramers_uniform_depth(q, **BASE)
    assert h.shape == q.shape and np.all(np.diff(h) > 0)


def test_profile_tends_to_uniform_depth_far_from_discharge():
    q = 1e-5
    p = kramers_profile(q, length=40.0, n_points=2001, **BASE)
    h_inf = kramers_uniform_depth(q, **BASE)
    assert p.depth[0] == pytest.approx(h_inf, rel=1e-6)
    assert p.limiting_depth == pytest.approx(h_inf)
    assert p.depth[-1] == pytest.approx(0.0, abs=1e-12)  # open discharge (Saeman)
    assert np.all(np.diff(p.depth) <= 1e-15)  # depth falls towards the open end


def test_profile_satisfies_ode():
    q = 1e-5
    p = kramers_profile(q, length=2.0, n_points=4001, **BASE)
    x = p.length - p.z
    dhdx = -np.gradient(p.depth, p.z)
    mid = (x > 0.2) & (x < 1.8)
    np.testing.assert_allclose(dhdx[mid], _rhs(p.depth[mid], q, **BASE), rtol=2e-3)


def test_dam_higher_than_uniform_depth_decreases_upstream():
    p = kramers_profile(1e-5, length=60.0, dam_height=0.1, **BASE)
    assert p.depth[-1] == pytest.approx(0.1)
    assert np.all(np.diff(p.depth) >= 0)  # rising towards the dam
    assert p.depth[0] == pytest.approx(kramers_uniform_depth(1e-5, **BASE), rel=1e-4)


def test_variable_properties_constant_matches_fast_path():
    a = kramers_profile(1e-5, length=2.0, dam_height=0.05, **BASE)
    args = dict(BASE, radius=lambda z: 0.2 + 0 * z)
    b = kramers_profile(1e-5, length=2.0, dam_height=0.05, **args)
    np.testing.assert_allclose(a.depth, b.depth, rtol=1e-5, atol=1e-7)
    assert a.mean_fill == pytest.approx(b.mean_fill, rel=1e-5)


def test_variable_feed_table_and_residence_time():
    z = np.array([0.0, 2.0])
    p = kramers_profile((z, np.array([1.2e-5, 0.8e-5])), length=2.0, **BASE)
    # t(z) = int A/q dz; mean residence time is its end value; hold-up = int A dz
    integrand = p.bed_area / np.interp(p.z, z, [1.2e-5, 0.8e-5])
    assert p.mean_residence_time == pytest.approx(np.trapezoid(integrand, p.z), rel=1e-9)
    assert p.holdup_volume == pytest.approx(np.trapezoid(p.bed_area, p.z), rel=1e-9)
    assert np.all(np.diff(p.residence_time) > 0)


def test_mass_feed_and_holdup_mass():
    p = kramers_profile(62 / 3600, density=1500, length=2.0, **BASE)
    assert p.holdup_mass == pytest.approx(p.holdup_volume * 1500)
    assert p.mean_residence_time == pytest.approx(p.holdup_mass / (62 / 3600), rel=1e-3)


def test_bad_inputs():
    with pytest.raises(InputError, match="dam"):
        kramers_profile(1e-5, length=2.0, dam_height=0.2, **BASE)
    with pytest.raises(InputError, match="slope"):
        kramers_profile(1e-5, length=2.0, **dict(BASE, slope=np.radians(40)))
    with pytest.raises(InputError, match="no steady solution"):
        kramers_profile(1e-3, length=2.0, **dict(BASE, slope=0.0))
    with pytest.raises(InputError, match="no steady solution"):
        kramers_uniform_depth(1e-3, **BASE)
    with pytest.raises(InputError, match="no steady solution"):
        kramers_profile(1e-3, length=2.0, **dict(BASE, radius=lambda z: 0.2 + 0 * z))


def test_warnings():
    with pytest.warns(OutOfRangeWarning, match="critical"):
        kramers_profile(1e-5, length=2.0, **dict(BASE, speed=40 * RPM))
    with pytest.warns(OutOfRangeWarning, match="50 %"):
        kramers_profile(3e-5, length=2.0, dam_height=0.19, **dict(BASE, slope=0.0))


def test_frame_and_plot():
    import matplotlib

    matplotlib.use("Agg")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        p = kramers_profile(1e-5, length=2.0, dam_height=0.05, n_points=50, **BASE)
    df = p.to_frame()
    assert list(df.columns)[:3] == ["z_m", "x_from_discharge_m", "depth_m"]
    assert len(df) == 50
    ax = p.plot().axes[0]
    assert ax.get_xlabel().startswith("distance")
