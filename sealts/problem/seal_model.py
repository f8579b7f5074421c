"""The seal between a rigid rod and groove: mesh, material and walls as Problem terms.

The steps of a procedure (:mod:`sealts.steps`) build their problems from it: mounting and
pressurisation (paper Section 3.1.1, steps 1-2) move the rod and groove along the pseudo-time
of :mod:`sealts.steps.pseudo_time`; the hold and the stroke (step 3) use the walls at their
final radii. The model holds no history of a run: that is the :class:`sealts.steps.RunState`
handed from step to step.
"""
import numpy as np

from ..contact.asperity import ExponentialLaw, law_from_scene
from ..contact.rigid import (GrooveContact, RodContact, node_contact_pressure,
                             tributary_lengths)
from ..contact.extrusion_guard import ExtrusionGuard, extrusion
from ..contact.rod_side_guard import RodSideGuard
from ..contact.rod_side import RodSide
from ..contact.self_contact import SelfContact
from ..mesh.partition import Partition
from ..mesh.seal_mesh import FLANK
from ..solid.stabilisation import ViscousStabilisation
from ..solid.term import SolidTerm
from .problem import Problem

NEWTON_ATOL = 1e-9   # a seal's Newton solves converge to this fraction of its force scale
WALLS_FINAL = 1.0    # rod and groove reach their final radii at this pseudo-time


# seal.self_contact = "auto" turns the self-contact on from this sealed or back pressure
# (MPa): the paper's O-ring (0.025 / 0.2 mm) creases against the atmosphere side's wall
# at 38 MPa, and pressurised to 30 or 35 MPa its closest boundary nodes within reach stay
# 2.8 contact distances apart; below, the term's pattern would only cost (its couplings
# along the boundary put 27 % more fill into steps 1-2's factorisations)
SELF_CONTACT_FROM = 10.0


def ramp(t):
    """Smooth 0 -> 1 over t in [0, 1] (C1), then 1."""
    s = min(max(t, 0.0), 1.0)
    return s * s * (3.0 - 2.0 * s)


