"""The results of Schmidt, Andre, Poll (2010), Section 3 (Figs. 8-14), regenerated with sealts
and put beside the paper's stated values in a markdown report.

Runs the ``configs/paper_*.toml`` scenes one after another (one simulation at a time), each
through ``python -m sealts`` in its own process, then reads their output
(:mod:`sealts.io.results`, the numbers from :mod:`sealts.io.metrics`) and writes
``OUT/report.md`` with PNG figures beside it:

* steps 1-2 once per sealed pressure: ``paper_state_1mpa`` (mounted, pressurised to 1 MPa)
  and ``paper_state_0mpa`` (mounted only); every stroke scene restarts from their
  ``state.h5`` (``[start] state``, same mesh and p_in);
* Fig. 8: steady outstroke and instroke at +-100 mm/s;
* Fig. 9: 500 mm/s held 15 h, viscoelastic (Table 2, relaxed start), against long-term;
* Figs. 10-11: Patir-Cheng flow factors (Rq = 2.15e-4 mm, gamma = 1) and their effect;
* Fig. 12: p_in = p_out = 0, 100 and 500 mm/s, against ``sealts ihl``;
* Fig. 14: the 10 s sinusoidal cycle in four variants, with an IHL leakage estimate.

Each run lives in ``OUT/runs/<key>/``: the scene copy it ran (mesh sizes, state path and
mesh cache filled in), ``log.txt`` and sealts' own output. Usage:

    .venv/bin/python scripts/paper_report.py [--coarse] [--out DIR] [--reuse] [--report-only]

``--coarse`` runs the 0.1 / 0.4 mm mesh without refinement (a quick check, about 7 min on one
core) instead of the default 0.025 / 0.2 mm refined to 1.5 um at the pressurised contact's
edges (``mesh.h_edge = 0.0015``: the mesh of ``configs/oring_stroke.toml``, the setting
whose cycle is within the work-precision benchmark's bounds); ``--mesh H_CONTACT H_BULK``
runs other sizes, also without the refinement. ``--reuse`` keeps every run
whose scene copy is unchanged and finished; ``--report-only`` only rewrites the report from
the runs already in OUT.
"""
import argparse
import datetime
import json
import os
import platform
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from sealts.film.ihl import ihl_film, ihl_flow  # noqa: E402
from sealts.io.metrics import (asperity_share, at_end, band_core, contact_band,  # noqa: E402
                               cumulative_volume, film_change, film_metrics, flow_film,
                               in_band, inlet_nodes, inlet_span, ripple, steady_change)
from sealts.io.results import MissingOutput, Results  # noqa: E402

# (h_contact, h_bulk, h_edge) mm
MESHES = {"default": (0.025, 0.2, 0.0015), "coarse": (0.1, 0.4, 0.0)}
TRIM = 0.1      # film statistics over the contact band without this share of it at each end

# What the paper states in its text (Section 3) and figures, the column "paper" of the report.
PAPER = {
    "fig8_film": 1e-3,              # mm, "about 1 um" in the contact
    "fig8_p_max": (3.0, 3.5),       # MPa, peak fluid pressure
    "fig8_p_axis": 3.6,             # MPa, the top of its Fig. 8a pressure axis
    "fig9_excess": 0.15e-3,         # mm, viscoelastic film over long-term at 0 h, at most
    "fig9_hours": (1.0, 5.0, 15.0),  # h, its curves besides 0 h
    "fig14_net": 100.0,             # mm^3, net leakage of ve,sq,Phi over the cycle
    "fig14_q": (-30.0, 50.0),       # mm^3/s, range of Q over the cycle
}

# The README's mesh study of the hyperelastic cycle (configs/oring_stroke.toml, recorded in
# tests/test_cycle_regression.py): contact / bulk mesh (mm), net leakage and outstroke
# volume (mm^3); the last row is the paper's mesh. And the pressurised O-ring's dry contact
# peak on the paper's mesh (README, "The seal body and mounting").
CYCLE_STUDY = [((0.1, 0.4), 11.05, 75.85), ((0.05, 0.2), 12.40, 78.92),
               ((0.025, 0.2), 15.88, 83.98), ((0.0125, 0.2), 15.49, 83.59),
               ((0.01, 0.05), 15.87, 84.6)]
DRY_PEAK_PAPER_MESH = 2.71          # MPa


def study(col, nd=2):
    """'a / b / c / d mm^3 on the 0.1 / ... mm contact meshes, e on the paper's 0.01 / 0.05
    mm mesh' of the cycle study's column ``col`` (1: net leakage, 2: outstroke volume)."""
    rows, paper = CYCLE_STUDY[:-1], CYCLE_STUDY[-1]
    return (" / ".join(f"{r[col]:.{nd}f}" for r in rows) + " mm^3 on the "
            + " / ".join(f"{r[0][0]:g}" for r in rows) + " mm contact meshes (bulk "
            + " / ".join(f"{r[0][1]:g}" for r in rows) + " mm), "
            f"{paper[col]:.{nd}f} on the paper's {paper[0][0]:g} / {paper[0][1]:g} mm mesh")


@dataclass
class Run:
    key: str                    # directory under OUT/runs
    scene: str                  # configs/<scene>.toml
    what: str                   # one line for the progress and the report
    command: str = "run"        # sealts run | sealts ihl
    state: str = ""             # key of the run whose state.h5 this one restarts from
    edits: dict = field(default_factory=dict)   # {(section, key): value} for the copy


RUNS = [
    Run("state_1mpa", "paper_state_1mpa", "steps 1-2: mount, pressurise to 1 MPa"),
    Run("state_0mpa", "paper_state_0mpa", "step 1: mount, no pressure"),
    Run("fig8_out", "paper_fig8_outstroke", "Fig. 8: steady outstroke +100 mm/s",
        state="state_1mpa"),
    Run("fig8_in", "paper_fig8_instroke", "Fig. 8: steady instroke -100 mm/s",
        state="state_1mpa"),
    Run("fig11_ff", "paper_fig11_flowfactors", "Fig. 11: outstroke +100 mm/s, flow factors",
        state="state_1mpa"),
    Run("fig9_lt", "paper_fig9_longterm", "Fig. 9: steady +500 mm/s, long-term",
        state="state_1mpa"),
    Run("fig9_ve", "paper_fig9_viscoelastic", "Fig. 9: +500 mm/s held 15 h, viscoelastic",
        state="state_1mpa"),
    Run("fig12_100", "paper_fig12_100", "Fig. 12a: EHL, p = 0, +100 mm/s",
        state="state_0mpa"),
    Run("fig12_500", "paper_fig12_500", "Fig. 12b: EHL, p = 0, +500 mm/s",
        state="state_0mpa"),
    Run("ihl12_100", "paper_fig12_ihl", "Fig. 12a: IHL, p = 0, 100 mm/s", command="ihl"),
    Run("ihl12_500", "paper_fig12_ihl", "Fig. 12b: IHL, p = 0, 500 mm/s", command="ihl",
        edits={("rod", "velocity"): 500.0}),
    Run("fig14_he", "paper_fig14_he", "Fig. 14: cycle, hyperelastic", state="state_1mpa"),
    Run("fig14_ve", "paper_fig14_ve", "Fig. 14: cycle, viscoelastic", state="state_1mpa"),
    Run("fig14_ve_sq", "paper_fig14_ve_sq", "Fig. 14: cycle, viscoelastic + squeeze",
        state="state_1mpa"),
    Run("fig14_ve_sq_ff", "paper_fig14_ve_sq_ff",
        "Fig. 14: cycle, viscoelastic + squeeze + flow factors", state="state_1mpa"),
    Run("ihl14", "paper_fig14_ihl", "Fig. 14: IHL films at 500 mm/s, p_in = 1 MPa",
        command="ihl"),
]

FIG14 = [("fig14_he", "he", "hyperelastic, steady Reynolds"),
         ("fig14_ve", "ve", "viscoelastic, steady Reynolds"),
         ("fig14_ve_sq", "ve,sq", "viscoelastic, transient Reynolds (squeeze)"),
         ("fig14_ve_sq_ff", "ve,sq,Φ", "viscoelastic, squeeze, flow factors")]


# ---------------------------------------------------------------------------------------
# scene copies and runs

def toml_value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    return repr(v)


def set_key(text, section, key, value):
    """``text`` (a scene file) with ``section.key = value``: the key's line replaced in
    place, or added at the end of its section, or a new section appended. Comments and the
    other lines are kept (a commented-out ``# [section]`` does not count)."""
    lines = text.splitlines()
    line = f"{key} = {toml_value(value)}    # set by scripts/paper_report.py"
    start = next((i for i, s in enumerate(lines) if s.strip() == f"[{section}]"), None)
    if start is None:
        return text.rstrip("\n") + f"\n\n[{section}]\n{line}\n"
    end = next((i for i in range(start + 1, len(lines)) if lines[i].lstrip().startswith("[")),
               len(lines))
    for i in range(start + 1, end):
        if lines[i].split("=", 1)[0].strip() == key and not lines[i].lstrip().startswith("#"):
            lines[i] = line
            return "\n".join(lines) + "\n"
    last = max(i for i in range(start, end) if lines[i].strip()
               and not lines[i].lstrip().startswith("#"))
    lines.insert(last + 1, line)
    return "\n".join(lines) + "\n"


def scene_copy(run, mesh, out):
    """The text of ``run``'s scene as it runs: mesh sizes, an absolute mesh cache, the
    restart state and the run's own edits."""
    text = (ROOT / "configs" / f"{run.scene}.toml").read_text()
    edits = {("mesh", "h_contact"): mesh[0], ("mesh", "h_bulk"): mesh[1],
             ("mesh", "h_edge"): mesh[2],
             ("mesh", "cache"): str(ROOT / "meshes"), **run.edits}
    if run.state:
        edits[("start", "state")] = str((out / "runs" / run.state / "state.h5").resolve())
    for (sec, key), v in edits.items():
        text = set_key(text, sec, key, v)
    return text


def run_one(run, mesh, out, reuse, k, n):
    """Run one scene (sequentially, in its own process); returns its wall time (s) or None
    when it failed. A finished run with the same scene copy is kept under ``reuse``."""
    d = out / "runs" / run.key
    text = scene_copy(run, mesh, out)
    done = d / "done.json"
    if reuse and done.exists() and (d / "scene.toml").exists() \
            and (d / "scene.toml").read_text() == text:
        info = json.loads(done.read_text())
        if info.get("returncode") == 0:
            print(f"[{k:2d}/{n}] {run.key:15s} {run.what}: kept ({info['wall_s']:.1f} s "
                  "when it ran)", flush=True)
            return info["wall_s"]
    d.mkdir(parents=True, exist_ok=True)
    done.unlink(missing_ok=True)
    (d / "scene.toml").write_text(text)
    env = dict(os.environ, PYTHONPATH=str(ROOT), OMP_NUM_THREADS="1",
               OPENBLAS_NUM_THREADS="1")
    cmd = [sys.executable, "-m", "sealts", run.command, str(d / "scene.toml"), "-o", str(d)]
    print(f"[{k:2d}/{n}] {run.key:15s} {run.what} ...", end="", flush=True)
    t0 = time.perf_counter()
    with open(d / "log.txt", "w") as log:
        rc = subprocess.run(cmd, cwd=ROOT, env=env, stdout=log, stderr=subprocess.STDOUT).returncode
    wall = time.perf_counter() - t0
    done.write_text(json.dumps({"returncode": rc, "wall_s": wall, "command": cmd,
                                "commit": git_commit()}) + "\n")
    if rc != 0:
        tail = (d / "log.txt").read_text().strip().splitlines()[-3:]
        print(f" FAILED (exit {rc}, {wall:.1f} s): " + " | ".join(tail), flush=True)
        return None
    print(f" {wall:.1f} s", flush=True)
    return wall


