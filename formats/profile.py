"""Machine profiles: everything that differs between machines, in one TOML file each.

A profile names the Annex B and Annex C classifications, the G/M code table, the units codes,
the control type (for the reset states of clause 14), the characters allowed beyond Annex A,
limits, checker settings and the serial link. Built-in profiles ship in ``formats/profiles``;
a user's own ``.toml`` file works wherever a profile name does. The schema is documented in
``docs/profiles.md``; every bad key or value is a :class:`ProfileError` naming the key.
"""

from __future__ import annotations

import math
import os

from formats.classification import DetailedClassification, GeneralClassification
from formats.codes import OWN_TABLE, TABLES, Code, CodeTable
from formats.errors import FormatSpecError, ProfileError, TapegateError
from formats.exact import Text, Texts, exact_fields, shown, table_keys
from formats.parser import Dialect
from formats.records import NEW, FrozenRecord, field, init_fields, new, record
from formats.wordformat import WordFormat, count_format

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from collections.abc import Callable
    from decimal import Decimal
    from typing import Any

    from formats.codes import Status

    def _exact(text: str) -> Decimal:
        """A default of an exact field: its text, made a ``Decimal`` when read."""
else:
    _exact = Text  # (formats.exact: the field's text until it is read)

# the defaults of exact fields, as their texts
_RAPID_RATE = _exact("5000")
_ARC_TOLERANCE = _exact("0.0282843")
_ARC_RELATIVE = _exact("0.001")

CONTROL_TYPES = ("positioning", "line", "contouring", "lathe")
RESET_STATES = {
    # ISO 6983-1 clause 14
    "positioning": ("G00", "G40", "G71", "G80", "G90", "G94"),
    "line": ("G00", "G40", "G71", "G80", "G90", "G94"),
    "contouring": ("G01", "G17", "G40", "G71", "G80", "G90", "G94"),
    "lathe": ("G01", "G40", "G71", "G80", "G90", "G94", "G97"),
}
EOB_STYLES = {"lf": "\n", "crlf": "\r\n", "lfcrcr": "\n\r\r", "cr": "\r"}
PQR_ROLES = ("length", "parameter", "other")


def _default_pqr() -> dict[str, str]:
    return {"P": "parameter", "Q": "parameter", "R": "parameter"}


@record
class SerialSettings(FrozenRecord):
    """A machine's serial link: framing, pace and flow control."""

    baud: int = 9600
    data_bits: int = 7
    parity: str = "even"  # none | even | odd
    stop_bits: int = 2
    code: str = "iso"  # iso | eia
    parity_mode: str = "uart"  # uart | software
    flow: str = "xonxoff"  # xonxoff | rtscts | none
    flow_by: str = "tapegate"  # tapegate | driver: who obeys DC1/DC3
    eob: str = "lf"  # lf | crlf | lfcrcr
    leader: int = 20  # leader characters before "%"
    leader_char: str = "nul"  # nul | del | space
    trailer: int = 20
    tv_check: bool = False  # pad odd-length blocks with a space (Fanuc TV check)
    overrun_allowance: int = 10  # characters the control accepts after it sent DC3
    dc3_reaction: float | None = None  # the longest the host may take to see a DC3, seconds
    # (None: the command's own default: 0 for one port, the gateway's dc3_reaction for many)
    wait_for_dc1: bool = True
    xon_timeout: float = 30.0  # seconds to wait for DC1 (start or resume)
    char_delay: float = 0.0  # seconds after each character when flow = none
    line_delay: float = 0.0  # seconds after each end of block when flow = none
    dc_codes: bool = True  # the control sends DC2/DC4 around what it punches

    def __init__(self, baud: int = 9600, data_bits: int = 7, parity: str = "even",
                 stop_bits: int = 2, code: str = "iso", parity_mode: str = "uart",
                 flow: str = "xonxoff", flow_by: str = "tapegate", eob: str = "lf",
                 leader: int = 20, leader_char: str = "nul", trailer: int = 20,
                 tv_check: bool = False, overrun_allowance: int = 10,
                 dc3_reaction: float | None = None, wait_for_dc1: bool = True,
                 xon_timeout: float = 30.0, char_delay: float = 0.0, line_delay: float = 0.0,
                 dc_codes: bool = True) -> None:
        init_fields(self, baud, data_bits, parity, stop_bits, code, parity_mode, flow, flow_by,
                    eob, leader, leader_char, trailer, tv_check, overrun_allowance, dc3_reaction,
                    wait_for_dc1, xon_timeout, char_delay, line_delay, dc_codes)


@record
class NumberReading(FrozenRecord):
    """How the control reads a word written without a decimal point, in a DS program."""

    without_point: str = "whole"  # whole (ISO 6983-1, Siemens, LinuxCNC) | increments (Fanuc)
    whole: frozenset[str] = frozenset()  # addresses read as whole numbers all the same

    def __init__(self, without_point: str = "whole", whole: frozenset[str] = frozenset()) -> None:
        init_fields(self, without_point, whole)

    def increments(self, letter: str) -> bool:
        return self.without_point == "increments" and letter not in self.whole

    def whole_letters(self) -> str | None:
        """For the core: the letters read as whole numbers anyway by a control that reads
        increments, or None for a control that reads every word without a point as a whole
        number."""
        return "".join(sorted(self.whole)) if self.without_point == "increments" else None


@record
class Limits(FrozenRecord):
    """A machine's travel, feed, spindle and tool limits and its rapid rate."""

    axes: dict[str, tuple[Decimal, Decimal]] = field(default_factory=dict)
    feed_max: Decimal | None = None
    spindle_max: Decimal | None = None
    tool_max: int | None = None
    rapid_rate: Decimal = _RAPID_RATE  # for cycle-time estimates, in program units a minute

    def __init__(self, axes: dict[str, tuple[Decimal, Decimal]] = NEW,
                 feed_max: Decimal | None = None, spindle_max: Decimal | None = None,
                 tool_max: int | None = None, rapid_rate: Decimal = _RAPID_RATE) -> None:
        init_fields(self, new(axes, dict), feed_max, spindle_max, tool_max, rapid_rate)


# kept as their texts until read (formats.exact): no decimal before a batch's threads
exact_fields(Limits, {"axes": dict, "feed_max": None, "spindle_max": None, "rapid_rate": "5000"})


