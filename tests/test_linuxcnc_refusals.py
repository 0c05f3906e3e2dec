"""Plain LinuxCNC blocks that rs274 refuses (review 13, finding 6): each is a program a LinuxCNC
machine will not run, so the linuxcnc profile refuses it with rs274's own message (TG412 for
the words no code of the block uses, interp_check.cc ``check_other_codes``; the other rules
where tapegate has its own). tapegate's finding is asserted always; rs274 -g, where installed,
is asserted to stop with the same message on the same program (and to run the accepted ones to
their end).
"""

from __future__ import annotations

import os

import pytest

from formats.profile import load_profile
from postproc.check import check_text

from .conftest import rs274_output

HEAD = "G21 G17 G90 F100\nG0 X0 Y0 Z0\n"


def program(body: str) -> str:
    return f"{HEAD}{body}\nM2\n"


def errors(text: str) -> list[tuple[str, int, str]]:
    return [(f.rule, f.line, f.message) for f in check_text(text, load_profile("linuxcnc"))
            if f.severity == "error"]


def clean_on_both(tmp_path, text: str) -> None:
    """No error from the checker, and rs274 runs the program to its end."""
    assert errors(text) == [], text
    out = rs274_output(tmp_path, text)
    assert "PROGRAM_END" in out, out


def judged_as_rs274(tmp_path, text: str, line: int | None, rule: str, message: str) -> None:
    """With no ``line``, clean on both; else the checker's one error, ``rule`` at ``line``, and
    rs274 -g refuses the program with ``message``."""
    if line is None:
        clean_on_both(tmp_path, text)
        return
    assert [(r, n) for r, n, _ in errors(text)] == [(rule, line)], text
    assert message in rs274_output(tmp_path, text)


def refused_once(text: str, line: int) -> str:
    """The checker's one error, TG412 at ``line``: its message."""
    found = errors(text)
    assert [(rule, n) for rule, n, _ in found] == [("TG412", line)], found
    return found[0][2]


# (the block or blocks after HEAD, the rule, its line, rs274's message)
REFUSED = [
    ("G1 X1 Y1 I2", "TG412", 3,
     "I word with no G2, G3, G5, G5.1, G10, G33.1, G76, or G87 to use it"),
    ("G1 X1 K2", "TG412", 3, "K word with no G2, G3, G33, G33.1, G76, or G87 to use it"),
    ("G0 X1 J2", "TG412", 3, "J word with no G2, G3, G5, G5.1, G10, G76 or G87 to use it"),
    ("G1 X1 Y1 R2", "TG412", 3, "R word with no g code that uses it"),
    ("G1 X1 Y1 Q2", "TG412", 3, "Q word with no G5, G10, G64, G73, G76, G83, M19, M66, M67, "
     "M68 or user M code that uses it"),
    # the mode in force runs a block that moves without a motion code
    ("G1 X1\nY2 R2", "TG412", 4, "R word with no g code that uses it"),
    # no motion at all: a plane code with an arc's centre
    ("G17 I1", "TG412", 3,
     "I word with no G2, G3, G5, G5.1, G10, G33.1, G76, or G87 to use it"),
    ("G81 X1 Y1 Z-1 R1 I1", "TG412", 3,
     "I word with no G2, G3, G5, G5.1, G10, G33.1, G76, or G87 to use it"),
    ("G81 X1 Y1 Z-1 R1 A5", "TG412", 3, "Cannot put an a in canned cycle"),
    ("G1 X1 L2", "TG412", 3, "L word with no G10, cutter compensation, canned cycle, "
     "digital/analog input, M98 or NURBS code"),
    ("G0 X1 D1", "TG412", 3,
     "D word with no G41, G41.1, G42, G42.1, G71, G71.1, G71.2 or G96 to use it"),
    ("M19 R400", "TG412", 3, "R value must be within 0..360 with M19"),
    ("G96 D1000", "TG412", 3, "S word missing with G96"),
    ("G91\nG53 G0 X1", "TG412", 4, "Cannot use g53 incremental"),
    # rs274 2.9 compares the motion, not the spindle mode, with G97: `G97 $0` is refused
    ("G97 $0", "TG412", 3, "$ (spindle selection) word with no M3, M4, M5, M19, M51, G33, "
     "G33.1, G76, G95, G96 or G97 to use it"),
    ("M3 S100\nG33 Z-1", "TG412", 4, "K word missing with g33/g33.1"),
    # under G95 the feed is a length a spindle turn: rs274 starts at S0
    ("G95 F0.1\nG1 X1", "TG412", 4, "Cannot feed with zero spindle speed in feed per rev mode"),
    ("S0 M3\nG95 F0.1\nG2 X2 Y0 I1 J0", "TG412", 5,
     "Cannot feed with zero spindle speed in feed per rev mode"),
    # an R arc that ends where it starts has no centre (interp_arc.cc arc_data_r)
    ("G2 X0 Y0 R5", "TG412", 3, "Current point same as end point of arc"),
    ("G91 G3 X0 R5", "TG412", 3, "Current point same as end point of arc"),
    # an absolute move in the coordinates chosen, or after a return home, knows the start again
    ("G55\nG0 X1 Y0\nG2 X1 Y0 R5", "TG412", 5, "Current point same as end point of arc"),
    ("G28\nG0 X1 Y0\nG2 X1 Y0 R5", "TG412", 5, "Current point same as end point of arc"),
    # a move in the block of the offset ends where it says in the new coordinates
    ("G55 G0 X1 Y0\nG2 X1 Y0 R5", "TG412", 4, "Current point same as end point of arc"),
    ("G43 H1 G0 X1 Y0 Z1\nG2 X1 Y0 R5", "TG412", 4, "Current point same as end point of arc"),
    # a tool length offset moves Z (and X in G18, a lathe's plane): a G17 arc's X and Y stay
    # known; G92 sets the axes it names to its values exactly (review 15, finding 8)
    ("G43 H1\nG2 X0 Y0 R5", "TG412", 4, "Current point same as end point of arc"),
    ("G0 X1 Y0\nG43 H1 Z1\nG2 X1 R5", "TG412", 5, "Current point same as end point of arc"),
    ("G0 X1 Y0\nG92 X0\nG2 X0 Y0 R5", "TG412", 5, "Current point same as end point of arc"),
    ("G28\nG92 X0 Y0\nG2 X0 Y0 R5", "TG412", 5, "Current point same as end point of arc"),
    ("G43.1 Z1\nG2 X0 Y0 R5", "TG412", 4, "Current point same as end point of arc"),
    # an R word alone runs no arc: rs274 names the word, and nothing more (review 14, 9)
    ("G2 X2 Y0 R1\nR2", "TG412", 4, "R word with no g code that uses it"),
    # a probe feeds per minute (interp_convert.cc convert_probe)
    ("S1000 M3\nG95 F0.1\nG38.2 Z-1", "TG412", 5, "Cannot probe with feed per rev mode"),
    ("G95 F0\nG94\nG38.2 Z-1", "TG412", 5, "Cannot probe with zero feed rate"),
    # an M code is a whole number to rs274 (interp_read.cc read_integer_value)
    ("M00.1", "TG412", 3, "Non integer value for integer"),
    ("M1.5", "TG412", 3, "Non integer value for integer"),
    ("M97.5", "TG412", 3, "Non integer value for integer"),
    ("M3 S100 M8.2", "TG412", 3, "Non integer value for integer"),
    # G33's lead is its K: TG511, every family's rule
    ("M3 S100\nG33 Z-1 K1 F1", "TG511", 4, "F must not be programmed"),
    # rs274's feed rate, which a probe and a cycle read, is zeroed by G94 and G95 and set by
    # an F under them alone: an F under G93 is its block's inverse time (review 15, 5)
    ("G93\nG94\nG38.2 X5", "TG412", 5, "Cannot probe with zero feed rate"),
    ("G94\nG93\nG38.2 X5 F10", "TG412", 5, "Cannot probe with zero feed rate"),
    ("G94\nG93\nG81 X1 Y1 Z-1 R1 F10", "TG412", 5, "Cannot feed with zero feed rate"),
    # with a feed rate, a cycle under G93 is refused for G93 (interp_cycles.cc convert_cycle)
    ("G93\nG81 X1 Y1 Z-1 R1", "TG412", 4, "Cannot use inverse time feed with canned cycles"),
    # a probe that must trip and ends where it starts (interp_convert.cc convert_probe)
    ("G38.2 Z0 F10", "TG412", 3, "Start point too close to probe point"),
    ("G0 X1\nG38.2 X1 Y0", "TG412", 4, "Start point too close to probe point"),
    ("G91\nG38.4 X0 F10", "TG412", 4, "Start point too close to probe point"),
    # rs274 holds doubles and compares them with ==: G91 sums that are the nearest double of
    # the decimal sum end where the absolute word does (0.5 + 0.25), and an absolute move
    # gives the nearest double again (review 16c, 3)
    ("G91\nG0 Z0.5\nG0 Z0.25\nG90\nG38.2 Z0.75", "TG412", 7,
     "Start point too close to probe point"),
    ("G91\nG0 Z0.1\nG0 Z0.2\nG90\nG0 Z0.3\nG38.2 Z0.3", "TG412", 8,
     "Start point too close to probe point"),
    ("G91\nG0 Z0.1\nG0 Z0.2\nG92 Z0.3\nG90\nG38.2 Z0.3", "TG412", 8,
     "Start point too close to probe point"),
    ("G91\nG0 X0.5\nG0 X0.25\nG90\nG2 X0.75 Y0 R5", "TG412", 7,
     "Current point same as end point of arc"),
    # a motion code with no axis word (interp_internal.cc enhance_block)
    ("G38.2 F10", "TG412", 3, "All axes missing with motion code"),
    ("M3 S100\nG33 K1", "TG412", 4, "All axes missing with motion code"),
    ("G5 I1 J1 P1 Q1", "TG412", 3, "All axes missing with motion code"),
    # an expression of numbers: an M code that is no whole number, a division by zero
    ("M[3.5]", "TG412", 3, "Non integer value for integer"),
    ("M[7/2]", "TG412", 3, "Non integer value for integer"),
    ("G0 X[1/0]", "TG412", 3, "Attempt to divide by zero"),
    ("G0 X[1/[2-2]] Y1", "TG412", 3, "Attempt to divide by zero"),
    ("G0 X[SIN[1/0]]", "TG412", 3, "Attempt to divide by zero"),
    # M66's words (interp_convert.cc convert_m)
    ("M66 P0 E0 L0", "TG412", 3,
     "Invalid to select both a digital and an analog input with M66"),
    ("M66 P0 L1", "TG412", 3, "Zero timeout with wait type != immediate return"),
    ("M66 E0 L1 Q1", "TG412", 3,
     "Can't select analog input with wait type != immediate return"),
    ("M66 L0", "TG412", 3, "Need to have either a valid P or a valid E word with M66"),
    ("M66 P-1.5", "TG412", 3, "Need to have either a valid P or a valid E word with M66"),
    # M70-M73 are in rs274's spindle group (interp_array.cc _ems)
    ("M3 M70", "TG412", 3, "Two m codes used from same modal group"),
    ("M73 M19", "TG412", 3, "Two m codes used from same modal group"),
    # a local named parameter read before any line sets it (interp_namedparams.cc)
    ("G0 X#<nope>", "TG412", 3, "Named parameter #<nope> not defined"),
    ("o1 if [#<nope> GT 0]\no1 endif", "TG412", 3, "Named parameter #<nope> not defined"),
    ("G0 X#<x> #<x>=1", "TG412", 3, "Named parameter #<x> not defined"),
    # a name read before is remembered as its bytes: one of the same length (packed into
    # one integer up to 8 bytes) or the same first 8 bytes is another name
    ("#<ab> = 1\nG0 X#<ab>\nG0 X#<ba>", "TG412", 5, "Named parameter #<ba> not defined"),
    ("#<scale_xy_1> = 1\nG0 X[#<scale_xy_1>*2]\nG0 X[#<scale_xy_2>*2]", "TG412", 5,
     "Named parameter #<scale_xy_2> not defined"),
    ("o<s> sub\n#<q> = 1\no<s> endsub\no<s> call\nG0 X#<q>", "TG412", 7,
     "Named parameter #<q> not defined"),
    # after a definition, a call, a closed condition or loop, or M73 in the main program,
    # the lines run unconditionally again and are judged (review 17: one o-word had turned
    # these refusals off for the rest of the file)
    ("o<s> sub\nG1 X1\no<s> endsub\nG95 F0.1 S100 M3\nG38.2 Z-5", "TG412", 7,
     "Cannot probe with feed per rev mode"),
    ("o<s> sub\nG1 X1\no<s> endsub\nG93\nG81 X1 Y1 Z-1 R1 F10", "TG412", 7,
     "Cannot use inverse time feed with canned cycles"),
    ("o<s> sub\nG1 X1\no<s> endsub\no<s> call\nG95 F0.1 S100 M3\nG38.2 Z-5", "TG412", 8,
     "Cannot probe with feed per rev mode"),
    ("M73\nG93\nG81 X1 Y1 Z-1 R1 F10", "TG412", 5,
     "Cannot use inverse time feed with canned cycles"),
    ("o1 if [0]\nG93\no1 endif\nG94\nG95 S100 M3 F1\nG38.2 Z-5", "TG412", 8,
     "Cannot probe with feed per rev mode"),
    ("o<s> sub\no1 if [#1 GT 0]\nG1 X1\no1 endif\no<s> endsub\nM[3.5]", "TG412", 8,
     "Non integer value for integer"),
    ("o1 if [1]\nG1 X1\no1 endif\nM[3.5]", "TG412", 6, "Non integer value for integer"),
    ("o1 repeat [2]\nG1 X1\no1 endrepeat\nG0 X[1/0]", "TG412", 6,
     "Attempt to divide by zero"),
    ("o1 do\nG1 X1\no1 while [0]\nG0 X#<u>", "TG412", 6, "Named parameter #<u> not defined"),
    # G43 takes no axis word without a motion mode (G43.1 and G43.2 do: enhance_block)
    ("G80\nG43 H1 Z1", "TG411", 4, "Z with no motion mode in force"),
    # NURBS (interp_convert.cc convert_nurbs): each point's weight, the order, G5.2 first
    ("G5.2 X1 Y1 L3\nX2 Y2\nG5.3", "TG412", 4,
     "Must specify positive weight P for every Control Point"),
    ("G5.2 X1 Y1 P1\nG5.3", "TG412", 4,
     "You must specify a number of control points at least equal to the order L = 3"),
    ("G5.3", "TG412", 3, "Cannot use G5.3 without G5.2 first"),
    ("G5.2 X1 P1", "TG412", 3, "You must specify both X and Y coordinates for Control Points"),
    # a cycle drills along the plane's axis: Y in G18, X in G19 (TG541, every family's rule)
    ("G18\nG0 X0 Z5\nG81 X1 Z-1 R2\nG80", "TG541", 5,
     "Y value unspecified in xz plane canned cycle"),
    ("G19\nG81 Y1 Z1 R2\nG80", "TG541", 4, "X value unspecified in yz plane canned cycle"),
    # review 52, F11: rs274 reads L as an integer (read_l), a cycle's repeat count as G10's
    ("G91 G81 X1 Y0 Z-1 R1 L2.5\nG90 G80", "TG412", 3, "Non integer value for integer"),
    ("G10 L2.5 P1 X0", "TG412", 3, "Non integer value for integer"),
]


@pytest.mark.parametrize("body, rule, line, message", REFUSED)
def test_linuxcnc_refuses_a_block_rs274_refuses(tmp_path, body, rule, line, message):
    text = program(body)
    found = errors(text)
    assert [(r, n) for r, n, _ in found] == [(rule, line)], found
    assert message in found[0][2], found
    said = RS274_SAYS.get(rule, message)
    assert said in rs274_output(tmp_path, text)


# rs274's message where tapegate says it in its own words
RS274_SAYS = {"TG511": "F word used with a g33/g33.1",
              "TG411": "Cannot use axis values without a g code that uses them"}


# Blocks rs274 runs: the same letters where a code of the block, or the motion it runs,
# uses them
ACCEPTED = [
    "G2 X2 Y0 I1 J0\nG3 X0 Y0 R1",
    # I J alone continue the arc mode (interp_internal.cc enhance_block)
    "G2 X2 Y0 I1 J0\nI-1 J0",
    "G83 X1 Y1 Z-1 R1 Q0.5\nX2 Q0.4",
    "G64 P0.01 Q0.01",
    "G10 L1 P1 R0.1 I0 J0 Q1",
    "M19 R90 Q1",
    # rs274's own value for no Q (a negative L it refuses while reading, as TG204 does)
    "G1 X1 Q-1",
    "G0 X1 A5\nG1 B2 C3",
    "G81 X1 Y1 Z-1 R1 L2",
    "G91\nG90 G53 G0 X1",
    "S100 $0\nM3 $0",
    "G2 X1 R5\nG91 G3 X-1 R5",
    "S1000 M3\nG95 F0.1\nG1 X1\nG2 X3 Y0 I1 J0",
    # a G code set by a parameter tapegate does not evaluate may be the arc that uses I J
    # (LinuxCNC's ngcgui helix.ngc writes `g#<dir> x.. y.. i.. j..`)
    "G1 X0\n#<dir> = [2 + #1]\nG#<dir> X2 Y0 I1 J0\nX0 Y0 I-1 J0",
    # where the current point moved, or its coordinates did, by an amount tapegate does not
    # follow, an R arc's start is unknown and it is not refused (review 14, 2): a work offset
    # set and chosen, a return home, a probe that stops at contact
    "G10 L2 P2 X1\nG0 X1 Y0\nG55\nG2 X1 Y0 R5",
    "G0 X1 Y0\nG28\nG2 X1 Y0 R5",
    "G0 X1 Y0\nG30\nG2 X1 Y0 R5",
    "G0 X0 Y0\nG38.2 X5 F10\nG2 X5 Y0 R5",
    # G28's words are an intermediate point, the end is home
    "G0 X1 Y0\nG28 X1 Y0\nG2 X1 Y0 R5",
    # an M code written with a zero fraction is the M code
    "S100 M3.0\nM5.0",
    "M1.00001",
    # G93 keeps rs274's feed rate, which the probe reads (review 15, 5)
    "G93\nG38.2 X5",
    "G93\nG94 F20\nG93\nG38.2 X5",
    "G93\nG38.2 X5 F10",
    # a probe that may not trip (G38.3, G38.5) may end where it starts; a probe after a code
    # that moves the coordinates by an amount rs274 holds is not judged
    "G38.3 Z0 F10",
    "G91\nG38.5 X0 F10",
    "G38.2 Z-1 F10\nG38.2 Z-1",
    # G18's cycle needs no Z
    "G18\nG81 X1 Y-1 R2\nG80",
    "G19\nG81 Y1 X-1 R2\nG80",
    "M66 P0 L0",
    "M66 P0 L1 Q1",
    "M66 E0 L0",
    "M66 P-0.4 L0",
    "M[1+2] S100\nM5",
    "M[3.00001] S100\nM5",
    "G0 X[1/0.5]",
    "M3 S100\nM70\nM72",
    "G5.2 X1 Y1 P1 L3\nX2 Y2 P1\nX3 Y0 P1\nG5.3",
    "G5.2 P1\nX1 Y1 P1\nX2 Y0 P1\nG5.3\nG1 X0",
    "#<x> = [#<x> + 1]\n#<y>=1 G0 X#<y>\n#<z> = EXISTS[#<nope>]\nG0 X#< X >",
    "o<s> sub\nG0 X#<inner>\no<s> endsub\nG0 X1",
    # lines that may not run, or run only when called, are not judged (review 16c, 1, 2, 4)
    "o<tap> sub\nG95 F1 S100 M3\nG1 Z-1\no<tap> endsub\nG38.2 Z-5\no<tap> call",
    "o<tap> sub\nM73\nG95 F1 S100 M3\nG1 Z-1\no<tap> endsub\no<tap> call\nG38.2 Z-5",
    "o<c> sub\nG93 G1 X1 F1\no<c> endsub\nG81 X1 Y1 Z-1 R2\nG80\no<c> call",
    "o<s> sub\nG95\no<s> endsub\nF10\nG81 X1 Y1 Z-1 R2\nG80",
    "o1 if [0]\nG95\no1 endif\nG38.2 Z-5",
    "o1 if [1]\nG1 X1\no1 else\nG95\no1 endif\nG38.2 Z-5",
    "o1 if [0]\nG93\no1 endif\nG81 X1 Y1 Z-1 R2\nG80",
    "o<s> sub\nM[3.5]\no<s> endsub",
    "o1 if [0]\nM[3.5]\no1 endif",
    "#<i>=0\no1 while [#<i> LT 3]\no2 if [#<i> GT 0]\nG1 X#<prev>\no2 endif\n"
    "#<prev>=[#<i>*2]\n#<i>=[#<i>+1]\no1 endwhile",
    "M73\nG38.2 Z-1",
    # a G1 under G93 sets rs274's feed rate to its length times F (interp_inverse.cc): the
    # probe after it under G93 has one (review 17, found by rs274_random.py --flow, seed 5)
    "G95\nG93 G1 X1 F2\nG91 G0 X0\nG38.2 X1 Y0",
    # an M98 call of a FANUC-style subprogram (LinuxCNC 2.9) may set another feed mode
    # (review 17: its G94 ran, the probe was refused for the caller's G95)
    "G95 F0.1 S100 M3\nM98 P1000\nG38.2 Z-5\nM2\nO1000\nG94 F100\nM99",
    # 0.1 + 0.2 is 0.30000000000000004 to rs274, not the 0.3 of the word (review 16c, 3)
    "G91\nG0 Z0.1\nG0 Z0.2\nG90\nG38.2 Z0.3",
    "G91\nG0 Z0.1\nG0 Z0.7\nG90\nG38.2 Z0.8",
    "G91\nG0 Z0.1\nG0 Z0.2\nG0 Z-0.3\nG90\nG38.2 Z0",
    "G20\nG0 X0 Y0 Z0\nG91\nG0 Z0.1\nG0 Z0.2\nG90\nG38.2 Z0.3",
    "G91\nG0 X0.1 Y0.1\nG0 X0.2 Y0.2\nG90\nG3 X0.3 Y0.3 R2",
    "G91 G0 X0.1\nG0 X0.2\nG90 G2 X0.3 Y0 R5",
]


