"""The one entry point of every model: :func:`simulate` and :func:`simulate_many`.

Shared code, written once for all models (see :mod:`rocking.models.base` for what a model
provides): validation of the arguments, packing the motions for the compiled kernels, the
output buffers and the memory guard, the parallel batch, and building
:class:`~rocking.results.Response` / :class:`~rocking.results.BatchResponse`.
"""

from __future__ import annotations

import math
import threading
import warnings
from collections import namedtuple

import numba
import numpy as np

from .._compile_notice import compile_notice
from .._validate import as_float, as_int, in_range, non_negative, positive, sequence_of
from ..blocks import Block, Stack
from ..errors import OutputTooLargeError, ParameterError, SimulationError
from ..motions import HorizontalPair, Motion
from ..motions._kernel import NPRM
from ..results import DEFAULT_DT_OUT, BatchResponse
from .base import (
    BATCH_OUTPUTS,
    Batch,
    Model,
    empty_results,
    result_arrays,
    result_values,
)
from .registry import MODELS

HALF_PI = 0.5 * math.pi
MAX_OUTPUT_BYTES = 2 * 1024 ** 3
"""Largest memory (bytes) the output buffers of one call may take (the memory guard)."""
MAX_IMPACTS = 100_000
"""Default number of impact times kept by a single run (all impacts are counted)."""
DEFAULT_MAX_FREE_TIME = 60.0
"""Default cap (s) of the free motion after the ground motion ends (``duration=None``).

Free rocking decays geometrically: each impact multiplies the angular velocity by
``mu`` (Eq 4) and a half-cycle of amplitude ``a alpha`` lasts ``~ (2/p) sqrt(2 a)``
(linearised Eq 1), so a block released from any amplitude below ``alpha`` comes to rest
within ``T = 2 sqrt(2) / (p (1 - mu))``. For Housner's ``mu = 1 - 1.5 sin^2(alpha)``
(Eq 4) that is 18 s for specimen 2 (``alpha = 0.168``, ``p = 3.8``) and 60 s for a block
with ``p = 1.5 1/s`` (about 4.5 m tall) and ``alpha = 0.2`` (``mu = 0.94``): 60 s lets
every block with ``p >= 1.5 1/s`` and ``alpha >= 0.2``, or ``p >= 3`` and
``alpha >= 0.14``, settle from any amplitude. More slender or larger blocks may end
unsettled (flagged by ``settled``) in the CCRR and DEM models; the classical model
decides every block at the cap exactly, by energy (:func:`rocking.models.housner.free_outcome`).
The tail costs little: most runs end at rest or overturned long before the cap, and once
the ground is still the classical and CCRR models put a block to rest at ``1e-3 alpha``
(``free_rest_tol``): on ``benchmarks/bench_campaign.py --only tail`` (10^5 classical
runs, 20 s records) the CPU time is 1.054 times that of runs stopped at the record's end,
18,760 runs were still rocking there, and 3 of them overturn afterwards."""


def get_model(model) -> type[Model]:
    """The model class of a registered name (case-insensitive) or a :class:`Model` class.

    Examples
    --------
    >>> from rocking.models import get_model
    >>> get_model("Housner").label
    'classical (Housner)'
    >>> [o.name for o in get_model("isolated").row_outputs][:2]
    ['max_base_displacement', 'max_plate_acceleration']
    """
    if isinstance(model, type) and issubclass(model, Model):
        if model.kernel is None or model.batch_kernel is None:
            raise ParameterError(f"model class {model.__name__} must define kernel and "
                                 "batch_kernel (see rocking.models.base)")
        return model
    try:
        return MODELS[str(model).lower()]
    except KeyError:
        raise ParameterError(f"model must be one of {', '.join(MODELS)} or a "
                             f"rocking.models.Model subclass; got {model!r}") from None


def require_planar(model, what: str) -> type[Model]:
    """The model class of ``model`` if it has a planar angle (``Model.tags["planar"]``),
    else a ParameterError saying that ``what`` works on ``max |theta| / alpha``.

    Examples
    --------
    >>> from rocking.models import require_planar
    >>> require_planar("housner", "fragility").name
    'housner'
    """
    cls = get_model(model)
    if not cls.tags.get("planar"):
        raise ParameterError(f"model {cls.name!r} has no planar angle (Model.tags['planar'] "
                             f"is False): {what} works on max |theta| / alpha of a planar "
                             "model")
    return cls


