"""The Reynolds film on the deforming seal surface: the coupled soft-EHL term (issue 5).

The film nodes are the vertices of the seal's ``rod_side`` chain (ordered by reference z) at
their *current* axial position, and the gap follows the seal's radial displacement (the rod
side's geometry, :class:`sealts.contact.rod_side.RodSide`):

    y_i = Z_i + u_z,i                                             (Eq. 25)
    h_i = R_i + u_r,i - r(t)                                      (Eq. 18)
    dh_i/dt = du_r,i/dt - dr/dt                                   (Eq. 26, from the TS's U')

(the seal's axial velocity is neglected in the film, Eq. 21; the rod's radius is constant in
a stroke, so dr/dt only matters while a scene moves the rod radially). The unknowns are the
nodal film pressures p_i (the ``film_pressure`` field of :class:`sealts.mesh.layout.Layout`)
and the seal displacements; this term owns

* the film rows (one per chain node): the control-volume balance of
  :mod:`sealts.film.reynolds_fv` for the transient Reynolds equation (Eq. 13),

      R_i = M_i dh_eff_i/dt + q_{i+1/2} - q_{i-1/2} = 0,
      q_e = (I2_e - (p_b - p_a) / L_e) / I1_e,   L_e = sqrt((y_b - y_a)^2 + EPS_L^2),
      M_i = (L_{i-1/2} + L_{i+1/2}) / 2,

  (L_e is y_b - y_a but where the rod side lies along a groove wall and its nodes share
  one axial position: :mod:`sealts.film.reynolds_fv`, "Element lengths"; with ``stiff`` =
  pi E' > 0 q_e carries the upwinded Couette share of the same module, "Upwinded Couette
  flow")

  each multiplied by a fixed positive row scale (so the rows read in MPa), with the
  Dirichlet rows p = p_in at the pressurised end of the chain and p = p_out at the other;
* the radial force of the film on the seal (Eq. 29-31), on the u_r rows:

      F_r,i = p_i A L_i,   L_i = (y_{i+1} - y_{i-1}) / 2 (one-sided at the chain ends),

  the same current tributary lengths as the asperity contact of
  :class:`sealts.contact.rigid.RodContact` (Eq. 45), so fluid and asperity loads are lumped
  alike; A = 2 pi r_rod (axisymmetric) or the depth (Eq. 31). The residual is internal minus
  external force, so F_r is subtracted (+r pushes the seal away from the rod).
* optionally (``surface_normal=True``) the axial part of the pressure on the seal's own
  surface, on the u_z rows:

      F_z,i = -p_i A (r_{i+1} - r_{i-1}) / 2,   r_i = R_i + u_r,i,

  which makes F_i = p_i A (L_i, -(r_{i+1} - r_{i-1})/2) the lumped follower load of p on the
  current chain edges, F_e = p A (dy, -dr) split half to each node. In the thin film dr << dy
  and F_z is negligible, as the paper assumes; on the open, inclined inlet and outlet parts
  of the chain (gaps of 0.1 mm and more, p = p_in or p_out) the radial force alone has a
  moment about the cross-section's centre and, with frictionless walls, rolls an O-ring in
  its groove (seen in a quasi-static pressurisation of the coarse O-ring).

Exact Jacobian (the chain rule through the gap provider, docs/design.md):

* dq_e/dp_a = 1/(L I1), dq_e/dp_b = -1/(L I1) and dq_e/dh_a, dq_e/dh_b from
  :func:`sealts.film.reynolds_fv.element_fluxes`, with dh/du_r = 1;
* dq_e/dL = (p_b - p_a) / (L^2 I1) (I1, I2 are averages over the element in its own
  coordinate, independent of L) plus the upwinded share's through P_e, from
  :func:`element_fluxes`, with dL/du_z,b = c_e, dL/du_z,a = -c_e, c_e = dy_e / L_e;
* the storage S_i = M_i h_eff'(h_i) dh_i/dt: dS/dh_i from :func:`storage`, dS/d(dh_i/dt)
  = M_i h_eff'(h_i) times the TS ``shift`` on u_r,i (dh'/du' = 1), and through M_i
  dS/du_z,i+1 = c_{i+1/2} / 2, dS/du_z,i-1 = -c_{i-1/2} / 2, dS/du_z,i = (c_{i-1/2} -
  c_{i+1/2}) / 2, each times h_eff'(h_i) dh_i/dt;
* dF_r,i/dp_i = A L_i, dF_r,i/du_z,hi = p_i A / 2, dF_r,i/du_z,lo = -p_i A / 2;
  dF_z,i/dp_i = -A (r_hi - r_lo)/2, dF_z,i/du_r,hi = -p_i A / 2, dF_z,i/du_r,lo = p_i A / 2.

* with ``shear=True`` (the paper's model), the fluid shear force on the u_z rows
  (Eq. 32-34), positive in +y, the rod's direction of motion for v > 0:

      tau_i = eta v / h_eff_i - (h_eff_i / 2) (dp/dy)_i - eta (d(dh/dt)/dy)_i,   (Eq. 32)
      (dp/dy)_i = (c(h_i) - q_i) / k(h_i),                                     (Eq. 13)
      F_s,i = tau_i A L_i,                                                     (Eq. 34)

  with the nodal flow q_i the mean of the two element flows (the boundary flow at the ends,
  as :meth:`ControlVolumeScheme.pressure_gradient`) and the squeeze-rate gradient the
  beta-weighted difference of Eq. 33, as the film-only output
  (:func:`sealts.film.quantities.shear_stress`). Its Jacobian runs through the same flux
  derivatives, the storage at the ends, h in k, c and h_eff, the rates (TS shift) and the
  element lengths.
"""
import numba
import numpy as np