@record
class CheckSettings(FrozenRecord):
    """How the checker reads a machine: arc tolerances, unknown codes, indices, P/Q/R."""

    # LinuxCNC's figures: an arc's start and end radii may differ by max(0.0282843 mm, 0.1 % of
    # the radius), capped at 100 times the absolute part (2.8284 mm); in inch 0.0028284 in (a
    # tenth of the mm figure, as LinuxCNC has it), capped at 0.28284 in
    arc_tolerance: Decimal = _ARC_TOLERANCE
    arc_tolerance_relative: Decimal = _ARC_RELATIVE
    ijk: str = "incremental"  # incremental (7.3 recommended) | absolute | quadrant (sign-less)
    repeatable: frozenset[str] = frozenset()  # non-dimensional words allowed twice in a block
    m_classes: frozenset[int] = frozenset({0, 1})
    max_index: int = 9  # of an indexed axis, feed, spindle... (6.2)
    max_parameter: int = 999  # of a parameter: the index is its memory location (6.4.7)
    index_g: bool = False  # G1= ...: "the indexing of G codes is not intended" (6.2.2)
    pqr: dict[str, str] = field(default_factory=_default_pqr)
    # How the control answers a G or M code it does not have: "alarm" (an error, TG306) or
    # "warn" (TG301/TG302 warnings); None: alarm for G codes on the controls of a dialect
    # family, warn for M codes (they go to the machine builder's logic) and under ISO
    unknown_g: str | None = None
    unknown_m: str | None = None
    # What the control does with decimals past its least input increment, and with a
    # sequence number longer than the N format: "alarm" (TG203/TG205 errors, ISO 6983-1's
    # formats), "round" (documented rounding: TG208, a warning), "unknown" (the manuals do not
    # say: TG208, a warning), "any" (no least increment, as LinuxCNC: nothing said)
    past_decimals: str = "alarm"
    past_sequence: str = "alarm"
    # What a ':' inside a comment does: "stop" where the control's tape reader searches for
    # ':' as its alignment (rewind) stop even there, "text" where it reads the comment as text;
    # None: Profile.comment_colon's default
    comment_colon: str | None = None
    # The numbered variables a program may read but not set, as the control's documentation
    # lists them: (first, last, what it holds), beside the dialect family's own list (Custom
    # Macro B's, LinuxCNC's, the core's); None: none stated. An assignment to one is TG209.
    read_only: tuple[tuple[int, int, str], ...] | None = None

    def __init__(self, arc_tolerance: Decimal = _ARC_TOLERANCE,
                 arc_tolerance_relative: Decimal = _ARC_RELATIVE, ijk: str = "incremental",
                 repeatable: frozenset[str] = frozenset(),
                 m_classes: frozenset[int] = frozenset({0, 1}), max_index: int = 9,
                 max_parameter: int = 999, index_g: bool = False, pqr: dict[str, str] = NEW,
                 unknown_g: str | None = None, unknown_m: str | None = None,
                 past_decimals: str = "alarm", past_sequence: str = "alarm",
                 comment_colon: str | None = None,
                 read_only: tuple[tuple[int, int, str], ...] | None = None) -> None:
        init_fields(self, arc_tolerance, arc_tolerance_relative, ijk, repeatable, m_classes,
                    max_index, max_parameter, index_g, new(pqr, _default_pqr), unknown_g,
                    unknown_m, past_decimals, past_sequence, comment_colon, read_only)


exact_fields(CheckSettings, {"arc_tolerance": "0.0282843", "arc_tolerance_relative": "0.001"})


@record
class RestartSettings(FrozenRecord):
    """How ``send --restart-at`` approaches the restart block (docs/dnc.md): the clearance
    height the tool rapids at, in the profile's ``units``; None: the highest the program went
    before the restart block. ``clearance_x`` is a lathe's: the diameter it retracts to."""

    clearance: Decimal | None = None
    clearance_x: Decimal | None = None

    def __init__(self, clearance: Decimal | None = None,
                 clearance_x: Decimal | None = None) -> None:
        init_fields(self, clearance, clearance_x)


exact_fields(RestartSettings, {"clearance": None, "clearance_x": None})


_NUMBERS = NumberReading()  # the defaults a profile shares
_RESTART = RestartSettings()


@record
class Profile(FrozenRecord):
    """A machine profile: everything that differs between machines, validated."""

    name: str
    description: str
    general: GeneralClassification
    detailed: DetailedClassification
    table: CodeTable
    # (inch code, metric code): ("G70", "G71") or ("G20", "G21"); ("", "") for a control whose
    # units are a parameter of the machine only (units_codes = "none": an Okuma OSP lathe)
    units_codes: tuple[str, str]
    default_units: str  # metric | inch
    control_type: str
    dialect: Dialect
    program_number: str  # "" or the address of a program number word, e.g. "O"
    extra_codes: dict[str, Code]
    limits: Limits
    checks: CheckSettings
    serial: SerialSettings
    source: str  # "built-in" or the file it was read from
    reset: tuple[str, ...] = ()  # the control's own reset state, where it departs from clause 14
    numbers: NumberReading = _NUMBERS
    # The word formats while inch is in force, where the control's differ (Annex B class N
    # controls accept both: Fanuc IS-B writes X+053 in mm and X+044 in inches); None: the same.
    detailed_inch: DetailedClassification | None = None
    restart: RestartSettings = _RESTART
    # The machine position of each work zero the profile knows: {"G54": {"X": -400, ...}}, in
    # the profile's units ([work_offsets]); where the program selects one of them, the checker
    # compares machine positions with the travel.
    work_offsets: dict[str, dict[str, Decimal]] = field(default_factory=dict)
    # The regular expressions (with named groups) of the lines the control's macros print on
    # its serial port (DPRNT) that the gateway takes as machine data (dnc.dataline); None: the
    # gateway's defaults for the usual Fanuc and Haas forms.
    data_patterns: tuple[str, ...] | None = None
    # The units of the limits and the work offsets, where the units the machine starts in were
    # given otherwise (:func:`with_start_units`); None: ``default_units``.
    limit_units: str | None = None
    # A FANUC lathe's G code system (parameter No. 3401 GSB/GSC): "A", "B" or "C"; "" for every
    # other control. B and C number the lathe's codes otherwise (docs/dialects.md).
    g_code_system: str = ""
    # The limits that are a built-in profile's sample machine of the family, not the user's:
    # of "travel", "feed_max", "spindle_max" and "tool_max", every one on a built-in profile,
    # none on a user's file without a base, and on a file with a base those its own [limits]
    # do not set (the travel: unless it sets every axis the profile has a travel for)
    # (:func:`sample_limits`). A limit passed on the sample machine is said so.
    sample_limits: frozenset[str] = frozenset()

    def __init__(self, name: str, description: str, general: GeneralClassification,
                 detailed: DetailedClassification, table: CodeTable,
                 units_codes: tuple[str, str], default_units: str, control_type: str,
                 dialect: Dialect, program_number: str, extra_codes: dict[str, Code],
                 limits: Limits, checks: CheckSettings, serial: SerialSettings, source: str,
                 reset: tuple[str, ...] = (), numbers: NumberReading = _NUMBERS,
                 detailed_inch: DetailedClassification | None = None,
                 restart: RestartSettings = _RESTART,
                 work_offsets: dict[str, dict[str, Decimal]] = NEW,
                 data_patterns: tuple[str, ...] | None = None,
                 limit_units: str | None = None, g_code_system: str = "",
                 sample_limits: frozenset[str] = frozenset()) -> None:
        init_fields(self, name, description, general, detailed, table, units_codes, default_units,
                    control_type, dialect, program_number, extra_codes, limits, checks, serial,
                    source, reset, numbers, detailed_inch, restart, new(work_offsets, dict),
                    data_patterns, limit_units, g_code_system, sample_limits)

    # -- reading values ------------------------------------------------------------------

    @property
    def explicit(self) -> bool:
        return self.detailed.explicit_decimal

    def word_format(self, letter: str, units: str | None = None) -> WordFormat:
        """The format of ``letter``; ``units`` "inch" takes the inch formats where the profile
        has them."""
        if units == "inch" and self.detailed_inch is not None:
            fmt = self.detailed_inch.formats.get(letter)
            if fmt is not None:
                return fmt
        fmt = self.detailed.formats.get(letter)
        return fmt if fmt is not None else _fallback_format(letter)

    def __getstate__(self) -> dict[str, Any]:
        """A profile pickles as its settings: the core's compiled machine kept with it
        (``formats.machine.machine``) is not pickled, the process that loads it compiles its
        own (nor the key of its kept spec: that process makes the spec)."""
        return {k: v for k, v in self.__dict__.items() if k not in ("_machine", "_spec_key")}

    def __setstate__(self, state: dict[str, Any]) -> None:
        self.__dict__.update(state)

    def least_increment(self, units: str) -> Decimal:
        """One least input increment of the control in ``units`` (IS-B: 0.001 mm, 0.0001 in):
        the resolution of its X format. A length a cycle writes as a count (the Fanuc lathe's
        ``G76 P1200 Q350``) counts these; the converter and the comparison both read it here."""
        return self.word_format("X", units).resolution

    def value(self, token: str, units: str | None = None) -> Decimal:
        """Exact value of a plain word token (``X-12.5``, ``X1=3``) under this profile, in the
        formats of ``units`` (the profile's default units when None)."""
        letter = token[0].upper()
        body = token[1:]
        if "=" in body:
            body = body.split("=", 1)[1]
        sign = ""
        if body[:1] in "+-":
            sign, body = body[0], body[1:]
        fmt = self.word_format(letter, units or self.default_units)
        # (the letters a control counting increments reads whole are whole in an
        # implicit-decimal program too, as the core's `Numbers::no_point` reads them)
        numbers = self.numbers
        whole = numbers.without_point == "increments" and letter in numbers.whole
        return fmt.read(sign, body, self.explicit or whole, numbers.increments(letter))

    def code(self, letter: str, number: int) -> Code | None:
        extra = self.extra_codes.get(f"{letter}{number:02d}")
        return extra if extra is not None else self.table.lookup(letter, number)

    @property
    def units_by_code(self) -> bool:
        """Whether a program selects its units with a G code; False where the machine's
        parameters alone set them (``units_codes = "none"``): then no G code is a units code,
        and a change of units is the machine's setting, not a word of the program."""
        return bool(self.units_codes[0])

    @property
    def inch_code(self) -> str:
        return self.units_codes[0]

    @property
    def metric_code(self) -> str:
        return self.units_codes[1]

    @property
    def units_kept_at_end(self) -> bool:
        """Whether the control keeps the units a program selected through its M02/M30, so that
        a program after it (a Haas local subprogram, a second program of the file) runs in
        them: a Fanuc, a Haas (Setting 9) and LinuxCNC do, and so is read a program whose
        units codes are G20/G21, the codes of that lineage (the neutral profile reading one).
        Clause 14 puts G71 in the reset state, and a Sinumerik returns to its machine data's
        G70/G71 (MD20150); a HEIDENHAIN program states its units in its first line."""
        family = self.dialect.family
        return family in ("fanuc", "haas", "linuxcnc") or (
            family == "iso" and self.inch_code == "G20")

    def comment_colon(self) -> str:
        """What a ':' in a comment does on this control: ``checks.comment_colon``, or by default
        "stop" for an ISO 6983-1 control whose classification has the alignment function ':'
        (its tape reader searches the tape for ':'), "text" for one without it and for the
        dialect families (Fanuc, Haas, Siemens, Heidenhain and LinuxCNC read a comment as
        text)."""
        if self.checks.comment_colon is not None:
            return self.checks.comment_colon
        return "stop" if self.dialect.family == "iso" and self.detailed.alignment else "text"

    def reset_state(self) -> tuple[str, ...]:
        """The modes at power-on and after M02/M30: clause 14 for the control type, or the
        profile's ``reset`` list (the exceptions the detailed format classification states).
        A ``reset`` list names the units code of the profile's units: a profile that changes
        ``units`` and keeps its base's list (``base = "fanuc-mill"``, ``units = "inch"``) powers
        on in G20, not in the base's G21."""
        if self.reset:
            if not self.units_by_code:
                return self.reset
            inch = self.default_units == "inch"
            code, other = ((self.inch_code, self.metric_code) if inch
                           else (self.metric_code, self.inch_code))
            return tuple(code if c == other and code else c for c in self.reset)
        codes = RESET_STATES[self.control_type]
        if not self.units_by_code:
            return tuple(c for c in codes if c != "G71")
        if self.units_codes != ("G70", "G71") or self.default_units == "inch":
            unit = self.metric_code if self.default_units == "metric" else self.inch_code
            codes = tuple(unit if c == "G71" else c for c in codes)
        return codes