def is_3d(model) -> bool:
    """True for a model of a 3-D body: its state has an orientation quaternion
    (``q0`` to ``q3`` among ``Model.state_names``: ``rigid3d``), its block is a
    :class:`rocking.shapes.Shape`.

    Examples
    --------
    >>> from rocking.models import is_3d
    >>> is_3d("rigid3d"), is_3d("housner")
    (True, False)
    """
    names = get_model(model).state_names
    # a model whose states depend on its block (the DEM's, per block) declares them as a
    # property: not a single 3-D body
    return not isinstance(names, property) and {"q0", "q1", "q2", "q3"} <= set(names)


def _make(model, block, linear: bool, options: dict) -> Model:
    cls = get_model(model)
    if check_linear(linear):
        if "linear" not in {f for f in cls.Options.__dataclass_fields__}:
            raise ParameterError(f"linear=True is not available for model {cls.name!r} "
                                 "(use model='housner')")
        options = {**options, "linear": True}
    return cls.from_kwargs(block, **options)


def _guard(n_values: int, extra: int, dt_out: float, duration: float) -> None:
    """Refuse output buffers larger than :data:`MAX_OUTPUT_BYTES`."""
    need = 8 * n_values + extra
    if need > MAX_OUTPUT_BYTES:
        raise OutputTooLargeError(
            f"dt_out = {dt_out:g} s over a duration of {duration:g} s needs "
            f"{need / 1e9:.3g} GB of output (limit {MAX_OUTPUT_BYTES / 1e9:.3g} GB): "
            "increase dt_out or shorten the duration (with duration=None a run may go on "
            "max_free_time seconds after the motion)")


def _n_out(duration: float, dt_out: float) -> int:
    n = duration / dt_out
    if not n < 2 ** 53:
        return 2 ** 62
    return int(math.floor(n + 1e-9)) + 1


# ================================================================================ window
def run_window(motion, duration=None, max_free_time=None) -> tuple[float, float]:
    """``(t_end, t_quiet)`` of a run (s): where it stops at the latest, and from when the
    ground is still, so that it stops as soon as the block has settled.

    An explicit ``duration`` is the run's length exactly (``t_quiet = inf``). With
    ``duration=None`` the run covers the motion (``max(motion.duration,
    motion.quiet_time)``; 0 for free rocking) and goes on with the ground still until
    the block is at rest or has overturned, at most ``max_free_time`` more seconds
    (default :data:`DEFAULT_MAX_FREE_TIME`).
    """
    if duration is not None:
        if max_free_time is not None:
            raise ParameterError("max_free_time applies only with duration=None (a run "
                                 "with an explicit duration stops exactly there)")
        return positive("duration", duration, "s"), math.inf
    free = DEFAULT_MAX_FREE_TIME if max_free_time is None else non_negative(
        "max_free_time", max_free_time, "s")
    t_quiet = 0.0 if motion is None else max(motion.duration, motion.quiet_time)
    return t_quiet + free, t_quiet


# ================================================================================ single
def check_run(motion, duration, theta0, omega0, max_free_time=None
              ) -> tuple[float, float, float, float]:
    """Validated ``(t_end, t_quiet, theta0, omega0)`` of a single run
    (:func:`run_window`)."""
    if motion is not None and not isinstance(motion, Motion | HorizontalPair):
        raise ParameterError(f"motion must be a rocking.motions.Motion (a HorizontalPair "
                             f"for a 3-D model) or None, got {type(motion).__name__}")
    t_end, t_quiet = run_window(motion, duration, max_free_time)
    theta0 = in_range("theta0", theta0, -HALF_PI, HALF_PI, shown="(-pi/2, pi/2) rad")
    omega0 = as_float("omega0", omega0)
    return t_end, t_quiet, theta0, omega0


def check_linear(linear) -> bool:
    """``linear`` as a bool: only ``True`` or ``False`` (a string such as ``"false"``
    would otherwise select the linear model)."""
    if not isinstance(linear, bool | np.bool_):
        raise ParameterError(f"linear must be True or False, got {linear!r}")
    return bool(linear)


