"""The rod-side guard: a run ends with a one-line SolveError when a boundary node off the rod
side is more than h_mix inside the rod, or when the rod side folds over (a PhysicalStop,
"fold", where it turns back along the rod).

Only the ``rod_side`` chain feels the rod (and carries the film); a node off it that passes
into the rod means the chain no longer covers the contact, and nothing stops the others
from passing through: a run would only crawl on (dt ~ 1e-7 s). A term without rows: its
post-step hook ``accepted`` checks every accepted state.

A fold: an element of the chain near the rod turns over: its current axial length against
the reference order falls below -FOLD of its reference length, and the element points
backwards along the rod (its axial length below -BACK of its current length). The film is
a function of the axial position along the rod and cannot follow: the run stops and says
where. Further than FILM_GAP from the rod the film's conductance (h^3) is some 1e6 times
the contact's and carries nothing, and there a surface squeezed into the corner between
rod and groove wall creases (the paper's O-ring at 38 MPa with no clearance): with the
seal's self-contact (:mod:`.self_contact`) the crease closes on itself and only elements
with a node within FILM_GAP of the rod are watched; without it the crease's faces would
pass through each other, and the run stops there too, saying so. Where the rod side runs
up a groove wall, its nodes are pressed
into the wall by the wall's penalty (about 0.1 um per MPa) to depths that differ from node
to node, so neighbours there swap their axial order by microns (4 um at 40 MPa, more than
FOLD of a 0.025 mm element): their element runs along the wall, radially, and is not a fold
(the film takes it as a short positive element, :mod:`sealts.film.reynolds_fv`); nor is an
element both of whose nodes are pressed into the same wall, even where the surface there
is crumpled so short that the penalty's microns tilt it backwards. Nodes pressed flat
against a wall sit at one axial position to round-off, far above that bound.
"""
import numpy as np

from ..core import PhysicalStop, SolveError, Term

FOLD = 0.1      # an element inverted by a tenth of its reference length ...
BACK = 0.5      # ... and pointing backwards along the rod (within 60 degrees of it)
FILM_GAP = 0.01  # mm from the rod: elements further out are not watched for folds


def fold(side, u, back=BACK, skip=None):
    """The rod-side element most turned over (module docstring: its current axial length
    against the reference order below -FOLD of its reference length and below -``back`` of
    its current length; ``back`` None: whatever its direction), by its first chain index,
    but the elements where ``skip`` (a mask) is true; -1 if none is."""
    dz = np.diff(side.Z)
    if dz.size == 0:
        return -1
    order = np.sign(np.median(dz))
    dy = order * np.diff(side.y(u))
    back = (dy < -back * np.hypot(dy, np.diff(side.r(u))) if back is not None
            else np.ones(dy.size, bool))
    if skip is not None:
        back &= ~np.asarray(skip, bool)
    ratio = np.where(back, dy / np.abs(np.where(dz != 0.0, dz, np.inf)), np.inf)
    k = int(np.argmin(ratio))
    return k if ratio[k] < -FOLD else -1


class RodSideGuard(Term):
    def __init__(self, side, depth, note=None, walls=None, creases=False, fold_hint=""):
        """``side``: the :class:`sealts.contact.rod_side.RodSide` (its ``off`` nodes, their
        dofs and the rod radius); ``depth``: how far (mm) a node may enter the rod;
        ``note(u)``: more words for the message (e.g. the rolling angle), or None;
        ``walls(t)``: the groove's side walls (z_a, z_b) (mm): an element both of whose
        nodes are pressed into one of them is no fold, whatever its direction (their
        order there is the wall penalty's), or None; ``creases``: the seal's surface has its
        self-contact, which holds a fold away from the rod; ``fold_hint``: more words for
        the message of a fold on the rod (what causes it in this run and what to try)."""
        self.side, self.depth, self.note, self.walls = side, float(depth), note, walls
        self.creases, self.fold_hint = bool(creases), fold_hint

    def accepted(self, t, u):
        self._check_fold(t, u)
        self._check_off(t, u)

    def _pressed(self, t, u):
        """Per element: both nodes pressed into the same side wall (None without walls)."""
        if self.walls is None:
            return None
        za, zb = self.walls(t)
        y = self.side.y(u)
        a, b = y <= za, y >= zb
        return (a[:-1] & a[1:]) | (b[:-1] & b[1:])

    def _skipped(self, t, u):
        """Per element: both nodes pressed into one side wall (``_pressed``), or, with the
        self-contact, no node within FILM_GAP of the rod; None if nothing is skipped."""
        skip = self._pressed(t, u)
        if not self.creases:
            return skip
        far = self.side.gap(t, u) > FILM_GAP
        far = far[:-1] & far[1:]
        return far if skip is None else skip | far

    def _check_fold(self, t, u):
        side = self.side
        k = fold(side, u, skip=self._skipped(t, u))
        if k < 0:
            return
        y, h = side.y(u), side.gap(t, u) * 1e3
        a, b = side.chain[k], side.chain[k + 1]
        on_rod = min(h[k], h[k + 1]) <= FILM_GAP * 1e3
        if on_rod:        # a physical stop: the quasi-static seal has no state past it
            why = ("the seal's surface turns back along the rod, where the film (a function "
                   "of the axial position) cannot follow it" + self.fold_hint)
        else:             # the model's: its self-contact is off
            why = ("the seal's surface creases and its faces would pass through each other: "
                   "seal.self_contact = \"on\" closes the crease on itself")
        kind = (lambda m: PhysicalStop("fold", m)) if on_rod else SolveError
        raise kind(f"at t = {t:.6g} the rod side folds over between nodes {a} and {b} "
                   f"(y = {y[k]:.4f} and {y[k + 1]:.4f} mm, {h[k]:.3g} and "
                   f"{h[k + 1]:.3g} um from the rod{self._wall_note(t, y[k])}): {why}")

    def _wall_note(self, t, y):
        """How far the fold at ``y`` lies from the nearer groove wall (a fold next to the
        atmosphere side's wall is where the rod's friction drags the surface out of the
        corner: README, "Operating limits")."""
        if self.walls is None:
            return ""
        za, zb = self.walls(t)
        z = za if abs(y - za) <= abs(y - zb) else zb
        return f", {abs(y - z):.3g} mm from the groove wall at y = {z:g} mm"

    def _check_off(self, t, u):
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
