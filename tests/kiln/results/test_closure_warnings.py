"""Warnings with meaning: one per closure out of its range, naming the heat flow it feeds, its
share of the heat to the solids and the other choices; library defaults said so; every built-in
kiln case's warnings listed in its header comment."""

from __future__ import annotations

import re
import warnings

import numpy as np
import pytest
import yaml

from rotarykiln.case import load_case, parse_case
from rotarykiln.cases import builtin_case_path, list_builtin_cases
from rotarykiln.cli import main
from rotarykiln.commands.kiln_runs import kiln_run
from rotarykiln.errors import OutOfRangeWarning
from rotarykiln.kiln.inputs.closures import COVERED_WALL
from rotarykiln.kiln.results.closure_warnings import PATHS, ClosureWarning

# the case of docs/getting-started.md: a library solid and no particle size
MY_KILN = """
name: limestone pilot kiln
kiln:      {length: 5.5 m, diameter: 0.406 m, slope: 3 %}
operation: {speed: 1.5 rpm, feed: 42 kg/h}
material:  {name: limestone, solid: limestone, bulk_density: 1500 kg/m3, repose_angle: 35 deg}
bed:       {fill: 0.1}
gas:       {flow: 180 kg/h, temperature: 1300 K}
wall:      {lining: [{material: fireclay_brick, thickness: 50 mm}]}
"""


def _run(case):
    """The kiln run of ``case`` and the warnings it gave."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        run = kiln_run(case)
    return run, [w.message for w in caught]


@pytest.fixture(scope="module")
def barr_t4():
    return _run(load_case(builtin_case_path("barr_T4")))


def test_barr_t4_one_li_warning_with_its_heat_path_share_and_alternatives(barr_t4):
    run, shown = barr_t4
    li = [w for w in shown if "Li et al. (2005)" in str(w)]
    assert len(li) == 1 and len(shown) == 1, [str(w) for w in shown]
    (w,) = li
    assert isinstance(w, ClosureWarning) and isinstance(w, OutOfRangeWarning)
    text = str(w)
    assert w.field == "closures.covered_wall" and w.value == "li2005"
    assert w.paths == ("q_covered_wall_bed",)
    assert PATHS["q_covered_wall_bed"][0] in text  # the covered wall -> bed contact
    # the alternatives: the field and every other value it accepts
    others = [v for v in COVERED_WALL if v != "li2005"]
    assert set(w.alternatives) == set(others)
    assert f"closures.covered_wall: {', '.join(others)}" in text
    # what is outside, with its unit and where it comes from (the case gives it)
    assert "d_p = 2.5 mm (material.particle_size)" in text
    # the share, from the solution's heat flows: the covered wall's part of the heat the bed
    # exchanges with gas and wall, cell by cell
    sol = run.value
    dz = np.diff(sol.z_nodes)
    paths = [np.abs(sol.fluxes[k]) for k, (_, side) in PATHS.items() if side == "bed"]
    expected = 100.0 * float(np.abs(sol.fluxes["q_covered_wall_bed"]) @ dz) / float(sum(paths) @ dz)
    assert 0.0 < w.share < 100.0
    assert w.share == pytest.approx(expected, rel=1e-12)
    assert f"{w.share:.0f} % of the heat to the solids" in text
    net = float(sum(np.asarray(sol.fluxes[k]) for k, (_, s) in PATHS.items() if s == "bed") @ dz)
    assert net == pytest.approx(sol.heat_to_solids, rel=1e-6)  # an inert bed: all of it
    assert f"{net / 1e3:.3g} kW net)" in text
    assert run.extra["closure_warnings"] == [w]


def test_the_cli_and_the_api_show_it_once(tmp_path, capsys):
    import rotarykiln as rk

    assert main(["run", "barr_T4", "--no-plots", "--out", str(tmp_path / "b")]) == 0
    err = capsys.readouterr().err
    lines = [x for x in err.splitlines() if x.startswith("warning: ")]
    assert len(lines) == 1 and lines[0].startswith("warning: closures.covered_wall: li2005")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # not shown here; kept by the result all the same
        result = rk.run("barr_T4")
    assert len(result.warnings) == 1 and result.warnings[0] == lines[0][len("warning: ") :]
    (w,) = result.closure_warnings
    assert str(w) == result.warnings[0]
    assert "closures.covered_wall: li2005" in repr(result) and "% of the heat" in repr(result)


def test_a_library_default_is_said_to_be_one():
    data = yaml.safe_load(MY_KILN)
    _, shown = _run(parse_case(data))
    li = [w for w in shown if getattr(w, "closure", None) == "covered_wall.li2005"]
    assert len(li) == 1, [str(w) for w in shown]
    text = str(li[0])
    assert "d_p = 5 mm (the library default for limestone: give material.particle_size)" in text
    # given in the case, inside the fit: no warning about it
    data["material"]["particle_size"] = "0.5 mm"
    _, shown = _run(parse_case(data))
    assert not [w for w in shown if getattr(w, "closure", None) == "covered_wall.li2005"]
    # given in the case, outside the fit: the case's field, not a default
    data["material"]["particle_size"] = "3 mm"
    _, shown = _run(parse_case(data))
    (li,) = [w for w in shown if getattr(w, "closure", None) == "covered_wall.li2005"]
    assert "d_p = 3 mm (material.particle_size)" in str(li) and "default" not in str(li)


def _kiln_cases():
    out = []
    for name in list_builtin_cases():
        case = load_case(builtin_case_path(name))
        if case.has_kiln_model:
            out.append(name)
    return out


@pytest.mark.parametrize("name", _kiln_cases())
def test_every_builtin_kiln_case_lists_its_warnings_in_its_header(name):
    path = builtin_case_path(name)
    comments = [x for x in path.read_text(encoding="utf-8").splitlines() if x.startswith("#")]
    listed = {
        m.group(1) for x in comments if (m := re.match(r"#\s*Warns: (closures\.\w+: \w+)", x))
    }
    _, shown = _run(load_case(path))
    closures = [w for w in shown if isinstance(w, ClosureWarning)]
    named = [f"{w.field}: {w.value}" for w in closures]
    assert len(named) == len(set(named))  # once per closure per run
    for w in shown:
        if not isinstance(w, ClosureWarning):  # another model's range: its source named
            assert w.source and any(w.source in x for x in comments), str(w)
        else:
            assert 0.0 <= w.share <= 100.0
            assert "% of the heat to the solids" in str(w) and "Alternatives: closures." in str(w)
    # each warning listed in the header, and each listed one still warned
    assert set(named) == listed, (name, named, listed)
