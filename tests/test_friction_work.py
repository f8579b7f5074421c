"""The friction work as a TS unknown (sealts.contact.friction_work): its row's Jacobian in
the coupled stroke against central differences, for both film schemes and both friction
histories; and what TS integrates against the work summed over the accepted steps."""
import numpy as np
import pytest

from conftest import central_differences, scene, slips_off_the_kinks


@pytest.mark.parametrize("scheme, history", [("fv", "anchors"), ("paper", "state")])
def test_work_row_jacobian(tmp_path, scheme, history):
    """d/dU + shift d/dU' of the W row (its owner's dW/dt, the sources' -v F) on the rod side's u_r, u_z, film pressures (and
    the slips, the paper scheme's constants) against central differences in U and U', on a
    coarse O-ring chain spread from contact to open with film pressures and slips of both
    signs; bound 1e-6 of the row's largest entry."""
    from sealts.problem import Problem
    from sealts.problem.seal_model import model_from_scene
    from sealts.problem.stroke_problem import StrokeProblem
    s = scene("oring_stroke", film={"scheme": scheme},
              mesh={"h_contact": 0.1, "h_bulk": 0.4, "cache": str(tmp_path)},
              stroke={"velocity": "constant", "v_max": 100.0, "output_times": [],
                      "friction_history": history})
    model = model_from_scene(s)
    stroke = StrokeProblem(model, np.zeros(model.n), s)
    assert stroke.work is not None
    lay, X = stroke.layout, model.mesh.X
    c = lay.rod_nodes
    rng = np.random.default_rng(6)
    U = np.zeros(stroke.n)
    U[lay.udofs[c, 0]] = model.r_rod_final + np.linspace(-5e-4, 2e-3, c.size) - X[c, 0]
    U[lay.udofs[c, 1]] = rng.uniform(-1e-3, 1e-3, c.size)
    U[lay.film_dofs] = rng.uniform(0.0, 2.0, c.size)
    if history == "state":
        U[lay.slip_dofs] = slips_off_the_kinks(rng, c.size, s.stroke.gamma_crit)
    else:
        stroke.friction.anchors = stroke.friction.s(0.01) - U[lay.udofs[c, 1]] \
            + rng.uniform(-2e-4, 2e-4, c.size)
    if stroke.xdofs is not None:
        U[stroke.xdofs] = stroke.film.constants(0.0, U)
    stroke.film.set_row_scale(0.0, U)
    Ud = rng.uniform(-1.0, 1.0, stroke.n) * 1e-3
    t, shift = 0.01, 700.0
    p = Problem(stroke.n, [stroke.work] + stroke.work.sources)    # the row's owner and sources
    J = p.jacobian_dense(t, U, Ud, shift)
    blocks = {"ur": lay.udofs[c, 0], "uz": lay.udofs[c, 1], "p": lay.film_dofs}
    eps = {"ur": 1e-8, "uz": 1e-8, "p": 1e-7}
    if history == "state":
        blocks["z"], eps["z"] = lay.slip_dofs, 1e-6 * s.stroke.gamma_crit
    if stroke.xdofs is not None:
        blocks["x"], eps["x"] = stroke.xdofs, 1e-6
    fd_u, fd_ud = central_differences(p, t, U, Ud, blocks, eps, stroke.n)
    cols = np.concatenate(list(blocks.values()))
    w = stroke.work.wd
    row, fd = J[w, cols], fd_u[w, cols] + shift * fd_ud[w, cols]
    assert np.abs(row).max() > 0
    assert np.abs(row - fd).max() <= 1e-6 * np.abs(row).max()
    assert J[w, w] == shift


def test_work_is_the_integral_of_the_power(tmp_path):
    """The coarse stroke (ramp to 100 mm/s in 10 ms, held to 30 ms, friction on): W after it
    is the trapezoid of v (F_fluid + F_solid) over the accepted steps to 1 % (the
    trapezoid's own error, and the outputs' fluid shear without the squeeze rate, which the
    observer does not see), and positive: the rod drags the seal."""
    from conftest import Recorder, coarse_stroke, mount_and_pressurise, stroke_of
    s = coarse_stroke(tmp_path)
    state = mount_and_pressurise(s)
    step = stroke_of(state, s)
    rows = []                       # during the run: the friction anchors are the step's

    def on_step(t, U):
        rows.append((t, step.motion.v(t) * step.scalars(t, U)["friction_total"]))

    U = step.run(step.start(), s.stroke.t_end, s.stroke.dt, s.stroke.rtol,
                 observers=[Recorder(on_step)])
    t, power = np.array(rows).T
    W = U[step.work.wd]
    assert W > 0 and t.size > 20
    assert W == pytest.approx(np.trapezoid(power, t), rel=1e-2)
