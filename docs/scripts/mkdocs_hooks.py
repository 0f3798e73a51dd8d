"""MkDocs hook: Sphinx markup of the docstrings rendered for the web (mkdocs.yml ``hooks``).

The docstrings follow the ht style with Sphinx roles and directives (``:func:`x```,
``:math:`x```, ``.. math::``) for the doctests and IDEs; mkdocstrings renders them as Markdown,
where the roles would show raw (``:func:<code>x</code>``). This hook rewrites the rendered HTML
of every page: math roles and directives become the spans and blocks of arithmatex's
``generic`` form, which the site's vendored KaTeX typesets (docs/assets/javascripts/katex-init.js),
cross-reference roles become plain code (``~a.b.c``
shows ``c``, as Sphinx does).
"""

from __future__ import annotations

import re

_MATH_BLOCK = re.compile(r"<p>\.\. math::\s*(.*?)</p>", re.DOTALL)
_MATH_ROLE = re.compile(r":math:<code>(.*?)</code>", re.DOTALL)
_XREF_ROLE = re.compile(r":(?:func|class|mod|meth|attr|data|exc|obj|py:\w+):<code>~?([^<]*)</code>")


def _xref(match: re.Match) -> str:
    text = match.group(0)
    target = match.group(1)
    short = target.rsplit(".", 1)[-1] if ":<code>~" in text else target
    return f"<code>{short}</code>"


def sphinx_to_html(html: str) -> str:
    """The page's HTML with the Sphinx roles and math directives rewritten.

    Examples
    --------
    >>> sphinx_to_html("see :func:<code>~rotarykiln.kiln.steady.solve.solve_kiln</code>")
    'see <code>solve_kiln</code>'
    >>> sphinx_to_html(":math:<code>k_b</code>")
    '<span class="arithmatex">\\\\(k_b\\\\)</span>'
    >>> sphinx_to_html("<p>.. math:: a = b</p>")
    '<div class="arithmatex">\\\\[a = b\\\\]</div>'
    """
    html = _MATH_BLOCK.sub(
        lambda m: f'<div class="arithmatex">\\[{m.group(1).strip()}\\]</div>', html
    )
    html = _MATH_ROLE.sub(lambda m: f'<span class="arithmatex">\\({m.group(1)}\\)</span>', html)
    return _XREF_ROLE.sub(_xref, html)


def on_page_content(html, page, config, files):  # noqa: ARG001 (the MkDocs hook signature)
    """MkDocs event: rewrite each page's HTML once it is rendered."""
    return sphinx_to_html(html)
