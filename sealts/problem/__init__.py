"""The PETSc problem: one DAE F(t, U, U') = 0 summed from pluggable physics terms."""
from .problem import Problem, SolveError, Term

__all__ = ["Problem", "SolveError", "Term"]
