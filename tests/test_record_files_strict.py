"""Issue 32, part B: record files and meshes are read exactly or refused in one line.

Each declared quantity of a record file is checked against the others (the step against
the duration and the count, the unit fields against each other), a malformed mesh file is
refused naming the file, the line and the defect, numba's cache falls back where it cannot
be written, and a record selection says when its scale factors sit at their limits. Then
bounded fuzz tests: each reader is given a valid file, mutated (a line dropped or
duplicated, a header value altered, the file cut, a byte changed), and must refuse it with a
:class:`~rocking.errors.RockingError` naming the file or read the original's numbers.

Expected line numbers, units and numbers are computed from the files written here (their
writers come from tests/test_record_formats.py), never copied from the readers' output.
"""

from __future__ import annotations

import math
import os
import re
import shutil
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest
import trimesh
from cli_helpers import assert_one_line_error, run_main
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_record_formats import ESM_KEYS, cosmos_text, esm_text, knet_counts, knet_text

from rocking import Block
from rocking.analysis import select_records
from rocking.campaign import parse_spec
from rocking.errors import ParameterError, PlausibilityWarning, RecordError, RockingError
from rocking.motions import Record, write_csv
from rocking.motions.io import read_builtin, read_record
from rocking.shapes import Shape, load_shape
from rocking.testing import mesh_reference as ref

NAME = "RSN948_NORTHR_CAM009"  # Northridge 1994, Arcadia: dt 0.01 s, PGA 0.09 g
SRC = Path(__file__).resolve().parents[1] / "src" / "rocking"
FUZZ = settings(max_examples=150, deadline=None, derandomize=True,
                suppress_health_check=list(HealthCheck))


@pytest.fixture(scope="module")
def at2():
    acc, dt, _ = read_builtin(NAME)
    return acc[:3400].copy(), dt


def esm_line(key: str) -> int:
    """1-based line of an ESM header key (the header has one key per line, in order)."""
    return ESM_KEYS.index(key) + 1


def write(path: Path, text) -> Path:
    (path.write_bytes if isinstance(text, bytes) else path.write_text)(text)
    return path


# ---------------------------------------------------------------- 1. ESM step vs duration
def test_esm_step_contradicting_duration_is_refused_naming_both_fields(tmp_path, at2):
    """3400 samples at 0.02 s with DURATION_S 34.000 (the issue's case: a 68 s motion)."""
    acc, dt = at2
    p = write(tmp_path / "a.asc", esm_text(acc, dt, SAMPLING_INTERVAL_S="0.020000"))
    with pytest.raises(RecordError) as e:
        read_record(p, units=None)
    msg = str(e.value)
    assert msg.startswith(f"{p}, line {esm_line('DURATION_S')}: DURATION_S: "
                          f"{len(acc) * dt:.3f}")
    assert f"SAMPLING_INTERVAL_S: 0.020000 (line {esm_line('SAMPLING_INTERVAL_S')})" in msg
    assert f"NDATA: {len(acc)} (line {esm_line('NDATA')})" in msg
    assert f"last {len(acc) * 0.02:g} s" in msg


def test_esm_step_in_ms_is_refused_with_a_hint(tmp_path, at2):
    """A step of 10 (ms) stated as SAMPLING_INTERVAL_S is not taken as 10 s."""
    acc, dt = at2
    p = write(tmp_path / "b.asc", esm_text(acc, dt, SAMPLING_INTERVAL_S=f"{dt * 1000:g}"))
    with pytest.raises(RecordError, match=r"in ms\?"):
        read_record(p, units=None)


@pytest.mark.parametrize("count", ["n", "n-1"])
def test_esm_duration_of_n_or_n_minus_1_steps_reads(tmp_path, at2, count):
    acc, dt = at2
    n = len(acc) - (count == "n-1")
    p = write(tmp_path / "c.asc", esm_text(acc, dt, DURATION_S=f"{n * dt:.3f}"))
    got, step, _ = read_record(p, units="cm/s^2")
    assert step == dt and got.size == len(acc)


