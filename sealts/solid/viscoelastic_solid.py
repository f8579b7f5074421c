"""The seal's Prony material for a step of a scene's time scales (paper Eq. 7-12): the
series and its WLF factor A(theta(t)), the classification of its terms (relaxed, frozen,
active) over [viscoelastic.t_min, t_end], and the terms on a Numbering from a relaxed start.
Shared by the hold and the stroke.

The start is relaxed, as ABAQUS hands over after a long-term step: every internal variable
is at equilibrium, H_i = S_iso(u0), so the stress is the long-term one and there is no
jump. Relaxed terms soften the elastic part, frozen ones keep the fixed stress
g_i S_iso(u0), active ones are the ``prony`` field.
"""
from dataclasses import replace

import numpy as np

from .prony import TABLE2_G, TABLE2_TAU, PronySeries, classify, wlf_shift
from .term import SolidTerm
from .viscoelastic import PronyTerm


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


class ViscoelasticSolid:
    """The seal's Prony material for a step of the scene's time scales: the series and its
    WLF factor, the classification of its terms over [viscoelastic.t_min, t_end], and the
    terms built on a Numbering from a relaxed start u0 (H_i = S_iso(u0)). Shared by the hold and
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
        displacement u0 of the model's own numbering, on this rank's cells (``cells``) of
        the :class:`sealts.mesh.partition.Numbering` ``layout``, in its local dofs."""
        solid, prony = self.terms_on(layout.cells, layout.udofs_local, layout.prony_local)
        u = np.zeros(layout.n)
        u[layout.udofs] = u0[self.model.udofs]
        return solid, prony, self.relax(prony, u[layout.serial])

    def terms_on(self, cells, udofs, prony_dofs):
        """(elastic SolidTerm, PronyTerm) on the mesh's ``cells`` with the dofs ``udofs``
        (node -> 2) and ``prony_dofs`` (one row per cell of ``cells``); the frozen terms'
        stress is set by :meth:`relax`."""
        s, c, m = self.series, self.classes, self.model
        keep = 1.0 - s.g[c.relaxed].sum()
        elastic = replace(self.instantaneous, c10=self.instantaneous.c10 * keep,
                          c01=self.instantaneous.c01 * keep)
        solid = SolidTerm(m.mesh.X, m.mesh.conn[cells], elastic, m.axisym, udofs=udofs)
        prony = PronyTerm(solid, self.instantaneous, s.g[c.active], s.tau[c.active],
                          prony_dofs, shift=self.shift_of_t)
        return solid, prony

    def relax(self, prony, u):
        """The relaxed state at the displacement in u (the layout's local vector): sets the
        frozen terms' stress g S_iso(u) and returns H_i = S_iso(u) per cell (the prony
        values of this rank's cells)."""
        H0, S0 = prony.equilibrium(u)
        prony.frozen = self.series.g[self.classes.frozen].sum() * S0
        return H0.reshape(H0.shape[0], -1)
