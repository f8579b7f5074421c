"""Problem: owns the unknown vector, the COO Jacobian, and the PETSc TS / SNES.

The discrete system is one DAE

    F(t, U, U') = sum_terms F_term(t, U, U') = 0,
    J = dF/dU + shift dF/dU'   (PETSc's IJacobian),

and a steady scene solves F(t, U, 0) = 0 with SNES. Each physics term supplies

* ``rows, cols``: its Jacobian's COO pattern in global unknown numbers, fixed for the run;
* ``add_residual(t, u, udot, f)``: adds its part of F to the full-length array f;
* ``jacobian_values(t, u, udot, shift)``: the values for its pattern (duplicates add up).

The Problem concatenates the patterns once (``setPreallocationCOO``) and, per Newton step,
concatenates the values (``setValuesCOO``). Terms never see PETSc objects, so adding a term
touches no other. Dirichlet constraints (``Constraints``: dofs and their values at time t)
replace whole rows after the terms are summed, u_i - g_i(t) = 0, so terms need not know
about them. ``setFromOptions()`` is called last, so the command line wins over the
defaults set here and over a scene's ``[petsc]`` table.

Parallel runs: PETSc distributes rows of U, F and J by contiguous blocks. Every rank gathers
the full U (the film-only problems are one-dimensional and small), evaluates all terms, and
keeps the rows it owns; each rank passes only its own COO entries. The distributed linear
solve is PETSc's (the default parallel preconditioner is ``redundant`` LU).
"""
from dataclasses import dataclass

import numpy as np
from petsc4py import PETSc


class SolveError(RuntimeError):
    """A solve that PETSc could not complete (diverged SNES, TS that could not step)."""


class Term:
    """Interface of a physics term (see module docstring)."""

    rows: np.ndarray
    cols: np.ndarray

    def add_residual(self, t, u, udot, f):
        raise NotImplementedError

    def jacobian_values(self, t, u, udot, shift):
        raise NotImplementedError


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
    steps: int = 0
    rejected: int = 0
    newton: int = 0
    linear: int = 0
    residuals: int = 0
    jacobians: int = 0


