"""Numbers read off a seal run's output: the contact band, film statistics over it, ripple
and steadiness of the film, the film that carries a flow, and where an IHL estimate's inlet
lies (the IHL film and flow themselves are :mod:`sealts.film.ihl`).

A *profile* is one output time of a profile CSV as :func:`sealts.io.results.read_profiles`
returns it with ``sort_by="y"``: arrays along the rod side, y ascending: y, h (mm), p,
p_asperity (MPa), tau, tau_solid (MPa); IHL profiles (``ihl_profile.csv``) have y, h,
p_contact, p and dp_dy instead. A *band* is a pair (y_lo, y_hi) in mm. Units: mm, s, MPa,
mm^3/s. Only numpy is needed.
"""
import numpy as np

from ..film.odd_even import neighbour_deviation


def contact_band(prof, threshold=1e-6):
    """(y_lo, y_hi): the span of y where the asperity pressure exceeds ``threshold`` (MPa).
    On the t = 0 profile of a stroke, before the film forms, that is the dry contact."""
    y = prof["y"][prof["p_asperity"] > threshold]
    if y.size == 0:
        raise ValueError("no node carries asperity pressure: no contact band")
    return float(y.min()), float(y.max())


def in_band(prof, band):
    """Mask of the nodes with band[0] <= y <= band[1]."""
    return (prof["y"] >= band[0]) & (prof["y"] <= band[1])


def band_core(band, trim=0.1):
    """The band without ``trim`` of its width at each end: clear of the inlet and outlet
    menisci, where a small axial shift of the steep flank reads as a large change of h."""
    w = band[1] - band[0]
    return band[0] + trim * w, band[1] - trim * w


def film_metrics(prof, band):
    """Film numbers of one profile: over the band, h_min and h_mean (mm) and total_max, the
    largest fluid + asperity pressure (MPa); over the whole profile, the peak fluid pressure
    p_max, its position y_pmax and the film h_at_pmax there, the lowest fluid pressure p_min
    and its y_pmin, the peak asperity pressure pa_max and the peak |tau| and |tau_solid|
    (tau_max, taus_max, MPa)."""
    m = in_band(prof, band)
    y, h, p, pa = prof["y"], prof["h"], prof["p"], prof["p_asperity"]
    k = int(np.argmax(p))
    j = int(np.argmin(p))
    return {"h_min": float(h[m].min()), "h_mean": float(h[m].mean()),
            "h_at_pmax": float(h[k]), "p_max": float(p[k]), "y_pmax": float(y[k]),
            "p_min": float(p[j]), "y_pmin": float(y[j]), "pa_max": float(pa.max()),
            "tau_max": float(np.abs(prof["tau"]).max()),
            "taus_max": float(np.abs(prof["tau_solid"]).max()),
            "total_max": float((p + pa)[m].max())}


def ripple(prof, band):
    """Amplitude (mm) of the node-to-node ripple of h over the band: half the largest
    deviation of a node's h from the straight line through its two neighbours. An
    alternating +-e on any smooth film gives about e; a straight film gives 0 on any grid."""
    m = in_band(prof, band)
    y, h = prof["y"][m], prof["h"][m]
    if h.size < 3:
        return 0.0
    return float(0.5 * np.abs(neighbour_deviation(y, h)).max())


def film_change(prof, ref, band):
    """(y, h - h_ref) at the nodes of ``prof`` in the band, h_ref interpolated linearly in y
    from the profile ``ref`` (which may have other nodes): how one film differs from
    another."""
    m = in_band(prof, band)
    y = prof["y"][m]
    return y, prof["h"][m] - np.interp(y, ref["y"], ref["h"])


def steady_change(profs, band):
    """How steady the film is at the end: (largest |change of h| over the band between the
    last two output times / the band's mean h at the last, that time before, the last time),
    from ``profs`` = {t: profile}."""
    ts = sorted(profs)
    if len(ts) < 2:
        raise ValueError("steadiness needs two output times")
    last = profs[ts[-1]]
    _, dh = film_change(last, profs[ts[-2]], band)
    return float(np.abs(dh).max() / last["h"][in_band(last, band)].mean()), ts[-2], ts[-1]


def at_end(series):
    """The last row of a series ({column: array}) as {column: float}."""
    return {k: float(v[-1]) for k, v in series.items()}


def asperity_share(row):
    """Share of the rod's radial load that the asperities carry, from a series row (or any
    dict with load_asperity and load_fluid, N)."""
    return row["load_asperity"] / (row["load_asperity"] + row["load_fluid"])


def flow_film(q, v, area):
    """The film thickness (mm) that carries the flow q (mm^3/s) at rod speed v (mm/s): the
    Couette flow of a uniform film, q = area v h / 2, solved for h; ``area`` is A of Eq. 31
    (2 pi r_rod, mm). At the pressure peak of a steady smooth film this is h there."""
    return 2.0 * np.asarray(q) / (area * np.asarray(v))


def inlet_nodes(ip, y_w, v):
    """(i0, iw): indices in an IHL profile ``ip`` (y ascending, p_contact) of the first node
    in contact along the motion (sign of v) and of the node nearest its steepest rise y_w."""
    pc = ip["p_contact"]
    touch = np.nonzero(pc > 0.0)[0]
    if touch.size == 0:
        raise ValueError("no node in contact")
    i0 = int(touch[0] if v > 0 else touch[-1])
    return i0, int(np.argmin(np.abs(ip["y"] - y_w)))


def inlet_span(ip, y_w, v):
    """Number of rod-side elements from the last node out of contact on the inlet side to
    the node nearest the steepest rise y_w (see :func:`inlet_nodes`): how many elements
    resolve the inlet, where the film forms."""
    i0, iw = inlet_nodes(ip, y_w, v)
    return int(np.sign(v)) * (iw - i0) + 1


def cumulative_volume(t, q):
    """The volume (mm^3) a flow q(t) carries from t[0] to each t, by the trapezoidal rule."""
    t, q = np.asarray(t, float), np.asarray(q, float)
    return np.concatenate([[0.0], np.cumsum(0.5 * (q[1:] + q[:-1]) * np.diff(t))])
