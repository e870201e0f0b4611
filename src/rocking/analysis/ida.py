"""Incremental dynamic analysis (IDA) and multiple-stripe analysis of a rocking block.

:func:`ida` scales every record to each level of an intensity measure and runs all of them
in one compiled batch; the long table it returns feeds :func:`~.fragility.fragility`
(stripes), :func:`~.fragility.fragility_ida` (capacities, :func:`ida_capacity`) and
:func:`~.damage.fragility_curves` (damage states).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..errors import ParameterError
from ..models import require_planar, simulate_many
from ..motions import Record
from ..plot import figure, im_label, style_axes
from .damage import DEFAULT_THRESHOLDS, damage_state, state_labels

IMS = {"pga": ("m/s^2", 1), "pgv": ("m/s", 1), "pgd": ("m", 1), "arias": ("m/s", 2),
       "pga_ratio": ("-", 1), "pgv_ratio": ("-", 1)}
"""Intensity measures (keys of :func:`rocking.motions.intensity_measures`): their unit and
the power of the load factor they scale with (Arias intensity: 2). The dimensionless
rocking measures are ``pga_ratio`` = PGA / (g tan alpha) and ``pgv_ratio`` =
PGV p / (g tan alpha)."""


def intensity(record: Record, im: str, block=None) -> float:
    """The intensity measure ``im`` (:data:`IMS`) of ``record`` (load factor applied)."""
    if im not in IMS:
        raise ParameterError(f"im must be one of {', '.join(IMS)}, got {im!r}")
    return float(record.intensity_measures(block=block if im.endswith("_ratio") else None)[im])


def ida(block, records, im: str = "pga", levels=None, model="housner",
        thresholds=DEFAULT_THRESHOLDS, duration: float | None = None,
        **options) -> pd.DataFrame:
    """Scale each record to each IM level and run them all: the IDA / stripes table.

    Parameters
    ----------
    block : Block
    records : sequence of Record
    im : str
        The intensity measure (:data:`IMS`), e.g. ``"pga"`` (m/s^2).
    levels : sequence of float
        IM levels (in the units of ``im``), > 0.
    model, duration, **options
        As in :func:`rocking.simulate_many`: with no ``duration`` each run goes on after
        its record until the block has settled, at most ``max_free_time`` (an option)
        longer.
    thresholds : sequence of float
        Damage-state thresholds on max ``|theta|`` / alpha (:func:`~.damage.damage_state`).

    Returns
    -------
    DataFrame, one row per (record, level): ``record`` (index), ``name``, ``level``,
    ``im``, ``scale`` (load factor), ``max_abs_theta`` (rad),
    ``max_abs_theta_over_alpha``, ``overturned``, ``overturn_time`` (s, NaN if none),
    ``n_impacts``, ``settled`` (the block was at rest or had overturned when the run
    ended; an unsettled run is still rocking: it counts as not overturned, with the angle
    it reached) and ``damage_state``.

    Examples
    --------
    A 1 Hz one-sine record scaled to PGA levels (m/s^2) on specimen 2 (``g tan alpha`` =
    1.66 m/s^2): below it the block does not rock (state 0), above it overturns (the last
    state, 3):

    >>> import rocking
    >>> from rocking.analysis import ida
    >>> from rocking.motions import Record
    >>> t = np.arange(0.0, 1.0, 0.005)
    >>> rec = Record(np.sin(2 * np.pi * t), 0.005, name="one sine 1 Hz")  # PGA 1 m/s^2
    >>> tab = ida(rocking.specimen(2), [rec], levels=[1.0, 3.0, 10.0], duration=6.0)
    >>> tab["scale"].tolist(), tab["damage_state"].tolist()
    ([1.0, 3.0, 10.0], [0, 3, 3])
    """
    recs = list(records) if not isinstance(records, Record) else [records]
    if not recs or not all(isinstance(r, Record) for r in recs):
        raise ParameterError("records must be a non-empty sequence of rocking.motions.Record")
    if levels is None:
        raise ParameterError("levels is required: the IM levels, > 0")
    try:
        lv = np.atleast_1d(np.asarray(levels, dtype=float))
    except (TypeError, ValueError):
        lv = np.array([np.nan])
    if lv.ndim != 1 or lv.size == 0 or not np.all(np.isfinite(lv) & (lv > 0)):
        raise ParameterError(f"levels must be a non-empty sequence of IM values > 0, "
                             f"got {levels!r}")
    state_labels(thresholds)  # checks the thresholds before any simulation
    require_planar(model, "an IDA's damage states")
    base = np.array([intensity(r, im, block) for r in recs])
    if not np.all(base > 0):
        raise ParameterError(f"every record must have {im} > 0 to be scaled")
    _check_isolator_records(recs, options)
    ri, li = np.meshgrid(np.arange(len(recs)), np.arange(lv.size), indexing="ij")
    ri, li = ri.ravel(), li.ravel()
    scale = (lv[li] / base[ri]) ** (1.0 / IMS[im][1])
    motions = [recs[i].scaled(s) for i, s in zip(ri, scale, strict=True)]
    res = simulate_many(block, motions, model=model, duration=duration, **options)
    ratio = res.max_abs_theta / block.alpha
    table = pd.DataFrame({
        "record": ri, "name": [recs[i].name for i in ri], "level": li, "im": lv[li],
        "scale": scale, "max_abs_theta": res.max_abs_theta, "max_abs_theta_over_alpha": ratio,
        "overturned": res.overturned, "overturn_time": res.overturn_time,
        "n_impacts": res.n_impacts, "settled": res.settled,
        "damage_state": damage_state(res.max_abs_theta, block.alpha, res.overturned,
                                     thresholds),
    })
    table.attrs.update(im=im, unit=IMS[im][0], n_states=len(state_labels(thresholds)))
    return table


def _check_isolator_records(recs, options: dict) -> None:
    """An IDA of an isolated block: warn (``RecordFitWarning``) when the records' mean
    spectrum falls more than 10 % below EN 1998-1 at the isolation period (issue 31)."""
    T = options.get("isolation_period")
    if T is None:
        return
    from ..motions.ec8_records import check_records_fit
    from ..units import parse_quantity

    try:
        T = float(parse_quantity(T, "time", name="isolation_period", default_unit="s")
                  if isinstance(T, str) else T)
    except (ParameterError, TypeError, ValueError):
        return  # simulate_many refuses it
    if T > 0:
        check_records_fit(recs, {"the isolation period": T}, what="ida: the records",
                          stacklevel=4)


def ida_capacity(table: pd.DataFrame, state: int | None = None) -> pd.DataFrame:
    """Per record, the IM capacity of an :func:`ida` table: the lowest level at which the
    record reaches damage state ``state`` (default: overturning, the last state), and
    whether it is right-censored (never reached up to the highest level: the capacity only
    exceeds it). Feed ``capacity`` and ``censored`` to :func:`~.fragility.fragility_ida`.
    The capacity is the first level reached, so it is high by up to one level step (the
    true capacity lies between that level and the one below): use fine levels.

    Examples
    --------
    >>> import rocking
    >>> from rocking.analysis import ida, ida_capacity
    >>> from rocking.motions import Record
    >>> t = np.arange(0.0, 1.0, 0.005)
    >>> rec = Record(np.sin(2 * np.pi * t), 0.005, name="one sine 1 Hz")  # PGA 1 m/s^2
    >>> tab = ida(rocking.specimen(2), [rec], levels=[1.0, 2.0, 3.0], duration=6.0)
    >>> ida_capacity(tab)[["capacity", "censored"]].values.tolist()
    [[2.0, False]]
    >>> ida_capacity(tab[tab["im"] < 1.5])["censored"].tolist()  # never overturned: censored
    [True]
    """
    need = {"record", "im", "damage_state"}
    if not need <= set(table.columns):
        raise ParameterError(f"table must be an ida() table with columns {sorted(need)}")
    n_states = int(table.attrs.get("n_states", table["damage_state"].max()))
    k = n_states if state is None else int(state)
    if not 1 <= k <= n_states:
        raise ParameterError(f"state must be in [1, {n_states}] (the damage states of the "
                             f"table; {n_states} = overturning), got {state!r}")
    rows = []
    for rec, g in table.sort_values("im").groupby("record"):
        hit = g.loc[g["damage_state"] >= k, "im"]
        rows.append({"record": rec, "capacity": float(hit.iloc[0]) if hit.size
                     else float(g["im"].max()), "censored": hit.size == 0})
    return pd.DataFrame(rows)


def plot_ida(table: pd.DataFrame, ax=None):
    """IDA curves of an :func:`ida` table: max ``|theta|`` / alpha against the IM level, one
    line per record, overturning marked at the top. Returns the Axes.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import rocking
    >>> from rocking.analysis import ida, plot_ida
    >>> from rocking.motions import Record
    >>> t = np.arange(0.0, 1.0, 0.005)
    >>> rec = Record(np.sin(2 * np.pi * t), 0.005, name="one sine 1 Hz")
    >>> tab = ida(rocking.specimen(2), [rec], levels=[1.0, 3.0], duration=6.0)
    >>> type(plot_ida(tab)).__name__
    'Axes'
    """

    if ax is None:
        _, ax = figure()
    top = 1.05 * max(1.0, float(table.loc[~table["overturned"],
                                          "max_abs_theta_over_alpha"].max()))
    for _rec, g in table.sort_values("im").groupby("record"):
        y = np.where(g["overturned"], top, g["max_abs_theta_over_alpha"])
        ax.plot(g["im"], y, color="0.45", linewidth=0.7, alpha=0.7)
    ov = table[table["overturned"]]
    ax.plot(ov["im"], np.full(len(ov), top), "x", color="#C00000", label="overturned")
    ax.axhline(1.0, color="0.3", linestyle=":", linewidth=0.8)
    ax.legend(loc="lower right", fontsize=8)  # upper left hid the crosses of the first levels
    style_axes(ax, im_label(table.attrs.get("im"), table.attrs.get("unit")),
           r"max $|\theta|/\alpha$")
    return ax
