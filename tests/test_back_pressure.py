"""A back pressure p_out on the seal's atmosphere side (sealts/solid/fluid_loads.py): two
fluids, each with its own pressure-penetration fronts, loads adding.

Independent truth is the mirror z -> -z about the groove's mid-plane, on a mesh that is
mirror-symmetric node for node (``mesh.symmetric = true``; the map comes from the
coordinates alone, :func:`sealts.mesh.seal_mesh.mirror_map`):

* p_in = p_out: nothing prefers a side, so the pressurised state is its own mirror image:
  u_r(j(i)) = u_r(i), u_z(j(i)) = -u_z(i), the fluids' axial forces cancel and each fluid's
  fronts reach as far as the other's;
* p_in = 0 with a back pressure p is the mirror image of p_in = p without one: the same seal
  pressed against the other wall. This compares the new fluid (started on the atmosphere
  side) with the old one (started on the pressure side), which share only PressureLoad.

A short stroke with p_in = p_out runs through the film with both Dirichlet ends at p.
"""
import numpy as np
import pytest

from conftest import mount_and_pressurise, scene
from sealts.mesh.seal_mesh import mirror_map

MESH = {"h_contact": 0.1, "h_bulk": 0.4, "symmetric": True}
P = 2.0          # MPa


def pressurised(cache, p_in, p_out, **sections):
    s = scene("oring_stroke", mesh={**MESH, "cache": cache},
              fluid={"p_in": p_in, "p_out": p_out}, **sections)
    return mount_and_pressurise(s)


@pytest.fixture(scope="module")
def states(tmp_path_factory):
    cache = str(tmp_path_factory.mktemp("mesh"))
    return {k: pressurised(cache, *k) for k in [(P, P), (P, 0.0), (0.0, P)]}


def mirrored(model, u):
    """u of the mirrored seal: node j(i) takes (u_r, -u_z) of node i."""
    j = mirror_map(model.mesh.X, 0.0)
    ud = model.udofs
    out = np.empty_like(u)
    out[ud[j, 0]] = u[ud[:, 0]]
    out[ud[j, 1]] = -u[ud[:, 1]]
    return out


def test_equal_pressures_pressurise_symmetrically(states):
    st = states[(P, P)]
    model, u, load = st.model, st.u, st.load
    assert st.done[-1] == "pressurise" and len(load.loads) == 2
    scale = np.abs(u).max()
    # the fronts' settling and the solves are mirror-symmetric to round-off
    assert np.abs(mirrored(model, u) - u).max() < 1e-9 * scale
    radial, axial = model.pressure_resultant(load, st.t, u)
    assert abs(axial) < 1e-9 * abs(radial)
    # each fluid wets as much of the loop as the other, and both wet some of it
    a, b = (np.asarray(f.reach) for f in load.loads)
    # the displacements mirror to Newton's tolerance (1e-9 of their scale, above); the
    # reach, an interpolation of the wall's contact pressure along an edge, amplifies that
    # (7e-10 of it measured with the solid kernel of 2026-12-03, whose tangents differ in
    # the last bit and so Newton's path)
    assert sorted(a) == pytest.approx(sorted(b), rel=1e-8) and a.min() > 0.0
    # neither wets the rod contact: no edge is wetted by both (check_blow_by)
    assert not ((load.loads[0].wet > 0) & (load.loads[1].wet > 0)).any()


def test_back_pressure_alone_mirrors_the_sealed_pressure(states):
    a, b = states[(P, 0.0)], states[(0.0, P)]
    scale = np.abs(a.u).max()
    # a sign error in which fluid starts where, or in its exit edges, moves the seal by the
    # width of the contact; the two runs' front updates and solves mirror each other to
    # round-off
    assert np.abs(mirrored(a.model, a.u) - b.u).max() < 1e-9 * scale
    fa = a.model.rod.forces(a.t, a.u).sum()
    fb = b.model.rod.forces(b.t, b.u).sum()
    assert fb == pytest.approx(fa, rel=1e-9)
    # p_in's fluid is there at 0 MPa and loads nothing; the p_out fluid wets and loads
    assert np.abs(b.load.loads[0].forces(b.t, b.u)).max() == 0.0
    assert b.load.loads[1].wet.max() > 0.0


