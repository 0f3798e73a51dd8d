"""The freeboard gas of one composition in every cell (rotarykiln.kiln.gas_mixture): its
conductivity, viscosity and specific heat from the species' pieces mixed once
(GasMixture.transport_tables, cp_tables) equal the cell-by-cell mixing to round-off, for one
composition and for a batch of cases with their own."""

import numpy as np
import pytest

from rotarykiln.kiln.gas_mixture import GasMixture, MixtureGas, mixture_of

NAMES = ("N2", "O2", "CO2", "H2O", "AR")


def _cell_by_cell(gas: MixtureGas, T):
    """The properties mixed per cell (the general path) at ``T``."""
    x = gas._x
    k, mu = gas.mixture.transport_x(T, x)
    cp = np.einsum("...i,...i->...", gas.mixture.species_cp(T), gas.flows) / gas.total
    return k, mu, gas.mixture.transport_x(T, x, viscosity=False), cp


@pytest.mark.parametrize("names", [NAMES, ("N2", "O2", "AR"), ("N2", "CO2", "H2O", "volatiles")])
def test_one_composition_in_every_cell_is_mixed_once_to_round_off(names):
    rng = np.random.default_rng(len(names))
    mixture = mixture_of(names)
    flows = rng.uniform(0.01, 1.0, len(names))
    T = rng.uniform(250.0, 2600.0, (3, 40))  # some cells outside the tables (clamped as before)
    gas = MixtureGas.of(mixture, np.broadcast_to(flows, (3, 1, len(names))), 101325.0, 0.2)
    assert gas._fixed is not None and gas._fixed[1] is None  # one composition
    k, mu = gas.transport(T)
    ref = _cell_by_cell(gas, T)
    np.testing.assert_allclose(k, ref[0], rtol=1e-13)
    np.testing.assert_allclose(mu, ref[1], rtol=1e-13)
    np.testing.assert_allclose(gas.conductivity(T), ref[2], rtol=1e-13)
    np.testing.assert_allclose(gas.cp(T), ref[3], rtol=1e-13)
    assert k.shape == mu.shape == gas.cp(T).shape == T.shape
    # the enthalpy flow, below T_MIN and above T_MAX on the tables' linear extensions
    h = (gas.flows * mixture.species_enthalpy(T)).sum(-1)
    np.testing.assert_allclose(gas.enthalpy_flow(T), h, rtol=1e-12, atol=1e-9 * np.abs(h).max())


def test_a_batch_of_cases_each_with_its_own_composition():
    rng = np.random.default_rng(7)
    mixture = GasMixture.of(NAMES)
    flows = rng.uniform(0.0, 1.0, (5, 1, len(NAMES)))
    flows[2, 0, 2:4] = 0.0  # a case without CO2 and H2O
    T = rng.uniform(300.0, 2200.0, (5, 30))
    gas = MixtureGas.of(mixture, flows, 101325.0, 0.2)
    assert gas._fixed is not None and gas._fixed[1] is not None  # a composition per case
    k, mu = gas.transport(T)
    ref = _cell_by_cell(gas, T)
    np.testing.assert_allclose(k, ref[0], rtol=1e-13)
    np.testing.assert_allclose(mu, ref[1], rtol=1e-13)
    np.testing.assert_allclose(gas.cp(T), ref[3], rtol=1e-13)
    h = (gas.flows * mixture.species_enthalpy(T)).sum(-1)
    np.testing.assert_allclose(gas.enthalpy_flow(T), h, rtol=1e-12, atol=1e-9 * np.abs(h).max())


def test_cases_of_one_composition_at_their_own_flows_keep_their_own_enthalpy_flows():
    # the heat sweep's cases: one inlet gas, its flow scaled per case (here by powers of 2,
    # which leave the mole fractions equal to the last bit): one transport table serves all,
    # but each case's enthalpy flow is that of its own flows
    mixture = GasMixture.of(NAMES)
    base = np.array([0.7, 0.2, 0.05, 0.04, 0.01])
    flows = base * np.array([1.0, 2.0, 0.5])[:, None, None]
    gas = MixtureGas.of(mixture, flows, 101325.0, 0.2)
    assert gas._fixed is not None and gas._fixed[1] is None  # one composition
    T = np.random.default_rng(3).uniform(250.0, 3400.0, (3, 20))
    h = (gas.flows * mixture.species_enthalpy(T)).sum(-1)
    np.testing.assert_allclose(gas.enthalpy_flow(T), h, rtol=1e-12, atol=1e-9 * np.abs(h).max())
    np.testing.assert_allclose(gas.cp(T), _cell_by_cell(gas, T)[3], rtol=1e-13)


def test_the_tables_of_a_composition_are_made_once_and_the_kept_ones_bounded():
    from rotarykiln.kiln import gas_mixture

    mixture = GasMixture.of(NAMES)
    x = np.array([[0.7, 0.1, 0.1, 0.08, 0.02]])
    assert mixture.transport_tables(x) is mixture.transport_tables(x.copy())
    for i in range(2 * gas_mixture.FIXED_TABLES_KEPT):
        mixture.cp_tables(x * (1.0 + i))
    assert len(mixture._fixed_cache) <= gas_mixture.FIXED_TABLES_KEPT


def test_cells_of_their_own_compositions_are_mixed_cell_by_cell():
    mixture = GasMixture.of(NAMES)
    flows = np.random.default_rng(3).uniform(0.1, 1.0, (20, len(NAMES)))
    gas = MixtureGas.of(mixture, flows, 101325.0, 0.2)
    assert gas._fixed is None and gas._fixed_cp is None
    T = np.linspace(400.0, 1800.0, 20)
    np.testing.assert_array_equal(gas.transport(T)[0], mixture.transport_x(T, gas._x)[0])
