"""The paper's film discretisation: weighted pressure-gradient integration (Eq. 15-28).

Reynolds' equation is linear in p for given h, so the film pressure is the sum of a
hydrostatic part (v = 0, dh/dt = 0, p_in -> p_out) and a hydrodynamic part (p = 0 at both
ends). Integrated once, their gradients are (Eq. 17 and Eq. 24)

    g_hs(y) = 12 eta / (Phi_p h^3) c0,
    g_hd(y) = 6 eta / (Phi_p h^3) [ v (h - h0 - Rq (Phi_s - Phi_s0)) + 2 int_{y0}^{y} dh/dt ],

with c0 the pressure-driven flow and y0 the point of zero hydrodynamic gradient,
h0 = h(y0), Phi_s0 = Phi_s(h0). For a uniform squeeze velocity the last integral is the
paper's 2 (du/dt)(y - y0); sealts integrates a nodal dh/dt with the trapezoid rule.

Unknowns x = (p_1 .. p_n, c0, y0). Equations (the y0 row carries a tiny anchor
Y0_ANCHOR (y0 - y_mid), MPa/mm: without sliding and squeeze the hydrodynamic part vanishes
for every y0, the pure hydrostatic film of the pressurisation step, and the anchor keeps the
Newton matrix regular; with hydrodynamics it moves y0 by ~1e-12 of its sensitivity):

* p_1 = p_in;
* p_i = p_{i-1} + dy_i [alpha g_{i-1} + (1 - alpha) g_i],  g = g_hs + g_hd  (Eq. 27);
* the hydrostatic integral spans p_in -> p_out and the hydrodynamic one 0 -> 0, which is
  the outlet condition p_n = p_out (Eq. 28) split into the two equations fixing c0 and y0.

The flow per unit circumference is q(y) = -c0 + (v/2)(h0 - Rq Phi_s0) - int_{y0}^{y} dh/dt
(Eq. 40 at y = y0). Film thickness enters through the same h_eff regularisation as the default
scheme. With a rigid film the Jacobian is sparse (two dense columns for c0, y0); coupled to a
deforming seal every pressure depends on all upstream thicknesses, which is why the
control-volume scheme is the default.
"""
import numba
import numpy as np

from .flow_factors import flow_factors
from .gap import h_eff, smooth_floor
from .reynolds_fv import PHI_P_MIN

Y0_ANCHOR = 1e-12


@numba.njit(cache=True)
def gradients(y, h, hd, c0, y0, v, eta, h_floor, model, par, th, tpp, tps):
    """Nodal g_hs, g_hd and their derivatives with respect to c0 and y0; plus q and dq."""
    n = y.size
    rq = -par[10] * par[0]  # Rq for a rough seal (Eq. 24 as printed), -Rq for a rough rod
    he = np.empty(n)
    w = np.empty(n)
    ps = np.empty(n)
    s = np.empty(n)  # cumulative int_{y_1}^{y_i} dh_eff/dt
    hde = np.empty(n)
    for i in range(n):
        he[i], dhe = h_eff(h[i], h_floor)
        pp, _, ps[i], _ = flow_factors(h[i], model, par, th, tpp, tps)
        pp = smooth_floor(pp, PHI_P_MIN)[0]
        w[i] = 12.0 * eta / (pp * he[i] ** 3)
        hde[i] = dhe * hd[i]
    s[0] = 0.0
    for i in range(1, n):
        s[i] = s[i - 1] + 0.5 * (y[i] - y[i - 1]) * (hde[i - 1] + hde[i])
    # y0 inside element j (linear extrapolation beyond the ends)
    j = np.searchsorted(y, y0) - 1
    j = min(max(j, 0), n - 2)
    L = y[j + 1] - y[j]
    tt = (y0 - y[j]) / L
    slope = (h[j + 1] - h[j]) / L
    h0raw = h[j] + tt * (h[j + 1] - h[j])
    h0, dh0 = h_eff(h0raw, h_floor)
    _, _, ps0, dps0 = flow_factors(h0raw, model, par, th, tpp, tps)
    hd0 = hde[j] + tt * (hde[j + 1] - hde[j])
    s0 = s[j] + L * (tt * hde[j] + 0.5 * tt * tt * (hde[j + 1] - hde[j]))
    dh0_dy0 = dh0 * slope
    dps0_dy0 = dps0 * slope

    ghs = w * c0
    ghd = np.empty(n)
    dghd = np.empty(n)
    for i in range(n):
        ghd[i] = 0.5 * w[i] * (v * (he[i] - h0 - rq * (ps[i] - ps0)) + 2.0 * (s[i] - s0))
        dghd[i] = 0.5 * w[i] * (-v * (dh0_dy0 - rq * dps0_dy0) - 2.0 * hd0)
    qy0 = -c0 + 0.5 * v * (h0 - rq * ps0)
    q = qy0 - (s - s0)
    dq_dy0 = 0.5 * v * (dh0_dy0 - rq * dps0_dy0) + hd0
    return w, ghs, ghd, dghd, q, dq_dy0


