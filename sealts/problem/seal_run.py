"""Seal scenes: the solid seal between a rigid rod and groove (mounting, pressurisation).

Mounting (paper Section 3.1.1, step 1): long-term material, frictionless. The groove bottom
starts just clear of the seal and moves to its final radius over the pseudo-time 0..1, like
ABAQUS's interference fit resolved gradually; the rod stays at its radius (the O-ring's
inner diameter may be smaller than the rod's: then the rod starts inside and grows). A hold
until t = t_hold lets the viscous stabilisation die out; the run reports its residual share.

Pressurisation (step 2), when the scene's fluid.p_in is not zero: p_in ramps on the wetted
free surface over the next pseudo-time unit and holds for as long again (see
:mod:`sealts.solid.pressure` for the pressure penetration).
"""
import time

import numpy as np

from ..contact.rigid import (GrooveContact, RodContact, node_contact_pressure,
                             tributary_lengths)
from ..mesh.partition import Partition
from ..problem import Problem, SolveError
from ..solid.stabilisation import ViscousStabilisation
from ..solid.term import SolidTerm


def ramp(t):
    """Smooth 0 -> 1 over t in [0, 1] (C1), then 1."""
    s = min(max(t, 0.0), 1.0)
    return s * s * (3.0 - 2.0 * s)


