"""Static condensation of a diagonal block: the default serial linear solver of a problem
whose Jacobian has a diagonal block (the Prony internal variables, paper Eq. 8-9).

With the diagonal block's unknowns q and the rest r, Newton's linear system is

    [ D     A_qr ] [x_q]   [b_q]
    [ A_rq  A_rr ] [x_r] = [b_r],        D diagonal,

and it is solved exactly by

    S x_r = b_r - A_rq D^-1 b_q,        S = A_rr - A_rq D^-1 A_qr,
    x_q = D^-1 (b_q - A_qr x_r).

An internal variable couples only to its own element's displacements, so S has the
pattern of A_rr's element blocks: it is assembled here from the Jacobian's own COO values
(its pattern, and the slot of every product in it, fixed once), factored by an inner KSP
(options prefix ``<problem's>condensed_``, LU by default) whose symbolic factorisation
is kept from one Newton iteration to the next. PCFIELDSPLIT's Schur complement with
``selfp`` computes the same S, but extracts four sub-matrices and forms the product
symbolically anew at every set-up.

The PC reads the values the Problem last assembled (``Problem._jac_vals``) when the
matrix it is handed is that assembly (its PETSc state), else the matrix's own CSR values.
Where it solves Newton's systems alone (KSP preonly), the Jacobian is not assembled into
an AIJ matrix at all: :class:`JacobianOperator` holds it as those COO values. There, when
the term that owns the block condenses it itself (the Prony term: its blocks per Gauss
point are rank 4, so its part of S is one 8 x 8 block per Gauss point,
:class:`sealts.solid.viscoelastic.PronyTerm`), the values are S's own on A_rr's entries
(:class:`Structured`): the off-diagonal blocks are never formed, and the right-hand
side's reduction, the back-substitution and the operator's product go through the term.
"""
import weakref

import numba
import numpy as np
from petsc4py import PETSc


# the options prefix of S's solver, after the problem's
PREFIX = "condensed_"


class NotCondensable(ValueError):
    """The pattern has no diagonal block over the given unknowns."""


@numba.njit(cache=True)
def condense_kernel(vals, qq_e, qq_q, qr_ptr, qr_e, qr_slot, rq_ptr, rq_e, rq_slot, gid,
                    L, n_groups, most, rr_e, s_block, dinv, svals):
    """svals = (A_rr entries, then -(A_rq D^-1 A_qr) per group block of L x L slots);
    dinv = 1 / diag(D). ``most``: the most entries of A_qr in a row, duplicates included.
    False if a diagonal entry is zero or not finite."""
    nq = dinv.size
    d = np.zeros(nq)
    for k in range(qq_e.size):
        d[qq_q[k]] += vals[qq_e[k]]
    nrr = rr_e.size
    for k in range(nrr):
        svals[k] = vals[rr_e[k]]
    blocks = np.zeros(n_groups * L * L)
    wv, ws = np.empty(most), np.empty(most, np.int64)
    for q in range(nq):
        if d[q] == 0.0 or not np.isfinite(d[q]):
            return False
        dinv[q] = 1.0 / d[q]
        base = gid[q] * L * L
        b0, nb = qr_ptr[q], qr_ptr[q + 1] - qr_ptr[q]
        for b in range(nb):       # the q's row of A_qr, once
            wv[b] = vals[qr_e[b0 + b]] * dinv[q]
            ws[b] = qr_slot[b0 + b]
        for a in range(rq_ptr[q], rq_ptr[q + 1]):
            va = vals[rq_e[a]]
            row = base + rq_slot[a] * L
            for b in range(nb):
                blocks[row + ws[b]] += va * wv[b]
    for k in range(s_block.size):
        svals[nrr + k] = -blocks[s_block[k]]
    return True


@numba.njit(cache=True)
def reduce_rhs(b, qdofs, rdofs, vals, rq_ptr, rq_e, rq_r, dinv, z):
    """z = b_r - A_rq D^-1 b_q."""
    for i in range(rdofs.size):
        z[i] = b[rdofs[i]]
    for q in range(qdofs.size):
        t = b[qdofs[q]] * dinv[q]
        for a in range(rq_ptr[q], rq_ptr[q + 1]):
            z[rq_r[a]] -= vals[rq_e[a]] * t


