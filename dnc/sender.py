"""The drip-feed sender as a pure state machine (no I/O, no clock of its own).

Events in: :meth:`Sender.data_received` (bytes from the control: DC1, DC3, NAK...),
:meth:`Sender.time_passed`, :meth:`Sender.bytes_accepted` (how much of a write the link took).
Actions out: :class:`Write`, :class:`Pause`, :class:`Resume`, :class:`Done`, :class:`Fail`,
:class:`Rewind`.
:attr:`Sender.deadline` says when the caller must report the time again. The same machine runs
under the blocking ``send`` loop, the emulator's punch and the gateway.

**Pacing.** The sender keeps a model of the wire: each byte handed to the link occupies
``1 / cps`` seconds of it. It never lets the link get more than ``ahead`` bytes in front of the
wire, whatever the transport buffers (UART FIFO, USB adapter, pty, TCP). So when the control sends
DC3, at most ``ahead`` bytes are still on their way, plus at most one write that was under way, and
the control's overrun allowance (Fanuc: 10 characters, the 11th is alarm 087) is never reached.
``ahead`` is chosen from the baud rate (:func:`bytes_ahead`): 2 up to 38400 baud, so that a DC3
is obeyed within 3 characters, and more at higher rates where a Python loop cannot wake up once
per character.

**A DC3 seen late.** That bound holds if the DC3 reaches the sender as soon as it is on the line.
On a busy host it can take milliseconds: the kernel hands a tty's input over in a worker thread
that must be woken and given a core, and at 115200 baud the whole allowance is under a
millisecond of wire. With ``reaction`` (the longest the host may take to see a DC3) the sender
never sends faster than ``(allowance - ahead) / reaction`` characters per second, so what it
can send between a DC3 and its sight of it, plus what is ahead, stays within the allowance. At
low baud rates the wire is slower than that anyway and nothing changes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

DC1, DC2, DC3, DC4 = 0x11, 0x12, 0x13, 0x14
NAK, SYN = 0x15, 0x16
_LOW = 0x7F  # the control's bytes are read without their parity bit


@dataclass(frozen=True)
class Write:
    data: bytes


@dataclass(frozen=True)
class Pause:
    reason: str


@dataclass(frozen=True)
class Resume:
    pass


@dataclass(frozen=True)
class Done:
    pass


@dataclass(frozen=True)
class Fail:
    message: str


@dataclass(frozen=True)
class Rewind:
    """The control was reset and rewound (SYN after DC3): this pass is over, and the program is
    wanted again from its ``%`` on the control's next DC1."""


Action = Write | Pause | Resume | Done | Fail | Rewind


