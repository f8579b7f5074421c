"""Step 2 of the paper: the sealed pressure p_in on the wetted free surface.

p_in ramps over one pseudo-time unit after the mount and holds for as long again
(:mod:`sealts.steps.pseudo_time`), long-term material, frictionless (the film comes with
the coupling). The pressure-penetration front (:mod:`sealts.solid.pressure`) advances after
every accepted step (:class:`sealts.solid.pressure.AdvancingFront`, a post-step hook); then
it is settled against the static equilibrium at p_in
(:func:`sealts.steps.quasi_static.settle_front`).
"""
from ..problem.seal_model import ramp
from ..solid.pressure import AdvancingFront
from .base import Step
from .quasi_static import RodProgress, quasi_static, settle_front

# edges the front may advance per accepted step while p_in rises (AdvancingFront: without a
# limit the paper's O-ring flooded completely at 40 MPa); the settled state does not depend
# on it, the number of pseudo-time steps does (benchmarks/stress.md)
FRONT_STEP = 8.0


class Pressurise(Step):
    name = "pressurise"

    @staticmethod
    def pressure_load(state):
        """The pressure load of the step: p_in ramped over the protocol's ramp, and with
        it a back pressure p_out on the atmosphere side, nothing wetted yet."""
        fl, t0 = state.scene.fluid, state.protocol.pressurise[0]
        p_in, p_out = fl.p_in, fl.p_out
        back = (lambda t: p_out * ramp(t - t0)) if p_out != 0.0 else None
        return state.model.pressure_load(lambda t: p_in * ramp(t - t0), fl.p_crit, back)

    def run(self, state):
        model, scene = state.model, state.scene
        p_in, p_out, dt = scene.fluid.p_in, scene.fluid.p_out, scene.mount.dt
        mounted = state.results
        back = f", back pressure {p_out:g} MPa" if p_out != 0.0 else ""
        state.say(f"mounted: rod force {mounted['contact_force_total']:.6g} N; pressurising "
                  f"to {p_in:g} MPa{back}", force=True)
        t0, t_ramp, t1 = state.protocol.pressurise
        load = self.pressure_load(state)
        load.update(model.node_contact_pressure(t0, state.u), t0)
        eq = quasi_static(model, [load], state.u, (t0, t_ramp, t1), dt,
                          hooks=[AdvancingFront(load, model.node_contact_pressure,
                                                max_advance=FRONT_STEP)],
                          observers=[RodProgress(model, state.say)])
        eq, moved, updates = settle_front(model, load, eq, t1, dt)
        state.counters.add(eq.counters)
        settled(state, eq, load, t1, moved, updates, mounted,
                f"pressurised to {p_in:g} MPa{back}, pseudo-time {t1:g}")


def settled(state, eq, load, t, moved, updates, mounted, label,
            hint="try a larger fluid.p_crit"):
    """The state, results and profile of steps 1-2's end: the equilibrium ``eq`` at t with
    the settled front of ``load`` (it would still move ``moved`` edges after ``updates``
    updates; ``hint`` ends the warning where it would); ``mounted`` the mount's results."""
    model = state.model
    state.u, state.udot, state.t, state.load = eq.u, eq.udot, t, load
    res = model.results(t, eq.u, eq.udot)
    res["mounted"] = mounted
    res["pressure_force_radial"], res["pressure_force_axial"] = \
        model.pressure_resultant(load, t, eq.u)
    res["wetted_boundary_fraction"] = float(load.wet.mean())
    # edges (fractions summed) the front would still move from the final state: 0 when
    # front and equilibrium agree
    res["front_change_edges"], res["front_updates"] = moved, updates
    state.results = res
    if moved >= 1e-4:
        state.say(f"warning: the pressure-penetration front did not settle in "
                  f"{updates + 1} updates (one more would move it {moved:.3g} edges); "
                  + hint, force=True)
    y, h, p = model.contact_profile(t, eq.u)
    state.writer.profile(t, {"y": y, "h": h, "p_contact": p}, label=label)
