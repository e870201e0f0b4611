"""The verification manual (issue 22): cases from the literature and the closed forms of
the package's other parts, each with its source, how its reference number was obtained, our
computed value, its tolerance and whether it passes (``PASS``; ``KNOWN``: a disagreement
with a documented reason and bound; ``FAIL``); ``rocking verify`` prints the table, and the
documentation's verification page is :func:`verification_markdown` (or
:func:`verification_rst`).

>>> from rocking.verification import run_cases
>>> table = run_cases(["housner-free-period"])
>>> table.passed
True
"""

from __future__ import annotations

from ..errors import ParameterError
from .catalog import CASES, IMPACT_CASES, case_names, clear_caches
from .core import REFERENCE_KINDS, TOLERANCE_KINDS, Case, Row, VerificationTable


def get_cases(names=None, quick: bool = False) -> list[Case]:
    """The cases named (all when ``names`` is None or empty), in catalog order; ``quick``
    leaves out the slow ones (only when no names are given). An unknown name raises
    :class:`~rocking.errors.ParameterError` listing the known ones.

    Examples
    --------
    >>> from rocking.verification import get_cases
    >>> [c.name for c in get_cases(["shape-box-p", "housner-free-period"])]
    ['housner-free-period', 'shape-box-p']
    >>> get_cases(["no-such-case"])
    Traceback (most recent call last):
    ...
    rocking.errors.ParameterError: unknown verification case 'no-such-case'; ...
    """
    if not names:
        return [c for c in CASES if not (quick and c.slow)]
    known = case_names()
    unknown = [n for n in names if n not in known]
    if unknown:
        raise ParameterError(f"unknown verification case {', '.join(map(repr, unknown))}; "
                             f"the cases are: {', '.join(known)}")
    wanted = set(names)
    return [c for c in CASES if c.name in wanted]


def run_cases(names=None, quick: bool = False) -> VerificationTable:
    """Run the cases named (all by default; ``quick``: without the slow ones) and return
    their :class:`VerificationTable` (``.passed``, ``.to_dataframe()``,
    ``.to_markdown()``, ``.to_text()``).

    Examples
    --------
    >>> from rocking.verification import run_cases
    >>> table = run_cases(["housner-free-period", "housner-eq1-acceleration"])
    >>> table.passed
    True
    >>> [row.status for row in table.rows]
    ['PASS', 'PASS']
    """
    cases = get_cases(names, quick)
    clear_caches()
    return VerificationTable([c.run() for c in cases])


def verification_markdown(names=None, quick: bool = False, details: bool = True) -> str:
    """The verification manual as Markdown (runs the cases): the table, then each case's
    source and how its reference was obtained (for the documentation's page).

    Examples
    --------
    >>> from rocking.verification import verification_markdown
    >>> md = verification_markdown(["housner-free-period"], details=False)
    >>> print(md.splitlines()[0])
    | case | source | what | reference is | reference | computed | unit | tolerance | pass |
    >>> md.splitlines()[2].endswith("| PASS |")
    True
    """
    return run_cases(names, quick).to_markdown(details=details)


def verification_rst(names=None, quick: bool = False, details: bool = True) -> str:
    """The verification manual as reStructuredText (runs the cases): a ``list-table``, then
    each case's source and how its reference was obtained.

    Examples
    --------
    >>> from rocking.verification import verification_rst
    >>> rst = verification_rst(["housner-free-period"])
    >>> rst.splitlines()[0]
    '.. list-table::'
    >>> ".. _verify-housner-free-period:" in rst
    True
    """
    return run_cases(names, quick).to_rst(details=details)


__all__ = ["CASES", "IMPACT_CASES", "REFERENCE_KINDS", "TOLERANCE_KINDS", "Case", "Row",
           "VerificationTable", "case_names", "get_cases", "run_cases", "verification_markdown",
           "verification_rst"]
