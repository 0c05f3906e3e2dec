"""The caller's moves after a call of a body read later in the file, judged where the body
leaves the tool and in the G90/G91 it leaves (issue 32 item 4, calls80).

G90/G91 are modal and a return restores neither: FANUC 0i-F / 30i-B Operator's Manual,
"Subprogram call (M98)" and M99; Haas Mill Operator's Manual, M97/M98/M99; LinuxCNC keeps a
subroutine's G91 after its `endsub` (`rs274 -g` of the LinuxCNC twins below prints the
STRAIGHT_TRAVERSE figures quoted). The profiles: a FANUC mill and a LinuxCNC mill with X
travel -762..762 (mm), G54 X0, G55 X-100; a Haas mill in inches with X -30..30, G54 X0.
The checker reads the file in order, so at the caller's moves the body is not read yet;
main judged nothing there (the mode and the offsets taken as not known): each "said" case
below was silent on main, a real overtravel passing.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from formats.parser import parse_text
from formats.profile import load_profile
from postproc.check import Checker

_MM = ("[limits]\nX = [-762.0, 762.0]\nY = [-406.0, 406.0]\nZ = [-508.0, 10.0]\n"
       "[work_offsets]\nG54 = { X = 0.0, Y = 0.0, Z = 0.0 }\n"
       "G55 = { X = -100.0, Y = 0.0, Z = 0.0 }\n")
_INCH = ("[limits]\nX = [-30.0, 30.0]\nY = [-16.0, 16.0]\nZ = [-20.0, 20.0]\n"
         "[work_offsets]\nG54 = { X = 0.0, Y = 0.0, Z = 0.0 }\n"
         "G55 = { X = -4.0, Y = 0.0, Z = 0.0 }\n")


@pytest.fixture
def profiles(tmp_path: Path) -> dict[str, str]:
    out = {}
    for name, base, limits in [("fanuc", "fanuc-mill", _MM), ("lcnc", "linuxcnc", _MM),
                               ("haas", "haas-mill", _INCH)]:
        path = tmp_path / f"{name}.toml"
        path.write_text(f'name = "r-{name}"\nbase = "{base}"\n' + limits)
        out[name] = str(path)
    return out


def said(text: str, profile: str) -> list[tuple[int, int, str]]:
    """The TG601s of `text` (` / ` between blocks; line 1 is the first block): line,
    column and the message's start."""
    prof = load_profile(profile)
    program = text.replace(" / ", "\n") + "\n"
    found = Checker(prof, "<input>").run(parse_text(program, prof.dialect, errors="collect"))
    return [(f.line, f.column, f.message.split(" in machine")[0])
            for f in found if f.rule == "TG601"]


FANUC_MAIN = "O1000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P2000 / "


@pytest.mark.parametrize("after, body, expected", [
    # (the h48 class: O2000 leaves G91 and the tool at X0; 0 + 500 + 500 = 1000 > 762)
    ("G0 X500. / G0 X500.", "G91", [(6, 4, "X goes to 1000")]),
    # (it moves X by 10 first: 10 + 500 + 500 = 1010)
    ("G0 X500. / G0 X500.", "G91 G0 X10.", [(6, 4, "X goes to 1010")]),
    # (it leaves X at 700 absolute, then G91: 700 + 100 = 800)
    ("G0 X100.", "G90 G0 X700. / G91", [(5, 4, "X goes to 800")]),
    # (it writes no G90/G91: the caller's G90, X800. absolute, under G54: 800)
    ("G0 X800.", "G0 Y10.", [(5, 4, "X goes to 800")]),
    # (inside the travel in G91: 500 then 0; nothing)
    ("G0 X500. / G0 X-500.", "G91", []),
    # (review 78-calls78 F3's FANUC form: #1 is 0 where the IF is read, THEN G91 does not
    # run: O2000 leaves G90 and X800. is absolute)
    ("G0 X800.", "#1=0 / IF [#1 EQ 1] THEN G91", [(5, 4, "X goes to 800")]),
    # (#1 is 1: THEN G91 runs; its condition is not followed so: main's reading, silent;
    # the truth is 500, inside)
    ("G0 X500.", "#1=1 / IF [#1 EQ 1] THEN G91", []),
    # (a GOTO to the next block: the run goes on there, as if no jump; G91 left: 1000)
    ("G0 X500. / G0 X500.", "GOTO 10 / N10 G91", [(6, 4, "X goes to 1000")]),
    # (a GOTO past a block: not followed, silent as main)
    ("G0 X500. / G0 X500.", "GOTO 20 / N10 G90 / N20 G91", []),
    # (a position by a parameter, a call the checker does not follow: silent as main)
    ("G0 X500. / G0 X500.", "G91 G0 X#1", []),
    ("G0 X500. / G0 X500.", "G91 / M98 P3000 / M99 / O3000 / G90", []),
])
def test_fanuc_m98_of_a_later_program(profiles, after, body, expected):
    text = FANUC_MAIN + after + " / M30 / O2000 / " + body + " / M99"
    assert said(text, profiles["fanuc"]) == expected


