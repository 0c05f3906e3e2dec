"""A subprogram's positions judged at every call, under the work offset in force there
(issue 32 item 4; review 62a F6d).

The profiles are a FANUC mill and a LinuxCNC mill whose G55 is X-100 (X travel -762..762):
`G0 X-700.` under G55 runs at -800, beyond the travel; under G54 at -700, inside. A call
of a subprogram read before it that surely leaves the offsets as they were (no G10, no work
offset variable, no G52/G92/frame, no G54-G59 or tool length offset of its own, no end or
return elsewhere, no call that may do these) no longer loses them: its next call, and the
caller's own moves after it, are judged as before the first. Every LinuxCNC case was run on
`rs274 -g`: the body's STRAIGHT_TRAVERSE comes at the call, under the SET_G5X_OFFSET in
force there (the machine position is that work position plus the profile's offset).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from formats.parser import parse_text
from formats.profile import load_profile
from postproc.check import Checker

OFFSETS = ("[limits]\nX = [-762.0, 762.0]\nY = [-406.0, 406.0]\nZ = [-508.0, 10.0]\n"
           "[work_offsets]\nG54 = { X = 0.0, Y = 0.0, Z = 0.0 }\n"
           "G55 = { X = -100.0, Y = 0.0, Z = 0.0 }\nG56 = { X = -200.0, Y = 0.0, Z = 0.0 }\n")


@pytest.fixture
def fanuc(tmp_path: Path) -> str:
    profile = tmp_path / "wo.toml"
    profile.write_text('name = "wo-mill"\nbase = "fanuc-mill"\n' + OFFSETS)
    return str(profile)


@pytest.fixture
def lcnc(tmp_path: Path) -> str:
    profile = tmp_path / "wol.toml"
    profile.write_text('name = "wo-lcnc"\nbase = "linuxcnc"\n' + OFFSETS)
    return str(profile)


def said(text: str, profile: str) -> list[tuple[int, int, str]]:
    """The TG601s of `text` (its blocks split at ` / `): line, column, message."""
    prof = load_profile(profile)
    program = text.replace(" / ", "\n") + "\n"
    found = Checker(prof, "<input>").run(parse_text(program, prof.dialect, errors="collect"))
    return [(f.line, f.column, f.message) for f in found if f.rule == "TG601"]


BODY = "O2000 / G0 X-700. / M99 / O1000 / G21 G17 G90 G54 / G0 X0 Y0 / "


@pytest.mark.parametrize("blocks, expected", [
    # (review 62a F6d, p36: one body, a call under G54 (-700), then one under G55 (-800))
    ("M98 P2000 / G55 / M98 P2000 / M30", [(9, 5, "X goes to -800")]),
    # (a call a fixture: G55 (-800) and G56 (-900), each said at its own call)
    ("M98 P2000 / G55 / M98 P2000 / G56 / M98 P2000 / M30",
     [(9, 5, "X goes to -800"), (11, 5, "X goes to -900")]),
    # (the same offset again: said once)
    ("G55 / M98 P2000 / G54 / M98 P2000 / G55 / M98 P2000 / M30", [(8, 5, "X goes to -800")]),
    # (the caller's own move after the call, under the offset it selects then)
    ("M98 P2000 / G55 / G0 X-700. / M30", [(9, 4, "X goes to -800")]),
    # (G65, as M98)
    ("G65 P2000 / G55 / G65 P2000 / M30", [(9, 5, "X goes to -800")]),
    # (the first call under G91 runs the body's X-700. as an increment, not known there; the
    # G90 call under G55 runs it at -800)
    ("G91 / M98 P2000 / G90 / G55 / M98 P2000 / M30", [(11, 5, "X goes to -800")]),
    # (p18: G10s of numbers between the calls: the second under the value written)
    ("G10 L2 P2 X0. / G55 / M98 P2000 / G10 L2 P2 X-200. / M98 P2000 / M30",
     [(11, 5, "X goes to -900")]),
])
def test_a_body_read_before_is_judged_at_every_call(fanuc: str, blocks: str,
                                                    expected: list[tuple[int, int, str]]) -> None:
    got = said(BODY + blocks, fanuc)
    assert [(line, col, msg.split(" in machine")[0]) for line, col, msg in got] == expected


def test_nested_calls_are_judged_at_every_outer_call(fanuc: str) -> None:
    """O2000 calls O3000, both read before the main: O3000's X-700. runs at each call of
    O2000, under G54 (-700) then G55 (-800)."""
    text = ("O3000 / G0 X-700. / M99 / O2000 / M98 P3000 / M99 / O1000 / G21 G17 G90 G54 / "
            "G0 X0 Y0 / M98 P2000 / G55 / M98 P2000 / M30")
    got = said(text, fanuc)
    assert [g[:2] for g in got] == [(12, 5)]
    assert "X goes to -800" in got[0][2] and "its position of line 2" in got[0][2]


def test_a_body_in_the_call_s_inch_units_is_judged_there(fanuc: str) -> None:
    """Review 62a F6c: a body with no units code of its own runs in its call's: `X-28.` under
    a G20 call is -711.2 mm, under G55 -811.2 (it was not judged in other units)."""
    text = "O2000 / G0 X-28. / M99 / O1000 / G20 G17 G90 G55 / G0 X0 Y0 / M98 P2000 / M30"
    got = said(text, fanuc)
    assert [g[:2] for g in got] == [(7, 5)]
    assert "X goes to -811.2 in machine coordinates (work -711.2 + G55 offset" in got[0][2]
    assert "runs in inches as called by M98 P2000 of line 7" in got[0][2]
    # is -660.4 mm, -760.4 under G55: inside)
    assert said(text.replace("X-28.", "X-26."), fanuc) == []


@pytest.mark.parametrize("body, after", [
    # (a body that selects an offset of its own: the caller runs under it after the call)
    ("G55 / G0 X-600.", "G0 X-700."),
    # (its own tool length offset: the caller's Z after it is under G43)
    ("G43 H1 Z0", "G0 Z-515."),
    # (a work offset variable, a G10 it writes: G54's X is -150 after it, X850. runs at 700)
    ("#5221=-150.", "G0 X850."),
    ("G10 L2 P1 X-150.", "G0 X850."),
    # (a G10 whose value is not known)
    ("G10 L2 P1 X#1", "G0 X850."),
    # (a call of a program written after it, which writes G54's X)
    ("M98 P3000", "G0 X850."),
    # (a rotation left on: X-700. under G68 R180 is X700)
    ("G68 X0 Y0 R180.", "G0 X-700."),
])
def test_a_body_that_may_change_the_offsets_still_loses_them(fanuc: str, body: str,
                                                            after: str) -> None:
    """Where the body may change what the offsets are, the caller's positions after the call
    are not compared as machine positions (as before): no false error."""
    text = (f"O2000 / {body} / M99 / O1000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P2000 / "
            f"{after} / M30 / O3000 / G10 L2 P1 X-150. / M99")
    assert said(text, fanuc) == []


def test_a_body_that_returns_elsewhere_loses_them(fanuc: str) -> None:
    """`M99 P5` returns to the caller's N5: the G55 and X-700. between never run."""
    text = ("O2000 / G0 X-10. / M99 P5 / O1000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P2000 / "
            "G55 / G0 X-700. / N5 M30")
    assert said(text, fanuc) == []


