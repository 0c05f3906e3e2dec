"""FANUC lathes in G code system B and C (fanuc-lathe-b, fanuc-lathe-c): their code tables, the
modal state the checker follows by them, and conversion between the three systems.

The codes are those of the FANUC 0i-TF/30i-B lathe operator's manuals' G code list, columns A, B
and C (docs/dialects.md, "G code systems B and C"). Each program here is written for the test.
"""

from __future__ import annotations

from decimal import Decimal
from pathlib import Path

import pytest

from formats.convert import ConvertOptions, convert_file, convert_text
from formats.errors import ConversionError, ProfileError
from formats.parser import parse_text
from formats.profile import builtin_names, builtin_text, load_profile, profile_from_text
from postproc.check import check_text
from postproc.restart import RestartRefused, RestartWalk
from postproc.state import state_at

A, B, C = "fanuc-lathe", "fanuc-lathe-b", "fanuc-lathe-c"


def found(text: str, profile: str) -> list[tuple[str, int, str]]:
    """(rule, line, message) of every finding but the notes about style."""
    return [(f.rule, f.line, f.message) for f in check_text(text, load_profile(profile))
            if f.rule not in ("TG130", "TG133", "TG703")]


def state(text: str, profile: str, line: int):  # type: ignore[no-untyped-def]
    prof = load_profile(profile)
    return state_at(parse_text(text, prof.dialect), prof, line)


def options(source: str, target: str) -> ConvertOptions:
    return ConvertOptions(target=load_profile(target), source=load_profile(source))


def convert(text: str, source: str, target: str) -> str:
    out, _ = convert_text(text, options(source, target))
    return out


def proved(tmp_path: Path, text: str, source: str, target: str) -> str:
    """The conversion, read back and proved value by value (``convert --verify``)."""
    path = tmp_path / "p.nc"
    path.write_text(text)
    out = tmp_path / f"p-{target}.nc"
    convert_file(str(path), str(out), options(source, target), verify=True, overwrite=True)
    return out.read_text()


def refusal(text: str, source: str, target: str) -> ConversionError:
    with pytest.raises(ConversionError) as info:
        convert(text, source, target)
    return info.value


# -- the profiles ---------------------------------------------------------------------------


def test_the_three_systems_are_built_in_and_b_and_c_are_written_on_a():
    assert {A, B, C} <= set(builtin_names())
    a, b, c = (load_profile(p) for p in (A, B, C))
    assert (a.g_code_system, b.g_code_system, c.g_code_system) == ("A", "B", "C")
    # the parts the three share are system A's: the M codes, the formats, the serial link
    assert b.extra_codes["M99"] == a.extra_codes["M99"] == c.extra_codes["M99"]
    assert b.detailed == a.detailed == c.detailed and b.serial == a.serial
    # what B numbers otherwise
    assert "G32" not in b.extra_codes and "G50" not in b.extra_codes
    assert b.extra_codes["G77"].meaning == a.extra_codes["G90"].meaning == "turning-cycle"
    assert b.extra_codes["G90"].meaning == "absolute-programming"
    assert b.extra_codes["G95"].meaning == a.extra_codes["G99"].meaning
    assert "G92.1" in b.extra_codes and "G50.3" not in b.extra_codes
    # C: B's, with the units codes and the cycles renumbered
    assert c.units_codes == ("G70", "G71") and "G79" not in c.extra_codes
    assert c.extra_codes["G72"].meaning == "finishing-cycle"
    assert c.extra_codes["G72"].words == (("P", "N"), ("Q", "N"))
    assert c.extra_codes["G91"].meaning == "incremental-programming"


def test_a_profile_of_ones_own_may_be_written_on_a_built_in_one(tmp_path):
    mine = profile_from_text('base = "fanuc-lathe-b"\nname = "m12"\n[limits]\nX = [0, 300]\n'
                             '[codes]\nM43 = false\n')
    assert mine.name == "m12" and mine.g_code_system == "B"
    assert mine.limits.axes["X"] == (Decimal(0), Decimal(300))
    assert mine.limits.axes["Z"] == load_profile(B).limits.axes["Z"]  # kept from the base
    assert "M43" not in mine.extra_codes and "M42" in mine.extra_codes


@pytest.mark.parametrize("text, key", [
    ('base = "no-such"\n', "base"),
    ('base = "neutral"\n', "base"),
    ('g_code_system = "B"\n', "g_code_system"),  # not a FANUC lathe
    ('base = "fanuc-lathe"\ng_code_system = "D"\n', "g_code_system"),
])
def test_a_bad_base_or_g_code_system_names_its_key(text, key):
    with pytest.raises(ProfileError) as info:
        profile_from_text(text)
    assert info.value.key == key


