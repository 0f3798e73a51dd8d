r"""Warnings with meaning: one per closure used outside its range in a kiln run.

A closure checks its validity range once on the converged kiln
(:class:`~rotarykiln.errors.OutOfRangeWarning`, tagged with the closure that checked it). A kiln
run (:func:`rotarykiln.commands.kiln_runs.kiln_run`, behind ``rotarykiln run`` and :func:`rotarykiln.run`)
records those warnings during its solve and gives, instead, **one** :class:`ClosureWarning` per
closure, which says

- which closure it is, as the case file chooses it (``closures.covered_wall: li2005``), and
  what lies outside its range, with units; a value the case did not give is said to come from
  the library (``d_p = 5 mm, the library default for limestone: give
  material.particle_size``);
- the heat flow the closure feeds (covered wall -> bed contact, ...) and its share of the heat
  to the solids, counted in the cells where the closure is outside its range
  (:func:`heat_share`);
- the other values the case-file field accepts.

What maps a closure to its case-file field, heat flows and advice is the table
:data:`CLOSURES` (data, one entry per closure); the quantities it checks are described in
:data:`QUANTITIES`. A warning that is not a closure's (a solid's heat-capacity fit, a
reaction's range) is passed on as it was, once.

**Share of the heat to the solids.** The bed takes heat from gas and wall through three
paths per metre of kiln (W/m, :data:`rotarykiln.kiln.exchange.FLOW_KEYS`): gas -> bed surface
convection :math:`q_{gb}`, covered wall -> bed contact :math:`q_{cw}` and radiation absorbed
by the bed surface :math:`q_{rb}` (gas and wall). The heat to the solids is
:math:`Q = \int (|q_{gb}| + |q_{cw}| + |q_{rb}|)\,dz` (the net heat to the bed when every path
carries heat into it). A closure of a path into the bed counts that path; a closure of a path
into the exposed wall (gas -> wall convection, radiation to the wall) counts, cell by cell, its
part of the wall's gains times the covered-wall contact :math:`q_{cw}` by which the wall passes
heat on to the bed.
"""

from __future__ import annotations

import warnings
from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np

from rotarykiln.errors import OutOfRangeWarning

__all__ = [
    "CLOSURES",
    "QUANTITIES",
    "PATHS",
    "ClosureWarning",
    "closure_warnings",
    "emit",
    "heat_share",
]

#: The heat flows a closure can feed (keys of a kiln solution's ``fluxes``, W/m): their words
#: and the side they heat (``bed``: into the solids directly; ``wall``: the exposed wall, which
#: passes heat on to the bed through the covered wall).
PATHS: dict[str, tuple[str, str]] = {
    "q_gas_bed_conv": ("the gas -> bed surface convection", "bed"),
    "q_covered_wall_bed": ("the covered wall -> bed contact", "bed"),
    "q_rad_to_bed": ("the radiation absorbed by the bed surface", "bed"),
    "q_gas_wall_conv": ("the gas -> exposed wall convection", "wall"),
    "q_rad_to_wall": ("the radiation absorbed by the exposed wall", "wall"),
}

#: Flows into the wall besides gas convection and radiation (heaters, a jacket), W/m.
_WALL_GAINS = ("q_gas_wall_conv", "q_rad_to_wall", "q_electric_heating")

#: Closure (``"<closures field>.<value>"``, as tagged by the closures' range checks) ->
#: ``name`` (the model and its source), ``feeds`` (keys of :data:`PATHS`), ``advice`` (what the
#: other choices do, or ""). The other accepted values come from
#: :mod:`rotarykiln.kiln.inputs.kiln` (``COVERED_WALL``, ...).
CLOSURES: dict[str, dict] = {
    "covered_wall.li2005": {
        "name": "Li et al. (2005), penetration with a gas film",
        "feeds": ("q_covered_wall_bed",),
        "advice": "wachters_kramers1964 is the same penetration model without the gas film; "
        "tscheng1979 is an empirical fit without particle size",
    },
    "gas_wall.tscheng1979": {
        "name": "Tscheng & Watkinson (1979), a pilot-kiln fit",
        "feeds": ("q_gas_wall_conv",),
        "advice": "gorog1982 is a pipe-flow form for Re above 1e4",
    },
    "gas_bed.tscheng1979": {
        "name": "Tscheng & Watkinson (1979), a pilot-kiln fit",
        "feeds": ("q_gas_bed_conv",),
        "advice": "gorog1982 is a mass-flux form without a Reynolds-number range",
    },
    "gas_wall.gorog1982": {
        "name": "Gorog et al. (1982), turbulent pipe flow",
        "feeds": ("q_gas_wall_conv",),
        "advice": "tscheng1979 was fitted for Re 1600-7800",
    },
    "gas_emissivity.johansson2011": {
        "name": "Johansson et al. (2011), weighted sum of grey gases",
        "feeds": ("q_rad_to_bed", "q_rad_to_wall"),
        "advice": "smith1982 is fitted for 600-2400 K; a number in [0, 1) is a constant emissivity",
    },
    "gas_emissivity.smith1982": {
        "name": "Smith et al. (1982), weighted sum of grey gases",
        "feeds": ("q_rad_to_bed", "q_rad_to_wall"),
        "advice": "johansson2011 is fitted for 500-2500 K; a number in [0, 1) is a constant "
        "emissivity",
    },
}

