import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rotarykiln.errors import InputError
from rotarykiln.rtd import dispersion as d
from rotarykiln.rtd.dispersion_pde import pulse_inlet, solve_dispersion_pde, step_inlet


def test_open_open_matches_seed_eq_14_written_out():
    # eq. 14 with tbar -> tau: E = 1/2 sqrt(Pe/(pi tau t)) exp(-Pe (tau - t)^2 / (4 tau t))
    t, tau, pe = np.array([2000.0, 2600.0, 3000.0]), 2600.0, 550.0
    eq14 = 0.5 * np.sqrt(pe / (np.pi * tau * t)) * np.exp(-pe * (tau - t) ** 2 / (4 * tau * t))
    assert d.open_open_exit_age(t, tau, pe) == pytest.approx(eq14, rel=1e-13)


@pytest.mark.parametrize("name", list(d.MODELS))
def test_models_are_zero_before_injection_and_vectorised(name):
    spec = d.MODELS[name]
    p = None if spec.shape is None else 50.0
    t = np.array([[-5.0, 0.0], [100.0, 1000.0]])
    e = spec.exit_age(t, 100.0, p)
    assert e.shape == t.shape and np.all(np.isfinite(e))
    if name != "gaussian":
        assert e[0, 0] == 0 and e[0, 1] == 0
    f = spec.cdf(t, 100.0, p)
    assert np.all((f >= 0) & (f <= 1))


@settings(max_examples=30, deadline=None)
@given(pe=st.floats(0.5, 5000.0), theta=st.floats(0.05, 5.0))
def test_cdfs_are_monotone(pe, theta):
    for name in ("open-open", "open-closed", "closed-closed"):
        spec = d.MODELS[name]
        f = spec.cdf(np.array([theta, theta * 1.01]), 1.0, pe)
        assert f[1] >= f[0] - 1e-10


def test_high_peclet_models_converge_to_each_other():
    t = np.linspace(0.9, 1.1, 41)
    oo = d.open_open_exit_age(t, 1.0 / (1 + 2 / 1e5), 1e5)
    cc = d.closed_closed_exit_age(t, 1.0, 1e5)
    assert np.max(np.abs(oo - cc)) < 0.02 * cc.max()


def test_peclet_and_dispersion_are_inverse():
    dd = d.dispersion_coefficient(550.0, 1.95, 2600.0)
    assert d.peclet_number(1.95 / 2600.0, 1.95, dd) == pytest.approx(550.0)


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: d.open_open_exit_age(1.0, -1.0, 10.0), "tau"),
        (lambda: d.open_open_exit_age(1.0, 1.0, 0.0), "peclet"),
        (lambda: d.tanks_in_series_exit_age(1.0, 1.0, -2), "n_tanks"),
        (lambda: d.open_open_exit_age([1.0, np.nan], 1.0, 10.0), "t"),
        (lambda: d.get_model("plug"), "one of open-open"),
        (lambda: d.closed_closed_exit_age(1.0, 1.0, 5.0, method="x"), "method"),
    ],
)
def test_bad_model_input(call, match):
    with pytest.raises(InputError, match=match):
        call()


def test_pde_step_response_is_the_cdf():
    res = solve_dispersion_pde(50.0, step_inlet(), 2.5, cells_per_length=400, n_out=251)
    exact = d.closed_closed_cdf(res.theta, 1.0, 50.0)
    assert np.max(np.abs(res.outlet - exact)) < 1e-3
    assert res.to_frame().shape == (251, 2)


def test_pde_rejects_a_coarse_grid_and_bad_boundaries():
    with pytest.raises(InputError, match="cells_per_length"):
        solve_dispersion_pde(1000.0, pulse_inlet(0.01), 2.0, cells_per_length=100)
    with pytest.raises(InputError, match="boundaries"):
        solve_dispersion_pde(10.0, pulse_inlet(0.01), 2.0, boundaries="open-closed")


# --------------------------------------------------------------------- issue 21: hardening


@pytest.mark.parametrize("name", [n for n, m in d.MODELS.items() if m.shape is not None])
@pytest.mark.parametrize("shape", [1e300, 1e-300, 0.0, float("nan"), float("inf")])
def test_shapes_outside_the_models_range_are_refused_in_one_line(name, shape):
    # were OverflowError / ZeroDivisionError (Pe = 1e300, 1e-300)
    spec = d.MODELS[name]
    for func in (
        lambda: spec.exit_age([1.0, 2.0], 1.0, shape),
        lambda: spec.cdf([1.0, 2.0], 1.0, shape),
        lambda: spec.moments(1.0, shape),
    ):
        with pytest.raises(InputError, match=rf"{spec.shape}: .* is not in \[1e-06, 1e\+10\]"):
            func()


@pytest.mark.parametrize("name", [n for n, m in d.MODELS.items() if m.shape is not None])
@pytest.mark.parametrize("shape", [d.SHAPE_RANGE[0], 1e-3, 50.0, 2e5, d.SHAPE_RANGE[1]])
def test_every_model_is_finite_across_its_whole_range(name, shape):
    spec = d.MODELS[name]
    mean, var = spec.moments(100.0, shape)
    t = np.linspace(max(mean - 6 * np.sqrt(var), 0.0), mean + 8 * np.sqrt(var), 300)
    e, f = spec.exit_age(t, 100.0, shape), spec.cdf(t, 100.0, shape)
    assert np.all(np.isfinite(e)) and np.all(e >= 0)
    assert np.all(np.isfinite(f)) and np.all((f >= 0) & (f <= 1))


@pytest.mark.parametrize(
    ("log_g", "a", "b"), [(d._log_g_closed_closed, 2.0, -3.0), (d._log_g_open_closed, 1.0, -2.0)]
)
def test_high_peclet_asymptotic_forms_match_the_laplace_inversion(log_g, a, b):
    # above ASYMPTOTIC_PECLET the boundary-corrected open-open form replaces the inversion
    # (whose nodes grow as sqrt(Pe)); their difference there is of order Pe^-3/2
    pe = d.ASYMPTOTIC_PECLET
    sd = np.sqrt(2 / pe)
    th = np.linspace(1 - 6 * sd, 1 + 8 * sd, 200)
    exact = d._invert(log_g(pe), th, pe)
    approx = d._boundary_corrected(th, pe, a, b)
    assert np.max(np.abs(approx - exact)) < 1e-6 * exact.max()
    exact_f = d._invert(log_g(pe), th, pe, cumulative=True)
    assert np.max(np.abs(d._boundary_corrected(th, pe, a, b, cumulative=True) - exact_f)) < 1e-6


def test_a_sharp_closed_closed_curve_at_many_times_is_evaluated_in_bounded_memory():
    # the 3.9e-11 deg repose angle case: Pe ~ 1.3e8 (was 28,454 Talbot nodes x every time,
    # 1.5 GB, then an overflow); now the asymptotic form, and a Laplace inversion is chunked
    import tracemalloc

    t = np.linspace(0.99, 1.01, 4000)
    tracemalloc.start()
    try:
        e = d.closed_closed_exit_age(t, 1.0, 1.3e8)
        e2 = d.open_closed_exit_age(t, 1.0, 9e4)  # Laplace: 750 nodes x 4000 times, 48 MB each
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert np.all(np.isfinite(e)) and np.all(np.isfinite(e2))
    assert np.trapezoid(e, t) == pytest.approx(1.0, rel=1e-6)
    assert peak < 60e6  # blocks of 200,000 (time, node) pairs
