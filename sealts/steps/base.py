"""The step interface: ``name`` and ``run(state)``, which advances a
:class:`sealts.steps.state.RunState` in place."""


class Step:
    name = "step"

    def run(self, state):
        raise NotImplementedError
