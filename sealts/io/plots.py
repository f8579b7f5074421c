"""PNG plots of film profiles and time series (matplotlib, Agg backend).

Every line is named, so that a seal engineer reads a plot without the code:

* profiles: one panel per quantity (its name in the panel's title, symbol and unit on the
  axis), one colour per output time, and a legend of the times;
* series: the lines of one unit share a panel, each named in the panel's legend.

The functions save the PNG and return the (closed) Figure, whose texts tests can read.
Units are the output files' (mm, MPa, N, s), except film thickness in um.
"""
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

DPI = 110

# profile column -> (panel title, axis label, factor from the file's unit)
PROFILE_QUANTITIES = {
    "h": ("Gap h between rod and seal (the film thickness)", "h [um]", 1e3),
    "p": ("Fluid pressure p in the film", "p [MPa]", 1.0),
    "p_asperity": ("Asperity pressure p_s (solid contact through the roughness)",
                   "p_s [MPa]", 1.0),
    "p_contact": ("Contact pressure of the seal on the rod", "p_contact [MPa]", 1.0),
    "p_fluid": ("Fluid pressure p_fluid on the wetted rod side", "p_fluid [MPa]", 1.0),
    "tau": ("Fluid shear stress tau on the seal (+ = towards +y)", "tau [MPa]", 1.0),
    "tau_solid": ("Solid friction stress tau_s on the seal (+ = towards +y)",
                  "tau_s [MPa]", 1.0),
    "dp_dy": ("Pressure gradient dp/dy of p", "dp/dy [MPa/mm]", 1.0),
}
# the IHL profile's p is the sum of the contact and fluid pressures
IHL_TOTAL = ("Total pressure p = p_contact + p_fluid", "p [MPa]", 1.0)

# output file stem -> (title, legend title of the output times)
PROFILE_FILES = {
    "stroke_profiles": ("Stroke: film and contact along the rod", "time in the stroke"),
    "hold_profiles": ("Viscoelastic hold: gap and contact pressure along the rod",
                      "time in the hold"),
    "ihl_profile": ("Inverse hydrodynamic (IHL) estimate: the static seal's pressures along "
                    "the rod", "time"),
    "profiles": ("Film along the rod", "output time"),
}
def _profile_defaults(path, keys, times):
    """(title, legend title, one label per time) for a profile file the caller did not
    describe. A seal scene's profiles.csv (y, h, p_contact) holds its load steps (the
    writer passes their names as labels)."""
    stem = Path(path).stem
    if stem == "profiles" and "p_contact" in keys and "p" not in keys:
        return ("Seal mounting: gap and contact pressure along the rod", "load step",
                [f"pseudo-time {t:g}" for t in times])
    title, legend = PROFILE_FILES.get(stem, PROFILE_FILES["profiles"])
    return title, legend, [f"t = {t:.4g} s" for t in times]


def _time_colours(n):
    """One colour per output time: up to 10 distinct colours (a stroke's profiles go back
    and forth), more on a scale from early (dark blue) to late (green-yellow)."""
    if n <= 10:
        return [f"C{i}" for i in range(n)]
    return [plt.cm.viridis(0.88 * i / (n - 1)) for i in range(n)]


