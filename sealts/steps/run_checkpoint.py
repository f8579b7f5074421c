"""Checkpoints of the stroke and of the viscoelastic hold, and the step resumed from one
(``sealts run SCENE --restart OUTDIR``).

At the step's start and each of its stops (the stroke's output times, the velocity law's
kinks and reversals and t_end; the hold's decades of t, temperature kinks and t_end), where
TS (re)starts its integrator anyway, :class:`StepCheckpoint` (the step's last observer)
writes OUTDIR/stroke_checkpoint.h5 or hold_checkpoint.h5, whole (a temporary file renamed
into place):

* the state the step started from, in ``state.h5``'s format (the displacement per node,
  X, the front's reach; p_in, p_crit, t, results), so :class:`sealts.steps.restart.Restart`
  reads it in place of steps 1-2;
* the run before the step: its counters, summary blocks and the steps it ran;
* under ``run/``: U at the stop, the Problem's snapshot (the step TS takes next, the counts,
  the terms' histories: the friction anchors; the hold's front and its relaxation), the
  series rows and profiles so far, the step's wall time; the stroke's transport per
  direction and field frames;
* the scene's fingerprint: every key but the name, description, output and start, and
  the steering keys (STEERING: the stroke's t_end, dt, rtol, stabilisations, output times,
  the hold's dt and rtol, [petsc]), which a resumed run may change, e.g. to go on to a
  later t_end (the hold's t_end classifies its Prony terms: not a steering key).

A resumed run with the same steering keys repeats the step's set-up (the stroke's start:
the film's row scales, the relaxed Prony stress; the hold's relaxed start), then takes U,
the histories and the outputs from the checkpoint and goes on from its time with its step:
its answer is the uninterrupted run's to the last bit (tests/test_restart.py). series.csv
and the profiles are rewritten from the checkpoint's rows and the field frames after it
dropped, so OUTDIR again holds one run.
"""
import dataclasses
import json
import time
from pathlib import Path

import numpy as np

from ..core import Observer

VERSION = 3          # of the file's layout: a checkpoint of another layout is refused
PROFILES = "stroke_profiles.csv"


def file_name(step):
    """The checkpoint file of a step ("stroke" or "hold")."""
    return f"{step}_checkpoint.h5"


def step_of(scene):
    """The step a restart of this scene continues: its hold, else its stroke."""
    return "hold" if scene.hold.p_end != 0.0 else "stroke"
# scene sections a resumed run may change: they do not move the answer
FREE = ("name", "description", "source", "output", "start")
# keys that steer the stroke from where it stands on (section.key, or a whole section): a
# resumed run may change them, e.g. go on to a later t_end, or with stroke.stabilisation
# after a snap; the summary then lists what changed (``restart_changes``)
STEERING = ("stroke.t_end", "stroke.dt", "stroke.rtol", "stroke.stabilisation",
            "stroke.snap_stabilisation", "stroke.output_times", "hold.dt", "hold.rtol", "petsc")


def _split(scene):
    """(the keys that decide the stroke's state, the steering keys) as dicts."""
    d = {k: v for k, v in dataclasses.asdict(scene).items() if k not in FREE}
    steer = {}
    for key in STEERING:
        sec, _, name = key.partition(".")
        steer[key] = d[sec].pop(name) if name else d.pop(sec)
    return d, steer


def fingerprint(scene):
    """The scene's keys that decide the stroke's state, as a JSON text."""
    return json.dumps(_split(scene)[0], sort_keys=True)


def steering(scene):
    """The steering keys' values (STEERING), as a JSON text."""
    return json.dumps(_split(scene)[1], sort_keys=True)


def changes(before, scene):
    """The steering keys a resumed run changed: key -> [checkpoint's value, now]."""
    now = json.loads(steering(scene))          # as the checkpoint has them (lists)
    was = json.loads(before)
    return {k: [was.get(k), now[k]] for k in STEERING if was.get(k) != now[k]}


