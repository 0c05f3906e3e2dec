"""Parameter expressions of ISO 6983-1 6.4.7, parsed with lark into an expression tree.

The standard shows ``R11 = 22.2`` (set), ``R29 = R9 + R15`` (add) and ``X2 = 105 + R9`` (an axis
value from an expression) and leaves the allowed operations to the control's manual. tapegate
reads the four arithmetic operations, unary signs, brackets ``[ ]`` (where a profile allows them,
as ``(`` is the comment character), functions written ``NAME[...]`` and parameters ``P``/``Q``/
``R`` with their index, or ``#n``. The macro dialects add, and this grammar reads as the core's
expression tree does: the power ``**``, inside brackets the word operators ``EQ ... MOD`` and ``,``
between arguments, ``#<name>`` parameters and parameters chosen by a value (``#[..]``, ``##n``),
and a numbered parameter with a decimal part (``#30003.078``, a Haas NGC parameter element: one
parameter, as the core's tree reads it; a dialect's reader lets it through only on a Haas).
HEIDENHAIN's Q-parameter formulas have a grammar of their own, :data:`FORMULA_GRAMMAR`, and so
have Siemens SINUMERIK expressions, :data:`SINUMERIK_GRAMMAR`.

Reading expressions in programs is the Rust core's (``crates/core/src/expr.rs``); this grammar is
the reference it is held to by property tests, and :func:`evaluate` computes an expression's
exact value where the parameters are known.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from decimal import Decimal
from functools import cache, lru_cache

from lark import Lark, Token, Tree, UnexpectedInput

from formats.errors import ParseError

EXPRESSION_GRAMMAR = r"""
?start: sum
?sum: product | sum ADDOP product -> binary
?inner: product | inner (ADDOP | WORDOP | COMMA) product -> binary
?product: unary | product (MULOP | POWOP) unary -> binary
?unary: atom | ADDOP unary -> negate
?atom: NUMBER -> number
     | PARAM -> parameter
     | NUMBERED -> parameter
     | NAMED -> parameter
     | indirect
     | "[" inner "]"
     | FUNCTION "[" inner "]" -> call
indirect: "#" "[" inner "]" | "#" (NUMBERED | NAMED) | "#" indirect
ADDOP: "+" | "-"
MULOP: "*" | "/"
POWOP: "**"
COMMA: ","
WORDOP: /(?i:EQ|NE|GT|GE|LT|LE|AND|OR|XOR|MOD)(?![A-Za-z])/
NUMBER: /[0-9]+\.?[0-9]*|\.[0-9]+/
PARAM: /[PQR][0-9]+/
NUMBERED: /#[0-9]+(\.[0-9]+)?/
NAMED: /#[ \t\r\x00\x7f]*<[^>]*>/
FUNCTION: /[A-Za-z]{2,6}(?![A-Za-z])/
%ignore /[ \t\r\x00\x7f]+/
"""

# HEIDENHAIN TNC Q-parameter formulas (``Q3 = ( Q1 + 2 ) * SIN 30``), as the TNC manuals'
# "Entering formulas directly" give them: ``( )`` group, ``^`` is a power and ``%`` the
# remainder, a function takes the operand after it without brackets (``SQ 10 - 3^3`` is 73),
# ``PI``, and Q, QL and QR parameters. The core's ``expr::formula_tree`` reads the same.
FORMULA_GRAMMAR = r"""
?start: sum
?sum: product | sum ADDOP product -> binary
?product: power | product (MULOP | MODOP) power -> binary
?power: unary | power POWOP unary -> binary
?unary: primary | ADDOP unary -> negate
?primary: NUMBER -> number
        | PARAM -> parameter
        | PI -> pi
        | "(" sum ")" -> group
        | FUNCTION unary -> call
