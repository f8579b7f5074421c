"""The plane-strain O-ring (``seal.symmetry = "planar"``, forces per mm of depth): steps 1-2
and a short stroke. Without hoop strain nothing holds a round section from rolling between
frictionless walls; steps 1-2 hold its rolling angle with a pure couple
(:mod:`sealts.solid.rolling`), and the tests check that the couple stays at discretisation
level and leaves every force balance alone."""
from dataclasses import replace

import numpy as np
import pytest

from conftest import Recorder, coarse_stroke, mount_and_pressurise, stroke_of

R_ROD, R_G, CORD = 25.0, 29.7, 5.33


def planar(cache, **stroke):
    s = coarse_stroke(cache, **stroke)
    return replace(s, seal=replace(s.seal, symmetry="planar"))


def test_planar_pressurised_oring_balances_axially(tmp_path):
    """1 MPa on the planar coarse O-ring: it seals at the rod and the groove bottom, so the
    axial load it passes to the atmosphere-side wall is p (r_G - r_rod) = 4.7 N per mm of
    depth (the planar form of test_mount's p pi (r_G^2 - r_rod^2)); radially the rod's push
    equals the groove bottom's plus the fluid's radial resultant. Both steps end in the
    unstabilised static equilibrium. The rolling couple is a pure couple, so it cannot
    enter these balances; it carries 0.026 N mm per mm (measured), 0.2 % of rod force x cord
    radius: the rolled equilibria are neutral, the couple only picks one. Without it the
    section rolled off the rod (18 degrees at p = 0.95 MPa, then the one-line error)."""
    s = planar(tmp_path)
    assert s.fluid.p_in == 1.0 and s.groove.diameter == 2 * R_G
    state = mount_and_pressurise(s)
    model, u, t = state.model, state.u, state.t
    r = state.results
    g = r["groove_reactions"]
    fr, fz = model.pressure_resultant(state.load, t, u)
    f = r["contact_force_total"]
    assert r["static_equilibrium"]
    assert fz == pytest.approx(s.fluid.p_in * (R_G - R_ROD), rel=1e-3)
    assert -g["wall_atmosphere_side"] - g["wall_pressure_side"] == pytest.approx(fz, rel=1e-6)
    assert g["wall_pressure_side"] < 1e-3                 # it left the pressure-side wall
    assert f + g["bottom"] + fr == pytest.approx(0.0, abs=1e-6 * f)
    assert r["p_contact_max"] > s.fluid.p_in              # it seals at the rod
    assert f > 1.5 * 2.367                                # pressed on harder than mounted
    assert abs(r["rolling_gauge_torque"]) < 1e-2 * f * 0.5 * CORD
    assert abs(r["rolling_angle_deg"]) < 0.1
    assert r["front_change_edges"] < 1e-4


def test_planar_stroke_runs_and_the_rod_load_balances(tmp_path):
    """The pressurised planar O-ring through the coarse stroke (rod ramped to 100 mm/s in
    10 ms, held to 30 ms) with the film and friction on rod and groove (which hold the ring
    in the stroke; the rolling couple is not used there). At every accepted state the
    rod's load on the seal, film + asperity, equals what the seal passes on radially: the
    groove bottom's reaction, the fluid's radial load on the free surface and the groove
    walls' radial friction (1e-6). Newton is held to 1e-6 of TS's tolerance here, not the
    stroke's 1e-3 (sealts/problem/newton_test.py): at 1e-3 a wall anchor's last correction
    may be 1e-7 mm, which the stick stiffness mu p w / gamma_crit turns into up to 1e-4 of
    the load, a solver tolerance and not a balance. The film lifts the seal: at 100 mm/s
    the film carries more and the asperities less than at the start."""
    s = planar(tmp_path)
    assert s.stroke.friction and s.stroke.film
    step = stroke_of(mount_and_pressurise(s))
    U0 = step.start()
    step.problem.update_test = 1e-6
    balance = []

    def on_step(t, U):
        row = step.scalars(t, U)
        F = step.load.forces(t, U)
        through = (step.groove.reactions(t, U)["bottom"] + F[:, 0].sum() + F[:, 2].sum()
                   + step.groove_friction.total(t, U)["total"][0])
        balance.append((row["load_fluid"] + row["load_asperity"], through))

    U = step.run(U0, s.stroke.t_end, s.stroke.dt, s.stroke.rtol,
                 observers=[Recorder(on_step)])
    t = s.stroke.t_end
    a, b = step.scalars(0.0, U0), step.scalars(t, U)
    assert b["v"] == 100.0 and len(balance) > 10
    for rod, through in balance:
        assert rod > 5.0
        assert rod + through == pytest.approx(0.0, abs=1e-6 * rod)
    assert b["load_fluid"] > a["load_fluid"] > 0.0
    assert 0.0 < b["load_asperity"] < a["load_asperity"]
    assert b["h_min"] > a["h_min"] > 0.0
    assert b["friction_solid"] > 0.0                      # the rod drags the seal along +z


