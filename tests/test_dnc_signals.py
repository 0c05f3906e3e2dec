"""SIGTERM and SIGINT to a standalone ``send`` or ``receive``: the transfer ends cleanly, it is
journalled ``interrupted``, nothing is left in the receive folder, and the exit code is
``128 + the signal`` (130, 143).

Real signals to a real ``tapegate`` process, whose port is a pseudo-terminal: an emulated
control (a thread of the test) behind it for ``send``, the test punching for ``receive``.
Every wait is on a condition, with a timeout.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from dnc.emulator import Emulator
from dnc.journal import read_journal
from dnc.session import open_pty
from tests.test_dnc_serial import control_for, program
from tests.test_gateway import until

pytestmark = pytest.mark.timeout(60)

CODES = {signal.SIGINT: 130, signal.SIGTERM: 143}


def tapegate(*args: str) -> subprocess.Popen[str]:
    env = dict(os.environ, PYTHONPATH=str(Path(__file__).resolve().parents[1]))
    return subprocess.Popen([sys.executable, "-m", "tapegate", *args], stderr=subprocess.PIPE,
                            stdout=subprocess.DEVNULL, text=True, env=env)


def ended(proc: subprocess.Popen[str]) -> str:
    try:
        _, err = proc.communicate(timeout=20)
    finally:
        if proc.poll() is None:
            proc.kill()
    assert "Traceback" not in err, err
    return err


@pytest.mark.parametrize("number", [signal.SIGTERM, signal.SIGINT])
def test_a_signal_ends_a_send_cleanly_and_journals_it(tmp_path: Path, number: int) -> None:
    src = tmp_path / "p.nc"
    src.write_text(program(300))
    journal = tmp_path / "journal.jsonl"
    # a control that reads 2,000 characters a second: the send takes several seconds
    control = control_for("fanuc-mill", baud=115200, buffer=64, rate=2000.0)
    emu = Emulator(control)
    try:
        proc = tapegate("send", str(src), "--port", emu.path, "-p", "fanuc-mill", "--baud",
                        "115200", "--xon-timeout", "5", "--journal", str(journal))
        assert until(lambda: control.stats.chars > 500), "the send did not start"
        proc.send_signal(number)
        err = ended(proc)
    finally:
        emu.stop()
    name = signal.Signals(number).name
    assert proc.returncode == CODES[number], err
    assert f"tapegate: {name}: interrupted at line" in err
    (record,) = read_journal(journal).transfers
    assert (record.direction, record.result) == ("send", "interrupted")
    assert 500 <= record.bytes < len(src.read_bytes())
    assert record.errors[0].startswith("interrupted at line")
    assert len(record.sha256) == 64
    assert sorted(p.name for p in tmp_path.iterdir()) == ["journal.jsonl", "p.nc"]


def test_sigterm_while_waiting_for_the_next_pass(tmp_path: Path) -> None:
    """With --repeat the command waits for the control's next DC1 for as long as it takes; a
    SIGTERM then ends it, and the pass it was waiting for is journalled."""
    src = tmp_path / "p.nc"
    src.write_text(program(5))
    journal = tmp_path / "journal.jsonl"
    control = control_for("fanuc-mill", baud=115200, programs=1)
    emu = Emulator(control)
    try:
        proc = tapegate("send", str(src), "--port", emu.path, "-p", "fanuc-mill", "--baud",
                        "115200", "--xon-timeout", "5", "--repeat", "--journal", str(journal))
        assert until(lambda: journal.exists() and len(read_journal(journal).transfers) == 1)
        proc.send_signal(signal.SIGTERM)
        err = ended(proc)
    finally:
        emu.stop()
    assert proc.returncode == 143, err
    assert [t.result for t in read_journal(journal).transfers] == ["ok", "interrupted"]


@pytest.mark.parametrize("number", [signal.SIGTERM, signal.SIGINT])
def test_a_signal_ends_a_receive_cleanly_and_leaves_nothing(tmp_path: Path,
                                                            number: int) -> None:
    folder = tmp_path / "in"
    folder.mkdir()
    journal = tmp_path / "journal.jsonl"
    pty = open_pty()
    try:
        proc = tapegate("receive", "--port", pty.path, "-p", "fanuc-mill", "-o",
                        f"{folder}/", "--journal", str(journal), "--idle", "30")
        # receive is capturing once its temporary file exists
        assert until(lambda: any(folder.iterdir())), "receive did not start"
        half = program(40).encode("ascii")[:300]  # a program cut off: no closing %, no DC4
        os.write(pty.master, b"\x12" + half)
        # FIONREAD could say 0 before the kernel had handed the bytes over, and the signal
        # came before receive had read them (0 bytes journalled)
        assert until(lambda: not pty.unread()), "receive did not read the data"
        proc.send_signal(number)
        err = ended(proc)
    finally:
        pty.close()
    name = signal.Signals(number).name
    assert proc.returncode == CODES[number], err
    assert f"tapegate: {name}: interrupted after" in err and "nothing written" in err
    assert list(folder.iterdir()) == []  # no .part file, no program
    (record,) = read_journal(journal).transfers
    assert (record.direction, record.result) == ("receive", "interrupted")
    assert record.bytes == len(half) + 1
    assert record.errors == [f"{name} after {len(half) + 1} bytes: nothing written"]
