"""Coulomb friction on the groove walls: the rod friction's law (:mod:`.friction`) on the
surfaces of :class:`sealts.contact.rigid.GrooveContact`.

Surfaces. Every groove node sees up to three surfaces ("slots" k), each with its contact
pressure p_k(x) (GrooveContact's softplus penalty of the node's gap to it, x = X + u the
node's current position) and unit tangent t_k(x) in the (r, z) plane:

    k = 0: the bottom r = r_G, t = e_z; in a rounded corner's square (GrooveContact's
           rule) the corner arc instead, centre c, n = (x - c) / |x - c|, t = (-n_z, n_r)
    k = 1: side wall a (z = z_a, pressure side), t = e_r   (replaced by arc a in its square)
    k = 2: side wall b (z = z_b, atmosphere side), t = e_r  (replaced by arc b in its square)

With an extrusion gap a side wall's slot is, below the bore r_bore + rho_e, its rounded
edge (n from the edge's centre, t = (-n_z, n_r)) or the bore (t = -e_z), as GrooveContact.

The arc's tangent is e_z where it meets the bottom and +-e_r where it meets a side wall, so
slot 0's surface and tangent are continuous along the groove's contour (slot 1 or 2 takes
over from the arc at the side wall with the same tangent up to sign, and the law is odd).
A node in a sharp corner (rho = 0) may press on the bottom and a side wall at once and then
carries both frictions.

Slip. One anchor point per node, a_i (a displacement, 2-vector), fixed within a step. The
walls do not move tangentially (their tangential motion is taken as 0), so the slip of node
i on slot k is minus its tangential displacement from the anchor,

    gamma_k,i = -t_k(x_i) . (u_i - a_i),

and the friction force on the seal (N, along t_k; opposing the node's tangential motion) is

    F_k,i = mu_g p_k(x_i) w_i phi(gamma_k,i / gamma_crit) t_k(x_i),

phi :func:`.friction.saturation` (stick gamma / gamma_crit up to 1 - blend, Coulomb sign(gamma)
from |gamma| = gamma_crit on, C1 between), w_i GrooveContact's tributary area of the node
(``groove.w``). On a flat wall t is constant and gamma = -(u_t - a_t): in sliding the force is
mu_g times the wall's normal force on the node, p_k w_i. Exact Jacobian (2x2 per node, the
columns u_r and u_z of the node):

    dF/dx = mu_g w [ phi t (dp/dx)^T + p phi' / gamma_crit t (dgamma/dx)^T + p phi dt/dx ],
    dgamma/dx = -t - (dt/dx)^T (u - a),
    dt/dx = (R - t n^T) / |x - c|  on an arc (R the rotation by +90 degrees), 0 on a flat wall.

Anchor update (return mapping, after each accepted step, as RodFriction): on every slot the
node touches (gap below 10 delta, i.e. p > k delta ln(1 + e^-10) ~ 4.5e-5 k delta; the softplus
never reaches exactly 0) the elastic slip is capped, gamma_k <- clip(gamma_k, +-gamma_crit),
and the anchor is placed at

    a_i = u_i + sum_k gamma_k t_k       (the touched slots' capped slips),

which gives back exactly the capped slips when the touched tangents are orthogonal: the
bottom (or an arc) alone, a side wall alone, the bottom and one side wall in a sharp corner.
(Two slots with parallel tangents, both side walls at once, cannot touch one node; an arc and
the opposite side wall neither, since rho < width / 2.) Slots not touched get zero slip, so a
node that lands on a wall starts from zero elastic slip. Where |gamma| > gamma_crit phi is
saturated, so the update leaves the forces unchanged. The costs and limits are those of
RodFriction (path-independent within a step, anchors outside the TS error estimate): this
is the history of ``stroke.friction_history = "anchors"``; by default the anchors are TS
unknowns (:mod:`.groove_slip_state`).
"""
import numpy as np

from ..core import Term, of_time
from .friction import check_law, saturation
from .rigid import corner_arcs, softplus_penalty, wall_edges

WALLS = ("bottom", "wall_pressure_side", "wall_atmosphere_side", "corner_pressure_side",
         "corner_atmosphere_side")


