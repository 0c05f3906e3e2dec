"""`tapegate diff` and formats.diff: programs compared as NC, and a --verify that can fail."""

from __future__ import annotations

import json
from decimal import Decimal
from fractions import Fraction
from pathlib import Path

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from formats.conversion import ConvertStats
from formats.convert import ConvertOptions, convert_file
from formats.diff import Differ, DiffError, DiffOptions, ProgramReader, diff_files
from formats.errors import ConversionError
from formats.parser import parse_text
from formats.profile import load_profile
from formats.verify import verify_conversion
from postproc.check import check_text
from tapegate.cli import main

from .conftest import corpus_files, needs_corpus

FANUC = load_profile("fanuc-mill")
HALF = Decimal("0.5")

PROGRAM = "%\nO1000\nN10 G21 G90 G94\nN20 G01 X25.4 Y10. F254.\nN30 X12.7 (CUT)\nN40 M30\n%\n"


def write(tmp_path: Path, name: str, text: str) -> str:
    path = tmp_path / name
    path.write_text(text)
    return str(path)


def differences(a: str, b: str, prof_a=FANUC, prof_b=FANUC, **options):
    differ = Differ(DiffOptions(**options), prof_b)
    found = list(diff_files(a, b, prof_a, prof_b, differ.options, differ=differ))
    return found, differ.summary


def run(*args: str):
    return CliRunner().invoke(main, list(args), catch_exceptions=False)


# -- the same program, written another way ------------------------------------------------------


def test_decimal_styles_zeros_spacing_and_line_ends_are_the_same_program(tmp_path):
    a = write(tmp_path, "a.nc", PROGRAM)
    # Fanuc least increments (X25400 = 25.400 mm), leading and trailing zeros, G1 for G01,
    # no spaces, CR LF
    b = write(tmp_path, "b.nc", "%\r\nO01000\r\nN010G21G90G94\r\nN20 G1 X25400 Y010.000 "
                                "F254.\r\n\r\nN30   X12.70 (CUT)\r\nN40M30\r\n%\r\n")
    found, summary = differences(a, b)
    assert found == [] and summary.same
    assert (summary.paired, summary.pairing) == (7, "number")
    result = run("diff", a, b, "-p", "fanuc-mill")
    assert result.exit_code == 0, result.output
    assert "are the same program (7 blocks paired by number)" in result.output


def test_the_same_program_in_inches_is_the_same_exactly(tmp_path):
    """25.4 mm = 1 in exactly, 254 mm/min = 10 in/min: compared in one unit, with decimal."""
    a = write(tmp_path, "a.nc", PROGRAM)
    b = write(tmp_path, "b.nc", PROGRAM.replace("G21", "G20").replace("X25.4", "X1.")
              .replace("Y10.", "Y0.3937").replace("F254.", "F10.").replace("X12.7", "X0.5"))
    found, _ = differences(a, b)
    [change] = found[0].words  # 10 mm is 0.393700787... in: 0.3937 is 0.008 of a step off
    assert (change.key, change.difference, change.steps) == ("Y", Decimal("-0.00002"),
                                                             Fraction(-2, 254))
    assert differences(a, b, tolerance=HALF)[0] == []


# -- what differs -----------------------------------------------------------------------------


def test_a_changed_value_is_reported_in_steps_of_b(tmp_path):
    a = write(tmp_path, "a.nc", PROGRAM)
    b = write(tmp_path, "b.nc", PROGRAM.replace("X12.7", "X12.701"))
    found, summary = differences(a, b)
    [block] = found
    assert (block.kind, block.a.line, block.b.line) == ("changed", 5, 5)
    [change] = block.words
    assert change.describe() == "X12.7 -> X12.701 (+0.001 mm, +1 step)"
    assert summary.largest == {"X": 1} and not summary.same
    # one step of B's inch format (0.0001 in) is 0.00254 mm
    inch = write(tmp_path, "c.nc", PROGRAM.replace("G21", "G20").replace("X25.4", "X1.0001")
                 .replace("Y10.", "Y0.3937").replace("F254.", "F10.").replace("X12.7", "X0.5"))
    [block] = differences(a, inch, tolerance=HALF)[0]
    assert block.words[0].describe() == "X25.4 -> X1.0001 (+0.00254 mm, +1 step)"


def test_added_and_removed_blocks_and_words_by_number(tmp_path):
    a = write(tmp_path, "a.nc", PROGRAM)
    b = write(tmp_path, "b.nc", PROGRAM.replace("N30 X12.7 (CUT)\n", "")
              .replace("N20 G01 X25.4 Y10. F254.\n", "N20 G01 X25.4 Y10.\nN25 M08\n")
              .replace("N40 M30", "N40 M30 M09"))
    found, summary = differences(a, b)
    kinds = [(d.kind, d.a.line if d.a else None, d.b.line if d.b else None) for d in found]
    assert kinds == [("changed", 4, 4), ("added", None, 5), ("removed", 5, None),
                     ("changed", 6, 6)]
    assert [w.describe() for w in found[0].words] == ["F254. removed"]
    assert [w.describe() for w in found[3].words] == ["M09 added"]
    assert (summary.changed, summary.added, summary.removed) == (2, 1, 1)


def test_by_number_a_lower_number_starts_the_next_program_and_groups_align_inside(tmp_path):
    """Two programs in one file (the numbers start again at N10), an unnumbered block added
    inside one group and a changed one in another: each is paired within its own number."""
    first = "N10 G21 G90\nN20 G01 X1. F100.\nY1.\nY2.\nN30 X2.\n"
    second = "N10 G21 G90\nN20 G00 X5.\nN30 M30\n"
    a = write(tmp_path, "a.nc", first + second)
    b = write(tmp_path, "b.nc", first.replace("Y1.\n", "Y1.\nY1.5\n") +
              second.replace("X5.", "X6."))
    found, summary = differences(a, b, pair="number")
    assert [(d.kind, d.a.line if d.a else None, d.b.line if d.b else None) for d in found] == [
        ("added", None, 4), ("changed", 7, 8)]
    assert [w.describe() for w in found[1].words] == ["X5. -> X6. (+1 mm, +1000 steps)"]
    assert (summary.pairing, summary.paired, summary.blocks_a, summary.blocks_b) == (
        "number", 8, 8, 9)
    # a number in one program only is unpaired where its number falls
    c = write(tmp_path, "c.nc", first.replace("N30 X2.", "N25 M08\nN30 X2.") + second)
    found, summary = differences(a, c, pair="number")
    assert [(d.kind, d.b.line, d.b.number) for d in found] == [("added", 5, Decimal(25))]
    found, summary = differences(c, a, pair="number")
    assert [(d.kind, d.a.line) for d in found] == [("removed", 5)]


def test_a_dropped_block_among_many_alike_is_one_removal_not_a_cascade(tmp_path):
    """Pairing by position looks ahead: the blocks after a lost one pair again."""
    moves = [f"X{i}.5 Y{i}." for i in range(1, 40)]
    a = write(tmp_path, "a.nc", "G21 G90\n" + "\n".join(moves) + "\nM30\n")
    b = write(tmp_path, "b.nc", "G21 G90\n" + "\n".join(moves[:20] + moves[21:]) + "\nM30\n")
    found, summary = differences(a, b)
    assert [(d.kind, d.a.line) for d in found] == [("removed", 22)]
    assert summary.pairing == "position" and summary.paired == 40
    found, _ = differences(b, a)
    assert [(d.kind, d.b.line) for d in found] == [("added", 22)]
    # a changed block among them stays one change
    c = write(tmp_path, "c.nc", "G21 G90\n" + "\n".join(moves).replace("X7.5 Y7.", "X7.5 Y7.1")
              + "\nM30\n")
    found, _ = differences(a, c)
    assert [(d.kind, d.a.line, [w.describe() for w in d.words]) for d in found] == [
        ("changed", 8, ["Y7. -> Y7.1 (+0.1 mm, +100 steps)"])]


def test_words_in_another_order_and_comments(tmp_path):
    a = write(tmp_path, "a.nc", "G21\nG90 G01 X1. (ROUGH)\n(TOOL 2)\nM30\n")
    b = write(tmp_path, "b.nc", "G21\nX1. G01 G90 (FINISH)\nM30\n")
    found, _ = differences(a, b)
    assert [(d.kind, d.details() if d.kind == "changed" else d.a.shown) for d in found] == [
        ("changed", ["comments (ROUGH) -> (FINISH)"]), ("removed", "(TOOL 2)")]
    assert differences(a, b, ignore_comments=True)[0] == []
    [order] = differences(a, b, ignore_comments=True, word_order=True)[0]
    assert order.details() == ["words in another order"]


def test_incremental_words_compare_as_positions(tmp_path):
    """In G91 a converter may write an increment a step off to keep the absolute path exact
    (1 mm is 0.03937 in: 0.0394, 0.0393, 0.0394); a step lost on the way is a difference."""
    a = write(tmp_path, "a.nc", "G21 G91\nX1.\nX1.\nX1.\nX1.\nM30\n")
    exact = write(tmp_path, "b.nc", "G20 G91\nX0.0394\nX0.0393\nX0.0394\nX0.0394\nM30\n")
    assert differences(a, exact, tolerance=HALF)[0] == []
    drifting = write(tmp_path, "c.nc", "G20 G91\nX0.0394\nX0.0394\nX0.0394\nX0.0394\nM30\n")
    found, _ = differences(a, drifting, tolerance=HALF)
    assert [(d.a.line, d.words[0].describe()) for d in found] == [  # reported, then afresh
        (3, "X1. -> X0.0394 (+0.00152 mm, +0.598 steps)"),
        (5, "X1. -> X0.0394 (+0.00152 mm, +0.598 steps)")]


