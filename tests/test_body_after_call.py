"""A subprogram written after its call, run under the state of the call (review 61a).

Review 59a F12 made a body written after the main's M30 run under the work offset in force at
its call (`O1000` / `G90 G55` / `M98 P2000` / `M30` / `O2000` / `G0 X-700.` / `M99`: X-800,
said). Review 61a found what the call's state must carry besides the offset: the tool length
offset (F1), a G66 that makes no call at its own block (F9), the caller's excursion (F3).
The profile is a FANUC mill whose G55 is X-100 (X travel -762..762, Z -508..10).
"""

from __future__ import annotations

import pytest

from tests.test_goto_passages import _wo2, said

MAIN = "G21 G17 G90 G55 / G0 X0 Y0 / "


@pytest.mark.parametrize("blocks, expected", [
    # (b27m: the usual FANUC layout, the tool length in the main, Z moves in the body)
    ("G43 H1 Z0 / M98 P2000 / M30 / O2000 / G0 Z-515. / M99", []),
    # (f1a: G44; f1d: G65; f1e: a body called from the body; f1f: a canned cycle's Z)
    ("G44 H1 Z0 / M98 P2000 / M30 / O2000 / G0 Z-515. / M99", []),
    ("G43 H1 Z0 / G65 P2000 / M30 / O2000 / G0 Z-515. / M99", []),
    ("G43 H1 Z0 / M98 P2000 / M30 / O2000 / M98 P3000 / M99 / O3000 / G0 Z-515. / M99", []),
    ("G43 H1 Z0 / G0 X0 / M98 P2000 / M30 / O2000 / G81 X-10. Z-515. R2. F100. / G80 / M99",
     []),
    # (b27o: the span of the Z positions, which holds whatever the tool length, as before)
    ("G43 H1 Z50. / M98 P2000 / G49 / M30 / O2000 / G0 Z-515. / M99",
     [("TG601", 10, 4, "Z spans 565 (from -515 to 50), more than the travel -508 to 10: no "
                       "work offset fits the program on this machine")]),
    # (f1c: the body's own G49: its Z judged)
    ("G43 H1 Z0 / M98 P2000 / M30 / O2000 / G49 / G0 Z-515. / M99",
     [("TG601", 10, 4, "Z goes to -515 in machine coordinates (work -515 + G55 offset 0.0)")]),
    # (no tool length at the call: judged, as flow60 made it)
    ("M98 P2000 / M30 / O2000 / G0 Z-515. / M99",
     [("TG601", 8, 4, "Z goes to -515 in machine coordinates (work -515 + G55 offset 0.0)")]),
    # (the body's X still judged under the call's G55 with the tool length on)
    ("G43 H1 Z0 / M98 P2000 / M30 / O2000 / G0 X-700. Z-515. / M99",
     [("TG601", 9, 4, "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)")]),
    # (two calls, one under G43 and one under G49: not known which, its Z not judged)
    ("G43 H1 Z0 / M98 P2000 / G49 / M98 P2000 / M30 / O2000 / G0 X-700. Z-515. / M99", []),
])
def test_a_body_written_after_its_call_runs_under_the_call_s_tool_length(tmp_path, blocks,
                                                                           expected):
    """Review 61a F1: G43/G44 are modal and M98/G65 change none (0i-MF Operator's Manual,
    "Tool length offset", "Subprogram call (M98)"): a body written after its call runs under
    the tool length offset in force there, and its Z, as the same body's inline, is not
    compared with the travel (the profile gives no tool lengths). It was "Z goes to -515",
    the body read in the reset state's G49."""
    assert said(MAIN + blocks, _wo2(tmp_path)) == expected


@pytest.mark.parametrize("blocks", [
    # (b4d: the one move the macro runs after is under G54: X-700, inside)
    "G66 P2000 / G54 / G0 X10. / G67 / M30 / O2000 / G0 X-700. / M99",
    # (b4b: no move between G66 and G67: the macro never runs)
    "G66 P2000 / G67 / M30 / O2000 / G0 X-700. / M99",
    # (b4: run after a move under G55: -800, but not judged: the offset at the moves is not
    # followed)
    "G66 P2000 / G0 X0 / G67 / M30 / O2000 / G0 X-700. / M99",
    # (an M98 of the same program under G55 as well: the G66's offset not known, not judged)
    "M98 P2000 / G66 P2000 / G54 / G0 X10. / G67 / M30 / O2000 / G0 X-700. / M99",
])
def test_a_g66_is_no_call_at_its_own_block(tmp_path, blocks):
    """Review 61a F9: a G66 registers its macro, run after each later block with a move until
    G67 (0i-MF Operator's Manual, "Modal call: G66"), under the offset in force at that move,
    not the G66 block's: a body written after it is not read under the G66 block's offset
    (it was "X goes to -800" under G55 where the control runs it under G54, or not at all)."""
    assert said(MAIN + blocks, _wo2(tmp_path)) == []


