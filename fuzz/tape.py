"""Fuzz target: punched-tape codes, ``tapegate tape encode`` and ``decode`` (``formats.tape``).

Byte 0: bit 0 encode (else decode), bits 1-2 the code (ISO, EIA, detected, ISO), bits 3-4 the
chunk size of the streaming functions (whole, 1, 5 or 300), bit 5 an ISO decoder that does not
check parity (a UART did), bits 6-7 leader and trailer length. The rest is the text to encode
(UTF-8, other bytes kept as they are) or the tape image to decode. What must hold:

* encode: tape bytes that decode back to the text (less what a tape does not carry: NUL and
  DEL fill; under EIA CR next to LF, and any other CR read back as LF; an ISO control code
  other than TAB, LF, CR reads as U+FFFD, an illegal code) or a :class:`TapeError` naming
  the line and column of a character the code cannot carry; the same, byte for byte or line
  and column, when the text arrives in chunks;
* decode: never an error; every byte kept or counted as fill; every issue at the byte offset,
  line and column where its byte is, in order; the same text, fill and issues in chunks.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from fuzz import _harness
from fuzz._harness import allowed, check

with _harness.instrumented():
    from formats.errors import TapeError, locate
    from formats.parser import decode_chunks
    from formats.tape import TapeDecoder, decode, decode_stream, encode, encode_stream

if TYPE_CHECKING:
    from formats.tape import Code

CODES: tuple[Code | None, ...] = ("iso", "eia", None, "iso")
SIZES = (0, 1, 5, 300)


def is_fill(byte: int, code: str) -> bool:
    return (byte & 0x7F if code == "iso" else byte) in (0x00, 0x7F)


def eia_lines(text: str) -> str:
    """``text`` with its line ends as EIA writes them: CRs next to LF dropped, any other CR an
    end of block."""
    return re.sub(r"\r*\n\r*", "\n", text).replace("\r", "\n")


def expected_text(text: str, code: str) -> str:
    """What a tape of ``text`` decodes to."""
    if code == "eia":
        return eia_lines(text).replace("\x00", "").replace("\x7f", "")
    text = text.replace("\x00", "").replace("\x7f", "")
    return "".join("\ufffd" if ch < " " and ch not in "\t\n\r" else ch for ch in text)


def one_input(data: bytes) -> None:
    if not data:
        return
    selector, body = data[0], data[1:]
    code = CODES[(selector >> 1) & 3]
    size = SIZES[(selector >> 3) & 3]
    if selector & 1:
        encoding(body, code or "eia", size, (selector >> 6) * 3)
    else:
        decoding(body, code, size, parity=not selector & 32)


def encoding(body: bytes, code: Code, size: int, leader: int) -> None:
    text = "".join(decode_chunks([body]))
    chunks = [text[i:i + size] for i in range(0, len(text), size)] if size else [text]
    try:
        tape = encode(text, code, leader=leader, trailer=leader, file="fuzz.nc")
    except TapeError as exc:
        allowed(exc, TapeError, line=True, column=True, clause=True, file="fuzz.nc")
        assert exc.line is not None and exc.column is not None
        lines = (eia_lines(text) if code == "eia" else text).split("\n")
        check(exc.line <= len(lines) and exc.column <= len(lines[exc.line - 1]),
              f"{exc} is outside the text")
        bad = lines[exc.line - 1][exc.column - 1]
        if bad == "%" and code == "eia":  # ER, the rewind stop, only where a line starts
            check(exc.column > 1, f"{exc}, but '%' starts its line")
        else:
            try:
                encode(bad, code)
            except TapeError:
                pass
            else:
                raise _harness.Find(f"{exc}, but {bad!r} can be carried") from None
        try:
            b"".join(encode_stream(chunks, code, file="fuzz.nc"))
        except TapeError as streamed:
            check((streamed.line, streamed.column) == (exc.line, exc.column),
                  f"in chunks of {size}: {streamed}; whole: {exc}")
        else:
            raise _harness.Find(f"in chunks of {size} no error; whole: {exc}") from None
        return
    pieces = b"".join(encode_stream(chunks, code, leader=leader, trailer=leader))
    check(pieces == tape, f"in chunks of {size} the tape differs")
    decoded = decode(tape, code)
    check(decoded.text == expected_text(text, code), "the tape does not decode to the text")


def decoding(body: bytes, code: Code | None, size: int, parity: bool) -> None:
    whole = decode(body, code)
    check(len(whole.text) + whole.fill == len(body), "bytes lost in decoding")
    chunks = _harness.split(body, size) if size else [body]
    decoder, texts = decode_stream(iter(chunks), whole.code)
    check("".join(texts) == whole.text and decoder.fill == whole.fill
          and decoder.issues == whole.issues, f"in chunks of {size} the decoding differs")
    last = -1
    for issue in whole.issues:
        check(last <= issue.offset < len(body) and body[issue.offset] == issue.byte,
              f"issue at the wrong byte: {issue}")
        last = issue.offset
        before = issue.offset - sum(is_fill(b, whole.code) for b in body[:issue.offset])
        check(locate(whole.text, before) == (issue.line, issue.column),
              f"issue at line {issue.line}, column {issue.column}, but its character is at "
              f"{locate(whole.text, before)}: {issue}")
    if whole.code == "iso" and not parity:
        plain = TapeDecoder("iso", parity=False)
        text = "".join(plain.feed(chunk) for chunk in chunks)
        check(text == whole.text and all(i.kind == "illegal" for i in plain.issues)
              and [i for i in whole.issues if i.kind == "illegal"] == plain.issues,
              "the decoder without parity differs")


def seeds() -> list[bytes]:
    out = []
    for i, piece in enumerate(_harness.pieces(300)):
        text = piece.decode("ascii", "ignore")
        out.append(bytes([(i * 2 + 1) % 256]) + piece)  # encode
        codes: tuple[Code, Code] = ("iso", "eia")
        for n, code in enumerate(codes):
            try:
                tape = encode(text.upper(), code, leader=4)
            except TapeError:
                continue
            out.append(bytes([(n << 1) | ((i % 4) << 3) | (i % 2) << 5]) + tape)  # decode
    return out


if __name__ == "__main__":
    _harness.main(one_input, seeds)
