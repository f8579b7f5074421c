"""Prony series of the shear relaxation (paper Eq. 7-9), WLF shift (Eq. 11-12), and which
terms a scene must carry.

Relaxation function and moduli (Eq. 7, 9):

    g_R(t) = 1 - sum_i g_i (1 - exp(-t / tau_i)),   G(t) = G_0 g_R(t),
    G_0 = G_inf / (1 - sum_i g_i),

with G_inf = 2 C10 the long-term modulus of the scene's material. At temperature theta the
relaxation times are A(theta) tau_i (time-temperature superposition, reduced time
xi = int dt / A, Eq. 11) with the WLF shift (Eq. 12)

    log10 A(theta) = -C1 (theta - theta_0) / (C2 + theta - theta_0).

**Which terms a scene carries.** Over the scene's window of time scales [t_min, t_end]
(t_min: the shortest time over which its loading changes, e.g. the smallest step; t_end: its
duration), each term is one of

* relaxed: always at equilibrium, H_i = S_iso. Folded into the elastic response exactly
  (its g_i comes off the instantaneous modulus). It replaces g_i (1 - exp(-t/tau_i)) by g_i,
  an error in g_R(t) of g_i exp(-t/tau_i) <= g_i exp(-t_min/tau_i) for t >= t_min;
* frozen: never moves from its initial value H_i(0). It replaces g_i (1 - exp(-t/tau_i))
  by 0, an error of at most g_i (1 - exp(-t_end/tau_i)) for t <= t_end;
* active: carried as state.

``classify`` folds terms, cheapest error first, while the summed error bound stays below
``tol`` g_R(t_end), so the relaxation modulus is right to the relative tolerance ``tol``
everywhere in the window (g_R(t_end) is its smallest value there).
"""
from dataclasses import dataclass

import numpy as np

# Paper Table 2 (EPDM 75 Shore A): g_i, tau_i (s) at theta_0 = 25 C; WLF C1, C2 (K)
TABLE2_G = np.array([0.765357482, 0.071302271, 0.068352334, 0.021267334, 0.008342972,
                     0.005090134, 0.006856138, 0.006895512, 0.005312413, 0.003746052,
                     0.007091882, 0.000239139, 0.000326593, 0.008936099, 0.009158911])
TABLE2_TAU = np.array([3.81334e-9, 3.13697e-8, 2.58056e-7, 2.12285e-6, 1.74632e-5,
                       1.43658e-4, 1.181772e-3, 9.721619e-3, 7.9972999e-2, 0.657882226,
                       5.411939407, 44.52026064, 366.2372133, 3012.778778, 24784.03514])
TABLE2_WLF = (7.69, 157.74)


def wlf_shift(theta, theta_0, c1, c2):
    """A(theta) of Eq. 12 (1 at theta_0; > 1, slower, when colder)."""
    d = np.asarray(theta, float) - theta_0
    return 10.0 ** (-c1 * d / (c2 + d))


@dataclass(frozen=True)
class PronySeries:
    g: np.ndarray
    tau: np.ndarray   # s, at the reference temperature

    def __post_init__(self):
        g, tau = np.asarray(self.g, float), np.asarray(self.tau, float)
        if g.shape != tau.shape or g.ndim != 1:
            raise ValueError("prony: g and tau must be lists of the same length")
        if (g <= 0).any() or g.sum() >= 1.0 or (tau <= 0).any():
            raise ValueError("prony: need g_i > 0, sum g_i < 1 and tau_i > 0")
        object.__setattr__(self, "g", g)
        object.__setattr__(self, "tau", tau)

    @property
    def g_inf(self):
        """Long-term fraction 1 - sum g_i = G_inf / G_0."""
        return 1.0 - self.g.sum()

    def relaxation(self, t, shift=1.0):
        """g_R(t) (Eq. 7) with relaxation times shift * tau_i."""
        t = np.asarray(t, float)[..., None]
        return 1.0 - (self.g * (1.0 - np.exp(-t / (shift * self.tau)))).sum(-1)


@dataclass(frozen=True)
class Classification:
    relaxed: np.ndarray   # indices into the series
    frozen: np.ndarray
    active: np.ndarray
    error_bound: float    # bound on |g_R error| / g_R(t_end) over [t_min, t_end]

    def describe(self, series, shift=1.0):
        tau = shift * series.tau
        rows = [f"Prony terms: {len(self.active)} active, {len(self.relaxed)} relaxed, "
                f"{len(self.frozen)} frozen of {len(tau)} (relative modulus error <= "
                f"{self.error_bound:.2g})"
                + ("" if shift == 1.0 else f"; tau shown times the WLF factor {shift:.3g}")]
        for name, idx in (("active", self.active), ("relaxed", self.relaxed),
                          ("frozen", self.frozen)):
            if len(idx):
                rows.append(f"  {name:8s} tau = " + ", ".join(f"{tau[i]:.3g}" for i in idx)
                            + " s")
        return "\n".join(rows)


def classify(series, t_min, t_end, tol, shift=1.0):
    """Relaxed / frozen / active terms for loading over [t_min, t_end] (s) within ``tol``.

    ``shift``: the WLF factor A, or its range (A_min, A_max) when the temperature varies:
    a term must then be relaxed at its slowest and frozen at its fastest."""
    if not 0.0 < t_min <= t_end:
        raise ValueError("prony classification needs 0 < t_min <= t_end")
    lo, hi = (shift, shift) if np.isscalar(shift) else (min(shift), max(shift))
    g = series.g
    err_relaxed = g * np.exp(-t_min / (hi * series.tau))
    err_frozen = g * -np.expm1(-t_end / (lo * series.tau))
    err = np.minimum(err_relaxed, err_frozen)
    shift = hi
    budget = tol * float(series.relaxation(t_end, shift))
    kind = np.full(len(g), "active", dtype=object)
    spent = 0.0
    for i in np.argsort(err, kind="stable"):
        if spent + err[i] > budget:
            break
        spent += err[i]
        kind[i] = "relaxed" if err_relaxed[i] <= err_frozen[i] else "frozen"
    pick = [np.nonzero(kind == k)[0] for k in ("relaxed", "frozen", "active")]
    return Classification(*pick, error_bound=spent / float(series.relaxation(t_end, shift)))
