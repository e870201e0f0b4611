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
``state_names`` (and ``state_units``)
    The state variables, in the order of the state vector: ``("theta", "omega")`` for
    the planar models (the default), the DEM its bodies' positions, rotations and
    velocities. A run starts from a state vector ``y0`` (``state0=`` of
    :func:`rocking.simulate`; the planar models keep ``theta0``/``omega0`` as their
    named shorthand, :meth:`Model.initial_state`); a single run returns the history as
    ``Response.states`` (samples x states), a batch as ``BatchResponse.states`` (runs x
    samples x states), as scipy's ``OdeSolver`` returns ``y``.
``outputs`` : a tuple of :data:`Output`
    The per-run outputs, declared once: :data:`GENERIC_OUTPUTS` (``n_out``, ``n_steps``,
    ``status``, ``settled``, ``overturned``, ``overturn_time``, ``uplift_time``,
    ``lift_off_time``), then the model's own (the planar models:
    :data:`PLANAR_OUTPUTS`, ``max_abs_theta`` and ``n_impacts``; the isolated base:
    ``max_base_displacement``, ...). From this declaration come the kernel's result
    record (:meth:`Model.result_dtype`), the batch arrays, the attributes of
    :class:`~rocking.results.BatchResponse`, ``summary()``, the campaign's columns and
    their units in the Parquet schema, and the docs: a new output is one line.
``kernel`` : a compiled (numba) function, the single-run kernel
    ``kernel(mp, kind, prm, samples, t_end, t_quiet, h_scan, y0, dt_out, hist, imp, res,
    extra)``, returning nothing:

    * ``mp`` is the model's own parameter tuple (:meth:`Model.kernel_params`; a named
      tuple: no index arithmetic);
    * ``(kind, prm, samples)`` is the motion spec (of the compiled motion kernels of
      :mod:`rocking.motions`; evaluate it with ``ground_acc`` and step onto
      ``next_breakpoint``), ``h_scan`` a time step that resolves it (s), ``t_end`` the
      simulated time (s);
    * ``t_quiet`` (s): from this time on the ground is still (the motion has ended), and
      the kernel stops as soon as the body is *settled*, at rest or overturned (``inf``:
      run to ``t_end`` whatever the state, as for an explicit ``duration``);
    * ``y0``: the initial state (:attr:`state_names`; all 0: at rest);
    * the kernel writes the state at ``k * dt_out`` into the rows of ``hist`` (samples x
      states; 0 rows: no history), impact times into ``imp`` up to its length (counting
      the impacts beyond it), and the model's extra single-run outputs into the tuple
      ``extra`` (:meth:`Model.extra_buffers`);
    * ``res`` is the run's result record (dtype :meth:`Model.result_dtype`, every field
      at its "not reached" value: NaN, 0 or False): the kernel sets its fields by name
      (``res.n_out = k``, ``res.overturned = True``, ...). ``status`` is 0 for success,
      otherwise a code that :meth:`Model.failure` explains; ``lift_off_time``: when a
      vertical motion makes ``g + a_v <= 0`` and the model cannot represent flight, it
      stops there; ``settled``: whether the body was at rest or had overturned when
      the run ended (a model may also call a body settled whose outcome it has decided
      exactly, as the classical model does by energy, see
      :mod:`rocking.models.housner`). Times with no event are NaN, the one convention
      of the package.
    * a vertical component, if any, travels in ``prm`` and ``samples``
      (the motion kernels ``has_vertical`` and ``vertical_acc``); it is positive
      upwards and replaces ``g`` by ``g + a_v`` in the gravity terms.
``batch_kernel`` : a compiled parallel function over many motions
    ``batch_kernel(mp, extra0, rows, blocks)``: always the same lines, a ``prange`` loop
    that calls the model's kernel on :func:`row_args` and finishes the row with
    :func:`store_row`::

        @njit(cache=True, parallel=True)
        def batch_kernel(mp, extra0, rows, blocks):
            for i in prange(rows.kinds.shape[0]):
                kernel(with_block(mp, blocks[i]), *row_args(i, rows), rows.res[i], extra0)
                store_row(i, rows)

    ``blocks[i]`` holds the block parameters of row ``i`` (:meth:`Model.block_row`) and
    ``with_block(mp, b)`` (compiled) returns ``mp`` with them: one batch may then hold a
    different block per row (Monte Carlo, campaigns). A model whose parameters cannot
    change per row uses :func:`same_block` and an empty :meth:`Model.block_row`; the
    driver then runs one batch per distinct block (and, without
    :attr:`Model.batch_initial_state`, per distinct initial state).

    Each model file keeps its own copy (rather than passing the kernel to a shared
    function) so that numba can cache it and invalidates that cache with the model's file.
