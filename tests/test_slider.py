"""The rigid slider bearing (paper Table 1) against the closed form of Eq. 43.

Truth: tests/closed_forms.py integrates the Reynolds equation twice analytically; its peak,
2.75 MPa at 7.5 mm, is the paper's (Fig. 5).
"""
import numpy as np
import pytest

from closed_forms import slider_pressure
from conftest import scene
from sealts.problem.film_run import solve_steady_film

L, H1, SH, V, ETA, HD = 10.0, 0.003, 0.002, 100.0, 1e-8, -0.001


def solve(scheme="fv", elements=1000, **film):
    s = scene("slider", film={"scheme": scheme, "elements": elements, **film})
    model, u, _ = solve_steady_film(s)
    return model, u


def rel_error(model, u):
    p = model.scheme.pressure(u)
    exact, _ = slider_pressure(model.y, L, H1, SH, V, ETA, HD)
    return np.abs(p - exact).max() / np.abs(exact).max()


def test_default_resolution_matches_closed_form():
    model, u = solve()
    assert rel_error(model, u) < 1e-4


def test_peak_pressure_and_position():
    model, u = solve()
    r = model.scalars(0.0, u)
    assert r["p_max"] == pytest.approx(2.75, rel=1e-4)
    assert r["y_at_p_max"] == pytest.approx(7.5, abs=2e-3)


def test_flow_and_load_match_closed_form():
    model, u = solve()
    r = model.scalars(0.0, u)
    _, q0 = slider_pressure(np.array([0.0]), L, H1, SH, V, ETA, HD)
    # mass: flow leaving at y = l is the inlet flow plus the squeezed-out volume rate
    assert r["Q_in"] == pytest.approx(q0, rel=1e-6)
    assert r["Q_out"] == pytest.approx(q0 - HD * L, rel=1e-6)
    yy = np.linspace(0.0, L, 200001)
    pp, _ = slider_pressure(yy, L, H1, SH, V, ETA, HD)
    load = np.trapezoid(pp, yy)
    assert r["load"] == pytest.approx(load, rel=1e-5)


@pytest.mark.parametrize("scheme", ["fv", "paper"])
def test_second_order_convergence(scheme):
    ns = [20, 40, 80, 160]
    errs = [rel_error(*solve(scheme, n)) for n in ns]
    orders = np.log2(np.array(errs[:-1]) / np.array(errs[1:]))
    assert np.all(orders > 1.8) and np.all(orders < 2.3), (errs, orders)


def test_schemes_agree_under_refinement():
    gaps = []
    for n in (25, 100, 400):
        m1, u1 = solve("fv", n)
        m2, u2 = solve("paper", n)
        gaps.append(np.abs(m1.scheme.pressure(u1) - m2.scheme.pressure(u2)).max())
    assert gaps[1] < gaps[0] / 10 and gaps[2] < gaps[1] / 10, gaps


def test_paper_scheme_integration_constants():
    """c0 = 0 (no pressure drop across the film); y0 is where the hydrodynamic gradient
    vanishes, which is the pressure peak 7.5 mm."""
    model, u = solve("paper", 1000)
    c0, y0 = u[model.scheme.n], u[model.scheme.n + 1]
    assert abs(c0) < 1e-12
    assert y0 == pytest.approx(7.5, abs=1e-3)


@pytest.mark.parametrize("scheme", ["fv", "paper"])
def test_shear_stress_matches_closed_form(scheme):
    """Eq. 32 with the exact gradient h^3/(12 eta) p' = (v/2) h + hd y - q0."""
    model, u = solve(scheme, 1000)
    prof = model.profile(0.0, u)
    y = model.y
    _, q0 = slider_pressure(np.array([0.0]), L, H1, SH, V, ETA, HD)
    h = H1 - SH / L * y
    dpdy = 12 * ETA * (0.5 * V * h + HD * y - q0) / h**3
    tau = ETA * V / h - 0.5 * h * dpdy
    assert np.abs(prof["tau"] - tau).max() < 1e-4 * np.abs(tau).max()


def test_axisymmetric_area_is_rod_circumference():
    """Eq. 31: forces and flows scale with 2 pi r instead of the planar width."""
    planar = solve_steady_film(scene("slider"))
    axi = solve_steady_film(scene("slider", gap={"symmetry": "axisymmetric"},
                                  rod={"radius": 25.0}))
    a, b = planar[0].scalars(0.0, planar[1]), axi[0].scalars(0.0, axi[1])
    for key in ("load", "Q_in", "Q_out", "friction_fluid"):
        assert b[key] == pytest.approx(2 * np.pi * 25.0 * a[key], rel=1e-12)
    assert b["p_max"] == pytest.approx(a["p_max"], rel=1e-12)
