"""The steady kiln solver on inert kilns: balance closure, mesh check, options, bad input."""

import warnings

import matplotlib
import numpy as np
import pytest

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.errors import ConvergenceError, InputError
from rotarykiln.kiln import Closures, solve_kiln
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.materials.lining import Layer, load_lining_material

matplotlib.use("Agg")

CLOSURE_TOL = 1e-6  # issue 6: the balance must close to 1e-6 of the heat to the solids


def _finite(sol):
    arrays = [sol.t_gas_nodes, sol.t_bed_nodes, sol.t_wall, sol.t_shell, sol.t_lining]
    arrays += [np.asarray(v) for v in sol.fluxes.values()]
    return all(np.all(np.isfinite(a)) for a in arrays)


@pytest.fixture(scope="module")
def flame_kiln():
    kiln, _ = kiln_from_case(load_case(builtin_case_path("ubc_pilot_flame")))
    return kiln


def _tscheng_a16(closures=None):
    """Tscheng's run A16 as its built-in case builds it (the kiln users run)."""
    kiln, _ = kiln_from_case(load_case(builtin_case_path("tscheng_A16")))
    return kiln if closures is None else kiln.replace(closures=closures)


def test_tscheng_run_closes_and_converges():
    sol = solve_kiln(_tscheng_a16())
    assert abs(sol.energy_closure) < CLOSURE_TOL
    assert sol.residual < 1e-9 and 1 <= sol.iterations < 20
    assert _finite(sol)
    # counter-current: gas enters hot at z = L, bed leaves hotter than it entered
    assert sol.t_gas_nodes[-1] == pytest.approx(535.0)
    assert sol.t_bed_nodes[0] == pytest.approx(298.15)
    assert sol.bed_outlet_temperature > 400.0
    assert sol.gas_outlet_temperature < 535.0


def test_flame_case_radiation_share(flame_kiln):
    on = solve_kiln(flame_kiln)
    off = solve_kiln(flame_kiln.replace(closures__radiation=False))
    for sol in (on, off):
        assert abs(sol.energy_closure) < CLOSURE_TOL
        assert _finite(sol)
    dz = on.z[1] - on.z[0]
    rad_to_bed = np.sum(on.fluxes["q_rad_to_bed"]) * dz
    assert rad_to_bed > 0.1 * on.heat_to_solids  # radiation is a major path in a flame kiln
    assert np.all(off.fluxes["q_rad_to_bed"] == 0.0)
    assert on.fluxes["eps_gas"].max() > 0.05  # CO2/H2O products participate
    # the released heat is the same; radiation moves heat from the gas to the bed and wall
    assert on.heat_release == pytest.approx(off.heat_release, rel=1e-12)
    assert on.gas_outlet_temperature < off.gas_outlet_temperature


@pytest.mark.parametrize(("which", "cells", "tol"), [("tscheng", 100, 1.0), ("flame", 200, 2.0)])
def test_mesh_doubling_below_tolerance(which, cells, tol, flame_kiln):
    # the fired kiln enters at its adiabatic flame temperature (1873 K here, hotter than
    # Barr's 826-1090 K): the steepest gradients are at the burner, where doubling 100 cells
    # moves the wall by 2.0 K and doubling 200 by 1.5 K (issue 10 asks < 2 K, for Barr's
    # profiles at 100 cells: tests/validation/test_heat_barr.py)
    kiln = _tscheng_a16() if which == "tscheng" else flame_kiln
    a = solve_kiln(kiln, cells)
    b = solve_kiln(kiln, 2 * cells)
    for x, y in ((a.t_gas_nodes, b.t_gas_nodes[::2]), (a.t_bed_nodes, b.t_bed_nodes[::2])):
        assert np.max(np.abs(x - y)) < tol
    assert np.max(np.abs(a.t_wall - 0.5 * (b.t_wall[::2] + b.t_wall[1::2]))) < tol


def test_co_current():
    kiln = _tscheng_a16().replace(gas__counter_current=False)
    sol = solve_kiln(kiln)
    assert abs(sol.energy_closure) < CLOSURE_TOL
    assert sol.t_gas_nodes[0] == pytest.approx(535.0)
    # co-current: the gas stays hotter than the bed and the two approach each other along z
    gap = sol.t_gas_nodes - sol.t_bed_nodes
    assert np.all(gap > 0) and gap[-1] < 0.2 * gap[0]


