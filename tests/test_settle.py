"""Runs end when the block has settled (issue 16, section 1): with the default duration a
run goes on after the motion, with the ground still, until the block is at rest or has
overturned; ``settled`` says whether it was; the classical model decides a block still
rocking at the cap exactly, by energy."""

from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import rocking
from rocking import ParameterError
from rocking.models.housner import free_outcome
from rocking.motions import (
    GroundMotion,
    HalfSine,
    HanningSine,
    MavroeidisPapageorgiou,
    OneCosine,
    OneSine,
    Record,
    Rectangular,
    Ricker,
    Sine,
)
from rocking.testing.housner_reference import simulate_reference

TP = 0.5  # s
AP = 2.5  # m/s^2: overturns specimen 2 (E) about 1 s after the pulse has ended


def _one_sine_record(ap=AP, tp=TP, dt=0.001) -> Record:
    """A one-sine pulse sampled as a record that ends with the pulse (Zhang and Makris
    2001): the block overturns in the free motion that follows it."""
    t = np.arange(int(round(tp / dt)) + 1) * dt
    return Record(ap * np.sin(2.0 * np.pi * t / tp), dt, name="one-sine")


@pytest.fixture(scope="module")
def block():
    return rocking.specimen(2, "experimental")


# --------------------------------------------------------------- the pulse that ends early
@pytest.mark.parametrize("model", ["housner", "ccrr", "dem"])
def test_a_pulse_record_overturns_after_its_end(block, model):
    rec = _one_sine_record()
    cut = rocking.simulate(block, rec, model=model, duration=rec.duration)
    assert not cut.overturned and not cut.settled  # still moving when the record ends
    full = rocking.simulate(block, rec, model=model)
    assert full.overturned and full.settled
    assert full.overturn_time > rec.duration + 0.5
    # the DEM steps past pi/2 by a fraction of its time step
    assert full.max_abs_theta == pytest.approx(0.5 * math.pi, abs=1e-3 if model == "dem"
                                               else 1e-12)


@pytest.mark.parametrize("model", ["housner", "ccrr"])
def test_batches_overturn_too_and_equal_single_runs(block, model):
    recs = [_one_sine_record(ap) for ap in (1.8, AP, 3.0)]
    batch = rocking.simulate_many(block, recs, model=model)
    cut = rocking.simulate_many(block, recs, model=model, duration=TP)
    assert list(batch.overturned) == [False, True, True]
    assert not cut.overturned.any() and not cut.settled[1:].any()
    assert batch.settled.all()
    for i, r in enumerate(recs):
        one = rocking.simulate(block, r, model=model)
        assert batch.max_abs_theta[i] == one.max_abs_theta
        assert batch.n_impacts[i] == one.n_impacts
        assert batch.settled[i] == one.settled
        assert (batch.overturn_time[i] == one.overturn_time
                or (math.isnan(batch.overturn_time[i]) and math.isnan(one.overturn_time)))


def test_ida_rows_overturn_after_the_record(block):
    import rocking.analysis as A

    rec = _one_sine_record()
    table = A.ida(block, [rec], im="pga", levels=[AP])
    assert bool(table["overturned"].iloc[0])
    assert bool(table["settled"].iloc[0])
    cut = A.ida(block, [rec], im="pga", levels=[AP], duration=TP)
    assert not bool(cut["overturned"].iloc[0]) and not bool(cut["settled"].iloc[0])


# ------------------------------------------------------------- the energy decision (exact)
@pytest.mark.parametrize("linear", [False, True])
def test_energy_decision_equals_integration_to_the_end(block, linear):
    """At the cap of the free motion the classical model decides by energy; with a long
    cap it integrates to rest or to the overturn: same outcome, same maximum angle."""
    worst = 0.0
    n_over = 0
    for ap in np.linspace(1.7, 3.0, 14):
        rec = _one_sine_record(ap)
        long = rocking.simulate(block, rec, linear=linear, max_free_time=120.0)
        assert long.settled
        for cap in (0.0, 0.05, 0.3):
            r = rocking.simulate(block, rec, linear=linear, max_free_time=cap)
            assert r.settled
            assert r.overturned == long.overturned
            if long.overturned:
                assert r.overturn_time == pytest.approx(long.overturn_time, abs=1e-9)
            else:
                worst = max(worst, abs(r.max_abs_theta / long.max_abs_theta - 1.0))
        n_over += long.overturned
    assert 0 < n_over < 14  # both outcomes are exercised
    assert worst < 1e-8


