"""The condensation of the Prony block (sealts.problem.condensed): Newton's linear solve by
S = A_rr - A_rq D^-1 A_qr against a dense solve of the whole system."""
import numpy as np
import pytest
from petsc4py import PETSc

from sealts.core import Constraints, Term
from sealts.problem import Problem
from sealts.problem import problem as problem_module
from sealts.problem.condensed import Condensation, NotCondensable, condensation
from sealts.solid.term import NeoHooke, SolidTerm
from sealts.solid.viscoelastic import PronyTerm


def prony_problem(prefix=None):
    """Two distorted axisymmetric Q1 elements, three active Prony terms and a frozen
    stress, two dofs fixed; a random state (the Jacobian is then unsymmetric and far from
    the identity)."""
    X = np.array([[1.0, 0.0], [1.6, 0.1], [2.2, 0.0], [1.1, 0.7], [1.5, 0.6], [2.3, 0.8]])
    conn = np.array([[0, 1, 4, 3], [1, 2, 5, 4]])
    nv, ne = X.shape[0], conn.shape[0]
    rng = np.random.default_rng(3)
    solid = SolidTerm(X, conn, NeoHooke(0.5, 0.01), True)
    hdofs = 2 * nv + np.arange(ne * 16 * 3).reshape(ne, -1)
    prony = PronyTerm(solid, NeoHooke(40.0, 0.01), [0.5, 0.2, 0.1], [1e-3, 0.1, 10.0],
                      hdofs, frozen=rng.uniform(-0.3, 0.3, (ne, 4, 4)), shift=lambda t: 2.0)
    n = 2 * nv + hdofs.size
    problem = Problem(n, [solid, prony], constraints=Constraints([1, 3], 0.0), prefix=prefix,
                      fields={"prony": hdofs.ravel(), "displacement": np.arange(2 * nv)})
    u = np.zeros(n)
    u[:2 * nv] = rng.uniform(-0.05, 0.05, 2 * nv)
    u[2 * nv:] = rng.uniform(-2.0, 2.0, hdofs.size)
    return problem, u, rng.uniform(-1.0, 1.0, n), rng.uniform(-1.0, 1.0, n)


def solve(problem, u, ud, b, shift=7.0, touch=False):
    """Newton's linear solve with the problem's default solver at (u, ud, shift); with
    ``touch`` the matrix changes state after assembly (the PC reads it back)."""
    snes = problem.make_snes()
    ksp = snes.getKSP()
    problem._assemble_jacobian(0.0, problem._owned(u), problem._owned(ud), shift,
                               problem.J, problem.J)
    if touch:
        problem.J.setValue(0, 0, 0.0, addv=PETSc.InsertMode.ADD_VALUES)
        problem.J.assemble()
    ksp.setOperators(problem.J, problem.J)
    B = problem._owned(b)
    x = B.duplicate()
    ksp.solve(B, x)
    return ksp, x.getArray().copy()


@pytest.mark.parametrize("touch", [False, True])
def test_condensed_solve_is_the_exact_solve(touch):
    """The default serial solver of a problem with a prony field is the condensation, one
    LU of the displacements' S, and its answer is the dense solve's to round-off, from the
    Problem's own values and from the matrix read back."""
    problem, u, ud, b = prony_problem()
    ksp, x = solve(problem, u, ud, b, touch=touch)
    assert ksp.getType() == "preonly" and ksp.getPC().getType() == "python"
    assert ksp.getConvergedReason() > 0
    assert ksp.getPC().getPythonContext().read_back == touch
    A = problem.jacobian_dense(0.0, u, ud, 7.0)
    xd = np.linalg.solve(A, b)
    assert np.abs(x - xd).max() < 1e-11 * np.abs(xd).max()


