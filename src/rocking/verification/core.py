"""The verification manual's machinery: a :class:`Case` (a number from the literature or a
closed form, and how we compute the same number), its evaluation into a :class:`Row`, and
the :class:`VerificationTable` that ``rocking verify`` prints.

A case never has its reference tuned to our output: the reference is a closed form (with
the equation it comes from) or a value quoted from a paper (with its page), and a case
whose computed value disagrees is shown as disagreeing (``known_difference`` says why, when
the reason is documented); it is not adjusted until it passes.
"""

from __future__ import annotations

import math
import re
import textwrap
import time
from collections.abc import Callable
from dataclasses import dataclass, field

TOLERANCE_KINDS = ("rel", "abs", "below")
"""``rel``: pass iff ``|computed - reference| <= tolerance * |reference|``; ``abs``: iff
``|computed - reference| <= tolerance``; ``below``: a bound, not a value: pass iff
``reference - tolerance <= computed < reference``."""

REFERENCE_KINDS = {
    "printed": "a value printed in the source, quoted as printed",
    "equation": ("an equation as printed in a source read for this project (the case's "
                 "own, or Pena et al. 2007 where it quotes it), evaluated here"),
    "textbook": "a textbook closed form, evaluated here",
    "derived": ("a closed form derived here from the source's model; the source's own "
                "printed numbers could not be read, so they are not compared"),
    "cross-check": ("another computation of the package, independent of the one checked "
                    "(another model, or the response spectrum)"),
}
"""What a case's reference value is (:attr:`Case.reference_kind`), as the tables say."""


