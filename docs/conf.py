"""Sphinx configuration of the rocking documentation.

Build (warnings are errors; no network needed)::

    .venv/bin/python -m sphinx -W --keep-going -b html docs docs/_build/html

Generated at build time, git-ignored, under ``docs/api/generated/``:

* one page per public package listing what its ``__all__`` exports (``PACKAGES``
  below), whose autosummary stubs autosummary writes beside it;
* ``docs/architecture.md`` and ``docs/cluster.md`` turned into reStructuredText by
  :func:`docs_md.convert` (the Markdown files stay the source, readable on GitHub).

The gallery (sphinx-gallery): every script of ``docs/gallery/`` runs during the build
(``abort_on_example_error``: an example that fails fails the build) and its pages, figures
and downloads go to ``docs/auto_examples/`` (git-ignored, like ``docs/sg_execution_times.rst``).
"""

from __future__ import annotations

import functools
import importlib
import importlib.util
import inspect
import os
import pkgutil
import re
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))              # docs_md
sys.path.insert(0, str(HERE.parent / "src"))

import docs_md  # noqa: E402

import rocking  # noqa: E402

project = "rocking"
author = "the rocking authors"
copyright = "2026, the rocking authors"
release = rocking.__version__
version = ".".join(release.split(".")[:2])

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "numpydoc",
    "sphinx_click",
    "sphinx_gallery.gen_gallery",
]

# -- the public API, generated from each package's __all__ --------------------------------
PACKAGES = {
    "rocking": "Blocks, simulation entry points, results, errors and constants.",
    "rocking.blocks": "Rigid blocks, stacks and the paper's specimens.",
    "rocking.motions": "Ground motions: harmonic, pulses, records, spectra, synthetics.",
    "rocking.buildings": "Buildings as linear filters: floor motions and floor spectra.",
    "rocking.shapes": "Rigid bodies from 3-D meshes: directional rocking parameters.",
    "rocking.models": "The model interface, the registry and the driver.",
    "rocking.analysis": "Spectra, Monte Carlo, IDA, fragility, hazard, record selection.",
    "rocking.identify": "Identification of alpha, p and mu from free rocking.",
    "rocking.campaign": "Campaigns: TOML specs, executors, the Parquet store.",
    "rocking.report": "The reproduction report.",
    "rocking.viewer3d": "Seeing a 3-D response: an animation and a self-contained page.",
    "rocking.testing": "The model contract and plain reference implementations.",
    "rocking.verification": "The verification manual: cases from the literature, run.",
}
GENERATED = HERE / "api" / "generated"


def _write_if_changed(path: Path, text: str) -> None:
    """Write ``text`` unless ``path`` already holds it (keeps incremental builds quick)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    if not path.exists() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")


_SEEN: dict[int, str] = {}       # id of an object -> the page's name that documents it


def _is_data(obj) -> bool:
    return not (inspect.ismodule(obj) or inspect.isclass(obj) or callable(obj))


def _modules_under(package: str) -> list[str]:
    """``package`` and every module below it (found, not imported; no ``__main__``)."""
    names = [package]
    spec = importlib.util.find_spec(package)
    for info in pkgutil.walk_packages(spec.submodule_search_locations or [], package + "."):
        if not info.name.endswith("__main__"):
            names.append(info.name)
    return names


def _data_doc(package: str, name: str) -> str:
    """The ``#:`` comment (or the string after it) of constant ``name``, where it is
    assigned: in ``package``'s modules first, then anywhere in ``rocking``."""
    from sphinx.pycode import ModuleAnalyzer

    for modname in _modules_under(package) + _modules_under("rocking"):
        try:
            docs = ModuleAnalyzer.for_module(modname).find_attr_docs()
        except Exception:  # noqa: BLE001 - a module without source: look further
            continue
        if ("", name) in docs:
            return "\n".join(docs[("", name)]).strip()
    return ""


def _data_entry(package: str, name: str, obj) -> list[str]:
    """A constant: ``.. data::`` with its value (when short) and its doc comment."""
    lines = [f".. data:: {name}"]
    value = repr(obj)
    if len(value) <= 70 and "<" not in value:
        lines.append(f"   :value: {value}")
    doc = _data_doc(package, name)
    lines.append("")
    lines += [f"   {ln}" if ln else "" for ln in doc.splitlines()] or [""]
    return lines + [""]


