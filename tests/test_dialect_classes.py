"""Classes of control behaviour found on real programs from outside the corpus (issue 32;
docs/dialects.md), each with small programs of our own from the manuals' forms, firing and
quiet: Fanuc program numbers of the 8-digit option, the Okuma OSP user task's arithmetic,
strings and loops, LinuxCNC subroutine files, and the feed a subprogram starts with.
"""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner

from formats.errors import ProfileError
from formats.parser import BadBlock, parse_text
from formats.printer import program_text
from formats.profile import load_profile, profile_from_text
from postproc.check import check_text
from tapegate.cli import main


def found(text: str, profile: str) -> list[tuple[str, str, int]]:
    """(rule, severity, line) of every finding but the notes about style."""
    return [(f.rule, f.severity, f.line) for f in check_text(text, load_profile(profile))
            if f.rule not in ("TG130", "TG133", "TG703")]


def errors(text: str, profile: str) -> list[tuple[str, int]]:
    return [(rule, line) for rule, severity, line in found(text, profile) if severity == "error"]


def jsonl(*args: str) -> tuple[int, list[dict]]:
    result = CliRunner().invoke(main, ["check", "--format", "jsonl", "-j", "1", *args])
    lines = [json.loads(line) for line in result.output.splitlines() if line.startswith("{")]
    return result.exit_code, lines


# -- Fanuc: program numbers of the 8-digit program number option ------------------------------


@pytest.mark.parametrize("number", ["O80000001", "O110001", "O00001234", "O1"])
def test_fanuc_program_numbers_up_to_eight_digits_are_read(number):
    main_program = (f"%\n{number} (MAIN)\nG21 G90 G00 X0 Y0\nG65 P130001 A1.\nM98 P80000003\n"
                    "M30\n%\n")
    assert not errors(main_program, "fanuc-mill")
    sub = f"%\n{number}\nG21 G99 G00 X40. Z2.\nM98 P30001234\nG65 P80000001\nM99\n%\n"
    assert not errors(sub, "fanuc-lathe")


@pytest.mark.parametrize("profile", ["fanuc-mill", "fanuc-lathe"])
def test_a_fanuc_program_number_of_nine_digits_is_refused(profile):
    text = "%\nO123456789\nG21 G00 X0\nM30\n%\n"
    hits = [f for f in check_text(text, load_profile(profile)) if f.rule == "TG205"]
    assert [(f.line, f.column) for f in hits] == [(2, 1)]
    assert "O08 holds 8" in hits[0].message


LATHE_CYCLE = """%
O0001
G21 G99 G00 X50. Z2.
G71 U1. R0.5
G71 P{n} Q{m} U0.2 W0.1 F0.2
N{n} G00 X20.
N{m} G01 Z-10.
G70 P{n} Q{m}
M30
%
"""


@pytest.mark.parametrize("profile, rule, severity", [
    ("fanuc-lathe", "TG205", "error"),    # N holds five digits: PS0003
    ("haas-lathe", "TG208", "warning"),   # a Haas's longer N: no alarm documented
])
def test_a_cycle_s_p_and_q_are_sequence_numbers_of_n_s_digits(profile, rule, severity):
    """G70-G73 P and Q name the finishing contour's first and last blocks: N's format, and
    what the control does with a longer N, whatever P's own digits (eight on fanuc-lathe, for
    M98 P). The block numbers themselves are said at their N words."""
    fine = check_text(LATHE_CYCLE.format(n=100, m=200), load_profile(profile))
    assert not [f for f in fine if f.rule in ("TG205", "TG208")], fine
    long = [f for f in check_text(LATHE_CYCLE.format(n=100000, m=100010), load_profile(profile))
            if f.rule == rule]
    at = [(f.line, f.column, f.severity) for f in long]
    assert at == [(5, 5, severity), (5, 13, severity), (6, 1, severity), (7, 1, severity),
                  (8, 5, severity), (8, 13, severity)]
    assert "in a G71 block P names a sequence number, whose format N05 holds 5" in long[0].message


@pytest.mark.parametrize("profile, block, rule, column", [
    ("fanuc-mill", "M99 P123456", "TG205", 5),          # a sequence number: N05
    ("fanuc-lathe", "M99 P123456", "TG205", 5),
    ("fanuc-mill", "G65 P123456789 A1.", "TG205", 5),   # a program number: O08
    ("fanuc-mill", "M98 P12345678", None, 0),           # count and number, or O08: P08
    ("fanuc-mill", "G04 P12345678", None, 0),           # a dwell in ms: P08
    ("fanuc-lathe", "G04 P123456789", "TG205", 5),
    ("haas-mill", "M98 P123456", "TG205", 5),           # a program number: O05
    ("haas-mill", "M97 P123456", "TG208", 5),           # a block number: N05, past it TG208
    ("haas-mill", "G65 P12345 A1.", None, 0),
])
def test_what_p_names_in_its_block_sets_its_digits(profile, block, rule, column):
    text = f"%\nO0001\nG21 G00 X0 Y0\n{block}\nM30\n%\n"
    hits = [(f.rule, f.line, f.column) for f in check_text(text, load_profile(profile))
            if f.rule in ("TG205", "TG208")]
    assert hits == ([(rule, 4, column)] if rule else [])


def test_a_code_s_words_name_n_or_o_only():
    base = "name = \"x\"\ndetailed = \"%/DS O04 N04 G02 X+053 P05 M02*\"\n"
    with pytest.raises(ProfileError, match=r"codes.M98.words.P must be \"N\""):
        profile_from_text(base + "[codes]\nM98 = { function = \"call\", words = { P = \"X\" } }\n")
    with pytest.raises(ProfileError, match=r"codes.G71.words: 'N'"):
        profile_from_text(base + "[codes]\nG71 = { function = \"c\", words = { N = \"N\" } }\n")
    good = profile_from_text(base + "[codes]\nG71 = { function = \"c\", words = { P = \"N\" } }\n")
    assert good.extra_codes["G71"].words == (("P", "N"),)


def test_a_fanuc_file_of_programs_between_percent_signs_splits_only_at_an_o_number():
    """A Fanuc's `%` is the end of record: no source at hand says a read goes on past it into
    a second program without O (docs/dialects.md), so that one is words after the end
    (TG106, a warning: the control never runs them; at its first block); with its O number it
    is a program of its own."""
    glued = "%\nO0001\nG21 G00 X1.\nM30\n%\nG21 G00 X2.\nM30\n%\n"
    assert ("TG106", "warning", 6) in found(glued, "fanuc-mill")
    assert not errors(glued, "fanuc-mill")
    numbered = glued.replace("%\nG21 G00 X2.", "%\nO0002\nG21 G00 X2.")
    assert not errors(numbered, "fanuc-mill")


def test_a_haas_program_number_keeps_five_digits():
    assert not found("%\nO01001\nG20 G00 X0\nM30\n%\n", "haas-mill")
    assert ("TG208", "warning", 2) in found("%\nO110001\nG20 G00 X0\nM30\n%\n", "haas-mill")


@pytest.mark.parametrize("profile", ["haas-mill", "haas-lathe"])
@pytest.mark.parametrize("number, digits", [("O03082011", 7), ("O2142011", 7), ("O120209", 6)])
def test_a_haas_program_number_past_five_digits_says_what_no_source_gives(profile, number, digits):
    """A date or a student's number after O (6-7 digits): the NGC manual gives the format
    Onnnnn, and no Haas source at hand says what the control does with more (an alarm, or the
    file loaded under its name). The number names the program and moves nothing, so under
    either answer the blocks are read as written: a warning (issue 32, severity by evidence)
    that says both, and the program is checked on (its move past the travel still found)."""
    text = f"%\n{number} (PART)\nG20 G00 X0\nG01 X1. Y1.\nM30\n%\n"
    said = check_text(text, load_profile(profile))
    hits = [f for f in said if f.rule in ("TG205", "TG208")]
    assert [(f.rule, f.severity, f.line, f.column) for f in hits] == [("TG208", "warning", 2, 1)]
    assert hits[0].message.startswith(f"{number}: {digits} digits before the decimal sign")
    assert "NGC, 2017, 4.3.3 and 5.2.2" in hits[0].message
    assert "no Haas source at hand says" in hits[0].message
    assert "the program is read as written" in hits[0].message
    # read on: the G01 without a feed after it is still found, at its line
    assert ("TG401", 4) in errors(text, profile)
    # a Fanuc reads it (the 8-digit program number option) and says nothing
    assert not errors(text.replace("G01 X1. Y1.", "G01 X1. Y1. F10."), "fanuc-mill")


def test_a_haas_program_number_past_five_digits_checks_clean_and_sends(tmp_path):
    """check exits 0 with the warning at its place; send sends it without --force; convert
    to a target whose O format holds five digits still refuses it (a digit overflow in the
    target's format: it cannot carry the number), and to a Fanuc (O of eight digits) carries
    it as written."""
    path = tmp_path / "maze.nc"
    path.write_text("%\nO03082011 (MAZE)\nG20 G90 G54 G00 X0 Y0\nG01 X1. F10.\nM30\n%\n")
    run = CliRunner().invoke(main, ["check", "-p", "haas-mill", str(path)])
    assert run.exit_code == 0, run.output
    assert f"{path}:2:1: warning TG208 O03082011: 7 digits" in run.output
    sent = CliRunner().invoke(main, ["send", "--port", "loop://", "--flow", "none", "-p",
                                     "haas-mill", "-y", str(path)])
    assert sent.exit_code == 0, sent.output
    out = tmp_path / "out.nc"
    refused = CliRunner().invoke(main, ["convert", "--from", "haas-mill", "--to", "haas-mill",
                                        "--units", "metric", "-o", str(out), str(path)])
    assert refused.exit_code != 0
    assert "O03082011 needs 7 digits; the target format O05 holds 5" in refused.output
    assert not out.exists()
    carried = CliRunner().invoke(main, ["convert", "--from", "haas-mill", "--to", "fanuc-mill",
                                        "--units", "metric", "-o", str(out), str(path)])
    assert carried.exit_code == 0, carried.output
    assert out.read_text().splitlines()[1:4] == ["O03082011 (MAZE)", "G21 G90 G54 G00 X0 Y0",
                                                 "G01 X25.4 F254."]


def test_a_haas_o999999_is_named_as_the_offsets_saved_with_a_program():
    """Setting 156 (NGC mill manual, 2017) saves the offsets in the program file under O999999
    before the final %, and loading the file offers to set them: still refused (tapegate does
    not read them, and they would set offsets), with the reason the manual gives, and nothing
    else: the section is no program (no TG114 "no M02 or M30"), and its lines are not read."""
    text = "%\nO01001 (PART)\nG20 G00 X0\nM30\nO999999\n(OFFSETS)\nG10 L99 P1 X-12.34567 Q5\n%\n"
    said = [f for f in check_text(text, load_profile("haas-mill")) if f.severity != "info"]
    assert [(f.rule, f.severity, f.line) for f in said] == [("TG205", "error", 5)]
    assert "O999999 after the program's end heads the offsets a Haas saves with a program " \
        "(Setting 156" in said[0].message
    assert "Mill Operator's Manual, NGC, 2017" in said[0].message
    assert "no Haas source at hand says" not in said[0].message
    # the lathe's profile says whose manual the setting is from
    lathe = [f for f in check_text(text, load_profile("haas-lathe")) if f.rule == "TG205"]
    assert "the Mill Operator's Manual's setting (NGC, 2017); no lathe manual was at hand" in \
        lathe[0].message


HAAS_AFTER_OFFSETS = "%\nO01000\nG20 G90 G54 G00 X0 Y0\nM30\nO999999\nG10 L2 P1 X-1. Y-1.\n{}" \
    "G90 G54 G00 X90. Y0.\nM30\n%\n"


def test_a_program_after_the_haas_saved_offsets_is_read():
    """Review 12: everything after O999999 was skipped, so O02000's 90 in move was never
    checked. The section ends at the next program number: the program after it is read."""
    said = check_text(HAAS_AFTER_OFFSETS.format("O02000\n"), load_profile("haas-mill"))
    assert ("TG205", 5) in [(f.rule, f.line) for f in said]
    assert ("TG601", 8) in [(f.rule, f.line) for f in said]


