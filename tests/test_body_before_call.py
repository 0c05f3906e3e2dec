"""A subprogram read apart judged at its calls under their work offset, and a program's own
G54-G59 after calls of programs written later (review 61a F7, F6, F2, F13).

A FANUC runs a subprogram under the work offset in force at its call: G54-G59 are modal and
M98/G65 change none (0i-MF Operator's Manual, "Subprogram call (M98)"). A program read apart
(written before its call, or after the main) that starts with no offset in force keeps its
absolute positions for its calls, which judge them under theirs. The profile is a FANUC mill
whose G55 is X-100 (X travel -762..762).
"""

from __future__ import annotations

import pytest

from formats.parser import parse_text
from formats.profile import load_profile
from postproc.check import Checker
from tests.test_goto_passages import _wo2


def said(programs: str, profile: str) -> list[tuple[str, int, int, str]]:
    """The errors of `%` / `programs` / `%` (line 1 is the `%`), each message's start."""
    text = "%\n" + programs.replace(" / ", "\n") + "\n%\n"
    prof = load_profile(profile)
    found = Checker(prof, "<input>").run(parse_text(text, prof.dialect, errors="collect"))
    return [(f.rule, f.line, f.column, f.message.split(", outside")[0])
            for f in found if f.severity == "error"]


@pytest.mark.parametrize("programs, expected", [
    # (z6: O4000, read apart after O1000 lost the offsets at its call of O3000 written
    # later, called by O3000, which runs under O1000's G55 with X written -200: -980)
    ("O1000 / G10 L2 P2 X-200. / G55 / M98 P3000 / M30 / O4000 / G0 X-780. / M99 / "
     "O3000 / M98 P4000 / M99",
     [("TG601", 11, 5, "X goes to -980 in machine coordinates (work -780 + G55 offset -200 as "
                       "a G10 before this call wrote it)")]),
    # (z8: the G10 writes X0.: -700, inside)
    ("O1000 / G10 L2 P2 X0. / G55 / M98 P3000 / M30 / O4000 / G0 X-700. / M99 / "
     "O3000 / M98 P4000 / M99 / O2000 / M99", []),
    # (z9c: no G10, O3000's own G55: -880)
    ("O1000 / G21 G90 G55 / M98 P3000 / M30 / O4000 / G0 X-780. / M99 / O3000 / G55 / "
     "M98 P4000 / M99",
     [("TG601", 11, 5, "X goes to -880 in machine coordinates (work -780 + G55 offset -100.0)")]),
    # (w2c, F6: the file's first program, called by the main under G55)
    ("O2000 / G0 X-700. / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / M98 P2000 / M30",
     [("TG601", 8, 5, "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)")]),
    # (the same called under G54: inside)
    ("O2000 / G0 X-700. / M99 / O1000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P2000 / M30", []),
    # (g8, F2: after a program that left a G52 on, called by a later program under G55)
    ("O1000 / G21 G17 G90 G55 / G0 X0 Y0 / G52 X10. / M30 / O2000 / G0 X-700. / M99 / "
     "O3000 / G21 G90 G55 / M98 P2000 / M30",
     [("TG601", 12, 5, "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)")]),
    # (called under a G52 of the caller's: not judged, g7)
    ("O1000 / G21 G17 G90 G55 / G0 X0 Y0 / G52 X10. / M30 / O2000 / G0 X-700. / M99 / "
     "O3000 / G21 G90 G55 / G52 X-100. / M98 P2000 / M30", []),
    # (the caller's excursion beyond that side runs on into it: one finding, b40e)
    ("O2000 / G0 X-710. / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / G0 X-700. / "
     "M98 P2000 / M30",
     [("TG601", 8, 4, "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)")]),
    # (the body's own G54 before its move: its own, judged where read as before)
    ("O2000 / G54 / G0 X-700. / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / M98 P2000 / M30",
     []),
    # (the body's own G52, G10 or G92 before the move: not its caller's offset's, not judged)
    ("O2000 / G52 X50. / G0 X-700. / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / M98 P2000 / "
     "M30", []),
    ("O2000 / G10 L2 P2 X0. / G0 X-700. / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / "
     "M98 P2000 / M30", []),
    ("O2000 / #5221=0. / G0 X-700. / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / "
     "M98 P2000 / M30", []),
    # (a G66 runs it at later moves, b4e; `M98 P2000 Q10` enters it at N10, q3)
    ("O2000 / G0 X-700. / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / G66 P2000 / G54 / "
     "G0 X10. / G67 / M30", []),
    ("O2000 / G0 X-700. / N10 G0 X0 / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / "
     "M98 P2000 Q10 / M30", []),
    # (a caller under G43: its Z not judged; its X is)
    ("O2000 / G0 X-700. Z-515. / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / G43 H1 Z0 / "
     "M98 P2000 / M30",
     [("TG601", 9, 5, "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)")]),
])
def test_a_body_read_with_no_offset_runs_under_its_call_s(tmp_path, programs, expected):
    """Review 61a F7 (z6: OLD's "-880" ignored the G10, main said nothing), F6 (w2c) and F2
    (g8): a program read apart with no work offset in force at its start was not compared
    ("where the program has selected no work offset") and nothing was kept for its calls."""
    assert said(programs, _wo2(tmp_path)) == expected