from ..core import Term
from .chain_film import ChainFilm
from .gap import h_eff
from .reynolds_fv import (conductance, element_fluxes, element_length,
                          element_lengths, storage)


@numba.njit(cache=True)
def nodal_conductance(h, eta, h_floor, model, par, th, tpp, tps):
    """Per node: h_eff, dh_eff/dh, 1/k, d(1/k)/dh, c/v, d(c/v)/dh (rows of a (6, n) array)."""
    out = np.empty((6, h.size))
    for i in range(h.size):
        out[0, i], out[1, i] = h_eff(h[i], h_floor)
        out[2, i], out[3, i], out[4, i], out[5, i] = conductance(h[i], eta, h_floor, model,
                                                                 par, th, tpp, tps)
    return out


class SealFilmTerm(ChainFilm):
    """The film on the seal's rod-side chain, coupled to the seal displacements.

    Owns the rows ``pdofs`` (film pressures, in chain order) and adds to the u_r rows of the
    chain nodes (and their u_z rows with ``surface_normal``). Columns: the chain's film
    pressures, u_r and u_z.
    """

    def __init__(self, side, pdofs, v, eta, p_in, p_out, ff=None, h_floor=1e-5,
                 squeeze=True, pressurised_end="min_z", h_ref=1e-3, surface_normal=False,
                 shear=True, beta=0.5, stiff=0.0):
        """``side``: the :class:`sealts.contact.rod_side.RodSide` (chain, dofs, rod, A);
        ``pdofs``, ``v``, ``eta``, ``p_in``, ``p_out``, ``ff``, ``h_floor``, ``squeeze``,
        ``pressurised_end``: as :class:`sealts.film.chain_film.ChainFilm`;
        ``surface_normal``: also the axial part of the pressure on the seal's inclined
        surface; ``shear``: the fluid shear force (Eq. 32-34) with the weight ``beta`` of
        Eq. 33 (module docstring); ``stiff`` (MPa): pi E' of the seal for the upwinded
        Couette flow (0: none). The film rows are scaled by their diagonal for the
        reference chain at a uniform gap ``h_ref`` (mm) until :meth:`set_row_scale` fixes
        them at a state."""
        super().__init__(side, pdofs, v, eta, p_in, p_out, ff, h_floor, squeeze,
                         pressurised_end)
        self.stiff = float(stiff)
        m = side.m
        ur, uz, pd = side.ur, side.uz, self.pd
        lo, hi = side.lo, side.hi
        a = np.arange(m - 1)
        b = a + 1
        # element flows: rows p_a (+q) and p_b (-q), columns p_a, p_b, u_r,a, u_r,b, u_z,a, u_z,b
        ecols = np.stack([pd[a], pd[b], ur[a], ur[b], uz[a], uz[b]], 1)
        erows = np.stack([a, b], 1)                                   # chain index of the row
        r6 = np.repeat(erows[:, :, None], 6, 2)                       # (e, 2, 6)
        c6 = np.repeat(ecols[:, None, :], 2, 1)
        self._ekeep = ((r6 != 0) & (r6 != m - 1)).ravel()
        i = np.arange(1, m - 1)                                       # interior nodes
        # storage: M_i dh_i/dt, M_i half the element lengths on either side
        self._rows_film = np.concatenate([r6.ravel()[self._ekeep], i, i, i, i])
        film_cols = np.concatenate([c6.ravel()[self._ekeep], ur[i], uz[i + 1], uz[i - 1],
                                    uz[i]])
        # nodal radial forces, the rod side's neighbours for L_i
        self.surface_normal = surface_normal
        rows = [pd[self._rows_film], [pd[0], pd[-1]], ur, ur, ur]
        cols = [film_cols, [pd[0], pd[-1]], pd, uz[hi], uz[lo]]
        if surface_normal:
            rows += [uz, uz, uz]
            cols += [pd, ur[hi], ur[lo]]
        self.shear, self.beta = shear, beta
        self.work_cols = np.zeros(0, np.int64)
        if shear:  # the pattern of the shear force, from the code that computes its values
            dummy = np.zeros(m)
            _, srows, scols, _ = self._shear(0.0, side.Z, dummy + 1e-3, dummy, dummy, 1.0,
                                             v=1.0)
            rows.append(uz[srows])
            cols.append(scols)
            self.work_cols = scols       # the friction work's columns (the shear's)
        self.rows = np.concatenate(rows).astype(np.int64)
        self.cols = np.concatenate(cols).astype(np.int64)
        self.row_scale = self._reference_row_scale(h_ref)

    def _reference_row_scale(self, h_ref):
        """1 / diagonal of the balance rows on the reference chain at the uniform gap h_ref."""
        ik = conductance(h_ref, self.eta, self.h_floor, *self._ffargs())[0]
        d = 1.0 / (element_lengths(self.side.Z)[0] * ik)               # 1 / (L I1) per element
        s = np.ones(self.side.m)
        s[1:-1] = 1.0 / (d[1:] + d[:-1])
        return s

    def set_row_scale(self, t, u, udot=None):
        """Fix each balance row's scale to 1 / its diagonal at this state (rows in MPa)."""
        y, h, hd, p = self.film(t, u, udot)
        _, dqa, dqb, _, _, _ = element_fluxes(y, h, p, self.v(t), self.eta, self.h_floor,
                                              *self._ffargs(), self.stiff)
        self.row_scale = np.ones(self.side.m)
        self.row_scale[1:-1] = 1.0 / (dqa[1:] - dqb[:-1])

    def _fluxes(self, t, y, h, hd, p, v=None):
        v = self.v(t) if v is None else v
        q, dqa, dqb, dha, dhb, dql = element_fluxes(y, h, p, v, self.eta, self.h_floor,
                                                    *self._ffargs(), self.stiff)
        s, ds_dh, ds_dhd = storage(y, h, hd, self.h_floor)
        return q, dqa, dqb, dha, dhb, s, ds_dh, ds_dhd, dql

    def balance(self, t, u, udot=None, fluxes=None):
        """The unscaled nodal balances M_i dh_eff_i/dt + q_{i+1/2} - q_{i-1/2} (mm^2/s), all
        nodes (the end ones are the boundary flows' reactions), and the element flows q."""
        if fluxes is None:
            fluxes = self._fluxes(t, *self.film(t, u, udot))
        q, s = fluxes[0], fluxes[5]
        r = s.copy()
        r[:-1] += q
        r[1:] -= q
        return r, q, s

    def flows(self, t, u, udot=None):
        """(Q_in, Q_out) in mm^3/s: the flow entering the film at the pressurised end and
        leaving at the other (Eq. 41); Q_in - Q_out = A d/dt sum_i M_i h_eff_i."""
        _, q, s = self.balance(t, u, udot)
        q_first, q_last = q[0] + s[0], q[-1] - s[-1]     # in +y at the two ends
        if self.pressurised_end == "min_z":
            return self.side.area * q_first, self.side.area * q_last
        return -self.side.area * q_last, -self.side.area * q_first

    def _shear(self, t, y, h, hd, p, shift, v=None, fluxes=None):
        """Fluid shear force on the chain nodes (Eq. 32-34, N, +y) and the COO parts of
        d(-F_s)/dU + shift d(-F_s)/dU': (F_s, rows as chain indices, cols, values).
        ``fluxes``: :meth:`_fluxes` at this state, if already known."""
        m, ur, uz, pd, A = self.side.m, self.side.ur, self.side.uz, self.pd, self.side.area
        v = self.v(t) if v is None else v
        eta, beta = self.eta, self.beta
        if fluxes is None:
            fluxes = self._fluxes(t, y, h, hd, p, v)
        q, dqa, dqb, dha, dhb, s, ds_dh, ds_dhd, dql = fluxes
        he, dhe, ik, dik, cv, dcv = nodal_conductance(h, eta, self.h_floor, *self._ffargs())
        L, cl = element_lengths(y)
        qn = np.empty(m)
        qn[1:-1] = 0.5 * (q[:-1] + q[1:])
        qn[0], qn[-1] = q[0] + s[0], q[-1] - s[-1]
        dpdy = (v * cv - qn) * ik
        dd = np.diff(hd) / L
        g = np.empty(m)
        g[0], g[-1] = dd[0], dd[-1]
        g[1:-1] = beta * dd[:-1] + (1.0 - beta) * dd[1:]
        tau = eta * v / he - 0.5 * he * dpdy - eta * g
        AL = A * self.lengths(y)
        F = tau * AL
        # d tau / d(h_i) at fixed q_i and g_i, d tau / d q_i, d tau / d g_i = -eta
        dtau_dh = (-eta * v * dhe / he**2 - 0.5 * dhe * dpdy
                   - 0.5 * he * (v * dcv * ik + (v * cv - qn) * dik))
        cq = AL * 0.5 * he * ik
        cg = -eta * AL
        i = np.arange(m)
        a = np.arange(m - 1)
        b = a + 1
        rows, cols, vals = [i, i, i], [ur, uz[self.side.hi], uz[self.side.lo]], \
            [AL * dtau_dh, 0.5 * A * tau, -0.5 * A * tau]
        # q_i through the element flows: mean of two inside, the end elements' own at the ends
        wa = np.where(a == 0, 1.0, 0.5) * cq[a]
        wb = np.where(b == m - 1, 1.0, 0.5) * cq[b]
        dqL = dql * cl
        ecols = [pd[a], pd[b], ur[a], ur[b], uz[a], uz[b]]
        for col, d in zip(ecols, (dqa, dqb, dha, dhb, -dqL, dqL)):
            rows += [a, b]
            cols += [col, col]
            vals += [wa * d, wb * d]
        # q_1 = q_3/2 + S_1 and q_n = q_n-1/2 - S_n: the end storage, M = half an element
        for k, nb, sign, e in ((0, 1, 1.0, 0), (m - 1, m - 2, -1.0, m - 2)):
            c = sign * cq[k]
            rate = dhe[k] * hd[k] * cl[e]
            rows += [[k], [k], [k]]
            cols += [[ur[k]], [uz[nb]], [uz[k]]]
            side = 1.0 if nb > k else -1.0
            vals += [[c * (ds_dh[k] + shift * ds_dhd[k])], [c * 0.5 * side * rate],
                     [-c * 0.5 * side * rate]]
        # the squeeze-rate gradient: d_e = (hd_b - hd_a) / L_e, weighted as in Eq. 33
        ga = np.where(a == 0, 1.0, 1.0 - beta) * cg[a]
        gb = np.where(b == m - 1, 1.0, beta) * cg[b]
        for col, d in zip((ur[a], ur[b], uz[a], uz[b]),
                          (-shift / L, shift / L, dd / L * cl, -dd / L * cl)):
            rows += [a, b]
            cols += [col, col]
            vals += [ga * d, gb * d]
        rows = np.concatenate(rows)
        cols = np.concatenate(cols)
        vals = -np.concatenate(vals)                  # the residual subtracts the force
        return F, rows, cols, vals

    def shear_forces(self, t, u, udot=None):
        """Axial fluid shear force on each chain node (N, +y), Eq. 32-34 (computed whether
        or not ``shear`` puts it into the residual)."""
        y, h, hd, p = self.film(t, u, udot)
        return self._shear(t, y, h, hd, p, 0.0)[0]

    # ---- Term interface ------------------------------------------------------------------
    def add_residual(self, t, u, udot, f):
        y, h, hd, p = self.film(t, u, udot)
        fluxes = self._fluxes(t, y, h, hd, p)
        r, _, _ = self.balance(t, u, udot, fluxes)
        r = r * self.row_scale
        r[0] = p[0] - self.p_first(t)
        r[-1] = p[-1] - self.p_last(t)
        np.add.at(f, self.pd, r)
        np.subtract.at(f, self.side.ur, self.forces(t, u))
        if self.surface_normal:
            np.subtract.at(f, self.side.uz, self.axial_forces(t, u))
        if self.shear:
            F = self._shear(t, y, h, hd, p, 0.0, fluxes=fluxes)[0]
            np.subtract.at(f, self.side.uz, F)
            if self.work is not None:              # the friction work's row: -v sum F
                f[self.work[0]] -= self.work[1](t) * F.sum()

    def jacobian_values(self, t, u, udot, shift):
        y, h, hd, p = self.film(t, u, udot)
        fluxes = self._fluxes(t, y, h, hd, p)
        q, dqa, dqb, dha, dhb, s, ds_dh, ds_dhd, dql = fluxes
        L, c = element_lengths(y)
        dqL = dql * c                                    # dq/dy_b = dq/dL dL/dy_b
        d = np.stack([dqa, dqb, dha, dhb, -dqL, dqL], 1)  # per element, columns as the pattern
        ev = np.stack([d, -d], 1).ravel()[self._ekeep]
        i = np.arange(1, self.side.m - 1)
        M = 0.5 * (L[i - 1] + L[i])
        rate = ds_dhd[i] / M * hd[i]                     # h_eff'(h_i) dh_i/dt = dS_i/dM_i
        shift_hd = shift if (self.squeeze and udot is not None) else 0.0
        sv = np.concatenate([ds_dh[i] + shift_hd * ds_dhd[i], 0.5 * rate * c[i],
                             -0.5 * rate * c[i - 1], 0.5 * rate * (c[i - 1] - c[i])])
        film = np.concatenate([ev, sv]) * self.row_scale[self._rows_film]
        A = self.side.area
        Li = self.lengths(y)
        vals = [film, [1.0, 1.0], -A * Li, -0.5 * A * p, 0.5 * A * p]
        if self.surface_normal:
            dr = self.lengths(self.side.R + u[self.side.ur])
            vals += [A * dr, 0.5 * A * p, -0.5 * A * p]
        if self.shear:
            sv = self._shear(t, y, h, hd, p, shift_hd, fluxes=fluxes)[3]
            vals.append(sv)
            if self.work is not None:              # d(-v sum F) = v times d(-F)
                vals.append(self.work[1](t) * sv)
        return np.concatenate(vals)


