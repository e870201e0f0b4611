"""The model contract as code: :func:`check_model`, like scikit-learn's ``check_estimator``.

``check_model(MyModel)`` runs every check below on a :class:`rocking.models.Model`
subclass (or a registered name) through the public API only (:func:`rocking.simulate`,
:func:`rocking.simulate_many`, the class attributes and the options' metadata), so it
holds whatever the kernels' internal data look like. Each check raises
:class:`AssertionError` whose message starts with the check's name and the model's name
and says what differed; :func:`check_model` runs them all and reports every failure in
one :class:`AssertionError`. :func:`model_checks` yields ``(name, check)`` pairs, and
:data:`CHECKS` lists the check functions (each ``check(cls, *, quick=True)``), so that a
test suite can parametrize over them (``tests/test_check_model.py``).

The checks
----------
``check_class_attributes``
    ``name``, ``label``, ``Options`` (a :class:`~rocking.models.ModelOptions`
    dataclass), ``kernel`` and ``batch_kernel`` are set.
``check_options``
    Every option with range metadata (:func:`rocking.models.option`) refuses, with a
    :class:`~rocking.ParameterError` naming it, the values just outside its range
    (``lo``/``hi``, open or closed), NaN and infinities, a bool for a number, a fraction
    for an ``int``, a non-bool for a ``bool`` and an unlisted string for ``choices``;
    it accepts its default and the values just inside its range; every option has a
    ``help`` text; unknown options are refused. (``kind=object`` options are validated by
    the options' own ``check()`` and are skipped.)
``check_kernel_params_pure``
    :meth:`Model.kernel_params` is a function: two calls give equal tuples, and neither
    they nor :meth:`Model.info` change the model's attributes (``vars(model)``) or
    ``info()``.
``check_result_conventions``
    Single runs and batches: ``overturn_time`` is NaN if and only if the block did not
    overturn, ``uplift_time`` NaN if and only if it never left rest, ``lift_off_time``
    NaN without a vertical motion; ``settled`` is a bool (a bool array in batches) and
    true for every overturned block; ``status`` is 0; ``errors="nan"`` gives the same
    rows, with arrays of the right shapes; the history is sampled at ``dt_out`` from 0.
``check_at_rest_below_uplift``
    Under motions below the uplift threshold (peak ``g tan(alpha) / 2``) the block does
    not move: no impacts, no overturning, NaN ``uplift_time``, ``settled``, and
    ``max_abs_theta`` below :data:`AT_REST_TOL` ``alpha`` (0 for rigid contacts; the
    DEM's contact springs tilt a block at rest by ~1e-5 ``alpha``).
``check_batch_rows_equal_single_runs``
    Row ``i`` of ``simulate_many`` is bit-identical to ``simulate`` of motion ``i``
    (``max_abs_theta``, ``n_impacts``, ``overturned``, ``overturn_time``,
    ``uplift_time``, ``lift_off_time``, ``settled``, and the ``theta``/``omega``
    histories, NaN past the samples the run wrote, and the model's row outputs:
    ``BatchResponse.outputs`` against ``Response.info``), for motions of different time
    scales in one batch (sines, pulses, short random records).
``check_chunk_independence``
    ``simulate_many`` over all motions equals the concatenation over two chunks.
``check_blocks_per_row``
    A batch with a different block per row equals the single runs (one compiled call
    when :meth:`Model.block_row` is not empty, one batch per block otherwise); a model
    with ``accepts_asymmetric = True`` gets an asymmetric block among them.
``check_initial_state_per_row``
    With ``batch_initial_state``, per-row ``theta0``/``omega0`` equal the single runs;
    without it, a batch refuses a non-zero initial state.
``check_free_rocking_symmetry``
    Free rocking from ``(-theta0, -omega0)`` mirrors the run from ``(theta0, omega0)``:
    same impacts, overturning and settling, ``theta`` histories negatives of each other
    to :data:`FREE_SYMMETRY_TOL` ``alpha``.
``check_motion_symmetry``
    The same for a motion and its negation ``-motion``, over the motion's duration, to
    :data:`MOTION_SYMMETRY_TOL` ``alpha``.
``check_rotation_equivariance``
    With the ``"rotation"`` tag (3-D models): the body and the motion turned together
    about the vertical (``rotate_state`` of the initial state, the option ``direction``)
    give the same outputs and the turned history, to :data:`ROTATION_TOL`.

Exactness. Batch rows and chunks must be equal bit for bit: nothing excuses a row that
depends on its batch. Symmetry is checked to a tolerance: a kernel written with the sign
of ``theta`` as a factor (the classical model, the fourth model of the tests) mirrors
exactly, but one whose arithmetic is not mirrored (the CCRR's phase ``psi + pi``, the
DEM's vertex sums) differs by rounding, which an adaptive step control turns into
different steps and so into differences of the order of its tolerance (measured on the
checks' motions: the CCRR at ``rtol = 1e-6``, up to 2e-4 ``alpha`` with ``quick=True``
and 7e-4 ``alpha`` with ``quick=False``, 1e-15 ``alpha`` in free rocking; the DEM,
1e-20 ``alpha``; the classical and fourth models, 0). A sign error is of the order of
``alpha``.

Cost. The checks run short motions with ``dt_out = 0.01`` s; a model with ``slow = True``
(the DEM) gets fewer and shorter motions and runs at most 0.5 s past each motion.
``quick=False`` adds motions, blocks and initial states.
"""

