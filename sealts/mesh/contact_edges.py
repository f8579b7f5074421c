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
few hundredths of a millimetre.
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


def points_along(X, chain, at, span, spacing):
    """Points (k, 2) on the reference polyline X[chain] at arc lengths within ``span`` of
    the chain nodes ``at`` (indices into ``chain``), ``spacing`` apart (mm)."""
    P = np.asarray(X, float)[np.asarray(chain)]
    s = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(P, axis=0).T))])
    out = []
    for i in at:
        lo, hi = max(s[i] - span, 0.0), min(s[i] + span, s[-1])
        q = np.linspace(lo, hi, max(int(np.ceil((hi - lo) / spacing)), 1) + 1)
        out.append(np.column_stack([np.interp(q, s, P[:, 0]), np.interp(q, s, P[:, 1])]))
    return np.concatenate(out) if out else np.zeros((0, 2))


def edge_refinement(model, t, u, h, span):
    """(points, h) for ``build_mesh(..., refine=...)`` around the contact's edges at (t, u),
    or None where the seal does not touch the rod; and the edges' reference positions
    (r, z) in mm."""
    at = edge_nodes(model, t, u)
    if not at:
        return None, []
    chain = model.side.chain
    points = points_along(model.mesh.X, chain, at, span, 0.5 * h)
    return (points, float(h)), [model.mesh.X[chain[i]].tolist() for i in at]
