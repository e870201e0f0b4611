"""The 3-D histories of a ``rigid3d`` response (issue 30): ``Response.tilt``, ``slide``,
``twist``, ``base_path`` and ``com_path``, against closed forms of torque-free flight and
against the kernel's own outputs (``max_tilt``, ``residual_slide``, ``residual_twist``)."""


import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import rocking
from rocking.motions import HorizontalPair, Record
from rocking.results import tilt_angle, twist_angle
from rocking.shapes import Shape

LX, LZ = 0.4, 1.2  # a box square in plan: its z and x axes are principal


@pytest.fixture(scope="module")
def box():
    return Shape.box(LX, LX, LZ, density=2000.0)


def _flight(box, **velocity):
    """A box released 2 m up with the given velocity (``vx``, ``wz``, ...), 0.3 s: it
    never reaches the ground (it falls 0.44 m)."""
    names = ("x", "y", "z", "q0", "q1", "q2", "q3", "vx", "vy", "vz", "wx", "wy", "wz")
    y0 = dict.fromkeys(names, 0.0) | {"z": 2.0, "q0": 1.0} | velocity
    return rocking.simulate(box, None, model="rigid3d", duration=0.3, dt_out=0.01,
                            step=1e-3, state0=[y0[n] for n in names])


def test_flight_spin_about_the_vertical_is_pure_twist(box):
    """Torque-free spin about a principal axis is steady: twist = wz t, tilt 0; the base
    point, under the centre of mass, slides with it: slide = vx t, the path x = vx t."""
    r = _flight(box, vx=0.3, wz=2.0)
    assert not r.lifted_off or r.lift_off_time == pytest.approx(0.001, abs=1e-3)
    np.testing.assert_allclose(r.twist, 2.0 * r.t, atol=1e-9)
    np.testing.assert_allclose(r.tilt, 0.0, atol=1e-12)
    np.testing.assert_allclose(r.slide, 0.3 * r.t, atol=1e-9)
    np.testing.assert_allclose(r.com_path(), np.column_stack((0.3 * r.t, 0 * r.t)), atol=1e-9)
    assert r.twist[-1] == pytest.approx(r.residual_twist, abs=1e-9)
    assert r.slide[-1] == pytest.approx(r.residual_slide, abs=1e-9)


def test_flight_spin_about_a_horizontal_axis_is_pure_tilt(box):
    """Spin wx about the body's x axis: tilt = wx t, no twist, and the base point
    (``h`` below the centre of mass) swings sideways by ``h sin(wx t)``, while the centre
    of mass does not move horizontally."""
    w = 1.5
    r = _flight(box, wx=w)
    np.testing.assert_allclose(r.tilt, w * r.t, atol=1e-9)
    np.testing.assert_allclose(r.twist, 0.0, atol=1e-12)
    path = r.base_path()
    np.testing.assert_allclose(path[:, 1], 0.5 * LZ * np.sin(w * r.t), atol=1e-9)
    np.testing.assert_allclose(path[:, 0], 0.0, atol=1e-12)
    np.testing.assert_allclose(r.slide, 0.5 * LZ * np.sin(w * r.t), atol=1e-9)
    np.testing.assert_allclose(r.com_path(), 0.0, atol=1e-12)
    assert np.max(r.tilt) == pytest.approx(r.max_tilt, rel=1e-9)


def test_tilt_is_the_up_axis_angle_and_twist_unwraps():
    """``tilt_angle`` is the angle of R e_z from e_z (scipy's rotations, independent), for
    random orientations; ``twist_angle`` of a turn about z is the turn, unwrapped."""
    rot = Rotation.random(200, random_state=1)
    xyzw = rot.as_quat()
    q = np.column_stack((xyzw[:, 3], xyzw[:, :3]))
    up = rot.apply([0.0, 0.0, 1.0])
    np.testing.assert_allclose(tilt_angle(q), np.arccos(np.clip(up[:, 2], -1, 1)), atol=1e-7)
    a = np.linspace(0.0, 9.0, 50)  # beyond 2 pi
    qz = np.column_stack((np.cos(a / 2), 0 * a, 0 * a, np.sin(a / 2)))
    np.testing.assert_allclose(twist_angle(qz), a, atol=1e-12)


@pytest.mark.parametrize("body", ["box", "cylinder"])
def test_histories_agree_with_the_kernels_outputs(box, body):
    """Under a pair of sines the histories' extremes are the kernel's outputs: the last
    slide and twist are ``residual_slide``, ``residual_twist`` (explicit duration: the
    last sample is the last step); the sampled peaks do not exceed ``max_tilt``,
    ``max_slide``, ``max_twist`` and come within a sample of them."""
    t = np.arange(0.0, 1.0, 0.005)
    pair = HorizontalPair(Record(4.5 * np.sin(2 * np.pi * 2 * t), 0.005),
                          Record(3.5 * np.sin(2 * np.pi * 3 * t), 0.005))
    shape = box if body == "box" else Shape.cylinder(0.2, 1.2, density=2000.0)
    r = rocking.simulate(shape, pair, model="rigid3d", duration=1.0, step=5e-4, heading=20.0,
                         dt_out=5e-4)
    assert r.max_tilt > 0.01 and not r.overturned  # it rocks
    assert r.slide[-1] == pytest.approx(r.residual_slide, rel=1e-9, abs=1e-12)
    assert r.twist[-1] == pytest.approx(r.residual_twist, rel=1e-9, abs=1e-12)
    for hist, peak in ((r.tilt, r.max_tilt), (r.slide, r.max_slide),
                       (np.abs(r.twist), r.max_twist)):
        assert np.max(hist) <= peak * (1 + 1e-9) + 1e-15
        assert np.max(hist) == pytest.approx(peak, rel=1e-9, abs=1e-12)  # every step sampled
    df = r.to_dataframe()
    assert {"tilt", "slide", "twist"} <= set(df.columns)
    np.testing.assert_array_equal(df["tilt"], r.tilt)


def test_planar_models_have_none():
    block = rocking.specimen(2)
    r = rocking.simulate(block, theta0=0.5 * block.alpha, duration=0.2)
    assert r.tilt is None and r.twist is None and r.slide is None
    assert r.base_path() is None and r.com_path() is None
    assert "tilt" not in r.to_dataframe().columns


def test_response_plot_draws_the_tilt(box):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    r = rocking.simulate(box, model="rigid3d", duration=0.3, tilt0=0.05, step=1e-3)
    ax = r.plot()
    np.testing.assert_allclose(ax.lines[0].get_ydata(), np.degrees(r.tilt))
    assert ax.get_ylabel() == "tilt (deg)"
    plt.close("all")
