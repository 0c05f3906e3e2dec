"""Receiving what a control punches, as a pure state machine.

The control announces itself with DC2 (tape punch on) or just starts sending; it ends with DC4
(punch off), the closing ``%`` or silence. In between come leader (NUL/DEL), ``%``, the program
and trailer. The receiver:

* answers DC2 with DC1 (controls such as the Rockwell 9/Series wait for it; others ignore it);
* detects ISO or EIA from the first ``%``/ER or end of block it sees (as Fanuc and Yaskawa
  controls do), unless told the code;
* never takes a byte of an EIA program for a DC code: in EIA 0x13 is the digit 3, and 0x11,
  0x12, 0x14 are digits with a parity error;
* decodes as it goes (memory stays flat): the program text from ``%`` to the closing ``%``,
  leader and trailer stripped, every parity error and illegal code kept in the text (as read,
  or U+FFFD) and reported with line and column;
* with UART parity on a local tty, reads the driver's parity marks (termios ``PARMRK``:
  ``FF 00 c``) so those errors are located too.

Events: :meth:`Receiver.data_received`, :meth:`Receiver.time_passed`. Actions: :class:`Reply`
(bytes to send back), :class:`Text` (decoded program text), :class:`Finished` (why it ended).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from formats.tape import EIA_EOB, EIA_ER, TapeDecoder, TapeIssue

if TYPE_CHECKING:
    from formats.tape import Code

DC1, DC2, DC4 = 0x11, 0x12, 0x14


@dataclass(frozen=True)
class Reply:
    data: bytes


@dataclass(frozen=True)
class Text:
    text: str


@dataclass(frozen=True)
class Finished:
    reason: str  # "DC4" | "closing %" | "idle" | "no data"


ReceiverAction = Reply | Text | Finished


class Receiver:
    def __init__(self, *, code: Code | None = None, uart_parity: bool = False,
                 parity_marks: bool = False, idle_timeout: float = 5.0,
                 start_timeout: float | None = None, now: float = 0.0):
        self.code: Code | None = code
        self.uart_parity = uart_parity  # 7-bit bytes: the UART checked parity, not us
        self.parity_marks = parity_marks
        self.idle_timeout = idle_timeout
        self.start_timeout = start_timeout
        self.started_at = now
        self.last_data: float | None = None
        self.state = "idle"  # idle | leader | program | done
        self.decoder: TapeDecoder | None = None
        self.held = bytearray()  # bytes before the code is known
        self.mark = 0  # PARMRK state: 0 none, 1 after FF, 2 after FF 00
        self.bytes = 0
        self.announced = False  # DC2 seen
        self.reason = ""
        self.reported = False

    @property
    def issues(self) -> list[TapeIssue]:
        return self.decoder.issues if self.decoder else []

    @property
    def done(self) -> bool:
        return self.state == "done"

    def data_received(self, data: bytes, now: float) -> list[ReceiverAction]:
        replies: list[ReceiverAction] = []
        out: list[str] = []
        for byte in data:
            if self.state == "done":
                break
            flagged = False
            if self.parity_marks:
                if self.mark == 0 and byte == 0xFF:
                    self.mark = 1
                    continue
                if self.mark == 1:
                    self.mark = 0
                    if byte == 0x00:
                        self.mark = 2
                        continue
                    # FF FF is a real FF byte
                elif self.mark == 2:
                    self.mark = 0
                    flagged = True
            self.bytes += 1
            self.last_data = now
            if self._control_code(byte):
                if byte & 0x7F == DC2 and not self.announced:
                    self.announced = True
                    replies.append(Reply(bytes([DC1])))
                elif byte & 0x7F == DC4 and self.state != "idle":
                    self._end("DC4")
                continue
            if self.state == "idle":
                self.state = "leader"
            if self.decoder is None:
                self.code = self.code or _detect(byte)
                if self.code is None:
                    self.held.append(byte)
                    continue
                self._start_decoding(out)
            if self.state != "done":
                self._byte(byte, flagged, out)
        return self._actions(replies, out)

    def time_passed(self, now: float) -> list[ReceiverAction]:
        if self.state == "done":
            return []
        if self.last_data is None:
            if self.start_timeout is not None and now - self.started_at >= self.start_timeout:
                self.state = "done"
                self.reported = True
                return [Finished("no data")]
            return []
        if now - self.last_data < self.idle_timeout:
            return []
        out: list[str] = []
        if self.decoder is None:
            self.code = self.code or "iso"
            self._start_decoding(out)
        self._end("idle")
        return self._actions([], out)

    @property
    def deadline(self) -> float | None:
        if self.state == "done":
            return None
        if self.last_data is None:
            return None if self.start_timeout is None else self.started_at + self.start_timeout
        return self.last_data + self.idle_timeout

    # -- inside --------------------------------------------------------------------------------

    def _control_code(self, byte: int) -> bool:
        if self.code == "eia":
            # 0x13 is the digit 3, and 0x11 0x12 0x14 are 1 2 4 with a parity error: inside
            # the program they are data (reported, never dropped); DC codes only around it
            return self.state != "program" and byte in (0x11, 0x12, 0x14, 0x93, 0x94)
        return byte & 0x7F in (0x11, 0x12, 0x13, 0x14)

    def _start_decoding(self, out: list[str]) -> None:
        assert self.code is not None
        self.decoder = TapeDecoder(self.code, parity=not self.uart_parity)
        held, self.held = bytes(self.held), bytearray()
        for b in held:
            if self.state != "done":
                self._byte(b, False, out)

    def _byte(self, byte: int, flagged: bool, out: list[str]) -> None:
        decoder = self.decoder
        assert decoder is not None
        start = byte in (0x25, 0xA5) if self.code == "iso" else byte == EIA_ER
        if self.state in ("idle", "leader"):
            if not start:
                return
            self.state = "program"
        elif start:
            out.append(decoder.feed(bytes([byte])))
            self._end("closing %")
            return
        if flagged:
            decoder.flag_parity(byte)
        out.append(decoder.feed(bytes([byte])))

    def _end(self, reason: str) -> None:
        self.state = "done"
        self.reason = reason

    def _actions(self, replies: list[ReceiverAction], out: list[str]) -> list[ReceiverAction]:
        actions = replies
        text = "".join(out)
        if text:
            actions.append(Text(text))
        if self.state == "done" and not self.reported:
            self.reported = True
            actions.append(Finished(self.reason))
        return actions


def _detect(byte: int) -> Code | None:
    if byte in (0x25, 0xA5, 0x0A):
        return "iso"
    if byte in (EIA_ER, EIA_EOB):
        return "eia"
    return None
