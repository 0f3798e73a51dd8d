"""Pulverised-fuel burn-out along a path: size distributions (checked, one-line refusals), the
integrated model against the closed forms of its own kinetics (char burn-out trajectory,
Kobayashi and Badzioch-Hawksley yields), element and energy closure, and bad input."""

import math
from dataclasses import replace

import numpy as np
import pytest

from rotarykiln.chemistry import fuel_burnout as fb
from rotarykiln.chemistry import solid_fuels as sf
from rotarykiln.chemistry.clinker import element_molar_mass
from rotarykiln.errors import InputError

ATM = 101325.0
P = fb.load_burnout_parameters()
H_C = -P.h_f_CO2 / element_molar_mass("C")  # heat of combustion of carbon, J/kg


def one_line(exc):
    msg = str(exc.value)
    assert "\n" not in msg
    return msg


def pure_char():
    """A fuel that is char only (carbon, no volatiles, moisture or ash)."""
    return sf.SolidFuel.from_analyses(
        ultimate={"C": 1.0, "H": 0.0, "O": 0.0, "N": 0.0, "S": 0.0, "ash": 0.0},
        ultimate_basis="d",
        proximate={"volatiles": 0.0, "ash": 0.0},
        proximate_basis="d",
        moisture_ar=0.0,
        hhv=H_C,
        hhv_basis="d",
        name="char",
    )


#: instantaneous "devolatilisation" of the pure char (no volatiles), coal density = char's
INSTANT = replace(P, A1=1e9, E1=1.0, A2=1e9, E2=1.0, alpha1=0.0, alpha2=0.0, coal_density=1000.0)


# ------------------------------------------------------------------ size distributions


def test_table_is_checked_and_kept():
    psd = fb.ParticleSizeDistribution.from_table([20e-6, 50e-6, 100e-6], [0.3, 0.5, 0.2])
    assert psd.n_classes == 3
    assert psd.mass_fractions.sum() == pytest.approx(1.0, abs=1e-15)
    with pytest.raises(ValueError):
        psd.sizes[0] = 1.0  # frozen arrays


@pytest.mark.parametrize(
    "sizes, fractions, expected",
    [
        ([20e-6, 50e-6], [0.5, 0.4], "psd.mass_fractions: sum 0.9 is not 1 +- 1e-06 (fractions"),
        ([20e-6, 50e-6], [50.0, 50.0], "psd.mass_fractions: sum 100 is not 1 +- 1e-06"),
        ([20e-6, 50e-6], [1.2, -0.2], "psd.mass_fractions: -0.2 is not >= 0 (a mass fraction)"),
        ([50e-6, 20e-6], [0.5, 0.5], "psd.sizes: 2e-05 m after 5e-05 m is not strictly incr"),
        ([0.0, 20e-6], [0.5, 0.5], "psd.sizes: 0 m is not > 0 m"),
        ([20e-6, 50e-6], [1.0], "psd.mass_fractions: 1 values is not 2 values, one per size"),
        ([], [], "psd.sizes: [] is not a non-empty list of sizes in m"),
    ],
)
def test_table_refusals_in_one_line(sizes, fractions, expected):
    with pytest.raises(InputError) as e:
        fb.ParticleSizeDistribution.from_table(sizes, fractions)
    assert one_line(e).startswith(expected)


def test_rosin_rammler_classes_carry_the_law():
    xp, n = 40e-6, 1.1
    psd = fb.ParticleSizeDistribution.rosin_rammler(xp, n, n_classes=8)
    assert psd.mass_fractions.sum() == pytest.approx(1.0, abs=1e-14)
    assert np.all(np.diff(psd.sizes) > 0)
    # each class at its mass median: the retained fraction there is the mid-point of the class
    R_mid = fb.rosin_rammler_retained(psd.sizes, xp, n)
    R_edges = 1.0 - np.concatenate(([0.0], np.cumsum(psd.mass_fractions)))
    assert R_mid == pytest.approx(0.5 * (R_edges[:-1] + R_edges[1:]), abs=1e-12)
    # one class: the mass median x'(ln 2)^(1/n)
    one = fb.ParticleSizeDistribution.rosin_rammler(xp, n, n_classes=1)
    assert one.sizes[0] == pytest.approx(xp * math.log(2.0) ** (1 / n), rel=1e-12)
    # the sieve residue and x' are each other's inverse
    assert fb.rosin_rammler_retained(90e-6, fb.rosin_rammler_x_prime(90e-6, 0.12, n), n) == (
        pytest.approx(0.12, rel=1e-12)
    )
    with pytest.raises(InputError) as e:
        fb.ParticleSizeDistribution.rosin_rammler(xp, -1.0)
    assert one_line(e) == "psd.n: -1 is not > 0"
    with pytest.raises(InputError) as e:
        fb.ParticleSizeDistribution.rosin_rammler(xp, n, n_classes=2.5)
    assert one_line(e) == "psd.n_classes: 2.5 is not an integer >= 1"
    with pytest.raises(InputError) as e:
        fb.rosin_rammler_x_prime(90e-6, 12.0, n)
    assert one_line(e) == "residue: 12 is not a mass fraction in (0, 1) (not a percentage)"


