"""Travel limits (TG601): machine positions through the work offsets a profile gives
(``[work_offsets]``), and the span of the program where it gives none; ``--stats`` says which."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from formats.errors import ProfileError
from formats.profile import Profile, builtin_text, load_profile, profile_from_text
from postproc.check import Checker, Finding
from tapegate.cli import main

# fanuc-mill's travel: X -762 to 762, Y -406 to 406, Z -508 to 10
OFFSETS = ("\n[work_offsets]\nG54 = { X = -400.0, Y = -200.0, Z = -300.0 }\n"
           "G55 = { X = 200.0, Y = -200.0 }\n")
MILL = "%\nO1\nG21 G17 G90 G94 G40 G49 G80\n{}\nM30\n%\n"


def with_offsets(base: str = "fanuc-mill", extra: str = OFFSETS) -> Profile:
    return profile_from_text(builtin_text(base) + extra, default_name=base)


def check(body: str, profile: Profile) -> tuple[list[Finding], Checker]:
    checker = Checker(profile)
    found = list(checker.run_stream([MILL.format(body)], profile.dialect))
    return [f for f in found if f.rule == "TG601"], checker


def lines(found: list[Finding]) -> list[tuple[int, int]]:
    return [(f.line, f.column) for f in found]


def test_a_machine_position_outside_the_travel_is_found_once_per_excursion() -> None:
    body = "G54 G00 X100. Y0\nX-400.\nX-450.\nX0\nX-500. Y10."
    found, checker = check(body, with_offsets())
    assert lines(found) == [(5, 1), (8, 1)]  # X-400 leaves the travel; X-500 leaves it again
    assert found[0].message == ("X goes to -800 in machine coordinates (work -400 + G54 offset "
                                "-400.0), outside the travel -762 to 762")
    assert checker.stats.travel_absolute == checker.stats.travel_moves == 7
    assert checker.stats.travel_not == []
    # the span of the program (600) fits the travel (1524): without offsets nothing is found
    found, checker = check(body, load_profile("fanuc-mill"))
    assert found == [] and checker.stats.travel_moves == 0


def test_the_offset_in_force_is_the_one_selected() -> None:
    """G55 X200: X-400 is machine -200, inside; the same move under G54 is outside."""
    found, _ = check("G55 G00 X-400. Y0", with_offsets())
    assert found == []
    found, _ = check("G55 G00 X0 Y0\nG54 X-400.", with_offsets())
    assert lines(found) == [(5, 5)]


def test_z_is_not_compared_while_a_tool_length_offset_is_in_force() -> None:
    """Z-250 under G54 Z-300 is machine -550, below -508: an error without G43, and not
    compared with it (the profile gives no tool lengths), said once in the statistics."""
    found, checker = check("G54 G00 X0 Y0\nG43 H1 Z-250.\nZ-260.", with_offsets())
    assert found == []
    assert checker.stats.travel_not == [
        "Z while a tool length offset was in force (the profile gives no tool lengths)"]
    found, _ = check("G54 G00 X0 Y0\nG49 Z-250.", with_offsets())
    assert [f.message.split(" (")[0] for f in found] == ["Z goes to -550 in machine coordinates"]


def test_an_axis_the_offset_does_not_list_is_not_compared() -> None:
    found, checker = check("G55 G00 X0 Y0\nZ-600.", with_offsets())
    assert found == []
    assert checker.stats.travel_not == ["Z under G55: the profile gives no G55 Z"]


@pytest.mark.parametrize(("shift", "why"), [
    ("G92 X0 Y0", "G92 shifts the coordinates"),
    ("G52 X10.", "G52 shifts the coordinates"),
    # (a G10 whose value is not known: under G91 it adds to the offset)
    ("G91 G10 L2 P1 X-100.", "G10 sets offsets"),
    ("G54.1 P1", "G54.1 selects an offset the profile does not give"),
    ("M98 P1000", "a jump or call the checker does not follow"),
])
def test_after_a_shift_the_profile_cannot_know_positions_are_not_compared(shift: str,
                                                                          why: str) -> None:
    found, checker = check(f"G54 G00 X0 Y0\n{shift}\nG54 G00 X-400. Y0", with_offsets())
    assert found == []
    assert checker.stats.travel_not == [f"from line 5 on: {why} (the offsets may have changed)"]


@pytest.mark.parametrize(("g10", "expected"), [
    # G54's X written -100: X-400. runs at -500, inside
    ("G10 L2 P1 X-100.", []),
    # written -400, the profile's: X-400. runs at -800, said with the value written
    ("G10 L2 P1 X-400.", ["X goes to -800 in machine coordinates (work -400 + G54 offset -400 "
                          "as a G10 before wrote it)"]),
    # G55's X written: G54's positions as the profile's make them (X-450. at -850)
    ("G10 L2 P2 X0.", ["X goes to -850 in machine coordinates (work -450 + G54 offset -400.0)"]),
])
def test_a_g10_of_a_value_known_judges_the_program_s_own_moves_after_it(
        g10: str, expected: list[str]) -> None:
    """Review 59a, F8: a `G10 L2 Pn` of numbers under G90 sets that offset's axis to the value
    written (FANUC 0i-MF Operator's Manual, "Changing workpiece coordinate system"): the
    program's own moves after it are judged with it, not left out of the comparison."""
    x = "X-450." if "P2" in g10 else "X-400."
    found, checker = check(f"G54 G00 X0 Y0\n{g10}\nG54 G00 {x} Y0", with_offsets())
    assert [f.message.split(", outside")[0] for f in found] == expected
    assert checker.stats.travel_not == []


def test_without_a_selection_nothing_is_compared_and_g53_is_one_block() -> None:
    found, checker = check("G00 X-400. Y0", with_offsets())
    assert found == []
    assert checker.stats.travel_not == [
        "where the program has selected no work offset (G54-G59)"]
    # G53 is a machine position for its block (checked as it is); G54 stays in force
    found, _ = check("G54 G00 X0 Y0\nG53 Z0\nX-400.", with_offsets())
    assert lines(found) == [(6, 1)]


def test_an_inch_program_is_compared_in_the_profile_s_units() -> None:
    """G20 X-16. is -406.4 mm; with G54's X-400 mm that is -806.4, outside -762."""
    found, _ = check("G20\nG54 G00 X-16. Y0", with_offsets())
    assert [f.message.split(" (")[0] for f in found] == [
        "X goes to -806.4 in machine coordinates"]


def test_the_span_check_still_runs_and_is_not_said_twice() -> None:
    """A program wider than the travel: the machine position is said, the span not again."""
    found, _ = check("G54 G00 X700. Y0\nX-800.", with_offsets())
    assert [f.message.split(" in ")[0] for f in found] == ["X goes to -1200"]
    found, _ = check("G00 X700. Y0\nX-900.", with_offsets())  # no selection: the span
    assert [f.message.split(" (")[0] for f in found] == ["X spans 1600"]


@pytest.mark.parametrize(("extra", "key"), [
    ("[work_offsets]\nG60 = { X = 1.0 }\n", "work_offsets.G60"),  # not a work offset
    ("[work_offsets]\nG54 = 5\n", "work_offsets.G54"),  # not a table of axis positions
    ("[work_offsets]\nG54 = { Q = 1.0 }\n", "work_offsets.G54.Q"),  # not an axis
    ("[work_offsets]\nG54 = { A = 1.0 }\n", "work_offsets.G54.A"),  # the profile has no limits.A
    ("[work_offsets]\nG54 = { X = \"-400\" }\n", "work_offsets.G54.X"),  # not a number
])
def test_bad_work_offsets_are_profile_errors_that_name_the_key(extra: str, key: str) -> None:
    with pytest.raises(ProfileError) as error:
        profile_from_text("[limits]\nX = [-500, 500]\n" + extra, source="mine.toml")
    assert (error.value.code, error.value.key) == ("profile-value", key)
    assert error.value.file == "mine.toml"


@pytest.mark.parametrize(("base", "why"), [("fanuc-lathe", "not on a lathe"),
                                           ("heidenhain-iso", "not on a Heidenhain")])
def test_work_offsets_are_refused_where_they_are_not_all_that_shifts(base: str,
                                                                      why: str) -> None:
    with pytest.raises(ProfileError) as info:
        with_offsets(base, "\n[work_offsets]\nG54 = { X = 1.0 }\n")
    assert (info.value.code, info.value.key) == ("profile-value", "work_offsets")
    assert why in info.value.message  # the reason the machine kind refuses them


def test_stats_say_which_travel_check_was_made(tmp_path: Path) -> None:
    path = tmp_path / "p.nc"
    path.write_text(MILL.format("G54 G00 X0 Y0\nG43 H1 Z5."))
    profile = tmp_path / "m.toml"
    profile.write_text(builtin_text("fanuc-mill") + OFFSETS)
    r = CliRunner().invoke(main, ["check", str(path), "-p", str(profile), "--stats"])
    assert ("  travel: machine positions through the profile's work offsets for 2 of 3 axis "
            "moves, and the span of each axis\n    not compared: Z while a tool length offset "
            "was in force") in r.output
    r = CliRunner().invoke(main, ["check", str(path), "-p", "fanuc-mill", "--stats"])
    assert ("  travel: the span of each axis against the travel (the profile gives no work "
            "offsets)") in r.output
    r = CliRunner().invoke(main, ["check", str(path), "-p", str(profile), "--stats",
                                  "--format", "json"])
    travel = json.loads(r.output)["stats"][str(path)]["travel"]
    assert travel == {"check": "machine positions and span", "moves": 3, "compared": 2,
                      "not_compared": ["Z while a tool length offset was in force (the "
                                       "profile gives no tool lengths)"]}


SIEMENS = "G17 G90 G71\n{}\nM30\n"
SIEMENS_OFFSETS = "\n[work_offsets]\nG54 = { X = -500.0, Y = 0.0 }\n"


@pytest.mark.parametrize(("shift", "why"), [
    ("TRANS X10", "the frame TRANS moves the coordinates"),
    # a frame turned to the tool (G group 53 of the Fundamentals' "List of G functions")
    ("TOROT", "the frame TOROT moves the coordinates"),
    ("tofrAMEZ", "the frame TOFRAMEZ moves the coordinates"),
    ("G505", "G505 is an offset the profile does not give"),
    ("G58 X10", "G58 is an offset the profile does not give"),
    # a frame set by assignment, as TRANS sets it (Programming Guide Advanced, "Frames":
    # $P_PFRAME=CTRANS(X,10) "or TRANS X10"), the settable and basic frames too
    ("$P_PFRAME=CTRANS(X,-300)", "the frame $P_PFRAME is set"),
    ("$P_UIFR[1]=CTRANS(X,10)", "the frame $P_UIFR is set"),
    ("$P_UIFR[1,X,TR]=10", "the frame $P_UIFR is set"),
    ("$p_bframe = CTRANS(X,5)", "the frame $P_BFRAME is set"),
])
def test_sinumerik_frames_and_its_other_offsets_end_the_comparison(shift: str, why: str) -> None:
    profile = with_offsets("sinumerik-840d", SIEMENS_OFFSETS)
    checker = Checker(profile)
    text = SIEMENS.format(f"G54 G0 X-200 Y0\nX-400\n{shift}\nG54 G0 X-400")
    found = [f for f in checker.run_stream([text], profile.dialect) if f.rule == "TG601"]
    assert [(f.line, f.message.split(" (")[0]) for f in found] == [
        (3, "X goes to -900 in machine coordinates")]
    assert checker.stats.travel_not == [f"from line 4 on: {why} (the offsets may have changed)"]


def test_reading_a_frame_is_no_frame_set() -> None:
    profile = with_offsets("sinumerik-840d", SIEMENS_OFFSETS)
    checker = Checker(profile)
    text = SIEMENS.format("G54 G0 X0 Y0\nR1=$P_PFRAME[X,TR]\nG0 X-400")
    found = [f.line for f in checker.run_stream([text], profile.dialect) if f.rule == "TG601"]
    assert found == [4] and checker.stats.travel_not == []


@pytest.mark.parametrize("transformation", ["TRACYL(400)", "TRAORI(1)", "TRANSMIT(1)",
                                            "TRAORI", "traang(1)"])
def test_a_sinumerik_transformation_ends_the_comparison_until_trafoof(
        transformation: str) -> None:
    """Under a kinematic transformation the axes are programmed in other coordinates (under
    TRACYL, Y is the distance round the cylinder): neither a machine position nor a span is
    compared until TRAFOOF, after which both are again."""
    profile = with_offsets("sinumerik-840d", SIEMENS_OFFSETS)
    checker = Checker(profile)
    body = (f"G54 G0 X0 Y0\n{transformation}\nG0 X-400 Y3000\nY-3000\nTRAFOOF\n"
            "G0 X-400 Y0")
    found = [(f.line, f.column) for f in checker.run_stream([SIEMENS.format(body)],
                                                          profile.dialect)
             if f.rule == "TG601"]
    assert found == [(7, 4)]  # X-400 + G54 X-500, outside -800 to 800
    name = transformation.split("(")[0].upper()
    assert checker.stats.travel_not == [
        f"from line 3 on: the transformation {name} programs the axes in other coordinates "
        "(until TRAFOOF)"]


def test_a_tool_length_offset_by_a_decimal_code_counts_too() -> None:
    """LinuxCNC's G43.1 (a dynamic tool length): Z is not compared until G49."""
    toml = builtin_text("linuxcnc").replace("[limits]\n", "[limits]\nX = [-300, 300]\n"
                                                          "Z = [-200, 0]\n")
    profile = profile_from_text(toml + "\n[work_offsets]\nG54 = { X = 0.0, Z = -100.0 }\n")
    checker = Checker(profile)
    text = "G21 G90 G54\nG0 X0 Z0\nG43.1 Z-150\nG0 Z-160\nG49\nG0 Z-150\nM2\n"
    found = [f for f in checker.run_stream([text], profile.dialect) if f.rule == "TG601"]
    assert [f.line for f in found] == [6]


@pytest.mark.parametrize("code", ["G68 X0 Y0 R90.", "G51 X0 Y0 Z0 P2.", "G51.1 X0", "G16",
                                  "G101 X0"])
def test_rotation_scaling_mirror_and_polar_end_the_comparison(code: str) -> None:
    """After G68 (rotation), G51 (scaling), G51.1/G101 (mirror) or G16 (polar) a work
    position is no longer the machine position plus the offset: X-450 under G54 would be
    outside, but it is not compared, and --stats says why (the review found X 35 where the
    travel ends at 30, rotated, and not reported)."""
    found, checker = check(f"G54 G00 X0 Y0\n{code}\nG00 X-450.", with_offsets())
    assert found == []
    assert any("rotates, scales or mirrors" in why or "mirrors the coordinates" in why
               for why in checker.stats.travel_not), checker.stats.travel_not


def test_the_centre_of_a_rotation_or_scaling_is_no_move() -> None:
    """G68 X-10. Y0 R90. and G51 X0 Y0 P2. give a centre: the extents do not reach it."""
    _, checker = check("G54 G00 X5. Y5.\nG68 X-300. Y-300. R90.\nG69\nG51 X300. Y0 P2.\nG50",
                       with_offsets())
    stats = checker.stats
    assert (stats.low["X"], stats.high["X"], stats.low["Y"], stats.high["Y"]) == (5, 5, 5, 5)


def test_a_move_from_one_side_of_the_travel_to_the_other_is_another_excursion() -> None:
    """X-770 is outside below; G55 X600. is machine 800, outside above: the move crosses the
    whole travel and is found again (it counted as the same excursion)."""
    found, _ = check("G54 G00 X-370. Y0\nG55 X600.\nX-600.", with_offsets())
    assert lines(found) == [(4, 9), (5, 5)]


@pytest.mark.parametrize("cancel", ["G50", "G15", "G100", "G50.1 X0"])
def test_a_cancel_ends_only_its_own_frame(cancel: str) -> None:
    """Review 12: one flag for every frame, cleared by any cancel, so `G50` under G68 restarted
    the spans and the real G69 then did not: X-25. rotated (machine Y) and X40. after G69 made
    a false 'X spans 65'. Each frame is its own; a cancel of a frame not on restarts nothing."""
    text = ("%\nO01000\nG20 G90 G54 G00 X0 Y0\nG68 X0 Y0 R90.\n" + cancel +
            "\nG00 X-25.\nG00 X0\nG69\nG00 X40.\nM30\n%\n")
    profile = load_profile("haas-mill")
    found = [f for f in Checker(profile).run_stream([text], profile.dialect)
             if f.rule == "TG601"]
    assert found == []
    # without the rotation the same moves span 65 in, more than the 30 in travel
    plain = text.replace("G68 X0 Y0 R90.\n", "").replace("G69\n", "")
    found = [f for f in Checker(profile).run_stream([plain], profile.dialect)
             if f.rule == "TG601"]
    assert [f.line for f in found] == [7]


def haas_travel(body: str) -> list[Finding]:
    """TG601 and TG140 of `body` on haas-mill (travel X -30 to 30, Y -16 to 16 in)."""
    text = f"%\nO01000\nG20 G17 G90 G54\n{body}\nM30\n%\n"
    profile = load_profile("haas-mill")
    return [f for f in Checker(profile).run_stream([text], profile.dialect)
            if f.rule in ("TG601", "TG140")]


@pytest.mark.parametrize(("body", "expected"), [
    # under R90 the program's Y 0 to 40 is machine X 0 to -40: inside X's 60 in
    ("G68 X0 Y0 R90.\nG00 X0 Y0\nY40.\nG69", []),
    # and its X 0 to 40 is machine Y 0 to 40, more than Y's 32 in
    ("G68 X0 Y0 R90.\nG00 X0 Y0\nX40.\nG69", [(6, "TG601", "Y spans 40 (from 0 to 40)")]),
    # about the centre X10. Y0: X0 Y0 is X10. Y-10. before the frame, X0 Y30. X-20. Y-10.;
    # Y23. after it spans 33 with them (as the program's, Y 0 to 30 and 23 span 30)
    ("G00 X20. Y0\nG68 X10. Y0 R90.\nG00 X0 Y0\nX0 Y30.\nG69\nY23.",
     [(9, "TG601", "Y spans 33 (from -10 to 23)")]),
    # X alone under the frame: where Y stands in its coordinates is not known, said
    ("G00 X0 Y0\nG68 X0 Y0 R90.\nX40.\nG69",
     [(6, "TG140", "G68 of line 5: the positions of X Y under it are not compared with the "
                   "travel (TG601) until every axis they are made of is given there")]),
    # Haas G51 P2.: Y20. is machine Y40.
    ("G00 X0 Y0 Z0\nG51 X0 Y0 Z0 P2.\nY20.\nG50", [(6, "TG601", "Y spans 40 (from 0 to 40)")]),
    ("G00 X0 Y0 Z0\nG51 X0 Y0 Z0 P2.\nY7.\nG50", []),
    # the positions before the frame and after its cancel are in one frame: Y-20. and Y20.
    # (X1. alone under the frame is not compared, said)
    ("G00 X0 Y-20.\nG68 X0 Y0 R90.\nX1.\nG69\nG00 Y20.",
     [(6, "TG140", "G68 of line 5"), (8, "TG601", "Y spans 40 (from -20 to 20)")]),
    # the cancel applies to its own block's move
    ("G00 X0 Y-20.\nG68 X0 Y0 R90.\nX1.\nG69 G00 Y20.",
     [(6, "TG140", "G68 of line 5"), (7, "TG601", "Y spans 40 (from -20 to 20)")]),
    ("G00 X0 Y-20.\nG51 X0 Y0 Z0 P1.\nG00 Y20. G50",
     [(6, "TG601", "Y spans 40 (from -20 to 20)")]),
])
def test_spans_under_a_rotation_or_scaling_are_the_machine_s(
        body: str, expected: list[tuple[int, str, str]]) -> None:
    """Review 13, 2: the spans under G68 and G51 were the program's, compared with the machine
    axis of the same letter (a false TG601 under R90, an over-travel missed), and a cancel
    dropped the positions from before the frame. Each position is taken back through the
    frame; the spans run on across its cancel."""
    found = haas_travel(body)
    assert [(f.line, f.rule) for f in found] == [(line, rule) for line, rule, _ in expected]
    for f, (_, _, text) in zip(found, expected, strict=True):
        assert f.message.startswith(text), f.message


@pytest.mark.parametrize(("frame", "why"), [
    # a FANUC-style scaling on haas-mill is Haas's; R from a parameter; a 3-D rotation; G268
    ("G51 X0 Y0 Z0", "no P"),
    ("G68 X0 Y0", "no R"),
    ("G68 X0 Y0 R90", "without a decimal point"),
    ("G68 X0 Y0 Z0 I0 J0 K1 R90.", "three-dimensional"),
    ("G91 G68 X0 Y0 R90.", "under G91"),
])
def test_a_frame_not_known_exactly_is_said_and_its_positions_left_out(
        frame: str, why: str) -> None:
    """Where the frame's words do not say exactly where it puts the axes, its positions are
    left out of the spans with a note (neither a false refusal nor a silent pass); the spans
    of the positions before and after it run on."""
    cancel = "G50" if frame.startswith("G51") else "G69"
    # as the program's, X40. Y40. and X-40. would span 80 and 50; Y25. after the cancel
    # spans 35 with Y-10. before the frame
    found = haas_travel(f"G00 X0 Y-10. Z0\n{frame}\nG90 G00 X40. Y40.\nX-40.\n{cancel}\n"
                        "G90 G00 Y25.")
    assert [(f.line, f.rule) for f in found] == [(5, "TG140"), (9, "TG601")], found
    assert why in found[0].message and "not compared with the travel" in found[0].message
    assert found[1].message.startswith("Y spans 35 (from -10 to 25)"), found[1].message


@pytest.mark.parametrize(("body", "expected"), [
    # review 15, 2a: G50.1 X0 ends X's mirror alone; Y17.5 is still Y-17.5, 32.5 from Y15.
    ("G00 X0 Y15.\nG51.1 X0 Y0\nG00 X1. Y1.\nG50.1 X0\nG00 Y17.5",
     [(8, "TG601", "Y spans 32.5 (from -17.5 to 15)")]),
    ("G00 X0 Y15.\nG51.1 X0 Y0\nG00 X1. Y1.\nG50.1 X0 Y0\nG00 Y17.5", []),
    # 2b: a second G51.1 adds Y about -5: Y12. is Y-22., 34 from Y12.
    ("G00 X0 Y12.\nG51.1 X0\nG51.1 Y-5.\nG00 Y12.\nG50.1 X0 Y0",
     [(7, "TG601", "Y spans 34 (from -22 to 12)")]),
    # the mirror's words are no move: G51.1 X40. leaves the tool at X-25. (no span of 65),
    # X75. under it is X5.
    ("G00 X-25. Y0\nG51.1 X40.\nG00 X75.\nG50.1 X0", []),
    # and G50.1 X0 leaves it at X-5. (X5. about X0): X-30. from there is X-35., 64 from X29.
    ("G00 X29. Y0\nG51.1 X0\nG00 X5.\nG50.1 X0\nG91 G00 X-30.\nG90",
     [(8, "TG601", "X spans 64 (from -35 to 29)")]),
])
def test_a_mirror_is_kept_axis_by_axis(body: str, expected: list[tuple[int, str, str]]) -> None:
    """Review 15, 2: the exact mirror was all or nothing -- G50.1 X0 ended Y's too, a second
    G51.1 was ignored -- and G51.1's and G50.1's axis words were read as moves (a false span
    of 65, a missed one of 64)."""
    found = haas_travel(body)
    assert [(f.line, f.rule) for f in found] == [(line, rule) for line, rule, _ in expected]
    for f, (_, _, text) in zip(found, expected, strict=True):
        assert f.message.startswith(text), f.message


def test_an_okuma_mill_s_frames_are_left_out_with_a_note() -> None:
    """Review 15, 3: okuma-mill (Y -400 to 400) read G11 X0 Y0 R90. as a move and no frame:
    X600. under it (Y600. if the rotation is as written) was compared as X, silently. Its
    words are in no page at hand: X Y Z under G11 (until G10) and G62 are left out, said."""
    profile = load_profile("okuma-mill")
    for frame, cancel, until in (("G11 X0 Y0 R90.", "G10", "until its cancel"),
                                 ("G62 X10.", "", "to the end of the file")):
        text = (f"%\nO01000\nG21 G17 G90\nG00 X0 Y-300.\n{frame}\nG00 X600. Y0\nX-500.\n"
                f"{cancel}\nM30\n%\n")
        found = [f for f in Checker(profile).run_stream([text], profile.dialect)
                 if f.rule in ("TG601", "TG140")]
        assert [(f.line, f.rule) for f in found] == [(5, "TG140")], found
        assert found[0].message.startswith(f"{frame.split()[0]}: the positions of X Y Z under "
                                           "it are not compared"), found[0].message
        assert until in found[0].message, found[0].message


@pytest.mark.parametrize(("base", "setting", "none"), [
    ("fanuc-lathe", "G50", "G92"), ("fanuc-lathe-b", "G92", "G50"),
    ("fanuc-lathe-c", "G92", "G50")])
def test_a_lathe_s_coordinate_setting_restarts_the_span_by_its_code_system(
        base: str, setting: str, none: str) -> None:
    """Review 15, 4: in G code systems B and C the coordinate setting is G92 (A's G50); the
    written number was read, so B's G92 left X180. and X-60. in one span of 240 (a false
    TG601) and a written G50, no code there, started the span again. (The setting at X180.
    is followed since review 38: X-60. is 120 in the coordinates before it, a span of 60.)"""
    profile = profile_from_text(f'base = "{base}"\n[limits]\nX = [-100, 100]\n'
                                "Z = [-100, 100]\n")
    text = "%\nO01000\nG21 G18\nG00 X180. Z0\n{} X0 Z0\nG00 X-60.\nM30\n%\n"
    for code, spans in ((setting, []), (none, [6])):
        found = [f.line for f in Checker(profile).run_stream([text.format(code)],
                                                             profile.dialect)
                 if f.rule == "TG601"]
        assert found == spans, (base, code)


def test_a_haas_mirror_s_words_are_no_move_and_its_cancel_is_per_axis() -> None:
    """Review 16b, 2 (Haas VF Series manual 96-8000, G101: the mirror is selected axis by
    axis, about the work zero): G100/G101's X is the axis named, no move to it (G100 X32. was
    a false `X spans 61`), and G100 X0 ends X's mirror alone: a mirrored Y15. (at -15) was
    compared with Y-15. as a span of 32.5 after it."""
    haas = load_profile("haas-mill")  # X -30..30, Y -16..16 in
    found, _ = check("G20 G54\nG00 X-29. Y0\nG101 X32.\nG00 X-29.\nG100 X32.", haas)
    assert found == []
    found, _ = check("G20 G54\nG00 X0 Y-15.\nG101 X0 Y0\nG00 X1. Y1.\nG100 X0\nG00 Y15.\n"
                     "G100 Y0", haas)
    assert found == []
    # Y is still mirrored after G100 X0: Y18. is not compared with the Y-15. before it
    found, _ = check("G20 G54\nG00 X0 Y-15.\nG101 X0 Y0\nG100 X0\nG00 Y18.\nG100 Y0", haas)
    assert found == []
    # after the last axis's cancel the positions are compared again
    found, _ = check("G20 G54\nG00 X0 Y-15.\nG101 X0 Y0\nG100 X0\nG100 Y0\nG00 Y18.", haas)
    assert [(f.line, f.message.split(",")[0]) for f in found] == [
        (9, "Y spans 33 (from -15 to 18)")]
    # a move to X32. is one, after the cancel as before
    found, _ = check("G20 G54\nG00 X-29. Y0\nG101 X32.\nG00 X-29.\nG100 X32.\nG00 X32.",
                     haas)
    assert [(f.line, f.message.split(",")[0]) for f in found] == [
        (9, "X spans 61 (from -29 to 32)")]


@pytest.mark.parametrize(("body", "expected"), [
    # review 16b, 2b: G100 X0 ends X's mirror alone; Y17.5 under the mirror of Y is Y-17.5,
    # 32.5 from the Y15. before it (it stood apart from it, and the over-travel was missed)
    ("G00 X0 Y15.\nG101 X0 Y0\nG00 X1. Y1.\nG100 X0\nG00 Y17.5\nG100 Y0",
     [(9, "Y spans 32.5 (from -17.5 to 15)")]),
    # about the work zero whatever the word's value, under G91 too: X31.5 is
    ("G00 X29. Y0\nG101 X5.\nG00 X31.5\nG100 X0", [(7, "X spans 60.5 (from -31.5 to 29)")]),
    ("G00 X29. Y0\nG91 G101 X0\nG90 G00 X31.5\nG100 X0",
     [(7, "X spans 60.5 (from -31.5 to 29)")]),
    # a second G101 of X leaves it mirrored as it was (Settings 45-48: one setting an axis)
    ("G00 X-29. Y0\nG101 X0\nG00 X-29.5\nG101 X0\nG00 X-31.5\nG100 X0",
     [(9, "X spans 60.5 (from -29 to 31.5)")]),
    # the true span under the mirror is no error: Y15. there is Y-15., 2.5 from Y-17.5
    ("G00 X0 Y-15.\nG101 X0 Y0\nG00 X1. Y15.\nG100 X0\nG00 Y17.5\nG100 Y0", []),
    # after a G52 the work zero is not known in the program's coordinates: apart, not
    # compared
    ("G52 X1.\nG00 X29. Y0\nG101 X0\nG00 X31.5\nG100 X0", []),
])
def test_a_haas_mirror_is_about_the_work_zero_axis_by_axis(
        body: str, expected: list[tuple[int, str]]) -> None:
    """Review 17 (16b, 2b left open): a Haas's G101 mirrors the axes it names about the work
    coordinate zero point (96-8000, p. 201), exactly, as G51.1 X0 does: its positions are
    taken back through it and compared with those before it, a partial G100 included."""
    found, _ = check(f"G20 G54\n{body}", load_profile("haas-mill"))
    assert [(f.line, f.message.split(",")[0]) for f in found] == expected, found


def test_g100_and_g101_are_no_mirror_on_a_fanuc() -> None:
    """Review 17: a FANUC's code list has no G100/G101 (the control alarms, or a parameter
    makes it a macro call): `G101 X0` mirrored nothing, and X780. after it, 1530 from X-750.,
    was left apart from it (a missed over-travel). Such a code is read as any code the table
    lacks."""
    fanuc = load_profile("fanuc-mill")  # X -762..762 mm
    found, _ = check("G21 G54\nG00 X-750. Y0\nG101 X0\nG00 X780.", fanuc)
    assert [(f.line, f.message.split(",")[0]) for f in found] == [
        (7, "X spans 1530 (from -750 to 780)")]
    found, _ = check("G21 G54\nG00 X-750. Y0\nG100 X0\nG00 X780.", fanuc)
    assert [(f.line, f.message.split(",")[0]) for f in found] == [
        (7, "X spans 1530 (from -750 to 780)")]


def test_an_okuma_mill_s_g53_to_g59_are_length_offsets_not_coordinates() -> None:
    """Review 16b, 4: on an OSP mill G53 cancels the tool length offset and G54-G59 select it
    by axis (OSP List of G Codes; the work system is G15 H). G53's Y390. was taken for a
    machine position and left out of the span (a missed TG601), its Y450. compared with the
    travel as one (a false TG601), and G54 H1 applied the profile's G54 work offset."""
    okuma = load_profile("okuma-mill")  # Y -400..400 mm
    found, _ = check("G15 H1\nG00 X0 Y-450.\nG53 G00 Y390.\nG00 X0", okuma)
    assert [(f.line, f.message.split(",")[0]) for f in found] == [
        (6, "Y spans 840 (from -450 to 390)")]
    found, _ = check("G15 H1\nG00 X0 Y0\nG53 G00 Y450.\nG00 X0", okuma)
    assert found == []
    offsets = with_offsets("okuma-mill",
                           "\n[work_offsets]\nG54 = { X = -500.0, Y = 0.0, Z = 0.0 }\n")
    found, _ = check("G15 H2\nG00 X0 Y0\nG54 H1 G00 Z50.\nG00 X-200.", offsets)
    assert found == []


def test_a_second_mirror_of_an_axis_already_mirrored_stands_apart_with_a_note() -> None:
    """Review 16b, 5: `G51.1 X5.` on an X already mirrored about 0 was taken to move the
    point (X-25. at 35: a TG601 `X spans 64`); no page at hand says whether it does that or
    mirrors the mirror (X-25. at -35: 45). The positions stand apart, with a TG140 note."""
    haas = load_profile("haas-mill")
    body = "G20 G54\nG00 X-29. Y0\nG51.1 X0\nG00 X-10.\nG51.1 X5.\nG00 X-25.\nG50.1 X0"
    checker = Checker(haas)
    found = list(checker.run_stream([MILL.format(body)], haas.dialect))
    assert [f for f in found if f.rule == "TG601"] == []
    notes = [f for f in found if f.rule == "TG140"]
    assert [(f.line, "a second mirror image of an axis already mirrored" in f.message)
            for f in notes] == [(8, True)]


def test_a_partial_cancel_of_a_mirror_not_known_exactly_gives_the_axis_its_span_back() -> None:
    """Review 16b, 3: after `G51.1 X#500 Y#500` (a point not known here) `G50.1 X0` left X's
    positions in the mirrored span: X780. after the cancel was not compared with X-750.
    before the mirror (a missed 1530), and X-770. was compared with the mirrored X760. (a
    false 1530). The ended axis gets its span back; its position is unknown until an
    absolute one."""
    fanuc = load_profile("fanuc-mill")  # X -762..762 mm
    found, _ = check("G54\nG00 X-750. Y0\nG51.1 X#500 Y#500\nG00 X750.\nG50.1 X0\n"
                     "G00 X780.\nG50.1 Y0\nG00 Y0", fanuc)
    assert [(f.line, f.message.split(",")[0]) for f in found] == [
        (9, "X spans 1530 (from -750 to 780)")]
    found, _ = check("G54\nG00 X0 Y0\nG51.1 X#500 Y#500\nG00 X760.\nG50.1 X0\nG00 X-770.\n"
                     "G50.1 Y0", fanuc)
    assert found == []
    # an increment after the partial cancel is not compared: the point it adds to is unknown
    found, _ = check("G54\nG00 X-750. Y0\nG51.1 X#500 Y#500\nG00 X750.\nG50.1 X0\n"
                     "G91 G00 X30.\nG90\nG50.1 Y0", fanuc)
    assert found == []


def cli_check(tmp_path: Path, text: str, profile: str, *extra: str) -> str:
    path = tmp_path / "p.nc"
    path.write_text(text)
    return CliRunner().invoke(main, ["check", str(path), "-p", profile, *extra]).output


@pytest.mark.parametrize("shift", ["G52 X900.", "G92 X-900."])
def test_an_over_travel_across_a_known_shift_is_found(tmp_path: Path, shift: str) -> None:
    """Review 38, finding 6: X-700., then X0 and X300. of a zero at X900. of the coordinates
    before (G52 X900.; G92 X-900. where the tool stands at X0) reach 900 and 1200, wider than
    the travel of 1524 from 900 on. The span started again at the shift, silently."""
    start = "G00 X-700. Y0 Z5.\n" + ("G01 X0 F500.\n" if shift.startswith("G92") else "")
    zero = "G92 X-900." if shift.startswith("G92") else shift
    text = MILL.format(f"{start}{zero}\nG01 X0 F500.\nG01 X300.")
    out = cli_check(tmp_path, text, "fanuc-mill", "--select", "TG601,TG140")
    assert "error TG601 X spans 1600 (from -700 to 900), more than the travel -762 to 762" in out
    assert "TG140" not in out


def test_a_program_inside_the_travel_only_through_a_shift_is_not_flagged(tmp_path: Path) -> None:
    """X700., then a local zero at X1400.: X-700. and X-1300. are 700 and 100 in the work
    system, a span of 600 (the numbers as written span 2000); under G91 after a G92 at X700.
    the increments are followed from there."""
    text = MILL.format("G00 X700. Y0 Z5.\nG52 X1400.\nG01 X-700. F500.\nX-1300.\nG52 X0")
    assert "TG601" not in cli_check(tmp_path, text, "fanuc-mill")
    # 700, then 100, -500 and -800: a span of 1500; a last X-400. instead ends at -900, 1600
    text = MILL.format("G00 X700. Y0 Z5.\nG92 X0\nG91 G01 X-600. F500.\nX-600.\nX-300.")
    assert "TG601" not in cli_check(tmp_path, text, "fanuc-mill")
    out = cli_check(tmp_path, text.replace("X-300.", "X-400."), "fanuc-mill", "--select", "TG601")
    assert "X spans 1600 (from -900 to 700)" in out


def test_a_shift_not_known_is_said_once_as_a_note(tmp_path: Path) -> None:
    """A G92 where X stood is not known (after G28): the span starts again, said."""
    text = MILL.format("G00 X-700. Y0 Z5.\nG91 G28 X0\nG90 G92 X0\nG01 X900. F500.\n"
                       "G91 G28 X0\nG90 G92 X0\nX-100.")
    out = cli_check(tmp_path, text, "fanuc-mill", "--select", "TG601,TG140")
    assert "error TG601" not in out
    assert out.count("info TG140") == 1
    assert ("info TG140 G92: the span of X (TG601) starts again here, in the coordinates after "
            "it, since the shift's amount is not known: where X stood before it is not known")\
        in out


def test_a_g53_position_in_the_other_units_names_both(tmp_path: Path) -> None:
    """Review 38, finding 11: 800 mm on a Haas (travel in inches) is 31.496063 in."""
    text = MILL.format("G00 X0 Y0 Z5.\nG53 G00 X800.")
    out = cli_check(tmp_path, text, "haas-mill", "--select", "TG601")
    assert ("error TG601 X goes to 800 mm (31.496063 in) in machine coordinates (G53), outside "
            "the travel -30 to 30 in") in out


@pytest.mark.parametrize("limit", ["G26 S3000", "G25 S100", "G26 X500 Y500 Z200"])
def test_a_sinumerik_working_area_or_speed_limit_is_no_canned_cycle(tmp_path: Path,
                                                                     limit: str) -> None:
    """Review 38, finding 12: G25/G26 were read as a canned cycle of the control's list (the
    table holds G81 as not a SINUMERIK code, in the one-block group), and the moves after them
    left out of --stats and the plot."""
    text = f"G71 G90 G17 G54 G0 X0 Y0 Z100\nG1 X-700 F100\n{limit}\nX750\nM30\n"
    out = cli_check(tmp_path, text, "sinumerik-840d", "--stats")
    assert "  X: -700 to 750 mm" in out
    assert "feed path 2150.0 mm" in out
    assert "canned cycle" not in out
