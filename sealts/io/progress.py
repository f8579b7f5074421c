"""Progress lines on rank 0, throttled to one a second unless forced."""
import time


class Progress:
    def __init__(self, comm, enabled=True, every=1.0):
        self.on = enabled and comm.getRank() == 0
        self.every, self.last = every, -1e9

    def due(self):
        """Whether a line that is not forced would be printed now."""
        return self.on and time.perf_counter() - self.last >= self.every

    def __call__(self, line, force=False):
        if self.on and (force or self.due()):
            print(line, flush=True)
            self.last = time.perf_counter()
