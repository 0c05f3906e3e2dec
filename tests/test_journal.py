"""The transfer journal: append-only, fsync'd, readable after a torn last line."""

from __future__ import annotations

import json
from datetime import UTC, datetime
from pathlib import Path

import pytest
from click.testing import CliRunner

from dnc.emulator import Emulator
from dnc.journal import Journal, Transfer, read_journal
from formats.errors import TapegateError
from tapegate.cli import main
from tests.test_dnc_serial import control_for, program

pytestmark = pytest.mark.timeout(60)


def transfer(port: str, start: str, result: str = "ok") -> Transfer:
    return Transfer(port, "send", "O1.nc", 100, 5, start, start, result, [], "ab" * 32)


def test_append_and_read_back_with_filters(tmp_path: Path) -> None:
    journal = Journal(tmp_path / "j.jsonl")
    journal.append(transfer("/dev/ttyS0", "2026-11-20T10:00:00+00:00"))
    journal.append(transfer("/dev/ttyS1", "2026-11-21T10:00:00+00:00", "failed"))
    assert len(read_journal(journal.path).transfers) == 2
    assert [t.port for t in read_journal(journal.path, port="/dev/ttyS1").transfers] == \
        ["/dev/ttyS1"]
    since = datetime(2026, 11, 21, tzinfo=UTC)
    assert [t.result for t in read_journal(journal.path, since=since).transfers] == ["failed"]


def test_a_torn_last_line_is_skipped_and_counted(tmp_path: Path) -> None:
    journal = Journal(tmp_path / "j.jsonl")
    journal.append(transfer("p", "2026-11-21T10:00:00+00:00"))
    with open(journal.path, "a") as f:
        f.write('{"port": "p", "direction": "se')  # a crash mid-write
    reading = read_journal(journal.path)
    assert len(reading.transfers) == 1 and reading.torn == 1
    journal.append(transfer("p", "2026-11-21T11:00:00+00:00"))
    assert read_journal(journal.path).torn == 1  # later lines still read (after the torn one)


def test_missing_journal_is_a_clear_error(tmp_path: Path) -> None:
    with pytest.raises(TapegateError) as info:
        read_journal(tmp_path / "none.jsonl")
    assert info.value.code == "journal-missing"
    assert info.value.file == str(tmp_path / "none.jsonl")


def test_send_and_a_failed_send_are_journalled(tmp_path: Path) -> None:
    src = tmp_path / "p.nc"
    src.write_text(program(4))
    journal = tmp_path / "j.jsonl"
    control = control_for("fanuc-mill", baud=115200)
    emu = Emulator(control)
    try:
        result = CliRunner().invoke(main, ["send", str(src), "--port", emu.path, "-p",
                                           "fanuc-mill", "--baud", "115200", "--xon-timeout",
                                           "5", "--journal", str(journal)])
        emu.wait(5)
    finally:
        emu.stop()
    assert result.exit_code == 0, result.output
    result = CliRunner().invoke(main, ["send", str(src), "--port", "/dev/nonexistent-port",
                                       "-p", "fanuc-mill", "--journal", str(journal)])
    assert result.exit_code == 3
    records = [json.loads(line) for line in journal.read_text().splitlines()]
    assert [r["result"] for r in records] == ["ok", "failed"]
    assert records[0]["bytes"] > 0 and len(records[0]["sha256"]) == 64
    assert records[0]["sha256"] == records[1]["sha256"]  # the same program
    assert "cannot open port" in records[1]["errors"][0]
    table = CliRunner().invoke(main, ["journal", str(journal)])
    assert table.exit_code == 0
    assert "send" in table.output and "failed" in table.output
    assert table.output.splitlines()[0].split()[:3] == ["start", "port", "dir"]