@pytest.mark.parametrize("body", ACCEPTED)
def test_linuxcnc_runs_the_same_words_where_a_code_uses_them(tmp_path, body):
    text = program(body)
    assert [f for f in errors(text) if f[0] == "TG412"] == []
    out = rs274_output(tmp_path, text)
    assert "PROGRAM_END" in out, out


def test_a_block_with_a_code_rs274_lacks_is_told_for_the_code_alone():
    """Stock rs274 stops at `G41.2` while it reads the block ("Unknown g code used"), before it
    checks the block's words; a configuration may REMAP it (G0-G99.9, the Remap manual's
    "Currently unallocated G-codes"), and the remap takes the block's words: either way the D
    beside it (a Tormach post's) is not refused. The code is TG307, the warning naming REMAP;
    G100 and two decimals, which no REMAP reaches, are TG306."""
    text = program("G1 G41.2 X1 Y1 D4")
    assert errors(text) == []
    warned = [(f.rule, f.line) for f in check_text(text, load_profile("linuxcnc"))
              if f.severity == "warning"]
    assert warned == [("TG307", 3)], warned
    found = errors(program("G1 G41.25 X1 Y1 D4"))
    assert [(r, n) for r, n, _ in found] == [("TG306", 3)], found


@pytest.mark.parametrize("plane, block, message", [
    ("G17", "G2 Z-1 R5", "X and y words missing for arc in xy plane"),
    ("G18", "G3 Y1 R5", "X and z words missing for arc in xz plane"),
    ("G19", "G2 X1 R5", "Y and z words missing for arc in yz plane"),
])
def test_an_r_arc_names_an_end_on_its_plane(tmp_path, plane, block, message):
    """From the start of the program, where the tool stands is not known (tapegate judges no
    arc there), but an R arc with no word of its plane's axes is refused wherever it starts
    (interp_convert.cc convert_arc: "a full circle is not allowed")."""
    text = f"G21 {plane} G90 F100\n{block}\nM2\n"
    found = errors(text)
    assert [(r, n) for r, n, _ in found] == [("TG412", 2)], found
    assert message in found[0][2], found
    assert message in rs274_output(tmp_path, text)


def test_after_a_call_the_motion_is_unknown_and_the_words_are_not_refused():
    text = f"{HEAD}o<s> call\nX1 Y1 I1 J1 R2 Q1\nI1\nM2\n"
    assert [f for f in errors(text) if f[0] == "TG412"] == []


@pytest.mark.parametrize("body, rs274_says", [
    # rs274's tool table holds no offsets, its G59.3 none: on a machine both hold values, so
    # the arc's start in the active coordinates is the machine's. rs274 itself finds the
    # start moved by the tool offset ("too small" to reach a different end).
    ("G18\nG0 X1 Z0\nG43 H1\nG2 X1 Z0 R5", "Arc radius too small to reach end point"),
    ("G0 X1 Y0\nG59.3\nG2 X1 Y0 R5", "Current point same as end point of arc"),
    # G92 sets only the axes it names: Y is the machine's after G28
    ("G28\nG92 X0\nG2 X0 Y0 R5", "Current point same as end point of arc"),
    # G43.1's words are the offsets
    ("G0 X1 Y0\nG43.1 X1\nG2 X1 Y0 R5", "PROGRAM_END"),
    # G53's words are machine coordinates: the same point only where no offset is in force
    ("G0 X1 Y0\nG53 G0 X1 Y0\nG2 X1 Y0 R5", "Current point same as end point of arc"),
])
def test_an_r_arc_after_an_offset_the_machine_holds_is_not_judged(tmp_path, body, rs274_says):
    """A work offset or a tool length offset chosen leaves the current point unknown in the
    coordinates the arc is written in until an absolute move on the axis: tapegate refuses no
    such arc, where rs274 -g, whose offsets are all zero, judges it against its own."""
    text = program(body)
    assert [f for f in errors(text) if f[0] == "TG412"] == []
    assert rs274_says in rs274_output(tmp_path, text)


@pytest.mark.parametrize("body", [
    # a probe and a NURBS read rs274's feed rate, not an inverse time: no F under G93 where
    # they run after a G1 (review 15's fuzzing against rs274)
    "G93 G1 X1 F2\nG38.2 X5\nX6",
    "G93 G1 X1 F2\nG5.2 X1 Y1 P1\nX2 Y2 P1\nG5.3",
    # G43.1's axis words are offsets: no probe or NURBS point runs them
    "G38.2 X1 Y0\nF0\nG43.1 Z1",
    "G5.2 X1 Y1 P1\nG43.1 Z1",
    # an M code of unknown value may start the spindle
    "M[1+2] S100\nG33 Z-1 K1",
    # G43.1 takes its offsets without a motion mode in force (enhance_block)
    "G1 X1\nG80\nG43.1 Z1",
    # under G93 an F the checker cannot evaluate is the block's F (held12's thread subroutine)
    "G93 G1 X1 F[75.0]\nX[1+1] Z-1 F[60/2]\nG94",
])
def test_linuxcnc_programs_rs274_runs_have_no_error(tmp_path, body):
    text = program(body)
    assert errors(text) == []
    out = rs274_output(tmp_path, text)
    assert "PROGRAM_END" in out, out


def test_g93_asks_the_block_after_an_expression_f_for_its_own(tmp_path):
    text = program("G93 G1 X1 F[75.0]\nG1 X2\nG94")
    assert [(r, n) for r, n, _ in errors(text)] == [("TG402", 4)]
    assert "F word missing with inverse time g1 move" in rs274_output(tmp_path, text)


def test_g93_still_asks_a_g1_for_its_f_after_a_nurbs(tmp_path):
    text = program("G93 G1 X1 F2\nG5.2 X1 Y1 P1\nX2 Y2 P1\nG5.3\nG1 X3")
    assert [(r, n) for r, n, _ in errors(text)] == [("TG402", 7)]
    assert "F word missing with inverse time g1 move" in rs274_output(tmp_path, text)


# Review 19 (findings 3, 4 and 6), each program compared with rs274 -g.
RS274_RUNS_REVIEW19 = [
    # the feed mode after a call, an M98 or a G93/G94/G95 in a condition is unsure: TG402 and
    # the G95 spindle refusal are not judged until the main program sets it unconditionally
    f"{HEAD}G93\no<s> call\nG1 X1\nM2\no<s> sub\nG94 F100\no<s> endsub\n",
    f"{HEAD}G93\nM98 P100\nG1 X1\nM2\nO100\nG94 F100\nM99\n",
    program("o1 if [0]\nG93\no1 endif\nG1 X1"),
    program("o1 if [0]\nG95\no1 endif\nS0\nG1 X1 F100"),
    # an F under an unsure mode may or may not set rs274's feed rate (not under G93)
    program("G93 G1 X1 F1\no1 if [0]\nG94\no1 endif\nF0\nG38.2 X5"),
    # a definition's body runs under its caller's mode, not the one before its sub
    program("G93\no<s> sub\nG1 X1\no<s> endsub\nG94 F100\no<s> call"),
    # an M2 in a condition resets no mode: the lines after it run where it did not
    program("G18\no1 if [#5420 GT 100]\nM2\no1 endif\nG0 X0 Z0\nG2 X2 Z0 I1 K0"),
    # an M2 in a condition never closed: the definition after it is not reached again
    f"{HEAD}o1 if [1]\no<s> call\nM2\no<s> sub\nG0 X1\no<s> endsub\n",
    # the G5.2 blocks leave the current point where it was (convert_nurbs)
    program("G5.2 X1 Y1 P1\nG2 X0 Y0 I1 J0"),
    program("G5.2 X1 Y1 P1\nX2 Y2 P1\nG1 X5\nG2 X0 Y0 I-2.5"),
    # under G91 each point is from that point; G5.3 ends at the last one (X1 Y1)
    program("G91\nG5.2 X1 Y1 P1\nX1 Y1 P1\nX1 Y1 P1\nG5.3\nG90\nG2 X0 Y0 I-0.5 J-0.5"),
    # G5 and G5.1 keep the motion mode (convert_spline sets none): a point after a G5.1
    # inside a G5.2 is a control point, a word after G1 / G5.1 a feed
    program("G5.2 X1 Y1 P1\nG5.1 X1 Y1 I1 J1\nX1 Y1 P1"),
    program("G5.2 X1 Y1 P1\nG5.1 X1 Y1 I1 J1\nX2 Y2 P1\nX3 Y0 P1\nG5.3\nG1 X0"),
    program("G1 X0 F100\nG5.1 X1 Y1 I1 J1\nX2"),
]


@pytest.mark.parametrize("text", RS274_RUNS_REVIEW19)
def test_review19_programs_rs274_runs_have_no_error(tmp_path, text):
    assert errors(text) == []
    out = rs274_output(tmp_path, text)
    assert "PROGRAM_END" in out, out


# (the program, tapegate's rule and line, tapegate's and rs274's words)
RS274_REFUSES_REVIEW19 = [
    # a G93 the main program runs unconditionally makes the mode sure again
    (program("o1 if [0]\nG94\no1 endif\nG93\nG1 X1"), "TG402", 7,
     "every motion block needs its F", "F word missing with inverse time g1 move"),
    # a definition's own G93 is its body's mode
    (program("o<s> sub\nG93\nG1 X1\no<s> endsub\no<s> call"), "TG402", 5,
     "every motion block needs its F", "F word missing with inverse time g1 move"),
    # after an M2 in a condition the lines are judged: they run where it did not (the
    # condition is false on rs274, #5420 being 0)
    (program("o1 if [#5420 GT 100]\nM2\no1 endif\nG0 X1\nG0 X#<undefined>"), "TG412", 7,
     "Named parameter #<undefined> not defined", "Named parameter #<undefined> not defined"),
    (program("G93\no1 if [#5420 GT 100]\nM2\no1 endif\nG1 X1"), "TG402", 7,
     "every motion block needs its F", "F word missing with inverse time g1 move"),
    (program("o<s> sub\nM2\no<s> endsub\nG0 X#<undefined>"), "TG412", 6,
     "Named parameter #<undefined> not defined", "Named parameter #<undefined> not defined"),
    (f"{HEAD}o<s> call\no1 if [#5420 GT 100]\nM2\no1 endif\no<s> sub\nG0 X1\no<s> endsub\nM2\n",
     "TG412", 7, "sub: o|s| found in illegal location", "sub: o|s| found in illegal location"),
    # G5.3 puts the current point at the last control point: the arc starts at X2 Y0
    (program("G5.2 X1 Y1 P1\nX2 Y0 P1\nG5.3\nG2 X0 Y0 I-1.5 J0"), "TG403", 6,
     "start radius 1.5000 and end radius 0.5000",
     "Radius to end of arc differs from radius to start"),
    # a G5.1 empties the NURBS list: the next point starts a new one from the G5.1's end
    (program("G5.2 X1 Y1 P1\nG5.1 X1 Y1 I1 J1\nX2 Y2 P1\nG5.3"), "TG412", 6,
     "at least equal to the order L = 3",
     "You must specify a number of control points at least equal to the order L = 3"),
    # after G0 / G5.1 the mode is G0's, which takes no P
    (program("G5.1 X1 Y1 I1 J1\nX2 Y1 P1"), "TG412", 4, "P word with no G2 G3 G4",
     "P word with no G2 G3 G4"),
]


@pytest.mark.parametrize("text, rule, line, message, rs274_says", RS274_REFUSES_REVIEW19)
def test_review19_programs_rs274_refuses(tmp_path, text, rule, line, message, rs274_says):
    # (beside a TG402, TG401: the condition, call or definition left no feed rate known)
    found = [f for f in errors(text) if (f[0], f[1]) != ("TG401", line) or rule != "TG402"]
    assert [(r, n) for r, n, _ in found] == [(rule, line)], found
    assert message in found[0][2], found
    assert rs274_says in rs274_output(tmp_path, text)


# Review 20, finding 3: an M2 in an `if` branch ends nothing for the `else`/`elseif` branch,
# which runs where it did not; each compared with rs274 -g
RS274_REFUSES_REVIEW20_BRANCH = [
    (f"{HEAD}o1 if [#1 GT 0]\nM2\no1 else\no<s> call\no1 endif\n"
     "o<s> sub\nG0 X1\no<s> endsub\nM2\n", 8),
    (f"{HEAD}o1 if [#1 GT 0]\nM2\no1 elseif [#1 EQ 0]\no<s> call\no1 endif\n"
     "o<s> sub\nG0 X1\no<s> endsub\nM2\n", 8),
    # the M2 in a condition nested in the `if` branch
    (f"{HEAD}o1 if [#1 GT 0]\no2 if [1]\nM2\no2 endif\no1 else\no<s> call\no1 endif\n"
     "o<s> sub\nG0 X1\no<s> endsub\nM2\n", 10),
]


@pytest.mark.parametrize("text, line", RS274_REFUSES_REVIEW20_BRANCH)
def test_review20_an_end_in_an_if_branch_leaves_its_else_branch_read(tmp_path, text, line):
    found = errors(text)
    assert [(r, n) for r, n, _ in found] == [("TG412", line)], found
    assert "sub: o|s| found in illegal location" in found[0][2]
    assert "sub: o|s| found in illegal location" in rs274_output(tmp_path, text)



# Issue 32, item 2: an `if` with an `else` whose every branch ends in M2 ends the program at
# its `endif`: a definition after it is never reached again (no "found in illegal location");
# rs274 -g runs each to its PROGRAM_END, with the condition true and false
BOTH_BRANCHES_END = [
    "o<s> call\no1 if [#1 GT 0]\nG0 X1\nM2\no1 else\nG0 X2\nM2\no1 endif\n"
    "o<s> sub\nG0 X3\no<s> endsub\nM2\n",
    # an `elseif` between, and an M2 in an `if` nested in the last branch whose own branches
    # both end
    "o<s> call\no1 if [#1 GT 1]\nM2\no1 elseif [#1 GT 0]\nM30\no1 else\no2 if [#2 GT 0]\n"
    "M2\no2 else\nM2\no2 endif\no1 endif\no<s> sub\nG0 X3\no<s> endsub\nM2\n",
]


@pytest.mark.parametrize("body", BOTH_BRANCHES_END)
@pytest.mark.parametrize("value", ["0", "1", "2"])
def test_an_if_all_of_whose_branches_end_ends_the_program(tmp_path, body, value):
    text = f"{HEAD}#1={value}\n#2={value}\n{body}"
    assert errors(text) == []
    out = rs274_output(tmp_path, text)
    assert "PROGRAM_END" in out and "illegal location" not in out, out


# ... and a branch that does not end, or no `else` (the condition may be false), leaves the
# definition read after the call: rs274 refuses it where that branch runs (#1 = 0)
ONE_BRANCH_RUNS_ON = [
    ("o<s> call\no1 if [#1 GT 0]\nM2\no1 else\nG0 X2\no1 endif\n"
     "o<s> sub\nG0 X3\no<s> endsub\nM2\n", 10),
    ("o<s> call\no1 if [#1 GT 0]\nM2\no1 elseif [#1 LT 0]\nM2\no1 endif\n"
     "o<s> sub\nG0 X3\no<s> endsub\nM2\n", 10),
    ("o<s> call\no1 if [#1 GT 0]\nM2\no1 else\no2 if [#1 LT 0]\nM2\no2 endif\no1 endif\n"
     "o<s> sub\nG0 X3\no<s> endsub\nM2\n", 12),
]


@pytest.mark.parametrize("body, line", ONE_BRANCH_RUNS_ON)
def test_an_if_with_a_branch_that_runs_on_leaves_the_lines_after_it_read(tmp_path, body, line):
    text = f"{HEAD}#1=0\n{body}"
    found = errors(text)
    assert [(r, n) for r, n, _ in found] == [("TG412", line)], found
    assert "sub: o|s| found in illegal location" in found[0][2]
    assert "sub: o|s| found in illegal location" in rs274_output(tmp_path, text)


# Issue 32, item 4: after `o<s> call` of a subroutine defined before it in the file whose body
# (and the bodies it calls, each defined before the call) sets no feed mode and ends nothing,
# the mode is the one before the call: a G1 without F under G93 after it is TG402, as rs274
# refuses it
SUBS = ("o<t> sub\nG0 Y1\no<t> endsub\n"
        "o<s> sub\nG1 X1 F10\no<t> call\no<s> endsub\n")


def test_a_call_of_a_subroutine_that_sets_no_feed_mode_keeps_the_mode(tmp_path):
    text = f"{HEAD}{SUBS}G93\no<s> call\nG1 X2\nM2\n"
    found = [f for f in errors(text) if f[0] != "TG401"]
    assert [(r, n) for r, n, _ in found] == [("TG402", 12)], found
    assert "F word missing with inverse time g1 move" in rs274_output(tmp_path, text)


