"""The HTML report of a run: one offline file, each number once, in the units people read.

Fast unit tests of the formatting (kW, degC, numerical noise shown as 0, the air ratio), then
the reports of barr_T4 (measured points) and limestone_fired (a fill computed by the kiln model).
"""

import contextlib
import dataclasses
import io
import json
import math
import re
from html.parser import HTMLParser

import pytest
import yaml

from rotarykiln import __version__
from rotarykiln.case import load_case
from rotarykiln.case_io import case_hash
from rotarykiln.cases import builtin_case_path
from rotarykiln.cli import main
from rotarykiln.kiln.combustion.flame import fire
from rotarykiln.kiln.from_case import burner_from_case
from rotarykiln.report import (
    ZERO_C,
    air_ratio,
    denoise,
    format_duration,
    format_mass_flow,
    format_power,
    format_quantity,
    format_temperature,
    significant,
)
from rotarykiln.report_html import (
    CASE_ECHOES,
    ENERGY_RTOL,
    measured_vs_computed,
    render_html_report,
    split_unit,
    typed_case_yaml,
)

# --- formatting -----------------------------------------------------------------------------


def _number(text: str) -> float:
    return float(re.match(r"[-+0-9.e]+", text).group(0))


@pytest.mark.parametrize("watts", [119740.3, 70538.07, 1.234e6, 812.5, -4321.0])
def test_power_is_in_kW_or_MW_to_four_figures(watts):
    text = format_power(watts)
    unit = text.split()[-1]
    factor = {"W": 1.0, "kW": 1e3, "MW": 1e6}[unit]
    assert 1.0 <= abs(watts) / factor < 1000.0  # the unit that keeps the number readable
    assert _number(text) * factor == pytest.approx(watts, rel=5e-4)
    assert "e" not in text.split()[0]


@pytest.mark.parametrize("kelvin", [298.15, 1011.83, 1731.1])
def test_temperature_shows_degC_beside_K(kelvin):
    text = format_temperature(kelvin)
    k, c = re.match(r"([0-9.]+) K \(([-0-9.]+) °C\)", text).groups()
    assert float(k) == pytest.approx(kelvin, abs=0.05)
    assert float(c) == pytest.approx(kelvin - ZERO_C, abs=0.05)
    assert format_quantity(kelvin, "K") == text


@pytest.mark.parametrize("kg_s", [0.0172222, 0.079155, 12.5])
def test_mass_flow_per_hour(kg_s):
    text = format_mass_flow(kg_s)
    factor = {"kg/h": 1.0, "t/h": 1000.0}[text.split()[-1]]
    assert _number(text) * factor == pytest.approx(kg_s * 3600.0, rel=5e-4)
    assert (factor == 1000.0) == (kg_s * 3600.0 >= 1000.0)


def test_duration_in_minutes_or_hours():
    for seconds in (45.0, 7423.0, 36000.0):
        text = format_duration(seconds)
        factor = {"s": 1.0, "min": 60.0, "h": 3600.0}[text.split()[-1]]
        assert _number(text) * factor == pytest.approx(seconds, rel=5e-4)
    assert format_duration(7423.0).endswith("min")


def test_noise_below_the_tolerance_is_zero():
    total = 70538.0
    noise, term = 1.6374e-09, 14139.0
    assert denoise(noise, total, ENERGY_RTOL) == 0.0
    assert denoise(term, total, ENERGY_RTOL) == term
    assert denoise(-0.9 * ENERGY_RTOL * total, total, ENERGY_RTOL) == 0.0
    assert denoise(1.1 * ENERGY_RTOL * total, total, ENERGY_RTOL) != 0.0


@pytest.mark.parametrize("excess", [-0.072574, 0.39653, 2.2193])
def test_air_ratio_beside_excess_air(excess):
    lam, pct = re.match(r"λ = ([0-9.]+) \(([-+0-9.]+) % excess air\)", air_ratio(excess)).groups()
    assert float(lam) == pytest.approx(1.0 + excess, abs=0.005)
    assert float(pct) == pytest.approx(100.0 * excess, abs=0.05)


def test_significant_figures_and_no_noise_digits():
    for value in (70538.07, 0.072574, 1.6374e-09, 123.456, -2.0):
        text = significant(value, 4)
        assert float(text) == pytest.approx(value, rel=5e-4)
        digits = re.sub(r"e.*$", "", text).replace("-", "").replace(".", "").lstrip("0")
        assert len(digits.rstrip("0")) <= 4, text


