"""Studies tests: ``@pytest.mark.slow`` tests run only with ``RK_SLOW=1`` (keeps `make test` fast)."""

import os

import pytest


def pytest_configure(config):
    config.addinivalue_line("markers", "slow: a long study test; run with RK_SLOW=1")


def pytest_collection_modifyitems(config, items):
    if os.environ.get("RK_SLOW") == "1":
        return
    skip = pytest.mark.skip(reason="slow: set RK_SLOW=1 to run")
    for item in items:
        if "slow" in item.keywords and "tests/studies" in str(item.fspath):
            item.add_marker(skip)
