"""The extrusion gap (groove.clearance): the side walls end at the bore r_rod + clearance,
their lower edges rounded (sealts.contact.rigid.GrooveContact's ``edge``), and a run stops
once the seal has flowed into the gap by more than groove.extrusion_limit.

Checks against independent truth: the contact's and the wall friction's Jacobians against
central differences on nodes placed on every piece (wall face, edge arc, bore; both walls);
the gap's continuity where the pieces meet (its closed form there); the arc's pressure
against the softplus law of the distance to the edge's centre.
"""
import numpy as np
import pytest

from sealts.contact.groove_friction import GrooveFriction, groove_surfaces
from sealts.contact.rigid import GrooveContact, softplus_penalty
from sealts.problem import Problem

ZA, ZB, R_BORE, RHO = 0.0, 1.0, 0.6, 0.1
K, DELTA = 1e3, 1e-3


def points():
    """Nodes pressed onto each piece of both walls (face, edge arc, bore), some near the
    pieces' joins, and some free in the gap."""
    c = R_BORE + RHO
    pts = []
    for zw, s in ((ZB, 1.0), (ZA, -1.0)):
        cz = zw + s * RHO
        pts += [(0.9, zw + s * 1e-3), (0.75, zw + s * 2e-3),            # face
                (c + 1e-4, zw + s * 1e-3)]                               # face, next to arc
        for ang in (0.1, 0.4, 0.8, 1.2, 1.5):                             # arc (radians)
            d = RHO - 2e-3
            pts.append((c - d * np.sin(ang), cz - s * d * np.cos(ang)))
        pts += [(R_BORE + 1e-3, cz + s * 1e-4), (R_BORE + 2e-3, cz + s * 0.2),  # bore
                (0.55, zw + s * 0.3)]                                    # free in the gap
    return np.array(pts)


def edge_groove(X):
    return GrooveContact(X, np.arange(X.shape[0]), np.full(X.shape[0], 0.1), True,
                         lambda t: 2.0, lambda t: (ZA, ZB), penalty=K, delta=DELTA,
                         edge=(R_BORE, RHO))


def assert_jacobian(term, u, eps=1e-8):
    """The term's Jacobian against central differences of its residual, to 1e-6 of its
    largest entry."""
    n = u.size
    problem = Problem(n, [term])
    J = problem.jacobian_dense(0.0, u, np.zeros(n), 1.0)
    fd = np.zeros((n, n))
    for j in range(n):
        e = np.zeros(n)
        e[j] = eps
        fd[:, j] = (problem.residual(0.0, u + e, u) - problem.residual(0.0, u - e, u)) / (2 * eps)
    assert np.abs(J - fd).max() <= 1e-6 * np.abs(J).max()


def test_edge_contact_jacobian():
    X = points()
    groove = edge_groove(X)
    n = 2 * X.shape[0]
    u = np.random.default_rng(3).uniform(-2e-5, 2e-5, n)
    assert_jacobian(groove, u)
    # every piece pressed: the wall pressure of every node but the free ones
    p = groove.node_pressures(0.0, u)
    assert (p > 0.5).sum() == X.shape[0] - 2 and (p < 1e-6).sum() == 2


def test_edge_pressure_is_the_law_of_the_distance_to_the_edge():
    """On the arc the pressure is the softplus law of rho - |x - c|, pushing away from c;
    on the bore the law of r - r_bore, pushing towards the rod; both walls alike."""
    X = points()
    groove = edge_groove(X)
    u = np.zeros(2 * X.shape[0])
    _, (fr, fa, fb), _ = groove._evaluate(0.0, u)
    for zw, s, f_ax, rows in ((ZB, 1.0, fb, slice(0, 11)), (ZA, -1.0, fa, slice(11, 22))):
        c = np.array([R_BORE + RHO, zw + s * RHO])
        arc = X[rows][3:8]
        d = np.linalg.norm(arc - c, axis=1)
        p, _ = softplus_penalty(d - RHO, K, DELTA)
        n = (arc - c) / d[:, None]
        assert np.allclose(fr[rows][3:8], p * n[:, 0], rtol=1e-12)
        assert np.allclose(f_ax[rows][3:8], p * n[:, 1], rtol=1e-12)
        bore = X[rows][8:10]
        p, _ = softplus_penalty(R_BORE - bore[:, 0], K, DELTA)
        assert np.allclose(fr[rows][8:10], -p, rtol=1e-12)
        assert np.allclose(f_ax[rows][8:10], 0.0, atol=1e-300)


