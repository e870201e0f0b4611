"""Peers of the 3-D rigid body (issue 30; a validation script, not CI): the same scenes in
``model="rigid3d"`` and in independent codes, with a table of the differences and figures.

Peers
-----
* **MuJoCo** (``pip install mujoco``; the extra ``peers``): compliant contact (a soft
  constraint with a time constant and a damping ratio, ``solref``; Todorov 2014), run with
  its default ``solref = (0.02, 1)`` and with a stiffer ``(0.002, 1)``;
* **PyBullet** (``pip install pybullet``; the extra ``peers``): rigid contact by sequential
  impulses with a Baumgarte position correction (ERP) and a restitution coefficient (0);
* **Siconos** (Debian's ``python3-siconos``, the system ``python3`` only: not on pip):
  non-smooth contact dynamics (Moreau-Jean, Newton's impact law, Coulomb cone), the same
  family as ``rigid3d``; run by ``peers_siconos.py`` in a subprocess, skipped if absent.

Every code runs at the same step, 1e-4 s, with the box's exact mass and inertia; a moving
ground is the inertial force ``-m a_g(t)`` on the body in the ground's frame (exact for a
translating ground). Scenes (box ``0.25 x 0.5 x 1 m``, 2500 kg/m^3, unless stated):

1. ``free``: free rocking in the planar limit from a tilt of alpha/2 about y (friction 2,
   restitution 0): the restitution of each impact measured from successive peaks,
   ``r_n^2 = (cos(alpha - th_n+1) - cos alpha) / (cos(alpha - th_n) - cos alpha)`` (the
   energy after an impact over the energy before), against Housner's Eq 4,
   ``mu = 1 - 1.5 sin^2 alpha``;
2. ``sine``: a sine along x, 2 Hz, 1.5 g tan(alpha), 3 s (friction 2): the tilt's history;
3. ``slide``: a squat box ``1 x 0.8 x 0.2 m`` under a constant 0.5 g along x with friction
   0.3: the slide relative to the ground against ``(a - mu g) t^2 / 2``;
4. ``drop``: the box ``0.4 x 0.3 x 0.6 m`` dropped flat from 5 cm (restitution 0): the
   rebound, the sink into the ground at rest and the time to rest.

Run::

    .venv/bin/pip install -e .[peers]      # mujoco, pybullet
    apt-get install -y python3-siconos     # optional
    .venv/bin/python benchmarks/peers_rigid3d.py --out docs/_static/peers_rigid3d

It writes ``peers.csv`` and ``peers.md`` (one row per scene and code) and one figure per
scene (``free.png``, ``sine.png``, ``slide.png``, ``drop.png``); ``--calibration`` writes
MuJoCo's restitution against its contact parameters (``calibration.png``, ``.csv``).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import tempfile
import time
from dataclasses import dataclass, field

import numpy as np

import rocking
from rocking import G
from rocking.models.rigid3d import rest_state
from rocking.motions import Rectangular, Sine
from rocking.shapes import Shape

STEP = 1e-4
DT_OUT = 1e-3
SICONOS_PYTHON = "/usr/bin/python3"


@dataclass
class Scene:
    name: str
    size: tuple
    duration: float
    friction: float
    motion: object = None
    tilt0: float = 0.0
    drop: float = 0.0
    density: float = 2500.0
    label: str = ""
    extra: dict = field(default_factory=dict)

    @property
    def shape(self):
        return Shape.box(*self.size, density=self.density)

    def acc(self, t):
        """The ground's acceleration along x (m/s^2) at the times ``t``."""
        if self.motion is None:
            return np.zeros_like(np.asarray(t, dtype=float))
        return np.asarray(self.motion.acceleration(np.asarray(t, dtype=float)), float)

    def state0(self):
        y = rest_state(self.shape, self.tilt0, 0.0)
        y[2] += self.drop
        return y


def scenes() -> list[Scene]:
    lx, ly, lz = 0.25, 0.5, 1.0
    alpha = math.atan(lx / lz)
    sine = Sine.from_acceleration(freq=2.0, acc_amplitude=1.5 * G * math.tan(alpha),
                                  duration=3.0)
    return [
        Scene("free", (lx, ly, lz), 3.0, 2.0, tilt0=0.5 * alpha,
              label="free rocking from alpha/2"),
        Scene("sine", (lx, ly, lz), 3.0, 2.0, motion=sine,
              label="sine 2 Hz, 1.5 g tan(alpha)"),
        Scene("slide", (1.0, 0.8, 0.2), 1.0, 0.3, motion=Rectangular(0.5 * G, 1.0),
              label="constant 0.5 g, friction 0.3"),
        Scene("drop", (0.4, 0.3, 0.6), 0.6, 0.7, drop=0.05, density=2000.0,
              label="dropped flat from 5 cm"),
    ]


