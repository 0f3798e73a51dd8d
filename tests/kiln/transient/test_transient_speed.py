"""What makes the transient's right-hand side and Jacobian cheaper (issue 25) gives the numbers
it replaced, to the last bit: the residual's enthalpies with the heat capacities at the outlets,
the Jacobian's differences from a right-hand side already known, the inputs of a time kept, the
gas enthalpies handed to the global balance, a lining's sub-layers of one material in one call,
the shell loss's air properties at one lookup."""

import numpy as np
import pytest
from transient_kilns import (  # noqa: F401 (the fixtures)
    BARR_WALL,
    U_WALL,
    barr_fixture,
    limestone_fixture,
)

from rotarykiln.errors import InputError
from rotarykiln.heat.wall import cylinder_layer_heat_flow, shell_heat_loss
from rotarykiln.kiln.accounting import global_balance
from rotarykiln.kiln.residual import T_FLOOR
from rotarykiln.kiln.transient.events import Schedule
from rotarykiln.kiln.transient.holdup import Holdup
from rotarykiln.kiln.transient.integrate import (
    CP_STEP,
    TransientKiln,
    _gas_cell_temperature,
    _Run,
)
from rotarykiln.kiln.wall.lining import LinedWall
from rotarykiln.materials.gas import air_table
from rotarykiln.materials.lining import Layer, load_lining_material
from rotarykiln.transient_file import parse_transient


def _system(kiln, wall, events=(), until=3600.0):
    """A transient kiln of 20 cells at a state off its steady solution (the bed at the quartz
    transition in some cells: the enthalpies' pieces switch there), with its schedule."""
    spec = {"wall": wall, "events": list(events)}
    tr = parse_transient(spec, kiln, until)
    tk = TransientKiln(kiln, 20, tr.wall)
    res = tk.res
    sched = Schedule(kiln, res.bed_names, res.gas_names, tr.events, until, tr.tracer)
    u = sched.inputs(0.0, 0)
    x, _ = tk.steady_state()
    rng = np.random.default_rng(11)
    i0 = res.i_species
    x[:, :i0] += rng.uniform(-60.0, 60.0, x[:, :i0].shape)
    x[:, i0:] = x[:, i0:] * rng.uniform(0.8, 1.2, x[:, i0:].shape) + 0.01
    tk.holdup = Holdup.of(res, tr.wall, _gas_cell_temperature(res, x, u), tk.layer_parent)
    return tk, sched, u, x


@pytest.mark.parametrize("name, wall", [("barr_T4", BARR_WALL), ("limestone_fired", U_WALL)])
def test_residual_heat_capacities_come_with_the_same_residual(name, wall, barr, limestone):
    """``heat_capacity_step``: the residual, its fluxes and faces as without it, the face
    enthalpies those of the enthalpy calls, and dh/dT at the outlets the central differences
    of separate calls (an inert bed, and a calcining one with its cell enthalpies)."""
    tk, _, u, x = _system(barr if name == "barr_T4" else limestone, wall)
    res = tk.res
    X = np.stack([x, x + 3.0 * (np.arange(res.nv) < res.i_species)])  # a batch of two
    plain = res.evaluate(X, full=True, inputs=u)
    R, fl, prod, rate, faces, (hb, cb, hg, cg) = res.evaluate(
        X, full=True, inputs=u, heat_capacity_step=CP_STEP
    )
    assert np.array_equal(R, plain[0]) and np.array_equal(prod, plain[2])
    assert np.array_equal(rate, plain[3])
    assert all(np.array_equal(a, b) for a, b in zip(faces, plain[4], strict=True))
    assert fl.keys() == plain[1].keys()
    assert all(np.array_equal(fl[k], plain[1][k]) for k in fl)
    tbn, tgn = np.maximum(faces[0], T_FLOOR), np.maximum(faces[1], T_FLOOR)
    assert np.array_equal(hb, res.bed_enthalpy(tbn))
    assert np.array_equal(hg, res.mixture.species_enthalpy(tgn))
    tb, tg = tbn[..., 1:], tgn[..., res.gas_out]
    up, down = res.bed_enthalpy(tb + CP_STEP), res.bed_enthalpy(tb - CP_STEP)
    assert np.array_equal(cb, (up - down) / (2 * CP_STEP))
    up, down = (res.mixture.species_enthalpy(tg + s * CP_STEP) for s in (1, -1))
    assert np.array_equal(cg, (up - down) / (2 * CP_STEP))
    assert np.all(cb > 0) and np.all(cg > 0)


def test_jacobian_from_a_known_right_hand_side_is_the_same(barr):
    """The Jacobian's differences taken from the right-hand side the caller has (BDF's
    predicted state, whose Newton iteration failed) equal those of the batch's own base."""
    tk, sched, _, x = _system(barr, BARR_WALL)
    y = tk.pack(x, np.linspace(0.0, 1e-3, tk.n))
    run = _Run()
    J = tk.jacobian(0.0, y, sched, run)
    f = tk.rhs(0.0, y, sched, run)
    calls = run.calls
    J_f = tk.jacobian(0.0, y, sched, run, f=f)
    assert run.calls == calls + 1  # one batched call
    assert (J != J_f).nnz == 0 and J.nnz == J_f.nnz
    assert np.array_equal(J.indices, J_f.indices) and np.array_equal(J.indptr, J_f.indptr)