@numba.njit(cache=True)
def back_substitute(b, qdofs, rdofs, vals, qr_ptr, qr_e, qr_r, dinv, xr, x):
    """x_r = xr; x_q = D^-1 (b_q - A_qr x_r)."""
    for i in range(rdofs.size):
        x[rdofs[i]] = xr[i]
    for q in range(qdofs.size):
        s = b[qdofs[q]]
        for a in range(qr_ptr[q], qr_ptr[q + 1]):
            s -= vals[qr_e[a]] * xr[qr_r[a]]
        x[qdofs[q]] = s * dinv[q]


@numba.njit(cache=True)
def coo_mult(rows, cols, vals, x, y):
    """y = A x of the COO entries (duplicates add)."""
    y[:] = 0.0
    for k in range(rows.size):
        y[rows[k]] += vals[k] * x[cols[k]]


def _by_q(q, e, slot, r, nq):
    """Entries e (with slots and r indices) sorted by their q, and the CSR pointers; 32-bit
    indices and 8-bit slots (the kernels read them once per entry per call)."""
    order = np.argsort(q, kind="stable")
    ptr = np.zeros(nq + 1, np.int64)
    np.cumsum(np.bincount(q, minlength=nq), out=ptr[1:])
    return ptr, e[order].astype(np.int32), slot[order].astype(np.uint8), \
        r[order].astype(np.int32)


