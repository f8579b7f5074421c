"""What a problem is made of, without PETSc or numba: terms, constraints, solve errors and
iteration counters. ``sealts check`` and ``sealts keys`` stop here.

A physics term (:class:`Term`) supplies its Jacobian's COO pattern (``rows``, ``cols``),
its residual and its Jacobian values, and, if it carries history, a post-step hook
``accepted(t, u)`` that :class:`sealts.problem.Problem` calls after every accepted step
(docs/design.md, "Term lifecycle").
"""
import sys
from dataclasses import dataclass, fields

import numpy as np


class SolveError(RuntimeError):
    """A solve that could not be completed (diverged SNES, a TS that could not step, a
    state that left the model's range); its message is one line naming the cause."""


class PhysicalStop(SolveError):
    """A run that stops for a physical reason it names, a result and not a numerical
    failure: ``cause`` one of "extrusion" (the seal flows into the extrusion gap),
    "blow-by" (the fluid passes the seal), "fold" (the rod side turns back along the rod)
    and "crease" (a fold of the surface the refined mesh cannot carry). The summary says
    ``"status": "stopped"`` with the cause; the table of scripts/stress.py "stopped"."""

    def __init__(self, cause, message):
        super().__init__(message)
        self.cause = cause

    def __reduce__(self):         # pickled whole (rank 0's verdict broadcast to the others)
        return PhysicalStop, (self.cause, str(self))


def reworded(e, message):
    """``e``'s message replaced (a caller that adds where it happened): a PhysicalStop
    stays one, with its cause; any other SolveError becomes a plain one."""
    return PhysicalStop(e.cause, message) if isinstance(e, PhysicalStop) else SolveError(message)


class StepTooSmall(SolveError):
    """TS's steps stuck at their minimum size: the solution runs away faster than any step
    (:meth:`sealts.problem.Problem._check_min_step`); ``t`` where."""

    def __init__(self, message, t=None):
        super().__init__(message)
        self.t = t


def of_time(x):
    """A term's parameter given as a number or as a function of t, as a function of t."""
    return x if callable(x) else (lambda t, x=float(x): x)


_NONE = np.zeros(0, np.int64)
_NONE.setflags(write=False)       # shared by every term without rows: never written


class Term:
    """A physics term of the DAE F(t, U, U') = sum_terms F_term = 0.

    * ``rows, cols``: its Jacobian's COO pattern in local dof numbers, fixed for the run;
    * ``add_residual(t, u, udot, f)``: adds its part of F to the local array f;
    * ``jacobian_values(t, u, udot, shift)``: dF/dU + shift dF/dU' for its pattern
      (duplicates add up);
    * ``accepted(t, u)``: the post-step hook, after every accepted step and at the start
      (u full, in serial order); the term's history moves here. A SolveError raised here
      ends the run with its message;
    * ``nonfinite(t, u)``: what and where a non-finite residual of the term is physically,
      or None (a run that stops on one names it; by default the first such unknown);
    * ``history_names``: the attributes (arrays) that hook moves, the history not in U: a
      checkpoint saves them (``history()``) and a restarted run puts them back
      (``restore``);
    * ``event_directions``: one direction (+1, -1, 0) per event of the term: TS locates
      in time where ``event_values(t, u)`` (one indicator per event, u full, serial order)
      crosses zero that way (``TSSetEventHandler``), then calls ``event(t, u, which)``
      (``which``: the indices of the events that fired) and restarts its integrator. A
      change of the term there is discrete, recorded and located, not made between steps.
      ``event`` may also set unknowns of its own in u (in place): the run goes on from the
      changed state.
    """

    rows = cols = _NONE
    history_names = ()
    event_directions = ()

    def event_values(self, t, u):
        """The indicator of each event at the state u (see the class docstring)."""
        return np.zeros(0)

    def event(self, t, u, which):
        """What the term does when its events ``which`` fire at t (the state u)."""

    def history(self):
        """The term's history not in U (name -> array), for a checkpoint."""
        return {n: np.array(getattr(self, n), float) for n in self.history_names}

    def restore(self, history):
        """Put back a :meth:`history` (a restarted run)."""
        for n in self.history_names:
            setattr(self, n, np.array(history[n], float))

    def add_residual(self, t, u, udot, f):
        pass

    def jacobian_values(self, t, u, udot, shift):
        """The values of dF/dU + shift dF/dU' on the term's pattern (rows, cols). The array
        may be the term's own buffer, overwritten by its next call: the caller copies."""
        return np.zeros(0)

    def accepted(self, t, u):
        """Post-step hook: nothing to do for a term without history."""

    def nonfinite(self, t, u):
        """Its non-finite residual at u in words, or None (the caller names the unknown)."""
        return None


