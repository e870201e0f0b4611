"""Overturning spectra, outcome maps and the Mavroeidis-Papageorgiou pulse (issue 10).

The physics asserted: the dimensionless similarity of Eq (1) (Dimitrakopoulos and DeJong
2012), the thresholds of the vectorised search equal a plain bisection with single
``rocking.simulate`` runs, the safe region of the one-sine pulse between the two
overturning modes (Zhang and Makris 2001), and the M&P pulse's acceleration is the exact
derivative of its velocity formula.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import cumulative_trapezoid

import rocking
from rocking import ParameterError
from rocking.analysis.overturning import (
    outcome_map,
    overturning_spectrum,
    plot_outcome_map,
    plot_overturning_spectrum,
    pulse_motion,
)
from rocking.motions import MavroeidisPapageorgiou, OneSine
from rocking.motions import _kernel as K
from rocking.units import G

ALPHA, MU = 0.2, 0.94
BLOCK = rocking.Block(alpha=ALPHA, p=2.0, mu=MU)
TOL = 0.005
GRID = np.geomspace(1.0, 30.0, 36)  # a coarser scan grid than the default, for speed


# ------------------------------------------------------------------ similarity
def _one_sine(p, wr, ar, tail):
    tp = 2.0 * math.pi / (wr * p)
    return OneSine(ar * G * math.tan(ALPHA), tp, duration=tp + tail / p)


def _mp(p, wr, ar, tail):
    fp = wr * p / (2.0 * math.pi)
    return MavroeidisPapageorgiou(ar * G * math.tan(ALPHA), fp, 2.5, 0.7,
                                  duration=2.5 / fp + tail / p)


@pytest.mark.parametrize("make, wr, ar", [
    (_one_sine, 3.0, 1.35),   # rocks with impacts, survives
    (_one_sine, 2.0, 1.6),    # overturns
    (_mp, 2.0, 1.5),
])
def test_similarity_theta_over_alpha_is_a_function_of_pt(make, wr, ar):
    """Same alpha and mu, same omega_p/p and a_p/(g tan alpha), different p: the same
    theta/alpha as a function of p t (samples at the same p t), to 1e-6."""
    tail, dtau = 30.0, 0.01
    out = []
    for p in (1.7, 5.3):
        blk = rocking.Block(alpha=ALPHA, p=p, mu=MU)
        r = rocking.simulate(blk, make(p, wr, ar, tail), dt_out=dtau / p, rtol=1e-12)
        out.append(r)
    a, b = out
    assert a.n_impacts == b.n_impacts and a.overturned == b.overturned
    n = min(a.t.size, b.t.size)
    assert abs(a.t.size - b.t.size) <= 1  # at most the overturning sample differs
    np.testing.assert_allclose(1.7 * a.t[:n - 1], 5.3 * b.t[:n - 1], rtol=1e-12)
    np.testing.assert_allclose(a.theta[:n - 1] / ALPHA, b.theta[:n - 1] / ALPHA, atol=1e-6)
    assert a.max_abs_theta / ALPHA == pytest.approx(b.max_abs_theta / ALPHA, abs=1e-6)
    assert a.max_abs_theta > 0.3 * ALPHA  # the case really rocks
    if a.overturned:
        assert 1.7 * a.overturn_time == pytest.approx(5.3 * b.overturn_time, rel=1e-6)


def test_spectrum_is_the_same_for_blocks_of_any_size():
    wr = [1.5, 4.0, 7.0]
    small = overturning_spectrum(BLOCK, "one_sine", wr, tol=TOL, accel_ratio=GRID)
    big = overturning_spectrum(rocking.Block(alpha=ALPHA, p=0.9, mu=MU), "one_sine", wr,
                               tol=TOL, accel_ratio=GRID)
    np.testing.assert_allclose(small["min_overturn_ratio"], big["min_overturn_ratio"],
                               rtol=TOL)
    assert list(small["mode"]) == list(big["mode"])


# ------------------------------------------------------------------ the spectrum
def _direct_threshold(wr, grid, tol):
    """Plain search with single runs: the first overturning grid level, then bisection
    between it and the level below."""
    def over(ar):
        r = rocking.simulate(BLOCK, _one_sine(BLOCK.p, wr, ar, 60.0))
        return r.overturned, r.n_impacts

    lo = 0.0
    for ar in grid:
        ov, imp = over(ar)
        if ov:
            hi = ar
            break
        lo = ar
    else:
        return math.nan, None
    while hi - lo > tol * hi:
        mid = 0.5 * (lo + hi)
        ov, i = over(mid)
        if ov:
            hi, imp = mid, i
        else:
            lo = mid
    return hi, (1 if imp > 0 else 2)  # Zhang and Makris (2001): 1 after an impact


def test_thresholds_equal_a_direct_bisection_with_simulate():
    wr = np.array([1.0, 3.5, 8.0])
    df = overturning_spectrum(BLOCK, "one_sine", wr, tol=TOL, accel_ratio=GRID)
    assert list(df.columns[:3]) == ["omega_ratio", "min_overturn_ratio", "mode"]
    np.testing.assert_array_equal(df["omega_ratio"], wr)
    for row in df.itertuples():
        direct, mode = _direct_threshold(row.omega_ratio, GRID, TOL)
        assert row.min_overturn_ratio == pytest.approx(direct, rel=TOL)
        assert row.mode == mode
        # the bracket is honoured: overturns at the top, not at the bottom, width <= tol
        assert row.min_overturn_ratio - row.safe_ratio <= TOL * row.min_overturn_ratio
        assert rocking.simulate(BLOCK, _one_sine(BLOCK.p, row.omega_ratio,
                                                 row.min_overturn_ratio, 60.0)).overturned
        assert not rocking.simulate(BLOCK, _one_sine(BLOCK.p, row.omega_ratio,
                                                     row.safe_ratio, 60.0)).overturned
    # no uplift below a_p = g tan(alpha); the threshold grows with the frequency
    assert (df["min_overturn_ratio"] > 1.0).all()
    assert df["min_overturn_ratio"].is_monotonic_increasing
    assert df.attrs["n_simulations"] > 0 and df.attrs["tol"] == TOL


def test_safe_region_between_the_two_modes_for_the_one_sine_pulse():
    """Zhang and Makris (2001): above the minimum (mode 1, after an impact) lies a band of
    amplitudes that do not overturn, below the mode-2 boundary (no impact)."""
    wr = 8.0
    spec = overturning_spectrum(BLOCK, "one_sine", [wr], tol=TOL, accel_ratio=GRID)
    r_min = float(spec["min_overturn_ratio"].iloc[0])
    assert spec["mode"].iloc[0] == 1
    ar = r_min * np.geomspace(1.0, 3.0, 40)
    m = outcome_map(BLOCK, "one_sine", [wr], ar)
    assert len(m) == 40 and set(m.columns) >= {"omega_ratio", "accel_ratio", "overturned",
                                               "mode", "max_abs_theta_over_alpha"}
    modes = m["mode"].to_numpy()
    safe = np.flatnonzero(modes == 0)
    assert safe.size, "no safe amplitude above the minimum"
    s = safe[0]
    assert modes[0] == 1 and (modes[:s] == 1).all()  # the mode-1 tongue
    assert (modes[s:] != 1).any() and modes[-1] == 2  # the mode-2 region above
    first_mode2 = np.flatnonzero(modes == 2)[0]
    assert s < first_mode2
    # a single run confirms the safe amplitude: it rocks hard, without overturning
    r = rocking.simulate(BLOCK, _one_sine(BLOCK.p, wr, ar[s], 60.0))
    assert not r.overturned and r.max_abs_theta > 0.5 * ALPHA
    row = m.iloc[s]
    assert row["max_abs_theta_over_alpha"] == pytest.approx(r.max_abs_theta / ALPHA,
                                                            rel=1e-12)


def test_other_pulses_and_plots(tmp_path):
    for pulse, prm in (("one_cosine", None), ("ricker", None),
                       ("mavroeidis_papageorgiou", {"gamma": 2.0, "nu": 0.5})):
        df = overturning_spectrum(BLOCK, pulse, [1.0, 2.0], tol=0.02, accel_ratio=GRID,
                                  pulse_params=prm)
        assert (df["min_overturn_ratio"] > 1.0).all()
        assert df.attrs["pulse"] == pulse
    m = outcome_map(BLOCK, "one_sine", [2.0, 4.0, 8.0], [1.5, 5.0, 12.0])
    assert len(m) == 9 and m["mode"].isin([0, 1, 2]).all()
    assert (m.loc[~m["overturned"], "mode"] == 0).all()
    ax = plot_overturning_spectrum(df)
    ax2 = plot_outcome_map(m, spectrum=df)
    ax.figure.savefig(tmp_path / "spec.png")
    ax2.figure.savefig(tmp_path / "map.png")
    assert (tmp_path / "map.png").stat().st_size > 0


def test_pulse_motion_uses_the_dimensionless_definitions():
    m = pulse_motion(BLOCK, "one_sine", 4.0, 2.0)
    assert isinstance(m, OneSine)
    assert m.length == pytest.approx(2.0 * math.pi / (4.0 * BLOCK.p))
    assert m.amplitude == pytest.approx(2.0 * G * math.tan(ALPHA))
    mp = pulse_motion(BLOCK, "mavroeidis_papageorgiou", 4.0, 2.0,
                      pulse_params={"gamma": 3.0, "nu": "0deg"})
    assert 2.0 * math.pi * mp.fp == pytest.approx(4.0 * BLOCK.p)
    assert mp.pga == pytest.approx(2.0 * G * math.tan(ALPHA), rel=1e-3)


# ------------------------------------------------------------------ one vocabulary
def test_pulses_are_catalog_kinds_built_by_the_catalog():
    """Every pulse is a motion kind of rocking.motions.catalog, and the motion of a point
    is the catalog's motion of the same parameters."""
    from rocking.analysis import PULSES
    from rocking.motions import catalog

    assert set(PULSES) <= set(catalog.KINDS)
    p, t_free = BLOCK.p, 60.0 / BLOCK.p
    ag = G * math.tan(ALPHA)
    tp = 2.0 * math.pi / (3.0 * p)
    fp = 3.0 * p / (2.0 * math.pi)
    expected = {
        "one_sine": catalog.build("one_sine", amplitude=2.0 * ag, period=tp,
                                  duration=tp + t_free),
        "one_cosine": catalog.build("one_cosine", amplitude=2.0 * ag, period=tp,
                                    duration=tp + t_free),
        "ricker": catalog.build("ricker", amplitude=2.0 * ag, frequency=fp,
                                duration=3.0 / fp + t_free),
        "mavroeidis_papageorgiou": catalog.build(
            "mavroeidis_papageorgiou", amplitude=2.0 * ag, frequency=fp, gamma=2.5, nu=0.3,
            duration=2.5 / fp + t_free),
    }
    for name, want in expected.items():
        prm = {"gamma": 2.5, "nu": 0.3} if name == "mavroeidis_papageorgiou" else None
        got = pulse_motion(BLOCK, name, 3.0, 2.0, pulse_params=prm)
        assert got == want
        assert got.duration == pytest.approx(want.duration)


