"""An input that is not a regular file (review 42, finding 6): a FIFO that no program writes
hung `check` for good (its open waits for a writer, in the core, the GIL released: no ^C
reached it), so it is refused up front, as a file that cannot be read (exit 2), by every
command that reads programs; a character device or a socket is refused unopened. A pipe given
by its name that a program writes (`<(cmd)`, `/dev/stdin` piped in, a FIFO whose writer is
there) is read to its end and copied, as `-` is: read by name it gave its bytes to the first
reading, and a check without --profile, parse, diff and convert saw an empty program.

Every command runs as a child process with a timeout (a hang fails the test instead of
hanging the suite)."""

from __future__ import annotations

import array
import fcntl
import os
import re
import signal
import socket
import stat
import subprocess
import sys
import termios
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PROGRAM = "%\nO1000\nG21 G90 G54\nG0 X1. Y2.\nG1 X5. F100.\nM30\n%\n"
REFUSED = "a pipe (FIFO) with no writer and nothing in it"


def _exe() -> str:
    return str(Path(sys.executable).with_name("tapegate"))


def _run(args: list[str], cwd: Path, **kw: object) -> subprocess.CompletedProcess[str]:
    return subprocess.run([_exe(), *args], cwd=cwd, capture_output=True, text=True,
                          timeout=60, **kw)  # type: ignore[call-overload]


def _commands(name: str) -> list[list[str]]:
    """Every command that reads a program, given ``name`` where the program goes."""
    return [["check", name, "-p", "fanuc-mill"],
            ["check", name],  # (the profile detected from its head: a second reading)
            ["parse", name, "--json"],
            ["diff", name, "a.nc"],
            ["convert", name, "--to", "fanuc-mill", "-o", "out.nc"],
            ["tape", "encode", name, "-o", "out.tap"],
            ["tape", "detect", name]]


def test_a_fifo_no_program_writes_is_refused_by_every_command(tmp_path: Path) -> None:
    (tmp_path / "a.nc").write_text(PROGRAM)
    os.mkfifo(tmp_path / "f.nc")
    for args in _commands("f.nc"):
        done = _run(args, tmp_path)
        assert done.returncode == 2, (args, done.stderr)
        assert f"tapegate: cannot read f.nc: {REFUSED}" in done.stderr, (args, done.stderr)
        assert "Traceback" not in done.stderr
    assert stat.S_ISFIFO(os.stat(tmp_path / "f.nc").st_mode)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.nc", "f.nc"]  # nothing written


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_a_batch_with_a_fifo_checks_the_other_files_and_exits_2(tmp_path: Path,
                                                               jobs: str) -> None:
    """The refusal is the FIFO's line at its turn, as a missing file's; the others are
    checked (the review's hang: `check a b fifo d -j 2`)."""
    for name in ("a.nc", "b.nc", "d.nc"):
        (tmp_path / name).write_text(PROGRAM)
    os.mkfifo(tmp_path / "c.nc")
    done = _run(["check", "a.nc", "b.nc", "c.nc", "d.nc", "-p", "fanuc-mill", "-j", jobs,
                 "--format", "jsonl"], tmp_path)
    assert done.returncode == 2, done.stderr
    assert f"tapegate: cannot read c.nc: {REFUSED}" in done.stderr
    files = {line.split('"file": "')[1].split('"')[0] for line in done.stdout.splitlines()
             if '"file": "' in line}
    assert files <= {"a.nc", "b.nc", "d.nc"}


def test_a_device_and_a_socket_are_refused_unopened(tmp_path: Path) -> None:
    """/dev/null read as an empty program, a terminal or a serial port would be waited on (and
    opened: a port's open acts on the line): not a file to read; `-` reads standard input."""
    (tmp_path / "a.nc").write_text(PROGRAM)
    server = socket.socket(socket.AF_UNIX)
    try:
        server.bind(str(tmp_path / "s.nc"))
        for name, kind in (("/dev/null", "a character device"), ("s.nc", "a socket")):
            for args in _commands(name):
                done = _run(args, tmp_path)
                assert done.returncode == 2, (args, done.stderr)
                assert (f"tapegate: cannot read {name}: not a regular file but {kind} "
                        "(- reads standard input)") in done.stderr, (args, done.stderr)
    finally:
        server.close()


def test_a_folder_lists_no_fifo_device_or_socket(tmp_path: Path) -> None:
    """A folder's listing has files and links only (tapegate.workers.folder_files): a FIFO
    in it is not a file of the batch, neither checked nor waited for."""
    folder = tmp_path / "d"
    folder.mkdir()
    (folder / "a.nc").write_text(PROGRAM)
    os.mkfifo(folder / "f.nc")
    server = socket.socket(socket.AF_UNIX)
    try:
        server.bind(str(folder / "s.nc"))
        for args in (["check", "d", "-p", "fanuc-mill", "-j", "2"],
                     ["convert", "d", "--to", "fanuc-mill", "--out-dir", "out"]):
            done = _run(args, tmp_path)
            assert done.returncode == 0, (args, done.stderr)
            assert "f.nc" not in done.stderr + done.stdout
        assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["a.nc"]
    finally:
        server.close()


