"""Conversion between machine formats: decimal style, zeros, units under the modal state."""

from __future__ import annotations

from decimal import Decimal
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from formats.convert import Converter, ConvertOptions, convert_file, convert_text
from formats.errors import ConversionError, ParseError
from formats.parser import parse_text
from formats.printer import program_text
from formats.profile import NEUTRAL, load_profile, profile_from_text
from formats.verify import verify_conversion
from formats.wordformat import Rounding, Zeros

ISO = load_profile("iso-mill")
FANUC = load_profile("fanuc-mill")
PM322 = load_profile("pm322-eia")
SIN = load_profile("sinumerik-7e2")

# An implicit-decimal inch control, leading zeros omitted, inch resolution 0.0001.
IMPLICIT_INCH = profile_from_text(
    'name = "implicit-inch"\n'
    'detailed = "%:/ N07 G02 X+044 Y+044 Z+044 I+044 J+044 K+044 F042 S05 T02 M02*"\n'
    'units_codes = "G20/G21"\nunits = "inch"\n')
BRACKETS = profile_from_text("name = \"brackets\"\nextra_characters = \"[]*\"\n")
# An explicit metric control with a fine resolution (0.0001 mm), for round trips.
FINE_METRIC = profile_from_text(
    'name = "fine-metric"\n'
    'detailed = "%:/DS N07 G02 X+054 Y+054 Z+054 I+054 J+054 K+054 F054 S05 T02 M02*"\n'
    'units_codes = "G20/G21"\n')


def conv(text: str, target=ISO, source=NEUTRAL, **kw) -> str:
    out, _ = convert_text(text, ConvertOptions(target=target, source=source, **kw))
    return out


def values(text: str, profile, letter: str) -> list[Decimal]:
    return [profile.value(t) for b in parse_text(text, profile.dialect) for t in b.words
            if t[0] == letter]


# -- decimal style and zeros --------------------------------------------------------------------


def test_explicit_to_implicit_leading_and_trailing():
    src = "N1 G01 X12.5 Y-0.03 Z0 F120.\n"
    # the target control starts in inch: the metric program gets its G21 (inserted, reported)
    assert conv(src, IMPLICIT_INCH) == "N1 G21 G01 X125000 Y-300 Z0 F12000\n"
    out = conv(src, IMPLICIT_INCH, zeros=Zeros.TRAILING)
    assert out == "N1 G21 G01 X00125 Y-000003 Z0 F012\n"
    assert values(out, ConvertOptions(IMPLICIT_INCH, zeros=Zeros.TRAILING)
                  .effective_target(), "X") == [Decimal("12.5")]


def test_implicit_trailing_source_to_explicit():
    # PM 322: X+430, four digits before and three after, trailing zeros omitted
    src = "N001 G01 X0125 Y-00005 F15\n"
    assert conv(src, ISO, PM322) == "N001 G01 X125. Y-0.5 F150.\n"


def test_unchanged_words_keep_their_writing():
    src = "N10 G1 X10.500 Y+2. (KEEP X1.)\r\n"
    assert conv(src, ISO) == src


def test_count_words_padded_for_a_no_zero_suppression_target():
    # PM 322 writes every G and M with two digits (format G2, no zero suppression)
    assert conv("N1 G1 X1. M3\n", PM322) == "N001 G01 X0001 M03\n"


def test_dwell_takes_the_dwell_facility_format():
    # iso-mill: F031, but F022 in a dwell block (Annex C facility note)
    assert conv("N1 G04 F2.25\n", ISO, decimal="implicit") == "N1 G04 F225\n"
    assert conv("N1 G01 F2.25\n", ISO, decimal="implicit") == "N1 G01 F22\n"


# -- units under the modal state ----------------------------------------------------------------

PROGRAM = """%
N1 G71 G90 G94
N2 G01 X25.4 Y-12.7 Z2.54 A90. F254.
N3 G95 F0.254
N4 G93 F2.5
N5 G94 G04 X2.5
N6 G97 S1000
N7 G92 S3000
N8 G96 S304.8
N9 T1 M06 D2
M30
%
"""


def test_units_follow_the_modal_state():
    out = conv(PROGRAM, IMPLICIT_INCH, units="inch", source=ISO)
    assert out.splitlines() == [
        "%",
        "N1 G20 G90 G94",                     # units code replaced (target's code pair)
        "N2 G01 X10000 Y-5000 Z1000 A900000 F1000",  # lengths, F per minute; angle untouched
        "N3 G95 F1",                          # mm/rev -> in/rev (0.01 in/rev at F042)
        "N4 G93 F250",                        # inverse time: not a length
        "N5 G94 G04 X25000",                  # dwell time: never converted
        "N6 G97 S1000",                       # rpm
        "N7 G92 S3000",                       # speed clamp (clause 12)
        "N8 G96 S1000",                       # m/min -> ft/min
        "N9 T1 M06 D2",
        "M30",
        "%",
    ]


def test_units_code_translated_between_code_pairs():
    assert conv("N1 G21 G90\nN2 X1.\n", ISO, source=None) == "N1 G71 G90\nN2 X1.\n"


def test_units_code_inserted_when_the_program_never_selects_units():
    out, stats = convert_text("%\nN1 G90 X25.4\n", ConvertOptions(ISO, NEUTRAL, units="inch"))
    assert out == "%\nN1 G70 G90 X1.\n"
    assert any("inserted G70" in n for n in stats.notes)


def test_inch_to_metric_and_arc_centres_and_lengths_of_r():
    src = "N1 G20\nN2 G02 X1. Y1. I0.5 J0 R1.\n"
    out = conv(src, FANUC, FANUC, units="metric")
    assert out == "N1 G21\nN2 G02 X25.4 Y25.4 I12.7 J0 R25.4\n"


def test_parameter_letter_of_unknown_role_refused_then_allowed():
    with pytest.raises(ConversionError) as err:
        conv("N1 G71\nN2 G02 X1. R5.\n", ISO, NEUTRAL, units="inch")
    assert err.value.line == 2 and err.value.column == 12
    assert err.value.code == "conversion-unprovable"
    out = conv("N1 G71\nN2 G02 X1. R5.\n", ISO, NEUTRAL, units="inch", allow_unconverted=True)
    assert out == "N1 G70\nN2 G02 X0.039 R5.\n"


