"""Fuzz target: comparing two programs as NC (``formats.diff``: ``tapegate diff``).

Byte 0: bits 0-2 A's profile, bits 3-5 B's, bit 6 motion compared, bit 7 comments ignored.
Byte 1: bits 0-1 the pairing (auto, number, position, auto), bit 2 a tolerance of half a step,
bit 3 bad blocks compared as text (``errors="collect"``), bit 4 the first number stretched to
over 5,000 digits. The rest is program A, then, after a
line ``--``, program B (without one, B is A). What must hold: the differences, with a summary;
or a :class:`ParseError` naming the file, line, column and rule code, or a :class:`DiffError`
or :class:`ConversionError` naming the file and line. A program compared with itself under the
same profile is the same.
"""

from __future__ import annotations

from decimal import Decimal

from fuzz import _harness
from fuzz._harness import allowed, check

with _harness.instrumented():
    from formats.diff import Differ, DiffError, DiffOptions, ProgramReader
    from formats.errors import ConversionError, ParseError
    from formats.parser import decode_chunks, parse_stream

PROFILES = _harness.profiles()
PAIRS = ("auto", "number", "position", "auto")


def blocks(text: str, profile: object, name: str, options: DiffOptions) -> object:
    reader = ProgramReader(profile, file=name, options=options)  # type: ignore[arg-type]
    return reader.read(parse_stream([text], profile.dialect, file=name,  # type: ignore[attr-defined]
                                    errors=options.errors))


def one_input(data: bytes) -> None:
    head = data[:2].ljust(2, b"\0")
    a, b = head
    text = "".join(decode_chunks([_harness.stretch(data[2:]) if b & 16 else data[2:]]))
    left, sep, right = text.partition("\n--\n")
    if not sep:
        right = left
    prof_a = PROFILES[(a & 7) % len(PROFILES)]
    prof_b = PROFILES[((a >> 3) & 7) % len(PROFILES)]
    options = DiffOptions(tolerance=Decimal("0.5") if b & 4 else Decimal(0),
                          ignore_comments=bool(a & 128), motion=bool(a & 64),
                          pair=PAIRS[b & 3], errors="collect" if b & 8 else "raise")  # type: ignore[arg-type]
    differ = Differ(options, prof_b)
    try:
        found = list(differ.run(blocks(left, prof_a, "a.nc", options),  # type: ignore[arg-type]
                                blocks(right, prof_b, "b.nc", options)))  # type: ignore[arg-type]
        for item in found:
            item.describe("a.nc", "b.nc")
            item.as_json()
        differ.summary.as_json()
    except ParseError as exc:
        allowed(exc, ParseError, line=True, column=True, code=True)
        check(exc.file in ("a.nc", "b.nc"), f"{exc} names no file")
        return
    except (DiffError, ConversionError) as exc:
        allowed(exc, (DiffError, ConversionError), line=True)
        check(exc.file in ("a.nc", "b.nc"), f"{exc} names no file")
        return
    if not sep and prof_a is prof_b and (found or not differ.summary.same):
        shown = found[0].describe("a.nc", "b.nc") if found else differ.summary
        raise _harness.Find(f"a program differs from itself: {shown}")


def seeds() -> list[bytes]:
    return [bytes([(i * 9) % 256 & ~0x38 | ((i * 9) % 8) << 3, i % 16]) + piece
            for i, piece in enumerate(_harness.pieces())]


if __name__ == "__main__":
    _harness.main(one_input, seeds, max_seeds=150)