@pytest.mark.parametrize("text, expected", [
    # (under G55, X-100: G91 left, -400 then -700 work, machine -500, -800)
    ("O1000 / G21 G17 G90 G55 / G0 X0 Y0 / M98 P2000 / G0 X-400. / G0 X-300. / M30 / "
     "O2000 / G91 / M99", [(6, 4, "X goes to -800")]),
    # (the caller in inches on a millimetre profile: 20 in + 20 in = 40 in, 1016 mm)
    ("O1000 / G20 G17 G90 G54 / G0 X0 Y0 / M98 P2000 / G0 X20. / G0 X20. / M30 / "
     "O2000 / G91 / M99", [(6, 4, "X goes to 1016")]),
    # (the call made under G91, O2000 writes G90: X800. absolute)
    ("O1000 / G21 G17 G90 G54 / G0 X0 Y0 / G91 / M98 P2000 / G0 X800. / M30 / "
     "O2000 / G90 / M99", [(6, 4, "X goes to 800")]),
    # (L2 runs it twice (0i-F "Subprogram call (M98)": L the repeat count): 10, 20, then
    # the caller's increments 520 and 1020 > 762)
    ("O1000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P2000 L2 / G0 X500. / G0 X500. / M30 / "
     "O2000 / G91 G0 X10. / M99", [(6, 4, "X goes to 1020")]),
    # (fanuc-mill's O format has eight digits (the 8-digit option): P22000 names O22000, not
    # in the file, no repeat of O2000; silent, as main)
    ("O1000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P22000 / G0 X500. / G0 X500. / M30 / "
     "O2000 / G91 G0 X10. / M99", []),
    # (a second call starts where the caller's moves after the first end: -200, 300, 100,
    # then 800 > 762; review 80-calls80 W1's start, the state's 500, would say 1000)
    ("O1000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P2000 / G0 X500. / M98 P2000 / G0 X700. / "
     "M30 / O2000 / G91 G0 X-200. / M99", [(7, 4, "X goes to 800")]),
    # (the same with the caller's X400.: -200, 200, 0, 400 inside; from the state's 400 the
    # second run would be placed at 200 and the last at 600, inside as well)
    ("O1000 / G21 G17 G90 G54 / G0 X0 Y0 / M98 P2000 / G0 X400. / M98 P2000 / G0 X400. / "
     "M30 / O2000 / G91 G0 X-200. / M99", []),
])
def test_fanuc_offsets_units_and_repeats(profiles, text, expected):
    assert said(text, profiles["fanuc"]) == expected


@pytest.mark.parametrize("text, expected", [
    # (M97 of a local N100 after M30 leaving G91: 20 + 20 = 40 in > 30)
    ("O01000 / G20 G17 G90 G54 / G0 X0 Y0 / M97 P100 / G0 X20. / G0 X20. / M30 / "
     "N100 G91 / M99", [(6, 4, "X goes to 40")]),
    # (M98 of an O02000 after M30, the same)
    ("O01000 / G20 G17 G90 G54 / G0 X0 Y0 / M98 P2000 / G0 X20. / G0 X20. / M30 / "
     "O02000 / G91 / M99", [(6, 4, "X goes to 40")]),
    # (F3's Haas form: #1 set 0 in the body, THEN G91 does not run: X31. absolute)
    ("O01000 / G20 G17 G90 G54 / G0 X0 Y0 / M97 P100 / G0 X31. / M30 / "
     "N100 #1=0 / IF [#1 EQ 1] THEN G91 / M99", [(5, 4, "X goes to 31")]),
    # (review 80-calls80 R1: main's held "X spans" at line 6 is dropped at the return (N100
    # leaves G91); the real position, -28 + 61 = 33 > 30, is said in its place)
    ("O01000 / G20 G17 G90 G54 / G0 X-28. / M97 P100 / G0 X61. / M30 / N100 G91 / M99",
     [(5, 4, "X goes to 33")]),
    # (main's said case kept: the caller selects G54 again, N100 leaves G90: X31. absolute)
    ("O01000 / G20 G17 G90 G54 / G0 X0 / M97 P100 / G54 / G0 X31. / M30 / "
     "N100 G91 G0 X1. / G90 / M99", [(6, 4, "X goes to 31")]),
    # (integers are increments of 0.0001 in on a Haas: X20 is 0.002 in; nothing)
    ("O01000 / G20 G17 G90 G54 / G0 X0 Y0 / M97 P100 / G0 X20 / G0 X20 / M30 / "
     "N100 G91 / M99", []),
])
def test_haas_calls_of_later_bodies(profiles, text, expected):
    assert said(text, profiles["haas"]) == expected


