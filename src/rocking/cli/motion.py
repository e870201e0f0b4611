"""``rocking motion ...``: synthetic earthquakes and response spectra from the command line.

::

    rocking motion synth --count 30 --out quakes/          # the paper's set (cached)
    rocking motion synth --count 5 --seed 1 --ag 0.25g --ground C --type 1 --out q/
    rocking motion spectrum quake.AT2                       # PEER file, in g
    rocking motion spectrum quake.csv --units m/s^2 --damping 5% --plot spec.png
    rocking motion show H.AT2 --vertical V.AT2 [--units g] [--plot motion.png]

The group is registered in :mod:`rocking.cli`. Bad input
raises :class:`~rocking.errors.RockingError`; the main entry point prints it as one line
``error: ...``.
"""

from __future__ import annotations

import json
from pathlib import Path

import click
import numpy as np

from .._atomic import atomic_path, atomic_write
from .._validate import as_float
from ..errors import ParameterError
from ..units import G, parse_quantity
from .common import CONTEXT, integer, positive_quantity, read_record_arg

# matplotlib, pandas and rocking.motions (numba) are imported inside the functions: lazy,
# so that `rocking --help` and the other commands start fast.


# ----------------------------------------------------------------------------- parsing
def _time(text, name: str) -> float | None:
    return positive_quantity(text, "time", name, "s", "s")


def _damping(text) -> float:
    """``5%`` or ``0.05`` as a fraction in [0, 1)."""
    s = str(text).strip()
    if s.endswith("%"):
        x = as_float("damping", s[:-1].strip()) / 100.0
    else:
        x = as_float("damping", s)
        if x >= 1.0:
            raise ParameterError(f"damping is a fraction (0.05) or a percentage (5%); "
                                 f"got {text!r}")
    if not 0.0 <= x < 1.0:  # name the text the user typed, not the fraction (500% -> 5.0)
        raise ParameterError(f"damping must be in [0, 100) % (or a fraction in [0, 1)), "
                             f"got {text!r}")
    return x


def _target(ag, ground, stype, damping: float):
    """The paper's target, or an EC8 spectrum when ``--ag`` is given."""
    from ..motions.ec8 import DesignSpectrum, paper_target  # lazy: numba

    if ag is None:
        if ground is not None or stype is not None:
            raise ParameterError("--ground/--type need --ag (design ground acceleration, "
                                 "e.g. --ag 0.25g)")
        t = paper_target()
        return t if damping == 0.05 else t.with_damping(damping), True
    a = parse_quantity(ag, "acceleration", name="ag")
    return DesignSpectrum.ec8(a, ground or "A", stype or 1, damping=damping), False


# ----------------------------------------------------------------------------- figures
def _save(fig, path: Path, dpi: int = 110) -> None:
    try:
        with atomic_path(path) as tmp:
            fig.savefig(tmp, dpi=dpi)
    except OSError as e:
        raise click.ClickException(f"cannot write {path}: {e.strerror or e}") from None


def _record_figure(rec, periods, sa, target, prange, damping):
    from matplotlib.figure import Figure

    from ..motions.processing import displacement
    from ..motions.spectra import plot_spectra

    d = 1000.0 * displacement(rec)
    fig = Figure(figsize=(10.0, 4.2), layout="constrained")
    gs = fig.add_gridspec(2, 2, width_ratios=[1.2, 1.0])
    ax = fig.add_subplot(gs[:, 0])
    plot_spectra(ax, periods, sa, target, period_range=prange,
                 labels=[f"record {rec.number}" if rec.number is not None else "record"],
                 title=f"{rec.name}: {100 * damping:g} % damped spectrum")
    ax2 = fig.add_subplot(gs[0, 1])
    ax2.plot(rec.t, rec.values, lw=0.5, color="#0072B2")
    ax2.set_ylabel("acc. (m/s²)")
    ax2.set_title(f"PGA {rec.pga:.2f} m/s², PGD {np.max(np.abs(d)):.0f} mm", fontsize=10)
    ax3 = fig.add_subplot(gs[1, 1], sharex=ax2)
    ax3.plot(rec.t, d, lw=1.0, color="#D55E00")
    ax3.set_ylabel("table disp. (mm)")
    ax3.set_xlabel("time (s)")
    for a in (ax2, ax3):
        a.axhline(0.0, color="0.5", lw=0.6)
        a.grid(True, alpha=0.3)
    ax2.tick_params(labelbottom=False)
    return fig


# ----------------------------------------------------------------------------- commands
@click.group("motion", context_settings=CONTEXT)
def motion():
    """Earthquake input: synthetic spectrum-compatible records, response spectra."""


