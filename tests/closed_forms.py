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


def slider_pressure(y, l, h1, s_h, v, eta, hd, phi_p=1.0, couette=1.0, tilt=0.0):
    """Pressure (MPa) of the rigid slider bearing and its inlet flow q(0) (mm^2/s).

    Generalised for the tests of flow factors and non-uniform squeeze:
    * phi_p: a constant pressure flow factor, k = phi_p h^3 / (12 eta);
    * couette: the factor (1 -+ Rq b) that a shear flow factor Phi_s = a + b h puts on the
      Couette term (its constant part a only shifts the integration constant);
    * tilt: a squeeze rate linear in y, dh/dt = hd + tilt y, whose once-integrated form is
      hd y + tilt y^2 / 2, which needs Fyy3 = int_0^y s^2 h^-3 ds
      = (1/m^2) [ ln(h/h1)/m - 2 h1 F2 + h1^2 F3 ].
    q(0) is returned for phi_p = couette = 1 only (the flow through y = 0 is then -C).
    """
    m = -s_h / l

    def integrals(yy):
        h = h1 + m * yy
        f2 = (1.0 / h1 - 1.0 / h) / m
        f3 = (1.0 / h1**2 - 1.0 / h**2) / (2.0 * m)
        fy3 = (f2 - h1 * f3) / m
        fyy3 = (np.log(h / h1) / m - 2 * h1 * f2 + h1**2 * f3) / m**2
        return f2, f3, fy3, fyy3

    def bracket(yy, c):
        f2, f3, fy3, fyy3 = integrals(yy)
        return 0.5 * v * couette * f2 + hd * fy3 + 0.5 * tilt * fyy3 + c * f3

    f2l, f3l, _, _ = integrals(np.float64(l))
    c = -bracket(np.float64(l), 0.0) / f3l
    return 12.0 * eta / phi_p * bracket(np.asarray(y, float), c), -c


def hydrostatic_pressure(y, l, h1, s_h, p_in, p_out):
    """Pure pressure flow (v = 0, no squeeze) through the tapered gap: q is constant, so
    p = p_in - (p_in - p_out) F3(y) / F3(l)."""
    m = -s_h / l
    f3 = lambda yy: (1.0 / h1**2 - 1.0 / (h1 + m * yy) ** 2) / (2.0 * m)
    return p_in - (p_in - p_out) * f3(np.asarray(y, float)) / f3(l)


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
