"""Restarting a program from a block, safely (``send --restart-at``, a gateway request's ``/BL``).

Restarting mid-way is where machines crash: the control is in its reset state, with whatever
tool in the spindle and the tool wherever the operator left it. :func:`plan_restart` (blocks)
and :func:`plan_restart_text` (a file's text, no Python object per block) read the program up
to the restart block with the core's checker (the one modal state machine, which knows which
values are set by parameters or lost at a jump or call) and the core's restart walk
(``crates/core/src/restart.rs``), and write a preamble that brings the control into the state
a run from the start would have there:

1. units, plane, absolute distance, feed mode, cutter compensation, length offset and cycle
   cancelled, the work offset (G54...), LinuxCNC's diameter or radius mode (G7/G8);
2. the tool in the spindle (``T1 M06`` where the program changes tools with M06, the T word
   alone on a lathe turret), the tool selected next, the radius offset D;
3. the spindle speed and direction (with a lathe's speed clamp) and the coolant;
4. the approach: rapid to the clearance height with the length offset (``G00 G43 Z50. H1``),
   rapid over the start point (the end point of the block before), down to it in feed (the
   feed in force, or the restart block's own F). A lathe retracts in X, moves to the Z
   clearance, then goes the way the program went in with the tool in use from its clearance
   plane (the same rapids and feeds again), or else over the start diameter and in Z in feed;
   :attr:`RestartPlan.notes` says which. An axis the program last sent to the reference point
   or moved in machine coordinates (G28, G30, G53) is sent there again the same way;
5. the distance mode and motion mode in force (a restart block that inherits an arc or thread
   mode is sent with that code written into it).

The clearance is the profile's ``[restart] clearance`` (docs/profiles.md), or else the highest
Z the program went to before the restart block; on a mill, one no higher than the start point,
which the tool reached in feed, is refused (the approach would rapid to the cutting depth and
traverse there), unless the restart block is itself a rapid in the plane at that height.

Where the state cannot be restored safely the restart is refused with the reason and the line
(:class:`RestartRefused`): inside cutter compensation or a canned cycle, after a jump, loop or
subprogram call the state cannot follow, at a value set by a parameter, under a coordinate
rotation, scaling, mirror image or a G92/G52 shift (and after their cancel, until the axes are
given again), after increments from a position never set, inside a subprogram (its state is
its caller's), in a later program of a file that selects no units, after a lathe's radial move
whose way in is not known, on a lathe whose tool came from where the previous tool stopped
below the clearance plane, after a G7/G8 switch that leaves X in the other mode (until X is
written again in the new mode), at the second block of a FANUC lathe's two-block cycle (its
first block's data left out), from a spindle orientation (M19) to the next M03/M04/M05, inside a
Haas lathe's live tool or C axis mode, on any other lathe after a move of C or Y until the main
spindle starts again (or with it stopped after a builder's M code since the tool change), and on
families whose codes tapegate does not restore. The units
code is written only where the program wrote one (:attr:`RestartPlan.notes` says so).
The preamble is checked before it is offered: run through the core's modal state machine from
reset it must reach the state in force before the restart block.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field, replace
from decimal import ROUND_CEILING, Decimal, InvalidOperation
from functools import partial
from itertools import chain
from typing import Any

from formats import _core
from formats.errors import TapegateError
from formats.machine import machine
from formats.model import Block
from formats.parser import BadBlock, parse_stream, parse_text, whole_lines
from formats.profile import Profile
from postproc.state import AXES, ModalState

__all__ = ["RestartPlan", "RestartRefused", "RestartWalk", "plan_restart", "plan_restart_text"]

INCH = Decimal("25.4")
_UNIT_NAMES = {"metric": "mm", "inch": "inch"}
MOTION_CODES = {0, 1, 2, 3, 6, 32, 33, 34, 35}  # as crates/core/src/restart.rs has them
ONE_SHOT_G53 = {"fanuc", "haas", "linuxcnc", "sinumerik"}  # G53 acts in its block only


class RestartRefused(TapegateError):
    """A restart that cannot be made safely here: the reason, at the restart block's line."""

    default_code = "restart-refused"


@dataclass
class RestartPlan:
    line: int  # the restart block's line
    state: ModalState  # in force before the restart block
    preamble: list[str]
    first_block: str | None = None  # the restart block as sent, with its inherited motion code
    clearance: Decimal | None = None  # the height (lathe: the Z) the rapids keep to
    restored: set[str] = field(default_factory=set)  # the axes the approach brings back
    # what the operator must know: the units, how the approach was chosen
    notes: list[str] = field(default_factory=list)


@dataclass
class _Lost:
    """Why an axis's position is not a plain value in the program's coordinates."""

    kind: str  # "machine": sent to a reference point or a machine position; "unknown"
    line: int
    what: str
    replay: tuple[str, str] = ("", "")  # for "machine": the codes and the word that send it
    # there again (``("G91 G28", "Z0")``)
    # lost to a canned cycle that moved an axis (the core says so, not the reason's wording):
    # the tool is at the cycle's return level
    cycle: bool = False


class RestartWalk:
    """The program read block by block (:meth:`step`, or whole chunks of text with
    :meth:`walk_lines`) by the core: the checker's modal state, and beside it what a preamble
    needs (``crates/core/src/restart.rs``); :meth:`plan` gives the restart at the next block."""

    def __init__(self, profile: Profile, file: str = "<input>") -> None:
        self.profile = profile
        self.file = file
        self.family = profile.dialect.family
        self.lathe = profile.control_type == "lathe"
        self.machine = machine(profile)
        self.fanuc_lathe = self.machine.fanuc_lathe
        # an Okuma lathe: G50 S the clamp, U W the increments of X Z (OSP-P200L 5238-E), and
        # G80 the end of a LAP contour definition, no cycle cancel
        self.okuma_lathe = self.lathe and self.family == "okuma"
        self.g50_lathe = self.fanuc_lathe or self.okuma_lathe
        self._core = _core.RestartWalk(self.machine)
        self.last_facts: _Facts | None = None  # of the last plan

    @property
    def state(self) -> ModalState:
        return ModalState(**self._core.state)

    def plan(self, block: Block) -> RestartPlan:
        """The restart at ``block``, the next block to step (:class:`RestartRefused` if it
        cannot be made safely)."""
        if self._core.not_read(block.line, block.text):
            raise RestartRefused(
                f"cannot restart here: the control never reads line {block.line}, which "
                "stands after the program's end (LinuxCNC stops at its M2/M30 or closing %)",
                file=self.file, line=block.line, code="restart-not-read")
        self.last_facts = _Facts.of(self._core.facts())
        return _Planner(self, self.last_facts, block, self.file).plan()

    def part_end(self, text: str, before: int) -> Ending:
        """How the program goes on from the line after ``before`` (``text``, the rest of the
        file from the restart block): ``("returns", line, text)``, ``("ends", ...)`` or None.
        The walk is spent after it."""
        found: Ending = self._core.part_end(text[:-1] if text.endswith("\n") else text,
                                           before, self.profile.dialect.flags)
        return found

    def step(self, block: Block) -> None:
        """Read ``block`` (after :meth:`plan`, if the restart is to be at it)."""
        self._core.step(block)

    def walk_lines(self, text: str, before: int, until: int) -> int | None:
        """Read the whole lines of ``text`` (each ending with LF), which follow line
        ``before``, up to line ``until``, not read: how many lines of ``text`` were read
        before it, or None if ``text`` ends first. A line that cannot be read is left out."""
        read: int | None = self._core.walk_lines(text[:-1], before,
                                                  self.profile.dialect.flags, until)
        return read


def _why(reason: tuple[Any, ...], axis: bool) -> str:
    """The core's reason as the message says it."""
    if reason[0] == "text":
        return str(reason[1])
    _, text, line = reason
    if axis:
        return f"{text!r}, which the modal state does not follow"
    return f"after {text!r} on line {line}, which the modal state does not follow"


