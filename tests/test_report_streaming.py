"""JSON, JSON Lines and SARIF reports are streamed: the same documents as when every finding was
kept, flat memory however many findings there are, SARIF valid against the official schema, and
a closed pipe (``| head``) ends the check quietly."""

from __future__ import annotations

import json
import subprocess
import sys
import tracemalloc
from collections.abc import Iterator, Sequence
from importlib.metadata import version
from io import StringIO
from pathlib import Path
from typing import Any

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from formats.profile import load_profile
from formats.tape import encode, iso_byte
from postproc import report
from postproc.check import CheckStats, iter_check_file
from postproc.findings import Finding
from postproc.rules import RULES
from tapegate.cli import main

ROOT = Path(__file__).resolve().parents[1]
SCHEMA = Path(__file__).resolve().parent / "data" / "sarif-schema-2.1.0.json"
# Rules first found in an order that is not the sorted one (TG601 before TG101...), a non-ASCII
# character, an unclosed program: a dozen findings of nine rules.
PROGRAM = ("%\nN1 G71\nN2 G90\nN3 G17\nN4 G00 X600\nN5 G01 X10\nN6 G00 G90 X1\n"
           "N7 G01 X1 F100 G02 X20 Y0 K5\nN8 X1 $ (\u00e9)\n")
GOOD = "%\nN1 G71\nN2 G01 X10 F100\nN3 M30\n%\n"


# -- the reports as they were made before streaming (every finding kept, one json.dumps) ---------

def old_as_json(findings: Sequence[Finding], stats: dict[str, CheckStats] | None = None) -> str:
    data: dict[str, Any] = {"findings": [
        {"rule": f.rule, "severity": f.severity, "message": f.message, "file": f.file,
         "line": f.line, "column": f.column, "clause": f.clause} for f in findings]}
    if stats:
        data["stats"] = {name: report.stats_dict(s) for name, s in stats.items()}
    return json.dumps(data, indent=2) + "\n"


def uri_reference(name: str) -> str:
    """SARIF 2.1.0's artifactLocation.uri for a file name (review 21, finding 4): a file: URI
    for an absolute path, a percent-encoded relative reference for a relative one."""
    from urllib.parse import quote

    path = Path(name)
    return path.as_uri() if path.is_absolute() else quote(path.as_posix(), safe="/")


def old_sarif(findings: Sequence[Finding]) -> str:
    used = sorted({f.rule for f in findings})
    index = {rule: i for i, rule in enumerate(used)}
    level = {"error": "error", "warning": "warning", "info": "note"}
    rules = [{
        "id": rule,
        "name": rule,
        "shortDescription": {"text": RULES[rule].title},
        "fullDescription": {"text": f"{RULES[rule].title} (ISO 6983-1 {RULES[rule].clause})"},
        "defaultConfiguration": {"level": level[RULES[rule].severity]},
        "properties": {"clause": RULES[rule].clause},
    } for rule in used]
    results = [{
        "ruleId": f.rule,
        "ruleIndex": index[f.rule],
        "level": level[f.severity],
        "message": {"text": f"{f.message} [{f.clause}]"},
        "locations": [{"physicalLocation": {
            "artifactLocation": {"uri": uri_reference(f.file)},
            "region": {"startLine": f.line, "startColumn": f.column},
        }}],
    } for f in findings]
    log = {
        "$schema": "https://json.schemastore.org/sarif-2.1.0.json",
        "version": "2.1.0",
        "runs": [{
            "tool": {"driver": {"name": "tapegate", "version": version("tapegate"),
                                "rules": rules}},
            "results": results,
        }],
    }
    return json.dumps(log, indent=2) + "\n"


def sarif_resolved(log: dict[str, Any]) -> dict[str, Any]:
    """``log`` with every result's ruleIndex checked against its ruleId and then dropped, and
    the rule descriptors in ID order: the streamed log numbers its rules as they first appear,
    the old one in ID order; everything else must be equal."""
    (run,) = log["runs"]
    rules = run["tool"]["driver"]["rules"]
    for result in run["results"]:
        assert rules[result.pop("ruleIndex")]["id"] == result["ruleId"]
    assert len({r["id"] for r in rules}) == len(rules)
    run["tool"]["driver"]["rules"] = sorted(rules, key=lambda r: r["id"])
    return log


def run(*args: str):
    return CliRunner().invoke(main, list(args), catch_exceptions=False)


@pytest.fixture
def programs(tmp_path, sample_program) -> list[str]:
    """Three programs with findings (one a tape image with a parity error), one without."""
    (tmp_path / "p\u00e9.nc").write_text(PROGRAM, encoding="utf-8")
    (tmp_path / "bracket.nc").write_text(sample_program)
    tape = bytearray(encode(GOOD, "iso", leader=5))
    tape[tape.index(iso_byte("X"))] ^= 0x80
    (tmp_path / "p.tap").write_bytes(bytes(tape))
    (tmp_path / "good.nc").write_text(GOOD)
    return [str(tmp_path / n) for n in ("p\u00e9.nc", "bracket.nc", "p.tap", "good.nc")]