def test_the_prony_term_s_own_condensation_is_the_exact_solve():
    """Where the Jacobian is the operator of COO values (KSP preonly), the Prony term gives
    S's values on A_rr's entries alone (K_uu - w sum_i g_i / (shift tau_i A + 1) B^T L dS
    B per Gauss point), and reduces, back-substitutes and multiplies through its B^T L and
    dS B: the solve is the dense one's to round-off, with constrained rows, and the values
    the Problem keeps are S's entries only."""
    from sealts.problem.condensed import structured
    problem, u, ud, b = prony_problem()
    snes = problem.make_snes()
    ksp = snes.getKSP()
    J = snes.getJacobian()[0]
    assert J.getType() == "python"
    problem._assemble_jacobian(0.0, problem._owned(u), problem._owned(ud), 7.0, J, J)
    st = structured(problem)
    assert st is not None and problem._jac_vals.size == st.n_values
    assert st.n_values < problem._rows.size // 4
    ksp.setOperators(J, J)
    x = problem.U.duplicate()
    ksp.solve(problem._owned(b), x)
    assert ksp.getConvergedReason() > 0 and ksp.getPC().getPythonContext().st is st
    xd = np.linalg.solve(problem.jacobian_dense(0.0, u, ud, 7.0), b)
    assert np.abs(x.getArray() - xd).max() < 1e-11 * np.abs(xd).max()
    assert condensation(problem)._s is None     # the generic products' structure unbuilt
    # handed the assembled matrix after all, the same PC condenses it the generic way
    problem._assemble_jacobian(0.0, problem._owned(u), problem._owned(ud), 7.0, problem.J,
                               problem.J)
    ksp.setOperators(problem.J, problem.J)
    ksp.solve(problem._owned(b), x)
    assert ksp.getPC().getPythonContext().st is None
    assert np.abs(x.getArray() - xd).max() < 1e-11 * np.abs(xd).max()
    # and back to the operator: S keeps the groups' entries, zero, and solves as before
    problem._assemble_jacobian(0.0, problem._owned(u), problem._owned(ud), 7.0, J, J)
    ksp.setOperators(J, J)
    ksp.solve(problem._owned(b), x)
    assert ksp.getPC().getPythonContext().st is st
    assert np.abs(x.getArray() - xd).max() < 1e-11 * np.abs(xd).max()


def test_a_preconditioner_set_up_from_one_jacobian_keeps_its_state_through_the_next():
    """A lagged preconditioner (-snes_lag_preconditioner, -ksp_reuse_preconditioner): the
    Problem and the Prony term compute a later Jacobian while the PC keeps the one it was
    set up from; its reduction and back-substitution must be that Jacobian's too (the
    term's pool does not reuse the state a PC holds), so that it still solves with it."""
    problem, u, ud, b = prony_problem()
    snes = problem.make_snes()
    ksp = snes.getKSP()
    J = snes.getJacobian()[0]
    problem._assemble_jacobian(0.0, problem._owned(u), problem._owned(ud), 7.0, J, J)
    ksp.setOperators(J, J)
    ksp.setUp()
    xd = np.linalg.solve(problem.jacobian_dense(0.0, u, ud, 7.0), b)
    u2 = u + np.random.default_rng(9).uniform(-0.02, 0.02, u.size)
    problem._assemble_jacobian(0.0, problem._owned(u2), problem._owned(ud), 70.0, J, J)
    pc = ksp.getPC()
    x = problem.U.duplicate()
    pc.getPythonContext().apply(pc, problem._owned(b), x)
    assert np.abs(x.getArray() - xd).max() < 1e-11 * np.abs(xd).max()


def test_inner_solver_takes_its_options_from_the_prefix():
    """The factorisation of S is tuned from the command line: <prefix>condensed_... (PETSc's
    LU is S's default at this size)."""
    opts = PETSc.Options()
    opts["cond_condensed_pc_factor_mat_solver_type"] = "umfpack"
    try:
        problem, u, ud, b = prony_problem(prefix="cond_")
        ksp, x = solve(problem, u, ud, b)
        inner = ksp.getPC().getPythonContext().ksp
        assert inner.getPC().getFactorSolverType() == "umfpack"
        assert inner.getOptionsPrefix() == "cond_condensed_"
    finally:
        opts.delValue("cond_condensed_pc_factor_mat_solver_type")
    xd = np.linalg.solve(problem.jacobian_dense(0.0, u, ud, 7.0), b)
    assert np.abs(x - xd).max() < 1e-11 * np.abs(xd).max()


