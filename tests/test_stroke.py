"""The coupled stroke (step 3): seal and film in one DAE, driven by the rod's velocity."""
import numpy as np
import pytest

from conftest import Recorder, coarse_stroke, mount_and_pressurise, stroke_of


@pytest.fixture(scope="module")
def stroke(tmp_path_factory):
    """The coarse O-ring at 1 MPa; the rod ramps to 100 mm/s outstroke in 10 ms and holds
    to 30 ms; no solid friction (tests/test_groove_friction.py runs it with friction) and no
    viscous stabilisation (the axial balance below is of the physical forces)."""
    cache = str(tmp_path_factory.mktemp("mesh"))
    s = coarse_stroke(cache, friction=False, stabilisation=0.0)
    state = mount_and_pressurise(s)
    step = stroke_of(state)
    U0 = step.start()
    rec = Recorder()
    U = step.run(U0, s.stroke.t_end, s.stroke.dt, s.stroke.rtol, observers=[rec])
    return step, U0, U, rec.states, (s, state)


def control_volumes(step, U):
    y = step.film.film(0.0, U)[0]
    m = np.zeros_like(y)
    m[:-1] += 0.5 * np.diff(y)
    m[1:] += 0.5 * np.diff(y)
    return m


def test_stroke_conserves_the_film_volume(stroke):
    """What entered minus what left is the film's growth: the leakage unknowns V_in, V_out
    (dV/dt = Q, integrated by TS with the film) against A sum_i M_i (h_i(end) - h_i(start)).
    The film is written in the seal's frame and neglects the nodes' axial velocity (Eq. 21),
    so its storage is M_i dh_i/dt with M_i following the nodes: the growth is summed step by
    step with the mean M of each step (the nodes move axially by microns; the wedges at the
    film's ends, 0.1-0.5 mm thick, make A h dM visible against the balance). Bound 1e-3 of
    the volume moved; the wedges' breathing makes that volume large against the growth."""
    step, U0, U, states, _ = stroke
    v_in, v_out = U[step.vdofs]
    growth = 0.0
    for (ta, Ua), (tb, Ub) in zip(states, states[1:]):
        m = 0.5 * (control_volumes(step, Ua) + control_volumes(step, Ub))
        dh = step.film.film(tb, Ub)[1] - step.film.film(ta, Ua)[1]
        growth += step.film.side.area * float(m @ dh)
    moved = max(abs(v_in), abs(v_out))
    assert moved > 0.05                                    # mm^3: the check has something
    assert v_in - v_out == pytest.approx(growth, abs=1e-3 * moved)


def test_stroke_lifts_the_seal_and_drags_it_along(stroke):
    """Hydrodynamics at 100 mm/s against the hydrostatic start: a pressure peak above p_in,
    a thicker film, less asperity load, and a fluid shear on the seal in the rod's
    direction (+y). The axial forces on the seal balance: the groove's side walls take the
    fluid's axial load (pressure-side flank, the film's surface-normal part) plus the
    shear."""
    step, U0, U, states, _ = stroke
    t = states[-1][0]
    a, b = step.scalars(0.0, U0), step.scalars(t, U)
    assert b["v"] == 100.0 and a["v"] == 0.0
    assert U[step.layout.film_dofs].max() > 1.2
    assert b["h_min"] > a["h_min"]
    assert b["load_asperity"] < a["load_asperity"]
    assert b["friction_fluid"] > 0.0
    walls = step.groove.reactions(t, U)
    fz = step.load.forces(t, U)
    fluid_z = (fz[:, 1].sum() + fz[:, 3].sum() + step.film.axial_forces(t, U).sum()
               + step.film.shear_forces(t, U, (U - states[-2][1]) / (t - states[-2][0])).sum())
    wall_z = walls["wall_pressure_side"] + walls["wall_atmosphere_side"]
    assert wall_z == pytest.approx(-fluid_z, rel=1e-6)


