"""A time step at TSAdapt's minimum is not an answer: PETSc's basic controller accepts such a
step whatever its error, so Problem.transient stops there and names the unknown that moved
most against its tolerance (a problem opts in: the stroke does). A closed form that blows up in finite time shows it: u' = u^2,
u(0) = 1, u = 1 / (1 - t), infinite at t = 1."""
import numpy as np
import pytest

from sealts.core import Recorder, SolveError, Term
from sealts.problem import Problem


class BlowUp(Term):
    """F = u' - u^2 on every unknown (independent copies)."""

    def __init__(self, n):
        self.rows = self.cols = np.arange(n)

    def add_residual(self, t, u, udot, f):
        f += udot - u * u

    def jacobian_values(self, t, u, udot, shift):
        return shift - 2.0 * u


def test_the_closed_form_is_followed_up_to_the_blow_up():
    p = Problem(2, [BlowUp(2)])
    rec = Recorder()
    u = p.transient(np.ones(2), 0.0, 0.9, 1e-4, observers=[rec], rtol=1e-7, atol=1e-9)
    assert u == pytest.approx(1.0 / (1.0 - 0.9), rel=1e-3)


def test_a_step_at_the_minimum_stops_the_run_and_names_the_unknown():
    p = Problem(2, [BlowUp(2)])
    p.stop_at_min_step = True              # as the stroke sets it
    u0 = np.array([1.0, 0.5])              # the first unknown blows up first (t = 1)
    with pytest.raises(SolveError) as e:
        p.transient(u0, 0.0, 2.0, 1e-4, rtol=1e-6, atol=1e-9)
    msg = str(e.value)
    assert "time step at its minimum (2e-12 s)" in msg
    assert "the fastest change: unknown 0" in msg
    t = float(msg.split("at t = ")[1].split(" s")[0])
    assert 0.999 < t <= 1.0


class FastOscillator(Term):
    """F = (x' - w y, y' + w x): circles of angular frequency w."""

    def __init__(self, w):
        self.w = w
        self.rows = np.array([0, 0, 1, 1])
        self.cols = np.array([0, 1, 0, 1])

    def add_residual(self, t, u, udot, f):
        f[0] += udot[0] - self.w * u[1]
        f[1] += udot[1] + self.w * u[0]

    def jacobian_values(self, t, u, udot, shift):
        return np.array([shift, -self.w, self.w, shift])


def test_a_crawl_stops_the_run_and_says_at_what_pace():
    """u = (cos wt, -sin wt) with w = 1e5 over 1 s: 16,000 periods, each needing tens of
    BDF steps at rtol 1e-6, millions in all. The steps neither shrink to the minimum nor
    finish: after PACE_WINDOW steps the run stops, saying how far they got and what the
    rest would take. With a window's pace that would finish in time it runs on (w = 1e2)."""
    from sealts.problem.problem import PACE_LIMIT, PACE_WINDOW
    p = Problem(2, [FastOscillator(1e5)])
    p.stop_at_min_step = True
    with pytest.raises(SolveError) as e:
        p.transient(np.array([1.0, 0.0]), 0.0, 1.0, 1e-7, rtol=1e-6, atol=1e-9)
    msg = str(e.value)
    assert f"the time steps crawl: the last {PACE_WINDOW} advanced t by" in msg
    need = float(msg.split("would take ")[1].split(" more steps")[0])
    assert need > PACE_LIMIT
    assert "the fastest change: unknown" in msg
    # and names the oscillation that keeps the steps small: its period is 2 pi / w
    assert "; it oscillates: unknown " in msg and "swings between -1 and 1" in msg
    period = float(msg.split("with a period of ")[1].split(" s")[0])
    assert period == pytest.approx(2 * np.pi / 1e5, rel=1e-2)
    q = Problem(2, [FastOscillator(1e2)])
    q.stop_at_min_step = True
    u = q.transient(np.array([1.0, 0.0]), 0.0, 1.0, 1e-4, rtol=1e-6, atol=1e-9)
    # 16 periods, BDF's phase error accumulating: on the circle, near its point
    assert np.hypot(*u) == pytest.approx(1.0, abs=1e-2)
    assert u == pytest.approx([np.cos(100.0), -np.sin(100.0)], abs=1e-2)


class Defective(BlowUp):
    """BlowUp whose residual (or Jacobian) raises a Python error of its own from t = 0.5 on:
    a defect in a term, not a physical stop."""

    def __init__(self, n, where):
        super().__init__(n)
        self.where = where

    def add_residual(self, t, u, udot, f):
        if self.where == "residual" and t > 0.5:
            raise ValueError("a defect in the term")
        super().add_residual(t, u, udot, f)

    def jacobian_values(self, t, u, udot, shift):
        if self.where == "Jacobian" and t > 0.5:
            raise ZeroDivisionError("division by zero")
        return super().jacobian_values(t, u, udot, shift)


@pytest.mark.parametrize("where", ["residual", "Jacobian"])
def test_a_terms_own_exception_is_named_in_one_line(where):
    """Not PETSc's bare "error 101": the callback, t and the exception (both solvers)."""
    p = Problem(1, [Defective(1, where)])
    with pytest.raises(SolveError) as e:
        p.transient(np.ones(1), 0.0, 0.9, 1e-4, rtol=1e-6, atol=1e-9)
    msg = str(e.value)
    assert msg.startswith(f"the {where} at t = 0.5") and "\n" not in msg
    assert ("ValueError: a defect in the term" if where == "residual"
            else "ZeroDivisionError: division by zero") in msg
    p.t_steady = 0.75
    with pytest.raises(SolveError) as e:
        p.solve_steady(np.ones(1), t=0.75)
    assert str(e.value).startswith(f"the {where} at t = 0.75 s raised")


class Breaks(Term):
    """F = u' + u, whose residual turns non-finite in unknown 1 from t = 0.5 on, whatever u:
    every retry of the step past it fails (a stand-in for an element that inverts)."""

    def __init__(self, n):
        self.rows = self.cols = np.arange(n)

    def add_residual(self, t, u, udot, f):
        f += udot + u
        if t >= 0.5:
            f[1] = np.nan

    def jacobian_values(self, t, u, udot, shift):
        return np.full(self.rows.size, shift + 1.0)


def test_a_run_that_gives_up_on_non_finite_residuals_names_the_term_and_where():
    p = Problem(2, [Breaks(2)])
    with pytest.raises(SolveError) as e:
        p.transient(np.ones(2), 0.0, 1.0, 1e-2, rtol=1e-6, atol=1e-9)
    msg = str(e.value)
    assert "DIVERGED_STEP_REJECTED" in msg
    assert "Breaks: not finite at the unknown 1" in msg, msg
    t = float(msg.split("at t = ")[1].split(" s")[0])
    assert 0.49 < t <= 0.5
