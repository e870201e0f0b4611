"""The campaign store: a directory that holds a campaign's spec and finished chunks, and
proves their integrity.

::

    STORE/
      spec.toml          the spec as given
      manifest.json      spec hash, package version, seeds, chunk layout, axes (format 2),
                         the site's hazard curve ([hazard]: its points, not re-read)
      chunks/chunk-000000.parquet   the rows of chunk 0
      chunks/chunk-000000.json      its record: rows, sim_id range, bytes, sha256
      quarantine/<time>-<pid>/...   files that failed verification, moved aside by ``run``

**Writing a chunk.** The Parquet bytes are built in memory and hashed (sha256); the file
is written under a temporary name, ``fsync``\\ ed, renamed into place and the directory
``fsync``\\ ed; only then is the chunk's record written the same way
(:mod:`rocking._atomic`). A chunk is finished exactly when its record exists and the file
matches it (size, sha256; the record's rows and ``sim_id`` range are the chunk's in the
manifest's layout, its spec hash and version the store's). A SIGKILL at any instant leaves
finished chunks, perhaps one file without a record (not finished: moved aside and
recomputed by the next run) and temporary files (removed when the next run takes the lock).

**Why one record file per chunk, not an append-only journal.** Each record is written
whole by the same write-sync-rename as every other file, so there is no torn last line to
recover, no journal to rewrite when a chunk is recomputed (its record is simply replaced),
appends need not be atomic (they are not on NFS), and damage to one record costs one chunk
(recomputed), never the index of the whole store. A store has at most a few thousand
chunks, so twice as many small files is cheap.

**Verification** (:meth:`Store.check`, run by ``status``, ``run``, ``load`` and ``verify``)
reads and hashes every chunk. Problems are named by file: ``missing`` (a record without
its file), ``truncated``, ``altered`` (another checksum), ``duplicate`` (the checksum of
another chunk: a chunk copied over this one), ``bad record``, ``unreadable`` (deep check:
the checksum matches but Parquet or its rows disagree), ``unrecorded`` (a chunk file
without a record) and ``stray`` (any other file in ``chunks/``). The first six are damage:
:func:`load` raises :class:`~rocking.errors.StoreError` naming the file. ``run`` moves every
problem file into ``quarantine/`` (nothing is deleted) and recomputes those chunks; a
damaged ``manifest.json`` is rewritten when the store's ``spec.toml`` (or its records)
shows it holds the spec being run.

**Stores of format 1** (before chunk records) are refused by every command with a message:
their files were never checksummed, so nothing can prove them intact.
:meth:`Store.upgrade` (``rocking campaign upgrade STORE``) adopts their chunks that pass
the structural checks (Parquet readable, rows and ``sim_id`` range of the layout) and
moves the others aside; values changed in place before the upgrade cannot be detected.

One run at a time writes to a store (an exclusive ``flock`` on ``STORE/.lock``, released
by the kernel however the run ends). While a run holds it, a chunk file whose record is
not written yet is "in progress", not a problem.
"""

from __future__ import annotations

import fcntl
import hashlib
import io
import json
import math
import os
import re
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from .. import __version__
from .._atomic import atomic_write, fsync_dir, is_temporary, replace
from ..errors import ParameterError, StoreError
from .plan import column_units
from .spec import CampaignSpec, nominal, parse_spec

MANIFEST = "manifest.json"
SPEC = "spec.toml"
CHUNKS = "chunks"
QUARANTINE = "quarantine"
FORMAT = 2
"""Store format: 2 has a record per chunk; 1 (no records) is refused, see upgrade."""
_CHUNK = re.compile(r"^chunk-(\d{6,})\.(parquet|json)$")
_REQUIRED = ("format", "name", "spec_hash", "version", "n_sims", "chunk_size", "n_chunks",
             "axes", "shape", "models", "blocks", "motions", "levels", "im", "samples",
             "thresholds", "duration", "seeds", "spec_dir")
_RECORD_KEYS = ("chunk", "file", "rows", "sim_id_first", "sim_id_last", "bytes", "sha256",
                "spec_hash", "version")
_DAMAGE = ("missing", "truncated", "altered", "duplicate", "bad record", "unreadable")


def chunk_name(k: int) -> str:
    return f"chunk-{k:06d}.parquet"


def record_name(k: int) -> str:
    return f"chunk-{k:06d}.json"


def _axes(spec: CampaignSpec) -> dict:
    """``axes`` and ``shape``: the axes of :attr:`CampaignSpec.axes`, without the floor
    axis when there is no building, without the mitigation axis when there is no
    ``[[mitigation]]`` and without the heading axis when there is no list of headings
    (the five axes of the stores written before any existed)."""
    a = spec.axes
    if spec.building is None:
        del a["floor"]
    if not spec.mitigations:
        del a["mitigation"]
    if not spec.headings:
        del a["heading"]
    return {"axes": list(a), "shape": list(a.values())}


def _mitigations(spec: CampaignSpec) -> dict:
    """The manifest's ``mitigations`` (each entry's name, model and options, SI); nothing
    without ``[[mitigation]]``."""
    if not spec.mitigations:
        return {}
    return {"mitigations": [{"name": m.name, "model": m.model, "options": m.options}
                            for m in spec.mitigations]}


def _building(spec: CampaignSpec) -> dict:
    """The manifest's ``building`` (its keys, modal periods, floors) and ``floors`` (or
    ``height_ratios``); nothing without a building."""
    b = spec.building
    if b is None:
        return {}
    return {"building": {**b["checked"], "name": b["name"], "n_floors": b["n_floors"],
                         "periods": b["periods"]},
            f"{b['axis']}s": list(b["values"])}


