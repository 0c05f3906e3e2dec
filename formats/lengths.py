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

A file of several programs (a Fanuc or Haas memory backup, split as the converter splits it:
``formats._core.ProgramStarts``) is read program by program for its **local** variables: on a
Custom Macro B control #1-#33 are the program's own (cleared at its end; a G65/G66 macro call
gives the macro a level of its own), so ``#1`` of one main program and ``#1`` of the next are
two parameters here, each proved from its own program's uses. A subprogram, though, runs at
its caller's level and reads and sets the caller's locals, and any program may call one: by
M98, or by an M or T code the machine maps to it (parameters 6071-6079, 6001#5), which the text
does not show. So only in a file with no subprogram (no program that returns by M99) has each
program locals of its own; in a file with one, every program's locals are read as one, as for
a file of one program. Every other parameter (the common #100-#199
and #500-#999, system variables) is one parameter of the whole file: a program can set one that
a later one reads.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from functools import cache
from typing import TypeVar

from formats import _core
from formats.errors import ConversionError

LENGTH = "length"
OTHER = "other"

T = TypeVar("T")


@cache
def is_local(name: str) -> bool:
    """A Custom Macro B local variable (#1-#33): a parameter of one program of the file."""
    return name[:1] == "#" and name[1:].isdigit() and 1 <= int(name[1:]) <= 33


@cache
def shown(key: str) -> str:
    """A parameter's key as a message names it: ``#1``, or a program's own local variable
    ``#1 of the program beginning on line 40`` (``of the file's first program``)."""
    name, _, start = key.partition("@")
    if not start:
        return name
    return (f"{name} of the program beginning on line {start}" if start != "0"
            else f"{name} of the file's first program")


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

    # Keyed by parameter, a program's own local variable by ``name@line`` (its program's
    # first line, 0 for the file's first): see :func:`shown`.
    classes: dict[str, str] = field(default_factory=dict)  # parameter -> LENGTH | OTHER
    problems: dict[str, str] = field(default_factory=dict)  # parameter -> why it is unprovable
    starts: list[int] = field(default_factory=lambda: [0])  # where each program begins
    own: set[int] = field(default_factory=set)  # the programs with local variables of their own

    def is_length(self, name: str) -> bool:
        return self.classes.get(name) == LENGTH

    def programs(self) -> list[tuple[int, list[str], list[tuple[str, str]]]]:
        """For the core's converter, program by program in the file's order: the line it begins
        on (0 for the first), its parameters proved lengths, and ``(parameter, why not)``; a
        parameter of the whole file is in every program's lists, a local one in its own."""
        def mine(key: str, start: int) -> bool:
            name, _, program = key.partition("@")
            if program:
                return int(program) == start
            return start not in self.own or not is_local(name)

        return [(start,
                 sorted(k.partition("@")[0] for k, kind in self.classes.items()
                        if kind == LENGTH and mine(k, start)),
                 sorted((k.partition("@")[0], why) for k, why in self.problems.items()
                        if mine(k, start)))
                for start in self.starts]


class ParameterAnalysis:
    """Collects parameter uses block by block; :meth:`result` solves the classes."""

    def __init__(self) -> None:
        self.uses: dict[str, dict[str, int]] = {}  # parameter -> {kind: first line}
        self.assignments: dict[str, list[tuple[list[str], bool, int]]] = {}
        self.nonlinear: dict[str, int] = {}
        self.starts = [0]  # the line each program of the file begins on
        self.returned = False  # a program of the file returns (M99): a subprogram
        self.keyed = False  # a local variable was keyed by its program

    def next_program(self, line: int) -> None:
        """The file's next program begins on ``line``: its local variables are its own."""
        self.starts.append(line)

    def returns(self) -> None:
        """The program being read returns (M99): a subprogram, which any program of the file
        may call and whose local variables are then its caller's."""
        self.returned = True

    def _key(self, name: str) -> str:
        """The key of a parameter read or set in the program being read (see :func:`shown`)."""
        if self.returned or not is_local(name):  # after an M99 no program has its own
            return name
        self.keyed = True
        return f"{name}@{self.starts[-1]}"

    def _own(self) -> set[int]:
        """The programs with local variables of their own: every program of a file of several
        that holds no subprogram; none where it holds one, or is one program (its locals are
        then just its parameters)."""
        if len(self.starts) == 1 or self.returned:
            return set()
        return set(self.starts)

    def _merged(self, own: set[int]) -> None:
        """The local variables of the programs that share them, keyed by their names alone."""
        if own or not self.keyed:
            return  # every key stands

        def key(k: str) -> str:
            name, _, start = k.partition("@")
            return k if not start or int(start) in own else name

        uses: dict[str, dict[str, int]] = {}
        for k, kinds in self.uses.items():
            merged = uses.setdefault(key(k), {})
            for kind, line in kinds.items():
                merged[kind] = min(line, merged.get(kind, line))
        assignments: dict[str, list[tuple[list[str], bool, int]]] = {}
        for k, entries in self.assignments.items():
            assignments.setdefault(key(k), []).extend(
                ([key(n) for n in names], linear, line) for names, linear, line in entries)
        nonlinear: dict[str, int] = {}
        for k, line in self.nonlinear.items():
            nonlinear[key(k)] = min(line, nonlinear.get(key(k), line))
        self.uses, self.assignments, self.nonlinear = uses, assignments, nonlinear

    def read(self, params: Iterable[str], kind: str, line: int) -> None:
        for name in params:
            self.uses.setdefault(self._key(name), {}).setdefault(kind, line)

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
                self.nonlinear.setdefault(self._key(name), line)
            return
        self.read(params, LENGTH, line)

    def assignment(self, target: str, expression: str, line: int) -> None:
        """``target = expression``; one the core cannot read passes the target's class on to
        nothing (the converter refuses the assignment where the target is a length)."""
        target = self._key(target)
        try:
            params = _read(_core.linear_parameters, expression, line)
        except ConversionError:
            self.assignments.setdefault(target, []).append(([], False, line))
            return
        linear = params is not None
        names = (params if params is not None
                 else _read(_core.expression_parameters, expression, line))
        self.assignments.setdefault(target, []).append(
            ([self._key(name) for name in names], linear, line))

    def result(self) -> ParameterClasses:
        own = self._own()
        self._merged(own)
        classes: dict[str, str] = {}
        problems: dict[str, str] = {}
        for name, kinds in self.uses.items():
            if len(kinds) > 1:
                problems[name] = (f"{shown(name)} is read as a length (line {kinds[LENGTH]}) "
                                  f"and as something else (line {kinds[OTHER]})")
            else:
                classes[name] = next(iter(kinds))
        for name, line in self.nonlinear.items():
            problems.setdefault(name, f"{shown(name)} is read in a non-linear expression on "
                                      f"line {line}, so its units cannot be converted")
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
                            problems.setdefault(name, f"{shown(name)} feeds the length "
                                                      f"{shown(target)} through a non-linear "
                                                      f"expression on line {line}")
                            continue
                        have = classes.get(name)
                        if have is None:
                            classes[name] = wanted
                            changed = True
                        elif have != wanted:
                            problems.setdefault(name, f"{shown(name)} is used both as a length "
                                                      f"and as something else (line {line})")
        for target, entries in self.assignments.items():
            if target not in classes and target not in problems:
                problems[target] = (f"{shown(target)} is assigned on line {entries[0][2]} but "
                                    "never read in this program, so nothing shows whether it "
                                    "is a length")
        # A length read here and set nowhere in the program holds what a caller (a macro's
        # argument) or the control put there, in units this conversion does not change.
        for name, kinds in self.uses.items():
            if kinds.get(LENGTH) is not None and name not in self.assignments:
                problems.setdefault(name, f"{shown(name)} is read as a length (line "
                                          f"{kinds[LENGTH]}) but not set in this program: its "
                                          "value comes from a caller or the control, in units "
                                          "this conversion does not change")
        for name in problems:
            classes.pop(name, None)
        return ParameterClasses(classes, problems, list(self.starts), own)
