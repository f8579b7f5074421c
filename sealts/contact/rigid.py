"""Contact of seal boundary nodes with rigid analytical surfaces.

Rod (``RodContact``): a cylinder of radius r_rod(t) against the seal's rod side
(:class:`sealts.contact.rod_side.RodSide`, whose gap h_i = r_i + u_r,i - r_rod is paper
Eq. 18). Its normal law is an asperity law p_s(h) (:mod:`sealts.contact.asperity`, Eq. 44 by
default), on the same rod side as the film in the coupled problem. The nodal force (Eq. 45)
acts radially outward on the seal:

    f_r,i = p_s(h_i) A L_i,   L_i = (z_{i+1} - z_{i-1}) / 2  (current axial positions, Eq. 30),

with A = 2 pi r_rod (axisymmetric) or the depth (plane strain), and one-sided L at the ends of
the rod-side chain. Its exact Jacobian includes the dependence of L_i on the neighbours' u_z.

Groove (``GrooveContact``): frictionless rigid walls, the bottom r = r_G(t) (seal inside,
r <= r_G) and the side walls z = z_a(t), z = z_b(t) (seal between). Each boundary node feels
the smooth penalty

    p(g) = k delta ln(1 + exp(-g / delta)),   g the node's distance to the wall,

(C-infinity; p ~ k |g| inside the wall, exponentially small outside), times the node's
reference tributary area. With k = ``penalty`` (MPa/mm) the penetration under a wall pressure
p is about p / k: 1e4 MPa/mm allows 0.1 um per MPa, against an O-ring squeeze of 0.63 mm.

Extrusion gap (optional, ``edge = (r_bore, rho_e)``): the side walls end at the bore
r_bore = r_rod + clearance above the rod, their lower edges rounded to rho_e. Below
r_bore + rho_e a node feels, instead of its wall's face, the edge's arc centred at
(r_bore + rho_e, z_w -+ rho_e) (g = |x - c| - rho_e, force p(g) away from the centre)
while it is short of the centre's z, and beyond it the bore (g = r_bore - r, force p(g)
towards the rod): seal material that passes the wall's plane has extruded into the gap.
Gap and normal are continuous where the pieces meet.

Groove corner radius rho (optional): the bottom corners are quarter circles centred at
c_a = (r_G - rho, z_a + rho) and c_b = (r_G - rho, z_b - rho). A node in a corner's square
(r > r_G - rho and z beyond the centre) feels that arc instead of the bottom and the side
wall: g = rho - |x - c|, force p(g) towards c. The gap and its normal are continuous across
the square's edges, where the arc meets the flat walls. rho = 0 gives sharp corners.
"""
import numpy as np

from ..mesh.layout import vertex_dofs
from ..core import Term


def tributary_lengths(X, edges, n):
    """Half the reference length of the boundary edges at each node (mm)."""
    L = np.linalg.norm(X[edges[:, 1]] - X[edges[:, 0]], axis=1)
    return np.bincount(edges.ravel(), np.repeat(0.5 * L, 2), minlength=n)


def node_contact_pressure(n_nodes, groove, rod, t, u):
    """Largest contact pressure (groove walls, rod) at every node, MPa (0 off the walls):
    what the pressure-penetration front compares with the fluid pressure."""
    pc = np.zeros(n_nodes)
    pc[groove.nodes] = groove.node_pressures(t, u)
    p_rod, _ = rod.pressure(t, u)
    np.maximum.at(pc, rod.side.chain, p_rod)
    return pc


def corner_arcs(r, z, rg, za, zb, rho):
    """The nodes in each rounded bottom corner's square (module docstring), for corners a
    (side -1) and b (side +1): yields (side, node indices, distance d to the arc's centre,
    unit normal (nr, nz) from the centre). Nothing with rho = 0."""
    if rho <= 0.0:
        return
    rc = rg - rho
    for zc, side in ((za + rho, -1.0), (zb - rho, 1.0)):
        inside = (r > rc) & (side * (z - zc) > 0.0)
        if side > 0:
            inside &= ~((r > rc) & (z < za + rho))
        idx = np.nonzero(inside)[0]
        dr_, dz_ = r[idx] - rc, z[idx] - zc
        d = np.maximum(np.hypot(dr_, dz_), 1e-12)
        yield side, idx, d, dr_ / d, dz_ / d