@pytest.mark.parametrize("old, new, prm", [
    ("sine", "one_sine", None),
    ("cosine", "one_cosine", None),
    ("mp", "mavroeidis_papageorgiou", {"gamma": 2.0, "nu": 0.5}),
])
def test_old_pulse_names_warn_and_give_identical_results(old, new, prm):
    wr, ar = [1.5, 5.0], [1.3, 3.0, 9.0]
    want_s = overturning_spectrum(BLOCK, new, wr, tol=0.02, accel_ratio=GRID, pulse_params=prm)
    want_m = outcome_map(BLOCK, new, wr, ar, pulse_params=prm)
    with pytest.warns(DeprecationWarning, match=f"write '{new}'"):
        got_s = overturning_spectrum(BLOCK, old, wr, tol=0.02, accel_ratio=GRID,
                                     pulse_params=prm)
    with pytest.warns(DeprecationWarning, match=f"write '{new}'"):
        got_m = outcome_map(BLOCK, old, wr, ar, pulse_params=prm)
    with pytest.warns(DeprecationWarning, match=f"write '{new}'"):
        assert pulse_motion(BLOCK, old, 2.0, 3.0, pulse_params=prm) == pulse_motion(
            BLOCK, new, 2.0, 3.0, pulse_params=prm)
    for got, want in ((got_s, want_s), (got_m, want_m)):
        for col in want.columns:
            np.testing.assert_array_equal(got[col].to_numpy(), want[col].to_numpy())
        assert got.attrs["pulse"] == new


