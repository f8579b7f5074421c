"""The second-invariant term of Mooney-Rivlin, on the five F entries of :mod:`.neo_hooke`.

    psi = C10 (I1bar - 3) + C01 (I2bar - 3) + U(J),   I2bar = J^(-4/3) I2,

(Neo-Hooke, paper Eq. 1, is C01 = 0). For F = [[F11, F12, 0], [F21, F22, 0], [0, 0, F33]],
C = F^T F is block diagonal, and its second principal invariant is

    I2 = a^2 + F33^2 q,   a = F11 F22 - F12 F21,   q = F11^2 + F12^2 + F21^2 + F22^2.

Small-strain shear modulus G = 2 (C10 + C01). This module gives C01 (I2bar - 3) with its
gradient and Hessian in f = (F11, F12, F21, F22, F33); the element kernel adds them to the
Neo-Hooke part and skips them when C01 = 0.
"""
import numba
import numpy as np

from .neo_hooke import det_into, isochoric_into


@numba.njit(cache=True, inline="always")
def isochoric_i2_add(f, J, dJ, HJ, c01, P, A, tangent):
    """C01 (J^-4/3 I2 - 3); its gradient added to P (5) and, with ``tangent``, its Hessian
    to A (5x5), from J, dJ, HJ of :func:`.neo_hooke.det_into`."""
    F11, F12, F21, F22, F33 = f[0], f[1], f[2], f[3], f[4]
    a = F11 * F22 - F12 * F21
    q = F11 * F11 + F12 * F12 + F21 * F21 + F22 * F22
    I2 = a * a + F33 * F33 * q
    da0, da1, da2, da3 = F22, -F21, -F12, F11
    dI2 = np.empty(5)
    dI2[0] = 2.0 * a * da0 + 2.0 * F33 * F33 * F11
    dI2[1] = 2.0 * a * da1 + 2.0 * F33 * F33 * F12
    dI2[2] = 2.0 * a * da2 + 2.0 * F33 * F33 * F21
    dI2[3] = 2.0 * a * da3 + 2.0 * F33 * F33 * F22
    dI2[4] = 2.0 * F33 * q
    g = J ** (-4.0 / 3.0)
    g1 = -(4.0 / 3.0) * g / J                       # dg/dJ
    g2 = (28.0 / 9.0) * g / (J * J)                 # d2g/dJ2
    for i in range(5):
        P[i] += c01 * (g * dI2[i] + I2 * g1 * dJ[i])
    if tangent:
        da = np.array([da0, da1, da2, da3, 0.0])
        HI2 = np.empty((5, 5))
        for i in range(5):
            for k in range(5):
                HI2[i, k] = 2.0 * da[i] * da[k]
        HI2[0, 3] += 2.0 * a
        HI2[3, 0] += 2.0 * a
        HI2[1, 2] -= 2.0 * a
        HI2[2, 1] -= 2.0 * a
        for i in range(4):
            HI2[i, i] += 2.0 * F33 * F33
            HI2[i, 4] += 4.0 * F33 * f[i]
            HI2[4, i] += 4.0 * F33 * f[i]
        HI2[4, 4] += 2.0 * q
        for i in range(5):
            for k in range(5):
                A[i, k] += c01 * (g * HI2[i, k] + g1 * (dJ[i] * dI2[k] + dI2[i] * dJ[k])
                                  + I2 * (g2 * dJ[i] * dJ[k] + g1 * HJ[i, k]))
    return c01 * (g * I2 - 3.0)


@numba.njit(cache=True)
def isochoric(f, c10, c01):
    """The whole isochoric energy C10 (I1bar - 3) + C01 (I2bar - 3), its gradient P (5) and
    Hessian A (5x5) in f (allocating; the kernels use the buffer forms)."""
    dJ, HJ, P, A = np.empty(5), np.empty((5, 5)), np.empty(5), np.empty((5, 5))
    J = det_into(f, dJ, HJ)
    psi = isochoric_into(f, J, dJ, HJ, c10, P, A, True)
    if c01 != 0.0:
        psi += isochoric_i2_add(f, J, dJ, HJ, c01, P, A, True)
    return psi, P, A