@pytest.mark.parametrize("text, expected", [
    # (rs274 -g: STRAIGHT_TRAVERSE X 0, 500, 1000: the endsub keeps G91)
    ("G21 G17 G90 G54 / G0 X0 Y0 / o2000 call / G0 X500. / G0 X500. / M2 / o2000 sub / G91 / "
     "o2000 endsub", [(5, 4, "X goes to 1000")]),
    # (the M98 form of an O2000 ... M99 after M2: rs274 -g 0, 500, 1000)
    ("G21 G17 G90 G54 / G0 X0 Y0 / M98 P2000 / G0 X500. / G0 X500. / M2 / O2000 / G91 / M99",
     [(5, 4, "X goes to 1000")]),
    # (rs274 -g: 0, 10, 510, 1010)
    ("G21 G17 G90 G54 / G0 X0 Y0 / o2000 call / G0 X500. / G0 X500. / M2 / o2000 sub / "
     "G91 G0 X10. / o2000 endsub", [(5, 4, "X goes to 1010")]),
    # (review 78-calls78 F3: G91 inside `o1 if [0]` never runs (rs274 -g: -700 under
    # SET_G5X_OFFSET(2), machine -800); main dropped the held finding)
    ("G21 G17 G90 G54 / G0 X0 Y0 / o2000 call / G55 / G0 X-700. / M2 / o2000 sub / "
     "o1 if [0] / G91 / o1 endif / o2000 endsub", [(5, 4, "X goes to -800")]),
    # (the same with no G55: X800. absolute under G54, rs274 -g 800)
    ("G21 G17 G90 G54 / G0 X0 Y0 / o2000 call / G0 X800. / M2 / o2000 sub / "
     "o1 if [0] / G91 / o1 endif / o2000 endsub", [(4, 4, "X goes to 800")]),
    # (review 80-calls80 R1: rs274 -g -700, then 800; main's held span at line 4 dropped at
    # the endsub, the position said)
    ("G21 G17 G90 G54 / G0 X-700 Y0 Z0 / o2000 call / G0 X1500 / M2 / o2000 sub / G91 / "
     "o2000 endsub", [(4, 4, "X goes to 800")]),
    # (the caller's move after the call with no G54-G59 of its own, under the call's G55
    # the body writes no offset and no G90/G91, so X-700 runs absolute at machine
    # -800; main left it not judged, test_calls_offsets.py's silent list until calls80)
    ("G21 G17 G90 G54 / G0 X0 Y0 / G55 / o100 call / G0 X-700 / M2 / o100 sub / G0 X0 / "
     "o100 endsub", [(5, 4, "X goes to -800")]),
    # (lcnc81: a condition false from numbers alone is read as `[0]` is, by the checker's one
    # reading of conditions; rs274 -g: the G91 never runs, -700 under SET_G5X_OFFSET(2),
    # machine -800; main kept the held finding dropped)
    ("G21 G17 G90 G54 / G0 X0 Y0 / o2000 call / G55 / G0 X-700. / M2 / o2000 sub / "
     "o1 if [1 GT 2] / G91 / o1 endif / o2000 endsub", [(5, 4, "X goes to -800")]),
    # (a condition not known: silent, as main)
    ("G21 G17 G90 G54 / G0 X0 Y0 / o2000 call / G0 X500. / G0 X500. / M2 / o2000 sub / "
     "o1 if [#1 GT 0] / G91 / o1 endif / o2000 endsub", []),
])
def test_linuxcnc_calls_of_later_definitions(profiles, text, expected):
    assert said(text, profiles["lcnc"]) == expected


