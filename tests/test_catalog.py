"""The motion catalog and the block factory: one entry per kind / form, declared parameters."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from rocking import Block, Stack, specimen
from rocking.blocks import factory
from rocking.errors import ParameterError
from rocking.motions import (
    GroundMotion,
    HalfSine,
    HanningSine,
    MavroeidisPapageorgiou,
    OneCosine,
    OneSine,
    Rectangular,
    Ricker,
    Sine,
    load_builtin,
    paper_earthquake,
    stochastic_records,
)
from rocking.motions import catalog as C
from rocking.motions.ec8_records import ec8_earthquake
from rocking.units import G

# one example per kind: (catalog parameters, the same motion built by its class)
EXAMPLES = {
    "sine": ({"frequency": 2.0, "amplitude": 1.5, "cycles": 4},
             lambda: Sine.from_acceleration(2.0, 1.5, 4 / 2.0)),
    "hanning": ({"frequency": 3.0, "displacement": 0.004, "duration": 5.0},
                lambda: HanningSine(3.0, 0.004, 5.0)),
    "one_sine": ({"amplitude": 2.0, "period": 0.5}, lambda: OneSine(2.0, 0.5)),
    "one_cosine": ({"amplitude": 2.0, "period": 0.5, "t0": 0.1},
                   lambda: OneCosine(2.0, 0.5, t0=0.1)),
    "half_sine": ({"amplitude": 2.0, "period": 0.3, "duration": 4.0},
                  lambda: HalfSine(2.0, 0.3, duration=4.0)),
    "rectangular": ({"amplitude": 1.0, "period": 0.2}, lambda: Rectangular(1.0, 0.2)),
    "ricker": ({"amplitude": 3.0, "period": 0.5}, lambda: Ricker(3.0, 2.0)),
    "mavroeidis_papageorgiou": ({"amplitude": 3.0, "frequency": 1.0, "gamma": 2.0, "nu": 0.3},
                                lambda: MavroeidisPapageorgiou(3.0, 1.0, 2.0, 0.3)),
    "builtin": ({"name": "Rinaldi228"}, lambda: load_builtin("Rinaldi228")),
    "earthquake": ({"number": 7}, lambda: paper_earthquake(7)),
    "ground_motion": ({"set": "duzce", "horizontal": 2},
                      lambda: GroundMotion.builtin("duzce", horizontal=2)),
    "stochastic": ({"index": 3, "dt": 0.02}, lambda: stochastic_records(1, seed=5, start=3,
                                                                        dt=0.02)[0]),
    "ec8_earthquake": ({"number": 2, "ground": "C"}, lambda: ec8_earthquake(2, "C", 1)),
}


def _same(a, b) -> bool:
    (ka, pa, sa), (kb, pb, sb) = a.spec(), b.spec()
    return ka == kb and np.array_equal(pa, pb) and np.array_equal(sa, sb) \
        and a.duration == b.duration


def test_every_kind_has_an_example():
    assert set(EXAMPLES) | {"record"} == set(C.KINDS)


@pytest.mark.parametrize("name", sorted(EXAMPLES))
def test_catalog_builds_the_class_motion(name):
    params, direct = EXAMPLES[name]
    m = C.build(name, C.Context(seed=5), **params)
    assert _same(m, direct())
    assert C.KINDS[name].vertical == isinstance(m, GroundMotion)


def test_record_kind_reads_the_file_relative_to_the_context(tmp_path):
    acc = np.sin(np.linspace(0, 20, 401)) * 0.1
    (tmp_path / "r.txt").write_text("\n".join(f"{x:.6f}" for x in acc))
    m = C.build("record", C.Context(base_dir=tmp_path), file="r.txt", dt=0.01, units="g")
    assert np.allclose(m.acc, np.round(acc, 6) * G)
    assert C.KINDS["record"].label(C.KINDS["record"].params(file="r.txt", dt=0.01)) == "r.txt"


def test_globs_expand_sorted_and_relative(tmp_path):
    for n in ("b.AT2", "a.AT2", "c.txt"):
        (tmp_path / n).write_text("x")
    ctx = C.Context(base_dir=tmp_path)
    assert C.expand_files("*.AT2", ctx) == ["a.AT2", "b.AT2"]
    assert C.expand_files("none*.AT2", ctx) == []
    assert C.expand_files("c.txt", ctx) == ["c.txt"]


def test_units_at_the_edge_equal_si_numbers():
    a = C.build("one_sine", amplitude="0.3g", period="500ms")
    b = C.build("one_sine", amplitude=0.3 * G, period=0.5)
    assert _same(a, b)
    s = C.build("sine", frequency="5Hz", displacement="5mm", duration=20)
    assert s.amplitude == pytest.approx(0.005, rel=1e-15)
    # amplitude (m/s^2) and displacement (m) of the same harmonic motion: X w^2 = A
    w = 2 * math.pi * 5.0
    s2 = C.build("sine", frequency=5.0, amplitude=0.005 * w * w, duration=20)
    assert s2.acc_amplitude == pytest.approx(s.acc_amplitude, rel=1e-14)


def test_ricker_by_period_or_frequency_is_the_same_pulse():
    assert _same(C.build("ricker", amplitude=1.0, period=0.25),
                 C.build("ricker", amplitude=1.0, frequency=4.0))
    k = C.KINDS["ricker"]
    assert k.label(k.params(amplitude=1.0, period=0.25)) == "ricker:0.25s"
    assert k.label(k.params(amplitude=1.0, frequency=4.0)) == "ricker:4Hz"


@pytest.mark.parametrize("name, params, key", [
    ("sine", {"frequency": -1.0, "amplitude": 1.0, "cycles": 2}, "frequency"),
    ("sine", {"frequency": 1.0, "amplitude": 1.0}, "duration or cycles"),
    ("sine", {"frequency": 1.0, "amplitude": 1.0, "displacement": 0.1, "cycles": 1},
     "amplitude or displacement"),
    ("sine", {"frequency": 1e-6, "amplitude": 1.0, "cycles": 10}, "cycles"),
    ("one_sine", {"amplitude": 1.0}, "period"),
    ("one_sine", {"amplitude": "0.3m", "period": 1.0}, "amplitude"),
    ("ricker", {"amplitude": 1.0}, "frequency or period"),
    ("mavroeidis_papageorgiou", {"amplitude": 1.0, "frequency": 1.0, "gamma": 0.5, "nu": 0},
     "gamma"),
    ("earthquake", {"number": 31}, "number"),
    ("builtin", {"name": "nope"}, "name"),
    ("ground_motion", {"set": "rinaldi", "file": "x"}, "set or file"),
    ("ground_motion", {"file": "x"}, "vertical_file"),
    ("stochastic", {"zeta_f": 1.5}, "zeta_f"),
    ("stochastic", {"duration": 1.0}, "duration"),
    ("stochastic", {"dt": 1e-6}, "dt"),
    ("one_sine", {"amplitude": 1.0, "period": 1.0, "amp": 2}, "amp"),
])
def test_bad_parameters_name_the_parameter(name, params, key):
    with pytest.raises(ParameterError, match=key):
        C.build(name, **params)


def test_unknown_kind_lists_the_kinds():
    with pytest.raises(ParameterError, match="one_sine.*stochastic"):
        C.kind("two_sine")


@pytest.mark.parametrize("old, new", [(a, k.name) for k in C.KINDS.values()
                                      for a in k.aliases])
def test_old_spellings_warn_and_resolve(old, new):
    with pytest.warns(DeprecationWarning, match=f"write '{new}'"):
        assert C.kind(old) is C.KINDS[new]


def test_names_do_not_warn():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for name in C.KINDS:
            assert C.kind(name).name == name


def test_table_lists_every_parameter_once_per_kind():
    rows = C.table()
    for name, k in C.KINDS.items():
        assert [r["name"] for r in rows if r["kind"] == name] == list(k.Params.names())
    assert all(r["help"] for r in rows)


# ------------------------------------------------------------------------------- blocks
def test_block_forms_equal_their_constructors():
    mk = factory.make_block
    assert mk({"specimen": 2, "params": "experimental"}) == specimen(2, "experimental")
    assert mk({"width": "170mm", "height": 0.75, "mass": 3}) == Block.rectangular(
        0.17, 0.75, mass=3, name="0.17 x 0.75 m block")
    b = mk({"alpha": "10deg", "p": 2.0, "mu": 0.9})
    assert (b.alpha, b.p, b.mu) == (math.radians(10), 2.0, 0.9)
    verts = [[-0.1, 0.0], [0.1, 0.0], [0.05, 0.8], [-0.05, 0.8]]
    poly = mk({"vertices": verts, "density": 2000.0})
    ref = Block.polygon([tuple(v) for v in verts], density=2000.0)
    assert (poly.alpha, poly.p, poly.mu, poly.mass) == (ref.alpha, ref.p, ref.mu, ref.mass)
    st = mk({"stack": [{"width": 0.2, "height": 0.4, "mass": 10},
                       {"width": 0.1, "height": 0.3, "mass": 2}], "name": "two"})
    assert isinstance(st, Stack) and len(st) == 2 and st.name == "two"
    assert st.top.width == 0.1
    assert mk({"specimen": 2, "mu": 0.9, "name": "x"}).mu == 0.9


@pytest.mark.parametrize("mapping, key", [
    ({"width": 1.0}, "height"),
    ({"width": 1.0, "height": 2.0, "alpha": 0.1}, "give exactly one"),
    ({}, "give exactly one"),
    ({"specimen": 9}, "specimen"),
    ({"width": -1.0, "height": 1.0}, "width"),
    ({"width": 1.0, "height": 1.0, "colour": "red"}, "colour"),
    ({"alpha": 2.0, "p": 1.0, "mu": 0.9}, "alpha"),
    ({"stack": [{"width": 1.0}]}, r"stack\[0\]\.height"),
    ({"vertices": 3}, "vertices"),
])
def test_bad_blocks_name_the_key(mapping, key):
    with pytest.raises(ParameterError, match=key):
        factory.make_block(mapping)


def test_block_table_lists_every_form():
    rows = factory.table()
    assert {r["form"] for r in rows} == set(factory.FORMS)
    for f in factory.FORMS.values():
        assert any(r["name"] == f.key for r in rows if r["form"] == f.name)
