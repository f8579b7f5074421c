"""Coulomb friction on the groove walls (GrooveFriction).

Each check is measured against something computed another way: the Jacobian against central
differences of the residual; the surfaces' pressures against GrooveContact's own reactions and
node pressures; the sliding and sticking forces against those pressures times mu and times
the penalty slope; the anchor update against its definition (slip capped, forces unchanged).
"""
import numpy as np
import pytest

from sealts.contact.groove_friction import GrooveFriction, groove_surfaces
from sealts.contact.rigid import GrooveContact
from sealts.mesh.structured import rectangle
from sealts.problem import Problem

GC = 1e-4


def corner_groove(nodes_X, rho):
    """As tests/test_mount.py: a groove of bottom r = 0.98, walls z = 0.02 and 0.98, corners
    of radius rho; the block r in [0.5, 1], z in [0, 1] digs 0.02 mm into every wall."""
    trib = np.full(nodes_X.shape[0], 0.1)
    return GrooveContact(nodes_X, np.arange(nodes_X.shape[0]), trib, True, lambda t: 0.98,
                         lambda t: (0.02, 0.98), penalty=1e3, delta=1e-3, corner_radius=rho)


def block(rho, seed=5):
    X, _, _ = rectangle(0.5, 1.0, 0.0, 1.0, 5, 10)
    groove = corner_groove(X, rho)
    u = np.random.default_rng(seed).uniform(-0.005, 0.005, 2 * X.shape[0])
    return X, groove, u


def set_slips(fric, t, u, x, y):
    """Anchors giving slip x * GC on slot 0 (bottom or arc) and y * GC on the side walls; on
    an arc y offsets the anchor along the normal instead (it then enters only through the
    tangent's turning, the dt/dx term)."""
    _, _, tan, _, region = groove_surfaces(fric.groove, t, u)
    d = fric._disp(u)
    t0 = tan[0]
    perp = np.stack([t0[:, 1], -t0[:, 0]], axis=1)      # e_r on the flat bottom (t0 = e_z)
    fric.anchors = d + GC * (x[:, None] * t0 + y[:, None] * perp)
    g = fric.slip(t, u)
    assert np.allclose(g[0], x * GC, rtol=0, atol=1e-15)
    flat = region == 0
    assert np.allclose(g[1:, flat], (y * GC)[flat], rtol=0, atol=1e-15)
    return region


@pytest.mark.parametrize("rho", [0.0, 0.2])
def test_groove_friction_jacobian(rho):
    """Every entry of the 2x2 nodal blocks against central differences (entries above 1e-3
    of the largest to 1e-6 relative, the rest to 1e-6 of the largest), with slips in stick,
    the blend and sliding of both signs, on the flat walls, in the sharp corners (two walls
    at once) and on the corner arcs; a time-dependent mu."""
    X, groove, u = block(rho)
    n = u.size
    t = 0.7
    fric = GrooveFriction(groove, mu=lambda t: 0.1 + 0.2 * t)
    m = X.shape[0]
    choices = np.array([-3.0, -0.9, -0.7, -0.2, 0.1, 0.4, 0.6, 0.8, 0.95, 2.0, 0.0, 0.3,
                        -0.45, -0.6, 1.3, 0.75, -1.7])
    rng = np.random.default_rng(1)
    x, y = rng.choice(choices, m), rng.choice(choices, m)
    region = set_slips(fric, t, u, x, y)
    p = groove_surfaces(groove, t, u)[0]
    problem = Problem(n, [fric])
    J = problem.jacobian_dense(t, u, np.zeros(n), 3.0)
    eps = 1e-8
    fd = np.zeros((n, n))
    for j in range(n):
        e = np.zeros(n)
        e[j] = eps
        fd[:, j] = (problem.residual(t, u + e, u) - problem.residual(t, u - e, u)) / (2 * eps)
    scale = np.abs(J).max()
    assert np.abs(J - fd).max() <= 1e-6 * scale
    big = np.abs(J) > 1e-3 * scale
    rel = np.abs(J[big] - fd[big]) / np.abs(J[big])
    assert rel.max() < 1e-6, rel.max()
    # the check saw every kind of node: two walls at once (sharp corners) or arcs, and stick,
    # blend and slide on pressed walls
    pressed = p > 1.0
    if rho == 0.0:
        assert (pressed.sum(axis=0) == 2).sum() >= 2
    else:
        assert ((region > 0) & pressed[0]).sum() >= 2
    for lo, hi in ((0.0, 0.5), (0.5, 1.0), (1.0, 10.0)):
        assert (pressed[0] & (np.abs(x) > lo) & (np.abs(x) < hi)).any()


