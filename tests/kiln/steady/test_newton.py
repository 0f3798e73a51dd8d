"""The banded Newton solver: squared unknowns stepped in their square (kiln/steady/newton.py)."""

from __future__ import annotations

import numpy as np
import pytest

from rotarykiln.chemistry.ratelaws import RATE_LAWS
from rotarykiln.errors import ConvergenceError
from rotarykiln.kiln.steady.newton import newton_banded


def _first_order_reactant(k_dz: float, q_in: float = 1.0):
    """Upwind cells of dq/dz = -k q, solved for s = sqrt(q): q_j (1 + k dz) - q_{j-1} = 0."""

    def F(x):
        s = x[..., 0]
        q = s * s
        prev = np.concatenate([np.full(q.shape[:-1] + (1,), q_in), q[..., :-1]], axis=-1)
        return (q * (1.0 + k_dz) - prev)[..., None]

    return F


def test_used_up_first_order_reactant_converges_quadratically_stepped_in_its_square():
    n, k_dz = 40, 2.0  # q falls by 3^40 ~ 1e-19 along the cells: a used-up reactant
    F = _first_order_reactant(k_dz)
    exact = (1.0 + k_dz) ** -np.arange(1, n + 1)
    x0 = np.full((n, 1), 0.5)
    kw = dict(tol=1e-14, temperature_vars=0, step_floor=1e-12, max_iter=200)
    x_q, rep_q = newton_banded(F, x0, 1.0, squared=np.array([True]), **kw)
    x_s, rep_s = newton_banded(F, x0, 1.0, **kw)
    np.testing.assert_allclose(x_q[:, 0] ** 2, exact, rtol=1e-9, atol=1e-14)
    np.testing.assert_allclose(x_s[:, 0] ** 2, exact, rtol=1e-6, atol=1e-14)
    # the residual is linear in q: Newton in q needs a handful of steps (the floor keeps q > 0),
    # Newton in s halves s per step at the double root near q = 0
    assert rep_q.iterations <= 12
    assert rep_s.iterations >= 2 * rep_q.iterations
    assert np.all(x_q[:, 0] ** 2 > 0)


def test_squared_unknowns_never_cross_zero():
    F = _first_order_reactant(50.0)
    seen = []

    def G(x):
        seen.append(np.array(x[..., 0]))
        return F(x)

    newton_banded(G, np.full((10, 1), 1.0), 1.0, tol=1e-13, temperature_vars=0,
                  step_floor=1e-12, squared=np.array([True]), max_iter=100)  # fmt: skip
    assert min(float(np.min(v)) for v in seen) > 0.0


def test_a_stalling_solve_gives_up_after_its_stall_iterations_and_a_slow_one_goes_on():
    F = _first_order_reactant(2.0)
    calls = []

    def G(x):
        calls.append(1)
        return F(x)

    kw = dict(tol=1e-14, temperature_vars=0, step_floor=1e-12, max_iter=200)
    # Newton in s is slow here (it halves s per step) but keeps lowering the residual: a stall
    # test it passes goes on to convergence ...
    _, rep = newton_banded(G, np.full((40, 1), 0.5), 1.0, stall=(3, 0.9), **kw)
    assert rep.residual <= 1e-14 and rep.iterations > 3
    # ... one it fails gives up at its iteration count, not at max_iter: exp(x) falls by e per
    # Newton step (dx = -1), 55-fold in 4 steps, and reaches 1e-10 only after 25

    def H(x):
        return np.exp(x)

    kw = dict(tol=1e-10, temperature_vars=0, max_iter=60)
    _, slow = newton_banded(H, np.ones((5, 1)), 1.0, **kw)
    assert slow.iterations == 25
    with pytest.raises(ConvergenceError) as failed:
        newton_banded(H, np.ones((5, 1)), 1.0, stall=(4, 1e-2), **kw)
    assert failed.value.diagnostics["iterations"] == 4


def test_a_continuation_steps_line_search_halves_fewer_times():
    # no step lowers |x^2 + 1|'s minimum at x = 0: every halving of the line search is a
    # residual evaluation; a continuation's step (stall given) stops at STALL_HALVINGS
    from rotarykiln.kiln.steady import newton

    calls = []

    def F(x):
        calls.append(np.ndim(x))
        return x * x + 1.0

    def plain_evaluations(**kw):
        calls.clear()
        with pytest.raises(ConvergenceError):
            newton_banded(F, np.zeros((3, 1)), 1.0, temperature_vars=0, max_iter=1, **kw)
        return sum(1 for d in calls if d == 2)

    assert plain_evaluations() == 1 + newton.HALVINGS
    assert plain_evaluations(stall=(8, 1e-2)) == 1 + newton.STALL_HALVINGS


def test_a_continuation_step_asking_for_a_newton_step_of_1e6_k_is_given_up_at_once():
    # a residual nearly flat in the temperature: Newton asks for -1e6 K, of which max_step
    # (300 K) allows 3e-4 of the step; an ordinary solve takes it, a continuation's step
    # (stall given) is too long and fails without a line search
    calls = []

    def F(x):
        calls.append(np.ndim(x))
        return 1e-6 * x + 1.0

    kw = dict(temperature_vars=1, max_iter=1, lower=-1e12)
    with pytest.raises(ConvergenceError):
        newton_banded(F, np.zeros((3, 1)), 1.0, stall=(8, 1e-2), **kw)
    assert sum(1 for d in calls if d == 2) == 1  # the start's residual only
    calls.clear()
    with pytest.raises(ConvergenceError):  # one iteration, not converged
        newton_banded(F, np.zeros((3, 1)), 1.0, **kw)
    assert sum(1 for d in calls if d == 2) == 2  # and its accepted 300 K step