def test_incremental_rounding_never_accumulates():
    # 1 mm steps in inch at 0.001 resolution: 0.03937 rounds to 0.039, drifting if each step is
    # rounded on its own; the converter writes differences of converted absolutes instead
    src = "N1 G71 G91\n" + "".join(f"N{i} X1.\n" for i in range(2, 102))
    out = conv(src, ISO, NEUTRAL, units="inch")
    steps = values(out, ISO, "X")
    assert set(steps) == {Decimal("0.039"), Decimal("0.04")}
    position = Decimal(0)
    for n, step in enumerate(steps, start=1):
        position += step
        assert abs(Fraction(position) - Fraction(n * 10, 254)) <= Fraction(1, 2000)


def test_g92_sets_the_position_for_incremental_tracking():
    src = "N1 G71 G92 X0.5\nN2 G91 X1.\nN3 X1.\n"
    out = conv(src, ISO, NEUTRAL, units="inch")
    assert out == "N1 G70 G92 X0.02\nN2 G91 X0.039\nN3 X0.039\n"


def test_parameters_that_are_provably_lengths_convert():
    src = "N1 G71\nN2 R11 = 25.4\nN3 R12 = 3\nN4 G01 X2 = 254 + R11 A1 = R12\n"
    out = conv(src, ISO, SIN, units="inch")
    assert out.splitlines() == ["N1 G70", "N2 R11 = 1.", "N3 R12 = 3",
                                "N4 G01 X2 = 10. + R11 A1 = R12"]


def test_parameters_that_cannot_be_proved_are_refused():
    src = "N1 G71\nN2 R11 = 25.4\nN3 G01 X2 = R11 A1 = R11\n"
    with pytest.raises(ConversionError) as err:
        conv(src, ISO, SIN, units="inch")
    assert (err.value.code, err.value.clause) == ("conversion-unprovable", "6.4.7")
    assert (err.value.line, err.value.column) == (2, 4)
    assert "R11" in err.value.message  # the parameter: no field names it
    unread = "N1 G71\nN2 R11 = 25.4\n"
    with pytest.raises(ConversionError) as err:
        conv(unread, ISO, SIN, units="inch")
    assert (err.value.code, err.value.line, err.value.column) == ("conversion-unprovable", 2, 4)
    # conversion-unprovable covers every why; the wording alone tells "never read" from the rest
    assert "never read" in err.value.message
    with pytest.raises(ConversionError) as err:
        conv("N1 G71\nN2 R1 = 2\nN3 X2 = R1 * R1\n", ISO, BRACKETS, units="inch")
    assert (err.value.code, err.value.clause) == ("conversion-unprovable", "6.4.7")
    assert "non-linear" in err.value.message  # the why, within the one code (as above)
    kept = conv(unread, ISO, SIN, units="inch", allow_unconverted=True)
    assert "R11 = 25.4" in kept


# -- rounding, overflow, errors -----------------------------------------------------------------


def test_round_error_policy_refuses_with_location():
    with pytest.raises(ConversionError) as err:
        conv("N1 X1.2345\n", ISO, rounding=Rounding.ERROR)
    assert (err.value.line, err.value.column, err.value.code) == (1, 4, "conversion-format")
    assert conv("N1 X1.2345\n", ISO) == "N1 X1.234\n"  # half-even
    assert conv("N1 X1.2345\n", ISO, rounding=Rounding.HALF_UP) == "N1 X1.235\n"


def test_digit_overflow_is_always_an_error():
    with pytest.raises(ConversionError) as err:
        conv("N1 G01\nN2 X123456.\n", ISO)
    assert (err.value.code, err.value.clause) == ("conversion-format", "Annex C")
    assert (err.value.line, err.value.column) == (2, 4)
    # conversion-format is also a refused rounding: the wording tells overflow apart
    assert "digit overflow" in err.value.message
    with pytest.raises(ConversionError) as err:
        conv("N1234 X1.\n", ISO)  # N03
    assert (err.value.code, err.value.line, err.value.column) == ("conversion-format", 1, 1)


def test_a_sequence_number_past_n99999_follows_the_target_s_past_sequence():
    """A Haas has no documented alarm for N100000 (Fusion 360's Haas post numbers on), and the
    checker says so (TG208, checks.past_sequence): the converter carries it as written, with a
    note, where it refused it as a digit overflow. A Fanuc alarms (PS0003): refused there."""
    haas = load_profile("haas-mill")
    src = "O1\nN99999 G0 X1.\nN100000 X2.\nN100010 X3.\nN100020 X4.\nM30\n"
    out, stats = convert_text(src, ConvertOptions(haas, haas, units="metric"))
    assert out.splitlines()[1:5] == ["N99999 G21 G0 X25.4", "N100000 X50.8", "N100010 X76.2",
                                     "N100020 X101.6"]
    said = [n for n in stats.notes if n.startswith("sequence numbers longer than the target")]
    assert said == ["sequence numbers longer than the target format N05 carried as written (the "
                    "first, N100000): the control's manuals do not say whether it rounds, cuts "
                    "or alarms"], stats.notes  # once a file, not once a block
    with pytest.raises(ConversionError) as err:
        convert_text(src, ConvertOptions(FANUC, haas))
    assert (err.value.code, err.value.line, err.value.column) == ("conversion-format", 3, 1)
    assert "PS0003" in err.value.message


def test_a_statement_is_not_carried_to_a_control_of_another_family():
    """A Custom Macro B statement written as it was for LinuxCNC reads there as words (IF is
    I, F...): the output could not be read, or would move otherwise. Refused at the source's
    line and column, where --verify found it only in the output ('(converted):4:2: address I
    must be followed by a number'). Fanuc to Haas, one family, carries it."""
    src = "O1\nG21 G90\n#1=2.\nIF[#1EQ2.]GOTO10\nG0 X#1\nN10 M30\n"
    with pytest.raises(ConversionError) as err:
        convert_text(src, ConvertOptions(load_profile("linuxcnc"), FANUC))
    assert (err.value.code, err.value.line, err.value.column) == ("conversion-dialect", 4, 1)
    assert "Custom Macro B (Fanuc, Haas), which a LinuxCNC control does not read" in str(
        err.value)
    assert convert_text(src, ConvertOptions(load_profile("haas-mill"), FANUC))[0] == src


