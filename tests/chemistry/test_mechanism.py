import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rotarykiln.chemistry.balance import (
    check_element_balance,
    check_stream_balance,
    element_residuals,
)
from rotarykiln.chemistry.mechanism import CellState, Mechanism
from rotarykiln.chemistry.reaction import builtin_reactions
from rotarykiln.errors import ConvergenceError, InputError

ALL = tuple(n for n in builtin_reactions() if n != "drying_heat_limited")


def _state(n=5, T=None):
    T = np.linspace(600.0, 1400.0, n) if T is None else T
    return CellState.build(
        T_bed=T,
        T_gas=T + 200.0,
        bed_mass_flow={
            "H2O(l)": 1e-3,
            "CaCO3": 5e-3,
            "CaO": 1e-3,
            "C": 2e-3,
            "kerogen": 1e-3,
            "bitumen": 2e-4,
            "ash": 1e-4,
            "inert": 1e-3,
        },
        bed_mass_per_length=20.0,
        partial_pressure={"CO2": 2e4, "H2O": 3e4},
        bed_mass_flow_in={"CaCO3": 6e-3, "kerogen": 1.5e-3},
        inputs={
            "steam_mass_flow": 5e-3,
            "drying_conductance": 30.0,
            "bed_heat_input": 1e4,
            "freeboard_area": 0.1,
        },
    )


def test_rates_shape_and_element_balance_closes():
    mech = Mechanism.builtin(*ALL, "drying_heat_limited")
    out = mech.rates(_state(50), check=True)
    assert out.production.shape == (50, len(mech.species.species))
    assert out.reaction_rate.shape == (50, len(mech.reactions))
    assert check_element_balance(out.production, mech.species) < 1e-12
    # heat is sum of rate x heat
    dh = np.array([r.heat for r in mech.reactions])
    assert np.allclose(out.heat_absorbed, out.reaction_rate @ dh)
    assert np.all(out.reaction_rate >= 0)


def test_vectorised_equals_cell_by_cell():
    mech = Mechanism.builtin(*ALL)
    full = mech.rates(_state(7))
    for i, T in enumerate(np.linspace(600.0, 1400.0, 7)):
        one = mech.rates(_state(1, np.array([T])))
        assert np.allclose(one.production[0], full.production[i], rtol=1e-13, atol=0)


def test_calcination_co2_release_matches_stoichiometry():
    mech = Mechanism.builtin("calcination_luisser")
    out = mech.rates(_state(3))
    r = out.reaction_rate[:, 0]
    assert np.allclose(out.of("CO2"), r * 44.009 / 100.086, rtol=1e-4)
    assert np.allclose(out.of("CaO"), r * 56.077 / 100.086, rtol=1e-4)
    assert np.allclose(out.gas_release, out.of("CO2"))


def test_activation_gas_gains_one_kg_per_kg_carbon():
    mech = Mechanism.builtin("activation_ortiz")
    out = mech.rates(_state(4, np.array([1000.0, 1080.0, 1150.0, 1250.0])))
    c = -out.of("C")
    assert c[0] == 0.0 and np.all(c[1:] > 0)  # onset at 1073 K
    assert np.allclose(out.gas_release, c, rtol=1e-12)  # CO + H2 - H2O = C
    assert np.allclose(out.heat_absorbed, c * 131.3e3 / 0.012011, rtol=1e-9)


def test_missing_inputs_are_named():
    mech = Mechanism.builtin("activation_ortiz")
    st_ = CellState.build(1100.0, 1200.0, {"C": 1e-3}, 5.0)
    with pytest.raises(
        InputError, match=r"inputs.steam_mass_flow: missing \(required: needed by rate law"
    ):
        mech.rates(st_)
    mech = Mechanism.builtin("calcination_luisser")
    with pytest.raises(InputError, match="bed_mass_flow_in.CaCO3"):
        mech.rates(CellState.build(1100.0, 1200.0, {"CaCO3": 1e-3}, 5.0))


def test_cell_state_refusals():
    with pytest.raises(InputError, match="a bed species"):
        CellState.build(1000.0, 1000.0, {"CO2": 1.0}, 1.0)
    with pytest.raises(InputError, match="is not >= 0"):
        CellState.build(1000.0, 1000.0, {"CaCO3": -1.0}, 1.0)
    with pytest.raises(InputError, match="T_bed"):
        CellState.build(-5.0, 1000.0, {"CaCO3": 1.0}, 1.0)
    with pytest.raises(InputError, match="length 1 or 3"):
        CellState.build([1000.0, 1.0, 2.0], [1.0, 2.0], {"CaCO3": 1.0}, 1.0)
    with pytest.raises(InputError, match="summing to 1"):
        CellState.from_fractions(1000.0, 1000.0, {"CaCO3": 0.7}, 1.0)
    with pytest.raises(InputError, match="unknown"):
        Mechanism.builtin("unknown")


def test_element_checker_detects_imbalance():
    mech = Mechanism.builtin("calcination_luisser")
    out = mech.rates(_state(3))
    bad = out.production.copy()
    bad[:, mech.species.index("CO2")] *= 1.0 + 1e-6
    with pytest.raises(ConvergenceError, match="element balance"):
        check_element_balance(bad, mech.species)
    assert element_residuals(bad, mech.species).max() > 1e-8


def test_stream_balance():
    res = check_stream_balance({"CaCO3": 1.0}, {"CaO": 0.56029, "CO2": 0.43971}, rtol=1e-3)
    assert max(res.values()) < 1e-3
    with pytest.raises(ConvergenceError, match="element=Ca"):
        check_stream_balance({"CaCO3": 1.0}, {"CaO": 0.5, "CO2": 0.43971})


@settings(max_examples=40, deadline=None)
@given(
    T=st.floats(500.0, 1600.0),
    dT=st.floats(-200.0, 600.0),
    fr=st.lists(st.floats(0.0, 1.0), min_size=8, max_size=8),
    pco2=st.floats(0.0, 2e5),
)
def test_property_balance_closes_and_rates_nonnegative(T, dT, fr, pco2):
    names = ["H2O(l)", "CaCO3", "CaO", "C", "kerogen", "bitumen", "ash", "inert"]
    flows = {n: 1e-3 * f for n, f in zip(names, fr, strict=True)}
    flows["inert"] += 1e-6
    mech = Mechanism.builtin(*ALL, kirchhoff=True)
    s = CellState.build(
        T,
        max(T + dT, 300.0),
        flows,
        10.0,
        partial_pressure={"CO2": pco2},
        bed_mass_flow_in={"CaCO3": 1e-3, "kerogen": 1e-3},
        inputs={
            "steam_mass_flow": 5e-3,
            "drying_conductance": 30.0,
            "bed_heat_input": 1e4,
            "freeboard_area": 0.1,
        },
    )
    out = mech.rates(s)
    assert np.all(out.reaction_rate >= 0) and np.all(np.isfinite(out.production))
    assert check_element_balance(out.production, mech.species) <= 1e-8
    # total mass conserved: bed loss = gas gain
    assert abs(out.production.sum()) <= 1e-12 * max(1e-30, np.abs(out.production).sum()) * 10


def test_frame_and_plot():
    import matplotlib

    matplotlib.use("Agg")
    mech = Mechanism.builtin("calcination_luisser", "drying_ahmad")
    out = mech.rates(_state(4))
    df = out.to_frame()
    assert "heat_absorbed_W_m" in df and len(df) == 4
    assert out.plot() is not None
