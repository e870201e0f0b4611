"""Why Siconos loses less energy than Housner's Eq 4 (``docs/guide/rigid3d_peers.rst``):
the first impact of the freely rocking box of ``peers_rigid3d.py``'s ``free`` scene, step
by step, in Siconos (Debian's ``python3-siconos``; run with the system interpreter, which
has numpy and siconos only)::

    /usr/bin/python3 benchmarks/peers_siconos_impact.py                  # 0.25 x 0.5 x 1 m
    /usr/bin/python3 benchmarks/peers_siconos_impact.py --lx 0.5         # a squat box
    /usr/bin/python3 benchmarks/peers_siconos_impact.py --contactor hull --perturbation 0

It prints, for the steps of the first impact, the normal impulses (N s) Siconos applies and
the points of the box's base (m) where Bullet's contact manifold puts them, then the ratio
of the angular velocity after / before the impact (from the kinetic energy just before
and after, ``sqrt(E+ / E-)``) against

* Eq 4, ``1 - 1.5 sin^2 alpha``: one plastic impact on the landing edge (Housner);
* ``1 - 0.75 sin^2 alpha``: two plastic impacts, first at the centre of the base (the
  angular momentum about it is kept: the angular velocity does not change, the centre of
  mass's vertical velocity stops), then on the landing edge (the angular momentum about
  it is kept): the ratio of the second is ``(I_c + m h^2) / (I_c + m (h^2 + b^2))``
  with ``I_c = m (b^2 + h^2) / 3`` (b, h the half-width and half-height).

The box starts tilted by alpha / 2 on its edge, at rest; friction 2 (no sliding),
restitution 0, step 1e-4 s, Moreau-Jean theta 0.5, the ground a thick box (as
``peers_siconos.py``).
"""

import argparse
import math

import numpy as np


def start(lx, ly, lz, tilt):
    """The centre of mass and quaternion (w, x, y, z) of the box tilted by ``tilt`` about
    y on its edge ``x = -lx / 2`` (the corners' lowest z at 0)."""
    c, s = math.cos(-tilt), math.sin(-tilt)
    rot = np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    corners = np.array([[sx * lx / 2, sy * ly / 2, sz * lz / 2] for sx in (-1, 1)
                        for sy in (-1, 1) for sz in (-1, 1)]) @ rot.T
    pos = np.array([0.0, 0.0, -corners[:, 2].min()])
    return pos, [math.cos(-tilt / 2), 0.0, math.sin(-tilt / 2), 0.0]


