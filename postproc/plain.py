"""Runs of plain blocks checked as arrays: the checker's fast path.

Most of a CAM program is *plain*: a sequence number, at most the motion codes G00-G03, the
coordinates X Y Z, the centre words of the selected plane and F, with explicit numbers, and
perhaps a comment no rule has anything to say about (made blank before the words are read).
Checking such a block word by word in Python costs tens of microseconds; this module checks a
whole run of them at once, with the words read as arrays by :mod:`formats.bulk`.

Every rule that can fire on a plain block is evaluated for the whole run: word order (TG130),
decimals and digits against the Annex C format (TG203, TG205), the TV check (TG703), a feed in
force (TG401), the arc rules (TG403-TG406, TG408), travel and feed limits (TG601, TG602), and the
statistics. The modal state a block inherits -- motion, position, feed -- is carried through the
run by forward filling.

The block path (:meth:`postproc.check.Checker.block`) stays the reference:

* a block with anything the arrays do not decide -- a repeated word, a sign on an unsigned
  address, a number that looks implicit in an explicit program -- goes through it, and the run
  is cut around that block so that the state it sees is exact;
* the decisions that hang on a float (an arc's radii against its tolerance, a position against
  a travel limit) are made here only when they are clear by a wide margin; the close ones, and
  every finding's message, come from the same scalar code the block path runs.

So the findings are the block path's, in the same order (tests compare the two on random
programs). The statistics' float sums (path lengths, time) are added in another order and may
differ from the block path's in the last bits.
"""

from __future__ import annotations

import gc
import math
import operator
import re
from bisect import bisect_left
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from formats import bulk
from formats.parser import Dialect, parse_lines
from formats.wordformat import WordFormat, Zeros
from postproc.findings import (
    Finding,
    decimals_message,
    digits_tail,
    findings,
    no_centre_message,
    no_start_message,
    order_messages,
    order_ranks,
    radii_messages,
    tv_messages,
)
from postproc.rules import RULES
from postproc.state import CENTRE_OF, PLANE_AXES

if TYPE_CHECKING:
    from postproc.check import Checker

F64 = np.typing.NDArray[np.float64]
I64 = bulk.I64

# What a finding of the fast path is, in the order the block path reports within a block: the
# TV check, then word by word (order, decimals, digits), then the motion rules and the limits.
(TV, ORDER, DECIMALS, DIGITS, NO_FEED, NO_CENTRE, NO_START, RADII, ARC, HELIX, TRAVEL,
 FEED) = range(12)
_KEY = {TV: 0, NO_FEED: 1 << 20, NO_CENTRE: (1 << 20) + 1, NO_START: (1 << 20) + 1,
        RADII: (1 << 20) + 1, ARC: (1 << 20) + 1, HELIX: (1 << 20) + 2, FEED: (1 << 20) + 40}
_TRAVEL_KEY = (1 << 20) + 10  # + the axis's place in "XYZUVWABC"
_RULE = {TV: "TG703", ORDER: "TG130", DECIMALS: "TG203", DIGITS: "TG205", NO_FEED: "TG401",
         NO_CENTRE: "TG404", NO_START: "TG408", RADII: "TG403"}  # the others: Checker.report
_KIND_RULE = np.array([_RULE.get(kind, "") for kind in range(FEED + 1)], dtype=object)
_KIND_SEVERITY = np.array([RULES[r].severity if r else "" for r in _KIND_RULE], dtype=object)
_KIND_CLAUSE = np.array([RULES[r].clause if r else "" for r in _KIND_RULE], dtype=object)
_COMMON = _KIND_RULE != ""
_FLOAT_POW10 = np.array([float(10**i) for i in range(19)])
_MARGIN = 1e-9  # relative: float decisions closer than this go to the block path's scalar code


@dataclass
class _Plan:
    """What a plain block may hold in one plane, and the per-letter tables (indexed by the
    letter's byte)."""

    plane: int
    allowed: np.typing.NDArray[np.bool_]  # the bytes of a plain line
    motions: np.typing.NDArray[np.bool_]  # the G codes of a plain block (G00-G03), by number
    rank: F64
    signed: np.typing.NDArray[np.bool_]
    dimension: np.typing.NDArray[np.bool_]  # a decimal dimension word (the 6.1 style rule)
    before: I64
    after: I64
    formats: dict[str, WordFormat]
    letters: str  # the value letters of a plain block
    axes: str  # X Y Z among them
    first: str
    second: str
    third: str


