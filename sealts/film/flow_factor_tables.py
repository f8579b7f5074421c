"""The flow-factor models' data, without numba (the scene checker reads it): Patir and
Cheng's published fit coefficients per Peklenik number gamma, and the reader of a
tabulated model's CSV. The models themselves are in :mod:`sealts.film.flow_factors`."""
import csv
from pathlib import Path

import numpy as np

# gamma: (C, r) for Phi_p (1978); (A1, a1, a2, a3, A2) for Phi_s (1979)
PATIR_CHENG_PRESSURE = {
    1 / 9: (1.48, 0.42), 1 / 6: (1.38, 0.42), 1 / 3: (1.18, 0.42), 1.0: (0.90, 0.56),
    3.0: (0.225, 1.5), 6.0: (0.520, 1.5), 9.0: (0.870, 1.5),
}
PATIR_CHENG_SHEAR = {
    1 / 9: (2.046, 1.12, 0.78, 0.03, 1.856), 1 / 6: (1.962, 1.08, 0.77, 0.03, 1.754),
    1 / 3: (1.858, 1.01, 0.76, 0.03, 1.561), 1.0: (1.899, 0.98, 0.92, 0.05, 1.126),
    3.0: (1.560, 0.85, 1.13, 0.08, 0.556), 6.0: (1.290, 0.62, 1.09, 0.08, 0.388),
    9.0: (1.011, 0.54, 1.07, 0.08, 0.295),
}
PATIR_CHENG_GAMMAS = sorted(PATIR_CHENG_PRESSURE)
H_LO = 0.5  # lower end of the fits' validity, in units of Rq


def pressure_fit_floor(gamma):
    """H below which the Phi_p fit is replaced by its extension."""
    return 1.0 if gamma < 0.3 else H_LO


def tabulated_gamma(gamma):
    """The tabulated Peklenik number equal to gamma (to 1e-6), or None."""
    for g in PATIR_CHENG_GAMMAS:
        if abs(gamma - g) <= 1e-6 * g:
            return g
    return None


def read_table(path):
    """Read a flow-factor CSV with header ``h,phi_p,phi_s``; h in mm, strictly increasing."""
    path = Path(path)
    try:
        with path.open(newline="") as f:
            rows = list(csv.DictReader(f))
    except (OSError, UnicodeDecodeError) as e:
        raise ValueError(f"{path}: cannot be read ({e})") from None
    if not rows or not {"h", "phi_p", "phi_s"} <= set(rows[0]):
        raise ValueError(f"{path}: needs the columns h, phi_p, phi_s")
    try:
        h = np.array([float(r["h"]) for r in rows])
        pp = np.array([float(r["phi_p"]) for r in rows])
        ps = np.array([float(r["phi_s"]) for r in rows])
    except (TypeError, ValueError):
        raise ValueError(f"{path}: every h, phi_p, phi_s must be a number") from None
    if not (np.all(np.isfinite(h)) and np.all(np.isfinite(pp)) and np.all(np.isfinite(ps))):
        raise ValueError(f"{path}: values must be finite")
    if h.size < 2 or np.any(np.diff(h) <= 0):
        raise ValueError(f"{path}: h must be strictly increasing with at least two rows")
    if np.any(pp < 0):
        raise ValueError(f"{path}: phi_p must be >= 0")
    return h, pp, ps
