"""The elements' dilatation theta_e (:mod:`sealts.solid.q1p0`) and a displacement field
corrected to given dilatations: a state carried to another mesh
(:mod:`sealts.steps.transfer`).

For a Q1/P0 element

    theta_e(u) = v_e / V_e = sum_g w_g J_g(u) / sum_g w_g,
    d theta_e / d u_e = sum_g w_g B_g^T dJ/df_g / V_e,

f_g = (F11, F12, F21, F22, F33) = I + B_g u_e, J = (F11 F22 - F12 F21) F33.

Why a correction: the rubber is nearly incompressible (K / G ~ 1000). A displacement field
interpolated from a coarser mesh is bilinear inside each old element, whose J varies there
by about 1 % while only its mean theta is held to the pressure (Q1/P0); the new, smaller
elements sample that variation, and at K = 2 / D1 every per cent is some 20 MPa of
pressure. Newton's method from such a state meets a Jacobian that is far from positive
(the geometric stiffness of those pressures) and turns elements over. So the field is first
moved, as little as possible, until each new element has the dilatation of the old element
it lies in (Gauss-Newton on theta(u) = theta_target, the least-norm step

    du = -G^T (G G^T)^-1 (theta(u) - theta_target),    G = d theta / d u,

with the nodes of ``fixed`` dofs kept: the boundary, whose penalty contacts take a
micrometre into a wall as some 10 MPa).
"""
import numpy as np

_I = np.array([1.0, 0.0, 0.0, 1.0, 1.0])


def dilatation(solid, u):
    """(theta (ne,), d theta / d u_e (ne, 8)) of the elements of ``solid`` (a
    :class:`sealts.solid.term.SolidTerm`) at u (its layout)."""
    ue = np.asarray(u)[solid.dofs]                                 # (ne, 8)
    f = np.einsum("egij,ej->egi", solid.B, ue) + _I
    F11, F12, F21, F22, F33 = np.moveaxis(f, -1, 0)
    J = (F11 * F22 - F12 * F21) * F33
    dJ = np.stack([F22 * F33, -F21 * F33, -F12 * F33, F11 * F33, F11 * F22 - F12 * F21], -1)
    V = solid.W.sum(axis=1)
    theta = (solid.W * J).sum(axis=1) / V
    grad = np.einsum("eg,egij,egi->ej", solid.W, solid.B, dJ) / V[:, None]
    return theta, grad


def match_dilatation(solid, u, target, fixed, n, iterations=4, tol=1e-9):
    """u (n,) moved by the least norm to elements of dilatation ``target`` (ne,), the
    ``fixed`` dofs kept (module docstring); Gauss-Newton, sparse LU of G G^T (PETSc,
    serial). Returns the new u and the largest misfit |theta - target| left (where the
    fixed boundary leaves the targets' volume no room, a small rest)."""
    from petsc4py import PETSc
    u = np.array(u, float)
    ne = solid.dofs.shape[0]
    keep = np.ones(n)
    keep[np.asarray(fixed, np.int64)] = 0.0
    G = PETSc.Mat().createAIJ((ne, n), comm=PETSc.COMM_SELF)   # the pattern once
    G.setPreallocationCOO(np.repeat(np.arange(ne), 8).astype(PETSc.IntType),
                          solid.dofs.ravel().astype(PETSc.IntType))
    ksp = PETSc.KSP().create(comm=PETSc.COMM_SELF)
    ksp.setType("preonly")
    ksp.getPC().setType("lu")
    A = lam = rhs = None
    du = PETSc.Vec().createSeq(n, comm=PETSc.COMM_SELF)
    try:
        for it in range(iterations + 1):
            theta, grad = dilatation(solid, u)
            r = theta - target
            misfit = float(np.abs(r).max())
            if misfit < tol or it == iterations:
                break
            G.setValuesCOO((grad * keep[solid.dofs]).ravel(),
                           addv=PETSc.InsertMode.INSERT_VALUES)
            A = G.matTransposeMult(G, result=A)
            # rows of elements with every node fixed are empty: a shift far below the
            # entries
            A.shift(1e-12 * float(np.abs(A.getDiagonal().getArray()).max()))
            ksp.setOperators(A)
            if lam is None:
                lam, rhs = A.createVecs()
            rhs.setArray(r)
            ksp.solve(rhs, lam)
            G.multTranspose(lam, du)
            u -= du.getArray()
    finally:
        for obj in (G, A, ksp, lam, rhs, du):
            if obj is not None:
                obj.destroy()
    return u, misfit