def test_motion_says_where_the_machine_goes_once_per_difference(tmp_path):
    a = write(tmp_path, "a.nc", "G21 G91\nG01 X1. F100.\nX1.\nX1.\nG90 X5.\nM30\n")
    b = write(tmp_path, "b.nc", "G21 G91\nG01 X1. F100.\nX1.1\nX1.\nG90 X5.\nM30\n")
    found, _ = differences(a, b, motion=True)
    assert [(d.a.line, d.details()) for d in found] == [
        (3, ["X1. -> X1.1 (+0.1 mm, +100 steps)", "then position X 2 mm -> 2.1 mm"])]
    # the same words, but one program moves in G91: the modal state differs from there on
    c = write(tmp_path, "c.nc", "G21 G90\nG01 X1. F100.\nG91\nX1.\nM30\n")
    d = write(tmp_path, "d.nc", "G21 G90\nG01 X1. F100.\nG90\nX1.\nM30\n")
    found, _ = differences(c, d, motion=True)
    assert found[0].details() == ["G91 -> G90", "then incremental yes -> no"]
    assert found[1].details() == ["then incremental yes -> no, position X 2 mm -> 1 mm"]


def test_motion_follows_a_fanuc_cycle_s_repeat_count(tmp_path):
    """Review 54, F1, in the modal state's own reading: a FANUC mill's K is the canned cycle's
    number of repeats (0i-MF, "Canned cycle"); written without a point (`K3`) it is three
    holes, not the 0.003 K's least increments read. Under G91 the holes step X three times:
    the motion after the block is followed, not lost (before: no position after it)."""
    head = "%\nO2014\nG21 G17 G40 G80 G90\nG54 G00 X0 Y0 S2000 M03\nG43 H01 Z5.\n"
    tail = "G90 G80\nG00 Y20.\nM30\n%\n"
    a = write(tmp_path, "a.nc", head + "G91 G99 G81 X10. Z-5. R-3. K3 F100.\n" + tail)
    b = write(tmp_path, "b.nc", head + "G91 G99 G81 X20. Z-5. R-3. K3 F100.\n" + tail)
    found, _ = differences(a, b, motion=True)
    assert [(d.a.line, d.details()) for d in found] == [
        (6, ["X10. -> X20. (+10 mm, +10000 steps)", "then position X 30 mm -> 60 mm"])]


def test_a_cycle_s_repeat_count_is_compared_as_a_count(tmp_path):
    """The diff's reader reads a FANUC cycle's K as the count it is (0i-MF, "Canned cycle"),
    whole, as the checker and the converter read it: `K3` against `K4` is one repeat more, a
    count compared exactly, as a code's argument is. No tolerance accepts it (a tolerance is in
    steps of a length's format, which count no holes), and no steps are said (review 55a, F5:
    "+1, +1000 steps", and "largest difference: K 1000 steps")."""
    head = "%\nO2014\nG21 G17 G90\nG54 G00 X0 Y0 S2000 M03\n"
    a = write(tmp_path, "a.nc", head + "G91 G99 G81 X10. Z-5. R-3. K3 F100.\nG80\nM30\n%\n")
    b = write(tmp_path, "b.nc", head + "G91 G99 G81 X10. Z-5. R-3. K4 F100.\nG80\nM30\n%\n")
    for tolerance in (Decimal(1), Decimal(1000)):
        found, summary = differences(a, b, tolerance=tolerance)
        assert [(d.a.line, d.details()) for d in found] == [(5, ["K3 -> K4"])]
        assert [c.steps for c in found[0].words] == [None] and summary.largest == {}
    assert differences(a, a)[0] == []
    # a hole-position block repeating the cycle counts by its K too (review 55a's k3.nc)
    c = write(tmp_path, "c.nc", head + "G91 G99 G81 X10. Z-5. R-3. K3 F100.\nX10. K3\n"
              "G80\nM30\n%\n")
    d = write(tmp_path, "d.nc", head + "G91 G99 G81 X10. Z-5. R-3. K3 F100.\nX10. K4\n"
              "G80\nM30\n%\n")
    result = run("diff", "-p", "fanuc-mill", "--tolerance", "1", c, d)
    assert result.exit_code == 1, result.output
    lines = result.output.splitlines()
    assert lines[:3] == [f"{c}:6: changed: X10. K3", f"{d}:6:     is: X10. K4", "    K3 -> K4"]
    assert lines[3] == f"{c} and {d} differ: 1 block changed (9 blocks paired by position)"
    result = run("diff", "-p", "fanuc-mill", "--format", "json", c, d)
    [word] = json.loads(result.output)["differences"][0]["words"]
    assert word == {"kind": "changed", "address": "K", "a": "K3", "a_value": "3", "b": "K4",
                    "b_value": "4"}


def test_a_fanuc_k_is_one_count_for_the_words_and_the_motion(tmp_path):
    """Review 56a, F3 and F8: a FANUC's G73/G83 has no I or J peck words (0i-MF, 30i-MB: X Y Z
    R Q F K), so its K is the repeat count whether or not the block writes them, and with a
    point too (`K3.` three holes, as the checker counts it): `diff --motion` compares it as a
    count, exactly and without steps, and follows as many holes. On a Haas the G83's K is the
    least peck depth, a length in steps of K's format, and counts no holes (its count is L)."""
    head = "%\nO2020\nG21 G17 G90 G54\nG00 X0 Y0 Z5. S1000 M03\n"
    block = "G91 G99 G83 X10. Z-5. R-3. I1. J0.5 K{} F100.\n"
    tail = "G90 G80\nM30\n%\n"
    for two, three in (("2", "3"), ("2.", "3.")):
        a = write(tmp_path, "a.nc", head + block.format(two) + tail)
        b = write(tmp_path, "b.nc", head + block.format(three) + tail)
        for tolerance in (Decimal(0), Decimal(1000)):
            found, _ = differences(a, b, motion=True, tolerance=tolerance)
            assert [(d.a.line, d.details()) for d in found] == [
                (5, [f"K{two} -> K{three}", "then position X 20 mm -> 30 mm"])]
            assert [c.steps for c in found[0].words] == [None]
        # without I and J alike
        c = write(tmp_path, "c.nc", head + block.format(two).replace(" I1. J0.5", "") + tail)
        d = write(tmp_path, "d.nc", head + block.format(three).replace(" I1. J0.5", "") + tail)
        found, _ = differences(c, d, motion=True)
        assert [(d.a.line, d.details()) for d in found] == [
            (5, [f"K{two} -> K{three}", "then position X 20 mm -> 30 mm"])]
    haas = ("%\nO2020\nG20 G17 G90 G54\nG00 X0 Y0 Z0.2 S1000 M03\n"
            "G91 G99 G83 X1. Z-0.2 R-0.1 I0.1 J0.02 K{} F10.\nG90 G80\nM30\n%\n")
    a = write(tmp_path, "ha.nc", haas.format("0.05"))
    b = write(tmp_path, "hb.nc", haas.format("0.06"))
    haas_mill = load_profile("haas-mill")
    found, _ = differences(a, b, haas_mill, haas_mill, motion=True)
    assert [(d.a.line, d.details()) for d in found] == [
        (5, ["K0.05 -> K0.06 (+0.254 mm, +100 steps)"])]


def test_a_drilling_cycle_s_dwell_is_compared_as_a_time(tmp_path):
    """Review 56a, F5: a drilling cycle's dwell P (FANUC `G82 ... P500`, 500 ms) is a time,
    compared as G04's P is, in seconds and within the tolerance; LinuxCNC G76's Q (the compound
    slide angle) and R (the depth degression) are numbers within the tolerance too. A true
    count stays exact: G76's H (spring passes), a repeat count (test above)."""
    head = "%\nO2002\nG21 G90 G17\nG00 X0. Y0. Z50.\nS1200 M03\n"
    for block in ("G99 G82 X10. Y0. Z-5. R3. P{} F100.", "G04 P{}"):
        a = write(tmp_path, "a.nc", head + block.format(500) + "\nG80\nM30\n%\n")
        b = write(tmp_path, "b.nc", head + block.format(501) + "\nG80\nM30\n%\n")
        found, _ = differences(a, b)
        assert [d.details() for d in found] == [["P500 -> P501 (+0.001, +1 step)"]], block
        assert differences(a, b, tolerance=Decimal(1))[0] == []
    thread = "G21 G18 G90\nG0 X10 Z5\nG76 P1.5 Z-20 I-0.5 J0.2 K1.0 R1.5 Q{} H{} E0.5 L2\nM2\n"
    a = write(tmp_path, "a.ngc", thread.format("29.5", 2))
    b = write(tmp_path, "b.ngc", thread.format("29.5001", 2))
    c = write(tmp_path, "c.ngc", thread.format("29.5", 3))
    linuxcnc = load_profile("linuxcnc")
    found, _ = differences(a, b, linuxcnc, linuxcnc)
    assert [d.details() for d in found] == [["Q29.5 -> Q29.5001 (+0.0001, +100 steps)"]]
    assert differences(a, b, linuxcnc, linuxcnc, tolerance=Decimal(100))[0] == []
    found, _ = differences(a, c, linuxcnc, linuxcnc, tolerance=Decimal(1000))
    assert [d.details() for d in found] == [["H2 -> H3"]]


