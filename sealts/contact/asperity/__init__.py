"""Asperity contact laws by the scene's ``asperity.law`` (docs/design.md: a new law is one
file here and one entry in ``LAWS``)."""
from .base import AsperityLaw
from .exponential import ExponentialLaw
from .greenwood_williamson import GreenwoodWilliamson

LAWS = {"exponential": ExponentialLaw, "greenwood-williamson": GreenwoodWilliamson}


def law_from_scene(asperity, material=None):
    """The law of a scene's ``[asperity]`` section (``material``: the seal's, for a law
    that takes its modulus from it)."""
    return LAWS[asperity.law].from_scene(asperity, material)


__all__ = ["AsperityLaw", "ExponentialLaw", "GreenwoodWilliamson", "LAWS", "law_from_scene"]