#: Quantity as a closure checks it -> ``words``, ``unit`` shown, ``scale`` (shown = checked x
#: scale) and ``field`` (the case-file field that sets it, when one does).
QUANTITIES: dict[str, dict] = {
    "d_p [um]": {
        "words": "particle size d_p",
        "unit": "mm",
        "scale": 1e-3,
        "field": "material.particle_size",
    },
    "Re": {"words": "gas Reynolds number Re", "unit": "", "scale": 1.0},
    "Re_omega": {"words": "rotational Reynolds number Re_omega", "unit": "", "scale": 1.0},
    "T [K]": {"words": "gas temperature T_g", "unit": "K", "scale": 1.0},
    "MR": {"words": "H2O/CO2 molar ratio MR", "unit": "", "scale": 1.0},
}


class ClosureWarning(OutOfRangeWarning):
    """One closure of a kiln run used outside its validated range, with its meaning.

    Besides the text: ``closure`` (``"covered_wall.li2005"``), ``field``
    (``"closures.covered_wall"``), ``value`` (``"li2005"``), ``alternatives`` (the other
    accepted values), ``paths`` (the heat flows it feeds, :data:`PATHS` keys), ``share`` (%,
    of the heat to the solids, in the cells outside the range), ``heat_to_solids`` (W, counted both ways),
    ``quantities`` (the quantities outside the range: (quantity, smallest, largest, low, high))
    and ``short``: one short line (``closures.covered_wall: li2005 outside its range (d_p),
    23 % of the heat to the solids``).
    """

    def __init__(self, *args, **context):
        extra = {
            k: context.pop(k, None)
            for k in (
                "field",
                "value",
                "alternatives",
                "paths",
                "share",
                "heat_to_solids",
                "short",
            )
        }
        quantities = context.pop("quantities", ())
        super().__init__(*args, **context)
        self.__dict__.update(extra)
        self.quantities = quantities


@dataclass
class _Group:
    """The raw warnings of one closure: quantity -> [smallest, largest, low, high], and where
    (quantity -> boolean mask over the values checked, None for one value)."""

    closure: str
    source: str
    quantities: dict
    masks: dict


def _accepted(field: str) -> tuple[str, ...]:
    from rotarykiln.kiln.inputs import closures as model

    return {
        "covered_wall": model.COVERED_WALL,
        "gas_wall": model.GAS_WALL,
        "gas_bed": model.GAS_BED,
        "gas_emissivity": (*model.GAS_EMISSIVITY, "a number in [0, 1)"),
    }[field]


def _number(v: float) -> str:
    """A value to 4 significant figures, no exponent below 1e6."""
    if v != 0 and (abs(v) >= 1e6 or abs(v) < 1e-3):
        return f"{v:.3g}"
    return f"{v:.4g}"


def _share(p: float) -> str:
    return f"{p:.0f}" if p >= 10 else f"{p:.2g}"


def _power(w: float) -> str:
    return f"{w / 1e3:.3g} kW" if abs(w) >= 1e3 else f"{w:.3g} W"