exact_fields(Profile, {"work_offsets": dict})


_FALLBACK = {
    letter: WordFormat(letter, 5, 4, signed=True) for letter in "XYZUVWPQRABCIJKE"
} | {"F": WordFormat("F", 5, 4), "S": WordFormat("S", 5, 3)}


def _fallback_format(letter: str) -> WordFormat:
    return _FALLBACK.get(letter) or count_format(letter)


# ---------------------------------------------------------------------------------------------
# Loading


# The package's own folder: the extension module makes it a directory on disk, never a zip, and
# importlib.resources would cost every command a tenth of its start-up. (os.path, not pathlib:
# a check by a built-in profile then does not import pathlib, urllib.parse and ipaddress.)
_BUILTIN = os.path.join(os.path.dirname(os.path.realpath(__file__)), "profiles")


def builtin_names() -> list[str]:
    return sorted(name[:-5] for name in os.listdir(_BUILTIN) if name.endswith(".toml"))


def builtin_text(name: str) -> str:
    if name == "neutral":
        return NEUTRAL_TOML
    with open(os.path.join(_BUILTIN, f"{name}.toml"), encoding="utf-8") as f:
        return f.read()


def load_profile(name_or_path: str) -> Profile:
    """A built-in profile by name (``neutral`` included), or a user's TOML file by path."""
    if name_or_path == "neutral":
        return neutral()
    if name_or_path in builtin_names():
        return profile_from_text(builtin_text(name_or_path), source="built-in",
                                 default_name=name_or_path, cache_as=name_or_path)
    # a user's file: its name as pathlib reads and shows it, without pathlib (its import is
    # 18M instructions of a conversion's start-up; docs/benchmarks.md, "the commits without
    # the GIL")
    from formats.files import pure

    path = pure(name_or_path)
    name = os.path.basename(path)
    dot = name.rfind(".")  # (PurePath.suffix and .stem)
    suffix, stem = (name[dot:], name[:dot]) if 0 < dot < len(name) - 1 else ("", name)
    if suffix == ".toml" or os.path.exists(path):  # (False for a name too long, or a NUL)
        try:
            with open(path, encoding="utf-8") as f:
                text = f.read()
        except OSError as exc:
            raise ProfileError(f"cannot read profile: {exc.strerror}", file=path,
                               code="profile-unreadable") from None
        except UnicodeDecodeError as exc:  # a binary file
            raise ProfileError(f"cannot read profile: not UTF-8 text ({exc.reason} at byte "
                               f"{exc.start})", file=path, code="profile-unreadable"
                               ) from None
        return profile_from_text(text, source=path, default_name=stem,
                                 cache_as=FILE_CACHE_NAME)
    raise ProfileError(
        f"no profile named {name_or_path!r}; built-in profiles: {', '.join(builtin_names())} "
        "(or give the path of a .toml file)", code="profile-not-found"
    )


# The name a profile file's parsed TOML is kept under (formats.profile_cache): its text decides
# whether an entry is used, whatever file held it.
FILE_CACHE_NAME = "file"


def profile_from_text(text: str, source: str = "<text>", default_name: str = "", *,
                      cache_as: str | None = None) -> Profile:
    """The profile of a TOML ``text``. ``cache_as``: the name its parsed TOML is kept under
    between runs (:mod:`formats.profile_cache`): a built-in profile's name, or
    :data:`FILE_CACHE_NAME` for a user's profile file."""
    data = _toml(text, source, cache_as)
    on_base = "base" in data
    own = data.get("limits") if on_base else None
    try:
        if on_base:
            data = _on_base(data, source)
        profile = _build(data, source, default_name)
    except ProfileError as exc:
        raise exc.located(file=source) from None
    sample = sample_limits(source == "built-in", on_base, own if isinstance(own, dict) else {},
                           profile.limits)
    if sample:
        object.__setattr__(profile, "sample_limits", sample)
    if cache_as is not None:  # the core's machine spec kept between runs too, by what made it
        from formats import profile_cache

        # (the file's own limits decide the spec too: the merged data alone does not say them)
        key = profile_cache.spec_key(data, source, default_name, sorted(sample))
        if key is not None:
            object.__setattr__(profile, "_spec_key", key)
    return profile


SAMPLE_LIMITS = frozenset({"travel", "feed_max", "spindle_max", "tool_max"})