# A FANUC's or Haas's call takes the caller's mode as G91 (called.rs, the mode not known
# after it); the body's moves before its own G90/G91 run in the caller's G90 all the same:
# `G0 X50.` / `M98 P2000` of `G0 X100.` / `G91` / `G0 X620.` runs at 100, then 720, inside
# (`rs274 -g` of the LinuxCNC twin: 50, 100, 720); read as an increment from 50 it was a
# false "X goes to 770". With X700. the truth is 800: said, as 800.
@pytest.mark.parametrize("form, text, expected", [
    ("fanuc", "O1000 / G21 G17 G90 G54 / G0 X50. / M98 P2000 / G0 X620. / M30 / O2000 / "
     "G0 X100. / G91 / M99", []),
    ("fanuc", "O1000 / G21 G17 G90 G54 / G0 X50. / M98 P2000 / G0 X700. / M30 / O2000 / "
     "G0 X100. / G91 / M99", [(5, 4, "X goes to 800")]),
    # (Haas: 10 + 19 = 29 in, inside; read from 2 as an increment it was 31)
    ("haas", "O1000 / G20 G17 G90 G54 / G0 X2. / M97 P100 / G0 X19. / M30 / "
     "N100 G0 X10. / G91 / M99", []),
    ("lcnc", "G21 G17 G90 G54 / G0 X50 Y0 / o2000 call / G0 X620 / M2 / o2000 sub / G0 X100 / "
     "G91 / o2000 endsub", []),
])
def test_a_body_move_before_its_own_mode_in_the_callers_mode(profiles, form, text, expected):
    assert said(text, profiles[form]) == expected


# A selection between the last position and the call: the real run keeps the machine
# position, and the checker re-expresses the work position it holds in the new system (new
# work = old work + old offset - new offset, limits.rs) where both offsets are known: the
# body runs from there, under the selected system (issue 32 item 4, calls82; FANUC 0i-F /
# 30i-B and Haas NGC: selecting a work system moves no axis; LinuxCNC `rs274 -g`). X-650
# under G54 is G55 work -550; the body's -540, the caller's X-100 at -640, machine -740:
# inside (rs274 -g, G55 X -100 in its var file; read from the old system's -650 it was "X
# goes to -840", a false error, the lead's review of stop 80's merge).
@pytest.mark.parametrize("form, text, expected", [
    ("lcnc", "G21 G17 G90 G54 / G0 X-650 Y0 / G55 / o2000 call / G0 X-100 / M2 / o2000 sub / "
     "G91 G0 X10. / o2000 endsub", []),
    ("fanuc", "O1000 / G21 G17 G90 G54 / G0 X-650. Y0 / G55 / M98 P2000 / G0 X-100. / M30 / "
     "O2000 / G91 G0 X10. / M99", []),
    # (the body leaves G90: X-700. absolute under G55, machine -800)
    ("lcnc", "G21 G17 G90 G54 / G0 X-650 Y0 / G55 / o2000 call / G0 X-700 / M2 / o2000 sub / "
     "G0 X10. / o2000 endsub", [(5, 4, "X goes to -800")]),
    # (review 81-calls81 f_sel1: machine 0 is G55 work 100; the body's G91 X100. to 200,
    # machine 100; the caller's increments 600 and 100 to machine 700 and 800 > 762)
    ("fanuc", "O1000 / G21 G17 G90 G54 / G0 X0 / G55 / M98 P2000 / G0 X600. / G0 X100. / "
     "M30 / O2000 / G91 G0 X100. / M99", [(7, 4, "X goes to 800")]),
    # (the LinuxCNC twin: rs274 -g with G55 X +100 prints work -100 after the selection
    # (machine 0), then 0, 600, 700: machine 800; on this profile's G55 X -100 the same
    # arithmetic gives 100, 200, 800, 900: machine 800)
    ("lcnc", "G21 G17 G90 G54 / G0 X0 Y0 / G55 / o2000 call / G0 X600 / G0 X100 / M2 / "
     "o2000 sub / G91 G0 X100 / o2000 endsub", [(6, 4, "X goes to 800")]),
    # (one increment only: machine 700, inside)
    ("fanuc", "O1000 / G21 G17 G90 G54 / G0 X0 / G55 / M98 P2000 / G0 X600. / M30 / "
     "O2000 / G91 G0 X100. / M99", []),
    # (Haas, G55 X -4 in: machine 0 is work 4; the body's G91 X5. to 9 (machine 5), the
    # caller's 24 and 2 to machine 29 and 31 > 30)
    ("haas", "O1000 / G20 G17 G90 G54 / G0 X0 / G55 / M97 P100 / G0 X24. / G0 X2. / M30 / "
     "N100 G91 G0 X5. / M99", [(7, 4, "X goes to 31")]),
    # (G56, not in the profile: its offset not known, the position not re-expressed: silent)
    ("fanuc", "O1000 / G21 G17 G90 G54 / G0 X0 / G56 / M98 P2000 / G0 X600. / G0 X100. / "
     "M30 / O2000 / G91 G0 X100. / M99", []),
])
def test_a_selection_before_the_call(profiles, form, text, expected):
    assert said(text, profiles[form]) == expected


