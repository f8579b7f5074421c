"""Symmetry of the coupled stroke: with p_in = p_out, outstroke and instroke are mirror images.

The mirror is z -> -z about the groove's mid-plane (z = 0: the groove's side walls are at
+-b/2 and the O-ring is centred there), which maps the rod velocity v to -v. With p_in =
p_out = 0 (no pressurisation, so no pressure-penetration front that would start from one
side) nothing else in the problem prefers a side: the rod is a cylinder, the groove is
symmetric, the film has the same Dirichlet value at both ends, and ``pressurised_end`` then
only names which end's flow is called Q_in. So a stroke at -v must be the mirror image of the
stroke at +v: node i's displacement (u_r, u_z) at +v is (u_r, -u_z) of its mirror node at -v,
the film profiles p(y) and h(y) are reversed in y, forces along z and the flows change sign,
and Q_in at +v is -Q_out at -v (V_in, V_out likewise).

For the check to be tight the mesh must itself be mirror-symmetric node for node, else the
mirrored runs differ by discretisation error (the default gmsh O-ring has nodes up to 0.31 mm
from any mirror image): the scenes here set ``mesh.symmetric = true``
(:func:`sealts.mesh.seal_mesh.build_mesh` with ``mirror=True``).

Independent truth: the mirror map is built from the mesh coordinates alone
(:func:`sealts.mesh.seal_mesh.mirror_map`); the simulator knows nothing of it.
"""
import numpy as np
import pytest

from conftest import CONFIGS, Recorder, mount_and_pressurise, scene
from sealts.mesh.seal_mesh import ORing, build_mesh, mirror_map
from sealts.problem.stroke_problem import StrokeProblem
from sealts.scene import SceneError

MESH = {"h_contact": 0.1, "h_bulk": 0.4, "symmetric": True}
STROKE = {"velocity": "ramp-hold", "t_ramp": 0.01, "t_end": 0.03, "dt": 2.5e-4,
          "output_times": [0.01, 0.02]}


def symmetric_scene(cache, v_max, friction=False, history="state"):
    """The paper's O-ring on the coarse symmetric mesh with p_in = p_out = 0; the rod ramps
    to v_max in 10 ms and holds to 30 ms."""
    return scene("oring_stroke", mesh={**MESH, "cache": cache},
                 fluid={"p_in": 0.0, "p_out": 0.0},
                 stroke={**STROKE, "v_max": v_max, "friction": friction,
                         "friction_history": history})


@pytest.fixture(scope="module")
def mounted(tmp_path_factory):
    """The mounted O-ring (p_in = 0: step 2 does nothing) and its mirror map j(i)."""
    cache = str(tmp_path_factory.mktemp("mesh"))
    s = symmetric_scene(cache, 100.0)
    state = mount_and_pressurise(s)
    model, u = state.model, state.u
    assert state.udot is None and state.load is None and state.done == ["mount"]
    return cache, model, u, mirror_map(model.mesh.X, 0.0)


class Mirror:
    """The mirror as a signed permutation of a StrokeProblem's unknowns: (M U)[dst] = sign U[src].
    Node i -> its image j(i) with u_r kept and u_z negated; the film pressures in reversed
    chain order; the rod friction's axial slips z in reversed chain order, negated; the
    groove walls' anchors (a_r, a_z) of node i -> (a_r, -a_z) of j(i);
    (V_in, V_out) -> (-V_out, -V_in); the friction work W -> W (v F keeps its sign).
    Residual rows transform alike (forces like displacements, film balances like
    pressures, slip rates like slips, dV/dt - Q like V)."""

    def __init__(self, step, j):
        lay = step.layout
        ud, pd, zd, vd = lay.udofs, lay.film_dofs, lay.slip_dofs, step.vdofs
        ad, gn = lay.groove_dofs, lay.groove_nodes
        at = {int(node): k for k, node in enumerate(gn)}
        image = np.array([at[int(j[node])] for node in gn], np.int64)
        wd = [step.work.wd] if step.work is not None else []
        self.src = np.concatenate([ud[:, 0], ud[:, 1], pd, zd, ad[:, 0], ad[:, 1], vd, wd])
        self.dst = np.concatenate([ud[j, 0], ud[j, 1], pd[::-1], zd[::-1], ad[image, 0],
                                   ad[image, 1], vd[::-1], wd])
        self.sign = np.concatenate([np.ones(len(j)), -np.ones(len(j)), np.ones(pd.size),
                                    -np.ones(zd.size), np.ones(len(gn)), -np.ones(len(gn)),
                                    -np.ones(2), np.ones(len(wd))])
        assert np.array_equal(np.sort(self.src), np.arange(step.n))     # every unknown
        assert np.array_equal(np.sort(self.dst), np.arange(step.n))
        self.n = step.n

    def __call__(self, U):
        out = np.empty(self.n)
        out[self.dst] = self.sign * U[self.src]
        return out

    def matrix(self):
        M = np.zeros((self.n, self.n))
        M[self.dst, self.src] = self.sign
        return M