@pytest.mark.parametrize("programs, expected", [
    # (f62c: O2000's own G54 after its G65 of O4000, written later and writing no offset)
    ("O2000 / G65 P4000 I2. / G90 G54 / G0 X850. / M99 / O4000 / M99 / O1000 / "
     "G90 G0 X-650. / M98 P2000 / M30",
     [("TG601", 11, 5, "X goes to 850 in machine coordinates (work 850 + G54 offset 0.0)")]),
    # (f62a: with a G52 at its end: said where read, as without the G65)
    ("O2000 / G65 P4000 I2. / G90 G54 / G0 X850. / G52 X-100. / M99 / O4000 / M99 / O1000 / "
     "G90 G0 X-650. / M98 P2000 / M30",
     [("TG601", 5, 4, "X goes to 850 in machine coordinates (work 850 + G54 offset 0.0)")]),
    # (O4000 writes G54's X: judged with its value, -150: inside)
    ("O2000 / G65 P4000 I2. / G90 G54 / G0 X850. / M99 / O4000 / G10 L2 P1 X-150. / M99 / "
     "O1000 / G90 G0 X-650. / M98 P2000 / M30", []),
    # (O4000 leaves a G52 on, or writes a value not known: not known, held)
    ("O2000 / G65 P4000 I2. / G90 G54 / G0 X850. / M99 / O4000 / G52 X-100. / M99 / "
     "O1000 / G90 G0 X-650. / M98 P2000 / M30", []),
    ("O2000 / G65 P4000 I2. / G90 G54 / G0 X850. / M99 / O4000 / G10 L2 P1 X#1 / M99 / "
     "O1000 / G90 G0 X-650. / M98 P2000 / M30", []),
    # (O9810 not in the file, a probing macro that may set G54: not known)
    ("O1000 / G21 G90 G54 / G65 P9810 Z-10. / G90 G54 / G0 X850. / M30", []),
    # (e1: the main's G55 after its call of O100, written later, which writes X-200: -900)
    ("O1000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P100 / G90 G55 / M98 P2000 / M30 / O100 / "
     "G10 L2 P2 X-200. / M99 / O2000 / G0 X-700. / M99",
     [("TG601", 13, 4, "X goes to -900 in machine coordinates (work -700 + G55 offset -200 as "
                       "a G10 before this call wrote it)")]),
    # (e3c: O100 writes none: -800)
    ("O1000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P100 / G90 G55 / G0 X-700. / M30 / O100 / "
     "M99",
     [("TG601", 7, 4, "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)")]),
])
def test_a_program_s_own_offset_after_a_call_of_a_later_program(tmp_path, programs, expected):
    """Review 61a F13: after a G65/M98 of a program written later, the caller's own G54-G59
    selects an offset only a G10 of that program could change: its positions are judged,
    held to the file's end, said where that program writes none (f62c: OLD said a span only
    through a G52 leak, main nothing)."""
    assert said(programs, _wo2(tmp_path)) == expected


