"""What a conversion is asked to do (:class:`ConvertOptions`) and what it did
(:class:`ConvertStats`): the data that :mod:`formats.convert` and :mod:`formats.verify` share.

A leaf of the two: the converter calls the proof, and the proof reads the options and the
roundings the converter reported, so neither imports the other.
"""

from __future__ import annotations

import os

from formats.classification import DetailedClassification
from formats.errors import ConversionError
from formats.profile import Profile, with_start_units
from formats.records import NEW, FrozenRecord, Record, field, init_fields, new, record
from formats.wordformat import Rounding, Zeros

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from collections.abc import Callable, Iterator
    from decimal import Decimal
    from typing import Any, TypeVar

    T = TypeVar("T")

# The families whose control reads a number without a decimal point as a whole number, with no
# setting for least increments (docs/dialects.md, "Numbers" of each): an implicit-decimal
# output is refused for them.
WHOLE_WITHOUT_POINT = {
    "linuxcnc": "LinuxCNC",  # the rs274ngc interpreter reads double-precision numbers
    "sinumerik": "SINUMERIK",  # Programming Manual "Fundamentals": X10 is 10 mm
    "heidenhain": "HEIDENHAIN",  # ISO mode: X+10 is 10 mm
    "okuma": "Okuma OSP",  # G0 X800 Z800 are whole
}


def _article(name: str) -> str:
    """``name`` after "a" or "an", as it is said ("an Okuma", "a SINUMERIK", "a LinuxCNC")."""
    return f"an {name}" if name[0] in "AEIOU" else f"a {name}"


def _replace(obj: T, **changes: Any) -> T:
    """``dataclasses.replace``, importing ``dataclasses`` (with ``inspect``, ``ast`` and
    ``dis``: 41M instructions) only where an override changes a record: a conversion without
    ``--from-*``, ``--decimal`` or ``--zeros`` does not load it (docs/benchmarks.md, "a
    conversion's start-up")."""
    import dataclasses

    return dataclasses.replace(obj, **changes)  # type: ignore[type-var]  # (a record)


