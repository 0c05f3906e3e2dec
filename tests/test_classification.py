import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from formats.classification import DetailedClassification, GeneralClassification
from formats.errors import FormatSpecError
from formats.wordformat import Zeros
from tests.conftest import timeout_for_work

EXAMPLE = "%:/DS N03 G02 X+053 Y+053 Z+053 F031 S04 T04 M02*"


def test_annex_c_example():
    d = DetailedClassification.parse(EXAMPLE + " (with dwell facility, the F word becomes F022)")
    assert d.program_start and d.alignment and d.block_skip and d.explicit_decimal
    x = d.formats["X"]
    assert (x.signed, x.before, x.after, x.zeros) == (True, 5, 3, Zeros.LEADING)
    f = d.formats["F"]
    assert (f.signed, f.before, f.after) == (False, 3, 1)
    assert d.formats["N"].before == 3 and not d.formats["N"].decimal
    assert d.facilities == {"dwell": {"F": d.facilities["dwell"]["F"]}}
    assert d.facilities["dwell"]["F"].spec() == "F022"
    assert str(d) == EXAMPLE + " (with dwell facility, the F word becomes F022)"


def test_spaces_are_for_reading_only():
    assert str(DetailedClassification.parse("%:/DSN03G02X+053*")) == "%:/DS N03 G02 X+053*"


def test_trailing_zero_format():
    d = DetailedClassification.parse("N03 X+530*")
    assert d.formats["X"].zeros is Zeros.TRAILING and not d.explicit_decimal


@pytest.mark.parametrize("text, message", [
    ("N03 X+053", "unexpected end of text"),
    ("N03 X+553*", "needs a 0 first"),
    ("X+053 N03*", "out of the proper sequence"),
    ("N03 N04*", "names N twice"),
    ("N03 X+053* (with dwell facility, the F word becomes F022)", "does not name"),
    ("N03 X$053*", "unexpected"),
])
def test_detailed_errors(text, message):
    with pytest.raises(FormatSpecError) as info:
        DetailedClassification.parse(text)
    assert (info.value.code, info.value.clause) == ("classification", "Annex C")
    # every malformed string is one code: only the wording tells which fault was found
    assert re.search(message, info.value.message)


def test_annex_b():
    g = GeneralClassification.parse("PM 322")
    assert (g.kind, g.units, g.motions, g.numerical, g.simultaneous) == ("P", "M", 3, 2, 2)
    assert str(g) == "PM 322"
    assert g.explain()[0][2] == "positioning only"


@pytest.mark.parametrize("text, message", [
    ("PM 232", "digit 2 <= digit 1"),
    ("PM 423", "digit 3 <= digit 2"),
    ("XM 322", "unexpected character"),
    ("PM 32", "unexpected"),
])
def test_annex_b_errors(text, message):
    with pytest.raises(FormatSpecError) as info:
        GeneralClassification.parse(text)
    assert (info.value.code, info.value.clause) == ("classification", "Annex B")
    # every malformed string is one code: only the wording tells which fault was found
    assert re.search(message, info.value.message)


@st.composite
def general(draw):
    d1 = draw(st.integers(0, 9))
    d2 = draw(st.integers(0, d1))
    d3 = draw(st.integers(0, d2))
    return f"{draw(st.sampled_from('PLDC'))}{draw(st.sampled_from('MIN'))} {d1}{d2}{d3}"


@given(general())
def test_annex_b_round_trip(text):
    assert str(GeneralClassification.parse(text)) == text


ORDER = "NGXYZUVWPQRABCIJKFESTDM"


@st.composite
def detailed(draw):
    flags = "".join(ch for ch in ("%", ":", "/", "DS") if draw(st.booleans()))
    letters = sorted(draw(st.sets(st.sampled_from(ORDER), min_size=1)), key=ORDER.index)
    specs = []
    for letter in letters:
        plus = "+" if draw(st.booleans()) else ""
        kind = draw(st.sampled_from(["lead3", "trail3", "count0", "count_trail", "count"]))
        a, b = draw(st.integers(1, 9)), draw(st.integers(0, 9))
        digits = {"lead3": f"0{a}{b}", "trail3": f"{a}{b}0", "count0": f"0{a}",
                  "count_trail": f"{a}0", "count": f"{a}"}[kind]
        specs.append(f"{letter}{plus}{digits}")
    return (f"{flags} " if flags else "") + " ".join(specs) + "*"


