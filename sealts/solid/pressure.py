"""Fluid pressure on the seal's free surface, with pressure penetration.

Follower load (paper step 2): the pressure p(t) acts on the *current* boundary edges that the
fluid wets. For a boundary edge a -> b, traversed counter-clockwise in (r, z) so that its
outward normal times length is (dz, -dr), the consistent nodal forces are

    axisymmetric:  F_a = -p 2 pi (2 r_a + r_b)/6 (dz, -dr),  F_b = -p 2 pi (r_a + 2 r_b)/6 (dz, -dr)
    plane strain:  F_a = F_b = -p (depth/2) (dz, -dr)

(2 pi int N r dl over a straight edge), with their exact Jacobian (the load stiffness).

Pressure penetration: the wetted set starts where the fluid comes in (the pressure side's
node nearest the rod, ``SealModel.pressure_load``) and follows the boundary loop in both
directions up to the first node where the seal seals: where its normal traction on the wall, sigma_n, exceeds the fluid pressure p
by more than p_crit. The wall's contact pressure p_c (groove penalty or rod asperity law) is
only the solid share of sigma_n: on a node whose load is wetted by the share phi (1 wet, 0
dry, a fraction next to the front) the fluid already presses with phi p, so

    sigma_n = p_c + phi p,     g = sigma_n - p - p_crit,     the seal seals where g > 0.

A dry node thus seals where p_c > p + p_crit, a wetted one only while p_c > p_crit. (Comparing
p_c alone with p let the front creep: the node just past it took over part of the front
edge's load as a fluid load, its p_c fell although sigma_n stayed, and the front moved on by
a fraction of an edge at every update; from about 4.4 MPa on the paper's O-ring it never
stopped.) p_crit (scene key ``fluid.p_crit``, default 0.1 MPa, ABAQUS's "critical contact
pressure") keeps a wetted node that still touches the wall from flipping with the penalty's
residual pressure at zero gap. The front lies inside the last edge, where the linear
interpolant of g between its two nodes crosses zero, so only that fraction theta of the edge
is loaded:

    F_a = -p 2 pi int_s0^s1 (1 - s) r(s) ds (dz, -dr),   F_b = -p 2 pi int_s0^s1 s r(s) ds (dz, -dr)

with [s0, s1] = [0, theta] (or [1 - theta, 1] walking the other way). The front thus moves
continuously: as p_c at the blocking node falls to p, theta reaches 1, and the next edge
starts from theta = 0. (Wetting whole edges made the load jump at every node the front
passed, and TS cut its step to one node per step: dt ~ 5e-5 on the paper's 0.01 mm mesh.)
The front is updated between time steps only (``update`` from the last accepted state,
called by the TS monitor), so each Newton solve sees a fixed, smooth load. While the pressure
rises the front may only advance (``recede=False``); the drivers then settle it at the final
pressure (front update and static solve in turn, until it stops moving).
"""
import copy

import numpy as np

from ..mesh.layout import vertex_dofs
from ..core import PhysicalStop, Term


def boundary_loop(conn):
    """Boundary edges (a, b) oriented counter-clockwise (as in their element), in loop order."""
    e = np.concatenate([conn[:, [0, 1]], conn[:, [1, 2]], conn[:, [2, 3]], conn[:, [3, 0]]])
    key = np.sort(e, axis=1)
    _, idx, counts = np.unique(key, axis=0, return_index=True, return_counts=True)
    edges = e[idx[counts == 1]]
    nxt = dict(zip(edges[:, 0], range(len(edges))))
    order = [0]
    while len(order) < len(edges):
        order.append(nxt[edges[order[-1], 1]])
    return edges[order]