def test_a_block_that_sets_no_offset_ends_the_haas_saved_offsets_refused():
    """A move after the G10 lines is no saved offset: refused at its line, and read."""
    said = [f for f in check_text(HAAS_AFTER_OFFSETS.format(""), load_profile("haas-mill"))
            if f.severity == "error"]
    assert [(f.rule, f.line, f.column) for f in said if f.rule == "TG205"] == [
        ("TG205", 5, 1), ("TG205", 7, 1)]
    assert "a block that sets no offset after O999999" in said[1].message
    assert ("TG601", 7) in [(f.rule, f.line) for f in said]


def test_an_o999999_after_m99_is_read_as_a_program():
    """Setting 156 writes the offsets after a main program's end; after M99 O999999 is only a
    number too long, and the blocks after it are read."""
    text = "%\nO01000\nG20 G90 G54 G00 X0 Y0\nM99\nO999999\nG00 X90. Y0.\nM30\n%\n"
    said = check_text(text, load_profile("haas-mill"))
    o = [f for f in said if f.rule == "TG205"]
    assert [f.line for f in o] == [5] and "not a program's own number" in o[0].message
    assert ("TG601", 6) in [(f.rule, f.line) for f in said]


def test_a_haas_o999999_at_the_top_of_a_file_is_a_program_number_too_long():
    """As the file's own program number O999999 heads no offsets: the message says what the
    number is where the control writes it, and the program is read and needs its end."""
    text = "%\nO999999\nG20 G00 X0\n%\n"
    said = [f for f in check_text(text, load_profile("haas-mill")) if f.severity != "info"]
    assert [(f.rule, f.line) for f in said] == [("TG205", 2), ("TG114", 4)]
    assert "O999999 is the heading the control gives the offsets it saves after a program's " \
        "end" in said[0].message
    assert "what follows would set offsets" not in said[0].message


# -- Haas NGC: the read-only variables of its Macro Variables Table --------------------------

HAAS_VARIABLES = """%
O01234
G20
#3020 = 0 (power-on timer)
#11018 = 1 (input 18)
#1 = 13013
#[#1] = 5 (coolant level)
#10000 = #3026
#3011 = 20260101
#3001 = 0
#20009 = 1
#12018 = 1
M30
%
"""


@pytest.mark.parametrize("profile", ["haas-mill", "haas-lathe"])
def test_haas_ngc_read_only_variables_are_those_of_its_table(profile):
    """Mill Operator's Manual, NGC (2017), 6.14.7: the inputs, the timers, the tool in the
    spindle and its speed are read only (TG209); Custom Macro B's list (the date, #3011),
    which the table does not mark, is a warning (TG211); the millisecond timer (#3001), a
    setting (#20009) and an output (#12018) are set."""
    found = check_text(HAAS_VARIABLES, load_profile(profile))
    hits = [(f.line, f.message) for f in found if f.rule == "TG209"]
    assert [line for line, _ in hits] == [4, 5, 7]
    assert [(f.line, f.severity) for f in found if f.rule == "TG211"] == [(9, "warning")]
    assert hits[0][1].startswith("#3020 is the power-on timer, read only")
    assert "checks.read_only" in hits[0][1]
    assert hits[2][1].startswith("#[#1] (#13013) is a filtered analog to digital input")
    # FANUC's alarm number is no Haas's: the Haas message quotes none
    assert not any("PS0116" in message for _, message in hits), hits
    # a Fanuc: Custom Macro B's own list, where the date is read only (PS0116)
    fanuc = [(f.line, f.message) for f in check_text(HAAS_VARIABLES, load_profile("fanuc-mill"))
             if f.rule == "TG209"]
    assert [line for line, _ in fanuc] == [9] and "PS0116" in fanuc[0][1]


# -- Okuma OSP: user task arithmetic, strings, loops, long sequence names ----------------------


OSP_LIBRARY = """OCLER
(PSRT, PEND: THE FIRST AND LAST VC TO CLEAR)
    IF [PSRT EQ EMPTY] NALM1
    CNTR = PSRT (FIRST)
    WHILE [CNTR LE PEND] DO 1
        VC[CNTR] = EMPTY
        CNTR = CNTR + 1
    END 1
    MROT = PRS + [ROT * [PINS - 1]]
    VC81 = VTOHT [[VC100],10001] (HEIGHT)
    DO 2
        IF [[CNTR + 1] GT PEND] NBRK
        CNTR = [CNTR + 1]
    END 2
    NBRK
    IF[VTLCN EQ 850020] N850020
    GOTO NEND
    NALM1
        VUACM[1]='PSRT = 0 (MISSING) #1.'
        VDOUT[993]=9001
    N850020 (LONG SEQUENCE NAME)
NEND
RTS
"""


def test_osp_user_task_statements_are_read_byte_for_byte():
    blocks = parse_text(OSP_LIBRARY, load_profile("okuma-mill").dialect, errors="collect")
    assert not [b for b in blocks if isinstance(b, BadBlock)]
    assert program_text(blocks) == OSP_LIBRARY
    kinds = {text: kind for b in blocks for _, text, kind in b.statements}
    assert kinds["VUACM[1]='PSRT = 0 (MISSING) #1.'"] == "assignment"
    assert kinds["CNTR = CNTR + 1"] == "assignment"
    assert kinds["VC81 = VTOHT [[VC100],10001]"] == "assignment"
    assert kinds["WHILE [CNTR LE PEND] DO 1"] == kinds["END 1"] == kinds["DO 2"] == "flow"


def test_an_osp_sequence_name_past_the_format_is_a_warning():
    got = found(OSP_LIBRARY, "okuma-mill")
    assert not [f for f in got if f[1] == "error"], got
    assert ("TG208", "warning", 21) in got
    # a Fanuc's N past its eight digits stays an alarm
    assert ("TG205", 3) in errors("%\nO1\nN123456 G21 G00 X0\nM30\n%\n", "fanuc-mill")


@pytest.mark.parametrize("statement, column, what", [
    ("VUACM[1]='NO END", 10, "closing '"),
    # the shared expression reader's errors, as a Fanuc's: an operand missing, or two with no
    # operator between them
    ("CNTR = CNTR +", 14, "expression ends without an operand"),
    ("VC1 = * 3", 7, "found '*'"),
    ("VC1 = VC2 VC3", 11, "two operands without an operator between them"),
    ("VC1 = VC2 3", 11, "two operands without an operator between them"),
    ("WHILE CNTR LE 3 DO 1", 7, "condition in [ ]"),
    ("WHILE [CNTR LE 3] 1", 19, "DO and the loop's number"),
])
def test_a_malformed_osp_statement_is_located(tmp_path, statement, column, what):
    path = tmp_path / "OBAD.LIB"
    path.write_text(f"OBAD\n{statement}\nRTS\n")
    code, lines = jsonl(str(path), "-p", "okuma-mill")
    assert code == 1
    hits = [f for f in lines if f.get("rule") == "TG100"]
    assert [(f["line"], f["column"]) for f in hits] == [(2, column)]
    assert what in hits[0]["message"]


def test_an_okuma_in_inch_reads_its_lengths_to_0_0001_in():
    """OSP-U100M/U10M Operation Manual (4203-E), section 1: "Inch system: 0.0001 in."; the
    machining centre selects inch by G20, the lathe by its unit system parameter (its G20 is a
    home position return): a lathe profile with ``units = "inch"``."""
    import dataclasses

    def tg208(units: str, text: str, profile) -> list[int]:
        program = f"$T.MIN%\nO1\n{units}\n{text}\nM02\n"
        return [f.line for f in check_text(program, profile) if f.rule == "TG208"]
    mill, move = load_profile("okuma-mill"), "G00 X1.2345 Y0.1 Z0.1"
    assert tg208("G20", move, mill) == []
    assert tg208("G20", move.replace("1.2345", "1.23456"), mill) == [4]
    assert tg208("G21", move, mill) == [4]  # 0.001 mm in metric
    lathe, move = load_profile("okuma-lathe"), "G00 X1.2345 Z0.1"
    inch_lathe = dataclasses.replace(lathe, default_units="inch")
    assert tg208("G50 S2000", move, inch_lathe) == []
    assert tg208("G50 S2000", move.replace("1.2345", "1.23456"), inch_lathe) == [4]
    assert tg208("G50 S2000", move, lathe) == [4]
    # and G20 on the metric lathe is its home position return, no inch: still 0.001 mm
    assert tg208("G20 HP=1", move, lathe) == [4]


def test_an_okuma_lathe_program_converted_to_inch_keeps_0_0001_in():
    from formats.convert import ConvertOptions, convert_text

    lathe = load_profile("okuma-lathe")
    src = "$T.MIN%\nO1\nG00 X31.37 Z2.\nG01 Z-25.4 F0.1\nG03 X33.37 Z-26.4 L1.\nM02\n"
    out = convert_text(src, ConvertOptions(lathe, lathe, units="inch"))[0]
    assert "G00 X1.235 Z0.0787\n" in out and "L0.0394" in out


# -- LinuxCNC: a subroutine file, called by its name ------------------------------------------


SUB_FILE = "(z_touch.ngc)\no<z_touch> sub\nG92.1\nG10 L20 P0 Z25\no<z_touch> endsub\n"


@pytest.mark.parametrize("after", ["", "M2\n", "%\n"])
def test_a_linuxcnc_subroutine_file_needs_no_m2(after):
    text = ("%\n" if after == "%\n" else "") + SUB_FILE + after
    assert "TG114" not in [rule for rule, _, _ in found(text, "linuxcnc")]


@pytest.mark.parametrize("text", [
    SUB_FILE + "o<z_touch> call\n",           # a program that calls it: ends with M2
    "G0 X0\no<b> call\n" + SUB_FILE,          # a call before the definition
    "o<a> sub\nG0 X1\no<a> endsub\no<b> sub\nG0 X2\no<b> endsub\n",  # two definitions
])
def test_a_file_that_is_more_than_one_subroutine_still_needs_m2(text):
    assert "TG114" in [rule for rule, _ in errors(text, "linuxcnc")]


# Issue 32, audit 37 I: a subroutine file read as `o<name> call` runs it (rs274 -i with a
# SUBROUTINE_PATH): (1) an endsub inside a condition of the body is an early return, (2) an
# endsub of another label returns too, (3) the lines before the sub are skipped by the call.
CALLED = {
    "early": ("o<t2> sub\n#<r> = 5\no100 if [#1 EQ 1]\n  o<t2> endsub [1]\no100 endif\n"
              "G0 X#<r>\no<t2> endsub [2]\n",
              "o<t2> call [0]\nG0 X0\no<t2> call [1]\nG0 Y1\nM2\n",
              [], [(5, 0), (0, 0), (0, 1)]),
    "other": ("o<t-4> sub\nG0 X3\no<t_4> endsub\n\nm2\n",
              "o<t-4> call\nG0 X0\nM2\n",
              [("TG138", "warning", 3)], [(3, 0), (0, 0)]),
    "before": ("(a library sub)\n#<_t3> = 0\nG0 Z9\nO<t3> SUB\n#<_t3> = [#1 + 1]\nO<t3> ENDSUB\n",
               "o<t3> call [4]\nG0 X#<_t3>\nM2\n",
               [("TG117", "warning", 2)], [(5, 0)]),
}