# (profile, the program with {} where the word goes, the word in A, the word in B, the
# difference as the diff says it, and the tolerance within which it is the same program)
MEASURES = [
    # a lathe's thread start angle, 0.001 deg without a point (FANUC 0i-TF G32/G92 Q; Haas
    # lathe G32 and G92 Q, "thread start angle"), compared in degrees
    ("fanuc-lathe", "G21 G18 G99\nG00 X30. Z5. S500 M03\nG32 Z-20. F1.5 {}", "Q60000", "Q60001",
     "Q60000 -> Q60001 (+0.001, +1 step)", 1),
    ("fanuc-lathe", "G21 G18 G99\nG00 X30. Z5. S500 M03\nG92 X28. Z-20. F1.5 {}", "Q90000",
     "Q90002", "Q90000 -> Q90002 (+0.002, +2 steps)", 2),
    ("haas-lathe", "G20 G18 G99\nG00 X1. Z0.2 S500 M03\nG92 X0.9 Z-1. F0.0625 {}", "Q180000",
     "Q180001", "Q180000 -> Q180001 (+0.001, +1 step)", 1),
    # Haas lathe G76: A the tool nose angle in degrees, Q the start angle, neither with a point
    ("haas-lathe", "G20 G18 G99\nG00 X1. Z0.2 S500 M03\nG76 X0.9 Z-1. K0.05 D0.01 F0.0625 {} P2",
     "A60", "A59", "A60 -> A59 (-1, -1 step)", 1),
    ("haas-lathe", "G20 G18 G99\nG00 X1. Z0.2 S500 M03\nG76 X0.9 Z-1. K0.05 D0.01 F0.0625 A60 {}",
     "Q45000", "Q45001", "Q45000 -> Q45001 (+0.001, +1 step)", 1),
    # a Haas lathe's G199 R: the secondary spindle's phase angle, degrees, stepped by the
    # angles' 0.001 deg in G20 and G21 alike (review 57a F5: 0.0001 in G20)
    ("haas-lathe", "G20 G18 G99\nG199 {}", "R30.", "R30.5", "R30. -> R30.5 (+0.5, +500 steps)",
     500),
    ("haas-lathe", "G21 G18 G99\nG199 {}", "R30.", "R30.004", "R30. -> R30.004 (+0.004, +4 steps)",
     4),
    # a modal G92's next pass: its Q the start angle as the G92 block's (review 57a F4)
    ("fanuc-lathe", "G21 G18 G99\nG00 X30. Z5. S500 M03\nG92 X28. Z-20. F1.5 Q0\nX27.5 {}",
     "Q90000", "Q90002", "Q90000 -> Q90002 (+0.002, +2 steps)", 2),
    ("haas-lathe", "G20 G18 G99\nG00 X1. Z0.2 S500 M03\nG32 Z-1. F0.0625 Q0\nZ-1.5 {}",
     "Q180000", "Q180001", "Q180000 -> Q180001 (+0.001, +1 step)", 1),
    # a mill's and a lathe's drilling cycles' dwell P, milliseconds (FANUC, Haas)
    ("fanuc-mill", "G21 G17 G90\nG00 X0 Y0 Z50. S1200 M03\nG99 G76 X10. Z-5. R3. Q0.5 {} F100.",
     "P300", "P302", "P300 -> P302 (+0.002, +2 steps)", 2),
    ("haas-mill", "G20 G17 G90\nG00 X0 Y0 Z2. S1200 M03\nG99 G89 X1. Z-0.5 R0.1 {} F10.",
     "P300", "P301", "P300 -> P301 (+0.001, +1 step)", 1),
    ("fanuc-lathe", "G21 G18 G99\nG00 X0 Z5. S500 M03\nG83 Z-20. R-2. Q5000 {} F0.1",
     "P500", "P501", "P500 -> P501 (+0.001, +1 step)", 1),
]

# counts, block numbers and selectors of the same tables: exact at any tolerance
COUNTS = [
    ("fanuc-lathe", "G21 G18 G99\nG00 X30. Z5. S500 M03\nG71 U2. R1.\nG71 {} Q20 U0.5 W0.1 F0.2"
     "\nN10 G00 X20.\nN20 G01 Z-20.", "P10", "P11", "P10 -> P11"),
    ("fanuc-lathe", "G21 G18 G99\nG00 X30. Z5. S500 M03\nG76 {} Q100 R0.05", "P021060",
     "P021055", "P021060 -> P021055"),  # m, r, a packed as digits
    ("haas-lathe", "G20 G18 G99\nG00 X1. Z0.2 S500 M03\nG76 X0.9 Z-1. K0.05 D0.01 F0.0625 A60 {}",
     "P2", "P3", "P2 -> P3"),  # the infeed method
    ("fanuc-mill", "G21 G17 G90\nG00 X0 Y0 Z5. S1000 M03\nG91 G99 G81 X10. Z-5. R-3. {} F100.",
     "K3", "K4", "K3 -> K4"),
    ("haas-mill", "G20 G17 G90\nG00 X0 Y0 Z1. S1000 M03\nG99 G84 X1. Z-0.5 R0.1 {} F10.",
     "J2", "J3", "J2 -> J3"),  # the retract multiple
    # a block's own G10 or G65 under a modal dwell cycle: its P is the offset's number, the
    # macro's program, not the cycle's dwell (review 57a F1)
    ("fanuc-mill", "G21 G17 G90\nG00 X0 Y0 Z5. S1000 M03\nG82 X10. Y10. Z-5. R2. P500 F100."
     "\nG10 L2 {} X0 Y0 Z0\nX20. Y10.", "P1", "P2", "P1 -> P2"),
    ("fanuc-mill", "G21 G17 G90\nG00 X0 Y0 Z5. S1000 M03\nG82 X10. Y10. Z-5. R2. P500 F100."
     "\nG65 {} A1.\nX20. Y10.", "P9000", "P9001", "P9000 -> P9001"),
]


@pytest.mark.parametrize(("profile", "body", "a", "b", "said", "within"), MEASURES)
def test_a_cycle_word_that_measures_is_compared_within_the_tolerance(
        tmp_path, profile, body, a, b, said, within):
    """Issue 32 (review 56a F5 for every cycle table): a cycle's word that is an angle, a time
    or a ratio is compared as a measure, in steps of its own unit and within --tolerance, where
    it was compared exactly as a count: a thread's start angle Q in 0.001 deg, Haas G76's tool
    nose angle A in degrees (read whole, as the control and the checker read it, one step of its
    last digit, not of the axis format's 0.001), the G199 phase angle, a dwell P."""
    program = "%\nO1\n" + body + "\nG80\nM30\n%\n"
    one = write(tmp_path, "a.nc", program.format(a))
    two = write(tmp_path, "b.nc", program.format(b))
    p = load_profile(profile)
    found, _ = differences(one, two, p, p)
    assert [d.details() for d in found] == [[said]]
    assert differences(one, two, p, p, tolerance=Decimal(within))[0] == []
    assert differences(one, two, p, p, tolerance=Decimal(within) - Decimal("0.5"))[0] != []
    result = run("diff", "-p", profile, "--format", "json", one, two)
    [word] = json.loads(result.output)["differences"][0]["words"]
    assert word["steps"] is not None and result.exit_code == 1


def test_a_thread_start_angle_with_a_point_is_compared_as_written(tmp_path):
    """A start angle with a point (`Q60.`) is no reading the manuals give (the checker's
    TG208: 60 deg or an alarm): compared as written, never the same as `Q60000` at any
    tolerance, and the same as its own text."""
    program = "%\nO1\nG21 G18 G99\nG00 X30. Z5. S500 M03\nG32 Z-20. F1.5 {}\nM30\n%\n"
    one = write(tmp_path, "a.nc", program.format("Q60000"))
    two = write(tmp_path, "b.nc", program.format("Q60."))
    lathe = load_profile("fanuc-lathe")
    found, _ = differences(one, two, lathe, lathe, tolerance=Decimal(100000))
    assert [d.details() for d in found] == [["Q60000 -> Q60."]]
    assert differences(two, two, lathe, lathe)[0] == []


def test_a_modal_thread_s_next_pass_reads_its_start_angle_as_the_thread_s(tmp_path):
    """Review 57a F4: under a modal G92 (or G32), a block naming no code of the motion group
    is the cycle's next pass (FANUC 0i-TF "Threading cycle (G92)"), its Q the start angle in
    0.001 deg as the G92 block's: `Q90.` (with a point, TG208's) is not `Q90` (0.09 deg), the
    checker says TG208 at the pass's Q, and a change of units keeps Q180000 as written (it
    was refused as a digit overflow of Q's length format)."""
    from formats.convert import convert_text
    program = ("%\nO1\nG21 G18 G99\nG00 X30. Z5. S500 M03\nG92 X24. Z-25. F1.5 Q0\n"
               "X23.5 Q0\nX24. {}\nG00 X100. Z100.\nM30\n%\n")
    one = write(tmp_path, "a.nc", program.format("Q90."))
    two = write(tmp_path, "b.nc", program.format("Q90"))
    lathe = load_profile("fanuc-lathe")
    found, _ = differences(one, two, lathe, lathe, tolerance=Decimal(100000))
    assert [d.details() for d in found] == [["Q90. -> Q90"]]
    found = [(f.rule, f.line, f.column, f.severity)
             for f in check_text(program.format("Q90."), lathe) if f.rule == "TG208"]
    assert found == [("TG208", 7, 6, "warning")]
    out, _ = convert_text(program.format("Q180000"),
                          ConvertOptions(target=lathe, source=lathe, units="inch"))
    assert out.splitlines()[6] == "X0.9449 Q180000", out


# a block straight after a G92 (G32) pass that names a code of its own reading Q: not a pass
# (review 58b): G74/G75/G76's Q are depths in least input increments of length, G65's Q the
# macro's argument #17, a G83's repeat's Q its peck
OWN_Q = [
    ("fanuc-lathe", "G92 X24. Z-20. F1.5 Q0\nX23.5 Q90000\n",
     "G75 R0.5\nG75 X30. Z-20. P2000 Q3000 F0.1\nG74 R0.5\nG74 Z-30. Q5000 F0.1\n"
     "G76 P011060 Q100 R0.05\nG76 X22.2 Z-20. P900 Q300 F1.5\n",
     ["X0.9252 Q90000", "G75 R0.0197", "G75 X1.1811 Z-0.7874 P787 Q1181 F0.0039",
      "G74 R0.0197", "G74 Z-1.1811 Q1969 F0.0039", "G76 P011060 Q39 R0.002",
      "G76 X0.874 Z-0.7874 P354 Q118 F0.0591"]),
    ("fanuc-lathe", "G32 Z-20. F1.5\n",
     "G76 P011060 Q100 R0.05\nG76 X22.2 Z-20. P900 Q0.3 F1.5\n",
     ["G76 P011060 Q39 R0.002", "G76 X0.874 Z-0.7874 P354 Q0.0118 F0.0591"]),
    # G code system B: G78 is A's G92
    ("fanuc-lathe-b", "G78 X24. Z-20. F1.5 Q0\n",
     "G76 P011060 Q100 R0.05\nG76 X22.2 Z-20. P900 Q300 F1.5\n",
     ["G76 P011060 Q39 R0.002", "G76 X0.874 Z-0.7874 P354 Q118 F0.0591"]),
]