def manifest_for(spec: CampaignSpec) -> dict:
    """The manifest of a store for ``spec`` (with a building: ``building`` and ``floors``
    or ``height_ratios``, after ``motions``; with ``[[mitigation]]``: ``mitigations``
    after ``models``, and the ``mitigation`` axis)."""
    from ..analysis.ida import IMS
    from .plan import STREAM
    return {
        "format": FORMAT,
        "name": spec.name,
        "spec_hash": spec.hash,
        "version": __version__,
        "n_sims": spec.n_sims,
        "chunk_size": spec.chunk_size,
        "n_chunks": spec.n_chunks,
        **_axes(spec),
        "models": list(spec.models),
        **_mitigations(spec),
        **({"headings": list(spec.headings)} if spec.headings else {}),
        "blocks": [{"name": b.name, "alpha": nominal(b).alpha, "p": nominal(b).p,
                    "mu": nominal(b).mu} for b in spec.blocks],  # a stack: its top block
        "motions": spec.motions,
        **_building(spec),
        "levels": np.asarray(spec.levels, dtype=float).tolist(),
        "im": ({"name": spec.im, "unit": IMS[spec.im][0]} if spec.im else None),
        "samples": spec.samples,
        "thresholds": list(spec.thresholds),
        "duration": spec.duration,
        "max_free_time": spec.max_free_time,
        "seeds": {
            "campaign_seed": spec.seed,
            "simulation": (f"SeedSequence({spec.seed}, spawn_key=({STREAM}, draw_id)): "
                           "draw_id the flat index over the axes without the mitigation "
                           "and heading axes (common random numbers)"
                           if spec.mitigations or spec.headings else
                           f"SeedSequence({spec.seed}, spawn_key=({STREAM}, sim_id))"),
            "stochastic_records": f"SeedSequence({spec.seed}, spawn_key=(2, motion))",
        },
        "spec_dir": str(spec.base_dir),
        **({"hazard": spec.hazard} if spec.hazard is not None else {}),
    }


def _hazard_label(h) -> str:
    return "none" if not isinstance(h, dict) else repr(str(h.get("label", "?")))


def _other_mitigations(m: dict, spec: CampaignSpec) -> str:
    """``; mitigations ... here, ... in this spec`` when they differ, else ``""``."""
    theirs = m.get("mitigations") or []
    ours = _mitigations(spec).get("mitigations", [])
    if json.loads(json.dumps(theirs, default=str)) == json.loads(json.dumps(ours,
                                                                             default=str)):
        return ""

    def names(x):
        return ", ".join(str(e.get("name")) if isinstance(e, dict) else "?" for e in x) \
            or "none"
    return f"; mitigations: {names(theirs)} in the store, {names(ours)} in this spec" + (
        " (other options)" if names(theirs) == names(ours) else "")


class ManifestError(StoreError):
    """``manifest.json`` is unreadable or lacks keys (the store is damaged)."""


def _whole(x) -> bool:
    return isinstance(x, int) and not isinstance(x, bool)


def _sha256(path: Path) -> tuple[str, int]:
    h = hashlib.sha256()
    n = 0
    with open(path, "rb") as f:
        while block := f.read(1 << 20):
            h.update(block)
            n += len(block)
    return h.hexdigest(), n


@dataclass(frozen=True)
class Problem:
    """A file of the store that fails verification."""

    name: str  # relative to the store, e.g. "chunks/chunk-000003.parquet"
    kind: str  # one of missing, truncated, altered, duplicate, bad record, unreadable,
    #            unrecorded, stray
    detail: str = ""
    chunk: int | None = None
    paths: tuple[Path, ...] = ()  # the files run moves aside

    @property
    def damage(self) -> bool:
        """Finished data lost or changed (``load`` refuses), not just a foreign file."""
        return self.kind in _DAMAGE

    def __str__(self) -> str:
        return f"{self.name}: {self.kind}" + (f" ({self.detail})" if self.detail else "")


@dataclass(frozen=True)
class Check:
    """The result of :meth:`Store.check`."""

    n_chunks: int
    ok: frozenset[int]  # chunks verified against their records
    problems: tuple[Problem, ...]
    running: bool  # a run holds the store's lock
    adopted: int = 0  # chunks recorded by upgrade (values not proven by a checksum)

    @property
    def damage(self) -> tuple[Problem, ...]:
        return tuple(p for p in self.problems if p.damage)