@pytest.mark.parametrize("form", CALLED)
def test_a_linuxcnc_subroutine_file_is_checked_as_a_call_runs_it(form, tmp_path):
    """tapegate's findings on the subroutine file, beside what rs274 does when a caller
    calls it (where rs274 is installed): it runs without an error, and its moves are these."""
    import re
    import shutil
    import subprocess

    from .conftest import rs274_env

    sub, caller, expected, moves = CALLED[form]
    assert [f for f in found(sub, "linuxcnc") if f[1] != "info"] == expected
    if shutil.which("rs274") is None:
        pytest.skip("LinuxCNC's rs274 is not installed")
    name = re.search(r"o<([^>]+)>", sub, re.IGNORECASE)[1]  # type: ignore[index]
    subs = tmp_path / "subs"
    subs.mkdir()
    (subs / f"{name}.ngc").write_text(sub)
    (tmp_path / "caller.ngc").write_text(caller)
    (tmp_path / "t.ini").write_text(f"[RS274NGC]\nSUBROUTINE_PATH = {subs}\n"
                                     f"PARAMETER_FILE = {tmp_path / 'rs274.var'}\n")
    (tmp_path / "rs274.var").write_text("")
    run = subprocess.run(["rs274", "-i", str(tmp_path / "t.ini"), "-g",
                          str(tmp_path / "caller.ngc")], capture_output=True, text=True,
                         timeout=30, input="", env=rs274_env(), cwd=tmp_path)
    out = run.stdout + run.stderr
    assert "PROGRAM_END()" in out, out
    traverses = [tuple(round(float(v)) for v in m.groups()) for m in
                 re.finditer(r"STRAIGHT_TRAVERSE\(([-\d.]+), ([-\d.]+), ([-\d.]+)", out)]
    assert [(x, y) for x, y, _ in traverses] == moves, out
    if form == "before":
        # the G0 Z9 before the sub never ran
        assert all(z == 0 for _, _, z in traverses), out


# -- the feed a subprogram starts with --------------------------------------------------------


HAAS_SUB = "%\nO01002 (SUB)\nG91 G01 Z-0.1\nX1.\nG90\nM99\n%\n"


def test_a_subprogram_ending_with_m99_runs_under_its_caller_s_feed():
    assert "TG401" not in [rule for rule, _, _ in found(HAAS_SUB, "haas-mill")]
    assert "TG401" not in [rule for rule, _, _ in found(HAAS_SUB, "fanuc-mill")]


def test_a_main_program_s_first_feed_move_without_f_stays_an_error():
    main_program = HAAS_SUB.replace("M99", "M30")
    assert [e for e in errors(main_program, "haas-mill") if e[0] == "TG401"] == [
        ("TG401", 3), ("TG401", 4)]
    # a file that ends without M30 or M99: a main program as far as anyone can tell
    assert ("TG401", 3) in errors(HAAS_SUB.replace("M99\n", ""), "haas-mill")


def test_a_subprogram_after_m30_in_the_same_file_starts_with_its_feed_unknown():
    text = "%\nO01000\nG20 G90 G00 X0 Y0\nG01 X1. F20.\nM97 P100\nM30\nN100 G01 X2.\nM99\n%\n"
    assert "TG401" not in [rule for rule, _, _ in found(text, "haas-mill")]


@pytest.mark.parametrize("name, expected", [("GEAR.SPF", []), ("GEAR.spf", []),
                                            ("GEAR.MPF", [2, 3])])
def test_a_sinumerik_spf_starts_under_its_caller_s_feed(tmp_path, name, expected):
    path = tmp_path / name
    path.write_text("; shape, called with its feed\nG90 G01 Z-2.8891 Y0\nZ-3.8 Y1.01\nM30\n")
    _, lines = jsonl(str(path), "-p", "sinumerik-840d")
    assert [f["line"] for f in lines if f.get("rule") == "TG401"] == expected


def test_a_sinumerik_proc_starts_under_its_caller_s_feed_whatever_its_name():
    text = "PROC SHAPE\nN10 G1 X10\nN20 M30\n"
    assert "TG401" not in [rule for rule, _, _ in found(text, "sinumerik-840d")]
    assert ("TG401", 2) in errors(text.replace("PROC SHAPE", "; SHAPE"), "sinumerik-840d")


@pytest.mark.parametrize("end", ["M17", "RET"])
def test_a_sinumerik_subprogram_ending_with_m17_or_ret_has_its_caller_s_feed(end):
    text = f"; SHAPE\nN10 G1 X10\nN20 {end}\n"
    assert "TG401" not in [rule for rule, _, _ in found(text, "sinumerik-840d")]
    assert ("TG401", 2) in errors(text.replace(end, "M30"), "sinumerik-840d")


def test_an_osp_subprogram_ending_with_rts_has_its_caller_s_feed():
    text = "OSUB\nG1 X10\nRTS\n"
    assert "TG401" not in [rule for rule, _, _ in found(text, "okuma-mill")]
    assert ("TG401", 2) in errors(text.replace("RTS", "M02"), "okuma-mill")


# -- forms no source at hand documents: refused at their column, by name ----------------------
# (docs/dialects.md, "What was searched and not found": Haas NGC parameter variables with a
# decimal part, as Renishaw's Inspection Plus macros for the NGC write them, and the first
# letters of a Custom Macro B word, as a Fanuc 0i-MD macro writes WH for WHILE)

NGC_PROBE = """%
O09810 (NGC PARAMETERS)
#10100=#30003.078
IF [ #30057.21 ] GOTO22
G01 Z [ - [ [ #30003.036 - 12.7 ] * #179 ] - #31 ] F100.
N22 M99
%
"""

ABBREVIATED = """%
O9811 (HELICAL BORE)
#1=#26
WH[[#1GE#2]AND[#3GE#7]]DO1
#1=#1-#19
END1
M99
%
"""


@pytest.mark.parametrize("profile", ["fanuc-mill", "fanuc-lathe"])
def test_a_variable_number_with_a_decimal_part_is_refused_by_name(tmp_path, profile):
    """On a Fanuc a variable is numbered with a whole number: refused by name. (A Haas reads
    the NGC program as an unknown value since issue 32's severity by evidence, below.)"""
    path = tmp_path / "O09810.nc"
    path.write_text(NGC_PROBE)
    code, lines = jsonl(str(path), "-p", profile)
    assert code == 1
    hits = [f for f in lines if f.get("rule") == "TG100"]
    assert [(f["line"], f["column"]) for f in hits] == [(3, 8), (4, 6), (5, 15)]
    assert [f["message"].split(" has")[0] for f in hits] == [
        "variable #30003.078", "variable #30057.21", "variable #30003.036"]
    assert all("decimal part" in f["message"] for f in hits)
    # the rest of the program is read, and the text is kept byte for byte
    read = parse_text(NGC_PROBE, load_profile(profile).dialect, errors="collect")
    assert program_text(read) == NGC_PROBE
    assert [i for i, b in enumerate(read) if isinstance(b, BadBlock)] == [2, 3, 4]


@pytest.mark.parametrize("profile", ["haas-mill", "fanuc-mill"])
def test_the_same_program_with_whole_variable_numbers_reads(profile):
    whole = NGC_PROBE.replace("#30003.078", "#30078").replace("#30057.21", "#30057").replace(
        "#30003.036", "#30036")
    assert not errors(whole, profile)


@pytest.mark.parametrize("profile", ["fanuc-mill", "fanuc-lathe", "haas-mill"])
def test_a_macro_word_s_first_letters_are_refused_by_name(tmp_path, profile):
    path = tmp_path / "O9811.nc"
    path.write_text(ABBREVIATED)
    code, lines = jsonl(str(path), "-p", profile)
    assert code == 1
    hits = [f for f in lines if f.get("rule") == "TG100"]
    assert [(f["line"], f["column"]) for f in hits] == [(4, 1)]
    assert hits[0]["message"].startswith("'WH' is not read as WHILE")
    # written in full, the loop reads
    assert not errors(ABBREVIATED.replace("WH[", "WHILE["), profile)


def test_convert_and_diff_refuse_what_check_refuses(tmp_path):
    """One reader: convert and diff stop at the same block, with the same message, as check
    (convert: exit 1, the file failed; diff: exit 2, a file that cannot be read)."""
    path = tmp_path / "O9811.nc"
    path.write_text(ABBREVIATED)
    result = CliRunner().invoke(main, ["convert", str(path), "--from", "fanuc-mill",
                                       "--to", "haas-mill", "-o", str(tmp_path / "out.nc")])
    assert result.exit_code != 0
    assert f"{path}:4:1: 'WH' is not read as WHILE" in result.output, result.output
    assert "Traceback" not in result.output
    result = CliRunner().invoke(main, ["diff", str(path), str(path), "-p", "fanuc-mill"])
    assert result.exit_code == 2, result.output
    assert f"{path}:4:1" in result.output and "'WH' is not read as WHILE" in result.output
    assert "Traceback" not in result.output


# -- blanks inside a word (docs/dialects.md, "Blanks inside a word") ---------------------------
# The Haas NGC mill manual (2017, 6.14 "Macros", Editing) gives `G01 G90 X 0 Y3.0` as wrong, "an
# alarm at runtime" (a letter standing alone is an address expression), and `X [COS [90]]` and
# `X0` as right. No Fanuc source at hand says what a blank inside a word does: the forms the
# reader refused stay refused, saying so; a blank between an address and its number is skipped
# there as ISO 6983-1 (4-08) skips it.

APART = """%
O40001 (BLANKS)
G00 G90 G54 X0 Y0
G01 G90 X 0 Y3.0 F20.
G01 G90 X [COS [90]] Y3.0
G01 X0 Y3.0
M30
%
"""
# the same on the lathe (one control software, the NGC; its lathe volume was not at hand)
APART_LATHE = """%
O40002 (BLANKS)
G00 G54 X0 Z1.
G01 X 0 Z-3.0 F0.2
G01 X [COS [90]] Z-3.0
G01 X0 Z-3.0
M30
%
"""


@pytest.mark.parametrize("profile, program", [("haas-mill", APART), ("haas-lathe", APART_LATHE)])
def test_a_haas_refuses_an_address_written_apart_from_its_number(tmp_path, profile, program):
    path = tmp_path / "O40001.nc"
    path.write_text(program)
    code, lines = jsonl(str(path), "-p", profile)
    assert code == 1
    hits = [f for f in lines if f.get("rule") == "TG100"]
    assert [(f["line"], f["column"]) for f in hits] == [(4, program.split("\n")[3].index(" 0") + 1)]
    assert hits[0]["message"].startswith("address X written apart from its number")
    assert "NGC, 2017, 6.14" in hits[0]["message"]
    # the rest is read, and the text is kept byte for byte
    read = parse_text(program, load_profile(profile).dialect, errors="collect")
    assert program_text(read) == program
    assert [i for i, b in enumerate(read) if isinstance(b, BadBlock)] == [3]
    # written together, the program reads
    assert not errors(program.replace("X 0", "X0"), profile)


@pytest.mark.parametrize("block, column", [("G01 X- 1. F10.", 7), ("G01 X 1. F10.", 6)])
def test_a_haas_refuses_a_number_apart_from_its_sign_as_from_its_address(block, column):
    """`X- 1.` is the NGC's `X 1.` with the sign before the blank: the number is not where its
    address ends, refused the same; `X-1.` and `X #101` (an address with a variable) read."""
    program = f"%\nO40003\nG00 G90 G54 X0 Y0\n{block}\nM30\n%\n"
    read = parse_text(program, load_profile("haas-mill").dialect, errors="collect")
    bad = [b for b in read if isinstance(b, BadBlock)]
    assert len(bad) == 1 and bad[0].line == 4, bad
    assert f":4:{column}: address X written apart from its number" in str(bad[0].error)
    assert not errors(program.replace(block, "G01 X-1. F10."), "haas-mill")
    assert not errors(program.replace(block, "G01 X #101 F10."), "haas-mill")


def test_a_haas_reads_a_blank_after_the_sign_of_an_assignment_s_value():
    """After `#8=` no address waits for its number: the value is an arithmetic expression (Haas
    96-8000, "Macros", "Arithmetic Expressions"), whose sign is an operator, so `#8= - 20.` reads
    as `#8= - #4` and `#8= 5. - 20.` do; the NGC's alarm for an address apart from its number
    (`Y- 1.`) still stands in the same program (held11: a shop's Haas macro templates)."""
    program = "%\nO01000\n#4= 1.\n#8= - 20.\n#9= + 20.\nG00 G90 G54 X#8 Y#9\nM30\n%\n"
    read = parse_text(program, load_profile("haas-mill").dialect, errors="collect")
    assert not [b for b in read if isinstance(b, BadBlock)]
    assert program_text(read) == program
    assert not errors(program, "haas-mill")
    apart = program.replace("Y#9", "Y- 1.")
    read = parse_text(apart, load_profile("haas-mill").dialect, errors="collect")
    bad = [b for b in read if isinstance(b, BadBlock)]
    assert len(bad) == 1 and bad[0].line == 6, bad
    assert ":6:19: address Y written apart from its number" in str(bad[0].error)


