"""Steps 1-2's front settling (sealts.solid.pressure.settle): front update and solve in turn.

What is asserted, on a load whose target reach is a given function of its reach (closed
forms, no seal):

* where the target moves continuously with the front (contracting, one way or
  alternating), the fronts move to their targets, update by update, as the plain fixed-point
  iteration does, and stop within tol of the fixed point;
* where each of two positions points at the other (the target jumps across the front, or
  its slope is -1: the plain iteration flips between them for ever, as on micrometre
  edges), the front is bisected onto the jump or the fixed point and settles there within
  tol, well within the updates allowed;
* so is a front that visits three positions in turn (met on the refined mesh of
  ``mesh.h_edge``, carried from the scene's own mesh: 97.73 -> 101.32 -> 98.92 -> 97.73
  edges), which no test of "the target is where it came from" catches;
* a settling that keeps its last equilibrium (``settle_front(keep=True)``) stops there
  when a solve fails, with the front that equilibrium was solved with.
"""
import pytest

from sealts.solid.pressure import settle


class Load:
    """Two fronts; front 0's target is f(reach 0), front 1 stays."""

    def __init__(self, f, x0):
        self.f, self.reach = f, [x0, 5.0]

    def target_reach(self, contact, t):
        return [self.f(self.reach[0]), self.reach[1]]

    def set_reach(self, reach):
        self.reach = list(reach)

    def check_blow_by(self, t):
        pass


def run(f, x0, tol=1e-4):
    load, path = Load(f, x0), []
    moved, k = settle(load, 0.0, lambda: None, lambda: path.append(load.reach[0]), tol)
    return load.reach[0], moved, k, path


def plain(f, x0, tol=1e-4, n=30):
    path, x = [], x0
    for _ in range(n):
        y = f(x)
        if abs(y - x) < tol:
            break
        x = y
        path.append(x)
    return path


@pytest.mark.parametrize("f", [lambda x: 0.5 * x + 1.0,                  # one way
                               lambda x: -0.5 * (x - 2.0) + 2.0])        # alternating
def test_a_continuous_target_is_followed_as_by_the_plain_iteration(f):
    x, moved, k, path = run(f, 0.0)
    assert path == plain(f, 0.0)
    assert abs(x - 2.0) < 2e-4 and moved < 1e-4 and k == len(path)


@pytest.mark.parametrize("f, x_star", [
    (lambda x: x + 1.0 if x < 1.2345 else x - 1.0, 1.2345),   # a jump across the front
    (lambda x: 3.4 - x, 1.7)])                               # slope -1: a two-cycle
def test_a_front_flipping_between_two_positions_settles_between_them(f, x_star):
    assert len(plain(f, 0.7)) == 30                # the plain iteration never settles
    x, moved, k, path = run(f, 0.7)
    assert abs(x - x_star) < 1e-4
    assert moved < 1e-4 and k < 29


def test_a_front_cycling_through_three_positions_settles_where_its_target_turns():
    def f(x):                         # 0 -> 2 -> 1 -> 0: up 2, down 1, down 1
        return x + 2.0 if x < 0.5 else x - 1.0
    assert plain(f, 0.0)[:6] == [2.0, 1.0, 0.0, 2.0, 1.0, 0.0]
    assert len(plain(f, 0.0)) == 30                # the plain iteration never settles
    x, moved, k, path = run(f, 0.0)
    assert path[:2] == [2.0, 1.0]                  # followed while its way shrank
    assert abs(x - 0.5) < 1e-4 and moved < 1e-4 and k < 29


def test_a_settling_that_keeps_stops_at_its_last_equilibrium(monkeypatch):
    """settle_front(keep=True) (steps 1-2 carried to a refined mesh): where a static solve
    fails on a move, the settling stops, and the last equilibrium stands with the front it
    was solved with; the move it could not make is what the front would still move."""
    import numpy as np

    import sealts.steps.quasi_static as qs
    from sealts.core import SolveError
    load = Load(lambda x: 0.5 * x + 1.0, 0.0)            # targets 1, 1.5, 1.75, ...
    solved = []

    def static(model, extra, u, t, counters, **newton):
        if load.reach[0] > 1.6:
            raise SolveError("3 element(s) of the seal invert")
        solved.append(load.reach[0])
        return u + 1.0

    class Model:
        def node_contact_pressure(self, t, u):
            return None

    monkeypatch.setattr(qs, "static", static)
    out, moved, k = qs.settle_front(Model(), load, qs.Equilibrium(np.zeros(2), None), 0.0,
                                    1.0, keep=True)
    assert out.stopped and solved == [1.0, 1.5]
    assert load.reach == [1.5, 5.0] and np.array_equal(out.u, [2.0, 2.0])
    assert moved == pytest.approx(0.25) and k == 2        # the third update failed


class Coupled:
    """Two fronts: front 1 moves down by one edge per update to 0 and stays; front 0's
    target cycles through three positions around a jump at 0.5 + 0.3 x1, which moves with
    front 1 (its state)."""

    def __init__(self):
        self.reach = [0.0, 5.0]

    def target_reach(self, contact, t):
        x0, x1 = self.reach
        s = 0.3 * x1
        return [x0 + 2.0 if x0 < 0.5 + s else x0 - 1.0, max(x1 - 1.0, 0.0)]

    def set_reach(self, reach):
        self.reach = list(reach)

    def check_blow_by(self, t):
        pass


def test_a_cycling_front_is_bisected_only_where_the_other_fronts_stand():
    """A bracket of front 0 taken while front 1 still moves would hold it round the jump
    where it was then (0.5 + 0.3 x1), not where it ends (0.5)."""
    load = Coupled()
    moved, k = settle(load, 0.0, lambda: None, lambda: None)
    assert load.reach[1] == 0.0
    assert abs(load.reach[0] - 0.5) < 1e-4 and moved < 1e-4 and k < 29
