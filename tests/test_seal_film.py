"""The film on the deforming seal (SealFilmTerm): exact Jacobian, rigid limit, mass balance,
and a coupled solve of the coarse O-ring.

Each test checks the coupled term against something computed another way: central
differences of its residual, the rigid-gap ControlVolumeScheme and shear_stress() of the
film-only scenes on the same nodes, a film volume differenced in time, trapezoid integrals of
p, and the axial force balance of the solved seal.
"""
import numpy as np
import pytest

from conftest import assert_jacobian_matches, central_differences
from sealts.contact.rod_side import RodSide
from sealts.film.flow_factors import FlowFactors
from sealts.film.quantities import shear_stress
from sealts.film.reynolds_fv import ControlVolumeScheme, control_volumes, element_fluxes
from sealts.film.seal_film import SealFilmTerm
from sealts.mesh.layout import Layout
from sealts.mesh.seal_mesh import ORing, build_mesh
from sealts.problem import Problem

ETA, H_FLOOR, RQ = 1e-8, 1e-5, 2.15e-4
R0 = 25.0                      # rod radius at t = 0 (mm)
AREA = 2 * np.pi * R0


def rod(t):
    return R0 + 1e-5 * t       # a slowly growing rod, so dr/dt enters dh/dt


def rod_rate(t):
    return 1e-5


def coarse(tmp_path):
    mesh = build_mesh(ORing(50.17, 5.33), 0.3, 0.6, cache_dir=tmp_path)
    return mesh, Layout(mesh, film=True)


def make_term(mesh, layout, factors="none", end="min_z", squeeze=True, v=80.0,
              surface_normal=False, shear=False, stiff=0.0):
    ff = FlowFactors.patir_cheng(RQ, 1.0) if factors == "patir-cheng" else FlowFactors.none()
    side = RodSide(mesh.X, layout.rod_nodes, rod, AREA, udofs=layout.udofs, rod_rate=rod_rate)
    return SealFilmTerm(side, layout.film_dofs, lambda t: v, ETA, lambda t: 1.0 + 0.1 * t,
                        0.2, ff=ff, h_floor=H_FLOOR, squeeze=squeeze, pressurised_end=end,
                        surface_normal=surface_normal, shear=shear, beta=0.3, stiff=stiff)


