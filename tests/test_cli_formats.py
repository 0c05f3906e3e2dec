import json

from click.testing import CliRunner

from formats.profile import NEUTRAL, load_profile
from formats.tape import encode
from tapegate.cli import main


def run(*args):
    return CliRunner().invoke(main, list(args), catch_exceptions=False)


def test_parse_reprint_json_summary(tmp_path, sample_program):
    path = tmp_path / "p.nc"
    path.write_bytes(sample_program.encode())
    assert run("parse", str(path), "--reprint").stdout == sample_program
    lines = run("parse", str(path), "--json", "-p", "iso-mill").output.splitlines()
    first = json.loads(lines[0])
    assert first["percent"] and first["ident"] == "(BRACKET OP10)"
    words = json.loads(lines[4])["words"]
    assert words[2] == {"address": "X", "column": 8, "sign": "", "number": "10.",
                        "value": "10"}
    summary = run("parse", str(path), "--summary").output
    assert "16 blocks, 51 words, 1 comment (text)" in summary


def test_parse_reads_tape_images(tmp_path, sample_program):
    path = tmp_path / "p.tap"
    path.write_bytes(encode(sample_program, "eia", leader=20))
    result = run("parse", str(path), "--reprint")
    assert result.stdout == sample_program and result.exit_code == 0


def test_parse_error_is_located_with_exit_1(tmp_path):
    path = tmp_path / "bad.nc"
    path.write_text("N1 X1\nN2 X1 Y\n")
    result = CliRunner().invoke(main, ["parse", str(path), "-p", "iso-mill"])
    assert result.exit_code == 1
    assert f"{path}:2:7: address Y has no value [6.1]" in result.output


def test_reprint_keeps_every_block_and_reports_the_unreadable_ones(tmp_path):
    """A block the profile cannot read is printed back as written and reported on stderr with
    its place: the reprint is the whole file, never nothing."""
    text = "%\nN1 X1 ; a semicolon comment\nN2 X1 Y\nN3 M30\n%\n\x1a"
    path = tmp_path / "dos.nc"
    path.write_bytes(text.encode())
    result = CliRunner().invoke(main, ["parse", str(path), "--reprint", "-p", "iso-mill"])
    assert result.exit_code == 1
    assert result.stdout == text
    assert f"{path}:2:7: character ';'" in result.stderr
    assert f"{path}:3:7: address Y has no value [6.1]" in result.stderr
    lines = CliRunner().invoke(main, ["parse", str(path), "--json", "-p", "iso-mill"]).stdout
    assert [json.loads(x).get("error", "")[:20] for x in lines.splitlines()][1:3] == [
        f"{path}:2:7: charac"[:20], f"{path}:3:7: addres"[:20]]


def test_a_dos_end_of_file_and_a_byte_order_mark_are_read_as_nothing(tmp_path):
    text = "\ufeff%\nN1 G21 X1.\nN2 M30\n%\n\x1a"
    path = tmp_path / "dos.nc"
    path.write_bytes(text.encode())
    result = CliRunner().invoke(main, ["parse", str(path), "--reprint", "-p", "iso-mill"])
    assert (result.exit_code, result.stdout, result.stderr) == (0, text, "")
    summary = CliRunner().invoke(main, ["parse", str(path), "--summary", "-p", "iso-mill"])
    assert "5 blocks, 5 words, 0 comments" in summary.stdout


def test_without_a_profile_every_command_says_what_it_assumed(tmp_path, sample_program):
    """One rule for every command: --profile is optional; without it the program is read with
    the neutral profile, adjusted to the units codes and decimal style found, and stderr says
    so. (check and plot ended with a TypeError.)"""
    path = tmp_path / "p.nc"
    path.write_text(sample_program)
    for args in (["parse", str(path), "--summary"], ["check", str(path)],
                 ["plot", str(path), "-o", str(tmp_path / "p.svg")]):
        result = CliRunner().invoke(main, args)
        assert result.exit_code in (0, 1), (args, result.output)
        assert result.exception is None or isinstance(result.exception, SystemExit), args
        assert "tapegate: no --profile: the neutral profile" in result.stderr, args
        assert "units codes G70/G71 (G71 found)" in result.stderr, args


