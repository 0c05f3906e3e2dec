"""Fuzz target: machine profiles read from TOML text (``formats.profile.profile_from_text``),
and then used: a small program read, checked and converted under the profile.

The input is the TOML text (UTF-8, bad bytes replaced). What must hold: a :class:`ProfileError`
that names the profile's file (and, in its message, the key or the TOML line and column), or a
profile under which the program is read, checked and converted to and from the neutral profile,
with no error but a located :class:`ParseError` or :class:`ConversionError`.
"""

from __future__ import annotations

from fuzz import _harness
from fuzz._harness import FILE, allowed

with _harness.instrumented():
    from formats.convert import ConvertOptions, convert_text
    from formats.errors import ConversionError, ParseError, ProfileError
    from formats.parser import parse_text
    from formats.profile import NEUTRAL, profile_from_text
    from postproc.check import check_text

PROGRAM = ("%\nO1234 (PART)\nN10 G21 G90 G17 G40 G80\nN20 G00 X10. Y-5.5 Z2. S1200 M03 T1\n"
           "N30 G01 Z-1. F150.\nN40 G02 X20. Y-5.5 I5. J0\nN50 G91 X1 Y1\nN60 G04 P2.\n"
           "/N70 R11=22.2\nN80 M30\n%\n")


def one_input(data: bytes) -> None:
    text = data.decode("utf-8", "replace")
    try:
        profile = profile_from_text(text, source="fuzz.toml")
    except ProfileError as exc:
        allowed(exc, ProfileError, file="fuzz.toml")
        return
    profile.reset_state()
    for letter in "XFSNG":
        profile.word_format(letter, "inch")
    try:
        parse_text(PROGRAM, profile.dialect, file=FILE)
        check_text(PROGRAM, profile, file=FILE)
        convert_text(PROGRAM, ConvertOptions(target=profile, source=NEUTRAL), file=FILE)
        convert_text(PROGRAM, ConvertOptions(target=NEUTRAL, source=profile, units="inch"),
                     file=FILE)
        convert_text(PROGRAM, ConvertOptions(target=profile, source=profile, units="inch"),
                     file=FILE)
    except ParseError as exc:
        allowed(exc, ParseError, line=True, column=True, code=True, file=FILE)
    except ConversionError as exc:
        allowed(exc, ConversionError, line=True, file=(FILE, None))


def seeds() -> list[bytes]:
    import re

    out = _harness.builtin_profile_texts()
    doc = (_harness.ROOT / "docs/profiles.md").read_text("utf-8")
    out += [m.group(1).encode() for m in re.finditer(r"```toml\n(.*?)```", doc, re.S)]
    return out


if __name__ == "__main__":
    _harness.main(one_input, seeds)
