r"""What a rocking model is: the interface every model implements.

A model is one class, in one file, registered by one line in :mod:`rocking.models`
(``MODELS``). Everything else -- validation of the block, the motion, the window and the
initial state, packing motions for compiled code, output buffers, the memory guard, the
parallel batch and the result objects -- is shared code (:mod:`rocking.models.run`), written
once. This mirrors ``scipy.integrate.OdeSolver``: a documented base class, a registry of
implementations, one entry point (:func:`rocking.simulate`, :func:`rocking.simulate_many`)
and one result convention (:mod:`rocking.results`).

A subclass of :class:`Model` provides
-------------------------------------

``name`` : str
    The registry name (``model="housner"``).
``label`` : str
    A human-readable name for tables and plots.
``Options`` : a frozen dataclass deriving from :class:`ModelOptions`
    The model's options with documented defaults, units and ranges (declare each field
    with :func:`option`). They are validated at the edge, when the dataclass is built:
    bad values raise :class:`~rocking.errors.ParameterError` naming the option and the
    allowed range; unknown options are rejected too.
``kernel`` : a compiled (numba) function, the single-run kernel
    ``kernel(mp, kind, prm, samples, t_end, t_quiet, theta0, omega0, h_scan, dt_out,
    out_th, out_om, imp, extra) -> KernelResult(n_out, n_impacts, max_abs_theta,
    overturned, overturn_time, uplift_time, n_steps, status, lift_off_time, settled)``
    (:data:`KernelResult`, a named tuple that numba compiles).

    * ``mp`` is the model's own parameter tuple (:meth:`Model.kernel_params`);
    * ``(kind, prm, samples)`` is the motion spec (of the compiled motion kernels of
      :mod:`rocking.motions`; evaluate it with ``ground_acc`` and step onto
      ``next_breakpoint``), ``h_scan`` a time step that resolves it (s), ``t_end`` the
      simulated time (s);
    * ``t_quiet`` (s): from this time on the ground is still (the motion has ended), and
      the kernel stops as soon as the block is *settled*, at rest or overturned (``inf``:
      run to ``t_end`` whatever the state, as for an explicit ``duration``);
    * ``theta0``, ``omega0``: the initial state (rad, rad/s; both 0: at rest);
    * the kernel writes ``theta`` and ``omega`` at ``k * dt_out`` into ``out_th``,
      ``out_om`` (length 0: no history), impact times into ``imp`` up to its length
      (counting the impacts beyond it), and the model's extra outputs into the tuple
      ``extra`` (:meth:`Model.extra_buffers`);
    * it returns the number of samples written, the number of impacts (zero crossings of
      ``theta``), ``max |theta|`` (rad), whether the block overturned (``|theta|`` reached
      pi/2), the overturning and uplift times (s, NaN if none), the number of steps, a
      ``status`` (0: success; otherwise a code that :meth:`Model.failure` explains) and
      the lift-off time (s): when a vertical motion makes ``g + a_v <= 0`` and the model
      cannot represent flight, it stops there and returns that time (NaN otherwise);
      and ``settled``: whether the block was at rest or had overturned when the run
      ended (a model may also call a block settled whose outcome it has decided exactly,
      as the classical model does by energy, see :mod:`rocking.models.housner`).
      Times with no event are NaN, the one convention of the package.
    * a vertical component, if any, travels in ``prm`` and ``samples``
      (the motion kernels ``has_vertical`` and ``vertical_acc``); it is positive
      upwards and replaces ``g`` by ``g + a_v`` in the gravity terms.
``batch_kernel`` : a compiled parallel function over many motions
    ``batch_kernel(mp, extra0, rows, blocks)``: always the same two lines, a ``prange`` loop
    that calls the model's kernel on :func:`row_args` and stores the result with
    :func:`store_row`::

        @njit(cache=True, parallel=True)
        def batch_kernel(mp, extra0, rows, blocks):
            for i in prange(rows[0].shape[0]):
                store_row(i, kernel(with_block(mp, blocks[i]), *row_args(i, rows, extra0)),
                          rows)

    ``blocks[i]`` holds the block parameters of row ``i`` (:meth:`Model.block_row`) and
    ``with_block(mp, b)`` (compiled) returns ``mp`` with them: one batch may then hold a
    different block per row (Monte Carlo, campaigns). A model whose parameters cannot
    change per row uses :func:`same_block` and an empty :meth:`Model.block_row`; the
    driver then runs one batch per distinct block.

    Each model file keeps its own copy (rather than passing the kernel to a shared
    function) so that numba can cache it and invalidates that cache with the model's file.
:meth:`Model.kernel_params`
    Builds ``mp`` from the block and the validated options.

And optionally: ``accepts_stack`` (the model simulates :class:`~rocking.Stack` objects),
``response_class`` with :meth:`Model.extra_buffers` and :meth:`Model.extra_fields` for
outputs beyond ``theta`` and ``omega`` (the DEM's histories), :meth:`Model.info` and
:meth:`Model.failure`.

**Row outputs** (scalars beyond :data:`KernelResult`, one value per run, such as the
isolated base's largest displacement): declare them in ``row_outputs`` (a tuple of
:data:`RowOutput`). The kernel writes them, in that order, into ``extra[0]`` when its
length is ``len(row_outputs)`` (NaN: not reached); the default :meth:`Model.extra_buffers`
gives a single run that buffer and puts the values in ``Response.info``, and the batch
kernel passes each row its own row of the batch's ``row_out`` array with
:func:`row_args_out` instead of :func:`row_args`::

    @njit(cache=True, parallel=True)
    def batch_kernel(mp, extra0, rows, blocks):
        for i in prange(rows[0].shape[0]):
            store_row(i, kernel(with_block(mp, blocks[i]), *row_args_out(i, rows)), rows)

:func:`rocking.simulate_many` returns them in ``BatchResponse.outputs`` (by name; also
``res.<name>``), campaigns store them as columns and
:func:`rocking.testing.check_model` checks that each batch row equals its single run.

Sign convention (all models): Eq (1) of Peña et al. (2007): a positive ground acceleration
drives ``theta`` positive (see :mod:`rocking.models.housner`).
"""

