"""Every public function and class (what each package's ``__all__`` exports), and every
public method of those classes, has an ``Examples`` section, and its examples run as
doctests (issue 22). Properties are attributes, documented in their class's docstring."""

from __future__ import annotations

import doctest
import importlib
import inspect

import numpy as np
import pytest

PACKAGES = ("rocking", "rocking.blocks", "rocking.motions", "rocking.buildings",
            "rocking.shapes", "rocking.models", "rocking.analysis", "rocking.identify",
            "rocking.campaign", "rocking.report", "rocking.testing", "rocking.verification",
            "rocking.viewer3d")


def public_objects() -> list[tuple[str, object]]:
    """``(qualified name, object)`` of every public function and class, each once (under
    the first package of :data:`PACKAGES` that exports it)."""
    seen, out = set(), []
    for pkg in PACKAGES:
        mod = importlib.import_module(pkg)
        for name in getattr(mod, "__all__", ()):
            obj = getattr(mod, name)
            # compiled (numba) and cached functions: the function they wrap
            obj = getattr(obj, "py_func", None) or getattr(obj, "__wrapped__", None) or obj
            if not (inspect.isfunction(obj) or inspect.isclass(obj)) or id(obj) in seen:
                continue
            seen.add(id(obj))
            out.append((f"{pkg}.{name}", obj))
    return out


def public_methods(objects) -> list[tuple[str, object]]:
    """``(qualified name, function)`` of every public method (plain, class or static) that
    a public class of ``objects`` defines in ``rocking`` itself (inherited ones once, under
    the class that defines them)."""
    out = []
    for qual, cls in objects:
        if not inspect.isclass(cls):
            continue
        for name, attr in vars(cls).items():
            func = attr.__func__ if isinstance(attr, (classmethod, staticmethod)) else attr
            if (name.startswith("_") or not inspect.isfunction(func)
                    or not func.__module__.startswith("rocking")):
                continue
            out.append((f"{qual}.{name}", func))
    return out


OBJECTS = public_objects()
OBJECTS += public_methods(OBJECTS)


@pytest.mark.parametrize("name, obj", OBJECTS, ids=[n for n, _ in OBJECTS])
def test_has_examples_that_run(name, obj, tmp_path, monkeypatch):
    doc = inspect.getdoc(obj) or ""
    assert "Examples\n--------" in doc, f"{name}: no numpydoc 'Examples' section"
    finder = doctest.DocTestFinder(recurse=False)
    tests = [t for t in finder.find(obj, name, globs={"np": np}) if t.examples]
    assert tests, f"{name}: the Examples section has no '>>>' example"
    monkeypatch.chdir(tmp_path)  # examples that write files write them here
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS
                                   | doctest.NORMALIZE_WHITESPACE)
    for t in tests:
        runner.run(t)
    res = runner.summarize(verbose=False)
    assert res.failed == 0, f"{name}: {res.failed} of {res.attempted} examples failed"
