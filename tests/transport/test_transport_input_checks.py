"""Input checks of the transport correlations and kinematics: InputError naming the argument,
and finite limits (not 0/0) at zero flow."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rotarykiln.errors import InputError
from rotarykiln.transport import correlations as cor
from rotarykiln.transport import kramers, saeman, scaleup, scott

NAN = float("nan")
DEG = np.pi / 180
DRUM = {"length": 10.0, "diameter": 1.0, "speed": 0.2, "slope": 2 * DEG, "repose": 35 * DEG}
HOGG = {"q": 2e-6, "length": 0.248, "radius": 0.0475, "speed": 6.6, "repose": 38 * DEG}
SCOTT_P = scott.ScottParameters(4.03, 28 * DEG, 24.5 * DEG, 0.0, 0.1302)
SCOTT_INCLINED = scott.ScottParameters(3.61, 28 * DEG, 24.5 * DEG, 2 * DEG, 0.1302)

CASES = [
    (cor.sullivan_residence_time, DRUM, "length", -10.0),
    (cor.sullivan_residence_time, DRUM, "diameter", NAN),
    (cor.sullivan_residence_time, DRUM, "speed", 0.0),
    (cor.sullivan_residence_time, DRUM, "slope", 0.0),
    (cor.sullivan_residence_time, DRUM, "repose", 1 * DEG),  # below the slope
    (cor.bayard_residence_time, DRUM, "repose", NAN),
    (cor.gilbert_residence_time, {"length": 1.0, "diameter": 0.1, "speed": 1.0}, "speed", -1.0),
    (cor.ginstling_residence_time, {**DRUM, "repose": None}, "slope", -0.1),
    (cor.van_krevelen_residence_time, {**DRUM, "repose": None, "k": 0.2}, "k", -0.2),
    (cor.gibbs_capacity, {"length": 18.0, "diameter": 2.4, "k": 1.0}, "diameter", -2.4),
    (cor.perry_residence_time, {**DRUM, "repose": None}, "length", NAN),
    (cor.perry_residence_time, {**DRUM, "repose": None}, "gas_mass_flux", -1.0),
    (cor.hogg_mean_fill, HOGG, "q", -1e-6),
    (cor.hogg_mean_fill, HOGG, "radius", 0.0),
    (cor.hogg_local_fill, {**HOGG, "length": None, "x": 0.2}, "x", -0.2),
    (cor.hogg_constricted_mean_fill, {**HOGG, "discharge_fill": 0.1}, "discharge_fill", 1.2),
    (cor.austin_flemmer_minimum_fill, {**HOGG, "length": None}, "repose", 2.0),
    (
        cor.abouzeid_fuerstenau_mean_fill,
        {
            "q": 1e-6,
            "length": 0.24,
            "diameter": 0.08,
            "speed": 4.4,
            "discharge_fill": 0.15,
            "a": 1.2,
        },
        "a",
        NAN,
    ),
    (
        cor.abouzeid_fuerstenau_weir_fill,
        {"height_over_weir": 0.0, "weir_radius": 0.037, "drum_radius": 0.0465},
        "height_over_weir",
        1.0,
    ),
    (
        cor.karra_fuerstenau_discharge_fill,
        {"q": 1e-6, "diameter": 0.127, "k3": 2.0, "k4": 0.5},
        "q",
        NAN,
    ),
    (
        cor.vahl_kingma_flow,
        {"inlet_depth": 0.03, "diameter": 0.11, "length": 0.63, "speed": 3.0, "repose": 0.6},
        "inlet_depth",
        -0.03,
    ),
    (
        cor.vahl_kingma_residence_time,
        {"inlet_depth": 0.03, "diameter": 0.11, "length": 0.63, "speed": 3.0, "repose": 0.6},
        "inlet_depth",
        0.0,
    ),
    (
        kramers.kramers_max_uniform_flow,
        {"radius": 0.2, "speed": 0.3, "slope": 0.02, "repose": 0.6},
        "radius",
        -0.2,
    ),
    (
        kramers.kramers_dimensionless_flow,
        {"q": 1e-5, "radius": 0.1, "speed": 1.0, "slope": 0.02, "repose": 0.7},
        "q",
        -1e-5,
    ),
    (
        kramers.kramers_dimensionless_length,
        {"length": 1.78, "radius": 0.1, "slope": 0.02, "repose": 0.7},
        "slope",
        0.0,
    ),
    (
        kramers.kramers_uniform_residence_time,
        {"length": 2.0, "q": 1e-5, "radius": 0.2, "speed": 0.3, "slope": 0.02, "repose": 0.6},
        "length",
        NAN,
    ),
    (
        saeman.saeman_axial_advance,
        {"chord": 1.0, "slope": 0.05, "bed_slope": 0.0, "repose": 0.7},
        "chord",
        -1.0,
    ),
    (saeman.saeman_cascades_per_revolution, {"chord": 1.0, "r": 1.0}, "chord", 3.0),
    (
        saeman.saeman_residence_time,
        {"length": 36.6, "r": 1.83, "speed": 0.1, "slope": 0.05, "repose": 0.7},
        "r",
        0.0,
    ),
    (
        saeman.saeman_axial_velocity,
        {
            "r": 1.0,
            "surface_distance": 0.9,
            "speed": 0.1,
            "slope": 0.05,
            "bed_slope": 0.0,
            "repose": 0.7,
        },
        "r",
        0.5,  # a path above the bed surface
    ),
    (
        saeman.saeman_flow,
        {
            "radius": 1.0,
            "surface_distance": 0.0,
            "speed": 6.0,
            "slope": 0.05,
            "bed_slope": 0.0,
            "repose": 0.7,
        },
        "repose",
        NAN,
    ),
    (
        saeman.mctait_residence_time,
        {
            "length": 36.6,
            "diameter": 3.66,
            "speed": 0.1,
            "slope": 0.05,
            "repose": 0.7,
            "y_over_r": 0.2,
        },
        "diameter",
        -3.66,
    ),
    (
        scaleup.abouzeid_psi,
        {"q": 7e-7, "length": 0.24, "diameter": 0.08, "speed": 4.4, "repose": 0.68},
        "q",
        -7e-7,
    ),
    (
        scaleup.scott_psi,
        {"q": 3e-6, "length": 0.25, "diameter": 0.1, "speed": 3.5, "repose": 0.5},
        "length",
        0.0,
    ),
    (scaleup.gilbert_flow_number, {"q": 1e-5, "diameter": 0.1, "speed": 6.0}, "speed", NAN),
    (scaleup.karra_feed_number, {"q": 1e-6, "diameter": 0.08}, "diameter", -0.08),
    (scott.bachmann_dynamic_angle, {"alpha_s": 0.6, "omega": 7.8, "radius": 0.04}, "omega", -7.8),
    (scott.scott_cascade_time, {"chord": 0.05, "alpha_d": 0.49, "mu": 0.13}, "mu", NAN),
    (scott.scott_cascade_time, {"chord": 0.05, "alpha_d": 0.49, "mu": 0.13}, "chord", -0.05),
    (scott.scott_friction_coefficient, {"law": "dynamic", "alpha_d": 0.49}, "alpha_d", NAN),
    (
        scott.scott_flow_integral,
        {"b": 0.03, "r_up": 0.0465, "omega": 4.03, "alpha_d": 0.49, "mu": 0.13},
        "b",
        0.06,
    ),
    (
        scott.scott_flow_integral,
        {"b": 0.03, "r_up": 0.0465, "omega": 4.03, "alpha_d": 0.49, "mu": 0.13},
        "omega",
        0.0,
    ),
    (
        scott.scott_discharge_half_angle,
        {"q": 1e-6, "radius": 0.0465, "opening_radius": 0.037, "params": SCOTT_P},
        "q",
        NAN,  # was a ValueError from brentq
    ),
    (
        scott.scott_discharge_half_angle,
        {"q": 1e-6, "radius": 0.0465, "opening_radius": 0.037, "params": SCOTT_P},
        "opening_radius",
        0.05,
    ),
    (
        scott.scott_limiting_half_angle,
        {"q": 3e-6, "radius": 0.0465, "params": SCOTT_INCLINED},
        "radius",
        NAN,
    ),
    (
        scott.scott_surface_slope,
        {"theta": 1.0, "q": 1.9e-6, "radius": 0.0465, "params": SCOTT_P},
        "q",
        -1.0,
    ),
]


@pytest.mark.parametrize(("func", "kwargs", "arg", "bad"), CASES)
def test_bad_value_raises_input_error_naming_the_argument(func, kwargs, arg, bad):
    kwargs = {k: v for k, v in kwargs.items() if v is not None}
    assert np.all(np.isfinite(func(**kwargs)))  # the valid call works
    with pytest.raises(InputError, match=arg):
        func(**{**kwargs, arg: bad})


def test_array_with_one_bad_element_is_rejected():
    speeds = np.array([0.1, 0.2, -0.3])
    with pytest.raises(InputError, match="speed"):
        cor.sullivan_residence_time(10.0, 1.0, speeds, 2 * DEG, 35 * DEG)


def test_co_current_gas_term_cannot_make_the_residence_time_negative():
    with pytest.raises(InputError, match="gas_mass_flux"):
        cor.perry_residence_time(
            36.6,
            3.66,
            np.pi / 30,
            3 * DEG,
            gas_mass_flux=5.0,
            feed_flux=0.01,
            particle_size=1e-3,
            flow="co",
        )


def test_constricted_mean_fill_at_zero_flow_is_the_discharge_fill():
    # was 0/0 = NaN; with no flow the bed is level at the discharge filling (the limit of
    # eq. 2.35 and of 2.39: 0.751 x 0.812 x 1.64 = 1.0001, 12.99 x 1.64 / 21.31 = 0.9997)
    f = cor.hogg_constricted_mean_fill(
        0.0, **{k: HOGG[k] for k in HOGG if k != "q"}, discharge_fill=0.1
    )
    assert f == pytest.approx(0.1, rel=2e-4)
    g = cor.abouzeid_fuerstenau_mean_fill(0.0, 0.24, 0.08, 4.4, 0.15, 1.2)
    assert g == pytest.approx(0.15, rel=5e-4)
    # continuous with small flows
    small = cor.hogg_constricted_mean_fill(
        1e-15, **{k: HOGG[k] for k in HOGG if k != "q"}, discharge_fill=0.1
    )
    assert small == pytest.approx(f, rel=1e-8)


def test_uniform_residence_time_at_zero_flow_is_the_thin_bed_limit():
    # was 0/0 = NaN; the limit is Saeman's outermost-path time L sin(a)/(omega R tan(psi))
    args = (2.0, 0.2, 3 * np.pi / 30, 1 * DEG, 35 * DEG)
    t0 = kramers.kramers_uniform_residence_time(args[0], 0.0, *args[1:])
    length, radius, omega, slope, repose = args
    assert t0 == pytest.approx(length * np.sin(repose) / (omega * radius * np.tan(slope)))
    t_small = kramers.kramers_uniform_residence_time(args[0], 1e-12, *args[1:])
    assert t_small == pytest.approx(t0, rel=1e-4)


def test_saeman_velocity_of_the_surface_path_is_finite():
    # the path at the bed surface has zero chord: was 0/0 = NaN, now the lightly-loaded limit
    u = saeman.saeman_axial_velocity(0.9, 0.9, 0.1, 3 * DEG, 0.0, 40 * DEG)
    u_light = saeman.saeman_axial_velocity(0.9, 0.9, 0.1, 3 * DEG, 0.0, 40 * DEG, exact=False)
    assert u == pytest.approx(float(u_light))


def test_surface_slope_at_zero_flow_is_level():
    p = scott.ScottParameters(3.61, 28 * DEG, 24.5 * DEG, 2 * DEG, 0.1302)
    t0 = scott.scott_surface_slope(1.0, 0.0, 0.0465, p)
    assert t0 == pytest.approx(-p.C)
    assert scott.scott_surface_slope(1.0, 1e-13, 0.0465, p) == pytest.approx(-p.C, abs=1e-6)


@settings(max_examples=60, deadline=None)
@given(
    q=st.floats(0.0, 1e-4),
    fill=st.floats(0.01, 0.45),
    radius=st.floats(0.02, 2.0),
    speed=st.floats(0.05, 5.0),
)
def test_correlations_are_finite_for_valid_input(q, fill, radius, speed):
    repose = 35 * DEG
    values = [
        cor.hogg_constricted_mean_fill(q, 1.0, radius, speed, repose, fill),
        cor.abouzeid_fuerstenau_mean_fill(q, 1.0, 2 * radius, speed, fill, 1.2),
        cor.hogg_mean_fill(q, 1.0, radius, speed, repose),
        kramers.kramers_dimensionless_flow(q, radius, speed, 2 * DEG, repose),
        scaleup.scott_psi(q, 1.0, 2 * radius, speed, repose),
    ]
    assert np.all(np.isfinite(values))


def test_uniform_depth_rejects_a_nan_flow():
    # ``np.any(q < 0)`` is False for NaN: the depth came back NaN
    with pytest.raises(InputError, match="feed"):
        kramers.kramers_uniform_depth(float("nan"), 0.2, 0.3, 1 * DEG, 35 * DEG)


@settings(max_examples=25, deadline=None)
@given(
    log_q=st.floats(-9.0, -4.0),
    slope_deg=st.floats(0.0, 4.0),
    radius=st.floats(0.03, 1.0),
    frac_critical=st.floats(0.05, 0.45),
    dam=st.booleans(),
)
def test_profiles_are_finite_or_refused(log_q, slope_deg, radius, frac_critical, dam):
    # an open end starts at zero fill (h = 0): the profile and its times must stay finite,
    # or the model must refuse the feed with InputError (no steady solution)
    q = 10.0**log_q
    speed = frac_critical * np.sqrt(9.81 / radius)
    for model in ("kramers", "scott"):
        try:
            if model == "kramers":
                prof = kramers.kramers_profile(
                    q,
                    length=2.0,
                    radius=radius,
                    speed=speed,
                    slope=slope_deg * DEG,
                    repose=35 * DEG,
                    dam_height=0.3 * radius if dam else None,
                    n_points=100,
                )
            else:
                prof = scott.scott_profile(
                    q,
                    length=2.0,
                    radius=radius,
                    speed=speed,
                    slope=slope_deg * DEG,
                    dynamic_angle=35 * DEG,
                    static_angle=32 * DEG,
                    discharge_radius=0.7 * radius if dam else None,
                    n_points=60,
                )
        except InputError:
            continue
        for values in (prof.depth, prof.fill, prof.residence_time, prof.mean_residence_time):
            assert np.all(np.isfinite(values))
