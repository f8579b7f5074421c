"""The results reader (sealts.io.results) gives back what the writers wrote, and the metrics
(sealts.io.metrics) give the known answers of hand-made profiles and closed forms."""
import math
import subprocess
import sys

import numpy as np
import pytest

from sealts.film import ihl
from sealts.io import metrics
from sealts.io.results import MissingOutput, Results, read_fields, read_profiles, read_series


class RootComm:
    def getRank(self):
        return 0


def written_run(d):
    """An output directory written by sealts' Writer: two profile times (nodes in descending
    y), three series rows, a summary. Returns what was written."""
    from sealts.io.writer import Writer
    w = Writer(d, RootComm(), plots=False)
    y = np.array([0.3, 0.2, -0.1, -0.4])
    prof = {0.0: {"y": y, "h": np.array([1e-3, 7.5e-4, 6.25e-4, 2e-3]),
                  "p": np.array([0.0, 1.5, 2.25, 1.0])},
            0.25: {"y": y + 0.01, "h": np.array([1.1e-3, 8e-4, 6e-4, 2.5e-3]),
                   "p": np.array([0.1, 1.25, 2.0, 1.0])}}
    for t, p in prof.items():
        w.profile(t, p, name="stroke_profiles.csv")
    rows = [{"t": 0.0, "Q_out": 0.0, "V_out": 0.0, "newton": 0},
            {"t": 0.125, "Q_out": 3.5, "V_out": 0.21875, "newton": 3},
            {"t": 0.25, "Q_out": -1.0 / 3.0, "V_out": 0.4, "newton": 2}]
    for r in rows:
        w.series(r)
    summary = {"scene": "x", "stroke": {"leakage_out": 0.4, "steps_accepted": 2}}
    w.summary(summary)
    w.close()
    return prof, rows, summary


def test_writer_output_reads_back(tmp_path):
    prof, rows, summary = written_run(tmp_path)
    r = Results(tmp_path)
    assert r.summary == summary
    assert list(r.series) == ["t", "Q_out", "V_out", "newton"]
    for k in r.series:
        assert np.allclose(r.series[k], [x[k] for x in rows], rtol=5e-10, atol=0)  # %.10g
    h5 = read_series(tmp_path / "series.h5")               # the same rows, unrounded
    assert list(h5) == list(r.series)
    for k in h5:
        assert np.allclose(h5[k], [x[k] for x in rows], rtol=1e-15, atol=0)
    got = r.profiles("stroke_profiles")
    assert list(got) == [0.0, 0.25]
    for t, p in prof.items():
        assert list(got[t]) == ["y", "h", "p"]
        for k in p:
            assert np.allclose(got[t][k], p[k], rtol=5e-10, atol=0)  # %.10g
    by_y = r.profiles("stroke_profiles.csv", sort_by="y")[0.25]
    order = np.argsort(prof[0.25]["y"])
    assert np.array_equal(by_y["y"], got[0.25]["y"][order])
    assert np.array_equal(by_y["h"], got[0.25]["h"][order])


def test_profile_blocks_are_the_runs_of_equal_t(tmp_path):
    """Blocks split where t changes, in file order; a time written again keeps the later
    block; numbers in the writer's %g forms (exponents, nan) parse."""
    path = tmp_path / "p.csv"
    path.write_text("t,y,h\n0,1,1e-3\n0,0,2e-3\n1e-1,0,nan\n1e-1,1,4E-3\n0,5,6\n")
    got = read_profiles(path)
    assert list(got) == [0.0, 0.1]
    assert np.array_equal(got[0.0]["y"], [5.0]) and np.array_equal(got[0.0]["h"], [6.0])
    assert np.isnan(got[0.1]["h"][0]) and got[0.1]["h"][1] == 4e-3
    (tmp_path / "empty.csv").write_text("t,y,h\n")
    assert read_profiles(tmp_path / "empty.csv") == {}


@pytest.mark.parametrize("text, message", [
    ("t,y\n0,1\n0\n", "line 3: 1 values for the 2 columns"),
    ("t,y\n0,abc\n", "line 2: not all numbers"),
    ("y,h\n0,1\n", "no t column"),
    ("", "empty"),
])
def test_malformed_files_are_named_with_the_line(tmp_path, text, message):
    path = tmp_path / "bad.csv"
    path.write_text(text)
    with pytest.raises(ValueError, match=message) as e:
        read_profiles(path)
    assert str(path) in str(e.value)


def test_missing_output_names_the_file(tmp_path):
    with pytest.raises(MissingOutput, match="no such output directory"):
        Results(tmp_path / "nope")
    r = Results(tmp_path)
    for read, name in ((lambda: r.summary, "summary.json"), (lambda: r.series, "series.csv"),
                       (lambda: r.profiles("hold_profiles"), "hold_profiles.csv"),
                       (lambda: r.fields("stroke_fields"), "stroke_fields.xdmf")):
        with pytest.raises(MissingOutput) as e:
            read()
        assert e.value.path == tmp_path / name and str(tmp_path / name) in str(e.value)
        assert isinstance(e.value, FileNotFoundError)


