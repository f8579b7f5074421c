"""Greenwood and Williamson's asperity law (``asperity.law = "greenwood-williamson"``).

Spherical summits of radius beta, eta_s of them per unit area, with Gaussian heights of
standard deviation sigma_s, each pressed in Hertzian contact (J.A. Greenwood, J.B.P.
Williamson, Proc. R. Soc. A 295 (1966) 300-319, Eq. 8-9):

    p_s(h) = (4/3) eta_s E' beta^(1/2) sigma_s^(3/2) F_3/2(h / sigma_s),

    F_n(d) = (2 pi)^(-1/2) int_d^inf (s - d)^n exp(-s^2 / 2) ds,

h the mean separation (mm), E' the composite modulus [(1 - nu_1^2)/E_1 + (1 - nu_2^2)/E_2]^-1
(a rigid rod: E/(1 - nu^2) of the seal). dF_n/dd = -n F_(n-1), so dp_s/dh = -(3/2) K
F_1/2(d) / sigma_s with K the prefactor.

**How F_3/2 is evaluated.** F_3/2 and F_1/2 are tabulated once, at import, on d in
[D_LO, D_HI] = [-30, 9] with step 0.01: with x = t^2, F_n(d) = (2 pi)^(-1/2) int_0^inf
2 t^(2n+1) exp(-(t^2 + d)^2 / 2) dt, a smooth integrand, by 400-point Gauss-Legendre on
[0, (max(0, -d) + 40)^(1/2)]. Between the nodes F_3/2 is the cubic Hermite interpolant of the
tabulated values and slopes -(3/2) F_1/2, so p_s is C1 and its derivative is the exact one of
the interpolant (tests/test_asperity_laws.py checks it against an independent tanh-sinh
quadrature). Beyond the table:

* above D_HI the pressure ends: F_3/2 is replaced by F_3/2(d) - F_3/2(D_HI) - F_3/2'(D_HI)
  (d - D_HI), which vanishes with its slope at D_HI (F_3/2 is convex, so it stays >= 0 and
  falling); the change, F_3/2(9) ~ 1e-20 and its slope, is far below the table's own error
  (1e-8 relative where p_s matters). The contact gap is D_HI sigma_s;
* below D_LO (a node 30 sigma_s into the rod) the law continues along its tangent, as the
  exponential law does below -h_mix, so a Newton predictor meets a finite force.
"""
import math

import numba
import numpy as np

from .base import AsperityLaw

D_LO, D_HI, D_STEP = -30.0, 9.0, 0.01


def gaussian_moment(n, d, nodes=400):
    """F_n(d) for an array d (n > -1/2), by Gauss-Legendre in t = x^(1/2) (module
    docstring)."""
    d = np.atleast_1d(np.asarray(d, float))
    x, w = np.polynomial.legendre.leggauss(nodes)
    top = np.sqrt(np.maximum(0.0, -d) + 40.0)[:, None]
    t = 0.5 * top * (x + 1.0)
    f = 2.0 * t ** (2 * n + 1) * np.exp(-0.5 * (t * t + d[:, None]) ** 2)
    return 0.5 * top[:, 0] * (f @ w) / math.sqrt(2.0 * math.pi)


_D = np.linspace(D_LO, D_HI, int(round((D_HI - D_LO) / D_STEP)) + 1)
_F = gaussian_moment(1.5, _D)
_DF = -1.5 * gaussian_moment(0.5, _D)
_F_HI, _DF_HI = _F[-1], _DF[-1]


@numba.njit(cache=True)
def f32(d, table_f, table_df, d_lo, step, f_hi, df_hi):
    """(F_3/2(d) as the law uses it, its derivative): the Hermite interpolant on the table,
    less its tangent at D_HI, zero above D_HI, linear below D_LO."""
    n = table_f.size
    d_hi = d_lo + step * (n - 1)
    if d >= d_hi:
        return 0.0, 0.0
    if d <= d_lo:
        f0 = table_f[0] - f_hi - df_hi * (d_lo - d_hi)
        return f0 + (table_df[0] - df_hi) * (d - d_lo), table_df[0] - df_hi
    k = min(int((d - d_lo) / step), n - 2)
    s = (d - (d_lo + k * step)) / step
    f0, f1 = table_f[k], table_f[k + 1]
    m0, m1 = table_df[k] * step, table_df[k + 1] * step
    s2, s3 = s * s, s * s * s
    f = ((2 * s3 - 3 * s2 + 1) * f0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * f1
         + (s3 - s2) * m1)
    df = ((6 * s2 - 6 * s) * f0 + (3 * s2 - 4 * s + 1) * m0 + (-6 * s2 + 6 * s) * f1
          + (3 * s2 - 2 * s) * m1) / step
    return f - f_hi - df_hi * (d - d_hi), df - df_hi


@numba.njit(cache=True)
def gw_pressure_array(h, k, sigma, table_f, table_df, d_lo, step, f_hi, df_hi):
    """(p_s, dp_s/dh) = (K F(h/sigma), K F'(h/sigma)/sigma) over an array of h."""
    p = np.empty_like(h)
    dp = np.empty_like(h)
    for i in range(h.size):
        f, df = f32(h[i] / sigma, table_f, table_df, d_lo, step, f_hi, df_hi)
        p[i], dp[i] = k * f, k * df / sigma
    return p, dp


class GreenwoodWilliamson(AsperityLaw):
    name = "greenwood-williamson"

    def __init__(self, summit_density, summit_radius, summit_sigma, modulus):
        """``summit_density`` eta_s (1/mm^2), ``summit_radius`` beta (mm), ``summit_sigma``
        sigma_s (mm), ``modulus`` E' (MPa)."""
        self.eta, self.beta, self.sigma = summit_density, summit_radius, summit_sigma
        self.modulus = modulus
        self.k = 4.0 / 3.0 * summit_density * modulus * math.sqrt(summit_radius) \
            * summit_sigma ** 1.5                                        # MPa
        self.contact_gap = D_HI * summit_sigma

    @classmethod
    def from_scene(cls, asperity, material=None):
        """The law of a scene's keys; ``asperity.modulus = 0`` takes E' of the seal's
        material against a rigid rod, E/(1 - nu^2) from its initial shear and bulk moduli."""
        a = asperity
        modulus = a.modulus if a.modulus > 0.0 else material.plane_strain_modulus
        return cls(a.summit_density, a.summit_radius, a.summit_sigma, modulus)

    def pressure(self, h):
        return gw_pressure_array(np.asarray(h, float), self.k, self.sigma, _F, _DF, D_LO,
                                 D_STEP, _F_HI, _DF_HI)