ADDOP: "+" | "-"
MULOP: "*" | "/"
MODOP: "%"
POWOP: "^"
NUMBER: /[0-9]+\.?[0-9]*|\.[0-9]+/
PARAM: /Q[LR]?[0-9]+/
PI: /PI(?![A-Z])/
FUNCTION: /(?:SIN|COS|TAN|ASIN|ACOS|ATAN|SQRT|SQ|LN|LOG|EXP|NEG|INT|ABS|FRAC|SGN)(?![A-Z])/
%ignore /[ \t\r\x00\x7f]+/
"""

# Siemens SINUMERIK 840D sl expressions (``X=R1+5``, ``R1=R2*SIN(30)``, ``IF (R1==2) AND
# (R2<>3)``), as the programming manual's "Priority of the operations" orders them, from the
# lowest priority to the highest: comparisons, ``<<`` (strings), OR, XOR, AND, B_OR, B_XOR,
# B_AND, ``+ -``, ``* / DIV MOD``, and NOT, B_NOT before an operand. Operands: numbers
# (``10EX-5`` with an exponent), strings, hexadecimal and binary constants (``'H1F'``), R
# parameters, names of variables and system variables (``_X``, ``$AA_IM``), calls ``NAME(..)``
# and elements ``NAME[..]``; names and operators in any case. The core's
# ``expr::sinumerik_prefix`` reads the same.
SINUMERIK_GRAMMAR = r"""
?start: compare
?compare: concat | compare CMPOP concat -> binary
?concat: or_ | concat CONCAT or_ -> binary
?or_: xor | or_ OR xor -> binary
?xor: and_ | xor XOR and_ -> binary
?and_: bor | and_ AND bor -> binary
?bor: bxor | bor B_OR bxor -> binary
?bxor: band | bxor B_XOR band -> binary
?band: sum | band B_AND sum -> binary
?sum: product | sum ADDOP product -> binary
?product: unary | product (MULOP | DIV | MOD) unary -> binary
?unary: primary | (ADDOP | NOT | B_NOT) unary -> negate
?primary: NUMBER -> number
        | PARAM -> parameter
        | NAME -> name
        | STRING -> string
        | CONSTANT -> string
        | "(" compare ")"
        | NAME "(" (compare ("," compare)*)? ")" -> call
        | NAME "[" compare ("," compare)* "]" -> element
CMPOP: /==|<>|<=|>=|<|>/
CONCAT.3: "<<"
ADDOP: "+" | "-"
MULOP: "*" | "/"
OR.2: /(?i:OR)(?![A-Za-z0-9_$])/
XOR.2: /(?i:XOR)(?![A-Za-z0-9_$])/
AND.2: /(?i:AND)(?![A-Za-z0-9_$])/
B_OR.2: /(?i:B_OR)(?![A-Za-z0-9_$])/
B_XOR.2: /(?i:B_XOR)(?![A-Za-z0-9_$])/
B_AND.2: /(?i:B_AND)(?![A-Za-z0-9_$])/
DIV.2: /(?i:DIV)(?![A-Za-z0-9_$])/
MOD.2: /(?i:MOD)(?![A-Za-z0-9_$])/
NOT.2: /(?i:NOT)(?![A-Za-z0-9_$])/
B_NOT.2: /(?i:B_NOT)(?![A-Za-z0-9_$])/
NUMBER: /(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[Ee][Xx][+-]?[0-9]+)?/
PARAM.1: /[Rr][0-9]+(?![A-Za-z0-9_$])/
NAME: /[A-Za-z_$][A-Za-z0-9_$]*/
STRING: /"[\x20\x21\x23-\x7e]*"/
CONSTANT: /'(?:[Hh][0-9A-Fa-f]+|[Bb][01]+)'/
%ignore /[ \t\r\x00\x7f]+/
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


@cache
def _formula_parser() -> Lark:
    return Lark(FORMULA_GRAMMAR, parser="lalr", cache=True)


@cache
def _sinumerik_parser() -> Lark:
    # the basic lexer: a word operator is never a name, even where no operator may stand
    # (lark's contextual lexer would read " DIV " as a variable DIV)
    return Lark(SINUMERIK_GRAMMAR, parser="lalr", lexer="basic", cache=True)


def _tree(parser: Lark, source: str, what: str, clause: str) -> Tree[Token]:
    """``source`` parsed by ``parser``; :class:`ParseError` with the column inside it."""
    try:
        return parser.parse(source)
    except UnexpectedInput as exc:
        raise ParseError(f"malformed {what} {source!r} at character {exc.column}",
                         column=exc.column, clause=clause) from None


def parse_sinumerik(source: str) -> Tree[Token]:
    """The tree of a Sinumerik expression; :class:`ParseError` with the column."""
    return _tree(_sinumerik_parser(), source, "expression", "Sinumerik")


def sinumerik_form(source: str) -> str:
    """A Sinumerik expression's tree in the canonical form the core's ``expr::sinumerik_form``
    prints: each operation in parentheses, its operator first (``(+ R1 (* 2 3))``), names and
    numbers as written, calls and elements by their name in upper case (``SIN(30)``,
    ``$AA_IM[X]``), ``( )`` groups left out. Comparing the two holds the core to the
    operators' priorities, not only to what it accepts."""
    done: list[str] = []
    stack: list[tuple[Tree[Token] | Token, bool]] = [(parse_sinumerik(source), False)]
    while stack:  # post-order without recursion, as Evaluator.transform
        node, ready = stack.pop()
        if not isinstance(node, Tree):
            done.append(str(node))
        elif ready:
            n = len(node.children)
            parts = done[len(done) - n:]
            del done[len(done) - n:]
            done.append(_form(str(node.data), parts))
        else:
            stack.append((node, True))
            stack.extend((child, False) for child in reversed(node.children))
    return done[-1]