@given(detailed())
def test_annex_c_round_trip(text):
    parsed = DetailedClassification.parse(text)
    assert str(parsed) == text
    assert DetailedClassification.parse(str(parsed)) == parsed


@pytest.mark.parametrize(("text", "kind", "message"), [
    ("PM 322", GeneralClassification, None),
    ("%:/DS N03 G02 X+053 M02*", DetailedClassification, None),
    # a detailed classification without its end of block is reported as one (issue 22)
    ("%/ N3 G2 X+430", None, "detailed classification: unexpected end of text (a detailed "
                             "classification ends with '*', the end of block) at column 15"),
    ("N3 G2", None, "detailed classification: unexpected end of text"),
    ("XM 322", None, "general classification 'XM 322': unexpected character at column 1"),
])
def test_either_classification_is_told_apart_by_its_shape(text, kind, message):
    from formats.classification import parse_classification

    if message is None:
        assert isinstance(parse_classification(text), kind)
    else:
        with pytest.raises(FormatSpecError) as info:
            parse_classification(text)
        assert info.value.code == "classification"
        assert info.value.clause in ("Annex B", "Annex C")
        # one code for every malformed string: the wording tells which fault was found
        assert message in info.value.message


# ---------------------------------------------------------------------------------------------
# The hand parser against the lark grammar: whatever the hand parser reads, it reads as lark
# does (the same classification, or the same error); what it leaves (None), lark reads.

from formats import classification as cl  # noqa: E402


def _outcome(parse, text):
    try:
        result = parse(text)
    except FormatSpecError as exc:
        return ("error", exc.code, str(exc), exc.clause)
    if result is None:
        return None
    if isinstance(result, tuple):  # Annex B tokens
        return ("ok", result)
    return ("ok", str(result), list(result.formats), result.formats, result.facilities,
            result.program_start, result.alignment, result.block_skip, result.explicit_decimal)


_SPACE = st.sampled_from(["", "", " ", " ", "  ", "\t", "\n", " \n "])
_ADDRESSES = st.sampled_from(list(cl.ADDRESS_ORDER + "L"))


@st.composite
def _spec(draw, address=None):
    address = address or draw(_ADDRESSES)
    plus = draw(st.sampled_from(["", "+"]))
    digits = draw(st.text("0123456789", min_size=1, max_size=4))
    return draw(_SPACE) + address + draw(_SPACE) + plus + draw(_SPACE) + digits


@st.composite
def _note(draw):
    s = draw(st.lists(_SPACE, min_size=5, max_size=5))
    g = draw(st.lists(st.sampled_from([" ", " ", "  ", "\t", "\n", ""]), min_size=6,
                      max_size=6))
    names = draw(st.lists(st.sampled_from(["dwell", "tool-length", "x", "with", "the", "word",
                                           "becomes", "facility", "a-"]),
                          min_size=1, max_size=2))
    name = "".join(n + g[5] for n in names)
    address = draw(_ADDRESSES)
    return (f"{s[0]}({s[1]}with{g[0]}{name}facility{s[2]},{s[3]}the{g[1]}{address}"
            f"{g[2]}word{g[3]}becomes{g[4]}"
            f"{draw(_spec(draw(st.sampled_from([address, 'F', 'X']))))}{s[4]})")


@st.composite
def _detailed_text(draw):
    flags = "".join(draw(_SPACE) + f for f in ("%", ":", "/", "DS") if draw(st.booleans()))
    specs = "".join(draw(_SPACE) + draw(_spec()) for _ in range(draw(st.integers(0, 4))))
    eob = draw(st.sampled_from(["*", "*", "", "**"]))
    notes = "".join(draw(_note()) for _ in range(draw(st.integers(0, 1))))
    return flags + specs + draw(_SPACE) + eob + notes + draw(_SPACE)


