"""The modal state of a program, block by block (ISO 6983-1 clauses 5.3, 7-14, Annex E).

An omitted word means "no change" (5.3): what a block does depends on everything before it.
:class:`ModalMachine` walks the blocks and keeps the complete :class:`ModalState` -- motion mode,
plane, units, distance mode, feed mode and value, spindle, coolant, compensation, offsets, zero
shift, tool, fixed cycle and its parameters, and the absolute position -- starting from the reset
state of clause 14 for the profile's control type, and resetting again after M02/M30.

It is a public API: the checker reads the state before and after each block, the DNC layer uses
:func:`state_at` to restart a program from a block with a preamble that restores the state.
"""

from __future__ import annotations

import copy
from collections.abc import Iterable
from dataclasses import dataclass, field
from decimal import Decimal

from formats.errors import TapegateError
from formats.model import Block
from formats.profile import Profile

MOTION = {0, 1, 2, 3, 6, 33, 34, 35}
CYCLES = set(range(81, 90))
AXES = "XYZUVWABC"
PLANE_AXES = {17: ("X", "Y", "Z"), 18: ("Z", "X", "Y"), 19: ("Y", "Z", "X")}
CENTRE_OF = {"X": "I", "Y": "J", "Z": "K"}


@dataclass
class ModalState:
    """Everything a block inherits from the blocks before it."""

    motion: int | None = None  # G00 G01 G02 G03 G06 G33 G34 G35
    plane: int = 17
    units: str = "metric"
    incremental: bool = False
    feed_mode: int = 94  # 93 inverse time, 94 per minute, 95 per revolution
    feed: Decimal | None = None
    spindle_mode: int = 97  # 96 constant surface speed, 97 rpm
    speed: Decimal | None = None
    speed_limit: Decimal | None = None  # G92 S (clause 12)
    spindle: str = "stop"  # cw (M03) | ccw (M04) | stop (M05)
    coolant: str = "off"  # mist (M07) | flood (M08) | off (M09)
    compensation: int = 40  # 40 | 41 | 42
    length_offset: int = 49  # 43 | 44 | 49 (cancelled)
    zero_shift: int | None = None  # 54..59, None when cancelled (G53) or never set
    tool: int | None = None
    offset: int | None = None  # D
    cycle: int | None = None  # 81..89 active fixed cycle
    cycle_words: dict[str, Decimal] = field(default_factory=dict)
    position: dict[str, Decimal] = field(default_factory=dict)
    ended: bool = False  # after M02/M30

    def copy(self) -> ModalState:
        new = copy.copy(self)
        new.cycle_words = dict(self.cycle_words)
        new.position = dict(self.position)
        return new


