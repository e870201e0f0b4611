"""Uncertain alpha, p, mu of an asymmetric block (a mesh block) keep its two sides, in
Monte Carlo and campaigns alike (the factor rule of rocking.analysis.montecarlo): a
vanishing spread gives the deterministic response, and a drawn value scales both sides
by drawn / nominal. Before, a drawn block was rebuilt symmetric from the weaker side: the
example statue rocked 28 times more under a Monte Carlo of mu ~ N(0.9, 1e-9) than
deterministically with mu = 0.9."""

from __future__ import annotations

import math

import numpy as np
import pytest

import rocking
from rocking import Block, ParameterError
from rocking.analysis import monte_carlo
from rocking.analysis.montecarlo import bounds, draw_samples, sample_block
from rocking.campaign import Campaign, parse_spec
from rocking.motions import Sine, load_builtin
from rocking.shapes import example_mesh_path

# the example statue along its weakest direction: asymmetric (alpha 0.243 / 0.296 rad)
STATUE = Block.from_mesh(example_mesh_path(), density=2600, direction="weakest", mu=0.9)
DERIVED = Block.from_mesh(example_mesh_path(), density=2600, direction="weakest")
QUAKE = load_builtin("Rinaldi228").scaled(0.4)
TINY = 1e-9  # relative spread: the response must be the nominal one


def _vanishing(name: str, block: Block) -> dict:
    nominal = getattr(block, name)
    return {name: {"dist": "normal", "mean": nominal, "std": TINY * nominal}}


def test_the_statue_is_asymmetric():
    assert not STATUE.symmetric
    assert STATUE.alpha_plus != STATUE.alpha_minus and STATUE.p_plus != STATUE.p_minus
    assert STATUE.mu_plus == STATUE.mu_minus == 0.9


@pytest.mark.parametrize("name", ["alpha", "p", "mu"])
def test_monte_carlo_with_a_vanishing_spread_is_the_deterministic_run(name):
    det = rocking.simulate(STATUE, QUAKE).max_abs_theta
    assert 0.0 < det < 0.5 * STATUE.alpha  # it rocks, far from overturning
    mc = monte_carlo(STATUE, QUAKE, _vanishing(name, STATUE), n=3, seed=1)
    theta = mc.samples["max_abs_theta"].to_numpy()
    assert not mc.samples["overturned"].any()
    np.testing.assert_allclose(theta, det, rtol=1e-4)


def test_monte_carlo_samples_keep_both_sides_and_the_outline():
    unc = _vanishing("mu", STATUE) | _vanishing("alpha", STATUE)
    table, blocks, _ = draw_samples(STATUE, [QUAKE], unc, 4, seed=2)
    for (_, row), b in zip(table.iterrows(), blocks, strict=True):
        assert not b.symmetric
        assert b.alpha == row["alpha"] and b.mu == row["mu"]  # the weaker side: the drawn
        assert b.alpha_minus / b.alpha_plus == pytest.approx(
            STATUE.alpha_minus / STATUE.alpha_plus, rel=1e-12)
        assert (b.p_plus, b.p_minus) == (STATUE.p_plus, STATUE.p_minus)
        assert b.vertices == STATUE.vertices and b.mass == STATUE.mass


CAMPAIGN = """
[campaign]
name = "statue"
seed = 4
model = "housner"
{samples}

[[blocks]]
mesh = "{mesh}"
density = 2600
direction = "weakest"
mu = 0.9

[motions]
kind = "builtin"
name = "Rinaldi228"
load_factors = [0.4]
{uncertain}
"""


@pytest.mark.parametrize("name", ["alpha", "mu"])
def test_a_campaign_with_a_vanishing_spread_is_the_deterministic_run(name):
    mesh = example_mesh_path().as_posix()
    plain = parse_spec(CAMPAIGN.format(mesh=mesh, samples="", uncertain=""))
    det = Campaign(plain).run_ids([0])
    nominal = getattr(plain.blocks[0], name)
    dist = f'{name} = {{dist = "normal", mean = {nominal!r}, std = {TINY * nominal!r}}}'
    spec = parse_spec(CAMPAIGN.format(mesh=mesh, samples="samples = 3",
                                      uncertain="[uncertain]\n" + dist))
    assert not spec.blocks[0].symmetric
    c = Campaign(spec)
    _, blocks, _ = c.inputs(range(spec.n_sims))
    assert all(not b.symmetric and b.vertices == spec.blocks[0].vertices for b in blocks)
    rows = c.run_ids(range(spec.n_sims))
    theta = det["max_abs_theta"].iloc[0]
    assert 0.0 < theta < 0.5 * spec.blocks[0].alpha
    np.testing.assert_allclose(rows["max_abs_theta"], theta, rtol=1e-4)
    assert not rows["overturned"].any()


