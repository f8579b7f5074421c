"""Rod friction with its elastic slip as a TS unknown: the paper's regularised Coulomb law
(Eq. 46-48) in rate form, so that TS's error control and step rejection see the history.

The paper's (and ABAQUS's) law is an elastic slip z in series with a Coulomb slider. The
force is the anchored law's (:mod:`sealts.contact.friction`, Eq. 45-46 lumped as the normal
force), with z_i one unknown per rod-side node (the ``rod_slip`` field):

    F_i = mu_s(t) p_s(h_i) A L_i phi(z_i / gamma_crit)          (N, +z on the seal),

phi :func:`sealts.contact.friction.saturation`: the stick law x up to 1 - blend, exactly
sign(x) (the Coulomb limit) from |x| = 1 on, C1 between. The slider is a viscoplastic
return (Duvaut and Lions 1972; the rate form of a return mapping): the slip follows the
rod's motion over the node, and whatever exceeds gamma_crit flows off with relaxation time
eta,

    dz_i/dt = w_i - psi(z_i) / eta,      w_i = v(t) - du_z,i/dt    (mm/s),
    psi(z)  = sgn(z) max(|z| - gamma_crit, 0).

* Stick (|z| < gamma_crit): psi = 0, z moves with the rod over the node; its force is the
  paper's stick stiffness mu_s p_s / gamma_crit (up to the blend). Nothing creeps: a rod
  at rest (w = 0) leaves the friction locked in, whatever its value.
* Slide: z settles at sgn(w) (gamma_crit + |w| eta), where phi is saturated, so the force is
  exactly mu_s p_s A L_i, whatever the overshoot |w| eta.
* Unloading after a reversal starts once the overshoot has flowed off. Under a smooth
  reversal (a sine) z follows |w| eta down to gamma_crit as w falls, a lag of order eta in
  time; after an abrupt reversal from w to -w the lag is a slip of |w| eta ln 2.
* eta = delta / v_ref (``overshoot`` delta = 0.1 gamma_crit at v_ref, the stroke's largest
  rod speed): the overshoot and the abrupt reversal's lag stay below 0.1 gamma_crit of
  slip, a tenth of the stick range.
* As eta -> 0 this is the anchored law: :meth:`sealts.contact.friction.RodFriction.update`
  is the same return (the anchor a_i = s - u_z,i - z_i), applied after each step instead of
  inside it.

Why not a Bouc-Wen law (dz/dt = w (1 - |x|^n) while loading): its rate switches between
loading and unloading with the sign of w x. At the edge of a sticking zone w crosses zero
between Newton iterates and the solve cycled between two states to the iteration limit
(twice the Newton iterations of the anchors on the coarse cycle;
benchmarks/stroke_sensitivity.md). Here w enters linearly and the only switch, |z| =
gamma_crit, lies where phi is already saturated.

Nodes out of contact keep integrating z (their force is zero): a node that touches a
sliding rod slides at once. The z rows are in mm/s. Exact Jacobian (TS shift a = dU'/dU;
k = mu_s A):

    d(z' - w + psi/eta)/dz_i   = a + [|z_i| > gamma_crit] / eta,
    d(z' - w + psi/eta)/du_z,i = a                          (dw/du_z,i' = -1),
    d(-F_i)/d(u_r,i, u_z,hi, u_z,lo, z_i) = -k (dp L phi, p phi / 2, -p phi / 2,
                                                p L phi' / gamma_crit).
"""
import numpy as np

from ..core import Term, of_time
from .friction import check_law, saturation

OVERSHOOT = 0.1          # delta / gamma_crit: the slide's overshoot at the largest rod speed


def excess(z, gamma_crit):
    """psi(z) = sgn(z) max(|z| - gamma_crit, 0) (mm) and psi'(z) (module docstring)."""
    over = np.abs(z) - gamma_crit
    flowing = over > 0.0
    return np.where(flowing, np.sign(z) * over, 0.0), flowing.astype(float)


def return_rate(w, z, gamma_crit, eta):
    """g = dz/dt (mm/s) of the module docstring at slip rate w (mm/s) and slip z (mm), and
    dg/dz (dg/dw is 1)."""
    psi, dpsi = excess(z, gamma_crit)
    return w - psi / eta, -dpsi / eta


