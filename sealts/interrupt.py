"""SIGINT and SIGTERM end a run cleanly (``sealts run`` installs the handlers).

The handler only records the signal; it does not raise in whatever code happens to run, so a
residual callback called from inside PETSc is never torn in half and a TS never mistakes an
interrupt for a failed step it could retry. :func:`check` raises :class:`Interrupted` where
stopping is safe: after each accepted time step (the Problem's monitor, before any observer
writes) and after each steady or pseudo-time solve. The run then writes ``summary.json``
(status "interrupted", how far it got), and the Writer flushes and closes its files.

A second signal while the first is handled raises at once (a run that does not reach a
check in reasonable time can still be stopped).
"""
import signal

EXIT_CODES = {"SIGINT": 130, "SIGTERM": 143}     # 128 + the signal's number


class Interrupted(BaseException):
    """A run stopped by a signal (a BaseException, so ``except Exception`` passes it on)."""

    def __init__(self, name):
        super().__init__(f"interrupted by {name}")
        self.signal = name


_pending = []


def _handler(signum, frame):
    name = signal.Signals(signum).name
    if _pending:
        raise Interrupted(name)
    _pending.append(name)


def install():
    """Record SIGINT and SIGTERM from now on (main thread only)."""
    _pending.clear()
    for sig in (signal.SIGINT, signal.SIGTERM):
        signal.signal(sig, _handler)


def check(comm=None):
    """Raise :class:`Interrupted` if a signal came since :func:`install`; with a PETSc
    ``comm`` of several ranks, on every rank as soon as one has it (so all stop at the same
    step)."""
    name = _pending[0] if _pending else None
    if comm is not None and comm.getSize() > 1:
        names = [n for n in comm.tompi4py().allgather(name) if n]
        name = names[0] if names else None
    if name:
        raise Interrupted(name)
