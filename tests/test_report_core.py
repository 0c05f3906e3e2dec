"""The check's text, JSON and JSON Lines findings are written by the core
(``crates/core/src/report.rs``) byte for byte as the Python writer it replaced wrote them: on every
real program of ``shared/corpus`` and ``shared/corpus/shops`` (skipped where it is absent), and on
any message, whatever its characters, exactly as ``json.dumps`` escapes them."""

from __future__ import annotations

import importlib.util
import json
import sys
import tracemalloc
from collections import Counter
from collections.abc import Iterable
from io import StringIO
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from formats import _core
from formats.parser import MAX_BLOCK
from formats.profile import load_profile
from formats.tape import encode, iso_byte
from postproc import report
from postproc.check import Checker, iter_check_file
from postproc.findings import Finding
from postproc.rules import RULES, TAPE_PARITY

from .conftest import CORPUS, corpus_files

ROOT = Path(__file__).resolve().parents[1]
SHOPS = CORPUS / "shops"
SLICE = 1 << 16  # what the core's checker hands to write at a time (crates/python/src/checker.rs)

# -- the Python writer as it was before the core wrote the findings (postproc/report.py) --------

_str = json.encoder.encode_basestring_ascii


def old_text(f: Finding) -> str:
    return (f"{f.file}:{f.line}:{f.column}: {f.severity} {f.rule} {f.message} "
            f"[{f.clause}]\n")


def old_json(f: Finding) -> str:
    """A finding in the JSON document, after the ",\\n" that separates it from the one before
    (``JsonReport.add`` for every finding but the first)."""
    return (",\n" +
            f'    {{\n      "rule": {_str(f.rule)},\n'
            f'      "severity": {_str(f.severity)},\n'
            f'      "message": {_str(f.message)},\n'
            f'      "file": {_str(f.file)},\n'
            f'      "line": {int(f.line)},\n'
            f'      "column": {int(f.column)},\n'
            f'      "clause": {_str(f.clause)}\n    }}')


def old_jsonl(f: Finding) -> str:
    return (f'{{"rule": {_str(f.rule)}, "severity": {_str(f.severity)}, '
            f'"message": {_str(f.message)}, "file": {_str(f.file)}, '
            f'"line": {int(f.line)}, "column": {int(f.column)}, '
            f'"clause": {_str(f.clause)}}}\n')


OLD = {"text": old_text, "json": old_json, "jsonl": old_jsonl}


def old(fmt: str, findings: Iterable[Finding]) -> str:
    return "".join(OLD[fmt](f) for f in findings)


# -- every real program -------------------------------------------------------------------------

def _shops() -> dict[str, str]:
    """Each shops program's family profile (``benchmarks/shops.py``), iso-mill where the
    family has none."""
    if not (SHOPS / "families.tsv").is_file():
        return {}
    spec = importlib.util.spec_from_file_location("shops", ROOT / "benchmarks" / "shops.py")
    assert spec and spec.loader
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # its dataclass looks its module up
    spec.loader.exec_module(module)
    return {name: module.profile_for(family, description) or "iso-mill"
            for name, family, description in module.entries(SHOPS)}


SHOP_PROFILES = _shops()
PROGRAMS = ([(p, "iso-mill") for p in corpus_files()]
            + [(SHOPS / name, profile) for name, profile in sorted(SHOP_PROFILES.items())
               if (SHOPS / name).is_file()])


@pytest.mark.skipif(not PROGRAMS, reason="shared/corpus is not present")
@pytest.mark.parametrize(("path", "profile"), PROGRAMS,
                         ids=[f"{p.parent.name}/{p.name}" for p, _ in PROGRAMS])
