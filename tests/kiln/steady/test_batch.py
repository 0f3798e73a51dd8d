"""Batched steady solves (issue 25): the same answers as one-at-a-time solves, a failing case
alone, structures split, batch sizes checked."""

import warnings

import numpy as np
import pytest

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.errors import ConvergenceError, InputError
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.residual import KilnResidual, cell_evaluations
from rotarykiln.kiln.steady.batch import (
    batch_residuals,
    batch_size_for,
    same_structure,
    solve_batch,
    structure_groups,
)
from rotarykiln.kiln.steady.solve import solve_kiln

#: Every built-in steady kiln case (Tscheng's 44 runs by one of them: the same model).
KILN_CASES = [
    "tscheng_A16",
    "barr_T2",
    "barr_T3",
    "barr_T4",
    "barr_T6",
    "barr_T9",
    "ubc_pilot_flame",
    "limestone_calcination",
    "limestone_fired",
    "charcoal_activation",
    "charcoal_activation_kramers",
    "rotary_pyrolysis",
]
#: Both paths solved to this tolerance: each then resolves the solution to far below the
#: 1e-8 K compared (at the default 1e-11 each is ~3e-8 K from the exact root, so two of them
#: from different starts may differ by that much).
TOL = 1e-13
#: Per-case tolerances (none: the calcining kiln, whose single solve stalled at ~2e-12 with the
#: forward differences of its stiff calcination rate, now reaches 1e-13 with the central
#: differences newton_banded falls back on: both paths agree there to ~1e-9 K).
TOL_OF: dict[str, float] = {}


def operating_points(kiln, n, seed):
    """``n`` kilns around ``kiln``: feed and gas flows +-15 %, inlet temperatures, rotation
    +-15 %, heat released +-10 %."""
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        f = rng.uniform(0.85, 1.15, 4)
        out.append(
            kiln.replace(
                feed__flows={s: v * f[0] for s, v in kiln.feed.flows.items()},
                feed__temperature=kiln.feed.temperature + rng.uniform(0.0, 20.0),
                gas__flows={s: v * f[1] for s, v in kiln.gas.flows.items()},
                gas__temperature=kiln.gas.temperature * rng.uniform(0.97, 1.03),
                drum__omega=kiln.drum.omega * f[2],
                firing__heat_release=kiln.firing.heat_release * (0.9 + 0.2 * (f[3] - 0.85) / 0.3),
            )
        )
    return out


def _same_solution(a, b, atol=1e-8):
    for name in ("t_bed", "t_gas", "t_wall"):
        np.testing.assert_allclose(getattr(a, name), getattr(b, name), rtol=0, atol=atol)
    for s in a.bed_flows:
        scale = max(float(np.max(a.bed_flows[s])), 1e-30)
        np.testing.assert_allclose(a.bed_flows[s], b.bed_flows[s], rtol=0, atol=1e-9 * scale)


@pytest.mark.parametrize("name", KILN_CASES)
def test_batched_and_single_solves_agree_on_every_builtin_kiln(name):
    kiln, cells = kiln_from_case(load_case(builtin_case_path(name)))
    # the calcining kiln's single solves need its continuation at every point: fewer points
    kilns = [kiln, *operating_points(kiln, 2 if name == "limestone_calcination" else 5, len(name))]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        tol = TOL_OF.get(name, TOL)
        batched = solve_batch(kilns, cells, tol=tol)
        for k, sol in zip(kilns, batched, strict=True):
            single = solve_kiln(k, cells, tol=tol)
            assert not isinstance(sol, ConvergenceError), sol
            _same_solution(sol, single)
            assert abs(sol.energy_closure) <= 1e-6
            assert max(sol.element_closure.values()) <= 1e-8


def _same_attribute(a, b) -> bool:
    """Deep equality of residual attributes (arrays bit for bit, dataclasses field by field)."""
    import dataclasses

    if a is b:
        return True
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return np.shape(a) == np.shape(b) and bool(np.array_equal(a, b, equal_nan=True))
    if dataclasses.is_dataclass(a) and not isinstance(a, type):
        return type(a) is type(b) and all(
            _same_attribute(getattr(a, f.name), getattr(b, f.name)) for f in dataclasses.fields(a)
        )
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(_same_attribute(a[k], b[k]) for k in a)
    if isinstance(a, tuple | list):
        return len(a) == len(b) and all(_same_attribute(u, v) for u, v in zip(a, b, strict=True))
    return bool(a == b)