def test_surfaces_are_groove_contacts():
    """The slots' pressures are GrooveContact's: their largest is node_pressures, and with
    sharp corners sum p w per wall is the wall's reaction."""
    for rho in (0.0, 0.2):
        X, groove, u = block(rho, seed=2)
        p = groove_surfaces(groove, 0.0, u)[0]
        assert np.allclose(p.max(axis=0), groove.node_pressures(0.0, u), rtol=1e-14, atol=0)
    X, groove, u = block(0.0, seed=2)
    p = groove_surfaces(groove, 0.0, u)[0]
    R = groove.reactions(0.0, u)
    w = groove.w
    assert -R["bottom"] == pytest.approx(p[0] @ w, rel=1e-13)
    assert R["wall_pressure_side"] == pytest.approx(p[1] @ w, rel=1e-13)
    assert -R["wall_atmosphere_side"] == pytest.approx(p[2] @ w, rel=1e-13)


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_coulomb_limit_in_sliding(sign):
    """Slips of 100 gamma_crit: every slot's force is mu times the wall's normal force on the
    node (p w), along the tangent, on each wall; the wall totals are mu times GrooveContact's
    reactions (sharp corners), the bottom's axial, the side walls' radial."""
    mu = 0.1
    X, groove, u = block(0.0, seed=3)
    fric = GrooveFriction(groove, mu=mu)
    m = X.shape[0]
    set_slips(fric, 0.0, u, np.full(m, 100.0 * sign), np.full(m, 100.0 * sign))
    p = groove_surfaces(groove, 0.0, u)[0]
    F = fric.slot_forces(0.0, u)
    assert np.allclose(F[0, :, 1], sign * mu * p[0] * groove.w, rtol=1e-14, atol=0)
    assert np.all(F[0, :, 0] == 0) and np.all(F[1:, :, 1] == 0)
    assert np.allclose(F[1:, :, 0], sign * mu * p[1:] * groove.w, rtol=1e-14, atol=0)
    R = groove.reactions(0.0, u)
    tot = fric.total(0.0, u)
    assert tot["bottom"][1] == pytest.approx(-sign * mu * R["bottom"], rel=1e-12)
    assert tot["wall_pressure_side"][0] == pytest.approx(sign * mu * R["wall_pressure_side"],
                                                         rel=1e-12)
    assert tot["wall_atmosphere_side"][0] == pytest.approx(
        -sign * mu * R["wall_atmosphere_side"], rel=1e-12)
    assert R["bottom"] < 0 and R["wall_pressure_side"] > 0
    # on the arcs too: mu p w along the arc's tangent
    X, groove, u = block(0.2, seed=3)
    fric = GrooveFriction(groove, mu=mu)
    region = set_slips(fric, 0.0, u, np.full(m, 100.0 * sign), np.zeros(m))
    p, _, tan, _, _ = groove_surfaces(groove, 0.0, u)
    F = fric.slot_forces(0.0, u)
    arc = (region > 0) & (p[0] > 1.0)
    assert arc.sum() >= 2
    assert np.allclose(F[0][arc], sign * mu * (p[0] * groove.w)[arc, None] * tan[0][arc],
                       rtol=1e-14, atol=0)


