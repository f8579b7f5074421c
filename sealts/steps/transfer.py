"""Steps 1-2 carried to another mesh of the same seal (``mesh.h_edge``: from the scene's own
mesh to the one refined at the contact's edges,
:func:`sealts.steps.procedure.refined_state`).

Steps 1-2 are quasi-static, hyperelastic (long-term) and frictionless: their end is a static
equilibrium that carries no history but the pressure-penetration front. So the refined
mesh need not repeat their path; it starts from the other mesh's end state, interpolated
node by node (:func:`sealts.mesh.transfer.interpolate`, in the reference configuration),
with the fronts at the same reference positions (:meth:`PressureLoad.reach_at`), and
Newton's method finds its own equilibrium from there; the front is then settled against it
(:func:`sealts.steps.quasi_static.settle_front`) as at the end of step 2.

Why not repeat the path: the pressurisation's front only advances while p_in rises, and
the refined mesh's micrometre edges let it run ahead of its equilibrium (at 20 MPa 74
edges, 0.11 mm, on the paper's O-ring); the settling that has to bring it back crushes the
micrometre elements at the pressure-side edge. From the carried state the front has only
its discretisation to settle. The seal also keeps the roll it found on the scene's own mesh
(steps 1-2's frictionless walls hold it weakly, and a repeated path can settle it 0.13 mm
elsewhere), and the pseudo-time runs of a second mount and pressurisation are saved.

Where neither Newton's method from the carried state nor the stabilised driver finds an
equilibrium, the run stops and names the place of the carried state's largest
out-of-balance force and, where the scene's own mesh's surface is folded onto itself there,
the fold (:func:`no_equilibrium`): the paper's O-ring at 40 MPa with no extrusion gap creases
along the atmosphere-side wall, at the scale of the mesh, and the refined mesh has no
equilibrium near the coarse mesh's fold (releasing the out-of-balance force in steps,
F(u) = (1 - lambda) F(u_carried), got no further than lambda = 0.016).

Where a static solve of the settling fails, the settling stops and the last equilibrium
stands, with a warning (``settle_front(..., keep=True)``): at 20-30 MPa the pressure-side
front's next move on micrometre edges, where the wetted nodes next to the contact touch the
rod's asperities (p_c above p_crit: they seal) and, once dry, no longer do. The front then
lies a few micrometre edges from its target, within one of the scene's own mesh's edges,
where that mesh settled it; in a stroke the film carries the fluid on the rod side.
"""
import numpy as np

from ..core import PhysicalStop, SolveError, reworded
from ..mesh.transfer import interpolate, locate, onto_boundary
from ..solid.pressure import boundary_loop
from ..solid.dilatation import dilatation, match_dilatation
from .base import Step
from .pressurise import Pressurise, settled
from .pseudo_time import PseudoTime
from .quasi_static import Equilibrium, quasi_static, settle_front, static

# Newton's method from the carried state and in the front's settling on the new mesh
# (options prefix ``transfer_``). Measured on the paper's O-ring, default sizes, h_edge
# 0.0015 mm: the full steps of the basic line search turn micrometre elements at a
# contact's edge over (20 MPa: NaN at the first step); l2 converges at 20 MPa but not at
# 30 MPa (200 iterations), PETSc's trust region at 20 but not 30 MPa; backtracking (bt)
# at 1, 5, 10, 20 and 30 MPa
NEWTON = {"prefix": "transfer_", "linesearch": "bt", "max_it": 50}


class Transfer(Step):
    """The end of steps 1-2 of ``source`` (a RunState on another mesh of the same seal)
    as the start of this state's, brought to equilibrium on this state's mesh."""
    name = "transfer"

    def __init__(self, source):
        self.source = source

    def run(self, state):
        src, model = self.source, state.model
        u = carried(src.model, src.u, model)
        t, dt = src.t, state.scene.mount.dt
        extra, load = [], None
        if src.load is not None:
            load = Pressurise.pressure_load(state)
            load.p_crit = src.load.p_crit
            load.set_reach(load.reach_at(src.load.front_points()))
            extra = [load]
        eq = Equilibrium(u, None)
        try:
            eq.u = static(model, extra, u, t, eq.counters, **NEWTON)
        except SolveError:         # not near enough: the stabilised way (settle_front's)
            try:
                eq = quasi_static(model, extra, u, PseudoTime.window(t), dt)
            except PhysicalStop as e:   # its guards' own verdict on the refined mesh
                raise reworded(e, f"{e} (on the refined mesh, from the state carried "
                                  "to it)") from None
            except SolveError as e:
                why = str(e).splitlines()[0].split("; try a smaller")[0]
                text, folded = no_equilibrium(src, model, extra, u, t)
                kind = (lambda m: PhysicalStop("crease", m)) if folded else SolveError
                raise kind(f"{text} (the stabilised driver from it: {why})") from None
        label = f"carried to the refined mesh, pseudo-time {t:g}"
        if load is None:
            state.counters.add(eq.counters)
            state.u, state.udot, state.t = eq.u, eq.udot, t
            state.results = model.results(t, eq.u, eq.udot)
            y, h, p = model.contact_profile(t, eq.u)
            state.writer.profile(t, {"y": y, "h": h, "p_contact": p},
                                 label="mounted, " + label)
            return
        eq, moved, updates = settle_front(model, load, eq, t, dt, keep=True, **NEWTON)
        state.counters.add(eq.counters)
        hint = ("try a larger fluid.p_crit" if not eq.stopped else
                "Newton's method failed on that move, and the front stands where it last "
                "converged (on the refined mesh's edges, next to a contact's edge loaded "
                "by p_in; in a stroke the film carries the fluid on the rod side)")
        settled(state, eq, load, t, moved, updates, src.results.get("mounted", {}),
                f"pressurised to {state.scene.fluid.p_in:g} MPa, " + label, hint)


