"""One send workflow: what ``tapegate send`` and every port of the gateway do to drip-feed a
program, written once.

1. :func:`prepare` (before the port is opened): convert to the profile's format on the way
   (optional, into a temporary file), **check** (errors refuse the send unless forced), find the
   restart block and its modal preamble (``--restart-at``, a request's ``/BL``), then frame and
   measure the program: the bytes of a pass, its SHA-256 for the journal, every character proven
   encodable. A message program (the gateway's "not found" answer) is prepared from its lines.
2. :func:`run` (on an open port): the passes. Each is one paced, flow-controlled drip-feed
   (:func:`dnc.session.send_frames`); a reset and rewind at the control (DC3 SYN) ends the pass
   and the program is sent again from its ``%`` on the next DC1; with ``repeat`` every finished
   pass is followed by another on the next DC1. Every end of a pass is journalled: ``ok``,
   ``rewound``, ``failed``, ``aborted`` or ``interrupted``.

The workflow does no output of its own: it reports what happens as small events
(:class:`Converted`, :class:`CheckWarnings`, :class:`CheckErrors`, :class:`RestartFound`,
:class:`Waiting`, :class:`Progress`, :class:`Rewinding`, :class:`PassDone`) to one callback,
which the CLI turns into messages and a progress bar and the gateway into its port status and
log. The port, the journal and the clock are passed in; what can be pure is: :func:`pass_flow`
(how a pass waits and paces), :func:`transfer` (the journal record), :func:`summary` (the
closing line).
"""

from __future__ import annotations

import contextlib
import os
import signal
import threading
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field
from types import FrameType, TracebackType
from typing import Any

from dnc.framing import Framer, FrameStats
from dnc.journal import Transfer, now_utc
from dnc.link import Aborted, LinkError, Port, Rewound, chars_per_second, flow_settings
from dnc.program import Restart, check, converted_copy, find_restart, program_lines
from dnc.sender import FlowSettings
from dnc.session import SendProgress, send_frames
from formats.convert import ConvertStats
from formats.errors import TapeError, TapegateError
from formats.profile import Profile, SerialSettings
from formats.tape import TapeDecoder, detect, is_tape_image
from postproc.check import Finding

# ---------------------------------------------------------------------------------------------
# Events: what the caller shows


@dataclass(frozen=True)
class Converted:
    """The program was converted to the format of the profile named ``profile``."""
    stats: ConvertStats
    profile: str


@dataclass(frozen=True)
class CheckErrors:
    """The check found errors; ``forced``: it is sent anyway."""
    findings: list[Finding]
    forced: bool


@dataclass(frozen=True)
class CheckWarnings:
    """Warnings of how the control may read the program otherwise than tapegate did
    (dnc.program.SHOWN), said before anything is sent; they do not stop the send."""
    findings: list[Finding]


@dataclass(frozen=True)
class RestartFound:
    restart: Restart


@dataclass(frozen=True)
class Waiting:
    """A pass is about to start: waiting for the control's DC1. ``again``: after a finished
    or rewound pass."""
    number: int
    again: bool


@dataclass(frozen=True)
class Progress:
    """Bytes and line of the pass under way, several times a second and at every pause."""
    progress: SendProgress


@dataclass(frozen=True)
class Rewinding:
    """The control was reset and rewound: the pass is over (journalled ``rewound``) and the
    program goes again from ``%`` on the next DC1."""
    message: str
    progress: SendProgress


@dataclass(frozen=True)
class PassDone:
    number: int
    progress: SendProgress


Event = (Converted | CheckWarnings | CheckErrors | RestartFound | Waiting | Progress | Rewinding
         | PassDone)
OnEvent = Callable[[Event], None]
Record = Callable[[Transfer], None]


def _ignore(event: Event) -> None:
    pass


# ---------------------------------------------------------------------------------------------
# Preparing


class Refused(TapegateError):
    """The check found errors: the program is not sent."""

    default_code = "check-refused"

    def __init__(self, findings: list[Finding]):
        super().__init__(f"the check found {len(findings)} error(s)")
        self.findings = findings