T_SUB = "o<t> sub\nG0 Y1\no<t> endsub\n"
S_SUB = "o<s> sub\nG1 X1 F10\no<t> call\no<s> endsub\n"


@pytest.mark.parametrize("before, after, sets", [
    # the called body, or one it calls, sets the mode: G94 after the call, rs274 runs on
    (SUBS.replace("G0 Y1", "G94 G0 Y1"), "", True),
    (SUBS.replace("G1 X1 F10", "G94 G1 X1 F10"), "", True),
    # the sub it calls is defined after the call (rs274 reads ahead to it): not followed
    (S_SUB, T_SUB, False),
    # the called sub is defined after the call: not followed
    ("", S_SUB + T_SUB, False),
])
def test_a_call_that_may_set_the_feed_mode_leaves_it_not_known(tmp_path, before, after, sets):
    text = f"{HEAD}{before}G93\no<s> call\nG1 X2 F1\nG1 X3\nM2\n{after}"
    assert [f for f in errors(text) if f[0] == "TG402"] == [], errors(text)
    out = rs274_output(tmp_path, text)
    if sets:
        assert "PROGRAM_END" in out and "F word missing" not in out, out
    else:
        # (G93 is still in force: rs274 refuses the G1 without F, which the check, not
        # following a body defined after the call, leaves unjudged)
        assert "F word missing with inverse time g1 move" in out, out


# Review 20, finding 1: a binary operation outside [ ] after a value (rs274ngc reads one only
# inside [ ]; read_items stops at the operator); (the block after HEAD, the operator's column)
RS274_REFUSES_BARE_OPERATOR = [
    ("#2=1\n#1=#2*3", 6, "*"),
    ("#1 = [1] * 2", 10, "*"),
    ("#<a>=4\n#4=#<a>/2", 8, "/"),
    ("#5=sin[30]*2", 11, "*"),
    ("#2=1\n#4=#2 + 1", 7, "+"),
    ("#2=1\n#4=#2-1", 6, "-"),
]


@pytest.mark.parametrize("body, column, op", RS274_REFUSES_BARE_OPERATOR)
def test_review20_an_operation_outside_brackets_is_refused(tmp_path, body, column, op):
    text = program(body)
    line = text.count("\n", 0, text.index(body.splitlines()[-1])) + 1
    found = [f for f in check_text(text, load_profile("linuxcnc")) if f.severity == "error"]
    assert [(f.rule, f.line, f.column) for f in found] == [("TG412", line, column)], found
    assert found[0].message.startswith(f"Bad character '{op}' used (rs274ngc)")
    assert f"Bad character '{op}' used" in rs274_output(tmp_path, text)


@pytest.mark.parametrize("body", [
    # a sign, a bracketed expression, ATAN's two arguments
    "#2=1\n#3=-#2\nG0 X-[#2]", "#1=ATAN[1]/[2]", "#1=[2*3]",
])
def test_review20_a_value_rs274_reads_is_not_refused(tmp_path, body):
    text = program(body)
    assert errors(text) == []
    out = rs274_output(tmp_path, text)
    assert "PROGRAM_END" in out, out


# Review 21, finding 1: the operation in a line that may run -- a loop's counter, an `if`
# branch, a subroutine's body -- is refused where it stands, as rs274 refuses it when it runs
# the line; (the blocks after HEAD, the line, the column, the operator, whether the line
# surely runs where the program reaches it: a block known to run, lcnc51)
RS274_REFUSES_BARE_OPERATOR_MAY_RUN = [
    ("#1=0\no1 while [#1 LT 2]\n#1=#1+1\no1 endwhile", 5, 6, "+", True),
    ("#1=2\no1 if [1]\n#2=#1*3\no1 endif", 5, 6, "*", True),
    # (the else of an if known false: it runs wherever the if is reached, review 52, F4)
    ("#1=2\no1 if [#1 GT 5]\nG0 X1\no1 else\n#2=#1/3\no1 endif", 7, 6, "/", True),
    ("o1 do\n#3=#3-1\no1 while [#3 GT 0]", 4, 6, "-", True),
    ("o1 if [ABS[-2] GT 1]\n#3=#3-1\no1 endif", 4, 6, "-", False),
    ("o100 sub\n#<n>=#1*2\nG0 X#<n>\no100 endsub\no100 call [3]", 4, 8, "*", False),
]


@pytest.mark.parametrize("body, line, column, op, surely", RS274_REFUSES_BARE_OPERATOR_MAY_RUN)
def test_review21_an_operation_outside_brackets_is_refused_where_it_may_run(
        tmp_path, body, line, column, op, surely):
    text = program(body)
    found = [f for f in check_text(text, load_profile("linuxcnc")) if f.severity == "error"]
    assert [(f.rule, f.line, f.column) for f in found] == [("TG412", line, column)], found
    assert found[0].message.startswith(f"Bad character '{op}' used (rs274ngc)")
    assert ("rs274 refuses it when it runs it" in found[0].message) != surely
    out = rs274_output(tmp_path, text)
    assert f"Bad character '{op}' used" in out and "PROGRAM_END" not in out, out


@pytest.mark.parametrize("body", [
    "o1 if [#<_x> GT 1]\n{}\no1 endif",
    "o1 while [#<_x> GT 1]\n{}\no1 endwhile",
    "o100 sub\n{}\no100 endsub",
])
def test_review21_a_line_rs274_may_not_run_is_judged_as_g10_l50_is(tmp_path, body):
    # a condition the checker does not work out (#<_x>, the current X position, is not
    # followed), or a definition it does not follow the calls of: a line there is judged as
    # one that may run, the same for the operation as for the other forms rs274 refuses
    # (G10 L50) -- an error that rs274, running the program to its end, does not make
    for line, rule_message in [("#1=#2*3", "Bad character '*' used"),
                               ("G10 L50", "Line with G10 does not have L0")]:
        text = program(body.format(line))
        found = errors(text)
        assert [(r, n) for r, n, _ in found] == [("TG412", 4)], found
        assert rule_message in found[0][2]
        out = rs274_output(tmp_path, text)
        assert "PROGRAM_END" in out, out


@pytest.mark.parametrize("body", [
    "o1 if [0]\n{}\no1 endif",
    "o1 while [0]\n{}\no1 endwhile",
    "o1 repeat [0.5]\n{}\no1 endrepeat",
    "o1 if [1]\nG0 X1\no1 else\n{}\no1 endif",
])
def test_review51_a_line_known_never_to_run_is_not_judged(tmp_path, body):
    # review 51, F4: where the checker knows the condition (or the count, rounded half to
    # even), the lines rs274 skips are judged by no rule, as rs274 runs none of them
    for line in ["#1=#2*3", "G10 L50", "G91\nG53 G0 X0", "M72", "G53 G2 X1"]:
        text = program(body.format(line))
        assert errors(text) == [], text
        out = rs274_output(tmp_path, text)
        assert "PROGRAM_END" in out, out


def test_review21_the_lines_after_the_end_are_not_judged_but_a_definition_there_is(tmp_path):
    # (TG117: rs274 stops at the M2; a call finds a definition after it)
    after_end = f"{HEAD}M2\n#1=#1+1\n"
    assert errors(after_end) == []
    called = f"{HEAD}o100 call\nM2\no100 sub\n#1=#1+1\no100 endsub\n"
    found = [f for f in check_text(called, load_profile("linuxcnc")) if f.severity == "error"]
    assert [(f.rule, f.line, f.column) for f in found] == [("TG412", 6, 6)], found
    assert "Bad character '+' used" in rs274_output(tmp_path, called)


# Review 21, finding 3: the fix the message names keeps the parameter assigned (`#<b>=[...]`,
# not `#[...]`, LinuxCNC's indexed parameter), and an indexed word of a letter is refused at its
# `=`, where rs274 stops; (the block after HEAD, the column, rs274's message, the fix or None)
RS274_REFUSES_REVIEW21_ASSIGNMENT = [
    ("#<a>=2\n#<b>=#<a>*2", 10, "Bad character '*' used", "(write #<b>=[...])"),
    ("#<_g>=2\n#<_g>=#<_g>-1", 12, "Bad character '-' used", "(write #<_g>=[...])"),
    ("#1=2\n#12=#1+1", 7, "Bad character '+' used", "(write #12=[...])"),
    ("R7=R5-R4", 3, "Bad character '=' used", None),
    ("R7 = R5 * 2", 4, "Bad character '=' used", None),
]


@pytest.mark.parametrize("body, column, says, fix", RS274_REFUSES_REVIEW21_ASSIGNMENT)
def test_review21_the_refusal_names_what_rs274_says_and_a_fix_it_reads(
        tmp_path, body, column, says, fix):
    text = program(body)
    line = text.count("\n", 0, text.index(body.splitlines()[-1])) + 1
    found = [f for f in check_text(text, load_profile("linuxcnc"))
             if f.severity == "error" and f.message.startswith("Bad character")]
    assert [(f.rule, f.line, f.column) for f in found] == [("TG412", line, column)], found
    assert found[0].message.startswith(f"{says} (rs274ngc)"), found
    out = rs274_output(tmp_path, text)
    assert says in out, out
    if fix is None:
        assert "(write" not in found[0].message
        return
    assert found[0].message.endswith(fix), found
    # the fix written: rs274 runs it to its end, and the parameter it sets is the one named
    fixed = text.replace(body.splitlines()[-1], fix[7:-6] + "[" + body.splitlines()[-1].split(
        "=", 1)[1] + "]")
    assert errors(fixed) == []
    out = rs274_output(tmp_path, fixed)
    assert "PROGRAM_END" in out, out


@pytest.mark.parametrize("body, column, rule", [
    # in an address's value the reading refuses the operator first, at the same column
    ("#2=1\nG0 X#2+1", 7, "TG100"), ("#1=1\nG0 X-#1*2", 8, "TG101"),
    ("#1=1\nG0 X#1/2", 7, "TG123"),
])
def test_review21_an_operation_in_an_address_value_is_the_readings_refusal(
        tmp_path, body, column, rule):
    text = program(body)
    line = text.count("\n", 0, text.index(body.splitlines()[-1])) + 1
    found = [f for f in check_text(text, load_profile("linuxcnc")) if f.severity == "error"]
    assert [(f.rule, f.line, f.column) for f in found] == [(rule, line, column)], found
    op = body[-2]
    assert f"Bad character '{op}' used" in rs274_output(tmp_path, text)


# Review 21: the G95 refusal with no spindle speed after an `o.. if/endif` whose branches
# provably set no S (no S word, call, loop, M2/M30/M98/M99 inside): the speed after the endif
# is the speed before the if, judged there. Each compared with rs274 -g.
G95_NO_SPEED = "Cannot feed with zero spindle speed in feed per rev mode"
RS274_REFUSES_REVIEW21_SPEED = [
    (program("#1=1\no1 if [#1 GT 0]\nG0 X1\no1 endif\nG0 X1 Y1 G95\nG1 X5 F1"), 8),
    # both branches, and a nested condition, set no S
    (program("#1=1\no1 if [#1 GT 0]\nG0 X1\no1 else\no2 if [1]\nG0 Y1\no2 endif\no1 endif\n"
             "G95\nG1 X5 F1"), 12),
    # S0 before the condition is the speed after it
    (program("S0\no1 if [1]\nG0 X1\no1 endif\nG95\nG1 X5 F1"), 8),
]


@pytest.mark.parametrize("text, line", RS274_REFUSES_REVIEW21_SPEED)
def test_review21_the_speed_before_a_condition_that_sets_none_is_judged_after_it(
        tmp_path, text, line):
    found = errors(text)
    assert [(r, n) for r, n, _ in found] == [("TG412", line)], found
    assert G95_NO_SPEED in found[0][2]
    assert G95_NO_SPEED in rs274_output(tmp_path, text)


RS274_RUNS_REVIEW21_SPEED = [
    # an S in the branch that runs, or a call there: the speed after the endif is not known
    # from the lines (unsure, not judged); rs274 runs them
    program("o1 if [1]\nS100\no1 endif\nG95\nG1 X5 F1"),
    program("o1 if [1]\no<s> call\no1 endif\nG95\nG1 X5 F1\nM2\no<s> sub\nS100\no<s> endsub"),
    program("#1=0\no1 if [#1 GT 0]\nG0 X1\no1 else\nS200\no1 endif\nG95\nG1 X5 F1"),
    # a speed before the condition is the speed after it
    program("S500\no1 if [1]\nG0 X1\no1 endif\nG95\nG1 X5 F1"),
]


@pytest.mark.parametrize("text", RS274_RUNS_REVIEW21_SPEED)
def test_review21_a_condition_that_may_set_the_speed_leaves_it_unsure(tmp_path, text):
    assert errors(text) == []
    out = rs274_output(tmp_path, text)
    assert "PROGRAM_END" in out, out


@pytest.mark.parametrize("block, column, letter", [
    ("G2 X2 Y0 R0.5 I0.5", 15, "I"),
    # any of I J K, on the plane or not: rs274 asks before it looks at the plane
    ("G2 X2 Y0 R0.5 K0.5", 15, "K"),
    ("G18 G2 X2 Z0 R0.5 I0.5", 19, "I"),
    # an I of zero is an I word all the same
    ("G3 X2 Y0 I0 R0.5", 10, "I"),
])
def test_an_arc_with_r_and_i_j_k_is_refused(tmp_path, block, column, letter):
    """interp_convert.cc convert_arc: "Mixed radius ijk format for arc", at the first I J K."""
    text = program(f"G1 X1\n{block}")
    found = [(f.rule, f.line, f.column, f.message)
             for f in check_text(text, load_profile("linuxcnc")) if f.severity == "error"]
    assert [(r, n, c) for r, n, c, _ in found] == [("TG412", 4, column)], found
    assert "Mixed radius ijk format for arc" in found[0][3], found
    assert f"gives R and {letter}" in found[0][3], found
    assert "Mixed radius ijk format for arc" in rs274_output(tmp_path, text)


def test_an_arc_by_r_alone_or_by_i_j_alone_is_not_mixed(tmp_path):
    text = program("G1 X1\nG2 X2 Y0 R0.5\nG2 X3 Y0 I0.5 J0")
    assert errors(text) == []
    assert "PROGRAM_END" in rs274_output(tmp_path, text)


def test_a_fanuc_arc_with_r_and_i_j_k_passes_the_fanuc_check():
    """A FANUC reads the arc by R and ignores I J K (16/18-C Lathe Operator's Manual)."""
    text = ("%\nO1000\nG21 G17 G90\nG0 X0 Y0 Z5.\nS500 M3\nG1 X1. F100.\n"
            "G2 X2. Y0 R0.5 I0.5\nM30\n%\n")
    found = [f for f in check_text(text, load_profile("fanuc-mill")) if f.severity == "error"]
    assert found == [], found


M98_SUB = "\nO100\nG0 Z1.\nM99\n"  # a FANUC-style subprogram, which M98 calls


@pytest.mark.parametrize("block, column, message", [
    ("G1 X10. F100. M98 P100", 15, "Unknown m code used: M98 (rs274ngc)"),
    ("M8 M98 P100", 4, "Unknown m code used: M98 (rs274ngc)"),
    ("(call) M98 P100", 8, "Unknown m code used: M98 (rs274ngc)"),
    ("#1=2 M98 P100", 6, "Unknown m code used: M98 (rs274ngc)"),
    ("M98 P100 X5.", 10, "X5. beside M98: LinuxCNC reads M98 as a call with its P and L alone"),
    ("M98 P100 G1 X10. F100.", 10, "G1 beside M98"),
    ("M98 P100 M8", 10, "M8 beside M98"),
])
def test_m98_beside_other_words_is_refused_as_rs274_reads_it(tmp_path, block, column, message):
    """Review 28, finding 3: LinuxCNC reads M98 where an O word stands, as the block's first
    word after its N (rs274ngc interp_read.cc read_o), then the call's P and L: a word before
    it is refused ("Unknown m code used: M98"), a word after it refused or not run at all
    (`M98 P100 G1 X10. F100. M8` calls and neither moves nor turns the coolant on). The check
    had no error for either."""
    text = program(block).replace("M2\n", "M2" + M98_SUB)
    found = [(f.rule, f.line, f.column, f.message)
             for f in check_text(text, load_profile("linuxcnc")) if f.severity == "error"]
    assert len(found) == 1, found
    assert found[0][:3] == ("TG412", 3, column)
    assert message in found[0][3]
    out = rs274_output(tmp_path, text)
    if message.startswith("Unknown"):
        assert "Unknown m code used: M98" in out
    else:
        # the call runs, the block's other words do not (no move to X5 or X10, no feed move,
        # no coolant), under the G0 in force too
        assert "STRAIGHT_TRAVERSE(0.0000, 0.0000, 1.0000" in out
        assert "STRAIGHT_TRAVERSE(5.0000" not in out and "STRAIGHT_FEED" not in out
        assert "FLOOD_ON" not in out


@pytest.mark.parametrize("block", ["M98 P100", "N5 M98 P100 L2", "M98 P100 (call)",
                                   "/M98 P100"])
def test_m98_first_with_its_p_and_l_is_clean(tmp_path, block):
    text = program(block).replace("M2\n", "M2" + M98_SUB)
    assert errors(text) == []
    out = rs274_output(tmp_path, text)
    assert "STRAIGHT_TRAVERSE(0.0000, 0.0000, 1.0000" in out  # the subprogram ran
    assert "PROGRAM_END" in out


@pytest.mark.parametrize("call", ["o#1 call [2]", "o[#1] call [2]", "O [ #1 ] call [2]",
                                  "o#<sub> call [2]", "o[#1*1] call [2]"])
def test_a_call_whose_label_is_worked_out_as_it_runs_is_read(tmp_path, call):
    """rs274ngc's ``read_o`` reads an o-word's label as a parameter or a bracketed expression
    too (``o#1 call``, ``o[#1] call``): LinuxCNC runs the subroutine of its value. The
    reader once refused these ("address c must be followed by a number"); now read, and
    where the parameter holds a known number the call is the numbered one's (the check's
    tests in the core: ``a_linuxcnc_call_by_a_parameter_calls_the_subroutine_of_its_value``)."""
    text = ("o100 sub\nG0 X#1\no100 endsub\n" + HEAD + "#1=100\n#<sub>=100\n" + call
            + "\nM2\n")
    found = check_text(text, load_profile("linuxcnc"))
    assert [f for f in found if f.severity == "error"] == []
    assert not any(f.rule.startswith("TG1") and f.rule not in ("TG133", "TG140", "TG141")
                   for f in found), found
    out = rs274_output(tmp_path, text)
    assert "STRAIGHT_TRAVERSE(2.0000, 0.0000, 0.0000" in out  # the subroutine ran, X#1 = 2
    assert "PROGRAM_END" in out


def test_a_plane_of_the_uvw_axes_under_compensation_is_refused_at_its_code(tmp_path):
    """Review 52, F3 (comp52): rs274's convert_set_plane lets G17.1-G19.1 pass under cutter
    radius compensation, but its compensated move and G40 then stop at the plane ("BUG: Invalid
    plane for cutter compensation"): refused at the code, column of the G, with the reason."""
    for code in ["G17.1", "G18.1", "G19.1"]:
        text = program(f"G41.1 D1\nG1 X5\n{code}\nG1 X10\nG40")
        found = [(f.rule, f.line, f.column, f.message) for f in check_text(
            text, load_profile("linuxcnc")) if f.severity == "error"]
        assert [(r, n, c) for r, n, c, _ in found] == [("TG412", 5, 1)], found
        assert "G17.1, G18.1 and G19.1 have no cutter radius compensation" in found[0][3]
        said = rs274_output(tmp_path, text)
        if said:
            assert "BUG:" in said and "plane" in said, said
    # without compensation the plane runs
    assert errors(program("G17.1\nG0 X1\nG17")) == []