def test_a_sinumerik_word_with_an_equals_sign_is_not_carried_to_another_family():
    """A SINUMERIK's extended address (S1=470 the first spindle, X4=20 axis X4, M1=3: Programming
    Manual Fundamentals, "Extended addresses"), its X=R1+5 and its R1=5 are no words a Fanuc
    reads: written as they were, the output was refused there (or R1 read as a radius) while
    the conversion said ok. Refused at the word, as a statement of another family is; a
    SINUMERIK target carries them."""
    siemens = load_profile("sinumerik-840d")
    for block, column in [("N20 S1=(R1+20)*2 M1=3", 5), ("N20 G0 X4=20", 8),
                          ("N20 S1=INI[53]", 5), ("N20 R1=5", 5), ("N20 G1 X=R1+5 F100", 8)]:
        src = f"N10 G0 X0 Y0\n{block}\nN40 M30\n"
        with pytest.raises(ConversionError) as err:
            convert_text(src, ConvertOptions(FANUC, siemens))
        assert (err.value.code, err.value.line, err.value.column) == (
            "conversion-dialect", 2, column), block
        assert "SINUMERIK" in err.value.message and "does not read" in err.value.message
        assert convert_text(src, ConvertOptions(siemens, siemens))[0] == src


def test_a_word_left_unconverted_is_left_exactly_as_written():
    """#1 is read as a length and set nowhere: X[#1+5.] cannot be converted. With
    --allow-unconverted the note says it is left unconverted; its 5. scaled to 0.1969 beside
    the unconverted #1 was neither the old value nor the new. Without the option: refused at
    the word."""
    src = "O0001\nG21 G0 X0 Y0\nG1 X[#1+5.] F100.\nM30\n"
    out, stats = convert_text(src, ConvertOptions(FANUC, FANUC, units="inch",
                                                  allow_unconverted=True))
    assert out.splitlines()[2] == "G1 X[#1+5.] F3.937"
    assert any(n.startswith("line 3: X[#1+5.] left unconverted: #1") for n in stats.notes)
    with pytest.raises(ConversionError) as err:
        convert_text(src, ConvertOptions(FANUC, FANUC, units="inch"))
    assert (err.value.code, err.value.line, err.value.column) == ("conversion-unprovable", 3, 4)


def test_a_sinumerik_expression_is_read_by_the_sinumerik_reader_for_the_units():
    """Round brackets group in SINUMERIK arithmetic, and its names are the same in any case
    ("The SINUMERIK NC language does not distinguish between uppercase and lowercase
    letters"): X=r1+5 and X4=(R1+5)*2 read R1 as a length, so R1=10 is converted with them,
    where the analysis passed both words over and refused R1 as "never read"."""
    siemens = load_profile("sinumerik-840d")
    inch = ConvertOptions(siemens, siemens, units="inch")
    src = "N10 G71 G0 X0 Y0\nN20 R1=10\nN30 G1 X=r1+5 F100\nN40 M30\n"
    assert convert_text(src, inch)[0].splitlines()[1:3] == ["N20 R1=0.3937",
                                                           "N30 G1 X=r1+0.1969 F100"]
    src = "N10 G71 G0 X0 Y0\nN20 R1=10\nN30 G1 X4=(R1+5)*2 F100\nN40 M30\n"
    assert convert_text(src, inch)[0].splitlines()[1:3] == ["N20 R1=0.3937",
                                                           "N30 G1 X4=(R1+0.1969)*2 F100"]
    # a variable makes the expression one the units cannot be converted through: R1 is
    # refused where it is set, with the word that reads it
    src = "N10 G71 G0 X0 Y0\nN20 R1=10\nN30 G1 X=(R1+_OFS)*2 F100\nN40 M30\n"
    with pytest.raises(ConversionError) as err:
        convert_text(src, inch)
    assert (err.value.code, err.value.line, err.value.column) == ("conversion-unprovable", 2, 5)
    assert "R1 is read in a non-linear expression on line 3" in err.value.message


def test_a_sinumerik_ic_or_ac_of_a_linear_value_converts_as_the_value(tmp_path):
    """Review 4, 11 (section 5): `X=IC(5)` is an increment of 5 and `Y=AC(R1)` the absolute
    position R1 whatever the G90/G91 in force (SINUMERIK Programming Manual Fundamentals,
    "Absolute dimensions (G90, AC)", "Incremental dimensions (G91, IC)"): linear in their
    value, so the value converts as it would alone (it was refused as "non-linear"), R1 with
    it. A function of the value is still refused."""
    siemens = load_profile("sinumerik-840d")
    inch = ConvertOptions(siemens, siemens, units="inch")
    src = ("G71 G90\nR1=2.5\nG1 X=IC(5) F100\nY=AC(R1+1)\nG91 X=ac(3.3)\n"
           "G90 G2 X5 Y0 I=AC(2.5) J0\nM30\n")
    assert convert_text(src, inch)[0].splitlines() == [
        "G70 G90", "R1=0.0984", "G1 X=IC(0.1969) F100", "Y=AC(R1+0.0394)", "G91 X=ac(0.1299)",
        "G90 G2 X0.1969 Y0 I=AC(0.0984) J0", "M30"]
    path = tmp_path / "ic.mpf"
    path.write_text("G71 G90\nG1 X=IC(5) F100\nM30\n")
    assert convert_file(str(path), str(tmp_path / "out.mpf"), inch, verify=True).verified
    with pytest.raises(ConversionError) as err:
        convert_text("G71 G90\nG1 X=IC(SIN(30)*5) F100\nM30\n", inch)
    assert "non-linear" in err.value.message
    # an IC is converted on its own, not against the positions as a G91 word is: a second
    # rounded one before an absolute position would add its rounding to the first's
    with pytest.raises(ConversionError) as err:
        convert_text("G71 G90\nG1 X=IC(5) F100\nX=IC(5)\nM30\n", inch)
    assert (err.value.line, err.value.column) == (3, 1)
    assert err.value.message.startswith("X=IC(5) on line 2 and X=IC(5) here are increments "
                                        "written with IC, each converted and rounded on its own")
    # an absolute position between them, an exact one, or one in G91 is no such sum
    for src in ("G71 G90\nG1 X=IC(5) F100\nX10\nX=IC(5)\nM30\n",
                "G71 G90\nG1 X=IC(5) F100\nX=AC(10)\nX=IC(5)\nM30\n",
                "G71 G90\nG1 X=IC(25.4) F100\nX=IC(25.4)\nM30\n",
                "G71 G91\nG1 X=IC(5) F100\nX5\nX5\nM30\n"):
        convert_text(src, inch)
    with pytest.raises(ConversionError) as err:
        convert_text("G71 G90\nLOOP\nG1 X=IC(5) F100\nENDLOOP\nM30\n", inch)
    assert "in a program with a jump or a loop" in err.value.message


