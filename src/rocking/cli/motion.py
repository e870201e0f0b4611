"""``rocking motion ...``: synthetic earthquakes, response spectra and floor motions from the
command line.

::

    rocking motion synth --count 30 --out quakes/          # the paper's set (cached)
    rocking motion synth --count 5 --seed 1 --ag 0.25g --ground C --type 1 --out q/
    rocking motion spectrum quake.AT2                       # PEER file, in g
    rocking motion spectrum quake.csv --units m/s^2 --damping 5% --plot spec.png
    rocking motion show H.AT2 --vertical V.AT2 [--units g] [--plot motion.png]
    rocking motion floor Rinaldi228 --building shear --storeys 5 --building-period 0.5 \\
        --building-damping 5% [--floors all|0,1,3 | --height-ratios 0.5,1] --out floors/
    rocking motion select records/ --target ec8 --ag 0.25g --ground C --specimen 2 \\
        --n 11 [--max-scale 4] --out selected/
    rocking motion select records/ --target uhs --hazard SA0.2.csv --hazard SA1.0.csv \\
        --return-period 475 --periods 0.2:1:50 --out selected/
    rocking motion select records/ --target site_spectrum.csv --specimen 2 --out selected/

``select`` reads every file of FOLDER that the record reader reads (files it refuses are
listed as skipped, with the reason), computes the candidates' spectra once and calls
:func:`rocking.analysis.select_records`; the target is the EC8 spectrum (``--ag``), a
uniform hazard spectrum of SA(T) hazard curves (:func:`rocking.analysis.selection.
uniform_hazard_spectrum`, curves read as by ``rocking hazard show``, with
``--investigation-time`` and ``--max-distance-km``) or a table
(:func:`read_target_table`); the periods are ``--periods`` (:func:`period_range`) or the
block's default range (:func:`rocking.analysis.default_periods`). It writes the scaled
records (``write_csv``: m/s^2), ``selection.csv`` (one row per record, ranked by its own
misfit), ``selection_spectra.csv``, ``selection.json`` and ``selection.png``. A set that
cannot meet the 90 % rule within ``--max-scale`` is written with ``compliant: false`` and
one ``warning:`` line, exit 0 (the best the candidates allow, flagged); bad input is one
``error:`` line, exit 2.

``floor`` filters a record through a building of :mod:`rocking.buildings.catalog` (the
flags of ``rocking simulate --building``, :func:`rocking.cli.common.building_options`)
into the absolute acceleration of its floors (:class:`rocking.buildings.FloorMotion`) and
writes, in OUT: one CSV per floor (``t,acc`` in s and m/s^2 whatever ``--units`` the
record was read in, with a header stating the units and ``dt``, as
:func:`rocking.motions.io.write_csv`: read it back with ``--units m/s^2``); ``floors.csv``
(per floor: ``floor``, ``height_ratio`` z/H, ``file``, the ground's PGA ``pga_ms2``, the
peak floor acceleration ``pfa_ms2``, ``pfa_over_pga``, and for comparison ASCE/SEI 7-22
Eq (13.3-4)'s ``asce7_hf`` with ``Ta`` the building's first period and EN 1998-1:2004
Eq (4.25)'s amplification of a rigid element ``ec8_rigid``, ``3 (1 + z/H) / 2 - 0.5``,
both :mod:`rocking.buildings.spectra`); ``floor_spectra.csv`` (one row per period: the
ground's and each floor's pseudo-acceleration spectrum, m/s^2, ``--damping`` default
5 %); ``floor_accelerations.png`` and ``floor_spectra.png`` (each floor's spectrum with
the ground's, Eq (4.25) with ``a_g S`` the record's PGA and ``T1`` the building's, and
ASCE 7's ``H_f`` PGA, :func:`rocking.buildings.plot_floor_spectrum`; at most
:data:`MAX_PLOTTED_FLOORS` floors are drawn). A ``modal`` building of the catalog has no
floor heights: its ``height_ratio`` and code columns are empty.

The group is registered in :mod:`rocking.cli`. Bad input
raises :class:`~rocking.errors.RockingError`; the main entry point prints it as one line
``error: ...``.
"""

from __future__ import annotations

import dataclasses
import json
import math
import re
import warnings
from pathlib import Path

import click
import numpy as np

from .._atomic import atomic_path, atomic_write
from .._validate import as_float
from ..errors import ParameterError, RockingError
from ..units import G, parse_quantity
from .common import (
    CONTEXT,
    block_options,
    building_options,
    in_flag_words,
    integer,
    json_default,
    km_option,
    make_block,
    make_building,
    mesh_flags,
    one_line,
    positive_quantity,
    read_hazard_option,
    read_record_arg,
    years_option,
)

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
    """Earthquake input: synthetic spectrum-compatible records, response spectra, the
    motion of a building's floors."""


@dataclasses.dataclass(frozen=True)
class SynthRequest:
    """``rocking motion synth``'s options, read and checked (:meth:`from_options`)."""

    count: int
    first: int
    seed: int
    duration: float | None
    dt: float | None
    envelope: str
    target: object
    """The target spectrum: the paper's, or EC8's of ``--ag``."""
    paper_target: bool
    out: str
    no_plots: bool

    @classmethod
    def from_options(cls, *, count, out, seed, first, duration, dt, envelope, ag, ground,
                     stype, no_plots):
        """The request of the command's options (click's values)."""
        from ..motions.synthetic import PAPER_SEED

        n = integer(count, "count", 1, 1000)
        k0 = integer(first, "first", 0)
        sd = PAPER_SEED if seed is None else integer(seed, "seed", 0)
        dur = _time(duration, "duration")
        step = _time(dt, "dt")
        target, is_paper = _target(ag, ground, stype, 0.05)
        return cls(count=n, first=k0, seed=sd, duration=dur, dt=step, envelope=envelope,
                   target=target, paper_target=is_paper, out=out, no_plots=no_plots)

    @property
    def paper(self) -> bool:
        """Whether the records are of the paper's set (taken from it: cached, identical
        numbering)."""
        from ..motions.synthetic import PAPER_COUNT, PAPER_SEED

        return (self.paper_target and self.seed == PAPER_SEED and 1 <= self.first
                and self.first + self.count - 1 <= PAPER_COUNT and self.duration is None
                and self.dt is None and self.envelope == "jennings")


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
def synth_cmd(**options):
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
        PERIOD_RANGE,
        Envelope,
        check_compatibility,
        seed_earthquakes,
        synthetic,
    )

    req = SynthRequest.from_options(**options)
    n, k0, sd, dur, step = req.count, req.first, req.seed, req.duration, req.dt
    target, out, no_plots = req.target, req.out, req.no_plots
    paper = req.paper
    if paper:  # records of the paper's set: take them from it (cached, identical numbering)
        recs = seed_earthquakes()[k0 - 1:k0 - 1 + n]
    else:
        env = Envelope(req.envelope, duration=20.0 if dur is None else dur)
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


@dataclasses.dataclass(frozen=True)
class SpectrumRequest:
    """``rocking motion spectrum``'s options, read and checked (:meth:`from_options`): the
    record read, the periods and the damping."""

    file: Path
    record: object
    units: str | None
    periods: np.ndarray
    damping: float
    plot_path: str | None
    no_plot: bool
    target: str
    as_json: bool

    @classmethod
    def from_options(cls, *, file, units, dt, damping, tmin, tmax, npts, plot_path, no_plot,
                     target, as_json):
        """The request of the command's options (click's values)."""
        from ..motions.spectra import log_periods

        zeta = _damping(damping)
        t_lo, t_hi = _time(tmin, "tmin"), _time(tmax, "tmax")
        n = integer(npts, "n", 2, 10000)
        step = _time(dt, "dt")
        p = Path(file)
        rec, _ = read_record_arg(p, "file", units, step)  # messages in option words
        T = log_periods(t_lo, t_hi, n)
        return cls(file=p, record=rec, units=units, periods=T, damping=zeta,
                   plot_path=plot_path, no_plot=no_plot, target=target, as_json=as_json)


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
def spectrum_cmd(**options):
    """Print and plot the elastic response spectrum of the record FILE.

    FILE is a PEER NGA .AT2 file (always in g) or CSV/whitespace columns (t, acc) or one
    acceleration column with --dt or a '# dt = ...' header line.
    """
    from matplotlib.figure import Figure

    from ..motions.ec8 import paper_target
    from ..motions.spectra import plot_spectra, response_spectra

    req = SpectrumRequest.from_options(**options)
    p, rec, units, T, zeta = req.file, req.record, req.units, req.periods, req.damping
    plot_path, no_plot, target, as_json = req.plot_path, req.no_plot, req.target, req.as_json
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