def test_stick_is_the_penalty_law():
    """From zero elastic slip (reset), moving every node by delta << gamma_crit along the
    bottom (z) gives the bottom nodes -mu p w delta / gamma_crit (opposing the motion),
    proportional to delta; along r the side walls' nodes the same radially."""
    mu = 0.1
    X, groove, u = block(0.0, seed=4)
    fric = GrooveFriction(groove, mu=mu)
    fric.reset(0.0, u)
    assert np.abs(fric.forces(0.0, u)).max() == 0.0
    for axis, slots in ((1, [0]), (0, [1, 2])):
        dofs = groove.uz if axis == 1 else groove.ur
        for delta in (1e-3 * GC, 2e-3 * GC, -5e-3 * GC):
            v = u.copy()
            v[dofs] += delta
            p = groove_surfaces(groove, 0.0, v)[0]
            F = fric.slot_forces(0.0, v)
            for k in slots:
                assert np.allclose(F[k, :, axis], -mu * p[k] * groove.w * delta / GC,
                                   rtol=1e-9, atol=0)
        assert (p[slots] > 1.0).sum() >= 4


@pytest.mark.parametrize("rho", [0.0, 0.2])
def test_update_caps_slip_and_keeps_forces(rho):
    """update(): afterwards every touched slot's |gamma| <= gamma_crit, nodes off the walls
    have zero slip, and the residual at that state is unchanged (and with flat walls the
    Jacobian too); a second update moves nothing."""
    X, groove, u = block(rho, seed=6)
    n, m = u.size, X.shape[0]
    fric = GrooveFriction(groove, mu=0.1)
    rng = np.random.default_rng(7)
    set_slips(fric, 0.0, u, rng.uniform(-5, 5, m), rng.uniform(-5, 5, m))
    problem = Problem(n, [fric])
    z = np.zeros(n)
    f0, J0 = problem.residual(0.0, u, z), problem.jacobian_dense(0.0, u, z, 0.0)
    moved = fric.update(0.0, u)
    g = fric.slip(0.0, u)
    p = groove_surfaces(groove, 0.0, u)[0]
    touched = p > fric.p_open
    assert moved > GC
    assert np.all(np.abs(g[touched]) <= GC * (1 + 1e-9))
    free = ~touched.any(axis=0)
    assert np.all(np.abs(g[:, free]) <= 1e-15)
    assert free.sum() > 10 and touched.sum() > 10
    assert np.allclose(problem.residual(0.0, u, z), f0, rtol=0, atol=1e-12 * np.abs(f0).max())
    if rho == 0.0:
        assert np.allclose(problem.jacobian_dense(0.0, u, z, 0.0), J0, rtol=0,
                           atol=1e-12 * np.abs(J0).max())
    assert fric.update(0.0, u) <= 1e-15


@pytest.fixture(scope="module")
def stroke_with_friction(tmp_path_factory):
    """The coarse O-ring at 1 MPa (as the fixture of tests/test_stroke.py) with friction on
    the rod and the groove walls: the rod ramps to 100 mm/s outstroke in 10 ms and holds to
    30 ms (2.5 mm of travel)."""
    from conftest import Recorder, coarse_stroke, mount_and_pressurise, stroke_of

    cache = str(tmp_path_factory.mktemp("mesh"))
    s = coarse_stroke(cache, friction=True)
    assert s.groove.mu == 0.1 and s.asperity.mu_s == 0.1
    step = stroke_of(mount_and_pressurise(s))
    assert step.friction is not None and step.groove_friction is not None
    U0 = step.start()
    rec = Recorder()
    U = step.run(U0, s.stroke.t_end, s.stroke.dt, s.stroke.rtol, observers=[rec])
    return s, step, U0, U, rec.states


