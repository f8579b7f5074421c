"""Physical stops: the rod-side guard (sealts.contact.rod_side_guard) for a node off the rod
side inside the rod and for the rod side folding over (along the rod, where the film cannot
follow; up a groove wall, the 40 MPa O-ring's crease in the corner between rod and wall
when the surface has no self-contact, benchmarks/stress.md); blow-by
(sealts.solid.pressure)."""
import numpy as np
import pytest

from sealts.contact.rod_side import RodSide
from sealts.contact.rod_side_guard import RodSideGuard
from sealts.core import PhysicalStop, SolveError


def chain(n=6, length=0.05):
    """n nodes along z at r = 1.0 (the rod at r = 0.999), one node off the chain at r = 1.5."""
    X = np.array([[1.0, k * length] for k in range(n)] + [[1.5, 0.0]])
    side = RodSide(X, np.arange(n), 0.999, 1.0, off=[n])
    return side, np.zeros(2 * (n + 1))


def test_a_fold_of_the_rod_side_stops_the_run_and_says_where():
    side, u = chain()
    guard = RodSideGuard(side, depth=7e-4)
    guard.accepted(0.0, u)                              # the reference: nothing to say
    u[side.uz[3]] = -0.05 - 0.2 * 0.05                  # node 3 pushed back past node 2
    with pytest.raises(SolveError) as e:
        guard.accepted(1.5, u)
    assert "at t = 1.5 the rod side folds over between nodes 2 and 3" in str(e.value)
    assert "the film (a function of the axial position) cannot follow" in str(e.value)
    assert isinstance(e.value, PhysicalStop) and e.value.cause == "fold"   # a result
    with pytest.raises(SolveError) as e:                # with the walls: which one, how far
        RodSideGuard(side, depth=7e-4, walls=lambda t: (-1.0, 0.3)).accepted(1.5, u)
    assert "um from the rod, 0.2 mm from the groove wall at y = 0.3 mm)" in str(e.value)


def test_a_fold_on_the_rod_names_its_cause_where_the_stroke_knows_it():
    """A hyperelastic stroke with the rod's friction gives its rod-side guard the hint that
    names the buckling (the paper's O-ring at 35-40 MPa, README "Operating limits") and what
    holds the surface; a viscoelastic one or one without the rod's friction does not."""
    from conftest import mount_and_pressurise, scene, stroke_of
    from sealts.problem.stroke_problem import FOLD_HINT

    coarse = dict(mesh={"h_contact": 0.1, "h_bulk": 0.4})
    state = mount_and_pressurise(scene("oring_stroke", **coarse))

    def hint(**sections):
        s = scene("oring_stroke", **coarse, **sections)
        (guard,) = [g for g in stroke_of(state, s).guards if isinstance(g, RodSideGuard)]
        return guard.fold_hint

    assert hint() == FOLD_HINT and "[viscoelastic] prony" in FOLD_HINT
    assert hint(viscoelastic={"prony": "table2"}) == ""
    assert hint(asperity={"mu_s": 0.0}) == ""
    side, u = chain()
    u[side.uz[3]] = -0.05 - 0.2 * 0.05
    with pytest.raises(SolveError, match="cannot follow it; where the rod's friction .* "
                                         "buckles the seal's surface"):
        RodSideGuard(side, depth=7e-4, fold_hint=FOLD_HINT).accepted(0.0, u)


def test_a_crease_up_the_wall_stops_without_self_contact_and_not_with_it():
    """The chain runs up a wall and turns back by 6 um radially 50-100 um above the rod: a
    crease. Without the surface's self-contact its faces would pass through each other:
    a stop naming seal.self_contact; with it (creases=True) the crease is held, no stop;
    the same turn-back at the rod stops either way (the film)."""
    side, u = chain()
    for k, dr in enumerate((0.05, 0.10, 0.094), start=3):
        u[side.ur[k]] = dr                              # up the wall, radially ...
        u[side.uz[k]] = 0.15 - side.Z[k]                # ... its nodes all at z = 0.15
    u[side.uz[5]] -= 0.006                              # node 5 6 um back along z ...
    with pytest.raises(SolveError, match='seal.self_contact = "on" closes the crease') as e:
        RodSideGuard(side, depth=7e-4).accepted(0.0, u)
    assert not isinstance(e.value, PhysicalStop)      # the model's setting, not physics
    RodSideGuard(side, depth=7e-4, creases=True).accepted(0.0, u)
    u[side.ur[4]] = u[side.ur[5]] = 0.0                 # ... the same turn-back on the rod
    with pytest.raises(SolveError, match="cannot follow"):
        RodSideGuard(side, depth=7e-4, creases=True).accepted(0.0, u)


