"""A legacy control's tape-reader interface, as a pure state machine: what the emulator is.

It behaves like a Fanuc-style control reading a drip-feed: DC1 to start (repeated until data
comes, as a control waiting at cycle start does), a buffer emptied at ``rate`` characters per
second by the "machining", DC3 when the free space falls to the overrun allowance and DC1 once
the buffer has drained to half, DC3 at the end of the program.

It watches what a real control would alarm on:

* **alarm 087**: more characters after a DC3 than the allowance;
* **TH check** (alarm 001): a character with the wrong parity or one the control does not accept
  — parity can only be seen in software-parity mode, since a pseudo-terminal has no UART. Which
  characters it accepts is the profile's one character table (``formats._core.character_allowed``,
  the table the checker reads by): any printable character inside a comment, and outside one
  Annex A, lower case where the dialect reads it and the profile's extra characters; without a
  dialect, a plain Fanuc's (no lower case, no ``" , ; ! @ $``);
* **TV check** (alarm 002): an odd number of characters in a block (end of block not counted).

Timing is modelled at the configured baud and frame, since a pseudo-terminal delivers a burst at
once: the bytes of each read are taken to have arrived back to back up to the moment of reading,
but never closer than one character time apart. A host that writes ahead of the wire therefore
sees its bytes "arrive" later, as they would on a real line, and they count after a DC3 sent
meanwhile. A DC3 counts from the moment it was written to the line (:meth:`Control.sent`), not
the moment the control decided on it, and the bytes already waiting to be read when it was
written count before it, so the emulator's own scheduling delays are not blamed on the host.
Line utilisation and the characters after DC3 come from that model, so they mean what they
would mean on a wire.
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass, field
from typing import BinaryIO

from formats import _core
from formats.parser import Dialect
from formats.tape import EIA_DECODE, EIA_EOB, EIA_ER, parity_bits

DC1, DC2, DC3, DC4 = b"\x11", b"\x12", b"\x93", b"\x14"  # ISO with even parity
SYN = b"\x96"  # after DC3: the control was reset (Fanuc remote buffer); the reading is abandoned
_TH_ILLEGAL = set('",;!@$')


@dataclass
class ControlError:
    kind: str  # "TH parity" | "TH illegal" | "TV" | "087"
    program: int
    line: int
    column: int
    detail: str

    def __str__(self) -> str:
        return f"program {self.program} line {self.line}:{self.column}: {self.kind}: {self.detail}"


@dataclass(frozen=True)
class Throttle:
    """One throttling DC3: when it was written to the line and how many characters arrived
    after it (modelled arrivals, as :attr:`ControlStats.after_dc3` counts them)."""

    at: float
    after: int


@dataclass
class ControlStats:
    chars: int = 0  # every byte received, leader included
    first: float | None = None  # modelled arrival of the first and last byte
    last: float = 0.0
    dc3: int = 0
    most_after_dc3: int = 0
    after_dc3: dict[int, int] = field(default_factory=dict)  # characters after a throttling
    # DC3 -> how many DC3s had that many (counted when the control resumes with DC1)
    throttles: list[Throttle] = field(default_factory=list)  # the same DC3s one by one
    alarms_087: int = 0
    blocks: int = 0
    programs: int = 0
    rewinds: int = 0  # programs abandoned by the operator's reset and rewind
    errors: list[ControlError] = field(default_factory=list)

    def utilisation(self, cps: float) -> float:
        """Characters received ÷ what the wire could carry from the first to the last."""
        if self.first is None or self.chars < 2:
            return 0.0
        span = self.last - self.first + 1.0 / cps
        return self.chars / (span * cps)

    def count(self, kind: str) -> int:
        return sum(e.kind.startswith(kind) for e in self.errors)


class Control:
    """Feed it what the host wrote (:meth:`data_received`) and the time (:meth:`time_passed`);
    both return the bytes the control sends back. Programs read go to ``sink`` (the bytes as
    received, from ``%`` to ``%``) and their decoded text to :attr:`programs`."""

    def __init__(self, *, cps: float, code: str = "iso", software_parity: bool = False,
                 buffer: int = 256, rate: float | None = None, allowance: int = 10,
                 tv_check: bool = False, dc1_every: float = 1.0, programs: int | None = 1,
                 now: float = 0.0, sink: BinaryIO | None = None, keep_text: bool = True,
                 dialect: Dialect | None = None):
        self.cps = cps
        self.tick = 1.0 / cps
        self.code = code
        self.software_parity = software_parity
        self.buffer = buffer
        self.rate = rate
        self.allowance = allowance
        self.high = max(1, buffer - allowance)
        self.low = buffer // 2
        self.tv_check = tv_check
        self.dc1_every = dc1_every
        self.wanted = programs
        self.sink = sink
        self.keep_text = keep_text
        self.flags = None if dialect is None else dialect.flags
        self.in_comment = False  # between "(" and ")": any printable character is text
        # between a FANUC program name's "<" and ">" (<NAME>, first in its block): the
        # characters of a name (docs/dialects.md)
        self.in_name = False
        self.names = dialect is not None and dialect.family == "fanuc"
        self._stats = ControlStats()
        self.programs: list[str] = []
        self.level = 0.0  # characters in the buffer
        self.level_at = now
        self.switched_on: float | None = None  # the first event: nothing arrived before it
        self.stopped = False  # we sent DC3 (throttling)
        self.dc3_at = now  # when the throttling DC3 reached the line
        self.dc3_unsent = False  # decided on, not yet reported written by sent()
        self.before_dc3 = 0  # bytes not yet read that were waiting when the DC3 was written
        self.after_dc3 = 0
        self.alarmed = False
        self.recent: deque[float] = deque(maxlen=64)  # modelled arrivals of the latest bytes
        self.phase = "leader"  # leader | label | program | finished
        self.text: list[str] = []
        self.line = 1
        self.column = 1
        self.block_length = 0
        self.started = False  # first data byte seen since the last DC1 request
        self.last_dc1 = now
        self.rewound = False  # reset and rewound: what is still on the line is thrown away
        # the operator resets and rewinds at the end of this block of the first program
        # (:class:`dnc.emulator.RewindButton`'s ``after``): done by the control at that block,
        # however many blocks after it the same read brought
        self.rewind_after: int | None = None
        self._rewind_due = False
        self.sink_start: int | None = None  # where the program being read began in the sink
        self.out: list[bytes] = [DC1]

    @property
    def stats(self) -> ControlStats:
        """What the control has seen so far (a DC3 not yet reported :meth:`sent` counts from
        the moment it was decided on)."""
        self._settle()
        return self._stats

    @property
    def done(self) -> bool:
        return self.phase == "finished"

    # -- events --------------------------------------------------------------------------------

    def data_received(self, data: bytes, now: float) -> bytes:
        self._event(now)
        stats = self._stats
        tick = self.tick
        assert self.switched_on is not None
        previous = stats.last if stats.first is not None else self.switched_on - tick
        arrival = now - len(data) * tick
        for byte in data:
            # back to back up to the moment of reading, never faster than the wire
            arrival += tick
            if arrival < previous + tick:
                arrival = previous + tick
            previous = arrival
            if stats.first is None:
                stats.first = arrival
            stats.last = arrival
            stats.chars += 1
            self.recent.append(arrival)
            if self.before_dc3:
                self.before_dc3 -= 1  # it was waiting when the DC3 went out: before it
            elif self.stopped and arrival > self.dc3_at:
                self._count_after_dc3()
            self._byte(byte)
            if self._rewind_due:  # the rest of this read came after the reset: thrown away
                self._rewind_due = False
                self._reset(now)
        if self.rate is not None and self.phase in ("label", "program"):
            self.level += len(data)
            if not self.stopped and self.level >= self.high:
                self._stop(now)
        return self._flush()

    def time_passed(self, now: float) -> bytes:
        self._event(now)
        if self.stopped and self.level <= self.low and self.phase != "finished":
            self.stopped = False
            tail = self._stats.after_dc3
            tail[self.after_dc3] = tail.get(self.after_dc3, 0) + 1
            self._stats.throttles.append(Throttle(self.dc3_at, self.after_dc3))
            self.out.append(DC1)
        elif not self.started and self.phase == "leader" and now - self.last_dc1 >= self.dc1_every:
            self.last_dc1 = now
            self.rewound = False
            self.out.append(DC1)
        return self._flush()

    def sent(self, now: float, waiting: int = 0) -> None:
        """What the last call returned was written to the line at ``now``. A DC3 among it counts
        from then: characters the host sent before it could see the DC3 are not over the
        allowance unless the wire would still have been carrying them. Callers that do not
        report this have their DC3s count from the moment they were decided on.

        ``waiting`` is how many bytes were waiting to be read just before the write: they had
        arrived before the DC3 went out, however late the control reads them. (An emulator
        that lost its core between deciding on a DC3 and writing it finds the host's bytes of
        those milliseconds waiting; read after the DC3, they would be dated after it.)"""
        if self.dc3_unsent:
            self.before_dc3 = waiting
            if now > self.dc3_at:
                self.dc3_at = now
        self._settle()

    @property
    def deadline(self) -> float | None:
        if self.phase == "finished":
            return None
        if self.stopped and self.rate:
            return self.level_at + max(0.0, self.level - self.low) / self.rate
        if not self.started and self.phase == "leader":
            return self.last_dc1 + self.dc1_every
        return None

    def rewind(self, now: float) -> bytes:
        """The operator presses RESET and rewinds the tape to its ``%`` (the absolute rewind
        stop of clause 4), then cycle start.

        A program being read is abandoned (its text is dropped, :attr:`ControlStats.rewinds`
        counts it) and the host is told at once with DC3 SYN, as a Fanuc remote buffer reports a
        reset; whatever is still on the line is thrown away. The DC1 asking for the program
        again from ``%`` follows ``dc1_every`` seconds later (at once when nothing was being
        read), and is repeated until data comes, as at the first start."""
        self._reset(now)
        return self._flush() + self.time_passed(now)

    def _reset(self, now: float) -> None:
        """:meth:`rewind`'s change of state; what it sends is in :attr:`out`."""
        reading = self.phase in ("label", "program")
        if self.phase == "finished" and self.wanted is not None:
            self.wanted += 1  # rewound after the end: the operator wants it read again
        self.phase = "leader"
        self.started = False
        self.stopped = False
        self.level = 0.0
        self.text = []
        self.line, self.column, self.block_length = 1, 1, 0
        if reading:
            if self.sink is not None and self.sink_start is not None:
                self.sink.seek(self.sink_start)  # the abandoned program is not kept
                self.sink.truncate()
            self._stats.rewinds += 1
            self.rewound = True
            self.last_dc1 = now
            self.out += [DC3, SYN]
        else:
            self.last_dc1 = now - self.dc1_every

    # -- inside --------------------------------------------------------------------------------

    def _flush(self) -> bytes:
        out = b"".join(self.out)
        self.out.clear()
        return out

    def _event(self, now: float) -> None:
        """What every event does first: settle a DC3 whose moment is now known, drain the
        buffer up to ``now``, and note when the control was switched on."""
        self._settle()
        self._drain(now)
        if self.switched_on is None:
            self.switched_on = now

    def _drain(self, now: float) -> None:
        if self.rate is not None and now > self.level_at:
            self.level = max(0.0, self.level - (now - self.level_at) * self.rate)
        self.level_at = now

    def _stop(self, now: float) -> None:
        self.stopped = True
        self._stats.dc3 += 1
        self.dc3_at = now
        self.dc3_unsent = True
        self.before_dc3 = 0
        self.alarmed = False
        self.out.append(DC3)

    def _settle(self) -> None:
        """Count, once the DC3's moment is known, the bytes already read whose modelled arrival
        is after it: the host was ahead of the wire by that much."""
        if self.dc3_unsent:
            self.dc3_unsent = False
            self.after_dc3 = sum(1 for t in self.recent if t > self.dc3_at)
            self._note_after_dc3()

    def _count_after_dc3(self) -> None:
        self.after_dc3 += 1
        self._note_after_dc3()

    def _note_after_dc3(self) -> None:
        stats = self._stats
        if self.after_dc3 > stats.most_after_dc3:
            stats.most_after_dc3 = self.after_dc3
        if self.after_dc3 > self.allowance and not self.alarmed:
            self.alarmed = True
            stats.alarms_087 += 1
            self._error("087", f"{self.allowance + 1}th character after DC3 "
                               "(buffer overflow)")

    def _error(self, kind: str, detail: str) -> None:
        self._stats.errors.append(ControlError(kind, self._stats.programs + 1, self.line,
                                              self.column, detail))

    def _byte(self, byte: int) -> None:
        if self.rewound:
            return  # sent before the host saw the reset
        if self.code == "iso":
            char = chr(byte & 0x7F)
            if char in "\x00\x7f":
                return  # tape fill
            if self.software_parity and parity_bits(byte) & 1:
                self._error("TH parity", f"byte 0x{byte:02X}")
            end = char == "%"
            eob = char == "\n"
            skip = char == "\r" or char in "\x11\x12\x13\x14"
        else:
            if byte in (0x00, 0x7F):
                return
            eia = EIA_DECODE.get(byte)
            if eia is None:
                self._error("TH parity" if parity_bits(byte) % 2 == 0 else "TH illegal",
                            f"byte 0x{byte:02X}")
                eia = EIA_DECODE.get(byte ^ 0x10, "\ufffd")
            char = eia
            end = byte == EIA_ER
            eob = byte == EIA_EOB
            skip = False
        self.started = True
        phase = self.phase
        if phase == "leader":
            if end:  # the program start: label skip follows
                self.phase = "label"
                if self.sink is not None and self.sink.seekable():
                    self.sink_start = self.sink.tell()
                self.line, self.column = 1, 1
                self.text = ["%"]
                self._sink(byte)
            return
        self._sink(byte)
        if skip:
            return
        if self.keep_text:
            self.text.append(char)
        if phase == "label":
            if eob:
                self.phase = "program"
                self._newline()
            else:
                self.column += 1
            return
        if end:
            self._finish_program()
            return
        if eob:
            self.in_comment = self.in_name = False
            if self.tv_check and self.block_length % 2:
                self.column = self.block_length + 1
                self._error("TV", f"{self.block_length} characters in the block")
            self._stats.blocks += 1
            self._newline()
            after = self.rewind_after
            if after is not None and self._stats.programs == 0 and self._stats.blocks >= after:
                self.rewind_after = None
                self._rewind_due = True
            return
        if char == "(" and not self.in_name:
            self.in_comment = True
        if not self._accepted(char):
            self._error("TH illegal", f"character {char!r}")
        if char == ")":
            self.in_comment = False
        elif char == "<" and self.names and not self.in_comment:
            self.in_name = True
        elif char == ">":
            self.in_name = False
        self.block_length += 1
        self.column += 1

    def _accepted(self, char: str) -> bool:
        """The TH check's table: the profile's (see the module docstring), or a plain Fanuc's."""
        if char == "\ufffd":
            return False
        if self.flags is None:
            return not (char.islower() or char in _TH_ILLEGAL)
        if self.in_name and char != ">":
            return _core.program_name_character(char)
        return _core.character_allowed(char, self.in_comment, self.flags)

    def _newline(self) -> None:
        self.line += 1
        self.column = 1
        self.block_length = 0

    def _sink(self, byte: int) -> None:
        if self.sink is not None:
            self.sink.write(bytes([byte]))

    def _finish_program(self) -> None:
        stats = self._stats
        stats.programs += 1
        if self.keep_text:
            self.programs.append("".join(self.text))
        self.text = []
        self.out.append(DC3)  # end of reading
        self.stopped = False
        self.level = 0.0
        if self.wanted is not None and stats.programs >= self.wanted:
            self.phase = "finished"
        else:
            self.phase = "leader"
            self.started = False