def test_every_real_program_is_reported_as_the_python_writer_did(path, profile):
    prof = load_profile(profile)
    checker, found = iter_check_file(str(path), prof)
    findings = list(found)
    severities = Counter(f.severity for f in findings)
    for fmt in ("text", "json", "jsonl"):
        core = Checker(prof, str(path), report=fmt)
        written: list[str] = []
        core.report_file(str(path), written.append)
        assert all(written), "no empty piece is handed over"
        assert max(map(len, written), default=0) < SLICE + 2000  # a slice and a finding at most
        assert "".join(written) == old(fmt, findings)
        assert core.counts == {s: severities[s] for s in ("error", "warning", "info")}
        # the same, the core's slices as the bytes written (what Python reads after them, a
        # last line without its LF, a tape image, stays str)
        raw = Checker(prof, str(path), report=fmt)
        pieces: list[bytes | str] = []
        raw.report_file(str(path), pieces.append, raw=True)
        kinds = [type(piece) for piece in pieces]
        assert kinds == sorted(kinds, key=lambda kind: kind is str)
        assert b"".join(p if isinstance(p, bytes) else p.encode("utf-8", "surrogatepass")
                        for p in pieces) == "".join(written).encode("utf-8", "surrogatepass")
        assert core.stats == checker.stats


def test_the_corpus_gives_findings_enough_to_compare():
    if not PROGRAMS:
        pytest.skip("shared/corpus is not present")
    total = 0
    rules = set()
    for path, profile in PROGRAMS[:40]:
        _, found = iter_check_file(str(path), load_profile(profile))
        for f in found:
            total += 1
            rules.add(f.rule)
    assert total > 10_000 and len(rules) > 20


def test_a_tape_image_and_a_line_the_core_cannot_read_are_written_by_the_core(tmp_path):
    """A tape's parity findings (made in Python) and a block read by the Python parser (the
    core's check_block) are written as the rest, and counted."""
    tape = bytearray(encode("%\nN1 G71\nN2 G01 X10 F100\nN3 M30\n%\n", "iso", leader=5))
    tape[tape.index(iso_byte("X"))] ^= 0x80
    (tmp_path / "p.tap").write_bytes(bytes(tape))
    # the last line without its end of block, and a block longer than any: both are read by
    # the Python parser and checked by the core's check_block
    (tmp_path / "last.nc").write_text("%\nN1 G71\nN2 G00 X1 Y\nN3 (\u00e9\"\\) X1 $")
    (tmp_path / "long.nc").write_text("%\nN1 G71\nN2 X1" + "1" * (MAX_BLOCK + 10))
    prof = load_profile("iso-mill")
    for name in ("p.tap", "last.nc", "long.nc"):
        path = str(tmp_path / name)
        _, found = iter_check_file(path, prof, display="shown \"name\".nc")
        findings = list(found)
        assert findings
        for fmt in ("text", "json", "jsonl"):
            core = Checker(prof, "shown \"name\".nc", report=fmt)
            written: list[str] = []
            core.report_file(path, written.append)
            assert "".join(written) == old(fmt, findings)
            assert sum(core.counts.values()) == len(findings)
    assert any(f.rule == TAPE_PARITY for f in iter_check_file(str(tmp_path / "p.tap"), prof)[1])
    assert any("longer than" in f.message
               for f in iter_check_file(str(tmp_path / "long.nc"), prof)[1])


# -- any message ---------------------------------------------------------------------------------

# Every character Python strings hold: quotes, backslashes, control characters, DEL, non-ASCII,
# beyond the BMP, and lone surrogates (a file name that is not UTF-8, read with surrogateescape)
odd = st.text(st.characters() | st.sampled_from(
    ['"', "\\", "\x00", "\x1f", "\x7f", "\x80", "\u2028", "\ud800", "\udcff", "\U0001f600",
     "\b", "\f", "\n", "\r", "\t", "/"]), max_size=20)
findings = st.lists(st.builds(
    Finding, st.sampled_from(sorted(RULES)), st.sampled_from(["error", "warning", "info"]),
    odd, odd, st.integers(0, 10**12), st.integers(0, 10**6), odd), max_size=6)


