"""The pseudo-time protocol of the quasi-static steps 1-2, named once.

Mounting and pressurisation have no time of their own; they run along a pseudo-time t:

* mount: the groove bottom (and a rod smaller than the seal) move to their final radii
  over t in [0, 1] (``SealModel.rod_radius``, ``groove_radius``), then hold until ``t_hold``
  (``mount.t_hold``) so that the viscous stabilisation dies out;
* pressurise: p_in ramps over [t_hold, t_hold + 1] and holds until 2 t_hold;
* a state restarted from ``state.h5`` continues from the end of what it saved.

For t >= 1 the walls are final, so any later quasi-static solve (the front settling, the
hold's long-term check) runs on a window [t, t + 1] after that.
"""
from dataclasses import dataclass

from ..problem.seal_model import WALLS_FINAL


@dataclass(frozen=True)
class PseudoTime:
    t_hold: float = 2.0            # end of the mount (mount.t_hold)
    walls_final: float = WALLS_FINAL  # rod and groove at their final radii from here on

    @property
    def mount(self):
        """(start, end of the moving walls, end) of the mount."""
        return 0.0, self.walls_final, self.t_hold

    @property
    def pressurise(self):
        """(start, end of the pressure ramp, end) of the pressurisation."""
        return self.t_hold, self.t_hold + 1.0, 2.0 * self.t_hold

    def end(self, pressurised):
        """Where a state of steps 1-2 stands (a restart continues from here)."""
        return self.pressurise[2] if pressurised else self.mount[2]

    @staticmethod
    def window(t):
        """A further quasi-static window from t >= walls_final: (start, stop, end)."""
        return t, t + 0.5, t + 1.0
