"""Solid (asperity) friction on the seal's rod side, paper Eq. 46-48.

The paper's law is Coulomb friction with a penalty regularisation: the asperity shear stress

    tau_s = mu_s p_s gamma / gamma_crit     |gamma| <= gamma_crit   (stick, elastic slip)
    tau_s = mu_s p_s sign(gamma)            |gamma| >  gamma_crit   (slide)

with gamma the tangential slip and p_s(h) the asperity pressure of Eq. 44. Lumped on the
rod-side nodes like the normal force (Eq. 45), it gives node i the axial force

    F_i = tau_s,i A L_i,     L_i = (z_{i+1} - z_{i-1}) / 2   (current axial positions),

p_s from :class:`sealts.contact.rigid.RodContact`, A and L_i from its rod side
(:class:`sealts.contact.rod_side.RodSide`), exactly as the normal force. Sign: F_i > 0
pushes the seal in +z; a rod moving in +z drags the seal along (gamma > 0, F > 0).

Slip with a history anchor (elastic-slip, "penalty" friction as in ABAQUS): the rod's axial
displacement s(t) (mm, e.g. the integral of v(t); +z for v > 0) against node i's own,

    gamma_i(t, u) = s(t) - u_z,i - a_i,

a_i a per-node anchor (:meth:`reset` zeroes the elastic slip; sliding then moves it).
Within a step the anchors are fixed and the stress is the smooth version of the law above,

    tau_s,i = mu_s(t) p_s(h_i) phi(gamma_i / gamma_crit),

phi odd and C1, with (x0 = 1 - ``blend``, s = (|x| - x0) / blend)

    phi(x) = x                                    |x| <= x0      (the paper's stick law)
    phi(x) = sign(x) (x0 + blend (s + s^2 - s^3))  x0 < |x| < 1
    phi(x) = sign(x)                              |x| >= 1       (the paper's Coulomb law)

phi'(x) = 1 + 2 s - 3 s^2 in the blend: 1 at x0, 0 at |x| = 1, at most 4/3 (at s = 1/3),
never negative, so phi rises monotonically to exactly 1 and |phi| <= 1. The law is the
paper's, stick stiffness mu_s p_s / gamma_crit included, except in the band
x0 < |gamma| / gamma_crit < 1, where phi lies above min(|x|, 1) by at most 4/27 ``blend``
(0.074 for the default 0.5). Why not tanh or a blend around the kink: saturation at exactly
|gamma| = gamma_crit is what lets the anchor update below leave the forces untouched; a phi
that is still below 1 at gamma_crit would lose force at every update (tanh: 24 %), one
rounding the corner beyond gamma_crit would need the anchor to keep more than gamma_crit.

Anchor update (return mapping), between time steps: after each accepted step,
:meth:`update` moves the anchors so that the elastic slip is capped, keeping its sign,

    gamma_i <- clip(gamma_i, -gamma_crit, gamma_crit),   a_i <- s(t) - u_z,i - gamma_i,

so a node that slid keeps its slip beyond gamma_crit as sliding (a_i moves) and stays on the
Coulomb limit. Where |gamma_i| > gamma_crit phi is already saturated, so the update changes
neither the residual nor the Jacobian at the accepted state: the equilibrium stands, and a
rod that slid and stopped leaves the friction locked in at mu_s p_s (no relaxation). Nodes
out of contact (p_s = 0, h >= h_mix) restart from zero elastic slip (ABAQUS resets it when
contact opens; there the force is zero either way). As with the pressure-penetration front
(:mod:`sealts.solid.pressure`), each Newton solve thus sees a fixed, smooth law, and the
history is advanced by the TS post-step monitor, never inside a step (rejected steps leave
it alone).

What this costs: within one step the law is the backward-Euler (implicit) return mapping of
the regularised Coulomb law, evaluated at the end of the step only, so it is path-
independent over the step: a slip that reverses inside one step (a stroke reversal
between t_n and t_n+1, a node that slides forward and back) is taken as its net increment,
and the friction dissipated within the step is not resolved. The error is first order in
the step's slip increment and vanishes where no step straddles a reversal: stop the time
stepper at the rod's reversals (:meth:`sealts.contact.rod_motion.RodMotion.reversals`,
whose ``s`` is the slip function this term wants). The anchors are also outside the TS
error estimate (as the front is), so step size control does not see them.

Newton: a node whose iterate lies beyond |gamma| = gamma_crit has no friction stiffness
(phi' = 0), so a predictor that puts the whole contact patch into sliding leaves the seal's
axial and rolling modes to the solid and the walls alone. Measured on the coarse mounted
O-ring, rod moved 0.3 mm in the stabilised quasi-static driver (frictionless groove): the
state is reached (static solve converges, axial forces balance), but 51 of 112 steps were
rejected, 667 Newton iterations in all (line search basic; bt: 17 of 49 rejected, 859
iterations; without friction: 8 steps, none rejected). The rejections inspected were
DIVERGED_FUNCTION_NANORINF: a first full Newton step of up to 0.4 mm that left the solid
non-finite.

gamma_crit: 1e-4 mm (0.1 um) by default, a scene-free choice: 1 % of the paper's contact
element size (0.01 mm), where ABAQUS's default would be 0.5 % of it (5e-5 mm); half the
roughness Rq = 0.215 um. The stick stiffness per area mu_s p_s / gamma_crit (5e3 MPa/mm at
p_s = 5 MPa, mu_s = 0.1) is then some 1e4 times the O-ring's own shear stiffness per area
(G / d2 ~ 2 MPa / 5 mm), so sticking nodes are held all but rigidly.

``mu_s(t)`` may be a function (the paper ramps it from 0 to mu_s during pressurisation).
"""
import numpy as np

