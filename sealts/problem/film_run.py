"""Film-only scenes: a film on a rigid gap, solved steady (SNES) or transient (TS).

Data flow: scene -> film nodes y -> scheme (unknown layout) -> FilmTerm -> Problem -> output.
A transient run starts from the consistent steady pressure at t = 0 (the film pressure is an
algebraic unknown of the DAE) and integrates the leakage volumes with the TS.
"""
import time

import numpy as np

from ..film.flow_factors import FlowFactors
from ..film.paper_scheme import PaperScheme
from ..film.quantities import (contact, effective_gap, integrate, shear_stress,
                               specific_area)
from ..film.reynolds_fv import ControlVolumeScheme, control_volumes
from ..film.term import FilmTerm, RigidGap
from .problem import Problem


def flow_factors_of(film):
    if film.flow_factors == "patir-cheng":
        return FlowFactors.patir_cheng(film.rq, film.gamma, film.rough_surface)
    if film.flow_factors == "table":
        return FlowFactors.from_table(film.table, film.rq, film.rough_surface)
    return FlowFactors.none()


class FilmModel:
    """A scene's film: nodes, scheme and term, with the quantities engineers read off it."""

    def __init__(self, scene, transient=None):
        self.scene = scene
        g, f, fl = scene.gap, scene.film, scene.fluid
        self.y = np.linspace(0.0, g.length, f.elements + 1)
        v = float(scene.rod.velocity)
        self.v_of_t = lambda t: v
        args = (self.y, fl.viscosity, self.v_of_t, fl.p_in, fl.p_out, flow_factors_of(f),
                f.h_floor)
        self.scheme = (PaperScheme(*args, alpha=f.alpha) if f.scheme == "paper"
                       else ControlVolumeScheme(*args))
        self.gap = RigidGap(self.y, g.h_min, g.s_h, g.squeeze_velocity, g.tilt_rate)
        self.area = specific_area(g.symmetry, g.width, scene.rod.radius)
        if transient is None:
            transient = scene.analysis.type == "transient"
        self.transient = transient
        self.n = self.scheme.size + (2 if transient else 0)
        self.term = FilmTerm(self.scheme, self.gap, 0,
                             self.scheme.size if transient else None, self.area, f.squeeze)

    def initial_state(self, t0):
        u = np.zeros(self.n)
        u[:self.scheme.size] = self.scheme.initial_guess()
        self.scheme.set_row_scale(t0, *self.term.film(t0, u))
        return u

    def profile(self, t, u):
        """Nodal film profile at time t: dict of arrays (mm, MPa)."""
        s = self.scene
        x, h, hd = self.term.film(t, u)
        p = self.scheme.pressure(x)
        dpdy = self.scheme.pressure_gradient(t, x, h, hd)
        v = self.v_of_t(t)
        tau = shear_stress(self.y, h, hd, dpdy, v, s.fluid.viscosity, s.film.h_floor,
                           s.film.beta)
        prof = {"y": self.y, "h": h, "p": p, "tau": tau}
        if s.asperity.enabled:
            a = s.asperity
            prof["p_asperity"], prof["tau_solid"] = contact(h, v, a.h_mix, a.p_mix, a.mu_s)
        return prof

    def scalars(self, t, u):
        """Key results at time t: peak pressure, load, friction, flows, film volume."""
        prof = self.profile(t, u)
        y, p = prof["y"], prof["p"]
        i = int(np.argmax(p))
        y_pk, p_pk = y[i], p[i]
        if 0 < i < y.size - 1:  # parabola through the peak node and its neighbours
            a, b, c = np.polyfit(y[i - 1:i + 2] - y[i], p[i - 1:i + 2], 2)
            if a < 0:
                y_pk, p_pk = y[i] - b / (2 * a), c - b * b / (4 * a)
        q_in, q_out = self.term.flows(t, u)
        out = {
            "t": float(t),
            "p_max": float(p_pk), "y_at_p_max": float(y_pk),
            "load": integrate(y, p, self.area),
            "friction_fluid": integrate(y, prof["tau"], self.area),
            "Q_in": float(q_in), "Q_out": float(q_out),
            "h_min": float(prof["h"].min()),
            "film_volume": self.area * float(control_volumes(y) @ effective_gap(
                prof["h"], self.scene.film.h_floor)),
        }
        if "p_asperity" in prof:
            out["load_asperity"] = integrate(y, prof["p_asperity"], self.area)
            out["friction_solid"] = integrate(y, prof["tau_solid"], self.area)
        if self.transient:
            out["V_in"], out["V_out"] = float(u[-2]), float(u[-1])
        return out


