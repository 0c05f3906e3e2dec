"""The blocks a sure Custom Macro B jump passes over, and the errors the passage must keep.

Review 53 found that an earlier attempt to pass over more blocks (numbered ones that nothing
had named yet) lost real errors. These programs pin the errors the checker finds today: each
is a run the control makes (FANUC Custom Macro B, "Branch and repetition": a `GOTO n` goes to
the block N n; `M99 P n` returns to the caller's block N n), out of fanuc-mill's X travel of
-762..762 (1524 mm), and none may be lost to a passage.
"""

from __future__ import annotations

import pytest

from formats.parser import parse_text
from formats.profile import load_profile
from postproc.check import Checker


def errors(blocks: str, profile: str = "fanuc-mill") -> list[tuple[str, int, int]]:
    """The errors of `%` / O1000 / `blocks` / `%` (lines 1-2 are `%` and O1000)."""
    text = "%\nO1000\n" + blocks.replace(" / ", "\n") + "\n%\n"
    prof = load_profile(profile)
    found = Checker(prof, "<input>").run(parse_text(text, prof.dialect, errors="collect"))
    return [(f.rule, f.line, f.column) for f in found if f.severity == "error"]


HEAD = "G21 G17 G90 G54 / "

# review 53, F1 (g1r.nc): pass 1 takes the IF to N10 (#1=0); the jump back to N1 runs it
# again with #1=1, the IF falls through and N5's X900. runs from X-700: a 1600 mm span.
G1R = HEAD + ("G0 X-700. Y0 Z1. / #1=0 / N1 IF [#1 EQ 0] GOTO 10 / N5 G0 X900. / "
              "N10 #1=#1+1 / IF [#1 LT 2] GOTO 1 / M30")
# review 53, F4 (g5.nc): O2000's `M99 P5` returns to O1000's N5, passed over by `GOTO 10`.
G5 = HEAD + ("G0 X-700. Y0 Z10. / GOTO 10 / N5 G0 X900. / M30 / N10 G0 X1. / M98 P2000 / "
             "M30 / O2000 / G0 Z5. / M99 P5")
# review 53, F19 (x1342.nc): where #5=1, N42, G91, X300., X900. and N59 X600. are 1800 mm
# of increments in a row, more than the whole travel.
X1342 = HEAD + ("#1=0 / G0 X0 Y0 Z10. / IF [#5 EQ 1] GOTO 42 / N9 #1=0 / GOTO 59 / "
                "G0 X850. / N29 IF [#5 EQ 1] GOTO 42 / N42 #1=1 / G91 / "
                "IF [#1 EQ 0] GOTO 59 / G0 X300. / G0 X900. / N59 G0 X600. / G91 / M30")
# review 53, F19 (x1202.nc): where #5 is not 1, the sure `GOTO 34` lands in G90 and N34's
# follows X850.: a 1550 mm span (the error is said at a block the checker judges
# in file order, line 10).
# the same as F4 with an external-device call: `M198 P2000` runs a subprogram that may
# `M99 P5` back into N5 (FANUC: M198 is the CNC's own call, like M98)
G5_M198 = HEAD + ("G0 X-700. Y0 Z10. / GOTO 10 / N5 G0 X900. / M30 / N10 G0 X1. / "
                  "M198 P2000 / M30")
X1202 = HEAD + ("#1=0 / G0 X0 Y0 Z10. / G0 X850. / IF [#5 EQ 1] GOTO 30 / N26 GOTO 34 / "
                "G0 X900. / G0 X-700. / N29 G0 X-700. / N30 G91 / G0 X-700. / G91 / "
                "N34 G0 X-700. / N37 G0 X0. / M30")


@pytest.mark.parametrize("program, expected", [
    (G1R, [("TG601", 7, 7)]),
    (G5, [("TG601", 6, 7)]),
    (G5_M198, [("TG601", 6, 7)]),
    (X1342, [("TG601", 16, 8)]),
    (X1202, [("TG601", 10, 4)]),
])
def test_a_run_out_of_travel_is_kept(program, expected):
    """Review 53's F1, F4 and F19: a passed-over block that another way runs, or a run of
    increments only one way in makes, is still judged: the TG601 stays."""
    assert errors(program) == expected


def test_a_sure_goto_after_a_joined_block_finds_no_false_span():
    """Review 53, F18 (y3.nc): `G0 X900.` follows a sure `GOTO 53` and has no N, so no run
    reaches it (X-700 -> N54, or X-700 -> N52 X0 -> N53 -> N54): no TG601."""
    y3 = HEAD + ("G0 X-700. Y0 Z10. / IF [#5 EQ 1] GOTO 52 / GOTO 54 / N52 G0 X0. / "
                 "GOTO 53 / G0 X900. / N53 G0 X0 / N54 G0 X1. / M30")
    assert errors(y3) == []


# Review 55b (F1, F2): an earlier attempt at conditional passages lost the TG401 of o6/o7/o12/
# o14 and made a false TG601 of q5b/q5d. FANUC: no F word is ever read before the G1, so the
# feed is zero there on every run (alarm PS0011, 0i-MF operator's manual, alarm list).
O6_HEAD = HEAD + "#1=0 / G0 X0 Y0 Z10. / "


@pytest.mark.parametrize("program, expected", [
    # o6.nc: a known-true IF, a call after: the G1 X3. has no feed on any run
    (O6_HEAD + "IF [#1 EQ 0] GOTO 10 / G0 Y1. / N10 G0 X0 / G1 X3. / M98 P2000 / M30",
     [("TG401", 9, 4)]),
    # o7.nc: the block passed over is itself a feed move
    (O6_HEAD + "IF [#1 EQ 0] GOTO 10 / G1 X10. / N10 G0 X0 / G1 X3. / M98 P2000 / M30",
     [("TG401", 9, 4)]),
    # o12.nc: a macro call (G65) in place of the M98
    (O6_HEAD + "IF [#1 EQ 0] GOTO 10 / G0 Y1. / N10 G0 X0 / G1 X3. / G65 P9000 / M30",
     [("TG401", 9, 4)]),
    # o14.nc: a counted loop with its test at the top; the first pass through N45 alarms
    (O6_HEAD + "#1=1 / N37 IF [#1 EQ 1] GOTO 45 / G0 Y1. / N45 G1 X6. / #1=#1+1 / "
     "IF [#1 LT 3] GOTO 37 / M30", [("TG401", 9, 8)]),
    # q5b.nc: the IF is taken, the G0 X600. and the G91 never run: X 0..600, no TG601
    (O6_HEAD + "IF [#1 EQ 0] GOTO 8 / G0 X600. / G91 / N8 G0 X600. / G0 X600. / "
     "M98 P2000 / M30 / O2000 / M99", []),
    # q5d.nc: the same with a macro call of a program not in the file
    (O6_HEAD + "IF [#1 EQ 0] GOTO 8 / G0 X600. / G91 / N8 G0 X600. / G0 X600. / "
     "G65 P9100 A1. / M30", []),
])
def test_a_known_true_jump_keeps_its_errors_and_finds_no_false_one(program, expected):
    """Review 55b's F1 and F2 classes: a known-true `IF [..] GOTO` followed by a call or a
    jump back keeps the TG401 the control alarms on, and judges no block it passes over."""
    assert errors(program) == expected


@pytest.mark.parametrize("program, expected", [
    # review 55b, F4 (r3b.nc): O2000 after the main's M30, which nothing in the file calls:
    # its X-700. is not in one span with the main's X850.
    (O6_HEAD + "G0 X850. / M30 / O2000 / G0 X-700. / M99", []),
    # q7.nc: the same after a sure GOTO over a numbered block
    (O6_HEAD + "GOTO 34 / N16 G91 / N34 G0 X850. / M30 / O2000 / G0 X-700. / M99", []),
    # its own span wider than the travel, from its own G90 on: said, where it grows past it
    (O6_HEAD + "G0 X850. / M30 / O2000 / G90 G0 X-700. / G0 X100. / G0 X850. / M99",
     [("TG601", 11, 4)]),
    # review 56b, F10: with no G90/G91 of its own it runs in its caller's mode, not known:
    # under G91 these are increments (-700, +800, +750: 800 mm), no span to judge
    (O6_HEAD + "G0 X850. / M30 / O2000 / G0 X-700. / G0 X100. / G0 X850. / M99", []),
    # ab1.nc: its positions are known from its own G90 on (X850. alone)
    (O6_HEAD + "G0 X0 / M30 / O2000 / G0 X-700. / G90 G0 X850. / M99", []),
    (O6_HEAD + "G0 X0 / M30 / O2000 / G0 X-700. / G90 G0 X850. / G0 X-700. / M99",
     [("TG601", 11, 4)]),
    # called by the main before its end: judged from its caller's spans, as before
    (O6_HEAD + "G0 X850. / M98 P2000 / M30 / O2000 / G0 X-700. / M99", [("TG601", 10, 4)]),
    # called by a later program of the file: judged at that call
    (O6_HEAD + "G0 X850. / M30 / O2000 / G0 X-700. / M99 / O3000 / M98 P2000 / M30",
     [("TG601", 12, 5)]),
    # a run of increments wider than the travel is its own: said
    (O6_HEAD + "G0 X850. / M30 / O2000 / G91 G0 X-800. / G0 X-800. / M99",
     [("TG601", 10, 4)]),
])
def test_a_program_no_call_names_after_the_end_has_its_own_span(program, expected):
    """Review 55b, F4: the span of a subprogram after M30 that no call of the file names is
    its own (a FANUC's M30 ends the main program and goes back to its head; whoever calls
    the subprogram is not known, nor the work offset it runs under); where the file calls it,
    it is judged from its caller's state as before."""
    assert errors(program) == expected


