"""The DAE of the transient stroke with the film (step 3 with ``[stroke] velocity``).

From the pressurised long-term state of steps 1-2 (dry, pressure penetration settled), one
monolithic DAE for seal plus film (paper Section 3.1.1, step 3):

* unknowns: the displacements and the film pressure on the ``rod_side`` vertices, fields of
  one Layout (:mod:`sealts.mesh.layout`);
* terms: the hyperelastic seal (long-term material), the rod as the asperity contact
  (Eq. 44-45) at its final radius, the frictionless groove, the fluid pressure on the free
  surfaces the step-2 front wetted (the rod side excluded: the film carries it), and
  :class:`sealts.film.seal_film.SealFilmTerm`: the transient Reynolds film (Eq. 13) on the
  deforming rod side, with squeeze from U', its radial and surface-normal load, and the fluid
  shear (Eq. 29-34), p_in at the pressure-side end of the film and p_out at the other;
  with ``film.scheme = "paper"`` the film is instead
  :class:`sealts.film.seal_paper_film.SealPaperFilmTerm`, the paper's integration-constant
  scheme (Eq. 15-28, weight ``film.alpha``) on the same chain with the same loads: two more
  unknowns, its integration constants c0 and qd (the flow at y0, in place of y0, see there),
  appended after V_in, V_out (``xdofs``), and its flows (Eq. 40) in the leakage rows
  (:class:`sealts.film.seal_paper_film.PaperLeakageTerm`);
* the start: the film pressures are solved with the seal held, then seal and film together
  at t = 0 (the hydrostatic film when v(0) = 0);
* the rod's axial velocity v(t) (:mod:`sealts.contact.rod_motion`) drives the film; TS
  steps the DAE with adaptive BDF and hits the law's kinks, reversals and output times.

Its outputs (series, profiles, fields) are observers of the stroke step
(:mod:`sealts.steps.stroke`).

Leakage: Q_in enters the film at the pressure side, Q_out leaves it at the atmosphere side
(Eq. 41); V_in and V_out (Eq. 42) are two more unknowns, dV/dt = Q
(:class:`sealts.film.seal_film.LeakageTerm`), so TS integrates them with the film and
V_in - V_out is the film's growth. The friction work W (N mm, the rod's power against the
fluid shear and the rod friction, :class:`sealts.contact.friction_work.FrictionWork`) is
one more, after them. The numbering (``model.partition.numbering``) places these scalars
after the Section's fields.

* solid friction (``stroke.friction``): mu_s p_s on the rod's asperity contact and
  ``groove.mu`` times the wall pressure on the groove's bottom, side walls and corner arcs
  (without it the rod's friction rolls the O-ring in its frictionless groove), both the
  paper's elastic slip with gamma_crit. Their history is, by default (``stroke.
  friction_history = "state"``), TS state with a viscoplastic return past gamma_crit:
  :class:`sealts.contact.slip_state_friction.SlipStateFriction` (the ``rod_slip`` field)
  and :class:`sealts.contact.groove_slip_state.GrooveStateFriction` (the
  ``groove_anchor`` field); with ``"anchors"`` :class:`sealts.contact.friction.RodFriction`
  and :class:`sealts.contact.groove_friction.GrooveFriction`, whose post-step hooks move
  their anchors after every accepted step (the paper's return mapping, outside the error
  estimate; the series' ``groove_slide`` is the slip the walls' hook took off a wall).
  ``friction_groove`` in the series is the walls' axial friction force on the seal.

* viscous stabilisation (``stroke.stabilisation``, c in MPa s/mm^2, 0 by default):
  :class:`sealts.solid.stabilisation.ViscousStabilisation`, F += c V_i u_i' on every
  node's displacement rows (V_i its lumped volume), each rank over the nodes it owns. The
  quasi-static seal has no rate term of its own: where its equilibrium path folds (the
  O-ring's outlet flank peeling off the rod, a stick-slide snap at 10 MPa), the DAE's
  solution runs away in finite time and no step is small enough. The stabilisation gives
  the snap a finite speed. Its force c V_i u_i' is absolute, so it is not negligible where
  the seal's own loads are small or it drifts as a whole (the rigid-limit scene: 2 % of
  the film load); hence not from the start by default, but once the seal has snapped
  (``stroke.snap_stabilisation``, :class:`sealts.solid.stabilisation.SnapStabilisation`:
  the stroke step goes back to its last stop and on with c from there), with its largest
  share of the normal load reported as ``stabilisation_share`` (benchmarks/stress.md has
  the answers' independence of c at 10 MPa).

* error control: the local error in the max norm over the unknowns (``Problem.ts_defaults``,
  docs/design.md); each unknown's tolerance in its own unit, the leakage volumes' absolute
  (``StrokeProblem.tolerances``).

* viscoelastic (``viscoelastic.prony``): the Prony terms of the hold
  (:class:`sealts.solid.viscoelastic_solid.ViscoelasticSolid`), classified over
  [viscoelastic.t_min, stroke.t_end], from a relaxed start: the start is solved with the
  long-term material, then every H_i = S_iso(u) and the frozen terms' stress is set there
  (paper step 3).

* dry (``stroke.film = false``): no film and no leakage unknowns; the rod side keeps the
  pressure penetration of step 2, and the asperity contact carries the rod's whole load.

* the pressure-penetration fronts (``stroke.front = "moving"``, the default):
  :class:`sealts.solid.moving_front.MovingFront` moves them to where the seal's traction
  puts them at located TS events, whenever that target drifts more than
  ``stroke.front_tolerance`` edges from them; ``"kept"`` leaves them where steps 1-2 did
  (the series' ``front_drift`` then says how far the traction would move them).
"""
from collections import deque

