"""The modal state of a program, block by block (ISO 6983-1 clauses 5.3, 7-14, Annex E).

An omitted word means "no change" (5.3): what a block does depends on everything before it.
The state machine is the Rust core's (``crates/core/src/modal.rs``), the one the checker runs:
:class:`ModalMachine` here is a view of it that keeps the complete :class:`ModalState` -- motion
mode, plane, units, distance mode, feed mode and value, spindle, coolant, compensation, offsets,
zero shift, tool, fixed cycle and its parameters, and the absolute position -- starting from the
reset state of clause 14 for the profile's control type, and resetting again after M02/M30.

It is a public API: :func:`state_at` gives the state in force at a block; the restart preamble
that brings a control back into it is ``postproc.restart``'s.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from decimal import Decimal

from formats import _core
from formats.machine import machine
from formats.model import Block
from formats.profile import Profile

AXES = "XYZUVWABC"


@dataclass
class ModalState:
    """Everything a block inherits from the blocks before it."""

    motion: int | None = None  # G00 G01 G02 G03 G06 G33 G34 G35
    plane: int = 17
    units: str = "metric"
    # the feed's units: the units of lengths, but on Sinumerik under G70/G71 the basic system's
    feed_units: str = "metric"
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


class ModalMachine:
    """Applies blocks to the modal state; :meth:`step` returns the state before and after."""

    def __init__(self, profile: Profile) -> None:
        self.profile = profile
        self._core = _core.ModalMachine(machine(profile))

    @property
    def state(self) -> ModalState:
        """A snapshot of the state now (a new object each time)."""
        return ModalState(**self._core.state)

    def reset(self) -> None:
        """The reset state of clause 14 for the profile's control type (position is kept)."""
        self._core.reset()

    def step(self, block: Block) -> tuple[ModalState, ModalState]:
        before = self.state
        self.apply(block)
        return before, self.state

    def apply(self, block: Block) -> None:
        """Apply a block's plain words; an indexed word or an expression leaves the state as
        it is, and so does a word the profile's format cannot read (the checker reports it)."""
        self._core.apply(block.words)


def state_at(blocks: Iterable[Block], profile: Profile, line: int) -> ModalState:
    """The modal state in force before the block on ``line`` (for a restart from that block)."""
    machine = ModalMachine(profile)
    for block in blocks:
        if block.line >= line:
            break
        machine.apply(block)
    return machine.state
