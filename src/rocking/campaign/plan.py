"""A campaign's table of simulations, and the run of one chunk of it.

The spec's axes ``(models, blocks, floors, motions, levels, samples)``
(:attr:`CampaignSpec.shape`) are enumerated in that order, the last fastest: ``sim_id`` is
the flat index, so it is stable for a given spec and needs no table to be stored (the
floor axis has size 1 without ``[building]``: the ids, columns and rows of such a spec are
those it had before buildings existed). A chunk is the contiguous range
``[k * chunk_size, (k + 1) * chunk_size)`` of ``sim_id``.

With ``[[mitigation]]`` the axes are ``(models, mitigations, blocks, floors, motions,
levels, samples)`` (:attr:`CampaignSpec.axes`; one model): a row runs its mitigation's
model with its options (:attr:`CampaignSpec.runs`), ``model`` is that model and
``mitigation`` (after ``model``) the entry's name.

Random draws: simulation ``sim_id`` draws its uncertain parameters (and the table noise)
from ``numpy.random.default_rng(SeedSequence(seed, spawn_key=(STREAM, draw_id)))``, where
``draw_id`` (:meth:`Campaign.draw_ids`) is the flat index of the row over the axes without
the mitigation axis: ``sim_id`` itself without ``[[mitigation]]``, and with it the same
draws for every mitigation of a (block, floor, motion, level, sample): common random
numbers, the mitigations are compared on the same realizations. The
stochastic records are those of :func:`rocking.motions.stochastic_records` with the
campaign seed (record ``j`` from ``spawn_key=(2, j)``). A row therefore depends on the spec
and its ``sim_id`` only, never on the chunk size, the executor or the order of execution;
the compiled batches make each row bit-identical to its single run
(:func:`rocking.simulate_many`).

The uncertain parameters are drawn as in :func:`rocking.analysis.monte_carlo`
(:func:`~rocking.analysis.montecarlo.draw_parameters`): each distribution truncated to its
parameter's range by redrawing, ``theta0`` to ``|theta0| < alpha`` of the row's own
(drawn) alpha. A row whose ``theta0`` was redrawn says so in ``theta0_truncated``; the
report counts them. The row's block is :func:`~rocking.analysis.montecarlo.sample_block`'s,
as in Monte Carlo: an asymmetric block (a ``mesh`` block) keeps its two sides, a drawn
``alpha``, ``p`` or ``mu`` scaling both by ``drawn / nominal`` (the factor rule; the
table's ``alpha``, ``p``, ``mu`` are the weaker side's).

With ``[building]``, motion ``j`` of ``[motions]`` is the ground motion and a block on a
floor feels :class:`rocking.buildings.FloorMotion` of it; the intensity levels scale the
ground motion (``load_factor``, ``im`` and ``pga`` are the ground's, the same for every
floor), the row's ``floor_pga`` is the peak absolute floor acceleration of the motion as
run, and the uncertain ``amplitude`` and ``noise`` act on the floor motion (the one the
block stands on). Floor motions are built once per (floor, ground motion) and kept like
the ground motions (:class:`MotionSet`), never per run.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd

from .._validate import each_warning_once
from ..analysis.damage import damage_state
from ..analysis.ida import IMS, intensity
from ..analysis.montecarlo import (
    PARAMETERS,
    distributions,
    draw_parameters,
    perturbed,
    sample_block,
)
from ..blocks import Block
from ..errors import ParameterError
from ..models import GENERIC_OUTPUTS, MODELS, PLANAR_OUTPUTS, simulate_many
from ..models.base import empty_results
from ..motions import GroundMotion, HorizontalPair, Motion, Record, catalog, sample
from .spec import BuildingAxis, CampaignSpec, MotionAxis, nominal

STREAM = 3
"""Tag of the campaign's random streams (Monte Carlo uses 1, stochastic records 2)."""
KEEP = 2000
"""Motions a worker keeps built between chunks (beyond: only the current chunk's)."""
RESULT_COLUMNS = ("max_abs_theta", "max_abs_theta_over_alpha", "overturned", "overturn_time",
                  "uplift_time", "n_impacts", "settled", "damage_state", "status")
