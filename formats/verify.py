"""Proof that a conversion kept every value: ``tapegate convert --verify``.

The converted program is read back **under the target profile** (its own word formats, through
:meth:`formats.profile.Profile.value`, not the converter's writer), block by block beside the
source. For each word the expected value is computed again from the source with
:class:`fractions.Fraction` -- the source value times the units factor of the block's modal
state -- and must equal the value read back within half a step of the target resolution. Axis
words are compared as **absolute positions** (accumulated through G91 increments), which proves
that rounding did not accumulate along an incremental path. Count words (N, G, M, T...) must keep
their value, and everything that is not a value (comments, order, other words) must be the same
word.
"""

from __future__ import annotations

from collections.abc import Iterator
from fractions import Fraction
from itertools import zip_longest

from formats.convert import (
    _KIND,
    ANGLE,
    AXIS,
    COUNT,
    FEED,
    FT_PER_M,
    G_MACHINE,
    INCH_PER_MM,
    PQR,
    SPEED,
    ConvertOptions,
    ConvertStats,
)
from formats.errors import ConversionError
from formats.model import Block, split_token
from formats.parser import parse_stream
from formats.profile import Profile
from formats.source import Source


class _State:
    """The little modal state a units conversion depends on, kept for one program."""

    def __init__(self, profile: Profile) -> None:
        self.units = profile.default_units
        self.incremental = False
        self.feed = 94
        self.css = False
        self.inch, self.metric = int(profile.inch_code[1:]), int(profile.metric_code[1:])
        self.position: dict[str, Fraction] = {}

    def end(self, block: Block) -> None:
        """After M02/M30 the control is in its reset state (distance, feed and spindle modes;
        the units are kept, as the converter keeps them)."""
        if any(tok[0] in "Mm" and tok[1:].isdigit() and int(tok[1:]) in (2, 30)
               for tok in block.words):
            self.incremental, self.feed, self.css = False, 94, False

    def block(self, block: Block) -> set[int]:
        codes = set()
        for tok in block.words:
            if tok[0] in "Gg" and tok[1:].isdigit():  # G91.1 is no G91
                n = int(tok[1:])
                codes.add(n)
                if n in (90, 91):
                    self.incremental = n == 91
                elif n in (93, 94, 95):
                    self.feed = n
                elif n in (96, 97):
                    self.css = n == 96
                elif n in (self.inch, self.metric):
                    self.units = "inch" if n == self.inch else "metric"
        return codes


def verify_conversion(source_path: str, output_path: str, source: Profile,
                      options: ConvertOptions, stats: ConvertStats, *, file: str) -> None:
    """Raise :class:`ConversionError` at the first value the output does not keep."""
    target = options.effective_target()
    src_blocks = parse_stream(Source(source_path).chunks(), source.dialect, file=file)
    out_blocks = parse_stream(Source(output_path).chunks(), target.dialect,
                              file=f"{file} (converted)")
    src_state, out_state = _State(source), _State(target)
    tolerance = {letter: value for letter, value in stats.rounding.items()}
    for src, out in zip_longest(src_blocks, out_blocks):
        if src is None or out is None:
            raise ConversionError("the converted program has a different number of blocks",
                                  file=file, clause="verify")
        _verify_block(src, out, src_state, out_state, source, target, tolerance, file)


def _pairs(src: Block, out: Block, target: Profile) -> Iterator[tuple[str, str | None]]:
    """Source and output tokens side by side; a units code the converter inserted (first, or
    after the sequence number) pairs with ""."""
    out_words = list(out.words)
    inserted = -1
    if len(out_words) == len(src.words) + 1:
        units = {target.inch_code, target.metric_code}
        inserted = next((i for i in (0, 1) if out_words[i].upper() in units), -1)
    if inserted >= 0:
        yield "", out_words.pop(inserted)
    for i, tok in enumerate(src.words):
        yield tok, out_words[i] if i < len(out_words) else None
    for extra in out_words[len(src.words):]:
        yield "", extra


def _verify_block(src: Block, out: Block, src_state: _State, out_state: _State,
                  source: Profile, target: Profile, tolerance: dict[str, Fraction],
                  file: str) -> None:
    src_codes = src_state.block(src)
    out_state.block(out)

    def fail(message: str) -> ConversionError:
        return ConversionError(message, file=file, line=src.line, clause="verify")

    if src.percent or not src.words:
        if src.text.rstrip("\r") != out.text.rstrip("\r") and src.percent:
            raise fail("the program start line changed")
        return
    if src_state.units == out_state.units:
        length = speed = Fraction(1)
    elif out_state.units == "inch":
        length, speed = INCH_PER_MM, FT_PER_M
    else:
        length, speed = 1 / INCH_PER_MM, 1 / FT_PER_M
    dwell = 4 in src_codes
    for tok, new in _pairs(src, out, target):
        if not tok:
            if new is None or new.upper() not in (target.inch_code, target.metric_code):
                raise fail(f"the converted block has an extra word {new}")
            continue
        if new is None:
            raise fail(f"{tok} is missing from the converted block")
        letter = tok[0].upper()
        kind = _KIND.get(letter)
        if new[0].upper() != letter:
            raise fail(f"{tok} became {new}")
        plain = "=" not in tok and split_token(tok)[4] == ""
        if kind is None or not plain:
            continue  # expressions are checked by their own tests; other words kept as written
        if kind == COUNT:
            if letter == "G" and tok[1:].isdigit() and int(tok[1:]) in (src_state.inch,
                                                                        src_state.metric):
                continue
            # a count keeps its value (G01 may become G1); a decimal one (G91.1, T1.1, D0.05)
            # is carried exactly as written
            same = (int(tok[1:]) == int(new[1:]) if tok[1:].isdigit() and new[1:].isdigit()
                    else tok[1:] == new[1:])
            if not same:
                raise fail(f"{tok} became {new}")
            continue
        factor = length
        if dwell and letter in "XUPF" or kind == ANGLE or kind == FEED and src_state.feed == 93:
            factor = Fraction(1)
        elif kind == SPEED:
            factor = speed if src_state.css and 92 not in src_codes else Fraction(1)
        elif kind == PQR and source.checks.pqr.get(letter) != "length":
            factor = Fraction(1)
        value = Fraction(source.value(tok, src_state.units)) * factor
        got = Fraction(target.value(new, out_state.units))
        if kind in (AXIS, ANGLE) and not dwell:
            if src_state.incremental and 92 not in src_codes:
                value += src_state.position.get(letter, Fraction(0))
                got += out_state.position.get(letter, Fraction(0))
            src_state.position[letter] = value
            out_state.position[letter] = got
        bound = tolerance.get(letter, Fraction(0))
        if abs(got - value) > bound:
            raise fail(f"{tok} converts to {float(value):.6g} but the output {new} reads "
                       f"{float(got):.6g} (largest rounding reported: {float(bound):.3g})")
    if src_codes & G_MACHINE:
        src_state.position.clear()
        out_state.position.clear()
    src_state.end(src)
    out_state.end(out)
