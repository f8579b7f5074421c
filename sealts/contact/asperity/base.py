"""The interface of an asperity contact law: the solid contact pressure p_s(h) of the rough
surfaces at a mean separation h (mm), paper Eq. 44-45 and beyond.

A law supplies

* ``pressure(h)``: (p_s, dp_s/dh) for an array of separations (MPa, MPa/mm), C1 in h and
  evaluated by a numba kernel;
* ``contact_gap``: the separation (mm) below which p_s > 0, so that the contact zone is
  ``touching(h)``, h < contact_gap (asked of the law, never read from a parameter).
"""
import numpy as np


class AsperityLaw:
    name = "law"
    contact_gap = 0.0

    def pressure(self, h):
        raise NotImplementedError

    def touching(self, h):
        """Where the asperities carry load."""
        return np.asarray(h) < self.contact_gap
