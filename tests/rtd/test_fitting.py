import numpy as np
import pytest

from rotarykiln.errors import ConvergenceError, InputError
from rotarykiln.rtd.dispersion import open_open_exit_age
from rotarykiln.rtd.fitting import (
    fit_rtd,
    fit_tracer,
    moment_method,
    open_open_peclet_from_variance,
)
from rotarykiln.rtd.tracer import analyse_tracer

T = np.linspace(30, 62, 129) * 60.0


def test_closed_form_root_solves_eq_13():
    for s2 in (1e-4, 3.67e-3, 0.05, 1.0):
        pe = open_open_peclet_from_variance(s2)
        assert 2 / pe + 8 / pe**2 == pytest.approx(s2, rel=1e-12)


@pytest.mark.parametrize("model", ["open-open", "open-closed", "closed-closed", "tanks-in-series"])
def test_rigorous_moment_method_reproduces_both_moments(model):
    from rotarykiln.rtd.dispersion import MODELS

    r = moment_method(2600.0, 26000.0, model=model, convention="rigorous")
    mean, var = MODELS[model].moments(r.tau, r.shape)
    assert mean == pytest.approx(2600.0, rel=1e-9)
    assert var == pytest.approx(26000.0, rel=1e-9)


def test_paper_and_rigorous_conventions_differ_by_the_mean_shift():
    paper = moment_method(2600.0, 26000.0)
    rigorous = moment_method(2600.0, 26000.0, convention="rigorous")
    assert paper.tau == 2600.0
    assert rigorous.tau == pytest.approx(2600.0 / (1 + 2 / rigorous.peclet))
    assert abs(rigorous.peclet / paper.peclet - 1) < 0.02  # < 2 % for Pe > 100 (notes sec. 2.4)


def test_moment_method_errors():
    with pytest.raises(InputError, match="reachable"):
        moment_method(100.0, 5e4, model="closed-closed")  # sigma_theta^2 = 5 > 1
    with pytest.raises(InputError, match="shape parameter"):
        moment_method(100.0, 10.0, model="plug-flow")
    with pytest.raises(InputError, match="convention"):
        moment_method(100.0, 10.0, convention="x")


def test_fit_distinguishes_tau_and_means():
    e = open_open_exit_age(T, 2520.0, 120.0)
    fit = fit_rtd(T, e, length=1.95)
    assert fit.tau == pytest.approx(2520.0, rel=1e-6)
    assert fit.model_mean == pytest.approx(2520.0 * (1 + 2 / 120), rel=1e-6)
    assert fit.data_mean != pytest.approx(fit.tau, rel=1e-3)
    assert fit.dispersion == pytest.approx(1.95**2 / (120 * 2520.0), rel=1e-5)
    assert fit.ci_tau[0] <= fit.tau <= fit.ci_tau[1]
    assert fit.r_squared == pytest.approx(1.0)
    assert set(fit.summary()) >= {"tau_s", "peclet", "model_mean_s", "data_mean_s", "moment_method"}
    assert fit.to_frame().shape[0] == T.size


def test_fit_tracer_uses_the_tracer_curve():
    tr = analyse_tracer(T, 1e3 * open_open_exit_age(T, 2520.0, 550.0))
    assert fit_tracer(tr).peclet == pytest.approx(550.0, rel=1e-4)


def test_fit_that_does_not_converge_raises():
    e = open_open_exit_age(T, 2520.0, 550.0)
    with pytest.raises(ConvergenceError, match="open-open"):
        fit_rtd(T, e, guess=(1.0, 1e-3), max_nfev=3)


def test_fit_input_errors():
    with pytest.raises(InputError, match=">= 0"):
        fit_rtd(T, -open_open_exit_age(T, 2520.0, 550.0))
    with pytest.raises(InputError, match="zero"):
        fit_rtd(T, 0 * T)
    with pytest.raises(InputError, match="strictly increasing"):
        fit_rtd(T[::-1], T)
