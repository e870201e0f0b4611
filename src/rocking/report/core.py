"""The report machinery: a registry of sections and the page writer.

A *section* is a function ``build(ctx) -> str`` that computes its results, writes its own
files (PNG figures, CSV tables) through the :class:`Context` it receives, and returns an
HTML fragment (without its ``<h2>`` title: the page adds it). Sections are registered with
the :func:`section` decorator and run in increasing ``order``::

    from rocking.report.core import section
    from rocking.report import html as H

    @section("ccrr", "CCRR model vs classical model", order=40)
    def build(ctx):
        df = ...                                   # compute
        csv = ctx.save_csv(df, "summary")          # -> "ccrr_summary.csv"
        fig_html = ctx.save_figure(fig, "theta", caption="...")
        return H.p("...") + H.table(...) + fig_html + ctx.files_html()

and the module (in :mod:`rocking.report.sections`) is added to ``SECTION_MODULES`` in
:mod:`rocking.report` so that it is imported (hence registered) before the page is built.

**Reproducibility.** What a section computes and shows depends only on ``ctx.quick``,
``ctx.full`` and fixed lists, never on measured time: the same command gives the same
sections and numbers on any machine. A part too slow for the default run goes behind
``full`` (``rocking reproduce --full``). Wall-clock times appear only in the provenance
footer of the page and in the progress log. The models a section runs when it means
"every model" come from :data:`rocking.models.MODELS` (:func:`report_models`), drawn
with :func:`model_style` (colours and line styles fixed by registry position).

A section that raises does not stop the report: its place in the page shows the error in
a red box, the other sections still run, the page is written, and only then
:func:`reproduce` raises :class:`ReportError` listing the failed sections.
"""

from __future__ import annotations

import datetime as _dt
import importlib
import os
import platform
import sys
import time
import traceback
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from .. import __version__
from .._atomic import atomic_path, atomic_write
from ..blocks import paper_data
from ..errors import ParameterError
from ..models import MODELS
from . import html as H


@dataclass(frozen=True)
class Section:
    """A registered report section.

    Examples
    --------
    >>> from rocking.report import SECTIONS
    >>> table2 = SECTIONS["table2"]
    >>> table2.id, table2.order
    ('table2', 10.0)
    >>> table2.title
    'Table II — classical parameters α, p, μ'
    """

    id: str
    title: str
    build: Callable[[Context], str]
    order: float = 100.0
    cost: float = 1.0


SECTIONS: dict[str, Section] = {}
"""Registered sections by id (see :func:`section`)."""


def section(id: str, title: str, order: float = 100.0, cost: float = 1.0):
    """Decorator registering ``build(ctx) -> str`` as a report section.

    ``id`` is short and file-name safe (it prefixes the section's files and is the HTML
    anchor); ``title`` is the heading; ``order`` sets the position in the page. ``cost``
    (seconds of the default report on one core, roughly) is a scheduling hint only: with
    several jobs the costliest sections start first (:func:`reproduce`).

    Examples
    --------
    Register a one-line section, build a page with it alone, then unregister it:

    >>> import math
    >>> from rocking.report import SECTIONS, reproduce, section
    >>> @section("hello", "Hello", order=1)
    ... def build(ctx):
    ...     return f"<p>alpha = {math.atan(0.085 / 0.5):.4f} rad</p>"
    >>> try:
    ...     path = reproduce("report", only="hello", progress=False)
    ... finally:
    ...     del SECTIONS["hello"]
    >>> "alpha = 0.1684 rad" in path.read_text()
    True
    """
    if not id.replace("_", "").replace("-", "").isalnum():
        raise ValueError(f"section id must be alphanumeric (with - or _), got {id!r}")

    def deco(fn):
        SECTIONS[id] = Section(id=id, title=title, build=fn, order=float(order),
                               cost=float(cost))
        return fn

    return deco


def ordered_sections() -> list[Section]:
    """The registered sections in page order.

    Examples
    --------
    >>> from rocking.report import ordered_sections
    >>> [s.id for s in ordered_sections()][:4]
    ['table2', 'table3', 'identification', 'table4']
    """
    return sorted(SECTIONS.values(), key=lambda s: (s.order, s.id))


