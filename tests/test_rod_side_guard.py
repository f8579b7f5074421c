"""The rod-side guard's stops (sealts.contact.rod_side_guard): a node off the rod side inside
the rod, and the rod side folding over (the 40 MPa O-ring squeezed into the corner between
rod and groove wall, benchmarks/stress.md)."""
import numpy as np
import pytest

from sealts.contact.rod_side import RodSide
from sealts.contact.rod_side_guard import RodSideGuard
from sealts.core import SolveError


def chain(n=6, length=0.05):
    """n nodes along z at r = 1.0 (the rod at r = 0.999), one node off the chain at r = 1.5."""
    X = np.array([[1.0, k * length] for k in range(n)] + [[1.5, 0.0]])
    side = RodSide(X, np.arange(n), 0.999, 1.0, off=[n])
    return side, np.zeros(2 * (n + 1))


def test_a_fold_of_the_rod_side_stops_the_run_and_says_where():
    side, u = chain()
    guard = RodSideGuard(side, depth=7e-4)
    guard.accepted(0.0, u)                              # the reference: nothing to say
    u[side.uz[3]] = -0.05 - 0.2 * 0.05                  # node 3 pushed back past node 2
    with pytest.raises(SolveError) as e:
        guard.accepted(1.5, u)
    assert "at t = 1.5 the rod side folds over between nodes 2 and 3" in str(e.value)
    assert "self-contact" in str(e.value)


def test_nodes_pressed_flat_against_a_wall_are_not_a_fold():
    """Nodes squeezed to one axial position (against a groove wall), round-off apart, and an
    element shortened to a twentieth of its length: no stop."""
    side, u = chain()
    u[side.uz[4]] = -0.05 + 1e-9                       # node 4 onto node 3's position ...
    u[side.uz[5]] = -2 * 0.05 - 1e-6                   # ... and node 5 a round-off behind
    RodSideGuard(side, depth=7e-4).accepted(0.0, u)
    u[side.uz[2]] = 0.95 * 0.05                        # element 1-2 at a twentieth
    RodSideGuard(side, depth=7e-4).accepted(0.0, u)


def test_a_node_off_the_rod_side_inside_the_rod_stops_the_run():
    side, u = chain()
    u[2 * 6] = -0.501 - 1e-3                           # the off node to r = 0.999 - 1e-3
    with pytest.raises(SolveError) as e:
        RodSideGuard(side, depth=7e-4).accepted(0.25, u)
    assert "node 6 off the rod side is 1 um inside the rod" in str(e.value)
