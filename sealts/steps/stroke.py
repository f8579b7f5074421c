"""Step 3 with ``[stroke] velocity``: the transient stroke with the film
(:class:`sealts.problem.stroke_problem.StrokeProblem`).

Output, as observers of the stroke's run: a series row per accepted step (the forces, flows,
volumes and gap of ``StrokeProblem.scalars``, with U' as the step's difference quotient,
then the solver's counts); at t = 0, each of stroke.output_times and t_end the profiles
(stroke_profiles.csv) and the fields (stroke_fields.xdmf/.h5, a time series: displacement
and film pressure on nodes, the Cauchy stresses on cells, with the Prony part in a
viscoelastic stroke). The cycle's integrals: the friction work W_friction, a TS unknown
(:mod:`sealts.contact.friction_work`), and the transport per stroke direction
(``CycleIntegrals``), the steps' V_out increments summed by the sign of v (TS stops at the
reversals, so each step lies in one direction).
"""
import time

import numpy as np

from ..core import StepTooSmall
from ..film.odd_even import ODD_EVEN_WARN, odd_even_note
from ..io.fields import FieldSeries
from ..io.observers import Fields, Profiles, Series, StepLine, solver_columns
from ..problem.stroke_problem import StrokeProblem
from ..solid.stresses import stress_cells
from .base import Step
from .run_checkpoint import PROFILES, Resumed, StepCheckpoint, changes


# the front drift (edges) from which the stroke says that it kept the front
FRONT_DRIFT_NOTE = 1.0


class StrokeColumns:
    """``StrokeProblem.scalars`` at each accepted state, U' from the previous one."""

    def __init__(self, stroke):
        self.stroke, self.last = stroke, None

    def __call__(self, t, U, info, row):
        Udot = None
        if self.last is not None and t > self.last[0]:
            Udot = (U - self.last[1]) / (t - self.last[0])
        self.last = (t, U)
        return self.stroke.scalars(t, U, Udot)


class OddEvenNote:
    """The ``odd_even`` column, the film gap's node-to-node mode over the contact
    (:mod:`sealts.film.odd_even`) as the stroke's own observer computed it for this state
    (0 without a film), and a warning once, at the first state above ODD_EVEN_WARN."""

    def __init__(self, say, h_contact, recent):
        self.say, self.h_contact, self.recent, self.warned = say, h_contact, recent, False

    def __call__(self, t, U, info, row):
        value = self.recent[-1][0] if self.recent and self.recent[-1][1] == t else 0.0
        if not self.warned and value > ODD_EVEN_WARN:
            self.warned = True
            self.say(f"warning: {odd_even_note(value, t, self.h_contact)}", force=True)
        return {"odd_even": value}


class CycleIntegrals:
    """Transport per direction (mm^3) over the accepted steps, from the columns before it
    (v, V_out); adds no column."""

    def __init__(self):
        self.transport, self.last = {1: 0.0, -1: 0.0}, None

    def __call__(self, t, U, info, row):
        if self.last is not None and t > self.last["t"]:
            prev = self.last
            way = 1 if prev["v"] + row["v"] > 0.0 else -1
            self.transport[way] += row["V_out"] - prev["V_out"]
        self.last = row
        return {}


def seal_fields(model, stroke):
    """(point data, cell data) of the stroke's state U at t: displacement and film pressure
    on nodes, the Cauchy stresses on cells (with the Prony part when viscoelastic)."""
    lay, n_nodes = stroke.layout, model.mesh.X.shape[0]

    def fields(t, U):
        u = stroke.displacement(U)
        disp = np.zeros((n_nodes, 3))
        disp[:, :2] = u[model.udofs]
        p = np.zeros(n_nodes)
        if lay.film_dofs.size:                      # none without the film
            p[lay.rod_nodes] = U[lay.film_dofs]
        if stroke.viscoelastic is None:
            cells = stress_cells(model.full_solid(), u)
        else:
            solid, prony = stroke.output_terms()
            cells = stress_cells(solid, U, prony)
        return {"displacement": disp, "film_pressure": p}, cells
    return fields


