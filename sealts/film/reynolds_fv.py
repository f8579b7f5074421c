"""Default film discretisation: a mass-conserving control-volume scheme for paper Eq. 13.

Written as a conservation law for the film volume per unit circumference,

    dh/dt + dq/dy = 0,   q = -k(h) dp/dy + c(h),
    k(h) = Phi_p(h) h^3 / (12 eta),   c(h) = (v/2) (h - Rq Phi_s(h)),

which is Eq. 13 rearranged (q is the flow in +y per unit circumferential length, mm^2/s).

Discretisation on nodes y_1 < ... < y_n (the seal surface nodes in the coupled problem):

* Element flux. Between nodes a and b (length L, h linear), integrating dp/dy = (c - q)/k
  with q constant gives p_b - p_a = L (I2 - q I1), hence

      q_e = (I2 - (p_b - p_a) / L) / I1,   I1 = <1/k>,   I2 = <c/k>,

  the element averages taken by 3-point Gauss quadrature. The harmonic mean <1/k> is what
  makes the flux exact for steady flow in a stiffening gap; the scheme is second order in y
  when squeeze makes q vary inside an element.
* Upwinded Couette flow (on a seal: ``stiff`` = pi E' > 0, E' the seal's plane-strain
  modulus). Near the contact the balance carries the gap like a concentration, advected at
  v/2 against the diffusivity k S, where S = pi E' / (2 L) is the seal's stiffness to a gap
  alternating from node to node (a half-space under the mesh's shortest wavelength 2 L;
  :mod:`sealts.film.odd_even`). Where the element Peclet number

      P_e = (|v|/2) L / (k_e S) = |v| L^2 I1 / (pi E'),   k_e = 1/I1,

  is large, the flux above hardly sees such a mode: its harmonic averages weigh both nodes
  alike, and the film and the contact settle into a sawtooth that TS crawls through. The
  flux then gets the exponentially fitted (Il'in-Allen-Southwell) share of the upwind
  Couette flow,

      q_e += xi(P_e) (|v|/2) (c_a - c_b) / v,   xi(P) = coth(P/2) - 2/P,

  c_a, c_b = c(h) at the nodes: for P >> 1 it adds the upwind node's Couette flow less the
  two nodes' mean, so a node thicker than its neighbours sends out more than it takes in
  and the sawtooth decays; for P << 1 the added diffusivity xi |v| L / 4 ~ v^2 L^3 I1 / (24
  pi E') vanishes as L^3 under refinement, and with rigid surfaces (``stiff`` = 0, the
  film-only scenes) it is nil. The same cause, an advection-dominated Reynolds equation in
  the loaded contact, leads full-system EHL solvers to artificial diffusion (Habchi et al.,
  Advances in Engineering Software 46, 2012). dq/dL (returned) includes P's dependence on
  L.
* Nodal balance over the control volume of node i (half of each neighbouring element, M_i):

      R_i = M_i dh_eff_i/dt + q_{i+1/2} - q_{i-1/2} = 0,

  with Dirichlet rows p_1 = p_in, p_n = p_out. The boundary flows are the reactions of the
  end control volumes, Q_in = q_{3/2} + M_1 dh_1/dt and Q_out = q_{n-1/2} - M_n dh_n/dt, so
  Q_in - Q_out = d/dt sum_i M_i h_eff_i holds to round-off: the discrete mass balance is exact.

Element lengths. On the seal the nodes are the rod side's, at their current axial positions,
and where the rod side runs up a groove wall (pressed into it by the seal) neighbours share
one axial position to within the wall penalty's compliance, about 0.1 um per MPa, in either
order. The scheme takes every element length as

    L_e = sqrt(dy_e^2 + EPS_L^2),   dy_e = y_b - y_a,

so a reversed element is a short positive one and a vanishing one stays positive: it lies on
the wall, far from the rod, where the film's resistance L / h^3 is nil whatever L. EPS_L
(1e-9 mm) only keeps L_e positive and smooth where dy_e passes zero; an element of the
contact meshes (0.01 mm and more) keeps its length to round-off. The control volumes M_i of
the balance are half sums of the L_e.

h enters through :func:`sealts.film.gap.h_eff` (see there for the regularisation at h <= 0),
and the conductance uses Phi_p through the same C1 floor, smooth_floor(Phi_p, PHI_P_MIN), so a
flow factor that vanishes in full contact (Patir-Cheng below H = 0.5, a table starting at 0)
still leaves a finite, tiny conductance: k >= PHI_P_MIN h_floor^3 / (12 eta). Phi_p is
unchanged where it exceeds 2 PHI_P_MIN.
"""
import numba
import numpy as np