def _positional(func: str, args: tuple, names: tuple, given: dict) -> dict:
    """Arguments after ``duration`` given by position (deprecated: keywords only, so that
    :func:`simulate` and :func:`simulate_many` take their arguments in one order)."""
    if not args:
        return {}
    if len(args) > len(names):
        raise TypeError(f"{func}() takes at most {4 + len(names)} positional arguments")
    out = dict(zip(names, args, strict=False))
    for k in out:
        if given.get(k) is not None:
            raise TypeError(f"{func}() got multiple values for argument {k!r}")
    warnings.warn(f"{func}(): passing {', '.join(out)} by position is deprecated; pass "
                  f"{'them' if len(out) > 1 else 'it'} by keyword", DeprecationWarning,
                  stacklevel=3)
    return out


def simulate(block, motion=None, model="housner", duration: float | None = None, *args,
             theta0: float | None = None, omega0: float | None = None,
             linear: bool | None = None, max_free_time: float | None = None,
             dt_out: float = DEFAULT_DT_OUT, max_impacts: int = MAX_IMPACTS, state0=None,
             **options):
    """Simulate one block under one base motion and return a :class:`~rocking.Response`.

    Parameters
    ----------
    block : Block (or Stack for ``model="dem"``)
    motion : Motion or None
        Base motion; ``None`` means free rocking from ``theta0``, ``omega0``. A
        :class:`~rocking.motions.GroundMotion` adds a vertical component (positive upwards:
        ``g`` becomes ``g + a_v``); where ``g + a_v <= 0`` the classical and CCRR models
        stop (``Response.lifted_off``, ``lift_off_time``).
    model : str or Model class
        A registered name (``"housner"``: classical model, Eq 1; ``"ccrr"``: Eq 10;
        ``"dem"``: discrete elements) or a :class:`rocking.models.Model` subclass.
    duration : float, optional
        Simulated time (s), exactly. By default (``None``) the run covers the motion and
        goes on, with the ground still, until the block is at rest or has overturned
        (``Response.settled``), at most ``max_free_time`` longer: a block still falling
        when the record ends is not reported as a survivor.
    theta0, omega0 : float
        Initial angle (rad, in (-pi/2, pi/2)) and angular velocity (rad/s): the planar
        models' shorthand for their initial state.
    state0 : array_like, optional
        The initial state vector (``Model.state_names``; instead of ``theta0``,
        ``omega0``). Default: at rest.
    linear : bool, optional
        The small-angle form of Eq 1 (models with a ``linear`` option); True or False
        (None, the default: False).

        ``theta0``, ``omega0`` and ``linear`` are keywords, as in :func:`simulate_many`
        (both take ``block, motion(s), model, duration`` by position, the rest by
        keyword); by position they still work, with a ``DeprecationWarning``.
    max_free_time : float, optional
        Cap (s) of the free motion after the ground motion ends, with ``duration=None``
        (default :data:`DEFAULT_MAX_FREE_TIME`, 60 s; see there why).
    dt_out : float
        Output interval of the time history (s).
    max_impacts : int
        Impact times kept in ``Response.impact_times`` (all are counted in ``n_impacts``).
    **options
        The model's options (``rocking.models.MODELS[name].Options``), e.g. ``rtol`` and
        ``rest_tol`` for ``"housner"``. Unknown options are an error.

    Examples
    --------
    Free rocking from half the critical angle (``motion=None``); in the linearised Eq 1
    the first impact comes at ``acosh(2) / p``:

    >>> import math
    >>> import rocking
    >>> block = rocking.specimen(2)
    >>> r = rocking.simulate(block, theta0=0.5 * block.alpha, duration=1.0, linear=True)
    >>> round(float(r.impact_times[0]), 4), round(math.acosh(2) / block.p, 4)
    (0.3457, 0.3457)

    A pulse below the uplift acceleration ``g tan(alpha)`` does not rock the block:

    >>> from rocking.motions import OneSine
    >>> pulse = OneSine(0.9 * rocking.G * math.tan(block.alpha), 0.5)
    >>> rocking.simulate(block, pulse).rocked
    False
    """
    pos = _positional("simulate", args, ("theta0", "omega0", "linear"),
                      {"theta0": theta0, "omega0": omega0, "linear": linear})
    theta0 = pos.get("theta0", theta0)
    omega0 = pos.get("omega0", omega0)
    linear = pos.get("linear", False if linear is None else linear)
    m = _make(model, block, linear, options)
    cls = type(m)
    duration, t_quiet, y0, (theta0, omega0) = _initial(m, motion, duration, theta0, omega0,
                                                       state0, max_free_time)
    dt_out = positive("dt_out", dt_out, "s")
    cap = as_int("max_impacts", max_impacts, 0, 10 ** 7)
    if motion is None:
        kind, prm, samples, h_scan = 0, np.zeros(NPRM), np.empty(0), max(duration, 1.0)
    else:
        (kind, prm, samples), h_scan = m.motion_spec(motion), motion.scan_step
    n_out = _n_out(duration, dt_out)
    ns = y0.size
    _guard(ns * n_out + int(cap), m.extra_bytes(n_out), dt_out, duration)
    hist = np.empty((n_out, ns))
    imp = np.empty(max(1, int(cap)))
    extra = m.extra_buffers(n_out)
    res = empty_results(cls.outputs, 1)
    mp = m.kernel_params(dt_out, theta0, omega0)
    compile_notice(m.kernels()[0])(mp, kind, prm, samples, duration, t_quiet, h_scan, y0, dt_out,
                               hist, imp, res[0], extra)
    values = result_values(cls.outputs, res[0])
    k = values["n_out"]
    if values["status"] != 0:
        raise SimulationError(m.failure(values["status"], k * dt_out, dt_out))
    t = np.arange(k) * dt_out
    states = hist[:k]
    over, t_over = values["overturned"], values["overturn_time"]
    shorthand = m.planar_shorthand()
    if (over and m.append_overturn and shorthand is not None
            and (k == 0 or t[-1] < t_over)):  # end on the overturn
        i_th, i_om = shorthand
        last = states[-1].copy() if k else np.zeros(ns)
        last[i_th] = math.copysign(HALF_PI, states[-1, i_th] if k else 1.0)
        last[i_om] = states[-1, i_om] if k else 0.0
        t = np.append(t, t_over)
        states = np.vstack((states, last[None, :]))
    fields = m.extra_fields(k, states, extra, dt_out)
    info = {**m.info(dt_out), "n_steps": values["n_steps"], **m.result_info(values),
            **fields.pop("info", {})}
    th = om = None
    if shorthand is not None:
        th, om = states[:, shorthand[0]].copy(), states[:, shorthand[1]].copy()
    n_imp = values.get("n_impacts", 0)
    return m.response_class(
        t=t, theta=th, omega=om, impact_times=imp[: min(n_imp, cap)].copy(),
        max_abs_theta=values.get("max_abs_theta"), overturned=over,
        overturn_time=t_over if over else math.nan, uplift_time=values["uplift_time"],
        n_impacts=n_imp, model=m.result_name, block=block, motion=motion,
        info=info, lift_off_time=values["lift_off_time"], settled=values["settled"],
        states=states.copy(), state_names=tuple(m.state_names),
        outputs={o.name: values[o.name] for o in cls.outputs if o.name != "n_out"}, **fields)


