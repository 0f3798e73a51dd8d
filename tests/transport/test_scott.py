import warnings

import numpy as np
import pytest
from scipy.integrate import quad

from rotarykiln.errors import InputError, OutOfRangeWarning
from rotarykiln.transport.kramers import kramers_uniform_depth
from rotarykiln.transport.scott import (
    ScottParameters,
    scott_flow_integral,
    scott_friction_coefficient,
    scott_limiting_half_angle,
    scott_profile,
    scott_surface_slope,
)
from rotarykiln.transport.weirs import Weir

RPM = np.pi / 30
DRUM = dict(length=0.216, radius=0.0465, speed=38.5 * RPM, slope=0.0)
BALLOTINI = dict(density=1780, dynamic_angle=np.radians(28), static_angle=np.radians(24.5))


@pytest.mark.parametrize("b", [0.0, 0.01, 0.03, 0.045])
def test_flow_integral_against_adaptive_quadrature(b):
    omega, a, mu, r_up = 4.03, np.radians(28), 0.13, 0.0465
    k = np.sin(a) - mu * np.cos(a)

    def f(r):
        th = np.arccos(b / r)
        tc = np.sqrt(2 * 2 * np.sqrt(r * r - b * b) / (9.81 * k))
        return r * r * th * np.sin(th) / (2 * th + omega * tc)

    ref = quad(f, b, r_up, epsabs=1e-16, limit=200)[0]
    assert scott_flow_integral(b, r_up, omega, a, mu) == pytest.approx(ref, rel=1e-8)


def test_no_cascade_time_limit_is_kramers_uniform_depth():
    # with t_c = 0 (and B = 1) the limiting filling is Saeman/Kramers' uniform depth exactly
    a, psi, omega, q, radius = np.radians(35), np.radians(2), 0.5, 2e-5, 0.2
    p = ScottParameters(omega, a, a, psi, 0.1, cascade="none")
    th = scott_limiting_half_angle(q, radius, p)
    h = radius * (1 - np.cos(th))
    assert h == pytest.approx(kramers_uniform_depth(q, radius, omega, psi, a), rel=1e-9)


def test_small_beta_limit_is_saeman():
    # tan(beta) ~ q/(Y I) - C for small beta (notes 001, 3.1)
    p = ScottParameters(4.0, np.radians(30), np.radians(28), 0.0, 0.1, cascade="none")
    theta, radius, q = np.radians(70), 0.05, 1e-7
    tb = scott_surface_slope(theta, q, radius, p)
    s3 = (radius * np.sin(theta)) ** 3
    assert tb == pytest.approx(q / (4 * 4.0 / np.tan(np.radians(30)) * s3 / 6), rel=1e-3)


def test_friction_laws():
    a, s = np.radians(28), np.radians(24.5)
    assert scott_friction_coefficient("zero", a, s) == 0.0
    assert scott_friction_coefficient("dynamic", a, s) == pytest.approx(np.tan(a) / 3.5)
    assert scott_friction_coefficient(0.3, a, s) == 0.3
    with pytest.raises(InputError):
        scott_friction_coefficient("bogus", a, s)
    with pytest.raises(InputError, match="friction"):
        scott_profile(0.003, friction="coulomb", **DRUM, **BALLOTINI)


def test_open_drum_more_friction_more_fill():
    fills = [
        scott_profile(0.003, friction=f, **DRUM, **BALLOTINI).mean_fill
        for f in ("zero", "static", "dynamic")
    ]
    assert fills[0] < fills[1] < fills[2]


def test_inclined_open_drum_reaches_limiting_fill():
    p = scott_profile(0.003, **dict(DRUM, length=3.0, slope=np.radians(2)), **BALLOTINI)
    assert p.region[0] == 1 and p.region[-1] == 0
    assert p.depth[0] == pytest.approx(p.limiting_depth, rel=1e-6)


def test_pool_behind_dam_length():
    # inclined drum, dam higher than the limiting depth: horizontal pool of (H_d - H_lim)/tan psi
    psi = np.radians(2)
    p = scott_profile(
        0.001, discharge_radius=0.037, **dict(DRUM, length=0.5, slope=psi), **BALLOTINI
    )
    pool = p.z[p.region == 2]
    h_d = p.depth[-1]
    expected = (h_d - p.limiting_depth) / np.tan(psi)
    assert p.length - pool.min() == pytest.approx(expected, rel=0.02)


def test_weir_restarts_only_when_higher():
    base = scott_profile(0.003, **dict(DRUM, length=0.5), **BALLOTINI)
    low = scott_profile(0.003, weirs=[Weir(0.25, 0.0465)], **dict(DRUM, length=0.5), **BALLOTINI)
    assert low.mean_fill == pytest.approx(base.mean_fill, rel=1e-3)
    high = scott_profile(0.003, weirs=[Weir(0.25, 0.02)], **dict(DRUM, length=0.5), **BALLOTINI)
    assert high.mean_fill > base.mean_fill
    assert len(high.section_fills) == 2 and high.section_fills[1][2] > high.section_fills[0][2]


def test_bad_inputs():
    with pytest.raises(InputError, match="dam"):
        scott_profile(0.003, discharge_radius=0.0, **DRUM, **BALLOTINI)
    with pytest.raises(InputError, match="slope"):
        scott_profile(0.003, **dict(DRUM, slope=np.radians(30)), **BALLOTINI)
    with pytest.raises(InputError, match="no steady solution"):
        scott_profile(0.5, discharge_radius=0.01, **DRUM, **BALLOTINI)
    with pytest.raises(InputError, match="weir"):
        scott_profile(0.003, weirs=[Weir(0.3, 0.02)], **DRUM, **BALLOTINI)


def test_warnings():
    with pytest.warns(OutOfRangeWarning, match="critical"):
        scott_profile(0.003, **dict(DRUM, speed=80 * RPM), **BALLOTINI)
    with pytest.warns(OutOfRangeWarning, match="50 %"):
        scott_profile(0.02, discharge_radius=0.03, **dict(DRUM, length=1.0), **BALLOTINI)


def test_holdup_and_residence_time_consistent():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        p = scott_profile(0.00337, discharge_radius=0.0262, **DRUM, **BALLOTINI)
    assert p.holdup_mass == pytest.approx(p.mean_fill * 1780 * np.pi * 0.0465**2 * 0.216)
    assert p.mean_residence_time == pytest.approx(p.holdup_mass / 0.00337)
    # t(z) integrates the same areas on the output grid
    assert p.residence_time[-1] == pytest.approx(p.mean_residence_time, rel=2e-3)
    assert p.to_frame().shape[0] == p.z.size
