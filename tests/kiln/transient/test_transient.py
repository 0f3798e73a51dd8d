"""The transient kiln (issue 12): steady start stays put, steps reach the new steady state,
the tracer pulse gives the RTD of the bed profile, energy and elements are conserved in time;
the Jacobian BDF is given (issue 25): fewer colours than the steady Newton's block-tridiagonal
band, the same entries, its couplings found at a cold kiln too; the outputs' boundary flows are
those of the states one by one."""

import numpy as np
import pytest
from scipy.sparse import csc_matrix
from transient_kilns import (  # noqa: F401 (the fixtures)
    BARR_WALL,
    U_WALL,
    barr_fixture,
    limestone_fixture,
)

from rotarykiln.kiln.steady.newton import band_entries, colour_batch
from rotarykiln.kiln.transient.events import Schedule, kiln_at
from rotarykiln.kiln.transient.holdup import Holdup
from rotarykiln.kiln.transient.integrate import (
    JAC_STEP,
    TransientKiln,
    _gas_cell_temperature,
    _Run,
    simulate,
)
from rotarykiln.transient_file import parse_transient


def _new_steady(kiln, n, tr, until):
    """Unknowns of the steady solution of the inputs at the end of the run."""
    tk = TransientKiln(kiln, n, tr.wall)
    names = tk.res.bed_names, tk.res.gas_names
    sched = Schedule(kiln, *names, tr.events, until)
    u = sched.inputs(until, len(sched.segments()) - 1)
    x, _ = tk.steady_state(kiln_at(tk.kiln, u, *names))
    return x, tk.res.i_species


def test_steady_start_stays_put(barr):
    until = 10 * barr.residence_time
    tr = parse_transient({"wall": BARR_WALL, "output_every": "1 h"}, barr, until)
    sol = simulate(barr, 20, tr, until)
    i0 = sol.i_species
    drift = np.abs(sol.x[:, :, :i0] - sol.x[0, :, :i0]).max()
    assert drift < 0.01  # K, over 10 residence times


def test_reacting_steady_start_stays_put(limestone):
    until = 10 * limestone.residence_time
    tr = parse_transient({"wall": U_WALL, "output_every": "1 h"}, limestone, until)
    sol = simulate(limestone, 20, tr, until)
    i0 = sol.i_species
    # the rate law of order 1/2 is regularised below 1e-6 of the feed: a few mK
    assert np.abs(sol.x[:, :, :i0] - sol.x[0, :, :i0]).max() < 0.01


def test_fuel_step_tends_to_the_new_steady_state(barr):
    until = 1.0e5
    spec = {
        "wall": BARR_WALL,
        "events": [{"at": "10 min", "variable": "fuel_flow", "to": "2.2 NL/s"}],
        "output_every": "1 h",
    }
    tr = parse_transient(spec, barr, until)
    sol = simulate(barr, 20, tr, until)
    x1, i0 = _new_steady(barr, 20, tr, until)
    assert np.abs(sol.x[0, :, :i0] - x1[:, :i0]).max() > 50.0  # a real step
    assert np.abs(sol.x[-1, :, :i0] - x1[:, :i0]).max() < 0.5
    assert abs(sol.energy_conservation()[-1]) < 1e-6


def test_feed_step_of_a_calcining_kiln(limestone):
    until = 1.0e5
    spec = {
        "wall": U_WALL,
        "events": [{"at": "10 min", "variable": "feed", "to": "50 kg/h", "over": "10 min"}],
        "output_every": "1 h",
    }
    tr = parse_transient(spec, limestone, until)
    # rtol 1e-7: at the default 1e-6 the used-up CaCO3 of the last cells ends ~1e-4 (of its
    # inlet flow) below 0, the integrator's error there, not a steady-state difference
    sol = simulate(limestone, 20, tr, until, rtol=1e-7)
    x1, i0 = _new_steady(limestone, 20, tr, until)
    assert np.abs(sol.x[-1, :, :i0] - x1[:, :i0]).max() < 0.5
    assert np.abs(sol.x[-1, :, i0:] - x1[:, i0:]).max() < 1e-4  # flows over the inlet flows
    assert max(sol.element_conservation().values()) < 1e-6


