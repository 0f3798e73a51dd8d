"""A kiln whose species and reaction come from the user's own YAML (issue 11, user species)."""

import numpy as np
import pytest

from rotarykiln.chemistry.biomass import mechanism_from_files
from rotarykiln.errors import InputError
from rotarykiln.kiln.inputs import Bed, Chemistry, Closures, Drum, Feed, GasInlet, Kiln
from rotarykiln.kiln.steady.solve import solve_kiln

pytestmark = pytest.mark.filterwarnings("ignore::rotarykiln.errors.OutOfRangeWarning")

# An illustrative polymer cracking to a user gas (ethylene, GRI-Mech 3.0 NASA polynomials under
# another name): the machinery is tested, not the kinetics.
USER_YAML = """
species:
  bed:
    polymer:
      elements: {C: 2, H: 4}
      cp: {polynomial: {T_range: [250, 1000], coefficients: [1200.0, 2.0]}}
      description: polyethylene-like repeat unit
  gas:
    C2H4_user:
      elements: {C: 2, H: 4}
      h_f: 52.5 kJ/mol
      cp:
        nasa7:
          T_range: [200.0, 1000.0, 3500.0]
          coefficients:
            - [3.95920148, -7.57052247e-3, 5.70990292e-5, -6.91588753e-8, 2.69884373e-11]
            - [2.03611116, 1.46454151e-2, -6.71077915e-6, 1.47222923e-9, -1.25706061e-13]
reactions:
  - name: polymer_cracking
    stoichiometry: {polymer: -1, C2H4_user: 1}
    basis: polymer
    rate: {law: arrhenius, A: 1.0e14, E: 220000.0}
    heat: 1.0 MJ/kg
"""


def _kiln(mech):
    return Kiln(
        drum=Drum(length=4.0, radius=0.25, omega=0.2),
        bed=Bed(
            fill=0.08,
            velocity=4.0 / 1800.0,
            bulk_density=500.0,
            conductivity=0.2,
            emissivity=0.9,
            particle_diameter=0.005,
        ),
        feed=Feed({"polymer": 0.01}, 298.15),
        gas=GasInlet({"N2": 0.05}, 1000.0, counter_current=True),
        chemistry=Chemistry(mech),
        closures=Closures(),
    )


def test_user_species_and_reaction_run_in_the_kiln(tmp_path):
    f = tmp_path / "polymer.yaml"
    f.write_text(USER_YAML, encoding="utf-8")
    mech = mechanism_from_files(files=[f])
    assert mech.names == ("polymer_cracking",)
    sol = solve_kiln(_kiln(mech), 40)
    assert abs(sol.energy_closure) < 1e-6
    assert max(sol.element_closure.values()) < 1e-8
    made = sol.gas_flows["C2H4_user"][0]  # counter-current: the gas leaves at z = 0
    lost = sol.bed_flows["polymer"][0] - sol.bed_flows["polymer"][-1]
    assert made == pytest.approx(lost, rel=1e-9)
    assert lost > 0.01 * 0.01  # it reacts (about 5 % here)
    # the bed carries the polymer's own c_p(T): its enthalpy at the outlet temperature
    sp = mech.species
    assert sp["polymer"].thermo.cp(500.0) == pytest.approx(2200.0)
    assert np.all(np.isfinite(sol.t_bed_nodes))


def test_unbalanced_user_reaction_refused_at_load(tmp_path):
    f = tmp_path / "bad.yaml"
    f.write_text(USER_YAML.replace("{polymer: -1, C2H4_user: 1}", "{polymer: -1, N2: 1}"))
    with pytest.raises(InputError, match=r"polymer_cracking\.stoichiometry: .*element-balanced"):
        mechanism_from_files(files=[f])
    f.write_text(USER_YAML.replace("C2H4_user: 1}", "C2H6_user: 1}"))
    with pytest.raises(InputError, match=r"C2H6_user.? is not a known species"):
        mechanism_from_files(files=[f])


CASE_YAML = """
name: polymer_kiln
description: a user species and its reaction in the case's own YAML
kiln: {length: 4 m, diameter: 0.5 m, slope: 2 deg}
operation: {speed: 1.91 rpm, feed: 36 kg/h, feed_temperature: 298.15 K}
material:
  name: polymer pellets
  bulk_density: 500 kg/m3
  particle_size: 5 mm
  thermal_conductivity: 0.2 W/m/K
  emissivity: 0.9
  composition: {polymer: 1.0}
bed: {residence_time: 1800 s, axial_dispersion: plug}
gas: {flow: 180 kg/h, temperature: 1000 K, mass_fractions: {N2: 1.0}}
wall: {U: 5 W/m2/K}
chemistry:
  species: polymer_species.yaml
  reactions:
    - name: polymer_cracking
      stoichiometry: {polymer: -1, C2H4_user: 1}
      basis: polymer
      rate: {law: arrhenius, A: 1.0e14, E: 220000.0}
      heat: 1.0 MJ/kg
solver: {cells: 30}
"""


def _case_files(tmp_path):
    species = USER_YAML.split("reactions:")[0].replace("species:\n", "", 1)
    import textwrap

    (tmp_path / "polymer_species.yaml").write_text(textwrap.dedent(species), encoding="utf-8")
    case = tmp_path / "polymer_kiln.yaml"
    case.write_text(CASE_YAML, encoding="utf-8")
    return case


def test_case_file_with_its_own_species_runs(tmp_path):
    from rotarykiln.case import load_case
    from rotarykiln.kiln.from_case import kiln_from_case

    case = load_case(_case_files(tmp_path))
    kiln, cells = kiln_from_case(case)
    assert "C2H4_user" in kiln.chemistry.mechanism.species and cells == 30
    sol = solve_kiln(kiln, cells)
    assert abs(sol.energy_closure) < 1e-6
    assert max(sol.element_closure.values()) < 1e-8
    assert sol.gas_flows["C2H4_user"][0] > 0


def test_case_file_with_its_own_species_through_the_cli(tmp_path):
    import subprocess
    import sys

    path = _case_files(tmp_path)
    out = tmp_path / "out"
    run = subprocess.run(
        [sys.executable, "-m", "rotarykiln", "run", str(path), "--out", str(out), "--no-plots"],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert run.returncode == 0, run.stderr
    assert any(out.iterdir())


@pytest.mark.parametrize(
    "edit, match",
    [
        (("C2H4_user: 1}", "CH4: 1}"), r"polymer_cracking\.stoichiometry: .*element-balanced"),
        (("species: polymer_species.yaml", "species: nowhere.yaml"), r"chemistry\.species"),
        (("composition: {polymer: 1.0}", "composition: {plastic: 1.0}"), r"plastic"),
    ],
)
def test_case_file_bad_user_chemistry_refused_at_load(tmp_path, edit, match):
    from rotarykiln.case import load_case

    path = _case_files(tmp_path)
    path.write_text(path.read_text().replace(*edit), encoding="utf-8")
    with pytest.raises(InputError, match=match) as err:
        load_case(path)
    assert "\n" not in str(err.value)


def test_case_species_inline_and_bad_species_refused(tmp_path):
    import yaml

    from rotarykiln.case import parse_case

    data = yaml.safe_load(CASE_YAML)
    species = yaml.safe_load(USER_YAML)["species"]
    data["chemistry"]["species"] = species
    case = parse_case(data)
    assert case.chemistry.species["bed"]["polymer"]["elements"] == {"C": 2, "H": 4}
    del species["bed"]["polymer"]["elements"]
    with pytest.raises(InputError, match=r"chemistry\.species\.polymer\.elements: missing"):
        parse_case(data)
