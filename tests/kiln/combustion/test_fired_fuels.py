"""Solid and liquid fuels in the burner (issue 26): products by elements, heat, ash into the bed.

Checked against what does not come from the code under test: the O2 demand formula of the
reference note (cement_lime.md 5.7: 2.664 C + 7.937 H + 0.998 S - O kg per kg), the products
of :func:`rotarykiln.chemistry.solid_fuels.complete_combustion` (a separate implementation),
Cantera's flame of the same fuel given as a gas, the heavy fuel oil LHV range (5.6 [SEEN:
HFO]); and the kiln's own element and energy closures with several fuels and the ash in the
bed.
"""

import dataclasses
import warnings

import numpy as np
import pytest
import yaml

from rotarykiln.case import parse_case
from rotarykiln.chemistry.solid_fuels import SolidFuel, complete_combustion, load_kiln_fuel
from rotarykiln.errors import InputError
from rotarykiln.kiln.combustion.fired_fuels import FiredFuel, burn_fired_fuels, particle_release
from rotarykiln.kiln.combustion.flame import AirStream, Burner, fire
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.residual import KilnResidual
from rotarykiln.kiln.steady.solve import solve_kiln
from rotarykiln.materials.gas import burn_fuel

pytestmark = pytest.mark.filterwarnings("ignore::rotarykiln.errors.OutOfRangeWarning")

#: A fuel-grade petroleum coke (cement_lime.md 5.6: S 4-7 %, ash < 1 %, VM 5-16 %), dry basis.
PETCOKE = dict(C=0.885, H=0.037, N=0.015, S=0.05, O=0.008, ash=0.005)
#: A heavy fuel oil inside the crude ranges of cement_lime.md 5.6 [SEEN: ATN].
FUEL_OIL = dict(C=0.86, H=0.115, S=0.02, N=0.003, O=0.002, ash=0.0)


def _petcoke():
    return SolidFuel.from_analyses(
        ultimate=PETCOKE,
        ultimate_basis="d",
        proximate={"moisture": 0.06, "volatiles": 0.10},
        proximate_basis="ar",
        name="petcoke",
    )


def _oil():
    return SolidFuel.from_analyses(ultimate=FUEL_OIL, ultimate_basis="d", moisture_ar=0.0)


def test_o2_demand_and_products_of_a_coal_by_hand_and_by_the_fuel_library():
    coal = load_kiln_fuel("pittsburgh_8")
    a = coal.as_fired()
    demand = 2.664 * a["C"] + 7.937 * a["H"] + 0.998 * a["S"] - a["O"]  # kg O2 / kg, note 5.7
    air = 1.2 * demand / 0.2314  # 20 % excess, dry air's O2 mass fraction (note 5.7)
    b = Burner("CH4:1", 0.0, AirStream(air), fired=(FiredFuel(coal, 1.0),))
    products, lhv, hhv, o2, ash = burn_fired_fuels(b)
    assert o2 * 0.031998 == pytest.approx(demand, rel=2e-3)  # the note's rounded factors
    ref = complete_combustion(a, excess_ratio=1.2).mole_fractions()
    x = dict(products.composition)
    for species, ours in (("CO2", "CO2"), ("H2O", "H2O"), ("SO2", "SO2"), ("O2", "O2")):
        assert x[ours] == pytest.approx(ref[species], rel=5e-3), species
    assert ash == pytest.approx(a["ash"] + a["Cl"], rel=1e-12)
    assert lhv == pytest.approx(coal.lhv("ar"), rel=1e-12)
    # the products hold the fuel's and the air's mass but the ash
    assert products.mass_flow == pytest.approx(1.0 + air - ash, rel=1e-12)