def test_a_fanuc_reads_the_blank_between_an_address_and_its_number():
    assert not errors(APART, "fanuc-mill")


BLANK_HASH = "%\nO1\n# 1 = 5.\nG90 G0 X0 Y0\nG1 X # 1 Y-# 1 Z[# 1+1.] F100.\nM30\n%\n"


@pytest.mark.parametrize("profile", ["fanuc-mill", "fanuc-lathe"])
def test_a_fanuc_reads_a_blank_after_the_hash_of_a_word_s_value_as_of_an_assignment(profile):
    """Audit 50, B12: `# 1 = 5.` read and `X # 1` was TG100; the blank after `#` is skipped in
    both, as between any address and its number: the findings are those of `X#1`."""
    text = BLANK_HASH if profile == "fanuc-mill" else BLANK_HASH.replace(
        " Y-# 1", "").replace("G90 G0 X0 Y0", "G0 X0 Z0")
    assert not errors(text, profile)
    # read as the form without the blank is: the same findings (`X#1` a known value)
    assert found(text, profile) == found(text.replace("# 1", "#1"), profile)
    read = parse_text(text, load_profile(profile).dialect, errors="collect")
    assert program_text(read) == text


def test_a_haas_refuses_a_blank_after_the_hash_of_a_word_s_value_as_of_an_assignment():
    """The NGC's alarm for an address apart from its number: `# 1 = 5.` and `X # 1` alike."""
    read = parse_text(BLANK_HASH, load_profile("haas-mill").dialect, errors="collect")
    bad = [(b.line, str(b.error).split(": ", 1)[0]) for b in read if isinstance(b, BadBlock)]
    assert [line for line, _ in bad] == [3, 5], bad
    assert all("address # written apart from its number" in str(b.error)
               for b in read if isinstance(b, BadBlock))
    assert ":5:7: address #" in str([b.error for b in read if isinstance(b, BadBlock)][1])


BLANK_BRACKET = ("%\nO1\n# [2] = 10.\n#1 = 5.\nG90 G0 X0 Y0\nG1 X # [1] Y-# [1+1] "
                 "Z[# [2]*2.] F100.\nM30\n%\n")


def test_a_fanuc_reads_a_blank_after_the_hash_before_a_bracket_as_before_a_number():
    """Review 52, F1: `X # 1` and `# 1 = 5` read as `X#1` and `#1 = 5` (audit 50, B12), but
    `X # [1]` was TG100 "expected a number or parameter" and `# [2] = 10.` TG100 "'#'
    parameter must be written #n = value": the blank before the bracket is the same blank."""
    assert not errors(BLANK_BRACKET, "fanuc-mill")
    assert found(BLANK_BRACKET, "fanuc-mill") == found(
        BLANK_BRACKET.replace("# [", "#["), "fanuc-mill")
    read = parse_text(BLANK_BRACKET, load_profile("fanuc-mill").dialect, errors="collect")
    assert program_text(read) == BLANK_BRACKET


def test_a_haas_refuses_a_blank_after_the_hash_before_a_bracket_as_before_a_number():
    """The NGC's "written apart" alarm, as `X # 1` and `# 1 = 5.` get, at the blank."""
    read = parse_text(BLANK_BRACKET, load_profile("haas-mill").dialect, errors="collect")
    bad = [str(b.error) for b in read if isinstance(b, BadBlock)]
    assert [b.line for b in read if isinstance(b, BadBlock)] == [3, 6], bad
    assert all("address # written apart from its number" in e for e in bad), bad
    assert ":3:2: address #" in bad[0] and ":6:7: address #" in bad[1], bad


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill"])
@pytest.mark.parametrize("block, column, says", [
    ("G0 G1 8 X1.", 7, "if it is the rest of the word before it (G1 8 for G18)"),
    ("N180 G01 X92. Y50. , R15.", 21, "',' written apart from its letter (', R')"),
])
def test_a_blank_no_source_reads_is_refused_saying_so(tmp_path, profile, block, column, says):
    path = tmp_path / "O1000.nc"
    path.write_text(f"%\nO1000\nG21 G90 G00 X0 Y0\nG01 F100.\n{block}\nM30\n%\n")
    code, lines = jsonl(str(path), "-p", profile)
    assert code == 1
    hits = [f for f in lines if f.get("rule") == "TG100"]
    assert [(f["line"], f["column"]) for f in hits] == [(5, column)]
    assert says in hits[0]["message"] and "no Fanuc or Haas source" in hits[0]["message"]


@pytest.mark.parametrize("profile, block, column, number", [
    ("haas-lathe", "N20 T1 01", 8, "'01'"),      # held12/held13's form: T101 written T1 01
    ("haas-mill", "G00 X1 00. Y2.", 8, "'00.'"),
    ("fanuc-mill", "G00 X1. -2.5", 9, "'-2.5'"),
])
def test_the_stray_number_is_named_whole(tmp_path, profile, block, column, number):
    """The refusal names the number as written after the blank (one sign, its digits and point),
    not its first character: `T1 01` says '01', which is the word's rest if a control read it."""
    path = tmp_path / "O1000.nc"
    path.write_text(f"%\nO1000\nG21 G90 G00 X0 Z0\n{block}\nM30\n%\n")
    code, lines = jsonl(str(path), "-p", profile)
    assert code == 1
    hits = [f for f in lines if f.get("rule") == "TG100"]
    assert [(f["line"], f["column"]) for f in hits] == [(4, column)]
    assert hits[0]["message"].startswith(f"number {number} without an address letter")


def test_linuxcnc_reads_a_blank_inside_a_word_as_rs274_does(tmp_path):
    """rs274 drops every blank outside comments before it reads a line: `G1 8` is G18 and
    `X1 00` is X100 there, which the arc in the XZ plane after it shows (rs274 -g)."""
    from .conftest import rs274_output

    text = "G21 G90 G0 X0 Y0 Z0\nG1 8 F100\nG1 X1 00 Z0\nG2 X0 Z0 I-50 K0\nM2\n"
    out = rs274_output(tmp_path, text)
    assert "SELECT_PLANE(CANON_PLANE_XZ)" in out and "ARC_FEED" in out, out
    blocks = parse_text(text, load_profile("linuxcnc").dialect, errors="collect")
    assert not [b for b in blocks if isinstance(b, BadBlock)]
    assert (blocks[1].words[0], blocks[2].words[1]) == ("G18", "X100")
    assert program_text(blocks) == text
    assert not errors(text, "linuxcnc")


def test_sinumerik_keeps_a_blank_as_a_separator():
    """On a SINUMERIK a blank separates words (`G1 8` is G1 and a number alone), so the Fanuc
    family's note about a blank inside a word is not said there."""
    text = "%_N_T_MPF\nG1 8 X1 F100\nM30\n"
    hits = [f for f in check_text(text, load_profile("sinumerik-840d")) if f.rule == "TG100"]
    assert [(f.line, f.column) for f in hits] == [(2, 4)]
    assert hits[0].message == "number '8' without an address letter"


@pytest.mark.parametrize("profile, says", [
    ("fanuc-mill", "the block holds 'C)', a word at 'C'; read nested, to the ')' that matches"),
    ("haas-mill", "the block holds 'C)', a word at 'C'; read nested, to the ')' that matches"),
    ("fanuc-lathe", "no Fanuc or Haas source at hand says which the control does"),
    ("iso-mill", None),
    ("linuxcnc", None),
])
def test_a_comment_inside_a_comment_says_whose_reading_it_is(profile, says):
    """`(A (B) C)`: ISO 6983-1 and rs274 refuse it. On a Fanuc or a Haas, read to its first
    `)` the block holds `C)`, read nested it holds nothing: the readings differ, so it stays
    refused there, the message saying what each reading leaves and that no source settles it."""
    block = "G21 G00 X0 Z0 (A (B) C)"
    text = f"%\nO1000\n{block}\nM30\n%\n" if profile != "linuxcnc" else f"{block}\nM2\n"
    hits = [f for f in check_text(text, load_profile(profile)) if f.rule == "TG121"]
    assert [(f.severity, f.column) for f in hits] == [("error", block.index("(B") + 1)], hits
    assert hits[0].message.startswith("comment inside a comment")
    if says:
        assert says in hits[0].message
        assert "no Fanuc or Haas source at hand says which" in hits[0].message
    else:
        assert "Fanuc" not in hits[0].message
    assert not [f for f in check_text(text.replace("(A (B) C)", "(A B C)"), load_profile(profile))
                if f.severity == "error"]


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill"])
def test_a_percent_left_by_a_nested_comment_says_the_control_stops_reading(profile):
    """Review 12: `(A (B) %)` read to its first `)` leaves a '%', the end of record; the
    message said only "a word at '%'"."""
    block = "G21 G00 X1. (A (B) %)"
    text = f"%\nO1000\n{block}\nM30\n%\n"
    hits = [f for f in check_text(text, load_profile(profile)) if f.rule == "TG121"]
    assert [(f.severity, f.column) for f in hits] == [("error", block.index("(B") + 1)]
    assert "the block holds '%)', a '%', the tape's end of record: the control stops reading " \
        "the program there" in hits[0].message


# A `(` inside a comment on a Fanuc or Haas (docs/dialects.md, "A '(' inside a comment"): both
# readings, the comment ending at its first ')' or nesting to the matching one, are taken.
LEFT = "is left: no word, no end of block, no block skip"
SAME_WORDS = [
    # (the block, what the first reading leaves after its first ')', the nested reading's end)
    ("G00 X1. (VNMG 332(1))", "a stray ')' is left", "to the matching ')'"),
    ("G00 X1. (CALL THE PROBE (O9100) )", "a stray ')' is left", "to the matching ')'"),
    ("G00 X1. (WAIT (CLEAR #503) ---)", "'---)' " + LEFT, "to the matching ')'"),
    ("G00 X1. (A (B) (C) ...)", "'(C) ...)' " + LEFT, "to the matching ')'"),
    ("G00 X1. (C:\\USERS\\R(STUD\\DESKTOP)", "the comment ends there", "never closed"),
    ("G00 X1. ; (FACE (FINAL) ...)", "'...)' " + LEFT, "to the matching ')'"),
]


@pytest.mark.parametrize("profile", ["fanuc-mill", "fanuc-lathe", "haas-mill", "haas-lathe"])
@pytest.mark.parametrize("block, first, nested", SAME_WORDS)
def test_a_nested_comment_whose_readings_leave_the_same_words_is_a_warning(profile, block,
                                                                           first, nested):
    """Between the first ')' and the end of the nested comment there is no word (only a stray
    ')' or marks a control reading so alarms on or passes over): no reading hides a word, so
    the block is read once, its words X1. alone, and TG136 warns, naming both readings."""
    text = f"%\nO1000\nG21 G90\n{block}\nM30\n%\n"
    profile_ = load_profile(profile)
    hits = [f for f in check_text(text, profile_) if f.rule in ("TG120", "TG121", "TG136")]
    assert [(f.rule, f.severity, f.line) for f in hits] == [("TG136", "warning", 4)], hits
    inner = block.index("(", block.index("(") + 1)
    assert hits[0].column == inner + 1
    assert first in hits[0].message and nested in hits[0].message, hits[0].message
    assert "no Fanuc or Haas source at hand says which reading" in hits[0].message
    assert not errors(text, profile)
    blocks = parse_text(text, profile_.dialect, errors="collect")
    assert not [b for b in blocks if isinstance(b, BadBlock)]
    assert blocks[3].words == ["G00", "X1."]
    assert program_text(blocks) == text


