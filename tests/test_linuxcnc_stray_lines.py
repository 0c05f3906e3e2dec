"""LinuxCNC: lines after a FANUC-style program's M99, and TG412's words for an O word of an
expression (issue 32, lcnc80; review 79-lcnc79 N2, N4).

A FANUC-style ``O2000`` ... ``M99`` after the main program's M2 is read as an ``o2000 sub`` is
(LinuxCNC G-code reference, "M98, M99"; interp_o_word.cc ``convert_control_functions``): an
``M98 P2000`` runs its lines to its M99, and returns. A line after that M99 is neither run by
the call nor read by the main program, which stopped at its M2: TG117 names it, not a line of
the body. Each program is asserted against ``rs274 -g`` where it is installed.
"""

from __future__ import annotations

import pytest

from formats.profile import load_profile
from postproc.check import check_text

from .conftest import rs274_output


def findings(text: str, rule: str) -> list[tuple[int, str]]:
    return [(f.line, f.message) for f in check_text(text, load_profile("linuxcnc"))
            if f.rule == rule]


# (the program, the line TG117 names): rs274 runs the body's X1 and nothing after its M99
STRAY = [
    ("G21 G90\nM98 P2000\nM2\nO2000\nG0 X1\nM99\nG0 X2\n", 7),
    # ... another program after it: its O line is read (an M98 may seek it), its body too
    ("G21 G90\nM98 P2000\nM2\nO2000\nG0 X1\nM99\nG0 X2\nO3000\nG0 X3\nM99\n", 7),
    # the o-word form's twin: as before
    ("G21 G90\no2000 call\nM2\no2000 sub\nG0 X1\no2000 endsub\nG0 X2\n", 7),
]


@pytest.mark.parametrize(("text", "line"), STRAY)
def test_tg117_names_the_line_after_the_m99_not_the_body(tmp_path, text: str, line: int) -> None:
    # (main named line 5, the body's G0 X1, which rs274 runs at the call)
    assert [n for n, _ in findings(text, "TG117")] == [line], text
    out = rs274_output(tmp_path, text)
    assert "STRAIGHT_TRAVERSE(1.0000" in out and "PROGRAM_END" in out, out
    assert "STRAIGHT_TRAVERSE(2.0000" not in out and "STRAIGHT_TRAVERSE(3.0000" not in out, out


def test_a_body_without_stray_lines_has_no_tg117() -> None:
    assert findings("G21 G90\nM98 P2000\nM2\nO2000\nG0 X1\nM99\n", "TG117") == []


@pytest.mark.parametrize(("word", "said"), [
    ("O103", "a bare O number is"),
    ("O[103]", "an O word alone on its line (O[103], whose whole value"),
    ("O#1", "an O word alone on its line (O#1,"),
    ("O-103", "an O word alone on its line (O-103,"),
    ("O103.0", "an O word alone on its line (O103.0,"),
])
def test_tg412_says_what_the_o_word_is(tmp_path, word: str, said: str) -> None:
    text = f"o<m> sub\n{word}\nG0 X1\no<m> endsub\nM2\n"
    [(line, message)] = findings(text, "TG412")
    assert line == 2 and f"Nested subroutine definition (rs274ngc): {said}" in message, message
    assert "Nested subroutine definition" in rs274_output(tmp_path, text)
