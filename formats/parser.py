"""Text -> a stream of :class:`~formats.model.Block`, fast, lossless and exactly located.

The tokenizer is the Rust core's (``crates/core/src/tokenizer.rs``, through ``formats._core``):
one pass over each line that reads every construct of clauses 4 to 6 -- words, ``%`` marks,
``/`` skip, comments, ``:`` alignment, indexed addresses, parameter expressions, the characters
a profile allows beyond Annex A -- and says exactly where something is wrong, with the checker's
rule code on the error. This module cuts the input into whole lines and streams them through it.

Values are not converted here: a block keeps its word tokens as strings and
:meth:`formats.profile.Profile.value` reads them through the Annex C word format on demand.
Input is consumed in chunks, so memory does not grow with the program (streaming).
"""

from __future__ import annotations

import codecs
from itertools import chain

from formats import _core
from formats._core import BadBlock
from formats.errors import ParseError
from formats.model import Block, BlockInfo
from formats.records import NEW, FrozenRecord, field, init_fields, new, record

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from collections.abc import Iterable, Iterator
    from typing import Literal

    Errors = Literal["raise", "collect"]

__all__ = [
    "CHUNK", "MAX_BLOCK", "PERMISSIVE", "STRICT", "BadBlock", "Dialect", "Errors", "count_blocks",
    "decode_chunks", "encode_text", "parse_lines", "parse_stream", "parse_text",
    "read_chunks", "tokenize_block", "whole_lines", "whole_texts",
]

# Longest block accepted: a guard against binary input or a file with no end of block at all.
MAX_BLOCK: int = _core.MAX_BLOCK
CHUNK = 1 << 20
_line_ends = _core.line_ends


@record
class Dialect(FrozenRecord):
    """What a profile allows beyond ISO 6983-1 Annex A, as far as reading text is concerned."""

    lowercase: bool = False  # lower-case addresses read as upper case
    extra: frozenset[str] = field(default_factory=frozenset)  # e.g. "#[];*"
    expressions: bool = True  # parameter expressions of 6.4.7 after "index ="
    family: str = "iso"  # whose statements are read: iso, fanuc, haas, sinumerik, heidenhain,
    #                      linuxcnc (docs/dialects.md)

    def __init__(self, lowercase: bool = False, extra: frozenset[str] = NEW,
                 expressions: bool = True, family: str = "iso") -> None:
        init_fields(self, lowercase, new(extra, frozenset), expressions, family)

    @property
    def semicolon_comments(self) -> bool:
        return ";" in self.extra

    @property
    def hash_parameters(self) -> bool:
        return "#" in self.extra

    @property
    def brackets(self) -> bool:
        return "[" in self.extra and "]" in self.extra

    @property
    def flags(self) -> tuple[bool, bool, bool, bool, bool, bool, str]:
        """What the core's tokenizer is told: lower case, ``#``, ``[ ]``, ``;``, ``*``,
        expressions, the family."""
        return (self.lowercase, self.hash_parameters, self.brackets, self.semicolon_comments,
                "*" in self.extra, self.expressions, self.family)


STRICT = Dialect()
PERMISSIVE = Dialect(lowercase=True, extra=frozenset("#[];*"))



def parse_text(text: str, dialect: Dialect = STRICT, *, file: str | None = None,
               errors: Errors = "raise") -> list[Block]:
    """All blocks of a program held in memory (tests, small programs)."""
    return list(parse_stream([text], dialect, file=file, errors=errors))


def parse_stream(chunks: Iterable[str], dialect: Dialect = STRICT, *, file: str | None = None,
                 errors: Errors = "raise", first_line: int = 0,
                 end: _core.ReadingEnd | None = None) -> Iterator[Block]:
    """Blocks from text arriving in chunks of any size; memory is bounded by the chunk size.

    ``first_line``: how many lines of the file came before the text (for error positions);
    ``end``: where the control stops reading, as the lines before left it (a fresh one by
    default): the lines it never reads (after a LinuxCNC program's end) are blocks of their
    text alone.
    """
    collect = errors == "collect"
    end = end or _core.ReadingEnd(dialect.family)
    for text, line, unread in whole_lines(chunks):
        line += first_line
        if unread is None:
            # parse_lines inlined: one generator fewer between a block and its reader
            blocks, error = _core.parse_lines(text[:-1], line, dialect.flags, file, collect,
                                              end)
            yield from blocks
            del blocks  # before the next chunk's are made: one chunk of blocks in memory
            if error is not None:
                raise error
        elif len(text) > MAX_BLOCK:
            yield from too_long_block(text, line + 1, file, errors)
        elif text:
            last = list(parse_lines(text, line, dialect, file, errors, end))
            block = last[-1]
            if block.info is None:
                block.info = BlockInfo()
            block.info.eob = False
            yield from last


