"""Compare two programs as NC, not as text: ``tapegate diff``, ``convert --verify``, auto-receive.

Each program is read under its own profile, as the control would read it: every plain word
through the profile's word format and ``[numbers]`` reading (decimal point, implicit decimals,
zero suppression, Fanuc least input increments), in the units in force at its block (G20/G21 or
G70/G71, by the profile's units codes; a units code in the block itself is the units of the
values beside it). Values are then held in one unit system, metric, exactly:
an inch value times 25.4 and a surface speed in ft/min times 0.3048 are exact in
:mod:`decimal`, so nothing is rounded before the comparison. Whatever the spacing, the leading
zeros, the decimal style or the units, the same program compares the same.

What a word is, and so which unit it is in, follows the modal state of its own program, read here
on purpose apart from the converter (a converter's misreading is not repeated by its check), with
the core's semantics: G and M codes read as the core reads them (through the profile's format,
whole: ``G01`` = ``G1.0`` = G1, any number of leading zeros), and on a Fanuc or Haas lathe
(``dialect.family`` fanuc or haas, ``control_type`` lathe) G98/G99 for feed per minute and per
revolution, ``G50 S`` the spindle clamp and ``G50 X Z`` a setting of position. The reset state
is the profile's reset codes, applied in order as the core applies them. A word is compared as:

=================  ============================================================================
word               compared as
=================  ============================================================================
X Y Z U V W I J K  a length (mm), except X U P F in a G04 dwell block (a time, as written)
A B C              an angle, as written
F E                a feed (mm/min, mm/rev) in G94 and G95; as written in G93 (inverse time)
S                  a surface speed (m/min) in G96, except ``G92 S`` (``G50 S`` on a lathe: a
                   speed clamp); else rpm
P Q R              a length where the profile's ``checks.pqr`` says so; else a number; in a
                   cycle, as the family's cycle table says (G71 P Q numbers, U R D lengths,
                   the Fanuc lathe's G76 P Q lengths in least input increments)
N G M T D H O L    a count or a code: its value exactly (``G01`` = ``G1``, ``G91.1`` is its own)
expressions        their text (upper case); ``#`` parameters likewise
=================  ============================================================================

The units codes themselves are not compared as words: their meaning is in every value after them.
A word whose number cannot be read (more than the 38 significant digits tapegate reads, more digits
than its format holds) is compared as written: the same word in the other program is the same,
any other is the located error of reading it.

A difference is accepted within ``tolerance`` resolution steps of **B's** word format (B is the
target: the received or converted program), and reported with its size in those steps. In G91
the axis words of both programs are compared as positions: the difference carried from the
words before is added, so that a conversion that keeps the exact absolute path (and may change an
increment by a step to do so) compares the same, and a step lost on the way does not.

Blocks are paired by sequence number or by position (:class:`DiffOptions.pair`):

* **by number**: the two programs are merged in sequence-number order, each numbered block
  together with the unnumbered blocks after it; a number lower than the one before starts a new
  run (the next program of the file), so the merge stays in order. This streams: nothing is held
  beyond the group of blocks being compared (the blocks of one number are aligned by position).
* **by position**: the blocks are aligned as they come, looking ahead ``window`` blocks on each side
  (64) to tell an added or removed block from a changed one. Memory is that window, whatever the
  size of the programs.
* **auto** (the default) looks at the first 1,000 blocks of each program and pairs by number when
  most blocks of both carry one.

Blank blocks are never compared, nor (with ``ignore_comments``) comment-only blocks or comments.
With ``motion`` the modal state after every block -- motion mode, plane, distance and feed modes,
feed, spindle, coolant, compensation, tool, cycle and the end point -- is taken from the core's
modal state machine (:class:`postproc.state.ModalMachine`) for both programs and compared, so
the answer is also whether the two programs move the machine the same way; the units, distance,
feed and spindle modes read here are checked against the core's at every block, so the two
readings cannot drift apart. A motion difference is reported where it starts or changes, not again
at every block after it.

The entry points are :func:`diff_files` (two files) and :class:`Differ` (block streams); a
difference is a :class:`BlockDiff`, and :attr:`Differ.summary` counts what was compared.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, field, replace
from decimal import (
    Context,
    Decimal,
    DivisionByZero,
    Inexact,
    InvalidOperation,
    Overflow,
    localcontext,
)
from fractions import Fraction
from itertools import chain, groupby, islice
from typing import Any, Literal

from formats import _core
from formats.errors import TapegateError
from formats.model import Block, split_token
from formats.parser import BadBlock, Errors, parse_stream
from formats.profile import Profile
from formats.source import Source
from formats.wordformat import WordFormat, Zeros

__all__ = ["BlockDiff", "DiffError", "DiffOptions", "DiffSummary", "Differ", "MotionChange",
           "NcBlock", "NcWord", "ProgramReader", "WordChange", "diff_files", "steps_text"]

MM_PER_INCH = Decimal("25.4")
M_PER_FOOT = Decimal("0.3048")
AXES = "XYZUVWABC"
LENGTH_AXES = "XYZUVW"
AUTO_LOOK = 1000  # blocks of each program that pair="auto" looks at
ONE = Decimal(1)

Kind = Literal["code", "units", "length", "feed", "speed", "number", "text"]
Pairing = Literal["auto", "number", "position"]


class DiffError(TapegateError):
    """Two programs that cannot be compared (a block that cannot be read, a modal drift)."""


@dataclass(frozen=True)
class DiffOptions:
    """How to compare. ``tolerance`` is in resolution steps of B's word format (0: exactly)."""

    tolerance: Decimal = Decimal(0)
    ignore_comments: bool = False
    motion: bool = False  # compare the modal state and end point after every block too
    pair: Pairing = "auto"
    word_order: bool = False  # the same words in another order is a difference
    # The largest difference accepted per address, in B's units, beside the tolerance (verify:
    # the rounding the converter reported).
    bounds: Mapping[str, Fraction] | None = None
    window: int = 64
    errors: Errors = "raise"  # "collect": a block the profile cannot read is compared as text
    # Parameters and expressions (6.4.7): compared as written ("text"), or only by their address
    # ("address": convert --verify, where their units follow the parameter analysis).
    parameters: Literal["text", "address"] = "text"
    # A P, Q or R word of no stated role (``checks.pqr`` "parameter") beside one the other
    # profile says is a length: read as that length ("adopt"), or both as written ("written":
    # convert --verify --allow-unconverted, which leaves such words as they are).
    unstated: Literal["adopt", "written"] = "adopt"
    # convert --verify: a word of the same value, read by the same format in both programs and
    # written in the source as that format writes it (``G01``, ``T0101``, ``P100``, ``X1.5``),
    # is the same text byte for byte -- a conversion has no reason to touch it, and the value
    # comparison alone takes ``G1`` for ``G01`` and ``T101`` for ``T0101``.
    same_text: bool = False


