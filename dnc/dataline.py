"""Machine data from DPRNT lines: what a control's macro prints on its RS-232 port.

A Fanuc or Haas macro can print a line on the same port the programs go through, with
``POPEN`` / ``DPRNT[...]`` / ``PCLOS``: at cycle start and end, or at a part count (the data that
CIMCO MDC-Max collects from controls with no Ethernet). On the wire such a line is text and an
end of block, with no ``%`` around it: Fanuc's ``POPEN`` sends DC2 and ``PCLOS`` DC4, Haas sends
the lines alone, ended by CR LF. The gateway used to take that for a program that never started.

Here, as small sans-I/O pieces the gateway drives:

* :class:`DataPatterns`: the regular expressions (with named groups) a line must match, whole,
  to be data; :data:`DEFAULT_PATTERNS` understand the usual forms, ``(CYCLE START O1234)``,
  ``(CYCLE END O1234)``, ``PARTS=57`` (or Fanuc's ``PARTS     57.``) and ``NAME=value``;
* :class:`LineSplitter`: the bytes a control sends while no program is coming in, cut into
  lines, up to the ``%`` (or the EIA rewind stop) that starts a program;
* :func:`data_program`: a "program" whose every line is data (``%`` ... ``%`` around DPRNT
  lines) is data too, never a received program.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field

from formats.tape import EIA_EOB, EIA_ER

DEFAULT_PATTERNS: tuple[str, ...] = (
    # (CYCLE START O1234), CYCLE END, CYCLE STOP, PART DONE, PROGRAM START / END
    r"\(?\s*(?P<event>CYCLE\s+(?:START|END|STOP)|PART\s+DONE|PROGRAM\s+(?:START|END))"
    r"(?:\s+(?P<program>[O:]\s*\d{1,8}))?\s*\)?",
    # PARTS=57, PARTS: 57, PART COUNT 57, and Fanuc's PARTS     57. (DPRNT[PARTS#3901[80]])
    r"\(?\s*PART(?:S|\s+COUNT)\s*[=:]?\s*(?P<parts>\d{1,9})(?:\.0*)?\s*\)?",
    # any other NAME=value: TOOL=12, SPINDLE LOAD=45.2, X=-12.500
    r"\(?\s*(?P<name>[A-Z][A-Z0-9_]{0,15}(?:\s[A-Z][A-Z0-9_]{0,15})?)\s*[=:]\s*"
    r"(?P<value>[-+]?\s*\d{1,12}(?:\.\d{0,9})?)\s*\)?",
)
GROUPS = frozenset(("event", "program", "parts", "name", "value"))  # documented; others allowed
MAX_LINE = 256  # a longer line is no DPRNT line (Fanuc prints at most 256 characters)
MAX_DATA_PROGRAM = 4096  # characters: a longer "program" is a program, whatever it holds

# event -> Modbus input register 15 of the port (docs/modbus.md)
EVENT_CODES = {"CYCLE START": 1, "CYCLE END": 2, "CYCLE STOP": 2, "PART DONE": 2,
               "PROGRAM START": 1, "PROGRAM END": 2}
OTHER_EVENT = 3  # an event the table does not name (a pattern of the user's own)


@dataclass(frozen=True)
class DataEvent:
    """A line that matched: the line as received, the pattern's index and its named groups
    that matched (values as strings, exactly as printed, whitespace collapsed)."""
    line: str
    pattern: int
    fields: dict[str, str] = field(default_factory=dict)

    @property
    def event_code(self) -> int:
        event = self.fields.get("event")
        return EVENT_CODES.get(event, OTHER_EVENT) if event else OTHER_EVENT

    @property
    def parts(self) -> int | None:
        parts = self.fields.get("parts", "")
        return int(parts) if parts.isdigit() else None


class DataPatterns:
    """The patterns of one port, compiled; a line is data when one of them matches it whole."""

    def __init__(self, patterns: Sequence[str]):
        self.sources = tuple(patterns)
        self.compiled = tuple(re.compile(p) for p in patterns)

    def __bool__(self) -> bool:
        return bool(self.compiled)

    def match(self, line: str) -> DataEvent | None:
        text = line.strip()
        if not text or len(text) > MAX_LINE:
            return None
        for i, pattern in enumerate(self.compiled):
            m = pattern.fullmatch(text)
            if m:
                fields = {k: " ".join(v.split()) for k, v in m.groupdict().items()
                          if v is not None}
                if "event" in fields:
                    fields["event"] = fields["event"].upper()
                if "program" in fields:
                    fields["program"] = fields["program"].replace(" ", "").replace(":", "O")
                if "value" in fields:
                    fields["value"] = fields["value"].replace(" ", "")
                return DataEvent(text, i, fields)
        return None


@dataclass
class Split:
    """What :meth:`LineSplitter.feed` found: whole lines, bytes to answer (DC1 to a DC2), and
    where a program starts (the offset in the data fed), if one does."""
    lines: list[str] = field(default_factory=list)
    replies: bytes = b""
    program_at: int | None = None
    dropped: int = 0  # lines longer than MAX_LINE, dropped


class LineSplitter:
    """The bytes a control sends outside a program, as lines. Bit 8 (even parity) is dropped;
    DC1-DC4 and tape fill are no text; CR and LF end a line; ``%`` (ISO) or the EIA rewind stop or
    end of block starts a program, handed back to the receiver from there."""

    def __init__(self) -> None:
        self.buffer = bytearray()
        self.overlong = False

    @property
    def pending(self) -> bool:
        return bool(self.buffer) or self.overlong

    def feed(self, data: bytes) -> Split:
        out = Split()
        for i, byte in enumerate(data):
            c = byte & 0x7F
            if c == 0x25 or byte in (EIA_ER, EIA_EOB):
                out.program_at = i
                self.buffer.clear()  # leader text before the program: dropped, as before
                self.overlong = False
                return out
            if c == 0x12:
                out.replies += b"\x11"  # DC2 (punch on): ready, as the receiver answers it
            elif c in (0x0A, 0x0D):
                self._end(out)
            elif c in (0x00, 0x11, 0x13, 0x14, 0x7F):
                continue
            elif len(self.buffer) >= MAX_LINE:
                self.overlong = True
            else:
                self.buffer.append(c)
        return out

    def flush(self) -> Split:
        """The line is quiet: a line still unended is ended."""
        out = Split()
        self._end(out)
        return out

    def _end(self, out: Split) -> None:
        if self.overlong:
            out.dropped += 1
        elif self.buffer.strip():
            out.lines.append(self.buffer.decode("ascii", errors="replace").strip())
        self.buffer.clear()
        self.overlong = False


def data_program(text: str, chars: int, patterns: DataPatterns) -> list[DataEvent] | None:
    """The events of a captured "program" whose every line (``%`` lines and blank lines aside)
    is data; ``None`` when it is a program (a line that is not data, or too long to be DPRNT
    output)."""
    if not patterns or chars > MAX_DATA_PROGRAM:
        return None
    events = []
    for line in _lines(text):
        event = patterns.match(line)
        if event is None:
            return None
        events.append(event)
    return events or None


def _lines(text: str) -> Iterable[str]:
    for line in text.replace("\r", "\n").split("\n"):
        stripped = line.strip()
        if stripped and stripped.strip("%").strip():
            yield stripped
        # a line of only % (or blank) is the program's frame, not data