@pytest.mark.parametrize("program, expected", [
    # review 53, F5's class: #1 is 0, the IF never jumps; the sure GOTO 44 passes X850.
    (O6_HEAD + "IF [#1 EQ 1] GOTO 44 / GOTO 44 / G0 X850. / N44 G0 X-700. / M30", []),
    # the IF known true: both ways to N44 pass X850.
    (O6_HEAD + "IF [#1 EQ 0] GOTO 44 / GOTO 44 / G0 X850. / N44 G0 X-700. / M30", []),
    # known false, no sure GOTO: X850. runs, then N44
    (O6_HEAD + "IF [#1 EQ 1] GOTO 44 / G0 X850. / N44 G0 X-700. / M30", [("TG601", 8, 8)]),
    # a jump back that makes it true on a second pass: the first pass still runs X850.
    (O6_HEAD + "N1 IF [#1 EQ 1] GOTO 44 / G0 X850. / N44 G0 X-700. / #1=1 / GOTO 1 / M30",
     [("TG601", 8, 8)]),
    # inside a WHILE loop, the values at the IF are not known: judged as before
    (O6_HEAD + "WHILE [#1 LT 2] DO1 / IF [#1 EQ 1] GOTO 44 / G0 X850. / N44 G0 X-700. / "
     "#1=#1+1 / END1 / M30", [("TG601", 9, 8)]),
])
def test_an_if_known_false_is_no_way_into_its_target(program, expected):
    """Review 53, F5: an `IF [..] GOTO n` whose condition the values known make false does
    not jump (FANUC Custom Macro B: the branch is taken only where the condition holds), so
    it does not make N n a block other ways arrive at; errors of the fall-through stay."""
    assert errors(program) == expected


# review 56b's reproducers: the main's blocks before an uncalled-looking O2000
MAIN = HEAD + "G0 X850. Y0 Z10. / "
AT_ZERO = HEAD + "G0 X0 Y0 Z10. / "


@pytest.mark.parametrize("program, expected", [
    # F1 (u3.nc, u4.nc): a FANUC without the 8-digit option reads P12000 and P0012000 as
    # O2000 once; fanuc-mill assumes the option, so the file's O2000 may still be the one run
    (MAIN + "M98 P12000 / M30 / O2000 / G0 X-700. / M99", [("TG601", 8, 4)]),
    (MAIN + "M98 P0012000 / M30 / O2000 / G0 X-700. / M99", [("TG601", 8, 4)]),
    # u8.nc: M198 from an external device may run the file's O2000
    (MAIN + "M198 P2000 / M30 / O2000 / G0 X-700. / M99", [("TG601", 8, 4)]),
    # F2 (k2.nc, k1.nc): O9001 and O9020 are run by an M code through parameters
    (MAIN + "M06 T1 / M30 / O9001 / G0 X-700. / M99", [("TG601", 8, 4)]),
    (MAIN + "M50 / M30 / O9020 / G0 X-700. / M99", [("TG601", 8, 4)]),
    # F4 (y1.nc, y3.nc, y11.nc): an uncalled O2000 that calls O3000, written after it: X goes
    # to -700 and then, in O3000, to 850 under whatever offset runs it
    (AT_ZERO + "M30 / O2000 / G0 X-700. / M98 P3000 / M99 / O3000 / G0 X850. / M99",
     [("TG601", 7, 4)]),
    (AT_ZERO + "M30 / O2000 / G0 X-700. / G65 P3000 / M99 / O3000 / G0 X850. / M99",
     [("TG601", 7, 4)]),
    (AT_ZERO + "M30 / O2000 / G0 X-700. / M98 P3000 L2 / M99 / O3000 / G0 X850. / M99",
     [("TG601", 7, 4)]),
    # y12.nc: a G66 modal call, and the same with G66.1
    (AT_ZERO + "M30 / O2000 / G0 X-700. / G66 P3000 / G0 X-690. / G67 / M99 / O3000 / "
     "G0 X850. / M99", [("TG601", 7, 4)]),
    (AT_ZERO + "M30 / O2000 / G0 X-700. / G66.1 P3000 / G0 X-690. / G67 / M99 / O3000 / "
     "G0 X850. / M99", [("TG601", 13, 4)]),
    # y13.nc: the call first, a G90 of its own after it
    (AT_ZERO + "M30 / O2000 / M98 P3000 / G90 G0 X-700. / M99 / O3000 / G90 G0 X850. / M99",
     [("TG601", 8, 8)]),
    # y10.nc: the same programs as a memory backup, `%` between them
    (AT_ZERO + "M30 / % / % / O2000 / G0 X-700. / M98 P3000 / M99 / % / % / O3000 / "
     "G0 X850. / M99", [("TG601", 9, 4)]),
    # review 56e, F1 (k3.nc): the uncalled O2000's M06 may run the file's O9001 (parameter
    # 6071): X -700 in O2000, then 850 in O9001
    (AT_ZERO + "M30 / O2000 / G0 X-700. / M06 T1 / M99 / O9001 / G0 X850. / M99",
     [("TG601", 11, 4)]),
    # F5 (r4.nc): G65 P5000 runs a program stored on the control, which may call O2000
    ("G21 G17 G90 G54 / G0 X850. Y0 Z10. / G65 P5000 / M30 / O2000 / G0 X-700. / M99",
     [("TG601", 8, 4)]),
    # F4 (m9.nc, m14.nc): the main's only end is one the block skip passes over; with the
    # switch on it runs on into O2000
    (MAIN + "/M30 / O2000 / G0 X-700. / M99", [("TG601", 7, 4)]),
    (MAIN + "/M99 / O2000 / G0 X-700. / M99", [("TG601", 7, 4)]),
])
def test_an_uncalled_program_is_joined_where_alone_could_lose_an_error(program, expected):
    """Review 56b, F1, F2, F4: a subprogram no call of the file names is judged on its own
    span only where that loses no overtravel: one that calls a program, one a call may name
    under another program-number option or from an external device, and an O9000-O9999 the
    control runs for an M, G or T code keep their span joined to the file's, as before; so do
    all of a file that holds an O9000-O9999 or calls a program it does not hold, and one after
    an end the block skip passes over (review 56e, F1, F4, F5)."""
    assert errors(program) == expected


@pytest.mark.parametrize("program, expected", [
    # review 56e, F2 (e1.nc): O3000, called by nothing, runs O2000 (written before it): X goes
    # to -700 under whatever offset runs O3000, never with the main's X850.
    (MAIN + "M30 / O2000 / G0 X-700. / M99 / O3000 / M98 P2000 / M99", []),
    # its own span, callee and all: X-700. at the call, then its own X850.
    (MAIN + "M30 / O2000 / G0 X-700. / M99 / O3000 / M98 P2000 / G0 X850. / M99",
     [("TG601", 11, 4)]),
    # review 56b, F4 in the other order (y2.nc): O3000's X850. and O2000's X-700. in one run
    (AT_ZERO + "M30 / O3000 / G0 X850. / M99 / O2000 / G0 X-700. / M98 P3000 / M99",
     [("TG601", 11, 5)]),
])
def test_an_uncalled_caller_is_judged_with_its_callees_alone(program, expected):
    """Review 56e, F2: a program no call names that calls programs written before it is
    judged on its own span, which holds its callees' positions from each call, not joined to
    the main program's; review 56b F4's run through both programs stays an error."""
    assert errors(program) == expected


def test_an_uncalled_program_says_one_overtravel_once(tmp_path):
    """Review 56b, F3 (x1.nc-x3.nc): under a known G54 offset, the machine position's TG601
    is the one said; the span it made wider than the travel is not said again."""
    profile = tmp_path / "wo.toml"
    profile.write_text('name = "wo-mill"\nbase = "fanuc-mill"\n[limits]\n'
                       "X = [-762.0, 762.0]\nY = [-406.0, 406.0]\nZ = [-508.0, 10.0]\n"
                       "[work_offsets]\nG54 = { X = 0.0, Y = 0.0, Z = 0.0 }\n")
    head = AT_ZERO + "M30 / O2000 / "
    assert errors(head + "G54 G0 X-800. / G0 X750. / M99", str(profile)) == [("TG601", 7, 8)]
    assert errors(head + "G54 G0 X750. / G0 X-800. / M99", str(profile)) == [("TG601", 8, 4)]
    # review 56e, F6: with no G54-G59 of its own, the offset it runs under is its caller's,
    # not the G54 the main left: no machine position is known, and its span (its caller's
    # G90/G91, review 56b F10) is not judged either
    assert errors(head + "G0 X750. / G0 X-800. / M99", str(profile)) == []
    assert errors(head + "G90 G0 X750. / G0 X-800. / M99", str(profile)) == [("TG601", 8, 4)]


def test_an_uncalled_program_runs_under_its_caller_s_work_offset(tmp_path):
    """Review 56e, F6 (x7.nc): the main's G55 is not carried past its M30 into a program no
    call names (a FANUC's M30 ends the main program; the subprogram's M99 returns to a caller
    not in the file): X-700. is no machine position X-800 there; from its own G55 on it is."""
    profile = tmp_path / "wo2.toml"
    profile.write_text('name = "wo-mill"\nbase = "fanuc-mill"\n[limits]\n'
                       "X = [-762.0, 762.0]\nY = [-406.0, 406.0]\nZ = [-508.0, 10.0]\n"
                       "[work_offsets]\nG54 = { X = 0.0, Y = 0.0, Z = 0.0 }\n"
                       "G55 = { X = -100.0, Y = 0.0, Z = 0.0 }\n")
    head = "G21 G17 G90 G55 / G0 X0 Y0 Z-10. / M30 / O2000 / "
    assert errors(head + "G0 X-700. / M99", str(profile)) == []
    assert errors(head + "G55 G0 X-700. / M99", str(profile)) == [("TG601", 7, 8)]
    # the main itself, under its own G55: said
    assert errors("G21 G17 G90 G55 / G0 X-700. Y0 Z-10. / M30", str(profile)) == [("TG601", 4, 4)]


