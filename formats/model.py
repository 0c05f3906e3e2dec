"""The lossless program model: blocks of words, exactly as written.

A :class:`Block` keeps its characters as written (``text``: everything between two end-of-block
LFs, including CR, spaces, tabs, comments, NUL/DEL leader) so that printing an unchanged program is
``text + LF`` per block -- byte for byte. Beside the text it holds the **word tokens** in written
order, each the word's characters without the non-printing ones (``"X-12.345"``,
``"X1=123.456"``, ``"R29=R9+R15"``, ``":1000"``). Tokens are plain strings so the parser's hot
path allocates nothing per word; :class:`Word` objects, columns and exact values are derived on
demand (:meth:`Block.word_objects`, :meth:`formats.profile.Profile.value`).

Blocks found by the careful tokenizer (comments, ``/`` skip, ``%`` marks, expressions) carry a
:class:`BlockInfo`; the many plain blocks of CAM output carry none.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

# A word token: address, optional "index=", then a plain number, or else an expression.
_TOKEN = re.compile(r"([A-Za-z:#])(?:([0-9]+)=)?([+-]?)([0-9]*\.?[0-9]*)")


@dataclass(frozen=True, slots=True)
class Word:
    """One word of a block, as written, with its 1-based column in the block's line."""

    address: str  # the address character as written ("X", "x", ":", "#")
    index: str  # the address index (6.2) as written, "" when none
    sign: str  # "", "+" or "-"
    number: str  # digits (and "." when explicit) as written; "" when the value is an expression
    expression: str  # the value's expression text (6.4.7), "" for a plain number
    column: int
    token: str

    @property
    def letter(self) -> str:
        return self.address.upper()

    @property
    def explicit(self) -> bool:
        return "." in self.number

    @property
    def key(self) -> str:
        """Address and index, the unit that must not repeat in a block: ``X``, ``X1``."""
        return self.letter + self.index


def split_token(token: str) -> tuple[str, str, str, str, str]:
    """(address, index, sign, number, expression) of a word token."""
    m = _TOKEN.match(token)
    assert m is not None, token
    address, index, sign, number = m.groups()
    if m.end() == len(token) and number:
        return address, index or "", sign, number, ""
    rest = token[len(address) + (len(index) + 1 if index else 0):]
    return address, index or "", "", "", rest


class BlockInfo:
    """What the careful tokenizer found beside the words of a block."""

    __slots__ = ("skip", "comments", "percent", "ident", "eob")

    def __init__(self) -> None:
        self.skip = ""  # "/" or "/1".."/9": optional block skip (clause 4)
        self.comments: list[tuple[int, str]] = []  # (column, text with its brackets)
        self.percent = False  # a "%" program start / rewind stop line
        self.ident = ""  # the text after "%" (program identification, clause 4)
        self.eob = True  # False for a last line that has no end of block


class Block:
    """One block: its text as written, its line, its word tokens, and what else it holds."""

    __slots__ = ("text", "line", "words", "info")

    def __init__(self, text: str, line: int, words: list[str], info: BlockInfo | None = None):
        self.text = text
        self.line = line
        self.words = words
        self.info = info

    def __repr__(self) -> str:
        return f"Block(line={self.line}, text={self.text!r})"

    # -- convenience views (not on the hot path) -------------------------------------------

    @property
    def skip(self) -> str:
        return self.info.skip if self.info else ""

    @property
    def comments(self) -> list[tuple[int, str]]:
        return self.info.comments if self.info else []

    @property
    def percent(self) -> bool:
        return bool(self.info and self.info.percent)

    @property
    def has_eob(self) -> bool:
        return self.info.eob if self.info else True

    def word_objects(self) -> list[Word]:
        """The words with their columns (found by scanning the text once)."""
        result = []
        pos = 0
        text = self.text
        for token in self.words:
            column = _find_token(text, token, pos)
            address, index, sign, number, expression = split_token(token)
            result.append(Word(address, index, sign, number, expression, column + 1, token))
            pos = column + 1
        return result



def _find_token(text: str, token: str, start: int) -> int:
    """Offset of ``token`` in ``text`` from ``start``, allowing non-printing characters inside."""
    at = text.find(token, start)
    if at >= 0 and not _inside_comment(text, at):
        return at
    # The token was written with spaces inside (``R11 = 22.2``) or sits after a comment that
    # contains the same characters: find its address character outside comments.
    i = start
    depth = False
    while i < len(text):
        ch = text[i]
        if depth:
            depth = ch != ")"
        elif ch == "(":
            depth = True
        elif ch == ";":
            break
        elif ch == token[0]:
            return i
        i += 1
    return max(at, 0)


def _inside_comment(text: str, at: int) -> bool:
    open_at = text.rfind("(", 0, at)
    return open_at >= 0 and text.rfind(")", open_at, at) < 0
