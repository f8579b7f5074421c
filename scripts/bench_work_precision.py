"""Run time against error: the paper's O-ring cycle around its defaults, and the slider
against its closed form (issue 17).

Every O-ring setting is one ``sealts run`` process, timed whole as a user meets it (numba's
cache warm, the mesh cached, nothing of steps 1-2 reused), one after another, nothing else
of sealts running beside. The defaults are ``configs/oring_stroke.toml`` (0.025 / 0.2 mm
mesh refined to ``mesh.h_edge`` = 0.0015 mm at the pressurised contact's edges, the film's
inlets; BDF 2, stroke rtol 1e-2, fv film, PETSc's LU with AMD ordering below 10,000 unknowns
and UMFPACK above, sealts/problem/problem.py); each family changes one factor:

* ``rtol``: the stroke's TS tolerance (``-stroke_ts_rtol``) 1e-2, 1e-3, 1e-4;
* ``edge``: the default meshed with grading distances 0.4, 0.45, 0.55, 0.6 mm
  (``mesh.grading_distance``, 0.5 by default): the same resolution with the nodes
  elsewhere. The report gives the spread of the errors over these meshes and the
  default's, which is the default's accuracy; one row alone is one draw from it;
* ``mesh``: without ``mesh.h_edge`` (``h_edge = 0``), contact / bulk element size 0.1 /
  0.4, 0.05 / 0.2, 0.025 / 0.2 (the default before 2026-12-05), 0.02 / 0.2, 0.0175 / 0.2,
  0.0125 / 0.2, 0.0125 / 0.1 mm (also the cost growth: wall time against unknowns, fitted
  exponent);
* ``layer``: without ``mesh.h_edge``, contact sizes 0.025, 0.02, 0.0175, 0.0125 mm kept to
  0.1 mm beneath the rod side (``mesh.layer_depth``), bulk 0.2 mm;
* ``placement``: without ``mesh.h_edge``, 0.025 / 0.2 mm meshed with the grading distances
  of ``edge`` and mirror-symmetric (``mesh.symmetric``), and 0.0125 / 0.1 mm with 0.45 and
  0.55;
* ``bdf``: the BDF order 1, 3 (the stroke's default 2026-12-03 to 05) and 4 against
  sealts' 2, PETSc's default (``-stroke_ts_bdf_order``);
* ``reuse``: the stroke's Jacobian (and its factorisation) reused for a second Newton
  iteration (``-stroke_snes_lag_jacobian 2``);
* ``theta``: Crank-Nicolson (``-stroke_ts_type theta -stroke_ts_theta_theta 0.5
  -stroke_ts_theta_endpoint``);
* ``film``: the paper's film scheme (``film.scheme = "paper"``);
* ``lu``: UMFPACK in place of PETSc's own LU (``-pc_factor_mat_solver_type umfpack`` for
  steps 1-2, the stroke's start and the stroke, LU_UMFPACK: all but the small transfer_ and
  stroke_film_ solves; the default until 2026-12-04);
* ``cache``: the default with the pressurised-state cache warm (sealts/steps/state_cache.py;
  every other row runs steps 1-2, ``[start] cache = false``);
* (the defaults until 2026-12-03, BDF 2 with stroke rtol 1e-3, are the ``rtol`` family's
  1e-3 row since BDF 2 is the default again);
* ``targets``: ``configs/paper_fig14_ve_sq_ff.toml`` (viscoelastic, squeeze, flow factors;
  timed, its leakage not compared; on the cycle's refined mesh, ``mesh.h_edge``, since
  2026-12-05, 2.5 times the Prony variables of the rows before) and the paper's mesh (0.01 / 0.05 mm, without
  ``mesh.h_edge``) at the defaults;
* ``prony``: the Prony series' pruning tolerance (``viscoelastic.tol``, the relaxation
  modulus' error from the terms folded as relaxed or frozen) of
  ``paper_fig14_ve_sq_ff`` at 1e-1 and 1e-3 against its 1e-2 (the ``targets`` row; its
  net leakage compared with theirs, there being no overkill reference of this scene);
* ``plain``: the default again without -log_view (every other row pays the log's own
  time; the 10 s target is judged on this row).

ARKIMEX and ROSW are not in the list: the DAE has no explicit part to split off (F(t, U,
U') = 0 with a singular mass matrix: the film pressures and the quasi-static seal carry no
U'), so they would run as fully implicit methods with stage counts of 3-4 per step.

Errors are against an overkill reference, the paper's mesh (0.01 / 0.05 mm, without
``mesh.h_edge``, about 30,300 unknowns) at stroke rtol 1e-4, meshed with three grading distances (REF_GRADINGS: the
same sizes with the nodes elsewhere move its net leakage by 1.6 %), their mean computed once
with ``--reference`` and kept in ``benchmarks/work_precision_reference.json`` with each
placement's values and their spread (its mean film profile at t = 2.5 s beside it as
CSV): net leakage, outstroke and instroke transports, friction work, peak friction per
direction (relative), and the mid-outstroke film (t = 2.5 s): the larger relative error of
its minimum and of its mean over the reference's contact (h_ref below three times its min).

Per run, from ``summary.json`` and ``-log_view``: unknowns, accepted and rejected steps,
Newton and linear iterations (all steps), the whole process's wall time, the stroke's, and
the process's time in LU factorisation, residuals, Jacobians and triangular solves (the rest
is Python, output and start-up), peak memory (the child's max RSS).

The slider (configs/slider.toml, the closed form of Eq. 43): the steady film's time and
max pressure error per scheme and element count, as ``scripts/bench_film.py`` measures it.

Writes benchmarks/work_precision.md (tables, machine, date, load), .csv and .png (wall time
against the net leakage's error per family; wall time against unknowns). Usage:

    .venv/bin/python scripts/bench_work_precision.py            # about 55 min here
    .venv/bin/python scripts/bench_work_precision.py --quick    # rtol and mesh, ~8 min
    .venv/bin/python scripts/bench_work_precision.py --families mesh,layer   # some families
    .venv/bin/python scripts/bench_work_precision.py --reference   # the reference, once
    .venv/bin/python scripts/bench_work_precision.py --from-csv    # report again, no runs
    .venv/bin/python scripts/bench_work_precision.py --add placement   # run a family again
    .venv/bin/python scripts/bench_work_precision.py --add default,rtol # (and the default)
"""
import argparse
import csv
import json
import os
import platform
import re
import subprocess
import sys
import time
from datetime import datetime, timezone
from pathlib import Path

