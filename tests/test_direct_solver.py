"""The default direct solver: PETSc's LU (no pivoting) on small problems, which gives way
to UMFPACK (partial pivoting) when a factorisation meets a zero pivot.

The systems here have zero diagonals, so an LU without pivoting meets a zero pivot in either
ordering, while their exact solutions are known: x = b of a permutation, and the closed form
of a small DAE."""
import numpy as np
import pytest
from petsc4py import PETSc

from sealts.core import SolveError, Term
from sealts.problem import Problem
from sealts.problem import problem as problem_module


class Swapped(Term):
    """F = (u1 - a(t), u0 - b(t), u2' - u0): the first two rows have zero diagonals
    (entered in the pattern, value 0); u2 integrates u0. ``steady``: u2 - u0 instead."""

    rows = np.array([0, 0, 1, 1, 2, 2])
    cols = np.array([0, 1, 0, 1, 2, 0])

    def __init__(self, a, b, steady=False):
        self.a, self.b, self.steady = a, b, steady

    def add_residual(self, t, u, udot, f):
        f[0] += u[1] - self.a(t)
        f[1] += u[0] - self.b(t)
        f[2] += (u[2] if self.steady else udot[2]) - u[0]

    def jacobian_values(self, t, u, udot, shift):
        return np.array([0.0, 1.0, 1.0, 0.0, 1.0 if self.steady else shift, -1.0])


def test_steady_solve_falls_back_to_umfpack_on_a_zero_pivot():
    pb = Problem(3, [Swapped(lambda t: 2.0, lambda t: -3.0, steady=True)], snes_atol=1e-12)
    u = pb.solve_steady(np.zeros(3))
    assert u == pytest.approx([-3.0, 2.0, -3.0], abs=1e-12)
    assert pb.lu_fallback is not None
    assert problem_module.SOLVERS[""]["pc_factor_mat_solver_type"].startswith("umfpack")


def test_transient_retries_the_step_with_umfpack():
    """u0 = cos t, u1 = sin t, u2 = sin t (u2' = u0, u2(0) = 0): the run switches at its first
    factorisation, retries that step, and integrates to the TS tolerance."""
    pb = Problem(3, [Swapped(np.sin, np.cos)])
    u = pb.transient(np.array([1.0, 0.0, 0.0]), 0.0, 1.0, 1e-3, rtol=1e-8, atol=1e-10)
    assert pb.lu_fallback == 0.0
    assert pb.counters.newton_failures == 1      # the step that met the zero pivot, once
    assert u[:2] == pytest.approx([np.cos(1.0), np.sin(1.0)], abs=1e-12)
    assert u[2] == pytest.approx(np.sin(1.0), abs=1e-5)


def test_a_step_that_keeps_failing_goes_on_with_umfpack():
    """PETSc's LU can fail a step without a zero pivot (small pivots of thin films at high
    pressure; the shipped mesh at 20 MPa). Here u' = 1 whose residual is non-finite past
    t = 0.05 while PETSc's LU is in force: TS retries the step smaller, and after
    LU_FAILURES failed Newton solves in a row the step goes on with UMFPACK and the run
    ends at u(1) = 1. (Failures spread over steps, one each, do not switch: the default
    cycle's, tests/test_cycle_regression.py.)"""
    class Stubborn(Term):
        rows = cols = np.array([0])

        def add_residual(self, t, u, udot, f):
            f[0] += udot[0] - 1.0
            if t > 0.05 and pb.lu_fallback is None:
                f[0] = np.nan

        def jacobian_values(self, t, u, udot, shift):
            return np.array([shift])

    pb = Problem(1, [Stubborn()])
    u = pb.transient(np.zeros(1), 0.0, 1.0, 0.02, rtol=1e-6, atol=1e-8)
    assert u[0] == pytest.approx(1.0, abs=1e-10)
    assert 0.0 < pb.lu_fallback <= 0.05
    # the step whose stage first crossed 0.05 may fail once and land short of it; the step
    # from there fails LU_FAILURES times, then switches
    assert problem_module.LU_FAILURES <= pb.counters.newton_failures <= \
        problem_module.LU_FAILURES + 1
    assert "failed Newton solves in a row" in \
        problem_module.SOLVERS[""]["pc_factor_mat_solver_type"]


def test_a_chosen_solver_is_kept():
    """-pc_factor_mat_solver_type petsc chosen on the command line: no fallback, the solve
    fails on the zero pivot with the linear solver named."""
    opts = PETSc.Options("chosen_")
    opts["pc_factor_mat_solver_type"] = "petsc"
    try:
        pb = Problem(3, [Swapped(lambda t: 2.0, lambda t: -3.0, steady=True)], prefix="chosen_",
                     snes_atol=1e-12)
        with pytest.raises(SolveError, match="DIVERGED_LINEAR_SOLVE"):
            pb.solve_steady(np.zeros(3))
        assert pb.lu_fallback is None
    finally:
        opts.delValue("pc_factor_mat_solver_type")