from __future__ import annotations

import dataclasses
import math
from collections import namedtuple
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np
from numba import njit

from ..blocks import Block, Stack
from ..errors import ParameterError
from ..options import Options, option  # noqa: F401 (option: re-exported for the models)
from ..results import Response


# ================================================================================= options
@dataclass(frozen=True)
class ModelOptions(Options):
    """Base of the option dataclasses of the models (validated when built; declare each
    field with :func:`rocking.options.option`).

    Examples
    --------
    The isolated model's options take quantities with units and refuse unknown names:

    >>> import rocking
    >>> Options = rocking.MODELS["isolated"].Options
    >>> opts = Options(isolation_period="2.5s", clearance="15cm")
    >>> opts.isolation_period, opts.clearance
    (2.5, 0.15)
    >>> try:
    ...     Options.build("isolated", isolation_perod=2.5)
    ... except rocking.ParameterError as e:
    ...     print(e)
    unknown option(s) for model 'isolated': isolation_perod (allowed: clearance, ...)
    """

    @classmethod
    def build(cls, model_name: str, **values) -> ModelOptions:
        """The options from keyword values, refusing unknown names.

        Parameters
        ----------
        model_name : str
            The model's registry name, for the message.
        **values
            The options by name (quantities with units accepted: ``"2.5s"``, ``"15cm"``).

        Raises
        ------
        ParameterError
            An unknown name (listing the allowed ones), or a value out of its range.

        Examples
        --------
        The same options as the constructor's, with unknown names refused:

        >>> import rocking
        >>> Options = rocking.MODELS["isolated"].Options
        >>> Options.build("isolated", clearance="15cm") == Options(clearance=0.15)
        True
        >>> Options.build("isolated", clearence=0.15)
        Traceback (most recent call last):
        ...
        rocking.errors.ParameterError: unknown option(s) for model 'isolated': clearence ...
        """
        names = {f.name for f in dataclasses.fields(cls)}
        unknown = [k for k in values if k not in names]
        if unknown:
            allowed = ", ".join(sorted(names)) or "none"
            raise ParameterError(f"unknown option(s) for model {model_name!r}: "
                                 f"{', '.join(unknown)} (allowed: {allowed})")
        return cls(**values)


