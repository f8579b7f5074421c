"""Scene files: typed, validated, one-line errors naming the key, exit code 2."""
import subprocess
import sys
import tomllib

import pytest

from conftest import CONFIGS, ROOT
from sealts.scene import SceneError, default_scene, load_scene, parse_scene


def sealts(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "sealts", *args], capture_output=True,
                          text=True, cwd=cwd or ROOT)


@pytest.mark.parametrize("text, message", [
    ("[fluid]\nviscocity = 1e-8", "unknown key fluid.viscocity; did you mean 'viscosity'?"),
    ("[fluid]\nviscosity = -1e-8", "fluid.viscosity must be > 0 MPa s (got -1e-08)"),
    ("[fluid]\nviscosity = 'thin'", "fluid.viscosity must be a number (got 'thin')"),
    ("[film]\nalpha = 1.5", "film.alpha must be <= 1 (got 1.5)"),
    ("[film]\nelements = 10.5", "film.elements must be an integer (got 10.5)"),
    ("[film]\nscheme = 'fem'", "film.scheme must be one of 'fv', 'paper' (got 'fem')"),
    ("[film]\nelements = 2000000000", "film.elements = 2,000,000,000: more than 10,000,000"),
    ("[asperity]\nh_mix = 0.0", "asperity.h_mix must be > 0 mm (got 0)"),
    ("[gap]\nh_min = 0.001\nsqueeze_velocity = -0.01\n[analysis]\ntype = 'transient'\n"
     "t_end = 1.0", "gap.squeeze_velocity = -0.01 mm/s closes the gap"),
    ("[film]\nflow_factors = 'patir-cheng'", "film.rq must be > 0 mm"),
    ("[film]\nflow_factors = 'patir-cheng'\nrq = 1e-4\ngamma = 2.0", "film.gamma must be one of"),
    ("[film]\nflow_factors = 'table'\ntable = 'nope.csv'", "film.table: no such file"),
    ("[analysis]\ntype = 'transient'\nt_end = 1.0\noutput_times = [2.0]",
     "analysis.output_times has 2 s after analysis.t_end = 1 s"),
    ("fluid = 3", "fluid must be a table (got 3)"),
    ("[fluid\n", "not valid TOML"),
    # a section the model never reads, one each way, named with the model it belongs to
    ("[stroke]\nvelocity = 'sine'", "[stroke] is not read by a model = 'film' scene; it "
                                   "belongs to model = 'seal'"),
    ("[seal]\nd2 = 5.33", "[seal] is not read by a model = 'film' scene"),
    ("model = 'seal'\n[gap]\nlength = 3.0", "[gap] is not read by a model = 'seal' scene; "
                                            "it belongs to model = 'film'"),
    ("model = 'seal'\n[analysis]\ntype = 'steady'", "[analysis] is not read by a model = "
                                                   "'seal' scene"),
])
def test_bad_scene_names_the_key(text, message):
    with pytest.raises(SceneError) as e:
        parse_scene(text)
    assert message in str(e.value)