def test_zero_diagonal_is_refused_instead_of_divided_by():
    """A zero entry of D (g_i w (shift tau_i A + 1) is positive for the Prony term; another
    term's could vanish) makes the condensation report failure (the PC then fails its
    set-up, Newton fails and TS retries smaller), never an inf in S."""
    problem, u, ud, b = prony_problem()
    cond = condensation(problem)
    vals = problem.jacobian_values(0.0, u, ud, 7.0)
    vals[cond.qq_e[cond.qq_q == 5]] = 0.0
    svals, dinv = np.zeros(cond.s_rows.size), np.zeros(cond.qdofs.size)
    assert not cond.values(vals, dinv, svals)


def test_a_block_that_is_not_diagonal_is_refused():
    """Condensation needs D diagonal: an off-diagonal entry among the q is refused (the
    Problem then keeps PCFIELDSPLIT's Schur complement)."""
    rows, cols = np.array([0, 1, 2, 0, 2, 1]), np.array([0, 1, 2, 2, 0, 2])
    Condensation(rows[:5], cols[:5], 3, [1])
    with pytest.raises(NotCondensable):
        Condensation(rows, cols, 3, [1, 2])


def test_s_by_petscs_lu_falls_back_to_umfpack_on_a_zero_pivot():
    """S is factored like any Jacobian of its size (PETSc's LU, small here) and gives way
    to UMFPACK on a zero pivot. S here has zero diagonals: u1 = 2, u0 = -3 (swapped rows),
    u2 + u3 / 2 - u0 = 0, and the internal variable's u3 - u0 = 0: u = (-3, 2, -1.5, -3)."""
    class Swapped(Term):
        rows = np.array([0, 0, 1, 1, 2, 2, 2, 3, 3])
        cols = np.array([0, 1, 0, 1, 2, 0, 3, 3, 0])

        def add_residual(self, t, u, udot, f):
            f[0] += u[1] - 2.0
            f[1] += u[0] + 3.0
            f[2] += u[2] - u[0] + 0.5 * u[3]
            f[3] += u[3] - u[0]

        def jacobian_values(self, t, u, udot, shift):
            return np.array([0.0, 1.0, 1.0, 0.0, 1.0, -1.0, 0.5, 1.0, -1.0])

    problem = Problem(4, [Swapped()], snes_atol=1e-12, fields={"prony": [3]})
    u = problem.solve_steady(np.zeros(4))
    assert u == pytest.approx([-3.0, 2.0, -1.5, -3.0], abs=1e-12)
    assert problem.lu_fallback is not None
    solver = problem_module.SOLVERS[""]
    assert solver["pc_type"].startswith("python (sealts condensation")
    assert solver["pc_factor_mat_solver_type"].startswith("umfpack")


def test_jacobian_as_coo_values_multiplies_like_the_matrix():
    """Where the condensation solves alone, the Jacobian is its COO values (no AIJ
    assembly); its product is the dense matrix's."""
    problem, u, ud, b = prony_problem()
    snes = problem.make_snes()
    J = snes.getJacobian()[0]
    assert J.getType() == "python"
    problem._assemble_jacobian(0.0, problem._owned(u), problem._owned(ud), 7.0, J, J)
    A = problem.jacobian_dense(0.0, u, ud, 7.0)
    X, Y = problem._owned(b), problem.U.duplicate()
    J.mult(X, Y)
    assert np.abs(Y.getArray() - A @ b).max() < 1e-13 * np.abs(A @ b).max()


