"""Film-only scenes: a film on a rigid gap (``model = "film"``), its nodes, scheme and term.

Data flow: scene -> film nodes y -> scheme (unknown layout) -> FilmTerm -> Problem. The
film-only steps (:mod:`sealts.steps.film`) solve it steady (SNES) or transient (TS).
"""
import numpy as np

from ..contact.asperity import law_from_scene
from ..film.flow_factors import FlowFactors
from ..film.paper_scheme import PaperScheme
from ..film.quantities import (contact, effective_gap, integrate, shear_stress,
                               specific_area)
from ..film.reynolds_fv import ControlVolumeScheme, control_volumes
from ..film.term import FilmTerm, RigidGap
from .problem import Problem


def flow_factors_of(film):
    if film.flow_factors == "patir-cheng":
        return FlowFactors.patir_cheng(film.rq, film.gamma, film.rough_surface)
    if film.flow_factors == "table":
        return FlowFactors.from_table(film.table, film.rq, film.rough_surface)
    return FlowFactors.none()


class FilmModel:
    """A scene's film: nodes, scheme and term, with the quantities engineers read off it."""

    def __init__(self, scene, transient=None):
        self.scene = scene
        g, f, fl = scene.gap, scene.film, scene.fluid
        self.y = np.linspace(0.0, g.length, f.elements + 1)
        v = float(scene.rod.velocity)
        self.v_of_t = lambda t: v
        args = (self.y, fl.viscosity, self.v_of_t, fl.p_in, fl.p_out, flow_factors_of(f),
                f.h_floor)
        self.scheme = (PaperScheme(*args, alpha=f.alpha) if f.scheme == "paper"
                       else ControlVolumeScheme(*args))
        self.gap = RigidGap(self.y, g.h_min, g.s_h, g.squeeze_velocity, g.tilt_rate)
        self.area = specific_area(g.symmetry, g.width, scene.rod.radius)
        if transient is None:
            transient = scene.analysis.type == "transient"
        self.transient = transient
        self.n = self.scheme.size + (2 if transient else 0)
        self.term = FilmTerm(self.scheme, self.gap, 0,
                             self.scheme.size if transient else None, self.area, f.squeeze)

    def initial_state(self, t0):
        u = np.zeros(self.n)
        u[:self.scheme.size] = self.scheme.initial_guess()
        self.scheme.set_row_scale(t0, *self.term.film(t0, u))
        return u

    def profile(self, t, u):
        """Nodal film profile at time t: dict of arrays (mm, MPa)."""
        s = self.scene
        x, h, hd = self.term.film(t, u)
        p = self.scheme.pressure(x)
        dpdy = self.scheme.pressure_gradient(t, x, h, hd)
        v = self.v_of_t(t)
        tau = shear_stress(self.y, h, hd, dpdy, v, s.fluid.viscosity, s.film.h_floor,
                           s.film.beta)
        prof = {"y": self.y, "h": h, "p": p, "tau": tau}
        if s.asperity.enabled:
            a = s.asperity
            prof["p_asperity"], prof["tau_solid"] = contact(h, v, law_from_scene(a), a.mu_s)
        return prof

    def scalars(self, t, u):
        """Key results at time t: peak pressure, load, friction, flows, film volume."""
        prof = self.profile(t, u)
        y, p = prof["y"], prof["p"]
        i = int(np.argmax(p))
        y_pk, p_pk = y[i], p[i]
        if 0 < i < y.size - 1:  # parabola through the peak node and its neighbours
            a, b, c = np.polyfit(y[i - 1:i + 2] - y[i], p[i - 1:i + 2], 2)
            if a < 0:
                y_pk, p_pk = y[i] - b / (2 * a), c - b * b / (4 * a)
        q_in, q_out = self.term.flows(t, u)
        out = {
            "t": float(t),
            "p_max": float(p_pk), "y_at_p_max": float(y_pk),
            "load": integrate(y, p, self.area),
            "friction_fluid": integrate(y, prof["tau"], self.area),
            "Q_in": float(q_in), "Q_out": float(q_out),
            "h_min": float(prof["h"].min()),
            "film_volume": self.area * float(control_volumes(y) @ effective_gap(
                prof["h"], self.scene.film.h_floor)),
        }
        if "p_asperity" in prof:
            out["load_asperity"] = integrate(y, prof["p_asperity"], self.area)
            out["friction_solid"] = integrate(y, prof["tau_solid"], self.area)
        if self.transient:
            out["V_in"], out["V_out"] = float(u[-2]), float(u[-1])
        return out


def solve_steady_film(scene, comm=None, t=None):
    """Film pressure at one time; returns (model, u, problem)."""
    model = FilmModel(scene, transient=False)
    t = scene.analysis.time if t is None else t
    u0 = model.initial_state(t)
    problem = Problem(model.n, [model.term], comm=comm)
    return model, problem.solve_steady(u0, t), problem
