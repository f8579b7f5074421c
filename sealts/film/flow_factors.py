"""Pressure and shear flow factors Phi_p(h), Phi_s(h) of the average Reynolds equation.

The film equation (paper Eq. 13, Patir and Cheng's average flow model) is

    d/dy( Phi_p h^3/(12 eta) dp/dy ) = (v/2) d/dy( h - Rq Phi_s ) + dh/dt

with Rq the composite RMS roughness (Eq. 14). Three models, chosen by ``film.flow_factors``:

``none``
    smooth surfaces: Phi_p = 1, Phi_s = 0.
``patir-cheng``
    the published closed-form fits for Gaussian roughness with Peklenik number gamma
    (N. Patir, H.S. Cheng, ASME J. Lubr. Technol. 100 (1978) 12-17 and 101 (1979) 220-230),
    with H = h / Rq:

    * gamma <= 1:  Phi_p = 1 - C exp(-r H);   gamma > 1:  Phi_p = 1 + C H^-r
    * H <= 5:  Phi_s = A1 H^a1 exp(-a2 H + a3 H^2);   H > 5:  Phi_s = A2 exp(-0.25 H)

    The fits hold for H > about 0.5, and for H > 1 for the most transverse patterns
    (gamma = 1/9, 1/6, whose Phi_p fit turns negative below). Below that H_lo (0.5, or 1 for
    those two rows; 0.5 for Phi_s) sealts continues the fits C1 and monotone:
    Phi_p (gamma <= 1) and Phi_s decay exponentially to 0, f = f_lo exp(f'_lo / f_lo (H - H_lo)),
    so flow stops smoothly in full contact; Phi_p (gamma > 1), which falls with H, saturates,
    f = f_lo - f'_lo (1 - exp(H - H_lo)). The published Phi_s rows jump by up to 0.08 % at
    H = 5; sealts keeps the published coefficients rather than re-fitting them.
``table``
    a CSV with columns ``h`` (mm), ``phi_p``, ``phi_s`` (e.g. factors computed for a measured
    surface); linear interpolation, held constant beyond the first and last rows.

All functions return the factors together with their derivatives with respect to h (1/mm),
because the Newton Jacobian needs them.
"""
from dataclasses import dataclass

import numba
import numpy as np

from .flow_factor_tables import (H_LO, PATIR_CHENG_GAMMAS, PATIR_CHENG_PRESSURE,  # noqa: F401
                                 PATIR_CHENG_SHEAR, pressure_fit_floor, read_table,
                                 tabulated_gamma)

NONE, PATIR_CHENG, TABLE = 0, 1, 2
MODELS = {"none": NONE, "patir-cheng": PATIR_CHENG, "table": TABLE}

@dataclass(frozen=True)
class FlowFactors:
    """Flow-factor model packed as plain arrays, so numba kernels can evaluate it.

    ``par`` = [Rq, C, r, A1, a1, a2, a3, A2, longitudinal, H_lo of Phi_p, s] with s = -1 for a
    rough seal (stationary surface, Eq. 13 as printed: h - Rq Phi_s) and +1 for a rough rod
    (the moving surface: h + Rq Phi_s); ``table`` = (h, phi_p, phi_s).
    """

    model: int
    par: np.ndarray
    table_h: np.ndarray
    table_pp: np.ndarray
    table_ps: np.ndarray

    @classmethod
    def none(cls):
        z = np.zeros(1)
        return cls(NONE, np.array([0.0] * 10 + [-1.0]), z, z, z)

    @classmethod
    def patir_cheng(cls, rq, gamma=1.0, rough_surface="seal"):
        g = tabulated_gamma(gamma)
        if g is None:
            raise ValueError(f"gamma must be one of the tabulated values, got {gamma}")
        c, r = PATIR_CHENG_PRESSURE[g]
        a = PATIR_CHENG_SHEAR[g]
        par = np.array([rq, c, r, *a, 1.0 if g > 1.0 else 0.0, pressure_fit_floor(g),
                        _sign(rough_surface)])
        z = np.zeros(1)
        return cls(PATIR_CHENG, par, z, z, z)

    @classmethod
    def from_table(cls, path, rq=0.0, rough_surface="seal"):
        h, pp, ps = read_table(path)
        par = np.array([rq, 0, 0, 0, 0, 0, 0, 0, 0, 0.0, _sign(rough_surface)])
        return cls(TABLE, par, h, pp, ps)

    def evaluate(self, h):
        """(Phi_p, dPhi_p/dh, Phi_s, dPhi_s/dh) at an array of h (mm)."""
        return flow_factors_array(np.asarray(h, float), self.model, self.par,
                                  self.table_h, self.table_pp, self.table_ps)


def _sign(rough_surface):
    return 1.0 if rough_surface == "rod" else -1.0


@numba.njit(cache=True)
def _phi_p_pc(H, c, r, longitudinal, h_lo):
    if longitudinal > 0.5:
        Hc = max(H, h_lo)
        f = 1.0 + c * Hc ** (-r)
        d = -r * c * Hc ** (-r - 1.0)
        if H >= h_lo:
            return f, d
        e = np.exp(H - h_lo)
        return f - d * (1.0 - e), d * e
    Hc = max(H, h_lo)
    f = 1.0 - c * np.exp(-r * Hc)
    d = r * c * np.exp(-r * Hc)
    if H >= h_lo:
        return f, d
    e = f * np.exp(d / f * (H - h_lo))
    return e, d / f * e


@numba.njit(cache=True)
def _phi_s_pc(H, a1_, a1, a2, a3, a2_):
    if H > 5.0:
        f = a2_ * np.exp(-0.25 * H)
        return f, -0.25 * f
    Hc = max(H, H_LO)
    f = a1_ * Hc ** a1 * np.exp(-a2 * Hc + a3 * Hc * Hc)
    d = f * (a1 / Hc - a2 + 2.0 * a3 * Hc)
    if H >= H_LO:
        return f, d
    e = f * np.exp(d / f * (H - H_LO))
    return e, d / f * e


@numba.njit(cache=True)
def _interp(x, xs, ys):
    n = xs.size
    if x <= xs[0]:
        return ys[0], 0.0
    if x >= xs[n - 1]:
        return ys[n - 1], 0.0
    j = np.searchsorted(xs, x) - 1
    s = (ys[j + 1] - ys[j]) / (xs[j + 1] - xs[j])
    return ys[j] + s * (x - xs[j]), s


@numba.njit(cache=True)
def flow_factors(h, model, par, th, tpp, tps):
    """(Phi_p, dPhi_p/dh, Phi_s, dPhi_s/dh) at one film thickness h (mm)."""
    if model == NONE:
        return 1.0, 0.0, 0.0, 0.0
    if model == TABLE:
        pp, dpp = _interp(h, th, tpp)
        ps, dps = _interp(h, th, tps)
        return pp, dpp, ps, dps
    rq = par[0]
    H = h / rq
    pp, dpp = _phi_p_pc(H, par[1], par[2], par[8], par[9])
    ps, dps = _phi_s_pc(H, par[3], par[4], par[5], par[6], par[7])
    return pp, dpp / rq, ps, dps / rq


@numba.njit(cache=True)
def flow_factors_array(h, model, par, th, tpp, tps):
    n = h.size
    pp = np.empty(n)
    dpp = np.empty(n)
    ps = np.empty(n)
    dps = np.empty(n)
    for i in range(n):
        pp[i], dpp[i], ps[i], dps[i] = flow_factors(h[i], model, par, th, tpp, tps)
    return pp, dpp, ps, dps
