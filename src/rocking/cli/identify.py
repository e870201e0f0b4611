"""``rocking identify``: free-rocking identification of alpha, p, mu from a CSV record.

::

    rocking identify RECORD.csv [--units rad|deg] [--block-width 170mm --block-height 1m]
        [--time-col t --angle-col theta] [--offset auto] [--out identify_out] [--json]

Prints a Table II-style comparison of the theoretical parameters (Eqs 2-4 of the block
given by ``--block-width``/``--block-height``) with the identified ones, and writes
``error_surface.png``, ``fit.png``, ``fit.json`` and ``half_cycles.csv`` into ``--out``.
The command is a plain :func:`click.command`; :mod:`rocking.cli` registers it. Bad input
raises :class:`~rocking.errors.RockingError`, which ``rocking``'s entry point prints as one
``error: ...`` line.
"""

from __future__ import annotations

import json
import math
import warnings
from pathlib import Path

import click
import numpy as np

from .._atomic import atomic_path, atomic_write
from .._validate import as_float
from ..blocks import Block, housner_mu
from ..errors import ParameterError
from ..results import jsonable
from .common import CONTEXT, json_default, positive_quantity


def _theoretical(width, height):
    """(Block or None, dict of T parameters or None); mu is NaN where Eq 4 gives mu <= 0."""
    if width is None and height is None:
        return None, None
    if width is None or height is None:
        raise ParameterError("give both --block-width and --block-height (the full width 2b "
                             "and height 2h of the block) for the theoretical parameters")
    try:
        block = Block.rectangular(width, height, name="theoretical")
        mu = block.mu
    except ParameterError:  # squat block: Eq 4 gives mu <= 0
        block = Block.rectangular(width, height, mu=1.0, name="theoretical")
        mu = float("nan") if housner_mu(block.alpha) <= 0 else housner_mu(block.alpha)
    return block, {"alpha": block.alpha, "p": block.p, "mu": mu}


def _offset(text, units):
    if text is None:
        return "auto"
    key = str(text).strip().lower()
    if key in ("auto", "rest", "symmetric"):
        return key
    return as_float("offset", text)


def table_lines(fit, theo: dict | None) -> list[str]:
    """The Table II-style comparison as text lines."""
    rows = (("alpha", "alpha (rad)", 4), ("mu", "mu", 4), ("p", "p (1/s)", 3))
    if theo is None:
        out = [f"{'':12s}  {'identified':>22s}"]
    else:
        out = [f"{'':12s}  {'T':>8s}  {'identified':>22s}  {'%':>7s}"]
    for key, label, nd in rows:
        v, s = getattr(fit, key), getattr(fit, f"{key}_std")
        ident = f"{v:.{nd}f} ± {s:.{nd}f}"
        if theo is None:
            out.append(f"{label:12s}  {ident:>22s}")
        else:
            t = theo[key]
            if math.isfinite(t):
                out.append(f"{label:12s}  {t:8.{nd}f}  {ident:>22s}  "
                           f"{(v - t) / t * 100:+7.1f}")
            else:
                out.append(f"{label:12s}  {'-':>8s}  {ident:>22s}  {'-':>7s}")
    return out


@click.command("identify", context_settings=CONTEXT)
@click.argument("record", type=click.Path(dir_okay=False))
@click.option("--units", type=click.Choice(["rad", "deg"], case_sensitive=False),
              default="rad", show_default=True, help="Units of the angle column.")
@click.option("--block-width", metavar="W",
              help="Full width 2b of the block (bare number: m; or 170mm), for the "
                   "theoretical parameters of Eqs 2-4.")
@click.option("--block-height", metavar="H", help="Full height 2h of the block (bare: m).")
@click.option("--time-col", metavar="COL",
              help="Time column: name or 0-based index (default: t/time, else the first).")
@click.option("--angle-col", metavar="COL",
              help="Angle column: name or 0-based index (default: theta/angle, else the "
                   "second).")
@click.option("--offset", metavar="X",
              help="Offset of the record: auto (default), rest, symmetric, or a number in "
                   "the record's units (needed when the record does not end at rest and "
                   "has too few peaks for the centre of its oscillation).")
