"""The film as a physics term of :class:`sealts.problem.Problem`.

Its unknowns are the film scheme's (nodal pressures, plus c0 and y0 for the paper scheme),
at ``offset`` in U. With ``leakage_offset`` it also carries the two leakage volumes through
the film's ends as ODE unknowns,

    dV_in/dt = A Q_in,   dV_out/dt = A Q_out     (Eq. 41-42),

so the TS integrates them with the same adaptive order and step as everything else (TS
quadrature is not available with BDF). V_in counts flow entering at the p_in end, V_out flow
leaving at the p_out end; V_in - V_out is the change of film volume.
"""
import numpy as np

from ..core import Term


class RigidGap:
    """A rigid tapered gap closing at a rate that may vary linearly along the film:

        h = h_min + s_h (1 - xi) + (hdot + tilt (xi - 1/2)) t,   xi = (y - y_1) / l.
    """

    def __init__(self, y, h_min, s_h, hdot, tilt=0.0):
        y = np.asarray(y, float)
        xi = (y - y[0]) / (y[-1] - y[0])
        self.shape = h_min + s_h * (1.0 - xi)
        self.rate = hdot + tilt * (xi - 0.5)

    def __call__(self, t, u=None, udot=None):
        return self.shape + self.rate * t, self.rate.copy()


class FilmTerm(Term):
    def __init__(self, scheme, gap, offset=0, leakage_offset=None, area=1.0, squeeze=True):
        self.scheme, self.gap, self.area, self.squeeze = scheme, gap, area, squeeze
        self.off = offset
        self.iv = leakage_offset
        r, c = scheme.pattern
        rows, cols = [r + offset], [c + offset]
        if self.iv is not None:
            qi, qo = scheme.q_cols
            rows += [[self.iv], np.full(qi.size, self.iv), [self.iv + 1],
                     np.full(qo.size, self.iv + 1)]
            cols += [[self.iv], qi + offset, [self.iv + 1], qo + offset]
        self.rows = np.concatenate(rows).astype(np.int64)
        self.cols = np.concatenate(cols).astype(np.int64)

    def film(self, t, u, udot=None):
        """(x, h, dh/dt) of the film at time t, dh/dt zero when the squeeze term is off."""
        h, hd = self.gap(t, u, udot)
        if not self.squeeze:
            hd = np.zeros_like(hd)
        return u[self.off:self.off + self.scheme.size], h, hd

    def add_residual(self, t, u, udot, f):
        x, h, hd = self.film(t, u, udot)
        r, qin, qout = self.scheme.residual(t, x, h, hd)
        f[self.off:self.off + self.scheme.size] += r
        if self.iv is not None:
            f[self.iv] += udot[self.iv] - self.area * qin
            f[self.iv + 1] += udot[self.iv + 1] - self.area * qout

    def jacobian_values(self, t, u, udot, shift):
        x, h, hd = self.film(t, u, udot)
        vals, (dqi, dqo) = self.scheme.jacobian(t, x, h, hd)
        if self.iv is None:
            return vals
        return np.concatenate([vals, [shift], -self.area * dqi, [shift], -self.area * dqo])

    def flows(self, t, u):
        """(Q_in, Q_out) in mm^3/s."""
        x, h, hd = self.film(t, u)
        _, qin, qout = self.scheme.residual(t, x, h, hd)
        return self.area * qin, self.area * qout
