"""Finite-strain Prony viscoelasticity with internal variables in the DAE (paper Eq. 7-9).

The model is Simo's (1987), as in ABAQUS's finite-strain viscoelasticity with a shear-only
Prony series: the second Piola-Kirchhoff stress is

    S = S_vol + S_iso(C) - sum_i g_i H_i,                                     (a)
    tau_i A(theta) dH_i/dt + H_i = S_iso(C),                                   (b)

where S_iso = F^-1 dpsi_iso/dF is the isochoric (deviatoric) stress of the *instantaneous*
material (C10_0 = C10 / (1 - sum g), likewise C01), S_vol the elastic bulk response, and
A(theta) the WLF shift (Eq. 11-12). At equilibrium H_i = S_iso and S = S_vol +
(1 - sum g) S_iso, the long-term (scene) material. For a step strain at small strain the
shear stress is G_0 g_R(t) gamma (Eq. 7). Both (a) and (b) are linear in H_i.

Terms folded by :func:`sealts.solid.prony.classify`:

* relaxed (H_i = S_iso): the elastic term's C10 is C10_0 (1 - sum_relaxed g);
* frozen (H_i = H_i(0)): a fixed stress sum_frozen g_i H_i(0) in (a);
* active: H_i, four components (11, 22, 33, 12) per Gauss point, are unknowns of the DAE
  (the ``prony`` field of :class:`sealts.mesh.layout.Layout`), integrated by the TS with
  the displacements.

This module is the term for (a) minus its elastic part, and for (b). With P = F S in the
five entries f = (F11, F12, F21, F22, F33) of :mod:`.neo_hooke`, P(f, H) = L(f) H, and

    r_u = - sum_g w_g B_g^T L(f_g) H_tot,g,      H_tot = sum_frozen g_i H_i(0) + sum_act g_i H_i,
    r_H,i = g_i w_g (tau_i A dH_i/dt + H_i - S_iso(f_g)),

(rows of (b) scaled by g_i w_g, so they are forces times length like r_u). Jacobian blocks:
dr_u/du = -w B^T M(H_tot) B (M = dP/df at fixed H), dr_u/dH_i = -g_i w B^T L(f),
dr_H/du = -g_i w dS_iso/df B, and the diagonal dr_H/dH = g_i w (shift tau_i A + 1).
"""
import numba
import numpy as np

from ..core import BufferPool, Term
from .mooney_rivlin import isochoric_i2_add
from .neo_hooke import det_into, isochoric_into
from .q1p0 import _bt_a_b, _bt_v, deformation_into


@numba.njit(cache=True, inline="always")
def iso_pk2_into(f, c10, c01, dJ, HJ, P, A, S, dS, tangent=True):
    """S_iso = F^-1 dpsi_iso/dF as (S11, S22, S33, S12) into S (4), and with ``tangent``
    its derivative in f into dS (4x5); dJ, HJ, P, A: work buffers (5, 5x5, 5, 5x5)."""
    J = det_into(f, dJ, HJ)
    isochoric_into(f, J, dJ, HJ, c10, P, A, tangent)
    if c01 != 0.0:
        isochoric_i2_add(f, J, dJ, HJ, c01, P, A, tangent)
    a = f[0] * f[3] - f[1] * f[2]
    i00, i01, i10, i11 = f[3] / a, -f[1] / a, -f[2] / a, f[0] / a
    # S (2x2) = a^-1 P2x2, P2x2 = [[P0, P1], [P2, P3]]
    s11 = i00 * P[0] + i01 * P[2]
    s12 = i00 * P[1] + i01 * P[3]
    s21 = i10 * P[0] + i11 * P[2]
    s22 = i10 * P[1] + i11 * P[3]
    S[0], S[1], S[2], S[3] = s11, s22, P[4] / f[4], 0.5 * (s12 + s21)
    if not tangent:
        return
    for k in range(5):
        # d(a^-1 P) = a^-1 (dP - da S), da = unit entry k (k < 4)
        d0, d1, d2, d3 = A[0, k], A[1, k], A[2, k], A[3, k]
        if k == 0:
            d0 -= s11
            d1 -= s12
        elif k == 1:
            d0 -= s21
            d1 -= s22
        elif k == 2:
            d2 -= s11
            d3 -= s12
        elif k == 3:
            d2 -= s21
            d3 -= s22
        dS[0, k] = i00 * d0 + i01 * d2
        dS[1, k] = i10 * d1 + i11 * d3
        dS[3, k] = 0.5 * (i00 * d1 + i01 * d3 + i10 * d0 + i11 * d2)
        dS[2, k] = (A[4, k] - (S[2] if k == 4 else 0.0)) / f[4]