from __future__ import annotations

import copy
import dataclasses
import functools
import math
import warnings
from collections.abc import Callable, Iterator
from dataclasses import dataclass, replace

import numpy as np

from .. import G, ParameterError
from ..blocks import Block, specimen
from ..models import GENERIC_OUTPUTS, Model, ModelOptions, get_model, simulate, simulate_many
from ..motions import HalfSine, OneSine, Sine
from .records import random_record

AT_REST_TOL = 1e-4
"""Largest ``max_abs_theta`` (fraction of ``alpha``) of a block that does not rock: 0 for
rigid contacts; the DEM's contact springs (settlement 1e-7 of the height) tilt specimen 3
by 7e-6 ``alpha`` under half the uplift acceleration."""
FREE_SYMMETRY_TOL = 1e-9
"""Mirror symmetry of free rocking: largest ``|theta(x) + theta(-x)|`` (fraction of alpha)."""
MOTION_SYMMETRY_TOL = 1e-2
"""Mirror symmetry under ``-motion``: largest ``|theta + theta_mirror|`` (fraction of
alpha) over the motion's duration (times: this over ``p``)."""
DT_OUT = 0.01
"""Output interval (s) of the checks' runs."""


# ================================================================================ plans
@dataclass(frozen=True)
class _Plan:
    """What the checks of one model run: blocks, motions and run settings."""

    block: Block
    blocks: tuple  # one block per row, for the per-row checks
    motions: tuple  # of different time scales, most of them rocking the block
    weak: tuple  # below the uplift threshold
    theta0: tuple  # free rocking initial states (fractions of alpha, omega0 in rad/s)
    run: dict  # keyword arguments of every run
    free_duration: float | None  # duration of free rocking runs


@functools.cache
def _plan(slow: bool, quick: bool) -> _Plan:
    block = specimen(3)
    thr = G * math.tan(block.alpha)
    if slow:
        rec = random_record(7, 0.5 * G, duration=2.5)
        motions = (HalfSine(3.0, 0.3, duration=1.0), Sine(5.0, 0.008, 1.2),
                   rec.scaled(0.9))
        if not quick:
            motions += (OneSine(4.0, 0.15, duration=1.0), rec.scaled(-1.2))
        weak = (Sine.from_acceleration(5.0, 0.5 * thr, 0.5),)
        blocks = (specimen(2), block) if quick else (specimen(2), block, specimen(4))
        return _Plan(block, blocks, motions, weak,
                     ((0.5, 0.0), (1.05, 0.0)) if quick else ((0.3, 0.0), (0.7, 0.2),
                                                               (1.05, 0.0)),
                     {"dt_out": DT_OUT, "max_free_time": 0.5}, 1.5)
    rec = random_record(7, 0.5 * G, duration=8.0)
    motions = (Sine(2.0, 0.02, 3.0), Sine(5.0, 0.008, 3.0), rec.scaled(1.2),
               HalfSine(3.0, 0.3, duration=3.0), rec.scaled(-0.9), OneSine(4.0, 0.15))
    weak = (Sine.from_acceleration(5.0, 0.5 * thr, 2.0), HalfSine(0.5 * thr, 0.5),
            random_record(3, 0.5 * thr, duration=4.0))
    if not quick:
        more = [random_record(s, f * G, duration=12.0) for s, f in ((1, 0.3), (2, 0.6))]
        motions += (*more, Sine(1.0, 0.05, 6.0), OneSine(2.0, 0.4, t0=0.5))
    blocks = (specimen(2), block, specimen(4), specimen(1))
    th0 = ((0.3, 0.0), (0.8, 0.0), (0.5, -0.3), (1.05, 0.0))
    return _Plan(block, blocks if quick else blocks * 2, motions, weak,
                 th0 if quick else th0 + ((0.95, 0.0), (0.0, 0.5)), {"dt_out": DT_OUT},
                 None)


def _plan_of(cls, quick: bool) -> _Plan:
    plan = _plan(bool(cls.slow), bool(quick))
    if getattr(cls, "accepts_asymmetric", False):  # both sides in the per-row checks
        asym = Block.from_geometry(0.5, 0.08, 0.12, 0.25, name="asymmetric")
        plan = replace(plan, blocks=(*plan.blocks, asym))
    return plan


# ============================================================================ comparison
def _same(a, b) -> bool:
    """Equal bit for bit (NaN equals NaN), scalars or arrays."""
    a, b = np.asarray(a), np.asarray(b)
    if a.shape != b.shape:
        return False
    if a.dtype.kind == "f" or b.dtype.kind == "f":
        return bool(np.array_equal(a, b, equal_nan=True))
    return bool(np.array_equal(a, b))


def _expect_same(what: str, got, want, got_name: str = "batch", want_name: str = "single"):
    if not _same(got, want):
        g, w = np.asarray(got), np.asarray(want)
        if g.shape != w.shape:
            raise AssertionError(f"{what}: shape {g.shape} ({got_name}) != {w.shape} "
                                 f"({want_name})")
        bad = np.flatnonzero(~((g == w) | (np.isnan(g) & np.isnan(w))
                               if g.dtype.kind == "f" else g == w).ravel())
        j = int(bad[0]) if bad.size else 0
        raise AssertionError(f"{what}: {got_name} {g.ravel()[j].item()!r} != {want_name} "
                             f"{w.ravel()[j].item()!r}" + (f" at index {j} ({bad.size} differ)"
                                                    if g.ndim else ""))