MODEL_COLOURS = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000")
"""Colours of the models in figures, by position in the registry (colour-blind safe)."""
MODEL_LINESTYLES = ("-", "--", "-.", ":")
"""Line styles of the models in figures, by position in the registry."""


@dataclass(frozen=True)
class ModelStyle:
    """How the report names and draws a registered model.

    Examples
    --------
    >>> from rocking.report import model_style
    >>> model_style("ccrr")
    ModelStyle(name='ccrr', label=..., colour='#D55E00', linestyle='--')
    """

    name: str
    label: str
    colour: str
    linestyle: str


def report_models() -> list[str]:
    """Names of every registered planar model of the free-standing block, in registry
    order (:data:`rocking.models.MODELS`; mitigation models, ``Model.mitigation``, are not
    models of the paper's specimens, and a model without a planar angle,
    ``Model.tags["planar"]``, has none of the paper's quantities: both are left out).

    Examples
    --------
    >>> from rocking.models import available
    >>> from rocking.report import report_models
    >>> report_models()
    ['housner', 'ccrr', 'dem']
    >>> sorted(set(available()) - set(report_models()))  # the mitigations, the 3-D body
    ['anchored', 'isolated', 'rigid3d']
    """
    return [name for name, cls in MODELS.items()
            if not cls.mitigation and cls.tags.get("planar")]


def model_style(name: str) -> ModelStyle:
    """Label (the class's ``label``), colour and line style of the registered model
    ``name``; fixed by its position in the registry, hence the same on every run.

    Examples
    --------
    >>> from rocking.report import model_style
    >>> style = model_style("housner")
    >>> style.label, style.colour, style.linestyle
    ('classical (Housner)', '#0072B2', '-')
    """
    names = list(MODELS)
    if name not in MODELS:
        raise KeyError(f"unknown model {name!r}; registered: {names}")
    i = names.index(name)
    return ModelStyle(name=name, label=str(getattr(MODELS[name], "label", name)),
                      colour=MODEL_COLOURS[i % len(MODEL_COLOURS)],
                      linestyle=MODEL_LINESTYLES[i % len(MODEL_LINESTYLES)])


