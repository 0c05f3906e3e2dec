"""Units where a span of the program runs again or a branch changes the feed's units (review 6).

Beside the conditions, loops and jumps of `test_convert_flow.py`: a jump back while the units are
in doubt (finding 3), a SINUMERIK branch from G700 into G70 that changes the feed's units and not
the lengths' (finding 4), and the spans words run again (finding 5): `M99 P n` (FANUC
"Subprogram": to block n), a main program's M99 (to its start), Haas `M97 P n` (the block n of the
same program, up to its M99) and `M98 P n` calling a program of the same file. Each is refused at
its line and column where a path reads a value in other units than the conversion does, and
converts where every path agrees.
"""

from __future__ import annotations

import pytest

from formats.convert import ConvertOptions, convert_text
from formats.errors import ConversionError
from formats.profile import load_profile

FANUC = load_profile("fanuc-mill")
HAAS = load_profile("haas-mill")
SIEMENS = load_profile("sinumerik-840d")


def refusal(src: str, profile, units: str) -> ConversionError:
    with pytest.raises(ConversionError) as info:
        convert_text(src, ConvertOptions(profile, profile, units=units))
    return info.value


def converted(src: str, profile, units: str) -> list[str]:
    return convert_text(src, ConvertOptions(profile, profile, units=units))[0].splitlines()


