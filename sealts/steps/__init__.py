"""The steps of a procedure: mount, pressurise, hold, stroke, IHL, and the film-only
steps, each ``run(state)`` on the :class:`RunState` handed from one to the next
(:mod:`sealts.steps.procedure`)."""
from .base import Step
from .procedure import new_state, prepare, run_scene, run_steps, steps_1_2, steps_for
from .pseudo_time import PseudoTime
from .state import RunState

__all__ = ["PseudoTime", "RunState", "Step", "new_state", "prepare", "run_scene",
           "run_steps", "steps_1_2", "steps_for"]