def _grid_samples(r) -> int:
    """Samples of a single run on the ``DT_OUT`` grid (without an appended overturn)."""
    n = r.t.size
    if n and r.overturned and r.t[-1] != (n - 1) * DT_OUT:
        n -= 1
    return n


def _describe(m) -> str:
    return "free rocking" if m is None else repr(m)


SCALARS = ("max_abs_theta", "n_impacts", "overturned", "overturn_time", "uplift_time",
           "lift_off_time", "settled")
"""The shared scalar outputs of the planar models (:data:`rocking.models.base.PLANAR_OUTPUTS`
and :data:`~rocking.models.base.GENERIC_OUTPUTS`); a model's checks compare every output
it declares (:func:`_declared`)."""


def _declared(cls) -> list[str]:
    """The names of the outputs ``cls`` declares that a result carries (not ``n_out``)."""
    return [o.name for o in cls.outputs if o.name != "n_out"]


def _planar(cls) -> bool:
    return bool(cls.tags.get("planar"))


def _row_equals_single(b, i: int, r, label: str, cls=None) -> None:
    """Row ``i`` of the batch ``b`` is the single run ``r``, bit for bit: every declared
    output, the row outputs in ``r.info``, and the state histories."""
    names = _declared(cls) if cls is not None else list(SCALARS)
    for key in names:
        if key not in r.outputs and cls is not None:
            raise AssertionError(f"{label}: declared output {key!r} is not in the single "
                                 "run's outputs")
        _expect_same(f"{label}: {key}", getattr(b, key)[i],
                     r.outputs[key] if key in r.outputs else getattr(r, key))
    for key, values in b.outputs.items():  # the model's row outputs
        if key not in r.info:
            raise AssertionError(f"{label}: row output {key!r} is in the batch but not in "
                                 "the single run's info")
        _expect_same(f"{label}: {key}", values[i], r.info[key])
    if b.states is not None:
        n = _grid_samples(r)
        row = b.states[i]
        _expect_same(f"{label}: state history", row[:n], r.states[:n])
        if not np.all(np.isnan(row[n:])):
            raise AssertionError(f"{label}: the batch's state history is not NaN past "
                                 f"the {n} samples the run wrote")
        if b.theta is not None:
            for key in ("theta", "omega"):
                _expect_same(f"{label}: {key} history", getattr(b, key)[i][:n],
                             getattr(r, key)[:n])


def _runs(cls, plan: _Plan, block, motions, **kw):
    """The batch (with histories) and the single runs of ``motions``."""
    b = simulate_many(block, list(motions), model=cls, return_histories=True,
                      **plan.run, **kw)
    blocks = block if isinstance(block, list | tuple) else [block] * len(motions)
    singles = []
    for i, m in enumerate(motions):
        one = {k: (v[i] if isinstance(v, list | tuple | np.ndarray) else v)
               for k, v in kw.items()}
        singles.append(simulate(blocks[i], m, model=cls, **plan.run, **one))
    return b, singles


# ================================================================================ checks
CHECKS: list[Callable] = []
"""The checks, in the order :func:`check_model` runs them (each ``check(cls, *,
quick=True)``)."""


def _check(fn):
    """Register ``fn(cls, plan)`` as a check whose failures name it and the model."""
    @functools.wraps(fn)
    def check(cls, *, quick: bool = True) -> None:
        cls = cls if isinstance(cls, type) else get_model(cls)
        where = (f"{fn.__name__} failed for model {getattr(cls, 'name', '?')!r} "
                 f"({getattr(cls, '__name__', cls)})")
        try:
            fn(cls, _plan_of(cls, quick))
        except AssertionError as e:
            raise AssertionError(f"{where}: {e}").with_traceback(e.__traceback__) from None
        except Exception as e:
            e.add_note(f"in {where}")
            raise

    CHECKS.append(check)
    return check


@_check
def check_class_attributes(cls, plan):
    """The class attributes every model sets."""
    assert isinstance(cls, type) and issubclass(cls, Model), \
        "not a rocking.models.Model subclass"
    for attr in ("name", "label"):
        value = getattr(cls, attr)
        assert isinstance(value, str) and value, f"{attr} must be a non-empty string"
    assert isinstance(cls.Options, type) and issubclass(cls.Options, ModelOptions), \
        "Options must be a ModelOptions subclass"
    assert dataclasses.is_dataclass(cls.Options), "Options must be a dataclass"
    for attr in ("kernel", "batch_kernel"):
        assert getattr(cls, attr) is not None, f"{attr} is not set"


def _outside(f) -> list:
    """Values of option ``f`` that its metadata refuses."""
    m = f.metadata
    kind = m.get("kind")
    if kind is bool:
        return [1, 0, "True", None]
    if m.get("choices"):
        return ["no such choice", 1, None]
    if kind not in (int, float):
        return []
    bad = [math.nan, math.inf, -math.inf, True, "not a number"]
    if kind is int:
        bad.append(0.5 if m["lo"] is None else m["lo"] + 0.5)
    if m["lo"] is not None:
        lo = float(m["lo"])
        bad += [lo] if m["lo_open"] else [np.nextafter(lo, -math.inf)]
        bad.append(lo - max(1.0, abs(lo)))
    if m["hi"] is not None:
        hi = float(m["hi"])
        bad += [hi] if m["hi_open"] else [np.nextafter(hi, math.inf)]
        bad.append(hi + max(1.0, abs(hi)))
    if f.default is not None:
        bad.append(None)
    return bad


