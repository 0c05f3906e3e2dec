"""`tapegate plot`: the drawn path (arcs by I J K, by R and by CR=, in every plane; a lathe's
Z across and X as a radius), the findings' legend, and real programs. The assertions are on the
computed points, not on pixels."""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import TYPE_CHECKING

import pytest

pytest.importorskip("matplotlib")

from click.testing import CliRunner  # noqa: E402

from formats.profile import load_profile  # noqa: E402
from postproc.check import Checker  # noqa: E402
from postproc.findings import Finding  # noqa: E402
from postproc.geometry import PLANE_AXES, sweep  # noqa: E402
from postproc.plot import (  # noqa: E402
    LEGEND_RULES,
    Move,
    backplot,
    backplot_file,
    default_view,
    legend_groups,
)
from tapegate.cli import main  # noqa: E402

from .conftest import CORPUS, needs_corpus  # noqa: E402

if TYPE_CHECKING:
    from postproc.rules import Severity

MILL = "%\nO1\nG21 G17 G90 G94\nG00 X0 Y0 Z0\nG01 F100.\n{}\nM30\n%\n"


def last_move(body: str, profile: str = "fanuc-mill", template: str = MILL) -> Move:
    return backplot(template.format(body), load_profile(profile)).moves[-1]


def turn(m: Move, centre: tuple[float, float], axes: tuple[int, int] = (0, 1)) -> float:
    """The angle the move's points turn through about ``centre`` (radians, signed: + ccw)."""
    i, j = axes
    angles = [math.atan2(p[j] - centre[1], p[i] - centre[0]) for p in m.points]
    total = 0.0
    for a, b in zip(angles, angles[1:], strict=False):
        total += (b - a + math.pi) % (2 * math.pi) - math.pi
    return total


def on_circle(m: Move, centre: tuple[float, float], radius: float,
              axes: tuple[int, int] = (0, 1)) -> bool:
    i, j = axes
    return all(abs(math.hypot(p[i] - centre[0], p[j] - centre[1]) - radius) < 1e-9
               for p in m.points)


# -- R arcs: the centre from the radius ---------------------------------------------------------

def test_an_r_arc_is_drawn_about_its_centre_not_as_a_chord() -> None:
    m = last_move("G02 X10. Y10. R10.")  # from X0 Y0: the quarter circle about X10 Y0
    assert m.arc and not m.impossible and len(m.points) > 2
    assert on_circle(m, (10, 0), 10)
    assert turn(m, (10, 0)) == pytest.approx(-math.pi / 2)  # clockwise, 90 degrees
    assert m.points[0] == (0, 0, 0) and m.points[-1] == (10, 10, 0)


def test_g03_r_takes_the_other_side_of_the_chord() -> None:
    m = last_move("G03 X10. Y10. R10.")
    assert on_circle(m, (0, 10), 10)
    assert turn(m, (0, 10)) == pytest.approx(math.pi / 2)


def test_a_negative_r_is_the_arc_over_180_degrees() -> None:
    m = last_move("G02 X10. Y10. R-10.")
    assert on_circle(m, (0, 10), 10)
    assert turn(m, (0, 10)) == pytest.approx(-3 * math.pi / 2)
    m = last_move("G03 X10. Y10. R-10.")
    assert on_circle(m, (10, 0), 10)
    assert turn(m, (10, 0)) == pytest.approx(3 * math.pi / 2)


def test_a_half_circle_written_in_decimals_is_exact() -> None:
    """R is exactly half the chord: the centre is the chord's middle (floats would find
    r*r - (c/2)**2 below zero and call the arc impossible)."""
    text = MILL.format("G02 X10.001 Y0. R5.0005")
    m = backplot(text, load_profile("fanuc-mill")).moves[-1]
    assert not m.impossible
    assert on_circle(m, (5.0005, 0), 5.0005)
    checker = Checker(load_profile("fanuc-mill"), record_path=True)
    list(checker.run_stream([text], load_profile("fanuc-mill").dialect))
    arc = (checker.path or [])[-1]
    assert (arc.kind, arc.centre, arc.large) == ("arc", (5.0005, 0.0, 0.0), False)