# a fold of the scene's own mesh this near (reference, mm) the largest out-of-balance force
# is named as its cause
NEAR_FOLD = 0.1


def no_equilibrium(src, model, extra, u, t):
    """Why the refined mesh found no equilibrium from the carried state ``u``: (in words,
    where the state is out of balance the most and whether the scene's own mesh's surface
    is folded onto itself there (its self-contact holds); whether it is)."""
    f = np.zeros(model.n)
    for term in model.local_terms(model.walls() + list(extra)):
        term.add_residual(t, u, np.zeros(model.n), f)
    un = np.asarray(u)[model.udofs]
    force = np.hypot(f[model.udofs[:, 0]], f[model.udofs[:, 1]])
    if not np.isfinite(force).all():     # an element of the carried state inverted
        return ("no equilibrium on the refined mesh near the state carried to it: "
                + (model.solid.nonfinite(t, u) or "its residual is not finite")), False
    k = int(np.argmax(force))
    X, x = model.mesh.X[k], model.mesh.X[k] + un[k]
    za, zb = model.groove.z_walls(t)
    wall, side = min((x[1] - za, "pressure-side"), (zb - x[1], "atmosphere-side"))
    where = (f"{force[k]:.4g} N at r = {X[0]:.4g}, z = {X[1]:.4g} mm (undeformed), "
             f"{wall:.3g} mm from the {side} wall and {x[0] - model.rod_radius(t):.3g} mm "
             "above the rod")
    fold = ""
    sc = src.model.self_contact
    if sc is not None:
        near = np.hypot(*(sc.closed(np.asarray(src.u)) - X).T) < NEAR_FOLD
        if near.any():
            fold = ("; the scene's own mesh's surface is folded onto itself there (its "
                    f"self-contact holds {near.sum()} pair(s) of nodes within {NEAR_FOLD:g} "
                    "mm): the rubber creases, compressed "
                    "along the surface, at the scale of the mesh, and the refined mesh's "
                    "finer elements fold otherwise")
    return ("no equilibrium on the refined mesh near the state carried to it: Newton's "
            f"method from it fails; its largest out-of-balance force is {where}{fold}"), bool(fold)


def carried(old, u_old, new):
    """The displacements ``u_old`` of the model ``old`` carried to the model ``new`` (another
    mesh of the same seal; serial): interpolated in the reference configuration
    (:func:`sealts.mesh.transfer.interpolate`), the boundary's nodes placed on the old
    deformed boundary (:func:`sealts.mesh.transfer.onto_boundary`), then corrected until
    each new element has the dilatation of the old element its centroid lies in, the
    boundary's nodes kept (:func:`sealts.solid.dilatation.match_dilatation`)."""
    X, conn = old.mesh.X, old.mesh.conn
    un_old = np.asarray(u_old)[old.udofs]
    un = interpolate(X, conn, un_old, new.mesh.X)
    boundary = np.unique(boundary_loop(new.mesh.conn).ravel())
    Xb = new.mesh.X[boundary]
    un[boundary] = onto_boundary(X, boundary_loop(conn), X + un_old, Xb) - Xb
    u = np.zeros(new.n)
    u[new.udofs] = un
    theta_old, _ = dilatation(old.solid, u_old)
    inside, _, _ = locate(X, conn, new.mesh.X[new.mesh.conn].mean(axis=1))
    u, _ = match_dilatation(new.solid, u, theta_old[inside], new.udofs[boundary].ravel(),
                            new.n)
    return u
