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