def wall_edges(r, z, za, zb, edge):
    """The nodes below the side walls' rounded lower edges (module docstring), for wall a
    (side -1) and wall b (side +1): yields (side, node indices, gap g, unit normal (nr, nz)
    from the housing towards the node, distance d to the edge's centre or 0 under the bore).
    Nothing without an edge (walls down to the rod)."""
    if edge is None:
        return
    r_bore, rho = edge
    cr = r_bore + rho
    for zw, side in ((za, -1.0), (zb, 1.0)):
        cz = zw + side * rho                      # the edge's centre, inside the housing
        below = np.nonzero(r < cr)[0]
        if below.size == 0:
            continue
        dr_, dz_ = r[below] - cr, z[below] - cz
        arc = side * dz_ <= 0.0                   # before the centre: on the arc
        d = np.where(arc, np.maximum(np.hypot(dr_, dz_), 1e-12), 0.0)
        g = np.where(arc, d - rho, r_bore - r[below])
        nr = np.where(arc, dr_ / np.where(arc, d, 1.0), -1.0)
        nz = np.where(arc, dz_ / np.where(arc, d, 1.0), 0.0)
        yield side, below, g, nr, nz, d


def softplus_penalty(g, k, delta):
    """p = k delta ln(1 + exp(-g/delta)) and dp/dg, overflow-safe."""
    x = -g / delta
    p = k * delta * np.logaddexp(0.0, x)
    dp = -k * 0.5 * (1.0 + np.tanh(0.5 * x))  # -k / (1 + exp(-x)) without overflow
    return p, dp


class RodContact(Term):
    def __init__(self, side, law):
        """``side``: the :class:`sealts.contact.rod_side.RodSide` (chain, dofs, gap,
        lengths, A); ``law``: the asperity law (:mod:`sealts.contact.asperity`)."""
        self.side, self.law = side, law
        s = side
        self.rows = np.concatenate([s.ur, s.ur, s.ur])
        self.cols = np.concatenate([s.ur, s.uz[s.hi], s.uz[s.lo]])

    def pressure(self, t, u):
        """(p_s, dp_s/dh) of the asperity law at each chain node's gap (MPa, MPa/mm)."""
        return self.law.pressure(self.side.gap(t, u))

    def forces(self, t, u):
        """Radial contact force on each chain node (N)."""
        p, _ = self.pressure(t, u)
        return p * self.side.area * self.side.lengths(u)

    def add_residual(self, t, u, udot, f):
        np.subtract.at(f, self.side.ur, self.forces(t, u))

    def jacobian_values(self, t, u, udot, shift):
        p, dp = self.pressure(t, u)
        s = self.side
        L = s.lengths(u)
        a = s.area
        return np.concatenate([-dp * a * L, -p * a * s.half, p * a * s.half])


