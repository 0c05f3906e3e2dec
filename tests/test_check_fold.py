"""The text report of ``tapegate check`` folds a rule repeated in a file: of each rule's warnings
and notes it prints the first five, then one line for the rest at the first one left out, with
their number and lines (crates/core/src/report.rs, ``Writer::folded``); a rule about a code
(TG307's M160, M161) per rule and code. Errors are all printed;
``--all`` prints everything; JSON, JSON Lines and SARIF are never folded; the summary's counts
and the exit code are of every finding."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from formats.tape import encode
from tapegate.cli import main

ROOT = Path(__file__).resolve().parent.parent

# 12 sequence numbers past the N05 of haas-mill's profile (TG208, a warning), lines 3-14
REPEATED = "%\nO1000\n" + "".join(f"N{100000 + 10 * n} G0 X{n}.\n" for n in range(1, 13)) \
    + "M30\n%\n"
# 12 feed moves with no feed rate in force (TG401, an error), lines 4-15
ERRORS = "%\nO1001\nG90 G21 G17 G0 X0 Y0 Z0 S1000 M3\n" \
    + "".join(f"G1 X{n}.\n" for n in range(1, 13)) + "M30\n%\n"
WARNING = "warning TG208 N1"


def run(*args: str) -> Result:
    return CliRunner().invoke(main, ["check", *args], catch_exceptions=False)


def fold_line(name: str, line: int, more: int, low: int, high: int) -> str:
    return (f"{name}:{line}:1: warning TG208 {more} more like this on lines {low}-{high} "
            "(--all shows each)")


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    (tmp_path / "a.nc").write_text(REPEATED)
    # the second file: its N words two lines further down
    (tmp_path / "b.nc").write_text(REPEATED.replace("O1000\n", "O1002\n(SECOND)\n\n"))
    (tmp_path / "e.nc").write_text(ERRORS)
    return tmp_path


def test_twelve_of_a_warning_print_five_and_one_line_for_the_rest(folder: Path) -> None:
    name = str(folder / "a.nc")
    result = run(name, "-p", "haas-mill")
    lines = result.stdout.splitlines()
    assert [line for line in lines if WARNING in line] == [
        f"{name}:{n}:1: warning TG208 N{100000 + 10 * (n - 2)}: 6 digits; the format N05 "
        "holds 5: the control's manuals do not say whether it rounds, cuts or alarms "
        "[profile]" for n in range(3, 8)]
    assert lines[-1] == fold_line(name, 8, 7, 8, 14)
    assert len(lines) == 6
    # the summary and the exit code count every finding
    assert result.stderr == "1 file checked: 0 errors, 12 warnings, 0 notes\n"
    assert result.exit_code == 0
    assert run(name, "-p", "haas-mill", "--fail-on", "warning").exit_code == 1


def test_all_prints_every_finding(folder: Path) -> None:
    name = str(folder / "a.nc")
    result = run(name, "-p", "haas-mill", "--all")
    jsonl = run(name, "-p", "haas-mill", "--format", "jsonl").stdout
    found = map(json.loads, jsonl.splitlines())
    assert result.stdout.splitlines() == [
        f"{name}:{f['line']}:{f['column']}: {f['severity']} {f['rule']} {f['message']} "
        f"[{f['clause']}]" for f in found]
    assert result.stdout.count(WARNING) == 12 and "more like this" not in result.stdout
    assert result.stderr == "1 file checked: 0 errors, 12 warnings, 0 notes\n"


def test_an_error_repeated_is_printed_every_time(folder: Path) -> None:
    name = str(folder / "e.nc")
    result = run(name, "-p", "haas-mill")
    errors = [line for line in result.stdout.splitlines() if "error TG401" in line]
    assert errors == [f"{name}:{n}:4: error TG401 feed motion with no feed rate in force [7]"
                      for n in range(4, 16)]
    assert "more like this" not in result.stdout
    assert result.exit_code == 1
    assert "12 errors" in result.stderr


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_each_file_is_folded_on_its_own_in_input_order(folder: Path, jobs: str) -> None:
    a, b = str(folder / "a.nc"), str(folder / "b.nc")
    result = run(a, b, "-p", "haas-mill", "-j", jobs)
    lines = result.stdout.splitlines()
    assert [line.split(":")[0] for line in lines] == [a] * 6 + [b] * 6
    assert lines[5] == fold_line(a, 8, 7, 8, 14)
    assert lines[11] == fold_line(b, 10, 7, 10, 16)
    assert sum(WARNING in line for line in lines) == 10
    assert result.stderr == "2 files checked: 0 errors, 24 warnings, 0 notes\n"
    # a folder of files: the same report
    folded = run(str(folder), "-p", "haas-mill", "-j", jobs, "--ignore", "TG401")
    assert folded.stdout.startswith(result.stdout)
    assert "e.nc" in folded.stdout


def test_select_ignore_and_stats_keep_the_fold(folder: Path) -> None:
    name = str(folder / "b.nc")
    selected = run(name, "-p", "haas-mill", "--select", "TG208").stdout.splitlines()
    assert len(selected) == 6 and selected[-1] == fold_line(name, 10, 7, 10, 16)
    ignored = run(name, "-p", "haas-mill", "--ignore", "TG1").stdout.splitlines()
    assert ignored == selected
    assert run(name, "-p", "haas-mill", "--ignore", "TG208").stdout.count("more like") == 0
    stats = run(name, "-p", "haas-mill", "--stats")
    assert stats.stdout.startswith(run(name, "-p", "haas-mill").stdout)
    assert "12 warnings" in stats.stderr


@pytest.mark.parametrize("fmt", ["json", "jsonl", "sarif"])
def test_the_reports_for_programs_are_never_folded(folder: Path, fmt: str) -> None:
    files = [str(folder / "a.nc"), str(folder / "e.nc")]
    folded = run(*files, "-p", "haas-mill", "--format", fmt)
    assert folded.stdout == run(*files, "-p", "haas-mill", "--format", fmt, "--all").stdout
    if fmt == "json":
        found = json.loads(folded.stdout)["findings"]
        assert sum(f["rule"] == "TG208" for f in found) == 12
        assert sum(f["rule"] == "TG401" for f in found) == 12


def test_a_tape_image_and_a_last_line_without_its_lf_are_folded_alike(tmp_path: Path) -> None:
    """A tape image is read by Python (``report_stream``), a last line without its LF too:
    their findings are folded by the same writer."""
    text = tmp_path / "p.nc"
    text.write_text(REPEATED)
    expected = run(str(text), "-p", "haas-mill").stdout
    tape = tmp_path / "p.tap"
    tape.write_bytes(encode(REPEATED, "iso"))
    assert run(str(tape), "-p", "haas-mill").stdout == expected.replace(str(text), str(tape))
    unended = tmp_path / "q.nc"
    unended.write_text(REPEATED.removesuffix("M30\n%\n") + "N999999 M30")
    lines = run(str(unended), "-p", "haas-mill").stdout.splitlines()
    assert lines[-1] == fold_line(str(unended), 8, 8, 8, 15)


def test_the_entry_point_without_click_folds_too(folder: Path) -> None:
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    code = "from tapegate.launch import main; main(prog_name='tapegate')"
    for extra, count in (((), 6), (("--all",), 12)):
        done = subprocess.run([sys.executable, "-c", code, "check", "a.nc", "-p", "haas-mill",
                               *extra], cwd=folder, env=env, capture_output=True, text=True,
                              timeout=120, check=False)
        assert len(done.stdout.splitlines()) == count
        assert done.stderr == "1 file checked: 0 errors, 12 warnings, 0 notes\n"


def test_a_rule_about_a_code_is_folded_per_code(tmp_path: Path) -> None:
    """Stop 58: TG307 for M160 and M161 was folded into one line past the first five of the
    file, and M161 was never named. A rule about a code folds per the code each finding names:
    five of each are printed, and each code has its own fold line naming it; a third code met
    once is printed; the summary counts every finding; JSON is unfolded; a tape image, whose
    findings Python renders, folds the same."""
    text = "%\nO1000\nG21 G90 G54\n" + "M160\nM161\n" * 7 + "M162\nM30\n%\n"
    path = tmp_path / "m.nc"
    path.write_text(text)
    name = str(path)
    result = run(name, "-p", "haas-mill", "--select", "TG307")
    lines = result.stdout.splitlines()
    for code, rows in (("M160", range(4, 13, 2)), ("M161", range(5, 14, 2)), ("M162", [18])):
        assert [line.split(":")[1] for line in lines
                if f"warning TG307 {code} is not" in line] == [str(n) for n in rows]
    assert lines[-2:] == [
        f"{name}:14:1: warning TG307 2 more like this (M160) on lines 14-16 (--all shows each)",
        f"{name}:15:1: warning TG307 2 more like this (M161) on lines 15-17 (--all shows each)"]
    assert len(lines) == 13
    assert result.stderr == "1 file checked: 0 errors, 15 warnings, 0 notes\n"
    found = json.loads(run(name, "-p", "haas-mill", "--select", "TG307",
                           "--format", "json").stdout)["findings"]
    assert len(found) == 15
    tape = tmp_path / "m.tap"
    tape.write_bytes(encode(text, "iso"))
    taped = run(str(tape), "-p", "haas-mill", "--select", "TG307").stdout
    assert taped == result.stdout.replace(name, str(tape))


def test_the_help_says_what_all_does() -> None:
    text = " ".join(CliRunner().invoke(main, ["check", "--help"]).stdout.split())
    assert ("--all Text: print every finding. Without it, past the first 5 warnings or notes "
            "of one rule in a file (of one code, for a rule about a code) the rest are one line") \
        in text
    assert "errors are always all printed" in text


def test_a_report_of_a_stream_ends_with_its_fold_lines_too() -> None:
    """Review 37, finding 8: ``Checker.report_stream`` (the API's checker of text chunks) never
    wrote the "more like this" line; it ends its report as ``report_file`` does."""
    from formats.profile import load_profile
    from postproc.check import Checker

    profile = load_profile("haas-mill")
    text = "%\nO1\nG20 G90 G00 X0 Y0\n" + "".join(
        f"N{100000 + 10 * i} X{i}.\n" for i in range(12)) + "M30\n%\n"
    out: list[str] = []
    checker = Checker(profile, "p.nc", report="text", fold=True)
    checker.report_stream([text], profile.dialect, out.append)
    lines = "".join(out).splitlines()
    assert sum(" TG208 N" in line for line in lines) == 5, lines
    assert [line for line in lines if "more like this" in line] == [
        "p.nc:9:1: warning TG208 7 more like this on lines 9-15 (--all shows each)"], lines
    assert checker.counts["warning"] == 12
