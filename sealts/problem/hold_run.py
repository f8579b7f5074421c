"""Step 3 of a seal scene: the viscoelastic pressure step and hold (``[hold] p_end``).

From the pressurised long-term state u0 (steps 1-2), the sealed pressure steps from
fluid.p_in to hold.p_end over hold.t_ramp and is held until hold.t_end, in real time (s),
with the Prony material of :mod:`sealts.solid.viscoelastic`:

* the start is relaxed, as ABAQUS hands over after a long-term step: every internal
  variable is at equilibrium, H_i = S_iso(u0), so the stress is the long-term one and there
  is no jump; the pressure step then meets the short-term stiffness (G_0 for the active
  terms) and the seal creeps towards the long-term state;
* terms are classified over [viscoelastic.t_min, hold.t_end] (``classify``): relaxed terms
  soften the elastic part, frozen ones keep the fixed stress g_i S_iso(u0), active ones are
  the ``prony`` field (on cells, see :mod:`sealts.mesh.partition`: each rank carries
  those of its own cells) and TS integrates them with the displacements;
* the rod and groove are at their final positions; the pressure-penetration front is
  updated after each accepted step, as in step 2, under-relaxed where it reverses
  (:class:`sealts.solid.pressure.RelaxedFront`).

At the end, the long-term static solution at p_end (the hyperelastic material, from the
hold's final state) is solved as well and the differences are reported
(``long_term_check``): after a hold far beyond the longest relaxation time they vanish.
"""
import copy
from dataclasses import replace

import numpy as np

from ..contact.rigid import node_contact_pressure
from ..solid.pressure import PressureLoad, RelaxedFront
from ..solid.prony import TABLE2_G, TABLE2_TAU, PronySeries, classify, wlf_shift
from ..solid.term import SolidTerm
from ..solid.viscoelastic import PronyTerm
from .problem import Problem, SolveError


def prony_series(ve):
    """The scene's Prony series and its WLF factor A(theta(t)) as a function of time in the
    hold (constant, or from the piecewise-linear temperature history)."""
    if ve.prony == "table2":
        series = PronySeries(TABLE2_G, TABLE2_TAU)
    else:
        series = PronySeries(np.array(ve.prony_g), np.array(ve.prony_tau))

    def shift_at(theta):
        return float(wlf_shift(theta, ve.theta_0, ve.wlf_c1, ve.wlf_c2))

    if ve.temperature_times:
        ts, th = np.array(ve.temperature_times), np.array(ve.temperature_values)
        return series, lambda t: shift_at(np.interp(t, ts, th))
    a = shift_at(ve.temperature)
    return series, lambda t: a


def step_ramp(t, t_ramp):
    s = min(max(t / t_ramp, 0.0), 1.0)
    return s * s * (3.0 - 2.0 * s)


class ViscoelasticSolid:
    """The seal's Prony material for a step of the scene's time scales: the series and its
    WLF factor, the classification of its terms over [viscoelastic.t_min, t_end], and the
    terms built on a Layout from a relaxed start u0 (H_i = S_iso(u0)). Shared by the hold and
    the stroke."""

    def __init__(self, model, ve, t_end):
        self.model = model
        self.series, self.shift_of_t = prony_series(ve)
        s = self.series
        temps = list(ve.temperature_values) or [ve.temperature]
        shifts = [float(wlf_shift(th, ve.theta_0, ve.wlf_c1, ve.wlf_c2)) for th in temps]
        self.shift = max(shifts)            # for reports: the slowest relaxation
        self.classes = classify(s, ve.t_min, t_end, ve.tol, shift=(min(shifts), max(shifts)))
        mat = model.material
        self.instantaneous = replace(mat, c10=mat.c10 / s.g_inf, c01=mat.c01 / s.g_inf)
        self.prony_size = 16 * len(self.classes.active)     # per cell

    def terms(self, layout, u0):
        """(elastic SolidTerm, PronyTerm, H0 as the layout's prony values per cell) from the
        displacement u0 of the model's own layout, on the layout's cells (``cells``) in its
        local dofs: every cell in serial dofs for a serial Layout (replicated problems),
        this rank's cells for the model's distributed Numbering."""
        s, c, m = self.series, self.classes, self.model
        keep = 1.0 - s.g[c.relaxed].sum()
        elastic = replace(self.instantaneous, c10=self.instantaneous.c10 * keep,
                          c01=self.instantaneous.c01 * keep)
        mesh = m.mesh
        solid = SolidTerm(mesh.X, mesh.conn[layout.cells], elastic, m.axisym,
                          udofs=layout.udofs_local)
        prony = PronyTerm(solid, self.instantaneous, s.g[c.active], s.tau[c.active],
                          layout.prony_local, shift=self.shift_of_t)
        u = np.zeros(layout.n)
        u[layout.udofs] = u0[m.udofs]
        return solid, prony, self.relax(prony, u[layout.serial])

    def relax(self, prony, u):
        """The relaxed state at the displacement in u (the layout's local vector): sets the frozen
        terms' stress g S_iso(u) and returns H_i = S_iso(u) per cell (the prony values)."""
        H0, S0 = prony.equilibrium(u)
        prony.frozen = self.series.g[self.classes.frozen].sum() * S0
        return H0.reshape(H0.shape[0], -1)


