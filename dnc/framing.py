"""Framing a program for the wire: leader, ``%``, blocks with the profile's end of block,
TV-check padding, closing ``%``, trailer, in the profile's tape code and parity mode.

* ISO code with **UART parity** (7E1/7E2): 7-bit bytes; the UART adds the parity bit.
* ISO code with **software parity** (8N1/8N2): bit 8 set so every byte has even parity, as on
  punched tape.
* **EIA** RS-244: always software (odd parity on track 5), end of block 0x80, ``%`` sent as ER.

The program start ``%`` and its identification (clause 4, up to the first end of block) are sent as
the file has them; a file without ``%`` gets one. Everything after the closing ``%`` stays behind
(it is reported, but for a DOS end of file, Ctrl-Z). A Ctrl-Z ends the program where only blanks
follow it, as the check reads it (the text before it on its line is the last line; with no closing
``%`` one is added); text after it is refused at it, in either code (neither has the character, and
dropping it would send what the check did not read). A byte-order mark before the first block is
not sent. CRs next to a line feed (CR LF, FANUC's punched LF CR CR) are the file's line end and are
not sent; a CR with text on both sides of it in a line is refused, located: the check read the line
as one block across it, and the wire has no CR that ends no block. A block of odd length gets a
space before its end of block when the profile enables the TV check, so that the control's alarm
002 cannot trip.
"""

from __future__ import annotations

import hashlib
import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from itertools import count, islice
from operator import itemgetter

from formats.errors import TapeError
from formats.profile import EOB_STYLES, SerialSettings
from formats.tape import DOS_EOF, EIA_DEL, encode, iso_byte

_FILL = {"nul": "\x00", "del": "\x7f", "space": " "}
BOM = "\ufeff"  # a UTF-8 byte-order mark before the first block
# ISO control characters that must never be data: DC1-DC4 would be read as flow control.
_CONTROL = re.compile(r"[\x00-\x08\x0a-\x1f\x7f]")


@dataclass
class FrameStats:
    blocks: int = 0
    padded: int = 0  # blocks given a space for the TV check
    added_start: bool = False  # the file had no "%": one was sent
    added_end: bool = False
    left_after_end: int = 0  # non-blank lines after the closing "%" (not sent)
    cr_by_lf: int = 0  # CRs at a line's ends (next to LF, or the file's end): not sent


class Framer:
    """Turns numbered program lines into the bytes of each block on the wire."""

    def __init__(self, s: SerialSettings, *, file: str | None = None):
        self.settings = s
        self.file = file
        self.stats = FrameStats()
        self.software = s.parity_mode == "software"
        if s.code == "iso":
            self.eob = self.encode(EOB_STYLES[s.eob], 0, control_ok=True)
        else:
            self.eob = bytes([0x80])
        fill = _FILL[s.leader_char]
        if s.code == "eia" and fill == "\x7f":
            self.fill = bytes([EIA_DEL])
        else:
            self.fill = self.encode(fill, 0, control_ok=True)

    # -- bytes ---------------------------------------------------------------------------------

    def encode(self, text: str, line: int, *, control_ok: bool = False) -> bytes:
        """One block's characters in the link's code; a character the code cannot carry is a
        :class:`TapeError` naming line and column."""
        s = self.settings
        if s.code == "eia":
            try:
                return encode(text.replace("\n", ""), "eia")
            except TapeError as exc:
                raise TapeError(exc.message, file=self.file, line=line, column=exc.column,
                                clause=exc.clause, code=exc.code) from None
        if not control_ok:
            bad = _CONTROL.search(text)
            if bad:
                code = ord(bad.group())
                what = ("would be read by the control as flow control" if 0x11 <= code <= 0x14
                        else "is not an Annex A character")
                raise TapeError(f"control character 0x{code:02X} {what}", file=self.file,
                                line=line, column=bad.start() + 1, clause="Annex A",
                                code="tape-character")
        try:
            raw = text.encode("ascii")
        except UnicodeEncodeError as exc:
            raise TapeError(f"character {text[exc.start]!r} cannot be carried by ISO 7-bit code",
                            file=self.file, line=line, column=exc.start + 1,
                            clause="Annex A", code="tape-character") from None
        return raw.translate(_SOFTWARE) if self.software else raw

    def _before_dos_eof(self, line: int, text: str, rest: Iterator[tuple[int, str]]) -> str:
        """The text of ``line`` before its DOS end of file (Ctrl-Z), which ends the file as
        the check reads it, where only blanks follow it to the end of the file (they are not
        sent); text after it is refused at the Ctrl-Z, as the check refuses it: neither
        sending it (ISO has no such character, EIA none at all) nor dropping it sends what was
        checked."""
        after = text.partition(DOS_EOF)[2]
        if after.strip(_BLANK_AFTER_EOF) or any(r.strip(_BLANK_AFTER_EOF) for _, r in rest):
            raise TapeError(
                "text after a DOS end of file (Ctrl-Z, 0x1A): the file ends at it as the check "
                "reads it, and the tape codes have no such character; take the Ctrl-Z out of "
                "the program", file=self.file, line=line, column=text.index(DOS_EOF) + 1,
                clause="Annex A", code="tape-character")
        return text.partition(DOS_EOF)[0]

    def leader(self) -> bytes:
        return self.fill * self.settings.leader

    def trailer(self) -> bytes:
        return self.fill * self.settings.trailer

    # -- the program ---------------------------------------------------------------------------

    def measure(self, lines: Iterable[tuple[int, str]]) -> tuple[int, str]:
        """Frame ``lines`` without sending them, before the port is opened: the bytes a pass
        sends (leader and trailer included) and the SHA-256 of the program as framed (without
        them), for the progress bar and the journal. Fills :attr:`stats`; raises the located
        error of a character the tape code cannot carry."""
        digest = hashlib.sha256()
        total = len(self.leader()) + len(self.trailer())
        frames = map(itemgetter(1), self.frames(lines))
        while batch := list(islice(frames, 4096)):  # hashed a batch at a time
            data = b"".join(batch)
            total += len(data)
            digest.update(data)
        return total, digest.hexdigest()

    def frames(self, lines: Iterable[tuple[int, str]]) -> Iterator[tuple[int, bytes]]:
        """``(line, bytes)`` for each block, from the ``%`` start line to the closing ``%``
        (leader and trailer not included)."""
        stats = self.stats
        tv = self.settings.tv_check
        eob = self.eob
        # the common block, printable ASCII in ISO code, is encoded here; any other goes
        # through encode(), which says what it cannot carry
        plain = self.settings.code == "iso"
        software = _SOFTWARE if self.software else None
        started = False
        raw = iter(lines)
        lines = _line_ends(raw, stats, self.file)
        last = False
        for line, text in lines:
            if DOS_EOF in text:  # a DOS end of file: the program's last line, or refused
                text = self._before_dos_eof(line, text, raw)
                last = True
            if not started:
                text = text.removeprefix(BOM)  # an editor's byte-order mark is never sent
                if not text.strip():
                    if last:
                        break
                    continue
                started = True
                if text.startswith("%"):
                    yield line, self.encode(text, line) + eob
                    continue
                stats.added_start = True
                yield 0, self.encode("%", 0) + eob
            if text.strip() == "%":
                yield line, self.encode("%", line)
                for _, rest in raw:  # not sent: a CR in them is no matter
                    if rest.strip(" \t\r\x00\x7f" + DOS_EOF):  # a DOS end of file is no line
                        stats.left_after_end += 1
                return
            if last and not text.strip():
                break
            if tv and len(text) % 2:
                text += " "
                stats.padded += 1
            stats.blocks += 1
            if plain and text.isascii() and text.isprintable():
                data = text.encode("ascii")
                yield line, (data if software is None else data.translate(software)) + eob
            else:
                yield line, self.encode(text, line) + eob
            if last:
                break
        stats.added_end = True
        if not started:
            stats.added_start = True
            yield 0, self.encode("%", 0) + eob
        yield 0, self.encode("%", 0)


