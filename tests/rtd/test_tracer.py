import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rotarykiln.errors import InputError
from rotarykiln.rtd.dispersion import open_open_exit_age
from rotarykiln.rtd.tracer import (
    TruncatedCurveWarning,
    analyse_tracer,
    read_tracer_csv,
    replicate_statistics,
)

T = np.arange(0.0, 81.0) * 60.0  # 30 s... here 60 s steps over 80 min
E = open_open_exit_age(T, 40 * 60.0, 300.0)


def test_moments_of_a_sampled_model_curve():
    res = analyse_tracer(T, 1e4 * E)  # any scale: E is normalised
    assert res.mean == pytest.approx(40 * 60 * (1 + 2 / 300), rel=1e-6)
    assert res.variance == pytest.approx((40 * 60) ** 2 * (2 / 300 + 8 / 300**2), rel=1e-3)
    assert np.trapezoid(res.exit_age, res.t) == pytest.approx(1.0)
    assert res.cumulative[-1] == pytest.approx(1.0)
    assert np.all(np.diff(res.cumulative) >= 0)
    assert res.sigma_theta2 == pytest.approx(res.variance / res.mean**2)
    assert np.trapezoid(res.exit_age_theta, res.theta) == pytest.approx(1.0)
    assert res.unaccounted_fraction == 0.0


def test_rectangle_weights_equal_trapezoid_for_constant_steps():
    a = analyse_tracer(T, E)
    b = analyse_tracer(T, E, weights="rectangle")
    assert a.mean == pytest.approx(b.mean, rel=1e-12)
    assert a.variance == pytest.approx(b.variance, rel=1e-9)


def test_variable_steps_give_the_same_moments():
    t = np.concatenate([np.arange(0, 30, 5.0), np.arange(30, 50, 0.25), np.arange(50, 81, 2.0)])
    res = analyse_tracer(t * 60, open_open_exit_age(t * 60, 2400.0, 300.0))
    assert res.mean == pytest.approx(2400 * (1 + 2 / 300), rel=1e-4)


def test_baseline_and_calibration():
    raw = 5.0 + 2.0 * E / E.max()
    res = analyse_tracer(T, raw, kind="conductivity", baseline=5.0, calibration=(3.0, 0.0))
    ref = analyse_tracer(T, E)
    assert res.mean == pytest.approx(ref.mean)
    auto = analyse_tracer(T, raw, baseline="auto")
    assert auto.mean == pytest.approx(ref.mean)


def test_tracer_mass_windows_and_recovery():
    mass = E * 60.0 * 0.012  # kg of tracer per 60 s window, 12 g injected
    res = analyse_tracer(T, mass, kind="tracer_mass", injected_mass=0.012)
    assert res.recovery == pytest.approx(1.0, rel=1e-3)


@pytest.mark.parametrize(
    ("t", "c", "match"),
    [
        (T, -E, "signal: .* is not >= 0"),
        (T[::-1], E, "t: .* is not strictly increasing"),
        (np.r_[T[:5], T[4], T[6:]], E, "strictly increasing"),
        (T, 0 * E, "zero everywhere"),
        (T, np.where(T == 600, np.nan, E), "finite"),
        (T[:2], E[:2], "at least 3"),
    ],
)
def test_bad_tracer_input(t, c, match):
    with pytest.raises(InputError, match=match):
        analyse_tracer(t, c)


def test_cut_tail_warns_with_the_fraction_unaccounted():
    # the exponential extrapolation of the last samples errs on the safe side for bell-shaped
    # tails (which decay faster than exponentially): between 1 and 1.5 times the truth
    full = analyse_tracer(T, E)
    for minutes in (46, 48):
        cut = T <= minutes * 60
        with pytest.warns(TruncatedCurveWarning, match=r"about \d+\.\d % of the tracer"):
            res = analyse_tracer(T[cut], E[cut])
        true_missing = 1 - full.cumulative[cut][-1]
        assert true_missing <= res.unaccounted_fraction <= 1.5 * true_missing