"""The result columns of every campaign (the shared outputs of the models,
:data:`rocking.models.base.GENERIC_OUTPUTS` and ``PLANAR_OUTPUTS``, and two derived
columns); after them, the models' own outputs (:func:`row_output_columns`). A 3-D body
(``rigid3d``) puts its ``max_tilt`` in ``max_abs_theta`` (the largest angle of its up axis
from the vertical: ``|theta|`` in the planar limit) and its ``alpha``, ``p``, ``mu`` are
those of its weakest direction (:func:`.spec.nominal`), so that ``max_abs_theta_over_alpha``
and the damage states read as for a planar block; its own outputs (``max_tilt``,
``overturn_azimuth``, ``max_slide``, ...) follow. A model without a planar angle or a tilt
leaves ``max_abs_theta`` and its ratio NaN, ``n_impacts`` 0 when it declares none, and
``damage_state`` -1."""
INPUT_UNITS = {"alpha": "rad", "p": "1/s", "mu": "", "theta0": "rad", "pga": "m/s^2",
               "heading": "deg",
               "floor_pga": "m/s^2", "load_factor": "", "amplitude": "", "noise": "m/s^2",
               "max_abs_theta_over_alpha": "", "damage_state": "", "lifted_off": ""}
"""The units of the campaign's input and derived columns (SI; ``""``: none), written with
the models' declared output units into the Parquet schema (:func:`column_units`)."""
VERTICAL_COLUMNS = ("lift_off_time", "lifted_off")
"""Result columns of motions with a vertical component (``vertical`` kinds of the catalog),
after ``settled``: ``lift_off_time`` (s, NaN if none) and ``lifted_off``."""


def row_output_columns(models) -> dict:
    """The row outputs (:attr:`rocking.models.base.Model.row_outputs`) of ``models`` (names
    of :data:`rocking.models.MODELS`), their union in the order of first appearance:
    ``{name: RowOutput}``. A campaign's table has one column each after the result
    columns: NaN (a value) or False (a flag) in the rows of models without it."""
    out = {}
    for m in models:
        for o in MODELS[m].row_outputs:
            out.setdefault(o.name, o)
    return out


OUTPUTS_BY_NAME = {o.name: o for o in GENERIC_OUTPUTS + PLANAR_OUTPUTS}
"""The shared outputs of the models by name (:data:`rocking.models.GENERIC_OUTPUTS`,
:data:`~rocking.models.PLANAR_OUTPUTS`): the declarations of the result columns."""


def balanced_order(n: int) -> np.ndarray:
    """The order in which a chunk's ``n`` runs go into their compiled batch: the
    golden-ratio stride permutation ``j -> (j g^-1) mod n`` (``g`` the odd number
    coprime to ``n`` nearest ``0.618 n``), so that any stretch of the batch holds runs
    from all over the chunk.

    numba's ``prange`` hands each thread one contiguous, equal share of the batch (it
    does not balance the load), and the runs of a chunk in ``sim_id`` order come in
    stretches of unequal cost (the levels of one record: at rest, rocking, overturned
    early). From each run's CPU time (``benchmarks/bench_campaign_profile.py --balance``:
    0.08 to 8.8 ms) on a chunk of 8,000 runs (32 stochastic records x 250 levels), the
    share of the cores kept busy (the mean share over the slowest) on 16 threads is 0.80
    in ``sim_id`` order and 0.96 in this order (64 threads: 0.61 and 0.90; a chunk of
    2,000 runs on 16 threads: 0.61 and 0.94). A run depends on its own inputs only
    (:func:`rocking.simulate_many`): the rows are the same, bit for bit, in any order.

    Examples
    --------
    >>> from rocking.campaign.plan import balanced_order
    >>> balanced_order(10).tolist()
    [0, 3, 6, 9, 2, 5, 8, 1, 4, 7]
    """
    if n < 3:
        return np.arange(n)
    g = int(round(0.6180339887498949 * n)) | 1
    while math.gcd(g, n) != 1:
        g += 2
    return np.argsort(np.arange(n) * g % n, kind="stable")