# ------------------------------------------------------------------ the model against its kinetics


def test_single_class_char_follows_the_analytic_burnout():
    # A 60 um char sphere of constant density 1000 kg/m3 at 1500 K in 5 % O2: the integrated
    # diameter must follow t(d) = rho (d0 - d)/(2 p R_k) + rho (d0^2 - d^2)/(4 p C1 T^0.75), the
    # integral of the same rate behind baum_street_char_burnout_time.
    d0, rho, T, p = 60e-6, 1000.0, 1500.0, 0.05 * ATM
    tb = sf.baum_street_char_burnout_time(d0, rho, T, p)
    t = np.linspace(0.0, 1.2 * tb, 241)
    psd = fb.ParticleSizeDistribution.from_table([d0], [1.0])
    r = fb.pulverised_fuel_burnout(
        pure_char(), psd, 1.0, t, T, p, time=t, parameters=INSTANT, heating_value="hhv"
    )
    assert r.extra["char_density"] == rho
    left = r.char_flow / 1.0
    d = d0 * np.cbrt(np.clip(left, 0.0, None))
    Rk = sf.baum_street_kinetic_rate_coefficient(T)
    t_of_d = rho * (d0 - d) / (2 * p * Rk) + rho * (d0**2 - d**2) / (4 * p * P.C1 * T**0.75)
    burning = (t > 1e-6) & (left > 1e-6)
    assert t_of_d[burning] == pytest.approx(t[burning], rel=2e-5)
    assert r.burnout[t >= tb * 1.001].min() > 1.0 - 1e-9  # burnt out at t_b, not later
    assert r.burnout[t <= tb * 0.999].max() < 1.0 - 1e-10  # and not before
    assert r.unburnt_carbon == pytest.approx(0.0, abs=1e-9)
    # all of its heat is the carbon's, released by the char
    assert r.cumulative_heat_release[-1] == pytest.approx(H_C, rel=1e-8)
    assert np.abs(r.heat_release_volatiles).max() <= 1e-9 * np.abs(r.heat_release_char).max()


def test_kobayashi_release_is_the_isothermal_yield():
    # no oxygen: nothing burns, the volatiles released follow kobayashi_isothermal_yield exactly
    f = sf.load_kiln_fuel("pittsburgh_8")
    daf = 1.0 - f.ultimate("ar")["moisture"] - f.ultimate("ar")["ash"]
    a1 = f.proximate("daf")["volatiles"]
    T = 1300.0
    z = np.linspace(0.0, 5.0, 51)
    psd = fb.ParticleSizeDistribution.from_table([50e-6], [1.0])
    r = fb.pulverised_fuel_burnout(f, psd, 2.0, z, T, 0.0, velocity=1.0)
    expect = 2.0 * daf * sf.kobayashi_isothermal_yield(T, r.t, a1, P.alpha2)
    assert r.volatiles_released == pytest.approx(expect, rel=1e-6, abs=1e-12)
    assert np.all(r.char_burning_rate == 0.0)
    assert r.unburnt_combustible == pytest.approx(2.0 * daf - r.volatiles_released[-1], rel=1e-12)


