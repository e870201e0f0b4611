"""The campaign store: a directory that holds a campaign's spec and finished chunks.

::

    STORE/
      spec.toml          the spec as given
      manifest.json      spec hash, package version, seeds, chunk layout, axes
      chunks/chunk-000000.parquet, chunk-000001.parquet, ...

A chunk's Parquet file is written under a temporary name in the same directory and renamed
(:func:`os.replace`, atomic on POSIX): a chunk is finished exactly when its file exists,
so a run killed at any instant leaves only finished chunks (and perhaps temporary files,
ignored, and removed when the next run takes the lock). One run at a time writes to a
store (an exclusive
``flock`` on ``STORE/.lock``, released by the kernel however the run ends).
"""

from __future__ import annotations

import fcntl
import json
import os
import re
from pathlib import Path

import numpy as np
import pandas as pd

from .. import __version__
from ..errors import ParameterError, StoreError
from .spec import CampaignSpec, parse_spec

MANIFEST = "manifest.json"
SPEC = "spec.toml"
CHUNKS = "chunks"
_CHUNK = re.compile(r"^chunk-(\d{6,})\.parquet$")


def chunk_name(k: int) -> str:
    return f"chunk-{k:06d}.parquet"


def manifest_for(spec: CampaignSpec) -> dict:
    """The manifest of a store for ``spec``."""
    from ..analysis.ida import IMS
    from .plan import STREAM
    return {
        "format": 1,
        "name": spec.name,
        "spec_hash": spec.hash,
        "version": __version__,
        "n_sims": spec.n_sims,
        "chunk_size": spec.chunk_size,
        "n_chunks": spec.n_chunks,
        "axes": ["model", "block", "motion", "level", "sample"],
        "shape": list(spec.shape),
        "models": list(spec.models),
        "blocks": [{"name": b.name, "alpha": b.alpha, "p": b.p, "mu": b.mu}
                   for b in spec.blocks],
        "motions": spec.motions,
        "levels": np.asarray(spec.levels, dtype=float).tolist(),
        "im": ({"name": spec.im, "unit": IMS[spec.im][0]} if spec.im else None),
        "samples": spec.samples,
        "thresholds": list(spec.thresholds),
        "duration": spec.duration,
        "seeds": {
            "campaign_seed": spec.seed,
            "simulation": f"SeedSequence({spec.seed}, spawn_key=({STREAM}, sim_id))",
            "stochastic_records": f"SeedSequence({spec.seed}, spawn_key=(2, motion))",
        },
    }


def _write_atomic(path: Path, text: str) -> None:
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    tmp.write_text(text, encoding="utf-8")
    os.replace(tmp, path)


