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
from rocking.models import MODELS, Model, ModelOptions, row_args, store_row
from rocking.motions import HalfSine, Record, Sine


# ------------------------------------------------------------- a fourth model in one class
@njit(cache=True)
def _linear_kernel(mp, kind, prm, samples, t_end, th0, om0, h_scan, dt_out, out_th, out_om,
                   imp, extra):
    """Free rocking of the linearised classical model, ``theta'' = p^2 (theta - sgn alpha)``,
    solved exactly between impacts (cosh/sinh), with Eq 4 at each impact. No ground motion
    (a minimal model for the interface test)."""
    alpha, p, mu = mp
    th, om = th0, om0
    t = 0.0
    k = 0
    n_imp = 0
    peak = abs(th)
    s = 1.0 if (th > 0.0 or (th == 0.0 and om > 0.0)) else -1.0
    n_out = out_th.shape[0]
    over = False
    t_over = math.nan
    h = min(dt_out, 1e-3 / p)
    steps = 0
    while t < t_end - 1e-12 and (th != 0.0 or om != 0.0):
        hh = min(h, t_end - t)
        u = th - s * alpha  # u'' = p^2 u: exact propagation
        c, sh = math.cosh(p * hh), math.sinh(p * hh)
        u1 = u * c + om / p * sh
        om1 = u * p * sh + om * c
        th1 = u1 + s * alpha
        steps += 1
        if s * th1 < 0.0:  # impact: bisection for the crossing inside the step
            lo, hi = 0.0, hh
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                if s * (u * math.cosh(p * mid) + om / p * math.sinh(p * mid) + s * alpha) > 0:
                    lo = mid
                else:
                    hi = mid
            hh = 0.5 * (lo + hi)
            om1 = u * p * math.sinh(p * hh) + om * math.cosh(p * hh)
            th1 = 0.0
            if n_imp < imp.shape[0]:
                imp[n_imp] = t + hh
            n_imp += 1
            om1 *= mu
            s = -s
        while k < n_out and k * dt_out <= t + hh + 1e-12:
            out_th[k] = th1
            out_om[k] = om1
            k += 1
        t += hh
        th, om = th1, om1
        peak = max(peak, abs(th))
        if abs(th) >= 0.5 * math.pi:
            over = True
            t_over = t
            break
    while k < n_out and k * dt_out <= t_end + 1e-12:
        out_th[k] = th
        out_om[k] = om
        k += 1
    return k, n_imp, peak, over, t_over, 0.0 if (th0 != 0.0 or om0 != 0.0) else math.nan, \
        steps, 0


@njit(cache=True, parallel=True)
def _linear_batch(mp, extra0, rows):
    for i in prange(rows[0].shape[0]):
        store_row(i, _linear_kernel(mp, *row_args(i, rows, extra0)), rows)


@dataclass(frozen=True)
class _NoOptions(ModelOptions):
    pass


class LinearFree(Model):
    """A minimal fourth model: linear free rocking solved exactly between impacts."""

    name = "linear-free"
    label = "linear free rocking (test)"
    Options = _NoOptions
    kernel = _linear_kernel
    batch_kernel = _linear_batch

    def kernel_params(self, dt_out, theta0, omega0):
        return (self.block.alpha, self.block.p, self.block.mu)


def test_a_fourth_model_runs_through_simulate_and_simulate_many():
    blk = rocking.Block.from_params(0.2, 2.0, 0.9)
    th0 = 0.5 * blk.alpha
    r = rocking.simulate(blk, None, model=LinearFree, duration=4.0, theta0=th0, dt_out=1e-3)
    ref = rocking.simulate(blk, None, model="housner", linear=True, duration=4.0, theta0=th0,
                           dt_out=1e-3, rtol=1e-11)
    assert isinstance(r, rocking.Response) and r.model == "linear-free"
    # the same physics as the compiled classical model with linear=True
    assert r.n_impacts >= 4
    np.testing.assert_allclose(r.impact_times[:4], ref.impact_times[:4], rtol=0, atol=1e-9)
    assert r.max_abs_theta == pytest.approx(th0, rel=1e-12)
    # first quarter period of the linear model, closed form: cosh(p t) = alpha/(alpha-th0)
    t1 = math.acosh(blk.alpha / (blk.alpha - th0)) / blk.p
    assert r.impact_times[0] == pytest.approx(t1, abs=1e-9)
    b = rocking.simulate_many(blk, [Sine(1.0, 0.0, 2.0)] * 3, model=LinearFree)
    assert len(b) == 3 and not b.overturned.any() and b.model == "linear-free"
    assert np.all(b.max_abs_theta == 0.0) and np.all(np.isnan(b.uplift_time))


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
    rng = np.random.default_rng(7)
    rec = Record(rng.normal(0.0, 0.35 * G, 801), 0.01, name="noise")
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
    for key in ("max_abs_theta", "overturned", "overturn_time", "uplift_time", "n_impacts"):
        chunked = np.concatenate([getattr(p, key) for p in parts])
        np.testing.assert_array_equal(getattr(whole, key), chunked)
    assert whole.max_abs_theta.max() > 0.1 * blk.alpha
    for i, m in enumerate(ms):
        r = rocking.simulate(blk, m, model=name)
        assert whole.max_abs_theta[i] == r.max_abs_theta
        assert whole.n_impacts[i] == r.n_impacts
        assert whole.overturned[i] == r.overturned
        n = min(r.t.size, whole.t.size) - (1 if r.overturned else 0)
        np.testing.assert_array_equal(whole.theta[i, :n], r.theta[:n])


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
            "rocking.identify.free_rocking; rocking.models.MODELS; rocking.dem.paper_parameters")
    subprocess.run([sys.executable, "-c", code], check=True)