DIFFERENT_WORDS = [
    # (the block, what the first reading leaves that the nested one hides)
    ("G00 X1. (A (B) X5)", "'X5)', a word at 'X'"),
    ("G00 X1. (A (B) (C) Y2)", "'(C) Y2)', a word at 'Y'"),
    ("G00 X1. (DEPTH (MAX) 5)", "'5)', a word at '5'"),
    ("G00 X1. (LINEAR (FACE) TO X=-1.6MM)", "a word at 'T'"),
    ("G00 X1. (A (B) #1=5)", "a word at '#'"),
    ("G00 X1. (A (B) X5", "'X5', a word at 'X'; read nested, it is never closed"),
    ("G00 X1. ; (A (B) X5)", "'X5)', a word at 'X'"),
]


@pytest.mark.parametrize("profile", ["fanuc-mill", "fanuc-lathe", "haas-mill", "haas-lathe"])
@pytest.mark.parametrize("block, says", DIFFERENT_WORDS)
def test_a_nested_comment_whose_readings_differ_stays_an_error(profile, block, says):
    """Where the first ')' leaves a word (or a digit, '#', '%', ':' that may make or join one)
    that the nested reading hides, the two readings send different blocks: TG121, an error,
    showing what the first reading leaves, at the inner '('."""
    text = f"%\nO1000\nG21 G90\n{block}\nM30\n%\n"
    hits = [f for f in check_text(text, load_profile(profile)) if f.rule in ("TG121", "TG136")]
    inner = block.index("(", block.index("(") + 1)
    assert [(f.rule, f.severity, f.line, f.column) for f in hits] == [
        ("TG121", "error", 4, inner + 1)], hits
    assert "its two readings send different blocks" in hits[0].message
    assert says in hits[0].message, hits[0].message


@pytest.mark.parametrize("profile", ["iso-mill", "linuxcnc", "okuma-mill"])
def test_other_families_keep_refusing_a_comment_inside_a_comment(profile):
    """LinuxCNC refuses it ("Nested comment found"), as ISO 6983-1 does; Okuma stays as it
    was: TG121, no TG136, whatever the text after the first ')'."""
    block = "G00 X1. (VNMG 332(1))"
    text = f"{block}\nM2\n" if profile == "linuxcnc" else f"%\nO1000\nG21 G90\n{block}\nM30\n%\n"
    found_ = [(f.rule, f.severity) for f in check_text(text, load_profile(profile))
              if f.rule in ("TG121", "TG136")]
    assert found_ == [("TG121", "error")]


def test_rs274_refuses_the_nested_comment_the_fanuc_family_reads(tmp_path):
    """The LinuxCNC oracle for the linuxcnc profile's refusal of `(VNMG 332(1))`."""
    from .conftest import rs274_output

    out = rs274_output(tmp_path, "G21 G0 X1 (VNMG 332(1))\nM2\n")
    assert "Nested comment found" in out, out


@pytest.mark.parametrize("profile, noted", [
    ("fanuc-mill", True), ("haas-lathe", True), ("iso-mill", False),
])
def test_a_comment_left_open_says_whose_reading_it_is(profile, noted):
    """A `(` with no `)` before the end of the block stays TG120; on a Fanuc or a Haas the
    message says the refusal is ISO 6983-1's, since no source of theirs says what they do."""
    text = "%\nO1000\nG21 G00 X0 Z0 (OPEN\nM30\n%\n"
    hits = [f for f in check_text(text, load_profile(profile)) if f.rule == "TG120"]
    assert [(f.severity, f.line, f.column) for f in hits] == [("error", 3, 15)]
    assert hits[0].message.startswith("comment not closed: '(' without ')'")
    assert ("no Fanuc or Haas source at hand" in hits[0].message) == noted


@pytest.mark.parametrize("profile, says", [
    ("fanuc-mill", "',R' written apart from its number: read only written together, since no "
                   "Fanuc source"),
    ("haas-mill", "address R written apart from its number: a Haas takes"),
])
def test_a_corner_word_apart_from_its_number(profile, says):
    text = "%\nO1000\nG21 G90 G00 X0 Y0\nG01 X92. Y50. ,R 15. F100.\nM30\n%\n"
    hits = [f for f in check_text(text, load_profile(profile)) if f.rule == "TG100"]
    assert [(f.line, f.column) for f in hits] == [(4, 17)]
    assert hits[0].message.startswith(says), hits[0].message
    assert not errors(text.replace(",R 15.", ",R15."), profile)


def test_a_haas_program_number_may_be_written_with_a_lower_case_o():
    """"The letter O, or o is followed by a 5-digit number" (Haas Mill Operator's Manual, NGC,
    2017, 5.3.1): read, with the lower-case address said (TG102); a Fanuc, and any other
    lower-case address on a Haas, stay refused (TG101)."""
    program = "%\no40001 (LOWER O)\nG20 G90 G00 X0 Y0\nM30\n%\n"
    assert not errors(program, "haas-mill")
    assert ("TG102", "warning", 2) in found(program, "haas-mill")
    assert ("TG101", 2) in errors(program, "fanuc-mill")
    assert ("TG101", 3) in errors(program.replace("G20 G90", "g20 G90"), "haas-mill")


def test_convert_refuses_what_a_haas_refuses(tmp_path):
    path = tmp_path / "O40001.nc"
    path.write_text(APART)
    result = CliRunner().invoke(main, ["convert", str(path), "--from", "haas-mill",
                                       "--to", "fanuc-mill", "-o", str(tmp_path / "out.nc")])
    assert result.exit_code != 0
    assert f"{path}:4:10: address X written apart" in result.output, result.output


# -- found by review: a program after the first, a skippable return, a mismatched endsub --------


def test_a_main_program_after_the_first_in_a_file_still_needs_its_feed():
    """Each program of a file starts from the reset state, feed absent as in the first: the
    second program's feed move without F is TG401 as it is alone (said at its M30)."""
    second = "O0002\nG21 G90 G0 X0. Y0. Z0.\nG1 X10.\nM30\n"
    backup = "%\nO0001\nG21 G90 G0 X0. Y0. Z0.\nG1 X10. F100.\nM30\n%\n%\n" + second + "%\n"
    assert ("TG401", 10) in errors(backup, "haas-mill")
    assert ("TG401", 4) in errors("%\n" + second + "%\n", "haas-mill")
    # the same second program ending with M99 is a subprogram: its caller's feed
    sub_backup = backup[: backup.rindex("M30")] + "M99\n%\n"
    assert ("TG401", 10) not in errors(sub_backup, "haas-mill")


def test_a_return_the_block_skip_passes_over_keeps_the_main_program_s_findings():
    """`/M99` before `M30` (a bar feeder's loop): with block skip on the M30 ends a main
    program, which alarms on a feed move without F; the findings are not dropped."""
    text = "%\nO0001\nG21 G90 G0 X0. Z0.\nG1 X1.\n/M99\nM30\n%\n"
    assert ("TG401", 4) in errors(text, "fanuc-lathe")
    assert ("TG401", 4) not in errors(text.replace("/M99\nM30\n", "M99\n"), "fanuc-lathe")
    # the slash in the middle of the block skips the M99 the same way (Fanuc: from the slash
    # to the end of the block); before it, the M99 is no longer skipped
    mid = text.replace("/M99\n", "G0 X0. /M99\n")
    assert ("TG401", 4) in errors(mid, "fanuc-lathe")
    assert ("TG401", 4) not in errors(mid.replace("G0 X0. /M99", "M99 /G0 X0."), "fanuc-lathe")


def test_an_endsub_naming_another_subroutine_does_not_close_the_file_s_definition():
    """rs274 reads `o<j> sub` ... `o<k> endsub` as a definition never closed where it reads the
    file from its top, as a program: TG114, said at the definition left open. A subroutine file
    that a call runs returns at it (issue 32, audit 37 I, 2): a warning, TG138, no TG114."""
    assert ("TG114", 1) in errors("o<j> sub\nG1 X1 F100\no<k> endsub\no<j> call\nM2\n",
                                  "linuxcnc")
    sub_file = found("o<j> sub\nG1 X1 F100\no<k> endsub\n", "linuxcnc")
    assert [f for f in sub_file if f[1] != "info"] == [("TG138", "warning", 3)]
    assert not errors("o<j> sub\nG1 X1 F100\nO<J> endsub\n", "linuxcnc")
    # (review 38, finding 2) the file's end after it may carry a sequence number or other M
    # codes: M2 among them still ends it
    for end in ("M2", "M5 M2", "N5 M2", "M2.0", "M30"):
        file = found(f"o<j> sub\nG1 X1 F100\no<k> endsub\n{end}\n", "linuxcnc")
        assert [f for f in file if f[1] != "info"] == [("TG138", "warning", 3)], end
    assert ("TG114", 1) in errors("o<j> sub\nG1 X1 F100\no<k> endsub\nG0 X2\nM2\n",
                                  "linuxcnc")


def test_a_macro_b_parameter_is_refused_for_a_family_that_does_not_read_it():
    from formats.convert import ConvertOptions, convert_text
    from formats.errors import ConversionError

    src = "O0001\nG21 G90\n#1=5.\nG0 X#1 Y0. Z0.\nM30\n"
    fanuc = load_profile("fanuc-mill")
    for target in ("sinumerik-840d", "okuma-mill"):
        with pytest.raises(ConversionError) as err:
            convert_text(src, ConvertOptions(load_profile(target), fanuc))
        assert (err.value.code, err.value.line, err.value.column) == ("conversion-dialect", 3, 1)
        assert "parameter" in str(err.value)
    # a TNC takes no other family's program at all (its program frame): refused at its start
    with pytest.raises(ConversionError) as err:
        convert_text(src, ConvertOptions(load_profile("heidenhain-iso"), fanuc))
    assert (err.value.code, err.value.line, err.value.column) == ("conversion-dialect", 1, 1)
    # a control that reads # parameters takes the program as written
    assert convert_text(src, ConvertOptions(load_profile("haas-mill"), fanuc))[0] == src


# -- FANUC lathe: the one-block G71/G72 with D ---------------------------------------------------

ONE_BLOCK_G71 = """%
O0001
G21 G99 G00 X52. Z2.
G71 P10 Q20 U0.4 W0.1 D1500 F0.25
N10 G00 X20.
G01 Z-20.
N20 X50.
G70 P10 Q20
M30
%
"""


def test_a_one_block_g71_on_a_fanuc_lathe_warns_at_its_d_saying_no_source_reads_it():
    """`G71 P Q U W D F` is the Haas lathe's one-block form; the FANUC 0i-TF's standard format
    writes the depth of cut in a `G71 U R` block of its own, and no FANUC source at hand says
    whether (or under which parameter) a 0i or 30i reads the one-block form: the D stays a
    warning (TG134) and says so; on haas-lathe it is the cycle's word and nothing is said."""
    hits = [f for f in check_text(ONE_BLOCK_G71, load_profile("fanuc-lathe")) if f.rule == "TG134"]
    assert [(f.severity, f.line, f.column) for f in hits] == [("warning", 4, 23)]
    assert "in a G71/G72 block D is the depth of cut of the one-block form" in hits[0].message
    assert "is in no FANUC source at hand" in hits[0].message
    assert not errors(ONE_BLOCK_G71, "fanuc-lathe")
    assert not [f for f in check_text(ONE_BLOCK_G71, load_profile("haas-lathe"))
                if f.rule == "TG134"]
    # a D elsewhere on the FANUC lathe is the address the profile does not classify, no more
    elsewhere = ONE_BLOCK_G71.replace("G01 Z-20.", "G01 Z-20. D1")
    other = [f for f in check_text(elsewhere, load_profile("fanuc-lathe"))
             if f.rule == "TG134" and f.line == 6]
    assert len(other) == 1 and "G71" not in other[0].message


# -- the audit's smaller findings (issue 32, audit 12, 13, 16) and LinuxCNC's G10 L ----------


@pytest.mark.parametrize("profile", ["fanuc-mill", "fanuc-lathe"])
def test_a_fanuc_has_no_variable_34_to_99(profile):
    """Custom Macro B: local #1-#33, common #100-, system #1000-: #50 alarms (PS0115)."""
    text = "%\nO1000\nG21\n#33 = 1.\n#50 = 1.\n#100 = 2.\nM30\n%\n"
    assert errors(text, profile) == [("TG206", 5)]
    # a Haas's table was not read for them: not judged
    assert errors(text.replace("O1000", "O01000"), "haas-mill") == []


