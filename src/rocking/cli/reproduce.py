"""``rocking reproduce``: the paper's tables and figures into ``OUT/index.html``.

::

    rocking reproduce --out results [--quick] [--full] [--jobs N]
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import click

from ..errors import ParameterError
from .common import CONTEXT


@dataclasses.dataclass(frozen=True)
class ReproduceRequest:
    """``rocking reproduce``'s options (:meth:`from_options`): the report's folder and how
    much to run."""

    out: str
    quick: bool
    full: bool
    jobs: int | None = None

    @classmethod
    def from_options(cls, *, out, quick, full, jobs=None):
        """The request of the command's options (click's values)."""
        if jobs is not None and jobs < 1:
            raise ParameterError(f"--jobs must be an integer >= 1, got {jobs}")
        return cls(out=out, quick=quick, full=full, jobs=jobs)

    @property
    def folder(self) -> Path:
        """The report's folder."""
        return Path(self.out)

    def make_folder(self) -> None:
        """Create the folder before any section runs: one line naming ``--out``, not a raw
        errno at the end."""
        try:
            self.folder.mkdir(parents=True, exist_ok=True)
        except OSError as e:
            raise ParameterError(f"--out {self.out}: cannot create the folder "
                                 f"({e.strerror or type(e).__name__})") from None


@click.command("reproduce", context_settings=CONTEXT)
@click.option("--out", default="results", show_default=True, type=click.Path(file_okay=False),
              help="Output folder of the report.")
@click.option("--quick", is_flag=True, help="Fewer, shorter simulations (for a smoke test).")
@click.option("--full", is_flag=True, help="Also the slow sections.")
@click.option("--jobs", type=int, default=None,
              help="Sections built at once, each in a worker process  [default: one per "
                   "core]; 1 builds them one after the other. The report is the same.")
def reproduce_cmd(**options):
    """Reproduce the paper's tables and figures into OUT/index.html."""
    req = ReproduceRequest.from_options(**options)
    try:  # lazy: the report imports matplotlib, pandas and every model
        from .. import report
    except ImportError as e:
        raise click.ClickException(f"the report module is not available ({e})") from None

    req.make_folder()
    report_error = getattr(report, "ReportError", ())
    # only when asked: an older report.reproduce lacks it
    extra = {"full": True} if req.full else {}
    if req.jobs is not None:
        extra["jobs"] = req.jobs
    try:
        index = report.reproduce(req.folder, quick=req.quick, **extra)
    except report_error as e:  # some sections failed; the page was still written
        click.echo(str(e.path))
        raise click.ClickException(str(e)) from None  # exit code 1
    click.echo(str(index))


__all__ = ["reproduce_cmd"]
