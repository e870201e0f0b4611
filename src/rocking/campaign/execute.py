"""Running a campaign into its store: the local executor and Dask.

* ``local`` (default): this process, one chunk after another, each chunk one compiled
  batch spread over every core by numba (``prange``); meanwhile one helper thread builds
  the next chunk's inputs and another assembles and writes the previous chunk
  (:func:`_run_local`), so that the cores rarely wait for the serial work.
* ``dask``: chunks as tasks on a ``dask.distributed`` cluster, an existing one
  (``scheduler="tcp://host:port"``) or a ``LocalCluster`` of ``dask_local`` worker
  processes. At most ``window`` chunks are in flight (``as_completed``, refilled as chunks
  finish): submitting every chunk at once stalls the scheduler for large campaigns
  (dask/distributed#2181). Results come back to this process, which writes the store, so
  the workers need no shared file system (but ``files`` records must be readable by them).

numba and Dask (see also the README):

* threads: a ``LocalCluster`` gets process workers with one Dask thread each. On every
  worker (of a ``LocalCluster`` or an existing cluster) each chunk runs with
  ``numba.set_num_threads(cores on its host // workers on its host)``, bounded by the
  worker's ``NUMBA_NUM_THREADS`` (the nanny sets neither; ``set_num_threads`` is
  thread-local, so it is called in the thread that runs the chunk). The
  ``LocalCluster`` also passes ``NUMBA_NUM_THREADS`` to its workers' environment (the
  nanny's ``env``; ``distributed.nanny.pre-spawn-environ`` would leak it into this
  process, where numba then refuses to compile: "Cannot set NUMBA_NUM_THREADS to a
  different value once the threads have been launched").
* a worker with several Dask threads runs one chunk at a time (a lock): numba's default
  ``workqueue`` threading layer aborts when two threads launch ``prange`` kernels at once.
* compilation: every worker loads (or compiles) the kernels of the campaign's models once,
  before any chunk is mapped.
* ``NUMBA_CACHE_DIR``: keep it on a disk local to each node (e.g. ``$TMPDIR``) on a
  cluster whose home directory is shared; numba's default is the package's
  ``__pycache__``.
"""

from __future__ import annotations

import os
import threading
import time
from collections.abc import Callable

import numpy as np

from ..errors import ParameterError
from .plan import Campaign
from .spec import CampaignSpec, read_spec
from .store import Store

#: The executors of :func:`run`: this process (numba threads), or a Dask cluster.
EXECUTORS = ("local", "dask")


def _cores() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not Linux
        return os.cpu_count() or 1


# ------------------------------------------------------------------------- on a worker
_CAMPAIGNS: dict[str, Campaign] = {}
_KERNEL_LOCK = threading.Lock()
_THREADS: int | None = None  # numba threads of this worker's chunks (setup_worker)


def _campaign(spec: CampaignSpec) -> Campaign:
    c = _CAMPAIGNS.get(spec.hash)
    if c is None:
        _CAMPAIGNS.clear()
        c = _CAMPAIGNS[spec.hash] = Campaign(spec)
    return c


def chunk_task(spec: CampaignSpec, k: int):
    """Run chunk ``k`` of ``spec`` (in a Dask worker): ``(k, table)``."""
    with _KERNEL_LOCK:
        if _THREADS is not None:  # thread-local in numba: set in the thread that runs
            import numba
            numba.set_num_threads(min(_THREADS, numba.config.NUMBA_NUM_THREADS))
        return k, _campaign(spec).run_chunk(k)


def warm_up(spec: CampaignSpec) -> None:
    """Load (or compile) the kernels of the models the spec runs: one short run each (with
    the options of its first run, :attr:`CampaignSpec.runs`)."""
    from ..models import simulate_many
    from ..motions import Sine
    first = {}
    for name, options in spec.runs:
        first.setdefault(name, options)
    for name, options in first.items():
        simulate_many(spec.blocks[0], [Sine.from_acceleration(2.0, 0.1, 0.05)], model=name,
                      **options)