DEF = "o100 sub / G0 X-700 / o100 endsub / "


@pytest.mark.parametrize("text, expected", [
    # (the brief's first form: rs274 -g runs X-700 at the call, under G55: -800)
    (DEF + "G21 G17 G90 G55 / G0 X0 Y0 / o100 call / M2", [(6, 1)]),
    # (G54 call (-700), then G55 call (-800))
    (DEF + "G21 G17 G90 G54 / G0 X0 Y0 / o100 call / G55 / o100 call / M2", [(8, 1)]),
    # (the main's G55 before the definition, the call under G54: -700, inside)
    ("G21 G90 G55 / " + DEF + "G54 / G0 X0 Y0 / o100 call / M2", []),
    # (the main's own moves after a definition: judged as machine positions again)
    ("o100 sub / G0 X1 / o100 endsub / G21 G90 G55 / G0 X-700 / M2", [(5, 4)]),
    ("G21 G90 G55 / o100 sub / G0 X1 / o100 endsub / G0 X-700 / M2", [(5, 4)]),
    # (nested: o100 calls o200, both defined before the main)
    ("o200 sub / G0 X-700 / o200 endsub / o100 sub / o200 call / o100 endsub / "
     "G21 G90 G54 / G0 X0 Y0 / o100 call / G55 / o100 call / M2", [(11, 1)]),
    # (a repeat of calls under G55)
    (DEF + "G21 G90 G55 / G0 X0 Y0 / o101 repeat [2] / o100 call / o101 endrepeat / M2",
     [(7, 1)]),
    # (in inches: X-27 under G20 is -685.8 mm, -785.8 under G55)
    ("o100 sub / G0 X-27 / o100 endsub / G20 G90 G55 / G0 X0 Y0 / o100 call / M2", [(6, 1)]),
    ("o100 sub / G0 X-27 / o100 endsub / G21 G90 G55 / G0 X0 Y0 / o100 call / M2", []),
    # (the body selects G55, or sets a tool length, or writes G54's X: lost, as before)
    ("o100 sub / G55 / o100 endsub / G21 G90 G54 / G0 X0 Y0 / o100 call / G0 X-700 / M2", []),
    ("o100 sub / G43 H1 / o100 endsub / G21 G90 G54 / G0 X0 Y0 / o100 call / G0 Z-515 / M2",
     []),
    ("o100 sub / #5221=-150 / o100 endsub / G21 G90 G54 / G0 X0 Y0 / o100 call / G0 X850 / M2",
     []),
    # (the body ends the program: nothing after the call runs)
    ("o100 sub / G0 X-10 / M2 / o100 endsub / G21 G90 G54 / G0 X0 Y0 / o100 call / G55 / "
     "G0 X-700 / M2", []),
    # (a definition that reads a G49, G92 or G55 of its own where it stands: the main
    # program's state after its endsub is read with it, so its moves lose the offsets there)
    ("G21 G90 G54 / G43 H1 Z0 / o100 sub / G49 / o100 endsub / G0 Z-515 / M2", []),
    ("G21 G90 G54 / G0 X0 Y0 / o100 sub / G92 X-400 / o100 endsub / G0 X-700 / M2", []),
    ("G21 G90 G54 / G0 X0 Y0 / o100 sub / G55 / o100 endsub / G0 X-700 / M2", []),
    # (its position from a parameter, or under a rotation at the call: not known)
    ("o100 sub / G0 X#1 / o100 endsub / G21 G90 G55 / G0 X0 Y0 / o100 call [-700] / M2", []),
    (DEF + "G21 G90 G55 / G0 X0 Y0 / G68 X0 Y0 R180 / o100 call / M2", []),
])
def test_a_linuxcnc_definition_is_judged_at_every_call(lcnc: str, text: str,
                                                       expected: list[tuple[int, int]]) -> None:
    assert [g[:2] for g in said(text, lcnc)] == expected


AFTER = "O1000 / G21 G17 G90 G54 / G0 X0 Y0 / "


@pytest.mark.parametrize("blocks, expected", [
    # (the body after M30: calls under G54 and G55, -700 and -800; calls that disagree left
    # it not compared)
    ("M98 P2000 / G55 / M98 P2000 / M30 / O2000 / G0 X-700. / M99",
     [(9, 4, "X goes to -800 in machine coordinates (work -700 + G55 offset -100.0), outside "
             "the travel -762 to 762 (O2000 runs as called by M98 P2000 of line 6: a "
             "subprogram written after its call runs under the work offset in force there)")]),
    # (G54, G55, G56: -800 at the G55 call's, -900 at the G56 call's, one excursion each)
    ("M98 P2000 / G55 / M98 P2000 / G56 / M98 P2000 / M30 / O2000 / G0 X-700. / G0 X-720. / "
     "M99",
     [(11, 4, "X goes to -800"), (11, 4, "X goes to -900")]),
    # (the first call under G55: said under it as before, the G54 call's inside)
    ("G55 / M98 P2000 / G54 / M98 P2000 / M30 / O2000 / G0 X-700. / M99",
     [(10, 4, "X goes to -800")]),
    # (the body writes a G91 after its move: the second call, whose mode is the one the
    # first left (G91), runs X-700. as an increment: dropped; with the caller's own G90 at
    # the second call, said)
    ("M98 P2000 / G55 / M98 P2000 / M30 / O2000 / G0 X-700. / G91 / G0 X10. / M99", []),
    ("M98 P2000 / G90 G55 / M98 P2000 / M30 / O2000 / G0 X-700. / G91 / G0 X10. / M99",
     [(9, 4, "X goes to -800")]),
    # (the same body with G90 written first: absolute at every call)
    ("M98 P2000 / G55 / M98 P2000 / M30 / O2000 / G90 G0 X-700. / G91 / G0 X10. / M99",
     [(9, 8, "X goes to -800")]),
    # (the body selects its own offset: the calls' no longer judged)
    ("M98 P2000 / G55 / M98 P2000 / M30 / O2000 / G54 / G0 X-700. / M99", []),
    # (it writes a G10 of its own first: not judged under the others)
    ("M98 P2000 / G55 / M98 P2000 / M30 / O2000 / G10 L2 P2 X0. / G0 X-700. / M99", []),
    # (review 76 F1: the body changes the offsets after its move, so the second call runs
    # under what it wrote: a G10, a variable, a shift, a frame left on, a call of a program
    # not in the file -- the other call's findings dropped at its end)
    ("M98 P2000 / G55 / M98 P2000 / M30 / O2000 / G0 X-700. / G10 L2 P2 X0. / M99", []),
    ("M98 P2000 / G55 / M98 P2000 / M30 / O2000 / G0 X-700. / #5241=0. / M99", []),
    ("M98 P2000 / G55 / M98 P2000 / M30 / O2000 / G0 X-700. / G52 X300. / M99", []),
    ("M98 P2000 / G55 / M98 P2000 / M30 / O2000 / G0 X-700. / G68 X0 Y0 R180. / M99", []),
    ("M98 P2000 / G55 / M98 P2000 / M30 / O2000 / G0 X-700. / M98 P9000 / M99", []),
    # (a G10 between the calls: left not compared, as calls that disagree were)
    ("M98 P2000 / G10 L2 P2 X-200. / G55 / M98 P2000 / M30 / O2000 / G0 X-700. / M99", []),
])
def test_a_body_after_its_calls_is_judged_under_each_call_s_offset(
        fanuc: str, blocks: str, expected: list[tuple[int, int, str]]) -> None:
    got = said(AFTER + blocks, fanuc)
    assert len(got) == len(expected)
    assert [(line, col, msg[:len(e)])
            for (line, col, msg), (_, _, e) in zip(got, expected, strict=True)] == expected


