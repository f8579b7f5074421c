"""The state handed from step to step, and its file (``state.h5``).

A scene's run is a list of steps (:mod:`sealts.steps.procedure`); each takes the
:class:`RunState`, advances it and hands it on. What one step leaves for the next is here
and nowhere else: the displacements u and where the run stands in (pseudo-)time t, the
pressure-penetration front (``load``), the solvers' counters, and what the summary reports
(``results``, the step blocks in ``parts``). The model holds no history of its own.

``save`` writes the state of steps 1-2 as ``state.h5`` (the displacement per node, the mesh
coordinates it belongs to, the front's reach, the points a ``mesh.h_edge`` mesh was refined
at; p_in, p_crit, t and the results as attributes); :class:`sealts.steps.restart.Restart`
reads it back in place of those steps.
``fork`` copies a state for a sweep.
"""
import copy
import json
from dataclasses import dataclass, field, replace

import numpy as np

from ..core import Counters
from .pseudo_time import PseudoTime


@dataclass
class RunState:
    scene: object
    model: object
    writer: object
    say: object                                  # sealts.io.progress.Progress
    comm: object = None                          # the PETSc communicator of the run
    u: np.ndarray | None = None                  # displacements, the model's numbering
    t: float = 0.0                               # pseudo-time in steps 1-2, s in step 3
    udot: np.ndarray | None = None               # rate of a state that is not static
    load: object = None                          # the pressure-penetration front (step 2 on)
    counters: Counters = field(default_factory=Counters)
    results: dict = field(default_factory=dict)  # the contact's key numbers at the end
    parts: dict = field(default_factory=dict)    # summary blocks of the steps: hold, stroke
    done: list = field(default_factory=list)     # names of the steps run
    refine: tuple | None = None                  # (points, h) the mesh was refined at
    prepared: bool = False                       # steps 1-2 done with the mesh's refinement

    @property
    def protocol(self):
        """The pseudo-time protocol of steps 1-2 for this scene."""
        return PseudoTime(self.scene.mount.t_hold)

    def fork(self):
        """A copy to run other steps on (a sweep: steps 1-2 once, then a step 3 per
        operating point from a fork each): its own counters, results, summary blocks and
        front; the model, scene, writer and arrays are shared (steps replace u, never write
        into it)."""
        load = None
        if self.load is not None:
            load = self.load.rebuilt()
        return replace(self, load=load, counters=copy.copy(self.counters),
                       results=copy.deepcopy(self.results),
                       parts=copy.deepcopy(self.parts), done=list(self.done))

    def file_data(self):
        """(arrays, attributes) of the state file: the displacement per node, the mesh
        coordinates, the front's reach; p_in, p_crit, t, the scene and the results."""
        m = self.model
        arrays = {"u": np.array(self.u[m.udofs]), "X": m.mesh.X}
        fl = self.scene.fluid
        attrs = {"p_in": fl.p_in, "p_out": fl.p_out, "t": self.t, "scene": self.scene.name,
                 "source": self.scene.source, "results": json.dumps(self.results)}
        if self.load is not None:
            # the reach counts edges from each fluid's entry node, saved beside it
            arrays["front_reach"] = np.asarray(self.load.reach, float)
            arrays["front_entries"] = np.asarray(self.load.entries, np.int64)
            attrs["p_crit"] = self.load.p_crit
        if self.refine is not None:   # mesh.h_edge: the mesh is rebuilt from these points
            arrays["refine_points"] = np.asarray(self.refine[0], float)
            attrs["refine_h"] = float(self.refine[1])
        return arrays, attrs

    def save(self, path):
        """Write the state (rank 0) as an HDF5 file, whole: a temporary file renamed into
        place, so a reader never sees half a state."""
        self.writer.state(*self.file_data(), name=path)


def read_refinement(path):
    """(points, h) a state file's mesh was refined at (``mesh.h_edge``), or None where it
    was not; SceneError (one line) where the file is not a state file."""
    import h5py

    from ..scene import SceneError
    try:
        with h5py.File(path, "r") as f:
            if "refine_points" not in f:
                return None
            return f["refine_points"][()], float(f.attrs["refine_h"])
    except (OSError, KeyError) as e:
        raise SceneError(f"start.state: {path} is not a sealts state file ({e})") from None


def read_state(path):
    """(u per node, X, front reach or None, attributes) of a state file; SceneError (one
    line) where it is not one."""
    import h5py

    from ..scene import SceneError
    try:
        with h5py.File(path, "r") as f:
            X, un = f["X"][()], f["u"][()]
            reach = f["front_reach"][()] if "front_reach" in f else None
            attrs = dict(f.attrs)
            if "front_entries" in f:
                attrs["front_entries"] = f["front_entries"][()]
    except (OSError, KeyError) as e:
        raise SceneError(f"start.state: {path} is not a sealts state file ({e})") from None
    return un, X, reach, attrs