def _first_difference(a, b, path=""):
    """The first key (dotted) whose values differ in two nested dicts, and the values."""
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            found = _first_difference(a.get(k), b.get(k), f"{path}.{k}" if path else k)
            if found:
                return found
        return None
    return None if a == b else (path, a, b)


def check_restart(outdir, scene):
    """OUTDIR's checkpoint for a run of ``scene`` (its path): of its hold if it has one,
    else of its stroke; a one-line SceneError where there is none, it is not one, or it was
    written for another scene (naming the first key that differs)."""
    import h5py

    from ..scene import SceneError
    step = step_of(scene)
    if scene.model != "seal" or (scene.stroke.velocity == "none" and step == "stroke"):
        raise SceneError("--restart continues a seal scene's hold or stroke; this scene has "
                         "neither")
    path = Path(outdir) / file_name(step)
    if not path.is_file():
        raise SceneError(f"--restart: no {file_name(step)} in {outdir} (a {step} writes one "
                         "at its start and at each stop)")
    try:
        with h5py.File(path, "r") as f:
            theirs = f.attrs["fingerprint"]
            version = int(f.attrs.get("version", 0))
    except (OSError, KeyError) as e:
        raise SceneError(f"--restart: {path} is not a {step} checkpoint ({e})") from None
    if version != VERSION:
        raise SceneError(f"--restart: {path} has layout {version}, this sealts reads "
                         f"{VERSION} (written by another version)")
    with h5py.File(path, "r") as f:
        t = float(f.attrs["run_t"])
    t_end = getattr(scene, step).t_end
    if t > t_end:
        raise SceneError(f"--restart: {path} stands at t = {t:g} s, past {step}.t_end = "
                         f"{t_end:g} s")
    if theirs != fingerprint(scene):
        key, was, now = _first_difference(json.loads(theirs), json.loads(fingerprint(scene))
                                          ) or ("?", "?", "?")
        raise SceneError(f"--restart: {path} was written for another scene ({key} = {was!r} "
                         f"there, {now!r} here)")
    if step == "stroke":
        fields = Path(outdir) / "stroke_fields.h5"
        if not fields.is_file():
            raise SceneError(f"--restart: {fields} is missing (the run's field frames)")
    return path


def _columns(rows):
    """Series rows as columns (name -> array; integer columns stay integer)."""
    out = {}
    for k in rows[0]:
        v = [r[k] for r in rows]
        whole = all(isinstance(x, (int, np.integer)) and not isinstance(x, bool) for x in v)
        out[k] = np.asarray(v, np.int64 if whole else float)
    return out


def _rows(group, names):
    cols = [(k, group[k][()]) for k in names]
    return [{k: (int(c[i]) if c.dtype.kind == "i" else float(c[i])) for k, c in cols}
            for i in range(cols[0][1].size)]