@dataclass
class Program:
    """A program ready to send: framed, measured, every character proven encodable.

    Use it as a context manager (or call :meth:`close`): a converted copy is a temporary file.
    """
    name: str  # as messages and the journal name it
    settings: SerialSettings
    source: Callable[[], Iterator[tuple[int, str]]]  # the numbered lines as sent, each pass anew
    total: int  # bytes of a pass: leader, program, trailer
    through_end: int  # leader and program up to the closing "%": a pass's 100 %
    digest: str  # SHA-256 of the program as framed, leader and trailer excluded
    frame: FrameStats = field(default_factory=FrameStats)
    restart: Restart | None = None
    temporary: str | None = None

    def close(self) -> None:
        if self.temporary:
            with contextlib.suppress(FileNotFoundError):
                os.unlink(self.temporary)
            self.temporary = None

    def __enter__(self) -> Program:
        return self

    def __exit__(self, kind: type[BaseException] | None, value: BaseException | None,
                 tb: TracebackType | None) -> None:
        self.close()


def prepare(path: str, profile: Profile, settings: SerialSettings, *, name: str,
            check_first: bool = True, force: bool = False, restart_at: str | None = None,
            convert: bool = False, source: Profile | None = None,
            on_event: OnEvent = _ignore) -> Program:
    """Everything before the port is opened, for the program file ``path`` (``name`` in
    messages): convert (``convert``, from ``source`` or the detected format), check (errors:
    :class:`Refused` unless ``force``), find the restart block, frame and measure. A character
    the tape code cannot carry, or a restart block that is not there, is a located
    :class:`TapegateError`."""
    # a restart sends the lines from its block on: the warnings of lines before it, which are
    # not sent, are held until the block is found and said only for the lines that are
    held: list[CheckWarnings] = []

    def checking(event: Event) -> None:
        if restart_at and isinstance(event, CheckWarnings):
            held.append(event)
        else:
            on_event(event)

    try:
        path, temporary = checked(path, profile, name=name, check_first=check_first,
                                  force=force, convert=convert, source=source,
                                  on_event=checking)
    except BaseException:
        for event in held:  # refused: every warning, as without a restart
            on_event(event)
        raise
    try:
        restart = None
        if restart_at:
            try:
                restart = find_restart(path, profile, restart_at, name)
            except BaseException:
                for event in held:  # refused: every warning, as without a restart
                    on_event(event)
                raise
            on_event(RestartFound(restart))
            sent = [f for event in held for f in event.findings if f.line >= restart.line]
            if sent:
                on_event(CheckWarnings(sent))
        program = measure(name, settings, lambda: program_lines(path, restart))
    except BaseException:
        if temporary:
            os.unlink(temporary)
        raise
    program.restart, program.temporary = restart, temporary
    return program


def checked(path: str, profile: Profile, *, name: str, check_first: bool = True,
            force: bool = False, convert: bool = False, source: Profile | None = None,
            on_event: OnEvent = _ignore) -> tuple[str, str | None]:
    """The first steps of :func:`prepare`, for a transfer that sends the file as it is (the
    gateway's FTP machines): convert (``convert``, into a temporary file), then check (errors:
    :class:`Refused` unless ``force``). Returns the path to send and the temporary file the
    caller removes (``None`` without a conversion). The warnings of :class:`CheckWarnings` come
    first, as events; they do not refuse."""
    temporary = None
    if convert:
        temporary, stats = converted_copy(path, profile, source)
        path = temporary
        on_event(Converted(stats, profile.name))
    try:
        _cr_only(path, name)
        if check_first:
            errors, warnings = check(path, profile, name)
            if warnings:
                on_event(CheckWarnings(warnings))
            if errors:
                on_event(CheckErrors(errors, force))
                if not force:
                    raise Refused(errors)
    except BaseException:
        if temporary:
            os.unlink(temporary)
        raise
    return path, temporary


