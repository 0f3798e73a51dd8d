"""Residence-time effects of a solved kiln: the batched classes against per-class LSODA.

All RTD classes and the frozen-profile plug class are integrated in one batch
(:func:`rotarykiln.chemistry.segregated.batch_plug_flow_conversion`); the reference is the
per-class LSODA integration (:func:`integrate_plug_flow`, rtol 1e-10) the model ran before,
through the same frozen profiles of the charcoal activation case (drying, and an activation
rate that jumps at its onset temperature). Agreement to 1e-6 in conversion.
"""

import numpy as np
import pytest
import yaml
from scipy.integrate import trapezoid

import rotarykiln.kiln.bed.residence as residence
from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.chemistry.plugflow import integrate_plug_flow
from rotarykiln.commands.kiln_runs import bed_peclet
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.steady.solve import solve_kiln


@pytest.fixture(scope="module")
def charcoal():
    data = yaml.safe_load(builtin_case_path("charcoal_activation").read_text(encoding="utf-8"))
    case = parse_case(data)
    kiln, cells = kiln_from_case(case)
    return case, kiln, solve_kiln(kiln, cells)


@pytest.fixture(scope="module")
def effects(charcoal):
    """residence_time_effects and the arguments it gave kiln_segregated_conversion."""
    case, kiln, sol = charcoal
    seen = {}
    real = residence.kiln_segregated_conversion

    def spy(*args, **kwargs):
        seen["args"], seen["kwargs"] = args, kwargs
        return real(*args, **kwargs)

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(residence, "kiln_segregated_conversion", spy)
        eff = residence.residence_time_effects(
            kiln, sol, peclet=bed_peclet(case, sol.residence_time)[0]
        )
    return eff, seen


def _lsoda(seen, tau):
    mech, feed, species, length, _rtd, T_bed, T_gas, pp, inputs = seen["args"]
    res = integrate_plug_flow(
        mech, feed, length, length / tau, T_bed, T_gas, pp, inputs, n_points=2, rtol=1e-10
    )
    return float(res.conversion(species)[-1])


def test_batched_classes_equal_per_class_lsoda(effects):
    eff, seen = effects
    r = eff.result
    n_classes = r.class_tau.size - 1  # the last one is the frozen plug class
    pick = np.unique(np.linspace(0, n_classes - 1, 5).round().astype(int))
    assert pick.size == 5
    ref = np.array([_lsoda(seen, r.class_tau[i]) for i in pick])
    assert np.ptp(ref) > 0.01  # the classes differ
    np.testing.assert_allclose(r.class_conversion[pick], ref, rtol=0, atol=1e-6)


def test_frozen_plug_class_equals_lsoda_at_the_kiln_velocity(effects, charcoal):
    eff, seen = effects
    _, kiln, _ = charcoal
    tau_s = kiln.drum.length / kiln.bed.velocity
    assert eff.result.class_tau[-1] == pytest.approx(tau_s, rel=1e-12)
    assert eff.frozen_plug_conversion == pytest.approx(_lsoda(seen, tau_s), abs=1e-6)
    # the frozen profiles reproduce the coupled kiln up to its discretisation (100 cells)
    assert eff.frozen_plug_conversion == pytest.approx(eff.kiln_conversion, rel=2e-3)


def test_rtd_weights_integrate_to_one_and_the_truncation_is_negligible(effects, charcoal):
    eff, _ = effects
    _, kiln, _ = charcoal
    r = eff.result
    assert trapezoid(r.E, r.tau) == pytest.approx(1.0, abs=1e-12)
    assert r.segregated == pytest.approx(trapezoid(r.conversion * r.E, r.tau), abs=1e-15)
    # weight beyond t_max = mean + 8 sd, and lost to the 801-point trapezoid rule
    rtd = residence.KilnRTD("open-open", kiln.residence_time, eff.peclet)
    raw = trapezoid(rtd.exitage(r.tau), r.tau)
    assert 0 <= 1.0 - raw < 1e-7
