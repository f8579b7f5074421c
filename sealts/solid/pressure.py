"""Fluid pressure on the seal's free surface, with pressure penetration.

Follower load (paper step 2): the pressure p(t) acts on the *current* boundary edges that the
fluid wets. For a boundary edge a -> b, traversed counter-clockwise in (r, z) so that its
outward normal times length is (dz, -dr), the consistent nodal forces are

    axisymmetric:  F_a = -p 2 pi (2 r_a + r_b)/6 (dz, -dr),  F_b = -p 2 pi (r_a + 2 r_b)/6 (dz, -dr)
    plane strain:  F_a = F_b = -p (depth/2) (dz, -dr)

(2 pi int N r dl over a straight edge), with their exact Jacobian (the load stiffness).

Pressure penetration: the wetted set starts at the most exposed node of the pressure side
(its smallest z) and follows the boundary loop in both directions up to the first node where
the contact pressure p_c from the groove or the rod exceeds the fluid pressure p: there the
seal seals. The front lies inside the last edge, where the linear interpolant of p_c - p
between its two nodes crosses zero, so only that fraction theta of the edge is loaded:

    F_a = -p 2 pi int_s0^s1 (1 - s) r(s) ds (dz, -dr),   F_b = -p 2 pi int_s0^s1 s r(s) ds (dz, -dr)

with [s0, s1] = [0, theta] (or [1 - theta, 1] walking the other way). The front thus moves
continuously: as p_c at the blocking node falls to p, theta reaches 1, and the next edge
starts from theta = 0. (Wetting whole edges made the load jump at every node the front
passed, and TS cut its step to one node per step: dt ~ 5e-5 on the paper's 0.01 mm mesh.)
The front is updated between time steps only (``update`` from the last accepted state,
called by the TS monitor), so each Newton solve sees a fixed, smooth load.
"""
import numpy as np

from ..mesh.layout import vertex_dofs
from ..problem import Term


def boundary_loop(conn):
    """Boundary edges (a, b) oriented counter-clockwise (as in their element), in loop order."""
    e = np.concatenate([conn[:, [0, 1]], conn[:, [1, 2]], conn[:, [2, 3]], conn[:, [3, 0]]])
    key = np.sort(e, axis=1)
    _, idx, counts = np.unique(key, axis=0, return_index=True, return_counts=True)
    edges = e[idx[counts == 1]]
    nxt = dict(zip(edges[:, 0], range(len(edges))))
    order = [0]
    while len(order) < len(edges):
        order.append(nxt[edges[order[-1], 1]])
    return edges[order]