def test_haas_g110_selects_an_offset_the_profile_does_not_give(tmp_path: Path) -> None:
    """Review 76 F2: a Haas's G110-G129 select the additional work offsets #7-#26 (G154
    P1-P20): the positions after one are not judged under the G55 before it, inline or after
    a call of a body that writes it."""
    profile = tmp_path / "wo2h.toml"
    profile.write_text('name = "wo-haas"\nbase = "haas-mill"\n[limits]\nX = [-30.0, 30.0]\n'
                       "Y = [-16.0, 16.0]\nZ = [-20.0, 0.5]\n[work_offsets]\n"
                       "G54 = { X = 0.0, Y = 0.0, Z = 0.0 }\n"
                       "G55 = { X = -4.0, Y = 0.0, Z = 0.0 }\n")
    head = "O01000 / G20 G17 G90 G55 / G0 X0 Y0 / "
    assert said(head + "G110 / G0 X-27. / M30", str(profile)) == []
    assert said("O02000 / G0 X-5. / G129 / M99 / " + head + "M98 P2000 / G0 X-27. / M30",
                str(profile)) == []
    # (without it, under G55: -31)
    assert [g[:2] for g in said(head + "G0 X-27. / M30", str(profile))] == [(4, 4)]


def test_linuxcnc_m72_restores_the_work_offset_m70_saved_before_a_call(lcnc: str) -> None:
    """Review 76 F3: M72 restores the work offset M70 saved (rs274 -g: SET_G5X_OFFSET(1) at
    the M72): the call after it, and an inline move, are judged under it, not under the G55
    between (lcnc76b's restore, merged with calls76's calls)."""
    # (G55 saved, G54 between: the M72 gives G55 back, and the call runs at -800)
    assert [g[:2] for g in said(DEF + "G21 G17 G90 G55 / G0 X0 Y0 / M70 / G54 / M72 / "
                                "o100 call / M2", lcnc)] == [(9, 1)]
    assert said(DEF + "G21 G17 G90 G54 / G0 X0 Y0 / o100 call / M70 / G55 / M72 / o100 call / "
                "M2", lcnc) == []
    assert said("G21 G17 G90 G54 / G0 X0 Y0 / M70 / G55 / M72 / G0 X-700 / M2", lcnc) == []
    # (a G55 selected after the M72: judged again)
    assert [g[:2] for g in said("G21 G90 G54 / G0 X0 Y0 / M70 / M72 / G55 / G0 X-700 / M2",
                                lcnc)] == [(6, 4)]


def test_a_conditional_offset_variable_write_leaves_the_offsets_not_known(fanuc: str) -> None:
    """Review 76 F4: `IF [#1 EQ 1] THEN #5241=0.` may set G55's X to 0: the positions after
    it, inline, after a call of a body holding it, or at the body's later call, are not
    judged under the profile's G55."""
    assert said("O1000 / G21 G17 G90 G55 / G0 X0 Y0 / IF [#1 EQ 1] THEN #5241=0. / "
                "G0 X-700. / M30", fanuc) == []
    assert said("O2000 / G0 X-10. / IF [#1 EQ 1] THEN #5241=0. / M99 / O1000 / "
                "G21 G17 G90 G55 / G0 X0 Y0 / M98 P2000 / G0 X-700. / M30", fanuc) == []
    assert said("O2000 / G0 X-700. / IF [#1 EQ 1] THEN #5241=0. / M99 / " + AFTER
                + "M98 P2000 / G55 / M98 P2000 / M30", fanuc) == []
    # (another variable in the IF-THEN: judged as before)
    assert [g[:2] for g in said("O1000 / G21 G17 G90 G55 / G0 X0 Y0 / IF [#1 EQ 1] THEN "
                                "#101=0. / G0 X-700. / M30", fanuc)] == [(5, 4)]


def test_a_linuxcnc_definition_no_call_names_is_not_judged_under_its_own_offset(
        lcnc: str) -> None:
    """Review 76 F5: rs274 never runs a definition the file does not call: its positions under
    a G55 of its own are not said (as before the definitions were read with no offset)."""
    assert said("G21 G90 G54 / G0 X0 / o100 sub / G55 / G0 X-700 / o100 endsub / M2",
                lcnc) == []
    assert said("o100 sub / G55 / G0 X-700 / o100 endsub / G21 G90 G54 / G0 X0 / M2",
                lcnc) == []


@pytest.mark.parametrize("blocks", [
    # (review 76 F6: both calls under G54, the main's G55 after them: -700, not said)
    "M98 P2000 / G54 / M98 P2000 / G55 / M30 / O2000 / G0 X-700. / M99",
    # (z8: a call of a body read before in front)
    "M98 P2001 / M98 P2000 / G54 / M98 P2000 / G55 / M30 / O2000 / G0 X-700. / M99",
])
def test_a_body_after_calls_under_one_offset_is_not_read_under_the_main_s_last(
        fanuc: str, blocks: str) -> None:
    text = "O2001 / G0 X-10. / M99 / " + AFTER + blocks
    assert said(text, fanuc) == []


