"""Events of a term (Term.event_directions): TS locates the crossing, the term changes, the
integrator restarts. Closed form: y' = a - y, y(0) = 0, with a = 1 until y reaches 1/2,
then a = 3: the event at t_e = ln 2, and y(t) = 3 - 2.5 exp(-(t - t_e)) after it.

And the moving pressure-penetration front (sealts.solid.moving_front) on a load whose
target the test sets: when it moves, how far, how fast, and when it stops the run."""
import numpy as np
import pytest

from sealts.core import Recorder, SolveError, Term
from sealts.problem import Problem
from sealts.solid.moving_front import MAX_FLIPS, MIN_RAMP, MovingFront


class Relax(Term):
    """F = y' - (a - y); an event where y - 1/2 crosses zero upwards sets a = 3."""

    event_directions = (1,)

    def __init__(self):
        self.rows = self.cols = np.array([0])
        self.a, self.fired = 1.0, []

    def add_residual(self, t, u, udot, f):
        f[0] += udot[0] - (self.a - u[0])

    def jacobian_values(self, t, u, udot, shift):
        return np.array([shift + 1.0])

    def event_values(self, t, u):
        return [u[0] - 0.5]

    def event(self, t, u, which):
        self.fired.append((t, float(u[0]), list(which)))
        self.a = 3.0


def test_an_event_is_located_and_changes_the_problem():
    term = Relax()
    rec = Recorder()
    p = Problem(1, [term])
    y = p.transient(np.zeros(1), 0.0, 3.0, 1e-3, observers=[rec], rtol=1e-8, atol=1e-10)
    (t_e, y_e, which), = term.fired
    assert which == [0]
    assert t_e == pytest.approx(np.log(2.0), abs=1e-5)
    assert y_e == pytest.approx(0.5, abs=1e-6)
    assert y[0] == pytest.approx(3.0 - 2.5 * np.exp(-(3.0 - np.log(2.0))), rel=1e-5)


class Jump(Relax):
    """Relax, but its indicator jumps through zero (from -1 to +1 where y passes 1/2), as
    a front's target that jumps by many edges: TS can only bisect the bracket."""

    def event_values(self, t, u):
        return [1.0 if u[0] > 0.5 else -1.0]


def test_an_indicator_that_jumps_is_located_without_a_stall():
    """The bisection stops at a bracket of EVENT_DT_MIN of the span, far above TSAdapt's
    smallest step: with PETSc's own floor the steps fell below that step twice in a row,
    which the run took for a stuck controller and stopped (StepTooSmall)."""
    from sealts.problem.problem import EVENT_DT_MIN
    term = Jump()
    p = Problem(1, [term])
    p.stop_at_min_step = True
    y = p.transient(np.zeros(1), 0.0, 3.0, 1e-3, rtol=1e-8, atol=1e-10)
    (t_e, y_e, which), = term.fired
    assert which == [0]
    # located to the bracket: y' = 1/2 there, so y within a few brackets' change of 1/2
    assert abs(y_e - 0.5) < 10 * 0.5 * EVENT_DT_MIN * 3.0
    assert t_e == pytest.approx(np.log(2.0), abs=1e-5)
    assert y[0] == pytest.approx(3.0 - 2.5 * np.exp(-(3.0 - np.log(2.0))), rel=1e-5)


class FakeLoad:
    """A load whose fronts' targets the test sets (target_reach ignores the state)."""

    def __init__(self, reach):
        self.reach, self.target, self.exit_at = list(reach), list(reach), np.inf

    def set_reach(self, reach):
        self.reach = list(reach)

    def target_reach(self, contact, t):
        return list(self.target)

    def check_blow_by(self, t):
        if max(self.reach) >= self.exit_at:
            raise SolveError(f"blow-by at t = {t}")


def front(reach=(10.0, 20.0), tol=0.1):
    load = FakeLoad(reach)
    return load, MovingFront(load, lambda t, u: None, tol=tol)


def test_the_front_fires_at_the_tolerance_and_ramps_at_its_targets_pace():
    load, mf = front()
    assert mf.event_directions == (1, -1, 1, -1)
    load.target = [10.05, 20.0]
    assert np.all(np.sign(mf.event_values(0.5, None)) == [-1, 1, -1, 1])   # within +-tol
    load.target = [10.1, 19.8]              # front 1 at +tol, front 2 past -tol
    v = mf.event_values(2.0, None)
    assert v[0] == pytest.approx(0.0, abs=1e-12) and v[3] < 0.0
    mf.event(2.0, None, [0, 3])
    # from where each stood, over the 2 s its target took to drift: at the target's pace
    assert mf.reach_at(2.0) == pytest.approx([10.0, 20.0])
    assert mf.reach_at(3.0) == pytest.approx([10.05, 19.9])
    assert mf.reach_at(5.0) == pytest.approx([10.1, 19.8])
    mf.add_residual(3.0, None, None, None)               # the load's wetting at t
    assert load.reach == pytest.approx([10.05, 19.9])
    # the events now count from where the fronts are going: quiet until +-tol from there
    assert mf.event_values(2.0, None) == pytest.approx([-0.1, 0.1, -0.1, 0.1])
    assert np.all(np.sign(mf.event_values(3.0, None)) == [-1, 1, -1, 1])
    load.target = [10.3, 19.8]              # the target runs on: the next ramp is faster
    mf.event(2.5, None, [0])
    assert mf.ramps[0][:2] == pytest.approx([2.5, 0.5])
    assert mf.reach_at(3.0)[0] == pytest.approx(10.3)
    assert list(mf.moves) == [2, 1]


