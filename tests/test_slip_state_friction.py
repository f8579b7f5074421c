"""Rod friction with the elastic slip as a TS unknown (sealts.contact.slip_state_friction):
its Jacobian against central differences, its stick, slide, unload and reslide history
integrated by TS against the closed form of the viscoplastic return, and the sliding seal
at the Coulomb limit in the coupled stroke."""
import numpy as np
import pytest

from sealts.contact.asperity import ExponentialLaw
from sealts.contact.rigid import RodContact
from sealts.contact.rod_side import RodSide
from sealts.contact.slip_state_friction import (OVERSHOOT, SlipStateFriction,
                                                relaxation_time, return_rate)
from sealts.core import Constraints, Recorder
from sealts.problem import Problem
from test_friction import GC, H_MIX, P_MIX, oring_chain


def test_jacobian_by_u_and_u_dot(tmp_path):
    """d(residual)/dU + shift d(residual)/dU' against central differences in U and U',
    entry by entry (relative 1e-6), on the coarse O-ring's chain with gaps from deep contact
    to open, slips from -1.6 to 1.6 gamma_crit (stick, blend and flowing, none within the
    differences' reach of the kink at |z| = gamma_crit), slip rates of both signs and a
    ramped mu_s(t)."""
    X, chain, rod, u = oring_chain(tmp_path)
    m, nu = chain.size, u.size
    n_all = nu + m
    zd = nu + np.arange(m)
    fric = SlipStateFriction(rod, lambda t: 40.0 * t, zd, mu_s=lambda t: 0.1 * t,
                             gamma_crit=GC, v_ref=50.0)
    rng = np.random.default_rng(1)
    t, shift = 0.7, 300.0
    x = rng.uniform(-1.6, 1.6, m)
    x[np.abs(np.abs(x) - 1.0) < 1e-3] = 0.3
    U = np.concatenate([u, x * GC])
    Ud = rng.uniform(-1.0, 1.0, n_all) * 60.0
    problem = Problem(n_all, [fric])
    J = problem.jacobian_dense(t, U, Ud, shift)
    cols = np.unique(fric.cols)
    fd = np.zeros((n_all, n_all))
    for j in cols:
        e = np.zeros(n_all)
        e[j] = 1e-8 if j < nu else 1e-7 * GC
        du = (problem.residual(t, U + e, Ud) - problem.residual(t, U - e, Ud)) / (2 * e[j])
        ed = np.zeros(n_all)
        ed[j] = 2e-7
        dud = (problem.residual(t, U, Ud + ed) - problem.residual(t, U, Ud - ed)) / 4e-7
        fd[:, j] = du + shift * dud
    assert np.all(J[:, np.setdiff1d(np.arange(n_all), cols)] == 0)
    nz = J != 0
    assert np.all(np.abs(fd[~nz]) <= 1e-9 * np.abs(J).max())
    row_max = np.abs(J).max(1, keepdims=True) * np.ones_like(J)
    err = np.abs(J - fd)[nz] / (np.abs(J[nz]) + 1e-8 * row_max[nz])
    assert err.max() < 1e-6, err.max()
    # stick, blend and flowing nodes were all there
    ax = np.abs(x)
    assert (ax < 0.5).any() and ((ax > 0.5) & (ax < 1.0)).any() and (ax > 1.0).any()


def stick_slip_closed_form(t, V, T, eta):
    """z(t) / gamma_crit of one node held axially under a rod at +V up to T, then -V, from
    z = 0: stick z = V t; from t1 = gamma_crit / V the flow, e = z - gamma_crit obeys
    e' = V - e / eta, e = V eta (1 - exp(-(t - t1) / eta)); after T, e' = -V - e / eta
    until e = 0 at t2 = T + eta ln((e_T + V eta) / (V eta)); then elastic unloading
    z = gamma_crit - V (t - t2) to -gamma_crit at t3, and the flow again, mirrored."""
    t1 = GC / V
    e_T = V * eta * (1.0 - np.exp(-(T - t1) / eta))
    t2 = T + eta * np.log((e_T + V * eta) / (V * eta))
    t3 = t2 + 2.0 * GC / V
    z = np.where(t <= t1, V * t,
                 np.where(t <= T, GC + V * eta * (1.0 - np.exp(-(t - t1) / eta)),
                          np.where(t <= t2, GC + (e_T + V * eta) * np.exp(-(t - T) / eta)
                                   - V * eta,
                                   np.where(t <= t3, GC - V * (t - t2),
                                            -GC - V * eta * (1.0 - np.exp(-(t - t3) / eta))))))
    return z / GC, (t1, t2, t3)