def test_energy_decision_agrees_with_the_scipy_reference(block):
    """The reference integrates the free motion with solve_ivp to rest: the compiled
    model's decision at a zero-length cap gives its outcome and maximum."""
    for ap in (2.0, 2.25, 2.4, 2.5):
        rec = _one_sine_record(ap)
        ref = simulate_reference(block, rec, max_free_time=120.0)
        dec = rocking.simulate(block, rec, max_free_time=0.0)
        assert ref.settled and dec.settled
        assert dec.overturned == ref.overturned
        if not ref.overturned:
            assert dec.max_abs_theta == pytest.approx(ref.max_abs_theta, rel=1e-6)


def test_free_outcome_closed_form(block):
    """free_outcome against hand computations: energy above the top while moving away
    overturns; moving towards the rest position, one impact multiplies the energy above
    the rest position by mu^2 first; past alpha it falls unless it comes back over."""
    a, p2, mu = block.alpha, block.p ** 2, block.mu
    top = p2
    # at theta = 0.5 alpha moving away with just less / more than the energy of the top
    th = 0.5 * a
    om_top = math.sqrt(2.0 * (top - p2 * math.cos(a - th)))
    assert not free_outcome(th, 0.999 * om_top, 1.0, a, p2, mu, False)[0]
    assert free_outcome(th, 1.001 * om_top, 1.0, a, p2, mu, False)[0]
    # the amplitude: alpha - acos(E / p^2)
    om = 0.5 * om_top
    e = 0.5 * om ** 2 + p2 * math.cos(a - th)
    assert free_outcome(th, om, 1.0, a, p2, mu, False)[1] == pytest.approx(
        a - math.acos(e / p2), rel=1e-14)
    # moving towards 0 with 1.001 x the energy of the top: overturns iff mu^2 keeps it above
    e_bottom = p2 * math.cos(a)
    om = -1.02 * om_top
    e = 0.5 * om ** 2 + p2 * math.cos(a - th)
    after = e_bottom + mu ** 2 * (e - e_bottom)
    assert free_outcome(th, om, 1.0, a, p2, mu, False)[0] == (after > top)
    assert free_outcome(th, om, 1.0, a, p2, 1.0, False)[0]  # no loss at the impact
    # past alpha: moving away falls; moving back without the energy of the top falls
    assert free_outcome(1.2 * a, 0.01, 1.0, a, p2, mu, False)[0]
    assert free_outcome(1.2 * a, -1e-3, 1.0, a, p2, mu, False)[0]
    # symmetric in the sign of theta
    for th, om in ((0.3 * a, 0.7), (0.3 * a, -0.7), (0.8 * a, 0.1)):
        assert (free_outcome(th, om, 1.0, a, p2, mu, False)
                == free_outcome(-th, -om, -1.0, a, p2, mu, False))


# ------------------------------------------------------------------------ settled, window
def test_free_rocking_without_duration_runs_to_rest(block):
    r = rocking.simulate(block, None, theta0=0.5 * block.alpha)
    assert r.settled and not r.overturned
    assert abs(r.theta[-1]) < 1e-3 * block.alpha  # the last sample, before rest at 1e-3
    assert r.duration < 60.0
    # Zeno: the half-cycles shrink geometrically, the total time is finite:
    # sum (2/p) sqrt(2 a_k) with a_{k+1} = mu^2 a_k is at most 2 sqrt(2 a0)/(p (1 - mu))
    bound = 2.0 * math.sqrt(2.0 * 0.5) / (block.p * (1.0 - block.mu))
    assert r.duration < 1.2 * bound


@pytest.mark.parametrize("model", ["housner", "ccrr"])
def test_the_free_rest_threshold_changes_only_the_impact_count(block, model):
    """Once the ground is still nothing can lift the block again: putting it to rest at
    1e-3 alpha instead of 1e-12 alpha (1e-6 for CCRR) changes no outcome and no maximum
    angle, only the number of (micro-)impacts counted."""
    from rocking.motions import stochastic_records

    recs = stochastic_records(6, duration=20.0, dt=0.01, seed=4)
    ms = [r.scaled(f) for r in recs for f in (0.6, 1.0, 1.4, 1.8)]
    fast = rocking.simulate_many(block, ms, model=model)
    fine = rocking.simulate_many(block, ms, model=model, free_rest_tol=1e-12)
    np.testing.assert_array_equal(fast.overturned, fine.overturned)
    np.testing.assert_allclose(fast.max_abs_theta, fine.max_abs_theta, rtol=1e-12)
    assert fast.settled.all() and fine.settled.all()
    rocked = ~fast.overturned & (fast.n_impacts > 0)
    assert rocked.sum() >= 3
    assert (fine.n_impacts[rocked] >= fast.n_impacts[rocked]).all()
    assert (fine.n_impacts[rocked] > fast.n_impacts[rocked]).any()