class GrooveContact(Term):
    """Frictionless groove bottom (r <= r_bottom(t)) and side walls (z_a(t) <= z <= z_b(t)),
    with bottom corners rounded to ``corner_radius``."""

    def __init__(self, X, nodes, tributary, axisym, r_bottom, z_walls, penalty=1e4,
                 delta=1e-4, udofs=None, depth=1.0, corner_radius=0.0, edge=None):
        """``edge``: (r_bore, rho_e), the radius (mm) where the side walls end above the
        rod, leaving the extrusion gap r_bore - r_rod, and the radius of their rounded
        lower edges; None: the walls reach down to the rod."""
        self.X, self.nodes = X, np.asarray(nodes)
        w = tributary[self.nodes] * (2 * np.pi * X[self.nodes, 0] if axisym else depth)
        self.w = w
        self.r_bottom, self.z_walls = r_bottom, z_walls
        self.k, self.delta, self.rho = penalty, delta, corner_radius
        self.edge = None if edge is None else (float(edge[0]), float(edge[1]))
        udofs = vertex_dofs(X.shape[0]) if udofs is None else udofs
        self.ur, self.uz = udofs[self.nodes, 0], udofs[self.nodes, 1]
        # a 2x2 block per node: (r, r), (r, z), (z, r), (z, z)
        self.rows = np.concatenate([self.ur, self.ur, self.uz, self.uz])
        self.cols = np.concatenate([self.ur, self.uz, self.ur, self.uz])

    def _evaluate(self, t, u):
        """Per node: contact pressure of each surface, the force on the seal split into
        (bottom radial, wall a axial, wall b axial) and its 2x2 stiffness d(-force)/dx."""
        r = self.X[self.nodes, 0] + u[self.ur]
        z = self.X[self.nodes, 1] + u[self.uz]
        za, zb = self.z_walls(t)
        rg = self.r_bottom(t)
        k, dl, rho = self.k, self.delta, self.rho
        pb, dpb = softplus_penalty(rg - r, k, dl)
        pa, dpa = softplus_penalty(z - za, k, dl)
        pz, dpz = softplus_penalty(zb - z, k, dl)
        fr, fa, fb = -pb, pa, -pz            # force per unit area on the seal
        Krr, Krz, Kzz = -dpb, np.zeros_like(r), -dpa - dpz
        # each surface's pressure where it acts (the bottom or its corner arc, wall a or its
        # corner arc or edge, wall b likewise): node_pressures is their largest
        on = np.stack([pb, pa, pz])
        for side, idx, d, nr, nz in corner_arcs(r, z, rg, za, zb, rho):
            pc, dpc = softplus_penalty(rho - d, k, dl)
            fr[idx] = -pc * nr              # the arc pushes the node towards its centre
            if side < 0:
                fa[idx] = -pc * nz           # in place of side wall a (wall b still acts)
            else:
                fb[idx] = -pc * nz
            on[0, idx] = pc
            on[1 if side < 0 else 2, idx] = 0.0
            # d(p n)/dx = -dp n n^T + p (I - n n^T) / d
            Krr[idx] = -dpc * nr * nr + pc * (1 - nr * nr) / d
            Krz[idx] = -dpc * nr * nz - pc * nr * nz / d
            Kzz[idx] = -dpc * nz * nz + pc * (1 - nz * nz) / d
            if side < 0:
                Kzz[idx] += -dpz[idx]
            else:
                Kzz[idx] += -dpa[idx]
        for side, idx, g, nr, nz, d in wall_edges(r, z, za, zb, self.edge):
            # below the bore the wall's face is replaced by its edge (an arc pushing away
            # from its centre) or the bore (pushing towards the rod)
            pe, dpe = softplus_penalty(g, k, dl)
            dface = dpa if side < 0 else dpz
            fr[idx] += pe * nr
            if side < 0:
                fa[idx] = pe * nz
            else:
                fb[idx] = pe * nz
            on[1 if side < 0 else 2, idx] = pe
            # d(p n)/dx = dp/dg n n^T + p (I - n n^T) / d on the arc, dp/dg n n^T under
            # the bore (n constant); K = -d(force)/dx
            curv = np.divide(pe, d, out=np.zeros_like(pe), where=d > 0.0)
            Krr[idx] += -dpe * nr * nr - curv * (1 - nr * nr)
            Krz[idx] += -dpe * nr * nz + curv * nr * nz
            Kzz[idx] += dface[idx] - dpe * nz * nz - curv * (1 - nz * nz)
        return on.max(axis=0), (fr, fa, fb), (Krr, Krz, Kzz)

    def node_pressures(self, t, u):
        """Largest wall pressure (bottom, side wall or corner) at each of ``nodes``, MPa."""
        return self._evaluate(t, u)[0]

    def reactions(self, t, u):
        """Total force on the seal (N): radial from the bottom (and the corners' and the
        wall edges' radial parts; inward < 0), axial from each side wall (and its corner
        and edge)."""
        _, (fr, fa, fb), _ = self._evaluate(t, u)
        return {"bottom": float(fr @ self.w), "wall_pressure_side": float(fa @ self.w),
                "wall_atmosphere_side": float(fb @ self.w)}

    def add_residual(self, t, u, udot, f):
        _, (fr, fa, fb), _ = self._evaluate(t, u)
        np.subtract.at(f, self.ur, fr * self.w)
        np.subtract.at(f, self.uz, (fa + fb) * self.w)

    def jacobian_values(self, t, u, udot, shift):
        _, _, (Krr, Krz, Kzz) = self._evaluate(t, u)
        w = self.w
        return np.concatenate([Krr * w, Krz * w, Krz * w, Kzz * w])