def sample_limits(builtin: bool, on_base: bool, own: dict[str, Any],
                  limits: Limits) -> frozenset[str]:
    """The limits of a profile that are a built-in profile's sample machine
    (:attr:`Profile.sample_limits`): every one of a built-in profile (``builtin``); of a
    user's file written on a base (``on_base``), each its own ``[limits]`` table (``own``, read
    before the merge) does not set -- the travel where it does not set every axis the profile
    has a travel for; none of a user's file without a base, whose limits are all its own."""
    if builtin:
        return SAMPLE_LIMITS
    if not on_base:
        return frozenset()
    sample = {key for key in ("feed_max", "spindle_max", "tool_max") if key not in own}
    # (the axes' names, not their travels: no Decimal made, and no decimal imported, for a
    # conversion to a user's profile on a base; docs/benchmarks.md, perf40)
    if any(axis not in own for axis in table_keys(limits, "axes")):
        sample.add("travel")
    return frozenset(sample)


def _toml(text: str, source: str, cache_as: str | None) -> dict[str, Any]:
    if cache_as is not None:
        from formats import profile_cache

        kept = profile_cache.load(cache_as, text)
        if kept is not None:
            return kept
    import tomllib  # (a built-in profile read from the cache does not need it)

    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ProfileError(f"not valid TOML: {exc}", file=source, code="profile-toml") from None
    if cache_as is not None:
        profile_cache.store(cache_as, text, data)
    return data


# The tables a profile written on a base merges key by key; any other key replaces the base's.
_MERGED_TABLES = ("codes", "numbers", "limits", "checks", "serial", "restart", "work_offsets")


def _on_base(data: dict[str, Any], source: str, seen: tuple[str, ...] = ()) -> dict[str, Any]:
    """A profile written on a built-in one (``base = "fanuc-lathe"``): the base's keys, each
    of ``data``'s replacing the base's, its tables merged key by key; a ``[codes]`` entry
    ``false`` drops the base's code (the control has no such code: TG307 where a program writes
    it). So the parts two profiles share are written once: FANUC's G code systems B and C
    are system A's table with the codes they number otherwise (docs/profiles.md, ``base``)."""
    name = data["base"]
    if not isinstance(name, str) or name == "neutral" or name not in builtin_names():
        raise ProfileError(f"base must name a built-in profile ({', '.join(builtin_names())}), "
                           f"not {name!r}", key="base", code="profile-base")
    if name in seen:
        raise ProfileError(f"base: {' -> '.join((*seen, name))} returns to {name}", key="base",
                           code="profile-base")
    base = _toml(builtin_text(name), f"built-in {name}", name)
    if "base" in base:
        base = _on_base(base, source, (*seen, name))
    merged = {key: value for key, value in base.items() if key != "name"}
    for key, value in data.items():
        if key == "base":
            continue
        if key in _MERGED_TABLES and isinstance(value, dict) and isinstance(merged.get(key), dict):
            merged[key] = (_merged_codes(merged[key], value) if key == "codes"
                           else {**merged[key], **value})
        else:
            merged[key] = value
    return merged


def spindle_notes(profile: Profile) -> list[str]:
    """What a profile's spindle codes leave out, for ``tapegate profiles show``: a modal M03 or
    M04 (ISO 6983-1's and every builder's spindle start) keyed with a meaning that turns no
    spindle is not one to the checker, so ``M03 M04`` is TG308, a warning, where an unkeyed
    one's (ISO 6983-1's meaning) or a turning key's is TG304 (crates/core check::turning_codes;
    reviews 56a F1, 56d F5)."""
    from formats._core import TURNING_KEYS  # (the core's one list: check::turning_codes)

    notes: list[str] = []
    if profile.dialect.family == "iso":
        # (ISO 6983-1 keeps every pair of one group TG304)
        return notes
    for number, key in ((3, "spindle-cw"), (4, "spindle-ccw")):
        code = profile.code("M", number)
        if (code is not None and code.duration not in ("", "TBO")
                and code.meaning and code.meaning not in TURNING_KEYS):
            notes.append(
                f"M{number:02d} ({code.function}) is in modal group {code.duration} with "
                f"meaning {code.meaning!r}: the checker does not take it to turn a spindle "
                f"(two codes of its group in a block a warning, TG308, not TG304); if it "
                f"starts the spindle, give it meaning = \"{key}\" "
                f"(docs/profiles.md, \"Code meanings\")")
    return notes


def _code_name(key: str) -> str:
    """A ``[codes]`` key as the code it names: ``M3`` and ``M03`` are one code."""
    return key[0] + str(int(key[1:])) if key[1:].isdigit() else key


def _one_spelling(codes: dict[str, Any]) -> None:
    """Refuses a ``[codes]`` table that writes one code twice (``M3`` and ``M03``): which of
    the two the profile means cannot be told, and taking either would decide silently what
    a code of the machine does (review 56d F4)."""
    seen: dict[str, str] = {}
    for code in codes:
        first = seen.setdefault(_code_name(code), code)
        if first != code:
            raise ProfileError(f"codes: {first} and {code} name one code; write it once",
                               key=f"codes.{code}", code="profile-code-twice")


def _merged_codes(base: dict[str, Any], own: dict[str, Any]) -> dict[str, Any]:
    """A base's ``[codes]`` with a profile's entries: each replaces the base's entry of the
    same code (``M3`` or ``M03``), and ``false`` drops it; an entry that sets no ``meaning``
    keeps the base's. The meaning keys are what says which codes turn a spindle (TG304 for
    ``M03 M04``, the restart's spindle), so rewording a builder's ``function`` must not drop
    them silently (review 56a F1); ``meaning = ""`` drops one on purpose."""
    _one_spelling(own)
    names = {_code_name(code): code for code in base}
    table = dict(base)
    for code, spec in own.items():
        old = names.get(_code_name(code))
        previous = table.pop(old) if old is not None else None
        if spec is False:
            continue
        if (isinstance(spec, dict) and "meaning" not in spec and isinstance(previous, dict)
                and "meaning" in previous):
            spec = {**spec, "meaning": previous["meaning"]}
        table[code] = spec
    return table


class Keys:
    """Typed access to one TOML table that names the key in every error (profiles, the gateway
    configuration)."""

    def __init__(self, data: dict[str, Any], prefix: str, known: set[str] | frozenset[str],
                 error: type[TapegateError] = ProfileError):
        self.data = data
        self.prefix = prefix
        self.error = error
        unknown = set(data) - known
        if unknown:
            key = sorted(unknown)[0]
            raise error(
                f"unknown key {prefix}{key!r}; known keys: {', '.join(sorted(known))}",
                key=prefix + key, code=error.unknown_key_code)

    def get(self, key: str, kind: type | tuple[type, ...], default: Any) -> Any:
        value = self.data.get(key, default)
        if kind is int and isinstance(value, bool):
            raise self.error(f"{self.prefix}{key} must be an integer, not {value!r}",
                             key=self.prefix + key)
        if not isinstance(value, kind):
            kinds = (kind,) if isinstance(kind, type) else kind
            names = " or ".join(k.__name__ for k in kinds)
            raise self.error(f"{self.prefix}{key} must be {names}, not {value!r}",
                             key=self.prefix + key)
        return value

    def choice(self, key: str, choices: tuple[str, ...] | list[str], default: str) -> str:
        value = self.get(key, str, default)
        if value not in choices:
            raise self.error(
                f"{self.prefix}{key} = {value!r}: choose one of {', '.join(choices)}",
                key=self.prefix + key)
        return str(value)

    def number(self, key: str, default: Decimal | None, minimum: float | Decimal | None = None
               ) -> Decimal | None:
        """The number under ``key`` (``default`` where it is not given), at least ``minimum``:
        a TOML integer or float as its text (``str(value)``), which an exact field makes the
        ``Decimal`` ``Decimal(str(value))`` when it is read (:mod:`formats.exact`: no
        ``decimal`` at a profile's load); a number written as a TOML string, read by
        ``Decimal`` as before. The type checker reads either as a ``Decimal``."""
        value = self.data.get(key)
        if value is None:
            return default
        if isinstance(value, bool) or not isinstance(value, int | float | str):
            raise self.error(f"{self.prefix}{key} must be a number, not {value!r}",
                             key=self.prefix + key)
        if isinstance(value, str):
            from decimal import Decimal

            try:
                result = Decimal(value)
            except ArithmeticError:
                raise self.error(f"{self.prefix}{key} must be a number, not {value!r}",
                                 key=self.prefix + key) from None
            finite = result.is_finite()
        else:  # (an int or a float compares with the minimum as its exact Decimal does)
            finite = math.isfinite(value)
        if not finite:
            raise self.error(f"{self.prefix}{key} must be a finite number, not {value!r}",
                             key=self.prefix + key)
        if minimum is not None and (result if isinstance(value, str) else value) < minimum:
            raise self.error(f"{self.prefix}{key} must be at least {minimum}, not {value}",
                             key=self.prefix + key)
        return result if isinstance(value, str) else _exact(str(value))


