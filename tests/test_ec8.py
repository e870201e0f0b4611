"""EN 1998-1 elastic spectrum (§3.2.2.2) and custom spectra of the same shape."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rocking.blocks.specimens import paper_data
from rocking.errors import ParameterError
from rocking.motions import DesignSpectrum, ec8_spectrum, paper_target
from rocking.motions.ec8 import PAPER_TD, ec8_parameters, eta

# EN 1998-1 Table 3.2 (Type 1) and Table 3.3 (Type 2), typed from the standard
TABLES = {
    (1, "A"): (1.00, 0.15, 0.4, 2.0), (1, "B"): (1.20, 0.15, 0.5, 2.0),
    (1, "C"): (1.15, 0.20, 0.6, 2.0), (1, "D"): (1.35, 0.20, 0.8, 2.0),
    (1, "E"): (1.40, 0.15, 0.5, 2.0),
    (2, "A"): (1.00, 0.05, 0.25, 1.2), (2, "B"): (1.35, 0.05, 0.25, 1.2),
    (2, "C"): (1.50, 0.10, 0.25, 1.2), (2, "D"): (1.80, 0.10, 0.30, 1.2),
    (2, "E"): (1.60, 0.05, 0.25, 1.2),
}


def standard(T, ag, S, TB, TC, TD, eta_=1.0):
    """EN 1998-1 Eqs (3.2)-(3.5), one period at a time, written out independently."""
    if T <= TB:
        return ag * S * (1.0 + T / TB * (eta_ * 2.5 - 1.0))
    if T <= TC:
        return ag * S * eta_ * 2.5
    if T <= TD:
        return ag * S * eta_ * 2.5 * TC / T
    return ag * S * eta_ * 2.5 * TC * TD / T**2


class TestEC8:
    def test_type1_ground_c_at_the_corners(self):
        ag = 2.0
        S, TB, TC, TD = 1.15, 0.2, 0.6, 2.0
        assert ec8_parameters("C", 1) == {"S": S, "TB": TB, "TC": TC, "TD": TD}
        T = [0.0, TB, TC, TD, 4.0]
        expected = [ag * S, ag * S * 2.5, ag * S * 2.5, ag * S * 2.5 * TC / TD,
                    ag * S * 2.5 * TC * TD / 16.0]
        np.testing.assert_allclose(ec8_spectrum(T, ag, "C", 1), expected, rtol=1e-14)
        assert ec8_spectrum(TC, ag, "C", 1) == pytest.approx(2.0 * 1.15 * 2.5)

    @pytest.mark.parametrize(("stype", "ground"), sorted(TABLES))
    def test_every_table_row_against_the_formulas(self, stype, ground):
        S, TB, TC, TD = TABLES[(stype, ground)]
        ag = 0.25 * 9.81
        T = np.concatenate([[0.0, 0.5 * TB, TB, 0.5 * (TB + TC), TC, 0.5 * (TC + TD), TD],
                            np.linspace(TD, 4.0, 5)])
        for damping, e in ((0.05, 1.0), (0.02, math.sqrt(10 / 7)), (0.10, math.sqrt(10 / 15))):
            got = ec8_spectrum(T, ag, ground, stype, damping=damping)
            want = [standard(t, ag, S, TB, TC, TD, e) for t in T]
            np.testing.assert_allclose(got, want, rtol=1e-13)

    @pytest.mark.parametrize(("stype", "ground"), [(1, "A"), (1, "D"), (2, "B"), (2, "E")])
    def test_continuous_at_the_corners(self, stype, ground):
        S, TB, TC, TD = TABLES[(stype, ground)]
        for Tc in (TB, TC, TD):
            lo, hi = ec8_spectrum([Tc * (1 - 1e-9), Tc * (1 + 1e-9)], 3.0, ground, stype)
            assert lo == pytest.approx(hi, rel=1e-7)

    def test_eta(self):
        assert eta(0.05) == 1.0
        assert eta(0.10) == pytest.approx(math.sqrt(10 / 15))
        assert eta(0.0) == pytest.approx(math.sqrt(2.0))
        assert eta(0.28) == pytest.approx(max(math.sqrt(10 / 33), 0.55))
        assert eta(0.30) == 0.55  # sqrt(10/35) = 0.53 is below the floor
        assert eta(0.5) == 0.55

    def test_scalar_in_scalar_out_and_zero_ag(self):
        assert isinstance(ec8_spectrum(0.3, 1.0), float)
        assert ec8_spectrum(1.0, 0.0) == 0.0

    @pytest.mark.parametrize(("kw", "words"), [
        ({"ground": "F"}, "ground must be one of A, B, C, D, E"),
        ({"spectrum_type": 3}, "spectrum_type must be 1 or 2"),
        ({"spectrum_type": 1.5}, "spectrum_type must be 1 or 2"),
        ({"damping": 5}, "damping must be in [0, 1)"),
        ({"damping": -0.01}, "damping"),
        ({"ag": -1.0}, "ag must be >= 0"),
        ({"periods": [-0.1]}, "periods must be finite and >= 0"),
        ({"periods": [np.nan]}, "periods must be finite"),
    ])
    def test_errors(self, kw, words):
        args = {"periods": [0.1, 1.0], "ag": 1.0}
        args.update(kw)
        with pytest.raises(ParameterError, match=None) as ei:
            ec8_spectrum(**args)
        assert words in str(ei.value)

    def test_string_type_and_lower_case_ground(self):
        np.testing.assert_allclose(ec8_spectrum([0.5], 1.0, "b", "2"),
                                   ec8_spectrum([0.5], 1.0, "B", 2))


class TestDesignSpectrum:
    def test_paper_target(self):
        t = paper_target()
        cfg = paper_data()["ec8_target"]
        assert t(0.0) == cfg["pga"] == 2.8
        assert t(cfg["plateau_start"]) == t(cfg["plateau_end"]) == cfg["plateau_acceleration"]
        assert t.amplification == pytest.approx(2.5)  # the EC8 plateau factor at 5 %
        assert t.td == PAPER_TD == 1.2
        np.testing.assert_allclose(t([0.05, 0.6, 1.2, 2.4]),
                                   [2.8 + 4.2 * 0.5, 3.5, 1.75, 7 * 0.3 * 1.2 / 2.4**2])

    def test_paper_target_is_ec8_type2_ground_d(self):
        """TB, TC of the paper are those of Type 2, ground D; with ag = 2.8 / S it is EC8."""
        T = np.linspace(0.0, 4.0, 401)
        np.testing.assert_allclose(paper_target()(T),
                                   ec8_spectrum(T, 2.8 / 1.8, "D", 2), rtol=1e-13)
        np.testing.assert_allclose(DesignSpectrum.ec8(2.8 / 1.8, "D", 2)(T),
                                   paper_target()(T), rtol=1e-13)

    def test_custom_shape(self):
        s = DesignSpectrum(pga=1.0, plateau=3.0, tb=0.2, tc=0.5, td=2.0)
        np.testing.assert_allclose(s([0.0, 0.1, 0.2, 0.5, 1.0, 2.0, 4.0]),
                                   [1.0, 2.0, 3.0, 3.0, 1.5, 0.75, 0.1875])
        assert isinstance(s(0.3), float)

    def test_with_damping_and_scaled(self):
        s = paper_target()
        s10 = s.with_damping(0.10)
        assert s10(0.0) == pytest.approx(2.8)
        assert s10(0.2) == pytest.approx(7.0 * math.sqrt(10 / 15))
        assert s10.with_damping(0.05)(0.2) == pytest.approx(7.0)
        np.testing.assert_allclose(s.scaled(2.0)([0, 0.2, 1.0]), 2 * s([0, 0.2, 1.0]))

    @pytest.mark.parametrize(("kw", "words"), [
        ({"tc": 0.05}, "tc must be > tb"),
        ({"td": 0.2}, "td must be >= tc"),
        ({"tb": 0.0}, "tb must be > 0"),
        ({"pga": -1.0}, "pga must be >= 0"),
        ({"damping": 1.0}, "damping"),
    ])
    def test_validation(self, kw, words):
        args = {"pga": 2.8, "plateau": 7.0, "tb": 0.1, "tc": 0.3, "td": 1.2}
        args.update(kw)
        with pytest.raises(ParameterError) as ei:
            DesignSpectrum(**args)
        assert words in str(ei.value)

    def test_describe(self):
        text = paper_target().describe()
        assert "PGA 2.8" in text and "TB = 0.1 s" in text and "TD = 1.2 s" in text