class SealModel:
    """Seal mesh + material + rod and groove, as Problem terms.

    The mesh is distributed over ``comm`` (:class:`sealts.mesh.partition.Partition`): each
    rank's ``solid`` covers its own cells, in its local dofs. ``rod``, ``groove``, ``stab``
    (and a pressure load) are written in serial dofs and cover the whole boundary (mesh):
    every rank evaluates them on the gathered state for outputs and front updates, and
    rank 0 alone assembles the rod, groove and pressure terms (``local_terms``). The
    stabilisation is assembled by each rank over the nodes it owns. Problems
    (``problem``) run on the model's communicator.

    ``hold_rolling``: hold the rolling angle with ``gauge`` (:mod:`sealts.solid.rolling`) in
    steps 1-2 (and the hold); by default on a plane-strain section whose boundary is a
    circle, which nothing else holds from rolling between frictionless walls.
    ``self_contact``: the surface's self-contact (:mod:`sealts.contact.self_contact`) among
    the boundary terms of every step (``surface``)."""

    def __init__(self, mesh, material, rod_radius, groove_radius, groove_walls, axisym=True,
                 law=None, penalty=1e4, stabilisation=1e-3, depth=1.0,
                 corner_radius=0.0, comm=None, hold_rolling=None, clearance=0.0,
                 edge_radius=0.1, extrusion_limit=0.25, off_hint="", self_contact=False):
        from petsc4py import PETSc

        from ..solid.pressure import boundary_loop
        self.mesh, self.material, self.axisym = mesh, material, axisym
        # what the rod-side guard adds when a node off the rod side enters the rod
        self.off_hint = off_hint
        self.comm = comm = comm or PETSc.COMM_WORLD
        X = mesh.X
        root_nodes = np.union1d(mesh.boundary_nodes(), boundary_loop(mesh.conn).ravel())
        self.partition = part = Partition(mesh, comm, root_nodes=root_nodes)
        self.dofs = dofs = part.numbering()
        self.n = dofs.n
        udofs = self.udofs = dofs.udofs                        # serial
        self.solid = SolidTerm(X, mesh.conn[part.cells], material, axisym,
                               udofs=dofs.udofs_local, heating=ramp)
        chain = mesh.chain("rod_side")
        r_out = X[:, 0].max()
        r_in = X[chain, 0].min()
        self.r_rod_final = rod_radius
        self.r_rod0 = min(rod_radius, r_in - 1e-3)          # clear of the seal at t = 0
        self.r_g_final = groove_radius
        self.r_g0 = max(groove_radius, r_out + 1e-3)
        area = 2 * np.pi * rod_radius if axisym else depth
        self.law = law if law is not None else ExponentialLaw()
        bnd = mesh.boundary_nodes()
        # the rod side (the boundary nodes off it: what the rod-side guard watches)
        self.side = RodSide(X, chain, self.rod_radius, area, udofs=udofs,
                            off=np.setdiff1d(bnd, chain))
        self.rod = RodContact(self.side, self.law)
        trib = tributary_lengths(X, np.concatenate(list(mesh.edges.values())), X.shape[0])
        self.groove = GrooveContact(X, bnd, trib, axisym, self.groove_radius,
                                    lambda t: groove_walls, penalty=penalty, depth=depth,
                                    corner_radius=corner_radius, udofs=udofs,
                                    edge=((rod_radius + clearance, edge_radius)
                                          if clearance > 0.0 else None))
        self.extrusion_limit = extrusion_limit
        # the surface against itself: a crease's faces (sealts.contact.self_contact)
        self.self_contact = (SelfContact(X, boundary_loop(mesh.conn)[:, 0], trib, axisym,
                                         udofs=udofs, penalty=penalty,
                                         delta=self.groove.delta, depth=depth)
                             if self_contact else None)
        # lumped nodal volumes as stabilisation weights (mm^3), scaled by c (MPa s / mm^2);
        # summed over the ranks' cells
        mpi = comm.tompi4py()
        vol = np.bincount(self.solid.conn.ravel(), np.repeat(self.solid.W.sum(1) / 4.0, 4),
                          minlength=X.shape[0])
        vol = mpi.allreduce(vol) if comm.getSize() > 1 else vol
        self.stab = ViscousStabilisation(udofs.ravel(), np.repeat(vol, 2), stabilisation)
        own = part.owned_nodes
        self.stab_local = ViscousStabilisation(dofs.udofs_local[own].ravel(),
                                               np.repeat(vol[own], 2), stabilisation)
        # force scale G * cross-section * circumference (N); Newton converges to 1e-9 of it
        volume = float(self.solid.W.sum())
        volume = mpi.allreduce(volume) if comm.getSize() > 1 else volume
        cross = volume / (2 * np.pi * X[:, 0].mean() if axisym else depth)
        circ = 2 * np.pi * X[:, 0].mean() if axisym else depth
        self.force_scale = material.shear_modulus * cross * circ
        self._full_solid = None
        # plane strain, round section: rolling is a free mode of steps 1-2, held by a pure
        # couple of stiffness G A R^2 (sealts.solid.rolling); the same measure of the
        # rolling angle, without the couple, for every model's messages
        from ..solid.rolling import RollingGauge, gauge_nodes, is_round
        loop = boundary_loop(mesh.conn)[:, 0]
        nodes = gauge_nodes(X, loop)
        r2 = float(((X[nodes] - X[nodes].mean(0)) ** 2).sum(1).mean())
        self.roll = RollingGauge(X, nodes, udofs, material.shear_modulus * cross * r2)
        if hold_rolling is None:
            hold_rolling = is_round(X, loop)
        self.gauge = self.roll if hold_rolling and not axisym else None

    def local_terms(self, boundary, stab=False, dofs=None, solid=None):
        """This rank's terms: its cells' solid, (its owned nodes' stabilisation), and on
        rank 0 the ``boundary`` terms (serial dofs) on its local vector."""
        dofs = dofs or self.dofs
        out = [solid or self.solid] + dofs.on_root(boundary)
        return out + [self.stab_local] if stab else out

    def full_solid(self):
        """The solid term over every cell in serial dofs (fields output, one rank)."""
        if self._full_solid is None:
            s = self.solid
            self._full_solid = SolidTerm(self.mesh.X, self.mesh.conn, self.material,
                                         self.axisym, udofs=self.udofs, heating=s.heating)
        return self._full_solid

    def rod_side_guard(self, side=None, groove=None, fold_hint=""):
        """The post-step guard of :mod:`sealts.contact.rod_side_guard` for this seal: the
        boundary nodes off the rod side may not pass into the rod by more than the asperity
        law's contact gap (h_mix of Eq. 44). ``side``: another layout's rod side (the
        stroke's, the hold's; default the model's, its rod moving in steps 1-2); ``groove``:
        the walls the rod side may be pressed into (default the model's); ``fold_hint``: the
        words a fold on the rod adds (:class:`RodSideGuard`)."""
        side = self.side if side is None else side
        groove = self.groove if groove is None else groove

        def note(u):
            if self.axisym:
                return self.off_hint
            u_ser = np.zeros(self.n)
            u_ser[self.udofs] = u[side.udofs]
            roll = np.degrees(self.roll.angle(u_ser))
            return (f"; the plane-strain section has rolled by {roll:.3g} degrees (without "
                    "hoop strain only friction holds a round section from rolling)"
                    + self.off_hint)

        return RodSideGuard(side, self.law.contact_gap, note, walls=groove.z_walls,
                            creases=self.self_contact is not None, fold_hint=fold_hint)

    def guards(self, side=None, groove=None, pressure=None, fold_hint=""):
        """The post-step guards of a run on this seal: with an extrusion gap the extrusion
        guard (:mod:`sealts.contact.extrusion_guard`) on ``groove`` (default the model's;
        ``pressure(t)`` the sealed pressure its message names), then the rod-side guard
        (:meth:`rod_side_guard`, with ``fold_hint``)."""
        groove = self.groove if groove is None else groove
        guard = self.rod_side_guard(side, groove, fold_hint)
        if groove.edge is None:
            return [guard]
        return [ExtrusionGuard(groove, self.extrusion_limit, guard.side, pressure), guard]

    def problem(self, n, terms, linesearch="basic", **kw):
        """A Problem of this seal's terms on its communicator: the basic line search (the
        residual norm is a poor merit function for a near-incompressible solid, see
        :class:`sealts.problem.Problem`) and Newton converged to NEWTON_ATOL of the force
        scale. ``linesearch``: another default line search (a steady solve without TS's
        step rejection behind it). ``kw``: prefix, constraints, fields, dofs."""
        return Problem(n, terms, comm=self.comm, linesearch=linesearch,
                       snes_atol=NEWTON_ATOL * self.force_scale, **kw)

    def walls(self):
        """The boundary terms of steps 1-2: rod, groove, the surface's own (and the rolling
        gauge)."""
        return ([self.rod, self.groove] + self.surface()
                + ([self.gauge] if self.gauge is not None else []))

    def surface(self, udofs=None):
        """The seal surface's terms against itself (its self-contact, if on) in the
        numbering ``udofs`` (nodes, 2; default the model's): every step's boundary terms
        take them."""
        if self.self_contact is None:
            return []
        return [self.self_contact if udofs is None else self.self_contact.on(udofs)]

    def rod_radius(self, t):
        """The rod's radius at pseudo-time t: moving in over [0, WALLS_FINAL] (mm)."""
        return self.r_rod0 + (self.r_rod_final - self.r_rod0) * ramp(t / WALLS_FINAL)

    def groove_radius(self, t):
        """The groove bottom's radius at pseudo-time t (mm)."""
        return self.r_g0 + (self.r_g_final - self.r_g0) * ramp(t / WALLS_FINAL)

    def node_contact_pressure(self, t, u):
        return node_contact_pressure(self.mesh.X.shape[0], self.groove, self.rod, t, u)

    def pressure_load(self, pressure, p_crit, back=None):
        """The fluid pressure ``pressure(t)`` (MPa) on the free surface, nothing wetted yet
        (:class:`sealts.solid.pressure.PressureLoad`), entering where it comes in through
        the rod clearance: at the pressure side's node nearest the rod. With ``back(t)``, a
        back pressure entering at the atmosphere side's node nearest the rod too
        (:class:`sealts.solid.fluid_loads.FluidLoads`).

        (The entry was the pressure side's most exposed node, its smallest z, until a back
        pressure came: a seal held against both walls has that node in the wall's contact,
        and the fluid at p_in = p_out then had no consistent front. Pushed off the wall by
        p_in alone, the seal settles to the same wetted set from either entry: the coarse
        O-ring at 1 MPa to 3e-9 mm.)"""
        from ..solid.fluid_loads import FluidLoads
        from ..solid.pressure import PressureLoad
        X, edges = self.mesh.X, self.mesh.edges

        def fluid(p, side, exit_):
            nodes = self.mesh.nodes(side)
            entry = nodes[np.argmin(X[nodes, 0])]     # the side's node nearest the rod
            load = PressureLoad(X, self.mesh.conn, p, self.axisym, entry, udofs=self.udofs,
                                p_crit=p_crit)
            load.mark_exit(edges[exit_])
            return load

        load = fluid(pressure, "pressure_side", "atmosphere_side")
        if back is None:
            return load
        return FluidLoads([load, fluid(back, "atmosphere_side", "pressure_side")])

    def pressure_resultant(self, load, t, u):
        """Total (radial, axial) force of the fluid pressure on the seal (N)."""
        F = load.forces(t, u)
        return float(F[:, 0].sum() + F[:, 2].sum()), float(F[:, 1].sum() + F[:, 3].sum())

    def contact_profile(self, t, u):
        """Along the rod side, by z: current axial position y (mm), gap h, contact pressure."""
        y = self.side.y(u)
        h = self.side.gap(t, u)
        p, _ = self.rod.pressure(t, u)
        return y, h, p

    def results(self, t, u, udot=None, quasi_static=True):
        """The contact's key numbers at (t, u). For the end of a quasi-static step
        (``quasi_static``) also whether u is a static equilibrium (``udot`` None) and, from
        ``udot`` (the state's rate where the final static solve failed), the viscous
        stabilisation's share of the rod load."""
        y, h, p = self.contact_profile(t, u)
        f_rod = self.rod.forces(t, u)
        total = float(f_rod.sum())
        circ = 2 * np.pi * self.r_rod_final if self.axisym else 1.0
        touching = p > 0.0
        width = float(y[touching].max() - y[touching].min()) if touching.sum() > 1 else 0.0
        out = {
            "contact_force_total": total,
            "contact_force_per_length": total / circ,
            "contact_width": width,
            "p_contact_max": float(p.max()),
            "y_at_p_contact_max": float(y[np.argmax(p)]),
            "h_min": float(h.min()),
            "groove_reactions": self.groove.reactions(t, u),
        }
        if self.groove.edge is not None:      # into the extrusion gap, mm
            out["extrusion"] = extrusion(self.groove, t, u)[0]
        if quasi_static:
            # the viscous stabilisation's force at the end, against the contact load it must
            # not carry (zero when the final static solve succeeded)
            stab = self.stab.forces(np.zeros(self.n) if udot is None else udot)
            out["stabilisation_share"] = float(np.abs(stab).max()
                                               / max(np.abs(f_rod).max(), 1e-300))
            out["static_equilibrium"] = udot is None
        if self.gauge is not None:
            out["rolling_angle_deg"] = float(np.degrees(self.gauge.angle(u)))
            out["rolling_gauge_torque"] = self.gauge.torque(u)
        return out