def test_cold_start_conserves_energy_and_elements(barr):
    until = 7200.0
    tr = parse_transient({"wall": BARR_WALL, "start": "cold"}, barr, until)
    sol = simulate(barr, 20, tr, until, rtol=1e-8, newton_tol=1e-6)
    assert sol.outlet[-1]["bed_outlet_temperature_K"] > 700.0  # heating up
    assert abs(sol.energy_conservation()[-1]) < 1e-6
    assert max(sol.element_conservation().values()) < 1e-10


def test_tracer_pulse_gives_the_rtd(barr):
    """Mean residence time to 1 %; variance of the dispersion model (closed ends) to 5 %
    once the numerical dispersion of the cell scheme is counted: each cell is a stirred tank
    of the hold-up, so the scheme adds the variance of n tanks in series, tau^2 / n."""
    n = 100
    kiln = barr.replace(bed__dispersion=1.43e-5)
    tau = kiln.residence_time
    until = 2.2 * tau
    spec = {"wall": BARR_WALL, "tracer": {"duration": "1 min"}, "output_every": "1 min"}
    tr = parse_transient(spec, kiln, until)
    sol = simulate(kiln, n, tr, until)
    rtd = sol.rtd(0.0, 60.0)
    assert rtd["recovered_fraction"] == pytest.approx(1.0, abs=1e-3)
    assert rtd["mean_residence_time_s"] == pytest.approx(tau, rel=0.01)
    pe = kiln.bed.velocity * kiln.drum.length / kiln.bed.dispersion
    model = (2.0 / pe - 2.0 / pe**2 * (1.0 - np.exp(-pe))) * tau**2
    physical = rtd["variance_s2"] - tau**2 / n
    assert physical == pytest.approx(model, rel=0.05)


def test_drum_stop_holds_the_bed(barr):
    until = 3600.0
    spec = {
        "wall": BARR_WALL,
        "events": [
            {"at": "10 min", "variable": "drum", "to": "stop"},
            {"at": "40 min", "variable": "drum", "to": "run"},
        ],
        "output_every": "5 min",
    }
    tr = parse_transient(spec, barr, until)
    sol = simulate(barr, 20, tr, until)
    stopped = (sol.t > 600.0) & (sol.t < 2400.0)
    out = np.array([o["solids_outlet_flow_kg_s"] for o in sol.outlet])
    assert np.all(out[stopped] == 0.0)
    held = sol.inventory_bed[:, 0]
    assert np.ptp(held[stopped]) < 1e-9 * held[0]  # nothing in, nothing out
    assert out[-1] > 0.5 * barr.feed_flow  # running again
    assert abs(sol.energy_conservation()[-1]) < 1e-5


@pytest.mark.parametrize("name, wall", [("barr_T4", BARR_WALL), ("limestone_fired", U_WALL)])
def test_jacobian_is_the_finite_difference_jacobian(name, wall, barr, limestone):
    """The coloured, batched Jacobian given to BDF equals a plain (column by column, uncoloured)
    central-difference Jacobian of the same right-hand side at a random state. Its forward
    differences of relative step 1e-7 err by ~h|f''| + eps|f|/h, ~1e-7 to 1e-6 of a row's
    largest entry (the central reference by ~1e-10): 1e-5 of the row's largest entry. The
    species are kept off 0, where the flow is clipped (a kink: one-sided derivatives differ)."""
    kiln = barr if name == "barr_T4" else limestone
    tr = parse_transient({"wall": wall}, kiln, 3600.0)
    tk = TransientKiln(kiln, 20, tr.wall)
    res = tk.res
    sched = Schedule(kiln, res.bed_names, res.gas_names, tr.events, 3600.0, tr.tracer)
    u = sched.inputs(0.0, 0)
    x, _ = tk.steady_state()
    rng = np.random.default_rng(25)
    i0 = res.i_species
    x[:, :i0] += rng.uniform(-50.0, 50.0, x[:, :i0].shape)
    x[:, i0:] = x[:, i0:] * rng.uniform(0.8, 1.2, x[:, i0:].shape) + rng.uniform(
        0.01, 0.05, x[:, i0:].shape
    )
    tk.holdup = Holdup.of(res, tr.wall, _gas_cell_temperature(res, x, u), tk.layer_parent)
    y = tk.pack(x, rng.uniform(0.0, 1e-3, tk.n))
    run = _Run()
    J = tk.jacobian(0.0, y, sched, run).toarray()
    assert J.shape == (tk.size, tk.size)
    nm = tk.n * tk.m
    floor = np.concatenate([np.tile(tk.jac_floor, tk.n), np.ones(tk.n_acc)])
    h = 1e-5 * np.maximum(np.abs(y), floor)
    h = (y + h) - y
    E = np.diag(h)
    fd = (tk.rhs(0.0, y[:, None] + E, sched, run) - tk.rhs(0.0, y[:, None] - E, sched, run)) / (
        2.0 * h
    )
    row = np.abs(fd[:nm]).max(1, keepdims=True)
    assert np.all(row > 0)
    # every entry of the cell rows, the band and (zero) off it, the quadrature columns too
    assert np.all(np.abs(J[:nm] - fd[:nm]) <= 1e-5 * row)
    assert not J[nm:].any()  # the quadrature rows feed back into nothing: left empty


