"""Fixtures of the suite's browser tests (tests/app/, tests/docs/): Debian's headless Chromium
driven by Selenium (no browser download: `make browser` installs chromium and chromium-driver),
and the app served on a free port. One conftest for the suite: two files named conftest.py in
folders without an ``__init__.py`` collide under ``--doctest-modules``. Screenshots go to
$ROTARYKILN_SCREENSHOTS when it is set, else to a temporary folder.

Without Chromium or a Python package they need, those tests are skipped on a developer's machine
and fail under CI (CI=true), where `make test` has installed everything.
"""

from __future__ import annotations

import importlib
import os
import shutil
from pathlib import Path

import pytest

CHROMIUM = os.environ.get("ROTARYKILN_CHROMIUM") or shutil.which("chromium") or "/usr/bin/chromium"
CHROMEDRIVER = (
    os.environ.get("ROTARYKILN_CHROMEDRIVER")
    or shutil.which("chromedriver")
    or "/usr/bin/chromedriver"
)


def _missing(reason: str):
    if os.environ.get("CI"):
        pytest.fail(f"{reason} (make test installs it)")
    pytest.skip(reason)


def _require(module: str):
    try:
        return importlib.import_module(module)
    except ImportError:
        _missing(f"{module} is not installed (pip install -e '.[test]')")


@pytest.fixture(scope="session")
def require_module():
    """``require_module(name)``: the module, or the test skipped (a failure under CI)."""
    return _require


@pytest.fixture(scope="session")
def selenium_webdriver():
    webdriver = _require("selenium.webdriver")
    for path in (CHROMIUM, CHROMEDRIVER):
        if not Path(path).is_file():
            _missing(f"{path} not found (Debian: apt-get install chromium chromium-driver)")
    return webdriver


@pytest.fixture(scope="session")
def chromium(selenium_webdriver):
    """``chromium(*arguments, window=..., prefs=...)``: a headless Chromium driver with the
    arguments every browser test needs (root in CI, no GPU, no first-run page) and ``arguments``
    of the test's own; the caller quits it."""
    from selenium.webdriver.chrome.service import Service

    os.environ.setdefault("SE_OFFLINE", "true")  # Selenium Manager fetches nothing

    def make(*arguments: str, window: str = "1400,1000", prefs: dict | None = None):
        options = selenium_webdriver.ChromeOptions()
        options.binary_location = CHROMIUM
        for arg in (
            "--headless=new",
            "--no-sandbox",  # CI runs as root
            "--disable-dev-shm-usage",
            "--disable-gpu",
            f"--window-size={window}",
            "--disable-extensions",
            "--no-first-run",
            *arguments,
        ):
            options.add_argument(arg)
        if prefs:
            options.add_experimental_option("prefs", prefs)
        driver = selenium_webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
        driver.set_page_load_timeout(30)
        return driver

    return make


@pytest.fixture(scope="session")
def screenshot_dir(tmp_path_factory) -> Path:
    folder = os.environ.get("ROTARYKILN_SCREENSHOTS")
    path = Path(folder) if folder else tmp_path_factory.mktemp("screenshots")
    path.mkdir(parents=True, exist_ok=True)
    return path


@pytest.fixture(scope="session")
def downloads(tmp_path_factory) -> Path:
    """The folder the browser saves downloads into."""
    return tmp_path_factory.mktemp("downloads")


@pytest.fixture(scope="session")
def browser(chromium, downloads):
    """One headless Chromium for the session (each test loads its own page)."""
    driver = chromium(
        prefs={"download.default_directory": str(downloads), "download.prompt_for_download": False}
    )
    driver.execute_cdp_cmd(
        "Browser.setDownloadBehavior", {"behavior": "allow", "downloadPath": str(downloads)}
    )
    try:
        yield driver
    finally:
        driver.quit()


@pytest.fixture(scope="module")
def app_server(tmp_path_factory, require_module):
    """The app on a free local port, shut down after the module's tests."""
    require_module("dash")
    from rotarykiln.app.running import RunStore
    from rotarykiln.app.server import AppServer

    server = AppServer(port=0, store=RunStore(tmp_path_factory.mktemp("runs")))
    server.start()
    try:
        yield server
    finally:
        server.stop()


@pytest.fixture(scope="session")
def screenshot(screenshot_dir):
    """``screenshot(driver, "name.png")``: the whole page (the window stretched to its height)."""

    def take(driver, name: str) -> Path:
        size = driver.get_window_size()
        full = driver.execute_script(
            "return Math.max(document.body.scrollHeight, document.documentElement.scrollHeight)"
        )
        driver.set_window_size(size["width"], min(max(int(full) + 140, 800), 6000))
        path = screenshot_dir / name
        try:
            driver.save_screenshot(str(path))
        finally:
            driver.set_window_size(size["width"], size["height"])
        return path

    return take
