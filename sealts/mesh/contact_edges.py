"""Where the film's inlets lie: the pressurised contact's two edges on the rod side, and the
points around them that ``mesh.h_edge`` refines (``build_mesh(..., refine=...)``).

The film's transports, and with them the leakage, are set at the contact's inlets. Next to
the edge of a line contact of half-width a and peak pressure p0 on a body of plane-strain
modulus E* the dry gap opens as

    g(s) = (8/3) (p0 / E*) (2 / a)^(1/2) s^(3/2)     (s: distance from the edge),

the Hertz gap expanded at the edge. For the paper's O-ring at 1 MPa (p0 ~ 2.7 MPa,
E* = 3 G / (1 - 1/4) ~ 8.5 MPa, a ~ 1.2 mm) it reaches the film's 0.6 um about 7 um from
the edge: the inlet is a few micrometres long, shorter than the contact mesh's elements,
and where the mesher puts the nodes there moves the net leakage by up to a quarter
(README, "Where gmsh puts the nodes").

Steps 1-2 on the scene's own mesh find the edges: the first and last node of the rod side's
chain where the rod's contact pressure is positive (the asperities touch). The points lie on
the chain's reference polyline (the seal as meshed, so the material points that the
pressurised contact's edges are), ``h / 2`` apart over ``span`` to either side of each
edge: friction shears the seal during a stroke and moves the edges' material points by a
few hundredths of a millimetre. Near a groove side wall it refines nothing
(:func:`edge_refinement`). The state carried to the refined mesh can settle its edges
elsewhere (a coarse mesh places them only to within its elements); where an edge then lies
outside the spans, it is refined as well and the state carried again
(:func:`sealts.steps.procedure.refined_state`).
"""
import numpy as np


def edge_nodes(model, t, u):
    """Chain indices (into ``model.side.chain``) of the first and last rod-side node the
    rod presses at (t, u); () where none touches."""
    _, _, p = model.contact_profile(t, u)
    touching = np.flatnonzero(np.asarray(p) > 0.0)
    if touching.size == 0:
        return ()
    return int(touching[0]), int(touching[-1])


def points_along(X, chain, at, span, spacing, values=None):
    """Points (k, 2) on the reference polyline X[chain] at arc lengths within ``span`` of
    the chain nodes ``at`` (indices into ``chain``), ``spacing`` apart (mm); with
    ``values`` (one per chain node) also those interpolated to the points."""
    P = np.asarray(X, float)[np.asarray(chain)]
    s = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(P, axis=0).T))])
    q = [np.linspace(lo, hi, max(int(np.ceil((hi - lo) / spacing)), 1) + 1)
         for lo, hi in ((max(s[i] - span, 0.0), min(s[i] + span, s[-1])) for i in at)]
    q = np.concatenate(q) if q else np.zeros(0)
    points = np.column_stack([np.interp(q, s, P[:, 0]), np.interp(q, s, P[:, 1])])
    return points if values is None else (points, np.interp(q, s, values))


def edge_refinement(model, t, u, h, span, refined=()):
    """(points, h) for ``build_mesh(..., refine=...)`` around the contact's edges at (t, u)
    that are not refined yet, or None where there is none; the edges' reference positions
    (r, z) in mm; and those of them that got points. ``refined``: the reference positions
    of edges refined before (another pass's): an edge within ``span / 2`` of one is
    covered. Points whose pressurised axial position lies within ``span`` of a groove side
    wall's plane are left out: where the contact ends in the corner against a wall there
    is no inlet to resolve, and micrometre elements pressed into a wall are turned over by
    the wall penalty's compliance (about 0.1 um per MPa)."""
    at = edge_nodes(model, t, u)
    chain = model.side.chain
    edges = [model.mesh.X[chain[i]].tolist() for i in at]
    new = [(i, e) for i, e in zip(at, edges)
           if all(np.hypot(e[0] - c[0], e[1] - c[1]) > 0.5 * span for c in refined)]
    if not new:
        return None, edges, []
    points, z = points_along(model.mesh.X, chain, [i for i, _ in new], span, 0.5 * h,
                             values=model.side.y(u))
    za, zb = model.groove.z_walls(t)
    points = points[(z > za + span) & (z < zb - span)]
    return ((points, float(h)) if len(points) else None), edges, [e for _, e in new]
