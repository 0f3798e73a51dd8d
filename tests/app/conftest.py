"""Fixtures of the browser tests: the app served on a free port, and Debian's headless Chromium
driven by Selenium (no browser download: `make browser` installs chromium and chromium-driver).

Without Chromium, Dash or Selenium the browser tests are skipped on a developer's machine and fail
under CI (CI=true), where `make test` has installed them. Screenshots go to
$ROTARYKILN_SCREENSHOTS when it is set, else to a temporary folder.
"""

from __future__ import annotations

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
    import importlib

    try:
        return importlib.import_module(module)
    except ImportError:
        _missing(f"{module} is not installed (pip install -e '.[test]')")


@pytest.fixture(scope="session")
def selenium_webdriver():
    webdriver = _require("selenium.webdriver")
    for path in (CHROMIUM, CHROMEDRIVER):
        if not Path(path).is_file():
            _missing(f"{path} not found (Debian: apt-get install chromium chromium-driver)")
    return webdriver


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
def browser(selenium_webdriver, downloads):
    """One headless Chromium for the session (each test loads its own page)."""
    from selenium.webdriver.chrome.service import Service

    os.environ.setdefault("SE_OFFLINE", "true")  # Selenium Manager fetches nothing

    options = selenium_webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for arg in (
        "--headless=new",
        "--no-sandbox",  # CI runs as root
        "--disable-dev-shm-usage",
        "--disable-gpu",
        "--window-size=1400,1000",
        "--disable-extensions",
        "--no-first-run",
    ):
        options.add_argument(arg)
    options.add_experimental_option(
        "prefs",
        {"download.default_directory": str(downloads), "download.prompt_for_download": False},
    )
    driver = selenium_webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    driver.set_page_load_timeout(30)
    driver.execute_cdp_cmd(
        "Browser.setDownloadBehavior", {"behavior": "allow", "downloadPath": str(downloads)}
    )
    try:
        yield driver
    finally:
        driver.quit()


@pytest.fixture(scope="module")
def app_server(tmp_path_factory):
    """The app on a free local port, shut down after the module's tests."""
    _require("dash")
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
