"""Run time against error when Prony terms are folded (relaxed / frozen) instead of carried.

1. Step-shear relaxation of one element with Table 2 over a window [t_min, t_end]: the
   stress against the closed form G_0 g_R(t) (Eq. 7), for the full series (15 active
   terms) and for classifications at several tolerances.
2. The paper's O-ring (coarse mesh): relaxed at 1 MPa, stepped to 3 MPa, held 10 s (a stroke's
   time scale): the rod force history against the run with every term active.

Prints tables and writes results/bench_prony.png. Usage:

    .venv/bin/python scripts/bench_prony.py [--quick]
"""
import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT), str(ROOT / "tests")]

from sealts.solid.prony import (TABLE2_G, TABLE2_TAU, Classification, PronySeries,  # noqa: E402
                                classify)
from sealts.solid.shear_element import shear_history  # noqa: E402

TABLE2 = PronySeries(TABLE2_G, TABLE2_TAU)


def every_term_active(series):
    n = len(series.g)
    return Classification(np.zeros(0, int), np.zeros(0, int), np.arange(n), 0.0)


def relaxation(series, classes, times, gamma=1e-4):
    """S12 / (G_0 gamma) of one element under a step shear at t = 0, wall time, steps."""
    t0 = time.perf_counter()
    got, problem = shear_history(series, times, gamma, classes=classes)
    return got / gamma, time.perf_counter() - t0, problem.counters.steps


def bench_relaxation(windows, tols):
    rows = []
    print("\n1. step-shear relaxation, one element, Table 2")
    print(f"{'window [s]':>16} {'tol':>8} {'active':>6} {'relaxed':>7} {'frozen':>6} "
          f"{'bound':>9} {'max err':>9} {'steps':>6} {'wall [s]':>8}")
    for t_min, t_end in windows:
        times = np.logspace(np.log10(t_min), np.log10(t_end), 21)
        exact = TABLE2.relaxation(times)
        for tol in [None] + list(tols):
            c = every_term_active(TABLE2) if tol is None else classify(TABLE2, t_min, t_end, tol)
            got, wall, steps = relaxation(TABLE2, c, times)
            err = float(np.abs(got / exact - 1).max())
            rows.append((t_min, t_end, tol, len(c.active), err, wall, steps))
            print(f"{t_min:7.0e}-{t_end:<8.0e} {'full' if tol is None else f'{tol:.0e}':>8} "
                  f"{len(c.active):6d} {len(c.relaxed):7d} {len(c.frozen):6d} "
                  f"{c.error_bound:9.2e} {err:9.2e} {steps:6d} {wall:8.2f}")
    return rows


def bench_oring(tols, t_end):
    """Rod force history of the O-ring hold against the all-active run."""
    from dataclasses import replace

    import tomllib

    from sealts.core import Recorder

    from sealts.problem.hold_problem import HoldProblem
    from sealts.scene.schema import scene_from_table
    from sealts.steps import prepare
    table = tomllib.loads((ROOT / "configs" / "oring_hold.toml").read_text())
    table["mesh"].update(h_contact=0.1, h_bulk=0.4)
    table["hold"].update(t_end=t_end, p_end=3.0)
    table.setdefault("output", {})["progress"] = False
    s = scene_from_table(table, base=ROOT / "configs")
    state = prepare(s)                     # steps 1-2: mounted, pressurised to 1 MPa
    times = np.logspace(-3, np.log10(t_end), 13)
    print(f"\n2. O-ring hold 1 -> 3 MPa over 1 ms, to {t_end:g} s, Table 2, coarse mesh")
    print(f"{'tol':>8} {'active':>6} {'unknowns':>8} {'steps':>6} {'wall [s]':>8} "
          f"{'max rod-force diff':>18}")
    ref, rows = None, []
    for tol in [0.0] + list(tols):
        ve = replace(s.viscoelastic, tol=tol) if tol else replace(s.viscoelastic, tol=1e-300)
        step = HoldProblem(state.model, state.u, state.load, 1.0, 3.0, 1e-3, ve, t_end)
        rec = Recorder()
        t0 = time.perf_counter()
        step.run(t_end, 1e-5, 1e-4, stops=times[:-1], observers=[rec])
        wall = time.perf_counter() - t0
        forces = {t: float(step.rod.forces(t, step.displacement(U)).sum())
                  for t, U in rec.stops}
        f = np.array([forces[min(forces, key=lambda x: abs(x - t))] for t in times])
        if ref is None:
            ref = f
        diff = float(np.abs(f / ref - 1).max())
        rows.append((tol, len(step.classes.active), wall, diff))
        print(f"{'full' if not tol else f'{tol:.0e}':>8} {len(step.classes.active):6d} "
              f"{step.layout.n:8d} {step.problem.counters.steps:6d} {wall:8.1f} {diff:18.2e}")
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="the relaxation part only")
    args = ap.parse_args()
    rel = bench_relaxation([(1e-4, 10.0), (1e-3, 1e6)], (1e-1, 1e-2, 1e-3))
    oring = [] if args.quick else bench_oring((1e-1, 1e-2, 1e-3), 10.0)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2 if oring else 1, figsize=(11 if oring else 6, 4.5))
    ax = np.atleast_1d(ax)
    for t_min, t_end in sorted({(r[0], r[1]) for r in rel}):
        pts = [r for r in rel if (r[0], r[1]) == (t_min, t_end)]
        ax[0].loglog([r[5] for r in pts], [max(r[4], 1e-12) for r in pts], "o-",
                     label=f"window {t_min:g}-{t_end:g} s")
        for r in pts:
            ax[0].annotate(f"{r[3]}", (r[5], max(r[4], 1e-12)), fontsize=8)
    ax[0].set_xlabel("wall time [s]")
    ax[0].set_ylabel("max relative error of g_R")
    ax[0].set_title("one element (labels: active terms)")
    ax[0].legend(fontsize=8)
    if oring:
        ax[1].loglog([r[2] for r in oring[1:]], [max(r[3], 1e-12) for r in oring[1:]], "o-")
        for r in oring[1:]:
            ax[1].annotate(f"{r[1]}", (r[2], max(r[3], 1e-12)), fontsize=8)
        ax[1].axvline(oring[0][2], ls="--", label="all 15 active")
        ax[1].set_xlabel("wall time [s]")
        ax[1].set_ylabel("max rod-force difference to all-active")
        ax[1].set_title("O-ring hold, 10 s")
        ax[1].legend(fontsize=8)
    for a in ax:
        a.grid(alpha=0.3, which="both")
    fig.tight_layout()
    out = ROOT / "results"
    out.mkdir(exist_ok=True)
    fig.savefig(out / "bench_prony.png", dpi=120)
    print(f"\nwritten: {out / 'bench_prony.png'}")


if __name__ == "__main__":
    main()
