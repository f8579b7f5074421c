"""Seal solid: Q1/P0 finite-strain Neo-Hooke elements against independent truth.

* element residual = gradient of the element energy, tangent = derivative of the residual
  (central differences; relative difference bound stated below);
* patch test: a homogeneous deformation is reproduced exactly on a distorted mesh;
* uniaxial and equibiaxial stretch against the closed-form compressible Neo-Hooke stress
  sigma = 2 C10 J^(-5/3) dev(b) + (2/D1)(J - 1) I, lateral stretch found by bisection;
* Cook's membrane with K/G ~ 940: coarse meshes already near the converged tip deflection
  (no volumetric locking);
* an axisymmetric ring far from the axis behaves like plane strain.
"""
import numpy as np
import pytest

from sealts.mesh.structured import quad_patch, rectangle
from sealts.problem import Constraints, Problem
from sealts.solid.loads import NodalForces
from sealts.solid.q1p0 import element_dofs, element_forces, gauss_operators
from sealts.solid.term import Hyperelastic, NeoHooke, SolidTerm

RUBBER = NeoHooke(c10=1.064, d1=0.001)  # the paper's EPDM, K/G ~ 940
FD_REL = 1e-8


@pytest.mark.parametrize("axisym", [True, False])
@pytest.mark.parametrize("j_th", [1.0, 1.03])
@pytest.mark.parametrize("c01", [0.0, 0.4], ids=["neo-hooke", "mooney-rivlin"])
def test_element_residual_and_tangent_against_finite_differences(axisym, j_th, c01):
    X = np.array([[1.0, 0.0], [2.0, 0.1], [2.2, 1.0], [0.9, 1.2], [3.0, 0.2], [3.1, 1.1]])
    conn = np.array([[0, 1, 2, 3], [1, 4, 5, 2]])
    W, B, _ = gauss_operators(X, conn, axisym)
    dofs = element_dofs(conn)
    u = np.random.default_rng(1).uniform(-0.1, 0.1, 12)

    def evaluate(u):
        r, K, E, ok, *_ = element_forces(u, conn, W, B, 1.064, c01, 0.001, j_th)
        g = np.bincount(dofs.ravel(), r.ravel(), minlength=12)
        Kg = np.zeros((12, 12))
        for e in range(2):
            Kg[np.ix_(dofs[e], dofs[e])] += K[e]
        return g, E, Kg, ok

    g, _, K, ok = evaluate(u)
    assert ok
    eps = 1e-6
    Kfd, gfd = np.zeros((12, 12)), np.zeros(12)
    for j in range(12):
        d = np.zeros(12)
        d[j] = eps
        gp, Ep, _, _ = evaluate(u + d)
        gm, Em, _, _ = evaluate(u - d)
        Kfd[:, j] = (gp - gm) / (2 * eps)
        gfd[j] = (Ep - Em) / (2 * eps)
    assert np.abs(g - gfd).max() / np.abs(g).max() < FD_REL
    assert np.abs(K - Kfd).max() / np.abs(K).max() < FD_REL
    assert np.abs(K - K.T).max() / np.abs(K).max() < 1e-12   # hyperelastic: symmetric


def test_inverted_element_is_reported():
    X, conn, _ = rectangle(1.0, 2.0, 0.0, 1.0, 1, 1)
    W, B, _ = gauss_operators(X, conn, True)
    u = np.zeros(8)
    u[2] = -2.0  # node 1 pulled through node 0
    # Neo-Hooke and Mooney-Rivlin, with and without tangents: reported, never raised
    for c01 in (0.0, 0.3):
        for tangent in (True, False):
            assert not element_forces(u, conn, W, B, 1.0, c01, 0.001, 1.0, tangent)[3]


def test_element_kernel_does_not_depend_on_the_threads():
    """element_forces shares its elements among numba's threads, each block with its own
    work arrays: one thread and two give the same bits (forces, tangents, energy, the
    inverted-element flag, Gauss-point state), with and without tangents."""
    import numba
    if numba.config.NUMBA_NUM_THREADS < 2:
        pytest.skip("numba has one thread here (NUMBA_NUM_THREADS): nothing to compare")
    X, conn, _ = rectangle(1.0, 2.0, 0.0, 1.0, 12, 9)
    W, B, _ = gauss_operators(X, conn, True)
    u = np.random.default_rng(3).uniform(-0.05, 0.05, 2 * X.shape[0])
    u[2 * conn[40, 1]] -= 1.0                   # and one element inverted
    before = numba.get_num_threads()
    try:
        for c01, tangent in ((0.0, True), (0.3, False)):
            out = []
            for threads in (1, 2):
                numba.set_num_threads(threads)
                out.append(element_forces(u, conn, W, B, 1.0, c01, 0.001, 1.0, tangent))
            assert not out[0][3] and not out[1][3]
            for a, b in zip(*out):
                assert np.array_equal(a, b)
    finally:
        numba.set_num_threads(before)


