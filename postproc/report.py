"""Findings out: compiler-style text, JSON and JSON Lines for scripts, SARIF 2.1.0 for CI and
code review.

Every format is written as the checker finds, finding by finding: the memory of a report does
not grow with the number of findings (a real program can have a million). A finding in text,
JSON and JSON Lines is written by the core (``crates/core/src/report.rs``): a checker made with
the report's format hands its findings to the report's ``write`` about 64 KiB at a time
(:meth:`postproc.check.Checker.report_file`), and findings made in Python are written by
``_core.render_findings``. This module writes what comes once per document. The JSON and
SARIF documents are laid out exactly as ``json.dumps(document, indent=2)`` would print them, and
whatever is only known at the end comes last:

- text: a line per finding, ``file:line:column: severity rule message [clause]``.
- JSON: ``{"findings": [...], "stats": {...}}`` -- the stats follow the findings.
- JSON Lines: a line per finding, as ``json.dumps(finding)`` writes it, then a line per file's
  stats.
- SARIF: the run's ``results`` come before its ``tool`` (a JSON object's members have no order),
  so the rule descriptors (``tool.driver.rules``) can describe exactly the rules used, in the
  order they first appear; each result's ``ruleIndex`` is its rule's place in that list.
"""

from __future__ import annotations

from io import StringIO
from itertools import islice

from formats import _core
from postproc import rules
from postproc.check import CheckStats, Finding

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from collections.abc import Callable, Iterable, Iterator, Mapping
    from typing import Any, TextIO

SARIF_SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"
_LEVEL = {"error": "error", "warning": "warning", "info": "note"}
_BATCH = 4096  # findings written by one call of the core


def _batches(findings: Iterable[Finding]) -> Iterator[list[Finding]]:
    it = iter(findings)
    while batch := list(islice(it, _BATCH)):
        yield batch


def text(findings: Iterable[Finding]) -> str:
    return "".join(_core.render_findings("text", batch) for batch in _batches(findings))


_SLICE = 1 << 16  # characters handed to the output at a time


def _sliced(write: Callable[[Any], object], piece: str | bytes, start: int = 0) -> None:
    """``piece[start:]`` written in slices (a batch of findings written by
    ``_core.render_findings`` can be a megabyte). A single write that a closed pipe
    (``| head``) cuts short returns a partial count, which Python's buffered writer does not
    report; the next slice fails with BrokenPipeError, which the command turns into its quiet
    exit. (A checker's own pieces are slices already.)"""
    if len(piece) - start <= _SLICE:
        write(piece[start:] if start else piece)
        return
    for at in range(start, len(piece), _SLICE):
        write(piece[at:at + _SLICE])


def _binary(out: TextIO) -> Callable[[bytes], object] | None:
    """The ``write`` of ``out``'s binary buffer, where a JSON report, all ASCII, goes as the
    core's bytes: the text layer copied each 64 KiB string into bytes again, and a spilled
    piece of ``-j`` was encoded, written, read back and decoded (docs/benchmarks.md, "the
    report as bytes"). None where there is no buffer (a ``StringIO``) or where the stream's
    encoding writes ASCII otherwise; what was written before through the text layer is
    flushed first, so that the two stay in order."""
    buffer = getattr(out, "buffer", None)
    encoding = getattr(out, "encoding", None)
    if buffer is None or not isinstance(encoding, str):
        return None
    import codecs  # (loaded by the interpreter's start)

    try:
        if codecs.lookup(encoding).name not in ("utf-8", "ascii"):
            return None
    except LookupError:
        return None
    out.flush()
    write: Callable[[bytes], object] = buffer.write
    return write


def _pieced(raw: Callable[[bytes], object] | None, write: Callable[[str], object],
            piece: str | bytes, start: int = 0) -> None:
    """A piece of a JSON report, ``str`` or ``bytes`` (ASCII), from ``start``, written in
    slices: as bytes to ``raw`` where there is one, else as text to ``write``."""
    if raw is None:
        _sliced(write, piece if isinstance(piece, str) else piece.decode("ascii"), start)
    else:
        _sliced(raw, piece.encode() if isinstance(piece, str) else piece, start)


