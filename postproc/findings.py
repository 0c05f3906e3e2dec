"""What the checker reports: :class:`Finding`, and the messages that both the block path
(:mod:`postproc.check`) and the fast path (:mod:`postproc.plain`) write, so they cannot drift."""

from __future__ import annotations

from functools import cache, partial
from itertools import repeat
from operator import sub
from typing import NamedTuple

from formats.wordformat import WordFormat
from postproc.rules import Severity
from postproc.state import CENTRE_OF, PLANE_AXES


class Finding(NamedTuple):
    """One rule broken at one place (a tuple: millions of them are cheap to make)."""

    rule: str
    severity: Severity
    message: str
    file: str
    line: int
    column: int
    clause: str

    def __str__(self) -> str:
        return (f"{self.file}:{self.line}:{self.column}: {self.severity} {self.rule} "
                f"{self.message} [{self.clause}]")


def findings(rules: list[str], severities: list[Severity], clauses: list[str], file: str,
             messages: list[str], lines: list[int], columns: list[int]) -> list[Finding]:
    """Many findings at once, from their fields as lists (the tuples are made in C, not by
    calls to ``Finding``: the fast path makes millions)."""
    return list(map(_make, zip(rules, severities, messages, repeat(file), lines, columns,
                               clauses)))


_make = partial(tuple.__new__, Finding)
make_finding = _make  # a Finding from its 7 fields in one tuple: the core makes millions


# The messages of the rules the fast path reports in bulk: one list function per rule, which
# the block path calls with one item.

def tv_messages(lengths: list[int]) -> list[str]:
    texts = {n: f"{n} characters in the block (the control's TV check wants an even number; "
                "the sender pads with a space)" for n in set(lengths)}
    return [texts[n] for n in lengths]


DIMENSIONS = "XYZUVWPQRABC"
_ORDER = {"N": 0.0, "O": 0.0, ":": 0.0, "G": 1.0, **{a: 2.0 + i for i, a in enumerate(DIMENSIONS)},
          "F": 20.0, "E": 20.0, "S": 21.0, "T": 22.0, "D": 22.0, "H": 22.0, "M": 23.0}


@cache
def order_ranks(plane: int) -> dict[str, float]:
    """Each address's place in the word order of clause 5.2 (TG130), in ``plane``: I J K stand
    right after the axis group they belong to (after Y in G17, after Z in G18 and G19)."""
    centre = {17: 3.5, 18: 4.5, 19: 4.5}.get(plane, 3.5)
    return {**_ORDER, "I": centre + 0.1, "J": centre + 0.2, "K": centre + 0.3}


def order_messages(tokens: list[str]) -> list[str]:
    return list(map(str.__add__, tokens, repeat(" is out of the order of clause 5.2")))


def decimals_message(token: str, fmt: WordFormat) -> str:
    decimals = len(token.partition(".")[2].rstrip("0"))
    return (f"{token}: {decimals} decimals; the format {fmt.spec()} holds "
            f"{fmt.after if fmt.decimal else 0}")


def digits_tail(digits: int, fmt: WordFormat) -> str:
    """What follows the token in TG205's message: ``digits`` before the decimal sign, more
    than ``fmt`` holds (the fast path makes each tail once and adds the tokens in C)."""
    return f": {digits} digits before the decimal sign; the format {fmt.spec()} holds {fmt.before}"


def radii_messages(r1: list[float], r2: list[float], tolerance: list[float]) -> list[str]:
    """TG403's messages (``%`` formatting in C: the stress benchmark has 150,000 of them)."""
    text = "start radius %.4f and end radius %.4f differ by %.4f (tolerance %.4f)"
    return list(map(text.__mod__, zip(r1, r2, map(abs, map(sub, r1, r2)), tolerance,
                                      strict=True)))


def no_centre_message(plane: int) -> str:
    first, second, _ = PLANE_AXES[plane]
    return f"arc without {' '.join(sorted((CENTRE_OF[first], CENTRE_OF[second])))} (or R)"


def no_start_message(plane: int) -> str:
    first, second, _ = PLANE_AXES[plane]
    return f"arc start point unknown: no earlier position on {first} and {second}"
