"""ISO 6983-1 Annex B (general) and Annex C (detailed) format classifications.

Both are small languages, validated and printed back in canonical form. The lark grammars below
are the reference. Every profile load reads its classification strings, and importing lark and
building a parser was a third of a short command's start-up, so a small hand parser
(:func:`_hand_detailed`, :func:`_hand_general`) reads the strings in the shapes they are written
in, with the same result; whatever it does not take (a bad string, or an unusual spacing) goes to
the lark parser, which reads it or says where it is wrong. ``tests/test_classification.py`` holds
the two equal under hypothesis. The hand parser reads character by character, without ``re``,
which a check does not import; the tests hold it to the regular expressions it was written
with.

* Annex B: ``PM 322`` -- letters for the kind of control and the units, then three digits;
* Annex C: ``%:/DS N03 G02 X+053 Y+053 Z+053 F031 S04 T04 M02*`` -- the program-start, alignment,
  block-skip and explicit-decimal flags, then one word format per address in the proper sequence,
  ``*`` for end of block, and optional facility notes such as
  ``(with dwell facility, the F word becomes F022)``.
"""

from __future__ import annotations

from formats.errors import FormatSpecError
from formats.records import NEW, FrozenRecord, field, init_fields, new, record
from formats.wordformat import WordFormat, Zeros

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:  # lark is imported only when a string needs it (see the module docstring)
    from typing import Any

    from lark import Lark, UnexpectedInput

# ----------------------------------------------------------------------------------------------
# Annex B

_GENERAL_GRAMMAR = r"""
start: KIND UNITS DIGIT DIGIT DIGIT
KIND: "P" | "L" | "D" | "C"
UNITS: "M" | "I" | "N"
DIGIT: /[0-9]/
%ignore /[ \t]+/
"""

KINDS = {
    "P": "positioning only",
    "L": "positioning and line motion",
    "D": "positioning, line motion and contouring",
    "C": "contouring only",
}
UNITS = {"M": "metric", "I": "inch", "N": "metric and inch"}

# the grammars' parsers, made once, when first used (kept here, not by functools.cache: a
# check's start-up does not import functools, docs/benchmarks.md, "functools")
_PARSERS: dict[str, Lark] = {}


def _general_parser() -> Lark:
    # built on first use and its analysis cached on disk by lark: `tapegate --help` does not pay
    parser = _PARSERS.get("general")
    if parser is None:
        from lark import Lark

        parser = _PARSERS["general"] = Lark(_GENERAL_GRAMMAR, parser="lalr", cache=True)
    return parser


# Annex B as the hand parser takes it: the grammar's tokens, spaces and tabs between any two.
# The hand parsers read character by character, without regular expressions: `re` (7.6M
# instructions to import) and the compiling of their patterns (11 of them, 0.85 ms) were a
# tenth of what a check runs before its threads start (docs/benchmarks.md, "a check without
# re").
_GENERAL_TOKENS = ("PLDC", "MIN", "0123456789", "0123456789", "0123456789")


def _hand_general(text: str) -> tuple[str, str, str, str, str] | None:
    """The five tokens of an Annex B string, or None for the lark parser to read."""
    tokens: list[str] = []
    at, end = 0, len(text)
    for allowed in _GENERAL_TOKENS:
        while tokens and at < end and text[at] in " \t":
            at += 1
        if at == end or text[at] not in allowed:
            return None
        tokens.append(text[at])
        at += 1
    return tuple(tokens) if at == end else None  # type: ignore[return-value]