_TOP = {"base", "name", "description", "general", "detailed", "code_table", "units_codes", "units",
        "control_type", "lowercase", "extra_characters", "program_number", "codes", "limits",
        "checks", "serial", "reset", "numbers", "detailed_inch", "dialect", "restart",
        "work_offsets", "data_patterns", "g_code_system"}

# The control families whose statements the core reads (docs/dialects.md).
DIALECTS = ("iso", "fanuc", "haas", "sinumerik", "heidenhain", "linuxcnc", "okuma")


def _build(data: dict[str, Any], source: str, default_name: str) -> Profile:
    top = Keys(data, "", _TOP)
    name = top.get("name", str, default_name or "profile")
    try:
        general = GeneralClassification.parse(top.get("general", str, "DM 333"))
    except FormatSpecError as exc:
        raise ProfileError(f"general: {exc.message}", key="general",
                               code="profile-classification") from None
    try:
        detailed = DetailedClassification.parse(
            top.get("detailed", str, "%:/DS N04 G02 X+053 Y+053 Z+053 I+053 J+053 K+053 F051 "
                                     "S04 T04 M02*"))
    except FormatSpecError as exc:
        raise ProfileError(f"detailed: {exc.message}", key="detailed",
                               code="profile-classification") from None
    detailed_inch = None
    if "detailed_inch" in data:
        try:
            detailed_inch = DetailedClassification.parse(top.get("detailed_inch", str, ""))
        except FormatSpecError as exc:
            raise ProfileError(f"detailed_inch: {exc.message}", key="detailed_inch",
                               code="profile-classification") from None
        if detailed_inch.explicit_decimal != detailed.explicit_decimal:
            raise ProfileError("detailed_inch must have DS exactly where detailed has it",
                               key="detailed_inch", code="profile-classification")
    table_name = top.choice("code_table", [*TABLES, OWN_TABLE.name], "iso6983-1")
    table = OWN_TABLE if table_name == OWN_TABLE.name else TABLES[table_name]
    units_codes = top.choice("units_codes", ("G70/G71", "G20/G21", "none"), "G70/G71")
    extra = top.get("extra_characters", str, "")
    bad = [ch for ch in extra if not ch.isprintable() or ch.isalnum() or ch == " "]
    if bad:
        raise ProfileError(f"extra_characters: {bad[0]!r} cannot be an extra character",
                           key="extra_characters")
    dialect = Dialect(lowercase=top.get("lowercase", bool, False), extra=frozenset(extra),
                      family=top.choice("dialect", DIALECTS, "iso"))
    program_number = top.get("program_number", str, "")
    if program_number not in ("", "O", "P", ":"):
        raise ProfileError("program_number must be \"\", \"O\", \"P\" or \":\"",
                           key="program_number")
    if units_codes == "G20/G21":
        inch, metric = "G20", "G21"
    elif units_codes == "none":
        inch, metric = "", ""
    else:
        inch, metric = "G70", "G71"
    extra_codes = _codes(top.get("codes", dict, {}))
    if inch:
        extra_codes = _designate_units_codes(table, (inch, metric), extra_codes)
    reset = tuple(str(c) for c in top.get("reset", list, []))
    for code in reset:
        number = _g_code(code)
        if number is None:
            raise ProfileError(f"reset: {code!r} is not a G code such as \"G90\"", key="reset")
        known = extra_codes.get(code) or table.lookup("G", number)
        if known is None or not known.modal:
            raise ProfileError(f"reset: {code} is not a modal code of the {table.name} table "
                               "or the profile's [codes]", key="reset")
    control_type = top.choice("control_type", CONTROL_TYPES, "contouring")
    limits = _limits(top.get("limits", dict, {}))
    g_code_system = _g_code_system(top, control_type, dialect.family)
    if "g_code_system" in data:  # (written, or the base's: a lathe of its own keeps A's default)
        _g_code_system_agrees(g_code_system,
                              lambda n: extra_codes.get(f"G{n}") or table.lookup("G", n))
    work_offsets = _work_offsets(top.get("work_offsets", dict, {}), limits, control_type,
                                 dialect.family)
    return Profile(
        name=name,
        description=top.get("description", str, ""),
        general=general,
        detailed=detailed,
        table=table,
        units_codes=(inch, metric),
        default_units=top.choice("units", ("metric", "inch"), "metric"),
        control_type=control_type,
        dialect=dialect,
        program_number=program_number,
        extra_codes=extra_codes,
        limits=limits,
        checks=_checks(top.get("checks", dict, {})),
        serial=_serial(top.get("serial", dict, {})),
        source=source,
        reset=reset,
        numbers=_numbers(top.get("numbers", dict, {})),
        detailed_inch=detailed_inch,
        restart=_restart(top.get("restart", dict, {})),
        work_offsets=work_offsets,
        data_patterns=_data_patterns(data["data_patterns"]) if "data_patterns" in data else None,
        g_code_system=g_code_system,
    )


def _g_code_system(top: Keys, control_type: str, family: str) -> str:
    """``g_code_system``: a FANUC lathe's G code system, "A" (the default of such a lathe), "B"
    or "C"; "" for every other control. The core reads a lathe's cycles, feed modes, threading
    and coordinate setting by their system A numbers and translates B's and C's to them."""
    fanuc_lathe = control_type == "lathe" and family == "fanuc"
    if "g_code_system" not in top.data:
        return "A" if fanuc_lathe else ""
    system = top.choice("g_code_system", ("A", "B", "C"), "A")
    if not fanuc_lathe:
        raise ProfileError("g_code_system is a FANUC lathe's parameter (No. 3401 GSB/GSC): it "
                           "needs control_type = \"lathe\" and dialect = \"fanuc\"",
                           key="g_code_system")
    return system


# What each G code system's code list says at the numbers the three differ on (the lathe's G
# code list, columns A, B and C, B-64604EN): G90 is system A's OD/ID cutting cycle and B's and
# C's absolute programming; the cycle is B's G77 and C's G20.
_SYSTEM_SIGNS = {
    "A": ((90, "turning-cycle"),),
    "B": ((90, "absolute-programming"), (77, "turning-cycle")),
    "C": ((90, "absolute-programming"), (20, "turning-cycle")),
}


def _g_code_system_agrees(system: str, lookup: Callable[[int], Any]) -> None:
    """Refuse a ``g_code_system`` that contradicts the profile's code list: the core reads the
    program's codes by the system and the checker and converter judge them by the list, so a
    list of system B read as system A (``base = "fanuc-lathe-b"`` with ``g_code_system =
    "A"``) would take B's G90 (absolute programming) for A's cutting cycle and convert it to
    system A unchanged. A profile that changes the system writes the codes of the new one in
    its ``[codes]``, as fanuc-lathe-b does on fanuc-lathe."""
    for number, meaning in _SYSTEM_SIGNS.get(system, ()):
        code = lookup(number)
        found = getattr(code, "meaning", "") if code is not None else ""
        if found != meaning:
            said = f"{found!r}" if found else ("no meaning" if code is not None else "no code")
            raise ProfileError(
                f"g_code_system = \"{system}\" contradicts the profile's code list: G{number} "
                f"is {meaning!r} in G code system {system}, the list gives it {said} (a "
                "profile on a base keeps the base's system unless its [codes] write the codes "
                "of the other system; docs/dialects.md, G code systems B and C)",
                key="g_code_system", code="profile-g-code-system")