_NOISE = st.text(alphabet="%:/DSNGXYFLwithfacly,eorbms +-0123456789*()\t\n\r$", max_size=40)


@given(st.one_of(_detailed_text(), _NOISE))
def test_hand_parser_reads_annex_c_as_the_grammar_does(text):
    hand = _outcome(cl._hand_detailed, text)
    if hand is not None:
        assert hand == _outcome(cl._lark_detailed, text)


@given(_detailed_text())
def test_hand_parser_reads_every_classification_in_its_printed_form(text):
    """Every classification the grammar accepts, printed, is read by the hand parser alone."""
    try:
        parsed = cl._lark_detailed(text)
    except FormatSpecError:
        return
    printed = str(parsed)
    assert _outcome(cl._hand_detailed, printed) == _outcome(cl._lark_detailed, printed)
    assert cl._hand_detailed(printed) == parsed


@given(st.one_of(st.from_regex(r"[ \t]*[A-Z][ \t]*[A-Z][ \t]*[0-9 \t]{0,6}", fullmatch=True),
                 st.text(alphabet="PLDCMIN0123456789 \t\nX", max_size=12)))
def test_hand_parser_reads_annex_b_as_the_grammar_does(text):
    hand = cl._hand_general(text.strip())
    if hand is not None:
        assert hand == cl._lark_general(text)


# The hand parsers as they were written with regular expressions, before they read character
# by character (a check's start-up without `re`): the reference they are held to.
_W = "[ \t\n]*"
_RE_FLAGS = re.compile(f"{_W}(%?){_W}(:?){_W}(/?){_W}((?:DS)?)")
_RE_SPEC = re.compile(f"{_W}([A-Z]){_W}(\\+?){_W}([0-9]{{1,3}})(?![0-9])")
_RE_EOB = re.compile(f"{_W}\\*")
_RE_NOTE = re.compile(
    f"{_W}\\({_W}with[ \t\n]+((?:[a-z][a-z-]*[ \t\n]+)+?)facility{_W},{_W}"
    f"the[ \t\n]+([A-Z])[ \t\n]+word[ \t\n]+becomes[ \t\n]+"
    f"([A-Z]){_W}(\\+?){_W}([0-9]{{1,3}}){_W}\\)")
_RE_GENERAL = re.compile(r"([PLDC])[ \t]*([MIN])[ \t]*([0-9])[ \t]*([0-9])[ \t]*([0-9])")
_RE_SHAPE = re.compile(r"\s*[A-Za-z]\s*[A-Za-z][\s0-9]*")


def _regex_detailed(text):
    flags = _RE_FLAGS.match(text)
    names = {name for name, found in zip(cl._FLAG_NAMES, flags.groups(), strict=True) if found}
    specs, notes, pos = [], [], flags.end()
    while (spec := _RE_SPEC.match(text, pos)) is not None:
        specs.append((spec[1], spec[2], spec[3]))
        pos = spec.end()
    eob = _RE_EOB.match(text, pos)
    if not specs or eob is None:
        return None
    pos = eob.end()
    while (note := _RE_NOTE.match(text, pos)) is not None:
        words = note[1].split()
        if cl._NOTE_WORDS.intersection(words):
            return None
        notes.append((" ".join(words), note[2], (note[3], note[4], note[5])))
        pos = note.end()
    if re.compile(_W).match(text, pos).end() != len(text):
        return None
    children = [names]
    children.extend(cl.word_format_from_spec(a, plus == "+", d) for a, plus, d in specs)
    for facility, address, (a, plus, d) in notes:
        children.append(cl._facility_note(facility, address,
                                          cl.word_format_from_spec(a, plus == "+", d)))
    return cl._build_detailed(children)


_TRICKY_NOTE = st.lists(st.sampled_from(["(", ")", " ", "\t", "\n", ",", "+", "0", "12", "1234",
                                          "F", "X", "with", "the", "word", "becomes",
                                          "facility", "facilityx", "dwell", "a-", "-b", "Q"]),
                        max_size=30).map("".join)


