"""The checker: a program against a machine profile, rule by rule (:mod:`postproc.rules`).

Every rule is the Rust core's (``crates/core/src/check.rs``): one pass over the blocks in flat
memory, with the one modal state machine of the core giving the state before and after every
block. This module hands it the profile's compiled machine (:func:`formats.machine.machine`,
built once per profile), feeds it the program --
whole lines of text a chunk at a time, or :class:`~formats.model.Block` objects -- and turns what
it finds into :class:`~postproc.findings.Finding` tuples, streamed as they are found; the
program-level ones (start, end) come when the program ends. A checker made with a ``report``
format (``text``, ``json``, ``jsonl``) has the core write its findings as that report prints them
(``crates/core/src/report.rs``) through a ``write`` callable, and only count them
(:meth:`Checker.report_file`).
"""

from __future__ import annotations

from itertools import chain

from formats import _core
from formats.records import NEW, Record, field, new, record
from postproc import rules
from postproc.findings import Finding, make_finding
from postproc.rules import TAPE_CHARACTER, TAPE_PARITY

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from collections.abc import Callable, Iterable, Iterator
    from decimal import Decimal
    from typing import Any

    from formats.model import Block
    from formats.parser import Dialect
    from formats.profile import Profile
    from formats.profile_cache import Compiled
    from formats.source import Source
    from formats.tape import TapeIssue

__all__ = ["CheckStats", "Checker", "Drawn", "Finding", "Segment", "check_file", "check_text",
           "iter_check_file"]



@record
class Segment(Record):
    """One move, for the backplot: rapid, feed or arc (with its centre and direction), as the
    core's path has it -- an arc by I J K, R or CR= alike; "chord" is an arc by a radius shorter
    than half its chord (TG410), which no arc can be. Positions as programmed (a lathe's X, and
    its centre's, a diameter)."""

    kind: str  # rapid | feed | arc | chord
    start: tuple[float, float, float]
    end: tuple[float, float, float]
    line: int
    centre: tuple[float, float, float] | None = None
    clockwise: bool = False
    plane: int = 17
    large: bool = False  # the arc turns through more than 180 degrees

    def __init__(self, kind: str, start: tuple[float, float, float],
                 end: tuple[float, float, float], line: int,
                 centre: tuple[float, float, float] | None = None, clockwise: bool = False,
                 plane: int = 17, large: bool = False) -> None:
        self.kind = kind
        self.start = start
        self.end = end
        self.line = line
        self.centre = centre
        self.clockwise = clockwise
        self.plane = plane
        self.large = large


@record
class Drawn(Record):
    """What the backplot needs beyond the path (the core's ``check::Drawn``, gathered in the
    checker's pass): the units of the moves drawn (empty: no move), by line the axes (0 X,
    1 Y, 2 Z) a block moves whose position before it is unknown (the program's start, a
    reference return, a shift), the lines that move to or through the reference point or in
    machine coordinates (G28 G30 G53), the blocks that shift, rotate, scale or mirror the
    coordinates, which the picture does not apply: the first few (line, code) and their
    count, and by line the axes a move does not name that the program had set and has lost
    (after a shift, a skip, a call: a view showing one of them does not draw the move)."""

    units: set[str]
    unknown: dict[int, set[int]]
    machine: set[int]
    transforms: list[tuple[int, str]] = field(default_factory=list)
    transform_count: int = 0
    adrift: dict[int, set[int]] = field(default_factory=dict)

    def __init__(self, units: set[str], unknown: dict[int, set[int]], machine: set[int],
                 transforms: list[tuple[int, str]] = NEW, transform_count: int = 0,
                 adrift: dict[int, set[int]] = NEW) -> None:
        self.units = units
        self.unknown = unknown
        self.machine = machine
        self.transforms = new(transforms, list)
        self.transform_count = transform_count
        self.adrift = new(adrift, dict)


