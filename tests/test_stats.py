"""`tapegate check --stats`: path lengths, arc count and extents of arcs by I J K, by R and by
Sinumerik CR=, all from the core's one arc geometry (the path the backplot draws)."""

from __future__ import annotations

import json
import math
from decimal import Decimal
from pathlib import Path

import pytest
from click.testing import CliRunner

from formats.profile import load_profile
from postproc.check import Checker, CheckStats
from tapegate.cli import main

MILL = "%\nO1\nG21 G17 G90 G94\nG00 X0 Y0 Z0\nG01 F100.\n{}\nM30\n%\n"
SIEMENS = "G17 G90 G0 X0 Y0 Z0\nG1 F100\n{}\nM30\n"


def stats(text: str, profile: str = "fanuc-mill") -> CheckStats:
    checker = Checker(load_profile(profile))
    list(checker.run_stream([text], load_profile(profile).dialect))
    return checker.stats


def extent(s: CheckStats, axis: str) -> tuple[Decimal, Decimal]:
    return s.low[axis], s.high[axis]


@pytest.mark.parametrize("arc", ["G02 X20. Y0. R10.", "G02 X20. Y0. I10. J0."])
def test_a_half_circle_of_radius_10_is_its_true_length_and_reaches_its_top(arc: str) -> None:
    """R and I J give the same arc: 10 pi long (not the 20 of the chord), one arc, and over
    the top from X0 Y0 to X20 Y0 clockwise, so Y reaches 10 though no end point is there."""
    s = stats(MILL.format(arc))
    assert s.feed_length == pytest.approx(10 * math.pi, abs=1e-9)
    assert s.arcs == 1
    assert extent(s, "X") == (0, 20) and extent(s, "Y") == (0, 10)


def test_the_arc_over_180_degrees_by_a_negative_radius() -> None:
    """G02 X10 Y10 R-10 from X0 Y0: three quarters of the circle about X0 Y10, through
    X-10 Y10 and X0 Y20."""
    s = stats(MILL.format("G02 X10. Y10. R-10."))
    assert s.feed_length == pytest.approx(15 * math.pi, abs=1e-9)
    assert extent(s, "X") == (-10, 10) and extent(s, "Y") == (0, 20)


def test_sinumerik_cr_arcs_count_as_arcs() -> None:
    """CR= had no length at all before (its centre was taken as the start point)."""
    s = stats(SIEMENS.format("G2 X20 Y0 CR=10"), "sinumerik-840d")
    assert s.arcs == 1 and s.feed_length == pytest.approx(10 * math.pi, abs=1e-9)
    assert extent(s, "Y") == (0, 10)


def test_a_full_circle_reaches_every_quadrant_point() -> None:
    s = stats(MILL.format("G01 X20.\nG03 X20. Y0. I-10. J0."))
    assert s.arcs == 1
    assert s.feed_length == pytest.approx(20 + 20 * math.pi, abs=1e-9)
    assert extent(s, "X") == (0, 20) and extent(s, "Y") == (-10, 10)


def test_an_impossible_radius_is_the_straight_move_and_no_arc() -> None:
    s = stats(MILL.format("G02 X10. Y0. R4."))
    assert s.arcs == 0 and s.feed_length == pytest.approx(10)
    assert extent(s, "Y") == (0, 0)


def test_quadrant_points_are_rounded_to_the_axis_format() -> None:
    """An R arc whose top is irrational: the extent is what the control can reach in its
    format (X+053: three decimals)."""
    s = stats(MILL.format("G02 X10. Y0. R7."))  # centre X5 Y-4.89898, top Y2.10102
    top = 7 - math.sqrt(49 - 25)
    assert extent(s, "Y")[1] == Decimal(f"{top:.3f}") == Decimal("2.101")