def seal_state(mesh, layout, seed, t=0.3, h_low=1.5e-5, h_mean=1.7e-3, p_uniform=False):
    """A random smooth displacement of the whole seal that brings the rod-side chain to gaps
    of h_mean (1 +- 0.7) (0.5..3 um by default; one node at h_low, inside the h_floor
    regularisation), random film pressures (or all 1 MPa) and a random U' (radial squeeze
    rates of order 1 um/s)."""
    rng = np.random.default_rng(seed)
    X = mesh.X
    u = np.zeros(layout.n)
    k = rng.uniform(0.5, 2.0, (2, 2))
    ph = rng.uniform(0, 2 * np.pi, 2)
    u[layout.udofs[:, 0]] = 0.01 * np.sin(k[0, 0] * X[:, 0] + k[0, 1] * X[:, 1] + ph[0])
    u[layout.udofs[:, 1]] = 0.02 * np.sin(k[1, 0] * X[:, 0] + k[1, 1] * X[:, 1] + ph[1])
    c = layout.rod_nodes
    z = X[c, 1]
    h = h_mean * (1.0 + 0.7 * np.sin(2.1 * z + rng.uniform(0, 6)))
    if h_low is not None:
        h[c.size // 3] = h_low
    u[layout.udofs[c, 0]] = rod(t) + h - X[c, 0]
    u[layout.film_dofs] = 1.0 if p_uniform else rng.uniform(0.0, 2.0, c.size)
    ud = rng.uniform(-1.0, 1.0, layout.n) * 1e-3
    return u, ud


@pytest.mark.parametrize("factors,end,normal,gap,stiff", [
    ("none", "min_z", False, "thin", 0.0), ("patir-cheng", "max_z", True, "thin", 0.0),
    ("none", "min_z", False, "thick", 0.0), ("patir-cheng", "min_z", True, "thin", 27.0)])
def test_seal_film_jacobian(tmp_path, factors, end, normal, gap, stiff):
    """Every block (p-p, p-u_r, p-u_z, p-u_r' through the TS shift, u_r-p, u_r-u_z, and the
    shear and surface-normal loads' u_z-p, u_z-u_r, u_z-u_z, u_z-u_r') against central
    differences in U and U'; bound 1e-6 of the largest entry of each row, and of each block
    (film pressure, u_r, u_z rows and columns of the chain). The "thin" films
    are 0.5..3 um with one node in the h_floor range and a sliding rod; the "thick" one
    (30..170 um, uniform p, rod at rest) leaves the squeeze-rate gradient of Eq. 32-33 as
    the shear, which is otherwise far below round-off of the rest. ``stiff`` = pi E' (MPa)
    of the hyperelastic O-ring's long-term modulus: the upwinded Couette flow, its element
    Peclet numbers from about 1 to 1e3 over these gaps."""
    mesh, layout = coarse(tmp_path)
    term = make_term(mesh, layout, factors, end, surface_normal=normal, shear=True,
                     v=80.0 if gap == "thin" else 0.0, stiff=stiff)
    t = 0.3
    if gap == "thin":
        u, ud = seal_state(mesh, layout, 1, t)
    else:
        u, ud = seal_state(mesh, layout, 1, t, h_low=None, h_mean=0.1, p_uniform=True)
    term.set_row_scale(t, u, ud)
    problem = Problem(layout.n, [term])
    shift = 37.0
    J0 = problem.jacobian_dense(t, u, ud, 0.0)
    Jshift = (problem.jacobian_dense(t, u, ud, shift) - J0) / shift
    c = layout.rod_nodes
    blocks = {"p": layout.film_dofs, "ur": layout.udofs[c, 0], "uz": layout.udofs[c, 1]}
    # u_r steps above the round-off of h = R + u_r - r (R ~ 25 mm: 3e-15 mm); F is affine in
    # U', so its step may be large
    eps = {"p": 1e-6, "ur": 1e-8, "uz": 1e-7}
    n = layout.n
    fd_u, fd_ud = central_differences(problem, t, u, ud, blocks, eps, n)
    # nothing outside the chain's dofs is touched
    others = np.setdiff1d(np.arange(n), np.concatenate(list(blocks.values())))
    assert not np.any(J0[others]) and not np.any(J0[:, others])
    assert_jacobian_matches(((J0, fd_u), (Jshift, fd_ud)), J0, blocks)
    # the check saw every coupling: pressure gradients, squeeze, moving nodes, loads
    assert np.abs(J0[np.ix_(blocks["p"], blocks["uz"])]).max() > 0
    assert np.abs(Jshift[np.ix_(blocks["p"], blocks["ur"])]).max() > 0
    assert np.abs(J0[np.ix_(blocks["ur"], blocks["uz"])]).max() > 0
    assert np.abs(Jshift[np.ix_(blocks["uz"], blocks["ur"])]).max() > 0   # Eq. 33's rates


def test_film_where_the_rod_side_runs_up_a_wall(tmp_path):
    """The last five chain nodes pressed into a groove wall (as at 30-40 MPa, where the rod
    side runs up the atmosphere-side wall): one axial position to within microns, out of
    order (two elements reversed by 3 and 1 um), gaps of 50-250 um. The film takes their
    elements as short positive ones (reynolds_fv, "Element lengths"): its rows stay finite,
    its Jacobian matches central differences as on a forward chain, and its balance still
    closes on the content A sum_i M_i h_i with M_i from those lengths (to round-off of the
    flows); with the raw axial lengths the reversed elements' conductances turn negative."""
    mesh, layout = coarse(tmp_path)
    term = make_term(mesh, layout, "none", "min_z", surface_normal=True, shear=True)
    c, t = layout.rod_nodes, 0.3
    ur, uz, pd = layout.udofs[c, 0], layout.udofs[c, 1], layout.film_dofs
    u, ud = seal_state(mesh, layout, 5, t, h_low=None)
    ud[uz] = 0.0
    wall = mesh.X[c[-6], 1] + u[uz[-6]] + 0.01
    y_wall = wall + np.array([2e-3, 5e-3, 2e-3, 3e-3, 1e-3])     # two reversals, 3 and 1 um
    h_wall = np.array([0.05, 0.1, 0.15, 0.2, 0.25])
    u[uz[-5:]] = y_wall - mesh.X[c[-5:], 1]
    u[ur[-5:]] = rod(t) + h_wall - mesh.X[c[-5:], 0]
    u[pd[-6:]] = 0.2                                            # p_out, as on the wall
    y = mesh.X[c, 1] + u[uz]
    assert np.sum(np.diff(y) < 0) == 2
    term.set_row_scale(t, u, ud)
    problem = Problem(layout.n, [term])
    f = problem.residual(t, u, ud)
    assert np.all(np.isfinite(f))
    # the elements' conductances 1/(L I1) = dq/dp_a: all positive
    ff = FlowFactors.none()
    h = mesh.X[c, 0] + u[ur] - rod(t)
    _, dqa, *_ = element_fluxes(y, h, u[pd], 80.0, ETA, H_FLOOR, ff.model, ff.par,
                                ff.table_h, ff.table_pp, ff.table_ps)
    assert np.all(dqa > 0.0)
    # the balance closes on the content: interior rows add up to Q_in - Q_out - dV/dt
    balance = f[pd][1:-1] / term.row_scale[1:-1]
    Q_in, Q_out = term.flows(t, u, ud)
    dvol = (term.content(t + 0.5, u + 0.5 * ud) - term.content(t - 0.5, u - 0.5 * ud))
    scale = max(abs(Q_in), abs(Q_out), abs(dvol)) / AREA
    assert abs(balance.sum() - (dvol - (Q_in - Q_out)) / AREA) <= 1e-10 * scale
    # the Jacobian against central differences: row by row, block by block, and row by row
    # within the film rows' u_z block (where the wall's storage moves with its lengths), at
    # this state and with pressures that differ along the wall (the lengths in the flows)
    blocks = {"p": pd, "ur": ur, "uz": uz}
    eps = {"p": 1e-6, "ur": 1e-8, "uz": 1e-8}
    shift = 37.0
    for p_wall in (np.full(6, 0.2), np.random.default_rng(6).uniform(0.0, 2.0, 6)):
        u[pd[-6:]] = p_wall
        term.set_row_scale(t, u, ud)
        J0 = problem.jacobian_dense(t, u, ud, 0.0)
        Jshift = (problem.jacobian_dense(t, u, ud, shift) - J0) / shift
        fd_u, fd_ud = central_differences(problem, t, u, ud, blocks, eps, layout.n)
        assert_jacobian_matches(((J0, fd_u), (Jshift, fd_ud)), J0, blocks)
        for J, fd in ((J0, fd_u), (Jshift, fd_ud)):
            a, b = J[np.ix_(pd, uz)], fd[np.ix_(pd, uz)]
            row = np.maximum(np.abs(a).max(1), np.abs(b).max(1))
            assert np.all(np.abs(a - b).max(1) <= 1e-6 * row + 1e-14)
    # the leakage rows, whose outlet element is the last, reversed one
    from sealts.film.seal_film import LeakageTerm
    n = layout.n + 2
    leak = LeakageTerm(term, [layout.n, layout.n + 1])
    uu, uud = np.zeros(n), np.zeros(n)
    uu[:layout.n], uud[:layout.n] = u, ud
    lp = Problem(n, [leak])
    rows = [layout.n, layout.n + 1]
    for s_ in (0.0, 23.0):
        J = lp.jacobian_dense(t, uu, uud, s_)
        fd = np.zeros((2, n))
        for j in np.unique(leak.cols):
            e = np.zeros(n)
            e[j] = 1e-6 if j in pd else 1e-8
            fd[:, j] = (lp.residual(t, uu + e, uud)[rows] - lp.residual(t, uu - e, uud)[rows]
                        ) / (2 * e[j])
            if s_:
                e[j] = 1e-2
                fd[:, j] += s_ * (lp.residual(t, uu, uud + e)[rows]
                                  - lp.residual(t, uu, uud - e)[rows]) / 2e-2
        assert np.all(np.abs(J[rows] - fd).max(1) <= 1e-6 * np.abs(J[rows]).max(1))
    # with one pressure along the wall the outlet element carries no flow through its
    # length, so Q_out's entries in that element's two u_z columns are its end storage's
    # alone, through M = L/2 (dS/dy = S/M dM/dy): far below the row's conductances, so
    # checked entry by entry
    uu[pd[-6:]] = 0.2
    cols = [uz[-2], uz[-1]]
    J = lp.jacobian_dense(t, uu, uud, 0.0)
    fd = np.zeros((2, 2))
    for k, j in enumerate(cols):
        e = np.zeros(n)
        e[j] = 1e-6
        fd[:, k] = (lp.residual(t, uu + e, uud)[rows] - lp.residual(t, uu - e, uud)[rows]) / (2 * 1e-6)
    out = rows[1] - layout.n
    assert np.all(np.abs(fd[out]) > 0.0)
    assert np.allclose(J[np.ix_(rows, cols)][out], fd[out], rtol=1e-5, atol=0.0)


@pytest.mark.parametrize("end", ["min_z", "max_z"])
def test_rigid_limit_is_the_film_only_scheme(tmp_path, end):
    """On the same nodes (y, h, dh/dt) the film rows are the ControlVolumeScheme's rows of the
    film-only scenes, residual and pressure Jacobian, to round-off: at u = 0 (the seal's own
    curved surface over the rod), and on a deformed seal with the scheme built on the current
    y = Z + u_z and h = R + u_r - r. The nodal shear forces are the film-only output's shear
    stress (Eq. 32-33, from the scheme's pressure gradient) times A M_i."""
    mesh, layout = coarse(tmp_path)
    term = make_term(mesh, layout, "patir-cheng", end, shear=True)
    c, t = layout.rod_nodes, 0.3
    ur, uz, pd = layout.udofs[c, 0], layout.udofs[c, 1], layout.film_dofs
    deformed, ud = seal_state(mesh, layout, 2, t)
    rigid = np.zeros(layout.n)
    rigid[pd] = deformed[pd]
    for u in (rigid, deformed):
        y = mesh.X[c, 1] + u[uz]
        h = mesh.X[c, 0] + u[ur] - rod(t)
        hd = ud[ur] - rod_rate(t)
        p_first, p_last = (1.0 + 0.1 * t, 0.2) if end == "min_z" else (0.2, 1.0 + 0.1 * t)
        scheme = ControlVolumeScheme(y, ETA, lambda t: 80.0, p_first, p_last,
                                     FlowFactors.patir_cheng(RQ, 1.0), H_FLOOR)
        scheme.set_row_scale(t, u[pd], h, hd)
        term.set_row_scale(t, u, ud)
        want, _, _ = scheme.residual(t, u[pd], h, hd)
        f = np.zeros(layout.n)
        term.add_residual(t, u, ud, f)
        assert np.allclose(f[pd], want, rtol=0, atol=1e-13 * np.abs(want).max())
        vals, _ = scheme.jacobian(t, u[pd], h, hd)
        Jp = np.zeros((c.size, c.size))
        np.add.at(Jp, scheme.pattern, vals)
        J = Problem(layout.n, [term]).jacobian_dense(t, u, ud, 5.0)
        assert np.allclose(J[np.ix_(pd, pd)], Jp, rtol=1e-13, atol=0)
        tau = shear_stress(y, h, hd, scheme.pressure_gradient(t, u[pd], h, hd), 80.0, ETA,
                           H_FLOOR, 0.3)
        want = tau * AREA * control_volumes(y)
        assert np.allclose(term.shear_forces(t, u, ud), want, rtol=1e-12,
                           atol=1e-12 * np.abs(want).max())
        assert np.allclose(f[uz], -want, rtol=1e-12, atol=1e-12 * np.abs(want).max())


def test_mass_balance_and_radial_force(tmp_path):
    """The interior balances add up to Q_in - Q_out - d/dt(sum_i M_i h_i) = 0 to round-off,
    the film's content is A sum_i M_i h_i,
    with the boundary flows from the element flows and the end control volumes, and the film
    volume differenced in time along u + s U' with a moving rod; and the radial film force on
    the seal is A times the trapezoid integral of p over the current y."""
    mesh, layout = coarse(tmp_path)
    term = make_term(mesh, layout, "none", "max_z", surface_normal=True)
    c, t = layout.rod_nodes, 0.3
    ur, uz, pd = layout.udofs[c, 0], layout.udofs[c, 1], layout.film_dofs
    u, ud = seal_state(mesh, layout, 3, t, h_low=4e-4)   # h > 2 h_floor: h_eff = h
    ud[uz] = 0.0             # the film ignores the seal's axial velocity (Eq. 21)
    term.set_row_scale(t, u, ud)
    f = np.zeros(layout.n)
    term.add_residual(t, u, ud, f)
    balance = f[pd][1:-1] / term.row_scale[1:-1]
    y = mesh.X[c, 1] + u[uz]
    M = np.zeros(c.size)
    M[:-1] += 0.5 * np.diff(y)
    M[1:] += 0.5 * np.diff(y)

    def volume(s):
        us, ts = u + s * ud, t + s
        return M @ (mesh.X[c, 0] + us[ur] - rod(ts))

    dvol = volume(0.5) - volume(-0.5)   # linear in s: exact for any step
    ff = FlowFactors.none()
    q, *_ = element_fluxes(y, mesh.X[c, 0] + u[ur] - rod(t), u[pd], 80.0, ETA, H_FLOOR,
                           ff.model, ff.par, ff.table_h, ff.table_pp, ff.table_ps)
    hd = ud[ur] - rod_rate(t)
    # pressurised end at max z: inflow there is -q in -y, outflow at min z is -q too
    q_in = -(q[-1] - M[-1] * hd[-1])
    q_out = -(q[0] + M[0] * hd[0])
    scale = np.abs(q).max()
    assert abs(balance.sum() - (dvol - (q_in - q_out))) <= 1e-12 * scale
    Q_in, Q_out = term.flows(t, u, ud)
    assert Q_in == pytest.approx(AREA * q_in, rel=1e-13)
    assert Q_out == pytest.approx(AREA * q_out, rel=1e-13)
    # the fluid the film holds (the stroke's V_film, whose change the summary's film_balance
    # sets against V_in - V_out): A sum_i M_i h_i
    assert term.content(t, u) == pytest.approx(AREA * volume(0.0), rel=1e-13)
    # the load: on the chain's u_r (outward on the seal) and u_z rows only; radially
    # A int p dy, axially -A int p dr over the current chain (trapezoids)
    f_u = f.copy()
    f_u[pd] = 0.0
    assert np.count_nonzero(f_u[ur]) == c.size and np.all(f_u[ur] < 0)
    assert np.count_nonzero(f_u) == np.count_nonzero(f_u[ur]) + np.count_nonzero(f_u[uz])
    p = u[pd]
    r = mesh.X[c, 0] + u[ur]
    assert -f_u[ur].sum() == pytest.approx(
        AREA * float(np.sum(0.5 * (p[1:] + p[:-1]) * np.diff(y))), rel=1e-13)
    assert -f_u[uz].sum() == pytest.approx(
        -AREA * float(np.sum(0.5 * (p[1:] + p[:-1]) * np.diff(r))), rel=1e-12)


def test_squeeze_off_and_dirichlet_ends(tmp_path):
    """Without the squeeze term U' does not enter (no shift entries); the end rows hold p_in
    at the pressurised end and p_out at the other, at their time-dependent values."""
    mesh, layout = coarse(tmp_path)
    c, t = layout.rod_nodes, 0.7
    u, ud = seal_state(mesh, layout, 4, t)
    pd = layout.film_dofs
    for end, (first, last) in (("min_z", (1.07, 0.2)), ("max_z", (0.2, 1.07))):
        term = make_term(mesh, layout, "none", end, squeeze=False)
        problem = Problem(layout.n, [term])
        f0 = problem.residual(t, u, np.zeros(layout.n))
        assert np.array_equal(f0, problem.residual(t, u, ud))
        assert np.array_equal(problem.jacobian_dense(t, u, ud, 0.0),
                              problem.jacobian_dense(t, u, ud, 50.0))
        assert f0[pd[0]] == pytest.approx(u[pd[0]] - first, abs=1e-15)
        assert f0[pd[-1]] == pytest.approx(u[pd[-1]] - last, abs=1e-15)


def test_pressurised_oring_with_film(tmp_path):
    """The coarse mounted O-ring with the film on its rod side (surface-normal load), p_in =
    1 MPa on the pressure side (the film's inlet, and the min-z flank by a PressureLoad with
    its ``pressure_side`` edges wetted, no front updates), ramped in pseudo-time with viscous
    stabilisation, then static Newton solves:

    * v = 0: the hydrostatic film falls monotonically from p_in to p_out through the
      contact; it leaks as much as it takes in (Q_in = Q_out > 0); it pushes the seal off the
      rod; and the seal's axial balance closes: the side walls take the fluid's axial load
      (pressure side flank plus the film's surface-normal part);
    * v = 100 mm/s out of the pressure side (from the v = 0 state): hydrodynamic lift, a film
      peak above p_in, a thicker film, less asperity load, more leakage, and the fluid shear
      drags the seal along.
    """
    from conftest import scene
    from sealts.contact.rigid import GrooveContact, RodContact
    from sealts.problem import Constraints
    from sealts.problem.seal_model import ramp
    from sealts.steps import prepare
    from sealts.solid.pressure import PressureLoad
    from sealts.solid.stabilisation import ViscousStabilisation
    from sealts.solid.term import SolidTerm

    s = scene("oring_mount", mesh={"h_contact": 0.1, "h_bulk": 0.4, "cache": str(tmp_path)})
    state = prepare(s)
    model, u_mounted = state.model, state.u
    assert state.udot is None
    mesh, X = model.mesh, model.mesh.X
    lay = Layout(mesh, film=True)
    chain, ud = lay.rod_nodes, lay.udofs
    u = np.zeros(lay.n)
    u[ud] = u_mounted[model.udofs]
    # the mounted model's terms, on the layout with the film pressure field
    solid = SolidTerm(X, mesh.conn, model.material, True, udofs=ud, heating=ramp)
    rod_side = model.side.on(ud)
    rod_c = RodContact(rod_side, model.law)
    g = model.groove
    groove = GrooveContact(X, g.nodes, np.ones(X.shape[0]), True, model.groove_radius,
                           g.z_walls, penalty=g.k, delta=g.delta, udofs=ud,
                           corner_radius=g.rho)
    groove.w = g.w
    stab = ViscousStabilisation(ud.ravel(), model.stab.m, model.stab.c)
    t0, t_mid, t1 = state.protocol.pressurise               # after the mount, as step 2
    p_in = lambda t: ramp(t - t0)                           # 0 -> 1 MPa over t0 .. t0 + 1
    velocity = [0.0]
    film = SealFilmTerm(rod_side, lay.film_dofs, lambda t: velocity[0], 1e-8, p_in, 0.0,
                        squeeze=False, pressurised_end="min_z", surface_normal=True)
    side = mesh.nodes("pressure_side")
    load = PressureLoad(X, mesh.conn, p_in, True, side[np.argmin(X[side, 1])], udofs=ud)
    flank = {tuple(sorted(e)) for e in mesh.edges["pressure_side"]}
    load.s1 = np.array([tuple(sorted(e)) in flank for e in load.edges], float)
    assert load.wet.sum() == len(flank)
    # a consistent film pressure on the mounted seal, then the pseudo-time ramp
    fixed = Constraints(ud.ravel(), u[ud.ravel()])
    u = Problem(lay.n, [film], constraints=fixed).solve_steady(u, t0)
    film.set_row_scale(t0, u)
    atol = 1e-9 * model.force_scale
    ramped = Problem(lay.n, [solid, rod_c, groove, stab, film, load], linesearch="basic",
                     snes_atol=atol)
    u = ramped.transient(u, t0, t1, 0.02, stops=(t_mid,), rtol=1e-3, atol=1e-4)
    static = Problem(lay.n, [solid, rod_c, groove, film, load], linesearch="basic",
                     snes_atol=atol)
    static.max_it = 10
    results = []
    for v in (0.0, 100.0):
        velocity[0] = v
        u = static.solve_steady(u, t1)
        p = u[lay.film_dofs]
        results.append(dict(p=p, q=film.flows(t1, u, np.zeros(lay.n)),
                            h_min=rod_side.gap(t1, u).min(), asperity=rod_c.forces(t1, u).sum(),
                            film=film.forces(t1, u).sum(),
                            shear=film.shear_forces(t1, u).sum()))
        if v == 0.0:
            assert p[0] == pytest.approx(1.0, abs=1e-12) and p[-1] == pytest.approx(0.0, abs=1e-12)
            assert np.all(np.diff(p) <= 1e-9) and p.min() >= -1e-9
            assert 0.0 < p[chain.size // 2] < 1.0               # it falls inside the contact
            walls = groove.reactions(t1, u)
            fz = load.forces(t1, u)
            fluid_z = (fz[:, 1].sum() + fz[:, 3].sum() + film.axial_forces(t1, u).sum()
                       + film.shear_forces(t1, u).sum())
            wall_z = walls["wall_pressure_side"] + walls["wall_atmosphere_side"]
            assert fluid_z > 0 and wall_z == pytest.approx(-fluid_z, rel=1e-6)
    still, moving = results
    for r in results:
        q_in, q_out = r["q"]
        assert q_out > 0 and q_in == pytest.approx(q_out, rel=1e-5)
        assert r["film"] > 0 and r["asperity"] > 0
    assert moving["p"].max() > 1.2                          # hydrodynamic peak above p_in
    assert moving["h_min"] > still["h_min"]
    assert moving["asperity"] < still["asperity"]
    assert moving["q"][1] > 10 * still["q"][1]
    assert moving["shear"] > 0                               # the rod drags the seal along


@pytest.mark.parametrize("end,stiff", [("min_z", 0.0), ("max_z", 0.0), ("min_z", 27.0)])
def test_leakage_term_jacobian_and_flows(tmp_path, end, stiff):
    """The leakage ODEs dV/dt = Q (LeakageTerm): their flows are SealFilmTerm.flows, and their
    Jacobian in U and U' (with the shift) matches central differences to 1e-6 of each row's
    largest entry (``stiff``: with the upwinded Couette flow)."""
    from sealts.film.seal_film import LeakageTerm
    mesh, layout = coarse(tmp_path)
    term = make_term(mesh, layout, "patir-cheng", end, stiff=stiff)
    n = layout.n + 2
    leak = LeakageTerm(term, [layout.n, layout.n + 1])
    t = 0.3
    u0, ud0 = seal_state(mesh, layout, 5, t)
    u, ud = np.zeros(n), np.zeros(n)
    u[:layout.n], ud[:layout.n] = u0, ud0
    ud[layout.n:] = (0.7, -0.2)
    assert leak.flows(t, u, ud) == pytest.approx(term.flows(t, u0, ud0), rel=1e-12)
    problem = Problem(n, [leak])
    shift = 23.0
    J0 = problem.jacobian_dense(t, u, ud, 0.0)
    Js = (problem.jacobian_dense(t, u, ud, shift) - J0) / shift
    rows = [layout.n, layout.n + 1]
    for J, which in ((J0, "u"), (Js, "ud")):
        fd = np.zeros((2, n))
        for j in np.unique(leak.cols):
            e = np.zeros(n)
            h = 1e-2 if which == "ud" else (1e-6 if j in layout.film_dofs else 1e-8)
            e[j] = h
            a, b = (u + e, ud) if which == "u" else (u, ud + e)
            c, d = (u - e, ud) if which == "u" else (u, ud - e)
            fd[:, j] = (problem.residual(t, a, b)[rows] - problem.residual(t, c, d)[rows]) / (2 * h)
        err = np.abs(J[rows] - fd).max(1) / np.abs(J[rows]).max(1)
        assert err.max() <= 1e-6, (which, err)
    assert np.abs(Js[rows][:, layout.udofs[layout.rod_nodes, 0]]).max() > 0   # squeeze