def test_cli_bad_scene_one_line_exit_2(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text((CONFIGS / "slider.toml").read_text().replace("viscosity", "viscosty"))
    r = sealts("run", str(bad), "-o", str(tmp_path / "out"))
    assert r.returncode == 2
    assert r.stderr.strip() == "scene error: unknown key fluid.viscosty; did you mean 'viscosity'?"
    assert "Traceback" not in r.stderr + r.stdout
    r = sealts("run", str(tmp_path / "missing.toml"))
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and "scene file not found" in r.stderr


def test_shipped_configs_are_valid():
    for path in CONFIGS.glob("*.toml"):
        load_scene(path)


def test_embedded_default_is_the_oring_cycle_config():
    """`sealts run` without a scene runs the paper's O-ring cycle: the packaged copy must be
    the shipped config, byte for byte, so the two cannot drift apart."""
    import dataclasses
    from importlib import resources
    a = default_scene()
    b = load_scene(CONFIGS / "oring_stroke.toml")
    assert dataclasses.replace(a, source="") == dataclasses.replace(b, source="")
    packaged = resources.files("sealts.data").joinpath("oring_stroke.toml").read_text()
    assert packaged == (CONFIGS / "oring_stroke.toml").read_text()
    assert a.model == "seal" and a.stroke.velocity == "sine" and a.stroke.v_max == 500.0


def test_petsc_table_values_become_option_strings():
    s = parse_scene("[petsc]\nts_type = 'bdf'\nts_rtol = 1e-6\nsnes_monitor = ''\n"
                    "ksp_view = true\n")
    assert s.petsc_options == {"ts_type": "bdf", "ts_rtol": "1e-06", "snes_monitor": "",
                               "ksp_view": "true"}


def test_keys_lists_every_section():
    r = sealts("keys")
    assert r.returncode == 0
    for key in ("fluid.viscosity", "film.h_floor", "gap.squeeze_velocity", "asperity.p_mix"):
        assert key in r.stdout
    assert tomllib.loads((CONFIGS / "slider.toml").read_text())["name"] == "slider"


@pytest.mark.parametrize("name, content, message", [
    ("inf.toml", "[fluid]\nviscosity = inf\n", "fluid.viscosity must be a finite number"),
    ("nan.toml", "[fluid]\np_in = nan\n", "fluid.p_in must be a finite number"),
    ("badcsv.toml", "[film]\nflow_factors = 'table'\ntable = 'bad.csv'\n",
     "film.table: "),
    ("latin1.toml", b"name = '\xe9'\n", "cannot be read as UTF-8"),
])
def test_cli_user_errors_are_one_line(tmp_path, name, content, message):
    (tmp_path / "bad.csv").write_text("h,phi_p,phi_s\n0.0,abc,0\n0.1,1,0\n")
    path = tmp_path / name
    path.write_bytes(content if isinstance(content, bytes) else content.encode())
    r = sealts("run", str(path), "-o", str(tmp_path / "out"))
    assert r.returncode == 2, r.stderr
    assert message in r.stderr and r.stderr.count("\n") == 1
    assert "Traceback" not in r.stderr


def test_cli_scene_after_options_and_usage_errors(tmp_path):
    r = sealts("run", "-o", str(tmp_path / "a"), str(CONFIGS / "squeeze_plates.toml"))
    assert r.returncode == 0 and "squeeze_plates" in r.stdout
    r = sealts("run", str(CONFIGS / "slider.toml"), str(CONFIGS / "squeeze_plates.toml"))
    assert r.returncode == 2 and "two scene files" in r.stderr
    r = sealts("run", str(CONFIGS / "slider.toml"), "stray")
    assert r.returncode == 2 and "unexpected argument 'stray'" in r.stderr
    blocker = tmp_path / "file"
    blocker.write_text("x")
    r = sealts("run", "-o", str(blocker))
    assert r.returncode == 2 and "output directory" in r.stderr
    assert "Traceback" not in r.stderr
    r = sealts("run", str(tmp_path))
    assert r.returncode == 2 and "is a directory" in r.stderr


@pytest.mark.parametrize("extra, message", [
    ("[seal]\nd2 = 5.8\n", "seal.d2 = 5.8 mm: the cord must be narrower than groove.width"),
    ("[rod]\nradius = 29.7\n", "the rod diameter must be below groove.diameter"),
    ("[seal]\nd1 = -50.0\n", "seal.d1 must be > 0 mm (got -50)"),
    ("[groove]\ndiameter = 56.0\n", "over 35 % squeeze"),
    ("[mesh]\nh_contact = 0.1\nh_bulk = 0.05\n", "mesh.h_contact = 0.1 mm must not exceed"),
    ("[groove]\ncorner_radius = 2.9\n", "groove.corner_radius = 2.9 mm must be below half"),
    ("[material]\nc01 = 0.2\n", "material.c01 = 0.2 MPa needs material.model = 'mooney-rivlin'"),
    ("[material]\nmodel = 'mooney-rivlin'\n", "material.c01 must be > 0 MPa"),
    ("[viscoelastic]\nprony = 'custom'\nprony_g = [0.5]\nprony_tau = [1.0, 2.0]\n",
     "prony_g and prony_tau must be lists of the same non-zero length"),
    ("[viscoelastic]\nprony = 'custom'\nprony_g = [0.6, 0.5]\nprony_tau = [1.0, 2.0]\n",
     "viscoelastic.prony_g must sum to below 1 (got 1.1)"),
    ("[viscoelastic]\nprony_g = [0.5]\n", "only used with prony = 'custom'"),
    ("[viscoelastic]\nprony_tau = [-1.0]\n", "viscoelastic.prony_tau"),
    ("[viscoelastic]\ntemperature = -140.0\n", "below the WLF range"),
    ("[viscoelastic]\ntemperature_times = [0.0, 10.0]\ntemperature_values = [25.0]\n",
     "temperature_times and temperature_values must have the same length"),
    ("[viscoelastic]\ntemperature_times = [10.0, 5.0]\ntemperature_values = [25.0, 20.0]\n",
     "temperature_times must increase"),
    ("[hold]\np_end = 5.0\n", "hold.p_end needs a viscoelastic material"),
    ("[viscoelastic]\nprony = 'table2'\n[hold]\np_end = 5.0\n",
     "hold.p_end needs the pressurised state: set fluid.p_in"),
    ("[viscoelastic]\nprony = 'table2'\n[hold]\np_end = 5.0\nt_end = 1e-4\n"
     "[fluid]\np_in = 1.0\n", "must lie below hold.t_end"),
    ("[stroke]\nvelocity = 'sine'\nt_end = 1.0\noutput_times = [2.0]\n",
     "stroke.output_times has 2 s after stroke.t_end = 1 s"),
    ("[stroke]\nvelocity = 'table'\n", "stroke.table must name a CSV file"),
    ("[stroke]\nvelocity = 'table'\ntable = 'nope.csv'\n", "stroke.table: no such file"),
    ("[stroke]\nvelocity = 'sine'\ntable = 'v.csv'\n", "stroke.table is only used with"),
    ("[stroke]\nvelocity = 'sinus'\n", "stroke.velocity must be one of"),
    ("[start]\nstate = 'nope.h5'\n", "start.state: no such file"),
    ("[fluid]\np_crit = -0.1\n", "fluid.p_crit must be >= 0 MPa"),
    ("[fluid]\np_in = -1.0\n", "fluid.p_in = -1 MPa is below vacuum (-0.101325 MPa)"),
    ("[mesh]\nh_contact = 1e-4\n", "mesh.h_contact = 0.0001 mm: about 8.4e+07 mesh nodes"),
    ("[mesh]\nh_bulk = 1e-3\nh_contact = 1e-3\n", "mesh.h_bulk = 0.001 mm: about 2.3e+07"),
    ("[viscoelastic]\nprony = 'table2'\n[hold]\np_end = -0.2\n[fluid]\np_in = 1.0\n",
     "hold.p_end = -0.2 MPa is below vacuum"),
    ("[fluid]\np_in = 0.5\np_out = -0.5\n", "fluid.p_out = -0.5 MPa is below vacuum"),
    ("[groove]\nmu = -0.1\n", "groove.mu must be >= 0"),
    ("[stroke]\nvelocity = 'sine'\ngamma_crit = 0.0\n", "stroke.gamma_crit must be > 0 mm"),
    ("[stroke]\nvelocity = 'sine'\nfilm = 'no'\n", "stroke.film must be true or false"),
    ("[stroke]\nvelocity = 'sine'\nfriction_exponent = 8.0\n",
     "unknown key stroke.friction_exponent"),
    ("[stroke]\nvelocity = 'sine'\nfriction_history = 'slip'\n",
     "stroke.friction_history must be one of"),
    ("[stroke]\nvelocity = 'sine'\n[viscoelastic]\nprony = 'table2'\n[hold]\np_end = 5.0\n"
     "[fluid]\np_in = 1.0\n", "a scene runs either the stroke or the pressure hold"),
])
def test_impossible_seal_geometry(extra, message):
    base = (CONFIGS / "oring_mount.toml").read_text()
    table = tomllib.loads(base)
    for sec, kv in tomllib.loads(extra).items():
        table.setdefault(sec, {}).update(kv)
    from sealts.scene.schema import scene_from_table
    with pytest.raises(SceneError) as e:
        scene_from_table(table)
    assert message in str(e.value)