def test_esm_units_contradicting_the_pga_field_is_refused(tmp_path, at2):
    """UNITS: g over cm/s^2 values whose peak PGA_CM/S^2 states: both fields named."""
    acc, dt = at2
    p = write(tmp_path / "d.asc", esm_text(acc, dt, UNITS="g"))
    with pytest.raises(RecordError) as e:
        read_record(p, units=None)
    msg = str(e.value)
    assert msg.startswith(f"{p}, line {esm_line('UNITS')}: UNITS: g contradicts PGA_CM/S^2 "
                          f"(line {esm_line('PGA_CM/S^2')})")


# ---------------------------------------------------------------- 2. unit contradictions
def test_knet_scale_factor_in_g_and_max_acc_in_gal_is_refused(tmp_path, at2):
    """The issue's K-NET case (read as 89 g today): line 14 says (g), line 15 (gal)."""
    acc, dt = at2
    text = knet_text(knet_counts(acc), dt).replace("(gal)/", "(g)/")
    lines = text.splitlines()
    assert lines[13].startswith("Scale Factor") and "(g)/" in lines[13]
    assert lines[14].startswith("Max. Acc. (gal)")
    p = write(tmp_path / "MYG0020601182325.NS", text)
    with pytest.raises(RecordError) as e:
        read_record(p, units=None)
    msg = str(e.value)
    assert msg.startswith(f"{p}, line 15: Max. Acc.") and "(gal)" in msg
    assert "line 14" in msg and "(g)" in msg


def test_knet_contradiction_is_exit_2_in_the_cli(capsys, tmp_path, at2):
    acc, dt = at2
    p = write(tmp_path / "k.NS", knet_text(knet_counts(acc), dt).replace("(gal)/", "(g)/"))
    code, _, err = run_main(capsys, "motion", "show", p, "--units", "g", "--no-plot")
    assert_one_line_error(code, err, "line 15")


def test_cosmos_declaring_g_with_cm_values_is_refused(tmp_path, at2):
    """Units code 02 (g) in the data header and integer #3, while the text header's line 11
    states the maximum in cm/s^2 (the values are cm/s^2): read as 89 g today."""
    acc, dt = at2
    text = cosmos_text(acc, dt, code=2, units_text="g(02)")
    lines = text.splitlines()
    data_line = next(i for i, ln in enumerate(lines, 1) if "acceleration pts" in ln)
    assert "Max =" in lines[10] and "cm/s^2" in lines[10]
    p = write(tmp_path / "c.v2", text)
    with pytest.raises(RecordError) as e:
        read_record(p, units=None)
    msg = str(e.value)
    assert msg.startswith(f"{p}, line 11: the text header states 'Max =")
    assert f"(line {data_line}) states units=g(02)" in msg


def test_cosmos_series_length_contradicting_the_step_is_refused(tmp_path, at2):
    """Real #62 (ms) 10.0009 against #63 = npts dt = 34.000000: 3.06 ms apart, beyond the
    rounding of both numbers (half a unit in their last place)."""
    acc, dt = at2
    p = write(tmp_path / "e.v2", cosmos_text(acc, dt, dt_ms=dt * 1000 + 0.0009))
    with pytest.raises(RecordError, match=r"#63 states a series length of 34 s"):
        read_record(p, units=None)


def test_column_file_stating_dt_twice_is_refused_naming_both_lines(tmp_path):
    p = write(tmp_path / "a.csv", "# dt = 0.01 s\n# units: g\n# dt = 0.02 s\n1\n2\n3\n")
    with pytest.raises(RecordError, match=re.escape(f"{p}, line 3: dt = 0.02 s contradicts "
                                                    "dt = 0.01 s stated on line 1")):
        read_record(p, units=None)
    p = write(tmp_path / "b.csv", "# units: g\n# dt = 0.01 s\n# units: gal\n1\n2\n3\n")
    with pytest.raises(RecordError, match=re.escape(f"{p}, line 3: units 'gal' contradict "
                                                    "units 'g' stated on line 1")):
        read_record(p, units=None)
    p = write(tmp_path / "c.csv", "# dt = 0.01 s, npts = 3\n# npts = 4\n1\n2\n3\n")
    with pytest.raises(RecordError, match="line 2: npts = 4 contradicts npts = 3"):
        read_record(p, units=None)


