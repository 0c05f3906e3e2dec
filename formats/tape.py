"""Punched-tape codes: ISO 7-bit with even parity on track 8, and EIA RS-244.

* **ISO** (ISO 6983-1 Annex A, ISO/IEC 646): the 7-bit code with bit 8 set so that every byte has
  an even number of 1 bits. ``%`` 0x25 -> 0xA5, LF 0x0A -> 0x0A, ``1`` 0x31 -> 0xB1.
* **EIA** RS-244: BCD on tracks 1-4, odd parity on track 5, zones on tracks 6-7, end of block on
  track 8 (0x80). EIA has no ``%``, ``:``, ``=``; its rewind stop ER (0x0B) stands where ISO has
  ``%`` and is decoded as ``%``.

Decoding never drops data: a parity error keeps the character (the parity bit is ignored) and is
reported with its byte offset, line and column; an illegal code becomes U+FFFD, which no NC parser
accepts, so it cannot pass unnoticed. Blank tape (NUL) and erased characters (DEL) are tape fill:
removed on decoding (leader, trailer, and anywhere else) and counted.
"""

from __future__ import annotations

from formats.errors import TapeError
from formats.records import NEW, FrozenRecord, Record, field, init_fields, new, record

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    import re
    from collections.abc import Callable, Iterable, Iterator
    from typing import Literal

    Code = Literal["iso", "eia"]
    Content = Literal["iso", "eia", "text", "binary"]


class _Lazy:
    """A regular expression compiled when first used (called): a conversion of text files
    reads no tape, and ``re`` (with ``enum``, ``collections``, ``functools``) was 25M
    instructions of its serial start-up (docs/benchmarks.md, perf40)."""

    __slots__ = ("_source", "_compiled")

    def __init__(self, source: str | Callable[[], str]) -> None:
        self._source = source
        self._compiled: re.Pattern[str] | None = None

    def __call__(self) -> re.Pattern[str]:
        compiled = self._compiled
        if compiled is None:
            import re

            source = self._source
            compiled = self._compiled = re.compile(source if isinstance(source, str)
                                                   else source())
        return compiled


# ---------------------------------------------------------------------------------------------
# ISO


def parity_bits(byte: int) -> int:
    return bin(byte).count("1")


def iso_byte(char: str) -> int:
    """The tape byte of one 7-bit character with even parity on track 8."""
    code = ord(char)
    return code | 0x80 if parity_bits(code) & 1 else code


_ISO_ENCODE = bytes(iso_byte(chr(c)) for c in range(128)) * 2  # 256 entries for translate
# Control characters that an ISO NC tape may hold: blank, TAB, LF, CR. DEL is erase.
# SUB 0x1A is the DOS end-of-file mark after a program's last line: carried on the tape and
# decoded as itself, so that an encode/decode round trip gives back every byte (the reader takes
# it as the end of the file; anywhere else it refuses it, located)
_ISO_CONTROLS_OK = {0x00, 0x09, 0x0A, 0x0D, 0x1A, 0x7F}

# ---------------------------------------------------------------------------------------------
# EIA RS-244 (table in the project's spec: SIMH i1620_pt.c, ProtoCore dnc.c, Yaskawa LX3)

EIA_EOB = 0x80
EIA_ER = 0x0B  # end of record / rewind stop: ISO's "%"
EIA_BLANK = 0x00
EIA_DEL = 0x7F
EIA_TABLE: dict[str, int] = {
    "0": 0x20, "1": 0x01, "2": 0x02, "3": 0x13, "4": 0x04, "5": 0x15, "6": 0x16, "7": 0x07,
    "8": 0x08, "9": 0x19,
    "A": 0x61, "B": 0x62, "C": 0x73, "D": 0x64, "E": 0x75, "F": 0x76, "G": 0x67, "H": 0x68,
    "I": 0x79, "J": 0x51, "K": 0x52, "L": 0x43, "M": 0x54, "N": 0x45, "O": 0x46, "P": 0x57,
    "Q": 0x58, "R": 0x49, "S": 0x32, "T": 0x23, "U": 0x34, "V": 0x25, "W": 0x26, "X": 0x37,
    "Y": 0x38, "Z": 0x29,
    " ": 0x10, ".": 0x6B, "-": 0x40, "+": 0x70, "/": 0x31, ",": 0x3B, "\t": 0x3E,
    "(": 0x1A, ")": 0x4A, "\n": EIA_EOB, "%": EIA_ER,
}
EIA_DECODE: dict[int, str] = {byte: char for char, byte in EIA_TABLE.items()}
# Encoding in C: anything EIA cannot carry is found first by the regular expression (so the
# error names the first such character); then every character is ASCII, and bytes.translate
# maps it to its tape byte, tape fill (NUL, DEL) to itself. CR is dealt with before (TapeEncoder).
_EIA_ENCODE = bytes(EIA_TABLE.get(chr(c), EIA_DEL if c == 0x7F else 0) for c in range(256))


