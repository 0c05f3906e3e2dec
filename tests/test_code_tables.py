"""The code tables, variables and block forms of each family, from the makers' references
(issue 32, docs/dialects.md): small programs written from the manuals' examples, each firing
and quiet.

- TG304 between a decimal code and the other codes of its group (``G54.1 P1 G55``);
  on LinuxCNC each pair against rs274 where it is installed.
"""

from __future__ import annotations

import math
import shutil
import subprocess
from pathlib import Path

import pytest

from formats.convert import ConvertOptions, convert_text
from formats.errors import ConversionError, ProfileError
from formats.profile import load_profile, profile_from_text
from postproc.check import Checker, check_text
from postproc.plot import backplot, transforms_note

from .conftest import rs274_env

RS274 = shutil.which("rs274")


def found(text: str, profile: str) -> list[tuple[str, str, int, str]]:
    """(rule, severity, line, message) of every finding but the notes about style."""
    return [(f.rule, f.severity, f.line, f.message) for f in check_text(text, load_profile(profile))
            if f.rule not in ("TG130", "TG133", "TG703")]


def fired(text: str, profile: str, rule: str) -> list[tuple[str, int, str]]:
    """(severity, line, message) of each finding of ``rule``."""
    return [(severity, line, message) for r, severity, line, message in found(text, profile)
            if r == rule]


def fanuc(body: str) -> str:
    return f"%\nO1000\nG21 G90 G17 G00 X0 Y0 Z10.\n{body}\nM30\n%\n"


def linuxcnc(body: str) -> str:
    return f"G21 G90 G17 G40 G49 G80 G94 G97\n{body}\nM2\n"


# -- TG304 between decimal codes -----------------------------------------------------------------


@pytest.mark.parametrize(("block", "pair"), [
    ("G54.1 P1 G55", "G54.1 and G55"),  # work offset (Fanuc group 14)
    ("G55 G54.1 P1", "G55 and G54.1"),
    ("G43.4 H1 G49", "G43.4 and G49"),  # length (group 08)
    ("G43.4 H1 G43.5", "G43.4 and G43.5"),
    ("G68.2 X0 Y0 Z0 I0 J45. K0 G69", "G68.2 and G69"),  # rotation (group 16)
    ("G12.1 G13.1", "G12.1 and G13.1"),  # polar interpolation (group 21)
    ("G41.2 D1 G40", "G41.2 and G40"),  # cutter (group 07)
    ("G50.1 X0 G51.1 X0", "G50.1 and G51.1"),  # mirror (group 22)
])
def test_a_decimal_fanuc_code_and_another_of_its_group_are_tg304(block, pair):
    hits = fired(fanuc(block), "fanuc-mill", "TG304")
    assert [(severity, line) for severity, line, _ in hits] == [("error", 4)]
    assert pair in hits[0][2]  # the codes in the block's order (review 51, F19)


@pytest.mark.parametrize("block", [
    "G54.1 P1 G43.4 H1",  # two groups
    "G54.1 P1 G54.1 P1",  # one code twice
    "G05.1 Q1 G04 P100",  # G05.1 is group 00: no modal group to share
    "G12.1 G40",
])
def test_decimal_fanuc_codes_of_two_groups_are_no_tg304(block):
    assert fired(fanuc(block), "fanuc-mill", "TG304") == []


def test_a_decimal_fanuc_lathe_code_and_another_of_its_group_are_tg304():
    program = "%\nO1000\nG21 G18 G00 X50. Z10.\nG12.1 G13.1\nM30\n%\n"
    assert [line for _, line, _ in fired(program, "fanuc-lathe", "TG304")] == [4]


# -- Haas mill: the G-code list of the Mill Operator's Manual, NGC (2017) ------------------------


def test_the_haas_ngc_mill_g_codes_of_the_2017_list_are_known():
    """The UMC options: 5-axis canned cycles, TCPC, dynamic work offset; G188 (pallet schedule)."""
    program = fanuc("G254\nG234 H1\nG161 X1. Y1. Z-5. R1. F100.\nG163 Z-8. Q2. R1.\nG80\n"
                    "G49 G255\nG188")
    assert not {r for r, *_ in found(program, "haas-mill")} & {"TG306", "TG307"}
    # each in the group the list gives it
    assert [line for _, line, _ in fired(fanuc("G254 G255"), "haas-mill", "TG304")] == [4]
    assert [line for _, line, _ in fired(fanuc("G234 H1 G49"), "haas-mill", "TG304")] == [4]
    assert [line for _, line, _ in fired(fanuc("G161 Z-5. R1. G80"), "haas-mill", "TG304")] == [4]


# -- Okuma OSP machining centre: the List of G Codes of 4203-E ------------------------------------


def test_the_okuma_mill_g_codes_are_those_of_the_osp_list():
    """OSP-U100M/U10M Operation Manual (4203-E), Appendix section 2, 1. List of G Codes."""
    program = ("$T.MIN%\nO1\nG0 X0 Y0 Z10\nG11 X10. Y10. R30.\nG10\nG22 X100. Y100. Z100.\n"
               "G23\nG62 X0\nG51 X0 Y0 P2\nG50\nG186\nG187\nG188 H2\nG189\n"
               "G284 X10. Y10. Z-10. R2. F1.5\nG80\nM02\n")
    assert not {r for r, *_ in found(program, "okuma-mill")} & {"TG306", "TG307"}
    # the list has no G98/G99 (an OSP's return level is G71 and M52-M54): a warning naming it
    hits = fired(okuma("G98"), "okuma-mill", "TG307")
    assert [(severity, line) for severity, line, _ in hits] == [("warning", 4)]
    assert hits[0][2].startswith("G98 ")


def test_the_later_osp_list_adds_the_air_cut_reduction_mode():
    """G37/G38, blank in 4203-E, are the later OSP list's air cut reduction mode (greenbau.ro's
    transcription of the OSP machining centre's List of G Codes): read, a group of their own."""
    program = okuma("G38\nG1 X10. F500\nG37\nG0 Z50.")
    assert not {r for r, *_ in found(program, "okuma-mill")} & {"TG306", "TG307"}
    # the same list's G33 (thread cutting) and G39 (corner arcs) move the machine by words the
    # list does not give: they stay a warning naming them, the motion unknown after them
    for code in ("G33 Z-10. F1.5", "G39 I1. J1."):
        hits = fired(okuma(code), "okuma-mill", "TG307")
        assert [(severity, line) for severity, line, _ in hits] == [("warning", 4)]
        assert hits[0][2].startswith(code.split()[0] + " ")


@pytest.mark.parametrize("block", ["G50 G51 X0 Y0 P2", "G22 G23", "G174 G175", "G186 G187",
                                   "G188 G189", "G194 G195", "G10 G11 X0 Y0 R30.", "G37 G38"])
def test_two_okuma_mill_g_codes_of_one_group_are_tg304(block):
    hits = fired(okuma(block), "okuma-mill", "TG304")
    assert [(severity, line) for severity, line, _ in hits] == [("error", 4)]


# LinuxCNC: each pair against rs274 2.9 ("Two g codes used from same modal group")
LINUXCNC_PAIRS = [
    ("G90.1 G91.1", True),
    ("G59.1 G54", True),
    ("G61.1 G64", True),
    ("G43.1 Z1 G49", True),
    ("G38.2 Z-1 F10 G1", True),
    ("G17.1 G18", True),
    ("G41.1 D1 G40", True),
    ("G28.1 G4 P1", True),
    ("G92.1 G92.3", True),
    # rs274 runs G92.1-G92.3 beside the other codes of the Overview's group 0
    ("G4 P1 G92.1", False),
    ("G92 X0 G92.2", False),
    ("G28.1 G92.1", False),
    ("G90.1 G90", False),
]


@pytest.mark.parametrize(("block", "refused"), LINUXCNC_PAIRS)
def test_decimal_linuxcnc_codes_in_one_group_as_rs274_has_them(block, refused):
    assert bool(fired(linuxcnc(block), "linuxcnc", "TG304")) is refused


