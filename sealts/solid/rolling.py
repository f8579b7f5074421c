"""A pure couple that holds a plane-strain O-ring's rolling angle (steps 1-2).

Why: in plane strain a circular cross-section between frictionless walls has no rolling
stiffness. If phi(X) is an equilibrium, so is phi(R X) for any rotation R of the reference
disc about its centre: the deformed shape, its contact pressures and the wetted free surface
are the same, only the material has rolled round inside them. The equilibria form a
one-parameter family and the static Jacobian is singular along it (axisymmetric rings are
held by their hoop strain: rolling moves material to other radii). Measured on the coarse
paper O-ring (0.1/0.4 mm, the planar mount): the smallest eigenvalue of the symmetric part of
the unstabilised Jacobian is -2.5e-5 N/mm, against 0.20 N/mm axisymmetrically, with 0.89 of
its mode a rigid rotation; the stabilised mount had already rolled the section by 12.8
degrees (axisymmetric: -0.07). The stabilised pressurisation then rolled it on: 20 degrees
at 95 % of p_in, then 48 degrees, until the rod side -- the only nodes that feel the rod,
and the film's surface -- had rolled off the rod and other nodes passed through it
unopposed (rod force 0.004 N, "min h" -118 um, dt 1e-7: the crawl).

``RollingGauge`` fixes that gauge freedom with one scalar condition: the mean rolling angle
of a ring of boundary nodes (``SealModel`` holds it on a plane-strain section whose
boundary is a circle, ``is_round``: the O-ring, or a mesh file of one),

    omega(u) = sum_i (d_i x u_i) / sum_i |d_i|^2,   d_i = X_i - c (reference, c their mean),

is held at ``angle`` by a spring of stiffness k, i.e. nodal forces -T d omega/du with the
torque T = k (omega - angle). d omega/du_i is proportional to d_i rotated by 90 degrees, and
the d_i sum to zero, so the forces are a pure couple: they add nothing to any force balance
(radial, axial). In the continuum the family is neutral, so the torque the gauge carries is
discretisation error; ``torque`` reports it (N mm per mm of depth) for the summary. The
stroke does not use the gauge: there friction holds (or rolls) the ring physically.
"""
import numpy as np

from ..core import Term


def circle_fit(P):
    """Least-squares circle through points P (n, 2) (Kasa's algebraic fit): centre, radius
    and the largest relative distance of a point from it."""
    A = np.column_stack([P, np.ones(len(P))])
    sol = np.linalg.lstsq(A, (P**2).sum(1), rcond=None)[0]
    c = 0.5 * sol[:2]
    radius = float(np.sqrt(sol[2] + c @ c))
    return c, radius, float(np.abs(np.hypot(*(P - c).T) - radius).max() / radius)


def is_round(X, loop_nodes, tol=1e-3):
    """Whether the boundary nodes lie on one circle (to ``tol`` of its radius): the
    cross-sections whose rolled equilibria are a neutral family."""
    return circle_fit(X[np.asarray(loop_nodes)])[2] <= tol


def gauge_nodes(X, loop_nodes, count=16):
    """``count`` boundary nodes spread round the cross-section: the loop node nearest to
    each of ``count`` equally spaced directions from the centre of the loop's circle fit
    (unique)."""
    loop_nodes = np.asarray(loop_nodes)
    P = X[loop_nodes]
    c = circle_fit(P)[0]
    ang = np.arctan2(P[:, 1] - c[1], P[:, 0] - c[0])
    picks = []
    for a in np.linspace(-np.pi, np.pi, count, endpoint=False):
        d = np.abs(np.angle(np.exp(1j * (ang - a))))
        picks.append(loop_nodes[np.argmin(d)])
    return np.unique(picks)


class RollingGauge(Term):
    def __init__(self, X, nodes, udofs, stiffness, angle=0.0):
        """``nodes``: the boundary nodes whose mean rolling is held; ``stiffness`` k in
        N mm/rad (per mm of depth); ``angle`` the held omega (rad)."""
        self.nodes = np.asarray(nodes)
        d = X[self.nodes] - X[self.nodes].mean(0)
        inertia = float((d**2).sum())
        self.a = (np.stack([-d[:, 1], d[:, 0]], 1) / inertia).ravel()   # d omega / d u
        self.dofs = np.asarray(udofs)[self.nodes].ravel()
        m = self.dofs.size
        self.rows = np.repeat(self.dofs, m)
        self.cols = np.tile(self.dofs, m)
        self.k, self.angle0 = float(stiffness), float(angle)
        self._kaa = (self.k * np.outer(self.a, self.a)).ravel()

    def angle(self, u):
        """The mean rolling angle omega(u) of the gauge nodes (rad)."""
        return float(self.a @ u[self.dofs])

    def torque(self, u):
        """The couple the gauge applies to hold omega (N mm per mm of depth; >0 turns the
        section from +r towards +z)."""
        return -self.k * (self.angle(u) - self.angle0)

    def add_residual(self, t, u, udot, f):
        # internal force of the spring: +k (omega - angle) d omega/du
        np.add.at(f, self.dofs, -self.torque(u) * self.a)

    def jacobian_values(self, t, u, udot, shift):
        return self._kaa
