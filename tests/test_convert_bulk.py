"""The array path of conversion (formats.bulk) against the block-by-block path, the reference.

Random programs mix plain runs (what the array path takes) with blocks that change the modal
state, comments, odd spacing and words the arrays refuse; both paths must give the same text,
the same statistics and the same located error.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from formats import bulk
from formats.convert import Converter, ConvertOptions, convert_text
from formats.errors import ConversionError, TapegateError
from formats.parser import parse_stream
from formats.profile import NEUTRAL, load_profile, profile_from_text
from formats.wordformat import Rounding, Zeros
from tests import words as shared

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
    converter.fast = False
    try:
        text = "".join(converter.convert(parse_stream([src])))
    except TapegateError as exc:
        return f"error {exc.line}:{exc.column} {exc.message}"
    return text + repr(_stats(converter))


def stream(src: str, options: ConvertOptions, chunk: int) -> str:
    converter = Converter(options, NEUTRAL)
    pieces = [src[i:i + chunk] for i in range(0, len(src), chunk)]
    try:
        text = "".join(converter.convert_stream(pieces, NEUTRAL.dialect))
    except TapegateError as exc:
        return f"error {exc.line}:{exc.column} {exc.message}"
    return text + repr(_stats(converter))


def _stats(converter: Converter) -> tuple[object, ...]:
    s = converter.stats
    return s.blocks, s.words, s.changed, sorted(s.rounding.items()), s.notes


@settings(max_examples=300, deadline=None)
@given(st.lists(line(), min_size=1, max_size=40), st.sampled_from(range(len(TARGETS))),
       st.sampled_from([None, "inch"]), st.sampled_from(list(Rounding)),
       st.sampled_from([None, "crlf"]), st.sampled_from([7, 64, 1 << 20]),
       st.booleans())
def test_array_path_agrees_with_the_block_path(lines, target, units, rounding, eob, chunk,
                                               final_eob):
    target = TARGETS[target]
    src = "G71\n" + "\n".join(lines) + ("\n" if final_eob else "")
    options = ConvertOptions(target, NEUTRAL, units=units, rounding=rounding, eob=eob)
    assert stream(src, options, chunk) == reference(src, options)


def test_the_array_path_takes_plain_runs():
    """A long plain run really goes through the arrays (not only the fallback)."""
    src = "G71\n" + "".join(f"N{i} G01 X{i}.5 Y-{i}.25 F100.\n" for i in range(1, 2000))
    options = ConvertOptions(IMPLICIT_INCH, NEUTRAL, units="inch")
    converter = Converter(options, NEUTRAL)
    calls = []
    original = converter._convert_run

    def spy(text, plan):
        out = original(text, plan)
        calls.append((text.count("\n"), out is not None))
        return out

    converter._convert_run = spy  # type: ignore[method-assign]
    out = "".join(converter.convert_stream([src], NEUTRAL.dialect))
    assert calls == [(1999, True)]
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
    assert f"{info.value.line}:{info.value.column}" == message


def test_numbers_too_long_for_the_arrays_fall_back():
    src = "G71\nN1 X1.0000000000000000001 Y2.\n" + "   " * 40 + "X1.\n"
    options = ConvertOptions(ISO, NEUTRAL)
    out, _ = convert_text(src, options)
    assert out == src.replace("X1.0000000000000000001", "X1.").replace("   " * 40 + "X1.",
                                                                         "   " * 40 + "X1.")


@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 10**12), st.integers(0, 6),
                          st.sampled_from([bulk.EXPLICIT, bulk.LEADING, bulk.TRAILING, bulk.FULL]),
                          st.booleans(), st.booleans()), min_size=1, max_size=30))
def test_render_writes_what_the_reference_writer_writes(values):
    """bulk.render against formats.convert._write, the one-word writer."""
    from formats.convert import _write
    from formats.wordformat import WordFormat
    src = " ".join(f"X{'-' if neg else '+' if plus else ''}1" for _, _, _, neg, plus in values)
    words = bulk.read_words(bulk.as_bytes(src + "\n"))
    assert words is not None
    u = np.array([v for v, *_ in values], dtype=np.int64)
    after = np.array([a for _, a, *_ in values], dtype=np.int64)
    mode = np.array([md for _, _, md, *_ in values], dtype=np.int64)
    width = np.full(len(values), 13 + 6, dtype=np.int64)
    rows, _ = bulk.render(words, np.arange(len(values)), u, mode, width, after)
    got = rows.T.tobytes().split(b"X")[1:]
    zeros = {bulk.LEADING: Zeros.LEADING, bulk.TRAILING: Zeros.TRAILING, bulk.FULL: Zeros.NONE,
             bulk.EXPLICIT: Zeros.LEADING}
    for (v, a, md, neg, plus), text in zip(values, got, strict=True):
        fmt = WordFormat("X", 19 - a, a, zeros=zeros[md])
        want = _write(-v if neg else v, a, fmt, md == bulk.EXPLICIT, plus and not neg)
        assert text.replace(b"\0", b"").decode() == want