def _eia_cannot() -> str:
    import re

    return "[^" + re.escape("".join(EIA_TABLE) + "\x00\x7f") + "]"


_EIA_CANNOT = _Lazy(_eia_cannot)


@record
class TapeIssue(FrozenRecord):
    """A parity error or an illegal code in a tape image, located."""

    kind: Literal["parity", "illegal"]
    offset: int  # byte offset in the tape image
    line: int
    column: int
    byte: int
    char: str  # what the byte was decoded as

    def __init__(self, kind: Literal["parity", "illegal"], offset: int, line: int, column: int,
                 byte: int, char: str) -> None:
        init_fields(self, kind, offset, line, column, byte, char)

    def message(self) -> str:
        if self.kind == "parity":
            return f"parity error: byte 0x{self.byte:02X} read as {self.char!r}"
        return f"illegal code 0x{self.byte:02X}"


@record
class Decoded(Record):
    """A tape image decoded: its text, its code and what was wrong in it."""

    text: str
    code: Code
    issues: list[TapeIssue] = field(default_factory=list)
    fill: int = 0  # NUL and DEL characters removed

    def __init__(self, text: str, code: Code, issues: list[TapeIssue] = NEW,
                 fill: int = 0) -> None:
        self.text = text
        self.code = code
        self.issues = new(issues, list)
        self.fill = fill


# ---------------------------------------------------------------------------------------------
# Encoding


@record
class EncodeNotes(Record):
    """What an encoding changed without refusing, counted so that the command can say it: every
    byte of the text comes back from the tape, or is named here."""

    # CR next to LF, and blanks after a line end's CR, dropped (EIA: its EOB alone ends the
    # block; the blanks are no text, as the sender leaves them)
    cr_by_lf: int = 0
    cr_eob: int = 0  # CR line ends (no LF next to them) written as EOB (EIA)
    fill: int = 0  # NUL and DEL written as tape fill, which decoding removes
    dos_eof: int = 0  # (EIA) a DOS end of file (Ctrl-Z) ending the text, and blanks after it

    def __init__(self, cr_by_lf: int = 0, cr_eob: int = 0, fill: int = 0,
                 dos_eof: int = 0) -> None:
        init_fields(self, cr_by_lf, cr_eob, fill, dos_eof)

    def lines(self) -> list[str]:
        """One sentence per kind of change, for standard error."""
        out = []
        if self.cr_by_lf:
            out.append(f"{self.cr_by_lf} CR next to LF (or blank after a line end's CR) not "
                       "carried: EIA's EOB alone ends a block (decoding gives LF)")
        if self.cr_eob:
            out.append(f"{self.cr_eob} CR line ends written as EOB (decoding gives LF)")
        if self.fill:
            out.append(f"{self.fill} NUL/DEL written as tape fill, which decoding removes")
        if self.dos_eof:
            out.append(f"{self.dos_eof} characters from the DOS end of file (Ctrl-Z) on not "
                       "carried: no part of the program, and EIA has no such character")
        return out


