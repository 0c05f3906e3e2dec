"""Exact conversion of a program from one machine format to another (ISO 6983-1 Annex C, 6.1).

What changes: the way numbers are written (implicit or explicit decimal sign, which zeros are
omitted, digits before and after the decimal sign), the units (metric <-> inch, 1 in = 25.4 mm
exactly), the units code, and -- on request -- spacing and end of block. Everything else --
comments, word order, block numbers, ``%`` and the identification -- is kept as written.

Units follow the **modal state of each block**, not a list of letters:

===========================  ==================================================================
word                         converted as a length when ...
===========================  ==================================================================
X Y Z U V W, I J K           always (positions, arc centres, thread leads) -- except a G04
                             dwell's time word (the control's: LinuxCNC's is P alone, so its
                             ``G4 P1 X10`` moves to X10, and X is converted)
P Q R                        the source profile says the letter is a length (``checks.pqr``)
F (and E)                    G94 (per minute) or G95 (per revolution); never G93 inverse time,
                             never the time of a G04 dwell (ISO, SINUMERIK ``G4 F``)
S                            G96 constant surface speed (m/min <-> ft/min); never G97 (rpm),
                             never ``G92 S`` (a spindle speed clamp)
A B C, N G M T D H O         never (angles and counts; only their written form may change)
===========================  ==================================================================

Arithmetic is on integers: a source value ``m * 10**-k`` times the factor ``num/den`` is rounded
to the target resolution ``10**-after`` with one division -- exact, with no float anywhere.
In G91 incremental mode the converter tracks the exact absolute position of each axis, converts
that and writes the difference of converted absolutes, so rounding never accumulates along a path.

The conversion itself is the Rust core's (``crates/core/src/convert.rs``), and so is the proof of
which parameters hold lengths that a units conversion needs (``crates/core/src/lengths.rs``);
this module holds the detection of an unnamed source format and the files, and hands the core
whole lines of text a chunk at a time. The options and the statistics
are :mod:`formats.conversion`'s, shared with the proof (:mod:`formats.verify`), which the
converter calls and which does not call it.
"""

from __future__ import annotations

import math
import os
from itertools import chain

from formats import _core
from formats.conversion import ConvertOptions, ConvertStats
from formats.errors import ConversionError
from formats.files import PendingFile, is_special, parent, pure
from formats.machine import machine
from formats.model import Block
from formats.parser import (
    CHUNK,
    MAX_BLOCK,
    Dialect,
    decode_chunks,
    parse_stream,
    read_chunks,
    too_long_block,
    whole_lines,
)
from formats.printer import print_lines
from formats.profile import EOB_STYLES, NEUTRAL, Profile, with_units_codes
from formats.source import Source

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from collections.abc import Callable, Iterable, Iterator
    from typing import Any, TypeVar

    T = TypeVar("T")

__all__ = ["ConvertOptions", "ConvertStats", "Converter", "ParameterClasses",
           "analyse_file_parameters", "analyse_parameters", "convert_file", "convert_text",
           "Handover", "detect_source", "sync_folders"]

# The parameter analysis's outcome: held in the core, the file's classes once (not a list per
# program of a memory backup), and handed to the converter as it is; ``programs()`` lists them.
ParameterClasses = _core.ParameterClasses


# ---------------------------------------------------------------------------------------------
# Detecting the source format


# (G20 HP=1 is an Okuma OSP lathe's home position return, no units code: okuma-lathe)
# (patterns, compiled by re's own cache at the first detection: a conversion given --from
# does not import re; docs/benchmarks.md, perf40)
_UNITS_CODE = r"(?<![A-Z0-9.])G0*(20|21|70|71)(?![0-9.])(?![ \t]*HP[ \t]*=)"
_DECIMAL_WORD = r"[XYZIJKF][+-]?[0-9]*\.[0-9]*"


def detect_source(head: str) -> tuple[Profile, list[str]]:
    """A reading of a program whose format was not given, and what was assumed (``--from``)."""
    import re

    notes = []
    text = re.sub(r"\([^)\n]*\)|;[^\n]*", "", head.upper())
    units = re.search(_UNITS_CODE, text)
    profile = NEUTRAL
    if units is None:
        notes.append("source: no units code (G70/G71, G20/G21) found, read as metric")
    else:
        code = int(units.group(1))
        if code in (20, 21):
            profile = with_units_codes(profile, "G20", "G21")
        notes.append(f"source: units codes G{code // 10 * 10}/G{code // 10 * 10 + 1} "
                     f"(G{code} found)")
    if re.search(_DECIMAL_WORD, text):
        notes.append("source: explicit decimal sign (decimal points found)")
    else:
        notes.append("source: no decimal points found; read as explicit decimal (whole "
                     "numbers) -- give --from for an implicit-decimal program")
    return profile, notes


