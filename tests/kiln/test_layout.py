"""The kiln package's layout rules, checked on the source (ast, not text search).

- a case file reaches the kiln model through one front end: no module of ``rotarykiln.kiln``
  but ``rotarykiln.kiln.from_case`` imports ``rotarykiln.case`` (docstring examples aside);
- the inputs are frozen and stay so: no ``object.__setattr__`` anywhere in the kiln package;
- nothing sets an attribute of the residual from outside it (its continuation scales and its
  inputs at the ends are arguments of ``KilnResidual.evaluate``).
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

import rotarykiln.kiln

KILN = Path(rotarykiln.kiln.__file__).parent
PACKAGE = KILN.parent
MODULES = sorted(p for p in KILN.rglob("*.py"))


def _imports(tree: ast.AST):
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            yield from (a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module:
            yield node.module
            yield from (f"{node.module}.{a.name}" for a in node.names)


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(KILN)))
def test_only_the_front_end_reads_a_case(path):
    names = set(_imports(ast.parse(path.read_text(encoding="utf-8"))))
    reads_case = {n for n in names if n == "rotarykiln.case" or n.startswith("rotarykiln.case.")}
    if not (path.name == "from_case.py" and path.parent == KILN):  # the front end may
        assert not reads_case, f"{path.relative_to(KILN)} imports {sorted(reads_case)}"


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(KILN)))
def test_no_frozen_input_is_written_to(path):
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):
            f = node.func
            if f.attr == "__setattr__" and isinstance(f.value, ast.Name):
                assert f.value.id != "object", f"{path.relative_to(KILN)}:{node.lineno}"


RESIDUAL_NAMES = {"res", "residual", "coarse", "F", "R", "C", "dst", "src"}


def _residual_writes(tree: ast.AST):
    """Assignments ``<residual>.<attr> = ...`` with a residual-like receiver."""
    for node in ast.walk(tree):
        targets = []
        if isinstance(node, ast.Assign):
            targets = node.targets
        elif isinstance(node, ast.AugAssign | ast.AnnAssign):
            targets = [node.target]
        for t in targets:
            if not isinstance(t, ast.Attribute):
                continue
            v = t.value
            if isinstance(v, ast.Name) and v.id in RESIDUAL_NAMES:
                yield node.lineno, f"{v.id}.{t.attr}"
            elif isinstance(v, ast.Attribute) and v.attr == "res":
                yield node.lineno, f"....res.{t.attr}"


@pytest.mark.parametrize(
    "path",
    sorted(p for p in PACKAGE.rglob("*.py") if p.name != "residual.py"),
    ids=lambda p: str(p.relative_to(PACKAGE)),
)
def test_nothing_sets_an_attribute_of_the_residual(path):
    found = list(_residual_writes(ast.parse(path.read_text(encoding="utf-8"))))
    assert not found, f"{path.relative_to(PACKAGE)}: {found}"


def test_the_rules_can_fail():
    """Each check finds what it looks for in a made-up module."""
    bad = ast.parse(
        "from rotarykiln.case import Case\n"
        "object.__setattr__(k, 'x', 1)\n"
        "res.radiation_scale = 0.5\n"
        "self.res.q_ref = 2.0\n"
    )
    assert "rotarykiln.case" in set(_imports(bad))
    assert [w for _, w in _residual_writes(bad)] == ["res.radiation_scale", "....res.q_ref"]
