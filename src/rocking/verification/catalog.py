r"""The verification cases (:data:`CASES`): numbers from the literature and the closed forms
of the other issues, each with its source, how its reference was obtained, and the package
call that computes the same number.

**Closed forms of the linearised classical model** (Housner 1963), derived here. For
``theta > 0`` and ``|theta| << 1`` Eq (1) reads ``theta'' = p^2 (theta - alpha) + p^2
a(t)/g`` (a positive ground acceleration drives ``theta`` positive). With
``phi = theta - alpha`` and ``y = phi + phi'/p``, ``y' = p y + p a(t)/g``: a first-order
linear equation. From uplift at ``t_u`` (``phi = -alpha``, ``phi' = 0``)

.. math::  y(t) = e^{p (t - t_u)} \left[-\alpha + \int_{t_u}^{t} p \frac{a(s)}{g}
           e^{-p (s - t_u)} ds \right]

and after the pulse (``a = 0``) ``phi`` grows without bound iff ``y >= 0`` at the end of
the pulse. So the least amplitude that overturns the block *without an impact* (mode 2 of
Zhang and Makris 2001) solves ``y(t_end) = 0``; with ``A = a_p / (g alpha)`` and
``w = omega_p / p``:

* rectangular pulse of length ``t_1`` (``t_u = 0``): ``A = 1 / (1 - exp(-p t_1))``;
* half-sine pulse ``a_p sin(omega_p t)``, ``0 <= t <= pi / omega_p`` (``sin(omega_p t_u) =
  1/A``): ``sqrt(A^2 - 1) + A exp(-(pi - asin(1/A)) / w) = w``;
* one-sine pulse over ``2 pi / omega_p``: ``sqrt(A^2 - 1) - A exp(-(2 pi - asin(1/A)) / w)
  = w``;
* one-cosine pulse (``t_u = 0``): ``A = (1 + w^2) / (1 - exp(-2 pi / w))``.

Each holds while ``theta`` stays positive during the pulse, which the simulation checks
(a run that impacts is not counted as mode 2). The half-sine cannot overturn the block
after an impact (the block is pushed one way only and loses energy at each impact), so its
mode-2 amplitude is the least overturning amplitude; the one-sine and one-cosine pulses can
(mode 1), and their cases compare the mode-2 boundary only.

**Quoted values.** Of the papers, only Pena et al. (2007) could be read in full (the
project's copy); its Table II is quoted as printed, and four of its values disagree with
Eqs 2-4 of its own Table I beyond the printing's rounding: they are shown as ``KNOWN``,
each with what is known of the reason and a bound.

**What was searched for the other papers** (issue 22, 2026-11; the stored copies of public
pages reachable by the project's search tool, which returns the opening of a page, never
its whole text):

* Housner (1963): two stored copies of the paper,
  https://scribd.com/doc/263600760/1963-Housner-The-Bevavior-of-Inverted-Pendulum-Strtuctures-During-Earthquakes
  and https://www.scribd.com/document/630563135 (through a mirror); only pages 403-404
  could be read: the abstract, Fig. 1 and Eq (1), printed on page 404 as
  ``I0 d2theta/dt2 = -WR sin(alpha - theta)``, followed by "For tall, slender blocks
  having the angle alpha less than about 20 degrees the sine of the angle may be
  approximated by the angle". Eq (1) is the reference of ``housner-eq1-acceleration``;
  the rectangular-pulse result and its numbers (later pages) could not be read.
* Makris (2014), "A half-century of rocking isolation", Earthquakes and Structures 7(6)
  1187-1221 (https://www.scribd.com/document/529064400/A-half-century-of-rocking-isolation),
  which reviews Housner (1963), Zhang and Makris (2001), Makris and Konstantinidis (2003)
  and Dimitrakopoulos and DeJong (2012): only its first page (title, abstract) could be
  read; none of its equations or figures.
* Makris (2018), "The dynamics of rocking isolation" (book chapter,
  https://scribd.com/document/539462415/The-Dynamics-of-Rocking-Isolation) and its
  newsletter version (SECED 26(2), 2015): abstract only.
* Zhang and Makris (2001): its abstract (https://discovery.researcher.life/article/
  rocking-response-of-free-standing-blocks-under-cycloidal-pulses/
  3ebc6c22970d33feaf6e6ec8b7cb4cc2), which states the two overturning modes and the
  safe region but prints no number. What its Eq 47 states could not be established: no
  reachable text quotes it.
* Makris and Roussos (2000), Makris and Konstantinidis (2003) and Dimitrakopoulos and
  DeJong (2012): no stored copy of their text was found (queries by title, by
  "cycloidal pulse", "minimum overturning acceleration", "omega_p/p", "a_p/(g tan
  alpha)", "similarity laws"); the source-code and documentation indexes hold no
  implementation that quotes them.

Since then (issue 30) some printed numbers could be read, each where
``../shared/reference/published-values.md`` says (a figure's caption, Housner's Eq 9 on his
page 404, the notes of a public repository that reproduce Makris and Konstantinidis's Fig 4):
the cases of group ``printed`` compare them as printed (``reference_kind="printed"``, the
middle of the printed survive/overturn pair, the tolerance half its width), and a
disagreement is shown as ``KNOWN`` with its size. Zhang and Makris's printed thresholds (3.00
/ 3.01, 6.32 / 6.33 and 7.17 / 7.18 for omega_p/p = 5) are not compared: they depend on how
their one-sine pulse starts (the phase at which it begins relative to uplift), which the
quoted text does not fix; our pulse starting at zero gives other boundaries. The other cases
of those papers compare the closed forms derived above (each says so); a reader with the
papers can replace a derived reference by the printed one, showing a disagreement
(``known_difference``), never tuning it away.
"""

from __future__ import annotations

import math
import os
import tempfile
import warnings
from functools import cache

import numpy as np

from ..errors import PlausibilityWarning
from .core import Case

G = 9.80665  # rocking.units.G, written here so the reference values do not import us

HOUSNER_1963 = ("Housner, G. W. (1963). The behavior of inverted pendulum structures "
                "during earthquakes. Bulletin of the Seismological Society of America "
                "53(2), 403-417.")
MAKRIS_ROUSSOS_2000 = ("Makris, N. and Roussos, Y. S. (2000). Rocking response of rigid "
                       "blocks under near-source ground motions. Geotechnique 50(3), "
                       "243-262.")
ZHANG_MAKRIS_2001 = ("Zhang, J. and Makris, N. (2001). Rocking response of free-standing "
                     "blocks under cycloidal pulses. Journal of Engineering Mechanics "
                     "127(5), 473-483.")
MAKRIS_KONSTANTINIDIS_2003 = ("Makris, N. and Konstantinidis, D. (2003). The rocking "
                              "spectrum and the limitations of practical design "
                              "methodologies. Earthquake Engineering and Structural "
                              "Dynamics 32(2), 265-289.")
DIMITRAKOPOULOS_DEJONG_2012 = ("Dimitrakopoulos, E. G. and DeJong, M. J. (2012). "
                               "Revisiting the rocking block: closed-form solutions and "
                               "similarity laws. Proceedings of the Royal Society A 468, "
                               "2294-2318.")
PENA_2007 = ("Peña, F., Prieto, F., Lourenço, P. B., Campos Costa, A. and Lemos, J. V. "
             "(2007). On the dynamics of rocking motion of single rigid-block structures. "
             "Earthquake Engineering and Structural Dynamics 36(15), 2383-2399.")
CHOPRA = ("Chopra, A. K. (2012). Dynamics of Structures: Theory and Applications to "
          "Earthquake Engineering, 4th ed. Prentice Hall.")
MIRANDA_TAGHAVI_2005 = ("Miranda, E. and Taghavi, S. (2005). Approximate floor "
                        "acceleration demands in multistory buildings. I: Formulation. "
                        "Journal of Structural Engineering 131(2), 203-211.")
VASSILIOU_MAKRIS_2012 = ("Vassiliou, M. F. and Makris, N. (2012). Analysis of the rocking "
                         "response of rigid blocks standing free on a seismically isolated "
                         "base. Earthquake Engineering and Structural Dynamics 41(2), "
                         "177-196.")

UNREAD = ("The paper's printed values could not be read in the sources available to this "
          "project (searched in 2026-11: see the module docstring of "
          "rocking.verification.catalog for where); no number of it is quoted.")

# ------------------------------------------------------------------------ shared pieces
PULSE_BLOCK = dict(alpha=0.2, p=2.0, mu=0.9)
"""The block of the pulse cases (alpha in rad, p in 1/s)."""

BISECTION_TOL = 1e-7
"""Relative width of the bisection bracket of the threshold cases."""


def _block(**kw):
    from ..blocks.block import Block

    return Block.from_params(**{**PULSE_BLOCK, **kw})


def _simulate(block, motion, **kw):
    from ..models.run import simulate

    return simulate(block, motion, **kw)


def _bisect(overturns, lo: float, hi: float, tol: float = BISECTION_TOL) -> float:
    """The amplitude ratio where ``overturns`` switches from False (at ``lo``) to True (at
    ``hi``), to a relative width ``tol``; RuntimeError if the bracket does not hold."""
    if overturns(lo) or not overturns(hi):
        raise RuntimeError(f"no threshold in [{lo:g}, {hi:g}]: the block "
                           f"{'overturns' if overturns(lo) else 'survives'} at {lo:g} and "
                           f"{'overturns' if overturns(hi) else 'survives'} at {hi:g}")
    while hi - lo > tol * hi:
        mid = 0.5 * (lo + hi)
        if overturns(mid):
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