@record
class CheckStats(Record):
    """What a check measured of a program: extents, path lengths, time, tools, travel."""

    blocks: int = 0
    arcs: int = 0
    low: dict[str, Decimal] = field(default_factory=dict)
    high: dict[str, Decimal] = field(default_factory=dict)
    rapid_length: float = 0.0
    feed_length: float = 0.0
    seconds: float = 0.0
    tools: list[int] = field(default_factory=list)
    units: str = "metric"
    # The travel check: moves of an axis with limits, how many were compared as machine
    # positions through the profile's work offsets, and why the others were not (each once)
    travel_moves: int = 0
    travel_absolute: int = 0
    travel_not: list[str] = field(default_factory=list)
    work_offsets: bool = False  # the profile gives work offsets
    # From which line the moves are not known and why (a G code the family's list lacks)
    moves_not_known: list[str] = field(default_factory=list)
    # Dwells whose time is not known, left out of ``seconds``: how many, and why (each kind
    # once, at its first line): SINUMERIK's G4 S, a FANUC or Haas X or U without a point under G20
    dwells_not_counted: int = 0
    dwells_not_known: list[str] = field(default_factory=list)

    def __init__(self, blocks: int = 0, arcs: int = 0, low: dict[str, Decimal] = NEW,
                 high: dict[str, Decimal] = NEW, rapid_length: float = 0.0,
                 feed_length: float = 0.0, seconds: float = 0.0, tools: list[int] = NEW,
                 units: str = "metric", travel_moves: int = 0, travel_absolute: int = 0,
                 travel_not: list[str] = NEW, work_offsets: bool = False,
                 moves_not_known: list[str] = NEW, dwells_not_counted: int = 0,
                 dwells_not_known: list[str] = NEW) -> None:
        self.blocks = blocks
        self.arcs = arcs
        self.low = new(low, dict)
        self.high = new(high, dict)
        self.rapid_length = rapid_length
        self.feed_length = feed_length
        self.seconds = seconds
        self.tools = new(tools, list)
        self.units = units
        self.travel_moves = travel_moves
        self.travel_absolute = travel_absolute
        self.travel_not = new(travel_not, list)
        self.work_offsets = work_offsets
        self.moves_not_known = new(moves_not_known, list)
        self.dwells_not_counted = dwells_not_counted
        self.dwells_not_known = new(dwells_not_known, list)


