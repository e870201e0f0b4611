"""Report sections for the tests of the report's worker processes
(``tests/test_report_jobs.py``): module-level, hence importable by a spawned worker.
Their ids start with ``zz_`` (ignored by the registry checks of ``test_report.py``)."""

from __future__ import annotations

import warnings

import pandas as pd

from rocking.report import section


@section("zz_ok", "A section that writes a table", order=1000)
def build_ok(ctx) -> str:
    ctx.save_csv(pd.DataFrame({"x": [0.1, 0.2], "y": [1.0 / 3.0, 2.0 / 3.0]}), "table")
    return "<p>ok</p>" + ctx.files_html()


@section("zz_warn", "A section that warns", order=1001, cost=2)
def build_warn(ctx) -> str:
    warnings.warn("zz: a warning raised in a worker", UserWarning, stacklevel=1)
    return "<p>warned</p>"


@section("zz_fail", "A section that fails", order=1002)
def build_fail(ctx) -> str:
    raise ValueError("zz: this section fails on purpose")
