"""Asperity friction on the rod side (RodFriction, paper Eq. 46-48).

Each check is measured against something computed another way: the Jacobian against central
differences of the residual; the sliding and sticking forces against the rod contact's own
normal forces (RodContact.forces, checked in test_mount) times mu_s and times the penalty
slope; the anchor update against its definition (slip capped, forces unchanged); and a
spring held by friction against the closed form of a linear spring on a stick-slip contact.
"""
import numpy as np
import pytest

from sealts.contact.asperity import ExponentialLaw
from sealts.contact.friction import RodFriction, saturation
from sealts.contact.rod_side import RodSide
from sealts.contact.rigid import RodContact
from sealts.mesh.seal_mesh import ORing, build_mesh
from sealts.problem import Constraints, Problem, Term

GC = 1e-4          # gamma_crit (mm), the default
H_MIX, P_MIX = 7e-4, 15.0


def oring_chain(tmp_path, seed=0):
    """The coarse O-ring's rod side with its chain nodes spread over gaps from beyond the
    tangent continuation (h < -h_mix) through contact to open (h > h_mix), and a random
    axial displacement. Returns (X, chain, rod, u)."""
    m = build_mesh(ORing(50.17, 5.33), 0.3, 0.6, cache_dir=tmp_path)
    X = m.X
    chain = m.chain("rod_side")
    rng = np.random.default_rng(seed)
    n = 2 * X.shape[0]
    u = rng.uniform(-2e-4, 2e-4, n)
    r_rod = 25.0
    rod = RodContact(RodSide(X, chain, lambda t: r_rod, 2 * np.pi * r_rod),
                     ExponentialLaw(H_MIX, P_MIX))
    # gaps 1.2e-4 apart, the nearest 1.5e-5 from the law's kinks at +-h_mix
    h = rng.permutation(np.linspace(-9.3e-4, 1.03e-3, chain.size))
    u[rod.side.ur] = r_rod + h - X[chain, 0]
    return X, chain, rod, u


def test_saturation_is_c1_odd_and_bounded():
    """phi: the identity up to 1 - blend, exactly +-1 from 1 on, values and slopes continuous
    at both joints, odd, |phi| <= 1, and phi' the derivative of phi (central differences)."""
    for blend in (0.5, 0.2, 1.0):
        x0 = 1.0 - blend
        for xj in (x0, 1.0):
            (pl, pr), (dl, dr) = saturation(np.array([xj - 1e-12, xj + 1e-12]), blend)
            assert pr == pytest.approx(pl, abs=1e-11)
            assert dr == pytest.approx(dl, abs=1e-10)
        x = np.linspace(-3, 3, 6001)
        phi, dphi = saturation(x, blend)
        assert np.array_equal(phi, -saturation(-x, blend)[0])
        assert np.abs(phi).max() == 1.0 and np.all(dphi >= 0) and dphi.max() <= 4 / 3 + 1e-12
        lin = np.abs(x) <= x0
        assert np.array_equal(phi[lin], x[lin]) and np.all(np.abs(phi[np.abs(x) >= 1]) == 1)
        e = 1e-6
        fd = (saturation(x + e, blend)[0] - saturation(x - e, blend)[0]) / (2 * e)
        assert np.abs(fd - dphi).max() < 1e-5


def test_friction_jacobian(tmp_path):
    """Every entry of d(residual)/du of the friction term (u_z rows; u_r, own and neighbour
    u_z columns) against central differences, relative bound 1e-6 entry by entry, with slips
    in stick, the blend and sliding (both signs), a ramped mu_s(t) and a moving rod."""
    X, chain, rod, u = oring_chain(tmp_path)
    n = u.size
    t = 0.7
    fric = RodFriction(rod, slip=lambda t: 3e-4 * t, mu_s=lambda t: 0.1 * t)
    # slips / gamma_crit away from the kinks of phi at 0.5 and 1 (the central differences
    # step 1e-4 in them)
    x = np.array([-3.0, -0.9, -0.7, -0.2, 0.1, 0.4, 0.6, 0.8, 0.95, 2.0, 0.0, 0.3, -0.45,
                  -0.6, 1.3, 0.75, -1.7])
    fric.anchors = fric.s(t) - u[rod.side.uz] - x[:chain.size] * GC
    assert np.allclose(fric.slip(t, u), x[:chain.size] * GC, rtol=0, atol=1e-15)
    problem = Problem(n, [fric])
    J = problem.jacobian_dense(t, u, np.zeros(n), 5.0)
    fd = np.zeros((n, n))
    cols = np.unique(fric.cols)
    eps = {c: 2e-8 for c in rod.side.ur} | {c: 1e-8 for c in rod.side.uz}
    for j in cols:
        e = np.zeros(n)
        e[j] = eps[j]
        fd[:, j] = (problem.residual(t, u + e, u) - problem.residual(t, u - e, u)) / (2 * e[j])
    assert np.all(J[:, np.setdiff1d(np.arange(n), cols)] == 0)
    nz = J != 0
    assert np.all(np.abs(fd[~nz]) <= 1e-9 * np.abs(J).max())
    rel = np.abs(J[nz] - fd[nz]) / np.abs(J[nz])
    assert rel.max() < 1e-6, rel.max()
    # the check saw every kind of entry: contact, neighbours' lengths, stick and blend slopes
    p, _ = rod.pressure(t, u)
    assert (p > 0).sum() >= 10 and (p == 0).sum() >= 2
    assert np.count_nonzero(J[np.ix_(rod.side.uz, rod.side.ur)]) >= 8