def test_at2_stating_npts_twice_is_refused(tmp_path):
    p = write(tmp_path / "r.AT2", "PEER\nX, 1/1/2000, S, 0\nACCELERATION TIME SERIES IN "
              "UNITS OF G\nNPTS=    3, DT=   .0100 SEC, NPTS= 4\n .1E-01 .2E-01 .3E-01\n")
    with pytest.raises(RecordError, match=r"r\.AT2, line 4: NPTS=4 contradicts NPTS=3"):
        read_record(p)


# ---------------------------------------------------------------------------- 3. meshes
BOX = (0.5, 0.25, 1.25)


def box_text(file_type: str, scale: float = 1.0, **kw):
    v, f = ref.box(*BOX)
    with np.errstate(all="ignore"):  # trimesh's normals of a huge box overflow
        return trimesh.Trimesh(v * scale, f, process=False).export(file_type=file_type, **kw)


def obj_lines() -> list[str]:
    return box_text("obj").splitlines()


def first_line(lines: list[str], prefix: str, k: int = 0) -> int:
    """0-based index of the ``k``-th line starting with ``prefix``."""
    return [i for i, ln in enumerate(lines) if ln.startswith(prefix)][k]


def _bad_meshes(tmp_path: Path) -> dict:
    """``name: (path, words the message must hold)`` of one malformed file per defect."""
    out = {}
    lines = obj_lines()
    i = first_line(lines, "v ", 2)
    short = list(lines)
    short[i] = "v " + " ".join(lines[i].split()[1:3])  # two coordinates
    out["short"] = (write(tmp_path / "short.obj", "\n".join(short) + "\n"),
                    [f"line {i + 1}", "2 coordinate"])
    for name, tok in (("nan", "nan"), ("inf", "-inf"), ("huge", "1e150")):
        bad = list(lines)
        bad[i] = f"v {lines[i].split()[1]} {tok} {lines[i].split()[3]}"
        out[name] = (write(tmp_path / f"{name}.obj", "\n".join(bad) + "\n"),
                     [f"line {i + 1}", tok])
    j = first_line(lines, "f ", 3)
    bad = list(lines)
    nv = sum(ln.startswith("v ") for ln in lines)
    bad[j] = f"f 1 2 {nv + 1}"
    out["face"] = (write(tmp_path / "face.obj", "\n".join(bad) + "\n"),
                   [f"line {j + 1}", f"vertex index {nv + 1}"])
    stl = box_text("stl_ascii", scale=1e150)
    k = next(n for n, ln in enumerate(stl.splitlines()) if ln.split()[:1] == ["vertex"])
    out["stl_huge"] = (write(tmp_path / "huge.stl", stl), [f"line {k + 1}", "beyond"])
    binary = bytearray(box_text("stl"))
    binary[84 + 50 * 4 + 12:84 + 50 * 4 + 16] = np.float32(np.inf).tobytes()
    out["stl_inf"] = (write(tmp_path / "inf.stl", bytes(binary)), ["triangle 5", "non-finite"])
    out["stl_cut"] = (write(tmp_path / "cut.stl", bytes(binary[:-20])), ["bytes", "cut"])
    ply = box_text("ply", encoding="ascii").decode()
    plines = ply.splitlines()
    h = plines.index("end_header")
    plines[h + 3] = "0.25 1e300 0.0"
    out["ply_huge"] = (write(tmp_path / "huge.ply", "\n".join(plines) + "\n"),
                       [f"line {h + 4}", "1e300"])
    return out


BAD_MESHES = ["short", "nan", "inf", "huge", "face", "stl_huge", "stl_inf", "stl_cut",
              "ply_huge"]


