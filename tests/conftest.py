"""Fixtures shared by the test modules."""

from __future__ import annotations

import hashlib
import importlib
import importlib.util
import os
import warnings
from importlib import resources
from pathlib import Path

import pytest

import rocking

# the module (``rocking.motions.synthetic`` as an attribute is the function of that name)
synthetic = importlib.import_module("rocking.motions.synthetic")


def pytest_configure(config):
    config.addinivalue_line("markers", "slow: a test that takes more than ~20 s on 2 cores")


# --------------------------------------------------------------------------- numba's cache
SHARED_KERNEL_SOURCES = ("motions/_kernel.py", "models/_numerics", "models/base.py")
"""The compiled helpers that kernels in other files call (relative to the package).
numba caches a compiled function per source file and checks only that file, so a change
here leaves every caller's cache stale (old code, or a type mismatch about tuples)."""

KERNEL_STAMP = Path("__pycache__") / ".shared-kernels.sha256"
"""Where the hash of the shared helpers is kept, relative to the package (git-ignored)."""


def shared_kernels_hash(package: Path) -> str:
    """sha256 of the shared helpers' sources (content and relative paths, not mtimes)."""
    h = hashlib.sha256()
    for rel in SHARED_KERNEL_SOURCES:
        path = package / rel
        for f in sorted(path.rglob("*.py")) if path.is_dir() else [path]:
            h.update(f.relative_to(package).as_posix().encode() + b"\0")
            h.update(f.read_bytes() + b"\0")
    return h.hexdigest()


def _numba_cache_dirs(root: Path):
    """Every directory where numba may cache the functions of the sources under ``root``:
    ``__pycache__`` beside them, or their mirror in ``NUMBA_CACHE_DIR`` when it is set."""
    user = os.environ.get("NUMBA_CACHE_DIR")
    for d in sorted({p.parent for p in root.rglob("*.py")}):
        yield d / "__pycache__"
        if user:  # numba's UserProvidedCacheLocator: <parent name>_<sha1 of the abspath>
            absd = os.path.abspath(d)
            yield Path(user) / f"{d.name}_{hashlib.sha1(absd.encode()).hexdigest()}"


def clear_stale_kernel_caches(package: Path, *others: Path) -> int | None:
    """Delete numba's cached machine code (``*.nbi``, ``*.nbc``) of ``package`` and of the
    ``others`` trees (the tests' own kernels) when the shared helpers changed since the
    last call (or were never seen); return the number of files deleted, or None when they
    are unchanged. The hash is kept in ``package / KERNEL_STAMP``."""
    digest = shared_kernels_hash(package)
    stamp = package / KERNEL_STAMP
    try:
        if stamp.read_text().strip() == digest:
            return None
    except OSError:
        pass  # first run (or unreadable): the caches cannot be trusted
    n = 0
    for root in (package, *others):
        for d in _numba_cache_dirs(root):
            for f in (*d.glob("*.nbi"), *d.glob("*.nbc")) if d.is_dir() else ():
                try:
                    f.unlink()
                    n += 1
                except FileNotFoundError:  # another session removed it first
                    pass
    try:
        stamp.parent.mkdir(exist_ok=True)
        tmp = stamp.with_name(f"{stamp.name}.{os.getpid()}.tmp")
        tmp.write_text(digest + "\n")
        os.replace(tmp, stamp)
    except OSError:
        pass  # a read-only install: the caches are cleared again next time
    return n


@pytest.hookimpl(tryfirst=True)
def pytest_sessionstart(session):
    """Before any test runs a kernel: clear numba's cache if a shared helper changed."""
    package = Path(importlib.util.find_spec("rocking").origin).parent
    n = clear_stale_kernel_caches(package, Path(__file__).parent)
    if n:
        msg = (f"numba cache: a shared kernel helper ({', '.join(SHARED_KERNEL_SOURCES)}) "
               f"changed; {n} cached files deleted, the kernels compile again")
        reporter = session.config.pluginmanager.get_plugin("terminalreporter")
        if reporter is not None:
            reporter.write_line(msg)
        else:
            print(msg)


