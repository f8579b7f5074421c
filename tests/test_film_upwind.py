"""The fv scheme's upwinded Couette flow (sealts.film.reynolds_fv, "Upwinded Couette flow"):
its weight against the closed form, that it damps a gap alternating from node to node where
the central flux does not, and that it vanishes as L^3 under refinement of a smooth film."""
from decimal import Decimal, localcontext

import numpy as np
import pytest

from sealts.film.flow_factors import FlowFactors
from sealts.film.reynolds_fv import element_fluxes, upwind_weight

ETA = 1e-8            # MPa s
STIFF = np.pi * 8.5   # MPa: pi E' of the paper's O-ring, E' = 4 G, G = 2 C10 (C10 = 1.064)
FF = FlowFactors.none()


def fluxes(y, h, p, v, stiff):
    return element_fluxes(y, h, p, v, ETA, 1e-5, FF.model, FF.par, FF.table_h, FF.table_pp,
                          FF.table_ps, stiff)


@pytest.mark.parametrize("P", [1e-6, 0.05, 0.0999, 0.1001, 0.7, 3.0, 20.0, 59.9, 60.1, 1e4])
def test_weight_is_coth_minus_two_over_p(P):
    """xi(P) = coth(P/2) - 2/P and its derivative 2/P^2 - 1/(2 sinh^2(P/2)), evaluated in
    60-digit decimals, on each of the three branches (series, closed form, tail)."""
    with localcontext() as ctx:
        ctx.prec = 60
        x = Decimal(P)
        e = (x / 2).exp()
        ref = (e * e + 1) / (e * e - 1) - 2 / x
        dref = 2 / (x * x) - 2 / (e - 1 / e) ** 2
    xi, dxi = upwind_weight(P)
    assert xi == pytest.approx(float(ref), rel=1e-12, abs=1e-300)
    assert dxi == pytest.approx(float(dref), rel=1e-8, abs=1e-300)


@pytest.mark.parametrize("v", [300.0, -300.0])
def test_sawtooth_decays(v):
    """A thin contact film (0.2 um) alternating by +-0.05 um from node to node on 0.05 mm
    elements, uniform pressure: element Peclet numbers of about 400, xi(P) > 0.99. With the
    upwinded flow each thick node sends out 2 xi(P) times the Couette flow of the amplitude
    A, |v| A / 2, more than it takes in, and each thin node as much less (the nodal balance
    M dh/dt = -(q_out - q_in): the sawtooth decays); the central flux's net flows are below
    a thousandth of it."""
    n = 21
    y = np.linspace(0.0, 1.0, n)
    amp = 5e-5
    h = 2e-4 + amp * (-1.0) ** np.arange(n)
    p = np.full(n, 1.0)
    for stiff, low, high in ((STIFF, 1.95, 2.0), (0.0, -1e-3, 1e-3)):
        q = fluxes(y, h, p, v, stiff)[0]
        net = q[1:] - q[:-1]                     # out minus in, interior nodes, +y flows
        scale = abs(v) * amp / 2
        thick = (h[1:-1] > 2e-4)
        assert np.all(net[thick] / scale > low) and np.all(net[thick] / scale < high), stiff
        assert np.all(-net[~thick] / scale > low) and np.all(-net[~thick] / scale < high)


def test_uniform_gap_unchanged():
    """A uniform gap has no upwind share: the same flows with and without it."""
    y = np.linspace(0.0, 1.0, 11) ** 1.5
    h = np.full(11, 3e-4)
    p = np.linspace(2.0, 0.0, 11)
    assert np.array_equal(fluxes(y, h, p, 500.0, STIFF)[0], fluxes(y, h, p, 500.0, 0.0)[0])


def test_share_vanishes_as_l_cubed():
    """On a smooth film (1 to 1.5 um) the upwind share, the largest difference of the
    element flows from the central ones, falls by 2^3 per halving of the elements where
    P << 1 (here P ~ 0.6, 0.14, 0.035, 0.009 on 20 to 160 elements over 1 mm at 50 mm/s)."""
    diffs = []
    for n in (20, 40, 80, 160):
        y = np.linspace(0.0, 1.0, n + 1)
        h = 1e-3 * (1.0 + 0.5 * np.sin(3.0 * y))
        p = 1.0 - y
        d = fluxes(y, h, p, 50.0, STIFF)[0] - fluxes(y, h, p, 50.0, 0.0)[0]
        diffs.append(np.abs(d).max())
    rates = np.log2(np.array(diffs[:-1]) / np.array(diffs[1:]))
    assert rates[-1] == pytest.approx(3.0, abs=0.05), rates
    assert np.all(rates > 2.5), rates