@pytest.mark.parametrize("name", KILN_CASES + ["cement_kiln", "lime_kiln"])
def test_a_residual_of_another_operating_point_is_the_residual_built_for_it(name):
    """``KilnResidual.with_kiln`` (a batch's cases after the first) sets every attribute as
    building the residual of that kiln does: inlet flows, scales, release profile, rotation,
    inputs, reference heat."""
    kiln, cells = kiln_from_case(load_case(builtin_case_path(name)))
    other = operating_points(kiln, 1, seed=7)[0]
    built, variant = KilnResidual(other, cells), KilnResidual(kiln, cells).with_kiln(other)
    assert built.__dict__.keys() == variant.__dict__.keys()
    differ = [
        k for k in built.__dict__ if not _same_attribute(built.__dict__[k], variant.__dict__[k])
    ]
    assert differ == []
    assert variant.q_ref != KilnResidual(kiln, cells).q_ref  # it did change with the inputs
    T = np.linspace(250.0, 3300.0, 700)
    for what in ("species_enthalpy", "species_cp"):
        want = getattr(built.mixture, what)(T)
        assert np.array_equal(getattr(variant.mixture, what)(T), want)


def test_a_burner_at_another_fuel_flow_gives_the_residual_built_for_it():
    """Another fuel flow burns to another gas (its own dissociation heat): the variant's gas
    mixture reuses the stacked species tables and evaluates as the one built, bit for bit."""
    from rotarykiln.case import case_with

    base = load_case(builtin_case_path("barr_T4"))
    kiln, cells = kiln_from_case(base)
    other = kiln_from_case(case_with(base, {"burner.fuel_flow": "2.05 L/s"}))[0]
    built, variant = KilnResidual(other, cells), KilnResidual(kiln, cells).with_kiln(other)
    assert variant.mixture.dissociation is other.firing.flame.dissociation
    assert variant.mixture.dissociation is not kiln.firing.flame.dissociation
    T = np.linspace(250.0, 3300.0, 700)
    for what in ("species_enthalpy", "species_cp"):
        assert np.array_equal(getattr(variant.mixture, what)(T), getattr(built.mixture, what)(T))
    assert variant.q_ref == built.q_ref


def test_batch_residuals_build_one_residual_per_structure():
    tscheng, _ = kiln_from_case(load_case(builtin_case_path("tscheng_A16")))
    longer = tscheng.replace(drum__length=3.0)
    cold = tscheng.replace(gas__temperature=400.0)
    no_argon = tscheng.replace(gas__flows={s: v for s, v in tscheng.gas.flows.items() if s != "AR"})
    residuals, groups = batch_residuals([tscheng, longer, cold, no_argon, cold], 20)
    assert groups == [[0, 2, 4], [1], [3]]
    assert groups == structure_groups(
        [KilnResidual(k, 20) for k in (tscheng, longer, cold, no_argon, cold)]
    )
    assert residuals[2].kiln is cold and residuals[2].inputs.gas_temperature == 400.0


def test_a_batch_with_an_impossible_case_returns_every_other_case():
    kiln, cells = kiln_from_case(load_case(builtin_case_path("barr_T4")))
    points = operating_points(kiln, 4, seed=3)
    # burnt gas entering at 9000 K: beyond the gas tables, no physical steady state
    impossible = kiln.replace(gas__temperature=9000.0)
    kilns = [points[0], impossible, *points[1:]]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        out = solve_batch(kilns, cells)
    assert isinstance(out[1], ConvergenceError)
    with pytest.raises(ConvergenceError) as alone:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            solve_kiln(impossible, cells)
    assert str(out[1]) == str(alone.value)  # its own failure, not the batch's
    for k, sol in zip(kilns[:1] + kilns[2:], out[:1] + out[2:], strict=True):
        assert not isinstance(sol, ConvergenceError)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            _same_solution(sol, solve_kiln(k, cells), atol=1e-6)


