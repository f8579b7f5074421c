"""The PNG plots name every line: synthetic profiles and series, no solver run."""
import numpy as np
import pytest

from sealts.io.plots import plot_hold_series, plot_profiles, plot_series

Y = np.linspace(-1.0, 2.0, 61)                   # mm


def stroke_profile(t):
    h = 1e-4 + 0.05 * np.abs(Y) ** 2 * (1 + 0.1 * t)  # mm: um in the contact, mm outside
    bump = np.exp(-Y**2 / 0.2)
    return {"y": Y, "h": h, "p": 5 * bump * (1 + 0.05 * t), "p_asperity": 2 * bump**2,
            "tau": 0.01 * np.sin(t) * bump, "tau_solid": 0.2 * bump**2 * np.cos(t)}


def contact_profile(t):
    return {"y": Y, "h": 1e-3 * (1 + Y**2), "p_contact": 4 * np.exp(-Y**2) * (1 + 0.01 * t)}


def legend_texts(fig):
    legends = list(fig.legends) + [a.get_legend() for a in fig.axes if a.get_legend()]
    return [t.get_text() for lg in legends for t in lg.get_texts()]


def all_texts(fig):
    return " | ".join(t.get_text() for t in fig.findobj(lambda a: hasattr(a, "get_text")))


def assert_readable(fig):
    """Each line on a visible panel is named in a legend; each panel has a unit."""
    named = set(legend_texts(fig))
    for a in fig.axes:
        if not a.get_visible():
            continue
        assert "[" in a.get_ylabel() and "]" in a.get_ylabel(), a.get_ylabel()
        for line in a.get_lines():
            if not line.get_label().startswith("_"):        # not a zero line
                assert line.get_label() in named, (a.get_title(), line.get_label())
        assert any(not ln.get_label().startswith("_") for ln in a.get_lines())
    assert any("[mm]" in a.get_xlabel() or "[s]" in a.get_xlabel() for a in fig.axes)


@pytest.mark.parametrize("n_times", [3, 10])
def test_stroke_profiles_name_each_time_and_quantity(tmp_path, n_times):
    times = list(np.linspace(0.0, 10.0, n_times))
    path = tmp_path / "stroke_profiles.png"
    fig = plot_profiles([(t, stroke_profile(t)) for t in times], path)
    assert path.stat().st_size > 10_000
    assert_readable(fig)
    legend = legend_texts(fig)
    for t in times:
        assert f"t = {t:.4g} s" in legend
    text = all_texts(fig).lower()
    for words in ("fluid pressure p", "asperity pressure p_s", "fluid shear",
                  "solid friction stress", "film thickness", "time in the stroke"):
        assert words in text, words
    units = [a.get_ylabel() for a in fig.axes]
    assert units == ["h [um]", "p [MPa]", "p_s [MPa]", "tau [MPa]", "tau_s [MPa]"]
    assert fig.axes[-1].get_xlabel() == "axial position y [mm]"
    assert fig.axes[0].get_yscale() == "log"          # um to mm: the gap on a log axis


def test_film_profiles_without_asperity(tmp_path):
    profs = [(t, {k: v for k, v in stroke_profile(t).items() if k in "y h p tau".split()})
             for t in (0.0, 0.01)]
    fig = plot_profiles(profs, tmp_path / "profiles.png")
    assert_readable(fig)
    assert [a.get_ylabel() for a in fig.axes] == ["h [um]", "p [MPa]", "tau [MPa]"]
    assert "asperity" not in all_texts(fig).lower()
    assert {"t = 0 s", "t = 0.01 s"} <= set(legend_texts(fig))
    fig = plot_profiles(profs[1:], tmp_path / "steady.png")       # a steady film: one time
    assert legend_texts(fig) == [] and "(t = 0.01 s)" in fig.get_suptitle()


def test_mount_profiles_name_the_load_steps(tmp_path):
    """The steps name their profiles (Writer.profile's label); without names the
    pseudo-times label them."""
    pair = [(2.0, contact_profile(2.0)), (4.0, contact_profile(4.0))]
    (tmp_path / "named").mkdir()
    fig = plot_profiles(pair, tmp_path / "profiles.png")
    assert legend_texts(fig) == ["pseudo-time 2", "pseudo-time 4"]
    fig = plot_profiles(pair, tmp_path / "named" / "profiles.png",
                        time_labels=["mounted, pseudo-time 2", "pressurised, pseudo-time 4"])
    assert_readable(fig)
    legend = legend_texts(fig)
    assert any("mounted" in s and "2" in s for s in legend)
    assert any("pressurised" in s and "4" in s for s in legend)
    assert "contact pressure" in all_texts(fig).lower()
    assert "p_contact [MPa]" in [a.get_ylabel() for a in fig.axes]


def test_hold_profiles_name_every_log_spaced_time(tmp_path):
    times = list(10.0 ** np.arange(-6, 7))
    fig = plot_profiles([(t, contact_profile(np.log10(t))) for t in times],
                        tmp_path / "hold_profiles.png")
    assert_readable(fig)
    legend = legend_texts(fig)
    for t in times:
        assert f"t = {t:.4g} s" in legend
    assert "time in the hold" in all_texts(fig)


