"""The stage's Newton convergence test (sealts.problem.newton_test): PETSc's residual tests
first, unchanged, then a correction below 1e-3 of TS's error tolerance of every unknown."""
import numpy as np
import pytest
from petsc4py import PETSc

from sealts.problem.newton_test import UpdateTest


class Tolerances:
    """What UpdateTest asks of a TS: its (rtol, atol)."""

    def __init__(self, rtol, atol):
        self.tol = (rtol, atol)

    def getTolerances(self):
        return self.tol


def solve(floor, test=None, n=3):
    """Newton on F(x) = x - 1 + floor (-1)^k (k the evaluation count): a residual whose
    round-off floor is ``floor``, exact Jacobian I; returns (reason, iterations, x)."""
    calls = [0]

    def residual(snes, x, f):
        calls[0] += 1
        f.setArray(x.getArray(readonly=True) - 1.0 + floor * (-1.0) ** calls[0])

    def jacobian(snes, x, J, P):
        pass                                  # the identity, assembled once

    J = PETSc.Mat().createAIJ([n, n], nnz=1, comm=PETSc.COMM_SELF)
    for i in range(n):
        J.setValue(i, i, 1.0)
    J.assemble()
    snes = PETSc.SNES().create(comm=PETSc.COMM_SELF)
    snes.setFunction(residual, PETSc.Vec().createSeq(n))
    snes.setJacobian(jacobian, J)
    snes.getLineSearch().setType("basic")
    snes.getKSP().setType("preonly")
    snes.getKSP().getPC().setType("lu")
    snes.setTolerances(rtol=1e-300, atol=1e-9, stol=0.0, max_it=20)
    if test is not None:
        snes.setConvergenceTest(test)
    x = PETSc.Vec().createSeq(n)
    x.set(3.0)
    snes.solve(None, x)
    return snes.getConvergedReason(), snes.getIterationNumber(), x.getArray().copy()


def test_a_residual_floor_above_atol_stalls_the_default_and_converges_by_the_update():
    R = PETSc.SNES.ConvergedReason
    reason, its, _ = solve(1e-7)
    assert reason == R.DIVERGED_MAX_IT                  # PETSc's test never gets there
    # tolerance w = 1e-6 + 1e-3 |x| ~ 1e-3; corrections 2e-7 after the first: 2e-4 w
    reason, its, x = solve(1e-7, UpdateTest(Tolerances(1e-3, 1e-6)))
    assert reason == R.CONVERGED_USER and its == 2
    assert np.abs(x - 1.0).max() < 1e-6
    # a tolerance ten times tighter than the floor's corrections: not converged
    reason, _, _ = solve(1e-7, UpdateTest(Tolerances(1e-5, 1e-9)))
    assert reason == R.DIVERGED_MAX_IT


def test_without_a_floor_the_default_reason_is_kept():
    R = PETSc.SNES.ConvergedReason
    assert solve(0.0)[:2] == solve(0.0, UpdateTest(Tolerances(1e-3, 1e-6)))[:2]
    assert solve(0.0)[0] == R.CONVERGED_FNORM_ABS


def test_per_unknown_tolerance_vectors():
    """The weights may be Vecs (the stroke's per-unknown tolerances): an unknown with a
    tight tolerance keeps the solve iterating."""
    R = PETSc.SNES.ConvergedReason
    at = PETSc.Vec().createSeq(3)
    at.setArray([1e-6, 1e-6, 1e-12])
    rt = PETSc.Vec().createSeq(3)
    rt.setArray([1e-3, 1e-3, 0.0])
    assert solve(1e-7, UpdateTest(Tolerances(rt, at)))[0] == R.DIVERGED_MAX_IT
    at.setArray([1e-6, 1e-6, 1e-3])
    assert solve(1e-7, UpdateTest(Tolerances(rt, at)))[0] == R.CONVERGED_USER