def test_a_numbered_parameter_is_one_whatever_its_leading_zeros():
    """R01 is R1 (SINUMERIK, "Extended addresses": leading zeros are ignored) and #007 is #7
    (Custom Macro B): one parameter, set once and read as a length, converted with its reads;
    as two, the one set would be refused as never read."""
    siemens = load_profile("sinumerik-840d")
    src = "N10 G71 G0 X0 Y0\nN20 R01=10\nN30 G1 X=R1+5 F100\nN40 M30\n"
    assert convert_text(src, ConvertOptions(siemens, siemens, units="inch"))[0].splitlines()[
        1:3] == ["N20 R01=0.3937", "N30 G1 X=R1+0.1969 F100"]
    src = "%\nO1\nG21 G90 G0 X0 Y0\n#007=10.\nG1 X#7 F100.\nM30\n%\n"
    assert convert_text(src, ConvertOptions(FANUC, FANUC, units="inch"))[0].splitlines()[
        3:5] == ["#007=0.3937", "G1 X#7 F3.937"]


def test_axis_words_a_fanuc_moves_after_g80_are_refused_for_linuxcnc(tmp_path):
    """A Fanuc keeps G00 through G80; LinuxCNC has no motion mode after G80 (nor at the start)
    and refuses axis words without a motion code (rs274: "Cannot use axis values without a g
    code that uses them"). Written as they were, the output stopped LinuxCNC; the converter
    refuses the block, at the word. Where the program writes G00 again first it converts, and
    verifies: the motion mode one control ends at G80 is no difference until a block moves by
    it (verify failed every such program: "then motion 0 -> none")."""
    linuxcnc = load_profile("linuxcnc")
    src = "%\nO1\nG00 G90 G40 G80 G21 G17\nG91 G28 Z0.\nG90 G54 X10. Y5.\nM30\n%\n"
    with pytest.raises(ConversionError) as err:
        convert_text(src, ConvertOptions(linuxcnc, FANUC))
    assert (err.value.code, err.value.line, err.value.column) == ("conversion-modal", 5, 9)
    assert "after G80 on line 3" in err.value.message and "write G00 or G01" in err.value.message
    fixed = src.replace("G90 G54 X10.", "G00 G90 G54 X10.")
    path = tmp_path / "p.nc"
    path.write_text(fixed.replace("O1\n", ""))
    assert convert_file(str(path), None, ConvertOptions(linuxcnc, FANUC), verify=True).verified
    # a macro call: no code of LinuxCNC's (its profile lists no G65), refused at the code
    # before its arguments are read as axis words
    call = "G65 P9724 C1. E1.\nM30\n"
    with pytest.raises(ConversionError) as err:
        convert_text(call, ConvertOptions(linuxcnc, FANUC))
    assert (err.value.line, err.value.column) == (1, 1)
    assert "no such code" in err.value.message


def test_the_size_of_a_string_is_no_value_to_convert():
    """DEF STRING[100] NAME holds no length: a change of units is not refused for it."""
    siemens = load_profile("sinumerik-840d")
    src = "DEF STRING[100] NAZIV\nG71 G90\nG0 X25.4\nM30\n"
    out, _ = convert_text(src, ConvertOptions(siemens, siemens, units="inch"))
    assert out.splitlines()[:3] == ["DEF STRING[100] NAZIV", "G70 G90", "G0 X1."]


def test_largest_rounding_reported_per_address():
    _, stats = convert_text("N1 X1.2345 Y1.2\n", ConvertOptions(ISO, NEUTRAL))
    # exact, as (numerator, denominator) in lowest terms: 0.0005 is 1/2000
    assert stats.rounding == {"X": (1, 2000)}
    assert Fraction(*stats.rounding["X"]) == Fraction(5, 10000)
    assert stats.largest_rounding() == ("X", Decimal("0.0005"))
    assert stats.largest_rounding_text() == ("X", "0.0005")


# -- properties ---------------------------------------------------------------------------------

coordinate = st.decimals(min_value=-9999, max_value=9999, places=4, allow_nan=False)


@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(coordinate, coordinate), min_size=1, max_size=20))
def test_explicit_implicit_explicit_is_identity(points):
    src = "".join(f"X{x} Y{y}\n" for x, y in points)
    there = conv(src, IMPLICIT_INCH)
    back = conv(there, FINE_METRIC, IMPLICIT_INCH)
    assert values(back, FINE_METRIC, "X") == [x for x, _ in points]
    assert values(back, FINE_METRIC, "Y") == [y for _, y in points]
    # parse(print(x)) == x for every converted program
    assert program_text(parse_text(there)) == there


@settings(max_examples=200, deadline=None)
@given(st.lists(st.decimals(min_value=-999, max_value=999, places=4, allow_nan=False),
                min_size=1, max_size=20))
def test_inch_metric_inch_returns_the_original(xs):
    src = "G20\n" + "".join(f"G01 X{x}\n" for x in xs)
    metric = conv(src, FINE_METRIC, FANUC, units="metric")
    back = conv(metric, IMPLICIT_INCH, FINE_METRIC, units="inch")
    assert values(back, IMPLICIT_INCH, "X") == xs