def relaxation_time(gamma_crit, v_ref):
    """eta (s): the overshoot OVERSHOOT gamma_crit at the rod speed v_ref (mm/s; a rod at
    rest, v_ref = 0, takes 1 mm/s)."""
    v = abs(float(v_ref))
    return OVERSHOOT * gamma_crit / (v if v > 0.0 else 1.0)


class SlipStateFriction(Term):
    """Rod friction whose elastic slips ``zdofs`` (one per chain node) are TS unknowns
    (module docstring). Adds the friction to the u_z rows of the contact's chain and owns
    the z rows."""

    def __init__(self, contact, velocity, zdofs, mu_s=0.1, gamma_crit=1e-4, v_ref=1.0,
                 blend=0.5):
        """``contact``: the :class:`sealts.contact.rigid.RodContact` (asperity pressure, rod
        side); ``velocity``: v(t), the rod's axial velocity (mm/s, +z); ``zdofs``: the dofs
        of z_i in chain order; ``mu_s`` (number or function of t); ``gamma_crit`` (mm);
        ``v_ref`` (mm/s): the largest rod speed, which sets eta (:func:`relaxation_time`);
        ``blend``: phi's stick-to-slide blend, as RodFriction."""
        check_law(gamma_crit, blend)
        self.contact = contact
        self.side = sd = contact.side
        self.v = of_time(velocity)
        self.mu = of_time(mu_s)
        self.gamma_crit, self.blend = float(gamma_crit), float(blend)
        self.eta = relaxation_time(gamma_crit, v_ref)
        self.zd = np.asarray(zdofs, np.int64)
        if self.zd.shape != (sd.m,):
            raise ValueError("zdofs must give one slip dof per chain node")
        uz, zd = sd.uz, self.zd
        self.rows = np.concatenate([uz, uz, uz, uz, zd, zd]).astype(np.int64)
        self.cols = np.concatenate([sd.ur, uz[sd.hi], uz[sd.lo], zd, zd, uz]).astype(np.int64)
        # the friction work's row (sealts.contact.friction_work), when attached: the
        # columns of the forces
        self.work, self.work_cols = None, self.cols[:4 * sd.m].copy()

    # ---- state -----------------------------------------------------------------------------
    def slip(self, t, u):
        """The elastic slips z_i (mm)."""
        return np.asarray(u[self.zd], float)

    def stress(self, t, u):
        """Asperity shear stress on the seal (MPa, +z), mu_s p_s phi(z / gamma_crit)."""
        p, _ = self.contact.pressure(t, u)
        return self.mu(t) * p * saturation(u[self.zd] / self.gamma_crit, self.blend)[0]

    def forces(self, t, u):
        """Axial friction force on each chain node (N, +z on the seal)."""
        return self.stress(t, u) * self.side.area * self.side.lengths(u)

    def total(self, t, u):
        """Total axial friction force on the seal (N, +z)."""
        return float(self.forces(t, u).sum())

    def reset(self, t, u):
        """Zero elastic slip at every node: sets the z entries of u (in place)."""
        u[self.zd] = 0.0

    def rates(self, t, u, udot):
        """(g, dg/dz) of every node at (u, u')."""
        w = self.v(t) - (0.0 if udot is None else udot[self.side.uz])
        return return_rate(w + np.zeros(self.side.m), u[self.zd], self.gamma_crit, self.eta)

    # ---- Term interface --------------------------------------------------------------------
    def add_residual(self, t, u, udot, f):
        F = self.forces(t, u)
        np.subtract.at(f, self.side.uz, F)
        if self.work is not None:
            f[self.work[0]] -= self.work[1](t) * F.sum()
        g = self.rates(t, u, udot)[0]
        zdot = 0.0 if udot is None else udot[self.zd]
        np.add.at(f, self.zd, zdot - g)

    def jacobian_values(self, t, u, udot, shift):
        p, dp = self.contact.pressure(t, u)
        sd = self.side
        L = sd.lengths(u)
        phi, dphi = saturation(u[self.zd] / self.gamma_crit, self.blend)
        k = self.mu(t) * sd.area
        _, dg_dz = self.rates(t, u, udot)
        a = shift
        force = np.concatenate([-k * dp * L * phi, -k * p * sd.half * phi,
                                k * p * sd.half * phi, -k * p * L * dphi / self.gamma_crit])
        vals = [force, a - dg_dz, np.full(sd.m, a)]
        if self.work is not None:
            vals.append(self.work[1](t) * force)                  # d(-v sum F)
        return np.concatenate(vals)
