import numpy as np
import pytest
from scipy.integrate import trapezoid

from rotarykiln.chemistry.mechanism import Mechanism
from rotarykiln.chemistry.plugflow import as_profile, integrate_plug_flow
from rotarykiln.chemistry.segregated import (
    kiln_segregated_conversion,
    rtd_arrays,
    segregated_average,
)
from rotarykiln.errors import InputError

FIRST_ORDER = {
    "name": "first_order",
    "stoichiometry": {"CaCO3": -1, "CaO": 1, "CO2": 1},
    "basis": "CaCO3",
    "rate": {"law": "arrhenius", "A": 0.01, "E": 0.0},
    "heat": 0.0,
}


def _first_order_mech(k=0.01):
    from rotarykiln.chemistry.reaction import reaction_from_dict

    d = dict(FIRST_ORDER)
    d["rate"] = {"law": "arrhenius", "A": k, "E": 0.0}
    return Mechanism((reaction_from_dict(d),))


def test_first_order_plug_flow_matches_exponential():
    mech = _first_order_mech(0.01)
    res = integrate_plug_flow(mech, {"CaCO3": 0.02, "inert": 0.01}, 2.0, 0.01, 1000.0)
    assert np.allclose(res.conversion("CaCO3"), 1 - np.exp(-0.01 * res.t), atol=1e-7)
    assert max(res.element_balance().values()) < 1e-8
    # released CO2 = 44/100 of CaCO3 converted
    assert res.flow("CO2")[-1] == pytest.approx(
        0.02 * res.conversion("CaCO3")[-1] * 44.009 / 100.086, rel=1e-6
    )


def test_temperature_profile_tabulated_and_callable_agree():
    mech = Mechanism.builtin("calcination_luisser")
    z = np.linspace(0, 5.5, 12)
    T = 800 + 100 * z
    a = integrate_plug_flow(mech, {"CaCO3": 0.01}, 5.5, 1e-3, (z, T))
    b = integrate_plug_flow(mech, {"CaCO3": 0.01}, 5.5, 1e-3, lambda x: np.interp(x, z, T))
    assert np.allclose(a.conversion("CaCO3"), b.conversion("CaCO3"), atol=1e-8)
    assert a.conversion("CaCO3")[-1] > 0.99


def test_equilibrium_calcination_does_not_start_below_equilibrium():
    mech = Mechanism.builtin("calcination_equilibrium")
    res = integrate_plug_flow(
        mech, {"CaCO3": 0.01}, 1.0, 1e-3, 1165.0, partial_pressure={"CO2": 101325.0}
    )
    assert res.conversion("CaCO3")[-1] == 0.0
    res = integrate_plug_flow(
        mech, {"CaCO3": 0.01}, 1.0, 1e-3, 1190.0, partial_pressure={"CO2": 101325.0}
    )
    assert res.conversion("CaCO3")[-1] > 0.5


def test_charcoal_burn_off_and_frame():
    mech = Mechanism.builtin("activation_ortiz", "drying_ahmad")
    res = integrate_plug_flow(
        mech,
        {"C": 3.0e-3, "H2O(l)": 3.33e-4},
        3.7,
        3.7 / 6480.0,
        1150.0,
        T_gas=1300.0,
        inputs={"steam_mass_flow": 0.005, "drying_conductance": 10.0},
    )
    k = 6.005 * np.exp(-8033 / 1150.0) * 0.005
    assert res.burn_off()[-1] == pytest.approx(100 * (1 - np.exp(-k * 6480.0)), rel=1e-5)
    assert res.flow("H2O(l)")[-1] < 1e-6
    df = res.to_frame()
    assert {"z_m", "t_s", "bed_C_kg_s"} <= set(df.columns)


def test_bad_inputs():
    mech = Mechanism.builtin("calcination_luisser")
    with pytest.raises(InputError, match="velocity"):
        integrate_plug_flow(mech, {"CaCO3": 1.0}, 1.0, 0.0, 1000.0)
    with pytest.raises(InputError, match="a bed species"):
        integrate_plug_flow(mech, {"CO2": 1.0}, 1.0, 1.0, 1000.0)
    with pytest.raises(InputError, match="tabulated"):
        as_profile("T", ([0, 1], [1.0]))