def test_symmetric_mesh_and_scene_key(tmp_path):
    """``mesh.symmetric``: every node has its mirror image in the mesh (to 1e-12 of the size:
    the image is computed, not meshed), the rod-side chain is its own image reversed, the
    pressure and atmosphere sides swap, and the default mesh has no such symmetry (the
    reason for the option). A mesh file cannot be mirrored: one-line scene error; the key
    is a boolean."""
    shape = ORing(50.17, 5.33)
    mesh = build_mesh(shape, 0.1, 0.4, cache_dir=tmp_path, mirror=True)
    j = mirror_map(mesh.X, 0.0)
    assert np.array_equal(j[j], np.arange(j.size))
    chain = mesh.chain("rod_side")
    assert np.array_equal(j[chain], chain[::-1])
    for a, b in (("pressure_side", "atmosphere_side"), ("groove", "groove")):
        assert np.array_equal(np.sort(j[mesh.nodes(a)]), mesh.nodes(b))
    assert set(map(tuple, np.sort(j[mesh.conn], 1))) == set(map(tuple, np.sort(mesh.conn, 1)))
    with pytest.raises(ValueError, match="not mirror-symmetric"):
        mirror_map(build_mesh(shape, 0.1, 0.4, cache_dir=tmp_path).X, 0.0)
    with pytest.raises(SceneError, match="mesh.symmetric = true needs a built-in seal.shape"):
        scene("chamfered_ring_mount", mesh={"symmetric": True})
    with pytest.raises(SceneError, match="mesh.symmetric must be true or false"):
        scene("oring_stroke", mesh={"symmetric": "yes"})


def test_static_state_is_its_own_mirror_image(mounted):
    """At v = 0 the stroke's start (mounted seal, film solved, seal and film in equilibrium)
    is its own mirror image: u_r(j(i)) = u_r(i), u_z(j(i)) = -u_z(i), p reversed = p. It is
    reached by Newton from a symmetric initial guess on mirror-equivariant equations, so it
    is symmetric up to round-off amplified by the solves; bound 1e-10 of the largest
    displacement (measured 6e-15 mm against 0.71 mm) and 1e-12 MPa on p (all p are 0 here)."""
    cache, model, u, j = mounted
    step = StrokeProblem(model, u, symmetric_scene(cache, 100.0))
    U0 = step.start()
    M = Mirror(step, j)
    scale = np.abs(U0[step.layout.udofs]).max()
    err = np.abs(M(U0) - U0)
    assert err[step.layout.udofs].max() <= 1e-10 * scale
    assert err[step.layout.film_dofs].max() <= 1e-12
    assert step.scalars(0.0, U0)["load_asperity"] > 100.0       # N: the seal is squeezed


def run_stroke(model, u, s):
    """The stroke of scene s from the mounted state: the StrokeProblem, its start, the series
    (every accepted step's scalars, with U' as the step's difference quotient, as
    ``sealts run`` writes them) and the states and profiles at the output times."""
    step = StrokeProblem(model, u, s)
    U0 = step.start()
    series, last = [], {}

    def on_step(t, U):
        Udot = (U - last["U"]) / (t - last["t"]) if last and t > last["t"] else None
        series.append((t, step.scalars(t, U, Udot)))
        last.update(t=t, U=U)

    rec = Recorder(on_step)
    st = s.stroke
    U = step.run(U0, st.t_end, st.dt, st.rtol, st.output_times, [rec])
    stops = {round(t, 12): (Ut, step.profile(t, Ut)) for t, Ut in rec.stops}
    return step, U0, U, series, stops


@pytest.fixture(scope="module")
def strokes(mounted):
    """The stroke at +100 and at -100 mm/s (ramp 10 ms, hold to 30 ms), without solid
    friction, in fixed steps of 0.25 ms: see test_stroke_at_minus_v_is_the_mirror_image."""
    from petsc4py import PETSc
    cache, model, u, j = mounted
    opts = PETSc.Options()
    opts["stroke_ts_adapt_type"] = "none"
    try:
        return {sign: run_stroke(model, u, symmetric_scene(cache, sign * 100.0))
                for sign in (1, -1)}
    finally:
        opts.delValue("stroke_ts_adapt_type")