def test_stroke_slides_the_seal_on_the_rod(stroke_with_friction):
    """With the groove walls holding the O-ring, the rod slides under it: at the end of the
    stroke (100 mm/s, 2.5 mm travelled) the solid friction is the Coulomb limit mu_s times
    the asperity load (1 %), in the rod's direction, and the groove bottom's friction resists
    the rolling (it drags the seal's outer surface along with the rod). The axial forces on
    the seal balance: rod friction + fluid shear + the fluid's axial loads (free surfaces,
    the film's surface-normal part) + the groove walls' normal reactions and friction = 0."""
    s, step, U0, U, states = stroke_with_friction
    t = states[-1][0]
    assert t == pytest.approx(0.03)
    row = step.scalars(t, U)
    assert row["v"] == 100.0
    coulomb = s.asperity.mu_s * row["load_asperity"]
    assert coulomb > 10.0
    assert row["friction_solid"] == pytest.approx(coulomb, rel=0.01)
    # the groove bottom's friction holds the O-ring from rolling: the rod's drag would turn
    # its outer surface against the rod's motion, so the bottom pushes it along (+z), and
    # the atmosphere-side wall takes the rest
    assert 0.0 < row["friction_groove"] < row["friction_solid"]
    Udot = (U - states[-2][1]) / (t - states[-2][0])
    walls = step.groove.reactions(t, U)
    fz = step.load.forces(t, U)
    fluid_z = (fz[:, 1].sum() + fz[:, 3].sum() + step.film.axial_forces(t, U).sum()
               + step.film.shear_forces(t, U, Udot).sum())
    wall_z = walls["wall_pressure_side"] + walls["wall_atmosphere_side"]
    total = fluid_z + wall_z + row["friction_solid"] + row["friction_groove"]
    assert total == pytest.approx(0.0, abs=1e-6 * abs(wall_z))
    assert row["friction_groove"] == pytest.approx(step.groove_friction.total(t, U)["total"][1])


def test_node_dragged_along_the_bottom_and_round_the_corner():
    """One node held 0.01 mm into the groove (moved by hand, anchors updated after each
    move). Along the flat bottom: 20 gamma_crit in steps of 0.3 gamma_crit gives the Coulomb
    force -mu p w e_z, kept when it stops (however often updated); back by 0.6 gamma_crit
    unloads to 0.4 of it, back by 3 gamma_crit reaches +mu p w. Round a corner arc (rho =
    0.2) in steps of 0.5 gamma_crit of arc length: the force is mu p w against the motion,
    along the arc's tangent, all the way from the bottom to the side wall, where it is the
    wall's radial friction."""
    mu, pen = 0.1, 0.01
    one = np.array([[0.98 + pen, 0.5]])
    groove = corner_groove(one, 0.0)
    fric = GrooveFriction(groove, mu=mu)
    u = np.zeros(2)
    fric.reset(0.0, u)
    p = groove_surfaces(groove, 0.0, u)[0][0, 0]
    coulomb = mu * p * groove.w[0]
    assert p == pytest.approx(1e3 * pen, rel=1e-3)
    for s in np.arange(1, 68) * 0.3 * GC:
        u[1] = s
        fric.update(0.0, u)
    for _ in range(3):
        assert fric.forces(0.0, u)[0] == pytest.approx([0.0, -coulomb], rel=1e-12, abs=0)
        fric.update(0.0, u)
    u[1] = s - 0.6 * GC
    assert fric.forces(0.0, u)[0, 1] == pytest.approx(-0.4 * coulomb, rel=1e-9)
    for ds in np.arange(1, 11) * 0.3 * GC:
        u[1] = s - ds
        fric.update(0.0, u)
    assert fric.forces(0.0, u)[0, 1] == pytest.approx(coulomb, rel=1e-12)

    # round corner a: centre (0.78, 0.22), the node at distance rho + pen from it, from the
    # bottom (theta = 0, direction +r) to the side wall (theta = -90 degrees, direction -z)
    rho = 0.2
    start = np.array([[0.98 + pen, 0.22]])
    groove = corner_groove(start, rho)
    fric = GrooveFriction(groove, mu=mu)
    R = rho + pen
    c = np.array([0.78, 0.22])

    def at(theta):
        x = c + R * np.array([np.cos(theta), np.sin(theta)])
        return x - start[0]

    u = at(0.0)
    fric.reset(0.0, u)
    dtheta = 0.5 * GC / R
    thetas = -np.arange(1, int(0.5 * np.pi / dtheta) + 30) * dtheta
    checked = 0
    for i, th in enumerate(thetas):
        u = at(th)
        if i >= 10 and i % 500 == 0 or i == thetas.size - 1:
            F = fric.forces(0.0, u)[0]
            p = groove_surfaces(groove, 0.0, u)[0].max()
            # the motion's direction: d(x)/d(-theta), on the arc (-sin, cos) * -1
            move = np.array([np.sin(th), -np.cos(th)])
            if th < -0.5 * np.pi:                     # past the arc: on the flat wall
                move = np.array([-1.0, 0.0])
            assert p == pytest.approx(1e3 * pen, rel=1e-3)
            assert F == pytest.approx(-mu * p * groove.w[0] * move, rel=1e-9, abs=1e-12)
            checked += 1
        fric.update(0.0, u)
    assert checked > 5
    # the last positions are on the flat side wall a (below z = z_a + rho), sliding in -r
    x = start[0] + u
    assert x[1] < 0.02 and x[0] < 0.78
    assert fric.total(0.0, u)["wall_pressure_side"][0] > 0


