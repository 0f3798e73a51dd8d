import numpy as np
import pytest

from rotarykiln.chemistry.activation import onset_window, ortiz_activation_rate
from rotarykiln.chemistry.calcination import (
    baker_co2_equilibrium_pressure,
    baker_equilibrium_temperature,
    calcination_rate_with_equilibrium,
    luisser_calcination_rate,
)
from rotarykiln.chemistry.drying import (
    ahmad_critical_moisture_drying_rate,
    heat_limited_drying_rate,
)
from rotarykiln.chemistry.pyrolysis import berkovich_conversion, wen_yen_kerogen_rates
from rotarykiln.errors import InputError, OutOfRangeWarning


def test_drying_zero_without_driving_force_or_moisture():
    assert ahmad_critical_moisture_drying_rate(20.0, 400.0, 500.0, 1e-3, 1e-2) == 0.0
    assert ahmad_critical_moisture_drying_rate(20.0, 700.0, 500.0, 0.0, 1e-2) == 0.0
    # falling-rate period: proportional to the moisture below the critical value
    r1 = ahmad_critical_moisture_drying_rate(20.0, 700.0, 500.0, 0.5e-3, 1e-2)
    r2 = ahmad_critical_moisture_drying_rate(20.0, 700.0, 500.0, 0.25e-3, 1e-2)
    assert r1 == pytest.approx(2 * r2)
    # capped above the critical moisture, uncapped as printed in the seed
    capped = ahmad_critical_moisture_drying_rate(20.0, 700.0, 500.0, 2e-3, 1e-2)
    assert capped == pytest.approx(20.0 * 200.0 / 2257200.0)
    assert ahmad_critical_moisture_drying_rate(
        20.0, 700.0, 500.0, 2e-3, 1e-2, cap=False
    ) == pytest.approx(2 * capped)
    with pytest.raises(InputError):
        ahmad_critical_moisture_drying_rate(-1.0, 700.0, 500.0, 1e-3, 1e-2)


def test_heat_limited_drying_energy_closes():
    q = np.array([1000.0, 1000.0, -50.0])
    r = heat_limited_drying_rate(q, np.array([373.15, 380.0, 373.15]), 1e-3)
    assert r[0] * 2257200.0 == pytest.approx(1000.0)
    assert r[2] == 0.0
    assert heat_limited_drying_rate(1000.0, 373.15, 0.0) == 0.0


def test_calcination_rate_monotone_and_equilibrium_stop():
    T = np.linspace(900, 1400, 26)
    r = luisser_calcination_rate(T, 0.3)
    assert np.all(np.diff(r) > 0)
    assert luisser_calcination_rate(1100.0, 1.0) == 0.0
    with pytest.raises(InputError):
        luisser_calcination_rate(1100.0, 1.2)
    Teq = baker_equilibrium_temperature(np.array([0.05, 0.2, 1.0]) * 101325)
    for p, te in zip(np.array([0.05, 0.2, 1.0]) * 101325, Teq, strict=True):
        assert calcination_rate_with_equilibrium(te - 0.5, 0.0, p) == 0.0
        assert calcination_rate_with_equilibrium(te + 5.0, 0.0, p) > 0.0
    with pytest.raises(InputError):
        calcination_rate_with_equilibrium(1200.0, 0.0, 1e4, equilibrium="x")


def test_baker_warns_out_of_range():
    with pytest.warns(OutOfRangeWarning):
        baker_co2_equilibrium_pressure(600.0)


def test_ortiz_window_and_linearity():
    assert ortiz_activation_rate(1072.0, 0.005, 1.0) == 0.0
    assert ortiz_activation_rate(1300.0, 0.005, 1.0, T_off=1273.0) == 0.0
    r = ortiz_activation_rate(1150.0, np.array([0.0025, 0.005]), 2.0)
    assert r[1] == pytest.approx(2 * r[0])
    s = onset_window(np.array([1060.0, 1068.0, 1073.0]), 1073.0, width=10.0)
    assert np.allclose(s, [0.0, 0.5, 1.0])


def test_wen_yen_conserves_mass():
    d = wen_yen_kerogen_rates(np.array([0.7, 0.3]), np.array([0.2, 0.4]), 720.0)
    assert np.allclose(sum(d), 0.0, atol=1e-15)


def test_berkovich_zero_below_onset():
    assert berkovich_conversion(700.0, 743.0, 21.71) == 0.0


def test_calcination_in_the_bed_co2_starts_at_the_1_atm_equilibrium():
    # co2_pressure: bed takes 1 atm of CO2 whatever the freeboard holds: no calcination below
    # Baker's 1173.6 K, where the freeboard's 0.2 atm lets it run; above it, the Luisser rate
    # times 1 - 1 atm / p_eq(T)
    from rotarykiln.chemistry.mechanism import CellState, Mechanism

    T = np.array([1100.0, 1150.0, 1250.0])
    state = CellState.build(
        T_bed=T,
        T_gas=T + 300.0,
        bed_mass_flow={"CaCO3": np.full(3, 1.0)},
        bed_mass_per_length=np.full(3, 100.0),
        partial_pressure={"CO2": np.full(3, 0.2 * 101325.0)},
        bed_mass_flow_in={"CaCO3": 1.0},
    )
    freeboard = Mechanism.builtin("calcination_equilibrium").rates(state).reaction_rate[:, 0]
    bed = Mechanism.builtin("calcination_bed_co2").rates(state).reaction_rate[:, 0]
    assert np.all(freeboard > 0.0)
    assert bed[0] == 0.0 and bed[1] == 0.0
    kinetic = 100.0 * luisser_calcination_rate(1250.0, 0.0)  # kg/m hold-up x 1/s
    drive = 1.0 - 101325.0 / baker_co2_equilibrium_pressure(1250.0)
    assert bed[2] == pytest.approx(kinetic * drive, rel=1e-12)
    assert bed[2] < freeboard[2]


def test_co2_pressure_choice_is_checked():
    from rotarykiln.chemistry.ratelaws import RATE_LAWS

    law = RATE_LAWS["carbonate_equilibrium"]
    assert law.validate_params({"co2_pressure": "bed"}, "r.rate", "CaCO3")["co2_pressure"] == "bed"
    with pytest.raises(InputError, match="co2_pressure.*freeboard, bed"):
        law.validate_params({"co2_pressure": "kiln"}, "r.rate", "CaCO3")