@pytest.mark.parametrize("profile", ["fanuc-mill", "fanuc-lathe"])
def test_a_fanuc_alarms_on_a_decimal_point_in_m_s_t(profile):
    """PS0007: M3.0, S1000.0 and T1.0 are refused; M[3.0] is rounded; a G65's arguments and a
    Haas are not judged so."""
    text = "%\nO1000\nG21\nM3.0 S1000\nM03 S1000.0\nT1.0\nM[3.0] S[1000.4]\nM30\n%\n"
    assert errors(text, profile) == [("TG202", 4), ("TG202", 5), ("TG202", 6)]
    assert errors("%\nO1000\nG21\nG65 P9732 S1. W2.\nM30\n%\n", profile) == []
    assert [r for r in found(text.replace("O1000", "O01000"), "haas-mill")
            if r[0] == "TG202"] == []


def test_a_conditional_assignment_keeps_the_position_known():
    """IF [..] THEN #106 = 1 jumps nowhere: the arc after it is still checked (TG410). An IF
    GOTO whose condition is not known is not followed (the position unknown at its target);
    one the known values make true is, from the position it left (review 51, F14)."""
    text = ("%\nO1000\nG21 G90 G17 G94\nG00 X0 Y0 Z5.\n#106 = 0\n"
            "IF [#106 EQ 0] THEN #106 = 1\nG02 X10. Y0 R2. F100.\nM30\n%\n")
    assert ("TG410", 7) in errors(text, "fanuc-mill")
    assert [r for r in found(text, "fanuc-mill") if r[0] == "TG140"] == []
    jump = text.replace("THEN #106 = 1", "GOTO 10").replace("G02", "N10 G02")
    assert ("TG410", 7) in errors(jump, "fanuc-mill")
    unknown = jump.replace("[#106 EQ 0]", "[#5 EQ 0]")
    assert ("TG410", 7) not in errors(unknown, "fanuc-mill")


def test_a_slash_after_a_macro_variable_is_said_doubtful():
    text = "%\nO1000\nG21\n#146 = 10.\nG90 G92 X#146/2\nG00 X[#146/2]\nM30\n%\n"
    doubtful = [r for r in found(text, "fanuc-mill") if r[0] == "TG128"]
    assert doubtful == [("TG128", "warning", 5)]


def test_a_sinumerik_def_after_the_program_section_began():
    late = "N10 G0 X0\nN20 DEF REAL ABC=1\nN30 G0 X=ABC\nN40 M30\n"
    assert errors(late, "sinumerik-840d") == [("TG109", 2)]
    early = "N10 DEF REAL ABC=1\nN20 G0 X0\nN30 G0 X=ABC\nN40 M30\n"
    assert errors(early, "sinumerik-840d") == []


@pytest.mark.parametrize("l_word, refused", [
    ("L50", True), ("L3", True), ("", True), ("L2", False), ("L20", False)])
def test_linuxcnc_g10_takes_its_own_l_values(l_word, refused):
    """interp_check.cc check_g_codes, as rs274 -g: G10 L0 L1 L2 L10 L11 L20, nothing else."""
    text = f"G21 G90 G17 G94\nG0 X0 Y0 Z5\nG10 {l_word} P1 X0\nM2\n".replace("  ", " ")
    assert (("TG412", 3) in errors(text, "linuxcnc")) == refused


@pytest.mark.parametrize("target, says", [
    ("linuxcnc", "LinuxCNC refuses it (rs274: \"Nested comment found\")"),
    ("iso-mill", "the target ends a comment at its first ')'"),
    ("okuma-mill", "the target ends a comment at its first ')'"),
    ("sinumerik-840d", "a SINUMERIK reads '( )' as brackets"),
])
def test_convert_refuses_a_fanuc_nested_comment_for_another_family(target, says):
    """`(VNMG 332(1))`, read once on a Fanuc or Haas (TG136), would be refused or read in part
    by a control that ends a comment at its first ')': convert says so at the inner '(' instead
    of writing it as it stands; to another Fanuc or Haas profile it is written unchanged."""
    from formats.convert import ConvertOptions, convert_text
    from formats.errors import ConversionError

    text = "%\nO1000\nG21 G90 G17\nG00 X1. (VNMG 332(1))\nM30\n%\n"
    options = ConvertOptions(target=load_profile(target), source=load_profile("fanuc-mill"))
    with pytest.raises(ConversionError) as err:
        convert_text(text, options)
    assert says in str(err.value), err.value
    assert "write the comment without the inner parentheses" in str(err.value)
    out, _ = convert_text(text, ConvertOptions(target=load_profile("haas-mill"),
                                               source=load_profile("fanuc-mill")))
    assert "G00 X1. (VNMG 332(1))\n" in out
    plain = text.replace("(VNMG 332(1))", "(VNMG 332-1)")
    assert "(VNMG 332-1)" in convert_text(plain, options)[0]


@pytest.mark.parametrize("block", ["G21 G0 X1 (H (I)", "G21 G0 X1 (A (B) C)", "G21 G0 X1 (A (B))"])
def test_linuxcnc_refuses_every_comment_inside_a_comment_as_rs274_does(tmp_path, block):
    """rs274 refuses a '(' inside a comment whether or not a second ')' follows it ("Nested
    comment found"); the linuxcnc profile did not refuse `(H (I)`, whose comment its first
    ')' closes. TG121 at the inner '(', and the oracle agrees."""
    from .conftest import rs274_output

    text = f"{block}\nM2\n"
    hits = [f for f in check_text(text, load_profile("linuxcnc")) if f.rule == "TG121"]
    assert [(f.severity, f.line, f.column) for f in hits] == [
        ("error", 1, block.index("(", block.index("(") + 1) + 1)], hits
    assert "Nested comment found" in rs274_output(tmp_path, text)


@pytest.mark.parametrize("target", ["linuxcnc", "iso-mill", "okuma-mill", "sinumerik-840d"])
def test_convert_takes_side_by_side_comments_after_a_semicolon(target):
    """The text after a Fanuc ';' is kept as one comment, `; (A) (B)`: its second '(' opens a
    comment of its own, inside none, so it is no nested comment and the block converts. A '('
    inside an open comment there is still refused, at that '('."""
    from formats.convert import ConvertOptions, convert_text
    from formats.errors import ConversionError

    frame = "%\nO1000\nG21 G90 G17\nG0 X0. Y0. Z50.\nG1 X5. F200.\n{}\nM30\n%\n"
    options = ConvertOptions(target=load_profile(target), source=load_profile("fanuc-mill"))
    out, _ = convert_text(frame.format("G1 Z-5. F50.; (A) (B)"), options)
    assert "Z-5." in out and "(B)" in out, out
    with pytest.raises(ConversionError) as err:
        convert_text(frame.format("G1 Z-5. F50.; (A (B) )"), options)
    assert err.value.column == 18, err.value
    assert "write the comment without the inner parentheses" in str(err.value)


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill", "fanuc-lathe"])
@pytest.mark.parametrize("line, inner, said", [
    # under the first reading the ';' ends the block: F50 (or the macro's arguments, which
    # would rotate A and B) become a block of their own
    ("G1 Z-5. (A (B) ;) F50.", 12, "a ';' that ends the block there"),
    ("G65 P9100 (A (B) ;) A1. B2.", 14, "a ';' that ends the block there"),
    # a mid-block '/' drops X20., L5 with the block-skip switch on
    ("G1 Z-5. F50. (A (B) /) X20.", 17, "a '/' that, with the block-skip switch on, skips"),
    ("M98 P100 (A (B) /) L5", 13, "a '/' that, with the block-skip switch on, skips"),
    # a ',' that joins the C after the stray ')' into a chamfer word
    ("G1 X10. F100. (A (B) ,)C1.", 18, "a ',' that joins the 'C' after it into a ',C'"),
])
def test_a_nested_comment_whose_first_reading_ends_skips_or_joins_is_an_error(
        profile, line, inner, said):
    """Review 11, findings 1, 2, 7: what the first reading (the comment ends at its first ')')
    leaves changes the block, so the readings send different blocks: TG121 at the inner '(',
    saying what each sends, and no TG136."""
    text = f"%\nO1000\nG21 G90 G17\nG0 X0. Y0. Z50.\nG1 X5. F2000.\n{line}\nM30\n%\n"
    found = [f for f in check_text(text, load_profile(profile))
             if f.rule in ("TG121", "TG136")]
    assert [(f.rule, f.severity, f.line, f.column) for f in found] == [
        ("TG121", "error", 6, inner)], found
    assert said in found[0].message
    assert "read nested, to the ')' that matches" in found[0].message


@pytest.mark.parametrize("line", ["G0 X1. (A (B) ...)", "G0 X1. (A (B) ,) Y2.",
                                  "G0 X1. (VNMG 332(1))"])
def test_a_nested_comment_that_leaves_only_marks_stays_a_warning(line):
    """Where nothing the first reading leaves can change what is sent or skipped, TG136."""
    text = f"%\nO1000\nG21 G90 G17\n{line}\nM30\n%\n"
    found = [(f.rule, f.severity) for f in check_text(text, load_profile("fanuc-mill"))
             if f.rule in ("TG121", "TG136")]
    assert found == [("TG136", "warning")]


@pytest.mark.parametrize("block", [
    "G10 G00 X90.", "G10 L2 P1 X-1. Y-1. G00 X90.", "G10 L2 P2 X0 M98 P2000",
    "G10 G91 G28 Z0 X90.", "G10 L2 P1 X#101"])
def test_a_g10_block_with_anything_else_ends_the_haas_saved_offsets(block: str) -> None:
    """Review 13, 4: a block whose first word was G10 was skipped whole, a G00 X90., an M98
    or a G28 in it unread. Only a G10 with its L P R Q and axis values is a saved offset; this
    one ends the section, is refused at its line (TG205) and read."""
    text = ("%\nO01000\nG20 G90 G54 G00 X0 Y0\nM30\nO999999\nG10 L2 P1 X-1. Y-1.\n"
            f"N5 G10 G90 L2 P2 X-1. Y2. Z0\n{block}\n%\n")
    said = check_text(text, load_profile("haas-mill"))
    assert [f.line for f in said if f.rule == "TG205"] == [5, 8]
    ended = [f for f in said if f.rule == "TG205" and f.line == 8][0]
    assert "a block that sets no offset after O999999" in ended.message
    # the saved offsets themselves (with N, G90) stay unread
    assert not [f for f in said if f.line in (6, 7) and f.severity != "info"]


def test_the_haas_saved_offsets_after_m97_local_subroutines() -> None:
    """Review 13, 4: a main program, its M97 local subroutine after the M30 (ended by M99),
    then the saved offsets: the main program has ended, so O999999 heads them (no false TG114
    "no M02 or M30"), and a subprogram file ended by M99 alone still heads none."""
    text = ("%\nO01000\nG20 G90 G54 G00 X0 Y0\nM97 P100\nM30\nN100 G00 X1.\nM99\nO999999\n"
            "G10 L2 P1 X-1. Y-1.\n%\n")
    said = [f for f in check_text(text, load_profile("haas-mill")) if f.severity != "info"]
    assert [(f.rule, f.line) for f in said] == [("TG205", 8)]
    assert "heads the offsets a Haas saves" in said[0].message


# -- Fanuc and Haas: a macro function's argument in parentheses (issue 32, held3 O9998) -------


ABS_PROGRAM = """%
O0001
#1 = 5.
#2 = ABS{open}#1 - 7.{close}
G21 G00 X#2 Z0
M30
%
"""