@pytest.mark.parametrize("programs, expected", [
    # (O2000 leaves G52 X-1000. on: the main's X800. after the call is at -200, its span
    # from -750 to -200 fits; read unshifted it was a false "X spans 1550")
    ("O2000 / G52 X-1000. / M99 / O1000 / G21 G90 G54 / G0 X-750. / M98 P2000 / G90 / "
     "G0 X800. / M30", []),
    # (G52 X10.: the span is 1560, to 810)
    ("O2000 / G52 X10. / M99 / O1000 / G21 G90 G54 / G0 X-750. / M98 P2000 / G90 / "
     "G0 X800. / M30",
     [("TG601", 10, 4, "X spans 1560 (from -750 to 810), more than the travel -762 to 762: "
                       "no work offset fits the program on this machine")]),
    # (carried through a program that calls it)
    ("O2000 / G52 X-1000. / M99 / O3000 / M98 P2000 / M99 / O1000 / G21 G90 G54 / "
     "G0 X-750. / M98 P3000 / G90 / G0 X800. / M30", []),
    # (a G52 a condition may pass over: not surely known, read unshifted as before)
    ("O2000 / IF [#1 EQ 1] GOTO 5 / G52 X-1000. / N5 M99 / O1000 / G21 G90 G54 / "
     "G0 X-750. / M98 P2000 / G90 / G0 X800. / M30",
     [("TG601", 11, 4, "X spans 1550 (from -750 to 800), more than the travel -762 to 762: "
                       "no work offset fits the program on this machine")]),
    # (no G52 in the body: the call keeps the offsets since calls76, so X800. is judged as
    # a machine position under G54 (0): beyond the travel, said in place of the span)
    ("O2000 / G0 X0 / M99 / O1000 / G21 G90 G54 / G0 X-750. / M98 P2000 / G90 / "
     "G0 X800. / M30",
     [("TG601", 10, 4, "X goes to 800 in machine coordinates (work 800 + G54 offset 0.0)")]),
])
def test_a_g52_a_called_program_leaves_on_is_its_caller_s_after_the_call(tmp_path, programs,
                                                                          expected):
    """Lead's root of review 61a F7/F13: a FANUC's local coordinate system (G52) stays in
    force until cancelled, through M99 (0i-MF Operator's Manual, "Local coordinate
    system"): a program read before its call that surely leaves one on gives it to its
    caller, whose spans after the call are in its coordinates."""
    assert said(programs, _wo2(tmp_path)) == expected


_SPAN_1550 = [("TG601", None, 4, "X spans 1550 (from -750 to 800), more than the travel -762 "
                                  "to 762: no work offset fits the program on this machine")]


@pytest.mark.parametrize("call", [
    # (g70: a condition may pass over the call)
    "IF [#1 EQ 1] GOTO 5 / M98 P2000 / N5 G90",
    # (g71: a loop that may run no time)
    "#1=0 / WHILE [#1 LT #2] DO1 / M98 P2000 / #1=#1+1 / END1 / G90",
    # (g76: a modal call with no move under it: O2000 never runs)
    "G66 P2000 / G67 / G90",
    # (g77b: M98 P.. Q10 enters O2000 at its N10, after the G52)
    "M98 P2000 Q10 / G90",
    # (g74: a block the skip switch may pass over)
    "/M98 P2000 / G90",
])
def test_a_g52_is_not_carried_from_a_call_that_may_not_run_from_its_start(tmp_path, call):
    """Review 62a F7: the G52 a called program leaves is carried only where the call surely
    runs and enters the body at its start; elsewhere the caller's spans read on unshifted,
    erring on the side of the alarm, as before the carry (where the call is passed over,
    X800. runs at 800: the span 1550 is true)."""
    programs = ("O2000 / G52 X-1000. / N10 M99 / O1000 / G21 G90 G54 / G0 X-750. / "
                f"{call} / G0 X800. / M30")
    line = 2 + programs.count(" / ") - 1
    assert said(programs, _wo2(tmp_path)) == [
        (rule, line, column, message) for rule, _, column, message in _SPAN_1550]
    # (the call surely run from its start: carried, the span fits)
    programs = ("O2000 / G52 X-1000. / N10 M99 / O1000 / G21 G90 G54 / G0 X-750. / "
                "M98 P2000 / G90 / G0 X800. / M30")
    assert said(programs, _wo2(tmp_path)) == []


