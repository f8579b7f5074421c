"""Checkpoint and restart of the stroke: ``sealts run SCENE --restart OUTDIR``.

The stroke writes a checkpoint at each of its stops (output times, the reversal, t_end),
where the run restarts its integrator anyway (BDF from first order, ``TSRestartStep``).
A run stopped by SIGTERM part-way and restarted goes on from its last checkpoint; since the
restarted run meets the same states, steps and histories (U, the next step, the friction
anchors) as the uninterrupted one, its series, profiles, field frames and results are the
uninterrupted run's to the last bit, wherever the signal fell. Only the wall time and
``restarted_at`` differ. A checkpoint is refused for a scene that differs in a key that
moves the answer, naming the key.
"""
import json
import shutil
import signal
import subprocess
import sys
import time

import h5py
import numpy as np
import pytest

from conftest import ROOT, config_text


def _sealts(*args, **kw):
    return subprocess.run([sys.executable, "-m", "sealts", "run", *map(str, args)],
                          capture_output=True, text=True, cwd=ROOT, timeout=600, **kw)


def _interrupted(scene, out, after, launch=()):
    """Run the scene, SIGTERM it once its series passes t = after (s)."""
    p = subprocess.Popen([*launch, sys.executable, "-m", "sealts", "run", str(scene), "-o",
                          str(out)],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT)
    series, t0 = out / "series.csv", time.monotonic()
    while p.poll() is None and time.monotonic() - t0 < 300:
        try:
            last = series.read_text().splitlines()[-1].split(",")[0]
            if float(last) > after:
                p.send_signal(signal.SIGTERM)
                break
        except (OSError, IndexError, ValueError):
            pass
        time.sleep(0.02)
    p.communicate(timeout=120)
    return p.returncode


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """The coarse O-ring cycle (0.1/0.4 mesh, the paper's 10 s sine, stops at 1, 2.5, 5, 6,
    7.5 and 10 s) run whole (a), and stopped after t = 3 s then restarted (b)."""
    d = tmp_path_factory.mktemp("restart")
    text = config_text("oring_stroke", mesh={"h_contact": 0.1, "h_bulk": 0.4,
                                             "cache": str(ROOT / "meshes")},
                       output={"plot": False},
                       start={"cache": False})     # both runs mount: equal counts too
    scene = d / "coarse.toml"
    scene.write_text(text)
    r = _sealts(scene, "-o", d / "a")
    assert r.returncode == 0, r.stderr
    code = _interrupted(scene, d / "b", after=3.0)
    stopped = json.loads((d / "b" / "summary.json").read_text())
    restarted = _sealts(scene, "--restart", d / "b")
    return d, scene, text, code, stopped, restarted


def test_a_stopped_stroke_restarted_is_the_uninterrupted_one(runs):
    d, _, _, code, stopped, restarted = runs
    assert code == 143 and stopped["status"] == "interrupted"
    assert 3.0 < stopped["t_reached"] < 10.0
    assert restarted.returncode == 0, restarted.stderr
    assert "stroke resumed at t = 2.5 s" in restarted.stdout   # the stop before t = 3 s
    a, b = (json.loads((d / x / "summary.json").read_text()) for x in "ab")
    assert b["status"] == "finished" and b["stroke"].pop("restarted_at") == 2.5
    for s in (a, b):
        s["stroke"].pop("wall_time_s")
        for k in ("wall_time_s", "provenance"):
            s.pop(k)
    assert b == a          # every result and count, to the last bit
    for name in ("series.csv", "stroke_profiles.csv", "stroke_fields.xdmf"):
        assert (d / "b" / name).read_text() == (d / "a" / name).read_text(), name
    with h5py.File(d / "a" / "stroke_fields.h5") as fa, \
            h5py.File(d / "b" / "stroke_fields.h5") as fb:
        assert sorted(fa) == sorted(fb)
        for g in fa:
            for k in fa[g]:
                assert np.array_equal(fa[g][k][()], fb[g][k][()]), (g, k)
    ma, mb = (json.loads((d / x / "manifest.json").read_text())["files"] for x in "ab")
    assert sorted(ma) == sorted(mb)


