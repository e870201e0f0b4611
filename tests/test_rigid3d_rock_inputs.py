"""A scanned rock with no flat base (issue 30) from the command line and in a campaign:
``rocking simulate --model rigid3d --mesh rock.stl`` and a campaign's ``mesh`` block of
``model = "rigid3d"`` settle it into its resting pose (no base tolerance to choose), where
the planar analysis refuses it in one line naming settle and rigid3d.

The rock: a convex hull of 40 points near an ellipsoid (0.5, 0.35, 0.3 m) written to an
STL; its lowest vertex alone lies within the planar tolerance (1e-3 of its height), so
it has no flat base; settled it rests on three vertices."""

from __future__ import annotations

import json

import numpy as np
import pytest
import trimesh
from cli_helpers import assert_one_line_error, run_main
from click.testing import CliRunner

import rocking
from rocking import ParameterError
from rocking.campaign import Campaign, parse_spec
from rocking.cli import cli
from rocking.motions import HorizontalPair, load_builtin
from rocking.shapes import load_shape
from rocking.shapes.mesh import convex_hull
from rocking.shapes.rest import is_resting

FAST = ("--step", "2e-3", "--dt-out", "0.01")


@pytest.fixture(scope="module")
def rock_stl(tmp_path_factory):
    rng = np.random.default_rng(3)
    d = rng.normal(size=(40, 3))
    d /= np.linalg.norm(d, axis=1)[:, None]
    v, f = convex_hull(d * np.array([0.5, 0.35, 0.3]) * rng.uniform(0.85, 1.0, (40, 1)))
    path = tmp_path_factory.mktemp("rock") / "rock.stl"
    trimesh.Trimesh(v, f).export(path)
    return path


@pytest.fixture(scope="module")
def rock(rock_stl):
    return load_shape(rock_stl, density=2700.0, settle=True)


def test_the_rock_has_no_flat_base_and_settles_on_three_points(rock_stl, rock):
    with pytest.raises(ParameterError, match="settle"):
        load_shape(rock_stl, density=2700.0)
    assert rock.contact_points == 3 and is_resting(rock)
    # its resting up is tilted from the file's z: it rolled onto that face
    assert rock.frame[2][2] < np.cos(np.radians(2.0))


def test_planar_analysis_refuses_it_in_one_line_naming_settle_and_rigid3d(capsys,
                                                                          rock_stl):
    for args in (("shape", rock_stl, "--density", "2700"),
                 ("simulate", "--mesh", rock_stl, "--density", "2700", "--record",
                  "Rinaldi228")):
        code, _, err = run_main(capsys, *args)
        assert_one_line_error(code, err, "flat base")
        assert "settle" in err and "rigid3d" in err


def test_cli_runs_the_settled_rock(rock_stl, rock):
    """The command line's body is the settled rock (mass, h, three contact points) and its
    run the library's on it."""
    res = CliRunner().invoke(cli, ["simulate", "--model", "rigid3d", "--mesh", str(rock_stl),
                                   "--density", "2700", "--record", "Rinaldi228",
                                   "--duration", "3", *FAST, "--json"],
                             catch_exceptions=False)
    assert res.exit_code == 0, res.output
    s = json.loads(res.stdout)
    blk = s["inputs"]["block"]
    assert blk["mass"] == pytest.approx(rock.mass, rel=1e-12)
    assert blk["h"] == pytest.approx(rock.h, rel=1e-12) and blk["contact_points"] == 3
    r = rocking.simulate(rock, load_builtin("Rinaldi228"), model="rigid3d", duration=3.0,
                         step=2e-3, dt_out=0.01)
    assert r.max_tilt > 1e-3  # it rocks
    for name in ("max_tilt", "max_slide", "max_twist", "n_impacts"):
        assert s[name] == pytest.approx(getattr(r, name), rel=1e-12, abs=1e-15), name


def test_campaign_mesh_block_runs_the_settled_rock(rock_stl, rock):
    """A campaign's mesh block of model rigid3d is the settled rock; a row is its run."""
    spec = parse_spec(f"""
[campaign]
name = "rock"
seed = 1
model = "rigid3d"
duration = 3.0

[[blocks]]
name = "rock"
mesh = "{rock_stl}"
density = 2700

[motions]
kind = "pair"
set = ["rinaldi"]
load_factors = [1.0]

[options.rigid3d]
step = 4e-3
heading = [0, 90]
""")
    body = spec.blocks[0]
    assert body.contact_points == 3 and body.h == pytest.approx(rock.h, rel=1e-12)
    rows = Campaign(spec).run_ids([0, 1])
    pair = HorizontalPair.builtin("rinaldi")
    for _, row in rows.iterrows():
        r = rocking.simulate(rock, pair, model="rigid3d", duration=3.0, step=4e-3,
                             heading=float(row["heading"]))
        assert row["max_tilt"] == pytest.approx(r.max_tilt, rel=1e-12)
        assert row["max_slide"] == pytest.approx(r.max_slide, rel=1e-12, abs=1e-15)
    assert sorted(rows["heading"]) == [0.0, 90.0] and rows["max_tilt"].max() > 0.1