# ---------------------------------------------------------------------------------------------
# The converter



#: The clause of a core refusal answered by converting again (``Reread``).
REREAD = "units-reread"


class Reread(Exception):
    """A length parameter is set before its first read in other units than the read's: its
    value is in the units of the read, which the core learns only there. The conversion is
    made again from the start with ``read_units`` (program, parameter, units): see
    :func:`with_rereads`."""

    def __init__(self, read_units: list[tuple[int, str, str]], error: ConversionError) -> None:
        super().__init__(str(error))
        self.read_units = read_units
        self.error = error


def with_rereads(convert: Callable[[list[tuple[int, str, str]]], T]) -> T:
    """``convert(read_units)`` again with what each :class:`Reread` learned, until it converts
    or fails otherwise; each round learns at least one parameter, so a program with N of them
    set before their reads takes at most N + 1 rounds."""
    read_units: list[tuple[int, str, str]] = []
    while True:
        try:
            return convert(read_units)
        except Reread as again:
            new = [r for r in again.read_units if r not in read_units]
            if not new:
                raise again.error from None
            read_units = read_units + new


class Converter:
    """Converts a stream of blocks; :attr:`stats` says what it did.

    ``parameters`` is the outcome of :func:`analyse_parameters` for programs with parameter
    expressions (``None``: the program has none); ``read_units`` what a :class:`Reread` learned.
    """

    def __init__(self, options: ConvertOptions, source: Profile, *, file: str | None = None,
                 parameters: ParameterClasses | None = None,
                 stats: ConvertStats | None = None,
                 read_units: list[tuple[int, str, str]] | None = None) -> None:
        self.read_units = read_units or []
        self.options = options
        self.source = source
        self.target = options.effective_target()
        self.file = file
        self.parameters = parameters
        self.stats = stats or ConvertStats(file=file or "")
        eob = options.eob
        self.eob = EOB_STYLES[eob] if eob else None
        self._core = _core.Converter(machine(source), machine(self.target), self._options(),
                                     self.eob, file)

    def _options(self) -> dict[str, Any]:
        """What this conversion is asked to do, beyond the two machines."""
        options, parameters = self.options, self.parameters
        return {
            "units": options.units,
            "rounding": str(options.rounding),
            "spacing": options.spacing,
            "allow_unconverted": options.allow_unconverted,
            "parameters": parameters,
            "source_detected": options.source is None,
            "source_units_given": options.from_units is not None,
            # a word the source reads in lower case, written for a target that reads only
            # upper case (review 16c, finding 5); a Haas reads its program number's `o`
            # (`o40001`, NGC manual 5.3.1) and no other lower-case address
            "upper_case": not self.target.dialect.lowercase
            and (
                self.source.dialect.lowercase
                or (self.source.dialect.family == "haas" and self.target.dialect.family != "haas")
            ),
            "read_units": self.read_units,
        }

    # -- the stream --------------------------------------------------------------------------

    def convert(self, blocks: Iterable[Block]) -> Iterator[str]:
        """Output text in chunks of about 64 KiB."""
        convert = self._core.convert_block
        yield from print_lines(((convert(block), block.has_eob) for block in blocks), self.eob)
        self._core.end()
        self.finish()

    def convert_stream(self, chunks: Iterable[str], dialect: Dialect) -> Iterator[str]:
        """Output text for a program arriving as text chunks (the way files are converted): the
        core converts whole lines a chunk at a time, with no Python object per block."""
        try:
            yield from self._convert_stream(chunks, dialect)
        except ConversionError as error:
            if error.clause == REREAD:
                raise Reread(self._core.read_units_learned(), error) from error
            raise

    def _convert_stream(self, chunks: Iterable[str], dialect: Dialect) -> Iterator[str]:
        """:meth:`convert_stream`, a refusal as the core made it."""
        flags = dialect.flags
        said, take = self.stats.said, self._core.take_notes
        for text, line, unread in whole_lines(chunks):
            if unread is None:
                yield self._core.convert_lines(text[:-1], line, flags)
            else:
                convert = self._core.convert_block
                yield from print_lines(((convert(block), block.has_eob) for block in parse_stream(
                    chain([text], unread), dialect, file=self.file, first_line=line)), self.eob)
            said(take())  # the chunk's notes, taken as they come: none kept in the core
        self._core.end()
        self.finish()

    def convert_file(self, path: str, dialect: Dialect, pending: PendingFile) -> None:
        """The file at ``path`` converted into ``pending``, as :meth:`convert_stream` converts
        its chunks. A text file is read, converted and written by the core with the GIL
        released (``Converter.convert_file``: the threads of ``convert -j`` take it only for
        each chunk's notes); a tape image, or a head that is not UTF-8, and the text after the
        last LF where the core leaves it (a last line without its LF, a line past
        ``MAX_BLOCK``), are read here as :meth:`convert_stream` reads them."""
        try:
            self._convert_file(path, dialect, pending)
        except ConversionError as error:
            if error.clause == REREAD:
                raise Reread(self._core.read_units_learned(), error) from error
            raise

    def _convert_file(self, path: str, dialect: Dialect, pending: PendingFile) -> None:
        """:meth:`convert_file`, a refusal as the core made it."""
        pending.file.flush()  # (the core writes after what the file holds)
        done = self._core.convert_file(path, dialect.flags, pending.file.fileno(),
                                       self.stats.said)
        if done is None:  # a tape image, or a head that is not UTF-8: Source reads it
            for text in self._convert_stream(Source(path).chunks(), dialect):
                pending.write(text.encode("utf-8", errors="surrogateescape"))
            return
        pending.size = os.lseek(pending.file.fileno(), 0, os.SEEK_CUR)  # what the core wrote
        if done is not True:  # the text after the last LF: as _convert_stream reads it
            rest, at, line = done
            unread = iter(()) if at is None else decode_chunks(read_chunks(path, CHUNK, at))
            convert = self._core.convert_block
            for text in print_lines(((convert(block), block.has_eob) for block in parse_stream(
                    chain([rest], unread), dialect, file=self.file, first_line=line)),
                    self.eob):
                pending.write(text.encode("utf-8", errors="surrogateescape"))
            self.stats.said(self._core.take_notes())
        self._core.end()
        self.finish()

    def finish(self) -> ConvertStats:
        """The statistics, with the largest rounding per address exact: (numerator,
        denominator) in lowest terms (:attr:`ConvertStats.rounding`)."""
        core = self._core.stats
        stats = self.stats
        stats.blocks, stats.words, stats.changed = core["blocks"], core["words"], core["changed"]
        stats.said(self._core.take_notes())
        stats.rounding = {letter: _lowest(e, d) for letter, e, d in core["rounding"]}
        stats.body_units = self._core.body_units()
        stats.left_as_written, stats.left_at = _left(core["left_as_written"])
        stats.left_statements = core["left_statements"]
        stats.never_read, stats.never_read_at = _left(core["never_read"])
        stats.machine_units = core["machine_units"]
        return stats