@pytest.mark.parametrize(("name", "thread", "after", "converted"), OWN_Q)
def test_a_cycle_after_a_thread_pass_reads_its_own_q(tmp_path, name, thread, after, converted):
    """Review 58b F2: a G74/G75/G76 block straight after a G92 (G32) pass is the cycle's own
    (group 00, FANUC 0i-TF "Multiple repetitive cycle"), not the thread's next pass: a change
    of units converts its Q depths, and the diff tells the unconverted Q from the source's."""
    from formats.convert import convert_text
    profile = load_profile(name)
    program = ("O1014\nG21 G18 G99\nG97 S500 M03\nG00 X24. Z5.\n" + thread + after
               + "G00 X50.\nM30\n")
    out, _ = convert_text(program, ConvertOptions(target=profile, source=profile, units="inch"))
    lines = out.splitlines()
    assert lines[-2 - len(converted):-2] == converted, out
    right = write(tmp_path, "right.nc", out)
    source = write(tmp_path, "source.nc", program)
    assert differences(source, right, profile, profile, tolerance=Decimal("0.5"))[0] == []
    # the Q depths left as written (the reading this replaced) are another program
    wrong = write(tmp_path, "wrong.nc", out.replace("Q118 ", "Q300 ").replace("Q0.0118", "Q0.3"))
    found, _ = differences(source, wrong, profile, profile, tolerance=Decimal("0.5"))
    assert len(found) == 1 and "Q" in found[0].details()[0], found


def test_a_code_of_its_own_after_a_thread_pass_is_no_pass():
    """Review 58b F1, F7: a G65's Q (macro argument #17) and a G83's repeat's Q after a G92
    pass are no thread's start angle: no TG208 "a thread's start angle" there, while the
    pass's own pointed Q has it."""
    lathe = load_profile("fanuc-lathe")
    program = ("O1\nG21 G18 G99\nG00 X30. Z5. S500 M03\nG92 X24. Z-20. F1.5 Q0\nX23.5 Q90.\n"
               "G65 P9010 A1. Q5. X2.\nG83 X0 Z-20. R1. Q5000 F0.1\nZ-25. Q4000.\nM30\n")
    found = [(f.rule, f.line, f.column) for f in check_text(program, lathe)
             if f.rule == "TG208" and "start angle" in f.message]
    assert found == [("TG208", 5, 7)]


# a lathe's thread is of group 01, G80 of group 10 (FANUC 0i-TF "G code list"): a plain pass
# after G80 (or after a drilling cycle and its G80) is the thread's, its Q the start angle
THREAD_AFTER_G80 = [
    ("G80\n", 7),
    ("G83 X0 Z-20. R1. Q5000 F0.1\nZ-25. Q4000\nG80\n", 9),
]


@pytest.mark.parametrize(("between", "line"), THREAD_AFTER_G80)
def test_a_thread_stays_in_force_through_g80(tmp_path, between, line):
    """Review 58b F8: G80 ends the drilling cycles (group 10), not the threading G92 (group 01):
    the checker, the converter and the diff read `X23.5 Q180000` after it as the thread's next
    pass (its Q kept as written under a change of units; it was refused as a digit overflow of
    a Q of no role) and `X23.4 Q90.` as a pointed start angle (TG208)."""
    from formats.convert import convert_text
    lathe = load_profile("fanuc-lathe")
    program = ("O1023\nG21 G18 G99\nG97 S500 M03\nG00 X30. Z5.\nG92 X24. Z-20. F1.5 Q0\n"
               + between + "X23.5 Q180000\nX23.4 Q90.\nG00 X30.\nM30\n")
    found = [(f.rule, f.line, f.column) for f in check_text(program, lathe)
             if f.rule in ("TG205", "TG208")]
    assert found == [("TG208", line + 1, 7)]
    out, _ = convert_text(program, ConvertOptions(target=lathe, source=lathe, units="inch"))
    lines = out.splitlines()
    assert lines[line - 1:line + 1] == ["X0.9252 Q180000", "X0.9213 Q90."], out
    source = write(tmp_path, "source.nc", program)
    right = write(tmp_path, "right.nc", out)
    assert differences(source, right, lathe, lathe, tolerance=HALF)[0] == []
    # a start angle changed after G80 is a difference, not a Q of no role compared in steps
    wrong = write(tmp_path, "wrong.nc", out.replace("Q180000", "Q180001"))
    found, _ = differences(source, wrong, lathe, lathe, tolerance=HALF)
    assert [(d.b.line, d.details()) for d in found] == [
        (line, ["Q180000 -> Q180001 (+0.001, +1 step)"])]


# a FANUC or Haas dwell's P with a point is seconds, without one milliseconds (the Haas NGC
# manuals, G04): a pointed P steps by a millisecond
POINTED_DWELLS = [
    ("haas-mill", "G04 P{}\n", 4, True),
    ("haas-mill", "G99 G82 X1. Y1. Z-0.5 R0.1 P0.5 F10.\nX2. P{}\nG80\n", 5, True),
    ("haas-lathe", "G04 P{}\n", 4, True),
    ("haas-lathe", "G00 X0 Z5.\nG83 Z-10. R1. Q2. P0.5 F0.1\nZ-12. P{}\nG80\n", 6, True),
    # an Okuma's P05 (a dwell word there, its unit without a point in no source at hand)
    ("okuma-mill", "G04 P{}\n", 4, False),
    ("okuma-lathe", "G04 P{}\n", 4, False),
]


@pytest.mark.parametrize(("name", "body", "line", "milliseconds"), POINTED_DWELLS)
def test_a_pointed_dwell_p_steps_by_a_millisecond(tmp_path, name, body, line, milliseconds):
    """Review 58b F4: `P0.5` and `P0.9` are 0.4 s apart, 400 steps of a millisecond, the unit
    a FANUC or Haas P counts without its point (it stepped by a second of the whole-number
    format, and `--tolerance 0.5` called them the same program); `P0.5` and `P500` are the
    same time there, and not on an Okuma."""
    profile = load_profile(name)
    program = "O1\nG21 G90\nT1 M06\n" + body + "M30\n"
    one = write(tmp_path, "a.nc", program.format("0.5"))
    found, _ = differences(one, write(tmp_path, "b.nc", program.format("0.9")),
                           profile, profile, tolerance=HALF)
    assert [(d.a.line, d.details()) for d in found] == [
        (line, ["P0.5 -> P0.9 (+0.4, +400 steps)"])]
    found, _ = differences(one, write(tmp_path, "c.nc", program.format("0.502")),
                           profile, profile, tolerance=HALF)
    assert [[c.steps for c in d.words] for d in found] == [[2]]
    found, _ = differences(one, write(tmp_path, "d.nc", program.format("500")),
                           profile, profile, tolerance=HALF)
    assert (found == []) == milliseconds


# a dwell whose letter's format is a whole number's, read whole without a point: an Okuma's
# P (seconds), a CM332's F, a SINUMERIK's S (revolutions)
WHOLE_DWELLS = [
    ("okuma-mill", "G21 G90\nG04 P{}\n", "P"),
    ("okuma-lathe", "G21 G90\nG04 P{}\n", "P"),
    ("cm332-quadrant", "G21 G90\nG04 F{}\n", "F"),
    ("sinumerik-840d", "G71 G90\nG4 S{}\n", "S"),
]


@pytest.mark.parametrize(("name", "body", "letter"), WHOLE_DWELLS)
def test_a_dwell_pointed_on_one_side_only_differs_in_both_orders(tmp_path, name, body, letter):
    """Review 59c F4: a pair was stepped by its second word alone, so `P5.4` against `P5`
    was 0.4 steps of a second (the same program at `--tolerance 0.5`) and `P5` against
    `P5.4` 400 steps; an unpointed time of a whole-number format steps by the millisecond
    too, so the 0.4 s (or revolutions) is 400 steps either way, and `P5` against `P6` 1000."""
    profile = load_profile(name)
    pointed = write(tmp_path, "a.nc", body.format("5.4"))
    whole = write(tmp_path, "b.nc", body.format("5"))
    for one, two, said in ((pointed, whole, "5.4 -> {0}5 (-0.4, -400 steps)"),
                           (whole, pointed, "5 -> {0}5.4 (+0.4, +400 steps)")):
        found, _ = differences(one, two, profile, profile, tolerance=HALF)
        assert [(d.a.line, d.details()) for d in found] == [
            (2, [letter + said.format(letter)])]
    found, _ = differences(whole, write(tmp_path, "c.nc", body.format("6")), profile, profile,
                           tolerance=HALF)
    assert [[c.steps for c in d.words] for d in found] == [[1000]]
    found, _ = differences(whole, write(tmp_path, "d.nc", body.format("5.")), profile, profile,
                           tolerance=HALF)
    assert found == []


@pytest.mark.parametrize(("profile", "body", "a", "b", "said"), COUNTS)
def test_a_cycle_word_that_counts_stays_exact(tmp_path, profile, body, a, b, said):
    """Issue 32: a count of the same tables (K repeats, G71's P Q block numbers, FANUC G76's
    packed P, Haas G76's P infeed method, Haas G84's J retract multiple) has no steps and is
    a difference at any tolerance."""
    program = "%\nO1\n" + body + "\nG80\nM30\n%\n"
    one = write(tmp_path, "a.nc", program.format(a))
    two = write(tmp_path, "b.nc", program.format(b))
    p = load_profile(profile)
    found, _ = differences(one, two, p, p, tolerance=Decimal(100000))
    assert [d.details() for d in found] == [[said]]
    assert [c.steps for c in found[0].words] == [None]


# -- errors and the command line ----------------------------------------------------------------


def test_exit_codes_and_a_bad_block_located(tmp_path):
    a = write(tmp_path, "a.nc", PROGRAM)
    assert run("diff", a, a).exit_code == 0
    b = write(tmp_path, "b.nc", PROGRAM.replace("X12.7", "X12.8"))
    result = run("diff", a, b, "-p", "fanuc-mill")
    assert result.exit_code == 1
    assert result.output.splitlines()[-1] == (
        f"{a} and {b} differ: 1 block changed (7 blocks paired by number); largest "
        "difference: X 100 steps")
    bad = write(tmp_path, "bad.nc", "N1 G21\nN2 X@1.\n")
    result = run("diff", a, bad, "-p", "fanuc-mill")
    assert result.exit_code == 2
    assert f"{bad}:2:5: address X must be followed by a number" in result.output
    assert "Traceback" not in result.output
    assert run("diff", a, str(tmp_path / "none.nc")).exit_code == 2
    assert run("diff", a, a, "--tolerance", "-1").exit_code == 2
    with pytest.raises(DiffError) as err:  # a number the format cannot read: its column
        differences(a, write(tmp_path, "long.nc", "N1 X1" + "1" * 40 + ".\n"))
    assert (err.value.line, err.value.column) == (1, 4)
    assert (err.value.code, err.value.clause) == ("diff-number", "Annex C")