@dataclass
class _Facts:
    """What the walk knows at the restart block beyond the modal state."""

    flow: tuple[int, str, str] | None  # the first jump, loop or call: (line, text, kind)
    unrestored: dict[str, tuple[int, str]]  # mode -> (line, what)
    lost: dict[str, _Lost]  # axis -> why its position is not known
    unknown: dict[str, str]  # letter -> why its value in force is not known
    seen: set[str]  # the axes that have had a position
    t_token: str | None  # the last T word: the tool selected
    spindle_t: str | None  # the T in force at the last M06
    m6: str | None  # how the program writes M06
    h: str | None  # the H of the length offset in force
    g43_line: int
    d_token: str | None
    work: int | None  # the last G54-G59
    arc_absolute: bool  # G90.1 (LinuxCNC, Haas): arc centres absolute
    comp_line: int
    cycle: tuple[int, int] | None  # (code, line) of a canned cycle in force
    high: dict[str, Decimal]  # the highest value of the retract axes, in mm
    too_long: int | None  # a height too long to compare in mm: the highest point unknown
    refused: int | None  # the first line with a word the control refuses: it alarms there
    # the first block with two codes of one modal group (TG304) and the check's message
    conflict: tuple[int, str] | None
    # the units each axis's position and the feed were last written in, and where: a value
    # in force from before a change of units is the same place or speed in other units
    written: dict[str, tuple[str, int]]
    # the motion mode in force after the last block that wrote Z, and its line: how the
    # height the tool is at was reached (a rapid or a feed)
    z_reached: tuple[int | None, int] | None
    # where a lathe's cycle left the tool: its start point, where the modal state reads the
    # cycle's words as the place reached
    held: dict[str, Decimal]
    contour_next: tuple[int, int, int, int] | None  # a G71-G73's (P, Q, code, line) just read
    thread: int | None  # the line of the block before, when it cut a thread
    okuma_work: tuple[str | None, int] | None  # an Okuma mill's G15 H: (H word, line)
    okuma_length: tuple[int, str | None, int] | None  # its G56 H: (code, H word, line)
    cycle_r: int | None  # the line of a lathe single cycle's R (taper) in force
    units_line: int | None  # the program's own last units code
    program: int  # which program of the file (0: the first)
    program_name: str | None  # its O word or %_N_..._SPF header
    m6_line: int  # the last M06's line (0: none)
    coolant: list[int]  # M07/M08 on, in the order they came
    # a lathe's last moves of the tool in use, the last first: ((X from, Z from, X to, Z to),
    # motion, line, whether it is the tool's first move: from where the previous tool left it)
    moves: list[tuple[tuple[Decimal | None, ...], int | None, int, bool]]
    tool_change: int | None  # the line of a lathe's last tool change (T word, M06)
    tool_moved: bool  # whether X or Z moved since it
    # the largest X (mm) the tool in use went to, and the ranges of Z (mm) it moved along there
    lane: tuple[Decimal, list[tuple[Decimal, Decimal]]] | None
    diameter_mode: tuple[int, int] | None  # LinuxCNC's G7/G8 as the program selected it, line
    diameter_switch: int | None  # a G7/G8 that changed the mode after X had a position
    diameter_rewritten: tuple[int, int] | None  # that switch, and the line X was written again
    # per machine mode switched on (a Haas lathe's live tool, C axis): where to restart instead
    mode_hints: dict[str, str]
    live_modes: bool  # the profile names its live tool and C axis codes (haas-lathe)
    oriented: tuple[int, int] | None  # the spindle orientation in force (M19): (line, code)
    oriented_since: int | None  # the first M19 of that orientation (a second one ends none)
    # a lathe's last C or Y move since the main spindle last started: (line, axis)
    side_move: tuple[int, str] | None
    # a lathe's last M code the profile's list lacks since the tool change: (line, code)
    builder_m: tuple[int, int] | None
    spin_line: int  # the last M03/M04's line (0: none), or of a keyed start (M13)
    # the keyed start other than M03/M04 in force (``spindle-cw-coolant-on``): (line, code)
    turned_by: tuple[int, int] | None
    # the keyed start with the coolant (``spindle-cw-coolant-on``) whose coolant is on: no
    # M09, mill M06 or program end since (line, code)
    keyed_coolant: tuple[int, int] | None
    # the codes of the spindle's group the walk does not read (an unkeyed M13), run while no
    # code it reads has come since: (the first one's line, the last one's line, its code)
    unread_spin: tuple[int, int, int] | None
    builder_first: int  # the first line of builder_m's run (since the spindle or an M06)
    # a SINUMERIK's spindle functions by extension or position (M1=3, SPOS=90) since the last
    # plain M3-M5: (the first one's line, the last one's line, its text)
    spindle_by_extension: tuple[int, int, str] | None
    coolant_line: int  # the last M07/M08's line (0: none)
    unset: set[str]  # the axes whose number is no place to go to (a Haas lathe's Y after G113)

    @classmethod
    def of(cls, facts: dict[str, Any]) -> _Facts:
        lost = {axis: _Lost(kind, line, _why(what, axis=True), replay, cycle)
                for axis, (kind, line, what, replay, cycle) in facts["lost"].items()}
        return cls(
            flow=facts["flow"],
            unrestored={key: (line, what) for key, line, what in facts["unrestored"]},
            lost=lost,
            unknown={letter: _why(why, axis=False) for letter, why in facts["unknown"].items()},
            seen=set(facts["seen"]),
            t_token=facts["t_token"], spindle_t=facts["spindle_t"], m6=facts["m6"],
            h=facts["h"], g43_line=facts["g43_line"], d_token=facts["d_token"],
            work=facts["work"], arc_absolute=facts["arc_absolute"],
            comp_line=facts["comp_line"], cycle=facts["cycle"], high=facts["high"],
            too_long=facts["too_long"], refused=facts["refused"],
            conflict=facts["conflict"], written=facts["written"],
            z_reached=facts["z_reached"],
            held=facts["held"],
            contour_next=facts["contour_next"], thread=facts["thread"],
            okuma_work=facts["okuma_work"], okuma_length=facts["okuma_length"],
            cycle_r=facts["cycle_r"], units_line=facts["units_line"],
            program=facts["program"], program_name=facts["program_name"],
            m6_line=facts["m6_line"], coolant=list(facts["coolant"]),
            moves=[(tuple(ends), motion, at, first)
                   for ends, motion, at, first in facts["moves"]],
            tool_change=facts["tool_change"], tool_moved=facts["tool_moved"],
            lane=(facts["lane"][0], list(facts["lane"][1])) if facts["lane"] else None,
            diameter_mode=facts["diameter_mode"], diameter_switch=facts["diameter_switch"],
            diameter_rewritten=facts["diameter_rewritten"],
            mode_hints=dict(facts["mode_hints"]), live_modes=facts["live_modes"],
            oriented=facts["oriented"], oriented_since=facts["oriented_since"],
            side_move=facts["side_move"],
            builder_m=facts["builder_m"], spin_line=facts["spin_line"],
            turned_by=facts["turned_by"], keyed_coolant=facts["keyed_coolant"],
            unread_spin=facts["unread_spin"], builder_first=facts["builder_first"],
            spindle_by_extension=facts["spindle_by_extension"],
            coolant_line=facts["coolant_line"],
            unset=set(facts["unset"]),
        )


def plan_restart(blocks: Iterable[Block], profile: Profile, line: int,
                 file: str = "<input>", *, walk: RestartWalk | None = None) -> RestartPlan:
    """The preamble for restarting at the block on ``line``, or :class:`RestartRefused`;
    ``walk``: one that has read the program before ``blocks``."""
    walk = walk or RestartWalk(profile, file)
    blocks = iter(blocks)
    return _plan_at(walk, blocks, line, file,
                    lambda block: partial(_ending_of_blocks, walk, chain([block], blocks)))


def plan_restart_text(chunks: Iterable[str], profile: Profile, line: int,
                      file: str = "<input>") -> RestartPlan:
    """:func:`plan_restart` of a program's text arriving in chunks, read by the core with no
    :class:`Block` made up to the restart line (a restart near the end of a long program is
    planned in a second, not in minutes)."""
    walk = RestartWalk(profile, file)
    pieces, first = _from_line(walk, whole_lines(chunks), line)
    rest = "".join(pieces)
    blocks = parse_stream([rest], profile.dialect, file=file, errors="collect", first_line=first)
    return _plan_at(walk, blocks, line, file, lambda block: partial(
        walk.part_end, rest[_line_start(rest, block.line - first - 1):], block.line - 1))


def _plan_at(walk: RestartWalk, blocks: Iterable[Block | BadBlock], line: int, file: str,
             ending_of: Callable[[Block], Callable[[], Ending]]) -> RestartPlan:
    """Step ``walk`` through ``blocks`` to the block on ``line`` or after it, and plan the
    restart there (``ending_of(block)``: what the plan reads of the program's end). A block
    the reader refused before ``line`` is stepped too: the control refuses it, and the restart
    after it."""
    for block in blocks:
        if isinstance(block, BadBlock):
            if block.line < line:
                walk.step(block)
            continue
        if block.line >= line:
            return _entered(walk, block, ending_of(block))
        walk.step(block)
    raise RestartRefused(f"no block on line {line} to restart at", file=file,
                         code="restart-no-block")


def _line_start(text: str, lines: int) -> int:
    """Where line ``lines`` + 1 of ``text`` begins (0 for the first)."""
    at = 0
    for _ in range(lines):
        at = text.index("\n", at) + 1
    return at


Ending = tuple[str, int, str] | None


def _ending_of_blocks(walk: RestartWalk, blocks: Iterable[Block]) -> Ending:
    """How the restart block's program ends, read block by block from it."""
    for block in blocks:
        found: Ending = walk._core.part_end_step(block)
        if found is not None:
            return None if found[0] == "other" else found
    return None


def _entered(walk: RestartWalk, block: Block, ending: Callable[[], Ending]) -> RestartPlan:
    """The plan at ``block``, unless its program is entered from a caller: a subprogram's or
    macro body's state at entry is its caller's (tool, spindle, length offset, position),
    which a walk of the file in its order does not have (``ending()``: how the program ends,
    read on from the block; the walk is spent after it)."""
    try:
        plan: RestartPlan | RestartRefused = walk.plan(block)
    except RestartRefused as exc:
        plan = exc
    facts = walk.last_facts
    name = (facts.program_name if facts is not None else None) or "the program"
    where = (f" ({_ordinal(facts.program)} program of the file)"
             if facts is not None and facts.program else "")
    spf = walk.family == "sinumerik" and (
        walk.file.upper().endswith(".SPF") or name.upper().endswith("_SPF"))
    found = ending()
    if spf or (found is not None and found[0] == "returns"):
        how = ("is a subprogram (SPF)" if spf else
               f"returns to a caller by {found[2]!r} on line {found[1]}")  # type: ignore[index]
        raise RestartRefused(
            f"cannot restart here: {name}{where} {how}: a subprogram or macro body (or a main "
            "program that loops back by M99) runs in the state its caller left, tool, spindle, "
            "length offset and position, which a preamble read from the program's own start "
            "does not have; restart the calling program at its call",
            file=walk.file, line=block.line)
    if isinstance(plan, RestartRefused):
        raise plan
    return plan


