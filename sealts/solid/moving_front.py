"""The pressure-penetration front during the stroke, moved at located TS events.

Step 2 leaves each front where the sealing margin g = p_c + phi p - p - p_crit of
:mod:`sealts.solid.pressure` crosses zero (``target_reach``). During the stroke the seal's
contact pressures p_c change with the friction, the film and the rod's motion, and the
target moves with them. Each front i carries two TS events on its drift
d_i(t, U) = target_i - b_i (edges), b_i where the front is going (its reach when at rest):

    d_i - tol = 0   crossing upwards:   the fluid gets further (the front advances),
    d_i + tol = 0   crossing downwards: the seal closes on the wetted edge (it recedes),

located in time by TS (``TSSetEventHandler``; BDF restarts there,
:meth:`sealts.problem.Problem._set_events`). From an event at t_e the front moves to the
target b_i it had there, linearly from where it stands over T = t_e - t_last (t_last its
previous event, or the stroke's start): at the mean pace its target drifted by tol before;
a target that runs on fires the next event sooner, and the next ramp is faster. A jump
instead of the ramp can have no solution at any step size where the seal is near a fold
(the default cycle's reversal, benchmarks/stroke_sensitivity.md): the quasi-static seal
must follow a jump of its load at once while the film's squeeze term holds the rod side.
Between events each target stays within +-tol edges of where its front is going
(``stroke.front_tolerance``): the front follows the seal's traction with a hysteresis of
tol, its lag behind the target is the series' ``front_drift``, and every change is recorded
(``moves``; the series' ``wetted_edges``) and placed where the state asks for it, never
made between steps.

The wetting of the load at t is this term's: it sets the load's reach for each evaluation
(it comes before the load in the Problem's terms). The target is where g first turns
positive walking from the fluid's entry, so a region of the seal that lifts off all at once
moves it by many edges; a target that reaches the atmosphere side stops the run at once
(blow-by).

The target depends on the front: the wet share phi of the front's edge enters g. Where the
target falls faster than the front advances (dT/db < -1, met at 30 MPa as the instroke
starts), moving the front to its target overshoots the consistent front b* = T(b*), and
the target points back by more than tol before the ramp ends: a front moved to its
targets swings about b* for ever. A target that turns back past the front while the
front's last ramp is still running (an overshoot) therefore sends it to the secant root
of f(b) = T(b) - b through this event's (reach, target) and the last event's, which lies
between the two. If flipping goes on all the same (``MAX_FLIPS`` reversals each within
``FLIP_WINDOW`` of the last) the run stops and says where.
"""
import numpy as np

from ..core import SolveError, Term

MAX_FLIPS = 8            # reversals of one front, each ...
FLIP_WINDOW = 1e-6       # ... within this time (s) of the last: a front that flips on end
MIN_RAMP = 1e-6          # s: the shortest ramp (two events of one front at one time)


def consistent_reach(b1, t1, b2, t2):
    """The secant root of f(b) = T(b) - b through (b1, T(b1) = t1) and (b2, t2), f of
    opposite signs there (a front that overshot): between b1 and b2; b2's target t2 where
    the two reaches coincide."""
    f1, f2 = t1 - b1, t2 - b2
    if b1 == b2 or f1 == f2:
        return t2
    return b2 - f2 * (b2 - b1) / (f2 - f1)


class MovingFront(Term):
    """The fronts of a pressure load (:class:`sealts.solid.pressure.PressureLoad` or
    :class:`sealts.solid.fluid_loads.FluidLoads`) moved towards their targets from TS
    events. ``contact_pressure(t, U)``: the nodal wall and rod contact pressures (MPa) at
    a state; ``tol``: the drift (edges) at which a front follows; ``t0``: the start."""

    history_names = ("ramps", "moves", "flips", "seen")

    def __init__(self, load, contact_pressure, tol=0.1, t0=0.0):
        if not tol > 0.0:
            raise ValueError(f"MovingFront: tol must be > 0 edges, not {tol}")
        self.load, self.contact_pressure, self.tol = load, contact_pressure, float(tol)
        self.event_directions = (1, -1) * len(load.reach)
        self.reset(t0)

    def reset(self, t0):
        """Start from the load's present fronts at t0, no moves yet."""
        r = np.array(self.load.reach, float)
        n = r.size
        # per front: start t_e, duration T, reach a at t_e, target b
        self.ramps = np.column_stack([np.full(n, float(t0)), np.ones(n), r, r])
        self.moves = np.zeros(n)          # events per front
        self.flips = np.zeros(n)          # reversals in a row, each within FLIP_WINDOW
        self.seen = np.column_stack([r, r])   # per front (reach, target) at its last event

    def restore(self, history):
        """Put back a :meth:`history`; one saved before ``seen`` was kept takes each front's
        last ramp (its start and goal) for it."""
        if "seen" not in history:
            history = {**history, "seen": np.asarray(history["ramps"], float)[:, 2:4]}
        super().restore(history)

    def reach_at(self, t):
        """Each front's reach (edges) at t."""
        t_e, T, a, b = self.ramps.T
        return a + (b - a) * np.clip((t - t_e) / T, 0.0, 1.0)

    def wet_at(self, t):
        """Set the load's wetting to the fronts' at t."""
        r = self.reach_at(t)
        if not np.array_equal(r, self.load.reach):
            self.load.set_reach([float(x) for x in r])

    def add_residual(self, t, u, udot, f):
        self.wet_at(t)

    def jacobian_values(self, t, u, udot, shift):
        self.wet_at(t)
        return np.zeros(0)

    def accepted(self, t, u):
        self.wet_at(t)

    def event_values(self, t, u):
        # the target against where the front is going (the ramp's end): a target that runs
        # on after an event fires again at +-tol from there
        self.wet_at(t)
        target = self.load.target_reach(self.contact_pressure(t, u), t)
        d = np.array(target, float) - self.ramps[:, 3]
        return np.column_stack([d - self.tol, d + self.tol]).ravel()

    def event(self, t, u, which):
        self.wet_at(t)
        now = self.reach_at(t)
        target = np.array(self.load.target_reach(self.contact_pressure(t, u), t), float)
        fired = sorted({int(k) // 2 for k in which})
        for i in fired:
            t_last, T_last = self.ramps[i, :2]
            a_seen, b_seen = self.seen[i]
            # the target turned to the other side of the front since the last event
            back = (self.moves[i] > 0
                    and np.sign(target[i] - now[i]) == -np.sign(b_seen - a_seen))
            flip = back and t - t_last <= FLIP_WINDOW
            self.flips[i] = self.flips[i] + 1 if flip else 0
            if self.flips[i] >= MAX_FLIPS:
                raise SolveError(
                    f"the pressure-penetration front {i + 1} flips between "
                    f"{now[i]:.3f} and {target[i]:.3f} edges from its entry at t = {t:.6g} "
                    "s: each position's equilibrium points at the other (the seal's "
                    "contact there is bistable)")
            goal = target[i]
            if back and t < t_last + T_last:        # within the last ramp: an overshoot
                goal = consistent_reach(a_seen, b_seen, now[i], target[i])
            self.seen[i] = (now[i], target[i])
            self.ramps[i] = (t, max(t - t_last, MIN_RAMP), now[i], goal)
            self.moves[i] += 1
        # a target on the atmosphere side is blow-by now, not at the ramp's end
        ends = now.copy()
        ends[fired] = target[fired]
        self.load.set_reach([float(x) for x in ends])
        self.load.check_blow_by(t)
        self.wet_at(t)