def findings_and_stats(files: list[str]) -> tuple[list[Finding], dict[str, CheckStats]]:
    """What the check command used to keep: every finding of every file, and the stats."""
    profile = load_profile("iso-mill")
    findings: list[Finding] = []
    stats = {}
    for name in files:
        checker, found = iter_check_file(name, profile)
        findings.extend(found)
        stats[name] = checker.stats
    return findings, stats


# -- (1) the same documents as before ------------------------------------------------------------

def test_streamed_json_is_the_old_document(programs):
    findings, stats = findings_and_stats(programs)
    assert len({f.rule for f in findings}) >= 9 and {"TG701", "TG101"} <= {f.rule for f in findings}
    for extra in ((), ("--stats",)):
        r = run("check", *programs, "-p", "iso-mill", "--format", "json", *extra)
        assert r.exit_code == 1
        old = old_as_json(findings, stats if extra else None)
        assert json.loads(r.stdout) == json.loads(old)
        assert r.stdout == old  # byte for byte, stats and all


def test_streamed_json_without_findings_or_stats(programs):
    good = programs[-1:]
    for extra in ((), ("--stats",)):
        r = run("check", *good, "-p", "iso-mill", "--format", "json", *extra)
        assert r.exit_code == 0
        assert r.stdout == old_as_json([], findings_and_stats(good)[1] if extra else None)
    assert report.as_json([]) == old_as_json([]) == '{\n  "findings": []\n}\n'


def test_streamed_sarif_is_the_old_document(programs):
    findings, _ = findings_and_stats(programs)
    r = run("check", *programs, "-p", "iso-mill", "--format", "sarif")
    assert r.exit_code == 1
    log = json.loads(r.stdout)
    assert r.stdout == json.dumps(log, indent=2) + "\n"  # laid out as json.dumps does it
    (run_,) = log["runs"]
    assert list(run_) == ["results", "tool"]  # results stream first, the rules used follow
    rules = [rule["id"] for rule in run_["tool"]["driver"]["rules"]]
    first_seen = list(dict.fromkeys(f.rule for f in findings))
    assert rules == first_seen and rules != sorted(rules)  # numbered as they first appear
    assert [res["ruleIndex"] for res in run_["results"]] == [rules.index(f.rule)
                                                            for f in findings]
    assert sarif_resolved(log) == sarif_resolved(json.loads(old_sarif(findings)))


def test_streamed_sarif_without_findings(programs):
    r = run("check", programs[-1], "-p", "iso-mill", "--format", "sarif")
    assert r.exit_code == 0
    assert json.loads(r.stdout) == json.loads(old_sarif([]))
    assert r.stdout == json.dumps(json.loads(r.stdout), indent=2) + "\n"


texts = st.text(st.characters(codec="utf-8", exclude_categories=["Cs"]) | st.sampled_from(
    ["\udcff", "\\", '"', "\n", "\x1b", "\u2028", "/"]), max_size=12)
finding_lists = st.lists(st.builds(
    Finding, st.sampled_from(sorted(RULES)), st.sampled_from(["error", "warning", "info"]),
    texts, texts | st.sampled_from(["a/b.nc", "./c.nc", "d//e.nc"]),
    st.integers(0, 10**9), st.integers(0, 10**6), texts), max_size=8)


@settings(max_examples=150, deadline=None)
@given(finding_lists)
def test_writers_match_the_old_documents_on_any_findings(findings):
    assert report.as_json(findings) == old_as_json(findings)
    log = report.sarif(findings)
    assert sarif_resolved(json.loads(log)) == sarif_resolved(json.loads(old_sarif(findings)))


def test_a_rule_outside_the_registry_fails_at_once():
    out = StringIO()
    sarif = report.SarifReport(out)
    with pytest.raises(KeyError):
        sarif.add(Finding("TG999", "error", "m", "f.nc", 1, 1, "4"))
    assert out.getvalue() == ""


def old_as_json_lines(findings: Sequence[Finding],
                      stats: dict[str, CheckStats] | None = None) -> str:
    """JSON Lines as json.dumps writes each record: a finding a line, then each file's stats."""
    records: list[dict[str, Any]] = [
        {"rule": f.rule, "severity": f.severity, "message": f.message, "file": f.file,
         "line": f.line, "column": f.column, "clause": f.clause} for f in findings]
    records += [{"file": name, "stats": report.stats_dict(s)} for name, s in (stats or {}).items()]
    return "".join(json.dumps(r) + "\n" for r in records)


def test_json_lines_are_a_finding_a_line_then_the_stats(programs):
    findings, stats = findings_and_stats(programs)
    for extra in ((), ("--stats",)):
        r = run("check", *programs, "-p", "iso-mill", "--format", "jsonl", *extra)
        assert r.exit_code == 1
        assert r.stdout == old_as_json_lines(findings, stats if extra else None)
    lines = r.stdout.splitlines()
    assert len(lines) == len(findings) + len(programs)
    assert [json.loads(x)["rule"] for x in lines[:len(findings)]] == [f.rule for f in findings]
    r = run("check", programs[-1], "-p", "iso-mill", "--format", "jsonl")
    assert (r.exit_code, r.stdout) == (0, "")