# the rod-side guard's hint for a rectangular ring with sharp corners, whose rod side ends
# FLANK up each side face: a ring that tilts further sets the next node of a side face on
# the rod
SHARP_CORNERS = (f"; the ring's corners are sharp (seal.corner_radius = 0): its rod side "
                 f"runs up its side faces by up to {FLANK:g} mm, and a side-face node beyond "
                 "reached the rod; with seal.corner_radius = 0.1 mm (say) the rounded corners belong to the "
                 "rod side and carry the film and the asperity contact")


def model_from_scene(scene, comm=None, refine=None):
    """Mesh (cached) and SealModel for a ``model = "seal"`` scene, distributed over comm
    (PETSc.COMM_WORLD by default); ``refine``: (points, h) to refine the mesh at
    (:mod:`sealts.mesh.contact_edges`)."""
    from ..mesh.seal_mesh import ORing, RectangularRing, build_mesh
    from ..solid.term import Hyperelastic
    sl, gr, m, mat = scene.seal, scene.groove, scene.mesh, scene.material
    z0 = 0.0  # the groove is centred on z = 0
    if sl.shape == "file":
        mesh = _file_mesh(sl.mesh_file, m.cache, scene.rod.radius, gr)
    else:
        if sl.shape == "oring":
            shape = ORing(sl.d1, sl.d2, z0)
        else:
            shape = RectangularRing(0.5 * sl.inner_diameter,
                                    0.5 * sl.inner_diameter + sl.height,
                                    z0 - 0.5 * sl.width, z0 + 0.5 * sl.width,
                                    sl.corner_radius)
        mesh = build_mesh(shape, m.h_contact, m.h_bulk, m.grading_distance, m.cache,
                          mirror=m.symmetric, layer_depth=m.layer_depth, refine=refine)
    material = Hyperelastic(mat.c10, mat.d1, mat.alpha_th, mat.temperature_rise, mat.c01)
    return SealModel(mesh, material, scene.rod.radius, 0.5 * gr.diameter,
                     (z0 - 0.5 * gr.width, z0 + 0.5 * gr.width),
                     axisym=sl.symmetry == "axisymmetric",
                     law=law_from_scene(scene.asperity, material), penalty=scene.mount.penalty,
                     stabilisation=scene.mount.stabilisation,
                     corner_radius=gr.corner_radius, comm=comm, clearance=gr.clearance,
                     edge_radius=gr.edge_radius, extrusion_limit=gr.extrusion_limit,
                     off_hint=SHARP_CORNERS if sl.shape == "rectangle"
                     and sl.corner_radius == 0.0 else "",
                     self_contact=self_contact_on(scene))


