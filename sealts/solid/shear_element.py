"""One plane-strain element in prescribed simple shear, u_x = gamma(t) y: the viscoelastic
material test the tests and ``scripts/bench_prony.py`` compare with closed forms.

Every displacement is prescribed, so only the Prony internal variables evolve, and the
shear stress S12 = keep S_iso,12 - sum_active g_i H_i,12 (keep = 1 - sum_relaxed g) is
read at the Gauss points (the state is homogeneous). Relaxed terms are folded into the
elastic modulus and frozen ones dropped (from a virgin state their H stays 0), as
:class:`sealts.problem.hold_problem.HoldProblem` builds them.
"""
import numpy as np

from ..core import Constraints, Recorder
from ..problem import Problem
from .term import NeoHooke, SolidTerm
from .viscoelastic import PronyTerm, iso_stress

UNIT_SQUARE = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])


def shear_history(series, times, gamma, classes=None, shift=1.0, stops=(), c10_inf=1.064,
                  dt0=1e-10, rtol=1e-6, atol=1e-12):
    """S12 / G_0 at ``times`` under u_x = gamma(t) y from a virgin state (H = 0).

    ``gamma``: a number (a step at t = 0) or a function of t; ``classes``: a
    Classification (default: every term active); ``shift``: A or A(t). Returns the
    values and the Problem (for its counters)."""
    n = len(series.g)
    act = np.arange(n) if classes is None else classes.active
    rel = np.zeros(0, int) if classes is None else classes.relaxed
    keep = 1.0 - series.g[rel].sum()
    conn = np.array([[0, 1, 2, 3]])
    inst = NeoHooke(c10_inf / series.g_inf, 0.001)
    solid = SolidTerm(UNIT_SQUARE, conn, NeoHooke(inst.c10 * keep, 0.001), False)
    na = len(act)
    hdofs = 8 + np.arange(16 * na).reshape(1, -1)
    prony = PronyTerm(solid, inst, series.g[act], series.tau[act], hdofs,
                      shift=shift if callable(shift) else (lambda t: shift))
    shape = np.zeros(8)
    shape[0::2] = UNIT_SQUARE[:, 1]
    values = (lambda t: gamma(t) * shape) if callable(gamma) else gamma * shape
    problem = Problem(8 + hdofs.size, [solid, prony],
                      constraints=Constraints(np.arange(8), values))
    u0 = np.zeros(problem.n)
    u0[:8] = gamma(0.0) * shape if callable(gamma) else gamma * shape
    out = {}

    rec = Recorder()
    problem.transient(u0, 0.0, times[-1], dt0, stops=list(times[:-1]) + list(stops),
                      observers=[rec], rtol=rtol, atol=atol)
    for t, u in rec.stops:
        S = iso_stress(u[:8], conn, solid.B, inst.c10, 0.0)[0, 0]
        H = u[hdofs].reshape(4, na, 4)[0]
        out[t] = (keep * S[3] - series.g[act] @ H[:, 3]) / (2 * inst.c10)
    got = np.array([out[min(out, key=lambda s: abs(s - t))] for t in times])
    return got, problem