@settings(max_examples=150, deadline=None)
@given(finding_lists)
def test_json_lines_match_json_dumps_on_any_findings(findings):
    out = StringIO()
    assert report.write_json_lines(out, findings) == len(findings)
    assert out.getvalue() == old_as_json_lines(findings)


# -- (2) flat memory ----------------------------------------------------------------------------

class Sink:
    """A text output that keeps nothing: the bytes written are only counted."""

    def __init__(self) -> None:
        self.chars = 0

    def write(self, text: str) -> int:
        self.chars += len(text)
        return len(text)

    def flush(self) -> None:
        pass


N = 300_000
RULE_IDS = sorted(RULES)


def synthetic(n: int = N) -> Iterator[Finding]:
    """``n`` distinct findings, made one at a time (each with its own message)."""
    for i in range(n):
        rule = RULE_IDS[i % len(RULE_IDS)]
        yield Finding(rule, RULES[rule].severity, f"synthetic finding number {i} of a long run",
                      f"programs/part{i // 1000 % 7}.nc", i + 1, i % 80 + 1, RULES[rule].clause)


@pytest.mark.parametrize("write", [
    lambda out, found: report.write_json(out, found, {"part.nc": CheckStats(blocks=N)}),
    lambda out, found: report.write_json_lines(out, found, {"part.nc": CheckStats(blocks=N)}),
    report.write_sarif,
], ids=["json", "jsonl", "sarif"])
def test_memory_does_not_grow_with_the_findings(write):
    sink = Sink()
    tracemalloc.start()
    try:
        count = write(sink, synthetic())
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert count == N
    assert sink.chars > 50_000_000  # the document is several times the limit below...
    assert peak < 20_000_000, f"peak {peak / 1e6:.1f} MB"  # ...but is never held


# -- (3) SARIF 2.1.0 schema -----------------------------------------------------------------------

def test_streamed_sarif_validates_against_the_official_schema(programs):
    import jsonschema

    schema = json.loads(SCHEMA.read_text(encoding="utf-8"))
    validator = jsonschema.Draft7Validator(schema)
    logs = [json.loads(run("check", *programs, "-p", "iso-mill", "--format", "sarif").stdout),
            json.loads(run("check", programs[-1], "-p", "iso-mill", "--format", "sarif").stdout),
            json.loads(report.sarif(synthetic(2000)))]
    for log in logs:
        validator.validate(log)
    assert [len(log["runs"][0]["results"]) for log in logs][1:] == [0, 2000]


# -- a closed pipe --------------------------------------------------------------------------------

@pytest.mark.parametrize("fmt", ["json", "jsonl", "sarif", "text"])
def test_a_closed_pipe_ends_the_check_quietly(tmp_path, fmt):
    program = tmp_path / "many.nc"  # 20,000 findings: far more than a pipe holds
    program.write_text("%\nN1 G71\n" + "".join(f"N{i} G00 G90 X1\n" for i in range(2, 20_002))
                       + "N99 M30\n%\n")
    proc = subprocess.Popen([sys.executable, "-m", "tapegate", "check", str(program), "-p",
                             "iso-mill", "--format", fmt], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, cwd=ROOT)
    assert proc.stdout is not None and proc.stderr is not None
    head = proc.stdout.read(100)
    proc.stdout.close()  # what `| head -c 100` does
    stderr = proc.stderr.read()
    assert proc.wait(timeout=60) == 0
    assert stderr == b""  # no traceback, no "cannot read ...: Broken pipe"
    assert len(head) == 100


@pytest.mark.parametrize("kind", [report.JsonReport, report.JsonLinesReport])
def test_a_json_report_goes_to_the_binary_buffer_as_the_cores_bytes(programs, kind):
    """On a stream with a binary buffer in UTF-8 or ASCII, a JSON report writes its own text
    and the core's bytes there (``raw``), after what the text layer held; the document is the
    one written as text to a StringIO, whether its pieces come as str or bytes. In another
    encoding, or without a buffer, it goes through the text layer."""
    import io

    from postproc.check import Checker

    fmt = "json" if kind is report.JsonReport else "jsonl"
    profile = load_profile("iso-mill")

    def written(out: Any, raw: bool) -> None:
        writer = kind(out)
        assert writer.raw is raw
        for name in programs:
            checker = Checker(profile, name, report=fmt)
            checker.report_file(name, writer.write, raw)
        writer.close()

    text = StringIO()
    written(text, False)
    for encoding in ("utf-8", "ascii"):
        data = io.BytesIO()
        out = io.TextIOWrapper(data, encoding=encoding)
        out.write("before\n")  # held by the text layer: flushed before the report's bytes
        written(out, True)
        assert data.getvalue() == b"before\n" + text.getvalue().encode()
    data = io.BytesIO()
    out = io.TextIOWrapper(data, encoding="utf-16")
    written(out, False)
    assert data.getvalue().decode("utf-16") == text.getvalue()
