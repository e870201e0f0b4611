"""``rocking shape MESH``: the mass properties and the directional table of a 3-D mesh on
the command line (issue 20).

Expected values are closed forms (a box: alpha = atan(b/h), its mass and principal
moments), the divergence-theorem reference of :mod:`rocking.testing.mesh_reference`
(independent of trimesh and of :mod:`rocking.shapes`), and :mod:`rocking.shapes`' own
values for the example statue (the command must print what the library computes)."""

from __future__ import annotations

import json
import math
import re

import numpy as np
import pandas as pd
import pytest
import trimesh
from cli_helpers import assert_one_line_error, run_main

from rocking.shapes import COLUMNS, example_mesh_path, load_example, weakest_direction
from rocking.testing import mesh_reference as ref
from rocking.units import G

A, B, C, RHO = 0.5, 0.25, 1.25, 2000.0  # a box (m; exact in the files float32)


def write_mesh(path, vertices, faces):
    trimesh.Trimesh(vertices, faces, process=False).export(path)
    return path


@pytest.fixture(scope="module")
def box_ply(tmp_path_factory):
    return write_mesh(tmp_path_factory.mktemp("box") / "box.ply", *ref.box(A, B, C))


def printed(out: str, which: str) -> dict:
    """``phi_deg``, ``alpha`` (rad) and ``uplift`` (m/s^2) of the line ``which:``."""
    m = re.search(rf"^{which}:\s+phi = (\S+) deg, side ([+-])[^:]*: alpha = (\S+) rad .*uplift "
                  r"(\S+) m/s\^2", out, re.M)
    assert m, out
    return {"phi_deg": float(m[1]), "side": m[2], "alpha": float(m[3]),
            "uplift": float(m[4])}


def test_the_example_prints_rocking_shapes_weakest_direction(capsys):
    code, out, err = run_main(capsys, "shape", example_mesh_path(), "--density", "2600")
    assert code == 0, err
    sh = load_example(density=2600.0)
    weak = sh.weakest()
    w = printed(out, "weakest")
    assert math.isclose(w["alpha"], weak.alpha, rel_tol=1e-9)
    assert math.isclose(w["phi_deg"], weak.phi_deg, abs_tol=1e-4)
    assert w["side"] == weak.side
    assert math.isclose(w["uplift"], G * math.tan(weak.alpha), rel_tol=1e-5)
    # the mass line is the library's mass; the table every 15 deg has 24 rows
    m = re.search(r"^mass\s+(\S+) kg", out, re.M)
    assert math.isclose(float(m[1]), sh.mass, rel_tol=1e-5)
    rows = [ln for ln in out.splitlines() if re.match(r"^\s+\d+\.\d\s", ln)]
    assert [float(r.split()[0]) for r in rows] == [15.0 * k for k in range(24)]


def test_a_box_prints_its_closed_forms(capsys, box_ply):
    """Mass, principal moments, alpha of the weakest (across the narrow side) and of the
    strongest direction (along the diagonal) of a box, against closed forms; the table's
    phi = 0 row is Eqs 2 and 4 with b = A/2."""
    code, out, err = run_main(capsys, "shape", box_ply, "--density", f"{RHO}", "--json")
    assert code == 0, err
    d = json.loads(out)
    m = RHO * A * B * C
    assert math.isclose(d["mass"], m, rel_tol=1e-12)
    assert math.isclose(d["volume"], A * B * C, rel_tol=1e-12)
    expected = sorted([m * (B * B + C * C) / 12, m * (A * A + C * C) / 12,
                       m * (A * A + B * B) / 12])
    assert np.allclose(d["principal_moments"], expected, rtol=1e-9)
    assert math.isclose(d["weakest"]["alpha"], math.atan(B / C), rel_tol=1e-9)
    assert math.isclose(d["weakest"]["uplift"], G * B / C, rel_tol=1e-9)
    # the strongest: the support function (A/2)|cos phi| + (B/2)|sin phi| is largest, the
    # half-diagonal, at tan(phi) = B/A (the bounded search refines the 0.1 deg grid)
    assert math.isclose(d["strongest"]["alpha"], math.atan(math.hypot(A, B) / C),
                        rel_tol=1e-9)
    assert math.isclose(math.tan(d["strongest"]["phi"]), B / A, rel_tol=1e-4)
    assert len(d["directions"]) == 360
    row0 = d["directions"][0]
    assert row0["phi"] == 0.0
    assert math.isclose(row0["alpha_plus"], math.atan(A / C), rel_tol=1e-9)
    assert math.isclose(row0["mu_plus"], 1 - 1.5 * math.sin(math.atan(A / C)) ** 2,
                        rel_tol=1e-9)


def test_mass_properties_agree_with_the_divergence_theorem(capsys):
    """The example statue's printed mass, centre of mass and principal moments against the
    independent reference (exact quadrature over the triangles)."""
    sh = load_example(density=2600.0)
    r = ref.mass_properties(np.asarray(sh.vertices), np.asarray(sh.faces), density=2600.0)
    code, out, err = run_main(capsys, "shape", example_mesh_path(), "--density", "2600",
                              "--json", "--directions", "36")
    assert code == 0, err
    d = json.loads(out)
    assert math.isclose(d["mass"], r["volume"] * 2600.0, rel_tol=1e-9)
    assert np.allclose(d["com"], r["com"], rtol=0, atol=1e-9)
    assert np.allclose(d["principal_moments"], np.linalg.eigvalsh(r["inertia"]), rtol=1e-9)
    # the strongest direction is at least as strong as every tabulated one, the weakest
    # at most as strong
    up = np.array([min(x["uplift_plus"], x["uplift_minus"]) for x in d["directions"]])
    assert d["weakest"]["uplift"] <= up.min() * (1 + 1e-12)
    assert d["strongest"]["uplift"] >= up.max() * (1 - 1e-12)