def count_blocks(chunks: Iterable[str], dialect: Dialect = STRICT, *,
                 file: str | None = None) -> tuple[int, int, int]:
    """(blocks, words, comments) of a program, as :func:`parse_stream` would read it (the
    first block that cannot be read raises its :class:`ParseError`), without making blocks."""
    blocks = words = comments = 0
    end = _core.ReadingEnd(dialect.family)
    for text, line, unread in whole_lines(chunks):
        if unread is None:
            b, w, c = _core.count_lines(text[:-1], line, dialect.flags, file, end)
        else:
            rest = list(parse_stream(chain([text], unread), dialect, file=file, first_line=line,
                                     end=end))
            b, w, c = len(rest), sum(len(x.words) for x in rest), sum(
                len(x.comments) for x in rest)
        blocks, words, comments = blocks + b, words + w, comments + c
    return blocks, words, comments


def whole_lines(chunks: Iterable[str]) -> Iterator[tuple[str, int, Iterator[str] | None]]:
    """The text of chunks cut at ends of block, for callers that take whole runs of lines.

    Yields ``(text, lines before it, None)`` where ``text`` is complete lines, each ending with
    LF; then once ``(rest, lines before it, the chunks not yet read)`` -- the unfinished last
    line at the end of the input, or a block running past :data:`MAX_BLOCK` (no more is read
    then), for the caller to finish or report.
    """
    line = 0
    for text, unread in whole_texts(chunks):
        yield text, line, unread
        # (counted by the core's vector search: str.count reads a character at a time)
        line += _line_ends(text)


def whole_texts(chunks: Iterable[str]) -> Iterator[tuple[str, Iterator[str] | None]]:
    """:func:`whole_lines` without the count of lines before each text, for a caller whose
    reader counts them as it reads (the checker's core: counting the LFs of every chunk again
    in Python cost as much as 2 % of a check)."""
    rest = ""
    it = iter(chunks)
    for chunk in it:
        data = rest + chunk if rest else chunk
        cut = data.rfind("\n")
        rest = data[cut + 1:]
        if cut >= 0:
            yield data[:cut + 1], None
        if len(rest) > MAX_BLOCK:
            break
    yield rest, it


def too_long_block(text: str, line: int, file: str | None, errors: Errors) -> Iterator[Block]:
    """A block running past :data:`MAX_BLOCK` without an end of block: its located error
    raised, or (``collect``) a :class:`BadBlock` of its first characters; the readers that
    take whole lines (:func:`parse_stream`, ``formats.diff``) end the input with it."""
    error = ParseError(
        f"block longer than {MAX_BLOCK} characters without an end of block (LF): "
        "binary data or not an NC program?",
        file=file, line=line, column=1, clause="4",
    )
    if errors == "raise":
        raise error
    yield BadBlock(text[:80], line, error)


def parse_lines(data: str, line: int, dialect: Dialect, file: str | None,
                errors: Errors, end: _core.ReadingEnd | None = None) -> Iterator[Block]:
    """The blocks of ``data``, whole lines without the last LF, after line ``line``; with
    ``end``, the reading of the lines before (a line the control never reads is a block of its
    text alone)."""
    blocks, error = _core.parse_lines(data, line, dialect.flags, file, errors == "collect",
                                      end)
    yield from blocks
    if error is not None:
        raise error


def tokenize_block(text: str, dialect: Dialect = STRICT) -> tuple[list[str], BlockInfo]:
    """Word tokens and extras of one block's text; :class:`ParseError` (column set) if bad."""
    words, info, error = _core.tokenize_block(text, dialect.flags)
    if error is not None:
        raise error
    assert info is not None
    return words, info


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


def read_chunks(path: str, size: int = CHUNK, at: int = 0) -> Iterator[bytes]:
    """The bytes of the file at ``path`` from byte ``at``, ``size`` at a time (``at``: where
    the core's reading of a text file left off)."""
    with open(path, "rb") as f:
        if at:
            f.seek(at)
        while True:
            chunk = f.read(size)
            if not chunk:
                return
            yield chunk
