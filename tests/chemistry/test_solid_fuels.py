"""Solid fuels: analyses on their bases, heating values, complete combustion with any oxidiser
(elements balanced to 1e-12), devolatilisation and char burn-out; bad input refused in one line."""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from rotarykiln.chemistry import solid_fuels as sf
from rotarykiln.errors import InputError, OutOfRangeWarning

PITT_PROX = {"moisture": 0.0165, "ash": 0.0910, "volatiles": 0.3720}
PITT_ULT = {"C": 0.7550, "H": 0.0483, "N": 0.0149, "S": 0.0219, "Cl": 0.0011, "ash": 0.0925}


def one_line(exc):
    msg = str(exc.value)
    assert "\n" not in msg
    return msg


def pitt():
    return sf.load_kiln_fuel("pittsburgh_8")


# ------------------------------------------------------------------ bases


def test_basis_factors_round_trip_and_astm_forms():
    M, A, Mad = 0.08, 0.12, 0.03
    for a in sf.BASES:
        for b in sf.BASES:
            f = sf.astm_d3180_basis_factor(a, b, M, A, Mad) * sf.astm_d3180_basis_factor(
                b, a, M, A, Mad
            )
            assert f == pytest.approx(1.0, rel=1e-14)
    # x_ar = x_ad (1 - W_ar)/(1 - W_ad); x_daf = x_d/(1 - A_d)
    assert sf.astm_d3180_basis_factor("ad", "ar", M, A, Mad) == pytest.approx((1 - M) / (1 - Mad))
    assert sf.astm_d3180_basis_factor("d", "daf", M, A) == pytest.approx(1 / (1 - A))


def test_analyses_on_every_basis_sum_to_one():
    f = pitt()
    with pytest.raises(InputError) as e:  # no air-dried moisture for this coal
        f.ultimate("ad")
    assert one_line(e) == "moisture_ad: missing (required for the air-dried basis)"
    for b in ("ar", "d", "daf"):
        u, p = f.ultimate(b), f.proximate(b)
        assert sum(u.values()) == pytest.approx(1.0, abs=1e-12), b
        assert sum(p.values()) == pytest.approx(1.0, abs=1e-12), b
    assert f.proximate("ar")["ash"] == pytest.approx(0.0925 * (1 - 0.0165))


def test_same_fuel_from_other_bases():
    f = pitt()
    daf = f.ultimate("daf")
    g = sf.SolidFuel.from_analyses(
        ultimate=daf,
        ultimate_basis="daf",
        proximate=f.proximate("d"),
        proximate_basis="d",
        moisture_ar=0.0165,
    )
    for k in ("C", "H", "O", "N", "S", "Cl", "ash", "volatiles"):
        assert g.dry[k] == pytest.approx(f.dry[k], rel=1e-12), k
    ad = {k: v * (1 - 0.01) for k, v in f.ultimate("d").items()}
    h = sf.SolidFuel.from_analyses(
        ultimate=ad, ultimate_basis="ad", moisture_ad=0.01, moisture_ar=0.0165
    )
    assert h.dry["C"] == pytest.approx(f.dry["C"], rel=1e-12)
    assert h.ultimate("ar")["C"] == pytest.approx(f.ultimate("ar")["C"], rel=1e-12)


def test_sum_refusals_name_the_basis():
    with pytest.raises(InputError) as e:
        sf.SolidFuel.from_analyses(ultimate=PITT_ULT, proximate={**PITT_PROX, "fixed_carbon": 0.60})
    msg = one_line(e)
    assert "as-received basis: moisture + volatiles + fixed_carbon + ash" in msg
    assert "sum 1.0795 is not 1 +- 0.005" in msg
    with pytest.raises(InputError) as e:
        sf.SolidFuel.from_analyses(ultimate={**PITT_ULT, "O": 0.10}, moisture_ar=0.0165)
    assert "ultimate (dry basis: C + H + O + N + S + Cl + ash): sum 1.0337" in one_line(e)
    with pytest.raises(InputError) as e:
        sf.SolidFuel.from_analyses(
            ultimate={k: v for k, v in PITT_ULT.items() if k != "ash"},
            ultimate_basis="daf",
            proximate={"volatiles": 0.5, "fixed_carbon": 0.6},
            proximate_basis="daf",
            moisture_ar=0.05,
        )
    assert "dry ash-free basis: volatiles + fixed_carbon" in one_line(e)


