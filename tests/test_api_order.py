"""simulate and simulate_many take their arguments in one order: block, motion(s), model,
duration by position, everything else by keyword; positional use of the rest still works
for one release, with a DeprecationWarning (issue 17)."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import rocking
from rocking.motions import OneSine, Sine


@pytest.fixture(scope="module")
def block():
    return rocking.specimen(2, "experimental")


def test_keywords_give_no_warning_and_the_same_order(block):
    m = Sine(5.0, 0.005, 3.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        a = rocking.simulate(block, m, "housner", 3.0, theta0=0.01, linear=True)
        b = rocking.simulate_many(block, [m], "housner", 3.0, theta0=0.01, linear=True)
    assert a.max_abs_theta == b.max_abs_theta[0] and a.model == b.model == "housner-linear"


def test_positional_use_is_deprecated_but_works(block):
    m = Sine(5.0, 0.005, 3.0)
    ref = rocking.simulate(block, m, "housner", 3.0, theta0=0.01, omega0=0.02, linear=True)
    with pytest.warns(DeprecationWarning, match="theta0, omega0, linear"):
        old = rocking.simulate(block, m, "housner", 3.0, 0.01, 0.02, True)
    np.testing.assert_array_equal(old.theta, ref.theta)
    refb = rocking.simulate_many(block, [m], "housner", 3.0, linear=True)
    with pytest.warns(DeprecationWarning, match="linear"):
        oldb = rocking.simulate_many(block, [m], "housner", 3.0, True)
    assert oldb.max_abs_theta[0] == refb.max_abs_theta[0]


def test_an_argument_given_twice_is_refused(block):
    m = OneSine(3.0, 0.5)
    with pytest.raises(TypeError, match="theta0"):
        rocking.simulate(block, m, "housner", None, 0.01, theta0=0.02)
    with pytest.raises(TypeError, match="positional"):
        rocking.simulate_many(block, [m], "housner", None, True, 1)
