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


class SnapStabilisation(ViscousStabilisation):
    """The stroke's stabilisation: c_base from the start (``stroke.stabilisation``), raised
    to c_snap (``stroke.snap_stabilisation``) once the seal has snapped.

    A snap is the stroke's steps stuck at TS's minimum size (``StepTooSmall``): the
    quasi-static seal's equilibrium path folds and the DAE's solution runs away in finite
    time. The stroke step then goes back to its last stop's checkpoint and runs on from
    there with c = c_snap for the rest of the run (:class:`sealts.steps.stroke.Stroke`), as
    ABAQUS's adaptive STABILIZE answers a convergence failure. (Raising c at the stuck state
    itself did not carry the 10 MPa O-ring on: that state, reached by steps accepted at the
    minimum, left errors of 500-1000 times the tolerance at every later step.) The term is
    part of the DAE from the start (with c = 0 it adds nothing), and the snap's time, its
    history, goes into the stroke's checkpoints, so a restarted run keeps c."""

    history_names = ("snapped_at",)

    def __init__(self, dofs, weights, c_base, c_snap):
        super().__init__(dofs, weights, c_base)
        self.c_base, self.c_snap = float(c_base), float(c_snap)
        self.snapped_at = -1.0

    def snap(self, t):
        """Raise c to c_snap at time t; False if that would not raise it (no snap
        stabilisation, a larger c from the start, or snapped before)."""
        if self.snapped_at >= 0.0 or self.c_snap <= self.c_base:
            return False
        self.snapped_at, self.c = float(t), self.c_snap
        return True

    def restore(self, history):
        super().restore(history)
        self.snapped_at = float(self.snapped_at)
        self.c = max(self.c_base, self.c_snap) if self.snapped_at >= 0.0 else self.c_base

    def add_residual(self, t, u, udot, f):
        if self.c != 0.0:
            f[self.dofs] += self.forces(udot)