@pytest.mark.parametrize(
    ("key", "expected"),
    [
        ("kiln_bed_outlet_temperature_K", ("kiln bed outlet temperature", "K")),
        ("feed_kg_h", ("feed", "kg/h")),
        ("speed_rpm", ("speed", "rpm")),
        ("regime", ("regime", "")),
        ("fill", ("fill", "")),
    ],
)
def test_split_unit(key, expected):
    assert split_unit(key) == expected


# --- the report of a run -----------------------------------------------------------------------


class _Report(HTMLParser):
    """Summary keys (``data-keys``) and shown values (of the first key of a row), h2 headings, figures, external links,
    warnings, the measured points and the text of each section."""

    def __init__(self):
        super().__init__()
        self.ids, self.figures, self.external, self.warnings = set(), [], [], []
        self.keys = []  # every summary key of every element, as often as it is shown
        self.values = {}  # summary key -> (shown text, exact SI value)
        self.h2, self.points, self.text = [], [], {}
        self.hash = ""
        self._row_keys, self._in, self._section = None, None, None
        self._warnings_list = False

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if "id" in a:
            self.ids.add(a["id"])
        if tag == "section":
            self._section = a.get("id")
            self.text[self._section] = ""
        for name in ("src", "href"):
            link = a.get(name) or ""
            if link and not link.startswith(("data:", "#")):
                self.external.append(link)
        if tag in ("script", "link", "iframe"):
            self.external.append(tag)
        if a.get("data-keys"):
            self.keys += a["data-keys"].split()
            self._row_keys = a["data-keys"].split()
        if tag == "td" and "value" in (a.get("class") or "") and self._row_keys:
            self.values[self._row_keys[0]] = ["", a["data-value"]]  # the value of the first
            self._in = "value"
        if tag == "tr" and "data-residual" in a:
            self.points.append({k[5:]: float(v) for k, v in a.items() if k.startswith("data-")})
        if tag == "figure":
            self.figures.append(a["data-file"])
        if tag == "img":
            assert a["src"].startswith("data:image/png;base64,") and len(a["src"]) > 1000
        if tag == "code" and a.get("id") == "case-hash":
            self._in = "hash"
        if tag == "h2":
            self._in = "h2"
            self.h2.append("")
        if tag == "ul" and a.get("class") == "warnings":
            self._warnings_list = True
        if tag == "li" and self._warnings_list:
            self._in = "li"

    def handle_endtag(self, tag):
        if tag in ("td", "code", "li", "h2"):
            self._in = None
        if tag == "ul":
            self._warnings_list = False
        if tag in ("tr", "pre", "p"):
            self._row_keys = None
        if tag == "section":
            self._section = None

    def handle_data(self, data):
        if self._section:
            self.text[self._section] += data
        if self._in == "value":
            self.values[self._row_keys[0]][0] += data
        elif self._in == "hash":
            self.hash += data
        elif self._in == "li":
            self.warnings.append(data)
        elif self._in == "h2":
            self.h2[-1] += data


def _run(out, case):
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        assert main(["run", case, "--out", str(out), "--report", "--json"]) == 0
    report = _Report()
    report.feed((out / "report.html").read_text(encoding="utf-8"))
    report.stderr = err.getvalue()
    return out, report, json.loads((out / "summary.json").read_text())


@pytest.fixture(scope="module")
def barr_t4(tmp_path_factory):
    return _run(tmp_path_factory.mktemp("barr_T4"), "barr_T4")


@pytest.fixture(scope="module")
def limestone(tmp_path_factory):
    return _run(tmp_path_factory.mktemp("limestone_fired"), "limestone_fired")


@pytest.mark.parametrize("which", ["barr_t4", "limestone"])
def test_every_number_of_the_summary_is_shown_once(which, request):
    _, report, summary = request.getfixturevalue(which)
    shown = [k for k in report.keys if k in summary]
    assert set(summary) <= set(shown), sorted(set(summary) - set(shown))
    twice = {k for k in shown if shown.count(k) > 1}
    assert not twice, twice
    assert len(report.h2) == len(set(report.h2)), report.h2  # no section twice
    assert "Summary" not in report.h2
    for key, (_, exact) in report.values.items():  # the value shown is the solver's
        if isinstance(summary.get(key), float) and exact:
            assert float(exact) == summary[key], key


