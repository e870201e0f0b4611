"""The local executor's chunk writer (issue 33): chunks are written by one background
thread while the next chunk computes. A failure of the writer surfaces in the run, an
interrupted or failed run keeps every chunk it finished, and a resumed run gives the same
files, byte for byte, as an uninterrupted one."""

from __future__ import annotations

import json
import threading
from pathlib import Path

import numpy as np
import pytest

from rocking import campaign
from rocking.campaign import Campaign, Store, execute, parse_spec
from rocking.campaign.execute import ChunkWriter
from rocking.errors import ParameterError
from rocking.motions import stochastic, stochastic_records

SPEC = """
[campaign]
name = "writer"
seed = 5
model = "housner"

[[blocks]]
specimen = 2
params = "experimental"

[motions]
kind = "stochastic"
n = 3
D5_95 = 4.0
t_mid = 3.0
duration = 8.0
load_factors = [0.5, 1.5, 3.0, 6.0]

[run]
chunk_size = 2
"""


def sha256s(store: Path) -> dict:
    """``{chunk: sha256}`` from the records of a store's finished chunks."""
    out = {}
    for f in sorted((store / "chunks").glob("chunk-*.json")):
        r = json.loads(f.read_text())
        out[r["chunk"]] = r["sha256"]
    return out


@pytest.fixture(scope="module")
def whole(tmp_path_factory):
    """The spec, and the chunk checksums of an uninterrupted run."""
    d = tmp_path_factory.mktemp("whole")
    spec = d / "spec.toml"
    spec.write_text(SPEC)
    st = campaign.run(spec, d / "store", progress=False)
    assert st["complete"] and st["chunks_done"] == 6
    return spec, sha256s(d / "store")


def test_writes_happen_in_one_other_thread_in_order(whole, tmp_path, monkeypatch):
    spec, sums = whole
    calls, progress = [], []
    real = Store.write_chunk

    def write(self, k, table):
        calls.append((k, threading.current_thread() is threading.main_thread()))
        return real(self, k, table)

    monkeypatch.setattr(Store, "write_chunk", write)
    s = Store(tmp_path / "s").prepare()
    s.lock()
    try:
        s.open_for(campaign.read_spec(spec))
        c = Campaign(campaign.read_spec(spec))
        with ChunkWriter(s, lambda k, n: progress.append((k, n))) as w:
            for k in range(6):
                w.put(k, c.run_chunk(k))
    finally:
        s.unlock()
    assert calls == [(k, False) for k in range(6)]
    assert progress == [(k, 2) for k in range(6)]  # each chunk counted once, when written
    assert sha256s(tmp_path / "s") == sums


def test_a_failing_writer_surfaces_and_the_resumed_run_is_identical(whole, tmp_path,
                                                                    monkeypatch):
    spec, sums = whole
    real = Store.write_chunk

    def write(self, k, table):
        if k == 3:
            raise OSError(28, "No space left on device")
        return real(self, k, table)

    monkeypatch.setattr(Store, "write_chunk", write)
    with pytest.raises(OSError, match="No space"):
        campaign.run(spec, tmp_path / "s", progress=False)
    monkeypatch.undo()
    st = campaign.status(tmp_path / "s")
    assert st["problems"] == [] and not st["running"]
    assert set(sha256s(tmp_path / "s")) == {0, 1, 2}  # nothing after the failure
    st = campaign.run(spec, tmp_path / "s", progress=False)
    assert st["complete"]
    assert sha256s(tmp_path / "s") == sums


def test_an_interrupt_keeps_every_computed_chunk(whole, tmp_path, monkeypatch):
    """Ctrl-C while chunk 4's batches run: chunks 0-3 (3 perhaps still queued for the
    writer) are all written before the run stops; the resumed run computes only 4 and
    5."""
    spec, sums = whole
    real = Campaign.simulate
    computed, interrupt = [], [True]

    def simulate(self, ids, inputs):
        k = int(ids[0]) // self.spec.chunk_size
        if k == 4 and interrupt[0]:
            raise KeyboardInterrupt
        computed.append(k)
        return real(self, ids, inputs)

    monkeypatch.setattr(Campaign, "simulate", simulate)
    with pytest.raises(KeyboardInterrupt):
        campaign.run(spec, tmp_path / "s", progress=False)
    assert computed == [0, 1, 2, 3] and set(sha256s(tmp_path / "s")) == {0, 1, 2, 3}
    computed.clear()
    interrupt[0] = False
    campaign.run(spec, tmp_path / "s", progress=False)
    assert computed == [4, 5] and sha256s(tmp_path / "s") == sums