def _package_page(name: str, summary: str) -> str:
    """The page of package ``name``: its docstring and an autosummary of its ``__all__``.

    An object exported by an earlier package of ``PACKAGES`` (``rocking.Block`` is
    ``rocking.blocks.Block``) is documented once, there, and named here with a link.
    Constants get a ``data`` entry with their value and doc comment (autosummary would
    show the docstring of their type).
    """
    mod = importlib.import_module(name)
    own, data, again = [], [], []
    for n in getattr(mod, "__all__", ()):
        if n.startswith("_"):
            continue
        obj = getattr(mod, n)
        scalar = isinstance(obj, (int, float, str, tuple))
        first = None if scalar else _SEEN.get(id(obj))
        if first is not None:
            again.append((n, first))
            continue
        if not scalar:
            _SEEN[id(obj)] = f"{name}.{n}"
        (data if _is_data(obj) else own).append((n, obj))
    title = f"``{name}``"
    lines = [title, "=" * len(title), "", summary, "",
             f".. automodule:: {name}", "   :no-members:", "",
             f".. currentmodule:: {name}", "",
             ".. autosummary::", "   :toctree: .", "   :nosignatures:", ""]
    lines += [f"   {n}" for n, _ in own]
    if data:
        lines += ["", "Constants", "---------", ""]
        for n, obj in data:
            lines += _data_entry(name, n, obj)
    if again:
        lines += ["", "Also exported here: " + ", ".join(
            f":obj:`{n} <{first}>`" for n, first in again) + "."]
    notes = sorted(m for m in _module_notes() if _home(m) == name)
    if notes:
        lines += ["", "Module notes", "------------", "",
                  "The derivations and conventions that the docstrings above cite as "
                  "their *module docstring*, one page per module.", "",
                  ".. toctree::", "   :maxdepth: 1", ""]
        lines += [f"   modules/{m}" for m in notes]
    return "\n".join(lines) + "\n"


# -- "see the module docstring": the cited module docstrings get a page, and the words a link
_MODULE_DOC = re.compile(r"\b(?:the )?module doc(?:string)?\b(?! of )")


def _doc_module(obj) -> str | None:
    """The module an object (function, class, method, property) is defined in."""
    return getattr(obj, "__module__", None) or getattr(getattr(obj, "fget", None),
                                                      "__module__", None)


@functools.cache
def _module_notes() -> frozenset[str]:
    """The modules whose docstring an exported object (or its public member) cites."""
    found = set()
    for package in PACKAGES:
        for n in getattr(importlib.import_module(package), "__all__", ()):
            obj = getattr(importlib.import_module(package), n)
            objs = [obj] + ([m for k, m in vars(obj).items() if not k.startswith("_")]
                            if inspect.isclass(obj) else [])
            for o in objs:
                o = getattr(o, "__func__", o)
                doc = inspect.getdoc(o) if callable(o) or isinstance(o, property) else None
                mod = _doc_module(o)
                if doc and mod and mod.startswith("rocking.") and _MODULE_DOC.search(
                        " ".join(doc.split())):
                    found.add(mod)
    # the verification page cites the derivations of the catalog's closed forms
    found.add("rocking.verification.catalog")
    return frozenset(found)


def _home(module: str) -> str:
    """The package of ``PACKAGES`` a module belongs to (the longest prefix)."""
    return max((p for p in PACKAGES if module == p or module.startswith(p + ".")), key=len)


_BUILTIN_DOCS = tuple(" ".join(t.__doc__.split())[:60]
                      for t in (int, float, str, bool, tuple, list, dict, object))


def _drop_builtin_docstring(app, what, name, obj, options, lines) -> None:
    """autodoc: an undocumented member that overrides a class attribute (``Motion.kind``,
    an ``int``) inherits the docstring of ``int``; show nothing rather than that."""
    if lines and " ".join(" ".join(lines).split()).startswith(_BUILTIN_DOCS):
        lines.clear()


def _link_module_docstring(app, what, name, obj, options, lines) -> None:
    """autodoc: "(see the module docstring)" links to the module's page (a page, not a
    ``py:module`` target: ``rocking.motions.synthetic`` is a module and a function)."""
    target = _doc_module(obj)
    if target not in _module_notes():     # an attribute: the module of its class
        parent, _, _ = name.rpartition(".")
        try:
            target = _doc_module(pkgutil.resolve_name(parent))
        except (ImportError, AttributeError, ValueError):
            return
        if target not in _module_notes():
            return
    for i in range(len(lines) - 1):       # "module" at the end of a line: join the words
        if re.search(r"\bmodule$", lines[i]) and re.match(r"\s*doc", lines[i + 1]):
            lines[i] = lines[i][:-len("module")].rstrip()
            stripped = lines[i + 1].lstrip()
            lines[i + 1] = lines[i + 1][:len(lines[i + 1]) - len(stripped)] + "module " \
                + stripped
    for i, line in enumerate(lines):
        lines[i] = _MODULE_DOC.sub(
            lambda m: f":doc:`{m.group(0)} </api/generated/modules/{target}>`", line)


