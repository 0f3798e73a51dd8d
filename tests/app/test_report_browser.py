"""The reports of ``rotarykiln demo`` and ``rotarykiln run barr_T4 --report`` opened in headless
Chromium from disk (offline), as a reader sees them: every section is there once and shown, every
figure renders, the version and case hash are the package's, and the measured-vs-computed table
gives the residual at every measured point."""

from __future__ import annotations

import json
import re

import pytest

from rotarykiln import __version__
from rotarykiln.case import load_case
from rotarykiln.case_io import case_hash
from rotarykiln.cases import builtin_case_path
from rotarykiln.cli import main

SECTIONS = {
    "case": "Case",
    "warnings": "Warnings",
    "results": "Results",
    "measured": "Measured vs computed",
    "energy": "Energy balance",
    "regime": "Regime",
    "convergence": "Balances and convergence",
    "files": "Files",
}
"""Section id -> the start of its heading: the sections a run of the demo's kiln has (others,
such as the residence time, are checked when the header links to them)."""
HEADINGS = {"residence": "Residence time", "burner": "Burner", "other": "Other results"}


@pytest.fixture(scope="module")
def demo_report(tmp_path_factory):
    out = tmp_path_factory.mktemp("demo")
    assert main(["demo", "--out", str(out)]) == 0
    return out / "report.html"


def test_demo_report_shows_every_section(browser, demo_report, screenshot):
    from selenium.webdriver.support.ui import WebDriverWait

    browser.get(demo_report.as_uri())
    WebDriverWait(browser, 20).until(
        lambda d: d.execute_script("return document.readyState") == "complete"
    )
    find = browser.find_elements

    # the header: case name, version, hash of the validated case
    case = load_case(builtin_case_path("tscheng_A16"))
    assert browser.find_element("tag name", "h1").text == case.name
    assert browser.find_element("id", "version").text == __version__
    assert browser.find_element("id", "case-hash").text == case_hash(case)

    # every section: present, shown, with its heading, and reached from the header's links
    links = {a.get_attribute("href").rsplit("#", 1)[-1] for a in find("css selector", "nav a")}
    assert set(SECTIONS) <= links
    for ident in links:
        section = browser.find_element("id", ident)
        assert section.is_displayed(), ident
        heading = section.find_element("tag name", "h2").text
        assert heading.startswith({**HEADINGS, **SECTIONS}.get(ident, "")), (ident, heading)
        assert section.text.strip(), ident

    # the case with its units
    case_text = browser.find_element("css selector", "#case pre").text
    assert "speed: 1.5 rpm" in case_text and "length: 2.44 m" in case_text

    # each summary value once: regime, outlet temperatures, energy balance, convergence
    keys = [
        k for e in find("css selector", "[data-keys]") for k in e.get_attribute("data-keys").split()
    ]
    assert len(keys) == len(set(keys)), sorted(k for k in set(keys) if keys.count(k) > 1)
    for end in (
        "regime",
        "froude",
        "bed_outlet_temperature_K",
        "gas_outlet_temperature_K",
        "energy_balance_closure",
        "shell_loss_W",
        "newton_iterations",
        "residual",
    ):
        assert any(k == end or k.endswith("_" + end) for k in keys), (end, sorted(keys))
    _no_section_twice(browser)

    # the energy balance sheet, in and out
    energy = browser.find_element("id", "energy")
    assert {h.text for h in energy.find_elements("tag name", "h3")} >= {"In", "Out"}
    assert "closure" in energy.text.lower()

    # the figures, wherever the report shows them: regime map, cross-section and profiles, each
    # drawn from data embedded in the file (offline)
    figures = find("css selector", "figure[data-file]")
    files = [f.get_attribute("data-file") for f in figures]
    assert "regime_map.png" in files and "cross_section.png" in files, files
    assert any(name.endswith("profiles.png") or "profile" in name for name in files), files
    for figure in figures:
        drawn = browser.execute_script(
            "const e = arguments[0].querySelector('img, svg');"
            "if (!e) return 0;"
            "return e.tagName.toLowerCase() === 'img' ? e.naturalWidth : e.getBBox().width;",
            figure,
        )
        assert drawn > 0, figure.get_attribute("data-file")
        src = browser.execute_script(
            "const i = arguments[0].querySelector('img'); return i ? i.src : 'svg';", figure
        )
        assert src == "svg" or src.startswith("data:"), src[:60]  # embedded, not a link

    # the files written beside it
    listed = browser.find_element("id", "files").text
    assert "summary.json" in listed and "report.html" in listed
    screenshot(browser, "report_demo.png")


def _no_section_twice(browser) -> list[str]:
    headings = [h.text for h in browser.find_elements("tag name", "h2")]
    assert headings and len(headings) == len(set(headings)), headings
    return headings


@pytest.fixture(scope="module")
def barr_report(tmp_path_factory):
    out = tmp_path_factory.mktemp("barr_T4")
    assert main(["run", "barr_T4", "--out", str(out), "--report"]) == 0
    return out / "report.html"


def test_barr_report_compares_measured_and_computed(browser, barr_report, screenshot):
    from selenium.webdriver.support.ui import WebDriverWait

    browser.get(barr_report.as_uri())
    WebDriverWait(browser, 20).until(
        lambda d: d.execute_script("return document.readyState") == "complete"
    )
    headings = _no_section_twice(browser)
    assert "Measured vs computed" in headings

    # a row per measured point, shown, residual = computed - measured to the 0.1 K shown
    m = load_case(builtin_case_path("barr_T4")).measurements
    expected = sum(len(getattr(m, f"z_{k}")) for k in ("bed", "gas", "gas_wall", "wall"))
    table = browser.find_element("id", "measured-points")
    assert table.is_displayed()
    rows = table.find_elements("css selector", "tbody tr")
    assert len(rows) == expected
    for row in rows:
        cells = [c.text for c in row.find_elements("tag name", "td")]
        measured, computed, residual = (float(c) for c in cells[2:5])
        assert residual == pytest.approx(computed - measured, abs=0.11), cells

    # the RMSE per quantity, in the summary's value to the 0.1 K shown
    summary = json.loads((barr_report.parent / "summary.json").read_text())
    rmse = browser.find_element("id", "measured-rmse")
    for row in rmse.find_elements("css selector", "tbody tr"):
        key = row.get_attribute("data-keys")
        shown = row.find_element("css selector", "td.value").text
        assert shown == f"{summary[key]:.1f} K", (key, shown)

    # engineering units where people read them; nothing fetched from the network
    energy = browser.find_element("id", "energy").text
    assert " kW" in energy and not re.search(r"\de[-+]\d+ k?W", energy)
    assert "λ = " in browser.find_element("id", "burner").text
    assert "°C" in browser.find_element("id", "results").text
    screenshot(browser, "report_barr_T4.png")
