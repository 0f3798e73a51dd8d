"""Fixtures of the app's browser tests: the app served on a free port and one Chromium for the
session (made by the ``chromium`` fixture of tests/conftest.py). Screenshots go to
$ROTARYKILN_SCREENSHOTS when it is set, else to a temporary folder.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest


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
