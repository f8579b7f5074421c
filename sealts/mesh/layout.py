"""Where each unknown of a seal scene lives: a DMPlex of the seal mesh and a PETSc.Section.

The seal mesh (:class:`sealts.mesh.seal_mesh.SealMesh`) becomes an interpolated DMPlex
(cells, edges, vertices) with one label per named boundary (``rod_side``, ``pressure_side``,
``groove``, ``atmosphere_side``), marking its edges and their vertices with value 1. The
Section on that DMPlex holds the fields of the scene:

==================  =========================  ==========================================
field               points                     components
==================  =========================  ==========================================
``displacement``    every vertex               2: u_r, u_z (mm)
``film_pressure``   ``rod_side`` vertices      1: p (MPa), when the scene has a film
``rod_slip``        ``rod_side`` vertices      1: z (mm), the rod friction's elastic slip
``groove_anchor``   boundary vertices          2: a_r, a_z (mm), the groove walls' friction
                                               anchors
``prony``           every cell                 ``prony``: internal variables (issue 4)
==================  =========================  ==========================================

A field is present only when the scene needs it, so nothing is carried that the physics does
not use. Dofs are numbered point by point (all fields of a point together), vertices first
in mesh node order, then cells: with displacement alone, node i holds unknowns 2i and 2i + 1.
Terms take their dof arrays from here (``udofs``: node -> (u_r, u_z)), never an offset, so a
new field does not change them; ``field_dofs(name)`` gives the index set of a field, for
example for ``-pc_type fieldsplit``.

This serial layout, on ``COMM_SELF``, defines the *serial* (natural) dof numbers: outputs,
the pressure front and every full state vector a run hands around use them. A problem does
not take a Layout: it takes the one numbering of a scene,
:class:`sealts.mesh.partition.Numbering` (``Partition.numbering``), whose serial dofs are
this Section's followed by the global scalars (leakage volumes, the paper scheme's
constants), and which adds the global and per-rank local numbers of the distributed mesh
(equal to the serial ones on one rank), so each rank assembles only its own cells
(:mod:`sealts.problem.problem`).
"""
import numpy as np
from petsc4py import PETSc


def vertex_dofs(n_nodes):
    """The node -> (u_r, u_z) dofs of a displacement-only layout: 2i, 2i + 1."""
    return np.arange(2 * n_nodes, dtype=np.int64).reshape(n_nodes, 2)


def label_boundaries(dm, mesh, v0):
    """One DMPlex label per named boundary: its edges and their vertices, value 1."""
    for name, edges in mesh.edges.items():
        dm.createLabel(name)
        for a, b in np.asarray(edges):
            for p in dm.getJoin([v0 + a, v0 + b]):
                dm.setLabelValue(name, int(p), 1)
            dm.setLabelValue(name, int(v0 + a), 1)
            dm.setLabelValue(name, int(v0 + b), 1)