from .flow_factors import flow_factors
from .gap import h_eff, h_eff_rate, smooth_floor

PHI_P_MIN = 1e-3
EPS_L = 1e-9          # mm: the element lengths' floor (module docstring)

# 3-point Gauss-Legendre on [0, 1]
_GX = np.array([0.5 - 0.5 * np.sqrt(0.6), 0.5, 0.5 + 0.5 * np.sqrt(0.6)])
_GW = np.array([5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0])


@numba.njit(cache=True)
def element_length(dy):
    """L = sqrt(dy^2 + EPS_L^2) and dL/d(dy) of one element (module docstring)."""
    L = np.sqrt(dy * dy + EPS_L * EPS_L)
    return L, dy / L


def element_lengths(y):
    """The element lengths L_e of positions ``y`` and dL_e/d(dy_e) (arrays, n - 1)."""
    dy = np.diff(y)
    L = np.sqrt(dy * dy + EPS_L * EPS_L)
    return L, dy / L


@numba.njit(cache=True)
def conductance(h, eta, h_floor, model, par, th, tpp, tps):
    """Return (1/k, d(1/k)/dh, c/v, d(c/v)/dh) at one h; c/v = (h_eff - Rq Phi_s)/2."""
    he, dhe = h_eff(h, h_floor)
    pp0, dpp0, ps, dps = flow_factors(h, model, par, th, tpp, tps)
    pp, dfl = smooth_floor(pp0, PHI_P_MIN)
    dpp = dfl * dpp0
    srq = par[10] * par[0]  # -Rq for a rough seal, +Rq for a rough rod
    k = pp * he ** 3 / (12.0 * eta)
    dk = (dpp * he ** 3 + 3.0 * pp * he ** 2 * dhe) / (12.0 * eta)
    ik = 1.0 / k
    cv = 0.5 * (he + srq * ps)
    dcv = 0.5 * (dhe + srq * dps)
    return ik, -dk * ik * ik, cv, dcv


@numba.njit(cache=True)
def conductance_array(h, eta, h_floor, model, par, th, tpp, tps):
    """Nodal 1/k and c/v for output (see :func:`conductance`)."""
    ik = np.empty_like(h)
    cv = np.empty_like(h)
    for i in range(h.size):
        ik[i], _, cv[i], _ = conductance(h[i], eta, h_floor, model, par, th, tpp, tps)
    return ik, cv


@numba.njit(cache=True)
def upwind_weight(P):
    """xi(P) = coth(P/2) - 2/P and dxi/dP: the upwind weight of an element Peclet number."""
    if P < 0.1:      # the series: coth - 2/P cancels below
        P2 = P * P
        return (P * (1.0 / 6.0 - P2 / 360.0 + P2 * P2 / 15120.0 - P2 ** 3 / 604800.0),
                1.0 / 6.0 - P2 / 120.0 + P2 * P2 / 3024.0 - P2 ** 3 / 86400.0)
    if P > 60.0:
        return 1.0 - 2.0 / P, 2.0 / (P * P)
    s = np.sinh(0.5 * P)
    return 1.0 / np.tanh(0.5 * P) - 2.0 / P, -0.5 / (s * s) + 2.0 / (P * P)