def test_a_checkpoint_of_another_scene_is_refused(runs):
    d, _, text, *_ = runs
    other = d / "other.toml"
    other.write_text(text.replace("v_max = 500.0", "v_max = 400.0"))
    assert other.read_text() != text
    r = _sealts(other, "--restart", d / "a")
    assert r.returncode == 2 and "Traceback" not in r.stderr
    line, = r.stderr.strip().splitlines()
    assert "another scene" in line and "stroke.v_max = 500.0 there, 400.0 here" in line


def test_a_finished_stroke_goes_on_to_a_later_end(runs, tmp_path):
    """The steering keys (stroke.t_end, dt, rtol, stabilisation, output times, [petsc]) may
    change on a restart: the finished cycle restarted with t_end = 11 s goes on from its
    checkpoint at 10 s, keeps every row it had, and the summary names the change. A t_end
    before the checkpoint is refused."""
    d, _, text, *_ = runs
    out = tmp_path / "a"
    shutil.copytree(d / "a", out)
    before = (out / "series.csv").read_text()
    longer = tmp_path / "longer.toml"
    longer.write_text(text.replace("t_end = 10.0", "t_end = 11.0"))
    assert longer.read_text() != text
    r = _sealts(longer, "--restart", out)
    assert r.returncode == 0, r.stderr
    s = json.loads((out / "summary.json").read_text())["stroke"]
    assert s["restarted_at"] == 10.0 and s["t_end"] == 11.0
    assert s["restart_changes"] == {"stroke.t_end": [10.0, 11.0]}
    after = (out / "series.csv").read_text()
    assert after.startswith(before) and len(after) > len(before)
    assert float(after.splitlines()[-1].split(",")[0]) == 11.0
    shorter = tmp_path / "shorter.toml"
    shorter.write_text(text.replace("t_end = 10.0", "t_end = 9.0"))
    r = _sealts(shorter, "--restart", out)
    assert r.returncode == 2 and "past stroke.t_end = 9 s" in r.stderr


MPIEXEC = shutil.which("mpiexec")


@pytest.mark.mpi
@pytest.mark.skipif(MPIEXEC is None, reason="mpiexec not found")
def test_restart_on_two_ranks(runs, tmp_path):
    """On two ranks (each assembling its own cells, rank 0 the boundary terms, the others
    running their hooks: the friction anchors live on every rank) a stopped and restarted
    cycle is the uninterrupted two-rank cycle to the last bit (the cycle's first 5.5 s:
    stops at 1, 2.5 and the reversal, 5 s)."""
    _, _, text, *_ = runs
    scene = tmp_path / "first_half.toml"
    scene.write_text(text.replace("t_end = 10.0", "t_end = 5.5").replace(
        "output_times = [1.0, 2.5, 5.0, 6.0, 7.5]", "output_times = [1.0, 2.5, 5.0]"))
    assert scene.read_text() != text
    mpi = (MPIEXEC, "-n", "2")
    a, b = tmp_path / "a", tmp_path / "b"
    r = subprocess.run([*mpi, sys.executable, "-m", "sealts", "run", str(scene), "-o", str(a)],
                       capture_output=True, text=True, cwd=ROOT, timeout=600)
    assert r.returncode == 0, r.stderr
    _interrupted(scene, b, after=3.0, launch=mpi)
    assert json.loads((b / "summary.json").read_text())["status"] == "interrupted"
    r = subprocess.run([*mpi, sys.executable, "-m", "sealts", "run", str(scene), "--restart",
                        str(b)], capture_output=True, text=True, cwd=ROOT, timeout=600)
    assert r.returncode == 0, r.stderr
    sa, sb = (json.loads((x / "summary.json").read_text()) for x in (a, b))
    assert sb["ranks"] == 2 and sb["stroke"].pop("restarted_at") == 2.5
    for s in (sa, sb):
        s["stroke"].pop("wall_time_s")
        for k in ("wall_time_s", "provenance"):
            s.pop(k)
    assert sb == sa
    assert (b / "series.csv").read_text() == (a / "series.csv").read_text()


