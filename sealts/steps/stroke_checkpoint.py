"""Checkpoints of the stroke, and the stroke resumed from one
(``sealts run SCENE --restart OUTDIR``).

At the stroke's start and each of its stops (its output times, the velocity law's kinks and
reversals, t_end), where TS (re)starts its integrator anyway, :class:`StrokeCheckpoint` (the
stroke's last observer) writes OUTDIR/stroke_checkpoint.h5, whole (a temporary file renamed
into place):

* the state the stroke started from, in ``state.h5``'s format (the displacement per node,
  X, the front's reach; p_in, p_crit, t, results), so :class:`sealts.steps.restart.Restart`
  reads it in place of steps 1-2;
* the run before the stroke: its counters, summary blocks and the steps it ran;
* under ``stroke/``: U at the stop, the Problem's snapshot (the step TS takes next, the
  counts, the terms' histories: the friction anchors), the series rows so far, the
  transport per direction, the profiles and field frames written, the stroke's wall time;
* the scene's fingerprint: every key but the name, description, output and start, and
  the steering keys (STEERING: t_end, dt, rtol, stabilisation, output times, [petsc]),
  which a resumed run may change, e.g. to go on to a later t_end.

A resumed run with the same steering keys repeats the stroke's start (the film's row scales, the relaxed Prony stress:
deterministic and a few Newton iterations), then takes U, the histories and the outputs from
the checkpoint and goes on from its time with its step: its answer is the uninterrupted
run's to round-off (tests/test_restart.py). series.csv and the profiles are rewritten from
the checkpoint's rows and the field frames after it dropped, so OUTDIR again holds one run.
"""
import dataclasses
import json
import time
from pathlib import Path

import numpy as np

from ..core import Observer

NAME = "stroke_checkpoint.h5"
VERSION = 1          # of the file's layout: a checkpoint of another layout is refused
PROFILES = "stroke_profiles.csv"
# scene sections a resumed run may change: they do not move the answer
FREE = ("name", "description", "source", "output", "start")
# keys that steer the stroke from where it stands on (section.key, or a whole section): a
# resumed run may change them, e.g. go on to a later t_end, or with stroke.stabilisation
# after a snap; the summary then lists what changed (``restart_changes``)
STEERING = ("stroke.t_end", "stroke.dt", "stroke.rtol", "stroke.stabilisation",
            "stroke.output_times", "petsc")


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
    """OUTDIR's checkpoint for a run of ``scene`` (its path); a one-line SceneError where
    there is none, it is not one, or it was written for another scene (naming the first
    key that differs)."""
    import h5py

    from ..scene import SceneError
    path = Path(outdir) / NAME
    if scene.model != "seal" or scene.stroke.velocity == "none":
        raise SceneError("--restart continues a seal scene's stroke; this scene has none")
    if scene.hold.p_end != 0.0:
        raise SceneError("--restart continues a stroke from steps 1-2; a scene with a hold "
                         "(hold.p_end) cannot be restarted")
    if not path.is_file():
        raise SceneError(f"--restart: no {NAME} in {outdir} (a stroke writes one at each "
                         "stop: its output times, reversals and t_end)")
    try:
        with h5py.File(path, "r") as f:
            theirs = f.attrs["fingerprint"]
            version = int(f.attrs.get("version", 0))
    except (OSError, KeyError) as e:
        raise SceneError(f"--restart: {path} is not a stroke checkpoint ({e})") from None
    if version != VERSION:
        raise SceneError(f"--restart: {path} has layout {version}, this sealts reads "
                         f"{VERSION} (written by another version)")
    with h5py.File(path, "r") as f:
        t = float(f.attrs["stroke_t"])
    if t > scene.stroke.t_end:
        raise SceneError(f"--restart: {path} stands at t = {t:g} s, past stroke.t_end = "
                         f"{scene.stroke.t_end:g} s")
    if theirs != fingerprint(scene):
        key, was, now = _first_difference(json.loads(theirs), json.loads(fingerprint(scene))
                                          ) or ("?", "?", "?")
        raise SceneError(f"--restart: {path} was written for another scene ({key} = {was!r} "
                         f"there, {now!r} here)")
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