@pytest.mark.parametrize("body, line, message", [
    ("G41.1 D1\nG18.1\nG1 X5", 5, "BUG: Invalid plane for cutter compensation"),
    ("G42.1 D1\nG4 P1\nG19.1\nM5\nX5", 7, "BUG: Invalid plane for cutter compensation"),
    ("G41.1 D1\nG18.1 G1 X5", 4, "BUG: Invalid plane for cutter compensation"),
    ("G41.1 D1\nG18.1\nG17.1\nG17", 6, "Cannot change planes with cutter radius compensation on"),
    # a flow the checker does not follow: refused there, not lost
    ("G41.1 D1\nG18.1\no1 if [#5220 GT 0]\nG1 X5\no1 endif\nG40", 5,
     "under cutter radius compensation (rs274ngc): the checker does not follow"),
])
def test_a_plane_of_the_uvw_axes_with_no_compensated_move_held_stops_at_the_next_move(
        tmp_path, body, line, message):
    """Review 53, F13: where no move came since the compensation turned on, rs274 holds no
    compensated move, lets G17.1-G19.1 pass and stops only at the next move (a G0 with no
    axis word too) or a change to G17-G19; a G40 or the program's end before it runs."""
    text = program(body)
    found = [(f.rule, f.line, f.column, f.message) for f in check_text(
        text, load_profile("linuxcnc")) if f.severity == "error"]
    assert [(r, n) for r, n, _, _ in found] == [("TG412", line)], found
    assert message in found[0][3]
    said = rs274_output(tmp_path, text)
    if said and "does not follow" not in message:
        assert message.split(" (")[0] in said, said


@pytest.mark.parametrize("body", [
    "G41.1 D1\nG18.1",
    "G41.1 D1\nG18.1\nG4 P1\nG40\nG1 X5",
    "G41.1 D1\nG18.1\nG1 G40 X3",
    "G41.1 D1\nG19.1\nG17.1\nG40\nG17",
])
def test_a_plane_of_the_uvw_axes_with_no_move_under_compensation_runs(tmp_path, body):
    """Review 53, F13: no move between the compensation's start and its G40 (or the end):
    rs274 runs the program, and the checker refuses nothing."""
    clean_on_both(tmp_path, program(body))


@pytest.mark.parametrize("body, line, column, message", [
    ("G41.1 D1\nG1 X5\nX1 G18", 5, 4, "Cannot change planes with cutter radius compensation on"),
    ("G18\nG41.1 D1\nG1 X5\nG17 G1 X4", 6, 1,
     "Cannot change planes with cutter radius compensation on"),
    ("G41.1 D1\nG1 X5\nG5 X2 Y2 I1 J0 P1 Q1", 5, 1,
     "Cannot convert spline with cutter radius compensation"),
    ("G41.1 D1\nG1 X5\nG30.1", 5, 1,
     "Cannot set reference point with cutter compensation in effect"),
])
def test_codes_rs274_refuses_under_compensation_are_told_at_the_g(tmp_path, body, line, column,
                                                                  message):
    """Review 52, F3 (comp52): the finding's line, column (the block's G word) and rs274's
    message (the column of the block's first G word, as every TG412 of a G code); rs274 -g,
    where installed, stops at the same line with it."""
    text = program(body)
    found = [(f.rule, f.line, f.column, f.message) for f in check_text(
        text, load_profile("linuxcnc")) if f.severity == "error"]
    assert [(r, n, c) for r, n, c, _ in found] == [("TG412", line, column)], found
    assert found[0][3].startswith(message), found
    said = rs274_output(tmp_path, text)
    if said:
        assert message in said, said

# Review 52, F8: an M2/M30 in a block known to run ends the program there, as one at the top
# does: no rule judges the lines after it (the rest of its branch, an else, the lines after
# the block), nor the rest of a branch after an M2 in a block not known to run
@pytest.mark.parametrize("body", [
    "o1 if [1]\nM2\no1 endif\nG999",
    "o1 if [1]\nM2\nG999\no1 endif",
    "o1 repeat [1]\nM30\no1 endrepeat\nG2 X1 F100",
    "o1 if [1]\nM2\no1 else\nG2 X1 F100\no1 endif",
    "o1 if [1]\no2 if [1]\nM2\no2 endif\nG999\no1 endif\nG998",
    "o1 do\no2 repeat [1]\nM30\no2 endrepeat\no1 while [0]\nM72",
    "o1 if [#<_x> GT 1]\nM2\nG999\no1 endif",
])
def test_review52_the_lines_after_an_m2_in_a_block_known_to_run_are_not_judged(tmp_path, body):
    clean_on_both(tmp_path, program(body))


def test_review52_the_lines_after_a_block_whose_m2_may_not_run_are_judged(tmp_path):
    # (the condition not known: the lines after the endif run where the M2 did not)
    text = program("o1 if [#<_x> GT 1]\nM2\no1 endif\nG999")
    assert [(rule, line) for rule, line, _ in errors(text)] == [("TG306", 6)]
    assert "G-code out of range" in rs274_output(tmp_path, text)


# Review 52, F4 (and review 51, F6): the state a block known to run leaves, nested in another
# known to run in any way, is the state after them: a G91 there refuses a G53 (the body
# after HEAD, the G53's line)
G53_AFTER_NESTED = [
    ("o1 if [1]\no2 if [1]\nG91\no2 endif\no1 endif\nG53 G0 Z0", 8),
    ("o1 if [1]\no2 if [1]\nG91\no2 endif\nG53 G0 Z0\no1 endif", 7),
    ("o1 repeat [1]\no2 if [1]\nG91\no2 endif\no1 endrepeat\nG53 G0 Z0", 8),
    ("o1 if [1]\no2 repeat [1]\nG91\no2 endrepeat\no1 endif\nG53 G0 Z0", 8),
    ("o1 if [1]\no2 if [0]\nG0 X0\no2 else\nG91\no2 endif\no1 endif\nG53 G0 Z0", 10),
    ("o1 do\no2 if [1]\nG91\no2 endif\no1 while [0]\nG53 G0 Z0", 8),
    ("#<k>=0\no1 do\no2 while [#<k> LT 1]\n#<k>=[#<k>+1]\nG91\no2 endwhile\no1 while [0]\n"
     "G53 G0 Z0", 10),
    ("o2 repeat [1]\no1 if [1]\nG91\no1 endif\no2 endrepeat\nG53 G0 X0", 8),
    # an else after a branch that ran does not run: the branch's G91 is the mode after
    ("o1 if [1]\nG91\no1 else\nG0 X1\no1 endif\nG53 G0 Z0", 8),
    # the lines after a block not known to run, in a block known to run, run
    ("o1 if [1]\no2 if [#<_x> GT 1]\nG0 X1\no2 endif\nG91\no1 endif\nG53 G0 Z0", 9),
]


@pytest.mark.parametrize("body, line", G53_AFTER_NESTED)
def test_review52_a_g91_in_nested_blocks_known_to_run_refuses_the_g53_after(
        tmp_path, body, line):
    text = program(body)
    message = refused_once(text, line)
    assert message.startswith("Cannot use g53 incremental (rs274ngc)")
    assert "Cannot use g53 incremental" in rs274_output(tmp_path, text)


@pytest.mark.parametrize("body", [
    "G91\no1 if [1]\no2 if [1]\nG90\no2 endif\no1 endif\nG53 G0 Z0",
    "o1 if [1]\no2 if [#<_x> GT 1]\nG91\no2 endif\no1 endif\nG53 G0 Z0",
    # a loop whose first turn runs a G91 and whose second a G90: the mode after it is not the
    # first turn's (its condition, or its count, runs it again)
    "#<k>=0\no1 while [#<k> LT 2]\no2 if [#<k> EQ 0]\nG91\no2 else\nG90\no2 endif\n"
    "#<k>=[#<k>+1]\no1 endwhile\nG53 G0 Z0",
    "#<k>=0\no1 repeat [2]\no2 if [#<k> EQ 0]\nG91\no2 else\nG90\no2 endif\n#<k>=1\n"
    "o1 endrepeat\nG53 G0 Z0",
    # a break surely taken (in a block known to run), or perhaps taken: the G91 after it
    # does not run, or may not
    "o1 do\no2 if [1]\no1 break\no2 endif\nG91\no1 while [0]\nG53 G0 Z0",
    "o1 do\no2 if [#<_x> LT 1]\no1 break\no2 endif\nG91\no1 while [0]\nG53 G0 Z0",
])
def test_review52_a_mode_nested_blocks_may_not_leave_refuses_nothing(tmp_path, body):
    clean_on_both(tmp_path, program(body))


@pytest.mark.parametrize("body, line, says", [
    ("o1 if [1]\no2 repeat [1]\nM[3.5]\no2 endrepeat\no1 endif", 5,
     "Non integer value for integer"),
    ("o1 if [1]\no2 if [1]\nM72\no2 endif\no1 endif", 5,
     "Cannot restore context from invalid stack frame"),
    ("o1 if [0]\nG0 X1\no1 else\no2 if [1]\nG0 X2 Y2 P1\no2 endif\no1 endif", 7,
     "P word with no"),
])
def test_review52_a_line_in_nested_blocks_known_to_run_is_refused_as_it_runs(
        tmp_path, body, line, says):
    text = program(body)
    message = refused_once(text, line)
    assert message.startswith(says), message
    assert "when it runs it" not in message
    assert says in rs274_output(tmp_path, text)


# Review 52, F7: a call that surely runs of a subroutine whose only definition stands in a
# block known not to run: rs274 skipped the definition without recording it and seeks the sub
# from the call to the end of the file
def test_review52_a_call_of_a_sub_defined_only_in_a_block_not_run_is_refused(tmp_path):
    text = program("o1 if [0]\no<s> sub\nG0 X1\no<s> endsub\no1 endif\no<s> call")
    found = errors(text)
    assert [(rule, line) for rule, line, _ in found] == [("TG412", 8)], found
    assert found[0][2].startswith("EOF in file seeking o-word: o<s> from line: 8 (rs274ngc)")
    out = rs274_output(tmp_path, text)
    assert "seeking o-word: o<s> from line: 8" in out, out


@pytest.mark.parametrize("body", [
    # a call before the definition finds it (the search reads o-word lines alone), and
    # rs274 skips it when it comes to the block
    "o<s> call\no1 if [0]\no<s> sub\nG0 X1\no<s> endsub\no1 endif",
    "o<s> call\no1 if [0]\no<s> sub\nG0 X1\no<s> endsub\no1 endif\no<s> call",
    # another definition the call finds after it
    "o1 if [0]\no<s> sub\nG0 X1\no<s> endsub\no1 endif\no<s> sub\nG0 X2\no<s> endsub\n"
    "o<s> call",
    # the skip goes on after the definition it passes over
    "o1 if [0]\no<s> sub\nG0 X1\no<s> endsub\nM72\no1 endif",
    # a definition in a block known to run, or in a loop of one turn
    "o1 if [1]\no<s> sub\nG0 X1\no<s> endsub\no1 endif\no<s> call",
    "o1 do\no<s> sub\nG0 X1\no<s> endsub\no1 while [0]\no<s> call",
    "o1 repeat [1]\no<s> sub\nG0 X1\no<s> endsub\no1 endrepeat\no<s> call",
])
def test_review52_a_sub_defined_in_a_block_is_found_where_rs274_finds_it(tmp_path, body):
    clean_on_both(tmp_path, program(body))


def test_review52_a_sub_defined_only_in_a_block_not_run_is_found_after_the_end(tmp_path):
    text = program("o1 if [0]\no<s> sub\nG0 X1\no<s> endsub\no1 endif\no<s> call") + (
        "o<s> sub\nG0 X2\no<s> endsub\n")
    assert errors(text) == [], text
    out = rs274_output(tmp_path, text)
    assert "PROGRAM_END" in out, out


# Review 52, F9: a break or continue of an if's label rs274 reads whichever way the condition
# goes (it runs the branch to it, or skips to it), and one of a subroutine's own label
@pytest.mark.parametrize("body, line, says", [
    ("o1 if [#5399 GT 1]\no1 break\no1 endif", 4,
     "no matching while/do label: 'o1 break' (found 'if' in line 3)"),
    ("o1 if [#<_x> GT 1]\no1 continue\no1 endif", 4,
     "no matching while/do label: 'o1 continue' (found 'if' in line 3)"),
    ("o1 if [#5399 LT 1]\no1 endif\no1 break", 5,
     "no matching while/do label: 'o1 break' (found 'if' in line 3)"),
    ("o1 repeat [#5399]\no1 break\no1 endrepeat", 4,
     "no matching while/do label: 'o1 break' (found 'repeat' in line 3)"),
    ("o<s> sub\no<s> continue\no<s> endsub\no<s> call", 4,
     "undefined O-word label: 'o<s> continue'"),
    ("o<s> sub\nG0 X1\no<s> break\no<s> endsub\no<s> call", 5,
     "undefined O-word label: 'o<s> break'"),
])
def test_review52_a_break_of_no_loop_s_label_is_refused(tmp_path, body, line, says):
    text = program(body)
    message = refused_once(text, line)
    assert message.startswith(says.split(":")[0] + " (rs274ngc)"), message
    assert says in rs274_output(tmp_path, text)


@pytest.mark.parametrize("body", [
    "o1 do\no2 if [#<_x> GT 1]\no1 break\no2 endif\nG0 X1\no1 while [0]",
    "o2 if [0]\no1 if [1]\no1 break\no1 endif\no2 endif",
    "o<s> sub\no1 if [#1 GT 1]\no<s> break\no1 endif\no<s> endsub\no<s> call",
])
def test_review52_a_break_rs274_does_not_refuse_is_clean(tmp_path, body):
    clean_on_both(tmp_path, program(body))


@pytest.mark.parametrize("body, line", [
    # a counter worked out from the values set before (review 52, F7): the loop turns again,
    # and rs274 reads the definition's line a second time
    ("#<k>=0\no1 while [#<k> LT 2]\n#<k>=[#<k>+1]\no<s> sub\nG0 X1\no<s> endsub\no1 endwhile",
     6),
    ("#<k>=0\no1 do\n#<k>=[#<k>+1]\no<s> sub\nG0 X1\no<s> endsub\no1 while [#<k> LT 2]", 6),
])
def test_review52_a_sub_defined_in_a_counted_loop_turning_twice_is_refused(
        tmp_path, body, line):
    text = program(body)
    message = refused_once(text, line)
    assert message.startswith("sub: o|s| found in illegal location (rs274ngc)")
    assert f"line:{line} sub: o|s| found in illegal location" in rs274_output(tmp_path, text)


def test_review52_a_sub_defined_in_a_counted_loop_of_one_turn_is_clean(tmp_path):
    text = program("#<k>=0\no1 while [#<k> LT 1]\n#<k>=[#<k>+1]\no<s> sub\nG0 X1\n"
                   "o<s> endsub\no1 endwhile\no<s> call")
    assert errors(text) == [], text
    assert "PROGRAM_END" in rs274_output(tmp_path, text)


# Where a canned cycle or a rigid tap leaves the tool (review 58c, F4): the cycle's clearance
# level (G99: R; G98: the higher of R and the start), and a rigid tap its start, not the point
# its words give. HEAD starts at Z0 with F100. (the blocks after HEAD, the probe's line)
CYCLE_END_RUNS = [
    # G98 from above R: back to Z2, not Z0 (the level depends on the retract mode: unsure)
    "G0 Z2\nG81 X0 Z0 R1\nG80\nG38.2 Z0",
    "G0 Z2\nG98 G81 X0 Z0 R1\nG80\nG38.2 Z0",
    # from Z0, below R: both modes end at R1
    "G81 X1 Z-1 R1\nG38.2 Z-1",
    "G0 Z2\nG99 G81 X0 Z0 R1\nG80\nG38.2 Z0",
    # a peck drill and a tap end at R as G81 does
    "S100 M3\nG73 X0 Z-1 R1 Q0.3\nG80\nG38.2 Z-1",
    "S100 M3\nG84 X0 Z-1 R1\nG80\nG38.2 Z-1",
    # G91: R from the start, unsure (rs274's sums of doubles)
    "G0 Z2\nG91 G81 X0 Z-1 R-0.5\nG90 G80\nG38.2 Z0",
    # a rigid tap goes back to where it started
    "S100 M3\nG0 Z1\nG33.1 Z0 K0.1\nG38.2 Z0",
    "S100 M3\nG0 X0 Z1\nG33.1 X1 Z0 K0.1\nG38.2 X1 Z0",
    # G73, then G74 with an R of its own (review 59b, F6)
    "G73 X1 Z-1 R2 Q0.5\nS100 M4\nG74 X2 Z-1 R1\nG80\nG38.2 Z2",
    "G73 X1 Z-1 R1 Q0.5\nG80\nG38.2 Z0.5",
]

CYCLE_END_REFUSED = [
    ("G81 X1 Z-1 R1\nG38.2 Z1", 4, 1),
    ("G0 Z0.5\nG98 G81 X0 Z0 R1\nG80\nG38.2 Z1", 6, 1),
    ("G18\nG81 X1 Y-1 R1\nG80\nG17\nG38.2 Y1", 7, 1),
    ("S100 M3\nG0 Z1\nG33.1 Z0 K0.1\nG38.2 Z1", 6, 1),
    ("S100 M3\nG0 X0 Z1\nG33.1 X1 Z0 K0.1\nG38.2 X0 Z1", 6, 1),
    # G73 and G74 end at R as G81-G89 do, a repeat at the R kept (review 59b, F6)
    ("G73 X1 Z-1 R1 Q0.5\nG80\nG38.2 Z1", 5, 1),
    ("S100 M4\nG74 X1 Z-1 R1\nG80\nG38.2 Z1", 6, 1),
    ("G73 X1 Z-1 R1 Q0.5\nX2\nG80\nG38.2 Z1", 6, 1),
    ("G98 G73 X1 Z-1 R1 Q0.3\nG81 X2 Z-1 R1\nG80\nG38.2 Z1", 6, 1),
]


def assert_refused_as_rs274(tmp_path, text, rule, line, column, message):
    """The one error is `rule` at line and column, and rs274 stops with `message`; the
    error is returned."""
    found = [f for f in check_text(text, load_profile("linuxcnc")) if f.severity == "error"]
    assert [(f.rule, f.line, f.column) for f in found] == [(rule, line, column)], found
    assert message in rs274_output(tmp_path, text)
    return found[0]


def assert_too_close_refused(tmp_path, text, line, column):
    """The one error is rs274's "too close" probe start, where rs274 stops too."""
    too_close = "Start point too close to probe point"
    assert too_close in assert_refused_as_rs274(tmp_path, text, "TG412", line, column,
                                                too_close).message


@pytest.mark.parametrize("body", CYCLE_END_RUNS)
def test_a_cycle_s_end_is_its_clearance_level_and_a_rigid_tap_s_its_start(tmp_path, body):
    clean_on_both(tmp_path, program(body))