class Store:
    """A campaign store at ``path`` (see the module docstring).

    Examples
    --------
    >>> from pathlib import Path
    >>> from rocking import campaign
    >>> from rocking.campaign import EXAMPLE_SPEC
    >>> _ = Path("pulses.toml").write_text(EXAMPLE_SPEC)
    >>> from rocking.campaign import Store
    >>> store = Store("pulses_store")
    >>> store.exists()
    False
    >>> _ = campaign.run("pulses.toml", "pulses_store", progress=False)
    >>> store.exists(), store.done(), store.spec().n_sims
    (True, {0, 1}, 4)
    >>> store.read_chunk(1).sim_id.tolist()
    [2, 3]
    """

    def __init__(self, path):
        self.path = Path(path)
        self._lock = None
        self._manifest: dict | None = None
        self._q: Path | None = None  # quarantine folder of this object

    # ------------------------------------------------------------------ opening
    @property
    def manifest_path(self) -> Path:
        return self.path / MANIFEST

    def exists(self) -> bool:
        """Whether the store's ``manifest.json`` exists (written when a run starts).

        Examples
        --------
        >>> from rocking import campaign
        >>> from rocking.campaign import EXAMPLE_SPEC, Store, parse_spec
        >>> store = Store("pulses_store")
        >>> store.exists()
        False
        >>> _ = campaign.run(parse_spec(EXAMPLE_SPEC), "pulses_store", progress=False)
        >>> store.exists(), store.manifest_path.name
        (True, 'manifest.json')
        """
        return self.manifest_path.is_file()

    def _read_manifest(self) -> dict:
        if not self.exists():
            raise StoreError(f"{self.path} is not a campaign store (no {MANIFEST})")
        where = f"{self.manifest_path}"
        try:
            m = json.loads(self.manifest_path.read_text(encoding="utf-8"))
        except (OSError, ValueError) as e:
            raise ManifestError(f"{where}: unreadable manifest ({str(e)[:80]})") from None
        if not isinstance(m, dict):
            raise ManifestError(f"{where}: damaged manifest (not a JSON object)")
        return m

    @property
    def manifest(self) -> dict:
        """The checked manifest (:class:`ManifestError` if damaged, a
        :class:`~rocking.errors.StoreError` for a store of another format)."""
        if self._manifest is None:
            m = self._read_manifest()
            where = f"{self.manifest_path}"
            if m.get("format") == 1:
                raise StoreError(
                    f"{self.path} is a store of format 1, written before chunk records: its "
                    f"chunks cannot be proven intact. Run `rocking campaign upgrade "
                    f"{self.path}` to adopt those that pass the structural checks, or run "
                    "the spec into a new --out")
            missing = [k for k in _REQUIRED if k not in m]
            if missing:
                raise ManifestError(f"{where}: damaged manifest, missing "
                                    f"key{'s' * (len(missing) > 1)} {', '.join(missing)}")
            if m["format"] != FORMAT:
                raise StoreError(f"{self.path}: store format {m['format']!r}, this rocking "
                                 f"{__version__} reads format {FORMAT}")
            n, cs, nc = m["n_sims"], m["chunk_size"], m["n_chunks"]
            if not (_whole(n) and _whole(cs) and _whole(nc) and n >= 0 and cs >= 1
                    and nc == math.ceil(n / cs)):
                raise ManifestError(f"{where}: damaged manifest (n_sims {n!r}, chunk_size "
                                    f"{cs!r}, n_chunks {nc!r} disagree)")
            if not (isinstance(m["spec_hash"], str) and len(m["spec_hash"]) == 64):
                raise ManifestError(f"{where}: damaged manifest (spec_hash "
                                    f"{m['spec_hash']!r})")
            self._manifest = m
        return self._manifest

    def spec(self) -> CampaignSpec:
        """The store's spec, checked again (``files`` paths as resolved when created).

        Examples
        --------
        >>> from rocking import campaign
        >>> from rocking.campaign import EXAMPLE_SPEC, Store, parse_spec
        >>> _ = campaign.run(parse_spec(EXAMPLE_SPEC), "pulses_store", progress=False)
        >>> store = Store("pulses_store")
        >>> store.spec().hash == parse_spec(EXAMPLE_SPEC).hash, store.spec().n_sims
        (True, 4)
        """
        return parse_spec((self.path / SPEC).read_text(encoding="utf-8"),
                          base_dir=self.manifest.get("spec_dir", "."))

    def prepare(self) -> Store:
        """Make the store's directory (refusing a path that is a file, or a directory that
        holds anything else than a store), ready for :meth:`lock`.

        Examples
        --------
        >>> from pathlib import Path
        >>> from rocking.campaign import Store
        >>> Store("new_store").prepare().path.is_dir()
        True
        >>> _ = Path("notes.txt").write_text("not a store")
        >>> Store("notes.txt").prepare()
        Traceback (most recent call last):
        ...
        rocking.errors.StoreError: --out notes.txt: exists and is a file, not a store directory
        """
        p = self.path
        if p.exists() and not p.is_dir():
            raise StoreError(f"--out {p}: exists and is a file, not a store directory")
        if p.is_dir() and not self.exists():
            leftovers = {SPEC, CHUNKS, ".lock", QUARANTINE}  # a run killed before its manifest
            other = [e.name for e in p.iterdir() if e.name not in leftovers
                     and not is_temporary(e.name) and not e.name.endswith(".tmp")]
            chunks = p / CHUNKS
            if other or (chunks.is_dir() and any(_CHUNK.match(n) for n in os.listdir(chunks))):
                raise StoreError(f"--out {p}: exists and is not a campaign store: give a new "
                                 "or empty directory")
        p.mkdir(parents=True, exist_ok=True)
        return self

    def open_for(self, spec: CampaignSpec, log: Callable | None = None) -> Store:
        """Create the store for ``spec``, or check that the existing one was made by the
        same spec and package version (else :class:`~rocking.errors.StoreError`); a damaged
        manifest is rewritten if the store's ``spec.toml`` or records show it holds
        ``spec``. Call it with the lock held (:meth:`prepare`, :meth:`lock`).

        Examples
        --------
        What ``run`` does first; another spec on the same store is refused:

        >>> from rocking.campaign import EXAMPLE_SPEC, Store, parse_spec
        >>> store = Store("pulses_store").prepare()
        >>> store.lock()
        >>> sorted(p.name for p in store.open_for(parse_spec(EXAMPLE_SPEC)).path.iterdir())
        ['.lock', 'chunks', 'manifest.json', 'spec.toml']
        >>> store.open_for(parse_spec(EXAMPLE_SPEC.replace("seed = 1", "seed = 2")))
        Traceback (most recent call last):
        ...
        rocking.errors.StoreError: pulses_store holds a different campaign (spec hash ...
        >>> store.unlock()
        """
        self.path.mkdir(parents=True, exist_ok=True)
        self._manifest = None
        if self.exists():
            try:
                m = self.manifest
            except ManifestError as e:
                self._rebuild_manifest(spec, str(e), log or (lambda msg: None))
                (self.path / CHUNKS).mkdir(exist_ok=True)
                return self
            if m.get("spec_hash") != spec.hash:
                raise StoreError(f"{self.path} holds a different campaign (spec hash "
                                 f"{str(m.get('spec_hash', '?'))[:12]}, this spec "
                                 f"{spec.hash[:12]}{_other_mitigations(m, spec)}): use "
                                 "another --out, or delete the store to start again")
            if m.get("version") != __version__:
                raise StoreError(f"{self.path} was written by rocking {m.get('version')}, this "
                                 f"is {__version__}: results could differ; use another --out")
            self._update_hazard(spec, log or (lambda msg: None))
        else:
            atomic_write(self.path / SPEC, spec.text)
            atomic_write(self.manifest_path, json.dumps(manifest_for(spec), indent=1,
                                                        default=str))
        (self.path / CHUNKS).mkdir(exist_ok=True)  # after the manifest: chunks/ implies it
        return self

    def _update_hazard(self, spec: CampaignSpec, log: Callable) -> None:
        """A store resumed with another ``[hazard]`` (or none): the hazard changes no run
        (it is not in the spec hash), so the manifest's ``hazard`` and ``spec.toml`` take
        the spec's, said in one line; the chunks stay."""
        m = self.manifest
        ours = json.loads(json.dumps(spec.hazard, default=str))
        if m.get("hazard") == ours:
            return
        new = {k: v for k, v in m.items() if k != "hazard"}
        if ours is not None:
            new["hazard"] = ours
        atomic_write(self.path / SPEC, spec.text)
        atomic_write(self.manifest_path, json.dumps(new, indent=1, default=str))
        self._manifest = None
        log(f"[hazard] changed: {_hazard_label(m.get('hazard'))} in the store, now "
            f"{_hazard_label(ours)}; the runs do not depend on it (kept), the report will "
            "use the new one")

    def _rebuild_manifest(self, spec: CampaignSpec, why: str, log: Callable) -> None:
        """Rewrite a damaged manifest from ``spec`` if the store shows it holds ``spec``."""
        evidence = None
        try:
            stored = parse_spec((self.path / SPEC).read_text(encoding="utf-8"),
                                base_dir=spec.base_dir)
            if stored.hash == spec.hash:
                evidence = f"{SPEC} has the same hash"
        except (OSError, ValueError):
            pass
        recs = [r for r in (self._record(k) for k in self._chunk_indices()) if
                isinstance(r, dict)]
        if any(r.get("spec_hash") != spec.hash or r.get("version") != __version__
               for r in recs):
            evidence = None  # chunks of another spec or version: never adopt them
        elif evidence is None and recs:
            evidence = f"its {len(recs)} chunk records name this spec"
        if evidence is None:
            raise StoreError(f"{why}; nothing in {self.path} shows it holds this spec "
                             "(and version): use another --out")
        q = self._move_aside(self.manifest_path).parent
        sp = self.path / SPEC
        if not sp.is_file() or sp.read_text(encoding="utf-8", errors="replace") != spec.text:
            if sp.exists():
                self._move_aside(sp)
            atomic_write(sp, spec.text)
        atomic_write(self.manifest_path, json.dumps(manifest_for(spec), indent=1, default=str))
        self._manifest = None
        log(f"{MANIFEST}: {why.split(': ', 1)[-1]}: rewritten from the spec ({evidence}); "
            f"the old one moved to {q.relative_to(self.path)}/")

    def lock(self) -> None:
        """Take the store's write lock (one writing run at a time); StoreError if another
        run (or another :class:`Store` object) holds it. Also removes the temporary files
        of a killed run.

        Examples
        --------
        >>> from rocking.campaign import Store
        >>> store = Store("pulses_store").prepare()
        >>> store.lock()
        >>> Store("pulses_store").lock()
        Traceback (most recent call last):
        ...
        rocking.errors.StoreError: another run is writing to pulses_store
        >>> store.unlock()
        """
        f = open(self.path / ".lock", "w")  # noqa: SIM115 - held until unlock / exit
        try:
            fcntl.flock(f, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            f.close()
            raise StoreError(f"another run is writing to {self.path}") from None
        self._lock = f
        for d in (self.path, self.path / CHUNKS):  # temporary files of a killed run
            for tmp in d.iterdir() if d.is_dir() else ():  # (not a report's folder)
                if (is_temporary(tmp.name) or (tmp.name.startswith(".")
                                               and tmp.name.endswith(".tmp"))) \
                        and tmp.is_file():
                    tmp.unlink(missing_ok=True)

    def unlock(self) -> None:
        """Release the write lock taken by :meth:`lock` (nothing if not held).

        Examples
        --------
        >>> from rocking.campaign import Store
        >>> store = Store("pulses_store").prepare()
        >>> store.lock()
        >>> Store("pulses_store").running()
        True
        >>> store.unlock()
        >>> Store("pulses_store").running()
        False
        """
        if self._lock is not None:
            self._lock.close()
            self._lock = None

    def running(self) -> bool:
        """Whether another run (process, or open handle) holds the write lock; False
        when this object holds it (it is the run).

        Examples
        --------
        >>> from rocking.campaign import Store
        >>> store = Store("pulses_store").prepare()
        >>> store.running()
        False
        >>> store.lock()
        >>> store.running(), Store("pulses_store").running()
        (False, True)
        >>> store.unlock()
        """
        if self._lock is not None:
            return False
        try:
            fd = os.open(self.path / ".lock", os.O_RDONLY)
        except OSError:
            return False
        try:
            fcntl.flock(fd, fcntl.LOCK_SH | fcntl.LOCK_NB)
            return False
        except OSError:
            return True
        finally:
            os.close(fd)  # releases the shared lock

    # ------------------------------------------------------------------ chunks
    def chunk_path(self, k: int) -> Path:
        """The Parquet file of chunk ``k`` (whether or not it exists).

        Examples
        --------
        >>> from rocking import campaign
        >>> from rocking.campaign import EXAMPLE_SPEC, Store, parse_spec
        >>> _ = campaign.run(parse_spec(EXAMPLE_SPEC), "pulses_store", progress=False)
        >>> store = Store("pulses_store")
        >>> store.chunk_path(1).as_posix()
        'pulses_store/chunks/chunk-000001.parquet'
        >>> import pandas as pd
        >>> pd.read_parquet(store.chunk_path(1)).sim_id.tolist()
        [2, 3]
        """
        return self.path / CHUNKS / chunk_name(k)

    def record_path(self, k: int) -> Path:
        """The record (JSON) of chunk ``k``: its rows, ``sim_id`` range, bytes and sha256.

        Examples
        --------
        The record's checksum is that of the chunk's file:

        >>> import hashlib, json
        >>> from rocking import campaign
        >>> from rocking.campaign import EXAMPLE_SPEC, Store, parse_spec
        >>> _ = campaign.run(parse_spec(EXAMPLE_SPEC), "pulses_store", progress=False)
        >>> store = Store("pulses_store")
        >>> rec = json.loads(store.record_path(1).read_text())
        >>> rec["rows"], rec["sim_id_first"], rec["sim_id_last"]
        (2, 2, 3)
        >>> rec["sha256"] == hashlib.sha256(store.chunk_path(1).read_bytes()).hexdigest()
        True
        """
        return self.path / CHUNKS / record_name(k)

    def chunk_range(self, k: int) -> tuple[int, int]:
        """``(start, stop)`` sim ids of chunk ``k`` in the manifest's layout.

        Examples
        --------
        The same layout as the campaign's (:meth:`Campaign.chunk_range`):

        >>> from rocking.campaign import Campaign
        >>> from rocking import campaign
        >>> from rocking.campaign import EXAMPLE_SPEC, Store, parse_spec
        >>> _ = campaign.run(parse_spec(EXAMPLE_SPEC), "pulses_store", progress=False)
        >>> store = Store("pulses_store")
        >>> [store.chunk_range(k) for k in range(2)]
        [(0, 2), (2, 4)]
        >>> store.chunk_range(1) == Campaign(store.spec()).chunk_range(1)
        True
        """
        m = self.manifest
        cs = m["chunk_size"]
        return k * cs, min((k + 1) * cs, m["n_sims"])

    def _chunk_indices(self) -> set[int]:
        d = self.path / CHUNKS
        return ({int(m.group(1)) for m in map(_CHUNK.match, os.listdir(d)) if m}
                if d.is_dir() else set())

    def _record(self, k: int):
        """The record of chunk ``k`` as a dict, None if absent, or why it is bad (str)."""
        p = self.record_path(k)
        try:
            r = json.loads(p.read_bytes())
        except FileNotFoundError:
            return None
        except (OSError, ValueError) as e:
            return f"unreadable: {str(e)[:60]}"
        if not isinstance(r, dict):
            return "not a JSON object"
        missing = [key for key in _RECORD_KEYS if key not in r]
        if missing:
            return f"missing {', '.join(missing)}"
        return r

    def _record_problem(self, k: int, r: dict) -> str | None:
        """Why record ``r`` cannot be chunk ``k``'s of this store, or None."""
        m = self.manifest
        a, b = self.chunk_range(k)
        if r["chunk"] != k or r["file"] != chunk_name(k):
            return f"the record of chunk {r['chunk']!r}"
        if r["spec_hash"] != m["spec_hash"] or r["version"] != m["version"]:
            return "written for another spec or version"
        if (r["rows"], r["sim_id_first"], r["sim_id_last"]) != (b - a, a, b - 1):
            return (f"says {r['rows']!r} rows, sim_ids {r['sim_id_first']!r}-"
                    f"{r['sim_id_last']!r}; the layout has {b - a}, {a}-{b - 1}")
        if not (_whole(r["bytes"]) and isinstance(r["sha256"], str)):
            return "bytes or sha256 malformed"
        return None

    def _scan(self, nc: int) -> tuple[set, dict, list]:
        """The chunk files and records in ``chunks/`` (records read), and its stray files."""
        d = self.path / CHUNKS
        problems: list[Problem] = []
        files, records = set(), {}
        for name in sorted(os.listdir(d)) if d.is_dir() else []:
            mt = _CHUNK.match(name)
            if is_temporary(name) or (name.startswith(".") and name.endswith(".tmp")):
                continue  # a temporary file of a run (removed by the next one)
            k = int(mt.group(1)) if mt else None
            if k is None or k >= nc or name != (chunk_name(k) if mt.group(2) == "parquet"
                                                else record_name(k)):
                why = (f"chunk index beyond the campaign's {nc} chunks" if k is not None
                       and k >= nc else "not a file of this store")
                problems.append(Problem(f"{CHUNKS}/{name}", "stray", why, None, (d / name,)))
            elif mt.group(2) == "parquet":
                files.add(k)
            else:
                records[k] = self._record(k)
        return files, records, problems

    def _checksum_problem(self, k: int, r: dict, by_sha: dict, paths) -> Problem | None:
        """Chunk ``k``'s file against its record ``r`` (sha256, size), or None if it
        matches."""
        cname = f"{CHUNKS}/{chunk_name(k)}"
        try:
            sha, size = _sha256(self.chunk_path(k))
        except OSError as e:
            return Problem(cname, "unreadable", e.strerror or str(e), k, paths)
        if sha == r["sha256"]:
            return None
        j = by_sha.get(sha)
        if j is not None and j != k:
            a, b = self.chunk_range(j)
            c, e = self.chunk_range(k)
            return Problem(cname, "duplicate", f"a copy of {chunk_name(j)}: sim_ids "
                                               f"{a}-{b - 1} twice, {c}-{e - 1} missing", k,
                           paths)
        if size < r["bytes"]:
            return Problem(cname, "truncated", f"{size} of {r['bytes']} bytes", k, paths)
        return Problem(cname, "altered", "sha256 differs from its record"
                       + (f", {size} of {r['bytes']} bytes" if size != r["bytes"] else ""),
                       k, paths)

    def check(self, deep: bool = False) -> Check:
        """Verify every chunk against its record (size and sha256; with ``deep`` also
        read it: Parquet, rows, ``sim_id`` range). Read-only.

        Examples
        --------
        A chunk file cut short is found (and named):

        >>> from rocking import campaign
        >>> from rocking.campaign import EXAMPLE_SPEC, Store, parse_spec
        >>> _ = campaign.run(parse_spec(EXAMPLE_SPEC), "pulses_store", progress=False)
        >>> store = Store("pulses_store")
        >>> _ = store.chunk_path(1).write_bytes(store.chunk_path(1).read_bytes()[:100])
        >>> c = store.check()
        >>> sorted(c.ok), [(p.name, p.kind) for p in c.problems]
        ([0], [('chunks/chunk-000001.parquet', 'truncated')])
        """
        nc = self.manifest["n_chunks"]
        running = self.running()
        files, records, problems = self._scan(nc)
        by_sha = {r["sha256"]: k for k, r in records.items() if isinstance(r, dict)
                  and isinstance(r.get("sha256"), str)}
        ok, adopted = set(), 0
        for k in sorted(files | set(records)):
            r, cname = records.get(k), f"{CHUNKS}/{chunk_name(k)}"
            paths = ((self.record_path(k),) if k in records else ()) + (
                (self.chunk_path(k),) if k in files else ())  # the record moves first
            if r is None:
                if not running:  # else: in progress, its record comes next
                    problems.append(Problem(cname, "unrecorded", "no record: not finished",
                                            k, paths))
                continue
            why = r if isinstance(r, str) else self._record_problem(k, r)
            if why is not None:
                problems.append(Problem(f"{CHUNKS}/{record_name(k)}", "bad record", why,
                                        k, paths))
                continue
            if k not in files:
                problems.append(Problem(cname, "missing", f"its record says {r['rows']} rows, "
                                        f"sim_ids {r['sim_id_first']}-{r['sim_id_last']}",
                                        k, paths))
                continue
            bad = self._checksum_problem(k, r, by_sha, paths)
            if bad is not None:
                problems.append(bad)
                continue
            if deep:
                why = self._read_problem(k, r)
                if why is not None:
                    problems.append(Problem(cname, "unreadable", why, k, paths))
                    continue
            ok.add(k)
            adopted += bool(r.get("adopted"))
        return Check(nc, frozenset(ok), tuple(sorted(problems, key=lambda p: p.name)),
                     running, adopted)

    def _read_problem(self, k: int, r: dict) -> str | None:
        return self._read(k, r)[1]

    def _read(self, k: int, r: dict) -> tuple[pd.DataFrame | None, str | None]:
        """``(rows, None)`` of chunk ``k`` if they agree with record ``r`` (rows,
        ``sim_id`` range), else ``(None, why)``."""
        import pyarrow as pa
        import pyarrow.parquet as pq
        try:
            t = pq.read_table(self.chunk_path(k)).to_pandas()
        except (pa.ArrowException, OSError, ValueError) as e:
            return None, f"unreadable Parquet: {str(e).splitlines()[0][:120]}"
        if "sim_id" not in t.columns:
            return None, "no sim_id column"
        ids = t["sim_id"].to_numpy()
        a, b = r["sim_id_first"], r["sim_id_last"]
        if ids.shape != (b - a + 1,) or not np.array_equal(ids, np.arange(a, b + 1)):
            return None, (f"{len(ids)} rows that are not sim_ids {a}-{b} in order, as its "
                          "record says")
        return t, None

    def read_chunk(self, k: int) -> pd.DataFrame:
        """The rows of chunk ``k``, checked against its record (rows, ``sim_id`` range);
        :class:`~rocking.errors.StoreError` naming the file otherwise.

        Examples
        --------
        The stored rows are those of the campaign's run of the chunk, bit for bit:

        >>> from rocking.campaign import Campaign
        >>> from rocking import campaign
        >>> from rocking.campaign import EXAMPLE_SPEC, Store, parse_spec
        >>> _ = campaign.run(parse_spec(EXAMPLE_SPEC), "pulses_store", progress=False)
        >>> store = Store("pulses_store")
        >>> rows = store.read_chunk(1)
        >>> rows.sim_id.tolist(), rows.equals(Campaign(store.spec()).run_chunk(1))
        ([2, 3], True)
        """
        r = self._record(k)
        name = f"{self.path / CHUNKS / chunk_name(k)}"
        if not isinstance(r, dict):
            raise StoreError(f"{name}: no valid record ({r or 'none'})")
        t, why = self._read(k, r)
        if why is not None:
            raise StoreError(f"{name}: {why}")
        return t

    def done(self) -> set[int]:
        """Indices of the finished chunks (verified against their records); none before
        the manifest is written.

        Examples
        --------
        >>> from rocking import campaign
        >>> from rocking.campaign import EXAMPLE_SPEC, Store, parse_spec
        >>> _ = campaign.run(parse_spec(EXAMPLE_SPEC), "pulses_store", progress=False)
        >>> store = Store("pulses_store")
        >>> store.done()
        {0, 1}
        >>> store.chunk_path(0).unlink()
        >>> store.done()
        {1}
        """
        return set(self.check().ok) if self.exists() else set()

    def write_chunk(self, k: int, table: pd.DataFrame) -> None:
        """Write chunk ``k`` (its rows, in ``sim_id`` order): the Parquet file, synced and
        renamed into place, then its record (see the module docstring).

        Examples
        --------
        A run's steps by hand: lock, open for the spec, write chunk 0, unlock:

        >>> from rocking.campaign import EXAMPLE_SPEC, Campaign, Store, parse_spec
        >>> spec = parse_spec(EXAMPLE_SPEC)
        >>> store = Store("pulses_store").prepare()
        >>> store.lock()
        >>> store.open_for(spec).write_chunk(0, Campaign(spec).run_chunk(0))
        >>> store.unlock()
        >>> store.done(), store.status()["sims_done"]
        ({0}, 2)
        """
        a, b = self.chunk_range(k)
        ids = table["sim_id"].to_numpy() if "sim_id" in table.columns else None
        if ids is None or ids.shape != (b - a,) or not np.array_equal(ids, np.arange(a, b)):
            raise StoreError(f"chunk {k}: the table is not sim_ids {a}-{b - 1} in order")
        import pyarrow.parquet as pq

        buf = io.BytesIO()
        pq.write_table(arrow_table(table), buf)
        data = buf.getvalue()
        self.record_path(k).unlink(missing_ok=True)  # a previous record of this chunk
        atomic_write(self.chunk_path(k), data)
        m = self.manifest
        rec = {"chunk": k, "file": chunk_name(k), "rows": b - a, "sim_id_first": a,
               "sim_id_last": b - 1, "bytes": len(data),
               "sha256": hashlib.sha256(data).hexdigest(), "spec_hash": m["spec_hash"],
               "version": m["version"],
               "written": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())}
        atomic_write(self.record_path(k), json.dumps(rec, indent=1))

    def files(self) -> list[Path]:
        """The files of the finished chunks, in order.

        Examples
        --------
        >>> import pandas as pd
        >>> from rocking import campaign
        >>> from rocking.campaign import EXAMPLE_SPEC, Store, parse_spec
        >>> _ = campaign.run(parse_spec(EXAMPLE_SPEC), "pulses_store", progress=False)
        >>> store = Store("pulses_store")
        >>> [f.name for f in store.files()]
        ['chunk-000000.parquet', 'chunk-000001.parquet']
        >>> sum(len(pd.read_parquet(f)) for f in store.files()) == store.spec().n_sims
        True
        """
        return [self.chunk_path(k) for k in sorted(self.done())]

    # ------------------------------------------------------------------ repair
    def _quarantine_dir(self) -> Path:
        """This object's folder in ``quarantine/``: made once, a name never used before."""
        if self._q is None:
            stamp = f"{time.strftime('%Y%m%dT%H%M%S', time.gmtime())}-{os.getpid()}"
            (self.path / QUARANTINE).mkdir(exist_ok=True)
            i = 0
            while True:
                q = self.path / QUARANTINE / (stamp + (f"-{i}" if i else ""))
                try:
                    q.mkdir()
                    break
                except FileExistsError:
                    i += 1
            fsync_dir(q.parent)
            fsync_dir(self.path)
            self._q = q
        return self._q

    def _move_aside(self, f: Path) -> Path:
        """Move ``f`` into the quarantine folder, never over another file."""
        q = self._quarantine_dir()
        dst, i = q / f.name, 1
        while dst.exists():
            dst, i = q / f"{f.name}.{i}", i + 1
        replace(f, dst)
        return dst

    def repair(self, log: Callable = print) -> list[Problem]:
        """Move every problem file into ``quarantine/`` (never deleted), saying so with
        ``log``; the chunks concerned are then not done, for ``run`` to recompute. Call it
        with the lock held.

        Examples
        --------
        A damaged chunk is moved aside (with its record), then recomputed by the next run:

        >>> from rocking import campaign
        >>> from rocking.campaign import EXAMPLE_SPEC, Store, parse_spec
        >>> _ = campaign.run(parse_spec(EXAMPLE_SPEC), "pulses_store", progress=False)
        >>> store = Store("pulses_store")
        >>> _ = store.chunk_path(1).write_bytes(b"damaged")
        >>> store.lock()
        >>> [(p.name, p.kind) for p in store.repair(log=lambda msg: None)]
        [('chunks/chunk-000001.parquet', 'truncated')]
        >>> store.unlock()
        >>> sorted(p.name for p in store.path.glob("quarantine/*/*")), store.done()
        (['chunk-000001.json', 'chunk-000001.parquet'], {0})
        >>> campaign.run(store.spec(), "pulses_store", progress=False)["complete"]
        True
        """
        problems = list(self.check().problems)
        if not problems:
            return []
        q = self._quarantine_dir()
        for p in problems:
            moved = []
            for f in p.paths:
                if f.exists():
                    moved.append(self._move_aside(f).name)
            what = ("to be recomputed" if p.chunk is not None else "not part of the campaign")
            log(f"{p}: moved to {q.relative_to(self.path)}/ ({', '.join(moved)}); {what}")
        return problems

    def upgrade(self, log: Callable = print) -> dict:
        """Upgrade a store of format 1 (no chunk records): record every chunk that reads
        as Parquet with the rows and ``sim_id`` range of its place in the layout (a
        checksum taken now: earlier changes cannot be detected), move the others into
        ``quarantine/``, and write the manifest as format 2.

        Examples
        --------
        A store made format 1 (no records), refused, then upgraded:

        >>> import json
        >>> from rocking import campaign
        >>> from rocking.campaign import EXAMPLE_SPEC, Store, parse_spec
        >>> _ = campaign.run(parse_spec(EXAMPLE_SPEC), "pulses_store", progress=False)
        >>> store = Store("pulses_store")
        >>> m = json.loads(store.manifest_path.read_text())
        >>> _ = store.manifest_path.write_text(json.dumps(dict(m, format=1)))
        >>> for k in (0, 1):
        ...     store.record_path(k).unlink()
        >>> Store("pulses_store").done()
        Traceback (most recent call last):
        ...
        rocking.errors.StoreError: pulses_store is a store of format 1, written before ...
        >>> Store("pulses_store").upgrade(log=print)
        {'adopted': 2, 'quarantined': []}
        >>> Store("pulses_store").check().adopted
        2
        """
        m = self._read_manifest()
        if m.get("format") != 1:
            raise StoreError(f"{self.path}: format {m.get('format')!r}: only a store of "
                             "format 1 needs an upgrade")
        missing = [k for k in _REQUIRED if k not in m and k not in ("spec_dir", "format")]
        if missing:
            raise ManifestError(f"{self.manifest_path}: damaged manifest, missing "
                                f"{', '.join(missing)}")
        self.prepare()
        self.lock()
        try:
            new = dict(m, format=FORMAT)
            new.setdefault("spec_dir", ".")
            self._manifest = new  # for the layout (written at the end)
            d = self.path / CHUNKS
            adopted, moved = [], []
            q = None
            for name in sorted(os.listdir(d)) if d.is_dir() else []:
                if is_temporary(name):
                    continue
                mt = _CHUNK.match(name)
                k = int(mt.group(1)) if mt and mt.group(2) == "parquet" else None
                why = None
                if k is None or k >= m["n_chunks"] or name != chunk_name(k):
                    why = "stray"
                else:
                    a, b = self.chunk_range(k)
                    rec = {"chunk": k, "file": name, "rows": b - a, "sim_id_first": a,
                           "sim_id_last": b - 1}
                    why = self._read(k, rec)[1]
                if why is None:
                    sha, size = _sha256(d / name)
                    rec.update(bytes=size, sha256=sha, spec_hash=m["spec_hash"],
                               version=m["version"], adopted="upgrade from format 1")
                    atomic_write(self.record_path(k), json.dumps(rec, indent=1))
                    adopted.append(k)
                else:
                    q = self._move_aside(d / name).parent
                    moved.append(name)
                    log(f"{CHUNKS}/{name}: {why}: moved to {q.relative_to(self.path)}/")
            atomic_write(self.manifest_path, json.dumps(new, indent=1, default=str))
            fsync_dir(d)
        finally:
            self.unlock()
            self._manifest = None
        return {"adopted": len(adopted), "quarantined": moved}

    # ------------------------------------------------------------------ summaries
    def status(self, check: Check | None = None) -> dict:
        """Counts of done (verified) and remaining simulations and chunks, and the
        problems found (as text).

        Examples
        --------
        >>> from rocking import campaign
        >>> from rocking.campaign import EXAMPLE_SPEC, Store, parse_spec
        >>> _ = campaign.run(parse_spec(EXAMPLE_SPEC), "pulses_store", progress=False)
        >>> store = Store("pulses_store")
        >>> store.chunk_path(1).unlink()
        >>> s = store.status()
        >>> s["sims_done"], s["sims_remaining"], s["complete"]
        (2, 2, False)
        >>> s["problems"]
        ['chunks/chunk-000001.parquet: missing (its record says 2 rows, sim_ids 2-3)']
        """
        m = self.manifest
        c = check if check is not None else self.check()
        sims = sum(b - a for a, b in map(self.chunk_range, c.ok))
        n, nc = m["n_sims"], m["n_chunks"]
        return {"name": m["name"], "store": str(self.path), "version": m["version"],
                "spec_hash": m["spec_hash"], "n_sims": n, "sims_done": sims,
                "sims_remaining": n - sims, "n_chunks": nc, "chunks_done": len(c.ok),
                "chunks_remaining": nc - len(c.ok), "complete": len(c.ok) == nc,
                "problems": [str(p) for p in c.problems], "running": c.running}


