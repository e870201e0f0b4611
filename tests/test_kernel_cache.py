"""The test session clears numba's cache when a shared compiled helper changed (numba
checks only the file of each cached function, not the helpers it calls in other files)."""

from __future__ import annotations

import importlib.util
import os
import re
from pathlib import Path

from conftest import KERNEL_STAMP, clear_stale_kernel_caches, shared_kernels_hash

SOURCES = {"motions/_kernel.py": "def ground_acc(): pass\n",
           "models/_numerics/dopri.py": "def step(): pass\n",
           "models/base.py": "def store_row(): pass\n",
           "models/housner.py": "def kernel(): pass\n"}


def _tree(tmp_path: Path) -> tuple[Path, Path]:
    pkg, tests = tmp_path / "pkg", tmp_path / "tests"
    for rel, text in SOURCES.items():
        (pkg / rel).parent.mkdir(parents=True, exist_ok=True)
        (pkg / rel).write_text(text)
    tests.mkdir()
    (tests / "test_model.py").write_text("def kernel(): pass\n")
    return pkg, tests


def _caches(pkg: Path, tests: Path) -> list[Path]:
    files = [pkg / "models/__pycache__/housner.kernel-1.py311.nbi",
             pkg / "models/__pycache__/housner.kernel-1.py311.1.nbc",
             pkg / "motions/__pycache__/_kernel.ground_acc-1.py311.nbi",
             pkg / "models/_numerics/__pycache__/dopri.step-1.py311.2.nbc",
             tests / "__pycache__/test_model.kernel-1.py311.nbi"]
    for f in files:
        f.parent.mkdir(exist_ok=True)
        f.write_bytes(b"compiled")
    return files


def test_caches_go_when_a_shared_helper_changes_and_stay_otherwise(tmp_path, monkeypatch):
    monkeypatch.delenv("NUMBA_CACHE_DIR", raising=False)
    pkg, tests = _tree(tmp_path)
    pyc = pkg / "models/__pycache__/housner.cpython-311.pyc"
    files = _caches(pkg, tests)
    pyc.write_bytes(b"bytecode")
    # never seen: the caches cannot be trusted
    assert clear_stale_kernel_caches(pkg, tests) == len(files)
    assert not any(f.exists() for f in files) and pyc.exists()
    assert (pkg / KERNEL_STAMP).read_text().strip() == shared_kernels_hash(pkg)

    files = _caches(pkg, tests)
    assert clear_stale_kernel_caches(pkg, tests) is None  # unchanged
    os.utime(pkg / "models/base.py", (1, 1))  # a new mtime is not a change
    assert clear_stale_kernel_caches(pkg, tests) is None
    (pkg / "models/housner.py").write_text("def kernel(): return 1\n")  # numba sees that
    assert clear_stale_kernel_caches(pkg, tests) is None
    assert all(f.exists() for f in files)

    for rel in ("motions/_kernel.py", "models/_numerics/dopri.py", "models/base.py"):
        files = _caches(pkg, tests)
        (pkg / rel).write_text((pkg / rel).read_text() + "# edited\n")
        assert clear_stale_kernel_caches(pkg, tests) == len(files), rel
        assert not any(f.exists() for f in files), rel
    (pkg / "models/_numerics/events.py").write_text("def rest(): pass\n")  # a new helper
    files = _caches(pkg, tests)
    assert clear_stale_kernel_caches(pkg, tests) == len(files)


def test_numba_cache_dir_is_cleared_too(tmp_path, monkeypatch):
    """With ``NUMBA_CACHE_DIR`` set, numba caches in a mirror of each source folder there
    (``<folder name>_<sha1 of its path>``): those go, another project's caches stay."""
    import hashlib

    pkg, tests = _tree(tmp_path)
    user = tmp_path / "numba-cache"
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(user))
    mirror = user / f"models_{hashlib.sha1(os.path.abspath(pkg / 'models').encode()).hexdigest()}"
    other = user / "models_0123456789abcdef0123456789abcdef01234567"
    for d in (mirror, other):
        d.mkdir(parents=True)
        (d / "housner.kernel-1.py311.nbi").write_bytes(b"compiled")
    clear_stale_kernel_caches(pkg, tests)
    assert not (mirror / "housner.kernel-1.py311.nbi").exists()
    assert (other / "housner.kernel-1.py311.nbi").exists()


def test_the_session_stamped_the_package():
    """The hook ran at the start of this session (the stamp holds a sha256)."""
    package = Path(importlib.util.find_spec("rocking").origin).parent
    assert re.fullmatch(r"[0-9a-f]{64}", (package / KERNEL_STAMP).read_text().strip())
    assert re.fullmatch(r"[0-9a-f]{64}", shared_kernels_hash(package))


def test_specs_give_writable_samples_and_records_stay_read_only():
    """numba compiles a kernel once per argument type, and a read-only array is another
    type: a record's read-only samples in single runs, next to the batches' packed
    (writable) samples, compiled every model's kernel twice (about 40 s more of first
    compilation for the five planar models). Every spec hands the kernels writable
    samples, copies: the record itself stays read-only."""
    import numpy as np
    import pytest

    from rocking.buildings import Building, FloorMotion
    from rocking.motions import GroundMotion, HorizontalPair, Record

    rec = Record(np.array([0.0, 1.0, -0.5, 0.0]), 0.01)
    vert = Record(np.array([0.0, 0.2, 0.0]), 0.01)
    specs = {"record": rec.spec(), "scaled": rec.scaled(2.0).spec(),
             "ground motion": GroundMotion(rec, vert).spec(),
             "floor": FloorMotion(rec, Building.sdof(0.5, 0.1), floor=1).spec(),
             "spec3": rec.spec3("30deg"), "pair": HorizontalPair(rec, rec).spec3()}
    for name, (_, prm, samples) in specs.items():
        assert samples.flags.writeable and samples.flags.c_contiguous, name
        assert prm.flags.writeable, name
    samples = specs["record"][2]
    np.testing.assert_array_equal(samples, rec.acc)
    samples[1] = 99.0  # a copy: the record is unchanged and still read-only
    assert rec.acc[1] == 1.0 and not rec.acc.flags.writeable
    with pytest.raises(ValueError):
        rec.acc[1] = 2.0