@pytest.mark.parametrize("body, line, column", CYCLE_END_REFUSED)
def test_a_probe_from_a_cycle_s_clearance_level_to_it_is_refused(tmp_path, body, line, column):
    assert_too_close_refused(tmp_path, program(body), line, column)


# A block whose M72 rs274 2.9 drops (the restore's block runs in its place): its own motion
# code never takes effect (review 58c, F7). HEAD has F100; these blocks start from G94 F0
# where they need it. (the blocks after HEAD)
M72_DROPPED_MOTION_RUNS = [
    # the mode, not the rate, differs: the drop is sure, G0 stays in force
    "G0 X0\nG94\nM70\nG93\nM72 G1 X1\nX2",
    "G0 X0\nG94\nM70\nG93\nM72 G1 X1\nG94\nX2",
    # the plane alone differs: the drop may happen, the mode after is not known
    "G0 X0\nG94\nM70\nG18\nM72 G1 X1\nX2",
    # nor do its plane and compensation codes (review 58c, F6): G17 and G40 stay
    "G94 F10\nM70\nG93\nM72 G18\nG2 X1 Y0 I0.5 J0 F10",
    "G94\nM70\nG18\nM72 G19\nG2 X1 Y0 I0.5 J0 F10",
    "G94 F10\nM70\nG93\nM72 G41.1 D0.1\nG81 X1 Z-1 R1 F10",
]


@pytest.mark.parametrize("body", M72_DROPPED_MOTION_RUNS)
def test_a_dropped_m72_block_s_motion_code_does_not_take_effect(tmp_path, body):
    clean_on_both(tmp_path, program(body))


def test_the_motion_before_a_surely_dropped_m72_block_is_judged_after_it(tmp_path):
    # G1 stays in force through `M72 G0 X1`: `X2` feeds at F0
    text = program("G94\nG1 X0.5 F10\nF0\nM70\nG93\nM72 G0 X1\nX2")
    assert_refused_as_rs274(tmp_path, text, "TG401", 9, 1, "Cannot do g1 with zero feed rate")


@pytest.mark.parametrize("body, line, column", [
    # a G20/G21 between the save and the restore converts no rate in rs274 (review 61b F1):
    # a zero saved and in force stays zero (review 58c, F2), the restore leaves F0
    ("G94 F0\nM70\nG20\nM72\nG1 X1", 7, 4),
    ("G94 F0\nM70\nG20\nM72 G1 X1\nG1 X2", 7, 4),
])
def test_a_zero_rate_saved_and_in_force_across_a_units_change_is_zero_after_m72(
        tmp_path, body, line, column):
    assert_refused_as_rs274(tmp_path, program(body), "TG401", line, column,
                            "Cannot do g1 with zero feed rate")


def test_a_rate_saved_before_a_units_change_runs_after_m72(tmp_path):
    # (F100 saved and in force at the M72: the restore leaves F100, which G1 feeds at)
    clean_on_both(tmp_path, program("G94 F100\nM70\nG20\nM72\nG1 X1"))


# G98's clearance is where the axis stood before the series of back-to-back cycles, a number
# rs274 keeps: a G92 or G92.1 inside the series does not move it (review 59b, F1). (the blocks
# after HEAD)
CYCLE_SERIES_RUNS = [
    # the retract goes to Z5, the series' start: the probe from Z5 to Z1 runs
    "G0 Z5\nG98 G81 X1 Z-1 R1\nG92 Z0\nG81 X2 Z-1 R1\nG80\nG38.2 Z1",
    # to Z0 in the coordinates before the G92: Z5 after it, the probe to Z-4 runs
    "G0 Z0\nG98 G81 X1 Z-1 R1\nG92 Z-5\nG81 X2 Z-8 R-4\nG80\nG38.2 Z-4",
    # G81 then G82 is one series, M8/M9 between do not end it
    "G0 Z5\nG98 G81 X1 Z-1 R1\nM8\nG92 Z0\nM9\nG82 X2 Z-1 R1 P0.1\nG80\nG0 X3\nG38.2 Z1",
    "G0 Z0\nG98 G81 X1 Z-1 R1\nG92.1\nG92 Z-5\nG81 X2 Z-8 R-4\nG80\nG38.2 Z-4",
]

CYCLE_SERIES_REFUSED = [
    # the series starts at Z0, below R: both cycles end at R1
    ("G98 G81 X1 Z-1 R1\nG82 X2 Z-1 R1 P0.1\nG80\nG38.2 Z1", 6, 1),
    ("G98 G81 X1 Z-1 R1\nM8\nG81 X2 Z-2 R1\nG80\nG38.2 Z1", 7, 1),
]


@pytest.mark.parametrize("body", CYCLE_SERIES_RUNS)
def test_g98_s_level_inside_a_series_is_the_series_start_kept_through_a_g92(tmp_path, body):
    clean_on_both(tmp_path, program(body))


@pytest.mark.parametrize("body, line, column", CYCLE_SERIES_REFUSED)
def test_a_probe_to_a_series_clearance_level_is_refused(tmp_path, body, line, column):
    assert_too_close_refused(tmp_path, program(body), line, column)


# A surely dropped M72 block (the feed mode differs: the restore's block runs in its place):
# its plane and compensation codes never take effect, the restore's plane and compensation
# stay known, and a canned cycle in force before it stays in force (review 59b, F3, F2).
# (the blocks after HEAD; the rule, line, column; rs274's message)
M72_SURE_DROP_REFUSED = [
    ("M70\nG93\nM72 G17\nG2 X1 Y0 I0.5 K0 F10", "TG404", 6, 15,
     "K word given for arc in xy plane"),
    ("M70\nG93\nM72 G18\nG94 G2 X1 Y0 I0.5 K0 F10", "TG404", 6, 19,
     "K word given for arc in xy plane"),
    ("G41.1 D0.1\nG1 X1\nM70\nG93\nM72 G40\nG94 G81 X1 Z-1 R1 F10", "TG412", 8, 1,
     "Cannot use canned cycles with cutter compensation on"),
    ("G81 X1 Z-1 R1\nM70\nG93\nM72 G1 X2\nX3", "TG412", 7, 1,
     "Cannot feed with zero feed rate"),
]


@pytest.mark.parametrize("body, rule, line, column, message", M72_SURE_DROP_REFUSED)
def test_a_surely_dropped_m72_block_leaves_the_plane_compensation_and_cycle_before_it(
        tmp_path, body, rule, line, column, message):
    assert_refused_as_rs274(tmp_path, program(body), rule, line, column, message)


# After a call of a definition read before it whose body writes no motion code but G0-G3
# (nor calls one that may), the mode before being G0-G3, the motion mode is one of G0-G3: a
# move without a motion code ends at its words' point (review 59b, F5); so after a possible
# M72 drop whose two modes are G0-G3 (F4). HEAD starts at Z0 with F100. (the blocks after
# HEAD, the probe's line and column)
CALL_PLAIN_REFUSED = [
    ("o100 sub\no100 endsub\no100 call\nZ0.5\nG38.2 Z0.5", 7, 1),
    # a body whose G0 surely runs, called under the caller's cycle: G0 after it (lcnc62)
    ("o100 sub\nG0 X0\no100 endsub\nG81 X1 Z-1 R2\no100 call\nZ0.5\nG38.2 Z0.5", 9, 1),
    ("o100 sub\nG1 X1 F10\no100 endsub\no100 call\nZ0.5\nG38.2 Z0.5", 8, 1),
    # a body that calls one that writes no other motion code
    ("o100 sub\nG0 X0\no100 endsub\no200 sub\no100 call\no200 endsub\no200 call\nZ0.5\n"
     "G38.2 Z0.5", 11, 1),
    # a cycle of the main program ended by G80 before the call
    ("o100 sub\nG1 X1 Y0\no100 endsub\nG81 X2 Z-1 R2\nG80\nG0 Z0\no100 call\nZ0.5\n"
     "G38.2 Z0.5", 11, 1),
    # a possible M72 drop (the plane alone differs) between G0 and G1, G0 and G2
    ("M70\nG18\nM72 G1 X1\nG17\nZ0.5\nG38.2 Z0.5", 8, 1),
    ("M70\nG18\nM72 G2 X1 Z0 R2\nG17\nZ0.5\nG38.2 Z0.5", 8, 1),
    ("G1 X0\nM70\nG18\nM72 G0 X1\nG17\nZ0.5\nG38.2 Z0.5", 9, 1),
]

CALL_PLAIN_RUNS = [
    # a body whose only call is an M98: O200 leaves G81 in force (review 61b F2)
    "o100 sub\nM98 P200\no100 endsub\no100 call\nZ0.5\nG80\nG38.2 Z0.5\nM2\nO200\n"
    "G81 X1 Z-1 R2\nM99",
    "o100 sub\nM98 P200 L2\no100 endsub\no100 call\nZ0.5\nG80\nG38.2 Z0.5\nM2\nO200\n"
    "G81 X1 Z-1 R2\nM99",
    "o101 sub\nM98 P200\no101 endsub\no100 sub\no101 call\no100 endsub\no100 call\nZ0.5\n"
    "G80\nG38.2 Z0.5\nM2\nO200\nG81 X1 Z-1 R2\nM99",
    # the body leaves G81 in force: Z0.5 is a cycle, which ends at R2
    "o100 sub\nG81 X1 Z-1 R2\no100 endsub\no100 call\nZ0.5\nG80\nG38.2 Z0.5",
    # so through a body that calls it, or in a condition of the body
    "o100 sub\nG81 X1 Z-1 R2\no100 endsub\no200 sub\no100 call\no200 endsub\no200 call\n"
    "Z0.5\nG80\nG38.2 Z0.5",
    "o100 sub\no1 if [#1 GT 0]\nG81 X1 Z-1 R2\no1 endif\no100 endsub\no100 call [1]\nZ0.5\n"
    "G80\nG38.2 Z0.5",
    # a body calling one defined after it
    "o100 sub\nG0 X0\no101 call\no100 endsub\no101 sub\nG81 X1 Z-1 R2\no101 endsub\n"
    "o100 call\nZ0.5\nG80\nG38.2 Z0.5",
    # G81 in force before the call of a body without a motion code: Z0.5 is a cycle
    "G81 X1 Z-1 R2\no100 sub\nM8\no100 endsub\no100 call\nZ0.5\nG80\nG38.2 Z0.5",
    # a possible M72 drop between a cycle and G1 (rs274 drops it here: G81 stays)
    "G81 X1 Z-1 R2\nM70\nG18\nM72 G1 X1\nG17\nZ0.5\nG80\nG38.2 Z0.5",
]


@pytest.mark.parametrize("body, line, column", CALL_PLAIN_REFUSED)
def test_a_move_after_a_call_that_leaves_g0_g3_ends_at_its_words(tmp_path, body, line, column):
    assert_too_close_refused(tmp_path, program(body), line, column)


@pytest.mark.parametrize("body", CALL_PLAIN_RUNS)
def test_a_move_after_a_call_that_may_leave_a_cycle_is_not_known_exactly(tmp_path, body):
    clean_on_both(tmp_path, program(body))


# rs274 reads a definition without running it: after its endsub the motion mode (and cycle)
# from before its sub is in force; after a call of it, the G0-G3 its body surely leaves (the
# last motion code, not in a condition, loop or after a return), else not known (review 61b,
# F4). HEAD sets G0. (the blocks after HEAD; the refused line, or None where rs274 runs)
BODY_MOTION = [
    ("o100 sub\nG2 X1 Y0 I0.5 J0\no100 endsub\nZ1", None),
    ("o100 sub\nG3 X1 Y0 R1\no100 endsub\nX2 Y0", None),
    ("o100 sub\nG2 X1 Y0 I0.5 J0\no100 endsub\nG17 X2", None),
    ("o100 sub\nG2 X1 Y0 I0.5 J0\no100 endsub\no100 call\nZ0.5", 7),
    ("o100 sub\no1 if [#1 GT 0]\nG1 X2\no1 endif\nG2 X1 Y0 I0.5 J0\no100 endsub\n"
     "o100 call\nZ0.5", 10),
    # the body's G1 after the caller's G2: the call leaves G1
    ("o100 sub\nG1 X2 Y0\no100 endsub\nG2 X1 Y0 I0.5 J0\no100 call\nZ0.5", None),
    # a second call after a G1 of the caller
    ("o100 sub\nG3 X1 Y0 R1\no100 endsub\nG1 X0\no100 call\nG1 X3\no100 call\nX2", 10),
    # the G2 in a condition not taken: not known, no error
    ("o100 sub\no1 if [#1 GT 0]\nG2 X1 Y0 I0.5 J0\no1 endif\no100 endsub\no100 call\n"
     "Z0.5", None),
    # the G1 in a condition taken, after the caller's G2: not known, not an arc
    ("o100 sub\no1 if [#1 GT 0]\nG1 X2 Y0\no1 endif\no100 endsub\nG2 X1 Y0 I0.5 J0\n"
     "o100 call [1]\nX3", None),
    # a cycle in the body: the caller's G1 after its endsub
    ("G1 X0\no100 sub\nG81 X1 Y1 Z-1 R1\no100 endsub\nX2 Y2", None),
    # a `do` loop runs at least once: its turn's last G2 is the body's (lcnc61's miss)
    ("#2=0\no100 sub\no102 do\nG2 X1 Y0 I0.5 J0\n#2=[#2+1]\no102 while [#2 LT 1]\n"
     "o100 endsub\no100 call\nZ0.5", 11),
    # a `do` in a `do`, and a call of a G2 body in a `do`
    ("#2=0\no100 sub\no102 do\no104 do\nG2 X1 Y0 I0.5 J0\no104 while [0]\n#2=[#2+1]\n"
     "o102 while [#2 LT 2]\no100 endsub\no100 call\nZ0.5", 13),
    ("o200 sub\nG2 X1 Y0 I0.5 J0\no200 endsub\no100 sub\no102 do\no200 call\n"
     "o102 while [0]\no100 endsub\no100 call\nZ0.5", 12),
    # a body calling one that ends in G2 (lcnc61's miss), and an M73 (no motion restored)
    ("o200 sub\nG2 X1 Y0 I0.5 J0\no200 endsub\no100 sub\no200 call\no100 endsub\n"
     "o100 call\nZ0.5", 10),
    ("o200 sub\nM73\nG2 X1 Y0 I0.5 J0\no200 endsub\no100 sub\no200 call\no100 endsub\n"
     "o100 call\nZ0.5", 11),
    # a `while` may not turn (here it does not): not known
    ("#2=0\no100 sub\no102 while [#2 GT 0]\nG2 X1 Y0 I0.5 J0\n#2=[#2+1]\no102 endwhile\n"
     "o100 endsub\no100 call\nZ0.5", None),
    # a `break` or `continue` before the loop's G2 leaves a turn in the mode before it
    ("o100 sub\nG1 X0\no102 do\no103 if [#1 GT 0]\no102 break\no103 endif\n"
     "G2 X1 Y0 I0.5 J0\no102 while [#1 LT 0]\no100 endsub\no100 call [1]\nX3", None),
    ("o100 sub\nG1 X0\no102 do\no103 if [#1 GT 0]\no102 continue\no103 endif\n"
     "G2 X1 Y0 I0.5 J0\no102 while [0]\no100 endsub\no100 call [1]\nX3", None),
    # a G1 in a condition after the loop's G2, or after the call of a G2 body
    ("o100 sub\no102 do\nG2 X1 Y0 I0.5 J0\no103 if [#1 GT 0]\nG1 X0\no103 endif\n"
     "o102 while [0]\no100 endsub\no100 call [1]\nX3", None),
    ("o200 sub\nG2 X1 Y0 I0.5 J0\no200 endsub\no100 sub\no200 call\no1 if [#1 GT 0]\n"
     "G1 X0\no1 endif\no100 endsub\no100 call [1]\nX3", None),
    # a body that ends the program after its G2: no line after its call runs
    ("o100 sub\nG2 X1 Y0 I0.5 J0\nM2\no100 endsub\no1 if [#5220 GT 0]\no100 call\nZ0.5\n"
     "o1 endif", None),
    # a definition written after M2: rs274 runs a file 100.ngc on its subroutine path
    # first where there is one, so the mode after the call is held (LATER_CALLS below)
    ("o100 call\nG1 X2\nM2\no100 sub\nG2 X1 Y0 I0.5 J0\no100 endsub", None),
    ("o100 call\nX2 R1\nM2\no100 sub\nG2 X1 Y0 I0.5 J0\no100 endsub", None),
    ("o100 call\nZ0.5\nM2\no100 sub\nG2 X1 Y0 I0.5 J0\nM2\no100 endsub", None),
    ("o100 call\nZ0.5\nM2\no100 sub\no1 if [#1 GT 0]\nG1 X0\no1 endif\no100 endsub", None),
    ("o100 call\nM70\nM72 G1 X0\nX2\nM2\no100 sub\nG2 X1 Y0 I0.5 J0\no100 endsub", None),
    # a possible M72 drop after the call of a G2 body
    ("o200 sub\nG2 X1 Y0 I0.5 J0\no200 endsub\no100 sub\no200 call\nM70\nM72 G1 X0\n"
     "o100 endsub\no100 call\nX3", None),
]


@pytest.mark.parametrize("body, line", BODY_MOTION)
def test_a_definition_s_motion_mode_is_its_calls_not_the_lines_after_it(tmp_path, body, line):
    judged_as_rs274(tmp_path, program(body), line, "TG404",
                    "R i j k words all missing for arc")


# A call of a label with no definition read yet: rs274 first looks for a file named after the
# label on its subroutine path (the current directory standalone) and runs it, else the
# definition written after M2 (interp_o_word.cc). The checker cannot see that path, so the
# mode the call leaves, and the sure modes and kept positions of later calls, are held (review
# 62b F2; lcnc62 judged the move at the later definition's endsub). (the blocks after HEAD, and
# the file 100.ngc beside it under which rs274 runs to its end)
LATER_CALLS = [
    ("o100 call\nZ0.5\nM2\no100 sub\nG2 X1 Y0 I0.5 J0\no100 endsub",
     "o100 sub\nG1 X0\no100 endsub\nM2\n"),
    ("o100 call\nG1 X0\no100 call\nX3\nM2\no100 sub\nG3 X1 Y0 R1\no100 endsub",
     "o100 sub\nG1 X0\no100 endsub\nM2\n"),
]


def rs274_in(directory, text: str) -> str:
    """rs274 -g of ``text`` run in ``directory`` (its subroutine path)."""
    import shutil
    import subprocess

    if shutil.which("rs274") is None:
        pytest.skip("LinuxCNC's rs274 is not installed")
    (directory / "program.ngc").write_text(text)
    run = subprocess.run(["rs274", "-g", "program.ngc"], capture_output=True, text=True,
                         timeout=30, input="", cwd=directory,
                         env={**os.environ, "HOME": str(directory)})
    return run.stdout + run.stderr


@pytest.mark.parametrize("body, file", LATER_CALLS)
def test_a_call_of_a_definition_written_after_it_is_held(tmp_path, body, file):
    text = program(body)
    assert errors(text) == [], text
    # (no 100.ngc: the later definition's G2 is in force at the move)
    assert "R i j k words all missing for arc" in rs274_in(tmp_path, text)
    (tmp_path / "100.ngc").write_text(file)
    assert "PROGRAM_END" in rs274_in(tmp_path, text)