def _system(kiln, wall, x=None, n=20):
    """A transient kiln of ``n`` cells with its hold-ups, its schedule (no event) and a state:
    ``x`` or the cold kiln."""
    tr = parse_transient({"wall": wall}, kiln, 3600.0)
    tk = TransientKiln(kiln, n, tr.wall)
    res = tk.res
    sched = Schedule(kiln, res.bed_names, res.gas_names, tr.events, 3600.0, tr.tracer)
    u = sched.inputs(0.0, 0)
    if x is None:
        x = tk.cold_state(u)
    tk.holdup = Holdup.of(res, tr.wall, _gas_cell_temperature(res, x, u), tk.layer_parent)
    return tk, sched, x


def _band_jacobian(tk, t, y, sched, run):
    """The steady Newton's Jacobian: the block-tridiagonal band in 3 m colours."""
    n, m = tk.n, tk.m
    nm = n * m
    src, rows, cols, step = band_entries(n, m)
    blk = y[:nm].reshape(n, m)
    h = JAC_STEP * np.maximum(np.abs(blk), tk.jac_floor)
    h = (blk + h) - blk
    Y = np.empty((tk.size, 3 * m + 1))
    Y[:nm, :-1] = colour_batch(blk, h).reshape(3 * m, nm).T
    Y[:nm, -1] = y[:nm]
    Y[nm:] = y[nm:, None]
    F = tk.rhs(t, Y, sched, run)
    dR = F[:nm, :-1].T - F[:nm, -1]
    data = dR.ravel()[src] / h.ravel()[step]
    return csc_matrix((data, (rows, cols)), shape=(tk.size, tk.size)).toarray()


@pytest.mark.parametrize("name, wall", [("barr_T4", BARR_WALL), ("limestone_fired", U_WALL)])
def test_coloured_jacobian_is_the_band_jacobian_to_the_last_bit(name, wall, barr, limestone):
    """At a random state (species off 0, a tracer held), the Jacobian of few colours has the
    entries of the band Jacobian of 3 m colours exactly: each entry is the difference quotient
    of its own column, and the columns a colour shares never reach the same row. Barr's lined
    kiln (bed dispersion, counter-current gas, 6 wall nodes) needs 18 colours, not 45 (27 when
    a column reaches every row of the cells it reaches)."""
    kiln = barr if name == "barr_T4" else limestone
    tk, sched, _ = _system(kiln, wall)
    x, _ = tk.steady_state()
    rng = np.random.default_rng(7)
    i0 = tk.res.i_species
    x[:, :i0] += rng.uniform(-50.0, 50.0, x[:, :i0].shape)
    x[:, i0:] = x[:, i0:] * rng.uniform(0.8, 1.2, x[:, i0:].shape) + 0.01
    y = tk.pack(x, rng.uniform(0.0, 1e-3, tk.n))
    run = _Run()
    J = tk.jacobian(0.0, y, sched, run).toarray()
    assert np.array_equal(J, _band_jacobian(tk, 0.0, y, sched, run))
    colours = tk._structure()[1]
    assert colours < 3 * tk.m
    if name == "barr_T4":
        assert colours == 18 and tk.m == 15