@pytest.mark.parametrize("text", [
    # system B's list read as system A: B's G90 (absolute) would be taken for A's cycle
    'base = "fanuc-lathe-b"\ng_code_system = "A"\n',
    'base = "fanuc-lathe-c"\ng_code_system = "B"\n',  # C's cycle is G20, not B's G77
    # system A's list read as B: A's G90 (the cycle) would be taken for absolute programming
    'base = "fanuc-lathe"\ng_code_system = "B"\n',
    # half of B's list is not B's
    'base = "fanuc-lathe"\ng_code_system = "B"\n[codes]\nG90 = { function = "absolute", '
    'duration = "distance", meaning = "absolute-programming" }\n',
])
def test_a_g_code_system_that_contradicts_the_code_list_is_refused(text):
    with pytest.raises(ProfileError) as info:
        profile_from_text(text)
    assert info.value.key == "g_code_system" and info.value.code == "profile-g-code-system"
    assert "contradicts the profile's code list" in info.value.message


def test_a_profile_on_a_base_takes_its_g_code_system():
    assert profile_from_text('base = "fanuc-lathe-c"\n').g_code_system == "C"
    # restating the base's own system is no contradiction
    assert profile_from_text('base = "fanuc-lathe-b"\ng_code_system = "B"\n').g_code_system \
        == "B"
    # a profile that writes system B's codes on system A's list is system B, as fanuc-lathe-b
    codes = "\n".join(line for line in builtin_text(B).splitlines()
                      if line.startswith(("G", '"G')))
    mine = profile_from_text(f'base = "fanuc-lathe"\ng_code_system = "B"\n'
                             f'reset = ["G00", "G18", "G21", "G40", "G80", "G90", "G95", "G97"]'
                             f'\n[codes]\n{codes}\n')
    assert mine.g_code_system == "B"
    assert mine.extra_codes["G77"].meaning == "turning-cycle"
    # a FANUC lathe of one's own that names no system is not judged by A's list: its table
    # is its own (here the ISO one, whose G90 is absolute programming)
    own = profile_from_text('control_type = "lathe"\ndialect = "fanuc"\n')
    assert own.g_code_system == "A"


# -- checking -------------------------------------------------------------------------------

B_MODES = """%
O1001
N10 G21 G18 G40 G95
N20 G92 S2000
N30 T0101
N40 G97 S800 M03
N50 G00 X50. Z2.
N60 G91 G01 X-10. F0.2
N70 Z-20.
N80 G90 G00 X60. Z5.
N90 G77 X45. Z-30. F0.25
N100 X40.
N110 G00 X60. Z5.
N120 G78 X48. Z-20. F1.5
N130 G79 X20. Z-1. F0.2
N140 G94 G01 Z-1. F100.
N150 G33 Z-10. F1.5
N160 G71 U1.5 R0.5
N170 G71 P180 Q190 U0.4 W0.1 F0.25
N180 G00 X30.
N190 G01 Z-20.
N200 G70 P180 Q190
N210 M30
%
"""


def test_a_system_b_program_reads_without_finding_on_b_and_draws_tg307_on_a():
    assert found(B_MODES, B) == []
    unknown = {m.split()[0] for r, _, m in found(B_MODES, A) if r == "TG307"}
    assert unknown == {"G91", "G77", "G78", "G79", "G95", "G33"}


def test_g90_g91_are_absolute_and_incremental_in_b():
    s = state(B_MODES, B, 9)  # after N60 G91 G01 X-10. (line 8)
    assert s.incremental and s.position["X"] == Decimal(40)
    s = state(B_MODES, B, 10)  # after N70 Z-20. in G91
    assert s.position["Z"] == Decimal(-18)
    assert not state(B_MODES, B, 11).incremental
    # on system A the same G91 is no code: the moves stay absolute
    assert not state(B_MODES, A, 9).incremental


def test_g94_g95_are_the_feed_modes_in_b_and_c_and_g98_g99_are_not():
    assert state(B_MODES, B, 4).feed_mode == 95
    assert state(B_MODES, B, 17).feed_mode == 94
    text = "%\nO1\nG71 G95\nG98 G01 X10. Z0 F0.2\nM30\n%\n"
    assert state(text, C, 5).feed_mode == 95  # G98: the drilling cycles' return level


def test_the_single_cycles_g77_g78_g79_are_motion_modes_in_b_and_g20_g21_g24_in_c():
    s = state(B_MODES, B, 13)  # N100 X40. repeats the G77 cycle
    assert s.motion == 90
    c_text = B_MODES.replace("G21 G18", "G71 G18").replace("G77", "G20").replace(
        "G78", "G21").replace("G79", "G24")
    assert state(c_text, C, 13).motion == 90 and state(c_text, C, 13).units == "metric"


