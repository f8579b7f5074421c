"""Step 1 of the paper (Section 3.1.1): the seal mounted dry between rod and groove.

Long-term material, frictionless walls. The groove bottom starts just clear of the seal and
moves to its final radius over the pseudo-time [0, 1] (:mod:`sealts.steps.pseudo_time`),
like ABAQUS's interference fit resolved gradually; the rod stays at its radius (an O-ring
whose inner diameter is smaller than the rod's: the rod starts inside and grows). A hold
until mount.t_hold lets the viscous stabilisation die out; the run reports its share.
"""
import numpy as np

from .base import Step
from .quasi_static import RodProgress, quasi_static


class Mount(Step):
    name = "mount"

    def run(self, state):
        model, scene = state.model, state.scene
        eq = quasi_static(model, [], np.zeros(model.n), state.protocol.mount, scene.mount.dt,
                          observers=[RodProgress(model, state.say)])
        state.u, state.udot, state.t = eq.u, eq.udot, state.protocol.mount[2]
        state.counters.add(eq.counters)
        state.results = model.results(state.t, state.u, state.udot)
        y, h, p = model.contact_profile(state.t, state.u)
        state.writer.profile(state.t, {"y": y, "h": h, "p_contact": p},
                             label=f"mounted, pseudo-time {state.t:g}")
