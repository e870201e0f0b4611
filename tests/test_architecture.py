"""The package's structure: no import cycle between its modules, layers pointing one way."""

from __future__ import annotations

import ast
from pathlib import Path

import rocking

ROOT = Path(rocking.__file__).resolve().parent


def _module_name(path: Path) -> str:
    rel = path.relative_to(ROOT.parent).with_suffix("")
    parts = list(rel.parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def _resolve(module: str, is_pkg: bool, node: ast.ImportFrom) -> str:
    if node.level == 0:
        return node.module or ""
    base = module.split(".") if is_pkg else module.split(".")[:-1]
    base = base[: len(base) - (node.level - 1)]
    return ".".join(base + ([node.module] if node.module else []))


def import_graph() -> dict[str, set[str]]:
    """Edges module -> imported rocking module, from every import statement (also those
    inside functions), parsed with ast."""
    files = {_module_name(p): p for p in ROOT.rglob("*.py")}
    graph: dict[str, set[str]] = {m: set() for m in files}
    for mod, path in files.items():
        is_pkg = path.name == "__init__.py"
        for node in ast.walk(ast.parse(path.read_text(), str(path))):
            targets = []
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                base = _resolve(mod, is_pkg, node)
                # ``from pkg import name``: the submodule pkg.name if there is one, else pkg
                targets = [f"{base}.{a.name}" if f"{base}.{a.name}" in files else base
                           for a in node.names]
            for t in targets:
                # the longest known module that t names (``from . import x`` may be a module)
                while t and t not in files:
                    t = t.rpartition(".")[0]
                if t and t.startswith("rocking") and t != mod:
                    graph[mod].add(t)
    return graph


def find_cycle(graph: dict[str, set[str]]) -> list[str] | None:
    """A cycle of the graph as a list of modules, or None (iterative DFS)."""
    state: dict[str, int] = {}
    for start in sorted(graph):
        if state.get(start):
            continue
        stack = [(start, iter(sorted(graph[start])))]
        path = [start]
        state[start] = 1
        while stack:
            node, it = stack[-1]
            nxt = next(it, None)
            if nxt is None:
                stack.pop()
                path.pop()
                state[node] = 2
            elif state.get(nxt) == 1:
                return path[path.index(nxt):] + [nxt]
            elif not state.get(nxt):
                state[nxt] = 1
                path.append(nxt)
                stack.append((nxt, iter(sorted(graph.get(nxt, ())))))
    return None


def test_cycle_detector_finds_a_cycle():
    """The checker itself can fail: a planted cycle is found, an acyclic graph is not."""
    assert find_cycle({"a": {"b"}, "b": {"c"}, "c": {"a"}}) == ["a", "b", "c", "a"]
    assert find_cycle({"a": {"b"}, "b": {"c"}, "c": set()}) is None


def test_no_import_cycle_inside_the_package():
    graph = import_graph()
    assert "rocking.models.base" in graph and len(graph) > 40
    cycle = find_cycle(graph)
    assert cycle is None, "import cycle: " + " -> ".join(cycle)


def test_layers_point_one_way():
    """inputs (blocks, motions) never import models, results, analysis layers above them;
    models never import identify, report or cli; analysis never imports campaign, report
    or cli; campaign never imports report or cli."""
    graph = import_graph()
    above = {"inputs": ("rocking.models", "rocking.identify", "rocking.analysis",
                        "rocking.report", "rocking.cli", "rocking.campaign"),
             "models": ("rocking.identify", "rocking.analysis", "rocking.report",
                        "rocking.cli", "rocking.campaign")}
    for mod, deps in graph.items():
        if mod.startswith("rocking.analysis"):
            bad = [d for d in deps if d.startswith(("rocking.report", "rocking.cli",
                                                    "rocking.campaign"))]
            assert not bad, f"{mod} imports {bad}"
        if mod.startswith("rocking.campaign"):
            bad = [d for d in deps if d.startswith(("rocking.report", "rocking.cli"))]
            assert not bad, f"{mod} imports {bad}"
        if mod.startswith(("rocking.blocks", "rocking.motions")):
            bad = [d for d in deps if d.startswith(above["inputs"])]
            assert not bad, f"{mod} imports {bad}"
        if mod.startswith("rocking.models"):
            bad = [d for d in deps if d.startswith(above["models"])]
            assert not bad, f"{mod} imports {bad}"
