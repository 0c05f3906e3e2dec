"""Restart from a block, safely (postproc.restart): the preamble, run through the core's modal
state machine from reset, reaches the state of a run from the start; the approach stays at the
clearance in rapid; and every restart that cannot be made safely is refused, with its reason."""

from __future__ import annotations

import re
from dataclasses import replace
from decimal import Decimal
from importlib import resources
from itertools import islice
from pathlib import Path

import pytest

from dnc import workflow
from formats.errors import ProfileError, TapegateError
from formats.parser import BadBlock, parse_stream, parse_text
from formats.profile import (
    NEUTRAL,
    Profile,
    load_profile,
    profile_from_text,
    with_start_units,
)
from formats.source import Source
from postproc.restart import (
    RestartPlan,
    RestartRefused,
    RestartWalk,
    plan_restart,
    plan_restart_text,
)
from postproc.state import ModalMachine, ModalState

from .conftest import CORPUS, corpus_files, needs_corpus, rs274_output
from .test_dialects import MATCHING

FANUC = load_profile("fanuc-mill")
SHOPS = CORPUS / "shops"
needs_shops = pytest.mark.skipif(not (SHOPS / "families.tsv").is_file(),
                                 reason="shared/corpus/shops is not present")
MODES = ("plane", "units", "feed_units", "incremental", "feed_mode", "feed", "spindle_mode",
         "speed", "speed_limit", "spindle", "coolant", "compensation", "length_offset",
         "zero_shift", "tool", "offset", "cycle", "cycle_words")
MACHINE_MOVES = ("G28", "G30", "G53")
# The corpus is sampled to keep this fast: restarts at PLANS blocks spread evenly over the first
# PREFIX blocks of each program (TOKARKA has 28,905); bracket.nc restarts at every block.
PLANS = 60
PREFIX = 8000


def plan(text: str, line: int, profile: Profile = FANUC) -> RestartPlan:
    return plan_restart(parse_text(text, profile.dialect), profile, line, "p.nc")


def refusal(text: str, line: int, profile: Profile = FANUC) -> str:
    with pytest.raises(RestartRefused) as caught:
        plan(text, line, profile)
    assert caught.value.line == line and caught.value.file == "p.nc"
    assert caught.value.code == "restart-refused"
    return caught.value.message


def run(profile: Profile, lines: list[str], machine: ModalMachine | None = None) -> ModalMachine:
    machine = machine or ModalMachine(profile)
    for block in parse_text("\n".join(lines) + "\n", profile.dialect):
        machine.apply(block)
    return machine


def words(line: str) -> dict[str, Decimal]:
    """The plain axis words of a preamble block, by letter."""
    out = {}
    for token in line.split():
        if token[0] in "XYZUVWABC":
            out[token[0]] = Decimal(token[1:])
    return out


# -- the simulation: every allowed restart of real programs -----------------------------------


def assert_restores(profile: Profile, plan: RestartPlan, before: ModalState, after: ModalState,
                    block_words: list[str], lathe: bool, work: int | None,
                    cycle: bool = False, unplaced: frozenset[str] = frozenset(),
                    tool_change_mill: bool = False) -> None:
    """The preamble (and the restart block as sent) reach what a run from the start reached.
    ``work`` is the last G54-G59 before the block: on these controls G53 acts in its block only,
    where the modal state machine takes it for ISO's zero shift cancel. ``cycle``: a lathe
    cycle ran before the block, which returns to its start point where the modal state reads
    its words as the place reached (the plan's state says where the tool is then).
    ``unplaced``: the axes a FANUC or Haas mill's M06 left at the tool change height and the
    program has not written since (no place of the program's; not positioned)."""
    moved = {a for a, v in plan.state.position.items() if before.position.get(a) != v}
    # where the position before the block is not known (lost to a change of work system, or
    # at a cycle's return level), the approach goes to the block's own target of the axis
    own = words(" ".join(block_words))
    targets = {a for a in moved if own.get(a) == plan.state.position[a]}
    assert not moved - targets or (lathe and cycle and moved <= {"X", "Z"}), (moved,
                                                                             plan.preamble)
    sent = run(profile, plan.preamble)
    state = sent.state
    modes = [m for m in MODES if not (lathe and m == "offset")]  # a lathe's D: depth of cut
    one_shot = profile.dialect.family != "iso"
    for name in modes:
        if name == "zero_shift" and one_shot:
            replayed_g53 = any(b.startswith("G53") for b in plan.preamble)
            expected = work if work is not None else before.zero_shift  # else the reset's
            assert state.zero_shift == (None if replayed_g53 else expected), plan.preamble
            continue
        if name == "feed" and before.feed is None and any(w[0] == "F" for w in block_words):
            continue  # no feed in force: the approach feeds at the block's own F
        assert getattr(state, name) == getattr(before, name), (name, plan.preamble)
    codes = {int(w[1:]) for w in block_words if w[0] == "G" and w[1:].isdigit()}
    own_motion = bool(codes & {0, 1, 2, 3, 6, 32, 33, 34, 35})
    if plan.first_block is None and not own_motion:
        assert state.motion == before.motion, plan.preamble
    replayed = {axis for b in plan.preamble if b.split()[0] in MACHINE_MOVES
                or b.split()[:2] in (["G91", "G28"], ["G91", "G30"])
                for axis in words(b)}
    if lathe:
        replayed |= {"X" if a == "U" else "Z" for a in replayed if a in "UW"}
    for axis in before.position:
        if lathe and axis in "UW" and profile.dialect.family in ("fanuc", "haas"):
            continue  # X and Z incremental there, not axes of their own
        if axis in unplaced and axis not in plan.restored:
            continue
        if axis in plan.restored:
            assert state.position.get(axis) == plan.state.position[axis], (axis, plan.preamble)
        else:
            assert axis in replayed, (axis, plan.preamble)
    # then the restart block itself, as sent
    first = plan.first_block
    block = parse_text((first if first is not None else " ".join(block_words)) + "\n",
                       profile.dialect)
    sent.apply(block[0])
    final = sent.state
    ms = {int(w[1:]) for w in block_words if w[:1] == "M" and w[1:].isdigit()}
    if tool_change_mill and 6 in ms:  # the block's own M06, as walk_program reads it
        final = replace(final, spindle=final.spindle if ms & {3, 4} else "stop",
                        coolant=final.coolant if ms & {7, 8} else "off")
    for name in (*modes, "motion"):
        if name == "zero_shift" and one_shot:
            continue
        assert getattr(final, name) == getattr(after, name), (name, plan.preamble, first)
    written = {w[0] for w in block_words}
    for axis in plan.restored:
        # an axis the block does not write stays where the preamble put it (a cycle's start)
        expected = after.position if axis in written or not moved else plan.state.position
        assert final.position.get(axis) == expected.get(axis), (axis, plan.preamble)


Point = tuple[Decimal | None, Decimal | None]


def assert_safe_approach(plan: RestartPlan, lathe: bool,
                         rapids: set[tuple[Point, Point]] | None = None,
                         widest: Decimal | None = None) -> None:
    """No rapid below the clearance: a mill rapids in Z no lower than the clearance and in X/Y
    only at it (or after a machine move up); a lathe rapids in X only at the Z clearance, and
    below it only as one of the program's own rapids again, from where the program made it
    (``rapids``: (from, to) in X Z)."""
    if plan.clearance is None:
        return
    height: Decimal | None = None
    machine = False
    at: Point = (None, None)
    retract = next((words(b)["X"] for b in plan.preamble if "X" in words(b)), None)
    for line in plan.preamble:
        parts = line.split()
        axes = words(line)
        if parts[0] in MACHINE_MOVES or parts[:2] in (["G91", "G28"], ["G91", "G30"]):
            machine = True
            continue
        rapid = parts[0] == "G00"
        came, at = at, (axes.get("X", at[0]), axes.get("Z", at[1]))
        low = at[1] is not None and at[1] < plan.clearance
        if lathe and rapid and axes and low:
            # along Z at the retract diameter or at the largest the program went to
            along = set(axes) == {"Z"} and came[0] in (retract, widest)
            assert along or (came, at) in (rapids or set()), plan.preamble
            height = at[1]
            continue
        if "Z" in axes:
            if rapid:
                assert axes["Z"] >= plan.clearance, plan.preamble
            height = axes["Z"]
        over = set(axes) - {"Z"} - ({"X"} if lathe and height is None else set())
        if rapid and over and not machine:
            assert height is not None and height >= plan.clearance, plan.preamble


def walk_program(path: Path | None, text: str | None, profile: Profile, every: bool) -> int:
    source = Source(str(path)).chunks() if path is not None else [text or ""]
    read = parse_stream(source, profile.dialect, file="p.nc", errors="collect")
    blocks = [b for b in islice(read, None if every else PREFIX) if not isinstance(b, BadBlock)]
    moving = [b for b in blocks if b.words]
    step = 1 if every else max(1, len(moving) // PLANS)
    sampled = {b.line for b in moving[::step]}
    walk = RestartWalk(profile, "p.nc")
    reference = ModalMachine(profile)
    lathe = profile.control_type == "lathe"
    allowed = 0
    work = None
    cycles = {31, 32, 33} if profile.dialect.family == "okuma" else {*range(70, 77), 90, 92, 94}
    cycle = False
    rapids: set[tuple[Point, Point]] = set()
    widest: Decimal | None = None
    # a FANUC or Haas mill's M06 stops the spindle and the coolant and leaves Z at the tool
    # change height (Haas mill manual, NGC, "M06 Tool Change"), which the checker's modal
    # state does not hold: the run from the start is read so here (review 36, finding 1)
    tool_change_mill = profile.dialect.family in ("fanuc", "haas") and not lathe
    stopped = cooled = False
    unplaced: frozenset[str] = frozenset()

    def as_run(state: ModalState, block_words: list[str] | None = None) -> ModalState:
        changed = replace(state, spindle="stop" if stopped else state.spindle,
                          coolant="off" if cooled else state.coolant)
        if block_words is not None and "Z" in unplaced and any(
                w in ("G43", "G44", "G49") for w in block_words) and any(
                w[0] == "Z" for w in block_words):
            changed = replace(changed, length_offset=49)  # the block sets its own
        return changed

    for block in blocks:
        came = (reference.state.position.get("X"), reference.state.position.get("Z"))
        restart = None
        if block.line in sampled:
            before = as_run(reference.state, list(block.words))
            was_unplaced = unplaced
            try:
                restart = walk.plan(block)
            except RestartRefused as exc:
                assert (exc.code, exc.line) == ("restart-refused", block.line)
                assert "cannot restart here: " in exc.message  # the refusal's wording starts so
        walk.step(block)
        reference.apply(block)
        ms = {int(w[1:]) for w in block.words if w[:1] == "M" and w[1:].isdigit()}
        if tool_change_mill and 6 in ms:
            stopped, cooled, unplaced = True, True, frozenset("XYZ")
        stopped = stopped and not ms & {3, 4, 5}
        cooled = cooled and not ms & {7, 8, 9}
        unplaced = unplaced - {w[0] for w in block.words}
        if restart is not None:
            allowed += 1
            assert_restores(profile, restart, before, as_run(reference.state), list(block.words),
                            lathe, work, cycle, was_unplaced, tool_change_mill)
            assert_safe_approach(restart, lathe, rapids, widest)
        x = reference.state.position.get("X")
        widest = x if x is not None and (widest is None or x > widest) else widest
        if reference.state.motion == 0 and lathe:
            rapids.add((came, (reference.state.position.get("X"),
                               reference.state.position.get("Z"))))
        codes = [w for w in block.words if w[:1] == "G" and w[1:].isdigit()]
        cycle = cycle or any(int(w[1:]) in cycles for w in codes)
        work = next((int(w[1:]) for w in reversed(codes) if 54 <= int(w[1:]) <= 59), work)
    return allowed


def test_every_block_of_the_shipped_example_restarts_to_the_state_of_a_run_from_the_start():
    text = (resources.files("tapegate") / "examples" / "bracket.nc").read_text("ascii")
    # in a FANUC's codes (the ISO example's G71, metric, is no FANUC code: after it the
    # restart is refused, the control alarms there)
    text = text.replace("G71", "G21")
    allowed = walk_program(None, text, FANUC, every=True)
    assert allowed >= 12  # every block but those inheriting an arc mode with nothing to move


@needs_corpus
@pytest.mark.parametrize("name", [p.name for p in corpus_files()])
def test_real_programs_restart_to_the_state_of_a_run_from_the_start(name):
    profile = load_profile(MATCHING[name]) if name in MATCHING else NEUTRAL
    assert walk_program(CORPUS / name, None, profile, every=False) >= 1


# -- the preamble ---------------------------------------------------------------------------------

PART = ("%\nO1000\nN1 G21 G17 G40 G49 G80 G90 G94\nN2 T1 M06\nN3 T2\n"
        "N4 G00 G54 X10. Y10. S3000 M03\nN5 G43 Z50. H1 M08\nN6 Z5.\nN7 G01 Z-1.5 F120.\n"
        "N8 X90.\nN9 G02 X100. Y20. I0 J10.\nN10 X110. Y30. I0 J10.\nN11 G01 Y80.\n"
        "N12 G00 Z50. M09\nN13 M05\nN14 G91 G28 Z0.\nN15 G90 M30\n%\n")


def test_the_preamble_brings_back_tool_offsets_spindle_coolant_and_approaches_safely():
    restart = plan(PART, 10)  # N8 X90.: the block before ended at X10. Y10. Z-1.5
    assert restart.preamble == [
        "G21 G17 G90 G94 G40 G49 G80 G54",  # modes, compensation, length offset, cycle off
        "T1 M06",  # the tool in the spindle, then the one selected next
        "T2",
        "G97 S3000 M03",  # the spindle before the approach
        "M08",
        "G00 G43 Z50. H1",  # to the clearance (the highest Z so far) with the length offset
        "G00 X10. Y10.",  # over the start point
        "G01 Z-1.5 F120.",  # down to it in feed
    ]
    assert restart.clearance == 50 and restart.first_block is None


def test_an_arc_block_starts_at_the_end_of_the_block_before_and_keeps_its_arc_mode():
    restart = plan(PART, 12)  # N10 X110. Y30. I0 J10.: G02 inherited, starts at X100. Y20.
    assert restart.preamble[-2:] == ["G00 X100. Y20.", "G01 Z-1.5 F120."]
    assert restart.first_block == "N10 G02 X110. Y30. I0 J10."
    machine = run(FANUC, [*restart.preamble, restart.first_block])
    reference = run(FANUC, PART.splitlines()[2:12])
    assert machine.state.motion == reference.state.motion == 2
    assert machine.state.position == reference.state.position


def test_a_block_that_inherits_a_rapid_gets_the_rapid_mode_and_the_feed_back():
    text = ("%\nO1\nN1 G21 G17 G90 G94 F200.\nN2 T1 M06\nN3 G00 G43 Z50. H1\nN4 X10. Y10.\n"
            "N5 Z2.\nN6 X20.\nN7 M30\n%\n")
    assert plan(text, 8).preamble[-4:] == ["G00 G43 Z50. H1", "G00 X10. Y10.",
                                           "G01 Z2. F200.", "G00"]
    # at the clearance already: rapids only, and the feed in force is set on its own
    assert plan(PART, 15).preamble[-3:] == ["G00 G43 Z50. H1", "G00 X110. Y80.", "F120."]


def test_a_restart_after_a_reference_return_sends_the_axis_there_again():
    restart = plan(PART, 17)  # N15 after N14 G91 G28 Z0.: Z at the reference point, in G91
    assert restart.preamble[-6:] == ["G91 G28 Z0", "G90", "G43 H1", "G00 X110. Y80.", "G91",
                                     "F120."]


def test_the_profile_gives_the_clearance_in_its_units():
    mine = replace(FANUC, restart=replace(FANUC.restart, clearance=Decimal("100")))
    assert "G00 G43 Z100. H1" in plan(PART, 10, mine).preamble
    inch = PART.replace("G21", "G20").replace("Z50.", "Z2.")
    # 100 mm is 3.93700... in, rounded up to the 0.0001 in of the Z format
    assert "G00 G43 Z3.9371 H1" in plan(inch, 10, mine).preamble


def test_a_clearance_past_the_machine_s_travel_is_refused():
    """Review 15, 6: a clearance was checked against the Z word's digits alone. The approach
    goes from it down to the start point (Z-1.5 at line 10) in one work offset: a drop longer
    than the profile's Z travel (fanuc-mill: -508 to 10 mm, 518) fits no offset, so the
    restart is refused, saying why; one within it is planned. In an inch program the drop is
    in inches (the profile's 480 mm is 18.8976 in, 20.3976 above Z-1.5, past 518 mm's
    20.3937 in)."""
    inch = PART.replace("G21", "G20").replace("Z50.", "Z2.")
    for text, clearance, refused in [(PART, "516.6", True), (PART, "516.5", False),
                                     (inch, "480", True), (inch, "479", False)]:
        mine = replace(FANUC, restart=replace(FANUC.restart, clearance=Decimal(clearance)))
        if not refused:
            assert plan(text, 10, mine).preamble[-1] == "G01 Z-1.5 F120."
            continue
        message = refusal(text, 10, mine)
        assert "above the start point Z-1.5, more than the machine's Z travel (-508 to 10 mm)" \
            in message, message
        assert "no work offset puts both on the machine" in message


def test_a_lathe_changes_tools_with_the_t_word_and_approaches_along_z():
    lathe = load_profile("fanuc-lathe")
    text = ("%\nO1\nN1 G21 G18 G40 G99\nN2 G50 S2500\nN3 T0101\nN4 G96 S200 M03\n"
            "N5 G00 X60. Z5. M08\nN6 G01 X40. F0.2\nN7 Z-20.\nN8 X60.\nN9 M30\n%\n")
    restart = plan(text, 10, lathe)  # N8 X60.: starts at X40. Z-20.
    assert restart.preamble == ["G21 G18 G99 G40 G80", "T0101", "G50 S2500", "G96 S200 M03",
                                "M08", "G00 X60.", "G00 Z5.", "G00 X40.", "G01 Z-20. F0.2"]


def test_the_restart_clearance_is_a_number():
    with pytest.raises(ProfileError) as info:
        profile_from_text('[restart]\nclearance = "high"\n', "mine.toml")
    assert (info.value.code, info.value.key, info.value.file) == \
        ("profile-value", "restart.clearance", "mine.toml")
    with pytest.raises(ProfileError) as info:
        profile_from_text("[restart]\nheight = 50.0\n", "mine.toml")
    assert (info.value.code, info.value.key, info.value.file) == \
        ("profile-unknown-key", "restart.height", "mine.toml")
    assert profile_from_text("[restart]\nclearance = 50.0\n").restart.clearance == 50


# -- refusals, each with its reason ----------------------------------------------------------------


def test_no_restart_inside_cutter_compensation():
    text = PART.replace("N8 X90.", "N8 G41 D1 X90.").replace("N11 G01 Y80.", "N11 G40 G01 Y80.")
    assert refusal(text, 11) == ("cannot restart here: inside cutter compensation G41 (from "
                                 "line 10); restart at a block after the G40 that ends it")
    plan(text, 14)  # after the G40: allowed


def test_no_restart_inside_a_canned_cycle():
    text = ("%\nO1\nN1 G21 G17 G90 G94\nN2 T3 M06\nN3 S1000 M03\nN4 G00 G43 Z50. H3\n"
            "N5 G98 G81 X10. Y10. Z-5. R2. F100.\nN6 X20.\nN7 G80\nN8 G00 Z50.\nN9 X0 Y0\n"
            "N10 M30\n%\n")
    assert refusal(text, 8) == ("cannot restart here: inside the canned cycle G81 from line 7; "
                                "restart at a block after the G80 that ends it")
    # N8 G00 Z50. sets Z itself: it goes there from the return level, the approach too
    assert plan(text, 10).preamble[-3:] == ["G00 G43 Z50. H3", "G00 X20. Y10.", "F100."]
    away = text.replace("N8 G00 Z50.\nN9 X0 Y0", "N8 G00 X0 Y0\nN9 Z50.")
    assert refusal(away, 10) == ("cannot restart here: the position of Z is not known here "
                                 "(line 8: the canned cycle G81: the tool is at its return "
                                 "level)")
    assert plan(text, 11).preamble[-3:] == ["G00 G43 Z50. H3", "G00 X20. Y10.", "F100."]


def test_no_restart_after_a_macro_loop_naming_the_statement():
    text = ("%\nO1\nN1 G21 G17 G90 G94\nN2 T1 M06\nN3 G00 G43 Z50. H1\n#1 = 0\n"
            "N4 WHILE [#1 LT 3] DO1\nN5 G01 Z-1. F100.\nN6 #1 = #1 + 1\nN7 END1\n"
            "N8 G00 Z50.\nN9 M30\n%\n")
    message = ("cannot restart here: after 'WHILE [#1 LT 3] DO1' on line 7 (a jump, loop or "
               "condition) the modal state is not known")
    assert refusal(text, 8).startswith(message)  # inside the loop
    assert refusal(text, 12).startswith(message)  # after it


def test_no_restart_at_a_value_set_by_a_parameter():
    text = PART.replace("N7 G01 Z-1.5 F120.", "N7 G01 Z-1.5 F#101")
    assert refusal(text, 10) == ("cannot restart here: the feed in force is not known: F#101 "
                                 "on line 9 sets it by a parameter")
    text = PART.replace("N8 X90.", "N8 X#24")
    assert refusal(text, 11) == ("cannot restart here: the position of X is not known here "
                                 "(line 10: X#24, set by a parameter)")


def test_no_restart_under_a_coordinate_rotation_or_a_length_offset_without_h():
    text = PART.replace("N6 Z5.", "N6 G68 X0 Y0 R30. Z5.")
    assert refusal(text, 10) == ("cannot restart here: G68 (coordinate rotation) from line 8 "
                                 "is in force and the preamble cannot restore it")
    text = PART.replace("N5 G43 Z50. H1", "N5 G43 Z50.")
    assert refusal(text, 10) == ("cannot restart here: G43 on line 7 has no H: the length "
                                 "offset to restore is not known")


def test_no_restart_where_the_height_to_approach_from_is_not_known():
    text = "%\nO1\nN1 G21 G90\nN2 G00 X10. Y10.\nN3 G01 Z-1. F100.\nN4 M30\n%\n"
    assert refusal(text, 5) == ("cannot restart here: the program moves X, Y before it sets "
                                "Z: the height to approach from is not known; restart at an "
                                "earlier block")


def test_no_restart_on_a_lathe_after_an_increment_it_does_not_follow():
    lathe = load_profile("fanuc-lathe")
    text = ("%\nO1\nN1 G21 G18 G99\nN2 T0101\nN3 G00 X60. Z5.\nN4 G01 U-10. F0.2\n"
            "N5 Z-20.\nN6 M30\n%\n")
    assert refusal(text, 7, lathe) == ("cannot restart here: the position of X is not known "
                                       "here (line 6: U-10., an increment of X on a lathe, not "
                                       "followed)")


def test_no_restart_preamble_for_a_heidenhain_control():
    heidenhain = load_profile("heidenhain-iso")
    text = "%1 G71 *\nN10 G00 G40 G90 Z100. *\nN20 X10. Y10. *\nN99999 %1 G71 *\n"
    assert "HEIDENHAIN" in refusal(text, 3, heidenhain)


def test_send_refuses_the_restart_before_the_port_opens(tmp_path: Path):
    src = tmp_path / "p.nc"
    src.write_text(PART.replace("N8 X90.", "N8 G41 D1 X90."))
    settings = replace(FANUC.serial, baud=115200, flow="none")
    with pytest.raises(RestartRefused) as info:
        workflow.prepare(str(src), FANUC, settings, name="p.nc", restart_at="N9")
    assert (info.value.code, info.value.file, info.value.line) == ("restart-refused", "p.nc", 11)
    assert "inside cutter compensation G41" in info.value.message  # the why, within the one code


def test_send_says_why_it_refuses_and_sends_nothing(tmp_path: Path):
    from tests.test_dnc_serial import cli

    src = tmp_path / "p.nc"
    src.write_text(PART.replace("N8 X90.", "N8 G41 D1 X90."))
    result = cli("send", str(src), "--port", "loop://", "-p", "fanuc-mill", "--restart-at", "N9",
                 "--yes")
    assert result.exit_code == 1
    assert (f"{src}:11: cannot restart here: inside cutter compensation G41 (from line 10); "
            "restart at a block after the G40 that ends it") in result.output
    assert "sent" not in result.output


def test_send_shows_the_preamble_and_the_restart_block_written_with_its_arc_mode(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]):
    from dnc.program import find_restart, program_lines
    from tapegate.serial_cli import _prepared

    src = tmp_path / "p.nc"
    src.write_text(PART)
    restart = find_restart(str(src), FANUC, "N10", "p.nc")
    _prepared(workflow.RestartFound(restart))
    shown = capsys.readouterr().err
    assert "restart at N10 (line 12); preamble:\n    G21 G17 G90 G94 G40 G49 G80 G54\n" in shown
    assert ("then line 12 with the motion mode it inherits written in: "
            "N10 G02 X110. Y30. I0 J10.") in shown
    sent = [text for _, text in program_lines(str(src), restart)]
    assert sent[0] == "%" and sent[1:len(restart.preamble) + 1] == restart.preamble
    assert sent[len(restart.preamble) + 1:len(restart.preamble) + 3] == [
        "N10 G02 X110. Y30. I0 J10.", "N11 G01 Y80."]


