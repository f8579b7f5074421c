"""The pressure-penetration front during the stroke (stroke.front = "moving", the default):
the coarse O-ring's cycle at 1 MPa, whose kept front ends up to 0.06 edges from where the
seal's traction puts it, with a front tolerance of 0.02 edges. At every accepted state each
front's target stays within the tolerance of where the front is going (the TS events are
located; without them the drift of the kept front breaks the bound), the fronts move, and
the moves are recorded in the series."""
import numpy as np
import pytest

from conftest import mount_and_pressurise, scene, stroke_of
from sealts.core import Recorder

TOL = 0.02        # edges


@pytest.fixture(scope="module")
def cycle(tmp_path_factory):
    cache = str(tmp_path_factory.mktemp("mesh"))
    s = scene("oring_stroke", mesh={"h_contact": 0.1, "h_bulk": 0.4, "cache": cache},
              stroke={"front_tolerance": TOL, "output_times": []})
    state = mount_and_pressurise(s)
    stroke = stroke_of(state)
    U0 = stroke.start()
    mf = stroke.front
    gaps = []          # per accepted state: target minus where each front is going
    wetted = []        # the series' record of the wetting

    def record(t, U):
        gaps.append(mf.event_values(t, U)[0::2] + TOL)
        wetted.append(stroke.scalars(t, U)["wetted_edges"])

    rec = Recorder(record)
    U = stroke.run(U0, s.stroke.t_end, s.stroke.dt, s.stroke.rtol, observers=[rec])
    return stroke, np.array(gaps), np.array(wetted), U


def test_the_targets_stay_within_the_tolerance_of_the_fronts(cycle):
    stroke, gaps, wetted, U = cycle
    assert np.isfinite(U).all()
    # the event location's own tolerance on top (PETSc locates a crossing to 1e-6 in t)
    assert np.abs(gaps).max() <= TOL * (1 + 1e-2), np.abs(gaps).max()


def test_the_fronts_move_and_the_series_records_it(cycle):
    stroke, gaps, wetted, U = cycle
    moves = stroke.front.moves.sum()
    assert moves >= 1
    assert np.ptp(wetted) > TOL


def test_a_kept_front_drifts_past_the_tolerance(tmp_path):
    """The same cycle with the front kept: its target leaves the tolerance band (so the
    bound above is not met by a quiet cycle)."""
    s = scene("oring_stroke", mesh={"h_contact": 0.1, "h_bulk": 0.4, "cache": str(tmp_path)},
              stroke={"front": "kept", "output_times": []})
    state = mount_and_pressurise(s)
    stroke = stroke_of(state)
    assert stroke.front is None
    U0 = stroke.start()
    drift = []
    rec = Recorder(lambda t, U: drift.append(stroke.scalars(t, U)["front_drift"]))
    stroke.run(U0, s.stroke.t_end, s.stroke.dt, s.stroke.rtol, observers=[rec])
    assert max(drift) > 2 * TOL