def _cr_only(path: str, name: str) -> None:
    """Refuse a file whose lines end in CR alone (docs/dnc.md): the check splits blocks at LF,
    so it read the whole file as one block (and said only "no M02 or M30"), while a sender
    could only drop every CR, joining the program into one block, or end a block at each. An
    ISO tape image is read as it is decoded (its CR is 0x8D, with the parity bit), so the
    same holds of its text."""
    with open(path, "rb") as f:
        head = f.read(1 << 16)
    what = "file"
    if is_tape_image(head):
        code = detect(head)
        text = TapeDecoder("eia" if code == "eia" else "iso").feed(head)
        head, what = text.encode("latin-1", "replace"), f"{code.upper()} tape image"
    if b"\r" in head and b"\n" not in head.rstrip(b"\r"):
        end = ("CR alone (CR-only line ends)" if what == "file" else
               "CR alone (0x8D, CR with its parity bit, and no LF: CR-only line ends)")
        raise TapeError(
            f"the {what}'s lines end in {end}: the check reads such a file as one block, and a "
            "sender can only drop the CRs, joining the program into one block, or end a block "
            "at each, not the program checked; write it with LF or CR-LF line ends",
            file=name, line=1, column=head.index(b"\r") + 1, clause="4",
            code="tape-character")


def prepare_lines(lines: Sequence[str], settings: SerialSettings, *, name: str) -> Program:
    """A program made of ``lines`` (a message program), framed and measured."""
    kept = list(lines)
    return measure(name, settings, lambda: iter(list(enumerate(kept, 1))))


def measure(name: str, settings: SerialSettings,
            source: Callable[[], Iterator[tuple[int, str]]]) -> Program:
    framer = Framer(settings, file=name)
    total, digest = framer.measure(source())
    return Program(name, settings, source, total, total - len(framer.trailer()), digest,
                   framer.stats)


# ---------------------------------------------------------------------------------------------
# Sending


@dataclass(frozen=True)
class Passes:
    """How the passes wait and repeat."""
    repeat: bool = False  # another pass on the next DC1 after each (production)
    passes: int | None = None  # with repeat: stop after this many
    wait_for_dc1: bool | None = None  # the first pass (None: the profile's wait_for_dc1)
    xon_timeout: float | None = None  # None: the profile's
    start_timeout: float | None = None  # for the first DC1 of a pass (None: xon_timeout)


@dataclass(frozen=True)
class Outcome:
    result: str  # ok | aborted | interrupted
    passes: int  # passes completed
    progress: SendProgress  # of the last pass


def pass_flow(settings: SerialSettings, passes: Passes, again: bool) -> FlowSettings:
    """How a pass waits and paces. After a finished or rewound pass the control must ask again
    (DC1); with ``repeat`` it may take as long as the operator likes."""
    if not again:
        return flow_settings(settings, wait_for_dc1=passes.wait_for_dc1,
                             xon_timeout=passes.xon_timeout,
                             start_timeout=passes.start_timeout)
    return flow_settings(settings, wait_for_dc1=True,
                         xon_timeout=float("inf") if passes.repeat else passes.xon_timeout,
                         start_timeout=passes.start_timeout)


def transfer(port: str, program: Program, progress: SendProgress | None, started: str,
             result: str, errors: list[str] | None = None) -> Transfer:
    """The journal record of a pass (or of a send that never started: ``progress`` None)."""
    sent, lines = (progress.sent, progress.lines) if progress else (0, 0)
    return Transfer(port, "send", program.name, sent, lines, started, now_utc(), result,
                    errors or [], program.digest)


def run(port: Port, program: Program, passes: Passes = Passes(), *, port_name: str,
        record: Record | None = None, on_event: OnEvent = _ignore,
        stop: Callable[[], str | None] | None = None) -> Outcome:
    """Send ``program`` on ``port``, pass after pass, journalling each end with ``record``.

    ``stop`` is asked several times a second: a word (``"aborted"``, ``"interrupted"``) ends
    the pass under way, journalled with that word, and is the outcome's result. A link that
    fails is journalled ``failed`` and its :class:`LinkError` raised.
    """
    latest = SendProgress(total=program.total)
    started = now_utc()

    def journal(result: str, errors: list[str] | None = None) -> None:
        if record is not None:
            record(transfer(port_name, program, latest, started, result, errors))

    def update(p: SendProgress) -> None:
        nonlocal latest
        latest = p
        on_event(Progress(p))

    done = 0
    again = False
    while True:
        flow = pass_flow(program.settings, passes, again)
        on_event(Waiting(done + 1, again))
        framer = Framer(program.settings, file=program.name)
        latest = SendProgress(total=program.total)
        started = now_utc()
        try:
            latest = send_frames(port, framer.frames(program.source()), flow,
                                 leader=framer.leader(), trailer=framer.trailer(),
                                 total=program.total, progress=update,
                                 stop=None if stop is None else lambda: stop() is not None)
        except Rewound as exc:
            journal("rewound", [exc.message])
            on_event(Rewinding(exc.message, latest))
            again = True
            continue
        except Aborted:
            why = (stop() if stop is not None else None) or "aborted"
            journal(why, [f"{why} at line {latest.line}"])
            return Outcome(why, done, latest)
        except LinkError as exc:
            journal("failed", [exc.message])
            raise
        done += 1
        journal("ok")
        on_event(PassDone(done, latest))
        if not passes.repeat or (passes.passes is not None and done >= passes.passes):
            return Outcome("ok", done, latest)
        again = True


