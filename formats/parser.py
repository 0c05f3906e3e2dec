"""Text -> a stream of :class:`~formats.model.Block`, fast, lossless and exactly located.

The hot path (tomllib-style small functions over ``(text, pos)``, and regular expressions that
run in C) works line by line:

1. a block of whitespace-separated simple words (``N10 G01 X12.5 Y-3 F200`` -- most of what CAM
   systems write) is recognised by one ``fullmatch`` and split with ``str.split``;
2. a block of glued words (``N10G01X12.5``) by a second ``fullmatch`` and one ``findall``;
3. anything else -- comments, ``%``, ``/`` skip, ``:`` alignment, indexed addresses, parameter
   expressions, characters the profile allows beyond Annex A, and every error -- goes through
   :func:`tokenize_block`, which walks the line and says exactly where something is wrong.

Values are not converted here: a block keeps its word tokens as strings and
:meth:`formats.profile.Profile.value` reads them through the Annex C word format on demand.
Input is consumed in chunks, so memory does not grow with the program (streaming).
"""

from __future__ import annotations

import codecs
import re
from bisect import bisect_right
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from itertools import accumulate
from typing import Literal

from formats.errors import ParseError
from formats.model import Block, BlockInfo

# Longest block accepted: a guard against binary input or a file with no end of block at all.
MAX_BLOCK = 65536
CHUNK = 1 << 20

# Non-printing characters that the control ignores (clause 4, Annex A) plus NUL, the blank tape
# of a leader or trailer. LF is the end of block and never reaches a block's text.
NON_PRINTING = " \t\r\x7f\x00"
ANNEX_A = set("ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789%()+,-./:=") | set(NON_PRINTING) - {"\x00"}

_W = r"[A-Z][+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)"
_SPACED = re.compile(rf"(?:[ \t\r]*{_W}(?![A-Z]))*+[ \t\r]*+")
_GLUED = re.compile(rf"(?:[ \t\r]*{_W})*+[ \t\r]*+")
_GLUED_WORD = re.compile(_W)

_NUMBER = re.compile(r"[0-9]+\.?[0-9]*|\.[0-9]+")
_DIGITS = re.compile(r"[0-9]+")
_WS = re.compile(r"[ \t\r\x7f\x00]*")


@dataclass(frozen=True)
class Dialect:
    """What a profile allows beyond ISO 6983-1 Annex A, as far as reading text is concerned."""

    lowercase: bool = False  # lower-case addresses read as upper case
    extra: frozenset[str] = field(default_factory=frozenset)  # e.g. "#[];*"
    expressions: bool = True  # parameter expressions of 6.4.7 after "index ="

    @property
    def semicolon_comments(self) -> bool:
        return ";" in self.extra

    @property
    def hash_parameters(self) -> bool:
        return "#" in self.extra

    @property
    def brackets(self) -> bool:
        return "[" in self.extra and "]" in self.extra


STRICT = Dialect()
PERMISSIVE = Dialect(lowercase=True, extra=frozenset("#[];*"))

Errors = Literal["raise", "collect"]


class BadBlock(Block):
    """A block the parser could not read, kept (text and position) when errors are collected."""

    __slots__ = ("error",)

    def __init__(self, text: str, line: int, error: ParseError) -> None:
        super().__init__(text, line, [], None)
        self.error = error


def parse_text(text: str, dialect: Dialect = STRICT, *, file: str | None = None,
               errors: Errors = "raise") -> list[Block]:
    """All blocks of a program held in memory (tests, small programs)."""
    return list(parse_stream([text], dialect, file=file, errors=errors))


def parse_stream(chunks: Iterable[str], dialect: Dialect = STRICT, *, file: str | None = None,
                 errors: Errors = "raise", first_line: int = 0) -> Iterator[Block]:
    """Blocks from text arriving in chunks of any size; memory is bounded by the chunk size.

    ``first_line``: how many lines of the file came before the text (for error positions).
    """
    for text, line, unread in whole_lines(chunks):
        line += first_line
        if unread is None:
            yield from parse_lines(text[:-1], line, dialect, file, errors)
        elif len(text) > MAX_BLOCK:
            yield from _too_long(text, line + 1, file, errors)
        elif text:
            last = list(parse_lines(text, line, dialect, file, errors))
            block = last[-1]
            if block.info is None:
                block.info = BlockInfo()
            block.info.eob = False
            yield from last


