"""The G and M code tables: ISO 6983-1:2009 Annex E and ISO 1056:1975, as data.

Each code has a function, a duration (a modal group letter, kept until cancelled or superseded
by another code of the same group, or ``TBO``: this block only) and a status:

* ``assigned`` -- the standard gives it a meaning;
* ``conditional`` -- ISO 6983-1's codes marked (c): assigned only where the control provides the
  function, otherwise unassigned;
* ``unassigned`` -- for individual use, designated in the detailed format classification (DDFC);
* ``permanent`` -- permanently unassigned: a program must not use it unless a profile redefines it.

A machine profile chooses a table and may add or redefine codes (Fanuc's G20/G21 and G28, say)
without touching these tables. Modal group letters follow the standards (``a`` motion, ``b`` plane,
``d`` compensation, ``e`` fixed cycles, ``f`` zero shift, ``g``/``h`` exact stop, ``j`` distance
mode, ``k`` feed mode, ``l`` spindle mode, ``m`` units).
"""

from __future__ import annotations

import _thread
from _collections_abc import Iterator, Mapping  # (collections.abc's, without collections)

from formats.records import FrozenRecord, init_fields, record

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from typing import Literal

    Status = Literal["assigned", "conditional", "unassigned", "permanent"]
    # numbers (a range or a tuple), function, status, duration: what a standard says of codes
    # it does not list one by one
    Range = tuple[range | tuple[int, ...], str, Status, str]

TBO = "TBO"


@record
class Code(FrozenRecord):
    """A G or M code of a table: its function, status and duration."""

    __slots__ = ("letter", "number", "function", "duration", "status", "timing", "words",
                 "meaning")
    letter: str  # "G" or "M"
    number: int
    function: str
    duration: str  # modal group letter/name, or "TBO", or "" where the standard leaves it open
    status: Status  # default "assigned"
    timing: str  # M codes of ISO 1056: "with" or "after" the motion of the block; default ""
    # The words that name a block or a program in this code's blocks, each with the address
    # whose format it then takes: (("P", "N"), ("Q", "N")) for G71 P100 Q200 (sequence
    # numbers), (("P", "O"),) for M98 P1234 (a program number). A profile's `words`.
    words: tuple[tuple[str, str], ...]
    # What the code does, as a key shared by the profiles of every family (a profile's
    # `meaning`, docs/profiles.md): two controls that list one number under two keys give it
    # two functions, and a conversion between them refuses it. "" where the profile gives none.
    meaning: str

    def __init__(self, letter: str, number: int, function: str, duration: str,
                 status: Status = "assigned", timing: str = "",
                 words: tuple[tuple[str, str], ...] = (), meaning: str = "") -> None:
        # the fields set one by one, as init_fields sets them, without its loop: a profile
        # makes its 200 codes before a batch's threads start, and init_fields was 2 us of a
        # code's 4 (docs/benchmarks.md, "the serial start-up without enum")
        put = object.__setattr__
        put(self, "letter", letter)
        put(self, "number", number)
        put(self, "function", function)
        put(self, "duration", duration)
        put(self, "status", status)
        put(self, "timing", timing)
        put(self, "words", words)
        put(self, "meaning", meaning)

    @property
    def name(self) -> str:
        return f"{self.letter}{self.number:02d}"

    @property
    def modal(self) -> bool:
        return self.duration not in ("", TBO)

    @property
    def usable(self) -> bool:
        return self.status in ("assigned", "conditional")