def test_badzioch_hawksley_release_is_first_order():
    f = sf.load_kiln_fuel("illinois_6")
    daf = 1.0 - f.ultimate("ar")["moisture"] - f.ultimate("ar")["ash"]
    v_star = 1.2 * f.proximate("daf")["volatiles"]  # a Q factor of 1.2
    pars = replace(P, sfor_yield_factor=1.2)
    T, t = 1100.0, np.linspace(0.0, 2.0, 41)
    psd = fb.ParticleSizeDistribution.from_table([50e-6], [1.0])
    r = fb.pulverised_fuel_burnout(
        f, psd, 1.0, t, T, 0.0, time=t, devolatilisation="badzioch_hawksley", parameters=pars
    )
    k = P.sfor_A * math.exp(-P.sfor_E / (sf.R_GAS * T))
    assert r.volatiles_released == pytest.approx(daf * v_star * (1 - np.exp(-k * t)), rel=1e-6)
    # the rate is the one of badzioch_hawksley_devolatilisation_rate (per kg daf) x daf / u
    V = r.volatiles_released / daf
    rate = sf.badzioch_hawksley_devolatilisation_rate(T, V, v_star, P.sfor_A, P.sfor_E) * daf
    assert r.volatile_release_rate == pytest.approx(rate, rel=1e-6)


def test_velocity_and_time_are_the_same_path():
    f = sf.load_kiln_fuel("pittsburgh_8")
    psd = fb.ParticleSizeDistribution.rosin_rammler(40e-6, 1.0, n_classes=4)
    z = np.linspace(0.0, 12.0, 25)
    u = np.linspace(8.0, 4.0, 25)  # a decelerating jet
    T = np.linspace(1300.0, 1700.0, 25)
    a = fb.pulverised_fuel_burnout(f, psd, 1.0, z, T, 0.04 * ATM, velocity=u)
    b = fb.pulverised_fuel_burnout(f, psd, 1.0, z, T, 0.04 * ATM, time=a.t + 3.0)
    assert b.t == pytest.approx(a.t, abs=1e-12)
    assert b.burnout == pytest.approx(a.burnout, abs=1e-7)
    # per-metre rates differ only through u = dz/dt (gradient of the time given)
    assert b.cumulative_heat_release == pytest.approx(a.cumulative_heat_release, rel=1e-6)


def test_particle_temperature_option_slows_a_cooler_particle():
    f = sf.load_kiln_fuel("pittsburgh_8")
    psd = fb.ParticleSizeDistribution.from_table([60e-6], [1.0])
    z = np.linspace(0.0, 5.0, 21)
    hot = fb.pulverised_fuel_burnout(f, psd, 1.0, z, 1500.0, 0.05 * ATM, velocity=5.0)
    cool = fb.pulverised_fuel_burnout(
        f, psd, 1.0, z, 1500.0, 0.05 * ATM, velocity=5.0, T_particle=1300.0
    )
    assert np.all(cool.burnout[1:] < hot.burnout[1:])


# ------------------------------------------------------------------ closure


def heteroatom_rich_fuel():
    """A petcoke-like fuel whose volatile matter (6 % daf) is below its H+O+N+S (about 11 %):
    the char keeps heteroatoms."""
    return sf.SolidFuel.from_analyses(
        ultimate={"C": 0.885, "H": 0.035, "O": 0.01, "N": 0.015, "S": 0.05, "ash": 0.005},
        ultimate_basis="d",
        proximate={"moisture": 0.06, "volatiles": 0.056, "ash": 0.0047},
        proximate_basis="ar",
        name="petcoke-like",
    )