def _form(rule: str, parts: list[str]) -> str:
    match rule:
        case "binary":
            left, op, right = parts
            return f"({op.upper()} {left} {right})"
        case "negate":
            op, value = parts
            return f"({op.upper()} {value})"
        case "call":
            return f"{parts[0].upper()}({' '.join(parts[1:])})"
        case "element":
            return f"{parts[0].upper()}[{' '.join(parts[1:])}]"
        case _:  # number, parameter, name, string: the token as written
            return parts[0]


def parse_formula(source: str) -> Tree[Token]:
    """The tree of a HEIDENHAIN formula's right-hand side; :class:`ParseError` with the
    column."""
    return _tree(_formula_parser(), source, "formula", "HEIDENHAIN formulas")


# Trees are cached for the short expressions a program repeats (``R1+R2``), not for long ones: a
# tree takes about 250 bytes per character of its expression, and 4,096 cached trees of 900
# characters took 1 GB (the fuzzing's out-of-memory find). Cached: at most 1,024 trees of at most
# 64 characters, a few MB.
_CACHED_LENGTH = 64


def parse_expression(source: str) -> Tree[Token]:
    """The expression tree of ``source``; :class:`ParseError` with the column inside it."""
    return _cached_parse(source) if len(source) <= _CACHED_LENGTH else _parse(source)


def _parse(source: str) -> Tree[Token]:
    return _tree(_parser(), source, "expression", "6.4.7")


_cached_parse = lru_cache(maxsize=1024)(_parse)


_PARAMETER_TOKENS = frozenset({"PARAM", "NUMBERED", "NAMED"})


def parameters(source: str, *, formula: bool = False) -> list[str]:
    """The parameters an expression reads, e.g. ``['R9', 'R15']``; with ``formula``, a
    HEIDENHAIN formula's right-hand side."""
    tree = parse_formula(source) if formula else parse_expression(source)
    return [str(t) for t in tree.scan_values(
        lambda v: isinstance(v, Token) and v.type in _PARAMETER_TOKENS)]


class Evaluator:
    """Evaluate with known parameter values; functions go through float (geometry only).

    The tree is walked with a stack of its own, not by recursion: a chain of 20,000 terms
    (``1+1+...``) is a tree 20,000 deep, far beyond Python's recursion limit."""

    def __init__(self, values: dict[str, Decimal]):
        self.values = values

    def transform(self, tree: Tree[Token]) -> Decimal:
        """The value of ``tree``, its subtrees evaluated before it (post-order)."""
        done: list[object] = []  # the values of evaluated subtrees, and the tokens
        stack: list[tuple[Tree[Token] | Token, bool]] = [(tree, False)]
        while stack:
            node, ready = stack.pop()
            if not isinstance(node, Tree):
                done.append(node)
            elif ready:
                n = len(node.children)
                children = done[-n:] if n else []
                del done[len(done) - n:]
                done.append(getattr(self, str(node.data))(children))
            else:
                stack.append((node, True))
                stack.extend((child, False) for child in reversed(node.children))
        value = done[-1]
        assert isinstance(value, Decimal)
        return value

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
            case "**":
                return left ** right
            case "/":
                pass
            case other:  # a comparison, a logic or MOD operator, an argument list
                raise ParseError(f"tapegate does not evaluate {other!r} in an expression",
                                 clause="6.4.7")
        if right == 0:
            raise ParseError("division by zero in expression", clause="6.4.7")
        return left / right

    def indirect(self, c: list[object]) -> Decimal:
        raise ParseError("a parameter chosen by a value (#[...], ##n) is not evaluated",
                         clause="6.4.7")

    def call(self, c: list[object]) -> Decimal:
        name, value = str(c[0]), c[1]
        assert isinstance(value, Decimal)
        function = FUNCTIONS.get(name)
        if function is None:
            raise ParseError(f"unknown function {name}; tapegate evaluates "
                             f"{', '.join(FUNCTIONS)}", clause="6.4.7")
        try:
            result = function(float(value))
        except (ValueError, OverflowError):  # SQRT[-1], SIN of an infinite value
            result = math.nan
        if not math.isfinite(result):
            raise ParseError(f"{name}[{value:.6g}] has no value (outside the function's domain, "
                             "or too large)", clause="6.4.7")
        return Decimal(repr(result))


def evaluate(source: str, values: dict[str, Decimal]) -> Decimal:
    """The exact value of an expression, given the values of the parameters it reads; a
    :class:`ParseError` (clause 6.4.7) for one that has none: a parameter without a value, a
    division by zero, a function outside its domain or unknown, a value beyond any number."""
    try:
        return Evaluator(values).transform(parse_expression(source))
    except ArithmeticError as exc:  # decimal: Infinity - Infinity, an exponent out of range
        raise ParseError(f"expression {source!r} has no value: {type(exc).__name__}",
                         clause="6.4.7") from None
