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

All values are :class:`decimal.Decimal`; nothing here goes through a float. The digits are read
and written by the core (``crates/core/src/wordformat.rs`` and ``convert.rs``), the one
implementation of Annex C that the checker, the converter and the diff use too.
"""

from __future__ import annotations

from formats import _core
from formats.errors import ConversionError
from formats.records import FrozenRecord, init_fields, record

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:  # the type checker reads the classes below as the enums they stand for
    from decimal import Decimal
    from enum import StrEnum as StrChoice
else:  # without enum's import (formats.choices)
    from formats.choices import StrChoice


class Zeros(StrChoice):
    """Which zeros an implicit-decimal word may omit (Annex C)."""

    LEADING = "leading"  # the recommended style: digits right-aligned
    TRAILING = "trailing"  # digits left-aligned, leading zeros written
    NONE = "none"  # every digit position written


class Rounding(StrChoice):
    """What to do with a value finer than the target resolution."""

    HALF_EVEN = "half-even"
    HALF_UP = "half-up"
    ERROR = "error"


@record
class WordFormat(FrozenRecord):
    """The Annex C format of one address."""

    __slots__ = ("address", "before", "after", "signed", "zeros", "decimal")
    address: str
    before: int  # decades before the decimal sign (count words: the maximum number of digits)
    after: int  # decades after the decimal sign (0 for count words)
    signed: bool  # "+" in the classification: the word may carry an algebraic sign
    zeros: Zeros
    decimal: bool  # a decimal (three-digit) spec rather than a count (two-digit) spec

    def __init__(self, address: str, before: int, after: int = 0, signed: bool = False,
                 zeros: Zeros = Zeros.LEADING, decimal: bool = True) -> None:
        init_fields(self, address, before, after, signed, zeros, decimal)

    @property
    def width(self) -> int:
        return self.before + self.after

    @property
    def resolution(self) -> Decimal:
        from decimal import Decimal  # (when first needed: not before a check's threads)

        return Decimal(1).scaleb(-self.after)

    @property
    def entry(self) -> tuple[str, int, int, bool, str, bool]:
        """The format as the core takes it."""
        return (self.address, self.before, self.after, self.signed, str(self.zeros),
                self.decimal)

    def spec(self) -> str:
        """The canonical Annex C text of this format, e.g. ``X+053`` or ``N03``."""
        sign = "+" if self.signed else ""
        digits = f"{self.before}{self.after}" if self.decimal else f"{self.before}"
        if self.zeros is Zeros.LEADING:
            digits = "0" + digits
        elif self.zeros is Zeros.TRAILING:
            digits = digits + "0"
        return f"{self.address}{sign}{digits}"

    def holds(self, value: Decimal) -> bool:
        """Whether ``value`` is a number with no more digits before the decimal sign than this
        format has: one the control can be sent (a value given by an operator, not read from
        the program, is not known to fit)."""
        return value.is_finite() and (not value or value.adjusted() < self.before)

    def read(self, sign: str, number: str, explicit_program: bool,
             increments: bool = False) -> Decimal:
        """The exact value of a word written as ``sign`` + ``number``.

        ``explicit_program`` says that the program uses the explicit decimal sign (the profile
        has DS): a number without ``.`` is then a whole number (6.1) -- or, with ``increments``,
        a count of the format's least increment, as a Fanuc reads ``X10000`` at 0.001 mm
        (10.000 mm). A number the format cannot hold is a :class:`ConversionError`.
        """
        from decimal import Decimal

        try:
            value = Decimal(_core.read_number(self.entry, number, explicit_program, increments))
        except ValueError as exc:  # the core's reason: too many digits for the format
            raise ConversionError(str(exc), clause="Annex C", code="conversion-format"
                                  ) from None
        return -value if sign == "-" else value

    def write(self, value: Decimal, explicit: bool, plus: bool = False) -> str:
        """The digits (with sign) to write after the address for a value already at this
        format's resolution, as the converter writes them.

        ``explicit`` writes a decimal sign (shortest exact form, whole values as ``10.``);
        otherwise implicit digits with this format's zero suppression. ``plus`` writes ``+``
        before a positive value (to keep a sign the source had written). A value of zero is
        ``0`` in every style (ISO 6983-1 6.1 and Annex C: written with at least one zero,
        ``X0`` whichever zeros are omitted).
        """
        if not self.decimal:  # a count: its whole digits
            units, after = int(value), 0
        elif explicit:  # exactly the value's digits
            exponent = value.as_tuple().exponent
            after = -exponent if isinstance(exponent, int) and exponent < 0 else 0
            units = int(value.scaleb(after))
        else:  # a count of the format's resolution
            units, after = int(value.scaleb(self.after).to_integral_value()), self.after
        return _core.write_number(self.entry, units, after, explicit, plus)


def count_format(address: str, digits: int = 0) -> WordFormat:
    """A plain count word (N, G, M...) used where a profile names no format for the address."""
    return WordFormat(address, before=digits or 9, after=0, decimal=False)