@record
class ConvertOptions(FrozenRecord):
    """What to convert to. ``None`` for an override means "as the target profile says"."""

    target: Profile
    source: Profile | None = None  # None: detect from the program (see :func:`detect_source`)
    decimal: str | None = None  # "explicit" | "implicit"
    zeros: Zeros | None = None  # zero suppression of implicit-decimal words
    units: str | None = None  # "metric" | "inch": convert the units; None keeps them
    eob: str | None = None  # a key of EOB_STYLES
    rounding: Rounding = Rounding.HALF_EVEN
    spacing: str = "keep"  # keep | remove | insert
    allow_unconverted: bool = False  # leave unprovable parameters and P/Q/R words unconverted
    # How to read the source, over its profile: "explicit" (a word without a point is a whole
    # number), "implicit" (no decimal points: digits by the format), "increments" (a word
    # without a point counts least increments, as a Fanuc reads it); and its zero suppression.
    from_decimal: str | None = None
    from_zeros: Zeros | None = None
    # The units the source machine is set to at the program's start (``--from-units``): where
    # its control has no units code (an Okuma OSP lathe), the units its machine parameter sets,
    # which nothing in the program shows; elsewhere those before the program's first units code.
    from_units: str | None = None

    def __init__(self, target: Profile, source: Profile | None = None,
                 decimal: str | None = None, zeros: Zeros | None = None,
                 units: str | None = None, eob: str | None = None,
                 rounding: Rounding = Rounding.HALF_EVEN, spacing: str = "keep",
                 allow_unconverted: bool = False, from_decimal: str | None = None,
                 from_zeros: Zeros | None = None, from_units: str | None = None) -> None:
        init_fields(self, target, source, decimal, zeros, units, eob, rounding, spacing,
                    allow_unconverted, from_decimal, from_zeros, from_units)
        self._refuse_misread()

    def _refuse_misread(self) -> None:
        """Refuse an output its target control would misread: ``--decimal implicit`` for a
        control that reads a number written without a decimal point as a whole number, and a
        target of G code system B or C with no source given (the system it is written in)."""
        if self.from_units not in (None, "metric", "inch"):
            raise ConversionError(f"--from-units must be metric or inch, not {self.from_units!r}",
                                  code="conversion-option")
        system = self.target.g_code_system
        if self.source is None and system in ("B", "C"):
            # a program's text does not show its G code system (G90 is the cutting cycle in A,
            # absolute programming in B): detected, the source's codes would be written as they
            # stand, each a function of system A read as another in B or C
            raise ConversionError(
                f"{self.target.name} reads G codes by G code system {system}, and which system "
                "the source is written in cannot be told from its text (G90 is a cutting cycle "
                "in system A and absolute programming in B, G98 feed per minute in A and a "
                "return level in B): give --from (fanuc-lathe for system A, fanuc-lathe-b, "
                "fanuc-lathe-c, or the source's own profile)",
                code="conversion-option")
        explicit = self.target.explicit if self.decimal is None else self.decimal == "explicit"
        zeros = self.zeros or self.target.word_format("X").zeros
        if not explicit and self.target.numbers.without_point == "increments" \
                and zeros == Zeros.TRAILING:
            # such a control counts least increments in a number without its point however
            # the program is written (a FANUC: X0001 is 0.001 mm); left-aligned digits are
            # another number to it (review 58b: --verify reads the output by its formats)
            raise ConversionError(
                f"--zeros trailing: {self.target.name} reads a number written without a "
                "decimal point as a count of least increments (X0001 is 0.001, not 10.000): "
                "trailing-zero output would be misread; leave --zeros out (or give leading)",
                code="conversion-option")
        family = self.target.dialect.family
        if self.decimal == "implicit" and family in WHOLE_WITHOUT_POINT:
            control = _article(WHOLE_WITHOUT_POINT[family])
            raise ConversionError(
                f"--decimal implicit: {self.target.name} is {control} "
                "control, which reads a number written without a decimal point as a whole "
                "number (X10 is 10 mm, not 0.010): implicit-decimal output would move it a "
                "thousand times too far; leave --decimal out (or give explicit)",
                code="conversion-option")

    def source_reading(self, source: Profile) -> tuple[Profile, list[str]]:
        """The source profile with the ``from_*`` overrides, and what they assume."""
        notes = []
        detailed, numbers, inch = source.detailed, source.numbers, source.detailed_inch
        if self.from_decimal is not None:
            explicit = self.from_decimal != "implicit"
            detailed = _replace(detailed, explicit_decimal=explicit)
            if inch is not None:
                inch = _replace(inch, explicit_decimal=explicit)
            whole = ", ".join(numbers.whole_letters() or "")
            # implicit, on a control that counts least increments in a number without its
            # point (a FANUC, a Haas): its own reading, whatever decimals the program was
            # written with -- the letters it reads whole stay whole (G21 is code 21, F100 is
            # 100: fanuc-mill.toml's whole = "PLFG"), the others count increments, which is
            # the implicit reading with leading zeros omitted; left-aligned digits are no
            # number it reads (review 58b F6: G21 was read G2.1, F100 F0.1, and verified)
            if self.from_decimal == "implicit" and numbers.without_point == "increments":
                if self.from_zeros == Zeros.TRAILING:
                    raise ConversionError(
                        f"--from-zeros trailing: {source.name} reads a number written without "
                        "a decimal point as a count of least increments (X0001 is 0.001, not "
                        "10.000), not with its trailing zeros omitted: give the profile of the "
                        "control the program was written for (--from)",
                        code="conversion-option")
            else:
                increments = self.from_decimal == "increments"
                numbers = _replace(numbers,
                                   without_point="increments" if increments else "whole")
            notes.append({
                "explicit": "source: decimal points as written, a word without one is a whole "
                            "number (--from-decimal explicit)",
                "implicit": (f"source: implicit decimal, read as {source.name}'s control "
                             f"reads a number without its point: {whole} whole numbers, the "
                             "others in least increments (--from-decimal implicit)"
                             if numbers.without_point == "increments" else
                             "source: implicit decimal, digits read by the word formats of "
                             f"{source.name} (--from-decimal implicit)"),
                "increments": "source: decimal points as written, a word without one counts "
                              "least increments of its format, X10000 = 10.000 at 0.001 "
                              "(--from-decimal increments)",
            }[self.from_decimal])
        if self.from_zeros is not None:
            zeros = self.from_zeros

            def rezero(d: DetailedClassification) -> DetailedClassification:
                formats = {k: _replace(f, zeros=zeros) if f.decimal else f
                           for k, f in d.formats.items()}
                return _replace(d, formats=formats)

            detailed = rezero(detailed)
            inch = None if inch is None else rezero(inch)
            notes.append(f"source: {zeros} zeros omitted in implicit-decimal words "
                         f"(--from-zeros {zeros})")
        if self.from_units is not None:
            notes.append(f"source: read in {self.from_units} from the program's start, "
                         + ("the units its machine parameter is set to" if not
                            source.units_by_code else "until a units code of the program")
                         + f" (--from-units {self.from_units})")
        if not notes:
            return source, notes
        if self.from_decimal is not None or self.from_zeros is not None:
            source = _replace(source, detailed=detailed, numbers=numbers, detailed_inch=inch)
        if self.from_units is not None:
            source = with_start_units(source, self.from_units)
        return source, notes

    def effective_target(self) -> Profile:
        """The target profile with the overrides applied: what the output must be read with."""
        target = self.target
        explicit = target.explicit if self.decimal is None else self.decimal == "explicit"

        def overridden(detailed: DetailedClassification) -> DetailedClassification:
            formats = dict(detailed.formats)
            if self.zeros is not None:
                formats = {k: _replace(f, zeros=self.zeros) if f.decimal else f
                           for k, f in formats.items()}
            if explicit == detailed.explicit_decimal and formats == detailed.formats:
                return detailed
            return _replace(detailed, formats=formats, explicit_decimal=explicit)

        detailed = overridden(target.detailed)
        inch = None if target.detailed_inch is None else overridden(target.detailed_inch)
        if detailed is target.detailed and inch is target.detailed_inch:
            return target
        return _replace(target, detailed=detailed, detailed_inch=inch)


