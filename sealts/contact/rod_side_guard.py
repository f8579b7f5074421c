"""The rod-side guard: a run ends with a one-line SolveError when a boundary node off the rod
side is more than h_mix inside the rod.

Only the ``rod_side`` chain feels the rod (and carries the film); a node off it that passes
into the rod means the chain no longer covers the contact, and nothing stops the others
from passing through: a run would only crawl on (dt ~ 1e-7 s). A term without rows: its
post-step hook ``accepted`` checks every accepted state.
"""
import numpy as np

from ..core import SolveError, Term, of_time


class RodSideGuard(Term):
    def __init__(self, X, nodes, udofs, r_rod, depth, note=None):
        """``nodes``: the boundary nodes off the rod side; ``udofs`` (n_nodes, 2): their
        displacement dofs in the problem's serial numbering; ``r_rod``: the rod radius (mm,
        number or function of t); ``depth``: how far (mm) a node may enter the rod;
        ``note(u)``: more words for the message (e.g. the rolling angle), or None."""
        self.X, self.nodes = X, np.asarray(nodes, np.int64)
        self.udofs = np.asarray(udofs, np.int64)
        self.r_rod, self.depth, self.note = of_time(r_rod), float(depth), note

    def accepted(self, t, u):
        off = self.nodes
        depth = self.r_rod(t) - (self.X[off, 0] + u[self.udofs[off, 0]])
        k = int(np.argmax(depth))
        if depth[k] <= self.depth:
            return
        why = self.note(u) if self.note is not None else ""
        raise SolveError(f"at t = {t:.6g} node {off[k]} off the rod side is "
                         f"{depth[k] * 1e3:.3g} um inside the rod: the rod side no longer "
                         f"covers the contact{why}")
