"""One line on stderr before the first compile of the rocking kernels in a process.

A model's kernels are compiled by numba at their first call and cached on disk
(``__pycache__`` beside the sources, or ``NUMBA_CACHE_DIR``); with a cold cache that
first call takes tens of seconds, silent. :func:`compile_notice` wraps a kernel's call:

    compile_notice(cls.kernel)(mp, kind, ...)

and, when that call is about to compile (the dispatcher holds no machine code for these
argument types, and numba's cache index on disk has no entry for them), writes
:data:`MESSAGE` on stderr first, once per process. With a warm cache (or a kernel
already compiled in this process) it says nothing; its cost then is a look at the
dispatcher's ``signatures``, and once the line has been written, nothing.
"""

from __future__ import annotations

import sys

MESSAGE = ("rocking: compiling the rocking kernels, once, about 30 s "
           "(numba caches them for the next runs)")
"""The line written on stderr before the first compile in a process."""

_said = False
"""Whether this process has written :data:`MESSAGE` already."""

_shared = None
"""A ``multiprocessing.Value`` shared by cooperating processes (the report's workers,
:func:`share`): set once one of them has written the line."""


def share(flag) -> None:
    """Say the line once for all the processes given the same ``flag`` (a
    ``multiprocessing.Value("b", 0)``); ``None``: once for this process alone."""
    global _shared
    _shared = flag


def _first() -> bool:
    """Whether this process is the first of those sharing :data:`_shared` to say it."""
    if _shared is None:
        return True
    with _shared.get_lock():
        if _shared.value:
            return False
        _shared.value = 1
        return True


def _cached(dispatcher, sig: tuple) -> bool:
    """Whether numba's cache on disk holds ``dispatcher``'s machine code for the argument
    types ``sig`` (the key numba looks up: argument types, target, bytecode)."""
    cache = getattr(dispatcher, "_cache", None)
    index = getattr(cache, "_cache_file", None)
    if index is None:  # no cache (cache=False): every process compiles
        return False
    try:
        key = cache._index_key(sig, dispatcher.targetctx.codegen())
        return key in index._load_index()
    except Exception:  # noqa: BLE001 - an unreadable index: numba recompiles too
        return False


def will_compile(dispatcher, args) -> bool:
    """Whether calling ``dispatcher(*args)`` compiles: not yet compiled in this process
    for these argument types, and not in numba's cache on disk.

    Examples
    --------
    >>> from rocking.models import same_block
    >>> import numpy as np
    >>> same_block((0.2, 2.0), np.zeros(3))
    (0.2, 2.0)
    >>> will_compile(same_block, ((0.2, 2.0), np.zeros(3)))
    False
    """
    if not hasattr(dispatcher, "signatures"):  # a plain function (NUMBA_DISABLE_JIT)
        return False
    sig = tuple(dispatcher.typeof_pyval(a) for a in args)
    if sig in dispatcher.overloads:
        return False
    return not _cached(dispatcher, sig)


def compile_notice(dispatcher):
    """``dispatcher``, to be called at once; when that call will compile (and this
    process has not said so yet), a function that writes :data:`MESSAGE` on stderr and
    then calls it.

    Examples
    --------
    >>> from rocking.models import same_block
    >>> import numpy as np
    >>> compile_notice(same_block)((0.2, 2.0), np.zeros(3))
    (0.2, 2.0)
    """
    if _said or not hasattr(dispatcher, "signatures") or dispatcher.signatures:
        return dispatcher

    def call(*args):
        global _said
        if not _said and will_compile(dispatcher, args):
            _said = True
            if _first():
                sys.stderr.write(MESSAGE + "\n")
                sys.stderr.flush()
        return dispatcher(*args)

    return call