def test_an_impossible_radius_is_drawn_as_its_chord_and_marked() -> None:
    text = MILL.format("G02 X10. Y0. R4.")  # shorter than half the chord, 5
    bp = backplot(text, load_profile("fanuc-mill"))
    m = bp.moves[-1]
    assert m.impossible and m.points == [(0, 0, 0), (10, 0, 0)]
    assert "TG410" in {f.rule for f in bp.findings}  # the checker says so too
    # within the checker's tolerance of half the chord: a half circle, not an error
    assert not last_move("G02 X10. Y0. R4.99").impossible


@pytest.mark.parametrize("plane", [17, 18, 19])
@pytest.mark.parametrize("motion", ["G02", "G03"])
def test_an_r_arc_is_the_same_arc_as_its_ijk_form_in_every_plane(plane: int,
                                                                   motion: str) -> None:
    """The core's centre of an I J K arc and the R centre found here agree: the same quarter
    circle in G17, G18 and G19, each way round."""
    first, second = {17: ("X", "Y"), 18: ("Z", "X"), 19: ("Y", "Z")}[plane]
    centre = {"X": "I", "Y": "J", "Z": "K"}
    # from the origin to (10, 10) in the plane's axes; G02's centre is at (10, 0), G03's (0, 10)
    offset = (10, 0) if motion == "G02" else (0, 10)
    ijk = (f"G{plane} {motion} {first}10. {second}10. {centre[first]}{offset[0]}. "
           f"{centre[second]}{offset[1]}.")
    by_r = f"G{plane} {motion} {first}10. {second}10. R10."
    a, b = last_move(ijk), last_move(by_r)
    assert a.arc and b.arc and not b.impossible
    axes = PLANE_AXES[plane]  # the plane's first axis across, its second up
    assert on_circle(b, (float(offset[0]), float(offset[1])), 10, axes)
    clockwise = -1 if motion == "G02" else 1
    assert turn(b, (float(offset[0]), float(offset[1])), axes) == pytest.approx(
        clockwise * math.pi / 2)
    assert len(a.points) == len(b.points)
    for p, q in zip(a.points, b.points, strict=True):
        assert p == pytest.approx(q, abs=1e-9)


def test_r_is_a_radius_only_where_the_profile_reads_it_as_a_length() -> None:
    """On iso-mill R is a parameter (ISO 6983-1): the block is no arc by R, and the checker
    says the arc has no centre."""
    text = MILL.format("G02 X10. Y10. R10.")
    bp = backplot(text, load_profile("iso-mill"))
    assert not bp.moves[-1].arc
    assert "TG404" in {f.rule for f in bp.findings}


def test_r_in_a_fixed_cycle_is_not_a_radius() -> None:
    m = last_move("G81 X10. Y10. Z-5. R2.")
    assert not m.arc


# -- Sinumerik CR= --------------------------------------------------------------------------------

SIEMENS = "G17 G90 G0 X0 Y0 Z0\n{}\nM30\n"


def test_sinumerik_cr_arcs_are_arcs() -> None:
    m = last_move("G2 X10 Y10 CR=10 F100", "sinumerik-840d", SIEMENS)
    assert m.arc and on_circle(m, (10, 0), 10)
    assert turn(m, (10, 0)) == pytest.approx(-math.pi / 2)
    m = last_move("G3 X10 Y10 cr=-10 F100", "sinumerik-840d", SIEMENS)
    assert on_circle(m, (10, 0), 10)
    assert turn(m, (10, 0)) == pytest.approx(3 * math.pi / 2)
    m = last_move("G2 X10 Y0 CR=4 F100", "sinumerik-840d", SIEMENS)
    assert m.impossible


def test_a_sinumerik_r_parameter_is_not_a_radius() -> None:
    m = last_move("G2 X10 Y10 I10 J0 F100 R1=5", "sinumerik-840d", SIEMENS)
    assert on_circle(m, (10, 0), 10)  # the I J arc, R1=5 left alone