NOTES_HELD = 1000  # notes a conversion keeps in memory before it spills the rest to a file


@record
class ConvertStats(Record):
    """What one conversion did, for the summary table and the closing report.

    The notes are in :attr:`notes`, in the order made, unless a folder to spill them to is
    given (:meth:`spill_to`, the command line's batches): then the first :data:`NOTES_HELD`
    are in :attr:`notes` and the rest, as the command prints them (``FILE: NOTE`` lines), in
    the file :attr:`notes_spill`, so a program with a note per word does not grow the memory
    (LinuxCNC's 3D_Chips at 1,000,000 blocks makes 1.9 million notes)."""

    file: str = ""
    output: str = ""
    blocks: int = 0
    words: int = 0
    changed: int = 0
    # address -> the largest |error| of its roundings, exact, as (numerator, denominator) in
    # lowest terms with a positive denominator: ``Fraction(*pair)`` is the value (integers,
    # not a Fraction: a conversion imports neither fractions nor decimal unless its proof or a
    # caller needs them; docs/benchmarks.md, perf40). The summary's text of the largest:
    # :meth:`largest_rounding_text`.
    rounding: dict[str, tuple[int, int]] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)
    error: str = ""
    verified: bool = False
    # The units the proof read the source in where nothing shows them (a source control that
    # selects its units by a machine parameter, no --from-units): "metric" or "inch", else ""
    # (:func:`formats.verify.assumed_units`).
    verified_assuming: str = ""
    # The statements the proof did not compare, as (line in the source, text): a statement
    # holding a number that no role of the converter's table gives, read in other units in
    # the output (left as written under --allow-unconverted; a LinuxCNC call's arguments,
    # converted by the parameter analysis). With any, ``verified`` stays False: the summary
    # says "partly verified" (:func:`formats.verify.verify_conversion`).
    not_compared: list[tuple[int, str]] = field(default_factory=list)
    # Words, statements and parameters --allow-unconverted left as written where the units
    # change, as the core counts them where it leaves them (``Converter.left_as_written`` in
    # crates/core/src/convert.rs; each is also named in a note): the proof reads them as written
    # on both sides, so it cannot say they move as in the source (`X#1` with `#1=10.` kept is
    # 10 in where it was 10 mm). With any, ``verified`` stays False: "partly verified". The
    # first one's (line, column) in ``left_at``.
    left_as_written: int = 0
    left_at: tuple[int, int] | None = None
    # How many of ``left_as_written`` are whole statements (``DPRNT[...]``), not words.
    left_statements: int = 0
    # The lines after the program's end that the control never reads, left as written where the
    # units change (a LinuxCNC file's text after its M2/M30): no word of the program, so no
    # bar to "verified". The first one's (line, column) in ``never_read_at``.
    never_read: int = 0
    never_read_at: tuple[int, int] | None = None
    # A target that selects its units by a machine parameter: the units the converter's note
    # says to set the machine to ("inch", "metric"), those the proof reads the output in.
    machine_units: str | None = None
    # Whether the output was read back and compared (--verify): ``verified`` then says whether
    # everything was proved, and with False the summary says "partly verified".
    proved: bool = False
    # The units each LinuxCNC subroutine body was read in under a change of units, its calls'
    # (label, "inch" or "metric"): the proof reads the source's bodies in them.
    body_units: list[tuple[str, str]] = field(default_factory=list)
    notes_spill: str | None = None  # the notes after the first NOTES_HELD (see above)

    # the notes made by Python (the detected source, the reading assumed), to say each once:
    # a set, as a list's ``in`` made a program with a note per word quadratic. The core's
    # notes come through :meth:`said`: the core says each once itself.
    _noted: set[str] = field(default_factory=set, repr=False, compare=False)
    _spill_dir: str | Callable[[], str] | None = field(default=None, repr=False, compare=False)
    _spill: int | None = field(default=None, repr=False, compare=False)  # its descriptor
    _spill_at: int = field(default=0, repr=False, compare=False)  # the bytes written there
    # Where the spill failed (no room in the temporary folder, no descriptor left, a folder that
    # cannot be written: an OSError), the notes after those spilled, as they are printed
    # (``FILE: NOTE`` lines), held in memory instead, and what to tell once: the folder and the
    # error (review 75, N1: the file was told as failed, "FILE: No space left on device", its
    # output not written and its notes lost)
    notes_kept: list[str] = field(default_factory=list, repr=False, compare=False)
    notes_unspilled: str = field(default="", repr=False, compare=False)

    def __init__(self, file: str = "", output: str = "", blocks: int = 0, words: int = 0,
                 changed: int = 0, rounding: dict[str, tuple[int, int]] = NEW,
                 notes: list[str] = NEW, error: str = "", verified: bool = False,
                 verified_assuming: str = "", not_compared: list[tuple[int, str]] = NEW,
                 left_as_written: int = 0, left_at: tuple[int, int] | None = None,
                 left_statements: int = 0, never_read: int = 0,
                 never_read_at: tuple[int, int] | None = None,
                 machine_units: str | None = None, proved: bool = False,
                 body_units: list[tuple[str, str]] = NEW, notes_spill: str | None = None,
                 _noted: set[str] = NEW, _spill_dir: str | Callable[[], str] | None = None,
                 _spill: int | None = None, _spill_at: int = 0, notes_kept: list[str] = NEW,
                 notes_unspilled: str = "") -> None:
        init_fields(self, file, output, blocks, words, changed, new(rounding, dict),
                    new(notes, list), error, verified, verified_assuming,
                    new(not_compared, list), left_as_written, left_at, left_statements,
                    never_read, never_read_at, machine_units, proved, new(body_units, list),
                    notes_spill, new(_noted, set), _spill_dir, _spill, _spill_at,
                    new(notes_kept, list), notes_unspilled)

    def note(self, text: str) -> None:
        if text not in self._noted:
            self._noted.add(text)
            self.said([text])

    def said(self, notes: list[str]) -> None:
        """Notes the core made (each already said once), in order."""
        if not notes:
            return
        room = len(notes) if self._spill_dir is None else NOTES_HELD - len(self.notes)
        if room > 0:
            self.notes.extend(notes[:room])
            if room >= len(notes):
                return
            notes = notes[room:]
        said, kept = f"{self.file}: ", self.notes_kept
        spilling = not kept and (self._spill is not None or self._spill_file())
        for at in range(0, len(notes), 1024):  # (a chunk of 1 MB can make 40,000 notes)
            text = said + f"\n{said}".join(notes[at:at + 1024]) + "\n"
            if not spilling or not self._spill_write(text):
                kept.append(text)
                spilling = False

    def _spill_file(self) -> bool:
        """The spill file made (:attr:`notes_spill`); False where it cannot be."""
        import tempfile

        folder = None
        try:
            folder = self._spill_dir() if callable(self._spill_dir) else self._spill_dir
            fd, self.notes_spill = tempfile.mkstemp(prefix="notes-", dir=folder)
        except OSError as exc:
            if folder is None:  # (the folder itself could not be made)
                folder = os.path.dirname(exc.filename) if isinstance(exc.filename, str) else (
                    os.environ.get("TMPDIR") or "the temporary folder")
            self._unspilled(exc, folder)
            return False
        self._spill = fd
        return True

    def _spill_write(self, text: str) -> bool:
        """``text`` written at the end of the spill file; False where it cannot be (the file
        cut back to the notes written before it, none of it left there)."""
        assert self._spill is not None
        data = text.encode("utf-8", "surrogateescape")
        done = 0
        try:
            while done < len(data):
                done += os.write(self._spill, data[done:])
        except OSError as exc:
            try:
                os.ftruncate(self._spill, self._spill_at)
                os.lseek(self._spill, self._spill_at, os.SEEK_SET)
            except OSError:  # (cut back or not, only the first ``_spill_at`` bytes are read)
                pass
            self._unspilled(exc, os.path.dirname(self.notes_spill or ""))
            return False
        self._spill_at += done
        return True

    def _unspilled(self, error: OSError, folder: str) -> None:
        """The spill's failure noted, to be told once: ``error``, and the folder, named as the
        temporary folder where a batch made its own in it (a function gave it)."""
        if callable(self._spill_dir) and os.path.basename(folder).startswith("tapegate-"):
            folder = os.path.dirname(folder)
        if not self.notes_unspilled:
            self.notes_unspilled = (f"cannot write the notes waiting for the summary to {folder}: "
                                    f"{error.strerror or error}; they are held in memory instead")

    def notes_after(self) -> Iterator[str]:
        """The notes after :attr:`notes`, as they are printed (``FILE: NOTE`` lines, in pieces):
        the spilled ones, read back from their file (removed), then those kept in memory
        where the spill failed."""
        if self.notes_spill:
            # (the bytes written whole: a write that failed was cut back, or is not read)
            with open(self.notes_spill, "rb") as rest:
                left, carry = self._spill_at, b""
                while left > 0:
                    piece = rest.read(min(left, 1 << 20))
                    if not piece:
                        break
                    left -= len(piece)
                    piece = carry + piece
                    cut = piece.rfind(b"\n") + 1 if left > 0 else len(piece)  # (whole lines)
                    carry = piece[cut:]
                    if cut:
                        yield piece[:cut].decode("utf-8", "surrogateescape")
            os.unlink(self.notes_spill)
            self.notes_spill = None
        yield from self.notes_kept

    def spill_to(self, folder: str | Callable[[], str]) -> None:
        """Notes beyond the first :data:`NOTES_HELD` go to a file in ``folder`` (or in the
        folder it gives, called at the first such note: a batch makes it only if needed)."""
        self._spill_dir = folder

    def close_notes(self) -> None:
        """The spilled notes written out (before the statistics are sent or read)."""
        if self._spill is not None:
            os.close(self._spill)
            self._spill = None

    def drop_notes(self) -> None:
        """No notes after all (the conversion failed: its error is what is told)."""
        self.close_notes()
        if self.notes_spill:
            os.unlink(self.notes_spill)
        self.notes, self.notes_spill, self.notes_kept = [], None, []

    def largest_rounding_pair(self) -> tuple[str, tuple[int, int]]:
        """The address of the largest rounding (the first such, in :attr:`rounding`'s order)
        and its (numerator, denominator); ``("", (0, 1))`` without any."""
        letter, best = "", (0, 1)
        for address, (num, den) in self.rounding.items():
            if not letter or num * best[1] > best[0] * den:
                letter, best = address, (num, den)
        return letter, best

    def largest_rounding_text(self) -> tuple[str, str]:
        """The address of the largest rounding and its error as the summary writes it
        (:func:`rounding_text`); ``("", "0")`` without any."""
        letter, (num, den) = self.largest_rounding_pair()
        return letter, rounding_text(num, den)

    def largest_rounding(self) -> tuple[str, Decimal]:
        """:meth:`largest_rounding_text`'s error as a :class:`~decimal.Decimal` (the same
        digits and exponent)."""
        from decimal import Decimal

        letter, text = self.largest_rounding_text()
        return letter, Decimal(text)


