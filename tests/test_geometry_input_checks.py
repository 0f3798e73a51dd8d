"""Input checks of geometry and regimes: bad values raise InputError naming the argument."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from rotarykiln import geometry as geo
from rotarykiln import regimes
from rotarykiln.errors import InputError

NAN = float("nan")

CASES = [
    # (function, valid keyword arguments, argument to spoil, bad value)
    (geo.bed_area, {"theta": 1.0, "radius": 0.5}, "radius", -0.5),
    (geo.bed_area, {"theta": 1.0, "radius": 0.5}, "radius", NAN),
    (geo.bed_area, {"theta": 1.0, "radius": 0.5}, "theta", 4.0),
    (geo.chord_from_half_angle, {"theta": 1.0, "radius": 0.5}, "theta", NAN),
    (geo.chord_from_half_angle, {"theta": 1.0, "radius": 0.5}, "radius", 0.0),
    (geo.depth_from_half_angle, {"theta": 1.0, "radius": 0.5}, "radius", -1.0),
    (geo.depth_from_fill, {"fill": 0.2, "radius": 0.5}, "radius", NAN),
    (geo.depth_from_fill, {"fill": 0.2, "radius": 0.5}, "fill", 1.5),
    (geo.covered_wall_arc, {"theta": 1.0, "radius": 0.5}, "theta", -0.1),
    (geo.exposed_wall_arc, {"theta": 1.0, "radius": 0.5}, "radius", -0.5),
    (geo.exposed_bed_width, {"theta": 1.0, "radius": 0.5}, "radius", NAN),
    (geo.freeboard_area, {"theta": 1.0, "radius": 0.5}, "radius", -0.5),
    (geo.freeboard_hydraulic_diameter, {"theta": 1.0, "radius": 0.5}, "radius", 0.0),
    (geo.freeboard_hydraulic_diameter, {"theta": 1.0, "radius": 0.5}, "theta", NAN),
    (
        regimes.critical_wall_friction_mellmann,
        {"fill": 0.1, "repose_angle": 0.6, "froude": 1e-3},
        "repose_angle",
        -0.6,
    ),
    (
        regimes.critical_wall_friction_mellmann,
        {"fill": 0.1, "repose_angle": 0.6, "froude": 1e-3},
        "froude",
        NAN,
    ),
]


@pytest.mark.parametrize(("func", "kwargs", "arg", "bad"), CASES)
def test_bad_value_raises_input_error_naming_the_argument(func, kwargs, arg, bad):
    func(**kwargs)  # the valid call works
    with pytest.raises(InputError, match=arg):
        func(**{**kwargs, arg: bad})


def test_bad_element_of_an_array_is_caught():
    with pytest.raises(InputError, match="radius"):
        geo.bed_area(np.array([0.5, 1.0]), np.array([0.3, -0.3]))


def test_classify_regime_rejects_negative_wall_friction():
    with pytest.raises(InputError, match="wall_friction"):
        regimes.classify_regime(1e-3, 0.2, wall_friction=-0.1, repose_angle=0.6)


def test_full_drum_has_zero_hydraulic_diameter_not_nan():
    # was 0/0 = NaN: a full drum has no freeboard (area ~ eps^3, perimeter ~ eps near theta = pi)
    assert geo.freeboard_hydraulic_diameter(np.pi, 0.5) == 0.0
    assert geo.CrossSection.from_fill(1.0, 0.5).hydraulic_diameter == 0.0
    # and the value just below full tends to it
    assert 0.0 < geo.freeboard_hydraulic_diameter(np.pi - 1e-3, 0.5) < 1e-6


@given(
    theta=st.floats(0.0, np.pi, allow_nan=False),
    radius=st.floats(1e-3, 10.0, allow_nan=False),
)
def test_cross_section_is_finite_over_the_whole_range(theta, radius):
    cs = geo.CrossSection.from_half_angle(theta, radius)
    values = np.array([np.asarray(v, float) for k, v in cs.as_dict().items()])
    assert np.all(np.isfinite(values))
    assert 0.0 <= cs.hydraulic_diameter <= 2.0 * radius + 1e-12
