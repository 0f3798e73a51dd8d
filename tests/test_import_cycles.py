"""No import cycle in the package: the modules of ``src/rotarykiln`` import each other one way.

Each module's imports executed when it is imported are read from its source (``ast``, nothing is
imported): the ``import rotarykiln...`` and ``from rotarykiln... import ...`` statements of the
module body, including those under a module-level ``if``/``try``/``with`` and in class bodies,
but not inside functions (deferred imports) nor under ``if TYPE_CHECKING:``. An import names the
module it loads: ``from rotarykiln.kiln.inputs import kiln as model`` the submodule ``rotarykiln.kiln.inputs.kiln``,
``from rotarykiln.kiln.inputs import Kiln`` the module ``rotarykiln.kiln.inputs.kiln``. The parent
packages Python initialises on the way are not counted as edges (every module would otherwise
lead to ``rotarykiln/__init__.py``), but a module that imports names from its own package's
``__init__`` is.

The graph of those edges must be acyclic. A cycle too large to break at once goes in
``KNOWN_CYCLES`` with the reason; the test then fails when the known cycle changes (broken or
grown), so that the list is kept true.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src"
PACKAGE = "rotarykiln"

#: Strongly connected sets of modules accepted for now: frozenset of module names -> reason.
KNOWN_CYCLES: dict[frozenset[str], str] = {}


def _module_files() -> dict[str, Path]:
    mods = {}
    for path in sorted((SRC / PACKAGE).rglob("*.py")):
        parts = path.relative_to(SRC).with_suffix("").parts
        if parts[-1] == "__init__":
            parts = parts[:-1]
        mods[".".join(parts)] = path
    return mods


def _is_type_checking(test: ast.expr) -> bool:
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"
    )


def _import_time_statements(body):
    """The statements of ``body`` run when the module is imported (not in functions)."""
    for node in body:
        yield node
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
            continue
        if isinstance(node, ast.If):
            if not _is_type_checking(node.test):
                yield from _import_time_statements(node.body)
            yield from _import_time_statements(node.orelse)
        elif isinstance(node, ast.Try) or type(node).__name__ == "TryStar":
            yield from _import_time_statements(node.body)
            for handler in node.handlers:
                yield from _import_time_statements(handler.body)
            yield from _import_time_statements(node.orelse)
            yield from _import_time_statements(node.finalbody)
        elif isinstance(node, (ast.With, ast.For, ast.While, ast.ClassDef)):
            yield from _import_time_statements(node.body)
            yield from _import_time_statements(getattr(node, "orelse", []))


def _resolve(name: str, modules) -> str | None:
    """The module of the package that ``name`` loads (its longest prefix that is a module)."""
    parts = name.split(".")
    while parts:
        candidate = ".".join(parts)
        if candidate in modules:
            return candidate
        parts.pop()
    return None


def _package_of(module: str, path: Path) -> str:
    return module if path.name == "__init__.py" else module.rpartition(".")[0]


def import_graph() -> dict[str, set[str]]:
    """Module -> the package's modules it imports at import time."""
    modules = _module_files()
    graph: dict[str, set[str]] = {}
    for mod, path in modules.items():
        tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
        edges = set()
        for node in _import_time_statements(tree.body):
            targets = []
            if isinstance(node, ast.Import):
                targets = [alias.name for alias in node.names]
            elif isinstance(node, ast.ImportFrom):
                if node.level:  # relative: from the module's own package upwards
                    base = _package_of(mod, path).split(".")
                    base = base[: len(base) - (node.level - 1)]
                    source = ".".join(base + ([node.module] if node.module else []))
                else:
                    source = node.module or ""
                targets = [f"{source}.{alias.name}" for alias in node.names]
            for target in targets:
                if target == PACKAGE or target.startswith(PACKAGE + "."):
                    found = _resolve(target, modules)
                    if found is not None and found != mod:
                        edges.add(found)
        graph[mod] = edges
    return graph


def strongly_connected(graph: dict[str, set[str]]) -> list[set[str]]:
    """Tarjan's strongly connected components (iterative), those of more than one module."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    components = []
    counter = 0
    for root in sorted(graph):
        if root in index:
            continue
        work = [(root, iter(sorted(graph[root])))]
        index[root] = low[root] = counter
        counter += 1
        stack.append(root)
        on_stack.add(root)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = counter
                    counter += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph[child]))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                parent = work[-1][0]
                low[parent] = min(low[parent], low[node])
            if low[node] == index[node]:
                component = set()
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.add(member)
                    if member == node:
                        break
                if len(component) > 1:
                    components.append(component)
    return components


def one_cycle(graph: dict[str, set[str]], component: set[str]) -> list[str]:
    """A shortest cycle through the first module of ``component`` (breadth first), closed."""
    start = min(component)
    previous = {start: None}
    queue = [start]
    while queue:
        node = queue.pop(0)
        for child in sorted(graph[node] & component):
            if child == start:
                path = [node]
                while previous[path[-1]] is not None:
                    path.append(previous[path[-1]])
                return [*reversed(path), start]
            if child not in previous:
                previous[child] = node
                queue.append(child)
    return sorted(component)  # pragma: no cover - a component always has a cycle


def _describe(graph, component) -> str:
    cycle = " -> ".join(one_cycle(graph, component))
    return f"{len(component)} modules: {sorted(component)}\n  for example {cycle}"


def test_the_graph_sees_the_imports():
    graph = import_graph()
    assert len(graph) > 100
    # a module-level import, a submodule named in ``from pkg import sub``, a package __init__
    assert "rotarykiln.kiln.gas_mixture" in graph["rotarykiln.kiln.residual"]
    assert "rotarykiln.kiln.inputs" in graph["rotarykiln.kiln"]
    # an import inside a function is deferred, not an edge (rotarykiln.__getattr__ -> api)
    assert "rotarykiln.api" not in graph["rotarykiln"]


def test_a_cycle_is_found_and_printed():
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a", "d"}, "d": set()}
    (component,) = strongly_connected(graph)
    assert component == {"a", "b", "c"}
    assert one_cycle(graph, component) == ["a", "b", "c", "a"]


def test_no_import_cycle_in_the_package():
    graph = import_graph()
    found = strongly_connected(graph)
    unknown = [c for c in found if frozenset(c) not in KNOWN_CYCLES]
    gone = [sorted(k) for k in KNOWN_CYCLES if set(k) not in found]
    message = "\n".join(f"import cycle among {_describe(graph, c)}" for c in unknown)
    assert not unknown, message
    assert not gone, f"known cycles no longer there (remove them from KNOWN_CYCLES): {gone}"


@pytest.mark.parametrize("component", sorted(map(sorted, KNOWN_CYCLES)) or [None])
def test_known_cycles_have_a_reason(component):
    if component is None:
        pytest.skip("no known cycle")
    assert KNOWN_CYCLES[frozenset(component)].strip()