@dataclasses.dataclass(frozen=True)
class ShowRequest:
    """``rocking motion show``'s options, read and checked (:meth:`from_options`): the
    components read, as ``(label, record, source)``."""

    file: str
    components: tuple
    plot_path: str | None
    no_plot: bool

    @property
    def vertical(self):
        """The vertical record, or None."""
        return self.components[1][1] if len(self.components) > 1 else None

    @classmethod
    def from_options(cls, *, file, vertical, units, dt, plot_path, no_plot):
        """The request of the command's options (click's values)."""
        step = _time(dt, "dt")
        h, hs = read_record_arg(file, "file", units, step)
        comps = [("horizontal", h, hs)]
        if vertical is not None:
            v, vs = read_record_arg(vertical, "vertical", units, step)
            comps.append(("vertical", v, vs))
        return cls(file=file, components=tuple(comps), plot_path=plot_path, no_plot=no_plot)


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
def show_cmd(**options):
    """Summarise a record FILE and its vertical component: peaks, intensity, and where
    g + a_v <= 0 (the base falls faster than gravity: a block would leave the ground).

    FILE and V are files (.AT2, columns) or the names of built-in records (e.g.
    Rinaldi228 and RinaldiUP).
    """
    from matplotlib.figure import Figure

    req = ShowRequest.from_options(**options)
    file, comps, plot_path, no_plot = req.file, list(req.components), req.plot_path, req.no_plot
    h, v = comps[0][1], req.vertical
    vertical = None if v is None else comps[1][2]
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


# ----------------------------------------------------------------------------- floors
MAX_PLOTTED_FLOORS = 6
"""The PNGs of ``rocking motion floor`` show at most this many floors (the lowest, the
highest and floors evenly between); the CSV files have them all."""


def _items(text, flag: str, what: str) -> list[str]:
    items = [x.strip() for x in str(text).split(",")]
    if not all(items):
        raise ParameterError(f"{flag} must be {what} separated by commas, got {text!r}")
    return items


def _unique(values: list, flag: str, text) -> list:
    seen = set()
    for v in values:
        if v in seen:
            raise ParameterError(f"{flag}: {v:g} given twice, got {text!r}")
        seen.add(v)
    return sorted(values)


def floor_list(floors, height_ratios, building) -> list[dict]:
    """The places of ``--floors`` (``all`` by default, or ``0,1,3``) or ``--height-ratios``
    (``0.5,1``) as keyword arguments of :class:`~rocking.buildings.FloorMotion`
    (``{"floor": k}`` or ``{"height_ratio": x}``), bottom to top."""
    if floors is not None and height_ratios is not None:
        raise ParameterError("floors or height-ratios: give one, not both")
    if height_ratios is not None:
        shown = "heights z/H in [0, 1]"
        xs = [as_float("height-ratios", x) for x in
              _items(height_ratios, "height-ratios", shown)]
        for x in xs:
            if not 0.0 <= x <= 1.0:
                raise ParameterError(f"height-ratios must be {shown} (0 the ground, 1 the "
                                     f"top), got {height_ratios!r}")
        return [{"height_ratio": x}
                for x in _unique(xs, "height-ratios", height_ratios)]
    n = building.n_floors
    if n is None:
        raise ParameterError(f"floors: a {building.kind} building without storeys has no "
                             "floors; give --height-ratios X,Y (z/H in [0, 1]) or --storeys "
                             "N")
    text = "all" if floors is None else str(floors).strip()
    if text.lower() == "all":
        return [{"floor": k} for k in range(n + 1)]
    shown = f"'all' or floor numbers in 0..{n} (0 the ground, {n} the top)"
    ks = []
    for item in _items(text, "floors", shown):
        try:
            k = int(item)
        except ValueError:
            raise ParameterError(f"floors must be {shown} separated by commas, e.g. "
                                 f"0,1,{n}; got {floors!r}") from None
        if not 0 <= k <= n:
            raise ParameterError(f"floors must be in 0..{n} (0 the ground, {n} the top), "
                                 f"got {floors!r}")
        ks.append(k)
    return [{"floor": k} for k in _unique(ks, "floors", floors)]


def _plotted(n: int) -> list[int]:
    """Indices of at most MAX_PLOTTED_FLOORS of ``n`` places, both ends included."""
    if n <= MAX_PLOTTED_FLOORS:
        return list(range(n))
    return sorted({int(round(i)) for i in np.linspace(0, n - 1, MAX_PLOTTED_FLOORS)})


def _accelerations_figure(rec, rows, motions, shown, bname):
    from matplotlib.figure import Figure

    from ..plot import PALETTE, style_axes

    fig = Figure(figsize=(8.0, 1.5 * len(shown) + 1.0), layout="constrained")
    axes = fig.subplots(len(shown), 1, sharex=True, sharey=True, squeeze=False)[:, 0]
    end = max(motions[i].record.duration for i in shown)
    for ax, i in zip(axes, reversed(shown), strict=True):  # the top floor on top
        r, fr = rows[i], motions[i].record
        ax.plot(rec.t, rec.values / G, lw=0.6, color=PALETTE[6], alpha=0.6, label="ground")
        ax.plot(fr.t, fr.values / G, lw=0.7, color=PALETTE[0], label=r["where"])
        z = ("" if r["floor"] is None or np.isnan(r["height_ratio"])
             else f" (z/H = {r['height_ratio']:.3g})")
        ax.set_title(f"{r['where']}{z}: peak {r['pfa_ms2'] / G:.3g} g = "
                     f"{r['pfa_over_pga']:.3g} x PGA", fontsize=9, loc="left")
        style_axes(ax, "", "acc. (g)")
    axes[0].legend(fontsize=8, loc="upper right", ncol=2)
    axes[-1].set_xlabel("time (s)")
    axes[-1].set_xlim(0.0, end)
    more = "" if len(shown) == len(rows) else f" ({len(shown)} of {len(rows)} places)"
    fig.suptitle(f"{rec.name or 'record'} on the floors of a {bname}{more}", fontsize=10)
    return fig