import tomllib

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
from sealts.io.results import read_profiles  # noqa: E402
from sealts.problem.problem import PETSC_LU_BELOW  # noqa: E402
OUT = ROOT / "benchmarks"
REFERENCE = OUT / "work_precision_reference.json"
REF_PROFILE = OUT / "work_precision_reference_profile.csv"
SLIDER = OUT / "work_precision_slider.csv"
# notes on the last measurement, written by hand, which the report includes
NOTES = OUT / "work_precision_notes.md"
SEALTS = [sys.executable, "-m", "sealts", "run"]
LIMIT = 900.0             # s, a run's time limit (SIGTERM: sealts writes its summary)
# Crank-Nicolson crawls from t = 0.017 s on (it ran into the 900 s limit on 2026-12-03),
# and the stroke with its Jacobian reused once from t = 0.01 s (stopped by the crawl guard
# after 754 s on 2026-12-05): two minutes show it
LIMITS = {"theta": 120.0, "reuse": 120.0}
T_PROFILE = 2.5           # s, mid-outstroke (v = v_max)
# the reference's placements: the same element sizes meshed with these grading distances
# (mesh.grading_distance) put the nodes elsewhere and move the net leakage by about 2 %
# (README, "Where gmsh puts the nodes"); the reference is their mean
REF_GRADINGS = (0.45, 0.5, 0.55)
REF_LIMIT = 4000.0        # s, one reference run's time limit
LU_UMFPACK = [f"-{p}pc_factor_mat_solver_type" for p in ("", "stroke_", "static_", "stroke_start_")]
# every residual and Jacobian goes through SNES (TS's own events are nested inside these)
EVENTS = {"MatLUFactorNum": "lu", "MatLUFactorSym": "lu", "MatSolve": "solve",
          "SNESFunctionEval": "residual", "SNESJacobianEval": "jacobian"}
# rows of another scene than the reference's: timed, not compared
OTHER_SCENES = ("paper_fig14_ve_sq_ff",)
TARGETS = {"default": 10.0, "paper_fig14_ve_sq_ff": 20.0, "paper mesh": 120.0}   # s
# the 'placement' family: the default's element sizes, meshed with these grading distances
# (mm; the default 0.5) and mirror-symmetric: the same resolution, nodes placed elsewhere
PLACEMENT_GRADINGS = (0.4, 0.45, 0.55, 0.6)
# the default's mesh.h_edge (mm); the 'edge' family meshes the default at PLACEMENT_GRADINGS
EDGE_H = tomllib.loads((ROOT / "configs" / "oring_stroke.toml").read_text())["mesh"]["h_edge"]
DEFAULT = f"0.025 / 0.2 mm, h_edge {EDGE_H:g} mm"      # the default row's mesh (its label)
BOUNDS = {"e_net": 2e-2, "e_transport": 1e-2, "e_work": 1e-2, "e_peak": 1e-2}


def scene_text(mesh=None, name=None, film_scheme=None, base="oring_stroke.toml",
               state_cache=False, layer=None, grading=None, symmetric=False, h_edge=None,
               edits=()):
    """The default scene's text with the mesh sizes (contact, bulk), name or film scheme
    replaced, ``layer`` the mesh's layer_depth (mm), ``grading`` its grading_distance (mm),
    ``symmetric`` its mirror-symmetric variant, ``h_edge`` its mesh.h_edge (mm; 0: the
    scene's mesh alone), ``edits`` (pattern, replacement) pairs each replacing one line;
    without ``state_cache`` steps 1-2 run in full (``[start] cache = false``)."""
    s = (ROOT / "configs" / base).read_text()
    for pattern, new in edits:
        s, k = re.subn(pattern, new, s, flags=re.M)
        if k != 1:
            raise ValueError(f"{base}: {pattern!r} matches {k} lines, not one")
    if grading is not None:
        if re.search(r"(?m)^grading_distance = ", s):
            s = re.sub(r"(?m)^grading_distance = [0-9.e-]+", f"grading_distance = {grading}", s)
        else:
            s = s.replace("[mesh]\n", f"[mesh]\ngrading_distance = {grading}\n", 1)
    if symmetric:
        s = re.sub(r"(?m)^symmetric = false", "symmetric = true", s)
    if h_edge is not None:
        s = re.sub(r"(?m)^h_edge = [0-9.e-]+", f"h_edge = {h_edge}", s)
    if not state_cache:
        s += "\n[start]\ncache = false\n"
    if mesh is not None:
        s = re.sub(r"(?m)^h_contact = [0-9.e-]+", f"h_contact = {mesh[0]}", s)
        s = re.sub(r"(?m)^h_bulk = [0-9.e-]+", f"h_bulk = {mesh[1]}", s)
    if layer is not None:
        s = re.sub(r"(?m)^layer_depth = [0-9.e-]+", f"layer_depth = {layer}", s)
    if name is not None:
        s = re.sub(r'(?m)^name = "[^"]*"', f'name = "{name}"', s)
    if film_scheme is not None:
        s = s.replace("[film]\n", f'[film]\nscheme = "{film_scheme}"\n', 1)
    return s


