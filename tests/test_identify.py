"""Free-rocking identification (rocking.identify): time model, round trips, bad input, CLI."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.integrate import quad

import rocking
from rocking.errors import ParameterError, RecordError, RockingError, UnitError
from rocking.identify import (
    FreeRockingFit,
    IdentificationError,
    free_rocking,
    from_csv,
    quarter_time,
    read_record_csv,
    sigma_surface,
)

FS = 200.0
NOISE = 0.005  # of the initial amplitude
SLENDER = rocking.Block.from_params(0.08, 2.5, 0.95, name="slender")
SLENDER_LIGHT = rocking.Block.from_params(0.08, 2.5, 0.99, name="slender, mu 0.99")
BLOCKS = {f"specimen {n}": rocking.specimen(n) for n in (1, 2, 3, 4)}
BLOCKS.update({"slender": SLENDER, "slender-0.99": SLENDER_LIGHT})


def record(block, *, fs=FS, noise=NOISE, theta0=0.8, hold=None, crop=None, duration=30.0,
           seed=0):
    """A 'measured' free-rocking record of the classical model.

    Released from rest at ``theta0 * alpha``; ``hold`` s held before the release (random
    in [0.2, 1.5] s if None); ``crop`` s cut from the start of the simulated motion (the
    record then starts mid-swing); Gaussian noise of ``noise * theta0`` and a random
    offset of up to 10 % of the release angle.
    """
    rng = np.random.default_rng(seed)
    th0 = theta0 * block.alpha
    r = rocking.simulate(block, None, duration=duration, theta0=th0, dt_out=1.0 / fs)
    t, th = r.t, r.theta
    if crop:
        i = int(round(crop * fs))
        t, th = t[i:], th[i:]
    else:
        hold = rng.uniform(0.2, 1.5) if hold is None else hold
        nh = int(round(hold * fs))
        t = np.concatenate((np.arange(nh) / fs, t + nh / fs))
        th = np.concatenate((np.full(nh, th0), th))
    y = th + noise * th0 * rng.standard_normal(t.size) + rng.uniform(-0.1, 0.1) * th0
    return t, y


def rel(a, b):
    return abs(a / b - 1.0)


# ----------------------------------------------------------------------------- time model
@pytest.mark.parametrize("alpha", [0.05, 0.25, 1.0])
@pytest.mark.parametrize("frac", [1e-3, 0.3, 0.7, 0.95])
def test_quarter_time_is_the_energy_integral(alpha, frac):
    r, p = frac * alpha, 3.0

    def f(x):
        return 1.0 / math.sqrt(math.cos(alpha - r) - math.cos(alpha - x))

    ref = quad(f, 0.0, r, limit=200)[0] / (p * math.sqrt(2.0))
    assert quarter_time(r, alpha, p) == pytest.approx(ref, rel=1e-7)


def test_quarter_time_limits_and_broadcasting():
    # small swings: sqrt(2 r / sin(alpha)) / p; slender blocks: the linearised model
    assert quarter_time(1e-5, 0.2, 4.0) == pytest.approx(math.sqrt(2e-5 / math.sin(0.2)) / 4,
                                                         rel=1e-4)
    assert quarter_time(0.006, 0.01, 4.0) == pytest.approx(math.acosh(1 / 0.4) / 4, rel=1e-4)
    assert quarter_time(0.0, 0.2, 4.0) == 0.0
    assert np.isinf(quarter_time(0.25, 0.2, 4.0))  # beyond alpha: no return
    assert quarter_time(-0.1, 0.2, 4.0) == quarter_time(0.1, 0.2, 4.0)
    T = quarter_time(np.linspace(0.01, 0.1, 5)[:, None], np.array([0.15, 0.2, 0.3]), 3.0)
    assert T.shape == (5, 3)
    assert np.all(np.diff(T, axis=0) > 0) and np.all(np.diff(T, axis=1) < 0)
    assert quarter_time(0.1, 0.2, 2.0) == pytest.approx(2.0 * quarter_time(0.1, 0.2, 4.0))


def test_sigma_surface_is_eq13_and_vanishes_at_the_truth():
    r = np.array([0.15, 0.1, 0.06, 0.03])
    d = quarter_time(r, 0.24, 3.8)
    alphas, ps = np.meshgrid(np.linspace(0.2, 0.3, 7), np.linspace(3.5, 4.1, 5), indexing="ij")
    S = sigma_surface(r, d, alphas, ps)
    brute = np.array([[np.sum((d - quarter_time(r, a, p)) ** 2) for a, p in zip(ra, rp,
                                                                               strict=True)]
                      for ra, rp in zip(alphas, ps, strict=True)])
    np.testing.assert_allclose(S, brute, rtol=1e-9, atol=1e-18)
    assert sigma_surface(r, d, 0.24, 3.8) == pytest.approx(0.0, abs=1e-20)
    w = np.array([1.0, 2.0, 3.0, 4.0])
    assert sigma_surface(r, d + 0.01, 0.24, 3.8, weights=w) == pytest.approx(
        np.sum((w * 0.01) ** 2))
    with pytest.raises(ParameterError, match="same length"):
        sigma_surface(r, d[:3], 0.24, 3.8)


# ----------------------------------------------------------------------------- round trips
@pytest.mark.parametrize("name", list(BLOCKS))
def test_round_trip_noisy_200hz(name):
    """0.5 % noise, random offset, record starting during the hold before the release."""
    block = BLOCKS[name]
    t, y = record(block, seed=list(BLOCKS).index(name) + 11)
    fit = free_rocking(t, y)
    assert rel(fit.alpha, block.alpha) < 0.01
    assert rel(fit.p, block.p) < 0.01
    assert rel(fit.mu, block.mu) < 0.005
    # the reported uncertainties are honest (a few standard errors at most)
    assert abs(fit.alpha - block.alpha) < 4.0 * fit.alpha_std
    assert abs(fit.p - block.p) < 4.0 * fit.p_std
    assert fit.release  # the release after the hold is used
    # mu = 0.99 still rocks after 30 s: no rest, the offset comes from the symmetry
    assert fit.offset_method == ("symmetric" if name == "slender-0.99" else "rest")
    assert fit.n_half_cycles >= 6


@pytest.mark.parametrize("name", list(BLOCKS))
def test_round_trip_noise_free(name):
    block = BLOCKS[name]
    t, y = record(block, noise=0.0, seed=3)
    fit = free_rocking(t, y)
    assert rel(fit.alpha, block.alpha) < 1e-3
    assert rel(fit.p, block.p) < 1e-3
    assert rel(fit.mu, block.mu) < 1e-3
    np.testing.assert_allclose(fit.mu_n, block.mu, rtol=1e-3)


@pytest.mark.parametrize("name,crop", [("specimen 2", 0.3), ("specimen 3", 0.45),
                                       ("slender", 0.8), ("specimen 3", 3.0),
                                       ("slender-0.99", 5.0)])
def test_start_at_any_point(name, crop):
    """Records that start mid-swing (without the release), at 0.6 alpha."""
    block = BLOCKS[name]
    t, y = record(block, theta0=0.6, crop=crop, seed=5)
    fit = free_rocking(t, y)
    # a first half-cycle cut by the start is used only if its peak is in the record
    ref = rocking.simulate(block, None, duration=30.0, theta0=0.6 * block.alpha, dt_out=1e-3)
    tp, _ = ref.half_cycle_peaks()
    c1 = ref.impact_times[np.searchsorted(ref.impact_times, crop)]  # end of the first one
    peak_inside = np.any((tp > crop) & (tp < c1))
    assert fit.release == bool(peak_inside)
    assert fit.peak_times[0] > t[0]
    assert rel(fit.alpha, block.alpha) < 0.01
    assert rel(fit.p, block.p) < 0.01
    assert rel(fit.mu, block.mu) < 0.005


@pytest.mark.parametrize("fs", [50.0, 1000.0])
@pytest.mark.parametrize("name", ["specimen 2", "slender"])
def test_sampling_rates(fs, name):
    block = BLOCKS[name]
    duration = 15.0 if fs > 500 else 30.0  # 15,000 samples at 1 kHz are plenty
    fit = free_rocking(*record(block, fs=fs, seed=7, duration=duration))
    # at 50 Hz there are 4 times fewer samples than at 200 Hz: the scatter doubles
    # (std ~0.4 % for alpha with 0.5 % noise), so the tolerance is 1.5 % there
    tol = 0.015 if fs < 100 else 0.01
    assert rel(fit.alpha, block.alpha) < tol
    assert rel(fit.p, block.p) < tol
    assert rel(fit.mu, block.mu) < 0.005
    assert fit.sampling_rate == pytest.approx(fs)
    exact = free_rocking(*record(block, fs=fs, noise=0.0, seed=7, duration=duration))
    assert rel(exact.alpha, block.alpha) < 1e-3
    assert rel(exact.p, block.p) < 1e-3


def test_peaks_and_crossings_are_sub_sample():
    block = BLOCKS["specimen 2"]
    th0 = 0.8 * block.alpha
    fine = rocking.simulate(block, None, duration=12.0, theta0=th0, dt_out=1e-4)
    tp, vp = fine.half_cycle_peaks()
    t, y = record(block, noise=0.0, hold=0.5, duration=12.0, seed=1)
    fit = free_rocking(t, y)
    c = fit.crossing_times[:, 1] - 0.5  # undo the hold
    k = min(c.size, fine.impact_times.size)
    dt = 1.0 / FS
    assert np.max(np.abs(c[:k] - fine.impact_times[:k])) < 1e-3 * dt
    j = np.searchsorted(tp, fit.peak_times[0] - 0.5 - 0.1)
    m = min(fit.n_half_cycles, tp.size - j)
    assert np.max(np.abs(fit.peak_times[:m] - 0.5 - tp[j:j + m])) < 0.02 * dt
    assert np.max(np.abs(np.abs(fit.peak_values[:m]) - np.abs(vp[j:j + m]))) < 1e-5 * th0


def test_offset_without_rest_and_given_offset():
    """A record cut while the block still rocks: the offset comes from the symmetry."""
    block = BLOCKS["slender-0.99"]
    t, y = record(block, duration=10.0, seed=9)
    fit = free_rocking(t, y)
    assert fit.offset_method == "symmetric"
    assert rel(fit.alpha, block.alpha) < 0.01 and rel(fit.p, block.p) < 0.01
    with pytest.raises(IdentificationError, match="rest"):
        free_rocking(t, y, offset="rest")
    true_offset = np.median(y[: int(0.2 * FS)]) - 0.8 * block.alpha  # during the hold
    given = free_rocking(t, y, offset=true_offset)
    assert given.offset_method == "given" and given.offset == true_offset
    in_deg = free_rocking(t, np.degrees(y), units="deg", offset=math.degrees(true_offset))
    assert in_deg.offset == pytest.approx(true_offset)
    assert rel(given.alpha, block.alpha) < 0.01


def test_spikes_do_not_spoil_the_fit():
    block = BLOCKS["specimen 2"]
    t, y = record(block, seed=4)
    rng = np.random.default_rng(104)
    i = rng.integers(100, 2000, 6)
    y = y.copy()
    y[i] += rng.choice([-1.0, 1.0], i.size) * 0.1 * 0.8 * block.alpha  # 20 noise std
    fit = free_rocking(t, y)
    assert rel(fit.alpha, block.alpha) < 0.01 and rel(fit.p, block.p) < 0.01


def test_degrees_and_units():
    block = BLOCKS["specimen 1"]
    t, y = record(block, seed=2)
    a = free_rocking(t, y)
    b = free_rocking(t, np.degrees(y), units="deg")
    assert b.alpha == pytest.approx(a.alpha, rel=1e-6)
    assert b.offset == pytest.approx(a.offset, rel=1e-6)  # rad, whatever the input
    with pytest.raises(UnitError, match="rad"):
        free_rocking(t, y, units="grad")


def test_small_swings_give_large_honest_uncertainty():
    """Swings small against alpha only fix p*sqrt(alpha): the std says so."""
    block = BLOCKS["specimen 4"]
    t, y = record(block, theta0=0.3, crop=0.2, seed=8)
    try:
        fit = free_rocking(t, y)
    except IdentificationError as e:  # also acceptable: refusing to guess
        assert "alpha" in str(e)
        return
    assert fit.alpha_std / fit.alpha > 0.01
    assert abs(fit.alpha - block.alpha) < 4.0 * fit.alpha_std
    assert fit.alpha_p_corr < -0.9


def test_bootstrap_uncertainty_agrees_with_jacobian():
    block = BLOCKS["specimen 3"]
    t, y = record(block, seed=6)
    jac = free_rocking(t, y)
    boot = free_rocking(t, y, n_boot=40, seed=1)
    assert boot.uncertainty.startswith("bootstrap")
    assert boot.alpha == jac.alpha
    assert 0.33 < boot.alpha_std / jac.alpha_std < 3.0
    assert 0.33 < boot.p_std / jac.p_std < 3.0


# ----------------------------------------------------------------------------- bad input
@pytest.fixture(scope="module")
def clean():
    """(t, theta) with a 0.5 s hold, and the impact times of the record."""
    block = BLOCKS["specimen 2"]
    t, y = record(block, noise=0.002, hold=0.5, duration=12.0, seed=1)
    imp = rocking.simulate(block, None, duration=12.0, theta0=0.8 * block.alpha).impact_times
    return t, y, imp + 0.5


def cut_after(clean, k):
    """The record up to halfway between impacts k and k + 1 (k impacts in it)."""
    t, y, imp = clean
    tc = 0.5 * (imp[k - 1] + imp[k]) if k else 0.5 * (0.5 + imp[0])
    i = int(np.searchsorted(t, tc))
    return t[:i], y[:i]


def test_no_impact(clean):
    with pytest.raises(IdentificationError, match="no impact"):
        free_rocking(*cut_after(clean, 0))


@pytest.mark.parametrize("k", [1, 2, 3])
def test_too_few_impacts(clean, k):
    with pytest.raises(IdentificationError, match=f"only {k} impact"):
        free_rocking(*cut_after(clean, k))


def test_few_impacts_suffice(clean):
    """Six impacts, cut mid-swing: enough peaks for the centre of the oscillation, and
    the parameters come back (with five, the offset must be given: next test; this test
    once passed with alpha 209 % off, when the median of the samples stood in for it)."""
    block = BLOCKS["specimen 2"]
    fit = free_rocking(*cut_after(clean, 6))
    assert fit.n_half_cycles >= 4 and fit.offset_method == "symmetric"
    assert rel(fit.alpha, block.alpha) < 0.01 and rel(fit.p, block.p) < 0.01


@pytest.mark.parametrize("k", [4, 5])
def test_short_record_without_rest_asks_for_the_offset(clean, k):
    """Four or five impacts, cut mid-swing: neither a rest level nor five interior peaks
    for the centre of the oscillation. The median of the samples is no rest level (3 s of
    specimen 2 from 0.6 alpha gave alpha 70 % off): refused, and with the offset given
    the parameters come back."""
    block = BLOCKS["specimen 2"]
    t, y = cut_after(clean, k)
    with pytest.raises(IdentificationError, match="offset"):
        free_rocking(t, y)
    with pytest.raises(IdentificationError, match="symmetric"):
        free_rocking(t, y, offset="symmetric")
    true_offset = np.median(y[: int(0.2 * FS)]) - 0.8 * block.alpha  # during the hold
    fit = free_rocking(t, y, offset=true_offset)
    assert rel(fit.alpha, block.alpha) < 0.01 and rel(fit.p, block.p) < 0.01


@pytest.mark.parametrize("kind", ["constant", "noise", "drift"])
def test_never_rocks(kind):
    rng = np.random.default_rng(0)
    t = np.arange(0.0, 10.0, 1.0 / FS)
    y = {"constant": np.full(t.size, 0.01),
         "noise": 0.01 + 1e-4 * rng.standard_normal(t.size),
         "drift": 1e-6 * t + 1e-4 * rng.standard_normal(t.size)}[kind]
    with pytest.raises(IdentificationError, match="never rocks|no impact"):
        free_rocking(t, y)


@pytest.mark.parametrize("bad", ["nan", "inf", "t-nan"])
def test_non_finite_samples(clean, bad):
    t, y = (a.copy() for a in clean[:2])
    if bad == "t-nan":
        t[10] = np.nan
    else:
        y[500] = np.nan if bad == "nan" else np.inf
    with pytest.raises(ParameterError, match="non-finite"):
        free_rocking(t, y)


def test_malformed_arrays(clean):
    t, y, _ = clean
    with pytest.raises(ParameterError, match="same length"):
        free_rocking(t, y[:-1])
    with pytest.raises(ParameterError, match="increasing"):
        free_rocking(t[::-1], y)
    with pytest.raises(ParameterError, match="1-D"):
        free_rocking(np.c_[t, t], np.c_[y, y])
    with pytest.raises(ParameterError, match="numeric"):
        free_rocking(["a"] * 30, y[:30])
    with pytest.raises(IdentificationError, match="samples"):
        free_rocking(t[:10], y[:10])
    with pytest.raises(ParameterError, match="offset"):
        free_rocking(t, y, offset="middle")
    with pytest.raises(ParameterError, match="loss"):
        free_rocking(t, y, loss="l3")
    with pytest.raises(ParameterError, match="min_amplitude"):
        free_rocking(t, y, min_amplitude=-1.0)


def test_errors_are_rocking_errors():
    assert issubclass(IdentificationError, RockingError)
    assert issubclass(IdentificationError, ValueError)


# ----------------------------------------------------------------------------- the result
@pytest.fixture(scope="module")
def fit():
    return free_rocking(*record(BLOCKS["specimen 1"], seed=21))


def test_fit_fields_and_summary(fit):
    assert isinstance(fit, FreeRockingFit)
    assert repr(fit).startswith("FreeRockingFit(alpha=0.24")
    n = fit.n_half_cycles
    assert fit.peak_times.shape == fit.peak_values.shape == (n,)
    assert fit.crossing_times.shape == fit.residuals.shape == (n, 2)
    assert fit.mu_n.shape == (n - 1,)
    assert np.all(np.diff(fit.peak_times) > 0)
    assert np.all(np.sign(fit.peak_values[1:]) == -np.sign(fit.peak_values[:-1]))
    np.testing.assert_array_equal(fit.crossing_times[1:, 0], fit.crossing_times[:-1, 1])
    assert np.isnan(fit.crossing_times[0, 0]) and np.isnan(fit.residuals[0, 0])  # release
    assert np.nanmax(np.abs(fit.residuals)) < 0.01  # s
    s = json.loads(json.dumps(fit.summary(), allow_nan=False))
    assert s["alpha"] == fit.alpha and s["n_half_cycles"] == n
    assert s["mu_std"] == pytest.approx(np.std(fit.mu_n, ddof=1))
    tab = fit.table()
    assert len(tab) == n and {"amplitude", "rise", "fall", "T_model", "mu_n"} <= set(tab)


def test_to_block_and_compare(fit):
    b = fit.to_block(name="stone")
    assert isinstance(b, rocking.Block)
    assert (b.alpha, b.p, b.mu, b.name) == (fit.alpha, fit.p, fit.mu, "stone")
    df = fit.compare(rocking.specimen(1, "experimental"))
    assert list(df.parameter) == ["alpha", "mu", "p"]
    row = df.set_index("parameter").loc["alpha"]
    assert row.diff_pct == pytest.approx((fit.alpha / 0.235 - 1) * 100)
    assert fit.compare({"alpha": 0.24, "p": 3.8, "mu": 0.9}).shape == (3, 5)
    with pytest.raises(ParameterError):
        fit.compare(42)


def test_error_surface_minimum_is_the_fit(fit):
    alphas, ps, S = fit.error_surface(n=41)
    assert S.shape == (41, 41)
    i, j = np.unravel_index(np.argmin(S), S.shape)
    assert abs(alphas[i] - fit.alpha) <= 2 * (alphas[1] - alphas[0]) + 2 * fit.alpha_std
    assert abs(ps[j] - fit.p) <= 2 * (ps[1] - ps[0]) + 2 * fit.p_std


def test_plots(fit):
    import matplotlib

    matplotlib.use("Agg", force=False)
    ax = fit.plot_error_surface(theoretical=rocking.specimen(1))
    assert ax.get_xlabel().startswith(r"$\alpha$")
    axs = fit.plot_fit(theoretical=rocking.specimen(1))
    assert len(axs) == 2 and len(axs[0].lines) >= 3
    one = fit.plot_fit()
    assert len(one.lines) >= 2


# ----------------------------------------------------------------------------- CSV and CLI
@pytest.fixture(scope="module")
def csv_deg(tmp_path_factory):
    t, y = record(BLOCKS["specimen 2"], seed=31)
    path = tmp_path_factory.mktemp("rec") / "test.csv"
    np.savetxt(path, np.c_[t, np.degrees(y), np.zeros_like(t)], delimiter=",",
               header="# free rocking test\ntime,theta_deg,other", comments="", fmt="%.9g")
    return path, t, y


def test_from_csv(csv_deg, tmp_path):
    path, t, y = csv_deg
    fit = from_csv(path, units="deg")
    direct = free_rocking(t, y)
    assert fit.alpha == pytest.approx(direct.alpha, rel=1e-5)
    tt, aa = read_record_csv(path, units="deg", time_col="time", angle_col=1)
    np.testing.assert_allclose(aa, y, atol=1e-8)
    bare = tmp_path / "bare.txt"
    np.savetxt(bare, np.c_[t, y], fmt="%.10g")  # no header, spaces
    assert from_csv(bare).alpha == pytest.approx(direct.alpha, rel=1e-5)
    with pytest.raises(RecordError, match="not found"):
        from_csv(tmp_path / "missing.csv")
    with pytest.raises(RecordError, match="no column"):
        read_record_csv(path, angle_col="rotation")
    with pytest.raises(RecordError, match="out of range"):
        read_record_csv(path, angle_col=7)
    one = tmp_path / "one.csv"
    one.write_text("t\n0\n1\n")
    with pytest.raises(RecordError, match="two columns"):
        read_record_csv(one)


def test_cli_identify(csv_deg, tmp_path):
    from click.testing import CliRunner

    from rocking.cli.identify import identify

    path, _, _ = csv_deg
    out = tmp_path / "out"
    res = CliRunner().invoke(identify, [str(path), "--units", "deg", "--block-width",
                                        "170mm", "--block-height", "1", "--out", str(out)])
    assert res.exit_code == 0, res.output
    assert "alpha (rad)" in res.output and "%" in res.output
    for f in ("error_surface.png", "fit.png", "fit.json", "half_cycles.csv"):
        assert (out / f).stat().st_size > 0
    data = json.loads((out / "fit.json").read_text())
    assert data["theoretical"]["alpha"] == pytest.approx(math.atan(0.085 / 0.5))
    assert abs(data["difference_pct"]["alpha"]) < 1.0
    res = CliRunner().invoke(identify, [str(path), "--units", "deg", "--json", "--out",
                                        str(out)])
    assert res.exit_code == 0 and json.loads(res.output)["n_half_cycles"] > 5
    res = CliRunner().invoke(identify, [str(path), "--block-width", "0.17", "--out", str(out)])
    assert isinstance(res.exception, ParameterError) and "block-height" in str(res.exception)


def test_cli_registered_error_line(csv_deg, capsys):
    from rocking import cli

    if "identify" not in cli.cli.commands:
        pytest.skip("rocking identify is not registered in rocking.cli yet")
    with pytest.raises(SystemExit) as e:
        cli.main(["identify", "missing.csv"])
    assert e.value.code == 2
    assert capsys.readouterr().err.startswith("error: ")