class Condensation:
    """The fixed structure: which COO entries are D, A_qr, A_rq, A_rr, and where each
    product of A_rq D^-1 A_qr lands in S's COO values. With ``lazy``, the products' part
    (the costly one: seconds on the refined fig. 14 mesh) waits until the generic
    condensation is first asked for (:meth:`generic`); a problem whose Prony term condenses
    itself (:class:`Structured`) needs only A_rr's entries."""

    def __init__(self, rows, cols, n, qdofs, lazy=False):
        rows = np.asarray(rows, np.int64)
        cols = np.asarray(cols, np.int64)
        qdofs = np.unique(np.asarray(qdofs, np.int64))
        isq = np.zeros(n, bool)
        isq[qdofs] = True
        rdofs = np.flatnonzero(~isq)
        qidx = np.full(n, -1, np.int64)
        qidx[qdofs] = np.arange(qdofs.size)
        ridx = np.full(n, -1, np.int64)
        ridx[rdofs] = np.arange(rdofs.size)
        rq_, cq_ = isq[rows], isq[cols]
        qq = rq_ & cq_
        if (rows[qq] != cols[qq]).any():
            raise NotCondensable("the internal variables' block is not diagonal")
        if np.unique(rows[qq]).size != qdofs.size:
            raise NotCondensable("an internal variable without a diagonal entry")
        self.n, self.qdofs, self.rdofs = n, qdofs.astype(np.int32), rdofs.astype(np.int32)
        self.qq_e = np.flatnonzero(qq).astype(np.int32)
        self.qq_q = qidx[rows[qq]].astype(np.int32)
        self.rr_e = np.flatnonzero(~rq_ & ~cq_).astype(np.int32)
        # S's COO starts with A_rr's entries (in the r numbering)
        self.rr_rows, self.rr_cols = ridx[rows[self.rr_e]], ridx[cols[self.rr_e]]
        self._args = (rows, cols, rq_, cq_, qidx, ridx)
        self._s = None
        if not lazy:
            self.generic()

    def generic(self):
        """The products' structure (once): each internal variable's coupled unknowns, their
        groups (an element's) and S's COO entries for the groups' blocks."""
        if self._s is not None:
            return
        rows, cols, rq_, cq_, qidx, ridx = self._args
        qdofs, rdofs = self.qdofs, self.rdofs
        qr = np.flatnonzero(rq_ & ~cq_)
        rq = np.flatnonzero(~rq_ & cq_)
        nq, nr = qdofs.size, rdofs.size
        # each q's coupled r, sorted: its row's columns and its column's rows
        q_qr, r_qr = qidx[rows[qr]], ridx[cols[qr]]
        q_rq, r_rq = qidx[cols[rq]], ridx[rows[rq]]
        keys = np.unique(np.concatenate([q_qr * nr + r_qr, q_rq * nr + r_rq]))
        kq = keys // nr
        start = np.searchsorted(kq, np.arange(nq + 1))
        count = np.diff(start)
        L = int(count.max(initial=1))
        if L > 255:
            raise NotCondensable(f"an internal variable coupled to {L} unknowns")
        if max(rows.size, L * L * nq) >= 2**31:
            raise NotCondensable("too many Jacobian entries for 32-bit indices")
        pad = np.full((nq, L), -1, np.int64)
        pad[kq, np.arange(keys.size) - start[kq]] = keys % nr
        # q with the same coupled set share a block of S (an element's internal variables)
        groups, gid = np.unique(pad, axis=0, return_inverse=True)
        self.gid, self.L = gid.ravel().astype(np.int32), L
        self.n_groups = groups.shape[0]
        slot_qr = np.searchsorted(keys, q_qr * nr + r_qr) - start[q_qr]
        slot_rq = np.searchsorted(keys, q_rq * nr + r_rq) - start[q_rq]
        self.qr_ptr, self.qr_e, self.qr_slot, self.qr_r = _by_q(q_qr, qr, slot_qr, r_qr, nq)
        self.most = int(np.diff(self.qr_ptr).max(initial=0))
        self.rq_ptr, self.rq_e, self.rq_slot, self.rq_r = _by_q(q_rq, rq, slot_rq, r_rq, nq)
        # S's COO: A_rr's entries, then each group's valid L x L slots
        gi = np.repeat(groups[:, :, None], L, axis=2)
        gj = np.repeat(groups[:, None, :], L, axis=1)
        valid = ((gi >= 0) & (gj >= 0)).ravel()
        self.s_block = np.flatnonzero(valid).astype(np.int32)
        self._s = (np.concatenate([self.rr_rows, gi.ravel()[valid]]),
                   np.concatenate([self.rr_cols, gj.ravel()[valid]]))
        self._args = None

    @property
    def s_rows(self):
        """S's COO rows: A_rr's entries, then the groups' blocks."""
        self.generic()
        return self._s[0]

    @property
    def s_cols(self):
        self.generic()
        return self._s[1]

    def values(self, vals, dinv, svals):
        """S's COO values and 1 / diag(D) from the Jacobian's COO values; False if D has a
        zero or non-finite entry."""
        self.generic()
        return condense_kernel(vals, self.qq_e, self.qq_q, self.qr_ptr, self.qr_e,
                               self.qr_slot, self.rq_ptr, self.rq_e, self.rq_slot, self.gid,
                               self.L, self.n_groups, self.most, self.rr_e, self.s_block,
                               dinv, svals)

    def from_csr(self, rows, cols, indptr, indices, values):
        """COO values read back from an assembled matrix's CSR arrays: each entry's value
        at its first occurrence, zero at its duplicates."""
        key = rows * self.n + cols
        order = np.argsort(key, kind="stable")
        first = np.ones(rows.size, bool)
        first[order[1:]] = key[order[1:]] != key[order[:-1]]
        indptr = np.asarray(indptr, np.int64)
        csr_key = (np.repeat(np.arange(self.n), np.diff(indptr)) * self.n
                   + np.asarray(indices, np.int64))
        pos = np.minimum(np.searchsorted(csr_key, key), csr_key.size - 1)
        if csr_key.size != np.count_nonzero(first) or (csr_key[pos] != key).any():
            raise RuntimeError("the matrix handed to the condensation has another pattern "
                               "than the Problem's Jacobian")
        return np.where(first, np.asarray(values)[pos], 0.0)