class TapeEncoder:
    """Text -> tape bytes a chunk at a time; a character the code cannot carry is a located
    :class:`TapeError` (line and column in the whole text). :attr:`notes` counts what was
    written otherwise than as itself.

    EIA has no CR: CRs next to LF (CR LF, FANUC's punched LF CR CR, a CR before blanks and the
    LF) are dropped, the EOB ending the block, and CRs at the very end of the text, ending its
    last line, are written as EOB. A CR with text after it in its line (a CR inside a line, or
    a file whose lines end in CR alone) is refused at the CR: tapegate's check splits blocks at
    LF alone and read the text across it as one block, as a FANUC does, and EIA's only end of
    block would split that block there (docs/formats.md; the sender refuses the same CR). EIA's
    ER, the rewind stop a reader stops at, stands for ``%`` only where a line starts with it
    (FANUC reads the rest of that line as its label); a ``%`` inside a block, as in ``(FEED
    50%)``, would stop the reader part-way through the program and is refused, as ``:`` is. A
    DOS end of file (Ctrl-Z, 0x1A), which DOS editors write after the closing ``%``, is no part
    of the program and has no EIA character: where only blanks follow it, it and they are left
    off and counted (ISO code carries it as it is, as the sender leaves it behind); with text
    after it, it is refused."""

    def __init__(self, code: Code = "iso", *, file: str | None = None) -> None:
        self.code = code
        self.file = file
        self.notes = EncodeNotes()
        self._line = 0  # lines before the text not yet encoded
        self._column = 0  # characters of its line before the text not yet encoded
        # EIA: a CR met after text in its line, and the CRs and blanks after it, held (as
        # counts: a run of any length takes no memory) until what follows says what they are:
        # an LF (the line's end: dropped), text (refused, at the first CR), the end of the text
        # or a DOS end of file (the last line's end: its CRs written as EOB)
        self._held_cr = 0
        self._held_blank = 0
        self._held_at = (0, 0)  # line and column of the first CR held
        self._bol = True  # nothing of the current line written yet: a CR here follows an LF
        # EIA: the refusal of the DOS end of file met, should text follow it; where held CRs
        # came just before it, text after it makes them CRs inside a line, refused as such
        self._eof: TapeError | None = None
        self._cr_before_eof: TapeError | None = None

    def feed(self, chunk: str) -> bytes:
        if self.code != "eia":
            return self._encode(chunk)
        out: list[bytes] = []
        at, size = 0, len(chunk)
        while at < size:
            if self._eof is not None:  # only blanks may follow a DOS end of file
                out.append(self._encode(chunk[at:]))
                break
            if self._held_cr:
                end = _CR_OR_BLANK().match(chunk, at).end()  # type: ignore[union-attr]
                crs = chunk.count("\r", at, end)
                self._held_cr += crs
                self._held_blank += end - at - crs
                at = end
                if at == size:
                    break
                if chunk[at] == "\n":  # CR [blanks] LF: the line's end, not carried
                    self._release(False)
                elif chunk[at] == DOS_EOF:  # the text's end, if only blanks follow it
                    self._cr_before_eof = self._inside_line()
                    out.append(self._release(True))
                else:
                    raise self._inside_line()
            if self._bol:  # CRs just after an LF (FANUC's LF CR CR) or at the text's start
                end = _CRS().match(chunk, at).end()  # type: ignore[union-attr]
                self.notes.cr_by_lf += end - at
                self._column += end - at  # columns count them, as the check's and send's do
                at = end
                if at == size:
                    break
            cr = chunk.find("\r", at)
            out.append(self._encode(chunk[at:] if cr < 0 else chunk[at:cr]))
            if cr < 0:
                break
            if self._eof is not None:  # a DOS end of file before the CR: blanks after it
                out.append(self._encode(chunk[cr:]))
                break
            at = cr
            if not self._bol:  # a CR after text: held until what follows it is known
                self._held_at = (self._line + 1, self._column + 1)
                self._held_cr = 1
                at += 1
        return b"".join(out)

    def finish(self) -> bytes:
        """The CRs held at the end of the text: its last line's end, written as EOB."""
        return self._release(True) if self._held_cr else b""

    def _release(self, at_end: bool) -> bytes:
        """The held CRs and blanks, the line's end: no text, so the blanks are not carried
        (as the sender leaves them); the CRs are dropped before an LF, and at the end of the
        text each is written as EOB."""
        crs, self._held_cr = self._held_cr, 0
        self.notes.cr_by_lf += self._held_blank
        self._held_blank = 0
        if not at_end:
            self.notes.cr_by_lf += crs
            return b""
        self.notes.cr_eob += crs
        self._line += crs
        self._column = 0
        self._bol = True
        return bytes([EIA_EOB]) * crs

    def _inside_line(self) -> TapeError:
        line, column = self._held_at
        return TapeError(
            "a CR with text after it in its line (a CR inside a line, or lines ending in CR "
            "alone): tapegate's check splits blocks at LF alone and read the text across it as "
            "one block, as a FANUC does (its end of block is LF, CR-LF or LF-CR-CR), while EIA "
            "has no CR and its end of block would split that block here; write the program "
            "with LF or CR-LF line ends", file=self.file, line=line, column=column, clause="4",
            code="tape-character")

    def _encode(self, text: str) -> bytes:
        if not text:
            return b""
        notes = self.notes
        if self.code == "iso":
            bad = _ISO_CANNOT().search(text)
            if bad:
                raise self._cannot(text, bad.start(), "ISO 7-bit code")
            body = text.encode("ascii")
            notes.fill += body.count(0) + body.count(0x7F)
            self._advance(text)
            return body.translate(_ISO_ENCODE)
        if self._eof is not None or DOS_EOF in text:
            text = self._before_eof(text)
            if not text:
                return b""
        bad = _EIA_CANNOT().search(text)
        end = bad.start() if bad else len(text)
        # a '%' inside a block, before that: found by str.find (a program holds few)
        at = text.find("%", 0, end)
        while at >= 0:
            if text[at - 1] != "\n" if at else not self._bol:
                end = at
                break
            at = text.find("%", at + 1, end)
        if end < len(text):  # the first of a character EIA has not and a '%' inside a block
            raise self._cannot(text, end, "EIA RS-244 code")
        body = text.encode("ascii")
        notes.fill += body.count(0) + body.count(0x7F)
        self._advance(text)
        self._bol = text[-1] == "\n"
        return body.translate(_EIA_ENCODE)

    def _before_eof(self, text: str) -> str:
        """``text`` without a DOS end of file that only blanks follow (counted with them); a
        DOS end of file with text after it is refused at the Ctrl-Z."""
        at = 0 if self._eof is not None else text.find(DOS_EOF)
        if text[at:].strip(_BLANK_AFTER_EOF):
            if self._cr_before_eof is not None:
                raise self._cr_before_eof
            if self._eof is not None:
                raise self._eof
            return text  # refused at the Ctrl-Z as a character EIA has not
        if self._eof is None:
            self._eof = self._cr_before_eof or self._cannot(text, at, "EIA RS-244 code")
        self.notes.dos_eof += len(text) - at
        return text[:at]

    def _advance(self, text: str) -> None:
        newlines = text.count("\n")
        self._column = len(text) - text.rfind("\n") - 1 + (0 if newlines else self._column)
        self._line += newlines

    def _cannot(self, text: str, offset: int, code: str) -> TapeError:
        line = text.count("\n", 0, offset) + 1
        column = offset - (text.rfind("\n", 0, offset) + 1) + 1
        if line == 1:
            column += self._column
        exc = _cannot(text[offset], code, self.file, line + self._line, column)
        return exc