def bytes_ahead(cps: float, allowance: int) -> int:
    """How far in front of the wire the sender may be: about half a millisecond of wire time,
    at least 2 bytes, and never more than half the control's overrun allowance."""
    return max(2, min(allowance // 2, math.ceil(cps * 0.0005)))


def paced_cps(cps: float, allowance: int, ahead: int, reaction: float) -> float:
    """The most characters per second that keep a DC3 seen ``reaction`` seconds late within
    the allowance: ``ahead`` bytes may be on their way already, the rest of the allowance is
    what may be sent meanwhile. Never more than the wire carries (``cps``); no limit for a
    ``reaction`` of 0."""
    if reaction <= 0:
        return cps
    return min(cps, max(1, allowance - ahead) / reaction)


@dataclass(frozen=True)
class FlowSettings:
    cps: float  # wire characters per second
    flow: str = "xonxoff"  # xonxoff | rtscts | none
    obey_dc: bool = True  # tapegate reads DC1/DC3 (False: the driver does)
    wait_for_dc1: bool = True
    xon_timeout: float = 30.0
    start_timeout: float | None = None  # for the first DC1 (None: xon_timeout); a gateway
    # answering a remote request waits as long as the operator may take to press READ
    allowance: int = 10
    ahead: int | None = None  # None: bytes_ahead(cps, allowance)
    reaction: float = 0.0  # the longest the host may take to see a DC3 (see paced_cps)
    char_delay: float = 0.0
    line_delay: float = 0.0
    eob_last: int = 0x0A  # the byte that ends an end of block (for the line delay)


class Sender:
    """One pass of a program: wait for DC1, send, obey DC3/DC1, finish when the wire is idle.

    Program bytes are fed in with :meth:`feed` (the caller keeps :attr:`wants_data` satisfied)
    and :meth:`finish` says there are no more; memory stays bounded by what the caller feeds.
    """

    def __init__(self, flow: FlowSettings, now: float):
        self.flow = flow
        self.ahead = flow.ahead or bytes_ahead(flow.cps, flow.allowance)
        self.step = max(1, self.ahead // 2)  # write when this much room has opened
        self.delays = flow.flow == "none" and (flow.char_delay > 0 or flow.line_delay > 0)
        if self.delays:
            self.ahead = self.step = 1
        # the pace of the sender's model of the wire: the wire itself, or slower where a DC3
        # seen late could overrun the control (paced_cps); RTS/CTS and delays need no such pace
        reaction = flow.reaction if flow.flow == "xonxoff" else 0.0
        self.cps = paced_cps(flow.cps, flow.allowance, self.ahead, reaction)
        self.tick = 1.0 / self.cps
        self.pending = bytearray()
        self.pos = 0
        self.dropped = 0  # bytes removed from the front of pending
        self.program_end: int | None = None
        self.finished = False
        self.sent = 0  # bytes the link has taken
        self.handed = 0  # bytes of the last Write not yet confirmed by bytes_accepted
        self.wire_free_at = now
        self.paused_since: float | None = None
        self.in_flight_at_pause = 0.0
        obey = flow.flow == "xonxoff" and flow.obey_dc
        self.obey = obey
        self.state = "waiting" if obey and flow.wait_for_dc1 else "sending"
        if self.state == "waiting":
            self.paused_since = now
        self.pauses = 0  # DC3s obeyed
        self.paused_time = 0.0

    # -- data from the caller ------------------------------------------------------------------

    @property
    def wants_data(self) -> bool:
        return not self.finished and len(self.pending) - self.pos < 8192

    def feed(self, data: bytes) -> None:
        if self.pos > 65536:
            del self.pending[:self.pos]
            self.dropped += self.pos
            self.pos = 0
        self.pending += data

    def finish(self) -> None:
        self.finished = True

    def mark_end(self) -> None:
        """Everything fed so far is the program; what follows is trailer. A DC3 once the
        program is out is the control's "end of reading": the pass is done, trailer or not."""
        self.program_end = self.dropped + len(self.pending)

    # -- events --------------------------------------------------------------------------------

    def data_received(self, data: bytes, now: float) -> list[Action]:
        """Bytes from the control. Only the DC codes and NAK/SYN mean anything while sending;
        a repeated DC1 is harmless."""
        actions: list[Action] = []
        if not self.obey:
            return actions
        for byte in data:
            code = byte & _LOW
            if code == DC3 and self.state == "sending":
                if self.program_end is not None and self.sent >= self.program_end:
                    self.state = "done"
                    return [Done()]
                self.state = "paused"
                self.paused_since = now
                self.in_flight_at_pause = self._in_flight(now)
                self.pauses += 1
                actions.append(Pause("DC3 from the control"))
            elif code == DC1 and self.state in ("waiting", "paused"):
                if self.paused_since is not None:
                    self.paused_time += now - self.paused_since
                self.paused_since = None
                # bytes the driver was holding (tcflow) go out first
                self.wire_free_at = now + self.in_flight_at_pause * self.tick
                self.in_flight_at_pause = 0.0
                self.state = "sending"
                actions.append(Resume())
            elif code == SYN and self.state not in ("done", "failed", "rewound"):
                self.state = "rewound"
                return [Rewind()]
            elif code == NAK and self.state not in ("done", "failed", "rewound"):
                self.state = "failed"
                actions.append(Fail("the control reported an alarm (NAK)"))
        return actions + self.time_passed(now)

    def time_passed(self, now: float, queued: int | None = None) -> list[Action]:
        """The clock moved on; ``queued`` is the driver's output queue where it is known."""
        state = self.state
        if state in ("waiting", "paused"):
            assert self.paused_since is not None
            limit = self._timeout
            if now - self.paused_since >= limit:
                self.state = "failed"
                what = "to start" if state == "waiting" else "to resume after DC3"
                return [Fail(f"the control sent no DC1 {what} within {limit:g} s")]
            return []
        if state != "sending":
            return []
        available = len(self.pending) - self.pos
        if available == 0:
            if self.finished and now >= self.wire_free_at:
                self.state = "done"
                return [Done()]
            return []
        in_flight = self._in_flight(now)
        if queued is not None and queued > in_flight:
            in_flight = float(queued)
        room = self.ahead - in_flight
        if room < self.step and not (room >= 1 and available < self.step):
            return []
        n = min(int(room), available)
        data = bytes(self.pending[self.pos:self.pos + n])
        self.pos += n
        self.handed = n
        start = max(now, self.wire_free_at)
        busy = n * self.tick
        if self.delays:
            busy += self.flow.char_delay
            if data[-1] == self.flow.eob_last:
                busy += self.flow.line_delay
        self.wire_free_at = start + busy
        return [Write(data)]

    def bytes_accepted(self, n: int, now: float) -> list[Action]:
        """The link took ``n`` bytes of the last :class:`Write`; the rest is sent again."""
        short = self.handed - n
        if short > 0:
            self.pos -= short
            self.wire_free_at -= short * self.tick
        self.sent += n
        self.handed = 0
        return []

    # -- for the loop --------------------------------------------------------------------------

    @property
    def deadline(self) -> float | None:
        """When to report the time next (``None``: only when the control sends something)."""
        if self.state in ("waiting", "paused"):
            assert self.paused_since is not None
            return self.paused_since + self._timeout
        if self.state != "sending":
            return None
        available = len(self.pending) - self.pos
        if available == 0:
            return self.wire_free_at if self.finished else None
        # the moment the wire has drained enough to take the next write
        return self.wire_free_at - (self.ahead - min(self.step, available)) * self.tick

    @property
    def paused(self) -> bool:
        return self.state in ("waiting", "paused")

    @property
    def _timeout(self) -> float:
        start = self.flow.start_timeout
        return start if self.state == "waiting" and start is not None else self.flow.xon_timeout

    def _in_flight(self, now: float) -> float:
        return max(0.0, (self.wire_free_at - now) * self.cps)