def test_rtd_arrays_normalises_and_validates():
    t, E = rtd_arrays((np.linspace(0, 10, 11), 2 * np.ones(11)))
    assert trapezoid(E, t) == pytest.approx(1.0)
    with pytest.raises(InputError):
        rtd_arrays((np.linspace(0, 10, 11), -np.ones(11)))
    with pytest.raises(InputError, match="t_max"):
        rtd_arrays(lambda t: t)

    class Obj:
        def exitage(self, t):
            return np.exp(-t)

    t, E = rtd_arrays(Obj(), t_max=20.0)
    assert E[0] == pytest.approx(1.0, rel=1e-2)


def test_segregated_first_order_tanks_in_series():
    # N tanks in series, first order: X = 1 - (1 + k tau/N)^-N (Levenspiel, ch. 14)
    from scipy.special import gamma

    k, tau, N = 0.02, 100.0, 3
    E = lambda t: (N / tau) ** N * t ** (N - 1) * np.exp(-N * t / tau) / gamma(N)  # noqa: E731
    res = segregated_average(lambda t: 1 - np.exp(-k * t), E, t_max=20 * tau, n=8001)
    assert res.segregated == pytest.approx(1 - (1 + k * tau / N) ** -N, abs=1e-5)
    assert res.plug == pytest.approx(1 - np.exp(-k * tau), abs=1e-4)
    assert res.segregated < res.plug


def test_kiln_segregated_matches_closed_form_for_first_order():
    k, tau, N = 0.002, 1000.0, 4
    from scipy.special import gamma

    mech = _first_order_mech(k)
    E = lambda t: (N / tau) ** N * t ** (N - 1) * np.exp(-N * t / tau) / gamma(N)  # noqa: E731
    res = kiln_segregated_conversion(
        mech, {"CaCO3": 0.01}, "CaCO3", 5.0, E, 1000.0, t_max=15 * tau, n=3001, n_tau=40
    )
    assert res.segregated == pytest.approx(1 - (1 + k * tau / N) ** -N, abs=2e-3)
    assert res.plug == pytest.approx(1 - np.exp(-k * tau), abs=1e-3)
    assert res.to_frame().shape[1] == 3


def test_wen_yen_mechanism_reproduces_the_scheme():
    # The five element-balanced reactions must give the scheme's x1, x2, x3 exactly, and x4 as
    # fixed carbon plus the light gases released by step 5.
    from scipy.integrate import solve_ivp

    from rotarykiln.chemistry.pyrolysis import wen_yen_kerogen_rates

    T = 723.0
    mech = Mechanism.builtin(*[f"pyrolysis_wen_yen_{i}" for i in range(1, 6)])
    t_end = 20 * 60.0
    res = integrate_plug_flow(mech, {"kerogen": 1.0, "inert": 4.0}, 1.0, 1.0 / t_end, T, rtol=1e-10)
    ref = solve_ivp(
        lambda t, x: np.array(wen_yen_kerogen_rates(x[0], x[1], T)).ravel(),
        (0, t_end),
        [1, 0, 0, 0],
        rtol=1e-11,
        atol=1e-13,
        t_eval=res.t,
        method="LSODA",
    )
    x1, x2, x3, x4 = ref.y
    assert np.allclose(res.flow("kerogen"), x1, atol=2e-6)
    assert np.allclose(res.flow("bitumen"), x2, atol=2e-6)
    assert np.allclose(res.flow("volatiles"), x3, atol=2e-6)
    x4_model = res.flow("C") + res.flow("H2") + res.flow("H2O") + res.flow("N2")
    assert np.allclose(x4_model, x4, atol=2e-6)
    assert x1[-1] < 0.5  # the run is long enough to matter
    assert max(res.element_balance().values()) < 1e-8