def test_json_output_shape(tmp_path):
    a = write(tmp_path, "a.nc", PROGRAM)
    b = write(tmp_path, "b.nc", PROGRAM.replace("X12.7", "X12.701").replace("N40 M30", "N40 M02"))
    result = run("diff", a, b, "--from", "fanuc-mill", "-p", "fanuc-mill", "--format", "json")
    assert result.exit_code == 1
    data = json.loads(result.output)
    assert data["a"] == {"file": a, "profile": "fanuc-mill"}
    assert data["summary"] == {"same": False, "pairing": "number", "blocks_a": 7, "blocks_b": 7,
                               "paired": 7, "changed": 2, "added": 0, "removed": 0,
                               "largest_steps": {"X": "1"}}
    first, second = data["differences"]
    assert first == {"kind": "changed",
                     "a": {"line": 5, "text": "N30 X12.7 (CUT)", "number": "30"},
                     "b": {"line": 5, "text": "N30 X12.701 (CUT)", "number": "30"},
                     "words": [{"kind": "changed", "address": "X", "a": "X12.7", "a_value": "12.7",
                                "b": "X12.701", "b_value": "12.701", "unit": "mm",
                                "difference": "0.001", "steps": "1", "step": "0.001"}]}
    assert second["words"] == [{"kind": "changed", "address": "M", "a": "M30", "a_value": "30",
                                "b": "M02", "b_value": "2"}]


def test_without_a_profile_each_program_is_detected_and_said(tmp_path):
    a = write(tmp_path, "a.nc", "G71\nX25.4\n")
    b = write(tmp_path, "b.nc", "G70\nX1.\n")
    result = CliRunner().invoke(main, ["diff", a, b])
    assert result.exit_code == 0, result.output
    assert f"{b}: the neutral profile; units codes G70/G71 (G70 found)" in result.output


def test_without_a_profile_a_lost_decimal_point_is_no_same_program(tmp_path):
    """`X10.` and `X10` are the same number where a number without a point is whole (ISO
    6983-1, the neutral profile), 1000 times apart on a FANUC (X10 is 0.010 mm): the default
    does not say "the same program" and exit 0 on it, it shows the FANUC reading's
    differences and exits 1; a profile that names the machine decides."""
    head = "%\nO1002\nG21 G17 G90\nG01 X0 Y0 Z5. F100.\n"
    a = write(tmp_path, "a.nc", head + "G00 X10. Y10.\nG01 Z-2.\nM30\n%\n")
    b = write(tmp_path, "b.nc", head + "G00 X10 Y10\nG01 Z-2.\nM30\n%\n")
    result = CliRunner().invoke(main, ["diff", a, b])
    assert result.exit_code == 1, result.output
    assert "are the same program" in result.stdout  # under the neutral reading
    assert "X10. -> X10 (-9.99 mm, -9990 steps)" in result.stdout
    assert "reads it in least input increments (FANUC, Haas, Okuma" in result.stderr
    assert CliRunner().invoke(main, ["diff", a, b, "-p", "fanuc-mill"]).exit_code == 1
    assert CliRunner().invoke(main, ["diff", a, b, "-p", "iso-mill"]).exit_code == 0
    # a real difference under either reading is said once, as ever; the same text is the same
    assert CliRunner().invoke(main, ["diff", a, a]).exit_code == 0
    json_run = CliRunner().invoke(main, ["diff", a, b, "--format", "json"])
    assert json_run.exit_code == 1 and "least input increments" in json_run.stderr
    assert json.loads(json_run.stdout)["summary"]["same"]  # the neutral reading's, as asked


# -- verification that can fail -------------------------------------------------------------------


def _converted(tmp_path: Path, text: str, options: ConvertOptions):
    src = write(tmp_path, "src.nc", text)
    out = str(tmp_path / "out.nc")
    stats = convert_file(src, out, options)
    return src, out, stats


SOURCE = ("%\nO2000\nN1 G21 G90 G94\nN2 G01 X25.4 Y-12.7 F254.\nN3 G91 X1.\nN4 X1.\nN5 X1.\n"
          "N6 G90 X10.\nN7 M30\n%\n")


@pytest.mark.parametrize(("label", "alter", "message"), [
    ("a hand-altered value", lambda t: t.replace("Y-0.5", "Y-0.6"),
     "Y-12.7 converts to -0.5 but the output Y-0.6 reads -0.6"),
    ("one step off", lambda t: t.replace("X0.3937", "X0.3938"),
     "X10. converts to 0.393701 but the output X0.3938 reads 0.3938"),
    ("a step lost along an incremental path", lambda t: t.replace("N4 X0.0393", "N4 X0.0394"),
     "X1. converts to 0.0393701 but the output X0.0394 reads 0.0394"),
    ("a dropped block", lambda t: t.replace("N5 X0.0394\n", ""), "N5 X1."),
    ("the units code left metric", lambda t: t.replace("G20", "G21"),
     "X25.4 converts to 25.4 but the output X1. reads 1"),
    ("a word dropped", lambda t: t.replace(" F10.", ""), "F254. removed"),
    ("words reordered", lambda t: t.replace("G01 X1. Y-0.5", "Y-0.5 G01 X1."),
     "words in another order"),
])
def test_verify_catches_a_wrong_conversion(tmp_path, label, alter, message):
    options = ConvertOptions(FANUC, FANUC, units="inch")
    src, out, stats = _converted(tmp_path, SOURCE, options)
    good = Path(out).read_text()
    assert "N3 G91 X0.0394\nN4 X0.0393\nN5 X0.0394\n" in good  # the exact absolute path
    verify_conversion(src, out, FANUC, options, stats, file="src.nc")  # the real one holds
    Path(out).write_text(alter(good))
    assert Path(out).read_text() != good, label
    with pytest.raises(ConversionError) as err:
        verify_conversion(src, out, FANUC, options, stats, file="src.nc")
    assert (err.value.code, err.value.clause, err.value.file) == ("conversion-verify", "verify",
                                                                   "src.nc")
    assert message in err.value.message  # the word and the values compared: no field has them


LATHE = load_profile("fanuc-lathe")
TURNING = ("%\nO3000\nN10 G21 G99\nN20 T0101\nN30 G00 X30. Z2.\nN40 G71 U2. R0.5\n"
           "N50 G71 P60 Q80 U0.4 W0.1 F0.25\nN60 G01 X20.\nN70 Z-20.\nN80 X30.\n"
           "N90 G70 P60 Q80\nN100 M30\n%\n")


@pytest.mark.parametrize("units", [None, "inch"])
@pytest.mark.parametrize(("label", "alter", "message"), [
    ("a G code written shorter", lambda t: t.replace("N60 G01", "N60 G1"),
     "G01 is written G1 in the output"),
    ("a tool word losing its zero", lambda t: t.replace("T0101", "T101"),
     "T0101 is written T101 in the output"),
    ("a block number padded", lambda t: t.replace("G70 P60", "G70 P060"),
     "P60 is written P060 in the output"),
    ("a sequence number padded", lambda t: t.replace("N70 ", "N070 "),
     "N70 is written N070 in the output"),
    # (a number of the cycle's table, read whole: compared exactly, as a code's argument)
    ("a P block number changed", lambda t: t.replace("G70 P60", "G70 P61"), "P60 -> P61"),
])
def test_verify_holds_every_unchanged_word_to_its_bytes(tmp_path, units, label, alter, message):
    """A word whose role the conversion does not change (codes, counts, block numbers) keeps
    its text: G1 for G01 is the same value, and still not what the converter may write."""
    options = ConvertOptions(LATHE, LATHE, units=units)
    src, out, stats = _converted(tmp_path, TURNING, options)
    good = Path(out).read_text()
    verify_conversion(src, out, LATHE, options, stats, file="src.nc")
    Path(out).write_text(alter(good))
    assert Path(out).read_text() != good, label
    with pytest.raises(ConversionError) as err:
        verify_conversion(src, out, LATHE, options, stats, file="src.nc")
    assert (err.value.code, err.value.clause, err.value.file) == ("conversion-verify", "verify",
                                                                   "src.nc")
    assert message in err.value.message  # the word and the values compared: no field has them
    line = next(i for i, text in enumerate(TURNING.splitlines(), 1)
                if text != alter(TURNING).splitlines()[i - 1])
    assert err.value.line == line


def test_with_no_change_of_units_or_format_every_word_keeps_its_bytes(tmp_path):
    """Lengths too: X30. written X30.0 is the same value in the same format, and not kept."""
    options = ConvertOptions(LATHE, LATHE)
    src, out, stats = _converted(tmp_path, TURNING, options)
    assert Path(out).read_text() == TURNING
    Path(out).write_text(TURNING.replace("N80 X30.", "N80 X30.0"))
    with pytest.raises(ConversionError) as err:
        verify_conversion(src, out, LATHE, options, stats, file="src.nc")
    assert (err.value.code, err.value.file, err.value.line) == ("conversion-verify", "src.nc", 10)
    # a spelling, not a value, differs: only the wording tells it from a wrong value
    assert "X30. is written X30.0 in the output" in err.value.message
    # tapegate diff compares values: there the two are the same program
    assert differences(src, out, LATHE, LATHE)[0] == []


def test_verify_holds_the_converter_to_the_rounding_it_reported(tmp_path):
    """Within half a step but more than the converter said it rounded: not verified."""
    options = ConvertOptions(FANUC, FANUC, units="inch")
    src, out, stats = _converted(tmp_path, "G21\nX25.4\nM30\n", options)
    assert Fraction(*stats.rounding.get("X", (0, 1))) == 0
    Path(out).write_text("G20\nX1.00004\nM30\n")  # 0.4 of a step, where the rounding was 0
    with pytest.raises(ConversionError) as err:
        verify_conversion(src, out, FANUC, options, stats, file="src.nc")
    assert (err.value.code, err.value.file, err.value.line) == ("conversion-verify", "src.nc", 2)
    # the verify error has no column: the message names the word and both values
    assert "X25.4 converts to 1 but the output X1.00004" in err.value.message


