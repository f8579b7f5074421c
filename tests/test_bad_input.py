"""The bad-input corpus: malformed scenes, files and command lines, each answered by the
command line with one line that names the item, exit code 2, and no traceback.

Scene-level cases go through ``sealts check`` (no PETSc, fast); cases that only show when a
run starts (files read by a step, PETSc options, the output directory) through
``sealts run``. Each case is (name, scene text or None, extra files, arguments, words the
one line must contain).
"""
import subprocess
import sys

import pytest

from conftest import CONFIGS, ROOT, config_text

COARSE = {"mesh": {"h_contact": 0.1, "h_bulk": 0.4, "cache": str(ROOT / "meshes")},
          "output": {"plot": False, "progress": False}}


def seal(**sections):
    """configs/oring_stroke.toml, coarse, with keys set."""
    s = {k: dict(v) for k, v in COARSE.items()}
    for sec, kv in sections.items():
        s.setdefault(sec, {}).update(kv)
    return config_text("oring_stroke", **s)


def film(**sections):
    """configs/slider.toml with keys set."""
    return config_text("slider", **sections)


SLIDER = (CONFIGS / "slider.toml").read_text()

# (name, scene text, {file name: bytes or text}, command, expected words)
CHECK = [
    ("typo key", film(rod={"velocty": 1.0}), {}, "unknown key rod.velocty"),
    ("typo section", film(fluids={"viscosity": 1e-8}), {}, "fluids"),
    ("string for number", seal(fluid={"p_in": "high"}), {}, "fluid.p_in must be a number"),
    ("string for integer", film(film={"elements": "many"}), {}, "film.elements"),
    ("float for integer", film(film={"elements": 10.5}), {}, "film.elements must be an integer"),
    ("string for bool", seal(stroke={"film": "yes"}), {}, "stroke.film must be true or false"),
    ("bad choice", seal(seal={"shape": "star"}), {}, "seal.shape must be one of"),
    ("bad model", 'model = "gas"\n', {}, "model must be one of"),
    ("list expected", seal(stroke={"output_times": "1, 2"}), {}, "stroke.output_times"),
    ("negative viscosity", film(fluid={"viscosity": -1e-8}), {}, "fluid.viscosity must be > 0"),
    ("infinite", seal(fluid={"p_in": float("inf")}), {}, "fluid.p_in must be a finite number"),
    ("section not a table", "model = 'film'\nfluid = 3\n", {}, "fluid must be a table"),
    ("not TOML", "[fluid\nviscosity = 1\n", {}, "not valid TOML"),
    ("not UTF-8", b"name = '\xe9'\n", {}, "cannot be read as UTF-8"),
    ("section of the other model", seal(gap={"length": 3.0}), {}, "[gap] is not read by"),
    ("cord wider than groove", seal(seal={"d2": 5.8}), {}, "seal.d2 = 5.8 mm"),
    ("rod larger than groove", seal(rod={"radius": 29.9}), {}, "rod diameter"),
    ("over-squeezed", seal(groove={"diameter": 56.0}), {}, "squeeze"),
    ("corner radius too large", seal(groove={"corner_radius": 2.9}), {}, "groove.corner_radius"),
    ("extrusion gap wider than the groove", seal(groove={"clearance": 4.65}), {},
     "groove.clearance = 4.65 mm"),
    ("negative extrusion limit", seal(groove={"extrusion_limit": -0.1}), {},
     "groove.extrusion_limit must be > 0"),
    ("seal corner radius on an O-ring", seal(seal={"corner_radius": 0.1}), {},
     "seal.corner_radius is the rectangle's"),
    ("seal corner radius too large", seal(seal={"shape": "rectangle", "inner_diameter": 50.1,
                                                "height": 2.4, "width": 2.0,
                                                "corner_radius": 1.0}), {},
     "seal.corner_radius = 1 mm must be below half"),
    ("paper film scheme on a sharp-cornered ring",
     seal(seal={"shape": "rectangle", "inner_diameter": 50.1, "height": 2.4, "width": 2.0},
          film={"scheme": "paper"}), {}, "film.scheme = 'paper' integrates dp/dy"),
    ("contact mesh coarser than bulk", seal(mesh={"h_contact": 0.5, "h_bulk": 0.4}), {},
     "mesh.h_contact"),
    ("mesh too large for the machine", seal(mesh={"h_contact": 1e-4}), {}, "mesh nodes"),
    ("edge size not below the contact size", seal(mesh={"h_edge": 0.1}), {},
     "mesh.h_edge = 0.1 mm must be below"),
    ("edge refinement on a mirror-symmetric mesh",
     seal(mesh={"h_edge": 0.01, "symmetric": True}), {}, "mesh.symmetric = false"),
    ("edge refinement too fine for the machine", seal(mesh={"h_edge": 1e-6}), {},
     "mesh.h_edge = 1e-06 mm"),
    ("film too large for the machine", film(film={"elements": 2000000000}), {},
     "film.elements"),
    ("below vacuum", seal(fluid={"p_in": -0.5}), {}, "below vacuum"),
    ("back pressure below vacuum", seal(fluid={"p_out": -0.2}), {}, "fluid.p_out"),
    ("output time after the end", seal(stroke={"output_times": [20.0]}), {},
     "stroke.output_times has 20 s"),
    ("negative friction", seal(asperity={"mu_s": -0.1}), {}, "asperity.mu_s must be >= 0"),
    ("Prony weights over 1", seal(viscoelastic={"prony": "custom", "prony_g": [0.6, 0.5],
                                                "prony_tau": [1.0, 2.0]}), {},
     "viscoelastic.prony_g must sum to below 1"),
    ("temperatures not increasing", seal(viscoelastic={
        "temperature_times": [10.0, 5.0], "temperature_values": [25.0, 20.0]}), {},
     "temperature_times must increase"),
    ("velocity table missing", seal(stroke={"velocity": "table", "table": "nope.csv"}), {},
     "stroke.table: no such file"),
    ("velocity table not numbers", seal(stroke={"velocity": "table", "table": "v.csv"}),
     {"v.csv": "t,v\n0,abc\n1,2\n"}, "stroke.table"),
    ("velocity table without header", seal(stroke={"velocity": "table", "table": "v.csv"}),
     {"v.csv": "0,0\n1,2\n"}, "columns t (s) and v (mm/s)"),
    ("velocity table going back in time", seal(stroke={"velocity": "table", "table": "v.csv"}),
     {"v.csv": "t,v\n0,0\n2,1\n1,2\n"}, "t must increase"),
    ("velocity table empty", seal(stroke={"velocity": "table", "table": "v.csv"}),
     {"v.csv": ""}, "stroke.table"),
    ("flow-factor table missing", film(film={"flow_factors": "table", "table": "no.csv"}),
     {}, "film.table: no such file"),
    ("flow-factor table not numbers", film(film={"flow_factors": "table", "table": "f.csv"}),
     {"f.csv": "h,phi_p,phi_s\n0.0,abc,0\n0.1,1,0\n"}, "film.table"),
    ("mesh file missing", seal(seal={"shape": "file", "mesh_file": "no.msh"}), {},
     "seal.mesh_file: no such file"),
    ("state file missing", seal(start={"state": "no.h5"}), {}, "start.state: no such file"),
    ("bad PETSc table value", seal(petsc={"ts_rtol": [1, 2]}), {}, "petsc.ts_rtol"),
]