def test_series_h5_is_read_where_there_is_no_csv(tmp_path):
    import h5py
    with h5py.File(tmp_path / "series.h5", "w") as f:
        f["t"], f["v"] = [0.0, 1.0], [2.0, 3.0]
        f.attrs["columns"] = "t,v"
    s = Results(tmp_path).series
    assert list(s) == ["t", "v"] and np.array_equal(s["v"], [2.0, 3.0])


def mesh():
    X = np.array([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [0.0, 1.0], [1.0, 1.0], [2.0, 1.0]])
    conn = np.array([[0, 1, 4, 3], [1, 2, 5, 4]])
    return X, conn


def test_stroke_field_series_reads_back(tmp_path):
    """stroke_fields.xdmf as sealts.io.fields.FieldSeries writes it: the mesh once, then
    point and cell arrays per time step."""
    from sealts.io.fields import FieldSeries
    X, conn = mesh()
    rng = np.random.default_rng(0)
    steps = [(0.0, rng.normal(size=(6, 3)), rng.normal(size=6), rng.normal(size=2)),
             (0.5, rng.normal(size=(6, 3)), rng.normal(size=6), rng.normal(size=2))]
    fs = FieldSeries(tmp_path / "stroke_fields.xdmf", X, conn)
    for t, disp, p, mises in steps:
        fs.add(t, {"displacement": disp, "film_pressure": p}, {"von_mises": mises})
    fs.close()
    f = Results(tmp_path).fields("stroke_fields")
    assert len(f) == 2 and np.array_equal(f.times, [0.0, 0.5])
    assert np.array_equal(f.points[:, :2], X) and np.array_equal(f.cells, conn)
    for k, (_, disp, p, mises) in enumerate(steps):
        assert np.array_equal(f.point_data["displacement"][k], disp)
        assert np.array_equal(f.point_data["film_pressure"][k], p)
        assert np.array_equal(f.cell_data["von_mises"][k], mises)


def test_meshio_fields_read_back(tmp_path):
    """fields.xdmf as the seal run writes it with meshio: one state, no time."""
    import meshio
    X, conn = mesh()
    points = np.c_[X, np.zeros(6)]
    disp = np.arange(18.0).reshape(6, 3)
    meshio.write(tmp_path / "fields.xdmf", meshio.Mesh(
        points, [("quad", conn)], point_data={"displacement": disp},
        cell_data={"von_mises": [np.array([1.5, 2.5])], "sigma_rr": [np.array([-1.0, 3.0])]}))
    f = read_fields(tmp_path / "fields.xdmf")
    assert len(f) == 1 and np.isnan(f.times[0])
    assert np.array_equal(f.points, points) and np.array_equal(f.cells, conn)
    assert np.array_equal(f.point_data["displacement"][0], disp)
    assert np.array_equal(f.cell_data["von_mises"][0], [1.5, 2.5])
    assert np.array_equal(f.cell_data["sigma_rr"][0], [-1.0, 3.0])