def test_ihl_profile_names_its_pressures(tmp_path):
    p_c, p_f = 3 * np.exp(-Y**2), 0.5 * (Y < 0)
    prof = {"y": Y, "h": 1e-3 * (1 + Y**2), "p_contact": p_c, "p_fluid": p_f,
            "p": p_c + p_f, "dp_dy": np.gradient(p_c + p_f, Y)}
    fig = plot_profiles([(0.0, prof)], tmp_path / "ihl_profile.png")
    text = all_texts(fig).lower()
    for words in ("contact pressure", "fluid pressure p_fluid", "total pressure",
                  "dp/dy [mpa/mm]"):
        assert words in text, words
    assert [a.get_ylabel() for a in fig.axes] == ["h [um]", "p_contact [MPa]", "p_fluid [MPa]",
                                                  "p [MPa]", "dp/dy [MPa/mm]"]
    assert legend_texts(fig) == []                   # one profile: no legend of times


def test_caller_labels_and_title_win(tmp_path):
    fig = plot_profiles([(1.0, contact_profile(1.0)), (2.0, contact_profile(2.0))],
                        tmp_path / "x.png", title="My seal", time_labels=["a", "b"],
                        time_title="case")
    assert set(legend_texts(fig)) == {"a", "b"}
    assert fig.get_suptitle() == "My seal"
    assert fig.legends[0].get_title().get_text() == "case"


def stroke_rows(n=40):
    rows = []
    for i, t in enumerate(np.linspace(0.0, 10.0, n)):
        v = 200 * np.sin(2 * np.pi * t / 10)
        rows.append({"t": t, "v": v, "friction_fluid": 0.01 * v, "friction_solid": 3 * np.sign(v),
                     "friction_total": 0.01 * v + 3 * np.sign(v), "friction_groove": -0.5,
                     "normal_load": 100.0, "load_fluid": 30.0, "load_asperity": 70.0,
                     "Q_in": 0.1 * v, "Q_out": 0.09 * v, "V_in": t, "V_out": 0.9 * t,
                     "h_min": 2e-4, "asperity_contact_length": 0.3, "p_fluid_max": 5.0,
                     "dt": 0.1 + 0.01 * i, "newton": 3 * i})
    return rows


def test_stroke_series_shows_friction_beside_flows(tmp_path):
    path = tmp_path / "series.png"
    fig = plot_series(stroke_rows(), path)
    assert path.stat().st_size > 10_000
    assert_readable(fig)
    legend = " | ".join(legend_texts(fig))
    for words in ("rod velocity v", "total friction", "fluid shear friction",
                  "solid (asperity) friction", "groove", "Q_in", "Q_out", "V_in", "V_out"):
        assert words in legend, words
    panels = {a.get_title(loc="left"): a for a in fig.axes if a.get_visible()}
    friction = next(a for k, a in panels.items() if k.startswith("Friction"))
    flow = next(a for k, a in panels.items() if k.startswith("Flow"))
    # side by side: different columns, overlapping rows
    fb, qb = friction.get_position(), flow.get_position()
    assert fb.x1 <= qb.x0 and fb.y0 < qb.y1 and qb.y0 < fb.y1
    assert friction.get_ylabel() == "friction [N]" and flow.get_ylabel() == "Q [mm^3/s]"


def test_film_series_with_missing_keys(tmp_path):
    rows = [{"t": t, "Q_in": 1.0, "Q_out": 0.5, "V_in": t, "V_out": 0.5 * t, "dt": 1e-3,
             "h_min": 1e-3, "p_max": 2.0} for t in np.linspace(0, 1, 10)]
    rows[3].pop("V_out")                              # a row without a key
    rows[4]["p_max"] = None                           # or without a number
    fig = plot_series(rows, tmp_path / "series.png")
    assert_readable(fig)
    legend = " | ".join(legend_texts(fig))
    assert "Q_in" in legend and "V_out" in legend and "time step" in legend
    assert "friction" not in all_texts(fig).lower()   # no panel for keys not there
    fig = plot_series([{"t": 0.0, "Q_out": 1.0}, {"t": 1.0, "Q_out": 2.0}],
                      tmp_path / "minimal.png")
    assert_readable(fig)


def test_hold_series_on_log_time(tmp_path):
    t = np.concatenate([[0.0], 10.0 ** np.linspace(-6, 5, 30)])
    rows = [{"t": ti, "dt": 0.1 * max(ti, 1e-6), "p_sealed": 5.0, "rod_force": 2800 + np.log1p(ti),
             "p_contact_max": 9.0, "h_min": -1e-5, "wetted": 0.3, "newton": 2} for ti in t]
    fig = plot_series(rows, tmp_path / "series.png")    # dispatches on rod_force
    assert_readable(fig)
    assert all(a.get_xscale() == "log" for a in fig.axes)
    legend = " | ".join(legend_texts(fig))
    assert "rod contact force" in legend and "peak contact pressure" in legend
    assert "hold" in fig.get_suptitle()
    fig = plot_hold_series(rows, tmp_path / "hold.png", title="Hold of seal X")
    assert fig.get_suptitle() == "Hold of seal X"
