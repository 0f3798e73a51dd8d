"""Study designs over case field paths: grids, one-at-a-time, Latin hypercube, Sobol, Monte Carlo.

A design is a list of :class:`CaseSpec`: an id, the values to set (path -> value as given, a
number or a string with units such as ``"62 kg/h"``) and a group (``"base"``, ``"grid"``, the
path varied one at a time, ``"lhs"``, ``"sobol"``, ``"mc"``). Sampled designs draw from a
:class:`Param` (path, distribution, unit), parsed from ``"operation.speed=uniform(1 rpm, 3 rpm)"``.
"""

from __future__ import annotations

import difflib
import functools
import itertools
import math
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from rotarykiln.errors import InputError
from rotarykiln.studies.io import shown

__all__ = [
    "DISTRIBUTIONS",
    "MAX_DESIGN_CASES",
    "CaseSpec",
    "check_design_size",
    "Param",
    "as_params",
    "cases_from_unit",
    "grid",
    "latin_hypercube",
    "monte_carlo",
    "one_at_a_time",
    "parse_param",
    "si_value",
    "sobol_sequence",
    "typed_unit",
    "unit_latin_hypercube",
    "in_unit",
]


MAX_DESIGN_CASES = 100_000
"""Most cases of one design, whatever its kind (grid, one at a time, sampled, sensitivity):
checked from the counts before the design is built."""


def check_design_size(cases: int, option: str, how: str = "") -> int:
    """Refuse a design of more than :data:`MAX_DESIGN_CASES` cases, before it is built.

    Parameters
    ----------
    cases : int
        Number of cases the design would have.
    option : str
        The option or field that sets it (named in the message).
    how : str
        How the count follows from the inputs, e.g. "n (d + 2)".

    Returns
    -------
    int
        ``cases``.

    Examples
    --------
    >>> check_design_size(10**6, "--grid", "4 values x 250000 values")
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: --grid: a design of 1000000 cases (4 values x 250000 values) is not at most 100000 cases
    """
    if cases > MAX_DESIGN_CASES:
        detail = f" ({how})" if how else ""
        raise InputError(
            option, f"a design of {cases} cases{detail}", f"at most {MAX_DESIGN_CASES} cases"
        )
    return cases


@dataclass(frozen=True)
class CaseSpec:
    """One case of a sweep."""

    case_id: int
    values: dict[str, Any] = field(default_factory=dict)
    group: str = "grid"


def _counts(ranges: Mapping[str, list]) -> str:
    return " x ".join(f"{len(v)} values of {shown(p, 40)}" for p, v in ranges.items())


def _check_ranges(ranges: Mapping[str, Sequence]) -> dict[str, list]:
    if not isinstance(ranges, Mapping) or not ranges:
        raise InputError("sweep.parameters", ranges, "a non-empty mapping path -> list of values")
    out = {}
    for path, values in ranges.items():
        if isinstance(values, str | bytes) or not isinstance(values, Sequence) or len(values) == 0:
            raise InputError(f"sweep.parameters.{path}", values, "a non-empty list of values")
        out[path] = list(values)
    return out


def grid(ranges: Mapping[str, Sequence]) -> list[CaseSpec]:
    """Full factorial design: every combination of the given values.

    Examples
    --------
    >>> [c.values for c in grid({"a": [1, 2], "b": ["x", "y"]})]
    [{'a': 1, 'b': 'x'}, {'a': 1, 'b': 'y'}, {'a': 2, 'b': 'x'}, {'a': 2, 'b': 'y'}]
    """
    r = _check_ranges(ranges)
    paths = list(r)
    check_design_size(math.prod(len(v) for v in r.values()), "--grid", _counts(r))
    return [
        CaseSpec(i, dict(zip(paths, combo, strict=True)), "grid")
        for i, combo in enumerate(itertools.product(*(r[p] for p in paths)))
    ]