@pytest.mark.parametrize("option, value", [("ksp_type", "gmres"), ("snes_fd", "")])
def test_a_krylov_method_or_snes_own_jacobian_gets_the_assembled_matrix(option, value):
    """With a Krylov method (the operator is applied, not only its condensation) or a
    Jacobian SNES computes itself, the matrix is PETSc's AIJ."""
    opts = PETSc.Options("kry_")
    opts[option] = value
    try:
        problem, u, ud, b = prony_problem(prefix="kry_")
        snes = problem.make_snes()
        assert snes.getJacobian()[0].getType() in ("seqaij", "mpiaij")
    finally:
        opts.delValue(option)


def test_newton_with_the_condensation_is_newton_with_lu():
    """A steady solve of the Prony problem (its frozen stress loads it) from the random
    state: the condensation on the Jacobian's COO values takes the same Newton iterations
    to the same answer as PETSc's LU of the assembled matrix, chosen by -pc_type lu alone
    (the PC switched from the condensation by the options reports no factor package; it
    was taken for another package's and handed the 'external' ordering, and its symbolic
    factorisation failed)."""
    problem, u, _, _ = prony_problem()
    x = problem.solve_steady(u)
    opts = PETSc.Options("lu_")
    opts["pc_type"] = "lu"
    try:
        lu, u, _, _ = prony_problem(prefix="lu_")
        x_lu = lu.solve_steady(u)
    finally:
        opts.delValue("pc_type")
    assert problem.counters.newton == lu.counters.newton
    assert np.abs(x - x_lu).max() < 1e-12
    assert np.abs(problem.global_residual(0.0, x)).max() < 1e-12


def test_jacobian_values_held_by_a_caller_are_never_overwritten():
    """The Problem reuses the arrays of its Jacobian's values, but only those nothing
    else refers to: the values a caller (the condensation's PC set up from them) still
    holds stay as they were through later Jacobians, and a released array is reused."""
    problem, u, ud, _ = prony_problem()
    held = problem.jacobian_values(0.0, u, ud, 7.0)
    kept = held.copy()
    later = problem.jacobian_values(0.0, u, ud, 70.0)
    assert np.array_equal(held, kept) and not np.array_equal(later, kept)
    n = len(problem._pool.arrays)
    del later
    problem.jacobian_values(0.0, u, ud, 700.0)
    assert len(problem._pool.arrays) == n and np.array_equal(held, kept)


def test_a_failed_factorisation_of_s_is_retried_and_the_run_goes_on():
    """A transient run whose S meets a zero pivot of PETSc's LU at its first factorisation:
    the failed Newton solve is retried with UMFPACK and the run integrates on (the
    condensation's failure is cleared at its next set-up and belongs to that set-up's own
    factorisation). u0 = cos t, u1 = sin t (swapped rows), the internal variable
    u3' + u3 = u0 and u2' = u0 - u3 / 2 from rest: u3 = (cos t + sin t - e^-t) / 2,
    u2 = sin t - (sin t - cos t + e^-t) / 4."""
    class Swapped(Term):
        rows = np.array([0, 0, 1, 1, 2, 2, 2, 3, 3])
        cols = np.array([0, 1, 0, 1, 2, 0, 3, 3, 0])

        def add_residual(self, t, u, udot, f):
            f[0] += u[1] - np.sin(t)
            f[1] += u[0] - np.cos(t)
            f[2] += udot[2] - u[0] + 0.5 * u[3]
            f[3] += udot[3] + u[3] - u[0]

        def jacobian_values(self, t, u, udot, shift):
            return np.array([0.0, 1.0, 1.0, 0.0, shift, -1.0, 0.5, shift + 1.0, -1.0])

    problem = Problem(4, [Swapped()], fields={"prony": [3]})
    u = problem.transient(np.array([1.0, 0.0, 0.0, 0.0]), 0.0, 1.0, 1e-3, rtol=1e-8,
                          atol=1e-10)
    assert problem.lu_fallback == 0.0
    assert problem.counters.newton_failures == 1
    t = 1.0
    u3 = (np.cos(t) + np.sin(t) - np.exp(-t)) / 2
    u2 = np.sin(t) - (np.sin(t) - np.cos(t) + np.exp(-t)) / 4
    assert u == pytest.approx([np.cos(t), np.sin(t), u2, u3], abs=1e-5)
