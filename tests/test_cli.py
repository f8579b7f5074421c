"""sealts run: output contract, PETSc options from the command line and from the scene."""
import subprocess
import sys

import numpy as np
import pytest

from closed_forms import slider_pressure
from conftest import CONFIGS, ROOT
from sealts.io.results import Results, read_series


def sealts(*args):
    return subprocess.run([sys.executable, "-m", "sealts", *args], capture_output=True,
                          text=True, cwd=ROOT)


def test_slider_run_writes_the_output_contract(tmp_path):
    out = tmp_path / "out"
    r = sealts("run", str(CONFIGS / "slider.toml"), "-o", str(out))
    assert r.returncode == 0, r.stderr
    summary = Results(out).summary
    res = summary["results_t0"]
    assert summary["scene"] == "slider" and summary["status"] == "finished"
    for key in ("wall_time_s", "steps_accepted", "steps_rejected", "newton_iterations",
                "linear_iterations"):
        assert key in summary
    assert res["p_max"] == pytest.approx(2.75, rel=1e-4)
    assert res["y_at_p_max"] == pytest.approx(7.5, abs=2e-3)
    for key in ("load", "Q_in", "Q_out", "friction_fluid", "V_in", "V_out"):
        assert key in res
    # at t_end = 0.5 s the gap has closed by 0.5 um: closed form with the shifted gap
    end = summary["results"]
    y = np.linspace(0.0, 10.0, 100001)
    p_end, _ = slider_pressure(y, 10.0, 0.0025, 0.002, 100.0, 1e-8, -0.001)
    assert end["t"] == pytest.approx(0.5)
    assert end["p_max"] == pytest.approx(p_end.max(), rel=1e-4)
    profiles = Results(out).profiles()
    assert list(profiles) == [0.0, 0.25, 0.5]
    for p in profiles.values():
        assert list(p) == ["y", "h", "p", "tau"] and p["y"].size == 1001
    series = Results(out).series
    assert len(series["t"]) == summary["steps_accepted"] + 1  # plus the initial state
    h5 = read_series(out / "series.h5")                  # the same series in HDF5
    assert list(h5) == list(series)
    for k in series:
        assert np.allclose(h5[k], series[k], rtol=1e-9)
    for name in ("profiles.png", "series.png"):
        assert (out / name).stat().st_size > 10_000


def test_command_line_petsc_options_reach_the_solvers(tmp_path):
    r = sealts("run", str(CONFIGS / "squeeze_plates.toml"), "-o", str(tmp_path),
               "-ts_type", "beuler", "-ts_adapt_type", "none", "-ts_dt", "0.125",
               "-snes_monitor", "-ts_view")
    assert r.returncode == 0, r.stderr
    assert "SNES Function norm" in r.stdout
    assert "type: beuler" in r.stdout        # the command line beat the scene's bdf
    out = Results(tmp_path)
    assert out.summary["steps_accepted"] == 8    # 1 s at the fixed dt of 0.125 s
    # the summary records what the run needs to be repeated: the options as given, the
    # solvers they led to (the default LU solver too), the resolved scene with every
    # default, the versions
    import dataclasses
    import json
    from importlib import metadata

    from sealts.scene import load_scene
    prov = out.summary["provenance"]
    assert prov["petsc_options"]["ts_type"] == "beuler"
    assert prov["petsc_options"]["ts_dt"] == "0.125"
    solver = prov["solvers"]["(none)"]
    assert solver["ts_type"] == "beuler" and solver["pc_type"] == "lu"
    assert solver["pc_factor_mat_solver_type"] == "petsc"   # small: PETSc's own LU
    scene = json.loads(json.dumps(dataclasses.asdict(load_scene(CONFIGS / "squeeze_plates.toml"))))
    assert prov["scene"] == scene and "flow_factors" in prov["scene"]["film"]
    assert prov["sealts_version"] == metadata.version("sealts")
    assert prov["petsc4py_version"] == metadata.version("petsc4py")
    assert prov["petsc_version"] == prov["petsc4py_version"]
    import re
    assert prov["git_commit"] is None or re.fullmatch(r"[0-9a-f]{40}\+?", prov["git_commit"])
    assert out.series["t"][-1] == pytest.approx(1.0)


def test_scene_petsc_table_is_used_when_command_line_is_silent(tmp_path):
    r = sealts("run", str(CONFIGS / "squeeze_plates.toml"), "-o", str(tmp_path), "-ts_view")
    assert r.returncode == 0, r.stderr
    assert "type: bdf" in r.stdout


def test_diverging_solve_is_one_line_exit_3(tmp_path):
    r = sealts("run", str(CONFIGS / "slider.toml"), "-o", str(tmp_path), "-snes_max_it", "0",
               "-snes_rtol", "1e-300", "-snes_atol", "0", "-snes_stol", "0")
    assert r.returncode == 3, (r.stdout, r.stderr)
    assert r.stderr.startswith("solve error: steady Newton solve diverged")
    assert "Traceback" not in r.stderr
    # the failed run still writes its summary: status, the failing step and why
    summary = Results(tmp_path).summary
    assert summary["status"] == "failed"
    assert "SolveError: steady Newton solve diverged" in summary["error"]


