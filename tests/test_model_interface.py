"""The model interface (rocking.models.base): a fourth model in one class, one result
convention, batch rows identical to single runs whatever the batch, validated options."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pytest
from numba import njit, prange

import rocking
from rocking import G, ParameterError, SimulationError
from rocking.errors import OutputTooLargeError
from rocking.models import (
    MODELS,
    Model,
    ModelOptions,
    option,
    row_args,
    same_block,
    set_planar_result,
    store_row,
)
from rocking.models._numerics.events import rest_advance
from rocking.motions import HalfSine, Sine
from rocking.motions._kernel import ground_acc, next_breakpoint
from rocking.testing.records import random_record


# ------------------------------------------------------------- a fourth model in one class
@njit(cache=True)
def _lin_acc(th, t, s, alpha, p2, kind, prm, samples):
    """Linearised Eq 1 on pivot ``s``: theta'' = p^2 (theta - s alpha) + p^2 a / g."""
    return p2 * (th - s * alpha) + p2 * ground_acc(kind, prm, samples, t) / G


@njit(cache=True)
def _lin_rk4(th, om, t, h, s, alpha, p2, kind, prm, samples):
    k1t, k1o = om, _lin_acc(th, t, s, alpha, p2, kind, prm, samples)
    k2t = om + 0.5 * h * k1o
    k2o = _lin_acc(th + 0.5 * h * k1t, t + 0.5 * h, s, alpha, p2, kind, prm, samples)
    k3t = om + 0.5 * h * k2o
    k3o = _lin_acc(th + 0.5 * h * k2t, t + 0.5 * h, s, alpha, p2, kind, prm, samples)
    k4t = om + h * k3o
    k4o = _lin_acc(th + h * k3t, t + h, s, alpha, p2, kind, prm, samples)
    return (th + h * (k1t + 2 * k2t + 2 * k3t + k4t) / 6.0,
            om + h * (k1o + 2 * k2o + 2 * k3o + k4o) / 6.0)


@njit(cache=True)
def _linear_kernel(mp, kind, prm, samples, t_end, t_quiet, h_scan, y0, dt_out, hist, imp,
                   res, extra):
    """The linearised classical model with ground motion, written independently of
    rocking.models.housner: constant-step RK4 that steps onto the kinks of the motion,
    impacts by bisection on a cubic Hermite interpolant, Eq 4 at impacts, rest and uplift
    with the shared helper ``rest_advance`` (uplift when |a| > g alpha)."""
    alpha, p, mu, rest_tol = mp
    th0, om0, out_th, out_om = y0[0], y0[1], hist[:, 0], hist[:, 1]
    p2 = p * p
    thr = G * alpha
    h0 = min(2e-3 / p, 0.25 * h_scan)
    t, th, om, k, n_imp, n_steps = 0.0, th0, om0, 0, 0, 0
    peak = abs(th0)
    resting = th0 == 0.0 and om0 == 0.0
    t_up = math.nan if resting else 0.0
    s = 1.0 if (th0 > 0.0 or (th0 == 0.0 and om0 > 0.0)) else -1.0
    over, t_over = False, math.nan
    n_out = out_th.shape[0]
    while t < t_end - 1e-12:
        if resting:
            if t >= t_quiet:  # the ground is still: at rest for good
                break
            t, k, d, t_up = rest_advance(kind, prm, samples, t, min(t_end, t_quiet), h_scan,
                                         thr, alpha, dt_out, k, out_th, out_om, t_up)
            if d == 0.0:
                break
            resting, s = False, d
            continue
        h = min(h0, t_end - t, next_breakpoint(kind, prm, samples, t) - t)
        th1, om1 = _lin_rk4(th, om, t, h, s, alpha, p2, kind, prm, samples)
        n_steps += 1
        a0 = _lin_acc(th, t, s, alpha, p2, kind, prm, samples)
        if s * th1 < 0.0:  # impact inside the step: bisection on the exact RK4 sub-step
            lo, hi = 0.0, h
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                if s * _lin_rk4(th, om, t, mid, s, alpha, p2, kind, prm, samples)[0] > 0.0:
                    lo = mid
                else:
                    hi = mid
            h = 0.5 * (lo + hi)
            th1, om1 = 0.0, _lin_rk4(th, om, t, h, s, alpha, p2, kind, prm, samples)[1]
        while k < n_out and k * dt_out <= t + h + 1e-12:  # cubic Hermite output
            x = (k * dt_out - t) / h
            a1 = _lin_acc(th1, t + h, s, alpha, p2, kind, prm, samples)
            out_th[k] = ((2 * x**3 - 3 * x**2 + 1) * th + (x**3 - 2 * x**2 + x) * h * om
                         + (3 * x**2 - 2 * x**3) * th1 + (x**3 - x**2) * h * om1)
            out_om[k] = om + x * h * (a0 + 0.5 * x * (a1 - a0))
            k += 1
        th_prev = th
        t, th, om = t + h, th1, om1
        peak = max(peak, abs(th))
        if th == 0.0:  # Eq 4, the pivot switches; the Zeno rule
            if n_imp < imp.shape[0]:
                imp[n_imp] = t
            n_imp += 1
            om *= mu
            amp = alpha - math.sqrt(max(alpha * alpha - om * om / p2, 0.0))
            if amp < rest_tol * alpha and abs(ground_acc(kind, prm, samples, t)) <= thr:
                resting, om = True, 0.0
            else:
                s = 1.0 if om > 0.0 else -1.0
        if abs(th) >= 0.5 * math.pi:  # overturned: locate |theta| = pi/2 in the step
            over, peak = True, 0.5 * math.pi
            t_over = t - h * (abs(th) - 0.5 * math.pi) / max(abs(th) - abs(th_prev), 1e-300)
            break
    set_planar_result(res, k, n_imp, peak, over, t_over, t_up, n_steps, 0, math.nan,
                      over or resting)


@njit(cache=True, parallel=True)
def _linear_batch(mp, extra0, rows, blocks):
    for i in prange(rows.kinds.shape[0]):
        _linear_kernel(same_block(mp, blocks[i]), *row_args(i, rows), rows.res[i], extra0)
        store_row(i, rows)


@dataclass(frozen=True)
class LinearOptions(ModelOptions):
    rest_tol: float = option(1e-12, lo=0.0, hi=1e-2, help="Zeno threshold (fraction of alpha)")


class LinearHousner(Model):
    """A fourth model in one class: the linearised classical model with ground motion."""

    name = "linear-housner"
    label = "linear classical (test)"
    Options = LinearOptions
    kernel = _linear_kernel
    batch_kernel = _linear_batch

    def kernel_params(self, dt_out, theta0, omega0):
        b = self.block
        return (b.alpha, b.p, b.mu, self.options.rest_tol)


def test_a_fourth_model_runs_through_simulate_and_simulate_many():
    blk = rocking.specimen(3)
    th0 = 0.5 * blk.alpha
    # free rocking: the first quarter period in closed form, cosh(p t) = alpha/(alpha-th0)
    r = rocking.simulate(blk, None, model=LinearHousner, duration=3.0, theta0=th0)
    assert isinstance(r, rocking.Response) and r.model == "linear-housner"
    t1 = math.acosh(blk.alpha / (blk.alpha - th0)) / blk.p
    assert r.impact_times[0] == pytest.approx(t1, abs=1e-9)
    # under ground motion: the same physics as the compiled classical model, linear=True
    ms = _mixed_motions()
    for m in ms[:3]:
        a = rocking.simulate(blk, m, model=LinearHousner)
        b = rocking.simulate(blk, m, model="housner", linear=True, rtol=1e-10)
        assert a.overturned == b.overturned
        assert a.uplift_time == pytest.approx(b.uplift_time, abs=1e-9)
        assert a.max_abs_theta == pytest.approx(b.max_abs_theta, rel=1e-5)
        assert a.max_abs_theta > 0.2 * blk.alpha
        if a.overturned:
            assert a.overturn_time == pytest.approx(b.overturn_time, abs=1e-4)
        k = min(5, a.n_impacts)
        np.testing.assert_allclose(a.impact_times[:k], b.impact_times[:k], rtol=0, atol=1e-6)
    # a batch of the fourth model: rows bit-identical to single runs, chunking irrelevant
    whole = rocking.simulate_many(blk, ms, model=LinearHousner)
    parts = np.concatenate([rocking.simulate_many(blk, ms[:2], model=LinearHousner).max_abs_theta,
                            rocking.simulate_many(blk, ms[2:], model=LinearHousner).max_abs_theta])
    np.testing.assert_array_equal(whole.max_abs_theta, parts)
    for i, m in enumerate(ms):
        one = rocking.simulate(blk, m, model=LinearHousner)
        assert whole.max_abs_theta[i] == one.max_abs_theta
        assert whole.n_impacts[i] == one.n_impacts and whole.overturned[i] == one.overturned
    with pytest.raises(ParameterError, match="rest_tol"):
        rocking.simulate(blk, ms[0], model=LinearHousner, rest_tol=1.0)


def test_a_model_class_without_kernels_is_refused():
    class Empty(Model):
        name = "empty"

    with pytest.raises(ParameterError, match="kernel"):
        rocking.simulate(rocking.specimen(2), None, model=Empty, duration=1.0, theta0=0.01)


# ------------------------------------------------------------------ one result convention
@pytest.mark.parametrize("name", list(MODELS))
def test_result_convention_is_the_same_for_every_model(name):
    blk = rocking.specimen(2)
    weak = Sine(5.0, 0.0005, 1.0)  # far below uplift: the block never moves
    r = rocking.simulate(blk, weak, model=name)
    b = rocking.simulate_many(blk, [weak], model=name)
    assert math.isnan(r.uplift_time) and math.isnan(r.overturn_time)
    assert np.isnan(b.uplift_time[0]) and np.isnan(b.overturn_time[0])
    assert r.n_impacts == b.n_impacts[0] == 0
    assert not r.rocked or name == "dem"  # DEM springs tilt a block at rest by ~1e-9 rad
    s, bs = r.summary(), b.summary()
    assert s["uplift_time"] is None and s["overturn_time"] is None
    assert bs["n"] == 1 and bs["n_overturned"] == 0
    for d in (r.to_dict(), b.to_dict()):
        import json

        json.dumps(d, allow_nan=False)  # JSON-ready: no NaN
    assert np.diff(r.t)[0] == pytest.approx(rocking.results.DEFAULT_DT_OUT)


def test_n_impacts_counts_all_impacts_beyond_the_kept_times():
    blk = rocking.specimen(2)
    r = rocking.simulate(blk, None, duration=5.0, theta0=0.5 * blk.alpha, max_impacts=3)
    full = rocking.simulate(blk, None, duration=5.0, theta0=0.5 * blk.alpha)
    assert r.impact_times.size == 3 and r.n_impacts == full.n_impacts > 3
    np.testing.assert_array_equal(r.impact_times, full.impact_times[:3])


# --------------------------------------------------- batch rows are the single runs, exactly
def _mixed_motions():
    """Motions of different time scales: two sines, noise records (dt 0.01 s), a pulse."""
    rec = random_record(7, 0.5 * G, duration=8.0)
    return [Sine(2.0, 0.02, 3.0), Sine(5.0, 0.008, 3.0), rec.scaled(1.2),
            HalfSine(3.0, 0.3, duration=3.0), rec.scaled(-0.9)]


@pytest.mark.parametrize("name", ["housner", "ccrr"])
def test_batch_rows_equal_single_runs_and_do_not_depend_on_the_batch(name):
    """Each row is bit-identical to the single run, and splitting the batch into chunks
    changes nothing (motions of different time scales in one batch)."""
    blk = rocking.specimen(3)
    ms = _mixed_motions()
    whole = rocking.simulate_many(blk, ms, model=name, return_histories=True)
    parts = [rocking.simulate_many(blk, ms[:2], model=name),
             rocking.simulate_many(blk, ms[2:], model=name)]
    for key in ("max_abs_theta", "overturned", "overturn_time", "uplift_time", "n_impacts",
                "settled"):
        chunked = np.concatenate([getattr(p, key) for p in parts])
        np.testing.assert_array_equal(getattr(whole, key), chunked)
    assert whole.max_abs_theta.max() > 0.1 * blk.alpha
    for i, m in enumerate(ms):
        r = rocking.simulate(blk, m, model=name)
        assert whole.max_abs_theta[i] == r.max_abs_theta
        assert whole.n_impacts[i] == r.n_impacts
        assert whole.overturned[i] == r.overturned
        assert whole.settled[i] == r.settled
        n = min(r.t.size, whole.t.size) - (1 if r.overturned else 0)
        np.testing.assert_array_equal(whole.theta[i, :n], r.theta[:n])


@pytest.mark.parametrize("name", ["housner", "ccrr"])
def test_a_block_and_an_initial_state_per_row(name):
    """Monte Carlo batches: each row its own block and theta0, still one compiled call, and
    still bit-identical to the single runs."""
    rng = np.random.default_rng(3)
    n = 6
    blocks = [rocking.Block.from_params(a, p, rocking.housner_mu(a))
              for a, p in zip(rng.uniform(0.12, 0.25, n), rng.uniform(2.0, 4.0, n),
                              strict=True)]
    rec = random_record(11, 0.25 * G, duration=6.0)
    ms = [rec.scaled(f) for f in rng.uniform(0.8, 1.6, n)]
    th0 = rng.uniform(-0.3, 0.3, n) * np.array([b.alpha for b in blocks])
    th0[0] = 0.0  # one row from rest
    b = rocking.simulate_many(blocks, ms, model=name, theta0=th0)
    for i in range(n):
        r = rocking.simulate(blocks[i], ms[i], model=name, theta0=th0[i])
        assert b.max_abs_theta[i] == r.max_abs_theta
        assert b.n_impacts[i] == r.n_impacts and b.overturned[i] == r.overturned
    assert len(set(b.max_abs_theta)) == n and b.n_impacts.max() > 0
    with pytest.raises(ParameterError, match="one block per motion"):
        rocking.simulate_many(blocks[:2], ms, model=name)
    with pytest.raises(ParameterError, match="theta0"):
        rocking.simulate_many(blocks, ms, model=name, theta0=[0.1, 0.2])


def test_dem_batches_of_several_blocks():
    """The DEM cannot change its assembly per row: one batch per distinct block, same rows."""
    b2, b3 = rocking.specimen(2, "geometric"), rocking.specimen(3, "geometric")
    ms = [HalfSine(2.5, 0.25, duration=1.5), HalfSine(3.0, 0.25, duration=1.5)] * 2
    blocks = [b2, b3, b3, b2]
    batch = rocking.simulate_many(blocks, ms, model="dem")
    for i, m in enumerate(ms):
        r = rocking.simulate(blocks[i], m, model="dem")
        assert batch.max_abs_theta[i] == r.max_abs_theta
    # per-row initial states (issue 29; refused before): one batch per distinct state
    th0 = [0.0, 0.02, -0.02, 0.02]
    batch = rocking.simulate_many(blocks, ms, model="dem", theta0=th0, return_histories=True)
    for i, m in enumerate(ms):
        r = rocking.simulate(blocks[i], m, model="dem", theta0=th0[i])
        assert batch.max_abs_theta[i] == r.max_abs_theta
        np.testing.assert_array_equal(batch.states[i, : r.t.size], r.states)


# ------------------------------------------------------------------------- options, errors
def test_options_are_validated_at_the_edge():
    blk = rocking.specimen(2)
    m = Sine(5.0, 0.005, 1.0)
    with pytest.raises(ParameterError, match=r"rtol must be in \[1e-13, 0.01\]"):
        rocking.simulate(blk, m, rtol=0.5)
    with pytest.raises(ParameterError, match="unknown option.*bogus.*allowed"):
        rocking.simulate(blk, m, bogus=1)
    with pytest.raises(ParameterError, match="linear=True is not available for model 'ccrr'"):
        rocking.simulate(blk, m, model="ccrr", linear=True)
    with pytest.raises(ParameterError, match="friction_angle"):
        rocking.simulate(blk, m, model="dem", friction_angle=95.0)
    with pytest.raises(ParameterError, match="damping"):
        rocking.simulate(blk, m, model="dem", damping="lots")
    with pytest.raises(ParameterError, match="model must be one of housner, ccrr, dem"):
        rocking.simulate(blk, m, model="udec")
    with pytest.raises(ParameterError, match="return_forces=True is for single runs"):
        rocking.simulate_many(blk, [m], model="dem", return_forces=True)
    with pytest.raises(ParameterError, match="stacks need model='dem'"):
        rocking.simulate(rocking.Stack([blk, blk]), m)
    for cls in MODELS.values():  # every option is documented
        for d in cls.Options.describe():
            assert d["help"], (cls.name, d["name"])


def test_memory_guard_names_dt_out():
    blk = rocking.specimen(2)
    with pytest.raises(OutputTooLargeError, match="dt_out"):
        rocking.simulate(blk, None, duration=1e9, theta0=0.05)
    with pytest.raises(OutputTooLargeError, match="dt_out"):
        rocking.simulate_many(blk, [Sine(5.0, 0.005, 1e7)], return_histories=True)


def test_numerical_failure_is_a_simulation_error_not_bad_input():
    blk = rocking.specimen(2)
    with pytest.raises(SimulationError, match="constant step") as e:
        rocking.simulate(blk, None, model="ccrr", duration=2.0, theta0=0.05, dt=0.05)
    assert not isinstance(e.value, ParameterError)
    b = rocking.simulate_many(blk, [Sine(5.0, 0.005, 2.0)] * 2, model="ccrr", dt=0.05,
                              errors="nan")
    assert np.all(b.status != 0) and np.all(np.isnan(b.max_abs_theta))
    with pytest.raises(SimulationError):
        rocking.simulate_many(blk, [Sine(5.0, 0.005, 2.0)], model="ccrr", dt=0.05)


def test_every_error_type_is_exported():
    for name in ("RockingError", "ParameterError", "SpecimenError", "RecordError",
                 "UnitError", "OutputTooLargeError", "IdentificationError",
                 "SimulationError"):
        assert isinstance(getattr(rocking, name), type)
    assert issubclass(rocking.IdentificationError, rocking.RockingError)
    assert not issubclass(rocking.SimulationError, rocking.RockingError)


def test_lazy_submodules():
    import subprocess
    import sys

    code = ("import rocking, sys; assert 'rocking.identify' not in sys.modules; "
            "rocking.identify.free_rocking; rocking.models.MODELS; rocking.dem.paper_parameters;"
            "from rocking.dem import paper_parameters; import rocking.dem as d;"
            "assert d is rocking.models.dem and d.__spec__.name == 'rocking.models.dem'")
    subprocess.run([sys.executable, "-c", code], check=True)
