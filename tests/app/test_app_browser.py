"""The app end to end in headless Chromium: load, edit an input, run, compare the displayed
outlet temperature with the solver's; bad input shown next to its field, results kept; an RTD,
a transport and a transverse case show their results; the page holds at 420 px."""

from __future__ import annotations

import re
import urllib.request

import pytest
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.errors import InputError

CASE = "tscheng_A16"
WAIT = 45  # s; a run of the case takes about 4 s


def _raw() -> dict:
    return yaml.safe_load(builtin_case_path(CASE).read_text(encoding="utf-8"))


def _solver_outlet(raw: dict) -> float:
    """The bed outlet temperature (K) of the kiln model, straight from the solver."""
    from rotarykiln.kiln.from_case import kiln_from_case
    from rotarykiln.kiln.steady.solve import solve_kiln

    kiln, cells = kiln_from_case(parse_case(raw))
    return solve_kiln(kiln, cells).bed_outlet_temperature


def _by(driver, css):
    from selenium.webdriver.common.by import By

    return driver.find_element(By.CSS_SELECTOR, css)


def _wait(driver, condition, timeout=WAIT):
    from selenium.webdriver.support.ui import WebDriverWait

    return WebDriverWait(driver, timeout, poll_frequency=0.1).until(condition)


def _click(driver, find) -> None:
    """Click the element ``find(driver)`` returns once it is there and takes the click: an
    overlay still settling (the case list's search box, a closing dropdown) can intercept a
    click, which is then tried again until WAIT runs out."""
    from selenium.common.exceptions import (
        ElementClickInterceptedException,
        NoSuchElementException,
        StaleElementReferenceException,
    )

    def attempt(d) -> bool:
        try:
            element = find(d)
            if element is None:
                return False
            d.execute_script("arguments[0].scrollIntoView({block: 'center'})", element)
            element.click()
        except (
            ElementClickInterceptedException,
            NoSuchElementException,
            StaleElementReferenceException,
        ):
            return False
        return True

    _wait(driver, attempt)


def _field(driver, path: str):
    return _wait(
        driver,
        lambda d: d.find_element("css selector", f'input[id*=\'"path":"{path}"\']'),
    )


def _field_error(driver, path: str) -> str:
    return driver.find_element("css selector", f'div[id*=\'"path":"{path}"\'].error').text


def _type(driver, path: str, text: str) -> None:
    """Replace a field's text and leave it (the app reads a field when it loses focus).

    The keys are sent again while the field shows something else: on a loaded machine the
    page can still be settling (a field re-rendered, focus taken) when the first keys arrive.
    """
    from selenium.common.exceptions import StaleElementReferenceException, TimeoutException
    from selenium.webdriver.common.keys import Keys

    def shown(d) -> str | None:
        try:
            return _field(d, path).get_attribute("value")
        except StaleElementReferenceException:
            return None

    def attempt(d) -> bool:
        if shown(d) == text:
            return True
        try:
            field = _field(d, path)
            field.send_keys(Keys.CONTROL, "a")
            field.send_keys(Keys.DELETE)
            field.send_keys(text, Keys.TAB)
        except StaleElementReferenceException:
            return False
        try:  # give the page a moment before typing again
            return bool(_wait(d, lambda d2: shown(d2) == text, timeout=3))
        except TimeoutException:
            return False

    try:
        _wait(driver, attempt)
    except TimeoutException as exc:
        raise AssertionError(f"{path} shows {shown(driver)!r} after typing {text!r}") from exc


def _status(driver) -> str:
    return _by(driver, "#run-status").text


def _run(driver, expect_ok: bool = True) -> str:
    """Press Run and wait for its status line; return it."""
    before = _status(driver)
    _click(driver, lambda d: _by(d, "#run-button"))
    _wait(driver, lambda d: _status(d) and _status(d) != before)
    status = _status(driver)
    if expect_ok:
        assert "finished" in status, status + " / " + _by(driver, "#run-error").text
        _wait(driver, lambda d: d.find_elements("id", "headline"))
    return status


def _open(driver, server) -> None:
    driver.get(server.url)
    _field(driver, "operation.speed")
    _wait(driver, lambda d: _field(d, "operation.speed").get_attribute("value"))


