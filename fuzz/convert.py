"""Fuzz target: converting a program held in memory (``formats.convert.convert_text``), every
combination of source and target profile, units, decimal style, rounding, spacing and end of
block.

Byte 0: bits 0-2 the source profile, bits 3-5 the target, bits 6-7 the units (keep, metric,
inch, keep). Byte 1: bits 0-1 the decimal style (target's, explicit, implicit, target's),
bits 2-3 the rounding, bits 4-5 the spacing, bit 6 the end of block (target's or CR LF), bit 7
unconverted parameters allowed. Byte 2: bit 0 detect the source instead of naming it, bits 1-2
the source's reading (its own, explicit, implicit, increments), bit 5 the first number of
the program stretched to over 5,000 digits. The rest is the program. What
must hold: converted text, or a :class:`ConversionError` or :class:`ParseError` that names the
line (a ParseError its column and rule code too).
"""

from __future__ import annotations

from fuzz import _harness
from fuzz._harness import FILE, allowed

with _harness.instrumented():
    from formats.convert import ConvertOptions, convert_text
    from formats.errors import ConversionError, ParseError
    from formats.parser import decode_chunks
    from formats.wordformat import Rounding

PROFILES = _harness.profiles()
UNITS = (None, "metric", "inch", None)
DECIMAL = (None, "explicit", "implicit", None)
ROUNDING = (Rounding.HALF_EVEN, Rounding.HALF_UP, Rounding.ERROR, Rounding.HALF_EVEN)
SPACING = ("keep", "remove", "insert", "keep")
FROM = (None, "explicit", "implicit", "increments")


def options(data: bytes) -> tuple[ConvertOptions, bytes]:
    head = data[:3].ljust(3, b"\0")
    a, b, c = head
    source = PROFILES[(a & 7) % len(PROFILES)]
    target = PROFILES[((a >> 3) & 7) % len(PROFILES)]
    # (a target of G code system B or C refuses a detected source: ConvertOptions)
    detected = c & 1 and target.g_code_system not in ("B", "C")
    return ConvertOptions(
        target=target,
        source=None if detected else source,
        units=UNITS[a >> 6], decimal=DECIMAL[b & 3], rounding=ROUNDING[(b >> 2) & 3],
        spacing=SPACING[(b >> 4) & 3], eob="crlf" if b & 64 else None,
        allow_unconverted=bool(b & 128), from_decimal=FROM[(c >> 1) & 3],
    ), _harness.stretch(data[3:]) if c & 32 else data[3:]


def one_input(data: bytes) -> None:
    opts, body = options(data)
    text = "".join(decode_chunks([body]))
    try:
        convert_text(text, opts, file=FILE)
    except ParseError as exc:
        allowed(exc, ParseError, line=True, column=True, code=True, file=FILE)
    except ConversionError as exc:  # the parameter analysis knows the line, not the file
        allowed(exc, ConversionError, line=True, file=(FILE, None))


def seeds() -> list[bytes]:
    out = []
    for i, piece in enumerate(_harness.pieces()):
        out.append(bytes([(i * 37) % 256, (i * 11) % 256, (i // 7) % 8]) + piece)
    return out


if __name__ == "__main__":
    _harness.main(one_input, seeds)
