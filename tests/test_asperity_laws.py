"""Asperity laws as objects (sealts/contact/asperity): Greenwood and Williamson's F_3/2
against an independent quadrature and a closed form, p_s(h) continuous, C1 and monotone,
the law's derivative its own, and the coupled stroke's Jacobian with it against central
differences."""
import math

import numpy as np
import pytest

from conftest import central_differences, scene, slips_off_the_kinks
from sealts.contact.asperity import ExponentialLaw, GreenwoodWilliamson, law_from_scene
from sealts.contact.asperity.greenwood_williamson import D_HI, D_LO


def tanh_sinh_moment(n, d, levels=7):
    """F_n(d) = (2 pi)^-1/2 int_0^inf x^n exp(-(x + d)^2 / 2) dx by the tanh-sinh rule on
    x in (0, X) (X past the Gaussian's tail): an independent method (another variable,
    another rule) for the table's Gauss-Legendre in t = x^1/2."""
    top = max(0.0, -d) + 9.0
    h = 2.0 ** -levels
    k = np.arange(-int(4.0 / h), int(4.0 / h) + 1) * h
    u = 0.5 * math.pi * np.sinh(k)
    x = 0.5 * top * (1.0 + np.tanh(u))
    w = 0.5 * top * 0.5 * math.pi * np.cosh(k) / np.cosh(u) ** 2
    f = x ** n * np.exp(-0.5 * (x + d) ** 2)
    return h * float(np.sum(w * f)) / math.sqrt(2.0 * math.pi)


def law(sigma=2.0e-4, modulus=8.5):
    return GreenwoodWilliamson(1e4, 0.02, sigma, modulus)


def test_f32_against_an_independent_quadrature_and_its_closed_form_at_zero():
    """Over the range used (d from D_LO = -30 to 4, where p_s is above 1e-8 of its value at
    d = 0), at table nodes and between them: relative error below 1e-8. At d = 0,
    F_3/2 = 2^(1/4) Gamma(5/4) / (2 pi)^(1/2)."""
    g = law(sigma=1.0, modulus=1.0)
    k = g.k
    d = np.concatenate([np.linspace(D_LO, 4.0, 83), [0.0, -12.345, 3.21, -29.99]])
    p, _ = g.pressure(d)
    exact = np.array([tanh_sinh_moment(1.5, x) for x in d])
    assert np.all(np.abs(p / k - exact) <= 1e-8 * exact)
    f0 = 2 ** 0.25 * math.gamma(1.25) / math.sqrt(2 * math.pi)
    assert g.pressure(np.array([0.0]))[0][0] / k == pytest.approx(f0, rel=1e-9)
    # deep in contact F_3/2 ~ |d|^3/2 (1 + 3 / (8 d^2)): the right growth at D_LO
    assert p[0] / k == pytest.approx(30 ** 1.5 * (1 + 3 / (8 * 900)), rel=1e-5)


def test_pressure_is_c1_monotone_and_its_derivative_is_its_own():
    """On a grid that crosses table nodes, D_LO and D_HI: p_s >= 0, never rising with h,
    zero from the contact gap D_HI sigma_s on; dp_s/dh equals central differences of p_s
    (1e-6 of the largest slope) and is continuous (no jump larger than the grid step
    allows); the exponential law the same way."""
    for lw in (law(), ExponentialLaw(7e-4, 15.0)):
        gap = lw.contact_gap
        h = np.linspace(-1.2 * (30 * 2e-4), 1.5 * gap, 200001)
        p, dp = lw.pressure(h)
        assert np.all(p >= 0.0) and np.all(np.diff(p) <= 0.0) and np.all(dp <= 0.0)
        assert np.all(p[h >= gap] == 0.0) and p[h < gap][-1] >= 0.0
        assert np.all(lw.touching(h) == (h < gap))
        e = 1e-9 * gap
        pp, _ = lw.pressure(h + e)
        pm, _ = lw.pressure(h - e)
        assert np.abs((pp - pm) / (2 * e) - dp).max() <= 1e-6 * np.abs(dp).max()
        step = h[1] - h[0]
        curvature = np.abs(np.diff(dp)).max() / step       # bounded: no jump in dp
        assert curvature * step <= 1e-3 * np.abs(dp).max()


