"""Grid sequencing's start (rotarykiln.kiln.steady.continuation): the unknowns carried from a
coarse grid to a fine one across the fronts the coarse grid spreads over a cell, and the
wall's local unknowns relaxed before the fine Newton (rotarykiln.kiln.steady.newton)."""

import warnings
from types import SimpleNamespace

import numpy as np
import pytest

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.residual import KilnResidual
from rotarykiln.kiln.steady import continuation as steady
from rotarykiln.kiln.steady.newton import newton_banded, relax_local
from rotarykiln.kiln.steady.solve import newton_options, solve_kiln


def _grid(n, length=10.0, nb=1, ng=1, counter=True):
    """A stand-in residual of ``n`` cells: what interpolate_unknowns reads of its grids."""
    z_nodes = np.linspace(0.0, length, n + 1)
    return SimpleNamespace(
        n=n,
        nv=2 + nb + ng,
        z=0.5 * (z_nodes[1:] + z_nodes[:-1]),
        z_nodes=z_nodes,
        gas_out=slice(None, -1) if counter else slice(1, None),
        gas_in_face=-1 if counter else 0,
        i_species=2,
        nb=nb,
        bed_pos=list(range(nb)),
        gas_pos=list(range(ng)),
        sqrt_mask=np.zeros(nb, dtype=bool),
        bed_scale=1.0,
        gas_scale=1.0,
    )


def _with_faces(src, tb, tg, qb, qg):
    src.faces = lambda x: (np.asarray(tb), np.asarray(tg), np.asarray(qb), np.asarray(qg))
    return src


def test_a_smooth_profile_is_carried_linearly():
    coarse, fine = _grid(4), _grid(20)
    z = coarse.z_nodes
    _with_faces(
        coarse, 300 + 10 * z, 900 - 5 * z, (1 - 0.05 * z)[:, None], (0.1 + 0.01 * z)[:, None]
    )
    y = steady.interpolate_unknowns(coarse, np.zeros((4, coarse.nv)), fine)
    zf = fine.z_nodes
    np.testing.assert_allclose(y[:, 0], (300 + 10 * zf)[1:], rtol=1e-14)
    np.testing.assert_allclose(y[:, 1], (900 - 5 * zf)[:-1], rtol=1e-14)
    np.testing.assert_allclose(y[:, 2], (1 - 0.05 * zf)[1:], rtol=1e-14)
    np.testing.assert_allclose(y[:, 3], (0.1 + 0.01 * zf)[:-1], rtol=1e-14)


def test_a_reactant_used_up_within_a_coarse_cell_is_used_up_in_the_first_fine_cell():
    # the bed's reactant falls 1000-fold across coarse cell 1 (z 2.5-5 m): every fine face in
    # it takes the far face's flow; the gas's CO2 from it joins the gas at the front (z = 2.5 m)
    coarse, fine = _grid(4), _grid(20)
    qb = np.array([1.0, 0.9, 9e-4, 8e-4, 7e-4])[:, None]
    qg = np.array([0.5, 0.45, 0.05, 0.05, 0.05])[:, None]  # counter-current: enters at z = 10
    _with_faces(coarse, np.full(5, 1000.0), np.full(5, 1200.0), qb, qg)
    y = steady.interpolate_unknowns(coarse, np.zeros((4, coarse.nv)), fine)
    zf = fine.z_nodes
    inside = (zf > 2.5 + 1e-9) & (zf <= 5.0 + 1e-9)
    np.testing.assert_array_equal(y[inside[1:], 2], 9e-4)
    np.testing.assert_allclose(
        y[(zf[1:] <= 2.5 + 1e-9), 2],
        np.interp(zf, coarse.z_nodes, qb[:, 0])[1:][zf[1:] <= 2.5 + 1e-9],
    )
    gas = y[:, 3]  # the gas leaving fine cells at faces 0..19
    np.testing.assert_array_equal(gas[inside[:-1]], 0.05)
    assert gas[list(zf[:-1]).index(2.5)] == pytest.approx(0.45)