def _inside(f) -> list:
    """Values of option ``f`` that its metadata accepts (the default and the range's ends)."""
    m = f.metadata
    good = [f.default]
    if m.get("choices"):
        good += list(m["choices"])
    elif m.get("kind") is bool:
        good += [True, False]
    elif m.get("kind") in (int, float):
        if m["lo"] is not None:
            lo = float(m["lo"])
            good.append(float(np.nextafter(lo, math.inf)) if m["lo_open"] else lo)
        if m["hi"] is not None:
            hi = float(m["hi"])
            good.append(float(np.nextafter(hi, -math.inf)) if m["hi_open"] else hi)
        if m.get("kind") is int:
            good = [int(math.ceil(v)) if isinstance(v, float) else v for v in good]
    return good


@_check
def check_options(cls, plan):
    """Options refuse values outside their declared range and accept their defaults."""
    try:
        cls.Options()  # every default at once
    except ParameterError as e:
        raise AssertionError(f"the default options are refused: {e}") from None
    ranges = {}
    for d in cls.Options.describe():
        assert d["help"], f"option {d['name']!r} has no help text"
        ranges[d["name"]] = d["range"]
    for f in dataclasses.fields(cls.Options):
        if not f.metadata:
            raise AssertionError(f"option {f.name!r} is not declared with option()")
        for v in _inside(f):
            try:
                cls.Options.build(cls.name, **{f.name: v})
            except ParameterError as e:
                raise AssertionError(f"option {f.name}={v!r} (inside its declared range) "
                                     f"was refused: {e}") from None
        for v in _outside(f):
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                try:
                    cls.from_kwargs(plan.block, **{f.name: v})
                except ParameterError as e:
                    assert f.name in str(e), \
                        f"the error for {f.name}={v!r} does not name the option: {e}"
                    continue
            if any(issubclass(w.category, DeprecationWarning) and f.name in str(w.message)
                   for w in caught):
                continue  # an old spelling, accepted for one release with a warning
            raise AssertionError(f"option {f.name}={v!r} was accepted (declared: "
                                 f"{ranges[f.name] or f.metadata['kind'].__name__})")
    bogus = "no_such_option"
    try:
        cls.from_kwargs(plan.block, **{bogus: 1})
    except ParameterError as e:
        assert bogus in str(e), f"the error for an unknown option does not name it: {e}"
    else:
        raise AssertionError("an unknown option was accepted")


def _snapshot(obj):
    return copy.deepcopy(vars(obj))


def _equal_state(a, b, path: str = "", depth: int = 0) -> str | None:
    """Where two snapshots of attributes differ (None: equal)."""
    if depth > 8:
        return None
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(a.keys() | b.keys(), key=str):
            if k not in b:
                return f"{path}{k} removed"
            if k not in a:
                return f"{path}{k} added"
            d = _equal_state(a[k], b[k], f"{path}{k}.", depth + 1)
            if d:
                return d
        return None
    if type(a) is not type(b):
        return f"{path.rstrip('.')} changed type"
    if isinstance(a, np.ndarray):
        return None if _same(a, b) else f"{path.rstrip('.')} changed"
    if isinstance(a, list | tuple):
        if len(a) != len(b):
            return f"{path.rstrip('.')} changed length"
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            d = _equal_state(x, y, f"{path}{i}.", depth + 1)
            if d:
                return d
        return None
    if isinstance(a, float | np.floating):
        return None if _same(a, b) else f"{path.rstrip('.')} changed from {a!r} to {b!r}"
    if hasattr(a, "__dict__") and not isinstance(a, type):
        return _equal_state(vars(a), vars(b), path, depth + 1)
    try:
        return None if bool(a == b) else f"{path.rstrip('.')} changed from {a!r} to {b!r}"
    except (TypeError, ValueError):
        return None


@_check
def check_kernel_params_pure(cls, plan):
    """``kernel_params`` and ``info`` have no side effects."""
    model = cls.from_kwargs(plan.block)
    before, info0 = _snapshot(model), copy.deepcopy(model.info())
    mp = model.kernel_params(DT_OUT, 0.0, 0.0)
    d = _equal_state(before, _snapshot(model))
    assert d is None, f"kernel_params changed the model's attributes: {d}"
    d = _equal_state(info0, model.info())
    assert d is None, f"info() differs before and after kernel_params: {d}"
    model.kernel_params(0.5 * DT_OUT, 0.01, 0.1)
    d = _equal_state(mp, model.kernel_params(DT_OUT, 0.0, 0.0))
    assert d is None, f"kernel_params gave different tuples for the same arguments: {d}"
    d = _equal_state(before, _snapshot(model))
    assert d is None, f"kernel_params changed the model's attributes: {d}"


def _nan_iff(what: str, times, missing, text: str) -> None:
    """``times`` is NaN exactly where ``missing`` (the event did not happen)."""
    times, missing = np.atleast_1d(times), np.atleast_1d(missing)
    bad = np.flatnonzero(np.isnan(times) != missing)
    if bad.size:
        i = int(bad[0])
        raise AssertionError(f"{what} is {times[i]!r} (row {i}) where '{text}' is "
                             f"{bool(missing[i])}: a time is NaN if and only if its event "
                             "did not happen")