@pytest.mark.parametrize("name", BAD_MESHES)
def test_malformed_mesh_is_one_error_naming_file_line_and_defect(tmp_path, name):
    path, words = _bad_meshes(tmp_path)[name]
    with pytest.raises(ParameterError) as e:
        load_shape(path, density=2000.0)
    msg = str(e.value)
    assert str(path) in msg and "\n" not in msg
    for w in words:
        assert w in msg, (w, msg)
    with pytest.raises(ParameterError, match=re.escape(str(path))):
        Block.from_mesh(path, density=2000.0)


@pytest.mark.parametrize("name", ["short", "huge", "stl_huge"])
def test_malformed_mesh_is_exit_2_in_every_command(capsys, tmp_path, name):
    path, words = _bad_meshes(tmp_path)[name]
    capsys.readouterr()
    code, _, err = run_main(capsys, "shape", path, "--density", "2600")
    assert_one_line_error(code, err, words[0])
    code, _, err = run_main(capsys, "simulate", "--mesh", path, "--mass", "10", "--motion",
                            "ricker", "--amp", "0.1g", "--freq", "2Hz")
    assert_one_line_error(code, err, words[0])
    spec = (f'[campaign]\nname = "m"\nseed = 1\nmodel = "housner"\n\n[[blocks]]\nmesh = '
            f'"{path}"\ndensity = 2000\n\n[motions]\nkind = "builtin"\nname = '
            '["RSN126_GAZLI_GAZ000"]\nload_factors = [0.5]\n')
    with pytest.raises(RockingError) as e:
        parse_spec(spec, base_dir=tmp_path)
    assert str(path) in str(e.value) and words[0] in str(e.value)


def test_huge_coordinates_from_arrays_are_a_parameter_error():
    v, f = ref.box(*BOX)
    with pytest.raises(ParameterError, match="beyond"):
        Shape.from_arrays(v * 1e150, f, density=2000.0)


# ---------------------------------------------------------------------- 4. numba's cache
def test_kernel_dirs_cover_every_cached_kernel():
    from rocking._numba_cache import KERNEL_DIRS

    dirs = {p.parent.relative_to(SRC).as_posix() for p in SRC.rglob("*.py")
            if "cache=True" in p.read_text() and p.name != "_numba_cache.py"}
    assert dirs and dirs <= set(KERNEL_DIRS)


def test_cache_dir_choice(tmp_path):
    """Folders under a regular file cannot be created, even by root (chmod cannot stand in
    for a read-only installation when the tests run as root)."""
    blocker = write(tmp_path / "file", "")
    pkg = tmp_path / "pkg"
    from rocking._numba_cache import KERNEL_DIRS, choose_cache_dir, user_cache_dir

    for d in KERNEL_DIRS:
        (pkg / d).mkdir(parents=True)
    home = {"HOME": str(blocker / "home")}
    assert user_cache_dir(home) == str(blocker / "home" / ".cache" / "numba")
    # the package is writable: numba's own choice
    assert choose_cache_dir(pkg, home, tmp_path / "t") == (None, None)
    for d in KERNEL_DIRS:  # read-only package: a __pycache__ that cannot be a folder
        shutil.rmtree(pkg / d / "__pycache__")
        write(pkg / d / "__pycache__", "")
    folder, msg = choose_cache_dir(pkg, home, str(tmp_path / "t"))
    assert folder == os.path.join(str(tmp_path / "t"), f"rocking-numba-cache-{os.getuid()}")
    assert Path(folder).is_dir() and folder in msg and "\n" not in msg
    # a writable user cache, or a writable NUMBA_CACHE_DIR: numba's own choice
    assert choose_cache_dir(pkg, {"HOME": str(tmp_path / "h")}, None) == (None, None)
    assert choose_cache_dir(pkg, {**home, "NUMBA_CACHE_DIR": str(tmp_path / "n")},
                            None) == (None, None)
    # nothing writable at all: no cache
    folder, msg = choose_cache_dir(pkg, {**home, "NUMBA_CACHE_DIR": str(blocker / "n")},
                                   str(blocker / "t"))
    assert folder == "" and "without one" in msg and f"NUMBA_CACHE_DIR={blocker / 'n'}" in msg