# =================================================================================== model
class Model:
    """Base class of the rocking models (see the module docstring for the contract).

    Examples
    --------
    Every registered model is a subclass; its class attributes describe it:

    >>> from rocking.models import MODELS, Model
    >>> Isolated = MODELS["isolated"]
    >>> issubclass(Isolated, Model), Isolated.mitigation, MODELS["housner"].mitigation
    (True, True, False)
    >>> [o.name for o in Isolated.row_outputs]
    ['max_base_displacement', 'max_plate_acceleration', 'clearance_exceeded', 'clearance_time']
    """

    name: ClassVar[str] = ""
    label: ClassVar[str] = ""
    Options: ClassVar[type[ModelOptions]] = ModelOptions
    kernel: ClassVar[Any] = None
    batch_kernel: ClassVar[Any] = None
    accepts_stack: ClassVar[bool] = False
    batch_initial_state: ClassVar[bool] = True
    """Batches may start each row from its own ``theta0``, ``omega0``."""
    slow: ClassVar[bool] = False
    """A simulation costs seconds, not milliseconds: reports run the model's large batches
    only on request (``rocking reproduce --full``)."""
    mitigation: ClassVar[bool] = False
    """The model adds a mitigation (anchors, an isolated base) to the free-standing block:
    the report's comparisons with the paper, whose specimens stood free, leave it out
    (:func:`rocking.report.core.report_models`)."""
    append_overturn: ClassVar[bool] = True
    """End the history of a single run on the exact overturning point (pi/2)."""
    response_class: ClassVar[type] = Response
    row_outputs: ClassVar[tuple] = ()
    """Scalar outputs per run beyond :data:`KernelResult` (:data:`RowOutput` entries; see
    the module docstring)."""

    def __init__(self, block, options: ModelOptions | None = None):
        self.block = self.check_block(block)
        self.options = options if options is not None else self.Options()

    @classmethod
    def from_kwargs(cls, block, **options) -> Model:
        """The model for ``block`` with options given as keywords (validated by
        :meth:`ModelOptions.build`): what :func:`rocking.simulate` builds from its
        ``**options``.

        Examples
        --------
        >>> import rocking
        >>> block = rocking.Block.rectangular(0.2, 1.0)
        >>> m = rocking.MODELS["isolated"].from_kwargs(block, isolation_period="2.5s")
        >>> m.block is block, m.options.isolation_period, m.options.isolation_damping
        (True, 2.5, 0.05)
        """
        return cls(block, cls.Options.build(cls.name, **options))

    @classmethod
    def check_block(cls, block):
        """``block`` if the model simulates it (a :class:`~rocking.Block`; a
        :class:`~rocking.Stack` too when :attr:`accepts_stack`), else ParameterError.

        Examples
        --------
        >>> import rocking
        >>> block = rocking.Block.rectangular(0.2, 1.0)
        >>> rocking.MODELS["housner"].check_block(block) is block
        True
        >>> rocking.MODELS["housner"].check_block("0.2 x 1.0")
        Traceback (most recent call last):
        ...
        rocking.errors.ParameterError: block must be a rocking.Block, got str
        """
        allowed = (Block, Stack) if cls.accepts_stack else (Block,)
        if isinstance(block, Stack) and not cls.accepts_stack:
            raise ParameterError(f"model {cls.name!r} simulates a single rocking.Block; "
                                 "stacks need model='dem'")
        if not isinstance(block, allowed):
            what = "rocking.Block or rocking.Stack" if cls.accepts_stack else "rocking.Block"
            raise ParameterError(f"block must be a {what}, got {type(block).__name__}")
        return block

    # ---- to be provided by subclasses
    def kernel_params(self, dt_out: float, theta0: float, omega0: float) -> tuple:
        """The parameter tuple ``mp`` handed to the kernels (for a run with output interval
        ``dt_out``, s, from ``theta0``, rad, and ``omega0``, rad/s); each model defines its
        own layout.

        Examples
        --------
        The classical model's tuple starts with the block's ``alpha``, ``p`` and ``mu``
        (Eqs 2-4):

        >>> import rocking
        >>> block = rocking.Block.rectangular(0.2, 1.0)
        >>> mp = rocking.MODELS["housner"](block).kernel_params(0.01, 0.0, 0.0)
        >>> mp[:3] == (block.alpha, block.p, block.mu)
        True
        """
        raise NotImplementedError

    # ---- optional hooks
    @classmethod
    def block_row(cls, block) -> tuple:
        """The block parameters a batch row may change (``with_block`` puts them into ``mp``);
        empty: one block per batch.

        Examples
        --------
        The anchored model's rows take ``(alpha, p, mu)``; the base class, none:

        >>> import rocking
        >>> from rocking.models import Model
        >>> block = rocking.Block.rectangular(0.2, 1.0)
        >>> rocking.MODELS["anchored"].block_row(block) == (block.alpha, block.p, block.mu)
        True
        >>> Model.block_row(block)
        ()
        """
        return ()

    @property
    def result_name(self) -> str:
        """The ``model`` field of the results."""
        return self.name

    def extra_buffers(self, n_out: int) -> tuple:
        """Extra output arrays of the kernel for ``n_out`` samples (default: the buffer of
        the :attr:`row_outputs`, if any).

        Examples
        --------
        One NaN per row output (NaN: not reached) for the isolated model, none for the
        classical one:

        >>> import rocking
        >>> block = rocking.Block.rectangular(0.2, 1.0)
        >>> rocking.MODELS["isolated"](block).extra_buffers(100)
        (array([nan, nan, nan, nan]),)
        >>> rocking.MODELS["housner"](block).extra_buffers(100)
        ()
        """
        return (np.full(len(self.row_outputs), np.nan),) if self.row_outputs else ()

    def extra_bytes(self, n_out: int) -> int:
        """Memory of :meth:`extra_buffers` for ``n_out`` samples (bytes).

        Examples
        --------
        It agrees with the buffers themselves (four float64 row outputs, 32 bytes):

        >>> import rocking
        >>> m = rocking.MODELS["isolated"](rocking.Block.rectangular(0.2, 1.0))
        >>> m.extra_bytes(100), sum(a.nbytes for a in m.extra_buffers(100))
        (32, 32)
        """
        return 8 * len(self.row_outputs)

    def extra_fields(self, n_out: int, extra: tuple, dt_out: float) -> dict:
        """Fields of :attr:`response_class` beyond those of :class:`Response` (an ``"info"``
        entry is merged into ``Response.info``), from ``n_out`` samples at ``dt_out`` (s).
        Default: the :attr:`row_outputs` in ``info``.

        Examples
        --------
        The isolated model's buffer becomes named values, the flag as a bool:

        >>> import rocking
        >>> m = rocking.MODELS["isolated"](rocking.Block.rectangular(0.2, 1.0))
        >>> buf = np.array([0.12, 3.5, 0.0, np.nan])
        >>> info = m.extra_fields(0, (buf,), 0.01)["info"]
        >>> info["max_base_displacement"], info["clearance_exceeded"], info["clearance_time"]
        (0.12, False, nan)
        """
        if not self.row_outputs:
            return {}
        return {"info": row_output_values(self.row_outputs, extra[0])}

    def check_batch(self) -> None:
        """Refuse options that a batch cannot honour (raise ParameterError); default: none.

        Examples
        --------
        The DEM's contact forces are histories of single runs only:

        >>> import rocking
        >>> block = rocking.Block.rectangular(0.2, 1.0)
        >>> rocking.MODELS["housner"](block).check_batch() is None
        True
        >>> dem = rocking.MODELS["dem"].from_kwargs(block, damping=1e-3, return_forces=True)
        >>> dem.check_batch()
        Traceback (most recent call last):
        ...
        rocking.errors.ParameterError: return_forces=True is for single runs ...
        """

    def info(self, dt_out: float | None = None) -> dict:
        """Options and derived settings recorded in ``Response.info`` (of a run at the
        output interval ``dt_out``, s, when given). No hook may change the model: the
        same model runs any number of times (:func:`rocking.testing.check_model`).

        Examples
        --------
        The default is the options' scalars:

        >>> import rocking
        >>> m = rocking.MODELS["housner"].from_kwargs(rocking.Block.rectangular(0.2, 1.0),
        ...                                           linear=True)
        >>> m.info()
        {'rtol': 1e-08, 'rest_tol': 1e-12, 'free_rest_tol': 0.001, 'linear': True}
        """
        return {k: v for k, v in self.options.to_dict().items()
                if isinstance(v, int | float | str | bool) or v is None}

    def failure(self, status: int, t: float, dt_out: float | None = None) -> str:
        """Message of a numerical failure with code ``status`` near time ``t`` (s), in a
        run at the output interval ``dt_out`` (s).

        Examples
        --------
        >>> import rocking
        >>> m = rocking.MODELS["housner"](rocking.Block.rectangular(0.2, 1.0))
        >>> m.failure(3, 1.23456)
        "model 'housner' failed (status 3) near t = 1.235 s"
        """
        return f"model {self.name!r} failed (status {status}) near t = {t:.4g} s"