def _lowest(num: int, den: int) -> tuple[int, int]:
    """``num / den`` as ``Fraction(num, den)`` holds it: in lowest terms, the denominator
    positive (without importing fractions: docs/benchmarks.md, perf40)."""
    if den < 0:
        num, den = -num, -den
    common = math.gcd(num, den)
    return num // common, den // common


def _left(count: tuple[int, int, int]) -> tuple[int, tuple[int, int] | None]:
    """The core's ``(count, first line, first column)`` as the count and the first place."""
    n, line, column = count
    return n, (line, column) if n else None


# ---------------------------------------------------------------------------------------------
# Files


def has_parameters(text: str) -> bool:
    """Whether a program may hold parameter assignments or expressions (a cheap scan for a
    ``=`` or a ``#``; ``_core.has_parameters`` makes it of a file, with the GIL released)."""
    return "=" in text or "#" in text


def analyse_parameters(chunks: Iterable[str], source: Profile, *, file: str | None = None
                       ) -> ParameterClasses:
    """Which parameters of a program are lengths: the core's proof (``crates/core/src/lengths.rs``:
    the rule, and how a file of several programs is read), fed the program's whole lines a chunk
    at a time. The first line that cannot be read and holds a word that may read or set a
    parameter raises its :class:`ParseError`, as :func:`formats.parser.parse_stream` would."""
    analysis = _core.ParameterAnalysis(machine(source))
    flags = source.dialect.flags
    for text, line, unread in whole_lines(chunks):
        if unread is None:
            analysis.read_lines(text[:-1], line, flags, file)
        elif len(text) > MAX_BLOCK:
            next(too_long_block(text, line + 1, file, "raise"))  # raises its ParseError
        else:
            analysis.read_lines(text, line, flags, file)
    return analysis.result()