class PressureLoad(Term):
    def __init__(self, X, conn, pressure, axisym, start_node, depth=1.0, udofs=None,
                 p_crit=0.1):
        """``pressure(t)`` in MPa; ``start_node`` the node where the fluid arrives;
        ``p_crit`` (MPa) the traction beyond p at which a node seals."""
        self.X, self.pressure, self.axisym, self.depth = X, pressure, axisym, depth
        self.p_crit = p_crit
        self.edges = boundary_loop(conn)
        self.m = len(self.edges)
        self.start = int(np.nonzero(self.edges[:, 0] == start_node)[0][0])
        self.s0 = np.zeros(self.m)       # wetted part [s0, s1] of each edge, s from a to b
        self.s1 = np.ones(self.m)
        self.reach = None                # the two fronts' positions (edges from the start)
        self.held = (False, False)       # fronts another term owns (the film's, in a stroke)
        self.dry = None                  # edges another term carries the fluid on (a mask)
        self._number(vertex_dofs(X.shape[0]) if udofs is None else udofs)

    def _number(self, udofs):
        """The edges' dofs and COO pattern in the numbering ``udofs``."""
        a, b = self.edges[:, 0], self.edges[:, 1]
        self.udofs = udofs
        da, db = self.udofs[a], self.udofs[b]
        self.dofs = np.concatenate([da, db], 1)            # (m, 4): ra, za, rb, zb
        self.rows = np.repeat(self.dofs, 4, axis=1).ravel()
        self.cols = np.tile(self.dofs, (1, 4)).ravel()

    def mark_exit(self, edges):
        """The boundary edges (node pairs) beyond the seal, on its atmosphere side: the fluid
        reaching one of them has passed the seal (:meth:`check_blow_by`)."""
        keys = {tuple(sorted(e)) for e in np.asarray(edges).reshape(-1, 2).tolist()}
        self.exit = np.array([tuple(sorted(e)) in keys for e in self.edges.tolist()], bool)

    def check_blow_by(self, t):
        """PhysicalStop ("blow-by") if the wetted set reaches the atmosphere side."""
        exit_ = getattr(self, "exit", None)
        if exit_ is None or not exit_.any():
            return
        wet = self.wet[exit_]
        if wet.max() > 0.0:
            k = int(np.nonzero(exit_)[0][np.argmax(wet)])
            raise PhysicalStop("blow-by",
                               "blow-by: the pressure-penetration front reached the atmosphere "
                               f"side (edge of nodes {self.edges[k, 0]}-{self.edges[k, 1]}) at "
                               f"p = {self.pressure(t):.4g} MPa, t = {t:.6g}: the seal no "
                               "longer seals")

    @property
    def wet(self):
        """Wetted fraction of each boundary edge (0 dry, 1 wet)."""
        return self.s1 - self.s0

    def _reach(self, g, step):
        """How far the fluid gets from the start, one way round: the number of whole wet
        edges plus the wet fraction of the edge where p_c - p = g crosses zero."""
        k = self.start if step == 1 else (self.start - 1) % self.m
        for n in range(self.m):
            a, b = self.edges[k]
            near, far = (a, b) if step == 1 else (b, a)
            if g[far] > 0.0:
                return n + (-g[near] / (g[far] - g[near]) if g[near] < 0.0 else 0.0)
            k = (k + step) % self.m
        return float(self.m)

    def wet_share(self):
        """phi per node: the wetted share of the fluid load the node would carry if all its
        boundary edges were wet (int N ds over the wet part / over the edge), 0 off the loop."""
        s0, s1 = self.s0, self.s1
        a, b = self.edges[:, 0], self.edges[:, 1]
        n = self.X.shape[0]
        wet = (np.bincount(a, (s1 - s0) - 0.5 * (s1**2 - s0**2), minlength=n)
               + np.bincount(b, 0.5 * (s1**2 - s0**2), minlength=n))
        full = np.bincount(a, np.full(self.m, 0.5), minlength=n) + np.bincount(
            b, np.full(self.m, 0.5), minlength=n)
        return np.divide(wet, full, out=np.zeros(n), where=full > 0)

    @property
    def pressures(self):
        """The fluids' pressures, functions of t (MPa): one here."""
        return [self.pressure]

    def fluid_share(self, t):
        """The fluid's pressure on each node's wetted share, phi p(t) (MPa), 0 off the loop."""
        return self.wet_share() * self.pressure(t)

    def target_reach(self, contact_pressure_at_nodes, t):
        """How far the fluid gets each way (edges from the start) for the nodal wall contact
        pressures p_c at the fluid pressure p(t): where g = p_c + phi p - p - p_crit crosses
        zero (see the module docstring), phi from the present wetting."""
        p = self.pressure(t)
        g = contact_pressure_at_nodes + (self.wet_share() - 1.0) * p - self.p_crit
        return [now if held else self._reach(g, step)
                for now, held, step in zip(self.reach or (None, None), self.held, (1, -1))]

    @property
    def entries(self):
        """The fluid's entry node (a list of one)."""
        return [int(self.edges[self.start, 0])]

    def recount(self, reach, entries):
        """``reach`` counted from the entry nodes ``entries`` (a saved state's), counted
        from this load's entries: the same wetted edges."""
        (node,) = entries
        old = int(np.nonzero(self.edges[:, 0] == node)[0][0])
        shift = (self.start - old + self.m // 2) % self.m - self.m // 2   # signed, edges
        ahead, back = (float(r) for r in reach)
        return [ahead - shift, back + shift]

    def rebuilt(self, pressures=None, udofs=None, dry=None):
        """The same wetting, for another step: ``pressures`` (a list of one function of t)
        in place of the pressure, ``udofs`` another numbering, the edges of the mask ``dry``
        unwetted (the rod side where the film carries the fluid): a front that starts along
        them is the film's, and stays where it is (``held``)."""
        new = copy.copy(self)
        if pressures is not None:
            (new.pressure,) = pressures
        if udofs is not None:
            new._number(udofs)
        new.reach = None if self.reach is None else list(self.reach)
        new.s0, new.s1 = self.s0.copy(), self.s1.copy()
        if dry is not None:
            new.dry = np.asarray(dry, bool).copy()
            new.s0[dry] = new.s1[dry] = 0.0
            new.held = (bool(dry[self.start]), bool(dry[(self.start - 1) % self.m]))
        return new

    def update(self, contact_pressure_at_nodes, t, max_advance=None, recede=True):
        """Move the fronts to ``target_reach`` at time t; return how far they moved (edges).

        ``max_advance`` (edges): how far each front may advance in one update. A region
        whose contact pressure falls below p all at once would otherwise flood in one step,
        a load jump that no step size can soften (met in the viscoelastic hold).
        ``recede=False``: the fronts may only advance (while the pressure rises)."""
        reach = self.target_reach(contact_pressure_at_nodes, t)
        old = self.reach
        if old is not None:
            if max_advance is not None:
                reach = [min(r, o + max_advance) for r, o in zip(reach, old)]
            if not recede:
                reach = [max(r, o) for r, o in zip(reach, old)]
        self.set_reach(reach)
        return 0.0 if old is None else float(sum(abs(r - o) for r, o in zip(reach, old)))

    def set_reach(self, reach):
        """Wet the loop from the start node: reach[0] edges one way, reach[1] the other."""
        self.reach = list(reach)
        s0, s1 = np.zeros(self.m), np.zeros(self.m)
        for r, step in zip(reach, (1, -1)):
            n = int(min(r, self.m))
            first = self.start if step == 1 else (self.start - 1) % self.m
            k = (first + step * np.arange(n)) % self.m
            s0[k], s1[k] = 0.0, 1.0
            frac = r - n
            if n < self.m and frac > 0.0:
                k = (first + step * n) % self.m
                if s1[k] - s0[k] < 1.0:       # not already wet from the other side
                    if step == 1:
                        s0[k], s1[k] = 0.0, frac
                    else:
                        s0[k], s1[k] = 1.0 - frac, 1.0
        if self.dry is not None:
            s0[self.dry] = s1[self.dry] = 0.0
        self.s0, self.s1 = s0, s1

    def _walk(self, step):
        """The loop's edges from the start one way (step 1 or -1), each as (near, far)."""
        k = (self.start + (0 if step == 1 else -1) + step * np.arange(self.m)) % self.m
        a, b = self.edges[k, 0], self.edges[k, 1]
        return (a, b) if step == 1 else (b, a)

    def front_points(self):
        """The fronts' reference positions (r, z), one per ``reach``: where the wetted
        part of the loop ends each way."""
        out = []
        for r, step in zip(self.reach, (1, -1)):
            near, far = self._walk(step)
            n = int(min(r, self.m - 1))
            frac = min(r - n, 1.0)
            out.append(self.X[near[n]] + frac * (self.X[far[n]] - self.X[near[n]]))
        return np.array(out)

    def reach_at(self, points):
        """The reach whose fronts lie at the reference positions ``points`` (one per
        way, (r, z)), nearest on this loop: another mesh's fronts (:meth:`front_points`)
        carried to this one."""
        reach = []
        for P, step in zip(np.asarray(points, float), (1, -1)):
            near, far = self._walk(step)
            A, B = self.X[near], self.X[far]
            d = B - A
            tau = np.clip(np.einsum("kd,kd->k", P - A, d) / np.einsum("kd,kd->k", d, d),
                          0.0, 1.0)
            k = int(np.argmin(np.hypot(*(A + tau[:, None] * d - P).T)))
            reach.append(k + float(tau[k]))
        return reach

    def _weights(self, xa, xb):
        """2 pi int N_a r ds, 2 pi int N_b r ds over [s0, s1] (axisymmetric) or depth int N ds,
        and their derivatives by (r_a, r_b)."""
        s0, s1 = self.s0, self.s1

        def prim(s):  # antiderivatives of (1-s)(r_a + s d) and s (r_a + s d), split by r_a, d
            return (s - s * s / 2, s * s / 2 - s**3 / 3, s * s / 2, s**3 / 3)

        A0, Ad, B0, Bd = (hi - lo for hi, lo in zip(prim(s1), prim(s0)))
        if self.axisym:
            c = 2 * np.pi
            ra, rb = xa[:, 0], xb[:, 0]
            wa = c * (A0 * ra + Ad * (rb - ra))
            wb = c * (B0 * ra + Bd * (rb - ra))
            dwa = c * np.stack([A0 - Ad, Ad], 1)   # by (r_a, r_b)
            dwb = c * np.stack([B0 - Bd, Bd], 1)
        else:
            wa, wb = self.depth * A0, self.depth * B0
            dwa = dwb = np.zeros((self.m, 2))
        return wa, wb, dwa, dwb

    def _geometry(self, u):
        x = self.X + u[self.udofs]
        a, b = self.edges[:, 0], self.edges[:, 1]
        return x[a], x[b]

    def forces(self, t, u):
        """(m, 4) nodal forces (F_ra, F_za, F_rb, F_zb) of the wetted edges."""
        p = self.pressure(t)
        xa, xb = self._geometry(u)
        dr, dz = xb[:, 0] - xa[:, 0], xb[:, 1] - xa[:, 1]
        wa, wb, _, _ = self._weights(xa, xb)
        F = -p * np.stack([wa * dz, -wa * dr, wb * dz, -wb * dr], 1)
        return F

    def add_residual(self, t, u, udot, f):
        # the residual is internal minus external force
        np.subtract.at(f, self.dofs.ravel(), self.forces(t, u).ravel())

    def jacobian_values(self, t, u, udot, shift):
        p = self.pressure(t)
        xa, xb = self._geometry(u)
        dr, dz = xb[:, 0] - xa[:, 0], xb[:, 1] - xa[:, 1]
        K = np.zeros((self.m, 4, 4))  # d(-F)/d(ra, za, rb, zb)
        wa, wb, dwa2, dwb2 = self._weights(xa, xb)
        dwa = np.zeros((self.m, 4))
        dwb = np.zeros((self.m, 4))
        dwa[:, [0, 2]], dwb[:, [0, 2]] = dwa2, dwb2
        ddz = np.array([0, -1.0, 0, 1.0])
        ddr = np.array([-1.0, 0, 1.0, 0])
        # -F_ra = p wa dz, -F_za = -p wa dr, -F_rb = p wb dz, -F_zb = -p wb dr
        K[:, 0] = p * (dz[:, None] * dwa + wa[:, None] * ddz)
        K[:, 1] = -p * (dr[:, None] * dwa + wa[:, None] * ddr)
        K[:, 2] = p * (dz[:, None] * dwb + wb[:, None] * ddz)
        K[:, 3] = -p * (dr[:, None] * dwb + wb[:, None] * ddr)
        return K.ravel()


class AdvancingFront(Term):
    """The front's post-step hook while the pressure rises (step 2): after every accepted
    step the fronts move towards ``target_reach``, advancing only and by at most
    ``max_advance`` edges. ``contact_pressure(t, u)``: the nodal wall contact pressures
    (MPa) at a state.

    Why the limit: the target is read from a state solved with the previous front. Where the
    fluid has been held back (at the start node, by the seal's contact with the pressure-side
    wall, until p exceeds it), that state has carried no fluid load at all, so none of the
    seal's self-energising contact pressure has built up, and at the next accepted pressure
    every node may read p_c < p once p exceeds the mount's peak contact pressure: the whole
    loop floods in one update (the paper's O-ring at 40 MPa, benchmarks/stress.md), an
    artefact of the lag, after which no step converges. Advancing a few edges per step lets
    the seal answer each advance before the next, and the front settles where the
    equilibrium puts it (``settle_front`` afterwards, unlimited)."""

    def __init__(self, load, contact_pressure, max_advance=None):
        self.load, self.contact_pressure = load, contact_pressure
        self.max_advance = max_advance

    def accepted(self, t, u):
        self.load.update(self.contact_pressure(t, u), t, max_advance=self.max_advance,
                         recede=False)
        self.load.check_blow_by(t)


def front_drift(load, contact_pressure_at_nodes, t):
    """The largest distance (edges) from a load's fronts to their targets at a state: how
    far the seal's contact would move a front that is kept (the stroke's, docs/design.md)."""
    target = load.target_reach(contact_pressure_at_nodes, t)
    return float(max(abs(a - b) for a, b in zip(target, load.reach)))


# a target this close to a position visited before, relative to the way there, closes a
# cycle
REVISIT = 0.1


def settle(load, t, contact_pressure, solve, tol=1e-4, max_updates=30):
    """Front update and solve in turn at time t, from an equilibrium with the present front,
    until the fronts would move by less than ``tol`` edges in all; the state keeps the front
    it was solved with. ``contact_pressure()``: the nodal wall contact pressures of the
    present state, ``solve()``: the equilibrium with the present front. Returns (edges the
    fronts would still move, the index of the last update: max_updates - 1 where they did
    not settle).

    Each front moves to its target (the plain fixed-point iteration) until it cycles, met
    on micrometre edges, where the next node's contact pressure passes the wetting margin
    as the front reaches it:

    * two positions each pointing at the other (the target is the position the front came
      from, within tol), whatever the other fronts do: two fronts can flip together;
    * or more in turn (its target comes back to a position it visited, within a tenth of
      its way there, ``REVISIT``) while the other fronts stand (move by less than that:
      their moves change the state its targets are read from, and a bracket from before
      them is stale; at 20 MPa on the coarse O-ring one held a front 0.16 edges from its
      target while the other front moved on by tenths of an edge).

    Such a front is bisected between the nearest two positions of its cycle that point at
    each other (:func:`_bracket`) by the sign of its way at each midpoint, and settles where
    the target turns, to within tol edges (counted as its move)."""
    n = len(load.reach)
    prev, bracket, seen, moves = [None] * n, [None] * n, [[] for _ in range(n)], [0.0] * n
    stands = [None] * n         # a longer cycle's bracket holds while the others move less
    moved = 0.0
    for k in range(max_updates):
        kept = list(load.reach)
        target = load.target_reach(contact_pressure(), t)
        load.set_reach(target)
        load.check_blow_by(t)
        new, moved = [], 0.0
        for j, (x, y) in enumerate(zip(kept, target)):
            d = y - x
            if bracket[j] is None and abs(d) > tol:
                near = max(tol, REVISIT * abs(d))
                hit = [i for i, (p, _) in enumerate(seen[j]) if abs(y - p) <= near]
                if prev[j] is not None and abs(y - prev[j]) <= tol:       # a two-cycle
                    bracket[j] = [min(x, y), max(x, y)]
                elif hit and max(moves[:j] + moves[j + 1:], default=0.0) <= near:
                    b = _bracket(seen[j][hit[-1]:] + [(x, d)])
                    bracket[j], stands[j] = (None, None) if b is None else (list(b), near)
            seen[j].append((x, d))
            prev[j] = x
            b = bracket[j]
            if b is None or abs(d) <= tol:
                new.append(y)
                moved += abs(d)
            else:
                if b[0] <= x <= b[1]:
                    b[0 if d > 0.0 else 1] = x
                new.append(x if b[1] - b[0] < tol else 0.5 * (b[0] + b[1]))
                moved += b[1] - b[0]
        if moved < tol:
            load.set_reach(kept)
            return moved, k
        moves = [abs(a - c) for a, c in zip(new, kept)]
        for j in range(n):
            others = max(moves[:j] + moves[j + 1:], default=0.0)
            if stands[j] is not None and others > stands[j]:
                bracket[j] = stands[j] = None           # stale: followed again
        load.set_reach(new)
        solve()
    return moved, max_updates - 1


def _bracket(seen):
    """The nearest two positions (lo, hi), lo < hi, of the (position, way to its target)
    pairs ``seen`` whose ways point at each other (lo's up, hi's down), or None."""
    up = [x for x, d in seen if d > 0.0]
    down = [x for x, d in seen if d < 0.0]
    pairs = [(lo, hi) for lo in up for hi in down if lo < hi]
    return min(pairs, key=lambda p: p[1] - p[0]) if pairs else None


class RelaxedFront(Term):
    """The front's post-step hook for a long transient run (the hold): each front moves by
    omega times its way to ``target_reach``, at most ``max_advance`` edges forward. omega
    halves whenever the front reverses and doubles (up to 1) while it keeps its direction.
    Met in the viscoelastic hold at 5 MPa: at t = 10.45 s a front flipped between two
    positions at every step, each position's equilibrium pointing at the other, and the
    adaptive step collapsed. ``contact_pressure(t, u)`` as for :class:`AdvancingFront`."""

    history_names = ("omega", "direction")

    def __init__(self, load, contact_pressure, max_advance=1.0):
        self.load, self.contact_pressure = load, contact_pressure
        self.max_advance = max_advance
        self.omega = [1.0] * len(load.reach)       # per front (two per fluid)
        self.direction = [0.0] * len(load.reach)

    def history(self):
        """Its relaxation state and the fronts' reach (a checkpoint of the hold)."""
        return {**super().history(), "reach": np.array(self.load.reach, float)}

    def restore(self, history):
        self.omega = [float(x) for x in history["omega"]]
        self.direction = [float(x) for x in history["direction"]]
        self.load.set_reach([float(x) for x in history["reach"]])

    def accepted(self, t, u):
        L = self.load
        target = L.target_reach(self.contact_pressure(t, u), t)
        reach = []
        for i, (goal, now) in enumerate(zip(target, L.reach)):
            d = float(np.sign(goal - now))
            if d != 0.0:
                reverses = self.direction[i] != 0.0 and d != self.direction[i]
                self.omega[i] = 0.5 * self.omega[i] if reverses else min(1.0, 2 * self.omega[i])
                self.direction[i] = d
            reach.append(now + min(self.omega[i] * (goal - now), self.max_advance))
        L.set_reach(reach)
        L.check_blow_by(t)