def run(lx, ly, lz, density, contactor, perturbation, duration, step=1e-4):
    import siconos.kernel as sk
    from siconos.mechanics.collision import (
        RigidBodyDS,
        SiconosBox,
        SiconosContactor,
        SiconosContactorSet,
        SiconosConvexHull,
    )
    from siconos.mechanics.collision.bullet import (
        SiconosBulletCollisionManager,
        SiconosBulletOptions,
    )

    g = 9.80665
    m = density * lx * ly * lz
    inertia = np.diag([m * (ly**2 + lz**2) / 12, m * (lx**2 + lz**2) / 12,
                       m * (lx**2 + ly**2) / 12])
    alpha = math.atan(lx / lz)
    pos, quat = start(lx, ly, lz, 0.5 * alpha)
    body = RigidBodyDS(list(pos) + quat, [0.0] * 6, m, inertia)
    cset = SiconosContactorSet()
    if contactor == "hull":
        shape = SiconosConvexHull(np.array([[sx * lx / 2, sy * ly / 2, sz * lz / 2]
                                            for sx in (-1, 1) for sy in (-1, 1)
                                            for sz in (-1, 1)]))
    else:
        shape = SiconosBox(lx, ly, lz)
    shape.setInsideMargin(0.0)
    shape.setOutsideMargin(0.0)
    cset.append(SiconosContactor(shape))
    body.setContactors(cset)
    body.setFExtPtr(np.array([0.0, 0.0, -m * g]))
    nsds = sk.NonSmoothDynamicalSystem(0.0, duration)
    nsds.insertDynamicalSystem(body)
    opts = SiconosBulletOptions()
    opts.perturbationIterations = perturbation
    opts.minimumPointsPerturbationThreshold = perturbation
    opts.contactBreakingThreshold = 1e-4
    opts.worldScale = 1.0
    inter = SiconosBulletCollisionManager(opts)
    inter.insertNonSmoothLaw(sk.NewtonImpactFrictionNSL(0.0, 0.0, 2.0, 3), 0, 0)
    ground = SiconosBox(40.0, 40.0, 1.0)
    ground.setInsideMargin(0.0)
    ground.setOutsideMargin(0.0)
    gset = SiconosContactorSet()
    gset.append(SiconosContactor(ground))
    inter.insertStaticContactorSet(gset, [0.0, 0.0, -0.5, 1.0, 0.0, 0.0, 0.0])
    fc = sk.FrictionContact(3)
    fc.numericsSolverOptions().iparam[0] = 1000
    fc.numericsSolverOptions().dparam[0] = 1e-10
    fc.setKeepLambdaAndYState(True)
    sim = sk.TimeStepping(nsds, sk.TimeDiscretisation(0.0, step))
    sim.insertIntegrator(sk.MoreauJeanOSI(0.5))
    sim.insertNonSmoothProblem(fc)
    sim.insertInteractionManager(inter)
    sim.setNewtonMaxIteration(1)
    sim.setNewtonTolerance(1e-10)
    t, energy, tilt, impulses = [], [], [], []
    for k in range(int(round(duration / step))):
        sim.computeOneStep()
        q = np.array(body.q())
        v = np.array(body.twist())
        e = (0.5 * m * v[:3] @ v[:3] + 0.5 * v[3:] @ inertia @ v[3:]
             + m * g * (q[2] - lz / 2))
        hits = []
        for it in nsds.topology().indexSet0().interactions():
            lam = it.lambda_(1)
            p = float(lam[0]) if lam is not None else 0.0
            if p > 1e-6:
                pc = np.array(it.relation().pc1())
                hits.append((p, pc[0] - q[0], pc[1] - q[1]))
        t.append((k + 1) * step)
        energy.append(e)
        tilt.append(2.0 * math.asin(min(1.0, math.hypot(q[4], q[5]))))
        impulses.append(hits)
        sim.nextStep()
    return m, alpha, np.array(t), np.array(energy), np.array(tilt), impulses


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--lx", type=float, default=0.25, help="width (m), the rocking plane")
    ap.add_argument("--contactor", choices=("box", "hull"), default="box")
    ap.add_argument("--perturbation", type=int, default=12,
                    help="Bullet's perturbation iterations (peers_siconos.py: 12)")
    args = ap.parse_args()
    m, alpha, t, e, tilt, imp = run(args.lx, 0.5, 1.0, 2500.0, args.contactor,
                                    args.perturbation, 0.5)
    k = int(np.argmin(tilt[: int(0.45 / 1e-4)]))  # upright: the first impact
    lo, hi = max(k - 60, 0), min(k + 150, len(t) - 1)
    print(f"box {args.lx} x 0.5 x 1 m, contactor {args.contactor}, perturbation "
          f"{args.perturbation}: first impact at {t[k]:.4f} s")
    print("  step (s)   impulse (N s) at (x, y) of the base, from its centre (m)")
    big = 0.05 * max((p for h in imp[lo:hi] for p, _, _ in h), default=1.0)
    for j in range(lo, hi):
        hits = [h for h in imp[j] if h[0] > big]
        if hits:
            print(f"  {t[j]:.4f}   " + "; ".join(f"{p:6.2f} at ({x:+.3f}, {y:+.3f})"
                                                  for p, x, y in hits))
    ratio = math.sqrt(e[hi] / e[lo])
    s2 = math.sin(alpha) ** 2
    print(f"  angular velocity after / before: {ratio:.4f}; Eq 4 (one impact on the "
          f"landing edge) {1 - 1.5 * s2:.4f}; centre then edge {1 - 0.75 * s2:.4f}")


if __name__ == "__main__":
    main()