def analyse_file_parameters(path: str, source: Profile, *, file: str | None = None
                            ) -> ParameterClasses:
    """:func:`analyse_parameters` of the file at ``path``: a text file read by the core with
    the GIL released (``ParameterAnalysis.read_file``), a tape image, a head that is not UTF-8
    and the text after the last LF where the core leaves it read here, as
    :func:`analyse_parameters` reads them."""
    analysis = _core.ParameterAnalysis(machine(source))
    flags = source.dialect.flags
    done = analysis.read_file(path, flags, file)
    if done is None:
        return analyse_parameters(Source(path).chunks(), source, file=file)
    if done is not True:
        rest, _, line = done
        if len(rest) > MAX_BLOCK:
            next(too_long_block(rest, line + 1, file, "raise"))  # raises its ParseError
        analysis.read_lines(rest, line, flags, file)
    return analysis.result()


def convert_file(path: str, output: str | None, options: ConvertOptions, *,
                 overwrite: bool = False, verify: bool = False, display: str | None = None,
                 make_folder: bool = True, sync_folder: bool = True,
                 notes_spill: str | Callable[[], str] | None = None,
                 commit: Callable[[Handover], None] | None = None) -> ConvertStats:
    """Convert one file; ``output`` None is a dry run (everything but the write).

    The output is written through a temporary file in its folder, fsync'd, and renamed into
    place only when the whole program converted (and verified): a failure leaves nothing
    behind, and a crash or power cut never leaves a part of it under its name. The folder is
    fsync'd after the rename (the name itself on disk) unless ``sync_folder`` is False: a batch
    syncs each of its folders once, at its end (:func:`sync_folders`). An existing output is
    refused unless ``overwrite``. A missing output folder is made, unless ``make_folder`` is
    False (the command line's ``-o``, where it is an error). ``notes_spill``: a folder where
    the notes beyond the first thousand go, or a function that gives it
    (:meth:`ConvertStats.spill_to`).

    ``commit``: the fsync and the rename are not done here but handed to it (a
    :class:`Handover`: the output, and a function that commits it here), once the file is
    converted and verified: a batch runs them in threads of their own, so that a worker's core
    computes the next file while the disk writes this one (``tapegate.converting``; an fsync
    is 2-4 ms here, a conversion of a 3,000-block file 3 ms of CPU). Until it is committed,
    nothing has the output's name.
    """
    name = display or path

    def attempt(read_units: list[tuple[int, str, str]]) -> ConvertStats:
        stats = ConvertStats(file=name, output=output or "")
        if notes_spill is not None:
            stats.spill_to(notes_spill)
        try:
            return _convert_file(path, output, options, stats, overwrite=overwrite,
                                 verify=verify, make_folder=make_folder,
                                 sync_folder=sync_folder, read_units=read_units,
                                 commit=commit)
        except BaseException:
            stats.drop_notes()
            raise
        finally:
            stats.close_notes()

    return with_rereads(attempt)


