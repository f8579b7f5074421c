"""A seal mesh distributed over the ranks of a communicator: DMPlex.distribute and the dof
numbering that goes with it.

``Partition(mesh, comm)`` builds the interpolated DMPlex of the mesh on rank 0 (the other
ranks pass no cells), labels the named boundaries there (:func:`label_boundaries`, the same
labels as :class:`sealts.mesh.layout.Layout`), and calls ``DMPlex.distribute``: every rank
then holds its own cells and the vertices of their closure, and the labels travel with
them. The migration SF that ``distribute`` returns maps each local point to its point on
rank 0, whose numbering is the mesh's (cells 0..nc-1 first, then vertices), so every rank
knows its cells and vertices in the mesh's (serial) numbering. A vertex shared between
ranks is owned by one of them, the one the distributed DMPlex's point SF names (the others
hold it as a leaf). Every cell is on exactly one rank (no overlap).

Cells are partitioned by PETSc's partitioner (``-petscpartitioner_type``; this PETSc has
no ParMETIS, so the default is ``simple``: contiguous ranges of the cell numbers). Before
the DMPlex is built, cells are renumbered along a coordinate-sorted order (by axial, then
radial centroid position) only inside the partitioner's view: the ``simple`` partition
then cuts the seal into axial slabs with short interfaces instead of the mesh generator's
scattered ranges.

``Partition.numbering(prony=k)`` gives a :class:`Numbering`: the serial layout's dofs
(vertices first in node order, 2 displacement dofs each, then cells with k Prony dofs each,
exactly :class:`~sealts.mesh.layout.Layout`'s numbering, called *serial* or *natural*
below), and the global (PETSc) numbering: rank by rank, each rank's owned vertices' dofs
(in node order), then its cells' dofs. On one rank global = serial. Each rank's *local*
dofs are its owned dofs (a contiguous global range), then its ghosts: the other vertices
of its cells and, on rank 0, every boundary node (``root_nodes``), since the rod, groove
and pressure terms are evaluated on rank 0 over the whole boundary (``on_root``).

What every rank holds in full: the mesh (X, conn), ``natural`` (serial -> global) and
``local_of_serial`` (serial -> local or -1), O(unknowns) integers, built once; ``udofs_local``
(node -> local dofs, -1 where the node is not local). Per evaluation each rank works on
its local vector only, apart from the gathers of the full state for outputs.
"""
import numpy as np
from petsc4py import PETSc

from ..core import Term
from .layout import Layout, label_boundaries