def self_contact_on(scene):
    """Whether the scene's seal has its self-contact: ``seal.self_contact`` on, or auto and
    the sealed pressure (``fluid.p_in``, or a hold's ``hold.p_end``) or the back pressure at
    least SELF_CONTACT_FROM. One flag for the whole run: steps 1-2 take it too, so the
    state cache's key holds it (:func:`sealts.steps.state_cache.inputs`)."""
    mode = scene.seal.self_contact
    if mode != "auto":
        return mode == "on"
    return max(scene.fluid.p_in, scene.fluid.p_out, scene.hold.p_end) >= SELF_CONTACT_FROM


def _file_mesh(path, cache, r_rod, groove):
    """A user's mesh file, centred axially in the groove; its geometry checked against the
    rod and groove like the built-in shapes' (one-line SceneError naming the file)."""
    from dataclasses import replace

    from ..mesh.mesh_file import MeshFileError, read_mesh_file
    from ..scene import SceneError
    try:
        mesh = read_mesh_file(path, cache)
    except MeshFileError as e:
        raise SceneError(f"seal.mesh_file: {e}") from None
    X = mesh.X.copy()
    X[:, 1] -= 0.5 * (X[:, 1].min() + X[:, 1].max())
    r_in, r_out, width = X[:, 0].min(), X[:, 0].max(), np.ptp(X[:, 1])
    space = 0.5 * groove.diameter - r_rod
    if width >= groove.width:
        raise SceneError(f"seal.mesh_file: the seal is {width:g} mm wide, not narrower than "
                         f"groove.width = {groove.width:g} mm")
    if r_in <= 0.0 or r_out <= r_rod or r_in >= 0.5 * groove.diameter:
        raise SceneError(f"seal.mesh_file: the seal (r = {r_in:g} .. {r_out:g} mm) does not "
                         "lie between rod and groove bottom")
    if r_out - r_in > 1.35 * space:
        raise SceneError(f"seal.mesh_file: radial size {r_out - r_in:g} mm squeezed into "
                         f"{space:g} mm (over 35 % squeeze) cannot be mounted")
    return replace(mesh, X=X)