# cases that need ``sealts run``: (name, scene text, files, extra arguments, words)
RUN = [
    ("bad PETSc option value", SLIDER, {}, ["-ts_adapt_type", "foo"],
     'Unknown TSAdapt type "foo"'),
    ("bad PETSc option number", SLIDER, {}, ["-ts_rtol", "abc"], "abc"),
    ("misspelt PETSc option", SLIDER, {}, ["-snes_rtoll", "1e-8"], "-snes_rtoll"),
    ("unknown solver prefix", SLIDER, {}, ["-strok_ts_rtol", "1e-4"], "'strok_'"),
    ("a TS option for the condensation's KSP", SLIDER, {}, ["-stroke_condensed_ts_rtol", "1"],
     "-stroke_condensed_ts_rtol"),
    ("bad PC type for the condensation's KSP", SLIDER, {},
     ["-hold_condensed_pc_type", "foo"], "PC type foo"),
    ("sealts' own option not a number", SLIDER, {}, ["-stroke_ts_pressure_atol", "abc"],
     "-stroke_ts_pressure_atol 'abc'"),
    ("sealts' own option not positive", SLIDER, {}, ["-stroke_ts_pressure_atol", "-1"],
     "must be a positive number"),
    ("bad value in the [petsc] table", SLIDER + "ts_adapt_type = 'foo'\n", {}, [],
     'Unknown TSAdapt type "foo"'),
    ("PETSc option with two dashes", SLIDER, {}, ["--ts_rtol", "0.5"],
     "unknown option --ts_rtol"),
    ("misspelt output option", SLIDER, {}, ["--out", "{dir}/x"], "unknown option --out"),
    ("stray argument", SLIDER, {}, ["stray"], "unexpected argument 'stray'"),
    ("two scene files", SLIDER, {}, [str(CONFIGS / "slider.toml")], "two scene files"),
    ("output directory is a file", SLIDER, {"blocker": "x"}, ["-o", "{dir}/blocker"],
     "output directory"),
    ("output directory cannot be created", SLIDER, {}, ["-o", "/proc/sealts_out"],
     "output directory /proc/sealts_out cannot be created"),
    ("state file not HDF5", seal(start={"state": "s.h5"}), {"s.h5": "not a state"},
     [], "start.state"),
    ("state file without a displacement", seal(start={"state": "s.h5"}), {"s.h5": "EMPTY_H5"},
     [], "start.state"),
    ("state file without the mesh.h_edge refinement",
     seal(start={"state": "s.h5"}, mesh={"h_edge": 0.01}), {"s.h5": "EMPTY_H5"}, [],
     "holds no mesh refinement for mesh.h_edge"),
    ("state file refined at another mesh.h_edge",
     seal(start={"state": "s.h5"}, mesh={"h_edge": 0.01}), {"s.h5": "REFINED_H5"}, [],
     "was saved with mesh.h_edge = 0.02 mm, not 0.01 mm"),
    ("restart without a checkpoint", seal(), {}, ["--restart", "{dir}"],
     "no stroke_checkpoint.h5 in"),
    ("restart file not a checkpoint", seal(), {"stroke_checkpoint.h5": "EMPTY_H5"},
     ["--restart", "{dir}"], "is not a stroke checkpoint"),
    ("restart of a scene without a stroke", SLIDER, {}, ["--restart", "{dir}"],
     "--restart continues a seal scene's hold or stroke"),
    ("restart into another directory", seal(), {}, ["--restart", "{dir}", "-o", "{dir}/x"],
     "names another directory"),
    ("restart without its directory", seal(), {}, ["--restart"], "--restart needs a directory"),
    ("mesh file not a mesh", seal(seal={"shape": "file", "mesh_file": "m.msh"}),
     {"m.msh": "garbage\n"}, [], "seal.mesh_file"),
]


