"""simulate_many packs the samples into a per-thread buffer reused from batch to batch
(issue 33: no fresh pages per campaign chunk). A batch after a longer one must not see the
longer one's samples in its padding: each row still equals its single run."""

from __future__ import annotations

import threading

import numpy as np

import rocking
from rocking.models import pack_motions
from rocking.models.run import SCRATCH_BYTES, scratch_buffer
from rocking.motions import Record


def _records(n, m, seed):
    rng = np.random.default_rng(seed)
    return [Record(rng.normal(scale=2.0, size=m), 0.01) for _ in range(n)]


def test_rows_equal_single_runs_after_a_longer_batch():
    block = rocking.specimen(2)
    long = _records(6, 1500, 1)
    short = _records(4, 300, 2) + _records(1, 700, 3)
    rocking.simulate_many(block, long)  # fills the buffer with other samples
    res = rocking.simulate_many(block, short)
    for i, mo in enumerate(short):
        one = rocking.simulate(block, mo)
        assert res.max_abs_theta[i] == one.max_abs_theta
        assert res.n_impacts[i] == one.n_impacts


def test_packed_samples_same_with_or_without_the_buffer():
    motions = _records(3, 400, 4) + _records(2, 900, 5)
    scratch_buffer(10 ** 5).fill(np.nan)  # garbage where the padding goes
    a = pack_motions(motions, buffer=scratch_buffer)
    b = pack_motions(motions)
    assert np.array_equal(a.samples, b.samples)
    assert a.samples.base is not None  # a view of the buffer


def test_buffer_per_thread_and_bounded():
    mine = scratch_buffer(100)
    other = []
    t = threading.Thread(target=lambda: other.append(scratch_buffer(100)))
    t.start()
    t.join()
    assert other[0] is not mine
    assert scratch_buffer(SCRATCH_BYTES // 8 + 1) is None
