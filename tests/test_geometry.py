import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rotarykiln import geometry as g
from rotarykiln.errors import InputError

fills = st.floats(min_value=1e-9, max_value=1 - 1e-9, allow_nan=False)
radii = st.floats(min_value=1e-3, max_value=10.0)


@given(fills)
@settings(max_examples=500, deadline=None)
def test_fill_angle_fill_round_trip(f):
    assert abs(g.fill_from_half_angle(g.half_angle_from_fill(f)) - f) <= 1e-12


@given(st.floats(min_value=1e-6, max_value=2 - 1e-6), radii)
@settings(max_examples=500, deadline=None)
def test_depth_fill_depth_round_trip(h_over_r, radius):
    depth = h_over_r * radius
    back = g.depth_from_fill(g.fill_from_depth(depth, radius), radius)
    assert abs(back - depth) <= 1e-12 * max(1.0, radius)


@given(st.floats(min_value=1e-6, max_value=np.pi / 2), radii)
def test_chord_angle_round_trip(theta, radius):
    chord = g.chord_from_half_angle(theta, radius)
    assert g.half_angle_from_chord(chord, radius) == pytest.approx(theta, abs=1e-7)


def test_half_fill_at_depth_of_one_radius():
    assert g.fill_from_depth(0.7, 0.7) == pytest.approx(0.5, abs=1e-15)


def test_inverse_is_vectorised_and_handles_ends():
    f = np.array([0.0, 1e-15, 1e-8, 0.25, 0.5, 0.75, 1 - 1e-12, 1.0])
    theta = g.half_angle_from_fill(f)
    assert theta.shape == f.shape
    assert theta[0] == 0.0 and theta[-1] == pytest.approx(np.pi)
    assert np.all(np.diff(theta) > 0)
    assert np.max(np.abs(g.fill_from_half_angle(theta) - f)) <= 1e-12


def test_reflection_symmetry():
    f = np.linspace(0.01, 0.49, 49)
    assert np.allclose(g.half_angle_from_fill(1 - f), np.pi - g.half_angle_from_fill(f), atol=1e-13)


def test_areas_and_arcs_add_up():
    r, theta = 0.5, 0.9
    assert g.bed_area(theta, r) + g.freeboard_area(theta, r) == pytest.approx(np.pi * r**2)
    assert g.covered_wall_arc(theta, r) + g.exposed_wall_arc(theta, r) == pytest.approx(
        2 * np.pi * r
    )
    assert g.exposed_bed_width(theta, r) == pytest.approx(2 * r * np.sin(theta))
    # segment area by direct integration of the chord width over the depth
    y = np.linspace(-r, -r * np.cos(theta), 20001)
    width = 2 * np.sqrt(r**2 - y**2)
    assert g.bed_area(theta, r) == pytest.approx(np.trapezoid(width, y), rel=1e-6)


def test_hydraulic_diameter_limits():
    assert g.freeboard_hydraulic_diameter(0.0, 0.5) == pytest.approx(1.0)
    # half full: semicircle of radius R, Dh = 4 (pi R^2 / 2) / (pi R + 2R)
    r = 1.0
    assert g.freeboard_hydraulic_diameter(np.pi / 2, r) == pytest.approx(
        2 * np.pi * r / (np.pi + 2)
    )


def test_cross_section_from_every_measure_agrees():
    ref = g.CrossSection.from_fill(0.2, 0.3)
    for other in (
        g.CrossSection.from_depth(ref.depth, 0.3),
        g.CrossSection.from_half_angle(ref.theta, 0.3),
        g.CrossSection.from_chord(ref.chord, 0.3),
    ):
        assert other.fill == pytest.approx(0.2, abs=1e-12)
    frame = g.CrossSection.from_fill(np.array([0.1, 0.2]), 0.3).to_frame()
    assert list(frame["fill"].round(12)) == [0.1, 0.2]


@pytest.mark.parametrize(
    "call",
    [
        lambda: g.half_angle_from_fill(1.2),
        lambda: g.half_angle_from_fill(-0.1),
        lambda: g.half_angle_from_fill(np.nan),
        lambda: g.fill_from_depth(0.5, -1.0),
        lambda: g.fill_from_depth(2.5, 1.0),
        lambda: g.half_angle_from_chord(3.0, 1.0),
    ],
)
def test_bad_values_raise_input_error(call):
    with pytest.raises(InputError):
        call()
