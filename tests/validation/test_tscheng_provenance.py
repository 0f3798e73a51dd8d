"""Provenance of Tscheng's (1978) built-in cases: each number they carry comes from where their
comments say (src/rotarykiln/cases/tscheng_A16.yaml, the template; the other 43 written from the
data by docs/scripts/make_tscheng_cases.py).

These are provenance checks, not a validation of the model: they recompute or re-read the case
files' numbers from the data and the published figures they were taken or derived from.
"""

import math
from importlib import resources

import pandas as pd
import pytest
from scipy.optimize import brentq

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.heat.wall import cylinder_layer_heat_flow, shell_heat_loss
from rotarykiln.materials.gas import air_table
from rotarykiln.materials.lining import load_lining_material
from rotarykiln.studies.tscheng1978 import tscheng_case_name, tscheng_runs

# the thesis sample calculation, run A16 at z = 1.25 m (data README): the wall loses 154.4 W/m
# with the thermocouple between the cement lining and the steel shell at 369.2 K
SAMPLE_LOSS = 154.4  # W/m
SAMPLE_T_WALL = 369.2  # K
AMBIENT = 298.15  # K, the cases' ambient_temperature [assumed in the cases]
README_RADIUS = 0.09425  # m, inner radius (data README)
POSITIONS = resources.files("rotarykiln") / "data" / "tscheng1978" / "thermocouple_positions.csv"


def _case(run):
    return load_case(builtin_case_path(tscheng_case_name(run)))


def derived_insulation_thickness(r_inner, cement, steel, wool) -> float:
    """Mineral-wool thickness (m) for which the wall loses ``SAMPLE_LOSS`` with the
    cement/steel interface at ``SAMPLE_T_WALL``: steady conduction through the steel and the
    wool (k(T) by the Kirchhoff potential for the wool, the steel's k at the wool side), the
    shell (the wool's surface, its emissivity) losing to ``AMBIENT`` by natural convection and
    radiation; the library's wall functions (rotarykiln.heat.wall)."""
    air = air_table()
    r1 = r_inner + cement.thickness  # cement/steel interface: the thermocouples
    r2 = r1 + steel.thickness
    k_steel = load_lining_material(steel.material)
    k_wool = load_lining_material(wool.material)

    def loss(ts, r3):
        return float(shell_heat_loss(ts, AMBIENT, 2 * r3, k_wool.emissivity, air))

    def loss_error(t_ins):
        r3 = r2 + t_ins

        def steel_wool_interface(ts):  # the wool carries what the shell loses
            def wool_minus_shell(t):
                k_in, k_out = k_wool.conductivity_integral(t), k_wool.conductivity_integral(ts)
                return float(cylinder_layer_heat_flow(k_in, k_out, r2, r3)) - loss(ts, r3)

            return brentq(wool_minus_shell, ts, 2000.0)

        def cement_steel_interface(ts):  # minus the sample calculation's T_w
            ti = steel_wool_interface(ts)
            q = loss(ts, r3)
            return ti + q * math.log(r2 / r1) / (2 * math.pi * float(k_steel.conductivity(ti)))

        ts = brentq(
            lambda t: cement_steel_interface(t) - SAMPLE_T_WALL, AMBIENT + 1e-6, SAMPLE_T_WALL
        )
        return loss(ts, r3) - SAMPLE_LOSS

    return float(brentq(loss_error, 1e-4, 0.2))


def test_insulation_thickness_is_the_one_of_the_sample_calculation():
    """Provenance check: the mineral-wool thickness of the cases (13.77 mm) is recomputed from the
    thesis sample calculation (154.4 W/m at T_w = 369.2 K, run A16, z = 1.25 m; data README) with
    the library's wall functions and the cases' own radius, cement and steel; the file carries
    it rounded to 0.01 mm. Not a validation: it shows the number is derived, not fitted."""
    case = _case("A16")
    cement, steel, wool = case.wall.lining
    assert (cement.material, steel.material, wool.material) == (
        "refractory_cement",
        "carbon_steel",
        "mineral_wool",
    )
    derived = derived_insulation_thickness(case.kiln.diameter / 2, cement, steel, wool)
    assert derived * 1000 == pytest.approx(13.767, abs=5e-4)  # mm, as the case's comment says
    assert wool.thickness == pytest.approx(derived, abs=0.5e-5)  # 0.01 mm rounding
    assert case.wall.ambient_temperature == AMBIENT


def test_every_case_carries_its_data_row():
    """Provenance check: each of the 44 cases carries the measured inputs and profiles of its row
    of the data (speed, incline, fill, solids feed, air flow, the inlet air temperature = the gas
    reading at 2.32 m, T-g/T-s/T-w at the positions of thermocouple_positions.csv), and the
    template's kiln, sand and wall otherwise (the README's and the derived numbers)."""
    runs = tscheng_runs()
    with POSITIONS.open(encoding="utf-8") as fh:
        positions = pd.read_csv(fh)
    positions = positions.set_index("column")["z_m"]
    a16 = _case("A16")
    assert a16.kiln.diameter == pytest.approx(2 * README_RADIUS, rel=1e-12)
    for run, row in runs.iterrows():
        c = _case(run)
        assert c.name == f"Tscheng 1978 run {run}"
        assert c.operation.speed == pytest.approx(row["RPM"] * 2 * math.pi / 60, rel=1e-12)
        assert c.kiln.slope == pytest.approx(math.radians(row["Incline (degree)"]), rel=1e-12)
        assert c.bed.fill == pytest.approx(row["Solid loading (%)"] / 100, rel=1e-12)
        assert c.operation.feed == pytest.approx(row["Solid flow (kg/hr)"] / 3600, rel=1e-12)
        assert c.gas.flow == pytest.approx(row["Air flow (kg/hr)"] / 3600, rel=1e-12)
        assert c.gas.temperature == row["T-g-5"]
        m = c.measurements
        for key, prefix in (("gas", "T-g"), ("bed", "T-s"), ("wall", "T-w")):
            columns = [k for k in positions.index if k.startswith(prefix + "-")]
            assert getattr(m, f"t_{key}") == [float(row[k]) for k in columns], (run, key)
            assert getattr(m, f"z_{key}") == [float(positions[k]) for k in columns], (run, key)
        assert m.wall_interface == 1
        for section in ("kiln", "material", "wall", "closures", "solver"):
            if section == "kiln":
                assert (c.kiln.length, c.kiln.diameter) == (a16.kiln.length, a16.kiln.diameter)
            else:
                assert getattr(c, section) == getattr(a16, section), (run, section)
        assert c.gas.composition == a16.gas.composition and c.gas.mass_fractions is None