# -- real programs ------------------------------------------------------------------------------


ROUND_TRIP = ["GCodeWorkShop__FANUC0M.nc", "GCodeWorkShop__FANUC0T.nc",
              "cnc-sprayer__fusion-inch.nc", "vip74120.github.io__T.NC"]


@needs_corpus
@pytest.mark.parametrize("name", ROUND_TRIP)
def test_a_real_program_and_its_conversion_are_the_same_program(tmp_path, name):
    [path] = [p for p in corpus_files() if p.name == name]
    there, back = tmp_path / "inch.nc", tmp_path / "back.nc"
    convert_file(str(path), str(there), ConvertOptions(FANUC, FANUC, units="inch"))
    convert_file(str(there), str(back), ConvertOptions(FANUC, FANUC, units="metric"))
    for a, b in ((path, there), (there, back)):
        found, summary = differences(str(a), str(b), tolerance=HALF, motion=True)
        assert found == [] and summary.paired > 5, [d.describe("a", "b") for d in found[:3]]
    # and a single step taken out of the conversion is found, at its line
    text = there.read_text()
    block = next(b for b in parse_text(text, FANUC.dialect)
                 if any(t[0] == "X" and "." in t and "=" not in t for t in b.words))
    word = next(t for t in block.words if t[0] == "X" and "." in t)
    lines = text.splitlines(keepends=True)
    lines[block.line - 1] = lines[block.line - 1].replace(
        word, f"X{Decimal(word[1:]) + Decimal('0.0002')}", 1)
    there.write_text("".join(lines))
    found, _ = differences(str(path), str(there), FANUC, FANUC, tolerance=HALF)
    assert found and found[0].b.line == block.line
    assert any(w.key == "X" and abs(w.steps) > 1 for w in found[0].words)


# -- property: a program and its reformatting compare the same -----------------------------------


values = st.integers(min_value=-99_999_999, max_value=99_999_999)  # in 0.001 mm


def _explicit(units: int, zeros: int) -> str:
    text = str(Decimal(units).scaleb(-3))
    if "." not in text:
        text += "."
    return text + "0" * zeros


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.sampled_from("XYZ"), values, st.integers(0, 2), st.booleans()),
                min_size=1, max_size=12))
def test_a_program_and_its_reformatting_are_the_same(tmp_path_factory, words):
    tmp = tmp_path_factory.mktemp("prop")
    plain, styled = ["G21 G90"], ["G21G90"]
    for i, (letter, units, zeros, increments) in enumerate(words, 1):
        plain.append(f"N{i} G01 {letter}{_explicit(units, 0)}")
        number = str(units) if increments else _explicit(units, zeros)  # Fanuc increments
        styled.append(f"N{i:04d}G1 {letter}{number}")
    a = write(tmp, "a.nc", "\n".join(plain) + "\nM30\n")
    b = write(tmp, "b.nc", "\r\n".join(styled) + "\r\nM30\r\n")
    assert differences(a, b)[0] == []
    assert differences(a, b, pair="position", motion=True)[0] == []


def test_the_modal_state_read_here_is_held_to_the_cores(tmp_path, monkeypatch):
    """The units, distance, feed and spindle modes the comparison reads on its own are checked
    against the core's modal state machine at every block: if they drift apart, it says where."""
    from formats import diff

    text = "G21 G90\nG91 X1.\nX1.\nM30\n"
    real = diff.ProgramReader.block

    def misread(self, block):  # a reading that forgets G91, as a buggy one might
        found = real(self, block)
        self.incremental = False
        return found

    monkeypatch.setattr(diff.ProgramReader, "block", misread)
    options = DiffOptions(motion=True)

    def blocks():  # block by block (diff_files reads the text in the core, not through block)
        reader = ProgramReader(FANUC, file="a.nc", options=options)
        return reader.read(parse_text(text, FANUC.dialect))

    with pytest.raises(DiffError) as err:
        list(Differ(options, FANUC).run(blocks(), blocks()))
    assert (err.value.code, err.value.clause, err.value.file) == ("diff-modal-drift",
                                                                   "modal state", "a.nc")
    assert err.value.line == 3  # the first block read in G90 that the core reads in G91
    # the two modal states are told only in the message (what a bug report needs)
    assert ("(units, distance, feed and spindle modes metric G90 G94 G97) is not the core's "
            "(metric G91") in err.value.message


@pytest.mark.parametrize("target", ["pm322-eia", "linuxcnc", "iso-mill", "sinumerik-7e2"])
def test_verify_across_controls_compares_the_program_not_the_reset_states(tmp_path, target):
    """Each control starts from its own reset state (G00 on a positioning control, G54 on
    LinuxCNC): that is no difference of the program. A P/Q/R word of no stated role is read in
    the role the other profile states (R, a length on fanuc-mill)."""
    profile = load_profile(target)
    options = ConvertOptions(profile, FANUC, units="inch")
    text = "%\nN10 G21 G90\nN20 G01 X25.4 Y-12.7 F254.\nN30 G02 X50.8 R25.4\nN40 M30\n%\n"
    if profile.checks.pqr["R"] != "length":
        # an ISO 6983-1 profile's R is a parameter: its check finds no centre in an arc by R
        # (TG404), so the conversion refuses it (docs/convert.md, "What the target reads"),
        # and the arc is given by its centre
        with pytest.raises(ConversionError) as refused:
            _converted(tmp_path, text, options)
        assert (refused.value.line, refused.value.column) == (4, 15)
        text = text.replace("R25.4", "I12.7 J12.7")
    src, out, stats = _converted(tmp_path, text, options)
    verify_conversion(src, out, FANUC, options, stats, file="src.nc")
    good = Path(out).read_text()
    assert "R1" in good or profile.checks.pqr["R"] != "length"  # R25.4 -> 1 in
    Path(out).write_text(good.replace("Y-", "Y-1"))
    with pytest.raises(ConversionError) as err:
        verify_conversion(src, out, FANUC, options, stats, file="src.nc")
    assert (err.value.code, err.value.file, err.value.line) == ("conversion-verify", "src.nc", 3)
    assert "Y-12.7 converts to -0.5 but the output Y-" in err.value.message  # the values


def test_a_pqr_word_of_no_stated_role_takes_the_role_the_other_profile_states(tmp_path):
    from formats.profile import NEUTRAL, with_units_codes

    a = write(tmp_path, "a.nc", "G21\nG02 X25.4 R25.4\nM30\n")  # neutral: R has no stated role
    b = write(tmp_path, "b.nc", "G20\nG02 X1. R1.\nM30\n")  # fanuc-mill: R is a length
    g21 = with_units_codes(NEUTRAL, "G20", "G21")
    assert differences(a, b, g21, FANUC)[0] == []
    [found] = differences(a, b, g21, FANUC, unstated="written")[0]  # convert
    assert found.details() == ["R25.4 -> R1. (-24.4, -244000 steps)"]  # --allow-unconverted


# -- what the fuzzing found (fuzz/convert_verify.py, fuzz/diff.py; docs/robustness.md) ----------


def _verified(tmp_path: Path, text: str, source: str, target: str, **options):
    """Convert ``text`` with --verify; the output text (ConversionError/DiffError raise)."""
    src = write(tmp_path, "p.nc", text)
    out = str(tmp_path / "o.nc")
    opts = ConvertOptions(load_profile(target), load_profile(source), **options)
    convert_file(src, out, opts, overwrite=True, verify=True, display="p.nc")
    return Path(out).read_text()


def test_a_code_of_five_thousand_leading_zeros_is_read_without_int(tmp_path):
    """Found as ValueError: Exceeds the limit (4300 digits) for integer string conversion."""
    zeros = "0" * 5000
    # (fanuc-mill's G format G031, which holds G54.1, keeps a code as written, as fanuc-lathe's
    # does; the strict ISO format G02 writes it anew)
    assert _verified(tmp_path, f"G{zeros}1 X1.\n", "fanuc-mill", "fanuc-mill") == (
        f"G{zeros}1 X1.\n")
    assert _verified(tmp_path, f"G{zeros}1 X1.\n", "iso-mill", "iso-mill") == "G1 X1.\n"
    a = write(tmp_path, "a.nc", f"G21 G{zeros}91 X1.\nX1.\nM{zeros}30\n")
    b = write(tmp_path, "b.nc", "G21 G91 X1.\nX1.\nM30\n")
    for motion in (False, True):  # G91 as the core reads it: no modal drift
        assert differences(a, b, motion=motion)[0] == []
    c = write(tmp_path, "c.nc", "G21 G91 X1.\nX1.\nM31\n")
    [found] = differences(a, c)[0]
    assert found.details() == [f"M{zeros}30 -> M31"]


