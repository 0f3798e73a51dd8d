"""A lining layer whose thickness varies along the kiln (``thickness_profile``: a coating built up
in the burning zone, a worn brick), issue 26 "Coating and rings": in the wall's conduction, cell
by cell."""

from __future__ import annotations

import copy
import warnings

import numpy as np
import pytest
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.errors import InputError
from rotarykiln.heat.wall import cylinder_layer_heat_flow
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.steady.solve import solve_kiln

BARR = yaml.safe_load(builtin_case_path("barr_T4").read_text())
# a coating of k = 1 W/(m K) (the 0.5-1.5 of cement-kiln practice), 60 mm over 3-4 m, none
# elsewhere, on the hot face of Barr's refractory
COATING = {
    "material": {"name": "coating", "k": [1.0], "emissivity": 0.9, "t_max": "1800 K"},
    "thickness_profile": [["0 m", "0 mm"], ["3 m", "0 mm"], ["3.2 m", "60 mm"],
                          ["3.8 m", "60 mm"], ["4 m", "0 mm"]],
}  # fmt: skip


def _solve(data, cells=55):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        kiln, _ = kiln_from_case(parse_case(data))
        return kiln, solve_kiln(kiln, cells)


@pytest.fixture(scope="module")
def plain_and_coated():
    coated = copy.deepcopy(BARR)
    coated["wall"]["lining"] = [COATING, *coated["wall"]["lining"]]
    return _solve(BARR), _solve(coated)


def test_a_constant_profile_is_the_constant_layer():
    data = copy.deepcopy(BARR)
    brick = data["wall"]["lining"][0]
    thickness = brick.pop("thickness")
    brick["thickness_profile"] = [["0 m", thickness], ["5.5 m", thickness]]
    _, a = _solve(BARR)
    _, b = _solve(data)
    np.testing.assert_array_equal(a.t_bed_nodes, b.t_bed_nodes)
    np.testing.assert_array_equal(a.t_lining, b.t_lining)


def test_the_coating_insulates_where_it_lies_and_nowhere_else(plain_and_coated):
    (_, plain), (kiln, coated) = plain_and_coated
    z = coated.z
    inside = (z > 3.25) & (z < 3.75)
    far = z < 2.0
    # more resistance: a colder shell and less loss where the coating lies
    assert np.all(coated.t_shell[inside] < plain.t_shell[inside] - 5.0)
    q_p, q_c = plain.fluxes["q_shell_loss"], coated.fluxes["q_shell_loss"]
    assert np.all(q_c[inside] < 0.99 * q_p[inside])
    # where there is none, the wall is the plain one (the absent layer 1 um thick): the shell
    # differs only through the gas and bed the coated zone changed
    assert np.max(np.abs(coated.t_shell[far] - plain.t_shell[far])) < 2.0
    assert abs(coated.energy_closure) < 1e-6


def test_the_heat_through_the_coated_wall_is_its_series_conduction(plain_and_coated):
    """At a coated cell the heat the shell loses is what conducts through coating, brick and
    steel between the solved inner-wall and shell temperatures (the layers' k(T) integrals in
    series, the interface temperatures solved): the coating is in the wall's conduction."""
    _, (kiln, sol) = plain_and_coated
    j = int(np.argmin(np.abs(sol.z - 3.5)))
    layers = kiln.wall.layers
    r = kiln.drum.radius + np.concatenate(
        [[0.0], np.cumsum([la.thickness_at(sol.z[j]) for la in layers])]
    )
    t = sol.t_lining[:, j]  # inner surface, interfaces, shell
    flows = [
        float(
            cylinder_layer_heat_flow(
                la.material.conductivity_integral(t[i]),
                la.material.conductivity_integral(t[i + 1]),
                r[i],
                r[i + 1],
            )
        )
        for i, la in enumerate(layers)
    ]
    np.testing.assert_allclose(flows, flows[0], rtol=1e-6)  # the same heat through each layer
    assert flows[0] == pytest.approx(sol.fluxes["q_shell_loss"][j], rel=1e-6)


@pytest.mark.parametrize(
    "edit, message",
    [
        ({"thickness": "10 mm"}, "thickness or thickness_profile"),
        ({"thickness_profile": [["1 m", "5 mm"], ["1 m", "6 mm"]]}, "must increase"),
        ({"thickness_profile": [["0 m", "0 mm"], ["1 m", "0 mm"]]}, "0 everywhere"),
        ({"thickness_profile": [["0 m", "-1 mm"]]}, "thickness_profile"),
    ],
)
def test_a_bad_profile_is_refused_with_its_field(edit, message):
    data = copy.deepcopy(BARR)
    data["wall"]["lining"] = [{**COATING, **edit}, *data["wall"]["lining"]]
    with pytest.raises(InputError, match=message):
        parse_case(data)