def _pulse_threshold(kind: str, omega_ratio: float, *, length=None, mode2: bool = True,
                     bracket=(1.0001, 200.0)) -> float:
    """The least ``a_p / (g alpha)`` of the linearised classical model that overturns the
    pulse block (without an impact if ``mode2``), by bisection on :func:`rocking.simulate`."""
    from ..motions.pulses import HalfSine, OneCosine, OneSine, Rectangular

    blk = _block()
    p, alpha = blk.p, blk.alpha
    if kind == "rectangular":
        cls, lp = Rectangular, length
    else:
        w = omega_ratio * p
        cls, lp = {"half_sine": (HalfSine, math.pi / w), "one_sine": (OneSine, 2 * math.pi / w),
                   "one_cosine": (OneCosine, 2 * math.pi / w)}[kind]

    def overturns(ratio: float) -> bool:
        m = cls(ratio * G * alpha, lp, duration=lp + 30.0 / p)
        r = _simulate(blk, m, linear=True, rtol=1e-10)
        return bool(r.overturned and (r.n_impacts == 0 or not mode2))

    return _bisect(overturns, *bracket)


def _solve(f, lo: float, hi: float) -> float:
    from scipy.optimize import brentq

    return brentq(f, lo, hi, xtol=1e-14, rtol=1e-14)


def half_sine_mode2(w: float) -> float:
    """``A`` solving ``sqrt(A^2 - 1) + A exp(-(pi - asin(1/A))/w) = w`` (module docstring)."""
    return _solve(lambda A: math.sqrt(A * A - 1) + A * math.exp(-(math.pi - math.asin(1 / A))
                                                                 / w) - w, 1.0, 10.0 * w + 10)


def one_sine_mode2(w: float) -> float:
    """``A`` solving ``sqrt(A^2 - 1) - A exp(-(2 pi - asin(1/A))/w) = w`` (module
    docstring)."""
    return _solve(lambda A: math.sqrt(A * A - 1)
                  - A * math.exp(-(2 * math.pi - math.asin(1 / A)) / w) - w,
                  1.0, 10.0 * w * w + 10)


def one_cosine_mode2(w: float) -> float:
    """``A = (1 + w^2) / (1 - exp(-2 pi / w))`` (module docstring)."""
    return (1.0 + w * w) / (1.0 - math.exp(-2.0 * math.pi / w))


# ------------------------------------------------------------------ classical: Housner
FREE = dict(alpha=0.2, p=3.0, frac=0.5)


def _free_period() -> float:
    blk = _block(alpha=FREE["alpha"], p=FREE["p"], mu=1.0)
    T = 4.0 / blk.p * math.acosh(1.0 / (1.0 - FREE["frac"]))
    r = _simulate(blk, None, duration=2.2 * T, theta0=FREE["frac"] * blk.alpha, linear=True,
                  rtol=1e-12)
    return 2.0 * float(np.mean(np.diff(r.impact_times)))


RECT_BLOCK = dict(width=0.4, height=1.6, mass=100.0)
"""A rectangular block whose restitution is Housner's (alpha = atan(1/4))."""


def _rect_block():
    from ..blocks.block import Block

    return Block.rectangular(**RECT_BLOCK)


def _eq1_acceleration() -> float:
    """theta''(0) of the nonlinear model's rectangular block released from rest at theta0 =
    alpha/2: twice the t^2 coefficient of a degree-5 polynomial fitted to theta(t) over
    the first 0.03 s (before the impact at about 0.3 s)."""
    blk = _rect_block()
    r = _simulate(blk, None, duration=0.05, theta0=0.5 * blk.alpha, dt_out=1e-4,
                  rtol=1e-12)
    t, th = np.asarray(r.t), np.asarray(r.theta)
    m = t <= 0.03
    return 2.0 * float(np.polyfit(t[m], th[m], 5)[-3])


def _eq1_acceleration_ref() -> float:
    """Housner (1963) Eq (1), I0 theta'' = -W R sin(alpha - theta), at theta = alpha/2, with
    W, R, alpha from the block's width and height and I0 = (4/3)(W/g) R^2 (uniform
    rectangle about its corner: (1/3) m (b^2 + h^2) about the centre plus m R^2)."""
    b, h = RECT_BLOCK["width"] / 2, RECT_BLOCK["height"] / 2
    m = RECT_BLOCK["mass"]
    R, alpha = math.hypot(b, h), math.atan(b / h)
    i0 = m * (b * b + h * h) / 3.0 + m * R * R
    return -m * G * R * math.sin(alpha - 0.5 * alpha) / i0


def _velocity_ratio(block, model: str = "housner", th0_frac: float = 0.6) -> float:
    """The angular-velocity ratio through the first impact, from the free-rocking
    amplitudes before (``theta0``) and after it (energy conservation between impacts)."""
    th0 = th0_frac * block.alpha
    T = 4.0 / block.p * math.acosh(1.0 / (1.0 - th0_frac))
    r = _simulate(block, None, model=model, duration=1.2 * T, theta0=th0, dt_out=1e-4)
    r1 = float(np.abs(r.half_cycle_peaks()[1])[1])
    a = block.alpha
    return math.sqrt((math.cos(a - r1) - math.cos(a)) / (math.cos(a - th0) - math.cos(a)))


def _uplift_threshold() -> float:
    """The least a/(g tan alpha) of a constant acceleration (a rectangular pulse of 0.2 s)
    that uplifts the nonlinear block, by bisection on its uplift."""
    from ..motions.pulses import Rectangular

    blk = _block()
    thr = G * math.tan(blk.alpha)

    def uplifts(ratio: float) -> bool:
        r = _simulate(blk, Rectangular(ratio * thr, 0.2, duration=0.5))
        return not math.isnan(r.uplift_time)

    return _bisect(uplifts, 0.9, 1.1, tol=1e-9)


def _rect_pulse_response() -> float:
    """theta_max / alpha after a rectangular pulse at 90 % of its overturning amplitude."""
    from ..motions.pulses import Rectangular

    blk = _block()
    x = 1.0
    A = 0.9 / (1.0 - math.exp(-x))
    t1 = x / blk.p
    r = _simulate(blk, Rectangular(A * G * blk.alpha, t1, duration=t1 + 20.0 / blk.p),
                  linear=True, rtol=1e-11, dt_out=1e-4)
    return float(np.abs(r.half_cycle_peaks()[1])[0]) / blk.alpha


def _rect_pulse_response_ref() -> float:
    """``r/alpha = 1 - sqrt((1 - th1/alpha)^2 - (om1/(p alpha))^2)`` with ``th1/alpha =
    (A - 1)(cosh x - 1)``, ``om1/(p alpha) = (A - 1) sinh x`` at the pulse's end (the
    linearised free motion conserves ``(theta - alpha)^2 - (theta'/p)^2``)."""
    x = 1.0
    k = 0.9 / (1.0 - math.exp(-x)) - 1.0
    th1, om1 = k * (math.cosh(x) - 1.0), k * math.sinh(x)
    return 1.0 - math.sqrt((1.0 - th1) ** 2 - om1 ** 2)


# ------------------------------------------------------------------------- similarity
SIMILAR = dict(alpha=0.2, mu=0.9, p=(1.5, 6.0), omega_ratio=3.0, accel_ratio=1.5)


def _similarity_difference() -> float:
    """max |theta_1/alpha - theta_2/alpha| at equal ``p t`` for two blocks of the same alpha
    and mu whose p differ fourfold (sizes 16-fold), under one-cosine pulses of equal
    ``omega_p/p`` and ``a_p/(g tan alpha)`` (nonlinear model, impacts included)."""
    from ..motions.pulses import OneCosine

    out = []
    h = 0.01  # output step in p t
    for p in SIMILAR["p"]:
        blk = _block(alpha=SIMILAR["alpha"], p=p, mu=SIMILAR["mu"])
        Tp = 2 * math.pi / (SIMILAR["omega_ratio"] * p)
        m = OneCosine(SIMILAR["accel_ratio"] * G * math.tan(blk.alpha), Tp,
                      duration=40.0 / p)
        r = _simulate(blk, m, dt_out=h / p, rtol=1e-12)
        if r.n_impacts < 2 or r.overturned:
            raise RuntimeError("the similarity case must rock with impacts, not overturn")
        out.append(r.theta / blk.alpha)
    n = min(a.size for a in out)
    return float(np.max(np.abs(out[0][:n] - out[1][:n])))


def _dd_threshold(p: float) -> float:
    from ..analysis.overturning import overturning_spectrum

    blk = _block(alpha=SIMILAR["alpha"], p=p, mu=SIMILAR["mu"])
    df = overturning_spectrum(blk, "one_sine", [SIMILAR["omega_ratio"]], tol=1e-4)
    return float(df["min_overturn_ratio"].iloc[0])


# ------------------------------------------------------------------------ cross-model
def _free_amplitudes(model: str, block, n: int = 4, **kw) -> np.ndarray:
    th0 = 0.5 * block.alpha
    r = _simulate(block, None, model=model, duration=kw.pop("duration", 6.0), theta0=th0,
                  dt_out=kw.pop("dt_out", 2e-4), **kw)
    return np.abs(r.half_cycle_peaks()[1])[:n]


def _ccrr_block():
    return _block(alpha=0.2, p=2.0, mu=0.9)


def _specimen2():
    from ..blocks.specimens import specimen

    return specimen(2, "experimental")