def test_an_uncalled_lathe_program_keeps_its_overtravel():
    """Review 56b, F1 on fanuc-lathe (ul.nc): `M98 P12000` may run the file's O2000."""
    program = ("G21 G18 G40 / G0 X100. Z800. / M98 P12000 / M30 / O2000 / G0 X50. Z-700. / "
               "M99")
    assert errors(program, "fanuc-lathe") == [("TG601", 8, 9)]


def findings(blocks: str) -> list[tuple[str, str, int, int]]:
    """The errors and warnings of `%` / O1000 / `blocks` / `%` under fanuc-mill."""
    text = "%\nO1000\n" + blocks.replace(" / ", "\n") + "\n%\n"
    prof = load_profile("fanuc-mill")
    found = Checker(prof, "<input>").run(parse_text(text, prof.dialect, errors="collect"))
    return [(f.rule, f.severity, f.line, f.column) for f in found if f.severity != "info"]


@pytest.mark.parametrize("program, expected", [
    # review 56b, F7 (t7.nc): #1 is 0, the IF does not jump: the G1 runs with no F ever given
    (O6_HEAD + "IF [#1 EQ 1] GOTO 44 / G1 X20. / N44 G0 X30. / M30",
     [("TG401", "error", 7, 4)]),
    # t5.nc: and at its target, reached by falling through
    (O6_HEAD + "IF [#1 EQ 1] GOTO 44 / G0 X10. / N44 G1 X20. / M30",
     [("TG401", "error", 8, 8)]),
    # a condition not known: the jump may be taken, the feed after it is not known
    (O6_HEAD + "IF [#5 EQ 1] GOTO 44 / G1 X20. / N44 G0 X30. / M30", []),
    # a feed given before the IF stays in force after it: no finding
    (O6_HEAD + "G1 X5. F100. / IF [#1 EQ 1] GOTO 44 / G1 X20. / N44 G0 X30. / M30", []),
    # review 56b, F8 (t1.nc): the missing N99 of a known-false IF is searched on no pass
    # with these values: a warning, TG139, not TG118's "stops here"
    (O6_HEAD + "IF [#1 EQ 1] GOTO 99 / G0 X10. / M30", [("TG139", "warning", 6, 14)]),
    # known true or not known: the control searches for N99 and alarms (PS0128)
    (O6_HEAD + "IF [#1 EQ 0] GOTO 99 / G0 X10. / M30", [("TG118", "error", 6, 14)]),
    (O6_HEAD + "IF [#5 EQ 0] GOTO 99 / G0 X10. / M30", [("TG118", "error", 6, 14)]),
    # review 57c, F1 (j6.nc): false on the first pass of a counting loop, true on the sixth,
    # which alarms on every run: a jump back to the IF's block keeps TG118
    ("#1=0 / N10 IF [#1 GE 5] GOTO 90 / G0 X[#1*10.] / #1=#1+1 / GOTO 10 / N99 G0 Z50. / M30",
     [("TG118", "error", 4, 18)]),
    # review 57c, F4 (p6.nc, p8q.nc): M99 P and M98 Q arrive at N10 with the values where
    # they stand (#1=1), not those read down to it
    ("#1=1 / M99 P10 / #1=0 / N10 IF [#1 EQ 1] GOTO 20 / M30",
     [("TG118", "error", 6, 18)]),
    ("#1=1 / M98 Q10 / #1=0 / M30 / N10 IF [#1 EQ 1] GOTO 20 / M99",
     [("TG118", "error", 7, 18)]),
])
def test_an_if_known_false_runs_on_with_all_it_knows(program, expected):
    """Review 56b, F7 and F8: an `IF [..] GOTO n` whose condition the known values make false
    runs the next block (FANUC Custom Macro B, conditional branch: where the condition is
    not satisfied, the next block is executed), so the feed and position stay known after it
    and no TG140 is said of it, and its missing target is no error on that pass."""
    assert findings(program) == expected


@pytest.mark.parametrize("program, expected", [
    # review 56b, F6 (p1.nc) / review 53, F16 (v1.nc): either way the run goes to N44, and
    # X850. runs on no path
    (AT_ZERO + "IF [#5 EQ 1] GOTO 44 / GOTO 44 / G0 X850. / N44 G0 X-700. / M30", []),
    # review 55b (e7.nc): a known parameter, and a move between the IF and the GOTO
    (O6_HEAD + "IF [#5 EQ 1] GOTO 44 / G0 X300. / GOTO 44 / G0 X850. / N44 G0 X-700. / M30",
     []),
    # kept: the fall-through runs X850. before the GOTO, then N44's X-700.
    (AT_ZERO + "IF [#5 EQ 1] GOTO 44 / G0 X850. / GOTO 44 / G0 X0 / N44 G0 X-700. / M30",
     [("TG601", 9, 8)]),
    # kept: X850. before the IF and N44's X-700. are on every path
    (AT_ZERO + "G0 X850. / IF [#5 EQ 1] GOTO 44 / GOTO 44 / G0 X0 / N44 G0 X-700. / M30",
     [("TG601", 9, 8)]),
])
def test_an_if_to_the_sure_goto_s_target_adds_no_way_between(program, expected):
    """Review 56b, F6: an IF whose target is the target of the sure `GOTO` after it arrives
    there, not in the blocks the GOTO passes over: those are not run on any path, and the
    target is reached from both (its parameters an arrival's, its position not known)."""
    assert errors(program) == expected


def test_an_uncalled_lathe_program_s_positions_are_absolute():
    """Review 56e (l6.nc) on fanuc-lathe, G code system A: no G90/G91 mode (G90 is a turning
    cycle, U and W the increments), so the caller's mode leaves X and Z absolute, and an
    uncalled program's own Z span of 1200 mm is said (review 56b, F10 is for a mill's)."""
    program = "G21 G18 G99 / G0 X100. Z200. / M30 / O2000 / G0 Z-700. / G0 Z500. / M99"
    assert errors(program, "fanuc-lathe") == [("TG601", 8, 4)]
    # W is an increment from Z-700.: Z goes to 700, 1400 mm (review 56b, l2.nc)
    program = "G21 G18 G40 / G0 X100. Z5. / M30 / O2000 / G0 X50. Z-700. / W1400. / M99"
    assert errors(program, "fanuc-lathe") == [("TG601", 8, 1)]


def test_an_uncalled_program_after_a_skippable_end_keeps_the_main_s_offset(tmp_path):
    """Review 57c, F2 (x3.nc): the main's only end is `/M30`; with the block skip switch on
    it runs on into O2000 under its own G55 (X-700. is X-800 on the machine): said."""
    profile = tmp_path / "wo2.toml"
    profile.write_text('name = "wo-mill"\nbase = "fanuc-mill"\n[limits]\n'
                       "X = [-762.0, 762.0]\nY = [-406.0, 406.0]\nZ = [-508.0, 10.0]\n"
                       "[work_offsets]\nG54 = { X = 0.0, Y = 0.0, Z = 0.0 }\n"
                       "G55 = { X = -100.0, Y = 0.0, Z = 0.0 }\n")
    head = "G21 G17 G90 G55 / G0 X0 Y0 / "
    assert errors(head + "/M30 / O2000 / G0 X-700. / M99", str(profile)) == [("TG601", 7, 4)]
    # a plain M30 ends it: the offset O2000 runs under is its caller's, not known
    assert errors(head + "M30 / O2000 / G0 X-700. / M99", str(profile)) == []


@pytest.mark.parametrize("profile", ["fanuc-lathe-b", "fanuc-lathe-c"])
def test_an_uncalled_lathe_program_of_system_b_or_c_runs_in_its_caller_s_mode(profile):
    """Review 57c, F3 (l8.nc): on G code system B or C, G90/G91 are absolute/incremental, so
    an uncalled program's Z-700. before its own G90 may be an increment (review 56b, F10):
    no 1200 mm span is judged from it."""
    program = "G21 G18 G99 / G0 X100. Z200. / M30 / O2000 / G0 Z-700. / G90 G0 Z500. / M99"
    assert errors(program, profile) == []
    # from its own G90 on, both positions absolute: judged
    program = "G21 G18 G99 / G0 X100. Z200. / M30 / O2000 / G90 G0 Z-700. / G0 Z500. / M99"
    assert errors(program, profile) == [("TG601", 8, 4)]


