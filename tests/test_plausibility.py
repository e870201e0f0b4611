"""Values that are surely a unit slip, and one form per quantity (issue 31, items 9 and
10).

One set of limits (:data:`rocking.PLAUSIBLE_LIMITS`) serves the Python API (a one-line
:class:`rocking.UnitSlipWarning`) and the command line (a one-line refusal, exit code 2,
unless ``--force``): a density outside 300-25,000 kg/m^3, a site PGA above 2 g, a mesh
larger than 50 m, a building period above 20 s. A code PGA takes the same forms in the API
and in a spec: a bare number in g, or a string with its unit."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
import trimesh
from cli_helpers import assert_one_line_error, run_main

import rocking
from rocking import PLAUSIBLE_LIMITS, UnitSlipWarning
from rocking.analysis import HazardCurve
from rocking.buildings import Building
from rocking.buildings.catalog import MAX_PERIOD
from rocking.campaign import parse_spec
from rocking.errors import ParameterError
from rocking.shapes import Shape, example_mesh_path, load_shape
from rocking.units import G

STATUE = str(example_mesh_path())

SPEC = """\
campaign = {{name = "h", seed = 1, model = "housner"}}
blocks = [{{specimen = 2}}]
run = {{chunk_size = 2}}
[motions]
kind = "one_sine"
period = 0.5
amplitude = 1.0
load_factors = [1.0, 2.0]
[hazard]
{hazard}
"""


def one_slip(fn, *args, **kwargs):
    """The single UnitSlipWarning of ``fn(...)``: its one-line message."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        out = fn(*args, **kwargs)
    slips = [w for w in caught if issubclass(w.category, UnitSlipWarning)]
    assert len(slips) == 1, [str(w.message) for w in caught]
    msg = str(slips[0].message)
    assert "\n" not in msg and "unit slip" in msg
    return msg, out