# After a call of a definition not read yet whose body ends the program (its M2), no line after
# it runs: a later call's sure mode (a G1 body) or kept position (a still body) is not used
# there (review 62b F3; lcnc62 said "Start point too close to probe point" at the G38.2).
LATER_ENDS = [
    "o100 sub\nG1 X1 F10\no100 endsub\no300 call\no100 call\nZ0.5\nG38.2 Z0.5\nM2\n"
    "o300 sub\nM8\nM2\no300 endsub",
    "o100 sub\nM8\no100 endsub\no300 call\nG0 Z0\no100 call\nG38.2 Z0\nM2\n"
    "o300 sub\nG3 I1 J0\nM2\no300 endsub",
    # a body's do loop ending in G2 (review 62b LE5)
    "o300 call\n#2=0\no300 call\no100 sub\no102 do\nG2 X1 Y0 I0.5 J0\n#2=[#2+1]\n"
    "o102 while [#2 LT 1]\no100 endsub\nG1 X0\no100 call\nZ0.5\nM2\n"
    "o300 sub\nG3 I1 J0\nM2\no300 endsub",
    # the caller's G2 before the call of a G1 body, after the held call: not known, no arc
    "o300 call\no100 sub\nG1 X2\no100 endsub\nG2 X1 Y0 I0.5 J0\no100 call\nZ0.5\nM2\n"
    "o300 sub\nM8\no300 endsub",
    # the lines after a call of a later definition whose M2 ends the program are not judged
    # (review 62b LE1: TG404 at the G2 before lcnc63; X1 Y1 X2 was TG131)
    "o300 call\nG2 Z0.5\nM2\no300 sub\nM8\nM2\no300 endsub",
    "o300 call\nG21 G17 G90 F100\nG2 Z0.5\nX1 Y1 X2\nM2\no300 sub\nM8\nM2\no300 endsub",
    # a line rs274 could not read after such a call, of a body written later or read before:
    # never read (review 63-lcnc63 N1: the body read before kept its TG100)
    "o300 call\nG1 X\nG0 Z1\nM2\no300 sub\nM8\nM2\no300 endsub",
    "o300 sub\nM8\nM2\no300 endsub\no300 call\nG1 X\nG0 Z1\nM2",
    "o300 sub\nM8\nM2\no300 endsub\no300 call\nG1 X1 (not closed\nM2",
]


# ... but one after a call of a body that may return (its M2 in a condition) is read: rs274
# reads it where #1 is 0 and refuses it
def test_a_line_not_read_after_a_call_that_may_return_is_said(tmp_path):
    text = program("o300 sub\no1 if [#1 GT 0]\nM2\no1 endif\no300 endsub\no300 call\n"
                   "G1 X\nM2")
    assert [(r, n) for r, n, _ in errors(text)] == [("TG100", 9)], text
    assert "PROGRAM_END" not in rs274_output(tmp_path, text)


def test_lines_after_a_call_of_a_later_definition_that_returns_are_judged(tmp_path):
    # the same o300 without its M2 returns: rs274 refuses the G2 (review 62b LE1's other half)
    text = program("o300 call\nG2 Z0.5\nM2\no300 sub\nM8\no300 endsub")
    assert [(r, n) for r, n, _ in errors(text)] == [("TG404", 4)], text
    assert "R i j k words all missing for arc" in rs274_output(tmp_path, text)


@pytest.mark.parametrize("body", LATER_ENDS)
def test_lines_after_a_call_that_may_end_the_program_take_no_new_sure_state(tmp_path, body):
    text = "G21 G17 G90 F100\nG0 X0 Y0 Z0\n" + body + "\n"
    assert errors(text) == [], text
    assert "PROGRAM_END" in rs274_output(tmp_path, text)


# The caller's G2 before a call of a definition not read yet: the moves without a motion code
# after the call run in the mode the definition leaves, judged at its endsub (review 62b F4:
# lcnc62 and main judged them by the caller's G2, TG404 where rs274 runs the body's G0 or
# cycle). A body that leaves the mode as it found it (M8) leaves the caller's G2: rs274's "R i j
# k words all missing for arc" at the first move (review 62b LG4). (the blocks after HEAD; the
# refused line, or None where rs274 -g runs)
CALLER_ARC_LATER = [
    ("G2 X1 Y0 I0.5 J0\no300 call\nX2\nM2\no300 sub\nG0 X0\no300 endsub", None),
    ("G2 X1 Y0 I0.5 J0\no300 call\nX2\nX3\nM2\no300 sub\nG0 X0\no300 endsub", None),
    ("G2 X1 Y0 I0.5 J0\no300 call\nX2\nM2\no300 sub\nG81 X1 Z-1 R2\no300 endsub", None),
    ("G3 X1 Y0 I0.5 J0\no<up> call\nZ1\nM2\no<up> sub\nG1 Z0.5\no<up> endsub", None),
    ("G2 X1 Y0 I0.5 J0\no300 call\nX2\nM2\no300 sub\nM8\no300 endsub", 5),
    # a body of G4 (no motion code): the caller's G2 (review 63-lcnc63 F1)
    ("G2 X1 Y0 I0.5 J0\no300 call\nX2\nM2\no300 sub\nG4 P0.1\no300 endsub", 5),
    # the main program's own G2 after the call (review 63-lcnc63 F2)
    ("G2 X1 Y0 I0.5 J0\no300 call\nG2 X0 Y0 I-0.5 J0\nX2\nM2\no300 sub\nG0 X0\no300 endsub", 6),
    # the move's own G2 is judged where it stands
    ("G2 X1 Y0 I0.5 J0\no300 call\nG1 X2\nG2 X3\nM2\no300 sub\nG0 X0\no300 endsub", 6),
    # a body that may keep the caller's G2 (a call in it, a G0 in a condition that does not
    # run): judged as before (review 63-lcnc63 K8, K12)
    ("G2 X1 Y0 I0.5 J0\no300 call\nX2\nM2\no300 sub\no301 call\no300 endsub\no301 sub\nM8\n"
     "o301 endsub", 5),
    ("G2 X1 Y0 I0.5 J0\no300 call\nX2\nM2\no300 sub\no1 if [#1 GT 0]\nG0 X0\no1 endif\n"
     "o300 endsub", 5),
    # two calls in a row (review 63-lcnc63 N2, N11): the second body keeps the mode the first
    # left, G0 (rs274 runs; main's TG404 at X2), or the caller's G2 through both, or its own G3
    ("G2 X1 Y0 I0.5 J0\no300 call\no301 call\nX2\nM2\no300 sub\nG0 X0\no300 endsub\n"
     "o301 sub\nM8\no301 endsub", None),
    ("G2 X1 Y0 I0.5 J0\no300 call\no301 call\nX2\nM2\no300 sub\nM8\no300 endsub\n"
     "o301 sub\nG0 X0\no301 endsub", None),
    ("G2 X1 Y0 I0.5 J0\no300 call\no301 call\nX2\nM2\no300 sub\nM8\no300 endsub\n"
     "o301 sub\nM9\no301 endsub", 6),
    ("G2 X1 Y0 I0.5 J0\no300 call\no301 call\nX2\nM2\no300 sub\nG0 X0\no300 endsub\n"
     "o301 sub\nG3 X0 Y0 I-0.5 J0\no301 endsub", 6),
    # the second a definition read before the main program's lines (main's TG404 at X2)
    ("o301 sub\nM8\no301 endsub\nG2 X1 Y0 I0.5 J0\no300 call\no301 call\nX2\nM2\n"
     "o300 sub\nG0 X0\no300 endsub", None),
    # a body whose last line calls a body that surely leaves G0 (review 63-lcnc63 K8: main's
    # TG404 at X2), through two calls, or with a plain line after the call; a G3 body refused
    ("G2 X1 Y0 I0.5 J0\no300 call\nX2\nM2\no300 sub\no301 call\no300 endsub\no301 sub\n"
     "G0 X0\no301 endsub", None),
    ("G2 X1 Y0 I0.5 J0\no300 call\nX2\nM2\no300 sub\no301 call\no300 endsub\no301 sub\n"
     "o302 call\no301 endsub\no302 sub\nG0 X0\no302 endsub", None),
    ("G2 X1 Y0 I0.5 J0\no300 call\nX2\nM2\no300 sub\no301 call\nM8\no300 endsub\n"
     "o301 sub\nG0 X0\no301 endsub", None),
    ("G2 X1 Y0 I0.5 J0\no300 call\nX2\nM2\no300 sub\no301 call\no300 endsub\no301 sub\n"
     "G3 X0 Y0 I-0.5 J0\no301 endsub", 5),
    # review 75 F1: a G code of a value not known after the body's last call (a G2 here)
    ("G2 X1 Y0 I0.5 J0\no300 call [2]\nX2\nM2\no300 sub\no301 call\nG#1 X1 Y0 I0.5 J0\n"
     "o300 endsub\no301 sub\nG0 X0\no301 endsub", 5),
    # review 75 F1b: a body's own bare move, run in the mode the calls before it left (a
    # bare X0 under the caller's G2): refused in the body by rs274, judged at the move after
    # the call here
    ("G2 X1 Y0 I0.5 J0\no300 call\nX2\nM2\no300 sub\nX0\nG0 X1\no300 endsub", 5),
    # review 75 F2: a body that may return before its last call (#1 is 0 here)
    ("G2 X1 Y0 I0.5 J0\no300 call\nX2\nM2\no300 sub\no1 if [#1 EQ 0]\no300 return\n"
     "o1 endif\no301 call\no300 endsub\no301 sub\nG0 X0\no301 endsub", 5),
    # review 75 F3: a bare arc line under the caller's arc runs, then the body's G0; a bare
    # line in a condition that does not run
    ("G2 X1 Y0 I0.5 J0\no300 call\nX2\nM2\no300 sub\nX0 Y0 I-0.5 J0\nG0 X0\no300 endsub",
     None),
    ("G2 X1 Y0 I0.5 J0\no300 call\nX2\nM2\no300 sub\no1 if [#1 GT 0]\nX0\no1 endif\n"
     "G0 X0\no300 endsub", None),
    # the call in a condition of the body: may not run, judged as before
    ("G2 X1 Y0 I0.5 J0\no300 call\nX2\nM2\no300 sub\no1 if [#1 GT 0]\no301 call\n"
     "o1 endif\no300 endsub\no301 sub\nG0 X0\no301 endsub", 5),
]


@pytest.mark.parametrize("body, line", CALLER_ARC_LATER)
def test_the_caller_s_arc_is_not_the_mode_after_a_call_of_a_later_definition(
        tmp_path, body, line):
    judged_as_rs274(tmp_path, program(body), line, "TG404",
                    "R i j k words all missing for arc")


def test_a_later_body_s_own_arc_words_under_a_line_keep_the_move_after_the_calls_judged(
        tmp_path):
    # review 75 F1b: o301's bare `X1 Y0 I0.5 J0` runs under o300's G0, refused in the body by
    # rs274; the move after the calls is still judged (main's TG404 there)
    text = program("G2 X1 Y0 I0.5 J0\no300 call\no301 call\nX2\nM2\no300 sub\nG0 X0\n"
                   "o300 endsub\no301 sub\nX1 Y0 I0.5 J0\no301 endsub")
    judged_as_rs274(tmp_path, text, 6, "TG404", "I word with no G2, G3, G5, G5.1, G10")


# An M72 across a G20/G21 from its M70 (the same feed mode): rs274 -g converts no feed rate at
# a G20/G21 (no SET_FEED_RATE there), so the restore is as without one: the saved rate where
# the rate in force after the block's own F equals it, else the saved rate as F%.1f
# (interp_convert.cc restore_settings, gen_settings). HEAD sets F100. (the blocks after HEAD;
# the refused line, or None; review 61b F1: the rows with F0.04 kept in force ran in rs274 and
# were refused by lcnc60)
M72_UNITS_RATE = [
    ("F0\nM70\nG20\nM72 F10\nG1 X1", 7),
    ("F0.04\nM70\nG20\nM72 F10\nG1 X1", 7),
    ("F0\nM70\nG20\nG21\nF10\nM72\nG1 X1", 9),
    ("M70\nG20\nM72 F0\nG1 X1", None),
    ("M70\nG20\nF0\nM72\nG1 X1", None),
    ("F0.04\nM70\nG21\nM72\nG1 X1", None),
    ("S1000 M3\nG95 F0.04\nM70\nG21 G90 G17\nG0 X1\nM72\nG1 X2", None),
    ("F0.04\nM70\nG20\nM72\nG1 X1", None),
    ("F0.04\nM70\nG20\nM72 F0.04\nG1 X1", None),
    ("F0.04\nM70\nG20\nF0.001\nM72\nG1 X1", 8),
]


@pytest.mark.parametrize("body, line", M72_UNITS_RATE)
def test_an_m72_across_a_units_change_leaves_the_saved_rate_not_its_block_s_f(
        tmp_path, body, line):
    text = program(body)
    if line is None:
        clean_on_both(tmp_path, text)
        return
    assert_refused_as_rs274(tmp_path, text, "TG401", line, 4, "Cannot do g1 with zero feed rate")


# A G73/G81 repeat after a surely dropped M72 block (the speed differs: the restore's block
# runs in its place) retracts to the R from before it: the dropped block's R never runs
# (review 61b F5). HEAD starts at Z0. (the blocks after HEAD)
M72_DROPPED_R = "S100 M3\n{cycle} X1 Z-1 R1{q}\nM70\nS200\nM72 {again} X2 Z-1 R3{q}\nX3\nG80\n"


@pytest.mark.parametrize("cycle, again, q", [
    ("G73", "G73", " Q0.5"), ("G73", "", " Q0.5"), ("G81", "G81", ""),
])
def test_a_cycle_repeat_after_a_surely_dropped_m72_block_keeps_the_r_before_it(
        tmp_path, cycle, again, q):
    body = M72_DROPPED_R.format(cycle=cycle, again=again, q=q)
    # the repeat ends at Z1: a probe to Z3 runs, one to Z1 is "too close"
    clean_on_both(tmp_path, program(body + "G38.2 Z3"))
    if cycle == "G73":
        assert_too_close_refused(tmp_path, program(body + "G38.2 Z1"), 10, 1)


# An M72 not followed (its M70 in a condition or loop of the main program) whose every
# possible save holds the same rate, in the feed mode in force: rs274's rate after it is the
# saved rate where the rate in force is it, else that rate as F%.1f (review 61b F3: the
# block's own F0 is not the rate after it, and neither is a zero lost). HEAD sets F100.
@pytest.mark.parametrize("body, line", [
    ("F0\no1 repeat [2]\nM70\no1 endrepeat\nM72 F0\nG1 X1", 8),
    ("F0\no1 if [1]\nM70\no1 endif\nM72 F0\nG1 X1", 8),
    ("F0\no1 if [1]\nM70\no1 endif\nM72\nG1 X1", 8),
    # the saved F100, whatever the block's F
    ("o1 if [1]\nM70\no1 endif\nM72 F0\nG1 X1", None),
    ("o1 repeat [2]\nM70\no1 endrepeat\nF0\nM72\nG1 X1", None),
    # a loop's later turn saves the F set after its M70: not known
    ("F0\no1 repeat [2]\nM70\nF10\no1 endrepeat\nM72 F0\nG1 X1", None),
    # an `if` of a condition not known runs nothing: its M70 saves the rate before it
    # (review 61b v2; where the M70 does not run, rs274 refuses the M72 itself)
    ("F0\no1 if [#5220 GT 0]\nM70\no1 endif\nM72 F0\nG1 X1", 8),
    ("F0\no1 if [#5220 GT 0]\nM70\no1 endif\nM72\nG1 X1", 8),
    ("F0\nM70\no1 if [#5220 GT 0]\nM70\no1 endif\nM72 F0\nG1 X1", 9),
    ("F0\no1 if [#5220 GT 0]\nF10\nM70\no1 endif\nM72 F0\nG1 X1", None),
])
def test_an_m72_of_a_loose_save_leaves_the_rate_every_save_agrees_on(tmp_path, body, line):
    text = program(body)
    found = [f for f in check_text(text, load_profile("linuxcnc")) if f.severity == "error"]
    if line is None:
        assert found == [], found
        assert "PROGRAM_END" in rs274_output(tmp_path, text)
        return
    assert [(f.rule, f.line, f.column) for f in found] == [("TG401", line, 4)], found
    assert "Cannot do g1 with zero feed rate" in rs274_output(tmp_path, text)


# A call of a definition read before it whose body moves no axis and changes nothing the
# position is read in (no G code, axis word, M6, M70-M73 or call; S, F, T, parameters below
# #5000 or named, M0-M9 but M2/M6, M48-M53 and o-word lines): the axes stand where they did
# before it, as rs274 runs the body (lcnc60's list). HEAD starts at X0 Y0 Z0. (the blocks
# after HEAD; the refused line, or None where rs274 runs)
STILL_CALLS = [
    ("o100 sub\nM8\no100 endsub\nG0 Z0\no100 call\nG38.2 Z0", 8),
    ("o100 sub\nM8\no100 endsub\nG0 X1\no100 call\nG38.2 X1", 8),
    ("o100 sub\n#1=2\n#<a>=3\nS100 M3\nM5 T1 F20\no1 if [#1 GT 0]\nM9\no1 endif\n"
     "o100 endsub\nG0 Z0\no100 call\nG38.2 Z0", 14),
    # the body moves, or calls one that does: not known after it
    ("o100 sub\nG0 Z1\no100 endsub\nG0 Z0\no100 call\nG38.2 Z0", None),
    ("o101 sub\nG0 Z1\no101 endsub\no100 sub\no101 call\no100 endsub\nG0 Z0\no100 call\n"
     "G38.2 Z0", None),
    ("o100 sub\nM8\no100 endsub\nG0 Z0\no100 call\nG38.2 Z1", None),
]


@pytest.mark.parametrize("body, line", STILL_CALLS)
def test_a_call_of_a_body_that_moves_no_axis_keeps_the_position(tmp_path, body, line):
    text = program(body)
    if line is None:
        clean_on_both(tmp_path, text)
        return
    assert_too_close_refused(tmp_path, text, line, 1)


# An M72 of a body's own M70/M73 (no condition or loop open at either, nothing called
# between) whose saved rate is surely zero: the restore writes that rate after the block's F,
# so a feed move without an F after it is "Cannot do g1 with zero feed rate" (review 61b v9).
# The body is called. (the blocks after HEAD; the refused line, or None where rs274 runs)
BODY_M72_ZERO = [
    ("o100 sub\nF0\nM70\nM9\nM72 F0\nG1 X1\no100 endsub\no100 call", 8),
    ("o100 sub\nF0\nM70\nF10\nM72\nG1 X1\no100 endsub\no100 call", 8),
    ("o100 sub\nM70 F0\nM72 F10\nG1 X1\no100 endsub\no100 call", 6),
    ("o100 sub\nF0\nM73\nG1 X1 F10\nM72\nG1 X2\no100 endsub\no100 call", 8),
    ("o100 sub\nF10\nM70\nF0\nM72\nG1 X1\no100 endsub\no100 call", None),
    ("o100 sub\nF0\nM70\nM71\nM70 F10\nM72\nG1 X1\no100 endsub\no100 call", None),
    ("o100 sub\nF0\nM70\nM72\nG1 X1 F5\nG0 X2\no100 endsub\no100 call", None),
]


@pytest.mark.parametrize("body, line", BODY_M72_ZERO)
def test_an_m72_of_a_body_s_own_zero_save_leaves_a_zero_rate(tmp_path, body, line):
    judged_as_rs274(tmp_path, program(body), line, "TG401",
                    "Cannot do g1 with zero feed rate")


