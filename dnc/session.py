"""The blocking loops that run the DNC state machines on a real port.

Each loop does only I/O and timekeeping: it reports bytes and time to a state machine from
:mod:`dnc.sender`, :mod:`dnc.receiver` or :mod:`dnc.control` and carries out the actions it
gets back. Errors come out as :class:`dnc.link.LinkError` naming the block reached.
"""

from __future__ import annotations

import contextlib
import fcntl
import os
import re
import select
import sys
import termios
import time
import tty
from collections import deque
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from datetime import datetime
from pathlib import Path

from dnc.control import Control
from dnc.link import Aborted, FdPort, LinkError, Port, Rewound
from dnc.receiver import Receiver, ReceiverAction, Reply, Text
from dnc.sender import Done, Fail, FlowSettings, Pause, Resume, Rewind, Sender, Write
from formats.errors import OutputError
from formats.files import PendingFile
from formats.tape import TapeIssue

Clock = Callable[[], float]


# ---------------------------------------------------------------------------------------------
# Sending


@dataclass
class SendProgress:
    sent: int = 0  # bytes the link has taken
    total: int | None = None
    line: int = 0  # source line of the block being sent
    lines: int = 0  # lines completely sent (blocks and the "%" lines)
    paused: bool = False
    waiting: bool = False  # waiting for the first DC1
    started: float = 0.0
    elapsed: float = 0.0
    paused_time: float = 0.0  # waiting for the first DC1 included
    pauses: int = 0
    waited: float = 0.0  # waiting for the first DC1


def send_frames(port: Port, frames: Iterable[tuple[int, bytes]], flow: FlowSettings, *,
                leader: bytes = b"", trailer: bytes = b"", total: int | None = None,
                progress: Callable[[SendProgress], None] | None = None,
                clock: Clock = time.monotonic, every: float = 0.1,
                stop: Callable[[], bool] | None = None) -> SendProgress:
    """Drip-feed one pass: leader, the framed blocks, trailer. Returns the final progress.

    ``frames`` are ``(line, bytes)`` pairs (see :class:`dnc.framing.Framer`); they are pulled
    only as the sender needs them, so a program of any size is sent in flat memory. ``stop`` is
    asked several times a second; when it says so the pass ends with :class:`dnc.link.Aborted`.
    A reset and rewind at the control ends it with :class:`dnc.link.Rewound`.
    """
    now = clock()
    sender = Sender(flow, now)
    state = SendProgress(total=total, started=now, waiting=sender.paused)
    ends: deque[tuple[int, int]] = deque()  # (end offset, line) of blocks fed, not yet sent
    fed = 0
    source: Iterator[tuple[int, bytes]] = iter(frames)
    sender.feed(leader)
    fed += len(leader)
    tail = trailer
    next_report = now

    def feed() -> None:
        nonlocal fed, tail
        while sender.wants_data:
            item = next(source, None)
            if item is None:  # the last frame was the closing "%"
                sender.mark_end()
                if tail:
                    sender.feed(tail)
                    fed += len(tail)
                    tail = b""
                sender.finish()
                return
            line, data = item
            sender.feed(data)
            fed += len(data)
            ends.append((fed, line))

    def where() -> str:
        at = f"the block on line {state.line}" if state.line else "the start of the program"
        return f"{at}, {state.sent} bytes sent"

    def stopped(error: type[LinkError], message: str, code: str | None) -> LinkError:
        return error(f"{message}; stopped at {where()}", code=code,
                     stopped_at=(state.line, state.sent))

    feed()
    actions = sender.time_passed(now, port.queued())
    try:
        while True:
            spoke: bytes | None = None
            for action in actions:
                if isinstance(action, Write):
                    if sender.obey and port.wait(0):
                        # The control spoke since the write was decided (this thread may have
                        # waited for a core or the interpreter meanwhile): a DC3 goes first.
                        sender.bytes_accepted(0, clock())
                        spoke = port.read()
                        break
                    n = port.write(action.data)
                    sender.bytes_accepted(n, clock())
                    state.sent += n
                    while ends and ends[0][0] <= state.sent:
                        ends.popleft()
                        state.lines += 1
                    state.line = ends[0][1] if ends else state.line
                elif isinstance(action, Pause):
                    port.hold_output(True)
                    state.paused = True
                    if progress:  # the operator sees the control's hold at once
                        progress(state)
                elif isinstance(action, Resume):
                    port.hold_output(False)
                    if state.waiting:
                        state.waited = clock() - state.started
                    state.paused = state.waiting = False
                    if progress:
                        progress(state)
                elif isinstance(action, Fail):
                    raise stopped(LinkError, action.message, "link-flow")
                elif isinstance(action, Rewind):
                    port.discard_output()
                    raise Rewound(f"the control was reset and rewound at {where()}",
                                  stopped_at=(state.line, state.sent))
                elif isinstance(action, Done):
                    state.elapsed = clock() - state.started
                    state.paused_time, state.pauses = sender.paused_time, sender.pauses
                    if progress:
                        progress(state)
                    return state
            if spoke is not None:
                actions = sender.data_received(spoke, clock())
                continue
            feed()
            now = clock()
            if progress and now >= next_report:
                state.elapsed = now - state.started
                progress(state)
                next_report = now + every
            if stop is not None and stop():
                raise Aborted("aborted")
            deadline = sender.deadline
            timeout = None if deadline is None else max(0.0, deadline - now)
            if progress or stop is not None:
                timeout = every if timeout is None else min(timeout, every)
            if port.wait(timeout):  # a DC3 is read before anything more is written
                actions = sender.data_received(port.read(), clock())
            else:
                actions = sender.time_passed(clock(), port.queued())
    except LinkError as exc:
        if progress:  # the caller journals what was sent: the count as it stands now
            state.elapsed = clock() - state.started
            progress(state)
        if exc.stopped_at is not None:  # it says where already
            raise
        raise stopped(type(exc), exc.message, exc.code) from None