def test_displayed_outlet_temperature_is_the_solvers(browser, app_server, screenshot, downloads):
    _open(browser, app_server)
    assert _by(browser, "#case-info").text == f"Loaded: {CASE} (built-in)"
    assert _field(browser, "operation.speed").get_attribute("value") == "1.5 rpm"
    _type(browser, "operation.speed", "2.5 rpm")
    _run(browser)

    raw = _raw()
    raw["operation"]["speed"] = "2.5 rpm"
    expected = _solver_outlet(raw)
    assert abs(expected - _solver_outlet(_raw())) > 0.5  # the edit changes the answer

    shown = _wait(browser, lambda d: d.find_element("id", "outlet-temperature"))
    kelvin = float(shown.get_attribute("data-kelvin"))
    assert kelvin == pytest.approx(expected, rel=1e-9, abs=1e-9)
    text = shown.text
    assert text.startswith(f"{expected:.1f} K"), (text, expected)
    displayed = float(re.match(r"([0-9.]+) K", text).group(1))
    assert abs(displayed - expected) <= 0.05 + 1e-9

    # the profiles are drawn (Plotly loads its script after the page): bed, gas, wall, measured
    traces = _wait(
        browser,
        lambda d: d.find_elements("css selector", "[id^=temperature-graph] .scatterlayer .trace"),
    )
    assert len(traces) >= 4
    legend = _by(browser, "[id^=temperature-graph] .legend").text
    assert "bed" in legend and "gas" in legend and "measured" in legend, legend
    screenshot(browser, "app_after_run.png")

    # the downloads: the case as run (with units), the tables, the report
    links = {
        a.text: a.get_attribute("href")
        for a in browser.find_elements("css selector", "#downloads a")
    }
    assert {"case.yaml", "report.html", "summary.json"} <= set(links), links
    assert any(name.endswith("_profiles.csv") for name in links), links
    with urllib.request.urlopen(links["case.yaml"], timeout=10) as response:
        case_text = response.read().decode()
    assert "speed: 2.5 rpm" in case_text
    assert parse_case(yaml.safe_load(case_text)) == parse_case(raw)
    with urllib.request.urlopen(links["report.html"], timeout=10) as response:
        assert f"{expected:.6g}"[:5] in response.read().decode()

    # Save case: the edited case as a YAML file, with units, that loads to the same case
    _click(browser, lambda d: _by(d, "#save-button"))
    saved = downloads / f"{CASE}.yaml"
    _wait(browser, lambda d: saved.is_file() and saved.stat().st_size > 0)
    assert parse_case(yaml.safe_load(saved.read_text(encoding="utf-8"))) == parse_case(raw)


def _upload(driver, path) -> None:
    _by(driver, "#case-upload input[type=file]").send_keys(str(path))


def test_bad_input_is_shown_next_to_its_field_and_results_stay(
    browser, app_server, screenshot, tmp_path
):
    _open(browser, app_server)
    _run(browser)
    outlet = _by(browser, "#outlet-temperature").text
    assert re.match(r"[0-9.]+ K \(", outlet)

    # a value without a unit: refused next to the field, as it is typed and on Run
    _type(browser, "operation.speed", "3")
    _wait(browser, lambda d: "no unit" in _field_error(d, "operation.speed"))
    status = _run(browser, expect_ok=False)
    assert "not done" in status, status
    assert "operation.speed: 3 has no unit" in _field_error(browser, "operation.speed")
    assert _by(browser, "#outlet-temperature").text == outlet  # nothing computed is lost
    before = _status(browser)
    _click(browser, lambda d: _by(d, "#save-button"))  # nor saved
    _wait(browser, lambda d: _status(d) != before)
    assert _status(browser).startswith("Save 1 not done"), _status(browser)
    _type(browser, "operation.speed", "1.5 rpm")
    _wait(browser, lambda d: _field_error(d, "operation.speed") == "")

    # a value the case refuses: the CLI's one-line message, next to the field
    _type(browser, "kiln.diameter", "-0.4 m")
    raw = _raw()
    raw["kiln"]["diameter"] = "-0.4 m"
    with pytest.raises(InputError) as cli_error:
        parse_case(raw, source=CASE)
    _run(browser, expect_ok=False)
    _wait(browser, lambda d: _field_error(d, "kiln.diameter") == str(cli_error.value))
    assert _by(browser, "#outlet-temperature").text == outlet
    screenshot(browser, "app_field_error.png")

    # an upload that is not YAML: refused next to the upload; the loaded case stays
    junk = tmp_path / "notes.yaml"
    junk.write_text("kiln: [unclosed\n  speed: {\n", encoding="utf-8")
    _upload(browser, junk)
    _wait(browser, lambda d: "notes.yaml: malformed YAML" in _by(d, "#upload-error").text)
    assert _field(browser, "kiln.diameter").get_attribute("value") == "-0.4 m"
    assert _by(browser, "#outlet-temperature").text == outlet
    binary = tmp_path / "photo.png"
    binary.write_bytes(b"\x89PNG\r\n\x1a\n\x00\x00\xff\xfe")
    _upload(browser, binary)
    _wait(browser, lambda d: "photo.png: not UTF-8" in _by(d, "#upload-error").text)
    screenshot(browser, "app_upload_error.png")

    # an uploaded case with an error: loaded, its error next to the field
    bad = _raw()
    bad["operation"]["feed"] = "-5 kg/h"
    with pytest.raises(InputError) as feed_error:
        parse_case(bad, source="bad_feed.yaml")
    path = tmp_path / "bad_feed.yaml"
    path.write_text(yaml.safe_dump(bad, sort_keys=False), encoding="utf-8")
    _upload(browser, path)
    _wait(browser, lambda d: _by(d, "#case-info").text == "Loaded: bad_feed.yaml (uploaded)")
    assert _by(browser, "#upload-error").text == ""
    _wait(browser, lambda d: _field_error(d, "operation.feed") == str(feed_error.value))
    assert _by(browser, "#outlet-temperature").text == outlet

    # fixed in the app, it runs: the app kept going through all of the above
    _type(browser, "operation.feed", "14.2 kg/h")
    _run(browser)
    assert _field_error(browser, "operation.feed") == ""
    assert _by(browser, "#outlet-temperature").text == outlet  # the same inputs as the first run