@settings(max_examples=100, deadline=None)
@given(st.lists(st.decimals(min_value=-50, max_value=50, places=3, allow_nan=False),
                min_size=1, max_size=30))
def test_incremental_absolute_within_half_a_step(steps):
    src = "G71 G91\n" + "".join(f"X{s}\n" for s in steps)
    out = conv(src, ISO, NEUTRAL, units="inch")
    got = values(out, ISO, "X")
    position, exact = Fraction(0), Fraction(0)
    for s, g in zip(steps, got, strict=True):
        exact += Fraction(s) * Fraction(5, 127)
        position += Fraction(g)
        assert abs(position - exact) <= Fraction(1, 2000)


words = st.sampled_from(["X", "Y", "Z", "I", "J", "F", "S", "A"])
block = st.lists(st.tuples(words, st.decimals(min_value=-999, max_value=999, places=3,
                                              allow_nan=False)), min_size=1, max_size=5)
mode = st.sampled_from(["", "G91", "G90", "G04", "G92", "G95", "G93", "G96", "G97", "G94",
                        "G02", "G28"])


@settings(max_examples=150, deadline=None)
@given(st.lists(st.tuples(mode, block), min_size=1, max_size=25),
       st.sampled_from([None, "inch"]), st.sampled_from([ISO, IMPLICIT_INCH]))
def test_blocks_and_text_convert_alike_in_every_modal_state(blocks, units, target):
    src = "G71\n" + "".join(
        (f"{g} " if g else "") + " ".join(f"{a}{v}" for a, v in words) + "\n"
        for g, words in blocks)
    options = ConvertOptions(target, NEUTRAL, units=units)
    outputs = []
    for as_blocks in (True, False):
        converter = Converter(options, NEUTRAL)
        try:
            if as_blocks:
                outputs.append("".join(converter.convert(parse_text(src))))
            else:
                outputs.append("".join(converter.convert_stream([src], NEUTRAL.dialect)))
        except ConversionError as exc:
            outputs.append(f"error {exc.line}:{exc.column} {exc.message}")
    assert outputs[0] == outputs[1]


# -- files and verification ---------------------------------------------------------------------


def test_convert_file_verifies_and_writes_atomically(tmp_path):
    src = tmp_path / "p.nc"
    src.write_text(PROGRAM)
    out = tmp_path / "out" / "p.nc"
    options = ConvertOptions(IMPLICIT_INCH, ISO, units="inch")
    stats = convert_file(str(src), str(out), options, verify=True)
    assert stats.verified and out.exists()
    with pytest.raises(ConversionError) as exists:
        convert_file(str(src), str(out), options)
    assert (exists.value.code, exists.value.file) == ("output-exists", str(src))  # as test_errors
    bad = tmp_path / "bad.nc"
    bad.write_text("N1 X1.\nN2 X123456789.\n")
    with pytest.raises(ConversionError) as err:
        convert_file(str(bad), str(tmp_path / "bad.out"), ConvertOptions(ISO, NEUTRAL))
    assert (err.value.code, err.value.file) == ("conversion-format", str(bad))
    assert (err.value.line, err.value.column) == (2, 4)
    assert not (tmp_path / "bad.out").exists()
    assert [p.name for p in out.parent.iterdir()] == ["p.nc"]  # no temporary left behind


def test_verify_finds_a_changed_value(tmp_path):
    src = tmp_path / "p.nc"
    src.write_text("N1 G71\nN2 X25.4 Y1.\n")
    out = tmp_path / "o.nc"
    options = ConvertOptions(ISO, NEUTRAL, units="inch")
    stats = convert_file(str(src), str(out), options)
    out.write_text(out.read_text().replace("X1.", "X1.001"))
    with pytest.raises(ConversionError) as err:
        verify_conversion(str(src), str(out), NEUTRAL, options, stats, file="p.nc")
    assert (err.value.code, err.value.clause, err.value.file) == ("conversion-verify", "verify",
                                                                   "p.nc")
    assert err.value.line == 2
    assert "X25.4 converts to 1" in err.value.message  # the values compared: no field holds them


POLAR_G91 = ("%\nO1\nG21 G90 G17\nG0 X0 Y0\nG91\nG16\nG1 X10.001 Y30. F100.\nG1 X10.001 Y30.\n"
             "G1 X10.001 Y30.\nG15\nG90\nM30\n%\n")
UNITS_G91 = "%\nO2\nG21 G91\nG0 X10.\nG20\nX1.\nG21\nX1.\nX1.001\nM30\n%\n"


@pytest.mark.parametrize("text, expected, tampered", [
    # G16 G91: each polar radius rounded on its own (10.001 mm -> 0.3937 in, three times), as
    # the converter guarantees; a radius one step off is still refused
    (POLAR_G91, ["G1 X0.3937 Y30. F3.937", "G1 X0.3937 Y30.", "G1 X0.3937 Y30."],
     ("G1 X0.3937 Y30.\nG1 X0.3937 Y30.\nG15", "G1 X0.3937 Y30.\nG1 X0.3936 Y30.\nG15")),
    # G91 across G20/G21: the increment after a units code moves from the place reached
    # (10 mm, +1 in, +1 mm, +1.001 mm); an increment changed is still refused
    (UNITS_G91, ["G0 X0.3937", "G20", "X1.", "G20", "X0.0394", "X0.0394"],
     ("G20\nX1.\nG20", "G20\nX1.001\nG20")),
])
def test_verify_judges_what_the_conversion_guarantees(tmp_path, text, expected, tampered):
    """Earlier, --verify refused both correct conversions: it carried the G91 rounding through
    polar radii the converter rounds each on its own ("X10.001 converts to 0.39374 but the
    output X0.3937 reads 0.3937"), and added an inch increment to a position in mm ("then
    position X 279.4 mm -> 35.39998 mm")."""
    src, out = tmp_path / "p.nc", tmp_path / "o.nc"
    src.write_text(text)
    options = ConvertOptions(FANUC, FANUC, units="inch")
    stats = convert_file(str(src), str(out), options, verify=True)
    assert stats.verified
    lines = out.read_text().splitlines()
    assert [line for line in lines if line.startswith(("G0 X", "G1 X", "X", "G20"))][
        -len(expected):] == expected
    out.write_text(out.read_text().replace(*tampered))
    with pytest.raises(ConversionError) as err:
        verify_conversion(str(src), str(out), FANUC, options, stats, file="p.nc")
    assert err.value.code == "conversion-verify"
    if text is POLAR_G91:
        assert err.value.line == 9
        assert err.value.message.startswith(
            "X10.001 converts to 0.39374 but the output X0.3936 reads 0.3936: -1.402 steps")
    else:
        assert err.value.line == 6
        assert err.value.message.startswith(
            "X1. converts to 1 but the output X1.001 reads 1.001: +9.992 steps")


