"""What a conversion is asked to do (:class:`ConvertOptions`) and what it did
(:class:`ConvertStats`): the data that :mod:`formats.convert` and :mod:`formats.verify` share.

A leaf of the two: the converter calls the proof, and the proof reads the options and the
roundings the converter reported, so neither imports the other.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from decimal import ROUND_UP, Decimal, localcontext
from fractions import Fraction

from formats.classification import DetailedClassification
from formats.profile import Profile
from formats.wordformat import Rounding, Zeros


@dataclass(frozen=True)
class ConvertOptions:
    """What to convert to. ``None`` for an override means "as the target profile says"."""

    target: Profile
    source: Profile | None = None  # None: detect from the program (see :func:`detect_source`)
    decimal: str | None = None  # "explicit" | "implicit"
    zeros: Zeros | None = None  # zero suppression of implicit-decimal words
    units: str | None = None  # "metric" | "inch": convert the units; None keeps them
    eob: str | None = None  # a key of EOB_STYLES
    rounding: Rounding = Rounding.HALF_EVEN
    spacing: str = "keep"  # keep | remove | insert
    allow_unconverted: bool = False  # leave unprovable parameters and P/Q/R words unconverted
    # How to read the source, over its profile: "explicit" (a word without a point is a whole
    # number), "implicit" (no decimal points: digits by the format), "increments" (a word
    # without a point counts least increments, as a Fanuc reads it); and its zero suppression.
    from_decimal: str | None = None
    from_zeros: Zeros | None = None

    def source_reading(self, source: Profile) -> tuple[Profile, list[str]]:
        """The source profile with the ``from_*`` overrides, and what they assume."""
        notes = []
        detailed, numbers, inch = source.detailed, source.numbers, source.detailed_inch
        if self.from_decimal is not None:
            explicit = self.from_decimal != "implicit"
            detailed = dataclasses.replace(detailed, explicit_decimal=explicit)
            if inch is not None:
                inch = dataclasses.replace(inch, explicit_decimal=explicit)
            increments = self.from_decimal == "increments"
            numbers = dataclasses.replace(
                numbers, without_point="increments" if increments else "whole")
            notes.append({
                "explicit": "source: decimal points as written, a word without one is a whole "
                            "number (--from-decimal explicit)",
                "implicit": "source: implicit decimal, digits read by the word formats of "
                            f"{source.name} (--from-decimal implicit)",
                "increments": "source: decimal points as written, a word without one counts "
                              "least increments of its format, X10000 = 10.000 at 0.001 "
                              "(--from-decimal increments)",
            }[self.from_decimal])
        if self.from_zeros is not None:
            zeros = self.from_zeros

            def rezero(d: DetailedClassification) -> DetailedClassification:
                formats = {k: dataclasses.replace(f, zeros=zeros) if f.decimal else f
                           for k, f in d.formats.items()}
                return dataclasses.replace(d, formats=formats)

            detailed = rezero(detailed)
            inch = None if inch is None else rezero(inch)
            notes.append(f"source: {zeros} zeros omitted in implicit-decimal words "
                         f"(--from-zeros {zeros})")
        if not notes:
            return source, notes
        return dataclasses.replace(source, detailed=detailed, numbers=numbers,
                                   detailed_inch=inch), notes

    def effective_target(self) -> Profile:
        """The target profile with the overrides applied: what the output must be read with."""
        target = self.target
        explicit = target.explicit if self.decimal is None else self.decimal == "explicit"

        def overridden(detailed: DetailedClassification) -> DetailedClassification:
            formats = dict(detailed.formats)
            if self.zeros is not None:
                formats = {k: dataclasses.replace(f, zeros=self.zeros) if f.decimal else f
                           for k, f in formats.items()}
            if explicit == detailed.explicit_decimal and formats == detailed.formats:
                return detailed
            return dataclasses.replace(detailed, formats=formats, explicit_decimal=explicit)

        detailed = overridden(target.detailed)
        inch = None if target.detailed_inch is None else overridden(target.detailed_inch)
        if detailed is target.detailed and inch is target.detailed_inch:
            return target
        return dataclasses.replace(target, detailed=detailed, detailed_inch=inch)


@dataclass
class ConvertStats:
    """What one conversion did, for the summary table and the closing report."""

    file: str = ""
    output: str = ""
    blocks: int = 0
    words: int = 0
    changed: int = 0
    rounding: dict[str, Fraction] = field(default_factory=dict)  # address -> largest |error|
    notes: list[str] = field(default_factory=list)
    error: str = ""
    verified: bool = False

    # the notes already made, for the test below: a list's ``in`` made a program with a note
    # per word (--allow-unconverted) quadratic, 23 s of 29 s at 20,000 blocks
    _noted: set[str] = field(default_factory=set, repr=False, compare=False)

    def note(self, text: str) -> None:
        if text not in self._noted:
            self._noted.add(text)
            self.notes.append(text)

    def largest_rounding(self) -> tuple[str, Decimal]:
        if not self.rounding:
            return "", Decimal(0)
        letter, value = max(self.rounding.items(), key=lambda kv: kv[1])
        return letter, _fraction_decimal(value)


def _fraction_decimal(value: Fraction) -> Decimal:
    """A rounding error for people: three significant digits, rounded up (never understated)."""
    with localcontext() as ctx:
        ctx.prec = 3
        ctx.rounding = ROUND_UP
        return (Decimal(value.numerator) / Decimal(value.denominator)).normalize()
