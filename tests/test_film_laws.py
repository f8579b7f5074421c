"""Flow factors (Patir-Cheng, table) and the asperity law: limits, continuity, derivatives."""
import math

import numpy as np
import pytest

from sealts.contact.asperity.exponential import asperity_pressure_array
from sealts.film.flow_factors import (H_LO, PATIR_CHENG_GAMMAS, FlowFactors,
                                      PATIR_CHENG_SHEAR, pressure_fit_floor)
from sealts.film.gap import h_eff

RQ = 2.15e-4


def fd(f, h, eps):
    return (f(h + eps) - f(h - eps)) / (2 * eps)


@pytest.mark.parametrize("gamma", PATIR_CHENG_GAMMAS)
def test_patir_cheng_smooth_film_limit(gamma):
    pp, _, ps, _ = FlowFactors.patir_cheng(RQ, gamma).evaluate(np.array([200 * RQ]))
    assert pp[0] == pytest.approx(1.0, abs=2e-3)
    assert abs(ps[0]) < 1e-6


@pytest.mark.parametrize("gamma", PATIR_CHENG_GAMMAS)
def test_patir_cheng_pressure_factor_monotone_positive(gamma):
    h = np.linspace(-5 * RQ, 50 * RQ, 5001)
    pp, dpp, _, _ = FlowFactors.patir_cheng(RQ, gamma).evaluate(h)
    assert np.all(pp > 0)
    if gamma <= 1:   # transverse/isotropic roughness obstructs pressure flow: rises to 1
        assert np.all(np.diff(pp) > 0) and np.all(dpp > 0)
    else:            # longitudinal roughness eases it: falls to 1
        assert np.all(np.diff(pp) < 0) and np.all(dpp < 0)


@pytest.mark.parametrize("gamma", PATIR_CHENG_GAMMAS)
def test_patir_cheng_continuity_and_derivatives(gamma):
    ff = FlowFactors.patir_cheng(RQ, gamma)
    e = 1e-9 * RQ
    hp = pressure_fit_floor(gamma)
    for H in (H_LO, hp, 5.0):
        lo = ff.evaluate(np.array([(H - 1e-9) * RQ]))
        hi = ff.evaluate(np.array([(H + 1e-9) * RQ]))
        assert lo[0][0] == pytest.approx(hi[0][0], rel=1e-7)          # Phi_p
        tol = 1e-3 if H == 5.0 else 1e-7  # published Phi_s rows jump <= 0.08 % at H = 5
        assert lo[2][0] == pytest.approx(hi[2][0], rel=tol)
    # C1 at the extension points
    a = ff.evaluate(np.array([hp * RQ - e]))
    b = ff.evaluate(np.array([hp * RQ + e]))
    assert a[1][0] == pytest.approx(b[1][0], rel=1e-5)
    a = ff.evaluate(np.array([H_LO * RQ - e]))
    b = ff.evaluate(np.array([H_LO * RQ + e]))
    assert a[3][0] == pytest.approx(b[3][0], rel=1e-5)
    # analytic derivatives against central differences, away from the kinks
    h = np.array([-2.0, 0.2, 0.7, 1.3, 3.7, 8.0]) * RQ
    pp, dpp, ps, dps = ff.evaluate(h)
    eps = 1e-6 * RQ
    assert np.allclose(dpp, fd(lambda x: ff.evaluate(x)[0], h, eps), rtol=1e-5, atol=1e-8 / RQ)
    assert np.allclose(dps, fd(lambda x: ff.evaluate(x)[2], h, eps), rtol=1e-5, atol=1e-8 / RQ)


def test_shear_factor_published_values():
    """Spot check against the 1979 fit itself at H = 1 and 6 (isotropic row)."""
    a1_, a1, a2, a3, a2_ = PATIR_CHENG_SHEAR[1.0]
    ff = FlowFactors.patir_cheng(RQ, 1.0)
    _, _, ps, _ = ff.evaluate(np.array([1.0, 6.0]) * RQ)
    assert ps[0] == pytest.approx(a1_ * math.exp(-a2 + a3))
    assert ps[1] == pytest.approx(a2_ * math.exp(-1.5))


