"""Fuzz target: reading a program under every built-in profile (and the neutral one), in both
error modes, from the bytes of a file arriving in chunks of several sizes.

Byte 0 selects: bits 0-2 the profile (``_harness.profiles()``, modulo their number), bit 3 the
error mode (``raise`` / ``collect``), bits 4-5 the chunk size (whole, 5, 64 or 1024 bytes),
bit 6 the first number stretched to over 5,000 digits (``_harness.stretch``). The rest is the
file. What must hold:

* ``raise``: a :class:`ParseError` with the file, line, column and rule code, or blocks that
  print back to the very text read (lossless), whose counts ``count_blocks`` gives too, and
  whose plain words have a value or a located :class:`ConversionError`;
* ``collect``: no error at all; every bad block carries a located :class:`ParseError`;
* the same blocks (or the same error) whatever the chunk size.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from fuzz import _harness
from fuzz._harness import FILE, allowed, check

with _harness.instrumented():
    from formats.errors import ConversionError, ParseError
    from formats.parser import BadBlock, count_blocks, decode_chunks, parse_stream
    from formats.printer import print_blocks
    from formats.profile import Profile

if TYPE_CHECKING:
    from formats.parser import Errors

PROFILES = _harness.profiles()
SIZES = (0, 5, 64, 1024)


def read(data: bytes, size: int, profile: Profile, errors: Errors) -> object:
    """The blocks as (line, text, words), or the error as (line, column, code)."""
    chunks = decode_chunks(_harness.split(data, size) if size else [data])
    try:
        blocks = list(parse_stream(chunks, profile.dialect, file=FILE, errors=errors))
    except ParseError as exc:
        check(errors == "raise", f"errors='collect' raised {exc!r}")
        allowed(exc, ParseError, line=True, column=True, code=True, file=FILE)
        return ("error", exc.line, exc.column, exc.code)
    return blocks


def one_input(data: bytes) -> None:
    if not data:
        return
    selector, body = data[0], data[1:]
    profile = PROFILES[(selector & 7) % len(PROFILES)]
    errors: Errors = "collect" if selector & 8 else "raise"
    size = SIZES[(selector >> 4) & 3]
    if selector & 64:
        body = _harness.stretch(body)
    blocks = read(body, size, profile, errors)
    whole = read(body, 0, profile, errors) if size else blocks
    if isinstance(blocks, tuple) or isinstance(whole, tuple):
        check(blocks == whole, f"chunks of {size} bytes read {blocks!r}, the whole file {whole!r}")
        return
    assert isinstance(blocks, list) and isinstance(whole, list)
    check([(b.line, b.text, b.words) for b in blocks] == [(b.line, b.text, b.words) for b in whole],
          f"chunks of {size} bytes read other blocks than the whole file")
    text = "".join(decode_chunks([body]))
    bad = [b for b in blocks if isinstance(b, BadBlock)]
    for b in bad:
        allowed(b.error, ParseError, line=True, column=True, code=True, file=FILE)
    if bad:
        return
    check("".join(print_blocks(blocks)) == text, "the blocks do not print back to the text read")
    if errors == "raise":
        counts = count_blocks([text], profile.dialect, file=FILE)
        check(counts == (len(blocks), sum(len(b.words) for b in blocks),
                         sum(len(b.comments) for b in blocks)),
              f"count_blocks says {counts}")
    for b in blocks[:20]:
        for word in b.word_objects():
            if word.expression or word.address in ":#" or not word.number.strip("."):
                continue
            try:
                profile.value(word.token)
            except ConversionError as exc:
                allowed(exc, ConversionError, clause=True)


def seeds() -> list[bytes]:
    return [bytes([i % 128]) + piece for i, piece in enumerate(_harness.pieces())]


if __name__ == "__main__":
    _harness.main(one_input, seeds)
