"""The paper's film scheme on the deforming seal: Eq. 15-28 coupled to the seal (issue 5).

The same film as :class:`sealts.film.seal_film.SealFilmTerm` (the chain of ``rod_side``
vertices, current positions and gaps, the same loads on the seal), discretised as in the
paper (Sections 2.2.1-2.2.3) instead of by control volumes. On chain node i (i = 1..n in
the paper's numbering, ordered by reference z)

    y_i = Z_i + u_z,i                                             (Eq. 25)
    h_i = R_i + u_r,i - r(t)                                      (Eq. 18)
    dh_i/dt = du_r,i/dt - dr/dt                                   (Eq. 26, from the TS's U')

and, with h_eff the gap regularisation (:mod:`sealts.film.gap`), k_i = Phi_p h_eff^3 /
(12 eta) and c_i = (v/2)(h_eff - Rq Phi_s) at h_i (:func:`sealts.film.reynolds_fv.
conductance`), the hydrostatic plus hydrodynamic gradient of Eq. 17 + Eq. 24 (Eq. 35) is

    g_i = (dp/dy)_i = (c_i - q_i) / k_i,
    q_i = -c0 + c(h0) - S(y_i),      S(y) = int_{y0}^{y} dh_eff/dt dy        (Eq. 40)

(q_i the flow per unit circumference through y_i; for a uniform squeeze S = (dh/dt)(y - y0),
the paper's 2 (du/dt)(y - y0) in Eq. 24). c0 (mm^2/s) and y0 (mm) are two global unknowns,
h0 = h(y0) linear inside y0's current element, Phi_s0 = Phi_s(h0); dh_eff/dt is linear
between nodes, so S(y_i) is the trapezoid sum of the nodal rates M_k dh_eff_k/dt (the control
volumes of the default scheme) and S from y_1 to y0 the exact integral of the linear rate.

Rows (the film's own: the chain's pressures, then c0 and y0):

* p_1 = p_first (p_in at the pressurised end, ``pressurised_end = "min_z"``; p_out else);
* p_i - p_{i-1} - dy_i [alpha g_{i-1} + (1 - alpha) g_i] = 0,  dy_i = y_i - y_{i-1}  (Eq. 27);
* Eq. 28 (p_n = p_last) split as in :class:`sealts.film.paper_scheme.PaperScheme`:
  c0 row  sum_i dy_i [alpha g_hs,i-1 + (1 - alpha) g_hs,i] - (p_last - p_first) = 0,
  y0 row  sum_i dy_i [alpha g_hd,i-1 + (1 - alpha) g_hd,i] + Y0_ANCHOR (y0 - y_mid) = 0,
  g_hs = c0 / k (Eq. 17), g_hd = g - g_hs (Eq. 24), y_mid = (y_1 + y_n)/2 of the current
  chain (the anchor keeps y0 defined when v = 0 and dh/dt = 0, the hydrostatic start).

All rows are pressure differences (MPa): no row scale (``set_row_scale`` does nothing).

Loads on the seal, as :class:`SealFilmTerm` (the same functions for the radial and
surface-normal parts): F_r,i = p_i A L_i (Eq. 29-31) on u_r; with ``surface_normal``
F_z,i = -p_i A (r_{i+1} - r_{i-1})/2 on u_z; with ``shear`` the fluid shear (Eq. 32-34)

    tau_i = eta v / h_eff,i - (h_eff,i / 2) g_i - eta (d(dh/dt)/dy)_i,   F_s,i = tau_i A L_i

with the scheme's own gradient g_i and the beta-weighted squeeze-rate gradient of Eq. 33.

Flows (Eq. 40-41): q at the chain's ends, q_1 = -c0 + c(h0) + S(y_1)... i.e. q(y) above at
y_1 and y_n; Q_in = A q_1, Q_out = A q_n for a film pressurised at min z (ends and signs swap
for max z). Q_in - Q_out = A sum_k M_k dh_eff_k/dt exactly, as in the default scheme;
:class:`PaperLeakageTerm` integrates them, dV/dt = Q (Eq. 42).

Exact Jacobian. Every g_i depends on c0, y0, the gaps at y0's element (through h0) and on
every squeeze rate and node position between y0 and y_i (through S), so the pressure rows,
the c0 and y0 rows and the shear rows are dense over the chain's u_r and u_z; the pattern is
these blocks in full (y0's element moves). With hde_k = h_eff'(h_k) dh_k/dt:

* dq_i/dc0 = -1, dq_i/dy0 = c'(h0) dh0/dy0 + hde(y0) (the element's slope and rate);
* dq_i/dh_j, dq_i/dh_j+1 = c'(h0) (1 - t0), c'(h0) t0 (j y0's element, t0 its local
  coordinate), dq_i/dy_j, dy_j+1 = -c'(h0) slope (1 - t0), -c'(h0) slope t0;
* dq_i/dhde_k = -(dS_i/dhde_k - dS_0/dhde_k), the trapezoid weights from y0 to y_i, and
  dq_i/dy_k likewise through the element lengths (and S_0 through y0's element ends);
* hde_k depends on h_k (h_eff'' in the floor range) and on dh_k/dt = du_r,k/dt: the TS
  ``shift`` times dq_i/dhde_k h_eff'(h_k) on the u_r columns;
* dg_i = (d(1/k_i)/dh_i (c_i - q_i) + c'_i / k_i) dh_i - dq_i / k_i;
* Eq. 27's dy_i on u_z,i and u_z,i-1; the anchor's y_mid on u_z of the ends.

The kernels (:func:`chain_flow`, :func:`chain_flow_derivatives`) are numba with
``cache=True``; the assembly is vectorised numpy over the chain.
"""
import numba
import numpy as np

