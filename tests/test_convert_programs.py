"""Files of several programs, read by every reader as the checker reads them (issue 32).

A Fanuc memory backup or ALL-PROG punch-out holds many programs: `%`, folder markers
(`&F=/USER/PATH1/`, 30i), then each program from its O number to its M30 or M99, and `%`.
Each program is read, checked, converted, compared and walked as its own program, from its own
start state (the control's reset state in its start units, no position known); the programs
here are written from the Fanuc manuals' forms (program numbers, M98/M99, G20/G21, G68).
"""

from __future__ import annotations

import re

import pytest
from click.testing import CliRunner

from formats import _core
from formats.convert import (
    Converter,
    ConvertOptions,
    analyse_parameters,
    convert_file,
    convert_text,
)
from formats.diff import DiffOptions, diff_files
from formats.errors import ConversionError
from formats.machine import machine
from formats.parser import parse_text
from formats.profile import load_profile
from postproc.check import Checker
from postproc.restart import RestartRefused, plan_restart_text
from tapegate.cli import main

from .conftest import CORPUS

FANUC = load_profile("fanuc-mill")
HAAS = load_profile("haas-mill")

# A memory backup: folders, a main program in inch, a macro in metric ending with M99 (its own
# units selected), a program of its own that selects no units, and the closing %.
BACKUP = (
    "%\n"
    "&F=/USER/PATH1/\n"
    "O0001(MAIN)\n"
    "G20 G90 G54 G17\n"
    "G0 X1. Y2.\n"
    "G1 Z-0.1 F10.\n"
    "M30\n"
    "&F=/USER/PATH2/\n"
    "O9010(PROBE MACRO)\n"
    "G21 G91\n"
    "G1 X25.4 F100.\n"
    "M99\n"
    "O0003(FACE)\n"
    "G90 G0 X10. Y10.\n"
    "G1 X50. F500.\n"
    "M30\n"
    "%\n"
)


def programs(text: str) -> list[str]:
    """The text cut before each O number or folder marker that follows an M30 or M99: the
    programs of the file, each with what surrounds it (the markers, `%`)."""
    pieces, start, ended = [], 0, False
    at = 0
    for line in text.splitlines(keepends=True):
        if ended and re.match(r"(O\d|&F=)", line):
            pieces.append(text[start:at])
            start, ended = at, False
        if re.search(r"M(30|99)\b", line):
            ended = True
        at += len(line)
    pieces.append(text[start:])
    return pieces


@pytest.mark.parametrize("options", [
    {"decimal": "implicit"}, {"decimal": "explicit"}, {"target": HAAS}])
def test_each_program_of_a_backup_converts_as_a_file_of_its_own(options):
    """The whole file converts to what its programs convert to one by one, byte for byte: the
    folder markers, `%` and comments are kept, and no program reads another's state."""
    target = options.pop("target", FANUC)
    opts = ConvertOptions(target, FANUC, **options)
    whole, _ = convert_text(BACKUP, opts)
    one_by_one = "".join(convert_text(p, opts)[0] for p in programs(BACKUP))
    assert whole == one_by_one
    assert [line for line in whole.splitlines() if line.startswith(("%", "&F=", "O"))] == [
        line for line in BACKUP.splitlines() if line.startswith(("%", "&F=", "O"))]


def test_the_third_program_is_read_in_its_own_start_units(tmp_path):
    """Converted to inch: O0003, which selects no units, is metric (the control's start units,
    as a file of its own), not the inch O0001 left in force; O9010's own G21 converts; and the
    result verifies, read back the same way."""
    path = tmp_path / "backup.nc"
    path.write_text(BACKUP)
    out = tmp_path / "out.nc"
    stats = convert_file(str(path), str(out), ConvertOptions(FANUC, FANUC, units="inch"),
                         verify=True)
    assert stats.verified
    lines = out.read_text().splitlines()
    assert lines[4] == "G0 X1. Y2."  # O0001, inch already
    assert lines[9:11] == ["G20 G91", "G1 X1. F3.937"]  # O9010, its G21 converted
    assert lines[13] == "G20 G90 G0 X0.3937 Y0.3937"  # O0003: G20 inserted, read in mm
    assert ("inserted G20: the program beginning on line 13 did not select its units before "
            "line 14; it was read in metric, the source control's start units, as a program "
            "of its own") in stats.notes


