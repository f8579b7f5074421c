"""The paper's film scheme on the deforming seal: Eq. 15-28 coupled to the seal (issue 5).

The same film as :class:`sealts.film.seal_film.SealFilmTerm` (the chain of ``rod_side``
vertices, current positions and gaps, the same loads on the seal), discretised as in the
paper (Sections 2.2.1-2.2.3) instead of by control volumes. On chain node i (i = 1..n in
the paper's numbering, ordered by reference z)

    y_i = Z_i + u_z,i                                             (Eq. 25)
    h_i = R_i + u_r,i - r(t)                                      (Eq. 18)
    dh_i/dt = du_r,i/dt - dr/dt                                   (Eq. 26, from the TS's U')

With h_eff the gap regularisation (:mod:`sealts.film.gap`), k = Phi_p h_eff^3 / (12 eta) and
c = (v/2)(h_eff - Rq Phi_s) at h_i (:func:`sealts.film.reynolds_fv.conductance`), the
paper's hydrostatic (Eq. 17) and hydrodynamic (Eq. 24) gradients are

    g_hs,i = c0 / k_i,
    g_hd,i = (c_i - c(h0) + S(y_i) - S(y0)) / k_i,   S(y) = int_{y_1}^{y} dh_eff/dt dy,

(for a uniform squeeze S(y_i) - S(y0) = (dh/dt)(y_i - y0), the 2 (du/dt)(y - y0) of Eq. 24
with its 6 eta, not 12 eta, in front), g_i = g_hs,i + g_hd,i (Eq. 35), and the flow per unit
circumference through y_i is q_i = c_i - k_i g_i = -c0 + c(h0) + S(y0) - S(y_i) (Eq. 40).
dh_eff/dt is linear between nodes, so S(y_i) is the trapezoid sum, the nodal rates times the
default scheme's control volumes.

**The second integration constant.** g_hd, q, p and every load depend on y0 only through
qd = c(h0) + S(y0), the hydrodynamic flow at y0 (Eq. 40's (v/2)(h0 - Rq Phi_s0) plus the
squeeze integral). This term carries qd (mm^2/s) as the unknown instead of y0 (mm):

    g_hd,i = (c_i + S(y_i) - qd) / k_i,    q_i = -c0 + qd - S(y_i).

The discrete pressures are the paper's: for the solution's qd there is a y0 inside the
chain with c(h(y0)) + S(y0) = qd (qd is a positive weighted mean of the nodal c_i + S_i,
the y0 row below, and c(h(y)) + S(y) is continuous along the chain), and every such y0 gives
the same rows. :meth:`SealPaperFilmTerm.zero_gradient_points` returns them. With y0 itself
as the unknown (commit "literally with c0 and y0") the coupled stroke could not start: y0 is
defined only up to the roots of that equation (two on a converging-diverging gap: the
pressure's maximum and its minimum, and Newton hopped between them from step to step), and
at v = 0 with dh/dt = 0 (the hydrostatic start, and nearly so at the first steps of a
stroke) every y0 solves it, so its row's derivative vanishes while its U' derivative (TS
shift) does not: Newton sent y0 off the chain and the first step of the paper's cycle
failed at t = 9e-5 s. qd enters its row linearly, with the coefficient
-sum_i dy_i [alpha / k_i-1 + (1 - alpha) / k_i] < 0, so the row is regular at every state,
qd = 0 at the hydrostatic start, and it is continuous in time.

Accuracy: Eq. 27 integrates g ~ 1/h^3 by nodal values, which overestimates the pressure
change across an element where h grows several-fold (the O-ring's outlet, where the film
opens from 1 um to 10 um within one element); the default scheme's element flux averages
1/k exactly for a steady flow. Measured on the 0.05 mm O-ring mesh's gap at 500 mm/s
(film only, no squeeze): p_max 3.15 MPa and 1166 N against 2.71 MPa and 991 N, the outlet's
negative pressure -0.03 against -0.22 MPa; cut 16 times finer, both give 2.74-2.75 MPa,
1001-1005 N and -0.18 MPa. The paper meshed its contact at 0.01 mm.

Rows (the film's own: the chain's pressures, then c0 and qd), all pressure differences in
MPa (``set_row_scale`` does nothing):

* p_1 = p_first (p_in at the pressurised end, ``pressurised_end = "min_z"``; p_out else);
* p_i - p_{i-1} - dy_i [alpha g_{i-1} + (1 - alpha) g_i] = 0,  dy_i = y_i - y_{i-1}  (Eq. 27);
* Eq. 28 (p_n = p_last) split as in :class:`sealts.film.paper_scheme.PaperScheme`: the
  hydrostatic integral spans p_first -> p_last and the hydrodynamic one 0 -> 0,
  c0 row  sum_i dy_i [alpha g_hs,i-1 + (1 - alpha) g_hs,i] - (p_last - p_first) = 0,
  qd row  sum_i dy_i [alpha g_hd,i-1 + (1 - alpha) g_hd,i] = 0
  (PaperScheme's anchor of y0 is not needed: qd = 0 solves the qd row without hydrodynamics).

Loads on the seal, as :class:`SealFilmTerm` (both inherit the radial and surface-normal parts
from :class:`sealts.film.chain_film.ChainFilm`): F_r,i = p_i A L_i (Eq. 29-31) on u_r; with
``surface_normal`` F_z,i = -p_i A (r_{i+1} - r_{i-1})/2 on u_z; with ``shear`` the fluid
shear (Eq. 32-34)

    tau_i = eta v / h_eff,i - (h_eff,i / 2) g_i - eta (d(dh/dt)/dy)_i,   F_s,i = tau_i A L_i

with the scheme's own gradient g_i and the beta-weighted squeeze-rate gradient of Eq. 33.

Flows (Eq. 40-41): Q_in = A q_1, Q_out = A q_n for a film pressurised at min z (ends and
signs swap for max z); Q_in - Q_out = A S(y_n) = A sum_k M_k dh_eff_k/dt exactly, as in the
default scheme. :class:`PaperLeakageTerm` integrates them, dV/dt = Q (Eq. 42).

Outputs (:meth:`SealPaperFilmTerm.flows`, ``shear_forces``, ``pressure_gradient``,
``nodal_flows``) use the c0 and qd that solve their rows at the (u, U') they are given,
:meth:`SealPaperFilmTerm.constants` (closed form: the rows do not involve p and are linear
in their constant); at the TS's U' these are the unknowns. The stroke's outputs estimate U'
by the step's difference quotient, and g_i = (c_i + S_i - qd + c0)/k_i amplifies a mismatch
between that U' (in S) and the solve's (in qd) by 1/k_i, 1e3 MPa s/mm^3 at h = 0.5 um.

Exact Jacobian. q_i depends on c0, qd and, through S(y_i), on every squeeze rate and node
position from y_1 to y_i; so the pressure rows, the c0 and qd rows and the shear rows are
dense over the chain's u_r and u_z (the pattern holds these blocks in full). With hde_k =
h_eff'(h_k) dh_k/dt and M_k^(i) the trapezoid weight of node k in S(y_i):

* dq_i/dc0 = -1, dq_i/dqd = 1, dq_i/dhde_k = -M_k^(i), dq_i/dy_k = -dS_i/dy_k (the element
  lengths y_k - y_k-1 carry the mean rate of their element);
* hde_k depends on h_k (h_eff'' in the floor range) and on dh_k/dt = du_r,k/dt: the TS
  ``shift`` times dq_i/dhde_k h_eff'(h_k) on the u_r columns;
* dg_i = (d(1/k_i)/dh_i (c_i - q_i) + c'_i / k_i) dh_i - dq_i / k_i;
* Eq. 27's dy_i on u_z,i and u_z,i-1.

The kernels (:func:`chain_flow`, :func:`squeeze_integral_derivatives`,
:func:`zero_gradient_roots`) are numba with ``cache=True``; the assembly is vectorised numpy
over the chain.
"""
import numba
import numpy as np

