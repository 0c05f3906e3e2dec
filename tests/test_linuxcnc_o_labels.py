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
])
def test_a_label_rs274_reads_calls_the_same_subroutine(tmp_path, call, define):
    text = program(call, define)
    found = findings(text)
    assert [(r, line) for r, line, sev, _ in found if sev == "error"] == [(TRAVEL, 8)], found
    out = rs274_output(tmp_path, text)
    assert "STRAIGHT_TRAVERSE(900.0000" in out, out


@pytest.mark.parametrize("call", ["oabs[-100] call", "ofix[100.9] call", "o[abs[-100]] call"])
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