# ================================================================ the codes
def run_ours(sc: Scene):
    r = rocking.simulate(sc.shape, sc.motion, model="rigid3d", duration=sc.duration,
                         state0=sc.state0(), friction=sc.friction, restitution=0.0,
                         step=STEP, dt_out=DT_OUT)
    n = len(r.t)
    t = np.arange(n) * DT_OUT
    return t, r.states[:, :3], r.states[:, 3:7]


def run_mujoco(sc: Scene, solref=(0.02, 1.0)):
    import mujoco

    lx, ly, lz = sc.size
    m = sc.shape.mass
    ref = f"{solref[0]} {solref[1]}"
    xml = f"""<mujoco><option timestep="{STEP}" gravity="0 0 {-G}" cone="elliptic"
      integrator="implicitfast"/>
      <worldbody><geom type="plane" size="20 20 0.1" friction="{sc.friction} 0 0"
        solref="{ref}"/>
      <body name="box"><freejoint/><geom type="box" size="{lx/2} {ly/2} {lz/2}" mass="{m}"
        friction="{sc.friction} 0 0" solref="{ref}"/></body></worldbody></mujoco>"""
    model = mujoco.MjModel.from_xml_string(xml)
    data = mujoco.MjData(model)
    y0 = sc.state0()
    data.qpos[:3] = y0[:3]
    data.qpos[3:7] = y0[3:7]
    mujoco.mj_forward(model, data)
    bid = model.body("box").id
    n = int(round(sc.duration / STEP))
    every = int(round(DT_OUT / STEP))
    acc = sc.acc(np.arange(n) * STEP + 0.5 * STEP)
    pos, quat = [data.qpos[:3].copy()], [data.qpos[3:7].copy()]
    for k in range(n):
        data.xfrc_applied[bid, 0] = -m * acc[k]
        mujoco.mj_step(model, data)
        if (k + 1) % every == 0:
            pos.append(data.qpos[:3].copy())
            quat.append(data.qpos[3:7].copy())
    return np.arange(len(pos)) * DT_OUT, np.array(pos), np.array(quat)


def run_pybullet(sc: Scene):
    import pybullet as p

    cid = p.connect(p.DIRECT)
    try:
        p.setGravity(0, 0, -G, physicsClientId=cid)
        p.setPhysicsEngineParameter(fixedTimeStep=STEP, numSubSteps=0,
                                    numSolverIterations=50, physicsClientId=cid)
        plane = p.createMultiBody(0, p.createCollisionShape(p.GEOM_PLANE,
                                                            physicsClientId=cid),
                                  physicsClientId=cid)
        lx, ly, lz = sc.size
        m = sc.shape.mass
        y0 = sc.state0()
        col = p.createCollisionShape(p.GEOM_BOX, halfExtents=[lx / 2, ly / 2, lz / 2],
                                     physicsClientId=cid)
        box = p.createMultiBody(m, col, basePosition=list(y0[:3]),
                                baseOrientation=[y0[4], y0[5], y0[6], y0[3]],
                                physicsClientId=cid)
        # Bullet combines the two bodies' friction (and restitution) by their product:
        # the plane's 1 leaves the box's as the pair's
        for b, mu in ((plane, 1.0), (box, sc.friction)):
            p.changeDynamics(b, -1, lateralFriction=mu, restitution=0.0,
                             rollingFriction=0.0, spinningFriction=0.0,
                             physicsClientId=cid)
        n = int(round(sc.duration / STEP))
        every = int(round(DT_OUT / STEP))
        acc = sc.acc(np.arange(n) * STEP + 0.5 * STEP)
        pos, quat = [y0[:3].copy()], [y0[3:7].copy()]
        for k in range(n):
            if acc[k] != 0.0:
                com, _ = p.getBasePositionAndOrientation(box, physicsClientId=cid)
                p.applyExternalForce(box, -1, [-m * acc[k], 0, 0], com, p.WORLD_FRAME,
                                     physicsClientId=cid)
            p.stepSimulation(physicsClientId=cid)
            if (k + 1) % every == 0:
                x, q = p.getBasePositionAndOrientation(box, physicsClientId=cid)
                pos.append(x)
                quat.append([q[3], q[0], q[1], q[2]])
        return np.arange(len(pos)) * DT_OUT, np.array(pos), np.array(quat)
    finally:
        p.disconnect(cid)