@pytest.mark.parametrize("text", [
    # (review 76 F7: the body's G10 writes G54's X: the G55 call's -800 stays)
    AFTER + "M98 P2000 / G55 / M98 P2000 / M30 / O2000 / G0 X-700. / G10 L2 P1 X0. / M99",
    # (F8: another program written after it, called or not)
    AFTER + "M98 P2000 / G55 / M98 P2000 / M98 P2001 / M30 / O2000 / G0 X-700. / M99 / "
    "O2001 / G0 X-10. / M99",
])
def test_a_later_call_s_finding_stays_where_its_offset_is_untouched(fanuc: str,
                                                                   text: str) -> None:
    assert [g[2][:14] for g in said(text, fanuc)] == ["X goes to -800"]


def test_linuxcnc_m72_restores_the_offset_m70_saved(lcnc: str) -> None:
    """Review 76 F9: M72 with no selection since M70 leaves G55 in force: -800 said."""
    assert [g[:2] for g in said("G21 G17 G90 G55 / G0 X0 Y0 / M70 / G0 X-10 / M72 / G0 X-700 / "
                                "M2", lcnc)] == [(6, 4)]


def test_a_linuxcnc_definition_that_selects_another_system_loses_the_offsets_at_its_call(
        lcnc: str) -> None:
    """A definition read before its call that selects G59.1 (a system the profile does not
    give) leaves it in force after its call (rs274 -g: SET_G5X_OFFSET(7) in the body): the
    caller's `G0 X-700` after the call is not judged under the G55 before it (a false -800
    of the first merge of calls76 and lcnc76b, review 76-calls76's t/l72)."""
    assert said("o100 sub / G0 X-10 / G59.1 / o100 endsub / G21 G90 G55 / G0 X0 / o100 call / "
                "G0 X-700 / M2", lcnc) == []
    # (a definition that changes no system: the caller's move judged under G55 as before)
    assert [g[:2] for g in said("o100 sub / G0 X-10 / o100 endsub / G21 G90 G55 / G0 X0 / "
                                "o100 call / G0 X-700 / M2", lcnc)] == [(7, 4)]


@pytest.fixture
def haas(tmp_path: Path) -> str:
    """A Haas mill in inches, X travel -30..30, G55 X-4 (`G0 X-29.` at -33 under it)."""
    profile = tmp_path / "woh.toml"
    profile.write_text('name = "wo-haas"\nbase = "haas-mill"\n[limits]\nX = [-30.0, 30.0]\n'
                       'Y = [-16.0, 16.0]\nZ = [-20.0, 0.4]\n[work_offsets]\n'
                       'G54 = { X = 0.0, Y = 0.0, Z = 0.0 }\n'
                       'G55 = { X = -4.0, Y = 0.0, Z = 0.0 }\n')
    return str(profile)


LOCAL = "% / O1000 / G20 G17 G90 G54 / G0 X0 Y0 / "


@pytest.mark.parametrize("blocks, expected", [
    # (the everyday multi-fixture program: one local subprogram called under G54, then G55)
    ("M97 P1000 / G55 / M97 P1000 / M30 / N1000 G0 X-29. / M99 / %",
     [(9, 10, "X goes to -33", "N1000 runs as called by M97 P1000 of line 7")]),
    # (one call, under G55)
    ("G55 / M97 P1000 / M30 / N1000 G0 X-29. / M99 / %",
     [(8, 10, "X goes to -33", "N1000 runs as called by M97 P1000 of line 6")]),
    # (the main's G54 at its end does not place the body)
    ("M97 P1000 / G55 / M97 P1000 / G54 / M30 / N1000 G0 X-29. / M99 / %",
     [(10, 10, "X goes to -33", "N1000 runs as called by M97 P1000 of line 7")]),
    # (repeated by L: under the offset of its call)
    ("G55 / M97 P1000 L2 / M30 / N1000 G0 X-29. / M99 / %",
     [(8, 10, "X goes to -33", "N1000 runs as called by M97 P1000 of line 6")]),
    # (its move before a G54 or a call of its own: run at the call's offset)
    ("M97 P1000 / G55 / M97 P1000 / M30 / N1000 G0 X-29. / G54 / M99 / %",
     [(9, 10, "X goes to -33", "N1000 runs as called by M97 P1000 of line 7")]),
    # (a main program that ends by M99, its local subprogram after it: review 77 F0's h108)
    ("G55 / M97 P1000 / M99 / N1000 G0 X-29. / M99 / %",
     [(8, 10, "X goes to -33", "N1000 runs as called by M97 P1000 of line 6")]),
])
def test_a_haas_local_subprogram_is_judged_under_its_calls_offsets(
        haas: str, blocks: str, expected: list[tuple[int, int, str, str]]) -> None:
    got = said(LOCAL + blocks, haas)
    assert [(line, col, msg.split(" in machine")[0], msg.split("(")[-1].split(":")[0])
            for line, col, msg in got] == expected


@pytest.mark.parametrize("blocks", [
    # (its G10 after the move writes G55's X before the second call: -29 there)
    "M97 P1000 / G55 / M97 P1000 / M30 / N1000 G0 X-29. / G10 L2 P2 X0. / M99 / %",
    # (the main's G10 before the calls)
    "G10 L2 P2 X0. / M97 P1000 / G55 / M97 P1000 / M30 / N1000 G0 X-29. / M99 / %",
    # (a work offset's variable)
    "M97 P1000 / G55 / M97 P1000 / M30 / N1000 G0 X-29. / #5241=0. / M99 / %",
    # (its run in G91)
    "M97 P1000 / G55 / M97 P1000 / M30 / N1000 G91 G0 X-29. / M99 / %",
    # (a G91 it leaves: the second call's mode)
    "M97 P1000 / G55 / M97 P1000 / M30 / N1000 G0 X-29. / G91 / M99 / %",
    # (a return elsewhere, an end: the second call may not run)
    "M97 P1000 / G55 / M97 P1000 / M30 / N1000 G0 X-29. / M99 P10 / %",
    "M97 P1000 / G55 / M97 P1000 / M30 / N1000 G0 X-29. / M30 / %",
    # (a G52 at the calls, a G110 (an offset the profile does not give), a jump before)
    "G52 X2. / M97 P1000 / G55 / M97 P1000 / M30 / N1000 G0 X-29. / M99 / %",
    "G110 / M97 P1000 / M30 / N1000 G0 X-29. / M99 / %",
    "M97 P1000 / G110 / M97 P1000 / M30 / N1000 G0 X-29. / M99 / %",
    "IF [#1 EQ 1] GOTO 10 / G55 / N10 M97 P1000 / M30 / N1000 G0 X-29. / M99 / %",
    # (a nested local call that writes G55's X)
    "M97 P1000 / G55 / M97 P1000 / M30 / N1000 G0 X-29. / M97 P2000 / M99 / "
    "N2000 G10 L2 P2 X0. / M99 / %",
    # (calls in other units, a sequence number no call names, a P no block has)
    "G55 / G20 / M97 P1000 / G21 / M97 P1000 / M30 / N1000 G0 X-29. / M99 / %",
    "G55 / M97 P3000 / M30 / N1000 G0 X-29. / M99 / %",
    # (review 77 F2: a local subprogram's own M97, not followed, of a section that writes
    # G55's X or leaves a G52: the main's move after the call is not judged under G55's
    # value)
    "M97 P1000 / G90 G55 / G0 X-27. / M30 / N1000 M97 P2000 / M99 / N2000 G10 L2 P2 X0. / "
    "M99 / %",
    "M97 P1000 / G90 G55 / G0 X-27. / M30 / N1000 M97 P2000 / M99 / N2000 G52 X4. / M99 / %",
])
def test_a_haas_local_subprogram_stays_silent_where_its_offset_is_not_known(
        haas: str, blocks: str) -> None:
    assert said(LOCAL + blocks, haas) == []