@dataclass
class Context:
    """What a section gets: where to write, how thorough to be, and file helpers.

    ``quick`` asks for a cheaper run (coarser grids, fewer panels, lower resolution) that
    still produces every table and figure; ``full`` adds the parts too slow for the
    default run (for example the DEM in the batches of Table V). Neither depends on the
    machine: a section decides what to run from these flags and fixed lists only. Files
    are named ``<section id>_<name>`` in ``out`` and collected in ``files`` (relative
    names) for :meth:`files_html`.

    Examples
    --------
    >>> from pathlib import Path
    >>> import pandas as pd
    >>> from rocking.report import Context
    >>> ctx = Context(out=Path("."), quick=True, section_id="demo")
    >>> ctx.save_csv(pd.DataFrame({"specimen": [2], "alpha": [0.168]}), "params")
    'demo_params.csv'
    >>> ctx.files, ctx.dpi
    (['demo_params.csv'], 70)
    """

    out: Path
    quick: bool
    section_id: str
    files: list[str] = field(default_factory=list)
    full: bool = False

    @property
    def dpi(self) -> int:
        return 70 if self.quick else 120

    def path(self, name: str) -> Path:
        """Path of this section's file ``name`` in ``out``, prefixed with the section id;
        the name is added to :attr:`files` (once), whether or not the file is written.

        Examples
        --------
        >>> from pathlib import Path
        >>> from rocking.report import Context
        >>> ctx = Context(out=Path("report"), quick=True, section_id="table2")
        >>> ctx.path("notes.txt").as_posix(), ctx.files
        ('report/table2_notes.txt', ['table2_notes.txt'])
        """
        fname = f"{self.section_id}_{name}"
        if fname not in self.files:
            self.files.append(fname)
        return self.out / fname

    def save_csv(self, df, name: str, **kw) -> str:
        """Write a pandas DataFrame as ``<id>_<name>.csv`` (atomically; ``**kw`` go to
        :meth:`pandas.DataFrame.to_csv`, ``index=False`` by default); returns the relative
        name.

        Examples
        --------
        Specimen 2's alpha = atan(0.085/0.5) (Eq 2), written and read back:

        >>> import math
        >>> from pathlib import Path
        >>> import pandas as pd
        >>> from rocking.report import Context
        >>> ctx = Context(out=Path("."), quick=True, section_id="table2")
        >>> df = pd.DataFrame({"specimen": [2], "alpha": [round(math.atan(0.085 / 0.5), 4)]})
        >>> name = ctx.save_csv(df, "alpha")
        >>> name, pd.read_csv(name).to_dict("records")
        ('table2_alpha.csv', [{'specimen': 2, 'alpha': 0.1684}])
        """
        kw.setdefault("index", False)
        p = self.path(f"{name}.csv")
        with atomic_path(p) as tmp:
            df.to_csv(tmp, **kw)
        return p.name

    def save_figure(self, fig, name: str, caption: str, alt: str = "") -> str:
        """Save a matplotlib Figure as ``<id>_<name>.png`` at :attr:`dpi` (atomically);
        returns the ``<figure>`` HTML (the caption doubles as the image's alt text unless
        ``alt`` is given).

        Examples
        --------
        A 3 in x 2 in figure in quick mode (70 dpi) is a 210 x 140 pixel PNG:

        >>> from pathlib import Path
        >>> import matplotlib.image
        >>> from matplotlib.figure import Figure
        >>> from rocking.report import Context
        >>> ctx = Context(out=Path("."), quick=True, section_id="demo")
        >>> fig = Figure(figsize=(3, 2))
        >>> _ = fig.subplots().plot([0.0, 1.0], [0.0, 0.1])
        >>> html = ctx.save_figure(fig, "theta", caption="Rocking angle")
        >>> html.startswith('<figure><a href="demo_theta.png">'), "Rocking angle" in html
        (True, True)
        >>> matplotlib.image.imread("demo_theta.png").shape
        (140, 210, 4)
        """
        p = self.path(f"{name}.png")
        with atomic_path(p) as tmp:
            fig.savefig(tmp, dpi=self.dpi)
        return H.figure(p.name, caption, alt)

    def files_html(self) -> str:
        """Links to every file this section wrote so far (an empty string if none).

        Examples
        --------
        >>> from pathlib import Path
        >>> import pandas as pd
        >>> from rocking.report import Context
        >>> ctx = Context(out=Path("."), quick=True, section_id="demo")
        >>> ctx.files_html()
        ''
        >>> ctx.save_csv(pd.DataFrame({"specimen": [2]}), "ids")
        'demo_ids.csv'
        >>> ctx.files_html()
        '<p class="small files">Files: <a href="demo_ids.csv">demo_ids.csv</a></p>'
        """
        return H.files_line(self.files) if self.files else ""


class ReportError(RuntimeError):
    """Raised by :func:`reproduce` after writing the page when some sections failed.

    ``path`` is the written ``index.html``; ``failed`` maps section ids to error messages.

    Examples
    --------
    A section that raises is shown in the page; the error comes after the page is written:

    >>> from rocking.report import SECTIONS, ReportError, reproduce, section
    >>> @section("broken", "Broken", order=1)
    ... def build(ctx):
    ...     raise ValueError("no data")
    >>> try:
    ...     reproduce("report", only="broken", progress=False)
    ... except ReportError as e:
    ...     print(e.failed, e.path.is_file())
    ... finally:
    ...     del SECTIONS["broken"]
    {'broken': 'ValueError: no data'} True
    """

    def __init__(self, path: Path, failed: dict[str, str]):
        self.path = Path(path)
        self.failed = dict(failed)
        lines = "; ".join(f"{k}: {v}" for k, v in failed.items())
        super().__init__(f"{len(failed)} report section(s) failed ({lines}); "
                         f"the page was written anyway: {path}")


_TRANSLIT = {"—": "-", "–": "-", "α": "alpha", "μ": "mu", "θ": "theta", "×": "x", "²": "^2"}


def _ascii(text: str) -> str:
    """A plain-ASCII version of a title for the progress lines on stderr."""
    for k, v in _TRANSLIT.items():
        text = text.replace(k, v)
    return text.encode("ascii", "replace").decode()


