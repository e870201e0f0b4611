"""The 3-D rigid body (``model="rigid3d"``, issue 30): its physics against closed forms, the
classical planar model and a plain reference implementation; each test can fail.

Figures (box 0.25 x 0.5 x 1 m, free rocking from half its alpha, 2 s, friction 2,
restitution 0; measured when this file was written): the largest difference between the
tilt and the classical model's ``|theta|`` is 1.2e-3, 4.7e-4 and 1.6e-4 rad at
``h`` = 2e-4, 1e-4 and 5e-5 s (first order); the ratio of the angular velocities across
the first impact is Housner's ``mu`` (Eq 4, 0.91176) within 4.1e-4 (``h`` = 1e-4) and
2.1e-4 (5e-5). Forced by a sine along x at 1.5 g tan(alpha) (1.5 s, peak tilt 0.130 rad):
3.4e-4, 2.1e-4, 1.9e-4 and 5.6e-5 rad at h = 2e-4, 1e-4, 5e-5 and 2.5e-5 s, the uplift
within one step of g tan(alpha).
"""

import math

import numpy as np
import pytest

import rocking
from rocking import G, ParameterError
from rocking.models.rigid3d import Rigid3d, rest_state
from rocking.motions import GroundMotion, Rectangular, Sine
from rocking.motions import _kernel as K
from rocking.shapes import Shape
from rocking.testing import rigid3d_reference as reference
from rocking.testing.contract import check_rotation_equivariance

LX, LY, LZ = 0.25, 0.5, 1.0


@pytest.fixture(scope="module")
def box():
    return Shape.box(LX, LY, LZ, density=2500.0)


def tilt_of(states):
    """The angle (rad) of the body's up axis from the vertical, from the quaternions."""
    q = states[:, 3:7]
    return 2.0 * np.arcsin(np.clip(np.hypot(q[:, 1], q[:, 2]), 0.0, 1.0))


def test_box_is_the_planar_block(box):
    """The box's mass properties are the closed forms; rocked about a base edge it is the
    classical rectangular block (alpha, p; mu of Eq 4)."""
    m = box.mass
    assert m == pytest.approx(2500.0 * LX * LY * LZ, rel=1e-12)
    np.testing.assert_allclose(np.diag(box.inertia_local),
                               [m * (LY**2 + LZ**2) / 12, m * (LX**2 + LZ**2) / 12,
                                m * (LX**2 + LY**2) / 12], rtol=1e-12)
    blk = rocking.Block.rectangular(width=LX, height=LZ)
    R = 0.5 * math.hypot(LX, LZ)
    i_edge = box.inertia_local[1, 1] + m * R**2
    assert blk.alpha == pytest.approx(math.atan(LX / LZ), rel=1e-14)
    assert blk.p == pytest.approx(math.sqrt(m * G * R / i_edge), rel=1e-12)
    assert blk.mu == pytest.approx(1.0 - 1.5 * math.sin(blk.alpha) ** 2, rel=1e-14)
    assert len(box.hull_points()) == 8 and box.contact_points == 4


def _free_rocking(box, h, theta0, direction=0.0, duration=2.0, dt_out=5e-4):
    return rocking.simulate(box, None, model="rigid3d", duration=duration, tilt0=theta0,
                            friction=2.0, dt_out=dt_out, step=h, direction=direction)


def test_planar_limit_free_rocking_converges_to_housner(box):
    """Free rocking about a principal axis, friction sticking, restitution 0: the tilt is
    the classical model's |theta| (Eq 1 with Eq 4 at impacts), to first order in h."""
    blk = rocking.Block.rectangular(width=LX, height=LZ)
    th0 = 0.5 * blk.alpha
    ref = rocking.simulate(blk, None, model="housner", duration=2.0, theta0=th0,
                           dt_out=5e-4)
    errors = []
    for h in (2e-4, 1e-4, 5e-5):
        r = _free_rocking(box, h, th0)
        errors.append(float(np.max(np.abs(tilt_of(r.states) - np.abs(ref.theta)))))
        assert r.n_impacts == ref.impact_times[ref.impact_times < 2.0].size
        np.testing.assert_allclose(r.impact_times, ref.impact_times[:r.n_impacts],
                                   atol=10 * h)
        assert abs(r.max_twist) < 1e-9 and np.max(np.abs(r.states[:, 1])) < 1e-9
        assert not r.lifted_off and not r.overturned and r.unconverged_steps == 0
    assert errors[0] > errors[1] > errors[2]
    assert errors[2] < 3e-4 and errors[0] / errors[2] > 3.0, errors