@settings(max_examples=300, deadline=None)
@given(findings)
def test_any_message_is_escaped_as_json_dumps_escapes_it(found):
    for fmt in ("text", "json", "jsonl"):
        assert _core.render_findings(fmt, found) == old(fmt, found)
    for f in found:
        line = _core.render_findings("jsonl", [f])
        assert line == json.dumps(f._asdict()) + "\n"
        assert json.loads(line) == f._asdict()
        assert str(f) + "\n" == old_text(f)
    out = StringIO()
    assert report.write_json(out, found) == len(found)
    document = out.getvalue()
    assert document == json.dumps({"findings": [f._asdict() for f in found]}, indent=2) + "\n"


@settings(max_examples=100, deadline=None)
@given(odd)
def test_a_file_named_with_any_characters_is_written_as_python_wrote_it(name):
    """The checker's own writer takes the file's name once, as UTF-16 code units."""
    prof = load_profile("iso-mill")
    program = "%\nN1 G71\nN2 G00 G90 X1 \u00e9\nN3 X1 Y\n"
    findings = list(Checker(prof, name).run_stream([program], prof.dialect))
    assert len(findings) >= 3
    for fmt in ("text", "json", "jsonl"):
        checker = Checker(prof, name, report=fmt)
        written: list[str] = []
        checker.report_stream([program], prof.dialect, written.append)
        assert "".join(written) == old(fmt, findings)


def test_a_bad_report_format_or_finding_is_refused_clearly():
    with pytest.raises(ValueError, match="no report format 'xml': text, json or jsonl"):
        _core.render_findings("xml", [])
    with pytest.raises(ValueError, match="a finding has 7 fields"):
        _core.render_findings("json", [("TG101", "error")])
    with pytest.raises(TypeError):
        _core.render_findings("json", [("TG101", "error", 5, "f.nc", 1, 1, "4")])
    with pytest.raises(OverflowError):
        _core.render_findings("json", [("TG101", "error", "m", "f.nc", -1, 1, "4")])
    prof = load_profile("iso-mill")
    with pytest.raises(ValueError, match="no report format 'sarif'"):
        Checker(prof, "f.nc", report="sarif")
    with pytest.raises(ValueError, match="made without a report format"):
        Checker(prof, "f.nc")._core.render([])
    with pytest.raises(ValueError, match="made without a report format"):
        Checker(prof, "f.nc")._core.finish(print)
    with pytest.raises(ValueError, match="give it write"):
        Checker(prof, "f.nc", report="json")._core.finish()
    assert _core.render_findings("text", []) == ""


def test_what_write_raises_stops_the_check_and_what_was_written_is_counted(tmp_path):
    """A closed output (BrokenPipeError from write) leaves the core at once; the findings
    handed over are counted, no more."""
    program = tmp_path / "many.nc"
    program.write_text("%\nN1 G71\n" + "".join(f"N{i} G00 G90 X1\n" for i in range(2, 20_002)))
    written: list[str] = []

    def write(piece: str) -> None:
        if written:
            raise BrokenPipeError(32, "Broken pipe")
        written.append(piece)

    checker = Checker(load_profile("iso-mill"), "many.nc", report="jsonl")
    with pytest.raises(BrokenPipeError):
        checker.report_file(str(program), write)
    assert len(written) == 1 and len(written[0]) >= SLICE
    # counted: the findings handed to write, the slice it refused included, and no more
    lines = written[0].count("\n")
    assert lines < sum(checker.counts.values()) <= 2 * lines + 5