# ---------------------------------------------------------------------------------------
# reading the runs' output

def output(out, key):
    """The output of run ``key`` (:class:`sealts.io.results.Results`)."""
    return Results(out / "runs" / key)


def profiles(out, key, name="stroke_profiles"):
    """{t: profile sorted by y} of one of run ``key``'s profile files."""
    return output(out, key).profiles(name, sort_by="y")


def scene_of(out, key):
    """The scene run ``key`` ran: its copy in ``runs/<key>/``, or its ``configs/`` file
    before it has run (they differ in the mesh, the restart state and ``Run.edits`` only)."""
    from sealts.scene import SceneError, load_scene
    copy = out / "runs" / key / "scene.toml"
    if copy.is_file():
        try:
            return load_scene(copy)
        except SceneError:              # e.g. its [start] state has gone since
            pass
    return load_scene(ROOT / "configs" / f"{next(r for r in RUNS if r.key == key).scene}.toml")


def rod_area(scene):
    """A of Eq. 31 (mm): the rod's circumference, or the depth (1 mm) of a planar seal."""
    return 2 * np.pi * scene.rod.radius if scene.seal.symmetry == "axisymmetric" else 1.0


def table2():
    """The paper's Table 2 Prony series (:mod:`sealts.solid.prony`), 25 C."""
    from sealts.solid.prony import TABLE2_G, TABLE2_TAU, PronySeries
    return PronySeries(TABLE2_G, TABLE2_TAU)


def relaxation_modulus(t):
    """G(t) / G_inf of Table 2 (Eq. 7-9) at its reference temperature."""
    series = table2()
    return float(series.relaxation(t)) / series.g_inf


# ---------------------------------------------------------------------------------------
# report pieces

def table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return "\n".join(out)


def um(x, nd=3):
    return f"{x * 1e3:.{nd}f} um"


def mpa(x, nd=2):
    return f"{x:.{nd}f} MPa"


def word(cond, yes, no):
    return yes if cond else no


def plt_setup():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def zoom(ax, prof, b, margin=0.35):
    ax.set_xlim(b[0] - margin, b[1] + margin)


def mesh_label(m):
    """'h_contact / h_bulk mm' of a mesh tuple, with its edges' refinement if it has one."""
    return f"{m[0]:g} / {m[1]:g} mm" + (f", h_edge {m[2]:g}" if len(m) > 2 and m[2] else "")


def mesh_of(out):
    """(h_contact, h_bulk, h_edge) of the runs in ``out`` (from a run's scene copy), or
    None."""
    import tomllib
    for p in sorted((out / "runs").glob("*/scene.toml")):
        m = tomllib.loads(p.read_text())["mesh"]
        return (m["h_contact"], m["h_bulk"], m.get("h_edge", 0.0))
    return None