def encode(text: str, code: Code = "iso", *, leader: int = 0, trailer: int = 0,
           file: str | None = None, notes: EncodeNotes | None = None) -> bytes:
    """Text -> tape bytes. Characters the code cannot carry are a located :class:`TapeError`;
    ``notes``, when given, gets the counts of what was written otherwise than as itself."""
    encoder = TapeEncoder(code, file=file)
    body = encoder.feed(text) + encoder.finish()
    if notes is not None:
        init_fields(notes, *encoder.notes._values())
    return bytes(leader) + body + bytes(trailer)


def encode_stream(chunks: Iterable[str], code: Code = "iso", *, leader: int = 0,
                  trailer: int = 0, file: str | None = None,
                  notes: EncodeNotes | None = None) -> Iterator[bytes]:
    """Text chunks -> tape bytes, in flat memory whatever the size of the program; an error
    names the line and column in the whole text, as :func:`encode` does; ``notes`` as there,
    filled once the last chunk is through."""
    encoder = TapeEncoder(code, file=file)
    yield bytes(leader)
    for chunk in chunks:
        yield encoder.feed(chunk)
    yield encoder.finish()
    if notes is not None:
        init_fields(notes, *encoder.notes._values())
    yield bytes(trailer)


_ISO_CANNOT = _Lazy(r"[^\x00-\x7f]")
DOS_EOF = "\x1a"  # Ctrl-Z, the end of file DOS editors write after the program
_BLANK_AFTER_EOF = " \t\r\n\x00" + DOS_EOF
_CRS = _Lazy("\r*")
_CR_OR_BLANK = _Lazy("[\r \t]*")


