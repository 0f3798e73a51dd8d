"""Fixtures shared by the suite's browser tests (tests/app/, tests/docs/): Debian's headless
Chromium driven by Selenium (no browser download: `make browser` installs chromium and
chromium-driver).

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