# A G52 or G92 of the caller's, followed (its amount known), in force at the call: the body
# runs under it, and the caller's moves after it (issue 32 item 4, calls82; FANUC 0i-F /
# 30i-B Operator's Manual, "Local coordinate system" G52 and "Setting a workpiece
# coordinate system" G92: the shift holds until another or a reset, and M98/M99 end
# neither; Haas NGC Mill Operator's Manual, G52; LinuxCNC G92, `rs274 -g`). Main took the
# offsets as lost at the shift: each "said" case was silent on main.
@pytest.mark.parametrize("form, text, expected", [
    # (G92 X100. at machine 0: work 100, shift -100; the body's G91 X-100. to work 0
    # (machine -100); the caller's -600 and -100 to machine -700 and -800 < -762)
    ("fanuc", "O1000 / G21 G17 G90 G54 / G0 X0 / G92 X100. / M98 P2000 / G0 X-600. / "
     "G0 X-100. / M30 / O2000 / G91 G0 X-100. / M99", [(7, 4, "X goes to -800")]),
    # (rs274 -g: SET_G92_OFFSET(-100), then work 0, -600, -700: machine -800)
    ("lcnc", "G21 G17 G90 G54 / G0 X0 Y0 / G92 X100 / o2000 call / G0 X-600 / G0 X-100 / M2 "
     "/ o2000 sub / G91 G0 X-100 / o2000 endsub", [(6, 4, "X goes to -800")]),
    # (rs274 -g: work -550, machine -650: inside)
    ("lcnc", "G21 G17 G90 G54 / G0 X0 Y0 / G92 X100 / o2000 call / G0 X-550 / M2 / "
     "o2000 sub / G91 G0 X-100 / o2000 endsub", []),
    # (G52 X-100.: the body's G90 X-10. at machine -110, then G91; the caller's -680 to
    # -790 < -762)
    ("fanuc", "O1000 / G21 G17 G90 G54 / G0 X0 / G52 X-100. / M98 P2000 / G0 X-680. / M30 "
     "/ O2000 / G90 G0 X-10. / G91 / M99", [(6, 4, "X goes to -790")]),
    # (G52 X100.: 90 - 680 = -590, inside)
    ("fanuc", "O1000 / G21 G17 G90 G54 / G0 X0 / G52 X100. / M98 P2000 / G0 X-680. / M30 "
     "/ O2000 / G90 G0 X-10. / G91 / M99", []),
    # (Haas G52 X-4. (as FANUC's): the body's X-10. at -14, the caller's -15 and -2 to -29
    # and -31 < -30)
    ("haas", "O1000 / G20 G17 G90 G54 / G0 X0 / G52 X-4. / M97 P100 / G0 X-15. / G0 X-2. / "
     "M30 / N100 G90 G0 X-10. / G91 / M99", [(7, 4, "X goes to -31")]),
    # (not known, silent as main: a G92 where the position before it is not known; a
    # LinuxCNC G52 (it sets the offset G92 shares, kept from an earlier run); a Haas G92,
    # whose working Setting 33 decides)
    ("fanuc", "O1000 / G21 G17 G90 G54 / G92 X100. / M98 P2000 / G0 X-600. / G0 X-100. / "
     "M30 / O2000 / G91 G0 X-100. / M99", []),
    ("lcnc", "G21 G17 G90 G54 / G0 X0 Y0 / G52 X-100 / o2000 call / G0 X-600 / G0 X-100 / "
     "M2 / o2000 sub / G91 G0 X-100 / o2000 endsub", []),
    ("haas", "O1000 / G20 G17 G90 G54 / G0 X0 / G92 X4. / M97 P100 / G0 X-24. / G0 X-4. / "
     "M30 / N100 G91 G0 X-4. / M99", []),
])
def test_a_shift_in_force_at_the_call(profiles, form, text, expected):
    assert said(text, profiles[form]) == expected


