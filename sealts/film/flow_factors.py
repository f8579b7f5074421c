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
import csv
from dataclasses import dataclass
from pathlib import Path

import numba
import numpy as np

NONE, PATIR_CHENG, TABLE = 0, 1, 2
MODELS = {"none": NONE, "patir-cheng": PATIR_CHENG, "table": TABLE}

# gamma: (C, r) for Phi_p (1978); (A1, a1, a2, a3, A2) for Phi_s (1979)
PATIR_CHENG_PRESSURE = {
    1 / 9: (1.48, 0.42), 1 / 6: (1.38, 0.42), 1 / 3: (1.18, 0.42), 1.0: (0.90, 0.56),
    3.0: (0.225, 1.5), 6.0: (0.520, 1.5), 9.0: (0.870, 1.5),
}
PATIR_CHENG_SHEAR = {
    1 / 9: (2.046, 1.12, 0.78, 0.03, 1.856), 1 / 6: (1.962, 1.08, 0.77, 0.03, 1.754),
    1 / 3: (1.858, 1.01, 0.76, 0.03, 1.561), 1.0: (1.899, 0.98, 0.92, 0.05, 1.126),
    3.0: (1.560, 0.85, 1.13, 0.08, 0.556), 6.0: (1.290, 0.62, 1.09, 0.08, 0.388),
    9.0: (1.011, 0.54, 1.07, 0.08, 0.295),
}
PATIR_CHENG_GAMMAS = sorted(PATIR_CHENG_PRESSURE)
H_LO = 0.5  # lower end of the fits' validity, in units of Rq


def pressure_fit_floor(gamma):
    """H below which the Phi_p fit is replaced by its extension."""
    return 1.0 if gamma < 0.3 else H_LO


def tabulated_gamma(gamma):
    """The tabulated Peklenik number equal to gamma (to 1e-6), or None."""
    for g in PATIR_CHENG_GAMMAS:
        if abs(gamma - g) <= 1e-6 * g:
            return g
    return None


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


def read_table(path):
    """Read a flow-factor CSV with header ``h,phi_p,phi_s``; h in mm, strictly increasing."""
    path = Path(path)
    try:
        with path.open(newline="") as f:
            rows = list(csv.DictReader(f))
    except (OSError, UnicodeDecodeError) as e:
        raise ValueError(f"{path}: cannot be read ({e})") from None
    if not rows or not {"h", "phi_p", "phi_s"} <= set(rows[0]):
        raise ValueError(f"{path}: needs the columns h, phi_p, phi_s")
    try:
        h = np.array([float(r["h"]) for r in rows])
        pp = np.array([float(r["phi_p"]) for r in rows])
        ps = np.array([float(r["phi_s"]) for r in rows])
    except (TypeError, ValueError):
        raise ValueError(f"{path}: every h, phi_p, phi_s must be a number") from None
    if not (np.all(np.isfinite(h)) and np.all(np.isfinite(pp)) and np.all(np.isfinite(ps))):
        raise ValueError(f"{path}: values must be finite")
    if h.size < 2 or np.any(np.diff(h) <= 0):
        raise ValueError(f"{path}: h must be strictly increasing with at least two rows")
    if np.any(pp < 0):
        raise ValueError(f"{path}: phi_p must be >= 0")
    return h, pp, ps


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
