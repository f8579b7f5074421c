"""Element-mean stresses for output: the Cauchy stress of a solid term (Eq. 1-5 through
:func:`sealts.solid.neo_hooke.cauchy_stress`), with the Prony part of Eq. 9 where the material
is viscoelastic, its von Mises stress and its pressure, per cell."""
import numpy as np

from .neo_hooke import cauchy_stress


def element_stresses(solid, u, prony=None):
    """Element-mean Cauchy stress (rr, zz, tt, rz), von Mises and pressure (MPa) of the
    ``solid`` term at the state u of its layout, plus the Prony stress of ``prony``
    (:meth:`sealts.solid.viscoelastic.PronyTerm.viscous_cauchy`) if given."""
    f, P, p_el, _ = solid.state(u)
    s = cauchy_stress(f.reshape(-1, 5), P.reshape(-1, 5), np.repeat(p_el, 4))
    s = s.reshape(-1, 4, 4)
    if prony is not None:
        s = s + prony.viscous_cauchy(u)
    s = s.mean(1)
    rr, zz, tt, rz = s.T
    mises = np.sqrt(0.5 * ((rr - zz) ** 2 + (zz - tt) ** 2 + (tt - rr) ** 2) + 3 * rz**2)
    return s, mises, -(rr + zz + tt) / 3.0


def stress_cells(solid, u, prony=None):
    """The cell fields of ``element_stresses`` by name (MPa): von_mises, pressure and the
    Cauchy components sigma_rr, sigma_zz, sigma_tt, sigma_rz."""
    s, mises, pressure = element_stresses(solid, u, prony)
    return {"von_mises": mises, "pressure": pressure, "sigma_rr": s[:, 0],
            "sigma_zz": s[:, 1], "sigma_tt": s[:, 2], "sigma_rz": s[:, 3]}