class CondensedPC:
    """A petsc4py python PC: the exact solve by condensation (module docstring)."""

    def __init__(self, problem, cond):
        # weakly: the PC lives in PETSc's objects, which the garbage collector cannot see
        # through, and would keep the Problem alive
        self.problem, self.cond = weakref.proxy(problem), cond
        c = cond
        self.S = None
        self._make_s(generic=cond._s is not None)
        self.dinv = np.zeros(c.qdofs.size)
        self.z, self.xr = self.S.createVecs()
        # S's solver: the problem's default LU for its size (Problem._default_factor, with
        # its fall-back to UMFPACK), tuned by -<prefix>condensed_...
        self.ksp = PETSc.KSP().create(comm=PETSc.COMM_SELF)
        self.ksp.setOptionsPrefix((problem.prefix or "") + PREFIX)
        self.ksp.setType(PETSc.KSP.Type.PREONLY)
        inner = self.ksp.getPC()
        inner.setType(PETSc.PC.Type.LU)
        problem._default_factor(inner, c.rdofs.size, self.S.getInfo()["nz_allocated"])
        self.ksp.setOperators(self.S)
        self.vals = self.st = self.st_state = None
        self.read_back = False        # values read back from an assembled matrix

    def _make_s(self, generic):
        """S's matrix: on A_rr's entries alone (a term's own condensation), or with the
        groups' blocks for the generic products."""
        c = self.cond
        rows, cols = (c.s_rows, c.s_cols) if generic else (c.rr_rows, c.rr_cols)
        if self.S is not None:
            self.S.destroy()
        self.S = PETSc.Mat().create(comm=PETSc.COMM_SELF)
        self.S.setSizes((c.rdofs.size, c.rdofs.size))
        self.S.setType(PETSc.Mat.Type.AIJ)
        self.S.setPreallocationCOO(rows.astype(PETSc.IntType), cols.astype(PETSc.IntType))
        self.svals = np.zeros(rows.size)
        self.s_generic = generic

    def setFromOptions(self, pc):
        self.ksp.setFromOptions()

    def _values(self, P):
        p = self.problem
        if P.handle == p._jac_handle and P.stateGet() == p._jac_state:
            return p._jac_vals
        if P.getType() == PETSc.Mat.Type.PYTHON:
            raise RuntimeError("the condensation was handed a matrix the Problem did not "
                               "assemble")
        self.read_back = True
        return self.cond.from_csr(p.ltog[p._rows], p.ltog[p._cols], *P.getValuesCSR())

    def setUp(self, pc):
        # a python PC's failure stays until it is cleared (PETSc's own PCs clear theirs at
        # set-up): after one failed Newton solve every later one would fail too
        pc.setFailedReason(PETSc.PC.FailedReason.NOERROR)
        _, P = pc.getOperators()
        vals = np.ascontiguousarray(self._values(P), float)
        # the operator's values are S's own where a term condenses its block itself
        self.st = structured(self.problem) if P.getType() == PETSc.Mat.Type.PYTHON else None
        # the generic reduction and back-substitution read the values: kept with the PC
        self.vals = vals if self.st is None else None
        if self.st is None and not self.s_generic:     # an assembled matrix after all
            try:
                self.cond.generic()
            except NotCondensable as e:
                raise RuntimeError(f"the Prony block's condensation of an assembled "
                                   f"matrix: {e}") from None
            self._make_s(generic=True)
        # the term's state of these values: a later Jacobian does not change this PC
        self.st_state = self.st.term.condensed_state() if self.st is not None else None
        if self.st is not None and vals.size == self.svals.size:
            self.S.setValuesCOO(vals, addv=PETSc.InsertMode.INSERT_VALUES)
        else:
            if self.st is not None:           # S built for the generic products before
                self.svals[:vals.size] = vals
                self.svals[vals.size:] = 0.0  # the group blocks: in those entries already
            elif not self.cond.values(vals, self.dinv, self.svals):
                pc.setFailedReason(PETSc.PC.FailedReason.SETUP_ERROR)  # D not invertible
                return
            self.S.setValuesCOO(self.svals, addv=PETSc.InsertMode.INSERT_VALUES)
        # S is factored here (its symbolic factorisation kept: the same pattern), so that
        # the failure read below is this factorisation's; without setOperators the KSP
        # counts itself set up and refactors only inside the next solve
        self.ksp.setOperators(self.S)
        self.ksp.setUp()
        reason = self.ksp.getPC().getFailedReason()
        if reason:
            pc.setFailedReason(reason)

    def apply(self, pc, x, y):
        c, st = self.cond, self.st
        b = x.getArray(readonly=True)
        if st is not None:
            st.reduce(b, self.z.getArray(), self.st_state)
        else:
            reduce_rhs(b, c.qdofs, c.rdofs, self.vals, c.rq_ptr, c.rq_e, c.rq_r, self.dinv,
                       self.z.getArray())
        self.ksp.solve(self.z, self.xr)
        if self.ksp.getConvergedReason() < 0:
            pc.setFailedReason(self.ksp.getPC().getFailedReason()
                               or PETSc.PC.FailedReason.SUBPC_ERROR)
        if st is not None:
            st.back(b, self.xr.getArray(readonly=True), y.getArray(), self.st_state)
        else:
            back_substitute(b, c.qdofs, c.rdofs, self.vals, c.qr_ptr, c.qr_e, c.qr_r,
                            self.dinv, self.xr.getArray(readonly=True), y.getArray())

    def view(self, pc, viewer):
        c = self.cond
        viewer.printfASCII(f"  sealts condensation of {c.qdofs.size} internal variables: "
                           f"S of {c.rdofs.size} unknowns, {self.S.getInfo()['nz_used']:.0f}"
                           " nonzeros, solved by:\n")
        self.ksp.view(viewer)

    def destroy(self, pc):
        self.ksp.destroy()
        self.S.destroy()
        self.z.destroy()
        self.xr.destroy()