def test_neutral_is_a_profile_name_everywhere_a_profile_is(tmp_path, sample_program):
    """-p neutral names the neutral profile for every command, as it did for check alone
    (parse, convert --to and diff said "no profile named 'neutral'")."""
    path = tmp_path / "p.nc"
    path.write_text(sample_program)
    for args in (["parse", str(path), "--summary", "-p", "neutral"],
                 ["check", str(path), "-p", "neutral"],
                 ["plot", str(path), "-p", "neutral", "-o", str(tmp_path / "p.svg")],
                 ["convert", str(path), "--to", "neutral", "--from", "neutral", "--dry-run"],
                 ["diff", str(path), str(path), "-p", "neutral", "--from", "neutral"]):
        result = CliRunner().invoke(main, args)
        assert result.exit_code in (0, 1), (args, result.output)
        assert "no profile named" not in result.output, args
        assert "no --profile" not in result.stderr, args  # the profile named is the one used
    diff = CliRunner().invoke(main, ["diff", str(path), str(path), "-p", "neutral",
                                     "--format", "json"])
    assert diff.exit_code == 0
    assert json.loads(diff.stdout)["b"]["profile"] == "neutral"
    shown = CliRunner().invoke(main, ["profiles", "show", "neutral"])
    assert shown.exit_code == 0 and 'name = "neutral"' in shown.stdout
    assert load_profile("neutral") is NEUTRAL


def test_missing_file_and_bad_profile_exit_2(tmp_path):
    assert CliRunner().invoke(main, ["parse", str(tmp_path / "nope.nc")]).exit_code == 2
    path = tmp_path / "p.nc"
    path.write_text("N1\n")
    result = CliRunner().invoke(main, ["parse", str(path), "-p", "nonesuch"])
    assert result.exit_code == 2 and "no profile named 'nonesuch'" in result.output


def test_tape_encode_decode_detect(tmp_path, sample_program):
    src = tmp_path / "p.nc"
    src.write_text(sample_program)
    tap = tmp_path / "p.tap"
    assert run("tape", "encode", str(src), "--code", "eia", "-o", str(tap),
               "--leader", "10").exit_code == 0
    assert run("tape", "detect", str(tap)).output.strip() == "eia"
    out = tmp_path / "back.nc"
    result = run("tape", "decode", str(tap), "-o", str(out))
    assert "EIA code" in result.output and out.read_text() == sample_program
    damaged = bytearray(tap.read_bytes())
    damaged[15] ^= 0x10
    tap.write_bytes(bytes(damaged))
    result = CliRunner().invoke(main, ["tape", "decode", str(tap), "-o", str(out)])
    assert result.exit_code == 1 and "parity error" in result.output


def test_tape_encode_refuses_what_eia_cannot_carry(tmp_path):
    src = tmp_path / "p.nc"
    src.write_text("N1\n:2 X1\n")
    result = CliRunner().invoke(main, ["tape", "encode", str(src), "--code", "eia",
                                       "-o", str(tmp_path / "o")])
    assert result.exit_code == 1 and f"{src}:2:1: character ':'" in result.output
    assert not (tmp_path / "o").exists()


def test_classify_and_profiles():
    out = run("classify", "%:/DS N03 G02 X+053 Y+053 Z+053 F031 S04 T04 M02*").output
    assert "signed, 5 digits before and 3 after the decimal sign" in out
    assert "positioning only" in run("classify", "PM", "322").output
    bad = CliRunner().invoke(main, ["classify", "PM 232"])
    assert bad.exit_code == 1 and "digit 2 <= digit 1" in bad.output
    assert "pm322-eia" in run("profiles").output
    assert 'units_codes = "G20/G21"' in run("profiles", "show", "fanuc-mill").output


