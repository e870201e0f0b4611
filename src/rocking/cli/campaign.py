"""``rocking campaign run|status|verify|upgrade|report``: campaigns from a TOML spec into a
Parquet store.

::

    rocking campaign run SPEC.toml --out STORE [--executor local|dask]
                         [--scheduler tcp://host:port | --dask-local N] [--dry-run]
    rocking campaign status STORE [--json]
    rocking campaign verify STORE [--json]
    rocking campaign upgrade STORE
    rocking campaign report STORE [--out DIR] [--hazard FILE [--site I|LON,LAT]
                            [--max-distance-km 50] [--investigation-time T]] [--t-years 50]

``run`` on an existing store resumes it (finished chunks are not recomputed, damaged ones
are moved into ``STORE/quarantine/`` and recomputed) and refuses a different spec. Ctrl-C
stops cleanly: every finished chunk is kept (exit code 130).

**Long campaigns.** Before it starts, ``run`` bounds the time of the simulations left with
a per-model cost constant (:data:`SECONDS_PER_RUN_BOUND`: an upper bound of one
simulation's time on the local executor). Where the bound exceeds an hour, a short timing
(:func:`rocking.campaign.estimate`: a few motions built and 48 simulations per model, 4 of
a slow one) estimates the time; above an hour it prints one line ``estimated time: ...``
first, and above a day (:data:`REFUSE_SECONDS`) it refuses without ``--yes`` (exit code 2).
The estimate is that of the local executor on this machine (a Dask cluster divides it by
its workers, roughly).

``verify`` exit codes: 0 every chunk matches its record (the store may be incomplete),
1 problems found (each named on its own line, or a damaged manifest), 2 bad input (not a
store). The report is written into a temporary folder and its files renamed into
``--out`` one by one (``report.md`` last), each synced: a killed report never leaves a
half-written file.

``report`` gives the risk at the site when the store has a hazard (the spec's ``[hazard]``,
kept in the manifest) or one is given with ``--hazard`` (which replaces it for this report):
per block and mitigation the annual frequency of overturning and its probability over the
service life (``--t-years``), in ``risk.csv``, ``report.md`` and the lines printed.
"""

from __future__ import annotations

import dataclasses
import json
import os
import shutil
from pathlib import Path

import click

from .._atomic import fsync_dir, fsync_file, replace, temporary_name
from ..errors import ParameterError, StoreError
from .common import CONTEXT, force_option, hazard_option_words, json_default, one_line

SECONDS_PER_RUN_BOUND = {"fast": 0.05, "slow": 10.0}
"""An upper bound of one simulation's time (s) on the local executor: a model flagged
``slow`` (the DEM) and the others. The classical models take about 2 ms per simulation of
a 20 s earthquake on 2 cores (``rocking campaign run --dry-run`` of ``examples/site.toml``):
a campaign whose bound is under :data:`NOTICE_SECONDS` starts without a timing."""
NOTICE_SECONDS = 3600.0
"""A campaign estimated to run longer (s) prints its estimate first."""
REFUSE_SECONDS = 86400.0
"""A campaign estimated to run longer (s) is refused without ``--yes``."""


def long_run_estimate(spec, n_left: int) -> float | None:
    """The estimated seconds of ``n_left`` simulations of ``spec`` on the local executor
    (module docstring, "Long campaigns"), or None where the per-model bound is under
    :data:`NOTICE_SECONDS` (no timing is run)."""
    from ..campaign import estimate
    from ..models.registry import MODELS

    if n_left <= 0:
        return None
    runs = spec.runs
    bound = sum(SECONDS_PER_RUN_BOUND["slow" if MODELS[name].slow else "fast"]
                for name, _ in runs) / len(runs) * n_left
    if bound < NOTICE_SECONDS:
        return None
    e = estimate(spec)
    return e["estimated_seconds"] * n_left / max(spec.n_sims, 1)


def _duration(seconds: float) -> str:
    s = int(round(seconds))
    if s < 120:
        return f"{seconds:.3g} s"
    h, rem = divmod(s, 3600)
    if h >= 48:
        return f"{h} h ({h / 24:.3g} days)"
    return f"{h} h {rem // 60:02d} min" if h else f"{rem // 60} min {rem % 60:02d} s"


@click.group("campaign", context_settings=CONTEXT)
def campaign():
    """Campaigns: a study declared in a TOML spec, run by chunks into a resumable store."""