@dataclass(frozen=True)
class Case:
    """One verification case.

    Attributes
    ----------
    name : str
        Short identifier (``rocking verify NAME``).
    source : str
        Full citation of the paper (or textbook) the reference comes from.
    what : str
        One line: the quantity compared.
    how : str
        How the reference number was obtained: the closed form and its equation (derived
        here when the paper's own text could not be read), or the value quoted from a table
        or figure of the paper with its page.
    reference : Callable[[], float]
        The reference value (a closed form evaluated here, or a quoted constant).
    compute : Callable[[], float]
        Our value: runs the package (models, motions, analysis, buildings, shapes).
    unit : str
        Unit of both values ("-" for a ratio).
    tolerance : float
        Allowed difference, of kind ``tolerance_kind`` (:data:`TOLERANCE_KINDS`).
    tolerance_kind : str
        ``"rel"``, ``"abs"`` or ``"below"`` (a bound).
    group : str
        The part of the package it checks (``classical``, ``pulses``, ``similarity``,
        ``cross-model``, ``buildings``, ``isolation``, ``shapes``).
    known_difference : str
        Why the case disagrees with the literature, when it does for a documented reason
        (empty when it should agree).
    known_tolerance : float or None
        With ``known_difference``: the documented size of the disagreement (same kind as
        ``tolerance``). A case outside ``tolerance`` but inside ``known_tolerance`` is
        shown as ``KNOWN`` (disagreeing, for the stated reason) and does not fail the
        table; outside it, it fails.
    slow : bool
        Left out by ``quick=True``.
    reference_kind : str
        What the reference is (:data:`REFERENCE_KINDS`): ``printed``, ``equation``,
        ``textbook``, ``derived`` (the default) or ``cross-check``.

    Examples
    --------
    A case whose reference is a closed form (here ``cosh(1)``) and whose computation agrees
    with it; evaluated by :meth:`run` into a :class:`Row`:

    >>> import math
    >>> from rocking.verification import Case
    >>> c = Case(name="cosh-1", source="Abramowitz, M. and Stegun, I. A. (1964). Handbook "
    ...          "of Mathematical Functions.", what="cosh(1)", how="Eq 4.5.1, "
    ...          "(e + 1/e)/2, against math.cosh", reference=lambda: (math.e + 1 / math.e) / 2,
    ...          compute=lambda: math.cosh(1.0), tolerance=1e-12)
    >>> c.run().status
    'PASS'
    >>> c.tolerance_text
    'rel 1e-12'
    """

    name: str
    source: str
    what: str
    how: str
    reference: Callable[[], float]
    compute: Callable[[], float]
    unit: str = "-"
    tolerance: float = 1e-6
    tolerance_kind: str = "rel"
    group: str = ""
    known_difference: str = ""
    known_tolerance: float | None = None
    slow: bool = False
    reference_kind: str = "derived"

    def __post_init__(self):
        if self.tolerance_kind not in TOLERANCE_KINDS:
            raise ValueError(f"tolerance_kind must be one of {TOLERANCE_KINDS}")
        if self.reference_kind not in REFERENCE_KINDS:
            raise ValueError(f"reference_kind must be one of {tuple(REFERENCE_KINDS)}")
        if self.known_tolerance is not None and not (
                self.known_difference and self.tolerance_kind != "below"
                and self.known_tolerance > self.tolerance):
            raise ValueError("known_tolerance needs a known_difference, a value tolerance "
                             "(rel or abs) and must exceed the tolerance")

    @property
    def tolerance_text(self) -> str:
        """The tolerance as shown in the table: ``rel 1e-06`` or ``abs 1e-09 rad``."""
        if self.tolerance_kind == "below":
            return f"in [ref-{self.tolerance:g}, ref)"
        unit = "" if self.tolerance_kind == "rel" or self.unit == "-" else f" {self.unit}"
        return f"{self.tolerance_kind} {self.tolerance:.3g}{unit}"

    @property
    def known_tolerance_text(self) -> str:
        """The documented difference's bound as shown (empty when there is none)."""
        if self.known_tolerance is None:
            return ""
        unit = "" if self.tolerance_kind == "rel" or self.unit == "-" else f" {self.unit}"
        return f"{self.tolerance_kind} {self.known_tolerance:.3g}{unit}"

    def passes(self, reference: float, computed: float, tolerance: float | None = None
               ) -> bool:
        """Whether ``computed`` agrees with ``reference`` within the tolerance (or the
        given one; NaN fails), by the rule of ``tolerance_kind`` (:data:`TOLERANCE_KINDS`).

        Examples
        --------
        Table II's alpha of specimen 1 is printed to 3 decimals (abs 0.0005 rad); Eq 2 on
        Table I's 0.25 m x 1.0 m gives atan(0.25) = 0.2450 rad, within the documented
        ``known_tolerance`` only:

        >>> import math
        >>> from rocking.verification import get_cases
        >>> c = get_cases(["pena-table2-specimen1-alpha"])[0]
        >>> eq2 = math.atan(0.125 / 0.5)
        >>> c.passes(0.242, 0.2424), c.passes(0.242, eq2), c.passes(0.242, eq2, c.known_tolerance)
        (True, False, True)
        >>> c.passes(0.242, math.nan)
        False
        """
        tol = self.tolerance if tolerance is None else tolerance
        if not (math.isfinite(reference) and math.isfinite(computed)):
            return False
        if self.tolerance_kind == "below":
            return reference - tol <= computed < reference
        bound = tol * (abs(reference) if self.tolerance_kind == "rel" else 1.0)
        return abs(computed - reference) <= bound

    def status(self, reference: float, computed: float) -> str:
        """``PASS`` (within the tolerance), ``KNOWN`` (outside it, inside the documented
        ``known_tolerance``) or ``FAIL``.

        Examples
        --------
        Table II's alpha of specimen 1 (0.242 rad, abs 0.0005 rad; documented bound 0.004):

        >>> from rocking.verification import get_cases
        >>> c = get_cases(["pena-table2-specimen1-alpha"])[0]
        >>> [c.status(0.242, x) for x in (0.2424, 0.245, 0.25)]
        ['PASS', 'KNOWN', 'FAIL']
        """
        if self.passes(reference, computed):
            return "PASS"
        if self.known_tolerance is not None and self.passes(reference, computed,
                                                            self.known_tolerance):
            return "KNOWN"
        return "FAIL"

    def run(self) -> Row:
        """Evaluate the case: an error while computing is a failing row with its message,
        never an exception.

        Examples
        --------
        >>> import dataclasses
        >>> from rocking.verification import get_cases
        >>> c = get_cases(["pena-table2-specimen2-alpha"])[0]
        >>> row = c.run()
        >>> row.status, row.reference, round(row.computed, 4)
        ('PASS', 0.168, 0.1684)
        >>> broken = dataclasses.replace(c, compute=lambda: 1 / 0).run()
        >>> broken.status, broken.note
        ('FAIL', 'computation failed: ZeroDivisionError: division by zero')
        """
        t0 = time.perf_counter()
        note = ""
        try:
            ref = float(self.reference())
        except Exception as e:  # a broken reference is a failing row too
            ref, note = math.nan, f"reference failed: {type(e).__name__}: {e}"
        try:
            val = float(self.compute())
        except Exception as e:
            val, note = math.nan, f"computation failed: {type(e).__name__}: {e}"
        status = self.status(ref, val)
        if status == "KNOWN":
            note = f"disagrees as documented: {self.known_difference}"
        elif status == "FAIL" and not note:
            note = ("disagrees beyond the documented difference"
                    if self.known_tolerance is not None else "disagrees beyond the tolerance")
            if self.known_difference:
                note += f" ({self.known_difference})"
        return Row(case=self, reference=ref, computed=val, status=status, note=note,
                   seconds=time.perf_counter() - t0)