def _convert_file(path: str, output: str | None, options: ConvertOptions, stats: ConvertStats,
                  *, overwrite: bool, verify: bool, make_folder: bool,
                  sync_folder: bool, read_units: list[tuple[int, str, str]],
                  commit: Callable[[Handover], None] | None = None) -> ConvertStats:
    name = stats.file
    if (output is not None and not overwrite and os.path.exists(output)
            and not is_special(output)):  # (a device or a FIFO is written into, not replaced)
        raise ConversionError(f"{output} exists; use --force to overwrite it", file=name,
                              code="output-exists")
    source = options.source
    if source is None:
        head = next(iter(Source(path).chunks()), "")
        source, notes = detect_source(head[:CHUNK])
        for note in notes:
            stats.note(note)
    source, assumed = options.source_reading(source)
    for note in assumed:
        stats.note(note)
    parameters = None
    if options.units and _core.has_parameters(path):
        parameters = analyse_file_parameters(path, source, file=name)
    converter = Converter(options, source, file=name, parameters=parameters, stats=stats,
                          read_units=read_units)
    # One atomic write (formats.files.PendingFile); a dry run writes to the temporary folder.
    given = output  # (as the caller wrote it, in a message)
    if output:
        output = pure(os.fspath(output))
        folder = parent(output)
    else:
        import tempfile  # (a dry run only: the rest of a conversion does not load it)

        folder = tempfile.gettempdir()
    pending = PendingFile(folder, os.path.basename(output) if output else "tapegate",
                          create=make_folder)
    try:
        converter.convert_file(path, source.dialect, pending)
        pending.file.flush()
        if verify:  # (the proof and the diff it reports with: loaded only when asked for)
            from formats.verify import assumed_units, verify_conversion

            verify_conversion(path, pending.tmp, source, options, stats, file=name)
            # decided by the counts alone: the statements the proof could not read, the words
            # the core left as written where the units change
            stats.proved = True
            stats.verified = not stats.not_compared and not stats.left_as_written
            read_in = assumed_units(source, options)
            if read_in:
                stats.verified_assuming = read_in
                stats.note(f"verified with the source read in {read_in}, the source profile's "
                           "units: its control selects them by a machine parameter the program "
                           "does not show, so a program written for a machine set to the other "
                           "units is not proved; give --from-units to say what the machine is "
                           "set to")
    except BaseException:
        pending.discard()
        raise
    if output is None:  # a dry run: nothing is kept
        pending.discard()
        return stats

    target = output

    def refused() -> ConversionError:
        """The output's name taken while it was converted (no --force)."""
        return ConversionError(f"{given} exists; use --force to overwrite it", file=name,
                               code="output-exists")

    def finish() -> None:
        try:
            pending.name_as(target, overwrite=overwrite, version=False,
                            sync_folder=sync_folder)
        except FileExistsError:  # it appeared while converting
            raise refused() from None
        finally:  # (a failed fsync leaves the file open; commit removes it otherwise)
            if not pending.file.closed:
                pending.discard()

    if commit is None:
        finish()
    else:
        commit(Handover(pending, target, overwrite, finish, refused))
    return stats


class Handover:
    """An output converted, handed to ``convert_file``'s ``commit``: its data in ``pending``,
    its name ``target`` (replaced when ``overwrite``); ``finish`` does the commit here
    (:meth:`PendingFile.commit`: the fsync, the rename or link, the temporary file removed on
    a failure; a device or a FIFO written into) and raises what :func:`convert_file` would
    raise; ``refused`` makes the error of a name taken meanwhile (a commit's
    FileExistsError)."""

    __slots__ = ("pending", "target", "overwrite", "finish", "refused")

    def __init__(self, pending: PendingFile, target: str, overwrite: bool,
                 finish: Callable[[], None], refused: Callable[[], ConversionError]) -> None:
        self.pending, self.target, self.overwrite = pending, target, overwrite
        self.finish, self.refused = finish, refused


def sync_folders(outputs: Iterable[str]) -> None:
    """fsync the folders of ``outputs`` once each: the names a batch gave, on disk (each
    file's data was fsync'd before its rename)."""
    from formats.files import sync_folder

    for folder in sorted({os.path.dirname(os.path.abspath(o)) for o in outputs}):
        sync_folder(folder)


def convert_text(text: str, options: ConvertOptions, *, file: str | None = None
                 ) -> tuple[str, ConvertStats]:
    """Convert a program held in memory (tests, small programs)."""
    source = options.source
    notes: list[str] = []
    if source is None:
        source, notes = detect_source(text)
    source, assumed = options.source_reading(source)
    notes.extend(assumed)
    parameters = None
    if options.units and has_parameters(text):
        parameters = analyse_parameters([text], source, file=file)

    def attempt(read_units: list[tuple[int, str, str]]) -> tuple[str, ConvertStats]:
        stats = ConvertStats(file=file or "<text>", notes=list(notes))
        converter = Converter(options, source, file=file, parameters=parameters, stats=stats,
                              read_units=read_units)
        return "".join(converter.convert_stream([text], source.dialect)), stats

    return with_rereads(attempt)