def test_kilns_of_different_structures_are_split_not_refused():
    tscheng, n_t = kiln_from_case(load_case(builtin_case_path("tscheng_A16")))
    barr, n_b = kiln_from_case(load_case(builtin_case_path("barr_T4")))
    longer = tscheng.replace(drum__length=3.0)
    kilns = [tscheng, barr, longer, operating_points(tscheng, 1, seed=1)[0]]
    residuals = [KilnResidual(k, 40) for k in kilns]
    assert structure_groups(residuals) == [[0, 3], [1], [2]]
    assert same_structure(residuals[0], residuals[3])
    assert not same_structure(residuals[0], residuals[2])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        out = solve_batch(kilns, 40)
        for k, sol in zip(kilns, out, strict=True):
            _same_solution(sol, solve_kiln(k, 40), atol=1e-6)


def test_other_fuel_flows_share_a_batch_each_with_its_own_dissociation_heat(monkeypatch):
    """Each fuel flow burns to another gas (its own dissociation heat): the kilns still share a
    batch (each case's own gas enthalpy, :class:`~rotarykiln.kiln.gas_mixture.CaseMixtures`),
    only the first is solved alone, and each lands on its own root."""
    from rotarykiln.case import case_with
    from rotarykiln.kiln.steady import batch as B

    base = load_case(builtin_case_path("barr_T4"))
    kilns = [
        kiln_from_case(case_with(base, {"burner.fuel_flow": f"{q} L/s"}))[0]
        for q in (1.9, 1.95, 2.0, 2.05)
    ]
    cells = kiln_from_case(base)[1]
    residuals = [KilnResidual(k, cells) for k in kilns]
    assert len({id(r.mixture.dissociation) for r in residuals}) == 4
    assert structure_groups(residuals) == [[0, 1, 2, 3]]
    alone, original = [], B._alone
    monkeypatch.setattr(B, "_alone", lambda res, *a: alone.append(res) or original(res, *a))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        out = solve_batch(kilns, cells, tol=TOL)
        assert len(alone) == 1  # only the first, with the continuation
        for k, sol in zip(kilns, out, strict=True):
            _same_solution(sol, solve_kiln(k, cells, tol=TOL))
            assert abs(sol.energy_closure) <= 1e-6
    outlets = [s.gas_outlet_temperature for s in out]
    assert outlets == sorted(outlets)  # more fuel, a hotter kiln: the cases are not one


def test_kilns_of_another_structure_start_from_their_neighbour(monkeypatch):
    """Another wall emissivity is another structure (no batch), but the same unknowns: each
    case but the first starts by Newton from the nearest solved one, without the
    continuation, and lands on its own root."""
    from rotarykiln.kiln.steady import batch as B

    kiln, cells = kiln_from_case(load_case(builtin_case_path("barr_T4")))
    kilns = [kiln.replace(wall__emissivity=e) for e in (0.8, 0.85, 0.9)]
    residuals = [KilnResidual(k, cells) for k in kilns]
    assert structure_groups(residuals) == [[0], [1], [2]]
    assert all(B.same_layout(residuals[0], r) for r in residuals)
    alone, original = [], B._alone
    monkeypatch.setattr(B, "_alone", lambda res, *a: alone.append(res) or original(res, *a))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        out = solve_batch(kilns, cells, tol=TOL)
        assert len(alone) == 1
        for k, sol in zip(kilns, out, strict=True):
            _same_solution(sol, solve_kiln(k, cells, tol=TOL))


