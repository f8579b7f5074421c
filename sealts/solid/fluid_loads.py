"""Two fluids on the seal's free surface: the sealed pressure p_in and a back pressure p_out
(a double-acting cylinder, or the symmetric test p_in = p_out).

Each fluid is a :class:`sealts.solid.pressure.PressureLoad` with its own entry (where it
comes in through the rod clearance: p_in at the pressure side's node nearest the rod, p_out
at the atmosphere side's) and its own two fronts.
Where a node is wetted by both, its normal traction carries both fluids' shares, so a
fluid's front test of the module docstring there reads

    sigma_n = p_c + sum_j phi_j p_j,     g_i = sigma_n - p_i - p_crit,

which is the single fluid's test with p_c + sum_{j != i} phi_j p_j in place of p_c: each
fluid is handed the others' share as part of its contact pressure (all from the same
wetting: a Jacobi update). The loads and their Jacobians add. The fluids passing each other
is blow-by: a fluid reaching the other's side (``mark_exit``) or an edge wetted by both.

The reach is the fluids' reaches one after the other (two fronts each); everything else a
step asks of a load (``pressure`` is p_in's, ``wet``, ``fluid_share``, ``forces``,
``rebuilt``) is answered for the fluids together.
"""
import numpy as np

from ..core import PhysicalStop, Term


class FluidLoads(Term):
    def __init__(self, loads):
        self.loads = list(loads)
        self.pressure = self.loads[0].pressure
        self.edges, self.m = self.loads[0].edges, self.loads[0].m
        self.rows = np.concatenate([f.rows for f in self.loads])
        self.cols = np.concatenate([f.cols for f in self.loads])

    @property
    def pressures(self):
        return [f.pressure for f in self.loads]

    @property
    def p_crit(self):
        return self.loads[0].p_crit

    @p_crit.setter
    def p_crit(self, value):
        for f in self.loads:
            f.p_crit = value

    @property
    def reach(self):
        if any(f.reach is None for f in self.loads):
            return None
        return [r for f in self.loads for r in f.reach]

    @property
    def entries(self):
        return [n for f in self.loads for n in f.entries]

    def recount(self, reach, entries):
        return [r for k, f in enumerate(self.loads)
                for r in f.recount(reach[2 * k:2 * k + 2], entries[k:k + 1])]

    def set_reach(self, reach):
        for k, f in enumerate(self.loads):
            f.set_reach(reach[2 * k:2 * k + 2])

    def front_points(self):
        """The fronts' reference positions, the fluids' one after the other."""
        return np.vstack([f.front_points() for f in self.loads])

    def reach_at(self, points):
        """The reach whose fronts lie at ``points`` (:meth:`front_points`' order)."""
        return [r for k, f in enumerate(self.loads)
                for r in f.reach_at(points[2 * k:2 * k + 2])]

    @property
    def wet(self):
        return np.minimum(sum(f.wet for f in self.loads), 1.0)

    def wet_share(self):
        return np.minimum(sum(f.wet_share() for f in self.loads), 1.0)

    def fluid_share(self, t):
        return sum(f.fluid_share(t) for f in self.loads)

    def _others(self, contact, t):
        """Each fluid's contact pressure: the walls' plus the other fluids' shares."""
        shares = [f.fluid_share(t) for f in self.loads]
        total = sum(shares)
        return [contact + total - own for own in shares]

    @property
    def held(self):
        return tuple(h for f in self.loads for h in f.held)

    def target_reach(self, contact_pressure_at_nodes, t):
        return [r for f, c in zip(self.loads, self._others(contact_pressure_at_nodes, t))
                for r in f.target_reach(c, t)]

    def update(self, contact_pressure_at_nodes, t, max_advance=None, recede=True):
        others = self._others(contact_pressure_at_nodes, t)
        return sum(f.update(c, t, max_advance=max_advance, recede=recede)
                   for f, c in zip(self.loads, others))

    def check_blow_by(self, t):
        for f in self.loads:
            f.check_blow_by(t)
        both = np.sum([f.wet > 0.0 for f in self.loads], axis=0) > 1
        if both.any():
            k = int(np.nonzero(both)[0][0])
            raise PhysicalStop("blow-by",
                               "blow-by: the fluids of both sides meet on the edge of nodes "
                               f"{self.edges[k, 0]}-{self.edges[k, 1]} at p_in = "
                               f"{self.pressure(t):.4g} MPa, t = {t:.6g}: the seal no longer "
                               "seals")

    def rebuilt(self, pressures=None, udofs=None, dry=None):
        pressures = self.pressures if pressures is None else pressures
        return FluidLoads([f.rebuilt([p], udofs, dry) for f, p in zip(self.loads, pressures)])

    def forces(self, t, u):
        return sum(f.forces(t, u) for f in self.loads)

    def add_residual(self, t, u, udot, f):
        for load in self.loads:
            load.add_residual(t, u, udot, f)

    def jacobian_values(self, t, u, udot, shift):
        return np.concatenate([f.jacobian_values(t, u, udot, shift) for f in self.loads])
