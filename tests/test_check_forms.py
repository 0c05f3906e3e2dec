"""Programmed forms the checker follows as each control's documentation gives them, so that a
correct program is no false ERROR and a wrong one is still found: a SINUMERIK's polar moves
about its pole, its arc by opening angle and its absolute centre, its diameter modes and its
jump labels; HEIDENHAIN ISO's G90/G91 for the one coordinate after it, its tangential arc G06
and its mirror image G28; LinuxCNC's diameter mode G7 and its splines after an arc (run through
rs274 where it is installed); a macro call's argument addresses. Where a form cannot be
followed, the position it leaves is unknown and nothing is checked against it."""

from __future__ import annotations

from pathlib import Path

import pytest

from formats.convert import ConvertOptions, convert_text
from formats.parser import parse_text
from formats.profile import load_profile
from postproc.check import Checker

from .conftest import rs274_output


def found(text: str, profile: str) -> list[tuple[str, int]]:
    """(rule, line) of the warnings and errors of ``text``."""
    prof = load_profile(profile)
    read = parse_text(text, prof.dialect, errors="collect")
    return [(f.rule, f.line) for f in Checker(prof, "<input>").run(read)
            if f.severity in ("error", "warning")]


def rules(text: str, profile: str) -> set[str]:
    return {rule for rule, _ in found(text, profile)}


SINUMERIK = "G17 G71 G90\nG0 X0 Y0 Z5\nG1 Z-1 F100\n{}\nG0 Z50\nM30\n"


# -- SINUMERIK: polar moves about the pole ----------------------------------------------------

@pytest.mark.parametrize("body", [
    # G111: the pole from the workpiece zero; RP=10 AP=0 ends at X10 Y0
    "G111 X0 Y0\nG1 RP=10 AP=0\nG2 X0 Y10 I-10 J0",
    # G110: from the last programmed point (X10 Y0): the pole X10 Y0, the move to X10 Y5
    "G1 X10 Y0\nG110 X0 Y0\nG1 RP=5 AP=90\nG2 X15 Y0 I0 J-5",
    # G112: from the last pole; RP stays in force, AP alone moves on the circle
    "G111 X10 Y10\nG112 X-10 Y-10\nG1 RP=5 AP=0\nAP=90\nG3 X-5 Y0 I0 J-5",
    # the pole given by polar words itself
    "G111 RP=10 AP=90\nG1 RP=5 AP=0\nG2 X0 Y5 I-5 J0",
])
def test_a_polar_move_ends_where_rp_and_ap_put_it(body):
    assert rules(SINUMERIK.format(body), "sinumerik-840d") == set()


def test_an_arc_after_a_polar_move_is_still_checked():
    # X10 Y0 after the move; an arc about X0 Y0 to X0 Y15 has radii 10 and 15
    text = SINUMERIK.format("G111 X0 Y0\nG1 RP=10 AP=0\nG2 X0 Y15 I-10 J0")
    assert found(text, "sinumerik-840d") == [("TG403", 6)]


def test_with_no_pole_defined_the_workpiece_zero_is_the_pole():
    # "If no pole is defined, the origin of the current workpiece coordinate system will act as
    # the pole": RP=10 AP=0 is X10 Y0
    good = SINUMERIK.format("G1 RP=10 AP=0\nG2 X0 Y10 I-10 J0")
    assert found(good, "sinumerik-840d") == []
    wrong = SINUMERIK.format("G1 RP=10 AP=0\nG2 X0 Y15 I-10 J0")
    assert found(wrong, "sinumerik-840d") == [("TG403", 5)]


@pytest.mark.parametrize("body", [
    # an angle the checker does not follow, G91, a value not known, a pole from an unknown point
    "G111 X0 Y0\nG1 RP=10 AP=IC(30)\nG2 X0 Y15 I-10 J0",
    "G111 X0 Y0\nG91 G1 RP=10 AP=0\nG90 G2 X0 Y15 I-10 J0",
    "G111 X0 Y0\nG1 RP=R7 AP=0\nG2 X0 Y15 I-10 J0",
    "L100\nG110 X0 Y0\nG1 RP=10 AP=0\nG2 X0 Y15 I-10 J0",
])
def test_a_polar_end_not_known_leaves_the_position_unknown(body):
    # the arc after it is not measured from a guessed point
    assert rules(SINUMERIK.format(body), "sinumerik-840d") == set()


# -- SINUMERIK: opening angle, absolute centre, soft approach ---------------------------------

def test_an_arc_by_opening_angle_and_end_point_is_no_missing_centre():
    text = SINUMERIK.format("G1 X10 Y0\nG3 X30 Y0 AR=180")
    assert rules(text, "sinumerik-840d") == set()


