"""How each control reads a word written without a decimal point (profile key ``numbers``).

ISO 6983-1 (DS), Siemens, Heidenhain and LinuxCNC read ``X10000`` as 10,000 mm; a Fanuc or a
Haas reads it in least input increments, 10.000 mm at IS-B. The reading is used everywhere a
value is read: values, the checker's limits and TG201, the modal state, conversion.
"""

from __future__ import annotations

from decimal import Decimal

import pytest

from formats.convert import ConvertOptions, convert_text
from formats.errors import ProfileError
from formats.parser import parse_text
from formats.profile import load_profile, profile_from_text
from postproc.check import check_text
from postproc.state import state_at

FANUC = load_profile("fanuc-mill")
ISO = load_profile("iso-mill")


def test_a_fanuc_reads_increments_and_iso_whole_numbers():
    assert FANUC.value("X10000") == Decimal("10.000")
    assert FANUC.value("X-25") == Decimal("-0.025")
    assert FANUC.value("X10.") == Decimal("10")
    assert FANUC.value("P1000") == 1000  # dwell in ms, subprogram numbers: whole numbers
    assert FANUC.value("T5") == 5  # a count word is a count
    assert ISO.value("X10000") == 10000


def test_the_profile_key_is_checked():
    with pytest.raises(ProfileError) as info:
        profile_from_text('[numbers]\nwithout_point = "tenths"\n')
    assert (info.value.code, info.value.key) == ("profile-value", "numbers.without_point")
    with pytest.raises(ProfileError) as info:
        profile_from_text('[numbers]\nwithout_point = "increments"\nwhole = "P1"\n')
    assert (info.value.code, info.value.key) == ("profile-value", "numbers.whole")
    with pytest.raises(ProfileError) as info:
        profile_from_text('[numbers]\nsign = 1\n')
    assert (info.value.code, info.value.key) == ("profile-unknown-key", "numbers.sign")


def test_the_checker_reads_values_as_the_control_does():
    program = ("%\nO1000\nN1 G21 G90 G17\nN2 G00 X10000 Y0\nN3 G53 Z15000\n"
               "N4 G01 X12.5 F100.\nN5 M30\n%\n")
    found = [(f.rule, f.line, f.message.split(" (the built-in")[0])
             for f in check_text(program, FANUC)]
    # Z15000 is 15.000 mm: above the travel's 10 in machine coordinates, but not 15,000 mm
    assert ("TG601", 5, "Z goes to 15.000 in machine coordinates (G53), outside the travel "
            "-508 to 10") in found
    tg201 = [f for f in found if f[0] == "TG201"]
    assert tg201 == [("TG201", 4, "X10000 has no decimal point in a program that uses decimal "
                      "points: this control reads it in least input increments, as 10.000 "
                      "(6.1: the two must not be mixed)")]


def test_a_program_without_decimal_points_is_not_mixed():
    program = "%\nO1000\nN1 G21 G90 G17\nN2 G00 X10000 Y-2500\nN3 M30\n%\n"
    assert not [f for f in check_text(program, FANUC) if f.rule == "TG201"]


def test_the_restart_state_reads_increments():
    program = "%\nO1\nN1 G21 G90\nN2 G01 X10000 F100.\nN3 X2.\n"
    state = state_at(parse_text(program, FANUC.dialect), FANUC, 5)
    assert state.position["X"] == Decimal("10.000")


def test_converting_adds_the_decimal_points_a_fanuc_program_leaves_out():
    text = "N1 G21 G90\nN2 G01 X10000 Y-2500 F100.\nN3 X10. Z5\nN4 G04 P1000\nM30\n"
    out, _ = convert_text(text, ConvertOptions(ISO, FANUC))
    assert out == "N1 G71 G90\nN2 G01 X10. Y-2.5 F100.\nN3 X10. Z0.005\nN4 G04 P1000\nM30\n"


def test_a_whole_number_never_reaches_a_fanuc_without_its_point():
    """X10 meant as 10 mm would move a Fanuc 0.010 mm: written X10. for it. F is read whole
    (F100 is 100 mm/min), so it needs no point."""
    out, _ = convert_text("N1 G21\nN2 G01 X10 Y2.5 F100\n", ConvertOptions(FANUC, ISO))
    assert out == "N1 G21\nN2 G01 X10. Y2.5 F100\n"


def test_from_decimal_and_from_zeros_override_the_source_and_say_so():
    text = "N1 G21\nN2 X10000 Y1.5\n"
    out, stats = convert_text(text, ConvertOptions(ISO, ISO, from_decimal="increments"))
    assert out == "N1 G21\nN2 X10. Y1.5\n"  # G21 is no units code of iso-mill
    assert any("--from-decimal increments" in note for note in stats.notes)
    implicit = profile_from_text('name = "implicit"\ndetailed = "%:/ N04 G02 X+053 Y+053 F04*"\n')
    out, stats = convert_text("N1 G71\nN2 X1\n", ConvertOptions(ISO, implicit,
                                                               from_zeros="trailing"))
    assert out == "N1 G71\nN2 X10000.\n"  # X1 left-aligned in 5.3: 10000.000
    assert any("--from-zeros trailing" in note for note in stats.notes)