def test_a_sinumerik_restart_selects_the_units_of_the_feed_as_the_program_did():
    """G700 sets inch for the feed too, G70 for lengths only (the feed stays mm/min): the
    preamble's units code must bring back both, or F10 is 10 mm/min where the program ran at
    10 in/min."""
    siemens = load_profile("sinumerik-840d")
    text = "N1 G700 G90 G17 G94\nN2 T1 M6\nN3 S1000 M3\nN4 G0 X0 Y0 Z1\nN5 G1 Z-0.1 F10\n" \
           "N6 G1 X1 Y1\nN7 X2\nM30\n"
    g700 = plan(text, 7, siemens)
    assert g700.preamble[0].split()[0] == "G700" and g700.state.feed_units == "inch"
    assert g700.preamble[-1] == "G01 Z-0.1 F10."
    g70 = plan(text.replace("G700", "G70"), 7, siemens)
    assert g70.preamble[0].split()[0] == "G70"
    assert (g70.state.units, g70.state.feed_units) == ("inch", "metric")


def test_a_position_written_before_a_change_of_units_is_refused_and_the_height_is_compared_in_mm():
    """The modal state keeps a position as written: X1. from before G21 is one inch, and an
    approach to 'X1.' in mm would go to the wrong place, so the restart is refused until a block
    writes X again. The highest Z is compared in one unit: Z2. in inch (50.8 mm) is above the
    Z10. in mm that comes after it, and a metric height is rounded up in inch."""
    head = "%\nO1\nG20 G90 G17 G94\nT1 M6\nS1000 M3\nG0 X1. Y0. Z2.\nG21\n"
    with pytest.raises(RestartRefused) as info:
        plan(head + "G0 Z10.\nG1 Z-1. F100.\nY5.\nY10.\nM30\n%\n", 11)
    assert (info.value.code, info.value.line) == ("restart-refused", 11)
    # restart-refused is one code for every reason ("the message says why", docs/errors.md)
    assert ("position of X in force was written in inch (line 6) and the program works in mm"
            in info.value.message)
    rewritten = plan(head + "G0 X0. Y0. Z10.\nG1 Z-1. F100.\nX5.\nX10.\nM30\n%\n", 11)
    assert rewritten.preamble[3] == "G00 Z50.8" and rewritten.clearance == Decimal("50.8")
    siemens = load_profile("sinumerik-840d")
    metric_first = ("N10 G71 G90 G17 G94\nN20 T1 M6\nN30 S1000 M3\nN40 G0 X0 Y0 Z50\n"
                    "N50 G70 G0 X0 Y0 Z1\nN60 G1 Z-0.1 F100\nN70 X2\nN80 X3\nN90 M30\n")
    assert plan(metric_first, 8, siemens).preamble[3] == "G00 Z1.9686"  # 50 mm, rounded up
    with pytest.raises(RestartRefused) as info:
        plan("G20 G90 G17 G94\nT1 M6\nG1 X1. Y1. Z-1. F10. S100 M3\nG21\nX30. Y30. Z-2.\n"
             "X40.\nM30\n", 6)
    assert (info.value.code, info.value.line) == ("restart-refused", 6)
    assert "feed in force was written in inch (line 3)" in info.value.message  # the why


# -- the core's walk over text (send --restart-at) --------------------------------------------


def outcome(attempt) -> tuple[str, object]:
    """A restart plan, or the refusal's message and line: what the two readings must agree on."""
    try:
        return "plan", attempt()
    except RestartRefused as exc:
        return "refused", (exc.code, exc.line, exc.message)


def pieces(text: str, size: int) -> list[str]:
    """The text in chunks of ``size`` characters, cut anywhere (inside a line as well)."""
    return [text[i:i + size] for i in range(0, len(text), size)]


def agree_on(text: str, profile: Profile, lines: list[int], size: int = 257) -> int:
    """The text walk and the block walk give the same plan or refusal at every line."""
    planned = 0
    for line in lines:
        blocks = parse_stream([text], profile.dialect, file="p.nc", errors="collect")
        by_blocks = outcome(lambda: plan_restart(blocks, profile, line, "p.nc"))  # noqa: B023
        by_text = outcome(
            lambda: plan_restart_text(pieces(text, size), profile, line, "p.nc"))  # noqa: B023
        assert by_text == by_blocks, line
        planned += by_text[0] == "plan"
    return planned


def test_the_text_walk_plans_every_restart_of_the_shipped_example_as_the_block_walk_does():
    text = (resources.files("tapegate") / "examples" / "bracket.nc").read_text("ascii")
    text = text.replace("G71", "G21")  # in a FANUC's codes, as above
    count = text.count("\n")
    assert agree_on(text, FANUC, list(range(1, count + 2))) >= count // 2


def test_the_text_walk_agrees_on_refusals_and_on_a_last_line_without_its_end_of_block():
    loop = ("%\nO1\nN1 G21 G17 G90 G94\nN2 T1 M06\nN3 G00 G43 Z50. H1\n#1 = 0\n"
            "N4 WHILE [#1 LT 3] DO1\nN5 G01 Z-1. F100.\nN6 #1 = #1 + 1\nN7 END1\n"
            "N8 G00 Z50.\nN9 M30")
    rotated = PART.replace("N6 Z5.", "N6 G68 X0 Y0 R30. Z5.").replace("N8 X90.", "N8 X#24")
    for text in (loop, rotated, PART.replace("N15 G90 M30\n%\n", "N15 G90 X10. M30")):
        lines = list(range(1, text.count("\n") + 3))
        for size in (1, 7, 4096):
            agree_on(text, FANUC, lines, size)
    with pytest.raises(RestartRefused) as info:
        plan_restart_text([PART], FANUC, 99, "p.nc")
    assert (info.value.code, info.value.file) == ("restart-no-block", "p.nc")
    assert "line 99" in info.value.message  # the line asked for has no field of its own


def test_the_text_walk_refuses_after_a_line_it_cannot_read_as_the_block_walk_does():
    """A line the control refuses (here an unclosed comment) alarms there: nothing after it
    has run, and what it writes (X90.) is unknown, so both walks refuse a restart after it
    and plan one before it."""
    text = PART.replace("N8 X90.", "N8 X90. (an unclosed comment")
    assert agree_on(text, FANUC, [8, 11, 12]) == 1
    assert plan_restart_text([text], FANUC, 8, "p.nc").line == 8
    with pytest.raises(RestartRefused) as refused:
        plan_restart_text([text], FANUC, 11, "p.nc")
    assert "line 10 holds a word the control refuses" in refused.value.message