def test_standard_input_and_output_with_dash(tmp_path, sample_program):
    """- reads standard input and -o - writes standard output, for every command that reads or
    writes one file; the messages then go to stderr and name <stdin>/<stdout>."""
    runner = CliRunner()
    summary = runner.invoke(main, ["parse", "-", "--summary", "-p", "iso-mill"],
                            input=sample_program)
    assert summary.exit_code == 0 and summary.stdout.startswith("<stdin>: 16 blocks")
    reprint = runner.invoke(main, ["parse", "-", "--reprint"], input=sample_program)
    assert reprint.stdout == sample_program
    converted = runner.invoke(main, ["convert", "-", "-o", "-", "--from", "iso-mill", "--to",
                                     "iso-mill", "--units", "inch"], input=sample_program)
    assert converted.exit_code == 0, converted.output
    assert "N4 G00 X0.394 Y0.394 Z0.197 M08" in converted.stdout
    assert "<stdin>" in converted.stderr and "words changed" in converted.stderr
    assert not (tmp_path / "-").exists()
    checked = runner.invoke(main, ["check", "-", "-p", "iso-mill"], input=sample_program)
    assert "<stdin>:2:4: info TG133" in checked.stdout
    tape = runner.invoke(main, ["tape", "encode", "-", "-o", "-", "--code", "eia"],
                         input=sample_program)
    assert tape.exit_code == 0 and "<stdout>: 248 bytes, EIA code" in tape.stderr
    back = runner.invoke(main, ["tape", "decode", "-", "-o", "-"], input=tape.stdout_bytes)
    assert back.stdout == sample_program


def test_counts_are_written_as_a_person_would(tmp_path):
    """'1 comment', not '1 comments'; a file that could not be read is not counted as clean."""
    path = tmp_path / "p.nc"
    path.write_text("%\nN1 G71 X1. (ONE)\nM30\n%\n")
    summary = CliRunner().invoke(main, ["parse", str(path), "--summary", "-p", "iso-mill"])
    assert ": 4 blocks, 4 words, 1 comment (text)" in summary.stdout
    missing = CliRunner().invoke(main, ["check", str(tmp_path / "nope.nc"), "-p", "iso-mill"])
    assert missing.exit_code == 2
    assert "0 files checked (1 not read): 0 errors, 0 warnings, 0 notes" in missing.stderr


def test_a_bad_since_is_a_usage_error():
    result = CliRunner().invoke(main, ["journal", "j.jsonl", "--since", "yesterday"])
    assert result.exit_code == 2
    assert "Invalid value for --since" in result.stderr and "2026-11-21" in result.stderr


def test_outputs_are_written_one_way(tmp_path, sample_program):
    """One atomic write for every command: a missing folder is an error naming the file the
    user gave (not a temporary name, not 'cannot read'), exit 2 (1 for a failed conversion in
    the batch table); the file gets the mode of the umask (convert wrote 0600)."""
    import os

    path = tmp_path / "p.nc"
    path.write_text(sample_program)
    missing = tmp_path / "nowhere" / "x"
    for args, code in ((["tape", "encode", str(path), "-o", f"{missing}.tap"], 2),
                       (["tape", "decode", str(path), "-o", f"{missing}.nc"], 2),
                       (["plot", str(path), "-o", f"{missing}.svg", "-p", "iso-mill"], 2),
                       (["convert", str(path), "-o", f"{missing}.nc", "--to", "iso-mill"], 1)):
        result = CliRunner().invoke(main, args)
        assert result.exit_code == code, (args, result.output)
        assert f"cannot write {missing}." in result.stderr and "no such folder" in result.stderr
        assert ".part" not in result.stderr
    assert not missing.parent.exists()
    old = os.umask(0o022)
    try:
        out = tmp_path / "out.nc"
        assert CliRunner().invoke(main, ["convert", str(path), "-o", str(out), "--to",
                                         "iso-mill"]).exit_code == 0
        assert oct(out.stat().st_mode & 0o777) == "0o644"
    finally:
        os.umask(old)
    assert not [p for p in tmp_path.iterdir() if p.name.endswith(".part")]