def test_system_c_reads_g70_g71_as_units_and_its_cycles_two_numbers_up():
    text = """%
O1002
N10 G70 G95
N20 G00 X2. Z0.1
N30 G73 U0.05 R0.02
N40 G73 P50 Q60 U0.01 W0.005 F0.01
N50 G00 X1.
N60 G01 Z-1.
N70 G72 P50 Q60
N80 G71
N90 M30
%
"""
    assert found(text, C) == []
    assert state(text, C, 4).units == "inch"
    assert state(text, C, 11).units == "metric"
    # on system B, G70 and G71 are the finishing and the roughing cycles: no units code
    assert state(text, B, 4).units == "metric"


def test_g92_is_the_coordinate_setting_and_clamp_in_b_and_g50_no_code():
    text = "%\nO1\nG21 G95\nG92 X100. Z50.\nG50 S1500\nM30\n%\n"
    s = state(text, B, 5)
    assert (s.position["X"], s.position["Z"]) == (Decimal(100), Decimal(50))
    assert [(r, line) for r, line, _ in found(text, B)] == [("TG307", 5)]


def test_u_and_w_leave_x_and_z_unknown_in_b():
    text = "%\nO1\nG21 G95\nG00 X50. Z2.\nG01 U-10. F0.2\nM30\n%\n"
    assert "X" not in state(text, B, 6).position
    assert state(text, A, 6).position["X"] == Decimal(40)


def test_a_real_system_b_program_reads_without_tg307():
    """A CAM program of G code system B, in the form of the shared corpus's TOKARKA (G21 G90
    G40 G95, G92 S clamp, G33 threading passes): no TG307 on fanuc-lathe-b."""
    passes = "".join(f"N{100 + 10 * i} G0 X{60 - i}. Z5.\nG33 Z-20. F1.5\n" for i in range(20))
    text = f"%O1200(T)\nN10 G21 G90 G40 G95\nN20 G92 S500\nN30 G97 S300 M3\n{passes}M30\n%\n"
    assert not [f for f in found(text, B) if f[0] == "TG307"]
    assert len([f for f in found(text, A) if f[0] == "TG307"]) == 21  # G95 and each G33


# -- conversion -----------------------------------------------------------------------------

A_PROGRAM = """%
O1003
N10 G21 G18 G40 G99
N20 G50 S2000
N30 T0101
N40 G97 S800 M03
N50 G00 X52. Z2.
N60 G71 U1.5 R0.5
N70 G71 P80 Q110 U0.4 W0.1 F0.25
N80 G00 X30.
N90 G01 Z-20.
N100 X50. Z-30.
N110 Z-45.
N120 G70 P80 Q110
N130 G00 X60. Z5.
N140 G90 X45. Z-30. F0.25
N150 G92 X48. Z-20. F1.5
N160 G94 X20. Z-1. F0.2
N170 G98 G01 Z-1. F100.
N180 G32 Z-10. F1.5
N190 M30
%
"""


def test_a_to_b_renumbers_the_codes_and_back_again(tmp_path):
    b = proved(tmp_path, A_PROGRAM, A, B)
    assert "N10 G21 G18 G40 G95\nN20 G92 S2000\n" in b
    assert "N140 G77 X45." in b and "N150 G78 X48." in b and "N160 G79 X20." in b
    assert "N170 G94 G01" in b and "N180 G33 Z" in b
    assert "N60 G71 U1.5 R0.5\n" in b and "N120 G70 P80 Q110\n" in b  # B keeps A's numbers
    assert proved(tmp_path, b, B, A) == A_PROGRAM
    assert found(b, B) == []


def test_a_to_c_renumbers_units_and_the_repetitive_cycles(tmp_path):
    c = proved(tmp_path, A_PROGRAM, A, C)
    assert "N10 G71 G18 G40 G95\n" in c
    assert "N60 G73 U1.5 R0.5\nN70 G73 P80 Q110" in c and "N120 G72 P80 Q110" in c
    assert "N140 G20 X45." in c and "N150 G21 X48." in c and "N160 G24 X20." in c
    assert proved(tmp_path, c, C, A) == A_PROGRAM
    assert proved(tmp_path, c, C, B) == convert(A_PROGRAM, A, B)


def test_b_to_a_drops_g90_and_refuses_g91(tmp_path):
    text = "%\nO1\nN10 G21 G90 G40 G95\nN20 G00 X50. Z2.\nN30 G90 X40.\nM30\n%\n"
    assert proved(tmp_path, text, B, A) == (
        "%\nO1\nN10 G21 G40 G99\nN20 G00 X50. Z2.\nN30 X40.\nM30\n%\n")
    error = refusal(B_MODES, B, A)
    assert error.line == 8 and "G91" in error.message and "incremental programming" in (
        error.message)