def _cannot(ch: str, code: str, file: str | None, line: int, column: int) -> TapeError:
    hint = ""
    if ch in ":=":
        hint = " (EIA has no ':' or '='; use N sequence numbers and plain words)"
    elif ch == "%":
        hint = (" inside a block: EIA's ER, which stands for '%', is the rewind stop where a "
                "reader stops; it may only start a line")
    elif not ch.isascii():
        hint = " (it is no ASCII character)"
    elif ch.islower():
        hint = " (EIA carries upper case only)"
    if "\udc80" <= ch <= "\udcff":  # a byte that was no UTF-8, kept as it was in the file
        what = f"byte 0x{ord(ch) - 0xDC00:02X} (not ASCII or UTF-8 text: an 8-bit character set?)"
        hint = ""
    else:
        what = f"character {ch!r}"
    return TapeError(f"{what} cannot be carried by {code}{hint}", file=file, line=line,
                     column=column, clause="Annex A", code="tape-character")


# ---------------------------------------------------------------------------------------------
# Detecting and decoding


def detect(data: bytes) -> Literal["iso", "eia", "text"]:
    """Which tape code a file holds, from the first end of block (as Fanuc and Yaskawa controls
    do): EIA's EOB 0x80 has odd parity, ISO's LF 0x0A even. ``text`` is 7-bit text with no
    parity bits set, or UTF-8 (checked first: its multi-byte characters hold 0x80-0xBF): it
    reads as it is."""
    sample = data[:65536]
    if not sample.isascii() and _utf8(sample):  # an em dash holds 0x80, EIA's end of block
        return "text"
    lf = sample.find(b"\n")
    eob = sample.find(bytes([EIA_EOB]))
    if eob >= 0 and (lf < 0 or eob < lf):
        return "eia"
    if sample.isascii():
        return "eia" if lf < 0 and _eia_without_eob(sample) else "text"
    if not sample.translate(None, _EVEN_OR_FILL):
        return "iso"
    # Bytes with bit 8 set but 7-bit bytes with odd parity too: text (UTF-8) or a damaged ISO
    # tape. Most bytes of a damaged tape still carry even parity.
    even = len(sample) - len(sample.translate(None, _EVEN))
    has_high = len(sample.translate(None, _LOW))
    return "iso" if even > 0.9 * len(sample) and has_high > 0.1 * len(sample) else "text"


def _eia_without_eob(sample: bytes) -> bool:
    """True for an EIA tape with no end of block in it (one block, or one whose ends of block
    were lost): every byte an EIA character or tape fill, and among them one below 0x20 (the
    digits 1-9, blank, ER...), which in ASCII is a control that no text holds."""
    return (not sample.translate(None, _EIA_OR_FILL)
            and bool(sample.translate(None, _NOT_EIA_CONTROL)))


def _utf8(sample: bytes) -> bool:
    """True when the sample is UTF-8 text, but for a character cut at its end. A tape of any
    length is not: its high bytes (ISO's odd-parity characters, EIA's end of block) stand
    alone where UTF-8 wants a lead byte before them."""
    try:
        sample.decode("utf-8")
    except UnicodeDecodeError as exc:
        return exc.reason == "unexpected end of data" and exc.end == len(sample)
    return True


# Byte classes for detect(), counted in C by deleting them with bytes.translate.
_EVEN = bytes(b for b in range(256) if parity_bits(b) % 2 == 0)
_EVEN_OR_FILL = bytes(sorted(set(_EVEN) | {0x00, 0x7F, 0xFF}))
_LOW = bytes(range(128))
_EIA_OR_FILL = bytes(sorted(set(EIA_DECODE) | {EIA_BLANK, EIA_DEL}))
_NOT_EIA_CONTROL = bytes(b for b in range(256) if not (b in EIA_DECODE and b < 0x20))


