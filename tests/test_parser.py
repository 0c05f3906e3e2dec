from decimal import Decimal

import pytest

from formats.errors import ParseError
from formats.parser import PERMISSIVE, STRICT, BadBlock, Dialect, parse_stream, parse_text
from formats.printer import program_text, replace_words
from formats.profile import load_profile

PROGRAM = (
    "\x00\x00\x00%(PART 1)\r\n"
    "O1000\r\n"
    "N10 G01 X12.5 Y-3 F200\r\n"
    "N20G01X1Y2\r\n"
    "/N30 X1 (COMMENT) Y2\r\n"
    "/2 N31 X3\r\n"
    ":40 R11 = 22.2\r\n"
    "R29 = R9 + R15 X2 = 105 + R9\r\n"
    "N50\tX1=123.456 Y1=234\r\n"
    "M30\n\r\r"
    "%\x7f\x00"
)


def test_every_construct_of_clauses_4_to_6():
    blocks = parse_text(PROGRAM, STRICT)
    assert blocks[0].percent and blocks[0].info.ident == "(PART 1)"
    assert blocks[1].words == ["O1000"]
    assert blocks[2].words == ["N10", "G01", "X12.5", "Y-3", "F200"]
    assert blocks[3].words == ["N20", "G01", "X1", "Y2"]
    assert blocks[4].skip == "/" and blocks[4].comments == [(9, "(COMMENT)")]
    assert blocks[5].skip == "/2" and blocks[5].words == ["N31", "X3"]
    assert blocks[6].words == [":40", "R11=22.2"]
    assert blocks[7].words == ["R29=R9+R15", "X2=105+R9"]
    words = blocks[7].word_objects()
    assert (words[0].index, words[0].expression, words[1].column) == ("29", "R9+R15", 16)
    assert blocks[8].words == ["N50", "X1=123.456", "Y1=234"]
    assert blocks[-1].percent and not blocks[-1].has_eob


def test_round_trip_is_byte_identical():
    assert program_text(parse_text(PROGRAM)) == PROGRAM
    assert program_text(parse_text("N1\n\n\nN2")) == "N1\n\n\nN2"
    assert program_text(parse_text("")) == ""


@pytest.mark.parametrize("size", [1, 2, 3, 7, 64, 4096])
def test_streaming_in_chunks_of_any_size_gives_the_same_blocks(size):
    chunks = [PROGRAM[i:i + size] for i in range(0, len(PROGRAM), size)]
    streamed = list(parse_stream(chunks))
    whole = parse_text(PROGRAM)
    assert [(b.line, b.text, b.words) for b in streamed] == [(b.line, b.text, b.words)
                                                             for b in whole]
    assert program_text(streamed) == PROGRAM


@pytest.mark.parametrize("text, column, code", [
    ("N10 X", 5, "TG100"),  # address X has no value
    ("N10 (ABC", 5, "TG120"),  # comment not closed
    ("N10 x10", 5, "TG101"),  # lower-case 'x'
    ("N10 X1 #5", 8, "TG101"),  # outside ISO 6983-1 Annex A
    ("N10 \x01", 5, "TG101"),  # control or binary character 0x01
    ("N10 1.5", 5, "TG100"),  # without an address letter
    ("N10 X--1", 7, "TG100"),  # a sign must be followed by a number
    ("N10 X1)", 7, "TG121"),  # without an opening
    ("R1 = 5 + ", 10, "TG100"),  # expression ends without an operand
    ("N10 X1 / Y2", 8, "TG123"),  # block skip must stand at the start
    ("X0=1", 2, "TG206"),  # index of X must be greater than 0
    ("N10 (A\x02B)", 7, "TG101"),  # a control character in a comment
    ("N10 X1 ;C", 8, "TG101"),  # outside ISO 6983-1 Annex A
    (":A", 2, "TG125"),  # alignment label
])
def test_errors_are_located(text, column, code):
    with pytest.raises(ParseError) as info:
        parse_text("N1\n" + text + "\n", STRICT, file="p.nc")
    error = info.value
    assert error.code == code  # the checker's rule for such a block
    assert (error.file, error.line, error.column) == ("p.nc", 2, column)
    assert str(error).startswith(f"p.nc:2:{column}: ")


def test_dialect_allows_extra_characters():
    blocks = parse_text("n10 x1.5 ; lower case\n#1 = [#2 + 3] * 2\nX#1\n", PERMISSIVE)
    assert blocks[0].words == ["n10", "x1.5"] and blocks[0].comments == [(10, "; lower case")]
    assert blocks[1].words == ["#1=[#2+3]*2"]
    assert blocks[2].words == ["X#1"]