class Report:
    def __init__(self, out, mesh_name, mesh, walls, plots=True):
        self.out, self.mesh_name, self.mesh, self.walls = out, mesh_name, mesh, walls
        self.parts, self.numbers = [], {}
        self.plots = plots
        self.plt = plt_setup()
        self.scenes = {}

    def scene(self, key):
        """The scene of run ``key`` (:func:`scene_of`), loaded once."""
        if key not in self.scenes:
            self.scenes[key] = scene_of(self.out, key)
        return self.scenes[key]

    def area(self, key):
        return rod_area(self.scene(key))

    def add(self, text):
        self.parts.append(text.strip("\n") + "\n")

    def savefig(self, fig, name):
        if self.plots:
            fig.tight_layout()
            fig.savefig(self.out / name, dpi=110)
        self.plt.close(fig)
        return name

    def prepare(self):
        """What every section reads: the dry contact peak and the inlet's resolution."""
        try:
            s1 = output(self.out, "state_1mpa").summary
            self.dry_peak = s1["results"]["p_contact_max"]
        except MissingOutput:
            s1, self.dry_peak = None, float("nan")
        try:
            ih = output(self.out, "ihl14").summary["ihl"]["outstroke"]
            ip = profiles(self.out, "ihl14", "ihl_profile")[0.0]
            self.inlet_elements = inlet_span(ip, ih["y_w"], 1.0)
        except MissingOutput:
            self.inlet_elements = float("nan")
        return s1

    def sections(self):
        self.section("1. Fig. 8", self.fig8)
        self.section("2. Fig. 9", self.fig9)
        self.section("3. Figs. 10-11", self.fig10_11)
        self.section("4. Fig. 12", self.fig12)
        self.section("5. Fig. 14", self.fig14)

    def read_others(self, others):
        """The key numbers of the runs in ``others`` (other meshes): [(mesh, numbers, dir)]
        for each directory that holds finished runs (``self.others``)."""
        self.others = []
        for other in others:
            mesh = mesh_of(other)
            if mesh is None or mesh == tuple(self.mesh):
                continue
            o = Report(other, "", mesh, {}, plots=False)
            o.prepare()
            o.sections()
            if o.numbers:
                self.others.append((mesh, o.numbers, other))

    def values_across(self, *path, f=1.0):
        """[(h_contact, value)] of one number over this and the other meshes, coarse to
        fine, where it exists."""
        cols = sorted([(tuple(self.mesh), self.numbers)] + [(m, n) for m, n, _ in
                                                            getattr(self, "others", [])],
                      key=lambda c: -c[0][0])
        vals = []
        for m, n in cols:
            try:
                x = n
                for k in path:
                    x = x[k]
                vals.append((m[0], f * float(x)))
            except (KeyError, TypeError):
                pass
        return vals

    def across(self, *path, f=1.0, nd=3, unit=""):
        """'a / b / c' of one number over this and the other meshes, coarse to fine, with
        the contact sizes, or '' when no other mesh has it."""
        vals = self.values_across(*path, f=f)
        if len(vals) < 2:
            return ""
        return (" / ".join(f"{x:.{nd}f}" for _, x in vals) + (f" {unit}" if unit else "")
                + " on the "
                + " / ".join(f"{m:g}" for m, _ in vals) + " mm contact meshes")

    def mesh_check(self):
        """The key numbers of this report beside those of the other meshes' runs."""
        cols = [(self.mesh, self.numbers, None)] + list(getattr(self, "others", []))
        if len(cols) < 2:
            return
        A = self.numbers

        def get(n, *path, f=1.0):
            try:
                x = n
                for k in path:
                    x = x[k]
                return f * float(x)
            except (KeyError, TypeError):
                return None

        spec = [
            ("Fig. 8: mean film, outstroke [um]", ("fig8", "metrics", "out", "h_mean"), 1e3, 3),
            ("Fig. 8: mean film, instroke [um]", ("fig8", "metrics", "in", "h_mean"), 1e3, 3),
            ("Fig. 8: peak fluid pressure, outstroke [MPa]", ("fig8", "metrics", "out", "p_max"), 1, 2),
            ("Fig. 8: asperity share, outstroke [%]", ("fig8", "share", "out"), 100, 1),
            ("Fig. 9: h_ve - h_lt at 0 h, mean [um]", ("fig9", "d0h"), 1e3, 3),
            ("Fig. 9: h_ve - h_lt at 15 h, mean [um]", ("fig9", "d15"), 1e3, 3),
            ("Fig. 9: largest h_ve - h_lt [um]", ("fig9", "dmax"), 1e3, 3),
            ("Fig. 11: peak fluid pressure without / with flow factors [MPa]", ("fig11", "pmax"), 1, 2),
            ("Fig. 11: mean film without / with flow factors [um]", ("fig11", "hmean"), 1e3, 3),
            ("Fig. 12: IHL h* at 100 mm/s [um]", ("fig12", 100, "h_star"), 1e3, 3),
            ("Fig. 12: EHL flow film at 100 mm/s [um]", ("fig12", 100, "hq"), 1e3, 3),
            ("Fig. 12: IHL h* at 500 mm/s [um]", ("fig12", 500, "h_star"), 1e3, 3),
            ("Fig. 12: EHL flow film at 500 mm/s [um]", ("fig12", 500, "hq"), 1e3, 3),
        ] + [(f"Fig. 14: net leakage {tag} [mm^3]", ("fig14", "net", tag), 1, 2)
             for _, tag, _ in FIG14] + [
            ("Fig. 14: IHL net leakage [mm^3]", ("fig14", "ihl"), 1, 2)]
        cols = sorted(cols, key=lambda c: -c[0][0])
        rows = []
        for label, path, f, nd in spec:
            vals = []
            for _, n, _ in cols:
                if path[0] == "fig11":
                    k = "p_max" if path[1] == "pmax" else "h_mean"
                    a = get(n, "fig11", "M0", k, f=f)
                    b = get(n, "fig11", "M1", k, f=f)
                    vals.append("-" if a is None else f"{a:.{nd}f} / {b:.{nd}f}")
                else:
                    x = get(n, *path, f=f)
                    vals.append("-" if x is None else f"{x:.{nd}f}")
            rows.append([label] + vals)
        head = ["quantity"] + [mesh_label(m) + (" (this report)" if n is A else "")
                               for m, n, _ in cols]
        where = ", ".join(f"`{rel(d)}`" for _, _, d in cols if d is not None)
        self.add(f"""
## Mesh check

The same numbers from the runs on other meshes (contact / bulk element size) in {where};
"-" where a run is not there. The README's study of the hyperelastic cycle: net leakage
{study(1)}; outstroke volume {study(2)}.

{table(head, rows)}
""")

    def section(self, title, fn):
        try:
            fn()
        except MissingOutput as e:
            self.add(f"## {title}\n\n*Not available: a run did not finish ({rel(e.path)} is "
                     "missing; see its log.txt).*\n")

    # ---- Fig. 8 -------------------------------------------------------------------------
    def fig8(self):
        out = self.out
        P = {d: profiles(out, f"fig8_{d}") for d in ("out", "in")}
        S = {d: at_end(output(out, f"fig8_{d}").series) for d in ("out", "in")}
        bfull = contact_band(P["out"][0.0])
        b = band_core(bfull, TRIM)
        M = {d: film_metrics(P[d][max(P[d])], b) for d in P}
        steady = {d: steady_change(P[d], b) for d in P}
        share = {d: asperity_share(S[d]) for d in P}
        ratio = {d: M[d]["taus_max"] / M[d]["tau_max"] for d in P}
        fratio = {d: abs(S[d]["friction_solid"] / S[d]["friction_fluid"]) for d in P}
        hq = {d: flow_film(S[d]["Q_out"], S[d]["v"], self.area(f"fig8_{d}")) for d in P}
        dry = self.dry_peak
        h_mix = self.scene("fig8_out").asperity.h_mix
        lo, hi = PAPER["fig8_p_max"]
        film = PAPER["fig8_film"]
        stroke = self.scene("fig8_out").stroke
        self.numbers["fig8"] = {"metrics": M, "share": share, "ratio": ratio, "hq": hq}

        plt = self.plt
        fig, ax = plt.subplots(1, 2, figsize=(12, 4.4))
        a2 = ax[0].twinx()
        for d, c in (("out", "C0"), ("in", "C3")):
            pr = P[d][max(P[d])]
            lab = "outstroke" if d == "out" else "instroke"
            ax[0].plot(pr["y"], pr["h"] * 1e3, c + "-", lw=2, label=f"h, {lab}")
            a2.plot(pr["y"], pr["p"], c + "--", label=f"p_fl, {lab}")
            a2.plot(pr["y"], pr["p_asperity"], c + ":", lw=2, label=f"p_s, {lab}")
        ax[0].set_ylim(0, 1.5)
        ax[0].axhline(h_mix * 1e3, color="gray", lw=0.8)
        ax[0].text(bfull[0] - 0.3, h_mix * 1e3 + 0.02, "h_mix", color="gray", fontsize=8)
        ax[0].set_ylabel("film thickness h [um]")
        a2.set_ylabel("pressures p_fl, p_s [MPa]")
        a2.set_ylim(-0.6, 3.6)
        zoom(ax[0], None, bfull)
        ax[0].set_xlabel("axial position y [mm] (pressurised side left)")
        h1, l1 = ax[0].get_legend_handles_labels()
        h2, l2 = a2.get_legend_handles_labels()
        ax[0].legend(h1 + h2, l1 + l2, fontsize=7, loc="upper left", ncol=2)
        ax[0].set_title("(a) film thickness, fluid and solid contact pressure")
        a3 = ax[1].twinx()
        for d, c in (("out", "C0"), ("in", "C3")):
            pr = P[d][max(P[d])]
            lab = "outstroke" if d == "out" else "instroke"
            ax[1].plot(pr["y"], pr["tau"] * 1e3, c + "-", label=f"tau_fl, {lab}")
            a3.plot(pr["y"], pr["tau_solid"], c + ":", lw=2, label=f"tau_s, {lab}")
        lim = 1.1 * max(abs(P[d][max(P[d])]["tau"]).max() for d in P) * 1e3
        ax[1].set_ylim(-lim, lim)
        lim_s = 1.1 * max(abs(P[d][max(P[d])]["tau_solid"]).max() for d in P)
        a3.set_ylim(-lim_s, lim_s)
        ax[1].set_ylabel("fluid shear stress tau_fl [1e-3 MPa]")
        a3.set_ylabel("solid shear stress tau_s [MPa]")
        zoom(ax[1], None, bfull)
        ax[1].set_xlabel("axial position y [mm]")
        h1, l1 = ax[1].get_legend_handles_labels()
        h2, l2 = a3.get_legend_handles_labels()
        ax[1].legend(h1 + h2, l1 + l2, fontsize=7, loc="lower left")
        ax[1].set_title("(b) shear stresses on the seal (+y = outstroke direction)")
        name = self.savefig(fig, "fig8_profiles.png")

        o, i = M["out"], M["in"]
        neg = o["p_min"] < 0.0
        outlet = o["y_pmin"] > 0.5 * (b[0] + b[1])
        rows = [
            ["film thickness in the contact", f"about {um(film, 0)}",
             f"out: mean {um(o['h_mean'])}, min {um(o['h_min'])}; "
             f"in: mean {um(i['h_mean'])}, min {um(i['h_min'])}"],
            ["film that carries the flow, 2 Q / (A v)", "-",
             f"out {um(hq['out'])}, in {um(hq['in'])}"],
            ["lubrication state", "mixed",
             f"{word(min(share.values()) > 0.01, 'mixed', 'not mixed')}: asperities carry "
             f"{100 * share['out']:.0f} % (out) and {100 * share['in']:.0f} % (in) of the rod "
             f"load; min h {um(min(o['h_min'], i['h_min']))} against h_mix = {um(h_mix)}"],
            ["peak fluid pressure", f"{lo:g}-{hi:g} MPa",
             f"out {mpa(o['p_max'])}, in {mpa(i['p_max'])}"],
            ["peak solid contact pressure", "out < in",
             f"out {mpa(o['pa_max'])}, in {mpa(i['pa_max'])}"],
            ["peak fluid shear stress", "out > in",
             f"out {o['tau_max'] * 1e3:.2f}e-3 MPa, in {i['tau_max'] * 1e3:.2f}e-3 MPa"],
            ["peak solid shear stress", "out < in",
             f"out {o['taus_max']:.3f} MPa, in {i['taus_max']:.3f} MPa"],
            ["solid / fluid shear (peaks)", "about 100 (two orders)",
             f"out {ratio['out']:.0f}, in {ratio['in']:.0f}"],
            ["solid / fluid friction force", "-",
             f"out {fratio['out']:.0f} ({S['out']['friction_solid']:.1f} / "
             f"{S['out']['friction_fluid']:.2f} N), in {fratio['in']:.0f}"],
            ["negative fluid pressure, outstroke", "yes, at the outlet",
             f"{word(neg, 'yes', 'no')}: {mpa(o['p_min'])} at y = {o['y_pmin']:.2f} mm "
             f"({word(outlet, 'outlet (atmosphere) side', 'inlet side')})"],
            ["negative fluid pressure, instroke", "-",
             f"{word(i['p_min'] < -1e-3, 'yes', 'none')} (lowest {mpa(i['p_min'])})"],
        ]
        st = ", ".join(f"{d}stroke {100 * steady[d][0]:.2g} %" for d in P)
        self.add(f"""
## 1. Fig. 8: outstroke and instroke at {stroke.v_max:g} mm/s, p_in = {self.scene("fig8_out").fluid.p_in:g} MPa

Scenes `paper_fig8_outstroke.toml` and `paper_fig8_instroke.toml`: from the pressurised
state the rod ramps to +{stroke.v_max:g} / -{stroke.v_max:g} mm/s in {stroke.t_ramp:g} s and
holds that speed to t = {stroke.t_end:g} s; long-term (hyperelastic) material, transient
Reynolds, no flow factors, friction on. The profiles are those at t = {max(P['out']):g} s.
**Steady:** the film in the contact band changed by at
most {st} of its mean between t = {steady['out'][1]:g} s and {steady['out'][2]:g} s.
The contact band (y = {bfull[0]:.2f} to {bfull[1]:.2f} mm) is where the asperity law carries
load at rest; film statistics are taken over its inner {100 * (1 - 2 * TRIM):.0f} % (y = {b[0]:.2f} to {b[1]:.2f} mm),
clear of the steep flanks of the menisci. The plots show the current axial position y, the groove centred at y = 0, the
sealed pressure on the left (small y).

![Fig. 8]({name})

{table(["quantity", "paper", "sealts"], rows)}

**Agreement.** The contact is {word(min(share.values()) > 0.01, 'mixed', 'not mixed')}, the
fluid shear is {min(ratio.values()):.0f}-{max(ratio.values()):.0f} times below the solid
shear (the paper: about two orders of magnitude), the outstroke has the {word(o['p_max'] > i['p_max'], 'higher', 'lower')} fluid
pressure and the {word(o['tau_max'] > i['tau_max'], 'higher', 'lower')} fluid shear, the
{word(o['pa_max'] < i['pa_max'], 'lower', 'higher')} solid contact pressure and the
{word(o['taus_max'] < i['taus_max'], 'lower', 'higher')} solid shear, and the outstroke's
fluid pressure {word(neg and outlet, 'turns negative at the outlet', 'does not turn negative at the outlet')}
(no cavitation model, as in the paper).

**Differences.** (i) *Peak fluid pressure* {mpa(o['p_max'])} against the paper's
{lo:g}-{hi:g} MPa. In soft EHL the film hardly moves the seal, so fluid plus asperity pressure
stays close to the dry contact pressure: its peak here is {mpa(M['out']['total_max'])}
(out) and {mpa(M['in']['total_max'])} (in), and the pressurised O-ring's dry contact peaks
at {mpa(dry)} ({DRY_PEAK_PAPER_MESH:g} MPa on the paper's mesh, README). A fluid pressure of
{lo:g}-{hi:g} MPa is {word(dry < lo, "more than this O-ring's whole contact pressure",
"within this O-ring's contact pressure")} at {self.scene("fig8_out").fluid.p_in:g} MPa, so the paper's seal
{word(dry < lo, "presses harder on the rod than this one", "need not press harder on the rod than this one")}
(its Fig. 8a pressure axis does reach {PAPER['fig8_p_axis']:g} MPa),
for reasons the paper does not give: its geometry and material (Table 3) are the ones used
here, and it gives no dry contact pressure to compare. With the lower pressure
and the asperities carrying {100 * share['out']:.0f}-{100 * share['in']:.0f} % of the load,
the fluid peak is lower. (ii) *Film thickness*: {um(o['h_mean'])} (out) and
{um(i['h_mean'])} (in) on average over the band, against "about {um(film, 0)}". The paper's own
mixed contact needs h below h_mix = {um(h_mix, 1)} where the asperities touch, so its "about {um(film, 0)}"
is the order of the film (its Fig. 8a axis runs 0-1 um), not a film of 1 um throughout;
here it is {100 * o['h_mean'] / film:.0f} % (out) and {100 * i['h_mean'] / film:.0f} % (in) of that.
Coarse meshes thin the film: the film carried out on the README's cycle grows with
refinement up to the 0.025 mm contact mesh (outstroke volume {study(2)}), and the
inlet rise of the contact pressure, where
the film forms, spans {self.inlet_elements:.0f} element{'' if self.inlet_elements == 1 else 's'} of this mesh.
""")

    # ---- Fig. 9 -------------------------------------------------------------------------
    def fig9(self):
        out = self.out
        L = profiles(out, "fig9_lt")
        V = profiles(out, "fig9_ve")
        sv = output(out, "fig9_ve").series
        slt = output(out, "fig9_lt").series
        sl = at_end(slt)
        area = self.area("fig9_ve")
        bfull = contact_band(L[0.0])
        b = band_core(bfull, TRIM)
        lt = L[max(L)]
        steady = steady_change(L, b)
        times = [t for t in sorted(V) if t > 0.0]
        t0 = times[0]                    # end of the ramp
        t0h = 1.0 if 1.0 in V else t0     # the paper's "0 h": the film formed
        hq_lt = flow_film(sl["Q_out"], sl["v"], area)
        rows, diffs = [], {}
        for t in times:
            pr = V[t]
            m = in_band(pr, b)
            _, d = film_change(pr, lt, b)
            k = int(np.argmin(np.abs(sv["t"] - t)))
            hq = flow_film(sv["Q_out"][k], sv["v"][k], area)
            diffs[t] = {"max": float(d.max()), "min": float(d.min()), "mean": float(d.mean()),
                        "hq": hq, "h_mean": float(pr["h"][m].mean())}
            lab = self._when(t)
            rows.append([lab, f"{relaxation_modulus(t):.2f}", um(pr["h"][m].mean()),
                         um(pr["h"][m].min()), f"{d.mean() * 1e3:+.3f} um",
                         f"{d.min() * 1e3:+.3f} .. {d.max() * 1e3:+.3f} um", um(hq),
                         f"{(hq - hq_lt) * 1e3:+.3f} um"])
        m = in_band(lt, b)
        rows.append(["long-term, steady", "1", um(lt["h"][m].mean()), um(lt["h"][m].min()),
                     "0", "0", um(hq_lt), "0"])
        same = None
        if t0 in L:                      # the long-term film at the end of the ramp too
            a = L[t0]
            _, dd = film_change(V[t0], a, b)
            k = int(np.argmin(np.abs(slt["t"] - t0)))
            same = {"mean": float(dd.mean()), "max": float(dd.max()),
                    "lt_mean": float(a["h"][in_band(a, b)].mean()),
                    "hq": flow_film(slt["Q_out"][k], slt["v"][k], area)}
            rows.append([f"long-term at {t0:g} s", "1", um(same["lt_mean"]),
                         um(a["h"][in_band(a, b)].min()), "", "", um(same["hq"]), ""])
        self.numbers["fig9"] = {"diffs": diffs, "hq_lt": hq_lt, "same": same}
        stroke = self.scene("fig9_ve").stroke
        excess = PAPER["fig9_excess"]

        plt = self.plt
        fig, ax = plt.subplots(1, 3, figsize=(15, 4.4))
        paper_times = [t for t in times if t == t0h or t / 3600.0 in PAPER["fig9_hours"]]
        for t in times:
            pr = V[t]
            lab = f"viscoelastic, t = {self._when(t)}"
            style = "-" if t in paper_times else ":"
            ax[0].plot(pr["y"], pr["h"] * 1e3, style, label=lab)
            yb, d = film_change(pr, lt, b)
            ax[1].plot(yb, d * 1e3, style, label=lab)
        ax[0].plot(lt["y"], lt["h"] * 1e3, "k-", lw=2.5, label="long-term (steady)")
        if same is not None:
            ax[0].plot(L[t0]["y"], L[t0]["h"] * 1e3, "k--", lw=1.2, label=f"long-term, t = {t0:g} s")
        ax[0].set_ylim(0, 1.5)
        zoom(ax[0], None, bfull)
        ax[0].set_xlabel("axial position y [mm]")
        ax[0].set_ylabel("film thickness h [um]")
        ax[0].legend(fontsize=7)
        ax[0].set_title(f"(a) film at {stroke.v_max:g} mm/s")
        ax[1].axhline(excess * 1e3, color="gray", ls="--", lw=0.8)
        ax[1].text(b[0], excess * 1e3 + 0.005, f"paper: at most +{um(excess, 2)} (at 0 h)",
                   color="gray", fontsize=8)
        ax[1].axhline(0.0, color="k", lw=0.8)
        ax[1].set_ylim(-0.25, 0.2)
        ax[1].set_xlabel("axial position y [mm] (contact band)")
        ax[1].set_ylabel("h viscoelastic - h long-term (steady) [um]")
        ax[1].set_title("(b) difference from the long-term film")
        keep = sv["t"] >= t0 * (1 - 1e-9)
        ax[2].semilogx(sv["t"][keep], flow_film(sv["Q_out"][keep], sv["v"][keep], area) * 1e3,
                       "C0.-", ms=3, label="viscoelastic")
        kl = slt["t"] >= t0 * (1 - 1e-9)
        ax[2].semilogx(slt["t"][kl], flow_film(slt["Q_out"][kl], slt["v"][kl], area) * 1e3,
                       "k.-", ms=3, label="long-term (to steady)")
        ax[2].axhline(hq_lt * 1e3, color="k", lw=0.8)
        ax[2].set_xlabel("time t [s] (from the end of the ramp)")
        ax[2].set_ylabel("flow film 2 Q_out / (A v) [um]")
        ax[2].set_title("(c) film carried out of the seal")
        ax[2].legend(fontsize=8)
        ax[2].grid(alpha=0.3)
        name = self.savefig(fig, "fig9_viscoelastic.png")

        hours = [t for t in times if t >= 3600.0]
        d0, dend = diffs[t0h], diffs[times[-1]]
        dmax = max(v["max"] for v in diffs.values())
        above = [t for t in times if diffs[t]["mean"] > 0.0]
        if not above:
            course = "below it throughout"
        elif above[0] == t0:
            course = "above it from the start"
        else:
            course = (f"below it until {self._when(above[0])}, then slightly above")
        decay = ", ".join(f"{t / 3600:g} h: {diffs[t]['mean'] * 1e3:+.3f}" for t in hours)
        F = abs(sl["friction_total"])
        F_peak = float(np.abs(sv["friction_total"]).max())
        formed = [t for t in times if t >= t0h]
        d_formed = max(abs(diffs[t]["mean"]) for t in formed)
        if same is not None:
            same_txt = (f"At the end of the ramp ({t0:g} s) both films are still forming; "
                        f"there the viscoelastic film differs from the long-term one at the "
                        f"same time by {same['mean'] * 1e3:+.3f} um on average.")
        else:
            same_txt = ""
        self.numbers["fig9"].update(t0h=t0h, d0h=d0["mean"], d15=dend["mean"], dmax=dmax)
        tau = np.sort(table2().tau)
        extra = [t for t in times if t not in paper_times and t != t0]
        t_min = self.scene("fig9_ve").viscoelastic.t_min
        self.add(f"""
## 2. Fig. 9: viscoelastic against long-term at {stroke.v_max:g} mm/s

Scenes `paper_fig9_viscoelastic.toml` (Table 2 Prony series, relaxed start from the
pressurised long-term state; ramp to +{stroke.v_max:g} mm/s in {stroke.t_ramp:g} s, then held
to {stroke.t_end:,.0f} s = {self._when(stroke.t_end)}; transient Reynolds; terms faster than
{self._when(t_min)} folded in as relaxed) and
`paper_fig9_longterm.toml` (long-term material, the same ramp, held until steady: the film
changed by {100 * steady[0]:.2g} % between t = {steady[1]:g} s and {steady[2]:g} s). The
paper's "0 h" is taken as t = {t0h:g} s, when the film has formed ({t0h - t0:g} s after the
ramp); {t0:g} s (the end of the ramp, the film still forming) and
{", ".join(self._when(t) for t in extra) or "no other times"} are extra times. G(t)/G_inf is Table 2's relaxation modulus for a load applied at t = 0: the stiffness
the seal meets for the stroke's loads. Films and differences are taken over the contact
band without {100 * TRIM:.0f} % of its width at each end (y = {b[0]:.2f} to {b[1]:.2f} mm), where the
steep flanks of the menisci would turn tiny axial shifts into large differences of h.

![Fig. 9]({name})

{table(["time", "G(t)/G_inf", "mean h", "min h", "h_ve - h_lt, mean", "h_ve - h_lt, range", "flow film 2Q/(Av)", "flow film - long-term"], rows)}

| quantity | paper | sealts |
|---|---|---|
| viscoelastic film against long-term at "0 h" | thicker, by up to about {um(excess, 2)} | {word(d0['mean'] > 0, 'thicker', 'thinner')}: mean {d0['mean'] * 1e3:+.3f} um, range {d0['min'] * 1e3:+.3f} .. {d0['max'] * 1e3:+.3f} um at {t0h:g} s |
| largest excess over long-term, any time | about {um(excess, 2)} | {dmax * 1e3:+.3f} um |
| over {", ".join(f"{x:g}" for x in PAPER["fig9_hours"])} h | decays towards long-term from above | mean difference {decay} um |

**Difference.** {self._fig9_summary(diffs, times, t0h, dend, d_formed, course, same_txt)}

Why the effect is small: the viscoelastic run starts relaxed, with the long-term stress state of the
pressurised seal, so at t = 0 it presses on the rod with exactly the long-term contact
pressure. In soft EHL the film follows from that pressure profile (inverse theory:
h* = sqrt(8 eta v / (9 w)) from the steepest inlet rise w, Fig. 12), not from the seal's
stiffness. The stroke's own loads - the film pressure taking over from the asperities and
the friction drag (up to {F_peak:.0f} N while the rod starts sliding, {F:.0f} N once the
film carries the seal at {stroke.v_max:g} mm/s) - meet a seal {relaxation_modulus(1.0):.1f} times
stiffer than long-term at 1 s and {relaxation_modulus(3600.0):.1f} times at 1 h, which
deforms less at first and creeps later, but these loads move the inlet gradient only a
little, so the film moves only a little. What in the paper's set-up makes its
viscoelastic film {um(excess, 2)} thicker at 0 h, relaxing over hours (the time scale of
Table 2's two slowest terms, {tau[-2]:,.0f} s and {tau[-1]:,.0f} s), is not stated; with a
relaxed start (the scenes' reading of the paper's step 3), sealts gets
{word(dmax > 0, f"{100 * dmax / excess:.0f} % of that excess at most", "no excess")}.
A start that is not relaxed would change the contact pressure itself and is the next
thing to test.
""")

    def _fig9_summary(self, diffs, times, t0h, dend, d_formed, course, same_txt):
        d0 = diffs[t0h]
        later = [diffs[t]["mean"] for t in times if t >= t0h]
        decays = (d0["mean"] > 0.0 and all(a >= b - 1e-6 for a, b in zip(later, later[1:])))
        dmax = max(v["max"] for v in diffs.values())
        end, slowest = self._when(times[-1]), table2().tau.max()
        unrelaxed = f"{100 * np.exp(-times[-1] / slowest):.0f} % unrelaxed"
        excess = um(PAPER["fig9_excess"], 2)
        if decays:
            t = (f"As in the paper, the viscoelastic film is thicker than the long-term one at "
                 f"0 h and decays towards it over hours ({dend['mean'] * 1e3:+.3f} um on "
                 f"average at {end}, when Table 2's slowest term, {slowest:,.0f} s, is still "
                 f"{unrelaxed}); but the excess is "
                 f"{d0['mean'] * 1e3:+.3f} um on average and {dmax * 1e3:+.3f} um at most, "
                 f"not about {excess}. ")
        else:
            t = (f"sealts finds the viscoelastic film within {d_formed * 1e3:.3f} um (mean over "
                 f"the band) of the long-term one once the film has formed ({course}, ending "
                 f"{dend['mean'] * 1e3:+.3f} um from it at {end}, when Table 2's slowest term "
                 f"is still {unrelaxed}), not thicker by about {excess}. ")
        return t + same_txt + " The sign and size of so small a difference depend on the mesh (see the mesh check at the end)."

    @staticmethod
    def _when(t):
        return f"{t:g} s" if t < 3600 else f"{t / 3600:g} h"

    # ---- Figs. 10-11 ----------------------------------------------------------------------
    def fig10_11(self):
        from sealts.film.flow_factors import FlowFactors
        plt = self.plt
        h = np.linspace(0.0, 5e-3, 501)
        film = self.scene("fig11_ff").film
        rq, gamma = film.rq, film.gamma
        ff = FlowFactors.patir_cheng(rq, gamma, film.rough_surface)
        pp, _, ps, _ = ff.evaluate(h)
        tr = FlowFactors.patir_cheng(rq, 1 / 9, film.rough_surface)
        pp9, _, ps9, _ = tr.evaluate(h)
        fig, ax = plt.subplots(figsize=(6.5, 4.2))
        ax.plot(h * 1e3, pp, "C0-", lw=2, label=f"Phi_p, gamma = {gamma:.3g} (used)")
        ax.plot(h * 1e3, ps, "C3-", lw=2, label=f"Phi_s, gamma = {gamma:.3g} (used)")
        ax.plot(h * 1e3, pp9, "C0:", label="Phi_p, gamma = 1/9 (transverse)")
        ax.plot(h * 1e3, ps9, "C3:", label="Phi_s, gamma = 1/9 (transverse)")
        ax.axvline(0.5 * rq * 1e3, color="gray", lw=0.8)
        ax.text(0.5 * rq * 1e3 + 0.03, 1.9, "H = 0.5: fits end,\nC1 extension below",
                fontsize=7, color="gray", va="top")
        ax.set_xlim(0, 5)
        ax.set_ylim(0, 2)
        ax.set_xlabel("film thickness h [um]")
        ax.set_ylabel("flow factors Phi_p, Phi_s [-]")
        ax.set_title(f"Patir-Cheng flow factors, Rq = {rq * 1e3:.3f} um")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
        name10 = self.savefig(fig, "fig10_flow_factors.png")
        hs = np.array([0.1, 0.25, 0.5, 1.0, 2.0, 5.0]) * 1e-3
        pp_s, _, ps_s, _ = ff.evaluate(hs)
        rows10 = [[f"{x * 1e3:g}", f"{x / rq:.2f}", f"{a:.3f}", f"{c:.3f}"]
                  for x, a, c in zip(hs, pp_s, ps_s)]

        out = self.out
        P0 = profiles(out, "fig8_out")
        P1 = profiles(out, "fig11_ff")
        S0 = at_end(output(out, "fig8_out").series)
        S1 = at_end(output(out, "fig11_ff").series)
        bfull = contact_band(P0[0.0])
        b = band_core(bfull, TRIM)
        a, c = P0[max(P0)], P1[max(P1)]
        M0, M1 = film_metrics(a, b), film_metrics(c, b)
        steady = steady_change(P1, b)
        hq0 = flow_film(S0["Q_out"], S0["v"], self.area("fig8_out"))
        hq1 = flow_film(S1["Q_out"], S1["v"], self.area("fig11_ff"))
        stroke = self.scene("fig11_ff").stroke
        fig, ax = plt.subplots(1, 2, figsize=(12, 4.4))
        a2 = ax[0].twinx()
        for pr, st, lab in ((a, "-", "no flow factors"), (c, "--", "flow factors")):
            ax[0].plot(pr["y"], pr["h"] * 1e3, "k" + st, lw=2, label=f"h, {lab}")
            a2.plot(pr["y"], pr["p"], "C0" + st, label=f"p_fl, {lab}")
            a2.plot(pr["y"], pr["p_asperity"], "C3" + st, label=f"p_s, {lab}")
        ax[0].set_ylim(0, 1.5)
        a2.set_ylim(-0.6, 3.6)
        zoom(ax[0], None, bfull)
        ax[0].set_xlabel("axial position y [mm]")
        ax[0].set_ylabel("film thickness h [um]")
        a2.set_ylabel("pressures p_fl, p_s [MPa]")
        h1, l1 = ax[0].get_legend_handles_labels()
        h2, l2 = a2.get_legend_handles_labels()
        ax[0].legend(h1 + h2, l1 + l2, fontsize=7, loc="upper left", ncol=2)
        ax[0].set_title(f"(a) outstroke +{stroke.v_max:g} mm/s: film and pressures")
        a3 = ax[1].twinx()
        for pr, st, lab in ((a, "-", "no flow factors"), (c, "--", "flow factors")):
            ax[1].plot(pr["y"], pr["tau"] * 1e3, "C0" + st, label=f"tau_fl, {lab}")
            a3.plot(pr["y"], pr["tau_solid"], "C3" + st, label=f"tau_s, {lab}")
        ax[1].set_ylabel("fluid shear stress tau_fl [1e-3 MPa]")
        a3.set_ylabel("solid shear stress tau_s [MPa]")
        tf = 1.1e3 * max(np.abs(pr["tau"]).max() for pr in (a, c))
        ts = 1.1 * max(np.abs(pr["tau_solid"]).max() for pr in (a, c))
        ax[1].set_ylim(-0.25 * tf, tf)            # zero on both axes at the same height
        a3.set_ylim(-0.25 * ts, ts)
        ax[1].axhline(0.0, color="k", lw=0.6)
        zoom(ax[1], None, bfull)
        ax[1].set_xlabel("axial position y [mm]")
        h1, l1 = ax[1].get_legend_handles_labels()
        h2, l2 = a3.get_legend_handles_labels()
        ax[1].legend(h1 + h2, l1 + l2, fontsize=7, loc="lower center")
        ax[1].set_title("(b) shear stresses on the seal")
        name11 = self.savefig(fig, "fig11_flow_factors.png")
        share0, share1 = asperity_share(S0), asperity_share(S1)
        rows = [
            ["peak fluid pressure", "higher with", mpa(M0["p_max"]), mpa(M1["p_max"])],
            ["mean film in the band", "thicker with", um(M0["h_mean"]), um(M1["h_mean"])],
            ["min film in the band", "thicker with", um(M0["h_min"]), um(M1["h_min"])],
            ["flow film 2 Q / (A v)", "-", um(hq0), um(hq1)],
            ["peak solid contact pressure", "lower with", mpa(M0["pa_max"]), mpa(M1["pa_max"])],
            ["asperity share of the rod load", "lower with", f"{100 * share0:.1f} %",
             f"{100 * share1:.1f} %"],
            ["peak solid shear stress", "lower with", f"{M0['taus_max']:.3f} MPa",
             f"{M1['taus_max']:.3f} MPa"],
            ["solid friction force", "lower with", f"{S0['friction_solid']:.2f} N",
             f"{S1['friction_solid']:.2f} N"],
        ]
        self.numbers["fig11"] = {"M0": M0, "M1": M1, "share": (share0, share1), "hq": (hq0, hq1)}
        hi_p = M1["p_max"] > M0["p_max"]
        thick = M1["h_mean"] > M0["h_mean"]
        low_s = M1["pa_max"] < M0["pa_max"]
        self.add(f"""
## 3. Figs. 10-11: flow factors

**The choice.** The paper's flow factors (its Fig. 10) were computed for its turned rod
with a code of its own and are published only as a plot. sealts uses Patir and Cheng's
published fits instead (`[film] flow_factors = "patir-cheng"`), for Gaussian
roughness of Peklenik number gamma = {gamma:.3g}{word(gamma == 1.0, " (isotropic)", "")}, with the
paper's composite roughness Rq = {rq:.2e} mm (Table 3) on the {film.rough_surface}, so that the shear-flow term has the sign Eq. 13
prints (h - Rq Phi_s). Below H = h/Rq = 0.5, where the fits end, sealts continues them C1
and monotone towards 0 (`sealts/film/flow_factors.py`). The paper's Phi_p rises from 0 at
h = 0 to 1 at about 5 um and its Phi_s is a bump; here Phi_p rises from {pp[0]:.2f} at
h = 0 (the C1 extension decays towards 0 only as h falls below 0, in asperity contact) to
{float(ff.evaluate(np.array([1e-3]))[0][0]):.2f} at 1 um, and Phi_s peaks at
{ps.max():.2f} at h = {h[int(np.argmax(ps))] * 1e3:.2f} um. The turned surface's transverse
lay would be closer to gamma < 1 (dotted: Phi_p about 0 below H = 1, a larger Phi_s), which
this report does not run.

![Fig. 10]({name10})

{table(["h [um]", "H = h/Rq", "Phi_p", "Phi_s"], rows10)}

Scene `paper_fig11_flowfactors.toml` is `paper_fig8_outstroke.toml` (steady outstroke at
+{stroke.v_max:g} mm/s, p_in = {self.scene("fig11_ff").fluid.p_in:g} MPa, long-term) with these flow factors; steady: the film changed by
{100 * steady[0]:.2g} % between t = {steady[1]:g} s and {steady[2]:g} s.

![Fig. 11]({name11})

{table(["quantity", "paper (flow factors on)", "without", "with"], rows)}

**Agreement.** With flow factors the fluid pressure is
{word(hi_p, 'higher', 'lower')}, the film {word(thick, 'thicker', 'thinner')} and the solid
contact pressure {word(low_s, 'lower', 'higher')}{word(hi_p and thick and low_s, ', as in the paper', '')}.
Phi_p < 1 throttles the pressure flow, so the same flow needs steeper gradients and the
film must open to pass it. The flow itself *{word(hq1 < hq0, 'falls', 'rises')}* (flow film {um(hq0)} without,
{um(hq1)} with): at the pressure peak q = v (h - Rq Phi_s) / 2, and the shear-flow term of
a rough seal, Rq Phi_s = {um(rq * float(ff.evaluate(np.array([M1['h_at_pmax']]))[2][0]))}
there, is taken off the Couette flow. So flow factors carry {word(hq1 < hq0, 'less', 'more')} out
of the seal on the outstroke; how they change the cycle's net leakage depends on what they
carry back on the instroke (Fig. 14). The changes are small because in the contact band
h/Rq = {M0['h_mean'] / rq:.1f} on average, where
Phi_p = {float(ff.evaluate(np.array([M0['h_mean']]))[0][0]):.2f}: the paper's factors, for a
rougher turned surface, may act more strongly; their size is not given as numbers.
""")

    # ---- Fig. 12 ------------------------------------------------------------------------
    def fig12(self):
        out = self.out
        plt = self.plt
        fig, ax = plt.subplots(1, 2, figsize=(13, 4.6))
        rows = []
        self.numbers["fig12"] = {}
        self.ihl_check = []
        for k, v in enumerate((100, 500)):
            key = f"fig12_{v}"
            try:
                P = profiles(out, key)
                S = at_end(output(out, key).series)
            except MissingOutput:
                ax[k].set_title(f"({'ab'[k]}) {v} mm/s: not run")
                continue
            ih, ip, src = self.ihl_dry(v)
            bfull = contact_band(P[0.0])
            b = band_core(bfull, TRIM)
            pr = P[max(P)]
            M = film_metrics(pr, b)
            steady = steady_change(P, b)
            hq = flow_film(S["Q_out"], S["v"], self.area(key))
            hs = ih["outstroke"]["h_star"]
            share = asperity_share(S)
            y_w = ih["outstroke"]["y_w"]
            h_ihl = ihl_film(ip["y"], ip["p"], ip["dp_dy"], float(v), hs, y_w,
                             self.scene(f"ihl12_{v}").fluid.viscosity)
            i0, iw = inlet_nodes(ip, y_w, 1.0)
            self.numbers["fig12"][v] = {"hq": hq, "h_star": hs, "share": share, "M": M,
                                        "src": src,
                                        "ripple": ripple(pr, b),
                                        "inlet": inlet_span(ip, y_w, 1.0),
                                        "inlet_gaps": (ip["h"][i0], ip["h"][iw],
                                                       abs(ip["y"][iw] - ip["y"][i0])),
                                        "h_mix": self.scene(key).asperity.h_mix}
            rows.append([f"{v} mm/s", um(hs), um(hq), f"{100 * (hq / hs - 1):+.0f} %",
                         um(M["h_at_pmax"]), um(M["h_min"]),
                         f"{100 * share:.1f} %", mpa(M["p_max"]), mpa(ip["p"].max()),
                         f"{100 * steady[0]:.2g} %"])
            a = ax[k]
            a2 = a.twinx()
            a.plot(pr["y"], pr["h"] * 1e3, "k-", lw=2, label="h EHL")
            a.plot(ip["y"], h_ihl * 1e3, "k--", lw=2, label="h IHL")
            a.axhline(hs * 1e3, color="gray", ls=":", lw=1, label="h* IHL")
            a2.plot(pr["y"], pr["p"], "C0-", label="p_fl EHL")
            a2.plot(pr["y"], pr["p_asperity"], "C3-", label="p_s EHL")
            a2.plot(ip["y"], ip["p"], "C0--", label="p_fl IHL (= dry contact pressure)")
            a.set_ylim(0, 1.5)
            a2.set_ylim(-0.4, 2.4)
            zoom(a, None, bfull)
            a.set_xlabel("axial position y [mm]")
            a.set_ylabel("film thickness h [um]")
            a2.set_ylabel("pressures [MPa]")
            a.set_title(f"({'ab'[k]}) {v} mm/s, p_in = p_out = 0")
            h1, l1 = a.get_legend_handles_labels()
            h2, l2 = a2.get_legend_handles_labels()
            a.legend(h1 + h2, l1 + l2, fontsize=7, loc="upper left", ncol=2)
        name = self.savefig(fig, "fig12_ihl_ehl.png")
        n = self.numbers["fig12"]
        if len(n) < 2:
            self.add(f"""
## 4. Fig. 12: EHL against IHL, p_in = p_out = 0 (partial)

Only {', '.join(f'{v} mm/s' for v in n) or 'no speed'} ran here; IHL from {', '.join(x['src'] for x in n.values())}.

![Fig. 12]({name})

{table(["speed", "IHL h*", "EHL flow film", "EHL / IHL", "EHL h at p peak", "EHL min h", "asperity share", "EHL peak p_fl", "dry peak", "steady (dh)"], rows)}
""")
            return
        d100 = n[100]["hq"] / n[100]["h_star"] - 1
        d500 = n[500]["hq"] / n[500]["h_star"] - 1
        stroke = self.scene("fig12_500").stroke
        self.add(f"""
## 4. Fig. 12: EHL against IHL, p_in = p_out = 0

Scenes `paper_fig12_100.toml` and `paper_fig12_500.toml`: the O-ring mounted dry without
pressure (`paper_state_0mpa.toml`), the rod ramped to +100 / +500 mm/s in
{stroke.t_ramp:g} s and held to t = {stroke.t_end:g} s (long-term material; transient Reynolds run to steady, friction on). IHL:
`sealts ihl` on `paper_fig12_ihl.toml` at 100 and 500 mm/s (the same dry mounted seal):
h* = sqrt(8 eta v / (9 w)) from the steepest inlet rise w of the dry contact pressure. The
IHL film profile in the figure is Blok's construction from the same profile
(6 eta v (h - h*)/h^3 = dp/dy, thick root before the steepest rise); the IHL film
pressure is the dry contact pressure. The fair single-number comparison is the film that
carries the flow: q = v h*/2 in IHL, 2 Q_out / (A v) in EHL (equal to h at the pressure
peak of a steady, smooth film). {self._ihl_check_text()}

![Fig. 12]({name})

{table(["speed", "IHL h*", "EHL flow film", "EHL / IHL", "EHL h at p peak", "EHL min h", "asperity share", "EHL peak p_fl", "dry peak", "steady (dh)"], rows)}

| quantity | paper | sealts |
|---|---|---|
| 500 mm/s | full film: IHL and EHL coincide | EHL flow film {100 * d500:+.0f} % from IHL h*; asperities carry {100 * n[500]['share']:.1f} % |
| 100 mm/s | mixed: IHL and EHL differ | EHL flow film {100 * d100:+.0f} % from IHL h*; asperities carry {100 * n[100]['share']:.1f} % |

**Reading.** {self._fig12_text(n, d100, d500)}
""")

    def _ihl_check_text(self):
        if not self.ihl_check:
            return ""
        return (f"(Cross-check: the same estimate from the dry profile that the mount-only "
                f"state run wrote gives h* within {max(self.ihl_check):.1e} of `sealts ihl`'s.)")

    def _ripple_across(self):
        vals = self.values_across("fig12", 500, "ripple", f=1e3)
        if len(vals) < 2:
            return ""
        fades = vals[-1][1] < 0.5 * vals[0][1]
        return (f"{word(fades, 'It fades as the mesh is refined', 'Over the meshes')} "
                f"(+-{self.across('fig12', 500, 'ripple', f=1e3, unit='um')}). ")

    def ihl_dry(self, v):
        """(IHL summary, IHL profile, source) at speed v for p = 0: `sealts ihl`'s run when
        there is one, else the same estimate (:func:`sealts.film.ihl.ihl_estimate`) on the
        dry profile the mount-only state run wrote (profiles.csv at the end of mounting),
        which is what `sealts ihl` computes at p_in = 0. With both, the two are compared
        (``ihl_check``)."""
        from sealts.film.ihl import ihl_estimate, pressure_gradient
        key = f"ihl12_{v}"
        dry = None
        try:
            pr = profiles(self.out, "state_0mpa", "profiles")
            pr = pr[max(pr)]
            y, p = pr["y"], pr["p_contact"]
            dry = (ihl_estimate(y, p, self.scene(key).fluid.viscosity, float(v), self.area(key)),
                   {"y": y, "h": pr["h"], "p_contact": p, "p": p,
                    "dp_dy": pressure_gradient(y, p)})
        except MissingOutput:
            pass
        try:
            ih = output(self.out, key).summary["ihl"]
            ip = profiles(self.out, key, "ihl_profile")[0.0]
        except MissingOutput:
            if dry is None:
                raise
            return dry[0], dry[1], "the mounted state's dry profile (`sealts ihl`'s computation)"
        if dry is not None:
            self.ihl_check.append(abs(dry[0]["outstroke"]["h_star"] / ih["outstroke"]["h_star"] - 1))
        return ih, ip, "`sealts ihl`"

    def _fig12_text(self, n, d100, d500):
        closer = abs(d500) < abs(d100)
        t = (f"The EHL film is {word(closer, 'closer to', 'further from')} the IHL estimate at "
             f"500 mm/s ({100 * d500:+.0f} %) than at 100 mm/s ({100 * d100:+.0f} %), "
             f"{word(closer, 'the trend the paper reports', 'against the paper')}. ")
        h_mix = n[500]["h_mix"]
        if n[500]["share"] > 0.01:
            t += (f"At 500 mm/s the film here is still not fully separated: the IHL film "
                  f"h* = {um(n[500]['h_star'])} "
                  f"{word(n[500]['h_star'] > h_mix, 'exceeds', 'is below')} h_mix = "
                  f"{um(h_mix)}, the EHL "
                  f"film is thinner ({um(n[500]['M']['h_min'])} at its minimum) and the "
                  f"asperities carry {100 * n[500]['share']:.1f} % of the load, so the two do "
                  "not coincide as they do in the paper. ")
        else:
            t += (f"At 500 mm/s the film is full (the asperities carry "
                  f"{100 * n[500]['share']:.1f} % of the load, at the outlet) and EHL and IHL "
                  f"pressures lie on top of each other, as in the paper. ")
        ne = n[500]["inlet"]
        g0, gw, dy = n[500]["inlet_gaps"]
        t += ("What separates the two films at 500 mm/s is where IHL reads its w: the "
              "largest nodal gradient of the dry pressure, which a dry O-ring contact has "
              "at its very edge, where the pressure rises almost like a Hertzian square root "
              "and only the asperity law rounds it. On this mesh the rise from the first "
              f"node in contact (gap {um(g0)}) to the steepest point (gap {um(gw)}, "
              f"{dy:.3f} mm further) spans {ne:.0f} "
              f"element{'' if ne == 1 else 's'}; as the mesh resolves the edge, w grows and "
              "h* falls, while the EHL film, which needs no gradient of the dry profile, "
              "settles. ")
        a_ihl = self.across("fig12", 500, "h_star", f=1e3, unit="um")
        a_ehl = self.across("fig12", 500, "hq", f=1e3, unit="um")
        if a_ihl and a_ehl:
            t += (f"Across meshes, IHL h* at 500 mm/s is {a_ihl}, the EHL flow film "
                  f"{a_ehl}: the EHL film settles, the IHL estimate does not, so "
                  "'IHL and EHL coincide in full film' holds here only as far as the "
                  "mesh happens to place w. ")
        r5, r1 = n[500]["ripple"], n[100]["ripple"]
        t += (f"In full film the EHL film carries a node-to-node ripple of about "
              f"+-{r5 * 1e3:.3f} um (Fig. 12b, also Fig. 9a; +-{r1 * 1e3:.3f} um at 100 mm/s, "
              "where the stiff asperity law damps it). It looks like a mode of the film's "
              "discretisation: the control-volume element flux sees h only through "
              "symmetric Gauss averages over each element, so an alternating h changes "
              "every element's flux alike, to second order, and leaves every nodal balance "
              "unchanged; nothing in the film resists it and only the seal's stiffness "
              "limits it. The flow (an element mean) hardly notices. "
              + self._ripple_across())
        t += (f"At 100 mm/s IHL's h* = {um(n[100]['h_star'])} is "
              f"{word(n[100]['h_star'] < h_mix, 'below', 'above')} h_mix: IHL assumes "
              "the fluid carries the whole contact pressure, while here the asperities carry "
              f"{100 * n[100]['share']:.0f} % of it, so the fluid's pressure profile is flatter "
              "than the dry one and the film differs, as the paper explains.")
        return t

    # ---- Fig. 14 ------------------------------------------------------------------------
    def fig14(self):
        out = self.out
        plt = self.plt
        fig, ax = plt.subplots(1, 2, figsize=(13, 4.6))
        rows, net, qr, tr = [], {}, {}, {}
        for key, tag, what in FIG14:
            try:
                s = output(out, key).series
                st = output(out, key).summary["stroke"]
            except MissingOutput:
                rows.append([tag, what, "(missing)"] + [""] * 8)
                continue
            net[tag] = st["leakage_out"]
            qr[tag] = (float(s["Q_out"].min()), float(s["Q_out"].max()))
            tr[tag] = (st["outstroke_transport"], -st["instroke_transport"])
            ax[0].plot(s["t"], s["Q_out"], label=f"Q {tag}")
            ax[1].plot(s["t"], s["V_out"], label=f"V {tag}")
            rows.append([tag, what, f"{st['leakage_out']:.2f}",
                         f"{st['outstroke_transport']:.1f}",
                         f"{-st['instroke_transport']:.1f}",
                         f"{-st['outstroke_transport'] / st['instroke_transport']:.3f}",
                         f"{s['Q_out'].min():.1f} .. {s['Q_out'].max():.1f}",
                         f"{st['leakage_in'] - st['leakage_out']:+.2f}",
                         f"{st['peak_friction_outstroke']:.1f} / {st['peak_friction_instroke']:.1f}",
                         f"{st['h_min'] * 1e3:.3f}",
                         f"{st['steps_accepted']} / {st['steps_rejected']}"])
        from sealts.contact.rod_motion import motion_from_scene
        ih = output(out, "ihl14").summary["ihl"]
        stroke = self.scene("fig14_he").stroke
        motion = motion_from_scene(stroke)
        t = np.linspace(0.0, stroke.t_end, 4001)
        v = np.array([motion.v(x) for x in t])
        q_ihl = ihl_flow(v, ih["outstroke"]["h_star"], ih["instroke"]["h_star"], ih["speed"],
                         self.area("ihl14"))
        v_ihl = cumulative_volume(t, q_ihl)
        ax[0].plot(t, q_ihl, "k--", lw=1, label="Q IHL")
        ax[1].plot(t, v_ihl, "k--", lw=1, label="V IHL")
        out_ihl = float(cumulative_volume(t, np.maximum(q_ihl, 0.0))[-1])
        net_ihl = float(v_ihl[-1])
        rows.append(["IHL", f"`sealts ihl` films at {ih['speed']:g} mm/s, h* ~ sqrt(|v|)",
                     f"{net_ihl:.2f}", f"{out_ihl:.1f}", f"{out_ihl - net_ihl:.1f}",
                     f"{out_ihl / (out_ihl - net_ihl):.3f}",
                     f"{q_ihl.min():.1f} .. {q_ihl.max():.1f}", "-", "-",
                     f"{min(ih['outstroke']['h_star'], ih['instroke']['h_star']) * 1e3:.3f} (h*)",
                     "-"])
        for a in ax:
            a.set_xlabel("time t [s]")
            a.grid(alpha=0.3)
            a.legend(fontsize=8)
        ax[0].set_ylabel("volume flow rate Q_out [mm^3/s]")
        q_lo, q_hi = PAPER["fig14_q"]
        ax[0].axhline(q_hi, color="gray", ls=":", lw=0.8)
        ax[0].axhline(q_lo, color="gray", ls=":", lw=0.8)
        ax[0].text(0.2, q_hi - 4, f"paper's range: about {q_lo:g} to +{q_hi:g}", color="gray",
                   fontsize=7)
        ax[0].set_title("(a) flow out of the seal at the atmosphere side")
        ax[1].set_ylabel("leakage volume V_out [mm^3]")
        ax[1].plot([stroke.t_end], [PAPER["fig14_net"]], "k*", ms=9,
                   label=f"paper: ve,sq,Φ net (about {PAPER['fig14_net']:g})")
        ax[1].legend(fontsize=8)
        ax[1].set_title("(b) leakage volume")
        name = self.savefig(fig, "fig14_leakage.png")
        self.numbers["fig14"] = {"net": net, "ihl": net_ihl}
        order = self._fig14_order(net)
        starts = [f"{x:g}" for x in [0.0] + motion.reversals(stroke.t_end)]
        starts = " and ".join(filter(None, [", ".join(starts[:-1]), starts[-1]]))
        self.add(f"""
## 5. Fig. 14: leakage over the {stroke.t_end:g} s cycle

Scenes `paper_fig14_he/ve/ve_sq/ve_sq_ff.toml`: the paper's cycle (Fig. 13),
v = {stroke.v_max:g} sin(2 pi t / {stroke.period:g} s) mm/s, outstroke first, from the
pressurised state; friction on.
"Steady Reynolds" is `[film] squeeze = false` (the paper's cases without "sq"); the
viscoelastic runs use Table 2 from a relaxed start (terms faster than
{self._when(self.scene("fig14_ve").viscoelastic.t_min)} folded in);
flow factors as in Fig. 11. Q_out and V_out are the flow and volume leaving the film at
the atmosphere side (+ = out of the cylinder); the short spikes at t = {starts} s in the
squeeze variants are squeeze flow while the friction builds up after a reversal and the
seal shifts; the ve curves lie under the ve,sq ones. The IHL line is `sealts ihl` on
`paper_fig14_ihl.toml` (dry, pressurised to {self.scene("ihl14").fluid.p_in:g} MPa,
{ih['speed']:g} mm/s): the flow A v h*(|v|)/2 with
h* scaled as sqrt(|v|) and the outstroke or instroke film by the sign of v.

![Fig. 14]({name})

{table(["variant", "material and film", "net leakage [mm^3]", "carried out [mm^3]", "carried back [mm^3]", "out / back", "Q_out range [mm^3/s]", "film growth V_in - V_out [mm^3]", "peak friction out / in [N]", "min h [um]", "steps / rejected"], rows)}

| quantity | paper | sealts |
|---|---|---|
| order of the net leakage | he < ve = ve,sq < ve,sq,Φ | {order} |
| squeeze term | negligible | ve,sq - ve = {self._diff(net, 've,sq', 've')} mm^3 |
| net leakage, ve,sq,Φ | about {PAPER['fig14_net']:g} mm^3 | {net.get('ve,sq,Φ', float('nan')):.1f} mm^3 |
| Q over the cycle | about {q_lo:g} to +{q_hi:g} mm^3/s | {self._qrange(qr)} |
| IHL net leakage | - | {net_ihl:.1f} mm^3 |

**Differences.** {self._fig14_text(net, net_ihl, out_ihl, qr, tr, ih)}
""")

    @staticmethod
    def _diff(net, a, b):
        if a in net and b in net:
            return f"{net[a] - net[b]:+.2f}"
        return "n/a"

    @staticmethod
    def _qrange(qr):
        if not qr:
            return "n/a"
        lo = min(a for a, _ in qr.values())
        hi = max(b for _, b in qr.values())
        return f"{lo:.0f} to +{hi:.0f} mm^3/s over the four variants"

    @staticmethod
    def _fig14_order(net):
        if not net:
            return "n/a"
        items = sorted(net.items(), key=lambda kv: kv[1])
        return " < ".join(f"{k} ({v:.1f})" for k, v in items)

    def _fig14_text(self, net, net_ihl, out_ihl, qr, tr, ih):
        he, ve, vs, vf = (net.get(k) for k in ("he", "ve", "ve,sq", "ve,sq,Φ"))
        t = []
        if None not in (he, ve, vs):
            small = abs(vs - ve) < 0.05 * abs(ve)
            t.append(f"The squeeze term changes the viscoelastic leakage by "
                     f"{abs(vs - ve):.2f} mm^3 ({100 * abs(vs / ve - 1):.1f} %), "
                     f"{word(small, 'negligible as in the paper', 'unlike the paper')}. ")
            (ho, hb), (vo, vb) = tr["he"], tr["ve"]
            more = vo > ho
            mech = ", the mechanism the paper gives (a thicker film, Fig. 9)" if more else ""
            t.append(f"The viscoelastic seal carries {word(more, 'more', 'less')} out than the "
                     f"hyperelastic one ({vo:.1f} against {ho:.1f} mm^3)"
                     f"{mech}, "
                     f"but also {word(vb > hb, 'more', 'less')} back ({vb:.1f} against "
                     f"{hb:.1f} mm^3), so its net leakage is {ve:.2f} against {he:.2f} mm^3: "
                     f"{word(ve > he, 'larger, as in the paper, but by', 'smaller, unlike the paper, by')} "
                     f"{100 * abs(ve / he - 1):.0f} %. The transports change by "
                     f"{100 * (vo / ho - 1):+.1f} % (out) and {100 * (vb / hb - 1):+.1f} % "
                     "(back), and the net, their small difference, by the balance of the two: "
                     "the viscoelastic film gain is small here (Fig. 9), as a relaxed start "
                     "holds it to what the stroke's loads do to a stiffer seal. ")
        if vf is not None and vs is not None:
            (fo, fb), (so, sb) = tr["ve,sq,Φ"], tr["ve,sq"]
            largest = vf >= max(net.values())
            t.append(f"Flow factors {word(vf > vs, 'raise', 'lower')} the net leakage to "
                     f"{vf:.1f} mm^3 ({vf / vs:.2f} times ve,sq), "
                     f"{word(largest, 'the largest of the four, as in the paper', 'not the largest of the four, unlike the paper')}. "
                     f"They carry {word(fo < so, 'less', 'more')} out ({fo:.1f} against "
                     f"{so:.1f} mm^3: the shear-flow term, Fig. 11) and "
                     f"{word(fb < sb, 'less', 'more')} back ({fb:.1f} against {sb:.1f}), so "
                     f"the ratio of outward to inward transport "
                     f"{word(fo / fb > so / sb, 'grows', 'falls')} ({fo / fb:.3f} against "
                     f"{so / sb:.3f}){word(fo / fb > so / sb, ', the mechanism the paper names', '')}. ")
            paper = PAPER["fig14_net"]
            fig8 = self.numbers.get("fig8", {}).get("metrics", {}).get("out")
            fig9 = self.numbers.get("fig9", {}).get("dmax")
            film = (f"the film is {100 * fig8['h_mean'] / PAPER['fig8_film']:.0f} % of the "
                    "paper's (Fig. 8)" if fig8 else "the film is thinner than the paper's (Fig. 8)")
            gain = (f"{100 * fig9 / PAPER['fig9_excess']:.0f} % of the paper's (Fig. 9)"
                    if fig9 is not None else "a fraction of the paper's (Fig. 9)")
            t.append(f"The absolute level is about {paper / max(vf, 1e-9):.0f} times below the "
                     f"paper's {paper:g} mm^3. The net leakage is a small difference of two large "
                     f"transports (about {tr['he'][0]:.0f} mm^3 out and {tr['he'][1]:.0f} back), "
                     "and (i) it converges only from the 0.025 mm contact mesh on (net "
                     f"leakage {study(1)} for the hyperelastic cycle), (ii) {film}, (iii) the "
                     "flow factors are not the paper's, and (iv) the viscoelastic film gain is "
                     f"{gain}. ")
        if qr:
            lo = min(a for a, _ in qr.values())
            hi = max(b for _, b in qr.values())
            q_lo, q_hi = PAPER["fig14_q"]
            smaller = lo > q_lo and hi < q_hi
            t.append(f"Q_out swings between {lo:.0f} and +{hi:.0f} mm^3/s against the "
                     f"paper's about {q_lo:g} and +{q_hi:g} ({100 * lo / q_lo:.0f} % and "
                     f"{100 * hi / q_hi:.0f} % of them)"
                     + word(smaller, ": the same shape, smaller, as the film that carries the "
                                     "flow is thinner (Fig. 8). ", ". "))
        o, i = ih["outstroke"], ih["instroke"]
        he_out = f" against {tr['he'][0]:.1f} mm^3 in EHL (he)" if "he" in tr else ""
        t.append(f"The IHL estimate carries {out_ihl:.1f} mm^3 out{he_out}, but its net "
                 f"({net_ihl:.1f} mm^3) is the difference of two films read off the steepest "
                 f"nodal gradients at the two edges of the dry contact (here h*_out = "
                 f"{um(o['h_star'])} from w = {o['w']:.2f} MPa/mm at the sealed side, h*_in = "
                 f"{um(i['h_star'])} from w = {i['w']:.2f} MPa/mm at the atmosphere side, at "
                 f"{ih['speed']:g} mm/s); each w grows as the mesh resolves the contact edge "
                 "(Fig. 12), at its own rate, so the IHL net leakage, even its sign, is not "
                 "mesh-resolved"
                 + (f" ({self.across('fig14', 'ihl', nd=1, unit='mm^3')})."
                    if self.across('fig14', 'ihl') else "."))
        return "".join(t)

    # ---- the whole report -----------------------------------------------------------------
    def write(self, commit, total_wall, argv, others=()):
        s1 = self.prepare()
        try:
            s0 = output(self.out, "state_0mpa").summary
        except MissingOutput:
            s0 = None
        self.read_others([o for o in others if o != self.out])
        self.sections()
        self.mesh_check()
        body = "\n".join(self.parts)
        rows, commits = [], set()
        for r in RUNS:
            d = self.out / "runs" / r.key
            info = json.loads((d / "done.json").read_text()) if (d / "done.json").exists() else {}
            if info:
                commits.add(info.get("commit", "not recorded"))
            try:
                sm = output(self.out, r.key).summary
            except MissingOutput:
                sm = {}
            st = sm.get("stroke", {})
            edits = ", ".join(f"{sec}.{key} = {v:g}" for (sec, key), v in r.edits.items())
            rows.append([f"`{r.key}`", f"`configs/{r.scene}.toml`" + (f" ({edits})" if edits else ""),
                         r.what, f"{info['wall_s']:.1f}" if info else "-",
                         "ok" if info.get("returncode") == 0 else
                         (f"stopped: {sm['cause']}" if sm.get("status") == "stopped" else
                          "failed") if info else "not run",
                         st.get("unknowns", sm.get("unknowns", "-")),
                         f"{st['steps_accepted']} / {st['steps_rejected']}" if st else "-"])
        sm = s1 or s0 or {}
        edge = (f", refined to {self.mesh[2] * 1e3:g} um at the pressurised contact's edges "
                "(`mesh.h_edge`)" if self.mesh[2] > 0 else "")
        mesh = (f"{self.mesh[0]} mm along the rod side, {self.mesh[1]} mm in the bulk{edge} "
                f"({self.mesh_name}); {sm.get('nodes', '?')} nodes, "
                f"{sm.get('elements', '?')} quadrilaterals (the 1 MPa state's mesh)")

        sc = self.scene("fig8_out")
        paper_mesh, paper_net = CYCLE_STUDY[-1][0], CYCLE_STUDY[-1][1]
        fine = [r[1] for r in CYCLE_STUDY[:-1] if r[0][0] <= MESHES["default"][0]]
        spread = max(abs(x / paper_net - 1) for x in fine)
        low = 1 - CYCLE_STUDY[0][1] / paper_net
        p_in = self.scene("state_1mpa").fluid.p_in

        def state(s, what):
            if not s:
                return f"{what}: not run"
            r = s["results"]
            return (f"{what}: rod force {r['contact_force_total']:.1f} N, peak dry contact "
                    f"pressure {r['p_contact_max']:.2f} MPa")
        header = f"""# sealts against Schmidt, Andre, Poll (2010): Figs. 8-14 regenerated

Generated by `scripts/paper_report.py` on {datetime.date.today().isoformat()}
(`{' '.join(argv)}`), sealts commit `{commit}` (the runs: {', '.join(f'`{c}`' for c in sorted(commits)) or '-'}), Python {platform.python_version()} on
{platform.machine()}. Runs: `runs/<key>/` beside this file (each with the scene copy it ran
and its log).

- **Mesh:** {mesh}. The paper used {paper_mesh[0]:g} mm along the contact and
  {paper_mesh[1]:g} mm in the bulk.
- **Paper values** are those the paper states in its text (Section 3) and figures
  (`PAPER` in `scripts/paper_report.py`); sealts' numbers are measured from the runs.
- **Steps 1-2** (mount; pressurise to {p_in:g} MPa with pressure penetration; long-term,
  frictionless) ran once per sealed pressure ({state(s1, f"`paper_state_1mpa`, {p_in:g} MPa")};
  {state(s0, "`paper_state_0mpa`, 0 MPa")}); every stroke restarts from their `state.h5`.
- **Friction is on in every stroke** (rod mu_s = {sc.asperity.mu_s:g}, Eq. 46-48; groove
  walls {sc.groove.mu:g}): without solid friction the fluid shear rolls the O-ring in its
  groove, a different problem.
- **Mesh convergence of the leakage** (README, tests/test_cycle_regression.py): for the
  hyperelastic cycle net leakage {study(1)}: within {100 * spread:.1f} % of the paper's
  mesh from {MESHES["default"][0]:g} / {MESHES["default"][1]:g} mm on, without the edges'
  refinement, where gmsh's placement of the nodes moves it by up to a quarter; with it
  (`mesh.h_edge`, this report's default) the cycle is within the bounds of the
  work-precision benchmark (`benchmarks/work_precision.md`); the coarse mesh's leakage is
  {100 * low:.0f} % low.
- **Material:** the steady comparisons (Figs. 8, 11, 12) use the long-term (hyperelastic)
  material, as the paper does for its long-term and IHL cases; Fig. 9 and three of the four
  Fig. 14 cycles use Table 2's Prony series from a relaxed start.
- Units: mm, N, s, MPa; films in um. y is the current axial position of the seal's rod-side
  nodes (the groove centred at y = 0, the sealed pressure at small y).

Total wall time {total_wall / 60:.1f} min (sum of the runs below; one run at a time on a
2-core machine shared with other work).

{table(["run", "scene", "what", "wall [s]", "status", "unknowns", "stroke steps / rejected"], rows)}

"""
        closing = f"""
## What is left

- Every comparison on the paper's {paper_mesh[0]:g} mm contact mesh
  (`--mesh {paper_mesh[0]:g} {paper_mesh[1]:g}`; steps 1-2 alone take 10-20 min there, each
  viscoelastic cycle much longer): the cycle's net leakage is converged from the
  {MESHES["default"][0]:g} mm contact mesh on (README), the films of Figs. 8-12 are not
  checked there.
- `sealts ihl` takes w as the largest nodal gradient of the dry pressure. For this O-ring
  that is the contact edge, where the dry pressure rises almost like a square root and is
  carried by the asperity law at gaps as large as the film itself (Fig. 12), so
  IHL's premise (fluid pressure = dry pressure) fails just where it reads w; the gradient
  grows with refinement, and h* and above all the IHL net leakage (a difference of two such
  films) depend on the mesh. Where to read w (past the edge, on a fitted flank) is a
  modelling decision for `sealts ihl`.
- The node-to-node ripple of h in full film (Fig. 12): a check of the control-volume
  film's element flux against an alternating h, which it does not see to first order.
- The paper's own flow factors for the turned rod (a `[film] flow_factors = "table"` CSV,
  once digitised) and the transverse Patir-Cheng rows (gamma < 1).
- Why the paper's viscoelastic film gain is {um(PAPER["fig9_excess"], 2)}: a viscoelastic
  start that is not relaxed would test the explanation given under Fig. 9.
- Why the paper's fluid pressure peaks at {PAPER["fig8_p_max"][0]:g}-{PAPER["fig8_p_max"][1]:g} MPa,
  {word(self.dry_peak < PAPER["fig8_p_max"][0], "above", "near")} this O-ring's whole dry
  contact pressure (Fig. 8): the paper gives no dry contact pressure to compare.
- The pressure-penetration front is not updated during the stroke (sealts' stroke keeps
  step 2's wetted surface).
"""
        (self.out / "report.md").write_text(header + body + closing)


