"""Docstring shape of the public models (DESIGN.md, "What done means for a model").

Every public function of the physics modules that is a model or a correlation has: a Parameters
section naming the unit of each signature argument, a Returns section with a unit, an Examples
doctest and a References section (or a Source/Reference line). Helpers (loaders, plots, runners,
result classes) need only a one-line summary. The unit test is a heuristic: a unit is the text
after the last comma of the type line (``length : float, m``), a bracketed or trailing unit in
the description (``Time [s].``, ``Temperature, K.``), any bracketed text (``[rad/s]``,
``in [0, 1]``) or a non-physical type (str, bool, a result class...). The kiln package is walked
with its sub-packages; its solver machinery and result bookkeeping are helpers
(:data:`KILN_HELPER`). Before the audit of November 2026, 130 of the 167 models failed.
"""

import importlib
import inspect
import pkgutil
import re

import pytest

TOP = ["rotarykiln.geometry", "rotarykiln.regimes", "rotarykiln.units"]
PKGS = ["transport", "rtd", "transverse", "chemistry", "heat", "materials", "studies", "kiln"]

NONPHYS = re.compile(
    r"\b(\w*(Result|Profile|Prediction|Table|Stats|Section|Spec|Layer|Sizes|Geometry|Chart|Gas|"
    r"Solid|Material|Parameters|Options|Signal|Rates|State|Thermochemistry|Residual|Transient|Solution|Grid|Mixture|"
    r"Burner|Flame|Kiln)|str|bool|int|"
    r"callable|Callable|dict|Mapping|mapping|Path|path|None|Case|case|Axes|ax|Figure|object|type|"
    r"rng|seed|Species|Reaction|Mechanism|Weir|DataFrame|frame|Executor|Client)\b"
)
UNIT_IN_DESC = re.compile(
    r"(^|,|\[|\(|\bin)\s*(-|K|m|s|kg|J|W|Pa|bar|atm|rad|deg|mol|rpm|1/s|m2|m3|kg/s|J/kg|kg/m|"
    r"1/kg|m2/s|s2|W/m2|m2/m|J/mol|W/m|Pa s|kg/m3|m/s|m3/s|kg/\(s m\)|J/\(kg K\)|W/\(m K\)|"
    r"W/\(m2 K\)|1/K|%)(?=[\s\].,;)]|$)"
)
UNIT_TAIL = re.compile(r",\s*(\[?[-\w/^.*()%0-9 ]+\]?|-)\s*$")
OPTIONS = {"tol", "rtol", "atol", "max_iter", "maxiter", "check", "n_points", "n", "method", "ax"}
HELPER = re.compile(
    r"^(load_|plot|read_|write_|run|get_|set_|with_|parse_|builtin|as_|check_|register|animate|"
    r"raster|parity|format_|failing|grid$|one_at_a_time|si_value|retort_|solid_names|"
    r"lining_material_names|parquet_|.*_table$|to_si$|default_|rtd_arrays|element_|reaction_from|"
    r"ahmad_chapter5|chapter5|kiln_model|transport_model|warn_if|get_model|dirac_inlet|"
    r"step_inlet|pulse_inlet|predict_|peclet_from_case|fit_|analyse_tracer|replicate_|solve_bed|"
    r"design_chart|scott1986_|first_order|ortiz_isothermal|kiln_segregated|onset_window|"
    r"as_profile)"
)
#: The kiln's solver machinery and result bookkeeping (Newton driver, unknowns, reports,
#: warnings, table columns): numerics and post-processing, not models.
KILN_HELPER = re.compile(
    r"^(newton_with_continuation|newton_sequenced|ramp|scaled|locator|equation_names|"
    r"initial_temperatures|interpolate_unknowns|front_cells|inlet_front|relax_local|"
    r"profile_fields|colour_batch|cell_report|"
    r"closure_warnings|emit|heat_share|heat_flow_columns|zigzag|kiln_at|output_times_bound|"
    r"finish_solution|newton_options|same_structure|structure_groups|batch_size_for|batch_residuals|"
    r".*_from_case)$"
)


def _modules():
    for name in TOP:
        yield importlib.import_module(name)
    for pkg_name in PKGS:
        pkg = importlib.import_module(f"rotarykiln.{pkg_name}")
        yield pkg
        for info in pkgutil.walk_packages(pkg.__path__, prefix=f"{pkg.__name__}."):
            if not any(part.startswith("_") for part in info.name.split(".")):
                yield importlib.import_module(info.name)


