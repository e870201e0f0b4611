"""``rocking simulate --model rigid3d`` (issue 30): a body from --mesh, --box, --cylinder,
--width/--height; a pair of horizontal components (--pair, --vertical, --heading) or one
motion along --direction; the response, summary and plots; bad input refused in one line.
Each run is checked against the library call with the same inputs."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from cli_helpers import assert_one_line_error, run_main
from click.testing import CliRunner

import rocking
from rocking.cli import cli
from rocking.motions import HorizontalPair, load_builtin
from rocking.shapes import Shape, example

RECORDS = Path(rocking.__file__).parent / "motions" / "data" / "records" / "three_component"
FAST = ("--step", "2e-3", "--dt-out", "0.01")


def invoke(*args):
    res = CliRunner().invoke(cli, [str(a) for a in args], catch_exceptions=False)
    assert res.exit_code == 0, res.output
    return res.stdout


def run_json(*args) -> dict:
    return json.loads(invoke("simulate", "--model", "rigid3d", *FAST, *args, "--json"))


def same_outputs(summary: dict, r) -> None:
    for name in ("max_tilt", "max_slide", "residual_slide", "max_twist", "residual_twist",
                 "n_impacts"):
        assert summary[name] == pytest.approx(getattr(r, name), rel=1e-12, abs=1e-15), name
    assert summary["overturned"] == r.overturned


def test_issue_command_line_writes_response_summary_and_plots(tmp_path):
    """The issue's command (files with NGA headers, the vertical, heading 30 deg), on a
    box: the same run as the library's, the CSV's tilt/slide/twist those of the response,
    and the three plots."""
    files = [RECORDS / f"Rinaldi{c}.AT2" for c in ("228", "318", "UP")]
    out = tmp_path / "out"
    text = invoke("simulate", "--model", "rigid3d", "--box", "0.3", "0.4", "1.2",
                  "--pair", files[0], files[1], "--vertical", files[2], "--heading", "30",
                  "--duration", "4", *FAST, "--out", out)
    box = Shape.box(0.3, 0.4, 1.2, density=1000.0)
    pair = HorizontalPair.from_files(*files)
    r = rocking.simulate(box, pair, model="rigid3d", heading=30.0, duration=4.0, step=2e-3,
                         dt_out=0.01)
    assert r.max_tilt > 0.02  # it rocks
    assert f"max tilt    {math.degrees(r.max_tilt):.4g} deg" in text
    summary = json.loads((out / "summary.json").read_text())
    same_outputs(summary, r)
    assert summary["inputs"]["motion"]["azimuths_deg"] == pytest.approx([228.0, 318.0])
    assert summary["inputs"]["options"]["heading"] == 30.0
    df = pd.read_csv(out / "response.csv")
    assert {"t", "x", "y", "q0", "tilt", "slide", "twist"} <= set(df.columns)
    np.testing.assert_allclose(df["tilt"], r.tilt, rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(df["slide"], r.slide, rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(df["twist"], r.twist, rtol=1e-9, atol=1e-15)
    for png in ("tilt_slide_twist.png", "com_path.png", "overturn_azimuth.png"):
        assert (out / png).stat().st_size > 10_000, png
    assert not (out / "theta.png").exists()


def test_out_writes_the_page_and_with_animate_the_gif(tmp_path):
    """--out writes motion.html (on by default), which embeds this run: the same times,
    positions and quaternions as the library's response, the box's 12 triangles; with
    --animate the GIF too, one frame per 1/12 s of the response. --no-html: no page."""
    from PIL import Image

    from rocking.viewer3d import frame_indices, frame_times, read_page_data

    out = tmp_path / "out"
    invoke("simulate", "--model", "rigid3d", "--box", "0.3", "0.4", "1.2", "--pair",
           "Rinaldi228", "Rinaldi318", "--heading", "30", "--duration", "1.5", *FAST,
           "--out", out, "--animate")
    r = rocking.simulate(Shape.box(0.3, 0.4, 1.2, density=1000.0),
                         HorizontalPair.builtin("Rinaldi228", "Rinaldi318"),
                         model="rigid3d", heading=30.0, duration=1.5, step=2e-3, dt_out=0.01)
    data = read_page_data(out / "motion.html")
    idx = frame_indices(len(r.t), r.t[1] - r.t[0], 60.0)
    names = list(r.state_names)
    np.testing.assert_allclose(data["t"], r.t[idx], atol=1e-9)
    np.testing.assert_allclose(np.reshape(data["pos"], (-1, 3)),
                               r.states[idx][:, [names.index(n) for n in "xyz"]], atol=1e-7)
    q = r.states[idx][:, [names.index(f"q{i}") for i in range(4)]]
    np.testing.assert_allclose(np.reshape(data["quat"], (-1, 4)),
                               q / np.linalg.norm(q, axis=1)[:, None], atol=1e-8)
    assert len(data["faces"]) == 3 * 12
    text = (out / "motion.html").read_text("utf-8")
    assert "http://" not in text.split("<script")[0] and "0.3 x 0.4 x 1.2 m box" in text
    assert Image.open(out / "motion.gif").n_frames == len(frame_times(r.t[-1], 12.0, 1.0))
    out2 = tmp_path / "out2"
    invoke("simulate", "--model", "rigid3d", "--box", "0.3", "0.4", "1.2", "--record",
           "Rinaldi228", "--duration", "0.2", *FAST, "--out", out2, "--no-html")
    assert (out2 / "summary.json").exists()
    assert not (out2 / "motion.html").exists() and not (out2 / "motion.gif").exists()


@pytest.mark.parametrize("args, name", [
    (("--model", "rigid3d", "--box", "1", "1", "1", "--record", "Rinaldi228", "--animate"),
     "animate"),
    (("--model", "rigid3d", "--box", "1", "1", "1", "--record", "Rinaldi228", "--html"),
     "html"),
    (("--specimen", "2", "--record", "Rinaldi228", "--out", "x", "--animate"), "animate"),
    (("--specimen", "2", "--record", "Rinaldi228", "--out", "x", "--html"), "html"),
])
def test_viewer_flags_need_out_and_rigid3d(capsys, args, name, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, _, err = run_main(capsys, "simulate", *args)
    assert_one_line_error(code, err, name)
    assert not (tmp_path / "x").exists()


def test_built_in_pair_on_the_example_mesh():
    """--mesh with built-in record names: the whole mesh as a 3-D body."""
    mesh = example.example_mesh_path()
    s = run_json("--mesh", mesh, "--density", "2600", "--pair", "Rinaldi228", "Rinaldi318",
                 "--heading", "-45", "--duration", "0.5")
    shape = rocking.shapes.load_shape(mesh, density=2600.0)
    pair = HorizontalPair.from_records(load_builtin("Rinaldi228"), load_builtin("Rinaldi318"))
    r = rocking.simulate(shape, pair, model="rigid3d", heading=-45.0, duration=0.5,
                         step=2e-3, dt_out=0.01)
    same_outputs(s, r)
    assert s["inputs"]["block"]["mass"] == pytest.approx(shape.mass)


def test_direction_is_rigid3ds_option_and_resolves_weakest():
    """--direction is where a single motion acts; 'weakest' is the body's weakest
    direction (its support's edge nearest the centre of mass)."""
    s = run_json("--width", "0.25", "--height", "1.0", "--record", "Rinaldi228",
                 "--direction", "30", "--duration", "4")
    blk = rocking.Block.rectangular(0.25, 1.0)
    r = rocking.simulate(blk, load_builtin("Rinaldi228"), model="rigid3d", direction=30.0,
                         duration=4.0, step=2e-3, dt_out=0.01)
    assert r.max_tilt > 0.01
    same_outputs(s, r)
    s = run_json("--box", "0.3", "0.5", "1.0", "--record", "Rinaldi228", "--direction",
                 "weakest", "--duration", "0.2")
    weak = Shape.box(0.3, 0.5, 1.0, density=1000.0).weakest().phi_deg
    assert abs(math.cos(math.radians(s["inputs"]["options"]["direction"] - weak)) - 1) < 1e-12
    assert math.isclose(abs(math.cos(math.radians(weak))), 1.0)  # across the thin side (x)


def test_cylinder_flag_is_the_shapes_cylinder():
    s = run_json("--cylinder", "0.2", "1.0", "--mass", "100", "--pair", "Rinaldi228",
                 "Rinaldi318", "--duration", "0.3")
    assert s["inputs"]["block"]["mass"] == pytest.approx(100.0)
    r = rocking.simulate(Shape.cylinder(0.2, 1.0, mass=100.0), HorizontalPair.builtin(
        "Rinaldi228", "Rinaldi318"), model="rigid3d", duration=0.3, step=2e-3, dt_out=0.01)
    same_outputs(s, r)


@pytest.mark.parametrize("args, name", [
    (("--box", "0.4", "0.4", "-1", "--record", "Rinaldi228"), "box[2]"),
    (("--box", "0.4", "0.4", "1", "--cylinder", "1", "2", "--record", "Rinaldi228"), "block"),
    (("--box", "1", "1", "1", "--pair", "Rinaldi228", "Rinaldi318", "--direction", "20"),
     "direction"),
    (("--box", "1", "1", "1", "--record", "Rinaldi228", "--heading", "30"), "heading"),
    (("--box", "1", "1", "1", "--pair", "Rinaldi228", "nosuch.AT2"), "pair"),
    (("--box", "1", "1", "1", "--pair", "Rinaldi228", "RSN1158_KOCAELI_DZC180"), "pair"),
    (("--box", "1", "1", "1", "--pair", "Rinaldi228", "Rinaldi318", "--record",
      "Rinaldi228"), "record"),
    (("--box", "1", "1", "1", "--record", "Rinaldi228", "--theta0", "0.1"), "theta0"),
    (("--alpha", "0.2", "--p", "2", "--mu", "0.9", "--record", "Rinaldi228"), "alpha"),
    (("--box", "1", "1", "1", "--record", "Rinaldi228", "--friction", "0"), "friction"),
    (("--box", "1", "1", "1", "--record", "Rinaldi228", "--restitution", "1.5"),
     "restitution"),
    (("--box", "1", "1", "1", "--record", "Rinaldi228", "--direction", "20", "--option",
      "direction=3"), "direction"),
    (("--box", "1", "1", "1", "--density", "2000", "--mass", "4", "--record", "Rinaldi228"),
     "density"),
    (("--box", "1", "1", "1", "--up", "y", "--record", "Rinaldi228"), "up"),
])
def test_bad_input_is_one_line_exit_2(capsys, args, name):
    code, _, err = run_main(capsys, "simulate", "--model", "rigid3d", *args)
    assert_one_line_error(code, err, name)


@pytest.mark.parametrize("args, name", [
    (("--specimen", "2", "--pair", "Rinaldi228", "Rinaldi318"), "pair"),
    (("--box", "1", "1", "1", "--record", "Rinaldi228"), "box"),
])
def test_3d_flags_need_rigid3d(capsys, args, name):
    code, _, err = run_main(capsys, "simulate", *args)
    assert_one_line_error(code, err, name)
    assert "rigid3d" in err
