"""Seal cross-section meshes from the gmsh Python API, cached under ``meshes/``.

Coordinates (r, z) in mm: r radial (the rod axis is r = 0), z axial. The pressurised side is
at small z, the atmosphere at large z, so the film coordinate y runs with z, and a rod moving
in +z is an outstroke.

Named boundaries (gmsh physical curves, kept as node and edge sets):

* ``rod_side``        faces the rod and carries the film;
* ``pressure_side``   faces the sealed fluid;
* ``atmosphere_side`` faces the atmosphere;
* ``groove``          faces the groove bottom.

For the O-ring the four quarter arcs are centred on the directions -r (rod_side), -z
(pressure_side), +r (groove) and +z (atmosphere_side). The rectangle's rod side is its
inner face with the two corners: rounded (``corner_radius``), the quarter circles; sharp,
the first FLANK of each side face beyond the corner, so the film and the asperity contact
cover the side face's nodes that a tilted or dragged ring lays on the rod. Elements are
four-node quads (recombined, subdivided so that none is left triangular), of size
``h_contact`` next to the rod side and growing to ``h_bulk`` over ``grading_distance``;
with ``layer_depth`` > 0 the size stays ``h_contact`` to that depth beneath the rod side
and grows over ``grading_distance`` beyond it. The film's transports are set at the
contact's inlet and outlet, a few hundredths of a millimetre long, and the solid beneath
them shapes the gap there: without the layer the size a few contact elements deep follows
h_bulk, and the net leakage scatters with h_contact instead of converging
(benchmarks/work_precision.md, the layer family).

Refinement at given points (``build_mesh(..., refine=(points, h))``, the scene key
``mesh.h_edge``: :mod:`sealts.mesh.contact_edges` puts the points along the rod side around
the pressurised contact's two edges): the element size is h at the points and grows away
from them by REFINE_GROWTH per unit distance, up to h_bulk; elsewhere the sizes above hold.

Mirror-symmetric meshes (``build_mesh(..., mirror=True)``, scene key ``mesh.symmetric``): the
unstructured mesher has no reason to place nodes symmetrically about the cross-section's
mid-plane z = z_m (the O-ring's z0, the rectangle's mid-height), and it does not: on the
coarse O-ring nodes sit up to 0.31 mm from the nearest mirror image of a node. A problem that
should be mirror-symmetric (p_in = p_out, an outstroke against an instroke) then differs from
its mirror image by discretisation error. With ``mirror=True`` gmsh meshes the half z <= z_m
(the same size field, algorithm and subdivision), the nodes on the mid-plane are put exactly
on it, and the other half is the mirror image z -> 2 z_m - z of the first, node for node
(:func:`mirror_map` finds the pairs). The half's pressure side becomes the atmosphere side;
rod side and groove are each one half and its image. The default (``mirror=False``) meshes
and their cache keys are unchanged.
"""
import hashlib
import json
import math
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

GROUPS = ("rod_side", "pressure_side", "groove", "atmosphere_side")
# mm of each side face beyond a sharp corner that belongs to the rod side (module docstring):
# the sharp-cornered ring of the stress matrix (benchmarks/stress.md) lays the side face's
# first node, 0.05 mm off the corner, on the rod; the rounded ring's arcs end 0.1 mm off it
FLANK = 0.1


def flank(r_inner, r_outer):
    """mm of each side face of a sharp-cornered rectangle in its rod side: FLANK, or a
    quarter of the ring's height if that is less."""
    return min(FLANK, 0.25 * (r_outer - r_inner))