class Checker:
    """Checks one program. ``select`` / ``ignore`` are rule IDs or prefixes (``TG4``).
    ``report``: the findings are written as that report (``text``, ``json``, ``jsonl``) prints
    them, by :meth:`report_file` and :meth:`report_stream`, and counted (:attr:`counts`), not
    made into tuples. ``stats=False``: no :attr:`stats` (asking raises ValueError), and the
    moves' extents, lengths and time are not worked out, a cost on every move that only a
    report of them (``check --stats``) reads; the findings are the same. ``fold`` (a ``text``
    report, as ``check`` writes it without ``--all``): of each rule's warnings and notes in
    the file the first five are written, and at the end of :meth:`report_file` (and of
    :meth:`report_stream`) one line for the rest, at the first one left out, with their number
    and lines; every error is written (the core's ``report::Writer::folded``); the counts are
    of every finding."""

    def __init__(self, profile: Profile | Compiled, file: str = "<input>", *,
                 select: Iterable[str] = (), ignore: Iterable[str] = (),
                 record_path: bool = False, report: str | None = None,
                 stats: bool = True, fold: bool = False) -> None:
        self.profile = profile
        self.file = file
        self.select = tuple(select)
        self.ignore = tuple(ignore)
        self.record_path = record_path
        self.report = report
        # a built-in profile as the cache keeps it for a check (formats.profile_cache.Compiled:
        # its machine and its dialect's flags, without formats.profile's modules), or a profile
        compiled = getattr(profile, "compiled", None)
        if compiled is not None:
            built, self._flags = compiled()
        else:
            from formats.machine import machine

            built = machine(profile)  # type: ignore[arg-type]  # (a Profile: no compiled)
            self._flags = profile.dialect.flags
        self._core = _core.Checker(built, list(self.select), list(self.ignore),
                                   record_path, file, make_finding, report, stats, fold)

    # -- findings ------------------------------------------------------------------------------

    def enabled(self, rule: str) -> bool:
        """Whether this run reports ``rule``: the core's selection (``--select``/``--ignore``),
        the one the rules it checks itself are held to."""
        return self._core.enabled(rule)

    # -- the walk ------------------------------------------------------------------------------

    def run(self, blocks: Iterable[Block]) -> Iterator[Finding]:
        """Findings for a program's blocks, then the program-level ones."""
        return chain.from_iterable(self._batches_of(blocks))

    def run_stream(self, chunks: Iterable[str], dialect: Dialect) -> Iterator[Finding]:
        """Findings for a program arriving as text chunks (the way files are checked): the
        core reads whole lines a chunk at a time, with no Python object per block."""
        return chain.from_iterable(self._batches(chunks, dialect))

    def report_stream(self, chunks: Iterable[str], dialect: Dialect,
                      write: Callable[[str], object]) -> None:
        """Check a program arriving as text chunks, its findings written as the checker's
        ``report`` prints them, by the core, through ``write`` about 64 KiB at a time (a
        chunk's findings are never held whole), then a folded report's lines for the findings
        it left out (``fold``); what ``write`` raises stops the check."""
        for _ in self._batches(chunks, dialect, write):
            pass
        self._core.end(write, False)

    def report_file(self, path: str, write: Callable[[Any], object], raw: bool = False
                    ) -> None:
        """Check a text file or tape image as :func:`iter_check_file` does, the findings
        written as :meth:`report_stream` writes them; the tape's findings last, then a folded
        report's lines for the findings it left out (``fold``). A text file is
        read, and checked, by the core with the GIL released (``Checker.check_file``: the
        threads of ``check -j`` take it only to hand over the report's slices); a tape image,
        and the text after the last LF where the core leaves it (a last line without its LF,
        a line past ``MAX_BLOCK``), are read here as :meth:`report_stream` reads them. With
        ``raw``, the core's slices are handed over as bytes (a report written to a binary
        buffer: :attr:`postproc.report.JsonReport.raw`); what Python writes stays ``str``."""
        done = self._core.check_file(path, self._flags, write, raw)
        if done is None:  # a tape image, or a head that is not UTF-8: Source reads it
            from formats.source import Source  # (with the tape's module: only here)

            dialect = self.profile.dialect
            source = Source(path)
            for _ in self._batches(source.chunks(), dialect, write):
                pass
            tape = self.report_tape(source.issues)
            if tape:
                write(tape)
        elif done is not True:  # the text after the last LF: as _batches reads it
            from formats.parser import CHUNK, decode_chunks, parse_stream, read_chunks

            dialect = self.profile.dialect
            rest, at = done
            unread = iter(()) if at is None else decode_chunks(read_chunks(path, CHUNK, at))
            for _ in self._batches_of(parse_stream(
                    chain([rest], unread), dialect, file=self.file, errors="collect",
                    first_line=self._core.line), write):
                pass
        self._core.end(write, raw)

    @property
    def counts(self) -> dict[str, int]:
        """The findings written by :meth:`report_stream` and :meth:`report_tape`, by
        severity."""
        counts: dict[str, int] = self._core.counts
        return counts

    def _batches(self, chunks: Iterable[str], dialect: Dialect,
                 *write: Callable[[str], object]) -> Iterator[Any]:
        """The findings a chunk at a time (passed on by ``chain``, in C: there can be
        millions); with ``write`` (a checker with a ``report``), written through it, and
        nothing yielded but a None a chunk."""
        from formats.parser import parse_stream, whole_texts

        flags = dialect.flags
        line: int | None = 0  # then None: the core goes on after the last line it read
        for text, unread in whole_texts(chunks):
            if unread is None:
                yield self._core.check_lines(text[:-1], line, flags, *write)
                line = None
            else:
                yield from self._batches_of(parse_stream(
                    chain([text], unread), dialect, file=self.file, errors="collect",
                    first_line=self._core.line if line is None else line), *write)

    def _batches_of(self, blocks: Iterable[Block],
                    *write: Callable[[str], object]) -> Iterator[Any]:
        """The findings of each block, then those of the program's end."""
        check = self._core.check_block
        for block in blocks:
            found = check(block, *write)
            if found:
                yield found
        yield self._core.finish(*write)

    def tape(self, issues: Iterable[TapeIssue]) -> Iterator[Finding]:
        for issue in issues:
            rule = TAPE_PARITY if issue.kind == "parity" else TAPE_CHARACTER
            if self.enabled(rule):
                r = rules.RULES[rule]
                yield Finding(rule, r.severity, f"{issue.message()} at byte {issue.offset}",
                              self.file, issue.line, issue.column, r.clause)

    def report_tape(self, issues: Iterable[TapeIssue]) -> str:
        """The tape's findings as :meth:`report_stream` writes the others (returned), and
        counted."""
        rendered: str = self._core.render(list(self.tape(issues)))
        return rendered

    # -- what the walk gathered ----------------------------------------------------------------

    @property
    def stats(self) -> CheckStats:
        s = self._core.stats
        return CheckStats(blocks=s["blocks"], arcs=s["arcs"], low=s["low"], high=s["high"],
                          rapid_length=s["rapid_length"], feed_length=s["feed_length"],
                          seconds=s["seconds"], tools=s["tools"], units=s["units"],
                          travel_moves=s["travel_moves"], travel_absolute=s["travel_absolute"],
                          travel_not=s["travel_not"],
                          work_offsets=bool(self.profile.work_offsets),
                          moves_not_known=s["moves_not_known"],
                          dwells_not_counted=s["dwells_not_counted"],
                          dwells_not_known=s["dwells_not_known"])

    @property
    def drawn(self) -> Drawn | None:
        """What the backplot needs beyond the path, gathered in the same pass (None unless
        the checker was made with ``record_path``)."""
        if not self.record_path:
            return None
        units, unknown, machine, transforms, count, adrift = self._core.drawn

        def by_line(pairs: list[tuple[int, int]]) -> dict[int, set[int]]:
            return {line: {n for n in range(3) if axes >> n & 1} for line, axes in pairs}

        return Drawn(set(units), by_line(unknown), set(machine), transforms, count,
                     by_line(adrift))

    @property
    def path(self) -> list[Segment] | None:
        """The moves, for the backplot (None unless the checker was made with
        ``record_path``)."""
        if not self.record_path:
            return None
        return [Segment(*move) for move in self._core.path]


