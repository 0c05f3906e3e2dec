"""The fast tokenizer and the lark reference grammar agree on every generated block."""

from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from formats.errors import ParseError
from formats.parser import PERMISSIVE, STRICT, parse_text, tokenize_block
from tests.reference import ReferenceError, read_block

ws = st.sampled_from(["", " ", "  ", "\t", " \r", "\x00"])
number = st.from_regex(r"\A(?:[0-9]{1,6}(?:\.[0-9]{0,4})?|\.[0-9]{1,4})\Z")
address = st.sampled_from("ABCDEFGHIJKLMNOPQRSTUVWXYZ")


@st.composite
def plain_word(draw):
    sign = draw(st.sampled_from(["", "", "-", "+"]))
    index = draw(st.sampled_from(["", "", "", "1=", "12="]))
    return f"{draw(address)}{index}{sign}{draw(number)}"


@st.composite
def expression_word(draw):
    operand = st.one_of(number, st.from_regex(r"\A[PQR][0-9]{1,3}\Z"))
    parts = [draw(operand)]
    for _ in range(draw(st.integers(1, 3))):
        parts.append(draw(st.sampled_from(["+", "-", "/", " + ", " - "])))
        parts.append(draw(operand))
    return f"{draw(address)}{draw(st.integers(1, 99))} = {''.join(parts)}"


comment = st.from_regex(r"\A\([A-Z0-9 .,=:%/-]{0,12}\)\Z")


@st.composite
def block(draw):
    kind = draw(st.integers(0, 9))
    if kind == 0:
        return draw(ws) + "%" + draw(st.from_regex(r"\A[A-Z0-9 ()]{0,10}\Z"))
    items = draw(st.lists(st.one_of(plain_word(), expression_word(), comment,
                                    st.from_regex(r"\A:[0-9]{1,4}\Z")), max_size=6))
    skip = draw(st.sampled_from(["", "", "/", "/3"]))
    parts = [draw(ws) + skip]
    for item in items:
        parts.append(item)
        parts.append(draw(ws) if not item[-1].isdigit() else draw(ws.filter(bool)))
    return "".join(parts)


def fast(text, dialect):
    words, info = tokenize_block(text, dialect)
    return tuple(words), info.skip, tuple(info.comments), info.percent, info.ident


def reference(text, dialect):
    r = read_block(text, dialect)
    return r.words, r.skip, r.comments, r.percent, r.ident


@settings(max_examples=300, suppress_health_check=[HealthCheck.too_slow])
@given(block())
def test_agree_on_valid_blocks(text):
    assert fast(text, STRICT) == reference(text, STRICT)
    # the hot path (fullmatch + split / findall) gives the same words as the tokenizer
    assert tuple(parse_text(text + "\n")[0].words) == fast(text, STRICT)[0]


noise = st.text(alphabet="NGXYZRI0123456789.+-=()/: %\t#[];x", max_size=20)


@settings(max_examples=400, suppress_health_check=[HealthCheck.too_slow])
@given(noise, st.sampled_from([STRICT, PERMISSIVE]))
def test_agree_on_what_is_an_error(text, dialect):
    try:
        expected = reference(text, dialect)
    except ReferenceError:
        expected = None
    try:
        got = fast(text, dialect)
    except ParseError:
        got = None
    assert got == expected


expression_token = st.sampled_from(["1", "2.5", ".5", "7.", "R1", "P12", "#3", "+", "-", "*",
                                    "/", "[", "]", " ", "SIN", "SQRT", "ABS", "FOO", "R", "Q1",
                                    "**", "EQ", " and ", "mod", ",", "#", "<a>", "#<x_1>", "sin",
                                    "\t"])


@settings(max_examples=600, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(expression_token, max_size=12).map("".join))
@example("#2.5")  # a Haas NGC parameter element's form: one parameter in both
@example("#30003.078+#2.")
def test_the_core_reads_expressions_as_the_reference_grammar_does(text):
    """The core's expression trees (conversion, parameter analysis) accept what the lark
    expression grammar accepts, and find the same parameters in it."""
    from formats import _core
    from formats.expr import parameters

    try:
        expected = parameters(text)
    except ParseError:
        expected = None
    try:
        got = _core.expression_parameters(text)
    except ValueError:
        got = None
    assert got == expected


formula_token = st.sampled_from(["1", "2.5", ".5", "7.", "Q1", "QL12", "QR3", "QS4", "Q", "L",
                                 "+", "-", "*", "/", "%", "^", "(", ")", " ", "\t", "PI", "SIN",
                                 "SQ", "SQRT", "ATAN", "NEG", "SGN", "FRAC", "FOO", "sin", "[",
                                 "]", "#1", "R1", ",", "\x00"])


@settings(max_examples=600, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(formula_token, max_size=12).map("".join))
def test_the_core_reads_heidenhain_formulas_as_the_reference_grammar_does(text):
    """A HEIDENHAIN formula's right-hand side: the core's tree accepts what the lark formula
    grammar accepts, and finds the same parameters in it."""
    from formats import _core
    from formats.expr import parameters

    try:
        expected = parameters(text, formula=True)
    except ParseError:
        expected = None
    try:
        got = _core.expression_parameters(text, formula=True)
    except ValueError:
        got = None
    assert got == expected


sinumerik_token = st.sampled_from(["1", "2.5", ".5", "7.", "1EX2", "3ex-1", "R1", "r12", "R",
                                   "_X", "$AA_IM", "x", "+", "-", "*", "/", " DIV ", " mod ",
                                   "==", "<>", "<", ">", "<=", ">=", "<<", "=", " AND ", " or ",
                                   " XOR ", " B_AND ", " B_OR ", " b_xor ", "NOT ", "B_NOT ",
                                   "(", ")", "[", "]", ",", " ", "\t", "SIN", "ATAN2", '"A B"',
                                   '"', "AND", "#1", ";", "'H1F'", "'b01'", "'", "H"])


# no deadline: the first example builds the lark parser (a cold cache takes longer than one)
@settings(max_examples=600, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(sinumerik_token, max_size=12).map("".join))
def test_the_core_reads_sinumerik_expressions_as_the_reference_grammar_does(text):
    """A Sinumerik expression: the core's tree accepts what the lark grammar accepts, and is
    the same tree (the canonical forms agree, so the operators' priorities do too)."""
    from formats import _core
    from formats.expr import sinumerik_form

    try:
        expected = sinumerik_form(text)
    except ParseError:
        expected = None
    try:
        got = _core.sinumerik_form(text)
    except ValueError:
        got = None
    assert got == expected
