"""A conversion's notes are said as they come and not kept: the core hands them over after each
chunk, a note that names its line is said once on that line, and the command line's batches
keep the first thousand of a file in memory and spill the rest to a file (flat memory for a
program with a note per word, the output byte for byte what it was)."""

from __future__ import annotations

import os
from pathlib import Path

from click.testing import CliRunner

from formats import _core
from formats.conversion import NOTES_HELD
from formats.convert import (
    Converter,
    ConvertOptions,
    analyse_parameters,
    convert_file,
    convert_text,
)
from formats.errors import ConversionError
from formats.machine import machine
from formats.profile import load_profile
from tapegate.cli import main

LINUXCNC = load_profile("linuxcnc")
OPTIONS = ConvertOptions(LINUXCNC, LINUXCNC, units="inch", allow_unconverted=True)
WHY = ("left unconverted: #<a> is read as a length (line 2) but not set in this program: its "
       "value comes from a caller or the control, in units this conversion does not change")


def _program(lines: int) -> str:
    """A note per word: #<a> is read as a length and never set. X is written twice on a line:
    the same note twice on one line is said once."""
    return "G21\n" + "".join(f"G1 X[#<a>*{i}.] Y[#<a>*{i}.] X[#<a>*{i}.]\n"
                             for i in range(lines))


def _expected(lines: int) -> list[str]:
    return [f"line {i + 2}: {letter}[#<a>*{i}.] {WHY}"
            for i in range(lines) for letter in "XY"]


def test_a_note_naming_its_line_is_said_once_on_that_line_and_again_on_another():
    _, stats = convert_text(_program(3), OPTIONS, file="p.ngc")
    assert stats.notes == _expected(3)


def test_the_core_hands_its_notes_over_and_keeps_none():
    whole, stats = convert_text(_program(3), OPTIONS, file="p.ngc")
    parameters = analyse_parameters([_program(3)], LINUXCNC)
    converter = Converter(OPTIONS, LINUXCNC, file="p.ngc", parameters=parameters)
    chunks = [_program(3)[:40], _program(3)[40:]]
    assert "".join(converter.convert_stream(chunks, LINUXCNC.dialect)) == whole
    assert converter.stats.notes == stats.notes and len(stats.notes) > 3
    # the core's own list is empty: every note was taken (after each chunk and at the end)
    assert converter._core.stats["notes"] == []
    assert converter._core.take_notes() == []


def test_notes_without_a_line_are_said_once_per_conversion():
    core = _core.Converter(machine(LINUXCNC), machine(load_profile("iso-mill")),
                           {"units": None, "rounding": "half-even", "spacing": "keep",
                            "allow_unconverted": False, "parameters": None,
                            "source_detected": False, "source_units_given": False,
                            "upper_case": False,
                            "read_units": []}, None,
                           "p.ngc")
    core.convert_lines("G21\nG1 X1. Q1.\nG1 X2. Q2.", 0, LINUXCNC.dialect.flags)
    first = core.take_notes()
    assert any(note.startswith("address Q is not in the target classification") for note in
               first), first
    core.convert_lines("G1 Q3.", 3, LINUXCNC.dialect.flags)
    assert core.take_notes() == []  # said once, not again on line 4


def test_a_file_of_many_notes_spills_them_after_the_first_thousand(tmp_path):
    lines = NOTES_HELD  # two notes a line: half of them spilled
    source = tmp_path / "p.ngc"
    source.write_text(_program(lines))
    spill = tmp_path / "spill"
    spill.mkdir()
    stats = convert_file(str(source), str(tmp_path / "out.ngc"), OPTIONS, notes_spill=str(spill))
    expected = _expected(lines)
    assert stats.notes == expected[:NOTES_HELD]
    assert stats.notes_spill is not None and Path(stats.notes_spill).parent == spill
    assert Path(stats.notes_spill).read_text().splitlines() == [
        f"{source}: {note}" for note in expected[NOTES_HELD:]]
    # without a folder to spill to (the API), every note is kept as before
    stats = convert_file(str(source), str(tmp_path / "out2.ngc"), OPTIONS)
    assert stats.notes == expected and stats.notes_spill is None
    assert (tmp_path / "out.ngc").read_bytes() == (tmp_path / "out2.ngc").read_bytes()