class StepCheckpoint(Observer):
    """Writes a step's checkpoint (module docstring) at its start and each stop.
    ``state``: the RunState as the step began; ``problem``: the step's Problem; ``series``:
    its Series; ``profiles``: the name of its profiles file; ``integrals``: the stroke's
    CycleIntegrals; ``fields``: the stroke's Fields observer."""

    def __init__(self, state, step, problem, series, profiles, integrals=None, fields=None,
                 wall_before=0.0, resumed=False):
        self.writer, self.step, self.problem = state.writer, step, problem
        self.before = state.file_data()
        self.run_before = json.dumps({"counters": dataclasses.asdict(state.counters),
                                      "parts": state.parts, "done": state.done})
        self.fingerprint = fingerprint(state.scene)
        self.steering = steering(state.scene)
        self.series, self.profiles = series, profiles
        self.integrals, self.fields = integrals, fields
        self.t_wall = time.perf_counter() - wall_before
        self.started = resumed          # a resumed run has its start's checkpoint

    def accepted(self, t, u, info):
        """The start (t = 0, its series row written) is a checkpoint too: a run that stops
        before its first stop (a snap) can go on from there, e.g. with stabilisation."""
        if not self.started:
            self.started = True
            self.stop(t, u)

    def stop(self, t, u):
        if not self.writer.root:
            return
        snap = self.problem.snapshot()
        arrays, attrs = dict(self.before[0]), dict(self.before[1])
        arrays["run/U"] = u
        for k, history in snap["history"].items():
            for name, value in history.items():
                arrays[f"run/history/{k}/{name}"] = value
        rows = self.series.rows
        for k, v in _columns(rows).items():
            arrays[f"run/series/{k}"] = v
        profiles = self.writer.profiles_written(self.profiles)
        for i, (_, prof, _) in enumerate(profiles):
            for k, v in prof.items():
                arrays[f"run/profiles/{i}/{k}"] = np.asarray(v)
        attrs.update(
            version=VERSION, step=self.step, fingerprint=self.fingerprint,
            steering=self.steering, run_before=self.run_before,
            run_t=snap["t"], run_dt=snap["dt"], run_last_dt=snap["last_dt"],
            run_step=snap["step"], run_newton=snap["newton"],
            run_lu_fallback=snap["lu_fallback"],
            run_counters=json.dumps(snap["counters"]),
            run_series=json.dumps(list(rows[0])),
            run_profiles=json.dumps([[t_, list(p)] for t_, p, _ in profiles]),
            run_wall=time.perf_counter() - self.t_wall)
        if self.integrals is not None:
            attrs["run_transport"] = json.dumps([self.integrals.transport[1],
                                                 self.integrals.transport[-1]])
        if self.fields is not None:
            attrs["run_fields"] = json.dumps(self.fields.series.steps
                                             if self.fields.series.root else [])
        self.writer.state(arrays, attrs, name=file_name(self.step))


class Resumed:
    """A step's checkpoint read back (every rank): ``U``, ``snapshot`` (for
    ``Problem.transient(resume=...)``), ``rows``, ``profiles``, ``wall``, ``run_before``,
    ``steering``; the stroke's ``transport`` and ``frames`` (None for a hold)."""

    def __init__(self, path):
        import h5py
        self.path = str(path)
        with h5py.File(path, "r") as f:
            a = f.attrs
            self.U = f["run/U"][()]
            history = {}
            if "run/history" in f:
                for k, g in f["run/history"].items():
                    history[k] = {name: d[()] for name, d in g.items()}
            self.snapshot = {"t": float(a["run_t"]), "dt": float(a["run_dt"]),
                             "last_dt": float(a["run_last_dt"]),
                             "step": int(a["run_step"]), "newton": int(a["run_newton"]),
                             # a checkpoint from before the direct solver's fallback: none
                             "lu_fallback": float(a.get("run_lu_fallback", -1.0)),
                             "counters": json.loads(a["run_counters"]),
                             "history": history}
            self.rows = _rows(f["run/series"], json.loads(a["run_series"]))
            self.profiles = [(t, {k: f[f"run/profiles/{i}/{k}"][()] for k in names}, None)
                             for i, (t, names) in enumerate(json.loads(a["run_profiles"]))]
            self.transport = None
            if "run_transport" in a:
                out, back = json.loads(a["run_transport"])
                self.transport = {1: out, -1: back}
            self.frames = json.loads(a["run_fields"]) if "run_fields" in a else None
            self.wall = float(a["run_wall"])
            self.run_before = json.loads(a["run_before"])
            self.steering = a["steering"]

    @property
    def t(self):
        return self.snapshot["t"]

    def restore_run(self, state):
        """The RunState's counts, summary blocks and steps as they were before the step."""
        from ..core import Counters
        rb = self.run_before
        state.counters = Counters(**rb["counters"])
        state.parts = dict(rb["parts"])
        state.done[:] = rb["done"]
