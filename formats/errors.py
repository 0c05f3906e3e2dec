"""One error type for the whole formats layer, always located.

Every user-facing error in tapegate names the file, line and column and, where one applies, the
clause of ISO 6983-1 (or the profile key) that the input breaks. Like ``tomllib``'s
``suffixed_err`` helper, positions are turned into text in exactly one place (:func:`locate` and
:meth:`TapegateError.__str__`) so every message looks the same.
"""

from __future__ import annotations


class TapegateError(ValueError):
    """A user error: bad input, bad profile, bad option. Never shown as a traceback."""

    def __init__(
        self,
        message: str,
        *,
        file: str | None = None,
        line: int | None = None,
        column: int | None = None,
        clause: str | None = None,
        code: str | None = None,
    ) -> None:
        super().__init__(message)
        self.message = message
        self.code = code  # the checker's rule for this error (e.g. "TG101"), where one applies
        self.file = file
        self.line = line
        self.column = column
        self.clause = clause

    def located(self, **where: object) -> TapegateError:
        """Fill in location fields that are still unknown (e.g. the file name) and return self."""
        for key, value in where.items():
            if getattr(self, key, None) is None and value is not None:
                setattr(self, key, value)
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
    """A program that cannot be read as ISO 6983-1 word-address text under the given profile."""


class FormatSpecError(TapegateError):
    """A classification string (Annex B or C) that is malformed or inconsistent."""


class ProfileError(TapegateError):
    """A machine profile that is missing, malformed, or has a bad value for a key."""


class TapeError(TapegateError):
    """Text that a tape code cannot carry, or tape bytes that cannot be decoded."""


class OutputError(TapegateError):
    """A file that cannot be written where the user asked: a missing folder, no permission, a
    full disk. Named by the file the user gave, never by a temporary name."""


class ConversionError(TapegateError):
    """A value that cannot be converted exactly (digit overflow, rounding refused, unknown unit)."""


def locate(text: str, offset: int) -> tuple[int, int]:
    """1-based (line, column) of ``offset`` in ``text``; lines end at LF as in ISO 6983-1."""
    line = text.count("\n", 0, offset) + 1
    column = offset - (text.rfind("\n", 0, offset) + 1) + 1
    return line, column