def test_an_arc_by_centre_and_opening_angle_ends_where_the_angle_turns_it():
    # from X10 Y0 about X0 Y0, 90 degrees clockwise: X0 Y-10; the next arc is measured from there
    good = SINUMERIK.format("G1 X10 Y0\nG2 I-10 J0 AR=90\nG2 X-10 Y0 I0 J10")
    assert rules(good, "sinumerik-840d") == set()
    wrong = SINUMERIK.format("G1 X10 Y0\nG2 I-10 J0 AR=90\nG2 X-10 Y0 I0 J5")
    assert found(wrong, "sinumerik-840d") == [("TG403", 6)]


def test_an_absolute_centre_is_read_as_the_centre():
    good = SINUMERIK.format("G1 X10 Y0\nG2 X30 Y0 I=AC(20) J=AC(0)")
    assert found(good, "sinumerik-840d") == []
    wrong = SINUMERIK.format("G1 X10 Y0\nG2 X30 Y0 I=AC(25) J=AC(0)")
    assert found(wrong, "sinumerik-840d") == [("TG403", 5)]
    # IC(..) is the increment I is by default
    assert found(SINUMERIK.format("G1 X10 Y0\nG2 X30 Y0 I=IC(10) J0"), "sinumerik-840d") == []


@pytest.mark.parametrize("block", ["G147 X30 Y10 DISR=5", "G63 Z-10 F100 S200",
                                   "G331 Z-10 K1.5 S200"])
def test_a_move_of_its_own_after_an_arc_is_no_arc(block):
    text = SINUMERIK.format(f"G1 X10\nG2 X20 Y0 I5 J0\n{block}")
    assert rules(text, "sinumerik-840d") == set()


# -- SINUMERIK: diameter programming ----------------------------------------------------------

LATHE = "G18 G71 G90 G95 {mode}\nT1 D1\nG0 X40 Z2 S500 M3\nG1 Z0 F0.2\n{body}\nG0 X100 Z50\nM30\n"


def test_under_diamon_x_is_a_diameter_and_the_centre_a_radius():
    body = "G1 X50\nG3 X60 Z-5 CR=5\nG1 Z-20\nG2 X80 Z-30 I10 K0"
    assert rules(LATHE.format(mode="DIAMON", body=body), "sinumerik-840d") == set()
    # the same words as radii are two wrong arcs
    assert found(LATHE.format(mode="DIAMOF", body=body), "sinumerik-840d") == [
        ("TG410", 6), ("TG403", 8)]


def test_under_diam90_an_increment_is_a_radius():
    # X50 (a diameter: 25 from the axis), G91 X5 (a radius: to 30), an arc about X40 Z-20
    body = "G1 X50 Z-20\nG91 X5\nG90 G2 X80 Z-30 I10 K0"
    assert rules(LATHE.format(mode="DIAM90", body=body), "sinumerik-840d") == set()
    assert "TG403" in rules(LATHE.format(mode="DIAMON", body=body), "sinumerik-840d")


# -- SINUMERIK: jump labels -------------------------------------------------------------------

JUMPS = "G17 G71 G90\nR1=1\nTOP:\n{}\nN50 G0 X10\nEND1:\nM30\n"


@pytest.mark.parametrize("jump, line", [
    ("IF R1==1 GOTOF MISSING", 4),
    ("GOTOB END1", 4),       # END1 is after it: GOTOB searches toward the start
    ("GOTOF TOP", 4),        # and GOTOF toward the end
    ("GOTO N60", 4),
])
def test_a_jump_to_a_label_not_there_is_an_alarm(jump, line):
    assert found(JUMPS.format(jump), "sinumerik-840d") == [("TG118", line)]


@pytest.mark.parametrize("jump", [
    "IF R1==1 GOTOF END1", "GOTOB TOP", "GOTO TOP", "GOTOF N50", "GOTOC MISSING",
])
def test_a_jump_to_its_label_is_quiet(jump):
    assert found(JUMPS.format(jump), "sinumerik-840d") == []


def test_a_jump_to_a_string_variable_is_not_followed():
    text = JUMPS.format('DEF STRING[8] ZIEL="TOP"\nGOTOB ZIEL')
    assert "TG118" not in rules(text, "sinumerik-840d")


def test_iso_dialect_codes_are_alarms_on_the_840d_in_siemens_mode():
    text = SINUMERIK.format("G43 Z50\nG81 X10 Y10 Z-5 F100\nG80")
    assert [r for r in found(text, "sinumerik-840d") if r[0] == "TG306"] == [
        ("TG306", 4), ("TG306", 5), ("TG306", 6)]


# -- HEIDENHAIN ISO ---------------------------------------------------------------------------

HEIDENHAIN = ("%T3 G71 *\nN10 G99 T1 L+0 R+5 *\nN20 T1 G17 S2000 *\nN30 G00 G40 G90 Z+100 M03 *\n"
              "N40 X+0 Y+0 *\nN50 G01 Z-2 F200 *\nN55 X+10 Y+0 *\n{}\nN80 G00 Z+100 M30 *\n"
              "N99999 %T3 G71 *\n")


