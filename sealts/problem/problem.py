"""Problem: owns the unknown vector, the COO Jacobian, and the PETSc TS / SNES.

The discrete system is one DAE

    F(t, U, U') = sum_terms F_term(t, U, U') = 0,
    J = dF/dU + shift dF/dU'   (PETSc's IJacobian),

and a steady scene solves F(t, U, 0) = 0 with SNES. Each physics term supplies

* ``rows, cols``: its Jacobian's COO pattern in local dof numbers, fixed for the run;
* ``add_residual(t, u, udot, f)``: adds its part of F to the local array f;
* ``jacobian_values(t, u, udot, shift)``: the values for its pattern (duplicates add up).

The Problem concatenates the patterns once (``setPreallocationCOO``) and, per Newton step,
concatenates the values (``setValuesCOO``; where the Prony block's condensation solves
alone, :mod:`.condensed` reads the values themselves and no matrix is assembled, and the
Prony term gives its part of the condensed system in place of its Jacobian). Terms
never see PETSc objects, so adding a term touches no other. Dirichlet constraints
(``Constraints``: dofs and their values at time t) replace whole rows after the terms are
summed, u_i - g_i(t) = 0, so terms need not know about them. ``setFromOptions()`` is
called last, so the command line wins over the defaults set here and over a scene's
``[petsc]`` table.

Terms work on a rank's *local* arrays: ``add_residual`` gets the local u, udot and f, and
``rows, cols`` are local dof numbers. Two modes:

* distributed (``dofs``, a :class:`sealts.mesh.partition.Numbering`, as for the seal):
  each rank's terms cover its own cells (and, on rank 0, the boundary terms). U is
  scattered to the rank's local dofs (owned and ghost, an IS of ``ltog``); the local
  residual goes back by the reverse scatter with ADD_VALUES, so shared rows sum over the
  ranks; COO rows and columns are mapped by ``ltog`` and PETSc's MPIAIJ COO assembly sums
  the entries of rows other ranks own. Rank r owns a contiguous range of global dofs, the
  Numbering's;
* replicated (no ``dofs``: the film-only problems, 1D and small): local = serial = global
  dofs, PETSc's contiguous blocks of rows; every rank evaluates all terms and keeps only
  the rows (residual and COO entries) it owns.

Full vectors handed to and from a Problem (``u0``, what ``transient``, ``solve_steady``,
the post-step hooks, the observers and ``gather`` get) are in serial order on every rank
(a ``toAll`` scatter, reordered by the Numbering's ``natural``). A constrained row is
written by its owner only; every other rank drops its terms' entries in it. The distributed linear solve is PETSc's
(the default parallel preconditioner is ``redundant`` LU).
"""
from collections import deque
from dataclasses import asdict

import numpy as np
from petsc4py import PETSc

from .. import interrupt
from ..core import BufferPool, Counters, SolveError, StepInfo, StepTooSmall
from . import condensed


# the solvers in force, by options prefix, as set up last in this process (for the summary)
SOLVERS = {}
# the default serial direct solver: PETSc's own LU with AMD ordering below this many
# unknowns, UMFPACK from there on (scripts/bench_lu.py --stroke --stroke-meshes: the
# default's refined mesh, 8,199 unknowns, is AMD's; 0.0125 / 0.1 mm, 11,055, UMFPACK's;
# docs/petsc-build.md). PETSc's LU does not pivot: a factorisation that meets a zero pivot
# switches the problem to UMFPACK for good (Problem._fall_back_to_umfpack) and the solve is
# retried
PETSC_LU_BELOW = 10000
# ... and fewer nonzeros per row than this on average: a denser Jacobian is UMFPACK's (the
# paper's film scheme couples each film node to the whole chain, 96 per row on the refined
# default: PETSc's LU 359 ms a refactorisation with a relative residual of 1e-4, UMFPACK
# 131 ms and 3e-8; the fv scheme's 15 per row: 7.0 against 14.6 ms)
PETSC_LU_DENSITY = 40
# ... and a step whose Newton solve failed this many times in a row (TS retrying it smaller
# each time) goes on with UMFPACK too: without pivoting, PETSc's LU can lose the thin films'
# rows at high pressure without meeting an exact zero (the shipped mesh at 20 MPa: NaN
# iterates from t = 0.028 s, where UMFPACK goes through)
LU_FAILURES = 4
_ZERO_PIVOT = (PETSc.PC.FailedReason.FACTOR_NUMERIC_ZEROPIVOT,
               PETSc.PC.FailedReason.FACTOR_STRUCT_ZEROPIVOT)
# a crawl (Problem._check_pace): the last PACE_WINDOW accepted steps' pace would need more
# than PACE_LIMIT further steps to the end. The paper's cycles take 1,000-8,000 steps in
# all, and no window of the stress matrix's finished cases projects more than a few
# thousand; the crawl at 30 MPa and 2000 mm/s (benchmarks/stress.md) projects 0.7-1.8
# million
PACE_WINDOW = 2000
PACE_LIMIT = 1e5
# the accepted states a crawl's stop looks back over for an oscillation
# (Problem._oscillation): the last OSC_WINDOW, and OSC_WINDOW more spread over the pace
# window (every tenth), in single precision
OSC_WINDOW = 200
# TS locates an event to a bracket of this fraction of the run's end time (-ts_event_dt_min).
# An indicator that jumps through zero (a front whose target jumps by edges) is bisected
# down to it; PETSc's own floor lies below the smallest step TSAdapt may take, and two
# such steps in a row looked like a stuck controller (_check_min_step) and stopped the
# default cycle at its reversal as a "snap"
EVENT_DT_MIN = 1e-9