from ..core import Term
from .chain_film import ChainFilm
from .gap import h_eff_rate
from .reynolds_fv import conductance
from .seal_film import nodal_conductance


@numba.njit(cache=True)
def chain_flow(y, h, hd, c0, qd, v, eta, h_floor, model, par, th, tpp, tps):
    """Nodal flows q_i, gradients g_i = (c_i - q_i)/k_i and what their derivatives need.

    Returns (he, dhe, w, dw, cv, dcv, hde, dhde, S, q, g): h_eff and h_eff', w = 1/k and
    dw = d(1/k)/dh, cv = c/v and dcv = d(c/v)/dh, hde = dh_eff/dt and dhde = d(hde)/dh, the
    squeeze integral S_i = int_{y_1}^{y_i} hde dy (trapezoids), q_i = -c0 + qd - S_i."""
    n = y.size
    he, dhe, w, dw, cv, dcv = nodal_conductance(h, eta, h_floor, model, par, th, tpp, tps)
    hde = np.empty(n)
    dhde = np.empty(n)
    for i in range(n):
        hde[i], dhde[i] = h_eff_rate(h[i], hd[i], h_floor)
    S = np.empty(n)
    q = np.empty(n)
    g = np.empty(n)
    S[0] = 0.0
    for i in range(1, n):
        S[i] = S[i - 1] + 0.5 * (y[i] - y[i - 1]) * (hde[i - 1] + hde[i])
    for i in range(n):
        q[i] = -c0 + qd - S[i]
        g[i] = w[i] * (v * cv[i] - q[i])
    return he, dhe, w, dw, cv, dcv, hde, dhde, S, q, g


