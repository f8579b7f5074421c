"""The seal surface's self-contact (sealts.contact.self_contact): its Jacobian against
central differences, force and moment balance, the penalty's closed-form contact distance,
a smooth or right-angled surface that feels nothing, and the 40 MPa O-ring whose surface
creases against the atmosphere side's wall (benchmarks/stress.md): stopped without the
self-contact, pressurised with it."""
import numpy as np
import pytest

from conftest import mount_and_pressurise, scene, stroke_of
from sealts.contact.rigid import tributary_lengths
from sealts.contact.self_contact import THICKNESS, SelfContact
from sealts.core import SolveError
from sealts.solid.pressure import boundary_loop


def strip(n=12, length=1.0, thickness=0.05):
    """A thin strip's boundary, counter-clockwise: the lower face left to right, the upper
    face back (2 n nodes, uniform tributary lengths)."""
    x = np.linspace(0.0, length, n)
    X = np.concatenate([np.stack([x, np.zeros(n)], 1),
                        np.stack([x[::-1], np.full(n, thickness)], 1)])
    return X, np.arange(2 * n), np.full(2 * n, length / (n - 1))


def folded(X, n, gap):
    """Displacements that bring the strip's upper face down to ``gap`` above its lower
    face's line, shifted along it and wavy, so that pairs lie at every distance."""
    u = np.zeros_like(X)
    k = np.arange(n)
    u[n:, 0] = 0.3 / (n - 1) + 0.01 * np.cos(k)
    u[n:, 1] = -X[n:, 1] + gap + 2e-3 * np.sin(3 * k)
    return u.ravel()


def test_jacobian_matches_central_differences():
    X, loop, trib = strip()
    n = X.shape[0] // 2
    for axisym in (False, True):
        sc = SelfContact(X + [2.0, 0.0], loop, trib, axisym, reach=30, penalty=1e3,
                         delta=1e-3)
        u = folded(X, n, gap=0.03)                  # within d0 = 0.055 of the lower face
        assert sc.forces(u)[0].size > 10
        J = np.zeros((u.size, u.size))
        np.add.at(J, (sc.rows, sc.cols), sc.jacobian_values(0.0, u, None, 0.0))
        fd = np.zeros_like(J)
        for j in range(u.size):
            e = np.zeros(u.size)
            e[j] = 1e-7
            fp, fm = np.zeros(u.size), np.zeros(u.size)
            sc.add_residual(0.0, u + e, None, fp)
            sc.add_residual(0.0, u - e, None, fm)
            fd[:, j] = (fp - fm) / 2e-7
        assert np.abs(J - fd).max() < 1e-7 * np.abs(J).max()


def test_forces_and_moments_balance():
    """Central pair forces: the term's forces on the section add up to no force and no
    moment (plane strain)."""
    X, loop, trib = strip()
    sc = SelfContact(X, loop, trib, False, reach=30, penalty=1e3, delta=1e-3)
    u = folded(X, X.shape[0] // 2, gap=0.03)
    f = np.zeros(u.size)
    sc.add_residual(0.0, u, None, f)
    F, x = f.reshape(-1, 2), X + u.reshape(-1, 2)
    assert np.abs(F).max() > 0.1
    assert np.abs(F.sum(0)).max() < 1e-12 * np.abs(F).max()
    assert abs((x[:, 0] * F[:, 1] - x[:, 1] * F[:, 0]).sum()) < 1e-12 * np.abs(F).max()


def test_two_nodes_pushed_together_settle_at_the_penalty_distance():
    """A node pressed towards another by a force P settles where the penalty carries it,
    d = d0 + g, P = A k delta ln(1 + exp(-g/delta)): g = -delta ln(expm1(P / (A k delta)))
    (Newton on the term's own residual and Jacobian, the other node held)."""
    X = np.array([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0], [0.0, 1.0]])
    sc = SelfContact(X, np.arange(6), np.ones(6), False, reach=3, penalty=1e3, delta=1e-3)
    pair = np.flatnonzero((sc.i == 1) & (sc.j == 4)) if ((sc.i == 1) & (sc.j == 4)).any() \
        else np.flatnonzero((sc.i == 4) & (sc.j == 1))
    assert pair.size == 1
    k, dl, A, d0 = sc.k, sc.delta, sc.area[pair[0]], sc.d0[pair[0]]
    assert d0 == pytest.approx(THICKNESS)
    P = 2.0                                           # N on node 4 towards node 1
    u = np.zeros(12)
    u[9] = -(1.0 - d0)                                # node 4 moved down to d = d0
    for _ in range(50):
        f = np.zeros(12)
        sc.add_residual(0.0, u, None, f)
        f[9] += P                                     # external -P on node 4 (residual +P)
        J = np.zeros((12, 12))
        np.add.at(J, (sc.rows, sc.cols), sc.jacobian_values(0.0, u, None, 0.0))
        du = -f[9] / J[9, 9]
        u[9] += du
        if abs(du) < 1e-15:
            break
    g = -dl * np.log(np.expm1(P / (A * k * dl)))
    assert 1.0 + u[9] == pytest.approx(d0 + g, abs=1e-12)
    assert g < 0.0                                    # pressed within the contact distance
    # the surface is folded there (closed: this pair alone), and nowhere undeformed
    assert sc.closed(u).tolist() == [X[sc.i[pair[0]]].tolist()]
    assert sc.closed(np.zeros(12)).size == 0