@dataclasses.dataclass(frozen=True)
class RunRequest:
    """``rocking campaign run``'s options, read and checked (:meth:`from_options`): the spec
    read first, then (unless ``--dry-run``) the store and the executor's options."""

    spec: object
    """The :class:`~rocking.campaign.Spec` read from SPEC."""
    out: str | None
    executor: str | None
    """``local`` or ``dask`` (with ``--dry-run``: as given, not checked)."""
    scheduler: str | None
    dask_local: int | None
    window: int | None
    dry_run: bool
    quiet: bool
    yes: bool = False
    """Run a campaign estimated to take more than a day (:data:`REFUSE_SECONDS`)."""

    @classmethod
    def from_options(cls, *, spec, out, executor, scheduler, dask_local, window, dry_run,
                     quiet, yes=False):
        """The request of the command's options (click's values): the spec is read before
        the executor's options are checked, and ``--dry-run`` checks none of them."""
        from ..campaign import read_spec

        s = read_spec(spec)
        if not dry_run:
            executor = _executor(out, executor, scheduler, dask_local, window)
        return cls(spec=s, out=out, executor=executor, scheduler=scheduler,
                   dask_local=dask_local, window=window, dry_run=dry_run, quiet=quiet,
                   yes=bool(yes))


def _executor(out, executor, scheduler, dask_local, window) -> str:
    """The executor of a run (``--executor``, else ``dask`` with ``--scheduler`` or
    ``--dask-local``), its options checked."""
    if out is None:
        raise ParameterError("--out is required: the store directory")
    if executor is None:
        executor = "dask" if (scheduler or dask_local) else "local"
    if executor == "local" and (scheduler or dask_local):
        raise ParameterError("--scheduler and --dask-local need --executor dask")
    if dask_local is not None and not 1 <= dask_local <= 1024:
        raise ParameterError(f"--dask-local must be in [1, 1024] workers, got {dask_local}")
    if window is not None and window < 1:
        raise ParameterError(f"--window must be >= 1, got {window}")
    return executor


@campaign.command("run", context_settings=CONTEXT)
@click.argument("spec", type=click.Path(dir_okay=False))
@click.option("--out", "out", default=None, metavar="STORE",
              help="Store directory (created; an existing store of the same spec resumes).")
@click.option("--executor", type=click.Choice(["local", "dask"]), default=None,
              help="local (default): this process, all cores; dask: a Dask cluster (the "
                   "default with --scheduler or --dask-local).")
@click.option("--scheduler", default=None, metavar="ADDR",
              help="Address of a running Dask scheduler, e.g. tcp://host:8786.")
@click.option("--dask-local", "dask_local", type=int, default=None, metavar="N",
              help="Start a Dask LocalCluster of N worker processes (default 2).")
@click.option("--window", type=int, default=None, metavar="K",
              help="Chunks in flight on Dask (default 2 per worker thread).")
@click.option("--dry-run", is_flag=True,
              help="Print the number of simulations, chunks and an estimated time; run "
                   "nothing.")
@click.option("--quiet", is_flag=True, help="No progress bar.")
@click.option("--yes", is_flag=True,
              help="Run a campaign estimated to take more than a day (refused without it).")
@force_option
def run_cmd(**options):
    """Run the campaign SPEC (TOML) into the store --out."""
    try:
        req = RunRequest.from_options(**options)
        return _dry_run(req) if req.dry_run else _run(req)
    except KeyboardInterrupt:
        return _interrupted(options["out"])


def _interrupted(out) -> int:
    from ..campaign import Store
    s = Store(out) if out is not None else None
    try:
        st = s.status() if s is not None and s.exists() else None
    except StoreError:
        st = None
    if st is None:
        click.echo("\ninterrupted before any chunk was kept; nothing to resume", err=True)
    else:
        click.echo(f"\ninterrupted: {st['sims_done']} of {st['n_sims']} simulations done "
                   f"({st['chunks_done']} of {st['n_chunks']} chunks kept in {out}); run the "
                   "same command again to resume", err=True)
    return 130