@dataclass(frozen=True)
class Row:
    """One evaluated case: its reference and computed values, its status (``PASS``,
    ``KNOWN`` or ``FAIL``) and a note saying why it disagrees, when it does.

    Examples
    --------
    >>> from rocking.verification import Case
    >>> c = Case(name="one", source="Nobody, A. (2000). Nothing.", what="one",
    ...          how="a constant against a wrong constant", reference=lambda: 1.0,
    ...          compute=lambda: 1.1, tolerance=0.01)
    >>> row = c.run()
    >>> row.status, row.passed, round(row.difference, 6)
    ('FAIL', False, 0.1)
    >>> row.note
    'disagrees beyond the tolerance'
    """

    case: Case
    reference: float
    computed: float
    status: str
    note: str = ""
    seconds: float = 0.0

    @property
    def passed(self) -> bool:
        """Not a failure: ``PASS``, or ``KNOWN`` (a documented disagreement)."""
        return self.status != "FAIL"

    @property
    def difference(self) -> float:
        """``computed - reference`` (relative to ``|reference|`` for a relative
        tolerance)."""
        d = self.computed - self.reference
        if self.case.tolerance_kind == "rel" and self.reference != 0.0:
            return d / abs(self.reference)
        return d

    def to_dict(self) -> dict:
        """JSON-ready (NaN as None): the case's description, both values, the tolerance,
        the status and the note.

        Examples
        --------
        >>> import dataclasses, json
        >>> from rocking.verification import get_cases
        >>> row = get_cases(["pena-table2-specimen1-alpha"])[0].run()
        >>> d = row.to_dict()
        >>> d["case"], d["status"], d["reference"], round(d["difference"], 4)
        ('pena-table2-specimen1-alpha', 'KNOWN', 0.242, 0.003)
        >>> d = dataclasses.replace(row, computed=float("nan")).to_dict()
        >>> d["computed"], json.loads(json.dumps(d, allow_nan=False))["difference"]
        (None, None)
        """
        def num(x):
            return None if not math.isfinite(x) else x

        c = self.case
        return {"case": c.name, "group": c.group, "source": c.source, "what": c.what,
                "how": c.how, "reference_kind": c.reference_kind,
                "reference": num(self.reference), "computed": num(self.computed),
                "unit": c.unit, "tolerance": c.tolerance, "tolerance_kind": c.tolerance_kind,
                "difference": num(self.difference), "status": self.status,
                "passed": self.passed, "note": self.note,
                "known_difference": c.known_difference,
                "known_tolerance": c.known_tolerance, "seconds": self.seconds}