def run_siconos(sc: Scene):
    here = os.path.dirname(os.path.abspath(__file__))
    y0 = sc.state0()
    n = int(round(sc.duration / STEP))
    spec = {"lx": sc.size[0], "ly": sc.size[1], "lz": sc.size[2], "mass": sc.shape.mass,
            "pos": y0[:3].tolist(), "quat": y0[3:7].tolist(), "friction": sc.friction,
            "restitution": 0.0, "step": STEP, "duration": sc.duration, "dt_out": DT_OUT,
            "acc_x": sc.acc(np.arange(n) * STEP + STEP).tolist()}
    with tempfile.TemporaryDirectory() as tmp:
        src, out = os.path.join(tmp, "scene.json"), os.path.join(tmp, "out.npz")
        with open(src, "w") as fh:
            json.dump(spec, fh)
        subprocess.run([SICONOS_PYTHON, os.path.join(here, "peers_siconos.py"), src, out],
                       check=True, capture_output=True, timeout=1800)
        d = np.load(out)
        return d["t"], d["pos"], d["quat"]


def siconos_available() -> bool:
    try:
        subprocess.run([SICONOS_PYTHON, "-c", "import siconos.mechanics.collision.bullet"],
                       check=True, capture_output=True, timeout=60)
        return True
    except (OSError, subprocess.SubprocessError):
        return False


def codes(siconos: bool) -> list:
    out = [("rigid3d", run_ours)]
    try:
        import mujoco  # noqa: F401

        out += [("MuJoCo solref 0.02", run_mujoco),
                ("MuJoCo solref 0.002", lambda sc: run_mujoco(sc, (0.002, 1.0)))]
    except ImportError:
        print("MuJoCo is not installed (pip install mujoco): skipped")
    try:
        import pybullet  # noqa: F401

        out.append(("PyBullet", run_pybullet))
    except ImportError:
        print("PyBullet is not installed (pip install pybullet): skipped")
    if siconos:
        out.append(("Siconos", run_siconos))
    else:
        print("Siconos is not available (apt-get install python3-siconos): skipped")
    return out


# ================================================================ what is measured
def tilt_of(quat):
    """The angle (rad) of the body's up axis from the vertical."""
    q = np.asarray(quat)
    q = q / np.linalg.norm(q, axis=1)[:, None]
    return 2.0 * np.arcsin(np.clip(np.hypot(q[:, 1], q[:, 2]), 0.0, 1.0))


def rocking_peaks(t, tilt, alpha):
    """The peaks of |tilt| between impacts (local maxima above 2 % of alpha)."""
    from scipy.signal import find_peaks

    k, _ = find_peaks(tilt, height=0.02 * alpha, prominence=0.01 * alpha)
    return t[k], tilt[k]


def metrics(sc: Scene, t, pos, quat, ref=None) -> dict:
    tilt = tilt_of(quat)
    out = {"scene": sc.name, "max_tilt_rad": float(tilt.max())}
    if sc.name == "free":
        alpha = math.atan(sc.size[0] / sc.size[2])
        _, th = rocking_peaks(t, tilt, alpha)
        th = np.concatenate([[sc.tilt0], th])
        e = (np.cos(alpha - th) - math.cos(alpha))
        r = np.sqrt(e[1:] / e[:-1])
        mu = 1.0 - 1.5 * math.sin(alpha) ** 2
        out.update({"housner_mu": mu, "r_first3": float(np.mean(r[:3])) if len(r) else np.nan,
                    "r_first3_vs_mu_pct": 100 * (float(np.mean(r[:3])) / mu - 1)
                    if len(r) else np.nan, "peaks_in_3s": int(len(th) - 1)})
    if sc.name == "sine" and ref is not None:
        n = min(len(tilt), len(ref))
        out["rms_tilt_diff_rad"] = float(np.sqrt(np.mean((tilt[:n] - ref[:n]) ** 2)))
        up = np.flatnonzero(tilt > 1e-3)
        out["uplift_time_s"] = float(t[up[0]]) if len(up) else np.nan
    if sc.name == "slide":
        a, mu = 0.5 * G, sc.friction
        exact = -0.5 * (a - mu * G) * t[-1] ** 2
        out["slide_end_m"] = float(pos[-1, 0] - pos[0, 0])
        out["slide_exact_m"] = exact
        out["slide_err_pct"] = 100 * (out["slide_end_m"] / exact - 1)
    if sc.name == "drop":
        z = pos[:, 2]
        v = np.diff(z) / DT_OUT
        fall = np.flatnonzero(v < -0.5)
        land = fall[-1] + 1 if len(fall) else 0  # the end of the fall: the landing
        out["landing_speed_m_s"] = float(-v[:land].min()) if land else np.nan
        out["rebound_speed_m_s"] = float(max(v[land:].max(), 0.0))
        out["rebound_mm"] = float(1e3 * max(z[land + 2:].max() - z[-1], 0.0))
        out["max_sink_mm"] = float(1e3 * (sc.size[2] / 2 - z.min()))
        out["sink_at_rest_mm"] = float(1e3 * (sc.size[2] / 2 - z[-1]))
        moving = np.flatnonzero(np.abs(v) > 1e-3)
        out["time_to_rest_s"] = float(t[moving[-1] + 1]) if len(moving) else 0.0
    return out