class ModalMachine:
    """Applies blocks to a :class:`ModalState`; :meth:`step` returns the state before and after."""

    def __init__(self, profile: Profile) -> None:
        self.profile = profile
        self.inch = int(profile.inch_code[1:])
        self.metric = int(profile.metric_code[1:])
        self.state = ModalState()
        self.reset()

    def reset(self) -> None:
        """The reset state of clause 14 for the profile's control type (position is kept)."""
        position = self.state.position
        self.state = ModalState(units=self.profile.default_units, position=position)
        for code in self.profile.reset_state():
            self._g(int(code[1:]), {}, set())

    def step(self, block: Block) -> tuple[ModalState, ModalState]:
        before = self.state.copy()
        self.apply(block)
        return before, self.state

    def apply(self, block: Block) -> None:
        values: dict[str, Decimal] = {}
        gs: list[int] = []
        ms: list[int] = []
        for tok in block.words:
            letter = tok[0].upper()
            if "=" in tok or not _plain(tok):
                continue
            try:
                value = self.profile.value(tok)
            except TapegateError:
                continue
            if letter == "G":
                gs.append(int(value))
            elif letter == "M":
                ms.append(int(value))
            else:
                values.setdefault(letter, value)
        self.apply_words(gs, ms, values)

    def apply_words(self, gs: list[int], ms: list[int], values: dict[str, Decimal]) -> None:
        s = self.state
        codes = set(gs)
        for g in gs:
            self._g(g, values, codes)
        if "F" in values and 4 not in codes:
            s.feed = values["F"]
        if "S" in values:
            if 92 in codes:
                s.speed_limit = values["S"]
            else:
                s.speed = values["S"]
        if "T" in values:
            s.tool = int(values["T"])
        if "D" in values:
            s.offset = int(values["D"])
        for m in ms:
            self._m(m)
        self._move(values, codes)
        if any(m in (2, 30) for m in ms):
            self.reset()
            self.state.ended = True

    def _g(self, g: int, values: dict[str, Decimal], codes: set[int]) -> None:
        s = self.state
        if g in MOTION:
            s.motion = g
            s.cycle = None
        elif g in (17, 18, 19):
            s.plane = g
        elif g in (40, 41, 42):
            s.compensation = g
        elif g in (43, 44, 49):
            s.length_offset = g
        elif g == 53:
            s.zero_shift = None
        elif 54 <= g <= 59:
            s.zero_shift = g
        elif g == 80:
            s.cycle = None
            s.cycle_words = {}
        elif g in CYCLES:
            s.cycle = g
            s.cycle_words = {}
        elif g in (90, 91):
            s.incremental = g == 91
        elif g in (93, 94, 95):
            s.feed_mode = g
        elif g in (96, 97):
            s.spindle_mode = g
        elif g == self.inch:
            s.units = "inch"
        elif g == self.metric:
            s.units = "metric"

    def _m(self, m: int) -> None:
        s = self.state
        if m in (3, 4, 5):
            s.spindle = {3: "cw", 4: "ccw", 5: "stop"}[m]
        elif m in (7, 8):
            s.coolant = "mist" if m == 7 else "flood"
        elif m == 9:
            s.coolant = "off"

    def _move(self, values: dict[str, Decimal], codes: set[int]) -> None:
        s = self.state
        if 4 in codes:
            return  # a dwell's X is a time (clause 13)
        if s.cycle is not None:
            for letter in "RZQPF":
                if letter in values:
                    s.cycle_words[letter] = values[letter]
        for axis in AXES:
            if axis not in values:
                continue
            value = values[axis]
            if 92 in codes or not s.incremental:
                s.position[axis] = value
            else:
                s.position[axis] = s.position.get(axis, Decimal(0)) + value


def _plain(tok: str) -> bool:
    body = tok[1:].lstrip("+-")
    return bool(body) and body.replace(".", "", 1).isdigit()


def state_at(blocks: Iterable[Block], profile: Profile, line: int) -> ModalState:
    """The modal state in force before the block on ``line`` (for a restart from that block)."""
    machine = ModalMachine(profile)
    for block in blocks:
        if block.line >= line:
            break
        machine.apply(block)
    return machine.state


def preamble(state: ModalState, profile: Profile) -> list[str]:
    """Blocks that bring a control from reset into ``state``: units, plane, distance and feed
    mode, zero shift, compensation off, tool and offsets, spindle speed and direction, coolant."""
    units = profile.inch_code if state.units == "inch" else profile.metric_code
    g = [units, f"G{state.plane}", "G91" if state.incremental else "G90", f"G{state.feed_mode}",
         "G40"]
    if state.zero_shift is not None:
        g.append(f"G{state.zero_shift}")
    blocks = [" ".join(g)]
    tool = []
    if state.tool is not None:
        tool.append(f"T{state.tool}")
    if state.offset is not None:
        tool.append(f"D{state.offset}")
    if state.length_offset in (43, 44):
        tool.append(f"G{state.length_offset}")
    if tool:
        blocks.append(" ".join(tool))
    spindle = []
    if state.spindle_mode == 96 and state.speed_limit is not None:
        blocks.append(f"G92 S{_whole(state.speed_limit)}")
    if state.speed is not None:
        spindle.append(f"G{state.spindle_mode} S{_whole(state.speed)}")
    if state.spindle != "stop":
        spindle.append("M03" if state.spindle == "cw" else "M04")
    if state.coolant != "off":
        spindle.append("M07" if state.coolant == "mist" else "M08")
    if spindle:
        blocks.append(" ".join(spindle))
    if state.feed is not None and state.motion in (1, 2, 3):
        blocks.append(f"G01 F{_number(state.feed)}" if state.motion == 1
                      else f"F{_number(state.feed)}")
    return blocks


def _whole(value: Decimal) -> str:
    """A speed: whole numbers without a decimal point (S words are often count formats)."""
    return str(int(value)) if value == value.to_integral_value() else _number(value)


def _number(value: Decimal) -> str:
    text = f"{value.normalize():f}"
    return text if "." in text or not text else text + "."
