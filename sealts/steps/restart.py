"""Steps 1-2 read back from an earlier run's ``state.h5`` (``[start] state``, written by
:meth:`sealts.steps.state.RunState.save`) instead of computed. The mesh and p_in must be the
ones it was saved with (one-line SceneError otherwise); the run continues where the saved
state stood, with its pressure front and the results it reported."""
import json

import numpy as np

from .base import Step
from .pressurise import Pressurise
from .state import read_state


class Restart(Step):
    name = "restart"

    def __init__(self, path, cached=False):
        """``cached``: ``path`` is the state cache's entry for this scene
        (:mod:`sealts.steps.state_cache`), not a file the scene names."""
        self.path, self.cached = path, cached

    def run(self, state):
        path = self.path
        un, X, reach, attrs = read_state(path)
        restore(state, un, X, reach, attrs, path)
        if self.cached:
            state.say(f"steps 1-2 from the state cache {path} (same mesh, geometry, "
                      "material, contact, pressures, solver options and code)", force=True)
            state.parts["steps_1_2"] = {"from": "cache", "cache": str(path)}
        else:
            state.say(f"restarted from {path} ({attrs.get('scene', '?')}): steps 1-2 not "
                      "repeated", force=True)


def restore(state, un, X, reach, attrs, path):
    """Put a saved state of steps 1-2 (:func:`sealts.steps.state.read_state`'s, or
    :meth:`RunState.file_data`'s: the displacement per node, the mesh, the front's reach,
    the attributes) into ``state``; ``path`` names it in the errors: another mesh or
    pressure than the scene's (one-line SceneError)."""
    from ..scene import SceneError
    model, scene = state.model, state.scene
    if X.shape != model.mesh.X.shape or not np.allclose(X, model.mesh.X, atol=1e-12):
        raise SceneError(f"start.state: {path} was saved for another mesh "
                         f"({X.shape[0]} nodes; this scene's has "
                         f"{model.mesh.X.shape[0]})")
    for key in ("p_in", "p_out"):
        p = getattr(scene.fluid, key)
        if float(attrs.get(key, 0.0)) != p:
            raise SceneError(f"start.state: {path} was pressurised to {key} = "
                             f"{float(attrs.get(key, 0.0)):g} MPa, not fluid.{key} = "
                             f"{p:g} MPa")
    pressurised = scene.fluid.p_in != 0.0 or scene.fluid.p_out != 0.0
    state.u = np.zeros(model.n)
    state.u[model.udofs] = un
    state.t = float(attrs.get("t", state.protocol.end(pressurised=pressurised)))
    if pressurised:
        state.load = Pressurise.pressure_load(state)
        state.load.p_crit = float(attrs["p_crit"])
        entries = attrs.get("front_entries")
        if entries is None:       # written before the entry moved: the smallest z
            side = model.mesh.nodes("pressure_side")
            entries = [side[np.argmin(model.mesh.X[side, 1])]]
        state.load.set_reach(state.load.recount(reach, entries))
    state.udot = None
    state.results = (json.loads(attrs["results"]) if "results" in attrs
                     else model.results(state.t, state.u))