def test_a_subprogram_written_before_its_caller_runs_under_the_caller_s_offset(tmp_path):
    """Review 57c, F6 (v1.nc, v2.nc): O2000 follows the main's M30, and O3000, written after
    it, selects G55 and calls it: X-700. is X-800 on the machine there, past -762 (said at
    the call). Under O3000's G54 it is X-700, inside; with no call it is not known (review
    56e, F6); where O3000 selects none, its own offset is its caller's, not known either."""
    profile = tmp_path / "wo2.toml"
    profile.write_text('name = "wo-mill"\nbase = "fanuc-mill"\n[limits]\n'
                       "X = [-762.0, 762.0]\nY = [-406.0, 406.0]\nZ = [-508.0, 10.0]\n"
                       "[work_offsets]\nG54 = { X = 0.0, Y = 0.0, Z = 0.0 }\n"
                       "G55 = { X = -100.0, Y = 0.0, Z = 0.0 }\n")
    head = "G21 G17 G90 G55 / G0 X0 Y0 / M30 / O2000 / G0 X-700. / M99 / O3000 / "
    assert errors(head + "G90 G55 / G0 X0 Y0 / M98 P2000 / M99", str(profile)) == [
        ("TG601", 12, 5)]
    assert errors(head + "G90 G54 / G0 X0 Y0 / M98 P2000 / M99", str(profile)) == []
    assert errors(head + "G0 X0 Y0 / M98 P2000 / M99", str(profile)) == []
    assert errors("G21 G17 G90 G55 / G0 X0 Y0 / M30 / O2000 / G0 X-700. / M99",
                  str(profile)) == []
    # review 57e, F0 (jx1.nc): an uncalled O2000 that calls O3000 is joined to the file's span
    # for its call, but nothing of the file runs it: its X-700. under the main's G55 is not
    # said (it was "X goes to -800"); numbered O9001, an M code of the main may run it: said
    tail = "M98 P3000 / M99 / O3000 / G0 Y0 / M99"
    assert errors(head.replace("O3000 / ", "").replace("M99 / ", "") + tail,
                  str(profile)) == []
    assert errors(head.replace("O3000 / ", "").replace("M99 / ", "").replace("O2000", "O9001")
                  + tail, str(profile)) == [("TG601", 7, 4)]


@pytest.mark.parametrize("program, expected", [
    # review 57c, F5 (sh3.nc): the IF jumps to N44 or falls to the sure GOTO 44; no F on either
    (AT_ZERO + "IF [#5 EQ 1] GOTO 44 / GOTO 44 / G0 X850. / N44 G1 X-700. / M30",
     [("TG401", 8, 8)]),
    # review 55b, F3 (e4.nc): a move between the IF and the GOTO, the F100. passed over
    ("G21 G17 G90 G54 / #1=0 / G0 X0 Y0 Z10. / IF [#5 EQ 1] GOTO 44 / G0 X300. / GOTO 44 / "
     "F100. / N44 G1 X-7. / M30", [("TG401", 10, 8)]),
    # an F between the IF and the GOTO: the GOTO's way has a feed, the IF's none; not every run
    (AT_ZERO + "IF [#5 EQ 1] GOTO 44 / F100. / GOTO 44 / G0 X850. / N44 G1 X-700. / M30", []),
    # a call between: the subprogram may set a feed
    (AT_ZERO + "IF [#5 EQ 1] GOTO 44 / M98 P100 / GOTO 44 / G0 X850. / N44 G1 X-700. / M30",
     []),
    # a jump read before to a block after the target may come back with a feed first
    (AT_ZERO + "IF [#5 EQ 2] GOTO 90 / IF [#5 EQ 1] GOTO 44 / GOTO 44 / G0 X850. / "
     "N44 G1 X-700. / M30 / N90 F100. / GOTO 44", []),
])
def test_a_shared_target_keeps_no_feed_ever_set(program, expected):
    """Review 57c, F5 and review 55b, F3: where the sure `GOTO n` and every jump read before it
    name N n and no feed was ever set on the way to any of them, N n is reached with none
    (FANUC: F is modal, none at the start), so a feed move there without F is TG401."""
    assert [e for e in errors(program) if e[0] == "TG401"] == expected


@pytest.mark.parametrize("program, profile, expected", [
    # review 57c, F7 (ma1.nc): the file's only program, a looping main ending in M99, runs
    # from the reset state (G90): X -700 then 850 is 1550 mm
    ("G0 X-700. Y0 / G0 X850. / M99", "fanuc-mill", [("TG601", 4, 4)]),
    ("G17 G40 G80 / G0 X-700. Y0 / G0 X850. / M99", "fanuc-mill", [("TG601", 5, 4)]),
    # the same as a second program after a main's M30: its caller's G90/G91 not known
    ("G21 G90 G54 / G0 X0 Y0 / M30 / O2000 / G0 X-700. Y0 / G0 X850. / M99", "fanuc-mill", []),
])
def test_the_file_s_first_program_ending_in_m99_runs_from_the_reset_state(
        program, profile, expected):
    """Review 57c, F7: the caller's-mode rule (review 56b, F10) is for a program some other
    program calls; the file's first program is the one the control starts."""
    assert errors(program, profile) == expected


def test_a_subprogram_before_its_main_keeps_its_caller_s_mode():
    """Review 57c, F7's rule is for a file with no main program ending in M30: O2000 written
    before the O1000 that ends in M30 is no program the control starts, so its X-700. before
    a G90 of its own may be an increment (review 56b, F10): no span judged from it."""
    text = "%\nO2000\nG0 X-700. Y0\nG0 X850.\nM99\nO1000\nG21 G90 G54\nG0 X0 Y0\nM30\n%\n"
    prof = load_profile("fanuc-mill")
    found = Checker(prof, "<input>").run(parse_text(text, prof.dialect, errors="collect"))
    assert [(f.rule, f.line) for f in found if f.severity == "error"] == []


def _wo2(tmp_path):
    """A FANUC mill whose G55 is X-100 (X travel -762..762)."""
    profile = tmp_path / "wo2.toml"
    profile.write_text('name = "wo-mill"\nbase = "fanuc-mill"\n[limits]\n'
                       "X = [-762.0, 762.0]\nY = [-406.0, 406.0]\nZ = [-508.0, 10.0]\n"
                       "[work_offsets]\nG54 = { X = 0.0, Y = 0.0, Z = 0.0 }\n"
                       "G55 = { X = -100.0, Y = 0.0, Z = 0.0 }\n")
    return str(profile)


def test_a_call_under_an_offset_written_by_g10_is_not_judged_with_the_profile_s_value(tmp_path):
    """Review 57e, F1 (c3d.nc): O3000's `G10 L2 P2 X0.` sets G55's X to 0 before its G55 call
    of O2000, so X-700. runs at X-700, inside the travel (it was "X goes to -800", the
    finding read under the profile's G55 replayed by the offset's name). What a program the
    checker does not read may write is not followed (review 58a F1's b2.nc): said, as in a
    caller that calls none."""
    profile = _wo2(tmp_path)
    head = "G21 G17 G90 G55 / G0 X0 Y0 / M30 / O2000 / G0 X-700. / M99 / O3000 / "
    assert errors(head + "G10 L2 P2 X0. / G90 G55 / G0 X0 Y0 / M98 P2000 / M30", profile) == []
    assert errors(head + "G90 G55 / M98 P4000 / G90 G55 / M98 P2000 / M30", profile) == [
        ("TG601", 13, 5)]
    # (review 57e, c4.nc: the first call runs O2000, read, under G54; the second under G55)
    assert errors(head + "G90 G54 / M98 P2000 / G55 / M98 P2000 / M30", profile) == [
        ("TG601", 13, 5)]


def test_a_run_on_position_is_said_where_read_not_at_a_call_under_another_offset(tmp_path):
    """Review 57e, F2 (x4c.nc): with the block skip switch on, O1000 runs past `/M99` into
    O2000 under its G55 (X-700. is X-800): said at O2000's line, where that run makes it,
    not at O3000's call under G54 (X-700 there, inside) with the G55 offset as its reason."""
    program = ("G21 G17 G90 G55 / G0 X0 Y0 / /M99 / O2000 / G0 X-700. / M99 / O3000 / "
               "G90 G54 / M98 P2000 / M30")
    assert errors(program, _wo2(tmp_path)) == [("TG601", 7, 4)]
    # O3000's call under G55 runs it at X-800 too: the one overtravel said once, where read
    assert errors(program.replace("G90 G54", "G90 G55"), _wo2(tmp_path)) == [("TG601", 7, 4)]
    # its own G55 after the run-on: known whoever calls it, said at the call
    program = ("G21 G17 G90 G55 / G0 X0 Y0 / /M99 / O2000 / G0 X-600. / G55 / G0 X-700. / "
               "M99 / O3000 / G90 G54 / M98 P2000 / M30")
    assert errors(program, _wo2(tmp_path)) == [("TG601", 13, 5)]


def test_a_library_of_m99_programs_keeps_the_caller_s_mode():
    """Review 57e, F3 (m9c.nc, mb1.nc): a file of several programs each ending in M99, none a
    main, is a library for a main elsewhere: its first program's X-700. before a G90 of its
    own may be an increment (review 56b, F10), so no 1550 mm span is judged from it, as for
    the others. Where its first program calls the others, it is the program the control
    starts, from the reset state in G90 (review 57c, F7)."""
    assert errors("G0 X-700. Y0 / G0 X850. / M99 / O2000 / G0 X0 / M99") == []
    assert errors("G0 X-700. Y0 / G0 X850. / M99 / O2000 / G0 X-700. / G0 X850. / M99") == []
    assert errors("G0 X-700. Y0 / G0 X850. / M98 P2000 / M99 / O2000 / G0 Y0 / M99") == [
        ("TG601", 4, 4)]


def test_an_o9000_program_in_the_file_runs_no_uncalled_program_under_the_main_s_offset(
        tmp_path):
    """Review 57e, F0's jx3.nc: O2000's M06 may run the file's O9001, which makes O2000's span
    hold O9001's (review 56e, F1), but nothing runs O2000 under the main's G55: its X-700. is
    not said as X-800. The O9001 itself, which an M code of the main may run, keeps it."""
    profile = _wo2(tmp_path)
    head = "G21 G17 G90 G55 / G0 X0 Y0 Z-10. / M30 / "
    assert errors(head + "O2000 / G0 X-700. / M06 T1 / M99 / O9001 / G0 Y0 / M99",
                  profile) == []
    assert errors(head + "O9001 / G0 X-700. / M99", profile) == [("TG601", 7, 4)]


