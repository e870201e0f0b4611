"""The 3-D views of a ``rigid3d`` response (issue 30, "Seeing it"): the GIF's frames, the
self-contained page's data against the response, the poses against the ground plane, and
the page rendered in headless chromium (skipped only where no chromium exists)."""

from __future__ import annotations

import hashlib
import math
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

import rocking
from rocking.errors import ParameterError
from rocking.motions import Sine
from rocking.shapes import Shape
from rocking.viewer3d import (
    animate,
    decimate,
    frame_indices,
    frame_times,
    read_page_data,
    rotation_matrices,
    scene,
    tilt,
    write_html,
)

VENDOR = Path(rocking.viewer3d.__file__).parent / "vendor" / "three"
X, F, DIRECTION = 0.05, 2.0, 30.0  # m, Hz, deg: a box rocks hard (max tilt ~ alpha)


@pytest.fixture(scope="module")
def box():
    return Shape.box(0.4, 0.4, 1.2, mass=400.0)


@pytest.fixture(scope="module")
def response(box):
    """A box rocking, sliding and twisting under a sine along 30 deg (2 s)."""
    return rocking.simulate(box, Sine(freq=F, amplitude=X, duration=2.0), model="rigid3d",
                            direction=DIRECTION, duration=2.0)


@pytest.fixture(scope="module")
def page(response, tmp_path_factory):
    return write_html(response, tmp_path_factory.mktemp("page") / "box.html", fps=50)


def world_vertices(sc, pos, quat, ground=None):
    """Every vertex of the body in the ground's frame (or the fixed one), per frame."""
    R = rotation_matrices(quat)
    w = np.einsum("fij,vj->fvi", R, sc.vertices) + pos[:, None, :]
    return w if ground is None else w + ground[:, None, :]


# ------------------------------------------------------------------------- the poses
def test_the_body_stands_on_the_ground_in_every_frame(response):
    """The pose convention (vertices relative to the centre of mass, R(q) body to
    ground): the box never lifts off, so its lowest vertex is on the ground at every
    sample (to the scheme's penetration, a few 1e-5 of the size: Moreau-Jean keeps the
    contact in velocity), never below; a wrong quaternion order or sign would sink it or
    float it by centimetres."""
    assert not response.lifted_off and response.rocked
    sc = scene(response)
    zmin = world_vertices(sc, sc.position, sc.quaternion)[..., 2].min(axis=1)
    assert np.abs(zmin).max() < 1e-4 * 1.2, np.abs(zmin).max()


def test_tilt_history_matches_the_models_max_tilt(response):
    """The tilt from the quaternion (the up axis's angle from the vertical) peaks at the
    model's own ``max_tilt`` (sampled every dt_out: within a part in 10^3), and equals
    ``acos`` of the rotated up axis's z component."""
    sc = scene(response)
    tl = tilt(sc.quaternion)
    assert response.max_tilt > math.radians(5)
    assert tl.max() <= response.max_tilt * (1 + 1e-9)
    assert tl.max() == pytest.approx(response.max_tilt, rel=1e-3)
    up_z = rotation_matrices(sc.quaternion)[:, 2, 2]
    np.testing.assert_allclose(np.cos(tl), up_z, atol=1e-12)


def test_ground_displacement_is_the_sines(response):
    """Under ``Sine(X, f)`` along 30 deg, the ground moves by ``X sin(2 pi f t)`` along
    (cos 30, sin 30) while the motion lasts (the acceleration integrated twice)."""
    sc = scene(response, ground=True)
    exact = X * np.sin(2 * math.pi * F * sc.t)
    d = math.radians(DIRECTION)
    np.testing.assert_allclose(sc.ground[:, 0], exact * math.cos(d), atol=2e-5 * X)
    np.testing.assert_allclose(sc.ground[:, 1], exact * math.sin(d), atol=2e-5 * X)
    np.testing.assert_allclose(sc.ground[:, 2], 0.0, atol=1e-12)


