"""The rod-side guard: a run ends with a one-line SolveError when a boundary node off the rod
side is more than h_mix inside the rod.

Only the ``rod_side`` chain feels the rod (and carries the film); a node off it that passes
into the rod means the chain no longer covers the contact, and nothing stops the others
from passing through: a run would only crawl on (dt ~ 1e-7 s). A term without rows: its
post-step hook ``accepted`` checks every accepted state.
"""
import numpy as np

from ..core import SolveError, Term


class RodSideGuard(Term):
    def __init__(self, side, depth, note=None):
        """``side``: the :class:`sealts.contact.rod_side.RodSide` (its ``off`` nodes, their
        dofs and the rod radius); ``depth``: how far (mm) a node may enter the rod;
        ``note(u)``: more words for the message (e.g. the rolling angle), or None."""
        self.side, self.depth, self.note = side, float(depth), note

    def accepted(self, t, u):
        depth = self.side.off_depth(t, u)
        if depth.size == 0:
            return
        k = int(np.argmax(depth))
        if depth[k] <= self.depth:
            return
        why = self.note(u) if self.note is not None else ""
        raise SolveError(f"at t = {t:.6g} node {self.side.off[k]} off the rod side is "
                         f"{depth[k] * 1e3:.3g} um inside the rod: the rod side no longer "
                         f"covers the contact{why}")
