"""What a program written after its call leaves its caller after the return, not followed
where the caller's own G54-G59 after that call, or a body read apart judged at its call, is
compared with the travel (review 62a F1-F5 of the paths of review 61a F13 and F7).

A FANUC's work offset system variables (#5221-#5326: Custom Macro B, "System variables"),
its tool length offset (G43/G44), its units (G20/G21) stay in force after M99, an `M99 Pn`
returns to the caller's block Nn and M30 ends the program (0i-MF Operator's Manual,
"Subprogram call (M98)"): a later program that does any of these makes the caller's
positions after the call not known, held (not said) rather than judged with a wrong state.
The profile is a FANUC mill whose G55 is X-100 (X travel -762..762, Z -508..10).
"""

from __future__ import annotations

import pytest

from tests.test_body_before_call import said
from tests.test_goto_passages import _wo2

_SAID_850 = [("TG601", 7, 4, "X goes to 850 in machine coordinates (work 850 + G54 offset 0.0)")]


@pytest.mark.parametrize("later, expected", [
    # (a program that leaves nothing: said, as before)
    ("M99", _SAID_850),
    # (F1, o31: a work offset's variable written, by number or by expression)
    ("#[5221]=-150. / M99", []),
    ("#5221=-150. / M99", []),
    ("#1=5221 / #[#1]=-150. / M99", []),
    # (F1, o37 form: through a call of a program that writes one)
    ("M98 P5000 / M99 / O5000 / #5221=-150. / M99", []),
    # (a variable that is no offset's: said)
    ("#100=-150. / M99", _SAID_850),
    # (F3, o43 reversed: the caller's own units written again, nothing changed: said)
    ("G21 / M99", _SAID_850),
    # (G43 cancelled before its return: said)
    ("G43 H1 Z0 / G49 / M99", _SAID_850),
    # (F4, o44, o25: a return elsewhere, an end: the blocks after the call do not run)
    ("M99 P10", []),
    ("M30", []),
])
def test_a_later_program_s_effects_after_its_return(tmp_path, later, expected):
    """Review 62a F1, F4: `O1000` / `G21 G17 G90 G55` / `G0 X0 Y0` / `M98 P4000` / `G90 G54`
    / `G0 X850.` / `M30` / `O4000` / ...: flow62 said X850. at 850 whatever O4000 did."""
    programs = ("O1000 / G21 G17 G90 G55 / G0 X0 Y0 / M98 P4000 / G90 G54 / G0 X850. / "
                "N10 M30 / O4000 / " + later)
    assert said(programs, _wo2(tmp_path)) == expected


@pytest.mark.parametrize("programs, expected", [
    # (F1, o52: the caller's own variable write after the call; its G10 is followed, o50)
    ("O1000 / G21 G17 G90 G55 / G0 X0 Y0 / M98 P4000 / #5221=-150. / G90 G54 / G0 X850. / "
     "M30 / O4000 / M99", []),
    # (F2, o39b: O4000 leaves G43 on, the profile gives no tool lengths: Z not known)
    ("O1000 / G21 G17 G90 G55 / G0 X0 Y0 Z0 / M98 P4000 / G90 G54 / G0 Z-515. / M30 / "
     "O4000 / G43 H1 / M99", []),
    # (without it: said)
    ("O1000 / G21 G17 G90 G55 / G0 X0 Y0 Z0 / M98 P4000 / G90 G54 / G0 Z-515. / M30 / "
     "O4000 / M99",
     [("TG601", 7, 4, "Z goes to -515 in machine coordinates (work -515 + G54 offset 0.0)")]),
    # (F2, o16: the same in a body written before the main, judged at its call)
    ("O2000 / G65 P4000 / G90 G54 / G0 Z-515. / M99 / O4000 / G43 H1 / M99 / O1000 / "
     "G90 G0 X-650. / M98 P2000 / M30", []),
    # (F3, o43: a G20 caller, O4000 writes G21: X31. is 31 mm, not 787.4)
    ("O1000 / G20 G17 G90 G55 / G0 X0 Y0 / M98 P4000 / G90 G54 / G0 X31. / M30 / O4000 / "
     "G21 / M99", []),
    # (F1, o5: a body before the main, O4000 writes G54's X by its variable)
    ("O2000 / G65 P4000 / G90 G54 / G0 X850. / M99 / O4000 / #5221=100. / M99 / O1000 / "
     "G90 G0 X-650. / M98 P2000 / M30", []),
    # (F1, p60: the caller writes G55's X by its variable before the call of a body read
    # apart with no offset: X-700. runs at -700, not -800)
    ("O2000 / G0 X-700. / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / #5241=0. / "
     "M98 P2000 / M30", []),
    # (F5, o61: a body judged at a call after the caller's own G54 following a call of a
    # program not in the file, a probing macro that may set G54: held as the caller's own)
    ("O2000 / G0 X850. / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / G65 P9810 Z-10. / "
     "G90 G54 / M98 P2000 / M30", []),
])
def test_positions_after_a_later_call_held(tmp_path, programs, expected):
    """Review 62a F1, F2, F3, F5: each a false error of flow62 (OLD said nothing)."""
    assert said(programs, _wo2(tmp_path)) == expected


@pytest.mark.parametrize("write, moves, expected", [
    # (sv4: G55's X written, its Y still the profile's: Y-420. said)
    ("#5241=0.", "G90 G55 / G0 Y-420.",
     [("TG601", 7, 4, "Y goes to -420 in machine coordinates (work -420 + G55 offset 0.0)")]),
    # (a value not known: X alone not known, Y still said)
    ("#5241=#500", "G90 G55 / G0 Y-420.",
     [("TG601", 7, 4, "Y goes to -420 in machine coordinates (work -420 + G55 offset 0.0)")]),
    ("#5241=#500", "G90 G55 / G0 X-700.", []),
    # (sv10: a number written is followed as G10 L2 P2 X-150. is: -870)
    ("#5241=-150.", "G0 X-720.",
     [("TG601", 6, 4, "X goes to -870 in machine coordinates (work -720 + G55 offset -150 as "
                      "a G10 before wrote it)")]),
    # (#5242 is G55's Y: X still the profile's -100)
    ("#5242=-150.", "G0 X-720.",
     [("TG601", 6, 4, "X goes to -820 in machine coordinates (work -720 + G55 offset -100.0)")]),
    # (an index not known, the external offset: every axis not known, as before)
    ("#[5241+#1]=0.", "G90 G55 / G0 Y-420.", []),
    ("#5201=0.", "G90 G55 / G0 Y-420.", []),
])
def test_a_work_offset_variable_writes_its_own_axis(tmp_path, write, moves, expected):
    """Review 62a F10 (sv4, sv10): `#5241=` made every axis of G55 not known, and a number
    written was taken as not known. #5221 + 20 * (n - 1) + (axis - 1) is G54-G59's axis in
    the control's order (FANUC Custom Macro B, "System variables"), a mill's X, Y, Z."""
    program = f"O1000 / G21 G17 G90 G55 / G0 X0 Y0 / {write} / {moves} / M30"
    assert said(program, _wo2(tmp_path)) == expected


def test_a_work_offset_variable_write_starts_the_span_again(tmp_path):
    """Review 62a F10 (sv13): X850. under G55 runs at 750, then `#5241=150.` moves G55 and
    X-700. runs at -550; the span -700..850 is no span of one offset (was said: 1550)."""
    program = "O1000 / G21 G17 G90 G55 / G0 X0 Y0 / G0 X850. / #5241=150. / G0 X-700. / M30"
    assert said(program, _wo2(tmp_path)) == []
