"""A machine profile compiled once for the core: the one place a profile becomes core settings.

A :class:`~formats.profile.Profile` is validated in Python; :func:`machine_spec` turns it into a
:class:`MachineSpec` of plain values (mirrored in ``formats/_core.pyi``), and the core compiles
that into one immutable ``formats._core.Machine`` (``crates/core/src/machine.rs``): the word
formats per unit system, how numbers without a point are read, the code table with its groups,
the reset state and what M02/M30 keep, the roles of P, Q and R, the limits, and every rule that
depends on the control family (a Fanuc or Haas lathe, LinuxCNC's G80, the centre codes...).

The checker, the converter (source and target), the diff and verify reader, the restart walk,
the modal machine and the plot all take the ``Machine`` of :func:`machine`, built once per
profile object and shared across files, threads and gateway ports.
"""

from __future__ import annotations

import _thread

from formats import _core
from formats.codes import OWN_TABLE, Code
from formats.exact import text
from formats.profile import Profile
from formats.wordformat import WordFormat

__all__ = ["FormatEntry", "MachineSpec", "machine", "machine_spec"]

# A word format as the core reads it: address, digits before and after the point, signed, the
# zero suppression and whether the word has a decimal point.
FormatEntry = tuple[str, int, int, bool, str, bool]


# The spec is typed for the type checker (and the core's stub); at run time it is a plain
# dict: a TypedDict of 45 keys cost 4.5M instructions of every command's start-up to build.
TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from collections.abc import Iterable, Iterator
    from typing import TypedDict

    class MachineSpec(TypedDict):
        """A profile's facts as plain values: what ``_core.Machine`` is compiled from."""

        family: str  # the dialect: iso, fanuc, haas, sinumerik, heidenhain, linuxcnc
        lathe: bool
        formats: list[FormatEntry]
        formats_inch: list[FormatEntry] | None  # where they differ while inch is in force
        dwell_formats: list[FormatEntry]
        feed_rev_formats: list[FormatEntry]  # F in feed per revolution, metric, inch
        feed_rev_formats_inch: list[FormatEntry]
        explicit: bool
        increments: str | None  # letters read as whole numbers by a control reading increments
        alignment: bool
        percent: bool
        classification: str
        table_name: str
        g_codes: list[tuple[str, str] | None]  # (status, modal group) of G0..G999
        g_decimal: list[tuple[str, str, str]]  # ("91.1", status, modal group)
        m_codes: list[tuple[str, str] | None]
        program_number: str
        colon_stop: bool
        unknown_g: str | None  # "alarm", "warn", or None: the family decides
        unknown_m: str | None
        tv_check: bool
        arc_tolerance: float
        arc_tolerance_relative: float
        ijk: str
        repeatable: str
        m_classes: list[int]
        max_index: int
        max_parameter: int
        # checks.read_only: (first, last, what), beside the family's own list; None: none
        read_only: list[tuple[int, int, str]] | None
        # "alarm", "round", "round_computed", "unknown" or "any": a value past the word format
        past_decimals: str
        past_sequence: str
        meanings: list[tuple[str, str, str]]  # ("47", "text-engraving", "text engraving")
        code_words: list[tuple[str, str, str]]  # ("G71", "P", "N"): a word naming a block
        index_g: bool
        pqr: tuple[str | None, str | None, str | None]  # checks.pqr's roles; None: unstated
        travel: list[tuple[str, str, str]]
        work_offsets: list[tuple[int, str, str]]
        feed_max: str | None
        spindle_max: str | None
        # the limits that are a built-in profile's sample machine, not the user's own: bits 1
        # travel, 2 feed_max, 4 spindle_max, 8 tool_max (Profile.sample_limits)
        sample_limits: int
        tool_max: int | None
        rapid_rate: float
        reset: list[int]
        inch: int
        metric: int
        inch_code: str
        metric_code: str
        default_units: str
        limit_units: str  # the units of the limits and work offsets: the profile file's units
        units_kept_at_end: bool
        increment_digits: tuple[int, int]  # decimals of one least input increment, metric and inch
        g_code_system: str  # a FANUC lathe's G code system: "A", "B", "C"; "" elsewhere
        # what the dialect reads (formats.parser.Dialect.flags): the converter writes no `#`,
        # `[ ]` or `*` for a target whose dialect does not read it
        dialect: tuple[bool, bool, bool, bool, bool, bool, str]
else:
    MachineSpec = dict