def test_fill_as_array_callable_pair_equivalent():
    base = _tscheng_a16()
    ref = solve_kiln(base)
    for fill in (np.full(7, 0.17), lambda z: 0.17 + 0 * z, (np.array([0.0, 2.44]), [0.17, 0.17])):
        sol = solve_kiln(base.replace(bed__fill=fill))
        assert np.allclose(sol.t_bed_nodes, ref.t_bed_nodes, atol=1e-8)
    # a varying fill changes the answer and still closes
    sol = solve_kiln(base.replace(bed__fill=lambda z: 0.10 + 0.05 * z / 2.44))
    assert abs(sol.energy_closure) < CLOSURE_TOL
    assert sol.fill_profile[0] < sol.fill_profile[-1]


@pytest.mark.parametrize(
    "closures",
    [
        Closures(gas_wall="gorog1982", gas_bed="gorog1982"),
        Closures(covered_wall="tscheng1979", bed_conductivity="maxwell"),
        Closures(covered_wall="wachters_kramers1964", bed_conductivity="zehner_schlunder"),
    ],
)
def test_alternative_closures_close(closures):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sol = solve_kiln(_tscheng_a16(closures))
    assert abs(sol.energy_closure) < CLOSURE_TOL


def test_unconverged_raises_with_location():
    with pytest.raises(ConvergenceError, match=r"cell \d+ \(z = .* m\)") as info:
        solve_kiln(_tscheng_a16(), max_iter=1, tol=1e-30)
    assert info.value.diagnostics["iterations"] >= 1
    assert "residual" in info.value.diagnostics


def test_bad_inputs():
    base = _tscheng_a16()
    case = load_case(builtin_case_path("tscheng_A16"))
    with pytest.raises(InputError, match="gas.flow"):
        kiln_from_case(case.replace({"gas.flow": "0 kg/h"}))
    with pytest.raises(InputError, match="operation.feed"):
        kiln_from_case(case.replace({"operation.feed": "-1 kg/h"}))
    with pytest.raises(InputError, match="wall.emissivity"):
        base.replace(wall__emissivity=1.5)
    with pytest.raises(InputError, match="shell_emissivity"):
        base.replace(wall__shell_emissivity=0.0)
    with pytest.raises(InputError, match="thickness"):
        base.replace(wall__layers=(Layer(load_lining_material("carbon_steel"), 0.0),))
    with pytest.raises(InputError, match="closures.gas_wall"):
        Closures(gas_wall="nusselt")
    with pytest.raises(InputError, match="fill"):
        solve_kiln(base.replace(bed__fill=0.0))
    with pytest.raises(InputError, match="cells"):
        solve_kiln(base, 2)
    with pytest.warns(UserWarning, match="colder than the solids feed"):
        base.replace(gas__temperature=280.0)


def test_results_frame_and_plot():
    sol = solve_kiln(_tscheng_a16())
    df = sol.to_frame()
    assert len(df) == len(sol.z_nodes)
    for col in ("z_m", "T_gas_K", "T_bed_K", "T_wall_K", "T_shell_K", "q_shell_loss_W_m"):
        assert col in df
    assert df.notna().all().all()
    ax = sol.plot().axes[0]
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert "bed, measured" in labels and "gas, measured" in labels
    s = sol.summary()
    assert 0 < s["thermal_efficiency"] < 1


def test_continuation_used_when_newton_fails(monkeypatch, flame_kiln):
    import rotarykiln.kiln.steady.newton as newton_mod

    real = newton_mod.newton_banded
    calls = []

    def flaky(F, x0, scale, **kw):
        # the residual itself at full scales, or a stage of the continuation at its scales
        scales = getattr(F, "keywords", {}).get("scales")
        calls.append(1.0 if scales is None else scales.radiation)
        if len(calls) <= 2:
            raise ConvergenceError("forced failure", iterations=0)
        return real(F, x0, scale, **kw)

    monkeypatch.setattr(newton_mod, "newton_banded", flaky)
    sol = solve_kiln(flame_kiln)
    # full Newton fails, then radiation (and heat release) are ramped in from 0
    assert calls[:4] == [1.0, 1.0, 0.0, 0.25] and calls[-1] == 1.0
    assert abs(sol.energy_closure) < CLOSURE_TOL
    ref = solve_kiln(flame_kiln)
    assert np.max(np.abs(sol.t_bed_nodes - ref.t_bed_nodes)) < 1e-6