def groove_surfaces(groove, t, u):
    """The surfaces a groove node sees (module docstring), per slot k (0: bottom or corner
    arc, 1: side wall a, 2: side wall b) and node: pressure p (3, n), its gradient dp/dx
    (3, n, 2), unit tangent t (3, n, 2), its derivative dt/dx (3, n, 2, 2), and slot 0's
    region (n,: 0 the flat bottom, 1 arc a, 2 arc b). The same surfaces, regions and
    pressures as GrooveContact._evaluate."""
    g = groove
    r = g.X[g.nodes, 0] + u[g.ur]
    z = g.X[g.nodes, 1] + u[g.uz]
    za, zb = g.z_walls(t)
    rg = g.r_bottom(t)
    k, dl, rho = g.k, g.delta, g.rho
    n = r.size
    p = np.zeros((3, n))
    dp = np.zeros((3, n, 2))
    tan = np.zeros((3, n, 2))
    dtan = np.zeros((3, n, 2, 2))
    region = np.zeros(n, np.int64)
    p[0], d0 = softplus_penalty(rg - r, k, dl)
    dp[0, :, 0] = -d0
    tan[0, :, 1] = 1.0
    p[1], d1 = softplus_penalty(z - za, k, dl)
    dp[1, :, 1] = d1
    tan[1, :, 0] = 1.0
    p[2], d2 = softplus_penalty(zb - z, k, dl)
    dp[2, :, 1] = -d2
    tan[2, :, 0] = 1.0
    for side, idx, d, nr, nz in corner_arcs(r, z, rg, za, zb, rho):
        pc, dpc = softplus_penalty(rho - d, k, dl)
        wall = 1 if side < 0 else 2                     # the side wall the arc replaces
        p[0, idx], p[wall, idx] = pc, 0.0
        dp[0, idx, 0], dp[0, idx, 1] = -dpc * nr, -dpc * nz
        dp[wall, idx] = 0.0
        tan[0, idx], dtan[0, idx] = _turning(nr, nz, 1.0 / d)
        region[idx] = wall
    for side, idx, gap, nr, nz, d in wall_edges(r, z, za, zb, g.edge):
        pe, dpe = softplus_penalty(gap, k, dl)
        wall = 1 if side < 0 else 2                     # the side wall its edge replaces
        p[wall, idx] = pe
        dp[wall, idx, 0], dp[wall, idx, 1] = dpe * nr, dpe * nz
        # e_r on the face, -e_z on the bore; only the arc (d > 0) turns its tangent
        inv = np.divide(1.0, d, out=np.zeros_like(d), where=d > 0.0)
        tan[wall, idx], dtan[wall, idx] = _turning(nr, nz, inv)
    return p, dp, tan, dtan, region


def _turning(nr, nz, inv):
    """The tangent t = R n (R the rotation by +90 degrees) of a surface with unit normal n,
    and dt/dx = (R - t n^T) / d on an arc of radius d (``inv`` = 1/d; 0 on a flat piece):
    arrays (m, 2) and (m, 2, 2)."""
    tr, tz = -nz, nr
    dt = np.empty(nr.shape + (2, 2))
    dt[:, 0, 0] = -tr * nr * inv
    dt[:, 0, 1] = (-1.0 - tr * nz) * inv
    dt[:, 1, 0] = (1.0 - tz * nr) * inv
    dt[:, 1, 1] = -tz * nz * inv
    return np.stack([tr, tz], axis=1), dt


