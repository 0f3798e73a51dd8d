"""Clinker chemistry: raw meal type, moduli and practice checks, Bogue/Taylor, Lea-Parker,
database functions, reaction stoichiometry and rates; bad input refused in one line."""

import warnings

import numpy as np
import pytest

from rotarykiln.chemistry import clinker as ck
from rotarykiln.errors import InputError, OutOfRangeWarning

EX = {"CaO": 0.65, "SiO2": 0.22, "Al2O3": 0.055, "Fe2O3": 0.033, "MgO": 0.017}


def one_line(exc):
    msg = str(exc.value)
    assert "\n" not in msg
    return msg


# ------------------------------------------------------------------ RawMeal


def test_raw_meal_bases_round_trip():
    ign = ck.RawMeal(**EX, other=0.025, loi=0.35, basis="ignited")
    ar = ck.RawMeal(**ign.as_received, basis="as_received")
    for k, v in ign.ignited.items():
        assert ar.ignited[k] == pytest.approx(v, rel=1e-12)
    assert sum(ign.as_received.values()) == pytest.approx(1.0, abs=1e-12)
    assert ar.clinker_factor == pytest.approx(1 / 0.65)


@pytest.mark.parametrize(
    "basis, kwargs, words",
    [
        ("as_received", {"loi": 0.30}, "as-received basis: oxides + other + loi"),
        ("ignited", {"loi": 0.0, "other": 0.05}, "ignited, LOI-free basis: oxides + other"),
    ],
)
def test_raw_meal_sum_refused_naming_the_basis(basis, kwargs, words):
    with pytest.raises(InputError) as e:
        ck.RawMeal(**EX, basis=basis, **kwargs)
    msg = one_line(e)
    assert words in msg and "sum" in msg and "1 +- 0.005" in msg


def test_raw_meal_percentages_and_bad_fields_refused():
    with pytest.raises(InputError) as e:
        ck.RawMeal(CaO=65.0, SiO2=22.0, Al2O3=5.5, Fe2O3=3.3)
    assert one_line(e).startswith("raw_meal.CaO: 65 is not a mass fraction in [0, 1]")
    with pytest.raises(InputError) as e:
        ck.RawMeal(**EX, loi=1.0)
    assert "raw_meal.loi: 1" in one_line(e)
    with pytest.raises(InputError) as e:
        ck.RawMeal(**EX, basis="dry")
    assert one_line(e) == "raw_meal.basis: dry is not one of as_received, ignited"


def test_raw_meal_tolerance_is_a_parameter():
    ck.RawMeal(**EX, other=0.02, basis="ignited", sum_tolerance=0.006)  # sum 0.995 accepted
    with pytest.raises(InputError):
        ck.RawMeal(**EX, other=0.02, basis="ignited", sum_tolerance=0.004)


# ------------------------------------------------------------------ practice


def test_example_clinker_is_cement_practice_without_warning():
    meal = ck.RawMeal(**EX, other=0.025, basis="ignited")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        meal.check_practice("cement")


def test_outside_the_cement_envelope_refused_in_one_line():
    with pytest.raises(InputError) as e:
        ck.check_oxide_practice(0.75, 0.15, 0.055, 0.033)  # LSF 1.48
    msg = one_line(e)
    assert msg.startswith("raw_meal.LSF: 1.478 is not") and "in [0.66, 1.1] (cement practice" in msg
    with pytest.raises(InputError) as e:
        ck.check_oxide_practice(0.58, 0.16, 0.12, 0.08)  # LSF 0.90, SM 0.8
    assert one_line(e).startswith("raw_meal.SM: 0.8 is not in [1, 8]")
    with pytest.raises(InputError) as e:
        ck.check_oxide_practice(0.65, 0.22, 0.088, 0.0)  # no iron: AM infinite
    assert one_line(e).startswith("raw_meal.AM: inf is not in [0.2, 50]")


def test_typical_range_is_only_a_warning():
    with pytest.warns(OutOfRangeWarning, match="raw_meal.LSF"):
        ck.check_oxide_practice(0.675, 0.22, 0.055, 0.033)  # LSF 0.96 OK; AM/SM typical
        ck.check_oxide_practice(0.70, 0.22, 0.055, 0.033)  # LSF 0.995: warned, accepted


