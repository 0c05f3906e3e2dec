"""Parameter expressions of ISO 6983-1 6.4.7, parsed with lark into an expression tree.

The standard shows ``R11 = 22.2`` (set), ``R29 = R9 + R15`` (add) and ``X2 = 105 + R9`` (an axis
value from an expression) and leaves the allowed operations to the control's manual. tapegate
reads the four arithmetic operations, unary signs, brackets ``[ ]`` (where a profile allows them,
as ``(`` is the comment character), functions written ``NAME[...]`` and parameters ``P``/``Q``/
``R`` with their index, or ``#n``.

Reading expressions in programs is the Rust core's (``crates/core/src/expr.rs``); this grammar is
the reference it is held to by property tests, and :func:`evaluate` computes an expression's
exact value where the parameters are known.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from decimal import Decimal
from functools import cache, lru_cache

from lark import Lark, Token, Transformer, Tree, UnexpectedInput
from lark.exceptions import VisitError

from formats.errors import ParseError

EXPRESSION_GRAMMAR = r"""
?start: sum
?sum: product | sum ADDOP product -> binary
?product: unary | product MULOP unary -> binary
?unary: atom | ADDOP unary -> negate
?atom: NUMBER -> number
     | PARAM -> parameter
     | "[" sum "]"
     | FUNCTION "[" sum "]" -> call
ADDOP: "+" | "-"
MULOP: "*" | "/"
NUMBER: /[0-9]+\.?[0-9]*|\.[0-9]+/
PARAM: /[PQR][0-9]+|#[0-9]+/
FUNCTION: /[A-Z]{2,6}/
%ignore /[ \t]+/
"""

FUNCTIONS: dict[str, Callable[[float], float]] = {
    "SIN": lambda x: math.sin(math.radians(x)),
    "COS": lambda x: math.cos(math.radians(x)),
    "TAN": lambda x: math.tan(math.radians(x)),
    "ATAN": lambda x: math.degrees(math.atan(x)),
    "SQRT": math.sqrt,
    "ABS": math.fabs,
}

@cache
def _parser() -> Lark:
    return Lark(EXPRESSION_GRAMMAR, parser="lalr", cache=True)


@lru_cache(maxsize=4096)
def parse_expression(source: str) -> Tree[Token]:
    """The expression tree of ``source``; :class:`ParseError` with the column inside it."""
    try:
        return _parser().parse(source)
    except UnexpectedInput as exc:
        raise ParseError(f"malformed expression {source!r} at character {exc.column}",
                         column=exc.column, clause="6.4.7") from None


def parameters(source: str) -> list[str]:
    """The parameters an expression reads, e.g. ``['R9', 'R15']``."""
    return [str(t) for t in parse_expression(source).scan_values(
        lambda v: isinstance(v, Token) and v.type == "PARAM")]


class Evaluator(Transformer[Token, Decimal]):
    """Evaluate with known parameter values; functions go through float (geometry only)."""

    def __init__(self, values: dict[str, Decimal]):
        super().__init__()
        self.values = values

    def number(self, c: list[Token]) -> Decimal:
        return Decimal(str(c[0]))

    def parameter(self, c: list[Token]) -> Decimal:
        name = str(c[0])
        if name not in self.values:
            raise ParseError(f"parameter {name} has no value here", clause="6.4.7")
        return self.values[name]

    def negate(self, c: list[object]) -> Decimal:
        value = c[1]
        assert isinstance(value, Decimal)
        return -value if str(c[0]) == "-" else value

    def binary(self, c: list[object]) -> Decimal:
        left, op, right = c
        assert isinstance(left, Decimal) and isinstance(right, Decimal)
        match str(op):
            case "+":
                return left + right
            case "-":
                return left - right
            case "*":
                return left * right
        if right == 0:
            raise ParseError("division by zero in expression", clause="6.4.7")
        return left / right

    def call(self, c: list[object]) -> Decimal:
        value = c[1]
        assert isinstance(value, Decimal)
        return Decimal(repr(FUNCTIONS[str(c[0])](float(value))))


def evaluate(source: str, values: dict[str, Decimal]) -> Decimal:
    """The exact value of an expression, given the values of the parameters it reads."""
    try:
        return Evaluator(values).transform(parse_expression(source))
    except VisitError as exc:  # lark wraps what the evaluator raises
        if isinstance(exc.orig_exc, ParseError):
            raise exc.orig_exc from None
        raise