def solve_static(term, n, fixed, values, loads=()):
    """Equilibrium under prescribed displacements and loads, both ramped over a pseudo-time
    0..1 by TS (the way mounting is done): a step whose Newton solve fails is retried."""
    values = np.asarray(values, float)
    for load in loads:
        load.scale = lambda t: t
    problem = Problem(n, [term, *loads], constraints=Constraints(fixed, lambda t: t * values),
                      linesearch="basic")
    u = problem.transient(np.zeros(n), 0.0, 1.0, 0.25)
    return u, problem


@pytest.mark.parametrize("axisym", [True, False])
def test_patch_test_homogeneous_deformation_is_exact(axisym):
    X, conn, grid = quad_patch([[1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]], 3, 3)
    interior = grid[1:-1, 1:-1].ravel()
    X[interior] += np.random.default_rng(3).uniform(-0.12, 0.12, (interior.size, 2))
    if axisym:   # u_r = a r, u_z = b z: F = diag(1 + a, 1 + b, 1 + a), uniform stress
        F = np.array([[1.08, 0.0], [0.0, 0.93]])
    else:
        F = np.array([[1.08, 0.06], [-0.04, 0.93]])
    exact = (X @ (F - np.eye(2)).T).ravel()
    boundary = np.setdiff1d(np.arange(X.shape[0]), interior)
    fixed = np.stack([2 * boundary, 2 * boundary + 1], 1).ravel()
    term = SolidTerm(X, conn, RUBBER, axisym)
    u, _ = solve_static(term, exact.size, fixed, exact[fixed])
    assert np.abs(u - exact).max() < 1e-10


def hyperelastic_stress(l1, l2, l3, c10=1.064, d1=0.001, c01=0.0):
    """Principal Cauchy stresses of compressible Mooney-Rivlin (Neo-Hooke for c01 = 0) for
    stretches l1, l2, l3: sigma = (2/J) dev[(C10 + C01 I1bar) bbar - C01 bbar^2] + U'(J) I,
    bbar = J^-2/3 b."""
    J = l1 * l2 * l3
    bb = J ** (-2 / 3) * np.array([l1, l2, l3]) ** 2
    s = (c10 + c01 * bb.sum()) * bb - c01 * bb**2
    return 2 / J * (s - s.sum() / 3) + 2 / d1 * (J - 1)


def bisect(f, a, b):
    for _ in range(200):
        m = 0.5 * (a + b)
        if f(a) * f(m) <= 0:
            b = m
        else:
            a = m
    return 0.5 * (a + b)


MOONEY = Hyperelastic(c10=0.8, d1=0.001, c01=0.3)


@pytest.mark.parametrize("mat", [RUBBER, MOONEY], ids=["neo-hooke", "mooney-rivlin"])
def test_uniaxial_stretch_of_a_cylinder(mat):
    """Axisymmetric cylinder r < 1, 0 < z < 1 stretched to lambda along z, free mantle."""
    law = dict(c10=mat.c10, d1=mat.d1, c01=mat.c01)
    lam = 1.3
    X, conn, grid = rectangle(0.0, 1.0, 0.0, 1.0, 4, 4)
    bottom, top, axis = grid[0], grid[-1], grid[:, 0]
    fixed = np.concatenate([2 * bottom + 1, 2 * top + 1, 2 * axis])
    values = np.concatenate([0 * bottom, (lam - 1) * np.ones(top.size), 0 * axis])
    fixed, idx = np.unique(fixed, return_index=True)
    term = SolidTerm(X, conn, mat, True)
    u, problem = solve_static(term, 2 * X.shape[0], fixed, values[idx])
    lt = bisect(lambda x: hyperelastic_stress(x, lam, x, **law)[0], 0.5, 1.0)
    s_zz = hyperelastic_stress(lt, lam, lt, **law)[1]
    # lateral contraction and axial force (reaction on the top face) against the closed form
    assert u[2 * grid[0, -1]] == pytest.approx(lt - 1.0, rel=1e-9)
    f_int = np.zeros(u.size)
    term.add_residual(0.0, u, None, f_int)
    force = f_int[2 * top + 1].sum()
    assert force == pytest.approx(s_zz * np.pi * lt**2, rel=1e-9)


def test_equibiaxial_stretch_of_a_plate():
    """Axisymmetric plate 1 < r < 2 stretched radially so F11 = F33 = lambda at r = 1, 2;
    a homogeneous state needs u_r = (lambda - 1) r, free faces in z."""
    lam = 1.2
    X, conn, grid = rectangle(1.0, 2.0, 0.0, 0.5, 3, 2)
    radial = 2 * np.arange(X.shape[0])
    bottom = grid[0]
    fixed = np.concatenate([radial, 2 * bottom + 1])
    values = np.concatenate([(lam - 1) * X[:, 0], 0 * bottom])
    term = SolidTerm(X, conn, RUBBER, True)
    u, _ = solve_static(term, 2 * X.shape[0], fixed, values)
    lz = bisect(lambda x: hyperelastic_stress(lam, x, lam)[1], 0.3, 1.0)
    assert u[2 * grid[-1, 0] + 1] == pytest.approx(0.5 * (lz - 1.0), rel=1e-9)
    s_rr = hyperelastic_stress(lam, lz, lam)[0]
    f_int = np.zeros(u.size)
    term.add_residual(0.0, u, None, f_int)
    outer = grid[:, -1]
    # radial force on the outer face: sigma_rr times its current area 2 pi (2 lam)(0.5 lz)
    assert f_int[2 * outer].sum() == pytest.approx(s_rr * 2 * np.pi * 2 * lam * 0.5 * lz,
                                                   rel=1e-9)