@dataclass(slots=True)
class NcWord:
    """One word as the control reads it."""

    key: str  # address and index: "X", "X1", "#1"
    token: str  # as written (upper case for text words)
    kind: Kind
    value: Decimal | None  # in the metric unit of its kind; None for text
    factor: Decimal  # the value as written times this is ``value``
    step: Decimal  # one step of the word's format, in the unit of ``value``
    incremental: bool = False  # an axis word in G91
    parameter: bool = False  # a parameter assignment or an expression (6.4.7)
    as_length: Decimal | None = None  # P Q R of no stated role: the factor were it a length
    error: DiffError | None = None  # why its number could not be read (compared as written)
    per_revolution: bool = False  # a feed in G95 (G99 on a Fanuc or Haas lathe)
    written: str = ""  # the token exactly as written (``token`` is upper case)
    form: tuple[WordFormat, bool, bool] | None = None  # (format, explicit program, increments)

    @property
    def unit(self) -> str:
        if self.kind == "feed" and self.per_revolution:
            return "mm/rev"
        return _UNIT.get(self.kind, "")


_UNIT = {"length": "mm", "feed": "mm/min", "speed": "m/min"}


@dataclass(slots=True)
class NcBlock:
    """One block as the control reads it, with where it was written."""

    line: int
    text: str
    number: Decimal | None  # the sequence number (N), if any
    words: tuple[NcWord, ...]
    comments: tuple[str, ...]
    resets: bool = False  # G92, G28, G30, G53, M02/M30/M99: positions start again after it
    state: dict[str, Any] | None = None  # the core's modal state after the block (motion)

    @property
    def shown(self) -> str:
        return self.text.strip(" \t\r\x00\x7f")


@dataclass(frozen=True, slots=True)
class WordChange:
    kind: Literal["added", "removed", "changed", "order", "written"]
    key: str
    a: NcWord | None
    b: NcWord | None
    difference: Decimal | None = None  # B - A (as a position in G91), in the unit of the kind
    steps: Fraction | None = None  # ``difference`` in steps of B's format

    def describe(self) -> str:
        if self.kind == "order":
            return "words in another order"
        if self.kind == "written":
            assert self.a is not None and self.b is not None
            return f"{self.a.written} written {self.b.written}"
        if self.a is None:
            return f"{_tok(self.b)} added"
        if self.b is None:
            return f"{_tok(self.a)} removed"
        text = f"{self.a.token} -> {self.b.token}"
        if self.difference is not None and self.steps is not None:
            unit = f" {self.a.unit}" if self.a.unit else ""
            text += f" ({_signed(self.difference)}{unit}, {steps_text(self.steps)})"
        elif (self.a.token == self.b.token and self.a.value is not None
              and self.b.value is not None):  # one word, read otherwise under each profile
            text += f" (read as {_plain(self.a.value)} and as {_plain(self.b.value)})"
        return text

    def as_json(self) -> dict[str, Any]:
        item: dict[str, Any] = {"kind": self.kind, "address": self.key}
        for side, word in (("a", self.a), ("b", self.b)):
            if word is not None:
                item[side] = word.token
                if word.value is not None:
                    item[f"{side}_value"] = _plain(word.value)
        if self.a is not None and self.a.unit:
            item["unit"] = self.a.unit
        if self.difference is not None:
            item["difference"] = _plain(self.difference)
        if self.steps is not None:
            item["steps"] = steps_text(self.steps, unit=False)
            assert self.b is not None
            item["step"] = _plain(self.b.step)
        return item


@dataclass(frozen=True, slots=True)
class MotionChange:
    what: str  # "position X", "feed", "motion"...
    a: str
    b: str
    difference: Decimal | None = None  # B - A of a value, in its metric unit

    def describe(self) -> str:
        return f"{self.what} {self.a} -> {self.b}"

    @property
    def signature(self) -> tuple[Any, ...]:
        """What makes it news: for a value, its difference (a position off by the same amount
        block after block is one difference)."""
        if self.difference is not None:
            return (self.what, self.difference)
        return (self.what, self.a, self.b)