def test_a_program_called_in_other_units_than_its_own_start_is_refused():
    """Under a change of units, a program of its own (an O number after M30) that moves before
    selecting its units, after a program that leaves other units than its start units in
    force, has two readings: called by M98 from the program before, in those; run on its own,
    in its start units. Refused at its first move, with its line and column."""
    src = "O1\nG20\nG0 X1.\nM98 P2\nM30\nO2\nG90 G0 X1.\nM99\n"
    with pytest.raises(ConversionError) as info:
        convert_text(src, ConvertOptions(FANUC, FANUC, units="metric"))
    assert (info.value.code, info.value.line, info.value.column) == ("conversion-units", 7, 8)
    assert "the units the program before it in the file leaves in force" in info.value.message
    assert "M98" not in info.value.message  # (it names no call that may not exist)
    assert "in inch" in info.value.message and "in metric" in info.value.message
    # where the two agree (O1 in metric) it converts, and without a change of units too
    assert convert_text(src.replace("G20", "G21"), ConvertOptions(
        FANUC, FANUC, units="inch"))[0].splitlines()[6] == "G20 G90 G0 X0.0394"
    assert convert_text(src, ConvertOptions(FANUC, FANUC))[0] == src


def test_verify_and_diff_read_each_program_from_no_position(tmp_path):
    """O0002 moves incrementally from a position it does not know: the diff reader, as the
    checker, does not carry O0001's end point into it (verify failed: 'position X 26.4 mm ->
    50.8 mm', a position read across two programs in two units)."""
    src = "%\nO0001\nG20 G90\nG0 X1.\nM30\nO0002\nG21 G91\nG0 X25.4\nM99\n%\n"
    path = tmp_path / "p.nc"
    path.write_text(src)
    for units in ("metric", "inch"):
        stats = convert_file(str(path), None, ConvertOptions(FANUC, FANUC, units=units),
                             verify=True)
        assert stats.verified
    assert list(diff_files(str(path), str(path), FANUC, FANUC, DiffOptions(motion=True))) == []


def test_a_restart_in_a_later_program_is_not_refused_for_the_one_before():
    """O1 leaves G68 (a rotation the preamble cannot restore) in force and returns; a restart
    in O2 was refused for it. O2 is walked from its own start, as the checker reads it."""
    src = ("%\nO1\nG21 G90 G54\nG0 X0 Y0\nG68 X0 Y0 R45.\nG1 X10. F100.\nM99\n"
           "O2\nG21 G90 G54 G17\nT1 M6\nG43 H1 Z50.\nS1000 M3\nG0 X5. Y5.\nG1 Z-1. F100.\n"
           "X20.\nM30\n%\n")
    plan = plan_restart_text([src], FANUC, 15, "p.nc")
    assert plan.preamble[0].startswith("G21 G17 G90")
    assert "G01 Z-1. F100." in plan.preamble
    # within O1 it is still refused: O1 returns by M99 (a body runs in its caller's state),
    # whatever its G68
    with pytest.raises(RestartRefused, match="O1 returns to a caller by 'M99'") as info:
        plan_restart_text([src], FANUC, 6, "p.nc")
    assert (info.value.code, info.value.line) == ("restart-refused", 6)


def test_the_checker_reads_each_program_from_its_reset_state():
    """The reading the others follow: no TG116 words after the end, O0003's G90 X10. from no
    known position (no geometry measured from O9010's incremental end)."""
    found = list(Checker(FANUC).run(iter(parse_text(BACKUP, FANUC.dialect))))
    assert not [f for f in found
                if f.rule in ("TG106", "TG116", "TG113") or f.severity == "error"], [
        (f.rule, f.line, f.message) for f in found if f.severity == "error"]


# -- codes under an implicit decimal sign --------------------------------------------------