class SealModel:
    """Seal mesh + material + rod and groove, as Problem terms.

    The mesh is distributed over ``comm`` (:class:`sealts.mesh.partition.Partition`): each
    rank's ``solid`` covers its own cells, in its local dofs. ``rod``, ``groove``, ``stab``
    (and the pressure ``load``) are written in serial dofs and cover the whole boundary
    (mesh): every rank evaluates them on the gathered state for outputs and front updates,
    and rank 0 alone assembles the rod, groove and pressure terms (``local_terms``). The
    stabilisation is assembled by each rank over the nodes it owns. Problems run on the
    model's communicator; the ``comm`` arguments of its methods are kept for callers.

    ``hold_rolling``: hold the rolling angle with ``gauge`` (:mod:`sealts.solid.rolling`) in
    steps 1-2 (and the hold); by default on a plane-strain section whose boundary is a
    circle, which nothing else holds from rolling between frictionless walls."""

    def __init__(self, mesh, material, rod_radius, groove_radius, groove_walls, axisym=True,
                 h_mix=7e-4, p_mix=15.0, penalty=1e4, stabilisation=1e-3, depth=1.0,
                 corner_radius=0.0, comm=None, hold_rolling=None):
        from petsc4py import PETSc

        from ..solid.pressure import boundary_loop
        self.mesh, self.material, self.axisym = mesh, material, axisym
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
        self.rod = RodContact(X, chain, self.rod_radius, area, h_mix, p_mix, udofs=udofs)
        bnd = mesh.boundary_nodes()
        trib = tributary_lengths(X, np.concatenate(list(mesh.edges.values())), X.shape[0])
        self.groove = GrooveContact(X, bnd, trib, axisym, self.groove_radius,
                                    lambda t: groove_walls, penalty=penalty, depth=depth,
                                    corner_radius=corner_radius, udofs=udofs)
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
        # boundary nodes the rod does not act on (only the rod side carries contact and film)
        self.off_rod = np.setdiff1d(bnd, chain)

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

    def check_rod_side(self, t, u, udofs=None, r_rod=None):
        """SolveError (one line) when a boundary node off the rod side is more than h_mix
        inside the rod: the rod side, which alone feels the rod (and carries the film), no
        longer covers the contact, and nothing stops the others from passing through; a
        run would only crawl on (dt ~ 1e-7). ``udofs``, ``r_rod``: another layout's (the
        stroke's)."""
        udofs = self.udofs if udofs is None else udofs
        r_rod = self.rod_radius(t) if r_rod is None else r_rod
        off = self.off_rod
        depth = r_rod - (self.mesh.X[off, 0] + u[udofs[off, 0]])
        k = int(np.argmax(depth))
        if depth[k] <= self.rod.h_mix:
            return
        u_ser = np.zeros(self.n)
        u_ser[self.udofs] = u[udofs]
        roll = np.degrees(self.roll.angle(u_ser))
        why = ("" if self.axisym else
               f"; the plane-strain section has rolled by {roll:.3g} degrees (without hoop "
               "strain only friction holds a round section from rolling)")
        raise SolveError(f"at t = {t:.6g} node {off[k]} off the rod side is "
                         f"{depth[k] * 1e3:.3g} um inside the rod: the rod side no longer "
                         f"covers the contact{why}")

    def walls(self):
        """The boundary terms of steps 1-2: rod, groove (and the rolling gauge)."""
        return [self.rod, self.groove] + ([self.gauge] if self.gauge is not None else [])

    def rod_radius(self, t):
        return self.r_rod0 + (self.r_rod_final - self.r_rod0) * ramp(t)

    def groove_radius(self, t):
        return self.r_g0 + (self.r_g_final - self.r_g0) * ramp(t)

    def _quasi_static(self, extra, u0, t0, t_hold, dt0, stop, comm, on_step):
        """Stabilised pseudo-time run from t0 to t_hold, then the static equilibrium itself.

        The pseudo-time path needs no accuracy of its own, so the TS tolerances default to
        rtol 1e-3, atol 1e-4 mm (-ts_rtol wins); measured on the coarse O-ring mount: 1081
        steps at the DAE default 1e-6, 72 at 1e-3, the same mounted state to 1e-7. The final
        Newton solve drops the stabilisation (in the mounted state the walls hold every
        mode); if it fails, the stabilised state stands and its share is reported, with
        du/dt over the last accepted step.
        """
        atol = 1e-9 * self.force_scale
        comm = self.comm
        problem = Problem(self.n, self.local_terms(self.walls() + extra, stab=True),
                          comm=comm, linesearch="basic", snes_atol=atol, dofs=self.dofs)
        hist = []

        def record(ts, step, t, u):
            self.check_rod_side(t, u)
            hist[:] = hist[-1:] + [(t, u)]
            if on_step is not None:
                on_step(ts, step, t, u)

        u = problem.transient(u0, t0, t_hold, dt0, stops=(stop,), on_step=record,
                              rtol=1e-3, atol=1e-4)
        self.problem = problem
        try:
            u = self._static(extra, u, t_hold, comm)
            self.udot, self.static = np.zeros(self.n), True
        except SolveError:
            (ta, ua), (tb, ub) = hist[-2], hist[-1]
            self.udot, self.static = (ub - ua) / (tb - ta), False
        return u

    def _static(self, extra, u, t, comm):
        """Newton from u on the unstabilised equilibrium at t (raises SolveError); its
        iterations count towards ``self.problem``'s."""
        static = Problem(self.n, self.local_terms(self.walls() + extra),
                         comm=self.comm, linesearch="basic",
                         snes_atol=1e-9 * self.force_scale, prefix="static_", dofs=self.dofs)
        static.max_it = 10
        try:
            return static.solve_steady(u, t)
        finally:
            self.problem.counters.newton += static.counters.newton
            self.problem.counters.linear += static.counters.linear

    def mount(self, t_hold=2.0, dt0=0.02, comm=None, on_step=None):
        """Step 1: the groove bottom (and a rod smaller than the seal) move in over the
        pseudo-time 0..1, then hold until t_hold."""
        return self._quasi_static([], np.zeros(self.n), 0.0, t_hold, dt0, 1.0, comm, on_step)

    def node_contact_pressure(self, t, u):
        return node_contact_pressure(self.mesh.X.shape[0], self.groove, self.rod, t, u)

    def pressurise(self, u0, p_in, t0=2.0, t_hold=4.0, dt0=0.02, comm=None, on_step=None,
                   p_crit=0.1):
        """Step 2 of the paper: p_in ramped on the wetted free surface from t0 to t0 + 1,
        held to t_hold, from the mounted state u0; pressure penetration updated after every
        accepted step, advancing only; then the front is settled at p_in
        (``settle_front``). Long-term material, frictionless (the film comes with the
        coupling)."""
        self.pressure_load(p_in, t0, p_crit)
        self.load.update(self.node_contact_pressure(t0, u0), 0.0)

        def update_front(ts, step, t, u):
            self.load.update(self.node_contact_pressure(t, u), self.load.pressure(t),
                             recede=False)
            if on_step is not None:
                on_step(ts, step, t, u)

        u = self._quasi_static([self.load], u0, t0, t_hold, dt0, t0 + 1.0, comm,
                               update_front)
        return self.settle_front(self.load, u, t_hold, dt0, comm)

    def pressure_load(self, p_in, t0, p_crit):
        """``self.load``: p_in ramped from t0 over one pseudo-time unit on the free surface,
        entering at the pressure side's most exposed node (nothing wetted yet)."""
        from ..solid.pressure import PressureLoad
        chain_p = self.mesh.nodes("pressure_side")
        start = chain_p[np.argmin(self.mesh.X[chain_p, 1])]
        self.load = PressureLoad(self.mesh.X, self.mesh.conn,
                                 lambda t: p_in * ramp(t - t0), self.axisym, start,
                                 udofs=self.udofs, p_crit=p_crit)
        return self.load

    def settle_front(self, load, u, t, dt0, comm, tol=1e-4, max_updates=30):
        """Front update and static solve in turn until the front moves by less than ``tol``
        edges; the state keeps the front it was solved with. A static solve that fails
        falls back to the stabilised driver (pseudo-time t..t+1; rod, groove and pressure
        are final there). Sets ``front_settled`` (edges the front would still move, for the
        summary) and ``front_updates``."""
        for k in range(max_updates):
            kept = list(load.reach)
            moved = load.update(self.node_contact_pressure(t, u), load.pressure(t))
            if moved < tol:
                load.set_reach(kept)
                break
            try:
                u = self._static([load], u, t, comm)
                self.udot, self.static = np.zeros(self.n), True
            except SolveError:
                counters = self.problem.counters
                u = self._quasi_static([load], u, t, t + 1.0, dt0, t + 0.5, comm, None)
                for f in ("steps", "rejected", "newton", "linear"):
                    setattr(counters, f, getattr(counters, f) + getattr(self.problem.counters, f))
                self.problem.counters = counters
        self.front_settled, self.front_updates = moved, k
        return u

    def pressure_resultant(self, t, u):
        """Total (radial, axial) force of the fluid pressure on the seal (N)."""
        F = self.load.forces(t, u)
        return float(F[:, 0].sum() + F[:, 2].sum()), float(F[:, 1].sum() + F[:, 3].sum())

    def contact_profile(self, t, u):
        """Along the rod side, by z: current axial position y (mm), gap h, contact pressure."""
        c = self.mesh.chain("rod_side")
        y = self.mesh.X[c, 1] + u[self.udofs[c, 1]]
        h = self.rod.gap(t, u)
        p, _ = self.rod.pressure(t, u)
        return y, h, p

    def results(self, t, u):
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
        # the viscous stabilisation's force at the end, against the contact load it must not
        # carry (zero when the final static solve succeeded)
        stab = self.stab.forces(self.udot)
        out["stabilisation_share"] = float(np.abs(stab).max()
                                           / max(np.abs(f_rod).max(), 1e-300))
        out["static_equilibrium"] = self.static
        if self.gauge is not None:
            out["rolling_angle_deg"] = float(np.degrees(self.gauge.angle(u)))
            out["rolling_gauge_torque"] = self.gauge.torque(u)
        return out