def short_source(source: str) -> str:
    """``Surname (year)``, ``Surname and Surname (year)`` or ``Surname et al. (year)`` of a
    citation written ``Surname, I., ... (year). Title...``; the text up to the first
    closing parenthesis if it is not written so."""
    i = source.find(")")
    head = source[: i + 1] if i > 0 else source
    j = head.find(" (")
    names = re.findall(r"([A-Z][\w'-]+(?: [A-Z][\w'-]+)*), (?:[A-Z]\.[ -]?)+", head[:j])
    if j < 0 or not names:
        return head
    year = head[j:]
    if len(names) == 1:
        return names[0] + year
    if len(names) == 2:
        return f"{names[0]} and {names[1]}{year}"
    return f"{names[0]} et al.{year}"


def _fmt(x: float) -> str:
    return "nan" if not math.isfinite(x) else f"{x:.10g}"


def _sentence(text: str) -> str:
    """``text`` with a capital first letter and a final full stop."""
    text = text.strip()
    return text[:1].upper() + text[1:] + ("" if text.endswith(".") else ".")


def _md(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


@dataclass
class VerificationTable:
    """The evaluated cases, in catalog order (what :func:`rocking.verification.run_cases`
    returns): ``passed``, ``failed``, and the table as text, Markdown, reStructuredText,
    dicts or a DataFrame.

    Examples
    --------
    >>> from rocking.verification import run_cases
    >>> table = run_cases(["housner-free-period"])
    >>> table.passed, len(table.rows), table.failed
    (True, 1, [])
    >>> print(table.to_text().splitlines()[-1])
    1 of 1 cases pass.
    """

    rows: list[Row] = field(default_factory=list)

    @property
    def passed(self) -> bool:
        """True iff no case failed (``PASS`` or ``KNOWN``; an empty table: False)."""
        return bool(self.rows) and all(r.passed for r in self.rows)

    @property
    def failed(self) -> list[Row]:
        return [r for r in self.rows if not r.passed]

    def to_dicts(self) -> list[dict]:
        """One :meth:`Row.to_dict` per case, in order (JSON-ready: ``rocking verify --json``).

        Examples
        --------
        >>> from rocking.verification import run_cases
        >>> table = run_cases(["pena-table2-specimen1-alpha", "pena-table2-specimen2-alpha"])
        >>> [(d["case"], d["status"]) for d in table.to_dicts()]
        [('pena-table2-specimen1-alpha', 'KNOWN'), ('pena-table2-specimen2-alpha', 'PASS')]
        """
        return [r.to_dict() for r in self.rows]

    def to_dataframe(self):
        """A :class:`pandas.DataFrame`, one row per case (the keys of :meth:`Row.to_dict`).

        Examples
        --------
        >>> from rocking.verification import run_cases
        >>> table = run_cases(["pena-table2-specimen1-alpha", "pena-table2-specimen2-alpha"])
        >>> df = table.to_dataframe()
        >>> df[["case", "status", "reference"]]
                                  case status  reference
        0  pena-table2-specimen1-alpha  KNOWN      0.242
        1  pena-table2-specimen2-alpha   PASS      0.168
        >>> list(df.columns) == list(table.rows[0].to_dict())
        True
        """
        import pandas as pd

        return pd.DataFrame(self.to_dicts())

    def to_text(self) -> str:
        """The plain-text table of ``rocking verify``: case, source, reference, computed,
        unit, tolerance, pass (PASS, KNOWN: a documented disagreement, or FAIL); the notes
        of the failing and the known-difference cases below it.

        Examples
        --------
        >>> from rocking.verification import run_cases
        >>> table = run_cases(["pena-table2-specimen1-alpha", "pena-table2-specimen2-alpha"])
        >>> lines = table.to_text().splitlines()
        >>> print(lines[0])
        case                         source              reference is  reference  computed  ...
        >>> print(lines[lines.index("Reference is:") + 1])  # what the references are
          printed: a value printed in the source, quoted as printed.
        >>> print(next(x for x in lines if "cases pass" in x))
        1 of 2 cases pass; 1 KNOWN (documented disagreements).
        """
        head = ("case", "source", "reference is", "reference", "computed", "unit",
                "tolerance", "pass")
        body = [(r.case.name, short_source(r.case.source), r.case.reference_kind,
                 _fmt(r.reference),
                 _fmt(r.computed), r.case.unit, r.case.tolerance_text, r.status)
                for r in self.rows]
        widths = [max(len(h), *(len(b[i]) for b in body)) if body else len(h)
                  for i, h in enumerate(head)]
        lines = ["  ".join(h.ljust(w) for h, w in zip(head, widths, strict=True)).rstrip(),
                 "  ".join("-" * w for w in widths)]
        lines += ["  ".join(c.ljust(w) for c, w in zip(b, widths, strict=True)).rstrip()
                  for b in body]
        kinds = dict.fromkeys(r.case.reference_kind for r in self.rows)
        if kinds:
            lines += ["", "Reference is:"]
            for k in kinds:
                lines.extend(textwrap.wrap(f"{k}: {REFERENCE_KINDS[k]}.", width=100,
                                           initial_indent="  ", subsequent_indent="      "))
        n_fail = len(self.failed)
        n_known = sum(r.status == "KNOWN" for r in self.rows)
        lines.append("")
        lines.append(f"{len(self.rows) - n_fail - n_known} of {len(self.rows)} cases pass"
                     + (f"; {n_known} KNOWN (documented disagreements)" if n_known else "")
                     + (f"; {n_fail} FAIL" if n_fail else "") + ".")
        for r in self.rows:
            if r.note:
                lines.extend(textwrap.wrap(f"{r.case.name}: {r.note}", width=100,
                                           initial_indent="  ", subsequent_indent="      "))
        return "\n".join(lines)

    def to_markdown(self, details: bool = True) -> str:
        """A Markdown table (case, source, what, reference, computed, unit, tolerance,
        pass), followed, with ``details``, by one paragraph per case: its full source and
        how the reference was obtained. Used for the documentation's verification page.

        Examples
        --------
        >>> from rocking.verification import run_cases
        >>> table = run_cases(["pena-table2-specimen1-alpha", "pena-table2-specimen2-alpha"])
        >>> lines = table.to_markdown(details=False).splitlines()
        >>> print(lines[0])
        | case | source | what | reference is | reference | computed | unit | tolerance | pass |
        >>> len(lines), lines[2].endswith("| KNOWN |"), lines[3].endswith("| PASS |")
        (4, True, True)
        """
        lines = ["| case | source | what | reference is | reference | computed | unit | "
                 "tolerance | pass |", "|---|---|---|---|---|---|---|---|---|"]
        for r in self.rows:
            c = r.case
            lines.append(f"| `{c.name}` | {_md(short_source(c.source))} | {_md(c.what)} | "
                         f"{c.reference_kind} | {_fmt(r.reference)} | {_fmt(r.computed)} | "
                         f"{c.unit} | "
                         f"{c.tolerance_text} | "
                         f"{'**FAIL**' if r.status == 'FAIL' else r.status} |")
        if details:
            lines.append("")
            for r in self.rows:
                c = r.case
                lines.append(f"**`{c.name}`** ({c.group}). {_md(_sentence(c.what))}  ")
                lines.append(f"*Source*: {_md(c.source)}  ")
                lines.append(f"*Reference* ({c.reference_kind}: "
                             f"{_md(REFERENCE_KINDS[c.reference_kind])}): {_md(c.how)}"
                             + (f"  \n*Known difference*: {_md(c.known_difference)}"
                                + (f" (documented bound: {c.known_tolerance_text})"
                                   if c.known_tolerance is not None else "")
                                if c.known_difference else "")
                             + (f"  \n*Note*: {_md(r.note)}" if r.note and not r.passed
                                else ""))
                lines.append("")
        return "\n".join(lines).rstrip() + "\n"

    def to_rst(self, details: bool = True) -> str:
        """The same as :meth:`to_markdown` in reStructuredText: a ``list-table``, then, with
        ``details``, one definition per case (source, reference, known difference).

        Examples
        --------
        >>> from rocking.verification import run_cases
        >>> table = run_cases(["pena-table2-specimen1-alpha", "pena-table2-specimen2-alpha"])
        >>> lines = table.to_rst(details=False).splitlines()
        >>> lines[:2], lines[5:7]
        (['.. list-table::', '   :header-rows: 1'], ['   * - case', '     - source'])
        >>> ".. _verify-pena-table2-specimen2-alpha:" in table.to_rst()
        True
        """
        cols = ("case", "source", "reference is", "reference", "computed", "unit",
                "tolerance", "pass")
        lines = [".. list-table::", "   :header-rows: 1", "   :widths: auto",
                 "   :class: verification-table", ""]
        lines.append("   * - " + "\n     - ".join(cols))
        for r in self.rows:
            c = r.case
            name = f"`{c.name} <verify-{c.name}_>`_" if details else f"``{c.name}``"
            cells = [name] + [_rst(x) for x in (
                short_source(c.source), c.reference_kind, _fmt(r.reference),
                _fmt(r.computed),
                c.unit if c.unit.strip() not in ("", "-") else "\u2014",
                c.tolerance_text)] + [f"**{r.status}**" if r.status == "FAIL" else r.status]
            lines.append("   * - " + "\n     - ".join(cells))
        if details:  # one section per group, one subsection per case (the page's contents)
            groups: dict[str, list] = {}
            for r in self.rows:
                groups.setdefault(r.case.group, []).append(r)
            for group, rows in groups.items():
                title = GROUP_TITLES.get(group, str(group).capitalize())
                lines += ["", title, "-" * len(title)]
                for r in rows:
                    c = r.case
                    head = f"``{c.name}``"
                    u = "" if c.unit.strip() in ("", "-") else " " + _rst(c.unit)
                    lines += ["", f".. _verify-{c.name}:", "", head, "~" * len(head), ""]
                    body = [f"**{r.status}**. {_rst(_sentence(c.what))}",
                            f"*Source*: {_rst(c.source)}",
                            f"*Reference* ({c.reference_kind}: "
                            f"{_rst(REFERENCE_KINDS[c.reference_kind])}): {_rst(c.how)}",
                            f"*Reference value*: {_rst(_fmt(r.reference))}{u}; "
                            f"*computed*: {_rst(_fmt(r.computed))}{u}; "
                            f"*tolerance*: {_rst(c.tolerance_text)}"]
                    if c.known_difference:
                        bound = (f" (documented bound: {c.known_tolerance_text})"
                                 if c.known_tolerance is not None else "")
                        body.append(f"*Known difference*: {_rst(c.known_difference)}{bound}")
                    if r.note and not r.passed:
                        body.append(f"*Note*: {_rst(r.note)}")
                    for b in body:
                        lines += [b, ""]
        return "\n".join(lines).rstrip() + "\n"


GROUP_TITLES = {
    "classical": "Classical model: Housner's closed forms",
    "pulses": "Pulse thresholds",
    "similarity": "Similarity",
    "paper": "Values printed in Peña et al. (2007)",
    "cross-model": "Cross-model checks",
    "buildings": "Buildings",
    "isolation": "Isolation",
    "shapes": "Shapes from meshes",
    "printed": "Thresholds printed in the rocking literature",
    "three-d": "The 3-D rigid body (rigid3d)",
}
"""Section titles of the case groups on the verification page."""


def _rst(text: str) -> str:
    """Plain text safe in reStructuredText: markup characters escaped, one line."""
    text = str(text).replace("\n", " ").replace("\\", "\\\\")
    for ch in ("*", "`", "|", "_"):
        text = text.replace(ch, "\\" + ch)
    return text


__all__ = ["REFERENCE_KINDS", "TOLERANCE_KINDS", "Case", "Row", "VerificationTable", "short_source"]