# ============================================================================ row outputs
RowOutput = namedtuple("RowOutput", ["name", "unit", "flag", "help"])
"""A scalar output of each run (:attr:`Model.row_outputs`): its name (a result field and a
campaign column), its unit (SI, ``""`` if none), whether it is a flag (stored as 0/1 by
the kernel, returned as a bool) and a one-line description."""


def row_output_values(outputs: tuple, values) -> dict:
    """``{name: value}`` of the row outputs ``values`` (a kernel's buffer, or one row of a
    batch's ``row_out``): flags as bools (True where the value is 1), the rest as floats."""
    return {o.name: (bool(v == 1.0) if o.flag else float(v))
            for o, v in zip(outputs, values, strict=True)}


def row_output_arrays(outputs: tuple, row_out: np.ndarray) -> dict:
    """``{name: array}`` of a batch's ``row_out`` (rows x outputs): flags as bool arrays."""
    return {o.name: (row_out[:, j] == 1.0) if o.flag else row_out[:, j].copy()
            for j, o in enumerate(outputs)}


# ====================================================================== shared batch rows
KernelResult = namedtuple("KernelResult", [
    "n_out", "n_impacts", "max_abs_theta", "overturned", "overturn_time", "uplift_time",
    "n_steps", "status", "lift_off_time", "settled"])