def test_collect_mode_keeps_going_and_keeps_the_text():
    blocks = parse_text("N1 X1\nN2 Y\nN3 Z3\n", errors="collect")
    assert isinstance(blocks[1], BadBlock) and blocks[1].text == "N2 Y"
    assert "has no value" in str(blocks[1].error)
    assert blocks[2].words == ["N3", "Z3"]
    assert program_text(blocks) == "N1 X1\nN2 Y\nN3 Z3\n"


def test_binary_and_huge_lines_fail_fast():
    with pytest.raises(ParseError) as info:
        list(parse_stream(iter(["X" * 70000])))
    assert (info.value.code, info.value.line, info.value.column) == ("TG100", 1, 1)
    assert "longer than" in info.value.message  # TG100 is also an unreadable word: this is size
    with pytest.raises(ParseError) as info:
        parse_text("N1\n\x89PNG\x1a\n")
    assert (info.value.code, info.value.line, info.value.column) == ("TG101", 2, 1)
    blocks = parse_text("N1\n" + "A" * 70000 + "\n", errors="collect")
    assert isinstance(blocks[1], BadBlock)


def test_values_through_the_profile_word_formats():
    mill = load_profile("iso-mill")  # explicit decimal (DS): X1030 is 1030 mm
    assert mill.value("X1030") == Decimal(1030)
    assert mill.value("X-1.5") == Decimal("-1.5")
    assert mill.value("X1=123.456") == Decimal("123.456")
    old = load_profile("pm322-eia")  # implicit, trailing zeros omitted, X+430
    assert old.value("X00103") == Decimal("10.300")  # 4.3 digits, left-aligned
    assert old.value("X1030") == Decimal("1030.000")
    leading = load_profile("iso-mill").word_format("X")
    assert leading.read("", "1030", False) == Decimal("1.030")


def test_replace_words_keeps_everything_else():
    block = parse_text("N10 G01  X12.5 (KEEP X12.5)\tY-3 R11 = 22.2\r\n")[0]
    assert replace_words(block, {2: "X1.25", 4: "R11=2"}) == (
        "N10 G01  X1.25 (KEEP X12.5)\tY-3 R11=2\r")


def test_strict_dialect_refuses_expressions_when_disabled():
    with pytest.raises(ParseError) as info:
        parse_text("R1 = R2 + 1\n", Dialect(expressions=False))
    assert (info.value.code, info.value.line) == ("TG100", 1)


def test_expression_tree_parameters_and_evaluation():
    from formats.expr import evaluate, parameters

    block = parse_text("R29 = R9 + R15 X2 = [105 + R9] * 2\n", PERMISSIVE)[0]
    first, second = block.word_objects()
    assert parameters(first.expression) == ["R9", "R15"]
    values = {"R9": Decimal("1.5"), "R15": Decimal("2.25")}
    assert evaluate(first.expression, values) == Decimal("3.75")
    assert evaluate(second.expression, values) == Decimal("213.0")
    with pytest.raises(ParseError) as info:
        evaluate("R7 + 1", values)
    assert (info.value.code, info.value.clause) == ("TG100", "6.4.7")
    # an expression has no place in a file here; one code for both: the wording tells which
    assert "R7 has no value" in info.value.message
    with pytest.raises(ParseError) as info:
        evaluate("1 / 0", values)
    assert (info.value.code, info.value.clause) == ("TG100", "6.4.7")
    assert "division by zero" in info.value.message


def test_parse_stream_holds_one_chunk_of_blocks_at_a_time():
    """A chunk's blocks are let go before the next chunk's are made: the peak of reading many
    chunks is that of one (it once kept two, 65 MB instead of 48 for a million blocks)."""
    import tracemalloc

    line = "N10 G01 X12.345 Y-6.789 Z0.5 F1000.\n"
    chunk = line * 2000

    def peak(chunks: list[str]) -> int:
        tracemalloc.start()
        try:
            count = sum(1 for _ in parse_stream(iter(chunks), STRICT))
            highest = tracemalloc.get_traced_memory()[1]
        finally:
            tracemalloc.stop()
        assert count == 2000 * len(chunks)
        return highest

    one, many = peak([chunk]), peak([chunk] * 8)
    assert many < 1.5 * one, (one, many)