def test_lime_practice():
    limestone = {"CaO": 0.95, "SiO2": 0.02, "Al2O3": 0.005, "Fe2O3": 0.003, "MgO": 0.01}
    ck.check_oxide_practice(**limestone, practice="lime")
    ck.check_oxide_practice(**limestone, practice="any")
    with pytest.raises(InputError, match="raw_meal.LSF"):
        ck.check_oxide_practice(**limestone, practice="cement")
    with pytest.raises(InputError) as e:  # a cement meal is not a lime kiln feed
        ck.check_oxide_practice(**EX, practice="lime")
    assert "(lime practice" in one_line(e)
    with pytest.raises(InputError) as e:  # clay: neither
        ck.check_oxide_practice(0.05, 0.60, 0.20, 0.08, practice="any")
    assert "cement practice" in one_line(e)
    with pytest.raises(InputError, match="practice: glass"):
        ck.check_oxide_practice(**EX, practice="glass")


# ------------------------------------------------------------------ moduli and Bogue


def test_lsf_definitions_and_so3_correction():
    a = (0.65, 0.22, 0.055, 0.033)
    assert ck.lime_saturation_factor(*a) == pytest.approx(
        0.65 / (2.8 * 0.22 + 1.2 * 0.055 + 0.65 * 0.033)
    )
    so3 = ck.lime_saturation_factor(*a, SO3=0.01)
    assert so3 == pytest.approx(
        (0.65 - 0.70046 * 0.01) / (2.8 * 0.22 + 1.2 * 0.055 + 0.65 * 0.033), rel=1e-4
    )
    arr = ck.lime_saturation_factor(
        np.array([0.65, 0.66]), 0.22, 0.055, np.array([0.033, 0.1]), definition="lea_parker"
    )
    assert arr.shape == (2,)
    with pytest.raises(InputError, match="definition: bs"):
        ck.lime_saturation_factor(*a, definition="bs")


def test_lea_parker_lsf_of_one_means_no_belite():
    # at LSF(Lea-Parker) = 1 the Bogue C2S is zero, on both sides of A/F = 0.64
    for A, F in ((0.055, 0.033), (0.03, 0.06)):
        S = 0.22
        cS, cA, cF = ck.lea_parker_lsf_coefficients(A / F)
        C = cS * S + cA * A + cF * F
        assert ck.bogue_phase_composition(C, S, A, F)["C2S"] == pytest.approx(0.0, abs=1e-12)


def test_bogue_closure_for_random_clinkers():
    rng = np.random.default_rng(3)
    for _ in range(50):
        C, S, A, F = rng.uniform([0.55, 0.15, 0.02, 0.01], [0.70, 0.26, 0.08, 0.07])
        so3, fl = rng.uniform(0, 0.03), rng.uniform(0, 0.02)
        p = ck.bogue_phase_composition(C, S, A, F, SO3=so3, free_lime=fl)
        phases = p["C3S"] + p["C2S"] + p["C3A"] + p["C4AF"] + p["C2F"]
        assert phases + p["CaO_free"] == pytest.approx(C - 0.70046 * so3 + S + A + F, abs=2e-6)


def test_bogue_sets_meet_at_the_c4af_ratio():
    r = ck.molar_mass("Al2O3") / ck.molar_mass("Fe2O3")
    F = 0.05
    hi = ck.bogue_phase_composition(0.65, 0.22, r * F * (1 + 1e-12), F)
    lo = ck.bogue_phase_composition(0.65, 0.22, r * F * (1 - 1e-12), F)
    for k in ("C3S", "C2S", "C4AF"):
        assert hi[k] == pytest.approx(lo[k], abs=1e-9)
    assert hi["C3A"] == pytest.approx(0.0, abs=1e-9) and lo["C2F"] == pytest.approx(0.0, abs=1e-9)


def test_bogue_bad_input():
    with pytest.raises(InputError) as e:
        ck.bogue_phase_composition(0.65, 0.22, 0.055, 0.0)
    assert one_line(e).startswith("Fe2O3: 0 is not > 0")
    with pytest.raises(InputError, match="SiO2: 22 is not a mass fraction"):
        ck.bogue_phase_composition(0.65, 22.0, 0.055, 0.033)


def test_raw_meal_bogue_uses_the_ignited_basis():
    ar = ck.RawMeal(**{k: v * 0.65 for k, v in EX.items()}, other=0.025 * 0.65, loi=0.35)
    assert ar.bogue()["C3S"] == pytest.approx(
        ck.bogue_phase_composition(0.65, 0.22, 0.055, 0.033)["C3S"]
    )
    assert ar.moduli()["AM"] == pytest.approx(0.055 / 0.033)