@pytest.mark.skipif(RS274 is None, reason="LinuxCNC's rs274 is absent")
def test_the_linuxcnc_pairs_are_what_rs274_says(tmp_path: Path):
    (tmp_path / "tools.tbl").write_text("T1 P1 D1 Z0 ;\n")
    for block, refused in LINUXCNC_PAIRS:
        (tmp_path / "t.ngc").write_text(linuxcnc(block))
        assert RS274 is not None
        result = subprocess.run(env=rs274_env(),
                                args=[RS274, "-g", "-t", "tools.tbl", "t.ngc", "/dev/null"],
                                capture_output=True, text=True, timeout=30, cwd=tmp_path,
                                stdin=subprocess.DEVNULL)
        said = "Two g codes used from same modal group" in result.stdout + result.stderr
        assert said is refused, block


# -- M code tables -----------------------------------------------------------------------------
# Each family's M codes from its maker's list; an M code the list lacks is TG307, a warning
# naming it and what that control does with it; an error only where the control refuses it
# whatever its configuration (LinuxCNC past M999).


def sinumerik(body: str) -> str:
    return f"G71 G90 G17\nG0 X0 Y0 Z10\n{body}\nM30\n"


def okuma(body: str) -> str:
    return f"$T.MIN%\nO1\nG0 X0 Y0 Z10\n{body}\nM02\n"


@pytest.mark.parametrize(("profile", "program"), [
    # the manuals' own: a Fanuc subprogram call and interrupt macro, its builders' usual codes
    ("fanuc-mill", fanuc("M96 P9100\nM98 P1000\nM198 P2000\nM97\nM06 T1\nM03 S1000\nM08\nM19\n"
                         "M29 S500\nM09\nM05\nM01")),
    ("fanuc-lathe", fanuc("M03 S500\nM41\nM08\nM98 P100\nM198 P200\nM05\nM00")
     .replace("G17 G00 X0 Y0", "G18 G00 X0")),
    # Haas mill: pallets, user M codes with M-fin, relays, MOM, interactive input
    ("haas-mill", fanuc("M17\nM18\nM21\nM51\nM61\nM36 P1\nM50 P1\nM59 P1\nM69 P1\nM93 P1 Q1\n"
                        "M94\nM101 I1\nM103\nM109 P500\nM88\nM89\nM83\nM84\nM97 P10\nM30\nN10 M99")
     .replace("\nM30\n%", "\n%")),
    # Haas mill, the NGC Operator's Manual of 2017 (8.1.1 List of M-codes): tool air blast,
    # display media with its file in a comment, spindle speed variation with P (RPM), E (s)
    ("haas-mill", fanuc("M73\nM74\nM130(PART.PNG)\nM131\nM138 P500 E1.5\nM139")),
    # SINUMERIK 840D: the NC's own M functions
    ("sinumerik-840d", sinumerik("M3 S1000\nM40\nM41\nM19\nM70\nM6\nM5\nM1\nM0")),
    # LinuxCNC 2.9: overrides, I/O, modal state, tool number
    ("linuxcnc", linuxcnc("M3 S1000\nM48\nM50 P1\nM62 P1\nM64 P2\nM66 P0 L0\nM67 E0 Q1\n"
                          "M70\nM72\nM61 Q1\nM7\nM9\nM5\nM1")),
    # Okuma OSP machining centre (OSP-U100M/U10M List of M Codes): return levels, through-the-
    # tool coolant, touch sensor, synchronized tapping, pallets, gear ranges, overrides
    ("okuma-mill", okuma("M03 S1000\nM51\nM53\nM54\nM52\nM144\nM145\nM326\nM327\nM15\n"
                         "M16\nM101\nM60\nM41\nM134\nM135\nM292\nM293\nM09\nM05\nM01")),
    # Okuma OSP lathe: the key way cutting cycle's M codes (OSP-P20L/P200L, 5238-E, 8-4)
    ("okuma-lathe", okuma("M211\nM212\nM213\nM214").replace("X0 Y0 Z10", "X100 Z10")),
])
def test_the_m_codes_of_each_maker_s_list_are_known(profile, program):
    assert not {r for r, *_ in found(program, profile)} & {"TG302", "TG306", "TG307"}


@pytest.mark.parametrize(("profile", "program", "code", "effect"), [
    ("fanuc-mill", fanuc("M12"), "M12", "machine builder's ladder"),
    ("fanuc-mill", fanuc("M444"), "M444", "machine builder's ladder"),
    # a Haas is its own builder: the NGC manual's list, not FANUC's ladder
    ("haas-mill", fanuc("M12\nM13\nM46"), "M46", "not in the Haas NGC manual's M-code list"),
    ("sinumerik-840d", sinumerik("M90"), "M90", "to the PLC"),
    ("linuxcnc", linuxcnc("M100"), "M100", "USER_M_PATH"),
    ("linuxcnc", linuxcnc("M10"), "M10", "REMAP"),  # the ISO table's clamp: not LinuxCNC's
    ("okuma-mill", okuma("M13"), "M13", "machine's own list"),
    ("okuma-mill", okuma("M215"), "M215", "machine's own list"),
])
def test_an_m_code_the_list_lacks_is_a_warning_naming_it(profile, program, code, effect):
    hits = fired(program, profile, "TG307")
    assert [severity for severity, *_ in hits] == ["warning"]
    assert hits[0][2].startswith(code + " ") and effect in hits[0][2]
    assert not {r for r, *_ in found(program, profile)} & {"TG302", "TG306"}


@pytest.mark.parametrize(("block", "pair"), [
    ("M50 M51", "M50 and M51"),  # through-the-tool coolant, low and high pressure
    ("M53 M54", "M53 and M54"),  # fixed cycle return level
    ("M68 M69", "M68 and M69"),  # vertical spindle tool clamp and unclamp
    ("M326 M327", "M326 and M327"),  # synchronized tapping torque monitoring
])
def test_two_okuma_m_codes_of_one_group_are_tg308(block, pair):
    """The OSP-U100M/U10M List of M Codes gives each M code its group, and no source at hand
    what the control does with two of one: TG308, a warning (audit 50, B1), not TG304."""
    hits = fired(okuma(block), "okuma-mill", "TG308")
    assert [(severity, line) for severity, line, _ in hits] == [("warning", 4)]
    assert hits[0][2].startswith(pair)
    assert fired(okuma(block), "okuma-mill", "TG304") == []
    # one-shot codes and codes of two groups share no group
    assert fired(okuma("M52 M54"), "okuma-mill", "TG308") == []
    assert fired(okuma("M60 M101"), "okuma-mill", "TG308") == []


@pytest.mark.parametrize(("profile", "program", "line"), [
    ("fanuc-mill", fanuc("S1000 M03 M04"), 4),
    ("fanuc-lathe", "%\nO1000\nG21 G18 G00 X0 Z10.\nS1000 M03 M05\nM30\n%\n", 4),
    ("sinumerik-840d", sinumerik("S1000 M3 M4"), 3),
    ("okuma-mill", okuma("S1000 M03 M05"), 4),
])
def test_two_spindle_codes_in_a_block_are_refused_where_the_ladder_picks(profile, program, line):
    """Where no source says the control alarms on two M codes of one group (TG308, a warning),
    the spindle's group stays an error (review 51 F9): whether and which way the spindle turns
    for the cuts after it is not known, and the project refuses what decides how the tool
    meets the work, with the reason."""
    hits = fired(program, profile, "TG304")
    assert [(severity, at) for severity, at, _ in hits] == [("error", line)]
    assert "are both in modal group spindle; " in hits[0][2]
    assert hits[0][2].endswith(
        "so whether and which way the spindle turns for the cuts after it is not known")
    # the reason by who decodes the codes: a SINUMERIK's NC decodes its spindle's M functions
    # itself, no ladder or PLC does (review 55a F3)
    assert ("ladder" in hits[0][2]) is profile.startswith("fanuc")
    if profile == "sinumerik-840d":
        assert "the NC decodes the spindle's M functions itself" in hits[0][2]
    assert fired(program, profile, "TG308") == []
    # the coolant's group stays a warning on the same controls (the Okuma's: its own test)
    if not profile.startswith("okuma"):
        coolant = program.replace("M03 M04", "M08 M09").replace("M03 M05", "M08 M09")
        coolant = coolant.replace("M3 M4", "M8 M9")
        assert [s for s, *_ in fired(coolant, profile, "TG308")] == ["warning"]