class PressureLoad(Term):
    def __init__(self, X, conn, pressure, axisym, start_node, depth=1.0, udofs=None):
        """``pressure(t)`` in MPa; ``start_node`` the node where the fluid arrives."""
        self.X, self.pressure, self.axisym, self.depth = X, pressure, axisym, depth
        self.edges = boundary_loop(conn)
        self.m = len(self.edges)
        self.start = int(np.nonzero(self.edges[:, 0] == start_node)[0][0])
        self.s0 = np.zeros(self.m)       # wetted part [s0, s1] of each edge, s from a to b
        self.s1 = np.ones(self.m)
        self.reach = None                # the two fronts' positions (edges from the start)
        a, b = self.edges[:, 0], self.edges[:, 1]
        self.udofs = vertex_dofs(X.shape[0]) if udofs is None else udofs
        da, db = self.udofs[a], self.udofs[b]
        self.dofs = np.concatenate([da, db], 1)            # (m, 4): ra, za, rb, zb
        self.rows = np.repeat(self.dofs, 4, axis=1).ravel()
        self.cols = np.tile(self.dofs, (1, 4)).ravel()

    @property
    def wet(self):
        """Wetted fraction of each boundary edge (0 dry, 1 wet)."""
        return self.s1 - self.s0

    def _reach(self, g, step):
        """How far the fluid gets from the start, one way round: the number of whole wet
        edges plus the wet fraction of the edge where p_c - p = g crosses zero."""
        k = self.start if step == 1 else (self.start - 1) % self.m
        for n in range(self.m):
            a, b = self.edges[k]
            near, far = (a, b) if step == 1 else (b, a)
            if g[far] > 0.0:
                return n + (-g[near] / (g[far] - g[near]) if g[near] < 0.0 else 0.0)
            k = (k + step) % self.m
        return float(self.m)

    def update(self, contact_pressure_at_nodes, p, max_advance=None):
        """Wet the loop from the start node both ways up to where p_c - p crosses zero.

        ``max_advance`` (edges): how far each front may advance in one update. A region
        whose contact pressure falls below p all at once would otherwise flood in one
        step, a load jump that no step size can soften (met in the viscoelastic hold)."""
        g = contact_pressure_at_nodes - p
        reach = [self._reach(g, 1), self._reach(g, -1)]
        if max_advance is not None and self.reach is not None:
            reach = [min(r, old + max_advance) for r, old in zip(reach, self.reach)]
        self.reach = reach
        s0, s1 = np.zeros(self.m), np.zeros(self.m)
        for r, step in zip(reach, (1, -1)):
            n = int(min(r, self.m))
            first = self.start if step == 1 else (self.start - 1) % self.m
            k = (first + step * np.arange(n)) % self.m
            s0[k], s1[k] = 0.0, 1.0
            frac = r - n
            if n < self.m and frac > 0.0:
                k = (first + step * n) % self.m
                if s1[k] - s0[k] < 1.0:       # not already wet from the other side
                    if step == 1:
                        s0[k], s1[k] = 0.0, frac
                    else:
                        s0[k], s1[k] = 1.0 - frac, 1.0
        self.s0, self.s1 = s0, s1

    def _weights(self, xa, xb):
        """2 pi int N_a r ds, 2 pi int N_b r ds over [s0, s1] (axisymmetric) or depth int N ds,
        and their derivatives by (r_a, r_b)."""
        s0, s1 = self.s0, self.s1

        def prim(s):  # antiderivatives of (1-s)(r_a + s d) and s (r_a + s d), split by r_a, d
            return (s - s * s / 2, s * s / 2 - s**3 / 3, s * s / 2, s**3 / 3)

        A0, Ad, B0, Bd = (hi - lo for hi, lo in zip(prim(s1), prim(s0)))
        if self.axisym:
            c = 2 * np.pi
            ra, rb = xa[:, 0], xb[:, 0]
            wa = c * (A0 * ra + Ad * (rb - ra))
            wb = c * (B0 * ra + Bd * (rb - ra))
            dwa = c * np.stack([A0 - Ad, Ad], 1)   # by (r_a, r_b)
            dwb = c * np.stack([B0 - Bd, Bd], 1)
        else:
            wa, wb = self.depth * A0, self.depth * B0
            dwa = dwb = np.zeros((self.m, 2))
        return wa, wb, dwa, dwb

    def _geometry(self, u):
        x = self.X + u[self.udofs]
        a, b = self.edges[:, 0], self.edges[:, 1]
        return x[a], x[b]

    def forces(self, t, u):
        """(m, 4) nodal forces (F_ra, F_za, F_rb, F_zb) of the wetted edges."""
        p = self.pressure(t)
        xa, xb = self._geometry(u)
        dr, dz = xb[:, 0] - xa[:, 0], xb[:, 1] - xa[:, 1]
        wa, wb, _, _ = self._weights(xa, xb)
        F = -p * np.stack([wa * dz, -wa * dr, wb * dz, -wb * dr], 1)
        return F

    def add_residual(self, t, u, udot, f):
        # the residual is internal minus external force
        np.subtract.at(f, self.dofs.ravel(), self.forces(t, u).ravel())

    def jacobian_values(self, t, u, udot, shift):
        p = self.pressure(t)
        xa, xb = self._geometry(u)
        dr, dz = xb[:, 0] - xa[:, 0], xb[:, 1] - xa[:, 1]
        K = np.zeros((self.m, 4, 4))  # d(-F)/d(ra, za, rb, zb)
        wa, wb, dwa2, dwb2 = self._weights(xa, xb)
        dwa = np.zeros((self.m, 4))
        dwb = np.zeros((self.m, 4))
        dwa[:, [0, 2]], dwb[:, [0, 2]] = dwa2, dwb2
        ddz = np.array([0, -1.0, 0, 1.0])
        ddr = np.array([-1.0, 0, 1.0, 0])
        # -F_ra = p wa dz, -F_za = -p wa dr, -F_rb = p wb dz, -F_zb = -p wb dr
        K[:, 0] = p * (dz[:, None] * dwa + wa[:, None] * ddz)
        K[:, 1] = -p * (dr[:, None] * dwa + wa[:, None] * ddr)
        K[:, 2] = p * (dz[:, None] * dwb + wb[:, None] * ddz)
        K[:, 3] = -p * (dr[:, None] * dwb + wb[:, None] * ddr)
        return K.ravel()