@pytest.mark.parametrize("profile", ["fanuc-mill", "fanuc-lathe", "haas-mill", "haas-lathe"])
def test_a_macro_function_takes_its_argument_in_brackets(profile):
    """Brackets enclose an expression and parentheses a comment (FANUC Series 16/18-C lathe
    Operator's Manual, 16.3, p. 287; Haas 96-8000, "Expressions"): `ABS(#1 - 7.)` leaves ABS
    with no argument, the program's error, named so; `ABS[#1 - 7.]` reads."""
    assert not errors(ABS_PROGRAM.format(open="[", close="]"), profile)
    text = ABS_PROGRAM.format(open="(", close=")")
    hits = [f for f in check_text(text, load_profile(profile)) if f.severity == "error"]
    assert [(f.rule, f.line, f.column) for f in hits] == [("TG100", 4, 6)]
    assert "function ABS takes its argument in brackets" in hits[0].message
    # a '(' grouping an operand: the same reading
    grouped = "%\nO0001\n#1 = 5.\n#2 = 2. * (#1 - 7.)\nM30\n%\n"
    hits = [f for f in check_text(grouped, load_profile(profile)) if f.severity == "error"]
    assert [(f.rule, f.line, f.column) for f in hits] == [("TG100", 4, 11)]
    assert "brackets group an expression" in hits[0].message


# -- Fanuc: a sequence number past N99999 (issue 32 item 3, held11 SabirHusnain) --------------


@pytest.mark.parametrize("profile, rule, severity", [
    ("fanuc-mill", "TG205", "error"),     # N1 to N99999 (B-63684EN), PS0003 past it
    ("haas-mill", "TG208", "warning"),    # no Haas alarm documented
])
def test_a_sequence_number_past_five_digits_follows_the_control_s_documents(
        profile, rule, severity):
    fine = "%\nO0001\nN99999 G21 G90 G00 X0 Y0\nM30\n%\n"
    assert not [f for f in check_text(fine, load_profile(profile))
                if f.rule in ("TG205", "TG208")]
    long = fine.replace("N99999", "N100000")
    hits = [f for f in check_text(long, load_profile(profile)) if f.rule in ("TG205", "TG208")]
    assert [(f.rule, f.severity, f.line, f.column) for f in hits] == [(rule, severity, 3, 1)]
    if profile.startswith("fanuc"):
        assert "1 to 99999" in hits[0].message and "PS0003" in hits[0].message
    else:
        assert "B-63684EN" not in hits[0].message


# a FANUC profile narrowed to four-digit sequence numbers (a copied profile's own format)
N04 = ('name = "fanuc-n04"\nbase = "fanuc-mill"\ndetailed = "%:/DS O04 N04 G031 X+053 Y+053 '
       'Z+053 P08 Q+053 R+053 A+053 B+053 I+053 J+053 K+053 F052 S05 T08 D03 M03 H03 L04*"\n')


@pytest.mark.parametrize("number, digits, manual", [
    ("N12345", 5, False),   # within the manual's 1 to 99999: the profile's own N04 refuses it
    ("N123456", 6, True),   # past both: the manual's range and PS0003 said too
])
def test_a_sequence_number_past_a_narrower_n_format_is_told_its_own_format(number, digits,
                                                                            manual):
    """N12345 on a profile whose N format is N04 is past that format, not past FANUC's
    N99999: the message gives the format and leaves out the manual's five digits, which
    would contradict it."""
    text = f"%\nO0001\n{number} G21 G90 G00 X0 Y0\nM30\n%\n"
    hits = [f for f in check_text(text, profile_from_text(N04)) if f.rule == "TG205"]
    assert [(f.rule, f.severity, f.line, f.column) for f in hits] == [("TG205", "error", 3, 1)]
    assert hits[0].message.startswith(
        f"{number}: {digits} digits before the decimal sign; the format N04 holds 4")
    assert ("1 to 99999" in hits[0].message) is manual
    assert ("PS0003" in hits[0].message) is manual


# -- Fanuc and Haas: IF [..] THEN over several blocks (issue 32, held3 O9100), not read ---------


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill"])
def test_the_block_form_of_if_then_is_refused_at_else_and_endif(profile):
    """No Fanuc or Haas source at hand gives IF [..] THEN with its statements on the blocks
    after it, closed by ELSE and ENDIF: refused at those words, saying so; the one-block form
    IF [..] THEN statement reads."""
    one = "%\nO0001\n#1 = 2.\nIF [#1 GT 0] THEN #2 = 1.\nM30\n%\n"
    assert not errors(one, profile)
    block = ("%\nO0001\n#1 = 2.\nIF [#1 GT 0] AND [#1 LT 5] THEN\n#2 = 1.\nELSE\n#2 = 0.\n"
             "ENDIF\nM30\n%\n")
    hits = [f for f in check_text(block, load_profile(profile)) if f.severity == "error"]
    assert [(f.rule, f.line, f.column) for f in hits] == [("TG100", 6, 1), ("TG100", 8, 1)]
    assert hits[0].message.startswith("'ELSE' is not read: an IF [..] THEN over several blocks")
    assert hits[1].message.startswith("'ENDIF' is not read")


@pytest.mark.parametrize("profile", ["fanuc-lathe", "haas-mill"])
def test_go_before_an_address_is_the_letter_o_for_g0_s_zero(profile):
    """`GO Y0.` (held3's hand-typed lathe program, 1003.NC): no block number follows, so it
    is no GOTO, abbreviated or not; the letter O stands for G0's zero, the program's error as
    `GOO` and `TO303` are. `GO10` is still refused as an abbreviation of GOTO."""
    text = "%\nO0001\nG21 G00 X20. Z2.\nGO Z0.\nM30\n%\n"
    hits = [f for f in check_text(text, load_profile(profile)) if f.severity == "error"]
    assert [(f.rule, f.line, f.column) for f in hits] == [("TG100", 4, 1)]
    assert hits[0].message.startswith("'GO' is neither G0 nor GOTO")
    jump = "%\nO0001\nGO10\nN10 G21 G00 X20. Z2.\nM30\n%\n"
    hits = [f for f in check_text(jump, load_profile(profile)) if f.severity == "error"]
    assert [(f.line, f.message.split(":")[0]) for f in hits] == [(3, "'GO' is not read as GOTO")]
    assert not errors(text.replace("GO Z0.", "G0 Z0."), profile)


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill"])
@pytest.mark.parametrize("block, column, message", [
    # GOTO written with a blank inside: a block number does follow, after TO
    ("GO TO 10", 1, "'GO TO' is not read as GOTO: the macro words are read written in full, "
                    "with no blank inside"),
    ("N5 GO TO10", 4, "'GO TO' is not read as GOTO"),
    # GO, a number, then an address word: the letter O for G01's zero as much as GOTO 1
    ("GO1 X1.", 1, "'GO1' is neither G01 nor GOTO 1: G takes digits, and the letter O stands "
                   "where a zero belongs (G01, the address X after it as in a motion block), "
                   "or GOTO is abbreviated"),
    ("N7 GO2 X5. Y1. R3.", 4, "'GO2' is neither G02 nor GOTO 2"),
])
def test_go_is_told_what_is_true_of_its_block(profile, block, column, message):
    """Each GO form is refused, as before, with a message that fits what follows it: `GO TO 10`
    has its block number (after TO), so it is not told it has none; `GO1 X1.` is not only an
    abbreviated GOTO."""
    text = f"%\nO0001\nG21 G90 G00 X0 Y0\n{block}\nN10 G00 X1.\nM30\n%\n"
    hits = [f for f in check_text(text, load_profile(profile)) if f.severity == "error"]
    assert [(f.rule, f.line, f.column) for f in hits] == [("TG100", 4, column)]
    assert hits[0].message.startswith(message), hits[0].message
    assert "no block number" not in hits[0].message


# -- Haas: a parameter variable read with a decimal part (issue 32, severity by evidence) -----

HAAS_ELEMENT = ("%\nO09023 (PROBE)\nG20 G00 X0\nG00 Z1.\n#10100=#30003.078\n"
                "IF [ #30057.21 ] GOTO22\nG01 Z[#30003.036 - 12.7] F10.\nN30 G01 X1.\nG01 Z2.\n"
                "N22 #101=#30003.078\nM30\n%\n")


@pytest.mark.parametrize("profile", ["haas-mill", "haas-lathe"])
def test_a_haas_parameter_variable_with_a_decimal_part_is_read_as_an_unknown_value(profile):
    """Renishaw's Inspection Plus macros for the NGC read `#30003.078`, `#30057.21`: the NGC
    manual gives #30000-#39999 as the parameters, and no Haas source says what the decimals
    select, so the value is unknown to tapegate: a warning once per variable (TG212, at its
    '#'), the program read on, and what depends on it unknown (TG141), as for an unknown
    system variable."""
    said = [f for f in check_text(HAAS_ELEMENT, load_profile(profile))
            if f.rule not in ("TG130", "TG133", "TG703")]
    assert [f for f in said if f.severity == "error"] == []
    elements = [(f.severity, f.line, f.column, f.message.split(":")[0]) for f in said
                if f.rule == "TG212"]
    assert elements == [("warning", 5, 8, "#30003.078"), ("warning", 6, 6, "#30057.21"),
                        ("warning", 7, 7, "#30003.036")]
    assert "6.14.7, gives #30000-#39999 as the parameters" in said[0].message or any(
        "6.14.7, gives #30000-#39999 as the parameters" in f.message for f in said)
    # the Z the element sets is unknown, said as any unknown value is
    assert any(f.rule == "TG141" and f.line == 7 for f in said)
    # a decimal part outside the parameters is not named a parameter element (review 33)
    other = [f for f in check_text("%\nO1\n#1=#101.5\nM30\n%\n", load_profile(profile))
             if f.rule == "TG212"]
    assert len(other) == 1 and other[0].severity == "warning"
    assert other[0].message.startswith("#101.5: a variable with a decimal part outside the "
                                       "parameters"), other[0].message


def test_an_unknown_parameter_element_fires_no_geometry_rule():
    """A position set through the unknown value is no position: a travel limit that a plain
    Z-100. breaks is not judged on Z[#30003.036 - 100.], nor on the blocks after it until a
    plain value sets Z again."""
    plain = "%\nO1\nG20 G90 G54 G00 X0 Y0 Z1.\nG01 Z-100. F10.\nM30\n%\n"
    assert ("TG601", 4) in errors(plain, "haas-mill")
    unknown = plain.replace("G01 Z-100. F10.", "G01 Z[#30003.036 - 100.] F10.\nG01 X1.")
    assert [e for e in errors(unknown, "haas-mill")] == []


def test_setting_a_haas_parameter_variable_with_a_decimal_part_stays_refused():
    """What the assignment would change on the machine is not known: still TG100, saying so."""
    said = [f for f in check_text("%\nO1\nG20 G00 X0\n#30003.078 = 5\nM30\n%\n",
                                  load_profile("haas-mill")) if f.severity == "error"]
    assert [(f.rule, f.line, f.column) for f in said] == [("TG100", 4, 1)]
    assert "a Haas NGC parameter element such as #30003.078 is read as a value tapegate " \
        "does not know, but set here" in said[0].message


def test_a_fanuc_still_refuses_a_variable_with_a_decimal_part():
    """Custom Macro B numbers its variables with whole numbers; the Haas reading is the NGC's."""
    said = [f for f in check_text(HAAS_ELEMENT.replace("G20", "G21"), load_profile("fanuc-mill"))
            if f.severity == "error"]
    assert [(f.rule, f.line, f.column) for f in said][:1] == [("TG100", 5, 8)]
    assert "has a decimal part" in said[0].message