def _data_patterns(value: Any) -> tuple[str, ...]:
    """``data_patterns``: a list of regular expressions, each with at least one named group."""
    if not isinstance(value, list):
        raise ProfileError(f"data_patterns must be a list of regular expressions, not {value!r}",
                           key="data_patterns")
    for i, pattern in enumerate(value):
        problem = data_pattern_problem(pattern)
        if problem:
            raise ProfileError(f"data_patterns[{i}] {problem}", key=f"data_patterns[{i}]")
    return tuple(value)


def data_pattern_problem(pattern: Any) -> str | None:
    """Why ``pattern`` cannot be a data pattern (profile or gateway configuration), or None."""
    if not isinstance(pattern, str):
        return f"must be a string, not {pattern!r}"
    import re  # (a profile with data patterns only: a check does not load it otherwise)

    try:
        compiled = re.compile(pattern)
    except re.error as exc:
        return f"is not a regular expression: {exc}"
    if not compiled.groupindex:
        return "needs at least one named group such as (?P<parts>\\d+): the groups are the data"
    if compiled.fullmatch(""):
        return "matches an empty line: every blank line would be data"
    return None


def _designate_units_codes(table: CodeTable, units_codes: tuple[str, str],
                           extra_codes: dict[str, Code]) -> dict[str, Code]:
    """The profile's codes with its units codes designated where its table leaves them
    unassigned: ISO 1056 leaves G70/G71 so, ISO 6983-1 G20/G21; a profile that selects its units
    with them designates them (the format specification's "*")."""
    codes = dict(extra_codes)
    for unit, code in zip(("inch", "metric"), units_codes, strict=True):
        known = table.lookup("G", int(code[1:]))
        if code not in codes and (known is None or not known.usable):
            codes[code] = Code("G", int(code[1:]),
                               f"dimension input {unit} (designated by the profile)", "m")
    return codes


def with_units_codes(profile: Profile, inch: str, metric: str) -> Profile:
    """``profile`` selecting its units with ``inch``/``metric`` (G20/G21 found in a program read
    with the neutral profile), the codes designated as a profile file's ``units_codes`` does."""
    import dataclasses

    return dataclasses.replace(
        profile, units_codes=(inch, metric),
        extra_codes=_designate_units_codes(profile.table, (inch, metric), profile.extra_codes))


def with_start_units(profile: Profile, units: str) -> Profile:
    """``profile`` on a machine whose units at the program's start are ``units`` (``--from-units``
    of ``convert``, ``--units`` of ``check``): the units a machine parameter sets where the
    control has no units code (an Okuma OSP lathe's UNIT parameter, docs/dialects.md), the units
    in force before the program's first units code where it has one (a units code in the
    program still wins). Its reset state (the profile's ``reset``) names the units code of
    ``units`` in place of the other."""
    import dataclasses

    if units not in ("metric", "inch"):
        raise ProfileError(f"units must be metric or inch, not {units!r}")
    if units == profile.default_units:
        return profile
    code = profile.inch_code if units == "inch" else profile.metric_code
    other = profile.metric_code if units == "inch" else profile.inch_code
    reset = tuple(code if c == other and code else c for c in profile.reset)
    return dataclasses.replace(profile, default_units=units, reset=reset,
                               limit_units=profile.limit_units or profile.default_units)


def _restart(data: dict[str, Any]) -> RestartSettings:
    keys = Keys(data, "restart.", {"clearance", "clearance_x"})
    for key in ("clearance", "clearance_x"):
        if key in data and not _is_number(data[key]):
            raise ProfileError(f"restart.{key} must be a number (a height in the profile's "
                               f"units, such as 50.), not {data[key]!r}",
                               key=f"restart.{key}")
    return RestartSettings(clearance=keys.number("clearance", None),
                           clearance_x=keys.number("clearance_x", None, 0))


def _numbers(data: dict[str, Any]) -> NumberReading:
    keys = Keys(data, "numbers.", {"without_point", "whole"})
    whole = keys.get("whole", str, "")
    bad = [ch for ch in whole if not ("A" <= ch <= "Z")]
    if bad:
        raise ProfileError(f"numbers.whole: {bad[0]!r} is not an address letter",
                           key="numbers.whole")
    return NumberReading(keys.choice("without_point", ("whole", "increments"), "whole"),
                         frozenset(whole))


# The addresses a word may name a block or a program by, in a code's `words`: a sequence
# number (N) or a program number (O).
NAMING_ADDRESSES = ("N", "O")


def _code_words(keys: Keys, key: str) -> tuple[tuple[str, str], ...]:
    """``codes.KEY.words``: ``{ P = "N", Q = "N" }``, the words that name a sequence number
    (N) or a program (O) in the code's blocks, and so take that address's format there."""
    words = keys.get("words", dict, {})
    result = []
    for letter, address in words.items():
        if len(letter) != 1 or not ("A" <= letter <= "Z") or letter in "GMNO":
            raise ProfileError(f"codes.{key}.words: {letter!r} is not the address of a word a "
                               "code's block may give", key=f"codes.{key}.words")
        if address not in NAMING_ADDRESSES:
            raise ProfileError(f"codes.{key}.words.{letter} must be \"N\" (the word names a "
                               f"sequence number) or \"O\" (a program), not {address!r}",
                               key=f"codes.{key}.words.{letter}")
        result.append((letter, address))
    return tuple(result)


# The keys and values below are read character by character, without regular expressions: a
# check does not import `re` (docs/benchmarks.md, "a check without re"). A digit of \d is
# any Unicode decimal digit (str.isdecimal), of [0-9] an ASCII one.


def _g_code(code: str) -> int | None:
    """``G(\\d{2,3})``: a G code of two or three digits (``reset``), its number."""
    digits = code[1:]
    if code[:1] == "G" and 2 <= len(digits) <= 3 and digits.isdecimal():
        return int(digits)
    return None


def _decimal_code(key: str) -> tuple[int, str] | None:
    """``G(\\d+)\\.(\\d)``: a decimal G code (``G91.1``), its whole number and its tenth."""
    whole, point, tenth = key[1:].partition(".")
    if key[:1] == "G" and point and whole.isdecimal() and len(tenth) == 1 and tenth.isdecimal():
        return int(whole), tenth
    return None


_MEANING_CHARACTERS = frozenset("abcdefghijklmnopqrstuvwxyz0123456789")


def _is_meaning(text: str) -> bool:
    """``[a-z0-9]+(?:-[a-z0-9]+)*``: lower case words (or digits) joined by hyphens."""
    return all(word and _MEANING_CHARACTERS.issuperset(word) for word in text.split("-"))


_CODE_KEYS = frozenset({"function", "duration", "status", "words", "meaning"})


# The keys of the codes most profiles list (``G01 = { function = "...", duration = "...",
# meaning = "..." }``), read without Keys when each is a string: its checks give nothing to
# tell there, and they were a third of making a code (docs/benchmarks.md, "the codes")
_PLAIN_CODE_KEYS = frozenset({"function", "duration", "meaning"})


