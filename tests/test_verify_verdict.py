"""`convert --verify`'s verdict, "verified" or "partly verified", decided from the core's counts
(``ConvertStats.left_as_written``, ``never_read``, ``not_compared``), never from the wording of
its notes: a program per case, the verdict and the count in the summary's text and in the
statistics, and the error paths with their exit codes (docs/errors.md)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from click.testing import CliRunner

from formats.conversion import ConvertOptions
from formats.convert import convert_file
from formats.errors import ConversionError
from formats.profile import load_profile
from formats.verify import verify_conversion
from tapegate.cli import main

# M100 is no code of FANUC's list: what its P Q R are is not known (column 6, 9, 14)
UNKNOWN = "%\nO0011\nG21 G90 G54\nG00 X10. Y10. Z5.\nM100 P1 Q2.5 R3.123\nM30\n%\n"
# #1 is set and never read: nothing shows whether it is a length
PARAMETER = "%\nO1\nG21\n#1=#5221+1.\nG00 X10.\nM30\n%\n"
# after M2 LinuxCNC reads only O-word lines: these two are never read, and their note says
# "left as written" without being a word left
NEVER_READ = "G21\nG0 X10.\nM2\n  (tail) Y3.\nG0 X5.\n"
NOTHING = "%\nO1\nG21 G90\nG00 X10. Y25.4\nM30\n%\n"


def stats_of(tmp_path: Path, text: str, profile: str, *, allow: bool = True):  # type: ignore[no-untyped-def]
    src = tmp_path / "p.nc"
    src.write_text(text)
    p = load_profile(profile)
    options = ConvertOptions(target=p, source=p, units="inch", allow_unconverted=allow)
    return convert_file(str(src), str(tmp_path / "o.nc"), options, verify=True)


def summary(tmp_path: Path, text: str, profile: str, *extra: str) -> tuple[int, str]:
    """The command line's exit code and its result column for the one file, the same in its
    table and in its JSON (``--format json``, checked against the counts by :func:`as_json`)."""
    src = tmp_path / "c.nc"
    src.write_text(text)
    args = ["convert", str(src), "--from", profile, "--to", profile, "--units", "inch",
            "--verify", "--dry-run", *extra]
    run = CliRunner().invoke(main, args)
    rows = [line for line in run.output.splitlines() if line.startswith(str(src) + " ")]
    result = rows[0].rsplit("  ", 1)[-1].strip() if rows else run.output
    code, entry = as_json(args)
    assert (code, entry["result"]) == (run.exit_code, result)
    return run.exit_code, result


def as_json(args: list[str]) -> tuple[int, dict[str, Any]]:
    """``convert --format json``: the exit code and the one file's entry, its verdict and
    counts agreeing with its result."""
    run = CliRunner().invoke(main, [*args, "--format", "json"])
    document = json.loads(run.stdout)
    [entry] = document["files"]
    assert document["total"]["failed"] == (1 if entry["error"] else 0)
    left = entry["left_as_written"]["count"]
    assert (entry["verified"] is False) == entry["result"].startswith("partly verified")
    if entry["verified"] is not None:  # a proof was made: its result says the count
        assert (left > 0) == ("left as written" in entry["result"])
    assert (entry["left_as_written"]["first"] is None) == (left == 0)
    return run.exit_code, entry


def test_words_of_unknown_role_kept_make_it_partly_verified(tmp_path: Path) -> None:
    stats = stats_of(tmp_path, UNKNOWN, "fanuc-mill")
    assert stats.proved and not stats.verified
    assert (stats.left_as_written, stats.left_at) == (3, (5, 6))
    assert (stats.never_read, stats.not_compared) == (0, [])
    assert summary(tmp_path, UNKNOWN, "fanuc-mill", "--allow-unconverted") == (
        0, "partly verified: 3 words left as written")
    code, entry = as_json(["convert", str(tmp_path / "c.nc"), "--from", "fanuc-mill", "--to",
                           "fanuc-mill", "--units", "inch", "--allow-unconverted", "--verify",
                           "--dry-run"])
    assert code == 0 and entry["verified"] is False and entry["not_compared"] == []
    assert entry["left_as_written"] == {"count": 3, "statements": 0,
                                        "first": {"line": 5, "column": 6}}
    assert entry["never_read"] == {"count": 0, "first": None}


def test_a_parameter_left_unconverted_makes_it_partly_verified(tmp_path: Path) -> None:
    stats = stats_of(tmp_path, PARAMETER, "fanuc-mill")
    # its note names no line ("parameter #1 left unconverted: ..."): counted where it is left
    assert [n for n in stats.notes if n.startswith("parameter #1 left unconverted")]
    assert not stats.verified and (stats.left_as_written, stats.left_at) == (1, (4, 1))
    assert summary(tmp_path, PARAMETER, "fanuc-mill", "--allow-unconverted") == (
        0, "partly verified: 1 word left as written")


def test_lines_never_read_are_counted_apart_and_leave_it_verified(tmp_path: Path) -> None:
    stats = stats_of(tmp_path, NEVER_READ, "linuxcnc")
    assert any("never reads" in n and "left as written" in n for n in stats.notes)
    assert stats.verified and stats.left_as_written == 0 and stats.left_at is None
    assert (stats.never_read, stats.never_read_at) == (2, (4, 3))
    assert summary(tmp_path, NEVER_READ, "linuxcnc") == (0, "verified")
    code, entry = as_json(["convert", str(tmp_path / "c.nc"), "--from", "linuxcnc", "--to",
                           "linuxcnc", "--units", "inch", "--verify", "--dry-run"])
    assert code == 0 and entry["verified"] is True
    assert entry["left_as_written"] == {"count": 0, "statements": 0, "first": None}
    assert entry["never_read"] == {"count": 2, "first": {"line": 4, "column": 3}}


def test_nothing_left_is_verified(tmp_path: Path) -> None:
    stats = stats_of(tmp_path, NOTHING, "fanuc-mill", allow=False)
    assert stats.verified and (stats.left_as_written, stats.left_at) == (0, None)
    assert (stats.never_read, stats.never_read_at) == (0, None)
    assert summary(tmp_path, NOTHING, "fanuc-mill") == (0, "verified")


def test_without_verify_the_count_is_kept_but_no_verdict_said(tmp_path: Path) -> None:
    src = tmp_path / "c.nc"
    src.write_text(UNKNOWN)
    p = load_profile("fanuc-mill")
    stats = convert_file(str(src), None, ConvertOptions(target=p, source=p, units="inch",
                                                        allow_unconverted=True))
    assert stats.left_as_written == 3 and not stats.proved and not stats.verified
    run = CliRunner().invoke(main, ["convert", str(src), "--from", "fanuc-mill", "--to",
                                    "fanuc-mill", "--units", "inch", "--allow-unconverted",
                                    "--dry-run"])
    assert run.exit_code == 0 and "verified" not in run.output
    code, entry = as_json(["convert", str(src), "--from", "fanuc-mill", "--to", "fanuc-mill",
                           "--units", "inch", "--allow-unconverted", "--dry-run"])
    assert (code, entry["result"], entry["verified"]) == (0, "ok", None)
    assert entry["left_as_written"]["count"] == 3  # a fact of the conversion, no verdict


def test_the_count_holds_past_the_notes_held_in_memory(tmp_path: Path) -> None:
    """The command line keeps a file's first 1,000 notes in memory and spills the rest: a
    count read from the notes in memory said "verified" for a word left after 1,001 thread
    lead notes, and at most "1000 words" for more."""
    leads = "G32 Z-10. F1.23456\n" * 1001
    text = f"%\nO1\nG21 G99\nG00 X20. Z2.\n{leads}M100 P1\nM30\n%\n"
    assert summary(tmp_path, text, "fanuc-lathe", "--allow-unconverted") == (
        0, "partly verified: 1 word left as written")
    many = "%\nO1\nG21\nG00 X10.\n" + "M100 P1\n" * 1100 + "M30\n%\n"
    assert summary(tmp_path, many, "fanuc-mill", "--allow-unconverted") == (
        0, "partly verified: 1100 words left as written")


@pytest.mark.parametrize("text", [UNKNOWN, PARAMETER])
def test_without_allow_unconverted_the_refusal_exits_1(tmp_path: Path, text: str) -> None:
    with pytest.raises(ConversionError) as info:
        stats_of(tmp_path, text, "fanuc-mill", allow=False)
    assert info.value.code == "conversion-unprovable"
    code, said = summary(tmp_path, text, "fanuc-mill")
    assert code == 1 and said == "FAILED"
    code, entry = as_json(["convert", str(tmp_path / "c.nc"), "--from", "fanuc-mill", "--to",
                           "fanuc-mill", "--units", "inch", "--verify", "--dry-run"])
    assert code == 1 and entry["verified"] is None and "[6.4.7]" in entry["error"]


def test_a_value_changed_in_the_output_fails_the_proof(tmp_path: Path) -> None:
    stats = stats_of(tmp_path, UNKNOWN, "fanuc-mill")
    out = tmp_path / "o.nc"
    out.write_text(out.read_text().replace("X0.3937", "X0.3938"))
    p = load_profile("fanuc-mill")
    options = ConvertOptions(target=p, source=p, units="inch", allow_unconverted=True)
    with pytest.raises(ConversionError) as info:
        verify_conversion(str(tmp_path / "p.nc"), str(out), p, options, stats, file="p.nc")
    assert (info.value.code, info.value.line) == ("conversion-verify", 4)


def test_a_units_parameter_target_is_read_in_the_units_the_converter_gives(tmp_path: Path) -> None:
    """An inch Haas lathe program to an OSP lathe, no --units: the converter says to set the
    machine to inch, in a note and in ``machine_units``, and the proof reads the output so."""
    src = tmp_path / "h.nc"
    src.write_text("%\nO1\nG00 X1. Z0.1\nG97 S1000 M03\nG01 Z-1. F0.01\nM30\n%\n")
    options = ConvertOptions(target=load_profile("okuma-lathe"),
                             source=load_profile("haas-lathe"))
    stats = convert_file(str(src), str(tmp_path / "h.min"), options, verify=True)
    assert stats.machine_units == "inch" and stats.verified
    # the same program converted to a control with units codes: no machine setting to give
    options = ConvertOptions(target=load_profile("fanuc-lathe"),
                             source=load_profile("haas-lathe"))
    stats = convert_file(str(src), str(tmp_path / "f.nc"), options, verify=True)
    assert stats.machine_units is None and stats.verified


# A Haas DPRNT statement printing a position: under a change of units it prints another number,
# and --allow-unconverted leaves the whole statement as written (review 13, finding 9: it was
# called a word).
DPRNT = "%\nO01000\nG20 G90 G54\nDPRNT[POS*#5021[44]]\nG00 X1. Y1.\nM30\n%\n"


def test_a_statement_left_as_written_is_named_a_statement_not_a_word(tmp_path: Path) -> None:
    src = tmp_path / "d.nc"
    src.write_text(DPRNT)
    p = load_profile("haas-mill")
    options = ConvertOptions(target=p, source=p, units="metric", allow_unconverted=True)
    stats = convert_file(str(src), str(tmp_path / "o.nc"), options, verify=True)
    assert not stats.verified
    assert (stats.left_as_written, stats.left_statements, stats.left_at) == (1, 1, (4, 1))
    args = ["convert", str(src), "--from", "haas-mill", "--to", "haas-mill", "--units", "metric",
            "--allow-unconverted", "--verify", "--dry-run"]
    code, entry = as_json(args)
    assert code == 0 and entry["left_as_written"] == {
        "count": 1, "statements": 1, "first": {"line": 4, "column": 1}}
    assert entry["result"] == (
        "partly verified: 1 statement not compared; 1 statement left as written")
    assert "word" not in entry["result"]
