"""Word formats of the detailed format classification (ISO 6983-1 Annex C) and exact number I/O.

A word format says how the digits after an address are to be read and written:

* **decimal words** (dimension words, I J K, F, S...) have digits before and after an implicit
  decimal sign, e.g. ``X+053`` (signed, 5.3, leading zeros omitted) or ``X+530`` (5.3, trailing
  zeros omitted);
* **count words** (N, G, M, T...) have a maximum number of digits, e.g. ``N03`` (three digits,
  leading zeros omitted).

Reading an implicit-decimal value depends on which zeros are omitted (Annex C): with leading zeros
omitted the digits are right-aligned and the last ``after`` digits are decimals (``X1030`` under
5.3 is 1.030); with trailing zeros omitted the digits are left-aligned in the ``before + after``
positions (``X1030`` is 10300.000). Explicit-decimal words (with ``.``) are read as written, and in
an explicit-decimal program a word without ``.`` is a whole number (6.1).

All values are :class:`decimal.Decimal`; nothing here goes through a float.
"""

from __future__ import annotations

from dataclasses import dataclass
from decimal import ROUND_HALF_EVEN, ROUND_HALF_UP, Decimal
from enum import StrEnum

from formats.errors import ConversionError

# Significant digits of a number, as the core reads them (crates/core/src/decimal.rs).
MAX_DIGITS = 38


class Zeros(StrEnum):
    """Which zeros an implicit-decimal word may omit (Annex C)."""

    LEADING = "leading"  # the recommended style: digits right-aligned
    TRAILING = "trailing"  # digits left-aligned, leading zeros written
    NONE = "none"  # every digit position written


class Rounding(StrEnum):
    """What to do with a value finer than the target resolution."""

    HALF_EVEN = "half-even"
    HALF_UP = "half-up"
    ERROR = "error"


_DECIMAL_ROUNDING = {Rounding.HALF_EVEN: ROUND_HALF_EVEN, Rounding.HALF_UP: ROUND_HALF_UP}