def _readonly_copy(tmp_path: Path) -> tuple[Path, dict]:
    """A copy of the package whose kernel folders cannot hold a __pycache__, and an
    environment whose home cannot hold a cache (see test_cache_dir_choice)."""
    dirs = ("motions", "models", "models/dem", "models/_numerics")  # KERNEL_DIRS
    pkg = tmp_path / "site"
    shutil.copytree(SRC, pkg / "rocking",
                    ignore=shutil.ignore_patterns("__pycache__", "*.nbi", "*.nbc"))
    for d in dirs:
        write(pkg / "rocking" / d / "__pycache__", "")
    blocker = write(tmp_path / "file", "")
    env = {k: v for k, v in os.environ.items()
           if k not in ("NUMBA_CACHE_DIR", "XDG_CACHE_HOME", "PYTHONPATH")}
    env.update(HOME=str(blocker / "home"), PYTHONPATH=str(pkg), TMPDIR=str(tmp_path / "tmp"))
    (tmp_path / "tmp").mkdir()
    return blocker, env


def test_unwritable_cache_falls_back_to_the_temporary_folder(tmp_path):
    """Today: ``RuntimeError: cannot cache function 'ground_acc': no locator available``
    on importing any module with a kernel."""
    _, env = _readonly_copy(tmp_path)
    code = ("import rocking.motions._kernel, numba, sys; print(numba.config.CACHE_DIR)")
    r = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                       text=True, timeout=300, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    folder = str(tmp_path / "tmp" / f"rocking-numba-cache-{os.getuid()}")
    assert r.stdout.strip() == folder
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and folder in lines[0] and "numba cannot write" in lines[0]


def test_no_writable_folder_runs_without_a_cache(tmp_path):
    blocker, env = _readonly_copy(tmp_path)
    code = (f"import tempfile; tempfile.tempdir = {str(blocker / 'tmp')!r}\n"
            "import rocking.motions._kernel as k\n"
            "from numba.core.caching import NullCache\n"
            "print(type(k.ground_acc._cache).__name__)")
    r = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                       text=True, timeout=300, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "NullCache"
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and "running without one" in lines[0]


# -------------------------------------------------------------- 5. factors at a limit
def test_selection_says_when_every_factor_sits_at_its_limit():
    """A target a million times below the records: the factors all stop at 1/max_scale."""
    T = np.array([0.2, 0.5, 1.0])
    spectra = np.array([[6.0, 4.0, 1.0], [3.0, 2.5, 1.25], [2.0, 2.0, 2.0]])
    target = 1e-6 * spectra[1]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", PlausibilityWarning)
        sel = select_records(spectra, target, T, n=2, max_scale=4.0)
    assert sel.scales == pytest.approx([0.25, 0.25], rel=1e-12)
    ratio = sel.scales @ spectra[sel.indices] / 2 / target
    note = next(n for n in sel.notes if "limit" in n)
    assert note.startswith("all of the 2 scale factors at the lower limit 1/max_scale = 0.25")
    assert f"{ratio.min():.4g} to {ratio.max():.4g} times the target" in note
    # a reachable target: no such note
    sel = select_records(spectra, 2.0 * spectra[1], T, n=1, max_scale=4.0)
    assert sel.scales == pytest.approx([2.0], rel=1e-12)
    assert not any("limit" in n for n in sel.notes)


def test_selection_limit_note_is_printed_by_the_cli(capsys, tmp_path):
    folder = tmp_path / "cands"
    folder.mkdir()
    acc, dt, _ = read_builtin(NAME)
    for k in range(3):
        write_csv(Record(acc[:1500] * (1.0 + k), dt, name=f"r{k}"), folder / f"r{k}.csv")
    code, out, err = run_main(capsys, "motion", "select", folder, "--target", "ec8", "--ag",
                              "1e-6g", "--ground", "B", "--n", 3, "--periods", "0.1:1:5",
                              "--units", "m/s^2", "--out", tmp_path / "out", "--no-plot")
    assert code == 0, err
    assert re.search(r"^note +all of the 3 scale factors at the lower limit 1/max_scale = "
                     r"0\.25", out, re.M), out