def test_a_fuel_given_by_its_analysis_burns_as_cantera_burns_the_same_gas():
    """Methane as a 'liquid fuel' (C 74.87, H 25.13 %, its HHV): the adiabatic temperature of
    its products equals Cantera's for CH4 burnt with the same air (the products' tables are
    the same species; Cantera's 1200 K equilibrium keeps traces of NO and CO)."""
    m_ch4 = 0.016043
    c, h = 0.012011 / m_ch4, 4 * 0.001008 / m_ch4
    hhv = 55.50e6  # J/kg, CH4 HHV (Cantera's is recomputed below)
    from rotarykiln.materials.gas import fuel_data

    _, _, lhv_ct, hhv_ct = fuel_data((("CH4", 1.0),))
    fuel = SolidFuel.from_analyses(
        ultimate={"C": c, "H": h, "N": 0.0, "S": 0.0, "ash": 0.0},
        ultimate_basis="d",
        moisture_ar=0.0,
        hhv=hhv_ct,
        hhv_basis="d",
        sum_tolerance=2e-3,
    )
    air = 1e-3 * 17.2 * 1.15
    b = Burner("CH4:1", 0.0, AirStream(air, 600.0), fired=(FiredFuel(fuel, 1e-3, "liquid"),))
    products, lhv, *_ = burn_fired_fuels(b)
    ref = burn_fuel("CH4:1", 1e-3, air, 298.15, 600.0)
    assert lhv / 1e-3 == pytest.approx(lhv_ct, rel=3e-3)  # Channiwala's LHV from the HHV
    assert products.adiabatic_temperature == pytest.approx(ref.adiabatic_temperature, abs=8.0)
    assert hhv == pytest.approx(hhv_ct, rel=2e-3)


def test_fuel_oil_lhv_in_the_heavy_fuel_oil_range():
    """Channiwala-Parikh on an oil inside the crude ranges: 40-42 MJ/kg (note 5.6, HFO)."""
    assert 40e6 <= _oil().lhv("ar") <= 42e6


def test_too_little_air_for_a_solid_fuel_is_refused_with_the_air_ratio():
    coal = FiredFuel(load_kiln_fuel("pittsburgh_8"), 1.0)
    with pytest.raises(InputError, match="air ratio 0.8"):
        burn_fired_fuels(Burner("CH4:1", 0.0, AirStream(8.4), fired=(coal,)))


CASE = """
name: fired_fuels_test
description: the limestone kiln fired with solid and liquid fuels (test)
kiln: {length: 5.5 m, diameter: 0.406 m, slope: 0.03 m/m}
operation: {speed: 1.5 rpm, feed: 42 kg/h, feed_temperature: 298.15 K}
material:
  name: limestone
  bulk_density: 1680 kg/m3
  composition: {CaCO3: 1.0}
  specific_heat: 1040 J/kg/K
  thermal_conductivity: 0.69 W/m/K
  emissivity: 0.95
bed: {residence_time: 5400 s, axial_dispersion: plug}
gas: {emissivity_a: 0.85, emissivity_b_per_K: -0.0005, emissivity_minimum: 0.05}
wall: {U: 7 W/m2/K, ambient_temperature: 298 K, emissivity: 0.95}
closures: {preset: seed004}
chemistry: {reactions: [calcination_luisser]}
solver: {cells: 30}
"""


def _case(burner: dict):
    d = yaml.safe_load(CASE)
    d["burner"] = burner
    return parse_case(d)


BURNERS = {
    "coal, particles": {
        "solid_fuels": [
            {
                "library": "pittsburgh_8",
                "flow": "4.2 kg/h",
                "fineness": {"residue": "12 %", "sieve": "90 um"},
            }
        ],
        "primary_air": {"flow": "10 Nm3/h"},
        "secondary_air": {"flow": "35 Nm3/h"},
        "combustion": "particles",
    },
    "coal + petcoke + oil + gas, burnout": {
        "fuel": "CH4:1",
        "fuel_flow": "1 Nm3/h",
        "solid_fuels": [
            {"library": "illinois_6", "flow": "1.5 kg/h"},
            {
                "name": "petcoke",
                "ultimate": PETCOKE,
                "ultimate_basis": "d",
                "proximate": {"moisture": "6 %", "volatiles": "10 %", "ash": "0.47 %"},
                "flow": "1 kg/h",
            },
        ],
        "liquid_fuels": [
            {
                "name": "oil",
                "ultimate": FUEL_OIL,
                "ultimate_basis": "d",
                "moisture": 0,
                "flow": "0.8 kg/h",
                "specific_heat": "2 kJ/kg/K",
            }
        ],
        "fuel_temperature": "400 K",
        "primary_air": {"flow": "10 Nm3/h"},
        "secondary_air": {"flow": "45 Nm3/h", "temperature": "600 K"},
        "combustion": "burnout",
        "flame_length": "2.5 m",
    },
    "lignite, instant": {
        "solid_fuels": [{"library": "beulah_zap", "flow": "6 kg/h"}],
        "primary_air": {"flow": "10 Nm3/h"},
        "secondary_air": {"flow": "35 Nm3/h"},
    },
}


