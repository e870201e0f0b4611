"""``rocking campaign run|status|report``: campaigns from a TOML spec into a Parquet store.

::

    rocking campaign run SPEC.toml --out STORE [--executor local|dask]
                         [--scheduler tcp://host:port | --dask-local N] [--dry-run]
    rocking campaign status STORE [--json]
    rocking campaign report STORE [--out DIR]

``run`` on an existing store resumes it (finished chunks are not recomputed) and refuses a
different spec. Ctrl-C stops cleanly: every finished chunk is kept (exit code 130).
"""

from __future__ import annotations

import json
from pathlib import Path

import click

from ..errors import ParameterError
from .common import CONTEXT, json_default


def _duration(seconds: float) -> str:
    s = int(round(seconds))
    if s < 120:
        return f"{seconds:.3g} s"
    h, rem = divmod(s, 3600)
    return f"{h} h {rem // 60:02d} min" if h else f"{rem // 60} min {rem % 60:02d} s"


@click.group("campaign", context_settings=CONTEXT)
def campaign():
    """Campaigns: a study declared in a TOML spec, run by chunks into a resumable store."""


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
def run_cmd(spec, out, executor, scheduler, dask_local, window, dry_run, quiet):
    """Run the campaign SPEC (TOML) into the store --out."""
    from ..campaign import estimate, read_spec, run, status
    s = read_spec(spec)
    if dry_run:
        e = estimate(s)
        shape = " x ".join(f"{v} {k}" for k, v in e["shape"].items())
        click.echo(f"{s.name}: {e['n_sims']} simulations ({shape}) in {e['n_chunks']} "
                   f"chunks of {e['chunk_size']}")
        click.echo(f"estimated time with the local executor: "
                   f"{_duration(e['estimated_seconds'])} (from {e['sampled']} sample runs)")
        if out is not None and Path(out, "manifest.json").is_file():
            st = status(out)
            click.echo(f"store {out}: {st['sims_done']} done, {st['sims_remaining']} to run")
        return 0
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
    try:
        st = run(s, out, executor=executor, scheduler=scheduler, dask_local=dask_local,
                 window=window, progress=not quiet,
                 log=lambda m: click.echo(m, err=True))
    except KeyboardInterrupt:
        st = status(out)
        click.echo(f"\ninterrupted: {st['sims_done']} of {st['n_sims']} simulations done "
                   f"({st['chunks_done']} of {st['n_chunks']} chunks kept in {out}); run the "
                   "same command again to resume", err=True)
        return 130
    click.echo(f"{st['name']}: {st['sims_done']} of {st['n_sims']} simulations done "
               f"({st['chunks_done']} chunks) in {out}")
    return 0


@campaign.command("status", context_settings=CONTEXT)
@click.argument("store", type=click.Path(file_okay=False))
@click.option("--json", "as_json", is_flag=True, help="Machine-readable output.")
def status_cmd(store, as_json):
    """How many simulations of STORE are done and how many remain."""
    from ..campaign import status
    st = status(store)
    if as_json:
        click.echo(json.dumps(st, indent=1, default=json_default))
        return 0
    pct = 100.0 * st["sims_done"] / st["n_sims"] if st["n_sims"] else 100.0
    click.echo(f"{st['name']} ({st['store']}; rocking {st['version']}, spec "
               f"{st['spec_hash'][:12]})")
    click.echo(f"simulations: {st['sims_done']} done, {st['sims_remaining']} remaining of "
               f"{st['n_sims']} ({pct:.1f}%)")
    click.echo(f"chunks: {st['chunks_done']} done, {st['chunks_remaining']} remaining of "
               f"{st['n_chunks']}" + ("; complete" if st["complete"] else ""))
    return 0


@campaign.command("report", context_settings=CONTEXT)
@click.argument("store", type=click.Path(file_okay=False))
@click.option("--out", "out", default=None, metavar="DIR",
              help="Report directory (default STORE/report).")
def report_cmd(store, out):
    """Fragility curves, P(overturn) tables and plots from STORE (rocking.analysis)."""
    from ..campaign import Store, load
    from ..campaign.report import report, summary_lines
    s = Store(store)
    manifest = s.manifest
    table = load(store, lazy=False)
    if table.empty:
        raise ParameterError(f"{store} has no finished simulation yet: run it first")
    st = s.status()
    out = Path(out) if out is not None else Path(store) / "report"
    if out.exists() and not out.is_dir():
        raise ParameterError(f"--out {out}: exists and is a file, not a directory")
    res = report(table, manifest, out)
    if not st["complete"]:
        click.echo(f"note: the store is incomplete ({st['sims_done']} of {st['n_sims']} "
                   "simulations): the report covers the finished ones", err=True)
    for line in summary_lines(res):
        click.echo(line)
    click.echo(f"report: {out / 'report.md'}")
    return 0