@motion.command("synth")
@click.option("--count", default="30", show_default=True, metavar="N",
              help="Number of records.")
@click.option("--out", required=True, type=click.Path(file_okay=False),
              help="Folder for the CSV records, PNG spectra and summary.csv.")
@click.option("--seed", default=None, metavar="S",
              help="Random seed (default: the paper set's, 2007).")
@click.option("--first", "first", default="1", show_default=True, metavar="K",
              help="Number of the first record.")
@click.option("--duration", metavar="T", help="Record length (default 20 s).")
@click.option("--dt", metavar="DT", help="Time step (default 0.01 s).")
@click.option("--envelope", type=click.Choice(["jennings", "trapezoidal"]), default="jennings",
              show_default=True, help="Amplitude envelope (2 s rise, 10 s stationary).")
@click.option("--ag", metavar="AG", help="EC8 target instead of the paper's: design ground "
                                         "acceleration, e.g. 0.25g or 2.45m/s2.")
@click.option("--ground", type=click.Choice(list("ABCDE"), case_sensitive=False),
              help="EC8 ground type (with --ag; default A).")
@click.option("--type", "stype", type=click.Choice(["1", "2"]),
              help="EC8 spectrum type (with --ag; default 1).")
@click.option("--no-plots", is_flag=True, help="Skip the PNG of each record.")
def synth_cmd(count, out, seed, first, duration, dt, envelope, ag, ground, stype, no_plots):
    """Generate spectrum-compatible synthetic earthquakes into OUT.

    Without options this writes the paper's set (our realisation: 30 records, seed 2007,
    numbered 1-30, the same records as `rocking simulate --earthquake N`).
    """
    import pandas as pd
    from matplotlib.figure import Figure

    from ..motions.io import write_csv
    from ..motions.spectra import plot_spectra
    from ..motions.synthetic import (
        PAPER_COUNT,
        PAPER_SEED,
        PERIOD_RANGE,
        Envelope,
        check_compatibility,
        seed_earthquakes,
        synthetic,
    )

    n = integer(count, "count", 1, 1000)
    k0 = integer(first, "first", 0)
    sd = PAPER_SEED if seed is None else integer(seed, "seed", 0)
    dur = _time(duration, "duration")
    step = _time(dt, "dt")
    target, is_paper = _target(ag, ground, stype, 0.05)
    paper = (is_paper and sd == PAPER_SEED and 1 <= k0 and k0 + n - 1 <= PAPER_COUNT
             and dur is None and step is None and envelope == "jennings")
    if paper:  # records of the paper's set: take them from it (cached, identical numbering)
        recs = seed_earthquakes()[k0 - 1:k0 - 1 + n]
    else:
        env = Envelope(envelope, duration=20.0 if dur is None else dur)
        recs = synthetic(target, n=n, seed=sd, envelope=env, first_number=k0,
                         dt=0.01 if step is None else step)
    folder = Path(out)
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise click.ClickException(f"cannot create {folder}: {e.strerror or e}") from None

    periods = np.unique(np.concatenate([np.geomspace(0.02, 4.0, 150), PERIOD_RANGE]))
    comp = check_compatibility(recs, target, PERIOD_RANGE, periods=periods)
    width = max(2, len(str(max(r.number for r in recs))))
    rows = []
    dev = comp.record_deviation()
    for rec, sa, d in zip(recs, comp.spectra, dev, strict=True):
        stem = f"earthquake_{rec.number:0{width}d}"
        write_csv(rec, folder / f"{stem}.csv")
        im = rec.intensity_measures()
        rows.append({"number": rec.number, "file": f"{stem}.csv", "pga_ms2": im["pga"],
                     "pgv_ms": im["pgv"], "pgd_m": im["pgd"], "arias_ms": im["arias"],
                     "d5_95_s": im["d5_95"],
                     "max_dev_in_range": float(d),
                     "seed": rec.meta.get("seed")})
        if not no_plots:
            fig = _record_figure(rec, periods, sa, target, PERIOD_RANGE, 0.05)
            _save(fig, folder / f"{stem}_spectrum.png")
    table = pd.DataFrame(rows)
    with atomic_path(folder / "summary.csv") as tmp:
        table.to_csv(tmp, index=False, float_format="%.6g")
    fig = Figure(figsize=(8.0, 5.0), layout="constrained")
    plot_spectra(fig.add_subplot(), periods, comp.spectra, target, period_range=PERIOD_RANGE,
                 title=f"{len(recs)} synthetic records vs target (5 % damping)")
    _save(fig, folder / "spectra.png")
    atomic_write(folder / "compatibility.txt", comp.summary() + "\n")

    click.echo(f"target      {target.describe()}")
    click.echo(f"records     {len(recs)} x {recs[0].duration:g} s at dt = {recs[0].dt:g} s, "
               f"seed {sd}, numbers {recs[0].number}-{recs[-1].number}"
               + (" (the paper's set, cached)" if paper else ""))
    for line in comp.summary().splitlines():
        click.echo(line)
    if paper and n < PAPER_COUNT:
        click.echo(f"            (EC8 judges the set used in an analysis; these are {n} of the "
                   f"paper set's {PAPER_COUNT} records, which pass as a whole)")
    click.echo(f"PGA         {table.pga_ms2.min():.2f}-{table.pga_ms2.max():.2f} m/s^2 "
               f"(mean {table.pga_ms2.mean():.2f})")
    click.echo(f"PGD         {1000 * table.pgd_m.min():.0f}-{1000 * table.pgd_m.max():.0f} mm "
               f"(table stroke needed: +-{1000 * table.pgd_m.max():.0f} mm)")
    click.echo(f"per record  largest deviation from the target over "
               f"{PERIOD_RANGE[0]:g}-{PERIOD_RANGE[1]:g} s: median "
               f"{100 * table.max_dev_in_range.median():.1f} %, worst "
               f"{100 * table.max_dev_in_range.max():.1f} %")
    click.echo(f"wrote       {folder}/: {len(recs)} CSV (t s, acc m/s^2)"
               + ("" if no_plots else f", {len(recs)} PNG")
               + ", spectra.png, summary.csv, compatibility.txt")


