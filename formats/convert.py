"""Exact conversion of a program from one machine format to another (ISO 6983-1 Annex C, 6.1).

What changes: the way numbers are written (implicit or explicit decimal sign, which zeros are
omitted, digits before and after the decimal sign), the units (metric <-> inch, 1 in = 25.4 mm
exactly), the units code, and -- on request -- spacing and end of block. Everything else --
comments, word order, block numbers, ``%`` and the identification -- is kept as written.

Units follow the **modal state of each block**, not a list of letters:

===========================  ==================================================================
word                         converted as a length when ...
===========================  ==================================================================
X Y Z U V W, I J K           always (positions, arc centres, thread leads) -- except the time
                             of a G04 dwell block
P Q R                        the source profile says the letter is a length (``checks.pqr``)
F (and E)                    G94 (per minute) or G95 (per revolution); never G93 inverse time,
                             never a G04 dwell
S                            G96 constant surface speed (m/min <-> ft/min); never G97 (rpm),
                             never ``G92 S`` (a spindle speed clamp)
A B C, N G M T D H O         never (angles and counts; only their written form may change)
===========================  ==================================================================

Arithmetic is on integers: a source value ``m * 10**-k`` times the factor ``num/den`` is rounded
to the target resolution ``10**-after`` with one ``divmod`` -- exact, with no float anywhere.
In G91 incremental mode the converter tracks the exact absolute position of each axis, converts
that and writes the difference of converted absolutes, so rounding never accumulates along a path.
"""

from __future__ import annotations

import dataclasses
import os
import re
import tempfile
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from decimal import ROUND_UP, Decimal, localcontext
from fractions import Fraction
from itertools import chain
from pathlib import Path

import numpy as np

from formats import bulk
from formats.errors import ConversionError
from formats.expr import parse_expression
from formats.lengths import NotLinear, ParameterAnalysis, ParameterClasses, linear_parts
from formats.model import Block, split_token
from formats.parser import (
    CHUNK,
    BadBlock,
    Dialect,
    parse_lines,
    parse_stream,
    read_chunks,
    whole_lines,
)
from formats.printer import print_lines, replace_words, token_span
from formats.profile import EOB_STYLES, NEUTRAL, Profile
from formats.source import Source
from formats.wordformat import Rounding, WordFormat, Zeros

# How a plain explicit word of one letter is written in the modal state in force (see
# Converter._plan), or None where it needs the general path.
WordPlan = tuple[int, list[tuple[int, int, int]], int, int, WordFormat, bool, bool] | None

# Kinds of word, by address.
AXIS, ANGLE, CENTRE, FEED, SPEED, PQR, COUNT = range(7)
_KIND = {**dict.fromkeys("XYZUVW", AXIS), **dict.fromkeys("ABC", ANGLE),
         **dict.fromkeys("IJK", CENTRE), "F": FEED, "E": FEED, "S": SPEED,
         **dict.fromkeys("PQR", PQR), **dict.fromkeys("NGMTDHOL", COUNT)}
_DWELL_LETTERS = frozenset("XUPF")

INCH_PER_MM = Fraction(5, 127)  # 1 / 25.4
FT_PER_M = Fraction(1250, 381)  # 1 / 0.3048
_POW10 = [10**i for i in range(40)]

# Codes read for the modal state of the source program.
G_DWELL, G_SET, G_ABS, G_INC, G_INVERSE, G_PER_MIN, G_PER_REV, G_CSS, G_RPM = (
    4, 92, 90, 91, 93, 94, 95, 96, 97)
G_MACHINE = frozenset({28, 30, 53})  # reference / machine-coordinate moves: position unknown after


@dataclass(frozen=True)
class ConvertOptions:
    """What to convert to. ``None`` for an override means "as the target profile says"."""

    target: Profile
    source: Profile | None = None  # None: detect from the program (see :func:`detect_source`)
    decimal: str | None = None  # "explicit" | "implicit"
    zeros: Zeros | None = None  # zero suppression of implicit-decimal words
    units: str | None = None  # "metric" | "inch": convert the units; None keeps them
    eob: str | None = None  # a key of EOB_STYLES
    rounding: Rounding = Rounding.HALF_EVEN
    spacing: str = "keep"  # keep | remove | insert
    allow_unconverted: bool = False  # leave unprovable parameters and P/Q/R words unconverted

    def effective_target(self) -> Profile:
        """The target profile with the overrides applied: what the output must be read with."""
        target = self.target
        explicit = target.explicit if self.decimal is None else self.decimal == "explicit"
        formats = dict(target.detailed.formats)
        if self.zeros is not None:
            formats = {k: dataclasses.replace(f, zeros=self.zeros) if f.decimal else f
                       for k, f in formats.items()}
        if explicit == target.explicit and formats == target.detailed.formats:
            return target
        detailed = dataclasses.replace(target.detailed, formats=formats,
                                       explicit_decimal=explicit)
        return dataclasses.replace(target, detailed=detailed)


@dataclass
class ConvertStats:
    """What one conversion did, for the summary table and the closing report."""

    file: str = ""
    output: str = ""
    blocks: int = 0
    words: int = 0
    changed: int = 0
    rounding: dict[str, Fraction] = field(default_factory=dict)  # address -> largest |error|
    notes: list[str] = field(default_factory=list)
    error: str = ""
    verified: bool = False

    def note(self, text: str) -> None:
        if text not in self.notes:
            self.notes.append(text)

    def largest_rounding(self) -> tuple[str, Decimal]:
        if not self.rounding:
            return "", Decimal(0)
        letter, value = max(self.rounding.items(), key=lambda kv: kv[1])
        return letter, _fraction_decimal(value)