@pytest.mark.parametrize("n, solver", [(3, "petsc"), (problem_module.PETSC_LU_BELOW, "umfpack")])
def test_default_solver_by_size(n, solver):
    class Diagonal(Term):
        rows = cols = np.arange(n)

        def add_residual(self, t, u, udot, f):
            f += u - 1.0

        def jacobian_values(self, t, u, udot, shift):
            return np.ones(n)

    pb = Problem(n, [Diagonal()], snes_atol=1e-12)
    assert pb.solve_steady(np.zeros(n)) == pytest.approx(np.ones(n))
    assert problem_module.SOLVERS[""]["pc_factor_mat_solver_type"] == solver
    assert pb.lu_fallback is None


@pytest.mark.parametrize("m, solver", [(problem_module.PETSC_LU_DENSITY - 2, "petsc"),
                                       (problem_module.PETSC_LU_DENSITY + 2, "umfpack")])
def test_a_dense_jacobian_is_umfpacks(m, solver):
    """Small but dense (m nonzeros per row, a band about the diagonal, diagonally dominant):
    below PETSC_LU_DENSITY per row PETSc's LU, above it UMFPACK; both solve it."""
    n = 200
    off = np.arange(m) - m // 2
    rows = np.repeat(np.arange(n), m)
    cols = (rows + np.tile(off, n)) % n

    class Band(Term):
        def __init__(self):
            self.rows, self.cols = rows, cols
            self.vals = np.where(rows == cols, 2.0 * m, 1.0)

        def add_residual(self, t, u, udot, f):
            np.add.at(f, rows, self.vals * u[cols])
            f -= 1.0

        def jacobian_values(self, t, u, udot, shift):
            return self.vals

    pb = Problem(n, [Band()], snes_atol=1e-12)
    u = pb.solve_steady(np.zeros(n))
    assert u == pytest.approx(np.full(n, 1.0 / (3.0 * m - 1.0)), rel=1e-10)
    assert problem_module.SOLVERS[""]["pc_factor_mat_solver_type"] == solver


def test_a_resumed_run_goes_on_with_umfpack():
    """A run stopped after its switch and resumed from the stop's snapshot goes on with
    UMFPACK (no second zero pivot, no second failed step) and ends where the uninterrupted
    run does, to the last bit."""
    from sealts.core import Observer

    class Stops(Observer):
        def __init__(self, problem):
            self.problem, self.at = problem, {}

        def stop(self, t, u):
            self.at[round(t, 12)] = (u.copy(), self.problem.snapshot())

    def problem():
        pb = Problem(3, [Swapped(np.sin, np.cos)])
        pb.restart_at_stops = True          # what a resumable run does at its stops
        return pb

    kw = dict(rtol=1e-8, atol=1e-10)
    first = problem()
    stops = Stops(first)
    u_full = first.transient(np.array([1.0, 0.0, 0.0]), 0.0, 1.0, 1e-3, stops=(0.5,),
                             observers=[stops], **kw)
    u_half, snap = stops.at[0.5]
    assert snap["lu_fallback"] == 0.0
    again = problem()
    u = again.transient(u_half, 0.5, 1.0, snap["dt"], stops=(0.5,), resume=snap, **kw)
    assert again.counters.newton_failures == first.counters.newton_failures == 1
    assert again.lu_fallback == 0.0
    assert problem_module.SOLVERS[""]["pc_factor_mat_solver_type"].startswith(
        "umfpack (from t = 0:")
    assert np.array_equal(u, u_full)


def _ordering(pc, tmp_path):
    """The matrix ordering a PC's factorisation uses, from its view."""
    path = str(tmp_path / "pc.txt")
    viewer = PETSc.Viewer().createASCII(path, comm=PETSc.COMM_SELF)
    pc.view(viewer)
    viewer.destroy()
    text = open(path).read()
    return text.split("matrix ordering:")[1].split()[0]


def test_umfpack_orders_the_matrix_itself(tmp_path):
    """PETSc's LU runs with AMD; UMFPACK, after the fallback or chosen on the command line,
    with its own ordering ('external'): given AMD as a fixed column order it factors the
    default stroke Jacobian 3.7 times slower."""
    pb = Problem(3, [Swapped(lambda t: 2.0, lambda t: -3.0, steady=True)], snes_atol=1e-12)
    pb.t_steady = 0.0
    snes = pb.make_snes()
    snes.solve(None, pb._owned(np.zeros(3)))      # fails on the zero pivot
    ksp = snes.getKSP()
    assert _ordering(ksp.getPC(), tmp_path) == "amd"
    assert pb._fall_back_to_umfpack(snes, 0.0)
    ksp.setOperators(pb.J, pb.J)
    ksp.setUp()
    assert _ordering(ksp.getPC(), tmp_path) == "external"
    snes.destroy()
    opts = PETSc.Options("chosen_")
    opts["pc_factor_mat_solver_type"] = "umfpack"
    try:
        pb = Problem(3, [Swapped(lambda t: 2.0, lambda t: -3.0, steady=True)],
                     prefix="chosen_", snes_atol=1e-12)
        pb.t_steady = 0.0
        snes = pb.make_snes()
        snes.solve(None, pb._owned(np.zeros(3)))
        assert snes.getConvergedReason() > 0
        assert _ordering(snes.getKSP().getPC(), tmp_path) == "external"
        snes.destroy()
    finally:
        opts.delValue("pc_factor_mat_solver_type")
