"""Compressible Neo-Hooke with thermal expansion (paper Eq. 1-6), written on five F entries.

For axisymmetric (r, z, theta) and plane-strain (x, y, z) states the deformation gradient is

    F = [[F11, F12, 0], [F21, F22, 0], [0, 0, F33]],   f = (F11, F12, F21, F22, F33),

with F33 = 1 + u_r / R (hoop stretch) or 1 (plane strain). The strain energy splits into

    psi = C10 (I1bar - 3) + U(J),  I1bar = J^(-2/3) I1,  I1 = f . f,
    J = (F11 F22 - F12 F21) F33,   U(J) = (1/D1) (J / J_th - 1)^2,  J_th = (1 + alpha dT)^3,

(Eq. 1-5). The isochoric part depends on F at each Gauss point; the volumetric part is taken
on the element's mean dilatation (see :mod:`sealts.solid.q1p0`). This module gives the
isochoric energy's gradient dpsi/df (the first Piola-Kirchhoff entries) and Hessian, and the
volumetric function with its first two derivatives. Long-term moduli: G = 2 C10, K = 2 / D1.
"""
import numba
import numpy as np


@numba.njit(cache=True, inline="always")
def det_into(f, dJ, HJ):
    """J for f = (F11, F12, F21, F22, F33); dJ/df (5) and d2J/df2 (5x5) written into the
    buffers ``dJ`` and ``HJ`` (the element kernel's, so no Gauss point allocates)."""
    F11, F12, F21, F22, F33 = f[0], f[1], f[2], f[3], f[4]
    a = F11 * F22 - F12 * F21
    dJ[0] = F22 * F33
    dJ[1] = -F21 * F33
    dJ[2] = -F12 * F33
    dJ[3] = F11 * F33
    dJ[4] = a
    for i in range(5):
        for k in range(5):
            HJ[i, k] = 0.0
    HJ[0, 3] = HJ[3, 0] = F33
    HJ[1, 2] = HJ[2, 1] = -F33
    HJ[0, 4] = HJ[4, 0] = F22
    HJ[3, 4] = HJ[4, 3] = F11
    HJ[1, 4] = HJ[4, 1] = -F21
    HJ[2, 4] = HJ[4, 2] = -F12
    return a * F33


@numba.njit(cache=True, inline="always")
def isochoric_into(f, J, dJ, HJ, c10, P, A, tangent):
    """psi_iso = C10 (J^-2/3 I1 - 3); its gradient P (5) and, with ``tangent``, its Hessian
    A (5x5) in f written into the buffers, from J, dJ, HJ of :func:`det_into`."""
    I1 = f[0] * f[0] + f[1] * f[1] + f[2] * f[2] + f[3] * f[3] + f[4] * f[4]
    j23 = J ** (-2.0 / 3.0)
    j53 = j23 / J
    j83 = j53 / J
    for i in range(5):
        P[i] = c10 * (2.0 * j23 * f[i] - (2.0 / 3.0) * j53 * I1 * dJ[i])
    if tangent:
        for i in range(5):
            for k in range(5):
                A[i, k] = c10 * (
                    -(4.0 / 3.0) * j53 * (f[i] * dJ[k] + dJ[i] * f[k])
                    + (10.0 / 9.0) * j83 * I1 * dJ[i] * dJ[k]
                    - (2.0 / 3.0) * j53 * I1 * HJ[i, k])
            A[i, i] += c10 * 2.0 * j23
    return c10 * (j23 * I1 - 3.0)


@numba.njit(cache=True, inline="always")
def volumetric(theta, d1, j_th):
    """U(theta) = (1/D1)(theta/J_th - 1)^2 and its first and second derivatives."""
    x = theta / j_th - 1.0
    return x * x / d1, 2.0 * x / (d1 * j_th), 2.0 / (d1 * j_th * j_th)


def cauchy_stress(f, P, p_mean):
    """Cauchy stress components (rr, zz, tt, rz) from f, the isochoric P and the pressure
    term U'(theta) (the volumetric Cauchy stress is U'(theta) I)."""
    F11, F12, F21, F22, F33 = f.T
    J = (F11 * F22 - F12 * F21) * F33
    P11, P12, P21, P22, P33 = P.T
    s_rr = (P11 * F11 + P12 * F12) / J + p_mean
    s_zz = (P21 * F21 + P22 * F22) / J + p_mean
    s_tt = P33 * F33 / J + p_mean
    s_rz = (P11 * F21 + P12 * F22) / J
    return np.stack([s_rr, s_zz, s_tt, s_rz], -1)