@record
class Listing(FrozenRecord, Mapping[int, Code]):
    """The codes of one letter of a table, by number: the codes the standard lists one by one,
    and the ranges it gives one function and status (the first range that holds a number
    decides, after the listed codes). A code of a range is made when it is looked up, so the
    thousand G numbers of ISO 6983-1 are not made at import; iterated (``values()``), the
    listed codes come first, then each range's in its order."""

    letter: str
    listed: dict[int, Code]
    ranges: tuple[Range, ...]

    def __init__(self, letter: str, listed: dict[int, Code], ranges: tuple[Range, ...]) -> None:
        init_fields(self, letter, listed, ranges)

    def get(self, number: int, default: Code | None = None) -> Code | None:  # type: ignore[override]
        code = self.listed.get(number)
        if code is not None:
            return code
        made = self._made()
        code = made.get(number)
        if code is None:
            for numbers, function, status, duration in self.ranges:
                if number in numbers:
                    code = made[number] = Code(self.letter, number, function, duration, status)
                    break
            else:
                return default
        return code

    def _made(self) -> dict[int, Code]:
        """The codes of the ranges made so far (kept with the listing, not a field)."""
        made: dict[int, Code] | None = self.__dict__.get("_made_codes")
        if made is None:
            made = {}
            object.__setattr__(self, "_made_codes", made)
        return made

    def _all(self) -> dict[int, Code]:
        every: dict[int, Code] = dict(self.listed)
        for numbers, _, _, _ in self.ranges:
            for n in numbers:
                if n not in every:
                    every[n] = self[n]
        return every

    def states(self, count: int) -> list[tuple[str, str] | None]:
        """(status, duration) of the numbers 0 to ``count - 1``, None where the table has no
        code: what the core's machine is told, without making the codes."""
        result: list[tuple[str, str] | None] = [None] * count
        for numbers, _, status, duration in reversed(self.ranges):
            state = (status, duration)
            for n in numbers:
                if n < count:
                    result[n] = state
        for n, code in self.listed.items():
            if n < count:
                result[n] = (code.status, code.duration)
        return result

    def __getitem__(self, number: int) -> Code:
        code = self.get(number)
        if code is None:
            raise KeyError(number)
        return code

    def __iter__(self) -> Iterator[int]:
        return iter(self._all())

    def __len__(self) -> int:
        return len(self._all())


def _fill(ranges: list[Range], numbers: range | list[int], function: str,
          status: Status, duration: str = "") -> None:
    ranges.append((numbers if isinstance(numbers, range) else tuple(numbers), function, status,
                   duration))


def _iso6983_g() -> Listing:
    t: dict[int, Code] = {}
    r: list[Range] = []

    def a(n: int, f: str, d: str, s: Status = "assigned") -> None:
        t[n] = Code("G", n, f, d, s)

    a(0, "rapid positioning", "a")
    a(1, "linear interpolation", "a")
    a(2, "circular interpolation clockwise", "a")
    a(3, "circular interpolation counter-clockwise", "a")
    a(4, "dwell", TBO)
    a(6, "parabolic interpolation", "a")
    a(9, "exact stop (after this block)", TBO, "conditional")
    a(17, "XY plane selection", "b")
    a(18, "ZX plane selection", "b")
    a(19, "YZ plane selection", "b")
    a(33, "thread cutting, constant lead", "a")
    a(34, "thread cutting, increasing lead", "a", "conditional")
    a(35, "thread cutting, decreasing lead", "a", "conditional")
    a(40, "cutter compensation / tool offset cancel", "d")
    a(41, "cutter compensation left", "d")
    a(42, "cutter compensation right", "d")
    a(43, "tool offset positive", "d", "conditional")
    a(44, "tool offset negative", "d", "conditional")
    a(53, "dimension (zero) shift cancel", "f", "conditional")
    for n in range(54, 60):
        a(n, f"zero shift {n - 53}", "f", "conditional")
    a(60, "exact stop (after each block)", "g", "conditional")
    a(63, "tapping", TBO, "conditional")
    a(64, "continuous-path mode", "g", "conditional")
    a(70, "dimension input in inch", "m", "conditional")
    a(71, "dimension input metric", "m", "conditional")
    a(74, "home position", TBO, "conditional")
    a(80, "fixed cycle cancel", "e")
    for n, use in zip(range(81, 90), FIXED_CYCLE_USE, strict=True):
        a(n, f"fixed cycle ({use})", "e")
    a(90, "absolute dimension", "j", "conditional")
    a(91, "incremental dimension", "j", "conditional")
    a(92, "preload registers", TBO, "conditional")
    a(93, "inverse time feed", "k", "conditional")
    a(94, "feed per minute", "k")
    a(95, "feed per revolution", "k")
    a(96, "constant surface speed", "l")
    a(97, "revolutions per minute", "l", "conditional")
    _fill(r, list(range(25, 30)) + list(range(36, 40)), "permanently unassigned", "permanent")
    _fill(r, range(0, 1000), "unassigned (individual use, DDFC)", "unassigned")
    return Listing("G", t, tuple(r))


FIXED_CYCLE_USE = (
    "drill, spot drill",
    "drill, counterbore",
    "deep hole",
    "tap",
    "bore",
    "bore",
    "bore",
    "bore",
    "bore",
)