@record
class GeneralClassification(FrozenRecord):
    """Annex B: what kind of control this is, in four characters and three digits."""

    kind: str  # P L D C
    units: str  # M I N
    motions: int  # digit 1: motions controlled
    numerical: int  # digit 2: motions controlled by dimension words
    simultaneous: int  # digit 3: motions controlled at the same time

    def __init__(self, kind: str, units: str, motions: int, numerical: int,
                 simultaneous: int) -> None:
        init_fields(self, kind, units, motions, numerical, simultaneous)

    @classmethod
    def parse(cls, text: str) -> GeneralClassification:
        tokens = _hand_general(text.strip()) or _lark_general(text)
        kind, units, d1, d2, d3 = tokens
        result = cls(kind, units, int(d1), int(d2), int(d3))
        result.validate()
        return result

    def validate(self) -> None:
        if self.numerical > self.motions:
            raise FormatSpecError(
                f"general classification {self}: {self.numerical} motions by dimension words "
                f"cannot exceed {self.motions} motions controlled (digit 2 <= digit 1)",
                clause="Annex B",
            )
        if self.simultaneous > self.numerical:
            raise FormatSpecError(
                f"general classification {self}: {self.simultaneous} simultaneous motions cannot "
                f"exceed {self.numerical} motions by dimension words (digit 3 <= digit 2)",
                clause="Annex B",
            )

    def __str__(self) -> str:
        return f"{self.kind}{self.units} {self.motions}{self.numerical}{self.simultaneous}"

    def explain(self) -> list[tuple[str, str, str]]:
        return [
            ("1st letter", self.kind, KINDS[self.kind]),
            ("2nd letter", self.units, UNITS[self.units]),
            ("1st digit", str(self.motions), "motions controlled"),
            ("2nd digit", str(self.numerical), "motions controlled by dimension words"),
            ("3rd digit", str(self.simultaneous), "motions controlled simultaneously"),
        ]


def _lark_general(text: str) -> tuple[str, str, str, str, str]:
    """The reference: the five tokens of an Annex B string as the grammar reads them."""
    from lark import UnexpectedInput

    try:
        tree = _general_parser().parse(text.strip())
    except UnexpectedInput as exc:
        raise FormatSpecError(
            f"general classification {text!r}: unexpected character at column {exc.column}; "
            "expected e.g. 'PM 322' (P/L/D/C, M/I/N, three digits)",
            clause="Annex B",
        ) from None
    kind, units, d1, d2, d3 = (str(t) for t in tree.children)
    return kind, units, d1, d2, d3


# ----------------------------------------------------------------------------------------------
# Annex C

_DETAILED_GRAMMAR = r"""
start: flags spec+ EOB note*
flags: PERCENT? COLON? SLASH? DS?
spec: ADDRESS PLUS? DIGITS
note: "(" "with" facility_name "facility" "," "the" ADDRESS "word" "becomes" spec ")"
facility_name: NAME+
PERCENT: "%"
COLON: ":"
SLASH: "/"
DS: "DS"
PLUS: "+"
EOB: "*"
ADDRESS: /[A-Z]/
DIGITS: /[0-9]{1,3}/
NAME: /[a-z][a-z-]*/
%ignore /[ \t\n]+/
"""

def _detailed_parser() -> Lark:
    parser = _PARSERS.get("detailed")
    if parser is None:
        from lark import Lark

        parser = _PARSERS["detailed"] = Lark(_DETAILED_GRAMMAR, parser="lalr", cache=True)
    return parser


# Annex C as the hand parser takes it: the grammar's tokens with spaces, tabs or newlines (the
# grammar's %ignore) between them, and in a facility note at least one between two words.
_W = " \t\n"
# lark's lexer reads a note's words by where they stand: among the facility's name, "with",
# "the", "word" and "becomes" are names, and "facility" is the word that ends the name
_NOTE_WORDS = frozenset({"facility"})
_FLAG_NAMES = ("PERCENT", "COLON", "SLASH", "DS")
_NAME_START = "abcdefghijklmnopqrstuvwxyz"
_NAME = _NAME_START + "-"


def _space(text: str, at: int) -> int:
    """Past the spaces, tabs and newlines at ``at``."""
    end = len(text)
    while at < end and text[at] in _W:
        at += 1
    return at


def _spaced(text: str, at: int, word: str) -> int:
    """Past ``word`` at ``at`` and at least one space after it, or -1."""
    if not text.startswith(word, at):
        return -1
    after = _space(text, at + len(word))
    return after if after > at + len(word) else -1


def _format_spec(text: str, at: int, lookahead: bool) -> tuple[str, str, str, int] | None:
    """An address's format at ``at`` (spaces first): (letter, "+" or "", its 1-3 digits, where
    it ends); with ``lookahead``, not followed by a fourth digit."""
    end = len(text)
    at = _space(text, at)
    if at == end or not "A" <= text[at] <= "Z":
        return None
    letter = text[at]
    at = _space(text, at + 1)
    plus = ""
    if at < end and text[at] == "+":
        plus = "+"
        at = _space(text, at + 1)
    digits = at
    while at < end and "0" <= text[at] <= "9" and at - digits < 3:
        at += 1
    if at == digits or lookahead and at < end and "0" <= text[at] <= "9":
        return None
    return letter, plus, text[digits:at], at