@dataclass(slots=True)
class BlockDiff:
    """One difference: a block only in A (removed), only in B (added), or changed."""

    kind: Literal["added", "removed", "changed"]
    a: NcBlock | None
    b: NcBlock | None
    words: list[WordChange] = field(default_factory=list)
    comments: tuple[tuple[str, ...], tuple[str, ...]] | None = None
    motion: list[MotionChange] = field(default_factory=list)

    def details(self) -> list[str]:
        """What differs, one item each (changed blocks)."""
        out = [w.describe() for w in self.words]
        if self.comments is not None:
            a, b = (" ".join(c) or "none" for c in self.comments)
            out.append(f"comments {a} -> {b}")
        if self.motion:
            out.append("then " + ", ".join(m.describe() for m in self.motion))
        return out

    def describe(self, name_a: str, name_b: str) -> str:
        """One line, as the journal and ``convert --verify`` say it."""
        if self.b is None:
            assert self.a is not None
            return f"line {self.a.line} of {name_a}: {self.a.shown!r} not in {name_b}"
        if self.a is None:
            return f"line {self.b.line} of {name_b}: {self.b.shown!r} not in {name_a}"
        return (f"line {self.a.line} of {name_a}: {self.a.shown!r} is {self.b.shown!r} in "
                f"{name_b} (line {self.b.line}): " + "; ".join(self.details()))

    def as_json(self) -> dict[str, Any]:
        item: dict[str, Any] = {"kind": self.kind}
        for side, block in (("a", self.a), ("b", self.b)):
            if block is not None:
                item[side] = {"line": block.line, "text": block.shown}
                if block.number is not None:
                    item[side]["number"] = _plain(block.number)
        if self.kind == "changed":
            item["words"] = [w.as_json() for w in self.words]
            if self.comments is not None:
                item["comments"] = {"a": list(self.comments[0]), "b": list(self.comments[1])}
            if self.motion:
                item["motion"] = [{"what": m.what, "a": m.a, "b": m.b} for m in self.motion]
        return item


@dataclass
class DiffSummary:
    blocks_a: int = 0
    blocks_b: int = 0
    paired: int = 0
    changed: int = 0
    added: int = 0
    removed: int = 0
    pairing: str = ""
    largest: dict[str, Fraction] = field(default_factory=dict)  # address -> |steps|, changed
    other: int = 0  # changed blocks with more than values changed (words, comments, motion)

    @property
    def same(self) -> bool:
        return not (self.changed or self.added or self.removed)

    def as_json(self) -> dict[str, Any]:
        return {"same": self.same, "pairing": self.pairing, "blocks_a": self.blocks_a,
                "blocks_b": self.blocks_b, "paired": self.paired, "changed": self.changed,
                "added": self.added, "removed": self.removed,
                "largest_steps": {k: steps_text(v, unit=False)
                                  for k, v in sorted(self.largest.items())}}


# ---------------------------------------------------------------------------------------------
# Numbers


_EXACT = Context(prec=200, traps=[Inexact, InvalidOperation, DivisionByZero, Overflow])


def _exact() -> Any:
    """A decimal context in which every product and sum is exact, or raises."""
    return localcontext(_EXACT)


def _plain(value: Decimal) -> str:
    """``12.5``, ``-0.001``, ``10`` (no exponent)."""
    text = f"{value.normalize():f}" if value else "0"
    return text


def _signed(value: Decimal) -> str:
    return ("+" if value > 0 else "") + _plain(value)


def steps_text(steps: Fraction, unit: bool = True) -> str:
    """``+1000 steps``, ``-1 step``, ``+0.394 steps`` (three decimals where not whole)."""
    if steps.denominator == 1:
        text = f"{steps.numerator:+d}" if steps and unit else str(steps.numerator)
    else:
        with localcontext() as ctx:
            ctx.prec = 60
            value = (Decimal(steps.numerator) / Decimal(steps.denominator)).quantize(
                Decimal("0.001"))
        text = ("+" if value > 0 and unit else "") + f"{value:f}"
    if not unit:
        return text
    return f"{text} {'step' if abs(steps) == 1 else 'steps'}"


def _tok(word: NcWord | None) -> str:
    return "" if word is None else word.token


# ---------------------------------------------------------------------------------------------
# Reading a program as the control reads it