# ---------------------------------------------------------------------------------------------
# Receiving


@dataclass
class Received:
    path: Path | None
    reason: str
    code: str | None
    bytes: int
    chars: int
    issues: list[TapeIssue] = field(default_factory=list)


@dataclass
class Capture:
    """What :func:`capture` wrote: the first few kilobytes of text (to name the program and to
    recognise a remote request) and the number of characters."""
    head: str
    chars: int


def capture(port: Port, receiver: Receiver, pending: PendingFile, *, first: bytes = b"",
            stop: Callable[[], bool] | None = None, clock: Clock = time.monotonic) -> Capture:
    """Run ``receiver`` on ``port`` until the program has ended (or ``stop``), writing the
    decoded text to ``pending``. ``first`` is data already read from the port.

    A write that fails (a full disk) stops the writing, not the reading: the rest of the
    program is read and dropped, so that the control can finish its punch and the line is quiet
    again, and the error (an :class:`OSError`) is raised once the program has ended."""
    head: list[str] = []
    head_size = 0
    chars = 0
    failed: OSError | None = None

    def keep(data: bytes) -> None:
        nonlocal failed
        if failed is None:
            try:
                pending.write(data)
            except OSError as exc:
                failed = exc

    def act(actions: list[ReceiverAction]) -> None:
        nonlocal head_size, chars
        for action in actions:
            if isinstance(action, Reply):
                port.write(action.data)
            elif isinstance(action, Text):
                keep(action.text.encode("utf-8"))
                chars += len(action.text)
                if head_size < 4096:
                    head.append(action.text)
                    head_size += len(action.text)

    if first:
        act(receiver.data_received(first, clock()))
    while not receiver.done and not (stop is not None and stop()):
        deadline = receiver.deadline
        now = clock()
        timeout = 0.2 if deadline is None else max(0.0, min(0.2, deadline - now))
        if port.wait(timeout):
            act(receiver.data_received(port.read(), clock()))
        else:
            act(receiver.time_passed(clock()))
    if chars and receiver.reason == "closing %":
        keep(b"\n")
    if failed is not None:
        raise failed
    return Capture("".join(head), chars)


def receive_program(port: Port, receiver: Receiver, target: Path, *,
                    program_letter: str = "O", clock: Clock = time.monotonic,
                    stop: Callable[[], bool] | None = None) -> Received:
    """Capture one program into ``target`` (a folder: named from the program number; or a
    file). Written through a temporary file, never over an existing file. When ``stop`` (asked
    several times a second) says so before the program has ended, nothing is written and the
    reason is ``"interrupted"``."""
    folder = target if target.is_dir() else target.parent
    with _saving(folder), PendingFile(folder, "received", create=True) as pending:
        got = capture(port, receiver, pending, clock=clock, stop=stop)
        if not receiver.done and stop is not None and stop():
            pending.discard()
            return Received(None, "interrupted", receiver.code, receiver.bytes, got.chars,
                            receiver.issues)
        if not got.chars:
            pending.discard()
            return Received(None, receiver.reason or "no data", receiver.code, receiver.bytes,
                            0, receiver.issues)
        name = target if not target.is_dir() else target / program_name(got.head,
                                                                           program_letter)
        path = pending.commit(name, overwrite=False)
    return Received(path, receiver.reason, receiver.code, receiver.bytes, got.chars,
                    receiver.issues)


