"""How the stroke's answer moves with things that should not move it: rtol changed by one part
in a million, the physics terms summed in another order, the output stops, the initial dt;
with and without solid friction. The measurement that issue 15 (an accurate stroke) starts
from and is judged by.

Steps 1-2 (mount, pressurise to 1 MPa) run once; each variant then runs the stroke of
``configs/oring_stroke.toml`` (the paper's 10 s cycle at 500 mm/s) from the same state.
Prints a table: net leakage (mm^3), transport per direction (mm^3), friction work (N mm),
peak friction per direction (N), accepted / rejected steps, Newton iterations, wall time (s),
and the spread of each family against its base. Usage:

    .venv/bin/python scripts/stroke_sensitivity.py [--mesh 0.1 0.4] [--rtol 1e-3]
        [--variants base,rtol,order,stops,dt,sweep] [--no-friction-too | --no-friction] [--petsc '-opt value']
        [--set stroke.friction_history=state ...]

``sweep``: rtol 1e-2, 1e-3, 1e-4, 1e-5 (its spread is then the distance from the first).
The mesh is ``--mesh``'s sizes without the shipped scene's refinement at the contact's edges
(tests/conftest.coarsened); ``--set mesh.h_edge=0.0015`` refines them as the scene does.
"""
import argparse
import sys
import time
from dataclasses import replace
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT), str(ROOT / "tests")]

KEYS = [("leakage_out", "net mm^3", "{:.5f}"), ("outstroke_transport", "out mm^3", "{:.4f}"),
        ("instroke_transport", "in mm^3", "{:.4f}"), ("friction_work", "work N mm", "{:.1f}"),
        ("peak_friction_outstroke", "F out N", "{:.4f}"),
        ("peak_friction_instroke", "F in N", "{:.4f}")]


def variants(s, rtol, which):
    """(name, scene, reversed term order) per variant."""
    st = s.stroke
    out = []
    if "base" in which:
        out.append(("base", replace(s, stroke=replace(st, rtol=rtol)), False))
    if "rtol" in which:
        out.append(("rtol x (1 + 1e-6)", replace(s, stroke=replace(st, rtol=rtol * (1 + 1e-6))),
                    False))
    if "order" in which:
        out.append(("terms reversed", replace(s, stroke=replace(st, rtol=rtol)), True))
    if "stops" in which:
        out.append(("no output stops", replace(s, stroke=replace(st, rtol=rtol,
                                                                  output_times=[])), False))
    if "sweep" in which:
        out += [(f"rtol {r:g}", replace(s, stroke=replace(st, rtol=r)), False)
                for r in (1e-2, 1e-3, 1e-4, 1e-5)]
    if "dt" in which:
        out.append(("initial dt x 2", replace(s, stroke=replace(st, rtol=rtol, dt=2 * st.dt)),
                    False))
    return out


def run(state, s, reverse):
    from sealts.problem import stroke_problem
    from sealts.steps.stroke import Stroke
    terms = stroke_problem.StrokeProblem._terms
    if reverse:
        stroke_problem.StrokeProblem._terms = lambda self, *a, **k: terms(self, *a, **k)[::-1]
    try:
        st = replace(state.fork(), scene=s)
        t0 = time.perf_counter()
        Stroke().run(st)
        part = st.parts["stroke"]
        part["wall"] = time.perf_counter() - t0
        return part
    finally:
        stroke_problem.StrokeProblem._terms = terms


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--mesh", nargs=2, type=float, default=(0.1, 0.4),
                    metavar=("H_CONTACT", "H_BULK"))
    ap.add_argument("--rtol", type=float, default=1e-3)
    ap.add_argument("--variants", default="base,rtol,order,stops,dt")
    ap.add_argument("--no-friction-too", action="store_true",
                    help="repeat every variant with stroke.friction = false")
    ap.add_argument("--no-friction", action="store_true",
                    help="only stroke.friction = false")
    ap.add_argument("--set", action="append", default=[], metavar="SECTION.KEY=VALUE",
                    help="a scene key for every variant, e.g. stroke.friction_history=state")
    ap.add_argument("--petsc", default="",
                    help="PETSc options for every stroke, e.g. '-stroke_ts_adapt_wnormtype "
                         "infinity'")
    args = ap.parse_args()
    import petsc4py
    petsc4py.init(["stroke_sensitivity"] + args.petsc.split())
    from conftest import scene as load
    from sealts.steps import prepare
    s = load("oring_stroke", mesh={"h_contact": args.mesh[0], "h_bulk": args.mesh[1],
                                   "cache": str(ROOT / "meshes")},
             output={"progress": False})
    for kv in args.set:
        dotted, value = kv.split("=", 1)
        section, key = dotted.split(".")
        part = getattr(s, section)
        value = type(getattr(part, key))(value)
        s = replace(s, **{section: replace(part, **{key: value})})
    state = prepare(s)
    which = args.variants.split(",")
    dry = ("no friction: ", replace(s, stroke=replace(s.stroke, friction=False)))
    cases = ([dry] if args.no_friction else
             [("", s)] + ([dry] if args.no_friction_too else []))
    head = " ".join(f"{h:>12}" for _, h, _ in KEYS)
    print(f"mesh {args.mesh[0]} / {args.mesh[1]} mm, rtol {args.rtol:g} {args.petsc} "
          f"{' '.join(args.set)}")
    print(f"{'variant':<34}{head} {'acc':>5} {'rej':>4} {'Newton':>6} {'wall s':>7}")
    for prefix, base in cases:
        rows = []
        for name, sc, rev in variants(base, args.rtol, which):
            p = run(state, sc, rev)
            rows.append(p)
            vals = " ".join(f"{fmt.format(p[k]):>12}" for k, _, fmt in KEYS)
            print(f"{prefix + name:<34}{vals} {p['steps_accepted']:>5} "
                  f"{p['steps_rejected']:>4} {p['newton_iterations']:>6} {p['wall']:>7.1f}",
                  flush=True)
        b = rows[0]
        spread = " ".join(
            f"{100 * max(abs(r[k] - b[k]) for r in rows) / max(abs(b[k]), 1e-300):>11.3f}%"
            for k, _, _ in KEYS)
        print(f"{prefix + 'largest change from base':<34}{spread}")


if __name__ == "__main__":
    main()
