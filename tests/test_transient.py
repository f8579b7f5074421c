"""Transient film: closed-form squeeze film, exact mass balance, leakage integrated in time."""
import numpy as np
import pytest
from petsc4py import PETSc

from closed_forms import slider_pressure, squeeze_plates_pressure, squeeze_plates_volumes
from conftest import Recorder, scene
from sealts.problem.film_model import FilmModel, solve_steady_film
from sealts.problem import Problem


def run_transient(s, t_end, dt0=1e-3, stops=()):
    model = FilmModel(s, transient=True)
    _, u_film, _ = solve_steady_film(s, t=0.0)
    u0 = model.initial_state(0.0)
    u0[:model.scheme.size] = u_film[:model.scheme.size]
    problem = Problem(model.n, [model.term])
    rec = Recorder()
    u = problem.transient(u0, 0.0, t_end, dt0, stops, observers=[rec])
    return model, u, {round(t, 12): uu for t, uu in rec.stops}, problem


@pytest.mark.parametrize("scheme", ["fv", "paper"])
def test_squeeze_plates_pressure_follows_closed_form(scheme):
    s = scene("squeeze_plates", film={"scheme": scheme, "elements": 100})
    model, u, snaps, problem = run_transient(s, 1.0, stops=(0.5,))
    g = s.gap
    for t, uu in snaps.items():
        h = g.h_min + g.squeeze_velocity * t
        exact = squeeze_plates_pressure(model.y, g.length, h, s.fluid.viscosity,
                                        g.squeeze_velocity)
        p = model.scheme.pressure(uu)
        # the pressure is a quadratic in y, which both schemes reproduce to round-off
        assert np.abs(p - exact).max() < 1e-9 * np.abs(exact).max(), t
    # q is linear in y and t here, so the volumes are exact up to the TS tolerance
    v_in, v_out = squeeze_plates_volumes(1.0, g.length, g.h_min, g.squeeze_velocity,
                                         s.rod.velocity, model.area)
    assert u[-2] == pytest.approx(v_in, rel=1e-7)
    assert u[-1] == pytest.approx(v_out, rel=1e-7)


@pytest.mark.parametrize("scheme", ["fv", "paper"])
def test_mass_balance_is_exact(scheme):
    """V_in - V_out equals the change of film volume A int h dy, to solver tolerance, with a
    squeeze rate that varies along the film (so Q_in - Q_out is not trivially constant) and
    a gap that enters the h_floor regularisation at the thin end."""
    T = 0.5
    s = scene("slider", analysis={"type": "transient", "t_end": T},
              gap={"tilt_rate": -0.0015, "squeeze_velocity": -0.001},
              film={"elements": 200, "scheme": scheme, "h_floor": 1e-4})
    model, u, snaps, _ = run_transient(s, T, stops=(0.2,))
    from sealts.film.quantities import effective_gap
    vol = lambda t: model.area * np.trapezoid(effective_gap(model.gap(t)[0], 1e-4), model.y)
    assert model.gap(T)[0].min() < 2e-4  # the regularised range is reached
    for t, uu in snaps.items():
        r = model.scalars(t, uu)
        assert r["film_volume"] == pytest.approx(vol(t), rel=1e-12)
        assert r["V_in"] - r["V_out"] == pytest.approx(vol(t) - vol(0.0), rel=1e-6)


def test_leakage_volume_matches_quadrature_of_closed_form_flow():
    """V_in(T) = int_0^T A q_in(t) dt with q_in from Eq. 43's integration constant, computed
    independently by Gauss-Legendre quadrature in time. The BDF error shrinks with -ts_rtol."""
    T = 0.5
    s = scene("slider", analysis={"type": "transient", "t_end": T}, film={"elements": 800})
    g = s.gap
    xg, wg = np.polynomial.legendre.leggauss(40)
    tq = 0.5 * T * (xg + 1.0)
    q = [slider_pressure(np.array([0.0]), g.length, g.h_min + g.s_h + g.squeeze_velocity * t,
                         g.s_h, s.rod.velocity, s.fluid.viscosity, g.squeeze_velocity)[1]
         for t in tq]
    v_exact = 0.5 * T * np.dot(wg, q) * g.width
    errs = []
    opts = PETSc.Options()
    for rtol in (1e-4, 1e-6):
        opts["ts_rtol"] = rtol
        opts["ts_atol"] = rtol * 1e-2
        try:
            model, u, _, _ = run_transient(s, T)
        finally:
            del opts["ts_rtol"]
            del opts["ts_atol"]
        errs.append(abs(u[-2] - v_exact) / abs(v_exact))
    # the remaining error at tight tolerance is the O(dy^2) spatial error of Q_in
    assert errs[1] < 2e-5, errs
    assert errs[1] <= errs[0], errs


class RefusesLongSteps:
    """A test term that reports a non-physical state (NaN) for steps longer than dt_max,
    as a real term does for an inverted element: TS must retry smaller, never accept."""

    def __init__(self, dt_max):
        self.rows = self.cols = np.zeros(0, np.int64)
        self.dt_max, self.t_prev = dt_max, 0.0

    def add_residual(self, t, u, udot, f):
        if t - self.t_prev > self.dt_max * (1 + 1e-12):
            f[0] = np.nan

    def jacobian_values(self, t, u, udot, shift):
        return np.zeros(0)

    def accepted(self, t, u):
        self.t_prev = t


def test_failed_steps_are_retried_smaller():
    s = scene("squeeze_plates", film={"elements": 50})
    model = FilmModel(s, transient=True)
    _, u_film, _ = solve_steady_film(s, t=0.0)
    u0 = model.initial_state(0.0)
    u0[:model.scheme.size] = u_film[:model.scheme.size]
    guard = RefusesLongSteps(0.05)
    problem = Problem(model.n, [model.term, guard])
    rec = Recorder()
    u = problem.transient(u0, 0.0, 1.0, 0.2, observers=[rec])
    times = [0.0] + [t for t, _ in rec.states]
    assert problem.counters.rejected >= 1
    assert times[-1] == pytest.approx(1.0)
    assert np.diff(times[1:]).max() <= 0.05 * (1 + 1e-9)
    # and the accepted solution is still right
    g = s.gap
    v_in, _ = squeeze_plates_volumes(1.0, g.length, g.h_min, g.squeeze_velocity,
                                     s.rod.velocity, model.area)
    assert u[-2] == pytest.approx(v_in, rel=1e-6)