@numba.njit(cache=True)
def iso_pk2(f, c10, c01):
    """S_iso = F^-1 dpsi_iso/dF as (S11, S22, S33, S12), and its derivative (4x5) in f."""
    S, dS = np.empty(4), np.empty((4, 5))
    iso_pk2_into(f, c10, c01, np.empty(5), np.empty((5, 5)), np.empty(5),
                 np.empty((5, 5)), S, dS)
    return S, dS


@numba.njit(cache=True, inline="always")
def _pk1_into(f, H, P):
    """P = L(f) H for the symmetric H = (H11, H22, H33, H12)."""
    P[0] = f[0] * H[0] + f[1] * H[3]
    P[1] = f[0] * H[3] + f[1] * H[1]
    P[2] = f[2] * H[0] + f[3] * H[3]
    P[3] = f[2] * H[3] + f[3] * H[1]
    P[4] = f[4] * H[2]


@numba.njit(cache=True, inline="always")
def _pk1_by_f_into(H, scale, M):
    """M = scale dP/df at fixed H (5x5)."""
    for i in range(5):
        for k in range(5):
            M[i, k] = 0.0
    M[0, 0], M[0, 1] = scale * H[0], scale * H[3]
    M[1, 0], M[1, 1] = scale * H[3], scale * H[1]
    M[2, 2], M[2, 3] = scale * H[0], scale * H[3]
    M[3, 2], M[3, 3] = scale * H[3], scale * H[1]
    M[4, 4] = scale * H[2]


@numba.njit(cache=True, inline="always")
def _pk1_by_h_into(f, L):
    """L = dP/dH (5x4)."""
    for i in range(5):
        for c in range(4):
            L[i, c] = 0.0
    L[0, 0], L[0, 3] = f[0], f[1]
    L[1, 3], L[1, 1] = f[0], f[1]
    L[2, 0], L[2, 3] = f[2], f[3]
    L[3, 3], L[3, 1] = f[2], f[3]
    L[4, 2] = f[4]