def test_planar_limit_along_y(box):
    """Rocking along the body's y axis is the block of width ly."""
    blk = rocking.Block.rectangular(width=LY, height=LZ)
    th0 = 0.4 * blk.alpha
    ref = rocking.simulate(blk, None, model="housner", duration=1.5, theta0=th0,
                           dt_out=5e-4)
    r = _free_rocking(box, 1e-4, th0, direction=90.0, duration=1.5)
    assert np.max(np.abs(tilt_of(r.states) - np.abs(ref.theta))) < 1e-3
    assert np.max(np.abs(r.states[:, 0])) < 1e-8  # no motion along x


def test_planar_limit_forced(box):
    """Under a horizontal sine along x the box rocks as the classical block: its uplift
    time (g tan alpha reached) and its tilt history."""
    blk = rocking.Block.rectangular(width=LX, height=LZ)
    motion = Sine.from_acceleration(2.0, 1.5 * G * math.tan(blk.alpha), 1.5)
    ref = rocking.simulate(blk, motion, model="housner", duration=1.5, dt_out=1e-3)
    r = rocking.simulate(box, motion, model="rigid3d", duration=1.5, friction=2.0,
                         dt_out=1e-3, step=5e-5)
    assert r.uplift_time == pytest.approx(ref.uplift_time, abs=2 * 5e-5)  # within 2 steps
    assert r.unconverged_steps == 0
    assert r.max_tilt == pytest.approx(ref.max_abs_theta, rel=2e-3)
    assert np.max(np.abs(tilt_of(r.states) - np.abs(ref.theta))) < 5e-3 * ref.max_abs_theta


def _impact_ratio(box, h):
    blk = rocking.Block.rectangular(width=LX, height=LZ)
    r = rocking.simulate(box, None, model="rigid3d", duration=0.45, tilt0=0.5 * blk.alpha,
                         friction=2.0, dt_out=h, step=h)
    k = int(round(r.impact_times[0] / h))
    w = r.states[:, 11]  # about the body's y axis
    return w[k] / w[k - 1], blk.mu


def test_impact_ratio_is_housner_eq4(box):
    """Newton's law with restitution 0 gives Housner's Eq 4 at the impact, to O(h)."""
    e = []
    for h in (1e-4, 5e-5):
        ratio, mu = _impact_ratio(box, h)
        e.append(abs(ratio - mu))
    assert e[0] < 6e-4 and e[1] < 0.6 * e[0], e


def test_sliding_above_friction_sticking_below():
    """A squat box on ground accelerating at a > friction g slides with the relative
    acceleration -(a - friction g) and does not rock; below it sticks."""
    squat = Shape.box(1.0, 0.8, 0.2, density=2500.0)
    for a, mu, direction in ((0.5 * G, 0.3, 0.0), (0.5 * G, 0.3, 30.0), (0.2 * G, 0.3, 0.0)):
        r = rocking.simulate(squat, Rectangular(a, 1.0), model="rigid3d", duration=0.5,
                             friction=mu, dt_out=0.01, direction=direction)
        s = -0.5 * max(a - mu * G, 0.0) * r.t**2
        d = math.radians(direction)
        np.testing.assert_allclose(r.states[:, 0], s * math.cos(d), atol=1e-12)
        np.testing.assert_allclose(r.states[:, 1], s * math.sin(d), atol=1e-12)
        assert r.max_tilt < 1e-12 and np.ptp(r.states[:, 2]) < 1e-12
        assert r.residual_slide == pytest.approx(abs(s[-1]), abs=1e-12)
        assert math.isnan(r.uplift_time) == (a <= mu * G) and r.unconverged_steps == 0


def test_twisting_stops_as_friction_torque_says():
    """A square box spun about the vertical on the ground: the friction of its four corners
    (radius r) brakes it at mu m g r / I_zz; it turns by w0^2 I_zz / (2 mu m g r)."""
    sq = Shape.box(0.6, 0.6, 0.3, density=2000.0)
    mu, w0 = 0.5, 2.0
    y0 = rest_state(sq)
    y0[12] = w0
    r = rocking.simulate(sq, None, model="rigid3d", duration=1.0, state0=y0, friction=mu,
                         dt_out=0.01, step=1e-4)
    izz = sq.inertia_local[2, 2]
    torque = mu * sq.mass * G * math.hypot(0.3, 0.3)
    assert r.residual_twist == pytest.approx(w0**2 * izz / (2 * torque), rel=1e-3)
    assert r.max_twist == pytest.approx(r.residual_twist, rel=1e-12)
    assert r.residual_slide < 1e-12 and r.settled and r.unconverged_steps == 0