class TextReport:
    """The text report's findings, a line each, as the core writes them."""

    raw = False  # (text goes through the stream's own encoding)

    def __init__(self, out: TextIO) -> None:
        self._write = out.write
        self._out = out

    def write(self, piece: str) -> None:
        _sliced(self._write, piece)

    def close(self) -> None:
        self._out.flush()


def _nested(value: Any, indent: int) -> str:
    """``value`` as json.dumps(..., indent=2) prints it ``indent`` spaces deep in a document
    (a JSON string holds no raw newline, so every newline starts a line of the layout)."""
    import json  # (here and below: a text report, the everyday one, does not load json)

    return json.dumps(value, indent=2).replace("\n", "\n" + " " * indent)


class JsonReport:
    """``{"findings": [...], "stats": {...}}`` written to ``out`` finding by finding:
    :meth:`write` the findings as the core writes them (or :meth:`add` a finding), then
    :meth:`close` with the stats (if any), known by then."""

    def __init__(self, out: TextIO) -> None:
        self._out = out
        self._raw = raw = _binary(out)
        self._write: Callable[[str], object] = (out.write if raw is None
                                                else lambda text: raw(text.encode()))
        self._open = False  # a finding has been written: the array is open

    @property
    def raw(self) -> bool:
        """Whether the report goes to the output's binary buffer: then a checker hands its
        slices over as bytes (:meth:`postproc.check.Checker.report_file`'s ``raw``)."""
        return self._raw is not None

    def add(self, f: Finding) -> None:
        self.write(_core.render_findings("json", [f]))

    def write(self, piece: str | bytes) -> None:
        """Findings as the core writes them for this report (a report-format checker's
        pieces, ``_core.render_findings``), added after the ones already written: each is
        written after a comma and a newline, which the document's first drops to open the
        array. A piece is ``str``, or the core's ``bytes`` (ASCII) for a :attr:`raw` report."""
        if not piece:
            return
        # (a piece starts with the ",\n" of its first finding)
        _pieced(self._raw, self._write, piece, 2 if self.open_array() else 0)

    def open_array(self) -> bool:
        """Open the findings' array before the document's first finding: True if it was
        opened now (the finding's leading ",\n" is then to be dropped)."""
        if self._open:
            return False
        self._open = True
        self._write('{\n  "findings": [\n')
        return True

    def close(self, stats: Mapping[str, CheckStats] | None = None) -> None:
        """The end of the document: the findings' array closed, then ``stats`` per file."""
        self._write("\n  ]" if self._open else '{\n  "findings": []')
        if stats:
            body = {name: stats_dict(s) for name, s in stats.items()}
            self._write(',\n  "stats": ' + _nested(body, 2))
        self._write("\n}\n")
        self._out.flush()


class JsonLinesReport:
    """JSON Lines: one finding per line as a compact JSON object (``jq`` and log shippers read
    it line by line), then with ``--stats`` one line ``{"file": ..., "stats": {...}}`` per file.
    Each line is complete when written: a reader can stop anywhere."""

    def __init__(self, out: TextIO) -> None:
        self._out = out
        self._raw = raw = _binary(out)
        self._write: Callable[[str], object] = (out.write if raw is None
                                                else lambda text: raw(text.encode()))

    @property
    def raw(self) -> bool:
        """As :attr:`JsonReport.raw`."""
        return self._raw is not None

    def add(self, f: Finding) -> None:
        self.write(_core.render_findings("jsonl", [f]))

    def write(self, piece: str | bytes) -> None:
        """Findings as the core writes them for this report, a line each (``str``, or the
        core's ``bytes`` for a :attr:`raw` report)."""
        _pieced(self._raw, self._write, piece)

    def close(self, stats: Mapping[str, CheckStats] | None = None) -> None:
        import json

        for name, s in (stats or {}).items():
            self._write(json.dumps({"file": name, "stats": stats_dict(s)}) + "\n")
        self._out.flush()


