"""The steps of a film-only scene (``model = "film"``, :mod:`sealts.problem.film_model`):
one steady Reynolds solution, or the transient film from the consistent steady pressure at
t = 0 (the film pressure is an algebraic unknown of the DAE) with the leakage volumes
integrated by the TS."""
from ..io.observers import Profiles, Series, StepLine
from ..problem.film_model import FilmModel, solve_steady_film
from ..problem.problem import Problem
from .base import Step


class SteadyFilm(Step):
    name = "steady film"

    def run(self, state):
        a = state.scene.analysis
        model, u, problem = solve_steady_film(state.scene, state.comm)
        c = problem.counters
        state.say(f"steady film solved: {c.newton} Newton, {c.linear} linear iterations",
                  force=True)
        state.writer.profile(a.time, model.profile(a.time, u))
        state.u, state.t, state.results = u, a.time, model.scalars(a.time, u)
        state.counters.add(c)


class FilmColumns:
    """The film's scalars, the step size, v and the Newton iterations of each step."""

    def __init__(self, model):
        self.model, self.newton = model, 0

    def __call__(self, t, u, info, row):
        out = self.model.scalars(t, u)
        out.update(dt=info.dt, v=self.model.v_of_t(t), newton=info.newton - self.newton)
        self.newton = info.newton
        return out


class TransientFilm(Step):
    name = "transient film"

    def run(self, state):
        scene, writer, a = state.scene, state.writer, state.scene.analysis
        _, u_film, pre = solve_steady_film(scene, state.comm, t=0.0)
        model = FilmModel(scene, transient=True)
        u0 = model.initial_state(0.0)
        u0[:model.scheme.size] = u_film[:model.scheme.size]
        problem = Problem(model.n, [model.term], comm=state.comm)
        state.parts["results_t0"] = model.scalars(0.0, u0)
        times = [0.0, *a.output_times, a.t_end]
        line = StepLine("step", [("Newton", "newton", 1, ""), ("min h", "h_min", 1e3, "um")])
        observers = [Series(writer, [FilmColumns(model)], state.say, line),
                     Profiles(writer, model.profile, times=times, say=state.say)]
        u = problem.transient(u0, 0.0, a.t_end, a.dt, a.output_times, observers)
        state.u, state.t, state.results = u, a.t_end, model.scalars(a.t_end, u)
        state.counters.add(problem.counters).add(pre.counters)
