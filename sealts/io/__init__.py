"""Output: CSV (pandas), JSON summary, PNG plots; HDF5/XDMF fields come with the solid."""
from .writer import Writer

__all__ = ["Writer"]