def test_free_flight_conserves_momenta():
    """Thrown up by a vertical pulse beyond -g and spinning: the momentum follows the
    uniform field exactly, the angular momentum is constant, the energy to O(h)."""
    body = Shape.box(1.0, 0.8, 0.2, density=2500.0)
    motion = GroundMotion(Rectangular(0.0, 1.0), -Rectangular(1.5 * G, 0.3))
    y0 = rest_state(body)
    y0[2] += 0.5
    y0[7:10] = (0.1, -0.2, 0.05)
    y0[10:13] = (2.0, -1.0, 3.0)
    r = rocking.simulate(body, motion, model="rigid3d", duration=0.25, state0=y0,
                         dt_out=1e-3, step=1e-4)
    from scipy.spatial.transform import Rotation

    inertia = body.inertia_local
    L = np.array([Rotation.from_quat(s[[4, 5, 6, 3]]).as_matrix() @ inertia @ s[10:]
                  for s in r.states])
    assert np.max(np.abs(L - L[0])) < 1e-12 * np.abs(L[0]).max()
    v_expected = y0[7:10] + np.outer(r.t, [0.0, 0.0, 0.5 * G])
    np.testing.assert_allclose(r.states[:, 7:10], v_expected, atol=1e-12)
    energy = (0.5 * np.einsum("ij,jk,ik->i", r.states[:, 10:], inertia, r.states[:, 10:])
              + 0.5 * body.mass * np.sum(r.states[:, 7:10] ** 2, axis=1)
              - 0.5 * G * body.mass * r.states[:, 2])
    assert np.ptp(energy) < 2e-5 * abs(energy[0])
    assert r.lifted_off and r.lift_off_time == pytest.approx(1e-4)


def test_overturning_direction(box):
    """A strong pulse along x overturns the box as the classical block, at the same time
    and to the same side; the box turned by 90 deg and shaken along y, the same fall
    turned by 90 deg."""
    blk = rocking.Block.rectangular(width=LX, height=LZ)
    pulse = rocking.motions.OneSine(3.0 * G * math.tan(blk.alpha), 0.5)
    ref = rocking.simulate(blk, pulse, model="housner")
    assert ref.overturned
    r = rocking.simulate(box, pulse, model="rigid3d", friction=2.0, dt_out=0.01)
    assert r.overturned and r.settled and r.overturn_time >= r.uplift_time
    # theta > 0 leans the block towards -x (a positive ground acceleration drives it)
    towards = 180.0 if ref.theta[-1] > 0 else 0.0
    assert abs((r.overturn_azimuth - towards + 180.0) % 360.0 - 180.0) < 1.0
    assert r.overturn_time == pytest.approx(ref.overturn_time, abs=0.02)
    assert r.max_tilt == pytest.approx(0.5 * math.pi, abs=0.01)
    turned = Shape.box(LY, LX, LZ, density=2500.0)  # the same box turned by 90 deg
    r = rocking.simulate(turned, pulse, model="rigid3d", friction=2.0, dt_out=0.01,
                         direction=90.0)
    assert r.overturned  # the same fall, turned by 90 deg
    assert abs((r.overturn_azimuth - towards - 90.0 + 180.0) % 360.0 - 180.0) < 1.0


@pytest.mark.parametrize("name, value", [("friction", 0.0), ("friction", -0.5),
                                         ("restitution", -0.1), ("restitution", 1.1)])
def test_bad_options_are_refused(box, name, value):
    with pytest.raises(ParameterError, match=name):
        rocking.simulate(box, None, model="rigid3d", duration=0.1, **{name: value})


def test_bad_bodies_and_states_are_refused(box):
    with pytest.raises(ParameterError, match="Shape"):
        rocking.simulate(rocking.Block.from_params(0.2, 2.0, 0.9), None, model="rigid3d",
                         duration=0.1)
    y = rest_state(box)
    y[2] -= 0.01
    with pytest.raises(ParameterError, match="below the ground"):
        rocking.simulate(box, None, model="rigid3d", duration=0.1, state0=y)
    with pytest.raises(ParameterError, match="tilt0"):
        rocking.simulate(box, None, model="rigid3d", duration=0.1, theta0=0.1)


def test_kernel_matches_the_plain_reference(box):
    """The compiled kernel computes the scheme: a tilted, twisting box shaken at 30 deg
    (rocking on a corner, landing, three components), against the numpy reference."""
    h, duration = 1e-4, 0.12
    model = Rigid3d.from_kwargs(box, friction=0.6, direction=30.0, tol=1e-13, step=h)
    y0 = rest_state(box, 0.08, math.radians(30.0))
    y0[10:13] = (0.05, -0.3, 0.4)
    motion = GroundMotion(Sine(3.0, 0.02, 1.0), Sine(5.0, 0.002, 1.0))
    r = rocking.simulate(box, motion, model="rigid3d", duration=duration, state0=y0,
                         dt_out=h, friction=0.6, direction=30.0, tol=1e-13, step=h)
    spec = model.motion_spec(motion)
    mp = model.kernel_params(h, 0.0, 0.0)
    want = reference.simulate(mp, lambda t: K.ground_acc3(*spec, t), r.states[0], duration)
    assert want.shape == r.states.shape
    np.testing.assert_allclose(r.states, want, rtol=0, atol=1e-9)
    assert np.ptp(r.states[:, 12]) > 0.1 and r.n_impacts >= 1  # it wobbled and landed
    assert r.unconverged_steps == 0