from ..mesh.layout import vertex_dofs
from ..problem import Term, of_time
from .flow_factors import FlowFactors
from .gap import h_eff
from .paper_scheme import Y0_ANCHOR
from .reynolds_fv import conductance
from .seal_film import SealFilmTerm


@numba.njit(cache=True)
def chain_flow(y, h, hd, c0, y0, v, eta, h_floor, model, par, th, tpp, tps):
    """Nodal flows q_i, gradients g_i = (c_i - q_i)/k_i and what their derivatives need.

    Returns (he, dhe, w, dw, cv, dcv, hde, dhde, q, g, j, sigma, L, slope, dcv0, hd0) with
    w = 1/k, dw = d(1/k)/dh, cv = c/v, dcv = d(c/v)/dh, hde = dh_eff/dt, dhde = d(hde)/dh;
    y0's element j (clamped to the chain, y0 extrapolated linearly beyond its ends), sigma =
    y0 - y_j, L its length, slope its dh/dy, dcv0 = d(c/v)/dh at h0, hd0 = hde at y0."""
    n = y.size
    he = np.empty(n)
    dhe = np.empty(n)
    w = np.empty(n)
    dw = np.empty(n)
    cv = np.empty(n)
    dcv = np.empty(n)
    hde = np.empty(n)
    dhde = np.empty(n)
    for i in range(n):
        he[i], dhe[i] = h_eff(h[i], h_floor)
        w[i], dw[i], cv[i], dcv[i] = conductance(h[i], eta, h_floor, model, par, th, tpp, tps)
        d2 = 0.0
        if h_floor > 0.0 and h[i] < 2.0 * h_floor:
            d2 = dhe[i] / h_floor                     # h_eff'' in the floor range
        hde[i] = dhe[i] * hd[i]
        dhde[i] = d2 * hd[i]
    s = np.empty(n)                                   # int_{y_1}^{y_i} hde, trapezoids
    s[0] = 0.0
    for i in range(1, n):
        s[i] = s[i - 1] + 0.5 * (y[i] - y[i - 1]) * (hde[i - 1] + hde[i])
    j = np.searchsorted(y, y0) - 1
    j = min(max(j, 0), n - 2)
    L = y[j + 1] - y[j]
    sigma = y0 - y[j]
    slope = (h[j + 1] - h[j]) / L
    h0raw = h[j] + sigma * slope
    _, _, cv0, dcv0 = conductance(h0raw, eta, h_floor, model, par, th, tpp, tps)
    delta = hde[j + 1] - hde[j]
    hd0 = hde[j] + sigma * delta / L
    s0 = s[j] + sigma * hde[j] + 0.5 * sigma * sigma * delta / L
    q = np.empty(n)
    g = np.empty(n)
    for i in range(n):
        q[i] = -c0 + v * cv0 - (s[i] - s0)
        g[i] = w[i] * (v * cv[i] - q[i])
    return he, dhe, w, dw, cv, dcv, hde, dhde, q, g, j, sigma, L, slope, dcv0, hd0


