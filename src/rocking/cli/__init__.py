"""The ``rocking`` command line: one module per command group, shared parsing in
:mod:`rocking.cli.common`.

::

    rocking params --specimen 2 [--params theoretical|experimental|geometric] [--json]
    rocking simulate --specimen 2 --params experimental --motion sine --freq 5 --amp 5mm \\
        --duration 25 [--model ccrr --option rtol=1e-9] --out out/
    rocking models [--json]
    rocking motions [KIND] [--json]
    rocking blocks [FORM] [--json]
    rocking buildings [KIND] [--json]
    rocking motion synth|spectrum|show|floor ...
    rocking dem-params --specimen 2
    rocking identify RECORD.csv
    rocking reproduce --out results [--quick] [--full]
    rocking campaign run SPEC.toml --out STORE [--executor dask --dask-local 2]
    rocking campaign status|report STORE
    rocking shape MESH.stl --density 2600 [--up z] [--out DIR] [--json]
    rocking verify [CASE...] [--quick] [--json] [--markdown FILE] [--list]

Modules: :mod:`~rocking.cli.params`, :mod:`~rocking.cli.simulate`,
:mod:`~rocking.cli.models`, :mod:`~rocking.cli.catalog` (``motions``, ``blocks``,
``buildings``),
:mod:`~rocking.cli.motion`, :mod:`~rocking.cli.dem`,
:mod:`~rocking.cli.identify`, :mod:`~rocking.cli.reproduce`,
:mod:`~rocking.cli.campaign`, :mod:`~rocking.cli.shape`, :mod:`~rocking.cli.verify`; each
imports only :mod:`~rocking.cli.common` (and the library), and this module registers them.

Errors: :func:`main` prints bad input -- a :class:`~rocking.errors.RockingError` from the
library or a usage error from click -- as one line ``error: <message>`` on stderr with exit
code 2 (the output guard, :class:`~rocking.errors.OutputTooLargeError`, names
``--dt-out``/``--duration``); a numerical failure on valid input
(:class:`~rocking.errors.SimulationError`) as one line with exit code 1. Never a traceback.
Warnings of the package (:class:`~rocking.errors.PlausibilityWarning`, a
:class:`DeprecationWarning` such as ``--motion one-sine``) are one line ``warning: ...``.
"""

from __future__ import annotations

import functools
import sys
import warnings

import click

from .. import __version__
from .campaign import campaign
from .catalog import blocks_cmd, buildings_cmd, motions_cmd
from .common import CONTEXT, error_report, one_line
from .dem import dem_params
from .hazard import hazard
from .identify import identify
from .models import models_cmd
from .motion import motion
from .params import params_cmd
from .reproduce import reproduce_cmd
from .shape import shape_cmd
from .simulate import simulate_cmd
from .verify import verify_cmd


@click.group(context_settings=CONTEXT)
@click.version_option(__version__, "--version", prog_name="rocking")
def cli():
    """Dynamics of rocking rigid blocks (Pena et al. 2007).

    SI units inside; units are explicit at the edges (--amp 5mm, 0.3g; --freq 5Hz).
    """


for _command in (params_cmd, simulate_cmd, reproduce_cmd, identify, dem_params, motion,
                 models_cmd, motions_cmd, blocks_cmd, buildings_cmd, campaign, shape_cmd,
                 hazard, verify_cmd):
    cli.add_command(_command)

_NO_ARGS_IS_HELP = getattr(click.exceptions, "NoArgsIsHelpError", ())


def _show_warning(message, category, filename, lineno, file=None, line=None, *,
                  shown: set):
    """Our warnings (plausibility, unsettled runs, ...) as one ``warning: ...`` line, each
    once per command (``shown``: the lines printed so far), through ``tqdm.write`` (above
    a campaign's progress bar, not inside it)."""
    text = f"warning: {one_line(str(message))}"
    if text in shown:
        return
    shown.add(text)
    from tqdm.auto import tqdm  # lazy: the command line starts without it

    tqdm.write(text, file=sys.stderr)


def main(argv=None) -> None:
    """Console entry point: run :func:`cli`, turning errors into one ``error: ...`` line.

    Exit codes: 0 success, 2 bad input, 1 a numerical failure or another runtime error,
    130 interrupted (Ctrl-C).
    Exits with ``sys.exit(code)``; ``argv`` defaults to ``sys.argv[1:]``.
    """
    with warnings.catch_warnings():  # restores the filters and showwarning
        warnings.showwarning = functools.partial(_show_warning, shown=set())
        for module in _DEPRECATION_FROM:
            warnings.filterwarnings("default", category=DeprecationWarning, module=module)
        code = _run(argv)
    sys.exit(code)


_DEPRECATION_FROM = ("rocking", "click")
"""Modules whose DeprecationWarnings the command line shows (hidden by default): ours, and
click's frames, where a warning of the package attributed to its first caller outside the
package lands."""


def _run(argv) -> int:
    """:func:`cli` on ``argv``: its exit code, errors printed as one line."""
    try:
        rv = cli.main(args=argv, prog_name="rocking", standalone_mode=False)
        code = rv if isinstance(rv, int) else 0
    except click.exceptions.UsageError as e:
        if isinstance(e, _NO_ARGS_IS_HELP):  # bare `rocking` (click >= 8.2): show help
            click.echo(e.ctx.get_help() if e.ctx else cli.get_help(click.Context(cli)))
            sys.exit(0)
        click.echo(f"error: {one_line(e.format_message())}", err=True)
        code = 2
    except click.exceptions.Abort as e:
        if isinstance(e.__cause__, KeyboardInterrupt):  # Ctrl-C before a command caught it
            click.echo("interrupted", err=True)
            code = 130  # 128 + SIGINT, as a shell reports it
        else:
            click.echo("error: aborted", err=True)
            code = 1
    except click.ClickException as e:
        click.echo(f"error: {one_line(e.format_message())}", err=True)
        code = e.exit_code if e.exit_code else 1
    except MemoryError:
        click.echo("error: out of memory (for simulate: increase --dt-out or shorten "
                   "--duration)", err=True)
        code = 1
    except Exception as e:  # ours (bad input, numerical failure) or an OS error: one line
        report = error_report(e)
        if report is None:
            if not isinstance(e, OSError):
                raise
            report = (one_line(e), 1)
        msg, code = report
        click.echo(f"error: {msg}", err=True)
    return code


__all__ = ["cli", "main"]
