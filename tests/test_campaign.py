"""Campaigns: the spec, reproducibility across executors and chunkings, resume after a kill,
the store's guards, and agreement with direct calls of the models."""

from __future__ import annotations

import math
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd
import pyarrow as pa
import pyarrow.compute as pc
import pyarrow.parquet as pq
import pytest
from cli_helpers import run_main

import rocking
from rocking import campaign
from rocking.errors import SpecError, StoreError
from rocking.motions import Sine, load_builtin

ROCKING = [sys.executable, "-c", "from rocking.cli import main; main()"]

SMALL = """
[campaign]
name = "small"
seed = 11
model = ["housner", "ccrr"]

[[blocks]]
specimen = 2
params = "experimental"

[[blocks]]
alpha = 0.25
p = 2.2
mu = 0.95

[motions]
kind = "builtin"
name = ["RSN126_GAZLI_GAZ000", "RSN982_NORTHR_JEN292"]
load_factors = [0.4, 0.9, 1.6]

[uncertain]
alpha = {{dist = "normal", cov = 0.03}}
theta0 = {{dist = "uniform", low = -0.002, high = 0.002}}
noise = {{dist = "uniform", low = 0.0, high = 0.05}}

[run]
chunk_size = {chunk}
"""


def write(tmp_path: Path, text: str, name: str = "spec.toml") -> Path:
    p = tmp_path / name
    p.write_text(text)
    return p


def cli(*args, **kw):
    """The real command in a subprocess (exit code, one-line errors, signals)."""
    return subprocess.run([*ROCKING, *map(str, args)], capture_output=True, text=True,
                          timeout=300, **kw)


# ------------------------------------------------------------------ reproducibility
def parquet_rows(store: Path):
    """Every chunk file of a store read raw with pyarrow (not through ``campaign.load``),
    concatenated and sorted by ``sim_id``."""
    files = sorted((store / "chunks").glob("*.parquet"))
    assert files, store
    table = pa.concat_tables([pq.read_table(f) for f in files])
    return table.take(pc.sort_indices(table, [("sim_id", "ascending")]))


def assert_bit_identical(a, b):
    """Two pyarrow tables with the same schema (names, types, units in the field metadata)
    and, column by column, the same bytes in every row (NaN payloads and the sign of zero
    included: stricter than ``==``)."""
    assert a.schema.equals(b.schema, check_metadata=True), (a.schema, b.schema)
    assert a.num_rows == b.num_rows
    for name in a.column_names:
        x = a.column(name).combine_chunks()
        y = b.column(name).combine_chunks()
        assert x.null_count == y.null_count, name
        if not (pa.types.is_integer(x.type) or pa.types.is_floating(x.type)):
            assert x.to_pylist() == y.to_pylist(), name  # strings, booleans
            continue
        xa = np.ascontiguousarray(x.to_numpy(zero_copy_only=False))
        ya = np.ascontiguousarray(y.to_numpy(zero_copy_only=False))
        assert xa.dtype == ya.dtype and xa.tobytes() == ya.tobytes(), name


@pytest.fixture(scope="module")
def local_store(tmp_path_factory):
    """The store of the small spec in chunks of 7, run once for the module."""
    d = tmp_path_factory.mktemp("local")
    spec = write(d, SMALL.format(chunk=7))
    campaign.run(spec, d / "store", progress=False)
    return d / "store"


@pytest.fixture(scope="module")
def local_rows(local_store):
    return campaign.load(local_store)


def test_rows_identical_across_chunk_sizes(tmp_path, local_rows, local_store):
    spec = write(tmp_path, SMALL.format(chunk=5))
    campaign.run(spec, tmp_path / "store", progress=False)
    other = campaign.load(tmp_path / "store")
    assert_bit_identical(parquet_rows(local_store), parquet_rows(tmp_path / "store"))
    assert len(local_rows) == 2 * 2 * 2 * 3
    assert local_rows["sim_id"].tolist() == list(range(len(local_rows)))
    pd.testing.assert_frame_equal(local_rows, other, check_exact=True)
    # the draws are real: alpha varies, theta0 spans its range, noise > 0
    assert local_rows["alpha"].nunique() == len(local_rows)
    assert (local_rows["noise"] > 0).all()


