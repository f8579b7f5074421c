"""The quasi-static driver of steps 1-2: a stabilised pseudo-time run, then the static
equilibrium itself, and the pressure-penetration front settled against it.

The pseudo-time path needs no accuracy of its own, so the TS tolerances default to rtol
1e-3, atol 1e-4 mm (-ts_rtol wins); measured on the coarse O-ring mount: 1081 steps at the
DAE default 1e-6, 72 at 1e-3, the same mounted state to 1e-7. The final Newton solve drops
the viscous stabilisation (in the mounted state the walls hold every mode); if it fails, the
stabilised state stands and its rate du/dt over the last accepted step is returned, so that
the stabilisation's share of the load can be reported.
"""
from dataclasses import dataclass, field

import numpy as np

from ..core import Counters, Observer, SolveError
from ..solid.pressure import settle
from .pseudo_time import PseudoTime


@dataclass
class Equilibrium:
    """A quasi-static step's end: u, and udot (None where u is a static equilibrium; the
    stabilised run's final rate where the static solve failed)."""
    u: np.ndarray
    udot: np.ndarray | None
    counters: Counters = field(default_factory=Counters)
    stopped: bool = False        # settle_front(keep=True) stopped on a failed solve


class _LastTwo(Observer):
    """The last two accepted states, for the rate at the end."""

    def __init__(self):
        self.states = []

    def accepted(self, t, u, info):
        self.states = self.states[-1:] + [(t, u)]

    def rate(self):
        (ta, ua), (tb, ub) = self.states[-2], self.states[-1]
        return (ub - ua) / (tb - ta)


def stabilised_problem(model, extra, hooks=()):
    """The Problem of the stabilised pseudo-time run: the seal, the walls, the ``extra``
    terms (e.g. the pressure load), the viscous stabilisation, the guards (rod side,
    extrusion: the load's pressure in its message) and the ``hooks`` (post-step terms: the
    front)."""
    pressure = next((x.pressure for x in extra if hasattr(x, "pressure")), None)
    terms = (model.local_terms(model.walls() + list(extra), stab=True)
             + model.guards(pressure=pressure) + list(hooks))
    return model.problem(model.n, terms, dofs=model.dofs)


def quasi_static(model, extra, u0, window, dt0, hooks=(), observers=()):
    """Stabilised pseudo-time run over ``window`` = (t0, stop, t1) (``stabilised_problem``),
    TS stopping at ``stop``; then the static equilibrium at t1."""
    t0, stop, t1 = window
    problem = stabilised_problem(model, extra, hooks)
    last = _LastTwo()
    u = problem.transient(u0, t0, t1, dt0, stops=(stop,), observers=[last, *observers],
                          rtol=1e-3, atol=1e-4)
    out = Equilibrium(u, None, problem.counters)
    try:
        out.u = static(model, extra, u, t1, out.counters)
    except SolveError:
        out.udot = last.rate()
    return out


def static(model, extra, u, t, counters, prefix="static_", linesearch="basic", max_it=10):
    """Newton from u on the unstabilised equilibrium at t (raises SolveError); its
    iterations count in ``counters``. ``prefix``, ``linesearch``, ``max_it``: its PETSc
    options prefix, default line search and iterations."""
    problem = model.problem(model.n, model.local_terms(model.walls() + list(extra)),
                            linesearch=linesearch, prefix=prefix, dofs=model.dofs)
    problem.max_it = max_it
    try:
        return problem.solve_steady(u, t)
    finally:
        counters.newton += problem.counters.newton
        counters.linear += problem.counters.linear


def settle_front(model, load, eq, t, dt0, tol=1e-4, max_updates=30, keep=False, **newton):
    """Front update and static solve in turn, from the equilibrium ``eq`` at t, until the
    front moves by less than ``tol`` edges (:func:`sealts.solid.pressure.settle`, which
    bisects a front caught in a cycle); the state keeps the front it was solved with. A
    static solve that fails falls back to the stabilised driver on the window after t
    (:class:`PseudoTime`); with ``keep``, the settling stops there instead and the last
    equilibrium stands with its front (``stopped``). Returns (equilibrium, edges the front
    would still move, index of the last update). ``newton``: the static solves' options
    (:func:`static`)."""
    state = {"eq": eq, "good": (list(load.reach), eq.u), "solves": 0}

    def solve():
        e = state["eq"]
        try:
            e.u, e.udot = static(model, [load], e.u, t, e.counters, **newton), None
        except SolveError:
            if keep:
                raise _Unsettled() from None
            again = quasi_static(model, [load], e.u, PseudoTime.window(t), dt0)
            state["eq"] = Equilibrium(again.u, again.udot, e.counters + again.counters)
        state["good"] = (list(load.reach), state["eq"].u)
        state["solves"] += 1

    try:
        moved, k = settle(load, t, lambda: model.node_contact_pressure(t, state["eq"].u),
                          solve, tol, max_updates)
    except _Unsettled:
        failed = list(load.reach)
        reach, state["eq"].u = state["good"]
        state["eq"].stopped = True
        load.set_reach(reach)
        moved = float(sum(abs(a - b) for a, b in zip(failed, reach)))
        k = state["solves"]               # the update whose solve failed
    return state["eq"], moved, k


class _Unsettled(Exception):
    """A static solve of the settling failed (``settle_front(..., keep=True)``)."""


class RodProgress(Observer):
    """The quasi-static steps' progress line: step, pseudo-time, rod force and min gap."""

    def __init__(self, model, say):
        self.model, self.say = model, say

    def accepted(self, t, u, info):
        if self.say.due():
            rod = self.model.rod
            self.say(f"step {info.step:4d}  t = {t:.4g}  dt = {info.dt:.3g}  rod force = "
                     f"{rod.forces(t, u).sum():.4g} N  min h = "
                     f"{rod.side.gap(t, u).min() * 1e3:.4g} um")
