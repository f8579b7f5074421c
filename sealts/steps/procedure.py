"""A scene's run as a list of steps (docs/design.md).

    seal:  [Mount, Pressurise (p_in != 0), SaveToCache, Checkpoint] or [Restart]
           (a [start] state, or the state cache: sealts/steps/state_cache.py),
           then Hold (hold.p_end) or Stroke (stroke.velocity);
           --restart OUTDIR: [Restart, Hold or Stroke] from OUTDIR's checkpoint
    ihl:   [Mount, Pressurise (p_in != 0), SaveToCache] or [Restart], then Ihl
    film:  [SteadyFilm] or [TransientFilm]

``prepare`` runs steps 1-2 alone (tests, benchmarks); a sweep is ``prepare`` once, then a
step 3 per operating point on a fork of its state (``RunState.fork``). A new step is a file
in this package, imported here and put in ``steps_for``.
"""
import time

from ..interrupt import Interrupted
from ..io.fields import write_fields
from ..io.progress import Progress
from ..problem.seal_model import model_from_scene
from .checkpoint import Checkpoint
from .film import SteadyFilm, TransientFilm
from .hold import Hold
from .ihl import Ihl
from .mount import Mount
from .pressurise import Pressurise
from .restart import Restart
from .state import RunState
from .state_cache import SaveToCache, StateCache
from .stroke import Stroke


def steps_1_2(scene, cache=None):
    """A seal scene's steps 1-2: mount and (p_in != 0) pressurise, or the restart from a
    ``[start] state`` file or from the state cache (``cache``: the scene's
    :class:`sealts.steps.state_cache.StateCache` entry, None without)."""
    if scene.start.state:
        return [Restart(scene.start.state)]
    if cache is not None and cache.hit():
        return [Restart(cache.path, cached=True)]
    fl = scene.fluid
    steps = [Mount()] + ([Pressurise()] if fl.p_in != 0.0 or fl.p_out != 0.0 else [])
    return steps + ([SaveToCache(cache)] if cache is not None else [])


def steps_for(scene, command="run", resume=None, options=None):
    """The steps of a scene (``command``: "run" or "ihl"); ``resume``: a stroke checkpoint
    to go on from (``--restart``; :func:`sealts.steps.run_checkpoint.check_restart`);
    ``options``: the PETSc options in force (they key the state cache)."""
    if resume is not None:       # the checkpoint of the scene's hold or of its stroke
        return [Restart(resume),
                Hold(resume=resume) if scene.hold.p_end != 0.0 else Stroke(resume=resume)]
    if scene.model == "film":
        return [SteadyFilm() if scene.analysis.type == "steady" else TransientFilm()]
    steps = steps_1_2(scene, StateCache.for_scene(scene, options, command))
    if command == "ihl":
        return steps + [Ihl()]
    if not scene.start.state:         # also from the cache: every run leaves its state.h5
        steps.append(Checkpoint())
    if scene.hold.p_end != 0.0:
        steps.append(Hold())
    if scene.stroke.velocity != "none":
        steps.append(Stroke())
    return steps


def new_state(scene, comm=None, writer=None, say=None, options=None, cache=False):
    """The state a run starts from: the scene's model (for a seal scene), no history. With
    ``mesh.h_edge`` the model's mesh is refined at the contact's edges, which steps 1-2 on
    the scene's own mesh find first (:func:`refine_at_edges`; their work counts in the
    state's counters; ``cache``: from the state cache where it has them, ``options`` the
    PETSc options in force, which key it)."""
    from petsc4py import PETSc
    comm = comm or PETSc.COMM_WORLD
    if writer is None:
        from ..io.writer import NullWriter
        writer = NullWriter()
    say = say or Progress(comm, scene.output.progress)
    if scene.model != "seal":
        return RunState(scene, None, writer, say, comm)
    refine, base = None, None
    if scene.mesh.h_edge > 0.0:
        refine, base = refine_at_edges(scene, comm, say, options, cache)
    state = RunState(scene, model_from_scene(scene, comm, refine), writer, say, comm)
    if base is not None:
        state.counters.add(base.counters)
        state.parts["mesh_refinement"] = base.parts.pop("mesh_refinement")
    return state


def refine_at_edges(scene, comm, say, options=None, cache=False):
    """Steps 1-2 of ``scene`` on its own mesh (``mesh.h_edge`` off, no ``[start]`` state;
    with ``cache`` from the state cache where it has them), and the refinement at the
    pressurised contact's edges (:mod:`sealts.mesh.contact_edges`): (refine or None, that
    state, whose parts hold the summary's ``mesh_refinement``)."""
    from dataclasses import replace
    from ..mesh.contact_edges import edge_refinement
    m = scene.mesh
    base = replace(scene, mesh=replace(m, h_edge=0.0), start=replace(scene.start, state=""))
    say(f"mesh.h_edge = {m.h_edge:g} mm: steps 1-2 on the scene's mesh first, to find the "
        "contact's edges", force=True)
    st = run_steps(steps_1_2(base, StateCache.for_scene(base, options) if cache else None),
                   new_state(base, comm, None, say))
    refine, edges = edge_refinement(st.model, st.t, st.u, m.h_edge, m.edge_span)
    st.parts["mesh_refinement"] = {
        "h_edge": m.h_edge, "edge_span": m.edge_span,
        "points": 0 if refine is None else len(refine[0]), "edges_reference_mm": edges,
        "base_nodes": int(st.model.mesh.X.shape[0]),
        "base_steps_1_2": st.parts.get("steps_1_2", {}).get("from", "computed")}
    if refine is None:
        say("mesh.h_edge: the seal does not touch the rod after steps 1-2; the mesh is not "
            "refined", force=True)
    else:
        say("contact edges at (r, z) = " + ", ".join(f"({r:.4f}, {z:.4f})" for r, z in edges)
            + f" mm; refined to {m.h_edge:g} mm over {m.edge_span:g} mm each side",
            force=True)
    return refine, st


