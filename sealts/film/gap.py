"""Regularised film thickness.

The Reynolds conductance Phi_p h^3 / (12 eta) and the Couette flux v h / 2 lose meaning where
the nominal separation h = x + u - r (paper Eq. 18) falls to zero or below, which happens under
asperity contact. sealts keeps the film well posed everywhere by replacing h with

    h_eff(h) = h                                   for h >= 2 h_floor
    h_eff(h) = h_floor (1 + exp(h / h_floor - 2))  for h <  2 h_floor

h_eff is C1, increasing, equal to h above 2 h_floor and tends to h_floor as h -> -inf, so the
conductance never drops below Phi_p h_floor^3 / (12 eta): a contact zone is a very tight but
finite hydraulic resistance, and the pressure stays defined there. h_floor is the scene key
``film.h_floor`` (mm). The storage term uses d h_eff / dt, so the conserved film volume is the
integral of h_eff and the discrete mass balance stays exact.
"""
import numba
import numpy as np


@numba.njit(cache=True, inline="always")
def smooth_floor(x, floor):
    """x for x >= 2 floor, floor (1 + exp(x/floor - 2)) below: C1, increasing, > floor.
    Returns (value, derivative)."""
    if x >= 2.0 * floor or floor <= 0.0:
        return x, 1.0
    e = np.exp(x / floor - 2.0)
    return floor * (1.0 + e), e


@numba.njit(cache=True, inline="always")
def h_eff(h, h_floor):
    """Return (h_eff, d h_eff / dh)."""
    return smooth_floor(h, h_floor)


@numba.njit(cache=True, inline="always")
def h_eff_rate(h, hd, h_floor):
    """(d h_eff/dt, its derivative in h) for the rate dh/dt = hd: h_eff'(h) hd and
    h_eff''(h) hd (h_eff'' = h_eff' / h_floor in the floor range, 0 above it)."""
    _, dhe = smooth_floor(h, h_floor)
    d2 = dhe / h_floor if (h_floor > 0.0 and h < 2.0 * h_floor) else 0.0
    return dhe * hd, d2 * hd