def test_spacing_and_end_of_block_normalised():
    src = "%\n/N1G01X1.5 (CUT) Y2.\r\nN2  X3.\n"
    assert conv(src, ISO, spacing="insert", eob="crlf") == \
        "%\r\n/ N1 G01 X1.5 (CUT) Y2.\r\nN2 X3.\r\n"
    assert conv(src, ISO, spacing="remove", eob="lf") == "%\n/N1G01X1.5(CUT)Y2.\nN2X3.\n"


def test_heidenhain_end_of_block_is_kept_whatever_the_spacing():
    """HEIDENHAIN ISO ends a block with `*` (no word, no comment): respacing the words keeps
    it, with its blank; a comment running to the end holds it already."""
    hh = load_profile("heidenhain-iso")
    src = ("%P1 G71 *\nN10 G00 X+10.5 Y+5 *\nN15 G01 X+1 F100 ; CUT *\nN20 G01 X+20 *  \r\n"
           "N99999999 %P1 G71 *\n")
    assert conv(src, hh, hh, spacing="remove") == (
        "%P1 G71 *\nN10G00X+10.5Y+5 *\nN15G01X+1F100; CUT *\nN20G01X+20 *\r\n"
        "N99999999 %P1 G71 *\n")
    assert conv(src, hh, hh, spacing="insert") == (
        "%P1 G71 *\nN10 G00 X+10.5 Y+5 *\nN15 G01 X+1 F100 ; CUT *\nN20 G01 X+20 *\r\n"
        "N99999999 %P1 G71 *\n")


def test_a_runaway_block_is_reported_on_its_own_line() -> None:
    """More than MAX_BLOCK characters without LF after whole lines: the error is on line 4."""
    with pytest.raises(ParseError) as info:
        convert_text("%\nN1 X1.5\nN2 X2.5\n" + "A" * 70000, ConvertOptions(target=ISO))
    assert (info.value.code, info.value.line, info.value.column) == ("TG100", 4, 1)
    assert "longer than" in info.value.message  # TG100 is also an unreadable word: this is size



def test_the_program_number_and_the_units_code_stay_where_they_are_written():
    """O01010 is carried as written (it became O1010), and a G21 that comes after a block of
    modes is converted in place instead of a G20 being inserted before it."""
    src = "%\nO01010\nN10 G90 G17 G40\nN20 G21\nN30 G00 X25.4\nM30\n%\n"
    out, stats = convert_text(src, ConvertOptions(FANUC, FANUC, units="inch"))
    assert out == "%\nO01010\nN10 G90 G17 G40\nN20 G20\nN30 G00 X1.\nM30\n%\n"
    assert not any("inserted" in note for note in stats.notes)


def test_an_expression_of_twenty_thousand_terms_converts():
    """It ended in a RecursionError (formats/lengths.py); the core reads it in a loop."""
    src = "N1 G21\nN2 X1=1" + "+1" * 20000 + "\n"
    out, stats = convert_text(src, ConvertOptions(FANUC, FANUC, units="inch"))
    assert out.startswith("N1 G20\nN2 X1=0.0394+0.0394+")
    assert out.count("+0.0394") == 20000 and stats.blocks == 2


def test_huge_numbers_are_located_errors_that_name_the_limit():
    with pytest.raises(ConversionError) as info:
        convert_text("N1 G21\nN2 X" + "9" * 60000 + "\n", ConvertOptions(FANUC, FANUC))
    assert info.value.code == "conversion-format"
    assert (info.value.line, info.value.column) == (2, 4)
    assert "38 significant digits" in info.value.message  # naming the limit is the point
    out, _ = convert_text("N1 G21\nN2 A." + "0" * 40 + "\n", ConvertOptions(FANUC, FANUC))
    assert out.startswith("N1 G21\nN2 A")


def test_g91_does_not_survive_m30_into_the_next_program(tmp_path):
    """After M02/M30 the control is in its reset state: the next program of the file starts in
    G90 (it was converted as incremental: X25.403, X25.402). Its values are read in the units
    the program before left in force, and the output states them (below)."""
    src = "G20 G90\nG91 G28 Z0.\nM30\nG01 X1.0001\nX1.0001\n"
    out, _ = convert_text(src, ConvertOptions(FANUC, FANUC, units="metric"))
    assert out.splitlines()[3:] == ["G21 G01 X25.403", "X25.403"]
    path = tmp_path / "two.nc"
    path.write_text(src)
    stats = convert_file(str(path), str(tmp_path / "out.nc"),
                         ConvertOptions(FANUC, FANUC, units="metric"), verify=True)
    assert stats.verified


@pytest.mark.parametrize(("target", "code"), [("fanuc-mill", "G20"), ("sinumerik-840d", "G70")])
def test_a_program_after_the_end_is_given_its_units(target, code):
    """A second program of the file (an O number after M30) that moves before it selects its
    units is read as a program of its own, in the source control's start units, and its
    converted text states the target's: run on its own, it would otherwise move in whatever
    units the control was left in, and a Sinumerik resets G70/G71 at M30 (a G21 program
    converted to inch ran in millimetres). The note says what was read."""
    src = "O1\nG21\nG0 X25.4 Y50.8\nM30\nO2\nG0 X25.4 Y50.8\nM30\n"
    out, stats = convert_text(src, ConvertOptions(load_profile(target), FANUC, units="inch"))
    lines = out.splitlines()
    assert lines[5] == f"{code} G0 X1. Y2."
    assert (f"inserted {code}: the program beginning on line 5 did not select its units "
            "before line 6; it was read in metric, the source control's start units, as a "
            "program of its own") in stats.notes
    same, stats = convert_text(src, ConvertOptions(FANUC, FANUC))  # nothing converted
    assert same == src and not stats.notes
    src = "O1\nG21\nG0 X25.4\nM30\nO2\nG20 G0 X1.\nM30\n"  # it states them itself
    out, stats = convert_text(src, ConvertOptions(FANUC, FANUC, units="inch"))
    assert out.splitlines()[5] == "G20 G0 X1." and not stats.notes