def summary(p: SendProgress, settings: SerialSettings) -> str:
    """The closing line of a pass: what was sent, how fast, and how the control held it.

    The rate is taken over the time spent sending (not waiting for the first DC1, not paused by
    DC3). The link takes the last few bytes before the wire has carried them, so over a short
    pass bytes divided by seconds can come out above what the line carries; the wire cannot go
    faster, so the time is never taken as shorter than the line needs for those bytes.
    """
    cps = chars_per_second(settings)
    held = max(0.0, p.paused_time - p.waited)
    sending = max(p.elapsed - p.waited - held, p.sent / cps, 1e-9)
    rate = p.sent / sending
    share = rate / cps
    speed = ("the line's full rate" if share >= 0.995
             else f"{share:.0%} of the line's {cps:.0f} chars/s")
    parts = [f"sent {_count(p.sent, 'byte')} ({_count(p.lines, 'line')}) in {p.elapsed:.2f} s: "
             f"{rate:.0f} chars/s while sending, {speed}"]
    if p.waited >= 0.005:
        parts.append(f"waited {p.waited:.2f} s for the first DC1")
    parts.append(f"paused by the control {_count(p.pauses, 'time')} for {held:.2f} s"
                 if p.pauses else "never paused by the control")
    return "; ".join(parts)


def _count(n: int, noun: str) -> str:
    return f"{n} {noun}" if n == 1 else f"{n} {noun}s"


# ---------------------------------------------------------------------------------------------
# Signals: SIGINT and SIGTERM end a transfer cleanly


class StopSignals:
    """SIGINT and SIGTERM for a command that transfers a program, while the ``with`` block runs.

    During a transfer (:meth:`transferring`) a signal only sets a flag: the blocking loop asks
    for it (``stop``, several times a second), ends the pass, and the end is journalled. Outside
    one (checking, converting, opening the port) it raises :class:`KeyboardInterrupt` as usual.
    :attr:`number` is the signal received (exit ``128 + number``, as shells report it). Outside
    the main thread signals cannot be handled, and nothing is installed.
    """

    SIGNALS = (signal.SIGINT, signal.SIGTERM)

    def __init__(self) -> None:
        self.number: int | None = None
        self._armed = False
        self._previous: dict[int, Any] = {}

    def __enter__(self) -> StopSignals:
        if threading.current_thread() is threading.main_thread():
            for number in self.SIGNALS:
                self._previous[number] = signal.signal(number, self._handle)
        return self

    def __exit__(self, *exc: object) -> None:
        for number, previous in self._previous.items():
            signal.signal(number, previous)
        self._previous.clear()

    def _handle(self, number: int, frame: FrameType | None) -> None:
        self.number = number
        if not self._armed:
            raise KeyboardInterrupt

    @contextlib.contextmanager
    def transferring(self) -> Iterator[None]:
        self._armed = True
        try:
            yield
        finally:
            self._armed = False

    def __call__(self) -> str | None:
        """``"interrupted"`` once a signal has come, else ``None`` (a ``stop`` for :func:`run`)."""
        return "interrupted" if self.number is not None else None

    @property
    def name(self) -> str:
        return signal.Signals(self.number).name if self.number is not None else "SIGINT"

    @property
    def exit_code(self) -> int:
        return 128 + (self.number if self.number is not None else signal.SIGINT)