def test_a_lathe_arc_in_diameter_is_measured_as_the_tool_runs() -> None:
    """fanuc-lathe: X is a diameter. G02 X40 Z-10 R10 from X20 Z0 (radius 10 to 20) is a
    quarter circle of radius 10 about Z-10 X10 (radius): 5 pi long; the X extent stays in
    diameters."""
    text = "%\nO1\nG18 G21 G99\nG00 X20. Z0.\nG01 F0.2\nG02 X40. Z-10. R10.\nM30\n%\n"
    s = stats(text, "fanuc-lathe")
    assert s.arcs == 1 and s.feed_length == pytest.approx(5 * math.pi, abs=1e-9)
    assert extent(s, "X") == (20, 40) and extent(s, "Z") == (-10, 0)


def test_the_stats_output_counts_the_arcs(tmp_path: Path) -> None:
    path = tmp_path / "p.nc"
    path.write_text(MILL.format("G02 X20. Y0. R10.\nG03 X40. Y0. R10."))
    r = CliRunner().invoke(main, ["check", str(path), "-p", "fanuc-mill", "--stats"])
    assert "feed path 62.8 mm (2 arcs at their true length)" in r.output
    assert "  Y: -10 to 10 mm" in r.output  # quadrant points as the written values: no zeros
    r = CliRunner().invoke(main, ["check", str(path), "-p", "fanuc-mill", "--stats",
                                  "--format", "json"])
    data = json.loads(r.output)["stats"][str(path)]
    assert data["arcs"] == 2 and data["bounding_box"]["Y"] == [-10, 10]
    assert data["feed_length"] == pytest.approx(20 * math.pi, abs=1e-3)


def test_the_statistics_are_in_the_profiles_units_whatever_the_program_writes(tmp_path: Path
                                                                               ) -> None:
    """A G20 program on a metric profile: X1. to X2. is 25.4 to 50.8 mm, and the path and the
    time too (they said 'X: 1 to 2 mm'). A HEIDENHAIN program gives its units in its first line
    (%NAME G70 *)."""
    s = stats("%\nO1\nG20 G90 G17\nG0 X1. Y1.\nG1 X2. F10.\nM30\n%\n", "fanuc-mill")
    assert extent(s, "X") == (Decimal("25.4"), Decimal("50.8"))
    assert s.feed_length == pytest.approx(25.4) and s.units == "metric"
    assert s.seconds == pytest.approx(6.0, abs=1.0)  # 1 in at 10 in/min, and the rapid
    heidenhain = stats("%P G70 *\nN10 G00 G90 X+1 Y+0 Z+0.1 *\nN20 G01 X+2.5 F20 *\n"
                       "N30 M30 *\nN99999999 %P G70 *\n", "heidenhain-iso")
    assert extent(heidenhain, "X") == (Decimal("25.4"), Decimal("63.5"))


def test_a_checker_without_statistics_finds_the_same_and_has_none(tmp_path: Path) -> None:
    """``stats=False`` (what ``check`` without ``--stats`` makes): the moves' geometry is not
    worked out for the statistics, the findings are the same, and asking for the statistics
    is refused, not answered with empty ones. The path of the backplot is still recorded."""
    text = MILL.format("G02 X20. Y0. R10.\nG03 X40. Y0. I10. J0. Z-1.\nG01 X45.123456")
    profile = load_profile("fanuc-mill")
    found = {}
    for kept in (True, False):
        checker = Checker(profile, stats=kept)
        found[kept] = [(f.rule, f.line, f.column, f.message)
                       for f in checker.run_stream([text], profile.dialect)]
    assert found[True] == found[False]
    assert {rule for rule, *_ in found[True]} >= {"TG406", "TG208"}
    with pytest.raises(ValueError, match="without statistics"):
        _ = Checker(profile, stats=False).stats
    paths = []
    for kept in (True, False):
        drawn = Checker(profile, stats=kept, record_path=True)
        list(drawn.run_stream([text], profile.dialect))
        paths.append(drawn.path)
    assert paths[0] == paths[1] and [s.kind for s in paths[0] or []].count("arc") == 2