@pytest.mark.parametrize("target", ["iso-mill", "sinumerik-840d"])
def test_the_target_control_s_units_after_the_end_are_followed(tmp_path, target):
    """An ISO source returns to metric at M30, and so does the target: the second program needs
    nothing, and its F is not rescaled (it was F3.9: the output's feed was still taken as
    inch). It verifies."""
    src = "N1 G70\nN2 G1 X1 F10\nN3 M30\nN4 G1 X25.4 F100\nN5 M30\n"
    path = tmp_path / "p.nc"
    path.write_text(src)
    options = ConvertOptions(load_profile(target), load_profile("iso-mill"))
    stats = convert_file(str(path), str(tmp_path / "out.nc"), options, verify=True)
    assert stats.verified
    assert (tmp_path / "out.nc").read_text().splitlines()[3] == "N4 G1 X25.4 F100"


@pytest.mark.parametrize(("source", "target", "src"), [
    ("iso-mill", "fanuc-mill", "N1 G70\nN2 G1 X1 F10\nN3 M30\nN4 G1 X25.4 F100\nN5 M30\n"),
    ("fanuc-mill", "sinumerik-840d",
     # (no M98 call: a FANUC's subprogram call is not carried to a SINUMERIK at all,
     # tests/test_between_families.py)
     "N1 G20\nN2 G1 X1. F10.\nN3 M01\nN4 M30\nN4 G1 X1. F5.\nN5 M30\n")])
def test_a_program_after_the_end_is_refused_where_the_controls_differ_over_m30(
        source, target, src):
    """Without a change of units, a program after M30 that moves before selecting its units
    means the same on both controls only if both keep, or both reset, their units at M30: a
    subprogram runs in its caller's units, a program of its own in the reset state's or the
    kept ones. A G70 inserted in the Fanuc subprogram for the Sinumerik (reset to metric at
    M30) switched its caller from G700 to G70 on return: F10. in mm/min."""
    with pytest.raises(ConversionError) as info:
        convert_text(src, ConvertOptions(load_profile(target), load_profile(source)))
    assert (info.value.code, info.value.clause) == ("conversion-units", "units")
    assert (info.value.line, info.value.column) == (4 if source == "iso-mill" else 5, 7)
    # conversion-units has several causes (docs/errors.md): the wording tells this one
    assert "cannot mean the same on both" in info.value.message


def test_a_subprogram_after_the_end_is_left_as_written_when_nothing_is_converted(tmp_path):
    """The caller calls O2 in G21 and selects G20 after: a G20 inserted in O2 (the units the
    main program ended in) would have moved it 1 inch instead of 1 mm. Nothing is converted,
    so nothing is inserted."""
    src = ("%\nO1\nG21 G90 G17\nG0 X10. Y10.\nM98 P2\nG20\nG0 X1.\nM30\nO2\nG1 X1. F100.\n"
           "M99\n%\n")
    out, stats = convert_text(src, ConvertOptions(FANUC, FANUC))
    assert out == src and not stats.notes


def test_a_guessed_source_refuses_a_program_whose_units_after_the_end_it_cannot_know():
    """Without a source profile, a second program that moves before selecting its units is
    inch to a Fanuc (kept from the first) and metric by clause 14: refused, at its first move.
    Where the two readings agree it converts, and says so."""
    src = "O1\nG20\nG0 X1.\nM30\nO2\nG0 Y1.\nM30\n"
    with pytest.raises(ConversionError) as info:
        convert_text(src, ConvertOptions(FANUC, units="metric"))
    assert info.value.code == "conversion-units"
    assert (info.value.line, info.value.column) == (6, 4)
    # conversion-units has several causes: the wording tells "no source control" apart
    assert "the source control was not given" in info.value.message
    assert "reads it in inch" in str(info.value) and "in metric" in str(info.value)
    # From a Fanuc, O2 is a program of its own (an O number after M30), whose start units
    # (metric) are not those O1 leaves in force (inch), in which it runs when O1 calls it
    with pytest.raises(ConversionError) as info:
        convert_text(src, ConvertOptions(FANUC, FANUC, units="metric"))
    assert (info.value.code, info.value.line, info.value.column) == ("conversion-units", 6, 4)
    assert "the units the program before it in the file leaves in force" in info.value.message
    assert "M98" not in info.value.message  # (it names no call that may not exist)
    # the same program with no O number after M30 is no program of its own: kept units
    out, _ = convert_text(src.replace("O2\n", ""), ConvertOptions(FANUC, FANUC, units="metric"))
    assert out.splitlines()[4] == "G21 G0 Y25.4"
    rpm = "O1\nG20\nG0 X1.\nM30\nO2\nT1 M6\nS1000 M3\nG21\nG0 X1.\nM30\n"  # rpm read alike
    assert convert_text(rpm, ConvertOptions(FANUC, units="metric"))[0].splitlines()[6:9] == [
        "S1000 M3", "G21", "G0 X1."]
    with pytest.raises(ConversionError) as info:
        convert_text(rpm.replace("S1000", "G96 S200"), ConvertOptions(FANUC, units="metric"))
    assert info.value.code == "conversion-units"
    assert (info.value.line, info.value.column) == (7, 5)  # a surface speed is not
    out, stats = convert_text(src.replace("G20", "G21"), ConvertOptions(FANUC, units="inch"))
    assert out.splitlines()[5] == "G20 G0 Y0.0394"
    assert any(n.endswith("it was read in metric, the units both the program before left in "
                          "force and the reset state has") for n in stats.notes), stats.notes


