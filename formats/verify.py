"""Proof that a conversion kept every value: ``tapegate convert --verify``.

The proof is the NC comparison of :mod:`formats.diff`, not the converter's own arithmetic: the
source is read under the source profile, the output read back under the target profile (its own
word formats and number reading, not the converter's writer), and the two are compared block by
block, by position, in exact decimals in one unit system. Every value must be within half a step
of the target resolution of the source value, and within the largest rounding the converter
reported for its address; in G91 the axis words are compared as positions, so an incremental
path is proved, not only each step. The same blocks, the same words in the same order, the same
comments and the same modal state and end point after every block (from the core's modal state
machine, held at every block to the units, distance, feed and spindle modes the comparison reads
on its own). A word of the same value and format in both, written as its format writes it
(``G01``, ``T0101``, a block number), must be the same text byte for byte: the value comparison
takes ``G1`` for ``G01``. The first difference fails the file, named by its line in the source
(a block only in the output: by its line there, in ``FILE (converted)``).

A dialect's statements are compared too (the core's ``ncread::Reader::statement_words``): their
lengths by the converter's own table of roles, the rest as written. One holding a number of no
known role, read in other units in the output, is not compared: listed in
``ConvertStats.not_compared`` and noted, and the file is not "verified".
"""

from __future__ import annotations

import dataclasses
from decimal import Decimal, localcontext
from fractions import Fraction

from formats.conversion import ConvertOptions, ConvertStats
from formats.diff import BlockDiff, Differ, DiffOptions, diff_files, steps_text
from formats.errors import ConversionError
from formats.profile import Profile

HALF_STEP = Decimal("0.5")


def verify_options(stats: ConvertStats, options: ConvertOptions | None = None) -> DiffOptions:
    """How a conversion is compared with its source. With ``allow_unconverted``, a P/Q/R word
    whose role the source profile does not state was left as written, and is compared so. A
    LinuxCNC subroutine body is read in the units the converter read it in (its calls'), and
    in the output in the units converted to."""
    written = options is not None and options.allow_unconverted
    # a LinuxCNC body is read in its calls' units, as the converter read it; the output's
    # in the units converted to
    bodies = tuple(stats.body_units)
    units = options.units if options is not None else None
    return DiffOptions(tolerance=HALF_STEP, motion=True, pair="position", word_order=True,
                       bounds={letter: Fraction(num, den)
                               for letter, (num, den) in stats.rounding.items()},
                       parameters="address",
                       unstated="written" if written else "adopt", same_text=True,
                       bodies_a=bodies,
                       bodies_b=tuple((label, units) for label, _ in bodies) if units else bodies)


def assumed_units(source: Profile, options: ConvertOptions) -> str:
    """The units the proof reads the source in without anything to show them, or "": a source
    control that selects its units by a machine parameter (``units_codes = "none"``, an Okuma
    OSP lathe) whose setting was not given (``from_units``), where the output's reading
    depends on it (a change of units, or another profile: the converter reads the source in
    the profile's units, and so does the proof, so a program written for a machine set to the
    other units would be proved wrong the same way)."""
    if source.units_by_code or options.from_units is not None:
        return ""
    if options.units is None and options.target.name == source.name:
        return ""
    return source.default_units


def verify_conversion(source_path: str, output_path: str, source: Profile,
                      options: ConvertOptions, stats: ConvertStats, *, file: str) -> None:
    """Raise :class:`ConversionError` at the first difference between the source and the
    converted program."""
    target = options.effective_target()
    if not target.units_by_code:
        # no code in the output says its units: the machine's parameter does, set to the
        # units converted to (the converter says so in a note and in ``machine_units``:
        # `--units`, or without it the source program's own, an inch Haas program to an OSP
        # lathe), and the output is read in them
        units = options.units or stats.machine_units
        if units:
            target = dataclasses.replace(target, default_units=units)
    diff_options = verify_options(stats, options)
    differ = Differ(diff_options, target)
    for found in diff_files(source_path, output_path, source, target, diff_options,
                            name_a=file, name_b=f"{file} (converted)", differ=differ):
        if found.a is not None:  # named by its line in the source
            raise ConversionError(_message(found, file), file=file, line=found.a.line,
                                  clause="verify", code="conversion-verify")
        assert found.b is not None  # a block only in the output: named by its line there
        raise ConversionError(_message(found, file), file=f"{file} (converted)",
                              line=found.b.line, clause="verify", code="conversion-verify")
    for line, _, text in differ.unread():
        stats.not_compared.append((line, text))
        stats.note(f"line {line}: statement {text!r} not compared: it holds a number the "
                   "proof reads by no role (none in tapegate's table, or a call's argument "
                   "converted by the parameter analysis), in other units in the output, so it "
                   "cannot tell whether the number is right")


def _message(found: BlockDiff, file: str) -> str:
    """The first value that differs, in the target's units, a word of the same value written
    otherwise, or the whole difference."""
    for change in found.words:
        a, b = change.a, change.b
        if a is None or b is None or a.value is None or b.value is None or change.steps is None:
            continue
        expected = Fraction(a.value) / Fraction(b.factor)
        got = Fraction(b.value) / Fraction(b.factor)
        step = _number(Fraction(b.step) / Fraction(b.factor))
        return (f"{a.token} converts to {_number(expected)} but the output {b.token} reads "
                f"{_number(got)}: {steps_text(change.steps)} of {step}, more than the "
                f"rounding allows (read as {_ROLE.get(a.kind, 'a number')})")
    for change in found.words:
        if change.kind == "written":
            assert change.a is not None and change.b is not None
            return (f"{change.a.written} is written {change.b.written} in the output: a word "
                    "whose value and format the conversion keeps is kept byte for byte")
    return "the conversion is not the same program: " + found.describe(
        file, "the converted program")


_ROLE = {"length": "a length", "feed": "a feed", "speed": "a surface speed"}


def _number(value: Fraction) -> str:
    """Six significant digits at most (a value in inches may not end in decimal)."""
    with localcontext() as ctx:
        ctx.prec = 6
        number = Decimal(value.numerator) / Decimal(value.denominator)
    return f"{number.normalize():f}"