class _Table:
    """What every one of the 256 byte values decodes to under one code, computed once: the
    character, whether it is tape fill, and the issues it raises. Decoding then runs in C
    (``bytes.translate`` and a regular expression finding the bytes that raise an issue); only
    those bytes are looked at one by one, so the positions of the issues stay exact."""

    def __init__(self, code: Code, parity: bool) -> None:
        self.chars: list[str] = []
        self.issues: list[tuple[tuple[Literal["parity", "illegal"], str], ...]] = []
        fill = bytearray()
        for byte in range(256):
            char, issues = self._decode(code, parity, byte)
            self.chars.append(char)
            self.issues.append(issues)
            if char == "":
                fill.append(byte)
        self.fill = bytes(fill)
        # translate: every byte without an issue to its (ASCII) character
        self.translate = bytes(ord(c) if len(c) == 1 and c.isascii() else 0 for c in self.chars)
        flagged = bytes(b for b in range(256) if self.issues[b])
        import re  # (a tape's decoding: not at the module's import)

        self.flagged = re.compile(b"[" + b"".join(re.escape(bytes([b])) for b in flagged) + b"]"
                                  if flagged else b"(?!)")

    @staticmethod
    def _decode(code: Code, parity: bool, byte: int
                ) -> tuple[str, tuple[tuple[Literal["parity", "illegal"], str], ...]]:
        """The character of one byte ("" for tape fill) and its issues, in order."""
        if code == "iso":
            char = chr(byte & 0x7F)
            seven = byte & 0x7F
            if seven in (0x00, 0x7F):
                return "", ()
            issues: list[tuple[Literal["parity", "illegal"], str]] = []
            if parity and parity_bits(byte) & 1:
                issues.append(("parity", char))
            if seven < 0x20 and seven not in _ISO_CONTROLS_OK:
                issues.append(("illegal", char))
                char = "\ufffd"
            return char, tuple(issues)
        if byte in (EIA_BLANK, EIA_DEL):
            return "", ()
        decoded = EIA_DECODE.get(byte)
        if decoded is not None:
            return decoded, ()
        flipped = EIA_DECODE.get(byte ^ 0x10)
        if flipped is not None and parity_bits(byte) % 2 == 0:
            return flipped, (("parity", flipped),)
        return "\ufffd", (("illegal", "\ufffd"),)


_TABLES: dict[tuple[Code, bool], _Table] = {}


def _table(code: Code, parity: bool) -> _Table:
    table = _TABLES.get((code, parity))
    if table is None:
        table = _TABLES[code, parity] = _Table(code, parity)
    return table


class TapeDecoder:
    """Incremental decoder (feed chunks of any size); collects located issues.

    ``parity`` False reads ISO bytes without checking bit 8: the 7-bit bytes of a link whose
    UART checked the parity (its errors are reported with :meth:`flag_parity`)."""

    def __init__(self, code: Code, *, parity: bool = True):
        self.code = code
        self.parity = parity
        self.offset = 0
        self.line = 1
        self.column = 1
        self.issues: list[TapeIssue] = []
        self.fill = 0
        self._table = _table(code, parity)

    def feed(self, data: bytes) -> str:
        if len(data) < 8:  # a byte at a time from a serial link: a table lookup is quicker
            return self._bytes(data)
        table = self._table
        out: list[str] = []
        start = 0
        for m in table.flagged.finditer(data):
            at = m.start()
            if at > start:
                out.append(self._run(data[start:at]))
            byte = data[at]
            for kind, char in table.issues[byte]:
                self._issue(kind, byte, char)
            char = table.chars[byte]
            out.append(char)
            self.offset += 1
            if char == "\n":
                self.line += 1
                self.column = 1
            else:
                self.column += 1
            start = at + 1
        if start < len(data):
            out.append(self._run(data[start:] if start else data))
        return out[0] if len(out) == 1 else "".join(out)

    def _bytes(self, data: bytes) -> str:
        """A few bytes, one by one through the table."""
        table = self._table
        out = ""
        for byte in data:
            for kind, char in table.issues[byte]:
                self._issue(kind, byte, char)
            char = table.chars[byte]
            self.offset += 1
            if not char:
                self.fill += 1
                continue
            out += char
            if char == "\n":
                self.line += 1
                self.column = 1
            else:
                self.column += 1
        return out

    def _run(self, data: bytes) -> str:
        """Bytes none of which raises an issue: translated in one go."""
        table = self._table
        text = data.translate(table.translate, table.fill).decode("ascii")
        self.offset += len(data)
        self.fill += len(data) - len(text)
        lines = text.count("\n")
        if lines:
            self.line += lines
            self.column = len(text) - text.rfind("\n")
        else:
            self.column += len(text)
        return text

    def flag_parity(self, byte: int) -> None:
        """The next byte fed failed a parity check made elsewhere (the UART's)."""
        self._issue("parity", byte, chr(byte & 0x7F) if self.code == "iso" else
                    EIA_DECODE.get(byte, "\ufffd"))

    def _issue(self, kind: Literal["parity", "illegal"], byte: int, char: str) -> None:
        self.issues.append(TapeIssue(kind, self.offset, self.line, self.column, byte, char))