_BLANK_AFTER_EOF = " \t\r\x00\x7f" + DOS_EOF


def _line_ends(lines: Iterable[tuple[int, str]], stats: FrameStats, file: str | None
               ) -> Iterator[tuple[int, str]]:
    """The blocks of ``lines``: CRs next to a line feed (CR LF, FANUC's punched LF CR CR) are
    the file's line end, which the profile's end of block replaces, so they are not sent (sent
    as data, a CR would be two empty blocks per line in EIA, its EOB, and a control character
    ISO refuses); counted in ``stats``. Blanks after such a CR, before the LF, are no text: they
    go with it. A CR with text on both sides of it in a line is refused
    (:class:`TapeError`, located): tapegate's check splits blocks at LF alone and read the line
    as one block across it, as a FANUC does (its end of block is LF, CR-LF or LF-CR-CR), while
    on the wire it could only be dropped, which joins the two parts into a block no check saw,
    or sent as an end of block, which splits the block the check read (docs/dnc.md)."""
    for line, raw in lines:
        if "\r" not in raw:
            yield line, raw
            continue
        body = raw.strip("\r")
        tail = body.rstrip(" \t\r")
        if "\r" in body[len(tail):]:
            # CR then only blanks before the LF (an editor's trailing blank after CR): the
            # blanks are no text, the CR is the line end's, and neither is sent
            body = tail
        stats.cr_by_lf += raw.count("\r") - body.count("\r")
        if "\r" in body:
            lead = len(raw) - len(raw.lstrip("\r"))
            raise TapeError(
                "a CR inside the line, with text on both sides: the check read the line as one "
                "block across it (a FANUC's end of block is LF, CR-LF or LF-CR-CR), and a sender "
                "can only drop it or end the block there, either way not the block checked; "
                "write the program with LF or CR-LF line ends", file=file, line=line,
                column=lead + body.index("\r") + 1, clause="4", code="tape-character")
        yield line, body


_SOFTWARE = bytes(iso_byte(chr(c & 0x7F)) for c in range(256))


def split_lines(chunks: Iterable[str]) -> Iterator[tuple[int, str]]:
    """Numbered lines (without their line feed) from text chunks of any size."""
    line = 1
    rest = ""
    for chunk in chunks:
        if rest:
            chunk = rest + chunk
        parts = chunk.split("\n")
        rest = parts.pop()
        yield from zip(count(line), parts)  # numbered in C, not a Python step per line
        line += len(parts)
    if rest:
        yield line, rest