def one_at_a_time(ranges: Mapping[str, Sequence], include_base: bool = True) -> list[CaseSpec]:
    """One-at-a-time design: vary each path over its values, the others at the base case.

    Examples
    --------
    >>> [(c.group, c.values) for c in one_at_a_time({"a": [1, 2], "b": [5]})]
    [('base', {}), ('a', {'a': 1}), ('a', {'a': 2}), ('b', {'b': 5})]
    """
    r = _check_ranges(ranges)
    check_design_size(sum(len(v) for v in r.values()) + include_base, "--oat")
    cases = [CaseSpec(0, {}, "base")] if include_base else []
    for path, values in r.items():
        for v in values:
            cases.append(CaseSpec(len(cases), {path: v}, path))
    return cases


def si_value(value: Any) -> float:
    """Numeric SI value of a sweep value: numbers as they are, "62 kg/h" -> 0.01722 (kg/s).

    Returns NaN for values that are not quantities (e.g. a model name); used for table columns
    and plot axes only.

    Examples
    --------
    >>> round(si_value("62 kg/h"), 5), si_value(3), si_value("1100 degC")
    (0.01722, 3.0, 1373.15)
    """
    if isinstance(value, bool):
        return float(value)
    if isinstance(value, int | float):
        return float(value)
    if isinstance(value, str):
        return _si_text(value)
    return math.nan


@functools.lru_cache(maxsize=8192)
def _si_text(value: str) -> float:
    """:func:`si_value` of a text, kept per distinct text (pint reads one in ~0.3 ms; a
    study's table asks for each of its values more than once)."""
    m = _NUMBER.match(value)
    if m and m.group(2):
        conversion = _base_conversion(m.group(2))
        if conversion is not None:
            from rotarykiln.units import converted

            return converted(float(m.group(1)), conversion)
    return _pint_si(value)


def _pint_si(text: str) -> float:
    from rotarykiln.units import ureg

    try:
        q = ureg.Quantity(text.strip())
    except Exception:  # not a quantity: a label
        return math.nan
    try:
        return float(q.to_base_units().magnitude)
    except Exception:
        return math.nan


@functools.lru_cache(maxsize=256)
def _base_conversion(unit: str) -> tuple[float, float] | None:
    """``(factor, offset)`` of a unit to pint's base units, as
    :func:`rotarykiln.units._unit_conversion` (the same floats as pint's conversion of a
    whole text); None for a unit that is neither a factor nor a kelvin offset, or a label."""
    from rotarykiln.units import linear_conversion

    return linear_conversion(_pint_si(f"0 {unit}"), _pint_si(f"1 {unit}"))


# ---------------------------------------------------------------------------------------------
# Distributions and sampled designs (Latin hypercube, Sobol sequence, Monte Carlo)

DISTRIBUTIONS = ("uniform", "normal", "lognormal", "triangular")
"""Distribution names accepted by :func:`parse_param`."""

_NUMBER = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")
_SPEC = re.compile(r"^\s*([A-Za-z_]+)\s*\((.*)\)\s*$")
_NARGS = {"uniform": 2, "normal": 2, "lognormal": 2, "triangular": 3}
_SIGNATURE = {
    "uniform": "uniform(low, high) with low < high",
    "normal": "normal(mean, sd) with sd > 0",
    "lognormal": "lognormal(median, sigma) with median > 0 and sigma > 0 (sd of ln x, -)",
    "triangular": "triangular(low, mode, high) with low <= mode <= high and low < high",
}


def _split_quantity(value: Any) -> tuple[float, str] | None:
    """``"1.5 rpm"`` -> ``(1.5, "rpm")``, ``3`` -> ``(3.0, "")``; None for a label."""
    if isinstance(value, bool):
        return float(value), ""
    if isinstance(value, int | float):
        return float(value), ""
    if isinstance(value, str):
        m = _NUMBER.match(value)
        if m is not None:
            return float(m.group(1)), m.group(2)
    return None


