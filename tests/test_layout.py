"""The DMPlex + Section layout of a seal's unknowns (sealts.mesh.layout)."""
import numpy as np
import pytest

from conftest import scene
from sealts.contact.asperity import ExponentialLaw
from sealts.contact.rod_side import RodSide
from sealts.contact.rigid import GrooveContact, RodContact, tributary_lengths
from sealts.mesh.layout import Layout, vertex_dofs
from sealts.problem import Problem
from sealts.problem.seal_model import model_from_scene
from sealts.solid.term import SolidTerm


@pytest.fixture(scope="module")
def mesh(tmp_path_factory):
    s = scene("oring_mount", mesh={"h_contact": 0.1, "h_bulk": 0.3,
                                   "cache": str(tmp_path_factory.mktemp("mesh"))})
    return model_from_scene(s).mesh


def test_dmplex_is_the_mesh_with_its_named_boundaries(mesh):
    """Same cells, vertices and coordinates; Euler's V - E + F = 1 for the cross-section (a
    disc); the union of the four boundary labels is exactly PETSc's own boundary marking."""
    lay = Layout(mesh)
    dm = lay.dm
    nv, nc = mesh.X.shape[0], mesh.conn.shape[0]
    e0, e1 = dm.getDepthStratum(1)
    assert nv - (e1 - e0) + nc == 1
    assert np.allclose(dm.getCoordinatesLocal().getArray().reshape(-1, 2), mesh.X)
    dm.markBoundaryFaces("boundary", 1)
    boundary = set(dm.getStratumIS("boundary", 1).getIndices())
    labelled = set()
    for g in mesh.edges:
        pts = dm.getStratumIS(g, 1).getIndices()
        labelled |= {int(p) for p in pts if e0 <= p < e1}
        assert np.array_equal(lay.label_nodes(g), np.unique(mesh.nodes(g)))
    assert labelled == {int(p) for p in boundary if e0 <= p < e1}


def test_section_fields_partition_the_unknowns(mesh):
    """Displacement alone: node i holds 2i, 2i + 1. With a film and 3 Prony components the
    sizes add up and the three fields' dofs partition 0..n-1."""
    nv, nc = mesh.X.shape[0], mesh.conn.shape[0]
    assert np.array_equal(Layout(mesh).udofs, vertex_dofs(nv))
    lay = Layout(mesh, film=True, prony=3)
    n_rod = len(mesh.chain("rod_side"))
    assert lay.n == 2 * nv + n_rod + 3 * nc
    assert lay.fields == ["displacement", "film_pressure", "prony"]
    every = np.concatenate([lay.field_dofs(f) for f in lay.fields])
    assert np.array_equal(np.sort(every), np.arange(lay.n))
    assert lay.section.getFieldComponents(2) == 3
    with pytest.raises(KeyError, match="no field 'prony'"):
        Layout(mesh).field_dofs("prony")


def test_solid_and_contact_terms_do_not_care_where_their_dofs_are(mesh):
    """The same seal terms on a layout with film and Prony fields give the same residual and
    Jacobian on the displacement dofs, and touch no other dof: a new field needs no change
    to them."""
    from sealts.solid.term import NeoHooke
    X, conn = mesh.X, mesh.conn
    mat = NeoHooke(1.064, 0.001)
    chain = mesh.chain("rod_side")
    trib = tributary_lengths(X, np.concatenate(list(mesh.edges.values())), X.shape[0])
    walls = (X[:, 1].min() + 0.01, X[:, 1].max() - 0.01)
    rg = X[:, 0].max() - 0.02

    def terms(udofs):
        return [SolidTerm(X, conn, mat, True, udofs=udofs),
                RodContact(RodSide(X, chain, lambda t: X[chain, 0].min() + 0.01,
                                   2 * np.pi * 25.0, udofs=udofs), ExponentialLaw(7e-4, 15.0)),
                GrooveContact(X, mesh.boundary_nodes(), trib, True, lambda t: rg,
                              lambda t: walls, udofs=udofs)]

    plain = Layout(mesh)
    rich = Layout(mesh, film=True, prony=2)
    u = np.random.default_rng(1).uniform(-0.005, 0.005, plain.n)
    u_rich = np.zeros(rich.n)
    u_rich[rich.udofs] = u[plain.udofs]
    a, b = Problem(plain.n, terms(plain.udofs)), Problem(rich.n, terms(rich.udofs))
    fa, fb = a.residual(0.0, u, 0 * u), b.residual(0.0, u_rich, 0 * u_rich)
    assert np.array_equal(fa[plain.udofs], fb[rich.udofs])
    others = np.setdiff1d(np.arange(rich.n), rich.udofs)
    assert np.all(fb[others] == 0.0) and np.isin(b._rows, rich.udofs).all()
    Ja = a.jacobian_dense(0.0, u, 0 * u, 0.0)
    Jb = b.jacobian_dense(0.0, u_rich, 0 * u_rich, 0.0)
    ia, ib = plain.udofs.ravel(), rich.udofs.ravel()
    assert np.array_equal(Ja[np.ix_(ia, ia)], Jb[np.ix_(ib, ib)])
    assert np.abs(fa).max() > 0 and np.abs(Ja).max() > 0  # the comparison saw real forces
