"""Finite-difference checks of every film Jacobian.

The assembled IJacobian J = dF/dU + shift dF/dU' is compared with central differences of the
residual in U and U', entry by entry; the stated bound is on max|J - J_fd| / max|J| per row
block. The flux derivatives with respect to the gap (used when the film couples to the seal)
are checked the same way, across the h_floor regularisation and the flow-factor extension.
"""
import numpy as np
import pytest

from conftest import scene
from sealts.film.flow_factors import FlowFactors
from sealts.film.reynolds_fv import element_fluxes, storage
from sealts.problem import Problem
from sealts.problem.film_model import FilmModel

FD_REL = 1e-6


def fd_jacobian(problem, t, u, ud, shift, eps_u, eps_ud):
    n = problem.n
    J = np.zeros((n, n))
    for j in range(n):
        e = np.zeros(n)
        e[j] = eps_u[j]
        J[:, j] = (problem.residual(t, u + e, ud) - problem.residual(t, u - e, ud)) / (2 * e[j])
        e[j] = eps_ud[j]
        J[:, j] += shift * (problem.residual(t, u, ud + e)
                            - problem.residual(t, u, ud - e)) / (2 * e[j])
    return J


@pytest.mark.parametrize("scheme", ["fv", "paper"])
@pytest.mark.parametrize("factors", ["none", "patir-cheng"])
def test_problem_jacobian(scheme, factors):
    s = scene("slider", analysis={"type": "transient", "t_end": 0.5},
              fluid={"p_in": 1.0, "p_out": 0.2},
              gap={"h_min": 3e-4, "squeeze_velocity": -1e-4},
              film={"scheme": scheme, "elements": 12, "flow_factors": factors, "rq": 2e-4,
                    "h_floor": 1e-4})
    model = FilmModel(s, transient=True)
    u = model.initial_state(0.0)
    rng = np.random.default_rng(0)
    u[:model.scheme.n] += rng.uniform(-0.3, 0.3, model.scheme.n)
    if scheme == "paper":
        u[model.scheme.n:model.scheme.n + 2] = [0.01, 6.3]
    u[-2:] = [0.1, -0.2]
    ud = rng.uniform(-1, 1, model.n)
    problem = Problem(model.n, [model.term])
    shift = 37.0
    J = problem.jacobian_dense(0.1, u, ud, shift)
    scale = np.maximum(np.abs(u), 1e-3) * 1e-6
    Jfd = fd_jacobian(problem, 0.1, u, ud, shift, scale, np.full(model.n, 1e-6))
    err = np.abs(J - Jfd).max() / np.abs(J).max()
    assert err < FD_REL, err


@pytest.mark.parametrize("factors,stiff", [("none", 0.0), ("patir-cheng", 0.0), ("table", 0.0),
                                           ("patir-cheng", 38.0), ("none", 3800.0)])
def test_flux_derivatives_in_gap(factors, stiff, tmp_path):
    rq = 2.15e-4
    if factors == "patir-cheng":
        ff = FlowFactors.patir_cheng(rq, 1 / 3)
    elif factors == "table":
        p = tmp_path / "t.csv"
        p.write_text("h,phi_p,phi_s\n-0.001,0.01,0.0\n0.0005,0.3,0.6\n0.003,1.0,0.05\n")
        ff = FlowFactors.from_table(p, rq)
    else:
        ff = FlowFactors.none()
    y = np.linspace(0.0, 1.0, 9) ** 1.3
    # gaps from open film down through the regularised range to asperity overlap
    h = np.array([2e-3, 1.1e-3, 7e-4, 3.3e-4, 4.1e-5, 1.3e-5, -2e-5, -3e-4, 1.7e-4])
    p = np.linspace(1.0, 0.0, 9) + 0.1 * np.sin(7 * y)
    # stiff: the upwinded Couette flow, element Peclet numbers ~0.05..1e9 (38) or 100x less
    args = (50.0, 1e-8, 1e-5, ff.model, ff.par, ff.table_h, ff.table_pp, ff.table_ps, stiff)
    q, dqa, dqb, dha, dhb, dql = element_fluxes(y, h, p, *args)
    # dq/dL through the element lengths, moving each node (y) in turn
    for k in range(y.size):
        e = np.zeros_like(y)
        e[k] = 1e-8
        dy = (element_fluxes(y + e, h, p, *args)[0] - element_fluxes(y - e, h, p, *args)[0]) \
            / 2e-8
        ana = np.zeros_like(q)
        if k < q.size:
            ana[k] -= dql[k]
        if k > 0:
            ana[k - 1] += dql[k - 1]
        assert np.allclose(ana, dy, rtol=1e-5, atol=1e-7 * np.abs(dql).max()), k
    eps = 1e-9
    for k in range(h.size):
        e = np.zeros_like(h)
        e[k] = eps
        dq = (element_fluxes(y, h + e, p, *args)[0] - element_fluxes(y, h - e, p, *args)[0]) \
            / (2 * eps)
        ana = np.zeros_like(q)
        if k < q.size:
            ana[k] += dha[k]
        if k > 0:
            ana[k - 1] += dhb[k - 1]
        assert np.allclose(ana, dq, rtol=1e-5, atol=1e-7 * np.abs(q).max()), k
        e[k] = 1e-7
        dqp = (element_fluxes(y, h, p + e, *args)[0] - element_fluxes(y, h, p - e, *args)[0]) \
            / 2e-7
        anap = np.zeros_like(q)
        if k < q.size:
            anap[k] += dqa[k]
        if k > 0:
            anap[k - 1] += dqb[k - 1]
        assert np.allclose(anap, dqp, rtol=1e-6, atol=1e-9 * np.abs(dqa).max())
    hd = np.linspace(-1, 1, 9) * 1e-3
    s, ds_dh, ds_dhd = storage(y, h, hd, 1e-5)
    num = (storage(y, h + 1e-10, hd, 1e-5)[0] - storage(y, h - 1e-10, hd, 1e-5)[0]) / 2e-10
    assert np.allclose(ds_dh, num, rtol=1e-5, atol=1e-12)
    assert np.allclose(ds_dhd * hd, s)
