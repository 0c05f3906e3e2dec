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
    # review 5, 3 (m72): M72 brings back the inch M70 saved
    ("G20 G90\nG0 X1 Y1\nM70\nG21\nG0 X10\nM72\nG1 X2 F10\nM2\n", LINUXCNC, "metric", (6, 1),
     "M72 restores the modal state M70 saved, in inch, while a units code since selected "
     "metric"),
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
        run = subprocess.run([RS274, "-g", str(path)], capture_output=True, text=True,
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