class JacobianOperator:
    """A petsc4py python Mat: the Problem's last Jacobian as its COO values, never
    assembled into an AIJ matrix, where the condensation alone solves Newton's systems
    (it reads the values itself); its product serves a line search that asks for one."""

    def __init__(self, problem):
        self.problem = weakref.proxy(problem)
        self.rows = self.cols = None      # at the first product: most runs never ask

    def mult(self, A, x, y):
        p = self.problem
        st = structured(p)
        if st is not None:
            st.mult(p._jac_vals, x.getArray(readonly=True), y.getArray())
            return
        if self.rows is None:
            self.rows, self.cols = p.ltog[p._rows], p.ltog[p._cols]
        coo_mult(self.rows, self.cols, p._jac_vals, x.getArray(readonly=True), y.getArray())


class Structured:
    """The condensation by the term that owns the diagonal block (a Prony term's
    ``condensed_values``, ``condensed_reduce``, ``condensed_back``, ``condensed_mult``):
    where the Jacobian is the operator of COO values (:func:`operator`), the Problem
    computes S's values on the Jacobian's entries that couple no internal variable (A_rr's,
    the first of S's entries) with the term's S_rr part in place of its K_uu, and the
    right-hand side's reduction, the back-substitution and the operator's product go
    through the term: the off-diagonal blocks' values, 16 per internal variable (8 in
    each), are never formed, nor their products summed entry by entry. Where the PC was
    set up from one Jacobian and the term has since computed another (a lagged
    preconditioner), the PC's reduction and back-substitution use the state it was set up
    from (:meth:`PronyTerm.condensed_state`).

    ``rows``, ``cols``: those entries (serial numbering), ``fixed_entries`` the ones in
    constrained rows (zeroed, as in the Jacobian), ``n_values`` their number.
    """

    def __init__(self, problem, cond, term):
        self.term, self.cond = term, cond
        if not np.array_equal(problem.ltog, np.arange(problem.n)):
            raise NotCondensable("the term's dofs are not the problem's serial ones")
        if not term.can_condense:
            raise NotCondensable("a diagonal entry of the block is not positive")
        # each term's entries; the condensing term's first n_condensed (its K_uu) alone
        sizes = [np.asarray(t.rows).size for t in problem.terms]
        keep = np.concatenate([np.arange(m) < term.n_condensed if t is term
                               else np.ones(m, bool) for t, m in zip(problem.terms, sizes)])
        if problem.constraints is not None:
            keep = np.concatenate([keep, np.ones(problem._rows.size - keep.size, bool)])
        rows, cols = problem.ltog[problem._rows][keep], problem.ltog[problem._cols][keep]
        self.rows, self.cols, self.n_values = rows, cols, rows.size
        ridx = np.full(problem.n, -1, np.int64)
        ridx[cond.rdofs] = np.arange(cond.rdofs.size)
        nrr = cond.rr_e.size
        if rows.size != nrr or (ridx[rows] != cond.rr_rows).any() or (
                ridx[cols] != cond.rr_cols).any():
            raise NotCondensable("the term's condensed entries are not A_rr's")
        fixed = np.zeros(problem.n, bool)
        if problem.constraints is not None:
            fixed_entry = np.zeros(problem._rows.size, bool)
            fixed_entry[problem._fixed_entries] = True
            self.fixed_entries = np.flatnonzero(fixed_entry[keep])
            fixed[problem.ltog[problem.constraints.dofs]] = True
        else:
            self.fixed_entries = np.zeros(0, np.int64)
        if fixed[cond.qdofs].any():
            raise NotCondensable("a constrained internal variable")
        self.free = (~fixed).astype(float)        # rows that take the blocks' parts
        self.work = np.zeros(problem.n)

    def reduce(self, b, z, state):
        """z = b_r - A_rq D^-1 b_q (of the Jacobian of the term's ``state``)."""
        w, r = self.work, self.cond.rdofs
        w[r] = 0.0                            # the reduction adds to displacements only
        self.term.condensed_reduce(b, w, state)
        z[:] = b[r] + w[r] * self.free[r]

    def back(self, b, xr, x, state):
        """x_r = xr, x_q = D^-1 (b_q - A_qr x_r)."""
        x[self.cond.rdofs] = xr
        self.term.condensed_back(b, x, state)

    def mult(self, vals, x, y):
        """y = J x from S's values and the term's blocks."""
        coo_mult(self.rows, self.cols, vals, x, y)
        w = self.work
        w[:] = 0.0
        self.term.condensed_mult(x, w)
        y += w * self.free