class PaperScheme:
    """The paper's scheme: unknowns (p_1..p_n, c0, y0); same interface as the default."""

    name = "paper"

    def __init__(self, y, eta, v_of_t, p_in, p_out, ff, h_floor, alpha=0.5):
        self.y = np.asarray(y, float)
        self.n = self.y.size
        self.size = self.n + 2
        self.eta, self.v_of_t, self.ff, self.h_floor = eta, v_of_t, ff, h_floor
        self.p_in, self.p_out, self.alpha = p_in, p_out, alpha
        n = self.n
        i = np.arange(1, n)
        ic, iy = n, n + 1
        rows = [np.array([0]), i, i, i, i, np.full(n - 1, ic), np.full(n - 1, iy)]
        cols = [np.array([0]), i, i - 1, np.full(n - 1, ic), np.full(n - 1, iy),
                np.full(n - 1, ic), np.full(n - 1, iy)]
        self.pattern = (np.concatenate(rows), np.concatenate(cols))
        self.q_cols = (np.array([ic, iy]), np.array([ic, iy]))
        self.dy = np.diff(self.y)

    def _grad(self, t, x, h, hd):
        f = self.ff
        return gradients(self.y, h, hd, x[self.n], x[self.n + 1], self.v_of_t(t), self.eta,
                         self.h_floor, f.model, f.par, f.table_h, f.table_pp, f.table_ps)

    def set_row_scale(self, t, x, h, hd):
        """Rows are pressure differences in MPa already."""

    def _weighted(self, g):
        a = self.alpha
        return self.dy * (a * g[:-1] + (1.0 - a) * g[1:])

    def residual(self, t, x, h, hd):
        n = self.n
        p = x[:n]
        w, ghs, ghd, _, q, _ = self._grad(t, x, h, hd)
        r = np.empty(self.size)
        r[0] = p[0] - self.p_in
        r[1:n] = p[1:] - p[:-1] - self._weighted(ghs + ghd)
        r[n] = self._weighted(ghs).sum() - (self.p_out - self.p_in)
        y_mid = 0.5 * (self.y[0] + self.y[-1])
        r[n + 1] = self._weighted(ghd).sum() + Y0_ANCHOR * (x[n + 1] - y_mid)
        return r, q[0], q[-1]

    def jacobian(self, t, x, h, hd):
        n = self.n
        w, _, _, dghd, _, dq_dy0 = self._grad(t, x, h, hd)
        dc = self._weighted(w)
        dy0 = self._weighted(dghd)
        one = np.ones(n - 1)
        vals = np.concatenate([[1.0], one, -one, -dc, -dy0, dc, dy0])
        vals[-1] += Y0_ANCHOR  # the (y0, y0) entry is the last of the pattern
        dq = np.array([-1.0, dq_dy0])
        return vals, (dq, dq)

    def pressure(self, x):
        return np.asarray(x[:self.n])

    def pressure_gradient(self, t, x, h, hd):
        _, ghs, ghd, _, _, _ = self._grad(t, x, h, hd)
        return ghs + ghd

    def initial_guess(self):
        return np.concatenate([np.linspace(self.p_in, self.p_out, self.n),
                               [0.0, 0.5 * (self.y[0] + self.y[-1])]])
