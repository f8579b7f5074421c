"""Stress matrix of the stroke: does every operating point finish, and if not, why and where?

Runs ``sealts run`` on variants of ``configs/oring_stroke.toml`` (the paper's O-ring, one
10 s sine cycle at 500 mm/s) one factor at a time, each in its own process with a time
limit, and prints one table row per case: finished, stopped with a physical cause
(extrusion, blow-by, a fold on the rod, a crease the refined mesh cannot carry:
``summary.json``'s "stopped" and its cause) or FAILED (a numerical or model failure), with
the step and the reason from ``summary.json``; accepted and rejected stroke steps, Newton
iterations and failed Newton solves (each retried with a smaller step), min h (um,
negative: the seal's mean plane past the rod's), the groove walls' largest penalty
penetration (um), net leakage, the film's balance (V_in - V_out minus the change of the
fluid the film holds, mm^3: what the film's storage M_i dh_i/dt leaves out, chiefly the
seal surface's axial motion, Eq. 21), peak friction, any NaN or Inf in the series, and
wall time (a case whose steps 1-2 read the same inputs as an earlier one's starts from the
state cache, sealts/steps/state_cache.py, so wall times compare within one table). ``--out
FILE`` also writes the table as Markdown with the machine's load. Usage:

    .venv/bin/python scripts/stress.py [--factors pressure,speed,...] [--mesh 0.05 0.2]
        [--timeout 900] [--out benchmarks/stress.md] [--list]

Factors (``--list`` prints the cases): ``pressure`` p_in 0, 1, 5, 10, 20, 30, 40 MPa;
``speed`` amplitudes 1, 100, 2000 mm/s; ``rough`` h_mix a tenth (a smoother rod; also on
the default scene's 0.025 / 0.2 mm sizes) and ten times the paper's; ``friction`` mu_s and groove.mu 0.05 and 0.5, no friction;
``rtol`` 1e-2 and 1e-4; ``velocity`` constant, ramp-hold and an abrupt start-stop-reverse
table; ``geometry`` planar and the rectangular Mooney-Rivlin ring; ``flow`` Patir-Cheng
flow factors with Rq 0.02, 0.215 and 2 um; ``mesh`` 0.1 / 0.4 and 0.025 / 0.2;
``scene_mesh`` 10, 20, 30, 35 and 40 MPa, and 30 MPa at 2000 mm/s, on the shipped scene's
0.025 / 0.2 mm sizes without its edges' refinement;
``ve_pressure`` 10, 20, 30, 35 and 40 MPa with the paper's Table 2 (viscoelastic), and
40 MPa on 0.025 / 0.2 mm;
``edge`` the shipped scene's mesh (0.025 / 0.2 mm, ``mesh.h_edge = 0.0015``) at 0-40 MPa,
1 and 2000 mm/s, 30 MPa at 2000 mm/s, the smooth rod, mu 0.5, the abrupt table, back
pressure and a clearance.
Every case runs on the sizes of ``--mesh`` (or its own) without ``mesh.h_edge`` unless it
sets h_edge (tests/conftest.coarsened): only the ``edge`` factor refines the edges.
``stabilisation`` 10 and 40 MPa and the smooth rod with stroke.stabilisation = 1e-3;
``clearance`` extrusion gaps of 0.02, 0.05 and 0.1 mm at 1, 5 and 10 MPa; ``back`` a back
pressure p_out (p_in = p_out = 1 MPa, 10 against 5 MPa, and 1 MPa on the atmosphere side
alone); ``hold`` the viscoelastic O-ring of ``configs/oring_hold.toml`` held 15 h at 5 and
at 20 MPa (a case's ``_base`` names another shipped scene); ``grid`` the operating map,
p_in 0, 1, 5, 10, 20, 30, 40 MPa x clearance 0 (the default) and 0.1 mm x amplitude 1,
100 and 2000 mm/s (42 cases).
Add a factor as one entry of FACTORS.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT), str(ROOT / "tests")]

# configs/rect_ring_mount.toml's ring (Mooney-Rivlin, 10 % squeeze, rounded groove corners),
# at room temperature, its rod-side corners rounded to 0.1 mm (with sharp corners a corner
# node off the rod side enters the rod once the ring tilts: the "sharp corners" case)
RECT_RING = {
    "seal": {"shape": "rectangle", "inner_diameter": 50.1, "height": 2.4, "width": 2.0,
             "corner_radius": 0.1},
    "rod": {"radius": 25.0},
    "groove": {"diameter": 54.3, "width": 2.6, "corner_radius": 0.2},
    "material": {"model": "mooney-rivlin", "c10": 0.8512, "c01": 0.2128, "d1": 0.001}}

# the "abrupt" velocity table (t s, v mm/s): out at 500 mm/s within 10 ms, stop, back
VELOCITY_TABLE = ("t,v\n0,0\n0.01,500\n2.49,500\n2.5,0\n3.0,0\n3.01,-500\n5.49,-500\n"
                  "5.5,0\n6.0,0\n")

FACTORS = {
    "pressure": [(f"p_in {p:g} MPa", {"fluid": {"p_in": float(p)}})
                 for p in (0, 1, 5, 10, 20, 30, 40)],
    "speed": [(f"v_max {v:g} mm/s", {"stroke": {"v_max": float(v)}}) for v in (1, 100, 2000)],
    "rough": [("h_mix 7e-5 mm (smooth rod)", {"asperity": {"h_mix": 7e-5}}),
              ("h_mix 7e-5 mm (smooth rod), mesh 0.025 / 0.2",
               {"asperity": {"h_mix": 7e-5}, "mesh": {"h_contact": 0.025}}),
              ("h_mix 7e-3 mm", {"asperity": {"h_mix": 7e-3}})],
    "friction": [("mu 0.05", {"asperity": {"mu_s": 0.05}, "groove": {"mu": 0.05}}),
                 ("mu 0.5", {"asperity": {"mu_s": 0.5}, "groove": {"mu": 0.5}}),
                 ("no friction", {"stroke": {"friction": False}})],
    "rtol": [("rtol 1e-2", {"stroke": {"rtol": 1e-2}}), ("rtol 1e-4", {"stroke": {"rtol": 1e-4}})],
    "velocity": [("constant 100 mm/s", {"stroke": {"velocity": "constant", "v_max": 100.0}}),
                 ("ramp-hold 500 mm/s", {"stroke": {"velocity": "ramp-hold", "t_ramp": 1.0,
                                                    "t_end": 5.0, "output_times": [2.5]}}),
                 ("abrupt start-stop-reverse table", {"stroke": {
                     "velocity": "table", "table": "velocity.csv", "t_end": 6.0,
                     "output_times": [1.0, 4.0]}})],
    "geometry": [("planar O-ring", {"seal": {"symmetry": "planar"}}),
                 ("rectangular MR ring", RECT_RING),
                 ("rectangular MR ring, sharp corners",
                  {**RECT_RING, "seal": {**RECT_RING["seal"], "corner_radius": 0.0}})],
    "flow": [(f"Patir-Cheng Rq {rq * 1e3:g} um", {"film": {"flow_factors": "patir-cheng",
                                                           "rq": rq}})
             for rq in (2e-5, 2.15e-4, 2e-3)],
    "stabilisation": [(f"{name} + stabilisation 1e-3", {**over, "stroke": {"stabilisation": 1e-3}})
                      for name, over in (("p_in 10 MPa", {"fluid": {"p_in": 10.0}}),
                                         ("p_in 40 MPa", {"fluid": {"p_in": 40.0}}),
                                         ("h_mix 7e-5 mm", {"asperity": {"h_mix": 7e-5}}))],
    "clearance": [(f"clearance {c:g} mm, p_in {p:g} MPa", {"groove": {"clearance": c},
                                                          "fluid": {"p_in": p}})
                  for c, p in ((0.1, 1.0), (0.1, 5.0), (0.02, 10.0), (0.05, 10.0),
                               (0.1, 10.0))],
    "back": [(f"p_in {a:g} / p_out {b:g} MPa", {"fluid": {"p_in": a, "p_out": b}})
             for a, b in ((1.0, 1.0), (10.0, 5.0), (0.0, 1.0))],
    "hold": [(f"15 h hold at {p:g} MPa (viscoelastic)",
              {"_base": "oring_hold", "hold": {"p_end": p, "t_end": 54000.0}})
             for p in (5.0, 20.0)],
    "mesh": [("mesh 0.1 / 0.4", {"mesh": {"h_contact": 0.1, "h_bulk": 0.4}}),
             ("mesh 0.025 / 0.2", {"mesh": {"h_contact": 0.025, "h_bulk": 0.2}})],
    # the high pressures on the shipped scene's sizes without its edges' refinement (the
    # shipped mesh until 2026-12-05; the 'edge' factor is the shipped mesh)
    "scene_mesh": [(f"p_in {p:g} MPa{a}, mesh 0.025 / 0.2",
                    {"fluid": {"p_in": float(p)}, "mesh": {"h_contact": 0.025},
                     "stroke": {"v_max": float(v)}})
                   for p, v, a in ((10, 500, ""), (20, 500, ""), (30, 500, ""), (35, 500, ""),
                                   (40, 500, ""),
                                   (30, 2000, ", v_max 2000 mm/s"))],
    # the shipped scene's mesh: mesh.h_edge = 0.0015 on 0.025 / 0.2 (the setting within
    # issue 17's accuracy bounds) across the factors
    "edge": [(f"h_edge 0.0015, {name}",
              {**over, "mesh": {"h_contact": 0.025, "h_edge": 0.0015}})
             for name, over in [(f"p_in {p:g} MPa", {"fluid": {"p_in": float(p)}})
                                for p in (0, 1, 5, 10, 20, 30, 35, 40)]
             + [(f"v_max {v:g} mm/s", {"stroke": {"v_max": float(v)}}) for v in (1, 2000)]
             + [("p_in 30 MPa, v_max 2000 mm/s", {"fluid": {"p_in": 30.0},
                                                  "stroke": {"v_max": 2000.0}}),
                ("h_mix 7e-5 mm (smooth rod)", {"asperity": {"h_mix": 7e-5}}),
                ("mu 0.5", {"asperity": {"mu_s": 0.5}, "groove": {"mu": 0.5}}),
                ("abrupt start-stop-reverse table", {"stroke": {
                    "velocity": "table", "table": "velocity.csv", "t_end": 6.0,
                    "output_times": [1.0, 4.0]}}),
                ("p_in 10 / p_out 5 MPa", {"fluid": {"p_in": 10.0, "p_out": 5.0}}),
                ("clearance 0.1 mm, p_in 5 MPa", {"groove": {"clearance": 0.1},
                                                  "fluid": {"p_in": 5.0}})]],
    # the high pressures with the rubber's rate-dependent stiffness (the paper's Table 2, as
    # configs/paper_fig14_ve.toml): the long-term material's surface buckles under the
    # rod's friction from 35 MPa (README, "Operating limits")
    "ve_pressure": [(f"viscoelastic, p_in {p:g} MPa{a}",
                     {"fluid": {"p_in": float(p)}, "mesh": m,
                      "viscoelastic": {"prony": "table2", "temperature": 25.0,
                                       "t_min": 1e-3, "tol": 1e-2}})
                    for p, m, a in [(p, {}, "") for p in (10, 20, 30, 35, 40)]
                    + [(40, {"h_contact": 0.025}, ", mesh 0.025 / 0.2")]],
    # the operating map: sealed pressure x extrusion gap (none, the default, and 0.1 mm) x
    # the sine's amplitude
    "grid": [(f"p_in {p:g} MPa, clearance {c:g} mm, v_max {v:g} mm/s",
              {"fluid": {"p_in": float(p)}, "groove": {"clearance": c},
               "stroke": {"v_max": float(v)}})
             for c in (0.0, 0.1) for v in (1, 100, 2000) for p in (0, 1, 5, 10, 20, 30, 40)],
}


def case_text(overrides, mesh):
    """The scene file of one case: configs/oring_stroke.toml with the mesh, quiet output and
    the case's keys set (tests/conftest.config_text, which edits by key)."""
    from conftest import config_text
    sections = {"mesh": {"h_contact": mesh[0], "h_bulk": mesh[1], "cache": str(ROOT / "meshes")},
                "output": {"plot": False, "progress": False}}
    overrides = dict(overrides)
    base = overrides.pop("_base", "oring_stroke")
    for sec, values in overrides.items():
        sections.setdefault(sec, {}).update(values)
    return config_text(base, **sections)