def setup_worker(spec: CampaignSpec, per_host: dict | None = None, dask_worker=None) -> dict:
    """Choose numba's threads for this worker's chunks (cores on its host / workers on its
    host, at most its ``NUMBA_NUM_THREADS``) and warm up the kernels. Called on every
    worker with ``Client.run``."""
    global _THREADS
    import numba
    if per_host is not None and dask_worker is not None:
        host = dask_worker.address.rsplit(":", 1)[0]
        share = max(1, _cores() // max(1, per_host.get(host, 1)))
        _THREADS = min(share, numba.config.NUMBA_NUM_THREADS)
    with _KERNEL_LOCK:
        if _THREADS is not None:
            numba.set_num_threads(_THREADS)
        warm_up(spec)
    return {"pid": os.getpid(), "numba_threads": _THREADS or numba.get_num_threads(),
            "threading_layer": numba.config.THREADING_LAYER,
            "cache_dir": numba.config.CACHE_DIR or "(next to the package)"}


# ------------------------------------------------------------------------- executors
class ChunkWriter:
    """One background thread that writes finished chunks into the store
    (:meth:`.store.Store.write_chunk`, in the order given, then ``on_chunk(k, rows)``)
    while the caller computes the next chunk: the writes overlap the computation (the
    compiled batches release the GIL, and so do Parquet and the file system). With
    ``finish``, what :meth:`put` is given is ``finish(item)``'s raw material, made into
    the chunk's table in the writer's thread (the local executor: the raw results of
    :meth:`.plan.Campaign.simulate`, assembled by :meth:`.plan.Campaign.assemble`).

    At most ``depth`` chunks wait for the writer (:meth:`put` blocks beyond: memory stays
    a few chunks). A failure in the writer (a full disk, ...) is raised in the caller by
    the next :meth:`put` or by :meth:`close` (the chunks queued after it are dropped, not
    written: they are recomputed by the next run). :meth:`close` waits for every chunk
    put before it to be written, so that an interrupted run (Ctrl-C in the computation)
    keeps every chunk computed so far; each write is the store's own (file and record
    atomic, :mod:`.store`), so a kill at any instant leaves what a kill of the serial
    loop would.

    Examples
    --------
    >>> from rocking.campaign import EXAMPLE_SPEC, Campaign, Store, parse_spec
    >>> from rocking.campaign.execute import ChunkWriter
    >>> spec = parse_spec(EXAMPLE_SPEC)
    >>> store = Store("pulses_store").prepare()
    >>> store.lock()
    >>> _ = store.open_for(spec)
    >>> with ChunkWriter(store) as writer:
    ...     for k in range(spec.n_chunks):
    ...         writer.put(k, Campaign(spec).run_chunk(k))
    >>> store.unlock()
    >>> sorted(store.done())
    [0, 1]
    """

    def __init__(self, store: Store, on_chunk: Callable | None = None, depth: int = 1,
                 finish: Callable | None = None):
        import queue
        self.store, self.on_chunk, self.finish = store, on_chunk, finish
        self._queue: queue.Queue = queue.Queue(maxsize=max(1, depth))
        self._error: BaseException | None = None  # raised once in the caller
        self._failed = False  # for good: nothing more is written
        self._closed = False
        self._thread = threading.Thread(target=self._loop, name="rocking-chunk-writer",
                                        daemon=True)
        self._thread.start()

    def _loop(self) -> None:
        while True:
            item = self._queue.get()
            if item is None:
                return
            if self._failed:
                continue  # after a failure: drop the rest (recomputed by the next run)
            k, table = item
            try:
                if self.finish is not None:
                    table = self.finish(table)
                self.store.write_chunk(k, table)
                if self.on_chunk is not None:
                    self.on_chunk(k, len(table))
            except BaseException as e:  # raised in the caller (put, close)
                self._error, self._failed = e, True

    def _raise(self) -> None:
        if self._error is not None:
            err, self._error = self._error, None
            raise err

    def put(self, k: int, table) -> None:
        """Queue chunk ``k`` (its table) for writing; raises the writer's failure, if
        any, instead."""
        self._raise()
        if self._closed:
            raise RuntimeError("the chunk writer is closed")
        self._queue.put((k, table))

    def close(self) -> None:
        """Wait for every queued chunk to be written, stop the thread, and raise the
        writer's failure, if any."""
        if not self._closed:
            self._closed = True
            self._queue.put(None)
            self._thread.join()
        self._raise()

    def __enter__(self) -> ChunkWriter:
        return self

    def __exit__(self, *exc) -> None:
        if exc[0] is None:
            self.close()
            return
        try:  # the caller failed (or was interrupted): keep what was computed
            self.close()
        except Exception:  # the caller's exception is the one to see
            pass


def threadsafe_layer() -> bool:
    """Whether numba's threading layer lets two threads run parallel kernels at once
    (``tbb``, ``omp``; not ``workqueue``, which aborts). False until a parallel kernel has
    run in this process (the layer is chosen then)."""
    import numba
    try:
        return numba.threading_layer() in ("tbb", "omp")
    except ValueError:  # no parallel kernel yet
        return False


class PlanAhead:
    """One helper thread that builds the inputs of the next chunk
    (:meth:`.plan.Campaign.inputs`: its records, draws, scaled motions and blocks) while
    the caller runs the batches of the current one. The records' generator has parallel
    kernels of its own, so the inputs are built ahead only where numba's threading layer
    is thread-safe (:func:`threadsafe_layer`), else by :meth:`take`, in the caller's
    thread, as before. The inputs are a function of the spec and the chunk only: the
    same wherever they are built.

    Examples
    --------
    >>> from rocking.campaign import EXAMPLE_SPEC, Campaign, parse_spec
    >>> from rocking.campaign.execute import PlanAhead
    >>> c = Campaign(parse_spec(EXAMPLE_SPEC))
    >>> with PlanAhead(c) as ahead:
    ...     ahead.start(1)
    ...     ids, (table, blocks, motions) = ahead.take(1)
    >>> ids.tolist(), table.sim_id.tolist(), len(motions)
    ([2, 3], [2, 3], 2)
    """

    def __init__(self, campaign: Campaign):
        self.campaign = campaign
        self._pool = None
        self._next = None  # (chunk, future)
        self._kept = None  # (chunk, (ids, inputs)) built before: see keep

    def keep(self, k: int, built) -> None:
        """Keep ``(ids, inputs)`` of chunk ``k``, built already (the first chunk's, by the
        check before a new store is made): :meth:`take` hands them out once."""
        self._kept = (k, built)

    def _build(self, k: int, threads: int | None = None):
        if threads is not None:  # numba's threads are per thread: the caller's
            import numba
            numba.set_num_threads(threads)
        ids = np.arange(*self.campaign.chunk_range(k))
        return ids, self.campaign.inputs(ids)

    def start(self, k: int) -> None:
        """Start building the inputs of chunk ``k`` in the helper thread (where the
        threading layer allows it; else :meth:`take` builds them)."""
        if not threadsafe_layer():
            return
        import numba
        if self._pool is None:
            from concurrent.futures import ThreadPoolExecutor
            self._pool = ThreadPoolExecutor(1, thread_name_prefix="rocking-plan-ahead")
        self._next = (k, self._pool.submit(self._build, k, numba.get_num_threads()))

    def take(self, k: int):
        """``(ids, inputs)`` of chunk ``k``: those built ahead (their error, if any, is
        raised here), or built now."""
        kept, self._kept = self._kept, None
        if kept is not None and kept[0] == k:
            return kept[1]
        nxt, self._next = self._next, None
        if nxt is not None and nxt[0] == k:
            return nxt[1].result()
        if nxt is not None:
            nxt[1].cancel()
        return self._build(k)

    def close(self) -> None:
        """Stop the helper thread (after the build in progress, if any)."""
        if self._pool is not None:
            self._pool.shutdown(wait=True, cancel_futures=True)
            self._pool = None

    def __enter__(self) -> PlanAhead:
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def _run_local(campaign: Campaign, store: Store, todo: list[int], on_chunk: Callable,
               first=None):
    """The local executor: chunk after chunk, three threads at work. This one runs the
    compiled batches of chunk ``k`` (:meth:`.plan.Campaign.simulate`: numba's threads)
    while a helper builds the inputs of chunk ``k + 1`` (:class:`PlanAhead`) and the
    chunk writer assembles and writes chunk ``k - 1`` (:class:`ChunkWriter`): each chunk
    is still :meth:`.plan.Campaign.run_chunk`'s table, bit for bit. ``first``: the
    ``(ids, inputs)`` of chunk 0 built by the check of a new store (not built twice)."""
    with ChunkWriter(store, on_chunk, finish=campaign.assemble) as writer, \
            PlanAhead(campaign) as ahead:
        if first is not None:
            ahead.keep(0, first)
        for i, k in enumerate(todo):
            ids, inputs = ahead.take(k)
            if i + 1 < len(todo):
                ahead.start(todo[i + 1])
            writer.put(k, campaign.simulate(ids, inputs))


def _restore(environ: dict) -> None:
    """Put back this process's environment: the nanny copies its pre-spawn settings
    (``OMP_NUM_THREADS=1``, ``MALLOC_TRIM_THRESHOLD_``, ...) into the process that starts
    the workers (distributed's ``nanny.py``), where they would change every later child."""
    for k in set(os.environ) - set(environ):
        del os.environ[k]
    for k, v in environ.items():
        if os.environ.get(k) != v:
            os.environ[k] = v


def local_cluster(n_workers: int):
    """A ``LocalCluster`` of ``n_workers`` process workers, one Dask thread each, with
    ``NUMBA_NUM_THREADS = cores // n_workers`` set in each before it starts.

    Examples
    --------
    :func:`run` starts one with ``executor="dask", dask_local=2``; by hand (starting a
    worker process takes about two seconds):

    >>> from distributed import Client
    >>> from rocking.campaign import local_cluster
    >>> cluster = local_cluster(1)
    >>> client = Client(cluster)
    >>> [w["nthreads"] for w in client.scheduler_info()["workers"].values()]
    [1]
    >>> client.close(); cluster.close()
    """
    import logging

    from distributed import LocalCluster
    threads = max(1, _cores() // n_workers)
    # the nanny's ``env`` is set in each worker process before it starts, and, unlike
    # ``distributed.nanny.pre-spawn-environ``, does not leak into this process (where a
    # changed NUMBA_NUM_THREADS makes numba refuse to compile anything more)
    environ = dict(os.environ)
    try:
        return LocalCluster(n_workers=n_workers, threads_per_worker=1, processes=True,
                            dashboard_address=":0", silence_logs=logging.ERROR,
                            env={"NUMBA_NUM_THREADS": str(threads)})
    finally:
        _restore(environ)


def _run_dask(spec: CampaignSpec, store: Store, todo: list[int], on_chunk: Callable,
              scheduler: str | None, dask_local: int | None, window: int | None,
              log: Callable):
    from distributed import Client, as_completed
    environ = dict(os.environ)
    cluster = local_cluster(dask_local) if scheduler is None else None
    client = Client(cluster if cluster is not None else scheduler, timeout="60s")
    pending: set = set()  # submitted, not yet written: cancelled if the run stops
    try:
        workers = client.scheduler_info(n_workers=-1)["workers"]
        if not workers:
            client.wait_for_workers(1, timeout=120)
            workers = client.scheduler_info(n_workers=-1)["workers"]
        per_host: dict[str, int] = {}
        for addr in workers:
            host = addr.rsplit(":", 1)[0]
            per_host[host] = per_host.get(host, 0) + 1
        info = client.run(setup_worker, spec, per_host)
        threads = sum(w.get("nthreads", 1) for w in workers.values())
        log(f"dask: {len(workers)} workers on {len(per_host)} host(s), "
            f"{sorted({v['numba_threads'] for v in info.values()})} numba threads each")
        window = window or max(2, 2 * threads)
        spec_f = client.scatter(spec, broadcast=True)
        queue = iter(todo)
        pending.update(client.submit(chunk_task, spec_f, k, pure=False)
                       for k in (next(queue, None) for _ in range(window)) if k is not None)
        ac = as_completed(list(pending))
        with ChunkWriter(store, on_chunk, depth=2) as writer:
            for fut in ac:
                k, table = fut.result()
                writer.put(k, table)
                pending.discard(fut)
                fut.release()
                nxt = next(queue, None)
                if nxt is not None:
                    new = client.submit(chunk_task, spec_f, nxt, pure=False)
                    pending.add(new)
                    ac.add(new)
    finally:
        for f in pending:
            f.cancel()
        client.close()
        if cluster is not None:
            cluster.close()
        _restore(environ)


def run(spec, out, *, executor: str = "local", scheduler: str | None = None,
        dask_local: int | None = None, window: int | None = None, progress: bool = True,
        log: Callable = print) -> dict:
    """Run the campaign ``spec`` (a path to a TOML file or a :class:`CampaignSpec`) into
    the store ``out``, skipping the chunks already there (resume). Returns the store's
    :meth:`~.store.Store.status`.

    ``executor`` is ``"local"`` (default) or ``"dask"`` with ``scheduler`` (an address,
    ``tcp://host:port``) or ``dask_local`` (workers of a ``LocalCluster``, default 2);
    ``window`` bounds the chunks in flight (default 2 per Dask thread). A different spec on
    an existing store raises :class:`~rocking.errors.StoreError`. Interrupting (Ctrl-C)
    keeps every finished chunk; run again to resume.

    Order: the spec is parsed and the first chunk's motions and inputs are built before the
    store directory is created (a spec that fails never leaves a store behind); then the
    store is locked, every chunk verified against its record, files that fail moved into
    ``STORE/quarantine/`` (each named through ``log``) and their chunks recomputed.

    Examples
    --------
    Four one-sine pulses on specimen 2, in two chunks:

    >>> from pathlib import Path
    >>> from rocking import campaign
    >>> from rocking.campaign import EXAMPLE_SPEC
    >>> _ = Path("pulses.toml").write_text(EXAMPLE_SPEC)
    >>> status = campaign.run("pulses.toml", "pulses_store", progress=False)
    >>> status["sims_done"], status["chunks_done"], status["complete"]
    (4, 2, True)

    Running it again resumes: nothing is left to compute.

    >>> campaign.run("pulses.toml", "pulses_store", progress=False)["sims_done"]
    4
    """
    if not isinstance(spec, CampaignSpec):
        spec = read_spec(spec)
    if executor not in EXECUTORS:
        raise ParameterError(f"executor must be one of {', '.join(EXECUTORS)}, got "
                             f"{executor!r}")
    if executor == "local" and (scheduler is not None or dask_local is not None):
        raise ParameterError("scheduler and dask_local apply to executor 'dask' only")
    if scheduler is not None and dask_local is not None:
        raise ParameterError("give scheduler or dask_local, not both")
    if dask_local is not None and (isinstance(dask_local, bool) or not isinstance(
            dask_local, int | np.integer) or not 1 <= dask_local <= 1024):
        raise ParameterError(f"dask_local must be a whole number in [1, 1024], got "
                             f"{dask_local!r}")
    if window is not None and (isinstance(window, bool) or not isinstance(
            window, int | np.integer) or not 1 <= window <= 100_000):
        raise ParameterError(f"window must be a whole number in [1, 100000], got {window!r}")
    if executor == "dask" and scheduler is None and dask_local is None:
        dask_local = 2
    campaign = Campaign(spec)
    first = None
    if not Store(out).exists():  # a spec that cannot start never leaves a store behind
        first = _check_buildable(campaign)
    store = Store(out).prepare()
    store.lock()
    try:
        store.open_for(spec, log=log)
        store.repair(log=log)  # problem files moved aside, their chunks recomputed
        check = store.check()
        todo = [k for k in range(spec.n_chunks) if k not in check.ok]
        status = store.status(check)
        if todo:  # records short of EN 1998-1 at an isolator's or the building's period:
            from .report import records_fit  # said before the runs, not after them
            from .store import manifest_for
            records_fit(manifest_for(spec), stacklevel=3)
        from tqdm.auto import tqdm
        bar = tqdm(total=spec.n_sims, initial=status["sims_done"], unit="sim",
                   disable=not progress, dynamic_ncols=True, smoothing=0.1,
                   desc=spec.name)

        def on_chunk(k, n):
            bar.update(n)

        try:
            if todo and executor == "local":
                _run_local(campaign, store, todo, on_chunk, first)
            elif todo:
                _run_dask(spec, store, todo, on_chunk, scheduler, dask_local,
                          window or spec.window, log)
        finally:
            bar.close()
    finally:
        store.unlock()
    return store.status()


def _check_buildable(campaign: Campaign):
    """Build what the first chunk needs (its motions, and every motion of a deterministic
    kind up to the cache's size; the inputs: draws, scaling to the levels), so that an
    error surfaces before the store is created. Returns the first chunk's ``(ids,
    inputs)``, for the local executor."""
    from .plan import KEEP
    spec = campaign.spec
    first = np.arange(*campaign.chunk_range(0))
    if spec.motion_axis.kind != "stochastic":
        campaign.motions.prepare(range(min(spec.n_motions, KEEP)))
    return first, campaign.inputs(first)


def estimate(spec: CampaignSpec, n_sample: int = 48) -> dict:
    """A dry run: counts, and the time of the local executor estimated from the time to
    build the motions (up to 500 of them, extrapolated) and ``n_sample`` simulations per
    model drawn at random over the campaign's axes (after a warm-up).

    Examples
    --------
    >>> from pathlib import Path
    >>> from rocking import campaign
    >>> from rocking.campaign import EXAMPLE_SPEC
    >>> _ = Path("pulses.toml").write_text(EXAMPLE_SPEC)
    >>> est = campaign.estimate(campaign.read_spec("pulses.toml"), n_sample=4)
    >>> est["n_sims"], est["n_chunks"], est["shape"]["levels"]
    (4, 2, 4)
    >>> bool(est["estimated_seconds"] > 0)
    True
    """
    from ..models.registry import MODELS
    c = Campaign(spec)
    warm_up(spec)
    nm = spec.n_motions
    k_prep = min(nm, 500)
    t0 = time.perf_counter()
    c.motions.prepare(range(k_prep))
    seconds = (time.perf_counter() - t0) * nm / k_prep
    rng = np.random.default_rng(0)
    shape = spec.shape
    sampled = 0
    runs = spec.runs  # the models, or the mitigations of the single model
    for r, (name, _) in enumerate(runs):
        k = 4 if MODELS[name].slow else n_sample
        idx = [np.full(k, r)] + [rng.integers(0, n, k) for n in
                                 (shape[1], shape[2], k_prep, shape[4], shape[5])]
        ids = np.unique(np.ravel_multi_index(idx, shape))
        t0 = time.perf_counter()
        c.run_ids(ids)
        seconds += (time.perf_counter() - t0) / ids.size * spec.n_sims / len(runs)
        sampled += ids.size
    axes = {f"{k}s": v for k, v in spec.axes.items()}
    if spec.building_axis is None:
        del axes["floors"]
    if not spec.mitigations:
        del axes["mitigations"]
    if not spec.headings:
        del axes["headings"]
    return {"n_sims": spec.n_sims, "n_chunks": spec.n_chunks, "chunk_size": spec.chunk_size,
            "shape": axes, "sampled": sampled, "estimated_seconds": seconds}
