"""Steps 1-2 carried to another mesh (sealts/steps/transfer.py, sealts/mesh/transfer.py,
sealts/solid/dilatation.py): how ``mesh.h_edge`` starts on its refined mesh.

What is asserted:

* the interpolation reproduces any linear field exactly (closed form) on a distorted
  quadrilateral mesh, at interior points and at points just outside its boundary (the
  polygon of a curved boundary differs from mesh to mesh); boundary nodes go onto the old
  deformed boundary (affine maps exactly; a point on an arc onto the old chord);
* the dilatation is the element kernel's, its gradient the central difference quotient;
  the correction gives every element its target dilatation (quadratic Gauss-Newton), keeps
  the fixed dofs, and leaves a field that meets its targets alone;
* a front's reference position is where its wetted part ends, and carried to the same
  loop it gives back its reach;
* carried to the very mesh it came from, a pressurised state is itself (one fluid, or a
  back pressure too: four fronts): displacements to round-off, the same fronts, no move;
* carried to the mesh refined at the contact's edges (coarse O-ring), the mounted seal is
  the refined mesh's own mount (its one equilibrium: to 1e-6 of the rod force), and the
  pressurised one settles its front there with the rod force of the scene's own mesh.
"""
from dataclasses import replace

import numpy as np
import pytest

from conftest import scene
from sealts.mesh.transfer import interpolate, locate

H_CONTACT, H_BULK = 0.1, 0.4


def _distorted_mesh(nx=6, ny=4):
    x, y = np.meshgrid(np.linspace(0.0, 3.0, nx + 1), np.linspace(0.0, 2.0, ny + 1))
    X = np.column_stack([x.ravel(), y.ravel()])
    inner = (X[:, 0] > 0) & (X[:, 0] < 3) & (X[:, 1] > 0) & (X[:, 1] < 2)
    X[inner] += 0.1 * np.column_stack([np.sin(3 * X[inner, 1]), np.cos(2 * X[inner, 0])])
    k = np.arange((nx + 1) * (ny + 1)).reshape(ny + 1, nx + 1)
    conn = np.column_stack([k[:-1, :-1].ravel(), k[:-1, 1:].ravel(), k[1:, 1:].ravel(),
                            k[1:, :-1].ravel()])
    return X, conn


def test_interpolation_reproduces_a_linear_field_inside_and_just_outside():
    X, conn = _distorted_mesh()
    field = lambda P: np.column_stack([1.0 + 2.0 * P[:, 0] - P[:, 1], 3.0 - P[:, 0]])
    rng = np.random.default_rng(0)
    inside = rng.uniform([0.05, 0.05], [2.95, 1.95], (400, 2))
    outside = np.array([[-0.01, 0.7], [3.01, 1.3], [1.1, -0.005], [2.2, 2.01]])
    for P in (inside, outside, X):
        assert np.abs(interpolate(X, conn, field(X), P) - field(P)).max() < 1e-12
    elem, xi, eta = locate(X, conn, outside)
    assert np.all(np.maximum(np.abs(xi), np.abs(eta)) > 1.0)       # extrapolated
    assert np.all(np.maximum(np.abs(xi), np.abs(eta)) < 1.1)       # from the nearest


