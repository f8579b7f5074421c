"""User-supplied seal meshes: a gmsh ``.msh`` file, or a ``.geo`` script meshed by gmsh.

Coordinates are (r, z) in mm (gmsh x = r, y = z), the cross-section in the plane z_gmsh = 0.
The mesh must be four-node quadrilaterals only (in a ``.geo``: ``Mesh.RecombineAll = 1;`` and
``Mesh.SubdivisionAlgorithm = 1;`` or a transfinite recombined surface), and its boundary
must be split into the physical curves

* ``rod_side``        faces the rod and carries the film (one open chain);
* ``pressure_side``   faces the sealed fluid (the pressure reaches the seal there first);
* ``groove``          faces the groove bottom;
* ``atmosphere_side`` faces the atmosphere,

which together cover every boundary edge once. The read mesh is cached under the cache
directory, keyed by the file's bytes, like the built-in shapes.
"""
import hashlib
from pathlib import Path

import numpy as np

from .seal_mesh import GROUPS, SealMesh, _tidy, load_npz


class MeshFileError(ValueError):
    """A mesh file that cannot serve as a seal mesh (one-line message naming the file)."""


def read_mesh_file(path, cache_dir="meshes"):
    """SealMesh from ``path`` (.msh or .geo), reusing ``cache_dir/file-<hash>.npz``."""
    path = Path(path)
    if not path.is_file():
        raise MeshFileError(f"mesh file not found: {path}")
    if path.suffix not in (".msh", ".geo"):
        raise MeshFileError(f"{path}: a seal mesh file must be .msh or .geo")
    key = hashlib.sha1(path.read_bytes() + b"version=1").hexdigest()[:12]
    cached = Path(cache_dir) / f"file-{key}.npz"
    if cached.is_file():
        return load_npz(cached)
    mesh = _check(path, _gmsh_read(path))
    cached.parent.mkdir(parents=True, exist_ok=True)
    np.savez_compressed(cached, X=mesh.X, conn=mesh.conn, source=str(path),
                        **{f"edges_{g}": e for g, e in mesh.edges.items()})
    return mesh


def _gmsh_read(path):
    import gmsh
    gmsh.initialize(interruptible=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        try:
            gmsh.open(str(path))
            if path.suffix == ".geo":
                gmsh.model.mesh.generate(2)
        except Exception as e:
            raise MeshFileError(f"{path}: gmsh cannot read it ({e})") from None
        tags, coords, _ = gmsh.model.mesh.getNodes()
        index = {int(t): i for i, t in enumerate(tags)}
        X = coords.reshape(-1, 3)[:, :2].copy()
        if X.size and np.abs(coords.reshape(-1, 3)[:, 2]).max() > 1e-12:
            raise MeshFileError(f"{path}: the cross-section must lie in the plane z = 0")
        etypes, _, enodes = gmsh.model.mesh.getElements(2)
        if not etypes:
            raise MeshFileError(f"{path}: no surface elements")
        others = [gmsh.model.mesh.getElementProperties(t)[0] for t in etypes if t != 3]
        if others:
            raise MeshFileError(f"{path}: only 4-node quadrilaterals are supported, found "
                                f"{', '.join(others)} (recombine the mesh)")
        conn = np.vectorize(index.get)(enodes[0].reshape(-1, 4).astype(np.int64))
        names = {gmsh.model.getPhysicalName(1, tag): tag
                 for _, tag in gmsh.model.getPhysicalGroups(1)}
        missing = [g for g in GROUPS if g not in names]
        if missing:
            raise MeshFileError(f"{path}: no physical curve named {missing[0]!r} (needs "
                                f"{', '.join(GROUPS)})")
        edges = {}
        for g in GROUPS:
            parts = []
            for ent in gmsh.model.getEntitiesForPhysicalGroup(1, names[g]):
                types, _, en = gmsh.model.mesh.getElements(1, ent)
                for t, nodes in zip(types, en):
                    if t != 1:
                        raise MeshFileError(f"{path}: physical curve {g!r} has non-linear "
                                            "edges (use first-order elements)")
                    parts.append(nodes.reshape(-1, 2).astype(np.int64))
            edges[g] = np.vectorize(index.get)(np.concatenate(parts))
    finally:
        gmsh.finalize()
    return _tidy(X, conn, edges)


def _check(path, mesh):
    """Every boundary edge in exactly one group; rod_side one open chain."""
    from ..solid.pressure import boundary_loop
    c = mesh.conn
    e = np.sort(np.concatenate([c[:, [0, 1]], c[:, [1, 2]], c[:, [2, 3]], c[:, [3, 0]]]), 1)
    keys, counts = np.unique(e, axis=0, return_counts=True)
    boundary = {tuple(k) for k in keys[counts == 1].tolist()}
    try:
        loop = boundary_loop(c)
    except KeyError:
        loop = None
    if loop is None or len({tuple(sorted(x)) for x in loop.tolist()}) != len(boundary):
        raise MeshFileError(f"{path}: the mesh boundary is not one closed loop (holes or "
                            "separate pieces)")
    seen = {}
    for g, e in mesh.edges.items():
        for a, b in np.sort(e, axis=1).tolist():
            if (a, b) not in boundary:
                raise MeshFileError(f"{path}: physical curve {g!r} has edges inside the mesh")
            if (a, b) in seen:
                raise MeshFileError(f"{path}: an edge is in both {seen[(a, b)]!r} and {g!r}")
            seen[(a, b)] = g
    if len(seen) != len(boundary):
        raise MeshFileError(f"{path}: {len(boundary) - len(seen)} boundary edges are in no "
                            f"physical curve ({', '.join(GROUPS)})")
    try:
        mesh.chain("rod_side")
    except (KeyError, IndexError, ValueError):
        raise MeshFileError(f"{path}: rod_side must be one open chain of edges") from None
    return mesh