def _dry_run(req: RunRequest) -> int:
    """``--dry-run``: the size of the campaign, an estimated time, the store's state."""
    from ..campaign import estimate, status
    s, out = req.spec, req.out
    e = estimate(s)
    shape = " x ".join(f"{v} {k}" for k, v in e["shape"].items())
    click.echo(f"{s.name}: {e['n_sims']} simulations ({shape}) in {e['n_chunks']} "
               f"chunks of {e['chunk_size']}")
    click.echo(f"estimated time with the local executor: "
               f"{_duration(e['estimated_seconds'])} (from {e['sampled']} sample runs)")
    from ..campaign.report import records_fit
    from ..campaign.store import manifest_for
    records_fit(manifest_for(s))  # records that understate an isolator: said before a run
    if s.hazard is not None:
        h = s.hazard
        click.echo(f"hazard: {h['label']} ({h['im_name']} in {h['unit']}, {len(h['im'])} "
                   f"points); service life {h['t_years']:g} years (for the report)")
    if out is not None and Path(out, "manifest.json").is_file():
        st = status(out)
        click.echo(f"store {out}: {st['sims_done']} done, {st['sims_remaining']} to run")
        for p in st["problems"]:
            click.echo(f"  {p}")
    return 0


def _left(spec, out) -> int:
    """The simulations of ``spec`` not yet in the store ``out`` (all without a store, or
    a store of another spec: run refuses it)."""
    from ..campaign import status
    if out is not None and Path(out, "manifest.json").is_file():
        try:
            st = status(out)
        except (StoreError, ParameterError):
            return spec.n_sims
        if st.get("spec_hash", spec.hash) == spec.hash:
            return int(st["sims_remaining"])
    return spec.n_sims


def _check_duration(req: RunRequest) -> None:
    """One line with the estimate of a campaign longer than an hour; above a day, a
    refusal without ``--yes`` (module docstring, "Long campaigns")."""
    n_left = _left(req.spec, req.out)
    seconds = long_run_estimate(req.spec, n_left)
    if seconds is None or seconds < NOTICE_SECONDS:
        return
    line = (f"estimated time: {_duration(seconds)} for {n_left:,} simulations with the "
            "local executor on this machine (from a short timing)")
    if seconds > REFUSE_SECONDS and not req.yes:
        raise ParameterError(f"{line}: more than a day; give --yes to run it, or make the "
                             "campaign smaller (fewer levels, motions or samples)")
    click.echo(line, err=True)


def _run(req: RunRequest) -> int:
    """Run the campaign into its store."""
    from ..campaign import run
    _check_duration(req)
    st = run(req.spec, req.out, executor=req.executor, scheduler=req.scheduler,
             dask_local=req.dask_local, window=req.window, progress=not req.quiet,
             log=lambda m: click.echo(m, err=True))
    click.echo(f"{st['name']}: {st['sims_done']} of {st['n_sims']} simulations done "
               f"({st['chunks_done']} chunks) in {req.out}")
    return 0


@dataclasses.dataclass(frozen=True)
class StoreRequest:
    """The options of ``rocking campaign status``, ``verify`` and ``upgrade``
    (:meth:`from_options`): the store and whether to print JSON."""

    store: str
    as_json: bool = False

    @classmethod
    def from_options(cls, *, store, as_json=False):
        """The request of the command's options (click's values)."""
        return cls(store=store, as_json=as_json)


@campaign.command("status", context_settings=CONTEXT)
@click.argument("store", type=click.Path(file_okay=False))
@click.option("--json", "as_json", is_flag=True, help="Machine-readable output.")
def status_cmd(**options):
    """How many simulations of STORE are done (verified) and how many remain."""
    from ..campaign import status
    req = StoreRequest.from_options(**options)
    st = status(req.store)
    if req.as_json:
        click.echo(json.dumps(st, indent=1, default=json_default))
        return 0
    pct = 100.0 * st["sims_done"] / st["n_sims"] if st["n_sims"] else 100.0
    click.echo(f"{st['name']} ({st['store']}; rocking {st['version']}, spec "
               f"{st['spec_hash'][:12]})")
    click.echo(f"simulations: {st['sims_done']} done, {st['sims_remaining']} remaining of "
               f"{st['n_sims']} ({pct:.1f}%)")
    click.echo(f"chunks: {st['chunks_done']} done, {st['chunks_remaining']} remaining of "
               f"{st['n_chunks']}" + ("; complete" if st["complete"] else "")
               + ("; a run is writing to it" if st["running"] else ""))
    if st["problems"]:
        click.echo(f"{len(st['problems'])} problem(s), not counted as done; `rocking campaign "
                   "run` moves them into quarantine/ and recomputes:")
        for p in st["problems"]:
            click.echo(f"  {p}")
    return 0


