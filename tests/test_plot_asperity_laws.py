"""scripts/plot_asperity_laws.py on two made-up stroke runs (no solver): every line named,
every panel with a unit, each run labelled by its law and contact mesh, and a missing run
a one-line error with exit 2."""
import json
import subprocess
import sys

import numpy as np

from conftest import ROOT, load_script
from test_plots import assert_readable

SCRIPT = ROOT / "scripts" / "plot_asperity_laws.py"


def load():
    return load_script("plot_asperity_laws")


def fake_run(path, law, h_contact, lift):
    """An output directory as a finished stroke writes it: summary, series, profiles."""
    path.mkdir()
    scene = {"asperity": {"law": law}, "mesh": {"h_contact": h_contact}}
    (path / "summary.json").write_text(json.dumps({"status": "finished",
                                                   "provenance": {"scene": scene}}))
    t = np.linspace(0.0, 10.0, 101)
    with open(path / "series.csv", "w") as f:
        f.write("t,v,friction_total,h_min\n")
        for x in t:
            v = 500.0 * np.sin(2 * np.pi * x / 10.0)
            f.write(f"{x},{v},{0.1 * v},{lift * 1e-4 * (1 + np.sin(x))}\n")
    y = np.linspace(-1.0, 2.0, 31)
    with open(path / "stroke_profiles.csv", "w") as f:
        f.write("t,y,h,p,p_asperity,tau,tau_solid\n")
        for x in (0.0, 2.5, 7.5, 10.0):
            for yi in y:
                f.write(f"{x},{yi},{lift * 1e-3 * (0.5 + yi ** 2)},{2 * np.exp(-yi ** 2)},"
                        f"{0.1 * np.exp(-yi ** 2)},0,0\n")


def test_the_figure_names_both_runs_and_every_line(tmp_path):
    from sealts.io.results import Results
    fake_run(tmp_path / "exp", "exponential", 0.01, 1.0)
    fake_run(tmp_path / "gw", "greenwood-williamson", 0.0125, 1.3)
    fig = load().plot([Results(tmp_path / "exp"), Results(tmp_path / "gw")], [2.5, 7.5],
                      tmp_path / "laws.png")
    assert (tmp_path / "laws.png").stat().st_size > 0
    assert_readable(fig)
    names = " ".join(t.get_text() for a in fig.axes if a.get_legend()
                     for t in a.get_legend().get_texts())
    assert "Greenwood-Williamson, contact 0.0125 mm" in names
    assert "exponential (Eq. 44), contact 0.01 mm" in names


def test_a_missing_run_is_one_line_and_exit_2(tmp_path):
    r = subprocess.run([sys.executable, str(SCRIPT), str(tmp_path / "none"), "-o",
                        str(tmp_path / "x.png")], capture_output=True, text=True)
    assert r.returncode == 2
    assert r.stderr.count("\n") == 1 and "no such output directory" in r.stderr
    assert "Traceback" not in r.stderr
