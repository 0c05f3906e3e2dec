"""An emulated control served by a thread on a pseudo-terminal: for the demo, the tests and the
benchmarks (``tapegate emulate`` runs the same control in the foreground)."""

from __future__ import annotations

import contextlib
import os
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from dnc.control import Control
from dnc.link import LinkError
from dnc.sender import FlowSettings
from dnc.session import open_pty, punch, run_control


class RewindButton:
    """The emulated operator's RESET and rewind button: :meth:`press` from any thread, or once by
    itself after ``after`` blocks of the first program; the loop serving the control asks
    :meth:`pressed`. The press after ``after`` blocks is the control's own
    (:attr:`Control.rewind_after`), made at that block within the read that brought it: asked
    between reads, it came late where one read brought several blocks, and never where that
    read brought the program's end too (an emulator that read late on a busy host)."""

    def __init__(self, control: Control, after: int | None = None):
        self.control = control
        control.rewind_after = after
        self._pressed = threading.Event()

    def press(self) -> None:
        self._pressed.set()

    def pressed(self) -> bool:
        if self._pressed.is_set():
            self._pressed.clear()
            return True
        return False


@dataclass(frozen=True)
class DprntSchedule:
    """The control's macro printing machine data on its serial port (``POPEN``, ``DPRNT[...]``,
    ``PCLOS``) every ``every`` seconds: a cycle start, then a cycle end with the part count,
    then the next cycle's start... In the ``fanuc`` form each burst is DC2 (POPEN), the lines
    ended by LF, and DC4 (PCLOS); in the ``haas`` form (which ignores POPEN and PCLOS) the lines
    alone, ended by CR LF. ``cycles``: how many cycles to print (None: until stopped)."""
    every: float
    program: str = "O1234"
    form: str = "fanuc"
    cycles: int | None = None
    parts: int = 0  # the part count before the first cycle

    def lines(self, k: int) -> list[str]:
        """The lines of the ``k``-th burst (0-based): even ones start a cycle, odd ones end it."""
        if k % 2 == 0:
            return [f"(CYCLE START {self.program})"]
        return [f"(CYCLE END {self.program})", f"PARTS={self.parts + (k + 1) // 2}"]

    def burst(self, k: int) -> bytes:
        if self.form == "haas":
            return "".join(f"{line}\r\n" for line in self.lines(k)).encode("ascii")
        return b"\x12" + "".join(f"{line}\n" for line in self.lines(k)).encode("ascii") + b"\x14"

    @property
    def bursts(self) -> int | None:
        return None if self.cycles is None else 2 * self.cycles


def print_data(fd: int, schedule: DprntSchedule, stop: threading.Event,
               written: Callable[[int], None] = lambda k: None) -> int:
    """Write ``schedule``'s bursts on ``fd`` on time until it is done or ``stop`` is set;
    returns how many were written. A burst is one write: it never cuts a line the control is
    sending (the emulated control writes only DC1/DC3 meanwhile)."""
    k = 0
    start = time.monotonic()
    while schedule.bursts is None or k < schedule.bursts:
        if stop.wait(max(0.0, start + (k + 1) * schedule.every - time.monotonic())):
            break
        try:
            os.write(fd, schedule.burst(k))
        except OSError:
            break  # the port is gone
        k += 1
        written(k)
    return k


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
        self.printed = 0  # DPRNT bursts written
        self.printer: threading.Thread | None = None

    def print_data(self, schedule: DprntSchedule) -> None:
        """The control's macro starts printing machine data on ``schedule`` (a thread). What
        it prints before the host has opened its port is lost, as on a real line."""
        def written(k: int) -> None:
            self.printed = k

        self.printer = threading.Thread(target=print_data, args=(
            self.pty.master, schedule, self._stop, written), daemon=True)
        self.printer.start()

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
        if self.printer is not None:
            self.printer.join(5)
        self.pty.close()
        if self.link is not None:
            with contextlib.suppress(FileNotFoundError):
                os.unlink(self.link)
        return self.control
