"""Words, variables and the program frame between two control families (docs/convert.md, "Words
and variables between families"): a word the target family reads as other data is refused at
its column, naming both meanings; a word both controls' documents read alike is carried.

Each program is the smallest one that converted "ok" into a program that moves elsewhere: a
SINUMERIK's T1 D1 for a FANUC with no tool length, a FANUC's G10 L10 for LinuxCNC setting tool 3
from the current position, #5001 (block end position) read as a LinuxCNC parameter that is 0.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys

import pytest

from formats.convert import ConvertOptions, convert_text
from formats.errors import ConversionError
from formats.profile import load_profile
from tests.conftest import ISO_MACROS, profile


def convert(text: str, source: str, target: str) -> str:
    out, _ = convert_text(text, ConvertOptions(target=profile(target),
                                               source=profile(source)))
    return out


def refused(text: str, source: str, target: str) -> ConversionError:
    with pytest.raises(ConversionError) as info:
        convert(text, source, target)
    assert info.value.code in ("conversion-meaning", "conversion-dialect"), info.value
    return info.value


SIN = "G17 G71 G90 G94 G54\n"
FANUC = "O1\nG21 G90 G17\n"
NGC = "G21 G90 G17\n"


# -- tool offsets: T and D on a SINUMERIK, D and H elsewhere, G43 without H ---------------------


@pytest.mark.parametrize("target", ["fanuc-mill", "haas-mill", "linuxcnc", "iso-mill"])
@pytest.mark.parametrize("block, column, word", [
    ("T1 D1", 4, "D1"),   # D: the edge's length and radius
    ("T1", 1, "T1"),      # T alone: its default edge D1 (MD20270), length included
    ("G0 Z50 D2", 8, "D2"),
])
def test_a_sinumerik_tool_offset_is_refused_for_a_control_whose_length_needs_g43(
        target, block, column, word):
    e = refused(f"{SIN}{block}\nM6\nG0 X0 Y0 Z50\nG1 Z-5 F100\nM30\n", "sinumerik-840d", target)
    assert (e.code, e.line, e.column) == ("conversion-meaning", 2, column)
    assert e.message.startswith(f"{word}: on a SINUMERIK")
    if target == "iso-mill":  # ISO 6983-1 leaves what an offset holds to the control
        assert "applies an offset only by the codes that name it (G41-G44)" in e.message
    else:
        assert "G43 H" in e.message and "radius offset number of G41/G42 only" in e.message


def test_an_okuma_target_is_told_its_own_length_code():
    # (no G54: an OSP's G54 is a tool length offset, a code the code tables refuse)
    e = refused("G17 G71 G90 G94\nT1 D1\nM6\nG0 X0 Y0 Z50\nM30\n", "sinumerik-840d",
                "okuma-mill")
    assert e.column == 4 and "applies a tool length only by G56 H" in e.message


def test_no_tool_and_no_offset_are_carried_and_a_sinumerik_keeps_its_own():
    text = f"{SIN}T0 D0\nG0 X0 Y0 Z50\nM30\n"
    assert convert(text, "sinumerik-840d", "fanuc-mill").splitlines()[1] == "T0 D0"
    own = f"{SIN}T1 D1\nM6\nG0 X0 Y0 Z50\nM30\n"
    assert convert(own, "sinumerik-840d", "sinumerik-840d") == own


@pytest.mark.parametrize("source, text, line, column, word", [
    # (an H beside G43 is refused at the G43 first: a SINUMERIK has no such code,
    # test_code_meanings)
    ("fanuc-mill", FANUC + "T1 M6\nG0 H1 Z50.\nM30\n", 4, 4, "H1"),
    ("fanuc-mill", FANUC + "G0 X0 Y0\nG1 G41 X10. D1 F100.\nM30\n", 4, 13, "D1"),
    ("linuxcnc", NGC + "T1 M6\nG0 H1 Z50\nM2\n", 3, 4, "H1"),
    ("iso-mill", "N1 G71 G90\nN2 G1 G41 X10 Y0 D1 F100\nN3 M30\n", 2, 18, "D1"),
])
def test_another_family_s_d_or_h_is_refused_for_a_sinumerik(source, text, line, column, word):
    e = refused(text, source, "sinumerik-840d")
    assert (e.code, e.line, e.column) == ("conversion-meaning", line, column)
    assert e.message.startswith(f"{word}: on a")  # a FANUC, an ISO 6983-1
    assert "on a SINUMERIK" in e.message


@pytest.mark.parametrize("source, target, text, line, column", [
    # LinuxCNC: the loaded tool's length; a FANUC: the H in force, none after reset
    ("linuxcnc", "fanuc-mill", NGC + "T1 M6\nG43\nG0 X0 Y0 Z5\nM2\n", 3, 1),
    ("fanuc-mill", "linuxcnc", FANUC + "T1 M6\nG0 G43 Z50.\nM30\n", 4, 4),
])
def test_g43_without_h_is_refused_between_linuxcnc_and_fanuc(source, target, text, line,
                                                              column):
    e = refused(text, source, target)
    assert (e.line, e.column) == (line, column)
    assert "LinuxCNC applies the length of the tool in the spindle" in e.message
    assert "H0, no offset" in e.message


def test_g43_with_its_offset_number_is_carried_between_linuxcnc_and_fanuc():
    out = convert(NGC + "T1 M6\nG43 H1\nG0 X0 Y0 Z5\nM2\n", "linuxcnc", "fanuc-mill")
    assert out.splitlines()[2] == "G43 H1"
    out = convert(FANUC + "T1 M6\nG0 G43 H1 Z50.\nM30\n", "fanuc-mill", "linuxcnc")
    assert out.splitlines()[3] == "G0 G43 H1 Z50."


# -- G10: the data each L sets -----------------------------------------------------------------


@pytest.mark.parametrize("source, target, block, column, meanings", [
    ("fanuc-mill", "linuxcnc", "G10 L10 P3 R150.", 5,
     ("the length geometry of tool offset H P", "tool P's table entry, set so that the "
      "current position becomes the given values")),
    ("fanuc-mill", "linuxcnc", "G10 L11 P3 R-0.05", 5, ("the length wear", "in G59.3")),
    ("fanuc-mill", "linuxcnc", "G10 L12 P3 R5.", 5,
     ("the radius geometry of tool offset D P", "no such G10 form")),
    ("fanuc-mill", "linuxcnc", "G10 L13 P3 R0.1", 5, ("the radius wear", "no such G10 form")),
    ("fanuc-mill", "linuxcnc", "G10 L1 P3 R150.", 5,
     ("offset memory A", "the tool table entry of tool P")),
    ("fanuc-mill", "linuxcnc", "G10 L20 P1 X0 Y0", 5,
     ("the additional work offset G54.1 P", "coordinate system P, set so that the current")),
    ("linuxcnc", "fanuc-mill", "G10 L20 P1 X0 Y0", 5,
     ("coordinate system P, set so that the current", "the additional work offset G54.1 P")),
    ("linuxcnc", "fanuc-mill", "G10 L1 P3 Z120 R5", 5,
     ("the tool table entry of tool P", "offset memory A")),
    ("fanuc-lathe", "linuxcnc", "G10 P3 X0.2 Z0.1", 1,
     ("a lathe's tool offset", "no such G10 form")),
])
def test_a_g10_whose_data_differs_is_refused_naming_both(source, target, block, column,
                                                         meanings):
    # (a FANUC lathe's G90 is a turning cycle, its plane ZX)
    head = {"linuxcnc": NGC, "fanuc-lathe": "O1\nG21\n"}.get(source, "O1\nG21 G90\n")
    # (a lathe's X, a diameter, is refused for a target that reads X as a length: Z alone)
    move = "G0 Z10." if source == "fanuc-lathe" else "G0 X50. Y40. Z10."
    e = refused(f"{head}{move}\n{block}\nG0 X10. Z10.\nM30\n", source, target)
    line = 3 if source == "linuxcnc" else 4
    assert (e.code, e.line, e.column) == ("conversion-meaning", line, column)
    for meaning in meanings:
        assert meaning in e.message


@pytest.mark.parametrize("source, target, block, column, why", [
    # LinuxCNC's R: the rotation of coordinate system P about Z
    ("linuxcnc", "fanuc-mill", "G10 L2 P1 R30 X0", 11, "has no rotation"),
    ("linuxcnc", "fanuc-mill", "G10 L2 P0 X10", 8, "the active coordinate system"),
    ("linuxcnc", "fanuc-mill", "G10 L2 P7 X10", 8, "G59.1-G59.3"),
    ("fanuc-mill", "linuxcnc", "G10 L2 P0 X10.", 8, "the external work offset"),
    # FANUC adds in G91; LinuxCNC sets (rs274: G91 G10 L2 P1 X5 -> SET_G5X_OFFSET(1, 5, ...))
    ("fanuc-mill", "linuxcnc", "G91 G10 L2 P1 X5.", 5, "adds G10 L2's values"),
])
def test_a_g10_l2_differs_by_its_p_r_or_distance_mode(source, target, block, column, why):
    head = NGC if source == "linuxcnc" else FANUC
    e = refused(f"{head}{block}\nG90\nM30\n", source, target)
    assert e.column == column and why in e.message, e


def test_a_g10_l2_of_g54_to_g59_in_g90_is_carried_both_ways():
    out = convert(FANUC + "G10 L2 P1 X-238.84 Y-125.05 Z-370.\nG54\nM30\n", "fanuc-mill",
                  "linuxcnc")
    assert out.splitlines()[2] == "G10 L2 P1 X-238.84 Y-125.05 Z-370."
    out = convert(NGC + "G10 L2 P6 X10 Y20\nG59\nM2\n", "linuxcnc", "fanuc-mill")
    assert out.splitlines()[1] == "G10 L2 P6 X10. Y20."


# -- variables ---------------------------------------------------------------------------------


@pytest.mark.parametrize("source, target, block, meanings", [
    ("fanuc-mill", "linuxcnc", "#100=#5001",
     ("#5001 is the block end position of an axis on a Custom Macro B",
      "a parameter of no documented use (nothing sets it: it reads 0) on a LinuxCNC")),
    ("fanuc-mill", "linuxcnc", "#3006=1(CHECK PART)", ("the stop with a message",)),
    ("fanuc-mill", "linuxcnc", "#3000=1(STOP)", ("the macro alarm",)),
    ("fanuc-mill", "linuxcnc", "#102=#4001", ("modal information",)),
    ("fanuc-mill", "linuxcnc", "#103=#2001", ("a tool offset value",)),
    ("fanuc-mill", "linuxcnc", "#1=#0", ("the vacant (null) variable",)),
    # (an ISO 6983-1 profile that reads `#`: the built-in ones do not, test_convert_target_reads)
    ("fanuc-mill", ISO_MACROS, "#100=#5041", ("the current position of an axis",
                                              "no fixed meaning")),
    ("linuxcnc", "fanuc-mill", "#1=#5420",
     ("the current position of an axis on a LinuxCNC", "a system variable on a Custom")),
    ("linuxcnc", "fanuc-mill", "#2=#5400", ("the number of the tool in the spindle",)),
    ("linuxcnc", "fanuc-mill", "#40=1", ("a user parameter on a LinuxCNC",
                                         "no variable (the control alarms)")),
    ("linuxcnc", "fanuc-mill", "#1000=1", ("a user parameter on a LinuxCNC",
                                           "an interface signal (PMC) variable")),
])
def test_a_variable_outside_both_families_user_ranges_is_refused(source, target, block,
                                                                 meanings):
    head = NGC if source == "linuxcnc" else FANUC
    e = refused(f"{head}G0 X10. Y20. Z5.\n{block}\nG0 Z50.\nM30\n", source, target)
    assert (e.code, e.column) == ("conversion-meaning", 1)
    for meaning in meanings:
        assert meaning in e.message, e.message


@pytest.mark.parametrize("source, target, block, what", [
    ("linuxcnc", "fanuc-mill", "#<depth>=2", "a named parameter"),
    ("linuxcnc", ISO_MACROS, "G1 X[#<_x>+1] F100", "a named parameter"),
    ("fanuc-mill", "linuxcnc", "#[#1]=5.", "a variable chosen by a value"),
])
def test_a_named_or_indirect_variable_is_refused_between_families(source, target, block, what):
    head = NGC if source == "linuxcnc" else FANUC
    e = refused(f"{head}#1=100\n{block}\nM30\n", source, target)
    assert what in e.message


def test_user_variables_are_carried_between_macro_b_linuxcnc_and_iso():
    text = FANUC + "#1=5.\n#100=[#1+2.]\n#500=[#100*2.]\nG0 X#100 Y#500 Z#33\nM30\n"
    assert convert(text, "fanuc-mill", "linuxcnc").splitlines()[2:5] == text.splitlines()[2:5]
    # (`#100=#1+2.`, the operation outside [ ], rs274 refuses: "Bad character '+' used";
    # review 20, finding 1)
    e = refused(text.replace("[#1+2.]", "#1+2."), "fanuc-mill", "linuxcnc")
    assert (e.code, e.line) == ("conversion-meaning", 4)
    assert "'+' after a value outside [ ]" in e.message
    ngc = NGC + "#1=5\n#31=[#1*2]\n#999=#31\nG0 X#999\nM2\n"
    assert convert(ngc, "linuxcnc", "fanuc-mill").splitlines()[1:4] == ngc.splitlines()[1:4]


# -- thread lead, helix turns ------------------------------------------------------------------


@pytest.mark.parametrize("source, target, text, column, letters", [
    ("sinumerik-840d", "fanuc-mill", SIN + "G1 Z-2 F200\nG33 Z-20 K1.5\nM30\n", 10,
     ("from I J K", "from F")),
    ("linuxcnc", "fanuc-mill", NGC + "G1 Z-2 F200\nG33 Z-20 K1.5\nM2\n", 10,
     ("from K", "from F")),
    ("fanuc-mill", "linuxcnc", FANUC + "G1 Z-2. F200.\nG33 Z-20. F1.5\nM30\n", 11,
     ("from F", "from K")),
    # a taper thread: LinuxCNC's K along the move, a SINUMERIK's along Z
    ("sinumerik-840d", "linuxcnc", SIN + "G1 Z-2 F200\nG33 X10 Z-20 K1.5\nM30\n", 14,
     ("alike only for a thread along Z",)),
])
def test_a_thread_lead_read_from_another_letter_is_refused(source, target, text, column, letters):
    e = refused(text, source, target)
    assert (e.code, e.line, e.column) == ("conversion-meaning", text.count("\n") - 1, column)
    for letter in letters:
        assert letter in e.message


def test_a_lead_along_z_is_carried_between_the_k_families():
    text = SIN + "G1 Z-2 F200\nG33 Z-20 K1.5\nM30\n"
    assert convert(text, "sinumerik-840d", "linuxcnc").splitlines()[2] == "G33 Z-20 K1.5"
    assert convert(text, "sinumerik-840d", "iso-mill").splitlines()[2] == "G33 Z-20 K1.5"


@pytest.mark.parametrize("target", ["fanuc-mill", "sinumerik-840d", "iso-mill"])
@pytest.mark.parametrize("arc, column", [
    ("G2 X10 Y0 Z-6 I5 J0 P3", 21),
    ("G2 X10 Y0 I5 J0\nX0 Y0 Z-6 I-5 J0 P2", 18),  # the arc in force, its P
])
def test_linuxcnc_helix_turns_are_refused_for_a_control_without_a_turn_count(target, arc,
                                                                            column):
    text = f"{NGC}G0 X0 Y0 Z5\nG1 Z-1 F100\n{arc}\nG0 Z5\nM2\n"
    e = refused(text, "linuxcnc", target)
    assert (e.code, e.line, e.column) == ("conversion-meaning", text.count("\n") - 2, column)
    assert "number of turns of a helix" in e.message


def test_a_dwell_p_under_an_arc_in_force_is_no_turn_count():
    text = f"{NGC}G0 X0 Y0 Z5\nG1 Z-1 F100\nG2 X10 Y0 I5 J0\nG4 P1.5\nM2\n"
    assert convert(text, "linuxcnc", "fanuc-mill").splitlines()[4] == "G4 P1500"


# -- subprogram calls, the HEIDENHAIN frame ----------------------------------------------------


@pytest.mark.parametrize("source, text, line, word", [
    ("fanuc-mill", FANUC + "G0 X0 Y0 Z5.\nM98 P1000 L3\nG0 Z50.\nM30\nO1000\nG91 G1 Z-1. "
     "F100.\nG90\nM99\n", 4, "M98"),
    ("fanuc-mill", FANUC + "G0 X0 Y0 Z5.\nM99\n", 4, "M99"),
    ("haas-mill", "O1\nG20 G90\nM97 P100\nM30\nN100 G0 X0\nM99\n", 3, "M97"),
    ("linuxcnc", NGC + "M98 P1000\nM2\n", 2, "M98"),
])
def test_a_subprogram_call_by_m98_is_refused_for_a_family_that_calls_otherwise(
        source, text, line, word):
    e = refused(text, source, "sinumerik-840d")
    assert (e.line, e.column) == (line, 1)
    assert e.message.startswith(f"{word}: a subprogram call or return")


def test_a_subprogram_call_is_carried_between_fanuc_and_linuxcnc():
    text = FANUC + "G0 X0 Y0 Z5.\nM98 P1000 L3\nG0 Z50.\nM30\n"
    assert convert(text, "fanuc-mill", "linuxcnc").splitlines()[3] == "M98 P1000 L3"


@pytest.mark.parametrize("source, text", [
    ("fanuc-mill", "%\nO1\nG21 G90 G17\nG0 X0 Y0 Z5.\nG30 G91 Z0\nM30\n%\n"),
    ("sinumerik-840d", SIN + "G0 X0 Y0 Z5\nM30\n"),
    ("iso-mill", "N1 G71 G90\nN2 G0 X0 Y0\nN3 M30\n"),
])
def test_a_program_of_another_family_is_not_converted_for_a_heidenhain(source, text):
    e = refused(text, source, "heidenhain-iso")
    assert (e.code, e.line, e.column) == ("conversion-dialect", 1, 1)
    assert "%NAME G71 *" in e.message and "G28 mirror image" in e.message


def test_a_heidenhain_program_still_converts_for_a_heidenhain():
    text = "%P G71 *\nN10 G00 G90 X+10 Y+0 Z+5 *\nN20 G01 Z-1 F100 *\nN99999 %P G71 *\n"
    assert convert(text, "heidenhain-iso", "heidenhain-iso") == text


# -- what LinuxCNC itself does with the words refused above (rs274 -g, where installed) ---------


@pytest.mark.skipif(shutil.which("rs274") is None, reason="LinuxCNC's rs274 is absent")
def test_rs274_reads_the_words_as_the_refusals_say(tmp_path):
    """#5001 is a parameter nothing sets (0) where #5420 is the position; G2's P is the turn
    count (ARC_FEED's rotation); G91 leaves G10 L2's value absolute (a FANUC would add it)."""
    program = tmp_path / "p.ngc"
    program.write_text("G21 G90 G17\nG0 X10 Y20 Z5\n#1=#5001\n#2=#5420\n(debug, #1 #2)\n"
                       "G0 X0 Y0\nG2 X10 Y0 Z-6 I5 J0 P3 F100\nG0 Z50\n"
                       "G10 L2 P1 X5\nG91\nG10 L2 P1 X5\nG90\nM2\n")
    home = tmp_path / "home"
    home.mkdir()
    run = subprocess.run(["rs274", "-g", str(program)], capture_output=True, text=True,
                         env={**os.environ, "HOME": str(home)}, cwd=tmp_path, timeout=60)
    calls = [line.split("N..... ", 1)[1] for line in run.stdout.splitlines()
             if "N..... " in line]
    assert 'MESSAGE(" 0.000000 10.000000")' in calls, calls
    assert any(c.startswith("ARC_FEED(10.0000, 0.0000, 5.0000, 0.0000, -3, -6.0000")
               for c in calls), calls
    offsets = [c.split(",")[1].strip() for c in calls if c.startswith("SET_G5X_OFFSET(1,")]
    # G54's X: 0 at the start, 5 after the G90 block and still 5 after the G91 one (not 10)
    assert offsets[0] == "0.0000" and set(offsets[1:]) == {"5.0000"}, calls


# -- codes of another function: the profiles' meaning keys (docs/profiles.md) ----------------------


@pytest.mark.parametrize("source, target, text", [
    # LinuxCNC G76 threading cycle, FANUC G76 fine boring cycle, both ways
    ("linuxcnc", "fanuc-mill", "G21 G90 G18\nG0 X20 Z5\nM3 S500\n"
     "G76 P1.5 Z-20 I-1 J0.2 K1 Q29.5 H3\nM2\n"),
    ("fanuc-mill", "linuxcnc", FANUC + "G0 X30. Y30. Z5.\nG76 X30. Y30. Z-10. R2. Q0.5 P500 "
     "F50.\nG80\nM30\n"),
    # SINUMERIK G58 (programmable axial offset) and G53 (one block in machine coordinates)
    # against ISO 6983's zero shift 5 and modal cancel
    ("sinumerik-840d", "iso-mill", SIN + "G1 X10 Y0 F100\nG58 X10 Y5\nG1 X20 Y0\nM30\n"),
    ("iso-mill", "sinumerik-840d", "N1 G71 G90\nN2 G58\nN3 G1 X10 Y0 F100\nN4 M30\n"),
])
def test_a_code_of_another_function_is_refused(source, target, text):
    with pytest.raises(ConversionError):
        convert(text, source, target)


def test_linuxcnc_g96_d_spindle_limit_is_refused_for_another_family():
    """LinuxCNC's G96 D is the spindle's speed limit (G-code reference, G96); a FANUC reads D
    as the cutter compensation offset number, so D250 would be carried as offset 250 and the
    limit lost. A Haas mill has no G96 at all (its profile lists none): refused at the code."""
    text = "G21 G17 G90\nG0 X0 Y0 Z5\nG96 D250 S100 M3\nG1 X10 F100\nM2\n"
    e = refused(text, "linuxcnc", "fanuc-mill")
    assert (e.line, e.column) == (3, 5)
    assert e.message.startswith("D250: LinuxCNC's maximum spindle speed under G96 (G96 D)")
    with pytest.raises(ConversionError) as info:
        convert(text, "linuxcnc", "haas-mill")
    assert (info.value.line, info.value.column) == (3, 1)
    assert info.value.message.startswith("G96: ") and "no such code" in info.value.message


def test_linuxcnc_g43_1_and_g90_1_are_refused_where_the_target_has_another_or_none():
    """G43.1 (a dynamic tool length offset on LinuxCNC) is a length compensation taken from H on
    a FANUC, and no code on a Haas mill; G90.1 (absolute arc centres) is no code of the FANUC
    mill profile: each refused at its code, not carried."""
    g431 = "G21 G17 G90\nT1 M6\nG43.1 Z0.5\nG0 X0 Y0 Z5\nM2\n"
    for target in ("fanuc-mill", "haas-mill"):
        with pytest.raises(ConversionError) as info:
            convert(g431, "linuxcnc", target)
        e = info.value
        assert (e.line, e.column) == (3, 1) and e.message.startswith("G43.1: "), e.message
    with pytest.raises(ConversionError) as info:
        convert("G21 G90 G17 G90.1\nG0 X5 Y0\nG2 X20 Y0 I15 J0 F100\nM2\n", "linuxcnc",
                "fanuc-mill")
    e = info.value
    assert (e.line, e.column) == (1, 13) and "no such code" in e.message, e.message


@pytest.mark.parametrize("target", ["fanuc-mill", "haas-mill", "okuma-mill", "sinumerik-840d"])
def test_linuxcnc_g64_without_p_is_carried_as_the_target_s_cutting_mode(target):
    """LinuxCNC's G64 alone blends at the best speed (G-code reference, G64), no exact stop at
    block ends: FANUC's, Haas's and OSP's cutting mode, SINUMERIK's continuous-path mode. The
    line of boomerangv4.nc (`G20 G90 G64 G40`) is carried as written."""
    text = "G21 G90 G64 G40\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10\nM2\n"
    assert "G64" in convert(text, "linuxcnc", target).splitlines()[0]


@pytest.mark.parametrize("target", ["fanuc-mill", "haas-mill", "okuma-mill", "sinumerik-840d"])
@pytest.mark.parametrize("block, column, word", [
    ("G64 P0.01", 5, "P0.01"), ("G64 P0.01 Q0.005", 5, "P0.01"), ("G64 Q0.005", 5, "Q0.005"),
])
def test_linuxcnc_g64_tolerance_is_refused_for_another_family(target, block, column, word):
    """No other family's G64 reads a tolerance: G64 P Q is refused at its first tolerance."""
    e = refused(f"G21 G90\n{block}\nG0 X0 Y0 Z5\nM2\n", "linuxcnc", target)
    assert (e.code, e.line, e.column) == ("conversion-meaning", 2, column)
    assert e.message.startswith(f"{word}: LinuxCNC's path blending tolerance (G64 P, Q)")


def test_a_g64_tolerance_stays_converted_within_linuxcnc_and_fanuc_g64_reaches_linuxcnc():
    """Within LinuxCNC the tolerance is a length, converted with the units; FANUC's cutting mode
    is LinuxCNC's G64 without P."""
    out = convert_text("G20 G90\nG64 P0.01\nG0 X1 Y0\nM2\n",
                       ConvertOptions(target=load_profile("linuxcnc"), units="metric",
                                      source=load_profile("linuxcnc")))[0]
    assert "G64 P0.254" in out
    assert "G64" in convert(FANUC + "G64\nG0 X0 Y0\nM30\n", "fanuc-mill", "linuxcnc")


# -- M codes between families -----------------------------------------------------------------


@pytest.mark.parametrize("source, target, text, line, code, target_side", [
    # LinuxCNC's digital and analog I/O against a Haas's user relays cleared (mill operator's
    # manual, M61-M68), and against a FANUC, whose table has no such code
    ("linuxcnc", "haas-mill", NGC + "M64 P0\nM2\n", 2, "M64", "optional user M code clear"),
    ("linuxcnc", "haas-mill", NGC + "M66 P0 L3 Q5\nM2\n", 2, "M66", "relay 6"),
    ("linuxcnc", "haas-mill", NGC + "M68 E0 Q2.5\nM2\n", 2, "M68", "relay 8"),
    ("linuxcnc", "fanuc-mill", NGC + "M64 P0\nM2\n", 2, "M64", "no such code"),
    # a Haas's jump if no input: no code of an OSP mill
    ("haas-mill", "okuma-mill", FANUC + "M96 P10 Q1\nM30\n", 3, "M96", "no such code"),
    # a Haas's shower coolant, an OSP's oil mist
    ("haas-mill", "okuma-mill", FANUC + "M07\nM30\n", 3, "M07", "oil mist coolant on"),
])
def test_an_m_code_of_another_function_is_refused_naming_both(source, target, text, line,
                                                              code, target_side):
    with pytest.raises(ConversionError) as info:
        convert(text, source, target)
    e = info.value
    assert (e.line, e.column) == (line, 1), e.message
    assert e.message.startswith(f"{code}: the source and target controls give this code "
                                "different meanings"), e.message
    assert target_side in e.message


@pytest.mark.parametrize("source, target", [
    ("fanuc-mill", "okuma-mill"), ("fanuc-mill", "sinumerik-840d"), ("fanuc-mill", "linuxcnc"),
    ("okuma-mill", "fanuc-mill"), ("fanuc-mill", "haas-mill"), ("haas-mill", "fanuc-mill"),
])
def test_m_codes_of_one_function_are_carried_between_families(source, target):
    """Program stop and end, spindle, tool change and coolant: keyed alike in the profiles
    from the controls' manuals (docs/profiles.md, "Code meanings"), carried as written."""
    body = "T1 M06\nM03 S1000\nM08\nG0 X0 Y0\nM01\nM00\nM09\nM05\nM19\nM30\n"
    if target == "linuxcnc" or source == "linuxcnc":
        body = body.replace("M19\n", "")  # LinuxCNC's M19 orients to R (0): another function
    if "sinumerik" in target:
        body = body.replace("M08\n", "").replace("M09\n", "")  # no coolant code of its own
    out = convert(FANUC + body, source, target)
    for code in ("M06", "M03", "M01", "M00", "M05", "M30"):
        assert code in out, (code, out)


def test_a_haas_orientation_angle_is_refused_and_plain_m19_carried():
    """A Haas's M19 P (whole degrees) or R: a FANUC's M19 takes no angle (it orients to the
    parameter's position): refused at the angle; M19 alone is carried."""
    e = refused(FANUC + "M19 P90\nM30\n", "haas-mill", "fanuc-mill")
    assert (e.line, e.column) == (3, 5)
    assert e.message.startswith("P90: a Haas's spindle orientation angle (M19 P, R)")
    e = refused(FANUC + "M19 R45.5\nM30\n", "haas-mill", "okuma-mill")
    assert e.message.startswith("R45.5: a Haas's spindle orientation angle")
    assert "M19\n" in convert(FANUC + "M19\nM30\n", "haas-mill", "fanuc-mill")


# -- letter case: LinuxCNC and SINUMERIK read lower case, a FANUC or Haas does not -------------


@pytest.mark.parametrize("source, head", [("linuxcnc", NGC), ("sinumerik-840d", SIN)])
@pytest.mark.parametrize("target", ["fanuc-mill", "haas-mill"])
def test_a_lower_case_word_is_written_in_upper_case_for_a_control_that_reads_none(
        source, head, target):
    """Review 16c, finding 5: `g1 x2.5 y-.5 f100` was carried as written to a FANUC, which
    alarms on a lower-case address (TG101 on the output). The word is the upper-case one to
    the source, and written so; a comment keeps its text, and the proof holds it the same
    word."""
    from postproc.check import check_text

    text = f"{head}g0 x0 y0 z5. (move up)\ng1 x2.5 y-.5 f100\nm30\n"
    out = convert(text, source, target)
    assert "G0 X0 Y0 Z5. (move up)\nG1 X2.5 Y-.5 F100" in out and "\nM30" in out, out
    lower = [f for f in check_text(out, load_profile(target)) if f.rule == "TG101"]
    assert lower == []


def test_a_lower_case_expression_is_written_in_upper_case_and_verified(tmp_path):
    """`x[#1*2] y[sin[30]]`: the function's name too (a FANUC reads `SIN` alone); `--verify`
    reads the output as the same words."""
    source = tmp_path / "p.ngc"
    source.write_text("G21 G90 G17\ng0 x0 y0 z5.\n#1=2\ng1 x[#1*2] y[sin[30]] f100\nm2\n")
    target = tmp_path / "p.nc"
    run = subprocess.run([sys.executable, "-m", "tapegate", "convert", str(source),
                          "-o", str(target), "--from", "linuxcnc", "--to", "fanuc-mill",
                          "--verify"],
                         capture_output=True, text=True, timeout=120, env=os.environ.copy())
    assert run.returncode == 0, run.stdout + run.stderr
    assert "verified" in run.stdout
    assert "G1 X[#1*2] Y[SIN[30]] F100" in target.read_text()


def test_a_target_that_reads_lower_case_keeps_the_words_as_written():
    text = f"{NGC}g0 x0 y0 z5.\ng1 x2.5 f100\nm2\n"
    assert "g1 x2.5 f100" in convert(text, "linuxcnc", "linuxcnc")


def test_a_haas_lower_case_program_number_is_written_upper_case_for_another_control():
    """A Haas reads `o40001` as its program number (NGC manual 5.3.1: "The letter O, or o"),
    a FANUC reads no lower-case address: the `o` was carried as written and the output drew
    TG101 on its own profile. Written `O40001`; a Haas target keeps the `o`."""
    from postproc.check import check_text

    target = "fanuc-mill"
    text = "o40001 (part)\nG21 G90 G17\nG0 X1. Y2.\nM30\n"
    out = convert(text, "haas-mill", target)
    assert "O40001 (part)" in out and "o40001" not in out, out
    assert [f for f in check_text(out, load_profile(target)) if f.rule == "TG101"] == []
    assert "o40001 (part)" in convert(text, "haas-mill", "haas-mill")


# -- a letter the source reads that LinuxCNC reads otherwise or refuses: E, a lathe's U W -------


@pytest.mark.parametrize("source, text, line, column, word", [
    # a FANUC mill's E (not in its profile's classification, TG134) beside a G1
    ("fanuc-mill", FANUC + "G0 X0 Y0\nG1 X1. E2. F100.\nM30\n", 4, 8, "E2."),
    # after a variable, `X#1E2` is X#1 and E2 (the word the source's reader splits it into)
    ("fanuc-mill", FANUC + "#1=2.\nG0 X#1E2\nM30\n", 4, 7, "E2"),
    ("haas-mill", FANUC + "G0 X0 Y0\nG1 X1. E2. F100.\nM30\n", 4, 8, "E2."),
    # (Z alone: a lathe's X, a diameter, is refused for LinuxCNC at the first X)
    ("okuma-lathe", "G0 Z20\nG1 Z10 E1 F0.1\nM02\n", 2, 8, "E1"),
])
def test_an_e_word_no_linuxcnc_code_uses_is_refused(source, text, line, column, word):
    e = refused(text, source, "linuxcnc")
    assert (e.line, e.column) == (line, column), e
    assert e.message.startswith(f"{word}: E word with no G70, G76, M66, M67 or M68 to use it"), e
    assert "no LinuxCNC word that carries it" in e.message


@pytest.mark.parametrize("source", ["fanuc-lathe", "haas-lathe"])
@pytest.mark.parametrize("block, column, word", [
    ("G1 U2. F0.2", 4, "U2."),
    ("G1 W-1. F0.2", 4, "W-1."),
])
def test_a_lathe_s_incremental_u_w_is_refused_for_linuxcnc(source, block, column, word):
    # (no X before: a lathe's X, a diameter, is refused for LinuxCNC at the first X word)
    e = refused(f"O1\nG21 G18\nG0 Z0.\n{block}\nM30\n", source, "linuxcnc")
    assert (e.line, e.column) == (4, column), e
    assert e.message.startswith(f"{word}: the source lathe reads U and W as increments of X and Z")


@pytest.mark.parametrize("block, column, word", [("G1 U5. F0.2", 4, "U5."),
                                                 ("G1 X12. W-1. F0.2", 9, "W-1.")])
def test_an_iso_lathe_s_u_w_is_refused_for_linuxcnc_as_axes_of_their_own(block, column, word):
    # ISO 6983-1, Annex A: U and W are secondary dimensions parallel to X and Z, not
    # increments (review 23: the refusal said increments)
    e = refused(f"%\nN1 G21 G90 G18\nN2 G00 X20. Z2.\nN3 {block}\nN4 M30\n", "iso-lathe",
                "linuxcnc")
    assert (e.line, e.column) == (4, column + 3), e
    assert e.message.startswith(f"{word}: the source (ISO 6983-1, Annex A) reads U and W as "
                                "secondary axes of their own, parallel to X and Z"), e
    assert "increments" not in e.message


def test_a_lathe_s_dwell_u_still_converts_for_linuxcnc():
    out = convert("O1\nG21 G18\nG0 Z0.\nG4 U1.5\nM30\n", "fanuc-lathe", "linuxcnc")
    assert "G4 P1.5" in out and "U" not in out.split("O1", 1)[1]


# A dwell's time by a parameter or an expression between controls that read the time in
# other units (a FANUC or Haas G04 P and a cycle's P: milliseconds; LinuxCNC's P: seconds):
# carried as written, 1500 ms would be 1500 s (review 23, finding 1). Refused at the word.
@pytest.mark.parametrize("source, target, text, line, column, word", [
    ("fanuc-mill", "linuxcnc", FANUC + "#1=1500\nG04 P#1\nM30\n", 4, 5, "P#1"),
    ("haas-mill", "linuxcnc", FANUC + "#1=1500\nG04 P#1\nM30\n", 4, 5, "P#1"),
    ("fanuc-mill", "linuxcnc", FANUC + "G04 P[1500]\nM30\n", 3, 5, "P[1500]"),
    ("fanuc-mill", "linuxcnc",
     FANUC + "#1=500\nG0 X0 Y0 Z5.\nG98 G82 X1. Y1. Z-1. R1. P#1 F100.\nG80\nM30\n", 5, 26,
     "P#1"),
    ("fanuc-lathe", "linuxcnc", "O1\nG21 G18\n#1=1500\nG04 P#1\nM30\n", 4, 5, "P#1"),
    # a lathe's seconds in X or U (review 23, finding 2: U#1 reached rs274 as a U axis)
    ("fanuc-lathe", "linuxcnc", "O1\nG21 G18\n#1=1.5\nG04 U#1\nM30\n", 4, 5, "U#1"),
    ("fanuc-lathe", "linuxcnc", "O1\nG21 G18\nG04 U[1.5]\nM30\n", 3, 5, "U[1.5]"),
    ("haas-lathe", "linuxcnc", "O1\nG21 G18\n#1=1.5\nG04 X#1\nM30\n", 4, 5, "X#1"),
    # LinuxCNC's seconds for a FANUC's milliseconds
    ("linuxcnc", "fanuc-mill", "G21 G90\n#1=2\ng4 p#1\nm2\n", 3, 4, "p#1"),
    ("linuxcnc", "haas-mill", "G21 G90\ng4 p[2]\nm2\n", 2, 4, "p[2]"),
    ("linuxcnc", "fanuc-mill",
     "G21 G90\n#1=2\ng0 x0 y0 z5\ng82 x1 y1 z-1 r1 p#1 f100\ng80\nm2\n", 4, 18, "p#1"),
])
def test_a_dwell_time_by_a_parameter_is_refused_between_time_units(source, target, text, line,
                                                                   column, word):
    with pytest.raises(ConversionError) as info:
        convert(text, source, target)
    e = info.value
    assert (e.line, e.column) == (line, column), e
    assert e.message.startswith(f"{word}: a dwell's time given by a parameter or an "
                                "expression, where the controls write the time differently"), e
    # the same time as a plain number converts
    plain = text.replace(word, "P1500" if target == "linuxcnc" else "p2", 1)
    if word[0] in "UX":
        plain = text.replace(word, f"{word[0]}1.5", 1)
    convert(plain, source, target)


@pytest.mark.parametrize("text", [
    FANUC + "#1=1500\nG04 P#1\nM30\n",
    "O1\nG21 G18\nG04 P[1500]\nM30\n",
])
def test_a_dwell_time_by_a_parameter_stays_as_written_within_a_family(text):
    # FANUC to Haas: both read the time in the same unit, the word is carried
    out = convert(text, "fanuc-mill", "haas-mill")
    assert out == text


def test_the_proof_tells_a_dwell_parameter_in_milliseconds_from_one_in_seconds(tmp_path):
    """`--verify` reads a parameter's value in neither program, but a FANUC P#1 in G04 is
    milliseconds and a LinuxCNC P#1 seconds: the same text is another time."""
    from formats.convert import convert_file
    from formats.verify import verify_conversion

    source, target = load_profile("fanuc-mill"), load_profile("linuxcnc")
    options = ConvertOptions(target=target, source=source)
    plain = tmp_path / "plain.nc"
    plain.write_text(FANUC + "#1=1500\nG04 P1500\nM30\n")
    stats = convert_file(str(plain), str(tmp_path / "plain.ngc"), options, verify=True)
    assert stats.verified
    (tmp_path / "p.nc").write_text(FANUC + "#1=1500\nG04 P#1\nM30\n")
    (tmp_path / "p.ngc").write_text(FANUC + "#1=1500\nG04 P#1\nM30\n")
    with pytest.raises(ConversionError) as info:
        verify_conversion(str(tmp_path / "p.nc"), str(tmp_path / "p.ngc"), source, options,
                          stats, file="p.nc")
    assert (info.value.code, info.value.line) == ("conversion-verify", 4)
    # a Haas reads it as the FANUC does: the same text proves
    haas = load_profile("haas-mill")
    verify_conversion(str(tmp_path / "p.nc"), str(tmp_path / "p.nc"), source,
                      ConvertOptions(target=haas, source=source), stats, file="p.nc")


# Two time words in one G04 (review 23, finding 2): LinuxCNC reads one P and refuses two; a
# W beside a dwell's U is refused as any W is.
@pytest.mark.parametrize("source", ["fanuc-lathe", "haas-lathe"])
@pytest.mark.parametrize("block, column, word, why", [
    ("G04 X1. U1.", 9, "U1.", "a second time word in the dwell's block (beside X1.)"),
    ("G04 P1000 U1.", 11, "U1.", "a second time word in the dwell's block (beside P1000)"),
    ("G04 X1. P500", 9, "P500", "a second time word in the dwell's block (beside X1.)"),
    ("G04 X1. W1.", 9, "W1.", "the source lathe reads U and W as increments of X and Z"),
])
def test_a_lathe_dwell_with_two_time_words_or_a_w_is_refused_for_linuxcnc(source, block,
                                                                          column, word, why):
    with pytest.raises(ConversionError) as info:
        convert(f"O1\nG21 G18\nG0 Z0.\n{block}\nM30\n", source, "linuxcnc")
    e = info.value
    assert (e.line, e.column) == (4, column), e
    assert e.message.startswith(f"{word}: {why}"), e


def test_a_mill_dwell_with_two_time_words_is_refused_for_linuxcnc():
    with pytest.raises(ConversionError) as info:
        convert(FANUC + "G04 X1. P500\nM30\n", "fanuc-mill", "linuxcnc")
    assert (info.value.line, info.value.column) == (3, 9), info.value
    assert "Multiple p words on one line" in info.value.message


@pytest.mark.parametrize("text, said", [
    # what the refused forms would do carried as written: 1500 s, and rs274's refusals
    ("G21\n#1=1500\nG4 P#1\nM2\n", "DWELL(1500.0000)"),
    ("G21\nG4 P[1500]\nM2\n", "DWELL(1500.0000)"),
    ("G21\n#1=1.5\nG4 U#1\nM2\n", "Bad character 'u' used"),
    ("G21\nG0 X0\n#1=1.5\nG4 X#1\nM2\n", "Dwell time missing with g4"),
    ("G21\nG4 P1. P1.\nM2\n", "Multiple p words on one line"),
])
def test_rs274_reads_the_refused_dwells_otherwise(tmp_path, text, said):
    from tests.conftest import rs274_output
    assert said in rs274_output(tmp_path, text)


@pytest.mark.parametrize("text", [
    FANUC + "G0 X0 Y0\nG1 X1. E2. F100.\nM30\n",
    FANUC + "#1=2.\nG0 X#1E2\nM30\n",
    "O1\nG21 G18\nG0 X10. Z0.\nG1 U2. F0.2\nM30\n",
    FANUC + "G0 X0 Y0\nG1 X1. D1 F100.\nM30\n",
    FANUC + "G0 X0 Y0\nG0 Z50. H1\nM30\n",
])
def test_rs274_refuses_the_words_carried_as_written(tmp_path, text):
    from tests.conftest import rs274_output
    out = rs274_output(tmp_path, text)
    assert any(said in out for said in (
        "E word with no G70, G76, M66, M67 or M68 to use it", "Bad character 'u' used",
        "D word with no G41", "H word with no G43 or G76 to use it")), out


@pytest.mark.parametrize("source", ["fanuc-mill", "haas-mill"])
@pytest.mark.parametrize("block, column, word, why", [
    # a FANUC or Haas keeps the offset number for a later G41/G42 or G43
    ("G1 X1. D1 F100.", 8, "D1", "D word with no G41, G41.1, G42, G42.1, G71, G71.1, G71.2"),
    ("G0 Z50. H1", 9, "H1", "H word with no G43 or G76 to use it"),
    ("G49 H0", 5, "H0", "H word with no G43 or G76 to use it"),
])
def test_a_d_or_h_word_without_its_code_is_refused_for_linuxcnc(source, block, column, word,
                                                                why):
    e = refused(f"{FANUC}G0 X0 Y0\n{block}\nM30\n", source, "linuxcnc")
    assert (e.code, e.line, e.column) == ("conversion-meaning", 4, column), e
    assert e.message.startswith(f"{word}: {why}"), e


def test_d_and_h_beside_their_codes_still_convert_for_linuxcnc(tmp_path):
    from tests.conftest import rs274_output
    text = FANUC + "G0 X0 Y0\nG43 Z50. H1\nG41 X50. D1\nG1 Y50. F100.\nG40 X0\nG49\nM30\n"
    out = convert(text, "fanuc-mill", "linuxcnc")
    assert "G43 Z50. H1" in out and "G41 X50. D1" in out
    said = rs274_output(tmp_path, out)
    assert "PROGRAM_END" in said and "word with no" not in said, said


# A dwell's F (fix24): ISO 6983-1 (clause 13), an Okuma or a HEIDENHAIN dwells by G04 F; a
# FANUC or Haas mill by X or P only (the FANUC machining-center manuals, "G04 X_ ; or G04 P_ ;"),
# its F in a G04 block being the feed. Neither form is carried to the other as written.
ISO_DWELL = "%\nN1 G21 G90 G17\nN2 G00 X0 Y0 Z10.\nN3 G04 F2.\nN4 M30\n"


def dwell_refused(text: str, source: str, target: str) -> ConversionError:
    with pytest.raises(ConversionError) as info:
        convert(text, source, target)
    return info.value


@pytest.mark.parametrize("target", ["fanuc-mill", "haas-mill"])
def test_an_iso_dwell_by_f_is_refused_for_a_fanuc_or_haas_mill(target):
    e = dwell_refused(ISO_DWELL, "iso-mill", target)
    assert (e.code, e.line, e.column) == ("conversion", 4, 8), e
    assert e.message.startswith("F2.: the dwell's time by F, which the target control reads "
                                "as a feed"), e
    assert '"G04 X_ ; or G04 P_ ;"' in e.message
    # a FANUC lathe's G04 takes X, U or P: no F either
    lathe = "%\nN1 G21 G90 G18\nN2 G00 X10. Z10.\nN3 G04 F2.\nN4 M30\n"
    e = dwell_refused(lathe, "iso-lathe", "fanuc-lathe")
    assert (e.line, e.column) == (4, 8) and "F2.: the dwell's time by F" in e.message, e


def test_an_iso_dwell_by_x_or_p_is_carried_to_a_fanuc_mill_and_an_f_dwell_within_iso():
    for block in ("G04 X2.", "G04 P2000"):
        text = ISO_DWELL.replace("G04 F2.", block)
        assert block in convert(text, "iso-mill", "fanuc-mill")
    assert "N3 G04 F2.\n" in convert(ISO_DWELL, "iso-mill", "iso-mill")


@pytest.mark.parametrize("source", ["fanuc-mill", "haas-mill"])
def test_a_feed_in_a_fanuc_dwell_block_is_refused_where_f_is_the_dwell_and_kept_elsewhere(
        source):
    text = FANUC + "G00 X0 Y0 Z10.\nG04 X1. F200.\nG01 Z-2.\nM30\n"
    e = dwell_refused(text, source, "iso-mill")
    assert (e.code, e.line, e.column) == ("conversion", 4, 9), e
    assert e.message.startswith("F200.: a feed in the dwell's block, which the target control "
                                "reads as the dwell's time (ISO 6983-1, clause 13"), e
    # LinuxCNC reads G4 P1 F200 as a dwell of 1 s and a feed (rs274, the dwell section above)
    assert "G04 P1. F200.\n" in convert(text, source, "linuxcnc")
    other = "haas-mill" if source == "fanuc-mill" else "fanuc-mill"
    assert "G04 X1. F200.\n" in convert(text, source, other)


@pytest.mark.parametrize("name", ["fanuc-mill", "haas-mill"])
def test_the_check_reads_an_f_in_a_fanuc_mill_dwell_block_as_the_feed(name):
    """`G04 X1. F200.`: X is the dwell's time, F the feed in force after it (no TG401 at the
    G01 that follows); `G04 F2.` has no time word there (TG532). On ISO, F is the time."""
    from postproc.check import Checker

    def rules(text: str, profile_name: str) -> list[tuple[str, int]]:
        p = load_profile(profile_name)
        return [(f.rule, f.line) for f in Checker(p).run_stream([text], p.dialect)
                if f.rule in ("TG401", "TG531", "TG532")]

    text = ("%\nO1000\nN1 G21 G17 G90 G54\nN2 G00 X0 Y0 Z10.\nN3 G04 X1. F200.\nN4 G01 Z-2.\n"
            "M30\n%\n")
    assert rules(text, name) == [("TG531", 5)]
    assert rules(text, "iso-mill") == [("TG401", 6)]  # F200. a dwell's time there
    assert rules(ISO_DWELL + "%\n", name) == [("TG532", 4), ("TG531", 4)]
    assert rules(ISO_DWELL + "%\n", "iso-mill") == []


# -- an arc with R and I J K: a FANUC or Haas reads it by R, rs274 refuses it ----------------------


@pytest.mark.parametrize("source", ["fanuc-mill", "haas-mill"])
@pytest.mark.parametrize("block, column, word", [
    ("G2 X2. Y0 R0.5 I0.5", 16, "I0.5"),
    ("G3 X2. Y0 J0 R0.5", 11, "J0"),
    # the arc mode in force runs it
    ("X2. Y0 R0.5 I0.5", 13, "I0.5"),
])
def test_an_arc_with_r_and_i_j_k_is_refused_for_linuxcnc(tmp_path, source, block, column,
                                                         word):
    """FANUC Series 16/18-C Lathe Operator's Manual, "Circular interpolation": "If I, J, K, and
    R addresses are specified simultaneously, the arc specified by address R takes precedence
    and the other are ignored"; rs274: "Mixed radius ijk format for arc"."""
    head = f"{FANUC}G0 X0 Y0 Z5.\nS500 M3\nG1 X1. F100.\n"
    lead = "G2 X1.5 Y0.5 R0.5\n" if block.startswith("X") else ""
    text = f"{head}{lead}{block}\nM30\n"
    e = refused(text, source, "linuxcnc")
    line = 6 + bool(lead)
    assert (e.code, e.line, e.column) == ("conversion-meaning", line, column), e
    assert e.message.startswith(f"{word}: Mixed radius ijk format for arc"), e.message
    assert "reads the arc by its R and ignores I J K" in e.message, e.message
    # without the I J K word the arc converts, and rs274 runs it
    out = convert(text.replace(f" {word}", ""), source, "linuxcnc")
    from tests.conftest import rs274_output
    assert "PROGRAM_END" in rs274_output(tmp_path, out.replace("M30", "M2"))
    # carried as written, rs274 refuses it
    assert "Mixed radius ijk format for arc" in rs274_output(tmp_path, text.replace("O1\n", ""))


@pytest.mark.parametrize("source, target, block, meanings", [
    ("haas-mill", "fanuc-mill", "#1=#30003.078", ("a Haas NGC parameter element",)),
    ("haas-mill", "fanuc-mill", "#1=#3026", ("the tool in the spindle on a Haas",)),
    ("haas-mill", "fanuc-mill", "#101=#5201", ("the G52 work offset on a Haas",
                                               "external, G54-G59) on a FANUC")),
    ("fanuc-mill", "haas-mill", "#1=#2001", ("a tool offset value on a FANUC",
                                             "a tool length or diameter offset")),
    ("fanuc-mill", "haas-mill", "#750=1.", ("a common variable on a FANUC",
                                            "a number its table does not list on a Haas")),
    ("fanuc-mill", "haas-mill", "#720=1.", ("a hidden variable for the control's internal use",)),
    # review 35: the Haas's probe calibration, the groups numbered apart, FANUC's #3003 bit 1
    ("fanuc-mill", "haas-mill", "#550=1.", ("the probe's calibration data",)),
    ("haas-mill", "fanuc-mill", "#1=#580", ("the probe's calibration data",)),
    ("fanuc-mill", "haas-mill", "#31=#4014", ("its work coordinate system is group 12",)),
    ("haas-mill", "fanuc-mill", "#31=#4012", ("its work coordinate system is group 12",)),
    ("fanuc-mill", "haas-mill", "#3003=2", ("values 2 and 3",)),
    ("fanuc-mill", "haas-mill", "#1=#5227", ("X Y Z A B C on a mill",)),
    ("fanuc-lathe", "haas-lathe", "#1=#5041", ("a lathe's order is in no table at hand",)),
    ("haas-mill", "fanuc-mill", "#1=#101.5", ("outside the Haas NGC parameters",)),
    ("haas-mill", "fanuc-mill", "#10100=1.", ("its NGC number",)),
    ("fanuc-mill", "haas-mill", "#3901=#3901+1", ("the parts count on a FANUC",
                                                  "an M30 part counter on a Haas")),
    ("fanuc-mill", "haas-mill", "#[#1]=2.", ("a variable chosen by a value",)),
])
def test_a_variable_a_fanuc_and_a_haas_read_apart_is_refused_naming_both(source, target, block,
                                                                         meanings):
    """Review 33, doubtful: a FANUC and a Haas both write Custom Macro B, so the conversion
    carried every variable; but the NGC's Macro Variables Table (Mill Operator's Manual, NGC,
    2017, 6.14.7) gives many numbers other uses (`#30003.078`, a parameter element, which the
    FANUC profile's own check refuses, converted "ok"). A variable both leave to the program
    or read alike is carried; any other is refused at its word, naming both uses."""
    e = refused(f"O1\nG21 G90\n#1=1.\n{block}\nG0 X10. Y10.\nM30\n", source, target)
    assert (e.code, e.line, e.column) == ("conversion-meaning", 4, 1)
    for meaning in meanings:
        assert meaning in e.message, e.message


@pytest.mark.parametrize("block", ["#101=#5221+#5021", "#1=#3000", "#500=#4001",
                                   "#1=#5061", "#102=#7001", "#103=#14001", "#1=#3011",
                                   "#3004=2", "#3003=1", "#3003 = 0", "#1=#4003+#4120"])
def test_the_variables_a_fanuc_and_a_haas_read_alike_are_carried(block):
    """The work offsets G54-G59 and the additional ones laid out alike, the positions, the
    previous block's codes of the groups both number alike and its B D F H M S T, the alarm,
    the clocks, the feed hold bits of #3004 and single block suppression set 0 or 1 (the NGC
    table gives both FANUC's meaning: review 35): carried both ways as written."""
    text = f"O1\nG21 G90\n{block}\nG0 X10. Y10.\nM30\n"
    for source, target in (("fanuc-mill", "haas-mill"), ("haas-mill", "fanuc-mill")):
        assert block in convert(text, source, target)