def test_a_given_mass_and_the_output_folder(capsys, tmp_path):
    out_dir = tmp_path / "out"
    code, out, err = run_main(capsys, "shape", example_mesh_path(), "--mass", "900kg",
                              "--directions", "72", "--out", out_dir)
    assert code == 0, err
    table = pd.read_csv(out_dir / "directions.csv")
    assert list(table.columns) == list(COLUMNS) and len(table) == 72
    assert np.allclose(table["phi_deg"], 5.0 * np.arange(72))
    assert (out_dir / "polar.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    saved = json.loads((out_dir / "shape.json").read_text())
    assert math.isclose(saved["mass"], 900.0, rel_tol=1e-12)
    # alpha does not depend on the mass; the sampled weakest of the CSV is no weaker than
    # the exact one
    exact = load_example(density=2600.0).weakest()
    assert math.isclose(saved["weakest"]["alpha"], exact.alpha, rel_tol=1e-9)
    assert weakest_direction(table).uplift >= exact.uplift * (1 - 1e-12)


@pytest.mark.parametrize("args,name", [
    (["--density", "2600", "--mass", "900"], "density"),
    ([], "density"),
    (["--density", "-1"], "density"),
    (["--density", "2600", "--directions", "0"], "directions"),
    (["--density", "2600", "--up", "w"], "up"),
])
def test_bad_flags_are_one_line(capsys, args, name):
    code, _, err = run_main(capsys, "shape", example_mesh_path(), *args)
    assert_one_line_error(code, err, name)


def test_bad_meshes_are_one_line(capsys, tmp_path):
    code, _, err = run_main(capsys, "shape", tmp_path / "missing.stl", "--density", "2600")
    assert_one_line_error(code, err, "does not exist")
    v, f = ref.box(A, B, C)
    open_box = write_mesh(tmp_path / "open.ply", v, f[1:])
    code, _, err = run_main(capsys, "shape", open_box, "--density", "2600")
    assert_one_line_error(code, err, "not watertight")
    # --repair hull accepts it, with a one-line warning saying the volume added
    code, out, err = run_main(capsys, "shape", open_box, "--density", "2600", "--repair",
                              "hull", "--json")
    assert code == 0 and "warning:" in err and "Traceback" not in err
    assert math.isclose(json.loads(out)["volume"], A * B * C, rel_tol=1e-9)


def test_weakest_is_one_direction_in_the_api_the_block_the_command_and_its_plot(
        capsys, tmp_path):
    """Issue 31 item 3: weakest_direction (sampled), Shape.weakest (exact),
    Block.from_mesh(direction="weakest"), ``rocking shape`` (text, JSON) and its polar plot
    name the same direction, by the phi whose "+" side is the weak one (the statue's weak
    side is "-" at the first sampled minimum, 74 deg: the mirror of 254.4 deg)."""
    import rocking
    from rocking.shapes import directional_parameters, strongest_direction

    sh = load_example(density=2600.0)
    exact = sh.weakest()
    tab = directional_parameters(sh, 360)
    sampled = weakest_direction(tab)
    assert sampled.side == exact.side == "+"
    gap = abs((sampled.phi_deg - exact.phi_deg + 180.0) % 360.0 - 180.0)
    assert gap <= 1.0, (sampled.phi_deg, exact.phi_deg)  # same phi, not its mirror
    row = tab.loc[sampled.index]  # the row at the named phi, its "+" side the weak one
    assert math.isclose(row["phi"], sampled.phi) and row["alpha_plus"] == sampled.alpha
    assert row["uplift_plus"] <= row["uplift_minus"]
    blk = rocking.Block.from_mesh(example_mesh_path(), density=2600.0, direction="weakest")
    assert math.isclose(blk.alpha_plus, exact.alpha, rel_tol=1e-12)
    assert blk.alpha_plus <= blk.alpha_minus
    strong = strongest_direction(tab)
    assert strong.side == "+" and tab.loc[strong.index, "alpha_plus"] == strong.alpha
    code, out, err = run_main(capsys, "shape", example_mesh_path(), "--density", "2600",
                              "--out", str(tmp_path))
    assert code == 0, err
    w = printed(out, "weakest")
    assert w["side"] == "+" and math.isclose(w["phi_deg"], exact.phi_deg, abs_tol=1e-4)
    assert printed(out, "strongest")["side"] == "+"
    js = json.loads((tmp_path / "shape.json").read_text())
    assert js["weakest"]["side"] == js["strongest"]["side"] == "+"
    assert math.isclose(js["weakest"]["phi_deg"], exact.phi_deg, abs_tol=1e-9)
    # the plot of that run marks the same direction (its label and its marker)
    from rocking.shapes import plot_directional

    fig = plot_directional(tab, weakest=exact)
    marks = [ln for ln in fig.axes[1].lines if len(ln.get_xdata()) == 1]
    assert math.isclose(marks[0].get_xdata()[0], exact.phi)
    assert f"{exact.phi_deg:.1f} deg, side +" in marks[0].get_label()
    fig = plot_directional(tab)  # the table's own: the same phi within its sampling
    marks = [ln for ln in fig.axes[1].lines if len(ln.get_xdata()) == 1]
    assert abs((math.degrees(marks[0].get_xdata()[0]) - exact.phi_deg + 180) % 360 - 180) <= 1
