"""The rod side: the seal's ``rod_side`` boundary chain against the rod.

One object owns what every rod-side term reads: the chain (the rod-side vertices ordered by
reference z), their displacement dofs, the chain neighbours, the rod's radius r(t) and the
area factor A, and the geometry of the interface at a state u:

    y_i = Z_i + u_z,i                                   current axial position   (Eq. 25)
    h_i = R_i + u_r,i - r(t)                            gap to the rod           (Eq. 18)
    dh_i/dt = du_r,i/dt - dr/dt                         squeeze rate             (Eq. 26)
    L_i = (y_{i+1} - y_{i-1}) / 2                       tributary length         (Eq. 30)

with one-sided L at the chain's ends, so the L_i add up to the chain's axial extent; A =
2 pi r_rod (axisymmetric) or the depth (Eq. 31). The rod contact (Eq. 45), the rod friction
(Eq. 46-48), both film schemes, the leakage rows and the rod-side guard take a ``RodSide``;
none keeps a copy of the chain.
"""
import numpy as np

from ..core import of_time
from ..mesh.layout import vertex_dofs


class RodSide:
    def __init__(self, X, chain, r_rod, area, udofs=None, rod_rate=0.0, off=()):
        """``X``: reference coordinates (r, z) of the mesh nodes (mm); ``chain``: the
        rod-side nodes ordered by z (``mesh.chain("rod_side")``); ``r_rod`` the rod radius
        (mm) and ``rod_rate`` its rate (mm/s), numbers or functions of t; ``area``: A (mm);
        ``udofs`` (nodes, 2): the nodes' (u_r, u_z) dofs in the problem's numbering (default
        the vertices' own, :func:`sealts.mesh.layout.vertex_dofs`); ``off``: the boundary
        nodes off the chain (what the rod-side guard watches)."""
        self.X = np.asarray(X, float)
        self.chain = np.asarray(chain, np.int64)
        self.m = m = self.chain.size
        if m < 2:
            raise ValueError("the rod side needs at least two chain nodes")
        self.udofs = np.asarray(vertex_dofs(self.X.shape[0]) if udofs is None else udofs,
                                np.int64)
        self.ur, self.uz = self.udofs[self.chain, 0], self.udofs[self.chain, 1]
        self.R, self.Z = self.X[self.chain, 0], self.X[self.chain, 1]
        self.r_rod, self.rod_rate = of_time(r_rod), of_time(rod_rate)
        self.area = float(area)
        self.off = np.asarray(off, np.int64)
        # the neighbours of L_i, one-sided at the ends
        self.lo = np.concatenate([[0], np.arange(m - 1)])
        self.hi = np.concatenate([np.arange(1, m), [m - 1]])
        self.half = np.full(m, 0.5)

    def on(self, udofs, r_rod=None):
        """The same chain in another numbering ``udofs`` (and with another rod radius)."""
        return RodSide(self.X, self.chain, self.r_rod if r_rod is None else r_rod, self.area,
                       udofs, self.rod_rate, self.off)

    def y(self, u):
        """Current axial positions y_i (mm, Eq. 25)."""
        return self.Z + u[self.uz]

    def r(self, u):
        """Current radial positions of the chain nodes (mm)."""
        return self.R + u[self.ur]

    def gap(self, t, u):
        """h_i = R_i + u_r,i - r(t) (mm, Eq. 18)."""
        return self.R + u[self.ur] - self.r_rod(t)

    def gap_rate(self, t, udot):
        """dh_i/dt = du_r,i/dt - dr/dt (mm/s, Eq. 26)."""
        return udot[self.ur] - self.rod_rate(t)

    def lengths_of(self, y):
        """Tributary lengths of positions ``y`` along the chain, one-sided at the ends (mm)."""
        return self.half * (y[self.hi] - y[self.lo])

    def lengths(self, u):
        """Current tributary lengths L_i (mm, Eq. 30)."""
        return self.lengths_of(self.y(u))

    def off_depth(self, t, u):
        """How far each node off the chain is inside the rod (mm; negative: clear of it)."""
        return self.r_rod(t) - (self.X[self.off, 0] + u[self.udofs[self.off, 0]])