def _initial(m: Model, motion, duration, theta0, omega0, state0, max_free_time):
    """``(t_end, t_quiet, y0, (theta0, omega0))`` of a single run: the window and the
    initial state (``state0``, or the planar shorthand)."""
    if state0 is not None:
        if theta0 is not None or omega0 is not None:
            raise ParameterError("give the initial state as state0 or as theta0/omega0, "
                                 "not both")
        t_end, t_quiet, _, _ = check_run(motion, duration, 0.0, 0.0, max_free_time)
        y0 = m.check_state(state0)
        sh = m.planar_shorthand()
        return t_end, t_quiet, y0, ((y0[sh[0]], y0[sh[1]]) if sh else (0.0, 0.0))
    t_end, t_quiet, theta0, omega0 = check_run(
        motion, duration, 0.0 if theta0 is None else theta0,
        0.0 if omega0 is None else omega0, max_free_time)
    return t_end, t_quiet, m.initial_state(theta0, omega0), (theta0, omega0)


# ================================================================================= batch
PackedMotions = namedtuple("PackedMotions", ["kinds", "prms", "samples", "nsamp", "t_ends",
                                             "h_scans", "t_quiets"])
PackedMotions.__doc__ = """Motions packed for the batch kernels (:func:`pack_motions`):
kind codes, parameters, padded samples and their counts, and each run's window (s) and
scan step (s).

Examples
--------
>>> from rocking.models import pack_motions
>>> from rocking.motions import OneSine
>>> pm = pack_motions([OneSine(1.0, 0.5), OneSine(2.0, 0.25)], duration=2.0)
>>> pm._fields[:4], pm.t_ends
(('kinds', 'prms', 'samples', 'nsamp'), array([2., 2.]))
"""