# -------------------------------------------------------------------------- buildings
def _transmissibility() -> float:
    from ..buildings import Building, FloorMotion
    from ..motions.harmonic import Sine

    T, zeta, r = 0.5, 0.05, 1.5
    f = r / T
    ground = Sine.from_acceleration(f, 1.0, duration=40.0)
    fm = FloorMotion(ground, Building.sdof(T, zeta), floor=1)
    t = np.arange(fm.samples.size) * fm.step
    sel = (t > 40.0 - 10.0 / f - 1e-9) & (t <= 40.0 - 1e-9)
    wt = 2 * np.pi * f * t[sel]
    coef, *_ = np.linalg.lstsq(np.column_stack([np.sin(wt), np.cos(wt)]), fm.samples[sel],
                               rcond=None)
    return math.hypot(*coef)


def _transmissibility_ref() -> float:
    zeta, r = 0.05, 1.5
    return math.sqrt((1 + (2 * zeta * r) ** 2) / ((1 - r * r) ** 2 + (2 * zeta * r) ** 2))


def _cantilever_roots(n: int) -> list[float]:
    return [_solve(lambda x: math.cos(x) * math.cosh(x) + 1.0, (j - 1) * math.pi + 1e-6,
                   j * math.pi) for j in range(1, n + 1)]


def _cantilever_ratio() -> float:
    from ..buildings import Building

    b = Building.continuous(1.0, 0.0, n_modes=3)
    return float(b.periods[0] / b.periods[1])


def _shear_ratio() -> float:
    from ..buildings import Building

    b = Building.shear(5, 0.73)
    return float(b.omegas[1] / b.omegas[0])


# -------------------------------------------------------------------------- isolation
ISO = dict(isolation="linear", isolation_period=2.0, isolation_damping=0.1, scale=0.1)


@cache
def _isolated_run():
    from ..blocks.specimens import specimen
    from ..motions.records import load_builtin

    rec = load_builtin("Rinaldi228").scaled(ISO["scale"])
    blk = specimen(2, "experimental")
    with warnings.catch_warnings():  # the restitution it warns about: no impact here
        warnings.simplefilter("ignore", PlausibilityWarning)
        r = _simulate(blk, rec, model="isolated", isolation=ISO["isolation"],
                      isolation_period=ISO["isolation_period"],
                      isolation_damping=ISO["isolation_damping"])
    if not math.isnan(r.uplift_time):
        raise RuntimeError("the block uplifted: not the no-uplift case")
    return rec, r


def _isolated_spectrum(kind: str) -> float:
    from ..motions.spectra import response_spectrum

    rec, _ = _isolated_run()
    return float(response_spectrum(rec, [ISO["isolation_period"]], ISO["isolation_damping"],
                                   kind=kind)[0])


# ------------------------------------------------------------------------------ shapes
BOX = dict(a=0.5, b=0.25, c=1.25, density=2000.0)
"""A box (m, kg/m^3): shaken along x (phi = 0) it rocks across its a-face, half-width a/2."""


@cache
def _box_parameters() -> dict:
    import trimesh

    from ..shapes import load_shape

    a, b, c = BOX["a"], BOX["b"], BOX["c"]
    mesh = trimesh.creation.box(extents=(a, b, c))
    mesh.apply_translation((0.0, 0.0, c / 2))
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "box.ply")
        mesh.export(path)
        shape = load_shape(path, density=BOX["density"])
    return shape.parameters(0.0)


def _box_closed_form() -> tuple[float, float, float]:
    half, hh = BOX["a"] / 2, BOX["c"] / 2
    alpha = math.atan(half / hh)
    return alpha, math.sqrt(3 * G / (4 * math.hypot(half, hh))), 1 - 1.5 * math.sin(alpha) ** 2


# ------------------------------------------------------------------- Pena et al. 2007
def _geometric(n: int, name: str) -> float:
    from ..blocks.specimens import specimen

    return float(getattr(specimen(n, "geometric"), name))


TABLE2_HOW = ("Quoted from Table II of Pena et al. (2007), column T (the theoretical "
              "parameters, Eqs 2-4), as printed (alpha and mu to 3 decimals, p to 2; the "
              "page is not given in the project's copy of the paper). Computed: "
              "rocking.specimen({n}, 'geometric'), Eqs 2-4 on the width and height of "
              "Table I. Tolerance: half a unit of the last printed digit.")
TABLE2_UNITS = {"alpha": ("rad", 5e-4), "p": ("1/s", 5e-3), "mu": ("-", 5e-4)}


def _table2_case(n: int, name: str, printed: float, known: str = "",
                 known_tolerance: float | None = None) -> Case:
    unit, tol = TABLE2_UNITS[name]
    return Case(
        name=f"pena-table2-specimen{n}-{name}", source=PENA_2007, reference_kind="printed",
        what=f"{name} of specimen {n} from its Table I geometry (Eq "
             f"{ {'alpha': 2, 'p': 3, 'mu': 4}[name] }) against the printed theoretical value",
        how=TABLE2_HOW.format(n=n), reference=lambda: printed,
        compute=lambda: _geometric(n, name), unit=unit, tolerance=tol,
        tolerance_kind="abs", group="paper", known_difference=known,
        known_tolerance=known_tolerance)


def _table3_K(n: int) -> float:
    """K of Eq 17, M/2 (p^2 + 3 g/(4 R)), with Table II's T parameters and Table I's mass
    and geometry, by rocking.models.dem.paper_parameters."""
    from ..blocks.specimens import specimen
    from ..models.dem import paper_parameters

    return float(paper_parameters(specimen(n, "theoretical"))["K"])


# ------------------------------------------------------------------------------ cases
def _rectangular_case(pt1: float) -> Case:
    return Case(
        name=f"housner-rectangular-pulse-pt{pt1:g}",
        source=HOUSNER_1963,
        what=f"least a/(g alpha) of a rectangular pulse of length t1 = {pt1:g}/p that "
             "overturns the linearised block",
        how="Housner (1963), Eq 9 as printed (read in the opening pages of the paper, "
            "../shared/reference/published-values.md): cosh(p t1) = 1 + 1/(2 A (A - 1)) "
            "with A = a/(g alpha), the least overturning A of the linearised block under a "
            "rectangular pulse of length t1. Solved for A it is 1/(1 - exp(-p t1)), the "
            "closed form derived here (module docstring: the free motion after the pulse "
            "conserves (theta - alpha)^2 - (theta'/p)^2, and the block overturns iff "
            "theta - alpha + theta'/p >= 0 at t1); the two agree identically.",
        reference_kind="equation",
        reference=lambda: 1.0 / (1.0 - math.exp(-pt1)),
        compute=lambda: _pulse_threshold("rectangular", 0.0, length=pt1 / PULSE_BLOCK["p"]),
        tolerance=1e-5, group="classical")


# ------------------------------------------------------ printed values (published-values)
READ_IN_NOTES = ("as read in the rocking notes of the public repository "
                 "wshwwl/wshwwl.github.com (2020/02/rock.md), which reproduce the figure; the "
                 "paper itself could not be read here")
READ_IN_CAPTION = "as read in the figure's caption (the caption could be read, the text not)"


def _printed_threshold(alpha: float, p: float, mu: float, kind: str, length: float,
                       lo: float, hi: float, *, linear: bool = False,
                       g_paper: float = G) -> float:
    """The least pulse amplitude (in the paper's units: m/s^2 with its ``g_paper``, which
    our G replaces in a/g) that overturns the block (alpha, p, mu) under the pulse ``kind``
    of ``length`` (s), by bisection in ``[lo, hi]`` (a bracket with one switch: overturning
    under pulses is not monotone in the amplitude)."""
    from ..motions.pulses import HalfSine, OneCosine, OneSine

    cls = {"half_sine": HalfSine, "one_sine": OneSine, "one_cosine": OneCosine}[kind]
    blk = _block(alpha=alpha, p=p, mu=mu)

    def overturns(a_paper: float) -> bool:
        m = cls(a_paper / g_paper * G, length, duration=length + 30.0 / p)
        return bool(_simulate(blk, m, linear=linear, rtol=1e-10).overturned)

    return _bisect(overturns, lo, hi, tol=1e-7)


MK_ALPHA = math.radians(15.0)
MR_ALPHA = math.atan(1.0 / 3.0)  # b/h = 0.2/0.6 and 0.5/1.5
MR_P_FIG2 = math.sqrt(3.0 * 9.81 / (4.0 * math.hypot(0.2, 0.6)))  # Eq 3, their g


# ---------------------------------------------------------------- 3-D rigid body (rigid3d)
R3D_BOX = dict(width=0.17, depth=0.502, height=1.0, mass=228.0)  # specimen 2 (Table I)


def _r3d_box():
    from ..shapes import Shape

    b = R3D_BOX
    return Shape.box(b["width"], b["depth"], b["height"], mass=b["mass"], name="specimen 2")


def _r3d_alpha() -> float:
    return math.atan(R3D_BOX["width"] / R3D_BOX["height"])


def _r3d_impact_ratio() -> float:
    """The body angular velocity just after / before the first impact of the box released
    from alpha/2 (sticking friction, restitution 0), step 2.5e-5 s."""
    h = 2.5e-5
    r = _simulate(_r3d_box(), None, model="rigid3d", duration=0.45,
                  tilt0=0.5 * _r3d_alpha(), friction=2.0, dt_out=h, step=h)
    k = int(round(r.impact_times[0] / h))
    w = r.states[:, 11]  # about the body's y axis
    return float(w[k] / w[k - 1])