#: The coal's particles burnt as their jet entrains the secondary air (a 12 mm nozzle).
BURNERS["coal, particles, nozzle"] = dict(BURNERS["coal, particles"], nozzle_diameter="12 mm")


@pytest.mark.parametrize("which", list(BURNERS))
def test_kiln_fired_with_solid_and_liquid_fuels_closes_its_balances_with_the_ash_in_the_bed(
    which,
):
    kiln, cells = kiln_from_case(_case(BURNERS[which]))
    flame = kiln.firing.flame
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sol = solve_kiln(kiln, cells)
    assert max(sol.element_closure.values()) <= 1e-8
    assert abs(sol.energy_closure) <= 1e-6
    # the ash of every fuel leaves with the product, and nothing else of the fuels does
    assert sol.bed_flows["ash"][-1] == pytest.approx(flame.ash_flow, rel=1e-12)
    assert sol.bed_flows["ash"][0] == 0.0
    assert flame.ash_flow == pytest.approx(sum(f.ash_flow for f in flame.burner.fired), rel=1e-15)
    # the sulphur leaves as SO2 in the exhaust: all the fuels' sulphur
    s_in = sum(f.flow * f.as_fired["S"] for f in flame.burner.fired) / 0.03206
    s_out = sol.gas_flows["SO2"][0] / 0.064058
    assert s_out == pytest.approx(s_in, rel=1e-9)
    # the fuels' heat is all released in the kiln
    assert sol.heat_release == pytest.approx(flame.heat_release, rel=1e-9)
    assert sol.energy_sheet["fuel_lhv_input_W"] == pytest.approx(flame.fuel_lhv, rel=1e-12)


def test_particles_model_reports_the_burnout_and_refuses_a_grind_that_does_not_burn_out():
    kiln, _ = kiln_from_case(_case(BURNERS["coal, particles"]))
    summary = kiln.firing.flame.summary()
    assert summary["burnout_solid_fuels[0]"] >= 0.999
    coarse = dict(BURNERS["coal, particles"])
    coarse["solid_fuels"] = [
        {"library": "pittsburgh_8", "flow": "4.2 kg/h", "fineness": {"x_prime": "3 mm", "n": 1.1}}
    ]
    with pytest.raises(InputError, match=r"solid_fuels\[0\].fineness.*burn-out") as refused:
        kiln_from_case(_case(coarse))
    # the message names the O2 the char burns in (the products'), the other way to burn it out
    x_o2 = dict(kiln.firing.flame.products.composition)["O2"]
    assert f"here {100.0 * x_o2:.2g} mol%" in str(refused.value)


def test_particles_model_reports_where_its_heat_is_released():
    # the distances within which 90 % and 99 % of the heat is released: where the
    # cumulative release table crosses those shares; a coarser grind burns out further on
    kiln, _ = kiln_from_case(_case(BURNERS["coal, particles"]))
    flame = kiln.firing.flame
    x, cumulative = (np.asarray(v) for v in flame.release_table)
    summary = flame.summary()
    for share in (0.9, 0.99):
        d = summary[f"heat_released_{round(100 * share)}pct_m"]
        assert d == flame.release_distance(share)
        assert np.interp(d, x, cumulative) == pytest.approx(share, abs=1e-9)
        assert 0.0 < d < x[-1]
    assert flame.release_distance(0.9) < flame.release_distance(0.99)
    coarser = dict(BURNERS["coal, particles"])
    coarser["solid_fuels"] = [
        dict(coarser["solid_fuels"][0], fineness={"x_prime": "150 um", "n": 1.1})
    ]
    kiln_c, _ = kiln_from_case(_case(coarser))
    assert kiln_c.firing.flame.release_distance(0.99) > flame.release_distance(0.99)
    with pytest.raises(InputError, match="share"):
        flame.release_distance(1.5)
    instant, _ = kiln_from_case(_case(BURNERS["lignite, instant"]))
    assert instant.firing.flame.release_distance(0.9) is None
    assert "heat_released_90pct_m" not in instant.firing.flame.summary()