def test_whole_letters_stay_whole_under_an_implicit_decimal_sign():
    """A Fanuc reads a word without a decimal point in least increments, but for its whole
    letters (`numbers.whole`: F G P L): G21 is code 21 and F100 is 100 whatever decimal style
    the program is written in. So an implicit-decimal conversion for fanuc-mill writes X in
    increments and its codes and feed as the control reads them: G20 (not G200, code 200), G1
    (not G10, programmable data input), F3.937 with its point (not F3937, a thousand times the
    feed). These were written in tenths by the G format G031 until this was found; --verify
    passed, reading the output by the same mistake. Converted back to explicit, the program
    is the source again, byte for byte."""
    src = "O1\nN10 G55 G40 G0 X2. Y0 M3\nG91.1\nG1 X1.5 F100.\nG04 P1000\nM30\n"
    options = ConvertOptions(FANUC, FANUC, decimal="implicit", units="inch")
    out, stats = convert_text(src, options)
    assert out.splitlines()[1:5] == ["N10 G20 G55 G40 G0 X787 Y0 M3", "G91.1",
                                     "G1 X591 F3.937", "G04 P1000"]
    implicit = options.effective_target()
    read = parse_text(out, implicit.dialect)
    codes = [(f.rule, f.line) for f in Checker(implicit).run(iter(read))
             if f.rule in ("TG301", "TG307", "TG304")]
    assert codes == []
    # the real control's profile reads the output the same way: the same codes, no unknown one
    assert [(f.rule, f.line) for f in Checker(FANUC).run(iter(parse_text(out, FANUC.dialect)))
            if f.rule in ("TG301", "TG307", "TG304")] == []
    back, _ = convert_text(convert_text(src, ConvertOptions(FANUC, FANUC, decimal="implicit"))[0],
                           ConvertOptions(FANUC, ConvertOptions(FANUC, FANUC, decimal="implicit")
                                          .effective_target(), decimal="explicit"))
    assert back == src


def test_an_implicit_decimal_program_verifies(tmp_path):
    path = tmp_path / "p.nc"
    path.write_text("%\nO1\nG21 G17 G90 G94\nG55 G0 X2. Y0\nG91.1 G2 X4. I1. F100.\nM30\n%\n")
    stats = convert_file(str(path), str(tmp_path / "o.nc"),
                         ConvertOptions(FANUC, FANUC, decimal="implicit"), verify=True)
    assert stats.verified


# -- each program's local variables (#1-#33) are its own ---------------------------------
# Custom Macro B (FANUC 0i-F/30i-B "Custom macro", variable types): local variables belong to
# the program (a macro's level) and are cleared at its end; common variables (#100-#199,
# #500-#999) are shared by every program in the control's memory.

# O1 uses #1 as a length, O2 as a repeat count: each program alone converts.
LOCALS = ("%\n"
          "O0001(LENGTH)\n"
          "G21 G90\n"
          "#1 = 10.\n"
          "G01 X#1 F100.\n"
          "M30\n"
          "O0002(COUNT)\n"
          "G21 G90\n"
          "#1 = 3\n"
          "M98 P1000 L#1\n"
          "M30\n"
          "%\n")


@pytest.mark.parametrize("profile", [FANUC, HAAS])
def test_a_local_variable_of_two_programs_is_two_variables(profile):
    """#1 is a length in O0001 and a count in O0002: converted, O0001's #1 in inch and
    O0002's left alone; the same text as the two programs converted one by one."""
    opts = ConvertOptions(profile, profile, units="inch")
    whole, _ = convert_text(LOCALS, opts)
    lines = whole.splitlines()
    assert lines[3:5] == ["#1 = 0.3937", "G01 X#1 F3.937"]
    assert lines[8:10] == ["#1 = 3", "M98 P1000 L#1"]
    assert whole == "".join(convert_text(p, opts)[0] for p in programs(LOCALS))


def test_the_two_uses_in_one_program_are_still_refused():
    """The same two uses of #1 in one program: nothing proves what #1 holds."""
    one = LOCALS.replace("M30\nO0002(COUNT)\nG21 G90\n", "")
    with pytest.raises(ConversionError) as info:
        convert_text(one, ConvertOptions(FANUC, FANUC, units="inch"))
    assert (info.value.code, info.value.line) == ("conversion-unprovable", 4)
    assert ("#1 is read as a length (line 5) and as something else (line 7)"
            in info.value.message)