# A definition read before an M70 or M72 of the main program: rs274 reads it without running
# it, so the feed rate after its `endsub` is the one before its `sub` (review 62b F1). HEAD
# sets F100. (the blocks after HEAD; the refused line, or None where rs274 -g runs)
DEFINITION_KEEPS_RATE = [
    # rs274 runs: the M70 saves F100, the M72 writes it after the block's F0
    ("o100 sub\nM8\no100 endsub\nM70\nM72 F0\nG1 X4", None),
    ("o100 sub\nM8\no100 endsub\nM70\nF0\nM72\nG1 X4", None),
    ("o100 sub\nF0\no100 endsub\nM70\nF0\nM72\nG1 X4", None),
    # "Cannot do g1 with zero feed rate": the body's F10 is not run, the F0 saved is restored
    ("F0\no100 sub\nF10\no100 endsub\nM70\nF10\nM72\nG1 X4", 10),
    # and a plain G1 after the endsub (review 63-lcnc63 N3): the F0 from before the `sub`
    ("F0\no100 sub\nF10\no100 endsub\nG1 X1", 7),
    ("F0\no100 sub\nG1 X1 F10\no100 endsub\nG1 X2", 7),
    # rs274 runs: the call runs the body's F10; a body's F0 is not run
    ("F0\no100 sub\nF10\no100 endsub\no100 call\nG1 X1", None),
    ("o100 sub\nF0\no100 endsub\nG1 X1", None),
]


@pytest.mark.parametrize("body, line", DEFINITION_KEEPS_RATE)
def test_a_definition_read_keeps_the_rate_an_m70_saves(tmp_path, body, line):
    judged_as_rs274(tmp_path, program(body), line, "TG401",
                    "Cannot do g1 with zero feed rate")


def test_a_definition_read_gives_no_feed_rate_to_a_plain_g1(tmp_path):
    # review 63-lcnc63 N3 (R1): no F before the `sub`, the body's F10 not run: rs274 "Cannot do
    # g1 with zero feed rate" at `G1 X2` (main was clean)
    text = "G21 G17 G90\nG0 X0 Y0 Z0\no100 sub\nG1 X1 F10\no100 endsub\nG1 X2\nM2\n"
    judged_as_rs274(tmp_path, text, 6, "TG401", "Cannot do g1 with zero feed rate")


# A G2 in a condition or loop of the main program that may not run (its condition not known
# here, a `while` that may turn none): the bare move after it is an arc one way and a line the
# other, so it is not judged as an arc (lcnc63). rs274 -g reads #5220 as 1 (G54): `GT 100`
# is false there and the program runs; `[1]` and an `if` whose branches are both arcs are
# "R i j k words all missing for arc". (the blocks after HEAD; the refused line, or None)
FLOW_ARC = [
    ("o102 while [#5220 GT 100]\nG2 X1 Y0 I0.5 J0\no102 endwhile\nZ0.5", None),
    ("o102 if [#5220 GT 100]\nG2 X1 Y0 I0.5 J0\no102 endif\nZ0.5", None),
    # the `else` starts in the mode from before the `if`, G1 here (it was TG404 at X1)
    ("G1 X0\no102 if [#5220 GT 100]\nG2 X1 Y0 I0.5 J0\no102 else\nX1\no102 endif\nZ0.5",
     None),
    ("o102 if [1]\nG2 X1 Y0 I0.5 J0\no102 endif\nZ0.5", 6),
    ("G1 X0\no102 if [#5220 GT 100]\nG2 X1 Y0 I0.5 J0\no102 else\nG3 X0 Y0 I-0.5 J0\n"
     "o102 endif\nZ0.5", 9),
    # an `elseif` surely true closes the block as an `else` (review 63-lcnc63 F4)
    ("o1 if [#5220 GT 100]\nG2 X1 Y0 I0.5 J0\no1 elseif [1]\nG2 X0 Y0 I-0.5 J0\no1 endif\n"
     "Z0.5", 8),
    # a definition's body keeps the mode as read: its conditions are not evaluated
    # (review 63-lcnc63 F4; the call with #1 = 1 runs the G2, then Z0.5)
    ("o100 sub\no1 if [#1 GT 0]\nG2 X1 Y0 I0.5 J0\no1 endif\nZ0.5\no100 endsub\n"
     "o100 call [1]", 7),
    ("o100 sub\no3 if [1]\nG2 X1 Y0 I0.5 J0\no3 endif\nZ0.5\no100 endsub\no100 call", 7),
    ("o100 sub\no3 repeat [1]\nG2 X1 Y0 I0.5 J0\no3 endrepeat\nZ0.5\no100 endsub\n"
     "o100 call", 7),
]


@pytest.mark.parametrize("body, line", FLOW_ARC)
def test_an_arc_in_a_condition_that_may_not_run_leaves_the_mode_not_known(tmp_path, body, line):
    judged_as_rs274(tmp_path, program(body), line, "TG404",
                    "R i j k words all missing for arc")


def test_the_lines_of_a_later_body_that_ends_the_program_are_still_judged(tmp_path):
    # review 63-lcnc63 F3: the body's own G1 at F0 runs and is refused (its M2 ends the program
    # after it); only the main program's lines after the call are dropped
    text = "G21 G17 G90 F100\nG0 X0 Y0 Z0\no300 call\nM2\no300 sub\nG1 X1 F0\nM2\no300 endsub\n"
    assert [(r, n) for r, n, _ in errors(text)] == [("TG401", 6)], text
    assert "Cannot do g1 with zero feed rate" in rs274_output(tmp_path, text)


# A block whose M72 rs274 2.9.0 drops: where the save differs from the state in force (the feed
# mode, rate, speed, units, spindle or compensation: surely; another modal group: perhaps), the
# restore runs a block of its own through `execute`, which is read into the block rs274 runs
# (interp_convert.cc `restore_settings`), so nothing of the M72's block after the M72 in the
# order of execution runs: its G20/G21, G40-G42, G90/G91, other G codes, M48-M53 and its motion
# (review 59b F7). HEAD is G90 G21 at X0 Y0 Z0. (the blocks after HEAD, the refused line or
# None where rs274 -g runs, rs274's message)
TOO_CLOSE = "Start point too close to probe point"
M72_DROPPED_BLOCK = [
    # the dropped G91 G0 Z1: Z stays at 0, the Z1 after it is absolute, the probe has its way
    # (review 63-lcnc63 D1; D13 the same with the save's G91 restored)
    ("M70\nS200\nM72 G91 G0 Z1\nZ1\nG90 G38.2 Z2", None, TOO_CLOSE),
    ("G91\nM70\nG90\nS200\nM72 G91 G0 X1\nX1\nG90 G38.2 X2", None, TOO_CLOSE),
    # ... and where it has none (D19, D6, D14: G90 restored, X1 then X1 absolute)
    ("M70\nS200\nM72 G91 G0 Z1\nG38.2 Z0", 6, TOO_CLOSE),
    ("G91\nM70\nG90\nS200\nM72 G91 G0 X1\nX1\nG90 G38.2 X1", 9, TOO_CLOSE),
    ("M70\nS200\nM72 G91 G0 X1\nG0 X1\nG38.2 X1", 7, TOO_CLOSE),
    ("M70\nS200\nM72 G91 G1 X1\nG91 X0\nG90 G38.2 X0", 7, TOO_CLOSE),
    # nothing differs: the block runs, its G91 and its move (D11's shape)
    ("M70\nM72 G91 G0 X1\nG90 G38.2 X0", None, TOO_CLOSE),
    ("M70\nM72 G91 G0 Z1\nZ1\nG90 G38.2 Z2", 6, TOO_CLOSE),
    # the dropped G42.1 under G41.1 is not "Cannot turn cutter radius comp on when on" (D9,
    # D18), nor a G54 or an M48 "with cutter radius compensation on"
    ("G41.1 D0.1\nG1 X1\nM70\nG93\nM72 G42.1 D0.1\nG94 G1 X2 F10", None, ""),
    ("G41.1 D0.1\nG1 X1\nM70\nG93\nM72 G42.1 D0.1\nG40\nG94 G81 X2 Z-1 R1 F10", None, ""),
    ("G41.1 D0.1\nG1 X1\nM70\nS200\nM72 G54\nG1 X2", None, ""),
    ("G41.1 D0.1\nG1 X1\nM70\nS200\nM72 M48\nG1 X2", None, ""),
    ("M70\nS200\nM72 G19 G41.1 D0.1\nG1 X1", None, ""),
    # a drop only possible (an M8 and an M9 between, the restore writing nothing): judged,
    # as rs274 refuses them (review 75-lcnc75a F1)
    ("G41.1 D0.1\nM70\nM8\nM9\nM72 G42.1 D0.1\nG1 X1", 7,
     "Cannot turn cutter radius comp on when on"),
    ("G41.1 D0.1\nM70\nM8\nM9\nM72 M48\nG1 X1", 7,
     "Cannot enable overrides with cutter radius compensation on"),
    # nothing differs: the block's G42.1 runs under G41.1 (D10)
    ("G41.1 D0.1\nM70\nM72 G42.1 D0.1\nG1 X1", 5, "Cannot turn cutter radius comp on when on"),
    # the dropped G40: the compensation stays on, as saved
    ("G41.1 D0.1\nG1 X1\nM70\nS200\nM72 G40\nG81 X2 Z-1 R1", 8,
     "Cannot use canned cycles with cutter compensation on"),
    # units: the restore's G20/G21 runs first, a sure drop; the block's own is dropped
    ("M70\nG20\nM72 G0 X1\nG38.2 X0", 6, TOO_CLOSE),
    ("M70\nG20\nM72 G21 G0 X1\nG38.2 X0", 6, TOO_CLOSE),
    ("M70\nS200\nM72 G20 G0 X1\nG38.2 X1", None, TOO_CLOSE),
    # the spindle or the compensation the save took differs: a sure drop, X stays at 0
    ("S1000 M3\nM70\nM5\nM72 G0 X1\nG38.2 X0", 7, TOO_CLOSE),
    ("S1000 M3\nM70\nM5\nM72 G91 G0 X1\nG0 X1\nG38.2 X1", 8, TOO_CLOSE),
    ("G41.1 D0.1\nG1 X1\nM70\nG40\nM72 G0 X2\nG40 G38.2 X1", 8, TOO_CLOSE),
    # ... or the distance mode or the plane (`M70` / `G18` / `M72 G91 G0 X1`: the restore's G17)
    ("M70\nG91\nM72 G0 X1\nG90 G38.2 X0", 6, TOO_CLOSE),
    ("M70\nG91\nM72 G90 G0 X1\nG38.2 X0", 6, TOO_CLOSE),
    ("M70\nG18\nM72 G91 G0 X1\nG17\nG0 X1\nG38.2 X1", 8, TOO_CLOSE),
    # its arc is never converted: not "Current point same as end point of arc", "R i j k
    # words all missing" or "Mixed radius ijk format"; nothing differs, it runs and is
    ("M70\nS200\nM72 G2 X1 Y0 R2", None, ""),
    ("M70\nS200\nM72 G2 X1 Y0", None, ""),
    ("M70\nS200\nM72 G2 X1 Y0 R1 I1", None, ""),
    ("M70\nG18\nM72 G2 X1 Z0 R2", None, ""),
    ("M70\nM72 G2 X0 Y0 R2", 4, "Current point same as end point of arc"),
    # nor its probe, canned cycle or their refusals (review 75-lcnc75a N4, N6): a probe or
    # cycle under the compensation, a cycle without its Q or under its R
    ("G41.1 D0.1\nM70\nG93\nM72 G81 X1 Z-1 R1\nG94 G1 X1 F10", None, ""),
    ("G41.1 D0.1\nM70\nG93\nM72 G38.2 X1\nG94 G1 X1 F10", None, ""),
    ("M70\nS200\nM72 G83 X1 Z-1 R1\nG0 X1", None, ""),
    ("M70\nS200\nM72 G98 G81 X1 Z-1 R-5\nG80 G0 X1", None, ""),
    ("M70\nG19\nM72 G38.2 X5", None, ""),
    ("M70\nG21\nS200\nM72 G38.2 X5", None, ""),
    # ... where the drop does not happen, they are (nothing differs; G42 saved and G42.1 in
    # force are one side, which is all rs274 compares: review 76-lcnc76a F5)
    ("G42\nG1 X1\nM70\nG40\nG42.1 D0.1\nG1 X6\nM72 G81 X1 Z-1 R1\nG40", 9,
     "Cannot use canned cycles with cutter compensation on"),
    ("G41.1 D0.1\nM70\nM72 G38.2 X1\nG40", 5, "Cannot probe with cutter radius comp on"),
    # a G4 beside it, dropped with the G91
    ("M70\nS200\nM72 G91 G4 P0.1\nX1\nG38.2 X1", 7, TOO_CLOSE),
    # nothing saved: the M72 itself is refused, before any of its block runs
    ("M72 G91 G0 X1\nG0 X1\nG38.2 X1", 3,
     "Cannot restore context from invalid stack frame - missing M70/M73?"),
    # inside a body (its M73 restored at the endsub; the body's own save is not followed,
    # its M72 block's G91 not known after it, nothing judged by it)
    ("o100 sub\nM73\nS200\nM72 G91 G0 X1\no100 endsub\no100 call\nG0 X1\nG38.2 X1", 10,
     TOO_CLOSE),
]


@pytest.mark.parametrize("body, line, message", M72_DROPPED_BLOCK)
def test_a_dropped_m72_block_runs_nothing_after_its_m72(tmp_path, body, line, message):
    judged_as_rs274(tmp_path, program(body), line, "TG412", message)


# The coolant and the feed override, which rs274 2.9.0's restore writes where they differ from
# the save (interp_convert.cc `gen_m_codes`: slot 4 M7 under mist, M9 with both off, nothing
# under flood alone; slot 5 M8 under flood; slot 6 M48/M49), compared by value at the M72:
# where the restore surely writes one, its block is surely dropped (its arc or probe never
# judged); where they are back as saved, surely not (review 76-lcnc76a F7; each verdict is
# `rs274 -g`'s). (the blocks after HEAD, the refused line or None where rs274 runs, rs274's
# message)
SAME_POINT = "Current point same as end point of arc"
M72_RESTORE_EXTRAS = [
    # the restore writes M9 (or M48): dropped, even after a G21 that keeps the points known
    ("M70\nG21\nM8\nM72 G2 X0 Y0 R1", None, ""),
    ("M70\nM7\nM72 G38.2 X0", None, ""),
    ("M70\nM49\nM72 G2 X0 Y0 R1", None, ""),
    ("M8\nM70\nM9\nM72 G2 X0 Y0 R1", None, ""),
    ("M49\nM70\nM48\nM72 G2 X0 Y0 R1", None, ""),
    ("M70 M8\nM72 G2 X0 Y0 R1", None, ""),
    # a followed M72 that writes nothing: its own M8 runs, the next M72 writes M9
    ("M70\nM72 M8\nM72 G2 X0 Y0 R1", None, ""),
    # the coolant after a call or in a condition is not known: not judged
    ("o100 sub\nM8\no100 endsub\no100 call\nM70\nM9\nM72 G2 X0 Y0 R1", None, ""),
    ("M70\no1 if [#1 EQ 0]\nM8\no1 endif\nM72 G2 X0 Y0 R1", None, ""),
    # put back as saved, or a change the restore does not write (flood saved alone, mist
    # now; mist saved, flood now): the block runs
    ("M70\nM8\nM9\nM72 G2 X0 Y0 R1", 6, SAME_POINT),
    ("M70\nM49\nM48\nM72 G2 X0 Y0 R1", 6, SAME_POINT),
    ("M8\nM70\nM7\nM72 G2 X0 Y0 R1", 6, SAME_POINT),
    ("M7\nM70\nM8\nM72 G2 X0 Y0 R1", 6, SAME_POINT),
    ("M70\nM8\nM9\nM72 G38.2 X0", 6, TOO_CLOSE),
    # a surely dropped M72's own M8 never runs: the next M72 finds the coolant as saved
    ("M70\nS200\nM72 M8\nM72 G2 X0 Y0 R1", 6, SAME_POINT),
    ("M70\nM8\nM72 M9\nM72 G2 X0 Y0 R1", 6, SAME_POINT),
    # a surely dropped block's probe never runs: the point is the one before it (review
    # 77-lcnc77a F4)
    ("M70\nM8\nM72 G38.2 Z0\nG38.2 X0", 6, TOO_CLOSE),
    ("M70\nS200\nM72 G38.2 Z0\nG38.2 X0", 6, TOO_CLOSE),
    # M50 sets the feed override back on (no P, or P1), off with P0; M51 leaves it
    # (review 77-lcnc77a F1)
    ("M70\nG21\nM49\nM50\nM72 G2 X0 Y0 R1", 7, SAME_POINT),
    ("M70\nM49\nM50 P1\nM51 P1\nM72 G38.2 X0", 7, TOO_CLOSE),
    ("M70\nM50 P0\nM72 G2 X0 Y0 R1", None, ""),
    # an M72 in a condition or loop restores the coolant there or not: not known after it, the
    # next save's coolant neither (review 77-lcnc77a F3; rs274 runs the G91: no drop)
    ("G0 X5\nM70\nM8\no1 if [#<_x> EQ 5]\nM72\no1 endif\nM70\nM9\nM72 G91\nG0 X1\n"
     "G90 G38.2 X1", None, ""),
    ("G0 X5\nM70\nM8\no1 repeat [1]\nM72\no1 endrepeat\nM70\nM9\nM72 G91\nG0 X1\n"
     "G90 G38.2 X1", None, ""),
]


# A B C, which rs274's `convert_length_units` does not convert (X Y Z and U V W only): kept
# through a G20/G21 and through a surely dropped M72 block, a probe of them judged under G90
# where the start is known and its double is the nearest (the last word of the axis absolute;
# review 76-lcnc76a F6). (the blocks after HEAD, the refused line or None where rs274 runs)
ABC_PROBE = [
    ("G0 A0\nM70 G20\nM72 G91\nG38.2 A0", 6),
    ("G0 A0\nM70\nG20\nM72 G91\nG38.2 A0", 7),
    ("G0 A0\nG20\nG38.2 A0", 5),
    ("G0 A0.3\nG20\nG38.2 A0.3", 5),
    ("G0 A0\nM70\nS200\nM72 G91\nG38.2 A0", 7),
    ("G0 A5\nM70\nS200\nM72 G0 A7\nG38.2 A5", 7),
    # the block runs (nothing differs): A at 7
    ("G0 A5\nM70\nM72 G0 A7\nG38.2 A5", None),
    ("G0 A5 B2\nG91 B1\nG90 G38.2 A5", 5),
    # a sum of increments (0.1 + 0.1 + 0.1 is not the double of 0.3): not judged, runs
    ("G0 A0.1\nG91 G0 A0.1\nG0 A0.1\nG90 G38.2 A0.3", None),
    ("G0 A5\nG10 L2 P1 A1\nG38.2 A5", None),
]


@pytest.mark.parametrize("body, line", ABC_PROBE)
def test_a_probe_of_a_rotary_axis_is_judged_from_its_kept_point(tmp_path, body, line):
    judged_as_rs274(tmp_path, program(body), line, "TG412", TOO_CLOSE)


@pytest.mark.parametrize("body, line, message", M72_RESTORE_EXTRAS)
def test_an_m72_restore_writes_the_coolant_and_override_that_differ(tmp_path, body, line,
                                                                     message):
    judged_as_rs274(tmp_path, program(body), line, "TG412", message)


