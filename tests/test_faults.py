"""Faults that must leave nothing behind: a full disk on receive (standalone and in the gateway),
a second send to the same emulated control, Modbus requests the gateway cannot serve, and a
gateway port whose driver fails at start. Each test checks the journal and the folder after the
fault, not only the message.

The full disk is a real one: a small tmpfs mounted for the test, filled to a few kilobytes, so
the write, the flush and the close fail with ENOSPC as on a shop's full disk. Mounting needs
root; where it cannot be done those tests are skipped (the close that fails again is also
covered without a mount, in tests/test_files.py).
"""

from __future__ import annotations

import contextlib
import errno
import logging
import os
import shutil
import socket
import struct
import subprocess
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

import dnc.gateway
from dnc.emulator import Emulator
from dnc.gateway import Gateway, Job, Result, State
from dnc.journal import read_journal
from formats.files import PendingFile
from tests.test_dnc_serial import cli, control_for, expected_bytes, program, punch_in_background
from tests.test_gateway import (
    entries,
    free_port,
    journal,
    machine,
    running,
    sent_program,
    until,
    write_config,
)

__all__ = ["running"]  # the gateway fixture, used below

pytestmark = pytest.mark.timeout(60)

FREE = 8192  # bytes left on the full disk


@pytest.fixture
def full_disk(tmp_path: Path) -> Iterator[Path]:
    """A folder on a filesystem with only :data:`FREE` bytes left."""
    disk = tmp_path / "disk"
    disk.mkdir()
    mount = shutil.which("mount")
    if mount is None or os.geteuid() != 0:
        pytest.skip("mounting a small filesystem needs root")
    done = subprocess.run([mount, "-t", "tmpfs", "-o", "size=256k,mode=0777", "tapegate-full",
                           str(disk)], capture_output=True, text=True)
    if done.returncode:
        pytest.skip(f"cannot mount a small filesystem: {done.stderr.strip()}")
    try:
        room = disk / "room"
        room.write_bytes(b"\0" * FREE)
        with open(disk / "filler", "wb", buffering=0) as filler, contextlib.suppress(OSError):
            while True:
                filler.write(b"\0" * 4096)
        room.unlink()
        yield disk
    finally:
        subprocess.run([shutil.which("umount") or "umount", "-l", str(disk)],
                       capture_output=True)


def leftovers(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if p.name != "filler")


# -- a full disk on receive --------------------------------------------------------------------


def test_a_full_disk_fails_the_write_and_the_close_and_discard_still_removes_the_file(
        full_disk: Path) -> None:
    pending = PendingFile(full_disk, "received")
    with pytest.raises(OSError) as failure:
        for _ in range(100):
            pending.write(b"N10 X1. Y2.\n" * 1000)
    assert failure.value.errno == errno.ENOSPC
    with pytest.raises(OSError):  # what is still buffered fails again
        pending.file.flush()
    pending.discard()
    assert leftovers(full_disk) == []


def test_standalone_receive_on_a_full_disk(tmp_path: Path, full_disk: Path) -> None:
    text = program(1500, number=5001)
    assert len(text) > 2 * FREE
    path, thread, pty = punch_in_background(text.encode("ascii"), 50000)
    log = tmp_path / "j.jsonl"
    try:
        result = cli("receive", "--port", path, "-p", "fanuc-mill", "-o", f"{full_disk}/",
                     "--timeout", "10", "--idle", "1", "--journal", str(log))
        thread.join(10)
    finally:
        pty.close()  # type: ignore[attr-defined]
    assert result.exit_code == 2, result.output
    assert "Traceback" not in result.output
    assert f"tapegate: cannot save the program in {full_disk}: No space left on device" in (
        result.output)
    assert leftovers(full_disk) == []
    records = read_journal(log).transfers
    assert [(r.direction, r.result) for r in records] == [("receive", "failed")]
    assert "No space left on device" in records[0].errors[0]
    assert records[0].bytes == len(text)  # read to its end, not cut off at the failure


def test_the_gateway_on_a_full_disk_journals_leaves_nothing_and_keeps_serving(
        tmp_path: Path, full_disk: Path, running: Callable[..., Gateway]) -> None:
    text = program(800, number=5002)
    assert len(text) > FREE
    expected = sent_program(tmp_path, "O1234.nc", program(10))
    config = write_config(tmp_path, 1)
    config.write_text(config.read_text().replace('receive = "received/m0"',
                                                 f'receive = "{full_disk}"'))
    emu = machine(tmp_path, 0, punch=text.encode("ascii"))
    gateway = running(config)
    worker = gateway.port(0)
    try:
        # (the control punches 800 blocks first: a loaded machine needs more than the default)
        assert until(lambda: bool(entries(tmp_path, "failed")), timeout=60.0)
        failed = entries(tmp_path, "failed")[0]
        assert failed.direction == "receive" and "No space left on device" in failed.errors[0]
        assert until(lambda: worker.status.result == Result.WRITE_FAILED)
        assert leftovers(full_disk) == []
        # the port goes on: the control, now in READ mode, is sent a program
        worker.submit(Job("1234", "modbus"))
        assert until(lambda: bool(entries(tmp_path, "ok")))
        assert emu.wait(10)
        # idle again while its control is there (once the emulator stops, its port vanishes
        # and the worker rightly goes offline: asserted after the stop, that was a race)
        assert until(lambda: worker.status.state == State.IDLE)
    finally:
        emu.stop()
    assert emu.control.sink.getvalue() == expected  # type: ignore[union-attr]
    assert worker.is_alive()
    assert leftovers(full_disk) == []
    assert [(t.direction, t.result) for t in journal(tmp_path)] == [("receive", "failed"),
                                                                    ("send", "ok")]