def test_a_common_variable_stays_one_variable_of_the_file():
    """#100 is common: a program can set it for the next, so its uses in two programs are
    one variable's, and a length in one and a count in the other is refused."""
    common = LOCALS.replace("#1", "#100")
    with pytest.raises(ConversionError) as info:
        convert_text(common, ConvertOptions(FANUC, FANUC, units="inch"))
    assert info.value.code == "conversion-unprovable"
    assert ("#100 is read as a length (line 5) and as something else (line 10)"
            in info.value.message)
    # kept: #100 set in O0001 and read as a length in O0002 converts as a length
    shared = ("O0001\nG21 G90\n#100 = 10.\nM30\nO0002\nG21 G90\nG01 X#100 F100.\nM30\n")
    out, _ = convert_text(shared, ConvertOptions(FANUC, FANUC, units="inch"))
    assert out.splitlines()[2] == "#100 = 0.3937"


def test_a_main_program_s_local_variable_read_and_set_nowhere_else_is_refused():
    """O0002 (in a file of main programs: locals of its own) reads #1 as a length and sets it
    nowhere: its value comes from outside, in units nothing here converts. O0001's #1 is
    another variable, set and never read. Named with their programs."""
    src = "O0001\nG21 G90\n#1 = 10.\nM30\nO0002\nG21 G90\nG01 X#1 F100.\nM30\n"
    with pytest.raises(ConversionError) as info:
        convert_text(src, ConvertOptions(FANUC, FANUC, units="inch"))
    assert (info.value.code, info.value.line) == ("conversion-unprovable", 3)
    assert ("#1 of the file's first program is assigned on line 3 but never read in this "
            "program") in info.value.message
    _, stats = convert_text(src, ConvertOptions(FANUC, FANUC, units="inch",
                                                allow_unconverted=True))
    assert ("line 7: X#1 left unconverted: #1 of the program beginning on line 5 is read as "
            "a length (line 7) but not set in this program: its value comes from a caller or "
            "the control, in units this conversion does not change") in stats.notes


@pytest.mark.parametrize("call", ["M98 P9001", "M6"])
def test_a_file_holding_a_subprogram_shares_its_local_variables(call):
    """On the control a subprogram runs at its caller's level of local variables (only G65/G66
    give a macro its own), and a program may call one by M98 or by a code the machine maps to
    it (M6 -> O9001 by parameter 6071): O9001 sets the #1 that O0001 reads after the call. In
    a file holding a subprogram (M99) every program's locals are read as one, as before."""
    shared = (f"O0001\nG21 G90\n#1 = 10.\n{call}\nG01 X#1 F100.\nM30\n"
              "O9001\n#1 = 3\nM98 P1000 L#1\nM99\n")
    with pytest.raises(ConversionError) as info:
        convert_text(shared, ConvertOptions(FANUC, FANUC, units="inch"))
    assert info.value.code == "conversion-unprovable"
    assert "#1 is read as a length (line 5) and as something else (line 9)" \
        in info.value.message
    # a caller's #1 set before the call and read by the subprogram as a length: one variable
    src = f"O0001\nG21 G90\n#1 = 10.\n{call}\nM30\nO9001\nG91\nG01 X#1 F100.\nM99\n"
    out, _ = convert_text(src, ConvertOptions(FANUC, FANUC, units="inch"))
    assert out.splitlines()[2] == "#1 = 0.3937"


def test_a_file_of_locals_converts_and_verifies(tmp_path):
    """Written and proved: --verify reads the output back program by program."""
    path, out = tmp_path / "backup.nc", tmp_path / "out.nc"
    path.write_text(LOCALS)
    stats = convert_file(str(path), str(out), ConvertOptions(FANUC, FANUC, units="inch"),
                         verify=True)
    assert stats.verified
    assert out.read_text() == convert_text(LOCALS, ConvertOptions(FANUC, FANUC,
                                                                  units="inch"))[0]


def test_the_command_line_converts_the_locals_and_refuses_the_common(tmp_path):
    src, out = tmp_path / "p.nc", tmp_path / "o.nc"
    args = ["convert", str(src), "-o", str(out), "--from", "fanuc-mill", "--to",
            "fanuc-mill", "--units", "inch", "--verify"]
    src.write_text(LOCALS)
    result = CliRunner().invoke(main, args, catch_exceptions=False)
    assert result.exit_code == 0, result.output
    src.write_text(LOCALS.replace("#1", "#100"))
    result = CliRunner().invoke(main, [*args, "--force"], catch_exceptions=False)
    assert result.exit_code == 1 and "Traceback" not in result.output
    assert "p.nc:4:1: cannot convert the units of parameter #100" in result.output


