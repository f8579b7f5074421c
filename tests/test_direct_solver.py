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
    assert pb.lu_fallback == (0.0, "a zero pivot of PETSc's LU")
    assert pb.counters.newton_failures == 1      # the step that met the zero pivot, once
    assert u[:2] == pytest.approx([np.cos(1.0), np.sin(1.0)], abs=1e-12)
    assert u[2] == pytest.approx(np.sin(1.0), abs=1e-5)


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