class Stroke(Step):
    name = "stroke"

    def __init__(self, resume=None):
        """``resume``: the path of a stroke checkpoint to go on from
        (:mod:`sealts.steps.run_checkpoint`)."""
        self.resume = resume

    def run(self, state):
        first = Resumed(self.resume) if self.resume else None
        t_wall = time.perf_counter() - (first.wall if first else 0.0)
        try:
            self._run(state, first)
        except StepTooSmall as e:
            # a snap (steps stuck at TS's minimum): back to the last stop's checkpoint, and
            # from there with stroke.snap_stabilisation, once
            path = state.writer.dir / "stroke_checkpoint.h5"
            c = state.scene.stroke.snap_stabilisation
            if (e.t is None or not path.exists()
                    or c <= state.scene.stroke.stabilisation or "snap stabilisation" in str(e)):
                raise
            back = Resumed(path)
            state.say(f"stroke: the seal snaps at t = {e.t:.6g} s ({e}); going on from "
                      f"t = {back.t:.6g} s with the snap stabilisation c = {c:g} MPa s/mm^2",
                      force=True)
            try:
                self._run(state, back, snapped_at=e.t)
            except StepTooSmall as again:
                # the film's odd-even mode seen before the first stall, if not again
                seen = getattr(e, "odd_even", "")
                if seen and not getattr(again, "odd_even", ""):
                    raise StepTooSmall(f"{again}{seen}", t=again.t) from None
                raise
            part = state.parts["stroke"]
            part["snap_stabilised_from"] = back.t
            part["wall_time_s"] = time.perf_counter() - t_wall    # both attempts
            if first is None:
                part.pop("restarted_at", None)

    def _run(self, state, back, snapped_at=None):
        """The stroke from its start, or from the checkpoint ``back``; ``snapped_at``: the
        time of a snap, from which on (from ``back``) the snap stabilisation acts."""
        model, scene, say, writer = state.model, state.scene, state.say, state.writer
        st = scene.stroke
        t_wall = time.perf_counter()
        if back is not None:
            back.restore_run(state)
        stroke = StrokeProblem(model, state.u, scene, state.load)
        if snapped_at is not None:
            k = stroke.problem.history_terms().index(stroke.stab)
            back.snapshot["history"][str(k)]["snapped_at"] = np.array(float(snapped_at))
        if stroke.viscoelastic:
            ves = stroke.viscoelastic
            say(ves.classes.describe(ves.series, ves.shift), force=True)
        say(f"stroke: {st.velocity} v(t), v_max = {st.v_max:g} mm/s, to t = {st.t_end:g} s; "
            f"{stroke.n} unknowns ({stroke.layout.film_dofs.size} film pressures, "
            f"{scene.film.scheme + ' film' if stroke.film is not None else 'dry'})",
            force=True)
        U = stroke.start()
        s0 = stroke.scalars(0.0, U)
        say(f"stroke start: film load {s0['load_fluid']:.5g} N, asperity load "
            f"{s0['load_asperity']:.5g} N, Q_out = {s0['Q_out']:.4g} mm^3/s", force=True)
        integrals, columns = CycleIntegrals(), StrokeColumns(stroke)
        line = StepLine("stroke step", [("v", "v", 1.0, "mm/s"), ("Newton", "newton", 1, ""),
                                        ("min h", "h_min", 1e3, "um")])
        series = Series(writer, [columns, solver_columns, integrals,
                                 OddEvenNote(say, scene.mesh.h_contact, stroke.odd_even_recent)],
                        say, line)
        wanted = sorted(set(st.output_times) | {0.0, st.t_end})
        writer.path("stroke_fields.h5")
        fields = Fields(FieldSeries(writer.path("stroke_fields.xdmf"), model.mesh.X,
                                    model.mesh.conn, writer.root,
                                    frames=back.frames if back else None),
                        seal_fields(model, stroke), wanted)
        outputs = [series, Profiles(writer, stroke.profile, PROFILES, wanted), fields]
        if back is not None:      # the outputs and the state as they stood at its stop
            U = back.U
            for r in back.rows:   # a checkpoint from before the odd-even column: unmeasured
                r.setdefault("odd_even", np.nan)
            series.rows = list(back.rows)
            writer.restore_series(back.rows)
            writer.restore_profiles(PROFILES, back.profiles)
            integrals.transport, integrals.last = dict(back.transport), back.rows[-1]
            columns.last = (back.t, U)
            changed = changes(back.steering, scene)
            say(f"stroke resumed at t = {back.t:.6g} s from {back.path}" + "".join(
                f"; {k} {a} -> {b}" for k, (a, b) in changed.items()), force=True)
        outputs.append(StepCheckpoint(state, "stroke", stroke.problem, series, PROFILES,
                                      integrals, fields, wall_before=back.wall if back else 0.0,
                                      resumed=back is not None))
        t_wall -= back.wall if back else 0.0
        U = stroke.run(U, st.t_end, st.dt, st.rtol, st.output_times, outputs,
                       resume=back.snapshot if back else None)
        rows = series.rows
        v = np.array([r["v"] for r in rows])
        F = np.array([r["friction_total"] for r in rows])
        c = stroke.problem.counters
        state.parts["stroke"] = {
            "velocity": st.velocity, "v_max": st.v_max, "t_end": st.t_end,
            "film": stroke.film is not None,
            "film_scheme": scene.film.scheme if stroke.film is not None else "none",
            "unknowns": int(stroke.n),
            "leakage_in": rows[-1]["V_in"], "leakage_out": rows[-1]["V_out"],
            "outstroke_transport": integrals.transport[1],
            "instroke_transport": integrals.transport[-1],
            "peak_friction_outstroke": float(np.abs(F[v > 0]).max()) if (v > 0).any() else 0.0,
            "peak_friction_instroke": float(np.abs(F[v < 0]).max()) if (v < 0).any() else 0.0,
            "friction_work": rows[-1]["W_friction"],
            "h_min": float(min(r["h_min"] for r in rows)),
            # the moving fronts' events (stroke.front = "moving"; 0 when kept)
            "front_moves": int(stroke.front.moves.sum()) if stroke.front is not None else 0,
            "wall_penetration": float(max(r["wall_penetration"] for r in rows)),
            "front_drift": float(max(r["front_drift"] for r in rows)),
            # the largest slip the groove walls' return mapping took off a wall at one
            # accepted step (mm): how far the walls' friction history moved outside the TS
            # error estimate (0: the seal stuck to its walls)
            "groove_slide": float(max(r.get("groove_slide", 0.0) for r in rows)),
            # the film gap's largest node-to-node mode over the contact (sealts.film.odd_even)
            "odd_even": float(np.nanmax([r.get("odd_even", np.nan) for r in rows] + [0.0])),
            # V_in - V_out against the change of the film's content (StrokeProblem.scalars'
            # V_film): the fluid the film does not account for (mm^3)
            "film_balance": (rows[-1]["V_in"] - rows[-1]["V_out"]
                             - (rows[-1]["V_film"] - rows[0]["V_film"])),
            # the stabilisation's largest force (sum of |c V_i u_i'|) against the normal load
            "stabilisation_share": float(max(r["F_stabilisation"] / max(abs(r["normal_load"]),
                                                                          1e-300)
                                             for r in rows)),
            # the time of the seal's snap (stroke.snap_stabilisation acts from the last stop
            # before it, snap_stabilised_from)
            "snapped_at": stroke.stab.snapped_at if stroke.stab.snapped_at >= 0.0 else None,
            "steps_accepted": c.steps, "steps_rejected": c.rejected,
            "newton_iterations": c.newton, "linear_iterations": c.linear,
            "newton_failures": c.newton_failures,
            "wall_time_s": time.perf_counter() - t_wall,
            "units": {"volume": "mm^3", "force": "N", "work": "N mm"},
        }
        if back is not None:
            state.parts["stroke"]["restarted_at"] = back.t
            if changed:
                state.parts["stroke"]["restart_changes"] = changed
        drift = state.parts["stroke"]["front_drift"]
        if drift > FRONT_DRIFT_NOTE and stroke.front is None:
            k = int(np.argmax([r["front_drift"] for r in rows]))
            say(f"note: the stroke kept the pressure-penetration front where its start put "
                f"it; at t = {rows[k]['t']:.4g} s the seal's contact would have moved it by "
                f"{drift:.3g} boundary edges (front_drift in the series)", force=True)
        state.u, state.t = stroke.displacement(U), st.t_end
        state.counters.add(c)
