"""Direct solvers on a Jacobian-like matrix: PETSc's LU (nested-dissection and AMD
orderings) against UMFPACK, KLU and SuperLU.

The matrices: the 2D plane-strain stiffness of a structured Q1 mesh with nu = 0.49, clamped
at one edge (5k to 80k unknowns), like the seal's displacement block; with ``--stroke``
also the default cycle's coupled stroke Jacobian at the stroke's start (seal, film, leakage
and friction, on the scene's mesh refined at the contact's edges, 8.2k unknowns; mounts,
pressurises and carries the state to the refined mesh first, about 30 s), and with
``--stroke-meshes`` that Jacobian on four meshes without the refinement (0.025 / 0.2 to the
paper's 0.01 / 0.05 mm, 3.5k to 30k unknowns; tests/conftest.coarsened; steps 1-2 from the
state cache where an earlier run left them): the measurements behind
PETSC_LU_BELOW in sealts/problem/problem.py (PETSc's LU with AMD against UMFPACK). For each solver it
times the first set-up (symbolic + numeric factorisation and one solve) and a
refactorisation (numeric factorisation and one solve with the pattern kept: what every
Newton iteration of a run pays), best of ``--repeat``, and prints markdown tables
(docs/petsc-build.md keeps the last ones). Run:

    .venv/bin/python scripts/bench_lu.py [--sizes 50 100 200] [--repeat 3] [--stroke]
                                         [--stroke-meshes]
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


SOLVERS = [("petsc", "nd"), ("petsc", "amd"), ("umfpack", None), ("klu", None),
           ("superlu", None)]


def time_solver(A, b, solver, ordering, repeat):
    """(first set-up s, refactorisation s, relative residual) of one direct solver."""
    first = refactor = np.inf
    for _ in range(repeat):
        ksp = PETSc.KSP().create(comm=PETSc.COMM_SELF)
        ksp.setOperators(A)
        ksp.setType("preonly")
        pc = ksp.getPC()
        pc.setType("lu")
        pc.setFactorSolverType(solver)
        if ordering:
            pc.setFactorOrdering(ordering)
        x = b.duplicate()
        t = time.perf_counter()
        ksp.setUp()
        ksp.solve(b, x)
        first = min(first, time.perf_counter() - t)
        for _ in range(repeat):
            A.assemble()              # the same pattern, new values: a numeric refactorisation
            t = time.perf_counter()
            ksp.setOperators(A)
            ksp.setUp()
            ksp.solve(b, x)
            refactor = min(refactor, time.perf_counter() - t)
        r = b.duplicate()
        A.mult(x, r)
        r.axpy(-1.0, b)
        res = r.norm() / b.norm()
        ksp.destroy()
    return first, refactor, res


# (contact, bulk) element sizes of --stroke-meshes, mm
STROKE_MESHES = [(0.025, 0.2), (0.0125, 0.2), (0.0125, 0.1), (0.01, 0.05)]


def stroke_jacobian(mesh=None, scheme="fv"):
    """The default cycle's stroke Jacobian at the stroke's start (TS shift of a 1e-4 s
    backward-Euler step); ``mesh``: (contact, bulk) element sizes in place of the scene's,
    steps 1-2 then from the state cache if an earlier run left them; ``scheme``: the film
    scheme."""
    import sys
    from pathlib import Path
    root = Path(__file__).resolve().parents[1]
    sys.path[:0] = [str(root), str(root / "tests")]
    from conftest import scene, stroke_of
    from sealts.steps import prepare
    from sealts.steps.procedure import new_state, run_steps, steps_1_2
    from sealts.steps.state_cache import StateCache
    if mesh is None:
        state = prepare(scene("oring_stroke", film={"scheme": scheme},
                              output={"progress": False}))
    else:
        s = scene("oring_stroke", mesh={"h_contact": mesh[0], "h_bulk": mesh[1]},
                  film={"scheme": scheme})
        state = run_steps(steps_1_2(s, StateCache.for_scene(s, {}, "run")), new_state(s))
    step = stroke_of(state)
    pb = step.problem
    X = pb._owned(step.start())
    Xd = X.duplicate()
    Xd.set(0.0)
    pb._assemble_jacobian(0.0, X, Xd, 1e4, pb.J, pb.J)
    pb.J.assemble()
    return pb.J


def table(matrices, repeat):
    names = [s if o is None else f"{s} ({o})" for s, o in SOLVERS]
    print("| matrix | unknowns | " + " | ".join(names) + " |")
    print("|---" * (len(names) + 2) + "|")
    for name, A in matrices:
        b = A.createVecLeft()
        b.setRandom()
        cells = []
        for s, o in SOLVERS:
            first, again, res = time_solver(A, b, s, o, repeat)
            cells.append(f"{1e3 * first:.1f} / {1e3 * again:.1f} ms"
                         + ("" if res < 1e-6 else f" (res {res:.1e})"))
        print(f"| {name} | {A.getSize()[0]:,} | " + " | ".join(cells) + " |", flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", type=int, nargs="+", default=[50, 100, 200])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--stroke", action="store_true",
                    help="also the default cycle's stroke Jacobian (mounts first)")
    ap.add_argument("--film-scheme", default="fv", choices=("fv", "paper"),
                    help="the film scheme of the stroke Jacobians (default fv)")
    ap.add_argument("--stroke-meshes", action="store_true",
                    help="also the stroke Jacobian on the meshes " + ", ".join(
                        f"{c:g} / {b:g}" for c, b in STROKE_MESHES) + " mm")
    args = ap.parse_args()
    f = args.film_scheme
    matrices = [(f"stroke Jacobian ({f})", stroke_jacobian(scheme=f))] if args.stroke else []
    if args.stroke_meshes:
        matrices += [(f"stroke Jacobian ({f}), {c:g} / {b:g} mm", stroke_jacobian((c, b), f))
                     for c, b in STROKE_MESHES]
    for nx in args.sizes:
        n, rows, cols, vals = q1_plane_strain(nx)
        A = PETSc.Mat().createAIJ((n, n), comm=PETSc.COMM_SELF)
        A.setPreallocationCOO(rows.astype(PETSc.IntType), cols.astype(PETSc.IntType))
        A.setValuesCOO(vals)
        matrices.append((f"Q1 {nx} x {nx}", A))
    print("first set-up / refactorisation (each with one solve), best of "
          f"{args.repeat}")
    table(matrices, args.repeat)


if __name__ == "__main__":
    main()
