"""scripts/paper_report.py without running a simulation: its scenes load, and the scene
copies it runs carry the mesh sizes, the restart state and the run's edits."""
import importlib.util
import sys

import numpy as np
import pytest

from conftest import CONFIGS, ROOT
from sealts.scene import load_scene


@pytest.fixture(scope="module")
def report():
    spec = importlib.util.spec_from_file_location("paper_report",
                                                  ROOT / "scripts" / "paper_report.py")
    mod = importlib.util.module_from_spec(spec)
    sys.modules["paper_report"] = mod
    spec.loader.exec_module(mod)
    return mod


@pytest.mark.parametrize("path", sorted(CONFIGS.glob("paper_*.toml")), ids=lambda p: p.stem)
def test_paper_scenes_load(path):
    s = load_scene(path)
    assert s.model == "seal" and s.name == path.stem
    default = load_scene(CONFIGS / "oring_stroke.toml").mesh      # the report's default mesh
    assert (s.mesh.h_contact, s.mesh.h_bulk) == (default.h_contact, default.h_bulk)


def test_every_run_names_a_scene_and_an_earlier_state(report):
    seen = set()
    for r in report.RUNS:
        assert (CONFIGS / f"{r.scene}.toml").is_file()
        assert not r.state or r.state in seen
        seen.add(r.key)


def test_set_key_replaces_adds_and_appends(report):
    text = "name = \"x\"\n\n[mesh]\nh_contact = 0.05   # mm\n\n# [start]\n# state = \"a\"\n"
    t = report.set_key(text, "mesh", "h_contact", 0.1)
    assert "h_contact = 0.1 " in t and "0.05" not in t
    t = report.set_key(t, "mesh", "h_bulk", 0.4)
    assert t.index("h_bulk = 0.4") < t.index("# [start]")
    t = report.set_key(t, "start", "state", "/s/state.h5")
    assert t.rstrip().endswith("[start]\nstate = \"/s/state.h5\"    # set by "
                               "scripts/paper_report.py")


@pytest.mark.parametrize("key", ["fig9_ve", "ihl12_500"])
def test_scene_copy_runs_the_coarse_mesh_from_the_state(report, tmp_path, key):
    run = next(r for r in report.RUNS if r.key == key)
    if run.state:
        state = tmp_path / "runs" / run.state / "state.h5"
        state.parent.mkdir(parents=True)
        state.write_bytes(b"")
    path = tmp_path / "scene.toml"
    path.write_text(report.scene_copy(run, report.MESHES["coarse"], tmp_path))
    s = load_scene(path)
    assert (s.mesh.h_contact, s.mesh.h_bulk) == (0.1, 0.4)
    assert s.start.state == (str(state.resolve()) if run.state else "")
    if key == "ihl12_500":
        assert s.rod.velocity == 500.0
    else:
        assert s.viscoelastic.prony == "table2" and s.stroke.t_end == 54000.0


def test_ihl_film_inverts_the_reynolds_gradient(report):
    """Blok's construction returns h with 6 eta v (h - h*)/h^3 = dp/dy, thick on the inlet
    flank before the steepest rise, thin after it."""
    h_star, v = 5e-4, 100.0
    y = np.linspace(-1.0, 1.0, 9)
    h = np.array([1.4, 1.2, 1.0, 0.8, 0.6, 0.55, 0.5, 0.45, 0.42]) * 1e-3
    g = 6 * report.ETA * v * (h - h_star) / h**3
    p = np.ones_like(y)
    k = int(np.argmax(g))
    got = report.ihl_film(y, p, g, v, h_star, 0.5 * (y[k] + y[k + 1]))
    assert np.allclose(got, h, rtol=1e-9)


def test_report_default_mesh_is_the_shipped_cycle_mesh(report):
    """The report runs on the mesh whose leakage is mesh-converged, the shipped cycle's."""
    m = load_scene(CONFIGS / "oring_stroke.toml").mesh
    assert report.MESHES["default"] == (m.h_contact, m.h_bulk)
