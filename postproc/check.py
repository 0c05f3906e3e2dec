"""The checker: a program against a machine profile, rule by rule (:mod:`postproc.rules`).

One pass over the blocks, in flat memory: the parser collects unreadable blocks instead of
stopping (each becomes a finding), :class:`postproc.state.ModalMachine` gives the state before and
after every block, and the checks below read both. Findings stream out as they are found; the
program-level ones (start, end) come when the program ends.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from decimal import Decimal
from itertools import chain

from formats.errors import ParseError, TapegateError
from formats.model import Block, Word
from formats.parser import BadBlock, Dialect, parse_lines, parse_stream, whole_lines
from formats.profile import NEUTRAL, Profile, load_profile
from formats.source import Source
from formats.tape import TapeIssue
from postproc.findings import (
    DIMENSIONS,
    Finding,
    decimals_message,
    digits_tail,
    no_centre_message,
    no_start_message,
    order_messages,
    order_ranks,
    radii_messages,
    tv_messages,
)
from postproc.plain import PlainRuns
from postproc.rules import RULES
from postproc.state import CENTRE_OF, PLANE_AXES, ModalMachine, ModalState

_WORDLIKE = re.compile(r"\s*[A-Z][+-]?[0-9]")


@dataclass
class Segment:
    """One move, for the backplot: rapid, feed or arc (with its centre and direction)."""

    kind: str  # rapid | feed | arc
    start: tuple[float, float, float]
    end: tuple[float, float, float]
    line: int
    centre: tuple[float, float, float] | None = None
    clockwise: bool = False
    plane: int = 17


@dataclass
class CheckStats:
    blocks: int = 0
    low: dict[str, Decimal] = field(default_factory=dict)
    high: dict[str, Decimal] = field(default_factory=dict)
    rapid_length: float = 0.0
    feed_length: float = 0.0
    seconds: float = 0.0
    tools: list[int] = field(default_factory=list)
    units: str = "metric"


class Checker:
    """Checks one program. ``select`` / ``ignore`` are rule IDs or prefixes (``TG4``)."""

    def __init__(self, profile: Profile, file: str = "<input>", *,
                 select: Iterable[str] = (), ignore: Iterable[str] = (),
                 record_path: bool = False) -> None:
        self.profile = profile
        self.file = file
        self.select = tuple(select)
        self.ignore = tuple(ignore)
        self.machine = ModalMachine(profile)
        self.stats = CheckStats(units=profile.default_units)
        self.path: list[Segment] | None = [] if record_path else None
        self.checks = profile.checks
        self.formats = profile.detailed.formats
        self._found: list[Finding] = []
        self._first = True
        self._started = False  # a % line was seen first
        self._first_words = True  # the next block with words is the first after %
        self._ended_line = 0
        self._after_end_reported = False
        self._closed = False
        self._styles: set[str] = set()
        self._mixed_reported = False
        self._first_implicit: Word | None = None
        self._g06_open: int | None = None
        self._speed_limit_seen = False
        self._last_line = 0
        self.plain = PlainRuns(self)

    # -- findings ------------------------------------------------------------------------------

    def enabled(self, rule: str) -> bool:
        if self.select and not rule.startswith(self.select):
            return False
        return not (self.ignore and rule.startswith(self.ignore))

    def report(self, rule: str, message: str, line: int, column: int = 1) -> None:
        if not self.enabled(rule):
            return
        r = RULES[rule]
        self._found.append(Finding(rule, r.severity, message, self.file, line, column, r.clause))

    # -- the walk ------------------------------------------------------------------------------

    def run(self, blocks: Iterable[Block]) -> Iterator[Finding]:
        """Findings for a program's blocks, then the program-level ones."""
        return chain.from_iterable(self._batches_of(blocks))

    def run_stream(self, chunks: Iterable[str], dialect: Dialect) -> Iterator[Finding]:
        """Findings for a program arriving as text chunks (the way files are checked).

        Runs of plain blocks, in a modal state the fast path follows, are checked a run at a
        time by :mod:`postproc.plain`; every other block goes through :meth:`block`. The
        findings are the same either way, in the same order.
        """
        return chain.from_iterable(self._batches(chunks, dialect))

    def _batches(self, chunks: Iterable[str], dialect: Dialect) -> Iterator[list[Finding]]:
        """The findings a chunk at a time (passed on by ``chain``, in C: there can be
        millions)."""
        for text, line, unread in whole_lines(chunks):
            if unread is None:
                self._lines(text, line, dialect)
                yield self._take()
            else:
                yield from self._batches_of(parse_stream(
                    chain([text], unread), dialect, file=self.file, errors="collect",
                    first_line=line))

    def _batches_of(self, blocks: Iterable[Block]) -> Iterator[list[Finding]]:
        """The findings of each block, then those of the program's end."""
        for block in blocks:
            self.block(block)
            if self._found:
                yield self._take()
        self.finish()
        yield self._take()

    def _take(self) -> list[Finding]:
        found = self._found
        self._found = []
        return found

    def _lines(self, data: str, line: int, dialect: Dialect) -> None:
        """Whole lines (each ending with LF, the first being line ``line + 1``); their
        findings wait in :attr:`_found` (a chunk's worth at most)."""
        if self.plain.usable():
            self.plain.check(data, line, dialect)
            return
        for block in parse_lines(data[:-1], line, dialect, self.file, "collect"):
            self.block(block)

    def tape(self, issues: Iterable[TapeIssue]) -> Iterator[Finding]:
        for issue in issues:
            rule = "TG701" if issue.kind == "parity" else "TG702"
            self.report(rule, f"{issue.message()} at byte {issue.offset}", issue.line,
                        issue.column)
        yield from self._found
        self._found.clear()

    def block(self, block: Block) -> None:
        self.stats.blocks += 1
        self._last_line = block.line
        if isinstance(block, BadBlock):
            self._unreadable(block)
            return
        first = self._first
        self._first = False
        if block.percent:
            if first:
                self._started = True
                self._identification(block)
            elif self._ended_line:
                self._closed = True
            return
        if first:
            self.report("TG110", "the program does not begin with %", block.line)
        if not block.words:  # a comment line is a block too: the TV check counts it, a
            self._tv(block)  # control reads a ':' or '%' in it
            for column, comment in block.comments:
                self._comment(comment, block.line, column)
            return
        if self._ended_line and not self._after_end_reported:
            self._after_end_reported = True
            self.report("TG116", f"words after the end of program on line {self._ended_line}",
                        block.line)
        words = block.word_objects()
        self._program_number(block, words)
        self._tv(block)
        values = self._words(block, words)
        before, after, gs, v = self._step(words, values)
        self._codes(block, words, values, before, after, gs, v)
        if any(w.letter == "M" and values.get(i) in (2, 30) for i, w in enumerate(words)):
            self._ended_line = block.line

    def finish(self) -> None:
        line = self._last_line or 1
        if not self._ended_line:
            self.report("TG114", "the program has no M02 or M30", line)
        elif not self._closed:
            self.report("TG115", "M02/M30 is not followed by the closing %", line)

    # -- structure -----------------------------------------------------------------------------

    def _unreadable(self, block: BadBlock) -> None:
        error: ParseError = block.error
        text = error.message
        nested = _nested_comment(block.text)
        if nested:
            self.report("TG121", "comment inside a comment: '(' before the ')' that closes the "
                                 "first", block.line, nested)
            self._first = False
            return
        rule = error.code or "TG100"  # the core names the rule; no message is matched
        self.report(rule, text, block.line, error.column or 1)
        self._first = False

    def _identification(self, block: Block) -> None:
        ident = block.info.ident if block.info else ""
        if not ident.strip():
            return
        if _WORDLIKE.match(ident):
            self.report("TG111", f"words after % ({ident.strip()!r}): the first block must "
                                 "follow an end of block", block.line, 2)
        elif any(c.isalpha() for c in ident) and not ident.lstrip().startswith("("):
            self.report("TG112", f"identification {ident.strip()!r} contains letters and must "
                                 "be enclosed in parentheses", block.line, 2)
        for column, comment in block.comments:
            self._comment(comment, block.line, column)

    def _comment(self, comment: str, line: int, column: int) -> None:
        for ch in ":%":
            if ch in comment:
                self.report("TG122", f"comment contains {ch!r}, which a control may read as "
                                     f"{'alignment' if ch == ':' else 'a rewind stop'}", line,
                            column + comment.index(ch))

    def _program_number(self, block: Block, words: list[Word]) -> None:
        letter = self.profile.program_number
        first = self._first_words
        self._first_words = False
        if not letter or letter == ":":
            return
        for w in words:
            if w.letter == letter and not first and letter not in "PQR":
                self.report("TG113", f"program number {w.token} is not in the first block "
                                     "after %", block.line, w.column)

    def _tv(self, block: Block) -> None:
        if not self.profile.serial.tv_check:
            return
        length = len(block.text.replace("\r", ""))
        if length % 2:
            self.report("TG703", tv_messages([length])[0], block.line, length)

    # -- words ---------------------------------------------------------------------------------

    def _words(self, block: Block, words: list[Word]) -> dict[int, Decimal]:
        """Checks of the words themselves; returns the readable values (by word index)."""
        values: dict[int, Decimal] = {}
        line = block.line
        seen: dict[str, Word] = {}
        last_rank = -1.0
        g_count = 0
        ranks = order_ranks(self.machine.state.plane)
        for column, comment in block.comments:
            self._comment(comment, line, column)
        if block.skip and words and words[0].letter != "N":
            self.report("TG123", "'/' block skip must immediately precede the sequence number",
                        line, 1)
        for i, w in enumerate(words):
            letter = w.letter
            if w.address.islower():
                self.report("TG102", f"lower-case address {w.address!r}", line, w.column)
            if letter == ":":
                if not self.profile.detailed.alignment:
                    self.report("TG124", "':' alignment, but the profile's classification has "
                                         "no ':'", line, w.column)
                if i:
                    self.report("TG125", "alignment ':' must start the block", line, w.column)
            if letter == "G":
                g_count += 1
            # order (5.2)
            rank = ranks.get(letter, -1.0)
            if rank >= 0:
                if rank < last_rank:
                    self.report("TG130", order_messages([w.token])[0], line, w.column)
                last_rank = max(last_rank, rank)
            # repetition
            key = w.key
            if key in seen and letter not in ":":
                if letter in DIMENSIONS or letter in "IJK":
                    self.report("TG131", f"{w.token} repeats dimension word {seen[key].token}",
                                line, w.column)
                elif letter != "G" and letter not in self.checks.repeatable:
                    self.report("TG132", f"{w.token} repeats {seen[key].token} in one block",
                                line, w.column)
            seen.setdefault(key, w)
            if letter not in self.formats and letter not in ":#" and self.formats:
                self.report("TG134", f"address {letter} is not in the profile's classification "
                                     f"{self.profile.detailed}", line, w.column)
            if w.index:
                n = int(w.index)
                most = (self.checks.max_parameter if letter == "#" or (
                    letter in "PQR" and self.checks.pqr.get(letter) == "parameter")
                    else self.checks.max_index)
                if n == 0 or n > most:
                    self.report("TG206", f"index {n} of {letter}: allowed 1 to {most}", line,
                                w.column)
                if letter == "G" and not self.checks.index_g:
                    self.report("TG207", f"{w.token}: the indexing of G codes is not intended "
                                         "(ISO 6983-1 6.2.2); checks.index_g allows it", line,
                                w.column)
            if w.expression or letter in ":#":
                continue
            value = self._format(w, line)
            if value is not None:
                values[i] = value
        if g_count > 1:
            first_g = next(w for w in words if w.letter == "G")
            self.report("TG133", f"{g_count} G words in one block; Annex D recommends one",
                        line, first_g.column)
        return values

    def _format(self, w: Word, line: int) -> Decimal | None:
        """Annex C checks of one plain word; its value, or None if it cannot be read."""
        fmt = self.profile.word_format(w.letter)
        number = w.number
        explicit = "." in number
        if explicit and not self.profile.explicit:
            self.report("TG202", f"{w.token}: decimal point, but the profile has no DS "
                                 "(implicit decimal only)", line, w.column)
        if w.sign and not fmt.signed and w.letter in self.formats:
            self.report("TG204", f"{w.token}: the format {fmt.spec()} has no sign", line,
                        w.column)
        if (self.profile.explicit and fmt.decimal and w.letter in DIMENSIONS + "IJK"
                and not self._mixed_reported):
            # A whole number with more digits than the format has decimals looks implicit
            # (X12500 for 12.5 under 5.3); it is read as a whole number in an explicit program.
            if explicit:
                self._styles.add("explicit")
                first = self._first_implicit
            else:
                first = None
                if len(number.lstrip("0")) > fmt.after:
                    self._styles.add("implicit")
                    self._first_implicit = self._first_implicit or w
                    first = w
            if len(self._styles) == 2 and first is not None:
                self._mixed_reported = True
                self.report("TG201", f"{first.token} looks like an implicit-decimal word in a "
                                     "program that uses decimal points; it is read as the whole "
                                     f"number {first.number} (6.1: the two must not be mixed)",
                            line, first.column)
        try:
            value = self.profile.value(w.token)
        except TapegateError as exc:
            self.report("TG203", f"{w.token}: {exc.message}", line, w.column)
            return None
        if w.letter in self.formats:
            whole, _, fraction = number.partition(".")
            after = fmt.after if fmt.decimal else 0
            if explicit and len(fraction.rstrip("0")) > after:
                self.report("TG203", decimals_message(w.token, fmt), line, w.column)
            elif not explicit and not self.profile.explicit and fmt.decimal \
                    and len(number) > fmt.width:
                self.report("TG203", f"{w.token}: {len(number)} digits; the format "
                                     f"{fmt.spec()} holds {fmt.width}", line, w.column)
            integer_digits = len(str(int(abs(value)))) if abs(value) >= 1 else 0
            if integer_digits > fmt.before:
                self.report("TG205", w.token + digits_tail(integer_digits, fmt), line,
                            w.column)
        return value

    def _step(self, words: list[Word], values: dict[int, Decimal]
              ) -> tuple[ModalState, ModalState, list[int], dict[str, Decimal]]:
        """Apply the block to the modal state: (before, after, its G codes, its other values
        by letter, the first of each)."""
        machine = self.machine
        before = machine.state.copy()
        gs: list[int] = []
        ms: list[int] = []
        plain: dict[str, Decimal] = {}
        for i, w in enumerate(words):
            v = values.get(i)
            if v is None:
                continue
            if w.letter == "G":
                gs.append(int(v))
            elif w.letter == "M":
                ms.append(int(v))
            else:
                plain.setdefault(w.letter, v)
        machine.apply_words(gs, ms, plain)
        return before, machine.state, gs, plain

    # -- codes, motion, clauses ----------------------------------------------------------------

    def _codes(self, block: Block, words: list[Word], values: dict[int, Decimal],
               before: ModalState, after: ModalState, g_list: list[int],
               v: dict[str, Decimal]) -> None:
        line = block.line
        groups: dict[str, Word] = {}
        for i, w in enumerate(words):
            if w.letter not in "GM" or i not in values:
                continue
            n = int(values[i])
            klass = n // 100 if w.letter == "M" and n >= 100 else 0
            if klass and klass not in self.checks.m_classes:
                self.report("TG305", f"{w.token}: class {klass} M codes are not in the profile "
                                     f"(classes {sorted(self.checks.m_classes)})", line, w.column)
            code = self.profile.code(w.letter, n % 100 if klass else n)
            if code is None:
                self.report("TG301", f"{w.token} is not a code of {self.profile.table.name}",
                            line, w.column)
                continue
            if code.status == "permanent":
                self.report("TG303", f"{w.token} is permanently unassigned", line, w.column)
            elif code.status == "unassigned":
                self.report("TG302", f"{w.token} is unassigned (individual use) and the profile "
                                     "does not designate it", line, w.column)
            if code.modal:
                other = groups.get(code.duration)
                if other is not None and other.token != w.token:
                    self.report("TG304", f"{w.token} and {other.token} are both in modal group "
                                         f"{code.duration}", line, w.column)
                groups.setdefault(code.duration, w)
        gs = set(g_list)
        first_col = words[0].column

        def col(letter: str) -> int:
            return next((w.column for w in words if w.letter == letter), first_col)

        moved = [a for a in "XYZUVWABC" if a in v]
        # dwell (13)
        if 4 in gs:
            duration = [a for a in "FPX" if a in v]
            if not duration:
                self.report("TG532", "G04 without a duration (F, P or X)", line, col("G"))
            others = [w for w in words if w.letter not in "NG" and w.letter not in "FPX"]
            if others or len(g_list) > 1:
                self.report("TG531", "G04 dwell should stand alone in its block", line,
                            (others[0].column if others else col("G")))
            self._dwell_time(v, after)
            return
        # constant surface speed (12)
        if 92 in gs and "S" in v:
            self._speed_limit_seen = True
        if 96 in gs and not self._speed_limit_seen:
            self.report("TG521", "G96 without an earlier G92 S spindle speed limit", line,
                        col("G"))
        # compensation (10)
        if before.compensation != after.compensation and after.motion in (2, 3) and moved:
            self.report("TG501", f"G{after.compensation} in a circular interpolation block",
                        line, col("G"))
        if before.compensation in (41, 42) and 40 not in gs and ("T" in v or "D" in v):
            letter = "T" if "T" in v else "D"
            self.report("TG502", f"{letter} word while G{before.compensation} is active; "
                                 "program G40 first", line, col(letter))
        # threads (11)
        lead = [a for a in "IJK" if a in v]
        if (33 in gs or (after.motion == 33 and moved)) and lead and "F" in v:
            self.report("TG511", "G33 has its lead in I/J/K: F must not be programmed",
                        line, col("F"))
        if after.motion in (33, 34, 35):
            for w in words:
                if w.letter in "IJK" and w.sign:
                    self.report("TG512", f"{w.token}: a thread lead has no sign", line, w.column)
        if gs & {34, 35} and not ((lead and "F" in v) or ("F" in v and "K" in v)):
            self.report("TG513", "G34/G35 needs the initial lead (I/J/K) and the rate (F)", line,
                        col("G"))
        # fixed cycles (Annex E)
        cycle_codes = gs & set(range(81, 90))
        if cycle_codes:
            missing = [a for a in "ZR" if a not in v]
            if missing:
                self.report("TG541", f"G{min(cycle_codes)} without {' and '.join(missing)}",
                            line, col("G"))
        if before.cycle is not None and gs & {0, 1, 2, 3}:
            self.report("TG542", f"motion code while cycle G{before.cycle} is active; G80 first",
                        line, col("G"))
        # feeds (7, Annex E)
        feed_motion = after.motion in (1, 2, 3, 6) and after.cycle is None and moved
        if feed_motion and after.feed is None:
            self.report("TG401", "feed motion with no feed rate in force", line, col(moved[0]))
        if feed_motion and after.feed_mode == 93 and "F" not in v:
            self.report("TG402", "G93 inverse time: every motion block needs its F", line,
                        col(moved[0]))
        if after.motion == 6 or self._g06_open is not None:
            self._parabola(line, gs, v, after, moved)
        if after.motion in (2, 3) and (moved or lead or "R" in v) and after.cycle is None:
            self._arc(line, words, v, before, after, col)
        # limits
        self._limits(line, v, after, col, moved)
        self._motion_stats(before, after, moved, v, line)

    def _parabola(self, line: int, gs: set[int], v: dict[str, Decimal], after: ModalState,
                  moved: list[str]) -> None:
        if self._g06_open is not None:
            if not (after.motion == 6 and moved):
                self.report("TG407", "G06 three-point parabola without its end point block",
                            self._g06_open)
            self._g06_open = None
            return
        if 6 in gs and not any(a in v for a in "IJK"):
            self._g06_open = line

    def _arc(self, line: int, words: list[Word], v: dict[str, Decimal], before: ModalState,
             after: ModalState, col: Callable[[str], int]) -> None:
        first, second, third = PLANE_AXES[after.plane]
        centre_words = {CENTRE_OF[first], CENTRE_OF[second]}
        given = [a for a in "IJK" if a in v]
        for a in given:
            if a not in centre_words:
                self.report("TG404", f"{a} is not a centre word of the G{after.plane} plane",
                            line, next(w.column for w in words if w.letter == a))
                return
        radius_word = "R" in v and self.checks.pqr.get("R") == "length"
        if not given and not radius_word:
            self.report("TG404", no_centre_message(after.plane), line, words[0].column)
            return
        if first not in before.position or second not in before.position:
            self.report("TG408", no_start_message(after.plane), line, words[0].column)
            return
        if radius_word:
            return
        sx, sy = float(before.position[first]), float(before.position[second])
        ex = float(after.position.get(first, before.position[first]))
        ey = float(after.position.get(second, before.position[second]))
        ci = float(v.get(CENTRE_OF[first], 0))
        cj = float(v.get(CENTRE_OF[second], 0))
        helix = next((w.column for w in words if w.letter == third), 0) if third in v else 0
        self.arc_geometry(line, words[0].column, (sx, sy), (ex, ey), (ci, cj),
                          after.motion == 2, 1 / 25.4 if after.units == "inch" else 1.0,
                          third, helix)

    def arc_geometry(self, line: int, column: int, start: tuple[float, float],
                     end: tuple[float, float], ij: tuple[float, float], clockwise: bool,
                     scale: float, third: str, helix: int) -> None:
        """The radius checks of an arc whose start point is known (and TG406 at column
        ``helix`` when the third axis moves with it); shared with :mod:`postproc.plain`."""
        (sx, sy), (ex, ey) = start, end
        cx, cy = self._centre(start, end, ij, clockwise, scale)
        r1 = math.hypot(sx - cx, sy - cy)
        r2 = math.hypot(ex - cx, ey - cy)
        if r1 == 0 or r2 == 0:
            self.report("TG405", "arc of zero radius (the centre is on the start or end point)",
                        line, column)
            return
        tolerance = self._arc_tolerance(r1, r2, scale)
        if abs(r1 - r2) > tolerance:
            self.report("TG403", radii_messages([r1], [r2], [tolerance])[0], line, column)
        elif self.checks.ijk == "quadrant" and not _in_one_quadrant(
                start, end, (cx, cy), clockwise):
            self.report("TG409", "arc crosses a quadrant boundary: this control limits a block "
                                 "to one quadrant (7.3); split it at the axis crossing", line,
                        column)
        if helix:
            self.helical(third, line, helix)

    def helical(self, third: str, line: int, column: int) -> None:
        self.report("TG406", f"helical arc: {third} moves with the arc", line, column)

    def travel(self, axis: str, position: Decimal, line: int, column: int) -> None:
        """TG601 if ``position`` is outside the axis's travel (shared with the fast path)."""
        low, high = self.profile.limits.axes[axis]
        if not low <= position <= high:
            self.report("TG601", f"{axis} goes to {position}, outside the travel {low} to "
                                 f"{high}", line, column)

    def feed_limit(self, feed: Decimal, line: int, column: int) -> None:
        """TG602 if ``feed`` is above the profile's maximum (shared with the fast path)."""
        top = self.profile.limits.feed_max
        if top is not None and feed > top:
            self.report("TG602", f"feed {feed} above the maximum {top}", line, column)

    def _arc_tolerance(self, r1: float, r2: float, scale: float) -> float:
        return max(float(self.checks.arc_tolerance) * scale,
                   float(self.checks.arc_tolerance_relative) * max(r1, r2))

    def _centre(self, start: tuple[float, float], end: tuple[float, float],
                ij: tuple[float, float], clockwise: bool, scale: float) -> tuple[float, float]:
        """The arc centre in the plane, as the profile reads I J K (``checks.ijk``, 7.3):
        incremental from the start point (recommended), absolute, or sign-less for a
        quadrant-limited control -- then the signs that put the centre where the start and end
        radii agree and the arc stays in one quadrant."""
        (sx, sy), (ci, cj) = start, ij
        mode = self.checks.ijk
        if mode == "absolute":
            return ci, cj
        if mode == "incremental":
            return sx + ci, sy + cj
        best: tuple[float, float] | None = None
        best_key: tuple[bool, bool, float] | None = None
        for si in (1, -1):
            for sj in (1, -1):
                c = (sx + si * abs(ci), sy + sj * abs(cj))
                r1, r2 = math.dist(start, c), math.dist(end, c)
                miss = abs(r1 - r2)
                fits = miss <= self._arc_tolerance(r1, r2, scale)
                key = (not fits, not _in_one_quadrant(start, end, c, clockwise), miss)
                if best_key is None or key < best_key:
                    best, best_key = c, key
        assert best is not None
        return best

    def _limits(self, line: int, v: dict[str, Decimal], after: ModalState,
                column: Callable[[str], int], moved: list[str]) -> None:
        limits = self.profile.limits
        for axis in moved:
            bounds = limits.axes.get(axis)
            position = after.position.get(axis)
            if bounds and position is not None:
                self.travel(axis, position, line, column(axis))
        if limits.feed_max is not None and "F" in v and after.feed_mode != 93:
            self.feed_limit(v["F"], line, column("F"))
        if limits.spindle_max is not None and "S" in v and after.spindle_mode == 97 \
                and v["S"] > limits.spindle_max:
            self.report("TG603", f"spindle speed {v['S']} above the maximum "
                                 f"{limits.spindle_max}", line, column("S"))
        if "T" in v:
            tool = int(v["T"])
            if tool not in self.stats.tools:
                self.stats.tools.append(tool)
            if limits.tool_max is not None and tool > limits.tool_max:
                self.report("TG604", f"tool {tool} above the largest tool number "
                                     f"{limits.tool_max}", line, column("T"))

    # -- statistics and path -------------------------------------------------------------------

    def _dwell_time(self, v: dict[str, Decimal], state: ModalState) -> None:
        for a in "FPX":
            if a in v:
                seconds = float(v[a])
                if state.feed_mode == 95 and state.speed:
                    seconds = seconds * 60 / float(state.speed)
                self.stats.seconds += seconds
                return

    def _motion_stats(self, before: ModalState, after: ModalState, moved: list[str],
                      v: dict[str, Decimal], line: int) -> None:
        if not moved or after.motion is None:
            return
        stats = self.stats
        for axis in moved:
            p = after.position.get(axis)
            if p is None:
                continue
            if axis not in stats.low or p < stats.low[axis]:
                stats.low[axis] = p
            if axis not in stats.high or p > stats.high[axis]:
                stats.high[axis] = p
        start = _point(before.position)
        end = _point(after.position)
        length = math.dist(start, end)
        kind = "rapid" if after.motion == 0 else "feed"
        centre = None
        if after.motion in (2, 3) and "R" not in v:
            first, second, _ = PLANE_AXES[after.plane]
            ci = float(v.get(CENTRE_OF[first], 0))
            cj = float(v.get(CENTRE_OF[second], 0))
            c = dict(zip("XYZ", start, strict=True))
            e = dict(zip("XYZ", end, strict=True))
            scale = 1 / 25.4 if after.units == "inch" else 1.0
            c[first], c[second] = self._centre((c[first], c[second]), (e[first], e[second]),
                                               (ci, cj), after.motion == 2, scale)
            centre = (c["X"], c["Y"], c["Z"])
            length = _arc_length(start, end, centre, after.plane, after.motion == 2)
            kind = "arc"
        if kind == "rapid":
            stats.rapid_length += length
            stats.seconds += length / float(self.profile.limits.rapid_rate) * 60
        else:
            stats.feed_length += length
            feed = float(after.feed or 0)
            if after.feed_mode == 95:
                feed *= float(after.speed or 0)
            if after.feed_mode == 93 and feed:
                stats.seconds += 60 / feed
            elif feed > 0:
                stats.seconds += length / feed * 60
        if self.path is not None and start != end:
            self.path.append(Segment(kind, start, end, line, centre, after.motion == 2,
                                     after.plane))


