"""Direct solvers on a Jacobian-like matrix: PETSc's LU against UMFPACK, KLU and SuperLU.

The matrix is the 2D plane-strain stiffness of a structured Q1 mesh with nu = 0.49, clamped
at one edge (5k to 80k unknowns), like the seal's displacement block. For each solver it
times a symbolic + numeric factorisation and one solve, best of ``--repeat``, and prints a
markdown table (docs/petsc-build.md keeps the last one). Run:

    .venv/bin/python scripts/bench_lu.py [--sizes 50 100 200] [--repeat 2]
"""
import argparse
import time

import numpy as np
from petsc4py import PETSc


def q1_plane_strain(nx, E=1.0, nu=0.49):
    """COO (rows, cols, vals) of the stiffness on an nx x nx unit-square mesh."""
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    mu = E / (2 * (1 + nu))
    D = np.array([[lam + 2 * mu, lam, 0], [lam, lam + 2 * mu, 0], [0, 0, mu]])
    h = 1.0 / nx
    g = np.array([-1, 1]) / np.sqrt(3)
    xi = np.array([-1, 1, 1, -1])
    eta = np.array([-1, -1, 1, 1])
    Ke = np.zeros((8, 8))
    for a in g:
        for b in g:
            dN = np.stack([xi * (1 + eta * b), eta * (1 + xi * a)]) / 4 * (2 / h)
            B = np.zeros((3, 8))
            B[0, 0::2], B[1, 1::2] = dN[0], dN[1]
            B[2, 0::2], B[2, 1::2] = dN[1], dN[0]
            Ke += B.T @ D @ B * (h / 2) ** 2
    i, j = np.meshgrid(np.arange(nx), np.arange(nx), indexing="ij")
    n0 = (i * (nx + 1) + j).ravel()
    nodes = np.stack([n0, n0 + nx + 1, n0 + nx + 2, n0 + 1], 1)
    dofs = np.stack([2 * nodes, 2 * nodes + 1], 2).reshape(-1, 8)
    rows = np.repeat(dofs, 8, 1).ravel()
    cols = np.tile(dofs, (1, 8)).ravel()
    vals = np.tile(Ke.ravel(), dofs.shape[0])
    clamped = np.arange(2 * (nx + 1))  # the nodes of the first row, both components
    ndof = 2 * (nx + 1) ** 2
    rows = np.concatenate([rows, clamped])
    cols = np.concatenate([cols, clamped])
    vals = np.concatenate([vals, np.full(clamped.size, 1e6)])
    return ndof, rows, cols, vals


def time_solver(A, b, solver, repeat):
    best = np.inf
    for _ in range(repeat):
        ksp = PETSc.KSP().create(comm=PETSc.COMM_SELF)
        ksp.setOperators(A)
        ksp.setType("preonly")
        pc = ksp.getPC()
        pc.setType("lu")
        pc.setFactorSolverType(solver)
        if solver == "petsc":
            pc.setFactorOrdering("nd")
        x = b.duplicate()
        t = time.perf_counter()
        ksp.setUp()
        ksp.solve(b, x)
        best = min(best, time.perf_counter() - t)
        r = b.duplicate()
        A.mult(x, r)
        r.axpy(-1.0, b)
        res = r.norm() / b.norm()
        ksp.destroy()
    return best, res


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", type=int, nargs="+", default=[50, 100, 200])
    ap.add_argument("--repeat", type=int, default=2)
    args = ap.parse_args()
    solvers = ["petsc", "umfpack", "klu", "superlu"]
    print("| unknowns | " + " | ".join(solvers) + " |")
    print("|---" * (len(solvers) + 1) + "|")
    for nx in args.sizes:
        n, rows, cols, vals = q1_plane_strain(nx)
        A = PETSc.Mat().createAIJ((n, n), comm=PETSc.COMM_SELF)
        A.setPreallocationCOO(rows.astype(PETSc.IntType), cols.astype(PETSc.IntType))
        A.setValuesCOO(vals)
        b = A.createVecLeft()
        b.setRandom()
        cells = []
        for s in solvers:
            t, res = time_solver(A, b, s, args.repeat)
            cells.append(f"{t:.3f} s" + ("" if res < 1e-6 else f" (res {res:.1e})"))
        print(f"| {n:,} | " + " | ".join(cells) + " |", flush=True)


if __name__ == "__main__":
    main()