@numba.njit(cache=True)
def prony_kernel(u, conn, W, B, c10, c01, g, tau, H, Hdot, Hfrozen, shift, jac,
                 condensed=False):
    """All elements at once. u node-major displacements; H, Hdot (ne, 4, na, 4) active
    internal variables and rates; Hfrozen (ne, 4, 4) = sum_frozen g_i H_i(0); tau (na,) the
    shifted relaxation times. Returns r_u (ne, 8), r_H (ne, 4, na, 4); a non-empty ``jac``
    is overwritten with the Jacobian's values in :class:`PronyTerm`'s COO order: K_uu (ne,
    8, 8), K_uH (ne, 4, na, 8, 4), K_Hu (ne, 4, na, 4, 8), K_HH (ne, 4, na, 4) (the
    diagonal, one value per internal variable); an empty one skips the blocks (a residual
    alone). With ``condensed``, ``jac`` (ne * 320) gets instead the condensed K_uu (ne, 8,
    8) (:meth:`PronyTerm.condensed_values`), then B^T L and dS_iso B of every Gauss point
    (ne, 4, 64). B as :func:`.q1p0.gauss_operators` builds it (its zero pattern is used);
    every work array is allocated once per call."""
    ne, na = conn.shape[0], g.shape[0]
    ru = np.zeros((ne, 8))
    rH = np.zeros((ne, 4, na, 4))
    tangent = jac.size > 0
    nk = ne if tangent else 0
    nb = 0 if condensed else nk   # the off-diagonal blocks' elements
    o1, o2, o3 = nk * 64, nk * 64 + nb * na * 128, nk * 64 + nb * na * 256
    jac[:o1] = 0.0                 # K_uu is summed over the Gauss points; the rest is set
    Kuu = jac[:o1].reshape((nk, 8, 8))
    KuH = jac[o1:o2].reshape((nb, 4, na, 8, 4))
    KHu = jac[o2:o3].reshape((nb, 4, na, 4, 8))
    KHH = jac[o3:o3 + nb * na * 16].reshape((nb, 4, na, 4))
    # condensed: the Gauss points' B^T L and dS B, and sum_i g_i / (shift tau_i + 1)
    ng = nk if condensed else 0
    GP = jac[o1:o1 + ng * 256].reshape((ng, 4, 64))
    if na == 0:
        GP[:] = 0.0                # no internal variable: nothing couples through them
    csum = 0.0
    for k in range(na):
        csum += g[k] / (shift * tau[k] + 1.0)
    ue, f, Htot, P = np.empty(8), np.empty(5), np.empty(4), np.empty(5)
    M, MB = np.empty((5, 5)), np.empty((5, 8))
    S, dS, L = np.empty(4), np.empty((4, 5)), np.empty((5, 4))
    BtL, dSB = np.empty((8, 4)), np.empty((4, 8))
    dJ, HJ, Pi, Ai = np.empty(5), np.empty((5, 5)), np.empty(5), np.empty((5, 5))
    for e in range(ne):
        for a in range(4):
            ue[2 * a] = u[2 * conn[e, a]]
            ue[2 * a + 1] = u[2 * conn[e, a] + 1]
        for q in range(4):
            Bq = B[e, q]
            w = W[e, q]
            deformation_into(Bq, ue, f)
            for c in range(4):
                Htot[c] = Hfrozen[e, q, c]
            for k in range(na):
                for c in range(4):
                    Htot[c] += g[k] * H[e, q, k, c]
            _pk1_into(f, Htot, P)
            _bt_v(Bq, P, ru[e], -w)
            if tangent:
                _pk1_by_f_into(Htot, -w, M)
                _bt_a_b(Bq, M, Kuu[e], MB)
            if na == 0:
                continue
            iso_pk2_into(f, c10, c01, dJ, HJ, Pi, Ai, S, dS, tangent)
            for k in range(na):
                gw = g[k] * w
                for c in range(4):
                    rH[e, q, k, c] = gw * (tau[k] * Hdot[e, q, k, c] + H[e, q, k, c] - S[c])
            if not tangent:
                continue
            _pk1_by_h_into(f, L)
            for j in range(0, 8, 2):       # B^T L and dS B on B's zero pattern
                for c in range(4):
                    BtL[j, c] = Bq[0, j] * L[0, c] + Bq[1, j] * L[1, c] + Bq[4, j] * L[4, c]
                    BtL[j + 1, c] = Bq[2, j + 1] * L[2, c] + Bq[3, j + 1] * L[3, c]
                    dSB[c, j] = dS[c, 0] * Bq[0, j] + dS[c, 1] * Bq[1, j] + dS[c, 4] * Bq[4, j]
                    dSB[c, j + 1] = dS[c, 2] * Bq[2, j + 1] + dS[c, 3] * Bq[3, j + 1]
            if condensed:
                # K_uu - sum_i K_uH,i K_HH,i^-1 K_Hu,i = K_uu - w csum B^T L dS B
                for j in range(8):
                    for c in range(4):
                        GP[e, q, 4 * j + c] = BtL[j, c]
                        GP[e, q, 32 + 8 * c + j] = dSB[c, j]
                    for m in range(8):
                        acc = 0.0
                        for c in range(4):
                            acc += BtL[j, c] * dSB[c, m]
                        Kuu[e, j, m] -= w * csum * acc
                continue
            for k in range(na):
                gw = g[k] * w
                d = gw * (shift * tau[k] + 1.0)
                for c in range(4):
                    KHH[e, q, k, c] = d
                    for j in range(8):
                        KuH[e, q, k, j, c] = -gw * BtL[j, c]
                        KHu[e, q, k, c, j] = -gw * dSB[c, j]
    return ru, rH


