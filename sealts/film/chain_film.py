"""What both coupled film schemes share: the film on a rod side and its pressure loads.

A film lives on a :class:`sealts.contact.rod_side.RodSide` (chain, dofs, gap h (Eq. 18),
squeeze rate (Eq. 26), positions y (Eq. 25), tributary lengths L (Eq. 30), A (Eq. 31)), with
one film-pressure unknown per chain node. It loads the seal with

    F_r,i = p_i A L_i                              radial, on u_r             (Eq. 29-31)
    F_z,i = -p_i A (r_{i+1} - r_{i-1}) / 2         axial, with ``surface_normal``

(F_z: the axial part of the pressure on the seal's own inclined surface, see
:mod:`sealts.film.seal_film`). The schemes, :class:`sealts.film.seal_film.SealFilmTerm` and
:class:`sealts.film.seal_paper_film.SealPaperFilmTerm`, add their own film rows.
"""
import numpy as np

from ..core import Term, of_time
from .flow_factors import FlowFactors
from .reynolds_fv import control_volumes


class ChainFilm(Term):
    def __init__(self, side, pdofs, v, eta, p_in, p_out, ff=None, h_floor=1e-5,
                 squeeze=True, pressurised_end="min_z"):
        """``side``: the rod side; ``pdofs``: the film-pressure dofs in chain order
        (``Layout.film_dofs``); ``v(t)`` the rod's axial velocity (mm/s); ``eta`` the
        viscosity (MPa s); ``p_in``, ``p_out`` (MPa, numbers or functions of t) at the
        pressurised end (``pressurised_end``: ``"min_z"``, the chain's first node, or
        ``"max_z"``) and at the other; ``ff``: :class:`FlowFactors` (none by default);
        ``h_floor`` (mm): the gap regularisation of :mod:`sealts.film.gap`; ``squeeze``:
        with the dh/dt term."""
        if pressurised_end not in ("min_z", "max_z"):
            raise ValueError(f"pressurised_end must be 'min_z' or 'max_z', got "
                             f"{pressurised_end!r}")
        if side.m < 3:
            raise ValueError("the film needs at least three chain nodes")
        self.side = side
        self.pd = np.asarray(pdofs, np.int64)
        if self.pd.shape != (side.m,):
            raise ValueError("pdofs must give one film-pressure dof per chain node")
        self.v = of_time(v)
        self.eta, self.h_floor, self.squeeze = eta, h_floor, squeeze
        self.ff = FlowFactors.none() if ff is None else ff
        first = pressurised_end == "min_z"
        self.p_first = of_time(p_in if first else p_out)
        self.p_last = of_time(p_out if first else p_in)
        self.pressurised_end = pressurised_end
        self.work = None       # (dof, v) of the friction work's row: sealts.contact.friction_work

    def _ffargs(self):
        f = self.ff
        return f.model, f.par, f.table_h, f.table_pp, f.table_ps

    def film(self, t, u, udot=None):
        """(y, h, dh/dt, p) on the chain: current axial positions, gaps (Eq. 18), squeeze
        rates (zero with the squeeze term off or without U') and film pressures."""
        s = self.side
        y = s.y(u)
        h = s.gap(t, u)
        hd = s.gap_rate(t, udot) if (self.squeeze and udot is not None) else np.zeros(s.m)
        return y, h, hd, np.asarray(u[self.pd], float)

    def lengths(self, y):
        """Tributary lengths L_i of positions y (mm), one-sided at the ends (Eq. 30)."""
        return self.side.lengths_of(y)

    def forces(self, t, u):
        """Radial film force on each chain node (N), F_r,i = p_i A L_i (Eq. 29-31)."""
        return u[self.pd] * self.side.area * self.side.lengths(u)

    def axial_forces(self, t, u):
        """Axial film force on each chain node (N): F_z,i = -p_i A (r_hi - r_lo)/2 with
        ``surface_normal``, else zero."""
        s = self.side
        if not self.surface_normal:
            return np.zeros(s.m)
        return -u[self.pd] * s.area * s.lengths_of(s.r(u))

    def content(self, t, u):
        """The fluid the film holds (mm^3): V_film = A sum_i M_i h_eff_i (h_eff: the gap
        above its floor, :mod:`sealts.film.gap`; M_i the default scheme's control volumes,
        half the adjacent element lengths, which are the tributary lengths L_i wherever the
        chain runs forward along the rod). The default scheme's balance is
        Q_in - Q_out = A sum_i M_i dh_eff_i/dt, so over a run V_in - V_out equals the change
        of V_film but for A sum_i h_eff_i dM_i/dt, the seal's axial surface motion, which
        the film neglects (Eq. 21), and the time integration's error."""
        s, f = self.side, self.h_floor
        h = s.gap(t, u)
        he = h if f <= 0.0 else np.where(h >= 2.0 * f, h,
                                         f * (1.0 + np.exp(np.minimum(h / f - 2.0, 0.0))))
        return float(s.area * control_volumes(s.y(u)) @ he)

    def pressure(self, u):
        """The film pressures in chain order (MPa)."""
        return np.asarray(u[self.pd], float)