def test_a_nozzle_lengthens_the_particle_flame_to_the_air_its_jet_entrains():
    # Thring-Newby / Ricou-Spalding by hand: the primary air carries the coal through the
    # nozzle; the heat released by x is at most the share of the coal's O2 demand that the
    # primary air and the secondary air entrained by x hold (flames.md section 2)
    R, p_atm = 8.314462618, 101325.0
    burner = BURNERS["coal, particles, nozzle"]
    kiln, _ = kiln_from_case(_case(burner))
    flame = kiln.firing.flame
    m_air = 1.2925 / 3600.0  # kg/s per Nm3/h of air (0 degC, 1 atm)
    prim, sec, coal = 10.0 * m_air, 35.0 * m_air, 4.2 / 3600.0
    mm_air = 0.0289639
    d0 = 0.012
    u0 = prim / mm_air * R * 298.15 / p_atm / (np.pi * d0**2 / 4.0)
    m0 = prim + coal
    rho_a = p_atm * mm_air / (R * 298.15)
    de = 2.0 * m0 / np.sqrt(np.pi * rho_a * m0 * u0)
    assert flame.nozzle_velocity == pytest.approx(u0, rel=2e-3)
    assert flame.equivalent_diameter == pytest.approx(de, rel=2e-3)
    x_s = de * (m0 + sec) / (0.32 * m0)
    assert flame.entrainment_length == pytest.approx(x_s, rel=2e-3)
    x, cumulative = (np.asarray(v) for v in flame.release_table)
    o2_need = flame.o2_demand
    o2_p, o2_s = 0.2095 * prim / mm_air, 0.2095 * sec / mm_air
    taken = np.clip((0.32 * x / de - 1.0) * m0 / sec, 0.0, 1.0)
    share = np.minimum((o2_p + o2_s * taken) / o2_need, 1.0)
    assert np.all(cumulative <= share * (1.0 + 1e-9) + 1e-12)
    # a share of the heat is released where both the particles (burning alone, in mixed O2)
    # and the jet's O2 have reached it: the later of the two distances
    free = kiln_from_case(_case(BURNERS["coal, particles"]))[0].firing.flame
    for q in (0.9, 0.99):
        x_mix = de / 0.32 * (1.0 + (q * o2_need - o2_p) / o2_s * sec / m0)
        expected = max(x_mix, free.release_distance(q))
        assert flame.release_distance(q) == pytest.approx(expected, abs=x[1] - x[0])
    # here the mixing sets the flame: 90 % of the heat 3 times further than the particles alone
    assert flame.release_distance(0.9) > 3.0 * free.release_distance(0.9)
    wider, _ = kiln_from_case(_case(dict(burner, nozzle_diameter="25 mm")))
    assert wider.firing.flame.release_distance(0.9) > flame.release_distance(0.9)
    summary = flame.summary()
    assert summary["entrainment_length_m"] == flame.entrainment_length
    # a jet that does not take in the O2 within the kiln leaves fuel unburnt: refused (here
    # one entraining 160 times less than Ricou-Spalding's)
    slow = dataclasses.replace(flame.burner, entrainment=0.002)
    with pytest.raises(InputError, match=r"burner.nozzle_diameter: 0.012 m .*jet takes in the O2"):
        particle_release(dataclasses.replace(flame, burner=slow), 0.406, 5.5)


def test_a_sooting_coal_flame_radiates_over_the_length_its_particles_burn():
    # soot given as a volume fraction: with the particles model the luminous zone is where the
    # coal releases 99 % of its heat, from the burner (the gas inlet end of this
    # counter-current kiln), with the jet's entrainment setting that length here
    burner = dict(BURNERS["coal, particles, nozzle"], soot_volume_fraction=1e-7)
    kiln, cells = kiln_from_case(_case(burner))
    length = kiln.drum.length
    d99 = kiln.firing.flame.release_distance(0.99)
    assert kiln.firing.soot == pytest.approx((1e-7, length - d99, length))
    plain, _ = kiln_from_case(_case(BURNERS["coal, particles, nozzle"]))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sol, sol_plain = solve_kiln(kiln, cells), solve_kiln(plain, cells)
    assert abs(sol.energy_closure) <= 1e-6
    # the sooty gas radiates more where it burns: the wall there gets hotter
    zone = sol.z >= length - d99
    assert zone.any()
    assert np.max(sol.t_wall[zone] - sol_plain.t_wall[zone]) > 0.0
    assert kiln_from_case(_case(BURNERS["lignite, instant"]))[0].firing.soot is None
    with pytest.raises(InputError, match="soot_volume_fraction"):
        kiln_from_case(_case(dict(BURNERS["lignite, instant"], soot_volume_fraction=1e-7)))