@numba.njit(cache=True)
def _gp_dsb_x(GP, e, q, dofs, x, out):
    """out (4) = dS B x_e at the Gauss point (e, q) (GP as the condensed kernel stores it)."""
    for c in range(4):
        acc = 0.0
        for j in range(8):
            acc += GP[e, q, 32 + 8 * c + j] * x[dofs[e, j]]
        out[c] = acc


@numba.njit(cache=True)
def condensed_reduce(GP, dofs, hdofs, a, b, z):
    """z[u] += -K_uH D^-1 b_H = sum over Gauss points of B^T L sum_i a_i b_H,i, with
    a_i = 1 / (shift tau_i + 1) (K_uH,i = -g_i w B^T L, D_i = g_i w (shift tau_i + 1))."""
    ne, na = dofs.shape[0], a.size
    v = np.empty(4)
    for e in range(ne):
        for q in range(4):
            for c in range(4):
                acc = 0.0
                for k in range(na):
                    acc += a[k] * b[hdofs[e, q, k, c]]
                v[c] = acc
            for j in range(8):
                acc = 0.0
                for c in range(4):
                    acc += GP[e, q, 4 * j + c] * v[c]
                z[dofs[e, j]] += acc


@numba.njit(cache=True)
def condensed_back(GP, dofs, hdofs, W, g, a, b, x):
    """x_H = D^-1 (b_H - K_Hu x_u) = a_i (b_H,i / (g_i w) + dS B x_e) (K_Hu,i = -g_i w dS
    B), x_u given."""
    ne, na = dofs.shape[0], a.size
    d = np.empty(4)
    for e in range(ne):
        for q in range(4):
            _gp_dsb_x(GP, e, q, dofs, x, d)
            w = W[e, q]
            for k in range(na):
                for c in range(4):
                    h = hdofs[e, q, k, c]
                    x[h] = a[k] * (b[h] / (g[k] * w) + d[c])


@numba.njit(cache=True)
def condensed_mult(GP, dofs, hdofs, W, g, a, x, y):
    """y += the product of x with the blocks the condensed K_uu leaves out:
    y_u += K_uH (D^-1 K_Hu x_u + x_H) = -w B^T L sum_i g_i (x_H,i - a_i dS B x_e),
    y_H += K_Hu x_u + D x_H = g_i w (x_H,i / a_i - dS B x_e)."""
    ne, na = dofs.shape[0], a.size
    d, v = np.empty(4), np.empty(4)
    for e in range(ne):
        for q in range(4):
            _gp_dsb_x(GP, e, q, dofs, x, d)
            w = W[e, q]
            for c in range(4):
                v[c] = 0.0
            for k in range(na):
                for c in range(4):
                    h = hdofs[e, q, k, c]
                    v[c] += g[k] * (x[h] - a[k] * d[c])
                    y[h] += g[k] * w * (x[h] / a[k] - d[c])
            for j in range(8):
                acc = 0.0
                for c in range(4):
                    acc += GP[e, q, 4 * j + c] * v[c]
                y[dofs[e, j]] -= w * acc