def test_a_haas_parameter_element_checks_sends_and_refuses_what_it_cannot_carry(tmp_path):
    """check exits 0 (warnings only); a restart past the unknown Z is refused (its position is
    not known); convert to another unit system refuses the expression it cannot scale, as for
    any variable; convert within inch carries the line as written."""
    from dnc import workflow
    from postproc.restart import RestartRefused

    path = tmp_path / "probe.nc"
    path.write_text(HAAS_ELEMENT)
    run = CliRunner().invoke(main, ["check", "-p", "haas-mill", str(path)])
    assert run.exit_code == 0, run.output
    assert f"{path}:5:8: warning TG212 #30003.078" in run.output
    haas = load_profile("haas-mill")
    straight = tmp_path / "straight.nc"  # no IF: the unknown Z alone stops the restart
    straight.write_text(HAAS_ELEMENT.replace("IF [ #30057.21 ] GOTO22\n", ""))
    with pytest.raises(RestartRefused) as refused:
        workflow.prepare(str(straight), haas, haas.serial, name="probe.nc", restart_at="N30")
    assert refused.value.code == "restart-refused" and refused.value.line == 7
    assert "the position of Z is not known" in refused.value.message, refused.value.message
    out = tmp_path / "out.nc"
    metric = CliRunner().invoke(main, ["convert", "--from", "haas-mill", "--to", "haas-mill",
                                       "--units", "metric", "-o", str(out), str(path)])
    assert metric.exit_code != 0 and not out.exists()
    same = CliRunner().invoke(main, ["convert", "--from", "haas-mill", "--to", "haas-mill",
                                     "-o", str(out), str(path)])
    assert same.exit_code == 0, same.output
    assert "#10100=#30003.078" in out.read_text()


# -- Fanuc: a decimal point in S beside an M code the table lacks (issue 32) ------------------

DOOSAN_PROBE = ("%\nO0030 (PROBE)\nG21 G90 G54 G00 X0 Y0\nG43 H1 Z50. S3000 M03\n"
                "M165P9811Z0S2.\nG00 X10.\nM30\n%\n")


def test_a_point_in_s_beside_an_m_code_parameters_may_make_a_macro_call_is_a_warning(tmp_path):
    """FANUC parameters 6080-6089 make an M code a custom macro call, whose arguments are real
    numbers; where M165 is the builder's code instead, S2. is PS0007. An alarm moves nothing,
    and which it is the machine's parameters say: TG307 at S2., the block read on."""
    said = [f for f in check_text(DOOSAN_PROBE, load_profile("fanuc-mill"))
            if f.rule not in ("TG130", "TG133", "TG703")]
    assert [f for f in said if f.severity == "error"] == []
    hits = [(f.rule, f.severity, f.line, f.column) for f in said if f.line == 5]
    assert hits == [("TG307", "warning", 5, 12), ("TG307", "warning", 5, 1)]
    s = next(f for f in said if f.line == 5 and f.column == 12)
    assert s.message.startswith("S2.: a decimal point in a spindle speed, alarm PS0007 where "
                                "M165 is a machine builder's M code; parameters 6080-6089 may "
                                "make M165 a custom macro call (O9020-O9029")
    # an M code of the table keeps the alarm (TG202, an error), as does a lathe's
    assert ("TG202", 5) in errors(DOOSAN_PROBE.replace("M165P9811Z0S2.", "M05 S2."),
                                  "fanuc-mill")
    assert ("TG202", 5) in errors(DOOSAN_PROBE.replace("M165P9811Z0S2.", "M165.0 S2."),
                                  "fanuc-mill")
    run = CliRunner().invoke(main, ["check", "-p", "fanuc-mill", "-"], input=DOOSAN_PROBE)
    assert run.exit_code == 0, run.output


def test_the_m165_block_sends_and_no_restart_after_it_guesses_the_speed(tmp_path):
    """send sends it without --force; a restart after it is refused where the speed it would
    restore is the unknown S (an argument, or the alarm's)."""
    from dnc import workflow
    from postproc.restart import RestartRefused

    path = tmp_path / "O0030.nc"
    path.write_text(DOOSAN_PROBE.replace("G00 X10.", "N60 G00 X10."))
    sent = CliRunner().invoke(main, ["send", "--port", "loop://", "--flow", "none", "-p",
                                     "fanuc-mill", "-y", str(path)])
    assert sent.exit_code == 0, sent.output
    fanuc = load_profile("fanuc-mill")
    with pytest.raises(RestartRefused) as refused:
        workflow.prepare(str(path), fanuc, fanuc.serial, name="O0030.nc", restart_at="N60")
    assert refused.value.line == 6
    assert "the spindle speed in force is not known: S2. on line 5, beside M165, an M code the " \
        "profile's list lacks" in refused.value.message, refused.value.message
    # the same with D and no Z (O0050's form): the speed still stops the restart
    path.write_text(DOOSAN_PROBE.replace("G00 X10.", "N60 G00 X10.").replace(
        "M165P9811Z0S2.", "M165P9814D.453S2."))
    with pytest.raises(RestartRefused) as refused:
        workflow.prepare(str(path), fanuc, fanuc.serial, name="O0030.nc", restart_at="N60")
    assert "S2. on line 5" in refused.value.message, refused.value.message


# -- LinuxCNC: an end of program written by a parameter or expression, or block-deleted -------

# (review 38, finding 8) the end's line, the fourth: each form rs274 reads as M2 (read_m,
# read_integer_value), and the block-deleted one, which ends only with the switch off
LINUXCNC_END = "#<two> = 2\nG21 G90\nG0 X0 Y0 Z1\n{end}\nG0 X1\nM2\n"


@pytest.mark.parametrize("end", ["M2", "M#<two>", "M[2]", "M[1+1]", "M[#<two>*15]", "/M2"])
def test_linuxcnc_ends_where_rs274_ends(end, tmp_path):
    """`tapegate check` of a program whose fourth line ends it, beside what rs274 does with
    it (where rs274 is installed): an M2 written by a parameter or an expression is the end
    (TG117 for the lines after it, as for `M2`; it was TG116, or nothing); a block-deleted
    `/M2` is passed over with the block delete switch on (`rs274 -b`), so the lines after it
    run then: no TG116 or TG117 for them."""
    import re
    import shutil
    import subprocess

    from .conftest import rs274_env

    path = tmp_path / "end.ngc"
    path.write_text(LINUXCNC_END.format(end=end))
    _, lines = jsonl("-p", "linuxcnc", str(path))
    said = [(f["rule"], f["line"]) for f in lines if f["rule"] in ("TG116", "TG117", "TG114")]
    deleted = end.startswith("/")
    assert said == ([] if deleted else [("TG117", 5)]), lines
    if shutil.which("rs274") is None:
        pytest.skip("LinuxCNC's rs274 is not installed")

    def traverses(*flags: str) -> list[float]:
        run = subprocess.run(["rs274", *flags, "-g", str(path)], capture_output=True, text=True,
                             timeout=30, input="", env=rs274_env(), cwd=tmp_path)
        out = run.stdout + run.stderr
        assert "PROGRAM_END()" in out, out
        return [float(m[1]) for m in re.finditer(r"STRAIGHT_TRAVERSE\(([-\d.]+),", out)]

    # the G0 X1 after the end never runs; with the switch on, a deleted end's does
    assert traverses() == [0.0]
    assert traverses("-b") == ([0.0, 1.0] if deleted else [0.0])


# (issue 32, lcnc48, 3) the other readings follow the checker's end through the one rule
# (dialect::linuxcnc_m_number in ReadingEnd): after an end of an expression, a line that is no
# program is not read; after one of a parameter, whose value they do not know, they read on
AFTER_END = "G21 G90\n#<two> = 2\nG0 X1\n{end}\nthis is no program\n"


@pytest.mark.parametrize("end", ["M[1+1]", "M[30]", "M 2.00005"])
def test_parse_diff_and_convert_read_no_line_after_an_end_of_an_expression(end, tmp_path):
    path = tmp_path / "end.ngc"
    path.write_text(AFTER_END.format(end=end))
    runner = CliRunner()
    parsed = runner.invoke(main, ["parse", str(path), "-p", "linuxcnc"])
    assert parsed.exit_code == 0, parsed.output
    differ = runner.invoke(main, ["diff", str(path), str(path), "-p", "linuxcnc"])
    assert differ.exit_code == 0 and "same program" in differ.output, differ.output
    out = tmp_path / "out.ngc"
    converted = runner.invoke(main, ["convert", str(path), "--from", "linuxcnc", "--to",
                                     "linuxcnc", "-o", str(out)])
    assert converted.exit_code == 0, converted.output
    assert out.read_text().endswith("this is no program\n")


def test_parse_reads_on_after_an_m_word_of_a_parameter_and_says_so(tmp_path):
    path = tmp_path / "end.ngc"
    path.write_text(AFTER_END.format(end="M#<two>"))
    parsed = CliRunner().invoke(main, ["parse", str(path), "-p", "linuxcnc"])
    assert parsed.exit_code != 0
    assert "the M word on line 4 reads a value not known here" in parsed.output, parsed.output


# -- LinuxCNC: a subroutine's body reading a local named parameter it never assigns -----------

# (review 38, finding 9) rs274 keeps local named parameters per call level; each program's
# line of the read, or None where rs274 runs it
LOCALS = {
    "the caller's local": ("#<zz> = 1\no<s> sub\nG1 X#<zz> F100\no<s> endsub\no<s> call\n", 5),
    "never assigned": ("o<s> sub\nG1 X#<zz> F100\no<s> endsub\no<s> call\n", 4),
    "in the body's condition": ("#<zz> = 1\no<s> sub\no1 if [#<zz> GT 0]\nG1 X1 F100\n"
                                "o1 endif\no<s> endsub\no<s> call\n", 5),
    "a global": ("#<_zz> = 1\no<s> sub\nG1 X#<_zz> F100\no<s> endsub\no<s> call\n", None),
    "assigned in the body": ("o<s> sub\n#<zz> = 3\nG1 X#<zz> F100\no<s> endsub\no<s> call\n",
                             None),
    "not called": ("#<zz> = 1\no<s> sub\nG1 X#<zz> F100\no<s> endsub\n", None),
    "inside a branch not run": ("o<s> sub\no1 if [#1 GT 0]\nG1 X#<zz> F100\no1 endif\n"
                                "o<s> endsub\no<s> call [0]\n", None),
    # (review 39, finding 6) rs274 creates an assignment's target when it reads it, before
    # the value: its own value's read finds it (0), as a later setting's of the line does
    "its own assignment's value": ("o<s> sub\n#<zz> = [#<zz> + 1]\nG1 X#<zz> F100\n"
                                   "o<s> endsub\no<s> call\n", None),
    "its own assignment, alone": ("o<s> sub\n#<zz> = #<zz>\nG1 X#<zz> F100\n"
                                  "o<s> endsub\no<s> call\n", None),
    "a later setting of the line": ("o<s> sub\n#<zz> = 1 #<yy> = #<zz>\nG1 X#<yy> F100\n"
                                    "o<s> endsub\no<s> call\n", None),
    "another name's value": ("o<s> sub\n#<yy> = #<zz>\nG1 X#<yy> F100\n"
                             "o<s> endsub\no<s> call\n", 4),
    "an earlier setting of the line": ("o<s> sub\n#<yy> = #<zz> #<zz> = 1\nG1 X#<yy> F100\n"
                                       "o<s> endsub\no<s> call\n", 4),
}


@pytest.mark.parametrize("case", LOCALS)
def test_a_linuxcnc_sub_body_reads_only_its_own_locals(case, tmp_path):
    """`tapegate check` says TG412 ("Named parameter #<zz> not defined") at the body's first
    read of a local it does not assign where the file calls the sub, and nothing where rs274
    runs the program: beside rs274 -g where it is installed."""
    import shutil
    import subprocess

    from .conftest import rs274_env

    body, line = LOCALS[case]
    path = tmp_path / "locals.ngc"
    path.write_text("G21 G90\nG0 X0 Y0 Z1\n" + body + "M2\n")
    _, lines = jsonl("-p", "linuxcnc", str(path))
    refused = [(f["line"], f["message"]) for f in lines if f["rule"] == "TG412"]
    assert [at for at, _ in refused] == ([] if line is None else [line]), lines
    if refused:
        assert "#<zz> not defined (rs274ngc) when o<s> is called" in refused[0][1]
    if shutil.which("rs274") is None:
        pytest.skip("LinuxCNC's rs274 is not installed")
    run = subprocess.run(["rs274", "-g", str(path)], capture_output=True, text=True,
                         timeout=30, input="", env=rs274_env(), cwd=tmp_path)
    out = run.stdout + run.stderr
    assert ("Named parameter #<zz> not defined" in out) == (line is not None), out
    assert ("PROGRAM_END()" in out) == (line is None), out