@_check
def check_result_conventions(cls, plan):
    """NaN event times, ``settled``, ``status``, ``errors="nan"`` shapes."""
    ms = list(plan.motions + plan.weak)
    n = len(ms)
    tol = AT_REST_TOL * plan.block.alpha
    b = simulate_many(plan.block, ms, model=cls, return_histories=True, **plan.run)
    bn = simulate_many(plan.block, ms, model=cls, return_histories=True, errors="nan",
                       **plan.run)
    singles = [simulate(plan.block, m, model=cls, **plan.run) for m in ms]
    planar = _planar(cls)
    names = _declared(cls)
    hist = ("t", "states") + (("theta", "omega") if planar else ())
    for key in (*names, *hist):
        _expect_same(f"errors='nan' vs 'raise': {key}", getattr(bn, key), getattr(b, key),
                     "errors='nan'", "errors='raise'")
    for key in names:
        shape = np.shape(getattr(bn, key))
        assert shape == (n,), f"batch {key} has shape {shape}, not ({n},)"
    ns = len(b.state_names)
    assert bn.states.shape == (n, bn.t.size, ns), \
        f"batch states shape {bn.states.shape}, not (runs, samples, states) = " \
        f"({n}, {bn.t.size}, {ns})"
    if planar:
        assert bn.t.shape == (bn.theta.shape[1],) and bn.theta.shape == bn.omega.shape \
            and bn.theta.shape[0] == n, f"history shapes t {bn.t.shape}, theta {bn.theta.shape}"
    assert np.all(b.status == 0), f"status {b.status.tolist()} (0: success)"
    for o in cls.outputs:
        if o.name == "n_out":
            continue
        v = getattr(b, o.name)
        kind = "bool" if o.flag else "integer" if o.integer else "float"
        ok = (v.dtype == np.bool_ if o.flag else np.issubdtype(v.dtype, np.integer)
              if o.integer else np.issubdtype(v.dtype, np.floating))
        assert ok, f"output {o.name}: dtype {v.dtype} (declared {kind})"
    assert len(b) == n
    names_own = [o.name for o in cls.row_outputs]
    assert list(b.outputs) == names_own, \
        f"batch outputs {list(b.outputs)} != row_outputs {names_own}"
    for res, label in ((b, "batch"), *((r, f"single run of {_describe(m)}")
                                      for r, m in zip(singles, ms, strict=True))):
        over, t_up = np.atleast_1d(res.overturned), np.atleast_1d(res.uplift_time)
        _nan_iff(f"{label}: overturn_time", res.overturn_time, ~over, "not overturned")
        if planar:
            still = ((np.atleast_1d(res.n_impacts) == 0) & ~over
                     & (np.atleast_1d(res.max_abs_theta) <= tol))
            _nan_iff(f"{label}: uplift_time", res.uplift_time, still, "never left rest")
        assert np.all(np.isnan(res.lift_off_time)), \
            f"{label}: lift_off_time {res.lift_off_time} without a vertical motion"
        assert np.all(np.atleast_1d(res.settled)[over]), f"{label}: overturned, not settled"
        ok = np.isnan(t_up) | (t_up >= 0.0)
        assert np.all(ok), f"{label}: uplift_time {t_up} < 0"
        assert np.all(over <= (np.atleast_1d(res.overturn_time) >= t_up)), \
            f"{label}: overturn_time before uplift_time"
    for r, m in zip(singles, ms, strict=True):
        label = f"single run of {_describe(m)}"
        assert isinstance(r.settled, bool) and isinstance(r.overturned, bool), \
            f"{label}: settled/overturned are {type(r.settled).__name__}/" \
            f"{type(r.overturned).__name__}, not bool"
        assert sorted(r.outputs) == sorted(names), \
            f"{label}: outputs {sorted(r.outputs)} != declared {sorted(names)}"
        for o in cls.outputs:
            if o.name != "n_out":
                want = bool if o.flag else int if o.integer else float
                assert type(r.outputs[o.name]) is want, \
                    f"{label}: output {o.name} is a {type(r.outputs[o.name]).__name__}"
        assert r.impact_times.size <= r.n_impacts, \
            f"{label}: {r.impact_times.size} impact times for {r.n_impacts} impacts"
        k = _grid_samples(r)
        _expect_same(f"{label}: t", r.t[:k], np.arange(k) * plan.run["dt_out"], "t",
                     "k dt_out")
        assert r.states.shape == (r.t.size, ns) and tuple(r.state_names) == b.state_names, \
            f"{label}: states {r.states.shape} ({r.state_names}), t {r.t.shape}"
        cols = list(r.to_dataframe().columns)
        assert all(name in cols for name in r.state_names), \
            f"{label}: to_dataframe() columns {cols} lack a state of {r.state_names}"
        if planar:
            assert r.theta.shape == r.t.shape == r.omega.shape, f"{label}: history shapes"
    if planar:
        assert np.any(b.max_abs_theta > 0.1 * plan.block.alpha), "no motion rocks the block"
    else:
        assert np.any(np.isfinite(b.uplift_time)), "no motion moves the body"