def test_other_analysis_refusals():
    with pytest.raises(InputError) as e:  # ash 0.0925 dry vs 0.20 from the proximate analysis
        sf.SolidFuel.from_analyses(ultimate=PITT_ULT, proximate={**PITT_PROX, "ash": 0.20})
    assert one_line(e).startswith("proximate.ash: 0.203355 (dry basis) is not equal to")
    with pytest.raises(InputError) as e:
        sf.SolidFuel.from_analyses(ultimate={**PITT_ULT, "C": 75.5})
    assert one_line(e) == "ultimate.C: 75.5 is not a mass fraction in [0, 1] (not a percentage)"
    with pytest.raises(InputError) as e:
        sf.SolidFuel.from_analyses(ultimate=PITT_ULT, hhv=31.18e6)  # ar HHV, no moisture
    assert one_line(e) == "moisture_ar: missing (required: the as-received moisture)"
    with pytest.raises(InputError, match="ultimate: Fe is not keys among"):
        sf.SolidFuel.from_analyses(ultimate={**PITT_ULT, "Fe": 0.01})
    with pytest.raises(InputError, match="ultimate_basis: wet"):
        sf.SolidFuel.from_analyses(ultimate=PITT_ULT, ultimate_basis="wet")
    with pytest.raises(InputError, match="proximate.moisture"):
        sf.SolidFuel.from_analyses(ultimate=PITT_ULT, proximate=PITT_PROX, proximate_basis="d")
    with pytest.raises(InputError, match="has none"):
        sf.load_kiln_fuel("pocahontas_3")
    with pytest.raises(InputError, match="fuel: anthracite is not one of"):
        sf.load_kiln_fuel("anthracite")


# ------------------------------------------------------------------ heating values


def test_hhv_on_bases_and_correlations():
    f = pitt()
    assert f.hhv("ar") == pytest.approx(13404 * 2326.0)
    assert f.hhv("daf") == pytest.approx(f.hhv("d") / (1 - 0.0925))
    assert f.hhv("ar", "boie") > f.hhv("ar", "dulong") > f.hhv("ar", "channiwala_parikh")
    with pytest.raises(InputError, match="correlation: mendeleev"):
        f.hhv("ar", "mendeleev")
    no_hhv = sf.SolidFuel.from_analyses(ultimate=PITT_ULT, proximate=PITT_PROX)
    assert no_hhv.hhv("d") == pytest.approx(f.hhv("d", "channiwala_parikh"))


def test_lhv_is_hhv_less_the_latent_heat_of_the_water_formed():
    f = pitt()
    p = sf.complete_combustion(f, "air")
    water = p.flue_gas_moles["H2O"] * 0.018015  # kg per kg fuel, ar (moisture + H, Cl aside)
    hcl_h = p.flue_gas_moles["HCl"] * 0.018015 / 2  # the HCl hydrogen's water equivalent
    assert f.hhv("ar") - f.lhv("ar") == pytest.approx(sf.H_FG_25C * (water + hcl_h), rel=1e-3)


def test_channiwala_parikh_warns_outside_its_fit():
    with pytest.warns(OutOfRangeWarning, match="Channiwala"):
        sf.channiwala_parikh_hhv(0.95, 0.01, 0.0, 0.0, 0.04, 0.0)


# ------------------------------------------------------------------ combustion


OXIDISERS = [
    "air",
    "oxygen",
    {"O2": 0.30, "N2": 0.70},
    sf.oxidiser_composition("enriched_air", 0.28),
    {"O2": 0.25, "CO2": 0.55, "H2O": 0.15, "N2": 0.05},  # O2 + recirculated flue gas
]