def settings(quick):
    """(family, label, scene text, PETSc options)."""
    d = scene_text()
    out = [("rtol", f"rtol {r:.0e}", d, ["-stroke_ts_rtol", f"{r:g}"])
           for r in (1e-2, 1e-3, 1e-4)]
    # the scene's mesh alone (h_edge 0): labels without "h_edge"
    out += [("mesh", f"{m[0]:g} / {m[1]:g} mm", scene_text(m, h_edge=0.0), [])
            for m in ((0.1, 0.4), (0.05, 0.2), (0.025, 0.2), (0.02, 0.2), (0.0175, 0.2),
                      (0.0125, 0.2), (0.0125, 0.1))]
    if quick:
        return out
    out += [("edge", f"{DEFAULT}, grading {g:g} mm", scene_text(grading=g), [])
            for g in PLACEMENT_GRADINGS]
    out += [("layer", f"{c:g} / 0.2 mm, layer 0.1 mm", scene_text((c, 0.2), layer=0.1,
                                                                  h_edge=0.0), [])
            for c in (0.025, 0.02, 0.0175, 0.0125)]
    out += [("placement", f"0.025 / 0.2 mm, grading {g:g} mm",
             scene_text(grading=g, h_edge=0.0), []) for g in PLACEMENT_GRADINGS]
    out += [("placement", "0.025 / 0.2 mm, mirror-symmetric",
             scene_text(symmetric=True, h_edge=0.0), [])]
    out += [("placement", f"0.0125 / 0.1 mm, grading {g:g} mm",
             scene_text((0.0125, 0.1), grading=g, h_edge=0.0), []) for g in (0.45, 0.55)]
    out += [("bdf", f"BDF {k}", d, ["-stroke_ts_bdf_order", str(k)]) for k in (1, 3, 4)]
    out += [("reuse", "Jacobian reused once", d, ["-stroke_snes_lag_jacobian", "2"])]
    out += [("theta", "Crank-Nicolson", d, ["-stroke_ts_type", "theta",
                                            "-stroke_ts_theta_theta", "0.5",
                                            "-stroke_ts_theta_endpoint"])]
    out += [("film", "paper scheme", scene_text(film_scheme="paper"), [])]
    lu = []
    for o in LU_UMFPACK:
        lu += [o, "umfpack"]
    out += [("lu", "UMFPACK", d, lu)]
    cached = scene_text(state_cache=True).replace("[mesh]\n", '[mesh]\ncache = "{cache}"\n', 1)
    out += [("cache", "state cache warm", cached, [])]
    out += [("targets", "paper_fig14_ve_sq_ff", scene_text(base="paper_fig14_ve_sq_ff.toml"),
             []),
            ("targets", "paper mesh", scene_text((0.01, 0.05), h_edge=0.0), [])]
    out += [("prony", f"paper_fig14_ve_sq_ff, Prony tol {tol:.0e}",
             scene_text(base="paper_fig14_ve_sq_ff.toml", edits=[(r"^tol = [0-9.e-]+",
                                                                  f"tol = {tol:g}")]), [])
            for tol in (1e-1, 1e-3)]
    out += [("plain", "default without -log_view", d, [])]
    return out


def log_view(path):
    """Seconds per group of EVENTS and the total, from a -log_view ASCII file."""
    t = {"lu": 0.0, "solve": 0.0, "residual": 0.0, "jacobian": 0.0, "total": np.nan}
    if not path.exists():
        return t
    for line in path.read_text().splitlines():
        w = line.split()
        if len(w) > 3 and w[0] in EVENTS:
            t[EVENTS[w[0]]] += float(w[3])
        elif line.startswith("Time (sec):") and len(w) > 2:
            t["total"] = float(w[2])
    return t


def run(label, text, opts, work, log=True, limit=LIMIT):
    """One `sealts run` of the scene text: its summary, timings and memory (``log``: with
    -log_view's split), stopped after ``limit`` seconds."""
    work.mkdir(parents=True, exist_ok=True)
    scene = work / "scene.toml"
    scene.write_text(text)
    out = work / "out"
    logf = work / "log_view.txt"
    cmd = SEALTS + [str(scene), "-o", str(out), *opts] + (["-log_view", f":{logf}"] if log
                                                          else [])
    t0 = time.perf_counter()
    with open(work / "stdout.txt", "w") as so:
        p = subprocess.Popen(cmd, cwd=ROOT, stdout=so, stderr=subprocess.STDOUT)
        stopped = False
        while True:      # os.wait4: the child's own peak memory, which Popen.wait drops
            pid, status, ru = os.wait4(p.pid, os.WNOHANG)
            if pid:
                p.returncode = os.waitstatus_to_exitcode(status)
                break
            if not stopped and time.perf_counter() - t0 > limit:
                p.terminate()
                stopped = True
            time.sleep(0.05)
    wall = time.perf_counter() - t0
    rss = ru.ru_maxrss / 1024.0
    r = {"label": label, "wall": wall, "rss_mb": rss, "status": "no summary"}
    try:
        s = json.loads((out / "summary.json").read_text())
    except (OSError, ValueError):
        return r
    st = s.get("stroke", {})
    r.update(status=s.get("status", "?"), unknowns=st.get("unknowns", s.get("unknowns")),
             steps=s.get("steps_accepted"), rejected=s.get("steps_rejected"),
             newton=s.get("newton_iterations"), linear=s.get("linear_iterations"),
             stroke_wall=st.get("wall_time_s"), net=st.get("leakage_out"),
             out=st.get("outstroke_transport"), inn=st.get("instroke_transport"),
             work=st.get("friction_work"), peak_out=st.get("peak_friction_outstroke"),
             peak_in=st.get("peak_friction_instroke"), h_min=st.get("h_min"),
             error=s.get("error"))
    r.update(log_view(logf))
    r["profile"] = profile(out / "stroke_profiles.csv")
    return r


def profile(path, t=T_PROFILE):
    """(y, h) of the stroke's film profile at time t (mm), sorted by y, or None."""
    try:
        block = read_profiles(path, sort_by="y").get(t)
    except OSError:
        return None
    return None if block is None else np.column_stack([block["y"], block["h"]])


def errors(r, ref, ref_prof):
    """Relative errors of r against the reference (None where r has no value)."""
    if r.get("net") is None or r["label"].split(",")[0] in OTHER_SCENES:
        return {}
    rel = lambda a, b: abs(a - b) / abs(b)                              # noqa: E731
    e = {"e_net": rel(r["net"], ref["net"]),
         "e_transport": max(rel(r["out"], ref["out"]), rel(r["inn"], ref["inn"])),
         "e_work": rel(r["work"], ref["work"]),
         "e_peak": max(rel(r["peak_out"], ref["peak_out"]), rel(r["peak_in"], ref["peak_in"])),
         "e_hmin": rel(r["h_min"], ref["h_min"])}
    p = r.get("profile")
    if p is not None and ref_prof is not None:
        e["e_profile"] = film_error(p, ref_prof)
    return e


def film_error(p, ref_prof):
    """The mid-outstroke film against the reference's: the larger relative error of its
    minimum and of its mean over the reference's contact (where h_ref is below three times
    its minimum; the run's profile interpolated there). Node by node the steep flanks at
    the contact's ends differ by the meshes' spacing, not by the film."""
    y, h = ref_prof[:, 0], ref_prof[:, 1]
    zone = h <= 3.0 * h.min()
    hi = np.interp(y[zone], p[:, 0], p[:, 1])          # p sorted by y (profile)
    return float(max(abs(p[:, 1].min() - h.min()) / h.min(),
                     abs(hi.mean() - h[zone].mean()) / h[zone].mean()))


