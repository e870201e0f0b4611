"""Physics tests of the buildings (:mod:`rocking.buildings.building`) and of the plain
reference :mod:`rocking.testing.building_reference`.

Every expected value is a closed form, a published constant, or an independent
implementation (a finite-element model of the shear-flexural beam, quadrature of the
shapes, the textbook cantilever shape, direct integration), never a number captured from
this package's own output. Equation labels (S1)-(S3), (C1)-(C7), (B1)-(B2) are those of
the module docstring of :mod:`rocking.buildings.building`.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.linalg import eigh
from scipy.optimize import brentq

from rocking.buildings import Building
from rocking.buildings.building import characteristic
from rocking.errors import ParameterError
from rocking.testing.building_reference import (
    arrays_of,
    floor_response,
    shear_building_arrays,
)

# ------------------------------------------------------------------- shear building (S)


@pytest.mark.parametrize("n", [1, 2, 3, 5, 12, 40])
def test_uniform_shear_building_equals_the_closed_form(n):
    """(S3): omega_j = 2 sqrt(k/m) sin((2j-1) pi / (2(2N+1))), phi_ij ∝ sin((2j-1) i pi /
    (2N+1)), to 1e-10; the first period is the one asked for."""
    T1 = 0.73
    b = Building.shear(n, T1, damping=0.02)
    m = b.storey_masses
    k = b.storey_stiffnesses
    assert np.all(m == m[0]) and np.allclose(k, k[0], rtol=1e-15, atol=0)
    j = np.arange(1, n + 1)
    omega = 2.0 * np.sqrt(k[0] / m[0]) * np.sin((2 * j - 1) * np.pi / (2 * (2 * n + 1)))
    assert np.allclose(b.omegas, omega, rtol=1e-10, atol=0)
    assert b.periods[0] == pytest.approx(T1, rel=1e-14)
    assert 2 * np.pi / omega[0] == pytest.approx(T1, rel=1e-12)
    i = np.arange(1, n + 1)[:, None]
    shape = np.sin((2 * j - 1) * i * np.pi / (2 * n + 1))
    shape = shape / np.max(np.abs(shape), axis=0) * np.sign(shape[-1])  # largest 1, roof > 0
    assert np.allclose(b.shapes[1:], shape, rtol=0, atol=1e-10)
    assert np.all(b.shapes[0] == 0.0)
    assert np.allclose(b.heights, np.arange(n + 1) / n, rtol=0, atol=1e-15)
    assert np.all(b.damping == 0.02)


def _random_building(n, seed, T1=1.1):
    rng = np.random.default_rng(seed)
    masses = rng.uniform(0.5, 2.0, n)
    stiff = rng.uniform(0.3, 3.0, n)
    return Building.shear(n, T1, masses=masses, stiffnesses=stiff), masses, stiff


@pytest.mark.parametrize("n, seed", [(1, 0), (4, 1), (9, 2), (30, 3)])
def test_modal_expansion_of_the_unit_vector_and_participating_masses(n, seed):
    """With all modes, sum_j Gamma_j phi_j = 1 at every floor (the modal expansion of the
    influence vector 1, Chopra 13.1), so the absolute acceleration (B2) of a rigid building
    is a_g; the effective modal masses Gamma_j^2 phi_j^T M phi_j sum to the total mass;
    (S1) holds with the scaled K; T_1 is the period asked for."""
    b, masses, stiff = _random_building(n, seed)
    phi = b.shapes[1:]
    assert np.allclose(phi @ b.participation, 1.0, rtol=0, atol=1e-12)
    for floor in range(1, n + 1):
        assert b.modal_factors(floor=floor)[2].sum() == pytest.approx(1.0, abs=1e-12)
    assert b.modal_factors(floor=0)[2].sum() == 0.0
    mj = np.einsum("ij,i,ij->j", phi, masses, phi)
    assert np.sum(b.participation ** 2 * mj) == pytest.approx(masses.sum(), rel=1e-12)
    # the matrices solve (S1) with these modes: K phi = omega^2 M phi
    K, M = b.stiffness_matrix, b.mass_matrix
    assert np.allclose(np.max(np.abs(phi), axis=0), 1.0, rtol=1e-15) and np.all(phi[-1] > 0)
    res = np.linalg.norm(K @ phi - M @ phi * b.omegas ** 2, axis=0)
    assert np.all(res < 1e-12 * np.linalg.norm(K, 2))
    assert np.allclose(b.storey_stiffnesses / stiff, b.storey_stiffnesses[0] / stiff[0],
                       rtol=1e-14)  # one scale factor for every storey
    assert b.periods[0] == pytest.approx(1.1, rel=1e-14)
    # Rayleigh quotient of the first shape gives T_1 again (independent of eigh's order)
    p1 = phi[:, 0]
    assert 2 * np.pi / math.sqrt(p1 @ K @ p1 / (p1 @ M @ p1)) == pytest.approx(1.1, rel=1e-12)


def test_shear_building_heights_are_cumulative_storey_heights():
    b = Building.shear(3, 0.4, heights=[4.5, 3.0, 3.0])
    assert np.allclose(b.heights, [0.0, 4.5 / 10.5, 7.5 / 10.5, 1.0], rtol=1e-15)
    top = b.modal_factors(height_ratio=7.5 / 10.5)[2]
    assert np.array_equal(top, b.modal_factors(floor=2)[2])


def test_per_mode_damping_and_repr():
    b = Building.shear(3, 0.4, damping=[0.02, 0.03, 0.04])
    assert np.array_equal(b.damping, [0.02, 0.03, 0.04])
    assert "3-storey shear building" in repr(b)


# ---------------------------------------------------------- continuous beam (C1)-(C7)

CANTILEVER_BETA_L = [1.8751, 4.6941, 7.8548, 10.9955]
"""Clamped-free Euler-Bernoulli beam, beta_j L (Thomson, *Theory of Vibration with
Applications*, App. D.3; any vibrations text)."""


def _cantilever_roots(n):
    """Roots of cos(x) cosh(x) + 1 = 0 (written here, not with our characteristic)."""
    return np.array([brentq(lambda x: math.cos(x) * math.cosh(x) + 1.0, (j - 1) * math.pi
                            + 1e-6, j * math.pi) for j in range(1, n + 1)])


def test_flexural_limit_alpha_0():
    """alpha = 0: gamma_j are the cantilever's beta_j L (published to 4 decimals, and
    roots of cos x cosh x = -1 to 1e-12); T_1/T_j = (gamma_j/gamma_1)^2 = 1, 6.27, 17.55,
    34.39 (the published ratios; 6.2669, 17.5475, 34.3861 to 4 decimals by (C2)); the
    shapes are the textbook cantilever shape cosh - cos - s (sinh - sin), s = (cosh g +
    cos g)/(sinh g + sin g), and Gamma_j its int phi / int phi^2 by quadrature."""
    b = Building.continuous(1.0, 0.0, n_modes=6)
    g = _cantilever_roots(6)
    assert np.allclose(b.shape_function.gammas, g, rtol=1e-12, atol=0)
    assert np.allclose(g[:4], CANTILEVER_BETA_L, rtol=0, atol=5e-5)
    ratios = b.periods[0] / b.periods
    assert np.allclose(ratios, (g / g[0]) ** 2, rtol=1e-12)
    assert np.allclose(ratios[:4], [1.0, 6.27, 17.55, 34.39], rtol=0, atol=5e-3)
    assert np.allclose(ratios[1:4], [6.2669, 17.5475, 34.3861], rtol=0, atol=5e-5)

    x = np.linspace(0.0, 1.0, 41)
    for jj, gj in enumerate(g[:4]):  # higher: cosh - s sinh cancels to ~cosh(g) eps
        s = (math.cosh(gj) + math.cos(gj)) / (math.sinh(gj) + math.sin(gj))

        def tb(y, gj=gj, s=s):
            return np.cosh(gj * y) - np.cos(gj * y) - s * (np.sinh(gj * y) - np.sin(gj * y))

        tip = tb(1.0)
        assert np.allclose(b.shape_function(x)[:, jj], tb(x) / tip, rtol=0, atol=1e-9)
        i1 = quad(lambda y, tb=tb: tb(y), 0, 1, epsabs=1e-13, epsrel=1e-13, limit=200)[0]
        i2 = quad(lambda y, tb=tb: tb(y) ** 2, 0, 1, epsabs=1e-13, epsrel=1e-13,
                  limit=200)[0]
        assert b.participation[jj] == pytest.approx(i1 / i2 * tip, rel=1e-9)
    # the classical tip participation of a cantilever's first mode, 1.566
    assert b.participation[0] == pytest.approx(1.566, abs=5e-4)


@pytest.mark.parametrize("alpha", [math.inf, 1e6, 1e12, 1e200])
def test_shear_limit_alpha_large(alpha):
    """alpha -> inf: T_1/T_j = 2j - 1, phi_j = sin(gamma_j x)/sin(gamma_j), Gamma_j =
    2 (-1)^(j+1) / gamma_j with gamma_j = (2j-1) pi/2 (roof participation 4/pi, -4/(3 pi),
    ...); the corrections are O(1/alpha)."""
    b = Building.continuous(2.0, alpha, n_modes=8)
    j = np.arange(1, 9)
    g = (2 * j - 1) * np.pi / 2
    tol = max(50.0 / alpha, 1e-13)  # the flexural boundary layer: gamma_8 / alpha = 24 / alpha
    assert np.allclose(b.periods[0] / b.periods, 2 * j - 1, rtol=tol, atol=0)
    assert np.allclose(b.participation, 2 * (-1.0) ** (j + 1) / g, rtol=0, atol=tol)
    x = np.linspace(0, 1, 101)[:, None]
    assert np.allclose(b.shape_function(x[:, 0]), np.sin(g * x) / np.sin(g), rtol=0,
                       atol=tol)
    assert np.all(np.isfinite(b.shape_function(x[:, 0])))


def test_alpha_continuity_at_both_ends():
    """Tiny alpha equals alpha = 0 and huge finite alpha equals alpha = inf (no jump
    between the limits and the general formulas)."""
    for a, lim in ((1e-300, 0.0), (1e-8, 0.0), (1e300, math.inf)):
        b, c = Building.continuous(1.0, a), Building.continuous(1.0, lim)
        assert np.allclose(b.periods, c.periods, rtol=1e-12)
        assert np.allclose(b.participation, c.participation, rtol=1e-10)


def _fe_beam(alpha, n_el):
    """Independent finite-element model of (C1): cubic Hermite elements, energy int u''^2
    + alpha^2 int u'^2 (EI = rho = H = 1), consistent mass, base clamped, top free (its
    conditions are natural). Returns omega_j, the shapes at the nodes (1 at the top) and
    Gamma_j = phi^T M r / phi^T M phi with r the rigid translation."""
    h = 1.0 / n_el
    kb = np.array([[12, 6 * h, -12, 6 * h], [6 * h, 4 * h * h, -6 * h, 2 * h * h],
                   [-12, -6 * h, 12, -6 * h], [6 * h, 2 * h * h, -6 * h, 4 * h * h]]) / h ** 3
    kg = np.array([[36, 3 * h, -36, 3 * h], [3 * h, 4 * h * h, -3 * h, -h * h],
                   [-36, -3 * h, 36, -3 * h], [3 * h, -h * h, -3 * h, 4 * h * h]]) / (30 * h)
    me = np.array([[156, 22 * h, 54, -13 * h], [22 * h, 4 * h * h, 13 * h, -3 * h * h],
                   [54, 13 * h, 156, -22 * h], [-13 * h, -3 * h * h, -22 * h, 4 * h * h]]
                  ) * h / 420
    n = 2 * (n_el + 1)
    K, M = np.zeros((n, n)), np.zeros((n, n))
    for e in range(n_el):
        s = slice(2 * e, 2 * e + 4)
        K[s, s] += kb + alpha ** 2 * kg
        M[s, s] += me
    K, M = K[2:, 2:], M[2:, 2:]
    w2, v = eigh(K, M)
    r = np.zeros(n - 2)
    r[::2] = 1.0
    gam = (v.T @ M @ r) / np.einsum("ij,ik,kj->j", v, M, v)
    u = v[::2]  # displacements at nodes 1..n_el
    scale = u[-1]
    return np.sqrt(w2), u / scale, gam * scale


@pytest.mark.parametrize("alpha", [0.0, 0.5, 2.0, 5.0, 12.0, 30.0])
def test_continuous_agrees_with_a_finite_element_beam(alpha):
    """(C2), (C5), (C6), (C3)-(C4) and (C7) against an independent FE model of (C1),
    converging to them: the frequencies omega_j ∝ gamma_j beta_j of the first 6 modes to
    2e-5 with 50 elements, error ratio ~16 (h^4) from 25 to 50 elements; the shapes at the
    nodes to 1e-6 with 200 elements; Gamma_j to 1e-5 with 200 elements, error ratio ~8
    (h^3) from 100 to 200."""
    b = Building.continuous(1.0, alpha, n_modes=6)
    g = b.shape_function.gammas
    lam = g * np.hypot(g, alpha)  # omega_j with EI = rho = H = 1, by (C2)
    assert np.allclose(lam / lam[0], b.periods[0] / b.periods, rtol=1e-13)
    e25, e50 = (np.abs(_fe_beam(alpha, n)[0][:6] / lam - 1) for n in (25, 50))
    assert np.all(e50 < 2e-5)
    big = e50 > 1e-8  # above round-off (the first mode is 1e-9 already)
    assert big.sum() >= 4 and np.all((e25 / e50)[big] > 12) and np.all((e25 / e50)[big] < 20)
    _, u100, gam100 = _fe_beam(alpha, 100)
    _, u200, gam200 = _fe_beam(alpha, 200)
    x = np.arange(1, 201) / 200
    assert np.allclose(b.shape_function(x), u200[:, :6], rtol=0, atol=1e-6)
    g100, g200 = (np.max(np.abs(b.participation - gm[:6])) for gm in (gam100, gam200))
    assert g200 < 1e-5 and 6 < g100 / g200 < 10


@pytest.mark.parametrize("alpha", [0.0, 2.0, 10.0, 100.0])
def test_continuous_shapes_are_orthogonal_and_integrals_exact(alpha):
    """int phi_i phi_j dx = 0 (i != j) for the uniform beam, by quadrature; the closed-form
    integrals behind (C7) equal quadrature; phi(0) = 0, phi(1) = 1; the shapes at the
    floors are the shape function at k/n_floors; modal_factors(height_ratio) is Gamma phi."""
    b = Building.continuous(1.0, alpha, n_modes=6, n_floors=7)
    f = b.shape_function
    beta = math.hypot(f.gammas[-1], alpha)
    pts = sorted({min(0.5, 3 / beta), max(0.5, 1 - 3 / beta)})

    def q(fun):
        return quad(fun, 0, 1, epsabs=1e-14, epsrel=1e-13, limit=400, points=pts)[0]

    gram = np.array([[q(lambda x, i=i, j=j: f(x)[i] * f(x)[j]) for j in range(6)]
                     for i in range(6)])
    d = np.sqrt(np.diag(gram))
    assert np.max(np.abs(gram / np.outer(d, d) - np.eye(6))) < 1e-10
    i1, i2 = f.integrals()
    assert np.allclose(i2, np.diag(gram), rtol=1e-11)
    assert np.allclose(i1, [q(lambda x, i=i: f(x)[i]) for i in range(6)], rtol=0, atol=1e-12)
    assert np.allclose(b.participation, i1 / i2, rtol=1e-14)
    assert np.allclose(f(0.0), 0.0, atol=1e-13) and np.allclose(f(1.0), 1.0, rtol=1e-14)
    assert np.allclose(b.shapes, f(np.arange(8) / 7), rtol=0, atol=1e-13)
    assert np.array_equal(b.heights, np.arange(8) / 7)
    om, ze, gp = b.modal_factors(height_ratio=0.37)
    assert np.allclose(gp, b.participation * f(0.37), rtol=1e-15)
    assert np.array_equal(b.modal_factors(floor=3)[2], b.participation * b.shapes[3])


@pytest.mark.parametrize("alpha", [0.0, 3.0, 20.0, math.inf])
def test_continuous_effective_masses_tend_to_the_total_mass(alpha):
    """Parseval for the complete, orthogonal shapes of the uniform beam: sum_j Gamma_j^2
    int phi_j^2 = int 1^2 = 1 (the total mass), approached from below (50 modes leave less
    than 1 %). For the shear beam Gamma_j^2 int phi_j^2 = 8/((2j-1) pi)^2: 6 modes carry
    0.9663 (the docstring's truncation note) and 50 modes all but the tail sum_{j>50}
    8/((2j-1) pi)^2 ≈ (8/pi^2) int_100^inf dk / (2 k^2) = 8/(200 pi^2) = 4.05e-3."""
    def eff(n):
        b = Building.continuous(1.0, alpha, n_modes=n)
        i1, i2 = b.shape_function.integrals()
        return np.sum(b.participation ** 2 * i2)

    e6, e50 = eff(6), eff(50)
    assert e6 < e50 < 1.0
    assert 1.0 - e50 < 1e-2
    if math.isinf(alpha):
        j = np.arange(1, 51)
        exact = 8 / ((2 * j - 1) * np.pi) ** 2
        assert e6 == pytest.approx(np.sum(exact[:6]), rel=1e-14)
        assert e6 == pytest.approx(0.9663, abs=5e-5)
        assert e50 == pytest.approx(np.sum(exact), rel=1e-14)
        assert 1.0 - e50 == pytest.approx(8 / (200 * np.pi ** 2), rel=1e-3)


def test_characteristic_has_one_root_per_interval():
    """The bracketing of (C5): one sign change of :func:`characteristic` in each
    ((j-1) pi, j pi), j <= 12, on a fine grid, for alpha from 0 to 1e4."""
    gam = np.linspace(1e-6, 12 * np.pi, 24001)
    for alpha in np.concatenate([[0.0], np.logspace(-2, 4, 25)]):
        v = np.array([characteristic(x, alpha) for x in gam])
        changes = gam[1:][np.sign(v[1:]) != np.sign(v[:-1])]
        assert np.array_equal(np.ceil(changes / np.pi), np.arange(1, 13)), alpha


def test_large_alpha_agrees_with_a_200_storey_shear_building():
    """The uniform shear building is a lumped model of the shear beam: with alpha large,
    T_1/T_j, phi_j and Gamma_j phi_j of the first 4 modes agree with N = 200 storeys, and
    the difference halves from N = 100 to N = 200 (first order in 1/N: the roof mass is
    lumped)."""
    c = Building.continuous(1.0, 1e6, n_modes=4)
    errs = []
    for n in (100, 200):
        s = Building.shear(n, 1.0)
        x = s.heights
        e_t = np.max(np.abs(s.periods[0] / s.periods[:4] - c.periods[0] / c.periods) /
                     (c.periods[0] / c.periods))
        e_phi = np.max(np.abs(s.shapes[:, :4] - c.shape_function(x)))
        e_gp = np.max(np.abs(s.shapes[:, :4] * s.participation[:4]
                             - c.shape_function(x) * c.participation))
        errs.append((e_t, e_phi, e_gp))
    (t1, p1, g1), (t2, p2, g2) = errs
    assert t2 < 3e-4 and p2 < 0.05 and g2 < 0.01
    assert 1.8 < p1 / p2 < 2.2 and 1.8 < g1 / g2 < 2.2 and 3.5 < t1 / t2 < 4.5


# --------------------------------------------------------------------- bad input


@pytest.mark.parametrize("kwargs, name", [
    (dict(n_storeys=0, period=1.0), "n_storeys"),
    (dict(n_storeys=1001, period=1.0), "n_storeys"),
    (dict(n_storeys=3.0, period=1.0), "n_storeys"),
    (dict(n_storeys=True, period=1.0), "n_storeys"),
    (dict(n_storeys=3, period=0.0), "period"),
    (dict(n_storeys=3, period=-1.0), "period"),
    (dict(n_storeys=3, period=math.nan), "period"),
    (dict(n_storeys=3, period=math.inf), "period"),
    (dict(n_storeys=3, period="1 s"), "period"),
    (dict(n_storeys=3, period=1.0, damping=1.0), "damping"),
    (dict(n_storeys=3, period=1.0, damping=-0.01), "damping"),
    (dict(n_storeys=3, period=1.0, damping=True), "damping"),
    (dict(n_storeys=3, period=1.0, damping=[0.05, 0.05]), "damping"),
    (dict(n_storeys=3, period=1.0, damping=[0.05, 0.05, 1.5]), r"damping\[2\]"),
    (dict(n_storeys=3, period=1.0, masses=[1.0, 1.0]), "masses"),
    (dict(n_storeys=3, period=1.0, masses=[1.0, 0.0, 1.0]), r"masses\[1\]"),
    (dict(n_storeys=3, period=1.0, masses=[1.0, math.nan, 1.0]), r"masses\[1\]"),
    (dict(n_storeys=3, period=1.0, masses="heavy"), "masses"),
    (dict(n_storeys=3, period=1.0, stiffnesses=[1.0, -1.0, 1.0]), r"stiffnesses\[1\]"),
    (dict(n_storeys=3, period=1.0, stiffnesses=[[1.0, 1.0, 1.0]]), "stiffnesses"),
    (dict(n_storeys=3, period=1.0, heights=[3.0, 3.0]), "heights"),
    (dict(n_storeys=3, period=1.0, heights=[3.0, 0.0, 3.0]), r"heights\[1\]"),
])
def test_shear_bad_input_names_the_parameter(kwargs, name):
    with pytest.raises(ParameterError, match=name):
        Building.shear(**kwargs)


@pytest.mark.parametrize("kwargs, name", [
    (dict(period=0.0, alpha=1.0), "period"),
    (dict(period=1.0, alpha=-1.0), "alpha"),
    (dict(period=1.0, alpha=-math.inf), "alpha"),
    (dict(period=1.0, alpha=math.nan), "alpha"),
    (dict(period=1.0, alpha=True), "alpha"),
    (dict(period=1.0, alpha="shear"), "alpha"),
    (dict(period=1.0, alpha=1.0, damping=1.0), "damping"),
    (dict(period=1.0, alpha=1.0, damping=[0.05] * 5), "damping"),
    (dict(period=1.0, alpha=1.0, n_modes=0), "n_modes"),
    (dict(period=1.0, alpha=1.0, n_modes=51), "n_modes"),
    (dict(period=1.0, alpha=1.0, n_modes=3.0), "n_modes"),
    (dict(period=1.0, alpha=1.0, n_floors=0), "n_floors"),
    (dict(period=1.0, alpha=1.0, n_floors=1001), "n_floors"),
    (dict(period=1.0, alpha=1.0, n_floors=2.5), "n_floors"),
])
def test_continuous_bad_input_names_the_parameter(kwargs, name):
    with pytest.raises(ParameterError, match=name):
        Building.continuous(**kwargs)


def test_range_is_in_the_message():
    with pytest.raises(ParameterError, match=r"\[0, inf\]"):
        Building.continuous(1.0, -2.0)
    with pytest.raises(ParameterError, match=r"\[1, 1000\]"):
        Building.shear(0, 1.0)
    with pytest.raises(ParameterError, match=r"\[0, 1\)"):
        Building.shear(2, 1.0, damping=2.0)


def test_shape_function_and_height_ratio_checks():
    b = Building.continuous(1.0, 3.0)
    with pytest.raises(ParameterError, match="height_ratio"):
        b.shape_function(1.5)
    with pytest.raises(ParameterError, match="floor"):
        b.modal_factors(floor=1)  # no floors without n_floors
    with pytest.raises(ParameterError, match="height_ratio"):
        b.modal_factors(height_ratio=-0.1)


def test_modal_heights_of_floors_1_to_n_line_up_with_the_shapes():
    """Heights given for floors 1..N (as the shapes are) are those floors' z/H."""
    shapes, gam = [[0.4, 1.0], [1.0, -0.6]], [1.3, -0.35]
    b = Building.modal([1.2, 0.35], 0.05, shapes, gam, heights=[0.5, 1.0])
    assert np.array_equal(b.modal_factors(height_ratio=0.5)[2], b.modal_factors(floor=1)[2])
    assert np.array_equal(b.modal_factors(height_ratio=1.0)[2], np.array(gam) * shapes[1])
    with pytest.raises(ParameterError, match="heights"):
        Building.modal([1.2, 0.35], 0.05, shapes, gam, heights=[1.0, 0.5])
    with pytest.raises(ParameterError, match="heights"):
        Building.modal([1.2, 0.35], 0.05, shapes, gam, heights=[0.5, 1.0, 1.5])


# ------------------------------------------------------------ the plain reference


def _ramp_acceleration(w, z, c, t):
    """u_j'' of (B1) under a_g = c t from rest: u = -c t/w^2 + 2 z c/w^3 + e^{-z w t} (A
    cos w_d t + B sin w_d t), A = -2 z c/w^3, B = (c/w^2 + z w A)/w_d."""
    wd = w * math.sqrt(1 - z * z)
    A = -2 * z * c / w ** 3
    B = (c / w ** 2 + z * w * A) / wd
    e, co, si = np.exp(-z * w * t), np.cos(wd * t), np.sin(wd * t)
    return e * ((z * z * w * w - wd * wd) * (A * co + B * si)
                - 2 * z * w * wd * (B * co - A * si))


@pytest.mark.parametrize("floor", [0, 1, 3, 5])
def test_reference_direct_integration_equals_modal_closed_form(floor):
    """The reference integrates M u'' + C u' + K u = -M 1 a_g directly; under a ramp a_g =
    c t its absolute floor acceleration equals (B2) with each mode's closed-form ramp
    response, to 1e-10 of the peak (measured ~1e-11)."""
    b, _, _ = _random_building(5, 7, T1=0.6)
    b = Building.shear(5, 0.6, damping=[0.02, 0.05, 0.03, 0.08, 0.05],
                       masses=b.storey_masses, stiffnesses=b.storey_stiffnesses)
    t = np.linspace(0.0, 2.0, 41)
    c = 1.7
    a = floor_response(arrays_of(b), t, c * t, floor)
    om, ze, gp = b.modal_factors(floor=floor)
    exact = c * t + sum(g * _ramp_acceleration(w, z, c, t)
                        for w, z, g in zip(om, ze, gp, strict=True))
    assert np.max(np.abs(a - exact)) < 1e-10 * np.max(np.abs(exact))


def test_reference_matrices():
    """K assembled storey by storey equals the building's; C is classical: Phi^T C Phi =
    diag(2 zeta_j omega_j m_j) in the building's modes (Chopra 11.4)."""
    b, masses, stiff = _random_building(6, 11)
    b = Building.shear(6, 1.1, damping=np.linspace(0.01, 0.06, 6), masses=masses,
                       stiffnesses=stiff)
    M, C, K = arrays_of(b)
    assert np.allclose(K, b.stiffness_matrix, rtol=0, atol=1e-14 * np.max(K))
    assert np.array_equal(M, b.mass_matrix)
    phi = b.shapes[1:]
    mj = np.einsum("ij,ik,kj->j", phi, M, phi)
    cd = phi.T @ C @ phi
    assert np.allclose(cd, np.diag(2 * b.damping * b.omegas * mj), rtol=0,
                       atol=1e-11 * np.max(np.abs(cd)))
    with pytest.raises(ParameterError, match="shear building"):
        arrays_of(Building.sdof(0.5))
    assert shear_building_arrays([1.0], [4.0], 0.0).C[0, 0] == 0.0