def _iso6983_m() -> Listing:
    t: dict[int, Code] = {}
    r: list[Range] = []

    def a(n: int, f: str, d: str, timing: str = "") -> None:
        t[n] = Code("M", n, f, d, "assigned", timing)

    a(0, "program stop", TBO, "after")
    a(1, "optional (planned) stop", TBO, "after")
    a(2, "end of program", TBO, "after")
    a(3, "spindle clockwise", "spindle", "with")
    a(4, "spindle counter-clockwise", "spindle", "with")
    a(5, "spindle off", "spindle", "after")
    a(6, "tool change", TBO)
    a(7, "coolant no. 2 on (see ISO/TR 6983-2)", "coolant", "with")
    a(8, "coolant no. 1 on (see ISO/TR 6983-2)", "coolant", "with")
    a(9, "coolant off (see ISO/TR 6983-2)", "coolant", "after")
    a(10, "clamp", TBO)
    a(11, "unclamp", TBO)
    a(30, "end of data (rewind to program start)", TBO, "after")
    a(48, "cancel M49", "override")
    a(49, "bypass override", "override")
    a(60, "workpiece change", TBO)
    _fill(r, range(0, 100), "unassigned (individual use, DDFC)", "unassigned")
    return Listing("M", t, tuple(r))


def _iso1056_g() -> Listing:
    t: dict[int, Code] = {}
    r: list[Range] = []

    def a(n: int, f: str, d: str, s: Status = "assigned") -> None:
        t[n] = Code("G", n, f, d, s)

    a(0, "point-to-point positioning", "a")
    a(1, "linear interpolation", "a")
    a(2, "circular interpolation clockwise", "a")
    a(3, "circular interpolation counter-clockwise", "a")
    a(4, "dwell", TBO)
    a(6, "parabolic interpolation", "a")
    a(8, "acceleration", TBO)
    a(9, "deceleration", TBO)
    a(17, "XY plane selection", "c")
    a(18, "ZX plane selection", "c")
    a(19, "YZ plane selection", "c")
    a(33, "thread cutting, constant lead", "a")
    a(34, "thread cutting, increasing lead", "a")
    a(35, "thread cutting, decreasing lead", "a")
    a(40, "cutter compensation / tool offset cancel", "d")
    a(41, "cutter compensation left", "d")
    a(42, "cutter compensation right", "d")
    a(43, "tool offset positive", "d", "conditional")
    a(44, "tool offset negative", "d", "conditional")
    for n, signs in zip(range(45, 53), ("+/+", "+/-", "-/-", "-/+", "0/+", "0/-", "+/0", "-/0"),
                        strict=True):
        a(n, f"tool offset {signs}", "d", "conditional")
    a(53, "linear shift cancel", "f")  # "G54-G62 are unassigned if the control lacks them": not G53
    for n, axes in zip(range(54, 60), ("X", "Y", "Z", "XY", "XZ", "YZ"), strict=True):
        a(n, f"linear shift {axes}", "f", "conditional")
    a(60, "positioning exact 1 (fine)", "h", "conditional")
    a(61, "positioning exact 2 (medium)", "h", "conditional")
    a(62, "positioning fast (coarse)", "h", "conditional")
    a(63, "tapping", TBO)
    a(68, "tool offset, inside corner", "d", "conditional")
    a(69, "tool offset, outside corner", "d", "conditional")
    a(80, "fixed cycle cancel", "e")
    for n, use in zip(range(81, 90), FIXED_CYCLE_USE, strict=True):
        a(n, f"fixed cycle ({use})", "e")
    a(90, "absolute dimension", "j")
    a(91, "incremental dimension", "j")
    a(92, "preload registers", TBO)
    a(93, "inverse time feed", "k")
    a(94, "feed per minute", "k")
    a(95, "feed per revolution", "k")
    a(96, "constant surface speed", "l")
    a(97, "revolutions per minute", "l")
    _fill(r, list(range(25, 30)) + list(range(36, 40)), "permanently unassigned", "permanent")
    _fill(r, range(0, 100), "unassigned (designated in the format specification)",
          "unassigned")
    return Listing("G", t, tuple(r))