@dataclass(frozen=True)
class SealMesh:
    X: np.ndarray              # (nodes, 2) reference coordinates (r, z), mm
    conn: np.ndarray           # (elements, 4) counter-clockwise
    edges: dict                # group -> (m, 2) boundary edges (node pairs)

    def nodes(self, group):
        """Sorted node numbers of a named boundary."""
        return np.unique(self.edges[group])

    def boundary_nodes(self):
        return np.unique(np.concatenate([e.ravel() for e in self.edges.values()]))

    def chain(self, group):
        """Nodes of an open boundary group in order along the curve, by increasing z."""
        e = self.edges[group]
        nxt = {}
        deg = {}
        for a, b in e:
            nxt.setdefault(a, []).append(b)
            nxt.setdefault(b, []).append(a)
            deg[a] = deg.get(a, 0) + 1
            deg[b] = deg.get(b, 0) + 1
        ends = [n for n, d in deg.items() if d == 1]
        start = min(ends, key=lambda n: self.X[n, 1])
        out, prev = [start], None
        while len(out) < len(deg):
            cur = out[-1]
            cand = [n for n in nxt[cur] if n != prev]
            prev = cur
            out.append(cand[0])
        return np.array(out)


# how fast the element size grows away from refinement points (mm per mm of distance),
# the setting measured on the paper's O-ring (README, "Where gmsh puts the nodes")
REFINE_GROWTH = 0.2


@dataclass(frozen=True)
class ORing:
    d1: float          # inner diameter, mm
    d2: float          # cord diameter, mm
    z0: float = 0.0    # axial position of the cord centre, mm


@dataclass(frozen=True)
class RectangularRing:
    r_inner: float
    r_outer: float
    z_min: float
    z_max: float
    corner_radius: float = 0.0    # of the two corners on the rod side (part of it), mm


def _key(shape, h_contact, h_bulk, grading_distance, mirror=False, layer_depth=0.0,
         refine=None):
    spec = dict(kind=type(shape).__name__, **asdict(shape), h_contact=h_contact,
                h_bulk=h_bulk, grading=grading_distance, version=1)
    if layer_depth:        # only then: meshes without a layer keep their keys
        spec["layer_depth"] = layer_depth
    if refine is not None:     # only then: the same
        points, h = refine
        digest = hashlib.sha1(np.round(np.asarray(points, float), 9).tobytes()).hexdigest()
        spec["refine"] = {"h": float(h), "points": len(points), "digest": digest[:16]}
    if spec["kind"] == "RectangularRing" and not spec["corner_radius"]:
        del spec["corner_radius"]
        spec["flank"] = flank(spec["r_inner"], spec["r_outer"])
    if mirror:             # only then: the default meshes keep their keys
        spec["mirror"] = True
    text = json.dumps(spec, sort_keys=True)
    return hashlib.sha1(text.encode()).hexdigest()[:12], spec


def build_mesh(shape, h_contact, h_bulk, grading_distance=0.5, cache_dir="meshes",
               mirror=False, layer_depth=0.0, refine=None):
    """Mesh ``shape`` (ORing or RectangularRing), reusing ``cache_dir/<key>.npz``; with
    ``mirror`` mirror-symmetric about the shape's mid-plane; ``layer_depth`` (mm): the depth
    beneath the rod side meshed at ``h_contact``; ``refine`` = (points (k, 2), h): element
    size h at those points (r, z), growing from them at REFINE_GROWTH (module docstring)."""
    if refine is not None and mirror:
        raise ValueError("a refinement at given points is not mirror-symmetric")
    key, spec = _key(shape, h_contact, h_bulk, grading_distance, mirror, layer_depth, refine)
    path = Path(cache_dir) / f"{spec['kind'].lower()}-{key}.npz"
    if path.is_file():
        return load_npz(path)
    if mirror:
        mesh = _mirrored_mesh(shape, h_contact, h_bulk, grading_distance, layer_depth)
    else:
        mesh = _gmsh_mesh(shape, h_contact, h_bulk, grading_distance, layer_depth,
                          refine=refine)
    path.parent.mkdir(parents=True, exist_ok=True)
    np.savez_compressed(path, X=mesh.X, conn=mesh.conn, spec=json.dumps(spec),
                        **{f"edges_{g}": e for g, e in mesh.edges.items()})
    return mesh