def empty_columns(outputs, n: int) -> dict:
    """``{name: array}``: ``n`` rows of each declared output at its "not reached" value
    (NaN, 0 or False: :func:`rocking.models.base.empty_results`), as campaign columns.

    Examples
    --------
    >>> from rocking.campaign.plan import OUTPUTS_BY_NAME, empty_columns
    >>> cols = empty_columns([OUTPUTS_BY_NAME["overturned"], OUTPUTS_BY_NAME["n_impacts"]], 2)
    >>> cols["overturned"], cols["n_impacts"]
    (array([False, False]), array([0, 0]))
    """
    outputs = tuple(outputs)
    res = empty_results(outputs, n)
    return {o.name: np.ascontiguousarray(res[o.name]) for o in outputs}


def column_units(models) -> dict:
    """``{column: unit}`` of a campaign's table with ``models`` (registry names): the
    inputs (:data:`INPUT_UNITS`) and every output the models declare
    (:attr:`rocking.models.Model.outputs`).

    Examples
    --------
    >>> from rocking.campaign.plan import column_units
    >>> u = column_units(["isolated"])
    >>> u["max_abs_theta"], u["max_base_displacement"], u["pga"], u["overturned"]
    ('rad', 'm', 'm/s^2', '')
    """
    units = dict(INPUT_UNITS)
    for m in models:
        cls = MODELS.get(m)
        for o in () if cls is None else cls.outputs:
            units.setdefault(o.name, o.unit)
    return units


def motion_im(mo: Motion, im: str, block: Block | None = None) -> float:
    """The intensity measure ``im`` of ``mo``; a ground motion's is its horizontal
    component's; a :class:`~rocking.motions.HorizontalPair`'s the larger of its two
    horizontal components' (the PGA: the larger component's PGA, as recorded: it does
    not depend on the heading); the PGA is the motion's own
    (:attr:`rocking.motions.Motion.pga`: exact where the kind states it, else the motion
    sampled at ``min(scan_step, 0.005)``, as the other IMs here)."""
    if isinstance(mo, HorizontalPair):
        return max(motion_im(c, im, block) for c in (mo.first, mo.second))
    if isinstance(mo, GroundMotion):
        mo = mo.horizontal if mo.scale == 1.0 else mo.horizontal.scaled(mo.scale)
    if im == "pga":
        return mo.pga
    rec = mo if isinstance(mo, Record) else sample(mo, min(mo.scan_step, 0.005))
    return intensity(rec, im, block)