def test_rows_identical_on_a_dask_local_cluster(tmp_path, local_rows, local_store):
    spec = write(tmp_path, SMALL.format(chunk=3))
    before = dict(os.environ)
    logs: list[str] = []
    st = campaign.run(spec, tmp_path / "store", executor="dask", dask_local=2,
                      progress=False, log=logs.append)
    assert st["complete"]
    pd.testing.assert_frame_equal(local_rows, campaign.load(tmp_path / "store"),
                                  check_exact=True)
    # the Parquet files themselves, row by row and bit for bit (other chunk sizes: 7, 3)
    assert_bit_identical(parquet_rows(local_store), parquet_rows(tmp_path / "store"))
    # 2 workers share the cores: each runs its chunks on cores // 2 numba threads
    cores = len(os.sched_getaffinity(0))
    assert f"[{max(1, cores // 2)}] numba threads" in logs[0]
    # nothing leaked into this process: numba still compiles here
    assert dict(os.environ) == before  # (distributed's nanny sets OMP_NUM_THREADS=1, ...)
    import numba

    @numba.njit(parallel=True)
    def total(x):
        s = 0.0
        for i in numba.prange(x.size):
            s += x[i]
        return s

    assert total(np.ones(1000)) == 1000.0


def test_lazy_load_has_the_same_rows(local_rows, local_store):
    lazy = campaign.load(local_store, lazy=True)
    assert not isinstance(lazy, pd.DataFrame)
    got = lazy.compute().sort_values("sim_id").reset_index(drop=True)
    pd.testing.assert_frame_equal(local_rows, got, check_dtype=False)


# ------------------------------------------------------------------ physics of a row
def test_a_row_reproduces_the_direct_call(tmp_path):
    """Without ``duration``, each run lasts its motion's duration, as in simulate_many; a
    row equals rocking.simulate with the row's block and initial tilt under the named
    record times the row's load factor (built here, not by the campaign)."""
    text = SMALL.format(chunk=7).replace(
        'noise = {dist = "uniform", low = 0.0, high = 0.05}\n', "")
    campaign.run(write(tmp_path, text), tmp_path / "s", progress=False)
    rows = campaign.load(tmp_path / "s")
    for i in (0, 5, 13, 22):
        row = rows.iloc[i]
        block = rocking.Block.from_params(row.alpha, row.p, row.mu)
        motion = load_builtin(row.motion_id).scaled(row.load_factor)
        r = rocking.simulate(block, motion, model=row.model, theta0=row.theta0)
        assert r.max_abs_theta == row.max_abs_theta or (r.overturned and row.overturned)
        assert bool(r.overturned) == bool(row.overturned)
        assert r.n_impacts == row.n_impacts
        assert row.load_factor == [0.4, 0.9, 1.6][row.level]
        assert row.pga == pytest.approx(motion.pga, rel=1e-12)


def test_no_uncertainty_is_exactly_the_nominal_batch(tmp_path):
    text = """
[campaign]
name = "plain"
seed = 0
model = "housner"
[[blocks]]
specimen = 3
params = "experimental"
[motions]
kind = "sine"
frequency = [1.0, 2.5]
amplitude = 1.0
cycles = 4
load_factors = {start = 0.5, stop = 3.0, num = 6}
"""
    campaign.run(write(tmp_path, text), tmp_path / "s", progress=False)
    rows = campaign.load(tmp_path / "s")
    block = rocking.specimen(3, "experimental")
    motions = [Sine.from_acceleration(f, 1.0, 4 / f).scaled(a)
               for f in (1.0, 2.5) for a in np.linspace(0.5, 3.0, 6)]
    res = rocking.simulate_many(block, motions)
    np.testing.assert_array_equal(rows["max_abs_theta"], res.max_abs_theta)
    np.testing.assert_array_equal(rows["overturned"], res.overturned)
    # the sine grid's load factor is the peak acceleration (amplitude 1 m/s^2)
    np.testing.assert_allclose(rows["pga"], rows["load_factor"], rtol=1e-12)
    # below g tan(alpha) the block never leaves the ground (Housner's uplift condition)
    calm = rows["pga"] < rocking.G * math.tan(block.alpha)
    assert calm.any() and (rows.loc[calm, "max_abs_theta"] == 0).all()