class Constraints:
    """Prescribed unknowns u[dofs] = values(t)."""

    def __init__(self, dofs, values):
        self.dofs = np.asarray(dofs, np.int64)
        self._values = values

    def values(self, t):
        v = self._values(t) if callable(self._values) else self._values
        return np.broadcast_to(np.asarray(v, float), self.dofs.shape)


@dataclass
class Counters:
    """Work done by the solvers of one problem or step (merge them with ``+``)."""
    steps: int = 0
    rejected: int = 0
    newton: int = 0
    linear: int = 0
    newton_failures: int = 0    # failed Newton solves, each retried with a smaller step
    residuals: int = 0
    jacobians: int = 0

    def __add__(self, other):
        return Counters(*[getattr(self, f.name) + getattr(other, f.name)
                          for f in fields(self)])

    def add(self, other):
        """Add another's counts to these (in place); returns self."""
        for f in fields(self):
            setattr(self, f.name, getattr(self, f.name) + getattr(other, f.name))
        return self


@dataclass
class StepInfo:
    """What the time stepper reports with an accepted step: its number, the size of the
    step that comes next (s), and the Newton iterations of this run so far."""
    step: int
    dt: float
    newton: int


class Observer:
    """An output attached to a Problem's run (docs/design.md, "Observers"): ``start(t, u)``
    sees the initial state; after the terms' hooks, ``accepted(t, u, info)`` every accepted
    state (and the start), u full and in serial order; ``stop(t, u)`` the states at the
    run's stop times (output times and the end); ``close()`` runs when the run ends, also
    when it fails. All do nothing by default."""

    def start(self, t, u):
        pass

    def accepted(self, t, u, info):
        pass

    def stop(self, t, u):
        pass

    def close(self):
        pass


class Recorder(Observer):
    """Every accepted state (t, u) in ``states`` and the stop states in ``stops``, in
    memory (tests, scripts); ``call(t, u)`` on each accepted state too, if given."""

    def __init__(self, call=None):
        self.states, self.stops, self.call = [], [], call

    def accepted(self, t, u, info):
        self.states.append((t, u))
        if self.call is not None:
            self.call(t, u)

    def stop(self, t, u):
        self.stops.append((t, u))


def _free_refs():
    """sys.getrefcount of an array that only a list refers to, seen from a loop over the
    list as in :meth:`BufferPool.get` (the interpreter's own count: borrowed references
    may make it smaller)."""
    for buf in [np.empty(1)]:
        return sys.getrefcount(buf)


_FREE_REFS = _free_refs()


class BufferPool:
    """Arrays reused from call to call, but only those nothing outside the pool refers to:
    a caller may keep the array it was given (a preconditioner set up from its values) and
    the pool's next ``get`` hands out another. Arrays of tens of MB are fresh memory from
    the OS at every call otherwise, paid for in page faults."""

    def __init__(self):
        self.arrays = []

    def get(self, size):
        """A free array of ``size`` float64 (its values undefined)."""
        for buf in self.arrays:
            if buf.size == size and sys.getrefcount(buf) <= _FREE_REFS:
                return buf
        self.arrays.append(np.empty(size))
        return self.arrays[-1]
