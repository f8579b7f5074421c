"""User-supplied seal meshes (.geo / .msh with physical curves)."""
import subprocess
import sys

import numpy as np
import pytest

from conftest import CONFIGS, ROOT, scene
from sealts.mesh.mesh_file import MeshFileError, read_mesh_file
from sealts.steps import prepare

GEO = CONFIGS / "meshes" / "chamfered_ring.geo"


GROUPS = {"rod_side": (1,), "pressure_side": (2,), "groove": (3,), "atmosphere_side": (4, 5)}


def rectangle_geo(path, h, groups=GROUPS, recombine=True):
    """The rect_ring_mount cross-section (r 25.05..27.45, z -1..1) as a gmsh script; the
    atmosphere side is two lines so that a test can leave one of them out of every group."""
    corners = [(25.05, 1.0), (25.05, -1.0), (27.45, -1.0), (27.45, 1.0), (26.25, 1.0)]
    lines = [f"Point({i + 1}) = {{{r}, {z}, 0, {h}}};" for i, (r, z) in enumerate(corners)]
    lines += [f"Line({i + 1}) = {{{i + 1}, {(i + 1) % 5 + 1}}};" for i in range(5)]
    lines += ["Curve Loop(1) = {1, 2, 3, 4, 5};", "Plane Surface(1) = {1};"]
    lines += [f'Physical Curve("{g}") = {{{", ".join(map(str, c))}}};' for g, c in groups.items()]
    lines += ['Physical Surface("seal") = {1};']
    if recombine:
        lines += ["Mesh.RecombineAll = 1;", "Mesh.SubdivisionAlgorithm = 1;"]
    path.write_text("\n".join(lines) + "\n")
    return path


def test_file_mesh_mounts_like_the_builtin_rectangle(tmp_path):
    """The same rectangular ring from a .geo file and from the built-in shape, each on its own
    0.1 mm mesh, mounts to the same rod force within 1 % (the discretisation difference of
    two different meshes; the built-in rectangle's own 0.1 -> 0.05 mm change is below it)."""
    geo = rectangle_geo(tmp_path / "ring.geo", 0.2)
    forces = []
    # both sharp-cornered (the shipped ring rounds its rod-side corners)
    for seal in ({"shape": "file", "mesh_file": str(geo), "corner_radius": 0.0},
                 {"shape": "rectangle", "corner_radius": 0.0}):
        s = scene("rect_ring_mount", seal=seal, groove={"corner_radius": 0.0},
                  mesh={"h_contact": 0.1, "h_bulk": 0.1, "cache": str(tmp_path)})
        forces.append(prepare(s).results["contact_force_total"])
    assert forces[0] > 0
    assert forces[0] == pytest.approx(forces[1], rel=0.01)


def test_msh_and_geo_give_the_same_mesh(tmp_path):
    """A .msh written by gmsh from the shipped .geo reads back to the same mesh and groups."""
    import gmsh
    msh = tmp_path / "ring.msh"
    gmsh.initialize(interruptible=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(str(GEO))
        gmsh.model.mesh.generate(2)
        gmsh.write(str(msh))
    finally:
        gmsh.finalize()
    a = read_mesh_file(GEO, tmp_path / "a")
    b = read_mesh_file(msh, tmp_path / "b")
    assert np.allclose(a.X, b.X) and (a.conn == b.conn).all()
    for g in a.edges:
        assert len(a.edges[g]) == len(b.edges[g]) > 0
    # the rod side is the straight part at r = 25.05 and the 0.2 mm fillet, which ends where
    # the chamfer (pressure side) begins, at (25.10858, -0.75858)
    rod = a.X[a.nodes("rod_side")]
    assert rod[:, 0].min() == pytest.approx(25.05) and rod[:, 1].min() == pytest.approx(-0.75858)
    fillet = rod[rod[:, 1] < -0.6172]
    assert len(fillet) > 2 and np.allclose(np.hypot(fillet[:, 0] - 25.25,
                                                    fillet[:, 1] + 0.6172), 0.2, atol=1e-4)
    # cached: a second read does not call gmsh (it returns the stored arrays)
    assert list((tmp_path / "a").glob("file-*.npz"))


@pytest.mark.parametrize("kwargs, message", [
    ({"groups": {**{g: c for g, c in GROUPS.items() if g != "atmosphere_side"},
                 "atmosphere": (4, 5)}},
     "no physical curve named 'atmosphere_side'"),
    ({"groups": {**GROUPS, "atmosphere_side": (4,)}},
     "boundary edges are in no physical curve"),
    ({"recombine": False}, "only 4-node quadrilaterals are supported, found Triangle 3"),
])
def test_bad_mesh_files_name_the_problem(tmp_path, kwargs, message):
    geo = rectangle_geo(tmp_path / "bad.geo", 0.5, **kwargs)
    with pytest.raises(MeshFileError) as e:
        read_mesh_file(geo, tmp_path)
    assert message in str(e.value) and "bad.geo" in str(e.value)


def test_cli_mesh_file_errors_are_one_line(tmp_path):
    """A missing mesh file and a mesh that does not fit the groove: exit 2, one line."""
    cfg = tmp_path / "s.toml"
    text = (CONFIGS / "chamfered_ring_mount.toml").read_text()
    cfg.write_text(text.replace('"meshes/chamfered_ring.geo"', '"nowhere.geo"'))
    r = subprocess.run([sys.executable, "-m", "sealts", "run", str(cfg)], capture_output=True,
                       text=True, cwd=ROOT)
    assert r.returncode == 2 and "seal.mesh_file: no such file" in r.stderr
    assert len(r.stderr.strip().splitlines()) == 1
    cfg.write_text(text.replace('"meshes/chamfered_ring.geo"', f'"{GEO}"')
                   .replace("width = 2.6 ", "width = 1.9 ") + f'\n[mesh]\ncache = "{tmp_path}"\n')
    r = subprocess.run([sys.executable, "-m", "sealts", "run", str(cfg)], capture_output=True,
                       text=True, cwd=ROOT)
    assert r.returncode == 2 and "not narrower than groove.width = 1.9 mm" in r.stderr
    assert len(r.stderr.strip().splitlines()) == 1
