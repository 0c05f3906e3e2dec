"""Remote program requests: what the operator punches from the control's keypad to ask the
gateway for a program, and how the name asked for becomes a file.

An operator at a control without a file browser asks for a program by punching a small request
program to the gateway, then puts the control in READ mode; the gateway answers on the next DC1.
The conventions of common DNC systems are understood by default:

* a comment ``(PRG=1234)`` anywhere in a short program;
* ``(/REQ name)``, optionally ``(/REQ name /BL 120)`` to restart from block N120;
* any program whose number is a request number (``O9999``), which must then name the program
  in one of those forms.

The patterns are regular expressions with the named groups ``program`` and (optionally)
``block``, and can be replaced in the gateway configuration. Recognition is pure: text in,
:class:`Request` (or ``None``, or :class:`BadRequest`) out.

**Confinement.** A requested name is a name inside the port's program folder, never a path out
of it: absolute names, ``..`` parts and symbolic links that resolve outside the folder are
refused (:class:`Forbidden`), whatever the request pattern let through.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass, field
from pathlib import Path, PurePosixPath

from formats.errors import TapegateError

DEFAULT_PATTERNS = (
    r"\(\s*PRG\s*=\s*(?P<program>[^)]*?)\s*\)",
    r"\(\s*/REQ\b\s*(?P<program>[^\s)]*)(?:\s+/BL\s*(?P<block>[^\s)]*))?\s*\)",
)
DEFAULT_EXTENSIONS = ("", ".nc", ".NC", ".txt", ".TXT", ".tap", ".TAP", ".min", ".MIN",
                      ".mpf", ".MPF", ".h", ".H", ".ngc", ".NGC")
_NAME = re.compile(r"[A-Za-z0-9_.\-/\\: ]+")


class BadRequest(TapegateError):
    """A request that cannot be understood (it names no program, or a block that is no
    number)."""

    default_code = "request-bad"


class NotFound(TapegateError):
    """No program of that name in the program folder."""

    default_code = "request-not-found"


class Forbidden(TapegateError):
    """The name reaches outside the program folder."""

    default_code = "request-forbidden"


@dataclass(frozen=True)
class RequestRules:
    numbers: tuple[str, ...] = ("O9999",)
    patterns: tuple[str, ...] = DEFAULT_PATTERNS
    max_chars: int = 2048  # a longer program is a program, not a request (unless numbered so)
    not_found_message: bool = False
    message_number: str = "O9998"
    extensions: tuple[str, ...] = DEFAULT_EXTENSIONS
    compiled: tuple[re.Pattern[str], ...] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "compiled", tuple(re.compile(p, re.IGNORECASE)
                                                   for p in self.patterns))


@dataclass(frozen=True)
class Request:
    program: str  # the name as asked for
    block: int | None = None  # restart from sequence number N<block>
    number: str | None = None  # the request program's own number


def recognise(head: str, chars: int, number: str | None,
              rules: RequestRules) -> Request | None:
    """The request in a punched program, ``None`` if it is an ordinary program.

    ``head`` is the start of the text received, ``chars`` its whole length and ``number`` its
    program number (``O9999``). Raises :class:`BadRequest` for a request that cannot be served.
    """
    numbered = number is not None and _same_number(number, rules.numbers)
    if not numbered and chars > rules.max_chars:
        return None
    text = head[:rules.max_chars] if not numbered else head
    for pattern in rules.compiled:
        m = pattern.search(text)
        if m is None:
            continue
        parts = m.groupdict()
        program = (parts.get("program") or "").strip()
        if not program:
            raise BadRequest(f"the request {m.group(0)!r} names no program")
        if not _NAME.fullmatch(program):
            raise BadRequest(f"the request {m.group(0)!r} names no program file")
        block = parts.get("block")
        # ASCII digits, as many as a sequence number has ("²" is a digit to str.isdigit, and
        # int() refuses both it and a number of 5,000 digits)
        if block is not None and not re.fullmatch(r"[Nn]?[0-9]{1,9}", block):
            raise BadRequest(f"the request {m.group(0)[:80]!r}: /BL needs a block number "
                             "such as /BL 120")
        return Request(program, int(block.lstrip("Nn")) if block is not None else None,
                       number if numbered else None)
    if numbered:
        raise BadRequest(f"request program {number} names no program: punch a comment such "
                         "as (PRG=1234) or (/REQ name)")
    return None


def program_key(text: str) -> tuple[str, int] | None:
    """A program number as (letter, value): ``O1234``, ``o1234``, ``:1234`` and ``1234`` are
    all ``("O", 1234)``; ``None`` for a name that is no program number."""
    m = re.fullmatch(r"\s*([A-Za-z:]?)\s*([0-9]{1,18})\s*", text)  # longer is no number
    if not m:
        return None
    letter = m.group(1).upper()
    return ("O" if letter in ("", ":") else letter, int(m.group(2)))


def _same_number(number: str, numbers: tuple[str, ...]) -> bool:
    wanted = program_key(number)
    return wanted is not None and any(program_key(n) == wanted for n in numbers)


def find_program(folder: Path, name: str,
                 extensions: tuple[str, ...] = DEFAULT_EXTENSIONS) -> Path:
    """The file in ``folder`` that ``name`` asks for.

    Tried in order: the name as given, then with each extension; a number (``1234``, ``O1234``)
    is also tried as ``O1234`` and ``O0012``-style padded names, and case is ignored where the
    exact name is missing. Raises :class:`Forbidden` for any name that would reach outside the
    folder and :class:`NotFound` when nothing matches.
    """
    root = Path(os.path.realpath(folder))
    asked = name.strip().replace("\\", "/")
    pure = PurePosixPath(asked)
    if (not asked or "\x00" in asked or pure.is_absolute() or ".." in pure.parts
            or re.match(r"[A-Za-z]:", asked)):
        raise Forbidden(f"program {name!r} is not a name inside the program folder")
    for candidate in _candidates(asked, extensions):
        path = root / candidate
        found = path if os.path.lexists(path) else _ignoring_case(root, candidate)
        if found is None:
            continue
        real = Path(os.path.realpath(found))
        if real != root and root not in real.parents:
            raise Forbidden(f"program {name!r} is a link to outside the program folder")
        if real.is_file():
            return real
    raise NotFound(f"no program {name!r} in the program folder")


def _candidates(name: str, extensions: tuple[str, ...]) -> list[str]:
    stems = [name]
    m = re.fullmatch(r"([Oo:]?)([0-9]{1,18})", name)
    if m:
        digits = m.group(2)
        for stem in (f"O{digits}", f"O{int(digits):04d}", digits, f"{int(digits)}"):
            if stem not in stems:
                stems.append(stem)
    out: list[str] = []
    for stem in stems:
        for ext in extensions:
            if stem + ext not in out:
                out.append(stem + ext)
    return out


def _ignoring_case(root: Path, candidate: str) -> Path | None:
    path = root / candidate
    parent = Path(os.path.realpath(path.parent))
    if parent != root and root not in parent.parents:
        return None
    try:
        entries = os.listdir(parent)
    except OSError:
        return None
    wanted = path.name.lower()
    for entry in sorted(entries):
        if entry.lower() == wanted:
            return parent / entry
    return None


def message_program(number: str, text: str) -> list[str]:
    """A short program whose comment tells the operator at the control what happened
    (``PROGRAM 1234 NOT FOUND``), in characters every tape code carries."""
    words = re.sub(r"[^A-Z0-9 ]+", " ", text.upper())
    words = re.sub(r"\s+", " ", words).strip()[:60]
    return ["%", f"{number} ({words})", "M30", "%"]