def _ordinal(n: int) -> str:
    """The place of program ``n`` (0: the first) in words."""
    return {1: "the second", 2: "the third"}.get(n, f"number {n + 1}")


def _from_line(walk: RestartWalk, pieces: Iterator[tuple[str, int, Iterator[str] | None]],
               line: int) -> tuple[Iterable[str], int]:
    """Walk the pieces up to ``line``: the text from there on, and how many lines precede it."""
    for text, before, unread in pieces:
        if unread is not None:  # the unfinished last line, or a block too long
            return chain([text], unread), before
        read = walk.walk_lines(text, before, line)
        if read is not None:
            at = 0
            for _ in range(read):  # (in characters, whatever the text holds)
                at = text.index("\n", at) + 1
            return chain([text[at:]], _texts(pieces)), before + read
    return (), 0  # (whole_lines always ends with its unfinished piece)


def _texts(pieces: Iterator[tuple[str, int, Iterator[str] | None]]) -> Iterator[str]:
    """The text of the pieces :func:`~formats.parser.whole_lines` has not yet given."""
    for text, _, unread in pieces:
        yield text
        if unread is not None:
            yield from unread


class _Planner:
    def __init__(self, walker: RestartWalk, facts: _Facts, block: Block, file: str) -> None:
        self.walker = walker
        self.walk = facts
        self.profile = walker.profile
        self.block = block
        self.file = file
        self.state = walker.state
        stopped = False  # by a mill's M06
        if walker.family in ("fanuc", "haas") and not walker.lathe and facts.m6_line:
            # a mill's M06 stops the spindle and the coolant (Haas mill manual, NGC, "M06 Tool
            # Change"; a FANUC's is the builder's macro, which does so on the machines at
            # hand): off until the program's own M03/M04, M07/M08 after it (review 36,
            # finding 1: a probe loaded by T20 M06 was spun at the last tool's S8000)
            if facts.spin_line < facts.m6_line:
                self.state = replace(self.state, spindle="stop")
                stopped = True
            if facts.coolant_line < facts.m6_line:
                self.state = replace(self.state, coolant="off")
        # a start the profile keys (a builder's M13, spindle and coolant, `meaning =
        # "spindle-cw-coolant-on"`): the modal state follows M03-M05 alone, the preamble
        # starts the spindle by the program's own code (review 56a F9)
        self.turn_code = (facts.turned_by[1] if facts.turned_by is not None and not stopped
                          else None)
        keyed = facts.keyed_coolant
        if (self.turn_code is None and keyed is not None and not stopped
                and self.keyed_meaning(keyed[1]) == f"spindle-{self.state.spindle}-coolant-on"):
            # its coolant still on and the spindle turning its way again by a plain M03/M04
            # (`M13` ... `M05` ... `M03`): the program's own code restores both (review 57a F3)
            self.turn_code = keyed[1]
        # a lathe's cycle returns to its start point: that is where the tool is
        self.state.position.update(facts.held)
        self.units = self.state.units
        # an Okuma machining centre: G15 H the work system, G54-G59 H the length offsets
        self.okuma_mill = walker.family == "okuma" and not walker.lathe
        self.clearance_value: Decimal | None = None
        self.notes: list[str] = []
        self.stale_feed = False  # the F in force is in other units, the block gives its own

    def refuse(self, reason: str) -> RestartRefused:
        return RestartRefused(f"cannot restart here: {reason}",
                              file=self.file, line=self.block.line)

    # -- writing words -----------------------------------------------------------------------

    def word(self, letter: str, value: Decimal) -> str:
        """``letter`` and ``value`` in the profile's format (a value of the program, or a
        clearance already at its resolution)."""
        units = self.state.feed_units if letter in "FE" else self.units
        fmt = self.profile.word_format(letter, units)
        return letter + fmt.write(value, self.profile.explicit)

    def units_code(self) -> str:
        """The code that selects the units of lengths and of the feed in force: on Sinumerik,
        G700/G710 where the feed is not in the basic system (G70/G71 leave it there)."""
        s, profile = self.state, self.profile
        if profile.dialect.family == "sinumerik" and s.feed_units != profile.default_units:
            return "G700" if s.feed_units == "inch" else "G710"
        return profile.inch_code if s.units == "inch" else profile.metric_code

    def usable(self, g: int) -> bool:
        code = self.profile.code("G", g)
        return code is not None and code.usable

    def listed(self, g: int) -> bool:
        """A code the profile's own code list has, where it has one: a code it leaves to ISO
        6983's table may not exist on the control (an Okuma or Haas machining centre has no
        G97: their spindle speed is always in rpm)."""
        if any(key.startswith("G") for key in self.profile.extra_codes):
            return f"G{g:02d}" in self.profile.extra_codes and self.usable(g)
        return self.usable(g)

    # -- what must be known --------------------------------------------------------------------

    def check(self) -> None:
        walk, s = self.walk, self.state
        if s.ended and (self.block.text.strip() == "%" or "\x1a" in self.block.text):
            # the end of tape after M02/M30 (review 36: "would not restore tool (please report
            # this program)" at the closing %): nothing of the program comes after it
            raise self.refuse("the program has ended before this line (M02 or M30): there is "
                              "nothing after it to run; restart at a block before the end")
        if self.walker.family == "heidenhain":
            raise self.refuse("tapegate writes no restart preamble for a HEIDENHAIN control "
                              "(its G codes differ: G28 is a mirror image, G53 a datum shift); "
                              "use the control's own mid-program start-up")
        if self.walker.profile.g_code_system in ("B", "C"):
            system = self.walker.profile.g_code_system
            raise self.refuse(f"tapegate writes no restart preamble for a FANUC lathe of G code "
                              f"system {system} (the preamble is written in system A's codes: "
                              "G98/G99 feed, G50 clamp); use the control's own mid-program "
                              "start-up")
        if walk.flow is not None:
            at, text, kind = walk.flow
            what = {"flow": "a jump, loop or condition", "call": "a call",
                    "definition": "a subprogram definition",
                    "command": "a control instruction",
                    "code": "a G code the control's list does not hold: an alarm, or a macro "
                            "call its parameters name",
                    "parameter code": "a G or M code set by a parameter: which code ran is not "
                                      "known"}.get(kind, kind)
            raise self.refuse(f"after {text!r} on line {at} ({what}) the modal state is not "
                              "known: tapegate reads the program in file order and does not "
                              "follow jumps, loops, calls or control instructions")
        if walk.refused is not None:
            raise self.refuse(f"line {walk.refused} holds a word the control refuses (a reading "
                              "error, or a line tapegate cannot read that it takes as never "
                              "run, TG108: see tapegate check): the control alarms there, no "
                              "block after it has run, and what the word sets (a position, the "
                              "highest point the tool went to) is not known")
        if walk.conflict is not None:
            at, message = walk.conflict
            raise self.refuse(f"line {at} holds two codes of one modal group ({message}, TG304 "
                              "or TG308: see tapegate check): which of them the control takes, or "
                              "whether it alarms there, tapegate does not know, so the modal "
                              "state after that block is not known either; write one code of "
                              "the group in the block")
        if walk.too_long is not None:
            raise self.refuse(f"the height written on line {walk.too_long} has too many digits "
                              "to be compared in mm: the highest point the tool went to is not "
                              "known")
        if walk.unrestored:
            key, (at, what) = min(walk.unrestored.items(), key=lambda item: item[1])
            hint = walk.mode_hints.get(key)
            raise self.refuse(f"{what} from line {at} is in force and the preamble cannot "
                              "restore it" + (f"; {hint}" if hint else ""))
        if walk.oriented is not None:
            # M19 "adjusts the spindle to a fixed position" (Haas mill manual, "M19 Orient
            # Spindle"): stopped, at an angle, until M03/M04/M05 (review 35, finding 1)
            # (review 38, finding 5) a second M19 does not end the first's orientation: the
            # hint is the first's line, where a restart is not refused for either
            at, code = walk.oriented
            first_m19 = walk.oriented_since or at
            earlier = (f" (the spindle oriented since line {first_m19})" if first_m19 != at
                       else "")
            listed = self.profile.code("M", code)
            if listed is not None and listed.meaning == "spindle-to-axis-mode":
                # (840D sl Function Manual S1: M70 switches the spindle to axis mode, position
                # control, its C moved as an axis; M3 M4 M5 back to speed control)
                raise self.refuse(
                    f"M{code:02d} on line {at} switched the spindle to axis mode (position "
                    "control, moved as a rotary axis) and no M03, M04 or M05 has come since: "
                    "the preamble would start it turning, and the program's moves of that axis "
                    f"meet a turning spindle or alarm; restart at or before line {at}, or after "
                    "the M03 or M04 that starts the spindle again")
            raise self.refuse(f"M{code:02d} on line {at} oriented the spindle (stopped at a fixed "
                              f"angle){earlier} and no M03, M04 or M05 has come since: the "
                              "preamble would start it with the spindle mode of before, or "
                              "leave it at another angle (a bar shifted through a bore, a "
                              f"static tool fed); restart at or before line {first_m19}, or after "
                              "the M03 or M04 that starts the spindle again")
        if walk.spindle_by_extension is not None:
            # (review 56d F6, F11) M0=3 or M1=3 started the spindle, M1=70 switched it to
            # axis mode, SPOS=90 positioned it: the modal state reads the plain M3-M5 alone
            first, at, text = walk.spindle_by_extension
            raise self.refuse(
                f"{text} on line {at} commands a spindle by its address extension or "
                "position (SINUMERIK M<n>=, SPOS, SPOSA; Function Manual S1), which the "
                "restart's modal state does not follow (it reads the plain M3, M4 and M5): "
                "the preamble would leave the spindle stopped where the program turns it, or "
                "start it where the program holds it in position or axis mode; restart at or "
                f"before line {first}, or after a plain M3, M4 or M5 of the master spindle")
        self.check_unread_spindle()
        self.check_live_tool()
        self.check_builder_start()
        self.check_keyed_coolant()
        if s.compensation in (41, 42):
            raise self.refuse(f"inside cutter compensation G{s.compensation} (from line "
                              f"{walk.comp_line}); restart at a block after the G40 that "
                              "ends it")
        if walk.cycle is not None or s.cycle is not None:
            code, at = walk.cycle or (s.cycle or 0, 0)
            since = f" from line {at}" if at else ""
            raise self.refuse(f"inside the canned cycle G{code}{since}; restart at a block "
                              "after the G80 that ends it")
        if s.feed_mode == 93:
            raise self.refuse("inverse time feed (G93) is in force: there is no feed per "
                              "minute for the approach")
        if walk.diameter_switch is not None:
            raise self.refuse(f"the G{walk.diameter_mode[0] if walk.diameter_mode else 7} on "
                              f"line {walk.diameter_switch} changed between diameter (G7) and "
                              "radius (G8) mode after X had a position: the X in force and the "
                              "largest X the program went to were written in the other mode, "
                              "which the walk does not convert")
        for letter, (units, at) in sorted(walk.written.items()):
            now = s.feed_units if letter == "F" else s.units
            if letter == "F" and units != now and self.own_feed() is not None:
                # the block sets its own feed: the approach feeds at it, and the stale F in
                # force is neither used nor written again
                self.stale_feed = True
                continue
            if units != now and (letter == "F" or letter in s.position):
                what = "feed" if letter == "F" else f"position of {letter}"
                was, now = _UNIT_NAMES[units], _UNIT_NAMES[now]
                raise self.refuse(f"the {what} in force was written in {was} (line {at}) and "
                                  f"the program works in {now} here: the control keeps it as "
                                  "the same place or speed, which the modal state does not "
                                  f"convert; restart at a block after one that writes {letter} "
                                  f"in {now}")
        needed = [("T", "tool"), ("F", "feed"), ("S", "spindle speed")]
        if not self.walker.lathe:  # a lathe's D is a cycle's depth of cut
            needed.append(("D", "radius offset"))
        if s.length_offset in (43, 44):
            needed.append(("H", "length offset"))
        for letter, name in needed:
            if letter in walk.unknown:
                raise self.refuse(f"the {name} in force is not known: "
                                  f"{walk.unknown[letter]}")
        if self.okuma_mill:
            for name, fact in (("work coordinate system G15", walk.okuma_work),
                               ("tool length offset", walk.okuma_length)):
                if fact is not None and fact[-2] is None:
                    raise self.refuse(f"the {name} on line {fact[-1]} has no plain H: the "
                                      "offset to restore is not known")
        self.check_cycles()
        if s.length_offset in (43, 44) and walk.h is None and not self.loaded_tool_length():
            raise self.refuse(f"G{s.length_offset} on line {walk.g43_line} has no H: the "
                              "length offset to restore is not known")
        if (walk.units_line is None and self.profile.units_by_code and walk.program
                and self.profile.units_kept_at_end):  # (else it starts in the reset units)
            name = walk.program_name or "the program"
            raise self.refuse(
                f"{name} follows another program in the file and selects no units before this "
                "block: it runs in the units the control is in when it starts, which the "
                "program before it may have set; tapegate cannot tell them (convert calls them "
                f"ambiguous); restart at a block after the program's own "
                f"{self.profile.inch_code}/{self.profile.metric_code}")

    def check_live_tool(self) -> None:
        """A lathe whose profile names no live tool or C axis codes (every one but haas-lathe):
        on a FANUC lathe those modes are the machine builder's M codes (TG307), which the walk
        cannot name and the preamble cannot restore (review 35, finding 2)."""
        walk, s = self.walk, self.state
        if not self.walker.lathe or walk.live_modes:
            return
        change = walk.tool_change
        starts = self.block_starts_spindle()
        if walk.side_move is not None and not starts:
            # (a restart block that starts the main spindle itself is where the message sends
            # the operator: review 36, finding 5)
            at, axis = walk.side_move
            raise self.refuse(
                f"the program moved {axis} on line {at} and has not started the main spindle "
                "(M03, M04) since: the work of a live tool at an angle of C (or at a Y), whose "
                "drive and C axis (Cs) mode this control switches by the machine builder's M "
                "codes (TG307), which the preamble cannot restore (only haas-lathe's and "
                "okuma-lathe's are known); restart at a block before the program switches them "
                "on, or after the M03 or M04 that starts the main spindle again")
        carried = (s.spindle in ("cw", "ccw") and change is not None
                   and walk.spin_line < change)
        if walk.builder_m is not None and carried and not starts:
            # the spindle turns as a tool before this one started it, and a code the list
            # lacks came after the change (a FANUC lathe's builder M19 orients it for a
            # static tool, review 35): the preamble's M03 would turn what the program holds
            at, code = walk.builder_m
            raise self.refuse(
                f"M{code:02d} on line {at}, an M code the profile's list lacks, came after the "
                f"tool change on line {change}, and the main spindle has not been started "
                f"since (its M03/M04 is on line {walk.spin_line}): the builder's code may have "
                "stopped or oriented it (a spindle orientation, a live tool), which the "
                "preamble cannot know; restart at or before the tool change (line "
                f"{change}), or after the M03 or M04 that starts the main spindle again")
        if walk.builder_m is not None and s.spindle == "stop" and not starts:
            # (a restart block that starts the main spindle itself turns, as the program does)
            at, code = walk.builder_m
            since = f"the tool change on line {change}" if change is not None else "the start"
            where = f"the tool change (line {change})" if change is not None else f"line {at}"
            if change is not None and at < change:
                # given before the T word with the spindle stopped, or by a live tool before
                # this one: the mode stays in force over the change (review 36, finding 2)
                since = (f"the main spindle stopped, and stays in force over the tool change "
                         f"on line {change}")
                where = f"line {at}"
            raise self.refuse(
                f"the main spindle is stopped and M{code:02d} on line {at}, an M code the "
                f"profile's list lacks, came after {since}: a live tool's drive or the C axis "
                "(Cs) mode, which this control switches by the machine builder's M codes "
                "(TG307), the preamble cannot restore; restart at or before "
                f"{where}, or after the M03 or M04 that starts the main spindle")

    def tool_change_stops(self) -> bool:
        """Whether an M06 stops the spindle (a FANUC or Haas mill: Haas mill manual, NGC, "M06
        Tool Change"; a FANUC's is the builder's macro, which does so on the machines at
        hand)."""
        return self.walker.family in ("fanuc", "haas") and not self.walker.lathe

    def block_changes_tool(self) -> bool:
        """Whether the restart block has an M06 of its own."""
        return any(w.letter == "M" and w.number and w.number.isdigit() and int(w.number) == 6
                   for w in self.block.word_objects())

    def check_unread_spindle(self) -> None:
        """A code of the spindle's modal group that the walk does not read (a builder's M13
        listed without a meaning key, LinuxCNC's M19), run after the last spindle state it
        knows: it may have started, stopped or oriented the spindle, so the preamble's M03,
        M04 or M05 of the modal state would restore another state (review 56d F9). A tool
        change that stops the spindle after it, or the restart block's own M03, M04 or M06,
        sets the state again."""
        walk = self.walk
        if walk.unread_spin is None or self.block_starts_spindle():
            return
        first, at, code = walk.unread_spin
        if self.tool_change_stops() and (walk.m6_line > at or self.block_changes_tool()):
            return
        listed = self.profile.code("M", code)
        function = f" ({listed.function})" if listed is not None else ""
        raise self.refuse(
            f"M{code:02d}{function} on line {at} is a code of the spindle's modal group with "
            "no meaning the restart reads, and no M03, M04 or M05 has come since: what it did "
            "to the spindle (a builder's M13 starts it with the coolant, an M19 orients it) "
            f"the preamble cannot know or restore; restart at or before line {first}, or "
            "after the M03, M04 or M05 that sets the spindle again (or key the code in the "
            "profile: meaning = \"spindle-cw-coolant-on\", docs/profiles.md)")

    def keyed_coolant_off(self) -> bool:
        """Whether the spindle's keyed start that the preamble writes (a builder's M13,
        ``meaning = "spindle-cw-coolant-on"``) also turns on a coolant that the program had
        turned off again by M09 before the restart block (review 56d F1): the preamble then
        writes M09 after it."""
        code = self.turn_code
        return (code is not None and self.starts_coolant(code)
                and self.walk.keyed_coolant is None)

    def starts_coolant(self, m: int) -> bool:
        """Whether the profile keys M code ``m`` as a spindle start with the coolant
        (``spindle-cw-coolant-on``, ``spindle-ccw-coolant-on``)."""
        meaning = self.keyed_meaning(m)
        return meaning.startswith("spindle-") and meaning.endswith("-coolant-on")

    def keyed_meaning(self, m: int) -> str:
        """The meaning key the profile gives M code ``m`` ("" where it lists none)."""
        listed = self.profile.code("M", m)
        return listed.meaning if listed is not None else ""

    def check_keyed_coolant(self) -> None:
        """The coolant a keyed start with the coolant turned on (M13, M14) is on, but the
        spindle is no longer turned by that code (an M05 or M03 came since, and no M09): no
        code the preamble may write turns that coolant on alone (the code starts the spindle
        too, and which coolant M08 runs is the builder's), so refuse, unless the restart
        block sets the coolant itself (its own M09, the code again, or a mill's M06)."""
        keyed = self.walk.keyed_coolant
        if keyed is None or keyed[1] == self.turn_code:
            return
        own = {int(w.number) for w in self.block.word_objects()
               if w.letter == "M" and w.number and w.number.isdigit()}
        if (9 in own or any(self.starts_coolant(m) for m in own)
                or (self.tool_change_stops() and 6 in own)):
            return
        at, code = keyed
        raise self.refuse(
            f"M{code:02d} on line {at} turned the spindle and the coolant on, and the spindle "
            "has been stopped or started by another code since, with no M09: that coolant is "
            f"still on, and the preamble cannot turn it on without M{code:02d} starting the "
            f"spindle too; restart at or before line {at}, or after the M09 that ends the "
            "coolant")

    def check_builder_start(self) -> None:
        """A FANUC or Haas mill whose spindle is stopped (by M05, or by the M06 of a tool
        change) where an M code the profile's list lacks came after: a builder's M13 starts the
        spindle with the coolant, a code the preamble cannot know, so the program's cut would
        meet the work with the spindle stopped (review 56a F9). A profile that keys such a code
        (``meaning = "spindle-cw-coolant-on"``) has it restored instead."""
        walk = self.walk
        if (self.walker.lathe or walk.builder_m is None or self.state.spindle != "stop"
                or self.turn_code is not None):
            return
        at, code = walk.builder_m
        # (review 56d F7) the restart block's own M06 stops the spindle again
        if (at < (walk.m6_line or 0) or self.block_starts_spindle()
                or (self.tool_change_stops() and self.block_changes_tool())):
            return
        first = walk.builder_first or at
        raise self.refuse(
            f"the spindle is stopped and M{code:02d} on line {at}, an M code the profile's list "
            "lacks, came after: it may start the spindle (a builder's M13: spindle and coolant), "
            "which the preamble cannot know or restore; restart at or before line "
            f"{first}, at the next tool change, or after the M03 or M04 that starts the spindle "
            "(or key the code in the profile: meaning = \"spindle-cw-coolant-on\", "
            "docs/profiles.md)")

    def loaded_tool_length(self) -> bool:
        """LinuxCNC's G43 without H applies the length of the tool in the spindle (rs274ngc
        interp_convert.cc, convert_tool_length_offset: no H word, the current tool's): the
        preamble's own tool change loads that tool again, so ``G43`` restores it, where the
        G43 came after the last M06 (or the program changes no tool)."""
        walk, s = self.walk, self.state
        return (self.walker.family == "linuxcnc" and s.length_offset == 43
                and (walk.m6_line == 0 or walk.g43_line > walk.m6_line))

    def own_units(self) -> bool:
        """Whether the program selected its units before the restart block: otherwise the
        control's setting decides (Haas Setting 9, FANUC's G20/G21 kept), and the preamble
        writes no units code."""
        return self.walk.units_line is not None

    def check_cycles(self) -> None:
        """A lathe contour's first block, the second block of a two-block cycle (its first
        block's data), and a thread continued from the block before."""
        walk, block = self.walk, self.block
        n = next((w.number for w in block.word_objects() if w.letter == "N"), None)
        if walk.contour_next is not None and n is not None and n.isdigit():
            p, q, code, at = walk.contour_next
            if int(n) == p:
                raise self.refuse(f"the contour N{p} to N{q} of the cycle G{code} from line "
                                  f"{at} is the cycle's data, no moves; restart at the cycle "
                                  "or after its contour")
        data = self.walker._core.cycle_first_block(block)
        if data is not None:
            code, first = data
            raise self.refuse(f"the cycle G{code} runs with the data of its first block on line "
                              f"{first} (depth of cut, retract, passes or thread data, which "
                              "the control keeps as parameters): a restart here leaves that "
                              "block out and the cycle runs with whatever values are stored; "
                              f"restart at line {first}")
        motion = self.motion_of(block)
        if motion is None and any(w.letter in AXES and w.number for w in block.word_objects()):
            motion = self.state.motion
        if walk.thread is not None and motion is not None and self.thread_code(motion):
            raise self.refuse(f"the block continues the thread cut on line {walk.thread}: a "
                              "thread cannot be entered mid-way (the spindle's angle is lost); "
                              "restart at the thread's first block")

    def thread_code(self, g: int) -> bool:
        """G32-G35 cut a thread, except on an Okuma lathe, where G31-G35 are cycles."""
        return 32 <= g <= 35 and not self.walker.okuma_lathe

    # -- the preamble -------------------------------------------------------------------------

    def plan(self) -> RestartPlan:
        self.check()
        walk, s = self.walk, self.state
        out: list[str] = []
        # 1. modes
        units = self.units_code()  # none where the machine's parameter sets the units
        if units and not self.own_units():
            units = ""
            self.notes.append(
                f"no units code: the program selects none before line {self.block.line}, so "
                "the control's setting applies, as in a run from the start "
                f"(tapegate read it as {_UNIT_NAMES[s.units]})")
        modes = ([units] if units else []) + [f"G{s.plane}"]
        if not self.walker.fanuc_lathe:
            modes.append("G90")
        if self.walker.fanuc_lathe:
            modes.append("G99" if s.feed_mode == 95 else "G98")
        else:
            modes.append(f"G{s.feed_mode}")
        modes += [f"G{g}" for g in (40, 49, 80) if self.usable(g)
                  and not (g == 49 and self.walker.lathe)
                  and not (g == 80 and self.walker.okuma_lathe)]
        work = walk.work if self.walker.family in ONE_SHOT_G53 else s.zero_shift
        if work is None:
            work = s.zero_shift
        if self.okuma_mill:  # G54-G59 are length offsets there, restored in the approach
            if walk.okuma_work is not None:
                modes.append(f"G15 {walk.okuma_work[0]}")
        elif work is not None:
            modes.append(f"G{work}")
        if walk.arc_absolute:
            modes.append("G90.1")
        if walk.diameter_mode is not None:
            modes.append(f"G{walk.diameter_mode[0]}")  # LinuxCNC's diameter/radius mode
        out.append(" ".join(modes))
        # 2. tool
        if walk.spindle_t is not None and walk.m6 is not None:
            out.append(f"{walk.spindle_t} {walk.m6}")
        selected = [t for t in (walk.t_token,) if t is not None and (
            walk.m6 is None or walk.spindle_t is None
            or self.profile.value(t, s.units) != self.profile.value(walk.spindle_t, s.units))]
        if walk.d_token is not None and s.offset is not None and not self.walker.lathe:
            selected.append(walk.d_token)
        if selected:
            out.append(" ".join(selected))
        # 3. spindle and coolant
        if s.speed_limit is not None:
            # the code the modal state read it from (ModalSettings::s_limit): a SINUMERIK's
            # G26 S in its own language (review 38, finding 1)
            clamp = ("G50" if self.walker.g50_lathe
                     else "G26" if self.profile.dialect.family == "sinumerik" else "G92")
            out.append(f"{clamp} {self.word('S', s.speed_limit)}")
        spindle = []
        if s.speed is not None:
            if s.spindle_mode == 96 or self.listed(97):
                spindle.append(f"G{s.spindle_mode}")
            spindle.append(self.word("S", s.speed))
        if self.turn_code is not None:
            spindle.append(f"M{self.turn_code:02d}")
        elif s.spindle != "stop":
            spindle.append("M03" if s.spindle == "cw" else "M04")
        if spindle:
            out.append(" ".join(spindle))
        if self.keyed_coolant_off():
            # the program's own M09 turned off the coolant its M13 turned on: the preamble
            # runs the two in the program's order, each in its own block (a FANUC hands every
            # M code but M00-M02, M30, M98 and M99 to the builder's ladder, which decides what
            # two in one block do), so the cut restarts with the coolant as the program had
            # it (review 56d F1), and a coolant code in force after that M09 follows
            out.append("M09")
        if s.coolant != "off":
            codes = [f"M{m:02d}" for m in walk.coolant]
            if len(codes) > 1 and self.mist_and_flood():
                out += codes  # both on, the one in force last; one M code of the group a block
            else:
                out.append("M07" if s.coolant == "mist" else "M08")
        # 4. the approach
        restored = self.approach(out)
        if s.incremental:
            out.append("G91")
        return self.finish(out, restored)

    def mist_and_flood(self) -> bool:
        """Whether M07 and M08 are on at once: LinuxCNC's (rs274: MIST_ON and FLOOD_ON, off
        together by M9), or a profile whose M07 and M08 last apart (an Okuma's oil mist and
        coolant pump, each ended by M09)."""
        if self.walker.family == "linuxcnc":
            return True
        m7, m8 = self.profile.extra_codes.get("M07"), self.profile.extra_codes.get("M08")
        lasts = [getattr(c, "duration", None) for c in (m7, m8)]
        return None not in lasts and lasts[0] != lasts[1]

    def where(self, axis: str) -> tuple[str, Decimal | _Lost | None]:
        lost = self.walk.lost.get(axis)
        if lost is not None:
            return lost.kind, lost
        if axis in self.walk.unset:  # no place to go to: not positioned
            return "unset", None
        value = self.state.position.get(axis)
        if value is None and axis in self.walk.seen:
            return "unknown", _Lost("unknown", self.block.line, "the modal state has lost it")
        return ("known", value) if value is not None else ("unset", None)

    def clearance(self, axis: str, start: Decimal) -> Decimal:
        setting = self.profile.restart
        key = "clearance_x" if axis == "X" and self.walker.lathe else "clearance"
        given = getattr(setting, key)
        if given is not None:
            if not isinstance(given, Decimal) or not given.is_finite():
                # NaN would compare false with every height and pass for a safe one (review
                # 14, 5); the profile file and send --clearance refuse it before this
                raise self.refuse(f"the profile's [restart] {key} is {given!r}, not a finite "
                                  "Decimal: no height to approach at")
            if self.profile.default_units != self.units:
                given = given / INCH if self.units == "inch" else given * INCH
            fmt = self.profile.word_format(axis, self.units)  # rounded away from the part
            rounded = (given.quantize(fmt.resolution, rounding=ROUND_CEILING)
                       if fmt.holds(given) else None)
            if rounded is None or not fmt.holds(rounded):
                raise self.refuse(f"the clearance {axis}{given} ({self.units}) has more digits "
                                  f"than the profile's {fmt.spec()} holds: it cannot be sent")
            given = max(rounded, start)
            self.within_travel(axis, key, given, start)
            if self.own_units():
                return given
            # the units are the control's: the profile's clearance may be read in the other
            # ones, the program's own highest point is the same number in either
            return max(given, self.highest(axis, start))
        return self.highest(axis, start)

    def within_travel(self, axis: str, key: str, clear: Decimal, start: Decimal) -> None:
        """Refuse a given clearance whose approach down to the start point is longer than the
        machine's travel of ``axis`` in the profile (``[limits]``): both are the program's
        coordinates, one work offset and one tool length apart from the machine's, so no
        offset puts both on the machine (review 15, 6: `--clearance 500` on an inch Haas
        whose Z travels 40 in, from Z-0.1, was sent as `G00 Z500.`). The fact TG601 checks a
        program's span by; a lathe's X clearance is a diameter, not compared."""
        travel = self.profile.limits.axes.get(axis)
        if travel is None or key != "clearance" or clear <= start:
            return
        low, high = travel
        length = high - low
        units = self.profile.limit_units or self.profile.default_units
        if units != self.units:
            length = length / INCH if self.units == "inch" else length * INCH
        if clear - start > length:
            unit = {"metric": "mm", "inch": "in"}
            raise self.refuse(
                f"the clearance {self.word(axis, clear)} is {(clear - start).normalize():f} "
                f"{unit[self.units]} above the start point {self.word(axis, start)}, more than "
                f"the machine's {axis} travel ({low} to {high} {unit[units]}): no work offset "
                f"puts both on the machine; give a clearance within it (send --clearance, or "
                f"the profile's [restart] clearance)")

    def highest(self, axis: str, start: Decimal) -> Decimal:
        """The highest ``axis`` the program went to, in its units (at least ``start``)."""
        high = self.walk.high.get(axis)
        if high is None:
            return start
        if self.units == "inch":  # from mm, rounded up: never below the highest point
            fmt = self.profile.word_format(axis, self.units)
            try:
                high = (high / INCH).quantize(fmt.resolution, rounding=ROUND_CEILING)
            except InvalidOperation:  # more digits than the context holds: no height to write
                raise self.refuse(f"the highest {axis} the program went to ({high} mm) has too "
                                  f"many digits to be written in inch as a clearance") from None
        return max(high, start)

    def approach(self, out: list[str]) -> set[str]:
        # on a Fanuc or Haas lathe U and W are X and Z incremental, not axes of their own;
        # a lathe's C is the main spindle in position mode, which has no place while the
        # spindle turns (M03/M04): not positioned then (review 34, finding 2: the approach
        # sent `G00 C30.` after `M03`, a C move with the spindle turning)
        turning = self.walker.lathe and (self.state.spindle in ("cw", "ccw")
                                         or self.block_starts_spindle())
        axes = [a for a in AXES if not (self.walker.g50_lathe and a in "UW")
                and not (turning and a == "C")]
        places = {axis: self.where(axis) for axis in axes}
        for axis, (kind, info) in places.items():
            if kind == "frame":
                assert isinstance(info, _Lost)
                places[axis] = ("known", self.own_target(axis, info))
            elif (kind == "unknown" and axis == "Z" and not self.walker.lathe
                  and isinstance(info, _Lost) and info.cycle):
                # after the cycle the tool is at its return level; a block that sets Z
                # itself goes from wherever that is to its own Z: the approach goes there
                target = self.block_target(axis)
                if target is not None:
                    self.state.position[axis] = target
                    places[axis] = ("known", target)
        for axis, (kind, info) in places.items():
            if kind == "unknown":
                assert isinstance(info, _Lost)
                raise self.refuse(f"the position of {axis} is not known here (line "
                                  f"{info.line}: {info.what})")
        # the reference-point and machine moves again: the retract axis first, on its own
        retract = "X" if self.walker.lathe else "Z"
        replays: dict[tuple[bool, int, str], list[str]] = {}
        for axis, (kind, info) in places.items():
            if kind == "machine":
                assert isinstance(info, _Lost)
                key = (axis != retract, info.line if axis != retract else 0, info.replay[0])
                if info.replay[1] not in replays.setdefault(key, []):
                    replays[key].append(info.replay[1])
        known = {axis: info for axis, (kind, info) in places.items() if kind == "known"}
        restored: set[str] = set()
        last = "Z"
        lifts = ("X", "Z") if self.walker.lathe else ("Z",)
        own_length = self.tool_change_length(places)
        if (places[last][0] == "unset" and any(a in known for a in AXES if a != last)
                and not own_length):
            moved = ", ".join(a for a in AXES if a in known)
            raise self.refuse(f"the program moves {moved} before it sets {last}: the height "
                              f"to approach from is not known; restart at an earlier block")
        length = self.length_offset()
        clear: dict[str, Decimal] = {}
        for axis in lifts:
            value = known.get(axis)
            if isinstance(value, Decimal):
                clear[axis] = self.clearance(axis, value)
        approach_from = len(out)
        for (_, _, codes), again in sorted(replays.items()):
            replay = " ".join([codes, *again]).strip()
            if replay in out:  # one block returns both axes (an Okuma lathe's G20 HP=1)
                continue
            out.append(replay)
            if codes.startswith("G91 "):
                out.append("G90")
        # retract: mill Z (with the length offset); lathe X, then Z
        if self.walker.lathe:
            for axis in lifts:
                if axis in clear:
                    out.append(f"G00 {self.word(axis, clear[axis])}")
                    restored.add(axis)
        elif "Z" in clear:
            lead = f"G00 {length} " if length else "G00 "
            h = self.length_h() if length else None
            out.append(lead + self.word("Z", clear["Z"]) + (f" {h}" if h else ""))
            restored.add("Z")
            length = ""
        if length:
            h = self.length_h()
            out.append(f"{length} {h}" if h else length)
        way = self.lathe_way(known, clear) if self.walker.lathe else None
        if way is not None:
            # the other axes (a lathe's C, Y or B) at the clearance, before the way in
            # (review 33, finding 2: they were left where the operator had them)
            others = [a for a in AXES if a in known and a not in ("X", "Z")]
            if others:
                words = [self.word(a, known[a]) for a in others]  # type: ignore[arg-type]
                out.append("G00 " + " ".join(words))
            out += way
            restored.update(a for a in ("X", "Z", *others) if a in known)
            self.clearance_value = clear.get(last)
            return restored
        # over the start point
        over = [a for a in AXES if a in known and a != last
                 and not (a in clear and clear[a] == known[a])]
        restored.update(a for a in AXES if a in known and a != last)
        if over:
            words = [self.word(a, known[a]) for a in over]  # type: ignore[arg-type]
            out.append("G00 " + " ".join(words))
            restored.update(over)
        start = known.get(last)
        if (not self.walker.lathe and last in clear and isinstance(start, Decimal)
                and clear[last] <= start
                and self.state.motion != 0 and not self.traverses_at(last)):
            # the clearance is the start point's own height, which the tool did not reach by
            # a rapid: the approach would rapid down to what may be the cutting depth wherever
            # the tool was left and traverse there (review 13, 8)
            raise self.refuse(
                f"no height above the start point is known to be clear: the program did not "
                f"raise {last} above {self.word(last, start)} before this block"
                f"{self.reached(last)}, so the approach would rapid to that depth wherever the "
                f"tool was left and traverse there (it would send: "
                f"{' / '.join(out[approach_from:])}); give "
                f"a safe {last} above the part (send --clearance, or the profile's [restart] "
                f"clearance) or restart at a block after a retract")
        # down to it in feed
        if last in clear:
            start = known[last]
            assert isinstance(start, Decimal)
            plane = {17: ("X", "Y"), 18: ("X",), 19: ("Y",)}.get(self.state.plane, ("X", "Y"))
            unset = [a for a in plane if places[a][0] == "unset"]  # (of the plane in force)
            if start < clear[last] and unset and not self.walker.lathe:
                raise self.refuse(
                    f"the program has not set {' and '.join(unset)} before it: in a run from "
                    f"the start the tool goes down to {self.word(last, start)} wherever the "
                    "operator left it, which a restart cannot find; restart at a block after "
                    f"one that sets {' and '.join(unset)} absolutely")
            if start < clear[last]:
                out.append(f"G01 {self.word(last, start)} {self.approach_feed(start)}")
                if self.walker.lathe:
                    self.notes.append(
                        f"approach: over the start point at the clearance "
                        f"{self.word(last, clear[last])}, then along Z in feed to "
                        f"{self.word(last, start)}: the program's way in with this tool is not "
                        "among the moves the walk keeps, and its last move was not radial")
                else:
                    self.notes.append(
                        f"approach: from the clearance height {self.word(last, clear[last])} "
                        f"over the start point, then down to {self.word(last, start)} in feed")
            restored.add(last)
        self.clearance_value = clear.get(last)
        return restored

    def reached(self, axis: str) -> str:
        """How the program reached the height ``axis`` is at, as the refusal says it: the
        motion mode in force at the block that last wrote it (a rapid is no safer than a feed
        here: neither says what lies between where the operator left the tool and the start
        point)."""
        if axis != "Z" or self.walk.z_reached is None:
            return ""
        motion, line = self.walk.z_reached
        if motion is None:
            return f" and reached it in a motion mode not known (line {line})"
        how = ("with a rapid" if motion == 0 else "in feed" if motion in (1, 2, 3)
               else "in the motion mode")
        return f" and reached it {how} (G{motion:02d} on line {line})"

    def lathe_way(self, known: dict[str, Any], clear: dict[str, Decimal]) -> list[str] | None:
        """A lathe's approach the way the program reached its start point with the tool in use:
        from the last point of the clearance plane (its Z at the clearance, or an X at the
        profile's ``clearance_x``) or of the lane (:meth:`in_lane`) within the walk's last
        moves of this tool, the same rapids and feeds again (a rapid the program made is clear,
        a feed it made has cut its path); along Z alone where the start point is on the lane.

        Only the program's own way counts. A point reached radially (an ID groove's bottom is
        the largest diameter of the program) is no clear place to rapid along Z to; the moves
        before a tool change are another tool's path (its length, width and shape); and the
        first move after it starts from where the previous tool left the turret, a way in for
        this tool only where that point is on the clearance plane, where the preamble puts it.
        Feeding along Z at the start diameter from the face, as after a turning pass, would
        drive a grooving tool through the bar, or an internal one through the bore's wall:
        where the block before moved X alone, or moved along Z from the end of such a move, or
        the start point is the previous tool's, and the way in is not within reach, the restart
        is refused. None: the approach along Z stands (a turning pass, the tool in front of the
        part)."""
        x, z = known.get("X"), known.get("Z")
        moves = self.walk.moves
        if not ("X" in clear and isinstance(x, Decimal) and isinstance(z, Decimal)
                and z < clear["Z"]):
            return None
        change = self.walk.tool_change
        if change is not None and not self.walk.tool_moved:
            raise self.refuse(
                f"the tool has not moved since the tool change on line {change}: the start "
                f"point {self.word('X', x)} {self.word('Z', z)} is where the previous tool left "
                "the turret, below the clearance plane, a point this tool has not been at, and "
                f"a feed along Z there could cut the part; restart at the tool change (line "
                f"{change}) or before it")
        if not moves or moves[0][0][2:] != (x, z):
            return None
        setting = self.profile.restart.clearance_x
        if self.in_lane(x, z):  # the start point itself is on the lane: along Z to it
            self.notes.append(
                f"approach: along Z at {self.word('X', x)}, the largest diameter this tool went "
                f"to, where it moved along Z from {self.word('Z', z)} up to the highest Z")
            return ([f"G00 {self.word('X', x)}"] if x != clear["X"] else []) + [
                f"G00 {self.word('Z', z)}"]
        chain: list[tuple[tuple[Decimal, ...], int, int]] = []
        first_from: tuple[Decimal, Decimal, int] | None = None  # a first move from below
        for ends, motion, line, first in moves:
            if None in ends or motion not in (0, 1) or (
                    chain and ends[2:] != chain[-1][0][:2]):
                break  # an arc, a cycle, a position not followed: the way is lost
            x0, z0 = ends[0], ends[1]
            assert x0 is not None and z0 is not None
            if first and z0 < clear["Z"]:
                first_from = (x0, z0, line)
                break  # from where the previous tool stood, below the clearance plane
            chain.append((tuple(e for e in ends if e is not None), motion or 0, line))
            lane = self.in_lane(x0, z0)
            if z0 >= clear["Z"] or (setting is not None and x0 >= clear["X"]) or lane:
                # from the clearance plane, from the profile's clearance_x, or from a point of
                # the lane: along Z at the largest diameter this tool went to, over Z ranges
                # it moved along there from up to the highest Z (a diameter reached radially,
                # an ID groove's bottom, is no lane)
                out = [f"G00 {self.word('X', x0)}"] if x0 != clear["X"] else []
                if z0 < clear["Z"]:
                    out.append(f"G00 {self.word('Z', z0)}")
                for (xs, zs, xe, ze), m, _ in reversed(chain):
                    moved = [self.word(a, e) for a, s, e in (("X", xs, xe), ("Z", zs, ze))
                             if s != e]
                    feed = [self.approach_feed(ze)] if m == 1 else []
                    out.append(" ".join([f"G0{m}", *moved, *feed]))
                lines = sorted(at for _, _, at in chain)
                span = f"line {lines[0]}" if len(lines) == 1 else \
                    f"lines {lines[0]} to {lines[-1]}"
                where = (f"the clearance plane {self.word('Z', z0)}" if z0 >= clear["Z"]
                         else f"the profile's clearance_x {self.word('X', x0)}"
                         if setting is not None and x0 >= clear["X"] else
                         f"{self.word('X', x0)} {self.word('Z', z0)}, reached by a rapid along "
                         "Z at the largest diameter this tool went to, where it moved along Z "
                         "from there up to the highest Z")
                self.notes.append(
                    f"approach: the way the program went in with this tool, from {where}: "
                    f"the moves of {span} again, rapids as rapids, feeds at the feed in force")
                return out
        (x0, z0, _, _), _, at, _ = moves[0]
        radial = z0 == z and x0 != x
        if not radial and len(moves) > 1:
            (xa, za, xb, zb), _, at2, _ = moves[1]
            radial = (xb, zb) == (x0, z0) and za == zb and xa != xb
            at = at2 if radial else at
        if first_from is not None:
            fx, fz, fline = first_from
            switch = self.walk.diameter_rewritten
            if switch is not None and switch[1] == fline:
                code = self.walk.diameter_mode[0] if self.walk.diameter_mode else 8
                raise self.refuse(
                    f"the tool reached {self.word('X', x)} {self.word('Z', z)} from "
                    f"{self.word('X', fx)} {self.word('Z', fz)} (line {fline}), an X written "
                    f"before the G{code} on line {switch[0]} switched between diameter and "
                    "radius mode, below the clearance plane: the way this tool went in is not "
                    f"known; restart at the G{code} (line {switch[0]}) or before it")
            raise self.refuse(
                f"the tool reached {self.word('X', x)} {self.word('Z', z)} from where the "
                f"previous tool left the turret at the tool change on line {change} "
                f"({self.word('X', fx)} {self.word('Z', fz)}, below the clearance plane; "
                f"this tool's first move is line {fline}): the way this tool went in is not "
                f"known; restart at the tool change (line {change}) or before it")
        if radial:
            raise self.refuse(
                f"the tool reached {self.word('X', x)} {self.word('Z', z)} after a radial move "
                f"(line {at}), and the way the program went in from the clearance plane is "
                "not among the moves the walk keeps of this tool: a feed along Z at that "
                "diameter could cut the bar or a bore's wall; restart at the block that brings "
                "the tool in")
        return None

    def in_lane(self, x: Decimal, z: Decimal) -> bool:
        """Whether the tool in use moved along Z at ``x``, its largest diameter, over the whole
        way from ``z`` up to the program's highest Z (:attr:`_Facts.lane`): a rapid along Z
        there from the clearance goes where the program itself went."""
        lane, top = self.walk.lane, self.walk.high.get("Z")
        if lane is None or top is None:
            return False
        scale = INCH if self.units == "inch" else Decimal(1)
        if x * scale != lane[0]:
            return False
        return any(lo <= z * scale and hi >= top for lo, hi in lane[1])

    def approach_feed(self, start: Decimal, axis: str = "Z") -> str:
        """The F of the approach's feed: the one in force, or else the restart block's own F,
        the feed the program cuts there with (a first plunge after the program's own rapid
        approach carries its F)."""
        feed = None if self.stale_feed else self.state.feed
        if feed is None:
            feed = self.own_feed()
            if feed is None:
                raise self.refuse(f"no feed rate is in force before it for the approach "
                                  f"to {self.word(axis, start)}, and the block gives none")
        return self.word("F", feed)

    def own_feed(self) -> Decimal | None:
        """The restart block's own F, where it gives one plain positive number."""
        words = [w for w in self.block.word_objects() if w.letter == "F" and w.number]
        try:
            feed = Decimal(words[0].number) if len(words) == 1 else None
        except InvalidOperation:
            return None
        return feed if feed is not None and feed.is_finite() and feed > 0 else None

    def own_target(self, axis: str, lost: _Lost) -> Decimal:
        """Where the work system changed after ``axis``'s last position: the old number in the
        new system is a point the program never visits, so the approach goes to the restart
        block's own absolute target of ``axis`` (from the clearance height), or refuses."""
        value = self.block_target(axis)
        if value is None:
            raise self.refuse(f"the work coordinate system changed after the last position of "
                              f"{axis} ({lost.what} on line {lost.line}) and the block does not "
                              f"give {axis} as an absolute number: the position in the new "
                              "system is not known; restart at a block that gives every axis")
        self.state.position[axis] = value
        return value

    def tool_change_length(self, places: dict[str, tuple[str, Any]]) -> bool:
        """After a FANUC or Haas mill's M06 (Z at the tool change height, no place of the
        program's: the walk leaves X Y Z unset until written): True where the restart block
        itself sets the new tool's length offset and Z (`G43 H02 Z25.`), which then runs from
        the height the preamble's own M06 leaves, X and Y placed there first as the program
        placed them; the length offset of before the change is left out (the block sets its
        own). Refused where the length offset in force was set before the M06 and the block
        sets none: the old tool's H with the new tool, at a height the program never gave
        (review 36, finding 1: T2 went down to Z25. with H01)."""
        walk, s = self.walk, self.state
        if (self.walker.lathe or self.walker.family not in ("fanuc", "haas")
                or not walk.m6_line or places.get("Z", ("",))[0] != "unset"):
            return False
        gs = {w.number for w in self.block.word_objects() if w.letter == "G" and w.number}
        sets_length = any(g.lstrip("0") in ("43", "44", "49") for g in gs)
        if sets_length and self.block_target("Z") is not None:
            self.state = replace(self.state, length_offset=49)
            return True
        if s.length_offset in (43, 44) and walk.g43_line < walk.m6_line and not sets_length:
            h = f" {walk.h}" if walk.h else ""
            raise self.refuse(
                f"the length offset G{s.length_offset}{h} in force was set on line "
                f"{walk.g43_line}, before the tool change on line {walk.m6_line}, and the "
                "program has not moved Z since: the new tool is at the tool change height "
                "with the old tool's length; restart at the block that sets the new tool's "
                "length offset and Z (G43 H.. Z..), or at the tool change")
        return False

    def block_starts_spindle(self) -> bool:
        """Whether the restart block starts the (main) spindle itself: an M03 or M04."""
        return any(w.letter == "M" and w.number and w.number.isdigit()
                   and int(w.number) in (3, 4) for w in self.block.word_objects())

    def block_target(self, axis: str) -> Decimal | None:
        """The restart block's own absolute target of ``axis``, if it gives one plainly."""
        words = [w for w in self.block.word_objects() if w.letter == axis and w.number]
        own = {int(w.number) for w in self.block.word_objects() if w.letter == "G"
               and w.number and w.number.isdigit()}
        value = None
        if len(words) == 1 and not self.state.incremental and not own & {53, 91}:
            try:
                value = Decimal(words[0].number)
            except InvalidOperation:
                value = None
        return value if value is not None and value.is_finite() else None

    def length_offset(self) -> str:
        s = self.state
        if self.okuma_mill:
            length = self.walk.okuma_length
            return f"G{length[0]}" if length is not None else ""
        return f"G{s.length_offset}" if s.length_offset in (43, 44) else ""

    def length_h(self) -> str | None:
        """The H word of the length offset in force."""
        if self.okuma_mill and self.walk.okuma_length is not None:
            return self.walk.okuma_length[1]
        return self.walk.h

    # -- the motion mode and the check --------------------------------------------------------

    def finish(self, out: list[str], restored: set[str]) -> RestartPlan:
        s, block = self.state, self.block
        run = _core.ModalMachine(self.walker.machine)
        after = self.run(run, out)
        first_block = None
        own = self.motion_of(block)
        extra = []
        if s.motion is not None and after.motion != s.motion and own is None:
            if s.motion in (0, 1):
                extra.append(f"G{s.motion:02d}")
            else:
                first_block = self.restate(block, s.motion)
        if s.feed is not None and after.feed != s.feed and not self.stale_feed:
            extra.append(self.word("F", s.feed))
        if extra:
            extra = [" ".join(extra)]
            out += extra
            after = self.run(run, extra)
        self.verify(after, restored, motion=first_block is None and own is None)
        self.verify_diameter_mode(out)
        return RestartPlan(block.line, s, out, first_block, self.clearance_value, restored,
                           self.notes)

    def traverses_at(self, height: str) -> bool:
        """Whether the restart block is a rapid that keeps ``height`` (no word of it): the
        program itself traverses at the start point's height (`G43 H5 Z50.`, then `G00 X0 Y0`)."""
        words = list(self.block.word_objects())
        motion = self.motion_of(self.block)
        rapid = motion == 0 or (motion is None and self.state.motion == 0)
        return rapid and not any(w.letter == height for w in words) and any(
            w.letter in AXES and w.letter != height for w in words)

    def motion_of(self, block: Block) -> int | None:
        for w in block.word_objects():
            if w.letter == "G" and w.number and not w.index and "." not in w.number:
                g = int(w.number)
                if g in MOTION_CODES or g in self.cycle_codes():
                    return g  # (a mill's cycle or G80 keeps the motion mode in force)
        return None

    def cycle_codes(self) -> set[int]:
        """A lathe's cycles of the motion group, which a block of axis words repeats in
        their mode: a FANUC or Haas lathe's G90, G92, G94, an Okuma lathe's G31-G35."""
        if self.walker.fanuc_lathe:
            return {90, 92, 94}
        return {31, 32, 33, 34, 35} if self.walker.okuma_lathe else set()

    def restate(self, block: Block, motion: int) -> str:
        moves = [w for w in block.word_objects() if w.letter in AXES and w.number]
        if motion in (90, 92, 94) and self.walker.fanuc_lathe and moves:
            # X(U), Z(W) and R are modal within a single cycle (0i-TF, "Canned cycle"); the
            # preamble's G00 ends the cycle, so a repeat must give its Z and any R in force
            letters = {w.letter for w in block.word_objects() if w.number}
            if not letters & {"Z", "W"}:
                raise self.refuse(f"the repeat of the cycle G{motion} gives no Z (W): the "
                                  "cycle's end in force is ended by the preamble's G00; restart "
                                  f"at the G{motion} block or a repeat that writes Z")
            if self.walk.cycle_r is not None and "R" not in letters:
                raise self.refuse(f"the repeat of the cycle G{motion} gives no R: the taper R "
                                  f"from line {self.walk.cycle_r} is ended by the preamble's "
                                  f"G00; restart at the G{motion} block or a repeat that "
                                  "writes R")
        if not moves:
            raise self.refuse(f"the motion mode G{motion:02d} in force can only be restored in "
                              "a block that moves; restart at the next block with a move")
        word = next(w for w in block.word_objects() if w.address not in "N:")
        text = block.text
        at = len(text) - len(text.lstrip()) if word.column <= 0 else word.column - 1
        # written as the program writes its words: with blanks between them, or none; a
        # block of one word shows neither, and gets the blank (G33 X28.5, not G33X28.5)
        words = [w for w in block.word_objects() if w.address not in "N:"]
        gap = " " if " " in text.strip() or len(words) == 1 else ""
        return f"{text[:at]}G{motion:02d}{gap}{text[at:]}"

    def run(self, machine: _core.ModalMachine, lines: list[str]) -> ModalState:
        """The state the core's modal state machine reaches through ``lines`` (from reset)."""
        for block in parse_text("\n".join(lines) + "\n", self.profile.dialect):
            machine.apply(block.words)
        return ModalState(**machine.state)

    def verify_diameter_mode(self, out: list[str]) -> None:
        """LinuxCNC's G7/G8, which the modal state does not hold: the preamble read by the same
        walk selects the mode the program selected."""
        wanted = self.walk.diameter_mode
        if wanted is None:
            return
        check = RestartWalk(self.profile, self.file)
        check.walk_lines("\n".join(out) + "\n", 0, len(out) + 2)
        got = check._core.facts()["diameter_mode"]
        if got is None or got[0] != wanted[0]:
            raise self.refuse("the preamble would not restore the diameter mode "
                              f"G{wanted[0]} (please report this program)")

    def verify(self, after: ModalState, restored: set[str], motion: bool) -> None:
        """The preamble run from reset reaches the state in force: else refuse, never send."""
        s = self.state
        fields = ["plane", "units", "feed_units", "incremental", "feed_mode", "spindle_mode",
                  "speed", "speed_limit", "spindle", "coolant", "compensation",
                  "length_offset", "cycle"]
        if self.turn_code is not None:
            # (the modal state follows M03-M05 alone: the keyed start the preamble writes is
            # the program's own code, which it reads as no spindle code)
            fields.remove("spindle")
        if not self.walker.lathe:
            fields.append("offset")  # a lathe's D is a cycle's depth of cut
        if self.walk.m6 is not None or self.walk.t_token is not None:
            fields.append("tool")
        if s.feed is not None and not self.stale_feed:
            fields.append("feed")
        if motion:
            fields.append("motion")
        wrong = [f for f in fields if getattr(after, f) != getattr(s, f)]
        wrong += [f"position {a}" for a in sorted(restored)
                  if after.position.get(a) != s.position.get(a)]
        if wrong:
            raise self.refuse("the preamble would not restore " + ", ".join(wrong)
                              + " (please report this program)")