def _log(progress: bool, msg: str) -> None:
    if progress:
        print(msg, file=sys.stderr, flush=True)


def _versions() -> str:
    parts = [f"Python {platform.python_version()}"]
    for mod in ("numpy", "scipy", "numba", "matplotlib", "pandas"):
        try:
            m = __import__(mod)
            parts.append(f"{mod} {m.__version__}")
        except Exception:  # pragma: no cover - optional information only
            pass
    return ", ".join(parts)


HOW_TO_READ = """
<p>Each section reproduces one table or figure of the paper with this package and puts the
paper's printed numbers next to ours. <em>Ours</em> are computed when this page is built
(nothing is tuned to the paper); <em>paper</em> values are read from the package data
(<code>rocking/blocks/data/pena2007.json</code>, Tables I&ndash;V as printed). Percent differences
are <code>(ours &minus; paper) / paper &times; 100</code>. The discussion under each table
is generated from the numbers of this run. Every table is also written as a CSV file and
every figure as a PNG next to this page (links under each section). Simulations use the
classical (Housner) model, Eq (1) with the restitution rule of Eq (4), unless a section
says otherwise.</p>
"""

SIGN_CONVENTION = """
<p><strong>Sign convention.</strong> The ground acceleration <code>a</code> has the sign of
the paper's Eq (1): a positive <code>a</code> drives the rocking angle <code>&theta;</code>
positive (the inertial force &minus;M&nbsp;a<sub>g</sub> tilts the block against the
direction in which the table accelerates). &theta;&nbsp;&gt;&nbsp;0 means rotation about
the pivot O, &theta;&nbsp;&lt;&nbsp;0 about O&prime;. A block at rest uplifts when
|a|&nbsp;&gt;&nbsp;g&nbsp;tan&nbsp;&alpha;; it overturns (OVT) when |&theta;| reaches
&pi;/2. Angles are shown in degrees, everything else in SI units. A constant sine of
table displacement amplitude X and frequency f has the acceleration amplitude
X&nbsp;(2&pi;f)<sup>2</sup>; the table displacement starts at zero.</p>
"""


def _provenance(now: str, total: float, timings) -> str:
    """The footer: when and with what the page was built, and how long each section took
    here. The only place of the page that depends on the machine."""
    rows = "".join(f"<li>{H.esc(t)}: {H.esc(st)}, {dt:.1f} s</li>" for t, st, dt in timings)
    return (f'<section id="provenance" class="small">\n<h2>Provenance</h2>\n'
            f"<p>Generated {H.esc(now)} in {total:.1f} s; {H.esc(_versions())}. Times are "
            f"wall-clock on this machine and do not change the content above.</p>"
            f"<ul>{rows}</ul>\n</section>")


