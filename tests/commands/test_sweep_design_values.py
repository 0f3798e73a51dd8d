"""The sweep command refuses, before anything runs, a design value the case file would refuse:
of a sampled design (more than 50 values of a field) its smallest and largest are checked."""

import pytest
import yaml

from rotarykiln.cases import builtin_case_path
from rotarykiln.commands.sweep import check_design_values
from rotarykiln.errors import InputError
from rotarykiln.studies.design import CaseSpec


def _design(values):
    return [CaseSpec(i, {"operation.feed": v}) for i, v in enumerate(values)]


def test_the_extremes_of_a_sampled_design_are_checked_wherever_they_lie():
    base = yaml.safe_load(builtin_case_path("barr_T4").read_text())
    fine = [f"{55.0 + 0.2 * i:.6g} kg/h" for i in range(60)]
    check_design_values(base, _design(fine), "--param", "kiln")
    # the one refused value is the 60th: past the first 50, the smallest of them all
    bad = [*fine[:59], "-5 kg/h"]
    with pytest.raises(InputError, match=r"--param: .*operation.feed"):
        check_design_values(base, _design(bad), "--param", "kiln")