def test_the_command_keeps_the_statistics_only_for_stats(tmp_path: Path) -> None:
    """``check`` without ``--stats`` writes no statistics in any format; with it, the same
    statistics as the API's checker that keeps them."""
    path = tmp_path / "p.nc"
    path.write_text(MILL.format("G02 X20. Y0. R10.\nG03 X40. Y0. R10."))
    for fmt in ("json", "jsonl", "text"):
        r = CliRunner().invoke(main, ["check", str(path), "-p", "fanuc-mill", "--format", fmt])
        assert "bounding_box" not in r.output and "feed path" not in r.output, fmt
    r = CliRunner().invoke(main, ["check", str(path), "-p", "fanuc-mill", "--stats",
                                  "--format", "json"])
    data = json.loads(r.output)["stats"][str(path)]
    s = stats(path.read_text())
    assert data["arcs"] == s.arcs == 2
    assert data["bounding_box"]["X"] == [s.low["X"], s.high["X"]]


# -- after a G code the family's list lacks (review 8, finding 3) ------------------------------

# a system B/C lathe's thread pass (G33; system A's is G32), shaped as in a real program
SYSTEM_B_THREAD = ("%\nO1201\nG21 G99 G54\nG97 S500 M3\nG0 X15.405 Z-0.672\n"
                   "G33 Z-17.328 F1.5\nG0 X18. Z-18.\nM30\n%\n")


def test_a_thread_by_a_code_the_list_lacks_is_no_rapid_and_is_said_to_be_unknown() -> None:
    """On fanuc-lathe (system A) G33 is no code of the control: the control alarms, or its
    parameters make it a macro. The pass is neither counted as a rapid (the G00 in force) nor
    as anything else, and the statistics say from which line and why; the G00 after it is a
    known move again."""
    s = stats(SYSTEM_B_THREAD, "fanuc-lathe")
    # G0 X15.405 Z-0.672 from the start (X0 Z0, radius 7.7025) and G0 X18. Z-18. after the
    # G33, whose Z is a macro's argument where the parameters make it a call: where Z stands
    # after it is not known, and is taken as at the program's start (0); X, not written in
    # the G33 block, is where it was. The two rapids alone
    rapids = math.hypot(15.405 / 2, 0.672) + math.hypot((18 - 15.405) / 2, 18)
    assert s.rapid_length == pytest.approx(rapids, abs=1e-3)
    assert s.feed_length == 0
    assert len(s.moves_not_known) == 1
    assert s.moves_not_known[0].startswith("from line 6: G33 is not in the family's code list")
    known = stats(SYSTEM_B_THREAD.replace("G33", "G32"), "fanuc-lathe")
    assert known.feed_length == pytest.approx(16.656, abs=1e-3) and known.moves_not_known == []


def test_a_haas_lathe_drilling_code_it_lacks_draws_and_times_no_rapid() -> None:
    """haas-lathe's list has no G244: its strokes are no rapids of 0 s, and no move of the
    block nor the next (the same unknown mode) is counted, until G80 and a G00."""
    text = ("%\nO1\nG20 G18 G99\nT101\nG97 S1000 M3\nG0 X1. Z1.\n"
            "G98 G244 X1.0 Z-0.5 R0.1 Q0.1 F5.\nX0.8 Z-0.6\nG80\nG0 X2. Z1.\nM30\n%\n")
    s = stats(text, "haas-lathe")
    assert s.feed_length == 0
    # G0 X1. Z1. from the start and G0 X2. Z1. from the last stroke's end: the two rapids
    rapids = math.hypot(0.5, 1) + math.hypot((2 - 0.8) / 2, 1.6)
    assert s.rapid_length == pytest.approx(rapids, abs=1e-3)
    assert [m.split(":")[0] for m in s.moves_not_known] == ["from line 7"]
    assert "G244" in s.moves_not_known[0]