class SaveFailed(OutputError):
    """A received program could not be written (a full disk, no permission): it was read to its
    end and nothing of it is left in the folder."""

    default_code = "output-save"


@contextlib.contextmanager
def _saving(folder: Path) -> Iterator[None]:
    """An :class:`OSError` writing a received program as :class:`SaveFailed`; the temporary
    file is gone by then (:meth:`PendingFile.discard`, which the ``with`` inside runs)."""
    try:
        yield
    except OSError as exc:
        raise SaveFailed(f"cannot save the program in {folder}: {exc.strerror or exc}; "
                         "it was read to its end and nothing was kept", file=str(folder)
                         ) from None


_SAFE = re.compile(r"[^A-Za-z0-9_.-]+")


def program_number(head: str, letter: str = "O") -> str | None:
    """The program number near the start of a program (``O1234``; ``:1234`` is read as
    ``O1234``), or ``None``. A first line starting with ``%`` is the identification, not
    searched."""
    lines = head.split("\n")[:12]
    if lines and lines[0].lstrip().startswith("%"):
        lines = lines[1:]
    for text in lines:
        m = re.match(rf"\s*(?:N\d+\s*)?([{re.escape(letter or 'O')}:])\s*(\d+)", text)
        if m:
            prefix = "O" if m.group(1) == ":" else m.group(1)
            return f"{prefix}{m.group(2)}"
    return None


def program_name(head: str, letter: str = "O") -> str:
    """A file name for a received program: its program number (``O1234.nc``), else its
    identification after ``%``, else the time of receipt."""
    number = program_number(head, letter)
    if number:
        return f"{number}.nc"
    lines = head.split("\n")
    first = lines[0].lstrip("%").strip() if lines else ""
    ident = _SAFE.sub("_", first.strip("() ")).strip("._")[:60]
    if ident:
        return f"{ident}.nc"
    return datetime.now().strftime("received-%Y%m%d-%H%M%S.nc")


# ---------------------------------------------------------------------------------------------
# The emulated control


HOST_WAIT = 5.0  # seconds a pty is kept, at most, for a host still reading or writing


@dataclass
class Pty:
    """A pseudo-terminal pair: the emulator holds ``master``, the host opens ``path``.

    The emulator holds the host's end (``slave``) too: bytes written before the host opens it
    wait for the host, and the master never reads as hung up between two hosts. On Linux,
    closing the master hangs up the host's end and throws away what the host has not read yet
    (its next read is end of file), so before closing it the emulator waits: while it holds the
    host's end, until the host has read what was written (:meth:`wait_read`); once its part is
    done and it has let go of that end (:meth:`release`), until the host closes its port, which
    the master then reads as end of file (:func:`wait_hang_up`, :func:`run_control`).
    """
    master: int
    slave: int | None
    path: str

    def release(self) -> None:
        """Let go of the host's end, once the host holds its own handle on it: from now on the
        host closing its port is seen at the master."""
        if self.slave is not None:
            with contextlib.suppress(OSError):
                os.close(self.slave)
            self.slave = None

    def unread(self) -> bool:
        """Whether bytes written to the master wait, unread, at the host's end.

        Asked by ``select`` on the emulator's own handle on that end, which counts what the
        host has not read: the kernel's poll first takes in the bytes its worker thread has not
        handed over yet, where ``FIONREAD`` misses them (a third of one-byte writes, read back
        at once, on Linux 6.18). False once the host's end is released."""
        if self.slave is None:
            return False
        ready, _, _ = select.select([self.slave], [], [], 0)
        return bool(ready)

    def wait_read(self, timeout: float, *, stop: Callable[[], bool] = lambda: False,
                  clock: Clock = time.monotonic, every: float = 0.005) -> bool:
        """Wait until the host has read everything written to the master (looked at every
        ``every`` seconds: nothing wakes a writer when the reader takes bytes), at most
        ``timeout`` seconds or until ``stop``. True when it has."""
        end = clock() + timeout
        while self.unread():
            if stop() or clock() >= end:
                return False
            time.sleep(every)
        return True

    def close(self) -> None:
        self.release()
        with contextlib.suppress(OSError):
            os.close(self.master)


def open_pty() -> Pty:
    master, slave = os.openpty()
    tty.setraw(slave)  # no echo, no line editing, until the host sets its own modes
    return Pty(master, slave, os.ttyname(slave))