def test_a_state_alone_or_in_a_batch_has_the_same_right_hand_side(barr):
    """What the known right-hand side relies on: a state's rates are the same numbers alone
    and among others (perturbed ones, as the Jacobian's batch)."""
    tk, sched, _, x = _system(barr, BARR_WALL)
    y = tk.pack(x)
    Y = np.repeat(y[:, None], 4, axis=1)
    Y[: tk.n * tk.m : 7, 1:] *= 1.0 + 1e-7 * np.arange(1, 4)
    run = _Run()
    F = tk.rhs(0.0, Y, sched, run)
    for k in range(4):
        assert np.array_equal(F[:, k], tk.rhs(0.0, Y[:, k].copy(), sched, run))


def test_inputs_of_a_time_are_kept_and_a_ramp_still_moves(limestone):
    """The schedule keeps the last inputs (an implicit step asks for one time many times):
    the same object at the same time and segment, the interpolated ramp at another time, the
    same values as a schedule asked for the first time."""
    events = [{"at": "10 min", "variable": "feed", "to": "60 kg/h", "over": "20 min"}]
    tk, sched, _, _ = _system(limestone, U_WALL, events)
    names = tk.res.bed_names, tk.res.gas_names
    fresh = Schedule(limestone, *names, sched.events, 3600.0)
    ramp = [i for i, (a, b) in enumerate(sched.segments()) if a == 600.0][0]
    for t in (900.0, 900.0, 1200.0, 900.0):
        u = sched.inputs(t, ramp)
        assert sched.inputs(t, ramp) is u
        v = Schedule(limestone, *names, sched.events, 3600.0).inputs(t, ramp)
        assert np.array_equal(u.vector(), v.vector())
    assert sched.inputs(1200.0, ramp).feed.sum() > fresh.inputs(900.0, ramp).feed.sum()


def test_global_balance_with_the_gas_enthalpies_given(barr):
    """The global balance with the gas enthalpies handed in equals the one that computes
    them (only the ends' are read)."""
    tk, sched, u, x = _system(barr, BARR_WALL)
    res = tk.res
    R, fl, prod, _, faces, (hb, _, hg, _) = res.evaluate(
        x[None], full=True, inputs=u, heat_capacity_step=CP_STEP
    )
    tbn, tgn = (np.maximum(f, T_FLOOR) for f in faces[:2])
    a = global_balance(res, fl, prod, tbn, tgn, *faces[2:], u, reaction_from_sources=True)
    given = {"bed_enthalpy": hb, "gas_enthalpy": hg}
    b = global_balance(res, fl, prod, tbn, tgn, *faces[2:], u, **given, reaction_from_sources=True)
    assert a.keys() == b.keys() and all(np.array_equal(a[k], b[k]) for k in a)


def _lining():
    """A castable cut into 3 sub-layers, then a steel shell: two runs of one material."""
    castable = Layer(load_lining_material("fireclay_brick"), 0.03)
    steel = Layer(load_lining_material("carbon_steel"), 0.01)
    layers = (castable, castable, castable, steel)
    radii = 0.5 + np.cumsum([0.0, 0.03, 0.03, 0.03, 0.01])[:, None] * np.ones((1, 4))
    return LinedWall(layers, radii, 0.8, 300.0, 2.0)


def test_lining_flows_by_runs_of_one_material_are_the_layers_one_by_one():
    wall = _lining()
    assert [(a, b) for a, b, _ in wall._conduction[0]] == [(0, 3), (3, 4)]
    rng = np.random.default_rng(5)
    tl = np.sort(rng.uniform(320.0, 1400.0, (2, 4, 5)), -1)[..., ::-1].copy()
    q = wall.layer_flows(tl)
    for i, layer in enumerate(wall.layers):
        K = layer.material.conductivity_integral
        one = cylinder_layer_heat_flow(
            K(tl[..., i]), K(tl[..., i + 1]), wall.radii[i], wall.radii[i + 1]
        )
        assert np.array_equal(q[..., i], one)
        assert np.array_equal(q[..., i], wall._layer_flow(tl, i))
    rows, loss = wall.balance(np.full((2, 4), 5000.0), tl)
    assert len(rows) == 5 and np.all(q > 0)
    assert np.allclose(sum(rows), 5000.0 - loss, rtol=1e-12, atol=1e-9)  # telescoping


def test_shell_loss_unchecked_and_its_air_at_one_lookup_is_the_same():
    air = air_table()
    ts = np.linspace(310.0, 700.0, 9)
    checked = shell_heat_loss(ts, 300.0, 1.2, 0.85, air, 2.0)
    assert np.array_equal(shell_heat_loss(ts, 300.0, 1.2, 0.85, air, 2.0, check=False), checked)
    cp, k, mu = air.cp_conductivity_viscosity(ts)
    assert np.array_equal(cp, air.cp(ts)) and np.array_equal(k, air.conductivity(ts))
    assert np.array_equal(mu, air.viscosity(ts))
    with pytest.raises(InputError):
        shell_heat_loss(ts, 300.0, 1.2, 1.5, air)


def test_lined_wall_checks_its_shell_when_built():
    """The residual's shell loss does not check the wall any more: the wall is checked when
    it is built."""
    wall = _lining()
    for change in ({"eps_shell": 1.5}, {"ambient_temperature": -1.0}, {"wind_speed": -1.0}):
        kw = {"eps_shell": 0.8, "ambient_temperature": 300.0, "wind_speed": 0.0} | change
        with pytest.raises(InputError):
            LinedWall(wall.layers, wall.radii, **kw)