@pytest.mark.parametrize("oxidiser", OXIDISERS, ids=["air", "O2", "O2N2", "enriched", "recirc"])
@pytest.mark.parametrize("lam", [1.0, 1.15, 2.0])
def test_elements_balance_to_1e12(oxidiser, lam):
    for name in ("pittsburgh_8", "illinois_6", "wyodak_anderson", "beulah_zap"):
        p = sf.complete_combustion(sf.load_kiln_fuel(name), oxidiser, lam)
        assert p.element_balance_error() <= 1e-12
        # and the mass: fuel (1 kg) + oxidiser = flue gas + ash
        assert 1.0 + p.oxidiser_mass == pytest.approx(p.flue_gas_mass + p.ash, rel=1e-12)
        assert p.mole_fractions()["O2"] >= 0.0


def test_stoichiometric_oxygen_matches_the_combustion():
    f = pitt()
    u = f.as_fired()
    p = sf.complete_combustion(f, "oxygen", 1.0)
    demand = sf.stoichiometric_oxygen_demand(u["C"], u["H"], u["O"], u["S"], u["Cl"])
    assert p.oxidiser_mass == pytest.approx(demand, rel=1e-12)
    assert p.flue_gas_moles["O2"] == 0.0
    air = sf.complete_combustion(f, "air", 1.2)
    assert air.oxidiser_mass == pytest.approx(
        1.2 * demand / sf.oxidiser_oxygen_mass_fraction("air"), rel=1e-12
    )
    # enrichment: less oxidiser and less flue gas per kg of fuel
    rich = sf.complete_combustion(f, {"O2": 0.30, "N2": 0.70}, 1.2)
    assert rich.flue_gas_mass < air.flue_gas_mass


def test_blend_burns_as_the_sum_of_its_fuels():
    a, b = pitt(), sf.load_kiln_fuel("beulah_zap")
    blend = sf.blend_fuels([a, b], [3.0, 1.0])
    pb = sf.complete_combustion(blend, "air", 1.1)
    pa_, pb_ = sf.complete_combustion(a, "air", 1.1), sf.complete_combustion(b, "air", 1.1)
    assert pb.oxidiser_mass == pytest.approx(
        0.75 * pa_.oxidiser_mass + 0.25 * pb_.oxidiser_mass, rel=1e-12
    )
    assert pb.element_balance_error() <= 1e-12
    with pytest.raises(InputError, match="mass_flows"):
        sf.blend_fuels([a, b], [1.0])
    with pytest.raises(InputError, match="mass_flows"):
        sf.blend_fuels([a, b], [0.0, 0.0])


def test_combustion_refusals():
    f = pitt()
    with pytest.raises(InputError) as e:  # a fuel without air
        sf.complete_combustion(f, {"N2": 0.8, "CO2": 0.2})
    assert one_line(e) == "oxidiser.O2: 0 is not > 0 (a fuel needs an oxidiser with oxygen)"
    with pytest.raises(InputError) as e:
        sf.complete_combustion(f, "air", 0.9)
    assert one_line(e).startswith("excess_ratio: 0.9 is not >= 1 (complete combustion")
    with pytest.raises(InputError, match="oxidiser \\(mole fractions\\): sum 0.9"):
        sf.complete_combustion(f, {"O2": 0.2, "N2": 0.7})
    with pytest.raises(InputError, match="oxidiser: CH4 is not species among"):
        sf.complete_combustion(f, {"O2": 0.5, "CH4": 0.5})
    with pytest.raises(InputError, match="oxidiser: plasma is not one of"):
        sf.complete_combustion(f, "plasma")
    with pytest.raises(InputError, match="with moisture and ash\\): sum 0.9"):
        sf.complete_combustion({"C": 0.9})
    with pytest.raises(InputError, match="o2_mole_fraction"):
        sf.oxidiser_composition("enriched_air", 0.15)


def test_enriched_air_keeps_the_air_ratios():
    c = sf.oxidiser_composition("enriched_air", 0.35)
    air = sf.oxidiser_composition("air")
    assert c["O2"] == pytest.approx(0.35)
    assert c["Ar"] / c["N2"] == pytest.approx(air["Ar"] / air["N2"])
    assert sum(c.values()) == pytest.approx(1.0, abs=1e-15)


