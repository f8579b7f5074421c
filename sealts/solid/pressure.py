"""Fluid pressure on the seal's free surface, with pressure penetration.

Follower load (paper step 2): the pressure p(t) acts on the *current* boundary edges that the
fluid wets. For a boundary edge a -> b, traversed counter-clockwise in (r, z) so that its
outward normal times length is (dz, -dr), the consistent nodal forces are

    axisymmetric:  F_a = -p 2 pi (2 r_a + r_b)/6 (dz, -dr),  F_b = -p 2 pi (r_a + 2 r_b)/6 (dz, -dr)
    plane strain:  F_a = F_b = -p (depth/2) (dz, -dr)

(2 pi int N r dl over a straight edge), with their exact Jacobian (the load stiffness).

Pressure penetration: the wetted set starts at the most exposed node of the pressure side
(its smallest z) and follows the boundary loop in both directions up to the first node where
the contact pressure from the groove or the rod exceeds the fluid pressure: there the seal
seals. The front is updated between time steps only (``update`` from the last accepted state,
called by the TS monitor), so each Newton solve sees a fixed, smooth load.
"""
import numpy as np

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
    def __init__(self, X, conn, pressure, axisym, start_node, depth=1.0, offset=0):
        """``pressure(t)`` in MPa; ``start_node`` the node where the fluid arrives."""
        self.X, self.pressure, self.axisym, self.depth = X, pressure, axisym, depth
        self.edges = boundary_loop(conn)
        self.m = len(self.edges)
        self.start = int(np.nonzero(self.edges[:, 0] == start_node)[0][0])
        self.wet = np.ones(self.m, bool)
        a, b = self.edges[:, 0], self.edges[:, 1]
        da = np.stack([offset + 2 * a, offset + 2 * a + 1], 1)
        db = np.stack([offset + 2 * b, offset + 2 * b + 1], 1)
        self.dofs = np.concatenate([da, db], 1)            # (m, 4): ra, za, rb, zb
        self.rows = np.repeat(self.dofs, 4, axis=1).ravel()
        self.cols = np.tile(self.dofs, (1, 4)).ravel()

    def update(self, contact_pressure_at_nodes, p):
        """Wet the loop from the start node both ways until contact pressure exceeds p."""
        blocked = contact_pressure_at_nodes > p
        wet = np.zeros(self.m, bool)
        for step in (1, -1):
            k = self.start if step == 1 else (self.start - 1) % self.m
            for _ in range(self.m):
                a, b = self.edges[k]
                node = b if step == 1 else a
                wet[k] = True
                if blocked[node]:
                    break
                k = (k + step) % self.m
        self.wet = wet

    def _geometry(self, u):
        x = self.X + u[: 2 * self.X.shape[0]].reshape(-1, 2)
        a, b = self.edges[:, 0], self.edges[:, 1]
        return x[a], x[b]

    def forces(self, t, u):
        """(m, 4) nodal forces (F_ra, F_za, F_rb, F_zb) of the wetted edges."""
        p = self.pressure(t)
        xa, xb = self._geometry(u)
        dr, dz = xb[:, 0] - xa[:, 0], xb[:, 1] - xa[:, 1]
        if self.axisym:
            wa = 2 * np.pi * (2 * xa[:, 0] + xb[:, 0]) / 6
            wb = 2 * np.pi * (xa[:, 0] + 2 * xb[:, 0]) / 6
        else:
            wa = wb = np.full(self.m, 0.5 * self.depth)
        F = -p * np.stack([wa * dz, -wa * dr, wb * dz, -wb * dr], 1)
        F[~self.wet] = 0.0
        return F

    def add_residual(self, t, u, udot, f):
        # the residual is internal minus external force
        np.subtract.at(f, self.dofs.ravel(), self.forces(t, u).ravel())

    def jacobian_values(self, t, u, udot, shift):
        p = self.pressure(t)
        xa, xb = self._geometry(u)
        dr, dz = xb[:, 0] - xa[:, 0], xb[:, 1] - xa[:, 1]
        m = self.m
        K = np.zeros((m, 4, 4))  # d(-F)/d(ra, za, rb, zb)
        if self.axisym:
            c = 2 * np.pi / 6
            wa = c * (2 * xa[:, 0] + xb[:, 0])
            wb = c * (xa[:, 0] + 2 * xb[:, 0])
            dwa = np.array([2 * c, 0, c, 0])
            dwb = np.array([c, 0, 2 * c, 0])
        else:
            wa = wb = np.full(m, 0.5 * self.depth)
            dwa = dwb = np.zeros(4)
        ddz = np.array([0, -1.0, 0, 1.0])
        ddr = np.array([-1.0, 0, 1.0, 0])
        # -F_ra = p wa dz, -F_za = -p wa dr, -F_rb = p wb dz, -F_zb = -p wb dr
        K[:, 0] = p * (np.outer(dz, dwa) + wa[:, None] * ddz)
        K[:, 1] = -p * (np.outer(dr, dwa) + wa[:, None] * ddr)
        K[:, 2] = p * (np.outer(dz, dwb) + wb[:, None] * ddz)
        K[:, 3] = -p * (np.outer(dr, dwb) + wb[:, None] * ddr)
        K[~self.wet] = 0.0
        return K.ravel()