@pytest.mark.parametrize("devol", ["kobayashi", "badzioch_hawksley"])
@pytest.mark.parametrize(
    "fuel", ["pittsburgh_8", "illinois_6", "wyodak_anderson", "beulah_zap", "petcoke"]
)
def test_elements_and_energy_close(fuel, devol):
    f = heteroatom_rich_fuel() if fuel == "petcoke" else sf.load_kiln_fuel(fuel)
    psd = fb.ParticleSizeDistribution.rosin_rammler(45e-6, 1.0, n_classes=6)
    z = np.linspace(0.0, 30.0, 61)
    T = 1200.0 + 600.0 * np.sin(np.pi * z / 30.0)  # a flame: rises then falls
    p = ATM * np.linspace(0.06, 0.01, 61)
    mdot = 3.2
    r = fb.pulverised_fuel_burnout(f, psd, mdot, z, T, p, velocity=12.0, devolatilisation=devol)
    assert r.success
    assert r.element_closure_error <= 1e-8
    assert r.energy_closure_error <= 1e-8
    # the released C, H, O, N, S, Cl plus what the particles still hold make the fuel's
    # ultimate analysis (as received, without its moisture and ash), at every point
    u = f.ultimate("ar")
    fed = mdot * np.array([u[e] for e in fb.ELEMENTS])
    assert r.released_elements + r.unreleased_elements == pytest.approx(
        np.broadcast_to(fed, r.released_elements.shape), abs=1e-8 * mdot
    )
    assert r.unburnt_carbon == pytest.approx(max(r.unreleased_elements[-1, 0], 0.0), abs=1e-15)
    assert r.ash_flow == pytest.approx(mdot * u["ash"])
    assert r.moisture_flow[-1] == pytest.approx(0.0, abs=1e-9)
    # released by volatiles and by char: their sum is the total, and volatile + char masses too
    assert r.volatiles_released[-1] + r.char_burnt[-1] == pytest.approx(
        r.released_elements[-1].sum(), rel=1e-10
    )
    # heat: the cumulative release accounts for the heating value when all is burnt
    if r.burnout[-1] > 1 - 1e-9:
        assert r.cumulative_heat_release[-1] == pytest.approx(mdot * f.lhv("ar"), rel=1e-8)
    if fuel == "petcoke" and devol == "kobayashi":
        # the char of reaction 1 holds sulphur: some S is released by the burning char
        assert r.char_element_rate[:, 4].max() > 0


def test_full_burnout_releases_the_heating_value_on_both_bases():
    f = sf.load_kiln_fuel("pittsburgh_8")
    psd = fb.ParticleSizeDistribution.rosin_rammler(30e-6, 1.2, n_classes=5)
    z = np.linspace(0.0, 40.0, 81)
    for basis, hv in (("lhv", f.lhv("ar")), ("hhv", f.hhv("ar"))):
        r = fb.pulverised_fuel_burnout(
            f, psd, 1.5, z, 1750.0, 0.05 * ATM, velocity=10.0, heating_value=basis
        )
        assert r.burnout[-1] == pytest.approx(1.0, abs=1e-9)
        assert r.heating_value == pytest.approx(hv, rel=1e-12)
        assert r.cumulative_heat_release[-1] == pytest.approx(1.5 * hv, rel=1e-8)
        # the split: the char releases the heat of combustion of what it burns (here carbon
        # only: the Kobayashi yields exceed the heteroatoms), the volatiles the rest
        assert np.cumsum(r.heat_release_char) == pytest.approx(
            np.cumsum(r.char_burning_rate) * H_C, rel=1e-12
        )
    # drying absorbs the latent heat on the LHV basis only
    assert r.heat_of_drying.min() == 0.0


def test_rates_integrate_to_the_cumulative_flows():
    # point rates (kg/(s m), W/m) integrated along z give the cumulative flows, on a path smooth
    # enough for the trapezoid rule (dry fuel: no drying spike at the inlet)
    f = sf.SolidFuel.from_analyses(
        ultimate={"C": 0.7550, "H": 0.0483, "N": 0.0149, "S": 0.0219, "Cl": 0.0011, "ash": 0.0925},
        proximate={"volatiles": 0.3783, "ash": 0.0925},
        proximate_basis="d",
        moisture_ar=0.0,
    )
    psd = fb.ParticleSizeDistribution.from_table([40e-6, 80e-6], [0.6, 0.4])
    z = np.linspace(0.0, 10.0, 2001)
    T = 900.0 + 80.0 * z
    r = fb.pulverised_fuel_burnout(f, psd, 1.0, z, T, 0.05 * ATM, velocity=5.0)

    def cum(rate):
        return np.concatenate(([0.0], np.cumsum(0.5 * (rate[1:] + rate[:-1]) * np.diff(z))))

    assert cum(r.volatile_release_rate)[-1] == pytest.approx(r.volatiles_released[-1], rel=1e-4)
    assert cum(r.char_burning_rate)[-1] == pytest.approx(r.char_burnt[-1], rel=1e-4)
    assert cum(r.heat_release_rate)[-1] == pytest.approx(r.cumulative_heat_release[-1], rel=1e-4)
    # the char consumes 32/12 kg O2 per kg C (and S -> SO2, H -> H2O of its share)
    assert np.all(r.oxygen_demand_rate >= 0)
    frame = r.to_frame()
    assert frame.attrs["units"]["heat_release_W_m"] == "W/m"
    assert frame.attrs["units"]["char_burning_kg_s_m"] == "kg/(s m)"
    assert len(frame) == z.size


