"""An emulated control served by a thread on a pseudo-terminal: for the demo, the tests and the
benchmarks (``tapegate emulate`` runs the same control in the foreground)."""

from __future__ import annotations

import threading

from dnc.control import Control
from dnc.session import open_pty, run_control


class Emulator:
    """An emulated control on a pseudo-terminal, served by a thread: for the demo, the tests and
    the benchmarks. ``path`` is the port to open; :meth:`stop` ends it and returns the control."""

    def __init__(self, control: Control):
        self.control = control
        self.pty = open_pty()
        self.path = self.pty.path
        self._stop = threading.Event()
        self.thread = threading.Thread(
            target=run_control, args=(self.pty.master, control),
            kwargs={"stop": self._stop.is_set}, daemon=True)
        self.thread.start()

    def wait(self, timeout: float) -> bool:
        self.thread.join(timeout)
        return not self.thread.is_alive()

    def stop(self) -> Control:
        self._stop.set()
        self.thread.join(5)
        self.pty.close()
        return self.control

    def vanish(self) -> None:
        """The port disappears (a cable pulled, a USB adapter unplugged)."""
        self.stop()