def test_nodes_pressed_flat_against_a_wall_are_not_a_fold():
    """Nodes squeezed to one axial position (against a groove wall), round-off apart, and an
    element shortened to a twentieth of its length: no stop."""
    side, u = chain()
    u[side.uz[4]] = -0.05 + 1e-9                       # node 4 onto node 3's position ...
    u[side.uz[5]] = -2 * 0.05 - 1e-6                   # ... and node 5 a round-off behind
    RodSideGuard(side, depth=7e-4).accepted(0.0, u)
    u[side.uz[2]] = 0.95 * 0.05                        # element 1-2 at a twentieth
    RodSideGuard(side, depth=7e-4).accepted(0.0, u)


def test_nodes_pressed_into_a_wall_out_of_order_are_not_a_fold():
    """The rod side runs up a groove wall (its last three nodes along r at the wall's z),
    pressed into it to depths that differ by 6 um, more than a tenth of the element: the
    element runs along the wall, not backwards along the rod, so no stop; the same 6 um
    reversal along the rod is one."""
    side, u = chain()
    z_wall = 0.2
    for k, (dr, depth) in enumerate(((0.05, 2e-3), (0.10, 8e-3), (0.15, 2e-3)), start=3):
        u[side.ur[k]] = dr                              # up the wall, radially ...
        u[side.uz[k]] = z_wall + depth - side.Z[k]      # ... into it by 2, 6, 2 um
    u[side.uz[3]] -= 0.05                               # node 3 at the corner with node 2
    u[side.ur[3]] = 0.0
    guard = RodSideGuard(side, depth=7e-4)
    guard.accepted(0.0, u)                              # nodes 4 > 5 in z by 6 um: no stop
    u[side.ur[5]] = u[side.ur[4]]                       # node 5 beside node 4 on the rod ...
    with pytest.raises(SolveError, match="folds over between nodes 4 and 5"):
        guard.accepted(0.0, u)                          # ... 6 um behind it: a fold


def test_a_crumpled_element_pressed_into_a_wall_is_no_fold():
    """Up the wall the surface crumpled: an element 6 um long radially, its nodes 1 and 8 um
    into the wall (z = 0.2), so it points backwards at 50 degrees: a fold by its direction,
    but with the guard knowing the walls, both nodes pressed into the same one, none."""
    side, u = chain()
    for k, (dr, depth) in enumerate(((0.05, 1e-3), (0.056, 8e-3), (0.10, 1e-3)), start=3):
        u[side.ur[k]] = dr
        u[side.uz[k]] = 0.2 + depth - side.Z[k]
    u[side.uz[3]] -= 0.05                               # node 3 back on the rod
    u[side.ur[3]] = 0.0
    u[side.ur[5]] = u[side.ur[4]] + 0.006               # element 4-5: 6 um up, 7 um back
    with pytest.raises(SolveError, match="folds over between nodes 4 and 5"):
        RodSideGuard(side, depth=7e-4).accepted(0.0, u)
    RodSideGuard(side, depth=7e-4, walls=lambda t: (-1.0, 0.2)).accepted(0.0, u)


def test_the_extrusion_guard_sees_a_tongue_whatever_its_direction():
    """A tongue's return edge, turned back by 6 um but still steep (along r), is no fold for
    the rod-side guard and one for the extrusion guard (fold with back=None), which looks
    past a wall's plane, where no wall holds the rubber (6.5 MPa into a 0.1 mm gap on the
    0.05 mm mesh, benchmarks/stress.md)."""
    from sealts.contact.rod_side_guard import fold
    side, u = chain()
    u[side.ur[4]] = 0.02                                # node 4 lifted 20 um off the rod ...
    u[side.uz[4]] = -0.05 - 6e-3                        # ... and 6 um behind node 3
    assert fold(side, u) == -1
    assert fold(side, u, back=None) == 3


def test_a_node_off_the_rod_side_inside_the_rod_stops_the_run():
    side, u = chain()
    u[2 * 6] = -0.501 - 1e-3                           # the off node to r = 0.999 - 1e-3
    with pytest.raises(SolveError) as e:
        RodSideGuard(side, depth=7e-4).accepted(0.25, u)
    assert "node 6 off the rod side is 1 um inside the rod" in str(e.value)