def load_npz(path):
    d = np.load(path)
    edges = {k[6:]: d[k] for k in d.files if k.startswith("edges_")}
    return SealMesh(d["X"], d["conn"], edges)


def mid_plane(shape):
    """The axial position z_m of the shape's mirror plane (mm)."""
    if isinstance(shape, ORing):
        return shape.z0
    return 0.5 * (shape.z_min + shape.z_max)


def mirror_map(X, z_m, tol=1e-12):
    """The node j(i) at the mirror image (r_i, 2 z_m - z_i) of each node i, for a mesh that
    is mirror-symmetric about z = z_m to ``tol`` times its size (mm); ValueError naming the
    worst node otherwise."""
    X = np.asarray(X, float)
    image = X * [1.0, -1.0] + [0.0, 2.0 * z_m]
    atol = tol * max(float(np.abs(X).max()), 1.0)
    order = np.argsort(X[:, 0], kind="stable")
    r = X[order, 0]
    lo = np.searchsorted(r, image[:, 0] - atol, "left")
    hi = np.searchsorted(r, image[:, 0] + atol, "right")
    j = np.zeros(X.shape[0], np.int64)
    err = np.full(X.shape[0], np.inf)
    for i in range(X.shape[0]):                 # candidates: the nodes at the image's r
        cand = order[lo[i]:hi[i]]
        if cand.size:
            d = np.abs(X[cand] - image[i]).max(1)
            k = int(d.argmin())
            j[i], err[i] = cand[k], d[k]
    if err.max() > atol or np.any(j[j] != np.arange(j.size)):
        i = int(err.argmax())
        raise ValueError(f"not mirror-symmetric about z = {z_m:g}: node {i} at "
                         f"({X[i, 0]:.6g}, {X[i, 1]:.6g}) has no image within {atol:.1e} mm")
    return j


def _mirrored_mesh(shape, h_contact, h_bulk, grading_distance, layer_depth=0.0):
    """gmsh's mesh of the half z <= z_m, and its mirror image (module docstring)."""
    z_m = mid_plane(shape)
    X, conn, edges, mid = _gmsh_mesh(shape, h_contact, h_bulk, grading_distance,
                                   layer_depth, half=True)
    n = X.shape[0]
    if np.abs(X[mid, 1] - z_m).max() > 1e-9 * max(1.0, np.abs(X).max()):
        raise RuntimeError("gmsh put nodes of the mid-plane off it")
    X[mid, 1] = z_m                          # exactly on the plane: their images are them
    image = np.arange(n, 2 * n)
    image[mid] = mid
    Xm = X * [1.0, -1.0] + [0.0, 2.0 * z_m]
    X2 = np.concatenate([X, Xm])
    conn2 = np.concatenate([conn, image[conn]])   # reversed orientation: _tidy turns it
    edges2 = {"rod_side": np.concatenate([edges["rod_side"], image[edges["rod_side"]]]),
              "pressure_side": edges["pressure_side"],
              "groove": np.concatenate([edges["groove"], image[edges["groove"]]]),
              "atmosphere_side": image[edges["pressure_side"]][:, ::-1]}
    return _tidy(X2, conn2, edges2)