@pytest.mark.parametrize("counter", [True, False])
def test_a_stream_heated_within_its_inlet_cell_is_hot_from_the_first_fine_face(counter):
    coarse, fine = _grid(4, counter=counter), _grid(20, counter=counter)
    tb = np.array([1148.0, 1456.0, 1460.0, 1465.0, 1470.0])  # the feed heated within cell 0
    tg = np.array([2600.0, 2610.0, 2620.0, 2640.0, 1450.0])  # counter: the gas enters at z = 10
    if not counter:
        tg = tg[::-1].copy()
    _with_faces(coarse, tb, tg, np.ones((5, 1)), np.ones((5, 1)))
    y = steady.interpolate_unknowns(coarse, np.zeros((4, coarse.nv)), fine)
    np.testing.assert_array_equal(y[:5, 0], 1456.0)  # fine faces 1-5: in coarse cell 0
    assert y[5, 0] == pytest.approx(np.interp(fine.z_nodes[6], coarse.z_nodes, tb))
    if counter:  # the gas leaving fine cells 15-19 (faces 15-19, coarse cell 3)
        np.testing.assert_array_equal(y[15:, 1], 2640.0)
    else:  # the gas leaving fine cells 0-4 (faces 1-5, coarse cell 0)
        np.testing.assert_array_equal(y[:5, 1], 2640.0)


def test_front_and_inlet_tests():
    assert steady.front_cells(np.array([[1.0], [1e-3], [1e-4]])).tolist() == [True, False]
    # a product rising from nothing, or a reactant below the floor of its largest flow, is not
    assert not steady.front_cells(np.array([[0.0], [0.5], [1.0]])).any()
    assert steady.front_cells(np.array([[1.0], [1e-7], [1e-10]])).tolist() == [True, False]
    assert steady.inlet_front([300.0, 800.0, 850.0])
    assert not steady.inlet_front([300.0, 400.0, 500.0])
    assert not steady.inlet_front([300.0, 400.0])


@pytest.fixture(scope="module")
def cement():
    """The cement kiln on 200 cells, its start from its 40-cell solution (interpolated, and
    with the wall relaxed), the Newton options."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        kiln, cells = kiln_from_case(load_case(builtin_case_path("cement_kiln")))
        fine = KilnResidual(kiln, cells)
        coarse = KilnResidual(kiln, cells // 5, q_ref=fine.q_ref)
        x = solve_kiln(kiln, coarse.n, tol=1e-8).fluxes["x"]
        kw = newton_options(fine, tol=1e-11, max_iter=60)
        start = steady.interpolate_unknowns(coarse, x, fine)
        relaxed = relax_local(fine, start, fine.q_ref, kw["local"])
    return fine, start, relaxed, kw


def _rows(F, x):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return np.abs(F.evaluate(x)) / F.q_ref


def test_the_cement_kiln_carried_from_40_cells_to_200_converges_from_its_first_steps(cement):
    # the ferrite formed within the first metre of the hot meal, the meal heated by 300 K and
    # the burner's gas by 1100 K within a coarse cell, the wall across the coating's start:
    # linearly interpolated, the start had a residual of 7e5 and its Newton failed
    fine, start, relaxed, kw = cement
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        _, report = newton_banded(fine, relaxed, fine.q_ref, **kw)
    assert _rows(fine, start).max() < 1e3
    assert _rows(fine, relaxed).max() < 0.1 * _rows(fine, start).max()  # the coating's start
    assert report.iterations <= 12
    assert report.history[1] < 0.5 * report.history[0]  # no damped start (was 98 -> 79)


def test_relaxing_the_local_unknowns_holds_every_other_unknown(cement):
    fine, start, relaxed, kw = cement
    local = kw["local"]
    np.testing.assert_array_equal(relaxed[:, ~local], start[:, ~local])
    assert _rows(fine, relaxed)[:, local].max() < 1e-2 * _rows(fine, start)[:, local].max()


def test_a_relaxation_that_does_not_lower_the_residual_is_not_taken():
    # the local unknown's own row is lowered, the row of the unknown it also acts on grows
    def F(x):
        return np.stack([100.0 * (x[..., 1] - 2.0), x[..., 1] - 3.0], -1)

    x = np.array([[1.0, 2.0]])
    np.testing.assert_array_equal(relax_local(F, x, 1.0, [False, True]), x)