def series_stats(path):
    """(min h in um, any non-finite value) of a series.csv."""
    if not path.exists():
        return math.nan, False
    h_min, bad = math.inf, False
    with open(path) as f:
        for row in csv.DictReader(f):
            vals = [float(x) for x in row.values() if x not in ("", None)]
            bad |= not all(math.isfinite(x) for x in vals)
            if "h_min" in row:
                h_min = min(h_min, float(row["h_min"]) * 1e3)
    return h_min, bad


def _last_row(path):
    """The last row of a series.csv as floats ({} without one)."""
    if not path.exists():
        return {}
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: float(v) for k, v in rows[-1].items() if v not in ("", None)} if rows else {}


def run_case(name, overrides, mesh, timeout, work):
    d = work / "".join(c if c.isalnum() else "_" for c in name)
    d.mkdir(parents=True, exist_ok=True)
    scene = d / "scene.toml"
    scene.write_text(case_text(overrides, mesh))
    (d / "velocity.csv").write_text(VELOCITY_TABLE)
    t0 = time.perf_counter()
    # SIGTERM at the time limit: the run closes its files and says where it got to
    p = subprocess.Popen([sys.executable, "-m", "sealts", "run", str(scene), "-o", str(d / "out")],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT)
    try:
        _, stderr = p.communicate(timeout=timeout)
        rc, err = p.returncode, stderr.strip().splitlines()[-1:] or [""]
    except subprocess.TimeoutExpired:
        p.terminate()
        p.communicate()
        rc, err = None, [f"time limit {timeout:g} s"]
    wall = time.perf_counter() - t0
    summ = d / "out" / "summary.json"
    s = json.loads(summ.read_text()) if summ.exists() else {}
    # a physical stop (extrusion, blow-by, a fold) is a result; anything else not finished
    # is a failure
    status = ("finished" if rc == 0 else f"stopped: {s['cause']}"
              if rc is not None and s.get("status") == "stopped" else "FAILED")
    row = {"case": name, "status": status, "wall s": wall}
    st = s.get("stroke", s.get("hold", {}))
    if rc is None:       # stopped at the time limit: how far, and at what pace
        last = _last_row(d / "out" / "series.csv")
        row["why"] = (f"time limit {timeout:g} s at t = {last.get('t', math.nan):.6g} s, "
                      f"steps of {last.get('dt', math.nan):.2g} s" if last else err[0])
    elif rc != 0:
        row["why"] = s.get("error", err[0])[:320]
    elif st.get("snapped_at") is not None:
        row["why"] = (f"snapped at t = {st['snapped_at']:.4g} s; snap stabilisation from the "
                      f"last stop, t = {st.get('snap_stabilised_from', 0.0):.4g} s")
    pen, bal = st.get("wall_penetration"), st.get("film_balance")
    row.update({"accepted": st.get("steps_accepted", ""), "rejected": st.get("steps_rejected", ""),
                "Newton": st.get("newton_iterations", ""),
                "failed Newton": st.get("newton_failures", ""),
                "wall pen. um": pen * 1e3 if pen is not None else "",
                "film balance mm^3": bal if bal is not None else "",
                "net mm^3": st.get("leakage_out", ""),
                "F out / in N": (f"{st['peak_friction_outstroke']:.4g} / "
                                 f"{st['peak_friction_instroke']:.4g}")
                if "peak_friction_outstroke" in st else ""})
    h_min, bad = series_stats(d / "out" / "series.csv")
    row["min h um"], row["NaN/Inf"] = h_min, "yes" if bad else "no"
    return row