def test_viscoelastic_stroke_starts_relaxed(stroke):
    """With the Prony series of Table 2 the stroke starts from the relaxed state: the start is
    solved with the long-term material, so displacements and film equal the hyperelastic
    start's (to 1e-9 mm and 1e-9 MPa), and with every H_i = S_iso(u) and the frozen terms'
    stress set there, the viscoelastic DAE is in balance at t = 0 (no jump), and its Cauchy
    stress (elastic part plus -F sum g_i H_i F^T / J) is the long-term one (1e-9 of the
    largest)."""
    from dataclasses import replace
    step, U0, _, _, (s, state) = stroke
    model = state.model
    ve = replace(s.viscoelastic, prony="table2", t_min=1e-3)
    vstep = stroke_of(state, replace(s, viscoelastic=ve))
    assert len(vstep.viscoelastic.classes.active) > 0
    V0 = vstep.start()
    lay, vlay = step.layout, vstep.layout
    assert np.abs(V0[vlay.udofs] - U0[lay.udofs]).max() < 1e-9
    assert np.abs(V0[vlay.film_dofs] - U0[lay.film_dofs]).max() < 1e-9
    f = vstep.problem.residual(0.0, V0, np.zeros_like(V0))
    assert np.abs(f[vlay.prony_dofs]).max() < 1e-9 * model.force_scale
    assert np.abs(f[vlay.udofs]).max() < 10 * 1e-9 * model.force_scale
    from sealts.solid.stresses import element_stresses
    long_term = element_stresses(model.full_solid(), vstep.displacement(V0))[0]
    relaxed = element_stresses(vstep.solid, V0, vstep.prony)[0]
    elastic_only = element_stresses(vstep.solid, V0)[0]
    big = np.abs(long_term).max()
    assert np.abs(relaxed - long_term).max() < 1e-9 * big
    assert np.abs(elastic_only - long_term).max() > 0.1 * big     # the Prony part matters


def test_prony_stresses_are_held_to_the_film_pressures_tolerance(stroke):
    """Each active Prony term enters the stress as g_i H_i (sealts/solid/viscoelastic.py,
    Eq. (a)): its H_i is held to rtol |H_i| + rtol p_ref / g_i, so that the term's stress
    errs by at most what the film pressures may (rtol p_ref), on every Gauss point and
    component; a term of small weight is held loosely. The others keep theirs."""
    from dataclasses import replace
    step, _, _, _, (s, state) = stroke
    ve = replace(s.viscoelastic, prony="table2", t_min=1e-3)
    vstep = stroke_of(state, replace(s, viscoelastic=ve))
    g = vstep.viscoelastic.series.g[vstep.viscoelastic.classes.active]
    assert g.size > 1 and np.ptp(g) > 0.0
    rt, at = vstep.tolerances(1e-3)
    H = vstep.prony_dofs()
    assert H.shape[2] == g.size and np.unique(H).size == H.size
    assert (rt[H] == 1e-3).all()
    want = np.broadcast_to((1e-3 * vstep.pressure_scale / g)[None, None, :, None], H.shape)
    assert at[H] == pytest.approx(want, rel=1e-12)
    p = vstep.layout.film_dofs
    assert at[p] == pytest.approx(1e-3 * vstep.pressure_scale)
    assert (at[vstep.layout.udofs] == 1e-6).all()


def test_restart_from_a_saved_state_repeats_the_stroke(tmp_path):
    """A run writes state.h5 after steps 1-2 and the stroke's fields as an XDMF time series;
    a scene with [start] state = that file skips
    them and its stroke is the same (leakage, friction and steps to round-off: the state is
    the same to the last bit, so the run is). A state saved on another mesh is a one-line
    scene error, exit 2."""
    import json
    import subprocess
    import sys

    from conftest import config_text
    mesh = {"h_contact": 0.1, "h_bulk": 0.4, "cache": str(tmp_path)}
    stroke = {"velocity": "ramp-hold", "t_ramp": 0.01, "t_end": 0.02, "output_times": []}
    text = config_text("oring_stroke", mesh=mesh, stroke=stroke)
    first = tmp_path / "first.toml"
    first.write_text(text)

    def run(cfg, out):
        r = subprocess.run([sys.executable, "-m", "sealts", "run", str(cfg), "-o", str(out)],
                           capture_output=True, text=True, timeout=600)
        return r, (json.loads((out / "summary.json").read_text()) if r.returncode == 0
                   else None)

    r, a = run(first, tmp_path / "a")
    assert r.returncode == 0, r.stderr
    # the fields as a time series that meshio (as ParaView) reads: t = 0 and t_end, the
    # film pressure p_in at the pressurised end at t = 0
    import meshio
    series = meshio.xdmf.TimeSeriesReader(str(tmp_path / "a" / "stroke_fields.xdmf"))
    points, cells = series.read_points_cells()
    assert series.num_steps == 2 and cells[0].type == "quad"
    t0, pd, cd = series.read_data(0)
    assert t0 == 0.0 and pd["film_pressure"].max() == pytest.approx(1.0)
    assert pd["displacement"].shape == (points.shape[0], 3) and "von_mises" in cd
    assert series.read_data(1)[0] == pytest.approx(0.02)
    state = tmp_path / "a" / "state.h5"
    assert state.is_file()
    again = tmp_path / "again.toml"
    again.write_text(text + f'\n[start]\nstate = "{state}"\n')
    r, b = run(again, tmp_path / "b")
    assert r.returncode == 0, r.stderr
    assert "restarted from" in r.stdout
    assert b["analysis"] == "restart + stroke"
    assert b["results"] == a["results"]           # steps 1-2's results come with the state
    for key in ("leakage_out", "leakage_in", "peak_friction_outstroke", "h_min"):
        assert b["stroke"][key] == pytest.approx(a["stroke"][key], rel=1e-9, abs=1e-12)
    assert b["stroke"]["steps_accepted"] == a["stroke"]["steps_accepted"]
    other = tmp_path / "other.toml"
    other.write_text(config_text("oring_stroke", mesh={**mesh, "h_contact": 0.2}, stroke=stroke,
                                 start={"state": str(state)}))
    r, _ = run(other, tmp_path / "c")
    assert r.returncode == 2 and r.stderr.count("\n") == 1
    assert "start.state" in r.stderr and "another mesh" in r.stderr