def _in_one_quadrant(start: tuple[float, float], end: tuple[float, float],
                     centre: tuple[float, float], clockwise: bool) -> bool:
    """Whether the arc from ``start`` to ``end`` about ``centre``, in its direction, stays within
    one quadrant (crosses no axis through the centre): what a quadrant-limited control can do
    in one block."""
    eps = 1e-6
    a1 = math.degrees(math.atan2(start[1] - centre[1], start[0] - centre[0])) % 360
    a2 = math.degrees(math.atan2(end[1] - centre[1], end[0] - centre[0])) % 360
    sweep = ((a1 - a2) if clockwise else (a2 - a1)) % 360
    if sweep > 90 + eps:
        return False
    if clockwise:
        top = math.ceil((a1 - eps) / 90) * 90
        return a1 - sweep >= top - 90 - eps
    bottom = math.floor((a1 + eps) / 90) * 90
    return a1 + sweep <= bottom + 90 + eps


def _nested_comment(text: str) -> int:
    """1-based column of a '(' inside an open comment, or 0."""
    depth = 0
    for i, ch in enumerate(text):
        if ch == "(":
            if depth:
                return i + 1
            depth = 1
        elif ch == ")":
            depth = 0
    return 0


def _point(position: dict[str, Decimal]) -> tuple[float, float, float]:
    return (float(position.get("X", 0)), float(position.get("Y", 0)),
            float(position.get("Z", 0)))


