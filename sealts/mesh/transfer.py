"""A nodal field carried from one quadrilateral mesh to another of the same body
(``mesh.h_edge``: the pressurised state of the scene's own mesh onto the mesh refined at the
contact's edges, :func:`sealts.steps.transfer.carried`).

Each new node X is located in the old mesh's reference configuration: in the old element
whose bilinear map x(xi, eta) = sum_a N_a(xi, eta) X_a reaches it with (xi, eta) in
[-1, 1]^2, and the field is interpolated with the same shape functions,

    u(X) = sum_a N_a(xi, eta) u_a,    N_a = (1 + xi_a xi)(1 + eta_a eta) / 4.

(xi, eta) solve x(xi, eta) = X by Newton's method from the centre (exact in a few
iterations for the mildly distorted elements of a mesh). A node outside every old element
(a curved boundary is a polygon through other nodes on each mesh: up to h^2 / (8 R) off it)
takes the linear extrapolation of the element nearest to it in (xi, eta), which reproduces
any bilinear field exactly, as interpolation does.

The boundary is placed otherwise (:func:`onto_boundary`): each new boundary node goes to the
point of the old mesh's deformed boundary polygon that corresponds to its nearest point on
the old reference polygon. Extrapolated, a node on an arc between two old nodes lands the
arc's sagitta, h^2 / (8 R), beyond the old deformed chord: 0.12 um for 0.05 mm elements on
the paper's O-ring, into a rod whose asperity law (h_mix 0.07 um for a smooth rod) reads
it as a great pressure.
"""
import numpy as np

_XI = np.array([-1.0, 1.0, 1.0, -1.0])
_ETA = np.array([-1.0, -1.0, 1.0, 1.0])


def _shape(xi, eta):
    """N (..., 4) and dN/dxi, dN/deta at (xi, eta)."""
    xi, eta = xi[..., None], eta[..., None]
    N = 0.25 * (1 + _XI * xi) * (1 + _ETA * eta)
    return N, 0.25 * _XI * (1 + _ETA * eta), 0.25 * _ETA * (1 + _XI * xi)


def local_coordinates(Xe, P, iterations=12):
    """(xi, eta) of the points P (k, 2) in the elements Xe (k, 4, 2), one element each."""
    xi, eta = np.zeros(len(P)), np.zeros(len(P))
    for _ in range(iterations):
        N, dxi, deta = _shape(xi, eta)
        r = np.einsum("ka,kad->kd", N, Xe) - P
        a, c = np.einsum("ka,kad->kd", dxi, Xe).T        # dx/dxi
        b, d = np.einsum("ka,kad->kd", deta, Xe).T       # dx/deta
        det = a * d - b * c
        xi -= (d * r[:, 0] - b * r[:, 1]) / det
        eta -= (-c * r[:, 0] + a * r[:, 1]) / det
    return xi, eta


def locate(X_old, conn_old, P, batch=4096):
    """For each point of P (k, 2): (its old element, xi, eta). A point outside all elements
    gets the element whose local coordinates lie least outside [-1, 1]^2."""
    X_old, P = np.asarray(X_old, float), np.asarray(P, float)
    Xe = X_old[conn_old]                                  # (e, 4, 2)
    lo, hi = Xe.min(axis=1), Xe.max(axis=1)
    pad = 0.05 * (hi - lo).max(axis=1)                    # room for boundary chords
    centre = Xe.mean(axis=1)
    elem = np.empty(len(P), np.int64)
    xi, eta = np.empty(len(P)), np.empty(len(P))
    for s in range(0, len(P), batch):
        Q = P[s:s + batch]
        near = ((Q[:, None, :] >= lo[None] - pad[None, :, None])
                & (Q[:, None, :] <= hi[None] + pad[None, :, None])).all(axis=2)
        # every point gets candidates: the boxes around it, else the nearest centres
        none = np.flatnonzero(~near.any(axis=1))
        if none.size:
            dist = np.hypot(*(Q[none, None, :] - centre[None]).transpose(2, 0, 1))
            near[none[:, None], np.argsort(dist, axis=1)[:, :4]] = True
        pi, ei = np.nonzero(near)
        x, e = local_coordinates(Xe[ei], Q[pi])
        outside = np.maximum(np.abs(x), np.abs(e))
        outside[~np.isfinite(outside)] = np.inf
        order = np.lexsort((outside, pi))                 # by point, best first
        first = order[np.flatnonzero(np.r_[True, np.diff(pi[order]) != 0])]
        part = slice(s, s + len(Q))
        elem[part], xi[part], eta[part] = ei[first], x[first], e[first]
    return elem, xi, eta


def interpolate(X_old, conn_old, values, X_new):
    """The nodal field ``values`` (n_old, ...) of the old mesh at the new mesh's nodes
    X_new (n_new, 2): bilinear interpolation in the old element holding each node."""
    elem, xi, eta = locate(X_old, conn_old, X_new)
    N, _, _ = _shape(xi, eta)
    v = np.asarray(values, float)[np.asarray(conn_old)[elem]]   # (n_new, 4, ...)
    return np.einsum("ka,ka...->k...", N, v)


def onto_boundary(X_old, edges_old, x_old, P):
    """Deformed positions (k, 2) for the reference points P (k, 2) on the boundary: each
    one's nearest point on the old reference boundary polygon (``edges_old``, (m, 2) node
    pairs; ``X_old`` reference, ``x_old`` deformed coordinates of the old nodes), at the
    same fraction of the same old edge deformed."""
    A, B = np.asarray(X_old, float)[edges_old[:, 0]], np.asarray(X_old, float)[edges_old[:, 1]]
    P = np.asarray(P, float)
    d = B - A
    tau = np.clip(np.einsum("kmd,md->km", P[:, None, :] - A[None], d)
                  / np.einsum("md,md->m", d, d)[None], 0.0, 1.0)             # (k, m)
    dist = np.hypot(*(A[None] + tau[..., None] * d[None] - P[:, None, :]).transpose(2, 0, 1))
    k = np.argmin(dist, axis=1)
    t = tau[np.arange(len(P)), k][:, None]
    xa, xb = np.asarray(x_old)[edges_old[k, 0]], np.asarray(x_old)[edges_old[k, 1]]
    return xa + t * (xb - xa)
