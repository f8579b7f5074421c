"""Derived film quantities: shear stress, loads, friction and flow (paper Eq. 29-42).

* Specific area (Eq. 31): A = w for a planar film of depth w, A = 2 pi r for an axisymmetric
  film on a rod of radius r. A nodal force is (stress) * A * M_i with the tributary length
  M_i = (y_{i+1} - y_{i-1}) / 2, one-sided at the ends (Eq. 29-30, 34, 45).
* Fluid shear stress on the seal (Eq. 32):
      tau = eta v / h - (h / 2) dp/dy - eta d(dh/dt)/dy,
  h regularised as in :mod:`sealts.film.gap`; the last gradient is the beta-weighted nodal
  difference of Eq. 33.
* Volume flow rate Q = q A (Eq. 41) and leakage V = int Q dt (Eq. 42).
"""
import math

import numba
import numpy as np

from .gap import h_eff
from .reynolds_fv import control_volumes, element_lengths


def specific_area(symmetry, width=1.0, radius=1.0):
    """A of Eq. 31 in mm: the film's depth (planar) or circumference (axisymmetric)."""
    return width if symmetry == "planar" else 2.0 * math.pi * radius


def weighted_gradient(y, f, beta):
    """Nodal df/dy, beta-weighted between the left and the right difference (Eq. 33)."""
    d = np.diff(f) / element_lengths(y)[0]
    g = np.empty_like(f)
    g[0], g[-1] = d[0], d[-1]
    g[1:-1] = beta * d[:-1] + (1.0 - beta) * d[1:]
    return g


@numba.njit(cache=True)
def effective_gap(h, h_floor):
    out = np.empty_like(h)
    for i in range(h.size):
        out[i] = h_eff(h[i], h_floor)[0]
    return out


def shear_stress(y, h, hd, dpdy, v, eta, h_floor, beta):
    """Fluid shear stress on the seal (MPa), Eq. 32, positive in +y (rod direction v > 0)."""
    he = effective_gap(h, h_floor)
    return eta * v / he - 0.5 * he * dpdy - eta * weighted_gradient(y, hd, beta)


def contact(h, v, law, mu_s):
    """Asperity pressure of the ``law`` (:mod:`sealts.contact.asperity`, Eq. 44 by default)
    and the solid friction stress of a rod sliding at v.

    With the rod sliding, the slip exceeds gamma_crit and Eq. 46 gives mu_s p_s sign(v).
    """
    ps, _ = law.pressure(h)
    return ps, mu_s * ps * np.sign(v)


def integrate(y, f, area):
    """Nodal force sum A * sum_i M_i f_i (N for f in MPa)."""
    return area * float(control_volumes(y) @ f)
