"""External loads on the seal as a physics term: prescribed nodal forces scaled in time."""
import numpy as np

from ..core import Term


class NodalForces(Term):
    """Dead nodal forces F (N) on dofs, scaled by ``scale(t)``: residual -= scale(t) F."""

    def __init__(self, dofs, forces, scale=lambda t: 1.0):
        self.dofs = np.asarray(dofs, np.int64)
        self.forces = np.asarray(forces, float)
        self.scale = scale
        self.rows = self.cols = np.zeros(0, np.int64)

    def add_residual(self, t, u, udot, f):
        np.subtract.at(f, self.dofs, self.scale(t) * self.forces)

    def jacobian_values(self, t, u, udot, shift):
        return np.zeros(0)