@pytest.mark.parametrize("blocks, expected", [
    # (b40: the call at X-800, the body's first move at X-810: one excursion)
    ("G0 X-700. / M98 P2000 / M30 / O2000 / G0 X-710. / M99",
     [("TG601", 5, 4, "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)")]),
    # (the body back inside, then out again: a second excursion, said)
    ("G0 X-700. / M98 P2000 / M30 / O2000 / G0 X0 / G0 X-710. / M99",
     [("TG601", 5, 4, "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)"),
      ("TG601", 10, 4, "X goes to -810 in machine coordinates (work -710 + G55 offset -100.0)")]),
    # (the call inside: the body's first position outside said, as before)
    ("M98 P2000 / M30 / O2000 / G0 X-710. / M99",
     [("TG601", 8, 4, "X goes to -810 in machine coordinates (work -710 + G55 offset -100.0)")]),
])
def test_an_excursion_runs_from_the_call_into_a_body_written_after_it(tmp_path, blocks,
                                                                       expected):
    """Review 61a F3: a position beyond the travel at the call, and the body's first move
    still beyond it on the same side, are one excursion, said once, as the same program
    inline (it was said twice: the body began inside)."""
    assert said(MAIN + blocks, _wo2(tmp_path)) == expected


@pytest.mark.parametrize("program, expected", [
    # (x687: O3000 called only by O2000, read apart, under no offset known; O1000's G55
    # left at its M30 is not O3000's)
    ("M98 P3000 / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / G10 L2 P1 X-200. / M30 / "
     "O3000 / G0 X-760. / M99", []),
    # (x687b: the same without the G10)
    ("M98 P3000 / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / M30 / O3000 / G0 X-760. / M99",
     []),
    # (a call under G55 known, in the main: judged, as flow60 made it)
    ("G21 G17 G90 G55 / G0 X0 Y0 / M98 P3000 / M30 / O3000 / G0 X-760. / M99",
     [("TG601", 8, 4, "X goes to -860 in machine coordinates (work -760 + G55 offset -100.0)")]),
])
def test_a_body_called_where_the_offset_is_not_known_runs_under_none(tmp_path, program,
                                                                     expected):
    """Review 61a F5: a program written after its calls, one of them made where the work
    offset was not known (in a program read apart, which nothing in the file selects an
    offset for), runs under no offset the checker knows: not the one the program before it
    in the file left at its M30 (it was "X goes to -860" under O1000's G55)."""
    assert said(program, _wo2(tmp_path)) == expected


@pytest.mark.parametrize("blocks, expected", [
    # (j2: the G10 an `M99 P5` passes over never runs: X-600. at -700, inside)
    ("G21 G17 G90 G55 / G0 X0 Y0 / M99 P5 / G10 L2 P2 X-200. / N5 G0 X-600. / M30", []),
    # (b72: the G55 it passes over never runs: O2000 runs under G54, not judged)
    ("G21 G17 G90 G54 / G0 X0 Y0 / M99 P10 / G55 / N10 M98 P2000 / M30 / O2000 / G0 X-700. / "
     "M99", []),
    # (the G10 before the M99 P: followed, as flow60 made it)
    ("G21 G17 G90 G55 / G0 X0 Y0 / G10 L2 P2 X-200. / G0 X-600. / M99 P5 / N5 M30",
     [("TG601", 6, 4, "X goes to -800 in machine coordinates (work -600 + G55 offset -200 as "
                      "a G10 before wrote it)")]),
])
def test_a_main_s_m99_p_is_a_jump(tmp_path, blocks, expected):
    """Review 61a F10: a main program's `M99 P5` goes to its block N5 (0i-MF Operator's
    Manual, "Subprogram call (M98)": M99 in the main program), passing over what lies
    between: a G10 there writes no value known, a call after it is not read under the offset
    in force in file order (they were followed: "X goes to -800")."""
    assert said(blocks, _wo2(tmp_path)) == expected


def test_a_caller_read_apart_in_units_assumed_gives_its_body_no_offset(tmp_path):
    """Review 61a F11 (hu1): O2000, read apart before the main, selects G54 and calls O3000,
    written after; O1000 (G21) calls O2000, so O3000's X-600. runs in millimetres, 23.6 in,
    inside a Haas's inch travel. O2000's units are only assumed where its call is read: O3000
    is not judged under its offset as a machine position in inches (it was "X goes to -600 in
    machine coordinates"); the span's finding with its units caveat, as before."""
    profile = tmp_path / "wo2h.toml"
    profile.write_text('name = "wo-haas"\nbase = "haas-mill"\n[limits]\n'
                       "X = [-30.0, 30.0]\nY = [-16.0, 16.0]\nZ = [-20.0, 0.5]\n"
                       "[work_offsets]\nG54 = { X = 0.0, Y = 0.0, Z = 0.0 }\n"
                       "G55 = { X = -4.0, Y = 0.0, Z = 0.0 }\n")
    found = said("G54 / M98 P3000 / M99 / O01000 / G21 G17 G90 G55 / G0 X0 Y0 / M98 P2000 / "
                 "M30 / O03000 / G0 X-600. / M99", str(profile))
    assert [f[:3] for f in found] == [("TG601", 12, 4)]
    assert found[0][3].startswith("X spans 600 (from -600 to 0), more than the travel")


def test_a_call_entering_its_body_at_a_sequence_number_gives_it_no_offset(tmp_path):
    """Review 61a F12 (q1): `M98 P2000 Q10` enters O2000 at its N10 (0i-F Operator's Manual,
    "Subprogram call (M98)"): its `G0 X-700.` before N10 never runs, and is not judged under
    the call's G55 (it was "X goes to -800"); the same call without Q judges it."""
    body = " / M30 / O2000 / G0 X-700. / N10 G0 X0 / M99"
    assert said(MAIN + "M98 P2000 Q10" + body, _wo2(tmp_path)) == []
    assert said(MAIN + "M98 P2000" + body, _wo2(tmp_path)) == [
        ("TG601", 8, 4, "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)")]
