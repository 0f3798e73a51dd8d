"""The reacting kiln on the heat model's wall (lining with k(T), shell loss) and shared physics.

The two kilns share the cross-section exchange (kiln/exchange.py) and the wall model
(kiln/wall/lining.py). With no reaction (an inert feed) the reacting kiln must therefore reproduce the
heat model on the same kiln: same geometry, lining, closures, a constant-c_p solid and a
one-species gas (the reacting kiln mixes its gas from the same per-species Cantera tables, so a
pure gas has identical properties). The two discretise the same balances with the same scheme;
they differ only by round-off (measured ~1e-12 K), far inside the 1e-6 K asserted here.
"""

import copy
import warnings

import matplotlib
import numpy as np
import pytest
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.chemistry.mechanism import Mechanism
from rotarykiln.commands.kiln_runs import kiln_runner, run_kiln_case
from rotarykiln.errors import InputError, OutOfRangeWarning
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.inputs import Bed, Chemistry, Closures, Feed, GasInlet, Kiln, Wall
from rotarykiln.kiln.steady.solve import solve_kiln

matplotlib.use("Agg")

LINING = [
    {"material": "fireclay_brick", "thickness": "0.1 m"},
    {"material": "carbon_steel", "thickness": "8 mm"},
]


def _data(name):
    return yaml.safe_load(builtin_case_path(name).read_text(encoding="utf-8"))


def _lined(name):
    data = _data(name)
    del data["wall"]["U"]
    data["wall"]["lining"] = copy.deepcopy(LINING)
    return data


@pytest.fixture(scope="module")
def lined_limestone():
    return run_kiln_case(parse_case(_lined("limestone_calcination")))


def test_lined_reacting_kiln_converges_and_closes(lined_limestone):
    sol = lined_limestone
    assert abs(sol.energy_closure) < 1e-6
    assert max(sol.element_closure.values()) < 1e-8
    assert sol.conversion("CaCO3")[-1] == pytest.approx(1.0, abs=1e-9)
    # inner wall, brick/steel interface, shell: falling outwards, shell above ambient
    assert sol.t_lining.shape == (3, 100)
    assert np.all(np.diff(sol.t_lining, axis=0) < 0)
    assert np.all(sol.t_shell > 298.0)
    frame = sol.to_frame()
    assert "T_shell_K" in frame and np.all(np.isfinite(frame.to_numpy(dtype=float)))
    # the shell loss is what the wall rows pass outwards
    assert sol.shell_loss == pytest.approx(np.sum(sol.fluxes["q_shell_loss"]) * 5.5 / 100)


def test_charcoal_with_a_lining_closes():
    sol = run_kiln_case(parse_case(_lined("charcoal_activation")))
    assert abs(sol.energy_closure) < 1e-6
    assert max(sol.element_closure.values()) < 1e-8
    assert 0 < sol.burn_off < 100


def test_constant_u_or_a_lining():
    data = _data("limestone_calcination")
    seed, _ = kiln_from_case(parse_case(data))
    assert seed.wall.layers == () and seed.wall.loss_u == 7.0
    lined, _ = kiln_from_case(parse_case(_lined("limestone_calcination")))
    assert (
        len(lined.wall.layers) == 2
        and lined.wall.ambient_temperature == seed.wall.ambient_temperature
    )


@pytest.mark.parametrize(
    "edit, field",
    [
        ({"wall": {"ambient_temperature": "298 K"}}, "wall: give lining"),  # no lining, no U
        ({"wall": {"lining": []}}, "wall.lining"),
        ({"wall": {"U": "7 W/m2/K", "lining": LINING}}, "wall: give lining"),
        ({"closures": {"bed_conductivity": "maxwell"}}, "closures.bed_conductivity"),
    ],
)
def test_wall_inputs_refused(edit, field):
    data = _data("limestone_calcination")
    data.update(edit)
    with pytest.raises(InputError, match=field):
        kiln_from_case(parse_case(data))