@pytest.mark.parametrize(("profile", "program", "rule"), [
    # a stop beside an orientation turns nothing: the group's TG308 (review 55a F6)
    ("okuma-mill", okuma("M05 M19"), "TG308"),
    ("okuma-mill", okuma("S500 M03 M19"), "TG304"),
    # the Okuma lathe's M-tool spindle (List of M Codes: M12 stop, M13 forward, M14 reverse)
    # drives the milling tool as M03-M05 drive the main spindle (review 55a F1)
    ("okuma-lathe", "$T.MIN%\nO1\nG0 X100 Z10\nM13 M14\nM02\n", "TG304"),
    ("okuma-lathe", "$T.MIN%\nO1\nG0 X100 Z10\nM12 M13\nM02\n", "TG304"),
    # SINUMERIK: M3 M4 M5 M19 M70 are auxiliary function group 2 by default (808D Parameter
    # Manual, AUXFU_PREDEF_GROUP; review 55a F2)
    ("sinumerik-840d", sinumerik("S1000 M3 M19"), "TG304"),
    ("sinumerik-840d", sinumerik("S1000 M3 M70"), "TG304"),
    ("sinumerik-840d", sinumerik("M70 M4"), "TG304"),
    ("sinumerik-840d", sinumerik("M5 M70"), "TG308"),
    ("sinumerik-840d", sinumerik("M5 M19"), "TG308"),
    ("sinumerik-840d", sinumerik("M1=3 M1=19"), "TG304"),
    ("sinumerik-840d", sinumerik("M1=5 M1=70"), "TG308"),
    # the plain address is the master spindle's, spindle 1 on a one-spindle machine (review 55a F7)
    ("sinumerik-840d", sinumerik("S1000 M3 M1=4"), "TG304"),
    ("sinumerik-840d", sinumerik("M1=4 M3"), "TG304"),
    ("sinumerik-840d", sinumerik("M5 M1=19"), "TG308"),
    # after the program's own SETMS(2) the plain address is spindle 2's (Programming Manual
    # Fundamentals, "Main spindle, master spindle"); SETMS alone returns to the machine data's
    # (review 56a F2)
    ("sinumerik-840d", sinumerik("SETMS(2)\nM3 S2000 M2=4"), "TG304"),
    ("sinumerik-840d", sinumerik("SETMS(2)\nSETMS\nM3 S2000 M1=4"), "TG304"),
    ("sinumerik-840d", sinumerik("SETMS(2)\nM5 M2=70"), "TG308"),
    # a master the checker cannot read: refused, saying so
    ("sinumerik-840d", sinumerik("SETMS(R9)\nM3 S2000 M2=4"), "TG304"),
    ("sinumerik-840d", sinumerik("SETMS(R9)\nM3 S2000 M1=5"), "TG304"),
    # extension 0 is the master spindle: M0=3 is the plain M3 (H2; review 56a F7)
    ("sinumerik-840d", sinumerik("M0=3 M4 S1000"), "TG304"),
    ("sinumerik-840d", sinumerik("M0=3 M1=4"), "TG304"),
    ("sinumerik-840d", sinumerik("M0=5 M0=70"), "TG308"),
])
def test_a_spindle_pair_is_refused_only_where_one_code_turns_it(profile, program, rule):
    other = "TG308" if rule == "TG304" else "TG304"
    assert [s for s, *_ in fired(program, profile, rule)] == (
        ["error"] if rule == "TG304" else ["warning"])
    assert fired(program, profile, other) == []


def test_the_plain_and_spindle_1s_codes_name_the_master_spindle_setting():
    """A SINUMERIK's plain M function is the master spindle's (840D sl Function Manual Basic
    Functions, H2, address extension 0), which machine data 20090 names, spindle 1 on a
    one-spindle machine: the message names that setting; spindle 2's codes beside plain ones
    are another spindle's on such a machine, and no conflict."""
    hits = fired(sinumerik("S1000 M3 M1=4"), "sinumerik-840d", "TG304")
    assert "20090 SPIND_DEF_MASTER_SPIND" in hits[0][2]
    for quiet in ("S1000 M3 M2=4", "M2=5 M4", "M3 M1=3", "M1=3 M2=4 M3"):
        assert not {r for r, *_ in found(sinumerik(quiet), "sinumerik-840d")} & {
            "TG304", "TG308"}, quiet


def test_after_setms_the_plain_codes_are_the_named_spindles():
    """Review 56a F2: a turn-mill program's own `SETMS(2)` makes spindle 2 the master, so
    `M3 M1=5` (the tool spindle on, the main spindle stopped) is two spindles' and no
    conflict, as is `M1=70 M3`; the message of a conflict says which spindle is the master
    and why. `M0=3` is the plain M3 and no index out of range (review 56a F7)."""
    program = sinumerik("SETMS(2)\nM3 S2000 M1=5\nG1 X10 F100\nM1=70 M3 S2000\nSETMS")
    assert not {r for r, *_ in found(program, "sinumerik-840d")} & {"TG304", "TG308"}
    hits = fired(sinumerik("SETMS(2)\nM3 S2000 M2=4"), "sinumerik-840d", "TG304")
    assert [(severity, line) for severity, line, _ in hits] == [("error", 4)]
    assert ("of one spindle: the master spindle, the plain M function's, is spindle 2 since "
            "the SETMS on line 3;") in hits[0][2]
    hits = fired(sinumerik("SETMS(R9)\nM3 S2000 M1=5"), "sinumerik-840d", "TG304")
    assert ("which spindle is the master, the plain M function's, is not known since the "
            "SETMS on line 3 (an argument the checker cannot read), so it may be spindle 1"
            ) in hits[0][2]
    assert not {r for r, *_ in found(sinumerik("M0=3 S1000"), "sinumerik-840d")} & {
        "TG206", "TG304", "TG307"}


SPINDLE_BASE = 'base = "fanuc-mill"\n[codes]\n'


def test_a_code_reworded_on_a_base_keeps_the_bases_meaning(tmp_path: Path):
    """Review 56a F1: an entry of `[codes]` on a base replaces the base's, but keeps its
    `meaning` unless it sets one (`meaning = ""` drops it, and ISO 6983-1's meaning is left),
    whichever spelling names the code (`M3`, `M03`): a builder's wording of M03/M04 keeps them
    spindle starts, so `M03 M04` stays TG304; a key that turns nothing makes it TG308; `false`
    still drops the code."""
    def pair(profile_text: str) -> list[str]:
        path = tmp_path / "p.toml"
        path.write_text(profile_text)
        return [f.rule for f in check_text(fanuc("S1000 M03 M04"), load_profile(str(path)))
                if f.rule in ("TG304", "TG308")]

    for code in ("M03", "M3"):
        reworded = (SPINDLE_BASE + f'{code} = {{ function = "spindle CW (ours)", '
                    'duration = "spindle" }\n')
        assert pair(reworded) == ["TG304"], code
        assert load_profile(str(tmp_path / "p.toml")).code("M", 3).function == "spindle CW (ours)"
    dropped = SPINDLE_BASE + ('M03 = { function = "ours", duration = "spindle", meaning = "" }\n'
                              'M04 = { function = "ours", duration = "spindle", meaning = "" }\n')
    # (unkeyed, M03 and M04 keep ISO 6983-1's meaning, spindle starts: review 56d F5)
    assert pair(dropped) == ["TG304"]
    assert load_profile(str(tmp_path / "p.toml")).code("M", 3).meaning == ""
    stops = dropped.replace('meaning = ""', 'meaning = "spindle-stop"')
    assert pair(stops) == ["TG308"]
    other = SPINDLE_BASE + 'M03 = { function = "ours", duration = "spindle", meaning = "x-y" }\n'
    assert pair(other) == ["TG304"]  # (M04 keeps the base's spindle-ccw)
    assert load_profile(str(tmp_path / "p.toml")).code("M", 3).meaning == "x-y"
    gone = SPINDLE_BASE + "M3 = false\n"
    pair(gone)
    assert load_profile(str(tmp_path / "p.toml")).code("M", 3) is None