class ProgramReader:
    """Blocks of one program -> :class:`NcBlock`, read under ``profile``.

    The words are read by the core (``crates/core/src/ncread.rs``: the table above, and the
    little modal state the units depend on -- units, distance, feed and spindle modes -- from
    the profile's reset state); here they become :class:`NcWord` objects. With ``motion`` the
    core's modal state machine runs beside it, its state is kept on every block, and the two
    are held to each other.
    """

    def __init__(self, profile: Profile, *, file: str, options: DiffOptions) -> None:
        self.profile = profile
        self.file = file
        self.options = options
        self._core = _core.DiffReader(_reader_config(profile))
        self._decimals: dict[str, Decimal] = {}  # a step's text -> its Decimal
        self._forms: dict[tuple[str, int], tuple[WordFormat, bool, bool]] = {}
        self._machine: Any = None
        self._factors: dict[str, Decimal] = {}
        if options.motion:
            from postproc.state import ModalMachine

            self._machine = ModalMachine(profile)
            self._reset = self._machine._core.state  # the control's own reset state

    @property
    def feed_mode(self) -> int:
        """The feed mode read here after the last block (94, 95 or 93)."""
        return self._core.modes[3]

    @property
    def incremental(self) -> bool:
        return self._core.incremental

    @incremental.setter
    def incremental(self, value: bool) -> None:
        self._core.incremental = value

    def _units_code_now(self) -> str:
        """The units code that selects the units of lengths and of the feed read here."""
        units, feed_units = self._core.modes[:2]
        if self.profile.dialect.family == "sinumerik" and feed_units != self.profile.default_units:
            return "G700" if feed_units == "inch" else "G710"
        return self.profile.inch_code if units == "inch" else self.profile.metric_code

    def read(self, blocks: Iterable[Block]) -> Iterator[NcBlock]:
        for block in blocks:
            nc = self.block(block)
            if nc is not None:
                yield nc

    def _form(self, letter: str, form: int) -> tuple[WordFormat, bool, bool]:
        """(format, explicit program, increments) a word of ``letter`` was read by: the
        profile's format in the units the core says (``form`` 1: inch), or (``form`` 2) the
        least-increment reading of a length a cycle writes as a count."""
        found = self._forms.get((letter, form))
        if found is None:
            units = "inch" if form & 1 else "metric"
            fmt = self.profile.word_format(letter, units)
            if form & 2:
                step = self.profile.least_increment(units)
                fmt = replace(fmt, decimal=True, after=-int(step.as_tuple().exponent))
                found = (fmt, self.profile.explicit, True)
            else:
                found = (fmt, self.profile.explicit, self.profile.numbers.increments(letter))
            self._forms[(letter, form)] = found
        return found

    def _decimal(self, text: str) -> Decimal:
        found = self._decimals.get(text)
        if found is None:
            found = self._decimals[text] = Decimal(text)
        return found

    def block(self, block: Block) -> NcBlock | None:
        """The block as read, or None for a block with nothing to compare."""
        if isinstance(block, BadBlock):
            text = block.text.strip(" \t\r\x00\x7f").upper()
            return NcBlock(block.line, block.text, None,
                           (NcWord("?", text, "text", None, ONE, ONE),), ())
        tokens = block.words
        read, dwell, clamp, units_code, ended, resets = self._core.read(tokens)
        words = []
        number = None
        for i, (tok, (key, kind, value, factor, step, incremental, parameter, as_length, error,
                      per_revolution, form)) in enumerate(zip(tokens, read, strict=True)):
            word = NcWord(key, tok.upper(), kind,  # type: ignore[arg-type]
                          None if value is None else Decimal(value), _FACTORS[factor],
                          self._decimal(step), incremental=incremental, parameter=parameter,
                          as_length=None if as_length is None else _FACTORS[as_length],
                          per_revolution=per_revolution)
            if error is not None:  # compared as written; the error where the word differs
                word.error = DiffError(error, file=self.file, line=block.line,
                                       column=block.word_objects()[i].column, clause="Annex C")
            elif form is not None:
                word.written, word.form = tok, self._form(key[0], form)
            if key == "N" and number is None:
                number = word.value
            words.append(word)
        info = block.info
        if info is not None:
            if info.percent:
                words.insert(0, NcWord("%", "%", "text", None, ONE, ONE))
            if info.skip:
                words.insert(0, NcWord("/", info.skip, "text", None, ONE, ONE))
        comments: tuple[str, ...] = ()
        if not self.options.ignore_comments and info is not None:
            comments = tuple(text for _, text in info.comments)
            if info.percent and info.ident:
                comments = (info.ident, *comments)
        state = None
        if self._machine is not None:
            state = self._machine_state(block, words, dwell, clamp, units_code, ended)
            self._hold_to_core(block, state)
        if not words and not comments:
            return None
        return NcBlock(block.line, block.text, number, tuple(words), comments, resets=resets,
                       state=state)

    def _machine_state(self, block: Block, words: list[NcWord], dwell: bool, clamp: bool,
                       units_code: bool, ended: bool) -> dict[str, Any]:
        """The core's modal state after the block, with the unit each value was set in."""
        core = self._machine._core
        if units_code:
            # The core's machine reads a block's values in the units before it, its units
            # code aside (postproc.state.ModalMachine.apply; its checker and converter do
            # not): hand it the units first, so that it reads the values as the control.
            core.apply([self._units_code_now()])
        self._machine.apply(block)
        state: dict[str, Any] = core.state
        factors = self._factors
        for word in words:  # the unit each value of the state was set in
            if word.value is None:  # an expression, or a number not read: the core's
                continue  # state keeps the value it had, in its unit
            if word.key in AXES and not dwell or word.key == "F" and not dwell:
                factors[word.key] = word.factor
            elif word.key == "S" and not clamp:
                factors["S"] = word.factor
        state["factors"] = dict(factors)
        state["reset"] = self._reset
        if ended and (state["units"], state["feed_units"]) != self._core.modes[:2]:
            # The core's machine resets the units too (the checker's reading of clause 14);
            # the converter keeps them, and so does this comparison: hand it the code.
            core.apply([self._units_code_now()])
            state = {**core.state, "factors": state["factors"], "reset": self._reset}
        return state

    def _hold_to_core(self, block: Block, state: dict[str, Any]) -> None:
        units, feed_units, incremental, feed_mode, css = self._core.modes
        mine = (units, feed_units, incremental, feed_mode, 96 if css else 97)
        core = (state["units"], state["feed_units"], state["incremental"], state["feed_mode"],
                state["spindle_mode"])
        if mine != core:
            raise DiffError(
                "the modal state read for the comparison (units, distance, feed and spindle "
                f"modes {_modes(mine)}) is not the core's ({_modes(core)})",
                file=self.file, line=block.line, clause="modal state")


_FACTORS = (ONE, MM_PER_INCH, M_PER_FOOT)  # the core's factors 0, 1, 2


