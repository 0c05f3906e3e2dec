"""Which parameters of a program hold lengths: the proof a units conversion needs (6.4.7).

A units conversion must scale ``R11 = 22.2`` when R11 is later used as a length (``X2 = 105 +
R9``) and must not touch it when R11 is a feed, a count or an angle. The program does not say so,
so tapegate proves it from how each parameter is used, in one streaming pass before converting:

The expressions are read by the Rust core (``crates/core/src/expr.rs``: ``linear``), the same
reading the converter uses to convert their number terms.

* a length word (X Y Z U V W, I J K, a P/Q/R the profile calls a length) whose value is an
  expression **linear** in its parameters (sums and differences of numbers, parameters, and
  parameters multiplied or divided by numbers) makes each parameter it reads a *length*; its
  number terms are lengths too and are converted;
* any other word that reads a parameter makes it *not a length*;
* an assignment ``R29 = R9 + R15`` passes the class of R29 on to R9 and R15 (again only through a
  linear expression);
* a parameter used both ways, a length read through a non-linear expression (``SIN[R1]``,
  ``R1 * R2``), or an assignment to a parameter that is never read, cannot be proved: the
  conversion stops with an error naming the block, unless the user allows unconverted parameters.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from typing import TypeVar

from formats import _core
from formats.errors import ConversionError

LENGTH = "length"
OTHER = "other"

T = TypeVar("T")


def _read(reader: Callable[[str], T], expression: str, line: int) -> T:
    """The core's reading of an expression; one it cannot read (a ``ValueError`` from the core:
    the tokenizer let through a value its expression reader refuses, e.g. ``Y##136``) is a
    :class:`ConversionError` on its line, not a traceback."""
    try:
        return reader(expression)
    except ValueError as exc:
        raise ConversionError(f"cannot read the expression {expression!r} for the units "
                              f"conversion: {exc}", line=line, clause="6.4.7",
                              code="conversion-unprovable") from None



@dataclass
class ParameterClasses:
    """The outcome of the analysis: which parameters are lengths, and what could not be proved."""

    classes: dict[str, str] = field(default_factory=dict)  # parameter -> LENGTH | OTHER
    problems: dict[str, str] = field(default_factory=dict)  # parameter -> why it is unprovable

    def is_length(self, name: str) -> bool:
        return self.classes.get(name) == LENGTH


class ParameterAnalysis:
    """Collects parameter uses block by block; :meth:`result` solves the classes."""

    def __init__(self) -> None:
        self.uses: dict[str, dict[str, int]] = {}  # parameter -> {kind: first line}
        self.assignments: dict[str, list[tuple[list[str], bool, int]]] = {}
        self.nonlinear: dict[str, int] = {}

    def read(self, params: Iterable[str], kind: str, line: int) -> None:
        for name in params:
            self.uses.setdefault(name, {}).setdefault(kind, line)

    def word(self, expression: str, is_length: bool, line: int) -> None:
        """A word whose value is ``expression``; ``is_length`` says the word is a length.

        An expression the core cannot read (``Z=_Z_HOME``, a Sinumerik named variable) shows
        no parameter's class: it is passed over here, and the converter, meeting the word,
        refuses it at its column as an expression it cannot convert (``--allow-unconverted``
        leaves it as written), as it refuses the ``_Z_HOME=610.`` that sets it."""
        try:
            self._word(expression, is_length, line)
        except ConversionError:
            return

    def _word(self, expression: str, is_length: bool, line: int) -> None:
        if not is_length:
            self.read(_read(_core.expression_parameters, expression, line), OTHER, line)
            return
        params = _read(_core.linear_parameters, expression, line)
        if params is None:
            for name in _read(_core.expression_parameters, expression, line):
                self.nonlinear.setdefault(name, line)
            return
        self.read(params, LENGTH, line)

    def assignment(self, target: str, expression: str, line: int) -> None:
        """``target = expression``; one the core cannot read passes the target's class on to
        nothing (the converter refuses the assignment where the target is a length)."""
        try:
            params = _read(_core.linear_parameters, expression, line)
        except ConversionError:
            self.assignments.setdefault(target, []).append(([], False, line))
            return
        linear = params is not None
        names = (params if params is not None
                 else _read(_core.expression_parameters, expression, line))
        self.assignments.setdefault(target, []).append((names, linear, line))

    def result(self) -> ParameterClasses:
        classes: dict[str, str] = {}
        problems: dict[str, str] = {}
        for name, kinds in self.uses.items():
            if len(kinds) > 1:
                problems[name] = (f"{name} is read as a length (line {kinds[LENGTH]}) and as "
                                  f"something else (line {kinds[OTHER]})")
            else:
                classes[name] = next(iter(kinds))
        for name, line in self.nonlinear.items():
            problems.setdefault(name, f"{name} is read in a non-linear expression on line "
                                      f"{line}, so its units cannot be converted")
        # An assignment passes its target's class on to what it reads, until nothing changes.
        changed = True
        while changed:
            changed = False
            for target, entries in self.assignments.items():
                kind = classes.get(target)
                if kind is None:
                    continue
                for names, linear, line in entries:
                    for name in names:
                        wanted = kind if linear or kind == OTHER else None
                        if wanted is None:
                            problems.setdefault(name, f"{name} feeds the length {target} "
                                                      f"through a non-linear expression on line "
                                                      f"{line}")
                            continue
                        have = classes.get(name)
                        if have is None:
                            classes[name] = wanted
                            changed = True
                        elif have != wanted:
                            problems.setdefault(name, f"{name} is used both as a length and as "
                                                      f"something else (line {line})")
        for target, entries in self.assignments.items():
            if target not in classes and target not in problems:
                problems[target] = (f"{target} is assigned on line {entries[0][2]} but never "
                                    "read in this program, so nothing shows whether it is a "
                                    "length")
        # A length read here and set nowhere in the program holds what a caller (a macro's
        # argument) or the control put there, in units this conversion does not change.
        for name, kinds in self.uses.items():
            if kinds.get(LENGTH) is not None and name not in self.assignments:
                problems.setdefault(name, f"{name} is read as a length (line {kinds[LENGTH]}) "
                                          "but not set in this program: its value comes from "
                                          "a caller or the control, in units this conversion "
                                          "does not change")
        for name in problems:
            classes.pop(name, None)
        return ParameterClasses(classes, problems)