def _arc_length(start: tuple[float, float, float], end: tuple[float, float, float],
                centre: tuple[float, float, float], plane: int, clockwise: bool) -> float:
    i, j = {17: (0, 1), 18: (2, 0), 19: (1, 2)}[plane]
    a0 = math.atan2(start[j] - centre[j], start[i] - centre[i])
    a1 = math.atan2(end[j] - centre[j], end[i] - centre[i])
    sweep = (a0 - a1) if clockwise else (a1 - a0)
    sweep %= 2 * math.pi
    if sweep == 0:
        sweep = 2 * math.pi
    r = math.hypot(start[i] - centre[i], start[j] - centre[j])
    k = 3 - i - j
    return math.hypot(r * sweep, end[k] - start[k])


def profile_named(name: str) -> Profile:
    """A profile by built-in name or file; ``neutral`` is the permissive reading."""
    return NEUTRAL if name == "neutral" else load_profile(name)


def check_text(text: str, profile: Profile, *, file: str = "<input>",
               select: Iterable[str] = (), ignore: Iterable[str] = ()) -> list[Finding]:
    checker = Checker(profile, file, select=select, ignore=ignore)
    return list(checker.run_stream([text], profile.dialect))


def iter_check_file(path: str, profile: Profile, *, display: str | None = None,
                    select: Iterable[str] = (), ignore: Iterable[str] = (),
                    record_path: bool = False) -> tuple[Checker, Iterator[Finding]]:
    """Check a text file or tape image, findings streamed as they are found (flat memory);
    tape parity findings come last, once the whole image has been decoded."""
    name = display or path
    checker = Checker(profile, name, select=select, ignore=ignore, record_path=record_path)
    source = Source(path)
    open(path, "rb").close()  # an unreadable file fails here, before any output

    return checker, chain(checker.run_stream(source.chunks(), profile.dialect),
                          _tape_findings(checker, source))


def _tape_findings(checker: Checker, source: Source) -> Iterator[Finding]:
    """The tape's findings, made once the whole image has been read."""
    yield from checker.tape(source.issues)


def check_file(path: str, profile: Profile, *, display: str | None = None,
               select: Iterable[str] = (), ignore: Iterable[str] = (),
               record_path: bool = False) -> tuple[Checker, list[Finding]]:
    """Check a file and keep the findings, tape errors first, then the rules in order."""
    checker, found = iter_check_file(path, profile, display=display, select=select,
                                     ignore=ignore, record_path=record_path)
    findings = list(found)
    tape = [f for f in findings if f.rule in ("TG701", "TG702")]
    return checker, tape + [f for f in findings if f.rule not in ("TG701", "TG702")]