def whole_lines(chunks: Iterable[str]) -> Iterator[tuple[str, int, Iterator[str] | None]]:
    """The text of chunks cut at ends of block, for callers that take whole runs of lines.

    Yields ``(text, lines before it, None)`` where ``text`` is complete lines, each ending with
    LF; then once ``(rest, lines before it, the chunks not yet read)`` -- the unfinished last
    line at the end of the input, or a block running past :data:`MAX_BLOCK` (no more is read
    then), for the caller to finish or report.
    """
    line = 0
    rest = ""
    it = iter(chunks)
    for chunk in it:
        data = rest + chunk if rest else chunk
        cut = data.rfind("\n")
        rest = data[cut + 1:]
        if cut >= 0:
            yield data[:cut + 1], line, None
            line += data.count("\n", 0, cut + 1)
        if len(rest) > MAX_BLOCK:
            break
    yield rest, line, it


def _too_long(text: str, line: int, file: str | None, errors: Errors) -> Iterator[Block]:
    error = ParseError(
        f"block longer than {MAX_BLOCK} characters without an end of block (LF): "
        "binary data or not an NC program?",
        file=file, line=line, column=1, clause="4",
    )
    if errors == "raise":
        raise error
    yield BadBlock(text[:80], line, error)


# Chunk-level validation. A chunk of blocks is translated to the "shape" of its characters
# (letters -> A, digits -> 9, signs -> s, "." kept, blanks -> space, anything else -> ?) by one
# bytes.translate. Splitting the shape at blanks and taking the set of distinct token shapes
# leaves a handful of strings (A99, As9.999...) that one regular expression can judge: if each is
# a simple word, every line without a "?" is exactly its ``str.split()`` words. Lines with a "?"
# (comments, "%", "/", ":") take the per-line path; a chunk with any other odd token (glued words,
# errors) is read line by line.
_SHAPE = bytes(
    ord("A") if 65 <= c <= 90 else ord("9") if 48 <= c <= 57 else c if c in b".\n" else
    ord("s") if c in b"+-" else ord(" ") if c in b" \t\r" else ord("?")
    for c in range(256)
)
_WORD_SHAPE = re.compile(rb"As?(?:9+\.?9*|\.9+)")


def _careful_lines(data: str, lines: list[str]) -> set[int] | None:
    """Indexes of the lines the split path cannot take; None to read every line carefully."""
    try:
        shape = data.encode("ascii").translate(_SHAPE)
    except UnicodeEncodeError:
        return None
    odd = [t for t in set(shape.split()) if b"?" not in t and not _WORD_SHAPE.fullmatch(t)]
    if odd:
        return None
    careful: set[int] = set()
    at = shape.find(b"?")
    if at >= 0:
        starts = list(accumulate((len(t) + 1 for t in lines), initial=0))
        while at >= 0:
            careful.add(bisect_right(starts, at) - 1)
            at = shape.find(b"?", at + 1)
    return careful


def parse_lines(data: str, line: int, dialect: Dialect, file: str | None,
                errors: Errors) -> Iterator[Block]:
    """The blocks of ``data``, whole lines without the last LF, after line ``line``."""
    lines = data.split("\n")
    careful = _careful_lines(data, lines)
    if careful is not None:
        first = line + 1
        if not careful:
            for text in lines:
                line += 1
                yield Block(text, line, text.split())
            return
        for text in lines:
            line += 1
            if line - first not in careful:
                yield Block(text, line, text.split())
            else:
                yield _parse_line(text, line, dialect, file, errors)
        return
    for text in lines:
        line += 1
        yield _parse_line(text, line, dialect, file, errors)


def _parse_line(text: str, line: int, dialect: Dialect, file: str | None,
                errors: Errors) -> Block:
    """One line the chunk check did not clear: spaced words, glued words, or the tokenizer."""
    if _SPACED.fullmatch(text) is not None:
        return Block(text, line, text.split())
    if _GLUED.fullmatch(text) is not None:
        return Block(text, line, _GLUED_WORD.findall(text))
    try:
        words, info = tokenize_block(text, dialect)
    except ParseError as exc:
        exc.located(file=file, line=line)
        if errors == "raise":
            raise
        return BadBlock(text, line, exc)
    return Block(text, line, words, info)


# ---------------------------------------------------------------------------------------------
# The careful tokenizer: every construct of clauses 4-6, every error located.