:meth:`Model.kernel_params`
    Builds ``mp`` from the block and the validated options.

And optionally: ``accepts_stack`` (the model simulates :class:`~rocking.Stack` objects),
``tags`` (what :func:`rocking.testing.check_model` checks: mirror symmetry of planar
models, rotation equivariance of 3-D ones), ``response_class`` with
:meth:`Model.extra_buffers` and :meth:`Model.extra_fields` for single-run outputs beyond
the states (the DEM's energies and contact forces), :meth:`Model.info` and
:meth:`Model.failure`.

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


# ================================================================================ outputs
Output = namedtuple("Output", ["name", "unit", "flag", "help", "integer"], defaults=(False,))
Output.__doc__ = """A per-run output of a model (:attr:`Model.outputs`): its name (a result
field, a batch array and a campaign column), its SI unit (``""`` if none), whether it is a
flag (a bool), a one-line meaning, and whether it is an integer count (int64; otherwise
float64, NaN where not reached). The kernel writes it as a field of its result record.

Examples
--------
>>> from rocking.models.base import Output, PLANAR_OUTPUTS
>>> Output("max_slide", "m", False, "largest slide").integer
False
>>> [o.name for o in PLANAR_OUTPUTS]
['max_abs_theta', 'n_impacts']
"""

RowOutput = Output
"""The former name of :data:`Output` (the outputs a model adds to the shared ones)."""

GENERIC_OUTPUTS = (
    Output("n_out", "", False, "history samples written", True),
    Output("n_steps", "", False, "time steps taken", True),
    Output("status", "", False, "0: success; else the model's failure code "
                                "(Model.failure explains it)", True),
    Output("settled", "", True, "at rest or overturned when the run ended"),
    Output("overturned", "", True, "the body overturned"),
    Output("overturn_time", "s", False, "when it overturned (NaN: never)"),
    Output("uplift_time", "s", False, "when it first left its rest position (NaN: never)"),
    Output("lift_off_time", "s", False, "when the body first left the ground entirely (a "
                                        "planar model, which cannot represent flight, stops "
                                        "there: g + a_v <= 0; NaN: never)"),
)
"""The outputs every model has (:attr:`Model.outputs` starts with them)."""

PLANAR_OUTPUTS = (
    Output("max_abs_theta", "rad", False, "largest |theta| (pi/2 if it overturned)"),
    Output("n_impacts", "", False, "impacts: passages of theta through 0", True),
)
"""The outputs of the planar rocking models, after :data:`GENERIC_OUTPUTS`."""

SHARED_OUTPUTS = frozenset(o.name for o in GENERIC_OUTPUTS + PLANAR_OUTPUTS)
"""Names of the shared outputs; a model's others are its :attr:`Model.row_outputs`."""


def output_dtype(outputs: tuple) -> np.dtype:
    """The structured dtype of a result record with ``outputs`` (flags bool, counts
    int64, the rest float64).

    Examples
    --------
    >>> from rocking.models.base import output_dtype, GENERIC_OUTPUTS
    >>> dt = output_dtype(GENERIC_OUTPUTS)
    >>> dt["n_out"], dt["settled"], dt["overturn_time"]
    (dtype('int64'), dtype('bool'), dtype('float64'))
    """
    return np.dtype([(o.name, np.bool_ if o.flag else np.int64 if o.integer else np.float64)
                     for o in outputs])


def empty_results(outputs: tuple, n: int) -> np.ndarray:
    """``n`` result records, each field at its "not reached" value: NaN (floats), 0
    (counts), False (flags).

    Examples
    --------
    >>> from rocking.models.base import empty_results, GENERIC_OUTPUTS
    >>> r = empty_results(GENERIC_OUTPUTS, 2)
    >>> r["overturn_time"], r["settled"], r["n_steps"]
    (array([nan, nan]), array([False, False]), array([0, 0]))
    """
    res = np.zeros(n, output_dtype(outputs))
    for o in outputs:
        if not (o.flag or o.integer):
            res[o.name] = np.nan
    return res


def result_values(outputs: tuple, rec) -> dict:
    """``{name: value}`` of one result record: flags as bools, counts as ints, the rest
    as floats.

    Examples
    --------
    >>> from rocking.models.base import empty_results, result_values, GENERIC_OUTPUTS
    >>> result_values(GENERIC_OUTPUTS, empty_results(GENERIC_OUTPUTS, 1)[0])["settled"]
    False
    """
    return {o.name: (bool(rec[o.name]) if o.flag else int(rec[o.name]) if o.integer
                     else float(rec[o.name])) for o in outputs}


def result_arrays(outputs: tuple, res: np.ndarray) -> dict:
    """``{name: array}`` of a batch's result records (copies: plain numpy arrays).

    Examples
    --------
    >>> from rocking.models.base import empty_results, result_arrays, GENERIC_OUTPUTS
    >>> result_arrays(GENERIC_OUTPUTS, empty_results(GENERIC_OUTPUTS, 3))["status"]
    array([0, 0, 0])
    """
    return {o.name: np.ascontiguousarray(res[o.name]) for o in outputs}


def row_output_values(outputs: tuple, values) -> dict:
    """``{name: value}`` of row outputs given as a float buffer (flags: 1.0 is True).

    Examples
    --------
    >>> from rocking.models.base import Output, row_output_values
    >>> row_output_values((Output("hit", "", True, "x"),), [1.0])
    {'hit': True}
    """
    return {o.name: (bool(v == 1.0) if o.flag else float(v))
            for o, v in zip(outputs, values, strict=True)}


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
    """Batches may start each row from its own initial state (a model whose parameters
    depend on it, like the DEM's contact forces, gets one batch per distinct state)."""
    state_names: ClassVar[tuple] = ("theta", "omega")
    """The names of the state variables, in the order of the state vector (``y0``, the
    columns of ``Response.states``); units in :attr:`state_units`."""
    state_units: ClassVar[tuple] = ("rad", "rad/s")
    outputs: ClassVar[tuple] = GENERIC_OUTPUTS + PLANAR_OUTPUTS
    """The per-run outputs (:data:`Output`), declared once: :data:`GENERIC_OUTPUTS`, then
    the model's own. The kernel's result record, the batch arrays, the attributes of
    :class:`~rocking.results.BatchResponse`, ``summary()``, the campaign columns (and
    their units in the Parquet schema) and the docs all come from it."""
    tags: ClassVar[dict] = {"planar": True, "symmetry": "mirror"}
    """What :func:`rocking.testing.check_model` may assume (as scikit-learn's estimator
    tags): ``planar`` (the state starts with ``theta``, ``omega``; a run has
    ``Response.theta``) and ``symmetry``: ``"mirror"`` (the mirrored motion or initial
    state gives the mirrored response), ``"rotation"`` (3-D: rotating body and motion
    together changes nothing) or ``None``."""
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
    """The model's own outputs, beyond the shared ones (derived from :attr:`outputs`)."""

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        cls.row_outputs = tuple(o for o in cls.outputs if o.name not in SHARED_OUTPUTS)
        cls._dtype = output_dtype(cls.outputs)

    @classmethod
    def result_dtype(cls) -> np.dtype:
        """The structured dtype of the kernel's result record (one field per output).

        Examples
        --------
        >>> import rocking
        >>> rocking.MODELS["isolated"].result_dtype().names[-2:]
        ('clearance_exceeded', 'clearance_time')
        """
        return cls._dtype

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

    def kernels(self) -> tuple:
        """The compiled ``(kernel, batch_kernel)`` that :func:`rocking.simulate` and
        :func:`rocking.simulate_many` call for these options: the class's by default; a
        model whose option selects other compiled code (the classical model's
        ``method="taylor"``) returns that pair, so that the default never compiles it.

        Examples
        --------
        >>> import rocking
        >>> from rocking.models import housner
        >>> block = rocking.Block.rectangular(0.2, 1.0)
        >>> rocking.MODELS["housner"].from_kwargs(block).kernels()[1] is housner.batch_kernel
        True
        >>> m = rocking.MODELS["housner"].from_kwargs(block, method="taylor")
        >>> m.kernels() == (housner.kernel_taylor, housner.batch_kernel_taylor)
        True
        """
        cls = type(self)
        return cls.kernel, cls.batch_kernel

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

    def initial_state(self, theta0: float = 0.0, omega0: float = 0.0) -> np.ndarray:
        """The state vector ``y0`` (:attr:`state_names`) of a run released from
        ``theta0`` (rad) with ``omega0`` (rad/s): the planar shorthand; a model whose
        state is not planar maps it to its own (the DEM: its bodies rotated about the
        pivot).

        Examples
        --------
        >>> import rocking
        >>> m = rocking.MODELS["housner"](rocking.Block.rectangular(0.2, 1.0))
        >>> m.initial_state(0.1, -0.5)
        array([ 0.1, -0.5])
        """
        if not self.tags.get("planar"):
            if theta0 or omega0:
                raise ParameterError(f"model {self.name!r} has no planar angle: give its "
                                     f"initial state as state0 ({', '.join(self.state_names)})")
            return np.zeros(len(self.state_names))
        return np.array([theta0, omega0], dtype=np.float64)

    def check_state(self, y0) -> np.ndarray:
        """``y0`` as a float array of the model's state, checked (ParameterError naming
        ``state0``); the planar models require ``|theta| < pi/2``.

        Examples
        --------
        >>> import rocking
        >>> m = rocking.MODELS["housner"](rocking.Block.rectangular(0.2, 1.0))
        >>> m.check_state([0.1, 0.0])
        array([0.1, 0. ])
        >>> m.check_state([2.0, 0.0])
        Traceback (most recent call last):
        ...
        rocking.errors.ParameterError: state0: theta must be in (-pi/2, pi/2) rad, got 2
        """
        names = self.state_names
        try:
            y = np.array(y0, dtype=np.float64).reshape(-1)
        except (TypeError, ValueError):
            raise ParameterError(f"state0 must be {len(names)} numbers "
                                 f"({', '.join(names)}), got {y0!r}") from None
        if y.size != len(names):
            raise ParameterError(f"state0 must have {len(names)} values ({', '.join(names)}) "
                                 f"for model {self.name!r}, got {y.size}")
        if not np.all(np.isfinite(y)):
            raise ParameterError(f"state0 must be finite, got {y.tolist()}")
        if self.tags.get("planar") and not abs(y[0]) < 0.5 * math.pi:
            raise ParameterError(f"state0: theta must be in (-pi/2, pi/2) rad, got {y[0]:g}")
        return y

    def planar_shorthand(self) -> tuple[int, int] | None:
        """The columns of ``theta`` and ``omega`` in the state (``Response.theta``,
        ``omega``), or None for a model whose state has no planar angle.

        Examples
        --------
        >>> import rocking
        >>> rocking.MODELS["housner"](rocking.Block.rectangular(0.2, 1.0)).planar_shorthand()
        (0, 1)
        """
        return (0, 1) if self.tags.get("planar") else None

    # ---- optional hooks
    @classmethod
    def block_row(cls, block) -> tuple:
        """The block parameters a batch row may change (``with_block`` puts them into ``mp``);
        empty: one block per batch.

        Examples
        --------
        The anchored model's rows take both sides' ``(alpha, p, mu)``; the base class,
        none:

        >>> import rocking
        >>> from rocking.models import Model
        >>> block = rocking.Block.rectangular(0.2, 1.0)
        >>> rocking.MODELS["anchored"].block_row(block) == (block.alpha, block.p, block.mu) * 2
        True
        >>> Model.block_row(block)
        ()
        """
        return ()

    def motion_spec(self, motion) -> tuple:
        """The spec ``(kind, prm, samples)`` of ``motion`` that the kernel reads: the planar
        spec ``motion.spec()`` (default); a 3-D model returns ``motion.spec3(...)``
        (:func:`~rocking.motions._kernel.ground_acc3` reads it).

        Examples
        --------
        >>> import rocking
        >>> from rocking.motions import OneSine
        >>> m = rocking.MODELS["housner"](rocking.Block.rectangular(0.2, 1.0))
        >>> pulse = OneSine(2.0, 0.5)
        >>> all(np.array_equal(a, b) for a, b in zip(m.motion_spec(pulse), pulse.spec()))
        True
        >>> len(rocking.MODELS["rigid3d"](m.block).motion_spec(pulse)[1]) > len(pulse.spec()[1])
        True
        """
        if not hasattr(motion, "spec"):  # a HorizontalPair: two components
            raise ParameterError(f"model {self.name!r} is planar: give it a pair's motion "
                                 "on a plane, pair.on_plane(phi, heading)")
        return motion.spec()

    @property
    def result_name(self) -> str:
        """The ``model`` field of the results."""
        return self.name

    def extra_buffers(self, n_out: int) -> tuple:
        """Extra output arrays of the kernel of a single run with ``n_out`` samples (the
        DEM's energies and contact forces); default none.

        Examples
        --------
        >>> import rocking
        >>> rocking.MODELS["housner"](rocking.Block.rectangular(0.2, 1.0)).extra_buffers(100)
        ()
        """
        return ()

    def extra_bytes(self, n_out: int) -> int:
        """Memory of :meth:`extra_buffers` for ``n_out`` samples (bytes).

        Examples
        --------
        >>> import rocking
        >>> rocking.MODELS["housner"](rocking.Block.rectangular(0.2, 1.0)).extra_bytes(100)
        0
        """
        return 0

    def extra_fields(self, n_out: int, states: np.ndarray, extra: tuple, dt_out: float) -> dict:
        """Fields of :attr:`response_class` beyond those of :class:`Response` (an ``"info"``
        entry is merged into ``Response.info``), from the ``n_out`` samples of the state
        history ``states`` at ``dt_out`` (s) and the :meth:`extra_buffers`; default none.

        Examples
        --------
        >>> import numpy as np
        >>> import rocking
        >>> m = rocking.MODELS["housner"](rocking.Block.rectangular(0.2, 1.0))
        >>> m.extra_fields(0, np.empty((0, 2)), (), 0.01)
        {}
        """
        return {}

    def result_info(self, values: dict) -> dict:
        """What a single run adds to ``Response.info`` from its outputs ``values`` (by
        name): default, the model's own outputs (:attr:`row_outputs`).

        Examples
        --------
        >>> import rocking
        >>> m = rocking.MODELS["isolated"](rocking.Block.rectangular(0.2, 1.0))
        >>> values = {o.name: 0.0 for o in m.outputs}
        >>> list(m.result_info(values))[:2]
        ['max_base_displacement', 'max_plate_acceleration']
        """
        return {o.name: values[o.name] for o in self.row_outputs}

    def check_results(self, out: dict) -> None:
        """Look at a batch's outputs (``{name: array}``) after the run, to warn or flag
        what a model knows to be unverified; default: nothing.

        Examples
        --------
        >>> import rocking
        >>> m = rocking.MODELS["housner"](rocking.Block.rectangular(0.2, 1.0))
        >>> m.check_results({}) is None
        True
        """

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
        {'rtol': 1e-08, 'rest_tol': 1e-12, 'free_rest_tol': 0.001, 'linear': True,
         'method': 'dopri'}
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


# ====================================================================== shared batch rows
BATCH_INPUTS = ("kinds", "prms", "samples", "nsamp", "t_ends", "t_quiets", "h_scans", "y0",
                "dt_out")
"""The inputs of a batch: the packed motions (:class:`rocking.models.run.PackedMotions`),
each row's window and initial state (rows x states), and the output interval."""
BATCH_OUTPUTS = ("states", "res")
"""The outputs of a batch: the state histories (rows x samples x states; NaN past the
samples a run wrote) and the result records (:meth:`Model.result_dtype`, one per row)."""
Batch = namedtuple("Batch", BATCH_INPUTS + BATCH_OUTPUTS)
Batch.__doc__ = """A batch as the compiled batch kernels see it: named arrays, one entry per
row (the inputs :data:`BATCH_INPUTS`, then the outputs :data:`BATCH_OUTPUTS`).

Examples
--------
>>> from rocking.models import Batch
>>> from rocking.models.base import BATCH_INPUTS
>>> Batch._fields[:len(BATCH_INPUTS)] == BATCH_INPUTS, Batch._fields[-2:]
(True, ('states', 'res'))
"""


@njit(cache=True)
def row_args(i, rows):
    """The kernel arguments of row ``i`` of the :data:`Batch` ``rows`` between ``mp`` and
    the result record (``rows.res[i]``, which a compiled function cannot return).

    A model's ``batch_kernel`` calls it for each row (module docstring); called from
    Python it shows what a row hands the kernel.

    Examples
    --------
    A batch of one row (one-sine pulse, 1 s window, 100 output samples of the two states
    of the classical model), as :func:`rocking.simulate_many` builds it:

    >>> import numpy as np
    >>> import rocking
    >>> from rocking.models import Batch, pack_motions, row_args
    >>> from rocking.models.base import empty_results
    >>> from rocking.motions import OneSine
    >>> pm = pack_motions([OneSine(2.0, 0.5)], duration=1.0)
    >>> res = empty_results(rocking.MODELS["housner"].outputs, 1)
    >>> rows = Batch(*pm[:4], pm.t_ends, pm.t_quiets, pm.h_scans, np.zeros((1, 2)), 0.01,
    ...              np.zeros((1, 100, 2)), res)
    >>> args = row_args(0, rows)
    >>> len(args), float(args[3]), args[8].shape  # 10 arguments; t_end; the history
    (10, 1.0, (100, 2))
    """
    return (rows.kinds[i], rows.prms[i], rows.samples[i, : rows.nsamp[i]], rows.t_ends[i],
            rows.t_quiets[i], rows.h_scans[i], rows.y0[i], rows.dt_out, rows.states[i],
            np.empty(0))


@njit(inline="always")
def same_block(mp, b):
    """``with_block`` of a model whose batches take one block: ``mp`` unchanged (inlined
    and not cached: a model outside the package passes its own parameter type, which a
    cache of this file must not record).

    Examples
    --------
    >>> import numpy as np
    >>> from rocking.models import same_block
    >>> same_block((0.2, 2.0), np.zeros(3))  # the kernel parameters, whatever the block row
    (0.2, 2.0)
    """
    return mp


@njit(cache=True)
def store_row(i, rows):
    """Finish row ``i`` of the :data:`Batch` ``rows`` after its kernel ran: the history
    past the samples it wrote (``res.n_out``) is NaN.

    Examples
    --------
    A batch of one row, as in :func:`row_args`, whose run wrote 40 of its 100 samples:

    >>> import numpy as np
    >>> import rocking
    >>> from rocking.models import Batch, pack_motions, store_row
    >>> from rocking.models.base import empty_results
    >>> from rocking.motions import OneSine
    >>> pm = pack_motions([OneSine(2.0, 0.5)], duration=1.0)
    >>> res = empty_results(rocking.MODELS["housner"].outputs, 1)
    >>> rows = Batch(*pm[:4], pm.t_ends, pm.t_quiets, pm.h_scans, np.zeros((1, 2)), 0.01,
    ...              np.zeros((1, 100, 2)), res)
    >>> rows.res[0]["n_out"] = 40
    >>> store_row(0, rows)
    >>> bool(np.isnan(rows.states[0, 40:]).all()), bool((rows.states[0, :40] == 0).all())
    (True, True)
    """
    rows.states[i, rows.res[i].n_out:, :] = math.nan


@njit(cache=True, inline="always")
def set_planar_result(res, n_out, n_impacts, max_abs_theta, overturned, overturn_time,
                      uplift_time, n_steps, status, lift_off_time, settled):
    """Write the shared outputs of a planar model (:data:`GENERIC_OUTPUTS`,
    :data:`PLANAR_OUTPUTS`) into its result record ``res`` (inlined into each kernel:
    each model's record is a type of its own).

    Examples
    --------
    >>> import math
    >>> import rocking
    >>> from rocking.models.base import empty_results, set_planar_result
    >>> res = empty_results(rocking.MODELS["housner"].outputs, 1)
    >>> set_planar_result(res[0], 40, 3, 0.05, False, math.nan, 0.12, 400, 0, math.nan, True)
    >>> int(res["n_impacts"][0]), bool(res["settled"][0]), float(res["max_abs_theta"][0])
    (3, True, 0.05)
    """
    res.n_out = n_out
    res.n_impacts = n_impacts
    res.max_abs_theta = max_abs_theta
    res.overturned = overturned
    res.overturn_time = overturn_time
    res.uplift_time = uplift_time
    res.n_steps = n_steps
    res.status = status
    res.lift_off_time = lift_off_time
    res.settled = settled
