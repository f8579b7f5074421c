"""mesh.h_edge: the mesh refined at the pressurised contact's edges (sealts/mesh/contact_edges.py).

What is asserted:

* the points lie on the chain's reference polyline at the arc lengths asked for, a
  closed form on a straight chain (clipped at its ends);
* the mesh built with them has elements of about h at the points and the contact size
  far from them (the refinement is where it was asked for, and only there);
* an edge within half a span of one refined before gets no points, one further away does
  (the check after each refined pass);
* the whole loop on the coarse O-ring: steps 1-2 on the scene's own mesh find the
  contact's edges, and on the refined mesh the pressurised contact ends inside the
  refined spans, between chain nodes about h_edge apart; the summary says so; the state
  of the last pass is the run's (not computed again), and its file holds the points, so
  a run from the state cache builds the same mesh without steps 1-2;
* a failure says on which mesh: the refined one (and that the scene's own went through)
  or the scene's own (the same without mesh.h_edge).
"""
import numpy as np
import pytest

from conftest import scene
from sealts.mesh.contact_edges import points_along
from sealts.mesh.seal_mesh import ORing, _key, build_mesh

H_CONTACT, H_BULK = 0.1, 0.4


def test_points_lie_on_the_chain_at_the_arc_lengths_asked_for():
    X = np.column_stack([np.full(11, 25.0), np.linspace(0.0, 1.0, 11)])   # z every 0.1 mm
    chain = np.arange(11)
    p = points_along(X, chain, [5], span=0.2, spacing=0.01)
    assert np.allclose(p[:, 0], 25.0)
    assert p[:, 1] == pytest.approx(np.linspace(0.3, 0.7, 41))
    ends = points_along(X, chain, [0, 10], span=0.2, spacing=0.05)   # clipped to the chain
    assert ends[:, 1] == pytest.approx([0.0, 0.05, 0.1, 0.15, 0.2, 0.8, 0.85, 0.9, 0.95, 1.0])


def test_no_points_within_a_span_of_a_side_wall():
    """A contact from z = 0.2 to 0.9 mm on a straight chain, a side wall at z = 0.95: the
    span around the edge at 0.9 stops 0.08 mm short of the wall (z < 0.87), the one at 0.2
    is whole; with the wall at 2.0 both are."""
    from types import SimpleNamespace as NS
    from sealts.mesh.contact_edges import edge_refinement
    z = np.linspace(0.0, 1.0, 11)
    X = np.column_stack([np.full(11, 25.0), z])
    p = np.where((z > 0.15) & (z < 0.95), 1.0, 0.0)
    chain = np.arange(11)

    def model(wall):
        return NS(mesh=NS(X=X), contact_profile=lambda t, u: (z, 0.0 * z, p),
                  side=NS(chain=chain, y=lambda u: z),
                  groove=NS(z_walls=lambda t: (-1.0, wall)))

    (points, h), edges, new = edge_refinement(model(0.95), 0.0, None, 0.01, 0.08)
    assert edges == new == [[25.0, 0.2], [25.0, 0.9]]
    near = points[points[:, 1] > 0.5, 1]
    assert near.max() < 0.87 and near.min() == pytest.approx(0.82)
    low = points[points[:, 1] < 0.5, 1]
    assert (low.min(), low.max()) == pytest.approx((0.12, 0.28))
    assert np.diff(low).max() <= 0.005 + 1e-12                 # h / 2 apart
    (whole, _), _, _ = edge_refinement(model(2.0), 0.0, None, 0.01, 0.08)
    assert whole[:, 1].max() == pytest.approx(0.98)
    # an edge within span / 2 of one refined before is covered: no points for it; one
    # further away is refined again (the seal settled elsewhere on the refined mesh)
    (again, _), _, new = edge_refinement(model(2.0), 0.0, None, 0.01, 0.08,
                                         refined=[[25.0, 0.17], [25.0, 0.6]])
    assert new == [[25.0, 0.9]]
    assert (again[:, 1].min(), again[:, 1].max()) == pytest.approx((0.82, 0.98))
    covered = edge_refinement(model(2.0), 0.0, None, 0.01, 0.08,
                              refined=[[25.0, 0.23], [25.0, 0.87]])
    assert covered == (None, [[25.0, 0.2], [25.0, 0.9]], [])


def _chain_spacing(mesh):
    chain = mesh.chain("rod_side")
    P = mesh.X[chain]
    return P, np.hypot(*np.diff(P, axis=0).T)