def _public():
    seen = {}
    for mod in _modules():
        names = getattr(mod, "__all__", None)
        if names is None:
            names = [n for n in vars(mod) if not n.startswith("_")]
        for n in names:
            obj = getattr(mod, n, None)
            if (inspect.isfunction(obj) or inspect.isclass(obj)) and obj.__module__ == mod.__name__:
                seen[f"{mod.__name__}.{n}"] = obj
    return seen


PUBLIC = _public()


def _is_model(key, obj):
    name = key.rsplit(".", 1)[1]
    if inspect.isclass(obj) or ".studies." in key:
        return name in ("CrossSection", "Weir")
    if ".kiln." in key and KILN_HELPER.match(name):
        return False
    return not HELPER.match(name)


MODELS = {k: v for k, v in PUBLIC.items() if _is_model(k, v)}


def _section(doc, title):
    m = re.search(
        rf"^\s*{title}\s*\n\s*-{{3,}}\s*\n(.*?)(?=^\s*\w[\w ]*\n\s*-{{3,}}\s*$|\Z)",
        doc,
        re.S | re.M,
    )
    return m.group(1) if m else None


def _entries(sec):
    lines = sec.splitlines()
    ind = min((len(x) - len(x.lstrip()) for x in lines if x.strip()), default=0)
    out = []
    for i, line in enumerate(lines):
        if line.strip() and len(line) - len(line.lstrip()) == ind:
            desc = []
            for nxt in lines[i + 1 :]:
                if nxt.strip() and len(nxt) - len(nxt.lstrip()) <= ind:
                    break
                desc.append(nxt.strip())
            out.append((line.strip(), " ".join(desc)))
    return out


def _has_unit(head, desc):
    typ = head.split(" : ", 1)[1] if " : " in head else head
    return bool(
        ("," in typ and UNIT_TAIL.search(typ))
        or typ.strip().startswith("{")
        or UNIT_IN_DESC.search(desc)
        or re.search(r"\[[^\]]+\]", desc)
        or re.search(r"dimensionless|fraction|\bratio\b|number\b", typ + " " + desc, re.I)
        or NONPHYS.search(typ)
    )


def _gaps(obj):
    doc = inspect.getdoc(obj) or ""
    gaps = []
    params = [
        p.name
        for p in inspect.signature(obj).parameters.values()
        if p.name not in ("self", "cls")
        and p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)
        and not (p.kind == p.KEYWORD_ONLY and (isinstance(p.default, bool) or p.name in OPTIONS))
    ]
    if params:
        sec = _section(doc, "Parameters")
        if sec is None and inspect.isclass(obj):
            sec = _section(doc, "Attributes")
        named = {}
        for head, desc in _entries(sec or ""):
            for nm in head.split(" : ")[0].split(","):
                named[nm.strip().lstrip("*")] = (head, desc)
        missing = [p for p in params if p not in named or not _has_unit(*named[p])]
        if missing:
            gaps.append(f"Parameters with units ({', '.join(missing)})")
    if inspect.isfunction(obj):
        sec = _section(doc, "Returns")
        heads = _entries(sec or "")
        if not any(_has_unit(h if " : " in h else "x : " + h, d) for h, d in heads):
            gaps.append("Returns with a unit")
    if ">>>" not in doc:
        gaps.append("Examples doctest")
    if _section(doc, "References") is None and not re.search(r"\b(Source|Reference)s?\b", doc):
        gaps.append("References")
    return gaps


def test_the_scope_is_found():
    assert len(PUBLIC) > 250 and len(MODELS) > 150


@pytest.mark.parametrize("key", sorted(MODELS))
def test_model_docstring_has_the_design_shape(key):
    gaps = _gaps(MODELS[key])
    assert not gaps, f"{key} lacks: {'; '.join(gaps)} (see DESIGN.md docstring shape)"


@pytest.mark.parametrize("key", sorted(PUBLIC))
def test_public_name_has_a_summary_line(key):
    doc = inspect.getdoc(PUBLIC[key]) or ""
    assert doc.strip().splitlines()[0].strip(), f"{key} has no one-line summary"
