"""Unit tests of the grid network, simulation, heating, pyrolysis, config and CLI."""

import json
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rotarykiln.case import parse_case
from rotarykiln.cli import main
from rotarykiln.commands.transverse import retort_spec_from_case
from rotarykiln.errors import InputError, OutOfRangeWarning
from rotarykiln.transverse.grid import GridMaterial, simulate_grid
from rotarykiln.transverse.grid_geometry import build_grid
from rotarykiln.transverse.heating import cell_heat_exchange, thomas_sphere_nusselt
from rotarykiln.transverse.pyrolysis import berkovich_shale, reaction_extent
from rotarykiln.transverse.retort import retort_case, run_retort, tilted_distribution

RPM = 2 * np.pi / 60


def test_network_closes_fluxes_and_areas():
    g = build_grid(3.0, 5 * RPM, 0.3)
    assert g.cv_area.sum() == pytest.approx(g.active_area, rel=1e-12)
    assert g.layer_area.sum() == pytest.approx(g.stagnant_area, rel=1e-12)
    assert np.allclose(g.weights.sum(axis=1), 1.0)
    # steady state: what flows into every active CV equals its own flux
    inflow = g.weights.T @ g.cv_flux
    inflow[: g.n_active] += g.feed.T @ g.layer_flux
    assert np.allclose(inflow[: g.n_active], g.cv_flux, rtol=1e-10)
    assert np.allclose(inflow[g.n_active :], g.layer_flux, rtol=1e-10)
    tau, n = g.time_step()
    assert tau * n == pytest.approx(g.stagnant_residence)
    assert tau <= g.cv_residence.min()


def test_coarse_grid_is_rejected():
    with pytest.raises(InputError, match="too coarse"), pytest.warns(OutOfRangeWarning):
        build_grid(0.285, 2 * RPM, 0.4, layers=5)  # X_AL = 0.079 needs >= 6 layers
    with pytest.raises(InputError, match="grid.zones"):
        build_grid(0.285, 9 * RPM, 0.25, zones=2)
    with pytest.raises(InputError, match="grid.levels"):
        build_grid(0.285, 9 * RPM, 0.25, levels=[1, 2, 1])


def test_configurable_grid_size_keeps_mass():
    g = build_grid(0.285, 9 * RPM, 0.25, layers=4, zones=12)
    assert g.n_active == sum(g.levels) and len(g.levels) == 8
    mats = (GridMaterial("a", 1.0, [0.5, 0.5]), GridMaterial("b", 1.0, [0.3, 0.7]))
    r = simulate_grid(g, [1e-3, 3e-3], mats, duration=20.0, snapshot_times=[5.0])
    assert r.mass_error < 1e-13
    assert 5.0 in r.snapshots
    assert set(r.snapshots[5.0]["active"]) >= {"extent", "size", "share"}


def test_no_segregation_keeps_layers_uniform():
    g = build_grid(0.285, 9 * RPM, 0.25)
    mats = (GridMaterial("a", 1.0, [0.5, 0.5]), GridMaterial("b", 1.0, [0.5, 0.5]))
    r = simulate_grid(g, [1e-3, 3e-3], mats, duration=30.0, segregation=False)
    assert np.allclose(r.layer_sizes[-1], 2e-3, rtol=1e-9)


def test_bad_material_input():
    g = build_grid(0.285, 9 * RPM, 0.25)
    with pytest.raises(InputError, match="fractions"):
        simulate_grid(
            g, [1e-3], (GridMaterial("a", 1, [1, 2]), GridMaterial("b", 1, [1])), duration=1.0
        )
    with pytest.raises(InputError, match="volume"):
        simulate_grid(
            g, [1e-3], (GridMaterial("a", 0, [1]), GridMaterial("b", 1, [1])), duration=1.0
        )
    with pytest.raises(InputError, match="initial"):
        simulate_grid(
            g,
            [1e-3],
            (GridMaterial("a", 1, [1]), GridMaterial("b", 1, [1])),
            duration=1.0,
            initial="sandwich",
        )


@settings(max_examples=30, deadline=None)
@given(
    st.lists(st.floats(300, 1300), min_size=4, max_size=4),
    st.lists(st.floats(0.0, 2.0), min_size=4, max_size=4),
    st.floats(0.0, 1.0),
    st.sampled_from(["pairwise", "smaller"]),
)
def test_cell_exchange_conserves_energy(temps, masses, extent, balance):
    t = np.array(temps).reshape(1, 2, 2)
    m = np.array(masses).reshape(1, 2, 2)
    cp = np.full_like(t, 1000.0)
    area = 6 * m / (1500 * np.array([1e-3, 3e-3]))[None, None, :]
    q = cell_heat_exchange(
        m, cp, area, t, np.array([1e-3, 3e-3]), np.array([extent]), 0.5, balance=balance
    )
    scale = max(1.0, float(np.abs(q).max()))
    assert abs(float(q.sum())) <= 1e-9 * scale
    assert np.all(q[m == 0] == 0)


def test_exchange_does_not_overshoot():
    # one hot and one cold class with a huge step: they may meet, not cross
    t = np.array([1000.0, 400.0]).reshape(1, 2, 1)
    m = np.array([1e-3, 1e-3]).reshape(1, 2, 1)
    cp = np.full_like(t, 1000.0)
    area = np.full_like(t, 10.0)
    q = cell_heat_exchange(m, cp, area, t, np.array([1e-3]), np.array([1.0]), 100.0)
    t_new = t + q / (m * cp)
    assert t_new[0, 0, 0] >= t_new[0, 1, 0] - 1e-9


