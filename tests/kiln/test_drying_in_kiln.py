"""The default (boiling) drying law inside the kiln: no liquid water above the boiling point."""

from __future__ import annotations

import pytest
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.commands.kiln_runs import run_kiln_case


@pytest.mark.parametrize(
    ("feed_temperature", "cells"), [("300 K", 100), ("300 K", 200), ("550 K", 200)]
)
def test_limestone_with_the_default_drying_law(feed_temperature, cells):
    d = yaml.safe_load(builtin_case_path("limestone_calcination").read_text())
    d["chemistry"]["reactions"] = ["drying", "calcination_luisser"]
    d["operation"]["feed_temperature"] = feed_temperature
    sol = run_kiln_case(parse_case(d), cells)
    s = sol.summary()
    assert abs(s["energy_balance_closure"]) < 1e-6 and s["element_balance_closure"] < 1e-8
    water = sol.bed_flows["H2O(l)"]
    hot = sol.t_bed_nodes[1:] > 375.15  # the feed face itself is the given inlet state
    assert water[1:][hot].max() < 1e-5 * water[0]
    assert s["conversion_CaCO3"] == pytest.approx(1.0, abs=1e-6)
