"""Whole runs of plain blocks read and rewritten at once, as numpy arrays of bytes.

Most of a CAM program is *plain*: upper-case words -- an address letter, an optional sign, at
most 15 digits with at most one ``.`` -- separated by blanks, one block per line, with no comment,
skip, ``%`` or ``:``. Converting such a block word by word in Python costs microseconds; reading
a whole run of them as arrays costs tens of nanoseconds per word. This module holds the two
halves of that fast path, and nothing about what the words mean:

* :func:`read_words` -- the words of a run: where each starts and ends, its letter, its sign and
  its exact value as integers ``m * 10**-k`` (no float anywhere);
* :func:`render` and :func:`rewrite` -- new text for chosen words, written into the run with
  everything around them (spacing, other words, ends of block) kept byte for byte.

The caller (:mod:`formats.convert`) decides which runs are plain with a regular expression,
what each word becomes and when to fall back to the block-by-block path, which stays the
reference: tests compare the two on random programs.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

MAX_DIGITS = 15  # digits of one number: m < 10**15 keeps every product below 2**63
POW10 = np.array([10**i for i in range(19)], dtype=np.int64)

I64 = NDArray[np.int64]
U8 = NDArray[np.uint8]
Flags = NDArray[np.bool_]


MAX_GAP = 64  # blanks and ends of block between two words, at most
WIDTH = 2 + MAX_DIGITS + 2  # letter, sign, digits, "." -- and one more to see a longer number


@dataclass
class Words:
    """The words of a run, one entry per word, in order."""

    starts: I64  # byte offset of the address letter
    ends: I64  # byte offset just after the word
    letter: U8
    neg: Flags  # written with "-"
    plus: Flags  # written with "+"
    m: I64  # the digits as an integer (the decimal sign left out)
    k: I64  # digits after the decimal sign
    digits: I64  # how many digits
    dot: Flags  # written with a decimal sign
    columns: U8  # (width, words): byte j of each word in row j, zero after the word


def as_bytes(text: str) -> U8:
    return np.frombuffer(text.encode("ascii"), dtype=np.uint8)


def read_words(a: U8) -> Words | None:
    """The words of ``a``, which holds only plain words, blanks and ends of block.

    The text is read a column at a time -- byte j of every word at once -- so the work is a few
    array operations per character of the longest word, not per byte of text. None when a
    number has more than :data:`MAX_DIGITS` digits (the caller falls back).
    """
    starts = np.flatnonzero((a >= 65) & (a <= 90))
    n = len(starts)
    padded = np.concatenate([a, np.zeros(WIDTH, dtype=np.uint8)])
    columns = np.zeros((WIDTH, n), dtype=np.uint8)
    columns[0] = padded[starts]
    sign = padded[starts + 1]
    neg = sign == 45
    plus = sign == 43
    alive = np.ones(n, dtype=np.bool_)
    length = np.ones(n, dtype=np.int64)
    m = np.zeros(n, dtype=np.int64)
    dot_at = np.zeros(n, dtype=np.int64)
    width = 1
    for j in range(1, WIDTH):
        c = sign if j == 1 else padded[starts + j]
        digit = (c - 48) < 10  # uint8 arithmetic: everything below "0" wraps above 10
        dot = c == 46
        alive &= digit | dot | (neg | plus if j == 1 else False)
        if not alive.any():
            break
        width = j + 1
        np.multiply(c, alive, out=columns[j])
        length += alive
        digit &= alive
        m = np.where(digit, m * 10 + (c - 48), m)
        dot_at[alive & dot] = j
    else:
        return None  # a word as long as WIDTH: too many digits
    has_dot = dot_at > 0
    ndig = length - 1 - neg - plus - has_dot
    if n and int(ndig.max()) > MAX_DIGITS:
        return None
    k = np.where(has_dot, length - 1 - dot_at, 0)
    return Words(starts, starts + length, columns[0], neg, plus, m, k, ndig, has_dot,
                 columns[:width])


# How a number is written (per word, from its letter's format).
EXPLICIT, LEADING, TRAILING, FULL = range(4)


def render(words: Words, which: I64, u: I64, mode: I64, width: I64, after: I64
           ) -> tuple[U8, Flags]:
    """New text for the words ``which`` of magnitude ``u * 10**-after``: (the bytes in rows
    as :attr:`Words.columns`, zeros between them; whether each is written as it was).

    ``mode`` per word: EXPLICIT (``12.5``, ``0.03``, ``10.``), or implicit with LEADING zeros
    omitted, TRAILING zeros omitted, or FULL width (``width`` digits). A zero is written ``0``
    in every mode, with no sign; ``+`` is written only where the source wrote it.
    """
    n = len(u)
    neg, plus = words.neg[which], words.plus[which]
    zero = u == 0
    ndig = np.searchsorted(POW10[1:], u, side="right").astype(np.int64) + 1
    explicit = mode == EXPLICIT
    tz = np.zeros(n, dtype=np.int64)
    if ((mode == TRAILING) | explicit).any():
        rest = u.copy()
        for _ in range(18):
            divisible = (rest % 10 == 0) & ~zero
            if not divisible.any():
                break
            tz += divisible
            rest = np.where(divisible, rest // 10, rest)
    hi = np.where(mode == LEADING, ndig, np.where(explicit, np.maximum(ndig, after + 1), width)) - 1
    lo = np.where(mode == TRAILING, tz, np.where(explicit, np.minimum(tz, after), 0))
    hi[zero] = 0
    lo[zero] = 0
    dot = explicit & ~zero
    signed = ~zero & (neg | plus)
    top = int(hi.max(initial=0))
    # rows: letter, sign, then for each place from the top its digit (and the "." after it)
    any_dot = bool(dot.any())
    step = 2 if any_dot else 1
    rows = np.zeros((2 + step * (top + 1), n), dtype=np.uint8)
    rows[0] = words.letter[which]
    rows[1] = np.where(signed, np.where(neg, 45, 43), 0)
    rest = u
    for p in range(top + 1):
        rest, digit = np.divmod(rest, 10)
        row = 2 + step * (top - p)
        rows[row] = np.where((lo <= p) & (p <= hi), digit + 48, 0)
        if any_dot:
            rows[row + 1] = np.where(dot & (after == p), 46, 0)
    same = ((signed == (neg | plus)) & (hi - lo + 1 == words.digits[which])
            & (u // POW10[lo] == words.m[which]) & (dot == words.dot[which])
            & (~dot | (after - lo == words.k[which])))
    return rows, same


def rewrite(a: U8, words: Words, which: I64, new: U8) -> bytes | None:
    """``a`` with the words ``which`` (indexes into ``words``) replaced by the rows of ``new``
    (from :func:`render`). None if blanks and ends of block between two words are more than
    :data:`MAX_GAP` bytes (the caller falls back)."""
    n = len(words.starts)
    if n == 0:
        return a.tobytes()
    starts, ends = words.starts, words.ends
    following = np.empty(n, dtype=np.int64)
    following[:-1] = starts[1:]
    following[-1] = len(a)
    gap = following - ends
    wide = int(gap.max())
    if wide > MAX_GAP:
        return None
    padded = np.concatenate([a, np.zeros(wide, dtype=np.uint8)])
    old = words.columns
    word = max(len(old), len(new))
    table = np.zeros((word + wide, n), dtype=np.uint8)
    kept = np.ones(n, dtype=np.bool_)
    kept[which] = False
    np.multiply(old, kept, out=table[:len(old)])
    table[:len(new), which] = new
    for j in range(wide):
        table[word + j] = np.where(j < gap, padded[ends + j], 0)
    flat = table.T.reshape(-1)
    return a[:starts[0]].tobytes() + flat[flat != 0].tobytes()
