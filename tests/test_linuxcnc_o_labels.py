"""The o-word labels LinuxCNC's interpreter reads (issue 32, lcnc48): rs274ngc's ``read_o``
(interp_read.cc) reads a label that is no ``<name>`` through ``read_integer_value``, so any value
``read_real_value`` reads stands there -- a sign, a point with no fraction, a parameter, a
parameter whose number is a parameter's, an expression in brackets, a function -- and is taken as
a whole number within 0.0001 ("Non integer value for integer" further). Each program is asserted
against ``rs274 -g`` where installed (it runs the body of the called subroutine, a traverse to
X900), and tapegate's check follows the same call where it knows the label's value (the body's
TG601 at the call) and notes a call it cannot follow (TG140).
"""

from __future__ import annotations

import pytest

from formats.profile import builtin_text, profile_from_text
from postproc.check import check_text
from postproc.rules import rule_id

from .conftest import rs274_output

TRAVEL = rule_id("TravelExceeded")
NOT_FOLLOWED = rule_id("NotFollowed")
REFUSES = rule_id("LinuxCncRefuses")

# the subroutine o100 moves beyond the linuxcnc profile's X travel; the call is on line 8
SUB = "{define} sub\nG0 X900\n{define} endsub\nG21 G90\nG0 X-700 Y0\n#1=100\n#2=1\n{call}\nM2\n"


# the linuxcnc profile with an X travel, which the called body leaves
PROFILE = profile_from_text(
    builtin_text("linuxcnc").replace("[limits]\n", "[limits]\nX = [-300, 300]\n"))


def findings(text: str) -> list[tuple[str, int, str, str]]:
    return [(f.rule, f.line, f.severity, f.message) for f in check_text(text, PROFILE)]


def program(call: str, define: str = "o100") -> str:
    return SUB.format(define=define, call=call)


@pytest.mark.parametrize("call, define", [
    ("o+100 call", "o100"),
    ("o100 call", "o+100"),
    ("o100.0 call", "o100"),
    ("o100 call", "o100.0"),
    ("O 1 0 0 . 0 0 call", "o100"),
    ("o-[-100] call", "o100"),
    ("o100.00005 call", "o100"),
    ("o99.99995 call", "o100"),
    ("o-100 call", "o-100"),
    ("o[#1*2-100] call", "o100"),
    ("o##2 call", "o100"),
    ("o#[#2] call", "o100"),
    # a function of a constant that keeps a whole number whole (review 48, F4)
    ("oabs[-100] call", "o100"),
    ("o[abs[-100]] call", "o100"),
    ("ofix[100.9] call", "o100"),
    ("oround[99.5] call", "o100"),
    ("o100 call", "oabs[-100]"),
    ("o100 call", "o[abs[-100]]"),
    ("oabs[-100] call", "ofup[99.5]"),
])
def test_a_label_rs274_reads_calls_the_same_subroutine(tmp_path, call, define):
    text = program(call, define)
    found = findings(text)
    assert [(r, line) for r, line, sev, _ in found if sev == "error"] == [(TRAVEL, 8)], found
    out = rs274_output(tmp_path, text)
    assert "STRAIGHT_TRAVERSE(900.0000" in out, out


@pytest.mark.parametrize("call", ["osqrt[10000] call", "o[sqrt[10000]] call"])
def test_a_label_of_a_function_calls_a_target_the_checker_does_not_know(tmp_path, call):
    text = program(call)
    found = findings(text)
    assert [f for f in found if f[2] == "error"] == []
    assert any(r == NOT_FOLLOWED and line == 8 and "not known" in m for r, line, _, m in found)
    assert "STRAIGHT_TRAVERSE(900.0000" in rs274_output(tmp_path, text)


@pytest.mark.parametrize("call", ["o100.5 call", "o[100.5] call", "o[#2+99.5] call"])
def test_a_label_with_a_fraction_is_refused(tmp_path, call):
    text = program(call)
    found = findings(text)
    assert [(r, line) for r, line, sev, _ in found if sev == "error"] == [(REFUSES, 8)], found
    assert "Non integer value for integer" in rs274_output(tmp_path, text)


# A closing o-word with a computed label: rs274 works out its value where it reads the line and
# matches it to its opening by that value (issue 32, lcnc48, 2).
ENDSUB = "G21 G90\n{set}\no100 sub\nG0 X1\no#1 endsub\no100 call\nM2\n"
REFUSED = "File ended with no percent sign or program end"


