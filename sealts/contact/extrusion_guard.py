"""The extrusion guard: a run ends with a one-line PhysicalStop ("extrusion") when the seal
has flowed into the extrusion gap (``groove.clearance``) by more than ``groove.extrusion_limit``.

With a clearance the groove's side walls end at the bore r_rod + clearance
(:class:`sealts.contact.rigid.GrooveContact`, its ``edge``); seal material that passes a
wall's plane (z > z_b or z < z_a) can only be in the gap between rod and bore. How far it
has gone is the extrusion e = max_i max(z_i - z_b, z_a - z_i, 0) over the groove's nodes.
Beyond the limit the extruded lip would be nibbled off in service (the classic O-ring
failure at high pressure and large gaps); the model has no damage, so the run stops and
says where. A term without rows: its post-step hook checks every accepted state.

Extrusion starts with a tongue: the seal's surface runs along the rod into the gap and back
along the bore, so the rod side's chain turns over past the wall's plane
(:func:`sealts.contact.rod_side_guard.fold`, whatever the turned element's direction: past
the wall's plane no wall holds the rubber, so a reversal there is the tongue, not the
wall penalty's compliance). The film and the rod contact live on that
chain ordered along the rod and cannot follow it, so the run stops there too, as the
onset of extrusion (the rod-side guard would call it a fold). This guard runs before the
rod-side guard.
"""
import numpy as np

from ..core import PhysicalStop, Term
from .rod_side_guard import fold


def extrusion(groove, t, u):
    """(e, node): how far (mm) a groove node has passed a side wall's plane into the gap, the
    largest, and that node (-1 if none has)."""
    z = groove.X[groove.nodes, 1] + u[groove.uz]
    za, zb = groove.z_walls(t)
    past = np.maximum(z - zb, za - z)
    k = int(np.argmax(past))
    return (float(past[k]), int(groove.nodes[k])) if past[k] > 0.0 else (0.0, -1)


class ExtrusionGuard(Term):
    def __init__(self, groove, limit, side, pressure=None):
        """``groove``: the GrooveContact with its ``edge``; ``limit`` (mm); ``side``: the
        RodSide (the tongue's fold); ``pressure(t)``: the sealed pressure for the message
        (MPa), or None."""
        self.groove, self.limit, self.side = groove, float(limit), side
        self.pressure = pressure

    def accepted(self, t, u):
        e, node = extrusion(self.groove, t, u)
        if e <= 0.0:
            return
        at = f", p = {self.pressure(t):.4g} MPa" if self.pressure is not None else ""
        gap = (f"(bore r = {self.groove.edge[0]:.4g} mm, rod r = {self.side.r_rod(t):.4g} "
               "mm)")
        if e > self.limit:
            raise PhysicalStop("extrusion",
                               f"extrusion: at t = {t:.6g}{at} node {node} has flowed "
                               f"{e:.3g} mm past the groove's side wall into the extrusion gap "
                               f"{gap}; groove.extrusion_limit = {self.limit:g} mm")
        k = fold(self.side, u, back=None)
        if k >= 0 and self._past_wall(t, u, k):
            y = self.side.y(u)
            raise PhysicalStop("extrusion",
                               f"extrusion: at t = {t:.6g}{at} the seal flows into the "
                               f"extrusion gap {gap}: its rod side turns back along the bore "
                               f"between nodes {self.side.chain[k]} and "
                               f"{self.side.chain[k + 1]} (y = {y[k]:.4f} and "
                               f"{y[k + 1]:.4f} mm), {e:.3g} mm past the wall; the film along "
                               "the rod cannot follow a tongue")

    def _past_wall(self, t, u, k):
        """Whether the turned-over element lies at a wall's plane, within the edge."""
        za, zb = self.groove.z_walls(t)
        reach = self.groove.edge[1] + self.groove.edge[0] - self.side.r_rod(t)
        y = self.side.y(u)[k:k + 2]
        return bool(((y > zb - reach) | (y < za + reach)).any())