def _codes(data: dict[str, Any]) -> dict[str, Code]:
    _one_spelling(data)
    result = {}
    for key, spec in data.items():
        decimal = _decimal_code(key) if "." in key else None
        if decimal is not None:  # G91.1, G54.1: a code of its own
            keys = Keys(spec if isinstance(spec, dict) else {}, f"codes.{key}.",
                        {"function", "duration", "words", "meaning"})
            name = f"G{decimal[0]}.{decimal[1]}"
            result[name] = Code("G", decimal[0],
                                keys.get("function", str, "designated by the profile"),
                                keys.get("duration", str, "TBO"), "assigned",
                                words=_code_words(keys, key), meaning=_meaning(keys, key))
            continue
        if len(key) < 2 or key[0] not in "GM" or not key[1:].isdigit():
            raise ProfileError(f"codes: {key!r} is not a G or M code such as \"G20\", "
                               "\"G91.1\" or \"M19\"", key=f"codes.{key}")
        if not isinstance(spec, dict):
            raise ProfileError(f"codes.{key} must be a table with function and duration",
                               key=f"codes.{key}")
        number = int(key[1:])
        function = spec.get("function", "designated by the profile")
        duration = spec.get("duration", "TBO")
        meaning = spec.get("meaning", "")
        if (type(function) is str and type(duration) is str and type(meaning) is str
                and _PLAIN_CODE_KEYS.issuperset(spec)
                and (not meaning or _is_meaning(meaning))):
            # what Keys reads from such a table, the same values (any other key, value or
            # meaning: Keys below, which reads it or names what is wrong)
            result[f"{key[0]}{number:02d}"] = Code(key[0], number, function, duration,
                                                   "assigned", meaning=meaning)
            continue
        keys = Keys(spec, f"codes.{key}.", _CODE_KEYS)
        # status "unassigned": a code of the code table the control has not (LinuxCNC's M10)
        status: Status = ("unassigned" if "status" in spec and keys.choice(
            "status", ("assigned", "unassigned"), "assigned") == "unassigned" else "assigned")
        # (the keys a code leaves out read as their defaults without a look: a profile's 200
        # codes were half of its loading, which a check's threads wait for)
        result[f"{key[0]}{number:02d}"] = Code(
            key[0], number, keys.get("function", str, "designated by the profile"),
            keys.get("duration", str, "TBO"), status,
            words=_code_words(keys, key) if "words" in spec else (),
            meaning=_meaning(keys, key) if "meaning" in spec else "")
    return result




def _meaning(keys: Keys, key: str) -> str:
    """A code's ``meaning``: a key in lower case words joined by hyphens
    (``"text-engraving"``), the same in every profile whose control gives the code that
    function (docs/profiles.md, "Code meanings"); "" where the profile gives none."""
    meaning: str = keys.get("meaning", str, "")
    if meaning and not _is_meaning(meaning):
        raise ProfileError(f"codes.{key}.meaning {meaning!r} must be lower case words joined by "
                           "hyphens, such as \"text-engraving\"", key=f"codes.{key}.meaning")
    return meaning


def _limits(data: dict[str, Any]) -> Limits:
    keys = Keys(data, "limits.", set("XYZUVWABC") | {"feed_max", "spindle_max", "tool_max",
                                                      "rapid_rate"})
    axes = {}
    for axis in "XYZUVWABC":
        if axis in data:
            pair = data[axis]
            if (not isinstance(pair, list) or len(pair) != 2
                    or not all(_is_number(v) for v in pair)):
                raise ProfileError(f"limits.{axis} must be [minimum, maximum]",
                                   key=f"limits.{axis}")
            low, high = (Text(v) for v in pair)  # (their Decimals made when read)
            if pair[0] > pair[1]:
                raise ProfileError(f"limits.{axis}: minimum {shown(low)} is above maximum "
                                   f"{shown(high)}", key=f"limits.{axis}")
            axes[axis] = (low, high)
    tool_max = keys.get("tool_max", (int, type(None)), None)
    return Limits(axes=Texts(axes) if axes else {},
                  feed_max=keys.number("feed_max", None, 0),
                  spindle_max=keys.number("spindle_max", None, 0),
                  tool_max=tool_max,
                  rapid_rate=keys.number("rapid_rate", _RAPID_RATE, 1) or _RAPID_RATE)


def _or_zero(value: Decimal | Text | None) -> Decimal:
    """``value or Decimal(0)`` of :meth:`Keys.number`'s value: a zero, as a text too
    (``0.0``), made ``0``."""
    if isinstance(value, Text):
        return _exact("0" if shown(value).strip("-0.") == "" else value)
    return value or _exact("0")


WORK_OFFSETS = ("G54", "G55", "G56", "G57", "G58", "G59")


def _work_offsets(data: dict[str, Any], limits: Limits, control_type: str,
                  family: str) -> dict[str, dict[str, Decimal]]:
    """``[work_offsets]``: ``G54 = { X = -400.0, Y = -200.0, Z = -350.0 }``, the machine
    position of each work zero in the profile's units, for the axes the profile has travel
    limits for. Refused where a work offset is not all that lies between a program position and
    the machine's: a lathe's tool offsets (T0101) move X and Z too, and a Heidenhain's G54 is a
    datum shift written in the program."""
    if not data:
        return {}
    if control_type == "lathe":
        raise ProfileError("work_offsets: not on a lathe: its tool offsets (T0101) move X and Z "
                           "as well, and the profile does not give them",
                           key="work_offsets")
    if family == "heidenhain":
        raise ProfileError("work_offsets: not on a Heidenhain: its G54 is a datum shift written "
                           "in the program, not a stored offset", key="work_offsets")
    offsets: dict[str, dict[str, Decimal]] = {}
    for code, axes in data.items():
        if code not in WORK_OFFSETS:
            raise ProfileError(f"work_offsets: {code!r} is not a work offset; use "
                               f"{', '.join(WORK_OFFSETS)}", key=f"work_offsets.{code}")
        if not isinstance(axes, dict) or not axes:
            raise ProfileError(f"work_offsets.{code} must be a table of axis positions such as "
                               "{ X = -400.0, Y = -200.0, Z = -350.0 }",
                               key=f"work_offsets.{code}")
        values: dict[str, Decimal] = {}
        for axis, value in axes.items():
            if axis not in "XYZUVWABC" or len(axis) != 1:
                raise ProfileError(f"work_offsets.{code}.{axis}: not an axis; the axes are "
                                   "X Y Z U V W A B C",
                                   key=f"work_offsets.{code}.{axis}")
            if axis not in limits.axes:
                raise ProfileError(f"work_offsets.{code}.{axis}: the profile has no limits.{axis} "
                                   "to compare the machine position with",
                                   key=f"work_offsets.{code}.{axis}")
            if not _is_number(value):
                raise ProfileError(f"work_offsets.{code}.{axis} must be a number (the machine "
                                   f"position of the work zero, in the profile's units), not "
                                   f"{value!r}", key=f"work_offsets.{code}.{axis}")
            values[axis] = _exact(str(value))  # (made a Decimal when read)
        offsets[code] = values
    return Texts(offsets)


def _is_number(value: object) -> bool:
    """A finite TOML number: TOML's nan and inf are no position, limit or tolerance."""
    return (isinstance(value, int | float) and not isinstance(value, bool)
            and math.isfinite(value))


PAST_FORMAT = ("alarm", "round", "unknown", "any")
# decimals may also be "round_computed": the manuals round a computed value (a variable's, an
# expression's) to the increment and say nothing of a written number's extra decimals
PAST_DECIMALS = PAST_FORMAT + ("round_computed",)