class Layout:
    """DMPlex + Section of a seal mesh with the fields a scene needs."""

    def __init__(self, mesh, film=False, prony=0, slip=False, groove=False):
        X = np.ascontiguousarray(mesh.X, float)
        conn = np.ascontiguousarray(mesh.conn, PETSc.IntType)
        n_cells, n_nodes = conn.shape[0], X.shape[0]
        dm = PETSc.DMPlex().createFromCellList(2, conn, X, interpolate=True,
                                               comm=PETSc.COMM_SELF)
        c0, c1 = dm.getHeightStratum(0)
        v0, v1 = dm.getDepthStratum(0)
        if (c1 - c0, v1 - v0) != (n_cells, n_nodes):
            raise ValueError("DMPlex does not reproduce the mesh's cells and vertices")
        self.dm, self.v0, self.c0 = dm, v0, c0
        label_boundaries(dm, mesh, v0)

        fields = [("displacement", 2)]
        if film:
            fields.append(("film_pressure", 1))
        if slip:
            fields.append(("rod_slip", 1))
        if groove:
            fields.append(("groove_anchor", 2))
        if prony:
            fields.append(("prony", int(prony)))
        self.fields = [f for f, _ in fields]
        rod = mesh.chain("rod_side") if (film or slip) else np.zeros(0, np.int64)
        # every boundary vertex may touch a groove wall (GrooveContact's nodes)
        bnd = mesh.boundary_nodes() if groove else np.zeros(0, np.int64)
        sec = PETSc.Section().create(comm=PETSc.COMM_SELF)
        sec.setNumFields(len(fields))
        for i, (name, k) in enumerate(fields):
            sec.setFieldName(i, name)
            sec.setFieldComponents(i, k)
        p0, p1 = dm.getChart()
        sec.setChart(p0, p1)
        ndof = np.zeros(p1 - p0, np.int64)
        for v in range(v0, v1):
            sec.setFieldDof(v, 0, 2)
        ndof[v0 - p0:v1 - p0] = 2
        for name in ("film_pressure", "rod_slip"):
            if name in self.fields:
                f = self.fields.index(name)
                for node in rod:
                    sec.setFieldDof(v0 + int(node), f, 1)
                ndof[v0 + rod - p0] += 1
        if groove:
            f = self.fields.index("groove_anchor")
            for node in bnd:
                sec.setFieldDof(v0 + int(node), f, 2)
            ndof[v0 + bnd - p0] += 2
        if prony:
            for c in range(c0, c1):
                sec.setFieldDof(c, len(fields) - 1, int(prony))
            ndof[c0 - p0:c1 - p0] += int(prony)
        for p in np.nonzero(ndof)[0]:
            sec.setDof(p0 + int(p), int(ndof[p]))
        # vertices first (in node order), then cells, then the dof-free edges
        rest = np.setdiff1d(np.arange(p0, p1), np.r_[v0:v1, c0:c1])
        perm = np.concatenate([np.arange(v0, v1), np.arange(c0, c1), rest]) - p0
        sec.setPermutation(PETSc.IS().createGeneral(perm.astype(PETSc.IntType),
                                                    comm=PETSc.COMM_SELF))
        sec.setUp()
        dm.setLocalSection(sec)
        self.section = sec
        self.n = sec.getStorageSize()

        self.udofs = np.array([[sec.getFieldOffset(v, 0)] * 2 for v in range(v0, v1)],
                              np.int64) + [0, 1]
        self.rod_nodes = rod
        self.groove_nodes = bnd
        self.groove_dofs = (np.array([sec.getFieldOffset(v0 + int(i),
                                                         self.fields.index("groove_anchor"))
                                      for i in bnd], np.int64)[:, None] + np.arange(2)
                            if groove else np.zeros((0, 2), np.int64))
        self.film_dofs, self.slip_dofs = (
            np.array([sec.getFieldOffset(v0 + int(i), self.fields.index(name)) for i in rod]
                     if name in self.fields else [], np.int64)
            for name in ("film_pressure", "rod_slip"))
        k = int(prony)
        self.prony_dofs = (np.array([sec.getFieldOffset(c, len(fields) - 1)
                                     for c in range(c0, c1)], np.int64)[:, None]
                           + np.arange(k)) if k else np.zeros((n_cells, 0), np.int64)

    def field_dofs(self, name):
        """All dofs of one field, sorted."""
        arrays = {"displacement": self.udofs, "film_pressure": self.film_dofs,
                  "rod_slip": self.slip_dofs, "groove_anchor": self.groove_dofs,
                  "prony": self.prony_dofs}
        if name not in self.fields:
            raise KeyError(f"no field {name!r} in this layout (fields: {self.fields})")
        return np.sort(arrays[name].ravel())

    def label_nodes(self, name):
        """Mesh nodes marked by a boundary label of the DMPlex."""
        pts = self.dm.getStratumIS(name, 1).getIndices()
        v1 = self.v0 + len(self.udofs)
        return np.sort(pts[(pts >= self.v0) & (pts < v1)] - self.v0)
