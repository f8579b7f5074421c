"""The PETSc problem: one DAE F(t, U, U') = 0 summed from pluggable physics terms."""
from ..core import Constraints, Counters, Observer, SolveError, StepInfo, Term, of_time
from .problem import Problem

__all__ = ["Constraints", "Counters", "Observer", "Problem", "SolveError", "StepInfo", "Term",
           "of_time"]