def decode_stream(chunks: Iterable[bytes], code: Code | None = None
                  ) -> tuple[TapeDecoder, Iterator[str]]:
    """Tape bytes in chunks -> the decoder (its code, fill count, and the issues found so far,
    which the caller may take as it goes) and the text in chunks: flat memory."""
    it = iter(chunks)
    head = next(it, b"")
    if code is None:
        found = detect(head)
        code = "eia" if found == "eia" else "iso"
    decoder = TapeDecoder(code)

    def text() -> Iterator[str]:
        yield decoder.feed(head)
        for chunk in it:
            yield decoder.feed(chunk)

    return decoder, text()


def decode(data: bytes, code: Code | None = None) -> Decoded:
    """Tape bytes -> text; ``code`` None detects it (``text`` files decode as ISO)."""
    if code is None:
        found = detect(data)
        code = "eia" if found == "eia" else "iso"
    decoder = TapeDecoder(code)
    text = decoder.feed(data)
    return Decoded(text, code, decoder.issues, decoder.fill)


# The C0 controls a text NC file may hold: blank, TAB, LF, VT, FF, CR, the DC1-DC4 of a
# punch or reader dump, DOS's end of file Ctrl-Z; DEL is erase.
_TEXT_CONTROLS = _Lazy("[\x01-\x08\x0e-\x10\x15-\x19\x1b-\x1f]")
# More foreign bytes than this share of the sample, and a file is no NC program in any code.
_FOREIGN_SHARE = 0.02
# A file found to be a tape by its first end of block (with the parity of its code) stays one
# with this many parity errors or illegal codes, however short: a 28-byte tape with one
# damaged character is 3.6 % foreign, and still a tape that decoding reads and locates.
_FEW_ON_A_TAPE = 3


def identify(data: bytes) -> tuple[Content, int]:
    """What a file holds, for ``tape detect``: the code :func:`detect` finds, or ``binary`` when
    more than 2 % of the first 64 KiB are no character of that code -- in a text (UTF-8, or
    Latin-1 as old editors wrote accents) control characters and NULs between its first and
    last character (UTF-16 has one in every other byte), on a tape parity errors and illegal
    codes, more than three -- or when it holds nothing but tape fill. A tape with a few parity
    errors is still a tape (its decoding reports them); an image, an archive or a compiled
    file is none. Also returns the count of foreign bytes found."""
    sample = data[:65536]
    found = detect(sample)
    if found == "text":
        core = sample.strip(b"\x00\x7f")  # a leader and trailer of tape fill are no text
        if not core:
            return ("binary" if sample else "text"), len(sample)  # blank tape: no program
        try:
            text = core.decode("utf-8")
        except UnicodeDecodeError as exc:
            if exc.reason == "unexpected end of data" and len(data) > len(sample):
                text = core[:exc.start].decode("utf-8", errors="replace")  # cut at 64 KiB
            else:
                # Latin-1 (ISO 8859-1), as old editors wrote accented comments: its letters
                # 0xA0-0xFF are text, its C1 controls 0x80-0x9F are not
                text = core.decode("latin-1")
                text = "".join("\ufffd" if "\x80" <= c <= "\x9f" else c for c in text)
        foreign = (text.count("\ufffd") + len(_TEXT_CONTROLS().findall(text))
                   + text.count("\x00"))
    else:
        foreign = len(decode(sample, found).issues)
        if foreign <= _FEW_ON_A_TAPE:  # a short tape with a damaged character is a tape
            return found, foreign
    return ("binary" if foreign > _FOREIGN_SHARE * len(sample) else found), foreign


def is_tape_image(data: bytes) -> bool:
    """True when a file must be decoded before it can be read as text."""
    return detect(data) in ("iso", "eia") and not data[:65536].isascii()