@pytest.mark.parametrize("programs, expected", [
    # (review 60 F3, v1: G55's X set by its variable with no G10 before: not known)
    ("O1000 / G90 G55 G0 X-700. / M99 / O2000 / G21 G17 G90 G54 / G0 X0 Y0 / #5241=0. / "
     "G90 G55 / M98 P1000 / M30", []),
    ("O1000 / G21 G17 G90 G55 / #5241=0. / G0 X-700. / M30", []),
    # (G54's X set: G55 still the profile's)
    ("O1000 / G21 G17 G90 G55 / #5221=0. / G0 X-700. / M30",
     [("TG601", 5, 4, "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)")]),
    # (the main's own G52 after its call of a body written after it: the body runs at the
    # call, under none)
    ("O1000 / G21 G17 G90 G55 / G0 X0 Y0 / M98 P2000 / G52 X100. / M30 / O2000 / G0 X-700. / "
     "M99",
     [("TG601", 9, 4, "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)")]),
    # (fz558: a G52 a later call's program leaves on, not the earlier call's)
    ("O3000 / G52 X100. / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / M98 P2000 / G65 P3000 / "
     "G55 / M30 / O2000 / G0 X-700. / G90 / M99",
     [("TG601", 13, 4, "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)")]),
])
def test_offsets_set_by_variables_guessed_offsets_and_shifts_after_the_end(tmp_path, programs,
                                                                           expected):
    """Review 60 F3: a work offset's system variable (FANUC Custom Macro B, #5221 + 20 a
    system) sets an axis of that offset, whichever: not followed, the offset's axes not
    known, G10 before or not. A body written after the main runs under the shift at its
    calls, not the main's end's."""
    assert said(programs, _wo2(tmp_path)) == expected


def _wo2h(tmp_path):
    """A Haas mill in inches whose G55 is X-4 (X travel -30..30)."""
    profile = tmp_path / "wo2h.toml"
    profile.write_text('name = "wo2h"\nbase = "haas-mill"\n[limits]\n'
                       "X = [-30.0, 30.0]\nY = [-16.0, 16.0]\nZ = [-20.0, 0.4]\n"
                       "[work_offsets]\nG54 = { X = 0.0, Y = 0.0, Z = 0.0 }\n"
                       "G55 = { X = -4.0, Y = 0.0, Z = 0.0 }\n")
    return str(profile)


_BODY = " / O2000 / G0 X-27. / M99"
_MINUS_31 = "X goes to -31 in machine coordinates (work -27 + G55 offset -4.0)"


@pytest.mark.parametrize("programs, expected", [
    # (h82: O3000 read apart, merged at its own G20 after its call of O2000, returns: the
    # call was made in its caller's millimetres, -27 mm is inside; it was kept as made in
    # the profile's inches, "-31")
    ("O3000 / G90 G55 / M98 P2000 / G20 / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / "
     "M98 P3000 / M30" + _BODY, []),
    # (h83: merged at its own G52)
    ("O3000 / G90 G55 / M98 P2000 / G52 X0.5 / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / "
     "M98 P3000 / M30" + _BODY, []),
    # (h80: merged at the G52 a call of O4000 carries)
    ("O4000 / G52 X0.5 / M99 / O3000 / G90 G55 / M98 P2000 / M98 P4000 / M99 / O1000 / "
     "G21 G17 G90 G55 / G0 X0 Y0 / M98 P3000 / M30" + _BODY, []),
    # (merged the same way but ending as a main (M30): its call made in the reset units,
    # inches: -31)
    ("O3000 / G90 G55 / M98 P2000 / G20 / M30" + _BODY,
     [("TG601", 8, 4, _MINUS_31)]),
    # (its own G20 before the call: the call's units known)
    ("O3000 / G90 G55 / G20 / M98 P2000 / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / "
     "M98 P3000 / M30" + _BODY,
     [("TG601", 13, 4, _MINUS_31)]),
])
def test_a_call_in_units_only_assumed_is_settled_at_its_program_s_end(tmp_path, programs,
                                                                      expected):
    """Review 62a F12: a program read apart before its units code keeps its calls (made in
    units only assumed) to its end, not to a merge before it: where it returns (M99) they
    were made in its caller's units, not known here; where it ends as a main, in the reset
    state's."""
    assert said(programs, _wo2h(tmp_path)) == expected