def test_a_sinumerik_program_after_the_end_is_read_in_the_reset_units():
    """A Sinumerik sets G70/G71 back to its reset state at M30: the second program's X25.4 is
    millimetres, whatever the first selected (a Fanuc source kept the first's inch)."""
    siemens = load_profile("sinumerik-840d")
    src = "N1 G70\nN2 G0 X1.\nN3 M30\nN4 G0 X25.4\nN5 M30\n"
    out, stats = convert_text(src, ConvertOptions(siemens, siemens, units="inch"))
    assert out.splitlines()[3] == "N4 G70 G0 X1."
    assert any(n.endswith("it was read in metric, the units of the source control's reset "
                          "state") for n in stats.notes), stats.notes


@pytest.mark.parametrize("src", ["G91.1\nG0 X1.\nM30\n", "G21\nT1.1 M6\nD0.05\nM30\n"])
def test_decimal_codes_convert_and_verify(tmp_path, src):
    """G91.1 (arc centres incremental) is a code of its own, never G91, and T1.1 or D0.05 are
    carried as written: --verify ended in a ValueError on each."""
    path = tmp_path / "p.nc"
    path.write_text(src)
    stats = convert_file(str(path), str(tmp_path / "out.nc"),
                         ConvertOptions(FANUC, FANUC, units="inch"), verify=True)
    assert stats.verified
    out = (tmp_path / "out.nc").read_text()
    assert ("G91.1" in out) == ("G91.1" in src) and ("T1.1" in out) == ("T1.1" in src)


# -- Sinumerik: G70/G71 lengths only, G700/G710 lengths and feed ---------------------------------

SIEMENS = load_profile("sinumerik-840d")


def test_sinumerik_g70_converts_lengths_and_leaves_the_feed_in_the_basic_system():
    """On a Sinumerik, G70/G71 set the units of lengths only: F stays in the basic system
    (mm/min on a metric machine); G700/G710 set the feed's units too (Programming Manual
    Fundamentals, "Inch or metric dimensions"). G710 was left as it was in an inch output, and
    F converted under G70."""
    src = "G71 G90 G17\nG1 X10 Y20 F200\nG710\nG1 X1 F100\nM30\n"
    out = conv(src, SIEMENS, SIEMENS, units="inch")
    assert out == "G70 G90 G17\nG1 X0.3937 Y0.7874 F200\nG700\nG1 X0.0394 F3.937\nM30\n"
    back = conv("G700 G90\nG1 X1 Y2 F10\nG70\nG1 X2 F200\nM30\n", SIEMENS, SIEMENS,
                units="metric")
    assert back == "G710 G90\nG1 X25.4 Y50.8 F254.\nG71\nG1 X50.8 F200\nM30\n"
    # a program that never selected its units gets G70 for its lengths; its feed stays mm/min
    assert conv("G90\nG1 X10 F200\nM30\n", SIEMENS, SIEMENS, units="inch") == \
        "G90\nG70 G1 X0.3937 F200\nM30\n"
    # to a control whose G20 sets the feed too, the basic-system feed is converted
    assert conv("G71 G90\nG1 X10 F200\nM30\n", FANUC, SIEMENS, units="inch") == \
        "G20 G90\nG1 X0.3937 F7.874\nM30\n"


def test_sinumerik_units_are_verified_and_a_feed_left_unconverted_under_g700_fails(tmp_path):
    src = tmp_path / "p.mpf"
    src.write_text("G71 G90\nG1 X10 F200\nG710\nG1 X20 F300\nM30\n")
    out = tmp_path / "o.mpf"
    options = ConvertOptions(SIEMENS, SIEMENS, units="inch")
    stats = convert_file(str(src), str(out), options)
    verify_conversion(str(src), str(out), SIEMENS, options, stats, file="p.mpf")
    assert out.read_text() == "G70 G90\nG1 X0.3937 F200\nG700\nG1 X0.7874 F11.811\nM30\n"
    out.write_text(out.read_text().replace("F11.811", "F300"))  # G700: the feed is inch/min
    with pytest.raises(ConversionError) as err:
        verify_conversion(str(src), str(out), SIEMENS, options, stats, file="p.mpf")
    assert (err.value.code, err.value.file, err.value.line) == ("conversion-verify", "p.mpf", 4)
    # the verify error has no column: the message names the word and both values
    assert "F300 converts to 11.811" in err.value.message
    out.write_text("G70 G90\nG1 X0.3937 F7.874\nG700\nG1 X0.7874 F11.811\nM30\n")  # G70: mm/min
    with pytest.raises(ConversionError) as err:
        verify_conversion(str(src), str(out), SIEMENS, options, stats, file="p.mpf")
    assert (err.value.code, err.value.file, err.value.line) == ("conversion-verify", "p.mpf", 2)
    assert "F200 converts to 200" in err.value.message  # the values compared (as above)


def test_a_dwell_converts_only_its_own_time_words(tmp_path):
    """LinuxCNC's dwell time is P alone: rs274 reads `G4 P1 X2` as a dwell then a move to X2,
    and `G4 P1 F10` sets the feed, so a change of units scales that X and F as in any block
    (they were kept as times, and verify passed them). A SINUMERIK's `G4 F1.5` (seconds) and
    `G4 S2` (revolutions) are the dwell's and stay as written."""
    linuxcnc = load_profile("linuxcnc")
    src = "G20\nG0 X0 Y0 Z1\nG4 P1 X2\nG4 P1 F10\nG1 Y1\nM2\n"
    path = tmp_path / "p.ngc"
    path.write_text(src)
    out = tmp_path / "out.ngc"
    stats = convert_file(str(path), str(out),
                         ConvertOptions(linuxcnc, linuxcnc, units="metric"), verify=True)
    assert stats.verified
    assert out.read_text() == "G21\nG0 X0 Y0 Z25.4\nG4 P1 X50.8\nG4 P1 F254.\nG1 Y25.4\nM2\n"
    siemens = load_profile("sinumerik-840d")
    text = "N10 G71 G0 X10\nN20 G4 F1.5\nN30 G4 S2\nN40 G1 X20 F100\nM30\n"
    out_text = conv(text, siemens, siemens, units="inch")
    assert "N20 G4 F1.5\nN30 G4 S2\n" in out_text