def test_a_chunk_of_findings_is_never_held_whole(tmp_path):
    """A program with a finding on every word: the report's memory is a slice, not the
    chunk's findings (before, the core handed a chunk's findings over as one list)."""
    program = tmp_path / "heavy.nc"
    program.write_text("%\nN1 G71\n" + "".join(f"N{i} G00 G90 X1.123456789 Y2.123456789\n"
                                               for i in range(2, 60_002)))
    sizes: list[int] = []
    checker = Checker(load_profile("fanuc-mill"), "heavy.nc", report="json")
    tracemalloc.start()
    try:
        checker.report_file(str(program), lambda piece: sizes.append(len(piece)))
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert sum(checker.counts.values()) > 150_000 and sum(sizes) > 40_000_000
    assert max(sizes) < SLICE + 2000
    assert peak < 8_000_000, f"peak {peak / 1e6:.1f} MB"


# -- the core's reading of a file (Checker.check_file) -------------------------------------------

CHUNK = 1 << 20  # formats.parser.CHUNK: what each read takes, in Python and in the core


def _edge_programs() -> dict[str, bytes]:
    """Text files whose reading turns on the chunks: what the core reads must be what
    ``formats.source`` and ``whole_texts`` read (each chunk cut at its last LF, the rest
    carried, a rest past MAX_BLOCK characters at a chunk's end handed to the Python parser)."""
    line = b"N10 G01 G90 X1.5 Y2 F100 (a)\n"
    body = line * (CHUNK // len(line) + 1)

    def before(room: int) -> bytes:  # whole lines ending ``room`` bytes before a chunk's end
        return body[:body.rfind(b"\n", 0, CHUNK - room) + 1]

    start = b"%\nN1 G71\n"
    cut = before(70_001)
    return {
        "empty.nc": b"",
        "no-last-lf.nc": start + line * 50 + b"N9 G00 X1 Y",
        "crlf.nc": (start + line * 50).replace(b"\n", b"\r\n"),
        # undecodable bytes past the head, in the second chunk, and a character cut at the
        # first chunk's end
        "bytes.nc": start + before(1)[len(start):] + b"(\xe2\x80\x94)" + line
        + b"(\xff\xfe \xe2\x82)\n" + line * 10,
        # a line across the chunks' end, longer than MAX_BLOCK in bytes but not in characters
        "wide.nc": before(70_000) + b"(" + "\u00e4".encode() * 60_000 + b")\n" + line,
        # longer than MAX_BLOCK characters at the chunk's end: the Python parser's BadBlock,
        # and the file not read beyond it
        "overflow.nc": before(70_000) + b"(" + b"Y" * 100_000 + b")\n" + line,
        "overflow-cut.nc": cut + b"(" + b"Y" * (CHUNK - len(cut) - 2) + "\u2014".encode()
        + b"Z)\n" + line,
        "long-last.nc": start + line * 50 + b"X" * (MAX_BLOCK + 10),
    }


@pytest.mark.parametrize("name", sorted(_edge_programs()))
def test_the_cores_reading_of_a_file_is_pythons(tmp_path, name):
    from formats.source import Source

    path = tmp_path / name
    path.write_bytes(_edge_programs()[name])
    prof = load_profile("fanuc-mill")
    for fmt in ("text", "json", "jsonl"):
        python = Checker(prof, name, report=fmt)
        expected: list[str] = []
        python.report_stream(Source(str(path)).chunks(), prof.dialect, expected.append)
        core = Checker(prof, name, report=fmt)
        written: list[str] = []
        core.report_file(str(path), written.append)
        assert "".join(written) == "".join(expected)
        assert core.counts == python.counts
        assert all(written) and max(map(len, written), default=0) < SLICE + 2000
    assert sum(python.counts.values()) > 0


def test_the_core_reads_only_what_python_reads_as_text(tmp_path):
    """check_file leaves a tape image, and a head that is not UTF-8, to formats.source, having
    written nothing; it reads a file to its end (True), or hands back the text after the
    last LF and where the unread bytes begin."""
    prof = load_profile("fanuc-mill")
    tape = tmp_path / "p.tap"
    tape.write_bytes(encode("%\nN1 G71\nN2 G01 X10 F100\nN3 M30\n%\n", "iso", leader=5))
    latin = tmp_path / "latin.nc"
    latin.write_bytes(b"(Fr\xe4sen)\nN1 G71\nN2 X1\n")
    whole = tmp_path / "whole.nc"
    whole.write_bytes(b"%\nN1 G71\nN2 X1\n")
    last = tmp_path / "last.nc"
    last.write_bytes(b"%\nN1 G71\n" + b"N2 X1\n" * 12_000 + b"N3 X\xff2")  # past the head
    programs = _edge_programs()
    over = tmp_path / "over.nc"
    over.write_bytes(programs["overflow-cut.nc"])
    flags = prof.dialect.flags
    for path, answer in ((tape, None), (latin, None), (whole, True),
                         (last, ("N3 X\udcff2", None))):
        written: list[str] = []
        core = Checker(prof, path.name, report="json")._core
        assert core.check_file(str(path), flags, written.append) == answer
        assert (written == []) == (answer is None)
        assert core.line == (0 if answer is None else 3 if answer is True else 12_002)
    rest, at = Checker(prof, "o", report="json")._core.check_file(str(over), flags, print)
    # the rest as decoded so far: the first byte of the dash, cut at the chunk's end, is read
    # again from ``at``
    assert at == CHUNK - 1 and rest == "(" + "Y" * (len(rest) - 1) and len(rest) > MAX_BLOCK


def test_a_file_that_cannot_be_read_is_pythons_oserror(tmp_path):
    prof = load_profile("fanuc-mill")
    core = Checker(prof, "x", report="text")._core
    with pytest.raises(FileNotFoundError) as missing:
        core.check_file(str(tmp_path / "nowhere.nc"), prof.dialect.flags, print)
    assert missing.value.strerror == "No such file or directory" and missing.value.errno == 2
    with pytest.raises(IsADirectoryError) as folder:
        core.check_file(str(tmp_path), prof.dialect.flags, print)
    assert folder.value.strerror == "Is a directory"
    with pytest.raises(ValueError, match="made without a report format"):
        Checker(prof, "x")._core.check_file(str(tmp_path), prof.dialect.flags, print)


# pieces of a line: words, undecodable bytes, a multi-byte character (cut wherever a chunk ends
# in it), ends of block, and runs long enough to carry a line past a chunk's end or MAX_BLOCK
_piece = st.sampled_from([b"N10 G01 X1.5 Y2 F100", b" ", b"\n", b"\r\n", b"(", b")", b"\xff",
                          b"\xe2\x82", "\u2014".encode(), "\u00e4".encode(), b"#1=2",
                          b"Y" * 40_000, "\u00e4".encode() * 30_000])


@settings(max_examples=12, deadline=None)
@given(st.lists(_piece, min_size=1, max_size=60), st.integers(0, 70_000))
def test_any_text_across_a_chunks_end_is_read_by_the_core_as_python_reads_it(pieces, room):
    """Whatever bytes fall on a chunk's end: the core's reading (Checker.check_file) and
    Python's (Source and whole_texts) give the same report."""
    import tempfile

    from formats.source import Source

    line = b"N10 G01 G90 X1.5 Y2 F100 (a)\n"
    lead = (line * (CHUNK // len(line) + 1))[:CHUNK - room]
    data = lead[:lead.rfind(b"\n") + 1] + b"".join(pieces)
    prof = load_profile("fanuc-mill")
    with tempfile.TemporaryDirectory() as folder:
        path = str(Path(folder) / "p.nc")
        Path(path).write_bytes(data)
        python = Checker(prof, "p.nc", report="jsonl")
        expected: list[str] = []
        python.report_stream(Source(path).chunks(), prof.dialect, expected.append)
        core = Checker(prof, "p.nc", report="jsonl")
        written: list[str] = []
        core.report_file(path, written.append)
    assert "".join(written) == "".join(expected)
    assert core.counts == python.counts
