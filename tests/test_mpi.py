"""MPI: mpi4py and PETSc share one MPI library; two ranks reproduce the serial answer."""
import os
import shutil
import subprocess
import sys

import numpy as np
import pytest

from conftest import CONFIGS, ROOT, config_text
from sealts.io.results import Results

MPIEXEC = shutil.which("mpiexec")


def test_mpi4py_and_petsc_use_the_same_mpi_library():
    from mpi4py import MPI
    from petsc4py import PETSc  # noqa: F401  (loads libpetsc and its MPI)
    libs = set()
    with open("/proc/self/maps") as f:
        for line in f:
            path = line.split()[-1]
            if "libmpi" in os.path.basename(path) and path.startswith("/"):
                libs.add(os.path.realpath(path))
    assert len(libs) == 1, libs
    assert "MPICH" in MPI.Get_library_version()


def _run(n, scene, out, *opts):
    cmd = [sys.executable, "-m", "sealts", "run", str(CONFIGS / scene), "-o", str(out), *opts]
    if n > 1:
        cmd = [MPIEXEC, "-n", str(n)] + cmd
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT, timeout=600)
    assert r.returncode == 0, r.stderr
    res = Results(out)
    return res.summary, np.concatenate([p["p"] for p in res.profiles().values()])


@pytest.mark.mpi
@pytest.mark.skipif(MPIEXEC is None, reason="mpiexec not found")
@pytest.mark.parametrize("scene, opts", [("slider.toml", ()),
                                         ("slider.toml", ("-snes_type", "newtonls")),
                                         ("squeeze_plates.toml", ("-ts_adapt_type", "none"))])
def test_two_ranks_match_one(tmp_path, scene, opts):
    s1, p1 = _run(1, scene, tmp_path / "serial", *opts)
    s2, p2 = _run(2, scene, tmp_path / "mpi", *opts)
    assert s2["ranks"] == 2
    assert np.abs(p1 - p2).max() <= 1e-9 * np.abs(p1).max()
    for key in ("p_max", "load", "Q_in", "Q_out"):
        assert s2["results"][key] == pytest.approx(s1["results"][key], rel=1e-9)
    assert s2["steps_accepted"] == s1["steps_accepted"]


def _summary(n, cfg, out, timeout=600):
    """summary.json of ``sealts run cfg`` on n ranks."""
    cmd = [sys.executable, "-m", "sealts", "run", str(cfg), "-o", str(out)]
    if n > 1:
        cmd = [MPIEXEC, "-n", str(n)] + cmd
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT, timeout=timeout)
    assert r.returncode == 0, r.stderr
    return Results(out).summary


@pytest.mark.mpi
@pytest.mark.skipif(MPIEXEC is None, reason="mpiexec not found")
def test_user_error_under_mpi_exits_on_every_rank(tmp_path):
    """A bad output directory fails on all ranks alike: exit 2, no hang."""
    blocker = tmp_path / "file"
    blocker.write_text("x")
    r = subprocess.run([MPIEXEC, "-n", "2", sys.executable, "-m", "sealts", "run", "-o",
                        str(blocker)], capture_output=True, text=True, cwd=ROOT, timeout=60)
    assert r.returncode == 2
    assert r.stderr.count("output directory") == 2


@pytest.mark.mpi
@pytest.mark.skipif(MPIEXEC is None, reason="mpiexec not found")
def test_mounted_and_pressurised_seal_on_two_ranks(tmp_path):
    """The coarse O-ring mounted and pressurised on 2 ranks matches 1 rank. The seal's
    DMPlex is distributed and each rank assembles its own cells (rank 0 also the rod, groove
    and pressure terms along the boundary); the summary reports the cells per rank. The
    linear solve is PETSc's, redundant LU."""
    text = config_text("oring_pressurise",
                       mesh={"h_contact": 0.1, "h_bulk": 0.4, "cache": str(tmp_path)})
    cfg = tmp_path / "coarse.toml"
    cfg.write_text(text)
    out = {n: _summary(n, cfg, tmp_path / f"r{n}") for n in (1, 2)}
    a, b = out[1]["results"], out[2]["results"]
    assert out[2]["ranks"] == 2
    cells = out[2]["cells_per_rank"]
    assert len(cells) == 2 and min(cells) > 0 and sum(cells) == out[1]["elements"]
    assert out[1]["cells_per_rank"] == [out[1]["elements"]]
    for key in ("contact_force_total", "contact_width", "p_contact_max"):
        assert b[key] == pytest.approx(a[key], rel=1e-6)
    assert b["mounted"]["contact_force_total"] == pytest.approx(
        a["mounted"]["contact_force_total"], rel=1e-6)


@pytest.mark.mpi
@pytest.mark.skipif(MPIEXEC is None, reason="mpiexec not found")
def test_edge_refinement_on_two_ranks_is_the_serial_one(tmp_path):
    """mesh.h_edge on 2 ranks: the refinement passes (steps 1-2 on the scene's mesh, their
    state carried to meshes refined at the contact's edges until they hold them) run on
    rank 0 alone, so the mesh does not depend on the number of ranks: the same passes,
    edges and nodes as one rank; the ranks take rank 0's state and results."""
    text = config_text("oring_pressurise",
                       mesh={"h_contact": 0.1, "h_bulk": 0.4, "h_edge": 0.01,
                             "cache": str(tmp_path)})
    cfg = tmp_path / "coarse.toml"
    cfg.write_text(text)
    out = {n: _summary(n, cfg, tmp_path / f"r{n}") for n in (1, 2)}
    a, b = out[1]["mesh_refinement"], out[2]["mesh_refinement"]
    assert b["passes_on"] == "rank 0" and out[2]["ranks"] == 2
    assert out[2]["nodes"] == out[1]["nodes"] > a["base_nodes"]
    assert len(b["passes"]) == len(a["passes"])
    for pa, pb in zip(a["passes"], b["passes"]):
        assert np.allclose(pb["edges_reference_mm"], pa["edges_reference_mm"], atol=1e-9)
    for key in ("contact_force_total", "contact_width", "p_contact_max"):
        assert out[2]["results"][key] == pytest.approx(out[1]["results"][key], rel=1e-6)
    assert out[2]["analysis"] == out[1]["analysis"] == "mount + pressurise + transfer"