def rounding_text(num: int, den: int) -> str:
    """A rounding error ``num / den`` for people: three significant digits, rounded up (never
    understated), trailing zeros dropped, written as ``str`` writes the
    :class:`~decimal.Decimal` that a context of precision 3 and ``ROUND_UP`` gives for
    ``Decimal(num) / Decimal(den)``, normalized (``0.00347``, ``0.5``, ``1.27E-7``, ``1E+1``).
    Made from the integers, exactly, without importing :mod:`decimal` (which the conversion's
    start-up does not need; ``tests/test_convert_stats.py`` holds it to Decimal's text)."""
    if den <= 0:
        raise ValueError(f"a rounding's denominator must be positive, not {den}")
    if num == 0:
        return "0"
    sign, num = ("-", -num) if num < 0 else ("", num)
    # the adjusted exponent k: 10**k <= num/den < 10**(k+1), k one of two by the digit counts
    k = len(str(num)) - len(str(den))
    if (num * 10 ** -k if k < 0 else num) < (den if k < 0 else den * 10 ** k):
        k -= 1
    # three significant digits, rounded away from zero: ceil(num/den * 10**(2-k))
    top, bottom = (num * 10 ** (2 - k), den) if k <= 2 else (num, den * 10 ** (k - 2))
    digits = -(-top // bottom)
    exp = k - 2
    if digits == 1000:  # (999.5 and more rounded up to the next power of ten)
        digits, exp = 100, exp + 1
    while digits % 10 == 0:  # normalized: no trailing zero
        digits, exp = digits // 10, exp + 1
    coefficient = str(digits)
    # Decimal's to-scientific-string: plain for exponents <= 0 down to 1E-6, else E notation
    left = exp + len(coefficient)
    dot = left if exp <= 0 and left > -6 else 1
    if dot <= 0:
        text = "0." + "0" * -dot + coefficient
    elif dot >= len(coefficient):
        text = coefficient + "0" * (dot - len(coefficient))
    else:
        text = coefficient[:dot] + "." + coefficient[dot:]
    if left != dot:
        text += f"E{left - dot:+d}"
    return sign + text