# ------------------------------------------------------------------------- the GIF
def test_gif_has_the_expected_frames_and_size(response, tmp_path):
    fps, speed = 10.0, 2.0
    path = animate(response, tmp_path / "box.gif", fps=fps, speed=speed, size=(320, 240))
    im = Image.open(path)
    expected = len(frame_times(response.t[-1], fps, speed))
    assert expected == math.floor(response.t[-1] * fps / speed + 1e-9) + 1 == 11
    assert im.n_frames == expected
    assert im.size == (320, 240)
    # the body is drawn (its stone colour) and moves: the first and the peak frames differ
    frames = []
    for k in (0, expected // 2):
        im.seek(k)
        frames.append(np.asarray(im.convert("RGB"), dtype=float))
    r, g, b = frames[0][..., 0], frames[0][..., 1], frames[0][..., 2]
    stone = (r - b > 40) & (r > g)
    assert stone.mean() > 0.01
    assert np.abs(frames[0] - frames[1]).mean() > 1.0


def test_gif_refusals(response, tmp_path):
    with pytest.raises(ParameterError, match="path"):
        animate(response, tmp_path / "box.avi")
    with pytest.raises(ParameterError, match="fps"):
        animate(response, tmp_path / "box.gif", fps=0)
    with pytest.raises(ParameterError, match="fps"):
        animate(response, tmp_path / "box.gif", fps=1000, max_frames=100)
    planar = rocking.simulate(rocking.specimen(2), theta0=0.01, duration=0.2)
    with pytest.raises(ParameterError, match="response: a 3-D view needs"):
        animate(planar, tmp_path / "planar.gif")
    with pytest.raises(ParameterError, match="response"):
        write_html(planar, tmp_path / "planar.html")


# ------------------------------------------------------------------------- the page
def test_page_is_self_contained(page):
    text = page.read_text("utf-8")
    # nothing loaded from anywhere: no src/href on script, link, img, iframe
    assert not re.findall(r"<(?:script|link|img|iframe|source)\b[^>]*\b(?:src|href)\s*=",
                          text, re.I)
    assert not re.findall(r"@import|url\(\s*['\"]?https?:", text, re.I)
    # three.js and its controls are inlined, as vendored
    for name in ("three.min.js", "OrbitControls.js"):
        assert (VENDOR / name).read_text("utf-8") in text
    assert page.stat().st_size < 1_000_000


def test_vendored_files_are_the_ones_the_readme_names():
    readme = (VENDOR / "README.md").read_text("utf-8")
    assert "three@0.147.0" in readme and (VENDOR / "LICENSE").read_text().startswith(
        "The MIT License")
    for name in ("three.min.js", "OrbitControls.js"):
        digest = hashlib.sha256((VENDOR / name).read_bytes()).hexdigest()
        assert digest in readme, f"{name}: sha256 {digest} not in vendor/three/README.md"


def test_page_round_trips_the_response(response, page, box):
    data = read_page_data(page)
    idx = frame_indices(len(response.t), response.t[1] - response.t[0], 50)
    assert idx[-1] == len(response.t) - 1 and len(data["t"]) == len(idx)
    names = list(response.state_names)
    cols = [names.index(n) for n in ("x", "y", "z")]
    qcols = [names.index(n) for n in ("q0", "q1", "q2", "q3")]
    np.testing.assert_allclose(data["t"], response.t[idx], atol=1e-9)
    np.testing.assert_allclose(np.reshape(data["pos"], (-1, 3)),
                               response.states[idx][:, cols], atol=1e-7)
    q = response.states[idx][:, qcols]
    np.testing.assert_allclose(np.reshape(data["quat"], (-1, 4)),
                               q / np.linalg.norm(q, axis=1)[:, None], atol=1e-8)
    np.testing.assert_allclose(data["tilt"], tilt(q), atol=1e-8)
    # the mesh: the box's 8 corners about its centre of mass
    v = np.reshape(data["vertices"], (-1, 3))
    corners = box.local_vertices - [0.0, 0.0, box.h]
    np.testing.assert_allclose(np.unique(np.round(v, 6), axis=0),
                               np.unique(np.round(corners, 6), axis=0), atol=1e-6)
    np.testing.assert_allclose(corners.min(axis=0), [-0.2, -0.2, -0.6], atol=1e-12)
    assert len(data["faces"]) == 3 * 12 and data["ground"] is None


def test_page_with_the_ground(response, tmp_path):
    data = read_page_data(write_html(response, tmp_path / "g.html", ground=True, fps=25))
    g = np.reshape(data["ground"], (-1, 3))
    t = np.asarray(data["t"])
    d = math.radians(DIRECTION)
    np.testing.assert_allclose(g[:, 0], X * np.sin(2 * math.pi * F * t) * math.cos(d),
                               atol=2e-5 * X)


def test_big_meshes_are_decimated_for_the_page():
    statue = rocking.shapes.load_example()
    v, f = decimate(statue.local_vertices, statue.faces, 1000)
    assert len(f) <= 1000 and len(f) > 300
    assert f.min() >= 0 and f.max() == len(v) - 1
    # the outline is kept to the clustering cell: the bounding box within a few percent
    np.testing.assert_allclose(v.min(axis=0), statue.local_vertices.min(axis=0),
                               atol=0.05 * statue.height)
    np.testing.assert_allclose(v.max(axis=0), statue.local_vertices.max(axis=0),
                               atol=0.05 * statue.height)
    with pytest.raises(ParameterError, match="max_faces"):
        decimate(statue.local_vertices, statue.faces, 2)


# ------------------------------------------------------------------------- in a browser
def chromium() -> str | None:
    for name in ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable",
                 "chrome", "headless_shell"):
        path = shutil.which(name)
        if path:
            return path
    return None


