"""``rfc2217://`` as a tested transport: a real RFC 2217 server (ser2net, a Debian package) on
loopback, with a pseudo-terminal behind it and the emulated control on the pty.

What runs here is what a shop runs with a serial device server: ``tapegate send`` and
``tapegate receive`` with ``--port rfc2217://127.0.0.1:PORT``, and a gateway port whose device
server is not there when the service starts. ser2net cannot set DTR or RTS on a pty and never
answers those requests, as some device servers do not, so every test also shows that such a
request does not hang the open. The tests are skipped where ser2net is not installed
(``.ci/run`` installs it).
"""

from __future__ import annotations

import os
import shutil
import socket
import subprocess
import termios
import threading
import time
from collections.abc import Callable, Iterator
from dataclasses import replace
from pathlib import Path

import pytest
import serial
from pymodbus.client import ModbusTcpClient

from dnc.control import Control
from dnc.emulator import Emulator
from dnc.gateway import Gateway, State
from dnc.link import chars_per_second, open_port
from dnc.sender import FlowSettings
from formats.profile import load_profile
from tests.test_dnc_serial import (
    Sightings,
    assert_obeyed,
    cli,
    control_for,
    expected_bytes,
    program,
    sightings,
)
from tests.test_gateway import entries, free_port, running, until

__all__ = ["running", "sightings"]  # the gateway and sender fixtures, used below

SER2NET = shutil.which("ser2net", path=os.pathsep.join(
    [os.environ.get("PATH", ""), "/usr/sbin", "/usr/local/sbin"]))

pytestmark = [pytest.mark.timeout(60),
              pytest.mark.skipif(SER2NET is None, reason="ser2net is not installed")]

BAUD = 9600
FANUC = load_profile("fanuc-mill").serial
CPS = chars_per_second(replace(FANUC, baud=BAUD))