@pytest.mark.parametrize(("src", "profile", "units", "at", "start"), [
    # 3: if/else choosing G70 or G71, then GOTOB: the span runs again in either units although
    # the file-order units (G71) are the label's
    ("G71 G90 G17\nLAB1:\nG1 X1 F100\nIF R1>R2\nG70\nELSE\nG71\nENDIF\nIF R3>R4 GOTOB LAB1\n"
     "M30\n", SIEMENS, "inch", (9, 1),
     "the jump back to LAB1 (read first in metric) runs that span again in units not known "
     "here (the condition beginning on line 4 ends in metric on one path and in inch on "
     "another"),
    # 3: the Macro B form, a one-block IF .. THEN G20 before the jump back
    ("%\nO1000\nG21 G90 G17\nN10 G1 X1. F100.\nIF [#1 EQ #3] THEN G20\nIF [#2 LT #4] GOTO 10\n"
     "M30\n%\n", FANUC, "inch", (6, 1),
     "the jump back to N10 (read first in metric) runs that span again in units not known "
     "here (the condition on line 5 selects inch"),
    # 4: G700 then a branch into G70: X in inch on both paths, F in in/min on one only
    ("G700 G90 G17 G94\nG1 X1 F10\nIF R1>R2\nG70\nENDIF\nG1 X2 F100\nM30\n", SIEMENS,
     "metric", (6, 7),
     "the feed's units in force here are not known (G700/G710 set them, G70/G71 set them to "
     "the machine's): the condition beginning on line 3 ends in metric on one path and in "
     "inch on another (units code on line 4, column 1)"),
    # review 7, 4: past a G71 no path reads, the jumps bring the lengths in inch both, the
    # feed in mm (G70) from line 3 and in inch (G700) from line 5
    ("G710 G90 G17\nG70\nIF R1>R2 GOTOF LAB1\nG700\nGOTOF LAB1\nG71\nLAB1:\nG1 X1 F10\n"
     "M30\n", SIEMENS, "metric", (8, 7), "the feed's units in force here are not known "
     "(G700/G710 set them, G70/G71 set them to the machine's): the jumps to LAB1 come here in "
     "metric (line 3) and in inch (line 5)"),
    # 5: M99 P10 runs N10 again under G20
    ("%\nO1005\nG21 G90 G17\nN10 G1 X1. F100.\nG20\nG1 X2.\nM99 P10\n%\n", FANUC, "inch",
     (7, 1), "the jump back to N10 (read first in metric) runs that span again in inch "
     "(units code on line 5, column 1)"),
    # 5: a main program's M99 runs its head, read in metric, again in inch
    ("%\nO1025\nG90 G17\nG0 X1. Y0\nG20\nG1 X2. F10.\nM99\n%\n", FANUC, "metric", (7, 1),
     "M99 ends the program in inch: run as a main program, it begins again at its start, "
     "whose values from line 4 on, before its units code, were read in metric"),
    # 5: Haas M97 P100 from inch and from metric (after M30 only the calls reach N100)
    ("%\nO1006\nG20 G90 G17\nM97 P100\nG21\nM97 P100\nM30\nN100 G90 G1 X1. F10.\nM99\n%\n",
     HAAS, "metric", (8, 13),
     "the units in force here are not known: the jumps to N100 come here in inch (line 4) and "
     "in metric (line 6)"),
    # 5: a local span that returns in other units than its call's
    ("%\nO1006\nG20 G90 G17\nM97 P100\nG0 X1.\nM30\nN100 G21\nG90 G1 X1. F10.\nM99\n%\n",
     HAAS, "metric", (9, 1),
     "the span M97 calls at N100 returns here in metric, while its call on line 4 was in "
     "inch"),
    # 5: a span above its M97 call, in a program that changes its units
    ("%\nO1006\nG20 G90 G17\nGOTO 20\nN100 G90 G1 X1. F10.\nM99\nN20 G21\nM97 P100\nM30\n%\n",
     HAAS, "inch", (8, 1), "M97 calls N100, a span before the call, in a program that "
     "changes its units (units code on line 7, column 5)"),
    # 5: M98 P2000 from inch and from metric, O2000 after M30 read in metric
    ("%\nO1011\nG20 G90 G17\nM98 P2000\nG21\nM98 P2000\nM30\nO2000\nG90 G1 X1. F10.\nM99\n%\n",
     FANUC, "metric", (9, 8),
     "the units in force here are not known: the program O2000 is called by M98 on line 4 in "
     "inch, and read here in metric"),
    # 5: a subprogram of the file that returns in other units than its call's
    ("%\nO1011\nG20 G90 G17\nM98 P2000\nG1 X1.\nM30\nO2000\nG20\nG90 G1 X1. F10.\nG21\nM99\n%\n",
     FANUC, "metric", (11, 1),
     "the subprogram O2000 returns here in metric, while its call on line 4 was in inch"),
    # 5: the same returning to the caller's block 30 (M99 P30)
    ("%\nO1011\nG20 G90 G17\nM98 P2000\nN30 G1 X1.\nM30\nO2000\nG20\nG90 G1 X1. F10.\nG21\n"
     "M99 P30\n%\n", FANUC, "metric", (11, 1),
     "the subprogram O2000 returns here in metric, while its call on line 4 was in inch"),
    # review 7, 1: a macro called by G65 (and a modal G66 one) is entered and left as M98's
    # program is: the caller goes on in the units the macro returns in
    ("%\nO1\nG21\nG65 P2\nG1 X1. F10.\nM30\nO2\nG20\nM99\n%\n", FANUC, "inch", (9, 1),
     "the subprogram O2 returns here in inch, while its call on line 4 was in metric"),
    ("%\nO1\nG21\nG66 P2\nG1 X1. F10.\nG67\nM30\nO2\nG20\nM99\n%\n", FANUC, "inch",
     (10, 1), "the subprogram O2 returns here in inch, while its call on line 4 was in metric"),
    # an M99 under block skip may be passed over: the straight path reaches N30 in inch
    ("%\nO1\nG21 G90 G17\nG1 X1. F10.\nIF [#1 EQ #2] GOTO 30\n/M99\nG20\nN30 G1 X3.\n"
     "M30\n%\n", FANUC, "inch", (8, 8), "the units in force here are not known: the jump on "
     "line 5 to N30 comes here in metric, the straight path in inch"),
    # 5: a subprogram above its caller, read in metric, called in inch
    ("%\nO2000\nG90 G1 X1. F10.\nM99\nO1011\nG21 G90 G17\nM98 P2000\nG20\nM98 P2000\nM30\n%\n",
     FANUC, "inch", (9, 1),
     "M98 calls O2000 in inch: its first values were read in metric"),
])
def test_spans_run_again_in_other_units_are_refused(src, profile, units, at, start):
    error = refusal(src, profile, units)
    assert (error.code, error.clause, (error.line, error.column)) == (
        "conversion-units", "units", at), error.message
    assert error.message.startswith(start), error.message