# -- geometry ------------------------------------------------------------------------------------

def test_after_a_call_the_path_goes_on_from_the_next_known_point(tmp_path) -> None:
    """The checker does not follow a subprogram call: the position after it is unknown, and no
    line is drawn from a made-up origin, nor at one in a view that shows it: the feed to X25
    runs at a Z nobody knows after the call (drawn in XZ, it would run at Z0), so it is drawn
    in XY and not in XZ; after the plunge to Z2 (from where nobody knows) every view draws."""
    from postproc.plot import plot

    text = "G17 G90 G0 X10 Y10 Z5\nCYCLE832(0.02,3,1)\nG0 X20 Y30\nG1 X25 F100\nM30\n"
    bp = backplot(text, load_profile("sinumerik-840d"))
    # the first move comes from wherever the machine is: not drawn either
    assert [(m.line, m.lost, m.adrift) for m in bp.moves] == [
        (1, True, frozenset()), (3, True, frozenset()), (4, False, {2})]
    assert len(bp.moves[1].points) == 1 and bp.moves[1].points[0][:2] == (20, 30)
    assert bp.moves[2].points[0][:2] == (20, 30)
    drawn = {}
    for view in ("xy", "xz"):
        plot(bp, str(tmp_path / f"{view}.svg"), view=view, findings=False)
        drawn[view] = (tmp_path / f"{view}.svg").read_text().count("<path")
    assert drawn["xy"] > drawn["xz"]
    text = ("G17 G90 G0 X10 Y10 Z5\nCYCLE832(0.02,3,1)\nG0 X20 Y30\nG0 Z2\nG1 X25 F100\n"
            "M30\n")
    bp = backplot(text, load_profile("sinumerik-840d"))
    assert [(m.line, m.lost, m.adrift) for m in bp.moves] == [
        (1, True, frozenset()), (3, True, frozenset()), (4, True, frozenset()),
        (5, False, frozenset())]
    assert bp.moves[3].points == [(20, 30, 2), (25, 30, 2)]


def test_the_first_moves_are_drawn_once_their_axes_are_known() -> None:
    """G00 Z50. first: X and Y are still wherever the machine is, so the move to X10 Y10 is
    not drawn either; the plunge after it is."""
    text = "%\nO1\nG21 G17 G90\nG00 Z50.\nG00 X10. Y10.\nG01 Z-1. F100.\nX20.\nM30\n%\n"
    bp = backplot(text, load_profile("fanuc-mill"))
    assert [m.lost for m in bp.moves] == [True, True, False, False]
    assert bp.moves[2].points == [(10, 10, 50), (10, 10, -1)]


def test_a_reference_return_is_not_drawn_to_the_work_zero() -> None:
    """G28 and G53 move in machine coordinates: no line to X0 Y0 of the part, and the next
    move of those axes starts from the unknown too."""
    text = ("%\nO1\nG21 G90 G00 X10. Y10. Z25.\nG01 Z0 F100.\nX20.\nG91 G28 Z0.\n"
            "G90 G00 X5. Y5.\nZ10.\nG01 X6.\nG53 G00 X0 Y0\nG00 X1. Y1.\nG01 X2.\nM30\n%\n")
    bp = backplot(text, load_profile("fanuc-mill"))
    drawn = [m.points for m in bp.moves if not m.lost]
    assert drawn == [[(10, 10, 25), (10, 10, 0)], [(10, 10, 0), (20, 10, 0)],
                     [(5, 5, 10), (6, 5, 10)], [(1, 1, 10), (2, 1, 10)]]


def test_a_full_circle_by_i_j_is_drawn() -> None:
    m = last_move("G02 X0. Y0. I10. J0")
    assert m.arc and on_circle(m, (10, 0), 10)
    assert turn(m, (10, 0)) == pytest.approx(-2 * math.pi)