def _fraction_decimal(value: Fraction) -> Decimal:
    """A rounding error for people: three significant digits, rounded up (never understated)."""
    with localcontext() as ctx:
        ctx.prec = 3
        ctx.rounding = ROUND_UP
        return (Decimal(value.numerator) / Decimal(value.denominator)).normalize()


# ---------------------------------------------------------------------------------------------
# Detecting the source format


_UNITS_CODE = re.compile(r"(?<![A-Z0-9.])G0*(20|21|70|71)(?![0-9.])")
_DECIMAL_WORD = re.compile(r"[XYZIJKF][+-]?[0-9]*\.[0-9]*")


def detect_source(head: str) -> tuple[Profile, list[str]]:
    """A reading of a program whose format was not given, and what was assumed (``--from``)."""
    notes = []
    text = re.sub(r"\([^)\n]*\)|;[^\n]*", "", head.upper())
    units = _UNITS_CODE.search(text)
    profile = NEUTRAL
    if units is None:
        notes.append("source: no units code (G70/G71, G20/G21) found, read as metric")
    else:
        code = int(units.group(1))
        if code in (20, 21):
            profile = dataclasses.replace(profile, units_codes=("G20", "G21"))
        notes.append(f"source: units codes G{code // 10 * 10}/G{code // 10 * 10 + 1} "
                     f"(G{code} found)")
    if _DECIMAL_WORD.search(text):
        notes.append("source: explicit decimal sign (decimal points found)")
    else:
        notes.append("source: no decimal points found; read as explicit decimal (whole "
                     "numbers) -- give --from for an implicit-decimal program")
    return profile, notes


# ---------------------------------------------------------------------------------------------
# The converter