# ================================================================ figures and tables
def figure(sc: Scene, runs: dict, path: str):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    if sc.name == "drop":
        fig, (ax, zoom) = plt.subplots(1, 2, figsize=(10, 3.6),
                                       gridspec_kw={"width_ratios": [1, 1.3]})
        for name, (t, pos, _) in runs.items():
            style = dict(lw=2.2 if name == "rigid3d" else 1.2,
                         ls="-" if name in ("rigid3d", "Siconos") else "--")
            for a in (ax, zoom):
                a.plot(t, 1e3 * (pos[:, 2] - sc.size[2] / 2), label=name, **style)
        zoom.set_xlim(0.09, 0.32)
        zoom.set_ylim(-0.25, 0.5)
        zoom.set_title("the landing, zoomed (0 = resting on the plane)", fontsize=9)
        ax.set_ylabel("height of the base (mm)")
        for a in (ax, zoom):
            a.set_xlabel("time (s)")
            a.grid(alpha=0.3)
        zoom.legend(fontsize=8, ncol=2)
        ax.set_title(f"{sc.name}: {sc.label}")
        fig.tight_layout()
        fig.savefig(path, dpi=110)
        plt.close(fig)
        return
    fig, ax = plt.subplots(figsize=(8, 3.6))
    for name, (t, pos, quat) in runs.items():
        style = dict(lw=2.2 if name == "rigid3d" else 1.2,
                     ls="-" if name in ("rigid3d", "Siconos") else "--")
        if sc.name == "slide":
            ax.plot(t, 1e3 * (pos[:, 0] - pos[0, 0]), label=name, **style)
            ax.set_ylabel("slide along x (mm)")
        elif sc.name == "drop":
            ax.plot(t, 1e3 * (pos[:, 2] - sc.size[2] / 2), label=name, **style)
            ax.set_ylabel("height of the base (mm)")
        else:
            ax.plot(t, tilt_of(quat), label=name, **style)
            ax.set_ylabel("tilt (rad)")
    if sc.name == "slide":
        t = runs["rigid3d"][0]
        ax.plot(t, -1e3 * 0.5 * (0.5 * G - sc.friction * G) * t**2, "k:", lw=1,
                label="(a - mu g) t^2 / 2")
    if sc.name == "drop":
        ax.set_ylim(-2.0, 55.0)
    ax.set_xlabel("time (s)")
    ax.set_title(f"{sc.name}: {sc.label}")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, ncol=2)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def write_tables(rows: list, out: str):
    import pandas as pd

    df = pd.DataFrame(rows)
    df.to_csv(os.path.join(out, "peers.csv"), index=False, float_format="%.6g")
    with open(os.path.join(out, "peers.md"), "w") as fh:
        for name, g in df.groupby("scene", sort=False):
            g = g.dropna(axis=1, how="all")
            fh.write(f"### {name}\n\n")
            cols = list(g.columns)
            fh.write("| " + " | ".join(cols) + " |\n|" + "---|" * len(cols) + "\n")
            for _, r in g.iterrows():
                fh.write("| " + " | ".join(f"{v:.4g}" if isinstance(v, float) else str(v)
                                           for v in r) + " |\n")
            fh.write("\n")
    return df