LATER = "G21 G17 G90 G54 / G0 X0 Y0 / "


@pytest.mark.parametrize("blocks, expected", [
    # (a definition after M2, called before it: rs274 -g runs its STRAIGHT_TRAVERSE(-700)
    # at the call, after the call's SET_G5X_OFFSET(2))
    ("G55 / o100 call / M2 / o100 sub / G0 X-700 / o100 endsub",
     [(7, 4, "X goes to -800", "o100 runs as called by o100 call of line 4")]),
    # (one call under G54, one under G55: the second's)
    ("o100 call / G55 / o100 call / M2 / o100 sub / G0 X-700 / o100 endsub",
     [(8, 4, "X goes to -800", "o100 runs as called by o100 call of line 5")]),
    # (a named label, a return after the move)
    ("G55 / o<abc> call / M2 / o<abc> sub / G0 X-700 / o<abc> return / o<abc> endsub",
     [(7, 4, "X goes to -800", "o<abc> runs as called by o<abc> call of line 4")]),
    # (called in inches: -28 in, -711.2 mm, -811.2 under G55)
    ("G20 / G55 / o100 call / M2 / o100 sub / G0 X-28 / o100 endsub",
     [(8, 4, "X goes to -811.2", "o100 runs as called by o100 call of line 5")]),
    # (the main's own move after a G55 of its own after the call: the body writes nothing)
    ("o100 call / G55 / G90 G0 X-700 / M2 / o100 sub / G0 X0 / o100 endsub",
     [(5, 8, "X goes to -800", "work -700 + G55 offset -100.0), outside the travel -762 to "
       "762")]),
])
def test_a_linuxcnc_definition_after_the_end_is_judged_under_its_calls_offsets(
        lcnc: str, blocks: str, expected: list[tuple[int, int, str, str]]) -> None:
    got = said(LATER + blocks, lcnc)
    assert [(line, col, msg.split(" in machine")[0], msg.split("(")[-1].split(":")[0])
            for line, col, msg in got] == expected


@pytest.mark.parametrize("blocks", [
    # (its G10 or variable write after the move, before the second call: G55's X is 0 there)
    "o100 call / G55 / o100 call / M2 / o100 sub / G0 X-700 / G10 L2 P2 X0 / o100 endsub",
    "o100 call / G55 / o100 call / M2 / o100 sub / G0 X-700 / #5241=0 / o100 endsub",
    # (a system the profile does not give, its run in G91, a G91 it leaves)
    "o100 call / G55 / o100 call / M2 / o100 sub / G59.1 / G0 X-700 / o100 endsub",
    "o100 call / G55 / o100 call / M2 / o100 sub / G91 G0 X-700 / o100 endsub",
    "o100 call / G55 / o100 call / M2 / o100 sub / G0 X-700 / G91 / o100 endsub",
    # (its first run ends the program: the second call never runs)
    "o100 call / G55 / o100 call / M2 / o100 sub / G0 X-700 / M2 / o100 endsub",
    # (a G92 shift at the call, a call inside a condition, an M72 restore between)
    "G0 X-250 Y0 / G92 X-400 / o100 call / M2 / o100 sub / G0 X700 / o100 endsub",
    "o1 if [#1 GT 0] / o100 call / o1 endif / G55 / o100 call / M2 / o100 sub / G0 X-700 / "
    "o100 endsub",
    "M70 / G55 / o100 call / M72 / o100 call / M2 / o100 sub / G0 X-700 / o100 endsub",
    # (a G10 or variable write of the main's before the call)
    "G55 / G10 L2 P2 X0 / o100 call / M2 / o100 sub / G0 X-700 / o100 endsub",
    "#5241=0 / G55 / o100 call / M2 / o100 sub / G0 X-700 / o100 endsub",
    # (the main's move after a G10 of the body's; the move after the call with no G54-G59 of
    # its own, where the body writes no offset: judged since calls80, test_calls_resumed.py)
    "o100 call / G55 / G90 G0 X-700 / M2 / o100 sub / G0 X0 / G10 L2 P2 X0 / o100 endsub",
    # (called only from another definition after the end)
    "G55 / o200 call / M2 / o100 sub / G0 X-700 / o100 endsub / o200 sub / o100 call / "
    "o200 endsub",
    # (review 77 F1: the definition calls another after it that writes G55's X (rs274 -g:
    # SET_G5X_OFFSET(2, 0, ...) at the call, the G55's move then at -700), or a subroutine
    # the file does not hold: the main's move after the call is not judged under G55's value)
    "o100 call / G55 / G0 X-700 / M2 / o100 sub / o200 call / o100 endsub / o200 sub / "
    "G10 L2 P2 X0 / o200 endsub",
    "o100 call / G55 / G0 X-700 / M2 / o100 sub / G0 X-10 / o<ext> call / o100 endsub",
])
def test_a_linuxcnc_definition_after_the_end_stays_silent_where_not_known(
        lcnc: str, blocks: str) -> None:
    assert said(LATER + blocks, lcnc) == []


def test_the_main_s_move_after_an_m97_is_judged_where_the_body_changes_nothing(haas: str) -> None:
    """The caller's G90 read on across an M97 (review 77-calls77 F5), its G55 after the call
    the profile's where the body writes no offset: -33."""
    got = said(LOCAL + "M97 P1000 / G55 / G0 X-29. / M30 / N1000 G0 X0. / M99 / %", haas)
    assert [(line, msg.split(" in machine")[0]) for line, _, msg in got] == [(7, "X goes to -33")]