def test_stroke_at_minus_v_is_the_mirror_image(mounted, strokes):
    """The instroke (-v) is the mirror image of the outstroke (+v), step by step:

    * at every output time the whole state: U(-v) = M U(+v), so y(-v) = -y(+v) and h(y),
      p(y) reversed in y;
    * at every step: min h, the loads and the peak film pressure equal; fluid friction,
      v, Q_in <-> -Q_out and V_in <-> -V_out with opposite signs.

    Both runs start from the same (symmetric) state and take the same fixed steps, so they
    solve the same equations in mirrored order and differ only by where Newton stopped and
    round-off: measured at most 5e-14 mm in the displacements, y and h, 5e-11 of the peak in
    p and 3e-10 relative in the scalars (the flows with U' from the step's difference).
    Bounds: 1e-10 mm for displacements, y and h (2.5e-7 of min h), 1e-8 of the peak film
    pressure, 1e-8 of each scalar's largest magnitude over the run. Breaking the symmetry on
    purpose fails them: a 1e-4 imbalance of the film's Gauss weights or of the rod's
    tributary lengths moves the displacements by 6e-8 mm, a shear 1e-4 too large in one
    direction by 4e-6 mm, groove walls 0.1 um off centre or p_out = 1e-3 MPa by 2e-4 mm. On
    the default (unsymmetric) coarse mesh the mirrored runs differ by 2 % in min h, 2.4 % in
    the peak pressure and 12 % in the film load.

    Two choices make the check this tight. Fixed steps: with TS's adaptive steps the step
    sizes of the two runs part by up to 3e-4 of a step (the error estimate, a difference of
    nearly equal states, amplifies the round-off), and step-by-step values then differ by
    2e-5. No solid friction: its slip anchors are a history outside the TS error control, and
    with adaptive steps (149 against 147 with friction) the runs differed by 1e-4 of the
    friction and 4e-4 of the peak pressure; the friction terms' mirror symmetry is checked
    exactly, term by term, in test_terms_are_mirror_equivariant."""
    cache, model, u, j = mounted
    (sp, U0p, Up, series_p, stops_p), (sm, U0m, Um, series_m, stops_m) = strokes[1], strokes[-1]
    M = Mirror(sp, j)
    lay = sp.layout
    assert sp.motion.v(0.03) == 100.0 and sm.motion.v(0.03) == -100.0
    assert np.array_equal([t for t, _ in series_p], [t for t, _ in series_m])
    assert sorted(stops_p) == sorted(stops_m) == [0.01, 0.02, 0.03]
    p_peak = max(np.abs(U[lay.film_dofs]).max() for U, _ in stops_p.values())
    assert p_peak > 0.5                                   # MPa: hydrodynamic pressure
    for t in stops_p:
        (Ua, a), (Ub, b) = stops_p[t], stops_m[t]
        err = np.abs(Ub - M(Ua))
        assert err[lay.udofs].max() <= 1e-10
        assert err[lay.film_dofs].max() <= 1e-8 * p_peak
        assert np.abs(b["y"][::-1] + a["y"]).max() <= 1e-10
        assert np.abs(b["h"][::-1] - a["h"]).max() <= 1e-10
        assert np.abs(b["p"][::-1] - a["p"]).max() <= 1e-8 * p_peak
    mirrored = {"h_min": ("h_min", 1), "friction_fluid": ("friction_fluid", -1),
                "load_fluid": ("load_fluid", 1), "load_asperity": ("load_asperity", 1),
                "p_fluid_max": ("p_fluid_max", 1), "v": ("v", -1),
                "Q_in": ("Q_out", -1), "Q_out": ("Q_in", -1),
                "V_in": ("V_out", -1), "V_out": ("V_in", -1)}
    for key, (other, sign) in mirrored.items():
        a = np.array([r[key] for _, r in series_p])
        b = np.array([r[other] for _, r in series_m])
        assert np.abs(b - sign * a).max() <= 1e-8 * np.abs(a).max(), key
    # the check has something to see: the film lifts the seal, the rod drags it along and
    # fluid leaves at the outlet; frictionless, no solid friction
    start, end = series_p[0][1], series_p[-1][1]
    assert end["h_min"] > 1.02 * start["h_min"]
    assert end["friction_fluid"] > 0.1 and end["Q_out"] > 1.0
    assert end["friction_solid"] == 0.0


