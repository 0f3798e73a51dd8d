"""Checks shared by the clinker validations (the test kiln and the built-in cement kiln)."""

import warnings

from rotarykiln.chemistry import clinker as ck

#: Bogue phase -> the Taylor (1989) phase of the same name
TAYLOR_NAMES = {"C3S": "alite", "C2S": "belite", "C3A": "aluminate", "C4AF": "ferrite"}


def assert_phases_within_taylor(rep) -> None:
    """Each clinker phase of ``rep`` (:func:`~rotarykiln.chemistry.clinker.clinker_report`)
    no farther from Bogue's pure phase than Taylor's modified Bogue is for the same oxides:
    what the literature says separates real clinker phases from Bogue's."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        taylor = ck.taylor_phase_composition({k: v for k, v in rep.oxides.items() if k != "other"})
    scale = 1.0 - rep.loss_on_ignition
    for p, t in TAYLOR_NAMES.items():
        allowed = abs(taylor[t] * scale - rep.bogue[p])
        assert abs(rep.phases[p] - rep.bogue[p]) <= allowed, (p, rep.phases[p], rep.bogue[p])