def test_failed_solve_still_raises():
    def F(x):
        return x * x + 1.0  # no real root

    with pytest.raises(ConvergenceError):
        newton_banded(F, np.ones((5, 1)), 1.0, temperature_vars=0, max_iter=5,
                      squared=np.array([True]))  # fmt: skip


@pytest.mark.parametrize(
    "law, params, order",
    [
        ("arrhenius", {}, 1.0),
        ("ortiz_activation", {}, 1.0),
        ("wen_yen", {"step": 1.0}, 1.0),
        ("luisser_calcination", {}, 0.5),
        ("equilibrium_calcination", {"order": 0.8}, 0.8),
        ("ahmad_drying", {}, 0.0),
        ("boiling_drying", {}, 0.0),
    ],
)
def test_rate_law_order_in_the_flow_of_its_basis(law, params, order):
    p = dict(RATE_LAWS[law].defaults, **params)
    assert RATE_LAWS[law].flow_order(p) == order


@pytest.mark.parametrize("name", ["barr_T4", "rotary_pyrolysis", "limestone_calcination"])
def test_local_unknowns_are_those_the_probe_finds_and_give_the_same_jacobian(name):
    """The wall's radial temperatures act on their own cell only (a jacket's gas does not):
    the residual's ``local`` flags are what the finite-difference probe finds at the solution,
    and the Jacobian with one colour per local unknown is the full colouring's (bit for bit
    but for the round-off of the rates' matrix products, whose blocking follows the number of
    states evaluated together)."""
    import warnings

    from rotarykiln.case import load_case
    from rotarykiln.cases import builtin_case_path
    from rotarykiln.kiln.from_case import kiln_from_case
    from rotarykiln.kiln.residual import KilnResidual
    from rotarykiln.kiln.steady.batch import BatchResidual, local_unknowns
    from rotarykiln.kiln.steady.newton import _banded_jacobian
    from rotarykiln.kiln.steady.solve import solve_kiln

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        kiln, cells = kiln_from_case(load_case(builtin_case_path(name)))
        x = solve_kiln(kiln, cells).fluxes["x"]
    res = KilnResidual(kiln, cells)
    assert res.local.tolist() == local_unknowns(BatchResidual([res]), x).tolist()
    assert res.local.any()
    R = res.evaluate(x)
    full, _ = _banded_jacobian(res.evaluate, x, R)
    fewer, _ = _banded_jacobian(res.evaluate, x, R, local=res.local)
    np.testing.assert_allclose(fewer, full, rtol=0, atol=1e-11 * np.abs(full).max())


def test_logged_unknowns_fall_by_decades_in_a_step_and_never_cross_zero():
    # a reactant's flow past the end of its front falls by decades per cell: lowered in its
    # logarithm, Newton reaches 1e-2 .. 1e-18 from 1 in three steps; the straight steps
    # overshoot through zero (where the residual is not defined) and crawl
    target = 10.0 ** -np.arange(2, 22, 4)

    def F(x):
        return (np.log(np.abs(x[..., 0])) - np.log(target))[..., None]

    seen = []

    def G(x):
        seen.append(float(np.min(x)))
        return F(x)

    kw = dict(tol=1e-12, temperature_vars=0, step_floor=1e-300, max_iter=30)
    x, rep = newton_banded(G, np.ones((5, 1)), 1.0, logged=np.array([True]), **kw)
    np.testing.assert_allclose(x[:, 0], target, rtol=1e-10)
    assert rep.iterations <= 4 and min(seen) > 0.0
    with pytest.raises(ConvergenceError):
        newton_banded(F, np.ones((5, 1)), 1.0, **kw)


def _half_order_reactant(k_dz: float, q_in: float = 1.0):
    """Upwind cells of dq/dz = -k sqrt(q) (a shrinking core), solved for s = sqrt(q): the flow
    is used up within a finite length, past which s = 0 and the rate's |s| has its kink."""

    def F(x):
        s = x[..., 0]
        q = s * s
        prev = np.concatenate([np.full(q.shape[:-1] + (1,), q_in), q[..., :-1]], axis=-1)
        return (q - prev + k_dz * np.abs(s))[..., None]

    return F


@pytest.mark.parametrize("k_dz", [0.1, 0.3])
@pytest.mark.parametrize("start", [0.5, -0.5])
def test_root_unknowns_are_kept_on_their_positive_branch(k_dz, start):
    # the residual is even in s: started on either branch, every point Newton evaluates has
    # s >= 0, and the used-up cells end at s ~ 0 from above in fewer iterations than the
    # plain iteration, whose straight steps cross zero and difference across the kink
    F = _half_order_reactant(k_dz)
    seen = []

    def G(x):
        seen.append(float(np.min(x)))
        return F(x)

    kw = dict(tol=1e-14, temperature_vars=0, step_floor=1e-6, max_iter=100)
    x, rep = newton_banded(G, np.full((40, 1), start), 1.0, roots=np.array([True]), **kw)
    _, plain = newton_banded(F, np.full((40, 1), start), 1.0, **kw)
    assert min(seen) >= 0.0
    assert np.max(np.abs(F(x))) <= 1e-14
    assert rep.iterations <= plain.iterations
    if k_dz == 0.3 and start < 0:
        assert rep.iterations < plain.iterations
