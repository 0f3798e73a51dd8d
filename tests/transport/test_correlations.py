"""Closed-form checks of seed 002 (Boateng ch. 2) and the relations quoted by Scott (1986)."""

import numpy as np
import pytest

from rotarykiln.geometry import fill_from_depth
from rotarykiln.transport import correlations as c
from rotarykiln.transport import saeman as s

RPM = np.pi / 30


def test_fill_at_h_equal_r():
    assert fill_from_depth(1.0, 1.0) == pytest.approx(0.5)


def test_dimensionless_residence_time_limits():
    assert s.mctait_residence_time_dimensionless(1e-9) == pytest.approx(1 / np.pi, rel=1e-6)
    assert s.mctait_residence_time_dimensionless(1.0) == pytest.approx(0.5)


@pytest.mark.parametrize("y", [0.05, 0.2, 0.5, 0.8, 1.0])
def test_q_tau_over_l_as_is_one(y):
    # q * tau / (L * A_s) = 1 for eqs. 2.15/2.16 (A_s = D^2/4 (theta - sin cos))
    th = np.arcsin(np.sqrt((2 - y) * y))
    a_over_d2 = (th - np.sin(th) * np.cos(th)) / 4
    qd_td = s.mctait_flow_dimensionless(y) * s.mctait_residence_time_dimensionless(y)
    assert qd_td / a_over_d2 == pytest.approx(1.0, rel=1e-12)


def test_small_fill_limits_of_2_16_and_2_17_agree():
    y = 1e-6
    assert s.mctait_flow_dimensionless(y) == pytest.approx(
        s.mctait_uniform_flow_dimensionless(y), rel=1e-3
    )


@pytest.mark.parametrize(
    "y,tau_d,qd16,qd17",
    [
        (0.05, 0.3237, 0.01616, 0.01594),
        (0.2, 0.3414, 0.11973, 0.11310),
        (0.8, 0.4449, 0.65941, 0.49250),
    ],
)
def test_regenerated_design_table(y, tau_d, qd16, qd17):
    # notes 002 section 4, regenerated from the corrected equations (printed to 4-5 digits)
    assert s.mctait_residence_time_dimensionless(y) == pytest.approx(tau_d, abs=6e-5)
    assert s.mctait_flow_dimensionless(y) == pytest.approx(qd16, abs=6e-6)
    assert s.mctait_uniform_flow_dimensionless(y) == pytest.approx(qd17, abs=6e-6)


def test_saeman_shallow_limit_equals_mctait_limit():
    # eq. 2.10 with r = R is eq. 2.15 at zero depth: tau = L sin(xi)/(pi D n phi)
    args = (36.6, np.pi / 30, np.radians(3), np.radians(40))
    t_saeman = s.saeman_residence_time(args[0], 1.83, *args[1:])
    t_mctait = s.mctait_residence_time(36.6, 3.66, np.pi / 30, np.radians(3), np.radians(40), 1e-9)
    # Saeman uses phi in rad, McTait tan(phi): equal to (tan phi / phi) = 1.0009
    assert t_saeman / t_mctait == pytest.approx(np.tan(np.radians(3)) / np.radians(3), rel=1e-6)


def test_saeman_flow_is_velocity_integral():
    # q = int u(r) dA over the bed, dA = 2 r theta_r dr (Saeman eqs. 2.11-2.13)
    radius, r_o, w, phi, xi = 1.0, 0.6, 0.2, np.radians(3), np.radians(40)
    r = np.linspace(r_o, radius, 20001)[1:]
    u = s.saeman_axial_velocity(r, r_o, w, phi, 0.0, xi)
    q = np.trapezoid(u * 2 * r * np.arccos(r_o / r), r)
    assert q == pytest.approx(s.saeman_flow(radius, r_o, w, phi, 0.0, xi), rel=1e-4)


def test_critical_speed_rule():
    from rotarykiln.transport._common import critical_speed

    assert critical_speed(0.5) * 30 / np.pi == pytest.approx(42.3 / np.sqrt(1.0), rel=2e-3)