@numba.njit(cache=True)
def element_fluxes(y, h, p, v, eta, h_floor, model, par, th, tpp, tps, stiff=0.0):
    """Element flows q_e and their derivatives.

    Returns q, dq/dp_a, dq/dp_b, dq/dh_a, dq/dh_b, dq/dL (arrays of length n - 1), with a
    the left and b the right node of each element.
    """
    ne = y.size - 1
    q = np.empty(ne)
    dqa = np.empty(ne)
    dqb = np.empty(ne)
    dha = np.empty(ne)
    dhb = np.empty(ne)
    dql = np.empty(ne)
    cvn = np.empty(ne + 1)
    dcvn = np.empty(ne + 1)
    if stiff > 0.0:
        for i in range(ne + 1):
            _, _, cvn[i], dcvn[i] = conductance(h[i], eta, h_floor, model, par, th, tpp, tps)
    av = abs(v)
    for e in range(ne):
        L = element_length(y[e + 1] - y[e])[0]
        i1 = 0.0
        i2 = 0.0
        di1a = 0.0
        di1b = 0.0
        di2a = 0.0
        di2b = 0.0
        for g in range(3):
            na = 1.0 - _GX[g]
            nb = _GX[g]
            hg = na * h[e] + nb * h[e + 1]
            ik, dik, cv, dcv = conductance(hg, eta, h_floor, model, par, th, tpp, tps)
            w = _GW[g]
            i1 += w * ik
            i2 += w * v * cv * ik
            di1a += w * dik * na
            di1b += w * dik * nb
            d2 = w * v * (dcv * ik + cv * dik)
            di2a += d2 * na
            di2b += d2 * nb
        dp = p[e + 1] - p[e]
        qe = (i2 - dp / L) / i1
        dqa[e] = 1.0 / (L * i1)
        dqb[e] = -1.0 / (L * i1)
        dha[e] = (di2a - qe * di1a) / i1
        dhb[e] = (di2b - qe * di1b) / i1
        dql[e] = dp / (L * L * i1)
        if stiff > 0.0 and av > 0.0:
            P = av * L * L * i1 / stiff
            xi, dxi = upwind_weight(P)
            jump = 0.5 * av * (cvn[e] - cvn[e + 1])
            qe += xi * jump
            dha[e] += dxi * P / i1 * di1a * jump + xi * 0.5 * av * dcvn[e]
            dhb[e] += dxi * P / i1 * di1b * jump - xi * 0.5 * av * dcvn[e + 1]
            dql[e] += dxi * 2.0 * P / L * jump
        q[e] = qe
    return q, dqa, dqb, dha, dhb, dql


@numba.njit(cache=True)
def storage(y, h, hd, h_floor):
    """Nodal storage M_i dh_eff_i/dt (M_i half the adjacent element lengths) and its
    derivatives with respect to h_i and dh_i/dt."""
    n = y.size
    s = np.empty(n)
    ds_dh = np.empty(n)
    ds_dhd = np.empty(n)
    for i in range(n):
        m = 0.0
        if i > 0:
            m += 0.5 * element_length(y[i] - y[i - 1])[0]
        if i < n - 1:
            m += 0.5 * element_length(y[i + 1] - y[i])[0]
        rate, drate = h_eff_rate(h[i], hd[i], h_floor)
        s[i] = m * rate
        ds_dh[i] = m * drate
        ds_dhd[i] = m * h_eff(h[i], h_floor)[1]
    return s, ds_dh, ds_dhd


def control_volumes(y):
    """Lumped control-volume lengths M_i (mm): half the adjacent element lengths."""
    m = np.zeros_like(y)
    d = 0.5 * element_lengths(y)[0]
    m[:-1] += d
    m[1:] += d
    return m