def test_a_pipe_a_program_writes_is_read_whole_by_every_command(tmp_path: Path) -> None:
    """`tapegate parse <(cat a.nc)`: the pipe is read to its end once, and every reading
    after (detection, parameters, the conversion) reads the copy: the same output as the
    file's, named as the user named the pipe."""
    (tmp_path / "a.nc").write_text(PROGRAM)
    for args in [*_commands("a.nc"), ["convert", "a.nc", "--to", "fanuc-mill", "-o", "-"],
                 ["parse", "a.nc", "--reprint"]]:
        if args[0] == "convert" and "out.nc" in args:
            continue  # (-o -, below, shows the output)
        want = _run(args, tmp_path)
        line = " ".join("<(cat a.nc)" if a == "a.nc" and i == 1 + (args[0] == "tape") else a
                        for i, a in enumerate(args))
        got = subprocess.run(["bash", "-c", f"{_exe()} {line}"], cwd=tmp_path,
                             capture_output=True, text=True, timeout=60)
        assert got.returncode == want.returncode, (line, got.stderr)
        for ours, theirs in ((got.stdout, want.stdout), (got.stderr, want.stderr)):
            # (bash's first pipe is /dev/fd/63; a table's columns and rule are as wide as the
            # name)
            assert _words(ours.replace("/dev/fd/63", "a.nc")) == _words(theirs), line
    assert (tmp_path / "out.tap").exists()


def _words(text: str) -> str:
    return re.sub(r"[\s-]+", " ", text)


def test_a_pipe_from_standard_input_named_dev_stdin_is_read(tmp_path: Path) -> None:
    (tmp_path / "a.nc").write_text(PROGRAM)
    with open(tmp_path / "a.nc", "rb") as program:
        piped = subprocess.Popen(["cat"], stdin=program, stdout=subprocess.PIPE)
        assert piped.stdout is not None
        done = _run(["parse", "/dev/stdin", "--reprint"], tmp_path, stdin=piped.stdout)
        piped.stdout.close()
        piped.wait(timeout=60)
    assert done.returncode == 0, done.stderr
    assert done.stdout == PROGRAM


def _queued(fd: int) -> int:
    got = array.array("i", [0])
    fcntl.ioctl(fd, termios.FIONREAD, got)
    return got[0]


@pytest.mark.parametrize("args", [["check", "-p", "fanuc-mill"],
                                  ["check", "-p", "fanuc-mill", "-j", "2", "a.nc"],
                                  ["convert", "--to", "fanuc-mill", "-o", "out.nc"]])
def test_a_fifo_whose_writer_never_ends_stops_at_the_first_ctrl_c(tmp_path: Path,
                                                                  args: list[str]) -> None:
    """A FIFO whose writer is there is read as a stream the user opened on purpose, to its
    end; one that never ends is read until ^C, which ends the command at once ("Aborted!",
    exit 1): it is read in the main thread, where the signal is taken."""
    (tmp_path / "a.nc").write_text(PROGRAM)
    fifo = tmp_path / "f.nc"
    os.mkfifo(fifo)
    writer = os.open(fifo, os.O_RDWR)  # (a writer that never closes: opened without a reader)
    try:
        os.write(writer, PROGRAM[:20].encode())
        proc = subprocess.Popen(
            [_exe(), *args[:1], "f.nc", *args[1:]], cwd=tmp_path, stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            # (a suite run in the background may inherit SIGINT ignored)
            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
        try:
            waited = time.monotonic()
            while _queued(writer):  # until the command has read what was written
                assert proc.poll() is None and time.monotonic() - waited < 60
                time.sleep(0.01)
            proc.send_signal(signal.SIGINT)
            _, err = proc.communicate(timeout=30)
        finally:
            if proc.poll() is None:
                proc.kill()
                proc.wait()
        assert proc.returncode == 1, err
        assert err.endswith(b"Aborted!\n") and b"Traceback" not in err, err
    finally:
        os.close(writer)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.nc", "f.nc"]


_NO_ROOM_FOR_THE_COPY = """
import errno, os, sys, tempfile
from tapegate.launch import main

made = tempfile.NamedTemporaryFile
class Full:
    def __init__(self, *args, **kwargs):
        self.file = made(*args, **kwargs)
        self.name = self.file.name
    def write(self, data):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
    def flush(self):
        self.file.flush()
    def close(self):
        self.file.close()
tempfile.NamedTemporaryFile = Full
sys.argv = ["tapegate", *sys.argv[1:]]
main(clean_exit=True)
"""


@pytest.mark.parametrize("args", [["check", "-", "-p", "fanuc-mill"],
                                  ["convert", "-", "--to", "fanuc-mill", "-o", "out.nc"]])
def test_standard_input_whose_copy_finds_no_room_says_so(tmp_path: Path,
                                                        args: list[str]) -> None:
    """Standard input is copied to the temporary folder first: a copy that finds no room
    there is told as such, naming the folder, not as the input's own error ("cannot read
    <stdin>: No space left on device" blamed the program piped in); exit 2, no copy left."""
    done = subprocess.run([sys.executable, "-c", _NO_ROOM_FOR_THE_COPY, *args],
                          input=PROGRAM, cwd=tmp_path, capture_output=True, text=True,
                          timeout=60, env={**os.environ, "PYTHONPATH": str(ROOT),
                                           "TMPDIR": str(tmp_path)})
    assert done.returncode == 2, done.stderr
    assert (f"tapegate: cannot read <stdin>: cannot copy it to the temporary folder "
            f"{tmp_path}: No space left on device\n") in done.stderr, done.stderr
    assert "Traceback" not in done.stderr
    assert not list(tmp_path.glob("tapegate-stdin-*"))