def test_engineering_units_and_no_noise(barr_t4):
    _, report, summary = barr_t4
    key = "kiln_bed_outlet_temperature_K"
    shown, _ = report.values[key]
    assert shown == format_temperature(summary[key]) and "°C" in shown
    for key in ("kiln_energy_shell_loss_W", "kiln_energy_exhaust_loss_W"):
        shown, _ = report.values[key]
        assert shown.endswith(" kW") and _number(shown) * 1e3 == pytest.approx(
            summary[key], rel=5e-4
        )
    flow, _ = report.values["kiln_solids_outlet_flow_kg_s"]
    assert flow.endswith("kg/h")
    # the gas enters at 298.15 K: its sensible input is nil or round-off, shown as a nil term
    noise = summary["kiln_energy_sensible_input_gas_W"]
    assert 0 <= abs(noise) < ENERGY_RTOL * summary["kiln_energy_combustion_heat_W"]
    assert report.values.get("kiln_energy_sensible_input_gas_W") is None
    assert "gas and air entering" in report.text["energy"].split("Nil terms")[1]
    # no W-valued number in scientific notation anywhere in the energy balance
    assert not re.search(r"\de[-+]\d+ k?W", report.text["energy"])
    assert f"below {ENERGY_RTOL:g}" in report.text["energy"]


def test_air_ratio_beside_the_excess_air(barr_t4):
    _, report, summary = barr_t4
    shown, _ = report.values["kiln_burner_primary_excess_air"]
    assert shown == air_ratio(summary["kiln_burner_primary_excess_air"])
    assert "excess air" in shown and shown.startswith("λ = ")


def test_the_gap_between_LHV_and_combustion_heat_is_explained(barr_t4, tmp_path):
    """Barr T4's streams enter at 298.15 K and burn completely: the heat of combustion is the
    LHV input (within the round-off of the kiln's gas tables), and the sentence says so; with
    hot secondary air the products hold another heat than the reactants, and the sentence gives
    the gap: the heat of combustion at the inlet temperature, from Cantera."""
    import cantera as ct

    from rotarykiln.report_html import COMBUSTION_GAP_RTOL, _combustion_gap

    _, report, summary = barr_t4
    lhv = summary["kiln_energy_fuel_lhv_input_W"]
    gap = lhv - summary["kiln_energy_combustion_heat_W"]
    assert abs(gap) < COMBUSTION_GAP_RTOL * lhv
    assert "is the LHV input" in report.text["energy"]
    # hot air: Cantera's heat of combustion at the unburnt mixture's temperature
    case = load_case(builtin_case_path("barr_T4"))
    b = burner_from_case(case.burner, case.operation.counter_current)
    b = dataclasses.replace(b, secondary_air=dataclasses.replace(b.secondary_air, temperature=900))
    flame = fire(b, case.kiln.diameter, case.kiln.length)
    p = flame.products
    gas = ct.Solution("gri30.yaml")
    gas.TPX = 298.15, 101325.0, b.fuel
    fuel = ct.Quantity(gas, mass=b.fuel_flow, constant="HP")
    air = []
    for s in (b.primary_air, b.secondary_air):
        gas.TPX = s.temperature, 101325.0, s.composition
        air.append(ct.Quantity(gas, mass=s.flow, constant="HP"))
    mix = fuel + air[0] + air[1]
    assert mix.T == pytest.approx(p.inlet_temperature, abs=1e-6)  # Cantera stops within 1e-6 K
    mix.TP = p.inlet_temperature, 101325.0
    h_in = mix.enthalpy_mass * mix.mass  # W
    mix.TPX = mix.T, 101325.0, dict(p.composition)
    assert p.heat_release == pytest.approx(h_in - mix.enthalpy_mass * mix.mass, rel=1e-9)
    text = _combustion_gap({"lhv": flame.fuel_lhv, "combustion": p.heat_release}, {})
    gap = flame.fuel_lhv - p.heat_release
    assert abs(gap) > 1e-4 * flame.fuel_lhv and format_power(abs(gap)) in text