def run_steps(steps, state):
    """Run the steps in turn on ``state``; returns it."""
    for step in steps:
        step.run(state)
        if step.name:
            state.done.append(step.name)
    return state


def prepare(scene, comm=None, writer=None, say=None):
    """Steps 1-2 of a seal scene (mounted, pressurised to fluid.p_in when it is set) or
    the state they saved: the RunState with u, t and the front."""
    if scene.model != "seal":
        raise ValueError("prepare: steps 1-2 are a seal scene's (model = 'seal')")
    return run_steps(steps_1_2(scene), new_state(scene, comm, writer, say))


def run_scene(scene, writer, comm, command="run", petsc_options=None, resume=None):
    """Run a scene's steps, write its fields (seal) and ``summary.json``; returns the
    summary. ``resume``: a stroke checkpoint the run goes on from (``--restart``)."""
    from ..io.provenance import provenance
    t_wall = time.perf_counter()
    try:
        state = new_state(scene, comm, writer, options=petsc_options, cache=True)
    except (Exception, Interrupted) as e:
        if scene.model == "seal" and scene.mesh.h_edge > 0.0 and writer.root:
            # steps 1-2 on the scene's own mesh (mesh.h_edge) failed: the run says so
            writer.summary({"status": "interrupted" if isinstance(e, Interrupted) else "failed",
                            "error": f"steps 1-2 on the scene's mesh (mesh.h_edge): "
                                     f"{type(e).__name__}: {e}".splitlines()[0],
                            "scene": scene.name, "source": scene.source,
                            "wall_time_s": time.perf_counter() - t_wall})
        raise
    model = state.model
    if model is not None:
        cells = model.partition.cells_per_rank
        state.say(f"mesh: {model.mesh.X.shape[0]} nodes, {model.mesh.conn.shape[0]} quads, "
                  f"{model.n} unknowns" + (f"; cells per rank {cells}" if len(cells) > 1
                                           else ""), force=True)
    def finish(status, error=None):
        try:
            body = _summary(state, command)
        except Exception:        # a run that failed before it had a state to summarise
            if error is None:
                raise
            body = {"scene": scene.name, "source": scene.source,
                    "analysis": " + ".join(state.done)}
        summary = {"status": status, **({"error": error} if error else {}), **body}
        if status != "finished" and writer.root and writer.last_row is not None:
            summary["t_reached"] = writer.last_row.get("t")     # the last accepted step
        summary["wall_time_s"] = time.perf_counter() - t_wall
        if writer.root:          # git runs once, on rank 0, which alone writes
            summary["provenance"] = provenance(scene, petsc_options or {})
        writer.summary(summary)
        return summary

    steps = steps_for(scene, command, resume, petsc_options)
    try:
        run_steps(steps, state)
    except (Exception, Interrupted) as e:
        # a failed or interrupted run still says what it did: the steps done, their counts
        # and parts, the step it stopped in and why ("status": "failed" or "interrupted");
        # the series written so far stay
        stopped = next((st.name for st in steps if st.name and st.name not in state.done), "")
        if isinstance(e, Interrupted):
            finish("interrupted", f"{stopped}: {e}")
        else:
            finish("failed", f"{stopped}: {type(e).__name__}: {e}".splitlines()[0])
        raise
    if model is not None and command == "run" and writer.root:
        writer.path("fields.h5")
        write_fields(str(writer.path("fields.xdmf")), model, state.u)
    return finish("finished")


def _summary(state, command):
    scene, c, model = state.scene, state.counters, state.model
    counts = {"steps_accepted": c.steps, "steps_rejected": c.rejected,
              "newton_iterations": c.newton, "linear_iterations": c.linear,
              "newton_failures": c.newton_failures}
    if command == "ihl":
        return {"scene": scene.name, "source": scene.source, "analysis": "ihl",
                "p_in": scene.fluid.p_in, "viscosity": scene.fluid.viscosity,
                "ihl": state.parts["ihl"],
                "units": {"length": "mm", "pressure": "MPa", "speed": "mm/s",
                          "volume_per_mm_stroke": "mm^3/mm"}}
    if model is None:
        out = {"scene": scene.name, "source": scene.source, "analysis": scene.analysis.type,
               "scheme": scene.film.scheme, "unknowns": int(state.u.size),
               "ranks": state.comm.getSize(), **counts,
               "residual_evaluations": c.residuals, "jacobian_evaluations": c.jacobians,
               "results": state.results,
               "units": {"length": "mm", "pressure": "MPa", "force": "N", "time": "s",
                         "flow": "mm^3/s", "volume": "mm^3"}}
        return {**out, **state.parts}
    return {"scene": scene.name, "source": scene.source, "analysis": " + ".join(state.done),
            "nodes": int(model.mesh.X.shape[0]), "elements": int(model.mesh.conn.shape[0]),
            "unknowns": model.n, "ranks": state.comm.getSize(),
            "cells_per_rank": model.partition.cells_per_rank, **counts,
            "results": state.results,
            "units": {"length": "mm", "pressure": "MPa", "force": "N"}, **state.parts}