@pytest.mark.mpi
@pytest.mark.skipif(MPIEXEC is None, reason="mpiexec not found")
def test_viscoelastic_hold_on_two_ranks(tmp_path):
    """The coarse O-ring's viscoelastic hold (two Prony terms, both active; 1 -> 3 MPa,
    held to 0.05 s) on 2 ranks matches 1 rank: the Prony dofs live on each rank's own
    cells, and the Schur fieldsplit gets each rank's owned dofs of each field."""
    text = config_text("oring_hold",
                       mesh={"h_contact": 0.1, "h_bulk": 0.4, "cache": str(tmp_path)},
                       viscoelastic={"prony": "custom", "prony_g": [0.5, 0.3],
                                     "prony_tau": [0.01, 1.0], "t_min": 1e-3},
                       hold={"t_end": 0.05},
                       start={"cache": False})     # the 2 ranks pressurise, not the cache
    cfg = tmp_path / "hold.toml"
    cfg.write_text(text)
    out = {n: _summary(n, cfg, tmp_path / f"r{n}", timeout=900) for n in (1, 2)}
    assert min(out[2]["cells_per_rank"]) > 0
    a, b = out[1]["results"], out[2]["results"]
    assert out[2]["hold"]["unknowns"] == out[1]["hold"]["unknowns"]
    assert out[2]["hold"]["linear_iterations"] == out[2]["hold"]["newton_iterations"]
    for key in ("contact_force_total", "p_contact_max"):
        assert b[key] == pytest.approx(a[key], rel=1e-6)
    assert b["pressurised"]["contact_force_total"] == pytest.approx(
        a["pressurised"]["contact_force_total"], rel=1e-6)


@pytest.mark.mpi
@pytest.mark.skipif(MPIEXEC is None, reason="mpiexec not found")
@pytest.mark.parametrize("viscoelastic", [False, True])
def test_stroke_on_two_ranks_matches_one(tmp_path, viscoelastic):
    """The coupled stroke (seal + film + friction) on the distributed numbering, each rank
    assembling the solid of its own cells and rank 0 the boundary terms, matches 1 rank: a
    coarse 20 ms ramp to 100 mm/s; leakage and peak friction to 3e-5, min h to 1e-4, the
    accepted steps to 5 %. Viscoelastic (two active Prony terms): the
    stroke's fields, whose stresses each rank would only know on its own cells, are the
    same as on one rank."""
    ve = ({"viscoelastic": {"prony": "custom", "prony_g": [0.5, 0.3],
                            "prony_tau": [0.01, 1.0], "t_min": 1e-3}}
          if viscoelastic else {})
    text = config_text("oring_stroke",
                       mesh={"h_contact": 0.1, "h_bulk": 0.4, "cache": str(tmp_path)},
                       stroke={"velocity": "ramp-hold", "t_ramp": 0.01, "v_max": 100.0,
                               "t_end": 0.02, "output_times": []},
                       start={"cache": False}, **ve)   # the 2 ranks mount, not the cache
    cfg = tmp_path / "stroke.toml"
    cfg.write_text(text)
    out = {n: _summary(n, cfg, tmp_path / f"r{n}") for n in (1, 2)}
    a, b = out[1]["stroke"], out[2]["stroke"]
    assert out[2]["ranks"] == 2
    cells = out[2]["cells_per_rank"]
    assert len(cells) == 2 and min(cells) > 0 and sum(cells) == out[1]["cells_per_rank"][0]
    # round-off (the ranks sum the residual in another order) moves the step sequence
    # and with it these by up to 6e-6 here (the whole cycle's round-off spread is 1e-4,
    # tests/test_stroke_accuracy.py)
    for key in ("leakage_out", "peak_friction_outstroke"):
        assert b[key] == pytest.approx(a[key], rel=3e-5)
    # the smallest gap over the accepted states: sampled where the steps fall, which
    # the ranks' other order of summation moves by round-off (measured 5e-6)
    assert b["h_min"] == pytest.approx(a["h_min"], rel=1e-4)
    # the step sequence itself follows round-off (and, through the pressurisation's
    # front walk, which step a node's contact pressure crosses p at): a sanity bound only
    assert abs(b["steps_accepted"] - a["steps_accepted"]) <= 0.05 * a["steps_accepted"]
    f1, f2 = (Results(tmp_path / f"r{n}").fields("stroke_fields") for n in (1, 2))
    m1, m2 = f1.cell_data["von_mises"][-1], f2.cell_data["von_mises"][-1]
    assert m1.shape == m2.shape == (out[1]["cells_per_rank"][0],)
    assert np.abs(m2 - m1).max() <= 1e-5 * np.abs(m1).max()