@pytest.mark.parametrize(
    "fuel, message",
    [
        (
            {
                "ultimate": {"C": 0.9, "H": 0.1, "N": 0.01, "S": 0.01, "O": 0.0, "ash": 0.1},
                "flow": "1 kg/h",
            },
            "dry basis.*sum 1.12",
        ),
        ({"library": "coal_x", "flow": "1 kg/h"}, "coal_x"),
        (
            {
                "library": "pittsburgh_8",
                "flow": "1 kg/h",
                "fineness": {"residue": "150 %", "sieve": "90 um"},
            },
            "residue",
        ),
        ({"library": "pittsburgh_8", "flow": "0 kg/h"}, "flow"),
    ],
)
def test_bad_fuel_inputs_are_refused_in_one_line(fuel, message):
    burner = {"solid_fuels": [fuel], "primary_air": {"flow": "20 Nm3/h"}}
    with pytest.raises(InputError, match=message) as err:
        _case(burner)
    text = str(err.value)
    assert "\n" not in text.strip() and text.startswith("burner.solid_fuels"), text


def test_a_solid_fuel_without_air_is_refused():
    with pytest.raises(InputError, match="air"):
        _case({"solid_fuels": [{"library": "pittsburgh_8", "flow": "1 kg/h"}]})


def test_a_gas_fired_burner_has_no_ash_and_no_so2():
    """A gas-fired burner is untouched by the fired-fuel path."""
    b = Burner("CH4:1", 1e-3, AirStream(1e-3 * 17.2 * 1.1))
    f = fire(b, 0.4)
    assert f.ash_flow == 0.0 and "SO2" not in dict(f.products.composition)


def test_burning_particles_radiate_from_the_burner_until_they_burn_out():
    # kappa at the burner by hand: every size class's combustible (the dry ash-free fuel at
    # the coal density: its feed size x daf^(1/3)), N_i = m_i / m0_i particles a second in the
    # products' volume flow at the flame's adiabatic temperature
    from rotarykiln.chemistry.fuel_burnout import load_burnout_parameters
    from rotarykiln.chemistry.species import default_species

    case = _case(BURNERS["coal, particles"])
    kiln, cells = kiln_from_case(case)
    flame = kiln.firing.flame
    coal = flame.burner.fired[0]
    d, w = np.asarray(coal.size.sizes), np.asarray(coal.size.mass_fractions)
    m0 = load_burnout_parameters().coal_density * np.pi * d**3 / 6.0
    p = flame.products
    mm = sum(x * default_species()[s].molar_mass for s, x in p.composition)
    volume_flow = p.mass_flow / (101325.0 * mm / (8.314462618 * flame.adiabatic_temperature))
    u_ar = coal.fuel.ultimate("ar")
    d_burning = d * np.cbrt(1.0 - u_ar["moisture"] - u_ar["ash"])
    kappa0 = np.sum(coal.flow * w / m0 / volume_flow * np.pi * d_burning**2 / 4.0)
    assert flame.particle_absorption[0] == pytest.approx(kappa0, rel=1e-9)
    assert flame.particle_absorption[-1] == 0.0  # burnt out before the kiln's end
    # in the kiln: the burner is at the discharge (counter-current), the cells average kappa
    z, kappa = kiln.firing.particles
    assert z[0] == 0.0 and z[-1] == pytest.approx(case.kiln.length)
    assert kappa[-1] == pytest.approx(kappa0, rel=1e-9)
    kp = KilnResidual(kiln, cells).exchange.particle_kappa
    assert kp[-1] > 0.0 and kp[0] == 0.0
    dz = case.kiln.length / cells
    integral = np.sum(0.5 * (np.asarray(kappa[1:]) + kappa[:-1]) * np.diff(z))
    assert np.sum(kp * dz) == pytest.approx(integral, rel=1e-9)
    # switched off: no cloud; on, the flame gas loses its heat sooner (a lower peak)
    off = _case(dict(BURNERS["coal, particles"], particle_radiation=False))
    kiln_off, _ = kiln_from_case(off)
    assert kiln_off.firing.particles is None
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        on_sol, off_sol = solve_kiln(kiln, cells), solve_kiln(kiln_off, cells)
    assert abs(on_sol.energy_closure) <= 1e-6 and abs(off_sol.energy_closure) <= 1e-6
    assert np.max(on_sol.t_gas_nodes) < np.max(off_sol.t_gas_nodes)