def _rectangle(occ, s, half):
    """The rectangle's boundary curves counter-clockwise from the rod side, and the curves
    of each group (rod side, pressure side, groove, atmosphere side or the mid-plane). With
    a corner radius rc the two corners on the rod side are quarter circles, part of the
    rod side: a tilted ring then meets the rod with its rounded corner, which the film and
    the asperity contact cover; with sharp corners the rod side runs on up the side faces
    by FLANK (a quarter of the height at most), where a dragged corner lays them on the
    rod."""
    rc, ri, ro = s.corner_radius, s.r_inner, s.r_outer
    z_top = mid_plane(s) if half else s.z_max
    if rc == 0.0:
        f = flank(ri, ro)
        rod_top, rod_low = occ.addPoint(ri, z_top, 0), occ.addPoint(ri, s.z_min, 0)
        low_end = occ.addPoint(ri + f, s.z_min, 0)
        out_low, out_top = occ.addPoint(ro, s.z_min, 0), occ.addPoint(ro, z_top, 0)
        rod = [occ.addLine(rod_top, rod_low), occ.addLine(rod_low, low_end)]
        sides = [occ.addLine(low_end, out_low), occ.addLine(out_low, out_top)]
        if half:
            sides.append(occ.addLine(out_top, rod_top))
            return rod + sides, [rod] + [[c] for c in sides]
        top_end = occ.addPoint(ri + f, z_top, 0)
        sides.append(occ.addLine(out_top, top_end))
        top = occ.addLine(top_end, rod_top)
        return rod + sides + [top], [[top] + rod] + [[c] for c in sides]
    rod_top = occ.addPoint(ri, z_top - (0.0 if half else rc), 0)
    rod_low = occ.addPoint(ri, s.z_min + rc, 0)
    low_end = occ.addPoint(ri + rc, s.z_min, 0)
    out_low, out_top = occ.addPoint(ro, s.z_min, 0), occ.addPoint(ro, z_top, 0)
    rod = [occ.addLine(rod_top, rod_low),
           occ.addCircleArc(rod_low, occ.addPoint(ri + rc, s.z_min + rc, 0), low_end)]
    sides = [occ.addLine(low_end, out_low), occ.addLine(out_low, out_top)]
    if half:                      # the mid-plane closes the loop; it has no corner
        sides.append(occ.addLine(out_top, rod_top))
        return rod + sides, [rod] + [[c] for c in sides]
    top_end = occ.addPoint(ri + rc, z_top, 0)
    sides.append(occ.addLine(out_top, top_end))
    corner = occ.addCircleArc(top_end, occ.addPoint(ri + rc, z_top - rc, 0), rod_top)
    return rod + sides + [corner], [[corner] + rod] + [[c] for c in sides]