# ------------------------------------------------------------------ devolatilisation


def test_kobayashi_yield_against_integration():
    T, a1, a2 = 1600.0, 0.38, 0.9
    k1, k2 = sf.kobayashi_devolatilisation_rates(T)

    def rhs(t, y):
        mc, v = y
        return [-(k1 + k2) * mc, (a1 * k1 + a2 * k2) * mc]

    sol = solve_ivp(rhs, (0, 0.2), [1.0, 0.0], rtol=1e-11, atol=1e-13, dense_output=True)
    for t in (0.01, 0.05, 0.2):
        assert sf.kobayashi_isothermal_yield(T, t, a1, a2) == pytest.approx(sol.sol(t)[1], rel=1e-8)
    # high temperature favours reaction 2: the ultimate yield rises with T
    assert sf.kobayashi_isothermal_yield(2000.0, 10.0, a1, a2) > sf.kobayashi_isothermal_yield(
        1000.0, 1e4, a1, a2
    )
    with pytest.raises(InputError, match="t: "):
        sf.kobayashi_isothermal_yield(T, -1.0, a1, a2)
    with pytest.raises(InputError, match="alpha1"):
        sf.kobayashi_isothermal_yield(T, 1.0, 38.0, a2)


def test_sfor_rate():
    k = 1e5 * math.exp(-1e5 / (sf.R_GAS * 1500.0))
    assert sf.badzioch_hawksley_devolatilisation_rate(1500.0, 0.1, 0.5, 1e5, 1e5) == pytest.approx(
        k * 0.4
    )
    with pytest.raises(InputError, match="E: -1 J/mol is not > 0"):
        sf.badzioch_hawksley_devolatilisation_rate(1500.0, 0.1, 0.5, 1e5, -1.0)


# ------------------------------------------------------------------ char


def test_char_rate_limits():
    p = 0.05 * 101325.0
    # small particle at low T: kinetic limit pi d^2 p R_k; large at high T: diffusion limit
    d, T = 5e-6, 1100.0
    kin = math.pi * d**2 * p * sf.baum_street_kinetic_rate_coefficient(T)
    assert sf.baum_street_char_oxidation_rate(d, T, T, p) == pytest.approx(kin, rel=0.01)
    d, T = 1e-2, 2200.0  # a 1 cm piece
    dif = math.pi * d**2 * p * sf.baum_street_diffusion_rate_coefficient(d, T, T)
    assert sf.baum_street_char_oxidation_rate(d, T, T, p) == pytest.approx(dif, rel=0.01)
    # OpenFOAM evaluates R_k at the carrier temperature
    a = sf.baum_street_char_oxidation_rate(50e-6, 1800.0, 1400.0, p)
    b = sf.baum_street_char_oxidation_rate(50e-6, 1800.0, 1400.0, p, kinetic_temperature="particle")
    assert b > a
    assert sf.baum_street_char_oxidation_rate(50e-6, 1500.0, 1500.0, 0.0) == 0.0
    with pytest.raises(InputError, match="kinetic_temperature"):
        sf.baum_street_char_oxidation_rate(50e-6, 1500.0, 1500.0, p, kinetic_temperature="wall")
    with pytest.raises(InputError, match="d_p: 0 m is not > 0"):
        sf.baum_street_char_oxidation_rate(0.0, 1500.0, 1500.0, p)


def test_burnout_time_scales():
    p, rho, T = 0.05 * 101325.0, 1000.0, 1500.0
    t1 = sf.baum_street_char_burnout_time(np.array([20e-6, 50e-6, 100e-6]), rho, T, p)
    assert np.all(np.diff(t1) > 0)
    # kinetic part linear in d0, diffusion part quadratic
    tk = rho * 50e-6 / (2 * p * sf.baum_street_kinetic_rate_coefficient(T))
    assert t1[1] > tk
    with pytest.raises(InputError, match="p_o2: 0 Pa is not > 0"):
        sf.baum_street_char_burnout_time(50e-6, rho, T, 0.0)