@pytest.mark.parametrize("body, expected", [
    # (g80: O2000's G52 X-1000. runs in the caller's millimetres: X800. at -200 mm, the span
    # from -750 mm fits; it was carried as -1000 inches, "X spans 938.976378")
    ("G52 X-1000.", []),
    # (G52 X10.: X800. at 810 mm, 31.889764 in)
    ("G52 X10.", [("TG601", 10, 4, "X spans 61.417323 (from -29.527559 to 31.889764), more "
                                   "than the travel -30 to 30: no work offset fits the "
                                   "program on this machine")]),
    # (the body's own G21 before it: millimetres surely, the same)
    ("G21 / G52 X10.", [("TG601", 11, 4, "X spans 61.417323 (from -29.527559 to 31.889764), "
                                         "more than the travel -30 to 30: no work offset fits "
                                         "the program on this machine")]),
])
def test_a_carried_g52_is_in_its_caller_s_units(tmp_path, body, expected):
    """Review 62a F9: a G52 a body read before any units code of its own leaves on runs in
    its caller's units: carried by the caller's factor to the profile's units, not the one
    the body was read in (an inch profile, a G21 caller)."""
    programs = (f"O2000 / {body} / M99 / O1000 / G21 G90 G54 / G0 X-750. / M98 P2000 / "
                "G90 / G0 X800. / M30")
    assert said(programs, _wo2h(tmp_path)) == expected


@pytest.mark.parametrize("programs, expected", [
    # (g61: O3000 read apart with no offset calls O2000, which leaves a G52 on: merged
    # there, its X-780. before the call was no longer judged at its call under G55)
    ("O2000 / G52 X10. / M99 / O3000 / G0 X-780. / M98 P2000 / M99 / O1000 / "
     "G21 G17 G90 G55 / G0 X0 Y0 / M98 P3000 / M30",
     [("TG601", 12, 5, "X goes to -880 in machine coordinates (work -780 + G55 offset -100.0)")]),
    # (its own G52 after the move: the same)
    ("O3000 / G0 X-700. / G52 X10. / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / M98 P3000 / "
     "M30",
     [("TG601", 9, 5, "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)")]),
    # (called under G54: -700, inside)
    ("O3000 / G0 X-700. / G52 X10. / M99 / O1000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P3000 / "
     "M30", []),
    # (called in inches: not the units it was read in, not judged; under a G52: not judged)
    ("O3000 / G0 X-700. / G52 X10. / M99 / O1000 / G20 G17 G90 G55 / G0 X0 Y0 / M98 P3000 / "
     "M30", []),
    ("O3000 / G0 X-700. / G52 X10. / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / G52 X5. / "
     "M98 P3000 / M30", []),
])
def test_a_body_merged_by_a_g52_keeps_its_positions_before_it_for_its_calls(tmp_path, programs,
                                                                            expected):
    """Review 62a F8: a program read apart with no work offset in force, merged by a G52
    (its own, or one a call of a program read before carries), keeps the positions it read
    before it for its later calls, judged there under their offset as a returned body's."""
    assert said(programs, _wo2(tmp_path)) == expected


@pytest.mark.parametrize("programs, expected", [
    # (g75: `M98 P2000 L0` may run O2000 no time: its G52 not carried, X800. may run at 800)
    ("O2000 / G52 X-1000. / M99 / O1000 / G21 G90 G54 / G0 X-750. / M98 P2000 L0 / G90 / "
     "G0 X800. / M30", [(r, 10, c, m) for r, _, c, m in _SPAN_1550]),
    # (review 63 F3: the L0 call still a call; the later one under G54 judged: -780 is
    # beyond the travel whichever runs, said at the first)
    ("O2000 / G0 X-780. / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / M98 P2000 L0 / G54 / "
     "M98 P2000 / M30",
     [("TG601", 8, 5, "X goes to -880 in machine coordinates (work -780 + G55 offset -100.0)"),
      # (the L0 call keeps the offsets since calls76: the G54 call's -780 said too)
      ("TG601", 10, 5, "X goes to -780 in machine coordinates (work -780 + G54 offset 0.0)")]),
])
def test_a_call_repeated_zero_times_carries_no_g52(tmp_path, programs, expected):
    """Review 62a F7's g75: `M98 P.. L0` (a repeat count of zero, which may run the body no
    time; no page at hand says) carries no G52 into its caller; it is a call otherwise, as
    before (review 63 F3, F6, F7: taking it as no call lost real errors)."""
    assert said(programs, _wo2(tmp_path)) == expected