# ----------------------------------------------------------------------------- 6. fuzz
MUTATIONS = ["drop", "dup", "alter", "truncate", "flip"]
ALTERED = ["{x}0", "-{x}", "0", "", "x", "nan", "inf", "1e300", "{x}e3", "{x}e-3", "1{x}"]
_TOKEN = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def mutate(data: bytes, header_end: int, draw) -> bytes:
    """One mutation of ``data`` (its first ``header_end`` bytes are the header): a line
    dropped or duplicated, a number of the header altered, the file cut, a byte of the
    header changed. A data value changed in place cannot be told from a true one: the
    value mutations stay in the header."""
    op = draw(st.sampled_from(MUTATIONS))
    lines = data.split(b"\n")
    if op in ("drop", "dup"):
        i = draw(st.integers(0, len(lines) - 1))
        return b"\n".join(lines[:i] + lines[i:i + 1] * (2 if op == "dup" else 0)
                          + lines[i + 1:])
    if op == "truncate":
        return data[:draw(st.integers(1, len(data) - 1))]
    if op == "flip":
        j = draw(st.integers(0, max(header_end - 1, 0)))
        return data[:j] + bytes([draw(st.integers(0, 255))]) + data[j + 1:]
    head = data[:header_end].decode("latin-1")
    found = list(_TOKEN.finditer(head))
    if not found:
        return data
    m = draw(st.sampled_from(found))
    new = draw(st.sampled_from(ALTERED)).format(x=m[0].lstrip("+-"))
    return (head[:m.start()] + new + head[m.end():]).encode("latin-1") + data[header_end:]


def read_or_refuse(path: Path, expected, **kw) -> str:
    """The mutated file is refused with a RockingError naming it, or read to the original's
    numbers (a PlausibilityWarning naming it is a documented contradiction, stated)."""
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        try:
            acc, dt, _ = read_record(path, **kw)
        except RockingError as e:
            assert str(path) in str(e), e
            return "refused"
    acc0, dt0 = expected
    if acc.shape == acc0.shape and np.array_equal(acc, acc0) and dt == dt0:
        return "same"
    stated = [x for x in w if issubclass(x.category, PlausibilityWarning)
              and str(path) in str(x.message)]
    assert stated, (f"read to other numbers without a word: {acc.size} samples, dt {dt!r} "
                    f"(original {acc0.size}, {dt0!r})")
    return "warned"


def _fuzz(tmp_path_factory, name: str, text, header_end: int, **kw):
    original = text.encode() if isinstance(text, str) else text
    path = tmp_path_factory.mktemp("fuzz") / name
    expected = read_record(write(path, original), **kw)[:2]

    @FUZZ
    @given(st.data())
    def check(data_):
        write(path, mutate(original, header_end, data_.draw))
        read_or_refuse(path, expected, **kw)

    check()


def _short(at2, n=240):
    acc, dt = at2
    return acc[:n].copy(), dt


def test_fuzz_esm(tmp_path_factory, at2):
    acc, dt = _short(at2)
    text = esm_text(acc, dt)
    _fuzz(tmp_path_factory, "f.asc", text, len("\n".join(text.split("\n")[:64])),
          units=None)


def test_fuzz_cosmos(tmp_path_factory, at2):
    acc, dt = _short(at2)
    text = cosmos_text(acc, dt)
    head = text[:text.index("acceleration pts")]  # to the data header line, included
    _fuzz(tmp_path_factory, "f.v2", text, len(head) + 60, units=None)


def test_fuzz_knet(tmp_path_factory, at2):
    acc, dt = _short(at2, 400)  # 4.00 s: a whole number of seconds
    text = knet_text(knet_counts(acc), dt)
    _fuzz(tmp_path_factory, "f.NS", text, len("\n".join(text.split("\n")[:17])),
          units=None)


