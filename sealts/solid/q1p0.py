"""Four-node quadrilaterals with constant pressure (Q1/P0 mean dilatation), finite strain.

Total Lagrangian, axisymmetric (r, z) or plane strain (x, y). The element energy is

    W_e(u) = sum_g w_g psi_iso(F_g) + V_e U(theta_e),   psi_iso Neo-Hooke or Mooney-Rivlin,
    theta_e = v_e / V_e,  v_e = sum_g w_g J_g,  V_e = sum_g w_g,

the Simo-Taylor-Pister mean-dilatation form of the u-p (hybrid) element with the element
pressure p_e = U'(theta_e) condensed out; the family ABAQUS calls CAX4H/CPE4H. It does not
lock for K/G ~ 1000 (rubber: C10 = 1.064 MPa, D1 = 0.001 mm^2/N). 2x2 Gauss points,
w_g = det(J0) (times 2 pi R_g in axisymmetry, so forces are totals over the circumference;
per mm of depth in plane strain).

Since f = (F11, F12, F21, F22, F33) is linear in the element displacements, f = f0 + B u_e,
the residual and consistent tangent are exact:

    r_e = sum_g w_g B_g^T P_g + U'(theta) sum_g w_g B_g^T dJ_g,
    K_e = sum_g w_g B_g^T (A_g + U'(theta) H_J,g) B_g + U''(theta)/V_e b b^T,
    b = sum_g w_g B_g^T dJ_g.

Element dofs are ordered (u_r, u_z) per node, nodes counter-clockwise.
"""
import math
import os

import numba
import numpy as np

from .mooney_rivlin import isochoric_i2_add
from .neo_hooke import det_into, isochoric_into, volumetric

_G = 1.0 / math.sqrt(3.0)
GAUSS = np.array([[-_G, -_G], [_G, -_G], [_G, _G], [-_G, _G]])
_XI = np.array([-1.0, 1.0, 1.0, -1.0])
_ETA = np.array([-1.0, -1.0, 1.0, 1.0])


@numba.njit(cache=True, inline="always")
def deformation_into(B, ue, f):
    """f = (F11, F12, F21, F22, F33) = I + B u_e into f, for a B of :func:`gauss_operators`
    (u_r columns even, u_z columns odd)."""
    f[0] = 1.0 + B[0, 0] * ue[0] + B[0, 2] * ue[2] + B[0, 4] * ue[4] + B[0, 6] * ue[6]
    f[1] = B[1, 0] * ue[0] + B[1, 2] * ue[2] + B[1, 4] * ue[4] + B[1, 6] * ue[6]
    f[2] = B[2, 1] * ue[1] + B[2, 3] * ue[3] + B[2, 5] * ue[5] + B[2, 7] * ue[7]
    f[3] = 1.0 + B[3, 1] * ue[1] + B[3, 3] * ue[3] + B[3, 5] * ue[5] + B[3, 7] * ue[7]
    f[4] = 1.0 + B[4, 0] * ue[0] + B[4, 2] * ue[2] + B[4, 4] * ue[4] + B[4, 6] * ue[6]


@numba.njit(cache=True, inline="always")
def _bt_v(B, v, out, scale):
    """out += scale * B^T v for a B of :func:`gauss_operators` (5x8): the u_r columns (even)
    have entries in rows 0, 1, 4 only, the u_z columns (odd) in rows 2, 3."""
    for a in range(4):
        j = 2 * a
        out[j] += scale * (B[0, j] * v[0] + B[1, j] * v[1] + B[4, j] * v[4])
        out[j + 1] += scale * (B[2, j + 1] * v[2] + B[3, j + 1] * v[3])


@numba.njit(cache=True, inline="always")
def _bt_a_b(B, A, out, MB):
    """out += B^T A B for a B of :func:`gauss_operators` (5x8, its zero pattern as in
    :func:`_bt_v`); A 5x5, MB a 5x8 work buffer."""
    for j in range(0, 8, 2):
        for i in range(5):
            MB[i, j] = A[i, 0] * B[0, j] + A[i, 1] * B[1, j] + A[i, 4] * B[4, j]
            MB[i, j + 1] = A[i, 2] * B[2, j + 1] + A[i, 3] * B[3, j + 1]
    for j in range(0, 8, 2):
        for l in range(8):
            out[j, l] += B[0, j] * MB[0, l] + B[1, j] * MB[1, l] + B[4, j] * MB[4, l]
            out[j + 1, l] += B[2, j + 1] * MB[2, l] + B[3, j + 1] * MB[3, l]


@numba.njit(cache=True)
def gauss_operators(X, conn, axisym):
    """Per element and Gauss point: weight w (ne, 4), B (ne, 4, 5, 8), radius R (ne, 4)."""
    ne = conn.shape[0]
    W = np.empty((ne, 4))
    B = np.zeros((ne, 4, 5, 8))
    R = np.empty((ne, 4))
    for e in range(ne):
        xe = X[conn[e]]
        for g in range(4):
            xi, et = GAUSS[g, 0], GAUSS[g, 1]
            N = 0.25 * (1.0 + _XI * xi) * (1.0 + _ETA * et)
            dNxi = 0.25 * _XI * (1.0 + _ETA * et)
            dNet = 0.25 * _ETA * (1.0 + _XI * xi)
            j11 = j12 = j21 = j22 = r = 0.0
            for a in range(4):
                j11 += dNxi[a] * xe[a, 0]
                j12 += dNxi[a] * xe[a, 1]
                j21 += dNet[a] * xe[a, 0]
                j22 += dNet[a] * xe[a, 1]
                r += N[a] * xe[a, 0]
            det = j11 * j22 - j12 * j21
            dN1 = (j22 * dNxi - j12 * dNet) / det   # d/dX1 (r or x)
            dN2 = (-j21 * dNxi + j11 * dNet) / det  # d/dX2 (z or y)
            R[e, g] = r
            W[e, g] = det * (2.0 * math.pi * r if axisym else 1.0)
            for a in range(4):
                B[e, g, 0, 2 * a] = dN1[a]
                B[e, g, 1, 2 * a] = dN2[a]
                B[e, g, 2, 2 * a + 1] = dN1[a]
                B[e, g, 3, 2 * a + 1] = dN2[a]
                if axisym:
                    B[e, g, 4, 2 * a] = N[a] / r
    return W, B, R


