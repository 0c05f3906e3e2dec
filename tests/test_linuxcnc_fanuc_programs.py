"""LinuxCNC 2.9's FANUC-style programs, `O300` ... `M99` called by `M98 P300` (issue 32, lcnc78).

rs274ngc reads a bare O number alone on its line as the start of a FANUC-style program
(interp_read.cc ``read_o``, ``O_``), seeks it for an ``M98 P300`` as it seeks an ``o300 sub``
for an ``o300 call``, and returns at its ``M99`` (interp_o_word.cc
``convert_control_functions``, ``M_99``). Written before the main program it runs inline, and an
M99 with no call to return from ends the program (interp_convert.cc ``convert_stop``). A call of
one form that reaches a definition of the other is refused. The checker reads the M98 form as
the o-word form: the program after the main program's end as a definition, the M98 as a call of
a definition written after it (the move after it under the caller's G2/G3 held for the body's
M99). Each program is asserted against ``rs274 -g`` where it is installed (its verdict in the
comment beside it).
"""

from __future__ import annotations

import pytest

from formats.profile import load_profile
from postproc.check import check_text

from .conftest import rs274_output

HEAD = "G21 G17 G90 F100\nG0 X0 Y0 Z0\nG2 X1 Y0 I0.5 J0\n"


def errors(text: str) -> list[tuple[str, int]]:
    return sorted((f.rule, f.line) for f in check_text(text, load_profile("linuxcnc"))
                  if f.severity == "error")


def refused(out: str) -> bool:
    return "PROGRAM_END" not in out


def fanuc(body: str) -> str:
    return f"{HEAD}M98 P300\nX2\nM2\nO300\n{body}\nM99\n"


def oword(body: str) -> str:
    return f"{HEAD}o300 call\nX2\nM2\no300 sub\n{body}\no300 endsub\n"


# (the body, the checker's errors): the M98 form and the o-word form read alike
BODIES = [
    # rs274 runs X2 in the body's G0, G1 or cycle
    ("G0 X0", []),
    ("G1 X0", []),
    ("G81 X1 Z-1 R2", []),
    # the body ends the program: X2 never runs
    ("G0 X0\nM2", []),
    # the body leaves the caller's G2 (or its own G3): "R i j k words all missing for arc"
    ("M8", [("TG404", 5)]),
    ("G3 X0 Y0 R2", [("TG404", 5)]),
]


@pytest.mark.parametrize(("body", "expected"), BODIES)
def test_m98_of_a_later_program_reads_as_the_o_word_call(tmp_path, body: str, expected) -> None:
    for text in (fanuc(body), oword(body)):
        assert errors(text) == expected, text
        assert refused(rs274_output(tmp_path, text)) == bool(expected), text


def test_two_calls_and_a_second_program(tmp_path) -> None:
    # rs274: runs (both calls run O300's G0; O400 never called)
    text = f"{HEAD}M98 P300\nM98 P300\nX2\nM2\nO300\nG0 X0\nM99\nO400\nG2 X1 Y0 I0.5 J0\nM99\n"
    assert errors(text) == []
    assert not refused(rs274_output(tmp_path, text))


def test_a_program_before_the_main_program_runs_inline_and_its_m99_ends(tmp_path) -> None:
    # rs274: runs the X10 alone, M99 ends the program; the lines after it never run (the arc
    # of a radius too short among them)
    text = "O300\nG0 X10\nM99\nG21 G90 G17\nG0 X0 Y0\nG2 X1 Y0 R0.1\nM98 P300\nM2\n"
    found = [(f.rule, f.line) for f in check_text(text, load_profile("linuxcnc"))
             if f.severity != "info"]
    assert found == [("TG117", 4)]
    out = rs274_output(tmp_path, text)
    assert "STRAIGHT_TRAVERSE(10.0000" in out and "ARC_FEED" not in out and not refused(out)


# a call of one form reaching a definition of the other: rs274's refusal at the definition
MIXED = [
    # rs274: 'O.... sub' subroutine must be called with 'O.... call'
    (f"{HEAD}M98 P300\nX2\nM2\no300 sub\nG0 X0\no300 endsub\n", ("TG412", 7),
     "must be called with 'O.... call'"),
    # rs274: Fanuc 'O....' subroutine must be called with 'M98'
    (f"{HEAD}o300 call\nX2\nM2\nO300\nG0 X0\nM99\n", ("TG412", 7), "must be called with 'M98'"),
    # rs274: Fanuc 'O....' subroutine definition must end with 'M99'
    (f"{HEAD}M98 P300\nX2\nM2\nO300\nG0 X0\no300 endsub\n", ("TG412", 9), "must end with 'M99'"),
]


@pytest.mark.parametrize(("text", "error", "said"), MIXED)
def test_a_call_of_the_other_form_is_refused(tmp_path, text: str, error, said: str) -> None:
    assert error in errors(text), text
    message = [f.message for f in check_text(text, load_profile("linuxcnc"))
               if (f.rule, f.line) == error][0]
    assert said in message
    out = rs274_output(tmp_path, text)
    assert refused(out) and said in out, out


# a bare O number is a program number to rs274 (signed, with leading zeros, a comment after
# it): no TG134; a word after it is refused ("Unknown control command in o word")
@pytest.mark.parametrize("line", ["O300", "O-300", "O0300", "o300", "O300 (x)", "O 300"])
def test_a_bare_o_number_is_classified(tmp_path, line: str) -> None:
    text = f"G0 X0\n{line}\nG0 X2\nM2\n"
    found = [f.rule for f in check_text(text, load_profile("linuxcnc")) if f.severity != "info"]
    assert found == []
    assert not refused(rs274_output(tmp_path, text))


