"""The rod's velocity laws: s(t) is the integral of v(t) (checked by quadrature), the kinks and
reversals are where the laws put them, and a bad velocity table is a one-line scene error."""
import numpy as np
import pytest

from sealts.contact.rod_motion import RodMotion, read_velocity_table

LAWS = [RodMotion("constant", -80.0), RodMotion("ramp-hold", 500.0, t_ramp=0.3),
        RodMotion("sine", 500.0, period=10.0),
        RodMotion("table", times=[0.0, 1.0, 2.5, 4.0], values=[0.0, 100.0, -50.0, -50.0])]


@pytest.mark.parametrize("law", LAWS, ids=lambda m: m.law)
def test_displacement_is_the_integral_of_velocity(law):
    t = np.linspace(0.0, 6.0, 60001)
    v = np.array([law.v(x) for x in t])
    s = np.concatenate([[0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(t))])
    exact = np.array([law.s(x) for x in t])
    assert np.abs(exact - s).max() < 1e-6 * max(1.0, np.abs(s).max())
    assert law.s(0.0) == 0.0


def test_the_paper_cycle_kinks_and_reversals():
    sine = LAWS[2]
    assert sine.v(2.5) == pytest.approx(500.0)              # outstroke first
    assert sine.v(7.5) == pytest.approx(-500.0)
    assert sine.s(10.0) == pytest.approx(0.0, abs=1e-9)      # back where it started
    assert sine.s(5.0) == pytest.approx(2 * 500.0 * 10.0 / (2 * np.pi))   # stroke length
    assert sine.reversals(10.0) == [5.0]
    assert LAWS[1].kinks(10.0) == [0.3]
    table = LAWS[3]
    assert table.kinks(10.0) == [1.0, 2.5, 4.0]
    assert table.reversals(10.0) == [pytest.approx(1.0 + 1.5 * 100 / 150)]


def test_velocity_table_errors(tmp_path):
    f = tmp_path / "v.csv"
    f.write_text("time,speed\n0,1\n1,2\n")
    with pytest.raises(ValueError, match="columns t"):
        read_velocity_table(f)
    f.write_text("t,v\n0,1\n0,2\n")
    with pytest.raises(ValueError, match="t must increase"):
        read_velocity_table(f)
    f.write_text("t,v\n0,1\n1,fast\n")
    with pytest.raises(ValueError, match="must be numbers"):
        read_velocity_table(f)