def model_from_scene(scene, comm=None):
    """Mesh (cached) and SealModel for a ``model = "seal"`` scene, distributed over comm
    (PETSc.COMM_WORLD by default)."""
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
                                    z0 - 0.5 * sl.width, z0 + 0.5 * sl.width)
        mesh = build_mesh(shape, m.h_contact, m.h_bulk, m.grading_distance, m.cache,
                          mirror=m.symmetric)
    material = Hyperelastic(mat.c10, mat.d1, mat.alpha_th, mat.temperature_rise, mat.c01)
    return SealModel(mesh, material, scene.rod.radius, 0.5 * gr.diameter,
                     (z0 - 0.5 * gr.width, z0 + 0.5 * gr.width),
                     axisym=sl.symmetry == "axisymmetric", h_mix=scene.asperity.h_mix,
                     p_mix=scene.asperity.p_mix, penalty=scene.mount.penalty,
                     stabilisation=scene.mount.stabilisation,
                     corner_radius=gr.corner_radius, comm=comm)


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


def element_stresses(model, u, solid=None, prony=None):
    """Element-mean Cauchy stress (rr, zz, tt, rz), von Mises and pressure (MPa) of the
    long-term material (``model.full_solid()``), or of ``solid`` plus the Prony stress of
    ``prony`` (:meth:`sealts.solid.viscoelastic.PronyTerm.viscous_cauchy`) at the state u
    of their layout."""
    from ..solid.neo_hooke import cauchy_stress
    solid = model.full_solid() if solid is None else solid
    f, P, p_el, _ = solid.state(u)
    s = cauchy_stress(f.reshape(-1, 5), P.reshape(-1, 5), np.repeat(p_el, 4))
    s = s.reshape(-1, 4, 4)
    if prony is not None:
        s = s + prony.viscous_cauchy(u)
    s = s.mean(1)
    rr, zz, tt, rz = s.T
    mises = np.sqrt(0.5 * ((rr - zz) ** 2 + (zz - tt) ** 2 + (tt - rr) ** 2) + 3 * rz**2)
    return s, mises, -(rr + zz + tt) / 3.0


