"""Monte Carlo of one block under given motions with uncertain parameters.

The paper's random tests were not repeatable (Fig. 8: earthquake 20 at load factor 1.1
overturned the block once and not in its repeat). :func:`monte_carlo` turns such a pair of
outcomes into a probability: it draws the uncertain parameters of the block (``alpha``,
``p``, ``mu``), its initial tilt ``theta0`` and a perturbation of the table motion (an
amplitude factor and additive noise, as a shaking table adds), runs every sample through
the compiled batch kernels, and returns P(overturn) with a Wilson confidence interval.

Sample ``i`` draws from its own generator ``numpy.random.default_rng(SeedSequence(seed,
spawn_key=(STREAM, i)))`` (the tag ``STREAM`` keeps these draws independent of
:func:`rocking.motions.stochastic_records` with the same seed), and each batch row
depends on its own inputs only, so the result does not depend on ``chunk_size`` (or on
the executor of a campaign).

Truncation (:mod:`rocking.analysis.distributions`): each parameter is drawn from its
distribution truncated to its range (:data:`PARAMETERS`), by rejection. The initial tilt
is truncated to ``|theta0| < alpha`` of its own sample (a block tilted beyond alpha is not
a block at rest: it simply falls): a draw at or beyond is redrawn, the sample is flagged
(column ``theta0_truncated``) and counted (:attr:`MonteCarloResult.n_theta0_truncated`).
A sample whose draws all fell inside at once consumes its generator exactly as before the
truncation existed, so its numbers do not change. A distribution with more than 1 %
(:data:`~rocking.analysis.distributions.MAX_OUTSIDE`) of its mass outside its range (for
``theta0``: beyond +-alpha, averaged over alpha's distribution when alpha is uncertain) is
refused with a :class:`~rocking.ParameterError` naming it.

Asymmetric blocks (:attr:`rocking.Block.symmetric` False: :meth:`rocking.Block.from_geometry`,
``from_shape``, ``from_mesh``) keep their two sides, by the *factor rule*
(:func:`sample_block`, used by Monte Carlo and campaigns alike): the nominal ``alpha``,
``p``, ``mu`` of such a block are its one-number summaries, those of its weaker side
(:attr:`rocking.Block.alpha`, ...), and a drawn value ``x`` of parameter ``k`` multiplies
each side's own value by ``x / k_nominal``: ``k_plus = k_plus_nominal x / k_nominal``, and
the same for side ``-``. The weaker side gets ``x`` itself (the table's column), the block
keeps the ratio of its sides, its outline, mass and radii, and a vanishing spread gives the
nominal block. The range of ``alpha`` and ``mu`` (:func:`bounds`) is then the one that
keeps *every* side in its physical range (e.g. ``mu`` below ``mu_nominal / max(mu_plus,
mu_minus)``, so that neither side's restitution exceeds 1). A symmetric block's sample is
:meth:`rocking.Block.from_params` of the drawn values, as it always was. A
:class:`~rocking.Stack` has no rule for its blocks' sides: an uncertain ``alpha``, ``p`` or
``mu`` of a stack is refused.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from .._validate import in_range
from ..blocks import Block, Stack
from ..errors import ParameterError
from ..models import require_planar, simulate_many
from ..motions import Motion, Record, sample
from ..plot import figure, style_axes
from ..results import jsonable
from .distributions import MAX_OUTSIDE, check_mass, draw, draw_counted, frozen, mass_beyond

HALF_PI = 0.5 * math.pi
STREAM = 1
"""Tag of the Monte Carlo random streams (see the module docstring)."""
PARAMETERS = {  # name: (nominal from the block or the motion, physical range)
    "alpha": (lambda b: b.alpha, (0.0, HALF_PI)),
    "p": (lambda b: b.p, (0.0, math.inf)),
    "mu": (lambda b: b.mu, (0.0, 1.0 + 1e-12)),
    "theta0": (lambda b: 0.0, (-HALF_PI, HALF_PI)),
    "amplitude": (lambda b: 1.0, (0.0, math.inf)),
    "noise": (lambda b: 0.0, (-1e-300, math.inf)),
}
"""The uncertain parameters: ``alpha`` (rad), ``p`` (1/s), ``mu``, ``theta0`` (rad),
``amplitude`` (a factor on the motion) and ``noise`` (standard deviation of white noise
added to the motion's samples, m/s^2)."""
RANGES = {"alpha": "(0, pi/2) rad", "p": "(0, inf) 1/s", "mu": "(0, 1]",
          "theta0": "(-alpha, alpha)", "amplitude": "(0, inf)", "noise": "[0, inf) m/s^2"}
"""The ranges of :data:`PARAMETERS` as written in messages."""
SCALED = ("alpha", "p", "mu")
"""The parameters of the block itself: drawn, they make the sample's block
(:func:`sample_block`; an asymmetric block's sides by the factor rule of the module
docstring)."""


def bounds(block, name: str) -> tuple[float, float, str]:
    """``(lo, hi, shown)``: the open range that a draw of parameter ``name`` is truncated to
    for ``block``, and that range as written in messages. The range of :data:`PARAMETERS`
    (:data:`RANGES`), except for the ``alpha`` and ``mu`` of an asymmetric block: the
    factor rule (module docstring) multiplies each side by ``drawn / nominal``, so the
    drawn value must stay below ``pi/2`` (``1`` for ``mu``) times ``nominal / max(side
    values)`` for every side to stay in its range.

    Examples
    --------
    A body whose + side is the weaker one (``alpha_plus = atan(0.2) < alpha_minus =
    atan(0.4)``): a drawn alpha may reach ``pi/2 alpha_plus / alpha_minus`` only.

    >>> import math
    >>> from rocking import Block
    >>> from rocking.analysis.montecarlo import bounds
    >>> body = Block.from_geometry(0.5, 0.1, 0.2, 0.3)
    >>> lo, hi, shown = bounds(body, "alpha")
    >>> lo, round(hi, 6) == round(math.pi / 2 * math.atan(0.2) / math.atan(0.4), 6)
    (0.0, True)
    >>> bounds(Block.rectangular(0.4, 1.2), "alpha")[1] == math.pi / 2  # symmetric: as ever
    True
    """
    lo, hi = PARAMETERS[name][1]
    if name not in ("alpha", "mu") or not isinstance(block, Block) or block.sides is None:
        return lo, hi, RANGES[name]
    nom = PARAMETERS[name][0](block)
    plus, minus = getattr(block, f"{name}_plus"), getattr(block, f"{name}_minus")
    top = max(plus, minus)
    if not top > nom:
        return lo, hi, RANGES[name]
    side = f"{name}_{'plus' if plus >= minus else 'minus'}"
    cap, unit, cap_s = (HALF_PI, " rad", "pi/2") if name == "alpha" else (1.0, "", "1")
    hi = cap * (nom / top)
    return lo, hi, (f"(0, {hi:.6g}){unit} (an asymmetric block: {side} = {top:.6g}{unit} "
                    f"is scaled by drawn / {nom:.6g}, and must stay below {cap_s})")


def sample_block(block, values: dict, drawn) -> Block:
    """The block of one sample, in Monte Carlo and campaigns alike: ``block`` itself when
    none of :data:`SCALED` (``alpha``, ``p``, ``mu``) is in ``drawn`` (the names drawn,
    e.g. the keys of :func:`distributions`), else the block with the sample's ``values``
    (``{name: value}``, as :func:`draw_parameters` gives them).

    A symmetric block's sample is :meth:`rocking.Block.from_params` of ``values["alpha"]``,
    ``values["p"]``, ``values["mu"]`` (its name kept). An asymmetric block keeps its two
    sides by the factor rule (module docstring): each drawn parameter ``k`` multiplies both
    sides' ``k`` by ``values[k] / k_nominal`` (the weaker side gets ``values[k]`` itself);
    the block's outline, mass, inertia and radii are kept
    (:meth:`rocking.Block.with_params`). A :class:`~rocking.Stack` has no such rule: an
    uncertain ``alpha``, ``p`` or ``mu`` of a stack is a :class:`~rocking.ParameterError`.

    Examples
    --------
    An asymmetric body whose drawn alpha is 10 % above its nominal (weaker) one: both
    sides are 10 % above theirs.

    >>> from rocking import Block
    >>> from rocking.analysis.montecarlo import sample_block
    >>> body = Block.from_geometry(0.5, 0.1, 0.2, 0.3)
    >>> values = {"alpha": 1.1 * body.alpha, "p": body.p, "mu": body.mu}
    >>> drawn = sample_block(body, values, ["alpha"])
    >>> drawn.alpha == values["alpha"], round(drawn.alpha_minus / body.alpha_minus, 12)
    (True, 1.1)
    >>> (drawn.p_plus, drawn.mu_minus) == (body.p_plus, body.mu_minus)
    True
    """
    keys = [k for k in SCALED if k in drawn]
    if not keys:
        return block
    if isinstance(block, Stack):
        raise ParameterError(
            f"uncertain {', '.join(keys)}: no rule scales the blocks of a stack "
            f"({block.name or 'the stack'}); a stack's alpha, p and mu cannot be uncertain")
    if not isinstance(block, Block):
        raise ParameterError(f"block must be a rocking.Block, got {type(block).__name__}")
    if block.sides is None:
        return Block.from_params(values["alpha"], values["p"], values["mu"], name=block.name)
    changes = {}
    for k in keys:
        nom = PARAMETERS[k][0](block)
        for s in ("plus", "minus"):
            # drawn x (side / nominal): exactly the drawn value on the weaker side
            changes[f"{k}_{s}"] = values[k] * (getattr(block, f"{k}_{s}") / nom)
    return block.with_params(**changes)


def distributions(block: Block, uncertain: dict, where=None, of: str = "") -> dict:
    """The checked frozen distributions of ``uncertain`` for ``block``: ``{name: dist}``.

    ``where(name)`` names a parameter in messages (default ``uncertain['name']``; a
    campaign spec gives ``uncertain.name``), ``of`` the block (e.g. `` of blocks[1]``).
    Refused (:class:`~rocking.ParameterError`): an unknown name, a malformed
    distribution, and a distribution with more than
    :data:`~rocking.analysis.distributions.MAX_OUTSIDE` of its mass outside the
    parameter's range (for ``theta0``: at or beyond +-alpha, the nominal alpha of
    ``block`` or, when alpha is uncertain, averaged over its distribution)."""
    unknown = set(uncertain) - set(PARAMETERS)
    if unknown:
        raise ParameterError(f"uncertain: unknown parameter(s) "
                             f"{', '.join(sorted(map(str, unknown)))}; "
                             f"allowed: {', '.join(PARAMETERS)}")
    key = where or (lambda k: f"uncertain[{k!r}]")
    dists = {k: frozen(k, uncertain[k], PARAMETERS[k][0](block), where=key(k))
             for k in PARAMETERS if k in uncertain}
    for k, d in dists.items():
        if k != "theta0":
            check_mass(key(k), d, *bounds(block, k))
    if "theta0" in dists:
        a = dists.get("alpha", block.alpha)
        m = mass_beyond(dists["theta0"], a, bounds(block, "alpha")[:2])
        if m > MAX_OUTSIDE:
            alpha = (f"alpha{of} ~ its distribution around {block.alpha:.4g} rad"
                     if "alpha" in dists else f"alpha{of} = {block.alpha:.4g} rad")
            raise ParameterError(
                f"{key('theta0')}: {100 * m:.3g}% of the distribution lies at or beyond "
                f"+-alpha ({alpha}); at most {100 * MAX_OUTSIDE:g}% may (draws there are "
                "redrawn: theta0 is truncated to |theta0| < alpha)")
    return dists


def draw_parameters(block: Block, dists: dict, rng) -> tuple[dict, bool]:
    """One sample: ``({name: value}, theta0_truncated)``, every parameter of
    :data:`PARAMETERS` in its order, drawn from ``dists`` (:func:`distributions`) truncated
    to its range (:func:`bounds`), or nominal; ``theta0`` inside ``(-alpha, alpha)`` of
    this sample (the weaker side's alpha for an asymmetric block).
    ``theta0_truncated`` says that a ``theta0`` draw fell at or beyond +-alpha and was
    redrawn."""
    v, redrawn = {}, 0
    for k, (nominal, _) in PARAMETERS.items():
        lo, hi, _ = bounds(block, k)
        if k not in dists:
            v[k] = nominal(block)
        elif k == "theta0":
            v[k], redrawn = draw_counted(dists[k], rng, max(lo, -v["alpha"]),
                                         min(hi, v["alpha"]), name=k)
        else:
            v[k] = draw(dists[k], rng, lo, hi, name=k)
    return v, redrawn > 0


def wilson_interval(k: int, n: int, level: float = 0.95) -> tuple[float, float]:
    """Wilson score interval of a binomial proportion ``k / n`` (statsmodels).

    Examples
    --------
    With no success in ``n`` trials the upper bound is ``z^2 / (n + z^2)`` (z = 1.96):

    >>> from rocking.analysis import wilson_interval
    >>> lo, hi = wilson_interval(0, 20)
    >>> lo, round(hi, 4), round(1.959964**2 / (20 + 1.959964**2), 4)
    (0.0, 0.1611, 0.1611)
    >>> [round(v, 3) for v in wilson_interval(10, 20)]  # symmetric about 1/2
    [0.299, 0.701]
    """
    if not (isinstance(n, int | np.integer) and n >= 1):
        raise ParameterError(f"n must be a whole number >= 1, got {n!r}")
    if not (isinstance(k, int | np.integer) and 0 <= k <= n):
        raise ParameterError(f"k must be a whole number in [0, n = {n}], got {k!r}")
    level = in_range("level", level, 0.0, 1.0, shown="(0, 1)")
    from statsmodels.stats.proportion import proportion_confint

    lo, hi = proportion_confint(int(k), int(n), alpha=1.0 - level, method="wilson")
    return float(lo), float(hi)


@dataclass
class MonteCarloResult:
    """Samples and outcomes of :func:`monte_carlo`.

    Examples
    --------
    A pulse of 12 times ``g tan alpha`` overturns every sample; the Wilson interval of
    20 out of 20 starts at ``n / (n + z^2)``:

    >>> import rocking
    >>> from rocking.analysis import monte_carlo
    >>> from rocking.motions import OneSine
    >>> res = monte_carlo(rocking.specimen(2), OneSine(20.0, length=0.5),
    ...                   {"theta0": {"dist": "uniform", "low": 0.0, "high": 0.01}}, n=20,
    ...                   duration=3.0)
    >>> res.n, res.n_overturned, res.p_overturn
    (20, 20, 1.0)
    >>> round(res.ci[0], 4), round(20 / (20 + 1.959964**2), 4)
    (0.8389, 0.8389)
    """

    samples: pd.DataFrame
    """One row per sample: the drawn parameters, ``theta0_truncated`` (its first ``theta0``
    draw lay at or beyond +-alpha and was redrawn), ``motion`` (index into ``motions``),
    ``max_abs_theta`` (rad), ``max_abs_theta_over_alpha``, ``overturned``, ``n_impacts``,
    ``settled`` (at rest or overturned when the run ended; an unsettled sample counts as
    not overturned)."""
    level: float = 0.95
    seed: int = 0
    info: dict = field(default_factory=dict)

    @property
    def n(self) -> int:
        return len(self.samples)

    @property
    def n_overturned(self) -> int:
        return int(self.samples["overturned"].sum())

    @property
    def n_theta0_truncated(self) -> int:
        """Samples whose initial tilt was redrawn because a draw lay at or beyond +-alpha
        (the distribution of ``theta0`` truncated to ``|theta0| < alpha``)."""
        col = self.samples.get("theta0_truncated")
        return 0 if col is None else int(col.sum())

    @property
    def n_unsettled(self) -> int:
        """Samples still rocking when their run ended (counted as not overturned)."""
        col = self.samples.get("settled")
        return 0 if col is None else int((~col.astype(bool)).sum())

    @property
    def p_overturn(self) -> float:
        """The fraction of samples that overturned."""
        return self.n_overturned / self.n

    @property
    def ci(self) -> tuple[float, float]:
        """Wilson confidence interval of P(overturn) at :attr:`level`."""
        return wilson_interval(self.n_overturned, self.n, self.level)

    def quantiles(self, q=(0.05, 0.5, 0.95)) -> pd.Series:
        """Quantiles of max ``|theta|`` / alpha over the samples that did not overturn.

        Examples
        --------
        Free rocking from a random initial tilt: the largest angle is the initial one, so
        the quantiles are those of ``theta0 / alpha``.

        >>> import rocking
        >>> from rocking.analysis import monte_carlo
        >>> from rocking.motions import OneSine
        >>> block, still = rocking.specimen(2), OneSine(0.0, length=0.5)  # no ground motion
        >>> res = monte_carlo(block, still, {"theta0": {"dist": "uniform", "low": 0.0,
        ...                   "high": 0.5 * block.alpha}}, n=20, duration=1.0)
        >>> q = res.quantiles([0.05, 0.5, 0.95])
        >>> bool(np.allclose(q, (res.samples["theta0"] / block.alpha).quantile([0.05, 0.5, 0.95])))
        True
        >>> bool(q.max() < 0.5)  # theta0 < alpha / 2
        True
        """
        s = self.samples.loc[~self.samples["overturned"], "max_abs_theta_over_alpha"]
        return s.quantile(list(q))

    def summary(self) -> dict:
        """JSON-ready: the counts, P(overturn) and its Wilson interval, the quantiles of max
        ``|theta|`` / alpha (:meth:`quantiles`) and the run's ``info``.

        Examples
        --------
        >>> import rocking
        >>> from rocking.analysis import monte_carlo
        >>> from rocking.motions import OneSine
        >>> block, still = rocking.specimen(2), OneSine(0.0, length=0.5)  # no ground motion
        >>> res = monte_carlo(block, still, {"theta0": {"dist": "uniform", "low": 0.0,
        ...                   "high": 0.5 * block.alpha}}, n=20, duration=1.0)
        >>> s = res.summary()  # free rocking from theta0 < alpha / 2: none overturns
        >>> s["n"], s["n_overturned"], s["p_overturn"], round(s["ci_high"], 3)
        (20, 0, 0.0, 0.161)
        >>> s["max_abs_theta_over_alpha_median"] == float(res.quantiles().iloc[1])
        True
        """
        lo, hi = self.ci
        q = self.quantiles()
        return jsonable({"n": self.n, "n_overturned": self.n_overturned,
                         "p_overturn": self.p_overturn, "ci_low": lo, "ci_high": hi,
                         "level": self.level, "seed": self.seed,
                         "n_theta0_truncated": self.n_theta0_truncated,
                         "n_unsettled": self.n_unsettled,
                         "max_abs_theta_over_alpha_q05": q.iloc[0] if q.size else None,
                         "max_abs_theta_over_alpha_median": q.iloc[1] if q.size else None,
                         "max_abs_theta_over_alpha_q95": q.iloc[2] if q.size else None,
                         **self.info})

    def to_dict(self) -> dict:
        """Everything, JSON-ready: :meth:`summary` and the ``samples`` table (a list per
        column).

        Examples
        --------
        >>> import rocking
        >>> from rocking.analysis import monte_carlo
        >>> from rocking.motions import OneSine
        >>> block, still = rocking.specimen(2), OneSine(0.0, length=0.5)  # no ground motion
        >>> res = monte_carlo(block, still, {"theta0": {"dist": "uniform", "low": 0.0,
        ...                   "high": 0.5 * block.alpha}}, n=20, duration=1.0)
        >>> import json
        >>> d = json.loads(json.dumps(res.to_dict()))
        >>> len(d["samples"]["theta0"]), d["n"]
        (20, 20)
        >>> any(d["samples"]["overturned"])
        False
        """
        d = self.summary()
        d["samples"] = jsonable(self.samples.to_dict(orient="list"))
        return d

    def plot(self, ax=None):
        """Histogram of max ``|theta|`` / alpha of the surviving samples, with P(overturn).

        Examples
        --------
        >>> import rocking
        >>> from rocking.analysis import monte_carlo
        >>> from rocking.motions import OneSine
        >>> block, still = rocking.specimen(2), OneSine(0.0, length=0.5)  # no ground motion
        >>> res = monte_carlo(block, still, {"theta0": {"dist": "uniform", "low": 0.0,
        ...                   "high": 0.5 * block.alpha}}, n=20, duration=1.0)
        >>> ax = res.plot()
        >>> ax.get_title()  # P(overturn) and its Wilson interval
        'P(overturn) = 0.000 [0.000, 0.161] (95% Wilson), n = 20'
        >>> int(sum(p.get_height() for p in ax.patches))  # every surviving sample counted
        20
        >>> import matplotlib.pyplot as plt; plt.close("all")
        """

        if ax is None:
            _, ax = figure()
        s = self.samples.loc[~self.samples["overturned"], "max_abs_theta_over_alpha"]
        ax.hist(s, bins=min(40, max(5, s.size // 5)), color="#0072B2", alpha=0.8)
        lo, hi = self.ci
        ax.set_title(f"P(overturn) = {self.p_overturn:.3f} "
                     f"[{lo:.3f}, {hi:.3f}] ({100 * self.level:g}% Wilson), n = {self.n}")
        style_axes(ax, r"max $|\theta|/\alpha$ (samples that did not overturn)", "samples")
        return ax


def perturbed(motion: Motion, amplitude: float, noise: float, rng) -> Motion:
    """``motion`` scaled by ``amplitude`` plus white noise of standard deviation ``noise``
    (m/s^2) drawn from ``rng`` (a shaking table's perturbations)."""
    m = motion.scaled(amplitude) if amplitude != 1.0 else motion
    if noise == 0.0:
        return m
    rec = m if isinstance(m, Record) else sample(m, min(m.scan_step, 0.005))
    acc = rec.values + rng.normal(0.0, noise, rec.acc.size)
    return Record(acc, rec.dt, name=f"{rec.name} + noise")


def draw_samples(block: Block, motions, uncertain: dict, n: int, seed: int, start: int = 0):
    """Samples ``start .. start + n - 1``: ``(table, blocks, motions)`` (see the module;
    the table's columns as :attr:`MonteCarloResult.samples` before the results)."""
    dists = distributions(block, uncertain)
    rows, blocks, ms = [], [], []
    for i in range(start, start + n):
        rng = np.random.default_rng(np.random.SeedSequence(seed, spawn_key=(STREAM, i)))
        v, truncated = draw_parameters(block, dists, rng)
        j = i % len(motions)
        blocks.append(sample_block(block, v, dists))
        ms.append(perturbed(motions[j], v["amplitude"], v["noise"], rng))
        rows.append({"sample": i, "motion": j, **v, "theta0_truncated": truncated})
    return pd.DataFrame(rows), blocks, ms


def monte_carlo(block: Block, motions, uncertain: dict | None = None, n: int = 1000,
                seed: int = 0, model="housner", duration: float | None = None,
                chunk_size: int = 2000, level: float = 0.95, **options) -> MonteCarloResult:
    """Monte Carlo of ``block`` under ``motions`` with the ``uncertain`` parameters.

    Parameters
    ----------
    block : Block
        The nominal block (its ``alpha``, ``p``, ``mu`` are the nominal values). An
        asymmetric block keeps its two sides: a drawn ``alpha``, ``p`` or ``mu`` scales
        both sides by ``drawn / nominal`` (the factor rule, :func:`sample_block`; its
        nominal values are its weaker side's, the table's columns the weaker side's
        drawn ones).
    motions : Motion or sequence of Motion
        Sample ``i`` runs under ``motions[i % len(motions)]`` (one motion: every sample).
    uncertain : dict
        ``{name: distribution}`` for names in :data:`PARAMETERS` (``alpha``, ``p``, ``mu``,
        ``theta0``, ``amplitude``, ``noise``); distributions as in
        :mod:`rocking.analysis.distributions`, truncated to the parameter's range by
        redrawing (``theta0`` to ``|theta0| < alpha`` of its sample: the samples redrawn
        are flagged in ``theta0_truncated`` and counted in
        :attr:`MonteCarloResult.n_theta0_truncated`). A distribution with more than 1 % of
        its mass outside its range is refused (:class:`~rocking.ParameterError` naming
        it), before any run.
    n, seed : int
        Number of samples; the seed of every draw (see the module docstring).
    model, duration, **options
        As in :func:`rocking.simulate_many` (with no ``duration`` a run goes on after its
        motion until the block has settled, at most ``max_free_time`` longer; the samples
        still rocking at the end are flagged in ``settled``).
    chunk_size : int
        Samples per compiled batch (memory only: results do not depend on it).
    level : float
        Confidence level of the Wilson interval of P(overturn).

    Examples
    --------
    A one-sine pulse at half the uplift acceleration ``g tan alpha``: no sample rocks, so
    none overturns, whatever the scatter of alpha; 20 samples bound P(overturn) below 0.16:

    >>> import math
    >>> import rocking
    >>> from rocking.analysis import monte_carlo
    >>> from rocking.motions import OneSine
    >>> block = rocking.specimen(2)
    >>> pulse = OneSine(0.5 * rocking.G * math.tan(block.alpha), length=0.5)
    >>> res = monte_carlo(block, pulse, {"alpha": {"dist": "normal", "cov": 0.02}}, n=20,
    ...                   duration=2.0)
    >>> res.n_overturned, float(res.samples["max_abs_theta"].max()), round(res.ci[1], 3)
    (0, 0.0, 0.161)
    """
    if isinstance(motions, Motion):
        motions = [motions]
    motions = list(motions)
    if not motions or not all(isinstance(m, Motion) for m in motions):
        raise ParameterError("motions must be a Motion or a non-empty sequence of Motions")
    if not isinstance(n, int | np.integer) or isinstance(n, bool):
        raise ParameterError(f"n must be a whole number in [1, 1e9], got {n!r}")
    n = int(in_range("n", n, 1, 1e9, lo_open=False, hi_open=False, shown="[1, 1e9]"))
    chunk = int(in_range("chunk_size", chunk_size, 1, 1e9, lo_open=False, shown="[1, 1e9)"))
    level = in_range("level", level, 0.0, 1.0, shown="(0, 1)")
    if isinstance(seed, bool) or not isinstance(seed, int | np.integer) or seed < 0:
        raise ParameterError(f"seed must be a whole number >= 0, got {seed!r}")
    if uncertain is not None and not isinstance(uncertain, dict):
        raise ParameterError("uncertain must be a dict {parameter: distribution}, got "
                             f"{type(uncertain).__name__}")
    if not isinstance(block, Block):
        raise ParameterError(f"block must be a rocking.Block, got {type(block).__name__}")
    uncertain = dict(uncertain or {})
    distributions(block, uncertain)  # every distribution checked before any run
    require_planar(model, "a Monte Carlo study")
    parts = []
    for start in range(0, n, chunk):
        table, blocks, ms = draw_samples(block, motions, uncertain, min(chunk, n - start),
                                         int(seed), start)
        res = simulate_many(blocks, ms, model=model, duration=duration,
                            theta0=table["theta0"].to_numpy(), **options)
        table["max_abs_theta"] = res.max_abs_theta
        table["max_abs_theta_over_alpha"] = res.max_abs_theta / table["alpha"]
        table["overturned"] = res.overturned
        table["n_impacts"] = res.n_impacts
        table["settled"] = res.settled
        parts.append(table)
    samples = pd.concat(parts, ignore_index=True)
    return MonteCarloResult(samples, level=level, seed=int(seed),
                            info={"model": str(getattr(model, "name", model)),
                                  "uncertain": ", ".join(sorted(uncertain)) or "none"})