def test_old_option_spellings_warn_and_give_identical_results():
    """options={...} and gamma=/nu= as keywords still work (one release), with a
    DeprecationWarning, and give the same spectrum as **options and pulse_params."""
    prm = {"gamma": 2.0, "nu": 0.5}
    kw = {"tol": 0.02, "accel_ratio": GRID}
    want = overturning_spectrum(BLOCK, "mavroeidis_papageorgiou", [2.0], rtol=1e-9,
                                pulse_params=prm, **kw)
    with pytest.warns(DeprecationWarning) as rec:
        got = overturning_spectrum(BLOCK, "mavroeidis_papageorgiou", [2.0],
                                   options={"rtol": 1e-9}, gamma=2.0, nu=0.5, **kw)
    text = " ".join(str(w.message) for w in rec)
    assert "rtol=" in text and "pulse_params=" in text
    assert all(w.filename == __file__ for w in rec)  # attributed to the caller
    np.testing.assert_array_equal(got["min_overturn_ratio"], want["min_overturn_ratio"])
    assert got.attrs["gamma"] == 2.0 and got.attrs["nu"] == 0.5
    with pytest.warns(DeprecationWarning, match="pulse_params"):
        m = outcome_map(BLOCK, "mavroeidis_papageorgiou", [2.0], [3.0], gamma=2.0, nu=0.5)
    np.testing.assert_array_equal(
        m["max_abs_theta_over_alpha"],
        outcome_map(BLOCK, "mavroeidis_papageorgiou", [2.0], [3.0],
                    pulse_params=prm)["max_abs_theta_over_alpha"])
    with pytest.warns(DeprecationWarning, match="pulse_params"):
        pulse_motion(BLOCK, "mavroeidis_papageorgiou", 2.0, 3.0, gamma=2.0, nu=0.5)
    with pytest.raises(ParameterError, match="rtol"), \
            pytest.warns(DeprecationWarning, match="options"):
        outcome_map(BLOCK, "one_sine", [2.0], [3.0], options={"rtol": 1e-9}, rtol=1e-8)