def test_the_core_gives_r_arcs_their_centre_and_says_which_turn_over_180_degrees() -> None:
    """The path's segment of an R arc is an arc with the centre the checker's TG410 is decided
    by; a negative R is the arc over 180 degrees; an impossible R is a "chord"."""
    profile = load_profile("fanuc-mill")
    text = MILL.format("G02 X10. Y0. R5.\nG02 X20. Y10. R-10.\nG02 X30. Y10. R4.\n"
                       "G02 X30. Y10. R4.")
    checker = Checker(profile, record_path=True)
    list(checker.run_stream([text], profile.dialect))
    arcs = [(s.kind, s.centre, s.large) for s in checker.path or [] if s.line >= 6]
    assert arcs == [("arc", (5.0, 0.0, 0.0), False), ("arc", (10.0, 10.0, 0.0), True),
                    ("chord", None, False)]  # the last block moves nowhere: no segment
    assert sweep((1, 0, 0), (1, 0, 0), (0, 0, 0), 17, False) == pytest.approx(2 * math.pi)


def test_the_arcs_of_the_shipped_example_are_its_corners(sample_program: str) -> None:
    """bracket.nc: two quarter circles at the corners of its 90 x 80 rectangle, inside it (N7
    was a G02, a 270 degree loop out of the corner); the checker finds nothing wrong."""
    profile = load_profile("iso-mill")
    bp = backplot(sample_program, profile, file="bracket.nc")
    arcs = [m for m in bp.moves if m.arc]
    assert len(arcs) == 2
    # N4 G00 X10. Y10. Z5. starts wherever the machine is: drawn from there, not from X0 Y0
    assert bp.moves[0].lost and bp.moves[0].points == [(10, 10, 5)]
    assert bp.moves[1].points == [(10, 10, 5), (10, 10, -1.5)]
    for m in arcs:
        assert all(10 - 1e-9 <= p[0] <= 100 + 1e-9 and 10 - 1e-9 <= p[1] <= 90 + 1e-9
                   for p in m.points)
    assert turn(arcs[0], (90, 20)) == pytest.approx(math.pi / 2)
    assert turn(arcs[1], (90, 80)) == pytest.approx(math.pi / 2)
    assert not [f for f in bp.findings if f.severity in ("error", "warning")]


# -- the lathe view ------------------------------------------------------------------------------

LATHE = "%\nO1\nG18 G21 G40\nG00 X40. Z2.\nG01 X40. Z-10. F0.2\n{}\nM30\n%\n"


def test_a_lathe_draws_x_as_a_radius_with_z_across(tmp_path: Path) -> None:
    profile = load_profile("fanuc-lathe")
    assert default_view(profile) == "xz" and default_view(load_profile("fanuc-mill")) == "xy"
    bp = backplot(LATHE.format("G02 X60. Z-20. I10. K0\nG03 X80. Z-30. R10."), profile)
    assert bp.lathe and bp.diameter
    assert bp.moves[1].points[-1] == (20, 0, -10)  # X40. is a diameter: the radius 20
    # the I K arc: I is a radius, the centre is Z-10 X30 (radius), start and end on it
    ijk, by_r = bp.moves[2], bp.moves[3]
    assert on_circle(ijk, (-10, 30), 10, axes=(2, 0))
    assert turn(ijk, (-10, 30), axes=(2, 0)) == pytest.approx(-math.pi / 2)
    assert on_circle(by_r, (-30, 30), 10, axes=(2, 0))  # G03 R10 from Z-20 X30 to Z-30 X40
    out = tmp_path / "lathe.svg"
    result = CliRunner().invoke(main, ["plot", str(write(tmp_path, LATHE.format("G02 X60. "
                                       "Z-20. R10."))), "-p", "fanuc-lathe", "-o", str(out)])
    assert result.exit_code == 0, result.output
    svg = out.read_text()
    assert "(xz)" in svg  # the lathe's default view
    # Z across (the x label comes first in the file), X up, said to be the radius
    assert svg.index("Z (mm)") < svg.index("X/2 (mm, radius: X is programmed as a diameter)")