def _note_rest(text: str, at: int) -> tuple[str, tuple[str, str, str], int] | None:
    """After a note's "facility": ``, the A word becomes A+034)`` (the address, its format,
    where the note ends), or None."""
    at = _space(text, at)
    if not text.startswith(",", at):
        return None
    at = _spaced(text, _space(text, at + 1), "the")
    if at < 0 or at == len(text) or not "A" <= text[at] <= "Z":
        return None
    address = text[at]
    at = _spaced(text, at + 1, "")  # (at least one space)
    at = -1 if at < 0 else _spaced(text, at, "word")
    at = -1 if at < 0 else _spaced(text, at, "becomes")
    spec = None if at < 0 else _format_spec(text, at, False)
    if spec is None:
        return None
    a, plus, digits, at = spec
    at = _space(text, at)
    if not text.startswith(")", at):
        return None
    return address, (a, plus, digits), at + 1


def _note(text: str, at: int) -> tuple[list[str], str, tuple[str, str, str], int] | None:
    """A facility note at ``at`` (spaces first): (the facility's words, the address, its
    format, where the note ends), or None. Its words are the fewest before a "facility" that
    the rest of the note follows, each a lower-case name followed by spaces."""
    at = _space(text, at)
    if not text.startswith("(", at):
        return None
    at = _spaced(text, _space(text, at + 1), "with")
    words: list[str] = []
    while at >= 0:
        if words and text.startswith("facility", at):
            rest = _note_rest(text, at + len("facility"))
            if rest is not None:
                return words, *rest
        if at == len(text) or text[at] not in _NAME_START:
            return None
        start = at
        while at < len(text) and text[at] in _NAME:
            at += 1
        words.append(text[start:at])
        at = _spaced(text, at, "")
    return None


def _hand_detailed(text: str) -> DetailedClassification | None:
    """An Annex C string read by hand, or None for the lark parser to read (not an error:
    the string may only be spaced unusually). Raises what the grammar's builder raises for a
    string that reads but means nothing (a format without digits, an address named twice)."""
    names = set()
    pos = 0
    for name, flag in zip(_FLAG_NAMES, ("%", ":", "/", "DS"), strict=True):
        pos = _space(text, pos)
        if text.startswith(flag, pos):
            names.add(name)
            pos += len(flag)
    # the whole string is read before any of it is given a meaning, as the grammar does
    specs: list[tuple[str, str, str]] = []
    notes: list[tuple[str, str, tuple[str, str, str]]] = []
    while (spec := _format_spec(text, pos, True)) is not None:
        specs.append(spec[:3])
        pos = spec[3]
    pos = _space(text, pos)
    if not specs or not text.startswith("*", pos):
        return None
    pos += 1
    while (note := _note(text, pos)) is not None:
        words, address, becomes, pos = note
        if _NOTE_WORDS.intersection(words):
            return None
        notes.append((" ".join(words), address, becomes))
    if _space(text, pos) != len(text):
        return None
    children: list[object] = [names]
    children.extend(word_format_from_spec(a, plus == "+", digits) for a, plus, digits in specs)
    for facility, address, (a, plus, digits) in notes:
        fmt = word_format_from_spec(a, plus == "+", digits)
        children.append(_facility_note(facility, address, fmt))
    return _build_detailed(children)


def _facility_note(facility: str, address: str, fmt: WordFormat) -> tuple[str, str, WordFormat]:
    if fmt.address != address:
        raise FormatSpecError(
            f"facility note: the {address} word cannot become {fmt.spec()}", clause="Annex C"
        )
    return facility, address, fmt