def test_a_body_s_own_overtravel_is_said_at_its_call_whatever_it_calls(tmp_path):
    """Review 58a, F1 (u2.nc, a13.nc, b2.nc): O2000 selects its own G55 and goes to X-700.
    (machine -800, an overtravel alarm). Its `M98 P8000` of a program the checker does not
    read comes after the move, and runs only when O2000 runs: it holds nothing of the call
    (it did, read apart in file order, for the whole file). Nor does the caller's call of
    such a program before its call of O2000: what it writes is not followed."""
    profile = _wo2(tmp_path)
    # (u2: the body after the main, called by an O3000 under G54)
    assert errors("G21 G17 G90 G54 / G0 X0 Y0 / M30 / O2000 / G90 G55 G0 X-700. / M98 P8000 / "
                  "M99 / O3000 / G90 G54 / M98 P2000 / M30", profile) == [("TG601", 12, 5)]
    # (a13: the body first, its main after it)
    assert errors("G90 G55 G0 X-700. / M98 P8000 / M99 / O2000 / G21 G17 G90 G54 / G0 X0 Y0 / "
                  "M98 P1000 / M30", profile) == [("TG601", 9, 5)]
    # (b2: the main calls a stored O8000 first)
    assert errors("G90 G55 G0 X-700. / M99 / O2000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P8000 / "
                  "M98 P1000 / M30", profile) == [("TG601", 9, 5)]


def test_a_g10_of_a_subprogram_holds_positions_only_after_its_call(tmp_path):
    """Review 58a, F1 (a8b.nc): O2500's `G10 L2 P2 X0.` writes G55's X when the main calls
    O2500, not where it is read: O1000's X-700. under its own G55 is machine -800 at a call
    before that one, and not known (not said) at a call after it."""
    profile = _wo2(tmp_path)
    head = ("G90 G55 G0 X-700. / M99 / O2500 / G10 L2 P2 X0. / M99 / O3000 / G21 G17 G90 G54 / "
            "G0 X0 Y0 / ")
    assert errors(head + "M98 P1000 / M98 P2500 / M30", profile) == [("TG601", 11, 5)]
    assert errors(head + "M98 P2500 / M98 P1000 / M30", profile) == []


@pytest.mark.parametrize("g10, expected", [
    # (c3d: G55's X written, the guess read under the profile's -100 not known)
    ("G10 L2 P2 X0.", []),
    # (a1: G54's X; a2: G55's Y; a9: a tool length offset: G55's X is still -100)
    ("G10 L2 P1 X0.", [("TG601", 13, 5)]),
    ("G10 L2 P2 Y0.", [("TG601", 13, 5)]),
    ("G10 L10 P1 R0.", [("TG601", 13, 5)]),
    # (a FANUC's L20 writes an additional offset, G54.1 P2, not G55)
    ("G10 L20 P2 X0.", [("TG601", 13, 5)]),
    # (P0, the external offset, shifts every offset; an L not known may write any)
    ("G10 L2 P0 X0.", []),
    ("G10 L#1 P2 Y0.", []),
])
def test_a_g10_holds_only_the_positions_under_the_offset_and_axis_it_writes(
        tmp_path, g10, expected):
    """Review 58a, F3: the caller O3000's G10 before its G55 call of O2000 (X-700., machine
    -800 under the profile's G55) holds that position only where it may write G55's X."""
    program = ("G21 G17 G90 G55 / G0 X0 Y0 / M30 / O2000 / G0 X-700. / M99 / O3000 / "
               f"{g10} / G90 G55 / G0 X0 Y0 / M98 P2000 / M30")
    assert errors(program, _wo2(tmp_path)) == expected


@pytest.mark.parametrize("rest", [
    # (j6: its own call of a stored O8000)
    "O2000 / G0 X-700. / M98 P8000 / M99",
    # (j5: through an O3000 only it calls; j7: in another uncalled O3000)
    "O2000 / G0 X-700. / M98 P3000 / M99 / O3000 / M98 P8000 / M99",
    "O2000 / G0 X-700. / M99 / O3000 / M98 P8000 / M99",
])
def test_a_stored_call_the_main_does_not_reach_runs_no_uncalled_program_under_its_offset(
        tmp_path, rest):
    """Review 58a, F2 (j5-j7.nc): nothing the main runs calls O2000, and the only call of a
    program the file does not hold is made where the main's run does not reach: a stored
    O8000 called there runs under the offset of its own caller, not the main's G55, so
    O2000's X-700. is not said as X-800 (it was, as for a stored call of the main's)."""
    program = "G21 G17 G90 G55 / G0 X0 Y0 / M30 / " + rest
    assert errors(program, _wo2(tmp_path)) == []
    # (an O9001, which an M code of the main may run under its G55, keeps it)
    assert errors(program.replace("O2000", "O9001"), _wo2(tmp_path)) == [("TG601", 7, 4)]


def said(blocks: str, profile: str) -> list[tuple[str, int, int, str]]:
    """The errors of `%` / O1000 / `blocks` / `%`, with the start of each one's message."""
    text = "%\nO1000\n" + blocks.replace(" / ", "\n") + "\n%\n"
    prof = load_profile(profile)
    found = Checker(prof, "<input>").run(parse_text(text, prof.dialect, errors="collect"))
    return [(f.rule, f.line, f.column, f.message.split(", outside")[0])
            for f in found if f.severity == "error"]


# O1000 (lines 2-4) is the body, under its own G55 (X-100 on the profile); O2000 the main
BODY = "G90 G55 G0 X-700. / M99 / O2000 / G21 G17 G90 G54 / G0 X0 Y0 / "


@pytest.mark.parametrize("g10, expected", [
    # (e1: G55's X written -200: X-700. runs at -900, said with the value written)
    ("G10 L2 P2 X-200.", [("TG601", 10, 5, "X goes to -900 in machine coordinates (work -700 "
                           "+ G55 offset -200 as a G10 before this call wrote it)")]),
    # (e2: the profile's own value written again)
    ("G10 L2 P2 X-100.", [("TG601", 10, 5, "X goes to -800 in machine coordinates (work -700 "
                           "+ G55 offset -100 as a G10 before this call wrote it)")]),
    # (X0: -700 runs inside the travel)
    ("G10 L2 P2 X0.", []),
    # (under G91 the value is added to the offset; a #-value; L20, an additional offset's
    # on a FANUC, writes no G55: the profile's value holds)
    ("G91 G10 L2 P2 X-200.", []),
    ("#24=-200. / G10 L2 P2 X#24", []),
    ("G10 L20 P2 X-200.", [("TG601", 10, 5, "X goes to -800 in machine coordinates (work -700 "
                            "+ G55 offset -100.0)")]),
])
def test_a_g10_of_numbers_under_g90_writes_a_value_known(tmp_path, g10, expected):
    """Review 58d, F9 (e1.nc, e2.nc): a G10 L2 P2 of numbers under G90 sets G55's X to the
    value written (FANUC 0i-MF, "Changing workpiece coordinate system"): the body's X-700.
    is judged at the call with it (it was held, the value taken as not known, and the
    -900 overtravel lost). Under G91, with a #-value, the value is not known: held."""
    program = BODY + f"{g10} / G90 G55 / M98 P1000 / M30"
    expected = [(r, line + g10.count(" / "), c, m) for r, line, c, m in expected]
    assert said(program, _wo2(tmp_path)) == expected


def test_a_g10_of_g54_s_value_judges_a_body_under_g54(tmp_path):
    """Review 58d, F9 (e3.nc): `G10 L2 P1 X0.` writes G54's X as it is: O1000's `G90 G54 G0
    X-800.` is -800, said at the call with the value written."""
    program = ("G90 G54 G0 X-800. / M99 / O2000 / G21 G17 G90 G54 / G0 X0 Y0 / "
               "G10 L2 P1 X0. / M98 P1000 / M30")
    assert said(program, _wo2(tmp_path)) == [("TG601", 9, 5, (
        "X goes to -800 in machine coordinates (work -800 + G54 offset 0 as a G10 before "
        "this call wrote it)"))]


@pytest.mark.parametrize("other", [
    # (q2e: a G10 of G54; q2g: of a tool offset; q6: a stored program's call; q7: G52)
    "G10 L2 P1 X0.", "G10 L10 P1 R0.", "M98 P8000", "G52 X10. / G52 X0.",
    # (q9: an additional offset selected)
    "G54.1 P1 / G0 X0",
])
def test_what_an_uncalled_program_does_holds_no_later_program_s_positions(tmp_path, other):
    """Review 58d, F4 (q2e, q2g, q6, q7, q9): O3000, written first and never called, writes
    an offset, shifts, or calls a program the file does not hold: that loses the profile's
    offsets in O3000's run only, not in O1000's (its X-700. under G55 is -800) nor in the
    main's (it lost them for the whole file from there: every later overtravel silent)."""
    program = ("M99 / O3000 / " + other + " / M99 / O4000 / G90 G55 G0 X-700. / M99 / O2000 / "
               "G21 G17 G90 G54 / G0 X0 Y0 / M98 P4000 / M30")
    # (the blocks from line 3: the main's call the one before the last)
    line = program.count(" / ") + 2
    assert errors(program, _wo2(tmp_path)) == [("TG601", line, 5)]
    # (q2i: no call at all: O4000 judged alone says its own)
    program = "M99 / O3000 / " + other + " / M99 / O4000 / G90 G55 G0 X-700. / M99"
    assert errors(program, _wo2(tmp_path)) == [("TG601", program.count(" / ") + 2, 12)]