def _r3d_sine(model: str) -> float:
    """max |theta| of specimen 2 under 2.5 s of the 5 Hz, 5 mm sine of Figure 7: the
    classical block (geometric alpha and p, Eq 4 restitution) or the 3-D box (step 5e-5)."""
    from ..blocks.specimens import specimen
    from ..motions import Sine

    m = Sine(freq=5.0, amplitude=0.005, duration=2.5)
    if model == "housner":
        b = specimen(2, params="geometric")
        b = b.with_params(mu=1.0 - 1.5 * math.sin(b.alpha) ** 2)
        return float(_simulate(b, m, duration=2.5, dt_out=1e-3).max_abs_theta)
    r = _simulate(_r3d_box(), m, model="rigid3d", duration=2.5, dt_out=1e-3, step=5e-5,
                  friction=2.0)
    return float(r.max_tilt)


def _r3d_sliding() -> float:
    """The relative acceleration (m/s^2) of a squat box (1.0 x 0.8 x 0.2 m) on a ground
    accelerating at 0.5 g along 30 deg, friction 0.3: from its displacement after 0.5 s."""
    from ..motions.pulses import Rectangular
    from ..shapes import Shape

    squat = Shape.box(1.0, 0.8, 0.2, density=2500.0)
    r = _simulate(squat, Rectangular(0.5 * G, 1.0), model="rigid3d", duration=0.5,
                  friction=0.3, dt_out=0.01, direction=30.0)
    return float(2.0 * math.hypot(r.states[-1, 0], r.states[-1, 1]) / r.t[-1] ** 2)


def _r3d_uplift(shape, psi_deg: float, a_up: float, duration: float = 2.0) -> float:
    """The acceleration (m/s^2) at which a slow ramp of ground acceleration along
    ``psi_deg`` lifts ``shape`` (rigid3d, sticking friction)."""
    from ..motions import Record

    dt = 1e-3
    t = np.arange(0.0, duration + dt, dt)
    slope = 1.5 * a_up / duration
    r = _simulate(shape, Record(slope * t, dt, name="ramp"), model="rigid3d",
                  duration=duration, dt_out=0.01, direction=psi_deg, friction=2.0)
    return float(slope * r.uplift_time)


def _r3d_box_uplift_ref() -> float:
    from ..shapes import Shape

    box = Shape.box(0.25, 0.5, 1.0, density=2500.0)
    return float(box.parameters(math.radians(37.0))["uplift_3d_plus"])


def _r3d_box_uplift() -> float:
    from ..shapes import Shape

    box = Shape.box(0.25, 0.5, 1.0, density=2500.0)
    return _r3d_uplift(box, 37.0, _r3d_box_uplift_ref())


R3D_CYL = (0.2, 1.2)  # m: radius, height


def _r3d_cylinder_ratio() -> float:
    """The cylinder's angular-velocity ratio across its first impact, rocking in a plane on
    its rim (rigid3d, exact rims, sticking friction, step 5e-5 s)."""
    from ..shapes import Shape

    r_, height = R3D_CYL
    cyl = Shape.cylinder(r_, height, density=2500.0)
    h = 5e-5
    alpha = math.atan(r_ / (0.5 * height))
    r = _simulate(cyl, None, model="rigid3d", duration=0.6, tilt0=0.5 * alpha, friction=2.0,
                  dt_out=h, step=h)
    k = int(round(r.impact_times[0] / h))
    w = r.states[:, 11]
    return float(w[k] / w[k - 1])


def _r3d_flight_momentum() -> float:
    """The largest relative change of the angular momentum (about the centre of mass,
    ground frame) of a spinning box thrown off the ground by a vertical pulse of -1.5 g,
    while it flies (no contact: every step's vertices above the ground)."""
    from ..motions import GroundMotion, Record
    from ..shapes import Shape

    box = Shape.box(0.3, 0.4, 0.5, density=2000.0)
    from ..models.rigid3d import rest_state

    y0 = rest_state(box)
    y0[10:13] = (0.3, -0.2, 1.0)  # spinning, body frame (rad/s)
    dt = 1e-3
    n = 400
    az = np.where(np.arange(n) * dt < 0.1, -1.5 * G, 0.0)
    motion = GroundMotion(Record(np.zeros(n), dt, name="still"), Record(az, dt, name="up"))
    r = _simulate(box, motion, model="rigid3d", duration=0.3, state0=y0, dt_out=1e-3,
                  step=1e-4, friction=0.7)
    from scipy.spatial.transform import Rotation

    I = np.asarray(box.inertia_local)
    q = r.states[:, 3:7]
    R = Rotation.from_quat(q[:, [1, 2, 3, 0]]).as_matrix()
    L = np.einsum("nij,jk,nk->ni", R, I, r.states[:, 10:13])
    z = r.states[:, 2]
    verts = np.asarray(box.hull_points()) - np.array([0.0, 0.0, box.h])
    low = z + np.min(np.einsum("nj,kj->nk", R[:, 2, :], verts), axis=1)
    flying = low > 1e-4
    if flying.sum() < 20:
        raise RuntimeError("the box did not fly")
    Lf = L[flying]
    return float(np.max(np.linalg.norm(Lf - Lf[0], axis=1)) / np.linalg.norm(Lf[0]))


R3D_TURN_DEG = 37.0
"""The angle (deg) by which the invariance case turns the body and the pair."""
R3D_INVARIANCE_SCENES = ((0.6, 60.0), (0.8, 60.0))
"""(scale of the Rinaldi set, heading in deg) of the invariance cases' two runs: one that
rocks (39 impacts, max tilt 0.02 rad, twist 0.024 rad, no overturn) and one that
overturns (11 impacts, twist 0.09 rad); both well conditioned: a change of 1e-15 to 1e-11
in the motion's scale, or of 1e-12 deg in the heading, moves them (:func:`_r3d_difference`)
by at most 3e-8 (measured). Many runs are not: near a threshold a change of 1e-15 in the
scale changes the number of impacts."""


def _r3d_skewed_vertices() -> tuple[np.ndarray, np.ndarray]:
    """The vertices (m) and triangles of the invariance cases' body: a hexahedron with a
    0.40 x 0.30 m base and a 0.34 x 0.22 m top 1 m above it, the top shifted by (0.06,
    0.03) m and turned by 12 deg: no plane or axis of symmetry, its centre of mass off the
    base's centre, its support the base (8 hull vertices)."""
    import trimesh

    base = np.array([[-0.2, -0.15, 0.0], [0.2, -0.15, 0.0], [0.2, 0.15, 0.0],
                     [-0.2, 0.15, 0.0]])
    c, s = math.cos(math.radians(12.0)), math.sin(math.radians(12.0))
    top = [(c * x - s * y + 0.06, s * x + c * y + 0.03, 1.0)
           for x, y in ((-0.17, -0.11), (0.17, -0.11), (0.17, 0.11), (-0.17, 0.11))]
    hull = trimesh.Trimesh(np.vstack([base, np.array(top)])).convex_hull
    return np.asarray(hull.vertices, dtype=float), np.asarray(hull.faces)


def _r3d_outputs(r) -> dict:
    """The invariance cases' view of a rigid3d run: its scalar outputs, the centre of
    mass's horizontal path relative to its start (m) and the tilt history (rad)."""
    keys = ("max_tilt", "max_slide", "residual_slide", "max_twist", "residual_twist",
            "overturn_time", "overturn_azimuth", "uplift_time", "n_impacts", "overturned")
    out = {k: float(r.outputs[k]) for k in keys}
    out["path"] = r.states[:, :2] - r.states[0, :2]
    out["tilt"] = np.asarray(r.tilt, dtype=float)
    return out


def _r3d_difference(a: dict, b: dict) -> float:
    """The largest difference between two views (:func:`_r3d_outputs`) that should be
    equal: of each output relative to its size (the tilt's and twist's sizes at least
    1e-3 rad, the slides' at least 1 mm, the times' 1 s), of the azimuth in rad, of the
    tilt history (rad) and of the path relative to its largest excursion; 1.0 when the
    number of impacts, the overturn or the length of the histories differ."""
    if (a["n_impacts"] != b["n_impacts"] or a["overturned"] != b["overturned"]
            or a["tilt"].shape != b["tilt"].shape):
        return 1.0
    floors = {"max_tilt": 1e-3, "max_twist": 1e-3, "residual_twist": 1e-3,
              "max_slide": 1e-3, "residual_slide": 1e-3, "overturn_time": 1.0,
              "uplift_time": 1.0}
    d = 0.0
    for k, floor in floors.items():
        if math.isnan(a[k]) or math.isnan(b[k]):
            if math.isnan(a[k]) != math.isnan(b[k]):
                return 1.0
            continue
        d = max(d, abs(a[k] - b[k]) / max(abs(a[k]), floor))
    if a["overturned"]:
        d = max(d, abs(math.radians(math.remainder(a["overturn_azimuth"]
                                                   - b["overturn_azimuth"], 360.0))))
    d = max(d, float(np.max(np.abs(a["tilt"] - b["tilt"]))))
    size = max(float(np.max(np.linalg.norm(a["path"], axis=1))), 1e-3)
    return max(d, float(np.max(np.linalg.norm(a["path"] - b["path"], axis=1))) / size)