@pytest.mark.parametrize("programs, expected", [
    # (y2: O4000, uncalled, read under the G55 O1000 left; its own G55, then a G10 merging
    # it: its X-700. under the guess was said, "-800")
    ("O1000 / G21 G17 G90 G55 / G0 X0 Y0 / M30 / O4000 / G0 X-700. / G55 / "
     "G10 L2 P2 X-100. / M99", []),
    # (y1: its G54 then G55)
    ("O1000 / G21 G17 G90 G55 / G0 X0 Y0 / G10 L2 P1 X100. / M30 / O4000 / G0 X-700. / G54 / "
     "G55 / G10 L2 P2 X-100. / M99", []),
    # (the fuzzer's 1986: O4000 called under that G55 by O2000 written after it: its -820
    # is true, said)
    ("O1000 / G21 G17 G90 G55 / G0 X0 Y0 / G0 X-700. / G10 L2 P2 X0. / M30 / O4000 / "
     "G0 X-720. / G54 / G10 L2 P1 X0. / G52 X-100. / M99 / O2000 / G0 X-700. / G55 / G90 / "
     "M98 P4000 L2 / M99",
     [("TG601", 5, 4, "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)"),
      ("TG601", 9, 4, "X goes to -820 in machine coordinates (work -720 + G55 offset -100.0)")]),
])
def test_a_merged_program_s_guessed_positions_are_said_where_it_is_called(tmp_path, programs,
                                                                         expected):
    """Review 61a F5's second form: a program read under the offset the program before it
    left (a guess), merged after its own G54-G59, keeps its findings under the guess to the
    file's end: said where a call in the file names it, dropped where none does."""
    assert said(programs, _wo2(tmp_path)) == expected


def test_a_caller_s_own_position_judged_with_a_later_program_s_g10_names_no_call(tmp_path):
    """Review 62a F13 (o18c): the caller's own X-700. after its call of O4000, written later,
    whose G10 writes G55's X-200: "as a G10 before it wrote it", line 7 being no call."""
    programs = ("O1000 / G21 G17 G90 G55 / G0 X0 Y0 / M98 P4000 / G90 G55 / G0 X-700. / M30 / "
                "O4000 / G10 L2 P2 X-200. / M99")
    assert said(programs, _wo2(tmp_path)) == [
        ("TG601", 7, 4, "X goes to -900 in machine coordinates (work -700 + G55 offset -200 as "
                        "a G10 before it wrote it)")]


@pytest.mark.parametrize("programs, expected", [
    # (review 60 F4, q6: O1000 sets its own units, so it is read as a run of its own; its
    # only call follows a G10 that writes G55's X0.: X-700. runs at -700, inside; it was
    # "X goes to -800" with the profile's value)
    ("O1000 / G21 G90 G55 G0 X-700. / M99 / O2000 / G21 G17 G90 G54 / G0 X0 Y0 / "
     "G10 L2 P2 X0. / G90 G55 / M98 P1000 / M30", []),
    # (q2: in inches)
    ("O1000 / G20 G90 G55 G0 X-29.5 / M99 / O2000 / G20 G17 G90 G54 / G0 X0 Y0 / "
     "G10 L2 P2 X0. / G90 G55 / M98 P1000 / M30", []),
    # (q1: the G10 in a program written later, called before)
    ("O1000 / G20 G90 G55 G0 X-29.5 / M99 / O2000 / G20 G17 G90 G54 / G0 X0 Y0 / M98 P100 / "
     "G90 G55 / M98 P1000 / M30 / O100 / G10 L2 P2 X0. / M99", []),
    # (the G10 writes X-200.: -900, said with that value where read)
    ("O1000 / G21 / G90 G55 G0 X-700. / M99 / O2000 / G21 G17 G90 G54 / G0 X0 Y0 / "
     "G10 L2 P2 X-200. / G90 G55 / M98 P1000 / M30",
     [("TG601", 4, 12, "X goes to -900 in machine coordinates (work -700 + G55 offset -200 as "
                       "a G10 before its call wrote it)")]),
    # (no G10: the profile's value, -800, as before)
    ("O1000 / G21 G90 G55 G0 X-700. / M99 / O2000 / G21 G17 G90 G54 / G0 X0 Y0 / G90 G55 / "
     "M98 P1000 / M30",
     [("TG601", 3, 16, "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)")]),
    # (ending as a main, M30: as read, as before)
    ("O1000 / G21 G90 G55 G0 X-700. / M30 / O2000 / G21 G17 G90 G54 / G0 X0 Y0 / "
     "G10 L2 P2 X0. / G90 G55 / M98 P1000 / M30",
     [("TG601", 3, 16, "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)")]),
])
def test_a_subprogram_with_its_own_units_is_judged_with_its_calls_g10(tmp_path, programs,
                                                                      expected):
    """Review 60 F4: a subprogram read apart whose own units code merges it (read as a run
    of its own), ending with M99, has its positions under its own G54-G59 judged again at
    the file's end with the value a G10 of its callers' run wrote before every call."""
    assert said(programs, _wo2(tmp_path)) == expected