def _reader_config(profile: Profile) -> dict[str, Any]:
    """What the core's reader needs from a profile, as plain values."""
    fmts = [(f.address, f.before, f.after, f.signed, str(f.zeros), f.decimal)
            for f in profile.detailed.formats.values()]
    inch = None if profile.detailed_inch is None else [
        (f.address, f.before, f.after, f.signed, str(f.zeros), f.decimal)
        for f in profile.detailed_inch.formats.values()]
    pqr = profile.checks.pqr
    family = profile.dialect.family
    return {
        "formats": fmts, "formats_inch": inch, "explicit": profile.explicit,
        "increments": profile.numbers.whole_letters(),
        "pqr_length": [pqr.get(x) == "length" for x in "PQR"],
        "pqr_unstated": [pqr.get(x, "parameter") == "parameter" for x in "PQR"],
        "family": family, "lathe": profile.control_type == "lathe",
        # the core's reading of the profile (postproc.state.core_config "fanuc_lathe"): on a
        # Fanuc or Haas lathe G98/G99 are feed per minute/revolution and G50 S clamps the
        # spindle (G50 X Z sets the coordinate system); elsewhere G94/G95 and G92
        "fanuc_lathe": family in ("fanuc", "haas") and profile.control_type == "lathe",
        "reset": [int(c[1:]) for c in profile.reset_state() if c[1:].isdigit()],
        "inch": int(profile.inch_code[1:]), "metric": int(profile.metric_code[1:]),
        "default_units": profile.default_units,
    }


def _modes(modes: tuple[str, str, bool, int, int]) -> str:
    units, feed_units, incremental, feed, spindle = modes
    feed_in = "" if feed_units == units else f" (feed {feed_units})"
    return f"{units}{feed_in} G{91 if incremental else 90} G{feed} G{spindle}"


# ---------------------------------------------------------------------------------------------
# Comparing