@numba.njit(cache=True)
def squeeze_integral_derivatives(y, hde):
    """dS_i/dhde_k and dS_i/dy_k (n x n, lower triangular) of :func:`chain_flow`'s S: row
    i is row i-1 plus the trapezoid of element (i-1, i)."""
    n = y.size
    Se = np.zeros((n, n))
    Sy = np.zeros((n, n))
    for i in range(1, n):
        for k in range(i):
            Se[i, k] = Se[i - 1, k]
            Sy[i, k] = Sy[i - 1, k]
        half = 0.5 * (y[i] - y[i - 1])
        a = 0.5 * (hde[i - 1] + hde[i])
        Se[i, i - 1] += half
        Se[i, i] += half
        Sy[i, i] += a
        Sy[i, i - 1] -= a
    return Se, Sy


@numba.njit(cache=True)
def zero_gradient_roots(y, h, hde, S, qd, v, eta, h_floor, model, par, th, tpp, tps):
    """The y where f(y) = v (c/v)(h(y)) + S(y) - qd = 0, h and hde linear in each element, one
    per element whose end values differ in sign (bisection)."""
    n = y.size
    out = np.empty(n)
    k = 0
    f = np.empty(n)
    for i in range(n):
        f[i] = v * conductance(h[i], eta, h_floor, model, par, th, tpp, tps)[2] + S[i] - qd
    for e in range(n - 1):
        if f[e] == 0.0:
            out[k] = y[e]
            k += 1
            continue
        if f[e] * f[e + 1] > 0.0 or f[e + 1] == 0.0:
            continue
        L = y[e + 1] - y[e]
        a, b = 0.0, 1.0
        for _ in range(200):
            m = 0.5 * (a + b)
            if m == a or m == b:
                break
            fm = (v * conductance(h[e] + m * (h[e + 1] - h[e]), eta, h_floor, model, par, th,
                                  tpp, tps)[2]
                  + S[e] + L * (m * hde[e] + 0.5 * m * m * (hde[e + 1] - hde[e])) - qd)
            if (fm > 0.0) == (f[e] > 0.0):
                a = m
            else:
                b = m
        out[k] = y[e] + 0.5 * (a + b) * L
        k += 1
    if f[n - 1] == 0.0:
        out[k] = y[n - 1]
        k += 1
    return out[:k]