def _damage_error(s: Store, c: Check) -> StoreError:
    first = c.damage[0]
    more = (f"; {len(c.problems) - 1} more problems, see `rocking campaign verify {s.path}`"
            if len(c.problems) > 1 else "")
    return StoreError(f"{s.path}: {first}{more}; `rocking campaign run SPEC --out {s.path}` "
                      "moves the bad files aside and recomputes them")


def load(store, lazy: bool | None = None):
    """The rows of a campaign store, sorted by ``sim_id``, every chunk verified against its
    record (:class:`~rocking.errors.StoreError` naming the first damaged file otherwise).

    Returns a pandas DataFrame, or with ``lazy=True`` a lazy ``dask.dataframe`` over the
    chunk files (for stores larger than memory). ``lazy=None`` (default) chooses lazy when
    the files, as columns in memory (about 4 times their size on disk), would exceed half
    of the memory available now.

    Examples
    --------
    >>> from pathlib import Path
    >>> from rocking import campaign
    >>> from rocking.campaign import EXAMPLE_SPEC
    >>> _ = Path("pulses.toml").write_text(EXAMPLE_SPEC)
    >>> _ = campaign.run("pulses.toml", "pulses_store", progress=False)
    >>> rows = campaign.load("pulses_store")
    >>> rows[["sim_id", "pga", "overturned"]]
       sim_id  pga  overturned
    0       0  1.0       False
    1       1  1.5       False
    2       2  2.0       False
    3       3  3.0        True
    """
    if lazy is not None and not isinstance(lazy, bool):
        raise ParameterError(f"lazy must be True, False or None, got {lazy!r}")
    s = Store(store)
    c = s.check()
    if c.damage:
        raise _damage_error(s, c)
    done = sorted(c.ok)
    files = [s.chunk_path(k) for k in done]
    if lazy is None:
        import psutil
        size = sum(f.stat().st_size for f in files)
        lazy = 4 * size > 0.5 * psutil.virtual_memory().available
    if lazy:
        import dask.dataframe as dd
        if not files:
            raise StoreError(f"{s.path} has no finished chunk yet")
        return dd.read_parquet([str(f) for f in files])
    if not files:
        return pd.DataFrame()
    table = pd.concat([s.read_chunk(k) for k in done], ignore_index=True)
    return table.sort_values("sim_id", kind="stable").reset_index(drop=True)