def typed_unit(values) -> str:
    """The unit a parameter was typed in: that of its first value with a unit.

    ``""`` when every value is a bare number or a label. Sampled designs write their values in
    the unit of the distribution's first argument (:meth:`Param.value`), so the unit typed in
    ``--param`` comes back here.

    Examples
    --------
    >>> typed_unit(["1 rpm", "3 rpm"]), typed_unit([0.1, "12 Nm3/h"]), typed_unit([1, 2])
    ('rpm', 'Nm3/h', '')
    """
    for v in values:
        q = _split_quantity(v)
        if q is not None and q[1]:
            return q[1]
    return ""


def in_unit(value: Any, unit: str) -> float:
    """Magnitude of a sweep value in ``unit`` (the unit the parameter was typed in).

    A value typed in ``unit`` keeps its number as typed (``"12 Nm3/h"``, ``"3 %"``); one in
    another unit is converted (``"0.02 kg/s"`` -> 72 for ``kg/h``); a bare number is read as
    SI, as in a case file. NaN for a label or a unit that does not convert.

    Examples
    --------
    >>> in_unit("2 rpm", "rpm"), round(in_unit("0.02 kg/s", "kg/h"), 6), in_unit(5, "")
    (2.0, 72.0, 5.0)
    >>> round(in_unit("1373.15 K", "degC"), 6), math.isnan(in_unit("steam", "kg/s"))
    (1100.0, True)
    """
    q = _split_quantity(value)
    if q is None:
        return math.nan
    number, u = q
    if u == unit:
        return number
    if not unit:
        return si_value(value)
    from rotarykiln.units import ureg

    try:
        target = ureg.Unit(unit)
        if u:
            return float(ureg.Quantity(number, u).to(target).magnitude)
        base = ureg.Quantity(1.0, target).to_base_units().units  # a bare number is SI
        return float(ureg.Quantity(number, base).to(target).magnitude)
    except Exception:  # not a pint unit (Nm3/h) or another dimension
        return math.nan


@dataclass(frozen=True)
class Param:
    """An uncertain or varied case field: a dotted path and a distribution in a unit.

    Attributes
    ----------
    path : str
        Dotted field path into the case (``"operation.speed"``).
    dist : str
        One of :data:`DISTRIBUTIONS`.
    args : tuple of float
        Distribution parameters in ``unit`` (lognormal: median in ``unit``, sigma of ln x, -).
    unit : str
        Unit as typed (``"rpm"``); "" for a plain number (SI or dimensionless).
    """

    path: str
    dist: str
    args: tuple[float, ...]
    unit: str = ""

    def ppf(self, u) -> np.ndarray:
        """Values (in ``unit``) at probabilities ``u`` in (0, 1): the inverse CDF."""
        u = np.asarray(u, dtype=float)
        a = self.args
        if self.dist == "uniform":
            return a[0] + (a[1] - a[0]) * u
        from scipy import stats  # 0.4-0.6 s to import: only for the other distributions

        if self.dist == "normal":
            return stats.norm.ppf(u, loc=a[0], scale=a[1])
        if self.dist == "lognormal":
            return stats.lognorm.ppf(u, s=a[1], scale=a[0])
        c = (a[1] - a[0]) / (a[2] - a[0])
        return stats.triang.ppf(u, c, loc=a[0], scale=a[2] - a[0])

    @property
    def bounded(self) -> bool:
        """True for distributions with finite support (uniform, triangular)."""
        return self.dist in ("uniform", "triangular")

    @property
    def nominal(self) -> float:
        """Median of the distribution, in ``unit``."""
        return float(self.ppf(0.5))

    def value(self, x: float):
        """Case-file value of ``x`` (in ``unit``): ``"1.234 rpm"`` or a float."""
        return f"{float(x):.10g} {self.unit}" if self.unit else float(x)

    def __str__(self) -> str:
        u = f" {self.unit}" if self.unit else ""
        parts = [f"{v:g}{u}" for v in self.args]
        if self.dist == "lognormal":
            parts[1] = f"{self.args[1]:g}"
        return f"{self.path}={self.dist}({', '.join(parts)})"