@pytest.mark.parametrize("block, word, why", [
    ("G01 U-10. F0.2", "U-10.", "G91"),  # A's increment: not rewritten as G91 X
    ("G28 U0 W0", "U0", "G91"),
])
def test_a_to_b_refuses_u_and_w_increments(block, word, why):
    text = f"%\nO1\nG21 G99\nG00 X50. Z2.\n{block}\nM30\n%\n"
    error = refusal(text, A, B)
    assert error.line == 5 and error.message.startswith(word) and why in error.message


def test_the_cycles_u_and_w_carry_between_systems():
    text = "%\nO1\nG21 G99\nG00 X50. Z2.\nG71 U1. R0.5\nG71 P6 Q7 U0.4 W0.1 F0.2\nN6 G0 X30.\n" \
           "N7 G1 Z-10.\nG04 U1.5\nM30\n%\n"
    assert "G73 U1. R0.5\nG73 P6 Q7 U0.4 W0.1 F0.2" in convert(text, A, C)


@pytest.mark.parametrize("text, source, target, code", [
    ("G98 G83 X0 Z-5. R1. F0.1", B, A, "G98"),  # a return level: none in system A
    ("G50 S2000", B, A, "G50"),  # no code of system B
    ("G77 X40. Z-5. F0.2", A, B, "G77"),  # no code of A; B's cutting cycle
])
def test_a_code_the_other_system_cannot_say_is_refused(text, source, target, code):
    program = f"%\nO1\nG21\n{text}\nM30\n%\n"
    error = refusal(program, source, target)
    assert error.line == 4 and error.message.startswith(code + ":")


def test_no_restart_preamble_is_written_for_system_b():
    prof = load_profile(B)
    blocks = list(parse_text(B_MODES, prof.dialect))
    walk = RestartWalk(prof, "p.nc")
    for block in blocks[:8]:
        walk.step(block)
    with pytest.raises(RestartRefused) as info:
        walk.plan(blocks[8])
    assert "G code system B" in info.value.message


def test_only_two_fanuc_lathes_renumber_their_codes():
    # a program read by the ISO table (no source profile) is refused for system B: its own
    # system is not in its text, and its G90 would be kept as written
    with pytest.raises(ConversionError) as info:
        ConvertOptions(target=load_profile(B))
    assert info.value.code == "conversion-option"
    # system B for a Haas lathe: compared by meaning, G95 (feed per revolution) against the
    # Haas's G95 of another group, refused
    error = refusal("%\nO1\nG21 G95\nG0 X10. Z0\nM30\n%\n", B, "haas-lathe")
    assert error.line == 3 and error.message.startswith("G95:")


@pytest.mark.parametrize("code, why", [
    # a number B's list lacks: no source at hand gives polygon turning a number in B
    ("G251 P1 Q2", "not in the source profile's code list"),
    # system A's number of a function B numbers otherwise (its G92)
    ("G50 S2000", "its function has another number there"),
])
def test_the_refusal_of_a_code_system_b_lacks_says_why(code, why):
    error = refusal(f"%\nO1\nG21 G95\n{code}\nM30\n%\n", B, A)
    assert error.line == 4 and error.message.startswith(code.split()[0] + ":")
    assert why in error.message


def test_a_haas_lathe_program_is_compared_by_meaning_for_system_b():
    # a Haas lathe reads system A's numbers, yet no FANUC G code system is named in its
    # profile: its G90 cycle meets B's G90 (absolute programming) of another group, refused
    text = "%\nO1\nG21\nG00 X50. Z2.\nG90 X45. Z-20. F0.2\nM30\n%\n"
    error = refusal(text, "haas-lathe", B)
    assert error.line == 5 and error.message.startswith("G90:")


SIDE = "%\nO1\nG21 G99\nG00 X50. Z-10. C0\n{cycles}\nG80\nG00 X50.\nM30\n%\n"


@pytest.mark.parametrize("profile", [A, B, C])
def test_a_side_drilling_cycle_has_its_depth_on_x(profile):
    # G87 X(U)_ C(H)_ Z(W)_ R_: X is the hole's bottom on a FANUC lathe, in every system
    assert [f for f in found(SIDE.format(cycles="G87 X20. C90. R-2. Q2000 F0.1"), profile)
            if f[0] == "TG541"] == []
    missing = found(SIDE.format(cycles="G87 Z-12. C90. R-2. Q2000 F0.1"), profile)
    assert ("TG541", 5, "G87 without X") in missing


def test_a_side_cycle_keeps_no_r_from_a_face_cycle():
    cycles = "G83 Z-20. R-2. Q5000 F0.1\nG87 X20. C90. Q2000 F0.1"
    assert ("TG541", 6, "G87 without R") in found(SIDE.format(cycles=cycles), A)
    same = "G83 Z-20. R-2. Q5000 F0.1\nG83 C90. Q2000"
    assert [f for f in found(SIDE.format(cycles=same), A) if f[0] == "TG541"] == []
