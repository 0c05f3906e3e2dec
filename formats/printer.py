"""Blocks -> text. An unchanged block prints as its own text: the round trip is byte for byte.

:func:`replace_words` rewrites chosen words of a block in place, keeping everything around them
(spacing, comments, CR) exactly as written -- a conversion changes only what it was asked to.
"""

from __future__ import annotations

from formats.model import Block

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from collections.abc import Iterable, Iterator

FLUSH = 1 << 16


def print_blocks(blocks: Iterable[Block]) -> Iterator[str]:
    """Text in chunks of about 64 KiB (one string per block would be slow to write)."""
    return print_lines((block.text, block.info is None or block.info.eob) for block in blocks)


def print_lines(lines: Iterable[tuple[str, bool]], eob: str | None = None) -> Iterator[str]:
    """(block text, ends with an end of block) pairs -> text in chunks of about 64 KiB.

    ``eob`` None keeps each end of block as written (LF, with any CR kept in the text);
    otherwise every end of block becomes ``eob`` (the text's own trailing CRs dropped).
    """
    parts: list[str] = []
    size = 0
    for text, ends in lines:
        if not ends:
            parts.append(text)
            continue
        if eob is None:
            parts.append(text)
            parts.append("\n")
        else:
            parts.append(text.rstrip("\r"))
            parts.append(eob)
        size += len(text) + 1
        if size > FLUSH:
            yield "".join(parts)
            parts.clear()
            size = 0
    if parts:
        yield "".join(parts)


def program_text(blocks: Iterable[Block]) -> str:
    return "".join(print_blocks(blocks))


def token_span(text: str, start: int, token: str) -> int:
    """End offset of ``token`` written at ``start`` in ``text``, non-printing characters inside
    the word (``R11 = 22.2``) included."""
    i = start
    for ch in token:
        while i < len(text) and text[i] != ch and text[i] in " \t\r\x00\x7f":
            i += 1
        i += 1
    return i


def replace_words(block: Block, replacements: dict[int, str]) -> str:
    """The block's text with word ``i`` written as ``replacements[i]`` (the whole word, address
    included); everything else exactly as written."""
    if not replacements:
        return block.text
    text = block.text
    pieces: list[str] = []
    pos = 0
    for i, word in enumerate(block.word_objects()):
        if i not in replacements:
            continue
        start = word.column - 1
        end = token_span(text, start, word.token)
        pieces.append(text[pos:start])
        pieces.append(replacements[i])
        pos = end
    pieces.append(text[pos:])
    return "".join(pieces)