COLS = ["case", "status", "accepted", "rejected", "Newton", "failed Newton", "min h um",
        "wall pen. um", "net mm^3", "film balance mm^3", "F out / in N", "NaN/Inf", "wall s",
        "why"]


def fmt(v):
    if isinstance(v, float):
        return "" if math.isnan(v) else f"{v:.4g}"
    return str(v)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--factors", default="pressure")
    ap.add_argument("--mesh", nargs=2, type=float, default=(0.05, 0.2),
                    metavar=("H_CONTACT", "H_BULK"))
    ap.add_argument("--timeout", type=float, default=900.0, help="per case, s")
    ap.add_argument("--out", help="also write the table (Markdown) to this file")
    ap.add_argument("--work", default=str(ROOT / "results" / "stress"))
    ap.add_argument("--list", action="store_true")
    args = ap.parse_args()
    unknown = [f for f in args.factors.split(",") if f not in FACTORS]
    if unknown:
        sys.exit(f"stress.py: unknown factor {unknown[0]!r} (one of {', '.join(FACTORS)})")
    cases = [c for f in args.factors.split(",") for c in FACTORS[f]]
    if args.list:
        for name, over in cases:
            print(f"{name:<32} {over}")
        return
    print(" | ".join(COLS))
    rows = []
    for name, over in cases:
        row = run_case(name, over, args.mesh, args.timeout, Path(args.work))
        rows.append(row)
        print(" | ".join(fmt(row.get(c, "")) for c in COLS), flush=True)
    if args.out:
        load = os.getloadavg()
        head = (f"# Stress matrix (scripts/stress.py --factors {args.factors})\n\n"
                f"The paper's O-ring cycle (configs/oring_stroke.toml) on the {args.mesh[0]:g} / "
                f"{args.mesh[1]:g} mm mesh, one factor changed per row; measured "
                f"{time.strftime('%Y-%m-%d')}, load average {load[0]:.2f} at the end.\n\n")
        table = ["| " + " | ".join(COLS) + " |", "|" + "---|" * len(COLS)]
        table += ["| " + " | ".join(fmt(r.get(c, "")) for c in COLS) + " |" for r in rows]
        Path(args.out).write_text(head + "\n".join(table) + "\n")


if __name__ == "__main__":
    main()
