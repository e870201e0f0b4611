"""A campaign store proves its own integrity: every corruption found so far (missing,
truncated, bit-flipped, duplicated and stray chunks, a manifest with missing keys, old
stores without records) is detected by ``verify`` (Python and CLI), named, refused by
``load`` and ``report`` with one line, and recomputed by ``run`` into a store equal to an
uncorrupted one; a kill at the worst instant and a full disk leave nothing that looks
finished."""

from __future__ import annotations

import errno
import json
import os
import shutil
import signal
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from cli_helpers import run_main

from rocking import _atomic, campaign
from rocking.campaign.store import Store
from rocking.errors import StoreError

SPEC = """
[campaign]
name = "integrity"
seed = 5
model = "housner"
samples = 30

[[blocks]]
alpha = 0.25
p = 2.2
mu = 0.95

[motions]
kind = "one_sine"
period = [0.5, 1.0]
amplitude = 1.0
load_factors = [1.0, 2.5, 4.0, 6.0, 9.0]

[uncertain]
alpha = {dist = "normal", cov = 0.03}

[run]
chunk_size = 50
"""  # 300 classical runs in 6 chunks


@pytest.fixture(scope="module")
def clean(tmp_path_factory):
    """``(spec path, an uncorrupted store, its rows)``, built once."""
    d = tmp_path_factory.mktemp("clean")
    spec = d / "spec.toml"
    spec.write_text(SPEC)
    campaign.run(spec, d / "store", progress=False)
    return spec, d / "store", campaign.load(d / "store")


@pytest.fixture
def store(clean, tmp_path):
    """A fresh copy of the clean store, to corrupt."""
    s = tmp_path / "store"
    shutil.copytree(clean[1], s)
    return s


def chunk(s: Path, k: int, ext: str = "parquet") -> Path:
    return s / "chunks" / f"chunk-{k:06d}.{ext}"


def flip(path: Path, byte: int, bit: int = 0) -> None:
    b = bytearray(path.read_bytes())
    b[byte] ^= 1 << bit
    path.write_bytes(bytes(b))


def _missing(s):
    chunk(s, 2).unlink()