def wait_hang_up(fd: int, timeout: float, *, clock: Clock = time.monotonic) -> bool:
    """Wait until the host has closed its end of the pty whose master is ``fd`` (the emulator
    having released its own, :meth:`Pty.release`), at most ``timeout`` seconds; what the host
    still writes meanwhile is read and dropped. True when it has."""
    end = clock() + timeout
    while (left := end - clock()) > 0:
        ready, _, _ = select.select([fd], [], [], left)
        if ready:
            try:
                if not os.read(fd, 4096):
                    return True
            except OSError:  # EIO: no process holds the host's end any more
                return True
    return False


def run_control(fd: int, control: Control, *, stop: Callable[[], bool] = lambda: False,
                rewind: Callable[[], bool] = lambda: False, clock: Clock = time.monotonic,
                linger: float = 0.5, release: Callable[[], None] | None = None) -> None:
    """Serve the emulated control on ``fd`` until it has read its programs (or ``stop``).

    ``rewind`` is the operator's RESET and rewind button, asked as often as ``stop``: when it
    says so the control abandons the program it is reading and asks for it again from ``%``.
    After the last program it keeps reading, so that a host still sending its trailer does not
    find the port gone: for ``linger`` seconds, or, with ``release`` (the emulator's end of a
    pty about to be closed: :meth:`Pty.release`, called then), until the host closes its port,
    at most ``linger`` seconds.
    """
    def write(data: bytes) -> None:
        if data:
            # what is already waiting arrived before this write: a DC3 in it counts after that
            waiting = bytes_waiting(fd, clock)[0] if control.dc3_unsent else 0
            os.write(fd, data)
            control.sent(clock(), waiting)  # a DC3 counts from the moment it is on the line

    write(control.time_passed(clock()))
    end: float | None = None
    while not stop():
        now = clock()
        if rewind():
            end = None
            try:
                write(control.rewind(now))
            except OSError:
                return
        if control.done:
            if end is None and release is not None:
                release()  # the host holds the port: from now on its closing it ends the loop
            end = end or now + linger
            if now >= end:
                return
        deadline = control.deadline
        timeout = 0.05 if deadline is None else max(0.0, min(0.05, deadline - now))
        try:
            ready, _, _ = select.select([fd], [], [], timeout)
            if ready:
                waiting, at = bytes_waiting(fd, clock)
                data = os.read(fd, waiting or 4096)
                if not data:
                    return
                write(control.data_received(data, at if waiting else clock()))
            else:
                write(control.time_passed(clock()))
        except OSError:
            return  # the other side is gone


def bytes_waiting(fd: int, clock: Clock, *, within: float = 100e-6) -> tuple[int, float]:
    """How many bytes are waiting on ``fd``, and a moment when they all had arrived.

    The emulated control times what it reads by the moment of reading, so that moment must not
    be taken late: a thread or process that loses its core between reading and looking at the
    clock would date the bytes late, push every later arrival after them, and blame the host for
    characters "after DC3" it never sent. So the count (``FIONREAD``) is taken between two
    looks at the clock no more than ``within`` apart, tried again until it is, and only that many
    bytes are read. ``(0, now)`` where the count cannot be had."""
    for _ in range(100):
        before = clock()
        try:
            raw = fcntl.ioctl(fd, termios.FIONREAD, b"\0\0\0\0")
        except OSError:
            return 0, before
        after = clock()
        if after - before <= within:
            return int.from_bytes(raw, sys.byteorder), after
    return int.from_bytes(raw, sys.byteorder), after


def punch(fd: int, data: bytes, flow: FlowSettings, *, clock: Clock = time.monotonic,
          announce: float = 1.0, give_up: float = 60.0,
          stop: Callable[[], bool] | None = None) -> int:
    """The control punches ``data`` to the host: DC2 (repeated every ``announce`` seconds until
    the host answers DC1, for at most ``give_up`` seconds), the data paced at wire speed obeying
    the host's DC3/DC1 (the same sender as ``send``), then DC4. Returns the bytes sent."""
    start = clock()
    answered = False
    while not answered:
        if stop is not None and stop():
            raise Aborted("punch: stopped before the host answered")
        if clock() - start > give_up:
            raise LinkError(f"punch: the host did not answer DC2 within {give_up:g} s",
                            code="link-flow")
        os.write(fd, b"\x12")
        end = clock() + announce
        while clock() < end and not answered:
            ready, _, _ = select.select([fd], [], [], max(0.0, min(0.1, end - clock())))
            if ready:
                answered = any(b & 0x7F == 0x11 for b in os.read(fd, 4096))
    result = send_frames(FdPort(fd), [(0, data)], flow, clock=clock, stop=stop)
    os.write(fd, b"\x14")
    return result.sent
