"""The seal body as a physics term of :class:`sealts.problem.Problem`.

Unknowns: nodal displacements (u_r, u_z) (mm) at the dofs ``udofs`` (node -> 2 dofs, from
:class:`sealts.mesh.layout.Layout`; 2i, 2i + 1 by default). Residual: the
internal forces of the Q1/P0 elements (:mod:`sealts.solid.q1p0`) in N (totals over the
circumference in axisymmetry, per mm of depth in plane strain). External loads and contacts
are separate terms. An inverted element (J <= 0 at a Gauss point) makes the residual NaN, so
SNES fails and TS retries the step smaller; no such state is ever accepted.
"""
from dataclasses import dataclass

import numpy as np

from ..core import Term
from ..mesh.layout import vertex_dofs
from .q1p0 import element_forces, gauss_operators


@dataclass(frozen=True)
class Hyperelastic:
    """Compressible Mooney-Rivlin (C01 > 0) or Neo-Hooke (C01 = 0, Eq. 1-5): C10, C01 (MPa),
    D1 (mm^2/N), thermal expansion."""

    c10: float
    d1: float
    alpha_th: float = 0.0   # 1/K
    d_theta: float = 0.0    # K, temperature above the reference
    c01: float = 0.0        # MPa

    @property
    def j_th(self):
        return self.j_th_at(1.0)

    def j_th_at(self, fraction):
        """Thermal volume ratio with the temperature rise scaled by ``fraction``."""
        return (1.0 + self.alpha_th * self.d_theta * fraction) ** 3

    @property
    def shear_modulus(self):
        return 2.0 * (self.c10 + self.c01)

    @property
    def bulk_modulus(self):
        return 2.0 / self.d1

    @property
    def plane_strain_modulus(self):
        """E' = E/(1 - nu^2) (MPa) from the initial shear and bulk moduli G and K:
        E = 9KG/(3K + G), nu = (3K - 2G)/(2(3K + G)); 4 G for an incompressible one."""
        g, k = self.shear_modulus, self.bulk_modulus
        e = 9.0 * k * g / (3.0 * k + g)
        nu = (3.0 * k - 2.0 * g) / (2.0 * (3.0 * k + g))
        return e / (1.0 - nu * nu)


def NeoHooke(c10, d1, alpha_th=0.0, d_theta=0.0):
    """Compressible Neo-Hooke (paper Eq. 1-5)."""
    return Hyperelastic(c10, d1, alpha_th, d_theta)


class SolidTerm(Term):
    def __init__(self, X, conn, material, axisym, udofs=None, heating=lambda t: 1.0):
        """``heating(t)``: the fraction of the temperature rise applied at time t (a mounting
        step ramps it with the interference, so a warm seal does not start inside a wall)."""
        self.X = np.ascontiguousarray(X, float)
        self.conn = np.ascontiguousarray(conn, np.int64)
        self.material, self.axisym = material, bool(axisym)
        self.heating = heating
        self.nn = self.X.shape[0]
        self.W, self.B, self.R = gauss_operators(self.X, self.conn, self.axisym)
        self.udofs = vertex_dofs(self.nn) if udofs is None else np.asarray(udofs, np.int64)
        self.dofs = self.udofs[self.conn].reshape(self.conn.shape[0], 8)
        self.rows = np.repeat(self.dofs, 8, axis=1).ravel()
        self.cols = np.tile(self.dofs, (1, 8)).ravel()
        self._cache_key, self._tangent = None, False

    def _evaluate(self, u, t=None, tangent=True):
        """The element kernel's output at u, kept for the next call at the same u (a
        residual's evaluation serves the Jacobian's at the same state); ``tangent=False``
        (energy and output) skips the tangents."""
        j_th = self.material.j_th if t is None else self.material.j_th_at(self.heating(t))
        us = u[self.udofs].ravel()
        key = (j_th, hash(us.tobytes()))
        if key != self._cache_key or (tangent and not self._tangent):
            m = self.material
            self._out = element_forces(us, self.conn, self.W, self.B, m.c10, m.c01, m.d1,
                                       j_th, tangent)
            self._cache_key, self._tangent = key, tangent
        return self._out

    def add_residual(self, t, u, udot, f):
        r, _, _, ok, *_ = self._evaluate(u, t)
        if not ok:
            f[:] = np.nan
            return
        f += np.bincount(self.dofs.ravel(), r.ravel(), minlength=f.size)

    def jacobian_values(self, t, u, udot, shift):
        return self._evaluate(u, t)[1].ravel()

    def nonfinite(self, t, u):
        """The inverted elements (J <= 0 at a Gauss point) in words, the first by its
        reference centroid."""
        f = self._evaluate(u, t, tangent=False)[4]
        J = (f[..., 0] * f[..., 3] - f[..., 1] * f[..., 2]) * f[..., 4]
        bad = np.flatnonzero((J <= 0.0).any(axis=1))
        if not bad.size:
            return None
        r, z = self.X[self.conn[bad[0]]].mean(axis=0)
        return (f"{bad.size} element(s) of the seal invert (J <= 0), the first at r = "
                f"{r:.4g}, z = {z:.4g} mm (undeformed): the rubber is crushed or folds there")

    def energy(self, u):
        return self._evaluate(u, tangent=False)[2]

    def state(self, u):
        """Gauss-point f, P, element pressure term U'(theta) and dilatation theta."""
        _, _, _, _, f, P, p, th = self._evaluate(u, tangent=False)
        return f, P, p, th