def test_a_call_of_a_program_that_wrote_offsets_loses_them_in_its_caller(tmp_path):
    """Review 58d, F4: the loss a body makes (its own G10 of G55's X) is its caller's from
    the call on, not before it: the main's own X-700. under G55 is -800 before the call
    (said), -700 after it (it was silent before the call too: the body's G10, read first,
    lost the offsets for the whole file)."""
    program = ("G10 L2 P2 X0. / M99 / O2000 / G21 G17 G90 G55 / G0 X-700. Y0 / M98 P1000 / "
               "G0 X-700. / M30")
    assert errors(program, _wo2(tmp_path)) == [("TG601", 7, 4)]


@pytest.mark.parametrize("body, call", [
    # (v10: P a G65 argument; v2d: a local the main sets before an M98)
    ("G10 L2 P#4 X0.", "G65 P2500 I2."),
    ("G10 L2 P#1 X0.", "#1=2 / M98 P2500"),
    # (w2: a WHILE loop in the body writes G54, then G55)
    ("#5=1 / WHILE [#5 LE 2] DO1 / G10 L2 P#5 X0. / #5=#5+1 / END1", "M98 P2500"),
])
def test_a_body_whose_g10_p_is_an_expression_may_write_any_offset(tmp_path, body, call):
    """Review 58d, F5 and F6 (v10, v2d, w2): O2500's G10 writes the offset its P's value
    names where it runs, which the checker does not know where it reads the body: a call of
    it writes every offset, the values not known, so O4000's X-700. under G55 after it is
    held (it was said as -800, the body "not followed" and taken as writing nothing)."""
    program = ("M99 / O4000 / G90 G55 G0 X-700. / M99 / O2500 / " + body + " / M99 / O2000 / "
               f"G21 G17 G90 G54 / G0 X0 Y0 / {call} / M98 P4000 / M30")
    assert errors(program, _wo2(tmp_path)) == []
    # (the same call after O4000's: said there)
    program = program.replace(f"{call} / M98 P4000", f"M98 P4000 / {call}")
    assert [e[0] for e in errors(program, _wo2(tmp_path))] == ["TG601"]


def test_a_g10_whose_p_is_an_expression_in_a_loop_writes_every_offset(tmp_path):
    """Review 58d, F6 (w2g.nc): the loop back writes G54-G59 (P1-P6), not only the G54 of
    #5's first value: G55's X is 0 at the call, X-700. inside. Without the jump back the P
    is its value (P1, G54): the G55 position said."""
    program = ("M99 / O4000 / G90 G55 G0 X-700. / M99 / O2000 / G21 G17 G90 G54 / G0 X0 Y0 / "
               "#5=1 / N10 G10 L2 P#5 X0. / #5=#5+1 / IF [#5 LE 6] GOTO 10 / M98 P4000 / M30")
    assert errors(program, _wo2(tmp_path)) == []
    program = program.replace("IF [#5 LE 6] GOTO 10", "#6=1")
    assert [e[0] for e in errors(program, _wo2(tmp_path))] == ["TG601"]


@pytest.mark.parametrize("rest, expected", [
    # (o3: O100, written after the main, writes G55's X before O1000's call: -700, inside)
    ("G10 L2 P2 X0. / M99", []),
    # (b1: O100 writes nothing: the -800 said at the call)
    ("G0 Y0 / M99", [("TG601", 10, 5)]),
    # (O100 writes G54's X: G55's is the profile's)
    ("G10 L2 P1 X0. / M99", [("TG601", 10, 5)]),
    # (n1: through an O200 that O100 calls, written after it)
    ("M98 P200 / M99 / O200 / G10 L2 P2 X0. / M99", []),
])
def test_a_g10_of_a_program_written_after_its_call_holds_the_positions_after_it(
        tmp_path, rest, expected):
    """Review 58d, F1 (o3.nc, n1.nc): the main's `M98 P100` runs O100, written after the main,
    before its G55 call of O1000: what O100 writes is known only at the file's end, so the
    position said at the call waits for it there, dropped where O100 (or a program it calls)
    writes G55's X (it was "X goes to -800", O100 taken as writing nothing, as a program the
    file does not hold is)."""
    program = ("G90 G55 G0 X-700. / M99 / O2000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P100 / "
               "G90 G55 / M98 P1000 / M30 / O100 / " + rest)
    assert errors(program, _wo2(tmp_path)) == expected
    # (a stored program, not in the file: not followed, the alarm said)
    assert errors(program.replace("M98 P100 /", "M98 P8000 /"), _wo2(tmp_path)) == [
        ("TG601", 10, 5)]


def test_a_program_run_on_into_with_the_skip_switch_keeps_the_g10_before_it(tmp_path):
    """Review 58d (r1.nc): with the block skip switch on the main runs past `/M30` into O2000
    under its G55, whose X its G10 wrote 0: O2000's X-700. runs at -700, no overtravel
    there; and O3000's call of it under G54 runs it at -700 too. (With the G10 of the
    main read apart as its own run, the program after it was read under the profile's G55.)"""
    program = ("G21 G17 G90 G54 / G10 L2 P2 X0. / G90 G55 / G0 X0 Y0 / /M30 / O2000 / G0 X-700. "
               "/ M99 / O3000 / G90 G54 / M98 P2000 / M30")
    assert errors(program, _wo2(tmp_path)) == []
    # (r1c: no G10: the run-on's -800 said on O2000's line)
    assert errors(program.replace("G10 L2 P2 X0. / ", ""), _wo2(tmp_path)) == [("TG601", 8, 4)]


def test_a_g10_p_of_the_program_s_own_local_writes_that_offset_only(tmp_path):
    """Review 59a, F4 (v15.nc): O2500 sets its own local #5 to 1 before `G10 L2 P#5 X0.`:
    at every call it writes G54's X (FANUC Custom Macro B: #1-#33 local, cleared at each
    call), not every offset: O4000's X-700. under G55 after the call is -800, said (it was
    held, the P taken as any offset). A loop back over it writes every offset (v18): held."""
    program = ("M99 / O4000 / G90 G55 G0 X-700. / M99 / O2500 / #5=1 / G10 L2 P#5 X0. / M99 / "
               "O2000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P2500 / M98 P4000 / M30")
    assert said(program, _wo2(tmp_path)) == [("TG601", 15, 5, (
        "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)"))]
    # (a common variable may differ at another call: every offset, held)
    assert said(program.replace("#5", "#500"), _wo2(tmp_path)) == []
    loop = ("M99 / O4000 / G90 G55 G0 X-700. / M99 / O2000 / G21 G17 G90 G54 / G0 X0 Y0 / "
            "#5=3 / N10 G10 L2 P#5 X0. / #5=#5+1 / IF [#5 LE 6] GOTO 10 / M98 P4000 / M30")
    assert said(loop, _wo2(tmp_path)) == []


@pytest.mark.parametrize("rest, expected", [
    # (a4b: G55's X written -200 by O100, written after the main: -900)
    ("G10 L2 P2 X-200. / M99", "X goes to -900 in machine coordinates (work -700 + G55 offset "
                               "-200 as a G10 before this call wrote it)"),
    # (a4c: the profile's value written again: -800)
    ("G10 L2 P2 X-100. / M99", "X goes to -800 in machine coordinates (work -700 + G55 offset "
                               "-100 as a G10 before this call wrote it)"),
    # (a G52 left on with the G10: the position is not work + offset, held)
    ("G10 L2 P2 X-200. / G52 X300. / M99", None),
    # (c13: an additional offset selected and written: G55's X the profile's)
    ("G54.1 P1 / G0 X0 / G10 L20 P1 X0. / M99", "X goes to -800 in machine coordinates "
                                                  "(work -700 + G55 offset -100.0)"),
    # (c12: a G10 two calls deeper, after it: held)
    ("M98 P200 / M99 / O200 / M98 P300 / M99 / O300 / G10 L2 P2 X0. / M99", None),
])
def test_a_g10_of_a_program_written_after_its_call_is_judged_with_its_value(
        tmp_path, rest, expected):
    """Review 59a, F1 (a4b.nc, a4c.nc) and F10 (c12): the position held to the file's
    end for O100, written after the main, is judged there with the value O100's G10 writes,
    as it is where O100 is written before the main (it was dropped, the real overtravel
    lost); held only where the value is not known, the coordinates moved, or the write is
    deeper in programs O100 calls."""
    program = ("G90 G55 G0 X-700. / M99 / O2000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P100 / "
               "G90 G55 / M98 P1000 / M30 / O100 / " + rest)
    assert said(program, _wo2(tmp_path)) == ([("TG601", 10, 5, expected)] if expected else [])


PROFILE_800 = "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)"


@pytest.mark.parametrize("rest, expected", [
    # (h6b: G55's X -100 (the IF taken) or -200: -800 or -900, the nearer said, as read)
    ("IF [#500 EQ 1] GOTO 5 / G10 L2 P2 X-200. / N5 M99", PROFILE_800),
    # (e10: P#500 may name G55 or not: -100 or -200 again)
    ("G10 L2 P#500 X-200. / M99", PROFILE_800),
    # (the value written puts X-700. inside on one path: held)
    ("IF [#500 EQ 1] GOTO 5 / G10 L2 P2 X0. / N5 M99", None),
    ("G10 L2 P#500 X0. / M99", None),
    # (-200 surely written, then -150 or not: -900 or -850, the nearer said with its value)
    ("G10 L2 P2 X-200. / IF [#500 EQ 1] GOTO 5 / G10 L2 P2 X-150. / N5 M99",
     "X goes to -850 in machine coordinates (work -700 + G55 offset -150 as a G10 before this "
     "call wrote it)"),
    # (three values (-100, -200, 0): one inside, held)
    ("IF [#500 EQ 1] GOTO 5 / G10 L2 P2 X-200. / N5 IF [#501 EQ 1] GOTO 6 / "
     "G10 L2 P2 X0. / N6 M99", None),
])
def test_a_g10_that_may_not_run_keeps_the_overtravel_of_both_values(tmp_path, rest, expected):
    """Review 60, F1 (h6b.nc, f5/e10.nc): O100, written after the main, writes G55's X by a
    G10 that a condition may pass over, or whose P is not known; O1000's X-700. under G55
    runs at -800 (the value before) or -900 (the one written): an alarm on both paths, said
    (it was dropped as "a value not known"), with the value that puts it least far out;
    held where one of the values puts it inside the travel."""
    program = ("G90 G55 G0 X-700. / M99 / O2000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P100 / "
               "G90 G55 / M98 P1000 / M30 / O100 / " + rest)
    assert said(program, _wo2(tmp_path)) == ([("TG601", 10, 5, expected)] if expected else [])