class MotionSet:
    """The motions of a checked ``[motions]`` table (a :class:`~.spec.MotionAxis`), made
    by the catalog (:mod:`rocking.motions.catalog`) on demand and kept (unscaled) up to
    :data:`KEEP` of them (then those of the current chunk only: memory follows the chunk
    size, not the number of motions). Record files are not read again: the motions that
    the spec made while checking them (:attr:`~.spec.MotionAxis.records`) are taken as
    they are. With a checked ``[building]`` (``building``, a
    :class:`~.spec.BuildingAxis`), also the floor motions of each (floor, ground motion),
    kept the same way (:meth:`on_floor`)."""

    def __init__(self, m: MotionAxis, seed: int, base_dir=".",
                 building: BuildingAxis | None = None):
        self.m, self.seed = m, seed
        self.kind = m.catalog_kind
        self.n = m.n
        self.ctx = catalog.Context(Path(base_dir), seed)
        self._cache: dict[int, Motion] = {}
        self._params: dict[int, object] = {}
        self._im: dict[tuple, float] = {}
        self.building = building
        self.model = None if building is None else building.model()
        self._floors: dict[tuple[int, int], Motion] = {}
        self._floor_pga: dict[tuple[int, int], float] = {}

    def params(self, j: int):
        """The catalog parameters of motion ``j``: the checked parameters of motion 0 with
        its value of the swept parameter (:meth:`~.spec.MotionAxis.params`; kept, up to
        :data:`KEEP` of them)."""
        p = self._params.get(j)
        if p is None:
            if len(self._params) >= KEEP:
                self._params.clear()
            p = self._params[j] = self.m.params(j)
        return p

    def id(self, j: int) -> str:
        return self.kind.label(self.params(j))

    def prepare(self, js) -> None:
        """Build the motions ``js`` not built yet (in one call where the kind makes several
        at once: stochastic records)."""
        wanted = dict.fromkeys(np.asarray(js).tolist())
        missing = sorted(int(j) for j in wanted if j not in self._cache)
        if missing and len(self._cache) + len(missing) > KEEP:
            self._cache = {j: m for j, m in self._cache.items() if j in wanted}
        if not missing:
            return
        if self.m.records is not None:  # read by the spec's check: not read again
            made = [self.m.records[j] for j in missing]
        else:
            ps = [self.params(j) for j in missing]
            made = (self.kind.make_many(ps, self.ctx) if self.kind.make_many is not None
                    else [self.kind.make(p, self.ctx) for p in ps])
        self._cache.update(zip(missing, made, strict=True))

    def get(self, j: int) -> Motion:
        mo = self._cache.get(j)
        if mo is None:
            self.prepare([j])
            mo = self._cache[j]
        return mo

    def _floor_motion(self, f: int, j: int) -> Motion:
        from ..buildings import FloorMotion
        where = {self.building.axis: self.building.values[f]}
        return FloorMotion(self.get(j), self.model, **where)

    def prepare_floors(self, fs, js) -> None:
        """Build the floor motions of the pairs ``(fs[i], js[i])`` not built yet."""
        if self.building is None:
            return
        wanted = dict.fromkeys(zip(np.asarray(fs).tolist(), np.asarray(js).tolist(),
                                   strict=True))
        missing = [k for k in wanted if k not in self._floors]
        if missing and len(self._floors) + len(missing) > KEEP:
            self._floors = {k: m for k, m in self._floors.items() if k in wanted}
        for f, j in missing:
            self._floors[f, j] = self._floor_motion(f, j)

    def on_floor(self, f: int, j: int) -> Motion:
        """The motion (unscaled) that a block on floor ``f`` (an index of the floor axis)
        feels under ground motion ``j``: motion ``j`` itself without a building."""
        if self.building is None:
            return self.get(j)
        mo = self._floors.get((f, j))
        if mo is None:
            self.prepare_floors([f], [j])
            mo = self._floors[f, j]
        return mo

    def floor_pga(self, f: int, j: int) -> float:
        """The peak absolute acceleration of :meth:`on_floor` (unscaled)."""
        key = (f, j)
        if key not in self._floor_pga:
            mo = self.on_floor(f, j)  # the ground itself at floor 0: its PGA, as ``pga``
            self._floor_pga[key] = self.im(j, "pga") if mo.identity else mo.pga
        return self._floor_pga[key]

    def im(self, j: int, im: str, block: Block | None = None) -> float:
        """The intensity measure ``im`` of motion ``j`` unscaled (``block`` for the ratio
        IMs; a ground motion's: its horizontal component's)."""
        key = (j, im, (block.alpha, block.p) if im.endswith("_ratio") else None)
        if key not in self._im:
            self._im[key] = motion_im(self.get(j), im, block)
        return self._im[key]


