"""The package's structure: no import cycle between its modules, layers pointing one way,
no private name used outside the module that defines it."""

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
    """inputs (blocks, motions, buildings) never import models, results, analysis layers above them;
    models never import identify, report or cli; analysis never imports campaign, report
    or cli; campaign never imports report or cli; the verification manual (report layer)
    is imported only by the cli and never imports it."""
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
        if mod.startswith(("rocking.blocks", "rocking.motions", "rocking.buildings")):
            bad = [d for d in deps if d.startswith(above["inputs"])]
            assert not bad, f"{mod} imports {bad}"
        if mod.startswith("rocking.models"):
            bad = [d for d in deps if d.startswith(above["models"])]
            assert not bad, f"{mod} imports {bad}"
        if mod.startswith("rocking.verification"):
            bad = [d for d in deps if d.startswith("rocking.cli")]
            assert not bad, f"{mod} imports {bad}"
        elif not mod.startswith("rocking.cli"):
            bad = [d for d in deps if d.startswith("rocking.verification")]
            assert not bad, f"{mod} imports {bad}"


# --------------------------------------------------------------------------- private names
#
# A private NAME (``_x``: a function, class or constant) belongs to the file that defines
# it: another module, the package's ``__init__`` included, neither imports it (``from .mod
# import _x``) nor reaches it as an attribute (``mod._x``, ``rocking.mod._x``,
# ``Class._x`` of a class imported from elsewhere). A helper that other modules need gets
# a public name in the module that owns it. A private MODULE (``_validate``, ``_atomic``,
# ``motions/_kernel.py``, ``models/_numerics/``) is package-internal: any module of the
# package may import it and use its public names (not its private ones).

PRIVATE_ALLOWED: set[tuple[str, str]] = set()
"""Known exceptions: (importing module, owner module.private name)."""

_NAMEDTUPLE_API = {"_replace", "_asdict", "_fields", "_make", "_field_defaults"}


def _is_private(name: str) -> bool:
    return name.startswith("_") and not (name.startswith("__") and name.endswith("__"))


def private_uses(root: Path) -> list[tuple[str, str, str]]:
    """Every cross-module use of a private name in the package at ``root``, as
    ``(module, owner.name, "path:line")``, parsed with ast (imports inside functions too)."""
    pkg = root.name

    def name_of(path: Path) -> str:
        parts = list(path.relative_to(root.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        return ".".join(parts)

    files = {name_of(p): p for p in sorted(root.rglob("*.py"))}
    found = []
    for mod, path in files.items():
        is_pkg = path.name == "__init__.py"
        tree = ast.parse(path.read_text(), str(path))
        where = f"{path.relative_to(root.parent)}:{{}}"
        bound: dict[str, tuple[str, bool]] = {}  # name -> (module it comes from, is a module)
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                for a in node.names:
                    if a.name.split(".")[0] == pkg:
                        bound[a.asname or pkg] = (a.name if a.asname else pkg, True)
            elif isinstance(node, ast.ImportFrom):
                base = _resolve(mod, is_pkg, node)
                if base.split(".")[0] != pkg:
                    continue
                for a in node.names:
                    full = f"{base}.{a.name}"
                    if full in files:  # a module (private modules are fine)
                        bound[a.asname or a.name] = (full, True)
                        continue
                    bound[a.asname or a.name] = (base, False)
                    if _is_private(a.name) and base != mod:
                        found.append((mod, full, where.format(node.lineno)))
        for node in ast.walk(tree):
            if not (isinstance(node, ast.Attribute) and _is_private(node.attr)
                    and node.attr not in _NAMEDTUPLE_API):
                continue
            chain, v = [], node.value
            while isinstance(v, ast.Attribute):
                chain.append(v.attr)
                v = v.value
            if not (isinstance(v, ast.Name) and v.id in bound):
                continue
            owner, is_mod = bound[v.id]
            for attr in reversed(chain):  # follow submodules: rocking.motions._kernel
                if is_mod and f"{owner}.{attr}" in files:
                    owner = f"{owner}.{attr}"
                else:
                    is_mod = False
            if is_mod and f"{owner}.{node.attr}" in files:
                continue  # a private module reached as an attribute
            if owner != mod:
                found.append((mod, f"{owner}.{node.attr}", where.format(node.lineno)))
    return found


def test_private_name_checker_finds_planted_uses(tmp_path):
    """The checker itself can fail: every form of a cross-module private use is found, and
    public names of private modules, a module's own private names and re-exports of public
    names are not."""
    pkg = tmp_path / "pkg"
    (pkg / "sub").mkdir(parents=True)
    files = {
        "__init__.py": "from .a import _hidden, public\n",
        "a.py": "_hidden = 1\npublic = 2\n\ndef _f():\n    from .a import _hidden\n"
                "    return _hidden\n\nclass Thing:\n    _secret = 3\n\nx = Thing._secret\n",
        "_priv.py": "def helper():\n    pass\n\ndef _inner():\n    pass\n",
        "b.py": "import pkg.a\nimport pkg._priv as P\nfrom . import a, _priv\n"
                "from ._priv import helper\nfrom .a import Thing\nfrom .sub import c\n"
                "P.helper(); helper(); c.public\n"
                "a._f()\npkg.a._hidden\n_priv._inner()\nThing._secret\n",
        "sub/__init__.py": "",
        "sub/c.py": "from .. import _priv\nfrom ..a import _f as g\npublic = _priv.helper\n"
                    "def f(t):\n    return t._replace(x=1)\n",
    }
    for name, text in files.items():
        (pkg / name).write_text(text)
    found = sorted((m, o) for m, o, _ in private_uses(pkg))
    assert found == [("pkg", "pkg.a._hidden"),
                     ("pkg.b", "pkg._priv._inner"), ("pkg.b", "pkg.a._f"),
                     ("pkg.b", "pkg.a._hidden"), ("pkg.b", "pkg.a._secret"),
                     ("pkg.sub.c", "pkg.a._f")]


def test_no_private_name_is_used_across_modules():
    """No module imports or reaches another module's private name (see the note above
    ``PRIVATE_ALLOWED``); every offender is listed."""
    found = private_uses(ROOT)
    bad = [f"{where}: {mod} uses {name}" for mod, name, where in found
           if (mod, name) not in PRIVATE_ALLOWED]
    assert not bad, ("private names used across modules (give each a public name in the "
                     "module that defines it):\n" + "\n".join(bad))
    stale = PRIVATE_ALLOWED - {(mod, name) for mod, name, _ in found}
    assert not stale, f"PRIVATE_ALLOWED lists uses that are gone: {sorted(stale)}"
