"""The reproduction report: ``rocking.report.reproduce(out)`` writes ``out/index.html``.

The page puts the paper's numbers (Peña et al. 2007) and ours side by side, one section
per table or figure, each with its PNG figures and CSV tables next to the page.

Adding a section: write a module in :mod:`rocking.report.sections` with a function
decorated by :func:`rocking.report.core.section` (``build(ctx) -> HTML fragment``; see
:mod:`rocking.report.core` for the :class:`~rocking.report.core.Context` helpers) and add
the module name to :data:`SECTION_MODULES` below. Sections run in increasing ``order``.
"""

from __future__ import annotations

import importlib

from .core import (
    SECTIONS,
    Context,
    ModelStyle,
    ReportError,
    Section,
    model_style,
    ordered_sections,
    report_models,
    reproduce,
    section,
)

SECTION_PACKAGE = f"{__name__}.sections"
"""The package holding the section modules."""
SECTION_MODULES = ("table2", "identification", "table4", "free_rocking", "figure7", "dem",
                   "earthquakes", "figure6", "probability", "pulses", "fragility", "vertical",
                   "buildings", "mitigation", "real_object", "three_d")
"""Modules of :data:`SECTION_PACKAGE` that register sections when imported."""


def _import_sections() -> None:
    """Import the section modules; a module that fails to import becomes a failed section."""
    for i, name in enumerate(SECTION_MODULES):
        try:
            importlib.import_module(f"{SECTION_PACKAGE}.{name}")
        except Exception as exc:  # keep the rest of the report alive
            err = f"{type(exc).__name__}: {exc}"

            def _failed(ctx, _err=err, _name=name):
                raise RuntimeError(f"module {SECTION_PACKAGE}.{_name} failed to import: {_err}")

            section(name, f"{name} (module failed to import)", order=1000 + i)(_failed)


_import_sections()

__all__ = ["reproduce", "section", "Section", "SECTIONS", "Context", "ReportError",
           "ordered_sections", "SECTION_MODULES", "SECTION_PACKAGE", "ModelStyle",
           "model_style", "report_models"]