def test_probe_at_a_cold_kiln_finds_the_couplings_of_a_hot_one(barr):
    """At ambient every sensible enthalpy is 0, and Barr's bed is one species: the dispersion
    of the bed flow of a cell into the cell before it (enthalpy and composition) vanishes
    there, and the band Jacobian of the cold state alone misses it; the probe's spread state
    finds it. The wall nodes reach their own cell only, the counter-current gas the next cell
    along the gas (the one before it), the dispersed bed both neighbours. Rows: the inner wall
    reaches the cell's fluid rows (its exchange) and the first interface's; a node inside the
    lining only the rows of its neighbouring nodes (conduction), the shell's too."""
    tk, sched, x = _system(barr, BARR_WALL)
    couplings = tk.probe(0.0, tk.pack(x), sched, _Run())
    cold = tk.reach
    hot_tk, hot_sched, hot_x = _system(barr, BARR_WALL, tk.steady_state()[0])
    assert np.array_equal(couplings, hot_tk.probe(0.0, hot_tk.pack(hot_x), hot_sched, _Run()))
    hot = hot_tk.reach
    assert np.array_equal(cold, hot)
    i0, nb, ng = tk.res.i_species, tk.res.nb, tk.res.ng
    assert np.array_equal(cold[2:i0], np.tile([False, True, False], (i0 - 2, 1)))
    assert np.array_equal(cold, couplings.any(-1))
    fluid = np.r_[0, 1, i0 : i0 + nb + ng]
    own = couplings[:, 1]
    assert own[2, fluid].all() and own[2, 2:4].all() and not own[2, 4:i0].any()
    for k in range(3, i0):  # inside the lining and the shell: conduction to the neighbours
        assert np.array_equal(np.flatnonzero(own[k]), np.arange(k - 1, min(k + 2, i0)))
    # the gas (temperature, species): its own cell and the one its gas enters (j - 1)
    gas = np.tile([True, True, False], (ng, 1))
    assert np.array_equal(cold[1], gas[0]) and np.array_equal(cold[i0 + nb : i0 + nb + ng], gas)
    assert cold[0].all() and cold[i0 : i0 + nb].all() and cold[-1].all()  # bed, tracer


@pytest.mark.parametrize("name, wall", [("barr_T4", BARR_WALL), ("limestone_fired", U_WALL)])
def test_columns_of_a_colour_reach_no_common_row(name, wall, barr, limestone):
    """The colouring of the Jacobian's columns: every column has one colour, and no row is
    reached by two columns of one colour (else their differences would mix in that entry);
    with Barr's lining the nodes inside it share the colours of the fluid variables."""
    kiln = barr if name == "barr_T4" else limestone
    tk, sched, x = _system(kiln, wall)
    tk.probe(0.0, tk.pack(x), sched, _Run())
    flat_colour, k, src, cols, rows, indptr = tk._structure()
    nm = tk.n * tk.m
    assert flat_colour.shape == (nm,) and set(flat_colour) == set(range(k))
    assert np.array_equal(cols, np.repeat(np.arange(tk.size), np.diff(indptr)))
    pairs = flat_colour[cols] * nm + rows
    assert np.unique(pairs).size == pairs.size  # (colour, row) met once
    assert np.array_equal(src, pairs)
    if name == "barr_T4":
        colour = flat_colour.reshape(tk.n, tk.m)
        fluid = set(colour[:, [0, 1, *range(tk.res.i_species, tk.res.nv)]].ravel())
        assert set(colour[:, 3 : tk.res.i_species].ravel()) <= fluid


def test_batched_boundary_flows_are_those_of_the_states_one_by_one(barr):
    """The outputs' boundary flows are evaluated for many states at once: the same values as
    state by state."""
    tk, sched, _ = _system(barr, BARR_WALL)
    x, _ = tk.steady_state()
    rng = np.random.default_rng(3)
    i0 = tk.res.i_species
    Y = np.stack([tk.pack(x) for _ in range(4)])
    Y[1:, : tk.n * tk.m].reshape(3, tk.n, tk.m)[..., :i0] += rng.uniform(-5.0, 5.0, (3, tk.n, i0))
    run = _Run()
    dy, flux = tk.rhs(0.0, Y.T, sched, run, fluxes=True)
    for k in range(4):
        dy_k, flux_k = tk.rhs(0.0, Y[k], sched, run, fluxes=True)
        assert np.allclose(dy[:, k], dy_k, rtol=1e-13, atol=0.0)
        for key, v in flux_k.items():
            if isinstance(v, dict):
                assert all(np.isclose(flux[key][s][k], v[s], rtol=1e-13, atol=0) for s in v)
            else:
                assert np.allclose(flux[key][k], v, rtol=1e-13, atol=0.0), key