class Differ:
    """Compares two streams of :class:`NcBlock`; :meth:`run` yields the differences in order."""

    def __init__(self, options: DiffOptions | None = None, target: Profile | None = None
                 ) -> None:
        """``target``: B's profile, whose resolution measures a difference of modal state
        (without it, one unit)."""
        self.options = options or DiffOptions()
        self.steps = {} if target is None else _steps_of(target)
        self._limits: dict[Decimal, Decimal] = {}  # step -> tolerance in that unit
        self._bounds: dict[tuple[str, Decimal], tuple[int, int]] = {}  # bound as a ratio
        self.summary = DiffSummary()
        self._carry: dict[str, Decimal] = {}  # axis -> B's position minus A's (G91)
        self._motion: tuple[Any, ...] = ()  # the motion difference last reported
        self._misses = 0  # head mismatches in a row whose search for a resync found nothing

    # -- the stream ----------------------------------------------------------------------------

    def run(self, left: Iterable[NcBlock], right: Iterable[NcBlock]) -> Iterator[BlockDiff]:
        a, b = self._counted(left, "a"), self._counted(right, "b")
        pairing = self.options.pair
        if pairing == "auto":
            head_a, head_b = list(islice(a, AUTO_LOOK)), list(islice(b, AUTO_LOOK))
            pairing = "number" if _numbered(head_a) and _numbered(head_b) else "position"
            a, b = chain(head_a, a), chain(head_b, b)
        self.summary.pairing = pairing
        pairs = self._by_number(a, b) if pairing == "number" else self._align(a, b)
        for x, y in pairs:
            found = self._emit(x, y)
            if found is not None:
                yield found

    def _counted(self, blocks: Iterable[NcBlock], side: str) -> Iterator[NcBlock]:
        for block in blocks:
            if side == "a":
                self.summary.blocks_a += 1
            else:
                self.summary.blocks_b += 1
            yield block

    def _emit(self, a: NcBlock | None, b: NcBlock | None) -> BlockDiff | None:
        s = self.summary
        if b is SAME:
            s.paired += 1
            return None
        if a is None or b is None:
            for block in (a, b):
                if block is not None and any(w.incremental for w in block.words):
                    self._carry.clear()  # one program moved where the other did not
            _unread(chain(*(x.words for x in (a, b) if x is not None)))
            if a is None:
                s.added += 1
                return BlockDiff("added", None, b)
            s.removed += 1
            return BlockDiff("removed", a, None)
        s.paired += 1
        found = self.compare(a, b, commit=True)
        if found is not None:
            _unread(w for c in found.words for w in (c.a, c.b))
            s.changed += 1
            if found.comments is not None or found.motion or any(
                    change.steps is None for change in found.words):
                s.other += 1
            for change in found.words:
                if change.steps is not None:
                    size = abs(change.steps)
                    if size > s.largest.get(change.key, Fraction(0)):
                        s.largest[change.key] = size
        return found

    # -- one pair of blocks --------------------------------------------------------------------

    def compare(self, a: NcBlock, b: NcBlock, *, commit: bool = False) -> BlockDiff | None:
        """What differs between two paired blocks (None: the same). ``commit`` keeps the
        position carried in G91 and the motion difference reported, for the blocks after."""
        options = self.options
        changes: list[WordChange] = []
        carry = self._carry if commit else dict(self._carry)
        keyed: dict[str, tuple[list[NcWord], list[NcWord]]] = {}
        for w in a.words:
            keyed.setdefault(w.key, ([], []))[0].append(w)
        for w in b.words:
            keyed.setdefault(w.key, ([], []))[1].append(w)
        for key, (la, lb) in keyed.items():
            for wa, wb in _match(la, lb):
                if wa is None or wb is None:
                    word = wa or wb
                    assert word is not None
                    if word.kind != "units":  # a units code the other program has not: its
                        changes.append(WordChange(  # meaning is in the values after it
                            "removed" if wb is None else "added", key, wa, wb))
                    continue
                change = self._word(wa, wb, carry)
                if change is not None:
                    changes.append(change)
        if options.word_order and not changes and _order(a) != _order(b):
            changes.append(WordChange("order", "", None, None))
        if a.resets or b.resets:
            carry.clear()
        comments = None
        if a.comments != b.comments:
            comments = (a.comments, b.comments)
        motion: list[MotionChange] = []
        if a.state is not None and b.state is not None:
            found = tuple(self._motion_changes(a, b))
            signature = tuple(m.signature for m in found)
            if signature != self._motion:
                motion = list(found)
            if commit:
                self._motion = signature
        if not changes and comments is None and not motion:
            return None
        return BlockDiff("changed", a, b, changes, comments, motion)

    def _word(self, wa: NcWord, wb: NcWord, carry: dict[str, Decimal]) -> WordChange | None:
        if wa.parameter and wb.parameter and self.options.parameters == "address":
            return None
        if wa.value is None or wb.value is None or wa.kind == "text" or wb.kind == "text":
            if wa.token == wb.token and (wa.value is None) == (wb.value is None):
                return None  # the same text; a number neither reads, written the same
            return WordChange("changed", wa.key, wa, wb)
        if wa.kind == "units" and wb.kind == "units":
            return None  # G20 and G21 alike: their meaning is in every value after them
        if (self.options.same_text and wa.written != wb.written and wa.value == wb.value
                and wa.factor == wb.factor and wa.form is not None and wa.form == wb.form
                and _as_its_format_writes(wa)):
            return WordChange("written", wa.key, wa, wb)
        if wa.kind in ("code", "units") or wb.kind in ("code", "units"):
            return None if wa.value == wb.value else WordChange("changed", wa.key, wa, wb)
        if wa.kind != wb.kind and self.options.unstated == "adopt":
            if wa.as_length is not None and wb.kind == "length":
                wa = _as_length(wa)  # a P/Q/R word of no stated role, where the other profile
            elif wb.as_length is not None and wa.kind == "length":
                wb = _as_length(wb)  # says it is a length: that role
        if wa.kind != wb.kind:  # one profile reads a length, the other a number: as written
            assert wa.value is not None and wb.value is not None
            with _exact():
                wa = replace(wa, kind="number", value=wa.value / wa.factor, factor=Decimal(1),
                             step=wa.step / wa.factor, incremental=False)
                wb = replace(wb, kind="number", value=wb.value / wb.factor, factor=Decimal(1),
                             step=wb.step / wb.factor, incremental=False)
        assert wa.value is not None and wb.value is not None
        with _exact():
            difference = wb.value - wa.value
            if wa.incremental and wb.incremental:  # B's position minus A's, after the word
                difference += carry.get(wa.key, Decimal(0))
        if self._within(difference, wb):
            if wa.key in AXES:
                carry[wa.key] = difference
            return None
        carry.pop(wa.key, None)  # reported: the words after it are compared afresh
        steps = Fraction(difference) / Fraction(wb.step)
        return WordChange("changed", wa.key, wa, wb, difference, steps)

    def _within(self, difference: Decimal, word: NcWord, key: str | None = None) -> bool:
        """Whether a difference is accepted: within the tolerance in steps of ``word``'s format
        and within the bound of its address (exact: integer ratios, no rounding)."""
        if not difference:
            return True
        size = abs(difference)
        limit = self._limits.get(word.step)
        if limit is None:
            with _exact():
                limit = self._limits[word.step] = self.options.tolerance * word.step
        if size > limit:
            return False
        if self.options.bounds is not None:
            letter = (key or word.key)[:1]
            bound = self._bounds.get((letter, word.factor))
            if bound is None:
                exact = self.options.bounds.get(letter, Fraction(0)) * Fraction(word.factor)
                bound = self._bounds[(letter, word.factor)] = (exact.numerator,
                                                               exact.denominator)
            p, q = size.as_integer_ratio()
            if p * bound[1] > bound[0] * q:
                return False
        return True

    def _motion_changes(self, a: NcBlock, b: NcBlock) -> Iterator[MotionChange]:
        sa, sb = a.state, b.state
        assert sa is not None and sb is not None
        for name in ("motion", "plane", "incremental", "feed_mode", "spindle_mode", "spindle",
                     "coolant", "compensation", "length_offset", "zero_shift", "tool", "offset",
                     "cycle", "speed_limit"):
            if sa[name] != sb[name] and not (  # two controls, each in its own reset state
                    sa[name] == sa["reset"][name] and sb[name] == sb["reset"][name]):
                yield MotionChange(name.replace("_", " "), _state_text(sa[name]),
                                   _state_text(sb[name]))
        pa, pb = sa["position"], sb["position"]
        values = [("feed", "F", "feed"), ("speed", "S", "speed")] + [
            (f"position {axis}", axis, "length" if axis in LENGTH_AXES else "number")
            for axis in sorted(set(pa) | set(pb))]
        for what, letter, kind in values:
            va, vb = _state_value(sa, letter), _state_value(sb, letter)
            if va == vb or self._state_within(va, vb, b, letter, sb):
                continue
            unit = _state_unit(kind, sb, letter)
            difference = None
            if va is not None and vb is not None:
                with _exact():
                    difference = vb - va
            yield MotionChange(what, _state_text(va) + (unit if va is not None else ""),
                               _state_text(vb) + (unit if vb is not None else ""), difference)

    def _state_within(self, va: Decimal | None, vb: Decimal | None, b: NcBlock, letter: str,
                      sb: dict[str, Any]) -> bool:
        if va is None or vb is None:
            return False
        step, factor = _state_step(b, letter, sb, self)
        with _exact():
            word = NcWord(letter, "", "number", vb, factor, step)
            return self._within(vb - va, word, letter)

    # -- pairing -------------------------------------------------------------------------------

    def _same(self, a: NcBlock, b: NcBlock) -> bool:
        return self.compare(a, b) is None

    def _align(self, left: Iterable[NcBlock], right: Iterable[NcBlock]
               ) -> Iterator[tuple[NcBlock | None, NcBlock | None]]:
        """Blocks paired by position, an added or removed block told from a changed one by
        looking ahead ``window`` blocks on each side."""
        window = max(2, self.options.window)
        ia, ib = iter(left), iter(right)
        qa: deque[NcBlock] = deque()
        qb: deque[NcBlock] = deque()
        while True:
            _fill(qa, ia, window)
            _fill(qb, ib, window)
            if not qa or not qb:
                break
            a, b = qa[0], qb[0]
            saved = dict(self._carry), self._motion
            if self.compare(a, b, commit=True) is None:  # the common case: compared once
                self._misses = 0
                qa.popleft(), qb.popleft()
                yield a, SAME
                continue
            self._carry, self._motion = saved
            if not self._next_same(qa, qb) and self._misses < window:
                removed = self._resync(qa, qb)
                added = self._resync(qb, qa, flipped=True)
                if removed is not None and (added is None or removed <= added):
                    for _ in range(removed):
                        yield qa.popleft(), None
                    continue
                if added is not None:
                    for _ in range(added):
                        yield None, qb.popleft()
                    continue
                self._misses += 1
            yield qa.popleft(), qb.popleft()
        for a in chain(qa, ia):
            yield a, None
        for b in chain(qb, ib):
            yield None, b

    def _next_same(self, qa: deque[NcBlock], qb: deque[NcBlock]) -> bool:
        """Whether the blocks after the heads pair again (the heads are then one change)."""
        if len(qa) < 2 or len(qb) < 2:
            return len(qa) == len(qb)
        return self._same(qa[1], qb[1])

    def _resync(self, ahead: deque[NcBlock], other: deque[NcBlock],
                flipped: bool = False) -> int | None:
        """How many blocks of ``ahead`` come before one that pairs with ``other``'s head (and
        the block after it with the next), or None."""
        def same(x: NcBlock, y: NcBlock) -> bool:
            return self._same(y, x) if flipped else self._same(x, y)

        for i in range(1, len(ahead)):
            if same(ahead[i], other[0]) and (
                    i + 1 >= len(ahead) or len(other) < 2 or same(ahead[i + 1], other[1])):
                return i
        return None

    def _by_number(self, left: Iterable[NcBlock], right: Iterable[NcBlock]
                   ) -> Iterator[tuple[NcBlock | None, NcBlock | None]]:
        """Blocks merged in sequence-number order, each numbered block with the unnumbered
        blocks after it; within one number, aligned by position."""
        ga = groupby(_keyed(left), key=lambda kb: kb[0])
        gb = groupby(_keyed(right), key=lambda kb: kb[0])
        na, nb = next(ga, None), next(gb, None)
        while na is not None and nb is not None:
            (ka, blocks_a), (kb, blocks_b) = na, nb
            if ka == kb:
                yield from self._align((x for _, x in blocks_a), (y for _, y in blocks_b))
                na, nb = next(ga, None), next(gb, None)
            elif ka < kb:
                for _, x in blocks_a:
                    yield x, None
                na = next(ga, None)
            else:
                for _, y in blocks_b:
                    yield None, y
                nb = next(gb, None)
        for _, rest in chain([na] if na else [], ga):
            for _, x in rest:
                yield x, None
        for _, rest in chain([nb] if nb else [], gb):
            for _, y in rest:
                yield None, y