class Partition:
    """The mesh's DMPlex distributed over ``comm``; local cells and vertices in mesh
    numbering, vertex ownership (see module docstring)."""

    def __init__(self, mesh, comm=None, root_nodes=()):
        self.comm = comm = comm or PETSc.COMM_WORLD
        self.mesh = mesh
        self.rank, self.size = comm.getRank(), comm.getSize()
        X = np.ascontiguousarray(mesh.X, float)
        conn = np.ascontiguousarray(mesh.conn, PETSc.IntType)
        nc, nv = conn.shape[0], X.shape[0]
        self.n_cells, self.n_nodes = nc, nv
        # the partitioner's view of the cells: sorted by centroid (z, then r), see above
        centroid = X[conn].mean(1)
        order = np.lexsort((centroid[:, 0], centroid[:, 1]))
        root = self.rank == 0
        cells = conn[order] if root else np.zeros((0, 4), PETSc.IntType)
        coords = X if root else np.zeros((0, 2))
        dm = PETSc.DMPlex().createFromCellList(2, cells, coords, interpolate=True, comm=comm)
        c0, c1 = dm.getHeightStratum(0)
        v0, v1 = dm.getDepthStratum(0)
        if root:
            if (c1 - c0, v1 - v0) != (nc, nv):
                raise ValueError("DMPlex does not reproduce the mesh's cells and vertices")
            label_boundaries(dm, mesh, v0)
        else:
            for name in mesh.edges:
                dm.createLabel(name)
        mpi = comm.tompi4py()
        c0, v0 = mpi.bcast((c0, v0) if root else None, root=0)
        if self.size > 1:
            dm.getPartitioner().setFromOptions()
            sf = dm.distribute()
            _, ilocal, iremote = sf.getGraph()
            orig = np.full(dm.getChart()[1], -1, np.int64)
            orig[ilocal] = iremote[:, 1]
        else:
            orig = np.arange(dm.getChart()[1], dtype=np.int64)
        self.dm = dm
        lc0, lc1 = dm.getHeightStratum(0)
        lv0, lv1 = dm.getDepthStratum(0)
        cells_local = order[orig[lc0:lc1] - c0]
        verts_local = orig[lv0:lv1] - v0
        if (cells_local < 0).any() or (verts_local < 0).any():
            raise RuntimeError("distributed DMPlex: a local point has no origin on rank 0")
        xl = dm.getCoordinatesLocal().getArray().reshape(-1, 2)
        if not np.array_equal(xl, X[verts_local]):
            raise RuntimeError("distributed DMPlex: vertex coordinates do not match the mesh")
        if not np.array_equal(np.unique(conn[cells_local]), np.sort(verts_local)):
            raise RuntimeError("distributed DMPlex: local vertices are not those of the "
                               "local cells")
        # owned vertices: those that are not leaves of the point SF
        _, leaves, _ = dm.getPointSF().getGraph()
        ghost = np.zeros(lv1 - lv0, bool)
        leaves = np.asarray(leaves, np.int64)
        leaves = leaves[(leaves >= lv0) & (leaves < lv1)] - lv0
        ghost[leaves] = True
        self.cells = np.sort(cells_local)                    # this rank's cells, mesh ids
        self.owned_nodes = np.sort(verts_local[~ghost])      # vertices it owns
        local_nodes = verts_local
        if root:
            local_nodes = np.union1d(local_nodes, np.asarray(root_nodes, np.int64))
        self.ghost_nodes = np.setdiff1d(local_nodes, self.owned_nodes)
        self.cells_per_rank = [int(k) for k in mpi.allgather(len(self.cells))]
        owned = mpi.allreduce(len(self.owned_nodes))
        if sum(self.cells_per_rank) != nc or owned != nv:
            raise RuntimeError(f"partition covers {sum(self.cells_per_rank)} of {nc} cells "
                               f"and owns {owned} of {nv} vertices")
        self._mpi = mpi

    def numbering(self, prony=0, film=False, scalars=(), slip=False, groove=False):
        """The dofs of a layout with displacements, a film pressure (``film``) and the rod
        friction's elastic slip (``slip``) on the ``rod_side`` vertices, the groove walls'
        friction anchors (``groove``) on the boundary vertices, ``prony`` dofs per cell and
        named global ``scalars``: a :class:`Numbering`."""
        return Numbering(self, int(prony), film, scalars, slip, groove)


def node_dof_ranges(start, count, nodes):
    """The dofs of ``nodes`` (each node's ``count`` consecutive dofs from ``start``), node
    after node."""
    c = count[nodes]
    first = np.repeat(start[nodes], c)
    within = np.arange(c.sum()) - np.repeat(np.cumsum(c) - c, c)
    return (first + within).astype(np.int64)