@pytest.mark.parametrize(("name", "factor"), [("alpha", 1.1), ("p", 1.1), ("mu", 0.9)])
def test_a_drawn_value_ten_percent_off_nominal_scales_both_sides(name, factor):
    """10 % above (mu: below, 1.1 x mu_minus would exceed 1) on both sides."""
    block = DERIVED  # both sides differ in alpha, p and mu
    nominal = getattr(block, name)
    values = {k: getattr(block, k) for k in ("alpha", "p", "mu")}
    values[name] = factor * nominal
    drawn = sample_block(block, values, [name])
    for side in ("plus", "minus"):
        assert getattr(drawn, f"{name}_{side}") == pytest.approx(
            factor * getattr(block, f"{name}_{side}"), rel=1e-14)
        for other in {"alpha", "p", "mu"} - {name}:  # the others are the block's own
            assert getattr(drawn, f"{other}_{side}") == getattr(block, f"{other}_{side}")
    assert getattr(drawn, name) == values[name]  # the weaker side: exactly the drawn value
    assert drawn.vertices == block.vertices and drawn.name == block.name


def test_the_factor_rule_through_a_fixed_draw():
    """``dist = "fixed"`` at 1.1 x the nominal alpha: every sample's sides are 1.1 x."""
    a = 1.1 * STATUE.alpha
    table, blocks, _ = draw_samples(STATUE, [QUAKE], {"alpha": {"dist": "fixed", "value": a}},
                                    3, seed=0)
    assert (table["alpha"] == a).all()
    for b in blocks:
        assert b.alpha_plus == pytest.approx(1.1 * STATUE.alpha_plus, rel=1e-14)
        assert b.alpha_minus == pytest.approx(1.1 * STATUE.alpha_minus, rel=1e-14)


def test_the_range_keeps_every_side_physical():
    """mu_minus > mu_plus (the weaker side's, the nominal): a drawn mu may reach
    mu_plus / mu_minus only, so that mu_minus stays <= 1; a distribution with more than
    1 % of its mass beyond is refused, naming the rule."""
    block = DERIVED
    assert block.mu_minus > block.mu_plus == block.mu
    lo, hi, shown = bounds(block, "mu")
    assert lo == 0.0 and hi == pytest.approx(block.mu / block.mu_minus, rel=1e-15)
    assert "mu_minus" in shown
    assert bounds(block, "alpha")[1] == pytest.approx(
        0.5 * math.pi * block.alpha_plus / block.alpha_minus, rel=1e-15)
    with pytest.raises(ParameterError, match=r"uncertain\['mu'\].*asymmetric.*mu_minus"):
        monte_carlo(block, QUAKE, {"mu": {"dist": "normal", "mean": 0.97, "std": 0.02}}, n=2)
    ok = {"mu": {"dist": "uniform", "low": 0.5, "high": hi}}
    _, blocks, _ = draw_samples(block, [QUAKE], ok, 200, seed=3)
    assert all(0.0 < b.mu_plus < b.mu_minus <= 1.0 for b in blocks)


def test_a_symmetric_block_is_drawn_as_before():
    """A symmetric block's sample is Block.from_params of the drawn values (its numbers
    unchanged: the same block as before the rule existed)."""
    block = rocking.specimen(2, "experimental")
    unc = {"alpha": {"dist": "normal", "cov": 0.03}, "mu": {"dist": "normal", "cov": 0.01}}
    table, blocks, _ = draw_samples(block, [Sine(2.0, 0.01, 0.5)], unc, 20, seed=7)
    for (_, row), b in zip(table.iterrows(), blocks, strict=True):
        assert b == Block.from_params(row["alpha"], row["p"], row["mu"], name=block.name)
        assert b.vertices is None and b.symmetric


def test_a_stack_refuses_the_rule():
    stack = rocking.Stack([Block.rectangular(0.2, 0.4, mass=10.0),
                           Block.rectangular(0.2, 0.4, mass=10.0)])
    top = stack.top
    values = {"alpha": top.alpha, "p": top.p, "mu": top.mu}
    with pytest.raises(ParameterError, match="no rule scales the blocks of a stack"):
        sample_block(stack, values, ["mu"])
    assert sample_block(stack, values, ["theta0"]) is stack  # nothing of the block drawn