@pytest.mark.parametrize("blocks, expected", [
    # (review 77-calls77 F10, h176: N100 leaves G91, the main's `G0 X-27.` after the call is
    # an increment: N100 leaves X at machine 5, G55 work 9, 9 - 27 = -18, machine -22, inside;
    # not -31)
    ("M97 P100 / G55 / G0 X-27. / M30 / N100 G91 G0 X5. / M99 / %", []),
    # (h170: the same body, the main's X32.5 an increment to 32.5 from -28: no span of 60.5)
    ("G0 X-28. / M97 P100 / G0 X32.5 / M30 / N100 G91 G0 Y0 / M99 / %", []),
    # (the body writes G91 and then G90: it leaves the call's G90, the move judged, -31)
    ("M97 P100 / G55 / G0 X-27. / M30 / N100 G91 G0 X5. / G90 / M99 / %",
     [(7, "X goes to -31")]),
    # (the body writes no G90/G91: as before, -31)
    ("M97 P100 / G55 / G0 X-27. / M30 / N100 G0 X5. / M99 / %", [(7, "X goes to -31")]),
    # (the main's own G90 after the call: its moves from there are its own mode's, -31)
    ("M97 P100 / G55 / G90 G0 X-27. / M30 / N100 G91 G0 X5. / M99 / %",
     [(7, "X goes to -31")]),
    # (review 78 F1, h45: N100 leaves G91, then N200 writes G90: the main's move after both
    # is absolute, -31; h72: N200 writes none, N100's G91 holds: -27 an increment, -26)
    ("M97 P100 / M97 P200 / G55 / G0 X-27. / M30 / N100 G91 G0 X5. / M99 / N200 G90 G0 X0 / "
     "M99 / %", [(8, "X goes to -31")]),
    ("M97 P100 / M97 P200 / G55 / G0 X-27. / M30 / N100 G91 G0 X5. / M99 / N200 G0 Y1. / "
     "M99 / %", []),
    # (review 78 F2, h64: line 7 an increment (-26, inside), line 8 the main's own G90:
    # -28 under G55, machine -32, said on its own)
    ("M97 P100 / G55 / G0 X-27. / G90 G0 X-28. / M30 / N100 G91 G0 X5. / M99 / %",
     [(8, "X goes to -32")]),
    # (review 78 F7, h85: the main's own G91 after the held move: increments from a position
    # read in the wrong mode, not said (real: -22, then -23, inside); h84: a body that writes
    # no G90/G91, the excursion said once, at line 7)
    ("M97 P100 / G55 / G0 X-27. / G91 G0 X-1. / M30 / N100 G91 G0 X5. / M99 / %", []),
    ("M97 P100 / G55 / G0 X-27. / G90 G0 X-28. / M30 / N100 G0 Y1. / M99 / %",
     [(7, "X goes to -31")]),
    # (review 78 F2b, h67: line 6 an increment to 4.5, line 7 `G90 G0 X32.6`: the program
    # spans -28 .. 32.6 = 60.6 whatever N100 leaves; said there, from the span before the call)
    ("G0 X-28. / M97 P100 / G0 X32.5 / G90 G0 X32.6 / M30 / N100 G91 G0 Y0 / M99 / %",
     [(8, "X spans 60.6 (from -28 to 32.6), more than the travel -30 to 30: no work offset "
          "fits the program on this machine")]),
    # (no N100 in the file: the control alarms at the call (TG118), nothing judged after it,
    # as before)
    ("M97 P100 / G55 / G0 X-27. / M30 / %", []),
])
def test_the_main_s_moves_after_an_m97_wait_for_the_mode_its_body_leaves(
        haas: str, blocks: str, expected: list[tuple[int, str]]) -> None:
    """G90/G91 are modal and M99 restores neither: the main's moves after an M97 whose body
    is read after M30 run in the mode the body leaves (review 77-calls77 F10)."""
    got = said(LOCAL + blocks, haas)
    assert [(line, msg.split(" in machine")[0]) for line, _, msg in got] == expected


@pytest.mark.parametrize("blocks, expected", [
    # (rs274 -g: STRAIGHT_TRAVERSE(100) in o100, then SET_G5X_OFFSET(2) and
    # STRAIGHT_TRAVERSE(-600) with every offset 0; under G55 X-100 the body leaves machine 100,
    # G55 work 200, the main's X-700 an increment to work -500, machine -600, inside)
    ("o100 call / G55 / G0 X-700 / M2 / o100 sub / G91 G0 X100 / o100 endsub", []),
    # (rs274 -g: STRAIGHT_TRAVERSE(-700) after SET_G5X_OFFSET(2): machine -800)
    ("o100 call / G55 / G0 X-700 / M2 / o100 sub / G0 X5 / o100 endsub",
     [(5, "X goes to -800")]),
])
def test_the_main_s_moves_after_a_later_definition_wait_for_the_mode_it_leaves(
        lcnc: str, blocks: str, expected: list[tuple[int, str]]) -> None:
    got = said(LATER + blocks, lcnc)
    assert [(line, msg.split(" in machine")[0]) for line, _, msg in got] == expected


@pytest.mark.parametrize("blocks, expected", [
    # (review 77-calls77 F9, h172: N100 leaves G21, the second call (under G55) runs its
    # `G0 X-27.` in millimetres: -1.063 in, machine -5.063: inside, no -31)
    ("M97 P100 / G55 / M97 P100 / M30 / N100 G0 X-27. / G21 / M99 / %", []),
    # (it leaves the call's G20: -31 at the second call, as before)
    ("M97 P100 / G55 / M97 P100 / M30 / N100 G0 X-27. / G20 / M99 / %",
     [(9, "X goes to -31")]),
    # (its move after its own G21 runs in millimetres at both calls: -800 mm is -31.496 in,
    # under G54 at -31.496, under G55 at -35.496; the -27 before the G21 is -5.063 at the
    # second call)
    ("M97 P100 / G55 / M97 P100 / M30 / N100 G0 X-27. / G21 / G0 X-800. / M99 / %",
     [(11, "X goes to -31.496063"), (11, "X goes to -35.496063")]),
    # (it leaves G21 and a G54 of its own: the main's G55 before the second call, -5.063)
    ("M97 P100 / G55 / M97 P100 / M30 / N100 G0 X-27. / G21 / G54 / M99 / %", []),
])
def test_a_haas_local_subprogram_s_second_call_runs_in_the_units_it_leaves(
        haas: str, blocks: str, expected: list[tuple[int, str]]) -> None:
    """G20/G21 are modal and M99 restores neither: a call after the first runs the body's
    positions before its own units code in the units the first run leaves."""
    got = said(LOCAL + blocks, haas)
    assert [(line, msg.split(" in machine")[0]) for line, _, msg in got] == expected