@needs_corpus
@pytest.mark.parametrize("name", [p.name for p in corpus_files()])
def test_the_text_walk_agrees_with_the_block_walk_on_real_programs(name):
    profile = load_profile(MATCHING[name]) if name in MATCHING else NEUTRAL
    text = "".join(Source(str(CORPUS / name)).chunks())
    count = text.count("\n")
    step = max(1, min(count, PREFIX) // 12)
    agree_on(text, profile, [*range(1, min(count, PREFIX), step), count], size=65536)


def test_find_restart_finds_the_block_across_chunks_and_names_the_alignment_before_it(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch):
    from dnc import program
    from formats import parser

    text = PART.replace("N6 Z5.", ":6 Z5.").replace("N15 G90 M30\n%\n", "N0015 G90 M30")
    src = tmp_path / "p.nc"
    src.write_text(text)
    monkeypatch.setattr(parser, "CHUNK", 5)  # every line cut across chunks
    monkeypatch.setattr("formats.source.CHUNK", 5)
    restart = program.find_restart(str(src), FANUC, "N10", "p.nc")
    assert (restart.line, restart.label, restart.alignment) == (12, "N10", (":6", 8))
    assert program.find_restart(str(src), FANUC, ":6", "p.nc").line == 8
    # the last line, without its LF, and its number written with leading zeros
    assert program.find_restart(str(src), FANUC, "n15", "p.nc").line == 17
    with pytest.raises(TapegateError) as info:
        program.find_restart(str(src), FANUC, "N16", "p.nc")
    assert (info.value.code, info.value.file) == ("restart-no-block", "p.nc")
    assert "N16" in info.value.message  # the block asked for has no field of its own


def test_a_height_too_long_to_compare_in_mm_refuses_the_restart():
    # 36 digits in inch: 25.4 times it does not fit the core's exact numbers
    text = ("G20 G17 G90 G94\nT1 M06\nG00 G54 X0 Y0 S1000 M03\n"
            "G43 Z9.99999999999999999999999999999999999 H1\nG01 Z-0.1 F10.\nX1.\nX2.\n")
    for restart in (lambda: plan(text, 7),
                    lambda: plan_restart_text([text], FANUC, 7, "p.nc")):
        with pytest.raises(RestartRefused) as info:
            restart()
        assert (info.value.code, info.value.file, info.value.line) == ("restart-refused", "p.nc", 7)
        # one code for every reason a restart is refused: the wording tells which
        assert ("the height written on line 4 has too many digits to be compared in mm"
                in info.value.message)


def test_a_decimal_code_longer_than_28_digits_is_a_mode_the_preamble_cannot_restore():
    text = PART.replace("N6 Z5.", "N6 G54.100000000000000000000000000001 Z5.")
    assert refusal(text, 10) == ("cannot restart here: G54.100000000000000000000000000001 (a code "
                                 "of more than 28 digits) from line 8 is in force and the "
                                 "preamble cannot restore it")


def test_the_text_walk_restarts_at_the_first_block_for_line_0_and_counts_characters():
    assert outcome(lambda: plan_restart_text([PART], FANUC, 0, "p.nc")) == outcome(
        lambda: plan(PART, 0))
    # a comment holding characters kept by surrogateescape (bytes of no UTF-8), in a string
    # that is not the decoding of its own bytes: the restart block is still found by its line
    odd = PART.replace("N3 T2\n", "N3 T2 (\udcc3\udca9)\n")
    assert plan_restart_text(pieces(odd, 11), FANUC, 10, "p.nc") == plan(odd, 10)


def test_an_axis_word_beside_a_linuxcnc_dwell_moves(tmp_path):
    """rs274 reads `G4 P1 Z5` as a dwell, then a move to Z5 (P alone is LinuxCNC's dwell
    time): a restart after it approaches from Z5, not from the Z-5 of the block before (the
    preamble ended at Z-5 and then rapid across the part)."""
    from .conftest import rs274_output

    text = ("G21 G17 G90\nT1 M6\nG43 H1\nS1000 M3\nG0 X0 Y0 Z50\nG1 Z-5 F100\nG4 P1 Z5\n"
            "N10 G0 X50 Y50\nG1 Z-5\nM2\n")
    canon = rs274_output(tmp_path, text)
    assert canon.index("DWELL(1.0000)") < canon.index("STRAIGHT_FEED(0.0000, 0.0000, 5.0000")
    preamble = plan(text, 8, load_profile("linuxcnc")).preamble
    assert preamble[-1] == "G01 Z5. F100."
    assert run(load_profile("linuxcnc"), preamble).state.position["Z"] == 5


def test_a_sinumerik_dwell_in_revolutions_keeps_the_speed():
    """`G4 S2` dwells two revolutions of the master spindle (Fundamentals, "Dwell time (G4)"):
    the speed in force stays 1000, which the preamble restores (it held S2: 2 rpm)."""
    text = ("N5 G71 G17 G90\nT1 D1\nM6\nS1000 M3\nG0 X0 Y0 Z50\nG1 Z-5 F100\nG4 S2\n"
            "N10 G0 X50 Y50\nG1 Z-5\nM30\n")
    preamble = plan(text, 8, load_profile("sinumerik-840d")).preamble
    assert "G97 S1000 M03" in preamble and not [b for b in preamble if "S2" in b.split()]


def test_no_restart_at_a_line_the_control_never_reads():
    """LinuxCNC stops at its M30: a line after it is never run, so no restart is planned at
    it; one before it is (rs274's driver, docs/dialects.md)."""
    linuxcnc = load_profile("linuxcnc")
    text = "G21 G90 G17\nG0 X0 Y0 Z5\nG1 X10 F100\nM30\nG0 X5 Y5\nG1 X20\n"
    for plan in (lambda line: plan_restart_text([text], linuxcnc, line),
                 lambda line: plan_restart(parse_text(text, linuxcnc.dialect), linuxcnc, line)):
        assert plan(3).line == 3
        for line in (5, 6):
            with pytest.raises(RestartRefused, match=f"never reads line {line}") as refused:
                plan(line)
            assert refused.value.code == "restart-not-read"


def test_an_okuma_lathe_restart_writes_no_units_code():
    """An Okuma OSP lathe's G21 is its tool change home position return and G20 its home
    position return (its units are a machine parameter, docs/dialects.md): the preamble's modes
    carry no units code, where a G21 there would send the turret home."""
    lathe = load_profile("okuma-lathe")
    text = ("$R.MIN%\nO1\nG50 S2000\nG00 X100. Z100.\nT0101\nG97 S500 M03\nG20 HP=1\n"
            "G00 X50. Z2.\nG01 Z-20. F0.2\nZ-30.\nM02\n")
    restart = plan(text, 10, lathe)
    assert restart.preamble[0].startswith("G18 G90 G95 G40")  # the plane first, no G21
    assert not any(("G20" in line or "G21" in line) for line in restart.preamble)
    assert restart.preamble[-1] == "G01 Z-20. F0.2"


OKUMA_G96 = ("$R.MIN%\nO1\nG50 S2000\nG00 X100. Z100.\nT0101\nG96 S180 M03\nG20 HP=1\n"
             "G00 X50. Z2.\nG01 Z-20. F0.2\nZ-30.\nM02\n")


def test_an_okuma_lathe_restart_keeps_the_g50_spindle_clamp_before_g96():
    """On the OSP lathe G50 S is the maximum spindle speed (5238-E), as on a Fanuc lathe: a
    restart under G96 writes it before the constant surface speed, and never as a speed."""
    lathe = load_profile("okuma-lathe")
    restart = plan(OKUMA_G96, 10, lathe)
    clamp = restart.preamble.index("G50 S2000")
    assert restart.preamble[clamp + 1] == "G96 S180 M03"
    early = plan(OKUMA_G96, 6, lathe)  # before the G96: the clamp, no G97 S2000
    assert "G50 S2000" in early.preamble
    assert not any("G97" in line or "S2000" in line.replace("G50 S2000", "")
                   for line in early.preamble)


def test_an_okuma_lathe_restart_writes_no_g80_the_end_of_a_lap_contour():
    """The OSP lathe's G80 ends a LAP contour definition (5238-E), no cycle cancel: the
    preamble's modes leave it out."""
    restart = plan(OKUMA_G96, 10, load_profile("okuma-lathe"))
    assert restart.preamble[0] == "G18 G90 G95 G40"


OKUMA_LAP = ("$T.MIN%\nO1\nG50 S2000\nG00 X100. Z100.\nT0101\nG96 S150 M03\nG00 X82. Z5.\n"
             "G85 NLAP1 D4. F0.3 U0.4 W0.1\nNLAP1 G81\nG00 X40.\nG01 Z-30. F0.2\nX60.\nG80\n"
             "G00 X100. Z100.\nG00 X50. Z5.\nG01 Z-10. F0.2\nM02\n")


def test_an_okuma_lathe_restarts_after_a_lap_cycle_and_not_inside_its_contour():
    """A LAP call's U W are finishing allowances and its contour's blocks are the cycle's data
    (5238-E section 8): after the cycle the position is known again at the first absolute X
    and Z; inside the contour definition the restart is refused, naming it."""
    lathe = load_profile("okuma-lathe")
    for line in (15, 16, 17):
        restart = plan(OKUMA_LAP, line, lathe)
        assert restart.preamble[2:4] == ["G50 S2000", "G96 S150 M03"], restart.preamble
    for line in (10, 11, 12, 13):
        assert "LAP contour definition G81 from line 9" in refusal(OKUMA_LAP, line, lathe)
    assert "the cycle G85" in refusal(OKUMA_LAP, 9, lathe)


PARAMETERS = ("%\nO1000\nG21 G90 G17\nG00 X0 Y0 Z50.\nS1000 M03\nG10 L50\nN1420 R15000\n"
              "N1422 P1 R20000\nG11\nG00 X10. Y10.\nM30\n%\n")
TOOL_LIFE = ("%\nO1000\nG21 G90 G17\nT5\nG10 L3\nP1 L500 Q1\nT10\nG11\nM06\nG43 H5 Z50.\n"
             "S1000 M03\nG00 X0 Y0\nG01 Z-1. F100.\nX20.\nM30\n%\n")


def test_no_restart_inside_a_fanuc_data_input_mode_and_its_t_is_no_tool():
    """Inside G10 L50 / G10 L3 ... G11 the control takes blocks as data: a restart there would
    run them as program (refused, naming the mode). A tool life block's T10 selects no tool:
    the restart after the G11 changes to the T5 the program selected."""
    for line in (7, 8, 9):
        assert "G10 L50 data input mode" in refusal(PARAMETERS, line)
    assert plan(PARAMETERS, 10).preamble[-2:] == ["G00 Z50.", "G00 X0 Y0"]
    for line in (6, 7, 8):
        assert "G10 L3 data input mode" in refusal(TOOL_LIFE, line)
    assert plan(TOOL_LIFE, 12).preamble[1] == "T5 M06"


def test_an_okuma_lathe_restart_after_a_home_return_makes_it_again():
    """After `G20 HP=1` (or `G21`, the tool change home position) written alone, X and Z are
    at the machine's home position: the preamble returns there by the same block, as a Fanuc
    lathe's does by its G28, instead of refusing the restart."""
    lathe = load_profile("okuma-lathe")
    restart = plan(OKUMA_G96, 8, lathe)
    assert restart.preamble[-1] == "G20 HP=1", restart.preamble
    assert restart.preamble.count("G20 HP=1") == 1
    text = OKUMA_G96.replace("G20 HP=1\n", "G20 HP=1 M05\n")  # not alone: not followed
    assert "position of X is not known" in refusal(text, 8, lathe)


LATHE_CONTOUR = ("%\nO1000\nG50 S2000\nG00 G21 G40 G99\nT0101\nG96 S200 M03\nG00 X50. Z2.\n"
                 "G01 X40. F0.2\nG71 U1.5 R0.5\nG71 P100 Q200 U0.4 W0.1 F0.25\nN100 G00 X20.\n"
                 "G01 Z-20. F0.1\nN200 X45.\nG70 P100 Q200\nG00 X100. Z100.\nM30\n%\n")


@pytest.mark.parametrize("name", ["fanuc-lathe", "haas-lathe"])
def test_a_lathe_restarts_after_a_g71_at_its_start_point_and_not_inside_its_contour(name):
    """A G71-G73 P Q cycle runs the blocks N P to N Q as its shape, then returns to its start
    point (FANUC 0i-TF, multiple repetitive cycles): the restart at the G70 after it approaches
    X40. Z2., not the contour's end X45. Z-20.; inside the contour, and at its first block, it
    is refused; a feed written in the contour counts in G70 only, so after it the feed in force
    is not known."""
    lathe = load_profile(name)
    assert "F0.1 in the contour of the cycle G71 on line 10" in refusal(LATHE_CONTOUR, 14, lathe)
    restart = plan(LATHE_CONTOUR.replace(" F0.1", ""), 14, lathe)
    assert restart.state.position == {"X": Decimal("40"), "Z": Decimal("2")}
    assert [b for b in restart.preamble if b.startswith("G00 X")][-1] == "G00 X40."
    assert not any("Z-20" in b or "X45" in b for b in restart.preamble), restart.preamble
    assert "N100 to N200 of the cycle G71 from line 10" in refusal(LATHE_CONTOUR, 11, lathe)
    for line in (12, 13):
        assert "the contour N100 to N200 of the cycle G71" in refusal(LATHE_CONTOUR, line, lathe)
    assert restart.state.feed == Decimal("0.25")


@pytest.mark.parametrize(("first", "second", "data"), [
    ("G71 U2. R0.5", "G71 P100 Q200 U0.4 W0.1 F0.25", "G71"),
    ("G72 W2. R0.5", "G72 P100 Q200 U0.4 W0.1 F0.25", "G72"),
    ("G73 U3. W1. R3", "G73 P100 Q200 U0.4 W0.1 F0.25", "G73"),
])
def test_a_fanuc_lathe_restart_at_the_second_block_of_a_two_block_cycle_is_refused(
        first, second, data):
    """G71-G73 U/W R then P Q (FANUC 0i-TF, multiple repetitive cycles): the first block's
    depth of cut and retract are kept as parameters, which the second block runs with; a
    restart there would leave them out, so it is refused, naming the first block. At the first
    block the restart is made, and inside the contour it stays refused."""
    lathe = load_profile("fanuc-lathe")
    text = LATHE_CONTOUR.replace("G71 U1.5 R0.5", first).replace(
        "G71 P100 Q200 U0.4 W0.1 F0.25", second).replace(" F0.1", "")
    assert refusal(text, 10, lathe) == (
        f"cannot restart here: the cycle {data} runs with the data of its first block on line "
        "9 (depth of cut, retract, passes or thread data, which the control keeps as "
        "parameters): a restart here leaves that block out and the cycle runs with whatever "
        "values are stored; restart at line 9")
    assert plan(text, 9, lathe).state.position == {"X": Decimal("40"), "Z": Decimal("2")}
    for line in (11, 12, 13):
        assert "the contour N100 to N200" in refusal(text, line, lathe)
    assert plan(text, 14, lathe).preamble  # the G70 after the cycle


TWO_BLOCK = ("%\nO1000\nG21 G18 G99 G40\nT0101\nG97 S800 M03\nG00 X22. Z5.\n{first}\n"
             "{second}\nG00 X100. Z100.\nM30\n%\n")


@pytest.mark.parametrize(("first", "second", "code"), [
    ("G76 P010060 Q100 R0.05", "G76 X18.16 Z-20. P920 Q300 F1.5", "G76"),
    ("G74 R1.", "G74 Z-30. Q5000 F0.1", "G74"),
    ("G75 R1.", "G75 X15. Z-10. P2000 Q3000 F0.05", "G75"),
])
def test_a_g74_to_g76_second_block_is_refused_and_its_first_block_restarts(first, second, code):
    """G76 P Q R sets the finishing passes, chamfer, angle, minimum depth and allowance; G74
    and G75 R the return (0i-TF): the same as for G71-G73."""
    lathe = load_profile("fanuc-lathe")
    text = TWO_BLOCK.format(first=first, second=second)
    assert f"the cycle {code} runs with the data of its first block on line 7" in refusal(
        text, 8, lathe)
    assert "restart at line 7" in refusal(text, 8, lathe)
    assert plan(text, 7, lathe).state.position == {"X": Decimal("22"), "Z": Decimal("5")}


def test_a_second_block_reusing_an_earlier_first_blocks_data_names_it():
    """A later G72 P Q without a first block of its own runs with the depth and retract of the
    last G71 or G72 first block (the same parameters, 5132/5133), in a run from the start; a
    restart there names that block. A cycle with no first block in the program (a Haas's
    one-block form, or one relying on the control's settings) runs with the same values either
    way, and restarts."""
    fanuc, haas = load_profile("fanuc-lathe"), load_profile("haas-lathe")
    text = LATHE_CONTOUR.replace(" F0.1", "").replace(
        "G70 P100 Q200\n", "G70 P100 Q200\nG00 X50. Z2.\nG72 P100 Q200 U0.4 W0.1 F0.2\n")
    assert "restart at line 9" in refusal(text, 16, fanuc)
    one_block = LATHE_CONTOUR.replace(" F0.1", "").replace("G71 U1.5 R0.5\n", "G00 X40.\n")
    for profile in (fanuc, haas):
        assert plan(one_block, 10, profile).state.position == {"X": Decimal("40"),
                                                               "Z": Decimal("2")}


THREAD_PASSES = ("%\nO1000\nG50 S2000\nG00 G21 G40 G99\nT0101\nG97 S800 M03\nG00 X32. Z5.\n"
                 "G92 X29.3 Z-20. F1.5\nX28.9 Z-20.\nX28.5 Z-20.\nG00 X100. Z100.\nM30\n%\n")


def test_a_lathe_restart_at_a_repeat_of_a_single_cycle_starts_it_from_its_start_point():
    """Each pass of G90/G92/G94, written or repeated by a block of axis words in its mode, ends
    where it started (0i-TF, single canned cycles): the restart at the third pass approaches
    X32. Z5. and sends the pass with its cycle code, never a feed along the thread."""
    for name in ("fanuc-lathe", "haas-lathe"):
        restart = plan(THREAD_PASSES, 10, load_profile(name))
        assert restart.state.position == {"X": Decimal("32"), "Z": Decimal("5")}
        assert restart.first_block == "G92 X28.5 Z-20."
        assert not any("X28.9" in b or "Z-20" in b for b in restart.preamble), restart.preamble
    turning = THREAD_PASSES.replace("G92 X29.3 Z-20. F1.5", "G90 X29.3 Z-20. F0.2").replace(
        "X28.9 Z-20.", "X28.9\nG00 Z8.\nG01 X10.")
    restart = plan(turning, 11, load_profile("fanuc-lathe"))  # the G01 X10. after one axis
    assert restart.state.position == {"X": Decimal("32"), "Z": Decimal("8")}


def test_an_okuma_lathe_restart_at_a_thread_cutting_cycle_pass_starts_it_from_its_start_point():
    """An OSP lathe's G33 is a thread cutting cycle (5238-E section 7), its repeats too: the
    position after a pass is its start point, and the pass is sent with G33."""
    text = ("$A.MIN%\nO1\nG50 S2000\nG00 X100. Z100.\nT0101\nG97 S500 M03\nG00 X32. Z5.\n"
            "G33 X29.3 Z-20. F1.5\nX28.9\nX28.5\nG00 X100. Z100.\nM02\n")
    restart = plan(text, 10, load_profile("okuma-lathe"))
    assert restart.state.position == {"X": Decimal("32"), "Z": Decimal("5")}
    assert restart.first_block == "G33 X28.5"


def test_no_restart_at_a_thread_block_that_continues_a_thread():
    """A G32 block right after a G32 block continues the same thread, which the control cannot
    enter mid-way (its start waits for the spindle's one-revolution signal): refused; the
    thread's first block, after a rapid, is not refused for that."""
    text = ("%\nO1000\nG21 G40 G99\nT0505\nG97 S500 M03\nG00 X18. Z15.\nG00 Z0.2\nX11.6\n"
            "G32 Z-16.6 F1.\nX12. Z-16.8\nG00 X18.\nZ0.2\nX11.4\nG32 Z-16.6 F1.\nG00 X18.\n"
            "M30\n%\n")
    for name in ("fanuc-lathe", "haas-lathe"):
        lathe = load_profile(name)
        assert "continues the thread cut on line 9" in refusal(text, 10, lathe)
        assert plan(text, 14, lathe).first_block is None  # G32 written: its own motion


OKUMA_MILL = ("O1\nG15 H1\nG90 G17 G21 G40 G80\nT1 M06\nG56 H1 Z50.\nS1000 M03\nG00 X0 Y0\n"
              "G01 Z-1. F100.\nX10.\nY10.\nM02\n")


def test_an_okuma_mill_restart_restores_its_work_system_and_length_offset_with_their_h():
    """On an OSP machining centre G15 H selects the work system and G54-G59 H are tool length
    offsets, G53 their cancel (4203-E's List of G Codes): the preamble writes `G15 H1` and
    approaches with `G56 ... H1`, writes no G97 (not in the control's code list), and refuses
    where the H is not plain."""
    mill = load_profile("okuma-mill")
    restart = plan(OKUMA_MILL, 10, mill)
    assert restart.preamble[0].endswith("G15 H1") and " G56" not in restart.preamble[0]
    assert "G00 G56 Z50. H1" in restart.preamble
    assert not any("G97" in b for b in restart.preamble)
    assert "tool length offset on line 5 has no plain H" in refusal(
        OKUMA_MILL.replace("G56 H1", "G56 H=VC1"), 10, mill)
    assert "work coordinate system G15 on line 2" in refusal(
        OKUMA_MILL.replace("G15 H1", "G15 H=VC2"), 10, mill)
    cancelled = OKUMA_MILL.replace("X10.\n", "G53 X10.\n")
    assert not any("G56" in b for b in plan(cancelled, 10, mill).preamble)


def test_a_highest_point_too_long_to_write_in_inch_refuses_the_restart():
    """A Z of 27 digits in mm is 28 and more in inch, past the digits the clearance is written
    with: the restart is refused with the reason, no decimal.InvalidOperation traceback. (Past
    Z's format, too, the word the control refuses: the highest point is not known.)"""
    text = ("%\nO1\nG21 G90 G17 G54\nG00 X0 Y0 Z999999999999999999999999999.\nG20\n"
            "G00 X1. Y1. Z1.\nX2.\nM30\n%\n")
    assert "line 4 holds a word the control refuses" in refusal(text, 7)


WORK_CHANGE = ("%\nO1000\nG21 G90 G54\nT1 M6\nS1000 M3\nG00 X0 Y0\nG43 H1 Z50.\nG01 Z-5. F100\n"
               "X10.\nG55\nG00 X20. Y20.\nG01 X30.\nM30\n%\n")


def test_a_restart_after_a_work_system_change_approaches_the_blocks_own_target_or_refuses():
    """After G54 -> G55 the last position X10 Y0 Z-5 is a place of G54: the same numbers in
    G55 are a point the program never visits (FANUC: G54-G59 select the work system the
    axis words are read in). The restart at the first block after G55 refuses, naming G55,
    unless the block gives every axis; then the approach goes to its own target."""
    assert "changed after the last position of Z (G55 on line 10)" in refusal(WORK_CHANGE, 11)
    whole = WORK_CHANGE.replace("G00 X20. Y20.\n", "G00 X20. Y20. Z2.\n")
    restart = plan(whole, 11)
    assert restart.preamble[0].endswith("G55")
    assert restart.preamble[-2:] == ["G00 X20. Y20.", "G01 Z2. F100."]
    assert not any("X10." in b or "Z-5." in b for b in restart.preamble), restart.preamble
    assert restart.state.position == {"X": Decimal("20"), "Y": Decimal("20"), "Z": Decimal("2")}
    # the same system again is no change; after the block gave every axis the walk knows them
    assert plan(WORK_CHANGE.replace("G55", "G54"), 11).preamble[-1] == "G01 Z-5. F100."
    assert plan(whole, 12).preamble[-1] == "G01 Z2. F100."
    # an axis given as an increment is no target in the new system
    assert "does not give X as an absolute number" in refusal(
        whole.replace("G00 X20. Y20. Z2.", "G91 G00 X20. Y20. Z2."), 11)


def test_an_okuma_mill_restart_after_g15_h_changes_refuses_the_old_point():
    """OSP: G15 H selects the work system (4203-E's List of G Codes): after G15 H1 -> H2 the
    restart at the next move refuses, naming `G15 H2`, where the block does not give Z."""
    text = OKUMA_MILL.replace("Y10.\n", "G15 H2\nG00 X20. Y20.\nG01 X30.\n")
    assert "(G15 H2 on line 10)" in refusal(text, 11, load_profile("okuma-mill"))
    restart = plan(text.replace("G00 X20. Y20.", "G00 X20. Y20. Z2."), 11,
                   load_profile("okuma-mill"))
    assert restart.preamble[0].endswith("G15 H2")
    assert restart.preamble[-2:] == ["G00 X20. Y20.", "G01 Z2. F100."]


# the FANUC form: the repeats give X only, the cycle's Z and R being modal within it
CYCLE_REPEATS = ("%\nO1000\nG21 G99 G40\nT0101\nG97 S800 M03\nG00 X30. Z5.\n"
                 "G92 X29.2 Z-20. F1.5\nX28.6\nX28.2\nG00 X50. Z5.\nG90 X40. Z-20. R-2. F0.2\n"
                 "X38.\nX36. Z-10.\nX34. Z-10. R-1.\nG00 X100. Z100.\nM30\n%\n")


def test_a_lathe_restart_at_a_repeat_without_the_cycles_z_or_r_is_refused():
    """X(U), Z(W) and R of G90/G92/G94 are modal within the cycle (0i-TF, "Canned cycle"), and
    the preamble's G00 ends the cycle: `G92 X28.6` alone would cut the thread over no length,
    `G90 X36. Z-10.` would lose the taper R-2. Refused, naming what is missing; a repeat that
    writes them is restarted with its cycle code."""
    for name in ("fanuc-lathe", "haas-lathe"):
        lathe = load_profile(name)
        assert "the cycle G92 gives no Z (W)" in refusal(CYCLE_REPEATS, 8, lathe)
        assert "the cycle G90 gives no Z (W)" in refusal(CYCLE_REPEATS, 12, lathe)
        assert "taper R from line 11" in refusal(CYCLE_REPEATS, 13, lathe)
        assert plan(CYCLE_REPEATS, 14, lathe).first_block == "G90 X34. Z-10. R-1."
        # a cycle of no R: its repeat with Z is planned
        straight = CYCLE_REPEATS.replace(" R-2.", "")
        assert plan(straight, 13, lathe).first_block == "G90 X36. Z-10."


# -- where the state at the restart block is not the walk's, or the approach must follow the cut --

HEAD = ("%\nO1000\nN10 G21 G17 G90 G40 G49 G80\nN20 T1 M06\nN30 G54 G00 X0 Y0 S1000 M03\n"
        "N40 G43 H1 Z50.\n")  # lines 1-6
CALLED = (HEAD + "N50 M08\nN60 G00 X10. Y10. Z5.\nN70 M98 P2000 L3\nN80 G00 Z50.\nN90 M30\n%\n"
          "%\nO2000\nN100 G90 G00 X20. Y20.\nN110 Z2.\nN120 G01 Z-2. F150.\nN130 G01 X40.\n"
          "N140 G01 Y40.\nN150 G00 Z5.\nN160 M99\n%\n")


def test_no_restart_inside_a_subprogram_whose_state_is_its_callers():
    """O2000 returns by M99: it runs with the tool, spindle, G43 H1 and position O1000 left
    at its M98, none of which a walk from O2000's own start has (a plan there had no tool, no
    spindle and G49). Refused, naming the program and its return; the caller restarts."""
    for line in (16, 18, 19):
        message = refusal(CALLED, line)
        assert message.startswith("cannot restart here: O2000 (the second program of the file) "
                                  "returns to a caller by 'N160 M99' on line 21: a subprogram")
        assert message.endswith("restart the calling program at its call")
    # the caller itself is planned before its call
    assert plan(CALLED, 8).preamble[-3:] == ["M08", "G00 G43 Z50. H1", "G00 X0 Y0"]
    # a Haas local subprogram after the M30 (M97 P), and a macro body, return the same way
    local = HEAD + "N50 M97 P1000\nN60 M30\nN1000 G01 Z-1. F100.\nN1010 X10.\nN1020 M99\n%\n"
    assert "returns to a caller by 'N1020 M99' on line 11" in refusal(local, 10,
                                                                     load_profile("haas-mill"))
    assert agree_on(CALLED, FANUC, list(range(7, 24))) >= 2


def test_no_restart_in_a_sinumerik_subprogram_by_its_name():
    spf = "G90 G0 X10 Y10\nG1 Z-1 F100\nG1 X20\nM17\n"
    sinumerik = load_profile("sinumerik-840d")
    with pytest.raises(RestartRefused) as caught:
        plan_restart(parse_text(spf, sinumerik.dialect), sinumerik, 3, "SUB1.SPF")
    assert "SUB1.SPF" not in caught.value.message  # the file is named by the error's own field
    assert caught.value.message.startswith(
        "cannot restart here: the program is a subprogram (SPF): a subprogram or macro body")


def test_send_notes_that_the_preamble_writes_no_units_code(tmp_path: Path,
                                                           capsys: pytest.CaptureFixture[str]):
    from dnc.program import find_restart
    from tapegate.serial_cli import _prepared

    src = tmp_path / "p.nc"
    src.write_text(PART.replace("N1 G21 ", "N1 "))
    _prepared(workflow.RestartFound(find_restart(str(src), FANUC, "N8", "p.nc")))
    shown = capsys.readouterr().err
    assert "preamble:\n    G17 G90 G94 G40 G49 G80 G54\n" in shown
    assert ("note: no units code: the program selects none before line 10, so the control's "
            "setting applies, as in a run from the start (tapegate read it as mm)") in shown


def test_a_later_program_of_a_memory_backup_without_its_own_units_code_is_refused():
    """A FANUC memory backup: O2000 after O1000 (which ran in G20) writes no G20/G21, so its
    units are whatever the control is in when it starts (convert calls them ambiguous): no
    preamble may choose them. With its own G21 the restart is planned."""
    backup = ("%\n&F=//CNC_MEM/\nO1000(A)\nG20 G91 G18\nG01 X1. F10.\nM99\nO2000(B)\n"
              "G17 G90 G00 X10. Y10. Z5.\nG01 Z-1. F100.\nG01 Y20.\nM30\n%\n")
    assert refusal(backup, 10) == (
        "cannot restart here: O2000 follows another program in the file and selects no units "
        "before this block: it runs in the units the control is in when it starts, which the "
        "program before it may have set; tapegate cannot tell them (convert calls them "
        "ambiguous); restart at a block after the program's own G20/G21")
    own = backup.replace("G17 G90 G00", "G21 G17 G90 G00")
    assert plan(own, 10).preamble[0].startswith("G21 G17 G90")
    # a SINUMERIK starts each program in its machine data's units: the note, no refusal; a
    # later _SPF is a subprogram
    sinumerik = load_profile("sinumerik-840d")
    archive = ("%_N_A_MPF\nG70 G17 G90\nT1 M6\nG0 X1 Y1 Z1\nM30\n%_N_B_MPF\nG17 G90 T2 M6\n"
               "S1000 M3\nG0 X10 Y10 Z5\nG1 Z-1 F100\nG1 X20\nM30\n")
    restart = plan(archive, 11, sinumerik)
    assert restart.preamble[0] == "G17 G90 G94 G40" and restart.notes
    assert refusal(archive.replace("B_MPF", "B_SPF"), 11, sinumerik).startswith(
        "cannot restart here: %_N_B_SPF (the second program of the file) is a subprogram (SPF)")


def test_no_units_code_is_written_where_the_program_selects_none():
    """A program with no G20/G21 runs in the control's setting (Haas Setting 9, FANUC's
    retained G20/G21); the preamble writes none, and says so. The clearance is then the
    program's own highest point, a number that is the same height in either unit."""
    text = ("%\nO1009\nN10 T1 M06\nN20 G54 G90 G00 X0 Y0 S1000 M03\nN30 G43 H1 Z2.\n"
            "N40 G00 X1. Y1. Z0.2\nN50 G01 Z-0.1 F15.\nN60 G01 X4.\nN70 G01 Y4.\nN80 G00 Z2.\n"
            "N90 M30\n%\n")
    for name in ("haas-mill", "fanuc-mill"):
        restart = plan(text, 9, load_profile(name))
        assert restart.preamble[0] == "G17 G90 G94 G40 G49 G80 G54"
        assert restart.preamble[-3:] == ["G00 G43 Z2. H1", "G00 X4. Y1.", "G01 Z-0.1 F15."]
        assert restart.notes[0].startswith("no units code: the program selects none before "
                                           "line 9, so the control's setting applies")
    mine = replace(FANUC, restart=replace(FANUC.restart, clearance=Decimal("1")))
    assert plan(text, 9, mine).preamble[-3] == "G00 G43 Z2. H1"  # not Z1.: 1 mm or 1 in


def test_no_restart_after_increments_from_a_start_the_program_never_set():
    """G91 moves from where the operator put the tool: the modal state counts them from 0,
    which is nowhere. Refused until an absolute move sets the axis (as the checker does)."""
    text = ("%\nO1005\nN10 G21 G17 G90\nN20 T1 M06\nN30 S1000 M03\nN40 G91 G01 Z-5. F100.\n"
            "N50 X10.\nN60 Y10.\nN70 G90 G00 Z50.\nN80 X0 Y0\nN90 Z5.\nN100 M30\n%\n")
    assert refusal(text, 7) == ("cannot restart here: the position of Z is not known here "
                                "(line 6: Z-5., an increment from a position the program has "
                                "not set)")
    assert "the position of X is not known" in refusal(text, 9)
    assert "the position of X is not known" in refusal(text, 10)  # G90 Z50. sets Z only
    assert plan(text, 11).preamble[-3:] == ["G00 Z50.", "G00 X0 Y0", "F100."]
    # the axes never set at all: the plunge would be wherever the operator left the tool
    unset = HEAD.replace(" X0 Y0", "") + "N50 Z5.\nN60 G01 Z-2. F100.\nN70 G91 X10.\nN80 M30\n"
    assert refusal(unset, 9).startswith("cannot restart here: the program has not set X and Y "
                                        "before it")


MIRROR = HEAD + ("N50 G00 X10. Y10.\nN60 Z5.\nN70 G01 Z-2. F100.\nN80 G51.1 X0\n"
                 "N90 G01 X20. Y10.\nN100 G50.1 X0\nN110 G01 X30. Y10.\nN120 X40.\nN130 M30\n%\n")


def test_no_restart_under_a_mirror_image_nor_after_its_cancel_until_the_axes_are_given():
    """FANUC G51.1 X0 (0i-MF, programmable mirror image) moves nothing; under it N90 cuts to
    X-20. A restart there is refused; after G50.1 the tool stands at the mirrored X-20, so the
    next block's start is not the number the program wrote. Haas G101/G100 the same."""
    assert refusal(MIRROR, 11) == ("cannot restart here: G51.1 (programmable mirror image) from "
                                   "line 10 is in force and the preamble cannot restore it")
    assert "G51.1 (programmable mirror image)" in refusal(MIRROR, 12)
    assert refusal(MIRROR, 13) == (
        "cannot restart here: the position of X is not known here (line 12: G50.1 ends the "
        "mirror image: the tool stands where the transformed moves left it, not at the number "
        "the program wrote)")
    assert plan(MIRROR, 14).preamble[-2:] == ["G00 X30. Y10.", "G01 Z-2. F100."]
    haas = (MIRROR.replace("N80 G51.1 X0", "N80 G101 X0")
            .replace("N100 G50.1 X0", "N100 G100"))
    assert "G101 (mirror image) from line 10" in refusal(haas, 11, load_profile("haas-mill"))
    assert "(line 12: G100 ends the mirror image" in refusal(haas, 13, load_profile("haas-mill"))


def test_a_mirror_stays_on_until_its_last_axis_ends():
    """Review 15, 2 in the restart walk: G50.1 X0 ended the whole mirror, so a restart under
    the Y mirror still in force was planned unmirrored. G50.1 ends the axes it names; the
    restart is refused until none is mirrored."""
    both = (MIRROR.replace("N80 G51.1 X0", "N80 G51.1 X0 Y0")
            .replace("N120 X40.", "N120 G50.1 Y0\nN125 X40. Y10.\nN127 X50."))
    for line in (13, 14):  # line 14 was planned to the unmirrored Y10. of line 13
        assert refusal(both, line) == ("cannot restart here: G51.1 (programmable mirror image) "
                                       "from line 10 is in force and the preamble cannot "
                                       "restore it")
    assert plan(both, 16).preamble[-2:] == ["G00 X40. Y10.", "G01 Z-2. F100."]



AXIS_GIVEN_AFTER_ITS_CANCEL = (
    "%\nO1000\nN1 G21 G17 G90 G54\nN2 T1 M06\nN3 S1000 M03 G43 H1 Z1.\nN4 G00 X0 Y400.\n"
    "N5 G51.1 X0 Y0\nN6 G00 X10. Y-300.\nN7 G50.1 Y0\nN8 G00 Y-10.\nN9 G50.1 X0\n"
    "N10 G00 X5.\nN11 G00 Z2.\nN12 G00 Z3.\nM30\n%\n")  # N11 is line 13


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill"])
def test_an_axis_given_after_its_own_mirror_ended_is_known_at_a_later_cancel(profile):
    """Review 26, 2: Y, given plainly (N8) after `G50.1 Y0` ended its mirror, was called "not
    known" at `G50.1 X0` (N9), which ends X's mirror only; every axis moved while any mirror
    was on was taken as transformed. A mirror moves the axes it mirrors (FANUC G51.1, Haas
    G101 name them): N11 is restartable at X5. Y-10.; X is lost at N9 until N10 gives it."""
    haas = profile == "haas-mill"
    text = AXIS_GIVEN_AFTER_ITS_CANCEL
    if haas:
        text = (text.replace("G21", "G20").replace("G51.1", "G101").replace("G50.1", "G100")
                .replace("Y400.", "Y4.").replace("X10. Y-300.", "X1. Y-3.")
                .replace("Y-10.", "Y-1."))
    p = load_profile(profile)
    code = "G100" if haas else "G50.1"
    assert refusal(text, 12, p) == (
        f"cannot restart here: the position of X is not known here (line 11: {code} ends the "
        "mirror image: the tool stands where the transformed moves left it, not at the number "
        "the program wrote)")
    y = "Y-1." if haas else "Y-10."
    assert f"G00 X5. {y}" in plan(text, 13, p).preamble
    # Y not given after its cancel: lost there, and named with its own cancel (line 9)
    kept = text.replace(f"N8 G00 {y}\n", "")
    assert refusal(kept, 12, p) == (
        f"cannot restart here: the position of Y is not known here (line 9: {code} ends the "
        "mirror image: the tool stands where the transformed moves left it, not at the number "
        "the program wrote)")
    # Y given by an increment after its cancel: still not known
    step = text.replace(f"N8 G00 {y}", f"N8 G91 G00 {y}\nN85 G90")
    assert "the position of Y is not known here (line 9:" in refusal(step, 14, p)


def test_an_axis_never_mirrored_is_not_lost_at_the_mirror_s_cancel_but_under_a_rotation_it_is():
    """A move of Y under the mirror of X alone leaves Y at its number: planned after the
    cancel once X is given. Under a rotation (G68) too, every axis moved is lost at G69."""
    text = ("%\nO1000\nN1 G21 G17 G90 G54\nN2 T1 M06\nN3 S1000 M03 G43 H1 Z1.\n"
            "N4 G00 X0 Y0\nN5 G51.1 X0\nN6 G00 X10. Y20.\nN7 G50.1 X0\nN8 G00 X5.\n"
            "N9 G00 Z2.\nM30\n%\n")  # N9 is line 11
    assert "G00 X5. Y20." in plan(text, 11).preamble
    rotated = text.replace("N5 G51.1 X0", "N5 G68 X0 Y0 R90.").replace("N7 G50.1 X0", "N7 G69")
    assert "the position of Y is not known here (line 9: G69 ends" in refusal(rotated, 11)


def test_an_okuma_mill_s_frames_refuse_the_restart():
    """Review 15, 3 in the restart walk: an Okuma mill's G11 (parallel and rotation shift) was
    not known, so a restart under it was planned without it; its G16 (a work system for one
    block) was taken for FANUC's polar coordinates and its G69 (3-D conversion on) for a
    cancel. G11 until G10, G69 until G68 and G62 are frames the preamble cannot restore."""
    okuma = load_profile("okuma-mill")
    text = ("%\nO1000\nG21 G17 G90 G15 H1\nG00 X0 Y0 Z50.\n{}\nN10 G00 X20. Y5.\n"
            "N20 G01 Z-1. F100\nN30 X30.\n{}\nN40 G00 Z50.\nN50 X0 Y0\nN60 X5.\nM30\n%\n")
    for frame, cancel, name in (("G11 X10. Y0 R90.", "G10", "G11 (parallel and rotation shift"),
                                ("G69 X0 Y0 Z0", "G68", "G69 (3-D coordinate system conversion"),
                                ("G62 X0", "", "G62 (programmable mirror image")):
        program = text.format(frame, cancel)
        assert refusal(program, 8, okuma).startswith(f"cannot restart here: {name}"), frame
        if cancel:  # the block after an absolute X Y
            assert "G00 X0 Y0" in plan(program, 12, okuma).preamble, frame
    one_block = text.format("G16 H2", "")
    assert plan(one_block, 8, okuma).preamble[-1] == "G01 Z-1. F100."


def test_an_okuma_mill_s_air_cut_reduction_refuses_the_restart():
    """Review 57b F6: the profile's G38 (air cut reduction mode ON, G37 its cancel: the later
    OSP machining centres' List of G Codes) was planned past without a word, the mode dropped;
    the preamble does not write it, so a restart under it is refused, with the code and its
    line, and one after its G37 is planned (nothing of the position is lost at the cancel)."""
    okuma = load_profile("okuma-mill")
    text = ("%\nO1000\nN1 G15 H1\nN2 T1 M6\nN3 S1000 M3\nN4 G38\nN5 G0 X10. Y10. Z50.\n"
            "N6 G1 Z-5. F500\nN7 G1 X20.\nN8 G37\nN9 G0 Z50.\nN10 X0 Y0\nM02\n%\n")
    assert refusal(text, 9, okuma) == ("cannot restart here: G38 (air cut reduction) from "
                                       "line 6 is in force and the preamble cannot restore it")
    assert plan(text, 11, okuma).preamble[-2:] == ["G00 X20. Y10.", "G01 Z-5. F500."]
    after = plan(text, 12, okuma).preamble
    assert "G00 X20. Y10." in after and not any("G3" in line for line in after)


def test_an_okuma_mill_s_one_block_work_system_loses_the_axes_it_moves():
    """Review 16b, 1: after `G16 H2 G00 X20. Y5.` (work system 2 for that block only) the
    tool stands at X20 Y5 of system 2; the restart went to X20 Y5 of system 1 (`G15 H1`) and
    plunged there. Refused until an absolute position gives the axis again; a restart at the
    G16 block itself makes the program's own move and is planned."""
    okuma = load_profile("okuma-mill")
    text = ("%\nO1000\nN1 G21 G17 G90 G15 H1\nN2 G00 X0 Y0 Z50.\nN3 T1 M06\nN4 S1000 M03\n"
            "N5 G16 H2 G00 X20. Y5.\nN20 G01 Z-1. F100\nN30 X30.\nN40 G00 Z50.\n"
            "N50 X0 Y0\nN60 X5.\nM30\n%\n")  # N5 is line 7
    for line, axis in ((8, "X"), (9, "Y"), (10, "Y")):  # N30 X30. gives X; Y is of system 2
        assert refusal(text, line, okuma) == (
            f"cannot restart here: the work coordinate system changed after the last position "
            f"of {axis} (G16 H2 (a work coordinate system for one block) on line 7) and the "
            f"block does not give {axis} as an absolute number: the position in the new system "
            f"is not known; restart at a block that gives every axis")
    assert plan(text, 12, okuma).preamble[-2:] == ["G00 X0 Y0", "F100."]
    assert plan(text, 7, okuma).preamble[-1] == "G00 X0 Y0"  # then N5 runs as written
    # a G16 that moves no axis leaves every position as it was
    no_move = text.replace("N5 G16 H2 G00 X20. Y5.", "N5 G16 H2")
    assert plan(no_move, 8, okuma).preamble[-1] == "G00 X0 Y0"


def test_a_haas_mirror_s_words_are_no_move_and_its_cancel_is_per_axis():
    """Review 16b, 2 in the restart walk: `G100 X0` was read as a move to X0 (the restart
    plunged 1 in from where the program cut), and ended the Y mirror too (planned at the
    unmirrored Y2.). G100's words name the axes whose mirror ends (96-8000, G101)."""
    haas = load_profile("haas-mill")
    text = ("%\nO1000\nN1 G20 G17 G90 G54\nN2 T1 M06\nN3 S1000 M03\nN4 G00 X1. Y1.\n"
            "N5 G43 H1 Z1.\nN6 G01 Z-0.1 F10.\nN7 G101 X0\nN8 G100 X0\nN20 Y2.\n"
            "N30 G00 Z1.\nM30\n%\n")  # N20 is line 11
    assert plan(text, 11, haas).preamble[-2:] == ["G00 X1. Y1.", "G01 Z-0.1 F10."]
    both = text.replace("N7 G101 X0", "N7 G101 X0 Y0").replace("N20 Y2.", "N11 X3. Y2.\nN20 X4.")
    assert refusal(both, 12, haas) == ("cannot restart here: G101 (mirror image) from line 9 "
                                       "is in force and the preamble cannot restore it")
    ended = both.replace("N8 G100 X0", "N8 G100 X0 Y0")
    assert plan(ended, 12, haas).preamble[-2:] == ["G00 X3. Y2.", "G01 Z-0.1 F10."]


def test_a_haas_g101_naming_no_axis_refuses_the_restart_until_g100():
    """Review 17: `G101` with no axis word set nothing in the walk, and a restart after it was
    planned as if no mirror were on; the check takes it as the mirror of X, Y and Z (no page at
    hand says what it mirrors), and so does the walk now, until a G100 ends them."""
    haas = load_profile("haas-mill")
    text = ("%\nO1000\nN1 G20 G17 G90 G54\nN2 T1 M06\nN3 S1000 M03\nN4 G00 X1. Y1.\n"
            "N5 G43 H1 Z1.\nN6 G101\nN7 G01 Z-0.1 F10.\nN8 X2.\nN20 Y3.\nN30 G00 Z1.\n"
            "N40 G100\nM30\n%\n")  # N20 is line 11
    assert refusal(text, 11, haas) == ("cannot restart here: G101 (mirror image) from line 8 "
                                       "is in force and the preamble cannot restore it")
    # a G100 naming no axis ends them all; Z, moved under the mirror, is lost until given
    ended = text.replace("N8 X2.\n", "N8 X2.\nN9 G100\nN10 G00 X4. Y5.\n")
    assert "the position of Z is not known here (line 11: G100 ends the mirror image" in \
        refusal(ended, 13, haas)
    given = ended.replace("N10 G00 X4. Y5.\n", "N10 G00 X4. Y5.\nN11 G01 Z-0.2\n")
    assert plan(given, 14, haas).preamble[-2:] == ["G00 X4. Y5.", "G01 Z-0.2 F10."]


def test_an_okuma_mill_s_g69_words_are_not_known_rather_than_moves():
    """Review 16b, 6: the words of an Okuma mill's G69 (3-D conversion; no page at hand gives
    them) were read as moves under the conversion, and the refusal blamed the G68 cancel for
    a Y the program never moved. They are unknown, as G11's and G62's are, and said so."""
    okuma = load_profile("okuma-mill")
    text = ("%\nO1000\nN1 G21 G17 G90 G15 H1\nN2 T1 M06\nN3 S1000 M03\n"
            "N4 G00 X10. Y10. Z50.\nN5 G69 X0 Y0 Z-5.\nN6 G68\nN7 G00 X20.\n"
            "N20 G01 Z-1. F100\nN30 X30.\nN40 G00 Z50.\nN50 Y10.\nN60 X5.\nM30\n%\n")
    assert refusal(text, 10, okuma) == (
        "cannot restart here: the position of Y is not known here (line 7: Y0 in an Okuma "
        "frame block, whose axis words no page at hand gives)")
    assert plan(text, 15, okuma).preamble[-2:] == ["G00 X5. Y10.", "F100."]


def test_an_okuma_mill_s_g53_is_a_move_with_the_length_offset_cancelled():
    """Review 16b, 4 in the restart walk: an OSP mill's G53 cancels the tool length offset
    (OSP List of G Codes), no machine coordinates: `G53 G00 Z50.` leaves Z at 50 of the work
    system, which the preamble goes to, not a machine position sent again."""
    okuma = load_profile("okuma-mill")
    text = ("%\nO1000\nN1 G21 G17 G90 G15 H1\nN2 T1 M06\nN3 S1000 M03\n"
            "N4 G00 X10. Y10.\nN5 G53 G00 Z50.\nN20 G01 X20. F100\nM30\n%\n")
    preamble = plan(text, 8, okuma).preamble
    assert preamble[-2:] == ["G00 Z50.", "G00 X10. Y10."], preamble
    assert not any("G53" in block for block in preamble), preamble


def test_no_restart_after_a_rotation_or_scaling_cancel_until_the_axes_are_given():
    """After G69 the tool stands at the rotated point (FANUC: the first move after G69 is
    absolute, from there); after G50 at the scaled one. Refused at the block that moves from
    it; the block after, which starts at the absolute point given, is planned."""
    rotated = HEAD + ("N50 G00 X10. Y10.\nN60 Z5.\nN70 G01 Z-2. F100.\nN80 G01 X20. Y10.\n"
                      "N90 G68 X0 Y0 R30.\nN100 G01 X30. Y10.\nN110 X40.\nN120 G69\n"
                      "N130 G01 X50. Y10.\nN140 G00 Z50.\nN150 M30\n%\n")
    assert refusal(rotated, 15) == (
        "cannot restart here: the position of X is not known here (line 14: G69 ends the "
        "coordinate rotation: the tool stands where the transformed moves left it, not at the "
        "number the program wrote)")
    assert plan(rotated, 16).preamble[-2:] == ["G00 X50. Y10.", "G01 Z-2. F100."]
    scaled = rotated.replace("G68 X0 Y0 R30.", "G51 X0 Y0 P2000").replace("G69", "G50")
    assert "(line 14: G50 ends the scaling" in refusal(scaled, 15)
    # a rotation set and cancelled with no move under it leaves the position as it was
    idle = rotated.replace("N100 G01 X30. Y10.\nN110 X40.\n", "")
    assert plan(idle, 13).preamble[-2:] == ["G00 X20. Y10.", "G01 Z-2. F100."]


GROOVE = ("%\nO2002\nN10 G21 G18 G40 G99\nN20 T0505\nN30 G97 S600 M03\nN40 G00 X55. Z5.\n"
          "N50 M08\nN60 G00 X52. Z-20.\nN70 G01 X40. F0.05\nN80 G00 X52.\nN90 Z-23.\n"
          "N100 G01 X40.\nN110 G00 X52.\nN120 G00 X100. Z100.\nN130 M30\n%\n")


def test_a_lathe_restart_after_a_radial_cut_goes_in_the_way_the_program_went():
    """A grooving tool reached the groove's bottom by feeding in X: the approach goes the
    program's way from the clearance plane (its rapid from X55. Z5. to X52. Z-20., then its
    feed in X), where the old approach fed along Z at X40. through 20 mm of bar."""
    lathe = load_profile("fanuc-lathe")
    head = ["G21 G18 G99 G40 G80", "T0505", "G97 S600 M03", "M08", "G00 X55.", "G00 Z5."]
    way = ["G00 X52. Z-20.", "G01 X40. F0.05", "G00 X52.", "G00 Z-23."]
    for line in (9, 10, 11, 12):  # at N70, N80, N90, N100
        restart = plan(GROOVE, line, lathe)
        assert restart.preamble[:6] == head
        assert restart.preamble[6:] == way[:line - 8]
    assert plan(GROOVE, 10, load_profile("haas-lathe")).preamble[-2:] == way[:2]
    # an OSP lathe's feed per revolution is G95 (G99 is none of its codes: refused after it)
    osp = load_profile("okuma-lathe")
    assert plan(GROOVE.replace("G99", "G95"), 10, osp).preamble[-2:] == way[:2]
    with pytest.raises(RestartRefused) as refused:
        plan(GROOVE, 10, osp)
    assert "a G code the control's list does not hold" in refused.value.message
    # an internal groove (the feed outward, from a bore) goes in the same way
    bore = GROOVE.replace("N60 G00 X52. Z-20.\nN70 G01 X40. F0.05\nN80 G00 X52.",
                          "N60 G00 X30. Z-20.\nN70 G01 X34. F0.05\nN80 G00 X30.")
    assert plan(bore, 10, lathe).preamble[6:] == ["G00 X30. Z-20.", "G01 X34. F0.05"]


def test_a_lathe_restart_after_a_radial_move_is_refused_where_the_way_in_is_out_of_reach():
    """The walk keeps a lathe's last 8 moves: after more pecks than that since the rapid in,
    the way in is not known, and a feed along Z at the groove's diameter could cut the bar."""
    pecks = GROOVE.replace("N70 G01 X40. F0.05\n", "".join(
        f"N7{i} G01 X{50 - 2 * i}. F0.05\nN7{i}5 G00 X{51 - 2 * i}.\n" for i in range(5)))
    lathe = load_profile("fanuc-lathe")
    assert plan(pecks, 16, lathe).preamble[-1] == "G01 X44. F0.05"
    assert refusal(pecks, 17, lathe) == (
        "cannot restart here: the tool reached X45. Z-20. after a radial move (line 16), and "
        "the way the program went in from the clearance plane is not among the moves the walk "
        "keeps of this tool: a feed along Z at that diameter could cut the bar or a bore's wall; "
        "restart at the block that brings the tool in")


@needs_shops
def test_the_doosan_lathe_grooves_restart_the_way_the_program_went_in_or_are_refused():
    """Doosan Lynx 300 O2672's ID groove (G00X2.5Z.05 / G00X3.15Z-1.316 / G01X3.58F.003): in
    through the bore as the program went, where the old plan went out to X5. through the wall
    and fed along Z at X3.58. O0073's OD groove right after its G70 (whose moves the walk does
    not follow) is refused; the groove's own block, an approach along Z above the finished
    diameter, is planned."""
    lathe = load_profile("fanuc-lathe")
    ident = (SHOPS / "mikemacfarland__Doosan-Lynx-300__O2672").read_text("latin-1")
    assert plan(ident, 129, lathe).preamble[-4:] == [
        "G00 Z10.", "G00 X2.5 Z0.05", "G00 X3.15 Z-1.316", "G01 X3.58 F0.003"]
    assert plan(ident, 133, lathe).preamble[-4:] == [
        "G00 X3.15", "G00 Z-1.3994", "G01 X3.2487 Z-1.35 F0.003", "G01 X3.59 F0.003"]
    od = (SHOPS / "mikemacfarland__Doosan-Lynx-300__O0073").read_text("latin-1")
    assert "after a radial move (line 68)" in refusal(od, 69, lathe)
    assert plan(od, 68, lathe).preamble[-2:] == ["G00 X4.625", "G01 Z-1.045 F0.0065"]


def test_the_first_plunge_after_the_programs_own_rapid_feeds_at_the_blocks_f():
    """`Z5.` in rapid then `G01 Z-2. F100.`: no feed was in force before, the block carries
    its own, which the approach down to Z5. uses (it was refused for want of a feed)."""
    first = HEAD + "N50 G00 X10. Y10.\nN60 Z5.\nN70 G01 Z-2. F100.\nN80 X20.\nN90 M30\n%\n"
    assert plan(first, 9).preamble[-3:] == ["G00 G43 Z50. H1", "G00 X10. Y10.",
                                            "G01 Z5. F100."]
    bare = first.replace("N70 G01 Z-2. F100.", "N70 G01 Z-2.")
    assert refusal(bare, 9) == ("cannot restart here: no feed rate is in force before it for "
                                "the approach to Z5., and the block gives none")


LINUXCNC = load_profile("linuxcnc")


def test_linuxcnc_g43_without_h_is_restored_after_the_tool_change():
    """rs274ngc's convert_tool_length_offset: G43 with no H applies the tool in the spindle's
    length, so after the preamble's `t1 m6` a plain G43 restores it. A G43 written before a
    later tool change (the old tool's length) is refused."""
    text = ("g21 g17 g90\nt1 m6\ns1000 m3\ng43 g0 z50\ng0 x0 y0\ng1 z-1 f100\ng1 x10\n"
            "g1 x20\nm2\n")
    assert plan(text, 8, LINUXCNC).preamble[1:] == ["t1 m6", "G97 S1000. M03", "G00 G43 Z50.",
                                                    "G00 X10. Y0", "G01 Z-1. F100."]
    late = text.replace("g1 x10\n", "t2 m6\ng1 x10\n")
    assert "G43 on line 4 has no H" in refusal(late, 9, LINUXCNC)


def test_a_sinumerik_tool_name_is_restored():
    """840D tool management: T="MILL10" names the tool, a constant; it is restored as the
    program selects it, with its M6 and D."""
    text = ('N10 G17 G90 G71 G54\nN20 T="MILL10" D1\nN30 M6\nN40 S2000 M3 M8\n'
            "N50 G0 X0 Y0 Z50\nN60 G0 X10 Y10 Z5\nN70 G1 Z-2 F200\nN80 G1 X40\nN90 M30\n")
    sinumerik = load_profile("sinumerik-840d")
    restart = plan(text, 8, sinumerik)
    assert restart.preamble[1:3] == ['T="MILL10" M6', "D1"]


def test_mist_and_flood_on_together_are_both_restored_where_the_control_has_both():
    """LinuxCNC: M7 and M8 are on together (rs274: MIST_ON, FLOOD_ON) until M9; the preamble
    writes both, one a block, the one in force last. A FANUC's M08 alone is its coolant."""
    text = ("g21 g17 g90\nt1 m6\ns1000 m3\ng43 h1 g0 z50\ng0 x0 y0\nm7\nm8\ng1 z-1 f100\n"
            "g1 x10\ng1 x20\nm2\n")
    preamble = plan(text, 10, LINUXCNC).preamble
    assert preamble[3:5] == ["M07", "M08"]
    off = text.replace("m8\n", "m8\nm9\nm8\n")
    assert "M07" not in plan(off, 12, LINUXCNC).preamble
    fanuc = HEAD + "N50 M07\nN60 M08\nN70 G00 X0 Y0 Z5.\nN80 G01 Z-1. F100.\nN90 X10.\n"
    assert [b for b in plan(fanuc, 11).preamble if b.startswith("M0")] == ["M08"]


def test_a_restart_after_g92_1_is_planned_from_the_blocks_own_target():
    """G92.1 cancels the G92 shift: no shift is in force after it (it was refused as if it
    were). The shifted axes' numbers change under the tool, so the approach goes to the
    block's own target of X and Y; Z, which the G92 did not set, is kept."""
    text = ("g21 g17 g90\nt1 m6\ng54 g0 x0 y0 s1000 m3\ng43 h1 z50\ng0 x10 y10\nz5\n"
            "g1 z-2 f100\ng92 x0 y0\ng1 x10 y0\ng92.1\ng1 x40 y10\ng1 x50\nm2\n")
    assert "G92 (a coordinate system set" in refusal(text, 10, LINUXCNC)
    assert plan(text, 11, LINUXCNC).preamble[-2:] == ["G00 X40. Y10.", "G01 Z-2. F100."]
    assert plan(text, 12, LINUXCNC).preamble[-2:] == ["G00 X40. Y10.", "G01 Z-2. F100."]


def test_a_linuxcnc_restart_selects_the_diameter_mode_the_program_selected(tmp_path: Path):
    """LinuxCNC's G7 reads X as a diameter, G8 as a radius (G-code reference, G7/G8): a preamble
    without it leaves the control in its start-up mode, and rs274 runs the restarted X28. at
    twice (or half) the program's. The preamble writes the mode in force; a program that
    switches mode after X had a position is refused (the X in force, written in the other mode,
    is not converted); a program that selects none gets none (the control's setting, as in a
    run from the start)."""
    text = ("G21 G18 G7 G90 G94\nT1 M6\nS1000 M3\nG00 X30. Z2.\nG01 Z-20. F50.\nX32.\nG00 Z2.\n"
            "X28.\nG01 Z-20.\nX32.\nG00 Z2.\nM2\n")
    restart = plan(text, 10, LINUXCNC)
    assert restart.preamble[0] == "G21 G18 G90 G94 G40 G49 G80 G54 G7"
    radius = text.replace("G7 G90", "G8 G90")
    assert plan(radius, 10, LINUXCNC).preamble[0].endswith(" G8")
    assert "G7" not in plan(text.replace(" G7", ""), 10, LINUXCNC).preamble[0]
    # rs274, the oracle: the restarted pass feeds at the original's radius (14), not at 28
    sent = "\n".join([*restart.preamble, "X32.", "M2"]) + "\n"
    feeds = [[v.strip() for v in line.split("(")[1].split(",")[:3]] for line in
             rs274_output(tmp_path, sent).splitlines() if "STRAIGHT_FEED" in line]
    assert feeds == [["14.0000", "0.0000", "-20.0000"], ["16.0000", "0.0000", "-20.0000"]]
    switched = text.replace("X28.\n", "G8\nX14.\n")
    assert refusal(switched, 9, LINUXCNC) == (
        "cannot restart here: the G8 on line 8 changed between diameter (G7) and radius (G8) "
        "mode after X had a position: the X in force and the largest X the program went to "
        "were written in the other mode, which the walk does not convert")
    # X written again in the new mode (line 9): the X in force is a radius, as rs274 reads it
    again = plan(switched, 10, LINUXCNC)
    assert again.preamble[0].endswith(" G8") and "G00 X14." in again.preamble
    sent = "\n".join([*again.preamble, "G01 Z-20.", "M2"]) + "\n"
    feeds = [[v.strip() for v in line.split("(")[1].split(",")[:3]] for line in
             rs274_output(tmp_path, sent).splitlines() if "STRAIGHT_FEED" in line]
    assert feeds == [["14.0000", "0.0000", "-20.0000"]]
    assert plan(switched, 12, LINUXCNC).preamble[0].endswith(" G8")
    # an increment of X before it counts from the old mode's number: still refused after
    stepped = switched.replace("G8\nX14.\n", "G8\nG91 X-1.\nG90 X14.\n")
    assert "the G8 on line 8 changed" in refusal(stepped, 12, LINUXCNC)


LINUXCNC_LATHE = profile_from_text(
    resources.files("formats.profiles").joinpath("linuxcnc.toml").read_text(encoding="utf-8")
    .replace('control_type = "contouring"', 'control_type = "lathe"', 1),
    "linuxcnc-lathe.toml")


def test_a_linuxcnc_lathe_restarts_after_a_mode_switch_once_x_is_written_in_the_new_mode():
    """On a lathe the largest X is the retract: after G8 the diameter 62. is the radius 31.,
    which the approach retracts to; before X is written in the new mode the restart is
    refused."""
    assert LINUXCNC_LATHE.control_type == "lathe"
    text = ("G18 G21 G90 G7\nT1 M6\nG96 S200 M3\nG0 X60 Z5\nG1 Z-20 F0.2\nG0 X62 Z5\nG8\n"
            "G0 X30 Z5\nG1 Z-30 F0.2\nG0 X31 Z5\nG1 X29\nG1 Z-10\nG1 X31\nM2\n")
    assert "the G8 on line 7 changed" in refusal(text, 8, LINUXCNC_LATHE)
    for line in (9, 11, 12):
        restart = plan(text, line, LINUXCNC_LATHE)
        assert restart.preamble[0].endswith(" G8"), restart.preamble
        assert "G00 X31." in restart.preamble, restart.preamble  # the radius of X62.
        assert not any("X62" in b for b in restart.preamble), restart.preamble
    # the first X after the switch feeds in from below the clearance plane: where from, in the
    # new mode's numbers, is not known; the switch itself restarts (in G7, then its G8)
    direct = ("G18 G21 G90 G7\nT1 M6\nG96 S200 M3\nG0 X60 Z5\nG1 Z-20 F0.2\nG8\n"
              "G1 X29 Z-22\nG1 Z-30\nG1 X31\nM2\n")
    assert refusal(direct, 8, LINUXCNC_LATHE) == (
        "cannot restart here: the tool reached X29. Z-22. from X60. Z-20. (line 7), an X "
        "written before the G8 on line 6 switched between diameter and radius mode, below the "
        "clearance plane: the way this tool went in is not known; restart at the G8 (line 6) or "
        "before it")
    assert plan(direct, 6, LINUXCNC_LATHE).preamble[0].endswith(" G7")


TOOL_CHANGE = ("%\nO3002\nG21 G18 G99 G40\nG50 S2000\nT0101\nG96 S200 M03\nG00 X60. Z2. M08\n"
               "G00 X50.\nG01 Z-30. F0.2\nX56.\nG00 Z-5.\nT0202\nG97 S800 M03\nG00 X48.\n"
               "G01 X40. F0.05\nG00 X60.\nM30\n%\n")


def test_a_lathe_restart_never_goes_in_the_way_of_the_tool_before_the_tool_change():
    """T0101 turned X50. to Z-30. and stopped at X56. Z-5.; T0202, a grooving tool, goes in
    radially from there. The old approach replayed T0101's pass with T0202 (32 mm along Z at
    X50.); the moves before a tool change are another tool's path, and the first move after it
    starts where the previous tool left the turret: the groove and the block after the tool
    change are refused (below the clearance plane), the block before it is T0101's restart."""
    lathe = load_profile("fanuc-lathe")
    assert refusal(TOOL_CHANGE, 15, lathe) == (
        "cannot restart here: the tool reached X48. Z-5. from where the previous tool left the "
        "turret at the tool change on line 12 (X56. Z-5., below the clearance plane; this "
        "tool's first move is line 14): the way this tool went in is not known; restart at the "
        "tool change (line 12) or before it")
    for line in (13, 14):
        assert "the tool has not moved since the tool change on line 12" in refusal(
            TOOL_CHANGE, line, lathe)
    before = plan(TOOL_CHANGE, 12, lathe)  # T0202's own block: T0101 goes back to X56. Z-5.
    assert before.preamble[1] == "T0101" and "T0202" not in before.preamble
    # where the previous tool left the turret on the clearance plane, the new tool's first
    # rapid from there is its way in (as Doosan O2672's T1010 from X5. Z10.)
    away = TOOL_CHANGE.replace("G00 Z-5.\nT0202", "G00 Z2.\nT0202").replace(
        "G00 X48.\n", "G00 X48. Z-5.\n")
    restart = plan(away, 15, lathe)
    assert restart.preamble[-3:] == ["G00 X56.", "G00 X48. Z-5.", "F0.2"]
    assert "T0101" not in restart.preamble and restart.notes == [
        "approach: the way the program went in with this tool, from the clearance plane Z2.: "
        "the moves of line 14 again, rapids as rapids, feeds at the feed in force"]


@needs_corpus
def test_the_fanuc0t_restart_at_t0505s_first_cut_does_not_replay_t0202s_pass():
    """GCodeWorkShop FANUC0T.nc line 35 (T0505's first cut): the plan replayed T0202's last
    pass (G00 Z-51.4, G01 X0.106 F0.3) with T0505; T0505 came from where T0202 stopped, below
    the clearance plane: refused."""
    text = (CORPUS / "GCodeWorkShop__FANUC0T.nc").read_text("latin-1")
    message = refusal(text, 35, load_profile("fanuc-lathe"))
    assert "previous tool left the turret at the tool change on line 30" in message


ID_GROOVE = ("%\nO3007\nG21 G18 G99 G40\nG50 S2000\nT0101\nG97 S800 M03\nG00 X28. Z2. M08\n"
             "G01 Z-40. F0.1\nG01 X38. F0.05\nG01 X28.\nG00 Z2.\nG00 X100. Z100.\nM30\n%\n")


def test_a_lathe_restart_never_rapids_along_z_at_a_diameter_the_program_reached_radially():
    """An ID groove in a 30 mm bore: X38. is the largest diameter of the program, reached in X
    at Z-40. only. The old approach took it for a clear lane and rapid G00 Z-40. at X38.
    through the bore's wall; the way in goes from the clearance plane as the program went (in
    along Z at X28., out in X to the groove). A diameter this tool moved along in Z from the
    highest Z down is a lane (a thread's X18., from Z15. to each pass's retract)."""
    lathe = load_profile("fanuc-lathe")
    for line, tail in ((10, ["G00 X28.", "G01 Z-40. F0.05", "G01 X38. F0.05"]),
                       (11, ["G00 X28.", "G01 Z-40. F0.05", "G01 X38. F0.05", "G01 X28. F0.05"])):
        restart = plan(ID_GROOVE, line, lathe)
        assert restart.preamble[-len(tail):] == tail
        assert "G00 Z-40." not in restart.preamble
        assert restart.notes[-1].startswith(
            "approach: the way the program went in with this tool, from the clearance plane Z2.")
    thread = ("%\nO1000\nG21 G40 G99\nT0505\nG97 S500 M03\nG00 X18. Z15.\nG00 Z0.2\nX11.6\n"
              "G32 Z-16.6 F1.\nX12. Z-16.8\nG00 X18.\nZ0.2\nX11.4\nG32 Z-16.6 F1.\nM30\n%\n")
    restart = plan(thread, 14, lathe)
    assert restart.preamble[-4:] == ["G00 Z15.", "G00 Z0.2", "G00 X11.4", "F1."]
    assert "a rapid along Z at the largest diameter this tool went to" in restart.notes[-1]
    back = plan(thread, 13, lathe)  # at the retract's end itself: along Z on the lane
    assert back.preamble[-4:] == ["G00 X18.", "G00 Z15.", "G00 Z0.2", "F1."]
    assert back.notes == ["approach: along Z at X18., the largest diameter this tool went to, "
                          "where it moved along Z from Z0.2 up to the highest Z"]
    # the lane is the way the tool moved along Z there: only the retract's Z-16.8 to Z0.2
    # when it came in diagonally, not up to the highest Z15.
    diagonal = thread.replace("G00 Z0.2\nX11.6\n", "G00 X11.6 Z0.2\n")
    assert "after a radial move (line 12)" in refusal(diagonal, 13, lathe)


def test_a_restart_block_with_its_own_f_is_not_refused_for_the_feed_in_force():
    """`G20` after cutting at F200. (mm/min), then `G01 Z-0.1 F5.`: the feed in force is
    200 in/min to the control, which the walk does not convert; the block sets its own, so
    the approach feeds at F5. and the stale F is not written. A block without its own F is
    still refused."""
    text = ("%\nO3008\nG21 G90 G17 G40 G49 G80 G54\nT1 M06\nS2000 M03\nG00 G43 Z50. H1\n"
            "G00 X10. Y10.\nG01 Z-1. F200.\nG00 Z50.\nG20\nG00 X1. Y1. Z0.5\nG01 Z-0.1 F5.\n"
            "G01 X2.\nM30\n%\n")
    restart = plan(text, 12)
    assert restart.preamble[-1] == "G01 Z0.5 F5."
    assert not any("F200" in block or "F7.874" in block for block in restart.preamble)
    assert restart.notes == ["approach: from the clearance height Z1.9686 over the start "
                             "point, then down to Z0.5 in feed"]
    assert "the feed in force was written in mm (line 8)" in refusal(
        text.replace("G01 Z-0.1 F5.", "G01 Z-0.1"), 12)


AT_DEPTH = ("%\nO1000\nG21 G90 G54 G00 X0 Y0\nG01 Z-1. F100.\nX10.\nN20 X20.\nM30\n%\n")


def test_no_rapid_to_the_cutting_depth_where_the_program_never_raised_z():
    """Review 13, 8: a program that never raises Z above its cut (`G01 Z-1.`, `X10.`, `N20
    X20.`) made the preamble's clearance Z-1.: a rapid down to the cutting depth wherever the
    tool was left, then a rapid traverse at depth. Refused, naming what is missing and showing
    what would have been sent; a safe Z from the profile, or a restart after a retract, is
    planned as before."""
    said = refusal(AT_DEPTH, 6)
    assert said.startswith("cannot restart here: no height above the start point is known to "
                           "be clear: the program did not raise Z above Z-1. before this block "
                           "and reached it in feed (G01 on line 4)"), said
    assert "(it would send: G00 Z-1. / G00 X10. Y0)" in said
    assert said.endswith("give a safe Z above the part (send --clearance, or the profile's "
                         "[restart] clearance) or restart at a block after a retract")
    # the operator's safe Z: over the start point from there, down in feed
    safe = replace(FANUC, restart=replace(FANUC.restart, clearance=Decimal("50")))
    assert plan(AT_DEPTH, 6, safe).preamble[-3:] == ["G00 Z50.", "G00 X10. Y0",
                                                     "G01 Z-1. F100."]
    # a retract before the cut: its height is the clearance
    retracted = AT_DEPTH.replace("G01 Z-1. F100.", "G00 Z5.\nG01 Z-1. F100.")
    assert plan(retracted, 7).preamble[-3:] == ["G00 Z5.", "G00 X10. Y0", "G01 Z-1. F100."]
    # a rapid over the part at the height the program reached (`G43 H1 Z50.` in G01, then
    # `G00 X0 Y0`): the program traverses there itself
    traverse = "%\nO1000\nG21 G90 G17\nT1 M06\nG43 H1 Z50. F1000.\nG00 X0 Y0\nM30\n%\n"
    assert plan(traverse, 6).preamble[-2:] == ["G00 G43 Z50. H1", "F1000."]
    # a rapid retract from the cut as the restart block is refused too: the approach would
    # still traverse at the cutting depth
    up = AT_DEPTH.replace("N20 X20.", "N20 G00 Z5.")
    assert "reached it in feed (G01 on line 4)" in refusal(up, 6)


def test_the_refusal_for_want_of_a_clear_height_says_how_the_program_reached_it():
    """Review 14, 6: the refusal said Z was "reached in feed (G01)" from the motion mode in
    force at the restart block, also where the program went down to Z-1. with a rapid. It
    names the motion of the block that last wrote Z, and its line, read by the core walk both
    from blocks and from text."""
    rapid = "%\nO1000\nG21 G90 G54\nG00 X-10. Y0 Z-1.\nG01 X10. F100.\nN20 X20.\nM30\n%\n"
    for text, said in ((rapid, "and reached it with a rapid (G00 on line 4), "),
                       (AT_DEPTH, "and reached it in feed (G01 on line 4), ")):
        reason = refusal(text, 6)
        assert ("the program did not raise Z above Z-1. before this block " + said) in reason
        with pytest.raises(RestartRefused) as caught:
            plan_restart_text([text], FANUC, 6, "p.nc")
        assert caught.value.message == reason
    assert "in feed" not in refusal(rapid, 6)
    # an arc that ends at the depth is a feed too; the block that last wrote Z is named even
    # where a later block moves only X and Y in another mode
    arc = rapid.replace("G00 X-10. Y0 Z-1.", "G00 X-20. Y0\nG02 X-10. Y0 Z-1. R5. F100.")
    assert "and reached it in feed (G02 on line 5), " in refusal(arc, 7)


def test_a_clearance_that_is_no_height_is_refused_never_a_traceback():
    """Review 14, 5: a clearance of NaN passed click's range (NaN compares false) and crashed
    in ``quantize``. The planner refuses a clearance that is not a finite Decimal (the API
    takes the profile's record as given; the profile file and the command line refuse it
    first), and one whose digits the Z word cannot hold in the program's units, converted and
    rounded up as it is sent."""
    for bad in (Decimal("NaN"), Decimal("sNaN"), Decimal("Infinity"), Decimal("-Infinity"),
                50.0, "50"):
        setting = replace(FANUC.restart, clearance=bad)  # type: ignore[arg-type]
        mine = replace(FANUC, restart=setting)
        assert refusal(AT_DEPTH, 6, mine) == (
            f"cannot restart here: the profile's [restart] clearance is {bad!r}, not a finite "
            "Decimal: no height to approach at")
    with pytest.raises(ProfileError, match="restart.clearance must be a number"):
        profile_from_text('base = "fanuc-mill"\n[restart]\nclearance = nan\n')
    # more digits than Z+053 holds: given so, or once rounded up to 0.001
    for high, shown in ((Decimal("1E+999"), "Z1E+999"), (Decimal("123456.7"), "Z123456.7"),
                        (Decimal("99999.9999"), "Z99999.9999")):
        mine = replace(FANUC, restart=replace(FANUC.restart, clearance=high))
        assert refusal(AT_DEPTH, 6, mine) == (
            f"cannot restart here: the clearance {shown} (metric) has more digits than the "
            "profile's Z+053 holds: it cannot be sent")
    # a clearance that fits the inch format of the profile, and not once converted to mm
    inch = with_start_units(FANUC, "inch")
    assert inch.word_format("Z", "inch").spec() == "Z+044"
    wide = replace(inch, restart=replace(inch.restart, clearance=Decimal("9999")))
    assert "the clearance Z253974.6 (metric) has more digits than the profile's Z+053" in \
        refusal(AT_DEPTH, 6, wide)
    # the largest that fits is planned, rounded up, on a profile that gives no Z travel (with
    # fanuc-mill's, 518 mm, it is refused: review 15, 6)
    free = replace(FANUC, limits=replace(FANUC.limits, axes={}))
    top = replace(free, restart=replace(FANUC.restart, clearance=Decimal("99999.9985")))
    assert plan(AT_DEPTH, 6, top).preamble[-3] == "G00 Z99999.999"
    travel = replace(top, limits=FANUC.limits)
    assert "more than the machine's Z travel (-508 to 10 mm)" in refusal(AT_DEPTH, 6, travel)


def test_a_mirror_cancel_with_an_axis_word_not_known_leaves_the_mirror_not_known():
    """Review 19, 1: `G100 X#1` (or `G100 X[0]`, FANUC `G50.1 X#1`) was read as a cancel naming
    no axis, so as ending every mirror, and a restart after it was planned on the unmirrored
    side. An axis word whose value the restart does not know leaves that axis's mirror not
    known: the restart is refused, naming the cancel, until a cancel names the axis plainly."""
    haas, fanuc = load_profile("haas-mill"), load_profile("fanuc-mill")
    text = ("%\nO1000\nN1 G20 G17 G90 G54\nN2 T1 M06\nN3 S1000 M03\nN4 G00 X1. Y1.\n"
            "N5 G43 H1 Z1.\nN6 G01 Z-0.1 F10.\nN7 G101 X0 Y0\nN8 G100 X#1\nN9 X3. Y2.\n"
            "N20 X4.\nN30 G00 Z1.\nM30\n%\n")  # N20 is line 12
    doubt = ("cannot restart here: the mirror image of X, which {} may or may not have ended "
             "(an axis word whose value the restart does not know), from line 10 is in force "
             "and the preamble cannot restore it")
    # review 22, 2: with #1 vacant the G100 names no axis and ends Y's mirror too: Y is not
    # mirrored for certain either
    assert refusal(text, 12, haas) == doubt.replace("of X", "of XY").format("G100 X#1")
    # a plain word beside it names Y: its mirror ends, X's is not known
    assert refusal(text.replace("G100 X#1", "G100 X#1 Y0"), 12, haas) == doubt.format(
        "G100 X#1")
    x_only = text.replace("G101 X0 Y0", "G101 X0")
    assert refusal(x_only, 12, haas) == doubt.format("G100 X#1")
    assert refusal(x_only.replace("X#1", "X[0]"), 12, haas) == doubt.format("G100 X[0]")
    # a plain cancel of another axis leaves X not known; one of X, or of all, ends it
    y_ended = x_only.replace("N9 X3. Y2.", "N9 G100 Y0\nN10 X3. Y2.")
    assert refusal(y_ended, 13, haas) == doubt.format("G100 X#1")
    for cancel in ("G100 X0", "G100"):
        ended = x_only.replace("N9 X3. Y2.", f"N9 {cancel}\nN10 X3. Y2.")
        assert plan(ended, 13, haas).preamble[-2:] == ["G00 X3. Y2.", "G01 Z-0.1 F10."]
    # an axis not mirrored stays so whatever the word's value
    y_word = x_only.replace("G101 X0", "G101 Y0").replace("G100 X#1", "G100 Y#1")
    assert refusal(y_word, 12, haas) == doubt.replace("of X", "of Y").format("G100 Y#1")
    assert plan(x_only.replace("G100 X#1", "G100 X0 Y#1"), 12, haas).preamble[-2:] == [
        "G00 X3. Y2.", "G01 Z-0.1 F10."]
    # FANUC G50.1 the same; G51.1 X#1 mirrors X (about a point set by a parameter)
    f = x_only.replace("G101 X0", "G51.1 X0").replace("G100 X#1", "G50.1 X#1")
    assert refusal(f, 12, fanuc) == doubt.format("G50.1 X#1")
    assert plan(f.replace("N9 X3.", "N9 G50.1 X0\nN10 X3."), 13, fanuc).preamble[-2:] == [
        "G00 X3. Y2.", "G01 Z-0.1 F10."]
    g51 = f.replace("N7 G51.1 X0", "N7 #1=0\nG51.1 X#1").replace("N8 G50.1 X#1\n", "")
    assert refusal(g51, 12, fanuc) == ("cannot restart here: G51.1 (programmable mirror image) "
                                       "from line 10 is in force and the preamble cannot "
                                       "restore it")


def test_the_check_reads_a_cancel_whose_only_axis_word_is_not_known_as_the_restart():
    """Review 19, 1: `G100 X#1` names X (its mirror not known). Review 22, 2: with #1 vacant
    the block is a bare G100 (Haas "Address Substitution": a vacant variable drops its
    address), which ends Y's mirror too, so Y is not mirrored for certain: the Y18. after it
    (under the Y mirror 33 from the Y15. before it, TG601; without it 3) is not judged, and
    the restart names X and Y, where both read Y as still mirrored. `G100 X0` keeps Y
    mirrored (TG601), a bare `G100` ends it."""
    from postproc.check import Checker
    haas = load_profile("haas-mill")  # Y -16..16 in
    body = ("%\nO1000\nN1 G20 G17 G90 G54\nN2 T1 M06\nN3 S1000 M03\nN4 G00 X1. Y15.\n"
            "N7 G101 X0 Y0\nN8 {}\nN9 X3. Y18.\nN20 X4.\nN30 G00 Z1.\nM30\n%\n")

    def spans(cancel: str) -> list[str]:
        found = Checker(haas).run_stream([body.format(cancel)], haas.dialect)
        return [f.message.split(",")[0] for f in found if f.rule == "TG601"]

    assert spans("G100 X0") == ["Y spans 33 (from -18 to 15)"]
    assert spans("G100") == []
    assert spans("G100 X#1") == []
    # beside a plain word the block names Y whatever #1 holds: Y's mirror ended, Y18. is 3
    assert spans("G100 X#1 Y0") == []
    assert spans("G100 X0 Y#1") == []
    assert refusal(body.format("G100 X0"), 10, haas) == (
        "cannot restart here: G101 (mirror image) from line 7 is in force and the preamble "
        "cannot restore it")
    assert refusal(body.format("G100 X#1"), 10, haas) == (
        "cannot restart here: the mirror image of XY, which G100 X#1 may or may not have ended "
        "(an axis word whose value the restart does not know), from line 8 is in force and "
        "the preamble cannot restore it")


def test_the_check_and_the_restart_both_call_a_mirror_not_known_after_a_cancel_word_not_known():
    """Issue 32 (review 19, 1): after `G100 X#1` X's mirror may or may not have ended. The
    restart refuses there; the check, which read the word as ending X's mirror, now leaves X's
    positions uncompared (TG140 at the cancel) until a cancel names X plainly or names none:
    X-29. under the mirror about X0 is X29.; X31. after the cancel spans 61 from X-30. if the
    mirror ended (past the travel's 60), and 60 (X-31. to X29.: fits) if it did not."""
    from postproc.check import Checker
    haas = load_profile("haas-mill")  # X -30..30 in
    body = ("%\nO1000\nN1 G20 G17 G90 G54\nN2 T1 M06\nN3 S1000 M03 G43 H1 Z1.\nN4 G00 X-30. Y1.\n"
            "N7 G101 X0\nN8 X-29.\nN9 {}\nN10 X31.\n{}N20 X31.\nN30 G00 Z1.\nM30\n%\n")

    def found(cancel: str, then: str = "") -> list[tuple[str, int]]:
        out = Checker(haas).run_stream([body.format(cancel, then)], haas.dialect)
        return [(f.rule, f.line) for f in out if f.rule in ("TG601", "TG140")]

    # a plain cancel: X31. spans 61 from X-30., past the travel, at once (line 10)
    assert found("G100 X0") == [("TG601", 10)]
    # the word not known: not judged, said; the restart refuses at the same place
    assert found("G100 X#1") == [("TG140", 9)]
    assert "the mirror image of X, which G100 X#1 may or may not have ended" in refusal(
        body.format("G100 X#1", ""), 11, haas)
    # a known state again: the check judges, the restart plans
    for cancel in ("G100 X0", "G100"):
        assert found("G100 X#1", f"N11 {cancel}\n") == [("TG140", 9), ("TG601", 12)]
        assert plan(body.format("G100 X#1", f"N11 {cancel}\n"), 13, haas).preamble


@pytest.mark.parametrize(("name", "on", "off", "units", "scale"),
                         [("haas-mill", "G101", "G100", "G20", 1.0),
                          ("fanuc-mill", "G51.1", "G50.1", "G21", 25.4)])
def test_the_check_and_the_restart_both_call_every_mirror_not_known_after_a_lone_word_not_known(
        name: str, on: str, off: str, units: str, scale: float) -> None:
    """Review 22, 2: a cancel whose only axis word is not known (`G100 X#1`, `G50.1 X#1`) may be a
    bare cancel (a vacant #1 drops its address: Haas "Address Substitution"; Mitsubishi M700V
    user macro manual 13.5), which ends every mirror. Y was kept mirrored for certain: Y-14.
    under the Y mirror is Y14., and Y-18. after the cancel was taken as Y18. (3 from Y15.),
    where a bare cancel makes it 33 from there, past the travel. Now neither the check judges
    Y nor the restart plans until a cancel names it plainly (and X) or names none."""
    from postproc.check import Checker
    profile = load_profile(name)  # Haas Y -16..16 in, FANUC -406..406 mm
    y = [f"{v * scale:.1f}" for v in (15, -14, -18)]
    body = (f"%\nO1000\nN1 {units} G17 G90 G54\nN2 T1 M06\nN3 S1000 M03 G43 H1 Z1.\n"
            f"N4 G00 X1. Y{y[0]}\nN7 {on} X0 Y0\nN8 X3. Y{y[1]}\nN9 {{}}\n{{}}"
            f"N10 Y{y[2]}\nN20 X4.\nN30 G00 Z1.\nM30\n%\n")

    def found(cancel: str, then: str = "") -> list[tuple[str, int]]:
        out = Checker(profile).run_stream([body.format(cancel, then)], profile.dialect)
        return [(f.rule, f.line) for f in out if f.rule in ("TG601", "TG140")]

    assert found(off) == [("TG601", 10)]
    assert found(f"{off} X0") == []  # Y still mirrored: Y18., 3 from Y15.
    assert found(f"{off} X#1") == [("TG140", 9)]
    assert f"the mirror image of XY, which {off} X#1 may or may not have ended" in refusal(
        body.format(f"{off} X#1", ""), 11, profile)
    # Y named plainly: judged again (X not known still: the restart refuses, naming X alone:
    # review 23, the refusal named XY still)
    assert found(f"{off} X#1", f"N11 {off} Y0\n") == [("TG140", 9), ("TG601", 11)]
    said = refusal(body.format(f"{off} X#1", f"N11 {off} Y0\n"), 12, profile)
    assert f"the mirror image of X, which {off} X#1 may or may not have ended" in said, said
    # X named plainly: Y alone is in doubt
    said = refusal(body.format(f"{off} X#1", f"N11 {off} X0\n"), 12, profile)
    assert f"the mirror image of Y, which {off} X#1 may or may not have ended" in said, said
    # a known state again: the check judges, the restart plans
    for cancel in (f"{off} X0 Y0", off):
        then = f"N11 {cancel}\n"
        assert found(f"{off} X#1", then) == [("TG140", 9), ("TG601", 11)]
        assert plan(body.format(f"{off} X#1", then), 13, profile).preamble


@pytest.mark.parametrize("second", ["G51.1 X0", "(none)"])
def test_the_check_judges_an_axis_given_back_by_its_cancel_and_the_restart_waits_for_it(
        second: str) -> None:
    """Review 24, 1: after `G91 G51.1 X0 Y0` (not known exactly: its positions apart) and
    `G50.1 Y0`, a second `G51.1 X0` reset Y's span too, and Y-420. after it, plain as the Y400.
    before the mirror (820 apart on a travel of 812), was passed. Now the check flags it with
    the second mirror as without it; the restart refuses under the mirror of X and after its
    cancel until X and Y are given again, and plans there."""
    from postproc.check import Checker
    body = ("%\nO1000\nN1 G21 G17 G90 G54\nN2 T1 M06\nN3 S1000 M03 G43 H1 Z1.\nN4 G00 X0 Y400.\n"
            "N5 G91 G51.1 X0 Y0\nN6 G90 G00 X10. Y-300.\nN7 G50.1 Y0\nN8 {}\nN9 G00 Y-{}\n"
            "N10 G50.1\nN11 G00 X0 Y0\nN12 G00 Z1.\nM30\n%\n")
    for y, expected in [("420.", [11]), ("390.", [])]:
        found = Checker(FANUC).run_stream([body.format(second, y)], FANUC.dialect)
        assert [f.line for f in found if f.rule == "TG601"] == expected, (second, y)
    text = body.format(second, "420.")
    mirror_from = 10 if second.startswith("G51.1") else 7
    assert f"G51.1 (programmable mirror image) from line {mirror_from} is in force" in refusal(
        text, 11)
    # the line named is the cancel that ended X's mirror (line 12), not `G50.1 Y0` (line 9),
    # which left it in force (fix23's doubt: the refusal named line 9)
    said = refusal(text, 13)
    assert "the position of X is not known here (line 12: G50.1 ends the mirror image" in said
    assert plan(text, 14).preamble
    # an axis whose mirror ends at the partial cancel is named with that line
    y_off = body.replace("N7 G50.1 Y0", "N7 G50.1 X0").replace("N11 G00 X0 Y0", "N11 G00 Y0")
    said = refusal(y_off.format(second, "420."), 13)
    assert "the position of X is not known here (line 9: G50.1 ends the mirror image" in said


TILT = ("%\nO1000\nN1 G21 G17 G90 G54\nN2 T1 M06\nN3 S1000 M03 G00 G43 H1 Z1.\n"
        "N4 G01 X0 Y0 F100.\nN5 {on}\nN7 G00 X10. Y20. Z5.\nN9 G69\nN10 G00 X5.\nN11 G00 Z2.\n"
        "N12 G01 X50.\nM30\n%\n")  # N5 is line 7, N9 line 9, N10 line 10, N11 line 11


@pytest.mark.parametrize("on", ["G68.2 X0 Y0 Z0 I0 J30. K0", "G68.3 X0 Y0 Z0 R30.",
                                "G68.4 X0 Y0 Z0 I0 J30. K0"])
def test_a_fanuc_tilted_working_plane_in_force_refuses_and_its_moves_are_lost_at_g69(on):
    """Review 28, finding 1: FANUC's tilted working plane (G68.2, G68.3, G68.4, all ended by
    G69, fanuc-mill.toml) in force is a frame the preamble cannot restore: refused, naming it
    (G68.3/G68.4 were planned without it). The axes moved under it stand at the tilted point
    after G69, as a G68 rotation's do: unknown until given again (they were planned as known).
    A move of one axis in a tilted plane moves all three."""
    code = on.split()[0]
    in_force = TILT.format(on=on).replace("N9 G69\n", "")
    assert refusal(in_force, 10) == (
        f"cannot restart here: {code} (tilted working plane) from line 7 is in force and the "
        "preamble cannot restore it")
    text = TILT.format(on=on)
    assert refusal(text, 11) == (
        "cannot restart here: the position of Y is not known here (line 9: G69 ends the tilted "
        "working plane: the tool stands where the transformed moves left it, not at the number "
        "the program wrote)")
    # X alone moved under it: Y and Z, which it moved too, are lost as well
    one = text.replace("N7 G00 X10. Y20. Z5.", "N7 G00 X10.")
    assert "the position of Y is not known here (line 9: G69 ends the tilted" in refusal(one, 11)
    # once every axis is given absolutely after G69, the restart is planned from there
    given = text.replace("N10 G00 X5.", "N10 G00 X5. Y6. Z7.")
    assert plan(given, 11).preamble[-3:] == ["G00 G43 Z7. H1", "G00 X5. Y6.", "F100."]
    # set and cancelled with no move under it: the position is as it was
    idle = text.replace("N7 G00 X10. Y20. Z5.\n", "")
    assert plan(idle, 10).preamble[-3:] == ["G00 G43 Z1. H1", "G00 X5. Y0", "F100."]


def test_a_mirror_cancel_under_a_tilted_plane_loses_every_axis_moved():
    """Review 28, finding 1 (third case): under G68.2 and G51.1 X0, a move of Y and Z is under
    the tilted plane too: lost at the mirror's cancel (fix26's per-axis narrowing kept only X,
    so the restart was planned at Y20.)."""
    text = TILT.format(on="G68.2 X0 Y0 Z0 I0 J30. K0\nN6 G51.1 X0").replace(
        "N9 G69", "N8 G50.1 X0\nN9 G69")  # N8 is line 10, N11 line 13
    assert refusal(text, 13) == (
        "cannot restart here: the position of Y is not known here (line 10: G50.1 ends the "
        "mirror image: the tool stands where the transformed moves left it, not at the number "
        "the program wrote)")


def test_a_send_restart_under_a_tilted_plane_is_refused_by_the_cli(tmp_path):
    """The same through `send --restart-at`: refused, nothing sent, the cause named."""
    path = tmp_path / "tilt.nc"
    path.write_text(TILT.format(on="G68.4 X0 Y0 Z0 I0 J30. K0").replace("N9 G69\n", ""))
    from click.testing import CliRunner

    from tapegate.cli import main
    result = CliRunner().invoke(main, ["send", "-p", "fanuc-mill", "--port", "loop://",
                                       "--restart-at", "N11", "-y", "--xon-timeout", "1",
                                       str(path)])
    assert result.exit_code == 1
    assert "G68.4 (tilted working plane) from line 7 is in force" in result.output


TCP = ("%\nO1000\nN1 G21 G17 G90 G54\nN2 T1 M06\nN3 G00 B0 C0\n"
       "N4 S1000 M03 G00 {on} H1 Z100.\nN5 G00 X0 Y0\nN6 G00 B30. C10.\n"
       "N7 G01 X10. Y5. Z20. F100.\n{off}N8 G01 X50.\nM30\n%\n")  # N4 is line 6


@pytest.mark.parametrize("on", ["G43.4", "G43.5"])
def test_a_fanuc_tool_centre_point_control_in_force_refuses(on):
    """Review 29, finding 1: FANUC's tool centre point control (G43.4 type 1, G43.5 type 2)
    is a length offset the preamble cannot restore with G43 H: refused where in force, naming
    it (the plan was G49 ... G00 Z100. with no offset: the tool tip a tool length below the
    programmed Z). Ended by G49 (or G43), the restart is planned again."""
    assert refusal(TCP.format(on=on, off=""), 10) == (
        f"cannot restart here: {on} from line 6 is in force and the preamble cannot restore it")
    cancelled = TCP.format(on=on, off="N9 G49\n")  # N8 is line 11
    assert plan(cancelled, 11).preamble
    # one length offset code replaces another: G43.5 after G43.4 is the one named
    both = TCP.format(on="G43.4", off="").replace("N7 ", "N7 G43.5 ")
    assert "G43.5 from line 9 is in force" in refusal(both, 10)


def test_g53_1_loses_the_rotary_axes():
    """Review 29, finding 2: G53.1 (tool axis direction control) turns the rotary axes to the
    tilted working plane by the control's own sums, and they stay there after G69: unknown
    until given again (the preamble sent B and C back to their places before the tilt)."""
    text = ("%\nO1000\nN1 G21 G17 G90 G54\nN2 T1 M06\nN3 G00 B0 C0\n"
            "N4 S1000 M03 G00 G43 H1 Z100.\nN5 G00 X0 Y0\nN6 G68.2 X0 Y0 Z0 I0 J30. K0\n"
            "N7 G53.1\nN10 G69\nN12 G00 X5. Y5.\nN13 G01 Z2. F100.\nN14 G01 X50.\nM30\n%\n")
    said = refusal(text, 13)
    assert said.startswith("cannot restart here: the position of B is not known here (line 9: "
                           "G53.1 (the tool axis direction control"), said
    # the rotary axes the program moved (B, C) are the ones lost: given again, planned (an A
    # never written is not asked for: review 30, finding 2)
    given = text.replace("N12 G00 X5. Y5.", "N12 G00 X5. Y5. B0 C0")
    assert plan(given, 14).preamble
    # a program that moved no rotary axis loses all three: which the machine has is unknown
    none = text.replace("N3 G00 B0 C0\n", "")
    assert "the position of A is not known here" in refusal(none, 12)


def test_a_fanuc_3d_coordinate_conversion_loses_all_three_axes_at_g69():
    """FANUC's G68 with I J K is the 3-D coordinate conversion (a rotation about the vector I
    J K): a move of one of X, Y, Z under it moves all three, so all three are lost at G69, as a
    tilted plane's are (review 28's doubt: it was restarted as a plane rotation, its two
    axes lost and Z kept). A G68 without I J K rotates its plane's two axes alone."""
    space = TILT.format(on="G68 X0 Y0 Z0 I1 J0 K0 R30.").replace(
        "N7 G00 X10. Y20. Z5.", "N7 G00 X10.")
    assert refusal(space.replace("N9 G69\n", ""), 10) == (
        "cannot restart here: G68 (3-D coordinate conversion) from line 7 is in force and the "
        "preamble cannot restore it")
    said = refusal(space.replace("N10 G00 X5.", "N10 G00 X5. Y6."), 11)
    assert "the position of Z is not known here (line 9: G69 ends the coordinate rotation" in said
    plane = TILT.format(on="G68 X0 Y0 R30.").replace("N7 G00 X10. Y20. Z5.", "N7 G00 X10.")
    assert plan(plane.replace("N10 G00 X5.", "N10 G00 X5. Y6."), 11).preamble
    # a plane's G68 given under the 3-D conversion leaves it in force to G69: whether the
    # control nests the two or replaces one is not in the sources, so Z stays lost (review 31)
    nested = space.replace("N7 G00 X10.", "N6 G68 X0 Y0 R10.\nN7 G00 X10.")
    said = refusal(nested.replace("N10 G00 X5.", "N10 G00 X5. Y6."), 12)
    assert "the position of Z is not known here" in said, said


@pytest.mark.parametrize("move", ["G91 G28 B0\nN3 G90", "G91 G30 B0\nN3 G90", "G53 G00 B0"])
def test_g53_1_loses_a_rotary_axis_moved_only_by_a_reference_or_machine_move(move):
    """Review 31, finding 1: a rotary axis the program moved only by G28, G30 or G53 (lost
    with a replay, not given plainly) is turned by G53.1 as well: lost, not sent back by the
    preamble to its place before the tilt."""
    text = ("%\nO1000\nN1 G21 G17 G90 G54\nN2 T1 M06\nN3 G00 C0\nN3 " + move + "\n"
            "N4 S1000 M03 G00 G43 H1 Z100.\nN5 G00 X0 Y0\nN6 G68.2 X0 Y0 Z0 I0 J30. K0\n"
            "N7 G53.1\nN10 G69\nN12 G00 X5. Y5. C0\nN13 G01 Z2. F100.\nN14 G01 X50.\nM30\n%\n")
    line = text.splitlines().index("N13 G01 Z2. F100.") + 1
    said = refusal(text, line)
    assert said.startswith("cannot restart here: the position of B is not known here"), said
    assert "G53.1 (the tool axis direction control" in said
    # given again, planned
    assert plan(text.replace("X5. Y5. C0", "X5. Y5. B0 C0"), line).preamble


@pytest.mark.parametrize(("profile", "code", "held"), [("fanuc-mill", "G43.9", "G04.1"),
                                                       ("fanuc-mill", "G53.6", "G04.1"),
                                                       ("haas-mill", "G68.2", "G90")])
def test_a_decimal_g_code_the_profiles_list_lacks_refuses_as_a_whole_one_does(profile, code,
                                                                              held):
    """Review 31, finding 2: a decimal G code the profile's list does not hold (the check's
    TG307: the control alarms, or its parameters make it a macro call) leaves what ran after it
    unknown, as an unlisted whole code does; it was planned past as if it had run (Haas's
    G68.2, whose tilted plane is G268; FANUC's G43.9). A code the list holds (FANUC's G04.1,
    where the Haas list has no decimal code) is planned as before."""
    machine = load_profile(profile)
    text = ("%\nO1000\nN1 G21 G17 G90 G54\nN2 T1 M06\nN4 S1000 M03 G00 G43 H1 Z100.\n"
            f"N5 G00 X0 Y0\nN6 {code}\nN7 G00 X5. Y5.\nN8 G01 Z2. F100.\nN9 G01 X50.\nM30\n%\n")
    said = refusal(text, 10, machine)
    assert said.startswith(f"cannot restart here: after 'N6 {code}' on line 7 (a G code the "
                           "control's list does not hold"), said
    assert plan(text.replace(code, held), 10, machine).preamble


@pytest.mark.parametrize("code", ["G#1", "G[68.2] X0 Y0 Z0 I0 J30. K0", "G[68] X0 Y0 R30.",
                                  "M#500"])
def test_a_code_set_by_a_parameter_stops_the_restart(code):
    """Review 32, finding 1: a G or M code set by a parameter (`#1=68` then `G#1 X0 Y0 R30.`)
    runs a code the walk cannot name, so what ran after it is not known; it was skipped, and
    the rotation or tilted plane it set left out of the plan."""
    text = ("%\nO1000\nN1 G21 G17 G90 G54\nN2 T1 M06\n#1=68\nN4 S1000 M03 G00 G43 H1 Z100.\n"
            f"N5 {code}\nN7 G00 X5. Y5.\nN8 G01 Z2. F100.\nN9 G01 X50.\nM30\n%\n")
    said = refusal(text, 10)
    assert said.startswith(f"cannot restart here: after 'N5 {code}' on line 7 (a G or M code "
                           "set by a parameter: which code ran is not known)"), said


POLAR = ("%\nO1000\nN1 G21 G17 G90 G94 G40 G49 G80 G54\nN2 T1 M06\nN3 G97 S1000 M03\n"
         "N4 G00 G43 Z100. H1\nN5 G00 X50. Y0 C0\nN6 G01 Z-2. F100.\nN7 {on}\n"
         "N8 G01 X20. C10.\nN9 G01 X10. C5.\n{off}N11 G00 Z100.\nN12 G00 X50.\nM30\n%\n")


@pytest.mark.parametrize(("profile", "on", "off"), [
    ("fanuc-mill", "G12.1", "G13.1"), ("fanuc-lathe", "G12.1", "G13.1"),
    ("fanuc-mill", "G07.1 C25.", "G07.1 C0")])
def test_polar_and_cylindrical_interpolation_refuse_in_force_and_lose_their_axes(profile, on,
                                                                                 off):
    """Review 32, finding 2: FANUC's polar coordinate interpolation (G12.1, cancel G13.1) and
    cylindrical interpolation (G07.1 with the radius, cancel G07.1 C0) turn the program's
    plane into the axes' own: refused where in force (the plan rapid to `X10. C5.` as a
    straight move), and after the cancel X and C are not known until given again."""
    machine = load_profile(profile)
    code = on.split()[0]
    template = POLAR
    after = 14
    spin = ""
    if "lathe" in profile:
        template = POLAR.replace("G17 G90 G94 G40 G49 G80 G54", "G40 G80").replace(
            "T1 M06", "T0101").replace("G00 G43 Z100. H1", "G00 Z100.").replace(" Y0 ", " ")
        # (review 35, finding 2: after C moved, a FANUC lathe's restart waits for the main
        # spindle's M03, the live tool's modes being the builder's M codes)
        after, spin = 15, "N10 M03\n"
    assert refusal(template.format(on=on, off=""), 11, machine) == (
        f"cannot restart here: {code} ({'cylindrical' if '7.1' in on else 'polar coordinate'} "
        "interpolation) from line 9 is in force and the preamble cannot restore it")
    cancelled = template.format(on=on, off=f"N10 {off}\n{spin}")
    said = refusal(cancelled, after, machine)
    assert "is not known here (line 12: " in said and "interpolation" in said, said
    # (a lathe's C, the main spindle turning again, is not positioned: X alone)
    given = cancelled.replace("N11 G00 Z100.", "N11 G00 Z100. X50." + ("" if spin else " C0"))
    assert plan(given, after, machine).preamble
    if spin:
        said = refusal(template.format(on=on, off=f"N10 {off}\n"), 14, machine)
        assert said.startswith("cannot restart here: the program moved C on line 11"), said


def test_linuxcnc_work_systems_7_to_9_and_fanuc_g54_2_refuse_in_force():
    """Review 32, finding 3: LinuxCNC's G59.1-G59.3 (work systems 7-9) were planned with the
    preamble's G54, and FANUC's G54.2 P1 (rotary table dynamic fixture offset) was dropped.
    Both are refused where in force; G54.2 P0 and a G54-G59 end them, losing the axes seen."""
    lcnc = load_profile("linuxcnc")
    text = ("%\nG21 G17 G90 G54\nT1 M06\nS1000 M03 G00 G43 H1 Z100.\nG00 X0 Y0\nG59.1\n"
            "G00 X5. Y5.\nG01 Z2. F100.\nG01 X50.\nM30\n%\n")
    assert refusal(text, 9, lcnc) == ("cannot restart here: G59.1 (work coordinate system 7) "
                                      "from line 6 is in force and the preamble cannot restore "
                                      "it")
    back = text.replace("G01 Z2. F100.", "G54\nG00 X5. Y5. Z100.\nG01 Z2. F100.")
    assert plan(back, 11, lcnc).preamble
    fanuc = ("%\nO1000\nN1 G21 G17 G90 G54\nN2 T1 M06\nN3 S1000 M03 G00 G43 H1 Z100.\n"
             "N4 G00 X0 Y0\nN5 G54.2 P1\nN6 G00 X5. Y5.\nN7 G01 Z2. F100.\nN8 G01 X50.\nM30\n%\n")
    assert refusal(fanuc, 10) == ("cannot restart here: G54.2 (rotary table dynamic fixture "
                                  "offset) from line 7 is in force and the preamble cannot "
                                  "restore it")
    ended = fanuc.replace("N6 G00 X5. Y5.", "N5 G54.2 P0\nN6 G00 X5. Y5. Z100.")
    assert plan(ended, 11).preamble


def test_a_haas_lathe_g112_is_its_xc_interpolation_not_a_work_offset():
    """Review 32, doubtful: a Haas lathe's G112 (XY to XC interpolation, cancel G113; its list
    has no G110-G129 work offsets) was refused as "an extended work offset", and still after
    G113. It is refused where in force, by its name, and planned after G113 once X and C are
    given again."""
    haas = load_profile("haas-lathe")
    text = ("%\nO1000\nN1 G21 G40 G80\nN2 T101\nN3 G97 S1000 M03\nN4 G00 Z100.\n"
            "N5 G00 X50. C0\nN6 G01 Z-2. F100.\nN7 G112\nN8 G01 X20. C10.\nN9 G01 X10. C5.\n"
            "{off}N11 G00 Z100. X50. C0\nN12 G00 X60.\nM30\n%\n")
    assert refusal(text.format(off=""), 12, haas) == (
        "cannot restart here: G112 (polar coordinate interpolation) from line 9 is in force "
        "and the preamble cannot restore it")
    assert plan(text.format(off="N10 G113\n"), 14, haas).preamble


@pytest.mark.parametrize(("profile", "on", "off"), [
    ("fanuc-mill", "G112", "G113"), ("fanuc-mill", "G107 C25.", "G107 C0"),
    ("haas-mill", "G107 C25.", "G107"), ("haas-mill", "G107 Y0 A0 Q2.", "G107"),
    ("haas-mill", "G107 Y0 A0", "G107")])
def test_polar_and_cylindrical_g_code_system_b_codes_refuse_on_a_mill_too(profile, on, off):
    """Review 33, finding 1: a FANUC mill's G112/G113 (polar coordinate interpolation in G code
    system B/C) and G107 (cylindrical), and a Haas mill's G107, were planned past as if the
    moves under them were straight ones; only lathes were read. A Haas mill's G112/G113 are
    its work systems 9 and 10 (refused as an extended work offset, as before)."""
    # (a Haas's G107 is on when it names an axis, Q or R, whatever the values, off only
    # with no address: 96-8000, "G107 Cylindrical Mapping"; review 34, finding 1)
    machine = load_profile(profile)
    code = on.split()[0]
    kind = "cylindrical" if code == "G107" else "polar coordinate"
    mill = POLAR.replace("N3 G97 S1000", "N3 S1000")  # (G97 is a lathe's code)
    assert refusal(mill.format(on=on, off=""), 11, machine) == (
        f"cannot restart here: {code} ({kind} interpolation) from line 9 is in force and the "
        "preamble cannot restore it")
    said = refusal(mill.format(on=on, off=f"N10 {off}\n"), 14, machine)
    if " Y0" in on:
        # a Haas G107 naming Y maps Y alone (review 36, finding 8): X and C moved under it as
        # written, Y lost at its own block's word
        assert "the position of Y is not known here (line 9: Y0 in a G107 block)" in said, said
    else:
        assert "is not known here (line 12: " in said and "interpolation" in said, said
    haas = refusal(mill.format(on="G112", off=""), 11, load_profile("haas-mill"))
    assert "G112 (an extended work offset)" in haas, haas


CYLINDER = ("%\nO1000\nN1 G21 G18 G40 G99\nN2 T0101\nN3 G97 S600 M03\nN4 G00 X60. Z5. C0\n"
            "N5 {on}\nN6 G01 Z-10. C30. F0.1\nN7 {off}\nN8 G01 X50.\nN9 G01 Z-12.\nM30\n%\n")


def test_a_fanuc_lathe_g07_1_gives_its_radius_by_h_and_loses_the_axes_beside_it():
    """Review 33, findings 3 and 4: a FANUC lathe's `G07.1 H57299` (the radius by C's
    incremental address in G code system A, as the lathe manual writes it) was read as the
    cancel, and the moves under it planned as straight ones; `G07.1 C0 G00 X60.` left X at the
    block before's, where the control may move it in the cancel's block."""
    lathe = load_profile("fanuc-lathe")
    assert refusal(CYLINDER.format(on="G07.1 H57299", off="G07.1 H0"), 8, lathe) == (
        "cannot restart here: G07.1 (cylindrical interpolation) from line 7 is in force and "
        "the preamble cannot restore it")
    # (the main spindle started again after the cancel: review 35, finding 2 refuses a
    # restart after C moved until then)
    said = refusal(CYLINDER.format(on="G07.1 H57299", off="G07.1 H0\nN75 M03"), 11, lathe)
    assert "the position of Z is not known here (line 9: G07.1 ends the cylindrical" in said
    beside = CYLINDER.format(on="G07.1 C0 G00 X70.", off="G00 Z5.\nN75 M03")
    assert refusal(beside, 11, lathe) == ("cannot restart here: the position of X is not known "
                                          "here (line 7: X70. in a G07.1 block)")
    # given again, the restart is planned
    assert plan(beside, 12, lathe).preamble


MACRO_M = ("%\nO1000\nN1 G21 G17 G90 G40 G80 G54\nN2 T1 M06\nN3 S1000 M03\n"
           "N4 G00 G43 H1 X10. Y0 Z5.\nN5 {block}\nN6 G01 Z-1. F100.\nN7 G01 X20.\nM30\n%\n")


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill"])
def test_the_words_beside_an_unlisted_m_code_with_arguments_are_not_known(profile):
    """Review 33, finding 5: an M code the profile's list lacks may be a macro call (FANUC
    parameters 6080-6089, a Haas's M code aliases), its other words arguments: `M165 P9811 Z0
    S2` was planned as `S2 M03` at Z0. Where the block carries a word only an argument is (a P
    or Q, a point in S or T) its S and axes are not known; a builder's M code beside a plain
    speed or tool (`S300 M45`, `T0101 M16`) is the control's own function and planned."""
    machine = load_profile(profile)
    said = refusal(MACRO_M.format(block="M165 P9811 Z0 S2"), 9, machine)
    assert said.startswith("cannot restart here: the spindle speed in force is not known: S2 "
                           "on line 7, beside M165, an M code the profile's list lacks"), said
    assert "FANUC parameters 6080-6089" in said
    point = refusal(MACRO_M.format(block="M165 S2.5 X30."), 9, machine)
    assert "S2.5 on line 7, beside M165" in point, point
    # an I, J, K, R or E where no arc or cycle is in force: an argument too (review 34, 4)
    argument = refusal(MACRO_M.format(block="M165 I1. Z-3. S2"), 9, machine)
    assert "S2 on line 7, beside M165" in argument, argument
    plain = plan(MACRO_M.format(block="S300 M45"), 9, machine)
    assert "S300 M03" in " ".join(plain.preamble), plain.preamble


def test_a_lathe_restart_the_program_way_in_sets_its_c_axis_first():
    """Review 33, finding 2: a lathe's approach the program's own way in (a cross slot's,
    the main spindle stopped) set X and Z but left C where the operator had it; the other
    axes go to their place at the clearance, before the way in. Review 34, finding 2: with
    the main spindle turning (M03) C is the spindle, in no position: it is not sent."""
    lathe = load_profile("haas-lathe")
    text = GROOVE.replace("N50 M08\n", "N50 M08\nN55 G00 C30.\n")
    stopped = plan(text.replace("N30 G97 S600 M03", "N30 M05"), 11, lathe)
    assert stopped.preamble[-3:] == ["G00 C30.", "G00 X52. Z-20.", "G01 X40. F0.05"]
    turning = plan(text, 11, lathe)
    assert turning.preamble[-2:] == ["G00 X52. Z-20.", "G01 X40. F0.05"]
    assert not any("C30." in block for block in turning.preamble)
    # (review 35, finding 2) a FANUC lathe, whose live tool and C axis modes are the
    # builder's M codes: refused after C moved, until the main spindle starts again
    fanuc = load_profile("fanuc-lathe")
    for program in (text, text.replace("N30 G97 S600 M03", "N30 M05")):
        assert refusal(program, 11, fanuc).startswith(
            "cannot restart here: the program moved C on line 8 and has not started the main "
            "spindle (M03, M04) since")


def test_a_haas_lathe_live_tool_or_c_axis_in_force_refuses_the_restart():
    """Review 34, finding 2: a Haas lathe's M154 (C axis engage) and M133 P2000 (live tool
    drive forward), as Autodesk's HAAS Lathe post writes them, were planned past: the
    preamble had neither, and a radial drill fed in with the live tool stopped. Refused
    while one is on; planned again after M135 and M155."""
    haas = load_profile("haas-lathe")
    text = ("%\nO1000\nG20 G18 G40 G80 G99\nT0202\nM154\nG00 C0\nG98 M133 P2000\n"
            "G00 X2.4 Z-0.4\nG01 X1.2 F5.\nG00 X2.4\nG00 C90.\nG01 X1.2 F5.\n{off}"
            "G00 X2.4 Z1.\nG99 G97 S600 M03\nG00 X2.2 Z0.1\nG01 Z-0.5 F0.01\nM30\n%\n")
    said = refusal(text.format(off=""), 14, haas)
    assert said.startswith("cannot restart here: M1"), said
    assert "from line" in said and "is in force" in said
    assert refusal(text.format(off="M135\n"), 15, haas).startswith(
        "cannot restart here: M154 (C axis engage) from line 5 is in force")
    ended = text.format(off="M135\nM155\n")
    assert plan(ended, 18, haas).preamble


def test_an_okuma_lathe_m_tool_spindle_in_force_refuses_the_restart():
    """The Okuma lathe's M-tool spindle (List of M Codes: M12 stop, M13 forward, M14
    reverse) takes the live tool's meaning keys, as haas-lathe's M133-M135: while it turns the
    preamble cannot restore it, so a restart is refused until its M12; the lathe's C axis
    codes stay the builder's, so the refusals after a C move stay too."""
    okuma = load_profile("okuma-lathe")
    text = ("$T.MIN%\nO1\nG50 S2000\nG00 X100 Z100\nG97 S800 M03\nM13 SB=1000\nG00 X50 Z5\n"
            "G01 Z-10 F0.1\nG00 X100\n{off}G00 Z100\nM02\n")
    assert refusal(text.format(off=""), 10, okuma) == (
        "cannot restart here: M13 (M-tool spindle forward) from line 6 is in force and the "
        "preamble cannot restore it; restart at or before line 6, or after the M12 and M109 that "
        "end the modes")
    assert plan(text.format(off="M12\n"), 11, okuma).preamble


OKUMA_C = ("$T.MIN%\nO1\nG50 S2000\nG00 X100 Z100\nG97 S800 M03\nG00 X50 Z5\nG01 Z-10 F0.1\n"
           "G00 X100 Z100\nM05\nM110\nG00 C0\nM13 SB=1000\nG00 X52 Z-5\nG01 X40 F0.05\nG00 X52\n"
           "G00 C90.\nG01 X40\nG00 X100\nM12\nM109\nG00 Z100\nG97 S800 M03\nG00 X50 Z5\n"
           "G01 Z-20 F0.1\nM02\n")


def test_an_okuma_lathe_c_axis_mode_in_force_refuses_the_restart_and_its_hint_is_accepted():
    """Review 56a F4: the Okuma lathe's C-axis mode (List of M Codes: M110 on, M109 off) takes
    the C axis's meaning keys, as haas-lathe's M154/M155: a restart right after M110 (`G00 C0`)
    is refused, where it was planned with the C-axis mode off; the hint's first block (the
    M110's own, line 10) is accepted, and the program's own spindle start after M109 too."""
    okuma = load_profile("okuma-lathe")
    assert okuma.code("M", 110).meaning == "c-axis-engage"
    assert okuma.code("M", 109).meaning == "c-axis-disengage"
    for line in range(11, 21):
        said = refusal(OKUMA_C, line, okuma)
        assert said == (
            "cannot restart here: M110 (C-axis mode on) from line 10 is in force and the preamble "
            "cannot restore it; restart at or before line 10, or after the M12 and M109 that end "
            "the modes"), (line, said)
    assert plan(OKUMA_C, 10, okuma).preamble
    assert plan(OKUMA_C, 22, okuma).preamble


SIN_AXIS = ("N10 G54 G17 G90 G71\nN20 T1 D1\nN30 M6\nN40 G0 X0 Y0 Z50 S1000 M3\nN50 G1 Z-5 F100\n"
            "N60 G0 Z50\nN70 M70\nN80 G0 C90\nN90 G0 X10\nN100 M3 S1000\nN110 G1 X20 Z-5 F100\n"
            "N120 G0 Z50\nN130 M30\n")


def test_a_sinumerik_spindle_in_axis_mode_refuses_the_restart():
    """Review 56a F6: M70 switches a SINUMERIK's spindle to axis mode (840D sl Function Manual
    S1; the profile's `spindle-to-axis-mode`) until M3, M4 or M5: a restart there would start it
    turning (`M03`) and run the program's C positioning against it, so it is refused as after an
    orientation (M19), with a hint to a block that is accepted."""
    sin = load_profile("sinumerik-840d")
    for line in (8, 9, 10):
        assert refusal(SIN_AXIS, line, sin) == (
            "cannot restart here: M70 on line 7 switched the spindle to axis mode (position "
            "control, moved as a rotary axis) and no M03, M04 or M05 has come since: the preamble "
            "would start it turning, and the program's moves of that axis meet a turning spindle "
            "or alarm; restart at or before line 7, or after the M03 or M04 that starts the "
            "spindle again"), line
    assert plan(SIN_AXIS, 7, sin).preamble
    assert plan(SIN_AXIS, 11, sin).preamble


M13_MILL = ("%\nO1\nG21 G17 G40 G49 G80 G90\nN50 T1 M06\nN60 G43 H1 Z50.\nN70 S1000 M13\n"
            "N80 G00 X10. Y10.\nN90 G01 Z-5. F100.\nN100 G00 Z50.\nN110 M05\nN120 G00 X0 Y0\n"
            "N130 M30\n%\n")


def test_a_builders_spindle_start_is_restored_by_its_key_or_refused():
    """Review 56a F9: a builder's M13 (spindle and coolant on) after the tool change: on a
    profile that keys it (`spindle-cw-coolant-on`) the preamble restores the spindle by that
    code, as the program started it; on one whose list lacks it (fanuc-mill: TG307) the restart
    is refused, where it was planned with the spindle stopped and plunged. After the M05 that
    stops it, nothing is restored; before the M13 the restart is planned as before."""
    keyed = profile_from_text(
        'base = "fanuc-mill"\n[codes]\n'
        'M13 = { function = "spindle CW and coolant on", duration = "spindle", '
        'meaning = "spindle-cw-coolant-on" }\n'
        'M14 = { function = "spindle CCW and coolant on", duration = "spindle", '
        'meaning = "spindle-ccw-coolant-on" }\n', "m13")
    for line in (7, 8, 9):
        restored = plan(M13_MILL, line, keyed).preamble
        assert "G97 S1000 M13" in restored, (line, restored)
        assert not any("M03" in b for b in restored), restored
        assert refusal(M13_MILL, line, FANUC) == (
            "cannot restart here: the spindle is stopped and M13 on line 6, an M code the "
            "profile's list lacks, came after: it may start the spindle (a builder's M13: spindle "
            "and coolant), which the preamble cannot know or restore; restart at or before line "
            "6, at the next tool change, or after the M03 or M04 that starts the spindle (or key "
            'the code in the profile: meaning = "spindle-cw-coolant-on", docs/profiles.md)'), line
    for profile in (keyed, FANUC):
        assert not any("M13" in b or "M03" in b for b in plan(M13_MILL, 6, profile).preamble)
    stopped = plan(M13_MILL, 11, FANUC).preamble
    assert not any("M13" in b or "M03" in b for b in stopped), stopped
    # (after the keyed code's M05, its coolant is still on: test_a_keyed_start_with_the_...)
    assert refusal(M13_MILL, 11, keyed).startswith("cannot restart here: M13 on line 6 turned")
    # a restart block that starts the spindle itself is not refused
    started = M13_MILL.replace("N90 G01", "N90 M03 G01")
    assert plan(started, 9, FANUC).preamble
    # a keyed start ends an orientation as M03 does (review 56d F2: refused after M19 ... M14)
    oriented = M13_MILL.replace("N110 M05", "N110 M19\nN115 G00 Z60.\nN116 S1200 M14")
    assert "G97 S1200 M14" in plan(oriented, 13, keyed).preamble
    assert refusal(oriented, 12, keyed).startswith("cannot restart here: M19 on line 10")


KEYED = profile_from_text(
    'base = "fanuc-mill"\n[codes]\n'
    'M13 = { function = "spindle CW and coolant on", duration = "spindle", '
    'meaning = "spindle-cw-coolant-on" }\n'
    'M14 = { function = "spindle CCW and coolant on", duration = "spindle", '
    'meaning = "spindle-ccw-coolant-on" }\n', "m13")

# a keyed start with the coolant (line 6), the program's own M09 (line 8), a cut (line 9-10)
COOLED = ("%\nO1\nG21 G17 G40 G49 G80 G90\nN50 T1 M06\nN60 G43 H1 Z50.\nN70 S1000 {start}\n"
          "N80 G00 X10. Y10.\nN90 M09\nN100 G01 Z-5. F100.\nN110 G01 X50.\nN120 G00 Z50.\n"
          "N130 M05\nN140 G00 X0 Y0\nN150 M30\n%\n")


@pytest.mark.parametrize("start", ["M13", "M14"])
def test_a_keyed_start_with_the_coolant_leaves_the_coolant_as_the_program_had_it(
        start: str) -> None:
    """Review 56d F1: a restart after `S1000 M13` and the program's own M09 wrote `G97 S1000
    M13` and no M09: the cut ran with the coolant that the program had turned off. The
    preamble runs the program's own codes in its order, the keyed start then M09, each in a
    block of its own (a FANUC hands both to the builder's ladder), before the approach; a
    coolant code in force after that M09 follows. Without the M09 the coolant stays on by the
    keyed code alone, and no M08 is added."""
    text = COOLED.format(start=start)
    for line in (9, 10, 11, 12):
        preamble = plan(text, line, KEYED).preamble
        at = preamble.index(f"G97 S1000 {start}")
        assert preamble[at + 1] == "M09", (line, preamble)
        assert not any("M08" in b or "M03" in b or "M04" in b for b in preamble), preamble
    # before the M09: the keyed code alone, its coolant on as the program has it
    for line in (7, 8):
        preamble = plan(text, line, KEYED).preamble
        assert f"G97 S1000 {start}" in preamble and "M09" not in preamble, (line, preamble)
    # the program's M08 after its M09: the keyed start, its M09, then the M08 in force
    again = text.replace("N100 G01", "N95 M08\nN100 G01")
    preamble = plan(again, 11, KEYED).preamble
    at = preamble.index(f"G97 S1000 {start}")
    assert preamble[at + 1:at + 3] == ["M09", "M08"], preamble
    # the preamble's modal state is the program's at the block (it is verified before sending)
    assert plan(again, 11, KEYED).state.coolant == "flood"


def test_a_keyed_starts_coolant_left_on_after_the_spindle_stopped_refuses_the_restart() -> None:
    """The coolant a keyed M13 turned on outlasts the M05 that stops the spindle: the preamble
    cannot turn it on alone (M13 starts the spindle too; which coolant M08 runs is the
    builder's), so a restart after that M05 and before an M09 is refused, where it was planned
    with the coolant off. A restart block that sets the coolant itself (its M09, a keyed start
    with the coolant, a mill's tool change) is planned; after an M09, with the coolant off."""
    text = COOLED.format(start="M13").replace("N90 M09\n", "")
    for line in (12, 13):
        assert refusal(text, line, KEYED) == (
            "cannot restart here: M13 on line 6 turned the spindle and the coolant on, and the "
            "spindle has been stopped or started by another code since, with no M09: that "
            "coolant is still on, and the preamble cannot turn it on without M13 starting the "
            "spindle too; restart at or before line 6, or after the M09 that ends the "
            "coolant"), line
    assert plan(text, 6, KEYED).preamble
    for own in ("M09", "T2 M06", "M14"):
        changed = text.replace("N140 G00 X0 Y0", f"N140 G00 X0 Y0 {own}")
        assert plan(changed, 12, KEYED).preamble, own
    off = text.replace("N140 G00 X0 Y0", "N135 M09\nN140 G00 X0 Y0")
    preamble = plan(off, 13, KEYED).preamble
    assert not any(c in b for b in preamble for c in ("M13", "M09", "M08")), preamble
    # an M03 after the M13 (no M09), or after its M05: the spindle CW and M13's coolant on,
    # which M13 restores exactly (review 57a F3: refused); an M04 there is not M13's: refused
    turned = text.replace("N130 M05", "N130 M03")
    assert "G97 S1000 M13" in plan(turned, 13, KEYED).preamble
    again = text.replace("N140 G00 X0 Y0", "N135 M03\nN140 G00 X0 Y0")
    preamble = plan(again, 14, KEYED).preamble
    assert "G97 S1000 M13" in preamble and "M09" not in preamble, preamble
    reversed_ = text.replace("N130 M05", "N130 M04")
    assert refusal(reversed_, 13, KEYED).startswith("cannot restart here: M13 on line 6 turned")


def test_a_keyed_start_in_the_tool_changes_block_keeps_its_coolant_on() -> None:
    """Review 57a F2: `T2 M06 M13` (and `S1200 M13 T3 M06`) had the walk clear the keyed
    coolant at the block's M06 after setting it at its M13, so the preamble wrote M13 then
    M09 and the cut ran dry, where the program never turned its coolant off. The M13 of the
    tool change's own block runs after the change: its coolant stays on."""
    text = (COOLED.format(start="M13").replace("N50 T1 M06\n", "N50 S1000 T1 M06 M13\n")
            .replace("N70 S1000 M13\n", "N70 G00 X0 Y0\n").replace("N90 M09\n", ""))
    for line in (8, 9):
        preamble = plan(text, line, KEYED).preamble
        assert "M09" not in preamble and any("M13" in b for b in preamble), (line, preamble)
    # the M06 of a later block still ends it: after `T2 M06` the spindle and coolant are off
    later = text.replace("N130 M05\n", "N130 T2 M06\n").replace("N140 G00 X0 Y0",
                                                                  "N140 G43 H2 Z50.")
    preamble = plan(later, 13, KEYED).preamble
    assert not any(c in b for b in preamble for c in ("M13", "M09", "M08")), preamble


def test_a_listed_spindle_code_without_a_key_refuses_the_restart():
    """Review 56d F9: a profile that lists the builder's M13 in the spindle's modal group with
    no meaning key (the natural way to silence TG307) has the walk read no spindle state from
    it: a restart after it is refused (it was planned with the spindle stopped by the M06, and
    fed into the work), until an M03, M04 or M05 sets the spindle again or an M06 stops it; the
    hint's line is itself planned."""
    listed = profile_from_text(
        'base = "fanuc-mill"\n[codes]\n'
        'M13 = { function = "spindle CW and coolant on", duration = "spindle" }\n', "m13u")
    for line in (7, 8, 9):
        assert refusal(M13_MILL, line, listed) == (
            "cannot restart here: M13 (spindle CW and coolant on) on line 6 is a code of the "
            "spindle's modal group with no meaning the restart reads, and no M03, M04 or M05 has "
            "come since: what it did to the spindle (a builder's M13 starts it with the coolant, "
            "an M19 orients it) the preamble cannot know or restore; restart at or before line "
            "6, or after the M03, M04 or M05 that sets the spindle again (or key the code in the "
            'profile: meaning = "spindle-cw-coolant-on", docs/profiles.md)'), line
    assert plan(M13_MILL, 6, listed).preamble
    assert plan(M13_MILL, 11, listed).preamble  # after the M05
    assert plan(M13_MILL.replace("N90 G01", "N90 M03 G01"), 9, listed).preamble
    # a tool change after it stops the spindle (a FANUC mill's M06), the restart block's own too
    changed = M13_MILL.replace("N100 G00 Z50.\nN110 M05", "N100 T2 M06\nN110 G43 H2 Z50.")
    assert plan(changed, 9, listed).preamble
    assert not any("M13" in b or "M03" in b for b in plan(changed, 11, listed).preamble)
    # LinuxCNC's M19 is listed without a key: what it did is not known either
    lcnc = load_profile("linuxcnc")
    text = "G21 G17 G90\nT1 M6\nS1000 M3\nG0 X0 Y0 Z5\nM19 R90\nG0 X1\nG1 Z-5 F100\nM3\nG1 X5\nM2\n"
    assert refusal(text, 6, lcnc).startswith("cannot restart here: M19 (orient spindle")
    assert plan(text, 9, lcnc).preamble


# The Robodrill's probe on and off (M107, M117: shops/wafflesandpremix__RobodrillMacros),
# builder's codes fanuc-mill's list lacks, between two tool changes (line 13: T1 M06).
PROBED = ("%\nO2\nG21 G17 G90 G40 G80\nT20 M06\nG00 G54 X0 Y0\nG43 H20 Z50.\nM107\n"
          "G01 Z5. F3000.\nG31 Z-10. F500.\nM117\nG91 G28 Z0\nG90\nT1 M06\n"
          "G00 G54 X10. Y10. S3000 M03\nG43 H1 Z50. M08\nG01 Z-5. F300.\nG00 Z50.\nM30\n%\n")


def test_a_builders_code_before_the_restart_blocks_own_tool_change_is_no_refusal():
    """Review 56d F7: a FANUC mill's M06 stops the spindle, so at the restart block's own tool
    change whatever a builder's code after the last one did to the spindle is undone: planned,
    where it was refused. Between them the refusal's hint names the first builder's code of the
    run (line 7), a line that is planned, not the last (line 10), which is refused too."""
    assert plan(PROBED, 13).preamble
    assert plan(PROBED, 7).preamble
    for line in (8, 10, 11, 12):
        message = refusal(PROBED, line)
        assert "restart at or before line 7, at the next tool change" in message, (line, message)


SIN_EXTENDED = ("N10 G17 G90 G71 G40\nN20 T1 D1\nN30 M6\nN40 G0 X0 Y0 Z50\nN50 S1000 M3\n"
                "N60 G0 X10 Y10\nN70 G1 Z-5 F100\nN80 G1 X20\nN90 G0 Z50\nN100 {code}\n"
                "N110 G0 C90\nN120 G1 Z-5\nN130 M3 S1000\nN140 G1 X30\nN150 M30\n")


@pytest.mark.parametrize("code", ["M0=70", "M1=70", "M2=70", "SPOS=90", "SPOSA[1]=0",
                                  "M0=3", "M1=3", "M1=5", "M[R1]=3", "M1=R2"])
def test_a_sinumerik_spindle_function_by_extension_refuses_the_restart(code: str):
    """Review 56d F6, F11: the modal state reads a SINUMERIK's plain M3, M4, M5 alone, so a
    spindle's function by its address extension (`M1=70`, `M0=3`: Function Manual S1, H2) or
    its positioning (`SPOS=90`) left the preamble starting a spindle in axis mode, or cutting
    with one the program had started stopped: refused, naming it, until a plain M3, M4 or M5
    of the master (here line 13, whose own M3 plans it again)."""
    sin = load_profile("sinumerik-840d")
    text = SIN_EXTENDED.format(code=code)
    for line in (11, 12):
        message = refusal(text, line, sin)
        assert message.startswith(f"cannot restart here: {code} on line 10 commands a spindle "
                                  "by its address extension or position"), message
        assert message.endswith("restart at or before line 10, or after a plain M3, M4 or M5 "
                                "of the master spindle"), message
    assert plan(text, 10, sin).preamble
    if code.startswith(("M2=", "M[", "SPOSA[")):  # another spindle's, or one not read
        assert refusal(text, 14, sin)
    else:
        assert "G97 S1000 M03" in plan(text, 14, sin).preamble


# -- review 35: the restart's safety faults ---------------------------------------------------

# A fine boring bar's way out (N6-N9: oriented, shifted off the wall, out through the bore),
# then the spindle started again. N8 is line 10, N10 line 12.
ORIENTED = ("%\nO1000\nN1 G21 G17 G90 G40 G80 G54\nN2 T3 M06\nN3 S600 M03\n"
            "N4 G00 G43 H3 X20. Y10. Z5.\nN5 G01 Z-30. F50.\nN6 M19\nN7 G00 X19.8\n"
            "N8 G00 Z5.\nN9 G00 X20.\nN10 M03\nN11 G00 X40.\nM30\n%\n")
# A Haas lathe's keyway: a static tool fed along Z with the spindle oriented (N9 is line 11).
KEYWAY = ("%\nO1000\nN1 G20 G18 G40 G99\nN2 T0101\nN3 G97 S500 M03\nN4 G00 X2. Z0.1\n"
          "N5 T0909\nN6 M19 R45.\nN7 G98\nN8 G00 X1.1 Z0.1\nN9 G01 Z-0.8 F10.\n"
          "N10 G00 X1.\nM30\n%\n")


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill"])
def test_an_oriented_spindle_refuses_a_restart_until_it_turns_again(profile):
    """Review 35, finding 1: M19 (`spindle-orient`: "adjusts the spindle to a fixed position",
    Haas mill manual, "M19 Orient Spindle") left the modal state's M03 in force, so the
    preamble started the spindle with the boring bar shifted off-centre in the bore. Refused
    from the M19 to the next M03, M04 or M05, naming both places to restart."""
    machine = load_profile(profile)
    said = refusal(ORIENTED, 10, machine)
    assert said == (
        "cannot restart here: M19 on line 8 oriented the spindle (stopped at a fixed angle) "
        "and no M03, M04 or M05 has come since: the preamble would start it with the spindle "
        "mode of before, or leave it at another angle (a bar shifted through a bore, a static "
        "tool fed); restart at or before line 8, or after the M03 or M04 that starts the "
        "spindle again"), said
    assert refusal(ORIENTED, 12, machine).startswith("cannot restart here: M19 on line 8")
    # at the M19 itself, and after the M03 that starts the spindle again: planned
    assert any("S600 M03" in block for block in plan(ORIENTED, 8, machine).preamble)
    assert any("S600 M03" in block for block in plan(ORIENTED, 13, machine).preamble)
    # an M05 after it: the spindle stopped, as with no M19
    stopped = ORIENTED.replace("N9 G00 X20.", "N9 G00 X20. M05")
    assert not any("M03" in block for block in plan(stopped, 12, machine).preamble)


def test_a_haas_lathe_oriented_spindle_refuses_a_restart_of_its_static_tool():
    """Review 35, finding 1, on a Haas lathe: the keyway's static tool fed along Z with the
    spindle oriented (M19 R45.) was planned with `G97 S500 M03`."""
    haas = load_profile("haas-lathe")
    assert refusal(KEYWAY, 11, haas).startswith(
        "cannot restart here: M19 on line 8 oriented the spindle")


# A FANUC lathe's cross hole by the builder's codes (M45 C axis on, M13 live tool; neither in
# fanuc-lathe's list): T0606 is line 10, M13 line 12, N95 line 13.
CROSS_HOLE = ("%\nO1000\nN1 G20 G18 G40 G99\nN2 T0101\nN3 G97 S800 M03\n"
              "N4 G00 X3. Z0.1\nN5 G01 Z-1. F0.01\nN6 G00 X3.2\nN6 M05\nN7 T0606\n"
              "N8 M45\nN9 G98 M13 S1500\n{c}N10 G00 X3.2 Z-0.5\nN11 G01 X1.5 F4.\n"
              "N12 G00 X3.2 Z0.1\nN13 T0101 G99 G97 S800 M03\nN14 G00 X3.4 Z0.1\n"
              "N15 G01 Z-0.2 F0.01\nM30\n%\n")


def test_a_fanuc_lathe_live_tool_by_the_builders_m_codes_refuses_the_restart():
    """Review 35, finding 2: a FANUC lathe's live tool and C axis (Cs) mode are the builder's M
    codes (TG307), which fanuc-lathe's list does not name: the radial drill was planned with
    the live tool stopped (or the main spindle turning) and C where the operator left it.
    After a C (or Y) move, refused until the main spindle's M03/M04; with the main spindle
    stopped, refused after an M code the list lacks since the tool change. A turning pass
    after M03 is planned."""
    lathe = load_profile("fanuc-lathe")
    at_c = CROSS_HOLE.format(c="N95 G00 C45.\n")
    said = refusal(at_c, 15, lathe)
    assert said.startswith("cannot restart here: the program moved C on line 13 and has not "
                           "started the main spindle (M03, M04) since"), said
    assert "the machine builder's M codes (TG307)" in said
    # no C word (a hole on the centre line, C left as it is): the live tool's code named
    said = refusal(CROSS_HOLE.format(c=""), 13, lathe)
    assert said == (
        "cannot restart here: the main spindle is stopped and M13 on line 12, an M code the "
        "profile's list lacks, came after the tool change on line 10: a live tool's drive or "
        "the C axis (Cs) mode, which this control switches by the machine builder's M codes "
        "(TG307), the preamble cannot restore; restart at or before the tool change (line 10), "
        "or after the M03 or M04 that starts the main spindle"), said
    # at the block that starts the main spindle itself (N13, line 16): planned
    assert plan(CROSS_HOLE.format(c=""), 16, lathe).preamble
    # at the block that starts the main spindle itself after the C move (review 36, finding
    # 5: the message sent the operator to this very block, which it refused): planned, C not
    # positioned (the block turns the spindle)
    own_start = plan(at_c, 17, lathe)
    assert not any("C45." in block for block in own_start.preamble), own_start.preamble
    # turning again after M03: planned, C not positioned
    turning = plan(at_c, 19, lathe)
    assert not any("C45." in block for block in turning.preamble), turning.preamble
    # a builder's code with the main spindle turning (a turning pass) is planned as before
    assert plan(CROSS_HOLE.format(c="").replace("N6 M05", "N6 M23"), 7, lathe).preamble


def test_a_fanuc_lathe_builder_code_after_a_tool_change_with_the_spindle_carried_refuses():
    """Review 35, finding 1 left open by fix35r: a keyway tool's `M19 R90.` after T0707 was
    planned with `G97 S500 M03` on fanuc-lathe, whose list had no M19: the spindle the program
    holds still turned by the preamble. fanuc-lathe now lists M19 as the builders' usual
    orientation (review 36), and any M code the list lacks after a tool change that started no
    spindle (the M03 before it carried) refuses, naming both lines; where the tool starts the
    spindle itself, the builder's code after it is planned as before."""
    lathe = load_profile("fanuc-lathe")
    text = ("%\nO1003\nG20 G18 G40 G80 G99\nT0101\nG97 S500 M03\nG00 X2. Z0.1\n"
            "G01 Z-0.5 F0.01\nG00 X2.2 Z0.1\nT0707\nM19 R90.\nG98\nG00 X0.9 Z0.1\n"
            "G01 X1.0 F20.\nG01 Z-1. F20.\nG00 X0.9\nM30\n%\n")
    assert refusal(text, 15, lathe).startswith(  # the stroke along Z
        "cannot restart here: M19 on line 10 oriented the spindle")
    builder = text.replace("M19 R90.", "M20")  # a builder's code the list lacks
    said = refusal(builder, 15, lathe)
    assert said == (
        "cannot restart here: M20 on line 10, an M code the profile's list lacks, came after "
        "the tool change on line 9, and the main spindle has not been started since (its "
        "M03/M04 is on line 5): the builder's code may have stopped or oriented it (a spindle "
        "orientation, a live tool), which the preamble cannot know; restart at or before the "
        "tool change (line 9), or after the M03 or M04 that starts the main spindle again"), said
    assert plan(builder, 9, lathe).preamble  # at the tool change itself
    turning = builder.replace("T0707\nM20\nG98", "T0707\nG97 S500 M03\nM23\nG99")
    assert plan(turning, 15, lathe).preamble  # the tool's own M03, then the builder's M23


def test_a_fanuc_lathe_builder_code_with_the_spindle_stopped_holds_over_a_tool_change():
    """Review 36, finding 2: the builder's C axis code given before the T word (`M05 / M76 /
    T0505`), or a live tool's drive carried to the next live tool, was forgotten at the tool
    change and the radial drill planned with nothing turning. With the main spindle stopped
    the code holds until the next M03/M04; the refusal says it came before the change."""
    lathe = load_profile("fanuc-lathe")
    text = ("%\nO3001\nG20 G18 G40 G80 G99\nT0101\nG97 S500 M03\nG00 X2.2 Z0.1\n"
            "G01 Z-1. F0.005\nG00 X2.4 Z0.2\nM05\nM76\nT0505\nG98\nG00 X2.4 Z-0.4\n"
            "G01 X1.2 F5.\nG00 X2.4\nG00 Z0.2\nT0101\nG99 G97 S500 M03\nG00 X2.2 Z0.1\n"
            "G01 Z-1. F0.005\nM30\n%\n")
    said = refusal(text, 14, lathe)  # the drill's stroke under T0505
    assert said.startswith(
        "cannot restart here: the main spindle is stopped and M76 on line 10, an M code the "
        "profile's list lacks, came after the main spindle stopped, and stays in force over "
        "the tool change on line 11"), said
    assert "restart at or before line 10" in said
    assert plan(text, 20, lathe).preamble  # turning again after the M03


# Two tools on a mill: T2's M06 is line 10; its first move (line 11) and its G43 (line 12).
TWO_TOOLS = ("%\nO2002\nG21 G17 G40 G49 G80 G90\nT1 M06\nG00 G54 X0. Y0. S1000 M03\n"
             "G43 H01 Z25. M08\nG01 Z-5. F100.\nG00 Z25.\nM19\nT2 M06\nG00 X10. Y10.\n"
             "G43 H02 Z25.\nS2000 M03\nG01 Z-5. F100.\nG00 Z25.\nM30\n%\n")


@pytest.mark.parametrize("name", ["fanuc-mill", "haas-mill"])
def test_a_mill_restart_after_a_tool_change_does_not_carry_the_old_tool_s_state(name):
    """Review 36, finding 1: between an M06 and the new tool's own G43 and M03 the restart
    started the spindle at the old tool's speed and sent the new tool down with the old tool's
    length offset (a probe loaded by T20 M06 spun at S8000; T2 to Z25. with H01). The M06
    "stops the spindle, stops coolant, moves the Z Axis to the tool change position" (Haas mill
    manual, NGC, "M06 Tool Change"): after it the spindle and coolant are off until the
    program's own codes, Z is at no height of the program's, and the old H is refused."""
    profile = load_profile(name)
    said = refusal(TWO_TOOLS, 11, profile)  # X Y under T2 with H01 in force
    assert said == (
        "cannot restart here: the length offset G43 H01 in force was set on line 6, before the "
        "tool change on line 10, and the program has not moved Z since: the new tool is at the "
        "tool change height with the old tool's length; restart at the block that sets the new "
        "tool's length offset and Z (G43 H.. Z..), or at the tool change"), said
    # at the new tool's G43 H02 Z25.: X Y placed at the tool change height as the program
    # placed them, no spindle, no coolant, no old H (review 36, finding 2: the M19 before the
    # M06 no longer refuses it)
    at_g43 = plan(TWO_TOOLS, 12, profile)
    assert at_g43.preamble[1] == "T2 M06", at_g43.preamble
    assert at_g43.preamble[-2:] == ["G00 X10. Y10.", "F100."], at_g43.preamble
    assert not any("M03" in b or "M08" in b or "H01" in b for b in at_g43.preamble)
    # after the new tool's M03 and G43: its own speed and offset
    cutting = plan(TWO_TOOLS, 14, profile)
    assert any(b.endswith("S2000 M03") for b in cutting.preamble), cutting.preamble
    assert "G00 G43 Z25. H02" in cutting.preamble
    assert not any("M08" in b for b in cutting.preamble)  # the coolant the M06 stopped


def test_a_restart_at_the_end_of_tape_after_m30_says_the_program_ended():
    """Review 36, finding 6: the closing % after M30 (or a DOS end-of-file mark) was refused
    with "the preamble would not restore tool (please report this program)"."""
    text = "%\nO1\nG21 G90 G17\nT1 M06\nG00 G54 X0. Y0. S1000 M03\nG43 H1 Z10.\nM30\n%\n"
    assert refusal(text, 8, FANUC) == (
        "cannot restart here: the program has ended before this line (M02 or M30): there is "
        "nothing after it to run; restart at a block before the end")
    assert refusal(text + "\x1a", 9, FANUC).startswith(
        "cannot restart here: the program has ended before this line")


def test_a_fanuc_lathe_h_word_is_an_increment_of_c():
    """Review 36, finding 3 (doubtful safety): in G code system A a FANUC lathe writes C's
    increment as H (as U and W of X and Z), which fanuc-lathe's classification does not hold
    (TG134): `H90.` turned C and the restart after it was planned as if C had not moved. It
    is a C move now: C lost, the way in ended, refused until the main spindle's M03/M04."""
    lathe = load_profile("fanuc-lathe")
    text = ("%\nO3003\nG20 G18 G40 G80 G99\nT0101\nG97 S1000 M03\nG00 X2.2 Z0.1\n"
            "G01 Z-1. F0.005\nG00 X2.4\nG00 Z0.2\nM05\nT0202\nG00 X2.2 Z0.1\nH90.\n"
            "G01 X2.0 F0.005\nG00 X2.4\nM30\n%\n")
    assert refusal(text, 15, lathe).startswith(
        "cannot restart here: the program moved C on line 13")


def test_a_haas_g107_cancel_loses_the_mapped_axes_only():
    """Review 36, finding 8: after a Haas G107's cancel Z was lost, though the mapping turns
    only its named linear axis onto the cylinder (Haas mill manual, G107: "all programmed
    motion occurring in a specified linear axis"): Z written under it is where it was written.
    The rotary axis (A, which the program had moved) is lost, so the restart stays refused
    until A is written; once it is, Z is no obstacle."""
    haas = load_profile("haas-mill")
    text = ("%\nO2004\nG20 G17 G40 G49 G80 G90\nT1 M06\nG00 G54 X0. Y0. A0. S3000 M03\n"
            "G43 H01 Z1.\nG107 Y0 R1.\nG01 Z-0.05 F10.\nG01 Y2.\nG00 Z1.\nG107\n"
            "G00 X1. Y0.\nG01 Z-0.1 F10.\nM30\n%\n")
    assert "the position of A is not known here (line 11" in refusal(text, 13, haas)
    # A written again after the cancel: the Z1. written under G107 is where the tool is
    again = text.replace("G00 X1. Y0.\n", "G00 X1. Y0. A0.\n")
    restart = plan(again, 13, haas)
    assert "G00 G43 Z1. H01" in restart.preamble, restart.preamble


def test_a_lathe_way_in_stops_at_a_move_of_c():
    """Review 35, finding 3: a lathe's way in replayed X and Z moves made at another C: the
    hole at C0 drilled to X0.8 was replayed after the preamble set C90., where the program
    drills to X1.2 only. A move of C (or Y, B) ends the way: the moves before it are not
    replayed."""
    haas = load_profile("haas-lathe")
    text = ("%\nO1000\nN1 G20 G18 G40 G99\nN2 T0505\nN3 M05\nN4 G98\n"
            "N5 G00 X3. Z0.1 C0.\nN6 G00 X2.4 Z-0.4\nN7 G01 X0.8 F5.\nN8 G00 X2.4\n"
            "N9 G00 C90.\nN10 G01 X1.2 F5.\nN11 G00 X2.4\nM30\n%\n")
    planned = plan(text, 12, haas)  # at N10
    assert any("C90." in block for block in planned.preamble), planned.preamble
    assert not any("X0.8" in block for block in planned.preamble), planned.preamble


def test_a_haas_g107_loses_its_rotary_axis_at_the_cancel():
    """Review 35, finding 4: a Haas G107 turns the rotary axis for the moves of the linear one
    ("translates all programmed motion occurring in a specified linear axis into the
    equivalent motion along the surface of a cylinder", Haas mill manual, G107); the A0 of its
    block only names the axis. After the cancel A was planned at 0, where the moves had left
    it at 43 degrees."""
    haas = load_profile("haas-mill")
    text = ("%\nO1000\nN1 G20 G17 G40 G80 G90 G54\nN2 T2 M06\nN3 G00 X0 Y0 A0\n"
            "N4 S2000 M03\nN5 G43 H2 Z0.5\nN6 G107 A0 Y0 R2.\nN7 G01 Z-0.02 F8.\n"
            "N8 G01 Y1.5\nN9 G00 Z0.5\nN10 G107\nN11 G00 X2. Y0 Z0.5\nN12 G01 Z-0.05 F8.\n"
            "M30\n%\n")
    said = refusal(text, 14, haas)
    assert said.startswith("cannot restart here: the position of A is not known here (line "
                           "12: G107 ends the cylindrical interpolation"), said
    # A given again: planned
    assert plan(text.replace("N11 G00 X2. Y0", "N11 G00 X2. Y0 A0"), 14, haas).preamble
    # a G107 naming no rotary axis loses the one the program moved
    bare = text.replace("G107 A0 Y0 R2.", "G107 Y0 R2.")
    assert "position of A is not known" in refusal(bare, 14, haas)


# A Haas lathe's XC interpolation (G112: X Y to X C, Y the virtual axis) with a live tool, then
# turning again: N14 G113 is line 15, N21 line 22.
POLAR_HAAS = ("%\nO1000\nN1 G20 G18 G40 G99 G54\nN2 T0606\nN3 M154\nN4 G98\n"
              "N5 P1500 M133\nN6 G00 X3. Z0.1 C0.\nN7 G112\nN8 G17\nN9 G01 Z-0.05 F6.\n"
              "N10 G01 X0.6 Y0.3\nN11 G01 X-0.6\nN12 G00 Z0.1\n{y}N14 G113\nN15 M135\n"
              "N16 M155\nN17 G18 G99\nN18 G97 S700 M03\nN19 G00 X2.5 Z0.1\n"
              "N20 G01 Z-0.6 F0.008\nN21 G00 X2.7\nM30\n%\n")


def test_a_haas_lathe_y_after_g112_is_no_place_and_c_is_lost():
    """Review 35, finding 8: after a Haas lathe's G112/G113 every restart was refused on Y,
    the virtual axis of the XC plane (Autodesk's HAAS Lathe post writes Y only under G112),
    which turning programs never write again. After G113 Y has no place (not positioned) and
    C, which the control turned, is lost; a Y the program had before G112 (a Y-axis lathe's)
    stays not known."""
    haas = load_profile("haas-lathe")
    planned = plan(POLAR_HAAS.format(y=""), 22, haas)
    assert not any("Y" in block or "C" in block for block in planned.preamble[1:]), \
        planned.preamble
    # a real Y before the G112: its place after the G113 is not known
    real = POLAR_HAAS.format(y="").replace("N6 G00 X3. Z0.1 C0.", "N6 G00 X3. Y0 Z0.1 C0.")
    assert "the position of Y is not known here" in refusal(real, 22, haas)


def test_a_haas_lathe_c_axis_disengaged_is_not_positioned():
    """Review 35, finding 9: after M155 (C axis disengage) the approach positioned C at the
    live tool's last angle before the turning tool's own M03; a C word is no position then.
    Not positioned, until the program writes C again."""
    haas = load_profile("haas-lathe")
    text = POLAR_HAAS.format(y="").replace("N7 G112\nN8 G17\n", "N7 G00 C30.\nN8 G18\n")
    text = text.replace("N10 G01 X0.6 Y0.3\nN11 G01 X-0.6\n", "N10 G01 X1.5\nN11 G00 X3.\n")
    # N17 (line 18): after M155, the main spindle not yet started
    planned = plan(text, 18, haas)
    assert not any("C30." in block for block in planned.preamble), planned.preamble


def test_a_refusal_inside_a_live_tool_section_says_where_to_restart():
    """Review 35, finding 10: a refusal inside a Haas lathe's live tool section named no place
    to restart: it names the block of the first mode code in force and the codes that end the
    modes. Review 36, finding 7: it named the tool change before the code, which, where M154
    comes before the live tool's T word, is the tool before; the code's own block is the
    nearest place, and a restart there is planned."""
    haas = load_profile("haas-lathe")
    said = refusal(POLAR_HAAS.format(y=""), 13, haas)
    assert said == (
        "cannot restart here: M154 (C axis engage) from line 5 is in force and the preamble "
        "cannot restore it; restart at or before line 5, or after the M135 and M155 that end "
        "the modes"), said
    # the second mode code (M133, line 7) names the first's line: a restart at line 7 is
    # refused on M154
    assert "restart at or before line 5," in refusal(POLAR_HAAS.format(y=""), 9, haas)
    assert "M154 (C axis engage) from line 5" in refusal(POLAR_HAAS.format(y=""), 7, haas)
    assert plan(POLAR_HAAS.format(y=""), 5, haas).preamble
    # M154 before the live tool's T word, after a turning tool (line 5's T0101)
    before_t = ("%\nO1010\nG20 G18 G40 G80 G99\nG54\nT0101\nG97 S500 M03\nG00 X2. Z0.1\n"
                "G01 Z-0.5 F0.01\nG00 X2.2\nG00 Z0.1\nM05\nM154\nT0505\nG98\nP2000 M133\n"
                "G00 X2.4 C0. Z-0.4\nG01 X1.2 F5.\nG00 X2.4\nM135\nM155\nM30\n%\n")
    said = refusal(before_t, 16, haas)
    assert said.endswith("restart at or before line 12, or after the M135 and M155 that end "
                         "the modes"), said
    planned = plan(before_t, 12, haas)
    assert "T0101" in planned.preamble and not any("M03" in b for b in planned.preamble), \
        planned.preamble
    # review 37, finding 7: the line named is planned itself, also with an M19 before the
    # M154 (the M19's line) and in a second C axis section after a C move of the first (the
    # first section's M154: the way in from the second is not known)
    oriented = before_t.replace("M05\nM154\n", "M05\nM19\nM154\n")
    twice = before_t.replace("M30\n", "M154\nG00 C90.\nM155\nM30\n")
    for text, at in ((before_t, 16), (oriented, 17), (twice, 22)):
        said = refusal(text, at, haas)
        named = int(re.search(r"restart at or before line (\d+)", said).group(1))
        assert plan(text, named, haas).preamble, (at, named, said)


def test_a_second_m19_sends_a_restart_hint_to_the_first():
    """Review 38, finding 5: a second live tool section with an M19 before each, the spindle
    not started between them. The orientation of the first M19 (line 12) is in force up to
    the end, a second M19 (line 22) ends none: a hint that named line 13 (the first section's
    M154) or 22 (the second M19) sent the user to a restart refused for line 12's M19. Every
    line a refusal names is planned itself."""
    haas = load_profile("haas-lathe")
    text = ("%\nO1010\nG20 G18 G40 G80 G99\nG54\nT0101\nG97 S500 M03\nG00 X2. Z0.1\n"
            "G01 Z-0.5 F0.01\nG00 X2.2\nG00 Z0.1\nM05\nM19\nM154\nT0505\nG98\nP2000 M133\n"
            "G00 X2.4 C0. Z-0.4\nG01 X1.2 F5.\nG00 X2.4\nM135\nM155\nM19\nT0606\nM154\nG98\n"
            "P1500 M133\nG00 X2.4 C45. Z-0.6\nG01 X1.2 F5.\nM135\nM155\nM30\n%\n")
    said = refusal(text, 25, haas)
    assert "restart at or before line 12, or after the M135 and M155" in said, said
    said = refusal(text, 23, haas)
    assert said.startswith("cannot restart here: M19 on line 22 oriented the spindle (stopped "
                           "at a fixed angle) (the spindle oriented since line 12) and no "
                           "M03, M04 or M05"), said
    assert "restart at or before line 12, or after the M03" in said, said
    named = set()
    for at in range(2, len(text.split("\n"))):
        try:
            plan(text, at, haas)
        except RestartRefused as refused:
            found = re.search(r"restart at or before line (\d+)", refused.message)
            if found:
                named.add(int(found.group(1)))
    assert named == {12}
    for line in named:
        assert plan(text, line, haas).preamble
    # an M05 between the two M19: each orientation its own, the second's hint its own line
    # (the tool taken up to Z0.1 first, out of the bore: line 19's radial move is no way in)
    apart = text.replace("M155\nM19\nT0606", "M155\nG00 Z0.1\nS300 M03\nM05\nM19\nT0606")
    said = refusal(apart, 28, haas)
    assert "restart at or before line 25," in said, said
    assert plan(apart, 25, haas).preamble


# -- two codes of one modal group before the restart point (TG304) ------------------------------

CONFLICT = ("%\nO1000\nN1 G21 G17 G90 G54\nN2 T1 M06\nN3 S1000 M03 G00 Z150.\n"
            "N4 {block} Z100.\nN5 G00 X10. Y5.\nN6 G01 Z2. F100.\nN7 G01 X50.\nM30\n%\n")
# N4 is line 6, N7 line 9


@pytest.mark.parametrize("block, first, second", [
    ("G49 G43.4 H1", "G49", "G43.4"),
    ("G43 G49 H1", "G43", "G49"),
    ("G43.4 G43 H1", "G43.4", "G43"),
    ("G00 G01 G43 H1", "G00", "G01"),
    ("G43 H1 M08 M09", "M08", "M09"),
])
def test_no_restart_after_a_block_with_two_codes_of_one_modal_group(block, first, second):
    """fix28's doubt: `G49 G43.4 H1` (or `G43 G49 H1`) was planned by the restart as its first
    code, where the check reports the block (TG304) and no source at hand says which code
    the control takes. Refused, naming the block and the check's message. Two M codes of a
    group on a FANUC are TG308, a warning (no source shows an alarm), and refused alike: which
    one the machine takes is still not known."""
    rule = "TG308" if first.startswith("M") else "TG304"
    # (the two codes in the block's order: review 51, F19)
    text = CONFLICT.format(block=block)
    said = refusal(text, 9)
    assert said.startswith(
        f"cannot restart here: line 6 holds two codes of one modal group ({first} and "
        f"{second} are both in modal group"), said
    assert "TG304 or TG308: see tapegate check" in said
    # the check says the same of that block
    blocks = parse_text(text, FANUC.dialect, file="p.nc")
    from postproc.check import Checker
    found = [(f.rule, f.line) for f in Checker(FANUC, file="p.nc").run(iter(blocks))
             if f.rule in ("TG304", "TG308")]
    assert found == [(rule, 6)]
    # a restart at the block itself and before it is planned (nothing of it ran yet)
    assert plan(text, 6).preamble is not None
    # one code of the group: planned
    one = CONFLICT.format(block="G43 H1")
    assert plan(one, 9).preamble


def test_two_program_stops_in_a_block_refuse_a_restart_after_it_too():
    text = CONFLICT.replace("N5 G00 X10. Y5.", "N5 G00 X10. Y5. M00 M01").format(block="G43 H1")
    said = refusal(text, 9)
    assert said.startswith("cannot restart here: line 7 holds two codes of one modal group "
                           "(M00 and M01 are both in the group of program stops"), said


def test_a_modal_group_conflict_in_another_program_of_the_file_does_not_refuse():
    """Each program of a file is walked from its own start: a conflict in the first does not
    refuse a restart in the second."""
    second = CONFLICT.format(block="G43 H1").replace("O1000", "O2000")
    text = CONFLICT.format(block="G49 G43.4 H1").replace("M30\n%\n", "M30\n") + second[2:]
    lines = text.split("\n")
    at = lines.index("N7 G01 X50.", 10) + 1
    assert plan(text, at).preamble


def test_a_spindle_speed_limit_is_restored_as_a_limit_and_a_speed_as_a_speed():
    """Review 38, finding 1: the restart's modal state and the check read a block's S by one
    rule (ModalSettings::s_limit). A SINUMERIK's `G26 S3000` is the upper limit: the preamble
    started the spindle at 3000 (three times the cutting speed); a Haas's or LinuxCNC's
    `G92 S8000 M03` is a speed (their G92 only sets coordinates): the preamble started it at
    the speed before, S1000, and wrote `G92 S8000`, which LinuxCNC refuses."""
    sinumerik = load_profile("sinumerik-840d")
    text = ("G71 G90 G17 G54 G0 X0 Y0 Z100\nT1 D1\nM6\nS1000 M3\nG0 Z50\nG26 S3000\n"
            "G1 X10 F100\nG1 X20\nG1 X30\nM30\n")
    pre = plan(text, 8, sinumerik).preamble
    assert "G26 S3000" in pre and any("S1000 M03" in b for b in pre), pre
    assert not any("S3000 M03" in b or "G92" in b for b in pre), pre
    lower = plan(text.replace("G26 S3000", "G25 S50"), 8, sinumerik).preamble
    assert any("S1000 M03" in b for b in lower) and not any("S50" in b for b in lower), lower
    haas = ("%\nO1\nG20 G90 G54 G0 X0 Y0 Z1.\nS1000 M03\nG1 Z-0.1 F10.\nG92 S8000 M03\n"
            "G1 X1.\nG1 X2.\nG1 X3.\nM30\n%\n")
    pre = plan(haas, 8, load_profile("haas-mill")).preamble
    assert any("S8000 M03" in b for b in pre) and not any("G92" in b for b in pre), pre
    lcnc = ("G21 G90 G17 G54\nG0 X0 Y0 Z10\nS1000 M3\nG1 Z-1 F100\nG1 X5\nG92 S8000 M3\n"
            "G1 X10\nG1 X20\nG1 X30\nM2\n")
    pre = plan(lcnc, 8, load_profile("linuxcnc")).preamble
    assert any("S8000" in b and "M03" in b for b in pre) and not any("G92" in b for b in pre), pre
    # a FANUC mill's G92 S is the clamp: restored as one, the speed as before
    fanuc = haas.replace("G92 S8000 M03", "G92 S8000")
    pre = plan(fanuc, 8, load_profile("fanuc-mill")).preamble
    assert "G92 S8000" in pre and any("S1000 M03" in b for b in pre), pre


@pytest.mark.parametrize(("profile", "block", "x"), [
    ("fanuc-mill", "G91 G99 G81 X10. Z-5. R-3. K3 F100.", Decimal(30)),
    ("fanuc-mill", "G91 G99 G73 X10. Z-5. R-3. Q1. K3 F100.", Decimal(30)),
    ("fanuc-mill", "G91 G99 G83 X10. Z-5. R-3. I1. J0.5 K3 F100.", Decimal(30)),
    ("fanuc-mill", "G91 G99 G83 X10. Z-5. R-3. I1. J0.5 K3. F100.", Decimal(30)),
    ("haas-mill", "G91 G99 G81 X10. Z-5. R-3. L3 F100.", Decimal(30)),
    ("haas-mill", "G91 G99 G83 X10. Z-5. R-3. Q1. K3 F100.", Decimal(10)),
])
def test_the_modal_machine_counts_a_cycle_s_repeats_as_the_checker_does(profile, block, x):
    """Review 55a, F4: the modal machine on its own (the plot, `postproc.state`) counts a
    canned cycle's holes by the rule the checker asks: a FANUC's K (three holes, X 30 mm),
    beside a G73/G83's I and J too, which a FANUC's G73/G83 has not, and with a point (review
    56a, F3, F8), and on a Haas its L, never its G83's K (the least peck depth: one hole)."""
    machine = run(load_profile(profile),
                  ["G21 G17 G90 G54", "G00 X0 Y0 Z5. S1000 M03", block])
    assert machine.state.position.get("X") == x
