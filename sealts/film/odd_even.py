"""The film gap's odd-even (node-to-node) mode over the contact: the sign of a contact mesh
too coarse for the film over a soft contact law.

Near the contact the film's balance (Eq. 13, :mod:`sealts.film.reynolds_fv`) carries the
gap like a concentration. With the seal's surface answering the pressure with a local
stiffness S = dp/dh (the asperity law's dp_s/dh plus the seal's own, pi E' / (2 L) for a
half-space at the mesh's shortest wavelength 2 L),

    dh/dt + d/dy (v h / 2 - k S dh/dy) = 0,   k = Phi_p h^3 / (12 eta),

advection at v/2 against a diffusivity k S. Where the element's Peclet number
Pe = |v| L / (2 k S) exceeds 2, a central scheme no longer damps a gap that alternates
from node to node, and an element's flux, whose averages of 1/k and c/k weigh a linear gap
symmetrically, hardly sees one: the film and the contact settle into a sawtooth, the
minimum gap jumps between steps and TS crawls. The paper's law (Eq. 44) keeps S large
wherever the film is thin; Greenwood and Williamson's summits with the rubber's modulus do
not, nor does Eq. 44 with an h_mix far below the film (a smooth rod), so the film rides
on the seal's own stiffness, which grows as the mesh is refined (Pe ~ L^2): a fine enough
contact mesh resolves it (the meshes measured: README, "The film's node-to-node
mode"). The fv scheme's upwinded Couette flow (:mod:`sealts.film.reynolds_fv`, on by
default: ``film.upwind``) damps the mode where Pe is large; this indicator watches for it
where that is off, and with the paper's scheme.

The indicator, over the contact zone (the nodes from the first to the last whose h lies
below the law's contact gap), on the regularised gap g = h_eff (:mod:`sealts.film.gap`, so
the floor's flat zone under deep asperity contact counts as flat):

    d_i = g_i - [(1 - w_i) g_(i-1) + w_i g_(i+1)],   w_i = (y_i - y_(i-1)) / (y_(i+1) - y_(i-1)),
    z_i = |d_i| / 2  where d_(i-1) and d_(i+1) both have the other sign as d_i, else 0,
    I   = max_j  sum_(i in W_j) z_i / sum_(i in W_j) g_i,

W_j the windows of WINDOW consecutive nodes. d is the deviation from the straight line
through the two neighbours (:func:`neighbour_deviation`, which the paper report's
:func:`sealts.io.metrics.ripple` also takes), so a sawtooth of amplitude A gives z = A: over
the whole contact I = A / g, and one confined to a few nodes (as before the outlet's
constriction) reads against the gap there. Computed once per accepted step.
"""
import numpy as np

# the indicator from which the stroke warns, and from which a stall within the last
# ODD_EVEN_STEPS accepted steps names the mode in its message: a sawtooth is of the order of the
# mean gap, a resolved film far below (the values measured: README, "The film's
# node-to-node mode")
ODD_EVEN_WARN = 0.3
ODD_EVEN_STEPS = 200
# fewer contact nodes than this: no indicator; nodes per window
MIN_NODES = 5
WINDOW = 8


def neighbour_deviation(y, h):
    """d_i = h_i minus the straight line through its two neighbours, at the interior nodes
    of ``y`` (increasing; the midpoint's weight where two neighbours share a y)."""
    span = y[2:] - y[:-2]
    w = np.divide(y[1:-1] - y[:-2], span, out=np.full(span.size, 0.5), where=span > 0.0)
    return h[1:-1] - ((1.0 - w) * h[:-2] + w * h[2:])


def odd_even(y, h, h_floor, contact_gap):
    """The odd-even indicator I (module docstring) of the gaps ``h`` (mm) at the positions
    ``y`` (mm, increasing); 0 where fewer than MIN_NODES nodes lie below ``contact_gap``
    (mm)."""
    # numba's kernel, imported here: sealts.io.metrics takes neighbour_deviation from this
    # module, and the results reader loads no solver (tests/test_results.py)
    from .quantities import effective_gap
    y, h = np.asarray(y, float), np.asarray(h, float)
    zone = np.flatnonzero(h < contact_gap)
    if zone.size < MIN_NODES:
        return 0.0
    k = slice(zone[0], zone[-1] + 1)
    y, g = y[k], effective_gap(np.ascontiguousarray(h[k]), h_floor)
    d = neighbour_deviation(y, g)
    s = np.sign(d)
    turns = np.zeros(d.size, bool)
    turns[1:-1] = (s[1:-1] != s[:-2]) & (s[1:-1] != s[2:])
    z = np.where(turns, 0.5 * np.abs(d), 0.0)
    n = min(WINDOW, z.size)
    box = np.ones(n)
    gap = np.convolve(np.abs(g[1:-1]), box, "valid")
    return float(np.max(np.convolve(z, box, "valid") / np.where(gap > 0.0, gap, np.inf)))


def odd_even_note(value, t, h_contact):
    """One sentence naming the mode and the cure, for a warning or a stop's message."""
    return (f"the film's gap alternates from node to node over the contact at t = {t:.6g} s "
            f"(odd-even amplitude {value:.2g} of the local mean gap): the contact mesh "
            f"(mesh.h_contact = {h_contact:g} mm) is too coarse for the film over this "
            f"contact law, whose surface stiffness cannot damp it with the central flux: the "
            f"fv scheme's film.upwind = true damps it, a finer mesh.h_contact resolves it "
            f"(README, \"The film's node-to-node mode\")")