def test_rotation_check_catches_a_frame_error():
    """The contract's rotation check passes for the model and fails for one that ignores
    the direction of the motion."""
    check_rotation_equivariance(Rigid3d)

    class Blind(Rigid3d):
        def motion_spec(self, motion):
            return motion.spec3(0.0)

    with pytest.raises(AssertionError, match="rotation_equivariance"):
        check_rotation_equivariance(Blind)


def test_horizontal_pair_turned_with_the_body_changes_nothing(box):
    """A HorizontalPair at ``heading``: the same ground motion recorded on axes turned by
    beta, with the body's heading turned by beta too, is the same run; a pair whose second
    component is zero is its first component alone."""
    pair = rocking.motions.HorizontalPair.builtin("rinaldi", vertical=False).scaled(0.5)
    kw = {"model": "rigid3d", "duration": 3.0, "dt_out": 0.01}
    a = rocking.simulate(box, pair, heading=20.0, **kw)
    assert a.max_tilt > 0.01 and a.max_slide > 0.0  # it rocked
    b = rocking.simulate(box, pair.rotated(math.radians(35.0)), heading=55.0, **kw)
    for name in ("max_tilt", "max_slide", "max_twist", "residual_twist", "uplift_time"):
        assert b.outputs[name] == pytest.approx(a.outputs[name], rel=1e-6, abs=1e-9), name
    np.testing.assert_allclose(b.states, a.states, atol=1e-6)
    first = pair.first
    alone = rocking.motions.HorizontalPair(first, first.scaled(0.0))
    c = rocking.simulate(box, alone, **kw)
    d = rocking.simulate(box, first, **kw)
    np.testing.assert_allclose(c.states, d.states, atol=1e-9)
    with pytest.raises(ParameterError, match="planar"):
        rocking.simulate(rocking.Block.rectangular(LX, LZ), pair, duration=1.0)


@pytest.mark.parametrize("e", [0.0, 0.5, 1.0])
def test_flat_drop_bounces_with_newtons_restitution(e):
    """A box dropped flat from 5 cm lands on its four corners at once: Newton's law sends
    it back up at e times its landing speed (to O(g h)), with no rotation."""
    body = Shape.box(0.4, 0.3, 0.6, density=2000.0)
    y0 = rest_state(body)
    y0[2] += 0.05
    h = 1e-4
    r = rocking.simulate(body, None, model="rigid3d", duration=0.15, state0=y0,
                         restitution=e, dt_out=h, step=h)
    v_land = math.sqrt(2 * G * 0.05)
    k = int(round(r.impact_times[0] / h))
    assert r.impact_times[0] == pytest.approx(math.sqrt(2 * 0.05 / G), abs=2 * h)
    assert r.states[k, 9] == pytest.approx(e * v_land, abs=2 * G * h)
    assert np.max(np.abs(r.states[:, 10:])) < 1e-9 and r.max_tilt < 1e-9
    assert r.lifted_off and r.n_impacts == 1


def test_wobbling_dissipates_and_converges(box):
    """Released tilted on a corner and spinning, the box wobbles, twists and slips (friction
    0.7): the energy never grows but by the O(h^2) error of a free step, the impacts
    dissipate it, and the twist and the slide converge as h shrinks."""
    out = {}
    for h in (1e-4, 5e-5):
        y0 = rest_state(box, 0.15, math.radians(30.0))
        y0[10:13] = (0.2, -0.5, 1.5)
        r = rocking.simulate(box, None, model="rigid3d", duration=3.0, state0=y0, dt_out=h,
                             step=h, friction=0.7)
        s = r.states
        energy = (0.5 * box.mass * np.sum(s[:, 7:10] ** 2, axis=1)
                  + 0.5 * np.einsum("ij,jk,ik->i", s[:, 10:], box.inertia_local, s[:, 10:])
                  + box.mass * G * (s[:, 2] - box.h))
        d = np.diff(energy)
        assert d.max() < 1e-7 * (h / 1e-4) ** 2 * energy[0]  # per step: O(h^2)
        assert energy[-1] < 0.1 * energy[0] and r.n_impacts > 10
        assert r.unconverged_steps == 0
        out[h] = (r.residual_twist, r.residual_slide, d[d > 0].sum() / energy[0])
    (tw1, sl1, up1), (tw2, sl2, up2) = out[1e-4], out[5e-5]
    assert tw1 > 0.1 and sl1 > 0.01  # it twisted and slid
    assert abs(tw1 - tw2) < 1e-3 * tw1 and abs(sl1 - sl2) < 1e-3 * sl1
    assert up1 < 5e-4 and up2 < 0.7 * up1