def test_a_group_whose_batched_newton_crawls_solves_its_other_cases_alone(monkeypatch):
    """When the batched parts of a group cost more cells a case than SLOW_BATCH_FACTOR times
    its first case's solve alone (a reaction front moving between operating points), the
    group's other cases are solved alone: each the very solve of the single path."""
    from rotarykiln.kiln.steady import batch as B

    kiln, _ = kiln_from_case(load_case(builtin_case_path("tscheng_A16")))
    kilns = [kiln, *operating_points(kiln, 40, seed=4)]
    cells = 40
    alone, original = [], B._alone
    monkeypatch.setattr(B, "_alone", lambda res, *a: alone.append(res) or original(res, *a))
    parts, chunk = [], B._solve_chunk
    monkeypatch.setattr(
        B, "_solve_chunk", lambda r, part, *a: parts.append(part) or chunk(r, part, *a)
    )
    monkeypatch.setattr(B, "SLOW_BATCH_FACTOR", 0.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        out = solve_batch(kilns, cells)
        assert len(parts) == 1  # the seeds, batched; then every other case alone
        assert len(alone) == len(kilns) - len(parts[0])
        others = [k for k in range(1, len(kilns)) if k not in parts[0]]
        for k in (0, others[0], others[-1]):
            single = solve_kiln(kilns[k], cells)
            np.testing.assert_array_equal(out[k].t_bed, single.t_bed)  # the same solve
    monkeypatch.setattr(B, "SLOW_BATCH_FACTOR", 2.0)
    alone.clear()
    parts.clear()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        solve_batch(kilns, cells)
    assert len(alone) == 1 and len(parts) == 3  # this kiln's Newton does not crawl


def test_the_work_count_is_each_threads_own():
    """The batch's cost rule counts the cells its own thread's residuals evaluate: cells x
    stacked states per evaluation, and a solve in another thread (a threaded scheduler's)
    not in it, so that every run makes the same choice."""
    import threading

    kiln, cells = kiln_from_case(load_case(builtin_case_path("tscheng_A16")))
    x = solve_kiln(kiln, cells).fluxes["x"]
    res = KilnResidual(kiln, cells)
    start = cell_evaluations()
    res.evaluate(x)
    res.evaluate(np.stack([x, x, x]))
    assert cell_evaluations() - start == cells + 3 * cells
    counted = []
    other = threading.Thread(
        target=lambda: counted.append((cell_evaluations(), res.evaluate(x), cell_evaluations()))
    )
    before = cell_evaluations()
    other.start()
    other.join()
    assert (counted[0][0], counted[0][2]) == (0, cells)  # the thread's own count
    assert cell_evaluations() == before


def test_batch_sizes_are_checked_and_reduced_to_fit_memory(caplog):
    kiln, cells = kiln_from_case(load_case(builtin_case_path("barr_T4")))
    res = KilnResidual(kiln, cells)
    for bad in (0, -3, 2.5):
        with pytest.raises(InputError, match="batch"):
            batch_size_for(res, bad)
    fits = batch_size_for(res)
    assert fits >= 1
    with caplog.at_level("INFO", logger="rotarykiln.kiln.steady.batch"):
        assert batch_size_for(res, 10 * fits) == fits
    assert "reduced" in caplog.text
    assert batch_size_for(res, 1) == 1
    tiny = batch_size_for(res, 100, memory=1)
    assert tiny == 1  # never below one case


def test_warnings_are_kept_per_case():
    kiln, cells = kiln_from_case(load_case(builtin_case_path("barr_T4")))
    kilns = [kiln, *operating_points(kiln, 2, seed=5)]
    caught: list = []
    solve_batch(kilns, cells, warnings_out=caught)
    assert len(caught) == 3
    # Barr's 2.5 mm sand lies outside the particle sizes of Li et al.'s fit: each case says so
    for ws in caught:
        assert any("Li et al." in str(w.message) for w in ws)


def test_a_batch_warns_each_case_of_what_its_own_solve_warns():
    """The closures' ranges are checked once for the whole batch and again only for the cases
    a warning's mask names: each case keeps the warnings of its own solve, no more, no less
    (Tscheng and Watkinson's gas Reynolds range, left by the lower gas flows only)."""
    kiln, cells = kiln_from_case(load_case(builtin_case_path("tscheng_A16")))
    factors = [(1.0, 1.0), (0.6, 1.0), (1.4, 1.0), (0.8, 2.0), (1.2, 0.5), (0.7, 0.7)]
    kilns = [
        kiln.replace(
            gas__flows={s: v * f for s, v in kiln.gas.flows.items()},
            drum__omega=kiln.drum.omega * w,
        )
        for f, w in factors
    ]
    caught: list = []
    solve_batch(kilns, cells, warnings_out=caught)
    warned = []
    for k, ws in zip(kilns, caught, strict=True):
        with warnings.catch_warnings(record=True) as alone:
            warnings.simplefilter("always")
            solve_kiln(k, cells)
        assert sorted({str(w.message) for w in ws}) == sorted({str(w.message) for w in alone})
        warned.append(any("Re =" in str(w.message) for w in ws))
    assert warned == [False, True, False, True, False, True]


def test_a_batch_warns_each_case_of_a_property_every_case_has():
    """Barr's 2.5 mm sand lies outside Li et al.'s particle sizes: a warning of one value,
    checked once for the batch and given to every case (with the gas Reynolds numbers each
    case warns of on its own), as each case's own solve warns."""
    kiln, cells = kiln_from_case(load_case(builtin_case_path("barr_T4")))
    kilns = [kiln, *operating_points(kiln, 4, seed=11)]
    caught: list = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        solve_batch(kilns, cells, warnings_out=caught)
    for k, ws in zip(kilns, caught, strict=True):
        with warnings.catch_warnings(record=True) as alone:
            warnings.simplefilter("always")
            solve_kiln(k, cells)
        assert sorted({str(w.message) for w in ws}) == sorted({str(w.message) for w in alone})
        assert any("Li et al." in str(w.message) for w in ws)


def test_broyden_updates_keep_the_secant_equation_and_reach_the_same_root():
    """Each update makes the inverse map the last residual change onto the last step
    (H y = s), and Newton on a kept Jacobian with the updates lands where Newton with its own
    Jacobians does, in fewer residual evaluations."""
    from rotarykiln.kiln.steady.batch import _Broyden, _factor, newton_batch

    rng = np.random.default_rng(2)
    n, nv = 12, 2
    bw = 2 * nv - 1
    size = n * nv
    dense = np.diag(rng.uniform(4.0, 5.0, size))
    for k in range(1, bw + 1):
        dense += np.diag(rng.uniform(-0.5, 0.5, size - k), k) + np.diag(
            rng.uniform(-0.5, 0.5, size - k), -k
        )
    ab = np.zeros((2 * bw + 1, size))
    for i in range(size):
        for j in range(max(0, i - bw), min(size, i + bw + 1)):
            ab[bw + i - j, j] = dense[i, j]
    factors = _factor(ab, bw)
    # two cases sharing the factors (solved in one LAPACK call), with their own secants
    secant = _Broyden(2, size, bw, 3)
    both = np.array([0, 1])
    shared = [factors, factors]
    f = rng.normal(size=(2, size))
    for _ in range(3):
        d, ok = secant.directions(shared, both, f)  # -H_k F_k
        assert ok.all()
        s, f_new = rng.normal(size=(2, size)), rng.normal(size=(2, size))
        secant.update(shared, both, d, s, f_new)
        mapped, _ = secant.apply(shared, both, f_new - f)
        np.testing.assert_allclose(mapped, s, rtol=1e-9, atol=1e-11)
        # the next direction it found is -H_{k+1} F_{k+1}
        np.testing.assert_allclose(secant.next, secant.apply(shared, both, -f_new)[0], rtol=1e-9)
        f = f_new
    # each case alone: the same inverse as in the pair
    alone = _Broyden(1, size, bw, 3)
    alone.c[0], alone.s[0], alone.count[0] = secant.c[1], secant.s[1], secant.count[1]
    np.testing.assert_allclose(
        alone.apply([factors], np.array([0]), f[1:])[0],
        secant.apply(shared, both, f)[0][1:],
        rtol=1e-12,
    )

    target = rng.uniform(300.0, 900.0, (2, 1, 1, 1))

    def F(x, cases):  # a mildly nonlinear chain, a different right-hand side per case
        ends = np.ones(x.shape[:-2] + (1, x.shape[-1]))
        t = np.concatenate([300.0 * ends, x, target[cases] * ends], axis=-2)
        lap = t[..., :-2, :] - 2.0 * t[..., 1:-1, :] + t[..., 2:, :]
        return lap - 1e-3 * (x - 500.0) ** 2 / 100.0

    evaluated = []  # states evaluated (cases x colours) per run

    def counted(x, cases):
        evaluated[-1] += x.shape[0] * x.shape[1]
        return F(x, cases)

    x0 = np.full((2, n, nv), 600.0)
    runs = {}
    for updates in (0, 12):
        evaluated.append(0)
        runs[updates] = newton_batch(counted, x0, np.ones(2), tol=1e-12, broyden=updates)
    (x_own, _, _, ok_own), (x_b, _, _, ok_b) = runs[0], runs[12]
    assert ok_own.all() and ok_b.all()
    np.testing.assert_allclose(x_b, x_own, rtol=0, atol=1e-8)
    assert evaluated[1] < evaluated[0]