# ------------------------------------------------------------------ both cores (xdist)
HEAVY_FIRST = ("test_benchmarks.py", "test_report.py", "test_docs.py")
"""Test files started first when the suite is spread over processes (``-n auto --dist
loadfile``, the default in ``pyproject.toml``), the costliest first (on 2 cores with a
cold numba cache: the benchmarks' smoke runs about 120 s, the quick report 50 s, the
documentation site 40 s), so that no long file is left to run alone at the end."""


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(config, items):
    """In an xdist worker, put the files of :data:`HEAVY_FIRST` first (a stable sort: the
    collection order is kept within a file and among the other files). The controller
    hands out whole files (``loadfile``) in the workers' order (``--no-loadscope-reorder``),
    so a module fixture is built once and the longest files start at once."""
    if not hasattr(config, "workerinput"):
        return
    rank = {name: i for i, name in enumerate(HEAVY_FIRST)}
    items.sort(key=lambda it: rank.get(it.path.name, len(rank)))


@pytest.fixture(scope="session")
def records_dir() -> Path:
    """The folder of the PEER records shipped with the package."""
    with resources.as_file(resources.files("rocking.motions") / "data" / "records") as p:
        yield Path(p)


@pytest.fixture(scope="session", autouse=True)
def paper_cache(tmp_path_factory):
    """A private cache directory for the 30 seed earthquakes, for the whole session (the
    user's is left alone, and every test sees the same cache whatever the order)."""
    d = tmp_path_factory.mktemp("rocking-cache")
    old = os.environ.get("ROCKING_CACHE_DIR")
    os.environ["ROCKING_CACHE_DIR"] = str(d)
    synthetic.clear_cache()
    yield d
    synthetic.clear_cache()
    if old is None:
        del os.environ["ROCKING_CACHE_DIR"]
    else:
        os.environ["ROCKING_CACHE_DIR"] = old


@pytest.fixture(scope="session")
def paper_set(paper_cache):
    """The paper's 30 synthetic earthquakes (generated once per test session)."""
    return rocking.motions.seed_earthquakes()


QUICK_REPORT = pytest.StashKey[tuple]()
"""Where :func:`quick_report` leaves ``(out, index)`` once built in this process."""


@pytest.fixture(scope="session")
def quick_report(request, tmp_path_factory, paper_cache):
    """The whole quick report, built once for the session (~50 s on 2 cores):
    ``(out, index, warnings caught while building)``. The report tests read it, and so
    do the section tests (buildings, mitigation, a real object, fragility) when the
    session runs the report tests (:func:`report_section`): a section is built with its
    own :class:`rocking.report.Context` whatever the others, so its files are those of
    ``reproduce(..., only=[its id])``."""
    from rocking.report import reproduce

    out = tmp_path_factory.mktemp("report")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        index = reproduce(out, quick=True, progress=False)
    request.config.stash[QUICK_REPORT] = out, index
    return out, index, caught


def report_section(request, section_id: str) -> tuple[Path, Path, str]:
    """``(out, index, html)`` of one report section in quick mode: the session's whole
    quick report (:func:`quick_report`) when this process has built it, or will (it runs
    ``test_report.py`` and the tests are not spread over processes), else
    ``reproduce(out, quick=True, only=[section_id])`` (a few seconds); ``html`` is what
    the section wrote into the page."""
    built = request.config.stash.get(QUICK_REPORT, None)
    if built is None and not hasattr(request.config, "workerinput") and any(
            item.path.name == "test_report.py" for item in request.session.items):
        built = request.getfixturevalue("quick_report")[:2]
    if built is not None:
        out, index = built
    else:
        from rocking.report import reproduce

        out = request.getfixturevalue("tmp_path_factory").mktemp(section_id)
        index = reproduce(out, quick=True, progress=False, only=[section_id])
    text = index.read_text(encoding="utf-8")
    start = text.index(f'<section id="{section_id}">')
    return out, index, text[start:text.index("</section>", start)]