CHROMIUM_FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader",
                  "--enable-unsafe-swiftshader", "--hide-scrollbars",
                  "--virtual-time-budget=4000")


@pytest.mark.skipif(chromium() is None, reason="no chromium binary (chromium, "
                    "chromium-browser, google-chrome) on PATH: the page is not rendered")
def test_page_renders_in_headless_chromium(response, page, tmp_path):
    """The page, opened paused at the peak tilt (``#t=``), starts WebGL (``data-ready``),
    shows that time and the tilt there, and draws the body (its stone colour) over the
    ground; opened plainly, it plays."""
    sc = scene(response)
    tl = tilt(sc.quaternion)
    t_peak = float(sc.t[np.argmax(tl)])
    url = f"{page.resolve().as_uri()}#t={t_peak}"
    dom = subprocess.run([chromium(), *CHROMIUM_FLAGS, "--dump-dom", url],
                         capture_output=True, text=True, timeout=180).stdout
    assert 'data-ready="1"' in dom, dom[:600]
    assert f'data-t="{t_peak:.6f}"' in dom
    data = read_page_data(page)  # the page interpolates its frames linearly
    expected = math.degrees(np.interp(t_peak, data["t"], data["tilt"]))
    shown = re.search(r"tilt = ([0-9.]+) deg", dom)
    assert shown and float(shown.group(1)) == pytest.approx(expected, abs=0.006)
    assert expected == pytest.approx(math.degrees(tl.max()), rel=0.01)
    # without '#t=' the page plays: its time has advanced once loaded
    dom = subprocess.run([chromium(), *CHROMIUM_FLAGS, "--dump-dom", page.resolve().as_uri()],
                         capture_output=True, text=True, timeout=180).stdout
    played = re.search(r'data-t="([0-9.]+)"', dom)
    assert 'data-ready="1"' in dom and played and float(played.group(1)) > 0.0
    shot = tmp_path / "shot.png"
    subprocess.run([chromium(), *CHROMIUM_FLAGS, "--window-size=800,600",
                    f"--screenshot={shot}", url], capture_output=True, timeout=180)
    img = np.asarray(Image.open(shot).convert("RGB"), dtype=float)
    assert img.shape[:2] == (600, 800)
    assert img.std() > 10  # not blank
    r, g, b = img[..., 0], img[..., 1], img[..., 2]
    stone = (r - b > 40) & (r > g) & (g > b)
    assert stone.mean() > 0.01, stone.mean()


def test_mp4_needs_ffmpeg(response, tmp_path):
    """An MP4 is written where ffmpeg exists, refused naming ``path`` where it does not."""
    from matplotlib.animation import FFMpegWriter

    if FFMpegWriter.isAvailable():
        path = animate(response, tmp_path / "box.mp4", fps=5)
        assert path.stat().st_size > 1000
    else:
        with pytest.raises(ParameterError, match="path: .*ffmpeg"):
            animate(response, tmp_path / "box.mp4", fps=5)


def test_a_rectangular_block_is_drawn_as_the_models_box(tmp_path):
    """A run given a rectangular Block draws the box the model made of it."""
    block = rocking.Block.rectangular(0.3, 1.0)
    r = rocking.simulate(block, Sine(freq=F, amplitude=0.001, duration=0.2),
                         model="rigid3d", duration=0.2)
    v = np.reshape(read_page_data(write_html(r, tmp_path / "b.html"))["vertices"], (-1, 3))
    np.testing.assert_allclose(v.max(axis=0) - v.min(axis=0), [0.3, 0.3, 1.0], atol=1e-7)


def test_ground_of_a_run_shorter_than_its_motion(box):
    """A run that stops before its motion ends (an explicit duration, or an overturn)
    still sees the motion's ground displacement: the initial velocity comes from the whole
    motion, not from the part that was run."""
    r = rocking.simulate(box, Sine(freq=F, amplitude=0.001, duration=2.0), model="rigid3d",
                         duration=0.3)
    sc = scene(r, ground=True)
    np.testing.assert_allclose(sc.ground[:, 0], 0.001 * np.sin(2 * math.pi * F * sc.t),
                               atol=2e-5 * 0.001)
