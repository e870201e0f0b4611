"""``rocking reproduce``: the paper's tables and figures into ``OUT/index.html``.

::

    rocking reproduce --out results [--quick] [--full]
"""

from __future__ import annotations

from pathlib import Path

import click

from ..errors import ParameterError
from .common import CONTEXT


@click.command("reproduce", context_settings=CONTEXT)
@click.option("--out", default="results", show_default=True, type=click.Path(file_okay=False),
              help="Output folder of the report.")
@click.option("--quick", is_flag=True, help="Fewer, shorter simulations (for a smoke test).")
@click.option("--full", is_flag=True, help="Also the slow sections.")
def reproduce_cmd(out, quick, full):
    """Reproduce the paper's tables and figures into OUT/index.html."""
    try:  # lazy: the report imports matplotlib, pandas and every model
        from .. import report
    except ImportError as e:
        raise click.ClickException(f"the report module is not available ({e})") from None

    folder = Path(out)
    try:  # before any section runs: one line naming --out, not a raw errno at the end
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise ParameterError(f"--out {out}: cannot create the folder "
                             f"({e.strerror or type(e).__name__})") from None
    report_error = getattr(report, "ReportError", ())
    extra = {"full": True} if full else {}  # only when asked: older report.reproduce lacks it
    try:
        index = report.reproduce(Path(out), quick=quick, **extra)
    except report_error as e:  # some sections failed; the page was still written
        click.echo(str(e.path))
        raise click.ClickException(str(e)) from None  # exit code 1
    click.echo(str(index))


__all__ = ["reproduce_cmd"]