def test_a_failed_conversion_tells_its_error_and_leaves_no_spilled_notes(tmp_path):
    source = tmp_path / "p.ngc"
    source.write_text(_program(NOTES_HELD) + "G1 X12345678.\n")  # too long in inch
    spill = tmp_path / "spill"
    spill.mkdir()
    # (LinuxCNC to LinuxCNC: a named parameter is not carried to another family)
    options = ConvertOptions(LINUXCNC, LINUXCNC, units="inch", allow_unconverted=True)
    try:
        convert_file(str(source), str(tmp_path / "out.nc"), options, notes_spill=str(spill))
    except ConversionError as exc:
        assert exc.code and exc.line == NOTES_HELD + 2
    else:
        raise AssertionError("X12345678. converted")
    assert os.listdir(spill) == [] and not (tmp_path / "out.nc").exists()


def test_the_command_prints_every_note_in_order_with_one_or_two_workers(tmp_path):
    cam = tmp_path / "cam"
    cam.mkdir()
    (cam / "a.ngc").write_text(_program(NOTES_HELD))  # 2,000 notes: 1,000 spilled
    (cam / "b.ngc").write_text(_program(2))
    (cam / "c.nc").write_text("G21\nG1 X12345678.\n")  # fails: its error, no notes
    said = {}
    for jobs in ("1", "2"):
        result = CliRunner().invoke(main, [
            "convert", str(cam), "--out-dir", str(tmp_path / f"out{jobs}"), "--from", "linuxcnc",
            "--to", "linuxcnc", "--units", "inch", "--allow-unconverted", "-j", jobs])
        assert result.exit_code == 1, result.output
        said[jobs] = result.stderr
    assert said["1"] == said["2"]
    lines = said["1"].splitlines()
    assert lines[:NOTES_HELD * 2] == [f"{cam / 'a.ngc'}: {note}"
                                      for note in _expected(NOTES_HELD)]
    assert lines[NOTES_HELD * 2:NOTES_HELD * 2 + 4] == [f"{cam / 'b.ngc'}: {note}"
                                                        for note in _expected(2)]
    assert lines[-1].startswith(f"{cam / 'c.nc'}:2:4: X12345678.")
    assert len(lines) == NOTES_HELD * 2 + 5


def test_the_notes_folder_is_made_only_for_a_file_that_spills_and_removed(tmp_path):
    """tapegate.converting.SpillFolder: a batch whose files keep their notes in memory makes
    no temporary folder (nor imports tempfile); one with a file of more than a thousand notes
    makes one, every note is printed, and nothing is left in the temporary folder, with one
    worker or two."""
    import subprocess
    import sys

    root = Path(__file__).resolve().parent.parent
    cam = tmp_path / "cam"
    cam.mkdir()
    (cam / "a.ngc").write_text(_program(2))
    (cam / "b.ngc").write_text(_program(3))
    probe = ("import os, sys\nfrom tapegate.launch import main\n"
             "made = []\nmkdir = os.mkdir\n"
             "def watched(path, *args, **kwargs):\n"
             "    made.append(os.path.basename(path))\n"
             "    return mkdir(path, *args, **kwargs)\n"
             "os.mkdir = watched\n"
             "sys.argv = ['tapegate', *sys.argv[1:]]\n"
             "try:\n    main(clean_exit=True)\nfinally:\n"
             "    print('MADE', [m for m in made if m.startswith('tapegate-notes-')], "
             "'tempfile' in sys.modules, file=sys.stderr)\n")
    for long_file, jobs in ((False, "1"), (False, "2"), (True, "1"), (True, "2")):
        if long_file:
            (cam / "c.ngc").write_text(_program(NOTES_HELD))  # 2,000 notes: 1,000 spilled
        temporary = tmp_path / f"tmp-{long_file}-{jobs}"
        temporary.mkdir()
        done = subprocess.run(
            [sys.executable, "-c", probe, "convert", str(cam), "--out-dir",
             str(tmp_path / "out"), "--force", "--from", "linuxcnc", "--to", "linuxcnc",
             "--units", "inch", "--allow-unconverted", "-j", jobs],
            capture_output=True, text=True, check=False, timeout=120,
            env={**os.environ, "PYTHONPATH": str(root), "TMPDIR": str(temporary)})
        assert done.returncode == 0, done.stderr
        made = done.stderr.splitlines()[-1]
        assert made.startswith("MADE ['tapegate-notes-") if long_file else (
            made == "MADE [] False"), made
        notes = [line for line in done.stderr.splitlines() if line.startswith(str(cam))]
        assert len(notes) == 2 * 2 + 3 * 2 + (2 * NOTES_HELD if long_file else 0)
        assert os.listdir(temporary) == []


