"""The notebook API: load a case, change it, run it, look at the result.

Three calls, in the spirit of pvlib's ``ModelChain`` and Cantera's ``Solution``::

    import rotarykiln as rk

    case = rk.load_case("barr_T4", overrides={"operation.feed": "80 kg/h"})
    result = rk.run(case)          # what `rotarykiln run` computes, without writing files
    result                         # a short summary (a table in a notebook)
    result.to_frame()              # the kiln profiles, one row per face
    result.plot()                  # the kiln's temperatures with the measured points

:func:`load_case` reads a built-in case by name or a YAML file, with ``overrides`` (dotted
fields) applied to the file's mapping before it is validated, exactly as if the file said so.
A case is frozen; :meth:`rotarykiln.case.Case.replace` gives a changed, validated copy.
:func:`run` solves every model the case asks for through the code path of ``rotarykiln run``
(:func:`rotarykiln.commands.run.solve_case`: the transport bed profile feeding the kiln's fill,
the kiln model, the RTD) and returns one :class:`Result`.
"""

from __future__ import annotations

import html
import warnings
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # pragma: no cover - type names only
    import pandas as pd

    from rotarykiln.case import Case

__all__ = ["Result", "load_case", "run"]

MODELS = ("kiln", "transport", "rtd")
"""The models a :class:`Result` may hold, in the order :meth:`Result.to_frame` and
:meth:`Result.plot` choose their default from."""

_PROFILES = {"bed": "bed", "gas": "gas", "gas_wall": "gas near the wall", "wall": "wall"}


def load_case(case: str | Path | Case, overrides: Mapping[str, Any] | None = None) -> Case:
    """A validated case: a built-in case by name, a YAML case file, or a case, with overrides.

    Parameters
    ----------
    case : str, Path or Case
        The name of a built-in case (``"barr_T4"``, ``"retort/case02"``; see
        :func:`rotarykiln.cases.list_builtin_cases`), the path of a YAML case file, or a
        validated :class:`~rotarykiln.case.Case`.
    overrides : mapping, optional
        Dotted field -> value, as a case file would give it: ``{"operation.speed": "2.5 rpm",
        "bed.fill": 0.1, "wall.lining[0].thickness": "80 mm"}``; None removes a field.
        They are applied to the file's mapping before it is validated, so the case is the one
        the edited file would give (files it names are still looked up beside it).

    Returns
    -------
    Case

    Raises
    ------
    InputError
        One line naming the dotted field: a field the case has not (``operation.sped: not a
        field of the case, did you mean "speed"? ...``) or a value it refuses.

    Examples
    --------
    >>> case = load_case("barr_T4", overrides={"operation.speed": "2.5 rpm"})
    >>> round(case.operation.speed * 60 / (2 * 3.141592653589793), 6)
    2.5
    >>> load_case("barr_T4", overrides={"operation.sped": "2.5 rpm"})  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: operation.sped: not a field of the case, did you mean "speed"? ...
    """
    from rotarykiln.case import Case, _case_folder, change_fields, parse_case, read_case_yaml

    if isinstance(case, Case):
        return case.replace(overrides) if overrides else case
    from rotarykiln.commands.run import case_path

    path = case_path(str(case))
    data = change_fields(read_case_yaml(path), overrides)
    # as rotarykiln.case.load_case does: the files a case names are beside it
    return parse_case(data, source=str(path), base_dir=_case_folder(path))


def run(case: str | Path | Case, overrides: Mapping[str, Any] | None = None) -> Result:
    """Run a case as ``rotarykiln run`` does, in memory (no file is written).

    The models the case asks for are solved by :func:`rotarykiln.commands.run.solve_case`, the
    code path of the command: the transport bed profile (a ``transport:`` section, which then
    sets the kiln's fill), the kiln model (a heat source or chemistry) with the residence-time
    effects of a reacting bed, the RTD (an ``rtd:`` section), and the scores at the measured
    points. The warnings raised are kept in :attr:`Result.warnings` (one per closure of the kiln
    used outside its validated range, then any other, once each) and shown once each as the
    caller's warning filters say (``warnings.simplefilter("ignore")`` hides them, not from the
    result).

    Parameters
    ----------
    case : str, Path or Case
        A case, or what :func:`load_case` reads one from.
    overrides : mapping, optional
        Dotted field -> value (see :func:`load_case`).

    Returns
    -------
    Result

    Examples
    --------
    >>> result = run("tscheng_A16")
    >>> result.models
    ('kiln',)
    >>> abs(result.summary["kiln_energy_balance_closure"]) < 1e-6
    True
    """
    from rotarykiln.commands.run import solve_case
    from rotarykiln.report import case_summary

    case = load_case(case, overrides)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")  # every one kept, whatever the caller shows
        runs = solve_case(case)
    kept = {str(w.message): w for w in caught}  # once per text, in order
    for w in kept.values():  # shown (or not, or raised) as the caller's filters say
        warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    summary = case_summary(case)
    for solved in runs.values():
        summary.update(solved.summary)
    texts = tuple(kept)
    return Result(case=case, runs=runs, summary=summary, warnings=texts)