def test_table_interpolates_and_holds_ends(tmp_path):
    p = tmp_path / "ff.csv"
    p.write_text("h,phi_p,phi_s\n0.0,0.0,0.0\n0.001,0.5,0.4\n0.005,1.0,0.1\n")
    ff = FlowFactors.from_table(p, RQ)
    pp, dpp, ps, dps = ff.evaluate(np.array([-1.0, 0.0005, 0.003, 1.0]))
    assert np.allclose(pp, [0.0, 0.25, 0.75, 1.0])
    assert np.allclose(ps, [0.0, 0.2, 0.25, 0.1])
    assert np.allclose(dpp, [0.0, 500.0, 125.0, 0.0])


def test_asperity_law_values_and_c1():
    h_mix, p_mix = 7e-4, 15.0
    p, dp = asperity_pressure_array(np.array([0.0, h_mix, 2 * h_mix, -h_mix]), h_mix, p_mix)
    assert p[0] == pytest.approx(p_mix)
    assert p[1] == 0.0 and dp[1] == 0.0 and p[2] == 0.0
    assert p[3] > p[0]
    e = 1e-9 * h_mix
    pl, dl = asperity_pressure_array(np.array([h_mix - e]), h_mix, p_mix)
    assert abs(pl[0]) < 1e-12 and abs(dl[0]) < 1e-4
    h = np.linspace(-h_mix, 0.99 * h_mix, 7)
    _, d = asperity_pressure_array(h, h_mix, p_mix)
    num = fd(lambda x: asperity_pressure_array(x, h_mix, p_mix)[0], h, 1e-10)
    assert np.allclose(d, num, rtol=1e-6)
    assert np.all(d < 0)  # stiffer as the gap closes


def test_regularised_gap():
    hf = 1e-5
    for h in (3e-5, 2e-5, 1e-6, -1e-3):
        he, d = h_eff(h, hf)
        assert he >= hf and 0 < d <= 1
    assert h_eff(3e-5, hf) == (3e-5, 1.0)
    a, b = h_eff(2 * hf - 1e-15, hf), h_eff(2 * hf + 1e-15, hf)
    assert a[0] == pytest.approx(b[0]) and a[1] == pytest.approx(b[1])


def test_shear_stress_squeeze_gradient_term():
    """Eq. 32-33: with v = 0 and no pressure gradient only -eta d(dh/dt)/dy remains. For a
    quadratic dh/dt = b y^2 on a uniform grid, beta = 0.5 (central difference) is exact at
    interior nodes; beta = 1 (backward) is off by b dy."""
    from sealts.film.quantities import shear_stress
    y = np.linspace(0.0, 1.0, 11)
    b, eta = 3.0, 2.0
    hd = b * y**2
    h = np.full_like(y, 1e-3)
    tau = shear_stress(y, h, hd, np.zeros_like(y), 0.0, eta, 1e-6, 0.5)
    assert np.allclose(tau[1:-1], -eta * 2 * b * y[1:-1], rtol=1e-12)
    tau_b = shear_stress(y, h, hd, np.zeros_like(y), 0.0, eta, 1e-6, 1.0)
    assert np.allclose(tau_b[1:-1], -eta * (2 * b * y[1:-1] - b * 0.1), rtol=1e-12)


def test_asperity_law_tangent_continuation():
    """Below h = -h_mix the law continues along its tangent: C1 there, linear beyond."""
    h_mix, p_mix = 7e-4, 15.0
    e = 1e-12
    a = asperity_pressure_array(np.array([-h_mix + e, -h_mix - e]), h_mix, p_mix)
    assert a[0][0] == pytest.approx(a[0][1], rel=1e-8)
    assert a[1][0] == pytest.approx(a[1][1], rel=1e-8)
    assert a[0][0] == pytest.approx(p_mix * 2 * (math.e**2 - 1) / (math.e - 1))
    far, d = asperity_pressure_array(np.array([-0.1, -0.2]), h_mix, p_mix)
    assert np.isfinite(far).all() and d[0] == d[1] and far[1] > far[0]