def _spectra_figure(rec, rows, T, ground_psa, floor_psa, shown, zeta, T1, bname):
    from matplotlib.figure import Figure

    from ..buildings import code_floor_spectrum_ec8, plot_floor_spectrum

    ncol = min(3, len(shown))
    nrow = -(-len(shown) // ncol)
    fig = Figure(figsize=(4.2 * ncol, 3.4 * nrow + 0.5), layout="constrained")
    axes = fig.subplots(nrow, ncol, sharey=True, squeeze=False).ravel()
    pga = rec.pga
    for ax, i in zip(axes, reversed(shown), strict=False):  # the top floor first
        r = rows[i]
        refs = {}
        if not np.isnan(r["height_ratio"]):
            refs["EN 1998-1 Eq (4.25)"] = code_floor_spectrum_ec8(T, pga, r["height_ratio"],
                                                                  T1)
            refs["ASCE 7-22 $H_f$ × PGA"] = np.full(T.size, r["asce7_hf"] * pga)
        z = ("" if r["floor"] is None or np.isnan(r["height_ratio"])
             else f", z/H = {r['height_ratio']:.3g}")
        plot_floor_spectrum(ax, T, floor_psa[i], ground_psa, references=refs, damping=zeta,
                            units="g", label=r["where"], title=f"{r['where']}{z}")
    for ax in axes[len(shown):]:
        ax.set_visible(False)
    more = "" if len(shown) == len(rows) else f" ({len(shown)} of {len(rows)} places)"
    fig.suptitle(f"Floor response spectra: {rec.name or 'record'} (PGA {pga / G:.3g} g) "
                 f"in a {bname}{more}", fontsize=10)
    return fig


@dataclasses.dataclass(frozen=True)
class FloorRequest:
    """``rocking motion floor``'s options, read and checked (:meth:`from_options`): the
    record, the building, the places of its floors to write, the spectra's periods and
    damping."""

    record: object
    source: str
    """The record as the user named it (a file or a built-in record)."""
    building: object
    places: list
    """Keyword arguments of :class:`~rocking.buildings.FloorMotion`, bottom to top."""
    height_ratios: str | None
    """The text of ``--height-ratios`` (for messages)."""
    periods: np.ndarray
    damping: float
    no_plots: bool
    out: str

    @classmethod
    def from_options(cls, *, record, units, dt, building, storeys, building_period,
                     building_damping, building_params, floors, height_ratios, damping,
                     tmin, tmax, npts, no_plots, out):
        """The request of the command's options (click's values)."""
        from ..motions.spectra import log_periods

        if building is None:
            raise ParameterError("building: give --building KIND (sdof, shear, continuous, "
                                 "modal; 'rocking buildings' lists them)")
        zeta = _damping(damping)
        t_lo, t_hi = _time(tmin, "tmin"), _time(tmax, "tmax")
        n = integer(npts, "n", 2, 10000)
        step = _time(dt, "dt")
        bld, _ = make_building(building, storeys, building_period, building_damping,
                               building_params)
        places = floor_list(floors, height_ratios, bld)
        T = log_periods(t_lo, t_hi, n)
        rec, src = read_record_arg(record, "record", units, step)
        return cls(record=rec, source=src, building=bld, places=places,
                   height_ratios=height_ratios, periods=T, damping=zeta, no_plots=no_plots,
                   out=out)


def _floor_motions(req: FloorRequest) -> list:
    """The FloorMotion of each place (a height ratio that is not a floor: in the flags'
    words)."""
    from ..buildings import FloorMotion

    motions = []
    for where in req.places:
        try:
            motions.append(FloorMotion(req.record, req.building, **where))
        except ParameterError as e:  # a height ratio that is not a floor of the building
            words = {"height_ratio": ("height-ratios", req.height_ratios)}
            raise type(e)(one_line(in_flag_words(e, words))) from None
    return motions


def _floor_rows(req: FloorRequest, motions) -> list[dict]:
    """The rows of floors.csv (with ``where``, for the terminal)."""
    from ..buildings import asce7_hf, code_floor_spectrum_ec8

    rec, bld = req.record, req.building
    T1 = float(bld.periods[0])
    heights = bld.heights
    width = len(str(bld.n_floors or 0))
    rows = []
    for where, fm in zip(req.places, motions, strict=True):
        if "floor" in where:
            k = where["floor"]
            z = float(heights[k]) if heights is not None else math.nan
            name = f"floor_{k:0{width}d}.csv"
        else:
            k, z = None, where["height_ratio"]
            name = f"height_ratio_{z:g}.csv"
        known = not math.isnan(z)
        rows.append({"floor": k, "height_ratio": z, "file": name, "pga_ms2": rec.pga,
                     "pfa_ms2": fm.pga, "pfa_over_pga": fm.pga / rec.pga,
                     "asce7_hf": float(asce7_hf(z, T1)) if known else math.nan,
                     "ec8_rigid": float(code_floor_spectrum_ec8(0.0, 1.0, z, T1))
                     if known else math.nan,
                     "where": fm.where})
    return rows


def _write_floors(req: FloorRequest, rows, motions) -> list[str]:
    """OUT: the floor records, floors.csv, floor_spectra.csv and the PNGs (unless
    ``--no-plots``); the names of the PNGs written."""
    import pandas as pd

    from ..buildings import floor_spectrum
    from ..motions.io import write_csv
    from ..motions.spectra import response_spectrum

    rec, T, zeta = req.record, req.periods, req.damping
    folder = Path(req.out)
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise click.ClickException(f"cannot create {folder}: {e.strerror or e}") from None
    for r, fm in zip(rows, motions, strict=True):
        write_csv(fm.record, folder / r["file"])
    table = pd.DataFrame(rows).drop(columns="where")
    table["floor"] = table["floor"].astype("Int64")
    with atomic_path(folder / "floors.csv") as tmp:
        table.to_csv(tmp, index=False, float_format="%.10g")
    ground_psa = response_spectrum(rec, T, damping=zeta)
    floor_psa = [floor_spectrum(fm, periods=T, damping=zeta) for fm in motions]
    spectra = {"period_s": T, "ground_psa_ms2": ground_psa}
    for r, psa in zip(rows, floor_psa, strict=True):
        spectra[f"{r['file'][:-4]}_psa_ms2"] = psa
    with atomic_path(folder / "floor_spectra.csv") as tmp:
        pd.DataFrame(spectra).to_csv(tmp, index=False, float_format="%.10g")
    if req.no_plots:
        return []
    bld = req.building
    shown = _plotted(len(rows))
    _save(_accelerations_figure(rec, rows, motions, shown, bld.name),
          folder / "floor_accelerations.png")
    _save(_spectra_figure(rec, rows, T, ground_psa, floor_psa, shown, zeta,
                          float(bld.periods[0]), bld.name), folder / "floor_spectra.png")
    return ["floor_accelerations.png", "floor_spectra.png"]


def _echo_floors(req: FloorRequest, rows, motions, pngs) -> None:
    """The terminal: the record, the building, one line per place, the files."""
    rec, bld = req.record, req.building
    Ts = ", ".join(f"{t:.3g}" for t in bld.periods[:4]) + (", ..." if bld.n_modes > 4
                                                             else "")
    click.echo(f"record      {req.source}: {len(rec)} samples, dt = {rec.dt:g} s, PGA "
               f"{rec.pga:.4g} m/s^2 ({rec.pga / G:.3g} g)")
    click.echo(f"building    {bld.name}: T = {Ts} s, damping "
               f"{100 * float(bld.damping[0]):g} %")
    click.echo(f"floors      dt = {motions[-1].step:g} s, ring-down to t = "
               f"{max(fm.record.duration for fm in motions):.4g} s")
    click.echo(f"{'where':>14} {'z/H':>6} {'PFA (g)':>8} {'PFA/PGA':>8} {'ASCE7 Hf':>9} "
               f"{'EC8 rigid':>9}")
    for r in rows:
        z, hf, ec8 = (("-" if math.isnan(x) else f"{x:.4g}")
                      for x in (r["height_ratio"], r["asce7_hf"], r["ec8_rigid"]))
        click.echo(f"{r['where']:>14} {z:>6} {r['pfa_ms2'] / G:8.4g} "
                   f"{r['pfa_over_pga']:8.4g} {hf:>9} {ec8:>9}")
    if bld.heights is None and req.height_ratios is None:
        click.echo(f"            (a {bld.kind} building without floor heights: no z/H, "
                   "no code values)")
    click.echo(f"wrote       {Path(req.out)}/: {len(rows)} floor records (CSV: t s, acc "
               "m/s^2), floors.csv, floor_spectra.csv" + "".join(f", {p}" for p in pngs))


@motion.command("floor")
@click.argument("record")
@click.option("--units", metavar="U",
              help="Units of the record: g, m/s^2, cm/s^2 (gal); default g. The floor "
                   "records are written in m/s^2.")
@click.option("--dt", metavar="DT", help="Time step of a one-column record file (s).")
@building_options("The kind of building ('rocking buildings'): its floors filter the "
                  "record. Required.")
@click.option("--floors", metavar="K,...",
              help="Floors to write: all (default) or numbers, 0 the ground (e.g. 0,1,3).")
@click.option("--height-ratios", "height_ratios", metavar="X,...",
              help="Instead of --floors: heights z/H in [0, 1] (e.g. 0.5,1; a continuous "
                   "building).")
@click.option("--damping", default="5%", show_default=True, metavar="Z",
              help="Damping ratio of the floor spectra: 5% or 0.05.")
@click.option("--tmin", default="0.02", show_default=True, metavar="T",
              help="Shortest period of the spectra (s).")
@click.option("--tmax", default="4", show_default=True, metavar="T",
              help="Longest period of the spectra (s).")
@click.option("--n", "npts", default="100", show_default=True, metavar="N",
              help="Number of periods (log-spaced).")
@click.option("--no-plots", is_flag=True, help="Skip the PNGs.")
@click.option("--out", required=True, type=click.Path(file_okay=False),
              help="Folder for the floor records, floors.csv, floor_spectra.csv and PNGs.")
def floor_cmd(**options):
    """Filter the record RECORD through a building into the motion of its floors.

    RECORD is a file (.AT2, CSV or columns) or a built-in record's name (e.g.
    Rinaldi228). Writes, in OUT, each floor's absolute acceleration (CSV: t in s, acc in
    m/s^2, with the building's ring-down after the record), floors.csv (peak floor
    acceleration over PGA against ASCE 7-22 Hf and EN 1998-1), floor_spectra.csv
    (pseudo-acceleration, m/s^2) and the PNGs floor_accelerations.png and
    floor_spectra.png.
    """
    req = FloorRequest.from_options(**options)
    motions = _floor_motions(req)
    rows = _floor_rows(req, motions)
    pngs = _write_floors(req, rows, motions)
    _echo_floors(req, rows, motions, pngs)


# ----------------------------------------------------------------------------- select
SELECT_SHOWN_SKIPS = 10
"""``rocking motion select`` prints at most this many skipped files (all are in
selection.json)."""
SELECT_MIN_DURATION_S = 5.0
SELECT_MIN_CYCLES = 2.0
"""A candidate must last at least max(SELECT_MIN_DURATION_S, SELECT_MIN_CYCLES Tmax):
the spectrum is the peak response over the record (no free vibration after it), and the
peak of a lightly damped oscillator of period T comes within the cycles after the strong
pulses, so a record shorter than two cycles at the longest period cuts the response
where its peak would be; and a few seconds is less than the strong phase of any
earthquake record (EN 1998-1 3.2.3.1.2 asks 10 s of stationary part of an artificial
one): shorter files are fragments (a trigger, a test file, a cut download)."""
SELECT_SAME_SPECTRUM = 0.01
"""Two selected records whose spectra are in a ratio constant within 1 % over the period
range are noted as the same motion (one download in two formats, or a scaled copy)."""


def period_range(text) -> tuple[float, float, int]:
    """``TMIN:TMAX[:N]`` (s, or with a time unit: ``100ms:2s:50``) as ``(tmin, tmax, n)``;
    ``n`` defaults to 100."""
    shown = "TMIN:TMAX[:N] (periods in s, N >= 2 log-spaced; e.g. 0.1:2:50)"
    parts = [x.strip() for x in str(text).split(":")]
    if len(parts) not in (2, 3) or not all(parts):
        raise ParameterError(f"periods must be {shown}, got {text!r}")
    try:
        lo = parse_quantity(parts[0], "time", name="periods", default_unit="s")
        hi = parse_quantity(parts[1], "time", name="periods", default_unit="s")
    except ParameterError:
        raise ParameterError(f"periods must be {shown}, got {text!r}") from None
    if not (lo > 0 and math.isfinite(hi) and hi > lo):
        raise ParameterError(f"periods must have 0 < TMIN < TMAX (s), got {text!r}")
    n = integer(parts[2], "periods (N)", 2, 10000) if len(parts) == 3 else 100
    return lo, hi, n


def _return_period(text) -> float:
    s = str(text).strip()
    for word in ("years", "year", "yrs", "yr", "y"):
        if s.lower().endswith(word):
            s = s[: -len(word)].strip()
            break
    x = as_float("return-period", s)
    if not (math.isfinite(x) and x > 0):
        raise ParameterError(f"return-period must be > 0 years, got {text!r}")
    return x


def _hazard_curve(path, site, unit, investigation_time=None, max_distance_km=None):
    """A ``--hazard`` file (:func:`rocking.cli.common.read_hazard_option`)."""
    return read_hazard_option(path, site=site, unit=unit,
                              investigation_time=investigation_time,
                              max_distance_km=max_distance_km, file_name="hazard",
                              unit_name="--hazard-unit")


_TABLE_T = re.compile(r"^\s*(?:t|period|periods|tn)\s*(?:[_\s]\s*|[(\[]\s*)?([a-z]*)\s*[)\]]?\s*$",
                      re.I)
_TABLE_SA = re.compile(r"^\s*(?:sa|psa|se|s_a|sa_t|spectral[_\s]acceleration|acc\w*|target)"
                       r"(?:\s*\(\s*t\s*\))?\s*(?:[_\s]\s*|[(\[]\s*)?(.*?)\s*[)\]]?\s*$", re.I)


def read_target_table(path, unit=None) -> tuple[np.ndarray, np.ndarray, str, list[str]]:
    """A user's target spectrum: a CSV (or whitespace) table of period and spectral
    acceleration with a header row naming both (``T (s),Sa (g)``, ``period_s,sa_ms2``;
    ``#`` lines are comments). The Sa unit comes from the header or ``unit`` (both: they
    must agree); periods in s (or ms if the header says so). A row at T = 0 (the PGA) is
    left out: the match is log-log. Returns ``(periods s, values m/s^2, unit, notes)``."""
    from ..units import acceleration_factor, acceleration_unit

    p = Path(path)
    name = p.name
    try:
        text = p.read_text()
    except (OSError, UnicodeDecodeError) as e:
        raise ParameterError(f"target: cannot read {name} as text ({e})") from None
    lines = [ln for ln in text.splitlines() if ln.strip() and not ln.lstrip().startswith("#")]
    form = (f"target {name} must be a table of period (s) and Sa with a header row, e.g. "
            "'T (s),Sa (g)', and at least 2 rows")
    if len(lines) < 3:
        raise ParameterError(form)

    def cells(ln):
        return [c.strip() for c in (ln.split(",") if "," in ln else ln.split())]

    head = cells(lines[0])
    if len(head) != 2:
        raise ParameterError(f"{form}; its header has {len(head)} columns: {lines[0]!r}")
    mt, ms = _TABLE_T.match(head[0]), _TABLE_SA.match(head[1])
    if not mt or not ms:
        raise ParameterError(f"{form}; cannot read the header {lines[0]!r} as period and Sa")
    t_unit = mt[1].lower() or "s"
    if t_unit not in ("s", "ms", "sec"):
        raise ParameterError(f"target {name}: the period column's unit {mt[1]!r} is not s "
                             "or ms")
    t_factor = 1e-3 if t_unit == "ms" else 1.0
    stated = ms[1].strip()
    head_unit = None
    if stated:
        spelled = {"ms2": "m/s^2", "mps2": "m/s^2", "cms2": "cm/s^2"}.get(stated.lower(),
                                                                          stated)
        head_unit = acceleration_unit(spelled)
        if head_unit is None:
            raise ParameterError(f"target {name}: the Sa column's unit {stated!r} is not an "
                                 "acceleration unit (g, m/s^2, cm/s^2, gal)")
    given = None
    if unit is not None:
        given = acceleration_unit(unit)
        if given is None:
            raise ParameterError(f"target-unit must be an acceleration unit (g, m/s^2, "
                                 f"cm/s^2, gal), got {unit!r}")
    if head_unit and given and head_unit != given:
        raise ParameterError(f"target-unit {unit} contradicts {name}'s header "
                             f"{head[1]!r} ({head_unit})")
    u = head_unit or given
    if u is None:
        raise ParameterError(f"target-unit: {name}'s Sa column {head[1]!r} states no unit; "
                             "give --target-unit g (or m/s^2) or write the header as "
                             "'Sa (g)'")
    rows = []
    for k, ln in enumerate(lines[1:], 2):
        c = cells(ln)
        try:
            if len(c) != 2:
                raise ValueError
            rows.append((float(c[0]), float(c[1])))
        except ValueError:
            raise ParameterError(f"{form}; data row {k} is not two numbers: {ln!r}") from None
    data = np.array(rows)
    T, sa = data[:, 0] * t_factor, data[:, 1]
    notes = []
    if not (np.all(np.isfinite(data)) and np.all(T >= 0) and np.all(sa > 0)):
        raise ParameterError(f"target {name}: periods must be >= 0 and Sa > 0 (finite)")
    if np.any(T == 0):
        notes.append(f"target {name}: the row at T = 0 (PGA) is not used (the match is "
                     "log-log)")
        T, sa = T[T > 0], sa[T > 0]
    if T.size < 2 or np.any(np.diff(T) <= 0):
        raise ParameterError(f"target {name}: periods must increase, with at least 2 rows "
                             "at T > 0")
    return T, sa * acceleration_factor(u), u, notes


_VERTICAL = re.compile(r"^(?:UP|UD|DWN|DOWN|V|VER|VERT|VERTICAL|Z|HNZ|HGZ|HLZ|BNZ|EHZ|"
                       r"[A-Z]{2}Z|UP-DOWN|U-D)$", re.I)
"""Component names of a vertical record (AT2 ``UP``, K-NET ``UD``, ESM/SEED ``HNZ``, ...)."""


def _read_candidates(folder: Path, units, dt, tmax: float = 0.0):
    """Every regular file of ``folder`` that the record reader reads: ``(records,
    sources, files, skipped)`` with ``skipped`` a list of ``(file name, one-line reason)``.

    Skipped too: without ``units``, a file that states no unit (a column file; an AT2
    file is in g by the PEER convention, ``meta["units_from"]``); a vertical component;
    a record shorter than max(SELECT_MIN_DURATION_S, SELECT_MIN_CYCLES ``tmax``)."""
    from ..motions import Record

    step = None if dt is None else parse_quantity(dt, "time", name="dt", default_unit="s")
    records, sources, skipped = [], [], []
    files = sorted(p for p in folder.iterdir() if p.is_file())
    for p in files:
        try:
            if units is None:  # each file in the unit it states: a folder of downloads
                # mixes AT2 in g with ESM/COSMOS/K-NET in cm/s^2
                rec = Record.from_file(p, units=None, dt=step)
                if rec.meta.get("units_from") == "default":  # g would be a guess
                    skipped.append((p.name, "states no unit: pass --units to read such "
                                    "files"))
                    continue
            else:
                rec, _ = read_record_arg(p, p.name, units, dt)
            comp = str(rec.meta.get("component", "") or rec.meta.get("direction", ""))
            if _VERTICAL.match(comp.strip()):
                skipped.append((p.name, f"vertical component ({comp.strip()}): the target "
                                "is a horizontal spectrum"))
                continue
            need = max(SELECT_MIN_DURATION_S, SELECT_MIN_CYCLES * tmax)
            if rec.duration < need:
                skipped.append((p.name, f"too short: {rec.duration:.4g} s, less than "
                                f"{need:.4g} s (max of {SELECT_MIN_DURATION_S:g} s and "
                                f"{SELECT_MIN_CYCLES:g} cycles of the longest period "
                                f"{tmax:.4g} s)"))
                continue
        except RockingError as e:
            msg = one_line(e)
            for head in (f"{p}: ", f"{p.name}: ", f"file: {p}: ", f"{p.name}: {p}: "):
                if msg.startswith(head):  # the file is named in the list already
                    msg = msg[len(head):]
            skipped.append((p.name, msg))
            continue
        except Exception as e:  # a reader's own failure on a file it does not know
            skipped.append((p.name, f"{type(e).__name__}: {one_line(e)}"))
            continue
        records.append(rec)
        sources.append(p)
    return records, sources, files, skipped


def same_motion_notes(spectra, indices, names, periods,
                      rtol: float = SELECT_SAME_SPECTRUM) -> list[str]:
    """Notes naming the groups of selected candidates (``indices`` into the rows of
    ``spectra``) whose spectra are in a constant ratio, max/min of the ratio - 1 <= rtol
    over ``periods`` (pairs linked into groups): the same motion more than once (one
    download in two formats, a scaled copy), which the set then counts as two records."""
    idx = list(dict.fromkeys(int(i) for i in indices))
    group = {i: i for i in idx}  # union-find over the linked pairs

    def root(i):
        while group[i] != i:
            i = group[i]
        return i

    spread: dict[int, float] = {}
    for a in range(len(idx)):
        for b in range(a + 1, len(idx)):
            r = np.asarray(spectra[idx[a]]) / np.asarray(spectra[idx[b]])
            sp = float(r.max() / r.min() - 1.0)
            if sp <= rtol:
                ra, rb = root(idx[a]), root(idx[b])
                group[rb] = ra
                spread[ra] = max(spread.get(ra, 0.0), spread.pop(rb, 0.0), sp)
    out = []
    for g in dict.fromkeys(root(i) for i in idx):
        members = [names[i] for i in idx if root(i) == g]
        if len(members) > 1:
            out.append(f"{', '.join(members[:-1])} and {members[-1]} have nearly identical "
                       f"spectra (in ratios constant within {100 * spread[g]:.2g} % from "
                       f"{periods[0]:.4g} to {periods[-1]:.4g} s): likely one motion (in "
                       f"{len(members)} formats, or scaled copies) selected {len(members)} "
                       "times; keep one of these files to count it once")
    return out


# ----------------------------------------------------------------------------- select request
def _max_scale(text) -> float:
    """``--max-scale F``, a number >= 1."""
    try:
        ms = as_float("max-scale", text)
    except ParameterError:
        ms = math.nan
    if not (math.isfinite(ms) and ms >= 1.0):
        raise ParameterError(f"max-scale must be a number >= 1 (scale factors within "
                             f"[1/F, F]), got {text!r}")
    return ms


def _target_kind(target) -> str:
    """``ec8``, ``uhs`` (in any case) or the text of a table's path."""
    kind = str(target).strip()
    return kind.lower() if kind.lower() in ("ec8", "uhs") else kind


def _check_target_flags(kind: str, ec8_flags: tuple, uhs_flags: tuple) -> None:
    """The flags of a target kind given with another kind are refused (``uhs_flags``: the
    hazard files, return period, site, hazard unit, investigation time, max distance)."""
    if kind != "ec8" and any(ec8_flags):
        raise ParameterError("ag, ground and type apply to --target ec8 only")
    files, return_period, site, hazard_unit, investigation_time, max_distance_km = uhs_flags
    if kind != "uhs" and (files or return_period or site or hazard_unit
                          or investigation_time is not None or max_distance_km is not None):
        raise ParameterError("hazard, return-period, site, hazard-unit, investigation-time "
                             "and max-distance-km apply to --target uhs only")


def _check_target(kind: str, target_unit, zeta: float, damping) -> None:
    """``--target-unit`` with a table only, 5 % damping with ``uhs``, a table that exists."""
    if kind in ("ec8", "uhs") and target_unit is not None:
        raise ParameterError("target-unit applies to a target table (--target FILE.csv) "
                             "only")
    if kind == "uhs" and not math.isclose(zeta, 0.05):
        raise ParameterError(f"damping must be 5% with --target uhs (hazard models give "
                             f"5 %-damped SA), got {damping!r}")
    if kind not in ("ec8", "uhs") and not Path(kind).is_file():
        raise ParameterError(f"target must be ec8, uhs or a table file; no such file "
                             f"{kind!r}")


def _selection_periods(periods, specimen, params_set, width, height, alpha, p, mu):
    """``(periods, period range description)``: ``--periods`` or the default range of the
    block of the block flags (one of them)."""
    from ..analysis.selection import default_periods

    block_given = any(v is not None for v in (specimen, width, height, alpha)) \
        or bool(mesh_flags())
    if periods is not None and block_given:
        raise ParameterError("periods: give --periods or a block (its default range), not "
                             "both")
    if periods is not None:
        lo, hi, npts = period_range(periods)
        T = np.geomspace(lo, hi, npts)
        prange = {"source": "--periods", "text": str(periods),
                  "why": "given (--periods)"}
    elif block_given:
        block, binfo = make_block(specimen, params_set, width, height, None, alpha, p, mu,
                                  allow_classical=True)
        T = default_periods(block)
        prange = {"source": "block", "block": {**binfo, "name": block.name, "p": block.p,
                                               "alpha": block.alpha},
                  "why": (f"default of the block {block.name} (p = {block.p:.4g} 1/s): "
                          f"2 pi/(10 p) to 2 pi/p, the pulse periods that govern "
                          f"overturning (omega_p/p from 1 to 10; "
                          f"rocking.analysis.selection.default_periods)")}
    else:
        raise ParameterError("periods: give --periods TMIN:TMAX[:N] (s) or a block for its "
                             "default range (--specimen N, --width W --height H, --alpha "
                             "A --p P --mu MU, --mesh FILE)")
    prange.update({"tmin_s": float(T[0]), "tmax_s": float(T[-1]), "n_periods": int(T.size)})
    return T, prange


@dataclasses.dataclass(frozen=True)
class SelectRequest:
    """``rocking motion select``'s options, read and checked before any file is read
    (:meth:`from_options`); :func:`select_cmd` runs it."""

    folder: str
    target: str
    """``ec8``, ``uhs`` or the path of a target table."""
    count: str
    """The text of ``--n`` (for messages)."""
    n: int
    max_scale: float
    restarts: int
    damping: float
    units: str | None
    dt: float | None
    periods: np.ndarray
    period_range: dict
    periods_given: bool
    ag: str | None
    ground: str | None
    stype: str | None
    hazard_files: tuple[str, ...]
    return_period: str | None
    site: str | None
    hazard_unit: str | None
    investigation_time: float | None
    max_distance_km: float | None
    target_unit: str | None
    out: str
    no_plot: bool
    as_json: bool

    @classmethod
    def from_options(cls, *, folder, target, count, max_scale, periods, specimen, params_set,
                     width, height, alpha, p, mu, damping, units, dt, ag, ground, stype,
                     hazard_files, return_period, site, hazard_unit, investigation_time,
                     max_distance_km, target_unit, restarts, out, no_plot, as_json):
        """The request of the command's options (click's values), checked in the order
        of the flags' messages."""
        from ..units import acceleration_unit

        n = integer(count, "n", 1)
        ms = _max_scale(max_scale)
        k_restarts = integer(restarts, "restarts", 1, 1000)
        zeta = _damping(damping)
        if units is not None and acceleration_unit(units) is None:
            raise ParameterError(f"units must be g, m/s^2, cm/s^2, gal or mm/s^2, got "
                                 f"{units!r}")
        step = _time(dt, "dt")
        kind = _target_kind(target)
        _check_target_flags(kind, (ag, ground, stype),
                            (hazard_files, return_period, site, hazard_unit,
                             investigation_time, max_distance_km))
        inv_t = years_option(investigation_time)
        dmax = km_option(max_distance_km)
        _check_target(kind, target_unit, zeta, damping)
        T, prange = _selection_periods(periods, specimen, params_set, width, height, alpha,
                                       p, mu)
        return cls(folder=folder, target=kind, count=count, n=n, max_scale=ms,
                   restarts=k_restarts, damping=zeta, units=units, dt=step, periods=T,
                   period_range=prange, periods_given=periods is not None, ag=ag,
                   ground=ground, stype=stype, hazard_files=tuple(hazard_files),
                   return_period=return_period, site=site, hazard_unit=hazard_unit,
                   investigation_time=inv_t, max_distance_km=dmax, target_unit=target_unit,
                   out=out, no_plot=no_plot, as_json=as_json)


# ----------------------------------------------------------------------------- select steps
def _ec8_target(req: SelectRequest):
    """``(spectrum, description)`` of ``--target ec8``."""
    spec, is_paper = _target(req.ag, req.ground, req.stype, req.damping)
    return spec, {"kind": "ec8", "description": spec.describe(), "label": spec.name,
                  "paper_target": is_paper, "ag": req.ag,
                  "ground": (req.ground or "A").upper() if req.ag else None,
                  "type": int(req.stype or 1) if req.ag else None}


def _uhs_notes(files, curves, tr: float) -> list[str]:
    """Notes on the hazard curves of a uniform hazard spectrum at ``tr`` years."""
    notes = []
    for f, c in zip(files, curves, strict=True):
        if c.im_name.strip().upper() == "PGA":
            notes.append(f"hazard {Path(f).name}: a PGA curve is not used (T = 0 "
                         "has no log)")
        elif not (c.rate[-1] <= 1.0 / tr <= c.rate[0]):
            notes.append(f"hazard {Path(f).name}: 1/{tr:g} per year is beyond the "
                         f"curve's rates: {c.im_name} extrapolated as a power law")
        if c.approximate:
            notes.append(f"hazard {Path(f).name}: an approximation ({c.label})")
    return notes


def _uhs_target(req: SelectRequest):
    """``(periods, Sa, description, notes)`` of ``--target uhs``."""
    from ..analysis.selection import uniform_hazard_spectrum

    if not req.hazard_files:
        raise ParameterError("hazard: --target uhs needs SA(T) hazard curves: "
                             "--hazard FILE, repeatable (>= 2 periods)")
    tr = _return_period(475.0 if req.return_period is None else req.return_period)
    curves = [_hazard_curve(f, req.site, req.hazard_unit, req.investigation_time,
                            req.max_distance_km) for f in req.hazard_files]
    try:
        tp, tv = uniform_hazard_spectrum(curves, tr)
    except ParameterError as e:
        raise ParameterError(f"hazard: {one_line(e)}") from None
    used = [c for c in curves if c.im_name.strip().upper() != "PGA"]
    notes = _uhs_notes(req.hazard_files, curves, tr)
    desc = (f"uniform hazard spectrum at {tr:g} years (annual rate {1 / tr:.4g}) "
            f"from {len(used)} SA curves, T = {tp[0]:g} to {tp[-1]:g} s, 5 % damping")
    tinfo = {"kind": "uhs", "description": desc,
             "label": f"uniform hazard spectrum, {tr:g} years", "return_period": tr,
             "hazard": [{"file": str(f), "label": c.label, "im_name": c.im_name,
                         "unit": c.unit, "approximate": c.approximate,
                         "site_distance_km": getattr(c, "metadata", {}).get(
                             "site_distance_km")}
                        for f, c in zip(req.hazard_files, curves, strict=True)],
             "uhs_period_s": tp.tolist(), "uhs_sa_ms2": tv.tolist()}
    return tp, tv, tinfo, notes


def _table_target(req: SelectRequest):
    """``(periods, Sa, description, notes)`` of ``--target FILE``."""
    tp, tv, tu, notes = read_target_table(req.target, req.target_unit)
    name = Path(req.target).name
    tinfo = {"kind": "table",
             "description": f"table {name}: {tp.size} periods from {tp[0]:g} to "
                            f"{tp[-1]:g} s, Sa in {tu}, {100 * req.damping:g} % damping",
             "label": f"table {name}", "file": str(req.target), "unit": tu}
    return tp, tv, tinfo, notes


def _selection_target(req: SelectRequest):
    """``(target of select_records, its description, notes)``; a tabulated target (uhs,
    table) must cover the periods: it is not extrapolated."""
    if req.target == "ec8":
        spec, tinfo = _ec8_target(req)
        return spec, tinfo, []
    make = _uhs_target if req.target == "uhs" else _table_target
    tp, tv, tinfo, notes = make(req)
    T = req.periods
    if T[0] < tp[0] * (1 - 1e-9) or T[-1] > tp[-1] * (1 + 1e-9):
        what = "--periods" if req.periods_given else "the block's default range"
        raise ParameterError(f"periods: {what} ({T[0]:.4g} to {T[-1]:.4g} s) reaches "
                             f"beyond the target's periods ({tp[0]:.4g} to "
                             f"{tp[-1]:.4g} s), which are not extrapolated: narrow "
                             "--periods or extend the target")
    return (tp, tv), tinfo, notes


def _selection_candidates(req: SelectRequest):
    """``(records, sources, files, skipped)`` of FOLDER (:func:`_read_candidates`), after
    the checks of FOLDER and OUT; at least ``n`` records."""
    folder = req.folder
    src = Path(folder)
    if not src.exists():
        raise ParameterError(f"FOLDER: no such folder {folder!r}")
    if not src.is_dir():
        raise ParameterError(f"FOLDER: {folder!r} is not a folder (give the folder that "
                             "holds the record files)")
    dest = Path(req.out)
    if dest.exists() and dest.resolve() == src.resolve():
        raise ParameterError("out must not be FOLDER itself (the scaled records would "
                             "become candidates of the next run)")
    records, sources, files, skipped = _read_candidates(src, req.units, req.dt,
                                                        float(req.periods[-1]))
    if not records:
        first = f"; e.g. {skipped[0][0]}: {skipped[0][1]}" if skipped else ""
        raise ParameterError(f"FOLDER: no record file in {folder} ({len(files)} files, none "
                             f"read{first})")
    if req.n > len(records):
        raise ParameterError(f"n must be <= the number of readable records in FOLDER "
                             f"({len(records)} of {len(files)} files), got {req.count!r}")
    return records, sources, files, skipped


def _run_selection(req: SelectRequest, records, tfun):
    """``(candidate spectra, SelectionResult)``: the spectra once per candidate, then
    :func:`rocking.analysis.select_records` (its non-compliance warning is the command's
    own; other warnings pass on)."""
    from ..analysis.selection import candidate_spectra, select_records
    from ..errors import PlausibilityWarning

    S = candidate_spectra(records, req.periods, req.damping)  # once per candidate
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", PlausibilityWarning)
        res = select_records(S, tfun, req.periods, n=req.n, max_scale=req.max_scale,
                             damping=req.damping, restarts=req.restarts)
    for w in caught:  # the non-compliance warning is ours below; others pass on
        if not (issubclass(w.category, PlausibilityWarning)
                and "NOT compliant" in str(w.message)):
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    return S, res


def _selection_rows(res, records, sources, n: int):
    """``(rows of selection.csv, [(scaled record, file name, spectrum)])``, ranked by each
    record's own misfit."""
    from ..analysis.selection import log_misfit

    per = [log_misfit(s, res.target) for s in res.spectra]
    order = np.argsort(per, kind="stable")
    width_ = max(2, len(str(n)))
    rows, chosen = [], []
    for rank, j in enumerate(order, 1):
        i, s = int(res.indices[j]), float(res.scales[j])
        rec = records[i].scaled(s)
        stem = sources[i].stem
        name = f"{rank:0{width_}d}_{stem}.csv"
        ratio = res.spectra[j] / res.target
        rows.append({"rank": rank, "file": name, "source": sources[i].name, "scale": s,
                     "pga_ms2": rec.pga, "pga_g": rec.pga / G, "misfit": per[j],
                     "min_ratio": float(ratio.min()), "max_ratio": float(ratio.max()),
                     "dt_s": rec.dt, "npts": len(rec), "duration_s": rec.duration})
        chosen.append((rec, name, res.spectra[j]))
    return rows, chosen


def _selection_figure(req: SelectRequest, res, label: str, path: Path) -> None:
    """selection.png: the selection's spectra and the target, the period range marked."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(8.0, 5.0), layout="constrained")
    ax = res.plot(ax=fig.add_subplot())
    for x in (res.periods[0], res.periods[-1]):
        ax.axvline(x, color="0.4", lw=0.8, ls=":")
    ax.set_xlabel(f"period T (s): {res.periods[0]:.3g} to {res.periods[-1]:.3g} s, "
                  + ("--periods" if req.periods_given else "the block's range "
                     "2 pi/(10 p) to 2 pi/p"))
    ax.set_ylabel(f"Sa (m/s^2), {100 * req.damping:g} % damping")
    ax.set_title(f"{ax.get_title()}\ntarget: {label}", fontsize=10)
    _save(fig, path)


def _write_selection(req: SelectRequest, res, rows, chosen, summary: dict) -> None:
    """OUT: the scaled records, selection.csv, selection_spectra.csv, selection.json and
    (unless ``--no-plot``) selection.png."""
    import pandas as pd

    from ..analysis.selection import CODE_RATIO
    from ..motions.io import write_csv

    dest = Path(req.out)
    try:
        dest.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise click.ClickException(f"cannot create {dest}: {e.strerror or e}") from None
    for rec, name, _ in chosen:
        write_csv(rec, dest / name)
    with atomic_path(dest / "selection.csv") as tmp:
        pd.DataFrame(rows).to_csv(tmp, index=False, float_format="%.10g")
    cols = {"period_s": res.periods, "target_ms2": res.target,
            "target_90_ms2": CODE_RATIO * res.target, "mean_ms2": res.mean}
    for _, name, s in chosen:
        cols[f"{name[:-4]}_ms2"] = s
    with atomic_path(dest / "selection_spectra.csv") as tmp:
        pd.DataFrame(cols).to_csv(tmp, index=False, float_format="%.10g")
    atomic_write(dest / "selection.json",
                 json.dumps(summary, indent=2, default=json_default) + "\n")
    if not req.no_plot:
        _selection_figure(req, res, summary["target"]["label"], dest / "selection.png")


def _echo_selection(req: SelectRequest, res, summary: dict) -> None:
    """The terminal: the non-compliance warning (stderr), then selection.json (``--json``)
    or the summary."""
    n, ms, T = req.n, req.max_scale, req.periods
    if not res.compliant:
        click.echo(f"warning: the mean of the {n} selected records is "
                   f"{100 * res.min_ratio:.1f} % of the target at worst (< 90 %, EN 1998-1 "
                   f"3.2.3.1.2) with scale factors <= --max-scale {ms:g}: NOT compliant "
                   "(compliant=false in selection.json)", err=True)
    if req.as_json:
        click.echo(json.dumps(summary, indent=2, default=json_default))
        return
    skipped = summary["skipped"]
    click.echo(f"candidates  {summary['candidates']} records read in {summary['folder']} "
               f"({summary['files']} files"
               + (f", {len(skipped)} skipped)" if skipped else ")"))
    for s in skipped[:SELECT_SHOWN_SKIPS]:
        click.echo(f"skipped     {s['file']}: {s['reason']}")
    if len(skipped) > SELECT_SHOWN_SKIPS:
        click.echo(f"            ... {len(skipped) - SELECT_SHOWN_SKIPS} more "
                   "(selection.json)")
    click.echo(f"target      {summary['target']['description']}")
    click.echo(f"periods     {T.size} from {T[0]:.4g} to {T[-1]:.4g} s: "
               f"{req.period_range['why']}")
    sc = res.scales
    click.echo(f"selection   {n} records, scale factors {sc.min():.3g} to {sc.max():.3g} "
               f"(max-scale {ms:g}), misfit {res.misfit:.3g} (RMS log ratio), mean >= "
               f"{100 * res.min_ratio:.1f} % of the target: "
               + ("compliant (>= 90 %)" if res.compliant else "NOT compliant (< 90 %)"))
    click.echo(f"{'rank':>6}  {'scale':>7} {'PGA (g)':>8} {'misfit':>7} {'min ratio':>9}"
               "  source")
    for r in summary["records"]:
        click.echo(f"{r['rank']:>6}  {r['scale']:7.3g} {r['pga_g']:8.3g} {r['misfit']:7.3g} "
                   f"{r['min_ratio']:9.3g}  {r['source']}")
    for note in summary["notes"]:
        click.echo(f"note        {note}")
    click.echo(f"wrote       {Path(req.out)}/: {n} records (CSV: t s, acc m/s^2; read back "
               "with --units m/s^2), selection.csv, selection_spectra.csv, selection.json"
               + ("" if req.no_plot else ", selection.png"))


@motion.command("select")
@click.argument("folder", metavar="FOLDER")
@click.option("--target", "target", required=True, metavar="ec8|uhs|FILE",
              help="The target spectrum: ec8 (with --ag, --ground, --type; without --ag the "
                   "paper's target), uhs (uniform hazard spectrum of --hazard curves at "
                   "--return-period) or a CSV table FILE of period (s) and Sa.")
@click.option("--n", "count", default="11", show_default=True, metavar="N",
              help="Number of records to select (EN 1998-1 asks for >= 3; 7 for the mean "
                   "response).")
@click.option("--max-scale", "max_scale", default="4", show_default=True, metavar="F",
              help="Scale factors within [1/F, F] (F >= 1).")
@click.option("--periods", metavar="TMIN:TMAX[:N]",
              help="Periods of the match (s), N log-spaced (default 100); or give a block "
                   "(--specimen N, --width/--height, ...) for its default range.")
@block_options(classical=True)
@click.option("--damping", default="5%", show_default=True, metavar="Z",
              help="Damping ratio of the spectra: 5% or 0.05 (a target table must refer to "
                   "it; uhs: 5 % only).")
@click.option("--units", metavar="U",
              help="Units of the record files: g, m/s^2, cm/s^2 (gal). Default: each "
                   "file's own stated unit (ESM, COSMOS, K-NET: cm/s^2; AT2: g); a file "
                   "that states none is skipped. Given, a unit a file states must agree "
                   "(else the file is skipped).")
@click.option("--dt", metavar="DT", help="Time step of one-column record files (s).")
@click.option("--ag", metavar="AG", help="ec8: design ground acceleration, e.g. 0.25g.")
@click.option("--ground", type=click.Choice(list("ABCDE"), case_sensitive=False),
              help="ec8: ground type (with --ag; default A).")
@click.option("--type", "stype", type=click.Choice(["1", "2"]),
              help="ec8: spectrum type (with --ag; default 1).")
@click.option("--hazard", "hazard_files", multiple=True, metavar="FILE",
              help="uhs: an SA(T) hazard curve, repeatable (OpenQuake hazard_curve export, "
                   "or CSV of IM and annual rate or return period with a header such as "
                   "'SA(0.5) (g),rate').")
@click.option("--return-period", "return_period", default=None, metavar="YEARS",
              help="uhs: return period of the spectrum (default 475 years).")
@click.option("--site", metavar="IDX|LON,LAT",
              help="uhs: the site of OpenQuake exports (index, or nearest to LON,LAT; "
                   "default 0).")
@click.option("--hazard-unit", "hazard_unit", metavar="U",
              help="uhs: unit of CSV curves whose header states none (g, m/s^2).")
@click.option("--investigation-time", "investigation_time", metavar="YEARS",
              help="uhs: the years T of CSV curves of a probability of exceedance (poe), "
                   "read as rate = -ln(1 - poe)/T.")
@click.option("--max-distance-km", "max_distance_km", metavar="KM",
              help="uhs: refuse an OpenQuake site (--site LON,LAT) whose nearest row is "
                   "farther than this (default 50 km).")
@click.option("--target-unit", "target_unit", metavar="U",
              help="Target table: unit of Sa if its header states none (g, m/s^2, cm/s^2).")
@click.option("--restarts", default="8", show_default=True, metavar="K",
              help="The search is repeated from the K best first records.")
@click.option("--out", required=True, type=click.Path(file_okay=False),
              help="Folder for the scaled records, selection.csv, selection_spectra.csv, "
                   "selection.json and selection.png.")
@click.option("--no-plot", is_flag=True, help="Do not write selection.png.")
@click.option("--json", "as_json", is_flag=True, help="Print selection.json instead of "
                                                      "the summary.")
def select_cmd(**options):
    """Select N amplitude-scaled records from the files in FOLDER whose mean spectrum
    matches a target (EN 1998-1 3.2.3.1.2: the mean not below 90 % of the target at any
    period of the range; rocking.analysis.select_records).

    \b
    FOLDER: every file that the record reader reads is a candidate (PEER .AT2, CSV or
    columns, and the downloaded formats the reader detects); files it refuses are listed
    as skipped, with the reason, and so are, without --units, files that state no unit
    (an AT2 file without its units line is in g, the PEER convention), vertical
    components, and records shorter than max(5 s, 2 Tmax). Two selected records with
    spectra in a ratio constant within 1 % (one motion in two formats) are named in a
    note. The spectra are computed once per candidate.
    \b
    Targets:
      ec8        EN 1998-1 elastic spectrum: --ag 0.25g [--ground C] [--type 1]
                 (without --ag: the paper's target, rocking motion synth)
      uhs        uniform hazard spectrum: --hazard FILE (repeatable; one SA(T) curve per
                 period, >= 2 periods) [--return-period 475] [--site IDX|LON,LAT]
                 [--max-distance-km 50] [--investigation-time T (CSV of poe)]
      FILE.csv   a table of period (s) and Sa, header e.g. 'T (s),Sa (g)' (or
                 --target-unit g); log-log interpolated, never extrapolated
    \b
    Periods: --periods TMIN:TMAX[:N], or a block (--specimen 2, --width 0.2 --height 1,
    ...): its default range runs from 2 pi/(10 p) to 2 pi/p (p the block's frequency
    parameter, 1/s). A rocking block is not an oscillator: pulses of period 2 pi/omega_p
    overturn it at little more than the static g tan(alpha) when omega_p/p < 1, and at
    accelerations that grow fast above it, beyond earthquake levels for omega_p/p > 10
    (overturning spectra; rocking.analysis.selection.default_periods).
    \b
    Writes to OUT: the N records scaled (CSV t s, acc m/s^2: read them back with
    --units m/s^2, e.g. rocking simulate --record OUT/01_x.csv --units m/s^2),
    selection.csv (rank by each record's own misfit, file, source, scale, PGA after
    scaling, misfit, min and max ratio to the target), selection_spectra.csv, selection.json
    (target, period range and why, n, max_scale, misfit, min_ratio, compliant, notes,
    skipped files) and selection.png. A set that cannot meet the 90 % rule within
    --max-scale is still written, with compliant=false and a one-line warning (exit 0):
    it is the best the candidates allow, and the warning and the JSON say it is not
    compliant.
    """
    from ..analysis.selection import CODE_RATIO

    req = SelectRequest.from_options(**options)
    tfun, tinfo, notes = _selection_target(req)
    records, sources, files, skipped = _selection_candidates(req)
    S, res = _run_selection(req, records, tfun)
    notes += res.notes
    notes += same_motion_notes(S, res.indices, [p.name for p in sources], req.periods)
    rows, chosen = _selection_rows(res, records, sources, req.n)
    summary = {
        "folder": str(Path(req.folder)), "files": len(files), "candidates": len(records),
        "skipped": [{"file": f, "reason": r} for f, r in skipped],
        "target": tinfo, "period_range": req.period_range, "damping": req.damping,
        "n": req.n, "max_scale": req.max_scale, "restarts": req.restarts,
        "misfit": res.misfit, "min_ratio": res.min_ratio, "code_ratio": CODE_RATIO,
        "compliant": res.compliant, "notes": notes, "records": rows,
        "records_units": "m/s^2", "out": str(Path(req.out))}
    _write_selection(req, res, rows, chosen, summary)
    _echo_selection(req, res, summary)


__all__ = ["motion", "synth_cmd", "spectrum_cmd", "show_cmd", "floor_cmd", "floor_list",
           "select_cmd", "period_range", "read_target_table", "same_motion_notes"]