class HoldStep:
    """The DAE of the viscoelastic hold, built on a SealModel after pressurisation."""

    def __init__(self, model, u0, p_from, p_to, t_ramp, ve, t_end, comm=None):
        self.model, self.p_to = model, p_to
        ves = ViscoelasticSolid(model, ve, t_end)
        self.series, self.shift_of_t, self.shift = ves.series, ves.shift_of_t, ves.shift
        self.classes = ves.classes
        mesh = model.mesh
        # the model's distributed mesh, with the Prony field on its cells
        self.layout = lay = model.partition.numbering(prony=ves.prony_size)
        assert np.array_equal(lay.udofs, model.udofs)  # vertices first: u0 maps as it is
        X = mesh.X
        self.solid, self.prony, H0 = ves.terms(lay, u0)
        self.instantaneous = ves.instantaneous
        # rod and groove at their final positions
        self.rod = copy.copy(model.rod)
        self.rod.r_rod = lambda t: model.r_rod_final
        self.groove = copy.copy(model.groove)
        self.groove.r_bottom = lambda t: model.r_g_final
        old = model.load
        self.load = PressureLoad(X, mesh.conn,
                                 lambda t: p_from + (p_to - p_from) * step_ramp(t, t_ramp),
                                 model.axisym, old.edges[old.start, 0], udofs=lay.udofs,
                                 p_crit=old.p_crit)
        self.load.set_reach(old.reach)
        # serial start vector; each rank fills the internal variables of its own cells
        self.U0 = np.zeros(lay.n)
        self.U0[lay.udofs] = u0[model.udofs]
        self.U0[lay.prony_dofs[lay.cells]] = H0
        # the planar O-ring's rolling gauge too (frictionless, as steps 1-2)
        self.gauge_terms = [model.gauge] if model.gauge is not None else []
        terms = model.local_terms([self.rod, self.groove, self.load] + self.gauge_terms,
                                  dofs=lay, solid=self.solid)
        terms.insert(1, self.prony)
        fields = {"displacement": lay.field_dofs("displacement")}
        if ves.prony_size:
            fields["prony"] = lay.field_dofs("prony")
        self.problem = Problem(lay.n, terms, comm=model.comm, prefix="hold_",
                               linesearch="basic", snes_atol=1e-9 * model.force_scale,
                               fields=fields, dofs=lay)

    def node_contact_pressure(self, t, u):
        return node_contact_pressure(self.model.mesh.X.shape[0], self.groove, self.rod, t, u)

    def run(self, t_end, dt0, rtol, stops=(), on_step=None, on_stop=None):
        front = RelaxedFront(self.load, max_advance=1.0)

        def step(ts, k, t, U):
            self.model.check_rod_side(t, U, self.layout.udofs, self.model.r_rod_final)
            front(self.node_contact_pressure(t, U), self.load.pressure(t))
            if on_step is not None:
                on_step(ts, k, t, U)

        return self.problem.transient(self.U0, 0.0, t_end, dt0, stops=stops, on_step=step,
                                      on_stop=on_stop, rtol=rtol, atol=1e-6)

    def long_term_check(self, U, t_end):
        """How far the hold's end state is from the long-term (hyperelastic) equilibrium at
        the final pressure: its out-of-balance nodal forces in the long-term problem (N),
        and the distance to the equilibrium that the quasi-static driver of steps 1-2
        (stabilised pseudo-time, then Newton, then the front settled) finds from it (mm, N,
        edges of front position). A bare Newton solve from there inverted elements on the
        0.05 mm mesh."""
        m = self.model
        u = U[self.layout.udofs].ravel()
        tau_max = self.shift * float(self.series.tau.max())
        if t_end < 20.0 * tau_max:
            return {"skipped": f"hold.t_end = {t_end:g} s is not far beyond the longest "
                               f"relaxation time {tau_max:g} s"}
        load = copy.copy(self.load)
        load.pressure = lambda t: self.p_to
        # the hold's state in the long-term problem: its out-of-balance nodal forces
        residual = Problem(m.n, m.local_terms([self.rod, self.groove, load] + self.gauge_terms),
                           comm=m.comm, dofs=m.dofs).global_residual(t_end, u)
        out = {"long_term_residual_max_N": float(np.abs(residual).max())}
        try:
            # pseudo-time 2..3 (the rod and groove of SealModel are final for t >= 1)
            us = m._quasi_static([load], u, 2.0, 3.0, 0.05, 2.5, self.problem.comm, None)
            us = m.settle_front(load, us, 3.0, 0.05, self.problem.comm)
        except SolveError as e:
            return {**out, "static_solve": f"failed: {e}"}
        f_hold = float(self.rod.forces(t_end, u).sum())
        f_static = float(self.rod.forces(t_end, us).sum())
        return {**out, "max_displacement_difference_mm": float(np.abs(us - u).max()),
                "rod_force_hold": f_hold, "rod_force_long_term": f_static,
                "rod_force_relative_difference": abs(f_hold - f_static) / abs(f_static),
                "static_equilibrium": bool(m.static),
                "front_difference_edges": float(sum(abs(a - b) for a, b in
                                                    zip(load.reach, self.load.reach)))}
