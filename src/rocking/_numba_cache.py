"""Where numba caches the compiled kernels, decided when ``rocking`` is imported.

The kernels are compiled with ``cache=True``: numba writes them in the ``__pycache__``
folder next to each source file, else in the user's cache folder (``$XDG_CACHE_HOME/numba``
or ``~/.cache/numba``), or in ``NUMBA_CACHE_DIR`` when it is set; where none of these can
be written (a read-only installation and an unwritable home), numba refuses every kernel
(``cannot cache function ...: no locator available``) and every command fails.
:func:`ensure_numba_cache` checks, the way numba does (create the folder, write a
temporary file in it), before any kernel is decorated; where numba would find no folder it
sets ``NUMBA_CACHE_DIR`` to ``rocking-numba-cache-<user>`` in the temporary folder, or,
where even that cannot be written, turns numba's caching off (the kernels are compiled in
every process, about a minute), and says so in one line on stderr. Nothing is changed when
numba can write its cache (the check costs a few file creations per import).
"""

from __future__ import annotations

import os
import sys
import tempfile
from pathlib import Path

KERNEL_DIRS = ("motions", "models", "models/dem", "models/_numerics")
"""The package folders whose modules hold ``cache=True`` kernels (tests check the list)."""


def writable(path) -> bool:
    """Whether numba could cache in ``path``: the folder can be created and written (what
    numba's ``_CacheLocator.ensure_cache_path`` does)."""
    try:
        os.makedirs(path, exist_ok=True)
        tempfile.TemporaryFile(dir=path).close()
    except (OSError, ValueError):
        return False
    return True


def user_cache_dir(environ) -> str:
    """numba's user-wide cache folder (its ``appdirs.user_cache_dir``) for ``environ``."""
    home = environ.get("HOME") or os.path.expanduser("~")
    if sys.platform == "darwin":
        return os.path.join(home, "Library", "Caches", "numba")
    if sys.platform.startswith("win"):
        base = environ.get("LOCALAPPDATA") or os.path.join(home, "AppData", "Local")
        return os.path.join(base, "numba", "Cache")
    base = environ["XDG_CACHE_HOME"] if "XDG_CACHE_HOME" in environ else \
        os.path.join(home, ".cache")
    return os.path.join(base, "numba")


def choose_cache_dir(package, environ, tmpdir) -> tuple[str | None, str | None]:
    """``(folder, message)``: ``(None, None)`` where numba can cache by itself; else the
    folder to set as ``NUMBA_CACHE_DIR`` (``""``: none is writable, caching off) and the
    line that says so."""
    given = environ.get("NUMBA_CACHE_DIR", "")
    if given and writable(given):
        return None, None
    package = Path(package)
    in_tree = [package / d / "__pycache__" for d in KERNEL_DIRS]
    if all(writable(d) for d in in_tree):
        return None, None
    user = user_cache_dir(environ)
    if writable(user):
        return None, None
    tried = ([f"NUMBA_CACHE_DIR={given}"] if given else []) + \
        [f"{package}{os.sep}...{os.sep}__pycache__", user]
    uid = getattr(os, "getuid", lambda: environ.get("USERNAME", "user"))()
    fallback = None if tmpdir is None else os.path.join(tmpdir, f"rocking-numba-cache-{uid}")
    if fallback is not None and writable(fallback):
        return fallback, (f"rocking: numba cannot write its cache ({', '.join(tried)}): "
                          f"caching the compiled kernels in {fallback}")
    tried += [fallback or "no temporary folder"]
    return "", (f"rocking: numba cannot write its cache ({', '.join(tried)}): "
                "running without one (the kernels are compiled in every run)")


def ensure_numba_cache(package=None, environ=None, stderr=None) -> str | None:
    """Make sure numba can cache the kernels or runs without a cache (module doc); returns
    the line written on ``stderr``, None when nothing was changed."""
    environ = os.environ if environ is None else environ
    package = Path(__file__).parent if package is None else package
    try:
        tmpdir = tempfile.gettempdir()  # the first writable of TMPDIR, TEMP, TMP, /tmp, ...
    except OSError:  # none is
        tmpdir = None
    folder, message = choose_cache_dir(package, environ, tmpdir)
    if message is None:
        return None
    if folder:
        environ["NUMBA_CACHE_DIR"] = folder
        config = sys.modules.get("numba.core.config")
        if config is not None:  # numba was imported first: it read the variable already
            config.CACHE_DIR = folder
    else:
        environ.pop("NUMBA_CACHE_DIR", None)
        from numba.core.dispatcher import Dispatcher

        Dispatcher.enable_caching = _no_caching
    print(message, file=stderr if stderr is not None else sys.stderr)
    return message


def _no_caching(self) -> None:
    """``Dispatcher.enable_caching`` where no folder can be written: ``cache=True`` is
    ignored (numba keeps its in-memory compilation)."""