def test_each_lacked_code_is_said_once_at_its_first_line() -> None:
    text = SYSTEM_B_THREAD.replace("G0 X18. Z-18.", "G0 X15.405 Z-0.672\nG33 Z-17.328\nG95\n"
                                   "G0 X18. Z-18.")
    s = stats(text, "fanuc-lathe")
    assert [m.split(" is ")[0] for m in s.moves_not_known] == ["from line 6: G33",
                                                               "from line 9: G95"]


def test_the_text_and_json_stats_name_the_line_the_moves_are_unknown_from(tmp_path: Path) -> None:
    path = tmp_path / "thread.nc"
    path.write_text(SYSTEM_B_THREAD)
    text = CliRunner().invoke(main, ["check", str(path), "-p", "fanuc-lathe", "--stats"])
    assert "moves not known from line 6: G33 is not in the family's code list" in text.output
    out = CliRunner().invoke(main, ["check", str(path), "-p", "fanuc-lathe", "--stats",
                                    "--format", "json"])
    doc = json.loads(out.output)
    found = json.dumps(doc)
    assert "from line 6: G33 is not in the family's code list" in found


@pytest.mark.parametrize("code, does", [
    # rs274 reads no G code from G100 on, even where a REMAP names it (TG306)
    ("G100", "the control alarms"),
    # G0-G99.9 that LinuxCNC's tables leave blank are open to a configuration's REMAP (TG307)
    ("G44.1", "the control alarms, or runs the REMAP its configuration names"),
])
def test_where_the_control_alarms_on_a_code_it_lacks_no_macro_is_named(code, does) -> None:
    """LinuxCNC's rs274 stops at a code it does not have, or runs the REMAP a configuration
    gives it: the note says so, not that a macro may run, and the move after it is not
    counted."""
    s = stats(f"G21 G90 G94\nG0 X0 Y0 Z5\nG1 Z0 F100\n{code} X5\nM2\n", "linuxcnc")
    assert s.moves_not_known == [
        f"from line 4: {code} is not in the family's code list ({does}), so the "
        "motion is not known until the next motion code the list holds; the moves in between "
        "are not in the path, its lengths, the cycle time or the plot"]
    assert s.feed_length == pytest.approx(5)


# -- a dwell's time by the profile's dwell letters and units (word::dwell_words) ----------------

DWELL = "%\nO1\nG21 G17 G90 G94\nG00 X0 Y0 Z0\n{}\nM30\n%\n"


@pytest.mark.parametrize("profile, block, seconds", [
    # a FANUC or Haas P is milliseconds, X seconds; an F in the block is the feed
    ("fanuc-mill", "G04 P500", 0.5),
    ("fanuc-mill", "G04 X1.", 1.0),
    ("fanuc-mill", "G04 X1. F100.", 1.0),
    ("fanuc-mill", "G04 P500 F100.", 0.5),
    ("haas-mill", "G04 P500", 0.5),
    # a Haas P with a point is seconds
    ("haas-mill", "G04 P0.5", 0.5),
    # a lathe's U is its time, not an increment of X
    ("fanuc-lathe", "G04 U1.5", 1.5),
    ("fanuc-lathe", "G04 P1500", 1.5),
    # LinuxCNC's P is seconds
    ("linuxcnc", "G4 P1.5", 1.5),
    # SINUMERIK: F seconds; S revolutions, no time without the spindle's speed
    ("sinumerik-840d", "G4 F2", 2.0),
    ("sinumerik-840d", "G4 S30", 0.0),
])
def test_a_dwell_counts_its_time_in_the_profiles_units(profile, block, seconds) -> None:
    text = DWELL.format(block)
    if profile.startswith("sinumerik"):
        text = f"G17 G90 G0 X0 Y0 Z0\n{block}\nM30\n"
    elif profile == "linuxcnc":
        text = f"G21 G17 G90\nG0 X0 Y0 Z0\n{block}\nM2\n"
    base = stats(text.replace(f"{block}\n", ""), profile).seconds
    s = stats(text, profile)
    assert s.seconds - base == pytest.approx(seconds, abs=1e-9), s.seconds