class Converter:
    """Converts a stream of blocks; :attr:`stats` says what it did.

    ``parameters`` is the outcome of :class:`formats.lengths.ParameterAnalysis` for programs with
    parameter expressions (``None``: the program has none).
    """

    def __init__(self, options: ConvertOptions, source: Profile, *, file: str | None = None,
                 parameters: ParameterClasses | None = None,
                 stats: ConvertStats | None = None) -> None:
        self.options = options
        self.source = source
        self.target = options.effective_target()
        self.file = file
        self.parameters = parameters
        self.stats = stats or ConvertStats(file=file or "")
        self.rounding = options.rounding
        self.explicit_out = self.target.explicit
        self.explicit_in = source.explicit
        # modal state of the source program
        self.src_units = source.default_units
        self.incremental = False
        self.feed_mode = G_PER_MIN
        self.css = False
        self.units_seen = False
        self.src_pos: dict[str, Fraction] = {}
        self.out_pos: dict[str, int] = {}
        self.abs_raw: dict[str, tuple[bool, int, int]] = {}  # absolute words, kept unconverted
        self._inch_in = int(source.inch_code[1:])
        self._metric_in = int(source.metric_code[1:])
        self._formats: dict[str, tuple[WordFormat, int, int]] = {}
        self._src_formats: dict[str, WordFormat] = {}
        self._dwell_formats = self.target.detailed.facilities.get("dwell", {})
        self._set_factor()
        eob = options.eob
        self.eob = EOB_STYLES[eob] if eob else None
        self.pqr = source.checks.pqr
        self.fast = True  # tests turn the fast path off to compare it with the general one
        self._plans: dict[str, WordPlan] | None = None
        self._worst: dict[str, tuple[int, int]] = {}  # address -> (e, d): largest error e/d
        self._bulk: _BulkPlan | None = None

    # -- units -------------------------------------------------------------------------------

    @property
    def out_units(self) -> str:
        return self.options.units or self.src_units

    def _set_factor(self) -> None:
        src, out = self.src_units, self.out_units
        if src == out:
            self.length = self.speed = Fraction(1)
        elif out == "inch":
            self.length, self.speed = INCH_PER_MM, FT_PER_M
        else:
            self.length, self.speed = 1 / INCH_PER_MM, 1 / FT_PER_M

    def _units_code(self) -> str:
        t = self.target
        return t.inch_code if self.out_units == "inch" else t.metric_code

    # -- formats -----------------------------------------------------------------------------

    def _out_format(self, letter: str, dwell: bool = False) -> tuple[WordFormat, int, int]:
        if dwell and letter in self._dwell_formats:
            fmt = self._dwell_formats[letter]
            return fmt, fmt.after, _POW10[fmt.width]
        cached = self._formats.get(letter)
        if cached is None:
            if letter not in self.target.detailed.formats:
                self.stats.note(f"address {letter} is not in the target classification; "
                                f"written with the format {self.target.word_format(letter).spec()}")
            fmt = self.target.word_format(letter)
            cached = self._formats[letter] = (fmt, fmt.after, _POW10[fmt.width])
        return cached

    def _src_format(self, letter: str) -> WordFormat:
        fmt = self._src_formats.get(letter)
        if fmt is None:
            fmt = self._src_formats[letter] = self.source.word_format(letter)
        return fmt

    # -- the stream --------------------------------------------------------------------------

    def convert(self, blocks: Iterable[Block]) -> Iterator[str]:
        """Output text in chunks of about 64 KiB."""
        yield from print_lines(self._lines(blocks), self.eob)
        self.finish()

    def convert_stream(self, chunks: Iterable[str], dialect: Dialect) -> Iterator[str]:
        """Output text for a program arriving as text chunks (the way files are converted).

        Runs of plain blocks in a modal state the fast path covers are converted a run at a time
        by :mod:`formats.bulk`; every other block -- and any run the arrays cannot take exactly
        (an overflow, a refused rounding, a number too long) -- goes block by block, which also
        gives the located error.
        """
        for text, line, unread in whole_lines(chunks):
            if unread is None:
                yield from self._complete_lines(text, line, dialect)
            else:
                yield from print_lines(self._lines(parse_stream(
                    chain([text], unread), dialect, file=self.file, first_line=line)), self.eob)
        self.finish()

    def _complete_lines(self, data: str, line: int, dialect: Dialect) -> Iterator[str]:
        """Text of whole lines (each ending with LF) starting after line ``line``."""
        pos = 0
        size = len(data)
        while pos < size:
            window = 256
            if self._bulk_ready():
                plan = self._bulk_plan()
                end = plan.run.match(data, pos).end()  # type: ignore[union-attr]
                if end > pos:
                    run = data[pos:end]
                    out = self._convert_run(run, plan)
                    if out is None:  # the general path takes it (and locates any error)
                        yield from print_lines(self._lines(
                            parse_stream([run], dialect, file=self.file, first_line=line)),
                            self.eob)
                    else:
                        yield out if self.eob is None else _EOB_RE.sub(self.eob, out)
                    line += run.count("\n")
                    pos = end
                    continue
                window = 1
            # block by block: a window of lines, left as soon as the arrays can take over
            end = pos
            for _ in range(window):
                end = data.index("\n", end) + 1
                if end == size:
                    break
            taken = [pos, line]
            yield from print_lines(self._lines(self._until_ready(
                data[pos:end - 1], dialect, taken)), self.eob)
            pos, line = taken

    def _until_ready(self, text: str, dialect: Dialect, taken: list[int]) -> Iterator[Block]:
        """The blocks of ``text`` (lines after line ``taken[1]``) up to the one after which the
        arrays can take over; ``taken`` counts the characters and lines converted."""
        for block in parse_lines(text, taken[1], dialect, self.file, "raise"):
            yield block  # resumed once the block is converted
            taken[0] += len(block.text) + 1
            taken[1] += 1
            if self._bulk_ready():
                return

    def _bulk_ready(self) -> bool:
        return (self.fast and self.units_seen and not self.incremental
                and self.options.spacing == "keep")

    def _bulk_plan(self) -> _BulkPlan:
        """The run pattern and the tables of the modal state in force (rebuilt when it changes:
        a state change clears :attr:`_plans`)."""
        plans = self._plans
        if plans is None:
            plans = self._plans = {}
        if self._bulk is not None and self._bulk.plans is plans:
            return self._bulk
        bp = _BulkPlan(plans)
        formats = self.target.detailed.formats
        values = []
        count_words = []
        for letter in _BULK_LETTERS:
            if letter not in formats:  # the general path notes the format it writes with
                continue
            plan = plans[letter] = plans[letter] if letter in plans else self._plan(letter)
            if plan is None:
                continue
            kind, steps, after, limit, fmt, keep, tracked = plan
            if kind == COUNT:
                count_words.append((letter, limit - 1))
                continue
            b = ord(letter)
            if limit >= 2**62 or any(n >= 2**40 or d >= 2**62 for n, d, _ in steps[:16]):
                continue
            values.append(letter)
            for k in range(16):
                bp.num[b, k], bp.den[b, k], _ = steps[k]
            bp.error_den[letter] = [e for _, _, e in steps[:16]]
            bp.max_num = max(bp.max_num, max(n for n, _, _ in steps[:16]))
            bp.value[b] = True
            bp.limit[b] = limit
            bp.keep[b] = keep
            bp.after[b] = after
            bp.width[b] = fmt.width if fmt.decimal else fmt.before
            bp.mode[b] = (bulk.EXPLICIT if self.explicit_out and fmt.decimal else
                          {Zeros.LEADING: bulk.LEADING, Zeros.TRAILING: bulk.TRAILING}.get(
                              fmt.zeros, bulk.FULL))
            if tracked:
                bp.tracked.append(letter)
        words = []
        if values:
            words.append(rf"[{''.join(values)}][+-]?+(?:[0-9]++\.?+[0-9]*+|\.[0-9]++)")
        for letter, digits in count_words:
            if letter == "G":  # motion codes only: every other G may change the modal state
                words.append(r"G0?[0-3](?![0-9])" if digits >= 2 else r"G[0-3](?![0-9])")
            elif letter == "N":
                words.append(rf"N[0-9]{{1,{digits}}}+(?![0-9])")
        word = "|".join(words) or "(?!)"
        bp.run = re.compile(rf"(?:(?:[ \t]*+(?:{word}))*+[ \t\r]*+\n)*+")
        self._bulk = bp
        return bp

    def _convert_run(self, text: str, bp: _BulkPlan) -> str | None:
        """A run of plain blocks converted as arrays; None if it must go block by block."""
        a = bulk.as_bytes(text)
        words = bulk.read_words(a)
        if words is None:
            return None
        at = np.flatnonzero(bp.value[words.letter])
        letter, m, k = words.letter[at], words.m[at], words.k[at]
        if len(at) and int(m.max()) * bp.max_num >= 2**63:
            return None
        den = bp.den[letter, k]
        q, r = np.divmod(m * bp.num[letter, k], den)
        if self.rounding is Rounding.ERROR and r.any():
            return None
        twice = r + r
        odd = (q & 1) == 1 if self.rounding is Rounding.HALF_EVEN else True
        up = (twice > den) | ((twice == den) & odd)
        q += up
        r = np.where(up, den - r, r)
        if (q >= bp.limit[letter]).any():
            return None
        which = np.flatnonzero(~(bp.keep[letter] & (k <= bp.after[letter])))
        written = letter[which]
        new, same = bulk.render(words, at[which], q[which], bp.mode[written],
                                bp.width[written], bp.after[written])
        out = bulk.rewrite(a, words, at[which], new)
        if out is None:
            return None
        changed = len(same) - int(np.count_nonzero(same))
        neg = words.neg[at]
        self._record_run(bp, letter, k, r)
        for name in bp.tracked:
            hits = np.flatnonzero(letter == ord(name))
            if len(hits):
                j = hits[-1]
                self.abs_raw[name] = (bool(neg[j]), int(m[j]), int(k[j]))
                self.out_pos[name] = -int(q[j]) if neg[j] else int(q[j])
                self.src_pos.pop(name, None)
        stats = self.stats
        stats.changed += changed
        stats.words += len(words.starts)
        stats.blocks += text.count("\n")
        return out.decode("ascii")

    def _record_run(self, bp: _BulkPlan, letter: bulk.U8, k: bulk.I64, r: bulk.I64) -> None:
        """The largest rounding of a run, per address (exact: compared as fractions)."""
        rounded = np.flatnonzero(r)
        if not len(rounded):
            return
        best = np.zeros(256 * 16, dtype=np.int64)
        np.maximum.at(best, letter[rounded].astype(np.int64) * 16 + k[rounded], r[rounded])
        for key in np.flatnonzero(best):
            name = chr(key // 16)
            self._record(name, int(best[key]), bp.error_den[name][key % 16])

    def _lines(self, blocks: Iterable[Block]) -> Iterator[tuple[str, bool]]:
        stats = self.stats
        for block in blocks:
            if isinstance(block, BadBlock):
                raise block.error
            stats.blocks += 1
            yield (self._block(block) if block.words else block.text), block.has_eob

    def _plan(self, letter: str) -> WordPlan:
        """How the fast path writes a plain explicit word of ``letter`` in the current modal
        state (no dwell, no G92, absolute mode): (kind, [(N, D, D * 10**after) by source
        decimals k], after, limit, format, keep-as-written-when-exact, tracked), or None when
        the word needs the general path."""
        kind = _KIND.get(letter)
        if kind == COUNT:
            fmt = self._out_format(letter)[0]
            if fmt.decimal or fmt.zeros is Zeros.NONE:
                return None
            return (COUNT, [], 0, fmt.before + 1, fmt, True, False)
        if kind is None or not self.explicit_in:
            return None
        factor = self.length
        if kind == ANGLE or (kind == FEED and self.feed_mode == G_INVERSE):
            factor = Fraction(1)
        elif kind == SPEED:
            factor = self.speed if self.css else Fraction(1)
        elif kind == PQR:
            role = self.pqr.get(letter, "parameter")
            if role == "parameter" and self.length != 1:
                return None
            if role != "length":
                factor = Fraction(1)
        fmt, after, limit = self._out_format(letter)
        scale = _POW10[after]
        steps = [(factor.numerator * scale, factor.denominator * _POW10[k],
                  factor.denominator * _POW10[k] * scale) for k in range(20)]
        keep = self.explicit_out and factor == 1
        return (kind, steps, after, limit, fmt, keep, kind in (AXIS, ANGLE))

    def _fast(self, block: Block) -> list[str] | None:
        """The words of a plain block in absolute mode: the hot path of a big conversion."""
        plans = self._plans
        if plans is None:
            plans = self._plans = {}
        words = block.words
        new: list[str] | None = None
        explicit = self.explicit_out
        half_up = self.rounding is Rounding.HALF_UP
        refuse = self.rounding is Rounding.ERROR
        worst = self._worst
        abs_raw = self.abs_raw
        out_pos = self.out_pos
        src_pos = self.src_pos
        changed = 0
        for i, tok in enumerate(words):
            letter = tok[0]
            if letter in plans:
                plan = plans[letter]
            else:
                plan = plans[letter] = self._plan(letter)
            if plan is None:  # counts, lower case, implicit source...: the general path
                out = self._word(block, i, tok)
            elif plan[0] == COUNT:  # a count word that fits is kept as written
                if len(tok) <= plan[3] and tok[1:].isdigit():
                    continue
                out = self._word(block, i, tok)
            else:
                kind, steps, after, limit, fmt, keep, tracked = plan
                body = tok[1:]
                first = body[0]
                neg = first == "-"
                plus = first == "+"
                if neg or plus:
                    body = body[1:]
                whole, _, fraction = body.partition(".")
                k = len(fraction)
                if k >= 20 or not (whole + fraction).isdigit():  # an index or expression
                    out = self._word(block, i, tok)
                else:
                    m = int(whole + fraction)
                    n_, d_, e_ = steps[k]
                    q, r = divmod(m * n_, d_)
                    if r:
                        if refuse:
                            raise self._locate(_rounding_refused(letter, after), block, i)
                        twice = r + r
                        if twice > d_ or (twice == d_ and (half_up or q & 1)):
                            q += 1
                            r = d_ - r
                        w = worst.get(letter)
                        if w is None or r * w[1] > w[0] * e_:
                            worst[letter] = (r, e_)
                    if q >= limit:
                        raise self._locate(_overflow(tok, q, after, fmt), block, i)
                    if neg:
                        q = -q
                    if tracked:
                        abs_raw[letter] = (neg, m, k)
                        out_pos[letter] = q
                        if letter in src_pos:
                            del src_pos[letter]
                    if keep and k <= after:
                        continue
                    if explicit:
                        out = letter + _write(q, after, fmt, True, plus)
                    elif fmt.zeros is Zeros.LEADING:
                        out = letter + str(q) if not plus or q <= 0 else letter + "+" + str(q)
                    else:
                        out = letter + _write(q, after, fmt, False, plus)
            if out != tok:
                changed += 1
                if new is None:
                    new = list(words)
                new[i] = out
        self.stats.changed += changed
        return new

    def _word(self, block: Block, i: int, tok: str) -> str:
        """One word by the general path (the fast path's fallback)."""
        kind = _KIND.get(tok[0].upper())
        if kind is None:
            return tok
        try:
            if kind == COUNT:
                return self._count(tok)
            return self._value(block, i, tok, kind, False, False)
        except ConversionError as exc:
            raise self._locate(exc, block, i) from None

    def _block(self, block: Block) -> str:
        words = block.words
        stats = self.stats
        stats.words += len(words)
        dwell = set_position = False
        units_at = -1
        machine_move = False
        if block.percent:
            return block.text
        # 1. the block's G codes set the modal state its words are read in
        text = block.text
        has_g = "G" in text or "g" in text
        for i, tok in enumerate(words if has_g else ()):
            if tok[0] not in "Gg":
                continue
            try:
                n = int(tok[1:])
            except ValueError:
                continue
            if n == G_DWELL:
                dwell = True
            elif n == G_SET:
                set_position = True
            elif n == G_ABS:
                self.incremental = False
            elif n == G_INC:
                self.incremental = True
            elif n in (G_INVERSE, G_PER_MIN, G_PER_REV):
                self.feed_mode = n
            elif n == G_CSS:
                self.css = True
            elif n == G_RPM:
                self.css = False
            elif n in G_MACHINE:
                machine_move = True
            elif n == self._inch_in or n == self._metric_in:
                self.src_units = "inch" if n == self._inch_in else "metric"
                self._set_factor()
                units_at = i
                self.units_seen = True
            else:
                continue
            self._plans = None
        # 2. the words
        if (block.info is None and self.units_seen and not (dwell or set_position or machine_move
                                                            or self.incremental or units_at >= 0)
                and self.fast):
            fast = self._fast(block)
            if fast is None and self.options.spacing == "keep":
                return text
            if fast is not None and self.options.spacing == "keep" and text == " ".join(words):
                return " ".join(fast)
            return self._text(block, fast or words, "")
        new: list[str] | None = None
        insert = ""
        if not self.units_seen and self._selects_nothing_yet(words):
            self.units_seen = True
            if self.length != 1 or self.out_units != self.target.default_units:
                insert = self._units_code()
                stats.note(f"inserted {insert}: the program did not select its units before "
                           f"line {block.line}")
        for i, tok in enumerate(words):
            kind = _KIND.get(tok[0].upper())
            if kind is None:
                continue
            try:
                if kind == COUNT:
                    out = self._units_code() if i == units_at else self._count(tok)
                else:
                    out = self._value(block, i, tok, kind, dwell, set_position)
            except ConversionError as exc:
                raise self._locate(exc, block, i) from None
            if out != tok:
                stats.changed += 1
                if new is None:
                    new = list(words)
                new[i] = out
        if machine_move:
            self.src_pos.clear()
            self.out_pos.clear()
            self.abs_raw.clear()
        if new is None and not insert and self.options.spacing == "keep":
            return block.text
        return self._text(block, new or words, insert)

    @staticmethod
    def _selects_nothing_yet(words: list[str]) -> bool:
        """True for the first block with a word that does more than number the program."""
        return any(tok[0].upper() not in "NO:#" for tok in words)

    def _locate(self, exc: ConversionError, block: Block, i: int) -> ConversionError:
        column = block.word_objects()[i].column
        located = exc.located(file=self.file, line=block.line, column=column)
        assert isinstance(located, ConversionError)
        return located

    # -- count words -------------------------------------------------------------------------

    def _count(self, tok: str) -> str:
        letter = tok[0].upper()
        digits = tok[1:]
        if not digits.isdigit():  # indexed or expression: kept as written
            return tok
        fmt = self._out_format(letter)[0]
        if fmt.decimal:  # a count letter the target gives a decimal format: keep it
            return tok
        value = int(digits)
        if len(str(value)) > fmt.before:
            raise ConversionError(
                f"{tok} needs {len(str(value))} digits; the target format {fmt.spec()} holds "
                f"{fmt.before} (digit overflow)", clause="Annex C")
        if fmt.zeros is Zeros.NONE and len(digits) != fmt.before:
            out = tok[0] + str(value).rjust(fmt.before, "0")
        elif len(digits) > fmt.before:
            out = tok[0] + str(value)
        else:
            return tok
        return out

    # -- value words -------------------------------------------------------------------------

    def _value(self, block: Block, i: int, tok: str, kind: int, dwell: bool,
               set_position: bool) -> str:
        letter = tok[0].upper()
        # the factor this word takes in this block's modal state
        factor = self.length
        tracked = False
        if dwell and letter in _DWELL_LETTERS:
            factor = Fraction(1)
        elif kind == AXIS:
            tracked = True
        elif kind == ANGLE:
            factor = Fraction(1)
            tracked = True
        elif kind == FEED:
            if self.feed_mode == G_INVERSE:
                factor = Fraction(1)
        elif kind == SPEED:
            factor = self.speed if self.css and not set_position else Fraction(1)
        elif kind == PQR:
            role = self.pqr.get(letter, "parameter")
            if role != "length":
                if role == "parameter" and self.length != 1 and "=" not in tok:
                    if not self.options.allow_unconverted:
                        raise ConversionError(
                            f"{tok}: the source profile does not say whether {letter} is a "
                            f"length here (checks.pqr.{letter} = \"parameter\"); give a --from "
                            f"profile that does, or --allow-unconverted to leave it as written",
                            clause="6.4.7")
                    self.stats.note(f"{letter} words left unconverted (--allow-unconverted)")
                factor = Fraction(1)
        parsed = _plain(tok)
        if parsed is None:
            return self._expression(block, i, tok, factor)
        neg, plus, ip, dot, fp = parsed
        # the exact source value: m * 10**-k
        if dot or self.explicit_in:
            m = int(ip + fp) if (ip or fp) else 0
            k = len(fp)
        else:
            fmt_in = self._src_format(letter)
            digits = ip
            if fmt_in.zeros is Zeros.TRAILING:
                width = fmt_in.width if fmt_in.decimal else fmt_in.before
                if len(digits) > width:
                    raise ConversionError(f"{tok} has {len(digits)} digits; the source format "
                                          f"{fmt_in.spec()} holds {width}", clause="Annex C")
                digits = digits.ljust(width, "0")
            m = int(digits)
            k = fmt_in.after if fmt_in.decimal else 0
        fmt, after, limit = self._out_format(letter, dwell and letter in _DWELL_LETTERS)
        if tracked and (self.incremental or set_position) and not dwell:
            u = self._tracked(letter, neg, m, k, factor, after, set_position)
        else:
            u = self._scale(letter, m, k, factor, after)
            if neg:
                u = -u
            if tracked and not dwell:
                self.abs_raw[letter] = (neg, m, k)
                self.out_pos[letter] = u
                self.src_pos.pop(letter, None)
        if -limit >= u or u >= limit:
            raise _overflow(tok, abs(u), after, fmt)
        out = tok[0] + _write(u, after, fmt, self.explicit_out, plus)
        # explicit source and target, same value: keep the digits as the source wrote them
        if (out != tok and self.explicit_out and factor == 1 and (dot or self.explicit_in)
                and k <= after):
            return tok
        return out

    def _scale(self, letter: str, m: int, k: int, factor: Fraction, after: int) -> int:
        """round(m * 10**-k * factor / 10**-after) under the rounding policy, error recorded."""
        numerator = m * factor.numerator * _POW10[after]
        denominator = factor.denominator * _POW10[k]
        if denominator == 1:
            return numerator
        q, r = divmod(numerator, denominator)
        if r:
            q = self._round(letter, q, r, denominator, after)
        return q

    def _round(self, letter: str, q: int, r: int, denominator: int, after: int) -> int:
        twice = 2 * r
        if self.rounding is Rounding.ERROR:
            raise _rounding_refused(letter, after)
        if twice > denominator or (twice == denominator and
                                   (self.rounding is Rounding.HALF_UP or q & 1)):
            q += 1
            r = denominator - r
        self._record(letter, r, denominator * _POW10[after])
        return q

    def _record(self, letter: str, e: int, d: int) -> None:
        worst = self._worst.get(letter)
        if worst is None or e * worst[1] > worst[0] * d:
            self._worst[letter] = (e, d)

    def finish(self) -> ConvertStats:
        """The statistics, with the largest rounding per address as exact fractions."""
        self.stats.rounding = {letter: Fraction(e, d) for letter, (e, d) in self._worst.items()}
        return self.stats

    def _tracked(self, letter: str, neg: bool, m: int, k: int, factor: Fraction, after: int,
                 set_position: bool) -> int:
        """An incremental (or G92) axis word: convert the exact absolute position, write the
        difference of converted absolutes."""
        value = Fraction(-m if neg else m, _POW10[k])
        start = self.src_pos.get(letter)
        if start is None:
            raw = self.abs_raw.pop(letter, None)
            start = Fraction(-raw[1] if raw[0] else raw[1], _POW10[raw[2]]) if raw else Fraction(0)
        position = value if set_position else start + value
        self.src_pos[letter] = position
        exact = position * factor * _POW10[after]
        q, r = divmod(exact.numerator, exact.denominator)
        if r:
            q = self._round(letter, q, r, exact.denominator, after)
        previous = self.out_pos.get(letter, 0)
        self.out_pos[letter] = q
        return q if set_position else q - previous

    # -- parameter expressions ---------------------------------------------------------------

    def _expression(self, block: Block, i: int, tok: str, factor: Fraction) -> str:
        """An indexed word or an expression: numbers converted where they are provably lengths."""
        address, index, sign, number, expression = split_token(tok)
        letter = address.upper()
        is_length = factor != 1 and _KIND.get(letter) in (AXIS, CENTRE, PQR, FEED, SPEED)
        if index and letter in "PQR#" and self.pqr.get(letter, "parameter") == "parameter" \
                or address == "#":
            name = f"{address}{index}"
            is_length = self.parameters is not None and self.parameters.is_length(name)
            if self.length != 1 and not is_length:
                problem = self.parameters.problems.get(name) if self.parameters else None
                if problem and not self.options.allow_unconverted:
                    raise ConversionError(f"cannot convert the units of parameter {name}: "
                                          f"{problem}", clause="6.4.7")
                if problem:
                    self.stats.note(f"parameter {name} left unconverted: {problem}")
            factor = self.length if is_length else Fraction(1)
        written = _written(block, i, tok)
        if number:  # "X1=12.5" / "R11=22.2": an indexed plain number
            if factor == 1 and self.explicit_out:
                return tok
            m, k = _decimal_parts(Decimal(number))
            fmt, after, _ = self._out_format("X" if index and letter in "PQR#" else letter)
            u = self._scale(letter, m, k, factor, after)
            digits = _write(-u if sign == "-" else u, after, fmt, True, sign == "+")
            tail = sign + number
            if written.endswith(tail):
                return written[:len(written) - len(tail)] + digits
            return tok[:len(tok) - len(tail)] + digits
        # an expression: convert the number terms of a linear expression of lengths
        if factor == 1:
            return tok
        at = written.find("=") + 1 if index else 1
        try:
            numbers, _ = linear_parts(parse_expression(written[at:]))
        except NotLinear:
            if self.options.allow_unconverted:
                self.stats.note(f"line {block.line}: {tok} left unconverted (non-linear)")
                return tok
            raise ConversionError(
                f"{tok}: the value is a non-linear expression, so its units cannot be converted "
                "exactly (use --allow-unconverted to leave it as written)", clause="6.4.7"
            ) from None
        if not numbers:
            return tok
        after = self._out_format("X" if letter in "PQR#" else letter)[1]
        pieces = []
        pos = 0
        for number_token in numbers:
            start = at + (number_token.start_pos or 0)
            m, k = _decimal_parts(Decimal(str(number_token)))
            u = self._scale(letter, m, k, factor, after)
            pieces.append(written[pos:start])
            pieces.append(_explicit(u, after))
            pos = start + len(str(number_token))
        pieces.append(written[pos:])
        return "".join(pieces)


    # -- text --------------------------------------------------------------------------------

    def _text(self, block: Block, tokens: list[str], insert: str) -> str:
        spacing = self.options.spacing
        if spacing != "keep":
            return _respace(block, tokens, insert, spacing)
        words = block.words
        replacements = {i: t for i, t in enumerate(tokens) if t != words[i]}
        if insert:
            at = 1 if words[0][0] in "Nn" else 0
            if at == 1:
                replacements[0] = replacements.get(0, words[0]) + " " + insert
            else:
                replacements[0] = insert + " " + replacements.get(0, words[0])
        if block.info is None and block.text == " ".join(words):
            return " ".join(replacements.get(i, t) for i, t in enumerate(words))
        return replace_words(block, replacements)


# Letters a run of plain blocks may hold besides N and the motion codes G00-G03.
_BULK_LETTERS = "XYZUVWABCIJKFESPQRNG"
_EOB_RE = re.compile(r"\r*\n")


class _BulkPlan:
    """The tables of :meth:`Converter._convert_run`, indexed by the letter's byte (and the
    number of decimals ``k`` of the source word), for the modal state whose plans they hold."""

    def __init__(self, plans: dict[str, WordPlan]) -> None:
        self.plans = plans
        self.run: re.Pattern[str] = re.compile("(?!)")
        self.value = np.zeros(256, dtype=np.bool_)
        self.num = np.ones((256, 16), dtype=np.int64)
        self.den = np.ones((256, 16), dtype=np.int64)
        self.error_den: dict[str, list[int]] = {}
        self.max_num = 1
        self.limit = np.zeros(256, dtype=np.int64)
        self.keep = np.zeros(256, dtype=np.bool_)
        self.after = np.zeros(256, dtype=np.int64)
        self.width = np.zeros(256, dtype=np.int64)
        self.mode = np.zeros(256, dtype=np.int64)
        self.tracked: list[str] = []


def _written(block: Block, i: int, tok: str) -> str:
    """Word ``i`` as written in the block, spaces inside it (``R11 = 22.2``) included."""
    word = block.word_objects()[i]
    start = word.column - 1
    return block.text[start:token_span(block.text, start, tok)]


def _respace(block: Block, tokens: list[str], insert: str, spacing: str) -> str:
    """The block rebuilt from its pieces (skip, words, comments) with no spaces ("remove") or one
    space between pieces ("insert")."""
    pieces: list[tuple[int, str]] = []
    for word, token in zip(block.word_objects(), tokens, strict=True):
        pieces.append((word.column, token))
    for column, comment in block.comments:
        pieces.append((column, comment))
    pieces.sort()
    texts = [t for _, t in pieces]
    if insert:
        at = 1 if texts and texts[0][0] in "Nn" else 0
        texts.insert(at, insert)
    joiner = "" if spacing == "remove" else " "
    line = joiner.join(texts)
    if block.skip:
        line = block.skip + joiner + line if spacing == "insert" else block.skip + line
    return line + ("\r" if block.text.endswith("\r") else "")


def _plain(tok: str) -> tuple[bool, bool, str, str, str] | None:
    """(negative, plus written, integer digits, ".", fraction digits) of a plain word token."""
    body = tok[1:]
    first = body[:1]
    neg = first == "-"
    plus = first == "+"
    if neg or plus:
        body = body[1:]
    ip, dot, fp = body.partition(".")
    if not (ip.isdigit() or not ip) or not (fp.isdigit() or not fp) or not (ip or fp):
        return None
    return neg, plus, ip, dot, fp


def _decimal_parts(value: Decimal) -> tuple[int, int]:
    sign, digits, exponent = value.as_tuple()
    assert isinstance(exponent, int)
    m = int("".join(map(str, digits)) or "0")
    if exponent > 0:
        return (-1 if sign else 1) * m * _POW10[exponent], 0
    return (-1 if sign else 1) * m, -exponent


def _explicit(u: int, after: int) -> str:
    """Explicit text of ``u * 10**-after``: ``12.5``, ``0.03``, ``10.``, ``0``."""
    if u == 0:
        return "0"
    sign = "-" if u < 0 else ""
    digits = str(abs(u))
    if after:
        digits = digits.rjust(after + 1, "0")
        whole, fraction = digits[:-after], digits[-after:].rstrip("0")
    else:
        whole, fraction = digits, ""
    return f"{sign}{whole}.{fraction}"


def _write(u: int, after: int, fmt: WordFormat, explicit: bool, plus: bool) -> str:
    """The digits after the address of the value ``u * 10**-after`` in the target format."""
    if explicit and fmt.decimal:
        text = _explicit(u, after)
        return "+" + text if plus and u > 0 else text
    sign = "-" if u < 0 else ("+" if plus and u > 0 else "")
    if u == 0:
        return "0"
    digits = str(abs(u))
    zeros = fmt.zeros
    if zeros is Zeros.LEADING:
        return sign + digits
    width = fmt.width if fmt.decimal else fmt.before
    full = digits.rjust(width, "0")
    if zeros is Zeros.TRAILING:
        full = full.rstrip("0")
    return sign + full


def _rounding_refused(letter: str, after: int) -> ConversionError:
    return ConversionError(f"{letter}: the value needs more than {after} decimals in the target "
                           "format and rounding is not allowed (--round error)", clause="Annex C")


def _overflow(tok: str, u: int, after: int, fmt: WordFormat) -> ConversionError:
    """Digit overflow of ``tok``, whose magnitude is ``u * 10**-after`` in the target."""
    return ConversionError(
        f"{tok} is {_explicit(u, after).rstrip('.')} in the target format {fmt.spec()}, which "
        f"holds {fmt.before} digits before the decimal sign (digit overflow)", clause="Annex C")


# ---------------------------------------------------------------------------------------------
# Files


def has_parameters(chunks: Iterable[bytes] | Iterable[str]) -> bool:
    """Whether a program may hold parameter assignments or expressions (a cheap scan)."""
    return any("=" in c or "#" in c if isinstance(c, str) else b"=" in c or b"#" in c
               for c in chunks)


def analyse_parameters(blocks: Iterable[Block], source: Profile) -> ParameterClasses:
    """Which parameters of a program are lengths (:mod:`formats.lengths`)."""
    analysis = ParameterAnalysis()
    pqr = source.checks.pqr
    for block in blocks:
        for tok in block.words:
            if "=" not in tok and "#" not in tok and "[" not in tok:
                continue
            address, index, _, _, expression = split_token(tok)
            letter = address.upper()
            kind = _KIND.get(letter)
            is_param = address == "#" or (index and letter in "PQR"
                                          and pqr.get(letter, "parameter") == "parameter")
            if is_param and index:
                analysis.assignment(f"{address}{index}", expression or "0", block.line)
            elif expression:
                length = kind in (AXIS, CENTRE) or (kind == PQR and pqr.get(letter) == "length")
                analysis.word(expression, length, block.line)
    return analysis.result()


def convert_file(path: str, output: str | None, options: ConvertOptions, *,
                 overwrite: bool = False, verify: bool = False, display: str | None = None
                 ) -> ConvertStats:
    """Convert one file; ``output`` None is a dry run (everything but the write).

    The output is written through a temporary file in its folder and renamed into place only
    when the whole program converted (and verified): a failure leaves nothing behind. An existing
    output is refused unless ``overwrite``.
    """
    name = display or path
    stats = ConvertStats(file=name, output=output or "")
    if output is not None and not overwrite and os.path.exists(output):
        raise ConversionError(f"{output} exists; use --force to overwrite it", file=name)
    source = options.source
    if source is None:
        head = next(iter(Source(path).chunks()), "")
        source, notes = detect_source(head[:CHUNK])
        stats.notes.extend(notes)
    parameters = None
    if options.units and has_parameters(read_chunks(path, CHUNK)):
        parameters = analyse_parameters(
            parse_stream(Source(path).chunks(), source.dialect, file=name), source)
    converter = Converter(options, source, file=name, parameters=parameters, stats=stats)
    folder = Path(output).parent if output else Path(tempfile.gettempdir())
    folder.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=".tapegate-", suffix=".part", dir=folder)
    try:
        with os.fdopen(fd, "wb") as out:
            for text in converter.convert_stream(Source(path).chunks(), source.dialect):
                out.write(text.encode("utf-8", errors="surrogateescape"))
            out.flush()
            os.fsync(out.fileno())
        if verify:
            from formats.verify import verify_conversion
            verify_conversion(path, tmp, source, options, stats, file=name)
            stats.verified = True
        if output is not None:
            if overwrite:
                os.replace(tmp, output)
            else:
                os.link(tmp, output)  # fails rather than replace a file that appeared meanwhile
                os.unlink(tmp)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
    return stats


def convert_text(text: str, options: ConvertOptions, *, file: str | None = None
                 ) -> tuple[str, ConvertStats]:
    """Convert a program held in memory (tests, small programs)."""
    source = options.source
    notes: list[str] = []
    if source is None:
        source, notes = detect_source(text)
    parameters = None
    if options.units and has_parameters([text]):
        parameters = analyse_parameters(parse_stream([text], source.dialect, file=file), source)
    stats = ConvertStats(file=file or "<text>", notes=notes)
    converter = Converter(options, source, file=file, parameters=parameters, stats=stats)
    out = "".join(converter.convert_stream([text], source.dialect))
    return out, stats