def result_schema(table: pd.DataFrame, models=None):
    """The Parquet schema of a chunk's ``table``, written explicitly: each column's type,
    and its unit (``b"unit"``, SI; ``b""``: none) in the field's metadata, from the
    models' declared outputs and the campaign's inputs (:func:`.plan.column_units`).
    ``models``: the registry names (default: the table's ``model`` column).

    Examples
    --------
    >>> from rocking.campaign import EXAMPLE_SPEC, Campaign, parse_spec
    >>> from rocking.campaign.store import result_schema
    >>> rows = Campaign(parse_spec(EXAMPLE_SPEC)).run_chunk(0)
    >>> schema = result_schema(rows)
    >>> schema.field("max_abs_theta").metadata[b"unit"], schema.field("pga").metadata[b"unit"]
    (b'rad', b'm/s^2')
    >>> str(schema.field("overturned").type)
    'bool'
    """
    import pyarrow as pa

    if models is None:
        models = table["model"].unique().tolist() if "model" in table.columns else []
    units = column_units(models)
    base = pa.Schema.from_pandas(table, preserve_index=False)
    fields = [f.with_metadata({"unit": units[f.name]}) if f.name in units else f
              for f in base]
    return pa.schema(fields, metadata=base.metadata)


def arrow_table(table: pd.DataFrame):
    """``table`` as a pyarrow Table with its explicit :func:`result_schema`.

    Examples
    --------
    >>> from rocking.campaign import EXAMPLE_SPEC, Campaign, parse_spec
    >>> from rocking.campaign.store import arrow_table
    >>> t = arrow_table(Campaign(parse_spec(EXAMPLE_SPEC)).run_chunk(1))
    >>> t.num_rows, t.schema.field("overturn_time").metadata[b"unit"]
    (2, b's')
    """
    import pyarrow as pa

    return pa.Table.from_pandas(table, schema=result_schema(table), preserve_index=False)