@pytest.mark.parametrize(("name", "text", "expected"), [
    ("fanuc-mill", "G21 G17 G90 G94\nG01 X10000 Z-1000 F100\nG04 P500\nG02 X20000 Y5000 R5000\n",
     "G21 G17 G90 G94\nG01 X10. Z-1. F100\nG04 P500\nG02 X20. Y5. R5.\n"),
    ("fanuc-lathe", "G21 G18 G99\nG00 X30000 Z5000\nG92 X24000 Z-20000 F1.5 Q18\n",
     "G21 G18 G99\nG00 X30. Z5.\nG92 X24. Z-20. F1.5 Q18\n"),
    # an angle without its point counts 0.001 deg in inch too (the A format), as the control
    # reads it: the R format's 0.0001 would be 4.5 deg
    ("fanuc-mill", "G20\nG68 X0 Y0 R45000\n", "G20\nG68 X0 Y0 R45.\n"),
])
def test_an_implicit_decimal_source_is_read_as_its_control_reads_it(name, text, expected):
    """Review 58b F6: `--from-decimal implicit` read a FANUC's G and F by their formats (G031:
    `G21` became `G2.1`, F054: `F100` `F0.1`), verified by the same reading. A control that
    counts least increments reads a number without its point so however the program was
    written: G F P L (the lathe's Q) whole (`numbers.whole`), the others in increments, which
    is the implicit reading with leading zeros omitted; left-aligned (trailing zeros omitted)
    digits are no number it reads, refused at the option."""
    from formats.errors import ConversionError
    profile = load_profile(name)
    options = ConvertOptions(profile, profile, decimal="explicit", from_decimal="implicit")
    out, stats = convert_text(text, options)
    assert out == expected
    assert any(", ".join(sorted(profile.numbers.whole)) + " whole numbers" in note
               for note in stats.notes), stats.notes
    with pytest.raises(ConversionError) as err:
        convert_text(text, ConvertOptions(profile, profile, decimal="explicit",
                                          from_decimal="implicit", from_zeros="trailing"))
    assert err.value.code == "conversion-option"
    assert err.value.message.startswith(f"--from-zeros trailing: {name} reads")
    # a control reading whole numbers: the digits by the formats, zeros as said
    iso = load_profile("iso-mill")
    out, _ = convert_text("G71\nX1\n", ConvertOptions(iso, iso, decimal="explicit",
                                                       from_decimal="implicit",
                                                       from_zeros="trailing"))
    assert out == "G71\nX10000.\n"
    whole = profile_from_text('name = "w"\ndetailed = "%:/ G031 X+053 F054*"\n'
                              '[numbers]\nwithout_point = "increments"\nwhole = "FG"\n')
    assert (whole.value("G21"), whole.value("F100"), whole.value("X10000")) == \
        (Decimal(21), Decimal(100), Decimal("10.000"))


def test_trailing_zero_output_for_a_control_counting_increments_is_refused():
    """A FANUC reads `X0001` as 0.001 mm (least increments) however the program was written:
    `--decimal implicit --zeros trailing` output (10.000 left-aligned in X+053) would be
    misread (--verify refused it, naming a step count: review 58b F6), so the option is
    refused before anything is written, naming why; leading zeros are its own reading."""
    from formats.errors import ConversionError
    with pytest.raises(ConversionError) as err:
        convert_text("G21\nG01 X10. F100.\n",
                     ConvertOptions(FANUC, FANUC, decimal="implicit", zeros="trailing"))
    assert err.value.code == "conversion-option" and "X0001 is 0.001" in err.value.message
    out, _ = convert_text("G21\nG01 X10. F100.\n",
                          ConvertOptions(FANUC, FANUC, decimal="implicit"))
    assert out == "G21\nG01 X10000 F100.\n"


# -- a word format for each unit system ----------------------------------------------------------


def test_a_profile_has_a_format_for_each_unit_system():
    assert FANUC.word_format("X").spec() == "X+053"
    assert FANUC.word_format("X", "inch").spec() == "X+044"
    assert FANUC.word_format("A", "inch").spec() == "A+053"  # an angle is no length
    assert FANUC.value("X10000", "inch") == Decimal("1.0000")  # 0.0001 in increments
    with pytest.raises(ProfileError) as info:
        profile_from_text('detailed = "%:/DS X+053*"\ndetailed_inch = "%:/ X+044*"\n')
    assert (info.value.code, info.value.key) == ("profile-classification", "detailed_inch")


def test_an_inch_program_is_held_to_the_inch_format():
    program = "%\nO1\nN1 G20 G90 G17\nN2 G01 X1.0607 Y2.12345 F10.\nN3 M30\n%\n"
    found = [(f.rule, f.line, f.message) for f in check_text(program, FANUC)]
    # past the increment: TG208 on a Fanuc (no source says it alarms), TG203 under ISO
    assert [f[:2] for f in found if f[0] in ("TG203", "TG208")] == [("TG208", 4)]
    assert [f[2] for f in found if f[0] == "TG208"][0].startswith(
        "Y2.12345: 5 decimals; the format Y+044 holds 4")


def test_converting_to_inch_writes_the_inch_resolution():
    out, stats = convert_text("N1 G21 G90\nN2 G01 X10. Y25.4 F100.\nM30\n",
                              ConvertOptions(FANUC, FANUC, units="inch"))
    assert out == "N1 G20 G90\nN2 G01 X0.3937 Y1. F3.937\nM30\n"  # 10 mm to 0.0001 in
    # an inch program converted without a unit change keeps its four decimals
    out, _ = convert_text("N1 G20\nN2 X1.0607 Y-0.0001\n", ConvertOptions(FANUC, FANUC))
    assert out == "N1 G20\nN2 X1.0607 Y-0.0001\n"
