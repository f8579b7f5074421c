"""The film's gap floor from the surfaces' roughness (scene key ``film.h_floor``, default 0:
derived here).

Where the nominal separation h (paper Eq. 18) closes under asperity contact, the fluid still
passes through the valleys between the asperities. For two Gaussian surfaces of composite
roughness Rq whose mean planes touch, the mean gap (Patir and Cheng's average gap h_T at
h = 0, ASME J. Lubr. Technol. 100, 1978) is

    h_T(0) = Rq / sqrt(2 pi) = 0.40 Rq,

the scale below which the film's conductance cannot meaningfully fall. sealts uses it as the
floor of the regularised gap (:mod:`sealts.film.gap`), with the Rq of the asperity law, the
roughness that decides where the surfaces touch: ``asperity.summit_sigma`` for
Greenwood-Williamson, and for the exponential law of Eq. 44 the paper's ratio of its two
roughness parameters, Rq = h_mix (0.215 / 0.7) (Table 3: h_mix = 0.7 um, Rq = 0.215 um).
(``film.rq``, the flow factors' roughness, is not used: Phi_p already carries it, and a
floor from it would move with every flow-factor study.)

For the paper's O-ring the floor is 0.086 um. A floor far below the roughness (a fixed
0.01 um until this default) leaves the contact's hydraulic resistance flat over a zone the
film does not resolve; at a sealed pressure of 30 MPa the start of the stroke did not
converge with it (benchmarks/stress.md).
"""
import math

# the paper's Table 3: Rq per h_mix
RQ_PER_H_MIX = 2.15e-4 / 7e-4


def roughness(law, h_mix, summit_sigma):
    """Composite Rq (mm) of the asperity law (``asperity.law`` and its parameters)."""
    return summit_sigma if law == "greenwood-williamson" else h_mix * RQ_PER_H_MIX


def mean_gap_at_contact(rq):
    """Rq / sqrt(2 pi) (mm): the mean gap of Gaussian surfaces whose mean planes touch."""
    return rq / math.sqrt(2.0 * math.pi)
