"""Friction on the groove walls with its anchors as TS unknowns: the walls' history under
TS error control, with the rod's viscoplastic return (:mod:`.slip_state_friction`).

:class:`.groove_friction.GrooveFriction` gives each groove node an anchor a_i (an (r, z)
pair) and the force of slot k (the bottom or a corner arc, the side walls)

    F_k,i = mu_g p_k(x_i) w_i phi(gamma_k,i / gamma_crit) t_k(x_i),
    gamma_k,i = -t_k(x_i) . (u_i - a_i),

and moves the anchors after each accepted step so that no touched slot's |gamma| exceeds
gamma_crit (and sets the others' slips to zero). Here the anchors are the
``groove_anchor`` field (two unknowns per groove node), and each touched slot's excess over
gamma_crit flows off with the rod's relaxation time eta
(:func:`.slip_state_friction.relaxation_time`):

    da_i/dt = -sum_k omega_k,i psi(gamma_k,i) t_k(x_i) / eta,
    psi(gamma) = sgn(gamma) max(|gamma| - gamma_crit, 0)                   (mm/s),
    omega_k,i = p_k / (p_k + p_open)     (1 on a touched slot, 0 off it),

p_open the slot pressure at the gap ``open_gap`` delta (GrooveFriction's touch). Since
d gamma_k / d a = t_k, a touched slot's slip obeys d gamma_k/dt = (its rate from the
node's motion) - psi(gamma_k) / eta where the touched slots' tangents are orthogonal (a
flat wall alone, a sharp corner's bottom and side wall); in general the anchor follows the
gradient flow of sum_k omega_k Psi(gamma_k) (Psi' = psi, convex). A node that sticks
keeps its anchor (psi = 0); one that slides carries it along at gamma_crit plus the
overshoot |rate| eta, where phi is saturated and its force exactly the Coulomb limit.

Why the touch weight: with every slot flowing, the slots a node does not touch held its
anchor within gamma_crit along their tangents too. On a corner arc or a wall's rounded
edge (the tangent turning, the side walls' e_r beside it) they moved the anchor of a node
that sticks there: at 30 MPa the net leakage came out well above the return mapping's,
and at an extrusion gap Newton worked much harder (benchmarks/stroke_sensitivity.md).

Landing. Off the walls a node's anchor stands still (omega ~ 0). A slot that a node lands
on starts from zero elastic slip, as with the return mapping (ABAQUS's contact onset): a TS
event per slot and node, located where the slot's gap falls below ``open_gap`` delta,

    open_gap - g / delta = 0   crossing upwards,   g / delta = -ln(expm1(p / (k delta)))

(the softplus penalty inverted), moves the anchor along that slot's tangent to zero its
slip, a_i <- a_i - gamma_k,i t_k. A node that passes from one slot to the next with the
same tangent (an arc to its wall) keeps its slip.

Exact Jacobian, with the TS shift a = dU'/dU, per node (2x2 blocks; the force block dF/du
is GrooveFriction's, and the residual carries -F):

    d(-F)/da  = -mu_g w sum_k p_k phi_k' / gamma_crit t_k t_k^T,
    dR_a/da   = a I + sum_k omega_k psi_k' t_k t_k^T / eta,
    dR_a/du   = sum_k (omega_k psi_k' t_k (d gamma_k/dx)^T + omega_k psi_k dt_k/dx
                       + psi_k omega_k'(p_k) t_k (dp_k/dx)^T) / eta,
    d gamma_k/dx = -t_k - (dt_k/dx)^T (u - a).
"""
import numpy as np

from .groove_friction import GrooveFriction, groove_surfaces
from .slip_state_friction import excess, relaxation_time


