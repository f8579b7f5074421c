"""Golden assembly data: F and J (with the TS shift) of today's problems at stored states,
for tests/test_golden_assembly.py after the driver-layer redesign (issue 13).

Runs with the sealts of this commit, from the repository root:
    .venv/bin/python tests/data/make_golden.py tests/data/golden_assembly.npz [MESH_CACHE]
It is removed again by the redesign, whose API it predates.
"""
import sys
from dataclasses import replace

import numpy as np

sys.path.insert(0, "tests")
from conftest import coarse_stroke, scene  # noqa: E402

from sealts.problem import Problem  # noqa: E402
from sealts.problem.hold_run import HoldStep  # noqa: E402
from sealts.problem.stroke_run import StrokeStep  # noqa: E402
from sealts.problem.seal_run import model_from_scene  # noqa: E402

out = {}
rng = np.random.default_rng(20261202)
cache = sys.argv[2] if len(sys.argv) > 2 else "/tmp/golden_mesh"
s = coarse_stroke(cache)
model = model_from_scene(s)
out["X"] = model.mesh.X
u_m = model.mount(t_hold=s.mount.t_hold, dt0=s.mount.dt)
u_p = model.pressurise(u_m, s.fluid.p_in, t0=s.mount.t_hold, t_hold=2 * s.mount.t_hold,
                       dt0=s.mount.dt, p_crit=s.fluid.p_crit)
out["u_mounted"], out["u_pressurised"] = u_m, u_p
out["reach"] = np.asarray(model.load.reach, float)


SEEDS = {"mount": 1, "pressurise": 2, "hold": 3, "stroke": 4, "stroke_paper_ve": 5}


def probes(name, n, ud_scale):
    """U' and three probe vectors of problem ``name``, from its seed."""
    r = np.random.default_rng(SEEDS[name])
    return ud_scale * r.standard_normal(n), r.standard_normal((3, n))


def record(name, problem, t, U, ud_scale, shift, extra=None):
    n = problem.n
    Ud, X = probes(name, n, ud_scale)
    F = problem.residual(t, U, Ud)
    vals = problem.jacobian_values(t, U, Ud, shift)
    rows, cols = problem._rows, problem._cols
    JX = np.stack([np.bincount(rows, vals * x[cols], minlength=n) for x in X])
    absJX = np.bincount(rows, np.abs(vals) * np.abs(X).max(0)[cols], minlength=n)
    out[f"{name}/t"], out[f"{name}/shift"], out[f"{name}/ud_scale"] = t, shift, ud_scale
    out[f"{name}/U"], out[f"{name}/F"] = U, F
    out[f"{name}/JX"], out[f"{name}/absJX"] = JX, absJX
    for k, v in (extra or {}).items():
        out[f"{name}/{k}"] = np.asarray(v, float)
    print(name, n, "unknowns, |F| =", np.linalg.norm(F), ", |JX| =", np.linalg.norm(JX))


def noisy(U, scale):
    return U + scale * rng.standard_normal(U.size)


# step 1: the mounting problem (stabilised), in the ramp
p = Problem(model.n, model.local_terms(model.walls(), stab=True), linesearch="basic",
            snes_atol=1e-9 * model.force_scale, dofs=model.dofs)
record("mount", p, 0.6, noisy(0.6 * u_m, 1e-4), 1e-2, 37.0)
# step 2: pressurisation (stabilised, the pressure load at its reach), in the ramp
p = Problem(model.n, model.local_terms(model.walls() + [model.load], stab=True),
            linesearch="basic", snes_atol=1e-9 * model.force_scale, dofs=model.dofs)
record("pressurise", p, 2.6, noisy(u_p, 1e-4), 1e-2, 41.0)
# step 3: the viscoelastic hold 1 -> 3 MPa
# one Prony term keeps the stored data small (16 internal variables per cell)
ve = replace(s.viscoelastic, prony="custom", prony_g=(0.5,), prony_tau=(1.0,))
hold = HoldStep(model, u_p, 1.0, 3.0, 1e-3, ve, 1e4)
record("hold", hold.problem, 4e-4, noisy(hold.U0, 1e-5), 1e-2, 900.0)
# step 3: the stroke, fv film with rod and groove friction, from its start
st = StrokeStep(model, u_p, s)
U = st.start()
st.friction.anchors = st.friction.anchors + 0.5e-4 * rng.standard_normal(
    st.friction.anchors.shape)
st.groove_friction.anchors = st.groove_friction.anchors + 0.5e-4 * rng.standard_normal(
    st.groove_friction.anchors.shape)
record("stroke", st.problem, 0.004, noisy(U, 1e-6), 1e-3, 2500.0,
       {"rod_anchors": st.friction.anchors, "groove_anchors": st.groove_friction.anchors,
        "row_scale": st.film.row_scale})
# step 3: the paper's film scheme, viscoelastic, flow factors, squeeze
s2 = replace(s, film=replace(s.film, scheme="paper", flow_factors="patir-cheng",
                             rq=2.15e-4, gamma=1.0, squeeze=True),
             viscoelastic=ve)
st2 = StrokeStep(model, u_p, s2)
U2 = st2.U0.copy()
lay = st2.layout
U2[lay.film_dofs] = np.linspace(1.0, 0.0, lay.film_dofs.size)
U2[st2.xdofs] = st2.film.constants(0.0, U2)
st2.film.set_row_scale(0.0, U2)
for fr in st2.frictions:
    fr.reset(0.0, U2)
record("stroke_paper_ve", st2.problem, 0.02, noisy(U2, 1e-6), 1e-3, 700.0, {"rod_anchors": st2.friction.anchors,
               "groove_anchors": st2.groove_friction.anchors})
np.savez_compressed(sys.argv[1], **out)