def test_convert_force_keeps_the_mode_of_the_file_it_replaces(tmp_path, sample_program):
    """`convert --force` onto a 0640 program left it 0644 (review 42, finding 5): it stays
    0640, and a new output follows the umask (0644 under 022)."""
    import os

    path = tmp_path / "p.nc"
    path.write_text(sample_program)
    kept, new = tmp_path / "kept.nc", tmp_path / "new.nc"
    kept.write_text("old\n")
    kept.chmod(0o640)
    old = os.umask(0o022)
    try:
        for out in (kept, new):
            result = CliRunner().invoke(main, ["convert", str(path), "-o", str(out), "--to",
                                               "iso-mill", "--force"])
            assert result.exit_code == 0, result.output
    finally:
        os.umask(old)
    assert kept.read_text() == new.read_text() != "old\n"
    assert oct(kept.stat().st_mode & 0o777) == "0o640"
    assert oct(new.stat().st_mode & 0o777) == "0o644"


def test_the_help_lists_every_command_in_a_whole_sentence():
    """The one-line summaries were cut short ('...against a...')."""
    lines = CliRunner().invoke(main, ["--help"]).stdout.split("Commands:")[1].splitlines()
    summaries = [line.split(None, 1)[1] for line in lines if line.strip()]
    assert len(summaries) == 15  # diff, password and fleet included
    assert all(s.endswith(".") and not s.endswith("...") for s in summaries), summaries


def test_plot_without_matplotlib_says_how_to_install_it(tmp_path, sample_program, monkeypatch):
    import sys

    path = tmp_path / "p.nc"
    path.write_text(sample_program)
    monkeypatch.delitem(sys.modules, "postproc.plot", raising=False)
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # import matplotlib fails
    result = CliRunner().invoke(main, ["plot", str(path), "-o", str(tmp_path / "p.svg"),
                                       "-p", "iso-mill"])
    assert result.exit_code == 2
    assert "pip install 'tapegate[plot]'" in result.stderr
    assert result.exception is None or isinstance(result.exception, SystemExit)


def test_g20_g21_found_without_a_profile_are_the_units_codes_not_unassigned_codes(tmp_path):
    """Without --profile, a program that selects its units with G21 is read with G20/G21 as its
    units codes: designated, as a profile's units_codes designates them (it said TG302 'G21 is
    unassigned' next to the note that G20/G21 were found)."""
    path = tmp_path / "p.nc"
    path.write_text("%\nO01010\nN1 G21\nN2 G1 X10. F100\nN3 M30\n%\n")
    result = CliRunner().invoke(main, ["check", str(path)])
    assert "units codes G20/G21 (G21 found)" in result.stderr
    assert "TG302" not in result.stdout and result.exit_code == 0, result.stdout


def test_a_report_on_an_output_that_cannot_encode_its_text_escapes_it(tmp_path):
    """Text outside ASCII in a comment is named in the report (TG127); on a stdout whose
    encoding cannot hold it (PYTHONIOENCODING=ascii, a cp1252 console with Chinese text) the
    character is written as an escape, with one worker or two, and no traceback."""
    import os
    import subprocess
    import sys
    from pathlib import Path

    program = tmp_path / "p.nc"
    program.write_bytes("%\nO1\n(PRÜFUNG 中)\nG21 G0 X1.\nM30\n%\n".encode())
    exe = Path(sys.executable).with_name("tapegate")
    env = {**os.environ, "PYTHONIOENCODING": "ascii"}
    for args in ([str(program)], [str(program), str(program), "-j", "2"]):
        run = subprocess.run([str(exe), "check", *args, "-p", "fanuc-mill"], env=env,
                             capture_output=True, timeout=60)
        assert run.returncode == 0, run.stderr
        assert b"Traceback" not in run.stderr
        assert b"TG127" in run.stdout and b"\\xdc" in run.stdout