@pytest.mark.parametrize("text, expected", [
    # (review 77-calls77 F7, f13: O2000 leaves G20: the second call's `G0 X-700.` is -700 in,
    # -17780 mm, machine -17880 under G55)
    ("O1000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P2000 / G55 / M98 P2000 / M30 / O2000 / "
     "G0 X-700. / G20 / M99", [(9, "X goes to -17880", True)]),
    # (-300 mm inside under both offsets; -300 in, -7620 mm, is not)
    ("O1000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P2000 / G55 / M98 P2000 / M30 / O2000 / "
     "G0 X-300. / G20 / M99", [(9, "X goes to -7720", True)]),
    # (its own G21 before the move: millimetres at both calls, -800)
    ("O1000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P2000 / G55 / M98 P2000 / M30 / O2000 / "
     "G21 / G0 X-700. / G20 / M99", [(10, "X goes to -800", False)]),
    # (the main's own G21 between the calls: the second runs in it, -800 as before)
    ("O1000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P2000 / G21 / G55 / M98 P2000 / M30 / "
     "O2000 / G0 X-700. / G20 / M99", [(10, "X goes to -800", False)]),
    # (a G10 of G55's X after the move: not known, as before)
    ("O1000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P2000 / G55 / M98 P2000 / M30 / O2000 / "
     "G0 X-700. / G20 / G10 L2 P2 X0 / M99", []),
])
def test_a_later_program_s_second_call_runs_in_the_units_it_leaves(
        fanuc: str, text: str, expected: list[tuple[int, str, bool]]) -> None:
    got = said(text, fanuc)
    assert [(line, msg.split(" in machine")[0], ", in inches: the units" in msg)
            for line, _, msg in got] == expected


def test_a_later_definition_s_second_call_runs_in_the_units_it_leaves(lcnc: str) -> None:
    """rs274 -g: `STRAIGHT_TRAVERSE(-300)` in millimetres at the first call, then
    `USE_LENGTH_UNITS(CANON_UNITS_INCHES)`, `SET_G5X_OFFSET(2)` and `STRAIGHT_TRAVERSE(-300)`
    in inches: -7620 mm, machine -7720 (review 77-calls77 F4)."""
    got = said(LATER + "o100 call / G55 / o100 call / M2 / o100 sub / G0 X-300 / G20 / "
               "o100 endsub", lcnc)
    assert [(line, msg.split(" in machine")[0]) for line, _, msg in got] == \
        [(8, "X goes to -7720")]


# Issue 32 item 4, calls after a jump or inside a loop (callflow.rs): FANUC Custom Macro B,
# "WHILE [conditional expression] DO m ... END m" runs the blocks between while the
# condition holds, "IF [conditional expression] GOTO n" jumps where it holds; the offsets and
# G90/G91, G20/G21 are modal, so where nothing after the first jump changes them, every pass
# and every path reaches the call under the offset in force at the jump.
MAIN = "O1000 / G21 G17 G90 G54 / G0 X0 Y0 / G55 / #1=0 / "
LOOP = "WHILE [#1 LT 3] DO1 / M98 P2000 / "
LATER_BODY = " / O2000 / G0 X-700. / M99"


@pytest.mark.parametrize("text, expected", [
    # (a body read after the main, called in a loop: each pass runs X-700. under G55, machine
    # -700 - 100 = -800; said at the body's line, naming the call of line 7)
    (MAIN + LOOP + "#1=#1+1 / END1 / M30" + LATER_BODY, [(12, "X goes to -800")]),
    # (read before the main: said at the call, line 10)
    (BODY.replace("G0 X0 Y0 / ", "G0 X0 Y0 / G55 / #1=0 / ") + LOOP + "#1=#1+1 / END1 / M30",
     [(10, "X goes to -800")]),
    # (after a conditional jump forward over a block that changes nothing: both paths reach
    # the call under G55)
    (MAIN + "IF [#1 EQ 1] GOTO 10 / G0 Y1. / N10 M98 P2000 / M30" + LATER_BODY,
     [(11, "X goes to -800")]),
    # (under G54 the same body runs at -700, inside: nothing)
    (MAIN.replace("G55", "G54") + LOOP + "#1=#1+1 / END1 / M30" + LATER_BODY, []),
    # (the jump passes over a G54: one path reaches the call under G54 (-700), the other
    # under G55 (-800); not known there, nothing said)
    (MAIN + "IF [#1 EQ 1] GOTO 10 / G54 / N10 M98 P2000 / M30" + LATER_BODY, []),
    # (a selection, a G10, a work offset variable, a G91, a G20, a G52, a G43 after the call
    # inside the loop: the next pass runs under another offset or mode; nothing said)
    (MAIN + LOOP + "G56 / #1=#1+1 / END1 / M30" + LATER_BODY, []),
    (MAIN + LOOP + "G10 L2 P2 X0. / #1=#1+1 / END1 / M30" + LATER_BODY, []),
    (MAIN + LOOP + "#5241=0 / #1=#1+1 / END1 / M30" + LATER_BODY, []),
    (MAIN + LOOP + "G91 G0 X1. / G90 / #1=#1+1 / END1 / M30" + LATER_BODY, []),
    (MAIN + LOOP + "G20 / #1=#1+1 / END1 / M30" + LATER_BODY, []),
    (MAIN + LOOP + "G52 X50. / #1=#1+1 / END1 / M30" + LATER_BODY, []),
    (MAIN + LOOP + "G43 H1 Z0. / #1=#1+1 / END1 / M30" + LATER_BODY, []),
    # (a second body read later in the loop may change what the first runs under at its
    # next pass: nothing)
    (MAIN + LOOP + "M98 P3000 / #1=#1+1 / END1 / M30" + LATER_BODY + " / O3000 / "
     "G10 L2 P2 X0. / M99", []),
    # (the call reached only by a jump back from after the M30, past a G54 there: it runs
    # once, under G54, -700, inside; review 79-calls79 F1)
    ("O1000 / G21 G17 G90 G55 / G0 X0 Y0 / GOTO 20 / N10 M98 P2000 / M30 / N20 G54 / "
     "GOTO 10 / M30" + LATER_BODY, []),
    # (`G#2`, #2 = 54, in the loop: a G code not known after the jump; review 79-calls79 F2)
    (MAIN + "#2=54 / WHILE [#1 LT 2] DO1 / G#2 / M98 P2000 / #1=#1+1 / END1 / M30"
     + LATER_BODY, []),
    # (a loop the known values never enter, and an `IF .. THEN` that may select: nothing;
    # review 79-calls79 F3)
    (MAIN.replace("#1=0", "#1=5") + LOOP + "#1=#1+1 / END1 / M30" + LATER_BODY, []),
    (MAIN + "IF [#3 EQ 1] THEN G54 / M98 P2000 / M30" + LATER_BODY, []),
    # (a local variable's assignment by THEN changes no offset: said)
    (MAIN + LOOP + "IF [#1 EQ 0] THEN #2=1 / #1=#1+1 / END1 / M30" + LATER_BODY,
     [(13, "X goes to -800")]),
    # (a jump back to a call before the selection: the first pass under G54, -700, inside;
    # the jump's passes under G55 are not judged, nothing said)
    ("O1000 / G21 G17 G90 G54 / G0 X0 Y0 / #1=0 / N10 M98 P2000 / G55 / #1=#1+1 / "
     "IF [#1 LT 3] GOTO 10 / M30" + LATER_BODY, []),
])
def test_a_call_after_a_jump_or_in_a_loop_is_judged_where_every_path_agrees(
        fanuc: str, text: str, expected: list[tuple[int, str]]) -> None:
    got = said(text, fanuc)
    assert [(line, msg.split(" in machine")[0]) for line, _, msg in got] == expected