def calibration(out: str, timeconsts=(0.04, 0.02, 0.01, 0.005, 0.002, 0.001, 5e-4),
                dampratios=(1.0, 0.5, 0.2)) -> list:
    """MuJoCo's restitution of the free rocking scene against its contact time constant and
    damping ratio (``solref``): what a compliant code must calibrate, where rigid3d's Eq 4
    has no parameter. Writes ``calibration.csv`` and ``calibration.png``."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    sc = scenes()[0]
    sc.duration = 1.6
    mu = 1.0 - 1.5 * math.sin(math.atan(sc.size[0] / sc.size[2])) ** 2
    rows = []
    for zeta in dampratios:
        for tc in timeconsts:
            if tc < 2 * STEP:
                continue
            m = metrics(sc, *run_mujoco(sc, (tc, zeta)))
            rows.append({"timeconst_s": tc, "dampratio": zeta, "r_first3": m["r_first3"],
                         "r_vs_mu_pct": 100 * (m["r_first3"] / mu - 1)})
    ours = metrics(sc, *run_ours(sc))["r_first3"]
    fig, ax = plt.subplots(figsize=(6.5, 3.6))
    for zeta in dampratios:
        pts = [(r["timeconst_s"], r["r_first3"]) for r in rows if r["dampratio"] == zeta]
        xs, ys = np.array(pts).T
        ax.semilogx(xs, ys, "o-", label=f"MuJoCo, damping ratio {zeta:g}")
    ax.axhline(mu, color="k", lw=1, ls=":", label=f"Housner Eq 4, mu = {mu:.4f}")
    ax.axhline(ours, color="C3", lw=2, alpha=0.6, label=f"rigid3d (no parameter): {ours:.4f}")
    ax.set_xlabel("MuJoCo contact time constant, solref[0] (s)")
    ax.set_ylabel("restitution of the first impacts")
    ax.set_title("free rocking: the restitution a compliant contact gives")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "calibration.png"), dpi=110)
    plt.close(fig)
    import pandas as pd

    pd.DataFrame(rows).to_csv(os.path.join(out, "calibration.csv"), index=False,
                              float_format="%.6g")
    return rows


def _children_cpu() -> float:
    t = os.times()
    return t.children_user + t.children_system


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="peers_rigid3d_out", help="output folder")
    ap.add_argument("--scenes", nargs="*", default=None, help="scene names (default all)")
    ap.add_argument("--no-siconos", action="store_true", help="skip Siconos")
    ap.add_argument("--calibration", action="store_true",
                    help="only MuJoCo's restitution against solref (calibration.png)")
    args = ap.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    if args.calibration:
        for r in calibration(args.out):
            print(r)
        return
    runners = codes(not args.no_siconos and siconos_available())
    rows = []
    for sc in scenes():
        if args.scenes and sc.name not in args.scenes:
            continue
        runs = {}
        for name, fn in runners:
            t0 = time.process_time() + _children_cpu()
            w0 = time.perf_counter()
            try:
                runs[name] = fn(sc)
            except Exception as exc:  # a peer failing is reported, not fatal
                print(f"{sc.name}: {name} failed: {type(exc).__name__}: {exc}")
                continue
            cpu = time.process_time() + _children_cpu() - t0  # Siconos: its subprocess
            wall = time.perf_counter() - w0
            ref = tilt_of(runs["rigid3d"][2]) if "rigid3d" in runs else None
            row = {"code": name, **metrics(sc, *runs[name], ref=ref),
                   "cpu_s": cpu, "wall_s": wall}
            rows.append(row)
            print({k: (round(v, 5) if isinstance(v, float) else v) for k, v in row.items()})
        figure(sc, runs, os.path.join(args.out, f"{sc.name}.png"))
    cols = ["scene", "code"]
    rows = [{**{c: r[c] for c in cols}, **{k: v for k, v in r.items() if k not in cols}}
            for r in rows]
    csv = os.path.join(args.out, "peers.csv")
    if args.scenes and os.path.isfile(csv):  # keep the other scenes' rows
        import pandas as pd

        old = pd.read_csv(csv)
        keep = old[~old["scene"].isin(args.scenes)].to_dict("records")
        rows = [{k: v for k, v in r.items() if not (isinstance(v, float) and math.isnan(v))}
                for r in keep] + rows
        order = [sc.name for sc in scenes()]
        rows.sort(key=lambda r: order.index(r["scene"]))
    write_tables(rows, args.out)
    print(f"wrote {args.out}/peers.csv, peers.md and the figures")


if __name__ == "__main__":
    main()