def test_fuzz_at2(tmp_path_factory):
    from importlib import resources
    src = resources.files("rocking.motions") / "data" / "records" / f"{NAME}.AT2"
    lines = src.read_bytes().split(b"\n")
    head, body = lines[:4], lines[4:]
    npts = int(re.search(rb"NPTS\s*=\s*(\d+)", head[3])[1])
    keep = 60  # 60 lines of 5 values: a short file, the header's NPTS set to match
    head[3] = head[3].replace(str(npts).encode(), str(5 * keep).rjust(len(str(npts))).encode())
    data = b"\n".join(head + body[:keep]) + b"\n"
    _fuzz(tmp_path_factory, "f.AT2", data, len(b"\n".join(head)), units="g")


def test_fuzz_csv(tmp_path_factory, at2):
    acc, dt = _short(at2, 120)
    path = tmp_path_factory.mktemp("csv") / "r.csv"
    text = write_csv(Record(acc, dt, name="r"), path).read_text()
    _fuzz(tmp_path_factory, "f.csv", text, len("\n".join(text.split("\n")[:5])),
          units="m/s^2")


BAD_VALUES = ["", "x", "nan", "-inf", "1e300", "1e150", "1e"]


def _mesh_fuzz(tmp_path_factory, name: str, original: bytes, binary: bool = False):
    """A mutated mesh file is refused with a ParameterError naming it, or read to the
    original's volume and centre of mass. A duplicated line (an OBJ vertex shifts the
    indices after it) or a changed byte (a digit) can make another valid solid: for those
    the reader must refuse or read finite numbers, never raise anything else."""
    path = tmp_path_factory.mktemp("mesh") / name
    shape0 = load_shape(write(path, original), density=2000.0)

    @FUZZ
    @given(st.data())
    def check(data):
        op = data.draw(st.sampled_from(["flip", "truncate"] if binary else
                                       ["drop", "dup", "alter", "truncate", "flip"]))
        if op == "alter":
            text = original.decode()
            m = data.draw(st.sampled_from(list(_TOKEN.finditer(text))))
            mutated = (text[:m.start()] + data.draw(st.sampled_from(BAD_VALUES))
                       + text[m.end():]).encode()
        elif op == "flip":
            j = data.draw(st.integers(0, len(original) - 1))
            mutated = original[:j] + bytes([data.draw(st.integers(0, 255))]) + \
                original[j + 1:]
        elif op == "truncate":
            mutated = original[:data.draw(st.integers(1, len(original) - 1))]
        else:
            lines = original.split(b"\n")
            i = data.draw(st.integers(0, len(lines) - 1))
            mutated = b"\n".join(lines[:i] + lines[i:i + 1] * (2 if op == "dup" else 0)
                                  + lines[i + 1:])
        write(path, mutated)
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                shape = load_shape(path, density=2000.0)
        except ParameterError as e:
            assert str(path) in str(e) or "mesh" in str(e), e
            return
        same = math.isclose(shape.volume, shape0.volume, rel_tol=1e-9) and \
            np.allclose(shape.com, shape0.com, rtol=0, atol=1e-9)
        assert same or op in ("dup", "flip"), (op, shape.volume, shape0.volume)
        assert math.isfinite(shape.volume) and np.isfinite(shape.com).all()

    check()


@pytest.mark.parametrize("file_type, kw", [("obj", {}), ("stl_ascii", {}),
                                           ("ply", {"encoding": "ascii"})])
def test_fuzz_text_meshes(tmp_path_factory, file_type, kw):
    data = box_text(file_type, **kw)
    data = data.encode() if isinstance(data, str) else data
    _mesh_fuzz(tmp_path_factory, f"box.{file_type.split('_')[0]}", data)


@pytest.mark.parametrize("file_type", ["stl", "ply"])
def test_fuzz_binary_meshes(tmp_path_factory, file_type):
    _mesh_fuzz(tmp_path_factory, f"box.{file_type}", box_text(file_type), binary=True)