def write_fields(path, model, u):
    """Deformed-state fields as XDMF + HDF5 (ParaView): displacement on nodes, stresses on
    cells, on the reference mesh (apply ParaView's 'Warp By Vector' to see the deformation)."""
    import meshio
    s, mises, pressure = element_stresses(model, u)
    disp = np.zeros((model.mesh.X.shape[0], 3))
    disp[:, :2] = u[model.udofs]
    points = np.zeros((model.mesh.X.shape[0], 3))
    points[:, :2] = model.mesh.X
    meshio.write(path, meshio.Mesh(
        points, [("quad", model.mesh.conn)], point_data={"displacement": disp},
        cell_data={"von_mises": [mises], "pressure": [pressure], "sigma_rr": [s[:, 0]],
                   "sigma_zz": [s[:, 1]], "sigma_tt": [s[:, 2]], "sigma_rz": [s[:, 3]]}))


def run_seal(scene, writer, comm):
    """Mount the seal (``model = "seal"``) and write contact profile, fields and summary."""
    from .film_run import Progress
    t_wall = time.perf_counter()
    say = Progress(comm, scene.output.progress)
    model = model_from_scene(scene, comm)
    cells = model.partition.cells_per_rank
    say(f"mesh: {model.mesh.X.shape[0]} nodes, {model.mesh.conn.shape[0]} quads, "
        f"{model.n} unknowns" + (f"; cells per rank {cells}" if len(cells) > 1 else ""),
        force=True)
    def on_step(ts, step, t, u):
        h = model.rod.gap(t, u)
        say(f"step {step:4d}  t = {t:.4g}  dt = {ts.getTimeStep():.3g}  "
            f"rod force = {model.rod.forces(t, u).sum():.4g} N  min h = {h.min() * 1e3:.4g} um")

    p_in = scene.fluid.p_in
    if scene.start.state:
        u, res = _restart(model, scene, say)
        counters = []
    else:
        u, res, counters = _mount_and_pressurise(model, scene, writer, comm, say, on_step)
        state = {"u": u[model.udofs], "X": model.mesh.X}
        attrs = {"p_in": p_in, "scene": scene.name, "source": scene.source}
        if p_in != 0.0:
            state["front_reach"] = np.asarray(model.load.reach, float)
            attrs["p_crit"] = model.load.p_crit
        writer.state(state, attrs)
    hold = scene.hold
    hold_info = stroke_info = None
    if hold.p_end != 0.0:
        u, res, hold_info, hold_counters = _run_hold(model, u, scene, writer, comm, say, res)
        counters.append(hold_counters)
    if scene.stroke.velocity != "none":
        from .stroke_run import run_stroke
        u, stroke_info, stroke_counters = run_stroke(model, u, scene, writer, comm, say)
        counters.append(stroke_counters)
    if writer.root:
        write_fields(str(writer.dir / "fields.xdmf"), model, u)
    from .problem import Counters
    c = Counters(*[sum(getattr(k, f) for k in counters)
                   for f in ("steps", "rejected", "newton", "linear", "residuals", "jacobians")])
    summary = {
        "scene": scene.name, "source": scene.source,
        "analysis": ("restart" if scene.start.state
                     else "mount" if p_in == 0.0 else "mount + pressurise")
        + (" + viscoelastic hold" if hold_info else "") + (" + stroke" if stroke_info else ""),
        "nodes": int(model.mesh.X.shape[0]), "elements": int(model.mesh.conn.shape[0]),
        "unknowns": model.n, "ranks": comm.getSize(),
        "cells_per_rank": model.partition.cells_per_rank,
        "wall_time_s": time.perf_counter() - t_wall,
        "steps_accepted": c.steps, "steps_rejected": c.rejected,
        "newton_iterations": c.newton, "linear_iterations": c.linear,
        "results": res,
        "units": {"length": "mm", "pressure": "MPa", "force": "N"},
    }
    if hold_info:
        summary["hold"] = hold_info
    if stroke_info:
        summary["stroke"] = stroke_info
    writer.summary(summary)
    return summary


