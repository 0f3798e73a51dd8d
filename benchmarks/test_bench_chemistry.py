"""Speed of the chemistry hot paths (run with --benchmark-enable --benchmark-only)."""

import numpy as np
import pytest

from rotarykiln.chemistry.mechanism import CellState, Mechanism
from rotarykiln.chemistry.plugflow import integrate_plug_flow
from rotarykiln.chemistry.reaction import builtin_reactions

N = 10_000


@pytest.fixture(scope="module")
def state():
    rng = np.random.default_rng(0)
    T = rng.uniform(500.0, 1500.0, N)
    flows = {
        s: rng.uniform(0.0, 1e-3, N)
        for s in ["H2O(l)", "CaCO3", "CaO", "C", "kerogen", "bitumen", "inert"]
    }
    return CellState.build(
        T,
        T + 200.0,
        flows,
        rng.uniform(5.0, 50.0, N),
        partial_pressure={"CO2": rng.uniform(0, 1e5, N), "H2O": rng.uniform(0, 1e5, N)},
        bed_mass_flow_in={"CaCO3": 1e-3, "kerogen": 1e-3},
        inputs={
            "steam_mass_flow": 5e-3,
            "drying_conductance": 30.0,
            "bed_heat_input": 1e4,
            "freeboard_area": 0.1,
        },
    )


def test_bench_all_reactions_1e4_cells(benchmark, state):
    mech = Mechanism.builtin(*builtin_reactions(), kirchhoff=True)
    out = benchmark(mech.rates, state)
    assert out.production.shape[0] == N


def test_bench_calcination_1e4_cells(benchmark, state):
    mech = Mechanism.builtin("drying_ahmad", "calcination_equilibrium")
    out = benchmark(mech.rates, state)
    assert out.heat_absorbed.shape == (N,)


def test_bench_cell_state_build_1e4(benchmark, state):
    flows = dict(state.bed_mass_flow)
    benchmark(
        CellState.build,
        state.T_bed,
        state.T_gas,
        flows,
        state.bed_mass_per_length,
        dict(state.partial_pressure),
        dict(state.bed_mass_flow_in),
        dict(state.inputs),
    )


def test_bench_plug_flow_limestone(benchmark):
    mech = Mechanism.builtin("drying_ahmad", "calcination_luisser")
    z = np.linspace(0.0, 5.5, 12)
    T = np.interp(z, [0, 1, 3, 5.5], [550, 900, 1200, 1600])
    res = benchmark(
        integrate_plug_flow,
        mech,
        {"CaCO3": 0.0105, "H2O(l)": 0.00117},
        5.5,
        5.5 / 5400,
        (z, T),
        T_gas=(z, T + 200),
        inputs={"drying_conductance": 20.0},
    )
    assert res.conversion("CaCO3")[-1] > 0.999