@pytest.mark.parametrize(("src", "profile", "units", "line", "out"), [
    # 3: a jump back in known units equal to the label's
    ("%\nO1000\nG21 G90 G17\nN10 G1 X1. F100.\nIF [#1 EQ #3] THEN G21\nIF [#2 LT #4] GOTO 10\n"
     "M30\n%\n", FANUC, "inch", 3, "N10 G1 X0.0394 F3.937"),
    # 4: G700 written again after the branch settles the feed's units
    ("G700 G90 G17 G94\nG1 X1 F10\nIF R1>R2\nG70\nENDIF\nG700\nG1 X2 F100\nM30\n", SIEMENS,
     "metric", 6, "G1 X50.8 F2540."),
    # 4: a branch into G70 from G70 changes neither
    ("G70 G90 G17 G94\nG1 X1 F10\nIF R1>R2\nG70\nENDIF\nG1 X2 F100\nM30\n", SIEMENS,
     "metric", 5, "G1 X50.8 F100"),
    # review 7, 4: GOTOF passes over a G70 no path reads: the jump brings the feed in inch
    # (G700) and the lengths in inch, as the conversion reads on in at LAB1
    ("G710 G90 G17\nG700\nGOTOF LAB1\nG70\nLAB1:\nG1 X1 F10\nM30\n", SIEMENS, "metric",
     5, "G1 X25.4 F254."),
    ("G71\nGOTOF MARK1\nG70\nMARK1: G1 X1 F10\nM30\n", SIEMENS, "inch", 3,
     "MARK1: G1 X0.0394 F10"),
    # 4 with dead paths: the text GOTOF passes over sets the feed's units as the jump brings
    ("G710 G90 G17\nG700\nGOTOF LAB1\nG700\nLAB1:\nG1 X1 F10\nM30\n", SIEMENS, "metric",
     5, "G1 X25.4 F254."),
    # 5: M99 P10 in the units N10 was read in
    ("%\nO1005\nG21 G90 G17\nN10 G1 X1. F100.\nG0 X2.\nM99 P10\n%\n", FANUC, "inch", 3,
     "N10 G1 X0.0394 F3.937"),
    # 5: a main program that selects its units before its first value loops in them
    ("%\nO1025\nG20 G90 G17\nG0 X1. Y0\nG21\nG1 X2. F10.\nM99\n%\n", FANUC, "metric", 3,
     "G0 X25.4 Y0"),
    # 5: a call's P before the program's units code is no value its M99 runs again in inch
    ("%\nO1026\nM98 P9000\nG20 G90 G17\nG0 X1. Y0\nM99\n%\n", FANUC, "metric", 4,
     "G0 X25.4 Y0"),
    # 5: M97 P100 called twice in inch
    ("%\nO1006\nG20 G90 G17\nM97 P100\nG0 X1.\nM97 P100\nM30\nN100 G90 G1 X1. F10.\nM99\n%\n",
     HAAS, "metric", 7, "N100 G21 G90 G1 X25.4 F254."),
    # 5: a subprogram of the file called in the units it is read in, above and below its call
    ("%\nO1011\nG21 G90 G17\nM98 P2000\nG1 X1.\nM30\nO2000\nG90 G1 X1. F10.\nM99\n%\n", FANUC,
     "inch", 4, "G1 X0.0394"),
    ("%\nO2000\nG90 G1 X1. F10.\nM99\nO1011\nG21 G90 G17\nM98 P2000\nG1 X2.\nM30\n%\n", FANUC,
     "inch", 7, "G1 X0.0787"),
    # after M99 P30 (a jump) and a main program's M99 (to its start) no path reads the G20:
    # N20 and N30 are reached by the jumps only, in metric
    ("%\nO1\nG21 G90 G17\nIF [#1 EQ #2] GOTO 20\nN10 G1 X1. F10.\nM99 P30\nG20\n"
     "N20 G1 X2.\nN30 G1 X3.\nM30\n%\n", FANUC, "inch", 7, "N20 G1 X0.0787"),
    ("%\nO1\nG21 G90 G17\nG1 X1. F10.\nIF [#1 EQ #2] GOTO 30\nM99\nG20\nN30 G1 X3.\n"
     "M30\n%\n", FANUC, "inch", 7, "N30 G1 X0.1181"),
    # review 7, 1: a G65 macro that keeps its caller's units
    ("%\nO1\nG21\nG65 P2\nG1 X1. F10.\nM30\nO2\nG91 G0 X1.\nM99\n%\n", FANUC, "inch", 4,
     "G1 X0.0394 F0.394"),
])
def test_spans_every_path_agrees_on_still_convert(src, profile, units, line, out):
    assert converted(src, profile, units)[line] == out