def no_slip(fn, *args, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("error", UnitSlipWarning)
        return fn(*args, **kwargs)


# ----------------------------------------------------------------- the one set of limits
def test_the_limits_are_the_issues_and_the_cli_uses_the_same():
    assert PLAUSIBLE_LIMITS["density"][:2] == (300.0, 25_000.0)
    assert PLAUSIBLE_LIMITS["site_pga"][1] == pytest.approx(2.0 * G)
    assert PLAUSIBLE_LIMITS["size"][1] == 50.0
    assert PLAUSIBLE_LIMITS["building_period"][1] == MAX_PERIOD == 20.0
    assert issubclass(UnitSlipWarning, rocking.PlausibilityWarning)


# ------------------------------------------------------------------------------ density
def test_a_density_outside_the_limits_warns_in_python_at_both_ends():
    msg, box = one_slip(Shape.box, 0.4, 0.6, 2.0, density=2.6)  # t/m^3 meant
    assert "density = 2.6 kg/m^3" in msg and "300-25,000" in msg
    assert box.mass == pytest.approx(2.6 * 0.48)  # warned, not changed
    one_slip(Shape.box, 0.4, 0.6, 2.0, density=2.6e6)  # g/m^3?
    for rho in (300.0, 2600.0, 25_000.0):  # the edges are in
        no_slip(Shape.box, 0.4, 0.6, 2.0, density=rho)
    msg, _ = one_slip(rocking.Block.polygon, [(0, 0), (0.4, 0), (0.4, 1.2), (0, 1.2)],
                      density=2.6, thickness=0.3)
    assert "density" in msg


def test_a_mass_that_gives_an_implausible_density_is_named():
    """900 kg in the 0.096 m^3 statue is 9,377 kg/m^3: inside the unit-slip limits, but
    denser than steel: a plausibility warning (not a refusal) that gives the density; a
    mass 1000 times too small (kg read as t) is a unit slip."""
    with pytest.warns(rocking.PlausibilityWarning, match=r"9,37\d kg/m\^3, denser than steel"):
        sh = load_shape(STATUE, mass=900.0)
    assert sh.density == pytest.approx(900.0 / sh.volume)
    msg, _ = one_slip(load_shape, STATUE, mass=0.9)
    assert "the mass over the mesh's volume" in msg
    no_slip(load_shape, STATUE, mass=250.0)  # 2,600 kg/m^3: marble


def test_the_cli_refuses_a_density_slip_unless_forced(capsys):
    code, out, err = run_main(capsys, "shape", STATUE, "--density", "2.6")
    assert_one_line_error(code, err, "density")
    assert "--force" in err and "2600 kg/m^3" in err
    code, out, err = run_main(capsys, "shape", STATUE, "--density", "2.6", "--force")
    assert code == 0 and err.startswith("warning: density = 2.6")
    m = float(out.split("mass", 1)[1].split("kg")[0])
    assert m == pytest.approx(2.6 * load_shape(STATUE, density=2600.0).volume, rel=1e-5)
    code, out, err = run_main(capsys, "simulate", "--mesh", STATUE, "--density", "2.6",
                              "--motion", "ricker", "--amp", "0.3g", "--freq", "2")
    assert_one_line_error(code, err, "density")


# ---------------------------------------------------------------------------- mesh size
def test_a_mesh_in_mm_read_as_m_is_refused_by_the_cli_and_warned_in_python(tmp_path, capsys):
    mesh = trimesh.load(STATUE)
    mesh.apply_scale(1000.0)  # the statue in mm
    path = tmp_path / "statue_mm.ply"
    mesh.export(path)
    msg, sh = one_slip(load_shape, path, density=2600.0)
    assert "largest extent" in msg and "above 50 m" in msg and "units='mm'" in msg
    assert sh.height > 1000.0
    ok = no_slip(load_shape, path, density=2600.0, units="mm")
    assert ok.height == pytest.approx(load_shape(STATUE, density=2600.0).height)
    code, out, err = run_main(capsys, "shape", path, "--density", "2600")
    assert_one_line_error(code, err, "50 m")
    code, out, err = run_main(capsys, "shape", path, "--density", "2600", "--units", "mm")
    assert code == 0, err
    # a mesh wide and flat (a 60 m slab only 2 m tall) is as implausible as a tall one
    one_slip(Shape.box, 60.0, 1.0, 2.0, density=2600.0)


# ----------------------------------------------------------------------------- site PGA
def test_a_site_pga_above_2g_warns_in_python_in_every_form():
    msg, c = one_slip(HazardCurve.from_code_value, 25)  # 2.5 m/s^2 meant as g
    assert "pga_475" in msg and "above 2 g" in msg
    assert c.im_at_return_period(475) == pytest.approx(25.0)
    one_slip(HazardCurve.from_code_value, "25g")
    one_slip(HazardCurve.from_code_value, 0.25, pga_2475="45g")
    one_slip(HazardCurve.from_code_value, 25.0, unit="m/s^2")  # 2.55 g
    no_slip(HazardCurve.from_code_value, 2.0)  # the edge is in
    no_slip(HazardCurve.from_code_value, 19.0, unit="m/s^2")


def test_a_site_pga_above_2g_in_a_spec_warns_and_the_cli_refuses(tmp_path, capsys):
    text = SPEC.format(hazard='pga_475 = "25g"')
    msg, s = one_slip(parse_spec, text, base_dir=tmp_path)
    assert "pga_475" in msg and s.hazard is not None
    (tmp_path / "s.toml").write_text(text)
    code, out, err = run_main(capsys, "campaign", "run", tmp_path / "s.toml", "--dry-run")
    assert_one_line_error(code, err, "pga_475")
    assert "--force" in err
    code, out, err = run_main(capsys, "campaign", "run", tmp_path / "s.toml", "--dry-run",
                              "--force")
    assert code == 0, err
    assert "warning: pga_475" in err


# ---------------------------------------------------------------------- building period
def test_a_building_period_above_the_clis_limit_warns_in_python():
    msg, b = one_slip(Building.shear, 5, period=500.0)
    assert "20 s" in msg and "500" in msg
    assert b.periods[0] == pytest.approx(500.0)
    one_slip(Building.sdof, 25.0)
    one_slip(Building.continuous, 30.0, 5.0)
    no_slip(Building.shear, 5, period=MAX_PERIOD)
    with pytest.raises(ParameterError, match=r"\(0, 20\] s"):
        rocking.buildings.catalog.make_building({"kind": "shear", "storeys": 5,
                                                 "period": 500.0})


# ------------------------------------------------------------- one form per quantity
@pytest.mark.parametrize("form", [0.25, "0.25g", "0.25 g", "2.4516625m/s^2", "245.16625gal",
                                  "0.25"])
def test_a_code_pga_takes_the_same_forms_in_the_api_and_the_spec(form, tmp_path):
    """A bare number in g (the documented unit) or a string with its unit: the API and
    the spec give the same curve."""
    api = HazardCurve.from_code_value(form)
    assert api.im_at_return_period(475) == pytest.approx(0.25, rel=1e-12)
    value = repr(form) if isinstance(form, float) else f'"{form}"'
    s = parse_spec(SPEC.format(hazard=f"pga_475 = {value}"), base_dir=tmp_path)
    np.testing.assert_allclose(s.hazard["im"], api.im, rtol=1e-12)
    np.testing.assert_allclose(s.hazard["rate"], api.rate, rtol=1e-12)


def test_a_code_pga_in_another_form_is_refused_naming_it(tmp_path):
    for bad in (True, "0.25 parsec", -0.25, "fast"):
        with pytest.raises(ParameterError, match="pga_475"):
            HazardCurve.from_code_value(bad)
    # the two forms of pga_2475 agree as well
    a = HazardCurve.from_code_value(0.25, pga_2475=0.45)
    b = HazardCurve.from_code_value("0.25g", pga_2475="4.4129925m/s^2")
    assert a.tail_slopes[0] == pytest.approx(b.tail_slopes[0], rel=1e-12)
    assert math.isclose(b.im_at_return_period(2475), 0.45, rel_tol=1e-9)