def _write(d, text, files):
    for name, content in files.items():
        path = d / name
        if content == "EMPTY_H5":
            import h5py
            with h5py.File(path, "w") as f:
                f.attrs["p_in"] = 1.0
        elif content == "REFINED_H5":        # refined at one point to 0.02 mm
            import h5py
            with h5py.File(path, "w") as f:
                f["refine_points"] = [[25.3, 0.0]]
                f.attrs["refine_h"] = 0.02
        elif isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_text(content)
    scene = d / "scene.toml"
    scene.write_bytes(text if isinstance(text, bytes) else text.encode())
    return scene


def _one_line_exit_2(r, words):
    assert r.returncode == 2, (r.returncode, r.stdout[-500:], r.stderr[-1500:])
    assert "Traceback" not in r.stderr + r.stdout
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1, r.stderr
    assert words in lines[0], lines[0]


def test_the_corpus_has_forty_cases():
    assert len(CHECK) + len(RUN) >= 40


@pytest.mark.parametrize("name, text, files, words", CHECK, ids=[c[0] for c in CHECK])
def test_bad_scene(tmp_path, name, text, files, words):
    scene = _write(tmp_path, text, files)
    r = subprocess.run([sys.executable, "-m", "sealts", "check", str(scene)],
                       capture_output=True, text=True, cwd=ROOT)
    _one_line_exit_2(r, words)


@pytest.mark.parametrize("name, text, files, args, words", RUN, ids=[c[0] for c in RUN])
def test_bad_run(tmp_path, name, text, files, args, words):
    scene = _write(tmp_path, text, files)
    args = [a.replace("{dir}", str(tmp_path)) for a in args]
    if "-o" not in args and "--restart" not in args:
        args += ["-o", str(tmp_path / "out")]
    r = subprocess.run([sys.executable, "-m", "sealts", "run", str(scene), *args],
                       capture_output=True, text=True, cwd=ROOT, timeout=300)
    _one_line_exit_2(r, words)
