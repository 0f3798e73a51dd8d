"""The HTML report of a run (issue 14, item 1): one offline file with every section."""

import contextlib
import io
import json
from html.parser import HTMLParser

import pytest

from rotarykiln import __version__
from rotarykiln.case import load_case
from rotarykiln.case_io import case_hash
from rotarykiln.cases import builtin_case_path
from rotarykiln.cli import main
from rotarykiln.report_html import split_unit


class _Report(HTMLParser):
    """Section ids, summary cells (shown text and exact value), figures, external links."""

    def __init__(self):
        super().__init__()
        self.ids, self.figures, self.external, self.warnings = set(), [], [], []
        self.cells = {}  # data-key -> [shown text, data-value]
        self.hash = ""
        self._row = self._in = None
        self._warnings_list = False

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if "id" in a:
            self.ids.add(a["id"])
        for name in ("src", "href"):
            link = a.get(name) or ""
            if link and not link.startswith(("data:", "#")):
                self.external.append(link)
        if tag in ("script", "link", "iframe"):
            self.external.append(tag)
        if tag == "tr" and "data-key" in a:
            self._row = a["data-key"]
        if tag == "td" and a.get("class") == "value" and self._row:
            self.cells[self._row] = ["", a["data-value"]]
            self._in = "value"
        if tag == "figure":
            self.figures.append(a["data-file"])
        if tag == "img":
            assert a["src"].startswith("data:image/png;base64,") and len(a["src"]) > 1000
        if tag == "code" and a.get("id") == "case-hash":
            self._in = "hash"
        if tag == "ul" and a.get("class") == "warnings":
            self._warnings_list = True
        if tag == "li" and self._warnings_list:
            self._in = "li"

    def handle_endtag(self, tag):
        if tag in ("td", "code", "li"):
            self._in = None
        if tag == "ul":
            self._warnings_list = False
        if tag == "tr":
            self._row = None

    def handle_data(self, data):
        if self._in == "value":
            self.cells[self._row][0] += data
        elif self._in == "hash":
            self.hash += data
        elif self._in == "li":
            self.warnings.append(data)


@pytest.fixture(scope="module")
def barr_t4(tmp_path_factory):
    out = tmp_path_factory.mktemp("barr_T4")
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        assert main(["run", "barr_T4", "--out", str(out), "--report", "--json"]) == 0
    report = _Report()
    report.feed((out / "report.html").read_text(encoding="utf-8"))
    report.stderr = err.getvalue()
    return out, report, json.loads((out / "summary.json").read_text())


def test_report_has_every_section(barr_t4):
    _, report, _ = barr_t4
    assert {"case", "warnings", "summary", "figures", "files", "version", "case-hash"} <= report.ids
    assert {"summary-case", "summary-kiln"} <= report.ids
    # a kiln run: regime and cross-section, the energy sheet, balances and convergence
    assert {"regime", "energy", "energy-in", "energy-out", "convergence"} <= report.ids


def test_energy_sheet_adds_up(barr_t4):
    out, _, summary = barr_t4
    from rotarykiln.report_html import _energy_sheet

    sheet = _energy_sheet(summary)
    total_in = float(sheet["total_in"]["exact"])
    total_out = float(sheet["total_out"]["exact"])
    closure = float(sheet["closure"]["exact"])
    assert total_in - total_out == pytest.approx(closure, abs=1e-6 * total_in)
    assert abs(closure) < 1e-6 * total_in
    names = [r["name"] for r in sheet["inputs"]]
    assert "heat of combustion" in names  # a fired kiln
    assert total_in == pytest.approx(
        summary["kiln_energy_combustion_heat_W"]
        + summary["kiln_energy_sensible_input_gas_W"]
        + summary["kiln_energy_sensible_input_solids_W"]
    )


def test_outlet_temperature_shown_is_the_solvers(barr_t4):
    _, report, summary = barr_t4
    key = "kiln_bed_outlet_temperature_K"
    shown, exact = report.cells[key]
    assert float(exact) == summary[key]
    assert shown == f"{summary[key]:.5g}"
    assert 900 < float(shown) < 1100


def test_every_summary_value_is_in_the_report(barr_t4):
    _, report, summary = barr_t4
    assert set(summary) <= set(report.cells)
    for key, value in summary.items():
        if isinstance(value, float):
            assert float(report.cells[key][1]) == value, key


def test_figures_are_embedded_and_nothing_is_fetched(barr_t4):
    out, report, _ = barr_t4
    assert sorted(report.figures) == ["cross_section.png", "kiln_profiles.png", "regime_map.png"]
    assert report.external == []


def test_warnings_version_and_case_hash(barr_t4, capsys):
    _, report, _ = barr_t4
    assert any("Li et al. (2005)" in w for w in report.warnings)
    assert report.hash == case_hash(load_case(builtin_case_path("barr_T4")))
    html = (barr_t4[0] / "report.html").read_text()
    assert f"rotarykiln {__version__}" in html or f'"version">{__version__}<' in html


def test_the_cli_still_shows_the_warnings_the_report_records(barr_t4):
    out, report, _ = barr_t4
    shown = [line for line in report.stderr.splitlines() if line.startswith("warning:")]
    assert len(shown) == len(report.warnings) >= 1
    assert all(line.removeprefix("warning: ") in report.warnings for line in shown)
    assert not [p for p in out.iterdir() if p.name.startswith(".")]  # atomic: no temporary left


def test_a_figure_left_by_an_earlier_run_is_not_embedded(tmp_path):
    out = tmp_path / "rtd"
    assert main(["run", "rtd/bongo_njeng_sand_rl", "--out", str(out)]) == 0
    assert not (out / "report.html").exists()  # only with --report
    (out / "stale.png").write_bytes((out / "rtd_prediction.png").read_bytes())
    assert main(["run", "rtd/bongo_njeng_sand_rl", "--out", str(out), "--report"]) == 0
    report = _Report()
    report.feed((out / "report.html").read_text(encoding="utf-8"))
    assert report.figures == ["rtd_prediction.png"]  # written again by this run; stale.png not


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


def test_demo_writes_the_report(tmp_path):
    out = tmp_path / "demo"
    with contextlib.redirect_stdout(io.StringIO()) as printed:
        assert main(["demo", "--out", str(out)]) == 0
    assert "report.html" in printed.getvalue()
    report = _Report()
    report.feed((out / "report.html").read_text(encoding="utf-8"))
    assert {"case", "warnings", "summary", "figures", "files", "summary-kiln"} <= report.ids
    assert "kiln_profiles.png" in report.figures and report.external == []
    summary = json.loads((out / "summary.json").read_text())
    key = "kiln_bed_outlet_temperature_K"
    assert report.cells[key][0] == f"{summary[key]:.5g}"