def motion_list(motions) -> tuple:
    """``motions`` (one motion or a sequence) as a checked tuple of motions
    (:class:`~rocking.motions.HorizontalPair` objects too, for a 3-D model)."""
    if isinstance(motions, Motion | HorizontalPair):
        motions = [motions]
    return sequence_of("motions", motions, Motion | HorizontalPair,
                       "rocking.motions.Motion (or HorizontalPair)")


def pack_motions(motions, duration=None, max_free_time=None, spec=None,
                 buffer=None) -> PackedMotions:
    """Pack motions into padded arrays for the batch kernels.

    Returns a :data:`PackedMotions` (by name, or unpacked in the order ``kinds, prms,
    samples, nsamp, t_ends, h_scans, t_quiets``; the window of each run:
    :func:`run_window`). ``spec``: the function that gives a motion's spec (default
    ``Motion.spec``; a model's :meth:`~rocking.models.Model.motion_spec`). ``buffer``: a
    function of a size giving a 1-D float64 array at least that long (or None), whose
    view then holds ``samples`` instead of a new array (:func:`scratch_buffer`); the same
    values either way.

    Examples
    --------
    >>> from rocking.models import pack_motions
    >>> from rocking.motions import OneSine
    >>> kinds, prms, samples, nsamp, t_ends, h_scans, t_quiets = pack_motions(
    ...     [OneSine(1.0, 0.5), OneSine(2.0, 0.25)], duration=2.0)
    >>> kinds.shape, t_ends
    ((2,), array([2., 2.]))
    >>> pm = pack_motions([OneSine(1.0, 0.5)], duration=2.0)
    >>> pm.t_ends, pm.t_quiets  # by name; an explicit duration: t_quiet = inf
    (array([2.]), array([inf]))
    """
    motions = motion_list(motions)
    specs = [mo.spec() if spec is None else spec(mo) for mo in motions]
    n = len(motions)
    nsamp = np.array([s[2].size for s in specs], dtype=np.int64)
    width = max(1, int(nsamp.max()))
    buf = None if buffer is None else buffer(n * width)
    if buf is not None:
        samples = buf[: n * width].reshape(n, width)
        for i, s in enumerate(specs):
            samples[i, : s[2].size] = s[2]
            samples[i, s[2].size:] = 0.0
    else:
        samples = np.zeros((n, width))
        for i, s in enumerate(specs):
            samples[i, : s[2].size] = s[2]
    kinds = np.array([s[0] for s in specs], dtype=np.int64)
    prms = np.stack([s[1] for s in specs])
    windows = np.array([run_window(mo, duration, max_free_time) for mo in motions],
                       dtype=np.float64).reshape(n, 2)
    h_scans = np.array([mo.scan_step for mo in motions], dtype=np.float64)
    return PackedMotions(kinds, prms, samples, nsamp, windows[:, 0].copy(), h_scans,
                         windows[:, 1].copy())


SCRATCH_BYTES = 256 * 2 ** 20
"""The largest packed-samples array that :func:`simulate_many` keeps for the next batch
of its thread (bytes): a campaign's chunks then reuse memory already mapped instead of
faulting fresh pages in for every chunk (tens of microseconds per run, serial)."""

_scratch = threading.local()