def test_im_levels_scale_each_record_to_the_level(tmp_path):
    text = """
[campaign]
name = "ims"
seed = 0
model = "housner"
duration = 6.0
[[blocks]]
width = 0.2
height = 0.8
[motions]
kind = "stochastic"
n = 3
duration = 20.0
im = "pga"
levels = [1.0, 2.0, 4.0]
"""
    campaign.run(write(tmp_path, text), tmp_path / "s", progress=False)
    rows = campaign.load(tmp_path / "s")
    np.testing.assert_allclose(rows["pga"], rows["im"], rtol=1e-12)
    recs = rocking.motions.stochastic_records(3, seed=0, duration=20.0)
    for r in rows.itertuples():
        assert r.load_factor == pytest.approx(r.im / recs[r.motion].pga, rel=1e-12)


def test_draws_follow_their_distributions(tmp_path):
    text = SMALL.format(chunk=500).replace('load_factors = [0.4, 0.9, 1.6]',
                                           'load_factors = [0.01]')
    text = text.replace('model = ["housner", "ccrr"]', 'model = "housner"\nsamples = 200')
    spec = campaign.parse_spec(text)
    table = campaign.Campaign(spec).table()
    a = table.loc[table["block"] == 1, "alpha"].to_numpy()
    assert a.size == 400
    se = 0.25 * 0.03 / math.sqrt(a.size)
    assert abs(a.mean() - 0.25) < 4 * se
    assert a.std(ddof=1) == pytest.approx(0.25 * 0.03, rel=0.2)
    th = table["theta0"].to_numpy()
    assert th.min() >= -0.002 and th.max() <= 0.002 and abs(th.mean()) < 4 * 0.004 / 12**0.5 / 28