def slider_rows():
    sys.path.insert(0, str(ROOT / "scripts"))
    from bench_film import run as film_run
    rows = []
    for n in (50, 200, 1000, 4000):
        for scheme in ("fv", "paper"):
            t, err, newton = film_run(scheme, n, 3)
            rows.append({"scheme": scheme, "elements": n, "time_ms": 1e3 * t, "error": err,
                         "newton": newton})
    return rows


def machine():
    load = os.getloadavg()
    return (f"{platform.node()}, {os.cpu_count()} cores, Python "
            f"{platform.python_version()}, load average {load[0]:.2f} / {load[1]:.2f} / "
            f"{load[2]:.2f} at the start")


def fmt(x, f="{:.3g}"):
    return "" if x is None or (isinstance(x, float) and np.isnan(x)) else f.format(x)


def table(rows):
    head = ("| family | setting | status | unknowns | steps (rejected) | Newton | wall s | "
            "stroke s | LU s | residual s | Jacobian s | solve s | other s | MB | net mm^3 | "
            "err net | err transports | err work | err peak | err min h | err film |")
    lines = [head, "|" + "---|" * (head.count("|") - 1)]
    for r in rows:
        other = r.get("total", np.nan) - sum(r.get(k, 0.0) for k in
                                            ("lu", "residual", "jacobian", "solve"))
        lines.append(
            f"| {r['family']} | {r['label']} | {r['status']} | {fmt(r.get('unknowns'), '{:,}')} | "
            f"{fmt(r.get('steps'), '{:,}')} ({fmt(r.get('rejected'), '{:,}')}) | "
            f"{fmt(r.get('newton'), '{:,}')} | {r['wall']:.1f} | {fmt(r.get('stroke_wall'), '{:.1f}')} | "
            f"{fmt(r.get('lu'), '{:.1f}')} | {fmt(r.get('residual'), '{:.1f}')} | "
            f"{fmt(r.get('jacobian'), '{:.1f}')} | {fmt(r.get('solve'), '{:.1f}')} | "
            f"{fmt(other, '{:.1f}')} | {fmt(r.get('rss_mb'), '{:.0f}')} | "
            f"{fmt(r.get('net'), '{:.4f}')} | {fmt(r.get('e_net'), '{:.1e}')} | "
            f"{fmt(r.get('e_transport'), '{:.1e}')} | {fmt(r.get('e_work'), '{:.1e}')} | "
            f"{fmt(r.get('e_peak'), '{:.1e}')} | {fmt(r.get('e_hmin'), '{:.1e}')} | "
            f"{fmt(r.get('e_profile'), '{:.1e}')} |")
    return lines


def growth(rows):
    """(exponent, prefactor) of wall = c n^k over the mesh family (the scene's mesh alone:
    the default's refinement at the edges is another kind of mesh)."""
    pts = [(r["unknowns"], r["wall"]) for r in rows
           if r["family"] == "mesh" and r.get("unknowns")
           and r["status"] == "finished"]
    if len(pts) < 3:
        return None
    n, w = np.log(np.array(pts, float)).T
    k, c = np.polyfit(n, w, 1)
    return float(k), float(np.exp(c)), sorted(pts)


def plot(rows, fit, path, when):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(12, 8.4))
    default = next((r for r in rows if r["family"] == "default"), None)
    fams = {}
    for r in rows:
        if r.get("e_net") is not None:
            fams.setdefault(r["family"], []).append(r)
    names = {"cache": "default, state cache warm", "rtol": "stroke rtol 1e-3 / 1e-4",
             "mesh": "without mesh.h_edge: mesh (contact / bulk)",
             "bdf": "BDF order " + " / ".join(r["label"].split()[-1] for r in
                                              fams.get("bdf", [])),
             "theta": "Crank-Nicolson", "film": "paper film scheme",
             "reuse": "the Jacobian reused once (-stroke_snes_lag_jacobian 2)",
             "lu": "UMFPACK in place of PETSc's LU",
             "targets": f"paper mesh without h_edge at the defaults (one of the "
                        f"reference's {len(REF_GRADINGS)} placements)",
             "layer": "without mesh.h_edge: a 0.1 mm layer at h_contact",
             "plain": "default without -log_view",
             "placement": "without mesh.h_edge: 0.025 / 0.2 or 0.0125 / 0.1 mm, nodes "
                          "placed elsewhere (not joined)",
             "edge": f"the default at {len(PLACEMENT_GRADINGS)} other placements (not "
                     "joined)",
             "default": f"default ({default['label']})" if default else "default"}
    # one colour per family (the default cycle of ten repeats beyond ten families)
    colours = plt.get_cmap("tab20").colors[::2] + plt.get_cmap("tab20").colors[1::2]
    for i, (fam, rs) in enumerate(fams.items()):
        # a mesh family joined in the order of its unknowns, the others of their times
        rs = sorted(rs, key=lambda r: r["unknowns"] if fam in ("mesh", "layer") and
                    r.get("unknowns") else r["wall"])
        style = {"default": "*", "placement": "x", "edge": "+"}.get(fam, "o-")
        colour = {"placement": "k", "edge": "darkviolet"}.get(fam, colours[i % len(colours)])
        ax[0].loglog([r["wall"] for r in rs], [max(r["e_net"], 1e-6) for r in rs],
                     style, color=colour, ms={"default": 12, "edge": 9}.get(fam, 6),
                     mew=1.5 if fam == "edge" else 1.0, label=names.get(fam, fam))
        for r in rs:
            if fam == "mesh":
                ax[0].annotate(r["label"], (r["wall"], max(r["e_net"], 1e-6)), fontsize=7,
                               xytext=(3, 3), textcoords="offset points")
    ax[0].axhline(0.02, color="k", ls="--", lw=0.8, label="accuracy bound: 2 % of net leakage")
    ax[0].axvline(TARGETS["default"], color="r", ls=":", lw=0.8, label="target: 10 s")
    ax[0].set_xlabel("whole-process wall time [s]")
    ax[0].set_ylabel("error of the net leakage against the reference")
    ax[0].set_title("paper O-ring cycle, 1 MPa, 500 mm/s", fontsize=10)
    # below both axes, across the figure: inside, it hid the points near the bound; under
    # the left axes alone, its long names ran off the figure
    fig.legend(*ax[0].get_legend_handles_labels(), fontsize=7, loc="lower center", ncol=2)
    if fit is not None:
        k, c, pts = fit
        n, w = np.array(pts, float).T
        ax[1].loglog(n, w, "o", label="mesh family (without mesh.h_edge)")
        nn = np.geomspace(n.min(), n.max(), 20)
        ax[1].loglog(nn, c * nn ** k, "-", label=f"fit: wall ~ n^{k:.2f}")
        ax[1].loglog(nn, w[0] * (nn / n[0]) ** 1.5, ":",
                     label="n^1.5 (2-D nested-dissection LU)")
    ax[1].set_xlabel("unknowns of the stroke")
    ax[1].set_ylabel("whole-process wall time [s]")
    ax[1].set_title("cost growth", fontsize=10)
    ax[1].legend(fontsize=8)
    fig.suptitle(f"sealts run time against error ({when}"
                 + (f"; default {default['wall']:.1f} s)" if default else ")"), fontsize=10)
    fig.tight_layout(rect=(0, 0.22, 1, 1))
    fig.savefig(path, dpi=120)
    plt.close(fig)