def _unread(words: Iterable[NcWord | None]) -> None:
    """Raise the error of the first word of a difference whose number could not be read: a
    word is compared as written only to the same word."""
    for word in words:
        if word is not None and word.error is not None:
            raise word.error


def _as_its_format_writes(word: NcWord) -> bool:
    """Whether a word is written as its format writes it, so that a conversion keeping its
    value and format keeps its text: a count of no more digits than the format holds (all of
    them where it omits no zeros); in an explicit-decimal program a number with a point and no
    more decimals than the format's, or a whole number the control reads as such (not a count
    of increments, which a conversion writes with its point); in an implicit-decimal program the
    format's own writing of the value."""
    assert word.form is not None and word.value is not None
    fmt, explicit, increments = word.form
    number = split_token(word.written)[3]
    if not fmt.decimal:
        digits = len(number)
        return "." not in number and digits <= fmt.before and (
            fmt.zeros is not Zeros.NONE or digits == fmt.before)
    if explicit:
        if "." in number:
            return len(number.split(".", 1)[1]) <= fmt.after
        return not increments
    with _exact():
        raw = word.value / word.factor
    return "." not in number and fmt.write(abs(raw), False) == number


def _as_length(word: NcWord) -> NcWord:
    factor = word.as_length
    assert factor is not None and word.value is not None
    with _exact():
        return replace(word, kind="length", value=word.value * factor, factor=factor,
                       step=word.step * factor, as_length=None)


