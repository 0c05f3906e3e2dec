"""Units under a change of units where the program's flow is not straight (review 5).

A units code inside a condition or a loop, or in a span a jump skips or repeats, leaves the
units after it depending on values the conversion does not know; LinuxCNC's M70/M72 and M73
bring saved units back; LinuxCNC's #5420-#5428 follow G20/G21, its #5221.. work offsets do
not. Each case is a program the review ran through LinuxCNC's rs274 (or the control's manual),
and a conversion that would move the machine elsewhere on some path is refused at its line
and column, while one every path agrees on still converts.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from decimal import Decimal

import pytest

from formats.convert import ConvertOptions, convert_text
from formats.errors import ConversionError
from formats.profile import load_profile

from .conftest import rs274_env

LINUXCNC = load_profile("linuxcnc")
FANUC = load_profile("fanuc-mill")
SIEMENS = load_profile("sinumerik-840d")
RS274 = shutil.which("rs274")


def refusal(src: str, profile=LINUXCNC, units: str = "metric") -> ConversionError:
    with pytest.raises(ConversionError) as info:
        convert_text(src, ConvertOptions(profile, profile, units=units))
    return info.value


def converted(src: str, profile=LINUXCNC, units: str = "metric") -> list[str]:
    return convert_text(src, ConvertOptions(profile, profile, units=units))[0].splitlines()


BODY = "o100 sub\nG90 G1 Z-0.1 F10\no100 endsub\n"


@pytest.mark.parametrize(("src", "profile", "units", "at", "start"), [
    # review 5, 1 (cd4): a call after a G21 in an o-if; rs274 runs the body in inch when the
    # condition is false
    ("G20 G90\nG0 X1 Y1\no1 if [#5 GT #6]\nG21\no1 endif\no100 call\nM2\n" + BODY,
     LINUXCNC, "metric", (6, 1),
     "the units in force here are not known: the condition beginning on line 3 ends in "
     "metric on one path and in inch on another (units code on line 4, column 1)"),
    # c3: a length after it
    ("G20 G90\no1 if [#5 GT #6]\nG21\no1 endif\nG1 X2 F10\nM2\n", LINUXCNC, "inch", (5, 4),
     "the units in force here are not known: the condition beginning on line 2"),
    # an else branch that begins in the units before the if, not the if branch's
    ("G20 G90\no1 if [#5 GT #6]\nG21\no1 else\nG1 X2 F10\no1 endif\nM2\n", LINUXCNC, "metric",
     (5, 4), "the units in force here are not known: the branch before ends in metric"),
    # lp4: a loop whose second pass runs in other units
    ("G20 G90\n#2=2\no1 while [#2]\no100 call\nG21\n#2=[#2-1]\no1 endwhile\nM2\n" + BODY,
     LINUXCNC, "metric", (7, 1),
     "the loop beginning on line 3 begins in inch and ends in metric (units code on line 5, "
     "column 1)"),
    # Macro B (fj): a jump over G20
    ("%\nO1\nG21 G90\nG0 X10. Y10.\nIF [#5 GT #6] GOTO 10\nG20\nN10 G1 X2. F10.\nM30\n%\n",
     FANUC, "inch", (7, 8),
     "the units in force here are not known: the jump on line 5 to N10 comes here in "
     "metric, the straight path in inch"),
    # Macro B: a units code in a one-block IF ... THEN
    ("%\nO1\nG21 G90\nIF [#5 GT #6] THEN G20\nG1 X2. F10.\nM30\n%\n", FANUC, "inch", (5, 4),
     "the units in force here are not known: the condition on line 4 selects inch when it "
     "holds, and the units stay metric when not"),
    # Macro B: a backward jump to a span read first in other units
    ("%\nO1\nG21 G90\nN5 G0 X10. Y10.\nG20\nG1 X1. F10.\nIF [#5 GT #6] GOTO 5\nM30\n%\n",
     FANUC, "inch", (7, 1), "the jump back to N5 (read first in metric) runs that span again"),
    # SINUMERIK (sj): GOTOF over G70
    ("G71 G90\nG0 X10 Y10\nIF R5>R6 GOTOF LAB1\nG70\nLAB1:\nG1 X20 F100\nM30\n",
     SIEMENS, "inch", (6, 4), "the units in force here are not known: the jump on line 3 to "
     "LAB1 comes here in metric, the straight path in inch"),
    # review 5, 2 (m73b): M73 after the body's own G21 saves metric: the caller goes on in it
    ("G20 G90\nG0 X1 Y1\no100 call\nG1 X2 F10\nM2\no100 sub\nG21\nG90 G0 X10\nM73\n"
     "o100 endsub\n", LINUXCNC, "metric", (10, 1),
     "o100: the subroutine selects metric and returns in it (no M73 before that units code)"),
    # M72 brings back units M70 saved while they were in doubt
    ("G20 G90\no1 if [#5 GT #6]\nG21\no1 endif\nM70\nG20\nM72\nG1 X2 F10\nM2\n", LINUXCNC,
     "metric", (8, 4), "the units in force here are not known: M72 restores the units M70 "
     "saved, which were not known there: the condition beginning on line 2"),
    # review 6, 1 (t2): `break` leaves the loop in the inch of its pass (rs274: X1 inch)
    ("G21 G90 G17\no100 while [#1 LT #3]\nG20\no101 if [#2 GT #4]\no100 break\no101 endif\n"
     "G21\n#1 = [#1 + #5]\no100 endwhile\nG1 X1. F100.\nM2\n", LINUXCNC, "inch", (10, 4),
     "the units in force here are not known: the loop beginning on line 2 is left in metric "
     "at its end and in inch on another way (line 5)"),
    # (t15): `continue` begins the next pass in inch, its text read in metric
    ("G21 G90 G17\no100 while [#1 LT #3]\nG1 X1. F100.\nG20\no101 if [#2 GT #4]\n"
     "o100 continue\no101 endif\nG21\no100 endwhile\nM2\n", LINUXCNC, "inch", (6, 1),
     "the continue begins the next pass of the loop beginning on line 2 in inch, while its "
     "first pass begins in metric (units code on line 4, column 1)"),
    # (t13): `return` before the body's G21: the caller goes on in inch (rs274)
    ("o<s> sub\nG20\no2 if [#1 GT #2]\no<s> return\no2 endif\nG21\no<s> endsub\nG21 G90 G17\n"
     "o<s> call\nG1 X1. F10.\nM2\n", LINUXCNC, "inch", (10, 4),
     "the units in force here are not known: the subroutine o<s> returns in inch on line 4 "
     "and in metric at its end"),
    # review 6, 2 (t29): the body's if/else selects inch or metric: its end is in doubt
    ("o<s> sub\no2 if [#<_ra> GT #<_rb>]\nG20\no2 else\nG21\no2 endif\no<s> endsub\n"
     "G21 G90 G17\no<s> call\nG1 X1. F100.\nM2\n", LINUXCNC, "inch", (10, 4),
     "the units in force here are not known: the subroutine o<s> may return in units not "
     "known (line 7: the condition beginning on line 2 ends in"),
    # the same body below its call: the call went on already, refused at its end
    ("G21 G90 G17\no<s> call\nG1 X1. F100.\nM2\no<s> sub\no2 if [#<_ra> GT #<_rb>]\nG20\n"
     "o2 else\nG21\no2 endif\no<s> endsub\n", LINUXCNC, "inch", (11, 1),
     "the subroutine o<s> may return in units not known"),
    # review 6, 6 (t14): after `GOTO #5` a second G20 does not settle where the jump lands
    ("%\nO1\nG21 G90 G17\nGOTO #5\nG20\nG20\nN40 G1 X1. F10.\nM30\n%\n", FANUC, "metric",
     (7, 8), "the units in force here are not known: the jump on line 4 goes to a computed "
     "target, which may lie after the units code on line 6"),
    # a jump under block skip is optional: the straight path may reach G20 and N10
    ("%\nO1\nG21 G90\nIF [#1 EQ #2] GOTO 10\n/GOTO 20\nG20\nN10 G1 X1. F10.\nN20 M30\n%\n",
     FANUC, "inch", (7, 8), "the units in force here are not known: the jump on line 4 to N10 "
     "comes here in metric, the straight path in inch"),
    # a SINUMERIK CASE jumps to each label it names: LAB2 from metric, past the G70
    ("G71 G90 G17\nCASE R1 OF 1 GOTOF LAB1 2 GOTOF LAB2 DEFAULT GOTOF LAB3\nLAB1:\nG70\nLAB2:\n"
     "G1 X1 F100\nLAB3:\nM30\n", SIEMENS, "inch", (6, 4), "the units in force here are not "
     "known: the jump on line 2 to LAB2 comes here in metric, the straight path in inch"),
    # review 7, 3: a G21 after `continue` is dead, but the G20 before it is the next pass's
    ("G21 G90\no100 while [#5 GT #1]\n#1 = [#1 + #6]\nG20\no100 continue\nG21\n"
     "o100 endwhile\nG1 X1. F10.\nM2\n", LINUXCNC, "inch", (5, 1),
     "the continue begins the next pass of the loop beginning on line 2 in inch, while its "
     "first pass begins in metric"),
    # review 7, 3: a G21 after `return` is dead: the body returns in the inch before it
    ("G21 G90\no200 sub\nG20\no200 return\nG21\no200 endsub\no200 call\nG1 X1. F10.\nM2\n",
     LINUXCNC, "inch", (7, 1), "o200: the subroutine selects inch and returns in it"),
    # review 7, 5: the loop may run no pass, so the straight path comes to N50 in metric
    ("O1\nG21\nWHILE [#1 LT #2] DO1\nG20\nGOTO 50\nEND1\nN50 G1 X1. F10.\nM30\n", FANUC,
     "inch", (7, 8), "the units in force here are not known: the jump on line 5 to N50 comes "
     "here in inch, the straight path in metric"),
    # two jumps bring a label past the end two units
    ("%\nO1\nG21 G90\nIF [#1 EQ #2] GOTO 20\nG20\nIF [#3 EQ #4] GOTO 20\nM30\n"
     "N20 G1 X1. F10.\nM30\n%\n", FANUC, "inch", (8, 8),
     "the units in force here are not known: the jumps to N20 come here in metric (line 4) "
     "and in inch (line 6)"),
])
def test_units_a_path_may_skip_or_restore_are_refused_where_read(src, profile, units, at,
                                                                 start):
    error = refusal(src, profile, units)
    assert (error.code, error.clause, (error.line, error.column)) == (
        "conversion-units", "units", at), error.message
    assert error.message.startswith(start), error.message


@pytest.mark.parametrize(("src", "profile", "units", "line", "out"), [
    # both branches select metric: every path agrees
    ("G20 G90\no1 if [#5 GT #6]\nG21\no1 else\nG21\no1 endif\nG1 X2 F10\nM2\n", LINUXCNC,
     "inch", 6, "G1 X0.07874 F0.393701"),
    # the units selected again after the condition
    ("G20 G90\no1 if [#5 GT #6]\nG21\no1 endif\nG20\nG1 X2 F10\nM2\n", LINUXCNC, "metric", 5,
     "G1 X50.8 F254."),
    # a loop that selects the units it began in
    ("G20 G90\n#2=2\no1 while [#2]\nG21\nG0 X1\nG20\n#2=[#2-1]\no1 endwhile\nG1 X2 F10\nM2\n",
     LINUXCNC, "metric", 8, "G1 X50.8 F254."),
    # a jump over no change of units
    ("%\nO1\nG21 G90\nIF [#5 GT #6] GOTO 10\nG0 X10.\nN10 G1 X2. F10.\nM30\n%\n", FANUC, "inch",
     5, "N10 G1 X0.0787 F0.394"),
    # M73 before the body's own units code restores the caller's
    ("G20 G90\no100 call\nG1 X2 F10\nM2\no100 sub\nM73\nG21\nG90 G0 X10\no100 endsub\n",
     LINUXCNC, "metric", 2, "G1 X50.8 F254."),
    # M70 ... M72 over no change
    ("G20 G90\nM70\nG0 X1\nM72\nG1 X2 F10\nM2\n", LINUXCNC, "metric", 4, "G1 X50.8 F254."),
    # review 6, 12 (t22): M72 brings back the inch M70 saved (review 5, 3 refused it)
    ("G20 G90\nG0 X1 Y1\nM70\nG21\nG0 X10\nM72\nG1 X2 F10\nM2\n", LINUXCNC, "metric", 6,
     "G1 X50.8 F254."),
    # (t19): the loop selects its units at the head of its body, G21 after it
    ("G21 G90 G17\no1 repeat [#5]\nG20\nG1 X1. F10.\no1 endrepeat\nG21\nG1 X2. F100.\nM2\n",
     LINUXCNC, "inch", 6, "G1 X0.07874 F3.937008"),
    # (t4): the straight path does not reach G20; N10 is reached by the jump, in metric
    ("%\nO1\nG21 G90 G17\nGOTO 10\nG20\nN10 G1 X1. F100.\nM30\n%\n", FANUC, "inch", 5,
     "N10 G1 X0.0394 F3.937"),
    # (t10): past M30 only the jump comes
    ("%\nO1\nG21 G90 G17\nIF [#1 EQ #2] GOTO 20\nG20\nM30\nN20 G1 X1. F100.\nM30\n%\n",
     FANUC, "inch", 6, "N20 G20 G1 X0.0394 F3.937"),
    # review 7, 3: no path reads a units code after `continue`, `break` or `return` (rs274
    # never prints it); the loop, the branch and the body go on in the units before it
    ("G21 G90\no100 while [#5 GT #1]\n#1 = [#1 + #6]\no100 continue\nG20\no100 endwhile\n"
     "G1 X1. F10.\nM2\n", LINUXCNC, "inch", 6, "G1 X0.03937 F0.393701"),
    ("G21 G90\no100 do\n#1 = [#1 + #6]\no100 break\nG20\no100 while [#5 GT #1]\n"
     "G1 X1. F10.\nM2\n", LINUXCNC, "inch", 6, "G1 X0.03937 F0.393701"),
    ("G21 G90\no100 while [#5 GT #1]\no1 if [#5 GT #6]\no100 continue\nG20\no1 else\n"
     "G1 X1. F10.\no1 endif\no100 endwhile\nM2\n", LINUXCNC, "inch", 6,
     "G1 X0.03937 F0.393701"),
    ("G21 G90\no200 sub\no200 return\nG20\no200 endsub\no200 call\nG1 X1. F10.\nM2\n",
     LINUXCNC, "inch", 6, "G1 X0.03937 F0.393701"),
    # (t17): a SINUMERIK label on its own line, its units code on the next before any length
    ("G71 G90 G17\nLAB1:\nG71\nG1 X1 F100\nG70\nIF R1>R2 GOTOB LAB1\nM30\n", SIEMENS, "inch",
     3, "G1 X0.0394 F100"),
])
def test_units_every_path_agrees_on_still_convert(src, profile, units, line, out):
    assert converted(src, profile, units)[line] == out


@pytest.mark.parametrize("src", [
    "G20 G90\nG1 X[#5221+0.1] F10\nM2\n",
    "G20 G90\n#<a>=#5221\nG1 X#<a> F10\nM2\n",
    "G20 G90\no100 call [#5221+0.1]\nM2\no100 sub\nG90 G1 X#1 F10\no100 endsub\n",
    "G20 G90\no100 call [#5221]\nM2\no100 sub\nG90 G1 X[#1+0.1] F10\no100 endsub\n",
])
def test_a_work_offset_is_in_the_machine_s_units_on_every_path(src):
    """Review 5, 7: rs274 prints `#5221` set by `G10 L2 P1 X1` under G20 as 1 before and
    after G21: LinuxCNC's work offsets do not follow G20/G21, so a length read from one is
    refused whether it is read directly, copied, or passed as an argument."""
    error = refusal(src)
    assert error.code == "conversion-unprovable"
    assert "#5221" in error.message


MOVE = re.compile(r"STRAIGHT_FEED\((.*)\)")


def test_the_current_position_follows_the_units_as_rs274_reads_it(tmp_path):
    """#5420 (the current X) is in the units in force (rs274: 1 after `G21 G1 X1`, 0.03937
    after G20): a length read from it converts as the text around it does."""
    src = "G20 G90\nG0 X0 Y0\nG1 X1 F10\nG1 Y[#5420+0.5]\nM2\n"
    out = converted(src)
    assert out[3] == "G1 Y[#5420+12.7]"
    if RS274 is None:
        return
    moves = []
    for name, text in (("in.ngc", src), ("out.ngc", "\n".join(out) + "\n")):
        path = tmp_path / name
        path.write_text(text)
        run = subprocess.run(env=rs274_env(),
                             args=[RS274, "-g", str(path)], capture_output=True, text=True,
                             timeout=120, check=False)
        moves.append([[Decimal(v) for v in m[1].split(",")[:3]]
                      for m in map(MOVE.search, run.stdout.splitlines()) if m])
    (inch, mm) = moves
    assert len(inch) == len(mm) == 2
    for a, b in zip(inch, mm, strict=True):
        for x, y in zip(a, b, strict=True):
            assert abs(x * Decimal("25.4") - y) <= Decimal("0.0013")


def test_a_units_code_in_a_condition_with_no_length_after_converts():
    """Nothing after the condition depends on its units: the program converts."""
    src = "G21 G90\nG0 X1\no1 if [#5 GT #6]\nG20\no1 endif\nM2\n"
    assert converted(src, units="inch")[3] == "G20"


def rs274_moves(tmp_path, name: str, text: str) -> list[list[Decimal]]:
    path = tmp_path / name
    path.write_text(text)
    run = subprocess.run(env=rs274_env(),
                         args=[RS274, "-g", str(path)], capture_output=True, text=True,
                         timeout=120, check=False)
    assert "error" not in run.stdout.lower(), run.stdout
    # rs274 prints a move in the units in force: in mm here
    scale, moves = Decimal(1), []
    for line in run.stdout.splitlines():
        if "USE_LENGTH_UNITS" in line:
            scale = Decimal("25.4") if "INCHES" in line else Decimal(1)
        elif m := MOVE.search(line):
            moves.append([Decimal(v) * scale for v in m[1].split(",")[:3]])
    return moves


@pytest.mark.skipif(RS274 is None, reason="LinuxCNC's rs274 is not installed")
@pytest.mark.parametrize(("src", "params"), [
    # review 6, 12: the loop's head code (one pass, and none), M72
    ("G21 G90 G17\no1 repeat [#5]\nG20\nG1 X1. F10.\no1 endrepeat\nG21\nG1 X2. F100.\nM2\n",
     ["#5=1", "#5=0"]),
    ("G20 G90\nG0 X1 Y1\nM70\nG21\nG0 X10\nM72\nG1 X2 F10\nM2\n", [""]),
    # review 7, 3: the G21 after `continue` and after `return` is never read
    ("G20 G90\no100 while [#5 GT #1]\n#1 = [#1 + #6]\nG0 X1\no100 continue\nG21\n"
     "o100 endwhile\nG1 X2 F10\nM2\n", ["#5=2 #6=1", "#5=0"]),
    ("G20 G90\no200 sub\nG90 G0 X1\no200 return\nG21\no200 endsub\no200 call\nG1 X2 F10\nM2\n",
     [""]),
])
def test_what_the_flow_converts_moves_as_rs274_runs_the_source(tmp_path, src, params):
    """The source (inch where it says so) and its conversion to metric, run by rs274 with
    the parameters set, move to the same places on every path."""
    out = "\n".join(converted(src, units="metric")) + "\n"
    for i, param in enumerate(params):
        before = rs274_moves(tmp_path, f"in{i}.ngc", f"{param}\n{src}")
        after = rs274_moves(tmp_path, f"out{i}.ngc", f"{param}\n{out}")
        assert len(before) == len(after) > 0
        for a, b in zip(before, after, strict=True):
            for x, y in zip(a, b, strict=True):
                assert abs(x - y) <= Decimal("0.0013"), (param, before, after)


def test_text_past_the_end_a_jump_reaches_is_read_in_the_jump_s_units():
    """Review 6, 12 (t10): N20 past M30 runs only by the jump, in metric: its X1 is 1 mm, and
    the note on the inserted units code names the jump, not the program before."""
    src = "%\nO1\nG21 G90 G17\nIF [#1 EQ #2] GOTO 20\nG20\nM30\nN20 G1 X1. F100.\nM30\n%\n"
    text, stats = convert_text(src, ConvertOptions(FANUC, FANUC, units="inch"))
    assert text.splitlines()[6] == "N20 G20 G1 X0.0394 F3.937"
    assert any("it was read in metric, the units the jumps to its label bring" in note
               for note in stats.notes), stats.notes