@st.composite
def _cut_note(draw):
    """A facility note whose parts may each be left out, doubled or misspelt, with 0-3 name
    words among which "facility" and "facilityx"."""
    space = draw(st.sampled_from(["", " ", "\t", "\n ", "  "]))
    words = draw(st.lists(st.sampled_from(["dwell", "facility", "facilityx", "tool-length", "a-",
                                           "-b", "Dwell", "with"]), max_size=3))
    parts = ["(", "with", *words, "facility", ",", "the", "F", "word", "becomes",
             draw(st.sampled_from(["F022", "F+022", "F 2", "F1234", "F", "X+1"])), ")"]
    kept = [p for p in parts if draw(st.integers(0, 9))]  # each left out one time in ten
    return draw(st.sampled_from(["N03 X+053*", "%N04 F031* ", "X1*"])) + "".join(
        p + draw(st.sampled_from([space, " ", ""])) for p in kept)


@timeout_for_work(8.2)  # measured: the 3,000 examples take 8.2 s of CPU alone
@settings(max_examples=3000)
@given(st.one_of(_detailed_text(), _NOISE, _cut_note(),
                 st.builds(lambda head, note: head + note,
                           st.sampled_from(["N03 X+053*", "%N04 F031* ", "X1*"]),
                           _TRICKY_NOTE)))
def test_the_hand_parser_reads_as_its_regular_expressions_did(text):
    """The hand parsers read character by character what their regular expressions read, the
    same result or the same None (for lark), on the grammar's strings, noise, and facility
    notes cut and mixed (a name word that starts with "facility", no word, a fourth digit)."""
    assert _outcome(cl._hand_detailed, text) == _outcome(_regex_detailed, text)
    general = _RE_GENERAL.fullmatch(text.strip())
    assert cl._hand_general(text.strip()) == (general.groups() if general else None)
    assert cl._general_shape(text) == bool(_RE_SHAPE.fullmatch(text))


@given(st.text(alphabet="PLDCMIN0123456789 \t\nXa\u00a0\u2003\u0663", max_size=12))
def test_annex_b_is_read_by_hand_as_its_regular_expressions_did(text):
    general = _RE_GENERAL.fullmatch(text.strip())
    assert cl._hand_general(text.strip()) == (general.groups() if general else None)
    assert cl._general_shape(text) == bool(_RE_SHAPE.fullmatch(text))


def test_a_facility_name_may_hold_a_word_that_starts_with_facility():
    """The fewest words before a "facility" the rest of the note follows: "facilityx" is a
    word of the name, and a name word "facility" sends the string to lark."""
    text = "N03 F+053* (with dwell facilityx facility, the F word becomes F022)"
    assert _outcome(cl._hand_detailed, text) == _outcome(_regex_detailed, text)
    assert "dwell facilityx" in cl._hand_detailed(text).facilities
    assert cl._hand_detailed("N03 F+053* (with dwell facility facility, the F word becomes "
                             "F022)") is None


def test_every_builtin_profile_is_read_without_lark():
    """The strings of the built-in profiles are all read by the hand parser (no lark at
    start-up), and lark reads them the same."""
    import tomllib

    from formats.profile import builtin_names, builtin_text

    for name in builtin_names():
        data = tomllib.loads(builtin_text(name))
        for key in ("detailed", "detailed_inch"):
            if key in data:
                hand = cl._hand_detailed(data[key])
                assert hand is not None, (name, key)
                assert hand == cl._lark_detailed(data[key])
                assert str(hand) == str(cl._lark_detailed(data[key]))
        if "general" in data:
            assert cl._hand_general(data["general"].strip()) is not None, name


def test_a_bad_string_still_gets_the_grammars_located_error():
    with pytest.raises(FormatSpecError) as info:
        DetailedClassification.parse("N03 X$053*")
    assert (info.value.code, info.value.clause) == ("classification", "Annex C")
    # the grammar's located wording is the point: the column is given only in the message
    assert "unexpected character '$' at column 6" in info.value.message
    assert cl._hand_detailed("N03 X$053*") is None
