"""Fuzz target: ``tapegate convert --verify`` -- a file converted (``convert_file``) and the
output read back under the target profile and compared value by value (``formats.verify``).

The options are chosen as in ``fuzz/convert.py`` (its first three bytes); the program is
written to a file (text, or the program as an ISO or EIA tape image when byte 2 bits 3-4 say
so: the converter reads tape images too). What must hold: a verified conversion, or a
:class:`ConversionError`, :class:`DiffError` (the verification is ``formats.diff``'s) or
:class:`ParseError` naming the line -- a ParseError the file (the source, or ``fuzz.nc
(converted)``: an output the target profile cannot read), its column and rule code too. A
verification that refuses what the converter wrote is located; ``TAPEGATE_FUZZ_VERIFY_STRICT=1``
makes it a find (see docs/robustness.md).
"""

from __future__ import annotations

import os
import tempfile

from fuzz import _harness
from fuzz._harness import FILE, allowed, check
from fuzz.convert import options

with _harness.instrumented():
    from formats.convert import convert_file
    from formats.diff import DiffError
    from formats.errors import ConversionError, ParseError, TapeError
    from formats.tape import encode

FOLDER = tempfile.mkdtemp(prefix="tapegate-fuzz-")
SOURCE = os.path.join(FOLDER, FILE)
OUTPUT = os.path.join(FOLDER, "out.nc")
# A refusal by the verification is a located error; TAPEGATE_FUZZ_VERIFY_STRICT=1 makes it a
# find (the converter and the verification disagree on a program both accept).
STRICT = os.environ.get("TAPEGATE_FUZZ_VERIFY_STRICT") == "1"


def one_input(data: bytes) -> None:
    opts, body = options(data)
    tape = (data[2] >> 3) & 3 if len(data) > 2 else 0
    if tape in (1, 2):
        try:
            body = encode(body.decode("ascii", "ignore").upper(), "iso" if tape == 1 else "eia")
        except TapeError:
            return
    with open(SOURCE, "wb") as f:
        f.write(body)
    try:
        convert_file(SOURCE, OUTPUT, opts, overwrite=True, verify=True, display=FILE)
    except ParseError as exc:  # in the source, or in the output read back under the target
        allowed(exc, ParseError, line=True, column=True, code=True,
                file=(FILE, f"{FILE} (converted)"))
    except (ConversionError, DiffError) as exc:  # the verification is formats.diff's
        allowed(exc, (ConversionError, DiffError), line=True, file=(FILE, f"{FILE} (converted)",
                                                                    None))
        check(exc.clause != "verify" or not STRICT,
              f"the verification refuses the conversion: {exc}")


def seeds() -> list[bytes]:
    from fuzz.convert import seeds as convert_seeds

    return convert_seeds()


if __name__ == "__main__":
    _harness.main(one_input, seeds, max_seeds=150)