class GrooveFriction(Term):
    """Coulomb friction mu_g p w phi(gamma / gamma_crit) on the walls of a GrooveContact
    (module docstring). Adds to the groove nodes' u_r and u_z rows (a 2x2 block per node)."""

    def __init__(self, groove, mu=0.1, gamma_crit=1e-4, blend=0.5, anchors=None,
                 open_gap=10.0):
        """``groove``: the :class:`sealts.contact.rigid.GrooveContact`; ``mu``: the friction
        coefficient (number or function of t); ``gamma_crit``, ``blend``: as RodFriction;
        ``anchors``: initial a_i (n, 2) (mm; default 0); ``open_gap``: a slot counts as
        touched in :meth:`update` while the gap is below open_gap * delta."""
        check_law(gamma_crit, blend)
        self.groove = g = groove
        self.mu = of_time(mu)
        self.gamma_crit, self.blend = float(gamma_crit), float(blend)
        m = g.nodes.size
        self.anchors = np.zeros((m, 2)) if anchors is None else np.array(anchors, float)
        if self.anchors.shape != (m, 2):
            raise ValueError("anchors must give an (r, z) pair per groove node")
        self.open_gap = float(open_gap)
        self.p_open = g.k * g.delta * np.log1p(np.exp(-open_gap))
        self.slide = 0.0             # the last update's largest slide on a wall (mm)
        self.rows = np.concatenate([g.ur, g.ur, g.uz, g.uz]).astype(np.int64)
        self.cols = np.concatenate([g.ur, g.uz, g.ur, g.uz]).astype(np.int64)

    # ---- state -----------------------------------------------------------------------------
    def _disp(self, u):
        u = np.asarray(u, float)
        return np.stack([u[self.groove.ur], u[self.groove.uz]], axis=1)

    def _anchors(self, u):
        """The anchors a_i (n, 2), mm: this term's history (a subclass may keep them in u)."""
        return self.anchors

    def _evaluate(self, t, u):
        p, dp, tan, dtan, region = groove_surfaces(self.groove, t, u)
        rel = self._disp(u) - self._anchors(u)                   # u - a, (n, 2)
        gamma = -np.einsum("kni,ni->kn", tan, rel)
        phi, dphi = saturation(gamma / self.gamma_crit, self.blend)
        return p, dp, tan, dtan, region, rel, gamma, phi, dphi

    def slip(self, t, u):
        """gamma_k,i (3, n): the slip of each node on each slot (mm)."""
        return self._evaluate(t, u)[6]

    def slot_forces(self, t, u):
        """F_k,i (3, n, 2): the friction force of each slot on each node (N, (r, z))."""
        p, _, tan, _, _, _, _, phi, _ = self._evaluate(t, u)
        return self.slot_forces_of(t, p, tan, phi)

    def slot_forces_of(self, t, p, tan, phi):
        """F_k,i from the surfaces and slips of ``_evaluate``."""
        return (self.mu(t) * p * self.groove.w * phi)[..., None] * tan

    def forces(self, t, u):
        """Friction force on each groove node (n, 2), N, (r, z) on the seal."""
        return self.slot_forces(t, u).sum(axis=0)

    def total(self, t, u):
        """Friction force on the seal per wall (N): {wall: (F_r, F_z)} for the bottom, the
        side walls a (pressure side) and b, and the corner arcs; "total" their sum."""
        F = self.slot_forces(t, u)
        region = groove_surfaces(self.groove, t, u)[4]
        out = {}
        for i, name in enumerate(WALLS[:3]):
            f = F[i][region == 0].sum(axis=0) if i == 0 else F[i].sum(axis=0)
            out[name] = (float(f[0]), float(f[1]))
        for j, name in ((1, WALLS[3]), (2, WALLS[4])):
            f = F[0][region == j].sum(axis=0)
            out[name] = (float(f[0]), float(f[1]))
        f = F.sum(axis=(0, 1))
        out["total"] = (float(f[0]), float(f[1]))
        return out

    def axial(self, t, u):
        """Total axial friction force of the groove on the seal (N, +z)."""
        return float(self.forces(t, u)[:, 1].sum())

    # ---- history ---------------------------------------------------------------------------
    def reset(self, t, u):
        """Zero elastic slip on every wall: a_i = u_i."""
        self.anchors = self._disp(u)

    def update(self, t, u):
        """Return mapping after an accepted step: cap every touched slot's slip at
        gamma_crit (keeping its sign), zero the others. Returns the largest anchor move of a
        node touching a wall (mm); ``slide`` is the largest slip it took off a touched slot
        (mm): zero while the seal sticks to its walls, when the update changes no wall's
        friction and the walls' friction is a function of the state alone."""
        p, _, tan, _, _, _, gamma, _, _ = self._evaluate(t, u)
        touched = p > self.p_open
        self.slide = float(np.max(np.where(touched, np.abs(gamma) - self.gamma_crit, 0.0),
                                  initial=0.0))
        kept = np.where(touched, np.clip(gamma, -self.gamma_crit, self.gamma_crit), 0.0)
        new = self._disp(u) + np.einsum("kn,kni->ni", kept, tan)
        on = touched.any(axis=0)
        moved = np.linalg.norm(new - self.anchors, axis=1)[on]
        self.anchors = new
        return float(moved.max()) if moved.size else 0.0

    history_names = ("anchors", "slide")

    def accepted(self, t, u):
        """Post-step hook: the return mapping of ``update``."""
        self.update(t, u)

    # ---- Term interface --------------------------------------------------------------------
    def add_residual(self, t, u, udot, f):
        self.subtract_forces(self.forces(t, u), f)

    def subtract_forces(self, F, f):
        """The residual carries -F (F per node, (n, 2))."""
        np.subtract.at(f, self.groove.ur, F[:, 0])
        np.subtract.at(f, self.groove.uz, F[:, 1])

    @staticmethod
    def slip_gradient(tan, dtan, rel):
        """d gamma_k / dx (3, n, 2) = -t_k - (dt_k/dx)^T (u - a)."""
        return -tan - np.einsum("knij,ni->knj", dtan, rel)

    def force_jacobian(self, p, dp, tan, dtan, dgamma, phi, dphi, c):
        """d(-F)/du per node (n, 2, 2) from the surfaces and slips of ``_evaluate`` and
        ``slip_gradient``; c = mu_g w (n,)."""
        K = (np.einsum("kni,knj->knij", tan, phi[..., None] * dp
                       + (p * dphi / self.gamma_crit)[..., None] * dgamma)
             + (p * phi)[..., None, None] * dtan)                        # dF/dx (3, n, 2, 2)
        return -c[:, None, None] * K.sum(axis=0)                         # residual: -F

    def jacobian_values(self, t, u, udot, shift):
        p, dp, tan, dtan, _, rel, _, phi, dphi = self._evaluate(t, u)
        K = self.force_jacobian(p, dp, tan, dtan, self.slip_gradient(tan, dtan, rel), phi,
                                dphi, self.mu(t) * self.groove.w)
        return np.concatenate([K[:, 0, 0], K[:, 0, 1], K[:, 1, 0], K[:, 1, 1]])
