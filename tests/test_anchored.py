"""Anchored blocks (issue 19, part 2): the plain reference
:mod:`rocking.testing.anchored_reference` against closed forms and the classical model.

Tolerances. Uplift times are located by bisection to rounding: they are checked to 1e-9 s,
the precision of the classical model's uplift tests (``tests/test_housner.py``). With
anchors of zero strength (or after both anchors have broken) the reference integrates
Eq (1) with ``solve_ivp`` (DOP853, ``rtol = 1e-10``) while :func:`rocking.simulate` runs
the compiled classical kernel (``rtol = 1e-8``): on the motions below they differ by at
most 2e-10 s in overturning times, 1e-9 s in impact times and 1e-8 (relative) in the
largest angle, except under the 2 Hz sine, whose slow final rocking amplifies the
integration error of each impact (the classical reference of
:mod:`rocking.testing.housner_reference` differs from the kernel by the same 6e-7 s there):
the bounds below are these measured differences times about 5.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import rocking
from rocking import ParameterError
from rocking.motions import OneSine, Rectangular, Sine
from rocking.testing.anchored_reference import simulate_anchored_reference as anchored
from rocking.testing.records import random_record
from rocking.units import G

BLOCK = rocking.specimen(2, "experimental")
THR = G * math.tan(BLOCK.alpha)  # the free block's uplift acceleration
RIGID = math.inf
LAWS = [RIGID, 30.0]  # rigid (Makris and Zhang 2001) and elastic anchors


def rigid_threshold(q):
    """Uplift acceleration of a block held by rigid anchors of strength q = F_a/(m g):
    m a h = m g b + 2 b F_a."""
    return THR * (1.0 + 2.0 * q)


# ------------------------------------------------------------------------- uplift
@pytest.mark.parametrize("q", [0.25, 1.0])
def test_rigid_anchors_uplift_at_gravity_plus_anchor_moment_under_sine(q):
    thr, f = rigid_threshold(q), 2.0
    below = anchored(BLOCK, Sine.from_acceleration(f, 0.99 * thr, duration=1.0), 1.0, q)
    assert math.isnan(below.uplift_time) and below.max_abs_theta == 0.0
    assert below.anchor_broken == (False, False) and below.n_impacts == 0
    # the anchor carries (a/(g tan alpha) - 1)/2 of the weight while the block is down
    assert below.max_anchor_force == pytest.approx((0.99 * (1 + 2 * q) - 1) / 2, rel=1e-4)
    assert below.max_anchor_force_n == pytest.approx(below.max_anchor_force * BLOCK.mass * G)
    above = anchored(BLOCK, Sine.from_acceleration(f, 1.01 * thr, duration=1.0), 1.0, q)
    # a(t) = -A sin(2 pi f t) first exceeds thr at asin(1/1.01)/(2 pi f), with a < 0:
    t_up = math.asin(1 / 1.01) / (2 * math.pi * f)
    assert above.uplift_time == pytest.approx(t_up, abs=1e-9)
    # the anchor on the lifting side (theta < 0) reached its strength there and broke
    assert above.anchor_broken[1] and above.anchor_break_time[1] == above.uplift_time
    assert above.max_anchor_force == q
    assert above.theta[np.flatnonzero(above.theta != 0.0)[0]] < 0.0


@pytest.mark.parametrize("q", [0.1, 0.5])
def test_rigid_anchors_uplift_at_threshold_under_rectangular_pulse_and_ramp(q):
    thr = rigid_threshold(q)
    late = anchored(BLOCK, Rectangular(1.001 * thr, 0.1, t0=0.3, duration=1.0), 1.0, q)
    assert late.uplift_time == pytest.approx(0.3, abs=1e-9)
    assert late.anchor_broken[0] and late.anchor_break_time[0] == late.uplift_time
    weak = anchored(BLOCK, Rectangular(0.999 * thr, 0.5, duration=1.0), 1.0, q)
    assert math.isnan(weak.uplift_time) and weak.max_abs_theta == 0.0
    assert weak.max_anchor_force == pytest.approx((0.999 * (1 + 2 * q) - 1) / 2, rel=1e-12)
    # a slowly increasing acceleration a = c t (a plain function): uplift at thr / c
    c = thr / 2.0
    ramp = anchored(BLOCK, lambda t: c * t, 2.5, q, scan_step=0.01)
    assert ramp.uplift_time == pytest.approx(2.0, abs=1e-9)
    assert ramp.anchor_break_time[0] == ramp.uplift_time


def test_elastic_anchors_leave_the_uplift_threshold_unchanged_and_break_at_strength():
    """Not pre-tensioned, an elastic anchor carries no force at theta = 0: the block
    uplifts at g tan(alpha); it breaks where kappa sin|theta| reaches q."""
    kappa, q, f = 30.0, 0.05, 2.0
    above = anchored(BLOCK, Sine.from_acceleration(f, 1.01 * THR, duration=1.0), 1.0, q,
                     kappa)
    assert above.uplift_time == pytest.approx(math.asin(1 / 1.01) / (2 * math.pi * f),
                                              abs=1e-9)
    below = anchored(BLOCK, Sine.from_acceleration(f, 0.99 * THR, duration=1.0), 1.0, q,
                     kappa)
    assert math.isnan(below.uplift_time) and below.max_anchor_force == 0.0
    r = anchored(BLOCK, OneSine(2.0 * THR, 0.3, duration=0.3), 1.0, q, kappa)
    assert r.anchor_broken == (True, True)
    for side, t_b in zip((1.0, -1.0), r.anchor_break_time, strict=True):
        th, _ = r.state_at(t_b)
        assert side * th > 0.0
        assert kappa * math.sin(abs(th)) == pytest.approx(q, rel=1e-9)
    assert r.max_anchor_force == q


def test_strong_elastic_anchors_hold_below_strength():
    kappa, q = 30.0, 10.0
    r = anchored(BLOCK, OneSine(2.0 * THR, 0.3, duration=0.3), 1.5, q, kappa)
    assert r.anchor_broken == (False, False) and not r.overturned
    assert 0.0 < r.max_anchor_force < q
    assert r.max_anchor_force == pytest.approx(kappa * math.sin(r.max_abs_theta), rel=1e-9)


# ------------------------------------------------------- zero strength: the free block
MOTIONS = [(OneSine(3 * THR, 0.5, duration=3.0), 3.0),
           (Sine.from_acceleration(2.0, 1.5 * THR, duration=3.0), 4.0),
           (random_record(7, 0.4 * G), 8.0)]


@pytest.mark.parametrize("kappa", LAWS, ids=["rigid", "elastic"])
@pytest.mark.parametrize("case", range(len(MOTIONS)), ids=["pulse", "sine", "record"])
def test_zero_strength_anchors_give_the_free_block(case, kappa):
    motion, t_end = MOTIONS[case]
    r = anchored(BLOCK, motion, t_end, 0.0, kappa)
    free = rocking.simulate(BLOCK, motion, duration=t_end)
    assert r.overturned == free.overturned
    if free.overturned:
        assert r.overturn_time == pytest.approx(free.overturn_time, abs=5e-8)
    assert r.uplift_time == pytest.approx(free.uplift_time, abs=1e-12)
    assert r.max_abs_theta == pytest.approx(free.max_abs_theta, rel=1e-7)
    assert r.n_impacts == free.n_impacts
    np.testing.assert_allclose(r.impact_times, free.impact_times, rtol=0, atol=5e-6)
    assert r.max_anchor_force == 0.0


# ------------------------------------------------ after both anchors break: classical
@pytest.mark.parametrize(("kappa", "q"), [(RIGID, 0.2), (30.0, 0.05)],
                         ids=["rigid", "elastic"])
def test_after_both_anchors_break_the_block_is_classical(kappa, q):
    t_p, t_end = 0.3, 2.0
    r = anchored(BLOCK, OneSine(2.0 * THR, t_p, duration=t_p), t_end, q, kappa)
    assert r.anchor_broken == (True, True) and max(r.anchor_break_time) < t_p
    th0, om0 = r.state_at(t_p)  # both broken, the ground still from here
    assert abs(th0) > 0.01 * BLOCK.alpha
    free = rocking.simulate(BLOCK, None, duration=t_end - t_p, theta0=th0, omega0=om0,
                            rtol=1e-10, dt_out=0.01)
    later = r.impact_times[r.impact_times > t_p] - t_p
    assert later.size == free.n_impacts > 0
    np.testing.assert_allclose(later, free.impact_times, rtol=0, atol=1e-8)
    th = np.array([r.state_at(t_p + t)[0] for t in free.t])
    np.testing.assert_allclose(th, free.theta, rtol=0, atol=1e-7 * BLOCK.alpha)


# ------------------------------------------------------------ anchors and overturning
def test_strong_anchors_prevent_overturning_under_a_toppling_pulse():
    pulse = OneSine(2.5 * THR, 1.0, duration=1.0)
    assert rocking.simulate(BLOCK, pulse, duration=3.0).overturned
    assert anchored(BLOCK, pulse, 3.0, 0.0).overturned
    rigid = anchored(BLOCK, pulse, 3.0, 1.0)  # uplift needs 3 g tan(alpha)
    assert not rigid.overturned and math.isnan(rigid.uplift_time)
    assert rigid.max_abs_theta == 0.0 and rigid.anchor_broken == (False, False)
    assert rigid.max_anchor_force == pytest.approx(0.75, rel=1e-4)  # (2.5 - 1)/2
    elastic = anchored(BLOCK, pulse, 3.0, 10.0, 30.0)
    assert not elastic.overturned and elastic.anchor_broken == (False, False)
    assert elastic.max_abs_theta < BLOCK.alpha
    weak = anchored(BLOCK, pulse, 3.0, 0.2)  # it breaks, and the block falls
    assert weak.overturned and weak.anchor_broken[0]


def test_bad_anchor_parameters_are_refused():
    motion = OneSine(THR, 0.5)
    with pytest.raises(ParameterError, match="anchor_strength"):
        anchored(BLOCK, motion, 1.0, -0.1)
    with pytest.raises(ParameterError, match="anchor_stiffness"):
        anchored(BLOCK, motion, 1.0, 0.1, 0.0)
    with pytest.raises(ParameterError, match="scan_step"):
        anchored(BLOCK, lambda t: 0.0, 1.0, 0.1)


def test_stiff_elastic_anchors_tend_to_the_rigid_law():
    """Under a slow ramp a = c t a stiff elastic anchor breaks where the rigid one lets the
    block uplift, g tan(alpha) (1 + 2 q) (the quasi-static limit kappa -> inf; measured:
    -1e-2, -1.6e-3, 2e-5 for kappa = 1e2, 1e3, 1e4)."""
    q, t_ramp = 0.3, 20.0
    c = rigid_threshold(q) / t_ramp
    gaps = []
    for kappa in (1e2, 1e3, 1e4):
        r = anchored(BLOCK, lambda t: c * t, 1.1 * t_ramp, q, kappa, scan_step=0.01)
        assert r.uplift_time == pytest.approx(THR / c, rel=1e-12)  # gravity's threshold
        assert r.anchor_broken[0] and r.max_anchor_force == q
        gaps.append(abs(c * r.anchor_break_time[0] / rigid_threshold(q) - 1.0))
    assert gaps[0] > gaps[1] > gaps[2] and gaps[2] < 1e-4


@pytest.mark.parametrize("kappa", LAWS, ids=["rigid", "elastic"])
def test_negated_motion_mirrors_the_response_and_swaps_the_anchors(kappa):
    pulse = OneSine(2.0 * THR, 0.3, duration=0.3)
    a = anchored(BLOCK, pulse, 2.0, 0.05, kappa)
    b = anchored(BLOCK, -pulse, 2.0, 0.05, kappa)
    assert a.max_abs_theta == b.max_abs_theta
    np.testing.assert_array_equal(a.impact_times, b.impact_times)
    assert a.anchor_break_time == b.anchor_break_time[::-1]
    np.testing.assert_array_equal(a.theta, -b.theta)


# ------------------------------------------------- the compiled model (model="anchored")
AGREE = [(OneSine(2 * THR, 0.3, duration=0.3), 2.0), (OneSine(3 * THR, 0.5, duration=3.0), 3.0),
         (Sine.from_acceleration(2.0, 1.5 * THR, duration=3.0), 4.0),
         (random_record(7, 0.4 * G), 8.0)]
ANCHORS = [("rigid", RIGID, 0.2), ("elastic", 30.0, 0.05), ("elastic", 30.0, 10.0),
           ("rigid", RIGID, 0.0)]


@pytest.mark.parametrize("law", range(len(ANCHORS)),
                         ids=["rigid", "elastic", "elastic-strong", "rigid-zero"])
@pytest.mark.parametrize("case", range(len(AGREE)), ids=["short", "pulse", "sine", "record"])
def test_compiled_model_agrees_with_the_reference(case, law):
    """Measured (compiled at rtol 1e-10 against the reference at 1e-10): max angle within
    1.1e-8 alpha, break times 1e-10 s, impact times 1.3e-8 s (5.6e-7 s under the sine,
    see the module docstring), uplift times 1e-16 s."""
    motion, t_end = AGREE[case]
    anchors, kappa, q = ANCHORS[law]
    ref = anchored(BLOCK, motion, t_end, q, kappa)
    res = rocking.simulate(BLOCK, motion, model="anchored", duration=t_end, anchors=anchors,
                           anchor_strength=q, anchor_stiffness=30.0, rtol=1e-10)
    assert res.overturned == ref.overturned and res.n_impacts == ref.n_impacts
    if ref.overturned:
        assert res.overturn_time == pytest.approx(ref.overturn_time, abs=1e-8)
    assert res.uplift_time == pytest.approx(ref.uplift_time, abs=1e-12)
    assert res.max_abs_theta == pytest.approx(ref.max_abs_theta, abs=1e-7 * BLOCK.alpha)
    np.testing.assert_allclose(res.impact_times, ref.impact_times, rtol=0, atol=3e-6)
    info = res.info
    assert tuple(info["anchor_broken"]) == ref.anchor_broken
    np.testing.assert_allclose(info["anchor_break_time"], ref.anchor_break_time, rtol=0,
                               atol=1e-8)
    assert info["max_anchor_force"] == pytest.approx(ref.max_anchor_force, rel=1e-8)
    assert info["max_anchor_force_n"] == pytest.approx(ref.max_anchor_force_n, rel=1e-8)


def test_compiled_model_uplift_threshold_and_zero_strength():
    q = 0.5
    r = rocking.simulate(BLOCK, Rectangular(1.001 * rigid_threshold(q), 0.1, t0=0.3,
                                            duration=1.0), model="anchored",
                         anchor_strength=q)
    assert r.uplift_time == pytest.approx(0.3, abs=1e-9)
    weak = rocking.simulate(BLOCK, Rectangular(0.999 * rigid_threshold(q), 0.5,
                                               duration=1.0), model="anchored",
                            anchor_strength=q)
    assert math.isnan(weak.uplift_time) and weak.max_abs_theta == 0.0
    assert weak.info["anchor_broken"] == [False, False]
    motion = random_record(7, 0.4 * G)
    free = rocking.simulate(BLOCK, motion, duration=8.0)
    zero = rocking.simulate(BLOCK, motion, model="anchored", duration=8.0,
                            anchor_strength=0.0)
    assert zero.overturn_time == pytest.approx(free.overturn_time, abs=1e-9)
    assert zero.max_abs_theta == free.max_abs_theta
    np.testing.assert_allclose(zero.impact_times, free.impact_times, rtol=0, atol=1e-9)


def test_elastic_anchors_pass_the_model_contract():
    """The registered model runs the contract with its defaults (rigid anchors,
    tests/test_check_model.py); the elastic law here."""
    from dataclasses import dataclass

    from rocking.models import option
    from rocking.models.anchored import Anchored, AnchoredOptions
    from rocking.testing import check_model

    @dataclass(frozen=True)
    class ElasticOptions(AnchoredOptions):
        anchors: str = option("elastic", choices=("rigid", "elastic"), help="law")
        anchor_strength: float = option(0.05, lo=0.0, hi=1e3, lo_open=False, unit="",
                                        help="q = F_a/(m g)")
        anchor_stiffness: float = option(30.0, lo=0.0, hi=1e9, unit="",
                                         help="kappa = k_a 2b/(m g)")

    class AnchoredElastic(Anchored):
        name = "anchored-elastic"
        Options = ElasticOptions

    check_model(AnchoredElastic)


def test_an_intact_elastic_anchor_at_overturning_carries_kappa():
    """An elastic anchor weaker in stiffness than in strength (kappa < q) never breaks:
    when the block overturns its force is kappa sin(pi/2) = kappa (fraction of m g),
    the largest it reached."""
    pulse = OneSine(6.0 * THR, 1.0, duration=1.0)
    kappa, q = 0.05, 0.5
    r = rocking.simulate(BLOCK, pulse, model="anchored", anchors="elastic",
                         anchor_strength=q, anchor_stiffness=kappa, duration=3.0)
    assert r.overturned
    assert r.info["anchor_broken"] == [False, False]
    assert r.info["max_anchor_force"] == pytest.approx(kappa, rel=1e-12)


@pytest.mark.parametrize("av", [-0.3 * G, 0.2 * G])
def test_the_force_of_a_rigid_anchor_at_rest_balances_the_moments_with_a_vertical_motion(av):
    """At rest under a constant horizontal a and vertical a_v, the moments about the pivot
    balance: 2 b F = m h a - m (g + a_v) b, so F/(m g) = (a/(g tan(alpha)) - (1 + a_v/g))/2
    (below the uplift threshold (g + a_v) tan(alpha) + 2 q g tan(alpha))."""
    from rocking.motions import GroundMotion

    q, k = 0.5, 1.5  # a = k g tan(alpha)
    a = k * THR
    motion = GroundMotion(Rectangular(a, 1.0, duration=1.0),
                          Rectangular(abs(av), 1.0, duration=1.0, scale=math.copysign(1, av)))
    r = rocking.simulate(BLOCK, motion, model="anchored", anchor_strength=q, duration=1.0)
    assert math.isnan(r.uplift_time) and r.info["anchor_broken"] == [False, False]
    assert r.info["max_anchor_force"] == pytest.approx(0.5 * (k - (1.0 + av / G)),
                                                       rel=1e-12)
