"""Rod friction with its elastic slip as a TS unknown: the paper's regularised Coulomb law
(Eq. 46-48) in rate form, so that TS's error control and step rejection see the history.

The paper's (and ABAQUS's) law is an elastic slip z in series with a Coulomb slider: the
asperity shear stress is mu_s p_s z / gamma_crit while |z| < gamma_crit (stick), the slider
slides once |z| reaches gamma_crit. :mod:`sealts.contact.friction` advances it between
time steps (anchors, a return mapping outside the error estimate). Here z_i is one unknown
per rod-side node (the ``rod_slip`` field), with the evolution of the Bouc-Wen hysteresis
(Bouc 1967, Wen 1976; the smooth rate form of elastic-perfectly-plastic friction) in its
rate-independent form, x = z / gamma_crit:

    dz_i/dt = w_i - sgn(x) |x|^n max(0, w_i sgn(x))
            = w_i                           unloading (w x < 0) or |x| << 1: stick
            = w_i (1 - |x|^n)               loading (w x > 0): slides as |x| -> 1
    w_i = v(t) - du_z,i/dt                  slip rate of the rod over node i (mm/s)

and the nodal force (Eq. 45-46, lumped as the normal force)

    F_i = mu_s(t) p_s(h_i) A L_i x_i          (N, +z on the seal).

Under monotone loading |x| rises from 0 towards 1 with slope 1 - |x|^n: the
paper's stick stiffness mu_s p_s / gamma_crit at small slip, the Coulomb limit mu_s p_s in
sliding, and a knee between whose width shrinks with n (95 % of the limit after 1.83, 1.30,
1.07 gamma_crit of slip for n = 2, 4, 8; the paper's bilinear law at n -> infinity).
Unloading is elastic with the stick stiffness. A rod at rest (w = 0) leaves z where it is:
the friction stays locked in. The kink of max(0, y) at y = w sgn(x) = 0 is smoothed,

    max_eps(y) = (y + sqrt(y^2 + eps^2) - eps) / 2,

exactly 0 at y = 0 (no creep at rest), y - eps/2 for y >> eps and -eps/2 for y << -eps;
eps (mm/s) is a slip rate far below the rod's. Nodes out of contact keep integrating z
(their force is zero): a node that touches a sliding rod slides at once.

The z rows are in mm/s. Exact Jacobian (with the TS shift a = dU'/dU; m = max_eps at
y = w sgn(x)):

    d(z' - g)/dz_i    = a + n |x|^(n-1) m / gamma_crit,
    d(z' - g)/du_z,i  = a (1 - |x|^n m'(y))       (dw/du_z,i' = -1),
    d(-F_i)/d(u_r,i, u_z,hi, u_z,lo, z_i) = -mu A (dp L x, p x / 2, -p x / 2, p L / gamma_crit).
"""
import numpy as np

from ..core import Term, of_time


def smooth_max0(y, eps):
    """max(0, y) smoothed over eps, y (1 + tanh(y / eps)) / 2: exactly 0 at y = 0, y to
    within exp(-2 y / eps) beyond; and its derivative."""
    th = np.tanh(y / eps)
    return 0.5 * y * (1.0 + th), 0.5 * (1.0 + th) + 0.5 * y * (1.0 - th * th) / eps


def bouc_wen_rate(w, x, n, eps):
    """g = dz/dt (mm/s) of the module docstring at slip rate w (mm/s) and x = z / gamma_crit,
    with dg/dw and dg/dx."""
    sg = np.where(x >= 0.0, 1.0, -1.0)
    ax = np.abs(x)
    m, dm = smooth_max0(w * sg, eps)
    axn1 = ax ** (n - 1)
    g = w - sg * ax * axn1 * m
    dg_dw = 1.0 - ax * axn1 * dm                 # d(sg m)/dw = sg^2 dm = dm
    dg_dx = -n * axn1 * m                        # d(sg |x|^n)/dx = n |x|^(n-1)
    return g, dg_dw, dg_dx


class SlipStateFriction(Term):
    """Rod friction whose elastic slips ``zdofs`` (one per chain node) are TS unknowns
    (module docstring). Adds the friction to the u_z rows of the contact's chain and owns
    the z rows."""

    def __init__(self, contact, velocity, zdofs, mu_s=0.1, gamma_crit=1e-4, n=4, eps=1e-3):
        """``contact``: the :class:`sealts.contact.rigid.RodContact` (asperity pressure, rod
        side); ``velocity``: v(t), the rod's axial velocity (mm/s, +z); ``zdofs``: the dofs
        of z_i in chain order; ``mu_s`` (number or function of t); ``gamma_crit`` (mm);
        ``n``: the Bouc-Wen exponent (the knee's sharpness); ``eps`` (mm/s): the slip rate
        over which the loading switch is smoothed."""
        if gamma_crit <= 0.0:
            raise ValueError(f"gamma_crit must be positive, got {gamma_crit}")
        if n < 1:
            raise ValueError(f"the exponent n must be at least 1, got {n}")
        self.contact = contact
        self.side = sd = contact.side
        self.v = of_time(velocity)
        self.mu = of_time(mu_s)
        self.gamma_crit, self.n, self.eps = float(gamma_crit), float(n), float(eps)
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
        """Asperity shear stress on the seal (MPa, +z), mu_s p_s z / gamma_crit."""
        p, _ = self.contact.pressure(t, u)
        return self.mu(t) * p * u[self.zd] / self.gamma_crit

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
        """(g, dg/dw, dg/dx) of every node at (u, u')."""
        w = self.v(t) - (0.0 if udot is None else udot[self.side.uz])
        return bouc_wen_rate(w + np.zeros(self.side.m), u[self.zd] / self.gamma_crit,
                             self.n, self.eps)

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
        x = u[self.zd] / self.gamma_crit
        k = self.mu(t) * sd.area
        _, dg_dw, dg_dx = self.rates(t, u, udot)
        a = shift
        force = np.concatenate([-k * dp * L * x, -k * p * sd.half * x, k * p * sd.half * x,
                                -k * p * L / self.gamma_crit])
        vals = [force, a - dg_dx / self.gamma_crit, a * dg_dw]
        if self.work is not None:
            vals.append(self.work[1](t) * force)                  # d(-v sum F)
        return np.concatenate(vals)