def rel(path):
    path = Path(path)
    return path.relative_to(ROOT) if path.is_relative_to(ROOT) else path


def git_commit():
    """HEAD, and the commit that last changed sealts/ (the code the runs ran), with a note
    if sealts/, configs/ or this script differ from HEAD."""
    def git(*args):
        return subprocess.run(["git", "-C", str(ROOT), *args], capture_output=True,
                              text=True, check=True).stdout.strip()
    try:
        head = git("rev-parse", "--short", "HEAD")
        code = git("log", "-1", "--format=%h", "--", "sealts")
        dirty = git("status", "--porcelain", "--", "sealts", "configs",
                    "scripts/paper_report.py")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"
    return (f"{head}, sealts/ as of {code}"
            + (" (with uncommitted changes in sealts/, configs/ or this script)" if dirty else ""))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--coarse", action="store_true",
                    help="0.1 / 0.4 mm mesh (quick check) instead of 0.025 / 0.2 mm")
    ap.add_argument("--mesh", type=float, nargs=2, metavar=("H_CONTACT", "H_BULK"),
                    help="any other mesh (mm), e.g. the paper's 0.01 0.05")
    ap.add_argument("--only", default="",
                    help="comma-separated run keys to run (the others are kept or missing)")
    ap.add_argument("--out", type=Path, default=None,
                    help="output directory (default results/paper_report, "
                         "results/paper_report_coarse with --coarse)")
    ap.add_argument("--reuse", action="store_true",
                    help="keep finished runs whose scene copy is unchanged")
    ap.add_argument("--report-only", action="store_true",
                    help="run nothing; write the report from the runs in OUT")
    ap.add_argument("--other", type=Path, nargs="*", default=None,
                    help="run directories on other meshes to set beside these in a mesh "
                         "check (default: results/paper_report*/ that hold runs)")
    a = ap.parse_args()
    name = "coarse" if a.coarse else "default"
    mesh = MESHES[name]
    sub = "paper_report_coarse" if a.coarse else "paper_report"
    if a.mesh:
        name, mesh = "custom", (*a.mesh, 0.0)
        sub = f"paper_report_{mesh[0]:g}_{mesh[1]:g}"
    only = {k for k in a.only.split(",") if k}
    unknown = only - {r.key for r in RUNS}
    if unknown:
        ap.error(f"--only: no run named {', '.join(sorted(unknown))}")
    out = (a.out or ROOT / "results" / sub)
    out = out.resolve()
    out.mkdir(parents=True, exist_ok=True)
    print(f"paper report: mesh {mesh[0]} / {mesh[1]} mm ({name}), output {out}", flush=True)
    walls = {}
    if not a.report_only:
        for k, r in enumerate(RUNS, 1):
            if only and r.key not in only:
                continue
            if r.state:
                dep = out / "runs" / r.state / "done.json"
                if not dep.exists() or json.loads(dep.read_text()).get("returncode") != 0:
                    print(f"[{k:2d}/{len(RUNS)}] {r.key:15s} skipped: {r.state} failed",
                          flush=True)
                    continue
            walls[r.key] = run_one(r, mesh, out, a.reuse, k, len(RUNS))
    total = 0.0
    for r in RUNS:
        d = out / "runs" / r.key / "done.json"
        if d.exists():
            total += json.loads(d.read_text())["wall_s"]
    # the mesh the runs in OUT ran (--report-only may read runs of another one)
    rep = Report(out, name, mesh_of(out) or mesh, walls)
    others = a.other if a.other is not None else sorted(
        d for d in (ROOT / "results").glob("paper_report*") if (d / "runs").is_dir())
    rep.write(git_commit(), total, ["scripts/paper_report.py"] + sys.argv[1:],
              [Path(o).resolve() for o in others])
    print(f"written: {out / 'report.md'} (+ PNG figures); runs total {total / 60:.1f} min",
          flush=True)


if __name__ == "__main__":
    main()