import numpy as np

from ..contact.extrusion_guard import extrusion
from ..contact.friction import RodFriction
from ..contact.friction_work import FrictionWork
from ..contact.groove_friction import GrooveFriction
from ..contact.groove_slip_state import GrooveStateFriction
from ..contact.rigid import GrooveContact, RodContact, node_contact_pressure, tributary_lengths
from ..contact.rod_motion import motion_from_scene
from ..contact.slip_state_friction import SlipStateFriction
from ..core import Constraints, Observer, StepTooSmall
from ..film.odd_even import ODD_EVEN_STEPS, ODD_EVEN_WARN, odd_even, odd_even_note
from ..film.seal_film import LeakageTerm, SealFilmTerm
from ..film.seal_paper_film import PaperLeakageTerm, SealPaperFilmTerm
from ..solid.moving_front import MovingFront
from ..solid.pressure import front_drift, settle
from ..solid.stabilisation import SnapStabilisation
from ..solid.term import SolidTerm
from ..solid.viscoelastic_solid import ViscoelasticSolid
from .film_model import flow_factors_of
from .problem import Problem

# Newton iterations of the stroke's start (one steady solve, nothing behind it to retry
# smaller): the film replaces step 2's pressure load on the rod side, and at 35 MPa on the
# shipped mesh the backtracking line search cuts most steps that would invert the
# micrometre elements at the contact's edges; that start converges, but after more than
# PETSc's 50 (benchmarks/stress.md). An iteration is one factorisation: the limit costs
# only a start that would otherwise fail.
START_MAX_IT = 200

# What a fold on the rod adds in a stroke with the rod's friction and the long-term
# (hyperelastic) material: the friction can buckle the seal's surface where mu_s p nears
# the long-term shear modulus, the rubber's softest; at stroke rates the viscoelastic
# rubber is several times stiffer (README, "Operating limits")
FOLD_HINT = ("; where the rod's friction (asperity.mu_s times the contact pressure) nears "
             "the rubber's long-term shear modulus, its softest, it buckles the seal's "
             "surface: the rate-dependent stiffness ([viscoelastic] prony) or less friction "
             "holds it (README, \"Operating limits\")")


class OddEvenWatch(Observer):
    """The film gap's odd-even indicator of each accepted state into its stroke's
    ``odd_even_recent``, computed once per state: a stall's message names the mode from
    them, the stroke step's series column reads the last one."""

    def __init__(self, stroke):
        self.stroke = stroke

    def accepted(self, t, u, info):
        st = self.stroke
        h = st.side.gap(t, u)
        st.odd_even_recent.append((odd_even(st.side.y(u), h, st.film.h_floor,
                                            st.rod.law.contact_gap), t))