def _build_detailed(children: list[object]) -> DetailedClassification:
    """The classification from the flags' names, then word formats and facility notes in the
    order written (what the grammar's start rule holds)."""
    flags = children[0]
    assert isinstance(flags, set)
    formats: dict[str, WordFormat] = {}
    facilities: dict[str, dict[str, WordFormat]] = {}
    for child in children[1:]:
        if isinstance(child, WordFormat):
            if child.address in formats:
                raise FormatSpecError(
                    f"detailed classification names {child.address} twice", clause="Annex C"
                )
            formats[child.address] = child
        elif isinstance(child, tuple):
            facility, address, fmt = child
            if address not in formats:
                raise FormatSpecError(
                    f"facility note changes the {address} word, which the classification "
                    "does not name",
                    clause="Annex C",
                )
            facilities.setdefault(facility, {})[address] = fmt
    order = [a for a in formats if a in ADDRESS_ORDER]
    expected = sorted(order, key=ADDRESS_ORDER.index)
    if order != expected:
        raise FormatSpecError(
            "detailed classification lists addresses out of the proper sequence: "
            f"{' '.join(order)} (expected {' '.join(expected)})",
            clause="Annex C",
        )
    return DetailedClassification(
        program_start="PERCENT" in flags,
        alignment="COLON" in flags,
        block_skip="SLASH" in flags,
        explicit_decimal="DS" in flags,
        formats=formats,
        facilities=facilities,
    )

# The proper sequence of addresses in a classification (and in a block, clause 5.2).
ADDRESS_ORDER = "ONGXYZUVWPQRABCIJKFESTDMH"


def word_format_from_spec(address: str, plus: bool, digits: str) -> WordFormat:
    """Decode the digits of one Annex C word format (see the module docstring of wordformat)."""
    where = f"{address}{'+' if plus else ''}{digits}"
    if len(digits) == 3:
        if digits[0] == "0":
            before, after, zeros = int(digits[1]), int(digits[2]), Zeros.LEADING
        elif digits[2] == "0":
            before, after, zeros = int(digits[0]), int(digits[1]), Zeros.TRAILING
        else:
            raise FormatSpecError(
                f"word format {where}: a three-digit format needs a 0 first (leading zeros "
                "omitted) or last (trailing zeros omitted)",
                clause="Annex C",
            )
        if before + after == 0:
            raise FormatSpecError(f"word format {where} has no digits", clause="Annex C")
        return WordFormat(address, before, after, plus, zeros, decimal=True)
    if len(digits) == 2:
        if digits[0] == "0" and digits[1] != "0":
            return WordFormat(address, int(digits[1]), 0, plus, Zeros.LEADING, decimal=False)
        if digits[1] == "0" and digits[0] != "0":
            return WordFormat(address, int(digits[0]), 0, plus, Zeros.TRAILING, decimal=False)
        if "0" not in digits:
            return WordFormat(address, int(digits[0]), int(digits[1]), plus, Zeros.NONE)
        raise FormatSpecError(f"word format {where} has no digits", clause="Annex C")
    if digits == "0":
        raise FormatSpecError(f"word format {where} has no digits", clause="Annex C")
    return WordFormat(address, int(digits), 0, plus, Zeros.NONE, decimal=False)


@record
class DetailedClassification(FrozenRecord):
    """Annex C: the programming detail of a control, one word format per address."""

    program_start: bool
    alignment: bool
    block_skip: bool
    explicit_decimal: bool  # DS
    formats: dict[str, WordFormat]
    facilities: dict[str, dict[str, WordFormat]] = field(default_factory=dict)

    def __init__(self, program_start: bool, alignment: bool, block_skip: bool,
                 explicit_decimal: bool, formats: dict[str, WordFormat],
                 facilities: dict[str, dict[str, WordFormat]] = NEW) -> None:
        init_fields(self, program_start, alignment, block_skip, explicit_decimal, formats,
                    new(facilities, dict))

    @classmethod
    def parse(cls, text: str) -> DetailedClassification:
        return _hand_detailed(text) or _lark_detailed(text)

    def __str__(self) -> str:
        flags = "".join(
            ch
            for ch, on in (
                ("%", self.program_start),
                (":", self.alignment),
                ("/", self.block_skip),
                ("DS", self.explicit_decimal),
            )
            if on
        )
        words = " ".join(f.spec() for f in self.formats.values())
        text = f"{flags} {words}*" if flags else f"{words}*"
        for facility, changes in self.facilities.items():
            for address, fmt in changes.items():
                text += f" (with {facility} facility, the {address} word becomes {fmt.spec()})"
        return text

    def explain(self) -> list[tuple[str, str, str]]:
        rows: list[tuple[str, str, str]] = []
        for ch, on, meaning in (
            ("%", self.program_start, "program start character"),
            (":", self.alignment, "alignment character (restart positions)"),
            ("/", self.block_skip, "optional block skip"),
            ("DS", self.explicit_decimal, "explicit decimal sign accepted"),
        ):
            rows.append((ch, "yes" if on else "no", meaning))
        for fmt in self.formats.values():
            rows.append((fmt.spec(), fmt.address, describe_format(fmt)))
        for facility, changes in self.facilities.items():
            for address, fmt in changes.items():
                meaning = f"with {facility} facility: {describe_format(fmt)}"
                rows.append((fmt.spec(), address, meaning))
        return rows