# ------------------------------------------------------------------ Taylor


def test_taylor_recovers_a_clinker_made_of_its_phases():
    t = ck.taylor_phase_table()
    w = {"alite": 0.6, "belite": 0.2, "aluminate": 0.08, "ferrite": 0.12}
    bulk = sum(w[p] * t[p] for p in w)
    got = ck.taylor_phase_composition(dict(zip(t["oxides"], bulk, strict=True)))
    for p in w:
        assert got[p] == pytest.approx(w[p], abs=1e-12)


def test_taylor_gives_more_alite_than_bogue_for_the_example():
    # Taylor (1989): the Bogue calculation underestimates alite (substituted phases)
    tay = ck.taylor_phase_composition(EX)
    bog = ck.bogue_phase_composition(0.65, 0.22, 0.055, 0.033)
    assert tay["alite"] > bog["C3S"]


def test_taylor_bad_input():
    with pytest.raises(InputError) as e:
        ck.taylor_phase_composition({"CaO": 0.65, "LOI": 0.01})
    assert one_line(e).startswith("oxides: LOI is not one of CaO, SiO2")


# ------------------------------------------------------------------ Lea-Parker


def test_lea_parker_1338_branches_and_bad_temperature():
    # A/F >= 1.38: 6.1 F; below: 8.2 A - 5.22 F
    assert ck.lea_parker_liquid_fraction(0.06, 0.04, T=1611.15) == pytest.approx(6.1 * 0.04)
    assert ck.lea_parker_liquid_fraction(0.05, 0.04, T=1611.15) == pytest.approx(
        8.2 * 0.05 - 5.22 * 0.04
    )
    assert ck.lea_parker_liquid_fraction(0.055, 0.033, 0.04, mgo_max=0.02) == pytest.approx(
        3 * 0.055 + 2.25 * 0.033 + 0.02
    )
    with pytest.raises(InputError) as e:
        ck.lea_parker_liquid_fraction(0.055, 0.033, T=1700.0)
    assert (
        one_line(e) == "T: 1700 K is not one of 1611.15, 1673.15, 1723.15 K (1338, 1400, 1450 degC)"
    )
    with pytest.raises(InputError, match="Al2O3"):
        ck.lea_parker_liquid_fraction(5.5, 0.033)


def test_liquid_curve():
    args = (0.055, 0.033, 0.017)
    T = np.array([1500.0, 1611.0, 1611.15, 1673.15, 1723.15, 1800.0])
    L = ck.lea_parker_liquid_curve(T, *args)
    assert L[0] == 0.0 and L[1] == 0.0
    assert L[2] == pytest.approx(ck.lea_parker_liquid_fraction(*args, T=1611.15))
    assert L[3] == pytest.approx(ck.lea_parker_liquid_fraction(*args, T=1673.15))
    assert L[4] == L[5] == pytest.approx(ck.lea_parker_liquid_fraction(*args))


# ------------------------------------------------------------------ database


@pytest.mark.parametrize(
    "phase, source, T",
    [
        ("C3S", "NIST", 1200.0),
        ("CaCO3", "HP2011", 900.0),
        ("MgO", "NASA_GLENN", 1500.0),
        ("C2S_alphaprime", "NIST", 1300.0),
    ],
)
def test_database_functions_are_consistent(phase, source, T):
    # dH/dT = c_p, dS/dT = c_p/T, G = H - TS (central differences)
    h = 1e-3
    dH = (
        ck.simcem_phase_enthalpy(phase, T + h, source)
        - ck.simcem_phase_enthalpy(phase, T - h, source)
    ) / (2 * h)
    dS = (
        ck.simcem_phase_entropy(phase, T + h, source)
        - ck.simcem_phase_entropy(phase, T - h, source)
    ) / (2 * h)
    cp = ck.simcem_phase_cp(phase, T, source)
    assert dH == pytest.approx(cp, rel=1e-6)
    assert dS == pytest.approx(cp / T, rel=1e-6)
    G = ck.simcem_phase_gibbs(phase, T, source)
    assert G == pytest.approx(
        ck.simcem_phase_enthalpy(phase, T, source) - T * ck.simcem_phase_entropy(phase, T, source)
    )