def _order(block: NcBlock) -> list[str]:
    """The addresses of a block in written order, without its units code (inserted or
    replaced by a conversion, and a units code under one profile is another code under the
    other's)."""
    return [w.key for w in block.words
            if w.kind != "units" and not (w.key == "G" and w.value in _UNITS_CODES)]


_UNITS_CODES = frozenset({Decimal(20), Decimal(21), Decimal(70), Decimal(71), Decimal(700),
                          Decimal(710)})
def _match(la: list[NcWord], lb: list[NcWord]
           ) -> Iterator[tuple[NcWord | None, NcWord | None]]:
    """The words of one address in two blocks, paired: codes (``G90 G01`` and ``G01 G90``) by
    value first, then the rest in written order."""
    if len(la) == 1 and len(lb) == 1:
        yield la[0], lb[0]
        return
    rest_b = list(lb)
    rest_a = []
    for wa in la:
        if wa.kind in ("code", "units"):
            j = next((j for j, wb in enumerate(rest_b) if wb.value == wa.value), -1)
            if j >= 0:
                yield wa, rest_b.pop(j)
                continue
        rest_a.append(wa)
    for i in range(max(len(rest_a), len(rest_b))):
        yield (rest_a[i] if i < len(rest_a) else None), (rest_b[i] if i < len(rest_b) else None)


# The partner of a block that _align has already compared and found the same.
SAME = NcBlock(0, "", None, (), ())


def _fill(queue: deque[NcBlock], it: Iterator[NcBlock], size: int) -> None:
    while len(queue) < size:
        block = next(it, None)
        if block is None:
            return
        queue.append(block)


def _keyed(blocks: Iterable[NcBlock]) -> Iterator[tuple[tuple[int, Decimal, int], NcBlock]]:
    """Each block with the key of the numbered block it belongs to: (run, number, repeat). A
    number lower than the one before starts the next run, so keys only grow."""
    run, last, repeat = 0, Decimal(-1), 0
    for block in blocks:
        if block.number is not None:
            if block.number < last:
                run, repeat = run + 1, 0
            elif block.number == last:
                repeat += 1
            else:
                repeat = 0
            last = block.number
        yield (run, last, repeat), block


def _numbered(blocks: list[NcBlock]) -> bool:
    with_words = [b for b in blocks if any(w.key != "%" for w in b.words)]
    numbered = sum(1 for b in with_words if b.number is not None)
    return bool(with_words) and 2 * numbered >= len(with_words)


def _state_value(state: dict[str, Any], letter: str) -> Decimal | None:
    """A value of the core's modal state (``F``, ``S``, an axis) in its metric unit: times the
    factor of the word that set it."""
    value = state["position"].get(letter) if letter in AXES else state[
        "feed" if letter == "F" else "speed"]
    if value is None:
        return None
    factor = state["factors"].get(letter, ONE)
    if factor is ONE:
        return Decimal(value)
    with _exact():
        product: Decimal = Decimal(value) * factor
        return product


def _state_step(b: NcBlock, letter: str, sb: dict[str, Any],
                differ: Differ) -> tuple[Decimal, Decimal]:
    """One step of B's format for a state value, and its factor to the metric unit."""
    for w in b.words:  # the block's own word, where it has one, knows its format
        if w.key == letter and w.value is not None:  # not an expression (Z=_Z_HOME)
            return w.step, w.factor
    factor = sb["factors"].get(letter, Decimal(1))
    step = differ.steps.get((letter, sb["units"]), Decimal(1))
    with _exact():
        return step * factor, factor


def _state_unit(kind: str, state: dict[str, Any], letter: str) -> str:
    if letter not in state["factors"] and kind != "length":
        return ""
    if kind == "length":
        return " mm"
    if kind == "feed" and state["feed_mode"] != 93:
        return " mm/rev" if state["feed_mode"] == 95 else " mm/min"
    if kind == "speed" and state["spindle_mode"] == 96:
        return " m/min"
    return ""


def _state_text(value: Any) -> str:
    if value is None:
        return "none"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, Decimal):
        return _plain(value)
    return str(value)


# ---------------------------------------------------------------------------------------------
# Files


def read_file(path: str, profile: Profile, options: DiffOptions, *, file: str
              ) -> Iterator[NcBlock]:
    """The blocks of a file (text or tape image) as ``profile`` reads them."""
    reader = ProgramReader(profile, file=file, options=options)
    blocks = parse_stream(Source(path).chunks(), profile.dialect, file=file,
                          errors=options.errors)
    return reader.read(blocks)


def diff_files(path_a: str, path_b: str, profile_a: Profile, profile_b: Profile,
               options: DiffOptions | None = None, *, name_a: str | None = None,
               name_b: str | None = None, differ: Differ | None = None) -> Iterator[BlockDiff]:
    """The differences between two files, in order, each read under its profile; both are read
    as they are compared, a chunk at a time."""
    options = options or DiffOptions()
    differ = differ or Differ(options, profile_b)
    a = read_file(path_a, profile_a, options, file=name_a or path_a)
    b = read_file(path_b, profile_b, options, file=name_b or path_b)
    return differ.run(a, b)


def _steps_of(profile: Profile) -> dict[tuple[str, str], Decimal]:
    """One step of each decimal format of ``profile``, by (letter, units)."""
    out = {}
    for units in ("metric", "inch"):
        for letter in AXES + "FS":
            fmt = profile.word_format(letter, units)
            out[(letter, units)] = fmt.resolution if fmt.decimal else Decimal(1)
    return out
