import numpy as np
import pytest

from rotarykiln.errors import InputError
from rotarykiln.studies.design import (
    as_params,
    latin_hypercube,
    monte_carlo,
    parse_param,
    sobol_sequence,
)
from rotarykiln.studies.paths import with_values


def test_param_units_and_values():
    p = parse_param("operation.speed=uniform(1 rpm, 3 rpm)")
    assert p.value(2.5) == "2.5 rpm"
    q = parse_param("operation.feed=triangular(50 kg/h, 62 kg/h, 0.02 kg/s)")
    assert q.args == pytest.approx((50, 62, 72))
    t = parse_param("gas.temperature=normal(1000 degC, 20 K)")
    assert t.args == pytest.approx((1000, 20)) and t.unit == "degC"
    ln = parse_param("x=lognormal(2, 0.3)")
    assert ln.nominal == pytest.approx(2.0) and ln.value(2.0) == 2.0


@pytest.mark.parametrize(
    "text, match",
    [
        ("x=unifrom(1, 2)", "did you mean uniform"),
        ("x=uniform(2, 1)", "low < high"),
        ("x=normal(1, 0)", "sd > 0"),
        ("x=lognormal(-1, 0.2)", "median > 0"),
        ("x=triangular(1, 0, 2)", "low <= mode <= high"),
        ("x=uniform(1 rpm, 2 m)", "convertible to rpm"),
        ("x=uniform(1)", "uniform\\(low, high\\)"),
        ("x", "PATH=DIST"),
    ],
)
def test_bad_distributions_are_one_line_errors(text, match):
    with pytest.raises(InputError, match=match) as e:
        parse_param(text)
    assert "\n" not in str(e.value)


def test_unknown_field_did_you_mean():
    with pytest.raises(InputError, match="did you mean operation.speed"):
        with_values({"operation": {"speed": "1 rpm", "feed": "2 kg/h"}}, {"operation.sped": 1})


@pytest.mark.parametrize("design", [latin_hypercube, sobol_sequence, monte_carlo])
def test_sampled_designs_follow_the_distributions(design):
    params = as_params({"a": "uniform(2 m, 4 m)", "b": "normal(10, 1)"})
    cases = design(params, 256, seed=3)
    a = np.array([float(c.values["a"].split()[0]) for c in cases])
    b = np.array([c.values["b"] for c in cases])
    assert 2 <= a.min() and a.max() <= 4 and abs(a.mean() - 3) < 0.1
    assert abs(b.mean() - 10) < 0.2 and abs(b.std() - 1) < 0.15
    assert [c.case_id for c in cases] == list(range(256))
    again = design(params, 256, seed=3)
    assert [c.values for c in again] == [c.values for c in cases]  # reproducible: resumable


def test_latin_hypercube_strata():
    cases = latin_hypercube(["a=uniform(0, 1)"], 10, seed=1)
    assert sorted(int(c.values["a"] * 10) for c in cases) == list(range(10))
    with pytest.raises(InputError, match="study.n"):
        latin_hypercube(["a=uniform(0, 1)"], 0)
    with pytest.raises(InputError, match="given once"):
        as_params(["a=uniform(0, 1)", "a=uniform(0, 2)"])


@pytest.mark.parametrize(("d", "n", "seed"), [(1, 5, 0), (2, 200, 1), (8, 64, 7), (3, 1000, 12)])
def test_the_latin_hypercube_is_scipys(d, n, seed):
    """The design's points are scipy.stats.qmc.LatinHypercube's, draw for draw (drawn without
    importing scipy.stats, which costs a sweep command more than its cases' set-up)."""
    from scipy.stats import qmc

    from rotarykiln.studies.design import unit_latin_hypercube

    want = qmc.LatinHypercube(d=d, seed=seed).random(n)
    assert np.array_equal(unit_latin_hypercube(d, n, seed), want)


@pytest.mark.parametrize(("d", "n"), [(0, 5), (2, 0), (2, 2.5), (-1, 3)])
def test_a_latin_hypercube_of_no_points_or_dimensions_is_refused(d, n):
    from rotarykiln.studies.design import unit_latin_hypercube

    with pytest.raises(InputError, match="an integer >= 1"):
        unit_latin_hypercube(d, n)