def test_runner_writes_the_shell_temperature(tmp_path):
    summary = kiln_runner(parse_case(_lined("charcoal_activation")), tmp_path)
    assert abs(summary["kiln_energy_balance_closure"]) < 1e-6
    header = (tmp_path / "kiln_profiles.csv").read_text().splitlines()[0]
    assert "T_shell_K" in header


def _same_kiln(gas: str, closures: Closures, t_gas: float | None):
    """The Tscheng A16 kiln (3 layers, insulation absent on a stretch) built two ways: by the
    inert front-end (its built-in case, with a constant-c_p sand and a one-species gas, through
    :meth:`Kiln.inert`) and field by field."""
    data = yaml.safe_load(builtin_case_path("tscheng_A16").read_text(encoding="utf-8"))
    data["material"].update(
        specific_heat="800 J/kg/K", thermal_conductivity="0.27 W/m/K", emissivity=0.9
    )
    data["gas"]["composition"] = f"{gas}:1"
    if t_gas:
        data["gas"]["temperature"] = f"{t_gas} K"
    data["bed"]["axial_dispersion"] = "plug"  # plug flow, as the kiln built field by field below
    del data["measurements"]
    heat, _ = kiln_from_case(parse_case(data))
    heat = heat.replace(closures=closures)
    # calcination has nothing to calcine: the feed is inert, every rate is zero
    mech = Mechanism.builtin("calcination_luisser")
    reacting = Kiln(
        drum=heat.drum,
        bed=Bed(
            fill=heat.bed.fill,
            velocity=0.002,
            bulk_density=heat.bed.bulk_density,
            conductivity=0.27,
            emissivity=heat.bed.emissivity,
            particle_diameter=heat.bed.particle_diameter,
            cp={s: 800.0 for s in mech.species.bed_names},
        ),
        feed=Feed({"inert": heat.feed_flow}, heat.feed.temperature),
        gas=GasInlet({gas: heat.gas_flow}, heat.gas.temperature),
        chemistry=Chemistry(mech),
        wall=Wall(layers=heat.wall.layers, ambient_temperature=heat.wall.ambient_temperature),
        closures=closures,
    )
    return heat, reacting


@pytest.mark.parametrize(
    "gas, closures, t_gas",
    [
        ("N2", Closures(), None),  # Tscheng convection, Li covered wall
        ("N2", Closures(gas_wall="gorog1982", gas_bed="gorog1982"), None),
        ("CO2", Closures(), 1100.0),  # Johansson WSGG gas radiation
        ("CO2", Closures(gas_emissivity="smith1982", covered_wall="wachters_kramers1964"), 1100),
        ("N2", Closures(gas_emissivity=0.2, covered_wall="tscheng1979"), 1100.0),
    ],
)
def test_inert_front_end_equals_the_kiln_built_field_by_field(gas, closures, t_gas):
    heat, reacting = _same_kiln(gas, closures, t_gas)
    with warnings.catch_warnings():
        # pure CO2 lies outside Johansson's H2O/CO2 ratio range: both models warn alike
        warnings.simplefilter("ignore", OutOfRangeWarning)
        a = solve_kiln(heat, 100)
        b = solve_kiln(reacting, 100)
    assert max(abs(v) for v in b.bed_flows["CaCO3"]) == 0.0  # nothing reacted
    assert abs(b.energy_closure) < 1e-6 and max(b.element_closure.values()) < 1e-8
    assert np.max(np.abs(a.t_bed_nodes - b.t_bed_nodes)) < 1e-6
    assert np.max(np.abs(a.t_gas_nodes - b.t_gas_nodes)) < 1e-6
    assert np.max(np.abs(a.t_lining - b.t_lining)) < 1e-6  # wall, interfaces and shell
    assert a.shell_loss == pytest.approx(b.shell_loss, rel=1e-9)
    assert a.bed_outlet_temperature - heat.feed.temperature > 50.0  # a real heating