def artifact_uri(name: str) -> str:
    """A file name as SARIF 2.1.0's ``artifactLocation.uri`` (3.4.3: a URI reference, RFC
    3986): an absolute path a ``file:`` URI (RFC 8089, ``Path.as_uri``), a relative one a
    relative reference with ``/`` between its segments. Every byte a path may hold and a URI
    gives a meaning to -- a blank, ``#``, ``%``, ``?``, a ``:`` that would read as a scheme, a
    byte beyond ASCII (UTF-8) -- is percent-encoded (review 21, finding 4: ``part #2 100%.nc``
    was written as it stands, a path ``part `` and a fragment). A name that is not UTF-8 (a
    byte ``\\xff`` Python holds as the surrogate ``\\udcff``) is quoted by the bytes the file
    system holds (``os.fsencode``), as ``Path.as_uri`` quotes an absolute one: ``p%FF.ngc``
    (review 23, finding 3: a traceback)."""
    import os
    from pathlib import Path
    from urllib.parse import quote

    path = Path(name)
    if path.is_absolute():
        return path.as_uri()
    return quote(os.fsencode(path.as_posix()), safe="/")


class SarifReport:
    """A SARIF 2.1.0 log with one run written to ``out`` result by result: :meth:`add` each
    finding, then :meth:`close` writes the tool with the rules used, described from the
    registry (the run's ``results`` come first, so nothing about them must be known before)."""

    raw = False  # (the findings come as lists, added here)

    def __init__(self, out: TextIO) -> None:
        self._write = out.write
        self._out = out
        self.count = 0
        self._index: dict[str, int] = {}  # rule -> its place in tool.driver.rules
        from json.encoder import encode_basestring_ascii

        self._str = encode_basestring_ascii  # a JSON string, as json.dumps writes it (in C)
        self._file = ""
        self._uri = self._str(artifact_uri(self._file))

    def add(self, f: Finding) -> None:
        index = self._index.get(f.rule)
        if index is None:
            rules.RULES[f.rule]  # a rule the registry cannot describe fails here, not at the end
            index = self._index[f.rule] = len(self._index)
        if f.file != self._file:  # one Path per file, not per finding
            self._file, self._uri = f.file, self._str(artifact_uri(f.file))
        self._write((_SARIF_HEAD + '      "results": [\n' if not self.count else ",\n") +
                    f'        {{\n          "ruleId": {self._str(f.rule)},\n'
                    f'          "ruleIndex": {index},\n'
                    f'          "level": {self._str(_LEVEL[f.severity])},\n'
                    '          "message": {\n'
                    f'            "text": {self._str(f"{f.message} [{f.clause}]")}\n'
                    '          },\n'
                    '          "locations": [\n'
                    '            {\n'
                    '              "physicalLocation": {\n'
                    '                "artifactLocation": {\n'
                    f'                  "uri": {self._uri}\n'
                    '                },\n'
                    '                "region": {\n'
                    f'                  "startLine": {int(f.line)},\n'
                    f'                  "startColumn": {int(f.column)}\n'
                    '                }\n'
                    '              }\n'
                    '            }\n'
                    '          ]\n'
                    '        }')
        self.count += 1

    def close(self) -> None:
        """The end of the log: the results' array closed, then the tool and its rules."""
        self._write("\n      ],\n" if self.count else _SARIF_HEAD + '      "results": [],\n')
        tool = {"driver": {"name": "tapegate", "version": _tool_version(),
                           "rules": [rule_descriptor(rule) for rule in self._index]}}
        self._write('      "tool": ' + _nested(tool, 6) + "\n    }\n  ]\n}\n")
        self._out.flush()


_SARIF_HEAD = (f'{{\n  "$schema": "{SARIF_SCHEMA}",\n  "version": "2.1.0",\n'
               '  "runs": [\n    {\n')


def _tool_version() -> str:
    # imported here: importlib.metadata costs a plain check a sixth of its start-up
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("tapegate")
    except PackageNotFoundError:  # pragma: no cover - running from a source tree
        return "0"


def rule_descriptor(rule: str) -> dict[str, Any]:
    """SARIF's reportingDescriptor of a rule, from the registry."""
    r = rules.RULES[rule]
    return {
        "id": rule,
        "name": rule,
        "shortDescription": {"text": r.title},
        "fullDescription": {"text": f"{r.title} (ISO 6983-1 {r.clause})"},
        "defaultConfiguration": {"level": _LEVEL[r.severity]},
        "properties": {"clause": r.clause},
    }


def write_json(out: TextIO, findings: Iterable[Finding],
               stats: Mapping[str, CheckStats] | None = None) -> int:
    """Stream the JSON report of ``findings`` to ``out``; ``stats`` is read once the findings
    are exhausted (a mapping that fills while they are made is fine). Returns the count."""
    report = JsonReport(out)
    count = 0
    for batch in _batches(findings):
        report.write(_core.render_findings("json", batch))
        count += len(batch)
    report.close(stats)
    return count


