"""The reference block grammar: a lark (Earley) grammar of one ISO 6983-1 block.

It is too slow for real programs (about 20,000 blocks/s) and exists to say what the fast
tokenizer of :mod:`formats.parser` must do: the property tests generate programs and require
both to agree on every block (the words, the skip level, the comments, the ``%`` marks) and on
which blocks are errors. The grammar is built for a :class:`~formats.parser.Dialect`, because
what a block may contain depends on the characters the profile allows.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

from lark import Lark, Token, Tree, UnexpectedInput

from formats.parser import STRICT, Dialect

_BASE = r"""
start: percent_line | block
percent_line: "%" IDENT?
block: SKIP? element* SEMI_COMMENT?
?element: word | COMMENT | align
align: ALIGN
word: ADDRESS plain
    | ADDRESS INDEX "=" (plain | expr)
    {hash_word}
    {bracket_word}
plain: SIGN? NUMBER
?expr: sum
?sum: product | sum ADDOP product
?product: unary | product MULOP unary
?unary: atom | ADDOP unary
?atom: NUMBER | PARAM | {brackets}
SIGN: "+" | "-"
ADDOP: "+" | "-"
MULOP: {mulop}
NUMBER: /[0-9]+\.?[0-9]*|\.[0-9]+/
ALIGN: /:[0-9]+/
INDEX: /[0-9]+/
PARAM: /[PQR][0-9]+/ {hash_param}
FUNCTION: /[A-Z]{{2,6}}/
ADDRESS: /{address}/
SKIP: /\/[1-9]?/
COMMENT: /\([^)\n\x00-\x08\x0b-\x0c\x0e-\x1f\x7f]*\)/
SEMI_COMMENT: {semi}
IDENT: /[^\n\x00-\x08\x0b-\x0c\x0e-\x1f\x7f]+/
%ignore /[ \t\r\x00\x7f]+/
"""


@lru_cache(maxsize=8)
def _parser(dialect: Dialect) -> Lark:
    grammar = _BASE.format(
        address="[A-Za-z]" if dialect.lowercase else "[A-Z]",
        hash_word='| "#" INDEX "=" (plain | expr)' if dialect.hash_parameters else "",
        # X#1, X[#1+2], and signed (X-#1, X-[#1]): the operand's sign is part of it, as
        # Fanuc and LinuxCNC read it
        bracket_word='| ADDRESS operand' if dialect.brackets else "",
        brackets='"[" sum "]" -> bracket | FUNCTION "[" sum "]" -> call' if dialect.brackets
        else '"\\x01" "\\x01"',
        mulop='"*" | "/"' if "*" in dialect.extra else '"/"',
        hash_param='| /#[0-9]+/' if dialect.hash_parameters else "",
        semi=r'/;[^\n\x00-\x08\x0b-\x0c\x0e-\x1f\x7f]*/' if dialect.semicolon_comments
        else r'/\x01\x01/',
    )
    if dialect.brackets:
        grammar += ('\nbracket: "[" sum "]"\nHASHPARAM: /#[0-9]+/\n'
                    'operand: SIGN? (bracket | HASHPARAM)\n')
    return Lark(grammar, parser="earley", lexer="dynamic", propagate_positions=True,
                ambiguity="resolve")


@dataclass(frozen=True)
class Reading:
    """What the reference grammar reads in a block, in the terms of formats.model.Block."""

    words: tuple[str, ...]
    skip: str
    comments: tuple[tuple[int, str], ...]
    percent: bool
    ident: str


class ReferenceError(ValueError):
    pass


def read_block(text: str, dialect: Dialect = STRICT) -> Reading:
    """Read one block's text (no LF) with the reference grammar; ReferenceError if invalid."""
    try:
        tree = _parser(dialect).parse(text)
    except UnexpectedInput as exc:
        raise ReferenceError(f"column {exc.column}: {exc.__class__.__name__}") from None
    root = tree.children[0]
    assert isinstance(root, Tree)
    if root.data == "percent_line":
        ident = str(root.children[0]) if root.children else ""
        return Reading((), "", (), True, ident.strip(" \t\r"))
    words: list[str] = []
    comments: list[tuple[int, str]] = []
    skip = ""
    for child in root.children:
        if isinstance(child, Token):
            if child.type == "SKIP":
                skip = str(child)
            elif child.type in ("COMMENT", "SEMI_COMMENT"):
                comments.append((child.column or 0, str(child).rstrip("\r")))
            continue
        if child.data == "align":
            words.append(str(child.children[0]))
        else:
            words.append(_word_token(child, text))
    return Reading(tuple(words), skip, tuple(comments), False, "")


def _word_token(word: Tree[Token], text: str) -> str:
    first = word.children[0]
    if isinstance(first, Token) and first.type == "INDEX":  # "#" INDEX "=" value
        address, index, value = "#", str(first), word.children[1]
    elif len(word.children) == 3:
        address, index, value = str(first), str(word.children[1]), word.children[2]
        if index and int(index) == 0:
            raise ReferenceError("address index 0")
    else:
        address, index, value = str(first), "", word.children[1]
    prefix = f"{address}{index}=" if index else address
    if isinstance(value, Tree) and value.data == "plain":
        return prefix + "".join(str(t) for t in value.children)
    if isinstance(value, Token) and value.type in ("NUMBER",):
        return prefix + str(value)
    # An expression: its source text without the non-printing characters.
    meta_start = value.meta.start_pos if isinstance(value, Tree) else value.start_pos
    meta_end = value.meta.end_pos if isinstance(value, Tree) else value.end_pos
    assert meta_start is not None and meta_end is not None
    return prefix + "".join(text[meta_start:meta_end].split()).replace("\x00", "").replace(
        "\x7f", "")