@pytest.mark.parametrize("rho", [0.0, 0.2])
def test_groove_state_jacobian(rho):
    """The anchors as TS unknowns (GrooveStateFriction): every entry of the four 2x2 nodal
    blocks (force by displacement and anchor, anchor rate by anchor and displacement, with
    the TS shift) against central differences in U and U' (entries above 1e-3 of the
    largest to 1e-6 relative, the rest to 1e-6 of the largest), with slips in stick, the
    blend and flowing of both signs, on flat walls, sharp corners and corner arcs; and
    the anchors' rate is minus the excess over gamma_crit along the tangent, divided by
    eta (a flat wall alone)."""
    from sealts.contact.groove_slip_state import GrooveStateFriction
    X, groove, u = block(rho)
    m = X.shape[0]
    n = u.size + 2 * m
    ad = u.size + np.arange(2 * m).reshape(m, 2)
    t = 0.7
    fric = GrooveStateFriction(groove, ad, mu=lambda t: 0.1 + 0.2 * t, v_ref=50.0)
    ref = GrooveFriction(groove, mu=lambda t: 0.1 + 0.2 * t)
    choices = np.array([-3.0, -0.7, -0.2, 0.1, 0.4, 0.6, 0.8, 2.0, 0.0, 0.3, -0.6, 1.3,
                        -1.7])
    rng = np.random.default_rng(1)
    x, y = rng.choice(choices, m), rng.choice(choices, m)
    region = set_slips(ref, t, u, x, y)
    U = np.concatenate([u, ref.anchors.ravel()])
    Ud = rng.uniform(-1.0, 1.0, n)
    problem = Problem(n, [fric])
    shift = 3.0
    J = problem.jacobian_dense(t, U, Ud, shift)
    eps = 1e-8
    fd = np.zeros((n, n))
    for j in range(n):
        e = np.zeros(n)
        e[j] = eps
        fd[:, j] = ((problem.residual(t, U + e, Ud) - problem.residual(t, U - e, Ud))
                    / (2 * eps)
                    + shift * (problem.residual(t, U, Ud + e) - problem.residual(t, U, Ud - e))
                    / (2 * eps))
    scale = np.abs(J).max()
    assert np.abs(J - fd).max() <= 1e-6 * scale
    big = np.abs(J) > 1e-3 * scale
    rel = np.abs(J[big] - fd[big]) / np.abs(J[big])
    assert rel.max() < 1e-6, rel.max()
    # the forces are GrooveFriction's at the same anchors
    assert np.array_equal(fric.forces(t, U), ref.forces(t, u))
    # on the flat bottom (tangent e_z; the side walls' tangents are e_r) the anchor's z
    # rate is -w psi(gamma_0) / eta, w = p_0 / (p_0 + p_open) the bottom's touch: the
    # residual a' + sum w psi t / eta at a' = 0
    f = np.zeros(n)
    fric.add_residual(t, U, np.zeros(n), f)
    g = ref.slip(t, u)
    p0 = groove_surfaces(groove, t, u)[0][0]
    alone = (region == 0) & (np.abs(g[0]) > GC)
    psi = np.sign(g[0]) * (np.abs(g[0]) - GC)
    w = p0 / (p0 + fric.p_open)
    assert alone.sum() > 3 and (w[alone] > 0.9).any() and (w[alone] < 0.1).any()
    assert np.allclose(f[ad[alone, 1]], (w * psi)[alone] / fric.eta, rtol=1e-9, atol=0)


