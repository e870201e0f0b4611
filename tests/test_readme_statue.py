"""The README's worked example (the museum's marble statue, issue 31) runs as written
(:data:`SMALLER` may shrink its sizes should it grow slow), and its
answers obey the physics: the mass is density x volume, the weakest direction uplifts at
g tan(alpha), nothing overturns below its uplift acceleration, every risk interval holds
its estimate and P(50 yr) = 1 - exp(-50 lambda), and the linear isolator's displacement
at 475 years is EN 1998-1's displacement spectrum (the floor moves like the ground at the
isolator's period) and grows in proportion to the IM between 475 and 2475 years."""

import contextlib
import io
import math
import os
import re
from pathlib import Path

import numpy as np
import pytest

README = Path(__file__).resolve().parents[1] / "README.md"
G = 9.80665

#: Substitutions of the README's sizes for a faster test, old -> new (none: its 300 runs
#: take about 15 s once compiled, so the test runs the example as written).
SMALLER: dict = {}


def _block(text: str, marker: str, lang: str) -> str:
    m = re.search(rf"<!-- statue-example:{marker} -->\s*```{lang}\n(.*?)```", text, re.S)
    assert m, f"README.md: no ```{lang} block after <!-- statue-example:{marker} -->"
    return m.group(1)


@pytest.fixture(scope="module")
def example(tmp_path_factory):
    import matplotlib
    matplotlib.use("Agg")
    text = README.read_text(encoding="utf-8")
    spec, code = _block(text, "spec", "toml"), _block(text, "python", "python")
    for old, new in SMALLER.items():
        assert old in spec, f"the README's spec no longer has {old!r}: update SMALLER"
        spec = spec.replace(old, new)
    where = tmp_path_factory.mktemp("statue")
    (where / "statue.toml").write_text(spec)
    here = os.getcwd()
    out = io.StringIO()
    ns = {"__name__": "readme_statue"}
    try:
        os.chdir(where)
        with contextlib.redirect_stdout(out):
            exec(compile(code, "README.md (statue example)", "exec"), ns)
    finally:
        os.chdir(here)
    return ns, out.getvalue(), where


def test_runs_and_prints_the_answers(example):
    ns, text, where = example
    assert "weakest direction" in text and "isolator:" in text
    assert re.search(r"none .*\d/yr \(.*\), 50 yr: ", text), text
    for name in ("statue_directions.png", "statue_mitigations.png",
                 "statue-report/risk.png", "statue-report/p_overturn_none.png",
                 "statue-report/p_overturn_isolated.png",
                 "statue-report/p_overturn_anchored.png"):
        png = where / name
        assert png.is_file() and png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", name


def test_statue_mass_and_weakest_direction(example):
    import trimesh

    from rocking.shapes import example_mesh_path
    ns, _, _ = example
    shape, weak, table = ns["shape"], ns["weak"], ns["table"]
    volume = trimesh.load(example_mesh_path()).volume
    assert shape.mass == pytest.approx(2700 * volume, rel=1e-9)     # marble, not steel
    assert 2000 < shape.mass / volume < 3000
    # a rigid body on its edge uplifts when a = g tan(alpha) (Housner 1963)
    assert weak.uplift_g == pytest.approx(math.tan(weak.alpha), rel=1e-6)
    low = np.minimum(table["uplift_plus"], table["uplift_minus"]).min() / G
    assert weak.uplift_g == pytest.approx(low, rel=1e-9)             # the table's least
    assert weak.side == "+"


def test_nothing_overturns_below_its_uplift(example):
    ns, _, _ = example
    runs, weak = ns["runs"], ns["weak"]
    free = runs[(runs["mitigation"] == "none") & (runs["status"] == 0)]
    assert free["overturned"].any() and not free["overturned"].all()
    # a block that never lifts off cannot overturn: the floor's peak reached the uplift
    over = free[free["overturned"]]
    assert (over["floor_pga"] >= weak.uplift_g * G * (1 - 1e-6)).all()
    # the floor amplifies the ground: floor 3 of 5 in the first mode
    assert (free["floor_pga"] > free["pga"]).all()


def test_risk_intervals(example):
    ns, _, _ = example
    rk = ns["rk"]
    fitted = rk[np.isfinite(rk["annual_frequency"])]
    assert len(fitted) >= 2
    for _, r in fitted.iterrows():
        lam = r["annual_frequency"]
        assert r["annual_frequency_low"] <= lam <= r["annual_frequency_high"]
        for p, x in (("probability", lam), ("probability_low", r["annual_frequency_low"]),
                     ("probability_high", r["annual_frequency_high"])):
            assert r[p] == pytest.approx(-math.expm1(-r["t_years"] * x), rel=1e-6)


def test_isolator_room_is_ec8_displacement(example):
    from rocking.motions import ec8_spectrum
    ns, _, _ = example
    iso = ns["iso"]
    a475 = iso["im_475yr"]                                           # ground PGA, m/s^2
    assert a475 == pytest.approx(0.25 * G, rel=1e-6)                 # the code value
    sa = ec8_spectrum(2.5, a475, "C", 1, damping=0.10)               # m/s^2
    sd = sa * (2.5 / (2 * math.pi)) ** 2
    # 3rd floor of a 0.5 s building at 2.5 s: close to the ground (within 15 %); the
    # records match the spectrum within 10 %
    assert iso["displacement_median_475yr"] == pytest.approx(sd, rel=0.25)
    # a linear isolator: the displacement scales with the ground motion
    ratio = iso["displacement_median_2475yr"] / iso["displacement_median_475yr"]
    assert ratio == pytest.approx(iso["im_2475yr"] / a475, rel=0.10)


def test_verdicts_follow_the_ratios(example):
    ns, _, _ = example
    t = ns["cmp"].table.set_index("mitigation")
    assert t.loc["none", "verdict"] == "reference"
    for m in ("isolated", "anchored"):
        r = t.loc[m, "annual_frequency_ratio"]
        if np.isfinite(r):
            lo, hi = t.loc[m, "annual_frequency_low"], t.loc[m, "annual_frequency_high"]
            lo0, hi0 = (t.loc["none", "annual_frequency_low"],
                        t.loc["none", "annual_frequency_high"])
            overlap = lo <= hi0 and lo0 <= hi  # the intervals: within the records' noise
            assert t.loc[m, "verdict"] == ("not distinguishable" if overlap else
                                           "better" if r < 1 else "worse")