RTD_CASE = "rtd/bongo_njeng_sand_rl"
TRANSPORT_CASE = "charcoal_activation_kramers"  # a kiln whose bed depth follows Kramers
TRANSVERSE_CASE = "retort/case02"


def _builtin(name: str) -> dict:
    return yaml.safe_load(builtin_case_path(name).read_text(encoding="utf-8"))


def _pick(driver, name: str) -> None:
    """Choose a built-in case in the case list (searched by its name) and wait for it."""
    _click(driver, lambda d: _by(d, "#case-picker"))
    _wait(driver, lambda d: d.find_element("css selector", ".dash-dropdown-search")).send_keys(name)
    _click(
        driver,
        lambda d: next(
            (o for o in d.find_elements("css selector", "[role=option]") if o.text == name),
            None,
        ),
    )
    _wait(driver, lambda d: _by(d, "#case-info").text == f"Loaded: {name} (built-in)")


def _drawn(driver, graph: str) -> list:
    """The traces Plotly drew in the figure ``graph`` (an element id)."""
    return _wait(
        driver, lambda d: d.find_elements("css selector", f"#{graph} .scatterlayer .trace")
    )


def _page_text(driver) -> str:
    return driver.find_element("tag name", "body").text


def test_each_case_type_shows_its_results_and_the_page_holds_at_420_px(
    browser, app_server, screenshot
):
    from rotarykiln.commands.model_runs import bed_profile_from_case, predict_from_case

    _open(browser, app_server)

    # an RTD case: E(t) drawn, its moments shown as the prediction gives them
    _pick(browser, RTD_CASE)
    _run(browser)
    prediction = predict_from_case(parse_case(_builtin(RTD_CASE)))
    assert _drawn(browser, "rtd-graph")
    minutes = prediction.mean_residence_time / 60
    assert _by(browser, "#headline-value").text == f"{minutes:.1f} min"
    moments = _by(browser, "#rtd").text
    assert f"{minutes:.2f}\nmin" in moments or f"{minutes:.2f} min" in moments, moments
    assert f"{prediction.variance / 3600:.3g}" in moments and "Péclet" in moments, moments
    assert "no heat model" not in _page_text(browser).lower()
    screenshot(browser, "app_rtd.png")

    # a kiln with a transport section: its temperatures and its bed profile
    _pick(browser, TRANSPORT_CASE)
    _run(browser)
    profile = bed_profile_from_case(parse_case(_builtin(TRANSPORT_CASE)))
    assert _drawn(browser, "bed-profile-graph")
    assert _drawn(browser, "temperature-graph-kiln")
    bed = _by(browser, "#bed-profile").text
    assert f"{profile.holdup_mass:.4g}" in bed, bed
    assert f"{profile.mean_residence_time / 60:.1f}" in bed, bed
    assert _by(browser, "#outlet-temperature").get_attribute("data-kelvin")
    assert "no heat model" not in _page_text(browser).lower()

    # a transverse (retort-zone) case: the transverse run's time series, not "no heat model"
    _pick(browser, TRANSVERSE_CASE)
    _run(browser)
    assert len(_drawn(browser, "transverse-graph")) == 4  # 2 temperatures, mixing, volatiles
    assert "Mixing time" in _by(browser, "#transverse").text
    assert "no heat model" not in _page_text(browser).lower()
    screenshot(browser, "app_transverse.png")

    # the page holds on a phone: no horizontal scrollbar, figures as wide as the screen
    _pick(browser, TRANSPORT_CASE)
    _run(browser)
    _drawn(browser, "bed-profile-graph")
    size = browser.get_window_size()
    try:
        browser.set_window_size(420, 900)
        _wait(browser, lambda d: d.execute_script("return window.innerWidth") <= 440)
        width = browser.execute_script("return window.innerWidth")
        assert 380 <= width <= 440, width  # the window did narrow
        # Plotly redraws the figures at the new width
        _wait(
            browser,
            lambda d: d.execute_script(
                "return [...document.querySelectorAll('.graph .main-svg')]"
                ".every(s => s.getBoundingClientRect().right <= window.innerWidth)"
            ),
        )
        scroll = browser.execute_script("return document.documentElement.scrollWidth")
        assert scroll <= width + 1, (scroll, width)
        wide = browser.execute_script(
            "return [...document.querySelectorAll('body *')]"
            ".filter(e => e.getBoundingClientRect().right > window.innerWidth + 1)"
            ".map(e => e.tagName + '.' + e.className + '#' + e.id).slice(0, 5)"
        )
        assert wide == [], wide
        screenshot(browser, "app_420px.png")
    finally:
        browser.set_window_size(size["width"], size["height"])
