"""scripts/paper_report.py without running a simulation: its scenes load, the scene copies it
runs carry the mesh sizes, the restart state and the run's edits, and the report renders
from run directories with known numbers in them."""
import re

import numpy as np
import pytest

from conftest import CONFIGS, ROOT, load_script
from sealts.scene import load_scene


@pytest.fixture(scope="module")
def report():
    return load_script("paper_report")


@pytest.mark.parametrize("path", sorted(CONFIGS.glob("paper_*.toml")), ids=lambda p: p.stem)
def test_paper_scenes_load(path):
    s = load_scene(path)
    assert s.model == "seal" and s.name == path.stem
    # the report's default mesh: the shipped cycle's, refined at the contact's edges
    # (mesh.h_edge, the setting within the work-precision benchmark's bounds)
    default = load_scene(CONFIGS / "oring_stroke.toml").mesh
    assert (s.mesh.h_contact, s.mesh.h_bulk, s.mesh.h_edge, s.mesh.edge_span) == (
        default.h_contact, default.h_bulk, default.h_edge, default.edge_span)


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
    assert (s.mesh.h_contact, s.mesh.h_bulk, s.mesh.h_edge) == (0.1, 0.4, 0.0)
    assert s.start.state == (str(state.resolve()) if run.state else "")
    if key == "ihl12_500":
        assert s.rod.velocity == 500.0
    else:
        assert s.viscoelastic.prony == "table2" and s.stroke.t_end == 54000.0


def test_report_default_mesh_is_the_shipped_cycle_mesh(report):
    """The report runs on the mesh whose leakage is mesh-converged, the shipped cycle's,
    and its scene copies carry it whatever the scene says."""
    m = load_scene(CONFIGS / "oring_stroke.toml").mesh
    assert report.MESHES["default"] == (m.h_contact, m.h_bulk, m.h_edge)
    run = next(r for r in report.RUNS if r.key == "state_1mpa")
    text = report.scene_copy(run, (0.025, 0.2, 0.003), ROOT)
    assert re.search(r"^h_edge = 0\.003\b", text, re.M)


class RootComm:
    def getRank(self):
        return 0


AREA = 2 * np.pi * 25.0              # mm, the paper scenes' rod radius 25 mm
Y = np.linspace(-1.5, 1.5, 61)
BUMP = np.clip(1.0 - Y**2, 0.0, None)  # the contact on |y| < 1


def stroke_run(d, times, flow_film, v_end, net=0.0):
    """A stroke's output: profiles at ``times`` (dry at t = 0, a film after), a series
    ending at rod speed v_end with the flow that ``flow_film`` carries, a summary."""
    from sealts.io.writer import Writer
    w = Writer(d, RootComm(), plots=False)
    for t in times:
        wet = t > 0.0
        h = 1e-3 * (0.6 + Y**2) if not wet else 5e-4 + 1e-6 * np.log1p(t) + 1e-3 * Y**4
        w.profile(t, {"y": Y, "h": h, "p": 1.8 * BUMP * wet, "p_asperity": (2.0 - 1.8 * wet) * BUMP,
                      "tau": -1e-3 * BUMP * wet, "tau_solid": 0.02 * BUMP * wet},
                  name="stroke_profiles.csv")
    ts = np.unique(np.r_[0.0, np.geomspace(1e-3, times[-1], 40), times])
    for t in ts:
        v = v_end * min(t / 0.1, 1.0)
        w.series({"t": float(t), "v": v, "Q_out": 0.5 * AREA * v * flow_film,
                  "V_in": 0.0, "V_out": net * t / ts[-1], "load_asperity": 20.0,
                  "load_fluid": 180.0, "friction_solid": 2.0 * np.sign(v),
                  "friction_fluid": 0.05 * np.sign(v), "friction_total": 2.05 * np.sign(v)})
    w.summary({"results": {}, "stroke": {
        "unknowns": 700, "steps_accepted": 40, "steps_rejected": 1, "leakage_out": net,
        "leakage_in": 0.0, "outstroke_transport": 80.0 + net, "instroke_transport": -80.0,
        "peak_friction_outstroke": 60.0, "peak_friction_instroke": 55.0, "h_min": 4e-4}})
    w.close()


