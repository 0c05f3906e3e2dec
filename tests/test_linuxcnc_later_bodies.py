"""LinuxCNC: a body written after the main program's end, run at its call (issue 32, lcnc79).

rs274ngc runs an ``o300 sub`` ... ``o300 endsub`` and a FANUC-style ``O300`` ... ``M99``
written after the main program's M2 where an ``o300 call`` or an ``M98 P300`` before it seeks
it (interp_o_word.cc ``control_back_to``, ``convert_control_functions``): under the work
system in force at the call, between the main program's positions before the call and those
after it. The checker reads both forms' bodies alike: judged under the call's work offset
(review 78-lcnc78 N1: the M98 form's body was not judged at all), in the span in force at the
call -- a span across a selection of another known system set aside there stays so, as the
main program's own moves after the selection are (review 78-lcnc78b F7, H15, H17, H27).

The profile gives G54 X 0 and G55 X -100 on a travel of -762 to 762. rs274's own offsets are
its var file's zeros: each program is asserted to run in ``rs274 -g`` (where installed), the
body's move made under the system the call selected (``SET_G5X_OFFSET``: 1 is G54, 2 G55).
"""

from __future__ import annotations

import pytest

from postproc.check import check_text

from .conftest import rs274_output

HEAD = "G21 G17 G90 F100\n"


def profile():
    from formats.profile import builtin_text, profile_from_text

    toml = builtin_text("linuxcnc").replace("[limits]\n",
                                            "[limits]\nX = [-762, 762]\nY = [-406, 406]\n")
    return profile_from_text(toml + "\n[work_offsets]\nG54 = { X = 0.0, Y = 0.0 }\n"
                             "G55 = { X = -100.0, Y = 0.0 }\n")


def errors(text: str) -> list[tuple[str, int, str]]:
    return [(f.rule, f.line, f.message) for f in check_text(text, profile())
            if f.severity == "error"]


def forms(main: str, body: str) -> tuple[str, str]:
    """The program in the M98 form and in the o-word form: `main` (its `CALL` the call), then
    M2 and the body after it."""
    m98 = f"{HEAD}{main.replace('CALL', 'M98 P300')}\nM2\nO300\n{body}\nM99\n"
    oword = f"{HEAD}{main.replace('CALL', 'o300 call')}\nM2\no300 sub\n{body}\no300 endsub\n"
    return m98, oword


def first_line(main: str) -> int:
    """The line of the body's first move: after HEAD, the main program, M2 and the O line."""
    return main.count("\n") + 5


# (the main program, the body, the start of the TG601 said at the body's first line or None,
# the system rs274 selects before the body's first move)
LATER = [
    # review 78-lcnc78 N1: the body runs under the call's G55 (-700 at -800, beyond); the M98
    # form was silent
    ("G55\nG0 X0 Y0\nCALL", "G0 X-700", "X goes to -800 in machine coordinates", "2, "),
    ("G54\nG0 X0 Y0\nCALL", "G0 X800", "X goes to 800 in machine coordinates", "1, "),
    ("G55\nG0 X0 Y0\nCALL", "G0 X-600", None, "2, "),
    # review 78-lcnc78b F7's kind: X-700 under G54 (machine -700), then the body under the
    # call's G55 (860: machine 760): each inside; was "X spans 1560"
    ("G54\nG0 X-700\nG55\nCALL", "G0 X860", None, "2, "),
    # ... H17's: the body's X beyond under G55 alone is said as a machine position
    ("G54\nG0 X-700\nG55\nCALL", "G0 X870", "X goes to 770 in machine coordinates", "2, "),
    # ... H14's: the body's X-800 under G54 is beyond itself (a true error kept)
    ("G54\nCALL\nG55\nG0 X860", "G0 X-800", "X goes to -800 in machine coordinates", "1, "),
    # ... H27's: a position of the main under G55 before the call, the body's in the same
    ("G54\nG0 X-700\nG55\nG0 X0\nCALL", "G0 X800\nG0 X850", None, "2, "),
]


@pytest.mark.parametrize("main, body, said, system", LATER)
def test_a_later_body_is_judged_under_its_calls_system_and_span(tmp_path, main, body, said,
                                                                system):
    for text in forms(main, body):
        found = [(line, message) for _, line, message in errors(text)]
        if said is None:
            assert found == [], text
        else:
            assert len(found) == 1 and found[0][0] == first_line(main), (text, found)
            assert found[0][1].startswith(said), (text, found)
        out = rs274_output(tmp_path, text)
        assert "PROGRAM_END" in out, out
        move = body.split("\n")[0].replace("G0 X", "")
        before = out.split(f"STRAIGHT_TRAVERSE({float(move):.4f}")[0]
        assert before.rsplit("SET_G5X_OFFSET(", 1)[1].startswith(system), out


# kept as before, erring on the side of the alarm (rs274 goes beyond, or its offset is not
# known): G91 across the selection runs on from the machine position (review 78-lcnc78b H4:
# -700 under G54, then 1650 more under G55 at machine 950), and a span holding a position under
# a system the profile does not give (G56: its value not known, 78-lcnc78b H15 on wo.toml)
KEPT = [
    ("G54\nG0 X-700\nG91\nG55\nCALL", "G0 X1650"),
    ("G54\nCALL\nG56\nG0 X800", "G0 X-740"),
    # ... and a position of the main program after the call not judged as a machine position
    # (in a condition: #1 reads 0 in rs274, X-1100 runs; review 79-lcnc79 F1's S50), or a G91
    # run on from where the body left the tool (S54: work 1000 + 700, machine 1400)
    ("G54\nG0 X0\nCALL\no1 if [#1 EQ 0]\nG0 X-1100\no1 endif", "G0 X600"),
    ("G54\nG0 X-700\nG55\nCALL\nG91\nG0 X700\nG90", "G0 X860"),
]

# where the caller's moves after the body are judged too (calls81, check/resumed.rs), the same
# overtravel is said at the caller's own move as well: S54's G91 X700 from where the body left the
# tool (G55 work 860) is work 1560, machine 1460 (rs274: STRAIGHT_TRAVERSE(1560) under G55)
ALSO_AT = {"G54\nG0 X-700\nG55\nCALL\nG91\nG0 X700\nG90": [("TG601", 7)]}


@pytest.mark.parametrize("main, body", KEPT)
def test_a_later_body_keeps_the_span_where_a_position_is_not_judged(tmp_path, main, body):
    for text in forms(main, body):
        assert [(r, n) for r, n, _ in errors(text)] == \
            [("TG601", first_line(main))] + ALSO_AT.get(main, []), text
        assert "PROGRAM_END" in rs274_output(tmp_path, text)


def test_the_m98_forms_body_is_named_by_its_o_number() -> None:
    text = forms("G55\nG0 X0 Y0\nCALL", "G0 X-700")[0]
    [(_, _, message)] = errors(text)
    assert "(O300 runs as called by M98 P300 of line 4:" in message


def test_the_mains_own_position_after_the_call_joins_the_span_set_aside(tmp_path) -> None:
    # X-700 under G54, then G55 and the call; the main's X900 after it runs under the offset
    # the body may have changed (not judged): the span from -700, as the call joined it before
    # (review 79-lcnc79; rs274 with the profile's G55 runs it at 800, beyond)
    for text in forms("G54\nG0 X-700\nG55\nCALL\nG0 X900", "G0 X0"):
        assert [(r, n) for r, n, _ in errors(text)] == [("TG601", 6)], text
        assert "PROGRAM_END" in rs274_output(tmp_path, text)