def test_boundary_points_go_onto_the_old_deformed_boundary():
    """Under an affine map (straight edges stay straight) a point of the old boundary goes
    where the map takes it; a point on an arc between two old nodes goes onto their chord
    deformed, not the sagitta beyond it (as the element's extrapolation would)."""
    from sealts.mesh.transfer import onto_boundary
    X = np.array([[0.0, 0.0], [0.5, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    edges = np.array([[0, 1], [1, 2], [2, 3], [3, 4], [4, 0]])
    F, c = np.array([[1.1, 0.2], [-0.1, 0.9]]), np.array([0.3, -0.2])
    P = np.array([[0.25, 0.0], [0.8, 0.0], [1.0, 0.4], [0.3, 1.0], [0.0, 0.65]])
    assert np.abs(onto_boundary(X, edges, X @ F.T + c, P) - (P @ F.T + c)).max() < 1e-14
    a = np.radians(np.arange(0.0, 360.0, 30.0))                # a 12-gon on the unit circle
    X = np.column_stack([np.cos(a), np.sin(a)])
    edges = np.column_stack([np.arange(12), (np.arange(12) + 1) % 12])
    b = np.radians(15.0)                                       # mid-arc, the sagitta off
    got = onto_boundary(X, edges, X, [[np.cos(b), np.sin(b)]])
    assert np.abs(got - 0.5 * (X[0] + X[1])).max() < 1e-14


@pytest.fixture(scope="module")
def pressurised(tmp_path_factory):
    """The coarse O-ring pressurised to 1 MPa on its own mesh."""
    from sealts.steps import prepare
    cache = str(tmp_path_factory.mktemp("cache"))
    s = scene("oring_stroke", mesh={"h_contact": H_CONTACT, "h_bulk": H_BULK, "cache": cache},
              output={"progress": False})
    return prepare(s)


def test_the_dilatation_is_the_element_kernel_s_and_its_gradient_the_difference_quotient(
        pressurised):
    """theta_e as the element kernel computes it for its pressure (sealts.solid.q1p0), and
    d theta / d u against central differences."""
    from sealts.solid.dilatation import dilatation
    m = pressurised.model
    u = np.array(pressurised.u)
    theta, grad = dilatation(m.solid, u)
    assert np.abs(theta - m.solid.state(u)[3]).max() < 1e-14
    rng = np.random.default_rng(2)
    eps = 1e-7
    for e in rng.choice(theta.size, 5, replace=False):
        for j in range(8):
            du = np.zeros_like(u)
            du[m.solid.dofs[e, j]] = eps
            fd = (dilatation(m.solid, u + du)[0][e] - dilatation(m.solid, u - du)[0][e]) / (
                2 * eps)
            assert fd == pytest.approx(grad[e, j], rel=1e-6, abs=1e-6)


def test_the_dilatation_correction_meets_its_targets_and_keeps_the_fixed_dofs(pressurised):
    from sealts.solid.dilatation import dilatation, match_dilatation
    m = pressurised.model
    u0 = np.array(pressurised.u)
    theta0, _ = dilatation(m.solid, u0)
    rng = np.random.default_rng(1)
    target = theta0 * (1.0 + 2e-3 * rng.standard_normal(theta0.size))
    fixed = m.udofs[m.side.chain].ravel()
    u, misfit = match_dilatation(m.solid, u0, target, fixed, m.n)
    theta, _ = dilatation(m.solid, u)
    assert np.abs(theta - target).max() < 1e-9 and misfit < 1e-4
    assert np.array_equal(u[fixed], u0[fixed])
    assert np.abs(u - u0).max() > 1e-4                  # it did move the rest
    same, misfit = match_dilatation(m.solid, u0, theta0, fixed, m.n)
    assert np.array_equal(same, u0) and misfit < 1e-12


def test_a_front_carried_to_its_own_loop_keeps_its_reach(pressurised):
    load = pressurised.load.rebuilt()
    load.set_reach([3.25, 7.5])           # each front inside an edge: where wet meets dry
    partial = np.flatnonzero((load.wet > 0.0) & (load.wet < 1.0))
    a, b = load.edges[partial, 0], load.edges[partial, 1]
    s = np.where(load.s0[partial] == 0.0, load.s1[partial], load.s0[partial])
    ends = load.X[a] + s[:, None] * (load.X[b] - load.X[a])
    got = load.front_points()
    assert sorted(np.round(got, 12).tolist()) == sorted(np.round(ends, 12).tolist())
    for reach in ([3.25, 7.5], [0.0, 12.0], list(pressurised.load.reach)):
        load.set_reach(reach)
        assert load.reach_at(load.front_points()) == pytest.approx(reach, abs=1e-9)


@pytest.fixture(scope="module")
def back_pressurised(tmp_path_factory):
    """The coarse O-ring with 1 MPa on both sides: two fluids, four fronts."""
    from sealts.steps import prepare
    cache = str(tmp_path_factory.mktemp("cache"))
    s = scene("oring_stroke", mesh={"h_contact": H_CONTACT, "h_bulk": H_BULK, "cache": cache},
              fluid={"p_in": 1.0, "p_out": 1.0}, output={"progress": False})
    return prepare(s)


@pytest.mark.parametrize("fixture", ["pressurised", "back_pressurised"])
def test_a_state_carried_to_its_own_mesh_is_itself(fixture, request):
    from sealts.steps.state import RunState
    from sealts.steps.transfer import Transfer
    src = request.getfixturevalue(fixture)
    st = Transfer(src)
    same = RunState(src.scene, src.model, src.writer, src.say, src.comm)
    st.run(same)
    assert np.abs(same.u - src.u).max() < 1e-9
    assert same.load.reach == pytest.approx(list(src.load.reach), abs=1e-6)
    assert same.results["front_updates"] == 0
    assert same.results["contact_force_total"] == pytest.approx(
        src.results["contact_force_total"], rel=1e-9)


def test_a_mounted_seal_carried_to_the_refined_mesh_is_that_mesh_s_own_mount(tmp_path):
    """The mount (no fluid, no front) has one equilibrium on the refined mesh whatever the
    path: carried from the scene's own mesh it is the one steps 1-2 compute there."""
    from sealts.io.writer import NullWriter
    from sealts.problem.seal_model import model_from_scene
    from sealts.steps import prepare, run_steps, steps_1_2
    from sealts.steps.state import RunState
    s = scene("oring_stroke", mesh={"h_contact": H_CONTACT, "h_bulk": H_BULK, "h_edge": 0.01,
                                    "cache": str(tmp_path)},
              fluid={"p_in": 0.0}, output={"progress": False})
    carried = prepare(s)
    assert carried.done == ["mount", "transfer"] and carried.load is None
    computed = run_steps(steps_1_2(s), RunState(s, model_from_scene(s, None, carried.refine),
                                                NullWriter(), carried.say))
    assert np.abs(carried.u - computed.u).max() < 1e-5          # mm (measured 7e-7)
    assert carried.results["contact_force_total"] == pytest.approx(
        computed.results["contact_force_total"], rel=1e-6)


def test_a_pressurised_seal_carried_to_the_refined_mesh_settles_there(pressurised, tmp_path):
    """Pressurised, the carried state's front settles on the refined mesh, and its rod force
    is the scene's own mesh's to the difference of the two meshes (0.5 % on this coarse
    one). (Steps 1-2 repeated on the refined mesh are no truth here: their front can end in
    another roll state, or unsettled between two fronts that flip together.)"""
    from sealts.io.writer import ProfileRecorder
    from sealts.steps import prepare
    s = replace(pressurised.scene, mesh=replace(pressurised.scene.mesh, h_edge=0.01,
                                                cache=str(tmp_path)))
    written = ProfileRecorder()
    carried = prepare(s, writer=written)
    assert carried.done == ["mount", "pressurise", "transfer"]
    # the scene's own mesh's profiles (mounted, pressurised) in a file of their own, the
    # last refined mesh's pressurised one in profiles.csv (this coarse mesh is refined
    # twice): one block per t in each
    assert len(carried.parts["mesh_refinement"]["passes"]) == 3
    assert [(t, name) for t, _, name, _ in written.calls] == [
        (2.0, "profiles_scene_mesh.csv"), (4.0, "profiles_scene_mesh.csv"),
        (4.0, "profiles.csv")]
    assert len(written.calls[-1][1]["y"]) == len(carried.model.side.chain)
    assert carried.model.mesh.X.shape[0] > pressurised.model.mesh.X.shape[0]
    assert carried.results["front_change_edges"] < 1e-4
    assert carried.results["contact_force_total"] == pytest.approx(
        pressurised.results["contact_force_total"], rel=1e-2)


def _two_patches():
    """Two planar 2 x 2 patches of unit squares, apart, each with its middle node free."""
    from sealts.solid.term import NeoHooke, SolidTerm
    x, y = np.meshgrid(np.linspace(0.0, 2.0, 3), np.linspace(0.0, 2.0, 3))
    P = np.column_stack([x.ravel(), y.ravel()])
    c = np.array([[0, 1, 4, 3], [1, 2, 5, 4], [3, 4, 7, 6], [4, 5, 8, 7]])
    solid = SolidTerm(np.vstack([P, P + [3.0, 0.0]]), np.vstack([c, c + 9]),
                      NeoHooke(0.5, 0.01), False)
    fixed = [d for k in range(18) if k not in (4, 13) for d in (2 * k, 2 * k + 1)]
    return solid, fixed


def test_the_dilatation_correction_turns_no_element_over():
    """Asked to grow one element of the first patch to 2.5 times its area with its
    neighbours held at theirs, the least-norm Gauss-Newton step carries the free node past
    the opposite element's corner (J < 0 there: the carried state the paper's O-ring at
    40 MPa met in the corner of rod and wall); the correction stops that node short, every
    Gauss point keeping at least half its J, while the second patch's node takes its whole
    steps to the targets of a known displacement, exactly (with one step length for all
    nodes it got 40 % of the way)."""
    from sealts.solid.dilatation import dilatation, gauss_J, match_dilatation
    solid, fixed = _two_patches()
    known = np.zeros(36)
    known[26:28] = [0.12, -0.07]
    target = dilatation(solid, known)[0]
    target[:4] = [2.5, 1.0, 1.0, 1.0]
    u, misfit = match_dilatation(solid, np.zeros(36), target, fixed, 36)
    assert gauss_J(solid, u).min() >= 0.5
    assert misfit > 0.5 and np.abs(u[8:10]).min() > 0.1      # it moved, as far as it could
    assert np.abs(u[26:28] - known[26:28]).max() < 1e-9


def test_the_dilatation_correction_moves_past_an_element_turned_over_before_it():
    """A carried state with an element already turned over (J < 0 at a Gauss point of the
    first patch): that element may not get worse, and the second patch still meets its
    targets (a bound of half the starting J would have stopped every step)."""
    from sealts.solid.dilatation import dilatation, gauss_J, match_dilatation
    solid, fixed = _two_patches()
    u0 = np.zeros(36)
    u0[8:10] = [0.97, 0.97]                 # the first patch's node nearly on a corner
    J0 = gauss_J(solid, u0)
    assert J0.min() < 0.0
    known = u0.copy()
    known[26:28] = [0.12, -0.07]
    target = dilatation(solid, known)[0]
    u, _ = match_dilatation(solid, u0, target, fixed, 36)
    assert np.abs(u[26:28] - known[26:28]).max() < 1e-9
    assert (gauss_J(solid, u)[J0 <= 0.0] >= J0[J0 <= 0.0]).all()


def test_a_fold_the_refined_mesh_cannot_carry_stops_the_run_and_says_where(tmp_path):
    """The shipped scene at 40 MPa with no extrusion gap: on its own 0.025 / 0.2 mm mesh the
    surface squeezed along the atmosphere-side wall folds onto itself (its self-contact
    holds), about 0.4 mm above the rod; carried to the mesh refined at the contact's edges,
    that state is kilonewtons out of balance at single nodes of the fold and Newton's method
    finds no equilibrium near it (benchmarks/stress.md, twenty-sixth session). The run
    stops in steps 1-2 with one line naming the fold and its place, exit 3."""
    import re
    import subprocess
    import sys

    from conftest import ROOT, config_text
    path = tmp_path / "p40.toml"
    path.write_text(config_text("oring_stroke", fluid={"p_in": 40.0},
                                output={"plot": False, "progress": False}))
    r = subprocess.run([sys.executable, "-m", "sealts", "run", str(path), "-o",
                        str(tmp_path / "out")], capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 3, r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1, r.stderr
    line = lines[0]
    assert line.startswith("physical stop (crease): no equilibrium on the refined mesh near "
                           "the state carried to it"), line
    assert "surface is folded onto itself there" in line and "the rubber creases" in line
    wall = re.search(r"([-\d.e]+) mm from the atmosphere-side wall and ([-\d.e]+) mm above", line)
    assert wall, line
    assert abs(float(wall.group(1))) < 0.05 and 0.2 < float(wall.group(2)) < 0.7
    from sealts.io.results import Results
    summary = Results(tmp_path / "out").summary
    assert summary["status"] == "stopped" and summary["cause"] == "crease"


def test_a_guard_s_physical_stop_in_the_transfer_keeps_its_cause(pressurised, tmp_path,
                                                                 monkeypatch):
    """Where Newton's method from the carried state fails and the stabilised driver's guards
    stop it for a physical reason (here made to: extrusion), the run stops with that cause,
    the refined mesh named, not as a crease or a plain failure."""
    import sealts.steps.transfer as transfer
    from sealts.core import PhysicalStop, SolveError
    from sealts.steps import prepare

    def diverged(*args, **kwargs):
        raise SolveError("steady Newton solve diverged")

    def extruded(*args, **kwargs):
        raise PhysicalStop("extrusion", "extrusion: at t = 4 node 7 has flowed 0.3 mm")

    monkeypatch.setattr(transfer, "static", diverged)
    monkeypatch.setattr(transfer, "quasi_static", extruded)
    s = replace(pressurised.scene, mesh=replace(pressurised.scene.mesh, h_edge=0.01,
                                                cache=str(tmp_path)))
    with pytest.raises(PhysicalStop) as e:
        prepare(s)
    assert e.value.cause == "extrusion"
    assert str(e.value).startswith("extrusion: at t = 4 node 7 has flowed 0.3 mm (on the "
                                   "refined mesh, from the state carried to it)")
