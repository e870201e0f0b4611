"""``rocking verify``: the verification manual (:mod:`rocking.verification`, issue 22).

::

    rocking verify                      # every case: the table, exit 0 iff all pass
    rocking verify housner-free-period zhang-makris-one-sine
    rocking verify --quick              # without the slow cases
    rocking verify --json               # one object per case, and the summary
    rocking verify --markdown FILE      # the table and each case's source and derivation
    rocking verify --list               # the case names, their group and what they check

Prints one row per case: case, source, what the reference is (printed, equation,
textbook, derived, cross-check: ``rocking.verification.REFERENCE_KINDS``), reference
value, computed value, unit, tolerance, and PASS, KNOWN (the case disagrees with its
source for a documented reason, within a documented bound) or FAIL, then the notes (why
a case fails, or its documented difference). Exit code 0 when no case fails, 1 when one
does (a failing verification is not bad input), 2 for an unknown case name (one line
``error: ...`` listing the known names).
"""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import click

from .common import CONTEXT, json_default


@dataclasses.dataclass(frozen=True)
class VerifyRequest:
    """``rocking verify``'s options, read and checked (:meth:`from_options`): the cases
    selected and what to print or write."""

    cases: tuple
    """The :class:`rocking.verification` cases selected (all by default)."""
    as_json: bool
    markdown: Path | None
    list_only: bool

    @classmethod
    def from_options(cls, *, cases, quick, as_json, markdown, list_only):
        """The request of the command's options (click's values); an unknown case name is
        a :class:`~rocking.errors.ParameterError` (exit code 2)."""
        from ..verification import get_cases

        selected = get_cases(list(cases), quick)
        return cls(cases=tuple(selected), as_json=as_json, markdown=markdown,
                   list_only=list_only)


@click.command("verify", context_settings=CONTEXT)
@click.argument("cases", nargs=-1)
@click.option("--quick", is_flag=True, help="Leave out the slow cases (the DEM).")
@click.option("--json", "as_json", is_flag=True,
              help="Print JSON: {'passed': ..., 'n_cases': ..., 'n_failed': ..., 'cases': "
                   "[one object per case, with its 'status']}.")
@click.option("--markdown", "markdown", type=click.Path(dir_okay=False, path_type=Path),
              default=None, help="Also write the table and each case's source and "
                                 "derivation as Markdown to this file.")
@click.option("--list", "list_only", is_flag=True,
              help="List the cases (name, group, what) without running them.")
def verify_cmd(**options):
    """Run the verification cases and print the table: case, source, what the reference
    is (printed, equation, textbook, derived, cross-check), reference value, computed
    value, tolerance, pass (PASS; KNOWN: a disagreement with a documented reason
    and bound, not a failure; FAIL). Exit code 1 if any case fails.

    CASES: names of cases to run (all by default; see --list).
    """
    from ..verification import run_cases

    req = VerifyRequest.from_options(**options)  # an unknown name: ParameterError, exit 2
    selected, markdown = req.cases, req.markdown
    if req.list_only:
        if req.as_json:
            click.echo(json.dumps([{"case": c.name, "group": c.group, "source": c.source,
                                    "what": c.what, "slow": c.slow} for c in selected],
                                  indent=2))
        else:
            width = max(len(c.name) for c in selected)
            for c in selected:
                click.echo(f"{c.name.ljust(width)}  {c.group:<12} {c.what}")
        return 0
    table = run_cases([c.name for c in selected])
    if markdown is not None:
        markdown.parent.mkdir(parents=True, exist_ok=True)
        markdown.write_text(table.to_markdown())
    if req.as_json:
        click.echo(json.dumps({"passed": table.passed, "n_cases": len(table.rows),
                               "n_failed": len(table.failed), "cases": table.to_dicts()},
                              indent=2, default=json_default))
    else:
        click.echo(table.to_text())
    return 0 if table.passed else 1


__all__ = ["verify_cmd"]
