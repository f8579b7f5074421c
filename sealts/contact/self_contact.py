"""Self-contact of the seal's surface: nearby boundary nodes keep a contact distance apart,
so that a fold of the surface closes on itself instead of passing through itself.

Squeezed into the corner between rod and groove wall (the paper's O-ring at 38 MPa with no
clearance; not at 35), the surface pressed along the wall is compressed along itself to a
fifth of its length and folds inwards at the scale of the mesh. Without this term the
faces of the fold pass through each other.

Node-to-node penalty with a contact thickness (as shell elements' contact): each pair of
boundary nodes i, j from 2 to ``REACH`` positions apart along the boundary loop is held at
least d0 = ``THICKNESS`` min(h_i, h_j) apart, h the nodes' reference tributary lengths,
by the groove walls' softplus penalty (:func:`sealts.contact.rigid.softplus_penalty`,
the same k and delta) on the distance d = |x_i - x_j|:

    F_ij = p(d - d0) A_ij e_ij,   e_ij = (x_i - x_j) / d,   p(g) = k delta ln(1 + exp(-g/delta))

on i (and -F_ij on j), A_ij = min(A_i, A_j) the smaller tributary area (length times 2 pi
R, or the depth). Two nodes of an undeformed face lie 2 h apart, of a right-angled corner
1.4 h, so the undeformed surface feels nothing (p < 1e-17 k delta at d > d0 + ``CUTOFF``
delta, where pairs are skipped; on micrometre elements pairs of a face lie within the
cutoff, their force some 1e-9 MPa). A closing fold's faces stop at d0 where its nodes are
within reach (the one or two pairs nearest its tip; a deeper fold is not held): a node of
one face between two of the other (h apart) is at h / 2 from both, within d0 = 0.6 h. A
surface compressed along itself below 0.3 of its length is resisted too. The force is central, so
it is smooth in every direction (no projection onto segments, no facing test) and
conserves force and moment pair by pair; its 2 x 2 stiffness is

    d(-F_ij)/dx_i = -A (p' e e^T + p / d (I - e e^T)),   p' = dp/dg (< 0) at g = d - d0.

Its cost: the pattern couples boundary nodes within REACH along the loop, fill in the
factorisations (:data:`sealts.problem.seal_model.SELF_CONTACT_FROM`); a surface that is not
folding has no pair in reach of contact (its residual and Jacobian values are zeros).
"""
import numpy as np

from ..core import Term
from ..mesh.layout import vertex_dofs
from .rigid import softplus_penalty

REACH = 3          # pairs of boundary nodes 2 .. REACH positions apart along the loop
THICKNESS = 0.6    # d0 as a fraction of the smaller reference tributary length
CUTOFF = 40.0      # pairs further than d0 + CUTOFF delta apart carry nothing


class SelfContact(Term):
    def __init__(self, X, loop, tributary, axisym, udofs=None, penalty=1e4, delta=1e-4,
                 depth=1.0, reach=REACH):
        """``X``: reference coordinates (r, z) (mm); ``loop``: the boundary nodes in loop
        order (:func:`sealts.solid.pressure.boundary_loop`'s first column); ``tributary``:
        each node's reference boundary length (mm); ``penalty`` (MPa/mm) and ``delta``
        (mm): the groove walls' softplus penalty; ``udofs`` (nodes, 2): the (u_r, u_z)
        dofs of each node in the problem's numbering."""
        self._args = (X, loop, tributary, axisym, penalty, delta, depth, reach)
        X = np.asarray(X, float)
        loop = np.asarray(loop, np.int64)
        m = loop.size
        udofs = np.asarray(vertex_dofs(X.shape[0]) if udofs is None else udofs, np.int64)
        reach = min(int(reach), m // 2)
        steps = np.arange(2, reach + 1)
        a = np.repeat(np.arange(m), steps.size)
        b = (a + np.tile(steps, m)) % m
        if 2 * reach == m:                    # a small loop: each pair once
            keep = (b - a) % m != reach
            keep |= a < b
            a, b = a[keep], b[keep]
        self.i, self.j = loop[a], loop[b]
        h = tributary[loop]
        area = h * (2.0 * np.pi * X[loop, 0] if axisym else depth)
        self.d0 = THICKNESS * np.minimum(h[a], h[b])
        self.area = np.minimum(area[a], area[b])
        self.k, self.delta = float(penalty), float(delta)
        self.Xi, self.Xj = X[self.i], X[self.j]
        self.di, self.dj = udofs[self.i], udofs[self.j]
        # 2 x 2 blocks (i, i), (i, j), (j, i), (j, j), each (r, r), (r, z), (z, r), (z, z)
        rows, cols = [], []
        for p, q in ((self.di, self.di), (self.di, self.dj), (self.dj, self.di),
                     (self.dj, self.dj)):
            for c1 in (0, 1):
                for c2 in (0, 1):
                    rows.append(p[:, c1])
                    cols.append(q[:, c2])
        self.rows, self.cols = np.concatenate(rows), np.concatenate(cols)

    def on(self, udofs):
        """The same contact in another numbering ``udofs`` (nodes, 2)."""
        X, loop, trib, axisym, k, delta, depth, reach = self._args
        return SelfContact(X, loop, trib, axisym, udofs, k, delta, depth, reach)

    def _pairs(self, u):
        """The pairs within reach of contact: their indices, separation x_i - x_j (mm) and
        distance d."""
        u = np.asarray(u, float)
        dx = self.Xi - self.Xj + u[self.di] - u[self.dj]
        d = np.hypot(dx[:, 0], dx[:, 1])
        near = np.flatnonzero(d < self.d0 + CUTOFF * self.delta)
        return near, dx[near], d[near]

    def closed(self, u):
        """The reference positions (k, 2) of the first node of each pair closer than its
        contact distance d0 at u: where the surface is folded onto itself."""
        q, _, d = self._pairs(u)
        return self.Xi[q[d < self.d0[q]]]

    def forces(self, u):
        """The pairs in contact and the force on their node i (N, (pairs, 2); -F on j)."""
        q, dx, d = self._pairs(u)
        p, _ = softplus_penalty(d - self.d0[q], self.k, self.delta)
        return q, (p * self.area[q] / d)[:, None] * dx

    def add_residual(self, t, u, udot, f):
        q, F = self.forces(u)
        if q.size == 0:
            return
        np.subtract.at(f, self.di[q].ravel(), F.ravel())
        np.add.at(f, self.dj[q].ravel(), F.ravel())

    def jacobian_values(self, t, u, udot, shift):
        n = self.i.size
        vals = np.zeros((16, n))
        q, dx, d = self._pairs(u)
        if q.size:
            p, dp = softplus_penalty(d - self.d0[q], self.k, self.delta)
            e = dx / d[:, None]
            A = self.area[q]
            # d(-F_i)/dx_i = -A (dp/dd e e^T + p / d (I - e e^T)), dp/dd = dp/dg
            K = -A[:, None, None] * (dp[:, None, None] * e[:, :, None] * e[:, None, :]
                                     + (p / d)[:, None, None]
                                     * (np.eye(2) - e[:, :, None] * e[:, None, :]))
            Kf = K.reshape(-1, 4).T                      # (4, pairs): rr, rz, zr, zz
            vals[0:4, q] = Kf                            # (i, i)
            vals[4:8, q] = -Kf                           # (i, j)
            vals[8:12, q] = -Kf                          # (j, i)
            vals[12:16, q] = Kf                          # (j, j)
        return vals.ravel()