def test_stick_slip_history_under_ts_is_the_closed_form():
    """One contact node held axially (u_z = 0) under a rod moving at +V for T, then at -V:
    with w = +-V the law is an ODE in z alone, whose solution is known piecewise
    (stick_slip_closed_form). TS (adaptive BDF, rtol 1e-7) against it at every accepted step
    within 1e-4 of gamma_crit, every branch visited; the friction force is mu p A L
    phi(z / gamma_crit) throughout, exactly the Coulomb limit while it flows."""
    X = np.array([[1.0, 0.0], [1.0, 1.0]])
    rod = RodContact(RodSide(X, np.array([0, 1]), lambda t: 1.0, 1.0),
                     ExponentialLaw(H_MIX, P_MIX))
    V, T = 1e-3, 0.3                                          # 3 gamma_crit per 0.1 s
    fric = SlipStateFriction(rod, lambda t: V if t < T else -V, [4, 5], mu_s=0.1,
                             gamma_crit=GC, v_ref=V)
    eta = relaxation_time(GC, V)
    assert fric.eta == eta == pytest.approx(OVERSHOOT * GC / V)
    problem = Problem(6, [fric], constraints=Constraints(np.arange(4), 0.0))
    rec = Recorder()
    problem.transient(np.zeros(6), 0.0, 0.8, 1e-4, stops=[T], observers=[rec], rtol=1e-7,
                      atol=1e-12)
    t = np.array([s[0] for s in rec.states])
    z = np.array([s[1][4] for s in rec.states]) / GC
    exact, (t1, t2, t3) = stick_slip_closed_form(t, V, T, eta)
    assert np.abs(z - exact).max() < 1e-4
    for a, b in ((0.0, t1), (t1, T), (T, t2), (t2, t3), (t3, 0.8)):
        assert ((t > a) & (t < b)).sum() > 3, (a, b)
    # the slide's overshoot is V eta = OVERSHOOT gamma_crit at v_ref
    assert z[(t > t1 + 10 * eta) & (t < T)].max() == pytest.approx(1.0 + OVERSHOOT, rel=1e-4)
    Fc = 0.1 * P_MIX * 1.0 * 0.5                              # mu p A L of one node
    u_end = rec.states[-1][1]
    assert fric.forces(0.8, u_end)[0] == pytest.approx(-Fc, rel=1e-12)


def test_rate_at_rest_leaves_the_slip_alone():
    """w = 0: dz/dt = 0 anywhere in the stick range (the friction stays locked in) and
    beyond it the excess flows off towards gamma_crit; w z < 0 in the stick range: dz/dt = w
    (elastic unloading)."""
    eta = relaxation_time(GC, 50.0)
    x = np.linspace(-1.0, 1.0, 41)
    g, dg = return_rate(np.zeros_like(x), x * GC, GC, eta)
    assert np.all(g == 0.0) and np.all(dg == 0.0)
    g, _ = return_rate(-np.sign(x) * 50.0, x * GC, GC, eta)
    assert np.array_equal(g, -np.sign(x) * 50.0)
    g, dg = return_rate(np.zeros(2), np.array([1.5, -1.5]) * GC, GC, eta)
    assert np.allclose(g, np.array([-0.5, 0.5]) * GC / eta) and np.all(dg == -1.0 / eta)


@pytest.fixture(scope="module")
def dragged(tmp_path_factory):
    """The coarse O-ring at 1 MPa, the rod ramped to 100 mm/s in 10 ms and held to 30 ms,
    with the rod friction's slip as TS unknowns and as anchors, from one mounted state."""
    from conftest import coarse_stroke, mount_and_pressurise, stroke_of
    cache = tmp_path_factory.mktemp("mesh")
    out = {}
    state = None
    for history in ("state", "anchors"):
        s = coarse_stroke(cache, friction_history=history, rtol=1e-3)
        state = state or mount_and_pressurise(s)
        step = stroke_of(state, s)
        rec = Recorder()
        U = step.run(step.start(), s.stroke.t_end, s.stroke.dt, s.stroke.rtol,
                     observers=[rec])
        out[history] = step, U, rec.states
    return out


def test_sliding_seal_reaches_the_coulomb_limit_under_ts(dragged):
    """At 100 mm/s the contact slides: every touching node's elastic slip has passed
    gamma_crit by the overshoot w eta (OVERSHOOT gamma_crit at the rod's speed, v_ref; the
    slip rate w differs from it by the seal's own axial speed, a few mm/s), so
    the rod's friction on the seal is mu_s times the asperity load (Eq. 46, exactly: phi is
    saturated), as with the anchored law; no slip beyond the overshoot at any accepted
    step."""
    step, U, states = dragged["state"]
    t = states[-1][0]
    fr = step.friction
    p, _ = step.rod.pressure(t, U)
    x = fr.slip(t, U) / fr.gamma_crit
    touching = p > 0
    assert touching.sum() > 5
    assert x[touching].min() > 1.0 + 0.95 * OVERSHOOT
    assert x[touching].max() < 1.0 + 1.05 * OVERSHOOT
    load = step.rod.forces(t, U).sum()
    assert fr.total(t, U) == pytest.approx(0.1 * load, rel=1e-12)
    for ts, Us in states:
        assert np.abs(Us[step.layout.slip_dofs]).max() <= fr.gamma_crit * (1 + 1.05 * OVERSHOOT)
    anchored, Ua, _ = dragged["anchors"]
    assert fr.total(t, U) == pytest.approx(anchored.friction.total(t, Ua), rel=2e-3)