def _split_args(text: str) -> list[str]:
    return [t.strip() for t in text.split(",")] if text.strip() else []


def _magnitude(field: str, text: str, unit: str, delta: bool) -> float:
    """Magnitude of ``text`` in ``unit``; ``delta``: a difference (sd of a temperature in degC)."""
    m = _NUMBER.match(text)
    if m is None:
        raise InputError(field, text, "a number with an optional unit such as 1.5 rpm")
    number, u = float(m.group(1)), m.group(2)
    if u == unit or not u:
        return number
    if not unit:
        raise InputError(field, text, "a plain number like the first argument (no unit)")
    from rotarykiln.units import ureg

    try:
        q = ureg.Quantity(number, u)
        target = ureg.Unit(unit)
        if delta and q.units.dimensionality == ureg.kelvin.dimensionality:
            kelvin = q.to("delta_degC").magnitude if "deg" in u else q.to("kelvin").magnitude
            return (
                float(kelvin * ureg.Quantity(1, "delta_degC").to(f"delta_{unit}").magnitude)
                if unit.startswith("deg")
                else float(kelvin)
            )
        return float(q.to(target).magnitude)
    except Exception:
        raise InputError(field, text, f"a quantity convertible to {unit}") from None


def parse_param(
    text: str | None = None, *, path: str | None = None, spec: str | None = None
) -> Param:
    """Parse ``"PATH=DIST(ARGS)"`` (or ``path`` and ``spec``) into a :class:`Param`.

    Parameters
    ----------
    text : str
        ``"operation.speed=uniform(1 rpm, 3 rpm)"``; arguments carry the unit of the field
        (the first one's unit is used, the others are converted to it). Distributions:
        ``uniform(low, high)``, ``normal(mean, sd)``, ``lognormal(median, sigma)`` (sigma: the
        standard deviation of ln x, dimensionless), ``triangular(low, mode, high)``.
    path, spec : str
        The two halves given separately.

    Returns
    -------
    Param
        Path, distribution name, arguments in the unit as typed, the unit.

    Examples
    --------
    >>> p = parse_param("operation.speed=uniform(1 rpm, 3 rpm)")
    >>> p.dist, p.args, p.unit, p.value(p.ppf(0.5))
    ('uniform', (1.0, 3.0), 'rpm', '2 rpm')
    >>> parse_param("heat.gas.inlet_temperature=normal(535 K, 10 K)").args
    (535.0, 10.0)
    >>> parse_param("kiln.slope=normal(1 deg, -1 deg)")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: kiln.slope: normal(1 deg, -1 deg) is not normal(mean, sd) with sd > 0

    References
    ----------
    The distributions are scipy.stats' uniform, norm, lognorm (s = sigma, scale = median) and
    triang.
    """
    if text is not None:
        path, sep, spec = text.partition("=")
        if not sep:
            raise InputError(
                "--param", text, 'PATH=DIST(ARGS), e.g. "operation.speed=uniform(1 rpm, 3 rpm)"'
            )
    path = (path or "").strip()
    spec = (spec or "").strip()
    if not path:
        raise InputError("--param", text or spec, "PATH=DIST(ARGS) with a field path")
    m = _SPEC.match(spec)
    if m is None:
        raise InputError(
            path, spec, f"a distribution such as uniform(1 rpm, 3 rpm) ({', '.join(DISTRIBUTIONS)})"
        )
    name = m.group(1).lower()
    if name not in DISTRIBUTIONS:
        hint = difflib.get_close_matches(name, DISTRIBUTIONS, n=1)
        mean = f" (did you mean {hint[0]}?)" if hint else ""
        raise InputError(path, name, f"a distribution: {', '.join(DISTRIBUTIONS)}{mean}")
    args = _split_args(m.group(2))
    if len(args) != _NARGS[name]:
        raise InputError(path, spec, _SIGNATURE[name])
    first = _NUMBER.match(args[0])
    if first is None:
        raise InputError(path, args[0], "a number with an optional unit such as 1.5 rpm")
    unit = first.group(2)
    if unit:
        from rotarykiln.units import ureg

        try:
            ureg.Unit(unit)
        except Exception:
            raise InputError(path, args[0], "a quantity with a known unit") from None
    vals = []
    for i, a in enumerate(args):
        delta = name == "normal" and i == 1
        if name == "lognormal" and i == 1:
            sm = _NUMBER.match(a)
            if sm is None or sm.group(2):
                raise InputError(path, spec, _SIGNATURE[name])
            vals.append(float(sm.group(1)))
        else:
            vals.append(_magnitude(path, a, unit, delta))
    ok = all(math.isfinite(v) for v in vals)
    if name == "uniform":
        ok = ok and vals[0] < vals[1]
    elif name in ("normal",):
        ok = ok and vals[1] > 0
    elif name == "lognormal":
        ok = ok and vals[0] > 0 and vals[1] > 0
    else:
        ok = ok and vals[0] <= vals[1] <= vals[2] and vals[0] < vals[2]
    if not ok:
        raise InputError(path, spec, _SIGNATURE[name])
    return Param(path, name, tuple(vals), unit)