def test_a_viscoelastic_stroke_extended_is_the_longer_run(tmp_path):
    """The paper's viscoelastic cycle with squeeze and flow factors (coarse mesh; the Prony
    variables are unknowns, the start relaxes them): run to 0.5 s and then restarted with
    t_end = 0.75 s, it is the 0.75 s run from scratch to the last bit (same stops, 0.25 and
    0.5 s): the start's relaxed Prony stress is set up again, the rest comes from the
    checkpoint."""
    texts = {t: config_text("paper_fig14_ve_sq_ff", mesh={"h_contact": 0.1, "h_bulk": 0.4,
                                                          "cache": str(ROOT / "meshes")},
                            stroke={"t_end": t, "output_times": [0.25, 0.5]},
                            output={"plot": False, "progress": False},
                            start={"cache": False})     # both mount: equal counts too
             for t in (0.5, 0.75)}
    scenes = {}
    for t, text in texts.items():
        scenes[t] = tmp_path / f"t{t:g}.toml"
        scenes[t].write_text(text)
    r = _sealts(scenes[0.75], "-o", tmp_path / "whole")
    assert r.returncode == 0, r.stderr
    r = _sealts(scenes[0.5], "-o", tmp_path / "part")
    assert r.returncode == 0, r.stderr
    r = _sealts(scenes[0.75], "--restart", tmp_path / "part")
    assert r.returncode == 0, r.stderr
    a, b = (json.loads((tmp_path / x / "summary.json").read_text()) for x in ("whole", "part"))
    assert b["stroke"].pop("restart_changes") == {"stroke.t_end": [0.5, 0.75]}
    assert b["stroke"].pop("restarted_at") == 0.5
    assert a["stroke"]["unknowns"] > 10 * a["unknowns"]          # the Prony variables
    for s in (a, b):
        s["stroke"].pop("wall_time_s")
        for k in ("wall_time_s", "provenance"):
            s.pop(k)
    assert b == a
    for name in ("series.csv", "stroke_profiles.csv"):
        assert (tmp_path / "part" / name).read_text() == (tmp_path / "whole" / name).read_text()


def test_a_stopped_hold_restarted_is_the_uninterrupted_one(tmp_path):
    """The viscoelastic hold (coarse O-ring, two Prony terms, 1 -> 5 MPa, held to 1000 s)
    checkpoints at its start and at the decades of t; stopped by SIGTERM after t = 2 s and
    restarted, it goes on from t = 1 s with the front where it stood (RelaxedFront's
    history: the reach and its relaxation) and is the uninterrupted hold to the last bit,
    its long-term check included."""
    text = config_text("oring_hold", mesh={"h_contact": 0.1, "h_bulk": 0.4,
                                           "cache": str(ROOT / "meshes")},
                       viscoelastic={"prony": "custom", "prony_g": [0.5, 0.3],
                                     "prony_tau": [0.01, 1.0], "t_min": 1e-3},
                       hold={"t_end": 1e3}, output={"plot": False},
                       start={"cache": False})     # both runs pressurise: equal counts too
    scene = tmp_path / "hold.toml"
    scene.write_text(text)
    a, b = tmp_path / "a", tmp_path / "b"
    r = _sealts(scene, "-o", a)
    assert r.returncode == 0, r.stderr
    assert _interrupted(scene, b, after=2.0) == 143
    r = _sealts(scene, "--restart", b)
    assert r.returncode == 0, r.stderr
    assert "hold resumed at t = 1 s" in r.stdout
    sa, sb = (json.loads((x / "summary.json").read_text()) for x in (a, b))
    assert sb["hold"].pop("restarted_at") == 1.0
    for s in (sa, sb):
        for k in ("wall_time_s", "provenance"):
            s.pop(k)
    assert sb == sa
    for name in ("series.csv", "hold_profiles.csv"):
        assert (b / name).read_text() == (a / name).read_text(), name