#: The facility note of an Annex C classification that gives F its format in feed per
#: revolution (G95, a lathe's G99), where the control reads it to more decimals than a feed per
#: minute: ``(with feed per revolution facility, the F word becomes F034)``.
FEED_PER_REVOLUTION = "feed per revolution"


def _formats(formats: Iterable[WordFormat]) -> list[FormatEntry]:
    return [f.entry for f in formats]


def _increment_digits(profile: Profile) -> tuple[int, int]:
    """The decimals of one least input increment of ``profile``, metric and inch: those of
    its X format (:meth:`~formats.profile.Profile.least_increment`, without its ``Decimal``)."""
    return profile.word_format("X", "metric").after, profile.word_format("X", "inch").after


def _numbered(codes: dict[str, Code]) -> Iterator[tuple[str, Code]]:
    """The codes by the name the core gives them: ``G47`` as ``G47``, ``G05`` as ``G5``,
    ``G91.1`` as it is, ``M08`` as ``M8``."""
    for key, code in codes.items():
        number, dot, rest = key[1:].partition(".")
        yield f"{key[0]}{int(number)}{dot}{rest}", code


# Profile.sample_limits as the core's bits (check::SAMPLE_TRAVEL ...)
_SAMPLE_BITS = {"travel": 1, "feed_max": 2, "spindle_max": 4, "tool_max": 8}


def machine_spec(profile: Profile) -> MachineSpec:
    """What the core needs from ``profile``, as plain values."""
    checks, limits = profile.checks, profile.limits

    def codes(letter: str, count: int) -> list[tuple[str, str] | None]:
        """(status, duration) of each code 0 to count - 1 as ``profile.code`` finds it: the
        profile's own codes over its table's, without making a code object of each number."""
        states = (profile.table.g if letter == "G" else profile.table.m).states(count)
        for key, c in profile.extra_codes.items():
            if key[:1] == letter and key[1:].isdecimal():
                number = int(key[1:])
                if number < count and key == f"{letter}{number:02d}":
                    states[number] = (c.status, c.duration)
        return states

    family = profile.dialect.family
    return {
        "family": family,
        "lathe": profile.control_type == "lathe",
        "formats": _formats(profile.detailed.formats.values()),
        "formats_inch": None if profile.detailed_inch is None
        else _formats(profile.detailed_inch.formats.values()),
        "dwell_formats": _formats(profile.detailed.facilities.get("dwell", {}).values()),
        "feed_rev_formats": _formats(
            profile.detailed.facilities.get(FEED_PER_REVOLUTION, {}).values()),
        "feed_rev_formats_inch": [] if profile.detailed_inch is None else _formats(
            profile.detailed_inch.facilities.get(FEED_PER_REVOLUTION, {}).values()),
        "explicit": profile.explicit,
        "increments": profile.numbers.whole_letters(),
        "alignment": profile.detailed.alignment,
        "percent": profile.detailed.program_start,
        "classification": str(profile.detailed),
        # TG301's "not a code of ...": the standard's table, or the profile's own list
        "table_name": (f"the code list of profile {profile.name}" if profile.table is OWN_TABLE
                       else profile.table.name),
        "g_codes": codes("G", 1000),
        "g_decimal": [(key[1:], c.status, c.duration) for key, c in profile.extra_codes.items()
                      if key.startswith("G") and "." in key],
        # ISO 6983-1 reads M1xx as class 1 of M00-M99; the other families have M100-M999
        "m_codes": codes("M", 100 if family == "iso" else 1000),
        "program_number": profile.program_number,
        "colon_stop": profile.comment_colon() == "stop",
        "unknown_g": checks.unknown_g,
        "unknown_m": checks.unknown_m,
        "tv_check": profile.serial.tv_check,
        # the profile's exact numbers by their texts (formats.exact: no Decimal made)
        "arc_tolerance": float(text(checks, "arc_tolerance")),
        "arc_tolerance_relative": float(text(checks, "arc_tolerance_relative")),
        "ijk": checks.ijk,
        "repeatable": "".join(sorted(checks.repeatable)),
        "m_classes": sorted(checks.m_classes),
        "max_index": checks.max_index,
        "max_parameter": checks.max_parameter,
        "read_only": None if checks.read_only is None else list(checks.read_only),
        "past_decimals": checks.past_decimals,
        "past_sequence": checks.past_sequence,
        # the codes the profile lists itself: (the code as the core names it, "47" for G47,
        # "91.1", "M98"; its meaning key, "" where it gives none; the function as the profile
        # words it). Between two control families the converter compares them by key, or by
        # function where a key is missing, and refuses a G code the target does not list.
        "meanings": [(key[1:] if key[0] == "G" else key, c.meaning, c.function)
                     for key, c in _numbered(profile.extra_codes) if c.status != "unassigned"],
        # a FANUC lathe's G code system, "A", "B" or "C" ("" for other controls): the core
        # reads B's and C's codes by their system A numbers
        "g_code_system": profile.g_code_system,
        "code_words": [(key, letter, address) for key, c in profile.extra_codes.items()
                       for letter, address in c.words],
        "index_g": checks.index_g,
        "pqr": (checks.pqr.get("P"), checks.pqr.get("Q"), checks.pqr.get("R")),
        "travel": [(axis, low, high) for axis, (low, high) in text(limits, "axes").items()],
        "work_offsets": [(int(g[1:]), axis, value)
                         for g, axes in text(profile, "work_offsets").items()
                         for axis, value in axes.items()],
        "feed_max": text(limits, "feed_max"),
        "spindle_max": text(limits, "spindle_max"),
        "sample_limits": sum(bit for key, bit in _SAMPLE_BITS.items()
                             if key in profile.sample_limits),
        "tool_max": limits.tool_max,
        "rapid_rate": float(text(limits, "rapid_rate")),
        "reset": [int(c[1:]) for c in profile.reset_state()],
        # -1: no G code selects the units (units_codes = "none"), the machine's parameter does
        "inch": int(profile.inch_code[1:]) if profile.units_by_code else -1,
        "metric": int(profile.metric_code[1:]) if profile.units_by_code else -1,
        "inch_code": profile.inch_code,
        "metric_code": profile.metric_code,
        "default_units": profile.default_units,
        "limit_units": profile.limit_units or profile.default_units,
        "units_kept_at_end": profile.units_kept_at_end,
        "increment_digits": _increment_digits(profile),
        "dialect": profile.dialect.flags,
    }