def as_params(params) -> list[Param]:
    """Params from a list of Param/str or a mapping path -> spec; checks unique paths."""
    if isinstance(params, Param | str):
        params = [params]
    if isinstance(params, Mapping):
        out = [parse_param(path=k, spec=v) if isinstance(v, str) else v for k, v in params.items()]
    else:
        out = [p if isinstance(p, Param) else parse_param(p) for p in params]
    if not out:
        raise InputError("study.parameters", "[]", "at least one parameter")
    paths = [p.path for p in out]
    dup = [p for p in paths if paths.count(p) > 1]
    if dup:
        raise InputError("study.parameters", dup[0], "given once")
    return out


def _check_n(n) -> int:
    if isinstance(n, bool) or not isinstance(n, int | np.integer) or n < 1:
        raise InputError("study.n", n, "a whole number >= 1")
    return check_design_size(int(n), "study.n")


def cases_from_unit(params, unit_samples, group: str = "sample", start: int = 0) -> list[CaseSpec]:
    """Map points of the unit hypercube (rows, one column per param) to cases via the ppf.

    Parameters
    ----------
    params : sequence of Param
    unit_samples : array, shape (n, len(params)), in (0, 1) [-]
    group : str
    start : int
        First case id.

    Returns
    -------
    list of CaseSpec
        Values in each parameter's unit, as case-file strings.
    """
    params = as_params(params)
    u = np.atleast_2d(np.asarray(unit_samples, dtype=float))
    if u.shape[1] != len(params):
        raise InputError("study.samples", u.shape, f"{len(params)} columns (one per parameter)")
    cols = [p.ppf(u[:, j]) for j, p in enumerate(params)]
    return [
        CaseSpec(start + i, {p.path: p.value(cols[j][i]) for j, p in enumerate(params)}, group)
        for i in range(u.shape[0])
    ]


def latin_hypercube(params, n: int, seed: int | None = 0) -> list[CaseSpec]:
    """Latin hypercube design of ``n`` cases (the points of scipy.stats.qmc.LatinHypercube,
    :func:`unit_latin_hypercube`).

    Parameters
    ----------
    params : sequence of Param or str
        ``"path=dist(args)"`` (see :func:`parse_param`).
    n : int
        Number of cases.
    seed : int or None
        Random seed (reproducible designs: a resumed study draws the same cases).

    Returns
    -------
    list of CaseSpec
        Group ``"lhs"``.

    Examples
    --------
    >>> cs = latin_hypercube(["a=uniform(0, 1)", "b=normal(5 m, 1 m)"], 4)
    >>> sorted(int(c.values["a"] * 4) for c in cs)
    [0, 1, 2, 3]

    References
    ----------
    McKay, Beckman & Conover (1979), Technometrics 21, 239-245.
    """
    params = as_params(params)
    u = unit_latin_hypercube(len(params), _check_n(n), seed)
    return cases_from_unit(params, u, "lhs")


