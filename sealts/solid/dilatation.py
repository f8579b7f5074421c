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
micrometre into a wall as some 10 MPa), each step shortened until every Gauss point keeps
at least half the J it had before the correction, node by node (the nodes of an element
that would fall below it take a shorter step, the others their whole one): a target the
fixed nodes leave no room for is left unmet rather than met by turning an element over,
and the other elements meet theirs.
"""
import numpy as np

_I = np.array([1.0, 0.0, 0.0, 1.0, 1.0])


def dilatation(solid, u):
    """(theta (ne,), d theta / d u_e (ne, 8)) of the elements of ``solid`` (a
    :class:`sealts.solid.term.SolidTerm`) at u (its layout)."""
    F11, F12, F21, F22, F33 = np.moveaxis(_gauss_f(solid, u), -1, 0)
    J = (F11 * F22 - F12 * F21) * F33
    dJ = np.stack([F22 * F33, -F21 * F33, -F12 * F33, F11 * F33, F11 * F22 - F12 * F21], -1)
    V = solid.W.sum(axis=1)
    theta = (solid.W * J).sum(axis=1) / V
    grad = np.einsum("eg,egij,egi->ej", solid.W, solid.B, dJ) / V[:, None]
    return theta, grad


def _gauss_f(solid, u):
    """f = I + B u_e at the Gauss points (ne, ng, 5)."""
    return np.einsum("egij,ej->egi", solid.B, np.asarray(u)[solid.dofs]) + _I


def gauss_J(solid, u):
    """J = det F at the Gauss points (ne, ng) of ``solid`` at u."""
    f = _gauss_f(solid, u)
    return (f[..., 0] * f[..., 3] - f[..., 1] * f[..., 2]) * f[..., 4]


def match_dilatation(solid, u, target, fixed, n, iterations=4, tol=1e-9):
    """u (n,) moved by the least norm to elements of dilatation ``target`` (ne,), the
    ``fixed`` dofs kept (module docstring); Gauss-Newton, sparse LU of G G^T (PETSc,
    serial). Returns the new u and the largest misfit |theta - target| left (where the
    fixed boundary leaves the targets' volume no room, or an element held short of turning
    over, its rest)."""
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
    J_start = gauss_J(solid, u)
    try:
        for it in range(iterations + 1):
            theta, grad = dilatation(solid, u)
            r = theta - target
            if float(np.abs(r).max()) < tol or it == iterations:
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
            u = _kept_positive(solid, u, du.getArray(), J_start)
    finally:
        for obj in (G, A, ksp, lam, rhs, du):
            if obj is not None:
                obj.destroy()
    return u, float(np.abs(theta - target).max())


def _kept_positive(solid, u, du, J_start, keep=0.5, halvings=20):
    """u - alpha du with alpha per element node: 1 where that leaves every Gauss point
    at least ``keep`` of its J before the correction, ``J_start`` (or, where that J was
    not positive, a J no smaller), and halved on the nodes of each element that does not
    until it does (a fraction-to-the-boundary rule, node by node). The least-norm step of
    a small element held by fixed boundary nodes can ask more of it than it has, and turn
    it or its neighbour over (the paper's O-ring at 40 MPa, squeezed into the corner of rod
    and wall); the other elements' nodes take their whole step, and the misfit left is the
    equilibrium solve's after the transfer."""
    bound = np.where(J_start > 0.0, keep * J_start, J_start)
    alpha = np.ones(u.size)
    for k in range(halvings + 1):
        v = u - alpha * du
        bad = (gauss_J(solid, v) < bound).any(axis=1)
        if not bad.any():
            return v
        # the last try: those nodes not moved at all
        alpha[solid.dofs[bad].ravel()] *= 0.5 if k < halvings - 1 else 0.0
    return u