def _cores() -> int:
    """The cores this process may run on."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # pragma: no cover - not on Linux
        return max(1, os.cpu_count() or 1)


def _build_one(sec: Section, out: Path, quick: bool, full: bool) -> tuple:
    """``(fragment, status, seconds, failure or None)`` of one section; a section that
    raises gets a red box with the traceback instead of its fragment."""
    ctx = Context(out=out, quick=quick, section_id=sec.id, full=full)
    t0 = time.perf_counter()
    try:
        return sec.build(ctx), "ok", time.perf_counter() - t0, None
    except Exception as exc:  # a failing section must not kill the report
        msg = f"{type(exc).__name__}: {exc}"
        frag = (H.error_box(f"This section failed: {msg}",
                            "The other sections were still computed.",
                            traceback.format_exc()) + ctx.files_html())
        return frag, "FAILED", time.perf_counter() - t0, msg


def _portable(sec: Section) -> bool:
    """Whether a worker process finds ``sec`` by importing its module: its ``build`` is a
    module-level name of an imported module other than ``__main__``."""
    fn = sec.build
    mod = sys.modules.get(getattr(fn, "__module__", None) or "")
    return (mod is not None and mod.__name__ != "__main__"
            and getattr(mod, "__spec__", None) is not None
            and getattr(mod, getattr(fn, "__name__", ""), None) is fn)


def _worker_init(threads: int, said) -> None:
    """A report worker: its share of the cores as numba threads, and the compile notice
    said once for all the workers."""
    import numba

    from .. import _compile_notice

    numba.set_num_threads(min(threads, numba.config.NUMBA_NUM_THREADS))
    _compile_notice.share(said)


def _build_in_worker(section_id: str, module: str, out: Path, quick: bool,
                     full: bool) -> tuple:
    """:func:`_build_one` of the section ``section_id``, registered by importing
    ``module`` (in a worker process), and the warnings it raised (category, message,
    file, line)."""
    importlib.import_module(__name__.rpartition(".")[0])  # rocking.report: every section
    importlib.import_module(module)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")  # the caller's filters decide (_build_parallel)
        result = _build_one(SECTIONS[section_id], out, quick, full)
    return result, [(w.category, str(w.message), w.filename, w.lineno) for w in caught]


def _build_parallel(secs, out: Path, quick: bool, full: bool, jobs: int, threads: int,
                    done) -> None:
    """Build ``secs`` in ``jobs`` spawned worker processes, the costliest first; calls
    ``done(section, result)`` as each ends. Sections a worker cannot import are built
    here, meanwhile. A worker's warnings are raised again here, under this process's
    filters. Ctrl-C cancels what has not started and stops the workers."""
    import multiprocessing as mp
    from concurrent.futures import ProcessPoolExecutor, as_completed

    from .. import _compile_notice

    spawn = mp.get_context("spawn")
    said = spawn.Value("b", 0)
    ex = ProcessPoolExecutor(max_workers=jobs, mp_context=spawn, initializer=_worker_init,
                             initargs=(threads, said))
    registries: dict[str, dict] = {}
    try:
        futures = {}
        for sec in sorted(secs, key=lambda s: (-s.cost, s.order, s.id)):
            if _portable(sec):
                futures[ex.submit(_build_in_worker, sec.id, sec.build.__module__, out,
                                  quick, full)] = sec
        _compile_notice.share(said)
        try:
            for sec in secs:
                if not _portable(sec):
                    done(sec, _build_one(sec, out, quick, full))
        finally:
            _compile_notice.share(None)
        for fut in as_completed(futures):
            sec = futures[fut]
            try:
                result, caught = fut.result()
            except Exception as exc:  # the worker died (memory, a signal): say so
                msg = f"{type(exc).__name__}: {exc}"
                result, caught = (H.error_box(f"This section failed: {msg}",
                                              "Its worker process ended abnormally."),
                                  "FAILED", 0.0, msg), []
            done(sec, result)
            for category, message, filename, lineno in caught:
                warnings.warn_explicit(message, category, filename, lineno,
                                       registry=registries.setdefault(filename, {}))
    except BaseException:
        ex.shutdown(wait=False, cancel_futures=True)
        raise
    ex.shutdown(wait=True)


def reproduce(out, quick: bool = False, full: bool = False, progress: bool = True,
              only=None, jobs: int | None = None) -> Path:
    """Write the reproduction report ``out/index.html`` (+ PNG and CSV files); return its path.

    ``quick`` runs cheaper versions of the sections (for tests); ``full`` adds the parts
    too slow for the default run (``rocking reproduce --full``); the content depends on
    these flags only, never on how fast the machine is. ``progress`` prints one line per
    section on stderr; ``only`` restricts the report to some section ids.

    ``jobs`` sections are built at once, each in its own worker process (spawned; the
    costliest first, see :func:`section`), and the machine's cores are shared among them
    as numba threads. The default is one job per core (at most one per section); ``jobs=1``
    builds them one after the other in this process. A section never depends on another
    nor on the number of jobs: the page and every file are the same either way. A section
    that a worker cannot import (defined in ``__main__`` or a doctest) is built here.
    Raises :class:`ReportError` (a RuntimeError) *after* writing the page if any section
    failed.

    Examples
    --------
    The whole report takes minutes; one section is cheap. Table II in quick mode: our
    ``alpha = atan(b/h)`` of specimen 2 (Eq 2) next to the paper's:

    >>> import pandas as pd
    >>> from rocking.report import reproduce
    >>> path = reproduce("report", quick=True, only="table2", progress=False)
    >>> path.name
    'index.html'
    >>> t2 = pd.read_csv(path.parent / "table2_parameters.csv").set_index("specimen")
    >>> round(float(t2.loc[2, "alpha_ours"]), 4), float(t2.loc[2, "alpha_paper_T"])
    (0.1684, 0.168)
    """
    # Sections draw on matplotlib.figure.Figure objects (Agg canvas), never through pyplot,
    # so building a report does not change the user's backend or open windows.
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    secs = ordered_sections()
    if only is not None:
        wanted = [only] if isinstance(only, str) else list(only)
        unknown = sorted(set(wanted) - {s.id for s in secs})
        if unknown:
            raise ValueError(f"unknown report section(s) {unknown}; "
                             f"known: {[s.id for s in secs]}")
        secs = [s for s in secs if s.id in wanted]
    cores = _cores()
    if jobs is None:
        jobs = cores
    if isinstance(jobs, bool) or not isinstance(jobs, int) or jobs < 1:
        raise ParameterError(f"jobs must be an integer >= 1, got {jobs!r}")
    jobs = min(jobs, max(1, sum(_portable(s) for s in secs)))

    t_all = time.perf_counter()
    mode = ", ".join(m for m, on in (("quick", quick), ("full", full)) if on)
    _log(progress, f"rocking report: {len(secs)} section(s) -> {out}"
                   f"{f' ({mode})' if mode else ''}"
                   f"{f', {jobs} jobs' if jobs > 1 else ''}")
    width = max((len(s.title) for s in secs), default=0)
    built: dict[str, tuple] = {}

    def done(sec, result):
        built[sec.id] = result
        status, dt = result[1], result[2]
        _log(progress, f"  [{len(built)}/{len(secs)}] {_ascii(sec.title):<{width}}  "
                       f"{status:<6} {dt:6.1f} s")

    if jobs == 1:
        for sec in secs:
            done(sec, _build_one(sec, out, quick, full))
    else:
        _build_parallel(secs, out, quick, full, jobs, max(1, cores // jobs), done)

    bodies, toc, failed, timings = [], [], {}, []
    for i, sec in enumerate(secs, 1):
        frag, status, dt, msg = built[sec.id]
        if msg is not None:
            failed[sec.id] = msg
        cls = "status-ok" if status == "ok" else "status-failed"
        toc.append(f'<li><a href="#{H.esc(sec.id)}">{H.esc(sec.title)}</a> '
                   f'<span class="small {cls}">{H.esc(status)}</span></li>')
        timings.append((sec.title, status, dt))
        bodies.append(f'<section id="{H.esc(sec.id)}">\n<h2>{i}. {H.esc(sec.title)}</h2>\n'
                      f"{frag}\n</section>")

    total = time.perf_counter() - t_all
    src = paper_data()["source"]
    now = _dt.datetime.now().astimezone().strftime("%Y-%m-%d %H:%M %Z")
    modes = []
    if quick:
        modes.append("quick mode: shortened runs, fewer panels")
    if full:
        modes.append("full mode: includes the parts too slow for the default run")
    head = (
        f'<p class="meta">Built by <code>rocking</code> {H.esc(__version__)}'
        f"{' (' + '; '.join(modes) + ')' if modes else ''}.</p>"
        f'<div class="box"><strong>Reference.</strong> {H.esc(src)}</div>'
        f"<h2>How to read this report</h2>{HOW_TO_READ}{SIGN_CONVENTION}"
    )
    if failed:
        head += H.error_box(f"{len(failed)} section(s) failed",
                            "; ".join(f"{k}: {v}" for k, v in failed.items()))
    page = H.page("Rocking of single rigid blocks: reproduction of Peña et al. (2007)",
                  head, "<ol>" + "".join(toc) + "</ol>",
                  "\n".join(bodies) + _provenance(now, total, timings))
    index = out / "index.html"
    atomic_write(index, page)  # last: a complete index.html means a complete report
    _log(progress, f"rocking report: wrote {index} in {total:.1f} s"
                   + (f"; FAILED: {', '.join(failed)}" if failed else ""))
    if failed:
        raise ReportError(index, failed)
    return index