def test_convection_factor_scales_the_gas_coefficients():
    base = solve_kiln(_tscheng_a16())
    k = _tscheng_a16(Closures(convection_factor=2.0))
    sol = solve_kiln(k)
    assert np.allclose(sol.fluxes["h_gb"], 2.0 * base.fluxes["h_gb"], rtol=0.05)
    assert sol.bed_outlet_temperature > base.bed_outlet_temperature
    assert abs(sol.energy_closure) < CLOSURE_TOL


def test_a_solution_hotter_than_every_source_is_refused():
    from rotarykiln.kiln.residual import KilnResidual
    from rotarykiln.kiln.steady.solve import _check_no_hotter_than_sources

    kiln = _tscheng_a16()
    res = KilnResidual(kiln, 10)
    ok = np.full(11, 400.0)
    _check_no_hotter_than_sources(res, ok, ok, np.full((10, 4), 400.0), 3)
    hot = ok.copy()
    hot[4] = kiln.gas.temperature + 50.0  # an overshooting face
    with pytest.raises(ConvergenceError, match="unphysical solution: T_bed"):
        _check_no_hotter_than_sources(res, hot, ok, np.full((10, 4), 400.0), 3)


#: The fill of the rotary_pyrolysis case file before its bed depth was solved: the fresh feed's
#: Saeman profile behind the 25 mm dam, at 21 points from the feed end to the dam.
PYROLYSIS_FILL = [0.0757, 0.0755, 0.0752, 0.0749, 0.0745, 0.0741, 0.0736, 0.073, 0.0722, 0.0713,
                  0.0703, 0.069, 0.0675, 0.0657, 0.0635, 0.0607, 0.0572, 0.0528, 0.047, 0.0388,
                  0.026]  # fmt: skip


def test_a_kiln_hot_enough_to_react_at_once_converges(monkeypatch):
    # a 1099 K flue-gas jacket over 11.9 kg/h of wood (counter-current jacket, plug flow, the
    # fill profile of the case file when it was found, not its solved depth): the
    # reaction-free bed is so hot at the end that ramping the rates from 0 fails; the solver
    # then ramps the temperature the rates see (found by a random campaign)
    import yaml

    from rotarykiln.case import parse_case
    from rotarykiln.cases import builtin_case_path
    from rotarykiln.kiln.from_case import kiln_from_case
    from rotarykiln.kiln.steady import solve as solve_mod

    d = yaml.safe_load(builtin_case_path("rotary_pyrolysis").read_text())
    d["wall"]["jacket"].update(temperature="1099 K", counter_current=True)
    d["operation"]["feed"] = "11.9 kg/h"
    d.pop("transport")
    d["bed"] = {"fill": PYROLYSIS_FILL, "axial_dispersion": "plug"}
    kiln, _ = kiln_from_case(parse_case(d))
    capped = []
    real_capped = solve_mod.KilnResidual.rates

    def spy(self, *args, **kw):
        capped.append(np.isfinite(kw["scales"].rate_temperature_cap))
        return real_capped(self, *args, **kw)

    monkeypatch.setattr(solve_mod.KilnResidual, "rates", spy)
    # whether ramping the rates from 0 fails on this kiln depends on round-off (it failed when
    # the kiln was found, it converges on a fresh install of 2026-11-26): make it fail, so
    # that the fallback is exercised on every machine
    real_ramp = solve_mod.steady.ramp

    def failing_rate_ramp(scales_at, *args, **kwargs):
        stage = real_ramp(scales_at, *args, **kwargs)
        if scales_at(0.5) != solve_mod.Scales(reaction=0.5):
            return stage

        def fail(*_):
            raise ConvergenceError("rate ramp refused by the test")

        return fail

    monkeypatch.setattr(solve_mod.steady, "ramp", failing_rate_ramp)
    # the continuation itself (solve_kiln converges without it on such a machine)
    res = solve_mod.KilnResidual(kiln, 200)
    kw = solve_mod.newton_options(res, tol=1e-11, max_iter=60)
    run = solve_mod._continuation(res)
    x, total = run(res, solve_mod._initial_guess(res), res.q_ref, kw)
    sol = solve_mod.finish_solution(res, x, total)
    assert any(capped)  # the rate-temperature continuation was used ...
    assert abs(sol.energy_closure) < 1e-6  # ... and the converged solve is uncapped
    assert max(sol.element_closure.values()) < 1e-8
    assert sol.summary()["conversion_wood"] > 0.999


