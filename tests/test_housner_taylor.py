"""The classical model's ``method="taylor"`` (fixed Taylor-series steps, issue 33).

Checks of physics, not of captured output: agreement with the independent adaptive
Dormand-Prince integration of the same equations at a tight tolerance, the exact free
rocking of the linearised model (Housner 1963: ``theta = alpha - (alpha - theta0)
cosh(p t)``), the small-angle limit (nonlinear minus linear shrinking like ``alpha^2``),
convergence of the Taylor step under refinement, and the documented fallback to
Dormand-Prince where the ground acceleration is not piecewise linear.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import rocking
from rocking import Block, ParameterError, simulate, simulate_many
from rocking.models import housner as H
from rocking.motions import GroundMotion, OneSine, Record
from rocking.testing.records import random_record
from rocking.units import G

SPEC2 = rocking.specimen(2, "experimental")
ASYM = Block.from_geometry(0.5, 0.10, 0.07, 0.25, mu=0.95)


def _records(n, pga, seed=3, duration=8.0):
    return [random_record(seed + i, pga, duration) for i in range(n)]


@pytest.mark.parametrize("block", [SPEC2, ASYM], ids=["symmetric", "asymmetric"])
@pytest.mark.parametrize("linear", [False, True], ids=["nonlinear", "linear"])
def test_taylor_agrees_with_tight_dopri(block, linear):
    """Two independent integrators of the same piecewise ODE, events and rules: the
    largest angle, the impact count, the outcome and the uplift time agree."""
    uplift = G * math.tan(min(block.alpha_plus, block.alpha_minus))
    recs = _records(6, 1.6 * uplift)
    d = simulate_many(block, recs, rtol=1e-11, linear=linear, duration=8.0)
    t = simulate_many(block, recs, method="taylor", linear=linear, duration=8.0)
    assert (d.max_abs_theta > 0).all()
    np.testing.assert_allclose(t.max_abs_theta, d.max_abs_theta, rtol=1e-5, atol=1e-12)
    np.testing.assert_array_equal(t.overturned, d.overturned)
    np.testing.assert_allclose(t.uplift_time, d.uplift_time, rtol=0, atol=1e-12)


def test_taylor_history_and_impacts_agree_with_tight_dopri():
    rec = random_record(11, 1.5 * SPEC2.uplift_acceleration, 8.0)
    d = simulate(SPEC2, rec, rtol=1e-11, duration=8.0)
    t = simulate(SPEC2, rec, method="taylor", duration=8.0)
    assert t.n_impacts == d.n_impacts > 5
    np.testing.assert_allclose(t.impact_times, d.impact_times, rtol=0, atol=1e-8)
    np.testing.assert_allclose(t.theta, d.theta, rtol=1e-7, atol=1e-7 * SPEC2.alpha)


def test_overturning_time_agrees():
    rec = random_record(5, 4.0 * SPEC2.uplift_acceleration, 8.0)
    d = simulate(SPEC2, rec, rtol=1e-11, duration=8.0)
    t = simulate(SPEC2, rec, method="taylor", duration=8.0)
    assert d.overturned and t.overturned
    assert abs(t.overturn_time - d.overturn_time) < 1e-8


@pytest.mark.parametrize("theta0_frac", [0.3, 0.8])
def test_linear_free_rocking_is_housners_closed_form(theta0_frac):
    """Free rocking of the linearised block from rest at ``theta0``: ``theta(t) = alpha -
    (alpha - theta0) cosh(p t)`` until the impact at ``acosh(alpha / (alpha - theta0)) /
    p``, where ``omega = -p sqrt(alpha^2 - (alpha - theta0)^2)``; then Eq 4 and, on the
    other side, a flight of ``(2/p) atanh(|omega| / (p alpha))``."""
    a, p, mu = SPEC2.alpha, SPEC2.p, SPEC2.mu
    th0 = theta0_frac * a
    r = simulate(SPEC2, None, method="taylor", linear=True, theta0=th0, duration=3.0,
                 dt_out=0.005)
    t1 = math.acosh(a / (a - th0)) / p
    tt = r.t[r.t < t1]
    np.testing.assert_allclose(r.theta[: tt.size], a - (a - th0) * np.cosh(p * tt),
                               rtol=0, atol=1e-12)
    assert r.impact_times[0] == pytest.approx(t1, abs=1e-12)
    w = mu * p * math.sqrt(a * a - (a - th0) ** 2)
    t2 = t1 + 2.0 / p * math.atanh(w / (p * a))
    assert r.impact_times[1] == pytest.approx(t2, abs=1e-11)


def test_nonlinear_minus_linear_shrinks_like_alpha_squared():
    """Small-angle limit: with the load as a fraction of the uplift acceleration and the
    angle in units of ``alpha``, the nonlinear and linear models differ by O(alpha^2)."""
    diffs = []
    for alpha in (0.04, 0.02, 0.01):
        blk = Block(alpha=alpha, p=2.0, mu=0.95)
        pulse = [Record(*_sampled(OneSine(1.4 * G * math.tan(alpha), 0.8), 3.0))]
        nl = simulate_many(blk, pulse, method="taylor", duration=3.0).max_abs_theta[0]
        li = simulate_many(blk, pulse, method="taylor", linear=True,
                           duration=3.0).max_abs_theta[0]
        diffs.append(abs(nl - li) / alpha)
    r1, r2 = diffs[0] / diffs[1], diffs[1] / diffs[2]
    assert 3.0 < r1 < 5.0 and 3.0 < r2 < 5.0, diffs


def _sampled(motion, duration, dt=0.01):
    """The motion sampled as a record (piecewise linear: the Taylor steps' input)."""
    t = np.arange(int(round(duration / dt)) + 1) * dt
    return np.array([motion.acceleration(x) for x in t]), dt


def test_taylor_step_converges_under_refinement():
    """The one-step map against the tight Dormand-Prince solution under a constant ground
    acceleration: the error of one step of length h falls like h^(ORDER+1)."""
    a, p = SPEC2.alpha, SPEC2.p
    buf = np.full((5, H.TAYLOR_ORDER + 1), np.nan)
    mp = H.TaylorSideParams(a, p, 1.0, a, p, 1.0, False, p * p, p * p, 0.0, 0.0, 0.0, 0.0,
                            0.0, 0.0, buf)
    kind, prm, samples = rocking.motions.Record(np.full(11, 2.0), 0.1).spec()
    args = (1.0, a, p * p, False, kind, prm, samples)
    th0, om0 = 0.5 * a, 0.0
    errs = []
    for h in (0.2, 0.1, 0.05):
        th1, om1, _ = H.taylor_step(mp, args, 0.0, th0, om0, 0.0, h)
        errs.append(abs(th1 - _dopri_at(a, p, kind, prm, samples, th0, om0, h)))
    # local error O(h^(ORDER+1)): each halving gains at least 2^ORDER
    assert errs[0] / errs[1] > 2.0 ** H.TAYLOR_ORDER, errs
    assert errs[1] / errs[2] > 2.0 ** H.TAYLOR_ORDER, errs


def _dopri_at(a, p, kind, prm, samples, th0, om0, h):
    """``theta(h)`` by the adaptive Dormand-Prince kernel at rtol 1e-13 (output at 0, h)."""
    hist = np.zeros((2, 2))  # the kernel's layout: columns of a history (compiled once)
    out_th, out_om = hist[:, 0], hist[:, 1]
    H.integrate(a, p, 1.0, a, p, 1.0, False, kind, prm, samples, h + 1e-9, 1e9, th0, om0,
                1e-13, 0.0, 0.0, h / 16, 0.01, h, out_th, out_om, np.zeros(4))
    return out_th[1]


def test_fallback_to_dopri_off_records():
    """A motion that is not piecewise linear (a pulse), or has a vertical component, runs
    with Dormand-Prince: the results are those of ``method="dopri"`` exactly."""
    pulse = OneSine(2.0 * SPEC2.uplift_acceleration, 0.6)
    rec = random_record(2, 1.5 * SPEC2.uplift_acceleration, 4.0)
    gm = GroundMotion(rec, OneSine(2.0, 0.3, duration=4.0))
    for motion in (pulse, gm):
        d = simulate(SPEC2, motion, duration=4.0)
        t = simulate(SPEC2, motion, method="taylor", duration=4.0)
        np.testing.assert_array_equal(t.theta, d.theta)
        assert t.n_impacts == d.n_impacts


def test_row_of_batch_equals_single_run_and_bad_method_is_refused():
    recs = _records(3, 1.5 * SPEC2.uplift_acceleration, seed=20, duration=5.0)
    b = simulate_many(SPEC2, recs, method="taylor", duration=5.0)
    for i, r in enumerate(recs):
        one = simulate(SPEC2, r, method="taylor", duration=5.0)
        assert one.max_abs_theta == b.max_abs_theta[i]
        assert one.n_impacts == b.n_impacts[i]
    with pytest.raises(ParameterError, match="method"):
        simulate(SPEC2, recs[0], method="rk4")


def test_model_contract_with_taylor_as_default():
    """The model contract (:func:`rocking.testing.contract.check_model`) holds with
    ``method="taylor"``: a subclass whose options default to it."""
    from dataclasses import dataclass

    from rocking.options import option
    from rocking.testing.contract import check_model

    @dataclass(frozen=True)
    class TaylorOptions(H.HousnerOptions):
        method: str = option("taylor", choices=H.METHODS, help="integrator")

    class HousnerTaylor(H.Housner):
        Options = TaylorOptions

    check_model(HousnerTaylor)


def test_uplift_just_before_a_sample_keeps_the_tiny_angle():
    """A block uplifting 1e-6 s before a sample, the ground acceleration barely above the
    threshold: its first angles are ~1e-17 rad, below ``alpha`` times the machine epsilon,
    and must not round to 0 (they did once, and the step was halved for ever). The run
    ends and agrees with Dormand-Prince."""
    thr = SPEC2.uplift_acceleration
    ramp = np.concatenate(([0.0], np.full(300, thr / (1.0 - 1e-4))))
    rec = Record(ramp * np.concatenate(([1.0], 1.0 + 0.3 * np.sin(np.arange(300) * 0.2))),
                 0.01)
    d = simulate(SPEC2, rec, rtol=1e-11, duration=3.0)
    t = simulate(SPEC2, rec, method="taylor", duration=3.0)
    assert t.uplift_time == d.uplift_time < 0.01
    assert t.max_abs_theta == pytest.approx(d.max_abs_theta, rel=1e-6)
    assert t.n_impacts == d.n_impacts


# 0.56 s of a band-limited noise record (m/s^2, 100 Hz): ``benchmarks/bench_housner.py``'s
# make_records(400, 20.0, 2007)[63] from 3.45 s, where specimen 2 is at rest
GRAZE = [
    -0.53507675, -0.71693063, -0.96322161, -1.188641, -1.30091616, -1.24158003,
    -1.01212412, -0.67283617, -0.31776135, -0.04107878, 0.08961536, 0.04618204,
    -0.15951007, -0.48293516, -0.85899801, -1.21675024, -1.49327521, -1.64171049,
    -1.6307298, -1.43953268, -1.05794897, -0.49873989, 0.18258095, 0.87761738,
    1.44224452, 1.74264643, 1.71025348, 1.37510884, 0.85690724, 0.31747708,
    -0.09934444, -0.31043604, -0.30346623, -0.119276, 0.17662406, 0.51739487,
    0.84569465, 1.11375184, 1.27919655, 1.30350252, 1.15761157, 0.83468287,
    0.36383526, -0.18436978, -0.70657835, -1.08805957, -1.22990832, -1.07363432,
    -0.61693097, 0.0822272, 0.91425094, 1.73936343, 2.41804962, 2.84187922,
    2.95530849, 2.76320268]


def test_a_dip_across_zero_inside_one_sample_step_is_not_missed():
    """At ``|theta| ~ 1e-7`` the block crosses to its other side and back within 53 us,
    inside one 10 ms sample step, whose ends are on the same side: two impacts that a
    check at the step's quarters does not see (the first version of the Taylor steps
    missed them, and the 20 s run went on 23 % off in ``max |theta|``). The fixed steps
    find the dip at the velocity's root and give the tight Dormand-Prince impacts."""
    rec = Record(np.array(GRAZE), 0.01, name="graze")
    d = simulate(SPEC2, rec, rtol=1e-12)
    t = simulate(SPEC2, rec, method="taylor")
    gaps = np.diff(d.impact_times)
    assert gaps.min() < 1e-4 and d.n_impacts > 50  # the double impact is there
    assert t.n_impacts == d.n_impacts
    np.testing.assert_allclose(t.impact_times, d.impact_times, rtol=0, atol=1e-7)
    np.testing.assert_allclose(t.max_abs_theta, d.max_abs_theta, rtol=1e-6)


def test_kernels_hook_gives_the_taylor_pair_only_for_taylor():
    """``Model.kernels()``: the driver's kernels. The Taylor pair only with
    ``method="taylor"``; the default and the anchored block keep their class's pair (so
    they never compile the Taylor code)."""
    from rocking.models import anchored as A

    assert H.Housner.from_kwargs(SPEC2).kernels() == (H.kernel, H.batch_kernel)
    assert (H.Housner.from_kwargs(SPEC2, method="taylor").kernels()
            == (H.kernel_taylor, H.batch_kernel_taylor))
    assert A.Anchored.from_kwargs(SPEC2).kernels() == (A.kernel, A.batch_kernel)


def test_default_run_does_not_compile_the_taylor_kernels():
    """A fresh process running the default classical model and the anchored block
    compiles (or loads) no Taylor specialisation."""
    import os
    import subprocess
    import sys

    code = (
        "import numpy as np, rocking\n"
        "from rocking.models import housner as H\n"
        "from rocking.motions import Record\n"
        "rec = Record(np.random.default_rng(0).normal(size=200), 0.01)\n"
        "b = rocking.specimen(2)\n"
        "rocking.simulate_many(b, [rec]); rocking.simulate(b, rec)\n"
        "rocking.simulate(b, rec, model='anchored')\n"
        "assert H.kernel.signatures and H.batch_kernel.signatures\n"
        "print(len(H.kernel_taylor.signatures), len(H.batch_kernel_taylor.signatures),\n"
        "      len(H.integrate_taylor.signatures))\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env=os.environ.copy(), timeout=600, check=True)
    assert out.stdout.split() == ["0", "0", "0"], out.stdout + out.stderr