class Campaign:
    """The simulations of a checked spec (:class:`~.spec.CampaignSpec`), chunk by chunk.

    Examples
    --------
    Run the four pulses of a spec in memory (no store): the block rocks exactly when the
    pulse's peak exceeds ``g tan(alpha)`` (1.66 m/s^2 for specimen 2):

    >>> import math
    >>> import rocking
    >>> from rocking.campaign import EXAMPLE_SPEC, Campaign, parse_spec
    >>> spec = parse_spec(EXAMPLE_SPEC)
    >>> rows = Campaign(spec).run_ids(range(spec.n_sims))
    >>> up = rocking.G * math.tan(spec.blocks[0].alpha)
    >>> ((rows.max_abs_theta > 0) == (rows.pga > up)).tolist()
    [True, True, True, True]
    >>> rows.overturned.tolist()
    [False, False, False, True]
    """

    def __init__(self, spec: CampaignSpec):
        self.spec = spec
        self.motions = MotionSet(spec.motion_axis, spec.seed, spec.base_dir,
                                 spec.building_axis)
        self.levels = np.asarray(spec.levels, dtype=float)
        self._dists = [distributions(nominal(block), spec.uncertain_parameters.to_dict(),
                                     where=lambda k: f"uncertain.{k}")
                       for block in spec.blocks]

    @property
    def n_sims(self) -> int:
        return self.spec.n_sims

    def chunk_range(self, k: int) -> tuple[int, int]:
        """``(start, stop)`` sim ids of chunk ``k`` (the last chunk may be shorter);
        ParameterError outside ``[0, n_chunks - 1]``.

        Examples
        --------
        :data:`~rocking.campaign.EXAMPLE_SPEC`: four runs in chunks of two:

        >>> from rocking.campaign import EXAMPLE_SPEC, Campaign, parse_spec
        >>> c = Campaign(parse_spec(EXAMPLE_SPEC))
        >>> c.chunk_range(0), c.chunk_range(1)
        ((0, 2), (2, 4))
        >>> c.chunk_range(2)
        Traceback (most recent call last):
        ...
        rocking.errors.ParameterError: chunk must be in [0, 1], got 2
        """
        if not 0 <= k < self.spec.n_chunks:
            raise ParameterError(f"chunk must be in [0, {self.spec.n_chunks - 1}], got {k}")
        cs = self.spec.chunk_size
        return k * cs, min((k + 1) * cs, self.n_sims)

    def _scale(self, j: int, lv: int, b: int) -> float:
        s = self.spec
        if s.im is None:
            return float(self.levels[lv])
        base = self.motions.im(j, s.im, nominal(s.blocks[b]))
        if not base > 0:
            raise ParameterError(f"motion {self.motions.id(j)} has {s.im} = 0: it cannot be "
                                 "scaled to an intensity level")
        return float((self.levels[lv] / base) ** (1.0 / IMS[s.im][1]))

    def inputs(self, ids):
        """Simulations ``ids``: ``(table, blocks, motions)`` ready for
        :func:`rocking.simulate_many` (the table holds the inputs, see :meth:`run_ids`; a
        stack's ``alpha``, ``p`` and ``mu`` are its top block's: :func:`.spec.nominal`).
        With a building: ``floor`` (and ``height_ratio``) after ``block_name`` and
        ``floor_pga`` after ``pga`` (see the module docstring).

        Examples
        --------
        The pulses of load factors 1.5 and 3 (PGA 1.5 and 3 m/s^2), run directly: the
        same outcome as :meth:`run_ids`:

        >>> import rocking
        >>> from rocking.campaign import EXAMPLE_SPEC, Campaign, parse_spec
        >>> c = Campaign(parse_spec(EXAMPLE_SPEC))
        >>> table, blocks, motions = c.inputs([1, 3])
        >>> table.pga.tolist(), [m.pga for m in motions]
        ([1.5, 3.0], [1.5, 3.0])
        >>> rocking.simulate_many(blocks, motions).overturned.tolist()
        [False, True]
        """
        s = self.spec
        ids = np.asarray(ids, dtype=np.int64).reshape(-1)
        if ids.size and not (ids.min() >= 0 and ids.max() < self.n_sims):
            raise ParameterError(f"sim ids must lie in [0, {self.n_sims - 1}]")
        ri, bi, fi, ji, li, si = np.unravel_index(ids, s.shape)
        self.motions.prepare(ji)
        self.motions.prepare_floors(fi, ji)
        n = ids.size
        # what rows share is computed once: the nominal values of each block, the scale
        # of each (motion, level, block), the PGA and id of each motion
        scales: dict = {}
        keys = zip(ji.tolist(), li.tolist(), bi.tolist(), strict=True)
        lf = np.array([scales[k] if k in scales else scales.setdefault(k, self._scale(*k))
                       for k in keys], dtype=float).reshape(n)
        truncated = np.zeros(n, bool)
        if len(s.uncertain_parameters) > 0:
            vals = {k: np.empty(n) for k in PARAMETERS}
            draws = self.draw_ids(ids).tolist()
            blocks, motions = [], []
            for r, (b, j, f) in enumerate(
                    zip(bi.tolist(), ji.tolist(), fi.tolist(), strict=True)):
                block = s.blocks[b]
                rng = np.random.default_rng(np.random.SeedSequence(
                    s.seed, spawn_key=(STREAM, draws[r])))
                v, truncated[r] = draw_parameters(nominal(block), self._dists[b], rng)
                blocks.append(sample_block(block, v, self._dists[b]))
                motions.append(perturbed(self.motions.on_floor(f, j).scaled(float(lf[r])),
                                         v["amplitude"], v["noise"], rng))
                for k in PARAMETERS:
                    vals[k][r] = v[k]
        else:  # the nominal values; a motion object per (floor, motion, scale)
            noms = [nominal(b) for b in s.blocks]
            vals = {k: np.array([float(f(nom)) for nom in noms], dtype=float)[bi]
                    for k, (f, _) in PARAMETERS.items()}
            blocks = [s.blocks[b] for b in bi.tolist()]
            scaled: dict = {}
            motions = []
            for f, j, x in zip(fi.tolist(), ji.tolist(), lf.tolist(), strict=True):
                mo = scaled.get((f, j, x))
                if mo is None:
                    mo = scaled[f, j, x] = self.motions.on_floor(f, j).scaled(x)
                motions.append(mo)
        uj, jinv = np.unique(ji, return_inverse=True)
        amp = np.abs(lf * vals["amplitude"])
        pga = np.array([self.motions.im(j, "pga") for j in uj.tolist()], dtype=float)[
            jinv.reshape(n)] * amp
        floor_pga = np.empty(n)
        if s.building_axis is not None:
            floor_pga = np.array([self.motions.floor_pga(f, j) for f, j in
                                  zip(fi.tolist(), ji.tolist(), strict=True)],
                                 dtype=float) * amp
        motion_ids = np.array([self.motions.id(j) for j in uj.tolist()], dtype=object)
        runs = s.runs
        nh = max(1, len(s.headings))
        table = pd.DataFrame({
            "sim_id": ids, "model": np.array([m for m, _ in runs], dtype=object)[ri],
            **({"mitigation": np.array([m.name for m in s.mitigations],
                                       dtype=object)[ri // nh]}
               if s.mitigations else {}),
            **({"heading": np.asarray(s.headings, dtype=float)[ri % nh]}
               if s.headings else {}),
            "block": bi.astype(np.int64),
            "block_name": np.array([b.name for b in s.blocks], dtype=object)[bi],
            **self._floor_columns(fi),
            "alpha": vals["alpha"], "p": vals["p"], "mu": vals["mu"],
            "motion": ji.astype(np.int64),
            "motion_id": motion_ids[jinv.reshape(n)].tolist(),
            "level": li.astype(np.int64), "load_factor": lf,
            **({"im": self.levels[li]} if s.im else {}),
            "sample": si.astype(np.int64),
            "theta0": vals["theta0"], "theta0_truncated": truncated,
            "amplitude": vals["amplitude"], "noise": vals["noise"],
            "pga": pga,
            **({"floor_pga": floor_pga} if s.building_axis is not None else {}),
        })
        return table, blocks, motions

    def draw_ids(self, ids) -> np.ndarray:
        """The ids of the random streams of simulations ``ids``: the flat index over the
        axes without the mitigation and heading axes (``ids`` themselves without
        ``[[mitigation]]`` or headings): every mitigation (and heading) of a (model, block,
        floor, motion, level, sample) draws the same uncertain parameters (common random
        numbers).

        Examples
        --------
        Two mitigations (none, anchors) of the four pulses: rows ``j`` and ``4 + j`` share
        their random stream:

        >>> from rocking.campaign import EXAMPLE_SPEC, Campaign, parse_spec
        >>> Campaign(parse_spec(EXAMPLE_SPEC)).draw_ids([0, 3]).tolist()
        [0, 3]
        >>> mit = 'mitigation = [{name = "none"}, {name = "anchors", model = "anchored"}]\\n'
        >>> Campaign(parse_spec(mit + EXAMPLE_SPEC)).draw_ids(range(8)).tolist()
        [0, 1, 2, 3, 0, 1, 2, 3]
        """
        ids = np.asarray(ids, dtype=np.int64).reshape(-1)
        a = self.spec.axes
        shared = ("mitigation", "heading")
        if all(a[k] == 1 for k in shared):
            return ids
        idx = np.unravel_index(ids, tuple(a.values()))
        keep = [i for i, k in zip(idx, a, strict=True) if k not in shared]
        return np.ravel_multi_index(keep, tuple(v for k, v in a.items() if k not in shared))

    def _floor_columns(self, fi: np.ndarray) -> dict:
        """``floor`` (the floor number; with ``height_ratios`` its index there) and
        ``height_ratio`` (with ``height_ratios``); none without a building."""
        b = self.spec.building_axis
        if b is None:
            return {}
        values = np.asarray(b.values)
        if b.axis == "floor":
            return {"floor": values[fi].astype(np.int64)}
        return {"floor": fi.astype(np.int64), "height_ratio": values[fi].astype(float)}

    def run_ids(self, ids) -> pd.DataFrame:
        """Simulate ``ids`` (one compiled batch per model): the inputs and the results, one
        row per simulation.

        Results: ``max_abs_theta`` (rad), ``max_abs_theta_over_alpha``, ``overturned``,
        ``overturn_time`` and ``uplift_time`` (s, NaN if none), ``n_impacts``,
        ``settled`` (the block was at rest or had overturned when the run ended: with no
        ``duration`` a run goes on after its motion until then, at most the spec's
        ``max_free_time``; an unsettled run is still rocking and counts as a survivor with
        the angle it reached, flagged here), ``damage_state``
        (:func:`rocking.analysis.damage_state` with the spec's thresholds; -1 for a failed
        run) and ``status`` (0, or the model's failure code: the run failed
        numerically and its ``max_abs_theta`` is NaN). Motions with a vertical component
        (a ``vertical`` kind of the catalog) add :data:`VERTICAL_COLUMNS` after
        ``settled``: ``lift_off_time`` (s, NaN if none: the run stops when the block leaves
        the ground) and ``lifted_off``. Then the row outputs of the models run
        (:func:`row_output_columns`; none if no model has any).

        Examples
        --------
        Specimen 2 uplifts at ``g tan(alpha)`` = 1.66 m/s^2 (Housner 1963): the 1.5 m/s^2 pulse
        leaves it at rest, the 3 m/s^2 one overturns it (``|theta|`` = pi/2):

        >>> from rocking.campaign import EXAMPLE_SPEC, Campaign, parse_spec
        >>> rows = Campaign(parse_spec(EXAMPLE_SPEC)).run_ids([1, 3])
        >>> rows[["sim_id", "pga", "max_abs_theta", "overturned", "damage_state"]]
           sim_id  pga  max_abs_theta  overturned  damage_state
        0       1  1.5       0.000000       False             0
        1       3  3.0       1.570796        True             3
        """
        ids = np.asarray(ids, dtype=np.int64).reshape(-1)
        return self.assemble(self.simulate(ids, self.inputs(ids)))

    def simulate(self, ids, inputs) -> tuple:
        """The compiled batches of simulations ``ids`` (one per model) on their
        ``inputs`` (:meth:`inputs` of the same ``ids``): the raw results, for
        :meth:`assemble`. :meth:`run_ids` is ``assemble(simulate(ids, inputs(ids)))``; the
        local executor runs the three steps in three threads, chunk after chunk (the
        inputs of the next chunk and the table of the previous one are made while the
        batches of this one run; :mod:`.execute`).

        Examples
        --------
        >>> import numpy as np
        >>> from rocking.campaign import EXAMPLE_SPEC, Campaign, parse_spec
        >>> c = Campaign(parse_spec(EXAMPLE_SPEC))
        >>> ids = np.array([1, 3])
        >>> c.assemble(c.simulate(ids, c.inputs(ids))).equals(c.run_ids(ids))
        True
        """
        ids = np.asarray(ids, dtype=np.int64).reshape(-1)
        table, blocks, motions = inputs
        n = len(table)
        shared = [k for k in RESULT_COLUMNS if k in OUTPUTS_BY_NAME]
        if self.motions.kind.vertical:
            shared.append("lift_off_time")
        out = empty_columns([OUTPUTS_BY_NAME[k] for k in shared], n)
        if self.motions.kind.vertical:
            out["lifted_off"] = np.zeros(n, bool)
        rows_out = empty_columns(row_output_columns(self.spec.run_models).values(), n)
        runs = self.spec.runs
        ri = np.unravel_index(ids, self.spec.shape)[0]
        theta0 = table["theta0"].to_numpy()
        for r in dict.fromkeys(ri.tolist()):
            idx = np.flatnonzero(ri == r)
            idx = idx[balanced_order(idx.size)]  # the load of numba's threads
            name, options = runs[r]
            with each_warning_once():  # a model's notices: once, not once per chunk
                res = simulate_many([blocks[i] for i in idx], [motions[i] for i in idx],
                                    model=name, duration=self.spec.duration,
                                    max_free_time=self.spec.max_free_time,
                                    theta0=theta0[idx] if theta0[idx].any() else 0.0,
                                    errors="nan", **options)
            for k in out:
                v = getattr(res, k)
                if v is not None:  # None: an output the model does not declare
                    out[k][idx] = v
            if res.max_abs_theta is None and "max_tilt" in res.outputs:  # a 3-D body
                out["max_abs_theta"][idx] = res.outputs["max_tilt"]
            for k, v in res.outputs.items():
                rows_out[k][idx] = v
        return table, out, rows_out

    def assemble(self, raw) -> pd.DataFrame:
        """The table of :meth:`run_ids` from the raw results of :meth:`simulate`: the
        inputs, the result columns, the damage states, the models' row outputs.

        Examples
        --------
        >>> import numpy as np
        >>> from rocking.campaign import EXAMPLE_SPEC, Campaign, parse_spec
        >>> c = Campaign(parse_spec(EXAMPLE_SPEC))
        >>> ids = np.arange(4)
        >>> rows = c.assemble(c.simulate(ids, c.inputs(ids)))
        >>> rows.overturned.tolist(), rows.damage_state.tolist()  # overturned: the last state
        ([False, False, False, True], [0, 0, 0, 3])
        """
        table, out, rows_out = raw
        n = len(table)
        table = table.assign(**out)
        table["max_abs_theta_over_alpha"] = table["max_abs_theta"] / table["alpha"]
        ok = (table["status"].to_numpy() == 0) & np.isfinite(out["max_abs_theta"])
        ds = np.full(n, -1, dtype=np.int64)
        if ok.any():
            ds[ok] = damage_state(table["max_abs_theta"].to_numpy()[ok],
                                  table["alpha"].to_numpy()[ok], out["overturned"][ok],
                                  self.spec.thresholds)
        table["damage_state"] = ds
        results = list(RESULT_COLUMNS)
        if self.motions.kind.vertical:
            k = results.index("settled") + 1
            results[k:k] = VERTICAL_COLUMNS
        table = table[[c for c in table.columns if c not in results] + results]
        return table.assign(**rows_out) if rows_out else table

    def run_chunk(self, k: int) -> pd.DataFrame:
        """Simulate chunk ``k`` (:meth:`run_ids` over its range).

        Examples
        --------
        >>> import numpy as np
        >>> from rocking.campaign import EXAMPLE_SPEC, Campaign, parse_spec
        >>> c = Campaign(parse_spec(EXAMPLE_SPEC))
        >>> rows = c.run_chunk(1)
        >>> rows.sim_id.tolist(), rows.equals(c.run_ids(np.arange(*c.chunk_range(1))))
        ([2, 3], True)
        """
        return self.run_ids(np.arange(*self.chunk_range(k)))

    def table(self) -> pd.DataFrame:
        """The inputs of every simulation (no run): for inspection of small campaigns.

        Examples
        --------
        >>> from rocking.campaign import EXAMPLE_SPEC, Campaign, parse_spec
        >>> table = Campaign(parse_spec(EXAMPLE_SPEC)).table()
        >>> table[["sim_id", "motion_id", "load_factor", "pga"]]
           sim_id      motion_id  load_factor  pga
        0       0  one_sine:0.5s          1.0  1.0
        1       1  one_sine:0.5s          1.5  1.5
        2       2  one_sine:0.5s          2.0  2.0
        3       3  one_sine:0.5s          3.0  3.0
        >>> "overturned" in table
        False
        """
        return self.inputs(np.arange(self.n_sims))[0]