def test_an_adaptive_ramp_gives_up_a_stalling_step_but_not_its_last(monkeypatch):
    # the intermediate values of an adaptive continuation are given up when Newton stalls
    # (STEP_STALL; the step is then halved); the last has the caller's iterations
    from rotarykiln.kiln.inputs.boundary import Scales
    from rotarykiln.kiln.steady import continuation as cont

    seen = []

    def record(F, x, scale, **kw):
        seen.append((F.keywords["scales"].reaction, kw["tol"], kw.get("stall")))
        return x, cont.newton.NewtonReport(1, 0.0, (0.0,), 1)

    monkeypatch.setattr(cont.newton, "newton_banded", record)

    class Residual:
        def evaluate(self, x, scales):
            return x

    stage = cont.ramp(lambda v: Scales(reaction=v), adaptive=True)
    stage(Residual(), np.zeros((3, 2)), 1.0, {"tol": 1e-11, "max_iter": 60})
    assert [s[0] for s in seen] == [0.25, 0.75, 1.0]
    assert seen[:-1] == [(0.25, 1e-11, cont.STEP_STALL), (0.75, 1e-11, (8, 1e-2))]
    assert seen[-1] == (1.0, 1e-11, None)


def test_a_hot_feed_ramps_its_rate_temperature_from_below_its_own(monkeypatch):
    # a meal fed at 875 degC: the rates first see at most RATE_CAP_FLOOR, not the feed + 50 K
    from rotarykiln.kiln.steady import solve as solve_mod

    kiln, _ = kiln_from_case(load_case(builtin_case_path("cement_kiln")))
    caps = []
    real_ramp = solve_mod.steady.ramp

    def spy(scales_at, *args, **kwargs):
        caps.append(scales_at(0.0).rate_temperature_cap)
        return real_ramp(scales_at, *args, **kwargs)

    monkeypatch.setattr(solve_mod.steady, "ramp", spy)
    solve_mod._continuation(solve_mod.KilnResidual(kiln, 10))
    assert kiln.feed.temperature + solve_mod.RATE_CAP_START > 1190.0
    assert solve_mod.RATE_CAP_FLOOR in caps


MORE_FUEL = {"burner.solid_fuels.0.flow": "2.532 kg/s"}


@pytest.mark.parametrize(
    "overrides", [MORE_FUEL, {**MORE_FUEL, "operation.feed": "56.33 kg/s"}], ids=["fuel", "both"]
)
def test_the_cement_kiln_solves_with_ten_percent_more_fuel_or_fuel_and_feed(overrides):
    # both failed (bed C4AF flow) while the rate-temperature ramp started at the meal's 875 degC
    # + 50 K, where the recalled clinker rates are already ~1e7 times the flows per cell
    from rotarykiln.api import load_case as load_with

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        kiln, cells = kiln_from_case(load_with("cement_kiln", overrides))
        sol = solve_kiln(kiln, cells)
    assert abs(sol.energy_closure) < 1e-6
    assert max(sol.element_closure.values()) < 1e-8
    assert sol.bed_flows["CaCO3"][-1] < 1e-6 * kiln.feed.flows["CaCO3"]


def test_a_fine_grid_that_fails_from_its_coarse_start_is_retried_stepping_every_root_squared(
    monkeypatch,
):
    # the limestone kiln's CaCO3 (order 1/2) is solved for as sqrt(Q) and stepped in it; when
    # the fine grid's Newton fails from the coarse start, the retry steps it in Q
    from rotarykiln.kiln.steady import continuation as cont

    kiln, cells = kiln_from_case(load_case(builtin_case_path("limestone_calcination")))
    real = cont.newton.newton_banded
    fine = []

    def first_fine_fails(F, x0, scale, **kw):
        if np.shape(x0)[0] == cells and not hasattr(F, "keywords"):
            fine.append(kw.get("squared").copy())
            if len(fine) == 1:
                raise ConvergenceError("the first fine Newton, failed by the test")
        return real(F, x0, scale, **kw)

    monkeypatch.setattr(cont.newton, "newton_banded", first_fine_fails)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sol = solve_kiln(kiln, cells)
    from rotarykiln.kiln.residual import KilnResidual

    res = KilnResidual(kiln, cells)
    i0 = res.i_species
    roots = np.zeros(res.nv, dtype=bool)
    roots[i0 : i0 + res.nb] = res.sqrt_mask
    assert len(fine) == 2 and roots.any()
    assert not fine[0][roots].all()  # CaCO3 stepped in its root first ...
    assert fine[1][roots].all()  # ... then in its square: the retry converged
    monkeypatch.undo()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ref = solve_kiln(kiln, cells)
    np.testing.assert_allclose(sol.t_bed_nodes, ref.t_bed_nodes, rtol=0, atol=1e-6)


