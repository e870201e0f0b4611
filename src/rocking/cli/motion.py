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

import json
import math
from pathlib import Path

import click
import numpy as np

from .._atomic import atomic_path, atomic_write
from .._validate import as_float
from ..errors import ParameterError
from ..units import G, parse_quantity
from .common import (
    CONTEXT,
    building_options,
    in_flag_words,
    integer,
    make_building,
    one_line,
    positive_quantity,
    read_record_arg,
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
def floor_cmd(record, units, dt, building, storeys, building_period, building_damping,
              building_params, floors, height_ratios, damping, tmin, tmax, npts, no_plots,
              out):
    """Filter the record RECORD through a building into the motion of its floors.

    RECORD is a file (.AT2, CSV or columns) or a built-in record's name (e.g.
    Rinaldi228). Writes, in OUT, each floor's absolute acceleration (CSV: t in s, acc in
    m/s^2, with the building's ring-down after the record), floors.csv (peak floor
    acceleration over PGA against ASCE 7-22 Hf and EN 1998-1), floor_spectra.csv
    (pseudo-acceleration, m/s^2) and the PNGs floor_accelerations.png and
    floor_spectra.png.
    """
    import pandas as pd

    from ..buildings import FloorMotion, asce7_hf, code_floor_spectrum_ec8, floor_spectrum
    from ..motions.io import write_csv
    from ..motions.spectra import log_periods, response_spectrum

    if building is None:
        raise ParameterError("building: give --building KIND (sdof, shear, continuous, "
                             "modal; 'rocking buildings' lists them)")
    zeta = _damping(damping)
    t_lo, t_hi = _time(tmin, "tmin"), _time(tmax, "tmax")
    n = integer(npts, "n", 2, 10000)
    step = _time(dt, "dt")
    bld, bdesc = make_building(building, storeys, building_period, building_damping,
                               building_params)
    places = floor_list(floors, height_ratios, bld)
    T = log_periods(t_lo, t_hi, n)
    rec, src = read_record_arg(record, "record", units, step)

    motions = []
    for where in places:
        try:
            motions.append(FloorMotion(rec, bld, **where))
        except ParameterError as e:  # a height ratio that is not a floor of the building
            words = {"height_ratio": ("height-ratios", height_ratios)}
            raise type(e)(one_line(in_flag_words(e, words))) from None
    T1 = float(bld.periods[0])
    heights = bld.heights
    width = len(str(bld.n_floors or 0))
    rows = []
    for where, fm in zip(places, motions, strict=True):
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

    folder = Path(out)
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
    pngs = []
    if not no_plots:
        shown = _plotted(len(rows))
        _save(_accelerations_figure(rec, rows, motions, shown, bld.name),
              folder / "floor_accelerations.png")
        _save(_spectra_figure(rec, rows, T, ground_psa, floor_psa, shown, zeta, T1,
                              bld.name), folder / "floor_spectra.png")
        pngs = ["floor_accelerations.png", "floor_spectra.png"]

    Ts = ", ".join(f"{t:.3g}" for t in bld.periods[:4]) + (", ..." if bld.n_modes > 4
                                                             else "")
    click.echo(f"record      {src}: {len(rec)} samples, dt = {rec.dt:g} s, PGA "
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
    if heights is None and height_ratios is None:
        click.echo(f"            (a {bld.kind} building without floor heights: no z/H, "
                   "no code values)")
    click.echo(f"wrote       {folder}/: {len(rows)} floor records (CSV: t s, acc m/s^2), "
               "floors.csv, floor_spectra.csv" + "".join(f", {p}" for p in pngs))


__all__ = ["motion", "synth_cmd", "spectrum_cmd", "show_cmd", "floor_cmd", "floor_list"]
