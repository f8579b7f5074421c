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

from ..core import PhysicalStop, SolveError, reworded
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
from .transfer import Transfer


def steps_1_2(scene, cache=None, prepared=False):
    """A seal scene's steps 1-2: mount and (p_in != 0) pressurise, or the restart from a
    ``[start] state`` file or from the state cache (``cache``: the scene's
    :class:`sealts.steps.state_cache.StateCache` entry, None without). ``prepared``: the
    state has them already (``mesh.h_edge``: :func:`refined_state`); only the cache is
    written."""
    if prepared:
        return [SaveToCache(cache)] if cache is not None else []
    if scene.start.state:
        return [Restart(scene.start.state)]
    if cache is not None and cache.hit():
        return [Restart(cache.path, cached=True)]
    fl = scene.fluid
    steps = [Mount()] + ([Pressurise()] if fl.p_in != 0.0 or fl.p_out != 0.0 else [])
    return steps + ([SaveToCache(cache)] if cache is not None else [])


def steps_for(scene, command="run", resume=None, options=None, prepared=False):
    """The steps of a scene (``command``: "run" or "ihl"); ``resume``: a stroke checkpoint
    to go on from (``--restart``; :func:`sealts.steps.run_checkpoint.check_restart`);
    ``options``: the PETSc options in force (they key the state cache); ``prepared``: the
    state has steps 1-2 already (:func:`new_state`)."""
    if resume is not None:       # the checkpoint of the scene's hold or of its stroke
        return [Restart(resume),
                Hold(resume=resume) if scene.hold.p_end != 0.0 else Stroke(resume=resume)]
    if scene.model == "film":
        return [SteadyFilm() if scene.analysis.type == "steady" else TransientFilm()]
    steps = steps_1_2(scene, StateCache.for_scene(scene, options, command), prepared)
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
    ``mesh.h_edge`` the model's mesh is refined at the contact's edges and the state has
    steps 1-2 done on it (``prepared``; :func:`refined_state`; ``cache``: from the state
    cache where it has them, ``options`` the PETSc options in force, which key it)."""
    from petsc4py import PETSc
    comm = comm or PETSc.COMM_WORLD
    if writer is None:
        from ..io.writer import NullWriter
        writer = NullWriter()
    say = say or Progress(comm, scene.output.progress)
    if scene.model != "seal":
        return RunState(scene, None, writer, say, comm)
    if scene.mesh.h_edge > 0.0:
        return refined_state(scene, comm, writer, say, options, cache)
    return RunState(scene, model_from_scene(scene, comm), writer, say, comm)


# refined meshes at most, each pass refining where the last one's edges fell outside the
# spans
REFINE_PASSES = 3


def refined_state(scene, comm, writer, say, options=None, cache=False):
    """The state of a ``mesh.h_edge`` scene. Where the state cache's entry (``cache``) or
    the ``[start] state`` file holds the points its mesh was refined at, the mesh is built
    from them and steps 1-2 read back by the scene's steps. Otherwise steps 1-2 run on the
    scene's own mesh (from the state cache where it has them), the mesh is refined around
    the pressurised contact's edges (:mod:`sealts.mesh.contact_edges`) and their end state
    is carried to it and brought to equilibrium there (:class:`sealts.steps.transfer.
    Transfer`); where the contact's edges then lie outside the refined spans, they are
    refined too and the state carried again, at most ``REFINE_PASSES`` times. The last
    pass's state is returned with steps 1-2 done (``prepared``); all passes' work counts
    in its counters, the summary's ``mesh_refinement`` says where. Under MPI the passes
    run on rank 0 (:func:`_refined_on_rank_0`)."""
    from dataclasses import replace

    from ..scene import SceneError
    from .state import read_refinement
    m = scene.mesh
    entry = StateCache.for_scene(scene, options) if cache else None
    stored = scene.start.state or (entry.path if entry is not None and entry.hit() else "")
    if stored:
        refine = read_refinement(stored)
        if refine is None and scene.start.state:
            raise SceneError(f"start.state: {stored} holds no mesh refinement for mesh.h_edge "
                             "(saved without it, or by an older sealts); run steps 1-2 again")
        if refine is not None and refine[1] != m.h_edge:
            raise SceneError(f"start.state: {stored} was saved with mesh.h_edge = "
                             f"{refine[1]:g} mm, not {m.h_edge:g} mm")
        if refine is not None:
            state = RunState(scene, model_from_scene(scene, comm, refine), writer, say, comm,
                             refine=refine)
            state.parts["mesh_refinement"] = {"h_edge": m.h_edge, "edge_span": m.edge_span,
                                              "points": len(refine[0]), "from": str(stored)}
            return state
    if comm.getSize() > 1:
        return _refined_on_rank_0(scene, comm, writer, say, options, cache)
    st, record, points = _refine_passes(scene, comm, say, options, cache)
    st.writer.replay(writer)
    st = replace(st, scene=scene, writer=writer, prepared=True)
    st.parts["mesh_refinement"] = record
    return st


def _refined_on_rank_0(scene, comm, writer, say, options, cache):
    """Under MPI: the passes run on rank 0 alone, serially, and the ranks build the mesh at
    its points and take its state of steps 1-2 (as from a state file,
    :func:`sealts.steps.restart.restore`). The seal's roll is weakly held in steps 1-2, and
    a distributed solve, which differs from the serial one in round-off, can settle it
    elsewhere and so refine other points: the mesh would depend on the number of ranks."""
    from petsc4py import PETSc

    from .restart import restore
    mpi = comm.tompi4py()
    out = None
    if comm.getRank() == 0:
        try:
            st, record, points = _refine_passes(scene, PETSc.COMM_SELF, say, options, cache)
            out = (points, record, st.counters, st.file_data(), st.done, st.writer.calls)
        except (Exception, Interrupted) as e:      # every rank stops, with rank 0's reason
            out = e
    out = mpi.bcast(out, root=0)
    if isinstance(out, BaseException):
        raise out
    points, record, counters, (arrays, attrs), done, profiles = out
    refine = (points, scene.mesh.h_edge) if len(points) else None
    state = RunState(scene, model_from_scene(scene, comm, refine), writer, say, comm,
                     refine=refine, prepared=True, done=list(done))
    entries = arrays.get("front_entries")
    restore(state, arrays["u"], arrays["X"], arrays.get("front_reach"),
            {**attrs, **({"front_entries": entries} if entries is not None else {})},
            "steps 1-2 of rank 0")
    state.counters.add(counters)
    for t, prof, name, label in profiles:
        writer.profile(t, prof, name=name, label=label)
    state.parts["mesh_refinement"] = {**record, "passes_on": "rank 0"}
    return state


def _refine_passes(scene, comm, say, options, cache):
    """Steps 1-2 on the scene's mesh, then their state carried to meshes refined at the
    contact's edges until they lie inside the refined spans (:func:`refined_state`): (the
    last pass's state, the summary's ``mesh_refinement`` record, the refinement points).
    The profiles of all passes go to the run (the scene's own mesh's to
    ``profiles_scene_mesh.csv``)."""
    from dataclasses import replace

    import numpy as np

    from ..io.writer import ProfileRecorder
    from ..mesh.contact_edges import edge_refinement
    m = scene.mesh
    base = replace(scene, mesh=replace(m, h_edge=0.0), start=replace(scene.start, state=""))
    say(f"mesh.h_edge = {m.h_edge:g} mm: steps 1-2 on the scene's mesh first, to find the "
        "contact's edges", force=True)
    profiles = ProfileRecorder()
    entry = StateCache.for_scene(base, options) if cache else None
    try:
        st = run_steps(steps_1_2(base, entry),
                       RunState(base, model_from_scene(base, comm), profiles, say, comm))
    except SolveError as e:          # where: before any refinement
        raise reworded(e, f"{e} (on the scene's own mesh, which mesh.h_edge refines only "
                       "after steps 1-2: the same without it)") from None
    # the scene's own mesh's profiles in a file of their own: at the same pseudo-time as
    # the refined mesh's, they would be two blocks of one t in profiles.csv
    profiles.calls = [(t, p, name.replace(".csv", "_scene_mesh.csv"),
                       f"{label} (the scene's own mesh)")
                      for t, p, name, label in profiles.calls]
    n_base = len(profiles.calls)
    record = {"h_edge": m.h_edge, "edge_span": m.edge_span,
              "base_nodes": int(st.model.mesh.X.shape[0]),
              "base_steps_1_2": st.parts.get("steps_1_2", {}).get("from", "computed"),
              "passes": []}
    refined, points = [], np.zeros((0, 2))
    for k in range(REFINE_PASSES + 1):
        add, edges, new = edge_refinement(st.model, st.t, st.u, m.h_edge, m.edge_span,
                                          refined)
        record["passes"].append({"nodes": int(st.model.mesh.X.shape[0]),
                                 "edges_reference_mm": edges, "refined": new})
        refined += new
        if add is None or k == REFINE_PASSES:
            break
        points = np.vstack([points, add[0]])
        say(("contact edges at (r, z) = " if k == 0 else
             "the contact's edges moved out of the refined spans; refined again at (r, z) = ")
            + ", ".join(f"({r:.4f}, {z:.4f})" for r, z in new)
            + f" mm: {m.h_edge:g} mm over {m.edge_span:g} mm each side; the state carried "
            "there", force=True)
        nxt = RunState(scene, model_from_scene(scene, comm, (points, m.h_edge)),
                       profiles, say, comm, refine=(points, m.h_edge),
                       done=[d for d in st.done if d != "transfer"])
        nxt.counters.add(st.counters)
        del profiles.calls[n_base:]      # the last refined mesh's profile only
        try:
            st = run_steps([Transfer(st)], nxt)
        except SolveError as e:          # the scene's own mesh went through: say so
            raise reworded(e,
                f"{e} (on the mesh refined to mesh.h_edge = {m.h_edge:g} mm at the contact's "
                "edges, from steps 1-2 on the scene's own mesh, which went through: without "
                "mesh.h_edge the run goes on on that mesh)") from None
    if not len(points):
        say("mesh.h_edge: no contact edge away from the groove's walls after steps 1-2; "
            "the mesh is not refined", force=True)
    record.update(points=len(points), edges_reference_mm=record["passes"][-1]
                  ["edges_reference_mm"], converged=add is None)
    if add is not None:
        say(f"warning: mesh.h_edge: after {REFINE_PASSES} refinements the contact's edges "
            "still moved out of the refined spans; the run goes on with the last mesh",
            force=True)
    return st, record, points


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
    state = new_state(scene, comm, writer, say)
    return run_steps(steps_1_2(scene, prepared=state.prepared), state)


def run_scene(scene, writer, comm, command="run", petsc_options=None, resume=None):
    """Run a scene's steps, write its fields (seal) and ``summary.json``; returns the
    summary. ``resume``: a stroke checkpoint the run goes on from (``--restart``)."""
    from ..io.provenance import provenance
    t_wall = time.perf_counter()
    try:
        state = new_state(scene, comm, writer, options=petsc_options, cache=True)
    except (Exception, Interrupted) as e:
        if scene.model == "seal" and scene.mesh.h_edge > 0.0 and writer.root:
            # steps 1-2 on the scene's mesh or a refined one (mesh.h_edge) failed: the run
            # says so
            writer.summary({"status": _status(e), **_cause(e),
                            "error": f"steps 1-2 (mesh.h_edge's refinement passes): "
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
    def finish(status, error=None, cause=None):
        try:
            body = _summary(state, command)
        except Exception:        # a run that failed before it had a state to summarise
            if error is None:
                raise
            body = {"scene": scene.name, "source": scene.source,
                    "analysis": " + ".join(state.done)}
        summary = {"status": status, **({"cause": cause} if cause else {}),
                   **({"error": error} if error else {}), **body}
        if status != "finished" and writer.root and writer.last_row is not None:
            summary["t_reached"] = writer.last_row.get("t")     # the last accepted step
        summary["wall_time_s"] = time.perf_counter() - t_wall
        if writer.root:          # git runs once, on rank 0, which alone writes
            summary["provenance"] = provenance(scene, petsc_options or {})
        writer.summary(summary)
        return summary

    steps = steps_for(scene, command, resume, petsc_options, state.prepared)
    try:
        run_steps(steps, state)
    except (Exception, Interrupted) as e:
        # a run that stopped, failed or was interrupted still says what it did: the steps
        # done, their counts and parts, the step it stopped in and why ("status":
        # "stopped" with its physical "cause", "failed" or "interrupted"); the series
        # written so far stay
        stopped = next((st.name for st in steps if st.name and st.name not in state.done), "")
        if isinstance(e, Interrupted):
            finish("interrupted", f"{stopped}: {e}")
        else:
            finish(_status(e), f"{stopped}: {type(e).__name__}: {e}".splitlines()[0],
                   _cause(e).get("cause"))
        raise
    if model is not None and command == "run" and writer.root:
        writer.path("fields.h5")
        write_fields(str(writer.path("fields.xdmf")), model, state.u)
    return finish("finished")


def _status(e):
    """The summary's status of a run that ended with ``e``: "stopped" for a physical stop
    (:class:`sealts.core.PhysicalStop`), "interrupted" by a signal, else "failed"."""
    if isinstance(e, Interrupted):
        return "interrupted"
    return "stopped" if isinstance(e, PhysicalStop) else "failed"


def _cause(e):
    """{"cause": ...} of a physical stop, else {}."""
    return {"cause": e.cause} if isinstance(e, PhysicalStop) else {}


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
