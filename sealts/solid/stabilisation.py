"""Viscous stabilisation of quasi-static steps: F += c m_i du_i/dt.

Before the seal touches a wall, frictionless contact leaves rigid-body modes (axial
translation; radial too in plane strain) without stiffness. A small viscous force c m u'
with lumped nodal weights m_i regularises them inside the TS (J gains shift c m), and it
vanishes at equilibrium, when u' = 0. It is the same idea as ABAQUS's STABILIZE. The run
reports its share of the residual at the end of each step, so an unconverged (still
creeping) state cannot pass for an equilibrium.
"""
import numpy as np

from ..core import Term


class ViscousStabilisation(Term):
    def __init__(self, dofs, weights, c):
        self.dofs = np.asarray(dofs, np.int64)
        self.m = np.asarray(weights, float)
        self.c = c
        self.rows = self.cols = self.dofs

    def forces(self, udot):
        return self.c * self.m * udot[self.dofs]

    def add_residual(self, t, u, udot, f):
        f[self.dofs] += self.forces(udot)

    def jacobian_values(self, t, u, udot, shift):
        return shift * self.c * self.m