def unit_latin_hypercube(d: int, n: int, seed: int | None = 0) -> np.ndarray:
    """``n`` points of a Latin hypercube in the unit cube of ``d`` dimensions (n, d): in each
    dimension one point per stratum of width 1/n, the strata shuffled per dimension, each
    point uniform in its stratum.

    The points of ``scipy.stats.qmc.LatinHypercube(d, seed=seed).random(n)`` (its default,
    centred off and unoptimised: the same draws from the same generator, a test holds them
    equal) without importing scipy.stats (0.4-0.6 s, more than a study's sweep of a few
    hundred kilns costs to set up).

    Parameters
    ----------
    d, n : int
        Dimensions and points.
    seed : int or None
        Seed of numpy's default generator.

    Returns
    -------
    array (n, d), -
        In [0, 1).

    Examples
    --------
    >>> u = unit_latin_hypercube(2, 5, seed=1)
    >>> sorted((u[:, 0] * 5).astype(int).tolist()), sorted((u[:, 1] * 5).astype(int).tolist())
    ([0, 1, 2, 3, 4], [0, 1, 2, 3, 4])

    References
    ----------
    McKay, Beckman & Conover (1979), Technometrics 21, 239-245; scipy.stats.qmc.LatinHypercube.
    """
    for name, v in (("dimensions", d), ("points", n)):
        if isinstance(v, bool) or int(v) != v or v < 1:
            raise InputError(f"latin_hypercube.{name}", v, "an integer >= 1")
    rng = np.random.default_rng(seed)
    samples = rng.uniform(size=(n, d))
    perms = np.tile(np.arange(1, n + 1), (d, 1))
    for i in range(d):
        rng.shuffle(perms[i, :])
    return (perms.T - samples) / n


def sobol_sequence(params, n: int, seed: int | None = 0) -> list[CaseSpec]:
    """Scrambled Sobol low-discrepancy design of ``n`` cases (scipy.stats.qmc.Sobol).

    Parameters
    ----------
    params : sequence of Param or str
    n : int
        Number of cases (a power of 2 keeps the sequence balanced).
    seed : int or None
        Scrambling seed.

    Returns
    -------
    list of CaseSpec
        Group ``"sobol"``.

    Examples
    --------
    >>> len(sobol_sequence(["a=uniform(0, 1)"], 8))
    8

    References
    ----------
    Sobol' (1967), USSR Comput. Math. Math. Phys. 7, 86-112; Owen (1998) scrambling.
    """
    import warnings

    from scipy.stats import qmc

    params = as_params(params)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # balance warning for n not a power of 2
        u = qmc.Sobol(d=len(params), scramble=True, seed=seed).random(_check_n(n))
    return cases_from_unit(params, u, "sobol")


def monte_carlo(params, n: int, seed: int | None = 0) -> list[CaseSpec]:
    """Plain Monte Carlo design: ``n`` independent random draws of every parameter.

    Parameters
    ----------
    params : sequence of Param or str
    n : int
        Number of cases.
    seed : int or None
        numpy Generator seed.

    Returns
    -------
    list of CaseSpec
        Group ``"mc"``.

    Examples
    --------
    >>> len(monte_carlo(["a=triangular(0, 1, 3)"], 5))
    5

    References
    ----------
    Metropolis & Ulam (1949), J. Am. Stat. Assoc. 44, 335-341.
    """
    params = as_params(params)
    rng = np.random.default_rng(seed)
    u = rng.random((_check_n(n), len(params)))
    return cases_from_unit(params, np.clip(u, 1e-12, 1 - 1e-12), "mc")
