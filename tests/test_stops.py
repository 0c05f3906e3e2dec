"""A stop (^C, SIGTERM) whose exception the interpreter swallowed is still obeyed.

A signal's handler raises its exception wherever Python code runs next; where that is a
finalizer (a ``__del__``, a weak reference's callback: an import's module lock freed, a
collection), the interpreter prints it as "Exception ignored" and goes on. A command then
waiting on a FIFO whose writer never ends, or on a pipe nobody reads, waited for ever: 1 in some
hundred CI runs (the ^C of `check FIFO`, the SIGTERM of `convert -o -`). The handlers note the
signal, and the waits ask first (``formats.stops``). The finalizer here takes the
signal on purpose, so the swallow happens every time."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent

SWALLOW = """
import os, sys
from formats.files import exit_on_termination
from formats.stops import note_interrupts
exit_on_termination()
note_interrupts()
class Finalized:
    def __del__(self):
        os.kill(os.getpid(), {signum})
        for _ in range(10000):  # the handler runs here, in the finalizer: its exception is lost
            pass
Finalized()
print("swallowed", file=sys.stderr, flush=True)
"""


def _run(script: str, stdout: int = subprocess.PIPE) -> subprocess.CompletedProcess[bytes]:
    return subprocess.run([sys.executable, "-c", script], stdout=stdout, stderr=subprocess.PIPE,
                          timeout=60, env={**os.environ, "PYTHONPATH": str(ROOT)}, check=False,
                          preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGINT])
def test_a_swallowed_stop_ends_a_write_into_a_pipe_nobody_reads(signum: int) -> None:
    reader, writer = os.pipe()  # (nobody reads it: the write would wait for ever)
    try:
        script = SWALLOW.format(signum=int(signum)) + (
            "from tapegate.common import write_stream\n"
            "try:\n"
            "    write_stream('-', [b'x' * 1_000_000])\n"
            "except KeyboardInterrupt:\n"
            "    sys.exit(1)\n"
            "print('not stopped', file=sys.stderr)\n")
        done = _run(script, stdout=writer)
    finally:
        os.close(reader)
        os.close(writer)
    assert b"swallowed" in done.stderr and b"not stopped" not in done.stderr
    assert done.returncode == (1 if signum == signal.SIGINT else 128 + signal.SIGTERM)


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGINT])
def test_a_swallowed_stop_ends_the_copy_of_a_fifo_whose_writer_never_ends(
        tmp_path: Path, signum: int) -> None:
    fifo = tmp_path / "f.nc"
    os.mkfifo(fifo)
    writer = os.open(fifo, os.O_RDWR)  # (a writer that never closes)
    try:
        os.write(writer, b"%\nO1000\n")
        script = SWALLOW.format(signum=int(signum)) + (
            "from tapegate.common import input_path\n"
            "try:\n"
            f"    input_path({str(fifo)!r})\n"
            "except KeyboardInterrupt:\n"
            "    sys.exit(1)\n"
            "print('not stopped', file=sys.stderr)\n")
        done = _run(script)
    finally:
        os.close(writer)
    assert b"swallowed" in done.stderr and b"not stopped" not in done.stderr
    assert done.returncode == (1 if signum == signal.SIGINT else 128 + signal.SIGTERM)


def test_a_stop_taken_as_usual_is_not_raised_twice() -> None:
    """The note is only read before a wait: a command that handled its stop (the exception
    raised where it should be) ends with it once."""
    script = ("import os, signal, sys\n"
              "from formats.stops import note_interrupts\nnote_interrupts()\n"
              "try:\n    os.kill(os.getpid(), signal.SIGINT)\n"
              "    for _ in range(10000): pass\n"
              "except KeyboardInterrupt:\n    print('taken', file=sys.stderr)\n")
    done = _run(script)
    assert done.returncode == 0 and done.stderr == b"taken\n"