def test_an_okuma_lathe_draws_an_arc_by_its_radius_l() -> None:
    """The OSP lathe's G02/G03 give the radius by L (5238-E, P-26): drawn as the arc, and the
    same arc without L is the chord of an arc the checker cannot place (TG404)."""
    text = "$ARC.MIN%\nG00 X40. Z2.\nG01 X40. Z-10. F0.2\n{}\nM02\n"
    profile = load_profile("okuma-lathe")
    bp = backplot(text.format("G03 X60. Z-20. L10."), profile)
    assert bp.lathe and bp.diameter
    by_l = bp.moves[-1]
    assert by_l.arc and not by_l.impossible
    assert on_circle(by_l, (-20, 20), 10, axes=(2, 0))  # from Z-10 X20 to Z-20 X30 (radius)
    chord = backplot(text.format("G03 X60. Z-20."), profile).moves[-1]
    assert not chord.arc


def test_a_rotary_axis_is_not_drawn_and_the_picture_says_so(tmp_path: Path) -> None:
    text = MILL.format("G01 X10. A90.\nG01 Y10. A180.")
    bp = backplot(text, load_profile("fanuc-mill"))
    assert bp.not_drawn == ["A"]
    assert bp.moves[-1].points == [(10, 0, 0), (10, 10, 0)]  # degrees are not millimetres
    out = tmp_path / "a.svg"
    result = CliRunner().invoke(main, ["plot", str(write(tmp_path, text)), "-p", "fanuc-mill",
                                       "-o", str(out)])
    assert result.exit_code == 0 and "not drawn: A" in result.output
    assert "not drawn: A (the picture is the X Y Z path only; A B C are rotary" in \
        out.read_text()


# -- findings: markers, a legend grouped by rule and capped --------------------------------------

def finding(rule: str, severity: Severity, line: int) -> Finding:
    return Finding(rule, severity, "m", "f.nc", line, 1, "7")


def test_the_legend_groups_the_findings_by_rule_with_counts_and_is_capped() -> None:
    found = [finding(f"TG{100 + n}", "warning", 1) for n in range(12) for _ in range(n + 1)]
    found += [finding("TG401", "error", 2)] * 3
    groups = legend_groups(found)
    assert len(groups) == LEGEND_RULES + 1
    labels = [g[0] for g in groups]
    assert labels[0] == "TG401 error \u00d73"  # errors first, then the most frequent
    assert labels[1] == "TG111 warning \u00d712"
    assert labels[-1] == f"5 more rules \u00d7{1 + 2 + 3 + 4 + 5}"
    assert sum(g[2] for g in groups) == len(found)


def test_thousands_of_findings_are_a_few_legend_entries_not_labels(tmp_path: Path) -> None:
    """A TV-check finding per block and an arc error per block: markers, one legend entry per
    rule, no text label per finding."""
    body = "\n".join(f"G01 X{n}. Y{n % 7}." if n % 2 else f"G02 X{n}. Y0. R0.1"
                     for n in range(1, 1201))
    path = write(tmp_path, MILL.format(body))
    out = tmp_path / "many.svg"
    result = CliRunner().invoke(main, ["plot", str(path), "-p", "fanuc-mill", "-o", str(out)])
    assert result.exit_code == 0, result.output
    count = int(re.search(r"(\d+) findings marked", result.output)[1])  # type: ignore[index]
    assert count > 600
    svg = out.read_text()
    assert "TG410 error \u00d7600" in svg
    assert len(re.findall(r"<!-- TG\d+ ", svg)) <= LEGEND_RULES + 1  # the legend's, no more
    assert "600 R arcs that cannot exist drawn as chords" in result.output


def test_no_findings_hides_them(tmp_path: Path, sample_program: str) -> None:
    path = write(tmp_path, MILL.format("G02 X10. Y0. R4."))
    out = tmp_path / "p.svg"
    result = CliRunner().invoke(main, ["plot", str(path), "-p", "fanuc-mill", "-o", str(out),
                                       "--no-findings"])
    assert result.exit_code == 0, result.output
    assert "findings not shown" in result.output
    svg = out.read_text()
    assert "TG410" not in svg
    assert "R arc that cannot exist, chord drawn" in svg  # the chord is still marked
    result = CliRunner().invoke(main, ["plot", str(path), "-p", "fanuc-mill", "-o", str(out)])
    assert "TG410 error \u00d71" in out.read_text()