def test_reader_imports_no_solver():
    code = ("import sys, sealts.io.results, sealts.io.metrics; "
            "print(sorted(m for m in ('petsc4py', 'numba', 'h5py', 'meshio', 'mpi4py') "
            "if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "[]"


# --------------------------------------------------------------------------------------
# metrics

def stroke_profile():
    """A hand-made profile on a non-uniform grid: asperities touch on y in [-0.6, 0.9]."""
    y = np.array([-1.0, -0.6, -0.3, 0.0, 0.1, 0.5, 0.9, 1.2])
    return {"y": y,
            "h": np.array([5e-3, 9e-4, 6e-4, 5e-4, 4e-4, 5.5e-4, 8e-4, 4e-3]),
            "p": np.array([1.0, 1.2, 1.8, 2.4, 2.0, 0.9, -0.2, 0.0]),
            "p_asperity": np.array([0.0, 1e-3, 0.4, 0.6, 0.9, 0.5, 0.02, 0.0]),
            "tau": np.array([0.0, -1e-3, 2e-3, -3e-3, 1e-3, 0.0, 0.0, 0.0]),
            "tau_solid": np.array([0.0, 0.01, -0.05, 0.04, 0.03, 0.0, 0.0, 0.0])}


def test_band_and_film_metrics_of_a_hand_made_profile():
    pr = stroke_profile()
    b = metrics.contact_band(pr)
    assert b == (-0.6, 0.9)
    core = metrics.band_core(b, trim=0.1)
    assert core == pytest.approx((-0.45, 0.75))
    assert np.array_equal(metrics.in_band(pr, core), [0, 0, 1, 1, 1, 1, 0, 0])
    m = metrics.film_metrics(pr, core)
    assert m["h_min"] == 4e-4
    assert m["h_mean"] == pytest.approx((6e-4 + 5e-4 + 4e-4 + 5.5e-4) / 4)
    assert (m["p_max"], m["y_pmax"], m["h_at_pmax"]) == (2.4, 0.0, 5e-4)
    assert (m["p_min"], m["y_pmin"]) == (-0.2, 0.9)
    assert (m["pa_max"], m["tau_max"], m["taus_max"]) == (0.9, 3e-3, 0.05)
    assert m["total_max"] == pytest.approx(3.0)           # 2.4 + 0.6 at y = 0
    with pytest.raises(ValueError, match="no contact band"):
        metrics.contact_band({**pr, "p_asperity": np.zeros(8)})


def test_ripple_is_the_alternating_amplitude_on_any_grid():
    y = np.cumsum(np.r_[0.0, np.linspace(0.01, 0.05, 30)])    # graded, not uniform
    smooth = 6e-4 + 2e-4 * y
    e = 3e-6
    pr = {"y": y, "h": smooth + e * (-1.0) ** np.arange(y.size)}
    assert metrics.ripple(pr, (y[0], y[-1])) == pytest.approx(e, rel=1e-9)
    assert metrics.ripple({"y": y, "h": smooth}, (y[0], y[-1])) == pytest.approx(0.0, abs=1e-18)
    assert metrics.ripple(pr, (y[0], y[1])) == 0.0             # two nodes: no ripple


def test_film_change_and_steadiness_against_a_shifted_film():
    """The last film is the earlier one plus 1e-5 mm on other nodes; the earlier one is
    linear in y, so interpolating it is exact."""
    y0 = np.linspace(-1.0, 1.0, 7)
    y1 = np.linspace(-0.95, 0.95, 12)
    first = {"y": y0, "h": 5e-4 + 1e-4 * y0}
    last = {"y": y1, "h": 5e-4 + 1e-4 * y1 + 1e-5}
    band = (-0.5, 0.5)
    yb, dh = metrics.film_change(last, first, band)
    assert np.array_equal(yb, y1[np.abs(y1) <= 0.5]) and np.allclose(dh, 1e-5, rtol=1e-9)
    change, ta, tb = metrics.steady_change({1.0: last, 0.5: first}, band)
    assert (ta, tb) == (0.5, 1.0)
    assert change == pytest.approx(1e-5 / (5e-4 + 1e-4 * yb.mean() + 1e-5), rel=1e-9)


def test_series_end_share_and_flow_film():
    s = {"t": np.array([0.0, 1.0]), "load_asperity": np.array([5.0, 30.0]),
         "load_fluid": np.array([1.0, 10.0])}
    end = metrics.at_end(s)
    assert end == {"t": 1.0, "load_asperity": 30.0, "load_fluid": 10.0}
    assert metrics.asperity_share(end) == 0.75
    # Couette flow of a uniform film h past a rod of radius 25 mm: q = 2 pi r v h / 2
    area, h, v = 2 * np.pi * 25.0, 6e-4, np.array([100.0, -500.0])
    q = np.pi * 25.0 * v * h
    assert np.allclose(metrics.flow_film(q, v, area), h, rtol=1e-12)


ETA = 1e-8


def test_ihl_film_inverts_the_reynolds_gradient():
    """Blok's construction returns h with 6 eta v (h - h*)/h^3 = dp/dy, thick on the inlet
    flank before the steepest rise, thin after it; mirrored for the instroke; NaN out of
    contact."""
    h_star, v = 5e-4, 100.0
    y = np.linspace(-1.0, 1.0, 9)
    h = np.array([1.4, 1.2, 1.0, 0.8, 0.6, 0.55, 0.5, 0.45, 0.42]) * 1e-3
    g = 6 * ETA * v * (h - h_star) / h**3
    p = np.ones_like(y)
    k = int(np.argmax(g))
    y_w = 0.5 * (y[k] + y[k + 1])
    assert np.allclose(ihl.ihl_film(y, p, g, v, h_star, y_w, ETA), h, rtol=1e-9)
    back = ihl.ihl_film(-y[::-1], p, -g[::-1], -v, h_star, -y_w, ETA)
    assert np.allclose(back, h[::-1], rtol=1e-9)
    p[0] = 0.0
    assert np.isnan(ihl.ihl_film(y, p, g, v, h_star, y_w, ETA)[0])


def test_ihl_film_at_the_steepest_rise_is_three_halves_h_star():
    """Where dp/dy is the steepest rise w of sealts.film.ihl, 6 eta v (h - h*)/h^3 = w has
    its double root h = 3 h*/2 (and no root where it is steeper)."""
    from sealts.film.ihl import inverse_film, pressure_gradient
    y = np.linspace(-1.2, 1.2, 121)
    p = 2.0 * np.clip(1.0 - y**2, 0.0, None) ** 1.5
    est = inverse_film(y, p, ETA, 100.0)
    k = int(np.argmin(np.abs(y - est["y_w"])))
    h = ihl.ihl_film(y, p, pressure_gradient(y, p), 100.0, est["h_star"], est["y_w"], ETA)
    assert h[k] == pytest.approx(1.5 * est["h_star"], rel=1e-6)
    steeper = ihl.ihl_film(y[k:k + 1], [1.0], [2 * est["w"]], 100.0, est["h_star"], 0.0, ETA)
    assert steeper[0] == 1.5 * est["h_star"]


def test_inlet_span_counts_the_elements_to_the_steepest_rise():
    """Nodes 3-8 in contact, 0-2 and 9 dry; outstroke the rise from the last dry node (2)
    to the node at y_w = 5.1 (node 5) is three elements; instroke the inlet is the other
    end, from node 9 down to node 5."""
    ip = {"y": np.arange(10.0), "p_contact": np.r_[np.zeros(3), np.ones(6), 0.0]}
    assert metrics.inlet_nodes(ip, 5.1, 1.0) == (3, 5)
    assert metrics.inlet_span(ip, 5.1, 1.0) == 3
    assert metrics.inlet_nodes(ip, 5.1, -1.0) == (8, 5)
    assert metrics.inlet_span(ip, 5.1, -1.0) == 4
    with pytest.raises(ValueError, match="no node in contact"):
        metrics.inlet_span({**ip, "p_contact": np.zeros(10)}, 5.0, 1.0)


def test_ihl_flow_over_a_sine_cycle_against_its_integral():
    """q = A v h*(v)/2 with h* ~ sqrt(|v|): over v = V sin(w t) each half stroke carries
    A h* V / (2 w) * int_0^pi sin^(3/2) = A h* V / (2 w) sqrt(pi) G(5/4) / G(7/4)."""
    area, V, T, h_out, h_in = 2 * np.pi * 25.0, 500.0, 10.0, 8e-4, 7e-4
    t = np.linspace(0.0, T, 200001)
    v = V * np.sin(2 * np.pi * t / T)
    q = ihl.ihl_flow(v, h_out, h_in, V, area)
    assert ihl.ihl_flow(V, h_out, h_in, V, area) == pytest.approx(0.5 * area * V * h_out)
    half = area * V / (2 * (2 * np.pi / T)) * math.sqrt(math.pi) * math.gamma(1.25) / math.gamma(1.75)
    vol = metrics.cumulative_volume(t, q)
    assert vol[t.size // 2] == pytest.approx(half * h_out, rel=1e-6)
    assert vol[-1] == pytest.approx(half * (h_out - h_in), rel=1e-5)
    # a piecewise-linear q is integrated exactly: a ramp to 2 over 1 s, then 2 for 2 s
    assert np.array_equal(metrics.cumulative_volume([0.0, 1.0, 3.0], [0.0, 2.0, 2.0]),
                          [0.0, 1.0, 5.0])


def test_a_new_run_deletes_the_last_runs_files_and_keeps_its_inputs(tmp_path):
    """The manifest lists every file a run writes; the next run in the same directory
    deletes those (and the names of runs older than the manifest) before it writes, except
    the files its scene reads: no directory holds a mix of two runs."""
    import json
    from sealts.io.writer import Writer
    written_run(tmp_path)
    manifest = json.loads((tmp_path / "manifest.json").read_text())["files"]
    assert sorted(manifest) == sorted(["stroke_profiles.csv", "series.csv", "summary.json",
                                      "series.h5"])
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(manifest + ["manifest.json"])
    # an earlier run's extra file (in its manifest), a pre-manifest field file, a kept input,
    # and a file of the user's that no run wrote
    (tmp_path / "stroke_fields.h5").write_text("old")        # a legacy name
    (tmp_path / "custom_output.csv").write_text("old")
    (tmp_path / "state.h5").write_text("input")
    (tmp_path / "notes.txt").write_text("mine")
    (tmp_path / "manifest.json").write_text(json.dumps({"files": manifest +
                                                        ["custom_output.csv", "../x"]}))
    w = Writer(tmp_path, RootComm(), plots=False, keep=[tmp_path / "state.h5"])
    left = sorted(p.name for p in tmp_path.iterdir())
    assert left == ["manifest.json", "notes.txt", "state.h5"]
    w.series({"t": 0.0, "V_out": 0.0})
    w.close()
    assert json.loads((tmp_path / "manifest.json").read_text())["files"] == ["series.csv",
                                                                           "series.h5"]