@_check
def check_at_rest_below_uplift(cls, plan):
    """A body at rest stays at rest under motions below the uplift threshold."""
    tol = AT_REST_TOL * plan.block.alpha
    b = simulate_many(plan.block, list(plan.weak), model=cls, **plan.run)
    names = _declared(cls)
    for i, m in enumerate(plan.weak):
        r = simulate(plan.block, m, model=cls, **plan.run)
        for label, get in ((f"single run of {_describe(m)}", lambda k, r=r: getattr(r, k)),
                           (f"batch row {i}", lambda k, i=i: getattr(b, k)[i])):
            if "n_impacts" in names:
                assert get("n_impacts") == 0, f"{label}: {get('n_impacts')} impacts"
            assert not get("overturned"), f"{label}: overturned"
            assert math.isnan(get("uplift_time")), f"{label}: uplift_time {get('uplift_time')}"
            assert get("settled"), f"{label}: not settled"
            if "max_abs_theta" in names:
                assert get("max_abs_theta") <= tol, \
                    f"{label}: max_abs_theta {get('max_abs_theta')!r} rad > {tol:.3g}"
        if not _planar(cls):
            moved = float(np.max(np.abs(r.states - r.states[:1]))) if r.states.size else 0.0
            assert moved <= tol, f"single run of {_describe(m)}: the state moved by {moved:.3g}"


@_check
def check_batch_rows_equal_single_runs(cls, plan):
    """Each batch row is bit-identical to the single run of its motion."""
    b, singles = _runs(cls, plan, plan.block, plan.motions)
    for i, (m, r) in enumerate(zip(plan.motions, singles, strict=True)):
        _row_equals_single(b, i, r, f"row {i} ({_describe(m)})", cls)
    bare = simulate_many(plan.block, list(plan.motions), model=cls, **plan.run)
    for key in _declared(cls):  # histories must not change a run
        _expect_same(f"{key} without histories", getattr(bare, key), getattr(b, key),
                     "return_histories=False", "return_histories=True")


