"""Step 3 with ``[hold] p_end``: the viscoelastic pressure step and hold
(:class:`sealts.problem.hold_problem.HoldProblem`).

The sealed pressure steps from fluid.p_in to hold.p_end over hold.t_ramp and is held until
hold.t_end, in real time (s). TS stops at the decades of t and at the kinks of a temperature
history. Output: a series row per accepted step, the contact profile at every stop
(hold_profiles.csv). At the end, the long-term static solution at p_end (the hyperelastic
material, from the hold's final state) is solved as well and the differences are reported
(``long_term_check``): after a hold far beyond the longest relaxation time they vanish.
"""
import numpy as np

from ..core import PhysicalStop, SolveError
from ..io.observers import Profiles, Series, StepLine, solver_columns
from ..problem.hold_problem import HoldProblem
from .base import Step
from .pseudo_time import PseudoTime
from .quasi_static import quasi_static, settle_front
from .run_checkpoint import Resumed, StepCheckpoint

PROFILES = "hold_profiles.csv"


class HoldColumns:
    """The hold's series columns: sealed pressure, rod force, peak contact pressure, min
    gap, wetted share of the boundary."""

    def __init__(self, hold):
        self.hold = hold

    def __call__(self, t, U, info, row):
        hold, model = self.hold, self.hold.model
        u = hold.displacement(U)
        _, h, p = model.contact_profile(t, u)
        return {"p_sealed": hold.load.pressure(t),
                "rod_force": float(hold.rod.forces(t, u).sum()),
                "p_contact_max": float(p.max()), "h_min": float(h.min()),
                "wetted": float(hold.load.wet.mean())}


class Hold(Step):
    name = "viscoelastic hold"

    def __init__(self, resume=None):
        """``resume``: the path of a hold checkpoint to go on from
        (:mod:`sealts.steps.run_checkpoint`)."""
        self.resume = resume

    def run(self, state):
        model, scene, say = state.model, state.scene, state.say
        hold, ve = scene.hold, scene.viscoelastic
        p_in = scene.fluid.p_in
        back = Resumed(self.resume) if self.resume else None
        if back is not None:
            back.restore_run(state)
        step = HoldProblem(model, state.u, state.load, p_in, hold.p_end, hold.t_ramp, ve,
                           hold.t_end, p_back=scene.fluid.p_out)
        say(step.classes.describe(step.series, step.shift), force=True)
        say(f"hold: {p_in:g} -> {hold.p_end:g} MPa over {hold.t_ramp:g} s, held to "
            f"{hold.t_end:g} s; {step.layout.n} unknowns ({len(step.classes.active)} active "
            f"Prony terms x 16 per cell)", force=True)

        def profile(t, U):
            y, h, p = model.contact_profile(t, step.displacement(U))
            return {"y": y, "h": h, "p_contact": p}

        t_end = hold.t_end
        stops = [t for t in 10.0 ** np.arange(-6, 13) if hold.t_ramp <= t < t_end]
        stops += [t for t in ve.temperature_times if 0.0 < t < t_end]  # kinks of A(theta(t))
        line = StepLine("hold step", [("rod force", "rod_force", 1.0, "N"),
                                      ("min h", "h_min", 1e3, "um")])
        series = Series(state.writer, [HoldColumns(step), solver_columns], say, line)
        observers = [series, Profiles(state.writer, profile, PROFILES)]
        if back is not None:      # the outputs and the state as they stood at its stop
            series.rows = list(back.rows)
            state.writer.restore_series(back.rows)
            state.writer.restore_profiles(PROFILES, back.profiles)
            say(f"hold resumed at t = {back.t:.6g} s from {back.path}", force=True)
        observers.append(StepCheckpoint(state, "hold", step.problem, series, PROFILES,
                                        wall_before=back.wall if back else 0.0,
                                        resumed=back is not None))
        U = step.run(t_end, hold.dt, hold.rtol, stops=stops, observers=observers,
                     resume=back.snapshot if back else None,
                     U0=back.U if back else None)
        u = step.displacement(U)
        res = model.results(t_end, u, quasi_static=False)
        res["pressurised"] = state.results
        c = step.problem.counters
        state.parts["hold"] = {
            "p_from": p_in, "p_to": hold.p_end, "t_end": t_end,
            "wlf_shift": step.shift,            # the largest over the hold
            "prony_active_tau": [float(step.shift * step.series.tau[i])
                                 for i in step.classes.active],
            "prony_relaxed": len(step.classes.relaxed),
            "prony_frozen": len(step.classes.frozen),
            "prony_error_bound": step.classes.error_bound,
            "unknowns": int(step.layout.n), "steps_accepted": c.steps,
            "steps_rejected": c.rejected, "newton_iterations": c.newton,
            "linear_iterations": c.linear, "newton_failures": c.newton_failures,
            "long_term_check": long_term_check(step, U, t_end, state.protocol),
        }
        if back is not None:
            state.parts["hold"]["restarted_at"] = back.t
        state.u, state.t, state.results = u, t_end, res
        state.load = step.load
        state.counters.add(c)


def long_term_check(step, U, t_end, protocol):
    """How far the hold's end state is from the long-term (hyperelastic) equilibrium at
    the final pressure: its out-of-balance nodal forces in the long-term problem (N), and
    the distance to the equilibrium that the quasi-static driver of steps 1-2 (stabilised
    pseudo-time after steps 1-2, then Newton, then the front settled) finds from it (mm, N,
    edges of front position). A bare Newton solve from there inverted elements on the
    0.05 mm mesh."""
    m = step.model
    u = step.displacement(U)
    tau_max = step.shift * float(step.series.tau.max())
    if t_end < 20.0 * tau_max:
        return {"skipped": f"hold.t_end = {t_end:g} s is not far beyond the longest "
                           f"relaxation time {tau_max:g} s"}
    walls, load = step.long_term_terms()
    # the hold's state in the long-term problem: its out-of-balance nodal forces
    residual = m.problem(m.n, m.local_terms(walls), dofs=m.dofs).global_residual(t_end, u)
    out = {"long_term_residual_max_N": float(np.abs(residual).max())}
    window = PseudoTime.window(protocol.end(pressurised=True))
    try:
        eq = quasi_static(m, [load], u, window, 0.05)
        eq, _, _ = settle_front(m, load, eq, window[2], 0.05)
    except SolveError as e:
        what = f"stopped ({e.cause})" if isinstance(e, PhysicalStop) else "failed"
        return {**out, "static_solve": f"{what}: {e}"}
    f_hold = float(step.rod.forces(t_end, u).sum())
    f_static = float(step.rod.forces(t_end, eq.u).sum())
    return {**out, "max_displacement_difference_mm": float(np.abs(eq.u - u).max()),
            "rod_force_hold": f_hold, "rod_force_long_term": f_static,
            "rod_force_relative_difference": abs(f_hold - f_static) / abs(f_static),
            "static_equilibrium": eq.udot is None,
            "front_difference_edges": float(sum(abs(a - b) for a, b in
                                                zip(load.reach, step.load.reach)))}
