"""The documentation site typesets its equations with no network (KaTeX shipped with the site).

A minimal site is built with the real configuration (mkdocs.yml's theme, Markdown extensions,
hooks, extra CSS and JavaScript, and the vendored KaTeX files under docs/assets) around one real
page with equations, docs/geometry.md, and opened from disk in headless Chromium whose every
network fetch fails (a proxy on a dead port, background networking off). The equations must come
out typeset: KaTeX elements present, no raw TeX delimiters left in the visible text.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
PAGE = "geometry.md"  # inline ($Fr$) and display ($$...$$) equations, no API pages needed

pytest.importorskip(
    "mkdocs", reason="the docs packages are not installed (pip install -e '.[docs]')"
)
pytest.importorskip("material", reason="mkdocs-material is not installed (the docs extra)")


class _Loader(yaml.SafeLoader):
    """mkdocs.yml may carry !!python/name tags (e.g. for pymdownx options): kept as strings."""


_Loader.add_multi_constructor("tag:yaml.org,2002:python/", lambda loader, suffix, node: suffix)


def _site_config(docs_dir: Path, site_dir: Path) -> dict:
    """mkdocs.yml, reduced to one page: the same theme, Markdown, hooks and extra assets."""
    config = yaml.load((ROOT / "mkdocs.yml").read_text(encoding="utf-8"), Loader=_Loader)
    return {
        "site_name": config["site_name"],
        "docs_dir": str(docs_dir),
        "site_dir": str(site_dir),
        "use_directory_urls": config.get("use_directory_urls", False),
        "theme": config["theme"],
        "markdown_extensions": config["markdown_extensions"],
        "hooks": [str(ROOT / hook) for hook in config.get("hooks", [])],
        "extra_css": config.get("extra_css", []),
        "extra_javascript": config.get("extra_javascript", []),
        "nav": [{"Page": PAGE}],
        "plugins": [],
    }


@pytest.fixture(scope="module")
def built_site(tmp_path_factory) -> Path:
    """The one-page site, built by the mkdocs command into a temporary folder."""
    work = tmp_path_factory.mktemp("docs_site")
    docs_dir, site_dir = work / "docs", work / "site"
    docs_dir.mkdir()
    config = _site_config(docs_dir, site_dir)
    assets = [*config["extra_css"], *config["extra_javascript"]]
    assert assets, "mkdocs.yml loads no renderer (extra_css / extra_javascript)"
    for asset in assets:
        assert "://" not in asset, f"{asset}: the site must not load anything from the network"
    shutil.copytree(DOCS / "assets", docs_dir / "assets")
    shutil.copy2(DOCS / PAGE, docs_dir / PAGE)
    shutil.copytree(DOCS / "figures", docs_dir / "figures")  # the page's images
    (work / "mkdocs.yml").write_text(yaml.safe_dump(config), encoding="utf-8")
    build = subprocess.run(
        [sys.executable, "-m", "mkdocs", "build", "--quiet", "-f", str(work / "mkdocs.yml")],
        capture_output=True,
        text=True,
        timeout=120,
        env={**os.environ, "NO_MKDOCS_2_WARNING": "1"},
    )
    assert build.returncode == 0, build.stderr
    return site_dir


def test_vendored_katex_is_complete():
    """The files the site loads exist, with every font face the stylesheet names first."""
    katex = DOCS / "assets" / "katex"
    css = (katex / "katex.min.css").read_text(encoding="utf-8")
    assert (katex / "katex.min.js").stat().st_size > 100_000
    assert (DOCS / "assets" / "javascripts" / "katex-init.js").is_file()
    assert (katex / "LICENSE").is_file() and "MIT" in (katex / "LICENSE").read_text()
    woff2 = set(re.findall(r"url\((fonts/[\w-]+\.woff2)\)", css))
    assert len(woff2) >= 19
    missing = [name for name in woff2 if not (katex / name).is_file()]
    assert not missing, f"font files the css needs: {missing}"


@pytest.fixture(scope="module")
def offline_browser(chromium):
    """Headless Chromium with the network cut: every fetch goes to a dead proxy port."""
    driver = chromium(
        "--disable-background-networking",
        "--proxy-server=http://127.0.0.1:9",  # nothing listens there: any fetch fails
        "--proxy-bypass-list=<-loopback>",
        "--allow-file-access-from-files",
        window="1200,900",
    )
    try:
        yield driver
    finally:
        driver.quit()


def test_equations_render_offline(built_site, offline_browser):
    driver = offline_browser
    # the proxy really is dead: a page from the network does not load
    from selenium.common.exceptions import WebDriverException

    try:
        driver.get("http://example.com/")
        reached = "Example Domain" in driver.page_source
    except WebDriverException as exc:  # Chromium reports net::ERR_PROXY_CONNECTION_FAILED
        reached = "ERR_PROXY" not in str(exc)
    assert not reached, "the browser reached the network"

    page = built_site / PAGE.replace(".md", ".html")
    driver.get(page.as_uri())
    deadline = time.monotonic() + 15
    while time.monotonic() < deadline:
        done = driver.execute_script(
            "return document.querySelectorAll('.arithmatex').length > 0 &&"
            " document.querySelectorAll('.arithmatex:not([data-katex])').length === 0"
        )
        if done:
            break
        time.sleep(0.2)
    counts = driver.execute_script(
        "return {math: document.querySelectorAll('.arithmatex').length,"
        " katex: document.querySelectorAll('.arithmatex .katex').length,"
        " display: document.querySelectorAll('div.arithmatex .katex-display').length,"
        " errors: document.querySelectorAll('.katex-error, [data-katex=error]').length}"
    )
    assert counts["math"] >= 10, counts
    assert counts["katex"] == counts["math"], counts  # every equation typeset
    assert counts["display"] >= 1, counts
    assert counts["errors"] == 0, counts
    text = driver.find_element("tag name", "article").text
    for raw in ("\\(", "\\)", "\\[", "\\frac", "\\theta"):
        assert raw not in text, f"raw TeX {raw!r} visible on the page"
    # KaTeX's fonts came from the site, not a CDN: the math font is loaded
    fonts = driver.execute_script(
        "return Array.from(document.fonts).filter(f => f.family.indexOf('KaTeX') >= 0)"
        ".map(f => f.family + ':' + f.status)"
    )
    assert any(font.startswith("KaTeX_Main") and font.endswith(":loaded") for font in fonts), fonts
    assert any(font.startswith("KaTeX_Math") and font.endswith(":loaded") for font in fonts), fonts