def write_json_lines(out: TextIO, findings: Iterable[Finding],
                     stats: Mapping[str, CheckStats] | None = None) -> int:
    """Stream the JSON Lines report of ``findings`` to ``out``, as :func:`write_json`."""
    report = JsonLinesReport(out)
    count = 0
    for batch in _batches(findings):
        report.write(_core.render_findings("jsonl", batch))
        count += len(batch)
    report.close(stats)
    return count


def write_sarif(out: TextIO, findings: Iterable[Finding]) -> int:
    """Stream the SARIF log of ``findings`` to ``out``. Returns the number of results."""
    report = SarifReport(out)
    for f in findings:
        report.add(f)
    report.close()
    return report.count


def as_json(findings: Iterable[Finding], stats: Mapping[str, CheckStats] | None = None) -> str:
    """The JSON report as one string (for a few findings; :func:`write_json` streams)."""
    out = StringIO()
    write_json(out, findings, stats)
    return out.getvalue()


def sarif(findings: Iterable[Finding]) -> str:
    """The SARIF log as one string (for a few findings; :func:`write_sarif` streams)."""
    out = StringIO()
    write_sarif(out, findings)
    return out.getvalue()


def stats_dict(s: CheckStats) -> dict[str, Any]:
    """The statistics as JSON values. The extents are numbers (a JSON reader takes them as
    doubles: exact for the positions of any machine, whose resolution needs far fewer than the
    15 significant digits a double keeps)."""
    return {
        "blocks": s.blocks, "units": s.units, "arcs": s.arcs,
        "bounding_box": {a: [float(s.low[a]), float(s.high[a])] for a in sorted(s.low)},
        "rapid_length": round(s.rapid_length, 3), "feed_length": round(s.feed_length, 3),
        "cycle_time_seconds": round(s.seconds, 1), "tools": s.tools,
        "travel": {"check": "machine positions and span" if s.work_offsets else "span",
                   "moves": s.travel_moves, "compared": s.travel_absolute,
                   "not_compared": s.travel_not},
        "moves_not_known": s.moves_not_known,
        "dwells_not_counted": {"count": s.dwells_not_counted, "why": s.dwells_not_known},
    }


def _travel_text(s: CheckStats) -> list[str]:
    """Which travel check was made: a machinist reading "no TG601" must know whether the
    machine positions were compared or only the span of the program."""
    if not s.work_offsets:
        return ["  travel: the span of each axis against the travel (the profile gives no work "
                "offsets)"]
    lines = [f"  travel: machine positions through the profile's work offsets for "
             f"{s.travel_absolute} of {s.travel_moves} axis moves, and the span of each axis"]
    lines.extend(f"    not compared: {why}" for why in s.travel_not)
    return lines


def stats_text(name: str, s: CheckStats) -> str:
    unit = "in" if s.units == "inch" else "mm"
    lines = [f"{name}: {s.blocks} blocks"]
    for axis in sorted(s.low):
        lines.append(f"  {axis}: {s.low[axis]} to {s.high[axis]} {unit}")
    minutes, seconds = divmod(int(round(s.seconds)), 60)
    lines.append(f"  rapid path {s.rapid_length:.1f} {unit}, feed path {s.feed_length:.1f} {unit} "
                 f"({s.arcs} arc{' at its' if s.arcs == 1 else 's at their'} true length)")
    lines.append(f"  estimated cycle time {minutes} min {seconds:02d} s "
                 "(feeds, the profile's rapid rate, dwells)")
    lines.extend(f"  moves not known {why}" for why in s.moves_not_known)
    if s.dwells_not_counted:
        n = s.dwells_not_counted
        lines.append(f"  {n} dwell{'s' if n > 1 else ''} not in the cycle time, "
                     f"{'their' if n > 1 else 'its'} time not known:")
        lines.extend(f"    {why}" for why in s.dwells_not_known)
    lines.append(f"  tools: {', '.join(f'T{t}' for t in s.tools) or 'none'}")
    lines.extend(_travel_text(s))
    return "\n".join(lines) + "\n"
