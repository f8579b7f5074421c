"""The distributed DMPlex of a seal mesh (sealts.mesh.partition): cells on exactly one rank,
and the residual and Jacobian assembled rank by rank are the serial ones."""
import os
import shutil
import subprocess
import sys

import numpy as np
import pytest

from conftest import ROOT, scene
from sealts.mesh.layout import Layout
from sealts.mesh.partition import Partition
from sealts.problem.seal_model import model_from_scene

MPIEXEC = shutil.which("mpiexec")


@pytest.fixture(scope="module")
def mesh(tmp_path_factory):
    s = scene("oring_mount", mesh={"h_contact": 0.1, "h_bulk": 0.3,
                                   "cache": str(tmp_path_factory.mktemp("mesh"))})
    return model_from_scene(s).mesh


def test_one_rank_numbering_is_the_serial_layout(mesh):
    """On one rank global = local = serial, and the dofs are Layout's (vertices first in
    node order, then cells)."""
    part = Partition(mesh)
    assert part.cells_per_rank == [mesh.conn.shape[0]]
    for k in (0, 3):
        num, lay = part.numbering(prony=k), Layout(mesh, prony=k)
        assert num.n == lay.n and num.identity
        assert np.array_equal(num.natural, np.arange(num.n))
        assert np.array_equal(num.ltog, np.arange(num.n))
        assert np.array_equal(num.udofs, lay.udofs)
        assert np.array_equal(num.udofs_local, lay.udofs)
        assert np.array_equal(num.prony_local, lay.prony_dofs)
        for f in lay.fields:
            assert np.array_equal(num.field_dofs(f), lay.field_dofs(f))
    assert part.dm.getLabelSize("rod_side") > 0


SCRIPT = r'''
import sys
import numpy as np
from petsc4py import PETSc
from sealts.contact.asperity import ExponentialLaw
from sealts.contact.rod_side import RodSide
from sealts.contact.rigid import GrooveContact, RodContact, tributary_lengths
from sealts.mesh.partition import Partition
from sealts.mesh.seal_mesh import SealMesh
from sealts.problem import Problem
from sealts.solid.pressure import PressureLoad
from sealts.solid.term import NeoHooke, SolidTerm

d = np.load(sys.argv[1])
mesh = SealMesh(d["X"], d["conn"], {k[2:]: d[k] for k in d.files if k.startswith("e_")})
X, conn = mesh.X, mesh.conn
comm = PETSc.COMM_WORLD
rank = comm.getRank()
mpi = comm.tompi4py()
part = Partition(mesh, comm, root_nodes=mesh.boundary_nodes())
cells = np.sort(np.concatenate(mpi.allgather(part.cells)))
assert np.array_equal(cells, np.arange(conn.shape[0])), "a cell is not on exactly one rank"
assert all(k > 0 for k in part.cells_per_rank), part.cells_per_rank
owned = np.sort(np.concatenate(mpi.allgather(part.owned_nodes)))
assert np.array_equal(owned, np.arange(X.shape[0])), "a vertex is not owned by one rank"
# the labels travelled with the distribution: every rank with rod-side cells has the label
n_rod = mpi.allreduce(part.dm.getStratumSize("rod_side", 1))
assert n_rod >= 2 * len(np.unique(mesh.edges["rod_side"])) - 1, n_rod

num = part.numbering()
mat = NeoHooke(1.064, 0.001)
chain = mesh.chain("rod_side")
trib = tributary_lengths(X, np.concatenate(list(mesh.edges.values())), X.shape[0])
walls = (X[:, 1].min() + 0.01, X[:, 1].max() - 0.01)
rg = X[:, 0].max() - 0.02
start = mesh.nodes("pressure_side")[0]

def boundary(udofs):
    load = PressureLoad(X, conn, lambda t: 0.7, True, start, udofs=udofs)
    load.s0[:] = 0.0
    load.s1[:] = np.linspace(0.0, 1.0, load.m)
    return [RodContact(RodSide(X, chain, lambda t: X[chain, 0].min() + 0.01, 2 * np.pi * 25.0,
                               udofs=udofs), ExponentialLaw(7e-4, 15.0)),
            GrooveContact(X, mesh.boundary_nodes(), trib, True, lambda t: rg,
                          lambda t: walls, udofs=udofs), load]

u = np.random.default_rng(3).uniform(-0.005, 0.005, num.n)
serial = Problem(num.n, [SolidTerm(X, conn, mat, True)] + boundary(num.udofs),
                 comm=PETSc.COMM_SELF)
f_serial = serial.residual(0.0, u, 0 * u)
K = serial.jacobian_dense(0.0, u, 0 * u, 0.0)

terms = [SolidTerm(X, conn[part.cells], mat, True, udofs=num.udofs_local)]
terms += num.on_root(boundary(num.udofs))
dist = Problem(num.n, terms, comm=comm, dofs=num)
f = dist.global_residual(0.0, u)
scale = np.abs(f_serial).max()
assert scale > 0
err = np.abs(f - f_serial).max() / scale
assert err < 1e-12, err
# the Jacobian assembled from each rank's COO entries (off-process rows included)
x = dist._owned(u)
dist._assemble_jacobian(0.0, x, None, 0.0, dist.J, dist.J)
v = np.random.default_rng(4).standard_normal(num.n)
y = dist.U.duplicate()
dist.J.mult(dist._owned(v), y)
Kv = dist.gather(y).copy()
err = np.abs(Kv - K @ v).max() / np.abs(K @ v).max()
assert err < 1e-12, err
if rank == 0:
    print("cells per rank", part.cells_per_rank, "OK")
'''


@pytest.mark.mpi
@pytest.mark.skipif(MPIEXEC is None, reason="mpiexec not found")
def test_two_ranks_hold_every_cell_once_and_assemble_the_serial_residual(mesh, tmp_path):
    data = tmp_path / "mesh.npz"
    np.savez(data, X=mesh.X, conn=mesh.conn, **{f"e_{k}": v for k, v in mesh.edges.items()})
    script = tmp_path / "check.py"
    script.write_text(SCRIPT)
    env = {**os.environ, "PYTHONPATH": str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", "")}
    r = subprocess.run([MPIEXEC, "-n", "2", sys.executable, str(script), str(data)],
                       capture_output=True, text=True, cwd=tmp_path, env=env, timeout=300)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "OK" in r.stdout