@pytest.mark.parametrize("programs, expected", [
    # (review 63 F1: O3000 merged at its own G21 after its call of O2000, returns; called by
    # a G21 main on a metric profile: the call was made in the millimetres assumed, -880)
    ("O3000 / G90 G55 / M98 P2000 / G21 / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / "
     "M98 P3000 / M30 / O2000 / G0 X-780. / M99",
     [("TG601", 13, 4, "X goes to -880 in machine coordinates (work -780 + G55 offset -100.0)")]),
    # (review 63 F2: a second main, M30, merged by its G10 after its own G55: a main's
    # finding under the guess, said as before)
    ("O1000 / G21 G17 G90 G55 / G0 X0 / M30 / O2000 / G0 X-800. / G55 / G10 L2 P2 X-100. / "
     "M30",
     [("TG601", 7, 4, "X goes to -900 in machine coordinates (work -800 + G55 offset -100.0)")]),
    # (review 63 F4: its own G54 after the held position: said as read, as before)
    ("O1000 / G21 / G90 G55 G0 X-700. / G54 / G0 X-780. / M99 / O2000 / G21 G17 G90 G54 / "
     "G0 X0 Y0 / G10 L2 P2 X0. / G90 G55 / M98 P1000 / M30",
     [("TG601", 4, 12, "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)")]),
])
def test_review_63_s_regressions(tmp_path, programs, expected):
    """Review 63 F1, F2, F4: real errors the first forms of these fixes lost."""
    assert said(programs, _wo2(tmp_path)) == expected


@pytest.mark.parametrize("programs, expected", [
    # (review 63 F8: the body's last G52 of X, read after its own G21, is in millimetres
    # whatever its G52 before the G21: X800. runs at -200, the span from -750 fits; it was
    # "X spans 1550")
    ("O2000 / G52 X0 / G21 / G52 X-1000. / M99 / O1000 / G21 G90 G54 / G0 X-750. / "
     "M98 P2000 / G90 / G0 X800. / M30", []),
    ("O2000 / G52 X-1000. / G21 / G52 X-1000. / M99 / O1000 / G21 G90 G54 / G0 X-750. / "
     "M98 P2000 / G90 / G0 X800. / M30", []),
    # (a G52 of another axis before the G21)
    ("O2000 / G52 Y0 / G21 / G52 X-1000. / M99 / O1000 / G21 G90 G54 / G0 X-750. / "
     "M98 P2000 / G90 / G0 X800. / M30", []),
    # (G52 X10. last: X800. at 810, the span 1560 said with its true figure)
    ("O2000 / G52 X-1000. / G21 / G52 X10. / M99 / O1000 / G21 G90 G54 / G0 X-750. / "
     "M98 P2000 / G90 / G0 X800. / M30",
     [("TG601", 12, 4, "X spans 1560 (from -750 to 810), more than the travel -762 to 762: "
                       "no work offset fits the program on this machine")]),
    # (review 63 F9: a G52 carried through two calls, the inner body in its own inches:
    # G52 X1. is 25.4 mm once, X29. runs at 762, the span from -749.3 fits; it was scaled
    # twice, "X spans 2131.06")
    ("O2000 / G20 / G52 X1. / M99 / O3000 / M98 P2000 / M99 / O1000 / G20 G90 G54 / "
     "G0 X-29.5 / M98 P3000 / G90 / G0 X29. / M30", []),
    ("O2000 / G21 / G52 X25.4 / M99 / O3000 / M98 P2000 / M99 / O1000 / G20 G90 G54 / "
     "G0 X-29.5 / M98 P3000 / G20 / G90 / G0 X29. / M30", []),
    # (X30. at 787.4: the span 1536.7, said)
    ("O2000 / G20 / G52 X1. / M99 / O3000 / M98 P2000 / M99 / O1000 / G20 G90 G54 / "
     "G0 X-29.5 / M98 P3000 / G90 / G0 X30. / M30",
     [("TG601", 14, 4, "X spans 1536.7 (from -749.3 to 787.4), more than the travel -762 to "
                       "762: no work offset fits the program on this machine")]),
])
def test_a_carried_g52_s_units_are_its_last_g52_s_of_each_axis(tmp_path, programs, expected):
    """Review 63 F8, F9: what a body leaves is each axis's last G52, in the units that one was
    read in (the body's own, exact, or its caller's where only assumed); a G52 carried from a
    body's own units stays exact through a caller with none of its own."""
    assert said(programs, _wo2(tmp_path)) == expected