def _iso1056_m() -> Listing:
    t: dict[int, Code] = {}
    r: list[Range] = []

    def a(n: int, f: str, d: str, timing: str) -> None:
        t[n] = Code("M", n, f, d, "assigned", timing)

    a(0, "program stop", TBO, "after")
    a(1, "optional (planned) stop", TBO, "after")
    a(2, "end of program", TBO, "after")
    a(3, "spindle clockwise", "spindle", "with")
    a(4, "spindle counter-clockwise", "spindle", "with")
    a(5, "spindle off", "spindle", "after")
    a(6, "tool change", TBO, "")
    a(7, "coolant no. 2 on", "coolant", "with")
    a(8, "coolant no. 1 on", "coolant", "with")
    a(9, "coolant off", "coolant", "after")
    a(10, "clamp", "clamp", "")
    a(11, "unclamp", "clamp", "")
    a(13, "spindle clockwise and coolant on", "spindle", "with")
    a(14, "spindle counter-clockwise and coolant on", "spindle", "with")
    a(15, "motion +", TBO, "with")
    a(16, "motion -", TBO, "with")
    a(19, "oriented spindle stop", "spindle", "after")
    a(30, "end of tape (rewind)", TBO, "after")
    a(31, "interlock bypass", TBO, "")
    a(36, "feed range 1", "feed-range", "with")
    a(37, "feed range 2", "feed-range", "with")
    a(38, "spindle speed range 1", "speed-range", "with")
    a(39, "spindle speed range 2", "speed-range", "with")
    for n in range(40, 46):
        t[n] = Code("M", n, "gear change if used, otherwise unassigned", "", "unassigned")
    _fill(r, range(20, 30), "permanently unassigned", "permanent")
    _fill(r, range(0, 48), "unassigned (designated in the format specification)",
          "unassigned")
    # The copy of ISO 1056 available to this project ends at M47: M48-M99 are left to the
    # profile rather than given invented meanings.
    _fill(r, range(48, 100), "not confirmed in the available copy of ISO 1056 "
          "(designated by the profile)", "unassigned")
    return Listing("M", t, tuple(r))


@record
class CodeTable(FrozenRecord):
    """A table of G and M codes (ISO 6983-1 or ISO 1056)."""

    name: str
    g: Listing
    m: Listing

    def __init__(self, name: str, g: Listing, m: Listing) -> None:
        init_fields(self, name, g, m)

    def lookup(self, letter: str, number: int) -> Code | None:
        return (self.g if letter == "G" else self.m).get(number)


class _Tables(Mapping[str, CodeTable]):
    """The standards' code tables by name, each made when first asked for: a profile of a
    control family lists its own codes (``code_table = "own"``, below), and making both
    standards' tables at import was 0.2 ms (warm) of what a check of such a profile runs
    before its threads start, for nothing (docs/benchmarks.md, "a check without re"). Made
    once under a lock, so every profile of a table shares one."""

    _MAKERS = {"iso6983-1": (_iso6983_g, _iso6983_m), "iso1056": (_iso1056_g, _iso1056_m)}

    def __init__(self) -> None:
        self._made: dict[str, CodeTable] = {}
        self._lock = _thread.allocate_lock()

    def __getitem__(self, name: str) -> CodeTable:
        table = self._made.get(name)
        if table is None:
            g, m = self._MAKERS[name]  # (KeyError: no such table)
            with self._lock:
                table = self._made.get(name)
                if table is None:
                    table = self._made[name] = CodeTable(name, g(), m())
        return table

    def __iter__(self) -> Iterator[str]:
        return iter(self._MAKERS)

    def __len__(self) -> int:
        return len(self._MAKERS)


TABLES: Mapping[str, CodeTable] = _Tables()

# A control family's code table is the control's own list, its profile's `[codes]` (the
# maker's G and M code lists, docs/dialects.md), not ISO 6983-1's with the profile's codes over
# it: a code the list does not hold is no code of the control (TG307 or TG306 by what the
# control does), never the standard's meaning of that number (G91 incremental on a FANUC lathe
# of G code system A, whose G90 is a turning cycle). `code_table = "own"` selects it; it lists
# nothing, so every code comes from the profile.
OWN_TABLE = CodeTable("own", Listing("G", {}, ()), Listing("M", {}, ()))

# Which codes of ISO 6983-1 Annex E the M class digit (hundreds) may take (E.3).
M_CLASSES = {
    0: "universal",
    1: "milling, boring, turning centres",
    2: "lathes",
    3: "grinding and measuring",
    4: "flame, plasma, laser, water jet, wire EDM",
    5: "multi-carrier, head, spindle",
    6: "punching and nibbling",
    7: "permanently unassigned",
    8: "extension",
}
