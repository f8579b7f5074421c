"""Inverse hydrodynamic lubrication (sealts.film.ihl) against the forward Reynolds solution.

A rigid gap on [0, 10] mm converges steeply on the inlet side, h = h0 + c (y - 5)^2, and opens
gently on the outlet side, h = h0 + (c/100) (y - 5)^2 (mirrored for v < 0), with p = 0 at both
ends. The steady Reynolds equation without squeeze gives dp/dy = 6 eta v (h - hb)/h^3 with
hb = int h^-2 / int h^-3 (so that p returns to 0). Inverse theory must recover the film at
the pressure peak, hb, from p alone: the inlet's steepest rise is 8 eta v / (9 hb^2), where
h = 3 hb / 2. (The outlet stays below 3 hb / 2, as a dry contact profile's falling flank
has no second rise.)"""
import numpy as np
import pytest

from sealts.film.ihl import ihl_estimate, inverse_film

ETA = 1e-8       # MPa s
H0, C = 1e-3, 4e-4


def forward(v, n=40001):
    y = np.linspace(0.0, 10.0, n)
    x = y - 5.0 if v > 0 else 5.0 - y                   # x < 0 on the inlet
    h = H0 + np.where(x < 0.0, C, C / 100) * x**2
    w = np.full(n, 1.0)
    w[0] = w[-1] = 0.5                                  # trapezoid weights
    hb = (w * h**-2).sum() / (w * h**-3).sum()
    assert h[x > 0].max() < 1.5 * hb
    g = 6 * ETA * v * (h - hb) / h**3
    p = np.concatenate([[0.0], np.cumsum(0.5 * (g[1:] + g[:-1]) * np.diff(y))])
    return y, p, hb, h


@pytest.mark.parametrize("v", [100.0, -100.0, 500.0])
def test_ihl_recovers_the_film_at_the_pressure_peak(v):
    y, p, hb, h = forward(v)
    assert abs(p[-1]) < 1e-6 * np.abs(p).max()           # the forward solution is closed
    r = inverse_film(y, p, ETA, v)
    assert r["h_star"] == pytest.approx(hb, rel=1e-5)
    assert r["q"] == pytest.approx(0.5 * v * hb, rel=1e-5)
    # the steepest rise lies on the inlet, where h = 3 hb / 2
    assert np.interp(r["y_w"], y, h) == pytest.approx(1.5 * hb, rel=2e-3)
    assert (r["y_w"] < 5.0) == (v > 0)


def test_ihl_volumes_and_the_net_leakage_of_an_asymmetric_profile():
    """A profile twice as steep on the atmosphere side: the instroke film is thinner by
    sqrt(2) (h* ~ w^-1/2), so the net leakage per mm of stroke is A (h_out - h_in)/2 > 0."""
    y = np.linspace(0.0, 3.0, 3001)
    p = np.where(y < 2.0, y / 2.0, (3.0 - y))            # rise 0.5 MPa/mm, fall 1 MPa/mm
    area = 2 * np.pi * 25.0
    r = ihl_estimate(y, p, ETA, 100.0, area)
    h_out, h_in = r["outstroke"]["h_star"], r["instroke"]["h_star"]
    assert h_out == pytest.approx(np.sqrt(8 * ETA * 100.0 / (9 * 0.5)), rel=1e-9)
    assert h_out / h_in == pytest.approx(np.sqrt(2.0), rel=1e-9)
    assert r["net_leakage_per_mm_stroke"] == pytest.approx(0.5 * area * (h_out - h_in))


def test_ihl_needs_a_moving_rod_and_a_rising_flank():
    y = np.linspace(0.0, 1.0, 11)
    with pytest.raises(ValueError, match="moving rod"):
        inverse_film(y, y, ETA, 0.0)
    with pytest.raises(ValueError, match="rising inlet"):
        inverse_film(y, -y, ETA, 100.0)


def test_cli_ihl_on_the_pressurised_oring(tmp_path):
    """``sealts ihl``: the coarse O-ring at 1 MPa and 100 mm/s. The summary's films follow
    from the written traction profile (recomputed here from the CSV). Pressure enters on
    the pressurised side: the profile starts at p_in and ends at 0, and the outstroke's
    inlet lies on the pressure side (y below the peak). Without rod.velocity: one line, exit 2."""
    import subprocess
    import sys

    from conftest import config_text
    from sealts.io.results import Results
    text = config_text("oring_pressurise",
                       mesh={"h_contact": 0.1, "h_bulk": 0.4, "cache": str(tmp_path)})
    still = tmp_path / "still.toml"
    still.write_text(text)
    r = subprocess.run([sys.executable, "-m", "sealts", "ihl", str(still), "-o",
                        str(tmp_path / "x")], capture_output=True, text=True)
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and "rod.velocity" in r.stderr
    cfg = tmp_path / "ihl.toml"
    cfg.write_text(config_text("oring_pressurise", rod={"velocity": 100.0},
                               mesh={"h_contact": 0.1, "h_bulk": 0.4, "cache": str(tmp_path)}))
    out = tmp_path / "out"
    r = subprocess.run([sys.executable, "-m", "sealts", "ihl", str(cfg), "-o", str(out)],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    est = Results(out).summary["ihl"]
    prof = Results(out).profiles("ihl_profile")[0.0]
    y, p = prof["y"], prof["p"]
    assert p[0] == pytest.approx(1.0) and p[-1] == 0.0
    g = np.gradient(p, y)
    for key, sign in (("outstroke", 1.0), ("instroke", -1.0)):
        w = (sign * g).max()
        assert est[key]["h_star"] == pytest.approx(np.sqrt(8e-8 * 100.0 / (9 * w)), rel=1e-6)
    assert est["outstroke"]["y_w"] < y[np.argmax(p)] < est["instroke"]["y_w"]
    area = 2 * np.pi * 25.0
    assert est["net_leakage_per_mm_stroke"] == pytest.approx(
        0.5 * area * (est["outstroke"]["h_star"] - est["instroke"]["h_star"]))