def test_lathe_feed_modes_and_reset_state_are_the_cores(tmp_path):
    """Found as 'the modal state read for the comparison (... inch G90 G94 G97) is not the
    core's (inch G90 G95 G97)': a Fanuc lathe resets to G99, feed per revolution."""
    assert _verified(tmp_path, "X0G.0\n", "cm332-quadrant", "fanuc-lathe",
                     units="inch") == "G20 X0G.0\n"
    lathe = load_profile("fanuc-lathe")
    text = ("G21 G98 F254.\nG99 G1 X25.4 F0.254\nG50 S2000\nG96 S152.4\nM30\n"
            "G1 X25.4 F0.254\nG98 F254.\nM30\n")
    inch = _verified(tmp_path, text, "fanuc-lathe", "fanuc-lathe", units="inch")
    assert inch.startswith("G20 G98 F10.\nG99 G1 X1. F0.01\nG50 S2000\nG96 S500\nM30\n")
    a, b = write(tmp_path, "a.nc", text), write(tmp_path, "b.nc", inch)
    assert differences(a, b, lathe, lathe, motion=True)[0] == []
    # G98/G99 are feed modes on a lathe only (a mill's G98/G99 are cycle returns), G50 S is
    # a clamp: read so on both sides, a difference of value is still found
    b2 = write(tmp_path, "b2.nc", inch.replace("F0.01\nG50 S2000", "F0.011\nG50 S2001"))
    found = differences(a, b2, lathe, lathe, tolerance=HALF, motion=True)[0][0]
    assert found.details()[:2] == ["F0.254 -> F0.011 (+0.0254 mm/rev, +10 steps)",
                                   "then feed 0.254 mm/rev -> 0.2794 mm/rev"]
    assert [m.describe() for m in found.motion] == ["feed 0.254 mm/rev -> 0.2794 mm/rev"]
    [limit] = differences(a, b2, lathe, lathe, tolerance=HALF, motion=True)[0][1:]
    assert limit.details()[0] == "S2000 -> S2001 (+1, +1 step)"  # rpm, not a surface speed

    def feed_mode(profile, text):  # held to the core's at every block (motion)
        reader = ProgramReader(profile, file="p.nc", options=DiffOptions(motion=True))
        list(reader.read(parse_text(text, profile.dialect)))
        return reader.feed_mode

    # (a system A lathe's G94 is the facing cycle, not feed per minute: G98 is)
    assert [feed_mode(lathe, t) for t in ("", "G98\n", "G98\nM30\n", "G94\n")] == [95, 94, 95, 95]
    haas = load_profile("haas-mill")  # a mill's G98/G99 are cycle returns
    assert [feed_mode(p, "G95\nG98\n") for p in (FANUC, haas)] == [95, 95]


@pytest.mark.parametrize(("text", "source", "target", "options", "written"), [
    # metric values under the G21 the converter inserts, in a program of inch default units
    ("N7065 X10.674 Y-0.907\n", "fanuc-mill", "haas-mill", {"decimal": "implicit"},
     "N7065 G21 X10674 Y-907\n"),
    # and back: each block's units code is the units of its own values
    ("N1 G21 X10674 Y-907\nN2 G20 X10674\nM30\n", "haas-mill", "fanuc-mill", {},
     "N1 G21 X10.674 Y-0.907\nN2 G20 X1.0674\nM30\n"),
    ("N1 G21 X10674 Y-907\nN2 G20 X10674\nM30\n", "haas-mill", "fanuc-mill", {"units": "inch"},
     "N1 G20 X0.4202 Y-0.0357\nN2 G20 X1.0674\nM30\n"),
    ("N1 G20 X1.5 Y-0.907\nN2 G21 X10.674\nM30\n", "fanuc-mill", "haas-mill",
     {"decimal": "implicit", "units": "metric"}, "N1 G21 X38100 Y-23038\nN2 G21 X10674\nM30\n"),
])
def test_a_units_code_sets_the_units_of_the_values_in_its_own_block(
        tmp_path, text, source, target, options, written):
    """Found as a refusal: the verification read X10674 beside G21 as 1.0674 mm, in the inch
    increments in force before the block."""
    assert _verified(tmp_path, text, source, target, **options) == written
    a, b = write(tmp_path, "a.nc", text), write(tmp_path, "b.nc", written)
    found, _ = differences(a, b, load_profile(source), load_profile(target), tolerance=HALF,
                           motion=True)
    assert found == []


def test_a_word_too_long_to_read_is_the_same_word_where_it_is_written_the_same(tmp_path):
    """Found as a refusal (DiffError: more than the 38 significant digits) of a 5,005-digit
    word the converter passed on as written."""
    long = "1" + "2" * 5004
    text = f"N1 G1 T{long}\nM30\n"
    assert _verified(tmp_path, text, "heidenhain-iso", "heidenhain-iso") == text
    a = write(tmp_path, "a.nc", f"G21\nN1 X{long}\nN2 X1.\nM30\n")
    assert differences(a, a, motion=True)[0] == []
    b = write(tmp_path, "b.nc", f"G21\nN1 X{long}3\nN2 X1.\nM30\n")  # not the same word
    with pytest.raises(DiffError) as err:
        differences(a, b)
    assert err.value.code == "diff-number"
    assert (err.value.file, err.value.line, err.value.column) == (a, 2, 4)
    c = write(tmp_path, "c.nc", f"G21\nN1 X{long[:20]}\nN2 X1.\nM30\n")  # read on one side
    with pytest.raises(DiffError) as err:
        differences(a, c)
    assert (err.value.code, err.value.file, err.value.line, err.value.column) == \
        ("diff-number", a, 2, 4)


def test_a_block_only_in_the_output_is_named_by_its_line_there(tmp_path):
    """Found as a ConversionError whose message names line 2 of the converted program and
    whose line is None. (Under haas-mill 'O1677Z16' alone is the program's name; under
    iso-lathe a program number and a move: not the same program.) The converter now refuses
    such a name for a control of another family at the source (conversion-dialect); the
    output is written here as it was, for verify to read, beside a source without the name
    (the proof reads the source's name, a statement, as its text now)."""
    with pytest.raises(ConversionError) as err:
        _verified(tmp_path, "N14.\nO1677Z16", "haas-mill", "iso-lathe", units="inch",
                  from_decimal="implicit")
    assert (err.value.code, err.value.line, err.value.column) == ("conversion-dialect", 2, 1)
    src = write(tmp_path, "p.nc", "N14.\n")
    out = write(tmp_path, "o.nc", "N14\nO1677Z16")
    options = ConvertOptions(load_profile("iso-lathe"), load_profile("haas-mill"))
    with pytest.raises(ConversionError) as err:
        verify_conversion(src, out, load_profile("haas-mill"), options, ConvertStats(),
                          file="p.nc")
    e = err.value
    assert (e.code, e.file, e.line, e.clause) == ("conversion-verify", "p.nc (converted)", 2,
                                                  "verify")
    assert e.message == ("the conversion is not the same program: line 2 of the converted "
                         "program: 'O1677Z16' not in p.nc")
    assert str(e).startswith("p.nc (converted):2: ")


def test_a_dwell_s_x_is_no_step_for_the_position_before_it(tmp_path):
    """Found converting a thread grinder's backup to inch: G04 X1 (a dwell of 0.001 s) after
    X-40 (-0.040 mm, rounded to -0.0016 in) failed verify ('position X -0.04 mm -> -0.04064
    mm'): the position kept from the block before was held to the dwell word's step."""
    out = _verified(tmp_path, "G21 G90\nG01 X-40 F4000\nG04 X1\nM30\n", "fanuc-lathe",
                    "fanuc-lathe", units="inch")
    assert out.splitlines()[1:3] == ["G01 X-0.0016 F157.4803", "G04 X0.001"]


@pytest.mark.parametrize(("source", "fanuc", "lcnc", "line"), [
    ("fanuc-mill", "G21\n#1=2000\nG04 P#1\nM30\n", "g21\n#1=2000\ng4 p#1\nm30\n", 3),
    ("haas-mill", "G21\nG04 P[2000]\nM30\n", "g21\ng4 p[2000]\nm30\n", 2),
    ("fanuc-mill", "G21\n#1=2\nG0 X0 Y0 Z5.\nG98 G82 X1. Y1. Z-1. R1. P#1 F100.\nG80\nM30\n",
     "g21\n#1=2\ng0 x0 y0 z5\ng98 g82 x1 y1 z-1 r1 p#1 f100\ng80\nm30\n", 4),
])
def test_a_dwell_by_a_parameter_in_milliseconds_is_not_the_same_as_one_in_seconds(
        tmp_path, source, fanuc, lcnc, line):
    """Review 24, 2: `diff` compares parameters and expressions as written, and called a
    FANUC's `G04 P#1` (milliseconds) and LinuxCNC's `g4 p#1` (seconds), 1000 times apart,
    "the same program", exit 0, where `--verify` tells them apart. The block differs now,
    either way round; within a family of one time unit the same text is the same."""
    a, b = write(tmp_path, "a.nc", fanuc), write(tmp_path, "b.ngc", lcnc)
    linuxcnc, src = load_profile("linuxcnc"), load_profile(source)
    for (x, px), (y, py) in [((a, src), (b, linuxcnc)), ((b, linuxcnc), (a, src))]:
        found, summary = differences(x, y, px, py)
        assert not summary.same
        assert [(d.a.line, d.b.line) for d in found] == [(line, line)]
        [change] = found[0].words
        assert (change.kind, change.key) == ("changed", "P")
        first, second = ("milliseconds", "seconds") if px is src else ("seconds", "milliseconds")
        assert change.describe().endswith(f"(a dwell read in {first} and in {second})")
    result = run("diff", a, b, "--from", source, "-p", "linuxcnc")
    assert result.exit_code == 1, result.output
    assert "(a dwell read in milliseconds and in seconds)" in result.output
    assert "differ: 1 block changed" in result.output
    # the same control family on both sides: the same time
    other = "haas-mill" if source == "fanuc-mill" else "fanuc-mill"
    result = run("diff", a, a, "--from", source, "-p", other)
    assert result.exit_code == 0 and "the same program" in result.output, result.output


@pytest.mark.parametrize(("source", "dwell"), [
    ("fanuc-mill", "G04 X1.5"), ("fanuc-mill", "G04 P1500"), ("haas-mill", "G04 P1.5"),
    ("fanuc-lathe", "G04 U1.5"), ("fanuc-lathe", "G04 X1.5"),
])
def test_a_dwell_is_compared_by_its_time_whichever_letter_gives_it(tmp_path, source, dwell):
    """Review 26 (doubtful list): `G04 X1.5` and tapegate's own conversion `G4 P1.5` were
    "changed" (X removed, P added) while `G04 P1000` and `G4 P1` were the same: a dwell's
    time letters (`word::dwell_words`) are one word, read in seconds (a FANUC or Haas P
    without a point in milliseconds)."""
    head = "G21 G18\nG0 Z5.\n" if "lathe" in source else "G21 G17\nG0 X0 Y0 Z5.\n"
    a = write(tmp_path, "a.nc", f"{head}{dwell}\nM30\n")
    b = write(tmp_path, "b.ngc", f"{head.lower()}g4 p1.5\nm30\n")
    result = run("diff", a, b, "--from", source, "-p", "linuxcnc")
    assert result.exit_code == 0 and "the same program" in result.output, result.output
    # and the conversion's own output is the same program as its source
    c = str(tmp_path / "c.ngc")
    convert_file(a, c, ConvertOptions(target=load_profile("linuxcnc"),
                                      source=load_profile(source)))
    assert "P1.5" in Path(c).read_text()
    result = run("diff", a, c, "--from", source, "-p", "linuxcnc")
    assert result.exit_code == 0, result.output