# -- a second send to the same emulated control --------------------------------------------------


def test_a_second_send_to_the_same_emulated_control(tmp_path: Path) -> None:
    """The second open of a pty whose speed is already set changed only what a pty cannot
    keep (7 data bits, parity): Linux refuses that with EINVAL, and pyserial let the
    termios.error out as a traceback. A pty is opened at 8 bits without parity, as it is
    anyway."""
    control = control_for("fanuc-mill", baud=115200, programs=2)
    emu = Emulator(control)
    src = tmp_path / "p.nc"
    src.write_text(program(10))
    log = tmp_path / "j.jsonl"
    try:
        for _ in range(2):
            result = cli("send", str(src), "--port", emu.path, "-p", "fanuc-mill", "--baud",
                         "115200", "--xon-timeout", "5", "--journal", str(log))
            assert result.exit_code == 0, result.output
        assert emu.wait(5)
    finally:
        emu.stop()
    assert control.stats.programs == 2 and not control.stats.errors
    assert control.sink.getvalue() == 2 * expected_bytes(  # type: ignore[union-attr]
        "fanuc-mill", src.read_text())
    assert [r.result for r in read_journal(log).transfers] == ["ok", "ok"]


# -- Modbus requests the gateway cannot serve ------------------------------------------------------


def ask(port: int, pdu: bytes, unit: int = 1, transaction: int = 7) -> bytes:
    """One raw Modbus TCP request; the response's PDU."""
    with socket.create_connection(("127.0.0.1", port), 5) as s:
        s.sendall(struct.pack(">HHHB", transaction, 0, len(pdu) + 1, unit) + pdu)
        head = b""
        while len(head) < 7:
            chunk = s.recv(7 - len(head))
            assert chunk, "the server closed the connection"
            head += chunk
        tid, _, length, answered_unit = struct.unpack(">HHHB", head)
        assert (tid, answered_unit) == (transaction, unit)
        body = b""
        while len(body) < length - 1:
            chunk = s.recv(length - 1 - len(body))
            assert chunk
            body += chunk
        return body


@pytest.mark.parametrize(("pdu", "answer", "writes"), [
    (bytes([0x41, 0, 0]), bytes([0xC1, 1]), False),  # a function code nobody defined
    (bytes([8, 0, 0, 0x12, 0x34]), bytes([0x88, 1]), False),  # diagnostics: not served
    (bytes([43, 14, 1, 0]), bytes([0xAB, 1]), False),  # device identification: not served
    (bytes([4, 0, 0, 0, 126]), bytes([0x84, 3]), False),  # quantity over 125
    (bytes([4, 0, 0, 0, 0]), bytes([0x84, 3]), False),  # quantity 0
    (bytes([1, 0, 0, 0x07, 0xD1]), bytes([0x81, 3]), False),  # 2001 coils
    (bytes([3, 0]), bytes([0x83, 3]), False),  # truncated
    (bytes([4, 0, 0, 0, 1, 0]), bytes([0x84, 3]), False),  # one byte too many
    (bytes([4, 0, 100, 0, 1]), bytes([0x84, 2]), False),  # past the last port: the map's own
    # writes: the function code is checked first, so with writes disabled a malformed write
    # is refused (01) like any other
    (bytes([16, 0, 0, 0, 2, 4, 0, 1]), bytes([0x90, 1]), False),
    (bytes([16, 0, 0, 0, 2, 4, 0, 1]), bytes([0x90, 3]), True),  # byte count 4, 2 bytes given
    (bytes([5, 0, 0, 0x12, 0x34]), bytes([0x85, 3]), True),  # a coil is 0000 or FF00
    (bytes([6, 0, 2]), bytes([0x86, 3]), True),  # truncated
])
def test_modbus_answers_what_it_cannot_serve_as_the_specification_says(
        tmp_path: Path, running: Callable[..., Gateway], caplog: pytest.LogCaptureFixture,
        pdu: bytes, answer: bytes, writes: bool) -> None:
    port = free_port()
    config = write_config(tmp_path, 1, modbus=f"enabled = true\nport = {port}\n"
                          f"allow_write = {str(writes).lower()}")
    gateway = running(config)
    with caplog.at_level(logging.WARNING):
        assert ask(port, pdu) == answer
        assert ask(port, pdu) == answer  # the same again: still answered, logged once
        assert ask(port, bytes([4, 0, 0, 0, 1]))[:2] == bytes([4, 2])  # still serving
    assert not [r for r in caplog.records if r.levelno >= logging.ERROR or r.exc_info]
    said = [r.getMessage() for r in caplog.records if "answered exception" in r.getMessage()]
    assert len(said) == (answer[1] != 2)
    assert gateway.port(0).is_alive()
    assert journal(tmp_path) == []  # a request the map cannot serve is no transfer


