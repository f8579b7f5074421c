"""The work the rod spends on the seal's friction, as a TS unknown (N mm):

    dW/dt = v(t) (F_fluid + F_solid),

F_fluid the axial fluid shear force on the seal (Eq. 32-34), F_solid the rod's asperity
friction (Eq. 46-48), both positive in +z on the seal, v(t) the rod's velocity: v F > 0
while the rod drags the seal along. TS integrates W with the rest of the stroke, as it does
the leakage volumes (Eq. 42), not as a trapezoid over the accepted steps.

The row is shared: :class:`FrictionWork` owns dW/dt, and each force term (a *source*: the
fluid shear of either film scheme, the rod friction with anchors or with its slip as
unknowns) adds -v F and -v dF/dU (with the TS shift) to it from the forces and derivatives
it computes for its own rows anyway, so no force is evaluated twice per Newton step. A
source has ``work_cols`` (the columns of its force) and a ``work`` attribute, (dof, v) or
None, set by :func:`attach`.
"""
import numpy as np

from ..core import Term, of_time


def attach(source, wdof, velocity):
    """Let ``source`` add its share of the W row: extends its COO pattern by the row wdof
    on its ``work_cols``."""
    cols = np.asarray(source.work_cols, np.int64)
    source.work = (int(wdof), of_time(velocity))
    source.rows = np.concatenate([source.rows, np.full(cols.size, wdof, np.int64)])
    source.cols = np.concatenate([source.cols, cols])


class FrictionWork(Term):
    def __init__(self, wdof, velocity, sources):
        """``wdof``: the dof of W; ``velocity``: v(t) (mm/s); ``sources``: the force terms,
        which from now on add their share of the row (module docstring)."""
        self.wd = int(wdof)
        self.sources = list(sources)
        for s in self.sources:
            attach(s, self.wd, velocity)
        self.rows = self.cols = np.array([self.wd], np.int64)

    def add_residual(self, t, u, udot, f):
        f[self.wd] += udot[self.wd]

    def jacobian_values(self, t, u, udot, shift):
        return np.array([shift])