@pytest.mark.parametrize("side", [1.0, -1.0])
def test_edge_gap_is_continuous(side):
    """Along a path round the edge at the depth 1e-3 inside the housing (the face, the arc,
    the bore, across both joins) the pressure is the law's at that depth all the way: the
    gap is continuous where the pieces meet."""
    c = np.array([R_BORE + RHO, (ZB if side > 0 else ZA) + side * RHO])
    ang = np.linspace(-0.3, np.pi / 2 + 0.3, 401)     # beyond both joins
    d = RHO - 1e-3
    # round the edge: the face below the arc, then the arc, then the bore
    pts = []
    for a in ang:
        if a < 0.0:                                   # face, left of the centre's r
            pts.append((c[0] - a * 0.1, c[1] - side * d))
        elif a > np.pi / 2:                           # bore, beyond the centre's z
            pts.append((c[0] - d, c[1] + side * (a - np.pi / 2) * 0.1))
        else:
            pts.append((c[0] - d * np.sin(a), c[1] - side * d * np.cos(a)))
    X = np.array(pts)
    p = edge_groove(X).node_pressures(0.0, np.zeros(2 * X.shape[0]))
    p0, _ = softplus_penalty(-1e-3, K, DELTA)
    assert np.allclose(p, p0, rtol=1e-9)


def test_edge_friction_jacobian():
    """The wall friction on the edge's arc and the bore (their tangents turn with the node
    on the arc) against central differences, slips in stick, blend and slide."""
    X = points()
    groove = edge_groove(X)
    n = 2 * X.shape[0]
    u = np.random.default_rng(4).uniform(-2e-5, 2e-5, n)
    fric = GrooveFriction(groove, mu=0.2, gamma_crit=1e-4)
    rng = np.random.default_rng(5)
    fric.anchors = fric._disp(u) + rng.uniform(-3e-4, 3e-4, (X.shape[0], 2))
    p, _, tan, dtan, _ = groove_surfaces(groove, 0.0, u)
    assert np.abs(dtan).max() > 1.0                  # arcs turn their tangents
    assert_jacobian(fric, u)
    gamma = fric.slip(0.0, u)
    pressed = p > 0.5
    assert (np.abs(gamma[pressed]) < 1e-4).any() and (np.abs(gamma[pressed]) > 1e-4).any()


def _run(tmp_path, **sections):
    import json
    import subprocess
    import sys

    from conftest import ROOT, config_text
    scene = tmp_path / "scene.toml"
    sections.setdefault("output", {}).update(plot=False, progress=False)
    scene.write_text(config_text("oring_stroke", mesh={"h_contact": 0.1, "h_bulk": 0.4,
                                                       "cache": str(ROOT / "meshes")},
                                 **sections))
    r = subprocess.run([sys.executable, "-m", "sealts", "run", str(scene), "-o",
                        str(tmp_path / "out")], capture_output=True, text=True, cwd=ROOT,
                       timeout=600)
    return r, json.loads((tmp_path / "out" / "summary.json").read_text())


def test_a_seal_pressed_into_the_gap_stops_naming_extrusion(tmp_path):
    """The coarse O-ring with a 0.1 mm extrusion gap, pressurised towards 20 MPa: the seal
    flows into the gap and the run stops in pressurisation with one line naming extrusion,
    the pressure reached and the gap, exit 3 (on this mesh at 9 MPa, past the 0.25 mm
    limit; on the 0.05 mm mesh at 6.3 MPa, where the rod side wraps the wall's edge). With
    the walls down to the rod (clearance 0) the same O-ring seals 20 MPa
    (tests/test_stress.py)."""
    r, s = _run(tmp_path, fluid={"p_in": 20.0}, groove={"clearance": 0.1},
                stroke={"velocity": "none"})
    assert r.returncode == 3 and "Traceback" not in r.stderr
    line, = r.stderr.strip().splitlines()
    assert line.startswith("physical stop (extrusion): extrusion: at t = ")
    assert "bore r = 25.1 mm" in line
    p = float(line.split("p = ")[1].split(" MPa")[0])
    assert 3.0 < p < 15.0
    # a physical stop, a result: "stopped" with its cause, not "failed"
    assert s["status"] == "stopped" and s["cause"] == "extrusion"
    assert s["error"].startswith("pressurise: PhysicalStop: extrusion")


def test_a_sealing_stroke_reports_its_extrusion(tmp_path):
    """At 1 MPa the same groove seals: the pressurised state and every stroke row report how
    far the seal is past a wall (microns at most), and the run finishes."""
    r, s = _run(tmp_path, groove={"clearance": 0.1},
                stroke={"t_end": 0.05, "output_times": []})
    assert r.returncode == 0, r.stderr
    assert 0.0 <= s["results"]["extrusion"] < 1e-3
    from sealts.io.results import Results
    e = Results(tmp_path / "out").series["extrusion"]
    assert e.size > 10 and (e >= 0).all() and e.max() < 1e-3
