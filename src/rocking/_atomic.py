"""Atomic file output: a file appears complete under its name, or not at all.

Every helper writes to a temporary name in the destination's directory (hidden, see
:func:`temporary_name`), flushes and ``fsync``\\ s it, renames it over the destination
(:func:`os.replace`, atomic on POSIX) and ``fsync``\\ s the directory, so that the rename
itself survives a power cut. A run killed at any instant, or a full disk (``ENOSPC``),
leaves the old file (or none) and at most a temporary file, never a half-written file
under the final name; on an exception the temporary file is removed.

::

    atomic_write(path, text_or_bytes)
    with atomic_path(path) as tmp:          # any writer that takes a path
        df.to_csv(tmp) / fig.savefig(tmp)   # tmp keeps path's suffix (format inference)
    with atomic_open(path, "w") as f:
        f.write(...)
"""

from __future__ import annotations

import contextlib
import errno
import os
import secrets
from collections.abc import Iterator
from pathlib import Path

_TMP = ".tmp-"


def temporary_name(path: Path) -> Path:
    """A hidden temporary name next to ``path`` that keeps its suffix:
    ``.report.md.tmp-<pid>-<random>.md``."""
    path = Path(path)
    return path.with_name(f".{path.name}{_TMP}{os.getpid()}-{secrets.token_hex(3)}"
                          f"{path.suffix}")


def is_temporary(name: str) -> bool:
    """Whether ``name`` is a temporary name of :func:`temporary_name`."""
    return name.startswith(".") and _TMP in name


def fsync_dir(path) -> None:
    """``fsync`` the directory ``path`` (its entries: a rename, a new file). Filesystems
    that cannot sync a directory (``EINVAL``, ``ENOTSUP``) are skipped."""
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_DIRECTORY", 0))
    except OSError:
        return  # no directory handle on this platform
    try:
        os.fsync(fd)
    except OSError as e:
        if e.errno not in (errno.EINVAL, errno.ENOTSUP, errno.EOPNOTSUPP, errno.EBADF):
            raise
    finally:
        os.close(fd)


def fsync_file(path) -> None:
    """``fsync`` the file ``path`` (written by a library that does not sync)."""
    fd = os.open(path, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def replace(src, dst) -> None:
    """Rename ``src`` over ``dst`` and sync the directories involved."""
    os.replace(src, dst)
    src_dir, dst_dir = Path(src).parent, Path(dst).parent
    fsync_dir(dst_dir)
    if src_dir.resolve() != dst_dir.resolve():
        fsync_dir(src_dir)


@contextlib.contextmanager
def atomic_path(path) -> Iterator[Path]:
    """Yield a temporary path to write ``path``'s content to; on success the file is
    synced and renamed to ``path``, on an exception removed."""
    path = Path(path)
    tmp = temporary_name(path)
    try:
        yield tmp
        fsync_file(tmp)
        replace(tmp, path)
    except OSError as e:
        tmp.unlink(missing_ok=True)
        if e.filename is None:  # a write (a full disk) names no file: name the one written
            raise OSError(e.errno, e.strerror, str(path)) from e
        raise
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


@contextlib.contextmanager
def atomic_open(path, mode: str = "w", encoding: str | None = "utf-8", **kw):
    """``open(path, mode)`` for writing, atomically (see :func:`atomic_path`)."""
    if not ("w" in mode or "x" in mode) or "+" in mode:
        raise ValueError(f"atomic_open writes a new file: mode 'w' or 'wb', got {mode!r}")
    if "b" in mode:
        encoding = None
    with atomic_path(path) as tmp, open(tmp, mode, encoding=encoding, **kw) as f:
        yield f


def atomic_write(path, data: str | bytes, encoding: str = "utf-8") -> Path:
    """Write ``data`` (text or bytes) to ``path`` atomically; return ``path``."""
    path = Path(path)
    raw = data.encode(encoding) if isinstance(data, str) else bytes(data)
    with atomic_path(path) as tmp:
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
        try:
            view = memoryview(raw)
            while view:
                view = view[os.write(fd, view):]
        finally:
            os.close(fd)
    return path


__all__ = ["atomic_write", "atomic_path", "atomic_open", "fsync_dir", "fsync_file",
           "replace", "temporary_name", "is_temporary"]
