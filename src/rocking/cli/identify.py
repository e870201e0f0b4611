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

import dataclasses
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


@dataclasses.dataclass(frozen=True)
class IdentifyRequest:
    """``rocking identify``'s options, read and checked (:meth:`from_options`): the record,
    its columns and offset, and the block of the theoretical parameters."""

    record: str
    units: str
    """``rad`` or ``deg`` (lower case)."""
    width: float | None
    height: float | None
    block: object
    """The theoretical block (Eqs 2-4) of ``--block-width``/``--block-height``, or None."""
    theoretical: dict | None
    """Its ``alpha``, ``p``, ``mu`` (NaN where Eq 4 gives mu <= 0), or None."""
    time_col: str | None
    angle_col: str | None
    offset: object
    """``auto``, ``rest``, ``symmetric`` or a number in the record's units."""
    out: str
    as_json: bool

    @classmethod
    def from_options(cls, *, record, units, block_width, block_height, time_col, angle_col,
                     offset, out, as_json):
        """The request of the command's options (click's values)."""
        width = positive_quantity(block_width, "length", "block-width", "m", "m")
        height = positive_quantity(block_height, "length", "block-height", "m", "m")
        block, theo = _theoretical(width, height)
        return cls(record=record, units=units.lower(), width=width, height=height,
                   block=block, theoretical=theo, time_col=time_col, angle_col=angle_col,
                   offset=_offset(offset, units), out=out, as_json=as_json)

    def identify(self):
        """The fit of :func:`rocking.identify.from_csv`."""
        from .. import identify as ri  # lazy: numpy fits, pandas, the models

        with warnings.catch_warnings(), np.errstate(all="ignore"):
            # numpy's RuntimeWarnings (NaN in a candidate's shape, the mean of an empty set
            # of half-cycles) are intermediate: the pipeline refuses such a record with its
            # own one-line error, which must come first and alone
            warnings.simplefilter("ignore", RuntimeWarning)
            return ri.from_csv(self.record, units=self.units, time_col=self.time_col,
                               angle_col=self.angle_col, offset=self.offset)


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
def identify(**options):
    """Identify alpha, p and mu from a free-rocking RECORD (CSV: time, angle).

    The paper's method (Section 4.1): alpha and p minimise the error of the times between
    peaks and zero crossings (Eq 13, exact time model), mu follows Eq 12.
    """
    req = IdentifyRequest.from_options(**options)
    fit = req.identify()
    folder = Path(req.out)
    folder.mkdir(parents=True, exist_ok=True)
    summary = _summary(req, fit)
    atomic_write(folder / "fit.json", json.dumps(summary, indent=2, allow_nan=False,
                                                 default=json_default))
    with atomic_path(folder / "half_cycles.csv") as tmp:
        fit.table().to_csv(tmp, index=False, float_format="%.10g")
    _plots(fit, req.block, folder)

    if req.as_json:
        click.echo(json.dumps(summary, indent=2, default=json_default))
        return
    click.echo("\n".join(_text_lines(req, fit, summary, folder)))


def _summary(req: IdentifyRequest, fit) -> dict:
    """fit.json: the fit's summary with the record, its units and the theoretical
    parameters with the differences from them (NaN as null)."""
    theo = req.theoretical
    summary = fit.summary()
    summary["record"] = str(req.record)
    summary["units"] = req.units
    if theo is not None:
        summary["theoretical"] = {**theo, "width": req.width, "height": req.height}
        summary["difference_pct"] = {k: (summary[k] - theo[k]) / theo[k] * 100.0
                                     for k in ("alpha", "p", "mu") if math.isfinite(theo[k])}
    return jsonable(summary)  # NaN (e.g. mu of a squat block) -> null


def _text_lines(req: IdentifyRequest, fit, summary: dict, folder: Path) -> list[str]:
    """The text report: the record, its offset and half-cycles, the Table II-style
    comparison, the correlation and residual, the files written."""
    k = 180.0 / math.pi
    t = fit.t
    height = req.height
    unit_f, unit_s = (k, "deg") if req.units == "deg" else (1.0, "rad")
    rel = " (the first is the release)" if fit.release else ""
    return [
        f"record      {req.record}: {t.size} samples, {fit.sampling_rate:.4g} Hz, "
        f"{t[-1] - t[0]:.4g} s",
        f"offset      {fit.offset * unit_f:+.4g} {unit_s} ({fit.offset_method}); noise std "
        f"{fit.noise * unit_f:.2g} {unit_s}",
        f"half-cycles {fit.n_half_cycles} used of {fit.n_lobes_found}{rel}; amplitudes "
        f"{fit.amplitudes.max() * unit_f:.4g} to {fit.amplitudes.min() * unit_f:.3g} "
        f"{unit_s}",
        "",
        *table_lines(fit, req.theoretical),
        "",
        f"corr(alpha, p) {fit.alpha_p_corr:+.3f}; rms time residual "
        f"{summary['rms_residual'] * 1e3:.3g} ms; identified 2b = 2h tan(alpha) = "
        + (f"{2 * (height / 2) * math.tan(fit.alpha):.4g} m" if height else "-"),
        f"wrote       {folder / 'fit.json'}, error_surface.png, fit.png, half_cycles.csv",
    ]


def _plots(fit, block, folder: Path) -> None:
    from ..plot import save_figure  # lazy: matplotlib

    ax = fit.plot_error_surface(theoretical=block)
    save_figure(ax.figure, folder / "error_surface.png")
    axs = fit.plot_fit(theoretical=block)
    fig = (axs[0] if isinstance(axs, list) else axs).figure
    save_figure(fig, folder / "fit.png")


__all__ = ["identify", "table_lines"]