REF_QUANTITIES = ("net", "out", "inn", "work", "peak_out", "peak_in", "h_min")


def reference_from(runs, taken=False):
    """The reference from runs of its setting at REF_GRADINGS: each quantity's mean over
    the placements, the placements' own values and their spread ((max - min) / |mean|);
    the film profile is the mean of theirs on the first one's positions. ``taken``: the
    runs were made before (``--from-run``), so the machine's load now says nothing of
    them."""
    keep = {k: float(np.mean([r[k] for r in runs])) for k in REF_QUANTITIES}
    keep["spread"] = {k: float(np.ptp([r[k] for r in runs]) / abs(keep[k]))
                      for k in REF_QUANTITIES}
    keep["placements"] = [{"grading_mm": g, **{k: r[k] for k in REF_QUANTITIES + (
        "unknowns", "steps", "rejected", "newton", "wall", "status")}}
        for g, r in zip(REF_GRADINGS, runs)]
    for k in ("unknowns", "steps", "wall"):
        keep[k] = float(np.mean([r[k] for r in runs]))
    keep["setting"] = (f"paper's mesh 0.01 / 0.05 mm without mesh.h_edge, stroke rtol "
                       f"1e-4, otherwise the defaults; the mean over grading distances "
                       f"{', '.join(f'{g:g}' for g in REF_GRADINGS)} mm")
    keep["date"] = datetime.now(timezone.utc).strftime("%Y-%m-%d")
    keep["machine"] = (f"{platform.node()}, {os.cpu_count()} cores, Python "
                       f"{platform.python_version()}; taken from runs made before (--from-run: "
                       "the load they ran under is not known here)") if taken else machine()
    profiles = [r.get("profile") for r in runs]
    if all(q is not None for q in profiles):
        y = profiles[0][:, 0]
        keep["profile"] = np.column_stack(
            [y, np.mean([np.interp(y, q[:, 0], q[:, 1]) for q in profiles], axis=0)])
    return keep


def reference_spread(ref):
    """The reference's placements and their spread, for the report ("" for a reference of
    one run)."""
    pl, sp = ref.get("placements"), ref.get("spread")
    if not pl:
        return ""
    nets = ", ".join(f"{q['net']:.4f}" for q in pl)
    return (f"; its placements give net {nets} mm^3 (spread {sp['net']:.1e}; transports "
            f"{max(sp['out'], sp['inn']):.1e}, work {sp['work']:.1e}, peak friction "
            f"{max(sp['peak_out'], sp['peak_in']):.1e})")


def write_reference(keep):
    prof = keep.pop("profile", None)
    REFERENCE.write_text(json.dumps(keep, indent=1) + "\n")
    if prof is not None:
        np.savetxt(REF_PROFILE, prof, delimiter=",", header="y_mm,h_mm", comments="",
                   fmt="%.10g")
    print(f"written: {REFERENCE}, {REF_PROFILE}")


# the scene's sections a reference run shares with the default scene, key by key (all but
# the mesh, names, paths and outputs; the stroke's rtol and output times are the run's own;
# a key its summary lacks is an option added since the run, at its default)
PHYSICS = ("model", "analysis", "gap", "fluid", "rod", "film", "asperity", "seal", "groove",
           "material", "mount", "viscoelastic", "hold", "stroke")


def check_reference_run(s, grading, d="the run"):
    """Exit with one line naming what differs where the summary ``s`` is not a finished run
    of the reference's setting: the default scene (configs/oring_stroke.toml) on the paper's
    mesh without mesh.h_edge at ``grading``, stroke rtol 1e-4."""
    from dataclasses import asdict

    from sealts.scene import load_scene
    scene = s["provenance"]["scene"]
    mesh = scene["mesh"]
    rtol = s["provenance"]["solvers"].get("stroke_", {}).get("ts_rtol")
    want = {"mesh.h_contact": (mesh["h_contact"], 0.01), "mesh.h_bulk": (mesh["h_bulk"], 0.05),
            "mesh.h_edge": (mesh.get("h_edge", 0.0), 0.0),
            "mesh.grading_distance": (mesh["grading_distance"], grading),
            "stroke rtol": (rtol, 1e-4), "status": (s["status"], "finished")}
    default = json.loads(json.dumps(asdict(load_scene(ROOT / "configs" / "oring_stroke.toml")),
                                    default=str))
    for sec in PHYSICS:
        if not isinstance(default[sec], dict):
            want[sec] = (scene.get(sec), default[sec])
            continue
        for key, ref in default[sec].items():
            # a key the run's summary lacks is an option added since, at its default
            if key in scene.get(sec, {}) and not (sec == "stroke"
                                                  and key in ("rtol", "output_times")):
                want[f"{sec}.{key}"] = (scene[sec][key], ref)
    for key, (got, ref) in want.items():
        if got != ref:
            sys.exit(f"--from-run: {d} has {key} = {got!r}, the reference's is {ref!r}")


