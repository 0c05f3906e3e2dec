"""The lossless program model: blocks of words, exactly as written.

A :class:`Block` keeps its characters as written (``text``: everything between two end-of-block
LFs, including CR, spaces, tabs, comments, NUL/DEL leader) so that printing an unchanged program is
``text + LF`` per block -- byte for byte. Beside the text it holds the **word tokens** in written
order, each the word's characters without the non-printing ones (``"X-12.345"``,
``"X1=123.456"``, ``"R29=R9+R15"``, ``":1000"``). Tokens are plain strings; :class:`Word`
objects, columns and exact values are derived on demand (:meth:`Block.word_objects`,
:meth:`formats.profile.Profile.value`).

``Block`` and ``BlockInfo`` are native classes of the Rust core (``formats._core``), which makes
them by the million; a block with comments, a ``/`` skip, a ``%`` mark or no end of block carries
a :class:`BlockInfo`, the many plain blocks of CAM output carry none (``info is None``). A ``/``
at the head of the block is ``skip``; one in the middle (Fanuc, Haas: the switch on skips from it
to the end of the block) is ``skip_within``, its column and text, the words after it staying the
block's words.
"""

from __future__ import annotations

from formats._core import Block, BlockInfo, split_token
from formats.records import FrozenRecord, init_fields, record

__all__ = ["Block", "BlockInfo", "Word", "split_token"]


@record
class Word(FrozenRecord):
    """One word of a block, as written, with its 1-based column in the block's line."""

    __slots__ = ("address", "index", "sign", "number", "expression", "column", "token")
    address: str  # the address character as written ("X", "x", ":", "#")
    index: str  # the address index (6.2) as written, "" when none
    sign: str  # "", "+" or "-"
    number: str  # digits (and "." when explicit) as written; "" when the value is an expression
    expression: str  # the value's expression text (6.4.7), "" for a plain number
    column: int
    token: str

    def __init__(self, address: str, index: str, sign: str, number: str, expression: str,
                 column: int, token: str) -> None:
        init_fields(self, address, index, sign, number, expression, column, token)

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