from ..core import Term, of_time


def saturation(x, blend=0.5):
    """phi(x) and phi'(x) (module docstring): x up to 1 - blend, sign(x) beyond 1, C1."""
    x = np.asarray(x, float)
    ax = np.abs(x)
    sg = np.sign(x)
    x0 = 1.0 - blend
    s = np.clip((ax - x0) / blend, 0.0, 1.0)
    phi = np.where(ax <= x0, x, sg * (x0 + blend * (s + s * s - s**3)))
    dphi = np.where(ax <= x0, 1.0, 1.0 + 2.0 * s - 3.0 * s * s)
    return phi, dphi



def check_law(gamma_crit, blend):
    """The elastic-slip law's parameters (ValueError naming the bad one)."""
    if not 0.0 < blend <= 1.0:
        raise ValueError(f"blend must lie in (0, 1], got {blend}")
    if gamma_crit <= 0.0:
        raise ValueError(f"gamma_crit must be positive, got {gamma_crit}")


class RodFriction(Term):
    """Asperity friction on the u_z rows of the rod-side chain (module docstring).

    Owns no rows of its own: adds to the u_z rows of ``contact``'s chain nodes. Columns: the
    node's own u_r (through p_s(h)), its own u_z (through the slip) and its chain
    neighbours' u_z (through L_i).
    """

    def __init__(self, contact, slip, mu_s=0.1, gamma_crit=1e-4, blend=0.5, anchors=None):
        """``contact``: the :class:`sealts.contact.rigid.RodContact` whose asperity pressure
        (and rod side: chain, lengths, A) the friction uses; ``slip``: s(t), the rod's axial
        displacement (mm, +z; number or function of t); ``mu_s``: the friction coefficient
        (number or function of t); ``gamma_crit``: the elastic slip at which friction
        reaches mu_s p_s (mm); ``blend``: the fraction of gamma_crit over which phi turns
        from stick to slide (0 < blend <= 1); ``anchors``: initial a_i (mm, default 0; see
        :meth:`reset`)."""
        check_law(gamma_crit, blend)
        self.contact = c = contact
        self.s = of_time(slip)
        self.mu = of_time(mu_s)
        self.gamma_crit, self.blend = float(gamma_crit), float(blend)
        self.side = sd = c.side
        m = sd.m
        self.anchors = np.zeros(m) if anchors is None else np.array(anchors, float)
        if self.anchors.shape != (m,):
            raise ValueError("anchors must give one value per chain node")
        uz = sd.uz
        # d(-F_i)/d: u_r,i (p_s), u_z of the upper and lower neighbour (L_i), u_z,i (gamma)
        self.rows = np.concatenate([uz, uz, uz, uz]).astype(np.int64)
        self.cols = np.concatenate([sd.ur, uz[sd.hi], uz[sd.lo], uz]).astype(np.int64)
        # the friction work's row (sealts.contact.friction_work), when attached
        self.work, self.work_cols = None, self.cols.copy()

    # ---- state -----------------------------------------------------------------------------
    def slip(self, t, u):
        """gamma_i = s(t) - u_z,i - a_i (mm)."""
        return self.s(t) - u[self.side.uz] - self.anchors

    def _evaluate(self, t, u):
        p, dp = self.contact.pressure(t, u)
        L = self.side.lengths(u)
        phi, dphi = saturation(self.slip(t, u) / self.gamma_crit, self.blend)
        return p, dp, L, phi, dphi

    def stress(self, t, u):
        """Asperity shear stress tau_s,i on the seal (MPa, +z)."""
        p, _, _, phi, _ = self._evaluate(t, u)
        return self.mu(t) * p * phi

    def forces(self, t, u):
        """Axial friction force on each chain node (N, +z on the seal), F_i = tau_s,i A L_i."""
        p, _, L, phi, _ = self._evaluate(t, u)
        return self.mu(t) * p * phi * self.side.area * L

    def total(self, t, u):
        """Total axial friction force on the seal (N, +z)."""
        return float(self.forces(t, u).sum())

    # ---- history ---------------------------------------------------------------------------
    def reset(self, t, u):
        """Zero elastic slip at every node: a_i = s(t) - u_z,i (e.g. when friction starts,
        after the frictionless mounting)."""
        self.anchors = self.s(t) - np.asarray(u, float)[self.side.uz]

    def update(self, t, u):
        """Return mapping after an accepted step at (t, u): cap |gamma_i| at gamma_crit
        (keeping its sign; zero where the node is out of contact) by moving the anchors.
        Returns the largest slide of a node in contact in this update (mm; the open nodes'
        anchors follow the rod and are not counted)."""
        u = np.asarray(u, float)
        gamma = self.slip(t, u)
        kept = np.clip(gamma, -self.gamma_crit, self.gamma_crit)
        p, _ = self.contact.pressure(t, u)
        touching = p > 0.0
        kept[~touching] = 0.0
        new = self.s(t) - u[self.side.uz] - kept
        moved = np.abs(new - self.anchors)[touching]
        self.anchors = new
        return float(moved.max()) if moved.size else 0.0

    history_names = ("anchors",)

    def accepted(self, t, u):
        """Post-step hook: the return mapping of ``update``."""
        self.update(t, u)

    # ---- Term interface --------------------------------------------------------------------
    def add_residual(self, t, u, udot, f):
        F = self.forces(t, u)
        np.subtract.at(f, self.side.uz, F)
        if self.work is not None:
            f[self.work[0]] -= self.work[1](t) * F.sum()

    def jacobian_values(self, t, u, udot, shift):
        p, dp, L, phi, dphi = self._evaluate(t, u)
        k = self.mu(t) * self.side.area
        half = self.side.half
        # F = k p(h) L phi(gamma / gamma_crit); the residual subtracts F
        vals = -np.concatenate([k * dp * L * phi,
                                k * p * half * phi,
                                -k * p * half * phi,
                                -k * p * L * dphi / self.gamma_crit])
        if self.work is None:
            return vals
        return np.concatenate([vals, self.work[1](t) * vals])    # d(-v sum F)
