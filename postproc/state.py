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
from typing import Any

from formats import _core
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


def core_config(profile: Profile, select: tuple[str, ...] = (), ignore: tuple[str, ...] = (),
                record_path: bool = False) -> dict[str, Any]:
    """What the core needs from a profile (formats, code table, checks, limits, reset state),
    as plain values: the profile is validated in Python and handed over once."""
    checks, limits = profile.checks, profile.limits

    def code(letter: str, number: int) -> tuple[str, str] | None:
        c = profile.code(letter, number)
        return None if c is None else (c.status, c.duration)

    return {
        "formats": [(f.address, f.before, f.after, f.signed, str(f.zeros), f.decimal)
                    for f in profile.detailed.formats.values()],
        "formats_inch": None if profile.detailed_inch is None else [
            (f.address, f.before, f.after, f.signed, str(f.zeros), f.decimal)
            for f in profile.detailed_inch.formats.values()],
        "explicit": profile.explicit,
        "increments": profile.numbers.whole_letters(),
        "alignment": profile.detailed.alignment,
        "classification": str(profile.detailed),
        "table_name": profile.table.name,
        "g_codes": [code("G", n) for n in range(1000)],
        "g_decimal": [(key[1:], c.status, c.duration) for key, c in profile.extra_codes.items()
                      if key.startswith("G") and "." in key],
        # ISO 6983-1 reads M1xx as class 1 of M00-M99; the other families have M100-M999
        "m_codes": [code("M", n) for n in range(100 if profile.dialect.family == "iso" else 1000)],
        "program_number": profile.program_number,
        "family": profile.dialect.family,
        "units_kept_at_end": profile.units_kept_at_end,
        "percent": profile.detailed.program_start,
        "colon_stop": profile.comment_colon() == "stop",
        "diameter": profile.dialect.family in ("fanuc", "haas") and profile.control_type == "lathe",
        # Fanuc and Haas lathes: G50 S clamps the spindle, G98/G99 are feed per min/rev
        "fanuc_lathe": profile.dialect.family in ("fanuc", "haas")
        and profile.control_type == "lathe",
        "tv_check": profile.serial.tv_check,
        "arc_tolerance": float(checks.arc_tolerance),
        "alarm_g": (checks.unknown_g or ("warn" if profile.dialect.family == "iso" else "alarm"))
        == "alarm",
        "alarm_m": (checks.unknown_m or "warn") == "alarm",
        "arc_tolerance_relative": float(checks.arc_tolerance_relative),
        "ijk": checks.ijk,
        "repeatable": "".join(sorted(checks.repeatable)),
        "m_classes": sorted(checks.m_classes),
        "max_index": checks.max_index,
        "max_parameter": checks.max_parameter,
        "index_g": checks.index_g,
        "pqr": (checks.pqr.get("P", "other"), checks.pqr.get("Q", "other"),
                checks.pqr.get("R", "other")),
        "travel": [(axis, str(low), str(high)) for axis, (low, high) in limits.axes.items()],
        "work_offsets": [(int(g[1:]), axis, str(value))
                         for g, axes in profile.work_offsets.items()
                         for axis, value in axes.items()],
        "feed_max": None if limits.feed_max is None else str(limits.feed_max),
        "spindle_max": None if limits.spindle_max is None else str(limits.spindle_max),
        "tool_max": limits.tool_max,
        "rapid_rate": float(limits.rapid_rate),
        "reset": [int(c[1:]) for c in profile.reset_state()],
        "inch": int(profile.inch_code[1:]),
        "metric": int(profile.metric_code[1:]),
        "default_units": profile.default_units,
        "select": list(select),
        "ignore": list(ignore),
        "record_path": record_path,
    }


class ModalMachine:
    """Applies blocks to the modal state; :meth:`step` returns the state before and after."""

    def __init__(self, profile: Profile) -> None:
        self.profile = profile
        self._core = _core.ModalMachine(core_config(profile))

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
