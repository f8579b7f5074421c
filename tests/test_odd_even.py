"""The film gap's odd-even mode (sealts.film.odd_even): the indicator measures a sawtooth by
its amplitude and ignores smooth films and the gap floor's flat zone; the coarse O-ring on
Greenwood-Williamson's soft summits settles into the sawtooth (its film is
convection-dominated at the 0.1 mm contact mesh) and the stroke stops naming it, where the
paper's stiff law on the same mesh and window stays smooth.

Why the bounds: a sawtooth of amplitude A on a flat film of gap g reads A / g exactly (half
the deviation from the neighbours' line at the nodes where it turns, averaged over eight
nodes, against their mean gap); one confined to ten nodes reads A over the gap there (to
10 %: the window's edges); a smooth film, even one as curved as an EHL inlet, has no
turning nodes and reads 0. The coarse GW stroke's sawtooth is of the order of the gap
(README, "The film's node-to-node mode"), far above the warning threshold; the paper's
law keeps it more than an order below.
"""
import numpy as np
import pytest

from conftest import mount_and_pressurise, scene, stroke_of
from sealts.core import Recorder, SolveError
from sealts.film.odd_even import ODD_EVEN_WARN, odd_even

FLOOR = 8.6e-5         # mm, the paper's O-ring's gap floor
GAP = 1.9e-3           # mm, below which the contact is counted (GW's contact gap there)


def film(n=101):
    """A smooth EHL-like gap (mm): a steep inlet, a flat contact, a constriction and an
    outlet, all below GAP."""
    y = np.linspace(0.0, 1.0, n)
    return y, 1e-3 * (0.6 + 1.2 * np.exp(-y / 0.08) - 0.15 * np.exp(-((y - 0.9) / 0.04) ** 2)
                      + 0.1 * (y - 0.5) ** 2)


def test_a_smooth_film_reads_zero():
    y, h = film()
    assert odd_even(y, h, FLOOR, GAP) == 0.0


def test_a_sawtooth_on_a_flat_film_reads_its_amplitude_over_the_gap():
    y = np.linspace(0.0, 1.0, 81)
    for a in (1e-4, 3e-4):      # 0.17 and 0.5 of the 0.6 um gap: about the warning's size
        saw = 6e-4 + a * (-1.0) ** np.arange(y.size)
        assert odd_even(y, saw, FLOOR, GAP) == pytest.approx(a / 6e-4, rel=1e-9)


def test_a_sawtooth_on_a_few_nodes_reads_its_local_ratio():
    """Ten nodes before the outlet's constriction alternate by +-0.1 um (as the 0.025 mm GW
    cycle's film does while it crawls): read against the gap there, not the contact's."""
    y, h = film()
    k = slice(75, 85)
    saw = h.copy()
    saw[k] += 1e-4 * (-1.0) ** np.arange(10)
    local = 1e-4 / h[k].mean()
    assert odd_even(y, saw, FLOOR, GAP) == pytest.approx(local, rel=0.1)


def test_the_floor_flattens_deep_asperity_contact():
    """Mean planes 2 um into each other, alternating by 0.2 um: the film's gap there is the
    floor, flat to exp(-20), whatever the summits do."""
    y = np.linspace(0.0, 1.0, 60)
    h = -2e-3 + 2e-4 * (-1.0) ** np.arange(60)
    assert odd_even(y, h, FLOOR, GAP) < 1e-6
    assert odd_even(y, h + 2.5e-3, FLOOR, GAP) > 0.3     # the same sawtooth above the floor


def test_fewer_than_five_contact_nodes_read_zero():
    y = np.linspace(0.0, 1.0, 40)
    h = np.full(40, 5e-3)
    h[10:14] = 1e-4 * np.array([1.0, 5.0, 1.0, 5.0])
    assert odd_even(y, h, FLOOR, GAP) == 0.0


def test_the_stroke_warns_once_above_the_threshold():
    from sealts.steps.stroke import OddEvenNote
    said = []
    recent = []
    note = OddEvenNote(lambda msg, force=False: said.append(msg), 0.1, recent)
    for t, v in enumerate((0.0, 0.5 * ODD_EVEN_WARN, 2.0 * ODD_EVEN_WARN, 3.0 * ODD_EVEN_WARN)):
        recent.append((v, float(t)))
        assert note(float(t), None, None, {}) == {"odd_even": v}
    assert len(said) == 1 and "t = 2 s" in said[0] and "mesh.h_contact = 0.1 mm" in said[0]


def _window(gw, tmp_path, t_end=0.35, upwind=None):
    """The coarse O-ring (0.1 / 0.4 mm) on Greenwood-Williamson (``gw``, its scene's central
    film flux) or the paper's law (the default upwinded flux), or with ``upwind`` set, no
    solid friction, stroked to t_end: the odd_even column by accepted state, and the run's
    error (None if it finished)."""
    film = {} if upwind is None else {"film": {"upwind": upwind}}
    s = scene("oring_stroke_gw" if gw else "oring_stroke",
              mesh={"h_contact": 0.1, "h_bulk": 0.4, "cache": str(tmp_path)},
              stroke={"friction": False, "t_end": t_end, "output_times": []}, **film)
    stroke = stroke_of(mount_and_pressurise(s))
    seen = []
    rec = Recorder(lambda t, U: seen.append(stroke.odd_even_recent[-1][0]))
    U0 = stroke.start()
    try:
        stroke.run(U0, s.stroke.t_end, s.stroke.dt, s.stroke.rtol, observers=[rec])
        error = None
    except SolveError as e:
        error = str(e)
    return np.array(seen), error


def test_the_coarse_gw_stroke_stops_naming_the_odd_even_mode(tmp_path):
    seen, error = _window(True, tmp_path)
    assert seen.max() > 2.0 * ODD_EVEN_WARN, seen.max()
    assert error is not None and "alternates from node to node" in error, error
    assert "mesh.h_contact = 0.1 mm" in error


def test_the_upwinded_flux_keeps_the_coarse_gw_film_smooth(tmp_path):
    """The same coarse GW stroke with the upwinded Couette flow (sealts.film.reynolds_fv):
    the share damps the mode, the run finishes its window and stays below the warning."""
    seen, error = _window(True, tmp_path, upwind=True)
    assert error is None, error
    assert seen.max() < ODD_EVEN_WARN, seen.max()


def test_the_papers_law_on_the_same_mesh_stays_smooth(tmp_path):
    seen, error = _window(False, tmp_path, upwind=False)      # the law's stiffness alone
    assert error is None, error
    assert seen.max() < 0.25 * ODD_EVEN_WARN, seen.max()