def test_an_m72_restores_the_units_its_save_took(tmp_path):
    # `M70` / `G20` / `M72`: the restore's G21 runs first (rs274 moves to X-500 mm); a dropped
    # block's own G20 never runs; a save in inch restored from mm reads X-500 in inch, 12.7 m
    # beyond the X travel
    lc = tmp_path / "lc.toml"
    lc.write_text('name = "lc"\nbase = "linuxcnc"\n[limits]\nX = [-762, 762]\n'
                  'Y = [-406, 406]\nZ = [-508, 10]\n')
    profile = load_profile(str(lc))

    def found(body: str) -> list[tuple[str, int]]:
        return [(f.rule, f.line) for f in check_text(program(body), profile)
                if f.severity == "error"]

    assert found("M70\nG20\nM72\nG0 X-500") == []
    assert found("M70\nS200\nM72 G20\nG0 X-500") == []
    assert found("G20\nM70\nG21\nM72\nG0 X-500") == [("TG601", 7)]
    # the save's own G20/G21 runs after it: `M70 G20` saves mm (review 75-lcnc75a N2)
    assert found("M70 G20\nS200\nM72\nG0 X-500") == []
    assert found("G20\nM70 G21\nS200\nM72\nG0 X-500") == [("TG601", 7)]
    # without the M72, the G20 holds
    assert found("G20\nG0 X-500") == [("TG601", 4)]
    for body in ("M70\nG20\nM72\nG0 X-500", "M70\nS200\nM72 G20\nG0 X-500",
                 "M70 G20\nS200\nM72\nG0 X-500"):
        assert "PROGRAM_END" in rs274_output(tmp_path, program(body))
    # rs274 moves in inch after `G20` / `M70 G21` / `M72` (X-500 in is -12700 mm): its last
    # USE_LENGTH_UNITS before the move, the M72's
    out = rs274_output(tmp_path, program("G20\nM70 G21\nS200\nM72\nG0 X-500"))
    units = [line for line in out.splitlines() if "USE_LENGTH_UNITS" in line]
    assert units and "CANON_UNITS_INCHES" in units[-1], out


# rs274 keeps X Y Z in the units in force and converts them at a change of units, by
# `INCH_PER_MM` (1/25.4) at G20 and by 25.4 at G21 (interp_convert.cc `convert_length_units`;
# an M72's restore of other units the same): the doubles it compares are those products (0.3
# comes back as 0.3, 0.1 and 1 do not). Review 75-lcnc75a F2. HEAD is G90 G21 at X0 Y0 Z0.
UNITS_TURNED = [
    # F2: a unit restore with G91 beside it (dropped), the probe at the unmoved point
    ("M70\nG20\nM72 G91 G1 X1\nG40\nG38.2 X0", 7, TOO_CLOSE),
    ("M70\nG20\nM72 G91\nG38.2 X0", 6, TOO_CLOSE),
    ("M70\nG20\nM72\nG2 X0 Y0 R1", 6, "Current point same as end point of arc"),
    ("G20\nM70\nG21\nM72\nG38.2 X0", 7, TOO_CLOSE),
    ("G20\nG38.2 Y0", 4, TOO_CLOSE),
    ("G0 X0.3\nM70\nG20\nM72\nG38.2 X0.3", 7, TOO_CLOSE),
    ("G0 X0.3\nG20\nG21\nG38.2 X0.3", 6, TOO_CLOSE),
    ("G20\nG91 G0 X1\nG90 G38.2 X1", 5, TOO_CLOSE),
    # the round trips that are not the decimal: rs274 runs
    ("G0 X0.1\nM70\nG20\nM72\nG38.2 X0.1", None, ""),
    ("G0 X1\nG20\nG21\nG38.2 X1", None, ""),
    ("G0 X0.3\nG20 G91 G0 X1\nG90 G38.2 X1", None, ""),
    ("G20 F4\nG81 X1 Z-1 R1\nG38.2 Z-1", None, ""),
]


@pytest.mark.parametrize("body, line, message", UNITS_TURNED)
def test_a_change_of_units_converts_the_point_as_rs274(tmp_path, body, line, message):
    judged_as_rs274(tmp_path, program(body), line, "TG412", message)


# rs274 refuses the M72 itself where its restore block cannot run under the compensation in
# force (interp_convert.cc `restore_settings`: "M7x: restore_settings failed executing: ' G17
# G40': Cannot change planes with cutter radius compensation on"): a plane that differs, or
# the other side of a static compensation (review 75-lcnc75a N5).
M72_RESTORE_REFUSED = [
    ("M70\nG18\nG41.1 D0.1\nM72 G1 X1\nG40", 6,
     "Cannot change planes with cutter radius compensation on"),
    ("G18\nG41.1 D0.1\nG1 X1\nM70\nG40\nG17\nG41.1 D0.1\nG1 X2\nM72\nG40", 11,
     "Cannot change planes with cutter radius compensation on"),
    ("G41 D0\nG1 X1\nM70\nG40\nG42 D0\nG1 X2\nM72\nG40", 9,
     "Cannot turn cutter radius comp on when on"),
    # the same side (G41 saved, G41.1 in force) is not written: runs
    ("G41 D0\nG1 X1\nM70\nG40\nG41.1 D0\nG1 X2\nM72\nG40", None, ""),
    # a saved G17.1-G19.1 restored under the compensation: rs274 sets it without a word
    # (review 76-lcnc76a F8)
    ("G17.1\nM70\nG17\nG41 D0\nG1 X1\nM72\nG40", None, ""),
    # units restored under the compensation: runs
    ("M70\nG20\nG41.1 D0.1\nG1 X1\nM72\nG40", None, ""),
]


@pytest.mark.parametrize("body, line, message", M72_RESTORE_REFUSED)
def test_an_m72_whose_restore_rs274_refuses_is_said_at_it(tmp_path, body, line, message):
    judged_as_rs274(tmp_path, program(body), line, "TG412", message)


# A work offset's parameter write on LinuxCNC (interp_convert.cc): `convert_coordinate_system`
# loads the offset from #5221 + 20 * (n - 1)... only where the system selected is not the one
# in force; `convert_setup` (G10 L2/L20) of the system in force loads every axis of it from
# its parameters at once. A profile with G54 at 0 and G55's X at -100, X travel +-762: each
# program's `G0 X-700` under G55 runs at -800 (beyond too: the rows whose write waits are
# silent because X is not known while G55 stays in force, a miss kept, not a right silence)
# or, where the write of -200 holds, at -900, said. (rs274 -g has no travel; it reads the
# parameter in inches: the SET_G5X_OFFSET before the move says whether the write holds,
# -5080 mm, or not, 0.)
WO_HEAD = "G21 G17 G90 F100\n"
WRITE_IN_FORCE = [
    # selected again from another: rs274 SET_G5X_OFFSET(2, -5080...) then the move
    ("G55\n#5241=-200\nG54\nG55\nG0 X-700", 6),
    ("G55\n#5241=-200\nG56\nG55\nG0 X-700", 6),
    # a G10 L2 of the system in force, of another axis: the write holds from there
    ("G55\n#5241=-200\nG10 L2 P2 Y0\nG0 X-700", 5),
    ("G55\n#5241=-200\nG10 L2 P3 Y0\nG54\nG55\nG0 X-700", 7),
    # rewritten before the selection: by a G10 L2 of that axis, by another write
    ("G55\n#5241=-200\nG10 L2 P2 X0\nG54\nG55\nG0 X-700", None),
    ("G55\n#5241=-200\n#5241=0\nG54\nG55\nG0 X-700", None),
    # left for G54 (X-700 at -700), G55 again later: no move under it
    ("G55\n#5241=-200\nG54\nG0 X-700\nG55\nM2", None),
]


@pytest.mark.parametrize("body, line", WRITE_IN_FORCE)
def test_a_parameter_write_of_the_system_in_force_holds_at_its_next_selection(
        tmp_path, body, line):
    from formats.profile import builtin_text, profile_from_text

    toml = builtin_text("linuxcnc").replace("[limits]\n",
                                            "[limits]\nX = [-762, 762]\nY = [-406, 406]\n")
    profile = profile_from_text(toml + "\n[work_offsets]\nG54 = { X = 0.0, Y = 0.0 }\n"
                                "G55 = { X = -100.0, Y = 0.0 }\n")
    text = f"{WO_HEAD}{body}\nM2\n"
    found = [(f.rule, f.line) for f in check_text(text, profile) if f.severity == "error"]
    assert found == ([("TG601", line)] if line else []), text
    out = rs274_output(tmp_path, text)
    assert "PROGRAM_END" in out, out
    if "X-700" in body.split("\n")[-1]:
        before = out.split("STRAIGHT_TRAVERSE(-700.0000")[0]
        last = before.rsplit("SET_G5X_OFFSET(2, ", 1)[1]
        assert last.startswith("-5080.0000" if line else "0.0000"), out


# (program after WO_HEAD, the line of the TG601 or None, the system rs274 loads last before
# the program's last move and its X: SET_G5X_OFFSET(2, ...) for G55; rs274's own offsets are
# its var file's zeros, the profile's G55 X is -100: `G0 X-650` runs at -750 (inside) under
# it, at -850 (beyond) after a write of -200 loaded)
WRITE_LOADED = [
    # the line's parameter is set before its G55 runs (rs274 sets a line's parameters
    # before its codes): selected from G54, the write is loaded
    ("G54\nG55 #5241=-200\nG0 X-650", 4, "2, -5080.0000"),
    ("G54\nG55 #5241=[-100-100]\nG0 X-650", 4, "2, -5080.0000"),
    # ... but G55 again under G55 loads nothing: the old value holds (-750 inside, -800
    # beyond: review 76 F1, it was taken as not known)
    ("G55\nG55 #5241=-200\nG0 X-650", None, "2, 0.0000"),
    ("G55\n#5241=-200\nG55\nG0 X-700", 5, "2, 0.0000"),
    ("G55\n#5241=-200\nG0 X-700", 4, "2, 0.0000"),
    ("G55\n#5241=-150\nG0 X-700\nG54\nG55\nG0 X850", 4, "2, -3810.0000"),
    # a value not known loaded at the selection: not known (review 76 F4); a selection from a
    # system not known may load the line's write or not (review 76 F6)
    ("G55\n#5241=#1\nG54\nG55\nG0 X-700", None, "2, 0.0000"),
    ("G55\n#5241=#1\nG10 L2 P2 Y0\nG0 X-700", None, "2, 0.0000"),
    ("G55 #5241=0\nG0 X-700", None, "2, 0.0000"),
    ("G55 #5241=100\nG0 X500\nG54\nG55\nG0 X850", 6, "2, 2540.0000"),
    ("G59.1\nG55 #5241=0\nG0 X-700", None, "2, 0.0000"),
    # G7 (X a diameter) in a condition: the offsets lost there (review 76 F5)
    ("G55\no1 if [#1 EQ 0]\nG7\no1 endif\nG0 X-700", None, "2, 0.0000"),
    # a write by an index not known may replace the one held: not known (review 76 N2)
    ("G55\n#5241=-200\n#[5241]=0\nG54\nG55\nG0 X-650", None, "2, 0.0000"),
    ("G55\n#5241=-200\n#[5200+41]=0\nG54\nG55\nG0 X-650", None, "2, 0.0000"),
    # a value known from an expression or a parameter
    ("G55\n#5241=[-200]\nG54\nG55\nG0 X-650", 6, "2, -5080.0000"),
    ("#1=-200\nG55\n#5241=#1\nG54\nG55\nG0 X-650", 7, "2, -5080.0000"),
    # G10 L2 P0 (the system in force) and G10 L20 load every axis of it
    ("G55\n#5241=-200\nG10 L2 P0 Y0\nG0 X-650", 5, "2, -5080.0000"),
    ("G55\n#5241=-200\nG10 L20 P2 Y0\nG0 X-650", 5, "2, -5080.0000"),
    ("G55\nG10 L2 P0 X-200\nG0 X-650", 4, "2, -200.0000"),
    ("G54\nG10 L2 P0 X-200\nG55\nG0 X-650", None, "2, 0.0000"),
    # an L20 leaves the axes it names not known, the others as they were
    ("G55\nG10 L20 P2 Y0\nG0 X-900", 4, "2, 0.0000"),
    ("G55\nG10 L20 P2 X0\nG0 X-900", None, "2, 0.0000"),
    # G59.1-G59.3 select another system: G55 selected again loads the write
    ("G55\n#5241=-200\nG59.1\nG55\nG0 X-650", 6, "2, -5080.0000"),
    ("G59.1\nG0 X-900\nG55\nG0 X-700", 5, "2, 0.0000"),
    # a span from before the write's loading does not run across it (review 75 N4)
    ("G55\n#5241=-300\nG0 X-650\nG54\nG55\nG0 X1000", None, "2, -7620.0000"),
    ("G55\n#5241=300\nG0 X850\nG54\nG55\nG0 X-1000", None, "2, 7620.0000"),
    ("G55\n#5241=-300\nG0 X-650\nG54\nG55\nG0 X1100", 7, "2, -7620.0000"),
    # ... nor across a plain selection of another system whose values are known: each
    # position judged as a machine position (review 76-lcnc76b N3: -700 and 760, inside,
    # was "X spans 1560"; a write of G55 under G54 loaded at its selection, -650 and 700);
    # across G59.1, not known, it runs on
    ("G54\nG0 X-700\nG55\nG0 X860", None, "2, 0.0000"),
    ("G54\n#5241=-300\nG0 X-650\nG55\nG0 X1000", None, "2, -7620.0000"),
    ("G54\nG0 X-700\nG55\nG0 X870", 5, "2, 0.0000"),
    ("G54\nG0 X-700\nG59.1\nG0 X900", 5, "7, 0.0000"),
    # ... nor where the span holds a position not judged as a machine position (in a
    # condition, before the first selection), or a later one is not (a value not known
    # loaded), or G91 runs on from the tool's place, which the selection changes in work
    # coordinates (review 78-lcnc78b F1-F3: rs274 goes beyond in each)
    ("G54\no1 if [#1 EQ 0]\nG0 X-1100\no1 endif\nG55\nG0 X700", 7, "2, 0.0000"),
    ("G0 X-1100\nG54\nG0 X0\nG55\nG0 X700", 6, "2, 0.0000"),
    ("G55\n#5241=#1\nG0 X-650\nG54\nG55\nG0 X1000", 7, "2, 0.0000"),
    ("G54\nG0 X-650\nG55\nG91\nG0 X1650", 6, "2, 0.0000"),
    ("G54\nG0 X-650\nG91\nG55\nG0 X1650", 6, "2, 0.0000"),
    # ... G91 restored by an M72 too (review 78-lcnc78b F4: rs274 runs X800 at machine 800)
    ("G55\nG91\nM70\nG90\nG54\nG0 X-760\nG0 X0\nG55\nM72\nG0 X800", 11, "2, 0.0000"),
    # M72 restores the system M70 saved (SET_G5X_OFFSET(1) at the M72), before the block's
    # own G54-G59, which rs274 2.9.0 drops (`M72 G55` runs under G54)
    ("G54\nM70\nG55\nM72\nG0 X-700", None, "1, 0.0000"),
    ("G54\nM70\nG56\nM72 G55\nG0 X-700", None, "1, 0.0000"),
    ("G55\nM70\nG54\nM72\nG0 X-700", 6, "2, 0.0000"),
    # ... and a selection from another: the write held for G55 is loaded at the next G55
    ("G54\nM70\nG55\n#5241=-200\nM72\nG55\nG0 X-650", 8, "2, -5080.0000"),
    # a condition or loop of the main program: the positions inside not judged, the system
    # back after it where nothing inside touched the offsets (before: every offset lost)
    ("G55\no1 if [#1 GT 0]\nG0 X-900\no1 endif\nG0 X-700", 6, "2, 0.0000"),
    ("G55\n#1=0\no1 while [#1 LT 2]\nG0 X-600\n#1=[#1+1]\no1 endwhile\nG0 X-700", 8,
     "2, 0.0000"),
    ("G55\n#5241=-200\no1 if [#1 GT 0]\nM0\no1 endif\nG54\nG55\nG0 X-650", 9,
     "2, -5080.0000"),
    # ... a selection or a write inside: lost, as before
    ("G55\no1 if [#1 GT 0]\nG54\no1 endif\nG0 X-700", None, "2, 0.0000"),
    ("G55\no1 if [#1 GT 0]\n#5241=0\no1 endif\nG54\nG55\nG0 X-700", None, "2, 0.0000"),
    # a write of G54 before the program's first selection: rs274 starts in G54 and loads it
    # at no G54 (-500, inside), LinuxCNC in the system it persisted (#5220), from which a G54
    # loads it: not known there; a selection of another first leaves G54 with it, loaded at
    # its next selection (-800, beyond; review 76-lcnc76b N5); G55's write is loaded
    ("#5221=-300\nG54\nG0 X-500", None, "1, 0.0000"),
    ("#5221=-300\nG55\nG54\nG0 X-500", 5, "1, -7620.0000"),
    ("#5221=-300\nG59.1\nG54\nG0 X-500", 5, "1, -7620.0000"),
    ("#5221=-300\nG54\nG0 X-500\nG55\nG54\nG0 X-500", 7, "1, -7620.0000"),
    # ... but beyond under both values, said (-800 in rs274 -g, -1100 where loaded; review
    # 77-lcnc77a F5); beyond under one of them only, not
    ("#5221=-300\nG54\nG0 X-800", 4, "1, 0.0000"),
    ("#5221=0\nG54\nG0 X850", 4, "1, 0.0000"),
    ("#5221=100\nG54\nG0 X700", None, "1, 0.0000"),
    # a G10 L2/L20 P1 before the first selection: rs274 -g (in G54) loads the write there,
    # another start system at the first G54: loaded either way (review 77-lcnc77a F7)
    ("#5221=-300\nG10 L2 P1 Y0\nG54\nG0 X-500", 5, "1, -7620.0000"),
    ("#5241=-300\nG55\nG0 X-500", 4, "2, -7620.0000"),
]


@pytest.mark.parametrize("body, line, loaded", WRITE_LOADED)
def test_a_work_offset_written_is_judged_where_rs274_loads_it(tmp_path, body, line, loaded):
    from formats.profile import builtin_text, profile_from_text

    toml = builtin_text("linuxcnc").replace("[limits]\n",
                                            "[limits]\nX = [-762, 762]\nY = [-406, 406]\n")
    profile = profile_from_text(toml + "\n[work_offsets]\nG54 = { X = 0.0, Y = 0.0 }\n"
                                "G55 = { X = -100.0, Y = 0.0 }\n")
    text = f"{WO_HEAD}{body}\nM2\n"
    found = [(f.rule, f.line) for f in check_text(text, profile) if f.severity == "error"]
    assert found == ([("TG601", line)] if line else []), text
    out = rs274_output(tmp_path, text)
    assert "PROGRAM_END" in out, out
    before = out.rsplit("STRAIGHT_TRAVERSE(", 1)[0]
    assert before.rsplit("SET_G5X_OFFSET(", 1)[1].startswith(loaded), out


# ... nor in a definition after the main program's end, which rs274 reads where the ending body
# calls it: `G1 Y` refused there (review 76 F3)
def test_a_line_not_read_in_a_later_definition_the_ending_body_calls_is_said(tmp_path):
    text = program("o300 sub\no301 call\nM2\no300 endsub\no300 call\nG1 X\nM2\no301 sub\n"
                   "G1 Y\no301 endsub")
    assert [(r, n) for r, n, _ in errors(text)] == [("TG100", 11)], text
    assert "PROGRAM_END" not in rs274_output(tmp_path, text)