class StrokeCheckpoint(Observer):
    """Writes the checkpoint (module docstring) at each stop. ``state``: the RunState as the
    stroke began; ``parts``: the stroke's problem, series, transports and field series."""

    def __init__(self, state, stroke, series, integrals, fields, wall_before=0.0,
                 resumed=False):
        self.writer = state.writer
        self.before = state.file_data()
        self.run_before = json.dumps({"counters": dataclasses.asdict(state.counters),
                                      "parts": state.parts, "done": state.done})
        self.fingerprint = fingerprint(state.scene)
        self.steering = steering(state.scene)
        self.stroke, self.series, self.integrals, self.fields = stroke, series, integrals, fields
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
        snap = self.stroke.problem.snapshot()
        arrays, attrs = dict(self.before[0]), dict(self.before[1])
        arrays["stroke/U"] = u
        for k, history in snap["history"].items():
            for name, value in history.items():
                arrays[f"stroke/history/{k}/{name}"] = value
        rows = self.series.rows
        for k, v in _columns(rows).items():
            arrays[f"stroke/series/{k}"] = v
        profiles = self.writer.profiles_written(PROFILES)
        for i, (_, prof, _) in enumerate(profiles):
            for k, v in prof.items():
                arrays[f"stroke/profiles/{i}/{k}"] = np.asarray(v)
        attrs.update(
            version=VERSION, fingerprint=self.fingerprint, steering=self.steering,
            run_before=self.run_before,
            stroke_t=snap["t"], stroke_dt=snap["dt"], stroke_last_dt=snap["last_dt"],
            stroke_step=snap["step"], stroke_newton=snap["newton"],
            stroke_counters=json.dumps(snap["counters"]),
            stroke_series=json.dumps(list(rows[0])),
            stroke_profiles=json.dumps([[t_, list(p)] for t_, p, _ in profiles]),
            stroke_transport=json.dumps([self.integrals.transport[1],
                                         self.integrals.transport[-1]]),
            stroke_fields=json.dumps(self.fields.series.steps if self.fields.series.root
                                     else []),
            stroke_wall=time.perf_counter() - self.t_wall)
        self.writer.state(arrays, attrs, name=NAME)


class Resumed:
    """A stroke checkpoint read back (every rank): ``U``, ``snapshot`` (for
    ``Problem.transient(resume=...)``), ``rows``, ``transport``, ``profiles``, ``frames``,
    ``wall`` and ``run_before``."""

    def __init__(self, path):
        import h5py
        self.path = str(path)
        with h5py.File(path, "r") as f:
            a = f.attrs
            self.U = f["stroke/U"][()]
            history = {}
            if "stroke/history" in f:
                for k, g in f["stroke/history"].items():
                    history[k] = {name: d[()] for name, d in g.items()}
            self.snapshot = {"t": float(a["stroke_t"]), "dt": float(a["stroke_dt"]),
                             "last_dt": float(a["stroke_last_dt"]),
                             "step": int(a["stroke_step"]), "newton": int(a["stroke_newton"]),
                             "counters": json.loads(a["stroke_counters"]),
                             "history": history}
            self.rows = _rows(f["stroke/series"], json.loads(a["stroke_series"]))
            self.profiles = [(t, {k: f[f"stroke/profiles/{i}/{k}"][()] for k in names}, None)
                             for i, (t, names) in enumerate(json.loads(a["stroke_profiles"]))]
            out, back = json.loads(a["stroke_transport"])
            self.transport = {1: out, -1: back}
            self.frames = json.loads(a["stroke_fields"])
            self.wall = float(a["stroke_wall"])
            self.run_before = json.loads(a["run_before"])
            self.steering = a["steering"]

    @property
    def t(self):
        return self.snapshot["t"]

    def restore_run(self, state):
        """The RunState's counts, summary blocks and steps as they were before the stroke."""
        from ..core import Counters
        rb = self.run_before
        state.counters = Counters(**rb["counters"])
        state.parts = dict(rb["parts"])
        state.done[:] = rb["done"]