class StrokeProblem:
    """The coupled seal + film DAE of the stroke, built on a pressurised SealModel, with the
    front ``load`` of step 2 (None: unpressurised)."""

    def __init__(self, model, u0, scene, load=None):
        self.model, self.scene = model, scene
        self.motion = motion_from_scene(scene.stroke)
        mesh, X = model.mesh, model.mesh.X
        ve = scene.viscoelastic
        self.viscoelastic = None
        if ve.prony != "none":
            self.viscoelastic = ves = ViscoelasticSolid(model, ve, scene.stroke.t_end)
        prony_size = self.viscoelastic.prony_size if self.viscoelastic else 0
        wet = scene.stroke.film
        fl, fm = scene.fluid, scene.film
        # the global scalars: the leakage volumes, and the paper scheme's c0 and qd
        scalars = ()
        if wet:
            scalars = ("V_in", "V_out") + (("c0", "qd") if fm.scheme == "paper" else ())
        # the model's distributed mesh with this step's fields: each rank assembles the
        # solid on its own cells, rank 0 the terms along the boundary (in serial dofs)
        st = scene.stroke
        rod_friction = st.friction and scene.asperity.mu_s > 0.0
        slip_state = rod_friction and st.friction_history == "state"
        wall_friction = st.friction and scene.groove.mu > 0.0
        wall_state = wall_friction and st.friction_history == "state"
        if wet or rod_friction:
            scalars += ("W",)                    # the friction work, last
        self.layout = lay = model.partition.numbering(prony=prony_size, film=wet,
                                                      scalars=scalars, slip=slip_state,
                                                      groove=wall_state)
        self.n = lay.n
        ud = lay.udofs
        axisym = model.axisym
        self.prony = None
        if self.viscoelastic:
            self.solid, self.prony, H0 = ves.terms(lay, u0)
        else:
            self.solid = SolidTerm(X, mesh.conn[lay.cells], model.material, axisym,
                                   udofs=lay.udofs_local)
        a = scene.asperity
        # the rod side in this layout, the rod at its final radius
        self.side = side = model.side.on(ud, r_rod=lambda t: model.r_rod_final)
        self.rod = RodContact(side, model.law)
        g = model.groove
        trib = tributary_lengths(X, np.concatenate(list(mesh.edges.values())), X.shape[0])
        self.groove = GrooveContact(X, g.nodes, trib, axisym, lambda t: model.r_g_final,
                                    g.z_walls, penalty=g.k, delta=g.delta, udofs=ud,
                                    corner_radius=g.rho, edge=g.edge)
        self.film = self.leakage = self.xdofs = None
        # (indicator, t) of the run's last ODD_EVEN_STEPS accepted states (OddEvenWatch)
        self.odd_even_recent = deque(maxlen=ODD_EVEN_STEPS)
        self.vdofs = np.zeros(0, np.int64)
        # the seal surface's own terms (its self-contact, sealts.contact.self_contact)
        self.surface = model.surface(ud)
        if wet:
            film_kw = dict(v=self.motion.v, eta=fl.viscosity, p_in=fl.p_in, p_out=fl.p_out,
                           ff=flow_factors_of(fm), h_floor=fm.h_floor, squeeze=fm.squeeze,
                           pressurised_end="min_z", surface_normal=True, shear=True,
                           beta=fm.beta)
            self.vdofs = np.array([lay.scalar_dofs["V_in"], lay.scalar_dofs["V_out"]])
            # the paper's scheme (film.scheme = "paper") has two more unknowns, its
            # integration constants c0 and qd; same loads on the seal, its own film rows
            # and leakage flows
            if fm.scheme == "paper":
                self.xdofs = np.array([lay.scalar_dofs["c0"], lay.scalar_dofs["qd"]])
                self.film = SealPaperFilmTerm(side, lay.film_dofs, self.xdofs,
                                              alpha=fm.alpha, **film_kw)
                self.leakage = PaperLeakageTerm(self.film, self.vdofs)
            else:
                # the upwinded Couette flow's stiffness: pi E' of the long-term material
                stiff = np.pi * model.material.plane_strain_modulus if fm.upwind else 0.0
                self.film = SealFilmTerm(side, lay.film_dofs, stiff=stiff, **film_kw)
                self.leakage = LeakageTerm(self.film, self.vdofs)
        self.friction = self.groove_friction = None
        if slip_state:
            self.friction = SlipStateFriction(self.rod, self.motion.v, lay.slip_dofs,
                                              mu_s=a.mu_s, gamma_crit=st.gamma_crit,
                                              v_ref=self.motion.peak_speed())
        elif rod_friction:
            self.friction = RodFriction(self.rod, self.motion.s, mu_s=a.mu_s,
                                        gamma_crit=st.gamma_crit)
        if wall_state:
            if not np.array_equal(lay.groove_nodes, self.groove.nodes):
                raise RuntimeError("the groove anchors' nodes are not the groove contact's")
            self.groove_friction = GrooveStateFriction(self.groove, lay.groove_dofs,
                                                       mu=scene.groove.mu,
                                                       gamma_crit=st.gamma_crit,
                                                       v_ref=self.motion.peak_speed())
        elif wall_friction:
            self.groove_friction = GrooveFriction(self.groove, mu=scene.groove.mu,
                                                  gamma_crit=st.gamma_crit)
        # the friction work (fluid shear and rod friction) as a TS unknown
        sources = [f for f in (self.film, self.friction) if f is not None]
        self.work = (FrictionWork(lay.scalar_dofs["W"], self.motion.v, sources)
                     if sources else None)
        self.load = None
        old = load
        if old is not None:
            # step 2's wetting, without the rod side when the film carries it
            rod_edges = {tuple(sorted(e)) for e in mesh.edges["rod_side"]} if wet else set()
            on_rod = np.array([tuple(sorted(e)) in rod_edges for e in old.edges], bool)
            self.load = old.rebuilt([lambda t: fl.p_in, lambda t: fl.p_out][:len(old.pressures)],
                                    udofs=ud, dry=on_rod)
        # the fronts follow the seal's traction at TS events (on every rank, like the guards)
        self.front = (MovingFront(self.load, self.node_contact_pressure,
                                  scene.stroke.front_tolerance)
                      if self.load is not None and scene.stroke.front == "moving" else None)
        # the viscous stabilisation, over this rank's own nodes (lumped volumes)
        c, c_snap = scene.stroke.stabilisation, scene.stroke.snap_stabilisation
        self.node_volume = model.stab.m.reshape(-1, 2)[:, 0]
        # always a term (c = 0 adds nothing), so that a checkpoint's histories line up
        # with a resumed run's whatever c either has
        own = model.partition.owned_nodes
        self.stab = SnapStabilisation(lay.udofs_local[own].ravel(),
                                      np.repeat(self.node_volume[own], 2), c, c_snap)
        self.U0 = np.zeros(self.n)
        self.U0[ud] = u0[model.udofs]
        fields = None
        if prony_size:
            self.U0[lay.prony_dofs[lay.cells]] = H0
            prony = lay.field_dofs("prony")
            fields = {"prony": prony,
                      "displacement": np.setdiff1d(np.arange(self.n), prony)}
        # post-step hooks run in the terms' order: the guards first (on every rank: rod
        # side, extrusion), then the frictions' return mapping
        self.guards = model.guards(side, self.groove, lambda t: fl.p_in,
                                   FOLD_HINT if rod_friction and self.viscoelastic is None
                                   else "")
        self._output_terms = self._relaxed_from = None
        self.problem = model.problem(
            self.n, self._terms(self.solid, self.prony, with_leakage=True),
            prefix="stroke_", fields=fields, dofs=lay)
        # the local error in the max norm: every unknown (the leakage volumes, the film
        # pressures at the contact) meets its own tolerance, where TSAdapt's default 2-norm
        # averages it over all of them (benchmarks/stroke_sensitivity.md: with it, rtol
        # changed by one part in a million moved the net leakage by 0.4 %, with the max norm
        # by 0.01 %)
        self.problem.ts_defaults["ts_adapt_wnormtype"] = "infinity"
        # steps chosen for 0.6 of the tolerance in the step-size formula (PETSc's 0.9):
        # the friction's stick-slide knees make the error jump, and the default's steps,
        # sized just below the tolerance, were rejected twice each there; at 0.6 the coarse
        # cycle takes 1,147 + 99 steps for 862 + 251 and as many Newton iterations, and
        # lands nearer the converged answer (benchmarks/stroke_sensitivity.md)
        self.problem.ts_defaults["ts_adapt_safety"] = "0.6"
        # BDF of order 2 (PETSc's default; A-stable, where order 3 is not): with the
        # friction's history as TS state and the refined edges, the default cycle takes
        # fewer steps and Newton iterations with it than with order 3 at the same rtol
        # 1e-2, and its answers are as close to the reference; order 1 needs twice the
        # steps, order 4 more, Crank-Nicolson crawls at the first stick-slip
        # (benchmarks/work_precision.md, the bdf family)
        self.problem.ts_defaults["ts_bdf_order"] = "2"
        # a stage's Newton solve is converged by the residual's tests or once its correction
        # is below 1e-3 of every unknown's error tolerance (sealts.problem.newton_test)
        self.problem.update_test = 1e-3
        # checkpoints at the stops (sealts/steps/run_checkpoint.py): BDF restarts there
        self.problem.restart_at_stops = True
        # a step at TS's minimum size stops the run (Problem._check_min_step); the stroke
        # step then goes back to its last stop with the snap stabilisation, once
        self.problem.stop_at_min_step = True

    def _terms(self, solid, prony, with_leakage):
        """The problem's terms in its numbering: the guard, this rank's solid (and Prony
        term), rank 0's boundary terms (rod, groove, the surface's own, film, leakage,
        frictions, pressure, work)."""
        boundary = [self.rod, self.groove] + self.surface + [
            t for t in (self.film, self.leakage if with_leakage else None, self.friction,
                        self.groove_friction, self.load, self.work if with_leakage else None)
            if t is not None]
        stab = [self.stab] if with_leakage else []
        # the moving front sets the load's wetting at each t: before the load
        front = [self.front] if with_leakage and self.front is not None else []
        return (self.guards + [solid] + stab + ([prony] if prony is not None else []) + front
                + self.layout.on_root(boundary))

    def node_contact_pressure(self, t, U):
        """The walls' and the rod's contact pressure at every node (MPa), what the fronts
        are tested against."""
        return node_contact_pressure(self.model.mesh.X.shape[0], self.groove, self.rod, t, U)

    def start(self):
        """Film pressures with the seal held, then seal and film in equilibrium at t = 0."""
        lay, comm, n = self.layout, self.problem.comm, self.n
        U = self.U0.copy()
        if self.film is not None:
            U[lay.film_dofs] = np.linspace(self.scene.fluid.p_in, self.scene.fluid.p_out,
                                           lay.film_dofs.size)
            if self.xdofs is not None:
                U[self.xdofs] = self.film.constants(0.0, U)
            # one small 1D problem, replicated on every rank (serial dofs): every unknown
            # but the film's held
            film = np.concatenate([lay.film_dofs] + ([self.xdofs] if self.xdofs is not None
                                                     else []))
            held = np.setdiff1d(np.arange(n), film)
            U = Problem(n, [self.film], comm=comm, constraints=Constraints(held, U[held]),
                        prefix="stroke_film_").solve_steady(U, 0.0)
            self.film.set_row_scale(0.0, U)
        for fr in self.frictions:
            fr.reset(0.0, U)                       # no elastic slip in the pressurised state
        # the long-term equilibrium with the film (the paper's step 2 ends with the
        # hydrostatic film); a viscoelastic seal starts relaxed from it
        # the integrals (V, W), the slips z and the walls' anchors (zero slip, from the reset) held
        fixed = np.concatenate([self.vdofs, lay.slip_dofs, lay.groove_dofs.ravel()]
                               + ([[self.work.wd]] if self.work is not None else []))
        solid = self.solid
        if self.prony is not None:
            solid = SolidTerm(self.model.mesh.X, self.model.mesh.conn[lay.cells],
                              self.model.material, self.model.axisym, udofs=lay.udofs_local)
            fixed = np.concatenate([fixed, lay.prony_dofs[lay.cells].ravel()])
        loc, mine = lay.local(fixed)
        # one steady Newton solve with nothing behind it (no TS to retry smaller): the
        # backtracking line search. With full steps the film's switch-on at 20 MPa sent
        # the second iterate to a residual of 1e17 (DIVERGED_DTOL)
        start = self.model.problem(n, self._terms(solid, None, with_leakage=False),
                                   constraints=Constraints(loc, U[fixed][mine]),
                                   prefix="stroke_start_", dofs=lay, linesearch="bt")
        start.max_it = START_MAX_IT
        U = start.solve_steady(U, 0.0)
        if self.load is not None:
            U = self._settle_front(start, U)
        if self.front is not None:
            self.front.reset(0.0)            # from the fronts settled with the film
        self.problem.counters.newton += start.counters.newton
        self._relaxed_from = U
        if self.prony is not None:
            U[lay.prony_dofs[lay.cells]] = self.viscoelastic.relax(self.prony, U[lay.serial])
            U = self.problem.gather(self.problem._owned(U)).copy()   # every rank's cells
        self.problem.accepted(0.0, U)
        return U

    def _settle_front(self, start, U, tol=1e-4, max_updates=30):
        """The fronts settled with the film: step 2 settled them with the fluid on the rod
        side as a pressure load, the film's pressure there is another (the coarse O-ring at
        20 MPa: the groove-side front 0.7 edges short of its target). Front update and the
        start's solve in turn until a front would move less than ``tol`` edges (as step
        2's, :func:`sealts.solid.pressure.settle`); the rod side's front is the film's and
        stays."""
        state = {"U": U}

        def solve():
            state["U"] = start.solve_steady(state["U"], 0.0)

        settle(self.load, 0.0, lambda: self.node_contact_pressure(0.0, state["U"]), solve,
               tol, max_updates)
        return state["U"]

    def output_terms(self):
        """The viscoelastic solid and Prony terms over every cell in serial dofs, for the
        fields output: the problem's own on one rank; under MPI a copy over all cells,
        relaxed from the same start (its frozen Prony stress)."""
        if self.layout.identity:
            return self.solid, self.prony
        if self._output_terms is None:
            lay = self.layout
            cells = np.arange(self.model.mesh.conn.shape[0])
            solid, prony = self.viscoelastic.terms_on(cells, lay.udofs, lay.prony_dofs)
            self.viscoelastic.relax(prony, self._relaxed_from)
            self._output_terms = solid, prony
        return self._output_terms

    @property
    def frictions(self):
        """The friction terms in use (rod, groove walls)."""
        return [f for f in (self.friction, self.groove_friction) if f is not None]

    def displacement(self, U):
        """The displacement-only vector of the SealModel's layout (for its outputs)."""
        u = np.zeros(self.model.n)
        u[self.model.udofs] = U[self.layout.udofs]
        return u

    def profile(self, t, U, Udot=None):
        """Along the rod side: y (mm), h (mm), film pressure p and asperity pressure (MPa),
        fluid shear tau and solid friction stress tau_solid (MPa, +y on the seal); the names
        of the film-only scenes' profiles."""
        f, rod, side = self.film, self.rod, self.side
        y = side.y(U)
        h = side.gap(t, U)
        p_asp, _ = rod.pressure(t, U)
        p = tau = np.zeros_like(h)
        if f is not None:
            p = f.pressure(U)
            tau = f.shear_forces(t, U, Udot) / (side.area * side.lengths_of(y))
        tau_s = (self.friction.stress(t, U) if self.friction is not None
                 else np.zeros_like(tau))
        return {"y": y, "h": h, "p": p, "p_asperity": p_asp, "tau": tau, "tau_solid": tau_s}

    def scalars(self, t, U, Udot=None):
        """Forces on the seal (N): fluid shear (+y), radial film and asperity loads, flows
        (zero without the film)."""
        f, rod = self.film, self.rod
        h = self.side.gap(t, U)
        y = self.side.y(U)
        touching = rod.law.touching(h)
        length = float(np.ptp(y[touching])) if touching.sum() > 1 else 0.0
        q_in = q_out = shear = load_fluid = p_max = v_film = 0.0
        volumes = np.zeros(2)
        if f is not None:
            q_in, q_out = self.leakage.flows(t, U, Udot)
            shear = float(f.shear_forces(t, U, Udot).sum())
            load_fluid = float(f.forces(t, U).sum())
            volumes = U[self.vdofs]
            p_max = float(f.pressure(U).max())
            v_film = f.content(t, U)
        load_asperity = float(rod.forces(t, U).sum())
        solid = float(self.friction.total(t, U)) if self.friction is not None else 0.0
        gf = self.groove_friction
        groove = gf.axial(t, U) if gf is not None else 0.0
        work = float(U[self.work.wd]) if self.work is not None else 0.0
        f_stab = 0.0
        if Udot is not None:
            ud = self.layout.udofs
            f_stab = float(np.abs(self.stab.c * self.node_volume[:, None] * Udot[ud]).sum())
        out = {"v": self.motion.v(t), "friction_fluid": shear, "friction_solid": solid,
                "friction_total": shear + solid, "friction_groove": groove,
                "normal_load": load_fluid + load_asperity, "load_fluid": load_fluid,
                "load_asperity": load_asperity, "Q_in": q_in, "Q_out": q_out,
                "V_in": float(volumes[0]), "V_out": float(volumes[1]), "h_min": float(h.min()),
                "asperity_contact_length": length, "p_fluid_max": p_max,
                "W_friction": work, "F_stabilisation": f_stab, "V_film": v_film,
                # edges between the kept pressure-penetration fronts and where the
                # seal's contact would put them
                "front_drift": (front_drift(self.load, self.node_contact_pressure(t, U), t)
                                if self.load is not None else 0.0),
                # the wetted boundary (edges, the fronts' reaches summed): a moving front's
                # record
                "wetted_edges": float(sum(self.load.reach)) if self.load is not None else 0.0,
                # the groove walls' penalty penetration, p / k (mm)
                "wall_penetration": float(self.groove.node_pressures(t, U).max()) / self.groove.k,
                # the slip the walls' return mapping took off a touched wall at this state
                # (mm; 0 while the seal sticks to its walls)
                "groove_slide": float(gf.slide) if gf is not None else 0.0}
        if self.groove.edge is not None:     # how far the seal is into the extrusion gap, mm
            out["extrusion"] = extrusion(self.groove, t, U)[0]
        return out

    @property
    def volume_scale(self):
        """V_c = A L_film h_c (mm^3): a film of the contact law's contact gap h_c
        (``contact_gap``) over the rod side's reference length, the volume whose fraction
        rtol each step may err by in V_in and V_out."""
        side = self.side
        return side.area * float(np.ptp(side.Z)) * self.model.law.contact_gap

    @property
    def pressure_scale(self):
        """p_ref (MPa): the largest of the sealed pressures p_in, p_out and the peak asperity
        pressure of the pressurised seal (the dry contact the stroke starts from), the
        pressure whose fraction rtol each step may err by in the film pressures. A property
        of the scene and the pressurised state, so a restarted run holds the same."""
        fl = self.scene.fluid
        p, _ = self.rod.pressure(0.0, self.U0)
        return max(fl.p_in, fl.p_out, float(np.max(p)) if p.size else 0.0)

    @property
    def displacement_scale(self):
        """u_ref (mm): the contact law's contact gap h_c (``contact_gap``), the separation
        the film and the asperity contact respond to, as in ``volume_scale``: the
        displacement whose fraction rtol each step may err by in every displacement."""
        return float(self.model.law.contact_gap)

    def prony_dofs(self):
        """The Prony internal variables' dofs (serial), shaped (cells, 4 Gauss points,
        active terms, 4 components) as :class:`sealts.solid.viscoelastic.PronyTerm` holds
        them."""
        lay = self.layout
        return lay.prony_dofs[lay.cells].reshape(lay.cells.size, 4, self.prony.g.size, 4)

    def tolerances(self, rtol, atol=1e-6):
        """TS's local-error tolerances per unknown, (rtol, atol) arrays in the serial
        numbering: each unknown's error e_i is held to atol_i + rtol_i |U_i| in the max norm.
        The same weights are the Newton test's (:mod:`sealts.problem.newton_test`).

        * displacements (mm): rtol, and atol = rtol h_c (``displacement_scale``; at least
          atol). With 1e-6 mm the axial displacements that pass through zero as the
          friction drags the seal (their error held to a nanometre, where the radial ones
          beside them err by rtol of some 0.5 mm) set a fifth of the default cycle's
          stroke steps and more than half of those of a cycle without sealed pressure;
          held to rtol of the largest displacement (0.7 mm, normwise) the steps grow until
          Newton fails, and the 30 MPa cycle took twice the Newton iterations
          (benchmarks/stroke_sensitivity.md);
        * film pressures (MPa): rtol, and atol = rtol p_ref (``pressure_scale``; at least
          atol, for a scene with neither sealed pressure nor contact). With an atol of
          1e-6 MPa the film's near-ambient pressures in the outlet wedge (|p| of a few
          kPa, swinging with the squeeze) set most step sizes at the stick-slide
          transitions after the start and the reversal, to an error of 1 Pa that no
          result depends on (benchmarks/stroke_sensitivity.md);
        * the leakage volumes V_in, V_out (mm^3): atol = rtol V_c (``volume_scale``) and no
          relative part. The net leakage is the small difference of two transports of tens
          of mm^3: a tolerance of rtol |V| let every mid-stroke step err by 0.05 mm^3 and
          moved the net leakage by 2 % at rtol 1e-3 (benchmarks/stroke_sensitivity.md);
        * the elastic slips z of the rod friction (mm, ``friction_history = "state"``): rtol,
          and atol = gamma_crit. A sticking node's slip moves with its axial displacement
          (z' = v - u_z'), whose tolerance already holds it; a sliding node's force does not
          depend on it (phi saturated). What the slip's own tolerance adds is a bound on
          the path: no step may carry a node across its stick range unseen (a reversal
          inside one step, which the anchors take as its net increment). Held to
          1e-2 gamma_crit the slips' knees at the stick-slide transitions set the steps:
          the default cycle took 1,167 + 71 stroke steps for 340 + 21, the answers within
          0.01 % (benchmarks/stroke_sensitivity.md);
        * the groove walls' friction anchors (mm, ``friction_history = "state"``): rtol, and
          atol = gamma_crit, as the rod's slips: a sticking node's anchor stands still, a
          sliding one's follows its node where the force is saturated. Held to their
          nodes' displacement atol (rtol h_c) the default cycle took 382 + 23 stroke steps
          for 348 + 19, to the same answer within 0.03 %; with no relative part 571 + 20;
        * the Prony internal variables H_i (MPa, viscoelastic): rtol, and atol = rtol p_ref
          / g_i, so that each term's stress g_i H_i (Eq. (a) of
          :mod:`sealts.solid.viscoelastic`) is held to the film pressures' rtol p_ref. With
          1e-6 MPa the near-zero components of the fast terms' H_i set the steps
          (benchmarks/work_precision.md: the fig14_ve_sq_ff cycle's steps fell six-fold);
        * left out (atol 1e300): the friction work W, whose integrand v F is a function of
          the error-controlled state (its own error would be measured against |W|, tens of
          thousands of N mm), and the paper scheme's c0 and qd, algebraic flows.

        ``-stroke_ts_rtol`` on the command line replaces ``rtol`` here, and
        ``-stroke_ts_atol`` (mm) the displacements' atol (PETSc would otherwise ignore them
        beside per-unknown vectors); ``-stroke_ts_pressure_atol`` (MPa) replaces the film
        pressures' atol.
        """
        from petsc4py import PETSc
        opts = PETSc.Options(self.problem.prefix)
        rtol = opts.getReal("ts_rtol", float(rtol))
        atol = float(atol)
        rt, at = np.full(self.n, rtol), np.full(self.n, atol)
        at[self.layout.udofs.ravel()] = opts.getReal(
            "ts_atol", max(rtol * self.displacement_scale, atol))
        if self.work is not None:
            at[self.work.wd] = 1e300
        if self.xdofs is not None:
            at[self.xdofs] = 1e300
        if self.film is not None:
            at[self.layout.film_dofs] = opts.getReal(
                "ts_pressure_atol", max(rtol * self.pressure_scale, atol))
        if self.layout.slip_dofs.size:
            at[self.layout.slip_dofs] = self.friction.gamma_crit
        if self.layout.groove_dofs.size:
            at[self.layout.groove_dofs.ravel()] = self.groove_friction.gamma_crit
        if self.prony is not None:
            g = self.prony.g
            at[self.prony_dofs()] = (rtol * self.pressure_scale / g)[None, None, :, None]
        if self.vdofs.size:
            rt[self.vdofs] = 0.0
            at[self.vdofs] = rtol * self.volume_scale
        return rt, at

    def run(self, U0, t_end, dt0, rtol, output_times=(), observers=(), resume=None):
        """TS from t = 0 (U0 from :meth:`start`) to t_end, stopping at the output times and
        the law's kinks and reversals; ``resume``: a Problem snapshot at one of those stops
        (U0 its state), from which the run goes on as the one that took it."""
        m = self.motion
        stops = sorted(set(output_times) | set(m.kinks(t_end)) | set(m.reversals(t_end)))
        rtol, atol = self.tolerances(rtol)
        t0 = 0.0 if resume is None else resume["t"]
        dt0 = dt0 if resume is None else resume["dt"]
        self.odd_even_recent.clear()
        observers = ([OddEvenWatch(self)] if self.film is not None else []) + list(observers)
        try:
            return self.problem.transient(U0, t0, t_end, dt0, stops=stops,
                                          observers=observers, rtol=rtol, atol=atol,
                                          resume=resume)
        except StepTooSmall as e:
            note = self._odd_even_note()
            if self.stab.c_snap <= self.stab.c_base:
                msg = (f"{e}{note}; if the seal snaps there (a fold of its quasi-static "
                       "equilibrium), stroke.snap_stabilisation = 1e-3 (above "
                       "stroke.stabilisation) gives the snap a finite speed")
            elif self.stab.snapped_at >= 0.0:
                msg = (f"{e}{note}; stuck again with the snap stabilisation (c = "
                       f"{self.stab.c:g} MPa s/mm^2, for a snap at t = "
                       f"{self.stab.snapped_at:.6g} s); a finer contact mesh (mesh.h_contact) "
                       "resolved some such stops")
            else:
                msg = f"{e}{note}"
            stall = StepTooSmall(msg, t=e.t)
            stall.odd_even = note       # the Stroke step carries it past its snap retry
            raise stall from None

    def _odd_even_note(self):
        """"; <the mode and its cure>" if the film's gap alternated from node to node within
        the last ODD_EVEN_STEPS accepted states (sealts.film.odd_even), else ""."""
        zigzag, t = max(self.odd_even_recent, default=(0.0, 0.0))
        if zigzag <= ODD_EVEN_WARN:
            return ""
        return "; " + odd_even_note(zigzag, t, self.scene.mesh.h_contact)