def test_a_profile_whose_m03_turns_nothing_is_said_by_profiles_show(tmp_path: Path):
    """Reviews 56a F1, 56d F5: a profile of one's own (no base) whose M03 has no key keeps
    ISO 6983-1's meaning, a spindle start (`M03 M04` TG304, no note); one whose M03 is keyed
    with a meaning that turns nothing makes the pair a warning, and `tapegate profiles show`
    says so, naming the key to give. The built-in profiles say nothing."""
    from click.testing import CliRunner

    from formats.profile import builtin_names, spindle_notes
    from tapegate.profiles_cli import profiles

    own = ('name = "own"\ndialect = "fanuc"\ncode_table = "own"\n[codes]\n'
           'G00 = { function = "rapid", duration = "motion" }\n'
           'M03 = { function = "spindle cw", duration = "spindle" }\n'
           'M04 = { function = "spindle ccw", duration = "spindle", meaning = "spindle-ccw" }\n'
           'M05 = { function = "stop", duration = "spindle" }\n')
    path = tmp_path / "own.toml"
    path.write_text(own)
    assert spindle_notes(load_profile(str(path))) == []
    pair = "%\nO1000\nS1000 M03 M04\nM05 M03\nM30\n%\n"
    assert [(f.rule, f.severity, f.line) for f in check_text(pair, load_profile(str(path)))
            if f.rule in ("TG304", "TG308")] == [("TG304", "error", 3), ("TG304", "error", 4)]
    stop = path.with_name("stop.toml")
    stop.write_text(own.replace('duration = "spindle" }\nM04',
                                'duration = "spindle", meaning = "spindle-stop" }\nM04'))
    notes = spindle_notes(load_profile(str(stop)))
    assert len(notes) == 1
    assert notes[0].startswith(
        "M03 (spindle cw) is in modal group spindle with meaning 'spindle-stop': ")
    assert notes[0].endswith('give it meaning = "spindle-cw" (docs/profiles.md, "Code meanings")')
    assert [(f.rule, f.severity) for f in check_text(pair, load_profile(str(stop)))
            if f.rule in ("TG304", "TG308")] == [("TG304", "error"), ("TG308", "warning")]
    result = CliRunner().invoke(profiles, ["show", str(stop)])
    assert result.exit_code == 0
    assert f"{stop}: {notes[0]}" in result.output
    assert [n for n in builtin_names() if spindle_notes(load_profile(n))] == []


# (each built-in profile's form of a block, its start and its end)
def lathe(body: str) -> str:
    return f"%\nO1000\nG00 X0 Z10.\n{body}\nM30\n%\n"


SPINDLE_PAIR_FORMS = {
    "fanuc-mill": fanuc, "fanuc-lathe": lathe, "fanuc-lathe-b": lathe, "fanuc-lathe-c": lathe,
    "haas-mill": fanuc, "haas-lathe": lathe, "linuxcnc": linuxcnc,
    "sinumerik-840d": lambda body: sinumerik(body.replace("M0", "M")),
    "okuma-mill": okuma, "okuma-lathe": lambda body: f"$T.MIN%\nO1\nG0 X100 Z10\n{body}\nM02\n",
    "heidenhain-iso": lambda body: f"%T G71 *\nN10 G00 X+0 Y+0 *\nN20 {body} *\nN30 %T G71 *\n",
    "iso-mill": lambda body: f"%\nN1 G00 X+0 Y+0\nN2 {body}\nN3 M02\n",
    "iso-lathe": lambda body: f"%\nN1 G00 X+0 Z+0\nN2 {body}\nN3 M02\n",
}


@pytest.mark.parametrize("profile", sorted(SPINDLE_PAIR_FORMS))
def test_m03_m04_is_refused_on_every_profile_and_coolant_pairs_warned_where_the_ladder_picks(
        profile):
    """The spindle's direction both ways in one block is TG304 on every profile (the
    profile's meaning keys `spindle-cw`, `spindle-ccw` say M03 and M04 turn it); M08 M09 stay
    TG308 where no source says the control alarms (FANUC, SINUMERIK), TG304 where one does."""
    form = SPINDLE_PAIR_FORMS[profile]
    pair = [(r, s) for r, s, *_ in found(form("M03 M04"), profile) if r in ("TG304", "TG308")]
    assert pair == [("TG304", "error")], profile
    coolant = {(r, s) for r, s, *_ in found(form("M08 M09"), profile)} & {
        ("TG304", "error"), ("TG308", "warning")}
    unsourced = profile.split("-")[0] in ("fanuc", "sinumerik", "okuma")
    if profile != "okuma-mill":  # (its M09 is a group of its own: List of M Codes)
        assert coolant == {("TG308", "warning") if unsourced else ("TG304", "error")}, profile


@pytest.mark.parametrize("block", ["M138 M139", "M73 M74", "M130(A.PNG) M131"])
def test_two_haas_m_codes_of_one_pair_are_tg304(block):
    """The on and off codes of one function of the Haas NGC mill's list (2017) share a group."""
    hits = fired(fanuc(block), "haas-mill", "TG304")
    assert [(severity, line) for severity, line, _ in hits] == [("error", 4)]


def test_linuxcnc_refuses_m_codes_past_m999_and_leaves_m200_to_m999_to_a_remap():
    """rs274 reads an M code past M199 where the configuration remaps it, and M200-M999 are
    open to remapping (LinuxCNC Remap manual, "Currently unallocated M-codes"): a warning
    naming REMAP, as for M10; past M999 no configuration makes it valid."""
    hits = fired(linuxcnc("M1000"), "linuxcnc", "TG306")
    assert [(severity, line) for severity, line, _ in hits] == [("error", 2)]
    assert "M200-M999" in hits[0][2]
    for code in ("M600", "M200", "M999", "M199"):
        assert fired(linuxcnc(code), "linuxcnc", "TG306") == [], code
        warned = fired(linuxcnc(code), "linuxcnc", "TG307")
        assert [(severity, line) for severity, line, _ in warned] == [("warning", 2)], code
        assert "REMAP" in warned[0][2]


@pytest.mark.parametrize(("block", "refused"), [
    ("M99 M2", True),  # M99 is in the stopping group (rs274 2.9)
    ("M99 M5", False),
])
def test_linuxcnc_m99_is_in_the_stopping_group(block, refused):
    assert bool(fired(linuxcnc(block), "linuxcnc", "TG304")) is refused


@pytest.mark.skipif(RS274 is None, reason="LinuxCNC's rs274 is absent")
@pytest.mark.parametrize(("code", "said"), [
    ("M600", "remapped"),  # the remap's subroutine runs
    ("M1000", "Unknown m code used: M1000"),  # a REMAP past M999 makes nothing valid
])
def test_rs274_reads_a_remapped_m_code_up_to_m999(tmp_path: Path, code, said):
    """A configuration with ``REMAP=M600`` runs M600 (rs274 -i): it is the configuration's."""
    name = code.lower()
    (tmp_path / "subs").mkdir()
    (tmp_path / "subs" / f"{name}.ngc").write_text(
        f"o<{name}> sub\n(DEBUG, remapped)\no<{name}> endsub\nM2\n")
    (tmp_path / "r.ini").write_text(
        f"[RS274NGC]\nSUBROUTINE_PATH = {tmp_path / 'subs'}\n"
        f"REMAP={code} modalgroup=10 ngc={name}\n[EMCIO]\n[TRAJ]\n")
    (tmp_path / "prog.ngc").write_text(linuxcnc(f"{code}\nG0 X1"))
    assert RS274 is not None
    result = subprocess.run(env=rs274_env(), args=[RS274, "-i", "r.ini", "-g", "prog.ngc"],
                            capture_output=True, text=True, timeout=30, cwd=tmp_path,
                            stdin=subprocess.DEVNULL)
    assert said in result.stdout + result.stderr
    assert ("M-code greater than 199" in result.stdout + result.stderr) is False


@pytest.mark.skipif(RS274 is None, reason="LinuxCNC's rs274 is absent")
@pytest.mark.parametrize(("code", "said", "rule"), [
    ("G68.2", "remapped", "TG307"),  # a blank of the Remap manual's G0-G99.9 tables
    ("G100", "out of range", "TG306"),  # past G99.9 a REMAP makes nothing valid
])
def test_rs274_reads_a_remapped_g_code_up_to_g99_9(tmp_path: Path, code, said, rule):
    """A configuration with ``REMAP=G68.2`` runs G68.2 (rs274 -i), as held20's
    tilted-work-plane demos' INI files do: the check's TG307 names REMAP; G100 and G68.25
    rs274 refuses under a REMAP too, and there the check's TG306 stands."""
    name = "g" + code[1:].replace(".", "")
    (tmp_path / "subs").mkdir()
    (tmp_path / "subs" / f"{name}.ngc").write_text(
        f"o<{name}> sub\n(DEBUG, remapped)\no<{name}> endsub\nM2\n")
    (tmp_path / "r.ini").write_text(
        f"[RS274NGC]\nSUBROUTINE_PATH = {tmp_path / 'subs'}\n"
        f"REMAP={code} modalgroup=1 ngc={name}\n[EMCIO]\n[TRAJ]\n")
    text = linuxcnc(f"{code}\nG0 X1")
    (tmp_path / "prog.ngc").write_text(text)
    assert RS274 is not None
    result = subprocess.run(env=rs274_env(), args=[RS274, "-i", "r.ini", "-g", "prog.ngc"],
                            capture_output=True, text=True, timeout=30, cwd=tmp_path,
                            stdin=subprocess.DEVNULL)
    assert said in result.stdout + result.stderr, result.stdout + result.stderr
    assert [f.rule for f in check_text(text, load_profile("linuxcnc"))
            if f.rule in ("TG306", "TG307")] == [rule]


