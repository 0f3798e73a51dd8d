"""The bed depth solved inside the reacting kiln (kiln/bed/depth.py, issue 10 item 4)."""

from __future__ import annotations

import numpy as np
import pytest
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.commands.kiln_runs import run_kiln_case
from rotarykiln.errors import InputError
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.transport.kramers import kramers_profile


def _case(feed=None, **transport):
    d = yaml.safe_load(builtin_case_path("limestone_fired").read_text())
    d["bed"].pop("residence_time")
    d["material"]["repose_angle"] = "35 deg"
    d["transport"] = {"model": "kramers", "dam_height": "40 mm", **transport}
    if feed is not None:
        d["material"]["composition"] = feed
    return d


@pytest.fixture(scope="module")
def calcining():
    return run_kiln_case(parse_case(_case()))


def test_inert_bed_depth_equals_the_transport_model():
    # an inert feed keeps its flow: the in-solve depth must be the Kramers ODE's profile
    case = parse_case(_case(feed={"inert": 1.0}))
    sol = run_kiln_case(case)
    kiln, _ = kiln_from_case(case)
    b = kiln.bed.depth
    p = kramers_profile(
        case.operation.feed,
        length=case.kiln.length,
        radius=b.radius,
        speed=b.omega,
        slope=b.slope,
        repose=b.repose,
        density=b.density,
        dam_height=b.dam_height,
        n_points=2001,
    )
    ref = np.interp(sol.z, np.asarray(p.z), np.asarray(p.depth))
    assert np.max(np.abs(sol.fluxes["bed_depth"] - ref)) < 0.01 * b.dam_height
    # residence time: hold-up over flow, as the transport model computes it
    assert sol.residence_time == pytest.approx(p.mean_residence_time, rel=5e-3)


def test_calcination_thins_the_bed_and_balances_close(calcining):
    sol = calcining
    s = sol.summary()
    assert abs(s["energy_balance_closure"]) < 1e-6
    assert abs(s["element_balance_closure"]) < 1e-8
    assert s["conversion_CaCO3"] == pytest.approx(1.0, abs=1e-6)
    depth = sol.fluxes["bed_depth"]
    # 44 % of the limestone leaves as CO2: the uniform depth upstream of the dam's backwater
    # falls with the flow (Kramers: K ~ q), so the calcined bed is thinner than the feed's
    assert depth[sol.z < 0.3].mean() > 1.25 * depth[(sol.z > 2.5) & (sol.z < 3.5)].mean()
    assert sol.fluxes["fill"].shape == sol.z.shape


def test_mesh_doubling(calcining):
    fine = run_kiln_case(parse_case(_case()), n_cells=200)
    coarse = calcining
    d_c = coarse.fluxes["bed_depth"]
    d_f = 0.5 * (fine.fluxes["bed_depth"][::2] + fine.fluxes["bed_depth"][1::2])
    assert np.max(np.abs(d_c - d_f)) < 0.3e-3  # m
    # the steep calcination front moves the bed by up to ~7 K between 100 and 200 cells here
    # (10 K with the constant fill of the built-in case): the depth adds no error of its own
    assert np.max(np.abs(coarse.t_bed_nodes - fine.t_bed_nodes[::2])) < 10.0


@pytest.mark.parametrize(
    ("transport", "match"),
    [
        ({"model": "scott"}, "transport.model"),
        ({"dam_height": None}, "transport.dam_height"),
    ],
)
def test_refused(transport, match):
    d = _case()
    for k, v in transport.items():
        if v is None:
            d["transport"].pop(k)
        else:
            d["transport"][k] = v
    with pytest.raises(InputError, match=match):
        kiln_from_case(parse_case(d))


@pytest.mark.parametrize(
    ("transport", "match"),
    [
        ({"volume": "fresh"}, "transport.volume"),
        ({"volume": "fresh_feed", "shrinkage": 1.0}, "transport.shrinkage"),
        ({"volume": "fresh_feed", "shrinkage": "-5 %"}, "transport.shrinkage"),
        ({"shrinkage": "30 %"}, "transport.shrinkage: 0.3 is not 0 with volume: bulk"),
    ],
)
def test_a_bad_volume_law_is_refused_naming_its_field(transport, match):
    with pytest.raises(InputError, match=match) as err:
        parse_case(_case(**transport))
    assert "\n" not in str(err.value)


@pytest.mark.parametrize(
    ("law", "match"),
    [
        (dict(volume_law="constant"), "transport.volume"),
        (dict(volume_law="fresh_feed"), "transport.volume .the fresh feed's volume flow."),
        (dict(volume_law="fresh_feed", volume_flow0=1e-5, shrinkage=1.2), "transport.shrinkage"),
        (dict(shrinkage=0.3), "transport.shrinkage"),
        (dict(volume_law="fresh_feed", volume_flow0=1e-5, shrinkage=0.3), "operation.feed"),
    ],
)
def test_a_bad_volume_law_of_the_depth_is_refused(law, match):
    from rotarykiln.kiln.bed.depth import KramersBed

    with pytest.raises(InputError, match=match):
        KramersBed(0.2, 0.2, 0.05, 0.6, 300.0, 0.025, **law)


def test_the_volume_law_is_a_field_of_the_depth():
    # bulk (default): the flow over the bulk density, the kiln's own (one density); fresh_feed:
    # the fresh feed's volume all along, the bed density falling with the mass that leaves
    kiln, _ = kiln_from_case(parse_case(_case()))
    depth = kiln.bed.depth
    assert depth.volume_law == "bulk" and depth.density == kiln.bed.bulk_density
    kiln, _ = kiln_from_case(parse_case(_case(volume="fresh_feed", shrinkage="20 %")))
    depth = kiln.bed.depth
    feed = kiln.feed.flows
    assert depth.volume_law == "fresh_feed" and depth.shrinkage == pytest.approx(0.2)
    assert depth.volume_flow0 == pytest.approx(sum(feed.values()) / kiln.bed.bulk_density)
    names = tuple(feed)
    fresh = np.array([[feed[n] for n in names]])
    assert depth.volume_flow(names, fresh)[0] == pytest.approx(depth.volume_flow0)
    assert depth.bed_density(names, fresh)[0] == pytest.approx(kiln.bed.bulk_density)
    gone = np.zeros_like(fresh)  # every fed species converted: 20 % of the volume lost
    assert depth.volume_flow(names, gone)[0] == pytest.approx(0.8 * depth.volume_flow0)
    with pytest.raises(InputError, match="material.bulk_density"):
        kiln.replace(bed__bulk_density=2.0 * kiln.bed.bulk_density)


def test_a_bed_at_the_fresh_feed_volume_stays_deep_and_moves_faster(calcining):
    # the limestone loses 44 % of its mass as CO2: at the fresh feed's volume the calcined bed
    # keeps the feed's volume flow (its density falls), where the bulk law's flow falls with the
    # mass; a larger volume flow runs deeper (Kramers: K ~ q) but faster (tau ~ A / q), so the
    # solids leave sooner
    bulk = calcining
    fresh = run_kiln_case(parse_case(_case(volume="fresh_feed")))
    assert abs(fresh.energy_closure) < 1e-6 and max(fresh.element_closure.values()) < 1e-8
    assert fresh.residence_time < bulk.residence_time
    calcined = (bulk.z > 2.5) & (bulk.z < 3.5)
    assert fresh.fluxes["bed_depth"][calcined].mean() > bulk.fluxes["bed_depth"][calcined].mean()
