import math
import warnings

import numpy as np
import pytest

from rotarykiln.errors import InputError, OutOfRangeWarning
from rotarykiln.rtd.correlations import (
    bongo_njeng_dispersion,
    holdup_fraction,
    sai_dispersion_number,
    sherritt_dispersion,
)
from rotarykiln.rtd.internals import (
    exit_dam_blocked_fraction,
    lifter_cross_section,
    loading_lifter_area,
)

RPM = 2 * math.pi / 60
R = 0.1013 / 2


def test_straight_lifter_pocket_is_the_exact_triangle_minus_the_wall_segment():
    # analytic check on a large kiln where the wall is nearly flat: area -> h^2 tan(beta)/2
    s = lifter_cross_section(100.0, 0.01, math.radians(30))
    assert s == pytest.approx(0.01**2 * math.tan(math.radians(30)) / 2, rel=1e-4)


def test_rectangular_lifter_holds_more_and_grows_with_repose_angle():
    straight = [lifter_cross_section(R, 0.01, math.radians(b)) for b in (30, 35, 39)]
    rect = [lifter_cross_section(R, 0.01, math.radians(b), arm=0.01) for b in (30, 35, 39)]
    assert np.all(np.diff(straight) > 0) and np.all(np.diff(rect) > 0)
    assert all(r > s for r, s in zip(rect, straight, strict=True))


def test_lifter_discharges_as_it_rises():
    held = [
        lifter_cross_section(R, 0.01, math.radians(39), arm=0.01, position=math.radians(g))
        for g in (-30, 0, 30, 60, 90)
    ]
    assert np.all(np.diff(held) <= 0)


def test_loading_area_eq_19():
    assert loading_lifter_area(4, 2.0) == 3.0
    with pytest.raises(InputError, match="integer"):
        loading_lifter_area(2.5, 1.0)


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: lifter_cross_section(R, 0.06, 0.6), "height"),
        (lambda: lifter_cross_section(R, 0.01, 2.0), "repose_angle"),
        (lambda: lifter_cross_section(R, 0.01, 0.6, arm=-1), "arm"),
        (lambda: exit_dam_blocked_fraction(0.06, R), "dam_height"),
    ],
)
def test_internals_bad_input(call, match):
    with pytest.raises(InputError, match=match):
        call()


def test_exit_dam_limits():
    assert exit_dam_blocked_fraction(0.0, R) == 0.0
    assert exit_dam_blocked_fraction(R, R) == 1.0


def _bn(**kw):
    args = dict(
        mass_flow=2.5 / 3600,
        bulk_density=1422.0,
        speed=3 * RPM,
        slope=math.radians(2),
        repose_angle=math.radians(39),
        particle_size=0.55e-3,
        loading_area=5.833e-5,
        diameter=0.1013,
    )
    args.update(kw)
    return bongo_njeng_dispersion(**args)


def test_bongo_njeng_reference_values_of_the_notes():
    # notes sec. 2.6, convention U1: sand SL 1.548e-6, sand RL 1.967e-6 (Ls from sec. 2.7)
    assert _bn() == pytest.approx(1.548e-6, rel=1e-3)
    assert _bn(loading_area=1.8613e-4) == pytest.approx(1.967e-6, rel=1e-3)
    # the literal SI reading is 100-300 times smaller (notes: 8.745e-9)
    assert _bn(convention="si") == pytest.approx(8.745e-9, rel=2e-3)


def test_bongo_njeng_is_vectorised():
    d = _bn(speed=np.array([2, 3, 12]) * RPM)
    assert d.shape == (3,)


@pytest.mark.parametrize(
    ("kw", "match"),
    [
        ({"speed": 20 * RPM}, "speed"),
        ({"slope": math.radians(1)}, "slope"),
        ({"mass_flow": 5 / 3600}, "feed"),
        ({"diameter": 0.4}, "diameter"),
        ({"loading_area": 0.0}, "without lifters"),
    ],
)
def test_bongo_njeng_warns_outside_its_range(kw, match):
    with pytest.warns(OutOfRangeWarning, match=match):
        _bn(**kw)


def test_bongo_njeng_inside_its_range_is_silent():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        _bn()


def test_sherritt_and_sai():
    x = holdup_fraction(2.5 / 3600, 2600.0, 1422.0, 0.1013, 1.95)
    d1 = sherritt_dispersion(3 * RPM, 0.1013, 0.55e-3, x)
    d2 = sherritt_dispersion(6 * RPM, 0.1013, 0.55e-3, x)
    assert d2 / d1 == pytest.approx(2**0.39)
    with pytest.warns(OutOfRangeWarning, match="hold-up"):
        sherritt_dispersion(3 * RPM, 0.1013, 0.55e-3, 0.6)
    n_kg = sai_dispersion_number(0.6, math.radians(2), 3 * RPM, 1087.0)
    n_g = sai_dispersion_number(0.6, math.radians(2), 3 * RPM, 1087.0, density_unit="g/cm3")
    assert n_g == pytest.approx(n_kg * 1000**0.25)  # rho^-0.25 with rho 1000 times smaller
    with pytest.raises(InputError, match="density_unit"):
        sai_dispersion_number(0.6, 0.03, 0.3, 1000.0, density_unit="lb")