# Issue 32 item 4, calls81: more calls, repeat counts, Z, the profile's units. A body's runs
# follow one another, each from where the one before left the tool, in the mode it left (a
# body that leaves G91 moves again at each pass, one that leaves G90 ends where it ends); a
# later call starts where the caller's moves after the one before end, only where every block
# between was a plain move kept. FANUC 0i-F / 30i-B and Haas: "Subprogram call (M98)" (P, L
# the repeat count; on a FANUC with four-digit program numbers, P's digits above the last
# four); LinuxCNC: `rs274 -g` of the LinuxCNC twins.
_O04 = ('detailed = "%:/DS O04 N05 G031 X+053 Y+053 Z+053 P08 Q+053 R+053 A+053 B+053 I+053 '
        'J+053 K+053 F052 S05 T08 D03 M03 H03 L04*"\n')


@pytest.fixture
def more(tmp_path: Path, profiles: dict[str, str]) -> dict[str, str]:
    out = dict(profiles)
    path = tmp_path / "o04.toml"
    path.write_text('name = "r-o04"\nbase = "fanuc-mill"\n' + _O04 + _MM)
    out["o04"] = str(path)
    # (G54's Z at -100: machine Z = work Z - 100)
    path = tmp_path / "z.toml"
    path.write_text('name = "r-z"\nbase = "fanuc-mill"\n' + _MM.replace(
        "G54 = { X = 0.0, Y = 0.0, Z = 0.0 }", "G54 = { X = 0.0, Y = 0.0, Z = -100.0 }"))
    out["z"] = str(path)
    return out