def test_a_body_read_before_called_in_a_loop_that_changes_the_offset_is_not_judged(
        fanuc: str) -> None:
    """A body read before, held at its call in the loop, is dropped at the main's end where
    the loop's G10 after the call changes what its next pass runs under."""
    text = (BODY.replace("G0 X0 Y0 / ", "G0 X0 Y0 / G55 / #1=0 / ") + LOOP
            + "G10 L2 P2 X0. / #1=#1+1 / END1 / M30")
    assert said(text, fanuc) == []


@pytest.mark.parametrize("blocks, expected", [
    # (Haas Mill Operator's Manual, M97 and the macros' WHILE/DO/END, IF/GOTO: each pass of the
    # loop runs N1000's X-29. under G55, machine -29 - 4 = -33)
    ("G55 / #1=0 / WHILE [#1 LT 3] DO1 / M97 P1000 / #1=#1+1 / END1 / M30 / N1000 G0 X-29. / "
     "M99 / %", [(12, "X goes to -33")]),
    ("G55 / IF [#1 EQ 1] GOTO 10 / G0 Y1. / N10 M97 P1000 / M30 / N1000 G0 X-29. / M99 / %",
     [(10, "X goes to -33")]),
    # (a G55 after the call in the loop: the first pass under G54 (-29, inside), the next
    # under G55; nothing said)
    ("#1=0 / WHILE [#1 LT 3] DO1 / M97 P1000 / G55 / #1=#1+1 / END1 / M30 / N1000 G0 X-29. / "
     "M99 / %", []),
    # (the jump passes over a G54: not known at the call)
    ("G55 / IF [#1 EQ 1] GOTO 10 / G54 / N10 M97 P1000 / M30 / N1000 G0 X-29. / M99 / %", []),
    # (a G54 after M30 that a jump reaches before the call: -29 there, -33 on the other path;
    # review 79-calls79 F5)
    ("G55 / IF [#500 EQ 1] GOTO 20 / N10 M97 P1000 / M30 / N20 G54 / GOTO 10 / "
     "N1000 G0 X-29. / M99 / %", []),
    ("G55 / IF [#500 EQ 1] GOTO 20 / N10 M97 P1000 / M30 / N1000 G0 X-29. / M99 / "
     "N20 G54 / GOTO 10 / %", []),
])
def test_a_haas_local_call_after_a_jump_or_in_a_loop(haas: str, blocks: str,
                                                    expected: list[tuple[int, str]]) -> None:
    got = said(LOCAL + blocks, haas)
    assert [(line, msg.split(" in machine")[0]) for line, _, msg in got] == expected


def test_a_g53_position_of_a_body_in_a_loop_is_said_whatever_the_offset(fanuc: str) -> None:
    """Review 79-calls79 F4: `G53 G0 X-800.` runs at machine -800 at every pass whatever the
    loop's G54 after the call does: said at the call as before, only the positions judged
    through the offset are held."""
    text = ("O2000 / G53 G0 X-800. / M99 / O1000 / G21 G17 G90 G55 / G0 X0 Y0 / #1=0 / "
            "WHILE [#1 LT 2] DO1 / M98 P2000 / G54 / #1=#1+1 / END1 / M30")
    got = said(text, fanuc)
    assert [(line, msg.split(" in machine")[0]) for line, _, msg in got] == \
        [(9, "X goes to -800")]


def test_a_third_call_runs_in_the_units_the_second_leaves(fanuc: str, tmp_path: Path) -> None:
    """Review 78-calls78 F6: the caller's units code before the second call makes that call's
    units its own, not the third's: O2000 leaves G20 after the second call, and with no units
    code of the caller's before the third (G56) it runs `X-29.` in inches, -736.6 mm, machine
    -736.6 - 200 = -936.6 (the G55 call in the caller's G21: -129, inside)."""
    got = said("O1000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P2000 / G21 G55 / M98 P2000 / G56 / "
               "M98 P2000 / M30 / O2000 / G0 X-29. / G20 / M99", fanuc)
    assert [(line, msg.split(" in machine")[0]) for line, _, msg in got] == \
        [(11, "X goes to -936.6")]
    # (the Haas mirror, inches, G55 and G56 X-4: N100 leaves G21; the G56 call runs X-27. in
    # millimetres, -1.06 in, machine -5.06, inside; the G55 call, after the main's G20, -31)
    profile = tmp_path / "woh3.toml"
    profile.write_text('name = "wo-haas"\nbase = "haas-mill"\n[limits]\nX = [-30.0, 30.0]\n'
                       'Y = [-16.0, 16.0]\nZ = [-20.0, 0.4]\n[work_offsets]\n'
                       'G54 = { X = 0.0, Y = 0.0, Z = 0.0 }\nG55 = { X = -4.0, Y = 0.0, Z = 0.0 }\n'
                       'G56 = { X = -4.0, Y = 0.0, Z = 0.0 }\n')
    got = said("O1000 / G20 G17 G90 G54 / G0 X0 Y0 / M97 P100 / G20 G55 / M97 P100 / G56 / "
               "M97 P100 / M30 / N100 G0 X-27. / G21 / M99", str(profile))
    assert [(line, msg.split("(work ")[1].split(")")[0]) for line, _, msg in got] == \
        [(10, "-27 + G55 offset -4.0")]