def test_database_bad_input_and_range_warning():
    with pytest.raises(InputError) as e:
        ck.simcem_phase_cp("CaO", 1000.0)
    assert one_line(e) == "CaO.source: not given is not one of NIST, HP2011 (several exist)"
    with pytest.raises(InputError, match="phase: C5S is not one of"):
        ck.simcem_phase_cp("C5S", 1000.0)
    with pytest.raises(InputError, match="source: JANAF"):
        ck.simcem_phase_cp("C3S", 1000.0, "JANAF")
    with pytest.raises(InputError, match="T: -5 K is not > 0"):
        ck.simcem_phase_cp("C3S", -5.0)
    with pytest.warns(OutOfRangeWarning, match="C3S"):
        ck.simcem_phase_cp("C3S", 2500.0)
    with warnings.catch_warnings():  # T0 of a NASA entry is below its fit range: no warning
        warnings.simplefilter("error")
        ck.simcem_phase_enthalpy("CaCO3", 298.15, "NASA_GLENN")
    with pytest.raises(InputError, match="reaction: melting"):
        ck.simcem_reaction_enthalpy("melting", 1000.0)


def test_custom_reaction_mapping():
    r = {"CaO/NIST": -2, "quartz_alpha/NIST": -1, "C2S_beta/NIST": 1}
    assert ck.simcem_reaction_enthalpy(r, 298.15) == ck.simcem_reaction_enthalpy(
        "belite_beta", 298.15
    )


def test_theoretical_heat_refuses_a_composition_outside_bogue():
    with pytest.raises(InputError) as e:
        ck.theoretical_heat_of_clinker_formation(0.75, 0.18, 0.05, 0.03)  # C2S < 0
    assert one_line(e).startswith("bogue.C2S: -")
    with pytest.raises(InputError, match="carbonate_source: JANAF"):
        ck.theoretical_heat_of_clinker_formation(**EX, carbonate_source="JANAF")


def test_theoretical_heat_grows_with_lime():
    # more CaCO3 to decompose per kg of clinker: more heat
    q1 = ck.theoretical_heat_of_clinker_formation(0.64, 0.22, 0.055, 0.033)
    q2 = ck.theoretical_heat_of_clinker_formation(0.66, 0.22, 0.055, 0.033)
    assert q2 > q1


# ------------------------------------------------------------------ reactions and rates


def test_reaction_stoichiometry_conserves_mass():
    names, species, nu = ck.clinker_reaction_stoichiometry()
    assert names == ("calcination", "belite", "alite", "aluminate", "ferrite")
    assert np.abs(nu.sum(axis=1)).max() < 1e-15
    i = names.index("belite")
    assert -nu[i, species.index("CaO")] / nu[i, species.index("C2S")] == pytest.approx(
        2 * 56.077 / 172.237, rel=1e-5
    )


def test_mastorakos_rate_orders_and_arrhenius():
    k0, E = np.ones(5), np.full(5, 2e5)
    rho = {"CaCO3": 100.0, "CaO": 50.0, "SiO2": 20.0, "C2S": 30.0, "Al2O3": 5.0, "Fe2O3": 3.0}
    r = ck.mastorakos_clinker_rates(1600.0, rho, k0, E)
    r2 = ck.mastorakos_clinker_rates(1600.0, {**rho, "CaO": 100.0}, k0, E)
    assert r2 / r == pytest.approx([1, 4, 2, 8, 16])
    rT = ck.mastorakos_clinker_rates(1700.0, rho, k0, E)
    assert rT / r == pytest.approx(np.full(5, np.exp(-2e5 / ck.R_GAS * (1 / 1700 - 1 / 1600))))
    # production rates conserve mass
    _, _, nu = ck.clinker_reaction_stoichiometry()
    assert abs((r @ nu).sum()) < 1e-12 * np.abs(r @ nu).max()


def test_mastorakos_bad_input():
    with pytest.raises(InputError, match="rho: C3A is not one of"):
        ck.mastorakos_clinker_rates(1500.0, {"C3A": 1.0}, np.ones(5), np.ones(5))
    with pytest.raises(InputError, match="rho.CaO: -1 kg/m3 is not >= 0"):
        ck.mastorakos_clinker_rates(1500.0, {"CaO": -1.0}, np.ones(5), np.ones(5))
    with pytest.raises(InputError, match="5 values each"):
        ck.mastorakos_clinker_rates(1500.0, {}, np.ones(4), np.ones(5))
    p = ck.mastorakos_recalled_parameters()
    assert p["E"].shape == (5,) and p["k0_order"].shape == (5,)