@pytest.mark.parametrize(
    "overrides",
    [{"operation.feed": "18.063 t/h"}, {"burner.solid_fuels.0.flow": "2430.75 kg/h"}],
    ids=["less-feed", "more-coal"],
)
def test_the_lime_kiln_solves_with_less_feed_or_more_coal(overrides):
    # 10 % less feed failed on numpy 2.4.6 / scipy 1.17.1 (bed CaCO3 flow, at the end of
    # calcination) through every continuation, 5 % more coal on every build: both converge,
    # the first through the feed continuation (from 1.1 times its feed), the second since the
    # fine grid starts past its coarse grid's fronts (interpolate_unknowns) directly
    from rotarykiln.api import load_case as load_with

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        kiln, cells = kiln_from_case(load_with("lime_kiln", overrides))
        sol = solve_kiln(kiln, cells)
    assert abs(sol.energy_closure) < 1e-6
    assert max(sol.element_closure.values()) < 1e-8
    assert sol.bed_flows["CaCO3"][-1] < 1e-6 * kiln.feed.flows["CaCO3"]
    assert sol.residual <= 10 * 1e-11  # the tolerance, or its stagnation at round-off


def test_a_reacting_kiln_whose_solve_fails_is_solved_from_a_larger_feed(monkeypatch):
    # the feed continuation ends on the kiln's own root: the same profiles as the direct solve
    from rotarykiln.kiln.steady import solve as solve_mod

    kiln, cells = kiln_from_case(load_case(builtin_case_path("limestone_calcination")))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ref = solve_kiln(kiln, cells)
        real = solve_mod._solve_unknowns
        feeds = []

        def fails_at_its_own_feed(res, x0, kw, *, sequenced):
            feeds.append(res.kiln.feed.total / kiln.feed.total)
            if res.kiln is kiln:
                raise ConvergenceError("the kiln's own solve, failed by the test")
            return real(res, x0, kw, sequenced=sequenced)

        monkeypatch.setattr(solve_mod, "_solve_unknowns", fails_at_its_own_feed)
        sol = solve_kiln(kiln, cells)
    assert feeds[0] == 1.0 and feeds[1] == pytest.approx(solve_mod.FEED_START_FACTORS[0])
    assert sol.iterations > ref.iterations
    np.testing.assert_allclose(sol.t_bed_nodes, ref.t_bed_nodes, rtol=0, atol=1e-6)
    np.testing.assert_allclose(sol.t_gas_nodes, ref.t_gas_nodes, rtol=0, atol=1e-6)


def test_an_inert_kiln_whose_solve_fails_has_no_feed_continuation(monkeypatch):
    from rotarykiln.kiln.steady import solve as solve_mod

    def never(*args, **kwargs):
        raise AssertionError("no feed continuation for a kiln without reactions")

    monkeypatch.setattr(solve_mod, "_feed_continuation", never)
    with pytest.raises(ConvergenceError):
        solve_kiln(_tscheng_a16(), max_iter=1, tol=1e-30)


def test_a_solve_that_stalls_above_its_tolerance_is_polished(monkeypatch):
    """A solve accepted at round-off just above its tolerance (a stiff rate's forward
    differences too coarse for the last digits) is taken on by Newton with Broyden's updates
    of its Jacobian; a solve within its tolerance is left as it is."""
    from rotarykiln.kiln.steady import solve as solve_mod

    kiln, cells = kiln_from_case(load_case(builtin_case_path("limestone_calcination")))
    real = solve_mod._solve_unknowns

    totals = []

    def stalled(res, x0, kw, *, sequenced):
        x, total = real(res, x0, kw, sequenced=sequenced)
        x = x.copy()
        x[cells // 2, 0] += 1e-4  # off the root by more than the tolerance allows
        totals.append(total)
        return x, total

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        exact = solve_kiln(kiln, cells, tol=1e-13)
        monkeypatch.setattr(solve_mod, "_solve_unknowns", stalled)
        sol = solve_kiln(kiln, cells, tol=1e-13)
    assert sol.residual <= 1e-13
    np.testing.assert_allclose(sol.t_bed_nodes, exact.t_bed_nodes, rtol=0, atol=1e-8)
    assert sol.iterations > totals[-1]  # the polish's own iterations counted