@pytest.mark.parametrize("flow", [
    # (a24c: the IF is false, X0. runs and GOTO 6 passes over N5's X-200.)
    "#1=0 / IF [#1 EQ 1] GOTO 5 / G10 L2 P2 X0. / GOTO 6 / N5 G10 L2 P2 X-200. / N6 G0 X0",
    # (a24d: the second G10 is passed over by the GOTO)
    "G10 L2 P2 X0. / GOTO 6 / G10 L2 P2 X-200. / N6 G0 X0",
])
def test_a_g10_a_jump_may_pass_over_writes_no_value_known(tmp_path, flow):
    """Review 59a, F2 (a24c.nc, a24d.nc): the last G10 in file order is not the one in force
    where a jump passes over it or a condition chooses: a G10 passed over by a jump surely
    taken writes nothing, and one after a jump or condition of its program writes a value
    not known (held), not X-200 (it said a false -900; the control runs X-700. at -700)."""
    program = BODY + flow + " / G90 G55 / M98 P1000 / M30"
    assert said(program, _wo2(tmp_path)) == []
    # (the G10 of X-200. alone before the jump: -900 said)
    program = BODY + "G10 L2 P2 X-200. / GOTO 6 / G10 L2 P2 X0. / N6 G90 G55 / M98 P1000 / M30"
    assert said(program, _wo2(tmp_path)) == [("TG601", 12, 5, (
        "X goes to -900 in machine coordinates (work -700 + G55 offset -200 as a G10 before "
        "this call wrote it)"))]


@pytest.mark.parametrize("moved", [
    # (a8b rotation, a8e mirror, a8d scaling, a30 G92)
    "G68 X0 Y0 R180.", "G51.1 X0", "G51 X0 Y0 P500", "G92 X0",
    # (F11: G55's X written again through its system variable, u2 and u2c)
    "#5241=0.", "#5241=#5241+300.",
])
def test_a_value_written_is_not_judged_with_after_the_coordinates_or_the_offset_moved(
        tmp_path, moved):
    """Review 59a, F5 (a8b, a8e, a8d, a30) and F11 (u2, u2c): after `G10 L2 P2 X-200.` a
    rotation, mirror, scaling or G92 in force at the call, or a write of G55's X through
    #5241 (FANUC Custom Macro B system variables #5221-#5326), leaves the position not the
    work position plus -200: held (each said a false -900)."""
    program = BODY + f"G10 L2 P2 X-200. / G90 G55 / {moved} / M98 P1000 / M30"
    assert said(program, _wo2(tmp_path)) == []
    # (#5221, G54's X, leaves G55's written value: -900 said)
    program = BODY + "G10 L2 P2 X-200. / #5221=0. / G90 G55 / M98 P1000 / M30"
    assert said(program, _wo2(tmp_path)) == [("TG601", 11, 5, (
        "X goes to -900 in machine coordinates (work -700 + G55 offset -200 as a G10 before "
        "this call wrote it)"))]


@pytest.mark.parametrize("shift, expected", [
    # (w7, w11: where the main stands at the call, X0, becomes X-300: every work system moved
    # by +300, X-700. under G55 runs at -500; the position at the call not followed: held)
    ("G92 X-300.", None), ("G92 X-300. Y0", None),
    # (w2: G52 X0 Y0 is no shift; w1: G68 R0. cancelled by G69: the profile's -800 true)
    ("G52 X0 Y0", "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)"),
    ("G68 X0 Y0 R0. / G69", "X goes to -800 in machine coordinates (work -700 + G55 offset "
                            "-100.0)"),
    # (wv5: a G92 of a value not known, said as before, erring on the side of the alarm)
    ("G92 X#500", "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)"),
])
def test_a_g92_of_a_program_written_before_the_main_holds_the_positions_after_its_call(
        tmp_path, shift, expected):
    """Review 60, F5 (w7.nc, w11.nc): O1000, written before the main, does `G92 X-300.`; its
    call moves every work system's zero by where the main stood, so O1001's X-700. under G55
    after it is not at -800 (it was said: the profile's offsets trusted again after the
    call). A zero shift (`G52 X0 Y0`) or a frame cancelled keeps the profile's -800 said."""
    program = (f"{shift} / G0 Y0 / M99 / O1001 / G90 G55 G0 X-700. / M99 / O2000 / "
               "G21 G17 G90 G54 / G0 X0 Y0 / M98 P1000 / G90 G55 / M98 P1001 / M30")
    line = 15 if "G69" in shift else 14
    assert said(program, _wo2(tmp_path)) == ([("TG601", line, 5, expected)] if expected else [])


@pytest.mark.parametrize("shift, expected", [
    # (x2: G52 X0 Y0 is no shift: -900 said with the value written)
    ("G52 X0 Y0", (11, "X goes to -900 in machine coordinates (work -700 + G55 offset -200 as "
                       "a G10 before this call wrote it)")),
    # (a shift cancelled before the G10: the same)
    ("G52 X300. / G52 X0", (12, "X goes to -900 in machine coordinates (work -700 + G55 offset "
                                "-200 as a G10 before this call wrote it)")),
    # (a shift of 300 in force at the call: -600, held)
    ("G52 X300.", None),
])
def test_a_zero_shift_does_not_stop_a_value_written_being_judged(tmp_path, shift, expected):
    """Review 60, F6 (x2.nc): any G52 (even `G52 X0 Y0`, a cancel) marked the coordinates
    moved for good, and no value a G10 wrote after it was judged: O1000's X-700. under the
    G55 X-200 written runs at -900, an alarm lost. Only a shift not known to be zero holds."""
    program = BODY + f"{shift} / G10 L2 P2 X-200. / G90 G55 / M98 P1000 / M30"
    found = said(program, _wo2(tmp_path))
    assert found == ([("TG601", expected[0], 5, expected[1])] if expected else [])


@pytest.mark.parametrize("g10, expected", [
    # (a37: G55's X 0: X-700. inside, G1 X-780. beyond)
    ("G10 L2 P2 X0.", "X goes to -780 in machine coordinates (work -780 + G55 offset 0 as a G10 "
                      "before this call wrote it)"),
    # (a37b: X-50.: -750 inside, -830 beyond)
    ("G10 L2 P2 X-50.", "X goes to -830 in machine coordinates (work -780 + G55 offset -50 as "
                        "a G10 before this call wrote it)"),
    # (X100.: -680 at the farthest, inside)
    ("G10 L2 P2 X100.", None),
])
def test_an_excursion_is_judged_at_its_farthest_position_with_the_value_written(
        tmp_path, g10, expected):
    """Review 59a, F7 (a37.nc, a37b.nc): O1000's X-700. and X-780. under G55 are one excursion
    beyond the travel as read (-800, -880), said once at its first position; with the value
    a G10 wrote, the farthest, X-780. of line 4, decides (only the first was judged: inside,
    and the -780 overtravel dropped with it). The call names line 4."""
    program = ("G90 G55 G0 X-700. / G1 X-780. F100. / G0 X0 / M99 / O2000 / G21 G17 G90 G54 / "
               f"G0 X0 Y0 / {g10} / G90 G55 / M98 P1000 / M30")
    found = said(program, _wo2(tmp_path))
    assert found == ([("TG601", 12, 5, expected)] if expected else [])
    if expected:
        text = "%\nO1000\n" + program.replace(" / ", "\n") + "\n%\n"
        prof = load_profile(_wo2(tmp_path))
        messages = [f.message for f in Checker(prof, "<input>").run(
            parse_text(text, prof.dialect, errors="collect")) if f.severity == "error"]
        assert "its position of line 4 there" in messages[0]


# the main, O1000 (lines 2-5), calls O2000 written after it (line 6 on); G55 is X-100
AFTER = "G21 G17 G90 G55 / G0 X0 Y0 / M98 P2000 / M30 / O2000 / "
NAMED = ("O2000 runs as called by M98 P2000 of line 5: a subprogram written after its call runs "
         "under the work offset in force there")