class GrooveStateFriction(GrooveFriction):
    """GrooveFriction whose anchors are TS unknowns ``adofs`` ((n, 2): the (r, z) anchor of
    each groove node), integrated with the return of the module docstring."""

    history_names = ()

    def __init__(self, groove, adofs, mu=0.1, gamma_crit=1e-4, v_ref=1.0, blend=0.5):
        """``groove``, ``mu``, ``gamma_crit``, ``blend``: as GrooveFriction; ``adofs``: the
        anchors' dofs per groove node; ``v_ref`` (mm/s): the rod's largest speed, which sets
        eta as for the rod's slips."""
        super().__init__(groove, mu=mu, gamma_crit=gamma_crit, blend=blend)
        self.ad = np.asarray(adofs, np.int64)
        if self.ad.shape != (groove.nodes.size, 2):
            raise ValueError("adofs must give an (r, z) anchor dof pair per groove node")
        self.eta = relaxation_time(gamma_crit, v_ref)
        ur, uz = groove.ur, groove.uz
        ar, az = self.ad[:, 0], self.ad[:, 1]
        # the blocks (u, u) as GrooveFriction, then (u, a), (a, a) and (a, u), each row-major
        self.rows = np.concatenate([ur, ur, uz, uz, ur, ur, uz, uz,
                                    ar, ar, az, az, ar, ar, az, az]).astype(np.int64)
        self.cols = np.concatenate([ur, uz, ur, uz, ar, az, ar, az,
                                    ar, az, ar, az, ur, uz, ur, uz]).astype(np.int64)

    def touch(self, p):
        """The weight of each slot's flow, omega = p / (p + p_open), and d omega/dp: 1 on a
        touched slot, 0 off it."""
        d = 1.0 / (p + self.p_open)
        return p * d, self.p_open * d * d

    def _anchors(self, u):
        return np.asarray(u, float)[self.ad]

    def reset(self, t, u):
        """Zero elastic slip on every wall: sets the anchors in u to the nodes'
        displacements (in place)."""
        u[self.ad] = self._disp(u)

    def accepted(self, t, u):
        """No hook: TS integrates the anchors."""

    # ---- landing events --------------------------------------------------------------------
    @property
    def event_directions(self):
        return (1,) * (3 * self.groove.nodes.size)

    def event_values(self, t, u):
        """Per slot and node (slot-major): open_gap - g / delta (module docstring), from the
        slot's pressure."""
        p = groove_surfaces(self.groove, t, u)[0]
        x = p / (self.groove.k * self.groove.delta)
        lg = np.where(x > 30.0, x, np.log(np.maximum(np.expm1(np.minimum(x, 30.0)), 1e-300)))
        return (self.open_gap + lg).ravel()

    def event(self, t, u, which):
        """Slots landed on: zero their elastic slip, a_i <- a_i - gamma_k,i t_k (in u),
        unless the node touches another slot along the same tangent (it passed from an arc
        to its wall and keeps its slip)."""
        p, _, tan, _, _, _, gamma, _, _ = self._evaluate(t, u)
        n = self.groove.nodes.size
        a = np.asarray(u, float)[self.ad]
        for k, i in zip(*np.divmod(np.asarray(which, np.int64), n)):
            others = [j for j in range(3) if j != k and p[j, i] > self.p_open]
            if any(abs(tan[j, i] @ tan[k, i]) > 0.5 for j in others):
                continue
            a[i] -= gamma[k, i] * tan[k, i]
        u[self.ad] = a

    # ---- Term interface --------------------------------------------------------------------
    def add_residual(self, t, u, udot, f):
        p, _, tan, _, _, _, gamma, phi, _ = self._evaluate(t, u)      # once per residual
        self.subtract_forces(self.slot_forces_of(t, p, tan, phi).sum(axis=0), f)
        psi, _ = excess(gamma, self.gamma_crit)
        w, _ = self.touch(p)
        rate = np.einsum("kn,kni->ni", w * psi, tan) / self.eta
        adot = 0.0 if udot is None else udot[self.ad]
        np.add.at(f, self.ad, adot + rate)

    def jacobian_values(self, t, u, udot, shift):
        p, dp, tan, dtan, _, rel, gamma, phi, dphi = self._evaluate(t, u)
        c = self.mu(t) * self.groove.w
        tt = np.einsum("kni,knj->knij", tan, tan)                          # (3, n, 2, 2)
        dgamma = self.slip_gradient(tan, dtan, rel)
        K_uu = self.force_jacobian(p, dp, tan, dtan, dgamma, phi, dphi, c)
        K_ua = -c[:, None, None] * np.einsum("kn,knij->nij",
                                             p * dphi / self.gamma_crit, tt)
        psi, dpsi = excess(gamma, self.gamma_crit)
        w, dw = self.touch(p)
        K_aa = (shift * np.eye(2)[None] + np.einsum("kn,knij->nij", w * dpsi, tt) / self.eta)
        K_au = (np.einsum("kn,kni,knj->nij", w * dpsi, tan, dgamma)
                + np.einsum("kn,knij->nij", w * psi, dtan)
                + np.einsum("kn,kni,knj->nij", psi * dw, tan, dp)) / self.eta
        return np.concatenate([np.concatenate([K[:, 0, 0], K[:, 0, 1], K[:, 1, 0], K[:, 1, 1]])
                               for K in (K_uu, K_ua, K_aa, K_au)])
