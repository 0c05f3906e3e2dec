"""A LinuxCNC definition whose only endsub of its label stands inside a block of its body left
open (issue 32, lcnc77b): `o<min> sub` / `o100 if [#1]` / `G0 X1` / `o<min> endsub` / `M2`.

rs274ngc skips a definition that is not called to the first o-word line of its label
(interp_o_word.cc ``convert_control_functions``, ``skipping_o``): the endsub inside the `if`,
so the file runs as a program past it. A call runs the body from its sub: where the block's
condition is false (a `repeat`'s count below one) rs274 skips to the next o-word line of the
block's label, which the file does not have, and reads to its end ("File ended with no percent
sign or program end"); where it holds it returns at the endsub. A `do` runs its lines before
any test and never skips. The checker says the block left open (TG142, a warning), an error
(TG114) where a call of the file gives values that make the condition false, and TG114 for the
program's own missing end only where no M2/M30 follows the endsub. Each program is asserted
against ``rs274 -g`` where it is installed.
"""

from __future__ import annotations

import pytest

from formats.profile import load_profile
from postproc.check import check_text

from .conftest import rs274_output

ENDED = "File ended with no percent sign or program end"


def findings(text: str) -> list[tuple[str, int, str]]:
    return [(f.rule, f.line, f.severity) for f in check_text(text, load_profile("linuxcnc"))
            if f.severity != "info"]


def body(block: str, after: str) -> str:
    return f"o<min> sub\n{block}\nG0 X1\no<min> endsub\n{after}"


# (the block opened in the body, the lines after the endsub, the checker's findings, whether
# rs274 -g runs the file to its end)
CASES = [
    # not called: the definition skipped to its endsub, the M2 ends the program (held26's
    # snelweg `_dust_covert_action.ngc`, a HAL pin for the condition); TG114 before
    ("o100 if [1]", "M2\n", [], True),
    ("o100 if [#<_x>]", "M2\n", [("TG142", 2, "warning")], True),
    ("o100 if [#<_x>]", "G0 X5\nM2\n", [("TG142", 2, "warning")], True),
    ("o100 if [#<_x>]", "G0 X0 M2\n", [("TG142", 2, "warning")], True),
    # not called, no end after the endsub: the program's own TG114, at the last line
    ("o100 if [#<_x>]", "G0 X5\n", [("TG114", 5, "error"), ("TG142", 2, "warning")], False),
    # called with the condition false: rs274 reads to the end of the file
    ("o100 if [#1]", "o<min> call [0]\nM2\n", [("TG114", 5, "error")], False),
    ("o101 while [#1 GT 0]", "o<min> call [0]\nM2\n", [("TG114", 5, "error")], False),
    ("o101 repeat [#1]", "o<min> call [0]\nM2\n", [("TG114", 5, "error")], False),
    # called with it true: a return at the endsub, the program runs
    ("o100 if [#1]", "o<min> call [1]\nM2\n", [("TG142", 2, "warning")], True),
    ("o101 repeat [#1]", "o<min> call [2]\nM2\n", [("TG142", 2, "warning")], True),
    # a value the checker does not know (#5 is 0 to rs274): the warning
    ("o100 if [#1]", "o<min> call [#5]\nM2\n", [("TG142", 2, "warning")], False),
    # the endsub in the `else` branch: the first branch, run, skips from the `else` to an
    # `endif` the file does not have
    ("o100 if [#1]\nG0 X2\no100 else", "o<min> call [1]\nM2\n", [("TG114", 7, "error")], False),
    ("o100 if [#1]\nG0 X2\no100 else", "o<min> call [0]\nM2\n", [("TG142", 2, "warning")],
     True),
    ("o100 if [1]\nG0 X2\no100 else", "M2\n", [("TG142", 2, "warning")], True),
    # an `elseif` before the endsub: where the `if` and it are false, no branch runs
    ("o100 if [#1 GT 0]\nG0 X2\no100 elseif [#1 LT 0]", "o<min> call [0]\nM2\n",
     [("TG114", 7, "error")], False),
    # a call zeroes the parameters after its arguments; every call that surely runs counts
    ("o100 if [#1 GT 0]", "o<min> call\nM2\n", [("TG114", 5, "error")], False),
    ("o100 if [#1 GT 0]", "o<min> call [1]\no<min> call [0]\nM2\n", [("TG114", 6, "error")],
     False),
    # a call inside another definition never called does not run
    ("o100 if [#1 GT 0]", "o<other> sub\no<min> call [0]\no<other> endsub\nM2\n",
     [("TG142", 2, "warning")], True),
    # run as a program, the lines after the endsub are the main program's: an M2 in a block
    # that never runs ends nothing, a line closing a block of the body is refused
    ("o100 if [#<_x>]", "o1 if [0]\nM2\no1 endif\n", [("TG114", 7, "error"),
                                                       ("TG142", 2, "warning")], False),
    ("o100 if [1]", "o100 endif\nM2\n", [("TG412", 5, "error")], False),
    ("o100 if [#<_x>]", "G0 X2\no<min> endsub\nM2\n", [("TG412", 6, "error"),
                                                         ("TG142", 2, "warning")], False),
    ("o100 if [#<_x>]", "o<min> return\nM2\n", [("TG412", 5, "error"),
                                                  ("TG142", 2, "warning")], False),
    ("o100 while [#<_x>]", "o100 break\nM2\n", [("TG412", 5, "error"),
                                               ("TG142", 2, "warning")], False),
    # a subroutine file whose block never runs: every call reads to the end
    ("o100 repeat [0]", "", [("TG114", 2, "error")], False),
    # a `do` never skips: called or not, rs274 runs it
    ("o101 do", "o<min> call [0]\nM2\n", [], True),
]