@motion.command("spectrum")
@click.argument("file", type=click.Path(dir_okay=False))
@click.option("--units", metavar="U",
              help="Units of the acceleration column: g, m/s^2, cm/s^2 (gal); default g.")
@click.option("--dt", metavar="DT", help="Time step of a one-column file (s).")
@click.option("--damping", default="5%", show_default=True, metavar="Z",
              help="Damping ratio: 5% or 0.05.")
@click.option("--tmin", default="0.02", show_default=True, metavar="T", help="Shortest period (s).")
@click.option("--tmax", default="4", show_default=True, metavar="T", help="Longest period (s).")
@click.option("--n", "npts", default="100", show_default=True, metavar="N",
              help="Number of periods (log-spaced).")
@click.option("--plot", "plot_path", type=click.Path(dir_okay=False),
              help="PNG to write (default: <file stem>_spectrum.png here).")
@click.option("--no-plot", is_flag=True, help="Do not write a PNG.")
@click.option("--target", type=click.Choice(["none", "paper"]), default="none",
              show_default=True, help="Draw the paper's target spectrum on the plot.")
@click.option("--json", "as_json", is_flag=True, help="Print JSON instead of a table.")
def spectrum_cmd(file, units, dt, damping, tmin, tmax, npts, plot_path, no_plot, target,
                 as_json):
    """Print and plot the elastic response spectrum of the record FILE.

    FILE is a PEER NGA .AT2 file (always in g) or CSV/whitespace columns (t, acc) or one
    acceleration column with --dt or a '# dt = ...' header line.
    """
    from matplotlib.figure import Figure

    from ..motions.ec8 import paper_target
    from ..motions.spectra import log_periods, plot_spectra, response_spectra

    zeta = _damping(damping)
    t_lo, t_hi = _time(tmin, "tmin"), _time(tmax, "tmax")
    n = integer(npts, "n", 2, 10000)
    step = _time(dt, "dt")
    p = Path(file)
    rec, _ = read_record_arg(p, "file", units, step)  # messages in option words
    T = log_periods(t_lo, t_hi, n)
    s = response_spectra(rec, T, zeta)
    im = rec.intensity_measures()
    if as_json:
        click.echo(json.dumps({
            "file": str(p), "units_in_file": units or "g", "dt": rec.dt,
            "npts": len(rec), "damping": zeta, "intensity_measures": im,
            "period_s": T.tolist(), "psa_ms2": s["psa"].tolist(), "sa_ms2": s["sa"].tolist(),
            "sd_m": s["sd"].tolist(), "psv_ms": s["psv"].tolist()}, indent=1))
    else:
        click.echo(f"record      {p.name}: {len(rec)} samples, dt = {rec.dt:g} s, "
                   f"{rec.duration:g} s")
        click.echo(f"PGA         {im['pga']:.4g} m/s^2 ({im['pga_g']:.4g} g)   "
                   f"PGV {im['pgv']:.4g} m/s   PGD {im['pgd']:.4g} m")
        click.echo(f"Arias       {im['arias']:.4g} m/s   D5-95 {im['d5_95']:.3g} s "
                   f"({im['t5']:.3g}-{im['t95']:.3g} s)")
        click.echo(f"damping     {100 * zeta:g} %")
        click.echo(f"{'T (s)':>10} {'PSA (m/s^2)':>12} {'PSA (g)':>9} {'SD (mm)':>9}")
        for Ti, a, d in zip(T, s["psa"], s["sd"], strict=True):
            click.echo(f"{Ti:10.4g} {a:12.4g} {a / G:9.4g} {1000 * d:9.4g}")
    if not no_plot:
        out = Path(plot_path) if plot_path else Path(f"{p.stem}_spectrum.png")
        fig = Figure(figsize=(7.5, 4.5), layout="constrained")
        tgt = paper_target().with_damping(zeta) if target == "paper" else None
        plot_spectra(fig.add_subplot(), T, s["psa"], tgt, labels=[p.name],
                     title=f"{p.name}: {100 * zeta:g} % damped pseudo-acceleration "
                           f"(PGA {im['pga']:.3g} m/s²)")
        _save(fig, out)
        if not as_json:
            click.echo(f"wrote       {out}")