@dataclass
class _Run:
    """One run's words, with the block each belongs to."""

    text: str
    bytes: bulk.U8  # the text, one byte per character
    line: int  # lines before the run
    words: bulk.Words
    block: I64  # block of each word (0-based in the run)
    column: I64  # 1-based column of each word
    value: F64  # each word's value as the float nearest its exact decimal
    line_start: I64
    line_end: I64  # offset of each block's LF
    first_word: I64  # index of each block's first word (the next block's when it has none)

    def token(self, i: int) -> str:
        return self.text[self.words.starts[i]:self.words.ends[i]]

    def tokens(self, which: I64) -> list[str]:
        """The words ``which``, as strings: their bytes (kept by :func:`bulk.read_words` a
        column at a time) laid out word after word with an LF after each, decoded and split
        once, all in C."""
        laid = np.vstack([self.words.columns[:, which],
                          np.full((1, len(which)), 10, dtype=np.uint8)]).T.ravel()
        return laid[laid != 0].tobytes().decode("ascii").split("\n")[:-1]


class PlainRuns:
    """The fast path of one :class:`~postproc.check.Checker`."""

    def __init__(self, checker: Checker) -> None:
        self.checker = checker
        profile = checker.profile
        self.possible = profile.explicit and checker.checks.ijk != "quadrant"
        self._plans: dict[int, _Plan] = {}

    def usable(self) -> bool:
        """Whether the fast path can check this program at all (the profile's decimal and
        arc-centre conventions, no path recorded for a plot)."""
        return self.possible and self.checker.path is None

    def ready(self) -> bool:
        """Whether the modal state leaves a plain block nothing the arrays do not follow."""
        c = self.checker
        s = c.machine.state
        return (not c._first and not c._ended_line
                and c._g06_open is None and (c._first_implicit is None or c._mixed_reported)
                and s.cycle is None and not s.incremental and s.feed_mode != 93
                and s.motion in (None, 0, 1, 2, 3))

    def _plan(self) -> _Plan:
        plane = self.checker.machine.state.plane
        plan = self._plans.get(plane)
        if plan is None:
            plan = self._plans[plane] = self._build(plane)
        return plan

    def _build(self, plane: int) -> _Plan:
        profile = self.checker.profile
        formats = profile.detailed.formats
        first, second, third = PLANE_AXES[plane]
        centre = sorted((CENTRE_OF[first], CENTRE_OF[second]))
        ranks = order_ranks(plane)
        rank = np.full(256, -1.0)
        signed = np.zeros(256, dtype=np.bool_)
        dimension = np.zeros(256, dtype=np.bool_)
        before = np.zeros(256, dtype=np.int64)
        after = np.zeros(256, dtype=np.int64)
        letters = ""
        for letter in "XYZ" + "".join(centre) + "F":
            if letter not in formats:
                continue
            b = ord(letter)
            fmt = profile.word_format(letter)
            letters += letter
            rank[b] = ranks[letter]
            signed[b] = fmt.signed
            dimension[b] = fmt.decimal and letter != "F"
            before[b] = fmt.before
            after[b] = fmt.after if fmt.decimal else 0
        allowed = np.zeros(256, dtype=np.bool_)
        allowed[bulk.as_bytes("0123456789+-. \t\r\n" + letters)] = True
        motions = np.zeros(100, dtype=np.bool_)
        for letter in "NG":
            fmt = profile.word_format(letter)
            if letter not in formats or fmt.decimal or fmt.zeros is Zeros.TRAILING:
                continue
            b = ord(letter)
            rank[b] = ranks[letter]
            before[b] = fmt.before
            allowed[b] = True
            if letter == "G":
                for g in range(4):
                    code = profile.code("G", g)
                    motions[g] = code is not None and code.status in ("assigned", "conditional")
        return _Plan(plane, allowed, motions, rank, signed, dimension, before, after, formats,
                     letters, "".join(a for a in "XYZ" if a in letters), first, second, third)

    # -- a run ---------------------------------------------------------------------------------

    def check(self, text: str, line: int, dialect: Dialect) -> None:
        """Check ``text`` (whole lines, each ending with LF; the first is line ``line + 1``):
        findings go where :meth:`Checker.report` puts them, in the block path's order.

        The plain lines are checked in segments between the blocks the block path takes: lines
        that are not plain, blocks the arrays do not decide, and every block while the modal
        state is one the arrays do not follow."""
        plan = self._plan()
        # one byte per character (columns are counted in characters); anything else is "?"
        a = np.frombuffer(text.encode("ascii", "replace"), dtype=np.uint8)
        ends = np.flatnonzero(a == 10)
        starts = np.concatenate([[0], ends[:-1] + 1]) if len(ends) else ends
        odd_lines = np.unique(np.searchsorted(ends, np.flatnonzero(~plan.allowed[a])))
        if len(odd_lines):  # comments made blank; lines with anything else odd made blank
            uncommented = _comments_blanked(text, a, starts[odd_lines], ends[odd_lines])
            odd_lines = np.unique(np.searchsorted(
                ends, np.flatnonzero(~plan.allowed[uncommented])))
            blanked = _blanked(uncommented, starts[odd_lines], ends[odd_lines])
        else:
            blanked = a
        words = bulk.read_words(blanked)
        if words is None:  # a number too long for the arrays
            self._by_blocks(text, line, dialect, starts, 0, None)
            return
        run = _read(text, a, line, words, starts, ends)
        slow = self._slow_blocks(run, plan)
        slow[odd_lines] = True
        slow |= self._malformed(run, plan, blanked)
        static = self._word_events(run, plan)
        stops = [*np.flatnonzero(slow).tolist(), len(ends)]
        b = 0
        while b < len(ends):
            if not slow[b] and self.ready():
                end = stops[bisect_left(stops, b)]
                self._segment(run, plan, static, b, end)
                b = end
                continue
            b = self._by_blocks(text, line, dialect, starts, b, slow)
            if self.checker.machine.state.plane != plan.plane:  # what is plain has changed
                if b < len(ends):
                    self.check(text[int(starts[b]):], line + b, dialect)
                return

    def _by_blocks(self, text: str, line: int, dialect: Dialect, starts: I64, b: int,
                   slow: np.typing.NDArray[np.bool_] | None) -> int:
        """Blocks from ``b`` (lines starting at ``starts``) by the block path, until the next
        one the arrays can take or the plane changes; returns that block."""
        c = self.checker
        plane = c.machine.state.plane
        end = len(starts)
        while b < end:
            # a window of lines: the blocks up to the next plain one, or 256 while the state
            # keeps the arrays out
            stop = min(b + 256, end)
            if slow is not None and self.ready():
                plain = np.flatnonzero(~slow[b:stop])
                stop = b + int(plain[0]) if len(plain) else stop
            last = int(starts[stop]) - 1 if stop < end else len(text) - 1
            for block in parse_lines(text[int(starts[b]):last], line + b, dialect, c.file,
                                     "collect"):
                c.block(block)
                b += 1
                if slow is not None and b < end and not slow[b] and self.ready() \
                        or c.machine.state.plane != plane:
                    return b
        return b

    def _slow_blocks(self, run: _Run, plan: _Plan) -> np.typing.NDArray[np.bool_]:
        """Blocks the block path must check: a repeated address (and so two G words), a sign
        the format does not have, a number that looks implicit (6.1)."""
        w = run.words
        letter = w.letter
        slow = np.zeros(len(run.line_end), dtype=np.bool_)
        key = np.sort(run.block * 256 + letter)
        repeated = key[1:][key[1:] == key[:-1]] // 256
        slow[repeated] = True
        odd = (w.neg | w.plus) & ~plan.signed[letter]
        if not self.checker._mixed_reported:
            significant = _digit_count(w.m)
            odd |= plan.dimension[letter] & ~w.dot & (significant > plan.after[letter])
        slow[run.block[odd]] = True
        return slow

    def _malformed(self, run: _Run, plan: _Plan, a: bulk.U8) -> np.typing.NDArray[np.bool_]:
        """Lines of plain characters that are not plain blocks: a word without digits, with
        two decimal signs, an N or G with a sign or decimal sign, a G other than G00-G03, or
        characters outside the words (``X1-2``). The block path reads them (and reports any
        error where it is)."""
        w = run.words
        letter = w.letter
        n_lines = len(run.line_end)
        code = (letter == ord("G")) | (letter == ord("N"))
        bad = (w.digits == 0) | (np.count_nonzero(w.columns == 46, axis=0) > 1)
        bad |= code & (w.dot | w.neg | w.plus)
        g = letter == ord("G")
        bad |= g & ((w.digits > 2) | ~plan.motions[np.minimum(w.m, 99)])
        malformed = np.zeros(n_lines, dtype=np.bool_)
        malformed[run.block[bad]] = True
        # every byte of a line is a word's or a blank's
        in_words = np.bincount(run.block, weights=w.ends - w.starts, minlength=n_lines)
        blank = np.flatnonzero((a == 32) | (a == 9) | (a == 13))
        blanks = np.bincount(np.searchsorted(run.line_end, blank), minlength=n_lines)
        malformed |= in_words + blanks[:n_lines] != run.line_end - run.line_start
        return malformed

    def _word_events(self, run: _Run, plan: _Plan) -> tuple[I64, I64, I64, I64]:
        """Findings of the words themselves and the TV check, for the whole run: (block, key,
        kind, word or block) arrays, ordered by block."""
        w = run.words
        letter = w.letter
        n = len(letter)
        blk = run.block
        place = np.arange(n) - run.first_word[blk]
        found: list[tuple[I64, I64, I64, I64]] = []
        # order (5.2): a rank below the highest before it in the block
        if n:
            key = blk * 100.0 + plan.rank[letter]
            high = np.maximum.accumulate(key)
            late = np.flatnonzero(key[1:] < high[:-1]) + 1
            found.append((blk[late], 1 + 3 * place[late], np.full(len(late), ORDER), late))
        # decimals beyond the format, digits before the decimal sign beyond it
        k = w.k
        fraction = k - np.minimum(_trailing_zeros(w.m, k), k)
        many = np.flatnonzero(w.dot & (fraction > plan.after[letter]))
        found.append((blk[many], 2 + 3 * place[many], np.full(len(many), DECIMALS), many))
        whole = _digit_count(w.m // bulk.POW10[k])
        big = np.flatnonzero(whole > plan.before[letter])
        found.append((blk[big], 3 + 3 * place[big], np.full(len(big), DIGITS), big))
        if self.checker.profile.serial.tv_check:
            crs = np.flatnonzero(run.bytes == 13)
            length = run.line_end - run.line_start - np.bincount(
                np.searchsorted(run.line_end, crs), minlength=len(run.line_end))
            odd = np.flatnonzero(length % 2 == 1)
            found.append((odd, np.zeros(len(odd), dtype=np.int64), np.full(len(odd), TV),
                          length[odd]))
        return _merge(found)

    # -- a segment: blocks the arrays check alone ----------------------------------------------

    def _segment(self, run: _Run, plan: _Plan, static: tuple[I64, I64, I64, I64],
                 b0: int, b1: int) -> None:
        c = self.checker
        state = c.machine.state
        n = b1 - b0
        w0 = int(run.first_word[b0])
        w1 = int(run.first_word[b1]) if b1 < len(run.first_word) else len(run.words.letter)
        c.stats.blocks += n
        c._last_line = run.line + b1
        if w1 == w0:  # no words (empty lines, comments): only the TV check
            lo, hi = np.searchsorted(static[0], [b0, b1])
            self._emit(run, plan, (static[0][lo:hi], static[1][lo:hi], static[2][lo:hi],
                                   static[3][lo:hi]), np.zeros(0, dtype=np.int64), {})
            return
        letter = run.words.letter[w0:w1]
        blk = run.block[w0:w1] - b0
        index = np.arange(n)

        def where(name: str) -> I64:
            """The word of ``name`` in each block (segment-local), -1 where there is none."""
            at = np.full(n, -1, dtype=np.int64)
            hits = np.flatnonzero(letter == ord(name))
            at[blk[hits]] = hits
            return at

        def filled(at: I64) -> I64:
            """The word of the latest block up to each block that has one, -1 before any."""
            last = np.maximum.accumulate(np.where(at >= 0, index, -1))
            return np.where(last >= 0, at[np.maximum(last, 0)], -1)

        value = run.value[w0:w1]
        gw = where("G")
        g_last = filled(gw)
        motion = np.where(g_last >= 0, run.words.m[w0:w1][g_last], -1 if state.motion is None
                          else state.motion)
        # positions after each block and before it (NaN: not known yet)
        at: dict[str, I64] = {}
        after: dict[str, F64] = {}
        before: dict[str, F64] = {}
        for axis in plan.axes + CENTRE_OF[plan.first] + CENTRE_OF[plan.second] + "F":
            at[axis] = where(axis) if axis in plan.letters else np.full(n, -1, dtype=np.int64)
        for axis in plan.axes:
            last = filled(at[axis])
            held = state.position.get(axis)
            initial = float(held) if held is not None else math.nan
            after[axis] = np.where(last >= 0, value[np.maximum(last, 0)], initial)
            before[axis] = np.concatenate([[initial], after[axis][:-1]])
        moved = np.zeros(n, dtype=np.bool_)
        for axis in plan.axes:
            moved |= at[axis] >= 0
        feed_last = filled(at["F"])
        feed_known = (feed_last >= 0) | (state.feed is not None)
        feed = np.where(feed_last >= 0, value[np.maximum(feed_last, 0)],
                        float(state.feed) if state.feed is not None else 0.0)
        first_moved = np.full(n, -1, dtype=np.int64)
        for axis in reversed(plan.axes):
            first_moved = np.where(at[axis] >= 0, at[axis], first_moved)
        found: list[tuple[I64, I64, I64, I64]] = []

        def add(kind: int, blocks: I64, ref: I64, key: int | None = None) -> None:
            """Findings of ``kind`` in ``blocks`` of the segment; ``ref`` a word of the run or,
            for the arc kinds, a block of the segment."""
            found.append((blocks + b0, np.full(len(blocks), _KEY[kind] if key is None else key),
                          np.full(len(blocks), kind), ref))

        feeding = ((motion == 1) | (motion == 2) | (motion == 3)) & moved
        lost = np.flatnonzero(feeding & ~feed_known)
        add(NO_FEED, lost, first_moved[lost] + w0)
        arcs = self._arcs(plan, motion, moved, at, before, after, value, w0, add)
        self._limits(run, plan, at, w0, add)
        lo, hi = np.searchsorted(static[0], [b0, b1])
        found.append((static[0][lo:hi], static[1][lo:hi], static[2][lo:hi], static[3][lo:hi]))
        self._emit(run, plan, _merge(found), motion, arcs)
        self._statistics(run, plan, motion, moved, at, before, after, feed, arcs, w0)
        # the state the segment leaves
        if (gw >= 0).any():
            state.motion = int(motion[-1])
        for axis in plan.axes + "F":
            hits = np.flatnonzero(at[axis] >= 0)
            if len(hits):
                number = c.profile.value(run.token(w0 + int(at[axis][hits[-1]])))
                if axis == "F":
                    state.feed = number
                else:
                    state.position[axis] = number
        if not c._mixed_reported and (run.words.dot[w0:w1] & plan.dimension[letter]).any():
            c._styles.add("explicit")
        c._first_words = False

    def _arcs(self, plan: _Plan, motion: I64, moved: np.typing.NDArray[np.bool_],
              at: dict[str, I64], before: dict[str, F64], after: dict[str, F64], value: F64,
              w0: int, add: Callable[..., None]) -> dict[str, F64]:
        """The arc rules; returns the geometry of the segment's blocks (for the statistics,
        the messages and the scalar recheck). The radii decide here only when they are clear
        of the tolerance and their messages clear of a rounding of the fourth decimal, so that
        numpy's ``hypot`` and Python's cannot disagree; the rest go to the scalar code."""
        c = self.checker
        first, second, third = plan.first, plan.second, plan.third
        ci_at, cj_at = at[CENTRE_OF[first]], at[CENTRE_OF[second]]
        centred = (ci_at >= 0) | (cj_at >= 0)
        arc = ((motion == 2) | (motion == 3)) & (moved | centred)
        zero = np.zeros(len(motion))
        sx = before.get(first, zero)
        sy = before.get(second, zero)
        ci = np.where(ci_at >= 0, value[np.maximum(ci_at, 0)], 0.0)
        cj = np.where(cj_at >= 0, value[np.maximum(cj_at, 0)], 0.0)
        geometry = {"ci": ci, "cj": cj}
        no_centre = np.flatnonzero(arc & ~centred)
        add(NO_CENTRE, no_centre, no_centre)
        known = ~np.isnan(sx) & ~np.isnan(sy)
        no_start = np.flatnonzero(arc & centred & ~known)
        add(NO_START, no_start, no_start)
        measured = arc & centred & known
        if not measured.any():
            return geometry
        ex, ey = after.get(first, zero), after.get(second, zero)
        absolute = c.checks.ijk == "absolute"
        cx = ci if absolute else sx + ci
        cy = cj if absolute else sy + cj
        with np.errstate(invalid="ignore"):
            r1 = np.hypot(sx - cx, sy - cy)
            r2 = np.hypot(ex - cx, ey - cy)
            scale = 1 / 25.4 if c.machine.state.units == "inch" else 1.0
            largest = np.maximum(r1, r2)
            tolerance = np.maximum(float(c.checks.arc_tolerance) * scale,
                                   float(c.checks.arc_tolerance_relative) * largest)
            miss = np.abs(r1 - r2)
            margin = _MARGIN * (largest + tolerance)
            clear = (r1 != 0) & (r2 != 0) & ((miss < tolerance - margin) | (
                (miss > tolerance + margin) & ~_near_rounding(r1, r2, miss, tolerance)))
        wide = np.flatnonzero(measured & clear & (miss > tolerance))
        add(RADII, wide, wide)
        recheck = np.flatnonzero(measured & ~clear)
        add(ARC, recheck, recheck)
        helix_at = at[third] if third in plan.letters else np.full(len(motion), -1)
        helix = np.flatnonzero(measured & clear & (helix_at >= 0))
        add(HELIX, helix, helix_at[helix] + w0)
        geometry.update(sx=sx, sy=sy, ex=ex, ey=ey, r1=r1, r2=r2, tolerance=tolerance,
                        helix=np.where(helix_at >= 0, helix_at + w0, -1).astype(np.float64))
        return geometry

    def _limits(self, run: _Run, plan: _Plan, at: dict[str, I64], w0: int,
                add: Callable[..., None]) -> None:
        """Travel and feed limits, decided in floats with a margin, near ones for the exact
        check of the emitter."""
        c = self.checker
        limits = c.profile.limits
        for place, axis in enumerate("XYZUVWABC"):
            bounds = limits.axes.get(axis)
            if axis not in plan.axes or not bounds:
                continue
            blocks = np.flatnonzero(at[axis] >= 0)
            words = at[axis][blocks]
            v = run.value[w0 + words]
            lo, hi = float(bounds[0]), float(bounds[1])
            margin = _MARGIN * (1 + max(abs(lo), abs(hi)))
            near = np.flatnonzero((v < lo + margin) | (v > hi - margin))
            add(TRAVEL, blocks[near], words[near] + w0, _TRAVEL_KEY + place)
        if limits.feed_max is not None and "F" in plan.letters:
            blocks = np.flatnonzero(at["F"] >= 0)
            words = at["F"][blocks]
            v = run.value[w0 + words]
            top = float(limits.feed_max)
            near = np.flatnonzero(v > top - _MARGIN * (1 + abs(top)))
            add(FEED, blocks[near], words[near] + w0)

    def _emit(self, run: _Run, plan: _Plan, events: tuple[I64, I64, I64, I64],
              motion: I64, arcs: dict[str, F64]) -> None:
        """The findings, with the block path's messages, in the events' order: the messages
        and columns of each common kind are made together and placed in object arrays, then
        all the tuples at once; the rare kinds come from the block path's scalar code."""
        blocks, _, kinds, refs = events
        if not len(blocks):
            return
        c = self.checker
        enabled = np.array([kind not in _RULE or c.enabled(_RULE[kind])
                            for kind in range(len(_KIND_RULE))])
        messages = np.empty(len(blocks), dtype=object)
        columns = np.zeros(len(blocks), dtype=np.int64)
        scalar: list[tuple[int, list[Finding]]] = []
        with _collector_paused():
            for kind in np.unique(kinds).tolist():
                if not enabled[kind]:
                    continue
                at = np.flatnonzero(kinds == kind)
                if kind in _RULE:
                    messages[at], columns[at] = self._common(run, plan, kind, refs[at],
                                                             blocks[at], arcs)
                    continue
                for i, ref in zip(at.tolist(), refs[at].tolist(), strict=True):
                    scalar.append((i, self._scalar(run, plan, kind, ref,
                                                   int(blocks[i]) + run.line + 1, motion, arcs,
                                                   int(blocks[i]))))
            common = np.flatnonzero(enabled[kinds] & _COMMON[kinds])
            k = kinds[common]
            made = findings(_KIND_RULE[k].tolist(), _KIND_SEVERITY[k].tolist(),
                            _KIND_CLAUSE[k].tolist(), c.file, messages[common].tolist(),
                            (blocks[common] + (run.line + 1)).tolist(),
                            columns[common].tolist())
        if scalar:  # put each scalar finding after the common ones of the events before it
            scalar.sort()
            cuts = np.searchsorted(common, [i for i, _ in scalar]).tolist()
            merged: list[Finding] = []
            last = 0
            for cut, (_, new) in zip(cuts, scalar, strict=True):
                merged.extend(made[last:cut])
                merged.extend(new)
                last = cut
            merged.extend(made[last:])
            made = merged
        c._found.extend(made)

    def _common(self, run: _Run, plan: _Plan, kind: int, ref: I64, blocks: I64,
                arcs: dict[str, F64]) -> tuple[list[str] | str, I64]:
        """The messages and columns of the findings of one common kind."""
        if kind == TV:
            return tv_messages(ref.tolist()), ref
        block_columns = run.column[run.first_word[blocks]]
        if kind == RADII:
            return radii_messages(arcs["r1"][ref].tolist(), arcs["r2"][ref].tolist(),
                                  arcs["tolerance"][ref].tolist()), block_columns
        if kind == NO_CENTRE:
            return no_centre_message(plan.plane), block_columns
        if kind == NO_START:
            return no_start_message(plan.plane), block_columns
        if kind == NO_FEED:
            return "feed motion with no feed rate in force", run.column[ref]
        tokens = run.tokens(ref)
        if kind == ORDER:
            return order_messages(tokens), run.column[ref]
        if kind == DIGITS:  # the tails by letter and count, the tokens added in C
            key = run.words.letter[ref].astype(np.int64) * 32 + _digit_count(
                run.words.m[ref] // bulk.POW10[run.words.k[ref]])
            tails = np.empty(256 * 32, dtype=object)
            for k in np.unique(key).tolist():
                tails[k] = digits_tail(k % 32, plan.formats[chr(k // 32)])
            return list(map(str.__add__, tokens, tails[key].tolist())), run.column[ref]
        return [decimals_message(t, plan.formats[t[0]]) for t in tokens], run.column[ref]

    def _scalar(self, run: _Run, plan: _Plan, kind: int, ref: int, line: int, motion: I64,
                arcs: dict[str, F64], block: int) -> list[Finding]:
        """Findings of one arc, travel or feed check, made by the block path's code."""
        c = self.checker
        saved, c._found = c._found, []
        try:
            column = run.column
            if kind == ARC:
                helix = int(arcs["helix"][ref])
                c.arc_geometry(line, int(column[run.first_word[block]]),
                               (float(arcs["sx"][ref]), float(arcs["sy"][ref])),
                               (float(arcs["ex"][ref]), float(arcs["ey"][ref])),
                               (float(arcs["ci"][ref]), float(arcs["cj"][ref])),
                               bool(motion[ref] == 2),
                               1 / 25.4 if c.machine.state.units == "inch" else 1.0,
                               plan.third, int(column[helix]) if helix >= 0 else 0)
            elif kind == HELIX:
                c.helical(plan.third, line, int(column[ref]))
            elif kind == TRAVEL:
                t = run.token(ref)
                c.travel(t[0], c.profile.value(t), line, int(column[ref]))
            elif kind == FEED:
                c.feed_limit(c.profile.value(run.token(ref)), line, int(column[ref]))
            return c._found
        finally:
            c._found = saved

    def _statistics(self, run: _Run, plan: _Plan, motion: I64,
                    moved: np.typing.NDArray[np.bool_], at: dict[str, I64],
                    before: dict[str, F64], after: dict[str, F64], feed: F64,
                    arcs: dict[str, F64], w0: int) -> None:
        c = self.checker
        stats = c.stats
        counted = moved & (motion >= 0)
        if not counted.any():
            return
        for axis in plan.axes:
            blocks = np.flatnonzero(counted & (at[axis] >= 0))
            if not len(blocks):
                continue
            words = w0 + at[axis][blocks]
            v = run.value[words]
            for i, table, better in ((int(np.argmin(v)), stats.low, operator.lt),
                                     (int(np.argmax(v)), stats.high, operator.gt)):
                number = c.profile.value(run.token(int(words[i])))
                if axis not in table or better(number, table[axis]):
                    table[axis] = number
        start: list[F64] = []
        end: list[F64] = []
        for a in "XYZ":
            if a in after:  # unknown positions count as 0, as in the block path
                start.append(np.nan_to_num(before[a]))
                end.append(np.nan_to_num(after[a]))
            else:
                held = c.machine.state.position.get(a)
                start.append(np.full(len(motion), float(held) if held is not None else 0.0))
                end.append(start[-1])
        length = np.sqrt(sum((e - s) ** 2 for s, e in zip(start, end, strict=True)))
        arc = counted & ((motion == 2) | (motion == 3))
        if arc.any():
            i, j = {17: (0, 1), 18: (2, 0), 19: (1, 2)}[c.machine.state.plane]
            k = 3 - i - j
            absolute = c.checks.ijk == "absolute"
            ci_, cj_ = arcs["ci"], arcs["cj"]
            cx = ci_ if absolute else start[i] + ci_
            cy = cj_ if absolute else start[j] + cj_
            a0 = np.arctan2(start[j] - cy, start[i] - cx)
            a1 = np.arctan2(end[j] - cy, end[i] - cx)
            sweep = np.mod(np.where(motion == 2, a0 - a1, a1 - a0), 2 * math.pi)
            sweep = np.where(sweep == 0, 2 * math.pi, sweep)
            r = np.hypot(start[i] - cx, start[j] - cy)
            length = np.where(arc, np.hypot(r * sweep, end[k] - start[k]), length)
        rapid = counted & (motion == 0)
        cutting = counted & (motion > 0)
        stats.rapid_length += float(length[rapid].sum())
        stats.seconds += float(length[rapid].sum()) / float(c.profile.limits.rapid_rate) * 60
        stats.feed_length += float(length[cutting].sum())
        rate = feed
        state = c.machine.state
        if state.feed_mode == 95:
            rate = feed * float(state.speed or 0)
        timed = cutting & (rate > 0)
        stats.seconds += float((length[timed] / rate[timed] * 60).sum())


@contextmanager
def _collector_paused() -> Iterator[None]:
    """The cyclic garbage collector off while findings are made by the hundred thousand: they
    are tuples of strings and numbers, which cannot form a cycle, and every 700 of them would
    otherwise start a collection that walks all the objects alive (a third of the time)."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


def _near_rounding(*values: F64) -> np.typing.NDArray[np.bool_]:
    """Where one of the values is so close to a rounding of its fourth decimal that an ulp
    could change how ``:.4f`` writes it."""
    near = np.zeros(len(values[0]), dtype=np.bool_)
    for v in values:
        scaled = v * 1e4
        near |= np.abs(scaled - np.floor(scaled) - 0.5) < 1e-6 + 1e-13 * np.abs(scaled)
    return near


# A comment with none of what the block path reports in one (':' or '%', a bracket inside, a
# control character); printable ASCII only, as the arrays are
_COMMENT = re.compile(r"\([\t !-$&-'*-9;-~]*\)")


def _comments_blanked(text: str, a: bulk.U8, starts: I64, ends: I64) -> bulk.U8:
    """``a`` with the plain comments of the lines from ``starts`` to ``ends`` made blank.

    The comment's characters still count for the TV check (which reads the line's length),
    and a comment inside a word leaves a word without digits or digits without a word, which
    :meth:`PlainRuns._malformed` hands to the block path."""
    spans = [m.span() for a0, b0 in zip(starts.tolist(), ends.tolist(), strict=True)
             for m in _COMMENT.finditer(text, a0, b0)]
    if not spans:
        return a
    at = np.array(spans, dtype=np.int64)
    return _blanked(a, at[:, 0], at[:, 1])


def _blanked(a: bulk.U8, starts: I64, ends: I64) -> bulk.U8:
    """``a`` with the lines from ``starts`` to ``ends`` (their LF kept) made blank."""
    if not len(starts):
        return a
    inside = np.zeros(len(a) + 1, dtype=np.int64)
    np.add.at(inside, starts, 1)
    np.add.at(inside, ends, -1)
    blank = np.cumsum(inside[:-1]) > 0
    out = a.copy()
    out[blank] = 32
    return out


def _read(text: str, a: bulk.U8, line: int, words: bulk.Words, starts: I64, ends: I64
          ) -> _Run:
    block = np.searchsorted(ends, words.starts)
    count = np.bincount(block, minlength=len(ends))
    first = np.zeros(len(ends) + 1, dtype=np.int64)
    np.cumsum(count, out=first[1:])
    magnitude = words.m / _FLOAT_POW10[words.k]  # correctly rounded, as float(Decimal) is
    value = np.where(words.neg, -magnitude, magnitude)
    return _Run(text, a, line, words, block, words.starts - starts[block] + 1, value, starts,
                ends, first)


def _digit_count(m: I64) -> I64:
    """Digits of each non-negative integer, 0 for 0 (``len(str(m).lstrip("0"))``)."""
    return np.searchsorted(bulk.POW10, m, side="right").astype(np.int64)


def _trailing_zeros(m: I64, most: I64) -> I64:
    """Trailing zero digits of each integer, at most ``most`` (all of them for 0)."""
    count = np.zeros(len(m), dtype=np.int64)
    rest = m.copy()
    for _ in range(bulk.MAX_DIGITS):
        more = (count < most) & (rest % 10 == 0)
        if not more.any():
            break
        count += more
        rest = np.where(more, rest // 10, rest)
    return count


def _merge(found: list[tuple[I64, I64, I64, I64]]) -> tuple[I64, I64, I64, I64]:
    """Findings as four arrays (block, key, kind, reference) ordered by block and key."""
    if not found:
        empty = np.zeros(0, dtype=np.int64)
        return empty, empty, empty, empty
    blocks, keys, kinds, refs = (np.concatenate([f[i] for f in found]).astype(np.int64)
                                 for i in range(4))
    order = np.lexsort((keys, blocks))
    return blocks[order], keys[order], kinds[order], refs[order]