def test_complete_curve_does_not_warn():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        analyse_tracer(T, E)


@settings(max_examples=25, deadline=None)
@given(scale=st.floats(1e-6, 1e6), shift=st.floats(0, 3600))
def test_moments_are_scale_invariant_and_shift_equivariant(scale, shift):
    a = analyse_tracer(T, E)
    b = analyse_tracer(T + shift, scale * E)
    assert b.mean == pytest.approx(a.mean + shift, rel=1e-9)
    assert b.variance == pytest.approx(a.variance, rel=1e-6)


def test_replicate_statistics_uses_the_sample_sd():
    s = replicate_statistics([1.0, 2.0, 3.0])
    assert (s.mean, s.std, s.n) == (2.0, 1.0, 3)
    assert s.cv == pytest.approx(0.5)
    with pytest.raises(InputError, match="at least 2"):
        replicate_statistics([1.0])


def test_read_csv_with_units(tmp_path):
    p = tmp_path / "c.csv"
    p.write_text("time [min],C (uS/cm)\n0,0\n0.5,1\n1,0\n")
    t, c, name = read_tracer_csv(p)
    assert t.tolist() == [0.0, 30.0, 60.0] and c.tolist() == [0, 1, 0] and name == "C (uS/cm)"


@pytest.mark.parametrize(
    ("text", "match"),
    [
        ("time,C\n0,0\n1,1\n", "has no unit"),
        ("time [min],C\n0,0\n1,x\n", "line 3"),
        ("time [kg],C\n0,0\n1,1\n", "expected a time"),
        ("time [min]\n0\n1\n", "two columns"),
    ],
)
def test_read_csv_errors(tmp_path, text, match):
    p = tmp_path / "c.csv"
    p.write_text(text)
    with pytest.raises(InputError, match=match):
        read_tracer_csv(p)
    with pytest.raises(InputError, match="no such tracer file"):
        read_tracer_csv(tmp_path / "missing.csv")


# --------------------------------------------------------------------- issue 21: hardening


@pytest.mark.parametrize(
    ("text", "match"),
    [
        ("time [min],C\n0,0\n1,1e400\n2,0\n", r"line 3: signal inf is not a finite number"),
        ("time [min],C\n0,0\n1,1e300\n2,0\n", r"line 3: signal 1e\+300 is not a finite number"),
        ("time [min],C\n0,0\n1e300,1\n2,0\n", r"line 3: time 6e\+301 s is not a finite number"),
        ("time [min],C\n0,0\n1,nan\n", r"line 3: 1, nan is not two numbers"),
        ('time [min],C\n0,0\n1,"1\n2"\n', r"line 3: 1, '1\\n2' is not two numbers"),
        ('"time\n",C\n0,0\n1,1\n', r"the time column 'time\\n' has no unit"),
    ],
)
def test_tracer_values_are_finite_numbers_and_refusals_one_line(tmp_path, text, match):
    p = tmp_path / "c.csv"
    p.write_text(text)
    with pytest.raises(InputError, match=match) as e:
        read_tracer_csv(p)
    assert "\n" not in str(e.value)


def test_tracer_files_have_the_data_file_limits(tmp_path):
    # a 10-million-row file was read whole and its 746 MB table written
    p = tmp_path / "rows.csv"
    p.write_text("time [s],C\n" + "".join(f"{i},1\n" for i in range(100_001)))
    with pytest.raises(InputError, match="more than 100,000 rows"):
        read_tracer_csv(p)
    with p.open("wb") as fh:
        fh.truncate(25_000_000)
    with pytest.raises(InputError, match="too large for a tracer file"):
        read_tracer_csv(p)
    p.write_bytes("time [min],C\n0,0\n1,\xe9\n".encode("latin-1"))
    with pytest.raises(InputError, match=r"not UTF-8 text \(byte 0xe9 at line 3\)"):
        read_tracer_csv(p)