class SealPaperFilmTerm(ChainFilm):
    """The paper's scheme (Eq. 15-28) on the seal's rod-side chain; a drop-in for
    :class:`sealts.film.seal_film.SealFilmTerm` in the stroke (module docstring).

    Owns the rows ``pdofs`` (film pressures in chain order) and ``xdofs`` = (c0, qd); adds to
    the u_r rows of the chain nodes and their u_z rows (``surface_normal``, ``shear``).
    Columns: the chain's film pressures, u_r and u_z, and c0, qd.
    """

    name = "paper"

    def __init__(self, side, pdofs, xdofs, v, eta, p_in, p_out, ff=None, h_floor=1e-5,
                 squeeze=True, pressurised_end="min_z", surface_normal=False, shear=True,
                 alpha=0.5, beta=0.5):
        """Arguments as :class:`SealFilmTerm`'s (no ``h_ref``: the rows are in MPa), plus
        ``xdofs``: the dofs of the integration constants c0 and qd (both mm^2/s), and
        ``alpha``: the gradient weight of Eq. 27."""
        super().__init__(side, pdofs, v, eta, p_in, p_out, ff, h_floor, squeeze,
                         pressurised_end)
        m = side.m
        self.xd = np.asarray(xdofs, np.int64)
        if self.xd.shape != (2,):
            raise ValueError("xdofs must be the two dofs (c0, qd)")
        self.cdof, self.qdof = int(self.xd[0]), int(self.xd[1])
        self.alpha, self.beta = alpha, beta
        self.surface_normal, self.shear = surface_normal, shear
        ur, uz, pd = side.ur, side.uz, self.pd
        lo, hi = side.lo, side.hi
        # the dense columns: c0, qd, then u_r and u_z of the chain
        self.dense_cols = np.concatenate([self.xd, ur, uz])
        nb = self.dense_cols.size
        dense_rows = np.concatenate([pd[1:], self.xd])      # Eq. 27 rows, then c0 and qd
        rows = [[pd[0]], pd[1:], pd[1:], np.repeat(dense_rows, nb), ur, ur, ur]
        cols = [[pd[0]], pd[1:], pd[:-1], np.tile(self.dense_cols, m + 1), pd, uz[hi], uz[lo]]
        if surface_normal:
            rows += [uz, uz, uz]
            cols += [pd, ur[hi], ur[lo]]
        if shear:
            rows.append(np.repeat(uz, nb))
            cols.append(np.tile(self.dense_cols, m))
        self.rows = np.concatenate(rows).astype(np.int64)
        self.cols = np.concatenate(cols).astype(np.int64)
        # the shear's squeeze-rate gradient (Eq. 33): gd_i = sum over (i, e) of weight dd_e
        i = np.arange(1, m - 1)
        self._gd_node = np.concatenate([[0], i, i, [m - 1]])
        self._gd_elem = np.concatenate([[0], i - 1, i, [m - 2]])
        self._gd_w = np.concatenate([[1.0], np.full(m - 2, beta), np.full(m - 2, 1.0 - beta),
                                     [1.0]])

    # ---- the scheme on the chain ---------------------------------------------------------
    def _flow(self, t, u, udot, closed=False):
        """The chain's state and :func:`chain_flow` at the unknowns c0, qd, or (``closed``)
        at the constants that solve their rows at this (u, udot), :meth:`constants`."""
        y, h, hd, p = self.film(t, u, udot)
        v = self.v(t)
        c0, qd = self.constants(t, u, udot) if closed else (u[self.cdof], u[self.qdof])
        k = chain_flow(y, h, hd, float(c0), float(qd), v, self.eta, self.h_floor,
                       *self._ffargs())
        return y, h, hd, p, v, k

    def constants(self, t, u, udot=None):
        """(c0, qd) solving the c0 and qd rows at this (u, udot): they do not involve the
        pressures and are linear in their constant, so with W = sum_i dy_i [alpha / k_i-1 +
        (1 - alpha) / k_i], c0 = (p_last - p_first) / W and qd = sum_i dy_i [alpha (c_i-1 +
        S_i-1) / k_i-1 + (1 - alpha) (c_i + S_i) / k_i] / W. At the TS's U' they are the
        unknowns (to round-off); the outputs use them, so that a U' estimated after the step
        (the stroke's difference quotient) gives flows and a shear consistent with it: g_i
        amplifies a mismatch of qd and S(y_i) by 1/k_i, up to 1e3 MPa s/mm^3 at h = 0.5 um."""
        y, h, hd, _ = self.film(t, u, udot)
        v = self.v(t)
        k = chain_flow(y, h, hd, 0.0, 0.0, v, self.eta, self.h_floor, *self._ffargs())
        w, g = k[2], k[10]                        # g = (c + S) / k at c0 = qd = 0
        Le = np.diff(y)
        W = self._weighted(Le, w).sum()
        return (self.p_last(t) - self.p_first(t)) / W, self._weighted(Le, g).sum() / W

    def set_row_scale(self, t, u, udot=None):
        """The rows are pressure differences in MPa already."""

    # outputs: at the constants that solve their rows at (u, udot), see constants()
    def pressure_gradient(self, t, u, udot=None):
        """The scheme's nodal dp/dy (MPa/mm), g_i of Eq. 17 + Eq. 24."""
        return self._flow(t, u, udot, closed=True)[5][10]

    def nodal_flows(self, t, u, udot=None):
        """q(y_i) per unit circumference (mm^2/s, +y), Eq. 40 with the squeeze integral."""
        return self._flow(t, u, udot, closed=True)[5][9]

    def zero_gradient_points(self, t, u, udot=None):
        """The paper's y0 for this state (mm): the points of the chain where the
        hydrodynamic gradient vanishes, c(h(y)) + S(y) = qd (h and dh_eff/dt linear between
        nodes), one per element whose ends differ in sign (bisection to round-off). Usually
        two on a converging-diverging gap, the hydrodynamic pressure's maximum and minimum."""
        y, h, hd, p, v, k = self._flow(t, u, udot, closed=True)
        qd = self.constants(t, u, udot)[1]
        return zero_gradient_roots(y, h, k[6], k[8], qd, v, self.eta, self.h_floor,
                                   *self._ffargs())

    def flows(self, t, u, udot=None, closed=True):
        """(Q_in, Q_out) in mm^3/s: into the film at the pressurised end, out at the other
        (Eq. 41); Q_in - Q_out = A sum_k M_k dh_eff_k/dt. ``closed=False``: at the
        unknowns c0, qd (the leakage rows)."""
        q = self._flow(t, u, udot, closed=closed)[5][9]
        if self.pressurised_end == "min_z":
            return self.side.area * q[0], self.side.area * q[-1]
        return -self.side.area * q[-1], -self.side.area * q[0]

    def _weighted(self, Le, a):
        """dy_i [alpha a_{i-1} + (1 - alpha) a_i] for i = 2..n (rows of a, or entries)."""
        al = self.alpha
        if a.ndim == 1:
            return Le * (al * a[:-1] + (1.0 - al) * a[1:])
        return Le[:, None] * (al * a[:-1] + (1.0 - al) * a[1:])

    def _tau(self, v, he, g, hd, y):
        dd = np.diff(hd) / np.diff(y)
        gd = np.zeros(self.side.m)
        np.add.at(gd, self._gd_node, self._gd_w * dd[self._gd_elem])
        return self.eta * v / he - 0.5 * he * g - self.eta * gd, dd

    def shear_forces(self, t, u, udot=None):
        """Axial fluid shear force on each chain node (N, +y), Eq. 32-34 with the scheme's
        gradient (computed whether or not ``shear`` puts it into the residual)."""
        y, h, hd, p, v, k = self._flow(t, u, udot, closed=True)
        return self._tau(v, k[0], k[10], hd, y)[0] * self.side.area * self.lengths(y)

    # ---- Term interface ------------------------------------------------------------------
    def add_residual(self, t, u, udot, f):
        y, h, hd, p, v, k = self._flow(t, u, udot)
        he, w, g = k[0], k[2], k[10]
        Le = np.diff(y)
        p_first, p_last = self.p_first(t), self.p_last(t)
        r = np.empty(self.side.m)
        r[0] = p[0] - p_first
        r[1:] = p[1:] - p[:-1] - self._weighted(Le, g)
        ghs = w * u[self.cdof]
        np.add.at(f, self.pd, r)
        f[self.cdof] += self._weighted(Le, ghs).sum() - (p_last - p_first)
        f[self.qdof] += self._weighted(Le, g - ghs).sum()
        np.subtract.at(f, self.side.ur, self.forces(t, u))
        if self.surface_normal:
            np.subtract.at(f, self.side.uz, self.axial_forces(t, u))
        if self.shear:
            F = self._tau(v, he, g, hd, y)[0] * self.side.area * self.lengths(y)
            np.subtract.at(f, self.side.uz, F)
            if self.work is not None:              # the friction work's row: -v sum F
                f[self.work[0]] -= self.work[1](t) * F.sum()

    def derivatives(self, t, u, udot, shift):
        """The state, and dq_i, dg_i by the dense columns (c0, qd, u_r, u_z of the chain)
        plus shift times their derivatives by U' (n x (2n + 2) each)."""
        y, h, hd, p, v, k = self._flow(t, u, udot)
        he, dhe, w, dw, cv, dcv, hde, dhde, S, q, g = k
        Se, Sy = squeeze_integral_derivatives(y, hde)
        m = self.side.m
        shift_hd = shift if (self.squeeze and udot is not None) else 0.0
        dq = np.empty((m, 2 * m + 2))
        dq[:, 0] = -1.0
        dq[:, 1] = 1.0
        dq[:, 2:m + 2] = -Se * (dhde + shift_hd * dhe)
        dq[:, m + 2:] = -Sy
        dg = -w[:, None] * dq
        i = np.arange(m)
        dg[i, 2 + i] += dw * (v * cv - q) + w * v * dcv
        return (y, h, hd, p, v, k, shift_hd), dq, dg

    def _shear_jacobian(self, y, hd, p, v, k, dg, shift_hd):
        """d F_s,i / d(dense columns) + shift d/dU' (m x (2m + 2)), F_s the nodal shear
        force of the residual (Eq. 32-34)."""
        he, dhe, g = k[0], k[1], k[10]
        m, A = self.side.m, self.side.area
        i = np.arange(m)
        uzc = m + 2 + i                                       # u_z,i's dense column
        Le = np.diff(y)
        Li = self.lengths(y)
        tau, dd = self._tau(v, he, g, hd, y)
        dtau = -0.5 * he[:, None] * dg
        dtau[i, 2 + i] += -self.eta * v * dhe / he**2 - 0.5 * dhe * g
        # Eq. 33: dd_e = (hd_b - hd_a) / dy_e, weighted onto the nodes
        n_, e_, w_ = self._gd_node, self._gd_elem, -self.eta * self._gd_w
        Lg = Le[e_]
        for col, d in ((2 + e_ + 1, shift_hd / Lg), (2 + e_, -shift_hd / Lg),
                       (uzc[e_ + 1], -dd[e_] / Lg), (uzc[e_], dd[e_] / Lg)):
            np.add.at(dtau, (n_, col), w_ * d)
        dF = A * Li[:, None] * dtau
        dF[i, uzc[self.side.hi]] += 0.5 * A * tau
        dF[i, uzc[self.side.lo]] -= 0.5 * A * tau
        return dF

    @property
    def work_cols(self):
        """The friction work's columns: c0, qd, u_r and u_z of the chain."""
        return self.dense_cols

    def jacobian_values(self, t, u, udot, shift):
        (y, h, hd, p, v, k, shift_hd), _, dg = self.derivatives(t, u, udot, shift)
        w, dw, g = k[2], k[3], k[10]
        m, A, al = self.side.m, self.side.area, self.alpha
        c0 = u[self.cdof]
        Le = np.diff(y)
        i = np.arange(m)
        uzc = m + 2 + i                                       # u_z,i's dense column
        # Eq. 27 rows, i = 2..n
        E = al * g[:-1] + (1.0 - al) * g[1:]
        rows27 = -self._weighted(Le, dg)
        b = np.arange(m - 1)
        rows27[b, uzc[1:]] -= E
        rows27[b, uzc[:-1]] += E
        # c0 and qd rows: g_hs = w c0 depends on c0 and h only
        dghs = np.zeros_like(dg)
        dghs[:, 0] = w
        dghs[i, 2 + i] = c0 * dw
        ghs = w * c0
        Ehs = al * ghs[:-1] + (1.0 - al) * ghs[1:]
        row_c = self._weighted(Le, dghs).sum(0)
        row_q = self._weighted(Le, dg - dghs).sum(0)
        np.add.at(row_c, uzc[1:], Ehs)
        np.add.at(row_c, uzc[:-1], -Ehs)
        np.add.at(row_q, uzc[1:], E - Ehs)
        np.add.at(row_q, uzc[:-1], -(E - Ehs))
        Li = self.lengths(y)
        vals = [[1.0], np.ones(m - 1), -np.ones(m - 1), rows27.ravel(), row_c, row_q,
                -A * Li, -0.5 * A * p, 0.5 * A * p]
        if self.surface_normal:
            dr = self.lengths(self.side.R + u[self.side.ur])
            vals += [A * dr, 0.5 * A * p, -0.5 * A * p]
        if self.shear:
            dF = self._shear_jacobian(y, hd, p, v, k, dg, shift_hd)
            vals.append(-dF.ravel())                  # the residual subtracts the force
            if self.work is not None:                 # d(-v sum F)
                vals.append(-self.work[1](t) * dF.sum(0))
        return np.concatenate(vals)


