"""Two stroke cycles side by side: the film and friction of the paper's O-ring on two
asperity laws (README, "Greenwood-Williamson asperities on the stroke").

Reads finished runs' output directories (sealts.io.results) and writes one PNG: the film
thickness h and the film and asperity pressures along the contact at an outstroke and an
instroke time, and the total friction force over the cycle, one colour per run, labelled by
its scene's asperity law and contact mesh; and the smallest gap over the cycle.

    .venv/bin/sealts run configs/oring_stroke.toml -o results/exp    # or any stroke runs
    .venv/bin/sealts run configs/oring_stroke_gw.toml -o results/gw
    .venv/bin/python scripts/plot_asperity_laws.py results/exp results/gw \\
        -o benchmarks/asperity_laws.png [--times 2.5 7.5]
"""
import argparse
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from sealts.io.results import MissingOutput, Results  # noqa: E402


def label(r):
    """'<law>, contact <h> mm' of a run's resolved scene."""
    scene = r.summary["provenance"]["scene"]
    law = scene["asperity"]["law"]
    law = "Greenwood-Williamson" if law == "greenwood-williamson" else "exponential (Eq. 44)"
    edge = scene["mesh"].get("h_edge", 0.0)
    return (f"{law}, contact {scene['mesh']['h_contact']:g} mm"
            + (f", {1e3 * edge:g} um at its edges" if edge else ""))


def nearest(profiles, t):
    """The profile time closest to t."""
    return min(profiles, key=lambda s: abs(s - t))


def plot(runs, times, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(3, len(times), figsize=(6 * len(times), 11), squeeze=False)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for k, r in enumerate(runs):
        c, name = colours[k % len(colours)], label(r)
        prof = r.profiles("stroke_profiles", sort_by="y")
        for j, t in enumerate(times):
            tp = nearest(prof, t)
            p = prof[tp]
            v = np.interp(tp, r.series["t"], r.series["v"])
            ax[0, j].plot(p["y"], 1e3 * p["h"], color=c, label=name)
            ax[1, j].plot(p["y"], p["p"], color=c, label=f"{name}: film")
            ax[1, j].plot(p["y"], p["p_asperity"], color=c, ls=":",
                          label=f"{name}: asperities")
            ax[0, j].set_title(f"t = {tp:g} s, v = {v:.0f} mm/s")
        ax[2, 0].plot(r.series["t"], r.series["friction_total"], color=c, label=name)
        if len(times) > 1:
            ax[2, 1].plot(r.series["t"], 1e3 * r.series["h_min"], color=c, label=name)
    for j in range(len(times)):
        ax[0, j].set_ylim(-3.0, 3.0)
        ax[0, j].set_ylabel("gap h [um] (< 0: into the roughness)")
        ax[1, j].set_ylabel("pressure [MPa]")
        for i in (0, 1):
            ax[i, j].set_xlabel("axial position y on the seal [mm]")
            ax[i, j].legend(fontsize=8)
            ax[i, j].grid(alpha=0.3)
    ax[2, 0].set_xlabel("t [s]")
    ax[2, 0].set_ylabel("friction on the rod, fluid + solid [N]")
    ax[2, 0].legend(fontsize=8)
    ax[2, 0].grid(alpha=0.3)
    if len(times) > 1:
        ax[2, 1].set_xlabel("t [s]")
        ax[2, 1].set_ylabel("smallest gap min h [um]")
        ax[2, 1].legend(fontsize=8)
        ax[2, 1].grid(alpha=0.3)
    for j in range(2, len(times)):
        ax[2, j].axis("off")
    fig.suptitle("The paper's O-ring cycle (1 MPa, 500 mm/s sine) on two asperity laws")
    fig.tight_layout(rect=(0, 0, 1, 0.97))
    fig.savefig(out, dpi=90)
    return fig


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("runs", nargs="+", help="finished stroke runs' output directories")
    ap.add_argument("-o", "--out", default="asperity_laws.png", help="the PNG to write")
    ap.add_argument("--times", nargs="+", type=float, default=[2.5, 7.5],
                    help="profile times, s (the nearest written profile is taken)")
    a = ap.parse_args(argv)
    try:
        runs = [Results(d) for d in a.runs]
        plot(runs, a.times, a.out)
    except (MissingOutput, KeyError, ValueError) as e:
        print(f"plot_asperity_laws: {e}", file=sys.stderr)
        sys.exit(2)
    print(f"written: {a.out}")


if __name__ == "__main__":
    main()