@dataclass(frozen=True, slots=True)
class WordFormat:
    """The Annex C format of one address."""

    address: str
    before: int  # decades before the decimal sign (count words: the maximum number of digits)
    after: int = 0  # decades after the decimal sign (0 for count words)
    signed: bool = False  # "+" in the classification: the word may carry an algebraic sign
    zeros: Zeros = Zeros.LEADING
    decimal: bool = True  # a decimal (three-digit) spec rather than a count (two-digit) spec

    @property
    def width(self) -> int:
        return self.before + self.after

    @property
    def resolution(self) -> Decimal:
        return Decimal(1).scaleb(-self.after)

    @property
    def largest(self) -> Decimal:
        """The largest magnitude the format can hold."""
        return (Decimal(10) ** self.before - 1) + (1 - self.resolution if self.after else 0)

    def spec(self) -> str:
        """The canonical Annex C text of this format, e.g. ``X+053`` or ``N03``."""
        sign = "+" if self.signed else ""
        digits = f"{self.before}{self.after}" if self.decimal else f"{self.before}"
        if self.zeros is Zeros.LEADING:
            digits = "0" + digits
        elif self.zeros is Zeros.TRAILING:
            digits = digits + "0"
        return f"{self.address}{sign}{digits}"

    # -- reading ---------------------------------------------------------------------------

    def read(self, sign: str, number: str, explicit_program: bool,
             increments: bool = False) -> Decimal:
        """The exact value of a word written as ``sign`` + ``number``.

        ``explicit_program`` says that the program uses the explicit decimal sign (the profile
        has DS): a number without ``.`` is then a whole number (6.1) -- or, with ``increments``,
        a count of the format's least increment, as a Fanuc reads ``X10000`` at 0.001 mm
        (10.000 mm).
        """
        digits = len(number) - number.count(".")
        if digits - (len(number) - len(number.lstrip("0."))) > MAX_DIGITS:
            raise ConversionError(f"{digits} digits: more than the {MAX_DIGITS} significant "
                                  "digits tapegate reads in a number", clause="Annex C")
        # Digits go to Decimal straight from the text, never through int(): a word may carry
        # any number of leading zeros (X, 5,000 zeros, 1), beyond int()'s 4,300-digit guard.
        if "." in number:
            value = Decimal(number if number[0] != "." else "0" + number)
        elif increments and self.decimal:
            value = _whole(number).scaleb(-self.after)
        elif explicit_program or not self.decimal:
            value = _whole(number)
            if not self.decimal and self.zeros is Zeros.TRAILING and len(number) < self.before:
                value = _whole(number.ljust(self.before, "0"))
        else:
            value = self.read_implicit(number)
        return -value if sign == "-" else value

    def read_implicit(self, digits: str) -> Decimal:
        """Unsigned value of implicit-decimal ``digits`` under this format (Annex C)."""
        if self.zeros is Zeros.TRAILING:
            if len(digits) > self.width:
                raise ConversionError(
                    f"{self.address}{digits} has {len(digits)} digits; the format "
                    f"{self.spec()} holds {self.width}",
                    clause="Annex C",
                )
            return _whole(digits.ljust(self.width, "0")).scaleb(-self.after)
        return _whole(digits).scaleb(-self.after)

    # -- writing ---------------------------------------------------------------------------

    def quantize(self, value: Decimal, rounding: Rounding = Rounding.HALF_EVEN) -> Decimal:
        """``value`` at this format's resolution; :class:`ConversionError` if it does not fit."""
        step = self.resolution
        if rounding is Rounding.ERROR:
            exact = value.quantize(step, rounding=ROUND_HALF_EVEN)
            if exact != value:
                raise ConversionError(
                    f"{self.address}: {value} is finer than the resolution {step} of "
                    f"{self.spec()} and rounding is not allowed",
                    clause="Annex C",
                )
            result = exact
        else:
            result = value.quantize(step, rounding=_DECIMAL_ROUNDING[rounding])
        self.check_fits(result)
        return result

    def check_fits(self, value: Decimal) -> None:
        integer_digits = len(str(int(abs(value)))) if abs(value) >= 1 else 0
        if integer_digits > self.before:
            raise ConversionError(
                f"{self.address}{value} needs {integer_digits} digits before the decimal sign; "
                f"the format {self.spec()} holds {self.before} (digit overflow)",
                clause="Annex C",
            )

    def write(self, value: Decimal, explicit: bool, plus: bool = False) -> str:
        """The digits (with sign) to write after the address for an already quantized value.

        ``explicit`` writes a decimal sign (shortest exact form, whole values as ``10.``);
        otherwise implicit digits with this format's zero suppression. ``plus`` writes ``+``
        before a positive value (to keep a sign the source had written).
        """
        sign = "-" if value < 0 else ("+" if plus and value > 0 else "")
        magnitude = abs(value)
        if not self.decimal:
            digits = str(int(magnitude))
            if self.zeros is Zeros.NONE:
                digits = digits.rjust(self.before, "0")
            elif self.zeros is Zeros.TRAILING:
                digits = digits.rjust(self.before, "0").rstrip("0") or "0"
            return sign + digits
        if explicit:
            return sign + format_explicit(magnitude)
        units = int(magnitude.scaleb(self.after).to_integral_value())
        if units == 0:
            return "0"
        if self.zeros is Zeros.LEADING:
            return sign + str(units)
        full = str(units).rjust(self.width, "0")
        if self.zeros is Zeros.TRAILING:
            full = full.rstrip("0")
        return sign + full


def _whole(digits: str) -> Decimal:
    """The whole number ``digits`` (ASCII digits) as an exact Decimal with exponent 0, as
    ``Decimal(int(digits))`` but with no limit on the leading zeros."""
    if not digits.isascii() or not digits.isdigit():
        raise ConversionError(f"{digits!r} is not a number", clause="Annex C")
    return Decimal(digits.lstrip("0") or "0")


def format_explicit(magnitude: Decimal) -> str:
    """Shortest explicit-decimal text of a value >= 0: ``12.5``, ``0.03``, ``10.``, ``0``."""
    if magnitude == 0:
        return "0"
    text = f"{magnitude.normalize():f}"
    if "." in text:
        return text
    return text + "."


def count_format(address: str, digits: int = 0) -> WordFormat:
    """A plain count word (N, G, M...) used where a profile names no format for the address."""
    return WordFormat(address, before=digits or 9, after=0, decimal=False)