@pytest.mark.parametrize("body", [
    # the TNC manual's own block: X incremental, Y absolute, about the CC X+10 Y-5
    "N60 I+10 J-5 *\nN70 G02 G91 X+5 G90 Y-5 *",
    # the CC itself: I incremental from X+10, J absolute
    "N60 G91 I+0 G90 J-5 *\nN70 G02 G90 X+15 Y-5 *",
    # G91 for the whole block: the CC is an increment from the last point
    "N60 G91 I+0 J-5 *\nN70 G90 G02 X+15 Y-5 *",
])
def test_heidenhain_g90_g91_apply_to_the_coordinate_after_them(body):
    assert rules(HEIDENHAIN.format(body), "heidenhain-iso") == set()


def test_heidenhain_a_wrong_arc_after_mixed_distance_words_is_still_found():
    # from X+10 Y+0 about the CC X+10 Y-5: X+5 absolute, Y-5 incremental is X+5 Y-5 (radii 5
    # and 5); Y-10 incremental is X+5 Y-10 (radii 5 and 7.07)
    text = HEIDENHAIN.format("N60 I+10 J-5 *\nN70 G02 G90 X+5 G91 Y-5 *")
    assert rules(text, "heidenhain-iso") == set()
    wrong = HEIDENHAIN.format("N60 I+10 J-5 *\nN70 G02 G90 X+5 G91 Y-10 *")
    assert found(wrong, "heidenhain-iso") == [("TG403", 9)]


def test_heidenhain_g06_is_the_tangential_arc():
    text = HEIDENHAIN.format("N60 G01 X+60 Y+60 *\nN70 G06 X+80 Y+50 *")
    assert "TG407" not in rules(text, "heidenhain-iso")


def test_heidenhain_mirror_image_names_its_axes_without_values():
    text = HEIDENHAIN.format("N60 G28 X *\nN65 G01 X+20 Y+20 *\nN70 G28 X Y *\nN75 G28 *")
    assert rules(text, "heidenhain-iso") == set()
    same = ConvertOptions(load_profile("heidenhain-iso"), load_profile("heidenhain-iso"))
    assert convert_text(text, same)[0] == text
    # elsewhere an address still needs its number
    assert "TG100" in rules(HEIDENHAIN.format("N60 G01 X *"), "heidenhain-iso")


# -- LinuxCNC ---------------------------------------------------------------------------------

LINUXCNC = "G21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F100\n{}\nG0 Z5\nM2\n"


@pytest.mark.parametrize("body", [
    "G7\nG18\nG2 X20 Z-1 I5 K0\nG8",
    "G18\nG7\nG1 X20\nG2 X40 Z-11 I0 K-10\nG8",
    "G2 X10 Y0 I5 J0\nG5 I2 J2 P-2 Q2 X20 Y0",
    "G2 X10 Y0 I5 J0\nG5.2 X20 Y0 P1 L3\nX30 Y5 P1\nG5.3",
    "G2 X10 Y0 I5 J0\nG5.1 X20 Y0 I2 J2",
])
def test_linuxcnc_diameter_mode_and_splines_after_an_arc(tmp_path: Path, body):
    text = LINUXCNC.format(body)
    assert rules(text, "linuxcnc") == set()
    out = rs274_output(tmp_path, text)
    assert "PROGRAM_END" in out and "error" not in out.lower(), out


def test_linuxcnc_radius_mode_again_after_g8(tmp_path: Path):
    # G8: X20 is a radius again, the arc about X5 has radii 5 and 15 (rs274 refuses it)
    text = LINUXCNC.format("G7\nG8\nG18\nG2 X20 Z-1 I5 K0")
    assert found(text, "linuxcnc") == [("TG403", 7)]
    assert "PROGRAM_END" not in rs274_output(tmp_path, text)


def test_linuxcnc_a_fanuc_style_subprogram_after_the_end_is_read(tmp_path: Path):
    text = ("%\nO1\nG21 G90 G17\nG0 X0 Y0 Z5.\nM98 P1000 L3\nG0 Z50.\nM30\n"
            "O1000\nG91 G1 Z-1. F100.\nG90\nM99\n%\n")
    assert "TG117" not in rules(text, "linuxcnc")
    assert rs274_output(tmp_path, text).count("STRAIGHT_FEED") == 3
    # a line after the end that is no subprogram is still never read
    assert ("TG117", 8) in found(text.replace("O1000\n", "G0 X5\n"), "linuxcnc")


# -- FANUC macro call arguments ---------------------------------------------------------------

def test_a_macro_call_passes_every_argument_address():
    call = "%\nO1\nG21 G90 G17\nG65 P9000 X10. E1. H2. U1. V1. W1.\nM30\n%\n"
    assert "TG134" not in rules(call, "fanuc-mill")
    assert ("TG134", 4) in found(call.replace("G65 P9000", "G01"), "fanuc-mill")


def test_after_a_call_the_pole_is_not_known():
    # the subprogram may set another pole: the polar move after it is not followed
    text = SINUMERIK.format("G111 X0 Y0\nL100\nG1 X10 Y0\nG1 RP=10 AP=0\nG2 X0 Y15 I-10 J0")
    assert "TG403" not in rules(text, "sinumerik-840d")