@pytest.mark.parametrize("option, value, named", [
    ("-ts_adapt_type", "foo", 'Unknown TSAdapt type "foo"'),
    ("-snes_linesearch_type", "nope", "Line Search type nope"),
    ("-ts_rtol", "abc", "abc has no numeric value"),
    ("-transfer_snes_linesearch_type", "nope", "Line Search type nope")])
def test_bad_petsc_option_value_is_one_line_exit_2(tmp_path, option, value, named):
    """An invalid value of a PETSc option (command line or the scene's [petsc] table) is one
    line naming it, not PETSc's call stack and a Python traceback."""
    r = sealts("run", str(CONFIGS / "slider.toml"), "-o", str(tmp_path), option, value)
    assert r.returncode == 2, (r.stdout, r.stderr)
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("PETSc error: "), r.stderr
    assert named in lines[0]


def test_every_solver_prefix_is_accepted(tmp_path):
    """An option of each sealts solver's prefix (README, "Running") is read, not refused
    as unknown: ``transfer_`` is the Newton solve of steps 1-2 carried to the mesh
    of mesh.h_edge (sealts.steps.transfer); ``*_condensed_`` the KSP of the viscoelastic
    problems' S (sealts.problem.condensed), which has no SNES."""
    from sealts.cli import SOLVER_PREFIXES
    assert "transfer_" in SOLVER_PREFIXES
    args = [a for p in SOLVER_PREFIXES if p
            for a in ((f"-{p}pc_factor_mat_ordering_type", "amd") if p.endswith("condensed_")
                      else (f"-{p}snes_max_it", "60"))]
    r = sealts("run", str(CONFIGS / "slider.toml"), "-o", str(tmp_path), *args)
    assert r.returncode == 0, r.stderr


def test_bad_petsc_option_leaves_the_last_results_in_place(tmp_path):
    """The options are read through every solver prefix before the output directory is
    touched: a bad value of a later step's option (the stroke's) stops the run before it
    clears the last run's files."""
    assert sealts("run", str(CONFIGS / "slider.toml"), "-o", str(tmp_path)).returncode == 0
    before = (tmp_path / "summary.json").read_text()
    r = sealts("run", str(CONFIGS / "slider.toml"), "-o", str(tmp_path),
               "-stroke_ts_adapt_type", "foo")
    assert r.returncode == 2 and 'Unknown TSAdapt type "foo"' in r.stderr
    assert (tmp_path / "summary.json").read_text() == before
    assert (tmp_path / "series.csv").stat().st_size > 0


def test_help_shows_petsc_help(tmp_path):
    """PETSc's own -help reaches the user (on the slider: a film-only TS and SNES, a second)."""
    r = sealts("run", str(CONFIGS / "slider.toml"), "-o", str(tmp_path), "-help")
    assert r.returncode == 0, r.stderr
    assert "-snes_type" in r.stdout and "-ksp_type" in r.stdout


def test_double_dash_help_prints_the_usage_and_runs_nothing(tmp_path):
    """``sealts run --help`` (or ``-h``) used to pass the flag on to PETSc and run the default
    scene for a minute; it prints the usage and where PETSc's options are listed, and writes
    nothing."""
    for flag in ("--help", "-h"):
        r = sealts("run", flag, "-o", str(tmp_path / "out"))
        assert r.returncode == 0, r.stderr
        assert r.stdout.startswith("usage: sealts run") and "-help" in r.stdout
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("sig, code", [("SIGINT", 130), ("SIGTERM", 143)])
def test_a_signal_ends_the_run_cleanly(tmp_path, sig, code):
    """SIGINT or SIGTERM in the middle of a transient run: one line, exit 128 + signal, the
    series flushed and closed (CSV and HDF5 agree row for row), summary.json written with
    status "interrupted", the step and the last accepted time."""
    import signal
    import time
    scene = tmp_path / "long.toml"
    scene.write_text((CONFIGS / "slider.toml").read_text().replace("t_end = 0.5 ", "t_end = 0.9")
                     .replace("output_times = [0.25]", "output_times = [0.45]"))
    out = tmp_path / "out"
    p = subprocess.Popen([sys.executable, "-m", "sealts", "run", str(scene), "-o", str(out),
                          "-ts_adapt_type", "none", "-ts_dt", "1e-6"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT)
    series = out / "series.csv"
    t0 = time.monotonic()
    while time.monotonic() - t0 < 120 and p.poll() is None:
        if series.is_file() and series.read_text().count("\n") > 20:
            break
        time.sleep(0.2)
    assert p.poll() is None, p.communicate()
    p.send_signal(getattr(signal, sig))
    stdout, stderr = p.communicate(timeout=60)
    assert p.returncode == code, (stdout, stderr)
    lines = stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"stopped: interrupted by {sig}"), stderr
    res = Results(out)
    summary = res.summary
    assert summary["status"] == "interrupted"
    assert summary["error"] == f"transient film: interrupted by {sig}"
    rows = res.series
    assert summary["t_reached"] == pytest.approx(rows["t"][-1])
    assert 0.0 < rows["t"][-1] < 0.9
    h5 = read_series(out / "series.h5")
    assert list(h5) == list(rows) and len(h5["t"]) == len(rows["t"])
    assert np.allclose(h5["t"], rows["t"], rtol=1e-9)