def _gmsh_mesh(shape, h_contact, h_bulk, grading_distance, layer_depth=0.0, half=False,
               refine=None):
    """The gmsh mesh of the whole cross-section; with ``half`` of its half z <= z_m only,
    returned untidied with the nodes on the mid-plane: (X, conn, edges, mid); ``refine``:
    (points, h) as :func:`build_mesh`'s."""
    import gmsh
    gmsh.initialize(interruptible=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("seal")
        occ = gmsh.model.occ
        if isinstance(shape, ORing):
            rc, R = 0.5 * (shape.d1 + shape.d2), 0.5 * shape.d2
            c = occ.addPoint(rc, shape.z0, 0)
            if half:
                # rod side's lower half, pressure side, groove's lower half, the mid-plane
                angles = [1.25 * math.pi, 1.75 * math.pi]
                pts = [occ.addPoint(rc - R, shape.z0, 0)] + [
                    occ.addPoint(rc + R * math.cos(a), shape.z0 + R * math.sin(a), 0)
                    for a in angles] + [occ.addPoint(rc + R, shape.z0, 0)]
                curves = [occ.addCircleArc(pts[i], c, pts[i + 1]) for i in range(3)]
                curves.append(occ.addLine(pts[3], pts[0]))
            else:
                angles = [0.75 * math.pi, 1.25 * math.pi, 1.75 * math.pi, 0.25 * math.pi]
                pts = [occ.addPoint(rc + R * math.cos(a), shape.z0 + R * math.sin(a), 0)
                       for a in angles]
                curves = [occ.addCircleArc(pts[i], c, pts[(i + 1) % 4]) for i in range(4)]
            groups = [[c] for c in curves]
        else:
            curves, groups = _rectangle(occ, shape, half)
        loop = occ.addCurveLoop(curves)
        surf = occ.addPlaneSurface([loop])
        occ.synchronize()
        # curves in order: rod side, pressure side, groove, atmosphere side (the half: the
        # mid-plane, no group)
        for name, cvs in zip(GROUPS[:3] if half else GROUPS, groups):
            gmsh.model.addPhysicalGroup(1, cvs, name=name)
        gmsh.model.addPhysicalGroup(2, [surf], name="seal")
        f = gmsh.model.mesh.field
        dist = f.add("Distance")
        f.setNumbers(dist, "CurvesList", groups[0])
        f.setNumber(dist, "Sampling", 400)
        thr = f.add("Threshold")
        f.setNumber(thr, "InField", dist)
        # subdivision halves every size: ask for twice the target
        f.setNumber(thr, "SizeMin", 2 * h_contact)
        f.setNumber(thr, "SizeMax", 2 * h_bulk)
        f.setNumber(thr, "DistMin", layer_depth)
        f.setNumber(thr, "DistMax", layer_depth + grading_distance)
        if refine is None:
            f.setAsBackgroundMesh(thr)
        else:
            points, h = refine
            tags = [occ.addPoint(float(r), float(z), 0) for r, z in points]
            occ.synchronize()        # free points: distances only, not in the mesh
            near = f.add("Distance")
            f.setNumbers(near, "PointsList", tags)
            fine = f.add("Threshold")
            f.setNumber(fine, "InField", near)
            f.setNumber(fine, "SizeMin", 2 * h)
            f.setNumber(fine, "SizeMax", 2 * h_bulk)
            f.setNumber(fine, "DistMin", 0.0)
            f.setNumber(fine, "DistMax", (h_bulk - h) / REFINE_GROWTH)
            both = f.add("Min")
            f.setNumbers(both, "FieldsList", [thr, fine])
            f.setAsBackgroundMesh(both)
        gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
        gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
        gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
        gmsh.option.setNumber("Mesh.Algorithm", 8)
        gmsh.option.setNumber("Mesh.RecombineAll", 1)
        gmsh.option.setNumber("Mesh.SubdivisionAlgorithm", 1)
        gmsh.model.mesh.generate(2)
        tags, coords, _ = gmsh.model.mesh.getNodes()
        index = {int(t): i for i, t in enumerate(tags)}
        X = coords.reshape(-1, 3)[:, :2].copy()
        etypes, _, enodes = gmsh.model.mesh.getElements(2)
        quads = [n for t, n in zip(etypes, enodes) if t == 3]
        if len(etypes) != 1 or not quads:
            raise RuntimeError("gmsh left non-quadrilateral elements")
        conn = np.vectorize(index.get)(quads[0].reshape(-1, 4).astype(np.int64))
        edges = {}
        for name, cvs in zip(GROUPS[:3] if half else GROUPS, groups):
            en = np.concatenate([gmsh.model.mesh.getElements(1, cv)[2][0] for cv in cvs])
            edges[name] = np.vectorize(index.get)(en.reshape(-1, 2).astype(np.int64))
        if half:
            mid_tags, _, _ = gmsh.model.mesh.getNodes(1, groups[3][0], includeBoundary=True)
            mid = np.unique([index[int(t)] for t in mid_tags])
    finally:
        gmsh.finalize()
    if half:
        return X, conn, edges, mid
    return _tidy(X, conn, edges)


def _tidy(X, conn, edges):
    """Drop unused nodes (the arc centre), renumber, orient elements counter-clockwise."""
    used = np.unique(conn)
    new = -np.ones(X.shape[0], np.int64)
    new[used] = np.arange(used.size)
    X, conn = X[used], new[conn]
    edges = {g: new[e] for g, e in edges.items()}
    x, y = X[conn, 0], X[conn, 1]
    area = 0.5 * (x * np.roll(y, -1, 1) - np.roll(x, -1, 1) * y).sum(1)
    conn[area < 0] = conn[area < 0][:, ::-1]
    return SealMesh(X, conn, edges)
