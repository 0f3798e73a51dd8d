"""Build the :class:`~rotarykiln.kiln.model.Kiln` of a validated case file.

:func:`kiln_from_case` is the one entry point from a :class:`rotarykiln.case.Case` to the
kiln model (steady solve, transient, sweeps, the app).
"""

from __future__ import annotations

__all__ = ["kiln_from_case"]


def kiln_from_case(case):
    """The :class:`~rotarykiln.kiln.model.Kiln` and cell count of a validated case.

    Examples
    --------
    >>> from rotarykiln.case import load_case
    >>> from rotarykiln.cases import builtin_case_path
    >>> kiln, cells = kiln_from_case(load_case(builtin_case_path("barr_T4")))
    >>> round(kiln.length, 2), cells
    (5.5, 100)
    """
    if getattr(case, "chemistry", None) is not None:
        from rotarykiln.kiln.reacting import reacting_kiln_from_case

        return reacting_kiln_from_case(case)
    from rotarykiln.kiln.run import heat_kiln_from_case

    return heat_kiln_from_case(case)