def ihl_run(d, speed):
    from sealts.film.ihl import ihl_estimate, pressure_gradient
    from sealts.io.writer import Writer
    p = 2.0 * BUMP**1.5
    w = Writer(d, RootComm(), plots=False)
    w.profile(0.0, {"y": Y, "h": 1e-3 * (0.6 + Y**2), "p_contact": p, "p_fluid": 0 * p,
                    "p": p, "dp_dy": pressure_gradient(Y, p)}, name="ihl_profile.csv")
    w.summary({"ihl": ihl_estimate(Y, p, 1e-8, speed, AREA), "viscosity": 1e-8})
    w.close()


def fake_runs(out, report):
    """Every run of the report, finished, with made-up but consistent output."""
    import json
    for r in report.RUNS:
        d = out / "runs" / r.key
        d.mkdir(parents=True)
        (d / "done.json").write_text(json.dumps({"returncode": 0, "wall_s": 1.0,
                                                 "commit": "test"}))
    for key, net in (("fig14_he", 12.34), ("fig14_ve", 12.5), ("fig14_ve_sq", 12.6),
                     ("fig14_ve_sq_ff", 14.0)):
        stroke_run(out / "runs" / key, [0.0, 5.0, 10.0], 5e-4, 0.0, net)
    stroke_run(out / "runs" / "fig8_out", [0.0, 0.5, 1.0], 4.56e-4, 100.0)
    stroke_run(out / "runs" / "fig8_in", [0.0, 0.5, 1.0], 4.0e-4, -100.0)
    stroke_run(out / "runs" / "fig11_ff", [0.0, 0.5, 1.0], 4.4e-4, 100.0)
    stroke_run(out / "runs" / "fig9_lt", [0.0, 0.1, 0.5, 1.0], 7e-4, 500.0)
    stroke_run(out / "runs" / "fig9_ve", [0.0, 0.1, 1.0, 10.0, 3600.0, 54000.0], 7.1e-4, 500.0)
    stroke_run(out / "runs" / "fig12_100", [0.0, 0.5, 1.0], 3e-4, 100.0)
    stroke_run(out / "runs" / "fig12_500", [0.0, 0.5, 1.0], 7.7e-4, 500.0)
    ihl_run(out / "runs" / "ihl12_100", 100.0)
    ihl_run(out / "runs" / "ihl12_500", 500.0)
    ihl_run(out / "runs" / "ihl14", 500.0)
    from sealts.io.writer import Writer
    for key in ("state_1mpa", "state_0mpa"):
        w = Writer(out / "runs" / key, RootComm(), plots=False)
        w.profile(4.0, {"y": Y, "h": 1e-3 * (0.6 + Y**2), "p_contact": 2.0 * BUMP**1.5})
        w.summary({"nodes": 500, "elements": 400,
                   "results": {"contact_force_total": 850.0, "p_contact_max": 2.5}})
        w.close()


def test_report_renders_the_numbers_of_the_runs(report, tmp_path):
    """Every section renders from the runs' files (no section is "not available", no NaN),
    and numbers in the files come out in the report: the flow film 2 Q / (A v) with A from
    the scenes' rod radius, the runs' net leakage, the dry contact peak."""
    fake_runs(tmp_path, report)
    rep = report.Report(tmp_path, "coarse", report.MESHES["coarse"], {}, plots=False)
    rep.write("abc", 60.0, ["scripts/paper_report.py", "--report-only"])
    text = (tmp_path / "report.md").read_text()
    assert "Not available" not in text and not re.search(r"\bnan\b", text, re.I)
    assert "out 0.456 um, in 0.400 um" in text             # Fig. 8 flow films
    assert "| he | hyperelastic, steady Reynolds | 12.34 |" in text
    assert "peak dry contact pressure 2.50 MPa" in text
    assert rep.numbers["fig12"][500]["hq"] == pytest.approx(7.7e-4)
    assert rep.numbers["fig14"]["net"]["ve,sq,Φ"] == 14.0