def test_model_options_reach_the_model():
    """**options are the model's options: a tighter rtol changes nothing in the outcome
    (and the default is what simulate_many uses)."""
    a = outcome_map(BLOCK, "one_sine", [3.0], [1.35, 2.0])
    b = outcome_map(BLOCK, "one_sine", [3.0], [1.35, 2.0], rtol=1e-12)
    r = rocking.simulate(BLOCK, pulse_motion(BLOCK, "one_sine", 3.0, 1.35), rtol=1e-12)
    assert b["max_abs_theta_over_alpha"].iloc[0] == r.max_abs_theta / ALPHA
    np.testing.assert_array_equal(a["overturned"], b["overturned"])
    np.testing.assert_allclose(a["max_abs_theta_over_alpha"], b["max_abs_theta_over_alpha"],
                               rtol=1e-5)


# ------------------------------------------------------------------ bad input
@pytest.mark.parametrize("kwargs, name", [
    ({"pulse": "square"}, "pulse"),
    ({"omega_ratio": [1.0, 0.0]}, "omega_ratio"),
    ({"omega_ratio": -2.0}, "omega_ratio"),
    ({"omega_ratio": [1.0, math.nan]}, "omega_ratio"),
    ({"tol": 0.0}, "tol"),
    ({"tol": 0.5}, "tol"),
    ({"tol": -0.01}, "tol"),
    ({"accel_ratio": [1.0, -3.0]}, "accel_ratio"),
    ({"pulse": "sine_wave"}, "pulse"),
    ({"pulse": "mavroeidis_papageorgiou"}, "gamma"),
    ({"pulse": "mavroeidis_papageorgiou", "pulse_params": {"gamma": 0.8, "nu": 0.0}},
     "gamma"),
    ({"pulse": "mavroeidis_papageorgiou", "pulse_params": {"gamma": 2.0, "nu": "1m"}},
     "nu"),
    ({"pulse_params": {"gamma": 2.0}}, "gamma"),
    ({"pulse_params": {"duration": 2.0}}, "duration"),
    ({"pulse_params": [("gamma", 2.0)]}, "pulse_params"),
    ({"gamma": 2.0}, "gamma"),  # not a parameter of the one-sine pulse, nor of the model
    ({"rtol": -1.0}, "rtol"),
    ({"model": "udec"}, "model"),
    ({"tail": 0.0}, "tail"),
])
def test_bad_input_names_the_parameter(kwargs, name):
    kw = {"pulse": "one_sine", "omega_ratio": [1.0], **kwargs}
    with pytest.raises(ParameterError, match=name):
        overturning_spectrum(BLOCK, **kw)


