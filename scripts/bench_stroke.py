"""Run time against error of the coupled stroke: the paper's 10 s cycle at 500 mm/s.

Steps 1-2 (mount, pressurise to 1 MPa) run once per mesh; the stroke then runs at several
TS tolerances (stroke.rtol). The error of each run is taken against the tightest tolerance
on the same mesh (time error) and against the finest mesh at the tightest tolerance (time
and mesh error): the net leakage per cycle relative to the volume carried out on the
outstroke. Also printed: the outstroke volume and the peak fluid friction.
Run times are the stroke's alone, measured in one process, one after another.

Prints a table and writes results/bench_stroke.png. Usage:

    .venv/bin/python scripts/bench_stroke.py [--quick] [--viscoelastic]
"""
import argparse
import sys
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT), str(ROOT / "tests")]


def scene(h_contact, h_bulk, viscoelastic):
    from conftest import scene as load
    extra = {"viscoelastic": {"prony": "table2", "t_min": 1e-3}} if viscoelastic else {}
    return load("oring_stroke", mesh={"h_contact": h_contact, "h_bulk": h_bulk,
                                      "cache": str(ROOT / "meshes")}, **extra)


def stroke(state, s, rtol):
    from sealts.core import Recorder

    from sealts.problem.stroke_problem import StrokeProblem
    s = replace(s, stroke=replace(s.stroke, rtol=rtol))
    t0 = time.perf_counter()
    step = StrokeProblem(state.model, state.u, s, state.load)
    U = step.start()
    rows = []

    def on_step(t, Ut):
        rows.append((t, step.motion.v(t), step.scalars(t, Ut)["friction_fluid"],
                     Ut[step.vdofs[1]]))

    U = step.run(U, s.stroke.t_end, s.stroke.dt, rtol, observers=[Recorder(on_step)])
    wall = time.perf_counter() - t0
    t, v, F, V = map(np.array, zip(*rows))
    out = float(np.sum(np.diff(V)[(v[1:] + v[:-1]) > 0]))
    c = step.problem.counters
    return {"rtol": rtol, "leak": float(U[step.vdofs[1]]), "out": out,
            "F_peak": float(np.abs(F).max()), "steps": c.steps, "rejected": c.rejected,
            "newton": c.newton, "wall": wall, "unknowns": step.n, "t": t, "F": F}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true", help="coarse mesh only, two tolerances")
    ap.add_argument("--viscoelastic", action="store_true", help="Table 2 Prony series")
    a = ap.parse_args()
    meshes = [(0.1, 0.4)] if a.quick else [(0.1, 0.4), (0.05, 0.2), (0.025, 0.2)]
    tols = [1e-2, 1e-3] if a.quick else [1e-2, 1e-3, 1e-4]
    from conftest import mount_and_pressurise
    results = {}
    for h in meshes:
        s = scene(*h, a.viscoelastic)
        state = mount_and_pressurise(s)
        results[h] = [stroke(state, s, r) for r in tols]
        r = results[h][-1]
        print(f"  {h[0]}/{h[1]} mm done: net leakage {r['leak']:.4g} mm^3 at rtol {r['rtol']:.0e}",
              flush=True)
    best = results[meshes[-1]][-1]        # the finest mesh at the tightest tolerance
    print(f"{'mesh':>10} {'unknowns':>8} {'rtol':>7} {'steps':>6} {'rej':>4} {'Newton':>6} "
          f"{'wall [s]':>8} {'leak [mm3]':>10} {'out [mm3]':>9} {'F_fluid [N]':>11} "
          f"{'err time':>8} {'err all':>8}")
    for h, runs in results.items():
        ref = runs[-1]
        for r in runs:
            r["err_time"] = abs(r["leak"] - ref["leak"]) / abs(ref["out"])
            r["err_all"] = abs(r["leak"] - best["leak"]) / abs(best["out"])
            print(f"{h[0]:>4}/{h[1]:<5} {r['unknowns']:8d} {r['rtol']:7.0e} {r['steps']:6d} "
                  f"{r['rejected']:4d} {r['newton']:6d} {r['wall']:8.2f} {r['leak']:10.4g} "
                  f"{r['out']:9.4g} {r['F_peak']:11.4g} {r['err_time']:8.1e} "
                  f"{r['err_all']:8.1e}")
    print("errors of the net leakage relative to the outstroke volume (the net leakage is a "
          "small difference of two large ones): 'time' against the tightest rtol on the same "
          "mesh, 'all' against the finest mesh at the tightest rtol")
    out = ROOT / "results"
    out.mkdir(exist_ok=True)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    for h, runs in results.items():
        for r in runs:
            ax[0].plot(r["t"], r["F"], label=f"{h[0]}/{h[1]} mm, rtol {r['rtol']:.0e}")
        keep = [r for r in runs if r is not best]
        ax[1].loglog([r["wall"] for r in keep], [r["err_all"] for r in keep], "o-",
                     label=f"{h[0]}/{h[1]} mm, rtol " + " / ".join(f"{r['rtol']:.0e}"
                                                              for r in keep))
    ax[0].set_xlabel("t [s]")
    ax[0].set_ylabel("fluid friction [N]")
    ax[0].legend(fontsize=7)
    ax[1].set_xlabel("stroke wall time [s]")
    ax[1].set_ylabel("error of the net leakage / outstroke volume")
    ax[1].legend()
    fig.tight_layout()
    fig.savefig(out / "bench_stroke.png", dpi=120)
    print(f"written: {out / 'bench_stroke.png'}")


if __name__ == "__main__":
    main()