def _checks(data: dict[str, Any]) -> CheckSettings:
    keys = Keys(data, "checks.", {"arc_tolerance", "arc_tolerance_relative", "ijk", "repeatable",
                                   "m_classes", "max_index", "max_parameter", "index_g", "pqr",
                                   "unknown_g", "unknown_m", "comment_colon", "past_decimals",
                                   "past_sequence", "read_only"})
    repeatable = keys.get("repeatable", list, [])
    classes = keys.get("m_classes", list, [0, 1])
    if not all(isinstance(c, int) and 0 <= c <= 8 for c in classes):
        raise ProfileError("checks.m_classes must list class digits 0-8",
                           key="checks.m_classes")
    pqr = dict(CheckSettings().pqr)
    for letter, role in keys.get("pqr", dict, {}).items():
        if letter not in "PQR" or role not in PQR_ROLES:
            raise ProfileError(f"checks.pqr.{letter} = {role!r}: letters P Q R, roles "
                               f"{', '.join(PQR_ROLES)}", key=f"checks.pqr.{letter}")
        pqr[letter] = role
    return CheckSettings(
        arc_tolerance=_or_zero(keys.number("arc_tolerance", _ARC_TOLERANCE, 0)),
        arc_tolerance_relative=_or_zero(keys.number("arc_tolerance_relative", _ARC_RELATIVE,
                                                    0)),
        ijk=keys.choice("ijk", ("incremental", "absolute", "quadrant"), "incremental"),
        repeatable=frozenset(str(r) for r in repeatable),
        m_classes=frozenset(classes),
        max_index=keys.get("max_index", int, 9),
        max_parameter=keys.get("max_parameter", int, 999),
        index_g=keys.get("index_g", bool, False),
        pqr=pqr,
        # absent: None, the family's default (decided by the core's Machine)
        unknown_g=keys.choice("unknown_g", ("alarm", "warn"), "warn")
        if "unknown_g" in data else None,
        unknown_m=keys.choice("unknown_m", ("alarm", "warn"), "warn")
        if "unknown_m" in data else None,
        comment_colon=keys.choice("comment_colon", ("stop", "text"), "text")
        if "comment_colon" in data else None,
        past_decimals=keys.choice("past_decimals", PAST_DECIMALS, "alarm"),
        past_sequence=keys.choice("past_sequence", PAST_FORMAT, "alarm"),
        read_only=_read_only(keys.get("read_only", dict, {}))
        if "read_only" in data else None,
    )


def _variables(key: str) -> tuple[int, int] | None:
    """A read-only entry's key: a variable number (``3020``) or a range of them
    (``11000-11255``), each of 1 to 9 digits 0-9: (first, last), or None."""
    first, dash, last = key.partition("-")
    numbers = (first, last) if dash else (first,)
    if not all(1 <= len(n) <= 9 and n.isascii() and n.isdigit() for n in numbers):
        return None
    return int(first), int(last if dash else first)


def _read_only(table: dict[str, Any]) -> tuple[tuple[int, int, str], ...]:
    """`checks.read_only`: `"3020" = "the power-on timer"`, `"11000-11255" = "a discrete
    input"`: the variables (one or a range) with what each holds, as the message names it."""
    entries = []
    for key, what in table.items():
        match = _variables(key)
        first, last = match or (0, 0)
        if match is None or last < first:
            raise ProfileError(f"checks.read_only.{key}: a variable number or a range of them, "
                               "first-last (\"3020\", \"11000-11255\")",
                               key=f"checks.read_only.{key}")
        if not isinstance(what, str) or not what.strip():
            raise ProfileError(f"checks.read_only.{key} must say what the variable holds",
                               key=f"checks.read_only.{key}")
        entries.append((first, last, what.strip()))
    return tuple(sorted(entries))


_BAUDS = (110, 150, 300, 600, 1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200)


def serial_settings(data: dict[str, Any], base: SerialSettings | None = None,
                    prefix: str = "serial.", error: type[TapegateError] = ProfileError
                    ) -> SerialSettings:
    """A ``[serial]`` table read over ``base`` (the defaults): the keys it does not name keep
    their values from ``base``. Every error names the key."""
    from dataclasses import asdict

    merged = {**asdict(base), **data} if base is not None else data
    return _serial(merged, prefix, error)


def _serial(data: dict[str, Any], prefix: str = "serial.",
            error: type[TapegateError] = ProfileError) -> SerialSettings:
    d = SerialSettings()
    keys = Keys(data, prefix, set(SerialSettings.__record_fields__), error)
    baud = keys.get("baud", int, d.baud)
    if baud not in _BAUDS:
        raise error(f"{prefix}baud = {baud}: choose one of {', '.join(map(str, _BAUDS))}",
                    key=prefix + "baud")
    data_bits = keys.get("data_bits", int, d.data_bits)
    stop_bits = keys.get("stop_bits", int, d.stop_bits)
    if data_bits not in (7, 8):
        raise error(f"{prefix}data_bits must be 7 or 8", key=prefix + "data_bits")
    if stop_bits not in (1, 2):
        raise error(f"{prefix}stop_bits must be 1 or 2", key=prefix + "stop_bits")
    code = keys.choice("code", ("iso", "eia"), d.code)
    parity_mode = keys.choice("parity_mode", ("uart", "software"), d.parity_mode)
    parity = keys.choice("parity", ("none", "even", "odd"), d.parity)
    if code == "eia" and (parity_mode != "software" or data_bits != 8 or parity != "none"):
        raise error("serial: EIA code needs parity_mode = \"software\", data_bits = 8 and "
                    "parity = \"none\" (the UART cannot make EIA's track-5 parity)", key="serial")
    if parity_mode == "software" and (data_bits != 8 or parity != "none"):
        raise error("serial: parity_mode = \"software\" sets bit 8 itself: use "
                    "data_bits = 8 and parity = \"none\"", key="serial")
    return SerialSettings(
        baud=baud, data_bits=data_bits, parity=parity, stop_bits=stop_bits, code=code,
        parity_mode=parity_mode,
        flow=keys.choice("flow", ("xonxoff", "rtscts", "none"), d.flow),
        flow_by=keys.choice("flow_by", ("tapegate", "driver"), d.flow_by),
        eob=keys.choice("eob", tuple(EOB_STYLES), d.eob),
        leader=keys.get("leader", int, d.leader),
        leader_char=keys.choice("leader_char", ("nul", "del", "space"), d.leader_char),
        trailer=keys.get("trailer", int, d.trailer),
        tv_check=keys.get("tv_check", bool, d.tv_check),
        overrun_allowance=keys.get("overrun_allowance", int, d.overrun_allowance),
        dc3_reaction=_optional_float(keys.number("dc3_reaction", None, 0), d.dc3_reaction),
        wait_for_dc1=keys.get("wait_for_dc1", bool, d.wait_for_dc1),
        xon_timeout=_float(keys.number("xon_timeout", None, 0.01), 30),
        char_delay=_float(keys.number("char_delay", None, 0), 0),
        line_delay=_float(keys.number("line_delay", None, 0), 0),
        dc_codes=keys.get("dc_codes", bool, d.dc_codes),
    )


def _float(value: Decimal | None, default: float) -> float:
    """``float(value or default)`` of :meth:`Keys.number`'s value (a text or a ``Decimal``):
    a zero, or none, is ``default``."""
    number = 0.0 if value is None else float(value)
    return number or float(default)


def _optional_float(value: Decimal | None, default: float | None) -> float | None:
    return default if value is None else float(value)


# The permissive reading of a program for which no profile is given: a built-in profile by the
# name "neutral" everywhere a profile is named, though no file holds it.
NEUTRAL_TOML = ("name = \"neutral\"\n"
                "description = \"explicit decimal, metric, anything common accepted\"\n"
                "lowercase = true\nextra_characters = \"#[];\"\n"
                "detailed = \"%:/DS O09 N09 G03 X+054 Y+054 Z+054 U+054 V+054 "
                "W+054 P+054 Q+054 R+054 A+054 B+054 C+054 I+054 J+054 K+054 F054 "
                "E054 S06 T08 D03 M03 H03*\"\n")


_NEUTRAL: list[Profile] = []  # (kept here, not by functools.cache: a check does not import it)


def neutral() -> Profile:
    """The neutral profile (``NEUTRAL``), made when first used: one object for the process."""
    if not _NEUTRAL:
        _NEUTRAL.append(profile_from_text(NEUTRAL_TOML, source="built-in", cache_as="neutral"))
    return _NEUTRAL[0]


if TYPE_CHECKING:
    NEUTRAL: Profile
else:
    def __getattr__(name: str) -> Any:
        """``NEUTRAL``, made when first asked for (a check by a named profile never is)."""
        if name == "NEUTRAL":
            return neutral()
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
