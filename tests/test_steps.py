"""The step layer's own contracts (sealts/steps, sealts/io/observers): a forked state is
independent of its parent, the procedure's step lists, and the observers' bookkeeping."""
import numpy as np
import pytest

from conftest import scene
from sealts.core import Counters, StepInfo
from sealts.io.observers import Series, StepLine, at_times
from sealts.io.writer import NullWriter
from sealts.mesh.structured import rectangle
from sealts.solid.pressure import PressureLoad
from sealts.steps.state import RunState


def test_a_forked_state_keeps_its_own_history():
    """A sweep runs a step 3 per operating point on forks of one state: what a fork's step
    changes (its counters, results, summary blocks, the front's reach) leaves the parent
    and the other forks as they were."""
    X, conn, _ = rectangle(1.0, 3.0, -1.0, 1.0, 4, 4)
    load = PressureLoad(X, conn, lambda t: 1.0, True, 0)
    load.set_reach([2.0, 1.5])
    parent = RunState(None, None, NullWriter(), None, u=np.zeros(3), t=4.0, load=load,
                      counters=Counters(steps=5), results={"mounted": {"f": 1.0}},
                      done=["mount", "pressurise"])
    a, b = parent.fork(), parent.fork()
    a.counters.add(Counters(steps=7, newton=3))
    a.results["mounted"]["f"] = 2.0
    a.parts["stroke"] = {"leakage_out": 1.0}
    a.done.append("stroke")
    a.load.set_reach([5.0, 0.5])
    assert parent.counters == Counters(steps=5) == b.counters
    assert a.counters == Counters(steps=12, newton=3)
    assert parent.results == {"mounted": {"f": 1.0}} and parent.parts == {}
    assert parent.done == ["mount", "pressurise"]
    assert parent.load.reach == [2.0, 1.5] == b.load.reach
    assert np.array_equal(parent.load.s1, b.load.s1) and not np.array_equal(a.load.s1,
                                                                            parent.load.s1)


def test_steps_for_each_kind_of_scene(tmp_path):
    """The procedure of each scene as a list of step names."""
    from sealts.steps import steps_for

    def names(s, command="run"):
        return [type(step).__name__ for step in steps_for(s, command)]

    cache = {"cache": str(tmp_path)}
    assert names(scene("slider")) == ["TransientFilm"]
    assert names(scene("oring_mount", mesh=cache)) == ["Mount", "Checkpoint"]
    stroke = scene("oring_stroke", mesh=cache)
    assert names(stroke) == ["Mount", "Pressurise", "SaveToCache", "Checkpoint", "Stroke"]
    assert names(stroke, "ihl") == ["Mount", "Pressurise", "SaveToCache", "Ihl"]
    assert names(scene("oring_hold", mesh=cache)) == ["Mount", "Pressurise", "SaveToCache",
                                                      "Checkpoint", "Hold"]
    state = tmp_path / "state.h5"
    state.write_bytes(b"")
    assert names(scene("oring_stroke", mesh=cache, start={"state": str(state)})) == \
        ["Restart", "Stroke"]


def test_series_rows_take_their_columns_in_order():
    """Each source sees the columns before it; the row goes to the writer; the progress
    line names the step and its columns in their units."""
    seen = []

    def first(t, u, info, row):
        return {"v": 2.0 * t}

    def second(t, u, info, row):
        seen.append(dict(row))
        return {"w": row["v"] + 1.0}

    class Say:
        lines = []

        def due(self):
            return True

        def __call__(self, line, force=False):
            self.lines.append(line)

    say = Say()
    line = StepLine("demo step", [("min h", "w", 1e3, "um"), ("Newton", "v", 1, "")])
    series = Series(NullWriter(), [first, second], say, line)
    series.accepted(0.5, None, StepInfo(step=3, dt=0.25, newton=7))
    assert seen == [{"t": 0.5, "v": 1.0}]
    assert series.rows == [{"t": 0.5, "v": 1.0, "w": 2.0}]
    assert say.lines == ["demo step     3  t = 0.5 s  dt = 0.25 s  min h = 2000 um  "
                         "Newton = 1"]
    with pytest.raises(ValueError):
        Series(NullWriter(), [first], say=None, line=line)
    assert at_times([0.0, 0.01], 0.01 * (1 + 1e-12)) and not at_times([0.01], 0.0100001)