def test_gilbert_vs_sullivan_within_5_percent():
    # Scott: (2.1) with psi 2.29 deg and alpha 34 deg gives 4.49 L/(DN), within 5 % of 4.29
    args = (1.0, 1.0, RPM)
    t_s = c.sullivan_residence_time(*args, np.radians(2.29), np.radians(34))
    assert t_s / 60 == pytest.approx(4.49, abs=0.02)  # 1.77 sqrt(34)/2.29 = 4.507; printed 4.49
    assert c.gilbert_residence_time(*args) / 60 == pytest.approx(4.29, abs=0.01)


@pytest.mark.parametrize("alpha", [30, 35, 40, 45])
def test_bayard_within_2_percent_of_sullivan(alpha):
    # Scott: "within 2 % for alpha_d = 30-45 deg"; the end point 45 deg gives 2.3 %
    args = (10.0, 1.0, RPM, np.radians(2), np.radians(alpha))
    assert c.bayard_residence_time(*args) == pytest.approx(
        c.sullivan_residence_time(*args), rel=0.025
    )


def test_ginstling_about_2_5_times_sullivan():
    args = (10.0, 1.0, RPM, np.radians(2))
    ratio = c.ginstling_residence_time(*args) / c.sullivan_residence_time(*args, np.radians(35))
    assert 2.2 < ratio < 2.9


def test_perry_design_kiln_and_gas_term_sign():
    base = c.perry_residence_time(36.6, 3.66, RPM, np.radians(3))
    assert base / 60 == pytest.approx(43.89, abs=0.01)  # notes 002 section 4
    kw = dict(gas_mass_flux=1.0, feed_flux=2.0, particle_size=500e-6)
    counter = c.perry_residence_time(36.6, 3.66, RPM, np.radians(3), **kw)
    co = c.perry_residence_time(36.6, 3.66, RPM, np.radians(3), flow="co", **kw)
    assert co < base < counter
    assert counter - base == pytest.approx(base - co)


def test_hogg_mean_is_length_average_of_local():
    args = (2e-6, 0.0475, 6.6, np.radians(38))
    x = np.linspace(0, 0.248, 20001)
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        local = c.hogg_local_fill(args[0], x, *args[1:])
    mean = np.trapezoid(local, x) / 0.248
    assert c.hogg_mean_fill(args[0], 0.248, *args[1:]) == pytest.approx(mean, rel=2e-3)


def test_hogg_constricted_is_length_average():
    # eq. 2.35 = (1/L) int (f0^1.5625 + 0.812 q x / K')^0.64 dx (0.812 = 0.875^1.5625); the
    # printed exponents 2.56/1.56 are rounded, hence 1 %
    q, length, radius, w, a, f0 = 2e-6, 0.248, 0.0475, 6.6, np.radians(38), 0.1
    kp = 0.51 / np.tan(a) * w * radius**4
    x = np.linspace(0, length, 20001)
    ref = np.trapezoid((f0**1.5625 + 0.812 * q * x / kp) ** 0.64, x) / length
    got = c.hogg_constricted_mean_fill(q, length, radius, w, a, f0)
    assert got == pytest.approx(ref, rel=0.01)


def test_austin_flemmer_minimum_at_45_degrees():
    q, radius, w, a = 1e-5, 0.0475, 6.6, np.radians(38)
    fc = c.austin_flemmer_minimum_fill(q, radius, w, a)
    k = 2 / 3 * w * radius**3 / np.tan(a)
    # at that filling the flow at beta = 45 deg is exactly q
    from rotarykiln.geometry import half_angle_from_fill

    th = half_angle_from_fill(fc)
    assert k * np.sin(th) ** 3 * 0.5 == pytest.approx(q, rel=1e-9)


def test_weir_fill_at_zero_height_is_tangent_geometry():
    t = np.arccos(0.037 / 0.0465)
    assert c.abouzeid_fuerstenau_weir_fill(0.0, 0.037, 0.0465) == pytest.approx(
        (t - np.sin(t) * np.cos(t)) / np.pi
    )


def test_vectorised_1e5_points():
    n = 100_000
    rng = np.random.default_rng(1)
    L, D = rng.uniform(5, 50, n), rng.uniform(1, 4, n)
    t = c.sullivan_residence_time(L, D, RPM, np.radians(2), np.radians(35))
    assert t.shape == (n,) and np.all(np.isfinite(t))
