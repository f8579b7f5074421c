"""The paper's asperity law, Eq. 44-45 (``asperity.law = "exponential"``, the default):

    p_s(h) = 0                                              h >= h_mix
    p_s(h) = p_mix / (e - 1) (1 - h/h_mix) (exp(1 - h/h_mix) - 1)   h <  h_mix

p_s is C1 at h = h_mix (value and slope vanish), equals p_mix at h = 0 and keeps growing for
h < 0. The nodal force is p_s A_i (Eq. 45).

Below h = -h_mix (where p_s = 2 p_mix (e^2 - 1)/(e - 1), 7.4 p_mix, 112 MPa for the paper's
15 MPa) sealts continues the law along its tangent: still growing, still C1, but linear, so a
Newton predictor that pushes a node deep into the rod meets a large finite force instead of
exp(h/h_mix) overflowing. Contact states of interest (p_s of a few MPa) are untouched.
"""
import math

import numba
import numpy as np

from .base import AsperityLaw

_E1 = math.e - 1.0


@numba.njit(cache=True)
def asperity_pressure(h, h_mix, p_mix):
    """Return (p_s, dp_s/dh) for one separation h (mm), with p in MPa."""
    if h >= h_mix:
        return 0.0, 0.0
    x = 1.0 - h / h_mix
    if x > 2.0:  # tangent continuation below h = -h_mix
        e2 = np.exp(2.0)
        p2 = p_mix / _E1 * 2.0 * (e2 - 1.0)
        d2 = p_mix / _E1 * (e2 - 1.0 + 2.0 * e2)
        return p2 + d2 * (x - 2.0), -d2 / h_mix
    ex = np.exp(x)
    p = p_mix / _E1 * x * (ex - 1.0)
    dp_dx = p_mix / _E1 * (ex - 1.0 + x * ex)
    return p, -dp_dx / h_mix


@numba.njit(cache=True)
def asperity_pressure_array(h, h_mix, p_mix):
    """Vectorised :func:`asperity_pressure` over an array of separations."""
    p = np.empty_like(h)
    dp = np.empty_like(h)
    for i in range(h.size):
        p[i], dp[i] = asperity_pressure(h[i], h_mix, p_mix)
    return p, dp


class ExponentialLaw(AsperityLaw):
    name = "exponential"

    def __init__(self, h_mix=7e-4, p_mix=15.0):
        """``h_mix`` (mm): the separation where contact begins; ``p_mix`` (MPa): p_s at
        h = 0 (the paper's 0.7 um and 15 MPa, Table 3)."""
        self.h_mix, self.p_mix = float(h_mix), float(p_mix)
        self.contact_gap = self.h_mix

    @classmethod
    def from_scene(cls, asperity, material=None):
        return cls(asperity.h_mix, asperity.p_mix)

    def pressure(self, h):
        return asperity_pressure_array(np.asarray(h, float), self.h_mix, self.p_mix)