def test_two_events_at_one_time_ramp_over_the_shortest_time():
    load, mf = front()
    load.target = [11.0, 20.0]
    mf.event(1.0, None, [0])
    load.target = [12.0, 20.0]
    mf.event(1.0, None, [0])
    assert mf.ramps[0][1] == MIN_RAMP


def test_a_target_on_the_atmosphere_side_is_blow_by_at_once():
    load, mf = front()
    load.exit_at = 15.0
    load.target = [16.0, 20.0]
    with pytest.raises(SolveError, match="blow-by"):
        mf.event(1.0, None, [0])


def test_a_front_that_flips_on_end_stops_the_run_naming_it():
    load, mf = front()
    for k in range(MAX_FLIPS):
        load.target = [10.2, 20.0] if k % 2 == 0 else [10.0, 20.0]
        mf.event(1.0 + 1e-9 * k, None, [0 if k % 2 == 0 else 1])
    load.target = [10.2, 20.0]
    with pytest.raises(SolveError, match="front 1 flips between .* bistable"):
        mf.event(1.0 + 1e-9 * MAX_FLIPS, None, [0])


class SteepLoad(FakeLoad):
    """Front 1's target falls eleven times faster than the front advances (as at 30 MPa
    when the instroke starts): T(b) = b* - 11 (b - b*), consistent front b* = 10.5."""

    def target_reach(self, pc, t):
        if t < 0.1:                                   # at rest until t = 0.1
            return list(self.reach)
        return [10.5 - 11.0 * (self.reach[0] - 10.5), self.reach[1]]


def march(mf, t_end=1.0, dt=1e-4):
    """The front's events as TS meets them: a crossing of an indicator between two states
    fires the event there (upwards for the even, downwards for the odd indicators)."""
    before = mf.event_values(0.0, None)
    for t in np.arange(dt, t_end + dt / 2, dt):
        mf.add_residual(t, None, None, None)
        now = mf.event_values(t, None)
        up = (before[0::2] < 0.0) & (now[0::2] >= 0.0)
        down = (before[1::2] > 0.0) & (now[1::2] <= 0.0)
        which = [2 * i for i in np.flatnonzero(up)] + [2 * i + 1 for i in np.flatnonzero(down)]
        if which:
            mf.event(t, None, which)
            now = mf.event_values(t, None)
        before = now


def test_a_front_that_overshoots_settles_where_its_target_is_its_own():
    """Moved to its targets such a front swings about b* ever wider (each ramp overshoots
    it eleven times as far); when the target turns back past the front within a ramp, the
    front goes to the secant root of T(b) - b through its last two events, here b* exactly
    (T linear), and stays there."""
    load = SteepLoad([10.0, 20.0])
    mf = MovingFront(load, lambda t, u: None, tol=0.1)
    march(mf)
    assert mf.reach_at(1.0)[0] == pytest.approx(10.5, abs=1e-9)
    # up towards 16, once more as the target falls back by tol, then the turn: 3 moves
    # (moved to its targets instead, the front swings ever wider: blow-by at t = 0.13)
    assert mf.moves[0] == 3 and mf.moves[1] == 0
    assert not mf.flips.any()


def test_the_history_restores_the_ramps():
    load, mf = front()
    load.target = [11.0, 20.0]
    mf.event(1.0, None, [0])
    saved = mf.history()
    load2, mf2 = front()
    mf2.restore(saved)
    assert mf2.reach_at(1.5) == pytest.approx(mf.reach_at(1.5))
    assert list(mf2.moves) == [1, 0]


def test_a_stop_just_after_an_event_is_stepped_past():
    """The step that crosses the event ends at a stop (t = 0.695): PETSc's post-event steps
    follow the trajectory planned before the event, which the stop ended, and left a step
    of zero to go on with (every later step failed: U' = dU / 0)."""
    term = Relax()
    p = Problem(1, [term])
    y = p.transient(np.zeros(1), 0.0, 3.0, 1e-2, stops=[0.695], rtol=1e-8, atol=1e-10)
    (t_e, _, _), = term.fired
    assert t_e == pytest.approx(np.log(2.0), abs=1e-5)
    assert y[0] == pytest.approx(3.0 - 2.5 * np.exp(-(3.0 - np.log(2.0))), rel=1e-5)