def test_rolling_couple_is_a_pure_couple_with_its_exact_jacobian():
    """The gauge's nodal forces sum to zero in r and z (a pure couple: no force balance
    sees it), their moment is its torque, and its Jacobian matches central differences.
    It is switched on for a round plane-strain section only (an O-ring, not a rectangle)."""
    from sealts.mesh.structured import rectangle
    from sealts.problem import Problem
    from sealts.solid.pressure import boundary_loop
    from sealts.solid.rolling import RollingGauge, gauge_nodes, is_round
    X, conn, _ = rectangle(1.0, 3.0, -1.0, 1.0, 6, 6)
    loop = boundary_loop(conn)[:, 0]
    assert not is_round(X, loop)
    phi = np.linspace(0, 2 * np.pi, 40, endpoint=False)
    assert is_round(np.column_stack([27.75 + 2.665 * np.cos(phi), 2.665 * np.sin(phi)]),
                    np.arange(40))
    n = 2 * X.shape[0]
    gauge = RollingGauge(X, gauge_nodes(X, loop), np.arange(n).reshape(-1, 2), 300.0, 0.01)
    u = np.random.default_rng(7).uniform(-0.05, 0.05, n)
    f = np.zeros(n)
    gauge.add_residual(0.0, u, None, f)
    F = -f.reshape(-1, 2)                                  # external force on the nodes
    assert abs(gauge.torque(u)) > 1.0
    assert np.abs(F.sum(0)).max() < 1e-12 * np.abs(F).max()
    moment = float((X[:, 0] * F[:, 1] - X[:, 1] * F[:, 0]).sum())
    assert moment == pytest.approx(gauge.torque(u), rel=1e-12)
    problem = Problem(n, [gauge])
    J = problem.jacobian_dense(0.0, u, u, 0.0)
    for j in gauge.dofs:
        e = np.zeros(n)
        e[j] = 1e-6
        fd = (problem.residual(0.0, u + e, u) - problem.residual(0.0, u - e, u)) / 2e-6
        assert np.abs(J[:, j] - fd).max() <= 1e-8 * np.abs(J).max()


def test_an_unheld_planar_oring_stops_with_a_one_line_error(tmp_path):
    """Without the rolling couple the stabilised pressurisation lets the round section roll
    (no hoop strain holds it) until nodes off the rod side, which the rod does not act on,
    pass into the rod; the run then stops with one line naming the roll (measured: 18.4
    degrees at t = 2.77, p = 0.95 MPa) instead of crawling on at dt ~ 1e-7."""
    from sealts.core import SolveError
    from sealts.steps import new_state, run_steps
    from sealts.steps.mount import Mount
    from sealts.steps.pressurise import Pressurise
    s = planar(tmp_path)
    state = new_state(s)
    assert state.model.gauge is not None
    state.model.gauge = None
    run_steps([Mount()], state)
    with pytest.raises(SolveError, match=r"inside the rod.*rolled by") as e:
        run_steps([Pressurise()], state)
    assert "\n" not in str(e.value)