@pytest.mark.parametrize("direction", [1.0, -1.0])
def test_coulomb_limit_in_sliding(tmp_path, direction):
    """|gamma| >> gamma_crit: every nodal force is mu_s times the rod's normal force on that
    node, the total mu_s times the rod's total, signed with the rod's motion (the rod drags
    the seal along)."""
    X, chain, rod, u = oring_chain(tmp_path, seed=1)
    mu = 0.1
    fric = RodFriction(rod, slip=lambda t: direction * 0.05 * t, mu_s=mu)  # 500 gamma_crit
    normal = rod.forces(1.0, u)
    assert np.all(np.abs(fric.slip(1.0, u)) > 100 * GC)
    assert np.allclose(fric.forces(1.0, u), direction * mu * normal, rtol=1e-14, atol=0)
    assert fric.total(1.0, u) == pytest.approx(direction * mu * normal.sum(), rel=1e-13)
    assert np.sign(fric.total(1.0, u)) == direction and normal.sum() > 0


def test_stick_is_the_penalty_law(tmp_path):
    """From zero elastic slip (reset), a rod displacement delta << gamma_crit gives
    F_i = mu_s p_s A L_i delta / gamma_crit on every node, proportional to delta; the seal
    carried along with the rod (u_z += delta) feels none."""
    X, chain, rod, u = oring_chain(tmp_path, seed=2)
    mu = 0.1
    fric = RodFriction(rod, slip=lambda t: t, mu_s=mu)
    fric.reset(0.0, u)
    normal = rod.forces(0.0, u)
    for delta in (1e-3 * GC, 2e-3 * GC, -5e-3 * GC):
        f = fric.forces(delta, u)
        assert np.allclose(f, mu * normal * delta / GC, rtol=1e-9, atol=0)
    f1, f2 = fric.total(1e-3 * GC, u), fric.total(2e-3 * GC, u)
    assert f1 > 0 and f2 == pytest.approx(2 * f1, rel=1e-9)
    carried = u.copy()
    carried[rod.side.uz] += 1e-3 * GC
    assert np.abs(fric.forces(1e-3 * GC, carried)).max() <= 1e-12 * np.abs(normal).max()


def test_anchor_update_caps_slip_and_keeps_friction_locked(tmp_path):
    """update(): afterwards |gamma_i| <= gamma_crit (0 out of contact) and the residual and
    Jacobian at that state are unchanged. A rod moved by 20 gamma_crit in steps (update
    after each) then stopped leaves the friction at the Coulomb limit, however often it is
    updated; moving back by 0.6 gamma_crit unloads elastically to 0.4 of it; moving back by
    3 gamma_crit reaches the opposite limit."""
    X, chain, rod, u = oring_chain(tmp_path, seed=3)
    n, mu = u.size, 0.1
    fric = RodFriction(rod, slip=lambda t: t, mu_s=mu)
    rng = np.random.default_rng(4)
    fric.anchors = rng.uniform(-5 * GC, 5 * GC, chain.size)
    problem = Problem(n, [fric])
    z = np.zeros(n)
    f0, J0 = problem.residual(0.0, u, z), problem.jacobian_dense(0.0, u, z, 0.0)
    moved = fric.update(0.0, u)
    gamma = fric.slip(0.0, u)
    p, _ = rod.pressure(0.0, u)
    assert moved > GC and np.all(np.abs(gamma) <= GC * (1 + 1e-12))
    assert np.all(np.abs(gamma[p == 0]) <= 1e-18)  # round-off of s - u_z - a
    assert np.allclose(problem.residual(0.0, u, z), f0, rtol=0, atol=1e-12 * np.abs(f0).max())
    assert np.allclose(problem.jacobian_dense(0.0, u, z, 0.0), J0, rtol=0,
                       atol=1e-12 * np.abs(J0).max())

    coulomb = mu * rod.forces(0.0, u)
    fric.reset(0.0, u)
    s = 0.0
    for s in np.arange(1, 68) * 0.3 * GC:          # to 20.1 gamma_crit
        fric.update(s, u)
    for _ in range(3):                             # stopped: no relaxation
        assert np.allclose(fric.forces(s, u), coulomb, rtol=1e-12, atol=0)
        fric.update(s, u)
    back = s - 0.6 * GC
    assert np.allclose(fric.forces(back, u), 0.4 * coulomb, rtol=1e-9, atol=0)
    for ds in np.arange(1, 11) * 0.3 * GC:
        fric.update(s - ds, u)
    assert np.allclose(fric.forces(s - 3 * GC, u), -coulomb, rtol=1e-12, atol=0)