def _no_room_for_notes(monkeypatch, after: int = 1) -> list[int]:
    """os.write refused with ENOSPC for a spill file of notes (``notes-*``) once ``after``
    writes to such files went through (the disk full meanwhile); the count of attempts."""
    import errno

    write = os.write
    tried = [0]

    def filling(fd: int, data: bytes) -> int:
        try:
            spill = os.path.basename(os.readlink(f"/proc/self/fd/{fd}")).startswith("notes-")
        except OSError:
            spill = False
        if spill:
            tried[0] += 1
            if tried[0] > after:
                raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
            if tried[0] == after:  # a part written, then no room: cut back, never read
                write(fd, data[:len(data) // 2])
                raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        return write(fd, data)

    monkeypatch.setattr(os, "write", filling)
    return tried


def test_notes_whose_spill_fails_are_kept_in_memory_in_their_order(tmp_path, monkeypatch):
    """Review 75, N1, in convert: the spill of a file's notes failing (no room) midway lost
    them and failed the file. The notes written whole stay in the file, the rest are held in
    memory after them: every note comes back once, in order, and the failure is noted."""
    source = tmp_path / "p.ngc"
    source.write_text(_program(3 * NOTES_HELD))  # 6,000 notes: 5,000 past the first thousand
    spill = tmp_path / "spill"
    spill.mkdir()
    tried = _no_room_for_notes(monkeypatch, after=3)
    stats = convert_file(str(source), str(tmp_path / "out.ngc"), OPTIONS, notes_spill=str(spill))
    assert tried[0] >= 3 and stats.notes_kept  # (the spill did fail, after some writes)
    assert stats.notes == _expected(3 * NOTES_HELD)[:NOTES_HELD]
    rest = "".join(stats.notes_after()).splitlines()
    assert rest == [f"{tmp_path / 'p.ngc'}: {note}"
                    for note in _expected(3 * NOTES_HELD)[NOTES_HELD:]]
    assert stats.notes_unspilled == (f"cannot write the notes waiting for the summary to "
                                     f"{spill}: No space left on device; they are held in "
                                     f"memory instead")
    assert os.listdir(spill) == []  # (the spill file read and removed)
    assert (tmp_path / "out.ngc").exists() and not stats.error


def test_convert_whose_notes_cannot_be_spilled_converts_and_prints_every_note(tmp_path,
                                                                              monkeypatch):
    """`convert` of files of thousands of notes where the notes' spill fails (its folder
    cannot be made, or its writes find no room): each file converted, its output as without
    the failure, every note printed in order, with one or two workers; the failure told once,
    before the first notes held. (Before: "FILE: No space left on device", the file FAILED,
    its output not written, its notes lost.)"""
    import tempfile

    cam = tmp_path / "cam"
    cam.mkdir()
    for name, lines in (("a.ngc", NOTES_HELD), ("b.ngc", 2), ("c.ngc", 2 * NOTES_HELD)):
        (cam / name).write_text(_program(lines))

    def run(out: str, jobs: str) -> tuple[int, str, dict[str, bytes]]:
        result = CliRunner().invoke(main, [
            "convert", str(cam), "--out-dir", str(tmp_path / out), "--from", "linuxcnc",
            "--to", "linuxcnc", "--units", "inch", "--allow-unconverted", "-j", jobs])
        outputs = {p.name: p.read_bytes() for p in sorted((tmp_path / out).iterdir())}
        return result.exit_code, result.stderr, outputs

    clean = run("clean", "1")
    assert clean[0] == 0 and len(clean[2]) == 3
    temporary = tempfile.gettempdir()
    for failure in ("write", "folder"):
        with monkeypatch.context() as patched:
            if failure == "write":
                _no_room_for_notes(patched, after=1)
            else:
                def no_folder(*args: object, **kwargs: object) -> str:
                    raise OSError(28, "No space left on device",
                                  os.path.join(temporary, "tapegate-notes-x"))

                patched.setattr(tempfile, "mkdtemp", no_folder)
            for jobs in ("1", "2"):
                code, stderr, outputs = run(f"{failure}{jobs}", jobs)
                told = (f"tapegate: cannot write the notes waiting for the summary to "
                        f"{temporary}: No space left on device; they are held in memory "
                        f"instead\n")
                assert (code, outputs) == (clean[0], clean[2]), (failure, jobs, stderr[-500:])
                assert stderr.count(told) == 1, (failure, jobs, stderr[:500])
                assert stderr.replace(told, "") == clean[1], (failure, jobs)
                assert stderr.index(told) < stderr.index(f"{cam / 'a.ngc'}: ")


def _small_files() -> None:
    """A child's files limited to 64 KiB (a write past it fails with EFBIG, SIGXFSZ
    ignored): an output, or a spill of notes, that finds no room."""
    import resource
    import signal

    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    resource.setrlimit(resource.RLIMIT_FSIZE, (1 << 16, 1 << 16))


def test_an_output_that_finds_no_room_is_told_as_the_outputs(tmp_path):
    """An output whose write fails for want of room (here each file limited to 64 KiB) was
    told as "FILE: File too large", naming the input; it names the output now (and for a dry
    run the temporary folder), while a file that fits converts, its notes all printed (their
    spill past 64 KiB cut short: held in memory)."""
    import subprocess
    import sys

    root = Path(__file__).resolve().parent.parent
    cam = tmp_path / "cam"
    cam.mkdir()
    (cam / "big.ngc").write_text(_program(3000))  # 6,000 notes, an output of 200 kB
    (cam / "small.ngc").write_text(_program(2))
    (cam / "mid.ngc").write_text(_program(NOTES_HELD))  # fits; 1,000 notes past 64 KiB to spill
    common = ["--from", "linuxcnc", "--to", "linuxcnc", "--units", "inch",
              "--allow-unconverted"]
    runs = {}
    for name, where in (("out", ["--out-dir", str(tmp_path / "out")]), ("dry", ["--dry-run"])):
        runs[name] = subprocess.run(
            [sys.executable, "-m", "tapegate", "convert", str(cam), *where, *common],
            capture_output=True, text=True, check=False, timeout=120, preexec_fn=_small_files,
            env={**os.environ, "PYTHONPATH": str(root), "TMPDIR": str(tmp_path)})
    done = runs["out"]
    assert done.returncode == 1
    assert (f"{cam / 'big.ngc'}: cannot write {tmp_path / 'out' / 'big.ngc'}: File too large"
            in done.stderr.splitlines()), done.stderr[-800:]
    lines = done.stderr.splitlines()
    assert f"{cam / 'small.ngc'}: {_expected(2)[0]}" in lines
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["mid.ngc", "small.ngc"]
    told = (f"tapegate: cannot write the notes waiting for the summary to {tmp_path}: File "
            f"too large; they are held in memory instead")
    assert lines.count(told) == 1
    assert [line for line in lines if line.startswith(str(cam / "mid.ngc"))] == [
        f"{cam / 'mid.ngc'}: {note}" for note in _expected(NOTES_HELD)]
    dry = runs["dry"]
    assert dry.returncode == 1
    assert (f"{cam / 'big.ngc'}: cannot write its dry run's output to the temporary folder "
            f"{tmp_path}: File too large" in dry.stderr.splitlines()), dry.stderr[-800:]
    assert "Traceback" not in done.stderr + dry.stderr