@numba.njit(cache=True)
def chain_flow_derivatives(y, hde, dhde, dhe, j, sigma, L, slope, dcv0, hd0, v):
    """dq_i/dh_k, dq_i/d(dh_k/dt), dq_i/dy_k (n x n each) and dq_i/dy0 (one number, the same
    for every i) of :func:`chain_flow`'s q."""
    n = y.size
    # Se[i, k] = dS(y_i)/dhde_k, Sy[i, k] = dS(y_i)/dy_k, S from y_1: row i is row i-1 plus
    # the trapezoid of element (i-1, i)
    Se = np.zeros((n, n))
    Sy = np.zeros((n, n))
    for i in range(1, n):
        for k in range(i):
            Se[i, k] = Se[i - 1, k]
            Sy[i, k] = Sy[i - 1, k]
        Le = y[i] - y[i - 1]
        a = 0.5 * (hde[i - 1] + hde[i])
        Se[i, i - 1] += 0.5 * Le
        Se[i, i] += 0.5 * Le
        Sy[i, i] += a
        Sy[i, i - 1] -= a
    # S from y_1 to y0: S_j plus the integral of the linear rate over [y_j, y0]
    s0e = Se[j].copy()
    s0y = Sy[j].copy()
    delta = hde[j + 1] - hde[j]
    s0e[j] += sigma - 0.5 * sigma * sigma / L
    s0e[j + 1] += 0.5 * sigma * sigma / L
    s0y[j] += -hd0 + 0.5 * sigma * sigma * delta / (L * L)
    s0y[j + 1] += -0.5 * sigma * sigma * delta / (L * L)
    t0 = sigma / L
    dh = np.empty((n, n))
    dhd = np.empty((n, n))
    dy = np.empty((n, n))
    for i in range(n):
        for k in range(n):
            de = s0e[k] - Se[i, k]                    # dq_i/dhde_k
            dh[i, k] = de * dhde[k]
            dhd[i, k] = de * dhe[k]
            dy[i, k] = s0y[k] - Sy[i, k]
        # c(h0), h0 = (1 - t0) h_j + t0 h_j+1 over the current element
        dh[i, j] += v * dcv0 * (1.0 - t0)
        dh[i, j + 1] += v * dcv0 * t0
        dy[i, j] -= v * dcv0 * slope * (1.0 - t0)
        dy[i, j + 1] -= v * dcv0 * slope * t0
    return dh, dhd, dy, v * dcv0 * slope + hd0