class Springs(Term):
    """k u on the given dofs (a spring to ground on each)."""

    def __init__(self, dofs, k):
        self.rows = self.cols = np.asarray(dofs, np.int64)
        self.k = k

    def add_residual(self, t, u, udot, f):
        f[self.rows] += self.k * u[self.rows]

    def jacobian_values(self, t, u, udot, shift):
        return np.full(self.rows.size, self.k)


def test_spring_held_by_friction_stick_slip():
    """A two-node rod-side chain (z = 0, 1; at h = 0, so p_s = p_mix), each node on an axial
    spring k to ground, dragged by the rod out to s = 2e-3 mm and back to -2e-3 mm in steady
    solves (PETSc SNES) with the anchors updated after each. Closed form with the stick
    stiffness c = mu p A L / gamma_crit and the Coulomb force F_c = mu p A L:
    stick u = c (s - a) / (k + c) while |gamma| <= gamma_crit / 2, slide u = +-F_c / k
    once |gamma| >= gamma_crit, the anchor a = s* - u* -+ gamma_crit after the turn at s*."""
    X = np.array([[1.0, 0.0], [1.0, 1.0]])
    rod = RodContact(RodSide(X, np.array([0, 1]), lambda t: 1.0, 1.0),
                     ExponentialLaw(H_MIX, P_MIX))
    mu, k = 0.1, 1e3
    fric = RodFriction(rod, slip=lambda t: t, mu_s=mu)
    problem = Problem(4, [fric, Springs(rod.side.uz, k)],
                      constraints=Constraints(rod.side.ur, 0.0))
    Fc = mu * P_MIX * 1.0 * 0.5
    c = Fc / GC
    path = np.concatenate([np.arange(0, 21), np.arange(19, -21, -1)]) * 1e-4
    u = np.zeros(4)
    a = 0.0
    seen = set()
    for i, s in enumerate(path):
        u = problem.solve_steady(u, t=s)
        fric.update(s, u)
        uz = u[rod.side.uz]
        assert uz[0] == pytest.approx(uz[1], abs=1e-15)
        if i > 0 and path[i] < path[i - 1] and path[i - 1] == path.max():
            a = path[i - 1] - u_prev - GC                  # the turn: anchored at +gamma_crit
        u_stick = c * (s - a) / (k + c)
        if abs(s - a - u_stick) <= 0.5 * GC:
            assert uz[0] == pytest.approx(u_stick, rel=1e-9, abs=1e-15)
            seen.add("stick")
        elif s - a - Fc / k >= GC or s - a + Fc / k <= -GC:
            sign = 1.0 if s - a - Fc / k >= GC else -1.0
            assert uz[0] == pytest.approx(sign * Fc / k, rel=1e-9)
            seen.add("slide+" if sign > 0 else "slide-")
        u_prev = uz[0]
    assert seen == {"stick", "slide+", "slide-"}
    assert fric.total(path[-1], u) == pytest.approx(-2 * Fc, rel=1e-12)


def test_mounted_oring_dragged_by_the_rod(tmp_path):
    """The coarse mounted O-ring (frictionless groove) with rod friction, the rod moved
    0.3 mm axially in the stabilised quasi-static driver, anchors updated after every
    accepted step. At the final static state: the axial forces on the seal balance (rod
    friction = -(net groove wall reaction), GrooveContact's own sum; the solid's internal
    forces have no axial resultant); every slip is within gamma_crit; the contact patch has
    gone with the rod (its nodes' axial displacements grew by 0.3 mm, 1 % on average; the
    nodes that came into contact on the way less). With frictionless groove walls the
    O-ring rolls with the rod instead of sliding on it: the friction stays far below mu_s
    times the normal force."""
    from conftest import mount_and_pressurise, scene
    from sealts.problem.seal_model import ramp
    from sealts.steps.quasi_static import quasi_static

    s = scene("oring_mount", mesh={"h_contact": 0.1, "h_bulk": 0.4, "cache": str(tmp_path)})
    state = mount_and_pressurise(s)
    model, t0, u0 = state.model, state.t, state.u
    stroke, mu = 0.3, 0.1
    fric = RodFriction(model.rod, slip=lambda t: stroke * ramp(t - t0), mu_s=mu)
    fric.reset(t0, u0)
    t1 = t0 + 2.0
    # the friction's post-step hook caps the slip after every accepted step
    eq = quasi_static(model, [fric], u0, (t0, t0 + 1.0, t1), s.mount.dt)
    u = eq.u
    assert eq.udot is None                                # the static solve converged
    fric.update(t1, u)
    walls = model.groove.reactions(t1, u)
    net = walls["wall_pressure_side"] + walls["wall_atmosphere_side"]
    coulomb = mu * model.rod.forces(t1, u).sum()
    F = fric.total(t1, u)
    assert F + net == pytest.approx(0.0, abs=1e-6 * coulomb)
    assert 0 < abs(F) < 0.1 * coulomb
    p, _ = model.rod.pressure(t1, u)
    gamma = fric.slip(t1, u)
    assert np.all(np.abs(gamma) <= GC * (1 + 1e-9))
    uz = model.side.uz
    carried = (u[uz] - u0[uz])[p > 0]
    assert carried.size > 10 and carried.mean() == pytest.approx(stroke, rel=0.01)