def _mount_and_pressurise(model, scene, writer, comm, say, on_step):
    """Steps 1-2 of the paper: (u, results, counters)."""
    mount = scene.mount
    u = model.mount(t_hold=mount.t_hold, dt0=mount.dt, comm=comm, on_step=on_step)
    t_end = mount.t_hold
    res = model.results(t_end, u)
    y, h, p = model.contact_profile(t_end, u)
    writer.profile(t_end, {"y": y, "h": h, "p_contact": p})
    counters = [model.problem.counters]
    p_in = scene.fluid.p_in
    if p_in != 0.0:
        say(f"mounted: rod force {res['contact_force_total']:.6g} N; pressurising to "
            f"{p_in:g} MPa", force=True)
        t0, t_end = t_end, 2 * t_end
        u = model.pressurise(u, p_in, t0=t0, t_hold=t_end, dt0=mount.dt, comm=comm,
                             on_step=on_step, p_crit=scene.fluid.p_crit)
        counters.append(model.problem.counters)
        mounted, res = res, model.results(t_end, u)
        res["mounted"] = mounted
        fr, fz = model.pressure_resultant(t_end, u)
        res["pressure_force_radial"], res["pressure_force_axial"] = fr, fz
        res["wetted_boundary_fraction"] = float(model.load.wet.mean())
        # edges (fractions summed) the front would still move from the final state: 0 when
        # front and equilibrium agree
        res["front_change_edges"] = model.front_settled
        res["front_updates"] = model.front_updates
        if model.front_settled >= 1e-4:
            say(f"warning: the pressure-penetration front did not settle in "
                f"{model.front_updates + 1} updates (one more would move it "
                f"{model.front_settled:.3g} edges); try a larger fluid.p_crit", force=True)
        y, h, p = model.contact_profile(t_end, u)
        writer.profile(t_end, {"y": y, "h": h, "p_contact": p})
    return u, res, counters