class PronyTerm(Term):
    """Viscous stress of a Prony series (frozen and active terms) and the evolution (b) of
    its active internal variables; see the module docstring.

    ``solid``: the seal's :class:`SolidTerm` (geometry, element dofs); ``instantaneous``:
    the material with C10_0, C01_0; ``g``, ``tau`` (s): the active terms; ``hdofs``
    (ne, 4 * 4 * na): their dofs (Layout.prony_dofs); ``frozen`` (ne, 4, 4): the fixed stress
    sum_frozen g_i H_i(0) or None; ``shift(t)``: the WLF factor A(theta(t))."""

    def __init__(self, solid, instantaneous, g, tau, hdofs, frozen=None, shift=lambda t: 1.0):
        self.solid, self.mat = solid, instantaneous
        self.g, self.tau = np.asarray(g, float), np.asarray(tau, float)
        self.shift = shift
        ne, na = solid.conn.shape[0], self.g.size
        self.hdofs = np.asarray(hdofs, np.int64).reshape(ne, 4, na, 4)
        self.frozen = np.zeros((ne, 4, 4)) if frozen is None else np.asarray(frozen, float)
        ed = solid.dofs                                            # (ne, 8)
        hd = self.hdofs
        shape_uH = (ne, 4, na, 8, 4)
        rows = [np.repeat(ed, 8, axis=1).ravel(),
                np.broadcast_to(ed[:, None, None, :, None], shape_uH).ravel(),
                np.broadcast_to(hd[:, :, :, :, None], (ne, 4, na, 4, 8)).ravel(),
                hd.ravel()]
        cols = [np.tile(ed, (1, 8)).ravel(),
                np.broadcast_to(hd[:, :, :, None, :], shape_uH).ravel(),
                np.broadcast_to(ed[:, None, None, None, :], (ne, 4, na, 4, 8)).ravel(),
                hd.ravel()]
        self.rows, self.cols = np.concatenate(rows), np.concatenate(cols)
        self._jac = self._cstate = None
        self._cpool = BufferPool()        # the condensed values and what they need
        # the internal variables one run of dofs (the serial layout: cells after vertices):
        # read and added as a slice, not gathered and scattered entry by entry
        h0 = int(hd.min()) if hd.size else 0
        self._hrun = (slice(h0, h0 + hd.size) if np.array_equal(hd.ravel(),
                                                                 np.arange(h0, h0 + hd.size))
                      else None)

    def _evaluate(self, t, u, udot, shift, jac, condensed=False):
        s = self.solid
        us = u[s.udofs].ravel()
        hd = self.hdofs if self._hrun is None else self._hrun
        H = u[hd].reshape(self.hdofs.shape)
        Hd = np.zeros_like(H) if udot is None else udot[hd].reshape(self.hdofs.shape)
        A = self.shift(t)
        return prony_kernel(us, s.conn, s.W, s.B, self.mat.c10, self.mat.c01, self.g,
                            A * self.tau, H, Hd, self.frozen, shift, jac, condensed)

    def add_residual(self, t, u, udot, f):
        ru, rH = self._evaluate(t, u, udot, 0.0, np.empty(0))
        f += np.bincount(self.solid.dofs.ravel(), ru.ravel(), minlength=f.size)
        if self._hrun is None:
            f[self.hdofs] += rH
        else:
            f[self._hrun] += rH.ravel()

    def jacobian_values(self, t, u, udot, shift):
        # one buffer, overwritten by every call (the Problem copies the values out): a
        # fresh array of this size comes from the OS and is paid for again in page faults
        if self._jac is None:
            self._jac = np.empty(self.rows.size)
        self._evaluate(t, u, udot, shift, self._jac)
        return self._jac

    # ---- the condensation of the internal variables (sealts.problem.condensed) ----------
    # Per Gauss point and active term the blocks are K_uH,i = -g_i w B^T L,
    # K_Hu,i = -g_i w dS B and the diagonal D_i = g_i w (shift tau_i + 1), so the Schur
    # complement's part of this term is one 8 x 8 block per Gauss point,
    #     K_uu - sum_i K_uH,i D_i^-1 K_Hu,i = K_uu - w (sum_i g_i / (shift tau_i + 1)) B^T L dS B,
    # and the right-hand side's reduction, the back-substitution and the product with the
    # blocks left out need B^T L and dS B alone: the 4 x 8 x 2 x na values of the
    # off-diagonal blocks per Gauss point are never formed.

    @property
    def qdofs(self):
        """The internal variables: the diagonal block this term condenses."""
        return self.hdofs.ravel()

    @property
    def n_condensed(self):
        """How many of the first COO entries (K_uu) :meth:`condensed_values` gives."""
        return self.solid.conn.shape[0] * 64

    @property
    def can_condense(self):
        """D_i = g_i w (shift tau_i A + 1) is positive and finite at every Gauss point (the
        back-substitution divides by g_i w)."""
        W = self.solid.W
        return bool(np.all(self.g > 0.0) and np.all(np.isfinite(self.g))
                    and np.all(np.isfinite(W)) and np.all(W > 0.0))

    def condensed_values(self, t, u, udot, shift):
        """K_uu - K_uH D^-1 K_Hu on the first :attr:`n_condensed` entries of the pattern;
        also keeps, as :meth:`condensed_state`, what :meth:`condensed_reduce`,
        :meth:`condensed_back` and :meth:`condensed_mult` need. The values are a view of
        that state (a buffer of the term's pool, not reused while anyone holds it)."""
        ne, na = self.solid.conn.shape[0], self.g.size
        buf = self._cpool.get(ne * 320 + na)
        self._evaluate(t, u, udot, shift, buf[:ne * 320], condensed=True)
        buf[ne * 320:] = 1.0 / (shift * self.shift(t) * self.tau + 1.0)   # a_i
        self._cstate = buf
        return buf[:ne * 64]

    def condensed_state(self):
        """The last :meth:`condensed_values`' state: a preconditioner set up from those
        values keeps it for its reduction and back-substitution, through later
        evaluations (a lagged preconditioner)."""
        return self._cstate

    def _parts(self, state):
        ne = self.solid.conn.shape[0]
        state = self._cstate if state is None else state
        return state[ne * 64:ne * 320].reshape(ne, 4, 64), state[ne * 320:]

    def condensed_reduce(self, b, z, state=None):
        """z[u dofs] += -K_uH D^-1 b_H (b, z full arrays of the problem's dofs), of the
        Jacobian of ``state`` (the last by default)."""
        GP, a = self._parts(state)
        condensed_reduce(GP, self.solid.dofs, self.hdofs, a, b, z)

    def condensed_back(self, b, x, state=None):
        """x[H dofs] = D^-1 (b_H - K_Hu x_u), from x's displacements."""
        GP, a = self._parts(state)
        condensed_back(GP, self.solid.dofs, self.hdofs, self.solid.W, self.g, a, b, x)

    def condensed_mult(self, x, y, state=None):
        """y += (K_uH D^-1 K_Hu x_u + K_uH x_H, K_Hu x_u + D x_H): with the condensed K_uu's
        product, the Jacobian's."""
        GP, a = self._parts(state)
        condensed_mult(GP, self.solid.dofs, self.hdofs, self.solid.W, self.g, a, x, y)

    def viscous_cauchy(self, u):
        """The Prony part of the Cauchy stress at every Gauss point, (ne, 4, 4) as
        (rr, zz, tt, rz): sigma_v = -(1/J) F H_tot F^T, the push-forward of the -sum g_i H_i
        of (a) (frozen and active terms). Added to the elastic term's Cauchy stress it is
        the seal's stress (output only)."""
        f = self.solid.state(u)[0]                                   # (ne, 4, 5)
        H = self.frozen + np.einsum("a,eqak->eqk", self.g, u[self.hdofs])
        F11, F12, F21, F22, F33 = np.moveaxis(f, -1, 0)
        J = (F11 * F22 - F12 * F21) * F33
        h11, h22, h33, h12 = np.moveaxis(H, -1, 0)
        rr = F11 * F11 * h11 + 2.0 * F11 * F12 * h12 + F12 * F12 * h22
        zz = F21 * F21 * h11 + 2.0 * F21 * F22 * h12 + F22 * F22 * h22
        rz = F11 * F21 * h11 + (F11 * F22 + F12 * F21) * h12 + F12 * F22 * h22
        tt = F33 * F33 * h33
        return -np.stack([rr, zz, tt, rz], -1) / J[..., None]

    def equilibrium(self, u):
        """H_i = S_iso(u) at every Gauss point, for every active term: the relaxed start,
        (ne, 4, na, 4); also the frozen-stress unit S_iso (ne, 4, 4)."""
        s = self.solid
        S = iso_stress(u[s.udofs].ravel(), s.conn, s.B, self.mat.c10, self.mat.c01)
        return np.repeat(S[:, :, None, :], self.g.size, axis=2), S


@numba.njit(cache=True)
def iso_stress(u, conn, B, c10, c01):
    """S_iso (ne, 4, 4) at every Gauss point of the displacement u (node-major)."""
    ne = conn.shape[0]
    out = np.empty((ne, 4, 4))
    for e in range(ne):
        for q in range(4):
            f = np.array([1.0, 0.0, 0.0, 1.0, 1.0])
            for a in range(4):
                for d in range(2):
                    val = u[2 * conn[e, a] + d]
                    for i in range(5):
                        f[i] += B[e, q, i, 2 * a + d] * val
            S, _ = iso_pk2(f, c10, c01)
            out[e, q] = S
    return out