@_check
def check_chunk_independence(cls, plan):
    """A batch equals the concatenation of its chunks."""
    ms = list(plan.motions)
    k = max(1, len(ms) // 2)
    whole = simulate_many(plan.block, ms, model=cls, return_histories=True, **plan.run)
    parts = [simulate_many(plan.block, c, model=cls, return_histories=True, **plan.run)
             for c in (ms[:k], ms[k:])]
    for key in _declared(cls):
        _expect_same(key, getattr(whole, key),
                     np.concatenate([getattr(p, key) for p in parts]), "whole batch",
                     f"chunks [:{k}] + [{k}:]")
    for j, p in enumerate(parts):
        rows = slice(0, k) if j == 0 else slice(k, None)
        w = whole.states[rows]
        c = p.states
        _expect_same(f"state history of chunk {j}", w[:, : c.shape[1]], c, "whole batch",
                     "chunk")
        assert np.all(np.isnan(w[:, c.shape[1]:])), \
            f"state history of chunk {j}: the whole batch has samples past its end"


@_check
def check_blocks_per_row(cls, plan):
    """A batch with one block per row equals the single runs."""
    blocks = list(plan.blocks)
    ms = [plan.motions[i % len(plan.motions)] for i in range(len(blocks))]
    b, singles = _runs(cls, plan, blocks, ms)
    for i, r in enumerate(singles):
        _row_equals_single(b, i, r, f"row {i} ({blocks[i].name}, {_describe(ms[i])})", cls)
    if _planar(cls):
        assert len(set(b.max_abs_theta.tolist())) > 1, "every block gave the same answer"


def _state0(cls, plan, f: float, w: float, sign: float = 1.0) -> dict:
    """The initial state of a free run, as keywords: the planar shorthand ``theta0 = f
    alpha``, ``omega0 = w``; for another model ``state0`` with its first two states
    shifted by ``(f alpha, w)`` (times ``sign``) from its rest state
    (:meth:`Model.initial_state`)."""
    x = min(f * plan.block.alpha, 0.49 * math.pi)
    if _planar(cls):
        return {"theta0": sign * x, "omega0": sign * w}
    y = np.array(cls.from_kwargs(plan.block).initial_state(), dtype=np.float64)
    y[0] += sign * x  # from the model's rest state (a quaternion is not 0)
    if y.size > 1:
        y[1] += sign * w
    return {"state0": y}


@_check
def check_initial_state_per_row(cls, plan):
    """Per-row initial states equal the single runs."""
    ms = list(plan.motions)
    alpha = plan.block.alpha
    fr = [plan.theta0[i % len(plan.theta0)] for i in range(len(ms))]
    th0 = np.array([(-1) ** i * f * alpha for i, (f, _) in enumerate(fr)])
    th0 = np.clip(th0, -0.99 * alpha, 0.99 * alpha)
    th0[0] = 0.0
    om0 = np.array([w for _, w in fr])
    om0[0] = 0.0
    if _planar(cls):
        b, singles = _runs(cls, plan, plan.block, ms, theta0=th0, omega0=om0)
    else:
        y0 = np.array([_state0(cls, plan, t / alpha, w)["state0"]
                       for t, w in zip(th0, om0, strict=True)])
        b = simulate_many(plan.block, ms, model=cls, return_histories=True, state0=y0,
                          **plan.run)
        singles = [simulate(plan.block, m, model=cls, state0=y, **plan.run)
                   for m, y in zip(ms, y0, strict=True)]
    for i, r in enumerate(singles):
        _row_equals_single(b, i, r, f"row {i} (theta0={th0[i]:.4g}, omega0={om0[i]:.4g}, "
                                    f"{_describe(ms[i])})", cls)


def _mirror(label: str, a, b, frac: float, block) -> None:
    """``b`` is the mirror image of ``a`` (``theta`` negated; a model without a planar
    angle: every state negated) to ``frac alpha`` (angles) and ``frac / p`` (times)."""
    tol, tol_t = frac * block.alpha, frac / block.p
    planar = a.theta is not None
    for key in ("n_impacts", "overturned", "settled") if planar else ("overturned", "settled"):
        _expect_same(f"{label}: {key}", getattr(b, key), getattr(a, key), "mirrored",
                     "original")
    keys = (("max_abs_theta", tol),) if planar else ()
    for key, t in (*keys, ("overturn_time", tol_t), ("uplift_time", tol_t)):
        x, y = getattr(a, key), getattr(b, key)
        if not (_same(x, y) or abs(x - y) <= t):
            raise AssertionError(f"{label}: {key} {y!r} (mirrored) != {x!r} (original)")
    xa, xb = (a.theta, b.theta) if planar else (a.states, b.states)
    n = min(len(xa), len(xb))
    d = np.abs(xa[:n] + xb[:n])
    d = d if d.ndim == 1 else d.max(axis=1, initial=0.0)
    if a.t.size != b.t.size or not np.all(d <= tol):
        j = int(np.argmax(d)) if n else 0
        raise AssertionError(f"{label}: {'theta' if planar else 'state'} histories are not "
                             f"negatives of each other (lengths {a.t.size}, {b.t.size}; max "
                             f"|x + x_mirror| = {d.max() if n else 0:.3g} > {tol:.3g} at t = "
                             f"{a.t[j] if n else 0:.4g} s)")
    k = min(a.impact_times.size, b.impact_times.size)
    di = np.abs(a.impact_times[:k] - b.impact_times[:k])
    if k and di.max() > tol_t:
        raise AssertionError(f"{label}: impact times differ by up to {di.max():.3g} s "
                             f"> {tol_t:.3g} s")


@_check
def check_free_rocking_symmetry(cls, plan):
    """With the ``"mirror"`` tag, free motion from the mirrored initial state is the mirror
    image of the original (planar: ``-theta0``, ``-omega0``)."""
    if cls.tags.get("symmetry") != "mirror":
        return
    for f, w in plan.theta0:
        kw = {**plan.run, "duration": plan.free_duration}
        if plan.free_duration is not None:
            kw.pop("max_free_time", None)
        a = simulate(plan.block, None, model=cls, **_state0(cls, plan, f, w), **kw)
        b = simulate(plan.block, None, model=cls, **_state0(cls, plan, f, w, -1.0), **kw)
        _mirror(f"theta0 = +-{f:g} alpha, omega0 = +-{w:g}", a, b, FREE_SYMMETRY_TOL,
                plan.block)


@_check
def check_motion_symmetry(cls, plan):
    """With the ``"mirror"`` tag, the response to ``-motion`` is the mirror image of the
    response to ``motion``."""
    if cls.tags.get("symmetry") != "mirror":
        return
    for m in plan.motions:
        kw = {**plan.run, "duration": m.duration}
        kw.pop("max_free_time", None)
        a = simulate(plan.block, m, model=cls, **kw)
        b = simulate(plan.block, -m, model=cls, **kw)
        _mirror(f"{_describe(m)} and its negation", a, b, MOTION_SYMMETRY_TOL, plan.block)


ROTATION_TOL = 1e-4
"""Rotation equivariance: largest difference of a scalar output between a run and the
same run turned about the vertical (fraction of its scale: ``alpha`` for angles, the
body's height for lengths, ``1 / p`` for times): the contact solver's tolerance (its
default, ``rigid3d``) moves ``max_tilt`` by ~1e-5 ``alpha`` between the two runs; a frame
error moves it by the order of ``alpha``."""
ROTATION_HISTORY_TOL = 1e-3
"""Rotation equivariance of the state history: largest difference (fraction of the
body's height times ``p``, a velocity; positions and quaternions are held to the same
number). The contact solver's tolerance, amplified by the impacts, separates the two runs
by ~1e-5 of it (``rigid3d``, 3 s of rocking); a frame error is of the order of 1."""


@_check
def check_rotation_equivariance(cls, plan):
    """With the ``"rotation"`` tag, turning the body (its initial state, by the model's
    ``rotate_state(y, beta)``) and the motion (the option ``direction``, deg) together
    about the vertical changes nothing: the same scalar outputs (``overturn_azimuth``
    turned by ``beta``) and the state history turned by ``beta``."""
    if cls.tags.get("symmetry") != "rotation":
        return
    model = cls.from_kwargs(plan.block)
    y0 = model.initial_state()
    size = float(getattr(plan.block, "height", None) or 1.0)
    for m in plan.motions[:3]:
        kw = {**plan.run, "duration": m.duration}
        kw.pop("max_free_time", None)
        a = simulate(plan.block, m, model=cls, **kw)
        for beta_deg in (37.0, -120.0):
            beta = math.radians(beta_deg)
            b = simulate(plan.block, m, model=cls, state0=model.rotate_state(y0, beta),
                         direction=beta_deg, **kw)
            label = f"{_describe(m)} turned by {beta_deg:g} deg"
            for o in cls.outputs:
                if o.name in ("n_out", "n_steps"):
                    continue
                x, y = a.outputs[o.name], b.outputs[o.name]
                if o.name == "overturn_azimuth" and not math.isnan(x):
                    y = (y - beta_deg - x + 180.0) % 360.0 - 180.0 + x
                if o.flag or o.integer:
                    _expect_same(f"{label}: {o.name}", y, x, "turned", "original")
                    continue
                scale = {"rad": plan.block.alpha, "m": size, "s": 1.0 / plan.block.p,
                         "deg": math.degrees(plan.block.alpha)}.get(o.unit, 1.0)
                if not (_same(x, y) or abs(x - y) <= ROTATION_TOL * scale):
                    raise AssertionError(f"{label}: {o.name} {y!r} (turned) != {x!r} "
                                         "(original)")
            back = np.array([model.rotate_state(s, -beta) for s in b.states])
            n = min(len(back), len(a.states))
            d = float(np.max(np.abs(back[:n] - a.states[:n]), initial=0.0))
            if len(back) != len(a.states) or d > ROTATION_HISTORY_TOL * size * plan.block.p:
                raise AssertionError(f"{label}: the turned state history differs by {d:.3g} "
                                     f"(lengths {len(back)}, {len(a.states)})")


@_check
def check_declared_outputs(cls, plan):
    """The declared outputs and states, everywhere: the result record's fields are the
    outputs, ``summary()`` has every one, the batch and (for a registered model) a
    campaign's table have a column each, with the declared unit in the Parquet schema."""
    names = _declared(cls)
    dtype_names = list(cls.result_dtype().names)
    assert dtype_names == [o.name for o in cls.outputs], \
        f"result record fields {dtype_names} != outputs {[o.name for o in cls.outputs]}"
    assert [o.name for o in cls.outputs[:len(GENERIC_OUTPUTS)]] == \
        [o.name for o in GENERIC_OUTPUTS], "outputs must start with GENERIC_OUTPUTS"
    model = cls.from_kwargs(plan.block)
    assert len(model.state_names) == len(model.initial_state()), \
        f"initial_state() has {len(model.initial_state())} values for " \
        f"{len(model.state_names)} state_names"
    r = simulate(plan.block, plan.motions[0], model=cls, **plan.run)
    s = r.summary()
    missing = [k for k in names if k not in s]
    assert not missing, f"summary() lacks the declared outputs {missing}"
    from ..models import MODELS
    if MODELS.get(cls.name) is not cls:
        return  # campaigns take registered models
    from ..campaign import Campaign, parse_spec
    from ..campaign.store import result_schema
    spec = parse_spec(CAMPAIGN_SPEC.format(model=cls.name))
    rows = Campaign(spec).run_ids(range(spec.n_sims))
    # n_steps is a diagnostic of single runs; lift_off_time a column of vertical motions
    lacking = [k for k in names if k not in rows.columns
               and k not in ("n_steps", "lift_off_time")]
    assert not lacking, f"a campaign's table lacks the declared outputs {lacking}"
    schema = result_schema(rows, [cls.name])
    for o in cls.outputs:
        if o.name in rows.columns:
            meta = schema.field(o.name).metadata or {}
            assert meta.get(b"unit", b"").decode() == o.unit, \
                f"campaign column {o.name}: unit {meta.get(b'unit')} != declared {o.unit!r}"


CAMPAIGN_SPEC = """\
campaign = {{name = "check-model", seed = 1, model = "{model}"}}
blocks = [{{specimen = 3}}]
[motions]
kind = "one_sine"
period = 0.5
amplitude = 1.0
load_factors = [1.0, 3.0]
"""
"""The campaign of :func:`check_declared_outputs`: one block, one pulse at two levels."""


# ================================================================================ driver
def model_checks(cls, *, quick: bool = True) -> Iterator[tuple[str, Callable[[], None]]]:
    """``(name, check)`` pairs of the model contract for ``cls``; ``check()`` raises
    AssertionError naming itself on failure.

    Examples
    --------
    Run one check alone (a passing check returns None):

    >>> from rocking.testing import model_checks
    >>> checks = dict(model_checks("housner"))
    >>> "check_batch_rows_equal_single_runs" in checks
    True
    >>> checks["check_free_rocking_symmetry"]()  # -theta0 mirrors +theta0
    """
    for check in CHECKS:
        yield check.__name__, functools.partial(check, cls, quick=quick)


def check_model(cls, *, quick: bool = True) -> None:
    """Run every check of the model contract on ``cls`` (a Model subclass or a registered
    name); raise one AssertionError listing the failed checks and what differed.

    ``quick=False`` runs more motions, blocks and initial states.

    Examples
    --------
    ``check_model("housner")`` passes silently (about a second); a class that breaks the
    contract is named with what it broke:

    >>> from rocking.models import MODELS
    >>> from rocking.testing import check_model
    >>> class Unlabelled(MODELS["housner"]):
    ...     label = ""
    >>> try:
    ...     check_model(Unlabelled)
    ... except AssertionError as e:
    ...     print(e)
    check_class_attributes failed for model 'housner' (Unlabelled): label must be a non-empty string
    """
    cls = cls if isinstance(cls, type) else get_model(cls)
    check_class_attributes(cls)  # the other checks cannot run without them
    failed = []
    for name, check in model_checks(cls, quick=quick):
        try:
            if name != "check_class_attributes":
                check()
        except AssertionError as e:
            failed.append(str(e))
    if failed:
        raise AssertionError(f"check_model({cls.__name__}): {len(failed)} of {len(CHECKS)} "
                             "checks failed:\n" + "\n".join(f"- {m}" for m in failed))