def test_tolerances_per_unknown_and_from_the_command_line(stroke):
    """The leakage volumes are held to rtol V_c absolutely (V_c = A L h_c, here 2 pi 25 mm
    x the rod side's length x h_mix), the film pressures to rtol and rtol p_ref (p_ref: the
    largest of p_in and the pressurised seal's peak asperity pressure, Eq. 44 at its gap),
    the friction work not at all, the displacements to rtol and rtol h_c (h_c the contact
    law's contact gap, h_mix here, ``displacement_scale``) but at least 1e-6, every other
    unknown to rtol and 1e-6; -stroke_ts_rtol replaces the scene's rtol, -stroke_ts_atol
    the displacements' atol."""
    from petsc4py import PETSc
    step = stroke[0]
    side = step.side
    assert step.volume_scale == pytest.approx(
        2 * np.pi * 25.0 * (side.Z.max() - side.Z.min()) * 7e-4, rel=1e-6)
    x = 1.0 - side.gap(0.0, step.U0) / 7e-4              # Eq. 44, h_mix 7e-4, p_mix 15
    p_s = np.where(x > 0.0, 15.0 / (np.e - 1.0) * x * (np.exp(x) - 1.0), 0.0)
    assert 1.0 < p_s.max() < 15.0
    assert step.pressure_scale == pytest.approx(max(1.0, p_s.max()), rel=1e-9)
    rt, at = step.tolerances(1e-3)
    v, w = step.vdofs, step.work.wd if step.work is not None else []
    p = step.layout.film_dofs
    assert (rt[v] == 0.0).all() and at[v] == pytest.approx(1e-3 * step.volume_scale)
    assert (at[w] >= 1e300).all()
    assert (rt[p] == 1e-3).all() and at[p] == pytest.approx(1e-3 * step.pressure_scale)
    ud = step.layout.udofs.ravel()
    assert step.displacement_scale == 7e-4                # h_mix of Eq. 44
    assert (rt[ud] == 1e-3).all() and (at[ud] == 1e-6).all()   # 1e-3 h_c is below 1e-6
    rt2, at2 = step.tolerances(1e-2)
    assert (rt2[ud] == 1e-2).all() and at2[ud] == pytest.approx(1e-2 * 7e-4, rel=1e-12)
    rest = np.setdiff1d(np.arange(step.n),
                        np.concatenate([v, np.atleast_1d(w), p, ud]).astype(int))
    assert (rt[rest] == 1e-3).all() and (at[rest] == 1e-6).all()
    opts = PETSc.Options("stroke_")
    opts["ts_rtol"], opts["ts_atol"] = "1e-5", "1e-9"
    try:
        rt, at = step.tolerances(1e-3)
    finally:
        opts.delValue("ts_rtol")
        opts.delValue("ts_atol")
    assert (rt[rest] == 1e-5).all() and (at[rest] == 1e-6).all()
    assert (rt[ud] == 1e-5).all() and (at[ud] == 1e-9).all()
    assert at[v] == pytest.approx(1e-5 * step.volume_scale)
    assert at[p] == pytest.approx(1e-5 * step.pressure_scale)