# -- a dwell whose time is not known is counted apart, consistently with diff and convert -------

INCH_DWELL = "%\nO1\nG20 G17 G90 G94\nG00 X0 Y0 Z0\n{}\nM30\n%\n"


@pytest.mark.parametrize("profile, block", [
    ("fanuc-mill", "G04 X1500"),
    ("haas-mill", "G04 X1500"),
    ("fanuc-lathe", "G04 U1500"),
    ("fanuc-lathe", "G04 X1500"),
])
def test_a_fanuc_or_haas_inch_dwell_without_a_point_is_no_time_of_the_program(profile, block):
    """`G20 G04 X1500` is 0.15 s by the inch length format and 1.5 s by the increment system
    alone; no source says which the control takes. `diff` never calls it the same and convert
    refuses it: the statistics state no time for it either, and say why, once, with the
    count of such dwells."""
    text = INCH_DWELL.format(f"{block}\n{block}\nG04 X1.5")
    s = stats(text, profile)
    base = stats(INCH_DWELL.format(""), profile).seconds
    assert s.seconds - base == pytest.approx(1.5, abs=1e-9)  # the X1.5 alone
    assert s.dwells_not_counted == 2
    letter = block.split()[1][0]
    assert s.dwells_not_known == [
        f"from line 5: a dwell's {letter} without a decimal point under G20 ({block.split()[1]}):"
        " read with the inch format it is 0.15 s, with the metric one ten times that; no source "
        "says whether the control's dwell follows G20's increment (diff keeps such a dwell "
        "apart, convert refuses it)"]


@pytest.mark.parametrize("profile, block, seconds", [
    ("fanuc-mill", "G21\nG04 X1500", 1.5),  # metric: the increment 0.001 either way
    ("fanuc-mill", "G04 X1.5", 1.5),  # the point says seconds
    ("fanuc-mill", "G04 P1500", 1.5),  # P is milliseconds in either units
    ("haas-mill", "G04 P1.5", 1.5),
    ("fanuc-mill", "#1=1.5\nG04 X#1", 1.5),  # the value the control computes
])
def test_an_inch_dwell_whose_time_is_known_still_counts(profile, block, seconds):
    s = stats(INCH_DWELL.format(block), profile)
    base = stats(INCH_DWELL.format(block.rsplit("\n", 1)[0] if "\n" in block else ""),
                 profile).seconds
    assert s.seconds - base == pytest.approx(seconds, abs=1e-9)
    assert s.dwells_not_counted == 0 and s.dwells_not_known == []


def test_a_sinumerik_dwell_by_revolutions_is_said_not_counted():
    s = stats("G17 G90 G0 X0 Y0 Z0\nG4 S30\nG4 S10\nM30\n", "sinumerik-840d")
    assert s.seconds == 0 and s.dwells_not_counted == 2
    assert s.dwells_not_known == [
        "from line 2: SINUMERIK's G4 S is revolutions of the spindle, no time without the "
        "spindle's speed at the dwell"]


def test_check_stats_reports_the_dwells_not_counted_in_text_and_json(tmp_path):
    path = tmp_path / "inch.nc"
    path.write_text(INCH_DWELL.format("G04 X1500"))
    result = CliRunner().invoke(main, ["check", "--stats", "-p", "fanuc-mill", str(path)])
    assert "1 dwell not in the cycle time, its time not known:\n    from line 5: a dwell's X " \
        "without a decimal point under G20 (X1500)" in result.output, result.output
    result = CliRunner().invoke(main, ["check", "--stats", "--format", "json", "-p",
                                       "fanuc-mill", str(path)])
    stats_of = json.loads(result.output)["stats"][str(path)]
    assert stats_of["dwells_not_counted"]["count"] == 1
    assert stats_of["dwells_not_counted"]["why"][0].startswith("from line 5: a dwell's X")
