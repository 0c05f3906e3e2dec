"""One error type for the whole of tapegate, always located, always with a code.

Every user-facing error in tapegate names the file, line and column and, where one applies, the
clause of ISO 6983-1 (or the profile key) that the input breaks. As ``tomllib`` keeps ``msg``,
``pos``, ``lineno`` and ``colno`` on its ``TOMLDecodeError``, a :class:`TapegateError` keeps
what went wrong and where as fields:

* ``code``: a stable code (``docs/errors.md``): the checker's rule (``TG101``) for a block
  that cannot be read, otherwise a name such as ``profile-unknown-key``. Each class has a
  default code, and a raise that knows more gives a finer one. Code compares codes, never
  message text;
* ``file``, ``line``, ``column``: where, as far as it is known;
* ``clause``: the clause of ISO 6983-1 (or the part of tapegate) the input breaks;
* ``key``: the profile or configuration key at fault (``serial.baud``, ``port[1].profile``).

Positions are turned into text in exactly one place (:func:`locate` and
:meth:`TapegateError.__str__`), so every message looks the same.
"""

from __future__ import annotations

from formats import _core

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from typing import ClassVar


class TapegateError(ValueError):
    """A user error: bad input, bad profile, bad option. Never shown as a traceback."""

    default_code: ClassVar[str] = "error"
    unknown_key_code: ClassVar[str] = "unknown-key"  # a table key nobody reads (Keys)

    def __init__(
        self,
        message: str,
        *,
        code: str | None = None,
        file: str | None = None,
        line: int | None = None,
        column: int | None = None,
        clause: str | None = None,
        key: str | None = None,
    ) -> None:
        super().__init__(message)
        self.message = message
        self.code: str = code or self.default_code
        self.file = file
        self.line = line
        self.column = column
        self.clause = clause
        self.key = key

    def located(self, **where: object) -> TapegateError:
        """Fill in location fields that are still unknown (e.g. the file name) and return self."""
        for name, value in where.items():
            if getattr(self, name, None) is None and value is not None:
                setattr(self, name, value)
        return self

    @property
    def where(self) -> str:
        parts = [self.file or "<input>"]
        if self.line is not None:
            parts.append(str(self.line))
            if self.column is not None:
                parts.append(str(self.column))
        return ":".join(parts)

    def __str__(self) -> str:
        clause = f" [{self.clause}]" if self.clause else ""
        return f"{self.where}: {self.message}{clause}"


class ParseError(TapegateError):
    """A program that cannot be read as ISO 6983-1 word-address text under the given profile.
    Its code is the checker's rule for such a block (``TG100``: a word or expression that
    cannot be read; ``TG101`` a character, ``TG120``/``TG121`` comments and brackets, ...)."""

    default_code = _core.rule_id("Unreadable")


class FormatSpecError(TapegateError):
    """A classification string (Annex B or C) that is malformed or inconsistent."""

    default_code = "classification"


class ProfileError(TapegateError):
    """A machine profile that is missing, malformed, or has a bad value for a key."""

    default_code = "profile-value"  # a key with a value the profile cannot have
    unknown_key_code = "profile-unknown-key"


class TapeError(TapegateError):
    """Text that a tape code cannot carry, or tape bytes that cannot be decoded."""

    default_code = "tape"


class OutputError(TapegateError):
    """A file that cannot be written where the user asked: a missing folder, no permission, a
    full disk. Named by the file the user gave, never by a temporary name."""

    default_code = "output"


class ConversionError(TapegateError):
    """A value that cannot be converted exactly (digit overflow, rounding refused, unknown unit)."""

    default_code = "conversion"


def locate(text: str, offset: int) -> tuple[int, int]:
    """1-based (line, column) of ``offset`` in ``text``; lines end at LF as in ISO 6983-1."""
    line = text.count("\n", 0, offset) + 1
    column = offset - (text.rfind("\n", 0, offset) + 1) + 1
    return line, column
