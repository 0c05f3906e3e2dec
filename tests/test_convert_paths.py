"""Conversion fed text (the core converts whole lines a chunk at a time) against conversion fed
Block objects, and the core's arithmetic against an exact ``decimal`` oracle.

Random programs mix plain runs with blocks that change the modal state, comments, odd spacing and
words that must fail; both ways in must give the same text, the same statistics and the same
located error.
"""

from __future__ import annotations

from decimal import ROUND_HALF_EVEN, ROUND_HALF_UP, Decimal, localcontext

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from formats.convert import Converter, ConvertOptions, convert_text
from formats.errors import ConversionError, TapegateError
from formats.parser import parse_stream
from formats.profile import NEUTRAL, load_profile, profile_from_text
from formats.wordformat import Rounding
from tests import words as shared
from tests.conftest import timeout_for_work

ISO = load_profile("iso-mill")
IMPLICIT_INCH = profile_from_text(
    'name = "implicit-inch"\n'
    'detailed = "%:/ N07 G02 X+044 Y+044 Z+044 I+044 J+044 K+044 F042 S05 T02 M02*"\n'
    'units_codes = "G20/G21"\nunits = "inch"\n')
TRAILING = profile_from_text(
    'name = "trailing"\n'
    'detailed = "%:/ N04 G2 X+530 Y+530 Z+530 I+530 J+530 F430 S04 T02 M02*"\n')
FULL = profile_from_text(
    'name = "full"\ndetailed = "%:/ N04 G2 X+43 Y+43 Z+43 I+43 J+43 F42 S04 T02 M02*"\n')
TARGETS = [ISO, IMPLICIT_INCH, TRAILING, FULL]


def plain_word() -> st.SearchStrategy[str]:
    wholes = ["", "0", "1", "12", "123", "7000", "0012", "99999"]
    return shared.plain_word("XYZIJFXYAS", wholes, ["", "", "-", "+"])


@st.composite
def line(draw: st.DrawFn) -> str:
    kind = draw(st.integers(0, 9))
    if kind == 0:
        return draw(st.sampled_from(["G91", "G90", "G93", "G94", "G20", "G21", "G04 X1.5",
                                     "(NOTE)", "", "N7 G92 X0 Y0", "G95 F.2", "G96 S200",
                                     "G97 S1000", "%", "M30", "X1.2.3", "G28 X0"]))
    words = draw(st.lists(plain_word(), min_size=0, max_size=5))
    if draw(st.booleans()):
        words.insert(0, f"N{draw(st.integers(0, 99999))}")
    if draw(st.integers(0, 3)) == 0:
        words.insert(1 if words[:1] and words[0][0] == "N" else 0,
                     draw(st.sampled_from(["G0", "G1", "G02", "G03", "G00"])))
    blank = draw(st.sampled_from([" ", " ", "", "\t", "  "]))
    end = draw(st.sampled_from(["", "", "\r", " "]))
    return blank.join(words) + end


def reference(src: str, options: ConvertOptions) -> str:
    converter = Converter(options, NEUTRAL)
    try:
        text = "".join(converter.convert(parse_stream([src])))
    except TapegateError as exc:
        return f"error {exc.code} {exc.line}:{exc.column} {exc.message}"
    return text + repr(_stats(converter))


def stream(src: str, options: ConvertOptions, chunk: int) -> str:
    converter = Converter(options, NEUTRAL)
    pieces = [src[i:i + chunk] for i in range(0, len(src), chunk)]
    try:
        text = "".join(converter.convert_stream(pieces, NEUTRAL.dialect))
    except TapegateError as exc:
        return f"error {exc.code} {exc.line}:{exc.column} {exc.message}"
    return text + repr(_stats(converter))


def _stats(converter: Converter) -> tuple[object, ...]:
    s = converter.stats
    return s.blocks, s.words, s.changed, sorted(s.rounding.items()), s.notes


@timeout_for_work(4.7)  # measured: the 300 examples take 4.7 s of CPU alone
@settings(max_examples=300, deadline=None)
@given(st.lists(line(), min_size=1, max_size=40), st.sampled_from(range(len(TARGETS))),
       st.sampled_from([None, "inch"]), st.sampled_from(list(Rounding)),
       st.sampled_from([None, "crlf"]), st.sampled_from([7, 64, 1 << 20]),
       st.booleans())