def test_the_analysis_splits_the_file_where_the_converter_does():
    """The analysis (``_core.ParameterAnalysis``) finds the programs the converter begins: the
    backup's three, a folder marker or an O number after M30 or M99; an O word with no end
    before it, or a ``%``, begins none; other families never split."""
    def starts(chunks, profile=FANUC):
        analysis = _core.ParameterAnalysis(machine(profile))
        for text, line in chunks:
            analysis.read_lines(text, line, profile.dialect.flags, None)
        return [start for start, _, _ in analysis.result().programs()]

    assert starts([(BACKUP, 0)]) == [0, 8, 13]
    # chunk by chunk, the state carried: "M99" ends one chunk, the O number opens the next
    assert starts([("O1\nM98 P2\nO5\nM99", 0), ("%\nO2\nG0 X1.", 4)]) == [0, 6]
    assert starts([("G0 X1.\nM30\nO2\n#1=2\nG0 X#1", 0)], load_profile("linuxcnc")) == [0]
    # each program's words after the line it begins on: O0001's #1 a length, O0002's a count
    assert analyse_parameters([LOCALS], FANUC).programs() == [(0, ["#1"], []), (7, [], [])]


def test_an_analysis_split_elsewhere_is_refused_not_misapplied():
    """Should the analysis and the converter ever split a file apart, a program would be
    converted with another's classes: the core refuses instead."""
    opts = ConvertOptions(FANUC, FANUC, units="inch")
    # the analysis of another file, whose second program begins on line 9, not 7
    wrong = analyse_parameters([LOCALS.replace("M30\n", "M30\n(NEXT)\n(ONE)\n", 1)], FANUC)
    assert [start for start, _, _ in wrong.programs()] == [0, 9]
    converter = Converter(opts, FANUC, file="p.nc", parameters=wrong)
    with pytest.raises(ConversionError) as info:
        "".join(converter.convert_stream([LOCALS], FANUC.dialect))
    assert (info.value.code, info.value.line) == ("conversion-unprovable", 7)
    assert "split the file's programs differently at line 7" in info.value.message


# -- the corpus ---------------------------------------------------------------------------

BACKUPS = {
    "zhituaishangc__SK7420_750_N12_FANUC_HuBeiHengLong__ALL-PROG.TXT": FANUC,
}
SHOPS = CORPUS / "shops"


@pytest.mark.skipif(not SHOPS.is_dir(), reason="shared/corpus/shops is not present")
@pytest.mark.parametrize("name", sorted(BACKUPS))
@pytest.mark.parametrize("options", [{"decimal": "implicit"}, {"decimal": "explicit"}])
def test_a_real_memory_backup_converts_program_by_program(tmp_path, name, options):
    """A thread grinder's ALL-PROG punch-out (15 programs): converted whole and verified, and
    the same text as its programs converted one by one."""
    path = SHOPS / name
    profile = BACKUPS[name]
    opts = ConvertOptions(profile, profile, **options)
    stats = convert_file(str(path), str(tmp_path / "out.nc"), opts, verify=True)
    assert stats.verified
    text = path.read_bytes().decode("utf-8", "surrogateescape")
    parts = programs(text)
    assert len(parts) > 10
    whole = (tmp_path / "out.nc").read_bytes().decode("utf-8", "surrogateescape")
    assert whole == "".join(convert_text(p, opts)[0] for p in parts)


