"""The stroke without the film (``stroke.film = false``): dry sliding contact."""
import numpy as np
import pytest

from conftest import coarse_stroke, mount_and_pressurise, stroke_of


def test_dry_stroke_slides_at_the_coulomb_limit_with_no_film_unknowns(tmp_path):
    """A switched-off film adds no unknowns: the DAE is the displacements (2 per node), the
    rod friction's elastic slips (one per rod-side node), the groove walls' friction
    anchors (2 per boundary node) and the friction work W, a scalar, alone. The coarse pressurised O-ring dragged at 100 mm/s by a dry rod: once the rod has
    slid (5 mm of travel at the end against a stick range of microns), the rod's friction is
    the Coulomb limit mu_s times the asperity load (Eq. 46-48), the asperity contact carries
    the whole normal load, and the rod side keeps step 2's pressure penetration (the load
    at the start equals the pressurised rod force)."""
    s = coarse_stroke(tmp_path, t_end=0.05, film=False)
    state = mount_and_pressurise(s)
    model = state.model
    rod_force = state.results["contact_force_total"]
    step = stroke_of(state)
    assert step.film is None and step.leakage is None
    lay = step.layout
    assert step.n == (2 * model.mesh.X.shape[0] + lay.rod_nodes.size
                      + 2 * lay.groove_nodes.size + 1)
    assert lay.fields == ["displacement", "rod_slip", "groove_anchor"]
    assert step.layout.scalars == ("W",) and step.work.sources == [step.friction]
    U0 = step.start()
    start = step.scalars(0.0, U0)
    assert start["load_fluid"] == 0.0 and start["Q_out"] == 0.0
    assert start["load_asperity"] == pytest.approx(rod_force, rel=1e-3)
    U = step.run(U0, s.stroke.t_end, s.stroke.dt, s.stroke.rtol)
    end = step.scalars(s.stroke.t_end, U)
    assert end["friction_solid"] == pytest.approx(s.asperity.mu_s * end["load_asperity"],
                                                  rel=1e-6)
    assert end["friction_total"] == end["friction_solid"] > 50.0
    assert np.all(step.profile(s.stroke.t_end, U)["p"] == 0.0)
    assert end["W_friction"] > 0.0                     # the rod drags the seal along
