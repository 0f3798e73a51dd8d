"""The MkDocs hook that renders the docstrings' Sphinx roles and math (docs/scripts)."""

import importlib.util
from pathlib import Path

HOOKS = Path(__file__).resolve().parents[2] / "docs" / "scripts" / "mkdocs_hooks.py"


def _hooks():
    spec = importlib.util.spec_from_file_location("mkdocs_hooks", HOOKS)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_roles_and_math_are_rewritten():
    h = _hooks()
    html = (
        "<p>with :math:<code>N = 1 - B</code>, see :class:<code>rotarykiln.kiln.Kiln</code> and "
        ":meth:<code>~rotarykiln.kiln.inputs.kiln.Kiln.inert</code></p>\n<p>.. math::\n    a = b,\n"
        "    c = d</p>"
    )
    out = h.sphinx_to_html(html)
    assert ":math:" not in out and ":class:" not in out and ":meth:" not in out
    assert '<span class="arithmatex">\\(N = 1 - B\\)</span>' in out
    assert "<code>rotarykiln.kiln.Kiln</code>" in out and "<code>inert</code>" in out
    assert '<div class="arithmatex">\\[a = b,\n    c = d\\]</div>' in out
    assert h.on_page_content("<p>plain</p>", None, None, None) == "<p>plain</p>"