@pytest.mark.skipif(RS274 is None, reason="LinuxCNC's rs274 is absent")
@pytest.mark.parametrize(("block", "said"), [
    ("M200", "M-code greater than 199"),  # no configuration remaps it here
    ("M100", "Unknown m code used"),
    ("M10", "Unknown m code used"),
    ("M99 M2", "Two m codes used from same modal group"),
])
def test_the_linuxcnc_m_codes_are_what_rs274_says(tmp_path: Path, block, said):
    (tmp_path / "t.ngc").write_text(linuxcnc(block))
    assert RS274 is not None
    result = subprocess.run(env=rs274_env(),
                            args=[RS274, "-g", "t.ngc", "/dev/null"], capture_output=True,
                            text=True,
                            timeout=30, cwd=tmp_path, stdin=subprocess.DEVNULL)
    assert said in result.stdout + result.stderr


def test_a_profile_marks_a_code_of_the_table_its_control_has_not():
    """[codes] M10 = { ..., status = "unassigned" }: a profile built on the ISO 6983-1 table
    takes its M10 clamp out (the built-in fanuc-mill's own list has no M10 at all)."""
    profile = profile_from_text('dialect = "fanuc"\nunits_codes = "G20/G21"\n[codes]\n'
                                'M10 = { function = "none here", status = "unassigned" }\n')
    program = fanuc("M10")
    assert [r for r, *_ in found(program, "fanuc-mill") if r == "TG307"] == ["TG307"]
    hits = [f for f in check_text(program, profile) if f.rule == "TG307"]
    assert [(f.severity, f.line) for f in hits] == [("warning", 4)]
    with pytest.raises(ProfileError) as info:
        profile_from_text('[codes]\nM10 = { function = "x", status = "gone" }\n')
    assert (info.value.code, info.value.key) == ("profile-value", "codes.M10.status")
    assert "assigned, unassigned" in str(info.value)


# -- read-only variables (TG209) ---------------------------------------------------------------


@pytest.mark.parametrize(("profile", "program", "line", "start"), [
    # LinuxCNC 2.9: tool data, the current position, the predefined named parameters
    ("linuxcnc", linuxcnc("#5420 = 1"), 2, "#5420 is the current position"),
    ("linuxcnc", linuxcnc("#5400 = 3"), 2, "#5400 is the tool in the spindle"),
    ("linuxcnc", linuxcnc("#<_x> = 1"), 2, "#<_x> is a predefined named parameter"),
    ("linuxcnc", linuxcnc("#<_current_tool> = 2"), 2, "#<_current_tool> is a predefined"),
    # SINUMERIK: the actual values of the List of System Variables
    ("sinumerik-840d", sinumerik("$AA_IM[X]=5"), 3, "$AA_IM[X] is a system variable"),
    ("sinumerik-840d", sinumerik("$aa_ib[z] = 0"), 3, "$AA_IB[Z] is a system variable"),
])
def test_an_assignment_to_a_read_only_variable_is_an_error(profile, program, line, start):
    hits = fired(program, profile, "TG209")
    assert [(severity, at) for severity, at, _ in hits] == [("error", line)]
    assert hits[0][2].startswith(start)


@pytest.mark.parametrize(("profile", "program"), [
    ("linuxcnc", linuxcnc("#1 = #5420\n#<depth> = #<_z>\n#5399 = 1\n#5414 = 1\n#<_mine> = 2")),
    ("sinumerik-840d", sinumerik("R1=$AA_IM[X]\n$P_UIFR[1]=CTRANS(X,10)\n$A_OUT[1]=1")),
    # another family's #5420 is no system variable of LinuxCNC's
    ("fanuc-mill", fanuc("#5420 = 1")),
])
def test_reading_them_and_writing_the_others_is_no_tg209(profile, program):
    assert fired(program, profile, "TG209") == []


def test_a_haas_assignment_to_custom_macro_b_s_read_only_list_is_a_warning():
    """The NGC's macro variables table does not mark #5021 read only and no Haas source says
    what the control does (TG211); the variables it marks stay errors (TG209); on a Fanuc
    #5021 is an error (PS0116)."""
    text = "%\nO1\nG20 G90 G00 X0\n#5021 = 1.\n#3020 = 1.\nM30\n%\n"
    assert [(s, at) for s, at, _ in fired(text, "haas-mill", "TG211")] == [("warning", 4)]
    assert [(s, at) for s, at, _ in fired(text, "haas-mill", "TG209")] == [("error", 5)]
    assert "Haas" in fired(text, "haas-lathe", "TG211")[0][2]
    assert [(s, at) for s, at, _ in fired(text, "fanuc-mill", "TG209")] == [("error", 4)]
    assert fired(text, "fanuc-mill", "TG211") == []


def test_linuxcnc_numbered_parameters_end_at_5601():
    """rs274 2.9: "Parameter number out of range" for #5602."""
    assert fired(linuxcnc("#5601 = 1"), "linuxcnc", "TG206") == []
    assert [line for _, line, _ in fired(linuxcnc("#5602 = 1"), "linuxcnc", "TG206")] == [2]


@pytest.mark.skipif(RS274 is None, reason="LinuxCNC's rs274 is absent")
@pytest.mark.parametrize(("block", "said"), [
    ("#5420 = 1", "Parameter is readonly"),
    ("#5413 = 1", "Parameter is readonly"),
    ("#<_x> = 1", "Cannot assign to read-only parameter"),
    ("#5602 = 1", "Parameter number out of range"),
    ("#5414 = 1", None),
    ("#<_mine> = 1", None),
])
def test_the_linuxcnc_read_only_parameters_are_what_rs274_says(tmp_path: Path, block, said):
    (tmp_path / "t.ngc").write_text(linuxcnc(block))
    assert RS274 is not None
    result = subprocess.run(env=rs274_env(),
                            args=[RS274, "-g", "t.ngc", "/dev/null"], capture_output=True,
                            text=True,
                            timeout=30, cwd=tmp_path, stdin=subprocess.DEVNULL)
    out = result.stdout + result.stderr
    if said is None:
        assert "readonly" not in out and "read-only" not in out and "range" not in out, out
    else:
        assert said in out


# -- '/' block skip ------------------------------------------------------------------------------


@pytest.mark.parametrize("profile", ["linuxcnc", "sinumerik-840d", "iso-mill"])
@pytest.mark.parametrize("block", ["G1 X1 /Y1 F10", "N10 /G1 X1 F10"])
def test_a_block_skip_inside_a_block_is_a_located_reading_error(profile, block):
    """Read only at the start of a block, but on Fanuc and Haas (docs/dialects.md says what
    was searched)."""
    from formats.parser import BadBlock, parse_text

    read = parse_text(f"G21 G90\n{block}\nM2\n", load_profile(profile).dialect, errors="collect")
    bad = [b for b in read if isinstance(b, BadBlock)]
    assert [b.line for b in bad] == [2]
    assert "block skip must stand at the start of the block" in str(bad[0].error)
    assert f":2:{block.index('/') + 1}:" in str(bad[0].error)
    # at the start of the block it is the block skip every family reads
    at_start = "/" + block.replace("/", "")
    skipped = parse_text(f"G21 G90\n{at_start}\nM2\n", load_profile(profile).dialect,
                         errors="collect")
    assert not [b for b in skipped if isinstance(b, BadBlock)]
    assert skipped[1].skip == "/"


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-lathe"])
@pytest.mark.parametrize("block", ["G1 X1 /Y1 F10", "N10 /G1 X1 F10"])
def test_a_fanuc_or_haas_reads_a_block_skip_inside_a_block(profile, block):
    """The switch on skips from the slash to the end of the block: read, kept at its column."""
    from formats.parser import BadBlock, parse_text

    read = parse_text(f"G21 G90\n{block}\nM2\n", load_profile(profile).dialect, errors="collect")
    assert not [b for b in read if isinstance(b, BadBlock)]
    assert read[1].words == block.replace("/", "").split()
    assert (read[1].skip, read[1].skip_within) == ("", (block.index("/") + 1, "/"))


