"""The DAE of the viscoelastic pressure step and hold (step 3 with ``[hold] p_end``).

From the pressurised long-term state u0 (steps 1-2), the sealed pressure steps from p_from
to p_to over t_ramp and is held, in real time (s), with the Prony material of
:mod:`sealts.solid.viscoelastic_solid` from a relaxed start. The active Prony terms are the
``prony`` field on cells (see :mod:`sealts.mesh.partition`: each rank carries those of its
own cells) and TS integrates them with the displacements. The rod and groove are at their
final positions; the pressure-penetration front moves after each accepted step as in step
2, under-relaxed where it reverses (:class:`sealts.solid.pressure.RelaxedFront`, a
post-step hook), and the rod-side guard checks every accepted state.
"""
import copy

import numpy as np

from ..contact.rigid import RodContact, node_contact_pressure
from ..solid.pressure import RelaxedFront
from ..solid.viscoelastic_solid import ViscoelasticSolid
from .seal_model import ramp


class HoldProblem:
    """The hold's DAE on a SealModel after pressurisation, with the front ``load`` of step 2."""

    def __init__(self, model, u0, load, p_from, p_to, t_ramp, ve, t_end, p_back=0.0):
        """p_in from ``p_from`` to ``p_to`` (MPa) over ``t_ramp`` (s), held to ``t_end``;
        ``p_back`` the back pressure (fluid.p_out), held."""
        self.model, self.p_to = model, p_to
        ves = ViscoelasticSolid(model, ve, t_end)
        self.series, self.shift = ves.series, ves.shift
        self.classes = ves.classes
        mesh = model.mesh
        # the model's distributed mesh, with the Prony field on its cells
        self.layout = lay = model.partition.numbering(prony=ves.prony_size)
        assert np.array_equal(lay.udofs, model.udofs)  # vertices first: u0 maps as it is
        X = mesh.X
        self.solid, self.prony, H0 = ves.terms(lay, u0)
        # rod and groove at their final positions
        self.side = model.side.on(lay.udofs, r_rod=lambda t: model.r_rod_final)
        self.rod = RodContact(self.side, model.law)
        self.groove = copy.copy(model.groove)
        self.groove.r_bottom = lambda t: model.r_g_final
        # step 2's wetting, with p_in ramped from p_from to p_to (a back pressure held)
        self.load = load.rebuilt(
            [lambda t: p_from + (p_to - p_from) * ramp(t / t_ramp), lambda t: p_back]
            [:len(load.pressures)], udofs=lay.udofs)
        # serial start vector; each rank fills the internal variables of its own cells
        self.U0 = np.zeros(lay.n)
        self.U0[lay.udofs] = u0[model.udofs]
        self.U0[lay.prony_dofs[lay.cells]] = H0
        # the planar O-ring's rolling gauge too (frictionless, as steps 1-2)
        self.gauge_terms = [model.gauge] if model.gauge is not None else []
        self.surface = model.surface(lay.udofs)
        terms = model.local_terms([self.rod, self.groove, self.load] + self.surface
                                  + self.gauge_terms,
                                  dofs=lay, solid=self.solid)
        terms.insert(1, self.prony)
        terms += model.guards(self.side, self.groove, self.load.pressure) + [
            RelaxedFront(self.load, self.node_contact_pressure, max_advance=1.0)]
        fields = {"displacement": lay.field_dofs("displacement")}
        if ves.prony_size:
            fields["prony"] = lay.field_dofs("prony")
        self.problem = model.problem(lay.n, terms, prefix="hold_", fields=fields, dofs=lay)
        # checkpoints at the stops (sealts/steps/run_checkpoint.py): BDF restarts there
        self.problem.restart_at_stops = True

    def node_contact_pressure(self, t, u):
        return node_contact_pressure(self.model.mesh.X.shape[0], self.groove, self.rod, t, u)

    def displacement(self, U):
        """The displacement-only vector of the SealModel's numbering."""
        return U[self.layout.udofs].ravel()

    def run(self, t_end, dt0, rtol, stops=(), observers=(), resume=None, U0=None):
        """TS from t = 0 (or from a checkpoint: ``resume`` a Problem snapshot, ``U0`` its
        state) to t_end."""
        t0, dt0 = (0.0, dt0) if resume is None else (resume["t"], resume["dt"])
        return self.problem.transient(self.U0 if U0 is None else U0, t0, t_end, dt0,
                                      stops=stops, observers=observers, rtol=rtol, atol=1e-6,
                                      resume=resume)

    def long_term_terms(self):
        """The long-term (hyperelastic) problem's boundary terms at the final pressure (rod,
        groove, the load, the gauge), and that load: a copy of the hold's held at p_to."""
        load = self.load.rebuilt([lambda t: self.p_to] + self.load.pressures[1:])
        return [self.rod, self.groove, load] + self.surface + self.gauge_terms, load