@pytest.mark.skipif(not SHOPS.is_dir(), reason="shared/corpus/shops is not present")
def test_a_real_memory_backup_of_builder_m_codes_is_refused_for_a_haas():
    """The grinder's builder M codes (M21, M35, M39: its PLC's) are a Haas mill's own functions
    (M21 a user M-fin relay, M39 the turret's rotation): converted to haas-mill, the backup's
    `N5M21` (line 217) is refused naming the Haas's function (it converted `ok` before review
    6). The backup now stops before it, at line 133's `#753=#5121`: #753 is no general
    purpose variable on a Haas (the NGC's Macro Variables Table keeps #700-#799)."""
    path = SHOPS / "zhituaishangc__SK7420_750_N12_FANUC_HuBeiHengLong__ALL-PROG.TXT"
    with pytest.raises(ConversionError) as info:
        convert_file(str(path), None, ConvertOptions(HAAS, FANUC))
    assert (info.value.code, info.value.line, info.value.column) == ("conversion-meaning", 133,
                                                                     4)
    assert "#753 is a common variable on a FANUC" in info.value.message
    block = path.read_text("latin-1").splitlines()[216]
    assert block.strip() == "N5M21"
    with pytest.raises(ConversionError) as info:
        convert_text(f"O1\n{block}\nM30\n", ConvertOptions(HAAS, FANUC))
    assert (info.value.code, info.value.column) == ("conversion", 3)
    assert info.value.message.startswith(
        "M21: the source and target controls give this code different meanings (the machine "
        "builder's M function, handed to its PLC (its profile lists no such code) on the source, "
        '"optional user M code with M-fin" on the target'), info.value.message


@pytest.mark.skipif(not SHOPS.is_dir(), reason="shared/corpus/shops is not present")
def test_a_real_backup_s_common_variable_is_still_refused_under_a_change_of_units():
    """ALL-PROG.TXT has no local variables; its programs share the common #100-#106, which
    O0800 reads as an X length (G90 G1 X#100) and O0900 as a C angle (G90 G1 C#100). Each sets
    them before reading, but the control keeps one #100 for all of them, and O8200 reads what
    O8000 sets: refused. With --allow-unconverted it was converted and partly verified, but its
    dwell `G4 X#105` (seconds) was left as written while #105, a length by `X#105` elsewhere,
    was scaled: the dwell read another number (review 10, finding 1). Refused there now, with
    the option too."""
    path = SHOPS / "zhituaishangc__SK7420_750_N12_FANUC_HuBeiHengLong__ALL-PROG.TXT"
    with pytest.raises(ConversionError) as info:
        convert_file(str(path), None, ConvertOptions(FANUC, FANUC, units="inch"))
    assert (info.value.code, info.value.line) == ("conversion-unprovable", 9)
    assert "#100 is read as a length (line 15) and as something else (line 99)" \
        in info.value.message
    with pytest.raises(ConversionError) as info:
        convert_file(str(path), None, ConvertOptions(FANUC, FANUC, units="inch",
                                                     allow_unconverted=True), verify=True)
    assert (info.value.line, info.value.column) == (17, 6)
    assert info.value.message.startswith(
        "X#105 reads #105, which this conversion converts as a length, but this word's value "
        "is scaled otherwise here")


def test_programs_cuts_where_the_checker_does():
    assert [p.splitlines()[0] for p in programs(BACKUP)] == ["%", "&F=/USER/PATH2/",
                                                             "O0003(FACE)"]


def test_linuxcnc_cycle_words_convert_by_their_roles():
    """LinuxCNC's G-code reference: G64 P Q are tolerances (lengths), G5 I J P Q the spline's
    offsets (lengths), and G76 P (pitch) I J K E lengths but R (depth degression), Q (the
    compound slide angle), H (spring passes) and L (taper ends) not. The profile's P is a
    number elsewhere (G4 P seconds) and its Q a length (a peck)."""
    linuxcnc = load_profile("linuxcnc")
    src = ("G21 G90\nG64 P0.1 Q0.05\nG76 P1.5 Z-20 I-0.5 J0.2 K1 R2 Q29.5 H3 E1 L2\n"
           "G5 X10 Y10 I2 J0 P1 Q-1\nG4 P2\nG83 X0 Y0 Z-5 R1 Q0.5\nM2\n")
    out, _ = convert_text(src, ConvertOptions(linuxcnc, linuxcnc, units="inch"))
    assert out.splitlines()[1:6] == [
        "G64 P0.003937 Q0.001969",
        "G76 P0.059055 Z-0.787402 I-0.019685 J0.007874 K0.03937 R2 Q29.5 H3 E0.03937 L2",
        "G5 X0.393701 Y0.393701 I0.07874 J0 P0.03937 Q-0.03937",
        "G4 P2",
        "G83 X0 Y0 Z-0.19685 R0.03937 Q0.019685",
    ]