def rigid3d_invariance(kind: str, heading_error: float = 0.0) -> float:
    """The largest difference (:func:`_r3d_difference`) between the runs of the skewed
    body (:func:`_r3d_skewed_vertices`) under the Rinaldi set (three components) and those
    of its image: ``"turn"``, the body turned by :data:`R3D_TURN_DEG` about the vertical
    and the pair's heading by the same angle (the image's azimuth and path turned back);
    ``"mirror"``, the body mirrored in its x-z plane and the motion's y component negated
    (the pair's second component negated, the heading negated: the body sees ``(a_x,
    -a_y, a_z)``; the image's twist, azimuth and y mirrored back). ``heading_error``
    (deg), added to the image's heading, breaks the symmetry (a check that the measure
    sees it)."""
    from ..motions import HorizontalPair
    from ..shapes import Shape

    verts, faces = _r3d_skewed_vertices()
    body = Shape.from_arrays(verts, faces, density=2000.0, name="skewed")
    if kind == "turn":
        b = math.radians(R3D_TURN_DEG)
        c, s = math.cos(b), math.sin(b)
        rz = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
        image = Shape.from_arrays(verts @ rz.T, faces, density=2000.0, name="turned")
    else:
        image = Shape.from_arrays(verts * [1.0, -1.0, 1.0], faces[:, ::-1], density=2000.0,
                                  name="mirrored")
    pair = HorizontalPair.builtin("rinaldi")
    kw = dict(model="rigid3d", duration=10.0, dt_out=0.01, friction=0.8)
    worst = 0.0
    with warnings.catch_warnings():  # a step that misses tol: the same in both runs
        warnings.simplefilter("ignore", PlausibilityWarning)
        for scale, heading in R3D_INVARIANCE_SCENES:
            p = pair.scaled(scale)
            a = _r3d_outputs(_simulate(body, p, heading=heading, **kw))
            if kind == "turn":
                im = _r3d_outputs(_simulate(image, p, heading=heading - R3D_TURN_DEG
                                             + heading_error, **kw))
                im["overturn_azimuth"] -= R3D_TURN_DEG
                im["path"] = im["path"] @ rz[:2, :2]  # turned back (rz.T on each row)
            else:
                flipped = HorizontalPair(p.first, p.second.scaled(-1.0), azimuths=p.azimuths,
                                         vertical=p.vertical, name="mirrored")
                im = _r3d_outputs(_simulate(image, flipped, heading=heading_error - heading,
                                             **kw))
                im["overturn_azimuth"] = -im["overturn_azimuth"]
                im["residual_twist"] = -im["residual_twist"]
                im["path"] = im["path"] * [1.0, -1.0]
            worst = max(worst, _r3d_difference(a, im))
    return worst