def test_outcome_map_bad_input():
    with pytest.raises(ParameterError, match="pulse"):
        outcome_map(BLOCK, "triangle", [1.0], [2.0])
    with pytest.raises(ParameterError, match="omega_ratio"):
        outcome_map(BLOCK, "one_sine", [0.0], [2.0])
    with pytest.raises(ParameterError, match="accel_ratio"):
        outcome_map(BLOCK, "one_sine", [1.0], [])


# ------------------------------------------------------------------ the M&P pulse
def _mp_velocity(t, A, fp, gamma, nu, t0):
    tau = t - t0
    v = A / 2 * (1 + np.cos(2 * np.pi * fp * tau / gamma)) * np.cos(2 * np.pi * fp * tau + nu)
    return np.where(np.abs(tau) <= gamma / (2 * fp), v, 0.0)


def _mp_acceleration(t, A, fp, gamma, nu, t0):
    """d/dt of the velocity formula, written out independently of the kernel."""
    w = 2 * np.pi * fp
    tau = t - t0
    env = 1 + np.cos(w * tau / gamma)
    denv = -(w / gamma) * np.sin(w * tau / gamma)
    a = A / 2 * (denv * np.cos(w * tau + nu) - env * w * np.sin(w * tau + nu))
    return np.where(np.abs(tau) <= gamma / (2 * fp), a, 0.0)


MP_CASES = [(2.0, 0.0), (1.5, math.pi / 2), (3.2, 1.1), (1.05, -2.0)]


@pytest.mark.parametrize("gamma, nu", MP_CASES)
def test_mp_acceleration_integrates_to_the_velocity_formula(gamma, nu):
    m = MavroeidisPapageorgiou(3.0, 1.2, gamma, nu, t0=2.0)
    A = m.velocity_amplitude
    t = np.linspace(0.0, 2.0 + gamma / 1.2 + 0.5, 400_001)
    a = m.acceleration(t)
    v = cumulative_trapezoid(a, t, initial=0.0)
    v_formula = _mp_velocity(t, A, 1.2, gamma, nu, 2.0)
    np.testing.assert_allclose(v, v_formula, atol=1e-7 * A)
    np.testing.assert_allclose(m.velocity(t), v_formula, atol=1e-15)
    assert abs(v[-1]) < 1e-7 * A  # the ground comes back to rest