class PaperLeakageTerm(Term):
    """The leakage volumes of a :class:`SealPaperFilmTerm` as ODE unknowns (Eq. 41-42),

        dV_in/dt = Q_in,   dV_out/dt = Q_out,

    at ``vdofs`` = (V_in, V_out), Q from the scheme's q at the chain's ends (Eq. 40), as
    :class:`sealts.film.seal_film.LeakageTerm` for the default scheme. q_1 = -c0 + qd
    depends on the constants only, q_n = q_1 - S(y_n) also (through the squeeze integral)
    on every u_r, u_r' and u_z of the chain: exact with the TS shift."""

    def __init__(self, film, vdofs):
        self.film = film
        self.vd = np.asarray(vdofs, np.int64)
        nb = film.dense_cols.size
        self.rows = np.concatenate([self.vd, np.repeat(self.vd, nb)])
        self.cols = np.concatenate([self.vd, np.tile(film.dense_cols, 2)])
        # (node, sign) of the flows into V_in, V_out
        if film.pressurised_end == "min_z":
            self._ends = ((0, 1.0), (-1, 1.0))
        else:
            self._ends = ((-1, -1.0), (0, -1.0))

    def flows(self, t, u, udot=None):
        """(Q_in, Q_out) in mm^3/s (output: :meth:`SealPaperFilmTerm.flows`)."""
        return self.film.flows(t, u, udot)

    def add_residual(self, t, u, udot, f):
        q_in, q_out = self.film.flows(t, u, udot, closed=False)
        f[self.vd[0]] += udot[self.vd[0]] - q_in
        f[self.vd[1]] += udot[self.vd[1]] - q_out

    def jacobian_values(self, t, u, udot, shift):
        _, dq, _ = self.film.derivatives(t, u, udot, shift)
        A = self.film.side.area
        return np.concatenate([[shift, shift]]
                              + [-sg * A * dq[node] for node, sg in self._ends])