class Numbering:
    """Serial, global and local dof numbers of one field layout on a Partition: the one
    numbering of a seal scene's unknowns.

    Serial (natural): the DMPlex Section of :class:`~sealts.mesh.layout.Layout` (fields on
    labelled points, vertices first in node order, then cells), then the global scalars in
    the order named: ``udofs`` (node -> 2 dofs), ``film_dofs`` and ``slip_dofs`` (chain
    node -> 1 dof each, with ``rod_nodes`` the chain), ``groove_dofs`` (groove node -> 2
    dofs, with ``groove_nodes`` the boundary vertices), ``prony_dofs`` (cell -> k dofs),
    ``scalar_dofs`` (name -> dof), ``field_dofs(name)``, ``n``. Global: ``natural`` (serial -> global); this rank
    owns globals [rstart, rstart + n_owned): its owned vertices' dofs (node order, every
    field of a vertex together), its cells' dofs and, on rank 0, the scalars. Local (this
    rank's work vector): ``ltog`` (local -> global), ``owned`` (mask, the first
    ``n_owned``), ``serial`` (local -> serial), ``local_of_serial`` (serial -> local, -1
    if absent), ``udofs_local`` (node -> local dofs, -1 if absent), ``prony_local`` (the
    rank's cells ``cells`` -> local dofs). Rank 0's ghosts include every boundary node's
    dofs (``root_nodes``), so the boundary terms (rod, film, groove, pressure, friction,
    leakage) run there in serial dofs (``on_root``). ``distributed``: each local row is
    assembled by this rank alone (no replication), so every local contribution is added
    up. On one rank global = local = serial."""

    distributed = True

    def __init__(self, part, k, film=False, scalars=(), slip=False, groove=False):
        nv = part.n_nodes
        self.partition, self.k = part, k
        lay = Layout(part.mesh, film=film, prony=k, slip=slip, groove=groove)
        self.udofs, self.film_dofs, self.rod_nodes = lay.udofs, lay.film_dofs, lay.rod_nodes
        self.slip_dofs = lay.slip_dofs
        self.groove_nodes, self.groove_dofs = lay.groove_nodes, lay.groove_dofs
        self.prony_dofs = lay.prony_dofs
        self.fields = list(lay.fields)
        self.scalars = tuple(scalars)
        self.scalar_dofs = {name: lay.n + i for i, name in enumerate(self.scalars)}
        if len(self.scalar_dofs) != len(self.scalars):
            raise ValueError(f"scalar names repeat: {self.scalars}")
        self.n = lay.n + len(self.scalars)
        count = np.full(nv, 2, np.int64)
        count[lay.rod_nodes] += int(film) + int(slip)
        count[lay.groove_nodes] += 2
        start = self.udofs[:, 0]
        scal = (np.arange(lay.n, self.n, dtype=np.int64) if part.rank == 0
                else np.zeros(0, np.int64))
        own = np.concatenate([node_dof_ranges(start, count, part.owned_nodes),
                              self.prony_dofs[part.cells].ravel(), scal])
        ghosts = node_dof_ranges(start, count, part.ghost_nodes)
        self.n_owned = own.size
        every = part._mpi.allgather(own)
        self.rstart = int(sum(a.size for a in every[:part.rank]))
        serial_of_global = np.concatenate(every)
        if serial_of_global.size != self.n:
            raise RuntimeError("global numbering does not cover the unknowns")
        self.natural = np.empty(self.n, np.int64)
        self.natural[serial_of_global] = np.arange(self.n)
        self.serial = np.concatenate([own, ghosts])
        self.ltog = self.natural[self.serial]
        self.owned = np.zeros(self.serial.size, bool)
        self.owned[:self.n_owned] = True
        self.local_of_serial = np.full(self.n, -1, np.int64)
        self.local_of_serial[self.serial] = np.arange(self.serial.size)
        self.udofs_local = self.local_of_serial[self.udofs]
        self.cells = part.cells
        self.prony_local = self.local_of_serial[self.prony_dofs[part.cells]]
        self.identity = part.size == 1
        if self.identity and not np.array_equal(self.serial, np.arange(self.n)):
            raise RuntimeError("one rank's numbering is not the serial one")

    def describe(self, dof):
        """A serial dof in words: "radial displacement of node 83", "film pressure at node
        12", "V_out"."""
        for name, i in self.scalar_dofs.items():
            if dof == i:
                return name
        hit = np.argwhere(self.udofs == dof)
        if hit.size:
            node, c = hit[0]
            return f"{('radial', 'axial')[c]} displacement of node {node}"
        for name, arr in (("film pressure", self.film_dofs), ("rod slip", self.slip_dofs)):
            hit = np.argwhere(np.asarray(arr) == dof)
            if hit.size:
                return f"{name} at rod-side node {int(self.rod_nodes[hit[0][0]])}"
        hit = np.argwhere(self.groove_dofs == dof)
        if hit.size:
            node, c = hit[0]
            return (f"{('radial', 'axial')[c]} groove friction anchor of node "
                    f"{int(self.groove_nodes[node])}")
        hit = np.argwhere(self.prony_dofs == dof)
        if hit.size:
            return f"Prony variable of cell {hit[0][0]}"
        return f"unknown {dof}"

    def field_dofs(self, name):
        """All serial dofs of one field, sorted."""
        arrays = {"displacement": self.udofs, "film_pressure": self.film_dofs,
                  "rod_slip": self.slip_dofs, "groove_anchor": self.groove_dofs,
                  "prony": self.prony_dofs}
        if name not in self.fields:
            raise KeyError(f"no field {name!r} in this layout (fields: {self.fields})")
        return np.sort(arrays[name].ravel())

    def local(self, serial_dofs):
        """(local dofs, mask) of serial dofs: those this rank holds and which they are."""
        loc = self.local_of_serial[np.asarray(serial_dofs, np.int64)]
        return loc[loc >= 0], loc >= 0

    def on_root(self, terms):
        """Terms written in serial dofs (rod, groove, pressure: along the whole boundary),
        evaluated by rank 0 alone on its local vector. The other ranks get their post-step
        hooks only (:class:`HookOnly`), so a history (the friction anchors, the front) is
        the same on every rank, as are the outputs computed from it."""
        if self.partition.rank != 0:
            return [HookOnly(t) for t in terms if type(t).accepted is not Term.accepted]
        if self.identity:
            return list(terms)
        return [SerialTermOnLocal(t, self.local_of_serial) for t in terms]


