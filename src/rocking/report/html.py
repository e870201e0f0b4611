"""Small HTML builder for the report: escaping, tables, figures, notes, the page itself.

Plain HTML5 with one inline style sheet: no JavaScript, no network resources, so the page
can be opened from disk or attached to an e-mail together with its PNG and CSV files.
Every function returns a string (an HTML fragment).
"""

from __future__ import annotations

import html as _html
import math
from dataclasses import dataclass

CSS = """
body { font-family: -apple-system, "Segoe UI", Helvetica, Arial, sans-serif; max-width: 70rem;
       margin: 1.5rem auto; padding: 0 1rem; color: #222; line-height: 1.45; }
h1 { font-size: 1.6rem; margin-bottom: 0.2rem; }
h2 { font-size: 1.3rem; border-bottom: 2px solid #ccd; padding-bottom: 0.2rem; margin-top: 2.2rem; }
h3 { font-size: 1.05rem; margin-top: 1.4rem; }
.meta { color: #555; font-size: 0.9rem; }
.box { background: #f5f6fa; border-left: 4px solid #8a9ac0; padding: 0.5rem 0.9rem;
       margin: 0.8rem 0; }
.error { background: #fde8e8; border: 2px solid #c62828; color: #7f1010; padding: 0.5rem 0.9rem;
         margin: 0.8rem 0; }
.error pre { white-space: pre-wrap; font-size: 0.8rem; color: #5a0b0b; }
table { border-collapse: collapse; margin: 0.6rem 0; font-size: 0.88rem; }
caption { caption-side: top; text-align: left; font-weight: 600; padding-bottom: 0.3rem; }
th, td { border: 1px solid #c8c8d0; padding: 0.2rem 0.45rem; text-align: right;
         vertical-align: top; }
th { background: #eef0f6; }
td.l, th.l { text-align: left; }
td.c, th.c { text-align: center; }
.small { font-size: 0.8rem; color: #555; }
.ok { background: #e6f4ea; }
.warn { background: #fff4d6; }
.bad { background: #fde2e2; }
.na { color: #999; }
.files a { margin-right: 0.8rem; }
figure { margin: 1rem 0; }
figure img { max-width: 100%; border: 1px solid #ddd; }
figcaption { font-size: 0.88rem; color: #333; }
nav ol { margin-top: 0.2rem; }
.status-ok { color: #2e7d32; }
.status-failed { color: #c62828; font-weight: 600; }
code { background: #f0f0f4; padding: 0 0.2rem; }
"""


def esc(text) -> str:
    """HTML-escape ``text`` (any object, through ``str``)."""
    return _html.escape(str(text), quote=True)


@dataclass(frozen=True)
class Raw:
    """Already-formatted HTML that :func:`table` must not escape."""

    html: str


@dataclass(frozen=True)
class Cell:
    """A table cell with optional CSS class (``ok``, ``warn``, ``bad``, ``l``...) and tooltip."""

    content: object
    cls: str = ""
    title: str = ""


def _content(x) -> str:
    if isinstance(x, Raw):
        return x.html
    return esc(x)


def _cell(tag: str, x) -> str:
    if isinstance(x, Cell):
        attrs = ""
        if x.cls:
            attrs += f' class="{esc(x.cls)}"'
        if x.title:
            attrs += f' title="{esc(x.title)}"'
        return f"<{tag}{attrs}>{_content(x.content)}</{tag}>"
    return f"<{tag}>{_content(x)}</{tag}>"


def table(header, rows, caption: str | None = None, header_rows=None) -> str:
    """An HTML table. ``header``: list of column titles (str, :class:`Cell` or :class:`Raw`);
    ``rows``: list of lists of cells; ``header_rows``: optional extra header rows above."""
    out = ["<table>"]
    if caption:
        out.append(f"<caption>{esc(caption)}</caption>")
    out.append("<thead>")
    for hr in header_rows or []:
        out.append("<tr>" + "".join(_cell("th", h) for h in hr) + "</tr>")
    out.append("<tr>" + "".join(_cell("th", h) for h in header) + "</tr></thead><tbody>")
    for r in rows:
        out.append("<tr>" + "".join(_cell("td", c) for c in r) + "</tr>")
    out.append("</tbody></table>")
    return "\n".join(out)


def p(text: str) -> str:
    """A paragraph of escaped text."""
    return f"<p>{esc(text)}</p>"


def p_raw(html: str) -> str:
    """A paragraph of already-formatted HTML."""
    return f"<p>{html}</p>"


def ul(items, raw: bool = False) -> str:
    """A bullet list of escaped (or raw) items."""
    return "<ul>" + "".join(f"<li>{i if raw else esc(i)}</li>" for i in items) + "</ul>"


def box(html: str) -> str:
    """A shaded note box (raw HTML inside)."""
    return f'<div class="box">{html}</div>'


def error_box(title: str, message: str, tb: str = "") -> str:
    """A red box reporting a failure (with an optional traceback)."""
    pre = f"<pre>{esc(tb)}</pre>" if tb else ""
    return f'<div class="error"><strong>{esc(title)}</strong><br>{esc(message)}{pre}</div>'


def figure(src: str, caption: str, alt: str = "") -> str:
    """A figure with a relative ``src`` (PNG written next to the page) and a caption."""
    return (f'<figure><a href="{esc(src)}"><img src="{esc(src)}" alt="{esc(alt or caption)}">'
            f"</a><figcaption>{esc(caption)}</figcaption></figure>")


def files_line(paths) -> str:
    """``Files: a.csv b.png`` as links (relative paths)."""
    links = " ".join(f'<a href="{esc(x)}">{esc(x)}</a>' for x in paths)
    return f'<p class="small files">Files: {links}</p>'


def fmt(x, nd: int = 3, na: str = "—") -> str:
    """Fixed-point number, or ``na`` for None/NaN."""
    if x is None:
        return na
    try:
        xf = float(x)
    except (TypeError, ValueError):
        return str(x)
    if math.isnan(xf):
        return na
    return f"{xf:.{nd}f}"


def pct(x, nd: int = 1) -> str:
    """Signed percentage, e.g. ``+1.3 %``."""
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "—"
    return f"{float(x):+.{nd}f} %"


def page(title: str, head_html: str, toc_html: str, body_html: str) -> str:
    """The complete HTML document."""
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{esc(title)}</title>
<style>{CSS}</style>
</head>
<body>
<header>
<h1>{esc(title)}</h1>
{head_html}
</header>
<nav>
<h2>Contents</h2>
{toc_html}
</nav>
<main>
{body_html}
</main>
</body>
</html>
"""