def describe_format(fmt: WordFormat) -> str:
    sign = "signed" if fmt.signed else "unsigned"
    zeros = {
        Zeros.LEADING: "leading zeros may be omitted",
        Zeros.TRAILING: "trailing zeros may be omitted",
        Zeros.NONE: "all digits written",
    }[fmt.zeros]
    if fmt.decimal:
        return f"{sign}, {fmt.before} digits before and {fmt.after} after the decimal sign, {zeros}"
    return f"{sign}, up to {fmt.before} digits, {zeros}"


def _general_shape(text: str) -> bool:
    """Annex B's shape: two letters and three digits, whatever else is written being taken for
    Annex C (two ASCII letters, then digits, each with any white space around)."""
    at, end = 0, len(text)
    for _ in range(2):
        while at < end and text[at].isspace():
            at += 1
        if at == end or not ("A" <= text[at] <= "Z" or "a" <= text[at] <= "z"):
            return False
        at += 1
    return all(c.isspace() or "0" <= c <= "9" for c in text[at:])


def parse_classification(text: str) -> GeneralClassification | DetailedClassification:
    """An Annex B (``PM 322``) or Annex C (``%:/DS N03 ... M02*``) classification, told apart by
    its shape: two letters and digits are a general classification, anything else (flags, word
    formats, ``*``) a detailed one, so that an error says what is wrong with the one meant -- a
    detailed classification without its ``*`` is not a bad general one."""
    if _general_shape(text):
        return GeneralClassification.parse(text)
    return DetailedClassification.parse(text)


def _describe(exc: UnexpectedInput) -> str:
    token = getattr(exc, "token", None)
    if token is not None:
        if token.type == "$END":
            expected = getattr(exc, "expected", None) or ()
            return ("end of text (a detailed classification ends with '*', the end of block)"
                    if "EOB" in expected else "end of text")
        return f"{str(token)!r}"
    char = getattr(exc, "char", None)
    return f"character {char!r}" if char else "input"


def _lark_detailed(text: str) -> DetailedClassification:
    """The reference: an Annex C string read by the grammar, or the located error."""
    from lark import Token, Transformer, UnexpectedInput
    from lark.exceptions import VisitError

    class Builder(Transformer[Token, DetailedClassification]):
        def spec(self, children: list[Token]) -> WordFormat:
            address = str(children[0])
            plus = len(children) == 3
            return word_format_from_spec(address, plus, str(children[-1]))

        def flags(self, children: list[Token]) -> set[str]:
            return {t.type for t in children}

        def facility_name(self, children: list[Token]) -> str:
            return " ".join(str(c) for c in children)

        def note(self, children: list[Any]) -> tuple[str, str, WordFormat]:
            facility, address, fmt = children
            assert isinstance(fmt, WordFormat)
            return _facility_note(str(facility), str(address), fmt)

        def start(self, children: list[object]) -> DetailedClassification:
            return _build_detailed(children)

    try:
        tree = _detailed_parser().parse(text)
    except UnexpectedInput as exc:
        line_hint = f"line {exc.line}, " if text.count("\n") else ""
        token = getattr(exc, "token", None)
        # lark places the end of the text at its last token; the text ends after it
        end = token is not None and token.type == "$END"
        column = len(text.rstrip().rsplit("\n", 1)[-1]) + 1 if end else exc.column
        raise FormatSpecError(
            f"detailed classification: unexpected {_describe(exc)} at {line_hint}column "
            f"{column}; expected e.g. '%:/DS N03 G02 X+053 ... M02*'",
            clause="Annex C",
        ) from None
    try:
        return Builder().transform(tree)
    except VisitError as exc:  # lark wraps what the builder raises
        if isinstance(exc.orig_exc, FormatSpecError):
            raise exc.orig_exc from None
        raise