def _truncated(s):
    p = chunk(s, 2)
    p.write_bytes(p.read_bytes()[: p.stat().st_size // 2])


def _bitflip(s):
    flip(chunk(s, 2), chunk(s, 2).stat().st_size // 3, 5)


def _duplicated(s):
    shutil.copyfile(chunk(s, 1), chunk(s, 2))


def _stray(s):
    shutil.copyfile(chunk(s, 1), chunk(s, 9))


def _record_copied(s):  # the file and its record copied over chunk 2's
    shutil.copyfile(chunk(s, 1), chunk(s, 2))
    shutil.copyfile(chunk(s, 1, "json"), chunk(s, 2, "json"))


def _unrecorded(s):  # a run killed between the file and its record
    chunk(s, 2, "json").unlink()


def _manifest(s):
    m = json.loads((s / "manifest.json").read_text())
    del m["n_chunks"], m["spec_hash"]
    (s / "manifest.json").write_text(json.dumps(m))


# case: (corrupt, file named, kind named, damage: load refuses)
CASES = {
    "missing": (_missing, "chunk-000002.parquet", "missing", True),
    "truncated": (_truncated, "chunk-000002.parquet", "truncated", True),
    "bit flip": (_bitflip, "chunk-000002.parquet", "altered", True),
    "duplicated": (_duplicated, "chunk-000002.parquet", "duplicate", True),
    "record copied": (_record_copied, "chunk-000002.json", "bad record", True),
    "unrecorded": (_unrecorded, "chunk-000002.parquet", "unrecorded", False),
    "stray": (_stray, "chunk-000009.parquet", "stray", False),
}


@pytest.mark.parametrize("case", list(CASES))
def test_each_corruption_is_named_refused_and_recomputed(case, clean, store, capsys):
    spec, _, rows = clean
    corrupt, name, kind, damage = CASES[case]
    corrupt(store)
    bad = store / "chunks" / name
    content = bad.read_bytes() if bad.exists() else None

    # verify, in Python and on the command line: named, exit 1
    c = Store(store).check(deep=True)
    assert [(Path(p.name).name, p.kind) for p in c.problems] == [(name, kind)]
    code, out, err = run_main(capsys, "campaign", "verify", store)
    assert code == 1, out + err
    assert f"chunks/{name}: {kind}" in out and "Traceback" not in out + err

    # status: counts consistent, the bad chunk not done
    st = campaign.status(store)
    assert st["sims_done"] + st["sims_remaining"] == st["n_sims"] == 300
    assert st["chunks_done"] + st["chunks_remaining"] == st["n_chunks"] == 6
    assert st["complete"] == (st["chunks_remaining"] == 0) == (kind == "stray")
    assert st["sims_done"] == 50 * st["chunks_done"]
    assert len(st["problems"]) == 1 and name in st["problems"][0]
    code, out, _ = run_main(capsys, "campaign", "status", store)
    assert code == 0 and name in out

    # load and report: one line naming the file (damage), or only the finished rows
    if damage:
        with pytest.raises(StoreError) as e:
            campaign.load(store)
        msg = str(e.value)
        assert name in msg and "\n" not in msg and e.value.__context__ is None
        code, out, err = run_main(capsys, "campaign", "report", store)
        assert code == 2 and err.startswith("error: ") and name in err
        assert len(err.strip().splitlines()) == 1 and "Traceback" not in err
        assert not (store / "report").exists()
    else:
        got = campaign.load(store)
        assert got["sim_id"].is_unique
        assert set(got["sim_id"]) <= set(rows["sim_id"])

    # run: the bad file moved aside (never deleted), its chunk recomputed
    logs = []
    st = campaign.run(spec, store, progress=False, log=logs.append)
    assert st["complete"] and not st["problems"]
    assert any(name in line and "quarantine" in line for line in logs), logs
    pd.testing.assert_frame_equal(campaign.load(store), rows)
    assert not Store(store).check(deep=True).problems
    if content is not None:
        kept = list((store / "quarantine").glob(f"*/{name}"))
        assert len(kept) == 1 and kept[0].read_bytes() == content
    code, out, _ = run_main(capsys, "campaign", "verify", store)
    assert code == 0 and "6 of 6 chunks verified" in out and "complete" in out


def test_a_manifest_with_missing_keys(clean, store, capsys):
    spec, _, rows = clean
    _manifest(store)
    for f in (campaign.load, campaign.status):
        with pytest.raises(StoreError, match=r"manifest.json: damaged manifest, missing keys "
                                             r"spec_hash, n_chunks") as e:
            f(store)
        assert "\n" not in str(e.value)
    code, out, err = run_main(capsys, "campaign", "verify", store)
    assert code == 1 and "missing keys spec_hash, n_chunks" in out
    code, out, err = run_main(capsys, "campaign", "report", store)
    assert code == 2 and len(err.strip().splitlines()) == 1 and "manifest.json" in err
    logs = []
    campaign.run(spec, store, progress=False, log=logs.append)
    assert any("manifest.json" in line and "rewritten" in line for line in logs)
    pd.testing.assert_frame_equal(campaign.load(store), rows)
    assert (json.loads((store / "manifest.json").read_text())
            == json.loads((clean[1] / "manifest.json").read_text()))
    assert list((store / "quarantine").glob("*/manifest.json"))


def test_a_damaged_manifest_of_another_spec_is_not_rewritten(clean, store, tmp_path):
    _manifest(store)
    other = tmp_path / "other.toml"
    other.write_text(SPEC.replace("seed = 5", "seed = 6"))
    with pytest.raises(StoreError, match="nothing in .* shows it holds this spec"):
        campaign.run(other, store, progress=False)
    assert not (store / "quarantine").exists()


@pytest.mark.parametrize("trial", range(6))
def test_every_bit_flip_is_detected(clean, store, trial):
    """Today's random bit flips changed values silently in 36 of 60 trials: each of these
    60 is found (10 per trial, anywhere in any chunk file), and none changes a row."""
    rng = np.random.default_rng(trial)
    files = sorted((store / "chunks").glob("*.parquet"))
    for _ in range(10):
        f = files[rng.integers(len(files))]
        pos, bit = int(rng.integers(f.stat().st_size)), int(rng.integers(8))
        flip(f, pos, bit)
        c = Store(store).check()
        assert [(p.name, p.kind) for p in c.problems] == [(f"chunks/{f.name}", "altered")]
        with pytest.raises(StoreError, match=f.name):
            campaign.load(store)
        flip(f, pos, bit)
        assert not Store(store).check().problems


def test_the_issue_stray_case_counts_are_consistent(clean, store, capsys):
    """A stray chunk file once made status say both '500 remaining' and 'complete'."""
    shutil.copyfile(chunk(store, 0), chunk(store, 40))
    (store / "chunks" / "notes.txt").write_text("mine")
    st = campaign.status(store)
    assert st["complete"] and st["sims_remaining"] == 0 and st["chunks_remaining"] == 0
    assert [p.split(":")[0] for p in st["problems"]] == [
        "chunks/chunk-000040.parquet", "chunks/notes.txt"]
    code, out, _ = run_main(capsys, "campaign", "status", store)
    assert "0 remaining of 300" in out and "complete" in out and "notes.txt" in out
    code, out, _ = run_main(capsys, "campaign", "verify", store)
    assert code == 1 and out.count(": stray (") == 2


def test_verify_exit_codes_for_bad_input(tmp_path, capsys):
    code, _, err = run_main(capsys, "campaign", "verify", tmp_path / "nothing")
    assert code == 2 and "not a campaign store" in err
    (tmp_path / "empty").mkdir()
    code, _, err = run_main(capsys, "campaign", "verify", tmp_path / "empty")
    assert code == 2 and len(err.strip().splitlines()) == 1


def test_verify_cli_subprocess_one_line_and_exit_code(clean, store):
    """The installed command, not only main(): exit 1 on a truncated chunk, 0 after run."""
    _truncated(store)
    cmd = [sys.executable, "-c", "from rocking.cli import main; main()", "campaign"]
    r = subprocess.run([*cmd, "verify", str(store)], capture_output=True, text=True,
                       timeout=120)
    assert r.returncode == 1 and "chunks/chunk-000002.parquet: truncated" in r.stdout
    r = subprocess.run([*cmd, "report", str(store)], capture_output=True, text=True,
                       timeout=120)
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and "chunk-000002" in r.stderr
    assert "Traceback" not in r.stderr and "Arrow" not in r.stderr


# ------------------------------------------------------------------ how chunks are written
def test_a_chunk_is_synced_and_renamed_before_its_record(clean, tmp_path, monkeypatch):
    """Order of the durable steps: chunk file synced, renamed, directory synced; then the
    record the same way. A record never exists before its file is durable."""
    spec, _, _ = clean
    events = []
    real_fsync, real_replace = os.fsync, os.replace

    def fsync(fd):
        events.append(("fsync", os.readlink(f"/proc/self/fd/{fd}")))
        return real_fsync(fd)

    def replace(a, b):
        events.append(("rename", str(b)))
        return real_replace(a, b)

    s = Store(tmp_path / "s").prepare()
    s.open_for(campaign.read_spec(spec))
    table = campaign.Campaign(campaign.read_spec(spec)).run_chunk(3)
    monkeypatch.setattr(os, "fsync", fsync)
    monkeypatch.setattr(os, "replace", replace)
    s.write_chunk(3, table)
    names = [(e, Path(p).name) for e, p in events]
    chunks_dir = (tmp_path / "s" / "chunks").resolve().name
    i_file = names.index(("rename", "chunk-000003.parquet"))
    i_rec = names.index(("rename", "chunk-000003.json"))
    assert i_file < i_rec
    assert names[i_file - 1][0] == "fsync" and ".tmp-" in names[i_file - 1][1]
    assert names[i_file + 1] == ("fsync", chunks_dir)  # the directory entry
    assert names[i_rec + 1] == ("fsync", chunks_dir)
    assert not Store(tmp_path / "s").check(deep=True).problems


KILLER = """
import os, signal, sys
from rocking import _atomic, campaign
when, k = sys.argv[3], int(sys.argv[4])
real_write, real_replace = _atomic.atomic_write, os.replace

def write(path, data, encoding="utf-8"):
    if when == "before record" and str(path).endswith(f"chunk-{k:06d}.json"):
        os.kill(os.getpid(), signal.SIGKILL)
    return real_write(path, data, encoding)

def replace(a, b):
    if when == "before rename" and str(b).endswith(f"chunk-{k:06d}.parquet"):
        os.kill(os.getpid(), signal.SIGKILL)
    return real_replace(a, b)

campaign.store.atomic_write = write
os.replace = replace
campaign.run(sys.argv[1], sys.argv[2], progress=False)
"""


@pytest.mark.parametrize("when", ["before record", "before rename"])
def test_sigkill_at_the_worst_instant(clean, tmp_path, when, capsys):
    """SIGKILL between a chunk's file and its record (or before the file's rename): the
    store counts only chunks with records, nothing half-written looks finished, and the
    next run gives the uncorrupted store."""
    spec, _, rows = clean
    s = tmp_path / "s"
    r = subprocess.run([sys.executable, "-c", KILLER, str(spec), str(s), when, "3"],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == -signal.SIGKILL, r.stderr
    st = campaign.status(s)
    assert st["chunks_done"] == 3 and st["sims_done"] == 150 and not st["complete"]
    if when == "before record":
        assert st["problems"] == ["chunks/chunk-000003.parquet: unrecorded (no record: not "
                                  "finished)"]
    else:
        assert st["problems"] == [] and list((s / "chunks").glob(".chunk-000003*"))
    assert len(campaign.load(s)) == 150
    code, out, _ = run_main(capsys, "campaign", "verify", s)
    assert code == (1 if when == "before record" else 0)
    campaign.run(spec, s, progress=False)
    pd.testing.assert_frame_equal(campaign.load(s), rows)
    assert not [f for f in os.listdir(s / "chunks") if f.startswith(".")]


def test_a_run_in_progress_is_not_a_problem(clean, store):
    """While another run holds the lock, a chunk file without its record yet is in
    progress, not a problem."""
    _unrecorded(store)
    other = Store(store)
    other.lock()
    try:
        st = campaign.status(store)
        assert st["running"] and st["problems"] == [] and st["chunks_done"] == 5
    finally:
        other.unlock()
    assert campaign.status(store)["problems"]


def test_full_disk_leaves_no_half_written_file(tmp_path, monkeypatch):
    p = tmp_path / "out.csv"
    p.write_text("old, complete\n")
    real_write, calls = os.write, []

    def full(fd, data):  # the disk fills after the first 10 bytes
        calls.append(len(data))
        if len(calls) > 1:
            raise OSError(errno.ENOSPC, "No space left on device")
        return real_write(fd, data[:10])

    monkeypatch.setattr(os, "write", full)
    with pytest.raises(OSError, match="No space"):
        _atomic.atomic_write(p, "new " * 10_000)
    monkeypatch.undo()
    assert p.read_text() == "old, complete\n"
    assert os.listdir(tmp_path) == ["out.csv"]
    with pytest.raises(RuntimeError), _atomic.atomic_path(tmp_path / "fig.png") as tmp:
        assert tmp.suffix == ".png" and _atomic.is_temporary(tmp.name)
        tmp.write_bytes(b"half")
        raise RuntimeError("killed while drawing")
    assert os.listdir(tmp_path) == ["out.csv"]
    with _atomic.atomic_open(tmp_path / "a.txt") as f:
        f.write("done")
    assert (tmp_path / "a.txt").read_text() == "done"


def test_full_disk_while_writing_a_chunk(clean, store, monkeypatch):
    spec, _, rows = clean
    chunk(store, 4).unlink()
    chunk(store, 4, "json").unlink()

    def full(fd, data):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(os, "write", full)
    with pytest.raises(OSError, match="No space"):
        campaign.run(spec, store, progress=False)
    monkeypatch.undo()
    st = campaign.status(store)
    assert st["chunks_done"] == 5 and st["problems"] == []
    assert not [f for f in os.listdir(store / "chunks") if "000004" in f]
    campaign.run(spec, store, progress=False)
    pd.testing.assert_frame_equal(campaign.load(store), rows)


def test_a_failing_report_leaves_no_partial_files(clean, store, capsys, monkeypatch):
    import rocking.campaign.report as rep
    real = rep.report

    def dies(table, manifest, out, **kw):
        Path(out).mkdir(parents=True, exist_ok=True)
        (Path(out) / "p_overturn.csv").write_text("level,p\n0,")
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(rep, "report", dies)
    code, _, err = run_main(capsys, "campaign", "report", store)
    assert code == 1 and "No space" in err
    assert not (store / "report").exists() and not [
        f for f in os.listdir(store) if _atomic.is_temporary(f)]
    monkeypatch.setattr(rep, "report", real)
    code, out, err = run_main(capsys, "campaign", "report", store)
    assert code == 0, err
    files = sorted(os.listdir(store / "report"))
    assert "report.md" in files and "p_overturn.csv" in files
    assert not [f for f in os.listdir(store) if _atomic.is_temporary(f)]


# ------------------------------------------------------------------ old stores, ordering
def _as_format_1(s: Path) -> None:
    for r in (s / "chunks").glob("*.json"):
        r.unlink()
    m = json.loads((s / "manifest.json").read_text())
    m["format"] = 1
    del m["spec_dir"]
    (s / "manifest.json").write_text(json.dumps(m))


def test_a_store_without_records_is_refused_then_upgraded(clean, store, capsys):
    spec, _, rows = clean
    _as_format_1(store)
    _truncated(store)
    for f in (campaign.load, campaign.status):
        with pytest.raises(StoreError, match="format 1, written before chunk records.*"
                                             "rocking campaign upgrade"):
            f(store)
    with pytest.raises(StoreError, match="format 1"):
        campaign.run(spec, store, progress=False)
    code, out, _ = run_main(capsys, "campaign", "verify", store)
    assert code == 1 and "format 1" in out
    code, out, err = run_main(capsys, "campaign", "upgrade", store)
    assert code == 0 and "5 chunks recorded" in out and "1 moved into quarantine" in out
    assert "chunk-000002.parquet" in err
    st = campaign.status(store)
    assert st["chunks_done"] == 5 and not st["problems"]
    campaign.run(spec, store, progress=False)
    pd.testing.assert_frame_equal(campaign.load(store), rows)
    code, out, _ = run_main(capsys, "campaign", "verify", store)
    assert code == 0 and "5 chunks adopted by upgrade" in out


def test_a_spec_whose_motions_cannot_be_built_leaves_no_store(tmp_path, capsys):
    """The store directory is created only after the spec is parsed and the motions of
    the first chunk are built and scaled: a record of zeros cannot be scaled to a PGA."""
    (tmp_path / "zero.csv").write_text("t,acc\n" + "".join(f"{0.01 * i:.2f},0\n"
                                                           for i in range(200)))
    text = f"""
[campaign]
name = "zero"
seed = 0
model = "housner"
[[blocks]]
alpha = 0.2
p = 2.0
mu = 0.9
[motions]
kind = "record"
file = ["{tmp_path / 'zero.csv'}"]
units = "m/s^2"
im = "pga"
levels = [1.0, 2.0]
"""
    spec = tmp_path / "spec.toml"
    spec.write_text(text)
    with pytest.raises(ValueError):
        campaign.run(spec, tmp_path / "s", progress=False)
    assert not (tmp_path / "s").exists()
    code, _, err = run_main(capsys, "campaign", "run", spec, "--out", tmp_path / "s")
    assert code == 2 and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "s").exists()


def test_quarantine_never_overwrites(clean, store):
    """Two repairs of the same chunk within a second keep both bad files."""
    spec = clean[0]
    contents = []
    for byte in (100, 200):
        flip(chunk(store, 2), byte)
        contents.append(chunk(store, 2).read_bytes())
        campaign.run(spec, store, progress=False)
    kept = sorted(p.read_bytes() for p in (store / "quarantine").rglob("chunk-000002.parquet*"))
    assert kept == sorted(contents)


def test_ctrl_c_before_the_store_exists(clean, tmp_path, capsys, monkeypatch):
    """An interrupt while the motions are being built (before any store) exits 130 with
    the interrupt message, not 'error: aborted'."""
    import rocking.campaign as rc

    def interrupted(*a, **kw):
        raise KeyboardInterrupt

    monkeypatch.setattr(rc, "run", interrupted)
    code, out, err = run_main(capsys, "campaign", "run", clean[0], "--out", tmp_path / "s")
    assert code == 130 and "interrupted before any chunk was kept" in err
    assert "error" not in err and not (tmp_path / "s").exists()