@motion.command("show")
@click.argument("file")
@click.option("--vertical", metavar="V", help="Vertical component (positive upwards), a file "
              "or a built-in record's name.")
@click.option("--units", metavar="U",
              help="Units of the records: g, m/s^2, cm/s^2 (gal); default g.")
@click.option("--dt", metavar="DT", help="Time step of one-column files (s).")
@click.option("--plot", "plot_path", type=click.Path(dir_okay=False),
              help="PNG of both components (default: <file stem>_motion.png here).")
@click.option("--no-plot", is_flag=True, help="Do not write a PNG.")
def show_cmd(file, vertical, units, dt, plot_path, no_plot):
    """Summarise a record FILE and its vertical component: peaks, intensity, and where
    g + a_v <= 0 (the base falls faster than gravity: a block would leave the ground).

    FILE and V are files (.AT2, columns) or the names of built-in records (e.g.
    Rinaldi228 and RinaldiUP).
    """
    from matplotlib.figure import Figure

    step = _time(dt, "dt")
    h, hs = read_record_arg(file, "file", units, step)
    comps = [("horizontal", h, hs)]
    if vertical is not None:
        v, vs = read_record_arg(vertical, "vertical", units, step)
        comps.append(("vertical", v, vs))
    for label, rec, src in comps:
        im = rec.intensity_measures()
        click.echo(f"{label:<11} {src}: {len(rec)} samples, dt = {rec.dt:g} s, "
                   f"{rec.duration:g} s")
        click.echo(f"{'':<11} PGA {im['pga']:.4g} m/s^2 ({im['pga_g']:.4g} g), PGV "
                   f"{im['pgv']:.4g} m/s, PGD {im['pgd']:.4g} m, Arias {im['arias']:.4g} m/s")
    if vertical is not None:
        av = v.values
        low = np.flatnonzero(G + av <= 0.0)
        click.echo(f"{'':<11} a_v from {av.min() / G:.3g} g to {av.max() / G:.3g} g: "
                   + (f"g + a_v <= 0 at {low.size} samples, first at t = {low[0] * v.dt:.4g} s"
                      if low.size else "g + a_v > 0 throughout (no lift-off)"))
        click.echo(f"{'':<11} effective gravity g + a_v from {(G + av.min()) / G:.3g} g "
                   f"to {(G + av.max()) / G:.3g} g; PGA_v / PGA_h = "
                   f"{np.max(np.abs(av)) / h.pga:.3g}")
    if not no_plot:
        p = Path(file)
        out = Path(plot_path) if plot_path else Path(f"{p.stem}_motion.png")
        fig = Figure(figsize=(8.0, 2.4 * len(comps) + 0.6), layout="constrained")
        axes = fig.subplots(len(comps), 1, sharex=True, squeeze=False)[:, 0]
        for ax, (label, rec, src) in zip(axes, comps, strict=True):
            ax.plot(rec.t, rec.values / G, lw=0.7, color="0.2")
            ax.set_ylabel(f"{label} (g)")
            ax.set_title(Path(src).name, fontsize=9)
            ax.grid(alpha=0.3)
        if vertical is not None:
            axes[-1].axhline(-1.0, color="C3", lw=0.8, ls="--", label="a_v = -g (lift-off)")
            axes[-1].legend(fontsize=8, loc="lower right")
        axes[-1].set_xlabel("t (s)")
        _save(fig, out)
        click.echo(f"wrote       {out}")


__all__ = ["motion", "synth_cmd", "spectrum_cmd", "show_cmd"]
