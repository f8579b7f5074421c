"""Save the run state (``state.h5`` in the output directory) for a later scene's
``[start] state``: written after steps 1-2, so that a stroke that fails keeps it."""
from .base import Step


class Checkpoint(Step):
    name = None          # not a stage of the analysis

    def __init__(self, name="state.h5"):
        self.file = name

    def run(self, state):
        state.save(self.file)