def heat_share(solution, paths: Iterable[str], cells=None) -> tuple[float, float, float, float]:
    """The part of the heat to the solids that passes through ``paths`` (see the module).

    Parameters
    ----------
    solution : KilnSolution
    paths : iterable of str
        Keys of :data:`PATHS`.
    cells : array of bool, optional
        The cells counted (default: all).

    Returns
    -------
    (flow, share, total, net)
        ``flow``: the paths' heat in those cells (W, signed); ``share``: their part of the heat
        to the solids, % (0-100); ``total``: the heat to the solids counted both ways (W, the
        paths into the bed by magnitude, cell by cell); ``net``: the net heat the bed takes
        from gas and wall (W).

    Examples
    --------
    >>> from types import SimpleNamespace
    >>> sol = SimpleNamespace(z_nodes=np.array([0.0, 1.0, 2.0]), fluxes={
    ...     "q_gas_bed_conv": np.array([300.0, 100.0]), "q_covered_wall_bed": np.array([100.0, 0.0]),
    ...     "q_rad_to_bed": np.array([0.0, 0.0]), "q_gas_wall_conv": np.array([50.0, 0.0]),
    ...     "q_rad_to_wall": np.array([150.0, 0.0])})
    >>> heat_share(sol, ["q_covered_wall_bed"])  # 100 W of the 500 W into the bed
    (100.0, 20.0, 500.0, 500.0)
    >>> heat_share(sol, ["q_gas_wall_conv"])  # a quarter of the wall's gains, passed on
    (50.0, 5.0, 500.0, 500.0)
    """
    f = solution.fluxes
    dz = np.diff(np.asarray(solution.z_nodes, dtype=float))
    n = len(dz)

    def q(key):
        return np.asarray(f.get(key, 0.0), dtype=float) * np.ones(n)

    mask = np.ones(n, dtype=bool) if cells is None else np.asarray(cells, dtype=bool)
    bed_paths = [q(k) for k, (_, side) in PATHS.items() if side == "bed"]
    total = float(sum(np.abs(v) for v in bed_paths) @ dz)
    net = float(sum(bed_paths) @ dz)
    gains = sum(np.maximum(q(k), 0.0) for k in _WALL_GAINS)
    passed = np.divide(
        np.abs(q("q_covered_wall_bed")), gains, out=np.zeros(n), where=gains > 0
    )  # W to the bed per W gained by the wall
    part = np.zeros(n)
    flow = 0.0
    for key in paths:
        v = q(key)
        flow += float((v * mask) @ dz)
        part += np.abs(v) if PATHS[key][1] == "bed" else np.maximum(v, 0.0) * passed
    share = 100.0 * float((part * mask) @ dz) / total if total > 0 else 0.0
    return flow, min(share, 100.0), total, net


def _groups(caught) -> tuple[list, list]:
    """The recorded warnings split: closure groups (in order) and the others (once each)."""
    groups: dict[str, _Group] = {}
    others: dict[str, object] = {}
    for w in caught:
        m = w.message
        key = getattr(m, "closure", None)
        if isinstance(m, ClosureWarning) or key not in CLOSURES:
            others.setdefault(str(m), w)
            continue
        g = groups.setdefault(key, _Group(key, m.source, {}, {}))
        lo, hi = m.outside
        mask = getattr(m, "mask", None)
        old_mask = g.masks.get(m.quantity, False)
        if mask is None or old_mask is None or np.shape(old_mask) not in ((), np.shape(mask)):
            g.masks[m.quantity] = None  # one value (the same in every cell), or shapes differ
        else:
            g.masks[m.quantity] = np.asarray(mask, dtype=bool) | old_mask
        if m.quantity in g.quantities:
            old = g.quantities[m.quantity]
            old[0], old[1] = min(old[0], lo), max(old[1], hi)
        else:
            g.quantities[m.quantity] = [lo, hi, m.low, m.high]
    return list(groups.values()), list(others.values())


def _describe(quantity: str, lo: float, hi: float, low: float, high: float, origins) -> str:
    d = QUANTITIES.get(quantity, {"words": quantity, "unit": "", "scale": 1.0})
    s, unit = d["scale"], d["unit"]
    u = f" {unit}" if unit else ""
    value = _number(lo * s) if lo == hi else f"{_number(lo * s)} to {_number(hi * s)}"
    if unit == "K":
        c = (lo - 273.15, hi - 273.15)
        shown = f"{_number(c[0])}" if lo == hi else f"{_number(c[0])} to {_number(c[1])}"
        u = f" K ({shown} degC)"
    origin = None if origins is None else origins.get(d.get("field"))
    if origin is not None:
        given = f" ({origin})"
    elif d.get("field") and origins is not None:
        given = f" ({d['field']})"
    else:
        given = ""
    return (
        f"{d['words']} = {value}{u}{given} is outside {_number(low * s)}-{_number(high * s)}"
        f"{' ' + unit if unit else ''}"
    )