def scratch_buffer(size: int) -> np.ndarray | None:
    """This thread's reusable float64 buffer of at least ``size`` values (grown as needed),
    or None above :data:`SCRATCH_BYTES`: ``pack_motions(..., buffer=scratch_buffer)``.
    The next call on the same thread overwrites it.

    Examples
    --------
    >>> from rocking.models.run import scratch_buffer
    >>> a = scratch_buffer(1000)
    >>> a.size >= 1000, scratch_buffer(10) is a, scratch_buffer(2 ** 40) is None
    (True, True, True)
    """
    if size * 8 > SCRATCH_BYTES:
        return None
    buf = getattr(_scratch, "buf", None)
    if buf is None or buf.size < size:
        buf = np.empty(max(int(size), 1))
        _scratch.buf = buf
    return buf


def _per_row(name: str, value, n: int, lo: float = -math.inf, hi: float = math.inf,
             shown: str = "") -> np.ndarray:
    """A scalar or one value per motion, as a float array of length ``n``."""
    arr = np.atleast_1d(np.asarray(value, dtype=object))
    if arr.ndim != 1 or arr.size not in (1, n):
        raise ParameterError(f"{name} must be a number or one value per motion ({n}), "
                             f"got {arr.size} values")
    out = np.array([in_range(name, v, lo, hi, shown=shown) if (lo, hi) != (-math.inf, math.inf)
                    else as_float(name, v) for v in arr], dtype=np.float64)
    return np.broadcast_to(out, (n,)).copy()


def _blocks(cls: type[Model], block, n: int) -> list:
    """One block per row (``block`` is a block or one block per motion), each checked."""
    if isinstance(block, Block | Stack) or not isinstance(block, list | tuple | np.ndarray):
        return [block] * n
    blocks = list(block)
    if len(blocks) != n:
        raise ParameterError(f"block must be one block or one block per motion ({n}), "
                             f"got {len(blocks)}")
    seen = set()
    for b in blocks:  # each distinct block once (a campaign's rows share their blocks)
        if id(b) not in seen:
            seen.add(id(b))
            cls.check_block(b)
    return blocks