@numba.njit(cache=True)
def _element(e, u, conn, W, B, c10, c01, d1, j_th, tangent, r, K, f_all, P_all, p_el,
             th_el, e_el, bad, ue, b, dJ, HJ, A, M, MB):
    """Element e of :func:`element_forces` into its rows of the outputs (r ... bad), with
    the work arrays ue ... MB."""
    for a in range(4):
        ue[2 * a] = u[2 * conn[e, a]]
        ue[2 * a + 1] = u[2 * conn[e, a] + 1]
    V = 0.0
    v = 0.0
    en = 0.0
    b[:] = 0.0
    for g in range(4):
        Bg = B[e, g]
        f = f_all[e, g]
        deformation_into(Bg, ue, f)
        J = det_into(f, dJ[g], HJ[g])
        if J <= 0.0:
            bad[e] = True
            J = 1.0        # finite stand-in: the caller discards this state
        P = P_all[e, g]
        psi = isochoric_into(f, J, dJ[g], HJ[g], c10, P, A[g], tangent)
        if c01 != 0.0:
            psi += isochoric_i2_add(f, J, dJ[g], HJ[g], c01, P, A[g], tangent)
        w = W[e, g]
        en += w * psi
        _bt_v(Bg, P, r[e], w)
        _bt_v(Bg, dJ[g], b, w)
        V += w
        v += w * J
    theta = v / V
    U, dU, d2U = volumetric(theta, d1, j_th)
    e_el[e] = en + V * U
    for j in range(8):
        r[e, j] += dU * b[j]
    p_el[e] = dU
    th_el[e] = theta
    if not tangent:
        return
    Ke = K[e]
    for g in range(4):
        w = W[e, g]
        for i in range(5):
            for k in range(5):
                M[i, k] = w * (A[g, i, k] + dU * HJ[g, i, k])
        _bt_a_b(B[e, g], M, Ke, MB)
    c = d2U / V
    for j in range(8):
        for l in range(8):
            Ke[j, l] += c * b[j] * b[l]


CHUNKS = 16     # element_forces' blocks of elements, shared among numba's threads

# One thread unless NUMBA_NUM_THREADS asks for more: alone on this 2-core machine two threads
# make the default cycle 6 % faster, but two runs side by side with two threads each took
# three to eight times as long (the threads wait for each other at every call's barrier)
if "NUMBA_NUM_THREADS" not in os.environ:
    numba.set_num_threads(1)


@numba.njit(cache=True, parallel=True)
def element_forces(u, conn, W, B, c10, c01, d1, j_th, tangent=True):
    """Internal forces r (ne, 8), tangents K (ne, 8, 8) and energy of all elements.

    ``c01 = 0`` is Neo-Hooke (the I2 term is skipped), otherwise Mooney-Rivlin.
    ``tangent=False`` skips K (returned with no elements): a residual alone costs about
    half. Returns also the Gauss-point f (ne, 4, 5), P (ne, 4, 5) and element pressure
    U'(theta) and dilatation theta for output and checks. A non-positive J anywhere gives
    ``ok = False`` (inverted element): the caller rejects the Newton step.
    B as :func:`gauss_operators` builds it (its zero pattern is used). Each Gauss point's
    tangent is summed as B^T (A + U'(theta) H_J) B, one product. The elements go in
    CHUNKS blocks to numba's threads (one unless NUMBA_NUM_THREADS is set, above; one per
    rank under mpiexec, which the Problem sets), each block with its own work
    arrays and each element writing its own rows, so the result does not depend on the
    number of threads (the energy is summed afterwards in element order).
    """
    ne = conn.shape[0]
    r = np.zeros((ne, 8))
    K = np.zeros((ne if tangent else 0, 8, 8))
    f_all = np.empty((ne, 4, 5))
    P_all = np.empty((ne, 4, 5))
    p_el = np.empty(ne)
    th_el = np.empty(ne)
    e_el = np.empty(ne)
    bad = np.zeros(ne, np.bool_)
    for c in numba.prange(CHUNKS):
        ue = np.empty(8)
        b = np.empty(8)
        dJ = np.empty((4, 5))
        HJ = np.empty((4, 5, 5))
        A = np.empty((4, 5, 5))
        M = np.empty((5, 5))
        MB = np.empty((5, 8))
        for e in range(c * ne // CHUNKS, (c + 1) * ne // CHUNKS):
            _element(e, u, conn, W, B, c10, c01, d1, j_th, tangent, r, K, f_all, P_all,
                     p_el, th_el, e_el, bad, ue, b, dJ, HJ, A, M, MB)
    energy = 0.0
    for e in range(ne):
        energy += e_el[e]
    return r, K, energy, not bad.any(), f_all, P_all, p_el, th_el


def element_dofs(conn):
    """Global dof numbers (ne, 8) of each element, (u_r, u_z) per node."""
    return np.stack([2 * conn, 2 * conn + 1], 2).reshape(conn.shape[0], 8)