# ------------------------------------------------------------------ store and resume
def _killed_then_resumed(tmp_path: Path) -> tuple[Path, int, int]:
    text = SMALL.format(chunk=1).replace('model = ["housner", "ccrr"]',
                                         'model = "housner"\nsamples = 6')
    spec = write(tmp_path, text)
    store = tmp_path / "killed"
    proc = subprocess.Popen([*ROCKING, "campaign", "run", str(spec), "--out", str(store),
                             "--quiet"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    chunks = store / "chunks"
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and proc.poll() is None:
        if chunks.is_dir() and len([f for f in os.listdir(chunks) if f.endswith(".parquet")]) >= 3:
            break
        time.sleep(0.002)
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    n_done = len(campaign.Store(store).done())
    r = cli("campaign", "run", spec, "--out", store, "--quiet")
    assert r.returncode == 0, r.stderr
    return spec, n_done, campaign.status(store)["n_chunks"]


def test_sigkill_then_resume_equals_an_uninterrupted_run(tmp_path):
    spec, n_done, n_chunks = _killed_then_resumed(tmp_path)
    assert 0 < n_done < n_chunks, "the kill must land mid-run"
    campaign.run(spec, tmp_path / "clean", progress=False)
    a = campaign.load(tmp_path / "killed")
    b = campaign.load(tmp_path / "clean")
    assert a["sim_id"].is_unique and a["sim_id"].tolist() == list(range(n_chunks))
    pd.testing.assert_frame_equal(a, b)
    assert not list((tmp_path / "killed" / "chunks").glob(".*"))  # no temporary left


def test_resume_recomputes_nothing(tmp_path):
    spec = write(tmp_path, SMALL.format(chunk=4))
    campaign.run(spec, tmp_path / "s", progress=False)
    before = {f: f.stat().st_mtime_ns for f in campaign.Store(tmp_path / "s").files()}
    os.remove(campaign.Store(tmp_path / "s").chunk_path(2))
    st = campaign.status(tmp_path / "s")
    assert st["chunks_remaining"] == 1 and st["sims_remaining"] == 4
    campaign.run(spec, tmp_path / "s", progress=False)
    after = {f: f.stat().st_mtime_ns for f in campaign.Store(tmp_path / "s").files()}
    assert all(after[f] == t for f, t in before.items() if f.name != "chunk-000002.parquet")
    assert campaign.status(tmp_path / "s")["complete"]


def test_a_changed_spec_is_refused(tmp_path):
    spec = write(tmp_path, SMALL.format(chunk=12))
    campaign.run(spec, tmp_path / "s", progress=False)
    # comments and formatting are not a change
    write(tmp_path, "# a comment\n" + SMALL.format(chunk=12))
    campaign.run(spec, tmp_path / "s", progress=False)
    changed = write(tmp_path, SMALL.format(chunk=12).replace("seed = 11", "seed = 12"), "b.toml")
    with pytest.raises(StoreError, match="different campaign"):
        campaign.run(changed, tmp_path / "s", progress=False)
    r = cli("campaign", "run", changed, "--out", tmp_path / "s")
    assert r.returncode == 2 and "different campaign" in r.stderr
    assert "Traceback" not in r.stderr and len(r.stderr.strip().splitlines()) == 1


def test_a_directory_that_is_not_a_store_is_refused(tmp_path):
    (tmp_path / "d").mkdir()
    (tmp_path / "d" / "x.txt").write_text("mine")
    with pytest.raises(StoreError, match="not a campaign store"):
        campaign.run(write(tmp_path, SMALL.format(chunk=5)), tmp_path / "d", progress=False)
    with pytest.raises(StoreError):
        campaign.status(tmp_path / "d")


# ------------------------------------------------------------------ malformed specs
BAD = {
    "unknown key": (SMALL.replace('name = "small"', 'name = "small"\nnmae = "x"'),
                    "campaign.nmae"),
    "wrong type": (SMALL.replace("seed = 11", 'seed = "eleven"'), "campaign.seed"),
    "negative load factor": (SMALL.replace("[0.4, 0.9, 1.6]", "[0.4, -0.9]"),
                             "motions.load_factors[1]"),
    "unknown specimen": (SMALL.replace("specimen = 2", "specimen = 9"), "blocks[0].specimen"),
    "empty motion set": (SMALL.replace('name = ["RSN126_GAZLI_GAZ000", "RSN982_NORTHR_JEN292"]',
                                       "name = []"), "motions.name"),
    "unknown model": (SMALL.replace('["housner", "ccrr"]', '"houser"'), "campaign.model"),
    "unknown distribution": (SMALL.replace('dist = "normal"', 'dist = "gauss"'),
                             "uncertain.alpha"),
    "bad chunk size": (SMALL, "run.chunk_size"),
    "samples without uncertainty": (
        SMALL[:SMALL.index("[uncertain]")].replace('name = "small"',
                                                  'name = "small"\nsamples = 3')
        + "[run]\nchunk_size = {chunk}\n", "campaign.samples"),
    "not TOML": ("[campaign\nname=", "not valid TOML"),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_malformed_spec_gives_one_line_naming_the_key(tmp_path, capsys, case):
    text, key = BAD[case]
    text = text.format(chunk=0 if case == "bad chunk size" else 5) if "{chunk}" in text \
        else text
    spec = write(tmp_path, text)
    with pytest.raises(SpecError, match=key.replace("[", r"\[").replace("]", r"\]")):
        campaign.read_spec(spec)
    code, _, err = run_main(capsys, "campaign", "run", spec, "--out", tmp_path / "s")
    assert code == 2
    assert "Traceback" not in err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and key in lines[0]
    assert not (tmp_path / "s").exists()


def test_dem_refuses_uncertain_geometry():
    text = SMALL.format(chunk=5).replace('["housner", "ccrr"]', '["housner", "dem"]')
    with pytest.raises(SpecError, match="uncertain.alpha"):
        campaign.parse_spec(text)


# ------------------------------------------------------------------ CLI
def test_cli_dry_run_and_status(tmp_path, capsys):
    spec = write(tmp_path, SMALL.format(chunk=5))
    code, out, err = run_main(capsys, "campaign", "run", spec, "--out", tmp_path / "s",
                              "--dry-run")
    assert code == 0, err
    assert "24 simulations" in out and "5 chunks" in out and "estimated" in out
    assert not (tmp_path / "s").exists()
    code, out, err = run_main(capsys, "campaign", "run", spec, "--out", tmp_path / "s")
    assert code == 0, err
    assert "sim/s" in err and "24/24" in err  # the progress bar: count and rate
    code, out, err = run_main(capsys, "campaign", "status", tmp_path / "s")
    assert code == 0 and "24 done, 0 remaining" in out
    code, out, err = run_main(capsys, "campaign", "status", tmp_path / "nothing")
    assert code == 2 and "not a campaign store" in err


def test_ctrl_c_stops_cleanly_and_keeps_finished_chunks(tmp_path):
    text = SMALL.format(chunk=1).replace('model = ["housner", "ccrr"]',
                                         'model = "housner"\nsamples = 30')
    spec = write(tmp_path, text)
    store = tmp_path / "s"
    # SIGINT restored in the child: a test run started in the background by a
    # non-interactive shell (`pytest &`) passes SIGINT on as ignored, and a Python started
    # with SIGINT ignored never raises KeyboardInterrupt (the run then finishes, exit 0)
    proc = subprocess.Popen([*ROCKING, "campaign", "run", str(spec), "--out", str(store),
                             "--quiet"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and proc.poll() is None:
        if (store / "chunks").is_dir() and len(campaign.Store(store).done()) >= 3:
            break
        time.sleep(0.002)
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=120)
    assert proc.returncode == 130, err
    assert "Traceback" not in err and "interrupted" in err and "resume" in err
    st = campaign.status(store)
    assert 0 < st["chunks_done"] < st["n_chunks"]
    done = campaign.load(store)
    assert done["sim_id"].is_unique and len(done) == st["sims_done"]


def test_files_and_builtin_kinds_give_the_same_rows(tmp_path):
    """The same record read from its file and from the package gives the same runs."""
    from rocking.motions.io import _builtin_dir
    name = "RSN982_NORTHR_JEN292"
    base = """
[campaign]
name = "k"
seed = 0
model = "housner"
duration = 8.0
[[blocks]]
width = 0.25
height = 1.2
[motions]
{motion}
load_factors = [0.3, 1.0]
"""
    path = next(_builtin_dir().glob(name + "*"))
    a = campaign.parse_spec(base.format(motion=f'kind = "builtin"\nname = ["{name}"]'))
    b = campaign.parse_spec(base.format(motion=f'kind = "record"\nfile = ["{path}"]\n'
                                               'units = "g"'))
    ra, rb = campaign.Campaign(a).run_ids([0, 1]), campaign.Campaign(b).run_ids([0, 1])
    np.testing.assert_array_equal(ra["max_abs_theta"], rb["max_abs_theta"])
    np.testing.assert_array_equal(ra["n_impacts"], rb["n_impacts"])


def test_pulse_rows_are_the_pulses(tmp_path):
    """One-sine pulses: the load factor is the peak acceleration, and the block lifts off
    exactly for the pulses whose peak exceeds g tan(alpha) (Housner's uplift condition)."""
    text = """
[campaign]
name = "pulses"
seed = 0
model = "housner"
[[blocks]]
specimen = 3
params = "experimental"
[motions]
kind = "one_sine"
period = [0.5, 1.0]
amplitude = 1.0
load_factors = {start = 0.5, stop = 6.0, num = 12}
"""
    spec = campaign.parse_spec(text)
    rows = campaign.Campaign(spec).run_ids(np.arange(spec.n_sims))
    block = rocking.specimen(3, "experimental")
    motions = [rocking.motions.OneSine(1.0, T).scaled(a) for T in (0.5, 1.0)
               for a in np.linspace(0.5, 6.0, 12)]
    res = rocking.simulate_many(block, motions)
    np.testing.assert_array_equal(rows["max_abs_theta"], res.max_abs_theta)
    np.testing.assert_allclose(rows["pga"], rows["load_factor"], rtol=1e-12)
    up = rocking.G * math.tan(block.alpha)
    assert (rows["pga"] < up).any() and (rows["pga"] > up).any()
    assert ((rows["max_abs_theta"] > 0) == (rows["pga"] > up)).all()


def test_chunks_partition_the_sim_ids():
    from hypothesis import given, settings
    from hypothesis import strategies as st

    @settings(max_examples=30, deadline=None)
    @given(st.integers(1, 2), st.integers(1, 7), st.integers(1, 4), st.integers(1, 40))
    def check(n_models, n_levels, samples, chunk):
        # the noise (a perturbed copy of the record per row) does not change the ids
        text = SMALL.format(chunk=chunk).replace("[0.4, 0.9, 1.6]",
                                                 f"{{start = 0.1, stop = 2, num = {n_levels}}}")
        text = text.replace('noise = {dist = "uniform", low = 0.0, high = 0.05}\n', "")
        assert "noise" not in text
        models = '["housner", "ccrr"]' if n_models == 2 else '"housner"'
        text = text.replace('model = ["housner", "ccrr"]',
                            f"model = {models}\nsamples = {samples}")
        spec = campaign.parse_spec(text)
        c = campaign.Campaign(spec)
        ids = np.concatenate([np.arange(*c.chunk_range(k)) for k in range(spec.n_chunks)])
        assert ids.tolist() == list(range(spec.n_sims))
        assert spec.n_sims == n_models * 2 * 2 * n_levels * samples
        # every (model, block, motion, level, sample) once, the sample running fastest
        t = c.table()
        keys = list(zip(t["model"], t["block"], t["motion"], t["level"], t["sample"],
                        strict=True))
        expect = [(m, b, j, lv, sm) for m in ("housner", "ccrr")[:n_models]
                  for b in range(2) for j in range(2) for lv in range(n_levels)
                  for sm in range(samples)]
        assert keys == expect

    check()


def test_files_resume_after_moving_and_refuse_an_edited_record(tmp_path):
    """The spec hash covers the records' contents, not where they are: a moved project
    resumes, an edited record is a different campaign."""
    name = "RSN982_NORTHR_JEN292.AT2"
    from rocking.motions.io import _builtin_dir
    src = (_builtin_dir() / name).read_bytes()
    text = SMALL.format(chunk=8).replace(
        'kind = "builtin"\nname = ["RSN126_GAZLI_GAZ000", "RSN982_NORTHR_JEN292"]',
        f'kind = "record"\nfile = ["recs/{name}"]\nunits = "g"')
    for d in ("a", "b"):
        (tmp_path / d / "recs").mkdir(parents=True)
        (tmp_path / d / "recs" / name).write_bytes(src)
        write(tmp_path / d, text)
    store = tmp_path / "store"
    campaign.run(tmp_path / "a" / "spec.toml", store, progress=False)
    st = campaign.run(tmp_path / "b" / "spec.toml", store, progress=False)  # moved: resumes
    assert st["complete"]
    assert campaign.load(store)["motion_id"].unique().tolist() == [f"recs/{name}"]
    (tmp_path / "b" / "recs" / name).write_bytes(src.replace(b"E-0", b"E-1", 1))
    with pytest.raises(StoreError, match="different campaign"):
        campaign.run(tmp_path / "b" / "spec.toml", store, progress=False)


def test_store_out_that_is_a_file_is_refused(tmp_path, capsys):
    spec = write(tmp_path, SMALL.format(chunk=8))
    (tmp_path / "f").write_text("x")
    code, _, err = run_main(capsys, "campaign", "run", spec, "--out", tmp_path / "f")
    assert code == 2 and "--out" in err and len(err.strip().splitlines()) == 1
    with pytest.raises(rocking.ParameterError, match="window"):
        campaign.run(spec, tmp_path / "s", window=0, progress=False)


def test_builtin_three_component_records_in_a_campaign():
    text = SMALL.format(chunk=8).replace(
        'name = ["RSN126_GAZLI_GAZ000", "RSN982_NORTHR_JEN292"]', 'name = ["Rinaldi228"]')
    spec = campaign.parse_spec(text)
    assert spec.n_motions == 1
