"""The small Markdown subset of ``docs/*.md`` as reStructuredText (no MyST needed).

Handles what ``docs/architecture.md`` and ``docs/cluster.md`` use: ATX headings, paragraphs,
``-``/``*``/numbered lists (nested by indentation), fenced code blocks (also inside list
items), pipe tables, inline code, bold, emphasis and links. Anything else passes through
as text. ``conf.py`` calls :func:`convert` at every build, so the Markdown stays the one
source.
"""

from __future__ import annotations

import re

_HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
_FENCE = re.compile(r"^(\s*)```\s*([\w+-]*)\s*$")
_BULLET = re.compile(r"^(\s*)([-*]|\d+\.)\s+(.*)$")
_TABLE_SEP = re.compile(r"^\s*\|?\s*:?-{3,}:?\s*(\|\s*:?-{3,}:?\s*)*\|?\s*$")
_UNDERLINES = "=-~^\"'"


def _link(m: re.Match) -> str:
    """[text](target) -> an RST link; in-page anchors keep the text, sibling .md a :doc:."""
    label, target = m.group(1), m.group(2)
    if target.startswith("#"):
        return label
    if target.endswith(".md"):
        return f":doc:`{label} <{target.rsplit('/', 1)[-1][:-3]}>`"
    return f"`{label} <{target}>`__"


def _inline(text: str) -> str:
    """Inline Markdown -> RST: code, links (code is protected); may span lines."""
    parts = re.split(r"(`+[^`]+?`+)", text)
    out: list[str] = []
    for k, part in enumerate(parts):
        if k % 2 == 0:
            out.append(re.sub(r"\[([^\]]+)\]\(([^)]+)\)", _link, part))
            continue
        code = " ".join(part.strip("`").split())
        rst = f"``{code}``"
        before = out[-1][-1:] if out and out[-1] else ""
        after = parts[k + 1][:1] if k + 1 < len(parts) else ""
        if before and not (before.isspace() or before in "([{<'\"/-:"):
            rst = "\\ " + rst
        if after and not (after.isspace() or after in ")]}>'\".,;:!?/-"):
            rst = rst + "\\ "
        out.append(rst)
    return "".join(out)


def _table(rows: list[str]) -> list[str]:
    """A pipe table -> a ``list-table`` (header row first)."""
    cells = [[c.strip() for c in r.strip().strip("|").split("|")] for r in rows
             if not _TABLE_SEP.match(r)]
    n = max(len(c) for c in cells)
    lines = [".. list-table::", "   :header-rows: 1", ""]
    for row in cells:
        row = row + [""] * (n - len(row))
        for j, c in enumerate(row):
            lead = "   * - " if j == 0 else "     - "
            lines.append(lead + (_inline(c) if c else ""))
    lines.append("")
    return lines


def convert(md: str) -> str:
    """Convert the Markdown text ``md`` to reStructuredText."""
    src = md.splitlines()
    out: list[str] = []
    levels: dict[int, str] = {}
    i = 0
    list_indent: list[int] = []        # markdown indents of the open list items
    rst_indent: list[int] = []         # their RST content indents

    def indent_for(md_indent: int) -> int:
        while list_indent and md_indent < list_indent[-1]:
            list_indent.pop()
            rst_indent.pop()
        return rst_indent[-1] if rst_indent else 0

    while i < len(src):
        line = src[i]
        if not line.strip():
            out.append("")
            i += 1
            continue
        m = _FENCE.match(line)
        if m:
            md_ind = len(m.group(1))
            lang = m.group(2) or "text"
            ind = " " * (indent_for(md_ind) if md_ind else 0)
            if not md_ind:
                list_indent.clear()
                rst_indent.clear()
            body = []
            i += 1
            while i < len(src) and not re.match(r"^\s*```\s*$", src[i]):
                body.append(src[i][md_ind:] if src[i][:md_ind].strip() == "" else src[i])
                i += 1
            i += 1
            out += ["", f"{ind}.. code-block:: {lang}", ""]
            out += [f"{ind}   {b}" if b.strip() else "" for b in body]
            out.append("")
            continue
        m = _HEADING.match(line)
        if m:
            list_indent.clear()
            rst_indent.clear()
            depth = min(len(m.group(1)), max(levels, default=0) + 1)
            for deeper in [d for d in levels if d > depth]:
                del levels[deeper]
            if depth not in levels:
                levels[depth] = _UNDERLINES[depth - 1]
            title = _inline(m.group(2)).replace("\\ ", "")
            out += ["", title, levels[depth] * max(len(title), 3), ""]
            i += 1
            continue
        if line.lstrip().startswith("|") and i + 1 < len(src) and _TABLE_SEP.match(src[i + 1]):
            rows = []
            while i < len(src) and src[i].lstrip().startswith("|"):
                rows.append(src[i])
                i += 1
            out += [""] + _table(rows)
            continue
        m = _BULLET.match(line)
        if m:
            md_ind = len(m.group(1))
            base = indent_for(md_ind)
            if not list_indent or md_ind > list_indent[-1]:
                if list_indent:
                    out.append("")
            marker = "-" if m.group(2) in "-*" else "#."
            cont = md_ind + len(m.group(2)) + 1
            list_indent.append(cont)
            rst_indent.append(base + len(marker) + 1)
            # the item's own continuation lines
            raw = [m.group(3)]
            i += 1
            while (i < len(src) and src[i].strip() and not _BULLET.match(src[i])
                   and not _FENCE.match(src[i])):
                raw.append(src[i].strip())
                i += 1
            first, *rest = _inline("\n".join(raw)).split("\n")
            out.append(" " * base + f"{marker} " + first)
            out += [" " * rst_indent[-1] + r for r in rest]
            # a sibling at the same markdown indent closes this item
            if i < len(src) and _BULLET.match(src[i]):
                nxt = len(_BULLET.match(src[i]).group(1))
                if nxt <= md_ind:
                    list_indent.pop()
                    rst_indent.pop()
                    if nxt < md_ind:
                        out.append("")
            continue
        # a paragraph (possibly inside a list item)
        md_ind = len(line) - len(line.lstrip())
        ind = indent_for(md_ind) if md_ind else 0
        if not md_ind:
            list_indent.clear()
            rst_indent.clear()
        raw = []
        while i < len(src) and src[i].strip() and not _FENCE.match(src[i]) \
                and not _HEADING.match(src[i]) and not _BULLET.match(src[i]):
            raw.append(src[i].strip())
            i += 1
        out += [" " * ind + r for r in _inline("\n".join(raw)).split("\n")]
        out.append("")
    text = "\n".join(out)
    text = re.sub(r"\n{3,}", "\n\n", text).strip("\n") + "\n"
    return text