def test_text_and_blocks_convert_alike(lines, target, units, rounding, eob, chunk,
                                               final_eob):
    target = TARGETS[target]
    src = "G71\n" + "\n".join(lines) + ("\n" if final_eob else "")
    options = ConvertOptions(target, NEUTRAL, units=units, rounding=rounding, eob=eob)
    assert stream(src, options, chunk) == reference(src, options)


def test_a_long_plain_run():
    """A long run of plain blocks, metric explicit to implicit inch."""
    src = "G71\n" + "".join(f"N{i} G01 X{i}.5 Y-{i}.25 F100.\n" for i in range(1, 2000))
    options = ConvertOptions(IMPLICIT_INCH, NEUTRAL, units="inch")
    converter = Converter(options, NEUTRAL)
    out = "".join(converter.convert_stream([src], NEUTRAL.dialect))
    assert out.splitlines()[1] == "N1 G01 X591 Y-492 F394"  # 1.5 mm, -1.25 mm, 100 mm/min
    assert converter.stats.blocks == 2000 and converter.stats.changed == 3 * 1999 + 1


@pytest.mark.parametrize("src, message", [
    ("G71\nN1 X1.\nN2 X123456789.\n", "3:4"),  # digit overflow in the middle of a run
    ("G71\nN1 X1.\nN2 X1.23456\n", "3:4"),  # --round error
])
def test_errors_inside_a_run_are_located(src, message):
    options = ConvertOptions(ISO, NEUTRAL, rounding=Rounding.ERROR)
    with pytest.raises(ConversionError) as info:
        convert_text(src, options)
    assert info.value.code == "conversion-format"
    assert f"{info.value.line}:{info.value.column}" == message


def test_numbers_with_many_decimals():
    src = "G71\nN1 X1.0000000000000000001 Y2.\n" + "   " * 40 + "X1.\n"
    options = ConvertOptions(ISO, NEUTRAL)
    out, _ = convert_text(src, options)
    assert out == src.replace("X1.0000000000000000001", "X1.").replace("   " * 40 + "X1.",
                                                                         "   " * 40 + "X1.")


IMPLICIT_METRIC = profile_from_text(
    'name = "implicit-metric"\n'
    'detailed = "%:/ N07 G02 X+053 Y+053 Z+053 I+053 J+053 K+053 F052 S05 T02 M02*"\n'
    'units_codes = "G20/G21"\n')


@settings(max_examples=300, deadline=None)
@given(st.lists(st.decimals(min_value=-3000, max_value=3000, places=4, allow_nan=False,
                            allow_infinity=False), min_size=1, max_size=20),
       st.sampled_from(["inch", "metric"]), st.sampled_from(list(Rounding)[:2]),
       st.booleans())
def test_values_match_the_exact_decimal_oracle(values, units, rounding, explicit_target):
    """Every converted X word equals decimal arithmetic on the written value: times 1/25.4 (or
    25.4), rounded once to the target resolution under the policy."""
    source_units = "metric" if units == "inch" else "inch"
    code = "G21" if source_units == "metric" else "G20"
    src = code + "\n" + "".join(f"X{v:f}\n" for v in values)
    target = ISO if explicit_target else (IMPLICIT_INCH if units == "inch" else IMPLICIT_METRIC)
    source = profile_from_text('name = "s"\ndetailed = "%:/DS N07 G02 X+054 F052 S05 M02*"\n'
                               'units_codes = "G20/G21"\n')
    out, _ = convert_text(src, ConvertOptions(target, source, units=units, rounding=rounding))
    fmt = target.word_format("X")
    step = Decimal(1).scaleb(-fmt.after)
    policy = ROUND_HALF_EVEN if rounding is Rounding.HALF_EVEN else ROUND_HALF_UP
    with localcontext() as ctx:
        ctx.prec = 60
        for value, line in zip(values, out.splitlines()[1:], strict=True):
            exact = (value / Decimal("25.4") if units == "inch" else value * Decimal("25.4"))
            expected = exact.quantize(step, rounding=policy) if value >= 0 else \
                -((-exact).quantize(step, rounding=policy))
            assert target.value(line) == expected, (value, line)