# ------------------------------------------------------------------ refusals


def test_bad_path_and_options_refused_in_one_line():
    f = sf.load_kiln_fuel("pittsburgh_8")
    psd = fb.ParticleSizeDistribution.from_table([50e-6], [1.0])
    z = np.linspace(0.0, 1.0, 5)
    cases = [
        (dict(z=z[::-1]), "z: "),
        (dict(T_gas=-5.0), "T_gas: -5 is not > 0 K"),
        (dict(T_gas=np.ones(3) * 1500), "T_gas: 3 values is not 5 values, one per z"),
        (dict(p_o2=-1.0), "p_o2: -1 is not >= 0 Pa"),
        (dict(velocity=None), "velocity, time: both or neither is not exactly one of them given"),
        (dict(time=z), "velocity, time: both or neither"),
        (dict(velocity=0.0), "velocity: 0 m/s is not > 0"),
        (dict(devolatilisation="sfor"), "devolatilisation: sfor is not one of kobayashi"),
        (dict(heating_value="gcv"), "heating_value: gcv is not one of lhv, hhv"),
        (dict(method="RK45"), "method: RK45 is not one of BDF, Radau"),
        (dict(fuel_mass_flow=0.0), "fuel_mass_flow: 0 kg/s is not > 0"),
        (dict(psd=[50e-6]), "psd: list is not a ParticleSizeDistribution"),
        (dict(fuel="anthracite"), "fuel: anthracite is not one of"),
    ]
    for change, expected in cases:
        kw = dict(fuel=f, psd=psd, fuel_mass_flow=1.0, z=z, T_gas=1500.0, p_o2=5000.0, velocity=5.0)
        kw.update(change)
        with pytest.raises(InputError) as e:
            fb.pulverised_fuel_burnout(**kw)
        assert one_line(e).startswith(expected), (change, str(e.value))


def test_bad_fuel_refused_in_one_line():
    # an analysis that does not sum to 100 % is refused naming its basis, before any burn-out
    with pytest.raises(InputError) as e:
        sf.SolidFuel.from_analyses(
            ultimate={"C": 0.80, "H": 0.05, "O": 0.08, "N": 0.015, "S": 0.02, "ash": 0.10},
            ultimate_basis="d",
        )
    assert one_line(e).startswith(
        "ultimate (dry basis: C + H + O + N + S + Cl + ash): sum 1.065 is not 1 +- 0.005"
    )
    # no proximate analysis: the yields are unknown unless alpha1 is given
    f = sf.SolidFuel.from_analyses(
        ultimate={"C": 0.7550, "H": 0.0483, "N": 0.0149, "S": 0.0219, "ash": 0.0925},
        ultimate_basis="d",
    )
    psd = fb.ParticleSizeDistribution.from_table([50e-6], [1.0])
    z = np.linspace(0.0, 1.0, 3)
    with pytest.raises(InputError) as e:
        fb.pulverised_fuel_burnout(f, psd, 1.0, z, 1500.0, 5000.0, velocity=5.0)
    assert one_line(e).startswith("fuel.proximate: missing (required: its volatile matter sets")
    r = fb.pulverised_fuel_burnout(
        f,
        psd,
        1.0,
        z,
        1500.0,
        5000.0,
        velocity=5.0,
        parameters=replace(P, alpha1=0.4, char_density=700.0),
    )
    assert r.element_closure_error <= 1e-8
    with pytest.raises(InputError) as e:
        fb.pulverised_fuel_burnout(
            f,
            psd,
            1.0,
            z,
            1500.0,
            5000.0,
            velocity=5.0,
            parameters=replace(P, alpha1=0.4, alpha2=1.5),
        )
    assert one_line(e) == "parameters.alpha2: 1.5 is not in [0, 1] (volatiles per kg of daf fuel)"