def cook_tip_deflection(n, material=RUBBER, total_force=0.05):
    X, conn, grid = quad_patch([[0, 0], [48, 44], [48, 60], [0, 44]], n, n)
    term = SolidTerm(X, conn, material, False)
    left = grid[:, 0]
    fixed = np.concatenate([2 * left, 2 * left + 1])
    right = grid[:, -1]
    w = np.full(right.size, 1.0 / n)
    w[[0, -1]] *= 0.5
    load = NodalForces(2 * right + 1, total_force * w)
    u, _ = solve_static(term, 2 * X.shape[0], fixed, np.zeros(fixed.size), [load])
    return u[2 * grid[-1, -1] + 1]


def test_cooks_membrane_does_not_lock():
    """Plane strain Cook's membrane. Volumetric locking shows as coarse meshes that grow much
    stiffer when K/G rises. Here the coarse-to-fine deflection ratio at K/G ~ 940 (rubber)
    matches the one at K/G = 2.2 (nu = 0.3), where nothing can lock, within 5 %; what remains
    is ordinary bending stiffness of coarse four-node quads. The sequence converges
    monotonically."""
    soft = NeoHooke(c10=1.064, d1=2 / (2.2 * 2 * 1.064))
    ratios = []
    for mat in (RUBBER, soft):
        tips = [cook_tip_deflection(n, mat) for n in (2, 4, 8, 16, 32)]
        assert np.all(np.diff(tips) > 0)
        assert abs(tips[-1] - tips[-2]) < 0.02 * tips[-1]
        ratios.append(np.array(tips[:3]) / tips[-1])
    assert np.all(ratios[0] > 0.95 * ratios[1]), ratios
    assert ratios[0][1] > 0.8


def test_axisymmetric_far_from_axis_is_plane_strain():
    """A block at radius R0 = 1e4 mm behaves like plane strain to O(size / R0)."""
    def deflection(axisym, r0):
        X, conn, grid = rectangle(r0, r0 + 2.0, 0.0, 4.0, 4, 8)
        term = SolidTerm(X, conn, RUBBER, axisym)
        bottom = grid[0]
        fixed = np.concatenate([2 * bottom, 2 * bottom + 1])
        top = grid[-1]
        area = 2 * np.pi * r0 if axisym else 1.0
        w = np.full(top.size, 0.5)
        w[[0, -1]] = 0.25
        load = NodalForces(np.concatenate([2 * top, 2 * top + 1]),
                           area * np.concatenate([0.02 * w, -0.05 * w]))
        u, _ = solve_static(term, 2 * X.shape[0], fixed, np.zeros(fixed.size), [load])
        return u
    ps = deflection(False, 1e4)
    ax = deflection(True, 1e4)
    assert np.abs(ax - ps).max() < 2e-3 * np.abs(ps).max()


def test_free_thermal_expansion_is_stress_free_and_uniform():
    """A ring free but for axial rollers on its lower face, heated by dT: it grows uniformly,
    u = alpha dT X (Eq. 3-5), the exact stress-free state."""
    mat = NeoHooke(c10=1.064, d1=0.001, alpha_th=2e-4, d_theta=40.0)
    X, conn, grid = rectangle(25.0, 27.0, 0.0, 2.0, 4, 4)
    term = SolidTerm(X, conn, mat, True, heating=lambda t: t)
    bottom = grid[0]
    u, _ = solve_static(term, 2 * X.shape[0], 2 * bottom + 1, np.zeros(bottom.size))
    eps = 2e-4 * 40.0
    assert np.abs(u - eps * X.ravel()).max() < 1e-9


def test_an_inverted_element_is_named_where_it_is():
    """Two plane-strain unit squares side by side; the right one's free corner nodes pushed
    past its left edge (x 2 -> 0.5) turn it inside out (J < 0 at its Gauss points): the
    residual is not finite and ``nonfinite`` names one element at the right square's
    undeformed centroid (1.5, 0.5); undeformed, nothing."""
    X, conn, grid = rectangle(0.0, 2.0, 0.0, 1.0, 2, 1)
    term = SolidTerm(X, conn, RUBBER, False)
    u = np.zeros(2 * X.shape[0])
    assert term.nonfinite(0.0, u) is None
    right = grid[:, -1]
    u[2 * right] = -1.5
    f = np.zeros(u.size)
    term.add_residual(0.0, u, None, f)
    assert not np.isfinite(f).all()
    msg = term.nonfinite(0.0, u)
    assert msg.startswith("1 element(s) of the seal invert")
    assert "r = 1.5, z = 0.5 mm" in msg, msg