class HookOnly(Term):
    """A term's post-step hook without its rows: what the ranks that do not assemble a
    boundary term run of it (u full and serial)."""

    def __init__(self, term):
        self.term = term

    @property
    def history_names(self):
        return self.term.history_names

    def accepted(self, t, u):
        self.term.accepted(t, u)

    def history(self):
        return self.term.history()

    def restore(self, history):
        self.term.restore(history)


class SerialTermOnLocal(HookOnly):
    """A term whose dofs are serial numbers, evaluated on a local vector: its dofs (rows
    and columns) are copied into a serial-length work array, the term runs there, and its
    residual rows are copied back. O(the term's dofs) per call; the term object is shared,
    so state updated between steps (the pressure front) is seen here. Its hook and history
    are the term's own (u is full and serial already), as on the ranks that run it through
    :class:`HookOnly`; so are its events (the other ranks have none of them)."""

    def __init__(self, term, local_of_serial):
        self.term = term
        ser = np.unique(np.concatenate([np.asarray(term.rows, np.int64),
                                        np.asarray(term.cols, np.int64)]))
        loc = local_of_serial[ser]
        if (loc < 0).any():
            raise ValueError(f"{type(term).__name__}: dofs not in this rank's local set")
        self._ser, self._loc = ser, loc
        self.rows = local_of_serial[np.asarray(term.rows, np.int64)]
        self.cols = local_of_serial[np.asarray(term.cols, np.int64)]
        n = local_of_serial.size
        self._u, self._ud, self._f = np.zeros(n), np.zeros(n), np.zeros(n)

    @property
    def event_directions(self):
        return self.term.event_directions

    def event_values(self, t, u):
        return self.term.event_values(t, u)       # u full and serial already

    def event(self, t, u, which):
        self.term.event(t, u, which)

    def _load(self, u, udot):
        self._u[self._ser] = u[self._loc]
        if udot is not None:
            self._ud[self._ser] = udot[self._loc]
        return self._u, (None if udot is None else self._ud)

    def add_residual(self, t, u, udot, f):
        us, uds = self._load(u, udot)
        self._f[self._ser] = 0.0
        self.term.add_residual(t, us, uds, self._f)
        f[self._loc] += self._f[self._ser]

    def jacobian_values(self, t, u, udot, shift):
        us, uds = self._load(u, udot)
        return self.term.jacobian_values(t, us, uds, shift)