def check_text(text: str, profile: Profile, *, file: str = "<input>",
               select: Iterable[str] = (), ignore: Iterable[str] = ()) -> list[Finding]:
    checker = Checker(profile, file, select=select, ignore=ignore)
    return list(checker.run_stream([text], profile.dialect))


def iter_check_file(path: str, profile: Profile, *, display: str | None = None,
                    select: Iterable[str] = (), ignore: Iterable[str] = (),
                    record_path: bool = False, stats: bool = True
                    ) -> tuple[Checker, Iterator[Finding]]:
    """Check a text file or tape image, findings streamed as they are found (flat memory);
    tape parity findings come last, once the whole image has been decoded. ``stats``: as
    :class:`Checker`'s."""
    from formats.source import Source

    name = display or path
    checker = Checker(profile, name, select=select, ignore=ignore, record_path=record_path,
                      stats=stats)
    source = Source(path)
    open(path, "rb").close()  # an unreadable file fails here, before any output

    return checker, chain(checker.run_stream(source.chunks(), profile.dialect),
                          _tape_findings(checker, source))


def _tape_findings(checker: Checker, source: Source) -> Iterator[Finding]:
    """The tape's findings, made once the whole image has been read."""
    yield from checker.tape(source.issues)


def check_file(path: str, profile: Profile, *, display: str | None = None,
               select: Iterable[str] = (), ignore: Iterable[str] = (),
               record_path: bool = False) -> tuple[Checker, list[Finding]]:
    """Check a file and keep the findings, tape errors first, then the rules in order."""
    checker, found = iter_check_file(path, profile, display=display, select=select,
                                     ignore=ignore, record_path=record_path)
    findings = list(found)
    tape = [f for f in findings if f.rule in (TAPE_PARITY, TAPE_CHARACTER)]
    return checker, tape + [f for f in findings if f.rule not in (TAPE_PARITY, TAPE_CHARACTER)]
