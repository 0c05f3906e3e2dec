"""The stops (^C, SIGTERM, SIGHUP) a command was asked for, kept so that none is lost.

A signal's handler raises its exception wherever the interpreter runs Python code next. Where
that is a finalizer (a ``__del__``, a weak reference's callback: an import's module lock freed,
a collection), the interpreter prints it as "Exception ignored" and goes on: the stop is lost.
A command that then read a FIFO whose writer never ends, or wrote into a pipe nobody reads,
waited for ever (the ^C of `check FIFO`, the SIGTERM of `convert -o -`: 1 CI run in some
hundreds). The handlers note each signal in :data:`TAKEN`, and :func:`heed_stops`, called
before each such wait, raises the stop again. Nothing is imported here: the ``tapegate``
command loads it at its start."""

from __future__ import annotations

# the stop signals the handlers took, in order
TAKEN: list[int] = []

_SIGINT = 2  # (signal.SIGINT, without importing signal)


def interrupted(signum: int, frame: object) -> None:
    """^C's handler: ``KeyboardInterrupt``, as the interpreter's, the signal noted."""
    TAKEN.append(signum)
    raise KeyboardInterrupt


def note_interrupts() -> None:
    """^C's handler, where it is still the interpreter's, made :func:`interrupted`; in the main
    thread only. Set by the ``tapegate`` command's entry point (``tapegate.launch.main``), at
    each command's start: the stops noted before are forgotten (review 53, F10: after one ^C,
    a caller's next command stopped at its first wait)."""
    import _signal

    TAKEN.clear()  # (a caller that goes on: a stop obeyed before is not this command's)
    try:
        if _signal.getsignal(_signal.SIGINT) is _signal.default_int_handler:
            _signal.signal(_signal.SIGINT, interrupted)
    except ValueError:  # not the main thread (of the main interpreter)
        pass


def heed_stops() -> None:
    """The stop a signal asked for, raised again (``KeyboardInterrupt`` for ^C, else an exit
    with 128 + its number) if one was taken: called before the command waits on something
    that may never come (the next bytes of a FIFO, room in a full pipe)."""
    if TAKEN:
        signum = TAKEN[-1]
        TAKEN.clear()  # (raised once: what handles it goes on without it)
        raise KeyboardInterrupt if signum == _SIGINT else SystemExit(128 + signum)