class ControlVolumeScheme:
    """The default scheme's algebra on n film nodes; unknowns are the n nodal pressures.

    Interface shared with :class:`sealts.film.paper_scheme.PaperScheme`: ``size`` unknowns,
    a fixed local COO ``pattern``, ``residual``/``jacobian`` given (x, h, dh/dt), the boundary
    flows with their derivatives, and nodal pressures and pressure gradients for output.
    """

    name = "fv"

    def __init__(self, y, eta, v_of_t, p_in, p_out, ff, h_floor):
        self.y = np.asarray(y, float)
        self.n = self.y.size
        self.size = self.n
        self.eta, self.v_of_t, self.ff, self.h_floor = eta, v_of_t, ff, h_floor
        self.p_in, self.p_out = p_in, p_out
        ne = self.n - 1
        a = np.arange(ne)
        b = a + 1
        r = np.stack([a, a, b, b], 1).ravel()
        c = np.stack([a, b, a, b], 1).ravel()
        self._keep = (r != 0) & (r != self.n - 1)
        self.pattern = (np.concatenate([r[self._keep], [0, self.n - 1]]),
                        np.concatenate([c[self._keep], [0, self.n - 1]]))
        # boundary flows depend on the first and the last two pressures
        self.q_cols = (np.array([0, 1]), np.array([self.n - 2, self.n - 1]))
        self.row_scale = np.ones(self.n)

    def _ff(self):
        f = self.ff
        return f.model, f.par, f.table_h, f.table_pp, f.table_ps

    def _fluxes(self, t, x, h, hd):
        q, dqa, dqb, dha, dhb, _ = element_fluxes(self.y, h, x, self.v_of_t(t), self.eta,
                                                  self.h_floor, *self._ff())
        s, _, _ = storage(self.y, h, hd, self.h_floor)
        return q, dqa, dqb, s

    def set_row_scale(self, t, x, h, hd):
        """Fix each balance row's scale to its diagonal at this state (rows then read in MPa)."""
        _, dqa, dqb, _ = self._fluxes(t, x, h, hd)
        d = np.ones(self.n)
        d[1:-1] = dqa[1:] - dqb[:-1]
        self.row_scale = 1.0 / d

    def residual(self, t, x, h, hd):
        """Scaled residual (length n) and the boundary flows (Q_in, Q_out) per unit length."""
        q, _, _, s = self._fluxes(t, x, h, hd)
        r = s.copy()
        r[:-1] += q
        r[1:] -= q
        q_in, q_out = q[0] + s[0], q[-1] - s[-1]
        r[0] = x[0] - self.p_in
        r[-1] = x[-1] - self.p_out
        return r * self.row_scale, q_in, q_out

    def jacobian(self, t, x, h, hd):
        """Values for ``pattern`` and the derivatives of (Q_in, Q_out) at ``q_cols``."""
        _, dqa, dqb, _, _, _ = element_fluxes(self.y, h, x, self.v_of_t(t), self.eta,
                                              self.h_floor, *self._ff())
        vals = np.stack([dqa, dqb, -dqa, -dqb], 1).ravel()[self._keep]
        rows = self.pattern[0]
        vals = np.concatenate([vals * self.row_scale[rows[:-2]], [1.0, 1.0]])
        return vals, (np.array([dqa[0], dqb[0]]), np.array([dqa[-1], dqb[-1]]))

    def pressure(self, x):
        return np.asarray(x[:self.n])

    def pressure_gradient(self, t, x, h, hd):
        """Nodal dp/dy = (c(h) - q)/k(h), with q the nodal flow (mean of the element flows)."""
        q, _, _, s = self._fluxes(t, x, h, hd)
        qn = np.empty(self.n)
        qn[1:-1] = 0.5 * (q[:-1] + q[1:])
        qn[0], qn[-1] = q[0] + s[0], q[-1] - s[-1]
        ik, cv = conductance_array(h, self.eta, self.h_floor, *self._ff())
        return (self.v_of_t(t) * cv - qn) * ik

    def initial_guess(self):
        return np.linspace(self.p_in, self.p_out, self.n)