def test_groove_state_history_under_ts_is_the_closed_form():
    """One node pressed on the flat bottom (the side walls 0.48 mm away), moved along it at
    u_z = V t up to T and back at -V after, its anchor integrated by TS (adaptive BDF, rtol
    1e-7): its slip on the bottom, gamma = a_z - u_z, obeys gamma' = -V - psi(gamma)/eta,
    the rod slip's law with the rod's motion mirrored, so gamma / gamma_crit is minus the
    closed form of tests/test_slip_state_friction.py (stick, flow, unload, reflow) at every
    accepted step within 1e-4, every branch visited; the anchor's radial part stays at zero
    (no slip along the side walls' tangent); the force is the bottom's Coulomb limit
    mu p w while it flows."""
    from sealts.contact.groove_slip_state import GrooveStateFriction
    from sealts.contact.slip_state_friction import relaxation_time
    from sealts.core import Constraints, Recorder
    from test_slip_state_friction import stick_slip_closed_form
    X = np.array([[0.981, 0.5]])                       # 1 um into the bottom r = 0.98
    groove = corner_groove(X, 0.0)
    V, T, t_end = 1e-3, 0.3, 0.8
    fric = GrooveStateFriction(groove, np.array([[2, 3]]), mu=0.1, v_ref=V)
    eta = relaxation_time(GC, V)

    def u_z(t):
        return V * t if t <= T else V * (2 * T - t)

    problem = Problem(4, [fric], constraints=Constraints(
        np.array([0, 1]), lambda t: np.array([0.0, u_z(t)])))
    rec = Recorder()
    problem.transient(np.zeros(4), 0.0, t_end, 1e-4, stops=[T], observers=[rec], rtol=1e-7,
                      atol=1e-12)
    t = np.array([s[0] for s in rec.states])
    U = np.array([s[1] for s in rec.states])
    gamma = (U[:, 3] - U[:, 1]) / GC
    exact, (t1, t2, t3) = stick_slip_closed_form(t, V, T, eta)
    assert np.abs(gamma + exact).max() < 1e-4
    for a, b in ((0.0, t1), (t1, T), (T, t2), (t2, t3), (t3, t_end)):
        assert ((t > a) & (t < b)).sum() > 3, (a, b)
    assert np.abs(U[:, 2]).max() == 0.0
    p = groove_surfaces(groove, t_end, U[-1])[0][0, 0]
    assert p > 1.0
    assert fric.forces(t_end, U[-1])[0, 1] == pytest.approx(0.1 * p * groove.w[0], rel=1e-12)