def test_the_scene_chooses_the_law_and_its_modulus(tmp_path):
    """asperity.law picks the law; modulus = 0 takes the seal's E/(1 - nu^2) (4 G for an
    incompressible material, 3KG/(3K+G) ... here K/G ~ 940); GW keys without the GW law and
    a film scene's GW law without a modulus are one-line errors."""
    from sealts.scene import SceneError
    from sealts.solid.term import NeoHooke
    s = scene("oring_stroke", asperity={"law": "greenwood-williamson"},
              mesh={"cache": str(tmp_path)})
    mat = NeoHooke(s.material.c10, s.material.d1)
    gw = law_from_scene(s.asperity, mat)
    g, k = mat.shear_modulus, mat.bulk_modulus
    nu = (3 * k - 2 * g) / (2 * (3 * k + g))
    assert gw.modulus == pytest.approx(2 * g * (1 + nu) / (1 - nu ** 2), rel=1e-12)
    assert gw.modulus == pytest.approx(4 * g, rel=2e-3)
    assert mat.plane_strain_modulus == gw.modulus
    assert gw.contact_gap == D_HI * s.asperity.summit_sigma
    assert isinstance(law_from_scene(scene("oring_stroke").asperity), ExponentialLaw)
    with pytest.raises(SceneError, match="summit_radius is only used with"):
        scene("oring_stroke", asperity={"summit_radius": 0.05})
    with pytest.raises(SceneError, match="asperity.modulus must be > 0"):
        scene("slider", asperity={"law": "greenwood-williamson"})


def test_coupled_stroke_jacobian_with_greenwood_williamson(tmp_path):
    """The stroke's DAE with the GW law at a state whose rod-side gaps run from 20 sigma_s
    into the rod to beyond the contact gap: the terms the law enters (rod contact and
    friction, film, leakage; the seal's bulk left out, whose stiffness would hide them),
    every column of the rod side's u_r, u_z, film pressures and the rod friction's slips
    (from stick to flowing, off phi's and the flow's kinks) against central differences
    in U and U'; bound 1e-6 of each row block's largest entry."""
    from sealts.problem.seal_model import model_from_scene
    from sealts.problem.stroke_problem import StrokeProblem
    s = scene("oring_stroke", asperity={"law": "greenwood-williamson"},
              mesh={"h_contact": 0.1, "h_bulk": 0.4, "cache": str(tmp_path)},
              stroke={"velocity": "constant", "v_max": 100.0, "output_times": []})
    model = model_from_scene(s)
    stroke = StrokeProblem(model, np.zeros(model.n), s)
    assert isinstance(stroke.rod.law, GreenwoodWilliamson) and stroke.friction is not None
    lay, X = stroke.layout, model.mesh.X
    c = lay.rod_nodes
    sigma = s.asperity.summit_sigma
    h = sigma * np.linspace(-20.0, 8.0, c.size)
    rng = np.random.default_rng(5)
    U = np.zeros(stroke.n)
    U[lay.udofs[c, 0]] = model.r_rod_final + h - X[c, 0]
    U[lay.udofs[c, 1]] = rng.uniform(-1e-3, 1e-3, c.size)
    U[lay.film_dofs] = rng.uniform(0.0, 2.0, c.size)
    stroke.film.set_row_scale(0.0, U)
    U[lay.slip_dofs] = slips_off_the_kinks(rng, c.size, s.stroke.gamma_crit)
    Ud = rng.uniform(-1.0, 1.0, stroke.n) * 1e-3
    t, shift = 0.01, 700.0
    from sealts.problem import Problem
    p = Problem(stroke.n, [term for term in stroke.problem.terms if term is not stroke.solid])
    J = p.jacobian_dense(t, U, Ud, shift)
    blocks = {"ur": lay.udofs[c, 0], "uz": lay.udofs[c, 1], "p": lay.film_dofs,
              "z": lay.slip_dofs}
    eps = {"ur": 1e-4 * sigma, "uz": 1e-8, "p": 1e-7,    # the film rows curve strongly
           "z": 1e-6 * s.stroke.gamma_crit}
    fd_u, fd_ud = central_differences(p, t, U, Ud, blocks, eps, stroke.n)
    cols = np.concatenate(list(blocks.values()))
    fd = fd_u[:, cols] + shift * fd_ud[:, cols]
    for rows in blocks.values():
        ref = np.abs(J[np.ix_(rows, cols)]).max()
        assert np.abs(J[np.ix_(rows, cols)] - fd[rows]).max() <= 1e-6 * ref
