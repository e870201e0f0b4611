"""Every record and mesh reader reads back exactly what a valid file in each supported layout
and unit says (issue 32: "a hypothesis test per reader that writes a valid file in every
supported layout and unit and reads back the same numbers").

Each test draws a series (or a body), writes it from the format's specification in one of
its units and layouts, reads it with :func:`rocking.motions.io.read_record` (or
:func:`rocking.shapes.load_shape`) and compares with what was written: to the rounding
of the written number format, never to a number of our own code's making. The writers of
ESM, COSMOS and K-NET files are those of ``tests/test_record_formats.py``, written from the
formats' specifications.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_record_formats import GAL, cosmos_text, esm_text, knet_counts, knet_text

from rocking.motions.io import read_record
from rocking.units import ACCELERATION, G

SETTINGS = settings(max_examples=25, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.function_scoped_fixture,
                                           HealthCheck.too_slow])

UNIT_WORDS = {  # canonical unit -> the ways files write it
    "g": ["g", "G"],
    "m/s^2": ["m/s^2", "m/s2", "M/S^2"],
    "cm/s^2": ["cm/s^2", "cm/s2", "cm/sec^2", "cm/s/s"],
    "gal": ["gal", "Gal"],
    "mm/s^2": ["mm/s^2", "mm/s2"],
}
STEPS = [0.001, 0.002, 0.005, 0.01, 0.02]  # s: the usual sampling of accelerograms


@st.composite
def series(draw, n_min=8, n_max=300):
    """A record: samples (m/s^2, a peak between 0.01 and 1.5 g) and a time step (s)."""
    n = draw(st.integers(n_min, n_max))
    seed = draw(st.integers(0, 2 ** 32 - 1))
    peak = draw(st.floats(0.01, 1.5)) * G
    x = np.random.default_rng(seed).standard_normal(n)
    x *= peak / np.max(np.abs(x))
    return x, draw(st.sampled_from(STEPS))


def _unit(draw_unit):
    key, words = draw_unit
    return key, words, ACCELERATION[key]


UNITS = st.sampled_from(sorted(UNIT_WORDS.items()))


def _check(acc, dt, back, dt_back, rtol_dt=1e-9, atol=None):
    assert len(back) == len(acc)
    assert dt_back == pytest.approx(dt, rel=rtol_dt)
    assert np.allclose(back, acc, rtol=0.0, atol=atol), np.max(np.abs(back - acc))


# ------------------------------------------------------------------------------- AT2
@SETTINGS
@given(rec=series(), unit=UNITS, layout=st.sampled_from(["NPTS=", "columns"]),
       word_i=st.integers(0, 3))
def test_at2_in_every_unit_and_npts_layout(tmp_path_factory, rec, unit, layout, word_i):
    acc, dt = rec
    key, words, f = _unit(unit)
    word = words[word_i % len(words)]
    vals = [float(v) for v in acc / f]
    lines = ["PEER NGA STRONG MOTION DATABASE RECORD",
             "ROUND TRIP, 1/1/2000, TEST, 0",
             f"ACCELERATION TIME SERIES IN UNITS OF {word}",
             (f"NPTS=  {len(vals)}, DT=   {dt:.4f} SEC" if layout == "NPTS="
              else f"{len(vals)}    {dt:.4f}    NPTS, DT")]
    text = [f"{v:15.7E}" for v in vals]
    lines += ["".join(text[r:r + 5]) for r in range(0, len(text), 5)]
    p = tmp_path_factory.mktemp("at2") / "rt.AT2"
    p.write_text("\n".join(lines) + "\n")
    back, dt_back, meta = read_record(p, units=key)
    # 8 significant digits of E format: half an ulp of the 7th decimal of the mantissa
    _check(acc, dt, back, dt_back, atol=float(np.max(np.abs(acc))) * 1e-7)
    assert meta["units"] == key and meta["units_stated"]


# ---------------------------------------------------------------------- CSV columns
@SETTINGS
@given(rec=series(), unit=UNITS, word_i=st.integers(0, 3),
       layout=st.sampled_from(["one column, # dt", "t,acc", "t_ms,acc", "whitespace"]),
       where=st.sampled_from(["comment", "column name"]))
def test_columns_in_every_unit_and_layout(tmp_path_factory, rec, unit, word_i, layout, where):
    acc, dt = rec
    key, words, f = _unit(unit)
    word = words[word_i % len(words)]
    vals = [float(v) for v in acc / f]
    head = [f"# units: {word}"] if where == "comment" else []
    acc_name = "acc" if where == "comment" else f"acc ({word})"
    t = [float(x) for x in dt * np.arange(len(vals))]
    if layout == "one column, # dt":
        head += [f"# dt = {dt!r} s", acc_name]
        rows = [f"{v!r}" for v in vals]
    elif layout == "t,acc":
        head += [f"t (s),{acc_name}"]
        rows = [f"{a!r},{v!r}" for a, v in zip(t, vals, strict=True)]
    elif layout == "t_ms,acc":
        head += [f"time_ms,{acc_name}"]
        rows = [f"{1000 * a!r},{v!r}" for a, v in zip(t, vals, strict=True)]
    else:
        head += [f"t(s)   {acc_name.replace(' ', '')}"]
        rows = [f"{a!r}   {v!r}" for a, v in zip(t, vals, strict=True)]
    p = tmp_path_factory.mktemp("csv") / "rt.csv"
    p.write_text("\n".join(head + rows) + "\n")
    back, dt_back, meta = read_record(p, units=key)
    _check(acc, dt, back, dt_back, atol=float(np.max(np.abs(acc))) * 1e-12)
    assert meta["units"] == key


# ------------------------------------------------------------------------------- ESM
@SETTINGS
@given(rec=series())
def test_esm_reads_back_its_samples(tmp_path_factory, rec):
    acc, dt = rec
    p = tmp_path_factory.mktemp("esm") / "rt.ASC"
    p.write_text(esm_text(acc, dt))
    back, dt_back, meta = read_record(p, units="cm/s^2")
    # written in cm/s^2 with 6 decimals
    _check(acc, dt, back, dt_back, atol=0.5e-6 * GAL * (1 + 1e-9))


# ---------------------------------------------------------------------------- COSMOS
@SETTINGS
@given(rec=series(), code=st.sampled_from([(4, "cm/sec2(04)", "cm/s^2"),
                                           (10, "gal(10)", "gal")]),
       e_format=st.booleans())
def test_cosmos_in_every_unit_code_and_number_format(tmp_path_factory, rec, code, e_format):
    acc, dt = rec
    c, text, key = code
    if not e_format:  # (F10.5) holds |a| < 1000 cm/s^2 with its sign
        acc = acc * min(1.0, 999.0 * GAL / float(np.max(np.abs(acc))))
    p = tmp_path_factory.mktemp("cosmos") / "rt.V2"
    p.write_text(cosmos_text(acc, dt, code=c, units_text=text, e_format=e_format))
    back, dt_back, meta = read_record(p, units=key)
    # (8F10.5): 5 decimals of cm/s^2; (1E15.6): 7 significant digits
    atol = (float(np.max(np.abs(acc))) * 1e-6 if e_format else 0.5e-5 * GAL * (1 + 1e-9))
    _check(acc, dt, back, dt_back, atol=atol)


# ----------------------------------------------------------------------------- K-NET
@SETTINGS
@given(rec=series(n_max=200), dt=st.sampled_from([0.01, 0.005]),
       direction=st.sampled_from(["N-S", "E-W", "U-D"]))
def test_knet_reads_back_its_counts_times_the_scale_factor(tmp_path_factory, rec, dt,
                                                           direction):
    acc, _ = rec
    counts = knet_counts(acc)
    p = tmp_path_factory.mktemp("knet") / "rt.NS"
    n = len(counts) - len(counts) % round(1 / dt)  # a whole number of seconds
    if n == 0:
        return
    counts = counts[:n]
    p.write_text(knet_text(counts, dt, direction=direction))
    back, dt_back, meta = read_record(p, units="gal")
    # NIED: counts times the scale factor, after the mean
    gal = (counts - counts.mean()) * 7845 / 8223790
    _check(gal * GAL, dt, back, dt_back, atol=1e-9 * GAL)


# ---------------------------------------------------------------------------- meshes
def _body(draw):
    """A convex body on a flat base: a box, or the frustum of a pyramid whose top is half
    its base (volume ``7 a b c / 12``, centroid at ``11 c / 28``), with drawn sizes."""
    a, b, c = (draw(st.floats(0.05, 3.0)) for _ in range(3))
    top = 0.5 if draw(st.booleans()) else 1.0
    v = np.array([[x * (1 if z == 0 else top), y * (1 if z == 0 else top), z]
                  for z in (0, c) for x, y in ((-a, -b), (a, -b), (a, b), (-a, b))]) / 2
    v[:, 2] *= 2
    f = np.array([[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
                  [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]])
    if top == 1.0:
        return v, f, a * b * c, c / 2
    return v, f, 7 * a * b * c / 12, 11 * c / 28


@SETTINGS
@given(data=st.data(), fmt=st.sampled_from(["stl", "stl_ascii", "obj", "ply", "ply_ascii"]),
       scale=st.sampled_from([("m", 1.0), ("mm", 1e-3), ("cm", 1e-2)]))
def test_meshes_in_every_format_and_unit(tmp_path_factory, data, fmt, scale):
    import trimesh

    from rocking.shapes import load_shape

    v, f, vol, zc = _body(data.draw)
    unit, k = scale
    m = trimesh.Trimesh(vertices=v / k, faces=f, process=False)
    ext = fmt.split("_")[0]
    p = tmp_path_factory.mktemp("mesh") / f"rt.{ext}"
    if fmt == "stl":
        m.export(p, file_type="stl")
    elif fmt == "stl_ascii":
        m.export(p, file_type="stl_ascii")
    elif fmt == "ply":
        m.export(p, file_type="ply", encoding="binary")
    elif fmt == "ply_ascii":
        m.export(p, file_type="ply", encoding="ascii")
    else:
        p.write_text("".join(f"v {x!r} {y!r} {z!r}\n" for x, y, z in (v / k).tolist())
                     + "".join(f"f {i + 1} {j + 1} {l + 1}\n" for i, j, l in f.tolist()))
    s = load_shape(p, units=unit, density=1000.0)
    # trimesh writes single precision (binary STL and PLY: 24 bits of mantissa) or a few
    # digits (ASCII STL, PLY); the OBJ written here has every digit
    rtol = 1e-9 if fmt == "obj" else 2e-6
    assert s.mass == pytest.approx(1000.0 * vol, rel=rtol)
    assert s.h == pytest.approx(zc, rel=rtol)