@campaign.command("verify", context_settings=CONTEXT)
@click.argument("store", type=click.Path(file_okay=False))
@click.option("--json", "as_json", is_flag=True, help="Machine-readable output.")
def verify_cmd(**options):
    """Check every chunk of STORE against its record (size, sha256, Parquet, rows, sim_id
    range) and the manifest. Exit 0 if all is well (complete or not), 1 on any problem
    (each named), 2 if STORE is not a store."""
    from ..campaign.store import Store
    req = StoreRequest.from_options(**options)
    s = Store(req.store)
    if not s.path.is_dir() or not s.exists():
        raise StoreError(f"{req.store} is not a campaign store (no manifest.json)")
    try:
        c = s.check(deep=True)
    except StoreError as e:  # damaged manifest, or a store of format 1
        return _unreadable(req, e)
    st = s.status(c)
    if req.as_json:
        click.echo(json.dumps({**st, "ok": not c.problems, "adopted": c.adopted}, indent=1,
                              default=json_default))
        return 1 if c.problems else 0
    _echo_check(req.store, c, st)
    return 1 if c.problems else 0


def _unreadable(req: StoreRequest, e: StoreError) -> int:
    """``verify`` of a store whose manifest cannot be checked: the reason, exit code 1."""
    from ..campaign.store import ManifestError
    msg = one_line(e)
    if req.as_json:
        click.echo(json.dumps({"store": str(req.store), "ok": False, "problems": [msg]},
                              indent=1))
    else:
        click.echo(msg)
        if isinstance(e, ManifestError):
            click.echo("`rocking campaign run SPEC --out STORE` rewrites it when the "
                       "store's spec.toml or chunk records match SPEC")
    return 1


def _echo_check(store, c, st: dict) -> None:
    """``verify``'s text: each problem, the summary line, the remedy."""
    for p in c.problems:
        click.echo(str(p))
    n_rows = st["sims_done"]
    head = (f"{store}: {len(c.ok)} of {c.n_chunks} chunks verified (sha256, Parquet, rows, "
            f"sim_ids), {n_rows} of {st['n_sims']} simulations")
    tail = "complete" if st["complete"] else f"{st['chunks_remaining']} chunks to run"
    if c.running:
        tail += "; a run is writing to it (chunks in progress not checked)"
    if c.adopted:
        tail += (f"; {c.adopted} chunks adopted by upgrade (checksums from the upgrade, "
                 "not from their run)")
    click.echo(f"{head}; {tail}")
    if c.problems:
        click.echo(f"{len(c.problems)} problem(s): `rocking campaign run SPEC --out {store}` "
                   "moves these files into quarantine/ and recomputes the chunks concerned")


@campaign.command("upgrade", context_settings=CONTEXT)
@click.argument("store", type=click.Path(file_okay=False))
def upgrade_cmd(**options):
    """Upgrade a store of format 1 (written before chunk records): adopt the chunks that
    pass the structural checks (Parquet, rows, sim_id range), move the others aside."""
    from ..campaign.store import Store
    req = StoreRequest.from_options(**options)
    res = Store(req.store).upgrade(log=lambda m: click.echo(m, err=True))
    click.echo(f"{req.store}: upgraded to format 2: {res['adopted']} chunks recorded (values "
               f"written before the upgrade are not proven by a checksum), "
               f"{len(res['quarantined'])} moved into quarantine/")
    return 0


@dataclasses.dataclass(frozen=True)
class ReportRequest:
    """``rocking campaign report``'s options, read and checked (:meth:`from_options`): the
    store, the report's folder, the ``--hazard`` curve read (or None: the store's) and the
    service life."""

    store: str
    out: str | None
    hazard: tuple | None
    """``(curve, source)`` of ``--hazard``, or None."""
    t_years: float | None

    @classmethod
    def from_options(cls, *, store, out, hazard, site, investigation_time, max_distance_km,
                     t_years, fractiles=()):
        """The request of the command's options (click's values)."""
        from ..campaign.hazard import check_t_years, parse_site, read_hazard

        if t_years is not None:
            t_years = check_t_years(t_years, "--t-years")
        for name, v in (("--site", site), ("--investigation-time", investigation_time),
                        ("--max-distance-km", max_distance_km),
                        ("--fractiles", fractiles or None)):
            if v is not None and hazard is None:
                raise ParameterError(f"{name} applies with --hazard (the store's [hazard] "
                                     "holds one site's curve, read as its spec says)")
        read = None
        if hazard is not None:
            try:
                read = read_hazard(hazard, site=None if site is None else parse_site(site),
                                   investigation_time=investigation_time,
                                   max_distance_km=max_distance_km,
                                   fractiles=list(fractiles or ()))
            except ParameterError as e:
                if str(e).startswith("fractiles"):
                    raise ParameterError("--" + str(e)) from None
                msg = _option_names(str(e))
                raise ParameterError(msg if msg.startswith("--") else
                                     f"--hazard {msg.removeprefix('file: ')}") from None
        return cls(store=store, out=out, hazard=read, t_years=t_years)