@click.option("--out", default="identify_out", show_default=True,
              type=click.Path(file_okay=False), help="Folder for the plots and the JSON.")
@click.option("--json", "as_json", is_flag=True, help="Print the fit as JSON (SI units).")
def identify(record, units, block_width, block_height, time_col, angle_col, offset, out,
             as_json):
    """Identify alpha, p and mu from a free-rocking RECORD (CSV: time, angle).

    The paper's method (Section 4.1): alpha and p minimise the error of the times between
    peaks and zero crossings (Eq 13, exact time model), mu follows Eq 12.
    """
    from .. import identify as ri  # lazy: numpy fits, pandas, the models

    width = positive_quantity(block_width, "length", "block-width", "m", "m")
    height = positive_quantity(block_height, "length", "block-height", "m", "m")
    block, theo = _theoretical(width, height)
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        # numpy's RuntimeWarnings (NaN in a candidate's shape, the mean of an empty set of
        # half-cycles) are intermediate: the pipeline refuses such a record with its own
        # one-line error, which must come first and alone
        warnings.simplefilter("ignore", RuntimeWarning)
        fit = ri.from_csv(record, units=units.lower(), time_col=time_col,
                          angle_col=angle_col, offset=_offset(offset, units))

    folder = Path(out)
    folder.mkdir(parents=True, exist_ok=True)
    summary = fit.summary()
    summary["record"] = str(record)
    summary["units"] = units.lower()
    if theo is not None:
        summary["theoretical"] = {**theo, "width": width, "height": height}
        summary["difference_pct"] = {k: (summary[k] - theo[k]) / theo[k] * 100.0
                                     for k in ("alpha", "p", "mu") if math.isfinite(theo[k])}
    summary = jsonable(summary)  # NaN (e.g. mu of a squat block) -> null
    atomic_write(folder / "fit.json", json.dumps(summary, indent=2, allow_nan=False,
                                                 default=json_default))
    with atomic_path(folder / "half_cycles.csv") as tmp:
        fit.table().to_csv(tmp, index=False, float_format="%.10g")
    _plots(fit, block, folder)

    if as_json:
        click.echo(json.dumps(summary, indent=2, default=json_default))
        return
    k = 180.0 / math.pi
    t = fit.t
    deg = units.lower() == "deg"
    unit_f, unit_s = (k, "deg") if deg else (1.0, "rad")
    click.echo(f"record      {record}: {t.size} samples, {fit.sampling_rate:.4g} Hz, "
               f"{t[-1] - t[0]:.4g} s")
    click.echo(f"offset      {fit.offset * unit_f:+.4g} {unit_s} ({fit.offset_method}); noise std "
               f"{fit.noise * unit_f:.2g} {unit_s}")
    rel = " (the first is the release)" if fit.release else ""
    click.echo(f"half-cycles {fit.n_half_cycles} used of {fit.n_lobes_found}{rel}; amplitudes "
               f"{fit.amplitudes.max() * unit_f:.4g} to {fit.amplitudes.min() * unit_f:.3g} "
               f"{unit_s}")
    click.echo("")
    for line in table_lines(fit, theo):
        click.echo(line)
    click.echo("")
    click.echo(f"corr(alpha, p) {fit.alpha_p_corr:+.3f}; rms time residual "
               f"{summary['rms_residual'] * 1e3:.3g} ms; identified 2b = 2h tan(alpha) = "
               + (f"{2 * (height / 2) * math.tan(fit.alpha):.4g} m" if height else "-"))
    click.echo(f"wrote       {folder / 'fit.json'}, error_surface.png, fit.png, "
               "half_cycles.csv")


def _plots(fit, block, folder: Path) -> None:
    from ..plot import save_figure  # lazy: matplotlib

    ax = fit.plot_error_surface(theoretical=block)
    save_figure(ax.figure, folder / "error_surface.png")
    axs = fit.plot_fit(theoretical=block)
    fig = (axs[0] if isinstance(axs, list) else axs).figure
    save_figure(fig, folder / "fit.png")


__all__ = ["identify", "table_lines"]