def from_run(d, grading):
    """A reference run's values from its output directory, which must hold a finished run
    of the reference's setting (:func:`check_reference_run`)."""
    s = json.loads((d / "summary.json").read_text())
    check_reference_run(s, grading, d)
    st = s["stroke"]
    return {"net": st["leakage_out"], "out": st["outstroke_transport"],
            "inn": st["instroke_transport"], "work": st["friction_work"],
            "peak_out": st["peak_friction_outstroke"], "peak_in": st["peak_friction_instroke"],
            "h_min": st["h_min"], "unknowns": st["unknowns"], "steps": s["steps_accepted"],
            "rejected": s["steps_rejected"], "newton": s["newton_iterations"],
            "wall": s["wall_time_s"], "status": s["status"],
            "profile": profile(d / "stroke_profiles.csv")}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="rtol and mesh families only")
    ap.add_argument("--families", help="only these families (comma-separated; the default "
                                       "row always runs)")
    ap.add_argument("--reference", action="store_true",
                    help="compute the overkill reference (the paper's mesh at rtol 1e-4, the mean "
                         "over three grading distances; about an hour here)")
    ap.add_argument("--from-run", metavar="DIR", nargs="+",
                    help="with --reference: take it from the output directories of runs "
                         "already made with those settings, one per grading distance")
    ap.add_argument("--from-csv", action="store_true",
                    help="no runs: rebuild the report from benchmarks/work_precision*.csv "
                         "and the work directory of the last measurement")
    ap.add_argument("--add", metavar="FAMILIES",
                    help="run these families only and add their rows to the last "
                         "measurement's (benchmarks/work_precision.csv and its work "
                         "directory), then rebuild the report")
    ap.add_argument("--work", default=str(ROOT / "results" / "bench_work_precision"))
    a = ap.parse_args()
    work = Path(a.work)
    if a.reference:
        if a.from_run:
            if len(a.from_run) != len(REF_GRADINGS):
                sys.exit(f"--from-run: one output directory per grading distance "
                         f"{', '.join(f'{g:g}' for g in REF_GRADINGS)} mm, in that order")
            runs = [from_run(Path(d), g) for d, g in zip(a.from_run, REF_GRADINGS)]
        else:
            runs = [run(f"reference, grading {g:g} mm",
                        scene_text((0.01, 0.05), grading=g, h_edge=0.0),
                        ["-stroke_ts_rtol", "1e-4"], work / f"reference_{g:g}", log=False,
                        limit=REF_LIMIT) for g in REF_GRADINGS]
        write_reference(reference_from(runs, taken=bool(a.from_run)))
        return
    if not REFERENCE.exists():
        sys.exit(f"no reference {REFERENCE}: run with --reference first")
    ref = json.loads(REFERENCE.read_text())
    ref_prof = (np.loadtxt(REF_PROFILE, delimiter=",", skiprows=1)
                if REF_PROFILE.exists() else None)
    slider = None
    if a.from_csv or a.add:
        rows, when, host = reread(work, ref, ref_prof)
        if a.add:
            rows = [r for r in rows if r["family"] not in a.add.split(",")]
            first = 1 + max(int(r["run"]) for r in rows)
            added, when_added, _ = measure(work, False, ref, ref_prof, a.add.split(","),
                                           first=first, default=False)
            rows += added
            meta = json.loads((work / "meta.json").read_text())
            base = meta.get("measured", re.sub(r" \(the .*\)$", "", when))
            again = set(a.add.split(","))      # families measured again drop their dates
            added = {**{k: w for k, w in meta.get("added", {}).items()
                        if not set(k.split(",")) <= again}, a.add: when_added}
            when = base + " (" + "; ".join(f"the {f} rows added {w}"
                                          for f, w in added.items()) + ")"
            meta.update(when=when, measured=base, added=added)
            (work / "meta.json").write_text(json.dumps(meta))
        if SLIDER.exists():      # the slider rows of the (first) measurement
            with open(SLIDER) as f:
                slider = [{"scheme": x["scheme"], "elements": int(x["elements"]),
                           "time_ms": float(x["time_ms"]), "error": float(x["error"]),
                           "newton": int(x["newton"])} for x in csv.DictReader(f)]
    else:
        rows, when, host = measure(work, a.quick, ref, ref_prof,
                                   a.families.split(",") if a.families else None)
    report(rows, when, host, a.quick, ref, slider)


