"""The pressurised-state cache: steps 1-2 computed once per input, reused by later runs.

A seal scene's steps 1-2 (mount, pressurise) depend on the seal, the rod's radius, the
groove (not its friction), the long-term material, the mesh, the mount, the asperity law
(not its friction), the fluid's p_in, p_out and p_crit, the PETSc options of their solvers
(no prefix, ``static_`` and, for ``mesh.h_edge``, ``transfer_``; monitors and viewers
aside) and sealts' own code. A run whose
scene goes on to a hold, a stroke or ``sealts ihl`` keeps their end state, the ``state.h5``
of :mod:`sealts.steps.state`, as

    <mesh.cache>/states/<key>.h5,   key = SHA-256 of all of these (16 hex digits),

and a later run with the same key starts from it (:class:`sealts.steps.restart.Restart`)
instead of mounting again: a study of the stroke's speed, viscosity, friction, film or
tolerances mounts once. Any change of an input, or of any file of the ``sealts`` package,
gives another key; a cached file that cannot be read is recomputed and replaced.
``[start] cache = false`` turns the cache off (the benchmarks time steps 1-2 so); a
``[start] state`` file takes precedence over it. The summary's ``steps_1_2`` says which it
was.
"""
import hashlib
import json
from dataclasses import asdict
from functools import lru_cache
from pathlib import Path

from .base import Step

PACKAGE = Path(__file__).resolve().parents[1]
# PETSc option families of steps 1-2's solvers, and names that only report
FAMILIES = ("ts_", "snes_", "ksp_", "pc_", "mat_")
REPORTS = ("monitor", "view", "converged_reason", "log")


@lru_cache(maxsize=1)
def code_version():
    """SHA-256 of every Python file of the sealts package (path and content), with the
    petsc4py version: a changed line of code never reuses a state computed before it."""
    import petsc4py
    h = hashlib.sha256(petsc4py.__version__.encode())
    for path in sorted(PACKAGE.rglob("*.py")):
        h.update(str(path.relative_to(PACKAGE)).encode())
        h.update(path.read_bytes())
    return h.hexdigest()


def solver_options(options):
    """The options (name without dash -> value) that steer steps 1-2's solvers."""
    out = {}
    for name, value in (options or {}).items():
        name = name.lstrip("-")
        bare = next((name[len(p):] for p in ("static_", "transfer_") if name.startswith(p)),
                    name)
        if bare.startswith(FAMILIES) and not any(w in name for w in REPORTS):
            out[name] = str(value)
    return out


def inputs(scene, options=None):
    """Everything steps 1-2 depend on (module docstring), as a JSON-able dict."""
    from ..problem.seal_model import self_contact_on
    d = asdict(scene)
    spec = {k: d[k] for k in ("model", "seal", "groove", "material", "mesh", "mount",
                              "asperity")}
    spec["rod_radius"] = scene.rod.radius
    spec["fluid"] = {k: d["fluid"][k] for k in ("p_in", "p_out", "p_crit")}
    spec["self_contact"] = self_contact_on(scene)    # "auto" reads hold.p_end too
    for section, key in (("groove", "mu"), ("asperity", "mu_s"), ("asperity", "enabled"),
                         ("mesh", "cache")):
        spec[section].pop(key, None)
    if scene.seal.shape == "file":
        try:
            spec["mesh_file_sha256"] = hashlib.sha256(
                Path(scene.seal.mesh_file).read_bytes()).hexdigest()
        except OSError:
            pass                            # the mesh reader names the missing file
    spec["petsc"] = solver_options(options)
    spec["code"] = code_version()
    return spec


def key(scene, options=None):
    text = json.dumps(inputs(scene, options), sort_keys=True, default=str)
    return hashlib.sha256(text.encode()).hexdigest()[:16]


class StateCache:
    """The cache entry of one scene: ``path``, and whether it can be used (``hit``)."""

    def __init__(self, scene, options=None):
        self.path = Path(scene.mesh.cache) / "states" / f"{key(scene, options)}.h5"
        self.note = ""

    @classmethod
    def for_scene(cls, scene, options=None, command="run"):
        """The scene's entry, or None where the cache does not apply: off, a ``[start]
        state`` given, not a seal, or nothing after steps 1-2."""
        if (scene.model != "seal" or not scene.start.cache or scene.start.state
                or (command == "run" and scene.stroke.velocity == "none"
                    and scene.hold.p_end == 0.0)):
            return None
        return cls(scene, options)

    def hit(self):
        """The entry exists and reads as a state file; an unreadable one is a miss (it is
        recomputed and replaced) with a note for the progress output."""
        if not self.path.is_file():
            return False
        from ..scene import SceneError
        from .state import read_state
        try:
            read_state(self.path)
        except SceneError:
            self.note = f"the cached state {self.path} cannot be read; steps 1-2 recomputed"
            return False
        return True


class SaveToCache(Step):
    """After steps 1-2: their state into the cache (rank 0, whole or not at all). A cache
    that cannot be written costs the next run its steps 1-2, not this run: a note."""
    name = None          # not a stage of the analysis

    def __init__(self, cache):
        self.cache = cache

    def run(self, state):
        state.parts["steps_1_2"] = {"from": "computed", "cache": str(self.cache.path)}
        if self.cache.note:
            state.say(self.cache.note, force=True)
        if state.comm is not None and state.comm.getRank() != 0:
            return               # rank 0 writes (also where the run's writer writes nothing:
                                 # the scene's own mesh's steps 1-2 before mesh.h_edge)
        from ..io.writer import write_h5
        try:
            self.cache.path.parent.mkdir(parents=True, exist_ok=True)
            write_h5(self.cache.path, *state.file_data())
        except OSError as e:
            state.say(f"note: the state cache {self.cache.path} cannot be written "
                      f"({e.strerror}); the next run mounts again", force=True)
