"""The report of ``rotarykiln demo`` opened in headless Chromium from disk (offline): every section
is there and shown, every figure renders, the version and case hash are the package's."""

from __future__ import annotations

import pytest

from rotarykiln import __version__
from rotarykiln.case import load_case
from rotarykiln.case_io import case_hash
from rotarykiln.cases import builtin_case_path
from rotarykiln.cli import main

SECTIONS = {
    "case": "Case",
    "warnings": "Warnings",
    "regime": "Regime",
    "energy": "Energy balance",
    "convergence": "Balances and convergence",
    "summary": "Summary",
    "figures": "Figures",
    "files": "Files",
}
"""Section id -> the start of its heading: the sections a run of the demo's kiln has (others,
such as the residence time, are checked when the header links to them)."""
HEADINGS = {"residence": "Residence time"}


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

    # the summary: regime, outlet temperatures, energy balance, convergence
    keys = {row.get_attribute("data-key") for row in find("css selector", "#summary tr[data-key]")}
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