def _span(t0, t_end):
    """The time scale of a run from t0 to t_end that TS's smallest step and the events'
    bracket are fractions of: its end time (its span from 0), or its span where that is
    longer. A run resumed from a checkpoint has the uninterrupted run's (with t_end - t0
    alone the two-rank restart test failed)."""
    t0, t_end = float(t0), float(t_end)
    return max(abs(t_end), abs(t_end - t0), 1e-300)


def _solver_in_force(snes, ts=None):
    """The types and tolerances a solver ended up with, after setFromOptions."""
    ksp = snes.getKSP()
    pc = ksp.getPC()
    rtol, atol, stol, max_it = snes.getTolerances()
    out = {"snes_type": snes.getType(), "snes_linesearch_type": snes.getLineSearch().getType(),
           "snes_rtol": rtol, "snes_atol": atol, "snes_stol": stol, "snes_max_it": max_it,
           "ksp_type": ksp.getType(), "pc_type": pc.getType()}
    cond = condensed.condensed_pc(ksp)
    if cond is not None:                          # the condensation: S's solver
        pc = cond.ksp.getPC()
        out["pc_type"] = f"python (sealts condensation, S by {pc.getType()})"
    if pc.getType() in (PETSc.PC.Type.LU, PETSc.PC.Type.CHOLESKY):
        out["pc_factor_mat_solver_type"] = pc.getFactorSolverType()
    if ts is not None:
        ts_rtol, ts_atol = ts.getTolerances()
        if not np.isscalar(ts_rtol):      # per unknown: the run's rtol is the largest
            ts_rtol = ts_rtol.max()[1]
        out.update(ts_type=ts.getType(), ts_rtol=ts_rtol,
                   ts_atol=ts_atol if np.isscalar(ts_atol) else "per unknown")
    return out