KernelResult.__doc__ = """What a kernel returns (compiled by numba as a named tuple): the
number of history samples written, the impacts, ``max |theta|`` (rad), whether and when
(s) it overturned, the first uplift (s), the steps taken, the status (0: success), the
lift-off time (s) and whether the block had settled. A new output is one field here, one
array in :data:`Batch` and one line in :func:`store_row`.

Examples
--------
>>> from rocking.models import KernelResult
>>> KernelResult._fields[:4]
('n_out', 'n_impacts', 'max_abs_theta', 'overturned')
"""

BATCH_INPUTS = ("kinds", "prms", "samples", "nsamp", "t_ends", "t_quiets", "h_scans",
                "theta0", "omega0", "dt_out")
"""The inputs of a batch: the packed motions (:func:`rocking.models.run.pack_motions`),
each row's window and initial state, and the output interval."""
BATCH_OUTPUTS = ("theta", "omega", "max_abs_theta", "overturned", "overturn_time",
                 "uplift_time", "n_impacts", "n_steps", "status", "lift_off_time", "settled",
                 "row_out")
"""The outputs of a batch, one array per row (``theta``, ``omega``: the histories;
``row_out``: the model's :attr:`Model.row_outputs`, rows x outputs, NaN where not
written)."""
Batch = namedtuple("Batch", BATCH_INPUTS + BATCH_OUTPUTS)
Batch.__doc__ = """A batch as the compiled batch kernels see it: named arrays, one entry per
row (the inputs :data:`BATCH_INPUTS`, then the outputs :data:`BATCH_OUTPUTS`).

Examples
--------
>>> from rocking.models import Batch
>>> from rocking.models.base import BATCH_INPUTS
>>> Batch._fields[:len(BATCH_INPUTS)] == BATCH_INPUTS, Batch._fields[-1]
(True, 'row_out')
"""