def simulate_many(block, motions, model="housner", duration: float | None = None, *args,
                  theta0=0.0, omega0=0.0, linear: bool | None = None,
                  max_free_time: float | None = None, return_histories: bool = False,
                  dt_out: float = DEFAULT_DT_OUT, errors: str = "raise", state0=None,
                  **options):
    """Simulate blocks under many motions in one compiled, parallel call.

    ``block`` is one block for every motion, or one block per motion (Monte Carlo over the
    block's parameters; a model with a ``block_row`` -- the classical, CCRR, anchored and
    isolated models -- still runs a single compiled call, the DEM one call per distinct
    block). ``theta0``, ``omega0`` (rad, rad/s): the initial
    state, one value or one per motion (default: at rest). Row ``i`` of the result is
    bit-identical to ``simulate(block_i, motions[i], theta0=theta0_i, ...)``: each run
    depends on its own inputs only, never on the rest of the batch, so chunking a study
    never changes its numbers.

    Returns a :class:`~rocking.results.BatchResponse` with numpy arrays ``max_abs_theta``,
    ``overturned``, ``overturn_time``, ``uplift_time`` and ``n_impacts`` (one entry per
    motion); the time histories ``theta``, ``omega`` (at ``dt_out``) only with
    ``return_histories=True``; a model's own scalar outputs (its ``row_outputs``, e.g. the
    isolated base's ``max_base_displacement``) in ``outputs`` (by name, also as
    attributes: ``res.max_base_displacement``). ``errors="raise"`` (default) raises
    :class:`~rocking.errors.SimulationError` if a run fails numerically;
    ``errors="nan"`` marks it with a non-zero ``status`` and NaN ``max_abs_theta`` and
    times instead (its ``overturned`` and ``n_impacts`` are those reached before the
    failure). ``duration=None`` (default): each run covers its motion and goes on until
    the block has settled, at most ``max_free_time`` more (``settled`` flags the runs
    that had not); an explicit ``duration`` is every run's length exactly. Other
    arguments as in :func:`simulate`.

    Examples
    --------
    Each row equals its single run; on an isolated base (2.5 s, 10 % damping) the pulse
    that overturns the free-standing block leaves it standing:

    >>> import math
    >>> import rocking
    >>> from rocking.motions import OneSine
    >>> block = rocking.specimen(2)
    >>> pulses = [OneSine(f * rocking.G * math.tan(block.alpha), 0.5) for f in (0.9, 1.5)]
    >>> res = rocking.simulate_many(block, pulses, duration=3.0)
    >>> res.overturned
    array([False,  True])
    >>> bool(res.max_abs_theta[1] == rocking.simulate(block, pulses[1], duration=3.0).max_abs_theta)
    True
    >>> iso = rocking.simulate_many(block, pulses, model="isolated", isolation_period=2.5,
    ...                             isolation_damping=0.1, duration=3.0)
    >>> iso.overturned, bool(np.all(iso.max_base_displacement > 0))
    (array([False, False]), True)
    """
    linear = _positional("simulate_many", args, ("linear",), {"linear": linear}).get(
        "linear", False if linear is None else linear)
    if errors not in ("raise", "nan"):
        raise ParameterError(f"errors must be 'raise' or 'nan', got {errors!r}")
    if not isinstance(return_histories, bool | np.bool_):
        raise ParameterError(f"return_histories must be True or False, "
                             f"got {return_histories!r}")
    cls = get_model(model)
    planar_specs = cls.motion_spec is Model.motion_spec
    if planar_specs:  # the samples in this thread's scratch buffer: no fresh pages
        pm = pack_motions(motions, duration, max_free_time, buffer=scratch_buffer)
        n = pm.kinds.size
    else:  # a 3-D model: its specs (three components) need the model's options
        motions = motion_list(motions)
        n = len(motions)
    blocks = _blocks(cls, block, n)
    m = _make(model, blocks[0], linear, options)
    m.check_batch()
    if not planar_specs:
        pm = pack_motions(motions, duration, max_free_time, spec=m.motion_spec,
                          buffer=scratch_buffer)
    dt_out = positive("dt_out", dt_out, "s")
    y0, th0, om0 = _batch_states(m, n, theta0, omega0, state0)
    ns = y0.shape[1]
    n_out = _n_out(float(pm.t_ends.max()), dt_out) if return_histories else 0
    # the rows in flight (one per thread) may hold the model's extra buffers too
    _guard(ns * n * n_out, numba.get_num_threads() * m.extra_bytes(n_out), dt_out,
           float(pm.t_ends.max()))
    rows = Batch(kinds=pm.kinds, prms=pm.prms, samples=pm.samples, nsamp=pm.nsamp,
                 t_ends=pm.t_ends, t_quiets=pm.t_quiets, h_scans=pm.h_scans, y0=y0,
                 dt_out=dt_out, states=np.empty((n, n_out, ns)),
                 res=empty_results(cls.outputs, n))
    nb = len(cls.block_row(blocks[0]))
    per_state = not cls.batch_initial_state and (th0.any() or om0.any())
    if (nb or len({id(b) for b in blocks}) == 1) and not per_state:
        rows_of: dict = {}  # each distinct block's row once
        bp = np.array([rows_of[id(b)] if id(b) in rows_of
                       else rows_of.setdefault(id(b), cls.block_row(b)) for b in blocks],
                      dtype=np.float64).reshape(n, nb)
        compile_notice(m.kernels()[1])(m.kernel_params(dt_out, 0.0, 0.0), m.extra_buffers(0),
                                        rows, bp)
    else:  # one batch per distinct block (DEM) and initial state: results in place
        first: dict = {}
        groups: dict = {}
        for i, b in enumerate(blocks):
            key = (first.setdefault(b, i), float(th0[i]), float(om0[i]))
            groups.setdefault(key, []).append(i)
        for (j, t0, w0), members in groups.items():
            idx = np.array(members)
            sub = Batch(*(a[idx] if isinstance(a, np.ndarray) else a for a in rows))
            mb = m if blocks[j] is blocks[0] else type(m)(blocks[j], m.options)
            if state0 is None and cls.initial_state is not Model.initial_state:
                y = mb.initial_state(t0, w0)  # the state of this block (its own size)
                if y.size != ns:
                    if return_histories:
                        raise ParameterError(
                            f"return_histories=True needs blocks with states of one size; "
                            f"{blocks[0]!r} has {ns}, {blocks[j]!r} {y.size} (model "
                            f"{cls.name!r}): run them in separate batches")
                    sub = sub._replace(y0=np.empty((idx.size, y.size)),
                                       states=np.empty((idx.size, 0, y.size)))
                sub.y0[:] = y
            compile_notice(mb.kernels()[1])(mb.kernel_params(dt_out, t0, w0),
                                            mb.extra_buffers(0), sub, np.empty((idx.size, 0)))
            for name in BATCH_OUTPUTS:
                if getattr(sub, name).shape[1:] == getattr(rows, name).shape[1:]:
                    getattr(rows, name)[idx] = getattr(sub, name)
    out = result_arrays(cls.outputs, rows.res)
    m.check_results(out)
    status = out["status"]
    bad = np.flatnonzero(status)
    if bad.size:
        if errors == "raise":
            i = int(bad[0])
            raise SimulationError(f"{bad.size} of {n} runs failed; motions[{i}]: "
                                  + m.failure(int(status[i]), math.nan, dt_out))
        for o in cls.outputs:  # the failed runs: NaN values, not settled
            if o.name in ("overturned", "status", "n_out", "n_steps") or o.integer:
                continue
            out[o.name][bad] = False if o.flag else math.nan
    planar = m.planar_shorthand()
    states = rows.states if return_histories else None
    own = {o.name: out[o.name] for o in cls.row_outputs}
    return BatchResponse(
        max_abs_theta=out.get("max_abs_theta"), overturned=out["overturned"],
        overturn_time=out["overturn_time"], uplift_time=out["uplift_time"],
        n_impacts=out.get("n_impacts"), n_steps=out["n_steps"], status=status,
        t=np.arange(n_out) * dt_out if return_histories else None,
        theta=states[:, :, planar[0]] if planar and return_histories else None,
        omega=states[:, :, planar[1]] if planar and return_histories else None,
        model=m.result_name, block=block, info=m.info(dt_out),
        lift_off_time=out["lift_off_time"], settled=out["settled"], outputs=own,
        states=states, state_names=tuple(m.state_names),
    )


