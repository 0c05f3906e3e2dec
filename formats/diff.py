"""Compare two programs as NC, not as text: ``tapegate diff``, ``convert --verify``, auto-receive.

Each program is read under its own profile, as the control would read it: every plain word
through the profile's word format and ``[numbers]`` reading (decimal point, implicit decimals,
zero suppression, Fanuc least input increments), in the units in force at its block (G20/G21 or
G70/G71, by the profile's units codes; a units code in the block itself is the units of the
values beside it). Values are then held in one unit system, metric, exactly:
an inch value times 25.4 and a surface speed in ft/min times 0.3048 are exact in
:mod:`decimal`, so nothing is rounded before the comparison. Whatever the spacing, the leading
zeros, the decimal style or the units, the same program compares the same.

What a word is, and so which unit it is in, follows the modal state of its own program, read by
the core's reader (``crates/core/src/ncread.rs``) on purpose apart from the converter (a
converter's misreading is not repeated by its check), with the core's semantics: G and M
codes read as the core reads them (through the profile's format, whole: ``G01`` = ``G1.0`` = G1,
any number of leading zeros), and on a Fanuc or Haas lathe (``dialect.family`` fanuc or haas,
``control_type`` lathe) G98/G99 for feed per minute and per revolution, ``G50 S`` the spindle
clamp and ``G50 X Z`` a setting of position. The reset state is the profile's reset codes, applied
in order as the core applies them. A word is compared as:

=================  ============================================================================
word               compared as
=================  ============================================================================
X Y Z U V W I J K  a length (mm), except a G04 dwell's time word (a time, as written: the
                   control's, X U P on a Fanuc lathe, P on LinuxCNC, F S on SINUMERIK)
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
increment by a step to do so) compares the same, and a step lost on the way does not. A code,
a selector and a number a cycle's table makes a count (``G81 ... K3``, three holes; ``G70 P60``)
are compared exactly, with no steps: a length format's step is no unit of a count. A cycle's
number that measures (a drilling cycle's dwell P, a time as G04's P; LinuxCNC G76's Q and R)
is compared within the tolerance.

Blocks are paired by sequence number or by position (:class:`DiffOptions.pair`):

* **by number**: the two programs are merged in sequence-number order, each numbered block
  together with the unnumbered blocks after it; a number lower than the one before starts a new
  run (the next program of the file), so the merge stays in order. This streams: nothing is held
  beyond the group of blocks being compared (the blocks of one number are aligned by position,
  each group's search for a resync starting afresh: the core's ``ncdiff::NumberAligner``).
* **by position**: the blocks are aligned as they come, looking ahead ``window`` blocks on each side
  (64) to tell an added or removed block from a changed one. Memory is that window, whatever the
  size of the programs.
* **auto** (the default) looks at the first 1,000 blocks of each program and pairs by number when
  most blocks of both carry one.

Blank blocks are never compared, nor (with ``ignore_comments``) comment-only blocks or comments.
With ``motion`` the modal state after every block -- motion mode, plane, distance and feed modes,
feed, spindle, coolant, compensation, tool, cycle and the end point -- is taken from the core's
modal state machine (``crates/core/src/modal.rs``) for both programs and compared, so
the answer is also whether the two programs move the machine the same way; the units, distance,
feed and spindle modes read here are checked against the core's at every block, so the two
readings cannot drift apart. A motion difference is reported where it starts or changes, not again
at every block after it.

The entry points are :func:`diff_files` (two files) and :class:`Differ` (block streams); a
difference is a :class:`BlockDiff`, and :attr:`Differ.summary` counts what was compared. The
reading and the comparison of every pair are the core's (``ncread.rs``, ``ncdiff.rs``): the
blocks stay in Rust, and so does the pairing (by position or by number); only the description of
a difference is made here, so that a verification, where nearly every block is the same, makes no
Python object per word. :attr:`Differ.summary` is whole once :meth:`Differ.run` has ended; after
an error raised while reading, its counts are partial.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, field, replace
from decimal import Decimal, localcontext
from fractions import Fraction
from itertools import chain, count, islice
from operator import itemgetter
from typing import TYPE_CHECKING, Any, Literal

from formats import _core
from formats.errors import TapegateError
from formats.machine import machine
from formats.model import Block
from formats.parser import MAX_BLOCK, BadBlock, encode_text, too_long_block, whole_lines
from formats.profile import Profile
from formats.source import Source

if TYPE_CHECKING:
    from formats.parser import Errors

__all__ = ["BlockDiff", "DiffError", "DiffOptions", "DiffSummary", "Differ", "MotionChange",
           "NcBlock", "NcWord", "ProgramReader", "WordChange", "diff_files", "steps_text"]

MM_PER_INCH = Decimal("25.4")
M_PER_FOOT = Decimal("0.3048")
AXES = "XYZUVWABC"
AUTO_LOOK = 1000  # blocks of each program that pair="auto" looks at
ONE = Decimal(1)

Kind = Literal["code", "units", "length", "feed", "speed", "number", "text"]
Pairing = Literal["auto", "number", "position"]


class DiffError(TapegateError):
    """Two programs that cannot be compared (a block that cannot be read, a modal drift)."""

    default_code = "diff"


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
    # The units LinuxCNC subroutine bodies are read in, by label, in A and in B, where not those
    # in force where they stand (convert --verify: the source's as the converter read them, its
    # calls' units, the output's in the units converted to; docs/convert.md).
    bodies_a: tuple[tuple[str, str], ...] = ()
    bodies_b: tuple[tuple[str, str], ...] = ()


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
    # a dwell's time by a parameter or an expression that the control reads in milliseconds
    # (a FANUC or Haas G04 P, a drilling cycle's P; LinuxCNC's P is seconds)
    milliseconds: bool = False

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
    # the core's modal state after the block (motion), "factors" the factor of the word that set
    # each value of it (F, S, an axis)
    state: dict[str, Any] | None = None

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
        elif self.a.milliseconds != self.b.milliseconds:  # the same text, another time
            units = ["seconds", "milliseconds"]
            text += (f" (a dwell read in {units[self.a.milliseconds]} and in "
                     f"{units[self.b.milliseconds]})")
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
    """Blocks of one program -> the core's blocks (``_core.DiffBlock``), read under ``profile``.

    The words are read by the core (``crates/core/src/ncread.rs``: the table above, and the
    little modal state the units depend on -- units, distance, feed and spindle modes -- from
    the profile's reset state), and stay there: only a block that differs becomes an
    :class:`NcBlock`. With ``motion`` the core's modal state machine runs beside the reading,
    its state is kept on every block, and the two are held to each other (a drift is a
    :class:`DiffError` where it starts).
    """

    def __init__(self, profile: Profile, *, file: str, options: DiffOptions,
                 bodies: tuple[tuple[str, str], ...] = ()) -> None:
        self.profile = profile
        self.file = file
        self.options = options
        self._core = _core.DiffReader(machine(profile), options.motion, file)
        if bodies:
            self._core.set_bodies(list(bodies))

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

    def read(self, blocks: Iterable[Block]) -> Iterator[_core.DiffBlock]:
        """The blocks of a parsed program as read."""
        for block in blocks:
            nc = self.block(block)
            if nc is not None:
                yield nc

    def read_text(self, chunks: Iterable[str]) -> Iterator[_core.DiffBlock]:
        """The blocks of a program's text arriving in chunks, as :func:`parse_stream` would
        parse them, tokenized and read in the core with no :class:`Block` made, a few hundred
        lines at a time (memory: those blocks, whatever the chunk)."""
        return chain.from_iterable(self._batches(chunks))

    def _batches(self, chunks: Iterable[str]) -> Iterator[list[_core.DiffBlock]]:
        """:meth:`read_text`'s blocks a batch at a time (passed on by ``chain``, in C)."""
        collect = self.options.errors == "collect"
        flags = self.profile.dialect.flags
        ignore = self.options.ignore_comments
        for text, line, unread in whole_lines(chunks):
            if unread is None:
                text = text[:-1]
            elif len(text) > MAX_BLOCK:
                yield list(self.read(too_long_block(text, line + 1, self.file,
                                                    self.options.errors)))
                return
            elif not text:
                return
            data = encode_text(text)
            start: int | None = 0
            while start is not None:
                blocks, start, lines, error = self._core.read_lines(
                    data, start, line, _BATCH, flags, collect, ignore)
                line += lines
                yield blocks
                if error is not None:
                    raise error

    def block(self, block: Block) -> _core.DiffBlock | None:
        """The block as read, or None for a block with nothing to compare."""
        if self._core.not_read(block.line, block.text):
            # never read by the control (after a LinuxCNC program's end): compared as text
            return _core.DiffReader.bad(block.line, block.text) if block.text.strip() else None
        if isinstance(block, BadBlock):
            return _core.DiffReader.bad(block.line, block.text)
        info = block.info
        percent, skip, comments, statements, within = False, "", [], [], None
        if info is not None:
            percent, skip, statements = info.percent, info.skip, list(info.statements)
            within = info.skip_within
            if not self.options.ignore_comments:
                comments = [text for _, text in info.comments]
                if info.percent and info.ident:
                    comments.insert(0, info.ident)
        return self._core.read(block.line, block.text, block.words, percent, skip, comments,
                               statements, within)


_FACTORS = (ONE, MM_PER_INCH, M_PER_FOOT)  # the core's factors 0, 1, 2
_BATCH = 256  # lines read by the core at a time


def nc_block(read: _core.DiffBlock) -> NcBlock:
    """A block of the core as an :class:`NcBlock` (a block that differs: to describe it)."""
    errors = read.errors or {}
    words = []
    for i, (key, token, kind, value, factor, step,
            (incremental, parameter, per_revolution, milliseconds),
            as_length, _, written) in enumerate(read.words()):
        words.append(NcWord(
            key, token, kind, None if value is None else Decimal(value),  # type: ignore[arg-type]
            _FACTORS[factor], Decimal(step), incremental=incremental, parameter=parameter,
            as_length=None if as_length is None else _FACTORS[as_length], error=errors.get(i),
            per_revolution=per_revolution, written=written, milliseconds=milliseconds))
    number = read.number
    state = read.state()
    if state is not None:  # the factor of the word that set each value, as a Decimal
        state["factors"] = {k: _FACTORS[v] for k, v in state["factors"].items()}
    return NcBlock(read.line, read.text, None if number is None else Decimal(number),
                   tuple(words), tuple(read.comments), resets=read.resets, state=state)


# ---------------------------------------------------------------------------------------------
# Comparing


class Differ:
    """Compares two streams of blocks (:meth:`ProgramReader.read`); :meth:`run` yields the
    differences in order. Each pair is compared by the core (``crates/core/src/ncdiff.rs``:
    words, tolerance and bounds, the position carried in G91, comments, modal state); only
    what differs is made into a :class:`BlockDiff` here."""

    def __init__(self, options: DiffOptions | None = None, target: Profile | None = None
                 ) -> None:
        """``target``: B's profile, whose resolution measures a difference of modal state
        (without it, one unit)."""
        self.options = options = options or DiffOptions()
        steps = {} if target is None else _steps_of(target)
        self.summary = DiffSummary()
        self._core = _core.DiffComparer({
            "tolerance": _ratio(Fraction(options.tolerance)),
            "bounds": None if options.bounds is None else [
                (letter, _ratio(bound)) for letter, bound in options.bounds.items()],
            "word_order": options.word_order,
            "parameters_address": options.parameters == "address",
            "unstated_adopt": options.unstated == "adopt",
            "same_text": options.same_text,
            "steps": [(letter, units, str(step)) for (letter, units), step in steps.items()],
        })

    # -- the stream ----------------------------------------------------------------------------

    def run(self, left: Iterable[Read], right: Iterable[Read]) -> Iterator[BlockDiff]:
        # each side counted as it is read, in C (a generator per block cost a tenth of the
        # comparison): zip stops at the end of the blocks without taking a number more
        count_a, count_b = count(), count()
        a: Iterator[Read] = map(itemgetter(0), zip(left, count_a, strict=False))
        b: Iterator[Read] = map(itemgetter(0), zip(right, count_b, strict=False))
        pairing = self.options.pair
        if pairing == "auto":
            head_a, head_b = list(islice(a, AUTO_LOOK)), list(islice(b, AUTO_LOOK))
            pairing = "number" if _numbered(head_a) and _numbered(head_b) else "position"
            a, b = chain(head_a, a), chain(head_b, b)
        self.summary.pairing = pairing
        aligner = _core.DiffAligner(self._core, a, b, self.options.window, pairing == "number")
        while True:
            same, x, y = aligner.step()
            self.summary.paired += same  # the pairs that are the same are only counted
            if x is None and y is None:
                break
            found = self._emit(x, y)
            if found is not None:
                yield found
        # (both sides read to their ends: the counts are whole)
        self.summary.blocks_a, self.summary.blocks_b = next(count_a), next(count_b)

    def _emit(self, a: Read | None, b: Read | None) -> BlockDiff | None:
        s = self.summary
        if a is None or b is None:
            block = a if b is None else b
            assert block is not None
            self._core.unpaired(block)  # one program moved where the other did not
            nc = nc_block(block)
            _unread(nc.words)
            if a is None:
                s.added += 1
                return BlockDiff("added", None, nc)
            s.removed += 1
            return BlockDiff("removed", nc, None)
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

    def unread(self) -> list[tuple[int, int, str]]:
        """The statements of the blocks compared so far whose numbers were not compared, as
        (line in A, line in B, A's text): one holding a number of no role the converter's table
        gives, read in other units in the two programs (the core's ``Comparer::unread``)."""
        return self._core.unread()

    def compare(self, a: Read, b: Read, *, commit: bool = False) -> BlockDiff | None:
        """What differs between two paired blocks (None: the same). ``commit`` keeps the
        position carried in G91 and the motion difference reported, for the blocks after."""
        found = self._core.compare(a, b, commit)
        if found is None:
            return None
        words, comments, motion = found
        na, nb = nc_block(a), nc_block(b)
        changes = []
        for kind, key, side_a, side_b, difference in words:
            wa, wb = _side(na, side_a), _side(nb, side_b)
            change = WordChange(kind, key, wa, wb)  # type: ignore[arg-type]
            if difference is not None:
                assert wb is not None
                value = Decimal(difference)
                change = replace(change, difference=value,
                                 steps=Fraction(value) / Fraction(wb.step))
            changes.append(change)
        return BlockDiff("changed", na, nb, changes,
                         (na.comments, nb.comments) if comments else None,
                         [MotionChange(what, ta, tb, None if d is None else Decimal(d))
                          for what, ta, tb, d in motion])


Read = _core.DiffBlock  # a block as the core read it (ProgramReader.read)


def _ratio(value: Fraction) -> tuple[str, str]:
    """A non-negative ratio for the core, exactly: (numerator, denominator) as text."""
    return str(abs(value.numerator)), str(value.denominator)


def _side(block: NcBlock, side: tuple[int, tuple[str, str, int, str] | None] | None
          ) -> NcWord | None:
    """A word of a change as it was compared: the block's word, or (a P/Q/R word read as the
    length the other profile says it is, both words as written where one profile reads a
    length and the other a number) that word so read."""
    if side is None:
        return None
    index, view = side
    word = block.words[index]
    if view is None:
        return word
    kind, value, factor, step = view
    return replace(word, kind=kind, value=Decimal(value),  # type: ignore[arg-type]
                   factor=_FACTORS[factor], step=Decimal(step), incremental=False,
                   as_length=None)


def _unread(words: Iterable[NcWord | None]) -> None:
    """Raise the error of the first word of a difference whose number could not be read: a
    word is compared as written only to the same word."""
    for word in words:
        if word is not None and word.error is not None:
            raise word.error


def _numbered(blocks: list[Read]) -> bool:
    with_words = [b for b in blocks if b.has_words]
    numbered = sum(1 for b in with_words if b.number is not None)
    return bool(with_words) and 2 * numbered >= len(with_words)


# ---------------------------------------------------------------------------------------------
# Files


def read_file(path: str, profile: Profile, options: DiffOptions, *, file: str,
              bodies: tuple[tuple[str, str], ...] = ()) -> Iterator[Read]:
    """The blocks of a file (text or tape image) as ``profile`` reads them (in the core)."""
    return ProgramReader(profile, file=file, options=options,
                         bodies=bodies).read_text(Source(path).chunks())


def diff_files(path_a: str, path_b: str, profile_a: Profile, profile_b: Profile,
               options: DiffOptions | None = None, *, name_a: str | None = None,
               name_b: str | None = None, differ: Differ | None = None) -> Iterator[BlockDiff]:
    """The differences between two files, in order, each read under its profile; both are read
    as they are compared, a chunk at a time."""
    options = options or DiffOptions()
    differ = differ or Differ(options, profile_b)
    a = read_file(path_a, profile_a, options, file=name_a or path_a, bodies=options.bodies_a)
    b = read_file(path_b, profile_b, options, file=name_b or path_b, bodies=options.bodies_b)
    return differ.run(a, b)


def _steps_of(profile: Profile) -> dict[tuple[str, str], Decimal]:
    """One step of each decimal format of ``profile``, by (letter, units)."""
    out = {}
    for units in ("metric", "inch"):
        for letter in AXES + "FS":
            fmt = profile.word_format(letter, units)
            out[(letter, units)] = fmt.resolution if fmt.decimal else Decimal(1)
    return out