def _err(message: str, pos: int, clause: str | None = None) -> ParseError:
    return ParseError(message, column=pos + 1, clause=clause)


def tokenize_block(text: str, dialect: Dialect = STRICT) -> tuple[list[str], BlockInfo]:
    """Word tokens and extras of one block's text; :class:`ParseError` (column set) if bad."""
    if len(text) > MAX_BLOCK:
        raise _err("not an NC program (no end of block)", MAX_BLOCK, "4")
    info = BlockInfo()
    words: list[str] = []
    pos = _WS.match(text).end()  # type: ignore[union-attr]
    if pos < len(text) and text[pos] == "%":
        info.percent = True
        info.ident = text[pos + 1:].strip(" \t\r\x00\x7f")
        _check_ident(info.ident, pos + 1)
        return words, info
    if pos < len(text) and text[pos] == "/":
        level = text[pos + 1:pos + 2]
        if level.isdigit() and level != "0":
            info.skip = "/" + level
            pos += 2
        else:
            info.skip = "/"
            pos += 1
    n = len(text)
    while True:
        pos = _WS.match(text, pos).end()  # type: ignore[union-attr]
        if pos >= n:
            return words, info
        ch = text[pos]
        if ch == "(":
            end = text.find(")", pos + 1)
            if end < 0:
                raise _err("comment not closed: '(' without ')' before the end of block", pos,
                           "4")
            _check_comment(text, pos + 1, end)
            info.comments.append((pos + 1, text[pos:end + 1]))
            pos = end + 1
        elif ch == ";" and dialect.semicolon_comments:
            _check_comment(text, pos + 1, len(text))
            info.comments.append((pos + 1, text[pos:].rstrip("\r")))
            return words, info
        elif ch == ":":
            m = _DIGITS.match(text, pos + 1)
            if m is None:
                raise _err("alignment ':' must be followed by the sequence number digits",
                           pos + 1, "6.4.1")
            words.append(":" + m.group())
            pos = m.end()
        elif "A" <= ch <= "Z" or (ch.islower() and ch.isascii() and dialect.lowercase) or (
                ch == "#" and dialect.hash_parameters):
            pos = _word(text, pos, dialect, words)
        elif ch == ")":
            raise _err("')' without an opening '(' (nested or unbalanced comment)", pos, "4")
        elif ch == "/":
            raise _err("'/' block skip must stand at the start of the block, before the "
                       "sequence number", pos, "4")
        elif ch in "0123456789.+-":
            raise _err(f"number {ch!r} without an address letter", pos, "6.1")
        else:
            raise _err(_character_message(ch, dialect), pos, "Annex A")


def _character_message(ch: str, dialect: Dialect) -> str:
    code = f"0x{ord(ch):02X}" if ord(ch) < 0x110000 else "?"
    if ch.islower() and ch.isascii():
        return (f"lower-case {ch!r} is outside ISO 6983-1 Annex A and the profile does not "
                "allow lower case")
    if ch in ANNEX_A:
        return f"character {ch!r} is not expected here"
    if not ch.isprintable():
        return f"control or binary character {code} is not allowed in an NC program"
    return f"character {ch!r} ({code}) is outside ISO 6983-1 Annex A and not allowed by the profile"


def _check_ident(ident: str, pos: int) -> None:
    for i, ch in enumerate(ident):
        if ch in "\t \r\x00\x7f":
            continue
        if not ch.isprintable():
            raise _err(f"control or binary character 0x{ord(ch):02X} in the program "
                       "identification", pos + i, "Annex A")


def _check_comment(text: str, start: int, end: int) -> None:
    for i in range(start, end):
        ch = text[i]
        if not ch.isprintable() and ch not in "\t\r":
            raise _err(f"control or binary character 0x{ord(ch):02X} in a comment", i, "Annex A")