def _cells_outside(solution, group: _Group):
    """Cells where some quantity of the group was outside its range (None: every cell)."""
    n = len(solution.z)
    out = np.zeros(n, dtype=bool)
    for mask in group.masks.values():
        if mask is None or np.size(mask) != n:
            return None  # one value for the kiln (d_p), or not checked per cell
        out |= np.ravel(mask)
    return out


def closure_warnings(caught, solution=None, origins=None) -> list:
    """The warnings a kiln run shows for the warnings ``caught`` during its solve.

    Parameters
    ----------
    caught : list of warnings.WarningMessage
        As recorded by ``warnings.catch_warnings(record=True)``.
    solution : KilnSolution, optional
        The converged solution (for the heat flows and their shares).
    origins : dict, optional
        Case-file field -> where a value the case does not give comes from
        (:func:`rotarykiln.kiln.from_case.default_origins`); with it, a value the case gives
        is named by its field.

    Returns
    -------
    list
        One :class:`ClosureWarning` per closure, in the order they first warned, then the
        other warnings (``warnings.WarningMessage``), once per text.

    Examples
    --------
    >>> import warnings
    >>> from rotarykiln.heat.contact import li_film_thickness
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     _ = li_film_thickness([2.5e-3, 2.5e-3, 2.5e-3, 2.5e-3])
    ...     _ = li_film_thickness(3e-3)
    >>> (w,) = closure_warnings(caught)
    >>> print(w)  # doctest: +NORMALIZE_WHITESPACE
    closures.covered_wall: li2005 (Li et al. (2005), penetration with a gas film) is used outside its range: particle size d_p = 2.5 to 3 mm is outside
    0.1575-1.038 mm (Li et al. (2005) chi fit). It feeds the covered wall -> bed contact.
    Alternatives: closures.covered_wall: tscheng1979, wachters_kramers1964 (wachters_kramers1964
    is the same penetration model without the gas film; tscheng1979 is an empirical fit without
    particle size).
    """
    groups, others = _groups(caught)
    out: list = []
    for g in groups:
        entry = CLOSURES[g.closure]
        field, value = g.closure.split(".", 1)
        alternatives = tuple(a for a in _accepted(field) if a != value)
        what = "; ".join(_describe(q, *v, origins) for q, v in g.quantities.items())
        feeds = " and ".join(PATHS[p][0] for p in entry["feeds"])
        text = (
            f"closures.{field}: {value} ({entry['name']}) is used outside its range: {what} "
            f"({g.source}). It feeds {feeds}"
        )
        share = total = None
        if solution is not None and "q_covered_wall_bed" in solution.fluxes:
            cells = _cells_outside(solution, g)
            flow, share, total, net = heat_share(solution, entry["feeds"], cells)
            n = len(solution.z)
            where = (
                ""
                if cells is None or cells.all()
                else f" in the {int(cells.sum())} of {n} cells outside the range"
            )
            through = (
                ", through the wall" if all(PATHS[p][1] == "wall" for p in entry["feeds"]) else ""
            )
            text += (
                f": {_power(flow)} net{where}{through}, {_share(share)} % of the heat to the "
                f"solids counted both ways (the bed exchanges {_power(total)} with gas and wall, "
                f"{_power(net)} net)"
            )
        names = ", ".join(q.split(" [")[0] for q in g.quantities)
        short = f"closures.{field}: {value} outside its range ({names})"
        if share is not None:
            short += f", {_share(share)} % of the heat to the solids"
        text += f". Alternatives: closures.{field}: {', '.join(alternatives)}"
        text += f" ({entry['advice']})." if entry["advice"] else "."
        out.append(
            ClosureWarning(
                text,
                quantity="; ".join(g.quantities),
                outside=None,
                source=g.source,
                closure=g.closure,
                field=f"closures.{field}",
                value=value,
                alternatives=alternatives,
                paths=tuple(entry["feeds"]),
                share=share,
                heat_to_solids=total,
                short=short,
                quantities=tuple((q, *v) for q, v in g.quantities.items()),
            )
        )
    return out + others


def emit(caught, solution=None, origins=None) -> list:
    """Warn with :func:`closure_warnings` of ``caught``; returns what was warned.

    A :class:`ClosureWarning` is issued as a warning; another warning is issued again as it was
    (its category, file and line), once per text.
    """
    shown = closure_warnings(caught, solution, origins)
    for w in shown:
        if isinstance(w, ClosureWarning):
            warnings.warn(w, stacklevel=3)
        else:
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    return shown
