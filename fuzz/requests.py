"""Fuzz target: remote program requests (``dnc.requests``): recognising a request in what a
control punched, finding the program it names in a folder, and the message program sent back.

Byte 0: bit 0 the punched program is numbered as a request (``O9999``), bit 1 its own number
is read from its text instead, bit 2 a short ``max_chars``. The rest is the punched text
(UTF-8, bad bytes replaced). What must hold: no request, a request whose program the folder
lookup answers with a file inside the folder or a :class:`NotFound` / :class:`Forbidden`, or
a :class:`BadRequest`; the message program for any text is carried by both tape codes.
"""

from __future__ import annotations

import os
import re
import tempfile
from pathlib import Path

from fuzz import _harness
from fuzz._harness import allowed, check

with _harness.instrumented():
    from dnc.requests import (
        BadRequest,
        Forbidden,
        NotFound,
        RequestRules,
        find_program,
        message_program,
        recognise,
    )
    from formats.tape import encode

FOLDER = Path(tempfile.mkdtemp(prefix="tapegate-fuzz-"))
for name in ("O1234.nc", "BRACKET.NC", "sub/part.nc", "0012"):
    (FOLDER / name).parent.mkdir(parents=True, exist_ok=True)
    (FOLDER / name).write_text("%\nO1234\nM30\n%\n")
os.symlink("/etc", FOLDER / "outside")
RULES = (RequestRules(), RequestRules(max_chars=16))


def one_input(data: bytes) -> None:
    if not data:
        return
    selector, text = data[0], data[1:].decode("utf-8", "replace")
    number: str | None = None
    if selector & 1:
        number = "O9999"
    elif selector & 2:
        m = re.search(r"[O:]\s*(\d+)", text)
        number = m.group(0) if m else None
    rules = RULES[(selector >> 2) & 1]
    try:
        request = recognise(text, len(text), number, rules)
    except BadRequest as exc:
        allowed(exc, BadRequest)
        request = None
    for name in ([request.program] if request else []) + [text[:200]]:
        try:
            found = find_program(FOLDER, name, rules.extensions)
        except (NotFound, Forbidden) as exc:
            allowed(exc, (NotFound, Forbidden))
            continue
        real = Path(os.path.realpath(FOLDER))
        check(real in found.parents and found.is_file(), f"{name!r} found {found} outside")
    lines = message_program("O9998", text)
    for code in ("iso", "eia"):
        encode("\n".join(lines) + "\n", code)  # type: ignore[arg-type]


def seeds() -> list[bytes]:
    heads = [b"%\nO9999 (PRG=1234)\nM30\n%\n", b"(PRG=BRACKET.NC)\n", b"(/REQ BRACKET)\n",
             b"%\n(/REQ O1234 /BL 120)\n%\n", b"O9999\nM30\n", b"(PRG=../etc/passwd)\n",
             b"(/REQ sub/part /BL N12)\n", b"(PRG=outside/hostname)\n", b"(PRG=12)\n"]
    out = [bytes([i % 8]) + h for i, h in enumerate(heads)]
    out += [bytes([i % 8]) + p[:300] for i, p in enumerate(_harness.corpus_programs())]
    return out


if __name__ == "__main__":
    _harness.main(one_input, seeds)
