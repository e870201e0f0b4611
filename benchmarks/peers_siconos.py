"""The scenes of ``peers_rigid3d.py`` in Siconos (non-smooth contact dynamics, Moreau-Jean
with Newton's impact law and a Coulomb cone; Acary and Brogliato 2008), run by Debian's
``python3-siconos`` from the system ``python3`` (it is not installable with pip, and it is
built for Debian's interpreter)::

    apt-get install -y python3-siconos
    /usr/bin/python3 benchmarks/peers_siconos.py scene.json out.npz

``scene.json`` holds the box (``lx, ly, lz``, ``mass``, the initial ``pos`` and
quaternion ``quat`` w, x, y, z), ``friction``, ``restitution``, ``step``, ``duration`` and
the ground's acceleration along x sampled at each step (``acc_x``, m/s^2; applied as the
inertial force ``-m a`` on the body in the ground's frame, which is what a moving ground
does to a body on it). ``out.npz`` holds ``t`` and the states ``pos`` (n, 3), ``quat``
(n, 4, w first). Only numpy and siconos are used (the system interpreter has no more).
"""

import json
import sys

import numpy as np


def run(scene):
    import siconos.kernel as sk
    from siconos.mechanics.collision import (
        RigidBodyDS,
        SiconosBox,
        SiconosContactor,
        SiconosContactorSet,
        SiconosPlane,
    )
    from siconos.mechanics.collision.bullet import (
        SiconosBulletCollisionManager,
        SiconosBulletOptions,
    )

    g = 9.80665
    lx, ly, lz = scene["lx"], scene["ly"], scene["lz"]
    m = scene["mass"]
    h = scene["step"]
    inertia = np.diag([m * (ly**2 + lz**2) / 12, m * (lx**2 + lz**2) / 12,
                       m * (lx**2 + ly**2) / 12])
    q0 = list(scene["pos"]) + list(scene["quat"])
    body = RigidBodyDS(q0, [0.0] * 6, m, inertia)
    cset = SiconosContactorSet()
    box = SiconosBox(lx, ly, lz)
    box.setInsideMargin(0.0)
    box.setOutsideMargin(0.0)
    cset.append(SiconosContactor(box))
    body.setContactors(cset)
    weight = np.array([0.0, 0.0, -m * g])
    body.setFExtPtr(weight)
    t_end = scene["duration"]
    nsds = sk.NonSmoothDynamicalSystem(0.0, t_end)
    nsds.insertDynamicalSystem(body)
    opts = SiconosBulletOptions()
    opts.perturbationIterations = 3 * 4
    opts.minimumPointsPerturbationThreshold = 3 * 4
    opts.contactBreakingThreshold = scene.get("breaking", 1e-4)
    opts.worldScale = 1.0
    inter = SiconosBulletCollisionManager(opts)
    law = sk.NewtonImpactFrictionNSL(scene["restitution"], 0.0, scene["friction"], 3)
    inter.insertNonSmoothLaw(law, 0, 0)
    if scene.get("ground", "box") == "plane":
        plane = SiconosPlane()
        z0 = 0.0
    else:  # a thick box: Bullet's box-box detector gives the corners exactly
        plane = SiconosBox(40.0, 40.0, 1.0)
        z0 = -0.5
    plane.setInsideMargin(0.0)
    plane.setOutsideMargin(0.0)
    ground = SiconosContactorSet()
    ground.append(SiconosContactor(plane))
    inter.insertStaticContactorSet(ground, [0.0, 0.0, z0, 1.0, 0.0, 0.0, 0.0])
    osi = sk.MoreauJeanOSI(scene.get("theta", 0.5))
    td = sk.TimeDiscretisation(0.0, h)
    fc = sk.FrictionContact(3)
    fc.numericsSolverOptions().iparam[0] = 1000
    fc.numericsSolverOptions().dparam[0] = 1e-10
    fc.setKeepLambdaAndYState(True)
    sim = sk.TimeStepping(nsds, td)
    sim.insertIntegrator(osi)
    sim.insertNonSmoothProblem(fc)
    sim.insertInteractionManager(inter)
    sim.setNewtonMaxIteration(1)
    sim.setNewtonTolerance(1e-10)
    acc = np.asarray(scene["acc_x"], dtype=float)
    n = int(round(t_end / h))
    every = max(1, int(round(scene.get("dt_out", h) / h)))
    ts, pos, quat = [0.0], [q0[:3]], [q0[3:]]
    k = 0
    while sim.hasNextEvent() and k < n:
        a = acc[k] if k < len(acc) else 0.0
        weight[0] = -m * a
        body.setFExtPtr(weight)
        sim.computeOneStep()
        sim.nextStep()
        k += 1
        if k % every == 0:
            q = np.array(body.q())
            ts.append(k * h)
            pos.append(q[:3].tolist())
            quat.append(q[3:7].tolist())
    return np.array(ts), np.array(pos), np.array(quat)


if __name__ == "__main__":
    with open(sys.argv[1]) as fh:
        sc = json.load(fh)
    t, p, q = run(sc)
    np.savez(sys.argv[2], t=t, pos=p, quat=q)