class Problem:
    """A DAE assembled from terms, solved with PETSc TS (transient) or SNES (steady)."""

    def __init__(self, n, terms, comm=None, prefix=None, constraints=None, linesearch="bt",
                 snes_atol=None, fields=None):
        """``linesearch`` is the default SNES line search (the command line overrides it):
        ``bt`` for the film; ``basic`` for near-incompressible solids, where the residual
        norm is a poor merit function. Measured on a bent block with K/G ~ 940: basic 6
        Newton iterations, cp 12, l2 20, bt stalls at 50 (docs/design.md).

        ``snes_atol`` (units of the residual, e.g. N) makes Newton convergence absolute: the
        relative test max(atol, rtol |F0|) accepts nonsense when a poor predictor makes |F0|
        huge, which happened in quasi-static mounting (rod force 1e4 N accepted for 450 N).
        Without it the defaults are rtol 1e-10, atol 1e-12.

        ``fields`` (name -> global dofs), with a ``prony`` field of internal variables: the
        default linear solver becomes the exact Schur complement over the displacements
        (``_default_linear_solver``); any ``-pc_type fieldsplit`` gets these splits."""
        self.linesearch = linesearch
        self.max_it = 50  # of a steady SNES solve
        self.snes_tol = (dict(rtol=1e-10, atol=1e-12) if snes_atol is None
                         else dict(rtol=1e-14, atol=snes_atol, stol=1e-14))
        self.comm = comm or PETSc.COMM_WORLD
        self.n = int(n)
        self.terms = list(terms)
        self.constraints = constraints
        self.prefix = prefix
        self.fields = dict(fields or {})
        self.counters = Counters()

        self.U = PETSc.Vec().createMPI((PETSc.DECIDE, self.n), comm=self.comm)
        self.rstart, self.rend = self.U.getOwnershipRange()
        self._scatter, self._useq = PETSc.Scatter.toAll(self.U)
        self._udseq = self._useq.duplicate()

        rows = np.concatenate([np.asarray(t.rows, PETSc.IntType) for t in self.terms])
        cols = np.concatenate([np.asarray(t.cols, PETSc.IntType) for t in self.terms])
        if constraints is not None:
            self._fixed_entries = np.isin(rows, constraints.dofs)
            fixed = constraints.dofs.astype(PETSc.IntType)
            rows = np.concatenate([rows, fixed])
            cols = np.concatenate([cols, fixed])
        self._rows, self._cols = rows, cols
        self._mine = (rows >= self.rstart) & (rows < self.rend)
        self.J = PETSc.Mat().create(comm=self.comm)
        self.J.setSizes(((self.rend - self.rstart, self.n), (self.rend - self.rstart, self.n)))
        self.J.setType(PETSc.Mat.Type.AIJ)
        self.J.setPreallocationCOO(rows[self._mine], cols[self._mine])

    # ---- evaluation on full-length numpy arrays --------------------------------------------
    def gather(self, V, seq=None):
        """Full copy of a distributed vector on every rank (a numpy view, do not keep)."""
        seq = self._useq if seq is None else seq
        self._scatter.scatter(V, seq, addv=PETSc.InsertMode.INSERT_VALUES,
                              mode=PETSc.ScatterMode.FORWARD)
        return seq.getArray(readonly=True)

    def residual(self, t, u, udot):
        f = np.zeros(self.n)
        for term in self.terms:
            term.add_residual(t, u, udot, f)
        c = self.constraints
        if c is not None:
            f[c.dofs] = u[c.dofs] - c.values(t)
        return f

    def jacobian_values(self, t, u, udot, shift):
        vals = np.concatenate([np.asarray(term.jacobian_values(t, u, udot, shift), float)
                               for term in self.terms])
        if self.constraints is not None:
            vals[self._fixed_entries] = 0.0
            vals = np.concatenate([vals, np.ones(self.constraints.dofs.size)])
        return vals

    def jacobian_dense(self, t, u, udot, shift):
        """Assembled Jacobian as a dense array (serial tests and diagnostics only)."""
        a = np.zeros((self.n, self.n))
        np.add.at(a, (self._rows, self._cols), self.jacobian_values(t, u, udot, shift))
        return a

    # ---- PETSc callbacks -------------------------------------------------------------------
    def _set_owned(self, F, f):
        F.setArray(f[self.rstart:self.rend])

    def ifunction(self, ts, t, U, Udot, F):
        u = self.gather(U).copy()
        ud = self.gather(Udot, self._udseq)
        self._set_owned(F, self.residual(t, u, ud))
        self.counters.residuals += 1

    def ijacobian(self, ts, t, U, Udot, shift, J, P):
        u = self.gather(U).copy()
        ud = self.gather(Udot, self._udseq)
        vals = self.jacobian_values(t, u, ud, shift)[self._mine]
        P.setValuesCOO(vals, addv=PETSc.InsertMode.INSERT_VALUES)
        if J != P:
            J.assemble()
        self.counters.jacobians += 1

    def snes_function(self, snes, U, F):
        u = self.gather(U)
        self._set_owned(F, self.residual(self.t_steady, u, np.zeros(self.n)))
        self.counters.residuals += 1

    def snes_jacobian(self, snes, U, J, P):
        u = self.gather(U)
        vals = self.jacobian_values(self.t_steady, u, np.zeros(self.n), 0.0)[self._mine]
        P.setValuesCOO(vals, addv=PETSc.InsertMode.INSERT_VALUES)
        if J != P:
            J.assemble()
        self.counters.jacobians += 1

    # ---- solver set-up ---------------------------------------------------------------------
    def _default_linear_solver(self, ksp):
        if "prony" in self.fields:
            self._default_schur(ksp)
            return
        ksp.setType(PETSc.KSP.Type.PREONLY)
        pc = ksp.getPC()
        if self.comm.getSize() == 1:
            pc.setType(PETSc.PC.Type.LU)
            pc.setFactorSolverType("umfpack")  # 2x PETSc's LU at 80k unknowns, docs/petsc-build.md
        else:
            pc.setType(PETSc.PC.Type.REDUNDANT)

    def _default_schur(self, ksp):
        """Prony internal variables first, displacements second: their own block A00 is
        diagonal, so selfp's A11 - A10 diag(A00)^-1 A01 is the exact Schur complement, LU
        factors it, and the outer Krylov method converges in one iteration."""
        ksp.setType(PETSc.KSP.Type.FGMRES)
        pc = ksp.getPC()
        pc.setType(PETSc.PC.Type.FIELDSPLIT)
        pc.setFieldSplitType(PETSc.PC.CompositeType.SCHUR)
        pc.setFieldSplitSchurFactType(PETSc.PC.FieldSplitSchurFactType.FULL)
        pc.setFieldSplitSchurPreType(PETSc.PC.FieldSplitSchurPreType.SELFP)
        # the split solvers exist only at set-up, so their defaults stay in the options
        # database (scoped by this problem's prefix)
        serial = self.comm.getSize() == 1
        defaults = [("fieldsplit_prony_ksp_type", "preonly"),
                    ("fieldsplit_prony_pc_type", "jacobi"),
                    ("fieldsplit_displacement_ksp_type", "preonly"),
                    ("fieldsplit_displacement_pc_type", "lu" if serial else "redundant")]
        if serial:
            defaults.append(("fieldsplit_displacement_pc_factor_mat_solver_type", "umfpack"))
        for name, value in defaults:
            self._default_option(name, value, keep=True)

    def _set_splits(self, ksp):
        """Hand the fields to a fieldsplit preconditioner (the rank's own dofs of each)."""
        pc = ksp.getPC()
        if not self.fields or pc.getType() != PETSc.PC.Type.FIELDSPLIT:
            return
        order = sorted(self.fields, key=lambda k: k != "prony")
        splits = []
        for name in order:
            d = np.asarray(self.fields[name], PETSc.IntType)
            d = d[(d >= self.rstart) & (d < self.rend)]
            splits.append((name, PETSc.IS().createGeneral(d, comm=self.comm)))
        pc.setFieldSplitIS(*splits)

    def _default_option(self, name, value, keep=False):
        """Set an option only where the command line and the scene left it unset; it is
        removed again after the next setFromOptions (``_drop_defaults``), so it does not
        leak into the next solver of the same process."""
        opts = PETSc.Options(self.prefix)
        if not opts.hasName(name):
            opts[name] = value
            if not keep:
                self._set_defaults = getattr(self, "_set_defaults", []) + [name]

    def _drop_defaults(self):
        opts = PETSc.Options(self.prefix)
        for name in getattr(self, "_set_defaults", []):
            opts.delValue(name)
        self._set_defaults = []

    def make_snes(self):
        snes = PETSc.SNES().create(comm=self.comm)
        if self.prefix:
            snes.setOptionsPrefix(self.prefix)
        snes.setFunction(self.snes_function, self.U.duplicate())
        snes.setJacobian(self.snes_jacobian, self.J)
        snes.setType(PETSc.SNES.Type.NEWTONLS)
        snes.getLineSearch().setType(self.linesearch)
        snes.setTolerances(max_it=self.max_it, **self.snes_tol)
        self._default_linear_solver(snes.getKSP())
        snes.setFromOptions()
        self._set_splits(snes.getKSP())
        return snes

    def make_ts(self, t0, t_end, dt0, monitor=None, rtol=1e-6, atol=1e-8):
        ts = PETSc.TS().create(comm=self.comm)
        if self.prefix:
            ts.setOptionsPrefix(self.prefix)
        ts.setProblemType(PETSc.TS.ProblemType.NONLINEAR)
        ts.setEquationType(PETSc.TS.EquationType.DAE_IMPLICIT_INDEX1)
        ts.setType(PETSc.TS.Type.BDF)
        ts.setIFunction(self.ifunction, self.U.duplicate())
        ts.setIJacobian(self.ijacobian, self.J)
        ts.setTime(t0)
        ts.setTimeStep(dt0)
        ts.setMaxTime(t_end)
        ts.setMaxSteps(10_000_000)
        ts.setExactFinalTime(PETSc.TS.ExactFinalTime.MATCHSTEP)
        ts.setMaxSNESFailures(-1)  # a failed Newton solve rejects the step; TSAdapt retries
        ts.setErrorIfStepFails(False)  # report a TS that gives up through its reason
        ts.setTolerances(rtol=rtol, atol=atol)
        self._default_option("ts_adapt_type", "basic")  # petsc4py has no TSAdapt binding
        # a run whose steps shrink below 1e-12 of its span fails instead of crawling on
        self._default_option("ts_adapt_dt_min", repr(1e-12 * max(float(t_end - t0), 1e-300)))
        snes = ts.getSNES()
        snes.setType(PETSc.SNES.Type.NEWTONLS)
        snes.getLineSearch().setType(self.linesearch)
        snes.setTolerances(max_it=25, **self.snes_tol)
        self._default_linear_solver(snes.getKSP())
        if monitor is not None:
            ts.setMonitor(monitor)
        ts.setFromOptions()
        self._drop_defaults()
        self._set_splits(ts.getSNES().getKSP())
        return ts

    # ---- solves ----------------------------------------------------------------------------
    def _owned(self, u0):
        X = self.U.duplicate()
        X.setArray(np.asarray(u0, float)[self.rstart:self.rend])
        return X

    def solve_steady(self, u0, t=0.0):
        """Solve F(t, U, 0) = 0 from the initial guess u0; return the full solution."""
        self.t_steady = t
        snes = self.make_snes()
        X = self._owned(u0)
        snes.solve(None, X)
        reason = snes.getConvergedReason()
        self.counters.newton += snes.getIterationNumber()
        self.counters.linear += snes.getLinearSolveIterations()
        if reason <= 0:
            name = _reason(PETSc.SNES, reason)
            hint = ("-ksp_monitor_true_residual and another -pc_type"
                    if name == "DIVERGED_LINEAR_SOLVE"
                    else "-snes_monitor and another -snes_linesearch_type")
            raise SolveError(f"steady Newton solve diverged ({name}); try {hint}")
        u = self.gather(X).copy()
        snes.destroy()
        return u

    def transient(self, u0, t0, t_end, dt0, stops=(), on_step=None, on_stop=None,
                  rtol=1e-6, atol=1e-8):
        """Integrate from t0 to t_end with adaptive steps.

        ``on_step(ts, step, t, u)`` runs after every accepted step (and at t0);
        ``on_stop(t, u)`` at each time in ``stops`` (hit exactly) and at t_end.
        """
        last = [None]

        def monitor(ts, step, t, X):
            # TS calls its monitor at the start of every solve(): report each state once
            if on_step is not None and t != last[0]:
                last[0] = t
                on_step(ts, step, t, self.gather(X).copy())

        ts = self.make_ts(t0, t_end, dt0, monitor=monitor, rtol=rtol, atol=atol)
        X = self._owned(u0)
        targets = sorted({float(s) for s in stops if t0 < s < t_end} | {float(t_end)})
        for target in targets:
            ts.setMaxTime(target)
            try:
                ts.solve(X)
            except PETSc.Error as e:
                raise SolveError(f"time stepping failed at t = {ts.getTime():.6g} s "
                                 f"(PETSc error {e.ierr}); see the PETSc message above") from None
            reason = ts.getConvergedReason()
            if reason < 0:
                raise SolveError(f"time stepping failed at t = {ts.getTime():.6g} s "
                                 f"({_reason(PETSc.TS, reason)}); try a smaller -ts_dt or "
                                 "-ts_adapt_dt_min")
            if on_stop is not None:
                on_stop(ts.getTime(), self.gather(X).copy())
        c = self.counters
        c.steps += ts.getStepNumber()
        c.rejected += ts.getStepRejections()
        c.newton += ts.getSNESIterations()
        c.linear += ts.getKSPIterations()
        u = self.gather(X).copy()
        ts.destroy()
        return u


def _reason(cls, code):
    names = {v: k for k, v in vars(cls.ConvergedReason).items() if isinstance(v, int)}
    return names.get(code, str(code))