@njit(cache=True)
def row_args(i, rows, extra0):
    """The kernel arguments (after ``mp``) of row ``i`` of the :data:`Batch` ``rows``.

    A model's ``batch_kernel`` calls it for each row (module docstring); called from
    Python it shows what a row hands the kernel.

    Examples
    --------
    A hand-built batch of one row (one-sine pulse, 1 s window, 100 output samples; the
    outputs are zero placeholders) with the inputs :func:`rocking.simulate_many` gives:

    >>> import numpy as np
    >>> from rocking.models import Batch, pack_motions, row_args
    >>> from rocking.motions import OneSine
    >>> kinds, prms, samples, nsamp, t_ends, h_scans, t_quiets = pack_motions(
    ...     [OneSine(2.0, 0.5)], duration=1.0)
    >>> f = [np.zeros(1) for _ in range(5)]
    >>> i, b = np.zeros((3, 1), np.int64), np.zeros((2, 1), bool)
    >>> rows = Batch(kinds, prms, samples, nsamp, t_ends, t_quiets, h_scans, f[0], f[0],
    ...              0.01, np.zeros((1, 100)), np.zeros((1, 100)), f[1], b[0], f[2],
    ...              f[3], i[0], i[1], i[2], f[4], b[1], np.zeros((1, 0)))
    >>> args = row_args(0, rows, ())
    >>> len(args), float(args[3]), args[9].shape  # 13 arguments; t_end; theta's history
    (13, 1.0, (100,))
    """
    return (rows.kinds[i], rows.prms[i], rows.samples[i, : rows.nsamp[i]], rows.t_ends[i],
            rows.t_quiets[i], rows.theta0[i], rows.omega0[i], rows.h_scans[i], rows.dt_out,
            rows.theta[i], rows.omega[i], np.empty(0), extra0)


@njit(cache=True)
def row_args_out(i, rows):
    """:func:`row_args` with ``extra = (rows.row_out[i],)``: the kernel writes row ``i``'s
    :attr:`Model.row_outputs` in place (models with row outputs)."""
    return (rows.kinds[i], rows.prms[i], rows.samples[i, : rows.nsamp[i]], rows.t_ends[i],
            rows.t_quiets[i], rows.theta0[i], rows.omega0[i], rows.h_scans[i], rows.dt_out,
            rows.theta[i], rows.omega[i], np.empty(0), (rows.row_out[i],))


@njit(cache=True)
def same_block(mp, b):
    """``with_block`` of a model whose batches take one block: ``mp`` unchanged.

    Examples
    --------
    >>> import numpy as np
    >>> from rocking.models import same_block
    >>> same_block((0.2, 2.0), np.zeros(3))  # the kernel parameters, whatever the block row
    (0.2, 2.0)
    """
    return mp


@njit(cache=True)
def store_row(i, res, rows):
    """Store the :data:`KernelResult` ``res`` of row ``i`` in the :data:`Batch` ``rows``;
    the history past the written samples is NaN.

    Examples
    --------
    A batch of one row, as in :func:`row_args`, and a result that wrote 40 of its 100
    output samples (a run that settled after 0.4 s):

    >>> import numpy as np
    >>> from rocking.models import Batch, pack_motions, KernelResult, store_row
    >>> from rocking.motions import OneSine
    >>> kinds, prms, samples, nsamp, t_ends, h_scans, t_quiets = pack_motions(
    ...     [OneSine(2.0, 0.5)], duration=1.0)
    >>> f = [np.zeros(1) for _ in range(5)]
    >>> i, b = np.zeros((3, 1), np.int64), np.zeros((2, 1), bool)
    >>> rows = Batch(kinds, prms, samples, nsamp, t_ends, t_quiets, h_scans, f[0], f[0],
    ...              0.01, np.zeros((1, 100)), np.zeros((1, 100)), f[1], b[0], f[2],
    ...              f[3], i[0], i[1], i[2], f[4], b[1], np.zeros((1, 0)))
    >>> res = KernelResult(n_out=40, n_impacts=3, max_abs_theta=0.05, overturned=False,
    ...                    overturn_time=np.nan, uplift_time=0.12, n_steps=400, status=0,
    ...                    lift_off_time=0.12, settled=True)
    >>> store_row(0, res, rows)
    >>> int(rows.n_impacts[0]), bool(rows.settled[0]), bool(np.isnan(rows.theta[0, 40:]).all())
    (3, True, True)
    """
    rows.theta[i, res.n_out:] = math.nan
    rows.omega[i, res.n_out:] = math.nan
    rows.max_abs_theta[i] = res.max_abs_theta
    rows.overturned[i] = res.overturned
    rows.overturn_time[i] = res.overturn_time
    rows.uplift_time[i] = res.uplift_time
    rows.n_impacts[i] = res.n_impacts
    rows.n_steps[i] = res.n_steps
    rows.status[i] = res.status
    rows.lift_off_time[i] = res.lift_off_time
    rows.settled[i] = res.settled