@pytest.mark.parametrize("body, expected", [
    # (a1: the usual FANUC layout; a4: with its own G90; a7: its own G55; a8: beyond either way)
    ("G0 X-700. / M99", [("TG601", 8, 4, "X goes to -800 in machine coordinates (work -700 + "
                          "G55 offset -100.0)")]),
    ("G90 G0 X-700. / M99", [("TG601", 8, 8, "X goes to -800 in machine coordinates (work -700 "
                              "+ G55 offset -100.0)")]),
    ("G90 G55 G0 X-700. / M99", [("TG601", 8, 12, "X goes to -800 in machine coordinates (work "
                                  "-700 + G55 offset -100.0)")]),
    # (d1: each excursion, as inline)
    ("G0 X-700. / G0 X100. / G0 X-720. / M99",
     [("TG601", 8, 4, "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)"),
      ("TG601", 10, 4, "X goes to -820 in machine coordinates (work -720 + G55 offset -100.0)")]),
    # (c4: its own G54: X-700 inside)
    ("G54 / G0 X-700. / M99", []),
    # (d2, d3: its own G10 or G52 before the move: the offsets lost as inline)
    ("G10 L2 P2 X0. / G0 X-700. / M99", []),
    ("G52 X-100. / G0 X-700. / M99", []),
    # (c2: a program it calls, written after it, under the same G55)
    ("G0 X0 / M98 P3000 / M99 / O3000 / G0 X-750. / M99",
     [("TG601", 12, 4, "X goes to -850 in machine coordinates (work -750 + G55 offset -100.0)")]),
])
def test_a_subprogram_written_after_its_call_runs_under_the_call_s_offset(tmp_path, body,
                                                                         expected):
    """Review 59a, F12 (a1, a4, a7, d1-d3, c2, c4): O1000 selects G55 and calls O2000, written
    after its M30, the usual FANUC layout. A FANUC's M98 changes no modal state, the work
    offset is modal (0i-MF Operator's Manual, "Subprogram call (M98)"): O2000's X-700. runs
    at X-800, beyond the travel, said at its line naming the call (it was silent, where the
    same body written before the main, or inline, was said)."""
    found = said(AFTER + body, _wo2(tmp_path))
    assert found == expected
    text = "%\nO1000\n" + (AFTER + body).replace(" / ", "\n") + "\n%\n"
    prof = load_profile(_wo2(tmp_path))
    messages = [f.message for f in Checker(prof, "<input>").run(
        parse_text(text, prof.dialect, errors="collect")) if f.severity == "error"]
    for m in messages[:1]:
        assert NAMED in m or NAMED.replace("O2000", "O3000").replace("P2000 of line 5",
                                                                    "P3000 of line 9") in m


@pytest.mark.parametrize("main", [
    # (c1: a G10 of a value not known before the call; c6: a G52; c9: a call under G91, the
    # body read in G90; a5, two calls under G55 and G54, is judged under each since calls76:
    # tests/test_calls_offsets.py)
    "G21 G17 G90 G55 / G0 X0 Y0 / G91 G10 L2 P2 X-200. / G90 / M98 P2000 / M30",
    "G21 G17 G90 G55 / G0 X0 Y0 / G52 X10. / M98 P2000 / M30",
    "G21 G17 G90 G55 / G0 X0 Y0 / G91 / M98 P2000 / G90 / M30",
    # (a6: under G54, X-700 inside)
    "G21 G17 G90 G54 / G0 X0 Y0 / M98 P2000 / M30",
    # (a G66 runs O2000 at each later move, here under G54: not the G66 block's G55)
    "G21 G17 G90 G55 / G0 X0 Y0 / G66 P2000 / G54 / G0 X10. / G67 / M30",
])
def test_a_subprogram_written_after_calls_not_known_is_read_as_before(tmp_path, main):
    """Review 59a, F12: where the offset at the calls is not the profile's (a G10, a G52
    before the call), the calls disagree, or the body would be read in another distance
    mode than its call's, its machine positions are not judged (as before)."""
    assert said(main + " / O2000 / G0 X-700. / M99", _wo2(tmp_path)) == []


def test_a_program_after_a_body_read_under_its_call_is_read_as_its_own(tmp_path):
    """Review 59a, F12 (fuzz f024): the state read before a body run under its calls' offset
    is given back where it ends: a later main's own `G90 G55` / `G1 X-780.` is -880, said
    (what O3000's run wrote had silenced it)."""
    program = ("G90 G55 / G65 P3000 I2. / M99 / O3000 / G65 P5000 I2. / G90 G55 / M98 P5000 / "
               "M99 / O1000 / G21 G17 G90 G54 / G0 X0 Y0 / G90 G55 / G1 X-780. F100. / M30 / "
               "O5000 / G10 L2 P#4 X0. / M99")
    assert said(program, _wo2(tmp_path)) == [
        ("TG601", 15, 4, "X goes to -880 in machine coordinates (work -780 + G55 offset -100.0)")]


@pytest.mark.parametrize("program, expected", [
    # (g1: the main's G52 left on at its M30; g2: an uncalled O3000's at its M99; g4: the
    # later program merged by its own units code; g6: a first program ending in M99)
    ("G21 G17 G90 G55 / G52 X10. / G0 X0 Y0 / M30 / O2000 / G90 G55 G0 X-700. / M99",
     [("TG601", 8, 12)]),
    ("G21 G17 G90 G55 / G0 X0 Y0 / M30 / O3000 / G52 X10. / M99 / O2000 / G90 G55 G0 X-700. / "
     "M99", [("TG601", 10, 12)]),
    ("G21 G17 G90 G55 / G52 X10. / G0 X0 Y0 / M30 / O4000 / G21 G90 G55 / G0 X-700. / M30",
     [("TG601", 9, 4)]),
    ("G21 G17 G90 G55 / G52 X10. / G0 X0 Y0 / M99 / O2000 / G90 G55 G0 X-700. / M99",
     [("TG601", 8, 12)]),
    # (h1, h3: called by the program that has the G52 on, before or after it: as before)
    ("G21 G17 G90 G55 / G52 X-100. / G0 X0 Y0 / M98 P2000 / M30 / O2000 / G0 X-700. / M99", []),
    # (the skip switch on: the main runs on into O2000 under its G52: as before)
    ("G21 G17 G90 G55 / G52 X10. / G0 X0 Y0 / /M30 / O2000 / G90 G55 G0 X-700. / M99", []),
])
def test_a_g52_left_on_by_an_earlier_program_holds_no_later_program(tmp_path, program,
                                                                     expected):
    """Review 59a, F3: each program of the file is read from the control's reset state
    (docs/dialects.md, "Several programs in one file"): a G52 an earlier program left on at
    its end (M30 or M99) is not the later program's, whose `G90 G55 G0 X-700.` is X-800, said
    (the offsets were taken as lost for every later program). A program called by the one
    with the G52 on runs under it, as before."""
    assert errors(program, _wo2(tmp_path)) == expected


@pytest.mark.parametrize("blocks, expected", [
    # (k1: G55's X written -200: X-700. at -900)
    ("G10 L2 P2 X-200. / G0 X-700. / M30",
     [("TG601", 6, 4, "X goes to -900 in machine coordinates (work -700 + G55 offset -200 as a "
                      "G10 before wrote it)")]),
    # (k2: written 0: X-700. inside, X-780. beyond)
    ("G10 L2 P2 X0. / G0 X-700. / G0 X-780. / M30",
     [("TG601", 7, 4, "X goes to -780 in machine coordinates (work -780 + G55 offset 0 as a "
                      "G10 before wrote it)")]),
    # (k3: another offset written: G55's profile value)
    ("G10 L2 P1 X-200. / G0 X-700. / M30",
     [("TG601", 6, 4, "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0)")]),
    # (k4: under G91 the value is added; k5: set again by its variable; not known, as before)
    ("G91 G10 L2 P2 X-200. / G90 G0 X-700. / M30", []),
    ("G10 L2 P2 X-200. / #5241=0. / G0 X-700. / M30", []),
    # (a condition that may jump over the G10: its value not known, review 59a F2)
    ("IF [#5 EQ 1] GOTO 5 / G10 L2 P2 X-200. / N5 G0 X-700. / M30", []),
    # (c1: a body written after the call runs under the value its caller wrote, F12)
    ("G10 L2 P2 X-200. / M98 P2000 / M30 / O2000 / G0 X-700. / M99",
     [("TG601", 9, 4, "X goes to -900 in machine coordinates (work -700 + G55 offset -200 as a "
                      "G10 before wrote it)")]),
    ("G10 L2 P2 X0. / M98 P2000 / M30 / O2000 / G0 X-700. / M99", []),
])
def test_a_program_s_own_moves_after_its_g10_are_judged_with_the_value_written(
        tmp_path, blocks, expected):
    """Review 59a, F8 (k1-k5, c1): a `G10 L2 P2` of numbers under G90, surely run, sets G55's
    X to the value written (FANUC 0i-MF Operator's Manual, "Changing workpiece coordinate
    system"): the program's own moves after it are judged with it (they were not compared:
    the G10 made every offset not known for the rest of the program)."""
    assert said("G21 G17 G90 G55 / G0 X0 Y0 / " + blocks, _wo2(tmp_path)) == expected


@pytest.mark.parametrize("blocks, expected", [
    # (r1: O2000's own, after the main's excursion at X-800: said too)
    ("G0 X-700. / M30 / O2000 / G90 G55 / G0 X-700. / M99", [("TG601", 5, 4), ("TG601", 9, 4)]),
    # (r2: the later program merged by its units code)
    ("G0 X-700. / M30 / O2000 / G21 G90 G55 / G0 X-700. / M30",
     [("TG601", 5, 4), ("TG601", 9, 4)]),
    # (with the skip switch on the main runs on into O2000: one excursion, as before)
    ("G0 X-700. / /M30 / O2000 / G90 G55 / G0 X-700. / M99", [("TG601", 5, 4)]),
])
def test_an_excursion_of_one_program_holds_no_overtravel_of_the_next(tmp_path, blocks,
                                                                     expected):
    """Review 59a, F9 (r1, r2): an excursion beyond the travel is one run's: a position outside
    at the end of one program is not the start of one of the next program's, whose own
    first position beyond the travel is said (it was taken for the same excursion)."""
    assert errors("G21 G17 G90 G55 / G0 X0 Y0 / " + blocks, _wo2(tmp_path)) == expected