@pytest.mark.skipif(RS274 is None, reason="LinuxCNC's rs274 is absent")
@pytest.mark.parametrize("block", ["G1 X1 /Y1 F10", "N10 /G1 X1 F10"])
def test_rs274_refuses_a_block_skip_inside_a_block_too(tmp_path: Path, block):
    (tmp_path / "t.ngc").write_text(linuxcnc(block))
    assert RS274 is not None
    result = subprocess.run(env=rs274_env(),
                            args=[RS274, "-g", "t.ngc", "/dev/null"], capture_output=True,
                            text=True,
                            timeout=30, cwd=tmp_path, stdin=subprocess.DEVNULL)
    assert "Bad character '/' used" in result.stdout + result.stderr


# -- each family's code table is the control's list, not ISO 6983-1's (issue 32, item 1) --------


def stats_high(text: str, profile_name: str, axis: str) -> object:
    """The highest ``axis`` position the checker found in ``text`` on ``profile_name``."""
    profile = load_profile(profile_name)
    checker = Checker(profile)
    list(checker.run_stream([text], profile.dialect))
    return checker.stats.high[axis]


def test_g91_on_a_fanuc_lathe_of_code_system_a_warns_and_moves_stay_absolute():
    """G code system A has no G90/G91 (G90 is the OD cutting cycle; U/W are the incremental
    words): G91 is not the ISO table's incremental programming but a code the control alarms
    on unless a parameter makes it a macro call, so TG307 naming it, and X stays absolute."""
    program = "%\nO1\nG21 G99 G00 X50. Z2.\nG91 G00 X10.\nG00 X10.\nG00 X10.\nM30\n%\n"
    hits = fired(program, "fanuc-lathe", "TG307")
    assert [(severity, line) for severity, line, _ in hits] == [("warning", 4)]
    assert hits[0][2].startswith("G91 is not in the profile's G code list")
    assert stats_high(program, "fanuc-lathe", "X") == 50  # 80 if G91 were incremental
    # where G91 is a code of the table (ISO 6983-1, a FANUC mill) the same X words add up
    assert stats_high(program, "iso-lathe", "X") == 80
    mill = "%\nO1\nG21 G94 G00 X50. Y0\nG91 G00 X10.\nG00 X10.\nG00 X10.\nM30\n%\n"
    assert stats_high(mill, "fanuc-mill", "X") == 80


@pytest.mark.parametrize(("profile", "program", "line", "code"), [
    # FANUC mill (0i-MF/30i-MB G code list): no G06 parabola, G20/G21 the units, G70/G71 none
    ("fanuc-mill", fanuc("G06 X1. Y1. F100."), 4, "G06"),
    ("fanuc-mill", fanuc("G70"), 4, "G70"),
    ("fanuc-mill", fanuc("G71"), 4, "G71"),
    # FANUC lathe, system A: G95/G94 are B and C's feed codes (A: G99/G98), G33 B's threading
    ("fanuc-lathe", fanuc("G95"), 4, "G95"),
    ("fanuc-lathe", fanuc("G33 Z-10. F1.5"), 4, "G33"),
    # an M code the CNC does not decode and the profile does not list: the builder's
    ("fanuc-mill", fanuc("M10"), 4, "M10"),
    ("fanuc-lathe", fanuc("M48"), 4, "M48"),
    # Haas: no ISO parabola, no G96/G97 on the mill, no G91 on the lathe (G90 turns)
    ("haas-mill", fanuc("G06 X1. Y1. F100."), 4, "G06"),
    ("haas-mill", fanuc("G96 S100"), 4, "G96"),
    ("haas-lathe", fanuc("G91 G00 X1."), 4, "G91"),
    ("haas-lathe", fanuc("M48"), 4, "M48"),
    # Okuma OSP: the lathe's units are a parameter (G70 none), the mill has no G96
    ("okuma-lathe", "O1\nG00 X50. Z2.\nG70\nM02\n", 3, "G70"),
    ("okuma-mill", "O1\nG00 X0 Y0\nG96 S100\nM02\n", 3, "G96"),
    # LinuxCNC: G06, G44, G60 and G68.2 are none of rs274's codes ("Unknown g code used"), but
    # its Remap manual opens every G code of G0-G99.9 its tables leave blank to a
    # configuration's REMAP ("Currently unallocated G-codes"; rs274 2.9 runs a remapped G6,
    # G44, G60 and G68.2): the check cannot see the INI file
    ("linuxcnc", linuxcnc("G6 X1 Y1 F100"), 2, "G6"),
    ("linuxcnc", linuxcnc("G44 H1"), 2, "G44"),
    ("linuxcnc", linuxcnc("G60"), 2, "G60"),
    ("linuxcnc", linuxcnc("G68.2 X0 Y0 Z0 I0 J45 K0"), 2, "G68.2"),
])
def test_a_code_the_family_list_lacks_is_a_warning_naming_it(profile, program, line, code):
    hits = fired(program, profile, "TG307")
    assert [(severity, at) for severity, at, _ in hits] == [("warning", line)], found(program,
                                                                                      profile)
    assert hits[0][2].startswith(f"{code} is not in the profile's")


@pytest.mark.parametrize(("profile", "program", "line", "code"), [
    # LinuxCNC's rs274 reads no G code from G100 on, nor one with two decimals, even where a
    # REMAP names it ("G-code out of range"; the Remap manual's tables end at G99.9)
    ("linuxcnc", linuxcnc("G100"), 2, "G100"),
    ("linuxcnc", linuxcnc("G68.25 X0"), 2, "G68.25"),
    # SINUMERIK in Siemens mode: no G6 (ISO parabola) nor G92 (ISO preset) in its G list
    ("sinumerik-840d", "N10 G0 X0 Y0\nN20 G6 X1 Y1\nN30 M30\n", 2, "G6"),
    # HEIDENHAIN ISO: no G94/G95 (F is mm/min), no G64
    ("heidenhain-iso", "%T G71 *\nN10 G00 G40 G90 X0 Y0 *\nN20 G95 *\nN9999 %T G71 *\n", 3,
     "G95"),
])
def test_a_g_code_the_list_lacks_is_an_alarm_where_the_control_alarms(profile, program, line,
                                                                       code):
    hits = fired(program, profile, "TG306")
    assert [(severity, at) for severity, at, _ in hits] == [("error", line)], found(program,
                                                                                     profile)
    assert hits[0][2].startswith(f"{code}: the control has no such code")


@pytest.mark.parametrize(("profile", "program"), [
    # the codes each list holds, with the control's meaning and group: quiet
    ("fanuc-mill", fanuc("G91 G01 X1. F100.\nG90\nM08\nM09")),
    ("fanuc-lathe", "%\nO1\nG21 G99 G00 X50. Z2.\nG90 X40. Z-10. F0.2\nG80\nM08\nM09\nM30\n%\n"),
    ("haas-mill", fanuc("M03 S1000\nM08\nG91 G01 X1. F100.\nG90\nM09\nM05")),
    ("haas-lathe", "%\nO1\nG21 G99 G00 X50. Z2.\nM03 S500\nM08\nG01 Z-10. F0.2\nM09\nM05\n"
                   "M30\n%\n"),
    ("linuxcnc", linuxcnc("M3 S1000\nM8\nG1 X1 F100\nM9\nM5")),
    ("okuma-lathe", "O1\nG00 X50. Z2.\nM03 S500\nM08\nG01 Z-10. F0.2\nM09\nM05\nM02\n"),
    ("heidenhain-iso", "%T G71 *\nN10 G00 G40 G90 X0 Y0 *\nN20 M03 *\nN30 M08 *\nN40 M09 *\n"
                       "N50 M05 *\nN60 M30 *\nN9999 %T G71 *\n"),
])
def test_a_code_the_family_list_holds_is_read_without_a_code_finding(profile, program):
    codes = [f for f in found(program, profile) if f[0].startswith("TG30")]
    assert codes == []