class Problem:
    """A DAE assembled from terms, solved with PETSc TS (transient) or SNES (steady)."""

    def __init__(self, n, terms, comm=None, prefix=None, constraints=None, linesearch="bt",
                 snes_atol=None, fields=None, dofs=None):
        """``linesearch`` is the default SNES line search (the command line overrides it):
        ``bt`` for the film; ``basic`` for near-incompressible solids, where the residual
        norm is a poor merit function. Measured on a bent block with K/G ~ 940: basic 6
        Newton iterations, cp 12, l2 20, bt stalls at 50 (docs/design.md).

        ``snes_atol`` (units of the residual, e.g. N) makes Newton convergence absolute: the
        relative test max(atol, rtol |F0|) accepts nonsense when a poor predictor makes |F0|
        huge, which happened in quasi-static mounting (rod force 1e4 N accepted for 450 N).
        Without it the defaults are rtol 1e-10, atol 1e-12.

        ``fields`` (name -> serial dofs), with a ``prony`` field of internal variables: the
        default linear solver becomes the exact Schur complement over the displacements
        (``_default_linear_solver``); any ``-pc_type fieldsplit`` gets these splits.

        ``dofs``: the distributed numbering (:class:`sealts.mesh.partition.Numbering`) in
        which the terms are written (their dofs are this rank's local dofs). Without it the
        problem is replicated: local = serial = global dofs on every rank."""
        self.linesearch = linesearch
        self.max_it = 50  # of a steady SNES solve
        self.snes_tol = (dict(rtol=1e-10, atol=1e-12) if snes_atol is None
                         else dict(rtol=1e-14, atol=snes_atol, stol=1e-14))
        self.comm = comm or PETSc.COMM_WORLD
        if self.comm.getSize() > 1:
            # one thread per rank: the ranks already share the cores (the solid's element
            # kernel spreads its elements over numba's threads in a serial run)
            import numba
            numba.set_num_threads(1)
        self.n = int(n)
        self.terms = list(terms)
        self.constraints = constraints
        self.prefix = prefix
        self.fields = dict(fields or {})
        self.counters = Counters()
        # PETSc's LU by default and not by choice: it may give way to UMFPACK
        self._lu_may_fall_back = False
        # the time of that switch, if it happened (a resumed run carries it on), and why
        self.lu_fallback = None
        self.lu_fallback_why = "a zero pivot of PETSc's LU"
        self._step_failures = (None, 0)   # (the step's start time, TS's SNES failures then)
        self._set_defaults = []       # options set by _default_option, dropped after use
        self._callback_error = None   # a term's exception in a callback (_guarded)
        # the last Jacobian's COO values, and the state and handle of its matrix
        self._jac_vals = self._jac_state = self._jac_handle = None
        self._jac_op = None           # the Jacobian as COO values alone (condensed.operator)
        self._cond = False            # its Prony block's condensation, once computed
        self._structured = None       # ... by the term that owns the block (found with it)
        self._pool = BufferPool()     # for the Jacobian's values (_free_buffer)
        self._bdf_order = None        # TS BDF's order in force (make_ts; the summary's)
        # more TS defaults of this problem (option name without prefix -> value); the
        # command line and the scene's [petsc] table win
        self.ts_defaults = {}
        # c of sealts.problem.newton_test: a stage's Newton solve also converges once its
        # correction is below c times TS's error tolerance of every unknown (None: off)
        self.update_test = None
        # stop at a step of TS's minimum size (``_check_min_step``); a problem whose fastest
        # physics needs steps that small (a Prony term of 1e-8 s over 1e4 s) leaves it off
        self.stop_at_min_step = False
        # restart the integrator (BDF from first order) at every stop of ``transient``, so
        # that a run resumed from a checkpoint there is this run to the last bit (without,
        # PETSc's BDF carries its history across a stop)
        self.restart_at_stops = False

        self.dofs = dofs
        if dofs is None:      # replicated: every rank has every dof, adds its own rows
            self.U = PETSc.Vec().createMPI((PETSc.DECIDE, self.n), comm=self.comm)
            self.rstart, self.rend = self.U.getOwnershipRange()
            ltog = np.arange(self.n, dtype=np.int64)
            self._own = (ltog >= self.rstart) & (ltog < self.rend)
            self._keep = self._own
            self.natural = None
            self._serial_owned = np.arange(self.rstart, self.rend)
            self._replicated = True
        else:                 # distributed: each local contribution is this rank's alone
            if dofs.n != self.n:
                raise ValueError(f"numbering of {dofs.n} unknowns for a problem of {self.n}")
            self.U = PETSc.Vec().createMPI((dofs.n_owned, self.n), comm=self.comm)
            self.rstart, self.rend = self.U.getOwnershipRange()
            if self.rstart != dofs.rstart:
                raise RuntimeError("PETSc's ownership range is not the numbering's")
            ltog = np.asarray(dofs.ltog, np.int64)
            self._own = np.asarray(dofs.owned, bool)
            self._keep = np.ones(ltog.size, bool)
            self.natural = None if dofs.identity else np.asarray(dofs.natural, np.int64)
            self._serial_owned = np.asarray(dofs.serial[:dofs.n_owned], np.int64)
            self._replicated = False
        self.ltog = ltog
        self.n_local = ltog.size
        # global U -> this rank's local dofs (and back, adding, for residuals)
        self._lvec = PETSc.Vec().createSeq(self.n_local, comm=PETSc.COMM_SELF)
        self._ldvec, self._fvec = self._lvec.duplicate(), self._lvec.duplicate()
        iset = PETSc.IS().createGeneral(ltog.astype(PETSc.IntType), comm=PETSc.COMM_SELF)
        self._l2g = PETSc.Scatter().create(self.U, iset, self._lvec, None)
        self._scatter, self._useq = PETSc.Scatter.toAll(self.U)
        self._udseq = self._useq.duplicate()

        rows = np.concatenate([np.asarray(t.rows, np.int64) for t in self.terms])
        cols = np.concatenate([np.asarray(t.cols, np.int64) for t in self.terms])
        if constraints is not None:
            # a constrained row is u_i - g_i(t) = 0: every rank drops its terms' entries in
            # it, the owner adds the identity
            # the terms' entries in constrained rows (zeroed), by index: one pass of the
            # values per Jacobian
            self._fixed_entries = np.flatnonzero(np.isin(rows, constraints.dofs))
            self._fixed_own = self._own[constraints.dofs]
            fixed = constraints.dofs[self._fixed_own]
            rows = np.concatenate([rows, fixed])
            cols = np.concatenate([cols, fixed])
        self._rows, self._cols = rows, cols
        self._mine = self._keep[rows]
        if self._mine.all():     # serial: every entry is this rank's, no copy per Jacobian
            self._mine = slice(None)
        self.J = PETSc.Mat().create(comm=self.comm)
        m = self.rend - self.rstart
        self.J.setSizes(((m, self.n), (m, self.n)))
        self.J.setType(PETSc.Mat.Type.AIJ)
        self.J.setPreallocationCOO(ltog[rows[self._mine]].astype(PETSc.IntType),
                                   ltog[cols[self._mine]].astype(PETSc.IntType))

    # ---- evaluation on this rank's local numpy arrays --------------------------------------
    def gather(self, V, seq=None):
        """Full copy of a distributed vector on every rank, in serial order (do not keep:
        without a distributed numbering it is a view of a work vector)."""
        seq = self._useq if seq is None else seq
        self._scatter.scatter(V, seq, addv=PETSc.InsertMode.INSERT_VALUES,
                              mode=PETSc.ScatterMode.FORWARD)
        a = seq.getArray(readonly=True)
        return a if self.natural is None else a[self.natural]

    def local(self, V, seq=None):
        """This rank's local dofs of a distributed vector (a view of a work vector)."""
        seq = self._lvec if seq is None else seq
        self._l2g.scatter(V, seq, addv=PETSc.InsertMode.INSERT_VALUES,
                          mode=PETSc.ScatterMode.FORWARD)
        return seq.getArray(readonly=True)

    def residual(self, t, u, udot):
        """This rank's part of F on its local dofs (u, udot local)."""
        f = np.zeros(self.n_local)
        for term in self.terms:
            term.add_residual(t, u, udot, f)
        c = self.constraints
        if c is not None:
            f[c.dofs] = np.where(self._fixed_own, u[c.dofs] - c.values(t), 0.0)
        return f

    def jacobian_values(self, t, u, udot, shift, st=None):
        """The COO values of the Jacobian, in an array that is the caller's until it lets
        go of it (_free_buffer). With ``st`` (a :class:`.condensed.Structured`), those of
        the Schur complement over the Prony internal variables instead, on the Jacobian's
        entries that couple no internal variable: the term that condenses its own block
        gives its part of S, the others their Jacobians."""
        parts = [np.asarray(term.condensed_values(t, u, udot, shift)
                            if st is not None and term is st.term
                            else term.jacobian_values(t, u, udot, shift), float)
                 for term in self.terms]
        if self.constraints is not None:
            parts.append(np.ones(int(self._fixed_own.sum())))
        if st is None:
            size, fixed = self._rows.size, (self._fixed_entries if self.constraints
                                            is not None else None)
        else:
            size, fixed = st.n_values, st.fixed_entries
        vals = np.concatenate(parts, out=self._free_buffer(size))
        if fixed is not None:
            vals[fixed] = 0.0
        return vals

    def _free_buffer(self, size):
        """An array for the Jacobian's values that nothing outside this problem's pool
        refers to (the condensation's PC keeps the values it was set up from, the Problem
        the last ones, _jac_vals)."""
        return self._pool.get(size)

    def jacobian_dense(self, t, u, udot, shift):
        """Assembled Jacobian as a dense array (serial tests and diagnostics only)."""
        a = np.zeros((self.n_local, self.n_local))
        np.add.at(a, (self._rows, self._cols), self.jacobian_values(t, u, udot, shift))
        return a

    def global_residual(self, t, u, udot=None):
        """F(t, u, udot) of the whole problem, u and udot full and in serial order; the
        result too (on every rank)."""
        X = self._owned(u)
        Xd = self._owned(np.zeros(self.n) if udot is None else udot)
        F = X.duplicate()
        self._assemble_residual(t, X, Xd, F)
        return self.gather(F).copy()

    # ---- PETSc callbacks -------------------------------------------------------------------
    def _add_local(self, F, f):
        """F = sum over ranks of their local f. Replicated: each rank sets its own rows."""
        if self._replicated:
            F.setArray(f[self.rstart:self.rend])
            return
        F.zeroEntries()
        self._fvec.setArray(f)
        self._l2g.scatter(self._fvec, F, addv=PETSc.InsertMode.ADD_VALUES,
                          mode=PETSc.ScatterMode.REVERSE)

    def _assemble_residual(self, t, U, Udot, F):
        u = self.local(U).copy()
        ud = self.local(Udot, self._ldvec) if Udot is not None else np.zeros(self.n_local)
        f = self.residual(t, u, ud)
        if not np.isfinite(f).all() and np.isfinite(ud).all():
            # kept for the message of a run that stops on it (``_nonfinite``); a U' that is
            # itself not finite is TS's own (a step below the resolution of t)
            self._nonfinite_at = (t, u, ud.copy())
        self._add_local(F, f)

    def _assemble_jacobian(self, t, U, Udot, shift, J, P):
        u = self.local(U).copy()
        ud = self.local(Udot, self._ldvec) if Udot is not None else np.zeros(self.n_local)
        st = condensed.structured(self) if P.getType() == PETSc.Mat.Type.PYTHON else None
        # with st, the Schur complement's values alone (the condensation's; serial)
        vals = self.jacobian_values(t, u, ud, shift, st)[self._mine]
        if P.getType() == PETSc.Mat.Type.PYTHON:     # the values are the matrix
            P.stateIncrease()
        else:
            P.setValuesCOO(vals, addv=PETSc.InsertMode.INSERT_VALUES)
        # for the condensation's PC (sealts.problem.condensed), which reads them back
        self._jac_vals, self._jac_state, self._jac_handle = vals, P.stateGet(), P.handle
        if J != P:
            J.assemble()
        self.counters.jacobians += 1

    def _guarded(self, what, t, assemble, *args):
        """Run a callback's assembly; an exception of a term's own (not a SolveError or an
        interrupt, which the run handles) is kept as a one-line SolveError naming it, for
        :meth:`_callback_failure` to raise once PETSc has unwound (PETSc itself reports
        it only as its error 101)."""
        try:
            assemble(*args)
        except (SolveError, interrupt.Interrupted):
            raise
        except Exception as e:
            if self._callback_error is None:
                self._callback_error = SolveError(
                    f"the {what} at t = {t:.6g} s raised {type(e).__name__}: {e}")
            raise

    def _callback_failure(self):
        """The SolveError of a callback's exception (:meth:`_guarded`), once, or None."""
        err, self._callback_error = self._callback_error, None
        return err

    def ifunction(self, ts, t, U, Udot, F):
        if self._lu_may_fall_back:    # a step that keeps failing leaves PETSc's LU
            why = self._failing_step(ts)
            if why is not None:
                self._fall_back_to_umfpack(ts.getSNES(), ts.getTime(), why)
        self._guarded("residual", t, self._assemble_residual, t, U, Udot, F)
        self.counters.residuals += 1

    def ijacobian(self, ts, t, U, Udot, shift, J, P):
        self._guarded("Jacobian", t, self._assemble_jacobian, t, U, Udot, shift, J, P)

    def snes_function(self, snes, U, F):
        self._guarded("residual", self.t_steady, self._assemble_residual, self.t_steady, U,
                      None, F)
        self.counters.residuals += 1

    def snes_jacobian(self, snes, U, J, P):
        self._guarded("Jacobian", self.t_steady, self._assemble_jacobian, self.t_steady, U,
                      None, 0.0, J, P)

    # ---- solver set-up ---------------------------------------------------------------------
    def _default_linear_solver(self, ksp):
        if "prony" in self.fields:
            if not condensed.default_solver(self, ksp):
                self._default_schur(ksp)
            return
        ksp.setType(PETSc.KSP.Type.PREONLY)
        pc = ksp.getPC()
        if self.comm.getSize() == 1:
            pc.setType(PETSc.PC.Type.LU)
            self._default_factor(pc, self.n, self.J.getInfo()["nz_allocated"])
        else:
            pc.setType(PETSc.PC.Type.REDUNDANT)

    def _default_factor(self, pc, n, nonzeros):
        """The default serial LU of a matrix of n unknowns: PETSc's with AMD ordering where
        it is small and sparse (PETSC_LU_BELOW, PETSC_LU_DENSITY) and this problem has not
        fallen back to UMFPACK, else UMFPACK."""
        if n < PETSC_LU_BELOW and self.lu_fallback is None and nonzeros < PETSC_LU_DENSITY * n:
            pc.setFactorSolverType("petsc")
            pc.setFactorOrdering(PETSc.Mat.OrderingType.AMD)
        else:
            pc.setFactorSolverType("umfpack")

    def _factor_of(self, ksp):
        """(the PC that factors, its options prefix, the condensation or None): the KSP's
        own PC, or the condensation's LU of S (sealts.problem.condensed)."""
        cond = condensed.condensed_pc(ksp)
        if cond is not None:
            return cond.ksp.getPC(), cond.ksp.getOptionsPrefix(), cond
        return ksp.getPC(), self.prefix, None

    def _arm_lu_fallback(self, snes):
        """After setFromOptions: PETSc's LU in force by default (not chosen on the command
        line or in the scene's [petsc] table) may give way to UMFPACK; another factor
        package chosen there orders the matrix itself (_own_ordering). A PC that the
        options switched to LU from another type (a Prony problem's condensation) has no
        package set, so PETSc's own: it took the 'external' ordering meant for the others
        and failed in its symbolic factorisation (with a null communicator)."""
        pc, prefix, _ = self._factor_of(snes.getKSP())
        chosen = PETSc.Options(prefix).hasName("pc_factor_mat_solver_type")
        lu = pc.getType() == PETSc.PC.Type.LU
        solver = pc.getFactorSolverType() or "petsc"
        self._lu_may_fall_back = lu and not chosen and solver == "petsc"
        if lu and solver != "petsc":
            self._own_ordering(pc, prefix)

    def _solvers_in_force(self, snes, ts=None):
        """Record the solver this problem set up (SOLVERS, for the summary), with the time
        UMFPACK took over from PETSc's LU if it did."""
        SOLVERS[self.prefix or ""] = out = _solver_in_force(snes, ts)
        if ts is not None and ts.getType() == PETSc.TS.Type.BDF:
            out["ts_bdf_order"] = self._bdf_order
        if self.lu_fallback is not None:
            out["pc_factor_mat_solver_type"] = (
                f"umfpack (from t = {self.lu_fallback:.6g}: {self.lu_fallback_why})")

    def _own_ordering(self, pc, prefix):
        """A factor package other than PETSc's orders the matrix itself (PETSc's
        'external'), unless an ordering was chosen: the AMD ordering set for PETSc's LU,
        handed to UMFPACK as a fixed column order, made its factorisations 3.7 times slower
        on the stroke Jacobian of 0.025 / 0.2 mm (3,487 unknowns; 20 against 5.4 ms,
        2026-12-04)."""
        if not PETSc.Options(prefix).hasName("pc_factor_mat_ordering_type"):
            pc.setFactorOrdering("external")

    def _fall_back_to_umfpack(self, snes, t, why=None):
        """If the last linear solve of ``snes`` failed on a zero pivot of PETSc's default
        LU (it does not pivot), or ``why`` names another reason, switch its factorisation
        to UMFPACK (which pivots) for the rest of this problem's solves; True if it did."""
        ksp = snes.getKSP()
        if not self._lu_may_fall_back or (why is None and (
                ksp.getConvergedReason() != PETSc.KSP.ConvergedReason.DIVERGED_PCSETUP_FAILED
                or ksp.getPC().getFailedReason() not in _ZERO_PIVOT)):
            return False
        if why is not None:
            self.lu_fallback_why = why
        pc, prefix, cond = self._factor_of(ksp)
        pc.reset()                    # the factor goes; SNES sets the operators again
        pc.setFactorSolverType("umfpack")
        self._own_ordering(pc, prefix)
        if cond is not None:          # ... but S is the condensation's own
            cond.ksp.setOperators(cond.S)
        self._lu_may_fall_back = False
        self.lu_fallback = float(t)
        self._solvers_in_force(snes, getattr(self, "_ts", None))
        return True

    def _failing_step(self, ts):
        """The reason to leave PETSc's LU if this step has failed LU_FAILURES Newton solves
        since it began (TS retries a step from the same time), else None. TS counts its
        SNES failures over one solve(), and they only change between Newton solves, so the
        switch comes at a solve's first residual, before its first factorisation."""
        t, failures = ts.getTime(), ts.getSNESFailures()
        t0, at_start = self._step_failures
        if t != t0 or failures < at_start:
            self._step_failures = (t, failures)
            return None
        if failures - at_start < LU_FAILURES:
            return None
        return f"{failures - at_start} failed Newton solves in a row with PETSc's LU"

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
            d = np.asarray(self.fields[name], np.int64)
            if self.natural is not None:
                d = np.sort(self.natural[d])
            d = d[(d >= self.rstart) & (d < self.rend)].astype(PETSc.IntType)
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
                self._set_defaults.append(name)

    def _drop_defaults(self):
        opts = PETSc.Options(self.prefix)
        for name in self._set_defaults:
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
        op = condensed.operator(self, snes.getKSP())
        if op is not None:
            snes.setJacobian(self.snes_jacobian, op)
        self._arm_lu_fallback(snes)
        self._solvers_in_force(snes)
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
        if np.ndim(atol):        # one per unknown, full and in serial order
            atol = self._owned(atol)
        if np.ndim(rtol):
            rtol = self._owned(rtol)
        ts.setTolerances(rtol=rtol, atol=atol)
        for name, value in self.ts_defaults.items():
            self._default_option(name, value)
        self._default_option("ts_adapt_type", "basic")  # petsc4py has no TSAdapt binding
        # a run whose steps shrink below 1e-12 of its span (_span) fails instead of
        # crawling on
        self._default_option("ts_adapt_dt_min", repr(1e-12 * _span(t0, t_end)))
        snes = ts.getSNES()
        snes.setType(PETSc.SNES.Type.NEWTONLS)
        snes.getLineSearch().setType(self.linesearch)
        snes.setTolerances(max_it=25, **self.snes_tol)
        self._default_linear_solver(snes.getKSP())
        if monitor is not None:
            ts.setMonitor(monitor)
        try:
            ts.setFromOptions()
            # BDF's order in force (petsc4py has no getter; the default is dropped next)
            self._bdf_order = PETSc.Options(self.prefix).getInt("ts_bdf_order", 2)
        finally:
            self._drop_defaults()
        if self.update_test is not None:   # after setFromOptions: the tolerances in force
            from .newton_test import UpdateTest
            ts.getSNES().setConvergenceTest(UpdateTest(ts, self.update_test))
        self._set_splits(ts.getSNES().getKSP())
        op = condensed.operator(self, ts.getSNES().getKSP())
        if op is not None:
            ts.setIJacobian(self.ijacobian, op)
        self._arm_lu_fallback(ts.getSNES())
        if self._lu_may_fall_back:
            # before each Newton iteration: a step whose factorisation met a zero pivot
            # failed, and TS retries it (smaller) with UMFPACK (a step that failed
            # LU_FAILURES times in a row: ifunction, which every attempt calls first)
            ts.getSNES().setUpdate(lambda snes, its: self._fall_back_to_umfpack(
                snes, ts.getTime()))
        self._solvers_in_force(ts.getSNES(), ts)
        return ts

    def _set_events(self, ts, raised):
        """The terms' events (``Term.event_directions``) as TS events: located in time
        where an indicator crosses zero, then the term's ``event`` and a restart of the
        integrator (the DAE changed there). Every rank gathers U (collective) and evaluates
        its own terms' indicators. A SolveError of an event ends the run with its message
        (``raised``, as the monitor's).

        After the terms' events U's state is marked changed whether or not an event set an
        unknown: an event changes its term's indicators (a moved front's target is measured
        from its new place), and PETSc's TSEvent recomputes the indicators' signs at the
        event only when the post-event changed U; otherwise it keeps them zero there and
        does not count a sign change from zero as a crossing, so an indicator that passes
        its other zero within the first step after its event was never located (a front's
        target then ran 0.08 edges past a 0.02 tolerance on the coarse cycle)."""
        terms = [x for x in self.terms if getattr(x, "event_directions", ())]
        if not terms:
            return
        sizes = [len(x.event_directions) for x in terms]
        ends = np.cumsum(sizes)

        def call(f, *args):
            try:
                return f(*args)
            except (SolveError, interrupt.Interrupted) as e:
                raised.append(e)
                raise

        def indicator(ts, t, X, fvalue):
            u = self.gather(X).copy()
            fvalue[:] = call(lambda: np.concatenate(
                [np.asarray(x.event_values(t, u), float) for x in terms]))

        def post(ts, events, t, X, forward):
            u = self.gather(X).copy()
            before = u.copy()
            events = np.asarray(events, int)
            for x, end, size in zip(terms, ends, sizes):
                mine = events[(events >= end - size) & (events < end)] - (end - size)
                if mine.size:
                    call(x.event, t, u, mine)
            self._set_from_events(X, before, u)
            X.stateIncrease()       # the indicators changed: PETSc recomputes their signs
            ts.restartStep()

        span = _span(ts.getTime(), ts.getMaxTime())
        self._default_option("ts_event_dt_min", repr(EVENT_DT_MIN * span))
        try:        # TSSetEventHandler reads the event options
            ts.setEventHandler([d for x in terms for d in x.event_directions],
                               [False] * int(ends[-1]), indicator, post)
        finally:
            self._drop_defaults()

    def _set_from_events(self, X, before, u):
        """Write the unknowns that events set in u (full, serial) into X. The ranks' terms
        set disjoint unknowns (a boundary term runs on one rank), so the changes add up;
        collective."""
        change = u - before
        if self.comm.getSize() > 1:
            from mpi4py import MPI
            change = self.comm.tompi4py().allreduce(change, op=MPI.SUM)
        if not change.any():
            return
        X.setArray(X.getArray(readonly=True) + change[self._serial_owned])

    def accepted(self, t, u):
        """Every term's post-step hook at the accepted state u (full, serial order)."""
        for term in self.terms:
            term.accepted(t, u)

    # ---- solves ----------------------------------------------------------------------------
    def _owned(self, u0):
        X = self.U.duplicate()
        X.setArray(np.asarray(u0, float)[self._serial_owned])
        return X

    def solve_steady(self, u0, t=0.0):
        """Solve F(t, U, 0) = 0 from the initial guess u0; return the full solution."""
        self.t_steady = t
        for attempt in range(2):
            snes = self.make_snes()
            X = self._owned(u0)
            try:
                snes.solve(None, X)
            except PETSc.Error:
                interrupt.check()     # a signal that ended the solve from inside a callback
                err = self._callback_failure()
                if err is not None:
                    raise err from None
                raise
            interrupt.check(self.comm)
            if attempt or not self._fall_back_to_umfpack(snes, t):
                break
            self.counters.newton += snes.getIterationNumber()
            snes.destroy()            # again from u0, with UMFPACK (_default_linear_solver)
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

    def _option_real(self, name, default):
        """A real option as in force for this problem's prefix (the command line's, else
        ``default``)."""
        opts = PETSc.Options(self.prefix or None)
        return opts.getReal(name, default) if opts.hasName(name) else default

    def _unknown(self, i):
        """Serial unknown i in words (the numbering's, else "unknown i")."""
        return self.dofs.describe(i) if hasattr(self.dofs, "describe") else f"unknown {i}"

    def _fastest_change(self, u, rtol, atol):
        """"; the fastest change: <unknown>" since the last accepted state ("" without)."""
        u_prev = self._last_u[0]
        if u_prev is None:
            return ""
        scale = np.asarray(atol, float) + np.asarray(rtol, float) * np.abs(u)
        change = np.abs(u - u_prev) / np.where(scale > 0, scale, np.inf)
        i = int(np.argmax(change))
        return f"; the fastest change: {self._unknown(i)}"

    def _nonfinite(self, ts):
        """Where TS's last Newton solve failed on a non-finite residual: the first term whose
        part is not finite and what it says of it (``Term.nonfinite``; else the unknown of
        its first such row), at the last residual that was not finite with a finite U' (""
        otherwise)."""
        R = PETSc.SNES.ConvergedReason
        nan = {getattr(R, n) for n in ("DIVERGED_FNORM_NAN", "DIVERGED_FUNCTION_NANORINF")
               if hasattr(R, n)}
        if ts.getSNES().getConvergedReason() not in nan or self._nonfinite_at is None:
            return ""
        t, u, udot = self._nonfinite_at
        for term in self.terms:
            f = np.zeros(self.n_local)
            try:
                term.add_residual(t, u, udot, f)
            except Exception:        # the stop's own reason stands
                continue
            bad = np.flatnonzero(~np.isfinite(f))
            if bad.size:
                what = term.nonfinite(t, u)
                if what is None:
                    i = int(bad[0]) if self._replicated else int(self.dofs.serial[bad[0]])
                    what = "not finite at the " + self._unknown(i)
                return f": the residual at t = {t:.6g} s, {type(term).__name__}: {what}"
        return ""

    def _check_pace(self, t, u, t_end, rtol, atol):
        """A run whose steps have shrunk so far that, at the pace of its last PACE_WINDOW
        accepted steps, the rest would take more than PACE_LIMIT further steps, crawls: it
        would neither finish in any useful time nor stop. Stop it as a stuck step
        (StepTooSmall, which the stroke answers with its snap stabilisation once) and name
        the unknown that changed most against its tolerance. Off with
        ``stop_at_min_step``."""
        if not self.stop_at_min_step:
            return
        times = self._pace
        times.append(t)
        if len(times) <= PACE_WINDOW:
            return
        span = t - times[0]
        need = (t_end - t) / span * PACE_WINDOW if span > 0.0 else np.inf
        if need <= PACE_LIMIT:
            return
        raise StepTooSmall(f"the time steps crawl: the last {PACE_WINDOW} advanced t by "
                           f"{span:.3g} s (to t = {t:.6g} s), and at that pace the "
                           f"remaining {t_end - t:.4g} s would take {need:.2g} more steps"
                           f"{self._fastest_change(u, rtol, atol)}"
                           f"{self._oscillation(rtol, atol)}", t=t)

    def _oscillation(self, rtol, atol):
        """"; it oscillates: ..." when the unknown that swung most against its error
        tolerance over the last OSC_WINDOW accepted states (else over OSC_WINDOW states
        spread over the pace window: a period of more than a third of the first window is
        sampled at least six times there) rose through the upper quarter of its swing from
        below its lower quarter at least three times (a trigger with hysteresis, so
        round-off wiggles do not count): its range and its period, the mean time between
        those rises. "" otherwise."""
        for states in (self._recent, self._spread):
            found = self._oscillation_in(states, rtol, atol)
            if found:
                return found
        return ""

    def _oscillation_in(self, states, rtol, atol):
        if len(states) < 10:
            return ""
        t = np.array([s[0] for s in states])
        U = np.array([s[1] for s in states], float)
        scale = np.asarray(atol, float) + np.asarray(rtol, float) * np.abs(U).max(0)
        swing = (U.max(0) - U.min(0)) / np.where(scale > 0, scale, np.inf)
        i = int(np.argmax(swing))
        x = U[:, i]
        lo, hi = x.min() + np.array([0.25, 0.75]) * (x.max() - x.min())
        rises, below = [], False
        for tk, xk in zip(t, x):
            if xk < lo:
                below = True
            elif xk > hi and below:
                rises.append(tk)
                below = False
        if len(rises) < 3:
            return ""
        period = (rises[-1] - rises[0]) / (len(rises) - 1)
        return (f"; it oscillates: {self._unknown(i)} swings between {x.min():.4g} and "
                f"{x.max():.4g} with a period of {period:.3g} s ({len(rises)} rises since t = "
                f"{t[0]:.6g} s)")

    def _check_min_step(self, t_prev, t, u, rtol, atol):
        """TSAdapt accepts a step at its minimum size whatever its error (PETSc's basic
        controller): such a step is not an answer but a sign that the solution changes
        faster than any step can follow. Stop, and name the unknown that changed most
        against its tolerance."""
        if not self.stop_at_min_step or self._dt_min is None:
            return
        dt, at_min = t - t_prev, self._dt_min * (1.0 + 1e-6)
        last_dt, self._last_dt = self._last_dt, dt
        # a first step the caller chose below the minimum grows away from it: only a step
        # at the minimum that follows one there, and is no longer, is the controller stuck
        if dt > at_min or last_dt is None or last_dt > at_min or dt > last_dt * (1.0 + 1e-6):
            return
        name = self._fastest_change(u, rtol, atol)
        raise StepTooSmall(f"time step at its minimum ({self._dt_min:.3g} s) at t = {t:.6g} s: "
                           "the solution changes faster than the error tolerance can follow "
                           f"(a step this small is accepted unchecked){name}", t=t)

    def snapshot(self):
        """At a stop of :meth:`transient` (from an observer's ``stop``): what a run resumed
        there needs to go on as this one does (``transient(..., resume=snapshot)``): the
        time, the step TS takes next, the counts so far, the min-step check's last step and
        the histories of the terms that carry one, in their order. With ``restart_at_stops``
        ``transient`` restarts the integrator at every stop (``TSRestartStep``: BDF from
        first order), so nothing else carries over."""
        ts = self._ts
        c = self.counters + Counters(ts.getStepNumber(), ts.getStepRejections(),
                                     ts.getSNESIterations(), ts.getKSPIterations(),
                                     ts.getSNESFailures())
        return {"t": ts.getTime(), "dt": ts.getTimeStep(),
                "last_dt": -1.0 if self._last_dt is None else self._last_dt,
                # when PETSc's LU gave way to UMFPACK (-1: it did not)
                "lu_fallback": -1.0 if self.lu_fallback is None else self.lu_fallback,
                "counters": asdict(c),
                "step": ts.getStepNumber() + self._offset[0],
                "newton": ts.getSNESIterations() + self._offset[1],
                "history": {str(k): term.history()
                            for k, term in enumerate(self.history_terms())}}

    def history_terms(self):
        """The terms that carry a history, in order (the same on every rank: the ranks
        that do not assemble a boundary term run its hook, :class:`HookOnly`)."""
        return [term for term in self.terms if term.history_names]

    def transient(self, u0, t0, t_end, dt0, stops=(), observers=(), rtol=1e-6, atol=1e-8,
                  resume=None):
        """Integrate from t0 to t_end with adaptive steps; return the full final state.

        After every accepted step (and at t0) each term's post-step hook ``accepted(t, u)``
        runs, then each observer's ``accepted(t, u, info)`` (:class:`sealts.core.Observer`);
        a SolveError either raises ends the run with its own message. ``observer.stop(t, u)``
        runs at each time in ``stops`` (hit exactly) and at t_end; ``start`` before the first
        step, ``close`` when the run ends or fails. ``atol``: a number, or one
        per unknown (full, serial order; a huge one leaves that unknown out of the local
        error estimate).

        ``resume``: a :meth:`snapshot` taken at t0 by an earlier run (u0 its state, dt0 its
        step): the terms' histories and the counts are put back, and neither the hooks nor
        the observers see t0 again (they saw it in that run; the observers are restored by
        their owner).
        """
        last, last_u = [None], [None]
        taken = [None]        # the last accepted step's size
        raised = []
        observers = list(observers)
        targets = sorted({float(s) for s in stops if t0 < s < t_end} | {float(t_end)})
        targets = [s for s in targets if s > t0]      # a resumed run that had finished
        self._dt_min = None
        self._nonfinite_at = None
        self._offset = (0, 0)
        self._pace = deque(maxlen=PACE_WINDOW + 1)    # the last accepted steps' t
        # and their (t, u), for _oscillation: the last ones and every tenth
        self._recent = deque(maxlen=OSC_WINDOW)
        self._spread = deque(maxlen=OSC_WINDOW)
        if resume is not None:
            with_history = self.history_terms()
            for k, history in resume["history"].items():
                with_history[int(k)].restore(history)
            self.counters = Counters(**{k: int(v) for k, v in resume["counters"].items()})
            if resume.get("lu_fallback", -1.0) >= 0.0:     # on with UMFPACK, as that run
                self.lu_fallback = float(resume["lu_fallback"])
                self.lu_fallback_why = "in the run this one resumes"
            self._offset = (int(resume["step"]), int(resume["newton"]))
            last[0] = float(t0)

        def monitor(ts, step, t, X):
            # TS calls its monitor at the start of every solve(): report each state once
            if t == last[0]:
                return
            t_prev, last[0] = last[0], t
            if t_prev is not None and t > t_prev:
                taken[0] = t - t_prev
            # a non-finite residual is reported by the stop it causes, not by a later one
            self._nonfinite_at = None
            try:
                interrupt.check(self.comm)   # between steps, before anything is written
                u = self.gather(X).copy()
                self._recent.append((t, u.astype(np.float32)))
                if len(self._pace) % (PACE_WINDOW // OSC_WINDOW) == 0:
                    self._spread.append(self._recent[-1])
                if t_prev is not None and t not in targets:
                    self._check_min_step(t_prev, t, u, rtol, atol)
                if t_prev is not None:
                    self._check_pace(t, u, t_end, rtol, atol)
                last_u[0] = u
                self.accepted(t, u)
                info = StepInfo(step + self._offset[0], ts.getTimeStep(),
                                ts.getSNESIterations() + self._offset[1])
                for obs in observers:
                    obs.accepted(t, u, info)
            except (SolveError, interrupt.Interrupted) as e:   # PETSc: "error 101"
                raised.append(e)
                raise

        ts = self.make_ts(t0, t_end, dt0, monitor=monitor, rtol=rtol, atol=atol)
        self._set_events(ts, raised)
        self._dt_min = self._option_real("ts_adapt_dt_min", 1e-12 * _span(t0, t_end))
        self._last_u, self._last_dt = last_u, None
        if resume is not None:
            last_u[0] = np.array(u0, float)
            self._last_dt = None if resume["last_dt"] < 0 else float(resume["last_dt"])
        X = self._owned(u0)
        self._ts = ts
        try:
            u = np.array(u0, float)
            for obs in observers if resume is None else ():
                obs.start(t0, u)
            for k, target in enumerate(targets):
                ts.setMaxTime(target)
                if k and self.restart_at_stops:   # what a run resumed here does
                    ts.restartStep()
                if k and not ts.getTimeStep() > 0.0 and taken[0]:
                    # an event's post-event steps follow the trajectory planned before it;
                    # one that a stop ended leaves a step of zero to go on with
                    ts.setTimeStep(taken[0])
                try:
                    ts.solve(X)
                except PETSc.Error as e:
                    if raised:       # a hook's or observer's own verdict (one line) stands
                        raise raised[0] from None
                    interrupt.check()
                    err = self._callback_failure()
                    if err is not None:
                        raise err from None
                    raise SolveError(f"time stepping failed at t = {ts.getTime():.6g} s "
                                     f"(PETSc error {e.ierr}); see the PETSc message above"
                                     ) from None
                reason = ts.getConvergedReason()
                if reason < 0:
                    raise SolveError(f"time stepping failed at t = {ts.getTime():.6g} s "
                                     f"({_reason(PETSc.TS, reason)}){self._nonfinite(ts)}; "
                                     "try a smaller -ts_dt or -ts_adapt_dt_min")
                u = self.gather(X).copy()
                for obs in observers:
                    obs.stop(ts.getTime(), u)
        finally:
            c = self.counters
            c.steps += ts.getStepNumber()
            c.rejected += ts.getStepRejections()
            c.newton += ts.getSNESIterations()
            c.linear += ts.getKSPIterations()
            c.newton_failures += ts.getSNESFailures()
            ts.destroy()
            self._ts = None
            for obs in observers:
                obs.close()
        return u


def _reason(cls, code):
    names = {v: k for k, v in vars(cls.ConvergedReason).items() if isinstance(v, int)}
    return names.get(code, str(code))