@pytest.mark.parametrize("shape", ["oring", "rectangle"])
def test_a_smooth_or_right_angled_surface_feels_nothing(shape):
    """The undeformed O-ring and the sharp-cornered rectangular ring: every pair within
    reach lies beyond the contact distance and its cutoff, so the term is zero."""
    from sealts.problem.seal_model import model_from_scene
    name, extra = (("oring_mount", {}) if shape == "oring" else
                   ("rect_ring_mount", {"seal": {"corner_radius": 0.0}}))
    s = scene(name, mesh={"h_contact": 0.05, "h_bulk": 0.2}, **extra)
    mesh = model_from_scene(s).mesh
    X = mesh.X
    trib = tributary_lengths(X, np.concatenate(list(mesh.edges.values())), X.shape[0])
    sc = SelfContact(X, boundary_loop(mesh.conn)[:, 0], trib, True)
    q, F = sc.forces(np.zeros(2 * X.shape[0]))
    assert q.size == 0


def test_the_40_mpa_crease_is_held_by_the_self_contact():
    """The paper's O-ring (0.025 / 0.2 mm) pressurised to 40 MPa: at 38 MPa its surface
    against the atmosphere side's wall creases. Without the self-contact the rod-side
    guard stops there naming it; with it steps 1-2 reach a static equilibrium in which the
    crease's faces touch (pairs within the contact distance carry force) and no pair is
    closer than half of it."""
    sections = dict(mesh={"h_contact": 0.025, "h_bulk": 0.2}, fluid={"p_in": 40.0})
    with pytest.raises(SolveError, match='creases.*seal.self_contact = "on"'):
        mount_and_pressurise(scene("oring_stroke", seal={"self_contact": "off"}, **sections))
    state = mount_and_pressurise(scene("oring_stroke", **sections))   # auto: on at 40 MPa
    sc = state.model.self_contact
    u = state.u
    q, F = sc.forces(u)
    assert np.abs(F).max() > 1e-3                     # the crease's faces press (N)
    d = np.hypot(*(sc.Xi - sc.Xj + u[sc.di] - u[sc.dj]).T)
    assert (d / sc.d0).min() > 0.5
    assert state.model.results(state.t, u)["static_equilibrium"]
    # the stroke takes the term too: its start (seal and film in equilibrium at t = 0)
    # keeps the crease closed and held
    step = stroke_of(state)
    (term,) = step.surface
    assert any(t is term or getattr(t, "term", None) is term for t in step.problem.terms)
    U = step.start()
    q, F = term.forces(U)
    assert np.abs(F).max() > 1e-3
    d = np.hypot(*(term.Xi - term.Xj + U[term.di] - U[term.dj]).T)
    assert (d / term.d0).min() > 0.5