@pytest.mark.parametrize("value, closes", [("#1=100", True), ("#1=200", False)])
def test_an_endsub_s_computed_label_closes_the_sub_of_its_value(tmp_path, value, closes):
    text = ENDSUB.format(set=value)
    errors = [(r, line) for r, line, sev, _ in findings(text) if sev == "error"]
    out = rs274_output(tmp_path, text)
    if closes:
        assert errors == []
        assert "STRAIGHT_TRAVERSE(1.0000" in out and REFUSED not in out, out
    else:
        assert errors == [(rule_id("NoProgramEnd"), 3)]
        assert REFUSED in out, out


def test_an_endsub_of_a_value_not_known_is_taken_as_closing_and_said(tmp_path):
    # #5220, the coordinate system in force, is 1 to rs274 -g; the checker does not know it
    text = ENDSUB.format(set="#1=[#5220*100]")
    found = findings(text)
    assert [f for f in found if f[2] == "error"] == []
    assert [line for r, line, _, m in found
            if r == NOT_FOLLOWED and "value the checker does not know" in m] == [5]
    out = rs274_output(tmp_path, text)
    assert "STRAIGHT_TRAVERSE(1.0000" in out and REFUSED not in out, out


@pytest.mark.parametrize("value, judged", [("#1=5", True), ("#1=6", False)])
def test_an_endif_s_computed_label_closes_the_condition_of_its_value(tmp_path, value, judged):
    # closed, the line after it runs wherever the program does: rs274 refuses its unset name;
    # o6 endif closes nothing (rs274: "undefined O-word label"), the line is not judged
    text = f"G21 G90\no5 if [1]\n{value}\no#1 endif\nG0 X#<nope>\nM2\n"
    errors = [(r, line) for r, line, sev, _ in findings(text) if sev == "error"]
    out = rs274_output(tmp_path, text)
    if judged:
        assert errors == [(REFUSES, 5)]
        assert "Named parameter #<nope> not defined" in out, out
    else:
        assert errors == []
        assert "undefined O-word label" in out, out


def test_a_definition_labelled_by_a_function_is_closed_by_its_value(tmp_path):
    # review 48, F4: rs274 runs it; no TG114 (never closed) nor TG138 (another label)
    text = "oabs[-100] sub\nG0 X1\no100 endsub\nG21 G90\no100 call\nM2\n"
    found = findings(text)
    assert [f for f in found if f[2] in ("error", "warning")] == [], found
    out = rs274_output(tmp_path, text)
    assert "STRAIGHT_TRAVERSE(1.0000" in out and REFUSED not in out, out


@pytest.mark.parametrize("text, line", [
    ("G21 G90\no100.5 if [1]\nG0 X1\no100.5 endif\nM2\n", 2),
    ("G21 G90\no[100.5] while [0]\no[100.5] endwhile\nM2\n", 2),
    ("o100.5 sub\nG0 X1\no100.5 endsub\nG21 G90\no100.5 call\nM2\n", 1),
])
def test_a_fractional_label_is_refused_on_any_o_word_line(tmp_path, text, line):
    # review 48, F5: rs274's read_o reads every o-word's label as an integer
    found = findings(text)
    assert [(r, ln) for r, ln, sev, _ in found if sev == "error"] == [(REFUSES, line)], found
    assert not any(r == NOT_FOLLOWED and "does not know" in m for r, _, _, m in found), found
    out = rs274_output(tmp_path, text)
    assert "Non integer value for integer" in out, out


@pytest.mark.parametrize("before, on, ends", [
    ("#1=5", "#1=2 m#1", False),
    ("(none)", "#1=2 m#1", False),
    ("#1=5", "#1=7 m#1", False),
    ("#1=2", "#1=5 m#1", True),
])
def test_an_m_word_reads_the_value_from_before_its_line(tmp_path, before, on, ends):
    # review 48, F8: rs274 makes a line's assignments at its end (RS274/NGC 3.0, 3.2.1)
    text = f"G21 G90\n{before}\nG0 X1\n{on}\nG0 X2\nM2\n"
    unread = [ln for r, ln, _, _ in findings(text) if r == rule_id("NotRead")]
    assert unread == ([5] if ends else [])
    out = rs274_output(tmp_path, text)
    assert ("STRAIGHT_TRAVERSE(2.0000" in out) is not ends, out


def test_a_definition_whose_label_is_not_worked_out_is_closed_by_its_endsub(tmp_path):
    # review 48, F4: rs274 runs it (sqrt[10000] is 100); the checker says so, no TG114/TG138
    text = "osqrt[10000] sub\nG0 X1\no100 endsub\nG21 G90\no100 call\nM2\n"
    found = findings(text)
    assert [f for f in found if f[2] in ("error", "warning")] == [], found
    assert any(r == NOT_FOLLOWED and line == 3 for r, line, _, _ in found), found
    out = rs274_output(tmp_path, text)
    assert "STRAIGHT_TRAVERSE(1.0000" in out and REFUSED not in out, out