# review 77-lcnc77b F7: a call inside another definition that is itself surely called
# (rs274: "File ended with no percent sign or program end" where a TG114 is expected)
NESTED = [
    ("o300 sub\no200 call [0]\no300 endsub\no300 call\nM2\n", [("TG114", 8)]),
    ("o300 sub\no200 call [0]\no300 endsub\no400 sub\no300 call\no400 endsub\no400 call\nM2\n",
     [("TG114", 11)]),
    ("o300 sub\no200 call [0]\no300 endsub\no1 if [1]\no300 call\no1 endif\nM2\n",
     [("TG114", 9)]),
    # o300 never called, called only where it never runs, or its call of o200 in a block of
    # its own or with a value that returns: the warning (rs274 runs each)
    ("o300 sub\no200 call [0]\no300 endsub\nM2\n", []),
    ("o300 sub\no200 call [0]\no300 endsub\no1 if [0]\no300 call\no1 endif\nM2\n", []),
    ("o300 sub\no1 if [#2]\no200 call [0]\no1 endif\no300 endsub\no300 call\nM2\n", []),
    ("o300 sub\no200 call [1]\no300 endsub\no300 call\nM2\n", []),
]


@pytest.mark.parametrize(("after", "expected"), NESTED)
def test_a_call_inside_a_called_definition(tmp_path, after: str, expected) -> None:
    text = f"o200 sub\no100 if [#1 GT 0]\nG0 X1\no200 endsub\n{after}"
    assert errors(text) == expected, text
    rules = [f.rule for f in check_text(text, load_profile("linuxcnc"))]
    assert expected or "TG142" in rules
    out = rs274_output(tmp_path, text)
    assert refused(out) == bool(expected), out


# review 78-lcnc78: programs rs274 never reads, or reads only in part, stay unjudged (rs274 runs
# each): one no call names (F1), a second one of a number (the call runs the first), an o-word
# definition of the number after the program the call runs (F3), the lines after an M30 of the
# body (F4), an O number of ten digits or more (F5)
NOT_READ = [
    "G21 G17 G90 F100\nG0 X0 Y0\nM2\nO301\nG2 X1 Y0\nM99\n",
    f"{HEAD}M98 P300\nX2\nM2\nO300\nG0 X0\nM99\nO300\nG2 X1 Y0\nM99\n",
    "G21 G17 G90\nG0 X0 Y0\nM98 P300\nM2\nO300\nG0 X1\nM99\no300 sub\nG0 X2\no300 endsub\n",
    "G21 G17 G90\nG0 X0 Y0\nM98 P300\nM2\nO300\nG0 X1\nM30\nG2 X5\nM99\n",
    "G21 G17 G90\nO1234567890\nG0 X0 Y0\nM2\n",
]


@pytest.mark.parametrize("text", NOT_READ)
def test_what_rs274_never_reads_is_not_judged(tmp_path, text: str) -> None:
    assert errors(text) == [], text
    assert not refused(rs274_output(tmp_path, text))


def test_a_nested_m98_program_is_judged(tmp_path) -> None:
    # rs274: R i j k words all missing for arc (O3000, run by O2000's M98, at its G2)
    text = ("G21 G17 G90 F100\nG0 X0 Y0\nM98 P2000\nM2\nO2000\nM98 P3000\nM99\n"
            "O3000\nG2 X1 Y0\nM99\n")
    assert errors(text) == [("TG404", 9)]
    assert "R i j k words all missing for arc" in rs274_output(tmp_path, text)


# a main-level M99 or M2 in a condition on a parameter the program never sets counts as an end
# (docs/rules.md, TG114): `rs274 -g` reads #5 as 0 from its empty var file and refuses ("File
# ended with no percent sign or program end"), a machine's interpreter may hold any value from
# the programs run before it; an `if [0]` or a #5 set to 0 first is surely false: TG114
@pytest.mark.parametrize("end", ["M99", "M2"])
def test_an_end_in_a_condition_on_a_parameter_never_set_counts_as_an_end(tmp_path, end) -> None:
    for first, cond, expected in (("", "#5 NE 0", []), ("", "0", [("TG114", 6)]),
                                  ("#5=0\n", "#5 NE 0", [("TG114", 7)])):
        text = f"G21 G17 G90\nG0 X0 Y0\n{first}o1 if [{cond}]\n{end}\no1 endif\nG0 X5\n"
        assert errors(text) == expected, text
        assert refused(rs274_output(tmp_path, text)), text


# an M98 of an `o300 sub` defined before the main program: rs274 2.9 refuses it ("'O.... sub'
# subroutine must be called with 'O.... call'"; review 78-lcnc78 M1, M2); said at the M98 that
# surely runs, not at one in a condition not known or after the end
@pytest.mark.parametrize(("text", "expected"), [
    ("o300 sub\nG0 X1\no300 endsub\nG21 G17 G90\nG0 X0 Y0\nM98 P300\nM2\n", [("TG412", 6)]),
    ("o300 sub\nG0 X1\no300 endsub\nG21 G90\nM98 P300\nM2\nO300\nG0 X2\nM99\n",
     [("TG412", 5)]),
    ("o300 sub\nG0 X1\no300 endsub\nG21 G90\no1 if [#1 GT 0]\nM98 P300\no1 endif\nM2\n", []),
    ("o300 sub\nG0 X1\no300 endsub\nG21 G90\no300 call\nM2\n", []),
])
def test_an_m98_of_an_o_word_definition_before_it_is_refused(tmp_path, text, expected) -> None:
    assert errors(text) == expected, text
    out = rs274_output(tmp_path, text)
    assert refused(out) == bool(expected), out
    if expected:
        assert "'O.... sub' subroutine must be called with 'O.... call'" in out, out
