"""An emulated control served by a thread on a pseudo-terminal: for the demo, the tests and the
benchmarks (``tapegate emulate`` runs the same control in the foreground)."""

from __future__ import annotations

import contextlib
import os
import threading
from pathlib import Path

from dnc.control import Control
from dnc.link import LinkError
from dnc.sender import FlowSettings
from dnc.session import open_pty, punch, run_control


class RewindButton:
    """The emulated operator's RESET and rewind button: :meth:`press` from any thread, or once by
    itself after ``after`` blocks of the first program; the loop serving the control asks
    :meth:`pressed`."""

    def __init__(self, control: Control, after: int | None = None):
        self.control = control
        self.after = after
        self._pressed = threading.Event()

    def press(self) -> None:
        self._pressed.set()

    def pressed(self) -> bool:
        stats = self.control.stats
        if self.after is not None and stats.programs == 0 and stats.blocks >= self.after:
            self.after = None
            return True
        if self._pressed.is_set():
            self._pressed.clear()
            return True
        return False


class Emulator:
    """An emulated control on a pseudo-terminal, served by a thread. ``path`` is the port to
    open (or ``link``, a symbolic link to it, as udev makes ``/dev/serial/by-id`` names);
    :meth:`stop` ends it and returns the control.

    With ``punch`` the operator first punches those bytes to the host (DC2 ... DC4, as a remote
    request is sent from the keypad) and then puts the control in READ mode. With
    ``rewind_after`` the operator resets and rewinds once, after that many blocks of the first
    program; :meth:`rewind` does it at any moment.
    """

    def __init__(self, control: Control, *, punch: bytes | None = None,
                 punch_flow: FlowSettings | None = None, link: Path | None = None,
                 rewind_after: int | None = None):
        self.control = control
        self.button = RewindButton(control, rewind_after)
        self.pty = open_pty()
        self.path = self.pty.path
        self.link = link
        if link is not None:
            with contextlib.suppress(FileNotFoundError):
                link.unlink()
            link.symlink_to(self.path)
        self.punched: int | None = None
        self.error: str | None = None
        self._stop = threading.Event()
        self.thread = threading.Thread(target=self._run, args=(punch, punch_flow), daemon=True)
        self.thread.start()

    def _run(self, data: bytes | None, flow: FlowSettings | None) -> None:
        fd = self.pty.master
        try:
            if data is not None:
                self.punched = punch(fd, data, flow or FlowSettings(cps=self.control.cps,
                                                                     wait_for_dc1=False),
                                     give_up=30.0, stop=self._stop.is_set)
            run_control(fd, self.control, stop=self._stop.is_set, rewind=self.button.pressed)
        except LinkError as exc:
            self.error = exc.message

    def rewind(self) -> None:
        """The operator presses RESET and rewinds: the control abandons the program it is
        reading and asks for it again from ``%`` (see :meth:`dnc.control.Control.rewind`)."""
        self.button.press()

    def wait(self, timeout: float) -> bool:
        self.thread.join(timeout)
        return not self.thread.is_alive()

    def stop(self) -> Control:
        self._stop.set()
        self.thread.join(5)
        self.pty.close()
        if self.link is not None:
            with contextlib.suppress(FileNotFoundError):
                os.unlink(self.link)
        return self.control
