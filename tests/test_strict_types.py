"""Parameters are the type they say (issue 16, section 3, first bullet).

Booleans accept only ``bool`` (and ``numpy.bool_``); counts only integers (Python or
numpy, never a float, even a whole one); numbers refuse ``bool``.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import rocking
from rocking._validate import as_bool, as_float, as_int, in_range, non_negative, positive
from rocking.errors import ParameterError
from rocking.motions import OneSine, Record, Sine

BOOLS = [True, False, np.True_, np.False_]
NOT_BOOLS = ["false", "False", "true", "", "0", 0, 1, 1.0, 0.0, None, np.int64(1),
             np.float64(0.0), [True], (False,)]
INTS = [0, 3, -7, 10**12, np.int8(3), np.int16(-2), np.int32(5), np.int64(7), np.uint8(4),
        np.uint64(9)]
NOT_INTS = [1.5, 2.0, -0.0, np.float64(2.0), np.float32(3.0), True, False, np.True_, "3",
            "2", None, math.nan, math.inf, 3 + 0j, [1], np.array([1, 2])]


class TestAsBool:
    @pytest.mark.parametrize("value", BOOLS)
    def test_accepts_bools(self, value):
        out = as_bool("linear", value)
        assert type(out) is bool and out == bool(value)

    @pytest.mark.parametrize("value", NOT_BOOLS)
    def test_refuses_everything_else(self, value):
        with pytest.raises(ParameterError) as exc:
            as_bool("linear", value)
        msg = str(exc.value)
        assert msg.startswith("linear must be True or False") and repr(value) in msg
        assert "\n" not in msg

    def test_the_issue_example(self):
        # "false" is truthy: it must never be read as True (or as False)
        with pytest.raises(ParameterError, match="linear must be True or False, got 'false'"):
            as_bool("linear", "false")


class TestAsInt:
    @pytest.mark.parametrize("value", INTS)
    def test_accepts_integers(self, value):
        out = as_int("max_impacts", value)
        assert type(out) is int and out == int(value)

    @pytest.mark.parametrize("value", NOT_INTS)
    def test_refuses_non_integers(self, value):
        with pytest.raises(ParameterError) as exc:
            as_int("max_impacts", value)
        msg = str(exc.value)
        assert msg.startswith("max_impacts must be an integer") and "\n" not in msg

    def test_the_issue_example(self):
        with pytest.raises(ParameterError, match="max_impacts must be an integer, got 1.5"):
            as_int("max_impacts", 1.5)

    @pytest.mark.parametrize("value, lo, hi, shown", [
        (-1, 0, None, ">= 0"), (11, None, 10, "<= 10"), (0, 1, 5, r"\[1, 5\]"),
        (6, 1, 5, r"\[1, 5\]"), (np.int64(-3), 0, 100, r"\[0, 100\]"),
    ])
    def test_range(self, value, lo, hi, shown):
        with pytest.raises(ParameterError, match=rf"n must be an integer {shown}, got"):
            as_int("n", value, lo, hi)

    @given(st.integers(-10**6, 10**6), st.integers(-10**6, 10**6))
    def test_bounds_inclusive(self, a, b):
        lo, hi = min(a, b), max(a, b)
        assert as_int("n", lo, lo, hi) == lo and as_int("n", hi, lo, hi) == hi
        assert as_int("n", np.int64(hi), lo, hi) == hi

    @given(st.floats(allow_nan=True, allow_infinity=True))
    def test_no_float_is_a_count(self, x):
        with pytest.raises(ParameterError):
            as_int("n", x)


class TestNumbersRefuseBool:
    @pytest.mark.parametrize("fn", [as_float, positive, non_negative])
    @pytest.mark.parametrize("value", BOOLS)
    def test_validators(self, fn, value):
        with pytest.raises(ParameterError) as exc:
            fn("width", value)
        msg = str(exc.value)
        assert msg.startswith("width must be") and "bool" in msg and "\n" not in msg

    @pytest.mark.parametrize("value", BOOLS)
    def test_in_range(self, value):
        with pytest.raises(ParameterError, match="^mu must be"):
            in_range("mu", value, 0.0, 1.0, hi_open=False)

    @pytest.mark.parametrize("value, expected", [(1, 1.0), (np.int64(2), 2.0), (0.5, 0.5),
                                                 (np.float32(0.25), 0.25), ("1.5", 1.5)])
    def test_numbers_still_accepted(self, value, expected):
        out = as_float("x", value)
        assert type(out) is float and out == expected

    @pytest.mark.parametrize("value", BOOLS[:1] + BOOLS[2:3])
    def test_block_rectangular(self, value):
        with pytest.raises(ParameterError, match="^width must be"):
            rocking.Block.rectangular(value, 1.0)
        with pytest.raises(ParameterError, match="^height must be"):
            rocking.Block.rectangular(0.2, value)
        with pytest.raises(ParameterError, match="^mass must be"):
            rocking.Block.rectangular(0.2, 1.0, mass=value)

    def test_block_from_params_and_motions(self):
        with pytest.raises(ParameterError, match="^mu must be"):
            rocking.Block.from_params(0.2, 2.0, True)
        with pytest.raises(ParameterError, match="^freq must be"):
            Sine(True, 0.005, 2.0)
        with pytest.raises(ParameterError, match="^amplitude must be"):
            Sine(5.0, np.True_, 2.0)
        with pytest.raises(ParameterError, match="^scale must be"):
            Record([0.0, 1.0], 0.01, scale=True)
        with pytest.raises(ParameterError, match="^dt must be"):
            Record([0.0, 1.0], True)
        with pytest.raises(ParameterError, match="^factor must be"):
            OneSine(1.0, 0.5).scaled(True)