@pytest.mark.parametrize(("dwell", "other", "said"), [
    ("G04 X1.5", "g4 p2", "X1.5 -> P2 (+0.5"),  # another time
    ("G04 P1500", "g4 p1500", "P1500 -> P1500 (+1498.5"),  # milliseconds against seconds
    ("G04 X1.5", "g4 p1500", "X1.5 -> P1500 (+1498.5"),
])
def test_a_dwell_of_another_time_is_still_a_difference(tmp_path, dwell, other, said):
    head = "G21 G17\nG0 X0 Y0 Z5.\n"
    a = write(tmp_path, "a.nc", f"{head}{dwell}\nM30\n")
    b = write(tmp_path, "b.ngc", f"{head.lower()}{other}\nm30\n")
    result = run("diff", a, b, "--from", "fanuc-mill", "-p", "linuxcnc")
    assert result.exit_code == 1, result.output
    assert said in result.output and "differ: 1 block changed" in result.output, result.output
    found, _ = differences(a, b, FANUC, load_profile("linuxcnc"))
    [change] = found[0].words
    assert (change.kind, change.key) == ("changed", "P")


def test_a_sinumerik_dwell_in_revolutions_is_not_one_in_seconds(tmp_path):
    """SINUMERIK's G4 S is revolutions of the spindle, its F seconds: S2 and F2 differ."""
    sin = load_profile("sinumerik-840d")
    a = write(tmp_path, "a.mpf", "G71\nG4 F2\nM30\n")
    b = write(tmp_path, "b.mpf", "G71\nG4 S2\nM30\n")
    found, summary = differences(a, b, sin, sin)
    assert not summary.same
    assert sorted(c.kind for c in found[0].words) == ["added", "removed"]
    same, summary = differences(a, a, sin, sin)
    assert same == [] and summary.same


def test_a_position_one_program_never_set_is_none_without_a_unit(tmp_path):
    """'position Y none mm' read as if none were a length."""
    a = write(tmp_path, "a.nc", "G21 G90\nG01 X1. F100.\nX2.\nM30\n")
    b = write(tmp_path, "b.nc", "G21 G90\nG01 X1. Y1. F100.\nX2.\nM30\n")
    found, _ = differences(a, b, motion=True)
    details = " ".join(" ".join(d.details()) for d in found)
    assert "position Y none -> 1 mm" in details and "none mm" not in details, details


# -- the core's comparison, held to exact decimal arithmetic -------------------------------------

_values = st.decimals(min_value=-1000, max_value=1000, places=5, allow_nan=False,
                      allow_infinity=False)


def _read(text: str, options: DiffOptions) -> list:
    reader = ProgramReader(FANUC, file="p.nc", options=options)
    return list(reader.read(parse_text(text, FANUC.dialect)))


def _written(value: Decimal) -> str:
    text = f"{value:f}"
    return text if "." in text else text + "."  # no point: a count of increments on a Fanuc


@settings(max_examples=300, deadline=None)
@given(_values, _values, st.sampled_from(["G21", "G20"]),
       st.sampled_from([Decimal(0), HALF, Decimal(1), Decimal("0.3"), Decimal("2.5")]),
       st.none() | st.fractions(min_value=0, max_value=Fraction(1, 100), max_denominator=10**7))
def test_the_cores_tolerance_and_bounds_are_exact_decimal_arithmetic(va, vb, units, tolerance,
                                                                     bound):
    """A difference is accepted exactly when ``decimal`` says it is within ``tolerance`` steps
    of B's format and within the bound of its address (times 25.4 in inches): half a step is
    accepted, the least beyond it is not; a refused one is reported with its exact size."""
    from decimal import localcontext

    options = DiffOptions(tolerance=tolerance, pair="position",
                          bounds=None if bound is None else {"X": bound})
    differ = Differ(options, FANUC)
    found = list(differ.run(_read(f"{units} X{_written(va)}\n", options),
                            _read(f"{units} X{_written(vb)}\n", options)))
    inch = units == "G20"
    with localcontext() as ctx:
        ctx.prec = 100
        factor = Decimal("25.4") if inch else Decimal(1)
        step = FANUC.word_format("X", "inch" if inch else "metric").resolution * factor
        difference = (vb - va) * factor
        accepted = abs(difference) <= tolerance * step and (
            bound is None or Fraction(abs(difference)) <= bound * Fraction(factor))
    assert (found == []) == accepted, (va, vb, units, tolerance, bound)
    if found:
        [change] = found[0].words
        assert change.difference == difference
        assert change.steps == Fraction(difference) / Fraction(step)


@pytest.mark.parametrize(("b", "same"), [("X1.0005", True), ("X0.9995", True),
                                         ("X1.0006", False), ("X1.00050000001", False)])
def test_half_a_step_is_accepted_and_the_least_beyond_it_is_not(b, same):
    options = DiffOptions(tolerance=HALF, pair="position")
    found = list(Differ(options, FANUC).run(_read("G21 X1.\n", options),
                                            _read(f"G21 {b}\n", options)))
    assert (found == []) == same


def _blocks(read) -> list:
    return [(b.line, b.text, b.number, b.words(), b.comments, b.resets, b.state(),
             sorted((i, str(e), e.line, e.column) for i, e in (b.errors or {}).items()))
            for b in read]


@needs_corpus
@pytest.mark.parametrize("profile", ["fanuc-mill", "sinumerik-840d", "linuxcnc"])
def test_the_text_read_in_the_core_is_the_program_parsed_block_by_block(profile):
    """diff_files reads each line in the core (``ProgramReader.read_text``); the same program
    parsed into Blocks and read block by block is the same blocks, errors collected included."""
    from formats.parser import parse_stream
    from formats.source import Source

    prof = load_profile(profile)
    options = DiffOptions(motion=True, errors="collect")
    for path in corpus_files()[::7]:
        fast = ProgramReader(prof, file="p.nc", options=options)
        slow = ProgramReader(prof, file="p.nc", options=options)
        chunks = list(Source(str(path)).chunks())
        try:
            expected = _blocks(slow.read(parse_stream(chunks, prof.dialect, file="p.nc",
                                                      errors="collect")))
        except DiffError as exc:  # a modal drift: the same, at the same line
            with pytest.raises(DiffError) as err:
                _blocks(fast.read_text(chunks))
            assert (err.value.code, err.value.line, str(err.value)) == (exc.code, exc.line,
                                                                        str(exc))
            continue
        assert _blocks(fast.read_text(chunks)) == expected, path.name


def test_without_a_profile_a_g20_program_keeps_its_units_through_m30(tmp_path: Path) -> None:
    """Read with the neutral profile and G20/G21 found (the codes of controls that keep their
    units through M30), a second program without a units code is in the first's inch: the same
    as one that states G20. Read as clause 14's reset, it was 1 mm against 1 inch."""
    a, b = tmp_path / "a.nc", tmp_path / "b.nc"
    a.write_text("O1\nG20\nG0 X1.\nM30\nO2\nG0 X1.\nM30\n")
    b.write_text("O1\nG20\nG0 X1.\nM30\nO2\nG20 G0 X1.\nM30\n")
    result = CliRunner().invoke(main, ["diff", str(a), str(b)])
    assert result.exit_code == 0, result.output
    assert "are the same program" in result.output
    kept = {name: load_profile(name).units_kept_at_end
            for name in ("fanuc-mill", "haas-lathe", "linuxcnc", "iso-mill", "sinumerik-840d",
                         "heidenhain-iso")}
    assert kept == {"fanuc-mill": True, "haas-lathe": True, "linuxcnc": True,
                    "iso-mill": False, "sinumerik-840d": False, "heidenhain-iso": False}


@pytest.mark.parametrize("source", ["fanuc-mill", "haas-mill"])
@pytest.mark.parametrize("other, target", [
    ("G20\nG04 P150\nM30\n", None),  # 0.15 s, the inch length format's reading of X1500
    ("G20\nG04 P1500\nM30\n", None),  # 1.5 s, the increment system's reading
    ("G21\nG04 X1500\nM30\n", None),
    ("g20\ng4 p0.15\nm30\n", "linuxcnc"),
])
def test_a_dwell_s_x_without_a_point_under_g20_is_never_the_same(tmp_path, source, other,
                                                                  target):
    """Review 28, finding 2: `G20 G04 X1500` was read with X's inch length format, 0.15 s,
    and called "the same program" as `G04 P150` and LinuxCNC's `G4 P0.15`; the
    FANUC-compatible ISO mode's table gives X's time unit by the increment system alone
    (0.001 s at IS-B: 1.5 s), and no source at hand settles whether G20 changes it. Such a
    dwell keeps its own word: a difference against any other form, the same against its
    own text."""
    a = write(tmp_path, "a.nc", "G20\nG04 X1500\nM30\n")
    b = write(tmp_path, "b.ngc" if target else "b.nc", other)
    args = ["diff", a, b, "-p", target or source] + (["--from", source] if target else [])
    result = run(*args)
    assert result.exit_code == 1, result.output
    assert "differ: 1 block changed" in result.output, result.output
    assert "X1500 removed" in result.output or "X1500 -> X1500" in result.output
    result = run("diff", a, a, "-p", source)
    assert result.exit_code == 0 and "the same program" in result.output, result.output
    # with a point, or under G21, the dwell is still compared by its time
    pointed = write(tmp_path, "c.nc", "G20\nG04 X1.5\nM30\n")
    ms = write(tmp_path, "d.nc", "G20\nG04 P1500\nM30\n")
    assert run("diff", pointed, ms, "-p", source).exit_code == 0
    metric = write(tmp_path, "e.nc", "G21\nG04 X1500\nM30\n")
    metric_ms = write(tmp_path, "f.nc", "G21\nG04 P1500\nM30\n")
    assert run("diff", metric, metric_ms, "-p", source).exit_code == 0