@pytest.mark.parametrize("form, text, expected", [
    # (L3 of a body that leaves G91 after X100.: 100, 200, 300; the caller's X500. an
    # increment: 800 > 762)
    ("fanuc", "O1000 / G21 G17 G90 G54 / G0 X0 / M98 P2000 L3 / G0 X500. / M30 / "
     "O2000 / G91 G0 X100. / M99", [(5, 4, "X goes to 800")]),
    # (a body that writes G90 X100. then G91 X50.: every pass ends at 150, not 450; the
    # caller's X600. an increment: 750, inside)
    ("fanuc", "O1000 / G21 G17 G90 G54 / G0 X0 / M98 P2000 L3 / G0 X600. / M30 / "
     "O2000 / G90 G0 X100. / G91 G0 X50. / M99", []),
    # (its X100. before its own G91: the first pass in the caller's G90 (100, 150), the next
    # in the G91 it left (250, 300; 400, 450); 450 + 320 = 770)
    ("fanuc", "O1000 / G21 G17 G90 G54 / G0 X0 / M98 P2000 L3 / G0 X320. / M30 / "
     "O2000 / G0 X100. / G91 G0 X50. / M99", [(5, 4, "X goes to 770")]),
    # (the first pass in the caller's G91 (100), the next in the G90 it left (100, 100); the
    # caller's G91 X650.: 750, inside)
    ("fanuc", "O1000 / G21 G17 G90 G54 / G0 X0 / G91 / M98 P2000 L3 / G91 G0 X650. / M30 / "
     "O2000 / G0 X100. / G90 / M99", []),
    # (L0: the manual gives no such count: not followed, silent as main)
    ("fanuc", "O1000 / G21 G17 G90 G54 / G0 X0 / M98 P2000 L0 / G0 X800. / M30 / "
     "O2000 / G91 / M99", []),
    # (four-digit program numbers: P32000 is O2000 three times, 300 + 500 = 800; P2000 L3
    # the same)
    ("o04", "O1000 / G21 G17 G90 G54 / G0 X0 / M98 P32000 / G0 X500. / M30 / "
     "O2000 / G91 G0 X100. / M99", [(5, 4, "X goes to 800")]),
    ("o04", "O1000 / G21 G17 G90 G54 / G0 X0 / M98 P2000 L3 / G0 X500. / M30 / "
     "O2000 / G91 G0 X100. / M99", [(5, 4, "X goes to 800")]),
    # (eight-digit numbers: P32000 is O32000, once: 100 + 500 = 600, inside; three runs of
    # O2000 would say 800)
    ("fanuc", "O1000 / G21 G17 G90 G54 / G0 X0 / M98 P32000 / G0 X500. / M30 / "
     "O2000 / G91 G0 X100. / M99 / O32000 / G91 G0 X100. / M99", []),
    # (Haas M98 P2000 L3 and M97 P100 L3 in inches: 15 + 20 = 35 > 30)
    ("haas", "O01000 / G20 G17 G90 G54 / G0 X0 / M98 P2000 L3 / G0 X20. / M30 / "
     "O02000 / G91 G0 X5. / M99", [(5, 4, "X goes to 35")]),
    ("haas", "O01000 / G20 G17 G90 G54 / G0 X0 / M97 P100 L3 / G0 X20. / M30 / "
     "N100 G91 G0 X5. / M99", [(5, 4, "X goes to 35")]),
    # (two bodies: O2000 leaves X at 300 (G90), the caller's X500. is absolute; O3000 adds
    # 100 in G91: 600, then X200. an increment: 800)
    ("fanuc", "O1000 / G21 G17 G90 G54 / G0 X0 / M98 P2000 / G0 X500. / M98 P3000 / "
     "G0 X200. / M30 / O2000 / G90 G0 X300. / M99 / O3000 / G91 G0 X100. / M99",
     [(7, 4, "X goes to 800")]),
    # (the bodies in the other order in the file: the same)
    ("fanuc", "O1000 / G21 G17 G90 G54 / G0 X0 / M98 P2000 / G0 X500. / M98 P3000 / "
     "G0 X200. / M30 / O3000 / G91 G0 X100. / M99 / O2000 / G90 G0 X300. / M99",
     [(7, 4, "X goes to 800")]),
    # (Haas M97 twice, N100 G91 X5.: 5, then the caller's 10, 15, then X16. 31 > 30)
    ("haas", "O01000 / G20 G17 G90 G54 / G0 X0 / M97 P100 / G0 X5. / M97 P100 / G0 X16. / "
     "M30 / N100 G91 G0 X5. / M99", [(7, 4, "X goes to 31")]),
    # (LinuxCNC, two calls: rs274 -g 100, 300, 400, then 800)
    ("lcnc", "G21 G17 G90 G54 / G0 X0 Y0 / o2000 call / G0 X200 / o2000 call / G0 X400 / M2 / "
     "o2000 sub / G91 G0 X100 / o2000 endsub", [(6, 4, "X goes to 800")]),
    # (a G10 between the calls: the offset after it not the profile's; silent after it)
    ("fanuc", "O1000 / G21 G17 G90 G54 / G0 X0 / M98 P2000 / G10 L2 P1 X-100. / M98 P2000 / "
     "G0 X650. / M30 / O2000 / G91 G0 X100. / M99", []),
    # (a call of a program not in the file between: nothing after it known)
    ("fanuc", "O1000 / G21 G17 G90 G54 / G0 X0 / M98 P2000 / M98 P9000 / G0 X700. / M30 / "
     "O2000 / G91 G0 X100. / M99", []),
])
def test_more_calls_and_repeats(more, form, text, expected):
    assert said(text, more[form]) == expected