def test_measured_against_computed_at_every_point(barr_t4):
    _, report, summary = barr_t4
    case = load_case(builtin_case_path("barr_T4"))
    m = case.measurements
    n = sum(len(getattr(m, f"z_{k}")) for k in ("bed", "gas", "gas_wall", "wall"))
    assert len(report.points) == n
    for p in report.points:
        assert p["residual"] == pytest.approx(p["computed"] - p["measured"], abs=1e-9)
    # the RMSE of the residuals shown is the run's score of each quantity
    table = measured_vs_computed(case)
    for key, pts in table.items():
        rmse = math.sqrt(sum(p["residual_K"] ** 2 for p in pts) / len(pts))
        assert rmse == pytest.approx(summary[f"kiln_rmse_{key}_K"], rel=1e-9)
        assert report.values[f"kiln_rmse_{key}_K"][0] == f"{summary[f'kiln_rmse_{key}_K']:.1f} K"
    assert sorted(p["z"] for p in report.points) == sorted(
        z for k in ("bed", "gas", "gas_wall", "wall") for z in getattr(m, f"z_{k}")
    )


def test_inputs_as_typed_with_units(barr_t4, limestone):
    path = builtin_case_path("limestone_fired")
    raw = yaml.safe_load(path.read_text(encoding="utf-8"))
    text, typed = typed_case_yaml(load_case(path), "limestone_fired")
    assert typed
    assert f"slope: {raw['kiln']['slope']}" in text  # as typed, not converted to deg
    assert f"residence_time: {raw['bed']['residence_time']}" in text
    for key in CASE_ECHOES[1:]:
        assert key not in limestone[1].values  # an input: shown in the case only
    # lining conductivities carry their units (the file takes bare coefficients)
    barr_yaml = barr_t4[1].text["case"]
    assert re.search(r"k: \[[^\]]*\]  # W/\(m K\)", barr_yaml)
    # a case edited since it was loaded: the validated values, written back with units
    case = load_case(path).model_copy(update={"name": "edited"})
    text, typed = typed_case_yaml(case, "limestone_fired")
    assert not typed and "name: edited" in text


def test_every_kiln_report_has_the_same_figures(barr_t4, limestone):
    for out, report, _ in (barr_t4, limestone):
        assert {"cross_section.png", "regime_map.png", "kiln_profiles.png"} <= set(
            report.figures
        ), (out, report.figures)
        assert "energy" in report.text and "<svg" in (out / "report.html").read_text()
        assert report.external == []
    assert "kiln_rtd.png" in limestone[1].figures  # a reacting bed: its RTD
    # limestone: the fill is computed by the kiln model; the regime is drawn from it
    _, report, summary = limestone
    assert report.values["kiln_fill"][1] == repr(summary["kiln_fill"])
    assert "regime" in report.ids


def test_warnings_once_each_version_and_case_hash(barr_t4):
    out, report, summary = barr_t4
    assert any("Li et al. (2005)" in w for w in report.warnings)
    assert report.hash == case_hash(load_case(builtin_case_path("barr_T4")))
    html = (out / "report.html").read_text()
    assert f'"version">{__version__}<' in html
    shown = [line for line in report.stderr.splitlines() if line.startswith("warning:")]
    assert len(shown) == len(report.warnings) >= 1  # the CLI still shows what the report records
    assert not [p for p in out.iterdir() if p.name.startswith(".")]  # atomic: no temporary left
    case = load_case(builtin_case_path("barr_T4"))
    sections = {"case": {k: v for k, v in summary.items() if not k.startswith("kiln_")}}
    twice = render_html_report(case, sections=sections, warnings=["a", "b", "a"])
    parsed = _Report()
    parsed.feed(twice)
    assert parsed.warnings == ["a", "b"]


def test_a_figure_left_by_an_earlier_run_is_not_embedded(tmp_path):
    out = tmp_path / "rtd"
    assert main(["run", "rtd/bongo_njeng_sand_rl", "--out", str(out)]) == 0
    assert not (out / "report.html").exists()  # only with --report
    (out / "stale.png").write_bytes((out / "rtd_prediction.png").read_bytes())
    assert main(["run", "rtd/bongo_njeng_sand_rl", "--out", str(out), "--report"]) == 0
    report = _Report()
    report.feed((out / "report.html").read_text(encoding="utf-8"))
    assert report.figures == ["rtd_prediction.png"]  # written again by this run; stale.png not
    summary = json.loads((out / "summary.json").read_text())
    assert set(summary) <= set(report.keys)  # a run without a kiln: every value too
