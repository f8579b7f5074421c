"""When is a time step's Newton solve converged: in the units of each unknown, not of one
residual norm.

The residual of the stroke mixes forces (N), film rows (scaled to MPa), volume rates (mm^3/s)
and slip rates (mm/s); one absolute tolerance on its 2-norm cannot suit them all. At 20 MPa
the forces are ten times larger than at 1 MPa and so is the round-off floor of their sum:
the coarse O-ring's first stroke step stalled at |F| = 1.0e-5 N, alternating between two
values, against a tolerance of 8e-6 N, and TS retried it down to dt = 1e-12 s.

The stage's unknowns are what TS's error estimate measures, each against its own tolerance
w_i = atol_i + rtol_i |U_i| (``StrokeProblem.tolerances``). So a Newton iteration also
counts as converged when its correction dU is far below that error tolerance,

    max_i |dU_i| / w_i  <=  c                 (c = 1e-3),

reported as CONVERGED_USER: quadratic convergence leaves a remaining error far below the
last correction, so the stage's solution is exact to a thousandth of what the error
control allows. PETSc's default tests come first, unchanged (the residual's atol, rtol
relative to the first residual, stol; DIVERGED_FNORM_NAN and DIVERGED_DTOL), so every
solve that converged before converges at the same iterate.
"""
import numpy as np
from petsc4py import PETSc

R = PETSc.SNES.ConvergedReason


def _values(v):
    return v.getArray(readonly=True) if isinstance(v, PETSc.Vec) else float(v)


class UpdateTest:
    """SNES convergence test of a TS's stages (module docstring); ``ts`` supplies the error
    tolerances (scalars or per-unknown Vecs), ``c`` the fraction of them."""

    def __init__(self, ts, c=1e-3):
        self.ts, self.c, self.f0 = ts, float(c), None

    def __call__(self, snes, its, norms):
        xnorm, ynorm, fnorm = norms
        rtol, atol, stol, _ = snes.getTolerances()
        if its == 0:
            self.f0 = fnorm
        if not np.isfinite(fnorm):
            return R.DIVERGED_FNORM_NAN
        if fnorm < atol:
            return R.CONVERGED_FNORM_ABS
        if its == 0:
            return R.ITERATING
        if fnorm <= rtol * self.f0:
            return R.CONVERGED_FNORM_RELATIVE
        if ynorm < stol * xnorm:
            return R.CONVERGED_SNORM_RELATIVE
        divtol = snes.getDivergenceTolerance()
        if divtol > 0 and fnorm > divtol * self.f0:
            return R.DIVERGED_DTOL
        if self.weighted_update(snes) <= self.c:
            return R.CONVERGED_USER
        return R.ITERATING

    def weighted_update(self, snes):
        """max_i |dU_i| / (atol_i + rtol_i |U_i|) of the last Newton correction, over all
        ranks."""
        rt, at = self.ts.getTolerances()
        x = snes.getSolution().getArray(readonly=True)
        dx = snes.getSolutionUpdate().getArray(readonly=True)
        w = _values(at) + _values(rt) * np.abs(x)
        q = float(np.max(np.abs(dx) / w, initial=0.0))
        comm = snes.getComm().tompi4py()
        return comm.allreduce(q, op=_max()) if comm.Get_size() > 1 else q


def _max():
    from mpi4py import MPI
    return MPI.MAX