def structured(problem):
    """The problem's :class:`Structured` condensation (found with the condensation), or
    None: without a condensation, or where no term condenses the whole Prony block
    itself."""
    condensation(problem)
    return problem._structured


# SNES options under which SNES computes or tests the Jacobian itself, into an AIJ matrix
OWN_JACOBIAN = ("snes_fd", "snes_fd_color", "snes_mf", "snes_mf_operator",
                "snes_test_jacobian")


def condensation(problem):
    """The fixed structure of a problem's Prony block condensation (computed once), or
    None where it does not apply: in parallel, or a block that is not diagonal."""
    if problem._cond is False:
        problem._cond = problem._structured = None
        if problem.comm.getSize() == 1 and problem.natural is None:
            own = [t for t in problem.terms if hasattr(t, "condensed_values")]
            # the Prony term's own condensation needs the generic products' structure
            # only if it is handed an assembled matrix (lazy: built then)
            # the problem's own arrays where its numbering is the serial one: the lazy
            # structure keeps them
            same = np.array_equal(problem.ltog, np.arange(problem.n))
            rows, cols = ((problem._rows, problem._cols) if same else
                          (problem.ltog[problem._rows], problem.ltog[problem._cols]))
            try:
                cond = Condensation(rows, cols, problem.n, problem.fields["prony"], lazy=True)
                if len(own) == 1 and np.array_equal(
                        np.sort(problem.ltog[np.asarray(own[0].qdofs)]), cond.qdofs):
                    try:
                        problem._structured = Structured(problem, cond, own[0])
                    except NotCondensable:
                        pass
                if problem._structured is None:
                    cond.generic()
                problem._cond = cond
            except NotCondensable:
                pass
    return problem._cond


def default_solver(problem, ksp):
    """Serial: the problem's Prony internal variables condensed out exactly, S factored by
    LU (KSP preonly, the condensation as a python PC); False where it does not apply."""
    cond = condensation(problem)
    if cond is None:
        return False
    ksp.setType(PETSc.KSP.Type.PREONLY)
    pc = ksp.getPC()
    pc.setType(PETSc.PC.Type.PYTHON)
    pc.setPythonContext(CondensedPC(problem, cond))
    return True


def condensed_pc(ksp):
    """The KSP's condensation (a CondensedPC), or None."""
    pc = ksp.getPC()
    if pc.getType() != PETSc.PC.Type.PYTHON:
        return None
    ctx = pc.getPythonContext()
    return ctx if isinstance(ctx, CondensedPC) else None


def operator(problem, ksp):
    """After setFromOptions: where the condensation alone solves Newton's systems (KSP
    preonly, the Jacobian computed by the problem), the Jacobian as its COO values (one
    JacobianOperator per problem) instead of the AIJ matrix; else None."""
    if (ksp.getType() != PETSc.KSP.Type.PREONLY or condensed_pc(ksp) is None
            or any(PETSc.Options(problem.prefix).hasName(n) for n in OWN_JACOBIAN)):
        return None
    if problem._jac_op is None:
        m = problem.rend - problem.rstart
        problem._jac_op = PETSc.Mat().createPython(
            ((m, problem.n), (m, problem.n)), JacobianOperator(problem), comm=problem.comm)
        problem._jac_op.setUp()
    return problem._jac_op