# Held while a machine is built: `-j`'s threads ask for it at their first files at once, and
# one built it while the others waited for it (under callgrind, whose slowness lets the
# interpreter's switch interval pass while it is built, each thread built its own:
# docs/benchmarks.md, "what -j 2 adds")
_BUILDING = _thread.allocate_lock()


def machine(profile: Profile) -> _core.Machine:
    """The core's compiled machine of ``profile``: built on first use and kept with the profile
    object (a profile is immutable), so every file, thread and port of it shares one, built
    once."""
    compiled = profile.__dict__.get("_machine")
    if compiled is None:
        with _BUILDING:
            compiled = profile.__dict__.get("_machine")
            if compiled is None:
                compiled = _core.Machine(_spec(profile))
                object.__setattr__(profile, "_machine", compiled)
    return compiled


def keep_compiled(name: str, profile: Profile) -> None:
    """Keep what ``tapegate check`` takes of the built-in profile ``name``, which ``profile``
    was loaded from, for its next run (:func:`formats.profile_cache.store_compiled`): its
    machine spec and its dialect's flags. Only a built-in profile written on no ``base`` (the
    entry is keyed by its own text), read from a text with the cache on."""
    from formats import profile_cache
    from formats.profile import builtin_names, builtin_text

    if profile.__dict__.get("_spec_key") is None or name not in builtin_names():
        return
    table = profile_cache.load(name, builtin_text(name))
    if table is None or "base" in table:
        return
    profile_cache.store_compiled(name, profile.dialect.flags, _spec(profile))


def _spec(profile: Profile) -> MachineSpec:
    """:func:`machine_spec` of ``profile``, kept between runs in the user's cache folder for a
    profile read from a text (a built-in profile, a profile file: the key
    :func:`formats.profile.profile_from_text` gave it), and read back from there: the spec
    was most of the machine's build (1.1 of 1.3 ms), which the first file of each command
    waits for, and ``-j``'s other workers with it (docs/benchmarks.md, "the machine spec kept
    between runs"). A profile made otherwise (``with_start_units``, ``dataclasses.replace``)
    has no key: its spec is made each time."""
    key = profile.__dict__.get("_spec_key")
    if key is None:
        return machine_spec(profile)
    from formats import profile_cache

    kept = profile_cache.load_spec(key)
    if kept is not None:
        return kept  # type: ignore[return-value]
    spec = machine_spec(profile)
    profile_cache.store_spec(key, spec)  # type: ignore[arg-type]
    return spec