class Ser2net:
    """ser2net serving ``device`` as ``telnet(rfc2217)`` on 127.0.0.1:``port``, its
    configuration in ``folder``; :meth:`stop` ends it."""

    def __init__(self, folder: Path, device: str, port: int):
        self.port = port
        self.url = f"rfc2217://127.0.0.1:{port}"
        config = folder / f"ser2net-{port}.yaml"
        config.write_text(
            "connection: &control\n"
            f"    accepter: telnet(rfc2217),tcp,127.0.0.1,{port}\n"
            "    options:\n"
            "      kickolduser: true\n"
            f"    connector: serialdev,{device},9600n81,local\n")
        assert SER2NET is not None
        self.process = subprocess.Popen(
            [SER2NET, "-n", "-u", "-c", str(config), "-P", str(folder / f"ser2net-{port}.pid")],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        if not until(self.listening, 10):
            out = self.stop()
            pytest.fail(f"ser2net did not listen on {port}: {out}")

    def listening(self) -> bool:
        if self.process.poll() is not None:
            return False
        try:
            socket.create_connection(("127.0.0.1", self.port), 0.5).close()
        except OSError:
            return False
        return True

    def stop(self) -> str:
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(5)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait(5)
        assert self.process.stdout is not None
        return self.process.stdout.read().decode(errors="replace")


@pytest.fixture
def device_server(tmp_path: Path) -> Iterator[Callable[..., Ser2net]]:
    """Start ser2net in front of a device (an emulator's pty); stopped after the test."""
    started: list[Ser2net] = []

    def start(device: str, port: int | None = None) -> Ser2net:
        server = Ser2net(tmp_path, device, port or free_port())
        started.append(server)
        return server

    yield start
    for server in started:
        server.stop()


def emulator(**kw: object) -> Emulator:
    options: dict[str, object] = {"baud": BAUD}
    options.update(kw)
    return Emulator(control_for("fanuc-mill", **options))


# -- sending -------------------------------------------------------------------------------------


def test_a_throttling_control_behind_a_device_server_is_never_overrun(
        tmp_path: Path, device_server: Callable[..., Ser2net],
        sightings: Callable[[], Sightings]) -> None:
    """DC3 reaches the sender through the device server and pyserial's reader thread, and is
    obeyed (it was not when the port select()ed on the socket the thread was draining: the DC3
    never reached the sender, 10,733 characters after it), and the program arrives
    byte-exact. At 4800 baud, the setting of the shop that found it.

    The DC3 passes through ser2net, a process of its own, on its way: on a busy machine it can
    take tens of milliseconds (20 ms was seen at 9600 baud beside the whole suite, 90 ms on a
    machine running five times more than its cores), longer than the allowance lasts. So the
    sender is told so (``--dc3-reaction 0.03``, see docs/dnc.md), as a shop sets it for a
    device server on a busy network: it then sends at most (10 - 2 ahead) / 30 ms = 267
    characters a second. Each DC3 is held to what the sender could send before it read it
    (:func:`assert_obeyed`: what it had ahead, the pace over the DC3's delay, 2), and one seen
    within the allowance's time, (10 - 2 - 2) / 267 = 22.5 ms, to the allowance. Sent again
    (a fresh control and server) until a DC3 was seen in time: on a loaded machine a send may
    see every DC3 late, or the sender, waiting for a core, may never fill the buffer."""
    baud, reaction = 4800, 0.03
    cps = chars_per_second(replace(FANUC, baud=baud))
    src = tmp_path / "p.nc"
    src.write_text(program(15))
    for _ in range(8):
        seen = sightings()
        emu = emulator(baud=baud, buffer=48, rate=cps / 3)
        server = device_server(emu.path)
        try:
            result = cli("send", str(src), "--port", server.url, "-p", "fanuc-mill", "--baud",
                         str(baud), "--xon-timeout", "10", "--dc3-reaction", str(reaction))
            assert result.exit_code == 0, result.output
            assert emu.wait(10)
        finally:
            emu.stop()
            server.stop()
        assert seen.cps == (FANUC.overrun_allowance - 2) / reaction
        assert emu.control.sink.getvalue() == expected_bytes(  # type: ignore[union-attr]
            "fanuc-mill", src.read_text())
        if assert_obeyed(emu.control.stats, seen, FANUC.overrun_allowance, cps):
            break
    else:
        pytest.fail("no DC3 seen in time in 8 sends")  # the claim put to the test


def test_the_settings_travel_and_an_unanswered_modem_control_request_does_not_hang(
        tmp_path: Path, device_server: Callable[..., Ser2net]) -> None:
    """4800 7E2 from the profile and the command line reach the device: the pty shows the
    speed and the two stop bits (a Linux pty keeps itself at 8 bits without parity, so those
    two are seen as ser2net confirmed them: pyserial's open fails on a setting the server does
    not confirm). ser2net never answers DTR or RTS on a pty: plain pyserial gives up the open
    after its network timeout; tapegate's open does not wait for those answers."""
    emu = emulator()
    server = device_server(emu.path)
    try:
        plain = serial.serial_for_url(f"{server.url}?timeout=0.5", do_not_open=True,
                                      baudrate=4800, timeout=0)
        with pytest.raises(serial.SerialException, match="control"):
            plain.open()  # the premise: the server does not answer the DTR request
        plain.close()
        assert until(server.listening, 10)
        started = time.monotonic()
        port = open_port(server.url, replace(FANUC, baud=4800))
        opened = time.monotonic() - started
        try:
            assert opened < 2.5  # pyserial's own wait for an answer is 3 s
            attrs = termios.tcgetattr(emu.pty.slave)
            assert attrs[4] == attrs[5] == termios.B4800
            assert attrs[2] & termios.CSTOPB
        finally:
            port.close()
    finally:
        emu.stop()
    # the command line's overrides travel the same way (ser2net restores the device's own
    # settings when the client leaves, so they are looked at while the send is under way)
    emu = emulator(buffer=64, rate=CPS / 4)
    server = device_server(emu.path)
    seen: list[list[int]] = []

    def look() -> None:
        def at_19200() -> bool:
            attrs = termios.tcgetattr(emu.pty.slave)
            seen.append(attrs[2:6])
            return bool(attrs[4] == termios.B19200)
        until(at_19200, 20)

    watcher = threading.Thread(target=look, daemon=True)
    watcher.start()
    try:
        src = tmp_path / "p.nc"
        src.write_text(program(15))
        result = cli("send", str(src), "--port", server.url, "-p", "fanuc-mill", "--baud",
                     "19200", "--stop-bits", "1", "--xon-timeout", "10")
        assert result.exit_code == 0, result.output
        watcher.join(20)
    finally:
        emu.stop()
    cflag, _, ispeed, ospeed = seen[-1]
    assert ispeed == ospeed == termios.B19200 and not cflag & termios.CSTOPB


def test_a_device_server_that_is_not_there_is_a_clear_link_failure(tmp_path: Path) -> None:
    src = tmp_path / "p.nc"
    src.write_text(program(5))
    journal = tmp_path / "j.jsonl"
    result = cli("send", str(src), "--port", f"rfc2217://127.0.0.1:{free_port()}", "-p",
                 "fanuc-mill", "--journal", str(journal))
    assert result.exit_code == 3, result.output
    assert "cannot open port rfc2217://127.0.0.1:" in result.output
    assert "Traceback" not in result.output
    assert journal.read_text().count('"failed"') == 1


# -- receiving -----------------------------------------------------------------------------------


def test_receive_through_a_device_server(tmp_path: Path,
                                         device_server: Callable[..., Ser2net]) -> None:
    text = program(20, number=4321)
    data = text.encode("ascii")  # 7-bit: the UART on the control's side makes the parity
    control = Control(cps=CPS, dc1_every=0.05)
    emu = Emulator(control, punch=b"\x00" * 10 + data,
                   punch_flow=FlowSettings(cps=CPS, wait_for_dc1=False))
    server = device_server(emu.path)
    out = tmp_path / "in"
    try:
        result = cli("receive", "--port", server.url, "-p", "fanuc-mill", "--baud", str(BAUD),
                     "-o", f"{out}/", "--timeout", "20", "--idle", "2")
        assert result.exit_code == 0, result.output
        assert until(lambda: emu.punched is not None, 10), emu.error
    finally:
        emu.stop()
    assert emu.punched == len(data) + 10
    assert [p.name for p in out.iterdir()] == ["O4321.nc"]
    assert (out / "O4321.nc").read_text() == text


# -- the gateway ---------------------------------------------------------------------------------


def test_a_gateway_port_whose_device_server_is_down_at_start_is_retried(
        tmp_path: Path, device_server: Callable[..., Ser2net],
        running: Callable[..., Gateway]) -> None:
    """The device server is not there when the service starts: the port shows offline
    (Modbus state 0), a Modbus "send program" to it is queued and journalled, and once the
    server is up the port opens (backoff) and the program is sent on the control's DC1."""
    (tmp_path / "programs").mkdir()
    text = program(15, number=77)
    (tmp_path / "programs" / "O0077.nc").write_text(text)
    tcp, modbus = free_port(), free_port()
    config = tmp_path / "gateway.toml"
    config.write_text(
        '[gateway]\njournal = "journal.jsonl"\nrequest_timeout = 20\nidle = 0.5\n'
        'retry_first = 0.05\nretry_max = 0.4\n\n'
        f'[modbus]\nenabled = true\nport = {modbus}\nallow_write = true\n\n'
        f'[[port]]\nname = "lathe"\nurl = "rfc2217://127.0.0.1:{tcp}"\n'
        'profile = "fanuc-mill"\nprograms = "programs"\nreceive = "received"\n'
        f'serial = {{ baud = {BAUD}, xon_timeout = 10 }}\n')
    gateway = running(config)
    worker = gateway.port(0)
    assert until(lambda: worker.status.state == State.OFFLINE and "cannot open port"
                 in worker.status.message, 10), worker.status
    client = ModbusTcpClient("127.0.0.1", port=modbus)
    assert client.connect()
    emu = emulator()
    try:
        assert client.read_input_registers(0, count=1, device_id=1).registers == [0]
        assert not client.write_registers(0, [0, 77, 1], device_id=1).isError()
        queued = entries(tmp_path, "queued")
        assert [(t.port, t.direction, t.program) for t in queued] == [
            ("lathe", "command", "modbus send 77")]
        assert "offline" in queued[0].errors[0]
        server = device_server(emu.path, tcp)
        assert until(lambda: bool(entries(tmp_path, "ok")), 30), worker.status
        assert worker.is_alive()
        # the device server goes away while the port listens, and comes back
        server.stop()
        assert until(lambda: worker.status.state == State.OFFLINE, 10), worker.status
        device_server(emu.path, tcp)
        assert until(lambda: worker.status.state == State.IDLE, 10), worker.status
    finally:
        client.close()
        emu.stop()
    sent = entries(tmp_path, "ok")[0]
    assert (sent.port, sent.direction, sent.program) == ("lathe", "send", "O0077.nc")
    assert emu.control.sink.getvalue() == expected_bytes(  # type: ignore[union-attr]
        "fanuc-mill", text)