def test_nusselt_and_pyrolysis():
    assert thomas_sphere_nusselt(0.0, 0.7) == pytest.approx(1.77**2)
    with pytest.raises(InputError):
        thomas_sphere_nusselt(-1.0, 0.7)
    sh = berkovich_shale()
    t = np.linspace(300, 1100, 81)
    assert np.all(np.diff(sh.enthalpy(t)) > 0)
    assert np.allclose(sh.temperature(sh.enthalpy(t)), t, atol=0.05)
    assert sh.volatile_yield(523.0) == 0.0  # moisture is not counted
    assert reaction_extent(700.0, 743.0, 21.71) == 0.0
    # Table 9.1 enthalpies sum to 896.66 J/g
    total = sh.enthalpy(3000.0) - sh.cp * (3000.0 - sh.t_ref)
    assert total == pytest.approx(896.66e3, rel=1e-6)


def test_tilted_distribution_bad_mean():
    with pytest.raises(InputError, match="mean_size"):
        tilted_distribution(8e-3)


def test_speed_outside_rolling_regime_warns():
    with pytest.warns(OutOfRangeWarning, match="cascading regime, outside the rolling"):
        run_retort(retort_case(2, omega=10 * RPM, duration=2.0, snapshot_times=()))
    with pytest.warns(OutOfRangeWarning, match="slumping regime"):
        build_grid(3.0, 1.5 * RPM, 0.3, layers=8)


def test_size_beyond_limit_warns():
    with pytest.warns(OutOfRangeWarning, match="limiting size"):
        run_retort(retort_case(2, shale_size=7e-3, ash_size=7e-3, duration=2.0, snapshot_times=()))


def test_ratio_must_be_positive():
    with pytest.raises(InputError, match="shale_to_ash"):
        run_retort(retort_case(2, shale_to_ash=0.0, duration=2.0))


CASE = {
    "name": "t",
    "kiln": {"length": "1 m", "diameter": "6 m"},
    "operation": {"speed": "5 rpm"},
    "bed": {"fill": 0.3},
    "transverse": {
        "duration": "10 s",
        "shale_to_ash": 0.32,
        "shale": {"mean_size": "1.54 mm", "temperature": "275 degC"},
        "ash": {"mean_size": "2.11 mm", "temperature": "1048 K"},
        "snapshot_times": ["5 s"],
    },
}


def test_case_section_converts_units():
    spec = retort_spec_from_case(parse_case(CASE))
    assert spec.shale_temperature == pytest.approx(548.15)
    assert spec.shale_size == pytest.approx(1.54e-3)
    assert spec.duration == 10.0


@pytest.mark.parametrize(
    ("path", "value", "message"),
    [
        (("transverse", "shale_to_ash"), 0, "transverse.shale_to_ash: 0 is not > 0"),
        (("transverse", "shale_to_ash"), -0.3, "is not > 0"),
        (("transverse", "shale", "mean_size"), "3 K", "transverse.shale.mean_size"),
        (("transverse", "colour"), "red", "unknown key"),
        (("transverse", "grid"), {"layers": 1}, "transverse.grid.layers"),
    ],
)
def test_case_section_bad_values(path, value, message):
    data = json.loads(json.dumps(CASE))
    node = data
    for p in path[:-1]:
        node = node[p]
    node[path[-1]] = value
    with pytest.raises(InputError, match=message):
        parse_case(data)


def test_cli_runs_builtin_case(tmp_path, capsys):
    code = main(
        ["transverse", "retort/case02", "--duration", "6 s", "--out", str(tmp_path), "--json"]
    )
    assert code == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["active_layer_velocity_m_s"] == pytest.approx(7.01, abs=0.005)
    assert (tmp_path / "timeseries.csv").is_file()
    assert (tmp_path / "time_series.png").is_file()
    assert (tmp_path / "grid_0005.0s.png").is_file()


def test_cli_bad_case_exits_2(tmp_path, capsys):
    bad = tmp_path / "bad.yaml"
    bad.write_text(
        "kiln: {length: 1 m, diameter: 6 m}\noperation: {speed: 5 rpm}\nbed: {fill: 0.3}\n"
        "transverse: {shale_to_ash: 0}\n"
    )
    assert main(["transverse", str(bad), "--out", str(tmp_path)]) == 2
    assert "shale_to_ash" in capsys.readouterr().err


def test_all_builtin_cases_load():
    from rotarykiln.case import load_case
    from rotarykiln.cases import builtin_case_path

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for c in range(1, 17):
            spec = retort_spec_from_case(load_case(builtin_case_path(f"retort/case{c:02d}")))
            ref = retort_case(c)
            assert spec.shale_to_ash == ref.shale_to_ash
            assert spec.omega == pytest.approx(ref.omega)


def test_animation_and_result_plots(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    from rotarykiln.transverse.grid_plot import animate_grid, plot_layer_sizes
    from rotarykiln.transverse.mixing import vanpuyvelde_mixing
    from rotarykiln.transverse.segregation import vanpuyvelde_layer_mean_sizes

    r = run_retort(retort_case(2, duration=3.0, snapshot_times=(0.0, 1.0, 2.0, 3.0)))
    assert animate_grid(r, tmp_path / "a.gif", "temperature")
    assert (tmp_path / "a.gif").stat().st_size > 0
    assert plot_layer_sizes(r) is not None
    assert r.plot() is not None and len(r.to_frame()) == len(r.t)
    assert vanpuyvelde_mixing(0.285, 9 * RPM, 0.25, 2.51e-3, 1.06).plot() is not None
    assert vanpuyvelde_layer_mean_sizes([1e-3, 2e-3], [0.5, 0.5], 0.4).plot() is not None