def _batch_states(m: Model, n: int, theta0, omega0, state0):
    """``(y0, theta0, omega0)`` of a batch: the initial state of each row (rows x states)
    and its planar shorthand (zeros for a model without one)."""
    if state0 is not None:
        if np.any(np.asarray(theta0, dtype=object) != 0) or np.any(
                np.asarray(omega0, dtype=object) != 0):
            raise ParameterError("give the initial state as state0 or as theta0/omega0, "
                                 "not both")
        arr = np.asarray(state0, dtype=object)
        rows_in = [arr] if arr.ndim <= 1 else list(arr)
        if len(rows_in) not in (1, n):
            raise ParameterError(f"state0 must be one state or one state per motion ({n}), "
                                 f"got {len(rows_in)}")
        y = np.array([m.check_state(r) for r in rows_in], dtype=np.float64)
        y0 = np.broadcast_to(y, (n, y.shape[1])).copy()
        sh = m.planar_shorthand()
        zeros = np.zeros(n)
        return (y0, y0[:, sh[0]].copy(), y0[:, sh[1]].copy()) if sh else (y0, zeros, zeros)
    th0 = _per_row("theta0", theta0, n, -HALF_PI, HALF_PI, "(-pi/2, pi/2) rad")
    om0 = _per_row("omega0", omega0, n)
    if (th0.any() or om0.any()) and m.planar_shorthand() is None:
        m.initial_state(1.0, 0.0)  # raises: the model has no planar angle
    if type(m).initial_state is Model.initial_state:
        y0 = np.column_stack((th0, om0)) if m.planar_shorthand() else np.zeros(
            (n, len(m.state_names)))
    else:
        made: dict = {}
        for a, b in zip(th0.tolist(), om0.tolist(), strict=True):
            if (a, b) not in made:
                made[a, b] = m.initial_state(a, b)
        y0 = np.array([made[a, b] for a, b in zip(th0.tolist(), om0.tolist(), strict=True)])
    return np.ascontiguousarray(y0, dtype=np.float64), th0, om0