@dataclass(frozen=True, repr=False)
class Result:
    """What :func:`run` computed for a case: the models' results, the summary, the warnings.

    Attributes
    ----------
    case : Case
        The validated case that was run.
    runs : dict
        Model name -> :class:`rotarykiln.commands.model_runs.ModelRun` (in the order they ran).
    summary : dict
        The values ``rotarykiln run`` writes to ``summary.json`` (the names of its files
        aside): the case's geometry and regime, then each model's values (``transport_*``,
        ``kiln_*``, ``rtd_*``).
    warnings : tuple of str
        The texts of the warnings raised during the run, each once: one per closure of the
        kiln used outside its validated range (naming the heat flow it feeds, its share of the
        heat to the solids and the other choices; :attr:`closure_warnings`), then any other.
    """

    case: Case
    runs: dict = field(default_factory=dict)
    summary: dict = field(default_factory=dict)
    warnings: tuple = ()

    # --- the models' results ---------------------------------------------------------------
    @property
    def models(self) -> tuple[str, ...]:
        """Names of the models that ran (``"transport"``, ``"kiln"``, ``"rtd"``)."""
        return tuple(self.runs)

    def _value(self, model: str):
        run = self.runs.get(model)
        return None if run is None else run.value

    @property
    def solution(self):
        """The :class:`~rotarykiln.kiln.results.solution.KilnSolution` (None without the kiln model)."""
        return self._value("kiln")

    @property
    def bed(self):
        """The :class:`~rotarykiln.transport.result.BedProfile` of the ``transport:`` model (None
        without one)."""
        return self._value("transport")

    @property
    def rtd(self):
        """The :class:`~rotarykiln.rtd.predict.RTDPrediction` of the ``rtd:`` section (None
        without one)."""
        return self._value("rtd")

    @property
    def residence(self):
        """The :class:`~rotarykiln.kiln.bed.residence.ResidenceTimeEffects` of a reacting kiln
        (plug against segregated flow over the RTD; None otherwise)."""
        run = self.runs.get("kiln")
        return None if run is None else run.extra.get("residence")

    @property
    def closure_warnings(self) -> tuple:
        """The kiln's closures used outside their validated range, one
        :class:`~rotarykiln.kiln.results.closure_warnings.ClosureWarning` each (its text is in
        :attr:`warnings`; its ``field``, ``alternatives``, ``share`` of the heat to the solids,
        ``short`` line as attributes); empty without the kiln model or such a closure."""
        run = self.runs.get("kiln")
        return () if run is None else tuple(run.extra.get("closure_warnings", ()))

    @property
    def scores(self) -> dict:
        """RMSE (K) of the kiln solution at the measured points, per measured profile (``bed``,
        ``gas``, ``gas_wall``, ``wall``, ``gas_thermocouple``); empty without measurements."""
        return {} if self.solution is None else self.solution.measured_rmse()

    # --- tables and figures ------------------------------------------------------------------
    def _model(self, model: str | None, also: tuple[str, ...] = ()) -> str:
        from rotarykiln.errors import InputError

        present = [m for m in MODELS if m in self.runs]
        if self.residence is not None:
            present += list(also)
        if model is None and present:
            return present[0]
        if model not in present:
            shown = ", ".join(present) or "none: the case asks for no model"
            raise InputError("model", model, f"one of the models this case ran ({shown})")
        return model

    def to_frame(self, model: str | None = None) -> pd.DataFrame:
        """A model's profiles as a table (columns with units, e.g. ``T_bed_K``).

        Parameters
        ----------
        model : {"kiln", "transport", "rtd"}, optional
            Default: the first of them that ran (the kiln model's faces, the bed profile along
            the kiln, the predicted E(t)).
        """
        return self.runs[self._model(model)].value.to_frame()

    def measured(self) -> pd.DataFrame:
        """The measured points beside the computed values: one row per point with ``profile``
        (bed, gas, gas_wall, wall, gas_thermocouple), ``z_m``, ``measured_K``, ``computed_K``
        and ``residual_K`` (computed - measured). The RMSE of each profile's residuals is
        :attr:`scores`. Empty without measurements."""
        import numpy as np
        import pandas as pd

        sol = self.solution
        rows = []
        m = (sol.measurements if sol is not None else None) or {}
        tc = sol._thermocouple_nodes() if sol is not None else None
        at = {
            "bed": sol.bed_temperature_at if sol is not None else None,
            "gas": sol.gas_temperature_at if sol is not None else None,
            "gas_wall": sol.gas_temperature_at if sol is not None else None,
            "wall": (lambda z: sol.wall_temperature_at(z, int(m.get("wall_interface", 0)))),
        }
        for key in _PROFILES:
            z, t = np.asarray(m.get(f"z_{key}", ())), np.asarray(m.get(f"t_{key}", ()))
            if not (len(z) and len(t)):
                continue
            computed = {key: at[key](z)}
            if tc is not None and key == "gas":
                computed["gas_thermocouple"] = np.interp(z, sol.z_nodes, tc)
            for name, values in computed.items():
                for zi, ti, ci in zip(z, t, values, strict=True):
                    rows.append((name, float(zi), float(ti), float(ci), float(ci - ti)))
        columns = ["profile", "z_m", "measured_K", "computed_K", "residual_K"]
        return pd.DataFrame(rows, columns=columns)

    def plot(self, model: str | None = None):
        """A model's figure; returns the matplotlib Figure.

        Parameters
        ----------
        model : {"kiln", "transport", "rtd", "residence"}, optional
            Default: the first that ran of kiln (temperatures with the measured points, and the
            species flows of a reacting bed), transport (the bed depth along the kiln), rtd
            (E(t)); ``residence``: a reacting bed's conversion over the RTD.
        """
        model = self._model(model, also=("residence",))
        value = self.residence if model == "residence" else self.runs[model].value
        drawn = value.plot()
        return getattr(drawn, "figure", drawn)  # an Axes or a Figure

    # --- display ------------------------------------------------------------------------------
    def _lines(self) -> list[tuple[str, str]]:
        """(label, text) pairs of the short display, shared by the repr and the HTML."""
        s, lines = self.summary, []
        sol = self.solution
        if sol is not None:
            lines.append(
                (
                    "kiln",
                    f"bed {sol.t_bed_nodes[0]:.1f} -> {sol.bed_outlet_temperature:.1f} K, gas out "
                    f"{sol.gas_outlet_temperature:.1f} K, heat to solids "
                    f"{sol.heat_to_solids / 1e3:.3g} kW, {len(sol.z)} cells, energy closure "
                    f"{sol.energy_closure:.1e}",
                )
            )
            conversions = [
                f"{species} {s[f'kiln_conversion_{species}']:.3f}"
                for species in sol.bed_flows
                if f"kiln_conversion_{species}" in s
            ]
            if conversions:
                lines.append(("conversion", ", ".join(conversions)))
        if self.bed is not None:
            b = self.bed
            lines.append(
                (
                    f"bed profile ({b.model})",
                    f"mean fill {b.mean_fill:.4f}, residence time "
                    f"{b.mean_residence_time / 60:.1f} min",
                )
            )
        if self.rtd is not None:
            r = self.rtd
            lines.append(
                (
                    f"rtd ({r.model})",
                    f"mean residence time {r.mean_residence_time / 60:.1f} min, Pe {r.peclet:.3g}",
                )
            )
        if self.scores:
            shown = ", ".join(f"{_PROFILES.get(k, k)} {v:.1f} K" for k, v in self.scores.items())
            lines.append(("measured, RMSE", shown))
        n = len(self.warnings)
        closures = self.closure_warnings
        for w in closures:  # one line each: the closure, what is outside, its share
            lines.append(("closure warning", w.short))
        if n > len(closures):
            others = [t for t in self.warnings if t not in {str(w) for w in closures}]
            first = others[0] if len(others[0]) <= 90 else others[0][:87] + "..."
            more = f" (and {len(others) - 1} more: .warnings)" if len(others) > 1 else ""
            lines.append(("warnings", f"{len(others)}: {first}{more}"))
        return lines

    def __repr__(self) -> str:
        models = ", ".join(self.models) or "none"
        head = f"<rotarykiln Result {self.case.name!r}: models {models}>"
        body = [f"  {label}: {text}" for label, text in self._lines()]
        tail = (
            f"  .summary ({len(self.summary)} values), .to_frame(), .plot(), .measured(), "
            ".solution, .bed, .rtd, .warnings"
        )
        return "\n".join([head, *body, tail])

    def _repr_html_(self) -> str:
        e = html.escape
        rows = "".join(
            f"<tr><th style='text-align:left'>{e(label)}</th>"
            f"<td style='text-align:left'>{e(text)}</td></tr>"
            for label, text in self._lines()
        )
        models = ", ".join(self.models) or "none"
        return (
            f"<div><strong>rotarykiln result: {e(self.case.name)}</strong> "
            f"(models: {e(models)})<table>{rows}</table>"
            f"<small>.summary ({len(self.summary)} values), .to_frame(), .plot(), "
            ".measured()</small></div>"
        )