class Store:
    """A campaign store at ``path`` (see the module docstring)."""

    def __init__(self, path):
        self.path = Path(path)
        self._lock = None

    # ------------------------------------------------------------------ opening
    @property
    def manifest_path(self) -> Path:
        return self.path / MANIFEST

    def exists(self) -> bool:
        return self.manifest_path.is_file()

    @property
    def manifest(self) -> dict:
        if not self.exists():
            raise StoreError(f"{self.path} is not a campaign store (no {MANIFEST})")
        try:
            return json.loads(self.manifest_path.read_text(encoding="utf-8"))
        except (OSError, ValueError) as e:
            raise StoreError(f"{self.manifest_path}: unreadable manifest ({e})") from None

    def spec(self) -> CampaignSpec:
        """The store's spec, checked again (``files`` paths as resolved when created)."""
        return parse_spec((self.path / SPEC).read_text(encoding="utf-8"),
                          base_dir=self.manifest.get("spec_dir", "."))

    def prepare(self) -> Store:
        """Make the store's directory (refusing a path that is a file, or a directory that
        holds anything else than a store), ready for :meth:`lock`."""
        p = self.path
        if p.exists() and not p.is_dir():
            raise StoreError(f"--out {p}: exists and is a file, not a store directory")
        if p.is_dir() and not self.exists():
            leftovers = {SPEC, CHUNKS, ".lock"}  # a run killed before its manifest
            other = [e.name for e in p.iterdir() if e.name not in leftovers
                     and not e.name.endswith(".tmp")]
            chunks = p / CHUNKS
            if other or (chunks.is_dir() and any(_CHUNK.match(n) for n in os.listdir(chunks))):
                raise StoreError(f"--out {p}: exists and is not a campaign store: give a new "
                                 "or empty directory")
        (p / CHUNKS).mkdir(parents=True, exist_ok=True)
        return self

    def open_for(self, spec: CampaignSpec) -> Store:
        """Create the store for ``spec``, or check that the existing one was made by the
        same spec and package version (else :class:`~rocking.errors.StoreError`). Call it
        with the lock held (:meth:`prepare`, :meth:`lock`)."""
        if self.exists():
            m = self.manifest
            if m.get("spec_hash") != spec.hash:
                raise StoreError(f"{self.path} holds a different campaign (spec hash "
                                 f"{m.get('spec_hash', '?')[:12]}, this spec {spec.hash[:12]}):"
                                 " use another --out, or delete the store to start again")
            if m.get("version") != __version__:
                raise StoreError(f"{self.path} was written by rocking {m.get('version')}, this "
                                 f"is {__version__}: results could differ; use another --out")
            return self
        _write_atomic(self.path / SPEC, spec.text)
        man = manifest_for(spec)
        man["spec_dir"] = spec.base_dir
        _write_atomic(self.manifest_path, json.dumps(man, indent=1, default=str))
        return self

    def lock(self) -> None:
        """Take the store's write lock (one writing run at a time)."""
        f = open(self.path / ".lock", "w")  # noqa: SIM115 - held until unlock / exit
        try:
            fcntl.flock(f, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            f.close()
            raise StoreError(f"another run is writing to {self.path}") from None
        self._lock = f
        for d in (self.path, self.path / CHUNKS):  # temporary files of a killed run
            for tmp in d.glob(".*.tmp"):
                tmp.unlink(missing_ok=True)

    def unlock(self) -> None:
        if self._lock is not None:
            self._lock.close()
            self._lock = None

    # ------------------------------------------------------------------ chunks
    def chunk_path(self, k: int) -> Path:
        return self.path / CHUNKS / chunk_name(k)

    def done(self) -> set[int]:
        """Indices of the finished chunks."""
        d = self.path / CHUNKS
        if not d.is_dir():
            return set()
        return {int(m.group(1)) for m in map(_CHUNK.match, os.listdir(d)) if m}

    def write_chunk(self, k: int, table: pd.DataFrame) -> None:
        """Write chunk ``k`` atomically (temporary file, then rename)."""
        final = self.chunk_path(k)
        tmp = final.with_name(f".{final.name}.{os.getpid()}.tmp")
        table.to_parquet(tmp, index=False, engine="pyarrow")
        os.replace(tmp, final)

    def files(self) -> list[Path]:
        return [self.chunk_path(k) for k in sorted(self.done())]

    def status(self) -> dict:
        """Counts of done and remaining simulations and chunks."""
        m = self.manifest
        done = self.done()
        cs, n = m["chunk_size"], m["n_sims"]
        sims = sum(min(cs, n - k * cs) for k in done if k < m["n_chunks"])
        return {"name": m["name"], "store": str(self.path), "version": m["version"],
                "spec_hash": m["spec_hash"], "n_sims": n, "sims_done": sims,
                "sims_remaining": n - sims, "n_chunks": m["n_chunks"],
                "chunks_done": len(done), "chunks_remaining": m["n_chunks"] - len(done),
                "complete": len(done) == m["n_chunks"]}


def load(store, lazy: bool | None = None):
    """The rows of a campaign store, sorted by ``sim_id``.

    Returns a pandas DataFrame, or with ``lazy=True`` a lazy ``dask.dataframe`` over the
    chunk files (for stores larger than memory). ``lazy=None`` (default) chooses lazy when
    the files, as columns in memory (about 4 times their size on disk), would exceed half
    of the memory available now.
    """
    s = Store(store)
    s.manifest  # noqa: B018 - raises StoreError if not a store
    files = s.files()
    if lazy is None:
        import psutil
        size = sum(f.stat().st_size for f in files)
        lazy = 4 * size > 0.5 * psutil.virtual_memory().available
    if lazy:
        import dask.dataframe as dd
        if not files:
            raise StoreError(f"{s.path} has no finished chunk yet")
        return dd.read_parquet([str(f) for f in files])
    if not isinstance(lazy, bool):
        raise ParameterError(f"lazy must be True, False or None, got {lazy!r}")
    if not files:
        return pd.DataFrame()
    import pyarrow.parquet as pq
    table = pd.concat([pq.read_table(f).to_pandas() for f in files], ignore_index=True)
    return table.sort_values("sim_id", kind="stable").reset_index(drop=True)