def test_blow_by_is_a_stop_named_by_the_front(tmp_path):
    """The pressure-penetration front that reaches the atmosphere side has passed the seal:
    with no contact pressure anywhere, 1 MPa wets the whole boundary loop of the coarse
    O-ring, and the front's post-step hook stops the run with "blow-by" and the pressure."""
    from conftest import coarse_stroke
    from sealts.solid.pressure import AdvancingFront
    from sealts.steps import new_state
    model = new_state(coarse_stroke(tmp_path)).model
    load = model.pressure_load(lambda t: 1.0, 0.1)
    assert load.exit.sum() > 0 and not load.exit[load.start]
    none = np.zeros(model.mesh.X.shape[0])
    hook = AdvancingFront(load, lambda t, u: none)
    with pytest.raises(SolveError) as e:
        hook.accepted(2.5, np.zeros(model.n))
    assert str(e.value).startswith("blow-by: the pressure-penetration front reached the "
                                   "atmosphere side")
    assert "p = 1 MPa, t = 2.5" in str(e.value)
    # the front stopped by the contact (every node pressed harder than p + p_crit) is no
    # blow-by
    load = model.pressure_load(lambda t: 1.0, 0.1)
    AdvancingFront(load, lambda t, u: none + 5.0).accepted(2.5, np.zeros(model.n))


def test_a_seal_clear_of_the_rod_blows_by(tmp_path):
    """A scene that cannot seal: the O-ring held by a wider groove (60.5 mm) clears a 49 mm
    rod, so nothing presses it against the rod. Pressurisation stops at once with the
    physical cause (exit 3, one line), and summary.json says where."""
    import subprocess
    import sys

    from conftest import ROOT, config_text
    from sealts.io.results import Results
    scene = tmp_path / "clear.toml"
    scene.write_text(config_text(
        "oring_stroke", mesh={"h_contact": 0.1, "h_bulk": 0.4, "cache": str(tmp_path / "m")},
        rod={"radius": 24.5}, groove={"diameter": 60.5},
        output={"plot": False, "progress": False}))
    r = subprocess.run([sys.executable, "-m", "sealts", "run", str(scene), "-o",
                        str(tmp_path / "out")], capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 3, r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("physical stop (blow-by): blow-by: the "
                                                   "pressure-penetration front reached the "
                                                   "atmosphere")
    summary = Results(tmp_path / "out").summary
    assert summary["status"] == "stopped" and summary["cause"] == "blow-by"
    assert summary["error"].startswith("pressurise: PhysicalStop: blow-by")
    assert summary["results"]["contact_force_total"] == 0.0      # the mount never touched


@pytest.mark.parametrize("corner_radius", [0.0, 0.1])
def test_a_sharp_cornered_ring_is_told_to_round_its_corners(corner_radius):
    """The rectangular ring's side-face node next to the rod side set on the rod (with sharp
    corners, beyond the rod side's FLANK up the face; the stress matrix's sharp ring
    stopped so at t = 6.6 s before the rod side ran up the flanks): the stop says the
    corners are sharp and which key rounds them; a ring with rounded corners is not told
    so."""
    from conftest import ROOT, scene
    from sealts.problem.seal_model import model_from_scene
    s = scene("rect_ring_mount", seal={"corner_radius": corner_radius},
              mesh={"h_contact": 0.1, "h_bulk": 0.4, "cache": str(ROOT / "meshes")})
    model = model_from_scene(s)
    side = model.side
    k = int(np.argmin(model.mesh.X[side.off, 0]))          # the off node nearest the rod
    u = np.zeros(model.n)
    r = model.mesh.X[side.off[k], 0]
    u[model.udofs[side.off[k], 0]] = model.r_rod_final - 2e-3 - r     # 2 um into the rod
    guard = model.rod_side_guard()
    with pytest.raises(SolveError) as e:
        guard.accepted(2.0, u)                   # pseudo-time 2: rod and groove final
    assert f"node {side.off[k]} off the rod side is 2 um inside the rod" in str(e.value)
    assert ("seal.corner_radius = 0.1 mm" in str(e.value)) == (corner_radius == 0.0)


def test_a_physical_stop_keeps_its_cause_through_pickling_and_rewording():
    """Rank 0's verdict on steps 1-2 is broadcast to the other ranks (pickled), and a caller
    that adds where it happened rewords it: either way it stays a physical stop with its
    cause, and a plain solve error stays plain."""
    import pickle

    from sealts.core import reworded
    e = pickle.loads(pickle.dumps(PhysicalStop("extrusion", "extrusion: at t = 2")))
    assert isinstance(e, PhysicalStop) and e.cause == "extrusion"
    assert str(e) == "extrusion: at t = 2"
    again = reworded(e, f"{e} (on the refined mesh)")
    assert isinstance(again, PhysicalStop) and again.cause == "extrusion"
    assert str(again) == "extrusion: at t = 2 (on the refined mesh)"
    plain = reworded(SolveError("diverged"), "diverged (there)")
    assert type(plain) is SolveError and str(plain) == "diverged (there)"