@pytest.mark.parametrize("history", ["state", "anchors"])
def test_terms_are_mirror_equivariant(mounted, history):
    """Every term of the stroke with solid friction (seal, rod contact and its friction,
    groove and its friction on the bottom and both side walls, all pressed here, film with
    shear and surface-normal load, leakage) is mirror-equivariant, at a state that is not symmetric itself: at
    t = 5 ms of the ramp (v = +-50 mm/s, rod travel +-0.125 mm) and for a random U, U' and
    random elastic slips of the rod friction (from stick through the blend to flowing; as
    TS unknowns or through its anchors) and groove anchors,

        F_-v(t, M U, M U') = M F_+v(t, U, U'),   J_-v = M J_+v M^T,

    and the anchors after an update are the mirror images (rod, history "anchors": a -> -a on the mirrored
    chain node; groove: (a_r, a_z) -> (a_r, -a_z) on the mirrored node). The stroke steps'
    own starts fix the film's row scales, which must be mirror images too. Bound 1e-9 of
    each row block's largest entry: both sides add the same numbers in another order
    (measured at most 9e-12, on the film rows, whose balances cancel; anchors to 0). A friction
    law 1e-3 stronger in -z, or side wall b's tangent tilted by 1e-3, breaks it by
    5e-5 and 2e-5 of the largest force."""
    cache, model, u, j = mounted
    steps = {sign: StrokeProblem(model, u, symmetric_scene(cache, sign * 100.0, friction=True,
                                                           history=history))
             for sign in (1, -1)}
    sp, sm = steps[1], steps[-1]
    for st in (sp, sm):
        st.start()
    M = Mirror(sp, j)
    lay = sp.layout
    chain = lay.rod_nodes
    assert np.array_equal(j[chain], chain[::-1])
    assert np.allclose(sm.film.row_scale, sp.film.row_scale[::-1], rtol=1e-9, atol=0)
    rng = np.random.default_rng(7)
    t = 0.005
    U = np.zeros(sp.n)
    U[lay.udofs] = u[model.udofs] + rng.uniform(-1e-4, 1e-4, lay.udofs.shape)
    U[lay.film_dofs] = rng.uniform(-0.5, 1.5, chain.size)
    U[sp.vdofs] = rng.uniform(-1.0, 1.0, 2)
    Ud = rng.uniform(-1e-2, 1e-2, sp.n)
    # rod friction: elastic slips of -2..2 gamma_crit, gamma = s - u_z - a through the
    # anchors or z as unknowns
    rf_p, rf_m = sp.friction, sm.friction
    gc = rf_p.gamma_crit
    slips = rng.uniform(-2, 2, chain.size) * gc
    if history == "anchors":
        rf_p.anchors = (rf_p.s(t) - U[rf_p.side.uz] - slips)
        rf_m.anchors = -rf_p.anchors[::-1]
    else:
        U[lay.slip_dofs] = slips
    # groove friction: anchors within a few gamma_crit of the node, per groove node
    gf_p, gf_m = sp.groove_friction, sm.groove_friction
    nodes = sp.groove.nodes
    at = {int(n): k for k, n in enumerate(nodes)}
    image = np.array([at[int(j[n])] for n in nodes])
    assert np.array_equal(np.sort(image), np.arange(nodes.size))
    anchors = gf_p._disp(U) + rng.uniform(-3, 3, (nodes.size, 2)) * gc
    if history == "anchors":
        gf_p.anchors = anchors
        gf_m.anchors = np.empty_like(gf_p.anchors)
        gf_m.anchors[image] = gf_p.anchors * [1.0, -1.0]
    else:
        assert np.array_equal(lay.groove_nodes, nodes)
        U[lay.groove_dofs] = anchors
    # the state has every regime: asperity contact, sticking, sliding; walls pressed
    phi = np.abs(rf_p.slip(t, U)) / gc
    p_s, _ = rf_p.contact.pressure(t, U)
    assert (p_s > 0).sum() > 5 and (phi[p_s > 0] < 0.5).any() and (phi[p_s > 0] > 1).any()
    assert (gf_p.slot_forces(t, U) != 0).any()
    blocks = {"u": lay.udofs.ravel(), "p": lay.film_dofs, "V": sp.vdofs}
    if history == "state":
        blocks["z"], blocks["a"] = lay.slip_dofs, lay.groove_dofs.ravel()
    Fp = sp.problem.residual(t, U, Ud)
    Fm = sm.problem.residual(t, M(U), M(Ud))
    for name, rows in blocks.items():
        scale = np.abs(Fp[rows]).max()
        assert scale > 0
        assert np.abs(Fm - M(Fp))[rows].max() <= 1e-9 * scale, name
    shift = 400.0
    Jp = sp.problem.jacobian_dense(t, U, Ud, shift)
    Jm = sm.problem.jacobian_dense(t, M(U), M(Ud), shift)
    Mm = M.matrix()
    err = np.abs(Jm - Mm @ Jp @ Mm.T)
    for name, rows in blocks.items():
        assert err[rows].max() <= 1e-9 * np.abs(Jp[rows]).max(), name
    # the anchors' return mapping
    if history == "anchors":
        rf_p.update(t, U)
        rf_m.update(t, M(U))
        assert np.abs(rf_m.anchors + rf_p.anchors[::-1]).max() <= 1e-12
    if history == "anchors":
        gf_p.update(t, U)
        gf_m.update(t, M(U))
        assert np.abs(gf_m.anchors[image] - gf_p.anchors * [1.0, -1.0]).max() <= 1e-12
