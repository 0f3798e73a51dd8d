"""Batched plug-flow integration of many residence-time classes against per-class LSODA.

The reference is the per-class path the segregated-flow model used before the batching:
:func:`integrate_plug_flow` (LSODA) run once per residence time, here with rtol 1e-10. The
batched result must agree to 1e-6 in conversion. The profiles are tabulated on uneven knots
(slope breaks), the calcination classes range from 30 % to complete conversion (the
order-1/2 law's square-root singularity at the end), and the activation has the sharp
onset temperature of Ortiz et al. (a jump of the rate).
"""

import numpy as np
import pytest
from scipy.integrate import trapezoid

from rotarykiln.chemistry.mechanism import Mechanism
from rotarykiln.chemistry.plugflow import integrate_plug_flow
from rotarykiln.chemistry.segregated import (
    batch_plug_flow_conversion,
    kiln_segregated_conversion,
)
from rotarykiln.errors import InputError

L = 5.0
Z = L * np.linspace(0.0, 1.0, 26) ** 1.3
T_BED = (Z, 500.0 + 800.0 * np.sin(0.5 * np.pi * Z / L) ** 1.5)
T_GAS = (Z, T_BED[1] + 250.0 * (1 - Z / L) + 50.0)
PP = {"CO2": (Z, 2e4 * (1 - 0.8 * Z / L)), "H2O": (Z, 1e4 + 0 * Z)}
INPUTS = {
    "drying_conductance": (Z, 9.0 - Z / L),
    "steam_mass_flow": 0.006,
    "bed_heat_input": (Z, 5000.0 - 800.0 * Z),
}
CASES = {
    "calcination": (
        ("drying_ahmad", "calcination_equilibrium"),
        {"H2O(l)": 0.0012, "CaCO3": 0.0105, "inert": 0.001},
        "CaCO3",
        [8.0, 15.0, 25.0, 40.0, 3000.0],
    ),
    "activation": (
        ("drying_ahmad", "activation_ortiz"),
        {"H2O(l)": 0.000333, "C": 0.003},
        "C",
        [200.0, 600.0, 1500.0, 4000.0, 9000.0],
    ),
}


def _per_class_lsoda(mech, feed, species, taus, T_bed=T_BED):
    return np.array(
        [
            integrate_plug_flow(
                mech, feed, L, L / tau, T_bed, T_GAS, PP, INPUTS, n_points=2, rtol=1e-10
            ).conversion(species)[-1]
            for tau in taus
        ]
    )


@pytest.mark.parametrize("which", sorted(CASES))
def test_batch_equals_per_class_lsoda(which):
    names, feed, species, taus = CASES[which]
    mech = Mechanism.builtin(*names)
    x = batch_plug_flow_conversion(mech, feed, species, L, taus, T_BED, T_GAS, PP, INPUTS)
    ref = _per_class_lsoda(mech, feed, species, taus)
    assert x.shape == (5,)
    assert np.all(np.diff(ref) > 0) and 0 < ref[0] < 0.5  # a spread of conversions
    np.testing.assert_allclose(x, ref, rtol=0, atol=1e-6)


def test_batch_does_not_depend_on_the_other_classes():
    names, feed, species, taus = CASES["calcination"]
    mech = Mechanism.builtin(*names)
    together = batch_plug_flow_conversion(mech, feed, species, L, taus, T_BED, T_GAS, PP, INPUTS)
    alone = [
        batch_plug_flow_conversion(mech, feed, species, L, [t], T_BED, T_GAS, PP, INPUTS)[0]
        for t in taus[:2]
    ]
    np.testing.assert_allclose(together[:2], alone, rtol=0, atol=1e-9)


def test_batch_takes_a_callable_that_does_not_vectorise():
    names, feed, species, taus = CASES["calcination"]
    mech = Mechanism.builtin(*names)

    def t_bed(z):  # float() refuses arrays: called point by point
        return float(np.interp(z, *T_BED))

    x = batch_plug_flow_conversion(mech, feed, species, L, taus[:3], t_bed, T_GAS, PP, INPUTS)
    ref = batch_plug_flow_conversion(mech, feed, species, L, taus[:3], T_BED, T_GAS, PP, INPUTS)
    np.testing.assert_allclose(x, ref, rtol=0, atol=1e-6)


def test_kiln_segregated_extra_times_ride_along_without_changing_the_average():
    names, feed, species, _ = CASES["calcination"]
    mech = Mechanism.builtin(*names)

    def exitage(t):  # 3 tanks in series, mean 20 s
        return 27.0 / 20.0**3 * t**2 * np.exp(-3.0 * t / 20.0) / 2.0

    args = (mech, feed, species, L, exitage, T_BED, T_GAS, PP, INPUTS)
    base = kiln_segregated_conversion(*args, n_tau=12, t_max=200.0, n=801)
    more = kiln_segregated_conversion(
        *args, n_tau=12, t_max=200.0, n=801, extra_residence_times=[25.0]
    )
    assert more.segregated == base.segregated and more.plug == base.plug
    assert more.class_tau[-1] == 25.0 and more.class_tau.size == base.class_tau.size + 1
    assert more.class_conversion[-1] == pytest.approx(
        _per_class_lsoda(mech, feed, species, [25.0])[0], abs=1e-6
    )
    # the RTD weights integrate to 1 on the grid; the plug value is the class at the mean
    assert trapezoid(base.E, base.tau) == pytest.approx(1.0, abs=1e-12)
    i = np.argmin(np.abs(base.class_tau - base.mean_residence_time))
    assert base.plug == base.class_conversion[i]


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"residence_times": [10.0, -1.0]}, "residence_times"),
        ({"residence_times": []}, "residence_times"),
        ({"species": "CaO"}, "species"),
        ({"partial_pressure": {"CaO": 1.0}}, "partial_pressure.CaO"),
        ({"length": 0.0}, "length"),
        ({"T_bed": -5.0}, "T_bed"),
    ],
)
def test_batch_input_checks(kwargs, field):
    names, feed, species, taus = CASES["calcination"]
    args = {
        "mechanism": Mechanism.builtin(*names),
        "bed_mass_flow_in": feed,
        "species": species,
        "length": L,
        "residence_times": taus,
        "T_bed": T_BED,
        **kwargs,
    }
    with pytest.raises(InputError, match=field):
        batch_plug_flow_conversion(**args)