def test_a_code_the_list_holds_has_the_controls_group_not_the_iso_one():
    """Haas's M03 and M05 are one group (spindle): both in a block is TG304; FANUC lathe G98
    and G99 (feed per minute/revolution, system A) are one group where ISO has G94/G95."""
    assert [s for s, *_ in fired(fanuc("M03 M05"), "haas-mill", "TG304")] == ["error"]
    lathe = "%\nO1\nG21 G98 G99 G00 X50. Z2.\nM30\n%\n"
    assert [s for s, *_ in fired(lathe, "fanuc-lathe", "TG304")] == ["error"]


# -- the codes each list lacked against its control's documented list (issue 32, item 1) ---------


def converted(text: str, profile_name: str, units: str) -> str:
    """``text`` converted on ``profile_name`` to ``units``; raises ConversionError on a refusal."""
    profile = load_profile(profile_name)
    out, _ = convert_text(text, ConvertOptions(target=profile, source=profile, units=units))
    return out


def lathe(body: str) -> str:
    return f"%\nO1\nG20 G18 G99\nT101\nG97 S1000 M3\nG0 X2. Z1.\n{body}\nM30\n%\n"


@pytest.mark.parametrize(("profile", "program"), [
    # Haas lathe (NGC "G-codes", group 09): the radial live tooling cycles, reverse tapping
    ("haas-lathe", lathe("G98 G241 X1. Z-0.5 C0. R2.2 F5.\nC90.\nG80\nG0 X2. Z1.")),
    ("haas-lathe", lathe("G98 G243 X1. Z-0.5 R2.2 Q0.1 F5.\nG80")),
    ("haas-lathe", lathe("G98 G242 X1. Z-0.5 R2.2 P0.5 F5.\nG245 X1.\nG246 X1.\nG249 X1. P0.5\n"
                         "G80")),
    ("haas-lathe", lathe("G99 G195 X1. Z-0.5 R2.2 F0.05\nG196 X1.\nG184 Z-0.5 R0.1 F0.05\n"
                         "G186 Z-0.5 R0.1 F0.05\nG80")),
    ("haas-lathe", lathe("G107 C2.\nG199\nG198\nG200 T202")),
    # FANUC lathe, system A (0i-TF G code list): fluctuation detection, polygon turning
    ("fanuc-lathe", lathe("G26 P1000 Q10 R5 D50\nG25\nG51.2 P1 Q2\nG50.2")
     .replace("G20 G18 G99", "G20 G18 G99").replace("T101", "T0101")),
    # FANUC mill (0i-MF): chopping
    ("fanuc-mill", fanuc("G81.1 Z10. Q5. R2. F1000.\nG80")),
    # SINUMERIK: the SAR settings and the approach with tool radius compensation
    ("sinumerik-840d", sinumerik("G140 G340 G461\nG141\nG142\nG143 G341 G460\nG462")),
    # Okuma OSP lathe: grooving, chamfer and rounding, the LAP thread, the M-tool cycles, M codes
    ("okuma-lathe", "O1\nG00 X100 Z50\nG97 S800 M03\nG95\nG00 X60 Z5\nG74 X0 Z-12 D3 F0.12\n"
                    "G00 X60 Z5\nG88 NTHR1 H1.083 D0.4 U0.05 F1.5\nG01 G75 X50 L2 F0.2\n"
                    "G76 Z-20 L1\nM110\nG181 X0 Z-10 C0 F0.1 E1.\nG180\nM109\nM42\nM83\nM02\n"),
])
def test_the_codes_added_from_the_control_lists_are_read_without_a_code_finding(profile,
                                                                                 program):
    codes = [f for f in found(program, profile) if f[0] in ("TG304", "TG306", "TG307")]
    assert codes == []


@pytest.mark.parametrize(("profile", "program", "line", "code"), [
    # G247/G248 are not in the table the Haas lathe list was checked against; G244 is no code
    ("haas-lathe", lathe("G98 G247 X1. Z-0.5 R2.2 F5.\nG80"), 7, "G247"),
    ("haas-lathe", lathe("G98 G244 X1. Z-0.5 R2.2 F5.\nG80"), 7, "G244"),
    # the machining centre's turning cycles: U W and P Q of no role the mill knows
    ("fanuc-mill", fanuc("G70.7 P10 Q20"), 4, "G70.7"),
    # the OSP lathe's tapping cycles: whether F is a lead or a feed is not said
    ("okuma-lathe", "O1\nG00 X50. Z2.\nG77 X0 Z-10 F1.5\nM02\n", 3, "G77"),
])
def test_a_code_not_shown_by_a_source_stays_a_warning(profile, program, line, code):
    hits = fired(program, profile, "TG307")
    assert [(severity, at) for severity, at, _ in hits] == [("warning", line)]
    assert hits[0][2].startswith(f"{code} is not in the profile's")


def test_two_sinumerik_sar_direction_codes_are_tg304():
    hits = fired(sinumerik("G140 G141"), "sinumerik-840d", "TG304")
    assert [s for s, *_ in hits] == ["error"]


def test_a_haas_radial_cycle_converts_its_r_plane_and_its_dwell():
    """G241's X (a diameter), Z and R (the R plane) are lengths, P its dwell (written with its
    point, seconds: written in milliseconds, which a P without a point is); G243's Q the peck
    (the converter's cycle table): all converted by their roles, no refusal."""
    text = lathe("G98 G241 X1.5 Z-0.5 C0. R2.2 P0.5 F5.\nC90.\nG243 X1. Z-0.5 R2.2 Q0.1 F5.\n"
                 "G80\nG0 X2. Z1.")
    out = converted(text, "haas-lathe", "metric").splitlines()
    assert "G98 G241 X38.1 Z-12.7 C0. R55.88 P500 F127." in out
    assert "G243 X25.4 Z-12.7 R55.88 Q2.54 F127." in out
    assert "C90." in out
    # a block under G243 repeats it: its Q is the peck too (it was kept as 0.2 in mm)
    repeat = converted(lathe("G98 G243 X1. Z-0.5 R2.2 Q0.1 F5.\nX0.8 Z-0.6 Q0.2\nG80"),
                       "haas-lathe", "metric").splitlines()
    assert "X20.32 Z-15.24 Q5.08" in repeat


def test_a_haas_radial_cycle_s_strokes_are_not_counted_as_rapids():
    """The modal state does not model G241: its block and the positions after it are neither
    rapids nor feeds of the G00 in force, until G80 and a G00; said once in moves_not_known."""
    text = lathe("G98 G241 X1.0 Z-0.5 R0.1 F5.\nX0.8 Z-0.6\nG80\nG0 X2. Z1.")
    profile = load_profile("haas-lathe")
    checker = Checker(profile)
    list(checker.run_stream([text], profile.dialect))
    s = checker.stats
    assert s.feed_length == 0
    # G0 X2. Z1. from the start (X0 Z0; X a diameter: 1 across) and from the last stroke's
    # end X0.8 Z-0.6 (0.6 across) back to X2. Z1.: the two rapids, no stroke of G241
    assert s.rapid_length == pytest.approx(math.hypot(1, 1) + math.hypot(0.6, 1.6), abs=1e-3)
    assert len(s.moves_not_known) == 1 and s.moves_not_known[0].startswith(
        "from line 7: G241 is a canned cycle of the control's list")


def test_fanuc_fluctuation_detection_words_are_no_lengths():
    """G26 P Q R D: a time in ms, two percentages and a speed, whole numbers (0i-MF/0i-TF):
    kept as written; the mill's R was converted as a length, and Q D read in increments."""
    for profile in ("fanuc-mill", "fanuc-lathe"):
        text = "%\nO1\nG20\nG26 P1000 Q10 R5 D50\nG25\nM30\n%\n"
        assert "G26 P1000 Q10 R5 D50" in converted(text, profile, "metric")


def test_polygon_turning_s_ratio_is_kept_and_its_r_refused_under_a_change_of_units():
    text = "%\nO1\nG20\nG51.2 P1 Q2\nG50.2\nM30\n%\n"
    assert "G51.2 P1 Q2" in converted(text, "fanuc-lathe", "metric")
    with pytest.raises(ConversionError) as e:
        converted(text.replace("Q2", "Q2 R10."), "fanuc-lathe", "metric")
    assert "R10." in str(e.value)