def test_modbus_requests_for_another_unit_are_answered_0b_and_logged_once(
        tmp_path: Path, running: Callable[..., Gateway],
        caplog: pytest.LogCaptureFixture) -> None:
    port = free_port()
    config = write_config(tmp_path, 1, modbus=f"enabled = true\nport = {port}\nunit = 1")
    running(config)
    with caplog.at_level(logging.INFO):
        for _ in range(5):
            assert ask(port, bytes([4, 0, 0, 0, 2]), unit=7) == bytes([0x84, 0x0B])
        assert ask(port, bytes([4, 0, 0, 0, 2]), unit=9) == bytes([0x84, 0x0B])
        assert ask(port, bytes([0x41]), unit=7) == bytes([0xC1, 0x0B])
        assert len(ask(port, bytes([4, 0, 0, 0, 2]), unit=1)) == 6  # the right unit: served
    assert not [r for r in caplog.records if r.levelno >= logging.ERROR or r.exc_info]
    said = [r.getMessage() for r in caplog.records if "answered exception 0B" in r.getMessage()]
    assert len(said) == 2 and "unit 7" in said[0] and "unit 9" in said[1]
    assert journal(tmp_path) == []


# -- a port whose driver fails at start ------------------------------------------------------------


def test_a_port_whose_open_fails_unexpectedly_is_retried_not_lost(
        tmp_path: Path, running: Callable[..., Gateway], caplog: pytest.LogCaptureFixture,
        monkeypatch: pytest.MonkeyPatch) -> None:
    """An exception no one foresaw in the driver (pyserial's rfc2217 client raised
    NotImplementedError at open) used to end the port's thread: Modbus showed state 0 forever
    and a send to it vanished. It is retried with backoff like a port that cannot be opened."""
    real = dnc.gateway.open_port
    calls: list[str] = []

    def flaky(url: str, *args: object, **kw: object) -> object:
        calls.append(url)
        if len(calls) <= 3:
            raise RuntimeError("the driver is not ready")
        return real(url, *args, **kw)  # type: ignore[arg-type]

    monkeypatch.setattr(dnc.gateway, "open_port", flaky)
    expected = sent_program(tmp_path, "O1234.nc", program(10))
    config = write_config(tmp_path, 1)
    emu = machine(tmp_path, 0)
    with caplog.at_level(logging.WARNING):
        gateway = running(config)
        worker = gateway.port(0)
        try:
            assert until(lambda: "RuntimeError: the driver is not ready"
                         in worker.status.message or len(calls) > 3)
            assert until(lambda: worker.status.state == State.IDLE)
            worker.submit(Job("1234", "modbus"))
            assert until(lambda: bool(entries(tmp_path, "ok")))
            assert emu.wait(10)
        finally:
            emu.stop()
    assert len(calls) >= 4 and worker.is_alive()
    assert emu.control.sink.getvalue() == expected  # type: ignore[union-attr]
    told = [r for r in caplog.records if "the driver is not ready" in r.getMessage()]
    assert len(told) == 1  # one line per cause, with its traceback
    assert [(t.direction, t.result) for t in journal(tmp_path)] == [("send", "ok")]


# -- a full disk on convert ----------------------------------------------------------------------


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_a_conversion_onto_a_full_disk_names_the_files_that_did_not_fit_and_leaves_no_part(
        tmp_path: Path, full_disk: Path, jobs: str) -> None:
    """The core's commit (one file's and a batch's, the same steps): a file that does not fit
    is that file's error, "No space left on device", its temporary file removed; the files
    that fit are whole (the single conversion's bytes); nothing hidden stays."""
    from click.testing import CliRunner

    from tapegate.cli import main
    from tests.test_convert_interrupt import ARGS, _program

    cam = tmp_path / "cam"
    cam.mkdir()
    text = _program(0, 150)
    for n in range(6):
        (cam / f"p{n}.nc").write_text(text)
    single = tmp_path / "single.nc"
    assert CliRunner().invoke(main, ["convert", str(cam / "p0.nc"), "-o", str(single),
                                     *ARGS]).exit_code == 0
    expected = single.read_bytes()
    assert 2500 < len(expected) < 4096  # (two fit in FREE, on 4 KiB pages)
    out = full_disk / "out"
    result = CliRunner().invoke(main, ["convert", str(cam), "--out-dir", str(out), *ARGS,
                                       "-j", jobs])
    assert result.exit_code == 1, result.output
    written = leftovers(out)
    assert [n for n in written if n.startswith(".")] == []
    assert 1 <= len(written) < 6
    for name in written:
        assert (out / name).read_bytes() == expected
    for n in range(6):
        if f"p{n}.nc" not in written:
            assert f"p{n}.nc: No space left on device" in result.output