@pytest.mark.parametrize(("block", "after", "expected", "runs"), CASES)
def test_block_open_at_endsub(tmp_path, block: str, after: str, expected, runs: bool) -> None:
    text = body(block, after)
    assert sorted(findings(text)) == sorted(expected), text
    out = rs274_output(tmp_path, text.replace("#<_x>", "1"))
    if runs:
        assert "PROGRAM_END" in out and ENDED not in out, out
    elif expected and expected[0][0] == "TG412":
        assert "PROGRAM_END" not in out and ("undefined O-word label" in out
                                             or "not in a subroutine definition" in out
                                             or "redefining sub" in out), out
    else:
        assert ENDED in out, out


def test_called_false_names_the_block(tmp_path) -> None:
    text = body("o100 if [#1]", "o<min> call [0]\nM2\n")
    (message,) = [f.message for f in check_text(text, load_profile("linuxcnc"))
                  if f.rule == "TG114"]
    assert "o100 if (line 2)" in message and "endsub (line 4)" in message, message
    assert ENDED in rs274_output(tmp_path, text)


def test_subroutine_file_alone() -> None:
    # a subroutine file with nothing after the endsub: the warning, no TG114 (a call returns)
    text = body("o100 if [#<_x>]", "")
    assert findings(text) == [("TG142", 2, "warning")]


# a bare O number inside a definition: rs274 reads it as a FANUC-style program's start and
# refuses it while a subroutine is defined, run or skipped ("Nested subroutine definition");
# outside a definition it runs (LCNC_BMC20's `toolchange.ngc` typed `O103` for `O103 endif`)
BARE_O = [
    ("o<m> sub\nO103\no<m> endsub\nM2\n", 2),
    ("o<m> sub\nN5 O103\no<m> endsub\nM2\n", 2),
    ("o<m> sub\no1 if [0]\n  O103 (x)\no1 endif\no<m> endsub\no<m> call\nM2\n", 3),
    # ... signed, with a point, a parameter or an expression alike (read_integer_value; review
    # 78-lcnc78 N2: `O[103]` was only a TG134 warning)
    ("o<m> sub\nO[103]\nG0 X1\no<m> endsub\nM2\n", 2),
    ("o<m> sub\nN5 O[1+2] (c)\no<m> endsub\nM2\n", 2),
    ("o<m> sub\nO#1\no<m> endsub\nM2\n", 2),
    ("o<m> sub\nO-103\no<m> endsub\nM2\n", 2),
    ("o<m> sub\nO103.0\no<m> endsub\nM2\n", 2),
    ("G0 X0\nO103\nG0 X1\nM2\n", None),
    ("o<m> sub\nG0 X1\no<m> endsub\nO103\nM2\n", None),
    # after an early endsub (in a block left open) the lines are the main program's
    ("o<m> sub\no100 if [#1 GT 0]\nG0 X1\no<m> endsub\nM98 P300\nM2\nO300\nG0 X2\nM99\n", None),
]


@pytest.mark.parametrize(("text", "line"), BARE_O)
def test_bare_o_in_definition(tmp_path, text: str, line: int | None) -> None:
    errors = [(f.rule, f.line) for f in check_text(text, load_profile("linuxcnc"))
              if f.severity == "error"]
    out = rs274_output(tmp_path, text)
    if line is None:
        assert errors == [], text
        assert "PROGRAM_END" in out, out
    else:
        assert errors == [("TG412", line)], text
        assert "Nested subroutine definition" in out, out