@pytest.mark.parametrize("form, text, expected", [
    # (Z: G54 Z -100; the body leaves G91 after Z-100.: -100, then the caller's Z-350. an
    # increment: work -450, machine -550 < -508)
    ("z", "O1000 / G21 G17 G90 G54 / G0 X0 Y0 Z0 / M98 P2000 / G0 Z-350. / M30 / "
     "O2000 / G91 G0 Z-100. / M99", [(5, 4, "Z goes to -550")]),
    # (a tool length offset in force at the call: the profile gives no tool lengths, Z not
    # judged, as limits.rs)
    ("z", "O1000 / G21 G17 G90 G54 / G0 X0 Y0 Z0 / G43 H1 / M98 P2000 / G0 Z-350. / M30 / "
     "O2000 / G91 G0 Z-100. / M99", []),
    # (the body writes G43: not followed)
    ("z", "O1000 / G21 G17 G90 G54 / G0 X0 Y0 Z0 / M98 P2000 / G0 Z-350. / M30 / "
     "O2000 / G43 H1 / G91 G0 Z-100. / M99", []),
    # (Z 0 + 50 in G91, the caller's Z-30. an increment: 20 > 10)
    ("fanuc", "O1000 / G21 G17 G90 G54 / G0 X0 Y0 Z0 / M98 P2000 / G0 Z-30. / M30 / "
     "O2000 / G91 G0 Z50. / M99", [(5, 4, "Z goes to 20")]),
    # (LinuxCNC, rs274 -g: Z -100, then the caller's Z-450 an increment: -550 < -508)
    ("lcnc", "G21 G17 G90 G54 / G0 X0 Y0 Z0 / o2000 call / G0 Z-450 / M2 / o2000 sub / "
     "G91 G0 Z-100 / o2000 endsub", [(4, 4, "Z goes to -550")]),
])
def test_z_after_a_later_body(more, form, text, expected):
    assert said(text, more[form]) == expected


@pytest.mark.parametrize("form, text, expected", [
    # (no G20/G21 and an M30: the main program runs in the reset state's units, the
    # profile's (fanuc-mill.toml: units = "metric"); 500 + 500 = 1000 mm, as main judges its
    # own positions there)
    ("fanuc", "O1000 / G17 G90 G54 / G0 X0 / M98 P2000 / G0 X500. / G0 X500. / M30 / "
     "O2000 / G91 / M99", [(6, 4, "X goes to 1000")]),
    # (haas-mill.toml: units = "inch"; 20 + 20 = 40 in)
    ("haas", "O01000 / G17 G90 G54 / G0 X0 / M98 P2000 / G0 X20. / G0 X20. / M30 / "
     "O02000 / G91 / M99", [(6, 4, "X goes to 40")]),
    # (it ends with M99: a subprogram of a call not in the file, whose units are its
    # caller's: not judged)
    ("fanuc", "O1000 / G17 G90 G54 / G0 X0 / M98 P2000 / G0 X500. / G0 X500. / M99 / "
     "O2000 / G91 / M99", []),
])
def test_the_profiles_units_where_the_caller_writes_none(more, form, text, expected):
    assert said(text, more[form]) == expected


# A Haas's local subprogram (M97) runs from its sequence number to its M99, on through the
# blocks of the next one a call names (Haas Mill Operator's Manual, M97: the N words between
# are no end; issue 32 item 4, calls82). X -30..30 in.
@pytest.mark.parametrize("text, expected", [
    # (M97 P100: N100's G91 X5. and N200's X-5. to 0 (read alone, N100 left 5); the caller's
    # X5. to 5; M97 P200: its X-5. to 0 in G91; X32. to 32 > 30)
    ("O1000 / G20 G17 G90 G54 / G0 X0 / M97 P100 / G0 X5. / M97 P200 / G0 X32. / M30 / "
     "N100 G91 G0 X5. / N200 G0 X-5. / M99", [(7, 4, "X goes to 32")]),
    # (the same with X27.: 27, inside; read from N100 alone, 5 + 5 - 5 + 27 = 32, false)
    ("O1000 / G20 G17 G90 G54 / G0 X0 / M97 P100 / G0 X5. / M97 P200 / G0 X27. / M30 / "
     "N100 G91 G0 X5. / N200 G0 X-5. / M99", []),
    # (M97 P200 first: X5. in the caller's G90 to 5; M97 P100: 10, 15; X16. to 31 > 30)
    ("O1000 / G20 G17 G90 G54 / G0 X0 / M97 P200 / M97 P100 / G0 X16. / M30 / "
     "N100 G91 G0 X5. / N200 G0 X5. / M99", [(6, 4, "X goes to 31")]),
    # (N200 writes G90 on the way: P100 ends at 5 absolute; the caller's X29. absolute: 29)
    ("O1000 / G20 G17 G90 G54 / G0 X0 / M97 P100 / G0 X29. / M97 P200 / M30 / "
     "N100 G91 G0 X5. / N200 G90 G0 X5. / M99", []),
])
def test_haas_m97_runs_on_through_the_next_label(profiles, text, expected):
    assert said(text, profiles["haas"]) == expected