def setup(app) -> None:
    app.connect("autodoc-process-docstring", _drop_builtin_docstring)
    app.connect("autodoc-process-docstring", _link_module_docstring)


for _mod in _module_notes():
    _title = f"``{_mod}``"
    _write_if_changed(GENERATED / "modules" / f"{_mod}.rst",
                      "\n".join([_title, "=" * len(_title), "",
                                 f".. automodule:: {_mod}", "   :no-members:",
                                 "   :no-index:", ""]))   # a module and a function may
                                                          # share a name (motions.synthetic)


for _name, _summary in PACKAGES.items():
    _write_if_changed(GENERATED / f"{_name}.rst", _package_page(_name, _summary))
for _md in ("architecture", "cluster"):
    _write_if_changed(GENERATED / f"{_md}.rst",
                      docs_md.convert((HERE / f"{_md}.md").read_text(encoding="utf-8")))

def _model_outputs_rst() -> str:
    """Every registered model's states and declared outputs (``Model.outputs``), as a table."""
    from rocking.models import MODELS

    out = [".. list-table::", "   :header-rows: 1", "   :widths: 12 22 10 56", "",
           "   * - model", "     - output", "     - unit", "     - meaning"]
    for name, cls in MODELS.items():
        for o in cls.outputs:
            unit = "flag" if o.flag else ("count" if o.integer else (o.unit or "-"))
            out += [f"   * - ``{name}``", f"     - ``{o.name}``", f"     - {unit}",
                    f"     - {o.help.replace('|', chr(92) + '|')}"]
    return "\n".join(out) + "\n"


_write_if_changed(GENERATED / "model_outputs.inc", _model_outputs_rst())


def _toy_model_source() -> str:
    """The toy model of the guide's "How to add a model" (``tests/sliding_model.py`` of the
    repository this ``rocking`` was imported from, or beside this folder)."""
    import rocking

    for tests in (Path(rocking.__file__).resolve().parents[2] / "tests", HERE.parent / "tests"):
        if (tests / "sliding_model.py").is_file():
            return (tests / "sliding_model.py").read_text(encoding="utf-8")
    return "# tests/sliding_model.py: see the repository's tests folder\n"


_write_if_changed(GENERATED / "sliding_model.py", _toy_model_source())

# the verification manual: every case run at build time (``rocking verify`` prints the same)
from rocking.verification import verification_rst  # noqa: E402

_write_if_changed(GENERATED / "verification_table.inc", verification_rst())

# -- the gallery: runnable examples, each run at build time ----------------------------------
sphinx_gallery_conf = {
    "examples_dirs": "gallery",
    "gallery_dirs": "auto_examples",
    "filename_pattern": r"\.py$",         # every example runs (not only plot_*)
    "ignore_pattern": r"__init__\.py",
    "abort_on_example_error": True,        # a failing example fails the build
    "only_warn_on_example_error": False,
    "image_scrapers": ("gallery_tools", "matplotlib"),   # the library's Figures, pyplot's
    "within_subsection_order": "gallery_tools.GalleryOrder",   # docs/gallery_tools.py
    "download_all_examples": False,
    "remove_config_comments": True,
    "capture_repr": (),                    # printed output only, no stray reprs
    "min_reported_time": 1,
}

autosummary_generate = True
autosummary_imported_members = True
autodoc_default_options: dict[str, object] = {}
autodoc_typehints = "none"          # numpydoc's Parameters sections say the types
autoclass_content = "class"
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_validation_checks: set[str] = set()
numpydoc_xref_param_type = False

# -- no network: no intersphinx; mathjax is loaded by the reader's browser -----------------
nitpicky = False
templates_path = ["_templates"]
exclude_patterns = ["_build", "**/.ipynb_checkpoints",
                    "gallery"]            # the gallery's sources: pages in auto_examples/
source_suffix = {".rst": "restructuredtext"}
root_doc = "index"
default_role = "literal"            # `x` is code, as in the Markdown files
# smart quotes and ellipses, but no dashes: the CLI's help texts (sphinx-click) name options
# as --amp, which "D" would print as an en dash
smartquotes_action = "qe"

html_theme = "pydata_sphinx_theme"
html_title = f"rocking {release}"
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "header_links_before_dropdown": 7,
}
# pages without siblings: no empty "Section Navigation" column
html_sidebars = {"verification": [], "changelog": [], "cli": []}
html_static_path = ["_static"]
html_css_files = ["rocking.css"]      # long "On this page" entries wrap
html_show_sourcelink = False
# "On this page" lists a class's members as from_code_value(), not
# HazardCurve.from_code_value() (long names ran out of the right-hand column)
toc_object_entries_show_parents = "hide"

os.environ.setdefault("MPLBACKEND", "Agg")
