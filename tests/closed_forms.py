"""Closed-form film solutions used as independent truth by the tests.

Rigid slider with squeeze (paper Section 2.2.4, Eq. 43). With Phi_p = 1, Phi_s = 0, a linear
gap h(y) = h1 + m y (h1 at y = 0, m = -s_h / l) and a uniform squeeze rate hd, integrating
Eq. 13 once gives

    h^3/(12 eta) dp/dy = (v/2) h + hd y + C,            (q = -hd y - C)

and once more, with p(0) = 0,

    p(y) = 12 eta [ (v/2) F2(y) + hd Fy3(y) + C F3(y) ],
    F2 = int_0^y h^-2,  F3 = int_0^y h^-3,  Fy3 = int_0^y s h^-3 ds,

with C fixed by p(l) = 0. For linear h these integrals are elementary:
    F2 = (1/m)(1/h1 - 1/h),  F3 = (1/(2m))(1/h1^2 - 1/h^2),
    Fy3 = (1/m)(F2 - h1 F3).
"""
import numpy as np


def slider_pressure(y, l, h1, s_h, v, eta, hd):
    """Pressure (MPa) of the rigid slider bearing and its inlet flow q(0) (mm^2/s)."""
    m = -s_h / l

    def integrals(yy):
        h = h1 + m * yy
        f2 = (1.0 / h1 - 1.0 / h) / m
        f3 = (1.0 / h1**2 - 1.0 / h**2) / (2.0 * m)
        fy3 = (f2 - h1 * f3) / m
        return f2, f3, fy3

    f2l, f3l, fy3l = integrals(np.float64(l))
    c = -(0.5 * v * f2l + hd * fy3l) / f3l
    f2, f3, fy3 = integrals(np.asarray(y, float))
    return 12.0 * eta * (0.5 * v * f2 + hd * fy3 + c * f3), -c


def squeeze_plates_pressure(y, l, h, eta, hd):
    """Parallel plates approaching at hd < 0, p(0) = p(l) = 0: p = -6 eta hd y (l - y) / h^3."""
    return -6.0 * eta * hd * y * (l - y) / h**3


def squeeze_plates_volumes(T, l, h0, hd, v, area):
    """Leakage volumes through both ends of sliding, approaching parallel plates after T.

    By symmetry the pressure gradient vanishes mid-film, where q = (v/2) h; mass conservation
    dq/dy = -hd then gives q(0) = (v/2) h + hd l/2 and q(l) = (v/2) h - hd l/2, with
    h = h0 + hd t. Integrated over [0, T]:
    """
    couette = 0.5 * v * (h0 * T + 0.5 * hd * T**2)
    return area * (couette + 0.5 * hd * l * T), area * (couette - 0.5 * hd * l * T)