def _restart(model, scene, say):
    """The state of an earlier run's steps 1-2 (``start.state``): (u, results). The mesh
    and p_in must be the ones it was saved with (one-line SceneError otherwise)."""
    import h5py

    from ..scene import SceneError
    path = scene.start.state
    try:
        with h5py.File(path, "r") as f:
            X, un = f["X"][()], f["u"][()]
            reach = f["front_reach"][()] if "front_reach" in f else None
            attrs = dict(f.attrs)
    except (OSError, KeyError) as e:
        raise SceneError(f"start.state: {path} is not a sealts state file ({e})") from None
    if X.shape != model.mesh.X.shape or not np.allclose(X, model.mesh.X, atol=1e-12):
        raise SceneError(f"start.state: {path} was saved for another mesh "
                         f"({X.shape[0]} nodes; this scene's has {model.mesh.X.shape[0]})")
    p_in = scene.fluid.p_in
    if float(attrs.get("p_in", 0.0)) != p_in:
        raise SceneError(f"start.state: {path} was pressurised to {attrs.get('p_in'):g} MPa, "
                         f"not fluid.p_in = {p_in:g} MPa")
    u = np.zeros(model.n)
    u[model.udofs] = un
    t = 2 * scene.mount.t_hold if p_in != 0.0 else scene.mount.t_hold
    if p_in != 0.0:
        model.pressure_load(p_in, scene.mount.t_hold, float(attrs["p_crit"]))
        model.load.set_reach(reach)
    model.static, model.udot = True, np.zeros(model.n)
    say(f"restarted from {path} ({attrs.get('scene', '?')}): steps 1-2 not repeated",
        force=True)
    return u, model.results(t, u)


def _run_hold(model, u, scene, writer, comm, say, res_pressurised):
    """Step 3: the viscoelastic pressure step and hold (:mod:`sealts.problem.hold_run`)."""
    from .hold_run import HoldStep
    hold, ve = scene.hold, scene.viscoelastic
    step = HoldStep(model, u, scene.fluid.p_in, hold.p_end, hold.t_ramp, ve, hold.t_end,
                    comm=comm)
    say(step.classes.describe(step.series, step.shift), force=True)
    say(f"hold: {scene.fluid.p_in:g} -> {hold.p_end:g} MPa over {hold.t_ramp:g} s, held to "
        f"{hold.t_end:g} s; {step.layout.n} unknowns ({len(step.classes.active)} active "
        f"Prony terms x 16 per cell)", force=True)
    lay = step.layout

    def displacement(U):
        return U[lay.udofs].ravel()

    def on_step(ts, k, t, U):
        ud = displacement(U)
        y, h, p = model.contact_profile(t, ud)
        force = float(step.rod.forces(t, ud).sum())
        writer.series({"t": t, "dt": ts.getTimeStep(), "p_sealed": step.load.pressure(t),
                       "rod_force": force, "p_contact_max": float(p.max()),
                       "h_min": float(h.min()), "wetted": float(step.load.wet.mean()),
                       "newton": ts.getSNESIterations()})
        say(f"hold step {k:4d}  t = {t:.4g} s  dt = {ts.getTimeStep():.3g}  "
            f"rod force = {force:.5g} N  min h = {h.min() * 1e3:.4g} um")

    def on_stop(t, U):
        y, h, p = model.contact_profile(t, displacement(U))
        writer.profile(t, {"y": y, "h": h, "p_contact": p}, name="hold_profiles.csv")

    t_end = hold.t_end
    stops = [t for t in 10.0 ** np.arange(-6, 13) if hold.t_ramp <= t < t_end]
    stops += [t for t in ve.temperature_times if 0.0 < t < t_end]   # kinks of A(theta(t))
    U = step.run(t_end, hold.dt, hold.rtol, stops=stops, on_step=on_step, on_stop=on_stop)
    u = displacement(U)
    res = model.results(t_end, u)
    res["pressurised"] = res_pressurised
    c = step.problem.counters
    info = {
        "p_from": scene.fluid.p_in, "p_to": hold.p_end, "t_end": t_end,
        "wlf_shift": step.shift,            # the largest over the hold
        "prony_active_tau": [float(step.shift * step.series.tau[i])
                             for i in step.classes.active],
        "prony_relaxed": len(step.classes.relaxed), "prony_frozen": len(step.classes.frozen),
        "prony_error_bound": step.classes.error_bound,
        "unknowns": int(lay.n), "steps_accepted": c.steps, "steps_rejected": c.rejected,
        "newton_iterations": c.newton, "linear_iterations": c.linear,
        "long_term_check": step.long_term_check(U, t_end),
    }
    return u, res, info, c