def solve_steady_film(scene, comm=None, t=None):
    """Film pressure at one time; returns (model, u, problem)."""
    model = FilmModel(scene, transient=False)
    t = scene.analysis.time if t is None else t
    u0 = model.initial_state(t)
    problem = Problem(model.n, [model.term], comm=comm)
    return model, problem.solve_steady(u0, t), problem


class Progress:
    """Throttled one-line progress reports on rank 0."""

    def __init__(self, comm, enabled=True, every=1.0):
        self.on = enabled and comm.getRank() == 0
        self.every, self.last = every, -1e9

    def __call__(self, line, force=False):
        now = time.perf_counter()
        if self.on and (force or now - self.last >= self.every):
            print(line, flush=True)
            self.last = now


def run_film(scene, writer, comm):
    """Run a film-only scene, writing through ``writer``; returns the summary dict."""
    t_wall = time.perf_counter()
    a = scene.analysis
    say = Progress(comm, scene.output.progress)
    if a.type == "steady":
        model, u, problem = solve_steady_film(scene, comm)
        say(f"steady film solved: {problem.counters.newton} Newton, "
            f"{problem.counters.linear} linear iterations", force=True)
        writer.profile(a.time, model.profile(a.time, u))
        results = model.scalars(a.time, u)
        counters = problem.counters
    else:
        # consistent initial film pressure, then the DAE with the leakage volumes
        _, u_film, pre = solve_steady_film(scene, comm, t=0.0)
        model = FilmModel(scene, transient=True)
        u0 = model.initial_state(0.0)
        u0[:model.scheme.size] = u_film[:model.scheme.size]
        problem = Problem(model.n, [model.term], comm=comm)
        writer.profile(0.0, model.profile(0.0, u0))
        results_t0 = model.scalars(0.0, u0)
        state = {"newton": 0}

        def on_step(ts, step, t, u):
            row = model.scalars(t, u)
            its = ts.getSNESIterations()
            row.update(dt=ts.getTimeStep(), v=model.v_of_t(t), newton=its - state["newton"])
            state["newton"] = its
            writer.series(row)
            say(f"step {step:5d}  t = {t:.6g} s  dt = {row['dt']:.3g} s  "
                f"Newton {row['newton']}  h_min = {row['h_min'] * 1e3:.4g} um")

        def on_stop(t, u):
            writer.profile(t, model.profile(t, u))
            say(f"output at t = {t:.6g} s", force=True)

        u = problem.transient(u0, 0.0, a.t_end, a.dt, a.output_times, on_step, on_stop)
        results = model.scalars(a.t_end, u)
        counters = problem.counters
        counters.newton += pre.counters.newton
        counters.linear += pre.counters.linear
    summary = {
        "scene": scene.name,
        "source": scene.source,
        "analysis": a.type,
        "scheme": scene.film.scheme,
        "unknowns": model.n,
        "ranks": comm.getSize(),
        "wall_time_s": time.perf_counter() - t_wall,
        "steps_accepted": counters.steps,
        "steps_rejected": counters.rejected,
        "newton_iterations": counters.newton,
        "linear_iterations": counters.linear,
        "residual_evaluations": counters.residuals,
        "jacobian_evaluations": counters.jacobians,
        "results": results,
        "units": {"length": "mm", "pressure": "MPa", "force": "N", "time": "s",
                  "flow": "mm^3/s", "volume": "mm^3"},
    }
    if a.type == "transient":
        summary["results_t0"] = results_t0
    writer.summary(summary)
    return summary