def test_okuma_lathe_corner_sizes_and_m_tool_depths_convert_as_lengths():
    text = ("O1\nG00 X100 Z50\nG95\nG01 G75 X50 L2 F0.2\nG76 Z-20 L1.5\n"
            "G181 X0 Z-10 C0 D2 F0.1 E1.\nG180\nM02\n")
    out = converted(text, "okuma-lathe", "inch").splitlines()
    assert "G01 G75 X1.9685 L0.0787 F0.008" in out
    assert "G76 Z-0.7874 L0.0591" in out
    assert "G181 X0 Z-0.3937 C0 D0.0787 F0.004 E1." in out


def haas_mill(body: str) -> str:
    return f"%\nO01000\nG20 G17 G40 G80 G90 G54\nT1 M06\nG00 X1. Y1. S2000 M03\n{body}\nM30\n%\n"


def test_a_haas_feature_coordinate_system_is_a_code_of_the_plane_group():
    """G268/G269 (group 02, the public table of the Haas list): no TG307; G268 with a plane code
    of its block is two codes of one group (TG304)."""
    text = haas_mill("G268 X2. Y1. Z0 I0 J45. K0\nG01 X0 Y0 F10.\nG02 X1. Y0 R0.5\nG269")
    assert [f for f in found(text, "haas-mill") if f[0] in ("TG304", "TG306", "TG307")] == []
    hits = fired(haas_mill("G17 G268 X2. Y1. Z0"), "haas-mill", "TG304")
    assert [(s, line) for s, line, _ in hits] == [("error", 6)]
    # the lathe's list has no such code
    assert [at for _, at, _ in fired(lathe("G268 X1."), "haas-lathe", "TG307")] == [7]


def test_a_haas_feature_coordinate_system_s_words_are_no_move_and_convert_by_their_roles():
    """G268's words as the Autodesk Haas post writes them: its block's X Y Z are the origin,
    no move (the span of X stays the program's moves, 0 to 1 in) and lengths under a change of
    units; I J K angles and Q the rotation order are kept; a word the post never writes is
    refused at its column."""
    text = haas_mill("G268 X5. Y1. Z0 I0 J45. K0 Q1\nG01 X0 Y0 F10.\nG269\nG00 X1. Y1.")
    assert stats_high(text, "haas-mill", "X") == pytest.approx(1.0)
    assert "G268 X127. Y25.4 Z0 I0 J45. K0 Q1" in converted(text, "haas-mill", "metric")
    with pytest.raises(ConversionError) as e:
        converted(text.replace("Q1", "Q1 R2."), "haas-mill", "metric")
    assert ":6:31: R2.: the source control's manual, as tapegate has it, does not say what R" in \
        str(e.value)
    # the picture names it as a transform it does not apply, as it does a G68
    note = transforms_note(backplot(text, load_profile("haas-mill")))
    assert note.startswith("not applied: G268 (line 6)")
    # without G268 the same words are a move, converted as lengths
    plain = converted(haas_mill("G00 X5. Y1. Z0\nG269"), "haas-mill", "metric").splitlines()
    assert "G00 X127. Y25.4 Z0" in plain and "G269" in plain


@pytest.mark.parametrize("block", ["G90 G91 G00 X1. Y1.", "G17 G18", "G268 X1. Y1. Z0 G269"])
def test_two_haas_g_codes_of_one_group_in_a_block_are_an_error(block):
    """The NGC mill manual (2017, "Programming", "G-codes"): two G codes of one group may not
    stand in one block."""
    hits = fired(haas_mill(block), "haas-mill", "TG304")
    assert [(s, line) for s, line, _ in hits] == [("error", 6)]


def test_a_fanuc_machining_centre_turning_cycle_leaves_the_path_unknown_and_is_refused():
    """G71.7 (a 30i/0i-F machining centre's stock removal in turning): no stored FANUC page gives
    its words, so it stays a code the list lacks -- its rough passes are no rapids of the G00 in
    force (the path is not known from its line until a motion code), and a change of units
    refuses its block at the first word of a code's role, at its line and column."""
    text = fanuc("G00 X50. Y0 Z5.\nG71.7 U2. R1.\nG71.7 P100 Q200 U0.5 W0.1 F200.\n"
                 "N100 G01 X20.\nZ-10.\nN200 X50.\nG70.7 P100 Q200\nG00 Z100.")
    profile = load_profile("fanuc-mill")
    checker = Checker(profile)
    list(checker.run_stream([text], profile.dialect))
    said = checker.stats.moves_not_known
    assert [m.split(":")[0] for m in said] == ["from line 5", "from line 10"]
    assert "G71.7 is not in the family's code list" in said[0]
    with pytest.raises(ConversionError) as e:
        converted(text, "fanuc-mill", "inch")
    assert ":5:11: R1.: G71.7 is not in the source control's G code list" in str(e.value)


@pytest.mark.parametrize("turn, cancel", [("G268 X0. Y0. Z0. I0. J0. K0. Q123", "G269"),
                                          ("G68 X0. Y0. R45.", "G69")])
def test_the_spans_restart_where_a_frame_is_cancelled(turn, cancel):
    """X31 under the frame and X-29.5 after its cancel are positions of two frames: no span of
    60.5 (a false TG601 error on a 60-wide travel). Without a frame the same moves are one."""
    moves = "G00 X-29.5 Y0.\n{turn}\nG00 X31. Y0.\n{cancel}\nG00 X-29.5 Y0."
    narrow = profile_from_text('base = "haas-mill"\n[limits]\nX = [-30, 30]\n', "narrow")
    text = haas_mill(moves.format(turn=turn, cancel=cancel))
    assert [f for f in check_text(text, narrow) if f.rule == "TG601"] == []
    plain = haas_mill(moves.format(turn="", cancel=""))
    said = [f.message for f in check_text(plain, narrow) if f.rule == "TG601"]
    assert said and said[0].startswith("X spans 60.5")


def test_after_g268_the_operator_is_told_over_travel_is_not_checked_by_the_offsets():
    """With the profile's work offsets, G268 ... G269 then X55. (35 in machine coordinates on a
    -30 to 30 travel) is not compared: said as a TG140 note at G268, not only under --stats."""
    wo = profile_from_text('base = "haas-mill"\n[limits]\nX = [-30, 30]\n'
                           '[work_offsets]\nG54 = { X = -20.0, Y = -10.0 }\n', "wo")
    body = "G268 X0. Y0. Z0. I0. J0. K0. Q123\nG00 X1. Y0.\nG269\nG00 X55. Y0."
    said = [(f.rule, f.line) for f in check_text(haas_mill(body), wo)
            if f.rule in ("TG140", "TG601")]
    assert said == [("TG140", 6)]
    note = next(f for f in check_text(haas_mill(body), wo) if f.rule == "TG140")
    assert "after G269 too" in note.message and "nor, until G269, the span" in note.message
    # without G268 the move is over-travel
    plain = haas_mill("G00 X1. Y0.\nG00 X55. Y0.")
    assert [f.rule for f in check_text(plain, wo) if f.rule == "TG601"] == ["TG601"]


@pytest.mark.parametrize("profile, program", [
    # a FANUC's G117 is a macro call where parameters 6050-6059 make it one: X900. is its
    # argument (#24), not a position, and where X stands after it is not known
    ("fanuc-mill", "%\nO1\nG21 G90 G54 G17\nG0 X0 Y0 Z5.\nG117 X900. Y0\nG1 X-700. F100.\n"
     "M30\n%\n"),
    # a LinuxCNC configuration's REMAP of G68.2 takes X Y Z I J K as its words
    ("linuxcnc", "G21 G90 G54 G17\nG0 X0 Y0 Z5.\nG68.2 X900. Y0 Z0 I0 J45 K0\n"
     "G1 X-700. F100.\nM2\n"),
])
def test_the_axis_words_of_a_code_the_list_lacks_are_no_positions(profile, program):
    """Issue 32, item 4: where a part of the program starts at a position the checker cannot
    know (a macro, a remap), no geometry rule judges it. The code is TG307; the X900 beside
    it spans no travel with the X-700 after it (X travel -762 to 762 on fanuc-mill)."""
    found = check_text(program, load_profile(profile))
    assert [f.rule for f in found if f.severity == "warning"] == ["TG307"], found
    assert [f for f in found if f.rule == "TG601"] == [], found
    # a move the program makes itself is judged: X-700 then X900 in one program still spans
    # (the linuxcnc profile has no travel to judge it against)
    if profile == "fanuc-mill":
        moved = program.replace("G1 X-700. F100.", "G1 X-700. F100.\nX900.")
        assert [f.rule for f in check_text(moved, load_profile(profile))
                if f.rule == "TG601"] == ["TG601"]