def _word(text: str, pos: int, dialect: Dialect, words: list[str]) -> int:
    """Read the word at ``pos``; append its token; return the position after it."""
    address = text[pos]
    start = pos
    pos = _WS.match(text, pos + 1).end()  # type: ignore[union-attr]
    index = ""
    m = _DIGITS.match(text, pos)
    if m is not None:
        after = _WS.match(text, m.end()).end()  # type: ignore[union-attr]
        if after < len(text) and text[after] == "=":
            index = m.group()
            if address == "#":
                pass
            elif int(index) == 0:
                raise _err(f"address index of {address} must be greater than 0", m.start(),
                           "6.2")
            pos = _WS.match(text, after + 1).end()  # type: ignore[union-attr]
    if address == "#" and not index:
        raise _err("'#' parameter must be written #n = value", start, "6.4.7")
    value_start = pos
    sign = ""
    if pos < len(text) and text[pos] in "+-":
        sign = text[pos]
        pos = _WS.match(text, pos + 1).end()  # type: ignore[union-attr]
    number = _NUMBER.match(text, pos)
    if number is not None:
        end = number.end()
        probe = _WS.match(text, end).end()  # type: ignore[union-attr]
        operator = probe < len(text) and text[probe] in "+-*/" and (
            text[probe] != "*" or "*" in dialect.extra)
        if not (index and operator and dialect.expressions):
            token = f"{address}{index + '=' if index else ''}{sign}{number.group()}"
            words.append(token)
            return end
    if not dialect.expressions or not (index or _expression_start(text, value_start, dialect)):
        if pos >= len(text) or text[pos] in " \t\r":
            raise _err(f"address {address} has no value", start, "6.1")
        if text[pos] == "=" and not index:
            raise _err(f"address {address} has '=' but no index: a parameter is set with its "
                       f"index, as in {address}1 = 22.2", pos, "6.4.7")
        raise _err(f"address {address} must be followed by a number, found {text[pos]!r}", pos,
                   "6.1")
    end = _expression_end(text, value_start, dialect)
    source = text[value_start:end]
    from formats.expr import check_expression

    check_expression(source, value_start)
    compact = "".join(source.split())
    words.append(f"{address}{index + '=' if index else ''}{compact}")
    return end


def _expression_start(text: str, pos: int, dialect: Dialect) -> bool:
    if pos >= len(text):
        return False
    ch = text[pos]
    return (ch == "#" and dialect.hash_parameters) or (ch == "[" and dialect.brackets)


_OPERAND = re.compile(
    r"[+-]?[ \t]*(?:[0-9]+\.?[0-9]*|\.[0-9]+|[PQR][0-9]+|#[0-9]+|[A-Z]{2,6}(?=[ \t]*\[)|\[)"
)


def _expression_end(text: str, pos: int, dialect: Dialect) -> int:
    """End of the expression starting at ``pos``: operands joined by operators, brackets
    balanced. The expression grammar (formats.expr) then checks what lies in between."""
    n = len(text)
    depth = 0
    while True:
        pos = _WS.match(text, pos).end()  # type: ignore[union-attr]
        m = _OPERAND.match(text, pos)
        if m is None:
            if pos >= n:
                raise _err("expression ends without an operand", pos, "6.4.7")
            raise _err(f"expected a number or parameter in the expression, found {text[pos]!r}",
                       pos, "6.4.7")
        pos = m.end()
        while m.group().endswith("["):
            depth += 1
            pos = _WS.match(text, pos).end()  # type: ignore[union-attr]
            m = _OPERAND.match(text, pos)
            if m is None:
                raise _err("expected an operand after '['", pos, "6.4.7")
            pos = m.end()
        while True:
            pos2 = _WS.match(text, pos).end()  # type: ignore[union-attr]
            if depth and pos2 < n and text[pos2] == "]":
                depth -= 1
                pos = pos2 + 1
            else:
                break
        probe = _WS.match(text, pos).end()  # type: ignore[union-attr]
        if probe < n and text[probe] in "+-*/":
            if text[probe] == "*" and "*" not in dialect.extra:
                break
            pos = probe + 1
            continue
        if depth:
            raise _err("'[' without a closing ']' in the expression", probe, "6.4.7")
        return pos
    return pos


def decode_chunks(raw: Iterable[bytes]) -> Iterator[str]:
    """Bytes -> text, UTF-8 where it is UTF-8 and every other byte kept (surrogateescape), so
    encoding back with :func:`encode_text` gives the same bytes."""
    decoder = codecs.getincrementaldecoder("utf-8")(errors="surrogateescape")
    for chunk in raw:
        text = decoder.decode(chunk)
        if text:
            yield text
    tail = decoder.decode(b"", final=True)
    if tail:
        yield tail


def encode_text(text: str) -> bytes:
    return text.encode("utf-8", errors="surrogateescape")


def read_chunks(path: str, size: int = CHUNK) -> Iterator[bytes]:
    with open(path, "rb") as f:
        while True:
            chunk = f.read(size)
            if not chunk:
                return
            yield chunk