def test_inputs_built_ahead_in_a_helper_thread(whole, tmp_path, monkeypatch):
    """The inputs of chunk k + 1 are built in a helper thread while chunk k runs (numba's
    threading layer here is thread-safe); a failure there surfaces in the run, after the
    chunks before it are written, and the resumed run gives the same files."""
    spec, sums = whole
    real = Campaign.inputs
    where, fail = [], [True]

    def inputs(self, ids):
        k = int(ids[0]) // self.spec.chunk_size
        where.append((k, threading.current_thread() is threading.main_thread()))
        if k == 3 and fail[0]:
            raise ParameterError("inputs: chunk 3 fails")
        return real(self, ids)

    monkeypatch.setattr(Campaign, "inputs", inputs)
    with pytest.raises(ParameterError, match="chunk 3 fails"):
        campaign.run(spec, tmp_path / "s", progress=False)
    if execute.threadsafe_layer():
        assert (2, False) in where and (3, False) in where  # built ahead
    assert set(sha256s(tmp_path / "s")) == {0, 1, 2}
    fail[0] = False
    campaign.run(spec, tmp_path / "s", progress=False)
    assert sha256s(tmp_path / "s") == sums


def test_without_a_thread_safe_layer_the_inputs_are_built_in_turn(whole, tmp_path,
                                                                  monkeypatch):
    """numba's ``workqueue`` layer aborts when two threads run parallel kernels (the
    records' generator has some): then each chunk's inputs are built in the main thread,
    and the files are the same. Each chunk's inputs are built once (the first chunk's by
    the check before the store is made)."""
    spec, sums = whole
    real = Campaign.inputs
    threads, built = set(), []

    def inputs(self, ids):
        threads.add(threading.current_thread() is threading.main_thread())
        built.append(int(ids[0]) // self.spec.chunk_size)
        return real(self, ids)

    monkeypatch.setattr(execute, "threadsafe_layer", lambda: False)
    monkeypatch.setattr(Campaign, "inputs", inputs)
    campaign.run(spec, tmp_path / "s", progress=False)
    assert threads == {True} and built == [0, 1, 2, 3, 4, 5]
    assert sha256s(tmp_path / "s") == sums


def test_a_closed_writer_refuses_more_chunks(tmp_path):
    s = Store(tmp_path / "s").prepare()
    s.open_for(parse_spec(campaign.EXAMPLE_SPEC))
    w = ChunkWriter(s)
    w.close()
    with pytest.raises(RuntimeError, match="closed"):
        w.put(0, None)


def test_the_record_model_cache_keeps_the_checks_and_the_records():
    """The noise-free part of the records is computed once per parameter set; a value
    refused once is refused again (the cache keys on the values' types: True is not 1.0),
    and the records are those made without the cache."""
    args = (0.5, 10.0, 6.0, 31.4, -0.6, 0.3, 1.2, 0.01, 20.0)
    assert stochastic.record_model(*args) is stochastic.record_model(*args)
    for _ in range(2):
        with pytest.raises(ParameterError, match="Ia"):
            stochastic.record_model(True, *args[1:])
        with pytest.raises(ParameterError, match="Ia"):
            stochastic.record_model([0.5], *args[1:])
    cached = stochastic_records(2, seed=3, duration=15.0)
    stochastic._record_model.cache_clear()
    stochastic._modulating_parameters.cache_clear()
    fresh = stochastic_records(2, seed=3, duration=15.0)
    for a, b in zip(cached, fresh, strict=True):
        assert np.array_equal(a.values, b.values)


@pytest.mark.parametrize("n", [1, 2, 3, 10, 250, 2000, 8000])
def test_balanced_order_spreads_every_share_over_the_chunk(n):
    """The batch order is a permutation, and each of numba's contiguous equal shares of
    the batch (16 threads) takes its runs from every tenth of the chunk: no thread gets
    one stretch of levels of one record."""
    from rocking.campaign.plan import balanced_order
    order = balanced_order(n)
    assert np.array_equal(np.sort(order), np.arange(n))
    if n >= 2000:
        for share in np.array_split(order, 16):
            assert set(share * 10 // n) == set(range(10))