@campaign.command("report", context_settings=CONTEXT)
@click.argument("store", type=click.Path(file_okay=False))
@click.option("--out", "out", default=None, metavar="DIR",
              help="Report directory (default STORE/report).")
@click.option("--hazard", "hazard", default=None, metavar="FILE",
              help="A hazard curve for the risk (an OpenQuake export or a CSV of IM and "
                   "annual rate or return period), in place of the store's [hazard].")
@click.option("--site", default=None, metavar="INDEX|LON,LAT",
              help="With --hazard, an OpenQuake export: the site (row index, default 0, or "
                   "the nearest to LON,LAT).")
@click.option("--investigation-time", "investigation_time", default=None, type=float,
              metavar="YEARS", help="With --hazard, a CSV of a probability of exceedance "
                                    "(poe): the years T it refers to; rate = -ln(1 - poe)/T.")
@click.option("--fractiles", "fractiles", multiple=True, metavar="FILE",
              help="With --hazard, an OpenQuake export: one of the model's fractile exports "
                   "(hazard_curve-quantile-0.05-PGA_<id>.csv), repeated (at least two); the "
                   "risk's interval then includes the hazard's uncertainty.")
@click.option("--max-distance-km", "max_distance_km", default=None, type=float, metavar="KM",
              help="With --hazard, an OpenQuake export and --site LON,LAT: refuse a nearest "
                   "site farther than this (default 50 km).")
@click.option("--t-years", "t_years", default=None, type=float, metavar="YEARS",
              help="Service life of the probability 1 - exp(-lambda t) (default: the "
                   "[hazard]'s t_years, else 50).")
def report_cmd(**options):
    """Fragility curves, P(overturn) tables and plots from STORE (rocking.analysis); with a
    hazard (the spec's [hazard], or --hazard) the annual frequency of overturning and its
    probability over the service life per block and mitigation (risk.csv)."""
    from ..campaign import Store, load
    from ..campaign.hazard import DEFAULT_T_YEARS, record
    from ..campaign.report import report, summary_lines

    req = ReportRequest.from_options(**options)
    store, out, t_years = req.store, req.out, req.t_years
    given = None
    s = Store(store)
    manifest = s.manifest
    if req.hazard is not None:  # the service life: --t-years, else the store's [hazard]'s
        curve, src = req.hazard
        stored = manifest.get("hazard") or {}
        given = record(curve, src, t_years if t_years is not None
                       else stored.get("t_years", DEFAULT_T_YEARS))
    table = load(store, lazy=False)
    if table.empty:
        raise ParameterError(f"{store} has no finished simulation yet: run it first")
    st = s.status()
    out = Path(out) if out is not None else Path(store) / "report"
    if out.exists() and not out.is_dir():
        raise ParameterError(f"--out {out}: exists and is a file, not a directory")
    out.parent.mkdir(parents=True, exist_ok=True)
    tmp = temporary_name(out)
    try:
        res = report(table, manifest, tmp, hazard=given, t_years=t_years)
        _publish(tmp, out)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    if not st["complete"]:
        click.echo(f"note: the store is incomplete ({st['sims_done']} of {st['n_sims']} "
                   "simulations): the report covers the finished ones", err=True)
    for line in summary_lines(res):
        click.echo(line)
    click.echo(f"report: {out / 'report.md'}")
    return 0


def _option_names(msg: str) -> str:
    """A hazard loader's message with the command line's option names."""
    if msg.startswith(("site ", "site:")):
        msg = "--" + msg
    return hazard_option_words(msg)


def _publish(tmp: Path, out: Path) -> None:
    """Move the files written in ``tmp`` into ``out``, each synced and renamed (atomic),
    ``report.md`` last."""
    out.mkdir(parents=True, exist_ok=True)
    names = sorted(os.listdir(tmp), key=lambda n: (n == "report.md", n))
    for n in names:
        if (tmp / n).is_file():
            fsync_file(tmp / n)
    fsync_dir(tmp)
    for n in names:
        if (tmp / n).is_file():
            replace(tmp / n, out / n)
