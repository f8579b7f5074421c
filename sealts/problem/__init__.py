"""The PETSc problem: one DAE F(t, U, U') = 0 summed from pluggable physics terms."""
from .problem import Constraints, Problem, SolveError, Term, of_time

__all__ = ["Constraints", "Problem", "SolveError", "Term", "of_time"]