def write(folder: Path, text: str) -> Path:
    path = folder / "p.nc"
    path.write_text(text)
    return path


# -- real programs -------------------------------------------------------------------------------

@needs_corpus
@pytest.mark.parametrize(("name", "profile"), [
    ("AplicacionWebDePrueba__1010.nc", "haas-mill"),  # 8,600 blocks (speed: benchmarks.md)
    ("enier-cnc__round_head_plug.nc", "haas-lathe"),  # R arcs on a lathe, inch
    ("Five-Axis-Milling-Dataset__Bottle_opener_Flaschenoeffner.txt", "sinumerik-840d"),
])
def test_real_programs_plot(tmp_path: Path, name: str, profile: str) -> None:
    path = CORPUS / name
    if not path.exists():
        pytest.skip(f"{name} is not in the corpus")
    out = tmp_path / "p.png"
    result = CliRunner().invoke(main, ["plot", str(path), "-p", profile, "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert out.read_bytes()[:4] == b"\x89PNG"
    bp = backplot_file(str(path), load_profile(profile))
    assert bp.moves and all(math.isfinite(c) for m in bp.moves for p in m.points for c in p)
    # every move joins the one before it, unless the position was lost (a call: nothing drawn)
    for before, m in zip(bp.moves, bp.moves[1:], strict=False):
        assert m.lost or m.points[0] == pytest.approx(before.points[-1], abs=1e-9)
        assert not m.lost or len(m.points) == 1


def test_plot_counts_arcs_as_the_statistics_do(tmp_path: Path) -> None:
    """An R arc that cannot exist is drawn as its chord and is no arc: plot said '2 arcs' for
    two impossible ones where --stats said 0."""
    text = "%\nO1\nG21 G17\nG0 X0. Y0.\nG2 X10. Y0. R4. F100.\nG2 X20. Y0. R5.\nM30\n%\n"
    path = write(tmp_path, text)
    result = CliRunner().invoke(main, ["plot", str(path), "-p", "fanuc-mill",
                                       "-o", str(tmp_path / "p.svg")])
    assert "; 1 arc, 1 R arcs that cannot exist drawn as chords" in result.output, result.output
    stats = CliRunner().invoke(main, ["check", str(path), "-p", "fanuc-mill", "--stats"])
    assert "(1 arc at its true length)" in stats.output, stats.output


def test_blocks_that_set_or_shift_draw_nothing_and_the_picture_says_what_it_does_not_apply(
        tmp_path) -> None:
    """G52, G92, G92.1, G10 L2 and G51.1 take their axis words as data (FANUC 0i-MF "G code
    list"; rs274 runs `g52`/`g92` as SET_G92_OFFSET with no move): no segment is drawn to
    their words, no arc from an invented start, and the picture names the shifts, rotations,
    scalings and mirrors it draws in the program's coordinates."""
    from postproc.plot import plot, transforms_note

    text = ("%\nO1012\nG21 G17 G90\nG00 X110. Y0 Z5.\nG01 Z-1. F100.\nG52 X100. Y0\n"
            "G02 X20. Y0 I5. J0\nG52 X0 Y0\nG01 X130. Y0\nG92 X30. Y0\nG02 X40. Y0 I5. J0\n"
            "G68 X0 Y0 R30.\nG01 X50.\nG51.1 X0\nG01 X60.\nM30\n%\n")
    bp = backplot(text, load_profile("fanuc-mill"))
    drawn = [m for m in bp.moves if not m.lost and not m.adrift]
    # the plunge, and the moves under G68 and G51.1 (drawn unrotated and unmirrored: said);
    # G51.1's X0 is the mirror's axis, no move, as G68's X0 Y0 is its centre (review 15,
    # finding 2): the move after it starts where the one under G68 ended
    assert [m.line for m in drawn] == [5, 13, 15]
    assert [m.points for m in bp.moves if m.line == 15] == [[(50, 0, -1), (60, 0, -1)]]
    assert all(m.line not in (6, 8, 10, 14) for m in bp.moves)  # the setting blocks
    assert [m.line for m in bp.moves if m.arc] == []  # both arcs start where nobody draws
    note = transforms_note(bp)
    assert note.startswith("not applied: G52 (line 6), G52 (line 8), G92 (line 10), "
                           "G68 (line 12), G51.1 (line 14): the moves after them")
    out = tmp_path / "p.svg"
    plot(bp, str(out))
    assert "not applied: G52 (line 6)" in out.read_text()
    assert transforms_note(backplot("G21 G90\nG00 X1. Y1. Z1.\nG01 X2. F100.\nM30\n",
                                    load_profile("fanuc-mill"))) == ""


def test_the_units_are_those_the_moves_run_in_program_by_program() -> None:
    """A main program in inch, then a program with no units code that no call names, read in
    the reset units (metric, as convert reads it): the picture is in both, not "inch". The
    same program called by the main program's M98 runs in its caller's inches (review 38,
    finding 10: the check reads a subprogram after M30 in the units of its calls)."""
    text = ("%\nO1000\nG20 G90\nG00 X1. Y1. Z1.\nM98 P2000\nM30\n%\n"
            "%\nO2000\nG00 X10. Y10. Z1.\nG01 X20. F100.\nM99\n%\n")
    assert backplot(text.replace("P2000", "P3000"), load_profile("fanuc-mill")).units == "mixed"
    assert backplot(text, load_profile("fanuc-mill")).units == "inch"
    assert backplot("G20 G90\nG00 X1. Y1. Z1.\nG21\nM30\n",
                    load_profile("fanuc-mill")).units == "inch"  # no move after the G21


def test_moves_after_a_g10_for_another_work_system_are_drawn() -> None:
    """G10 L2 P2 sets G55 while G54 is in force: the moves after it are where the program
    left them, drawn from there (not lost, not adrift); G10 L2 P1 (G54, in force) shifts the
    named axes: the move after it starts where nobody knows (lost)."""
    text = ("%\nO1\nG21 G17 G90 G54\nG0 X10. Y10. Z5.\nG1 Z-1. F100.\n{g10}\nG1 Y20.\n"
            "G10 L11 P1 R0.1\nG1 X30.\nM30\n%\n")
    bp = backplot(text.format(g10="G10 L2 P2 X100. Y0 Z0"), load_profile("fanuc-mill"))
    after = [m for m in bp.moves if m.line > 6]
    assert [(m.line, m.lost, m.adrift, m.points) for m in after] == [
        (7, False, frozenset(), [(10, 10, -1), (10, 20, -1)]),
        (9, False, frozenset(), [(10, 20, -1), (30, 20, -1)]),
    ]
    bp = backplot(text.format(g10="G10 L2 P1 X100. Y0 Z0"), load_profile("fanuc-mill"))
    assert [m.lost for m in bp.moves if m.line == 7] == [True]


def test_after_a_code_the_list_lacks_the_picture_draws_no_rapid_and_says_why(tmp_path) -> None:
    """A system B/C lathe's G33 thread on fanuc-lathe (system A: no such code; the control
    alarms or runs a macro): the pass is not drawn as the G00 in force, and the picture says
    from which line its moves are not known. The G00 after it is drawn again."""
    from postproc.plot import plot

    text = ("%\nO1201\nG21 G99 G54\nG97 S500 M3\nG0 X15.405 Z-0.672\nG33 Z-17.328 F1.5\n"
            "G0 X18. Z-18.\nM30\n%\n")
    bp = backplot(text, load_profile("fanuc-lathe"))
    assert [(m.line, m.kind) for m in bp.moves] == [(5, "rapid"), (7, "rapid")]
    assert bp.moves_not_known[0].startswith("from line 6: G33 is not in the family's code list")
    out = tmp_path / "p.svg"
    plot(bp, str(out), view="xz")
    assert "moves not known from line 6: G33" in out.read_text()