class LeakageTerm(Term):
    """The leakage volumes of a :class:`SealFilmTerm` as ODE unknowns (Eq. 41-42),

        dV_in/dt = Q_in,   dV_out/dt = Q_out,

    at the dofs ``vdofs`` = (V_in, V_out), so TS integrates them with the same BDF formula as
    the film: V_in - V_out then equals the growth of the film volume A sum M_i h_eff_i to the
    order of the change of M_i. The end flows in +y (Eq. 41, per unit circumference),

        q_first = q_1/2 + M_1 dh_eff_1/dt,      q_last = q_{n-1/2} - M_n dh_eff_n/dt,

    are Q_in = A q_first, Q_out = A q_last for a film pressurised at min z (signs and ends
    swap for max z). Exact Jacobian through the element flux q (p, h, L of the end element)
    and the storage (h, M, and dh/dt with the TS shift)."""

    def __init__(self, film, vdofs):
        self.film = film
        self.vd = np.asarray(vdofs, np.int64)
        f = film
        ur, uz, m = f.side.ur, f.side.uz, f.side.m
        # per end: the end element's p_a, p_b, u_r,a, u_r,b, u_z,a, u_z,b
        first = [f.pd[0], f.pd[1], ur[0], ur[1], uz[0], uz[1]]
        last = [f.pd[m - 2], f.pd[m - 1], ur[m - 2], ur[m - 1], uz[m - 2], uz[m - 1]]
        self._cols = (np.array(first), np.array(last))
        in_end = 0 if f.pressurised_end == "min_z" else 1
        self._ends = (in_end, 1 - in_end)                  # which end each V row reads
        self._sign = 1.0 if in_end == 0 else -1.0
        self.rows = np.concatenate([self.vd, np.repeat(self.vd, 6)])
        self.cols = np.concatenate([self.vd] + [self._cols[e] for e in self._ends])

    def _end_flows(self, t, u, udot, shift):
        """(q_first, q_last) and their derivatives by the six columns of each end element
        (plus shift times those by U')."""
        f = self.film
        y, h, hd, p = f.film(t, u, udot)
        q, dqa, dqb, dha, dhb, s, ds_dh, ds_dhd, dql = f._fluxes(t, y, h, hd, p)
        shift_hd = shift if (f.squeeze and udot is not None) else 0.0
        out = []
        for e, node, sgn in ((0, 0, 1.0), (-1, -1, -1.0)):
            L, c = element_length(y[e] - y[e - 1] if e == -1 else y[1] - y[0])
            dqL = dql[e] * c
            M = 0.5 * L
            rate = s[node] / M * c                          # dS/dM dM/dy_b
            d = np.array([dqa[e], dqb[e], dha[e], dhb[e], -dqL, dqL])
            ds = ds_dh[node] + shift_hd * ds_dhd[node]
            k = 2 if node == 0 else 3                       # u_r of the end node
            d[k] += sgn * ds
            d[4] += sgn * (-0.5 * rate)
            d[5] += sgn * 0.5 * rate
            out.append((q[e] + sgn * s[node], d))
        return out

    def flows(self, t, u, udot=None):
        """(Q_in, Q_out) in mm^3/s."""
        ends = self._end_flows(t, u, udot, 0.0)
        A, sg = self.film.side.area, self._sign
        return tuple(sg * A * ends[e][0] for e in self._ends)

    def add_residual(self, t, u, udot, f):
        q_in, q_out = self.flows(t, u, udot)
        f[self.vd[0]] += udot[self.vd[0]] - q_in
        f[self.vd[1]] += udot[self.vd[1]] - q_out

    def jacobian_values(self, t, u, udot, shift):
        ends = self._end_flows(t, u, udot, shift)
        A, sg = self.film.side.area, self._sign
        return np.concatenate([[shift, shift]] + [-sg * A * ends[e][1] for e in self._ends])