def test_refinement_puts_elements_of_h_at_the_points_only(tmp_path):
    shape, h = ORing(50.17, 5.33), 0.01
    rc, R = 0.5 * (50.17 + 5.33), 0.5 * 5.33
    a = np.radians(np.linspace(199.0, 201.0, 200))       # 0.09 mm of the rod-side arc
    points = np.column_stack([rc + R * np.cos(a), R * np.sin(a)])
    plain = build_mesh(shape, H_CONTACT, H_BULK, cache_dir=tmp_path)
    fine = build_mesh(shape, H_CONTACT, H_BULK, cache_dir=tmp_path, refine=(points, h))
    P, d = _chain_spacing(fine)
    mid = 0.5 * (P[1:] + P[:-1])
    dist = np.min(np.hypot(mid[:, None, 0] - points[None, :, 0],
                           mid[:, None, 1] - points[None, :, 1]), axis=1)
    assert d[dist < 0.01].max() < 1.5 * h                  # h at the points
    assert d[dist > 1.0].min() > 0.5 * H_CONTACT           # the contact size far away
    assert fine.X.shape[0] > plain.X.shape[0]
    assert _key(shape, H_CONTACT, H_BULK, 0.5)[1] == _key(shape, H_CONTACT, H_BULK, 0.5,
                                                        refine=None)[1]
    assert _key(shape, H_CONTACT, H_BULK, 0.5, refine=(points, h))[1]["refine"]["h"] == h
    with pytest.raises(ValueError, match="mirror"):
        build_mesh(shape, H_CONTACT, H_BULK, cache_dir=tmp_path, mirror=True,
                   refine=(points, h))


def test_the_pressurised_contact_ends_inside_the_refined_spans(tmp_path):
    from sealts.mesh.contact_edges import edge_nodes
    from sealts.steps import prepare
    from sealts.steps.procedure import REFINE_PASSES
    h = 0.01
    s = scene("oring_stroke", mesh={"h_contact": H_CONTACT, "h_bulk": H_BULK, "h_edge": h,
                                    "cache": str(tmp_path)},
              output={"progress": False})
    st = prepare(s)
    record = st.parts["mesh_refinement"]
    assert record["h_edge"] == h and record["points"] > 0 and record["converged"]
    # the base pass found two edges; each refined pass refined the edges it found outside
    # the spans so far (this coarse mesh's 0.1 mm elements place an edge only to within a
    # few hundredths of a millimetre: the first refined mesh finds both 0.04 mm away), the
    # last found both inside
    refined = [e for p in record["passes"] for e in p["refined"]]
    assert len(record["passes"][0]["refined"]) == 2 and record["passes"][-1]["refined"] == []
    assert len(record["passes"]) <= REFINE_PASSES + 1
    assert st.model.mesh.X.shape[0] > record["base_nodes"]
    assert st.prepared and st.done == ["mount", "pressurise", "transfer"]
    chain = st.model.side.chain
    P, d = _chain_spacing(st.model.mesh)
    for i in edge_nodes(st.model, st.t, st.u):
        # the first and last node the rod presses, on the refined mesh: between
        # neighbours about h_edge apart, within the span of the base mesh's edge
        assert max(d[max(i - 1, 0)], d[min(i, d.size - 1)]) < 1.5 * h
        near = min(np.hypot(*(st.model.mesh.X[chain[i]] - np.array(e))) for e in refined)
        assert near <= 0.5 * s.mesh.edge_span
    # its state file holds the points: a run from it (or from the state cache) builds the
    # same mesh and reads steps 1-2 back instead of computing them
    from sealts.steps import new_state, run_steps, steps_1_2
    st.writer.root = False
    path = tmp_path / "state.h5"
    from sealts.io.writer import write_h5
    write_h5(path, *st.file_data())
    s2 = scene("oring_stroke", mesh={"h_contact": H_CONTACT, "h_bulk": H_BULK, "h_edge": h,
                                     "cache": str(tmp_path)},
               start={"state": str(path)}, output={"progress": False})
    again = new_state(s2)
    assert not again.prepared
    assert [type(x).__name__ for x in steps_1_2(s2, prepared=again.prepared)] == ["Restart"]
    run_steps(steps_1_2(s2), again)
    assert np.array_equal(again.model.mesh.X, st.model.mesh.X)
    assert np.array_equal(again.u, st.u)


@pytest.mark.parametrize("where", ["refined", "own"])
def test_a_failure_says_on_which_mesh(where, tmp_path, monkeypatch):
    """Steps 1-2 that fail say on which mesh, in one line: carried to a refined mesh and
    failing there (at 20-30 MPa micrometre elements at the pressure-side edge can be
    crushed), the scene's own mesh went through, so the scene runs without mesh.h_edge;
    failing before any refinement (the fold at 40 MPa), on the scene's own mesh: the same
    without mesh.h_edge."""
    from sealts.core import SolveError
    from sealts.steps import prepare
    from sealts.steps.pressurise import Pressurise
    from sealts.steps.transfer import Transfer

    def fails(self, state):
        raise SolveError("3 element(s) of the seal invert")

    monkeypatch.setattr(Transfer if where == "refined" else Pressurise, "run", fails)
    s = scene("oring_stroke", mesh={"h_contact": H_CONTACT, "h_bulk": H_BULK, "h_edge": 0.01,
                                    "cache": str(tmp_path)},
              output={"progress": False})
    with pytest.raises(SolveError) as e:
        prepare(s)
    msg = str(e.value)
    assert "\n" not in msg
    if where == "refined":
        assert msg.startswith("3 element(s) of the seal invert (on the mesh refined")
        assert "mesh.h_edge = 0.01 mm" in msg and "scene's own mesh" in msg
    else:
        assert msg.startswith("3 element(s) of the seal invert (on the scene's own mesh")
        assert "refined" not in msg