def test_explicit_duration_keeps_its_meaning(block):
    m = Sine(5.0, 0.005, 4.0)
    r = rocking.simulate(block, m, duration=3.0)
    assert r.t[-1] == pytest.approx(3.0)
    full = rocking.simulate(block, m, duration=3.0, dt_out=0.01)
    assert full.t[-1] == pytest.approx(3.0)


def test_default_run_covers_the_whole_motion(block):
    """A block at rest all along stops at the end of the motion, not before."""
    m = Sine(1.0, 1e-4, 7.0)  # far below uplift
    r = rocking.simulate(block, m)
    assert r.settled and r.uplift_time != r.uplift_time
    assert r.t[-1] == pytest.approx(7.0)


def test_window_errors(block):
    m = OneSine(3.0, 0.5)
    with pytest.raises(ParameterError, match="max_free_time"):
        rocking.simulate(block, m, duration=2.0, max_free_time=5.0)
    with pytest.raises(ParameterError, match="max_free_time"):
        rocking.simulate_many(block, [m], max_free_time=-1.0)
    with pytest.raises(ParameterError, match="linear"):
        rocking.simulate(block, m, linear="false")
    with pytest.raises(ParameterError, match="max_impacts"):
        rocking.simulate(block, m, max_impacts=1.5)


@pytest.mark.parametrize("motion", [
    Sine(3.0, 0.004, 2.0), HanningSine(2.0, 0.01, 3.0), OneSine(3.0, 0.4, t0=0.2),
    OneCosine(2.0, 0.3), HalfSine(2.0, 0.7), Rectangular(1.0, 0.25, t0=0.1),
    Ricker(3.0, 2.0), MavroeidisPapageorgiou(2.0, 1.5, 2.0, 0.3),
    GroundMotion(Sine(3.0, 0.004, 2.0), OneSine(2.0, 0.5, t0=1.9)),
])
def test_the_ground_is_still_after_quiet_time(motion):
    """What the tail relies on: zero acceleration (both components) after quiet_time."""
    t = motion.quiet_time + np.linspace(1e-9, 20.0, 4001)
    peak = max(abs(motion.acceleration(np.linspace(0.0, motion.quiet_time, 4001))).max(), 1.0)
    assert np.abs(motion.acceleration(t)).max() <= 1e-15 * peak
    if isinstance(motion, GroundMotion):
        assert np.abs(motion.vertical.acceleration(t)).max() <= 1e-15 * peak
    # and not before: quiet_time is where the motion ends, not later than needed
    tb = motion.quiet_time - np.linspace(1e-6, 0.05, 200)
    last = motion.vertical if isinstance(motion, GroundMotion) else motion
    assert np.abs(last.acceleration(tb)).max() > 0.0 or isinstance(motion, Ricker)


def test_dem_comes_to_rest_after_a_weak_pulse(block):
    rec = _one_sine_record(1.8)
    r = rocking.simulate(block, rec, model="dem", max_free_time=30.0)
    assert r.settled and not r.overturned
    assert r.duration < 30.0  # stopped at rest, not at the cap
    assert abs(r.theta[-1]) <= 1e-3 * block.alpha


def _cli(*args):
    exe = Path(sys.executable).parent / "rocking"
    cmd = [str(exe)] if exe.exists() else [sys.executable, "-m", "rocking.cli"]
    return subprocess.run([*cmd, *args], capture_output=True, text=True, timeout=120)


def test_cli_warns_when_still_rocking():
    args = ["simulate", "--specimen", "2", "--params", "experimental", "--motion", "one_sine",
            "--tp", "0.5s", "--amp", f"{AP}m/s2"]
    cut = _cli(*args, "--duration", "0.5")
    assert cut.returncode == 0, cut.stderr
    assert "overturned  no" in cut.stdout
    err = cut.stderr.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("warning: still rocking at the end")
    assert "extend --duration" in err[0]
    full = _cli(*args)
    assert full.returncode == 0, full.stderr
    assert "overturned  yes" in full.stdout and full.stderr == ""
    bad = _cli(*args, "--duration", "0.5", "--max-free-time", "3")
    assert bad.returncode == 2 and bad.stderr.startswith("error: max-free-time")


def test_settled_in_summaries(block):
    rec = _one_sine_record()
    r = rocking.simulate(block, rec, duration=TP)
    assert r.summary()["settled"] is False
    b = rocking.simulate_many(block, [rec, rec], duration=TP)
    assert b.summary()["n_unsettled"] == 2
    assert list(b.to_dataframe()["settled"]) == [False, False]
