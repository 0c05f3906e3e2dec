"""Fuzz target: parameter expressions of 6.4.7 -- the lark reference grammar
(``formats.expr``: parse, parameters, exact evaluation) and the reading a units conversion
makes of them (the core's parameter analysis, ``crates/core/src/lengths.rs``, for what the
core's tokenizer accepts as the value of ``X1=``).

Byte 0 seeds the parameters' values (P/Q/R1-9 and #1-9 get small values, 0 included, or stay
unknown); the rest is the expression. What must hold: a tree whose parameters are names the
grammar reads, an exact value or a :class:`ParseError` that names clause 6.4.7 (a syntax error
its column too); the tokenizer accepts ``X1=`` and the text or says where it stops, and the
parameter analysis of what it accepts, as a length word's value, another word's and an
assignment's, gives the programs' classes (an expression the core's expression reader refuses
where its tokenizer accepted it is passed over: docs/robustness.md) or, where the other words
are read otherwise than ``X1=``, a located :class:`ParseError`.
"""

from __future__ import annotations

import re
from decimal import Decimal

from fuzz import _harness
from fuzz._harness import allowed, check

with _harness.instrumented():
    from formats import _core
    from formats.errors import ParseError
    from formats.expr import evaluate, parameters, parse_expression
    from formats.machine import machine
    from formats.model import split_token
    from formats.parser import PERMISSIVE, tokenize_block
    from formats.profile import load_profile

    FANUC = machine(load_profile("fanuc-mill"))

NAMES = [f"{letter}{n}" for letter in ("P", "Q", "R", "#") for n in range(1, 10)]


def one_input(data: bytes) -> None:
    if not data:
        return
    seed, text = data[0], data[1:].decode("utf-8", "replace")
    values = {} if seed & 128 else {
        name: Decimal(((seed * (i + 3)) % 19) - 9) / (1 + seed % 4) for i, name in enumerate(NAMES)}
    try:  # the analysis reads what the tokenizer accepted as the value of a word
        words, _ = tokenize_block(f"X1={text}", PERMISSIVE)
    except ParseError as exc:
        allowed(exc, ParseError, column=True, code=True)
    else:
        if len(words) == 1 and split_token(words[0])[4]:
            analysis = _core.ParameterAnalysis(FANUC)
            try:
                analysis.read_lines(f"X1={text}\nF1={text}\n#100={text}\nG0 X#100", 0,
                                    PERMISSIVE.flags, "f.nc")
            except ParseError as exc:  # F1= or #100= read otherwise than X1=
                allowed(exc, ParseError, line=True, column=True, code=True, file="f.nc")
            else:
                check(len(analysis.result().programs()) >= 1, "no program in the analysis")
    try:
        parse_expression(text)
    except ParseError as exc:
        allowed(exc, ParseError, column=True, clause=True)
        return
    names = parameters(text)
    check(all(re.fullmatch(r"[PQR][0-9]+|#[0-9]+|#[ \t\r\x00\x7f]*<[^>]*>", n) for n in names),
          f"parameters {names}")
    try:
        value = evaluate(text, values)
    except ParseError as exc:
        allowed(exc, ParseError, clause=True)
        return
    check(isinstance(value, Decimal), f"{text!r} evaluates to {value!r}")


def seeds() -> list[bytes]:
    return [bytes([i % 256]) + e for i, e in enumerate(_harness.expressions())]


if __name__ == "__main__":
    _harness.main(one_input, seeds)