@pytest.mark.parametrize("gamma, nu", MP_CASES)
def test_mp_kernel_matches_the_formula_and_is_zero_outside(gamma, nu):
    fp, t0 = 0.8, 3.0
    m = MavroeidisPapageorgiou(2.0, fp, gamma, nu, t0=t0)
    half = gamma / (2 * fp)
    t = np.linspace(t0 - half - 1.0, t0 + half + 1.0, 20_001)
    expected = _mp_acceleration(t, m.velocity_amplitude, fp, gamma, nu, t0)
    np.testing.assert_allclose(m.acceleration(t), expected, rtol=1e-12, atol=1e-12)
    outside = np.abs(t - t0) > half
    np.testing.assert_array_equal(m.acceleration(t[outside]), 0.0)
    # amplitude is the peak |acceleration|; the load factor scales it
    assert np.max(np.abs(expected)) == pytest.approx(2.0, rel=1e-6)
    np.testing.assert_allclose(m.scaled(-1.5).acceleration(t), -1.5 * m.acceleration(t))
    # the kernel steps onto the ends of the pulse (kinks of the acceleration)
    kind, prm, samples = m.spec()
    assert kind == K.MAVROEIDIS_PAPAGEORGIOU
    assert K.next_breakpoint(kind, prm, samples, 0.0) == pytest.approx(t0 - half)
    assert K.next_breakpoint(kind, prm, samples, t0) == pytest.approx(t0 + half)
    assert K.next_breakpoint(kind, prm, samples, t0 + half + 0.1) == math.inf


def test_mp_defaults_and_validation():
    m = MavroeidisPapageorgiou(1.0, 2.0, 2.0, 0.0)
    assert m.t0 == pytest.approx(0.5)  # starts at t = 0
    assert m.duration == pytest.approx(10.0)
    assert rocking.motions.MavroeidisPapageorgiou is MavroeidisPapageorgiou
    with pytest.raises(ParameterError, match="gamma"):
        MavroeidisPapageorgiou(1.0, 2.0, 1.0, 0.0)
    with pytest.raises(ParameterError, match="fp"):
        MavroeidisPapageorgiou(1.0, 0.0, 2.0, 0.0)
    with pytest.raises(ParameterError, match="t0"):
        MavroeidisPapageorgiou(1.0, 2.0, 2.0, 0.0, t0=0.2)
    with pytest.raises(ParameterError, match="amplitude"):
        MavroeidisPapageorgiou(-1.0, 2.0, 2.0, 0.0)
    with pytest.raises(ParameterError, match="nu"):
        MavroeidisPapageorgiou(1.0, 2.0, 2.0, math.nan)


def test_mp_pulse_runs_in_the_models():
    m = MavroeidisPapageorgiou(3.0 * G * math.tan(ALPHA), 0.6, 2.0, 0.0)
    r = rocking.simulate(BLOCK, m)
    batch = rocking.simulate_many(BLOCK, [m, m.scaled(0.5)])
    assert r.max_abs_theta == batch.max_abs_theta[0]
    assert r.uplift_time >= 0.0


def test_a_narrow_overturning_tongue_is_not_missed():
    """One-cosine pulse at omega_p/p = 1: a tongue of overturning about 0.8% wide lies below
    a safe gap (found on a fine outcome map). The spectrum must return the tongue's lower
    edge to ``tol``, not the upper boundary of the gap."""
    wr = 1.0
    fine = outcome_map(BLOCK, pulse="one_cosine", omega_ratio=[wr],
                       accel_ratio=np.linspace(1.05, 1.25, 401))
    first = float(fine.loc[fine["overturned"], "accel_ratio"].min())
    # the map has a safe gap above the first overturning level (non-monotonic boundary)
    above = fine[fine["accel_ratio"] > first]
    assert (~above["overturned"]).any(), "no safe gap: the case no longer tests the scan"
    df = overturning_spectrum(BLOCK, pulse="one_cosine", omega_ratio=[wr], tol=TOL)
    got = float(df["min_overturn_ratio"].iloc[0])
    assert abs(got / first - 1.0) <= TOL + 0.2 / 400 / first
