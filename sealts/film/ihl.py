"""Inverse hydrodynamic lubrication (IHL): a quick film estimate from a dry contact profile.

Blok's inverse theory, as used for rod seals (Mueller and Nau, *Fluid Sealing Technology*,
1998). In a steady film between a stationary seal and a rod moving with v along +y, the
Reynolds equation (Eq. 13 without squeeze and flow factors) integrates once to

    dp/dy = 6 eta v (h - h*) / h^3,        q = v h* / 2,

h* being the film thickness where the pressure peaks (dp/dy = 0) and q the flow per unit
circumference. On the inlet side dp/dy, as a function of h, is largest at h = 3 h* / 2, where
it equals 8 eta v / (9 h*^2). If the seal is soft enough that the film hardly changes the
pressure profile, the dry contact pressure's steepest rise w on the inlet side fixes h*:

    h* = sqrt(8 eta |v| / (9 w)),     w = max(sign(v) dp/dy).

The rod leaves the contact with a film of thickness h*/2 (the flow q at rod speed), so a
stroke of length L carries the volume A L h*/2 through the seal (A = 2 pi r_rod): outward on
the outstroke (v > 0, from the pressurised side to the atmosphere) and back on the instroke.
The net leakage per cycle is A L (h*_out - h*_in)/2; a seal whose instroke film is the
thicker one brings back all it let out. ``ihl_film`` gives the whole film along the contact,
``ihl_flow`` the flow over a stroke cycle.
"""
import numpy as np


def pressure_gradient(y, p):
    """dp/dy at the nodes (second order on a non-uniform grid), MPa/mm."""
    return np.gradient(np.asarray(p, float), np.asarray(y, float))


def inverse_film(y, p, eta, v):
    """IHL for one stroke direction: the film thickness h* (mm), the steepest inlet rise w
    (MPa/mm), where it lies (y, mm) and the flow per unit circumference q (mm^2/s, in the
    direction of v). ``y`` ascending (mm), ``p`` the dry contact pressure (MPa), ``eta``
    (MPa s), ``v`` (mm/s, nonzero)."""
    if v == 0.0:
        raise ValueError("IHL needs a moving rod (v != 0)")
    g = np.sign(v) * pressure_gradient(y, p)
    k = int(np.argmax(g))
    w = float(g[k])
    if w <= 0.0:
        raise ValueError("the pressure profile has no rising inlet flank")
    h = float(np.sqrt(8.0 * eta * abs(v) / (9.0 * w)))
    return {"h_star": h, "w": w, "y_w": float(y[k]), "q": 0.5 * v * h}


def ihl_estimate(y, p, eta, speed, area):
    """Outstroke (+speed) and instroke (-speed) films and the volumes carried per mm of
    stroke (mm^3/mm): ``area`` A of Eq. 31 (2 pi r_rod or the depth)."""
    out = inverse_film(y, p, eta, abs(speed))
    back = inverse_film(y, p, eta, -abs(speed))
    v_out = 0.5 * area * out["h_star"]
    v_in = 0.5 * area * back["h_star"]
    return {"speed": abs(speed), "outstroke": out, "instroke": back,
            "volume_out_per_mm_stroke": v_out, "volume_in_per_mm_stroke": v_in,
            "net_leakage_per_mm_stroke": v_out - v_in}


def ihl_film(y, p, dpdy, v, h_star, y_w, eta):
    """The IHL film (mm) along the contact, Blok's construction (module docstring):
    where p > 0, h solves 6 eta v (h - h*) / h^3 = dp/dy. Where the pressure rises along the
    motion two films do: the thick one up to the steepest rise y_w, the thin one after it;
    where it falls, h < h*. At a node steeper than the steepest rise (possible only
    discretely) h = 3 h*/2, the film there. NaN where p <= 0 (no contact)."""
    s = np.sign(v)
    g = s * np.asarray(dpdy) / (6.0 * eta * abs(v))
    along, along_w = s * np.asarray(y), s * y_w
    h = np.full(len(y), np.nan)
    for i in np.nonzero(np.asarray(p) > 0.0)[0]:
        if abs(g[i]) < 1e-30:
            h[i] = h_star
            continue
        r = np.roots([g[i], 0.0, -1.0, h_star])
        r = np.sort(r[(np.abs(r.imag) < 1e-12 * h_star) & (r.real > 0.0)].real)
        if r.size == 0:
            h[i] = 1.5 * h_star
        elif g[i] < 0.0 or r.size == 1:
            h[i] = r[0]
        else:
            h[i] = r[-1] if along[i] < along_w else r[0]
    return h


def ihl_flow(v, h_out, h_in, speed, area):
    """The IHL flow (mm^3/s) at rod speeds v: area v h*(v) / 2, with the outstroke film
    h_out for v >= 0 and the instroke film h_in for v < 0, both IHL films at ``speed`` and
    scaled as h* ~ sqrt(|v|) (h* = sqrt(8 eta |v| / (9 w)), w fixed by the dry profile)."""
    v = np.asarray(v, float)
    h = np.where(v >= 0.0, h_out, h_in) * np.sqrt(np.abs(v) / speed)
    return 0.5 * area * v * h