CASES: tuple[Case, ...] = (
    Case(
        name="housner-free-period",
        source=HOUSNER_1963,
        what="period of free rocking of the linearised block released from theta0 = alpha/2 "
             "(mu = 1)",
        how="T = (4/p) arccosh(1/(1 - theta0/alpha)), the period of the linearised free "
            "motion (Housner 1963): theta = alpha - (alpha - theta0) cosh(p t) reaches 0 "
            "at a quarter period. " + UNREAD,
        reference=lambda: 4.0 / FREE["p"] * math.acosh(1.0 / (1.0 - FREE["frac"])),
        compute=_free_period, unit="s", tolerance=1e-7, group="classical"),
    Case(
        name="housner-eq1-acceleration", reference_kind="equation",
        source=HOUSNER_1963,
        what="angular acceleration of a rectangular block (width 0.4 m, height 1.6 m) "
             "released from rest at theta = alpha/2 (nonlinear model)",
        how="Eq (1) of Housner (1963) as printed on its page 404 (stored copy of the "
            "paper: https://scribd.com/doc/263600760), I0 d2theta/dt2 = -WR sin(alpha - "
            "theta), with W = m g, R = sqrt(b^2 + h^2), alpha = atan(b/h) and I0 = (4/3) "
            "(W/g) R^2 (the uniform rectangle's inertia about its corner, parallel-axis "
            "theorem; derived here). This block's alpha (14.0 degrees) is below the 'about "
            "20 degrees' under which Housner linearises (same page); the comparison is "
            "with the nonlinear equation. Computed: twice the t^2 coefficient of a "
            "polynomial fitted to rocking.simulate's theta(t) over the first 0.03 s.",
        reference=_eq1_acceleration_ref, compute=_eq1_acceleration, unit="rad/s^2",
        tolerance=1e-6, group="classical"),
    Case(
        name="housner-restitution", reference_kind="equation",
        source=HOUSNER_1963,
        what="ratio of angular velocities after and before an impact of a rectangular "
             "block (width 0.4 m, height 1.6 m), from its free-rocking amplitudes",
        how="Eq 4 of Pena et al. (2007) as printed there (Housner's 1963 result; Housner's "
            "own page could not be read): "
            "mu = 1 - (3/2) sin^2(alpha), Housner's coefficient of restitution of a "
            "rectangular block from the conservation of angular momentum about the new "
            "corner (Housner 1963; Eq 4 of Pena et al. 2007). Computed: the amplitudes "
            "theta0 and r1 before and after the first impact of the nonlinear model give "
            "the velocity ratio sqrt((cos(alpha - r1) - cos alpha)/(cos(alpha - theta0) - "
            "cos alpha)) (Eq 12 of Pena et al. 2007 with n = 1: energy is conserved "
            "between impacts).",
        reference=lambda: 1.0 - 1.5 * math.sin(math.atan(RECT_BLOCK["width"]
                                                         / RECT_BLOCK["height"])) ** 2,
        compute=lambda: _velocity_ratio(_rect_block()), tolerance=1e-5, group="classical"),
    Case(
        name="housner-uplift", reference_kind="equation",
        source=HOUSNER_1963,
        what="least constant ground acceleration a/(g tan alpha) that uplifts the block "
             "(nonlinear model)",
        how="Eq 1 of Pena et al. (2007) as printed there, at theta = 0 (Housner's 1963 "
            "statement; Housner's own Eq 1, on page 404, has no ground acceleration). "
            "At rest the block uplifts when the overturning moment of the inertial force, "
            "m a h, exceeds the restoring moment of gravity, m g b: a = g b/h = g tan "
            "alpha (Housner 1963; Eq 1 of Pena et al. 2007 at theta = 0), so the ratio is "
            "1. Computed by bisection on the uplift of rocking.simulate to 1e-9.",
        reference=lambda: 1.0, compute=_uplift_threshold, tolerance=1e-8,
        group="classical"),
    _rectangular_case(1.0),
    _rectangular_case(0.25),
    Case(
        name="housner-rectangular-pulse-response",
        source=HOUSNER_1963,
        what="largest theta/alpha of the linearised block after a rectangular pulse of "
             "length 1/p at 90 % of its overturning amplitude",
        how="During the pulse theta/alpha = (A - 1)(cosh(p t) - 1); afterwards the free "
            "linearised motion conserves (theta - alpha)^2 - (theta'/p)^2, so the largest "
            "angle is r/alpha = 1 - sqrt((1 - theta1/alpha)^2 - (theta1'/(p alpha))^2) "
            "(derived here, as in Housner 1963's treatment of the rectangular pulse). "
            + UNREAD,
        reference=_rect_pulse_response_ref, compute=_rect_pulse_response,
        tolerance=1e-6, group="classical"),
    Case(
        name="makris-roussos-half-sine",
        source=MAKRIS_ROUSSOS_2000,
        what="least a_p/(g alpha) of a half-sine pulse (omega_p/p = 4) that overturns the "
             "linearised block",
        how="Root of sqrt(A^2 - 1) + A exp(-(pi - asin(1/A)) p/omega_p) = omega_p/p, the "
            "overturning condition of the linearised block under the half-sine pulse "
            "(derived here in the framework of Makris and Roussos 2000, who give the "
            "minimum overturning acceleration of the linearised block under pulses in "
            "closed form; module docstring). " + UNREAD,
        reference=lambda: half_sine_mode2(4.0),
        compute=lambda: _pulse_threshold("half_sine", 4.0, mode2=False),
        tolerance=1e-5, group="pulses"),
    Case(
        name="makris-roussos-half-sine-long",
        source=MAKRIS_ROUSSOS_2000,
        what="the same threshold for a long half-sine pulse (omega_p/p = 1)",
        how="Root of the same equation at omega_p/p = 1 (module docstring). " + UNREAD,
        reference=lambda: half_sine_mode2(1.0),
        compute=lambda: _pulse_threshold("half_sine", 1.0, mode2=False),
        tolerance=1e-5, group="pulses"),
    Case(
        name="makris-roussos-one-sine",
        source=MAKRIS_ROUSSOS_2000,
        what="least a_p/(g alpha) of a long one-sine pulse (omega_p/p = 2) that overturns "
             "the linearised block without an impact",
        how="Root of sqrt(A^2 - 1) - A exp(-(2 pi - asin(1/A)) p/omega_p) = omega_p/p, the "
            "no-impact overturning condition of the linearised block under a one-sine "
            "pulse (derived here, module docstring). " + UNREAD,
        reference=lambda: one_sine_mode2(2.0),
        compute=lambda: _pulse_threshold("one_sine", 2.0, bracket=(1.5, 10.0)),
        tolerance=1e-5, group="pulses"),
    Case(
        name="zhang-makris-one-sine",
        source=ZHANG_MAKRIS_2001,
        what="least a_p/(g alpha) of a one-sine pulse (omega_p/p = 4) that overturns the "
             "linearised block without an impact (mode 2)",
        how="Root of sqrt(A^2 - 1) - A exp(-(2 pi - asin(1/A)) p/omega_p) = omega_p/p, "
            "the closed form of the minimum acceleration of a one-sine pulse that "
            "overturns the linearised block without impact (derived here, module "
            "docstring). Issue 22 names Zhang and Makris's Eq 47 for this threshold; what "
            "Eq 47 states could not be read in any reachable source (module docstring), "
            "so it is not claimed to be this equation. " + UNREAD,
        reference=lambda: one_sine_mode2(4.0),
        compute=lambda: _pulse_threshold("one_sine", 4.0, bracket=(2.0, 20.0)),
        tolerance=1e-5, group="pulses"),
    Case(
        name="zhang-makris-one-sine-short",
        source=ZHANG_MAKRIS_2001,
        what="the same mode-2 threshold for a short one-sine pulse (omega_p/p = 8)",
        how="Root of the same equation at omega_p/p = 8: for short pulses A grows like "
            "(omega_p/p)^2/(2 pi), a one-sine pulse acting through its net displacement "
            "(module docstring). " + UNREAD,
        reference=lambda: one_sine_mode2(8.0),
        compute=lambda: _pulse_threshold("one_sine", 8.0, bracket=(5.0, 60.0)),
        tolerance=1e-5, group="pulses"),
    Case(
        name="zhang-makris-one-sine-mode1-below-mode2",
        source=ZHANG_MAKRIS_2001,
        what="an a_p/(g alpha) of a one-sine pulse (omega_p/p = 4) where the overturning "
             "of the linearised block begins (found by bisection from 1 up), over the "
             "mode-2 value: below 1 means overturning after an impact (mode 1)",
        how="Zhang and Makris (2001) find that under a one-sine pulse the block can "
            "overturn after one impact (mode 1) at amplitudes below the no-impact (mode "
            "2) minimum. A bound, not a value: the ratio lies in [0, 1). " + UNREAD,
        reference=lambda: 1.0,
        compute=lambda: (_pulse_threshold("one_sine", 4.0, mode2=False, bracket=(1.0001, 2.0))
                         / one_sine_mode2(4.0)),
        tolerance=1.0, tolerance_kind="below", group="pulses"),
    Case(
        name="makris-konstantinidis-one-cosine",
        source=MAKRIS_KONSTANTINIDIS_2003,
        what="least a_p/(g alpha) of a one-cosine pulse (omega_p/p = 2) that overturns the "
             "linearised block without an impact",
        how="A = (1 + (omega_p/p)^2)/(1 - exp(-2 pi p/omega_p)): the block uplifts at t = 0 "
            "and overturns without impact iff theta - alpha + theta'/p >= 0 at the end of "
            "the pulse (derived here, module docstring). " + UNREAD,
        reference=lambda: one_cosine_mode2(2.0),
        compute=lambda: _pulse_threshold("one_cosine", 2.0, bracket=(2.0, 20.0)),
        tolerance=1e-5, group="pulses"),
    Case(
        name="makris-konstantinidis-similarity",
        source=MAKRIS_KONSTANTINIDIS_2003,
        what="largest difference of theta/alpha at equal p t between two blocks of the same "
             "alpha and mu, p = 1.5 and 6 1/s, under one-cosine pulses of equal omega_p/p "
             "(3) and a_p/(g tan alpha) (1.5)",
        how="Self-similarity of the rocking response (Makris and Konstantinidis 2003; "
            "dimensional analysis): theta/alpha as a function of p t depends only on "
            "omega_p/p, a_p/(g tan alpha), alpha and mu, so the difference is zero "
            "(exactly; the tolerance is the integration's). " + UNREAD,
        reference=lambda: 0.0, compute=_similarity_difference, tolerance=1e-8,
        tolerance_kind="abs", group="similarity"),
    Case(
        name="dimitrakopoulos-dejong-similarity",
        source=DIMITRAKOPOULOS_DEJONG_2012,
        what="ratio of the least overturning a_p/(g tan alpha) of a one-sine pulse "
             "(omega_p/p = 3) for two blocks of the same alpha and mu, p = 1.5 and 6 1/s",
        how="The similarity law of Dimitrakopoulos and DeJong (2012): the overturning "
            "spectrum drawn on omega_p/p and a_p/(g tan alpha) is the same for blocks of "
            "any size with the same alpha and mu, so the ratio is 1. Computed with "
            "rocking.analysis.overturning.overturning_spectrum (nonlinear model), whose "
            "bisection resolves a threshold to 1e-4: the tolerance. " + UNREAD,
        reference=lambda: 1.0,
        compute=lambda: _dd_threshold(SIMILAR["p"][0]) / _dd_threshold(SIMILAR["p"][1]),
        tolerance=1e-4, group="similarity"),
    Case(
        name="makris-konstantinidis-fig4-printed", reference_kind="printed",
        source=MAKRIS_KONSTANTINIDIS_2003,
        what="least amplitude (g) of a one-cosine pulse of Tp = 2 s that overturns the "
             "block p = 2 rad/s, alpha = 15 deg with Housner's restitution, near the "
             "printed 0.315/0.316 g pair",
        how="Printed in Fig 4 of Makris and Konstantinidis (2003): 0.315 g is on the verge "
            "(7 impacts in the 8 s after the pulse), 0.316 g overturns; " + READ_IN_NOTES
            + ". The reference is the middle of the printed pair, the tolerance half its "
            "width. Their r = 0.81 is the energy ratio, (1 - 1.5 sin^2 alpha)^2: mu = "
            "0.8995. Computed: the nonlinear classical model, bisection in [0.31, 0.32] g "
            "(the overturning region is not connected: 0.33 g survives, 0.4 g overturns).",
        reference=lambda: 0.3155,
        compute=lambda: _printed_threshold(MK_ALPHA, 2.0, 1.0 - 1.5 * math.sin(MK_ALPHA) ** 2,
                                           "one_cosine", 2.0, 0.31 * G, 0.32 * G) / G,
        unit="g", tolerance=5e-4, tolerance_kind="abs", group="printed"),
    Case(
        name="makris-roussos-fig2-printed", reference_kind="printed",
        source=MAKRIS_ROUSSOS_2000,
        what="least amplitude (m/s^2) of a half-sine pulse of 0.5 s that overturns the "
             "linearised block b = 0.2 m, h = 0.6 m (half-dimensions), g = 9.81",
        how="Printed in the caption of Fig 2 of Makris and Roussos (2000): 5.430 m/s^2 "
            "survives, 5.440 m/s^2 overturns (linear formulation, g = 9.81 m/s^2); "
            + READ_IN_CAPTION + ". Reference: the middle of the pair, tolerance half its "
            "width. Computed: the linearised classical model with alpha = atan(1/3), "
            "p = sqrt(3 g / 4R) with their g, bisection.",
        reference=lambda: 5.435,
        compute=lambda: _printed_threshold(MR_ALPHA, MR_P_FIG2,
                                           1.0 - 1.5 * math.sin(MR_ALPHA) ** 2, "half_sine",
                                           0.5, 5.3, 5.6, linear=True, g_paper=9.81),
        unit="m/s^2", tolerance=5e-3, tolerance_kind="abs", group="printed",
        known_difference="our threshold, 5.4405 m/s^2, lies 0.0005 m/s^2 (0.009 %) above "
                         "the printed overturning 5.440: at 5.440 our block survives. The "
                         "printed pair is the paper's search step; the difference is of "
                         "the order of its integration's error.",
        known_tolerance=6e-3),
    Case(
        name="makris-roussos-fig9-printed", reference_kind="printed",
        source=MAKRIS_ROUSSOS_2000,
        what="least amplitude (m/s^2) of a one-sine pulse of 1 s that overturns the "
             "linearised block b = 0.5 m, h = 1.5 m (p = 2.157 rad/s) after one impact, "
             "Housner's restitution",
        how="Printed in the caption of Fig 9 of Makris and Roussos (2000): 4.426 m/s^2 "
            "survives, 4.429 m/s^2 overturns after one impact; " + READ_IN_CAPTION
            + ". Reference: the middle of the pair, tolerance half its width. Computed: "
            "the linearised classical model (the nonlinear one gives 4.598 m/s^2: the "
            "caption's numbers are the linear formulation's), bisection in [4.3, 4.6].",
        reference=lambda: 4.4275,
        compute=lambda: _printed_threshold(MR_ALPHA, 2.157,
                                           1.0 - 1.5 * math.sin(MR_ALPHA) ** 2, "one_sine",
                                           1.0, 4.3, 4.6, linear=True, g_paper=9.81),
        unit="m/s^2", tolerance=1.5e-3, tolerance_kind="abs", group="printed",
        known_difference="our threshold, 4.4298 m/s^2, lies 0.0008 m/s^2 (0.02 %) above "
                         "the printed overturning 4.429: at 4.429 our block survives. As "
                         "for Fig 2, of the order of the paper's integration error.",
        known_tolerance=3e-3),
    Case(
        name="rigid3d-impact-eq4",
        source=HOUSNER_1963,
        what="angular-velocity ratio across the first impact of specimen 2 as a 3-D box "
             "(rigid3d, restitution 0, sticking friction) against Eq 4",
        how="Eq 4 of Pena et al. (2007) (Housner's momentum balance about the new edge), "
            "1 - 1.5 sin^2 alpha with alpha = atan(0.17/1.0): the 3-D model is not given it; "
            "its plastic impact (Newton's law with restitution 0) must produce it. "
            "Tolerance: the scheme's first-order error at the impact at step 2.5e-5 s.",
        reference=lambda: 1.0 - 1.5 * math.sin(_r3d_alpha()) ** 2, compute=_r3d_impact_ratio,
        tolerance=5e-4, tolerance_kind="abs", group="three-d", reference_kind="equation"),
    Case(
        name="rigid3d-planar-limit-sine", reference_kind="cross-check",
        source=PENA_2007,
        what="max |theta| of specimen 2 under 2.5 s of the 5 Hz, 5 mm sine of Figure 7: the "
             "3-D box (rigid3d, step 5e-5 s) against the classical model",
        how="Cross-model check: a 3-D box shaken along a principal axis with sticking "
            "friction is Housner's block (the planar limit); the reference is the classical "
            "model with the geometric alpha and p and Eq 4's restitution. Tolerance 1 %: "
            "the 3-D scheme's error at this step (it shrinks with the step; the report's "
            "'In three dimensions' section).",
        reference=lambda: _r3d_sine("housner"), compute=lambda: _r3d_sine("rigid3d"),
        unit="rad", tolerance=1e-2, group="three-d", slow=True),
    Case(
        name="rigid3d-sliding", reference_kind="textbook",
        source="Coulomb's law of dry friction (any dynamics textbook)",
        what="relative acceleration (m/s^2) of a squat box (1.0 x 0.8 x 0.2 m) on a ground "
             "accelerating at 0.5 g along 30 deg, friction 0.3",
        how="(0.5 - 0.3) g: the friction force mu m g opposes the slip; the box does not "
            "rock (its uplift needs a > g b/h = 5 g).",
        reference=lambda: 0.2 * G, compute=_r3d_sliding, unit="m/s^2", tolerance=1e-9,
        group="three-d"),
    Case(
        name="rigid3d-uplift-any-heading", reference_kind="equation",
        source=HOUSNER_1963,
        what="ground acceleration (m/s^2) at which a slow ramp along 37 deg from its x axis "
             "lifts a 0.25 x 0.5 x 1.0 m box (rigid3d)",
        how="The static balance of a rigid body on its support (Housner's uplift criterion "
            "generalised to any heading): it uplifts when a = g t(psi)/h, t the distance "
            "from the centre of mass's vertical to the support's edge along the heading, "
            "the uplift_3d_plus column of rocking.shapes.directional_parameters (computed "
            "from the support polygon). Tolerance: the ramp's step (2e-3).",
        reference=_r3d_box_uplift_ref, compute=_r3d_box_uplift, unit="m/s^2",
        tolerance=2e-3, group="three-d"),
    Case(
        name="rigid3d-cylinder-restitution", reference_kind="equation",
        source=("Srinivasan, M. and Ruina, A. (2008). Rocking and rolling: a can that appears "
                "to rock might actually roll. Physical Review E 78, 066601"),
        what="angular-velocity ratio across the first impact of an exact cylinder (r = 0.2 m, "
             "H = 1.2 m) rocking in a plane on its rim (rigid3d, restitution 0)",
        how="Housner's momentum balance for the cylinder's section: 1 - 2 r^2/(5 r^2/4 + "
            "4 h^2/3), h the half-height (issue 30; derived here: the angular momentum about "
            "the new contact point is kept, with I_O = m (5 r^2/4 + 4 h^2/3)). Tolerance: "
            "the scheme's first-order error at the impact at step 5e-5 s.",
        reference=lambda: 1 - 2 * R3D_CYL[0] ** 2 / (5 * R3D_CYL[0] ** 2 / 4
                                                     + 4 * (0.5 * R3D_CYL[1]) ** 2 / 3),
        compute=_r3d_cylinder_ratio, tolerance=5e-4, tolerance_kind="abs", group="three-d"),
    Case(
        name="rigid3d-flight-angular-momentum", reference_kind="textbook",
        source="Euler's laws of motion: a free rigid body keeps its angular momentum (any "
               "dynamics textbook, e.g. Goldstein (1980), Classical Mechanics, Ch. 5)",
        what="largest relative change of the angular momentum of a spinning box thrown off "
             "the ground by a vertical pulse of -1.5 g, while it flies",
        how="Gravity acts at the centre of mass: no torque, so the angular momentum about "
            "the centre of mass is constant in flight; the scheme advances it exactly (the "
            "rotation of each half step is the exact one of the body's angular velocity), "
            "so the change is rounding.",
        reference=lambda: 0.0, compute=_r3d_flight_momentum, tolerance=1e-9,
        tolerance_kind="abs", group="three-d"),
    Case(
        name="rigid3d-invariance-turn", reference_kind="textbook",
        source="Landau, L. D. and Lifshitz, E. M. (1976). Mechanics, 3rd ed., Section 9 "
               "(the isotropy of space: the laws of motion do not depend on the frame's "
               "orientation). Pergamon.",
        what="largest difference between a skewed body (no symmetry) under the Rinaldi "
             "three-component set and the same body turned by 37 deg about the vertical "
             "with the pair's heading turned by 37 deg (relative, rad or its path's size)",
        how="Turning the body and the ground motion together changes nothing: the same "
            "tilt history, slides, twists, impacts and overturn time, the overturn "
            "azimuth and the centre of mass's path turned by 37 deg. Two runs of 10 s "
            "at heading 60 deg (scale 0.6: 39 impacts, no overturn; 0.8: it overturns); "
            "the value is the largest difference over both: each output relative to its "
            "size, the azimuth and the tilt history in rad, the path relative to its "
            "largest excursion. Only rounding differs between the two (the turned "
            "vertices): measured 3e-9. Tolerance 1e-6: the scenes are well conditioned "
            "(a change of 1e-15 to 1e-11 in the motion's scale moves them by at most "
            "3e-8). Not every "
            "run is: near a threshold a change of 1e-15 in the scale changes the number "
            "of impacts, and a turned run then differs as much.",
        reference=lambda: 0.0, compute=lambda: rigid3d_invariance("turn"), tolerance=1e-6,
        tolerance_kind="abs", group="three-d"),
    Case(
        name="rigid3d-invariance-mirror", reference_kind="textbook",
        source="Landau, L. D. and Lifshitz, E. M. (1976). Mechanics, 3rd ed. Pergamon "
               "(the laws of motion are unchanged by a reflection: the mirror image of a "
               "motion is a motion).",
        what="largest difference between the skewed body's response under the Rinaldi "
             "set and the mirrored response of its mirror image (the mesh mirrored in its "
             "x-z plane, the motion's y component negated)",
        how="The body mirrored in its x-z plane (y -> -y) under the mirrored ground "
            "motion (the body sees (a_x, -a_y, a_z): the pair's second component negated "
            "and the heading negated) moves as the mirror image: the same tilt history, "
            "slides, max twist, impacts and overturn time; the residual twist, the "
            "overturn azimuth and the path's y negated. The runs, measure and tolerance "
            "of rigid3d-invariance-turn; measured 5e-9.",
        reference=lambda: 0.0, compute=lambda: rigid3d_invariance("mirror"), tolerance=1e-6,
        tolerance_kind="abs", group="three-d"),
    _table2_case(
        1, "alpha", 0.242, known_tolerance=4e-3,
        known="Eq 2 on Table I's 2b = 0.25 m, 2h = 1.000 m gives atan(0.125/0.5) = 0.2450 "
              "rad; the printed 0.242 (with mu = 0.914, which is Eq 4 of 0.242: the two "
              "printed values agree with each other) would need 2b = 0.247 m. The paper "
              "does not say which width it used; the 5 mm 45-degree cuts of the base "
              "(rocking.specimen(1, 'geometric', shape='cut')) give 0.2355 rad, not 0.242 "
              "either."),
    _table2_case(2, "alpha", 0.168),
    _table2_case(2, "p", 3.81),
    _table2_case(2, "mu", 0.958),
    _table2_case(
        3, "mu", 0.978, known_tolerance=1e-3,
        known="Eq 4 of Table I's geometry gives 0.97871 and Eq 4 of the printed alpha "
              "0.119 gives 0.97886; both round to 0.979, one unit of the last digit above "
              "the printed 0.978. The paper does not say how it rounded."),
    _table2_case(
        4, "alpha", 0.310, known_tolerance=3e-2,
        known="specimen 4 has a 40 mm 45-degree cut at its base (Section 3.1) that Table I "
              "does not describe fully: Eq 2 on Table I's rectangle gives 0.3368 rad and "
              "the cut base as we model it (shape='cut') 0.1698 rad; the printed 0.310 "
              "follows from neither (it would need 2b = 0.146 m with 2h = 0.457 m)."),
    _table2_case(
        4, "p", 5.16, known_tolerance=0.4,
        known="Eq 3 on Table I's rectangle (R = 0.242 m) gives 5.51 1/s; the printed 5.16 "
              "would need R = 0.276 m. As for its alpha, the paper does not say how the "
              "40 mm cut of specimen 4 enters its theoretical values."),
    Case(
        name="pena-table3-specimen2-K", reference_kind="printed",
        source=PENA_2007,
        what="normal stiffness K of the DEM contact for specimen 2 (T parameters), Eq 17 "
             "against the printed Table III value",
        how="Quoted from Table III of Pena et al. (2007), column T: K = 3302 N/m (page not "
            "given in the project's copy). Computed: Eq 17, K = (M/2)(p^2 + 3 g/(4 R)), "
            "with M = 228 kg and 2b = 0.17 m, 2h = 1.000 m of Table I and p = 3.81 1/s of "
            "Table II, by rocking.models.dem.paper_parameters. Tolerance: what the "
            "printing's rounding of its inputs allows, M +- 0.5 kg (7.3 N/m), p +- 0.005 "
            "1/s (4.3 N/m) and 2b +- 0.005 m (1.4 N/m): 13 N/m.",
        reference=lambda: 3302.0, compute=lambda: _table3_K(2), unit="N/m",
        tolerance=13.0, tolerance_kind="abs", group="paper"),
    Case(
        name="pena-table3-specimen3-K", reference_kind="printed",
        source=PENA_2007,
        what="the same stiffness K for specimen 3 (T parameters)",
        how="Quoted from Table III of Pena et al. (2007), column T: K = 1174 N/m. Computed: "
            "Eq 17 with M = 120 kg, 2b = 0.12 m, 2h = 1.000 m (Table I) and p = 3.82 1/s "
            "(Table II). Tolerance as for specimen 2 (rounding of the inputs, 13 N/m).",
        reference=lambda: 1174.0, compute=lambda: _table3_K(3), unit="N/m",
        tolerance=13.0, tolerance_kind="abs", group="paper",
        known_difference="Eq 17 gives 1752 N/m, 49 % above the printed 1174 N/m, and Eq 14 "
                         "alone (M p^2 = 1751 N/m) does not give it either; no combination "
                         "of the paper's equations and tables found gives 1174 (Eq 17 "
                         "reproduces the printed K of specimens 1 and 2 to 1 %; "
                         "tests/test_dem.py). The paper does not say how it was obtained.",
        known_tolerance=600.0),
    Case(
        name="ccrr-vs-classical", reference_kind="cross-check",
        source=PENA_2007,
        what="amplitude after the third impact of free rocking from alpha/2 (alpha = 0.2, "
             "p = 2, mu = 0.9): the CCRR model (Eqs 5-10) against the classical model",
        how="Cross-model check: the CCRR model tends to the classical model as its contact "
            "length l vanishes (Pena et al. 2007, Section 2.2); the reference is the "
            "classical model's amplitude; the tolerance, 0.5 %, is the agreement at the "
            "default l (tests/test_ccrr.py).",
        reference=lambda: float(_free_amplitudes("housner", _ccrr_block())[3]),
        compute=lambda: float(_free_amplitudes("ccrr", _ccrr_block())[3]),
        unit="rad", tolerance=5e-3, group="cross-model"),
    Case(
        name="dem-vs-classical", reference_kind="cross-check",
        source=PENA_2007,
        what="amplitude after the second impact of free rocking of specimen 2 "
             "(experimental parameters) from alpha/2: the DEM against the classical model",
        how="Cross-model check: the discrete-element model with its damping calibrated to "
            "the block's restitution rocks like the classical model (Pena et al. 2007, "
            "Section 2.3); the reference is the classical model's amplitude; the "
            "tolerance, 3 %, is the agreement documented in tests/test_dem.py.",
        reference=lambda: float(_free_amplitudes("housner", _specimen2(), duration=2.0,
                                                 dt_out=5e-4)[2]),
        compute=lambda: float(_free_amplitudes("dem", _specimen2(), duration=2.0,
                                               dt_out=5e-4)[2]),
        unit="rad", tolerance=3e-2, group="cross-model", slow=True),
    Case(
        name="sdof-floor-transmissibility", reference_kind="textbook",
        source=CHOPRA,
        what="steady-state floor acceleration over ground acceleration of an SDOF building "
             "(T = 0.5 s, zeta = 5 %) under a sine at 1.5 times its frequency",
        how="|1 + r^2/(1 - r^2 + 2 i zeta r)| = sqrt((1 + (2 zeta r)^2)/((1 - r^2)^2 + "
            "(2 zeta r)^2)) (transmissibility, Chopra Section 3.6); computed: the "
            "amplitude of the last 10 cycles of rocking.buildings.FloorMotion by least "
            "squares (the sampled sine's sinc^2(f dt) bias is below the tolerance).",
        reference=_transmissibility_ref, compute=_transmissibility, tolerance=1e-3,
        group="buildings"),
    Case(
        name="cantilever-period-ratio", reference_kind="textbook",
        source=MIRANDA_TAGHAVI_2005,
        what="T1/T2 of the continuous building with alpha = 0 (a flexural cantilever)",
        how="alpha = 0 is the flexural limit of Miranda and Taghavi's shear-flexural "
            "beam: an Euler-Bernoulli cantilever, whose frequencies are proportional to "
            "x_j^2 with x_j the roots of cos x cosh x + 1 = 0 (the textbook frequency "
            "equation), solved here by brentq: T1/T2 = (x2/x1)^2 = 6.2669 (tests/"
            "test_buildings.py quotes 6.27 as the published ratio; not re-read here).",
        reference=lambda: (_cantilever_roots(2)[1] / _cantilever_roots(2)[0]) ** 2,
        compute=_cantilever_ratio, tolerance=1e-9, group="buildings"),
    Case(
        name="shear-building-frequencies", reference_kind="textbook",
        source=CHOPRA,
        what="omega2/omega1 of a uniform 5-storey shear building",
        how="omega_j = 2 sqrt(k/m) sin((2j - 1) pi/(2(2N + 1))) for equal storey "
            "masses and stiffnesses, the closed form of the shear building's tridiagonal "
            "eigenproblem (Chopra Sections 9.2 and 10.2 for the shear building; (S3) of "
            "rocking.buildings.building), so omega2/omega1 = sin(3 pi/22)/sin(pi/22).",
        reference=lambda: math.sin(3 * math.pi / 22) / math.sin(math.pi / 22),
        compute=_shear_ratio, tolerance=1e-10, group="buildings"),
    Case(
        name="isolated-no-uplift-sd", reference_kind="cross-check",
        source=VASSILIOU_MAKRIS_2012,
        what="largest isolator displacement of specimen 2 on a linear isolation "
             "(T_b = 2 s, zeta_b = 10 %) under Rinaldi 228 x 0.1, where it never uplifts",
        how="A block that never uplifts rides the isolated base as one linear oscillator "
            "(Vassiliou and Makris 2012), so the base's largest displacement is the "
            "elastic spectral displacement Sd(T_b, zeta_b) of the ground motion, computed "
            "by rocking.motions.response_spectrum (Nigam and Jennings' exact recurrence, "
            "Chopra Section 5.2). The tolerance covers the peak taken at output samples.",
        reference=lambda: _isolated_spectrum("sd"),
        compute=lambda: float(_isolated_run()[1].info["max_base_displacement"]),
        unit="m", tolerance=2e-3, group="isolation"),
    Case(
        name="isolated-no-uplift-sa", reference_kind="cross-check",
        source=VASSILIOU_MAKRIS_2012,
        what="largest absolute acceleration of the isolated base in the same run",
        how="The same linear oscillator: the base's largest absolute acceleration is the "
            "elastic spectral acceleration Sa(T_b, zeta_b) (absolute, not pseudo) of the "
            "ground motion, by rocking.motions.response_spectrum.",
        reference=lambda: _isolated_spectrum("sa"),
        compute=lambda: float(_isolated_run()[1].info["max_plate_acceleration"]),
        unit="m/s^2", tolerance=2e-3, group="isolation"),
    Case(
        name="shape-box-alpha", reference_kind="equation",
        source=PENA_2007,
        what="alpha of a 0.5 x 0.25 x 1.25 m box mesh shaken along its long side, from "
             "rocking.shapes",
        how="alpha = atan(b/h) (Eq 2 of Pena et al. 2007) with b = 0.25 m, h = 0.625 m the "
            "half-width and the height of the centre of mass of the rectangle it rocks in.",
        reference=lambda: _box_closed_form()[0],
        compute=lambda: float(_box_parameters()["alpha_plus"]), unit="rad",
        tolerance=1e-9, group="shapes"),
    Case(
        name="shape-box-p", reference_kind="equation",
        source=PENA_2007,
        what="frequency parameter p of the same box mesh, from rocking.shapes",
        how="p = sqrt(3 g/(4 R)), R = sqrt(b^2 + h^2) (Eq 3 of Pena et al. 2007; the "
            "prism's inertia about its edge is (4/3) m R^2).",
        reference=lambda: _box_closed_form()[1],
        compute=lambda: float(_box_parameters()["p_plus"]), unit="1/s",
        tolerance=1e-9, group="shapes"),
    Case(
        name="shape-box-restitution", reference_kind="equation",
        source=HOUSNER_1963,
        what="coefficient of restitution of the same box mesh, from rocking.shapes",
        how="Eq 4 of Pena et al. (2007) as printed there (Housner 1963): "
            "mu = 1 - (3/2) sin^2(alpha) (Housner 1963; Eq 4 of Pena et al. 2007), the "
            "restitution of a rectangular block from angular momentum about the new corner.",
        reference=lambda: _box_closed_form()[2],
        compute=lambda: float(_box_parameters()["mu_plus"]),
        tolerance=1e-9, group="shapes"),
)
"""Every verification case, in the order of the table."""

IMPACT_CASES = ("housner-restitution", "ccrr-vs-classical", "dem-vs-classical")
"""The cases whose outcome depends on the classical model's impacts (its restitution)."""


def clear_caches() -> None:
    """Forget the runs shared by several cases (each :func:`rocking.verification.run_cases`
    starts afresh)."""
    _isolated_run.cache_clear()
    _box_parameters.cache_clear()


def case_names() -> list[str]:
    """The names of the cases, in catalog order (``rocking verify --list``).

    Examples
    --------
    >>> from rocking.verification import case_names
    >>> case_names()[:2]
    ['housner-free-period', 'housner-eq1-acceleration']
    """
    return [c.name for c in CASES]


__all__ = ["CASES", "IMPACT_CASES", "case_names", "clear_caches", "half_sine_mode2",
           "one_cosine_mode2", "one_sine_mode2"]