def test_a_stroke_with_equal_pressures_on_both_sides(tmp_path):
    """At rest (the stroke's start, v = 0) a film whose ends are both at p carries no flow,
    so its pressure is p all along the contact (Reynolds: q = -h^3/(12 eta) dp/dy = 0); then
    the rod ramps to 100 mm/s and the stroke runs with both fluids on the seal."""
    from conftest import stroke_of
    st = pressurised(str(tmp_path / "mesh"), P, P,
                     stroke={"velocity": "ramp-hold", "t_ramp": 0.01, "t_end": 0.03,
                             "dt": 2.5e-4, "output_times": [], "v_max": 100.0})
    stroke = stroke_of(st)
    U0 = stroke.start()
    p = U0[stroke.layout.film_dofs]
    assert np.abs(p - P).max() < 1e-9 * P
    s0 = stroke.scalars(0.0, U0)
    assert abs(s0["Q_in"]) < 1e-9 and abs(s0["Q_out"]) < 1e-9
    U = stroke.run(U0, 0.03, 2.5e-4, 1e-3)
    s1 = stroke.scalars(0.03, U)
    assert np.isfinite(U).all() and s1["load_fluid"] > 0.0


def test_the_hold_starts_with_the_loads_pressurisation_left(states):
    """No jump of the fluids' load where the viscoelastic hold takes over from step 2:
    p_in (ramped from there) and the held back pressure load the seal as at the end of the
    pressurisation."""
    from dataclasses import replace

    from sealts.problem.hold_problem import HoldProblem
    st = states[(P, P)]
    ve = replace(st.scene.viscoelastic, prony="custom", prony_g=(0.5,), prony_tau=(1.0,))
    hold = HoldProblem(st.model, st.u, st.load, P, 2 * P, 1e-3, ve, 10.0,
                       p_back=st.scene.fluid.p_out)
    F0 = st.load.forces(st.t, st.u)
    assert np.abs(hold.load.forces(0.0, st.u) - F0).max() <= 1e-12 * np.abs(F0).max()
    # and later the back pressure is still there: only p_in's share doubles
    back = hold.load.loads[1].forces(10.0, st.u)
    assert np.abs(back - st.load.loads[1].forces(st.t, st.u)).max() <= 1e-12 * np.abs(F0).max()


def test_two_fluid_load_jacobian(tmp_path):
    """The two fluids' load stiffness (their COO patterns concatenated) against central
    differences, with partly wetted edges of both (bound 1e-7, as for one fluid)."""
    from sealts.mesh.seal_mesh import ORing, build_mesh
    from sealts.problem import Problem
    from sealts.solid.fluid_loads import FluidLoads
    from sealts.solid.pressure import PressureLoad
    m = build_mesh(ORing(50.17, 5.33), 0.3, 0.6, cache_dir=tmp_path)
    n = 2 * m.X.shape[0]
    rng = np.random.default_rng(3)
    fluids = []
    for p, side in ((1.3, "pressure_side"), (0.7, "atmosphere_side")):
        f = PressureLoad(m.X, m.conn, lambda t, p=p: p, True, m.nodes(side)[0])
        f.s0 = rng.uniform(0, 0.5, f.m) * (rng.random(f.m) < 0.3)
        f.s1 = np.maximum(f.s0, rng.uniform(0.5, 1.0, f.m) * (rng.random(f.m) < 0.5))
        fluids.append(f)
    load = FluidLoads(fluids)
    u = np.random.default_rng(2).uniform(-0.05, 0.05, n)
    problem = Problem(n, [load])
    J = problem.jacobian_dense(0.0, u, u, 0.0)
    assert np.abs(J).max() > 0.0
    for j in range(0, n, 7):
        e = np.zeros(n)
        e[j] = 1e-7
        fd = (problem.residual(0.0, u + e, u) - problem.residual(0.0, u - e, u)) / 2e-7
        assert np.abs(J[:, j] - fd).max() <= 1e-7 * np.abs(J).max()
