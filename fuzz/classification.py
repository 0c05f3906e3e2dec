"""Fuzz target: the Annex B and Annex C classification strings (``formats.classification``).

Byte 0 bit 0 selects Annex B (``GeneralClassification``) or Annex C
(``DetailedClassification``); the rest is the string (UTF-8, bad bytes replaced). What must
hold: a classification that prints to a string reading back as the same classification, whose
table (``explain``) can be made; or a :class:`FormatSpecError` that names the clause.
"""

from __future__ import annotations

from fuzz import _harness
from fuzz._harness import allowed, check

with _harness.instrumented():
    from formats.classification import DetailedClassification, GeneralClassification
    from formats.errors import FormatSpecError


def one_input(data: bytes) -> None:
    if not data:
        return
    kind = DetailedClassification if data[0] & 1 else GeneralClassification
    text = data[1:].decode("utf-8", "replace")
    try:
        parsed = kind.parse(text)
    except FormatSpecError as exc:
        allowed(exc, FormatSpecError, clause=True)
        return
    printed = str(parsed)
    check(kind.parse(printed) == parsed, f"{text!r} prints as {printed!r}, read back otherwise")
    parsed.explain()


def seeds() -> list[bytes]:
    import re
    import tomllib

    out = []
    texts = [p.decode() for p in _harness.builtin_profile_texts()]
    for doc in ("docs/profiles.md", "docs/formats.md", "README.md"):
        texts.append((_harness.ROOT / doc).read_text("utf-8"))
    for text in texts[:6]:
        data = tomllib.loads(text)
        for key in ("general", "detailed", "detailed_inch"):
            if key in data:
                out.append(bytes([key != "general"]) + data[key].encode())
    for text in texts[6:]:
        for m in re.finditer(r"'([PLDC][MIN] ?\d{3})'|'(%?:?/?(?:DS)? ?[A-Z][^'\n]*\*[^'\n]*)'",
                             text):
            out.append(bytes([m.group(1) is None]) + (m.group(1) or m.group(2)).encode())
    return out


if __name__ == "__main__":
    _harness.main(one_input, seeds)
