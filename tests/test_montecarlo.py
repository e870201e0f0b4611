"""Monte Carlo, Wilson intervals and the rocking-motion space (rocking.analysis)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import rocking
from rocking import G, ParameterError
from rocking.analysis.harmonic import motion_space
from rocking.analysis.montecarlo import monte_carlo, wilson_interval
from rocking.motions import Rectangular, Sine


@pytest.mark.parametrize("p", [0.05, 0.3, 0.5])
def test_wilson_interval_covers_a_known_bernoulli_p_at_its_nominal_rate(p):
    rng = np.random.default_rng(1)
    n, reps = 120, 3000
    ks = rng.binomial(n, p, reps)
    cover = np.mean([lo <= p <= hi for lo, hi in (wilson_interval(k, n, 0.95) for k in ks)])
    # Wilson's interval is close to nominal (Brown, Cai and DasGupta 2001): 0.93-0.97
    assert 0.93 <= cover <= 0.97, cover


def _rectangular_case():
    """Linear classical model under a rectangular pulse: it overturns iff the amplitude
    exceeds a_min = g alpha / (1 - exp(-p t1)) (Housner 1963); with an amplitude factor
    uniform on (0.8, 1.3) x a_min, P(overturn) = (1.3 - 1) / 0.5 = 0.6 exactly."""
    blk = rocking.Block.from_params(alpha=0.15, p=3.0, mu=0.9)
    t1 = 1.0 / blk.p
    a_min = G * blk.alpha / (1.0 - math.exp(-1.0))
    pulse = Rectangular(a_min, t1, duration=t1 + 20.0 / blk.p)
    return blk, pulse, {"amplitude": {"dist": "uniform", "low": 0.8, "high": 1.3}}, 0.6


def test_monte_carlo_probability_matches_a_closed_form():
    blk, pulse, unc, p_true = _rectangular_case()
    res = monte_carlo(blk, pulse, unc, n=400, seed=5, linear=True, rtol=1e-10)
    lo, hi = res.ci
    assert lo <= p_true <= hi
    # every sample's outcome is the closed-form one, away from the threshold itself
    s = res.samples
    clear = np.abs(s["amplitude"] - 1.0) > 0.005
    np.testing.assert_array_equal(s.loc[clear, "overturned"], s.loc[clear, "amplitude"] > 1.0)
    # the drawn factors are uniform on (0.8, 1.3)
    assert s["amplitude"].between(0.8, 1.3).all()
    assert abs(s["amplitude"].mean() - 1.05) < 4 * 0.5 / math.sqrt(12 * 400)


def test_monte_carlo_same_seed_same_result_whatever_the_chunking():
    blk = rocking.specimen(2, "experimental")
    m = Sine(3.0, 0.008, 6.0)
    unc = {"alpha": {"dist": "normal", "cov": 0.03}, "p": {"dist": "lognormal", "beta": 0.05},
           "mu": {"dist": "uniform", "low": 0.95, "high": 0.99},
           "theta0": {"dist": "normal", "mean": 0.0, "std": 0.002},
           "noise": {"dist": "uniform", "low": 0.0, "high": 0.05}}
    a = monte_carlo(blk, m, unc, n=24, seed=9, chunk_size=24)
    b = monte_carlo(blk, m, unc, n=24, seed=9, chunk_size=5)
    c = monte_carlo(blk, m, unc, n=24, seed=10)
    assert a.samples.equals(b.samples)
    assert not a.samples["alpha"].equals(c.samples["alpha"])
    # the first samples of a larger study are the samples of a smaller one
    d = monte_carlo(blk, m, unc, n=30, seed=9)
    assert d.samples.iloc[:24].equals(a.samples)
    assert a.samples["max_abs_theta"].nunique() == 24  # the draws matter
    json_ready = a.to_dict()
    assert json_ready["n"] == 24 and len(json_ready["samples"]["alpha"]) == 24


def test_monte_carlo_bad_input():
    blk = rocking.specimen(2)
    m = Sine(3.0, 0.008, 2.0)
    with pytest.raises(ParameterError, match="unknown parameter.*height"):
        monte_carlo(blk, m, {"height": {"dist": "normal", "std": 0.1}}, n=2)
    with pytest.raises(ParameterError, match="dist"):
        monte_carlo(blk, m, {"alpha": {"dist": "cauchy"}}, n=2)
    with pytest.raises(ParameterError, match="exactly one of 'std' or 'cov'"):
        monte_carlo(blk, m, {"alpha": {"dist": "normal"}}, n=2)
    with pytest.raises(ParameterError, match="n must be"):
        monte_carlo(blk, m, {}, n=0)
    with pytest.raises(ParameterError, match="seed"):
        monte_carlo(blk, m, {}, n=2, seed=-1)


def test_motion_space_uplift_criterion_and_single_runs():
    """A constant sine uplifts a block at rest iff its acceleration amplitude exceeds
    g tan(alpha); each cell is the single run of that sine."""
    blk = rocking.specimen(2, "experimental")
    freqs, amps = [1.0, 2.0, 3.3, 5.0], [0.003, 0.006, 0.010]
    df = motion_space(blk, freqs, amps, duration=8.0)
    assert len(df) == len(freqs) * len(amps)
    clear = np.abs(df["acc_ratio"] - 1.0) > 0.01
    np.testing.assert_array_equal(df.loc[clear, "rocked"], df.loc[clear, "acc_ratio"] > 1.0)
    assert df["rocked"].any() and (~df["rocked"]).any()
    for _, row in df.sample(4, random_state=0).iterrows():
        r = rocking.simulate(blk, Sine(row["freq"], row["amplitude"], 8.0))
        assert row["max_abs_theta"] == r.max_abs_theta
    with pytest.raises(ParameterError, match="kind"):
        motion_space(blk, freqs, amps, kind="square")
    with pytest.raises(ParameterError, match="freqs"):
        motion_space(blk, [-1.0], amps)


# ----------------------------------------------------------------------------- IDA
def test_ida_scales_records_to_the_levels_and_runs_them(paper_set):
    from rocking.analysis.ida import ida, ida_capacity, intensity, plot_ida

    blk = rocking.specimen(3, "experimental")
    recs = paper_set[:4]
    ratio_levels = np.array([0.6, 1.0, 1.5, 2.5, 4.0])
    t = ida(blk, recs, im="pga_ratio", levels=ratio_levels)
    assert len(t) == len(recs) * ratio_levels.size
    for _, row in t.sample(5, random_state=1).iterrows():
        m = recs[int(row["record"])].scaled(row["scale"])
        assert intensity(m, "pga_ratio", blk) == pytest.approx(row["im"], rel=1e-12)
        r = rocking.simulate(blk, m)
        assert r.max_abs_theta == row["max_abs_theta"] and r.overturned == row["overturned"]
    # below the uplift level nothing moves; the damage state follows the angle
    assert not t.loc[t["im"] < 1.0, "overturned"].any()
    assert (t.loc[t["im"] < 1.0, "max_abs_theta"] == 0.0).all()
    assert (t.loc[t["overturned"], "damage_state"] == 3).all()
    cap = ida_capacity(t)
    assert len(cap) == len(recs)
    for _, c in cap.iterrows():
        g = t[t["record"] == c["record"]].sort_values("im")
        if c["censored"]:
            assert not g["overturned"].any()
        else:
            assert g.loc[g["im"] == c["capacity"], "overturned"].all()
            assert not g.loc[g["im"] < c["capacity"], "overturned"].any()
    # every intensity measure: the scaled records have exactly the requested level
    for im in ("pga", "pgv", "arias"):
        lv = np.array([0.5, 2.0]) * intensity(recs[0], im)
        ti = ida(blk, recs[:2], im=im, levels=lv, duration=2.0)
        for _, row in ti.iterrows():
            m = recs[int(row["record"])].scaled(row["scale"])
            assert intensity(m, im) == pytest.approx(row["im"], rel=1e-9), im
    # a table where nothing overturns: every capacity is censored at the top level
    low = ida(blk, recs[:2], im="pga_ratio", levels=[0.5, 0.8], duration=2.0)
    c = ida_capacity(low)
    assert c["censored"].all() and (c["capacity"] == 0.8).all()
    with pytest.raises(ParameterError, match="state must be in"):
        ida_capacity(low, state=9)
    with pytest.raises(ParameterError, match="thresholds"):
        ida(blk, recs, levels=[1.0], thresholds=(0.5, 0.2))
    ax = plot_ida(t)
    assert len(ax.lines) >= len(recs)
    with pytest.raises(ParameterError, match="im must be one of"):
        ida(blk, recs, im="sa", levels=[1.0])
    with pytest.raises(ParameterError, match="levels"):
        ida(blk, recs, levels=[-1.0])


def test_draws_are_those_of_scipy_rvs_bit_for_bit():
    """The one-draw functions made once per distribution (issue 33: scipy's per-call
    checks were most of a campaign row's time) give ``dist.rvs(random_state=rng)`` bit for
    bit and leave the generator in the same state."""
    from rocking.analysis.distributions import _sampler, frozen

    cases = [("alpha", {"dist": "normal", "cov": 0.015}, 0.2),
             ("theta0", {"dist": "normal", "mean": 0.0, "std": 0.001745}, 0.0),
             ("mu", {"dist": "lognormal", "median": 0.93, "beta": 0.05}, 0.93),
             ("noise", {"dist": "uniform", "low": 0.0, "high": 0.05}, 0.0),
             ("amplitude", {"dist": "fixed", "value": 1.1}, 1.0)]
    for name, spec, nominal in cases:
        d = frozen(name, spec, nominal)
        one = _sampler(d)
        assert _sampler(d) is one  # made once
        for seed in range(200):
            r1, r2 = np.random.default_rng(seed), np.random.default_rng(seed)
            for _ in range(3):
                a, b = float(d.rvs(random_state=r1)), one(r2)
                assert np.float64(a).tobytes() == np.float64(b).tobytes(), (spec, seed)
            assert r1.bit_generator.state == r2.bit_generator.state
