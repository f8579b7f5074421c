"""The work the rod spends on the seal's friction, as a TS unknown (N mm):

    dW/dt = v(t) (F_fluid + F_solid),

F_fluid the axial fluid shear force on the seal (Eq. 32-34), F_solid the rod's asperity
friction (Eq. 46-48), both positive in +z on the seal, v(t) the rod's velocity: v F > 0
while the rod drags the seal along. TS integrates W with the rest of the stroke, as it does
the leakage volumes (Eq. 42), so its error is the step's, under the same error control, not
that of a trapezoid over the accepted steps.

Each force term is a *source* with ``friction_cols`` (fixed), ``friction_force(t, u, u')``
(its total axial friction, as in its residual) and ``friction_gradient(t, u, u', shift)``
(dF/dU + shift dF/dU' on those columns): the fluid shear of either film scheme and the rod
friction with anchors or with its slip as unknowns. Exact Jacobian: v(t) times the
sources' gradients, and the TS shift on W itself.
"""
import numpy as np

from ..core import Term, of_time


class FrictionWork(Term):
    def __init__(self, wdof, velocity, sources):
        """``wdof``: the dof of W; ``velocity``: v(t) (mm/s); ``sources``: the force terms
        (module docstring)."""
        self.wd = int(wdof)
        self.v = of_time(velocity)
        self.sources = list(sources)
        self.cols = np.concatenate([[self.wd]] + [np.asarray(s.friction_cols, np.int64)
                                                   for s in self.sources]).astype(np.int64)
        self.rows = np.full(self.cols.size, self.wd, np.int64)

    def power(self, t, u, udot):
        """v(t) times the sources' axial friction (N mm/s)."""
        return self.v(t) * sum(s.friction_force(t, u, udot) for s in self.sources)

    def add_residual(self, t, u, udot, f):
        f[self.wd] += udot[self.wd] - self.power(t, u, udot)

    def jacobian_values(self, t, u, udot, shift):
        v = self.v(t)
        return np.concatenate([[shift]] + [-v * s.friction_gradient(t, u, udot, shift)
                                           for s in self.sources])