def test_a_node_that_lands_on_a_wall_starts_from_zero_slip():
    """One node 30 um off the bottom (delta 1 um) moves 3 gamma_crit along it, then down
    onto it and 1 um in, then rests. Off the wall its anchor hardly flows (no slot is
    touched), so its slip on the bottom passes -gamma_crit; the landing event, located
    where its gap falls to open_gap delta = 10 um (t = 0.3 + 0.3 * 20 / 31 s), sets its
    anchor to its displacement: zero slip, and at rest on the bottom zero friction. Without
    the event (a deliberate break) the slip would be saturated on landing and the force the
    Coulomb limit mu p w."""
    from sealts.contact.groove_slip_state import GrooveStateFriction
    from sealts.core import Constraints, Recorder
    X = np.array([[0.95, 0.5]])
    groove = corner_groove(X, 0.0)
    V, T1, T2, t_end = 1e-3, 0.3, 0.6, 0.8
    landed = []

    class Logged(GrooveStateFriction):
        def event(self, t, u, which):
            landed.append((t, -(u[1] - u[3]) / GC))
            super().event(t, u, which)

    fric = Logged(groove, np.array([[2, 3]]), mu=0.1, v_ref=V)

    def prescribed(t):
        u_z = V * min(t, T1)
        u_r = 0.031 * min(max(t - T1, 0.0), T2 - T1) / (T2 - T1)
        return np.array([u_r, u_z])

    problem = Problem(4, [fric], constraints=Constraints(np.array([0, 1]), prescribed))
    rec = Recorder()
    problem.transient(np.zeros(4), 0.0, t_end, 1e-4, stops=[T1, T2], observers=[rec],
                      rtol=1e-7, atol=1e-12)
    (t_land, gamma_land), = landed
    assert t_land == pytest.approx(T1 + (T2 - T1) * 20.0 / 31.0, abs=1e-6)
    # off the wall the anchor did not trail its node within gamma_crit (it flows with the
    # touch weight p / (p + p_open), which reaches 1/2 only at the landing gap)
    assert gamma_land < -1.5
    U = rec.states[-1][1]
    gamma = fric.slip(t_end, U)[0, 0]
    p = groove_surfaces(groove, t_end, U)[0][0, 0]
    assert p > 1.0 and abs(gamma) < 1e-9 * GC
    assert abs(fric.forces(t_end, U)[0, 1]) < 1e-9 * 0.1 * p * groove.w[0]


@pytest.mark.parametrize("gap", [8e-3, 10e-3, 12e-3])
def test_groove_state_jacobian_at_the_touch(gap):
    """Where a slot's touch weight w = p / (p + p_open) turns (gaps of 8-12 delta), with
    slips beyond gamma_crit on the bottom and along the side walls' tangent: the anchors'
    rows against central differences in U and U' (to 1e-6 of the largest entry), which
    the weight's derivative dw/dp dp/dx carries."""
    from sealts.contact.groove_slip_state import GrooveStateFriction
    X = np.array([[0.98 - gap, 0.5], [0.98 - gap - 0.001, 0.6]])
    groove = corner_groove(X, 0.0)
    u = np.array([0.0, 0.0, 3e-4, -2e-4])
    fric = GrooveStateFriction(groove, np.array([[4, 5], [6, 7]]), mu=0.1, v_ref=1.0)
    U = np.concatenate([u, [2.5 * GC, -2.0 * GC, -1.5 * GC, 2.0 * GC]])
    n = U.size
    Ud = np.random.default_rng(2).uniform(-1.0, 1.0, n)
    problem = Problem(n, [fric])
    shift = 3.0
    J = problem.jacobian_dense(0.0, U, Ud, shift)
    eps = 1e-9
    fd = np.zeros((n, n))
    for j in range(n):
        e = np.zeros(n)
        e[j] = eps
        fd[:, j] = ((problem.residual(0.0, U + e, Ud) - problem.residual(0.0, U - e, Ud))
                    / (2 * eps)
                    + shift * (problem.residual(0.0, U, Ud + e) - problem.residual(0.0, U, Ud - e))
                    / (2 * eps))
    w = fric.touch(groove_surfaces(groove, 0.0, u)[0][0])[0]
    assert (w > 0.05).all() and (w < 0.99).all()
    assert np.abs(J - fd).max() <= 1e-6 * np.abs(J).max()