def measure(work, quick, ref, ref_prof, families=None, first=0, default=True):
    """Run every setting (one process each, one after another); the rows. ``first``: the
    work directory number of the first row; ``default``: the default row first, and the
    measurement's meta.json (not when rows are added to an earlier one)."""
    when = datetime.now(timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    host = machine()
    print(f"{when}; {host}", flush=True)
    work.mkdir(parents=True, exist_ok=True)
    if default:
        (work / "meta.json").write_text(json.dumps({"when": when, "host": host}))
    # a warm-up run compiles numba's cache and meshes the default (not timed)
    run("warm-up", scene_text(), [], work / "warm-up")
    rows = []
    if families is not None and "default" in families:       # --add default,...
        default = True
    todo = [("default", f"{DEFAULT}, BDF 2, rtol 1e-2", scene_text(), [])] if default else []
    todo += [t for t in settings(quick) if (families is None or t[0] in families)
             and t[1] != "rtol 1e-02"]
    for k, (fam, label, text, opts) in enumerate(todo, start=first):
        if fam == "cache":       # an untimed run fills a fresh state cache first
            text = text.replace("{cache}", str(work / f"{k:02d}" / "cache"))
            run("fill", text, opts, work / f"{k:02d}" / "fill")
        r = run(label, text, opts, work / f"{k:02d}", log=fam != "plain",
                limit=LIMITS.get(fam, LIMIT))
        r["family"], r["run"] = fam, f"{k:02d}"
        r.update(errors(r, ref, ref_prof))
        rows.append(r)
        print(f"  {fam:8s} {label:28s} {r['status']:10s} {r['wall']:7.1f} s  net "
              f"{fmt(r.get('net'), '{:.4f}')}  err {fmt(r.get('e_net'), '{:.1e}')}", flush=True)
    return rows, when, host


def reread(work, ref, ref_prof):
    """The rows of the last measurement (benchmarks/work_precision.csv: wall times, memory,
    counts), their -log_view splits and film profiles taken again from its work directory
    where it still holds them (else the CSV's), their errors computed again."""
    meta = measured_when(work)
    with open(OUT / "work_precision.csv") as f:
        rows = list(csv.DictReader(f))
    for k, r in enumerate(rows):
        r["run"] = r.get("run") or f"{k:02d}"     # the row's work directory
        for key, v in list(r.items()):
            if key in ("family", "label", "status", "run"):
                continue
            r[key] = None if v == "" else float(v)
        for key in ("unknowns", "steps", "rejected", "newton", "linear"):
            if r[key] is not None:
                r[key] = int(r[key])
        if (work / r["run"] / "log_view.txt").exists():
            r.update(log_view(work / r["run"] / "log_view.txt"))
        r["profile"] = profile(work / r["run"] / "out" / "stroke_profiles.csv")
        film = r.get("e_profile")
        r.update({key: None for key in r if key.startswith("e_")})
        r.update(errors(r, ref, ref_prof))
        if r["profile"] is None and film is not None:
            r["e_profile"] = film
    return rows, meta["when"], meta["host"]


def measured_when(work):
    """When and where the last measurement ran: its work directory's meta.json, or (a
    fresh clone, a cleared /tmp) the header of benchmarks/work_precision.md."""
    try:
        return json.loads((work / "meta.json").read_text())
    except (OSError, ValueError):
        head = (OUT / "work_precision.md").read_text().splitlines()[2]
        when, host = re.match(r"(.+? UTC(?: \(.*?\))?); (.*)$",
                              head.split(". One process per row")[0]).groups()
        measured = re.sub(r" \(the .*\)$", "", when)
        added = dict(re.findall(r"the (\S+) rows added ([^;)]+)", when))
        meta = {"when": when, "host": host, "measured": measured, "added": added}
        work.mkdir(parents=True, exist_ok=True)
        (work / "meta.json").write_text(json.dumps(meta))
        return meta


def placement_groups(rows):
    """Rows of one setting meshed several ways: per setting (DEFAULT, "0.025 / 0.2 mm"),
    its default or 'mesh' row and the rows of the same setting with another grading
    distance or mirror-symmetric; only settings that have such rows."""
    groups = {}
    for r in rows:
        if r["family"] not in ("default", "mesh", "placement", "edge") or r.get("e_net") is None:
            continue
        key = (DEFAULT if r["family"] == "default" else
               re.sub(r", (grading [0-9.]+ mm|mirror-symmetric)$", "", r["label"]))
        groups.setdefault(key, []).append(r)
    return {k: rs for k, rs in groups.items()
            if len(rs) > 1 and any(re.search(r"grading|mirror", r["label"]) for r in rs)}


def spread(rs):
    """(net min, net max, the largest error of each bounded quantity, how many rows keep
    every bound) over the rows ``rs``."""
    nets = [r["net"] for r in rs]
    worst = {k: max(r[k] for r in rs) for k in BOUNDS}
    held = sum(all(r[k] <= b for k, b in BOUNDS.items()) for r in rs)
    return min(nets), max(nets), worst, held


def placement(rows):
    """The report's paragraph on the 'placement' family ([] without it)."""
    out = []
    for sizes, rs in placement_groups(rows).items():
        lo, hi, worst, held = spread(rs)
        out.append(f"- {sizes}, {len(rs)} meshes: net leakage {lo:.3f} to {hi:.3f} mm^3; "
                   f"largest errors net {worst['e_net']:.1e} (bound 2e-2), transports "
                   f"{worst['e_transport']:.1e}, friction work {worst['e_work']:.1e}, peak "
                   f"friction {worst['e_peak']:.1e} (bounds 1e-2); the bounds hold on {held} "
                   f"of {len(rs)}")
    if not out:
        return []
    return ["", "## Where the mesher puts the nodes ('placement')", "",
            "The same element sizes meshed several ways: grading distances of "
            f"{min(PLACEMENT_GRADINGS):g} to {max(PLACEMENT_GRADINGS):g} mm for the default "
            "0.5 (and, without h_edge, mirror-symmetric), so that gmsh places the nodes "
            "elsewhere at the same resolution. One row's error is one draw from the spread below, which is the "
            "accuracy of its sizes:", ""] + out


# the summary's wording of a family's rows ("{label}" by default) and its order
SUMMARY = {"default": "**default** ({label})", "plain": "the default without -log_view",
           "cache": "state cache warm (stroke only)", "rtol": "stroke {label}",
           "lu": "{label} in place of PETSc's LU", "film": "the {label} for the film",
           "mesh": "without h_edge: mesh {label}", "layer": "without h_edge: {label}",
           "reuse": "{label} (-stroke_snes_lag_jacobian 2)"}
SUMMARY_ORDER = ("default", "edge", "plain", "cache", "rtol", "bdf", "reuse", "theta",
                 "film", "lu", "mesh", "placement", "layer", "targets", "prony")


def summary(rows):
    """The short table (the README's): one line per row, the placements of one setting
    as one line of ranges (the default with its own, after it; a size without h_edge
    with its own)."""
    head = ["| setting | unknowns | steps (rejected) | wall s | net mm^3 | err net | "
            "err transports | err friction work | err peak friction |",
            "|---|---|---|---|---|---|---|---|---|"]
    e = lambda r, k: fmt(r.get(k), "{:.1e}")                          # noqa: E731
    rng = lambda v, f: (f.format(min(v)) + "-" + f.format(max(v))        # noqa: E731
                        if min(v) != max(v) else f.format(v[0]))
    groups = placement_groups(rows)
    lines = {f: [] for f in SUMMARY_ORDER}
    for r in rows:
        if r["family"] in ("edge", "placement"):
            continue
        name = SUMMARY.get(r["family"], "{label}").format(label=r["label"])
        if r["status"] != "finished":
            # its counts are steps 1-2's on the scene's own mesh: not the stroke's
            name += f" ({r['status']} at {r['wall']:.0f} s)"
            r = {k: v for k, v in r.items() if k not in ("unknowns", "steps", "rejected")}
        lines.setdefault(r["family"], []).append(
            f"| {name} | {fmt(r.get('unknowns'), '{:,}')} | "
            + (f"{fmt(r.get('steps'), '{:,}')} ({fmt(r.get('rejected'), '{:,}')})"
               if r.get("steps") is not None else "") + " | "
            f"{r['wall']:.1f} | {fmt(r.get('net'), '{:.3f}')} | {e(r, 'e_net')} | "
            f"{e(r, 'e_transport')} | {e(r, 'e_work')} | {e(r, 'e_peak')} |")
    for key, rs in groups.items():
        name = (f"the default at {len(rs)} placements (grading distances)" if key == DEFAULT
                else f"without h_edge: {key} at {len(rs)} placements")
        lines["edge" if key == DEFAULT else "placement"].append(
            f"| {name} | {rng([r['unknowns'] for r in rs], '{:,}')} | "
            f"{rng([r['steps'] for r in rs], '{:,}')} | "
            f"{rng([r['wall'] for r in rs], '{:.1f}')} | "
            f"{rng([r['net'] for r in rs], '{:.3f}')} | "
            + " | ".join(f"up to {max(r[k] for r in rs):.1e}" for k in BOUNDS) + " |")
    return head + [x for f in lines for x in lines[f]]


def report(rows, when, host, quick, ref, slider=None):
    """benchmarks/work_precision.md, .csv and .png from the rows (``slider``: the slider's
    rows, measured here if None)."""
    fit = growth(rows)
    slider = slider_rows() if slider is None else slider
    with open(SLIDER, "w", newline="") as f:
        w = csv.DictWriter(f, ["scheme", "elements", "time_ms", "error", "newton"])
        w.writeheader()
        w.writerows(slider)
    OUT.mkdir(exist_ok=True)
    plot(rows, fit, OUT / "work_precision.png", when)
    cols = ["run", "family", "label", "status", "unknowns", "steps", "rejected", "newton", "linear",
            "wall", "stroke_wall", "lu", "residual", "jacobian", "solve", "total", "rss_mb",
            "net", "out", "inn", "work", "peak_out", "peak_in", "h_min", "e_net",
            "e_transport", "e_work", "e_peak", "e_hmin", "e_profile"]
    with open(OUT / "work_precision.csv", "w", newline="") as f:
        w = csv.DictWriter(f, cols, extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)
    default = next((r for r in rows if r["family"] == "plain"),
                   next((r for r in rows if r["family"] == "default"), None))
    md = [f"# Run time against error (scripts/bench_work_precision.py{' --quick' if quick else ''})",
          "", f"{when}; {host}. One process per row, one after another, whole-process wall "
          "time (numba cache warm, mesh cached, steps 1-2 run in every row but 'cache'). "
          "Every row but 'plain' runs with -log_view, which costs time of its own (compare "
          "'plain' with 'default'); the LU, residual, Jacobian and solve columns are its "
          "times of the same process (SNES's function and Jacobian evaluations, LU numeric "
          "and symbolic factorisations, triangular solves), 'other' the rest (Python, "
          "output, start-up, the log itself).", "",
          f"Reference: {ref['setting']} ({ref['unknowns']:,.0f} unknowns, {ref['steps']:,.0f} "
          f"steps, {ref['wall']:.0f} s each on {ref['date']}): net leakage {ref['net']:.4f} "
          f"mm^3, transports {ref['out']:.3f} / {ref['inn']:.3f} mm^3, friction work "
          f"{ref['work']:.0f} N mm, peak friction {ref['peak_out']:.2f} / {ref['peak_in']:.2f} N"
          + reference_spread(ref) + ". Errors are relative to it; 'err film' is the "
          "mid-outstroke (t = 2.5 s) film's: the larger relative error of its minimum and of "
          "its mean over the contact.", ""]
    md += table(rows)
    md += ["", "## Targets (issue 17)", ""]
    by = {r["label"]: r for r in rows}
    for name, lim in TARGETS.items():
        r = default if name == "default" else by.get(name)
        if r is None:
            continue
        verdict = "met" if r["wall"] <= lim else f"missed by {r['wall'] / lim:.1f}x"
        md.append(f"- {name} ({r['label']}): {r['wall']:.1f} s against {lim:g} s: {verdict}"
                  + (f"; net leakage error {r['e_net']:.1e} (bound 2e-2), transports "
                     f"{r['e_transport']:.1e}, work {r['e_work']:.1e}, peak friction "
                     f"{r['e_peak']:.1e} (bounds 1e-2)" if r.get("e_net") is not None
                     else ""))
        group = placement_groups(rows).get(DEFAULT) if name == "default" else None
        if group:
            lo, hi, worst, held = spread(group)
            md[-1] += (f"; over the {len(group)} placements of its sizes (below) up to net "
                       f"{worst['e_net']:.1e}, transports {worst['e_transport']:.1e}, work "
                       f"{worst['e_work']:.1e}, peak friction {worst['e_peak']:.1e}")
    for key, rs in placement_groups(rows).items():
        if key == "0.025 / 0.2 mm":   # the default's mesh without the edges' refinement
            r = next((x for x in rs if x["family"] == "mesh"), None)
            if r is None:
                continue
            lo, hi, worst, held = spread(rs)
            md.append(f"- without mesh.h_edge ({key}): {r['wall']:.1f} s (with "
                      f"-log_view); over its {len(rs)} placements up to net "
                      f"{worst['e_net']:.1e}, transports {worst['e_transport']:.1e}, work "
                      f"{worst['e_work']:.1e}, peak friction {worst['e_peak']:.1e}: the "
                      f"bounds hold on {held} of {len(rs)}")
    if NOTES.exists():
        md += ["", NOTES.read_text().strip()]
    md += placement(rows)
    md += ["", "## Summary (the README's table)", ""] + summary(rows)
    if fit is not None:
        md += ["", f"Cost growth over the mesh family: wall time ~ n^{fit[0]:.2f} "
               "(sparse LU of a 2-D problem with nested dissection: n^1.5 flops; at these "
               "sizes fixed costs, start-up and steps 1-2, flatten it; from "
               f"{PETSC_LU_BELOW:,} unknowns on the factorisations are UMFPACK's, below "
               "PETSc's LU)."]
    md += ["", "## Slider (closed form, Eq. 43): steady film, best of 3", "",
           "| scheme | elements | time ms | max pressure error / p_max | Newton |",
           "|---|---|---|---|---|"]
    md += [f"| {s['scheme']} | {s['elements']} | {s['time_ms']:.2f} | {s['error']:.2e} | "
           f"{s['newton']} |" for s in slider]
    (OUT / "work_precision.md").write_text("\n".join(md) + "\n")
    print("\n".join(md))
    print(f"written: {OUT / 'work_precision.md'}, .csv, .png")

if __name__ == "__main__":
    main()