def plot_profiles(profiles, path, title=None, time_labels=None, time_title=None):
    """Profiles along the rod, one panel per quantity, one colour per output time.

    ``profiles``: list of (t, dict of arrays) with y (mm) and any of h (mm, drawn in um),
    p, p_asperity, p_contact, p_fluid, tau, tau_solid (MPa), dp_dy (MPa/mm); unknown
    columns get a panel under their own name. ``title``, ``time_labels`` (one string per
    profile) and ``time_title`` (the legend's title) default from the file name: e.g.
    "t = 0.5 s" for each output time, "pseudo-time 2" for a seal's load steps. Returns
    the Figure."""
    first = profiles[0][1]
    keys = [k for k in PROFILE_QUANTITIES if k in first]
    keys += [k for k in first if k != "y" and k not in PROFILE_QUANTITIES]
    ihl = "p" in keys and "p_contact" in keys
    if ihl:                 # contact, fluid, then their sum
        keys.remove("p")
        keys.insert(keys.index("p_fluid" if "p_fluid" in keys else "p_contact") + 1, "p")
    d_title, d_legend, d_labels = _profile_defaults(path, keys, [t for t, _ in profiles])
    labels = list(time_labels) if time_labels is not None else d_labels
    n = len(keys)
    fig, ax = plt.subplots(n, 1, figsize=(10, 1.75 * n + 1.1), sharex=True, squeeze=False)
    ax = ax[:, 0]
    colours = _time_colours(len(profiles))
    for a, k in zip(ax, keys):
        name, unit, scale = PROFILE_QUANTITIES.get(k, (k, k, 1.0))
        if k == "p" and ihl:
            name, unit, scale = IHL_TOTAL
        for (t, pr), lab, c in zip(profiles, labels, colours):
            if k in pr:
                a.plot(pr["y"], np.asarray(pr[k], float) * scale, color=c, lw=1.3, label=lab)
        a.set_title(name, loc="left", fontsize=9)
        a.set_ylabel(unit)
        a.grid(alpha=0.3)
        if k == "h":
            h_all = np.concatenate([np.asarray(pr["h"], float) for _, pr in profiles])
            if h_all.min() > 0.0 and h_all.max() > 100.0 * h_all.min():
                a.set_yscale("log")  # a seal's film: um in the contact, mm in the wedges
    ax[-1].set_xlabel("axial position y [mm]")
    if title is None and len(profiles) == 1 and not ihl:   # the time of a steady film
        title = f"{d_title} ({labels[0]})"
    fig.suptitle(title or d_title, fontsize=11)
    right = 1.0
    if len(profiles) > 1:   # the times, right of the panels
        per_col = max(4, int((fig.get_figheight() - 0.6) / 0.17))
        leg = fig.legend(*ax[0].get_legend_handles_labels(), loc="upper right",
                         title=time_title or d_legend, fontsize=8, title_fontsize=9,
                         ncols=-(-len(profiles) // per_col))
        leg.set_in_layout(False)
        width = leg.get_window_extent(fig.canvas.get_renderer()).width / fig.dpi
        right = 1.0 - (width + 0.1) / fig.get_figwidth()
    return _save(fig, path, right)


# series panels: (column, title, axis label, log axis, [(key, legend label, factor, style)])
# Column 0 holds the forces and the rod's motion, column 1 the leakage side: the friction
# sits beside the flows, the rod velocity beside the volumes.
TOTAL = {"color": "k", "lw": 2.0}
SERIES_PANELS = [
    (0, "Friction force on the seal (+ = towards +y)", "friction [N]", False, [
        ("friction_total", "total friction (fluid + solid, rod side)", 1.0, TOTAL),
        ("friction_fluid", "fluid shear friction", 1.0, {}),
        ("friction_solid", "solid (asperity) friction at the rod", 1.0, {}),
        ("friction_groove", "groove walls' friction (axial)", 1.0, {"ls": "--"})]),
    (0, "Rod velocity", "v [mm/s]", False, [("v", "rod velocity v", 1.0, {})]),
    # a key given as a tuple: the first of these names that the rows carry (the stroke's
    # names, then the film-only scenes')
    (0, "Radial load on the rod side", "load [N]", False, [
        ("normal_load", "total (film + asperity)", 1.0, TOTAL),
        (("load_fluid", "load"), "film pressure", 1.0, {}),
        ("load_asperity", "asperity contact", 1.0, {})]),
    (0, "Peak film pressure", "p_max [MPa]", False,
     [(("p_fluid_max", "p_max"), "peak fluid pressure", 1.0, {})]),
    (1, "Flow through the film", "Q [mm^3/s]", False, [
        ("Q_in", "Q_in: into the film at the pressure side", 1.0, {}),
        ("Q_out", "Q_out: out of the film at the air side", 1.0, {})]),
    (1, "Volume passed since t = 0 (leakage)", "V [mm^3]", False, [
        ("V_in", "V_in: in at the pressure side", 1.0, {}),
        ("V_out", "V_out: out at the air side", 1.0, {})]),
    (1, "Minimum film thickness", "h_min [um]", False, [
        ("h_min", "min film thickness h_min", 1e3, {})]),
    (1, "Accepted time step", "dt [s]", True, [
        ("dt", "time step dt", 1.0, {"marker": ".", "ms": 3})]),
]
HOLD_PANELS = [
    (0, "Contact force of the seal on the rod", "force [N]", False, [
        ("rod_force", "rod contact force", 1.0, {"marker": ".", "ms": 3})]),
    (0, "Peak contact pressure and sealed pressure", "pressure [MPa]", False, [
        ("p_contact_max", "peak contact pressure on the rod", 1.0, {"marker": ".", "ms": 3}),
        ("p_sealed", "sealed fluid pressure", 1.0, {"ls": "--"})]),
    (0, "Minimum gap to the rod", "h_min [um]", False, [
        ("h_min", "min gap h_min", 1e3, {})]),
    (0, "Wetted share of the seal's boundary", "fraction [-]", False, [
        ("wetted", "wetted fraction (pressure penetration)", 1.0, {})]),
    (0, "Accepted time step", "dt [s]", True, [
        ("dt", "time step dt", 1.0, {"marker": ".", "ms": 3})]),
]


def _column(rows, key, scale=1.0):
    """rows' values of key as floats (NaN where a row lacks it or holds no number)."""
    out = np.full(len(rows), np.nan)
    for i, r in enumerate(rows):
        try:
            out[i] = float(r[key]) * scale
        except (KeyError, TypeError, ValueError):
            pass
    return out


def _key(key, present):
    """The column a panel line draws: ``key``, or the first present of a tuple of names
    (None where the rows carry none)."""
    names = key if isinstance(key, tuple) else (key,)
    return next((k for k in names if k in present), None)


def _plot_panels(rows, path, specs, title, xlabel, log_time=False):
    """The panels of ``specs`` whose keys the rows carry, in up to two columns, each line
    named in its panel's legend. Returns the Figure."""
    t = _column(rows, "t")
    keep = np.isfinite(t) & (t > 0 if log_time else True)
    present = {k for r in rows for k in r}
    cols = [[s for s in specs if s[0] == c and any(_key(k, present) for k, *_ in s[4])]
            for c in (0, 1)]
    cols = [c for c in cols if c]
    nrow = max((len(c) for c in cols), default=1)
    fig, ax = plt.subplots(nrow, max(len(cols), 1), figsize=(6.5 * max(len(cols), 1) + 0.5,
                           2.1 * nrow + 0.9), sharex=True, squeeze=False)
    for j in range(ax.shape[1]):
        col = cols[j] if cols else []
        for i, a in enumerate(ax[:, j]):
            if i >= len(col):
                a.set_visible(False)
                continue
            _, name, unit, log_y, lines = col[i]
            for key, label, scale, style in lines:
                key = _key(key, present)
                if key is not None:
                    a.plot(t[keep], _column(rows, key, scale)[keep], label=label,
                           **{"lw": 1.3, **style})
            if log_y and a.lines:
                a.set_yscale("log")
            lo, hi = a.get_ylim()
            if not log_y and lo < 0.0 < hi:
                a.axhline(0.0, color="0.5", lw=0.6, zorder=0)
            if log_time:
                a.set_xscale("log")
            a.set_title(name, loc="left", fontsize=9)
            a.set_ylabel(unit)
            a.grid(alpha=0.3)
            a.legend(fontsize=7, loc="best")
        if col:
            ax[len(col) - 1, j].set_xlabel(xlabel)
            ax[len(col) - 1, j].xaxis.set_tick_params(labelbottom=True)
    fig.suptitle(title, fontsize=11)
    return _save(fig, path)


def plot_series(rows, path, title=None):
    """Quantities over time, one row per accepted step; panels for the keys present.

    A stroke's rows (v, friction_*, normal_load, Q_in/out, V_in/out, h_min, dt) give the
    rod velocity and the friction forces (left) beside the flows and volumes (right);
    a transient film's rows (Q_in/out, V_in/out, dt, h_min, p_max ...) the same panels
    for their keys. Rows with ``rod_force`` are a viscoelastic hold:
    :func:`plot_hold_series`. Returns the Figure."""
    if any("rod_force" in r for r in rows):
        return plot_hold_series(rows, path, title)
    if title is None:
        title = ("Stroke: friction, rod velocity, flows and leakage over time"
                 if any("friction_total" in r for r in rows)
                 else "Transient film: results over time")
    return _plot_panels(rows, path, SERIES_PANELS, title, "time t [s]")


def plot_hold_series(rows, path, title=None):
    """A seal's viscoelastic hold on log time: rod force, peak contact and sealed pressure,
    min gap, wetted share and time step (the keys present). Returns the Figure."""
    return _plot_panels(rows, path, HOLD_PANELS,
                        title or "Viscoelastic hold: rod force, pressures and time step",
                        "time in the hold t [s] (log scale)", log_time=True)


def _save(fig, path, right=1.0):
    """Lay the panels out left of ``right`` (a fraction of the width), save, close."""
    fig.tight_layout(rect=(0.0, 0.0, right, 1.0))   # a third of constrained layout's time
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    return fig