class SealPaperFilmTerm(Term):
    """The paper's scheme (Eq. 15-28) on the seal's rod-side chain; a drop-in for
    :class:`sealts.film.seal_film.SealFilmTerm` in the stroke (module docstring).

    Owns the rows ``pdofs`` (film pressures in chain order) and ``xdofs`` = (c0, y0); adds to
    the u_r rows of the chain nodes and their u_z rows (``surface_normal``, ``shear``).
    Columns: the chain's film pressures, u_r and u_z, and c0, y0.
    """

    name = "paper"
    # the chain's state and the pressure loads are SealFilmTerm's, the very functions
    film = SealFilmTerm.film
    lengths = SealFilmTerm.lengths
    forces = SealFilmTerm.forces
    axial_forces = SealFilmTerm.axial_forces
    pressure = SealFilmTerm.pressure
    _ffargs = SealFilmTerm._ffargs

    def __init__(self, X, chain, pdofs, xdofs, r_rod, v, eta, p_in, p_out, area, ff=None,
                 h_floor=1e-5, squeeze=True, pressurised_end="min_z", udofs=None,
                 rod_rate=None, surface_normal=False, shear=True, alpha=0.5, beta=0.5):
        """Arguments as :class:`SealFilmTerm`'s (``h_ref`` has no use: the rows are in MPa),
        plus ``xdofs``: the dofs of c0 (mm^2/s) and y0 (mm), and ``alpha``: the gradient
        weight of Eq. 27."""
        if pressurised_end not in ("min_z", "max_z"):
            raise ValueError("pressurised_end must be 'min_z' or 'max_z', "
                             f"got {pressurised_end!r}")
        self.X = np.asarray(X, float)
        self.chain = np.asarray(chain, np.int64)
        m = self.m = self.chain.size
        if m < 3:
            raise ValueError("the film needs at least three chain nodes")
        udofs = vertex_dofs(self.X.shape[0]) if udofs is None else np.asarray(udofs)
        self.ur, self.uz = udofs[self.chain, 0], udofs[self.chain, 1]
        self.pd = np.asarray(pdofs, np.int64)
        if self.pd.shape != (m,):
            raise ValueError("pdofs must give one film-pressure dof per chain node")
        self.xd = np.asarray(xdofs, np.int64)
        if self.xd.shape != (2,):
            raise ValueError("xdofs must be the two dofs (c0, y0)")
        self.cd, self.yd = int(self.xd[0]), int(self.xd[1])
        self.R, self.Z = self.X[self.chain, 0], self.X[self.chain, 1]
        self.r_rod, self.v = r_rod, of_time(v)
        self.rod_rate = of_time(0.0 if rod_rate is None else rod_rate)
        self.eta, self.area, self.h_floor, self.squeeze = eta, area, h_floor, squeeze
        self.ff = FlowFactors.none() if ff is None else ff
        first = pressurised_end == "min_z"
        self.p_first = of_time(p_in if first else p_out)
        self.p_last = of_time(p_out if first else p_in)
        self.pressurised_end = pressurised_end
        self.alpha, self.beta = alpha, beta
        self.surface_normal, self.shear = surface_normal, shear
        self.lo = np.concatenate([[0], np.arange(m - 1)])
        self.hi = np.concatenate([np.arange(1, m), [m - 1]])

        ur, uz, pd = self.ur, self.uz, self.pd
        # the dense columns: c0, y0, then u_r and u_z of the chain
        self.dense_cols = np.concatenate([self.xd, ur, uz])
        nb = self.dense_cols.size
        dense_rows = np.concatenate([pd[1:], self.xd])      # Eq. 27 rows, then c0 and y0
        rows = [[pd[0]], pd[1:], pd[1:], np.repeat(dense_rows, nb), ur, ur, ur]
        cols = [[pd[0]], pd[1:], pd[:-1], np.tile(self.dense_cols, m + 1), pd, uz[self.hi],
                uz[self.lo]]
        if surface_normal:
            rows += [uz, uz, uz]
            cols += [pd, ur[self.hi], ur[self.lo]]
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
    def _flow(self, t, u, udot):
        y, h, hd, p = self.film(t, u, udot)
        v = self.v(t)
        k = chain_flow(y, h, hd, float(u[self.cd]), float(u[self.yd]), v, self.eta,
                       self.h_floor, *self._ffargs())
        return y, h, hd, p, v, k

    def set_row_scale(self, t, u, udot=None):
        """The rows are pressure differences in MPa already."""

    def pressure_gradient(self, t, u, udot=None):
        """The scheme's nodal dp/dy (MPa/mm), g_i of Eq. 17 + Eq. 24."""
        return self._flow(t, u, udot)[5][9]

    def nodal_flows(self, t, u, udot=None):
        """q(y_i) per unit circumference (mm^2/s, +y), Eq. 40 with the squeeze integral."""
        return self._flow(t, u, udot)[5][8]

    def flows(self, t, u, udot=None):
        """(Q_in, Q_out) in mm^3/s: into the film at the pressurised end, out at the other
        (Eq. 41); Q_in - Q_out = A sum_k M_k dh_eff_k/dt."""
        q = self.nodal_flows(t, u, udot)
        if self.pressurised_end == "min_z":
            return self.area * q[0], self.area * q[-1]
        return -self.area * q[-1], -self.area * q[0]

    def _weighted(self, Le, a):
        """dy_i [alpha a_{i-1} + (1 - alpha) a_i] for i = 2..n (rows of a, or entries)."""
        al = self.alpha
        if a.ndim == 1:
            return Le * (al * a[:-1] + (1.0 - al) * a[1:])
        return Le[:, None] * (al * a[:-1] + (1.0 - al) * a[1:])

    def _tau(self, v, he, g, hd, y):
        dd = np.diff(hd) / np.diff(y)
        gd = np.zeros(self.m)
        np.add.at(gd, self._gd_node, self._gd_w * dd[self._gd_elem])
        return self.eta * v / he - 0.5 * he * g - self.eta * gd, dd

    def shear_forces(self, t, u, udot=None):
        """Axial fluid shear force on each chain node (N, +y), Eq. 32-34 with the scheme's
        gradient (computed whether or not ``shear`` puts it into the residual)."""
        y, h, hd, p, v, k = self._flow(t, u, udot)
        return self._tau(v, k[0], k[9], hd, y)[0] * self.area * self.lengths(y)

    # ---- Term interface ------------------------------------------------------------------
    def add_residual(self, t, u, udot, f):
        y, h, hd, p, v, k = self._flow(t, u, udot)
        he, w, g = k[0], k[2], k[9]
        c0, y0 = u[self.cd], u[self.yd]
        Le = np.diff(y)
        p_first, p_last = self.p_first(t), self.p_last(t)
        r = np.empty(self.m)
        r[0] = p[0] - p_first
        r[1:] = p[1:] - p[:-1] - self._weighted(Le, g)
        ghs = w * c0
        r_c = self._weighted(Le, ghs).sum() - (p_last - p_first)
        r_y = (self._weighted(Le, g - ghs).sum()
               + Y0_ANCHOR * (y0 - 0.5 * (y[0] + y[-1])))
        np.add.at(f, self.pd, r)
        f[self.cd] += r_c
        f[self.yd] += r_y
        np.subtract.at(f, self.ur, self.forces(t, u))
        if self.surface_normal:
            np.subtract.at(f, self.uz, self.axial_forces(t, u))
        if self.shear:
            F = self._tau(v, he, g, hd, y)[0] * self.area * self.lengths(y)
            np.subtract.at(f, self.uz, F)

    def derivatives(self, t, u, udot, shift):
        """The state and d(q_i, g_i)/d(dense columns) + shift d/dU' (n x (2n + 2) each)."""
        y, h, hd, p, v, k = self._flow(t, u, udot)
        he, dhe, w, dw, cv, dcv, hde, dhde, q, g, j, sigma, L, slope, dcv0, hd0 = k
        dh, dhd, dy, dq_dy0 = chain_flow_derivatives(y, hde, dhde, dhe, j, sigma, L, slope,
                                                     dcv0, hd0, v)
        m = self.m
        shift_hd = shift if (self.squeeze and udot is not None) else 0.0
        dq = np.empty((m, 2 * m + 2))
        dq[:, 0] = -1.0
        dq[:, 1] = dq_dy0
        dq[:, 2:m + 2] = dh + shift_hd * dhd
        dq[:, m + 2:] = dy
        dg = -w[:, None] * dq
        i = np.arange(m)
        dg[i, 2 + i] += dw * (v * cv - q) + w * v * dcv
        return (y, h, hd, p, v, k, shift_hd), dq, dg

    def jacobian_values(self, t, u, udot, shift):
        (y, h, hd, p, v, k, shift_hd), _, dg = self.derivatives(t, u, udot, shift)
        he, dhe, w, dw, g = k[0], k[1], k[2], k[3], k[9]
        m, A, al = self.m, self.area, self.alpha
        c0 = u[self.cd]
        Le = np.diff(y)
        i = np.arange(m)
        uzc = m + 2 + i                                       # u_z,i's dense column
        # Eq. 27 rows, i = 2..n
        E = al * g[:-1] + (1.0 - al) * g[1:]
        rows27 = -self._weighted(Le, dg)
        b = np.arange(m - 1)
        rows27[b, uzc[1:]] -= E
        rows27[b, uzc[:-1]] += E
        # c0 and y0 rows: g_hs = w c0 depends on c0 and h only
        dghs = np.zeros_like(dg)
        dghs[:, 0] = w
        dghs[i, 2 + i] = c0 * dw
        ghs = w * c0
        Ehs = al * ghs[:-1] + (1.0 - al) * ghs[1:]
        row_c = self._weighted(Le, dghs).sum(0)
        row_y = self._weighted(Le, dg - dghs).sum(0)
        np.add.at(row_c, uzc[1:], Ehs)
        np.add.at(row_c, uzc[:-1], -Ehs)
        np.add.at(row_y, uzc[1:], E - Ehs)
        np.add.at(row_y, uzc[:-1], -(E - Ehs))
        row_y[1] += Y0_ANCHOR
        row_y[uzc[0]] -= 0.5 * Y0_ANCHOR
        row_y[uzc[-1]] -= 0.5 * Y0_ANCHOR
        Li = self.lengths(y)
        vals = [[1.0], np.ones(m - 1), -np.ones(m - 1), rows27.ravel(), row_c, row_y,
                -A * Li, -0.5 * A * p, 0.5 * A * p]
        if self.surface_normal:
            dr = self.lengths(self.R + u[self.ur])
            vals += [A * dr, 0.5 * A * p, -0.5 * A * p]
        if self.shear:
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
            dF[i, uzc[self.hi]] += 0.5 * A * tau
            dF[i, uzc[self.lo]] -= 0.5 * A * tau
            vals.append(-dF.ravel())                  # the residual subtracts the force
        return np.concatenate(vals)


class PaperLeakageTerm(Term):
    """The leakage volumes of a :class:`SealPaperFilmTerm` as ODE unknowns (Eq. 41-42),

        dV_in/dt = Q_in,   dV_out/dt = Q_out,

    at ``vdofs`` = (V_in, V_out), Q from the scheme's q at the chain's ends (Eq. 40), as
    :class:`sealts.film.seal_film.LeakageTerm` for the default scheme. q_1 and q_n depend on
    c0, y0 and (through the squeeze integral from y0) on every u_r, u_r' and u_z of the
    chain: two dense rows, exact with the TS shift."""

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
        """(Q_in, Q_out) in mm^3/s."""
        return self.film.flows(t, u, udot)

    def add_residual(self, t, u, udot, f):
        q_in, q_out = self.flows(t, u, udot)
        f[self.vd[0]] += udot[self.vd[0]] - q_in
        f[self.vd[1]] += udot[self.vd[1]] - q_out

    def jacobian_values(self, t, u, udot, shift):
        _, dq, _ = self.film.derivatives(t, u, udot, shift)
        A = self.film.area
        return np.concatenate([[shift, shift]]
                              + [-sg * A * dq[node] for node, sg in self._ends])