_CALLER = "O1000 / G21 G90 G54 / G0 X-750. / M98 P2000 / G90 / G0 X800.{more} / M30 / O2000 / "


def _spans(least, most, width):
    return f"X spans {width} (from {least} to {most}), more than the travel -762 to 762: " \
           "no work offset fits the program on this machine"


@pytest.mark.parametrize("more, body, expected", [
    # (g52l: the body, written after its call, leaves G52 X-1000.: X800. runs at -200, the
    # span from -750 fits; it was "X spans 1550")
    ("", "G52 X-1000. / M99", []),
    # (g52p: it leaves G52 X10.: X800. runs at 810, the span 1560 with its true figure)
    ("", "G52 X10. / M99", [("TG601", 7, 4, _spans(-750, 810, 1560))]),
    # (both ends after the call: -200 and -1800, named by the later)
    (" / G0 X-800.", "G52 X-1000. / M99", [("TG601", 8, 4, _spans(-1800, -200, 1600))]),
    # (a body that leaves no G52: as read)
    ("", "G0 X10. / M99", [("TG601", 7, 4, _spans(-750, 800, 1550))]),
    # (a G52 of a value not known, or one a program it calls later may end: as read,
    # erring on the side of the alarm, as for a body read before its call)
    ("", "G52 X#1 / M99", [("TG601", 7, 4, _spans(-750, 800, 1550))]),
    ("", "G52 X-1000. / M98 P3000 / M99 / O3000 / G52 X0 / M99",
     [("TG601", 7, 4, _spans(-750, 800, 1550))]),
    # (review 75 F7: a body that leaves inches too: X800. is 20,320 mm, as read)
    ("", "G20 / G52 X-40. / M99", [("TG601", 7, 4, _spans(-750, 800, 1550))]),
])
def test_a_g52_a_body_written_after_its_call_leaves(tmp_path, more, body, expected):
    """Review 63-unit63 F10 (g52l, g52p): the caller's spans after a call of a program not
    read there kept apart from those before, the span across the call judged at the file's
    end with the G52 that program leaves where it is known."""
    assert said(_CALLER.format(more=more) + body, _wo2(tmp_path)) == expected


@pytest.mark.parametrize("caller, expected", [
    # (review 62a F6b, p31: O4000 runs X-780. under the G55 O1000 calls O3000 under: -880)
    ("G21 G17 G90 G55 / G0 X0 Y0", [("TG601", 11, 5, "X goes to -880 in machine coordinates "
                                     "(work -780 + G55 offset -100.0)")]),
    ("G21 G17 G90 G55 / G0 X0 Y0 / G10 L2 P2 X0.",
     [("TG601", 12, 5, "X goes to -780 in machine coordinates (work -780 + G55 offset 0 as a "
                       "G10 before this call wrote it)")]),
])
def test_a_body_read_with_no_offset_called_by_another_two_deep(tmp_path, caller, expected):
    """Review 62a F6b: a body read before its call with no work offset in force, called by
    a program read apart with none in force either, runs under that one's caller's."""
    programs = f"O4000 / G0 X-780. / M99 / O3000 / M98 P4000 / M99 / O1000 / {caller} / " \
               "M98 P3000 / M30"
    assert said(programs, _wo2(tmp_path)) == expected
    # (a G52 of the middle program's before the call: not judged)
    shifted = programs.replace("O3000 / M98", "O3000 / G52 X10. / M98")
    assert said(shifted, _wo2(tmp_path)) == []
