"""send, receive and emulate over pseudo-terminals, against the emulated control.

Programs are small and baud rates high enough that the whole file runs in seconds; every test
has a timeout. Timing figures (line utilisation, characters after DC3 at each baud) are measured
by ``benchmarks/run.py --only dnc``, not asserted here beyond the control's allowance.
"""

from __future__ import annotations

import io
import json
import math
import os
import threading
import time
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from dnc.control import Control, ControlStats
from dnc.emulator import Emulator
from dnc.framing import Framer, split_lines
from dnc.journal import read_journal
from dnc.link import Port, chars_per_second, open_port
from dnc.sender import FlowSettings, Resume, Sender, Write, bytes_ahead, paced_cps
from dnc.session import SendProgress, bytes_waiting, open_pty, punch, send_frames
from formats.profile import load_profile
from formats.tape import EIA_TABLE, decode, iso_byte
from tapegate.cli import main

pytestmark = pytest.mark.timeout(60)

FANUC = load_profile("fanuc-mill")


def program(blocks: int, number: int = 1234) -> str:
    lines = ["%(TEST PART)", f"O{number}", "N1 G21 G17 G90 G94", "N2 T1 M06",
             "N3 S3000 M03", "N4 G00 X10. Y10. Z5. M08", "N5 G01 Z-1.5 F120."]
    for i in range(blocks):
        lines.append(f"N{i + 6} X{10 + i % 80}.5 Y{20 + i % 50}.")
    lines += [f"N{blocks + 6} M30", "%"]
    return "\n".join(lines) + "\n"


def cli(*args: str) -> Result:
    return CliRunner().invoke(main, list(args), catch_exceptions=False)


def control_for(profile: str, **kw: object) -> Control:
    s = load_profile(profile).serial
    baud = kw.pop("baud", s.baud)
    s = replace(s, baud=baud)  # type: ignore[arg-type]
    options = dict(cps=chars_per_second(s), code=s.code,
                   software_parity=s.parity_mode == "software", tv_check=s.tv_check,
                   allowance=s.overrun_allowance, dc1_every=0.05, sink=io.BytesIO())
    options.update(kw)
    return Control(**options)  # type: ignore[arg-type]


def expected_bytes(profile: str, text: str) -> bytes:
    framer = Framer(load_profile(profile).serial)
    return b"".join(d for _, d in framer.frames(split_lines([text])))


# -- sending -----------------------------------------------------------------------------------


@pytest.mark.parametrize(("profile", "overrides"), [
    ("fanuc-mill", []),  # ISO, UART parity 7E2, TV padding, LF
    ("fanuc-mill", ["--parity-mode", "software"]),  # ISO with bit 8 set by tapegate
    ("sinumerik-7e2", []),
    ("pm322-eia", []),  # EIA RS-244
])
def test_send_is_byte_exact(tmp_path: Path, profile: str, overrides: list[str]) -> None:
    text = program(30)
    src = tmp_path / "p.nc"
    src.write_text(text)
    software = "software" in overrides or load_profile(profile).serial.code == "eia"
    control = control_for(profile, baud=115200, software_parity=software)
    emu = Emulator(control)
    try:
        result = cli("send", str(src), "--port", emu.path, "-p", profile, "--baud", "115200",
                     *overrides, "--xon-timeout", "5", "--force")
        assert result.exit_code == 0, result.output
        assert emu.wait(5)
    finally:
        emu.stop()
    framer = Framer(replace(load_profile(profile).serial,
                            **({"parity_mode": "software", "data_bits": 8, "parity": "none"}
                               if software else {})))
    sent = b"".join(d for _, d in framer.frames(split_lines([text])))
    assert control.sink.getvalue() == sent  # type: ignore[union-attr]
    assert not control.stats.errors
    as_read = sent.decode("ascii") if not software else decode(sent, framer.settings.code).text
    assert control.programs[0] == as_read.replace("\r", "")  # type: ignore[arg-type]


class Sightings:
    """What the sender did, by its own clock: when its loop read each DC3 that paused it and
    each DC1 that resumed it, its pace, the moment of each of its writes to the port, and the
    moment by its clock it decided each write."""

    def __init__(self) -> None:
        self.times: list[float] = []  # DC3s read, one per pause
        self.resumes: list[float] = []  # DC1s read, one per resume after a pause
        self.writes: list[tuple[float, int]] = []  # (the moment of a write, bytes it wrote)
        self.decided: list[tuple[float, int]] = []  # (the sender's now deciding a write, bytes
        # the link took of it)
        self.ahead = 0
        self.cps = 0.0


@pytest.fixture
def sightings(monkeypatch: pytest.MonkeyPatch) -> Callable[[], Sightings]:
    """A fresh record for each send (``sightings()``), filled by the sender's events."""
    seen = [Sightings()]
    data_received, write = Sender.data_received, Port.write
    time_passed, bytes_accepted = Sender.time_passed, Sender.bytes_accepted
    decisions: list[float] = []  # the now of the write the link has not answered yet

    def watched(sender: Sender, data: bytes, now: float) -> list[object]:
        pauses, was = sender.pauses, sender.state
        actions = data_received(sender, data, now)
        seen[-1].times += [now] * (sender.pauses - pauses)  # one read may hold DC3 DC1 DC3
        if was == "paused" or sender.pauses > pauses:
            seen[-1].resumes += [now] * sum(isinstance(a, Resume) for a in actions)
        seen[-1].ahead, seen[-1].cps = sender.ahead, sender.cps
        return actions  # type: ignore[return-value]

    def written(port: Port, data: bytes) -> int:
        moment = time.monotonic()  # the bytes go on the line no earlier than this
        n = write(port, data)
        if n:
            seen[-1].writes.append((moment, n))
        return n

    def timed(sender: Sender, now: float, queued: int | None = None) -> list[object]:
        actions = time_passed(sender, now, queued)
        if any(isinstance(a, Write) for a in actions):
            decisions[:] = [now]
        return actions  # type: ignore[return-value]

    def accepted(sender: Sender, n: int, now: float) -> list[object]:
        seen[-1].decided.append((decisions.pop(), n))
        return bytes_accepted(sender, n, now)  # type: ignore[return-value]

    def fresh() -> Sightings:
        seen.append(Sightings())
        return seen[-1]

    monkeypatch.setattr(Sender, "data_received", watched)
    monkeypatch.setattr(Sender, "time_passed", timed)
    monkeypatch.setattr(Sender, "bytes_accepted", accepted)
    monkeypatch.setattr(Port, "write", written)
    return fresh


def after_each_dc3(stats: ControlStats, seen: Sightings, cps: float) -> list[int]:
    """For each throttling DC3, the characters a wire would have delivered after it: each byte
    the sender wrote, carried at the wire's pace from the moment of its write, arriving after
    the DC3 was written and written before the sender read the DC1 that resumed it.

    Counted from the sender's writes, not from the emulated control's reads: a pseudo-terminal
    hands the host's bytes to the control through a kernel worker, which on a loaded machine
    holds them for milliseconds (once here, 42 bytes written before the DC3 was decided were
    readable only 15 ms after it was written), and the control's thread may wait as long for a
    core; no wire delays a character once sent, so such bytes would count against the sender
    for what the host did."""
    tick = 1.0 / cps
    arrivals: list[tuple[float, float]] = []  # (arrival, moment taken) per byte
    free = 0.0
    for moment, n in seen.writes:
        for _ in range(n):
            free = max(free, moment) + tick
            arrivals.append((free, moment))
    out = []
    for throttle, sighting in zip(stats.throttles, seen.times, strict=False):
        resume = next((r for r in seen.resumes if r >= sighting), math.inf)
        out.append(sum(1 for arrival, moment in arrivals
                       if arrival > throttle.at and moment < resume))
    return out


def assert_obeyed(stats: ControlStats, seen: Sightings, allowance: int, cps: float) -> bool:
    """Every throttling DC3 was obeyed: what a wire would have delivered after it
    (:func:`after_each_dc3`) is at most what the sender had ahead of the wire, what the wire
    carried while the DC3 was on its way to the sender (the moment its loop read it, less the
    moment it was written), and 2 for the write already decided and the rounding of the two
    models. A DC3 that reached the sender within the allowance's time is never overrun (alarm
    087); one the host delivered later (the kernel's tty worker or the sender's thread waiting
    for a core) is beyond any sender, and what ``--dc3-reaction`` is for.

    The control's throttling DC3s and the sender's pauses come in the same order, one for one
    (a DC3 the program ended under is not resumed, so not a throttle, and may have paused the
    sender last). Returns whether the claim was put to the test: a DC3 seen in time."""
    throttles = stats.throttles
    assert len(seen.times) in (len(throttles), len(throttles) + 1), (stats, seen.times)
    margin = (allowance - seen.ahead - 2) / seen.cps  # the latency the allowance covers
    tested = False
    for throttle, sighting, after in zip(throttles, seen.times,
                                         after_each_dc3(stats, seen, cps), strict=False):
        # the emulator looks at the clock after its write: the sender may read the DC3 first
        latency = max(0.0, sighting - throttle.at)
        reach = seen.ahead + math.ceil(latency * seen.cps) + 2
        assert after <= reach, (throttle, after, f"seen {latency * 1000:.2f} ms after")
        if latency <= margin:  # no alarm 087 on a DC3 seen in time
            assert after <= allowance, (throttle, after)
            tested = True
    return tested


@pytest.mark.parametrize("baud", [4800, 9600, 19200, 38400, 57600, 115200])
def test_a_throttling_control_is_never_overrun(tmp_path: Path, baud: int,
                                               sightings: Callable[[], Sightings]) -> None:
    """Sent again (a fresh control) until a DC3 has been seen in time: on a loaded machine a
    send may see every DC3 late, or none at all (the control's thread, waiting for a core,
    reads the program in a few gulps and never fills its buffer). Every send is held to the
    bound."""
    cps = baud / 11
    src = tmp_path / "p.nc"
    src.write_text(program(max(8, int(cps * 0.25) // 14)))
    sends = 0
    while True:
        sends += 1
        seen = sightings()
        control = control_for("fanuc-mill", baud=baud, buffer=64, rate=cps / 2)
        emu = Emulator(control)
        try:
            result = cli("send", str(src), "--port", emu.path, "-p", "fanuc-mill", "--baud",
                         str(baud), "--xon-timeout", "5")
            assert result.exit_code == 0, result.output
            emu.wait(5)
        finally:
            emu.stop()
        assert control.programs and control.programs[0].rstrip("\n% ").endswith("M30")
        if assert_obeyed(control.stats, seen, FANUC.serial.overrun_allowance, cps):
            break
        assert sends < 10, "no DC3 seen in time in 10 sends"  # the claim put to the test


def test_dc3_reaction_paces_the_send(tmp_path: Path,
                                     sightings: Callable[[], Sightings]) -> None:
    """``--dc3-reaction 0.004`` at 115200 baud (docs/dnc.md, "A DC3 that arrives late"): the
    sender paces its model of the wire at (allowance 10 - 5 ahead) / 4 ms = 1,250 characters
    a second, not the wire's 10,473, so by its own clock it is never more than its 5
    characters ahead of that pace. A control machining slower than that throttles it: at each
    DC3 the sender stops within what it had ahead plus what the pace carried until it read
    the DC3 (:func:`assert_obeyed`), decides no write until the DC1, resumes on it, and the
    program arrives whole and in order. Without the option the pace is the wire's.

    Only upper bounds on the pace are asserted: a sender on a loaded machine is slower, never
    faster. The throughput it reaches is measured by ``benchmarks/dnc.py`` (job ``paced``).
    Sent again (a fresh control) until the control has throttled: a sender that lost its core
    may never fill the control's buffer."""
    cps = 115200 / 11
    allowance = FANUC.serial.overrun_allowance
    ahead = bytes_ahead(cps, allowance)
    pace = paced_cps(cps, allowance, ahead, 0.004)
    assert (ahead, pace) == (5, 1250)  # min(5, ceil(10473 x 0.5 ms)) ahead; 5 / 4 ms
    src = tmp_path / "p.nc"
    src.write_text(program(16))

    def send(*options: str, **control: object) -> tuple[Control, Sightings]:
        seen = sightings()
        emu = Emulator(control_for("fanuc-mill", baud=115200, **control))
        try:
            result = cli("send", str(src), "--port", emu.path, "-p", "fanuc-mill", "--baud",
                         "115200", "--xon-timeout", "5", *options)
            assert result.exit_code == 0, result.output
            assert emu.wait(5)
        finally:
            emu.stop()
        # nothing lost, nothing sent twice, in order
        assert emu.control.sink.getvalue() == expected_bytes(  # type: ignore[union-attr]
            "fanuc-mill", src.read_text())
        return emu.control, seen

    for _ in range(10):
        control, seen = send("--dc3-reaction", "0.004", buffer=64, rate=300.0)
        assert (seen.ahead, seen.cps) == (ahead, pace)
        first = seen.decided[0][0]
        total = 0
        for decided, n in seen.decided:  # the pace, on the sender's clock
            total += n
            assert total <= ahead + (decided - first) * pace + 1e-6, (total, decided - first)
        for sighting in seen.times[:len(control.stats.throttles)]:
            resume = next(r for r in seen.resumes if r >= sighting)  # resumed on the DC1
            assert not [d for d, _ in seen.decided if sighting < d < resume]  # stopped
            assert any(d >= resume for d, _ in seen.decided)  # and sent again
        assert_obeyed(control.stats, seen, allowance, cps)
        if control.stats.throttles:
            break
    assert control.stats.throttles, "the control never throttled in 10 sends"

    control, seen = send()
    assert seen.cps == cps  # no reaction given: the wire's pace
    result = cli("send", str(src), "--port", "loop://", "-p", "fanuc-mill",
                 "--dc3-reaction", "-1")
    assert result.exit_code == 2 and "--dc3-reaction" in result.output


def test_the_emulator_dates_what_it_reads_between_two_close_looks_at_the_clock() -> None:
    """A look at the clock taken late (the thread lost its core) is tried again, so the bytes
    are never dated later than they were there."""
    read_end, write_end = os.pipe()
    try:
        os.write(write_end, b"X1Y2\n")
        looks = iter([0.0, 0.5, 1.0, 1.00002])  # first pair 0.5 s apart: looked at again
        assert bytes_waiting(read_end, lambda: next(looks)) == (5, 1.00002)
    finally:
        os.close(read_end)
        os.close(write_end)


def test_control_that_never_starts_is_a_clear_error(tmp_path: Path) -> None:
    src = tmp_path / "p.nc"
    src.write_text(program(3))
    pty = open_pty()  # nobody behind it
    try:
        result = cli("send", str(src), "--port", pty.path, "-p", "fanuc-mill", "--xon-timeout",
                     "0.3")
    finally:
        pty.close()
    assert result.exit_code == 3
    assert "no DC1 to start within 0.3 s; stopped at the start of the program" in result.output


def test_control_that_stops_mid_program_names_the_block(tmp_path: Path) -> None:
    src = tmp_path / "p.nc"
    src.write_text(program(40))
    control = control_for("fanuc-mill", baud=115200, buffer=64, rate=1.0)  # DC3, then silence
    emu = Emulator(control)
    try:
        result = cli("send", str(src), "--port", emu.path, "-p", "fanuc-mill", "--baud",
                     "115200", "--xon-timeout", "0.4")
    finally:
        emu.stop()
    assert result.exit_code == 3
    assert "no DC1 to resume after DC3 within 0.4 s; stopped at the block on line" in \
        result.output


def test_port_vanishing_mid_send(tmp_path: Path) -> None:
    src = tmp_path / "p.nc"
    src.write_text(program(200))
    control = control_for("fanuc-mill", baud=9600)
    emu = Emulator(control)
    timer = threading.Timer(0.4, emu.stop)  # the port disappears mid-send
    timer.start()
    try:
        result = cli("send", str(src), "--port", emu.path, "-p", "fanuc-mill", "--xon-timeout",
                     "2")
    finally:
        timer.cancel()
        emu.stop()
    assert result.exit_code == 3
    assert "vanished" in result.output and "stopped at the block on line" in result.output


def test_send_refuses_a_program_with_errors_and_characters_eia_cannot_carry(
        tmp_path: Path) -> None:
    bad = tmp_path / "bad.nc"
    bad.write_text("%\nN1 G01 X10. X20.\n%\n")
    pty = open_pty()
    try:
        result = cli("send", str(bad), "--port", pty.path, "-p", "fanuc-mill")
        assert result.exit_code == 1 and "not sent: the check found" in result.output
        eia = tmp_path / "eia.nc"
        eia.write_text("%\nN1 X1.\nN2 #1=2\n%\n")
        result = cli("send", str(eia), "--port", pty.path, "-p", "pm322-eia", "--force")
        assert result.exit_code == 1
        assert "eia.nc:3:" in result.output and "cannot be carried by EIA" in result.output
        assert not _readable(pty.master)  # nothing was sent
    finally:
        pty.close()


def _readable(fd: int) -> bool:
    import select
    return bool(select.select([fd], [], [], 0)[0])


def _send_restart_at_n9(tmp_path: Path, *more: str) -> tuple[Result, Control]:
    """`send --restart-at N9` of a ten-block program to an emulated FANUC (``more``: further
    options); the emulator waited on where the send went through."""
    src = tmp_path / "p.nc"
    src.write_text(program(10))
    control = control_for("fanuc-mill", baud=115200)
    emu = Emulator(control)
    try:
        result = cli("send", str(src), "--port", emu.path, "-p", "fanuc-mill", "--baud",
                     "115200", "--restart-at", "N9", *more)
        if result.exit_code == 0:
            emu.wait(5)
    finally:
        emu.stop()
    return result, control


def test_restart_at_sends_the_preamble_then_the_rest(tmp_path: Path) -> None:
    result, control = _send_restart_at_n9(tmp_path, "--xon-timeout", "5", "--yes")
    assert result.exit_code == 0, result.output
    assert "restart at N9" in result.output and "G21 G17 G90 G94" in result.output
    lines = [line.rstrip() for line in control.programs[0].split("\n")]
    assert lines[0] == "%(TEST PART)"
    assert lines[1].startswith("G21 G17 G90 G94")
    assert "T1" in lines[2] and "S3000 M03 M08" in " ".join(lines)
    first_program_line = next(i for i, line in enumerate(lines) if line.startswith("N"))
    assert lines[first_program_line].startswith("N9 ")
    assert "N5 " not in control.programs[0]


def test_a_restart_off_a_terminal_is_sent_only_with_yes(tmp_path: Path) -> None:
    """A restart is confirmed by the operator: with no terminal to ask on (a script, a pipe)
    and no --yes, the preamble is shown and nothing is sent (exit 1); the port stays unopened."""
    result, control = _send_restart_at_n9(tmp_path, "--xon-timeout", "1")
    assert result.exit_code == 1, result.output
    assert "restart at N9" in result.output and "G21 G17 G90 G94" in result.output
    assert ("tapegate: not sent: a restart is sent only when confirmed, and there is no terminal "
            "to ask on; read the preamble above and pass --yes (-y) to send it") in result.output
    assert control.programs == [] and control.stats.chars == 0


def test_a_restart_on_a_terminal_is_sent_only_when_the_operator_says_so(
        monkeypatch: pytest.MonkeyPatch) -> None:
    from tapegate import serial_cli

    asked: list[str] = []

    def answer(reply: bool):
        def confirm(text: str, err: bool = False) -> bool:
            asked.append(text)
            return reply
        return confirm

    monkeypatch.setattr(serial_cli.sys.stdin, "isatty", lambda: True, raising=False)
    monkeypatch.setattr(serial_cli.click, "confirm", answer(True))
    serial_cli._confirm_restart()  # yes: returns, the send goes on
    monkeypatch.setattr(serial_cli.click, "confirm", answer(False))
    with pytest.raises(SystemExit) as stop:
        serial_cli._confirm_restart()
    assert stop.value.code == 1 and asked == ["send?", "send?"]


def test_repeat_sends_again_on_the_next_dc1(tmp_path: Path) -> None:
    src = tmp_path / "p.nc"
    text = program(5)
    src.write_text(text)
    control = control_for("fanuc-mill", baud=115200, programs=2)
    emu = Emulator(control)
    try:
        result = cli("send", str(src), "--port", emu.path, "-p", "fanuc-mill", "--baud",
                     "115200", "--repeat", "--passes", "2", "--xon-timeout", "5")
        assert result.exit_code == 0, result.output
        emu.wait(5)
    finally:
        emu.stop()
    assert "pass 2:" in result.output
    assert len(control.programs) == 2 and control.programs[0] == control.programs[1]


# -- receiving ---------------------------------------------------------------------------------


def punch_in_background(data: bytes, cps: float) -> tuple[str, threading.Thread, object]:
    pty = open_pty()
    flow = FlowSettings(cps=cps, wait_for_dc1=False)
    thread = threading.Thread(target=punch, args=(pty.master, data, flow),
                              kwargs={"announce": 0.05, "give_up": 10}, daemon=True)
    thread.start()
    return pty.path, thread, pty


@pytest.mark.parametrize("code", ["iso", "eia"])
def test_receive_names_the_file_and_locates_parity_errors(tmp_path: Path, code: str) -> None:
    text = program(12, number=4711)
    body = text.rstrip("\n")
    if code == "iso":
        data = bytearray(iso_byte(c) for c in body)
    else:
        data = bytearray(EIA_TABLE[c] for c in body)
    line3 = body.index("N1 ")
    data[line3 + 1] ^= 0x80 if code == "iso" else 0x10  # the "1" of N1 on line 3
    path, thread, pty = punch_in_background(b"\0" * 10 + bytes(data) + b"\0" * 10, 11520)
    out = tmp_path / "in"
    out.mkdir()
    try:
        result = cli("receive", "--port", path, "-p", "fanuc-mill", "--baud", "115200",
                     "--parity-mode", "software", "-o", str(out) + "/", "--timeout", "5",
                     "--idle", "1")
        thread.join(5)
    finally:
        pty.close()  # type: ignore[attr-defined]
    assert result.exit_code == 1, result.output  # parity error: data kept, exit 1
    saved = out / "O4711.nc"
    assert saved.read_text() == text
    assert f"{saved}:3:2: parity error" in result.output
    assert f"{code.upper()} code" in result.output


def test_receive_never_overwrites(tmp_path: Path) -> None:
    (tmp_path / "O1234.nc").write_text("keep me\n")
    data = bytes(iso_byte(c) for c in program(2).rstrip("\n"))
    path, thread, pty = punch_in_background(data, 11520)
    try:
        result = cli("receive", "--port", path, "-p", "fanuc-mill", "--parity-mode", "software",
                     "-o", str(tmp_path), "--timeout", "5", "--journal",
                     str(tmp_path / "journal" / "j.jsonl"))
        thread.join(5)
    finally:
        pty.close()  # type: ignore[attr-defined]
    assert result.exit_code == 0, result.output
    assert (tmp_path / "O1234.nc").read_text() == "keep me\n"
    assert (tmp_path / "O1234.1.nc").read_text() == program(2)
    (record,) = read_journal(tmp_path / "journal" / "j.jsonl").transfers
    assert (record.direction, record.result) == ("receive", "ok")
    assert record.blocks == program(2).count("\n")  # lines, "%" lines included
    assert record.program.endswith("O1234.1.nc") and len(record.sha256) == 64


def test_receive_with_nothing_arriving(tmp_path: Path) -> None:
    pty = open_pty()
    try:
        result = cli("receive", "--port", pty.path, "-p", "fanuc-mill", "-o", str(tmp_path),
                     "--timeout", "0.3")
    finally:
        pty.close()
    assert result.exit_code == 3 and "nothing received (no data)" in result.output
    assert list(tmp_path.iterdir()) == []


def test_emulator_punches_to_a_receiving_host(tmp_path: Path) -> None:
    """The emulator's --punch and the receive command end to end, with the pty in between."""
    src = tmp_path / "p.nc"
    src.write_text(program(4, number=77))
    pty = open_pty()
    s = replace(FANUC.serial, baud=115200)
    framer = Framer(s)
    data = framer.leader() + b"".join(d for _, d in framer.frames(split_lines([src.read_text()])))
    thread = threading.Thread(target=punch, args=(pty.master, data,
                                                  FlowSettings(cps=chars_per_second(s),
                                                               wait_for_dc1=False)),
                              kwargs={"announce": 0.05}, daemon=True)
    thread.start()
    try:
        result = cli("receive", "--port", pty.path, "-p", "fanuc-mill", "--baud", "115200",
                     "-o", str(tmp_path / "got.nc"), "--timeout", "5")
        thread.join(5)
    finally:
        pty.close()
    assert result.exit_code == 0, result.output
    got = (tmp_path / "got.nc").read_text()
    assert got.replace(" \n", "\n") == src.read_text()


def test_send_frames_reports_progress_and_pauses() -> None:
    """The progress seen paused at the control's DC3 and resumed at its DC1, the pause
    counted.

    The hold is the control's keypad's, written on its port by the progress callback itself
    once 50 bytes have gone: DC3, then DC1 when the progress shows the sender paused. So the
    pause comes whatever the pace of either side: at 38400 baud (3,840 chars/s) the 1,017
    bytes take 0.26 s at least, and the DC3 is read before the sender's next write. (A
    control that throttles on its buffer pauses a sender only where the sender outpaces its
    drain, which a loaded host did not: 6 of 20 runs paused never, with a buffer of 48 and
    1,500 chars/s, and 1 in a whole suite with a buffer of 12.) The control reads as fast as
    the bytes come: its only other DC3 is its end of reading, which ends the pass."""
    s = replace(FANUC.serial, baud=38400)
    control = control_for("fanuc-mill", baud=38400)
    emu = Emulator(control)
    seen: list[bool] = []
    held: list[str] = []

    def progress(p: SendProgress) -> None:
        seen.append(p.paused)
        if not held and p.sent >= 50:
            os.write(emu.pty.master, b"\x93")  # DC3 (ISO, even parity)
            held.append("DC3")
        elif held == ["DC3"] and p.paused:
            os.write(emu.pty.master, b"\x11")  # DC1
            held.append("DC1")

    try:
        port = open_port(emu.path, s)
        framer = Framer(s)
        result = send_frames(port, framer.frames(split_lines([program(60)])),
                             FlowSettings(cps=chars_per_second(s), xon_timeout=5),
                             leader=framer.leader(), progress=progress, every=0.01)
        port.close()
        emu.wait(5)
    finally:
        emu.stop()
    assert held == ["DC3", "DC1"]
    assert result.pauses == 1  # (DC1 may come in the same read as DC3: a pause of 0 s)
    assert True in seen and seen[-1] is False  # paused, then resumed
    assert result.sent == len(framer.leader()) + len(expected_bytes("fanuc-mill", program(60)))
    assert control.sink.getvalue() == expected_bytes("fanuc-mill", program(60))  # type: ignore[union-attr]


# -- other transports and the command-line emulator ---------------------------------------------


def test_send_over_loop_url_without_flow_control(tmp_path: Path) -> None:
    src = tmp_path / "p.nc"
    src.write_text(program(3))
    result = cli("send", str(src), "--port", "loop://", "-p", "fanuc-mill", "--flow", "none",
                 "--baud", "115200")
    assert result.exit_code == 0, result.output
    assert "sent " in result.output


def test_send_over_socket_url_to_a_control_on_tcp(tmp_path: Path) -> None:
    import socket

    from dnc.session import run_control

    src = tmp_path / "p.nc"
    src.write_text(program(6))
    server = socket.create_server(("127.0.0.1", 0))
    port = server.getsockname()[1]
    control = control_for("fanuc-mill", baud=115200)

    def serve() -> None:
        conn, _ = server.accept()
        with conn:
            run_control(conn.fileno(), control)

    thread = threading.Thread(target=serve, daemon=True)
    thread.start()
    try:
        result = cli("send", str(src), "--port", f"socket://127.0.0.1:{port}", "-p",
                     "fanuc-mill", "--baud", "115200", "--xon-timeout", "5")
        thread.join(5)
    finally:
        server.close()
    assert result.exit_code == 0, result.output
    assert control.programs and "N12 M30" in control.programs[0]


def test_send_converts_on_the_way(tmp_path: Path, sample_program: str) -> None:
    src = tmp_path / "bracket.nc"
    src.write_text(sample_program)  # written for iso-mill: G71 metric
    control = control_for("fanuc-mill", baud=115200)
    emu = Emulator(control)
    try:
        result = cli("send", str(src), "--port", emu.path, "-p", "fanuc-mill", "--baud",
                     "115200", "--convert", "--from", "iso-mill", "--xon-timeout", "5")
        emu.wait(5)
    finally:
        emu.stop()
    assert result.exit_code == 0, result.output
    assert "converted for fanuc-mill" in result.output
    assert "G21" in control.programs[0] and "G71" not in control.programs[0]


def test_emulate_command_reports_statistics(tmp_path: Path) -> None:
    import json
    import subprocess
    import sys

    # The control reads as fast as the bytes come (no --rate): its figures are then the
    # host's, whatever the load. (It used to throttle at 3,000 chars/s and assert a DC3,
    # which needs the sender faster than that drain: a loaded host sends 5 bytes a wake-up,
    # and 8 of 20 runs under load had no DC3; the DC3 and the pauses it makes are asserted
    # where they are certain, test_send_frames_reports_progress_and_pauses.)
    src = tmp_path / "p.nc"
    src.write_text(program(10))
    proc = subprocess.Popen(
        [sys.executable, "-m", "tapegate", "emulate", "-p", "fanuc-mill", "--baud", "115200",
         "--buffer", "64", "--dc1-every", "0.05", "--json", "--save", str(tmp_path / "read.nc")],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        assert proc.stderr is not None
        first = proc.stderr.readline()
        assert first.startswith("port: ")
        result = cli("send", str(src), "--port", first.split()[1], "-p", "fanuc-mill", "--baud",
                     "115200", "--xon-timeout", "5")
        out, err = proc.communicate(timeout=10)
    finally:
        proc.kill()
    assert result.exit_code == 0, result.output
    assert proc.returncode == 0, err
    stats = json.loads(out)
    framer = Framer(FANUC.serial)
    # the leader's 20 bytes and the program's 267, then as much of the 20 of the trailer as
    # went before the control's end-of-reading DC3 (the host's pass ends at it, trailer or
    # not: all of it unloaded, 4 bytes in a run under load)
    program_end = len(framer.leader()) + len(expected_bytes("fanuc-mill", program(10)))
    assert program_end <= stats["chars"] <= program_end + len(framer.trailer())
    # O1234 and N1-N16: the 17 blocks after the label "%(TEST PART)", one program
    assert (stats["blocks"], stats["programs"], stats["rewinds"]) == (17, 1, 0)
    assert (stats["dc3"], stats["most_after_dc3"], stats["alarm_087"]) == (0, 0, 0)
    assert (stats["th_errors"], stats["tv_errors"], stats["errors"]) == (0, 0, [])
    assert 0 < stats["utilisation"] <= 1
    assert (tmp_path / "read.nc").read_text().startswith("%(TEST PART)\nO1234")


def test_emulate_punch_command_to_receive(tmp_path: Path) -> None:
    import subprocess
    import sys

    src = tmp_path / "p.nc"
    src.write_text(program(5, number=321))
    proc = subprocess.Popen(
        [sys.executable, "-m", "tapegate", "emulate", "-p", "fanuc-mill", "--baud", "115200",
         "--punch", str(src)], stderr=subprocess.PIPE, text=True)
    try:
        assert proc.stderr is not None
        path = proc.stderr.readline().split()[1]
        result = cli("receive", "--port", path, "-p", "fanuc-mill", "--baud", "115200", "-o",
                     str(tmp_path / "in") + "/", "--timeout", "5")
        _, err = proc.communicate(timeout=10)
    finally:
        proc.kill()
    assert result.exit_code == 0, result.output
    assert "punched" in err
    got = (tmp_path / "in" / "O321.nc").read_text()
    assert got.replace(" \n", "\n") == src.read_text()



def test_emulate_punch_keeps_the_port_until_the_host_has_read_it(tmp_path: Path) -> None:
    """Closing a pty's master throws away what the host has not read (its next read is end of
    file): the emulator keeps the port after DC4 until the host closes it, however late the
    host reads. It used to exit at once, and a receive that had not read the end yet under
    load failed with "port vanished" (1 run in 4 with both cores busy)."""
    import fcntl
    import subprocess
    import sys
    import termios

    from tests.test_gateway import until

    src = tmp_path / "p.nc"
    src.write_text(program(5, number=321))
    framer = Framer(load_profile("fanuc-mill").serial)
    punched = (framer.leader() + expected_bytes("fanuc-mill", src.read_text())
               + framer.trailer() + b"\x14")
    proc = subprocess.Popen(
        [sys.executable, "-m", "tapegate", "emulate", "-p", "fanuc-mill", "--baud", "115200",
         "--punch", str(src)], stderr=subprocess.PIPE, text=True)
    try:
        assert proc.stderr is not None
        host = os.open(proc.stderr.readline().split()[1], os.O_RDWR | os.O_NOCTTY)
        try:
            assert until(lambda: _readable(host), 10) and os.read(host, 1) == b"\x12"
            os.write(host, b"\x11")

            def unread() -> int:
                raw = fcntl.ioctl(host, termios.FIONREAD, b"\0\0\0\0")
                return int.from_bytes(raw, sys.byteorder)

            # the host reads nothing until the whole punch, DC4 included, waits for it
            assert until(lambda: unread() >= len(punched), 10), unread()
            got = b""
            while not got.endswith(b"\x14"):
                data = os.read(host, 4096)
                assert data, "the emulator closed the port before the host had read it"
                got += data
        finally:
            os.close(host)
        _, err = proc.communicate(timeout=10)  # ends once the host has closed its port
    finally:
        proc.kill()
    assert proc.returncode == 0, err
    assert got.lstrip(b"\x12") == punched
    assert "punched" in err


def test_pty_unread_sees_what_the_kernel_has_not_handed_over_yet() -> None:
    """``Pty.unread`` is True for a byte written a moment ago, which ``FIONREAD`` on the
    host's end can still miss (the kernel's worker thread hands it over later), and False once
    the host has read it."""
    pty = open_pty()
    host = os.open(pty.path, os.O_RDWR | os.O_NOCTTY)
    try:
        assert not pty.unread()
        for _ in range(2000):
            os.write(pty.master, b"x")
            assert pty.unread()
            assert os.read(host, 16) == b"x"
            assert not pty.unread()
        os.write(pty.master, b"%\n")
        assert not pty.wait_read(0.05)  # nobody reads it
        assert os.read(host, 16) == b"%\n"
        assert pty.wait_read(5)
    finally:
        os.close(host)
        pty.close()


def test_wait_hang_up_waits_for_the_host_to_close_its_port() -> None:
    from dnc.session import wait_hang_up

    pty = open_pty()
    host = os.open(pty.path, os.O_RDWR | os.O_NOCTTY)
    try:
        os.write(pty.master, b"%\nN1 X1\n%\n\x14")
        pty.release()
        assert pty.slave is None and not pty.unread()
        os.write(host, b"\x11")  # the host still holds the port: read and dropped
        assert not wait_hang_up(pty.master, 0.05)
        assert os.read(host, 64) == b"%\nN1 X1\n%\n\x14"  # releasing lost nothing
        os.close(host)
        host = -1
        assert wait_hang_up(pty.master, 5)
    finally:
        if host >= 0:
            os.close(host)
        pty.close()


def test_restart_at_an_alignment_label_and_the_hint_for_a_sequence_number(
        tmp_path: Path) -> None:
    text = program(6).replace("N8 X12.5 Y22.", ":100 X12.5 Y22.")
    src = tmp_path / "p.nc"
    src.write_text(text)
    for target, first, hint in ((":100", ":100 ", False), ("N10", "N10 ", True)):
        control = control_for("fanuc-mill", baud=115200)
        emu = Emulator(control)
        try:
            result = cli("send", str(src), "--port", emu.path, "-p", "fanuc-mill", "--baud",
                         "115200", "--restart-at", target, "--xon-timeout", "5", "--yes")
            emu.wait(5)
        finally:
            emu.stop()
        assert result.exit_code == 0, result.output
        assert ("nearest alignment block before it is :100 (line 10)" in result.output) == hint
        lines = control.programs[0].split("\n")
        assert next(x for x in lines if x[:1] in "N:").startswith(first)


# -- rewind stops ------------------------------------------------------------------------------


@pytest.mark.parametrize("profile", ["fanuc-mill", "pm322-eia"])  # % in ISO, ER in EIA
def test_a_reset_and_rewind_at_the_control_restarts_the_program_from_percent(
        tmp_path: Path, profile: str) -> None:
    src = tmp_path / "p.nc"
    text = program(40)
    src.write_text(text)
    software = load_profile(profile).serial.code == "eia"
    # 4800 baud (436-480 chars/s): block 12 reaches the control about 0.5 s into the pass,
    # and the host sends for 1.1 s more, so the reset finds it still sending however late
    # the emulator's thread reads. (At 115200 the 757 bytes took 72 ms: a loaded emulator
    # read block 12 after the host had finished, and the reset went unheard, 3 of 40 runs.)
    control = control_for(profile, baud=4800, software_parity=software, dc1_every=0.1)
    emu = Emulator(control, rewind_after=12)  # the operator resets at block 12 and rewinds
    journal = tmp_path / "journal.jsonl"
    try:
        result = cli("send", str(src), "--port", emu.path, "-p", profile, "--baud", "4800",
                     "--xon-timeout", "5", "--journal", str(journal), "--force")
        emu.wait(5)
    finally:
        emu.stop()
    assert result.exit_code == 0, result.output
    assert "the control was reset and rewound at the block on line" in result.output
    assert "sending again from % on the control's next DC1" in result.output
    assert "stopped at" not in result.output  # where it was, said once (issue 22)
    sink = control.sink.getvalue()  # type: ignore[union-attr]
    start = 0x0B if software else 0x25  # ER is EIA's %
    assert sink[0] == start and sink[-1] == start
    assert sink == expected_bytes(profile, text)  # the whole program once, from its %
    assert control.stats.rewinds == 1 and control.stats.programs == 1
    assert control.stats.errors == []
    assert [t.result for t in read_journal(journal).transfers] == ["rewound", "ok"]


def test_the_rewind_after_a_block_comes_at_that_block_in_a_read_of_the_whole_program() -> None:
    """The operator's rewind after block 3 (``--rewind-after 3``) where one read brought the
    whole program, as an emulator that reads late on a busy host gets it: the control resets
    at block 3 and throws the rest of that read away. It used to be asked between reads only:
    the program was read to its end first and never rewound (the rewind tests' failures
    under load)."""
    from dnc.emulator import RewindButton

    text = program(6)
    sent = expected_bytes("fanuc-mill", text)  # (TV padded: a space before odd blocks' LF)
    control = control_for("fanuc-mill", baud=115200)
    button = RewindButton(control, after=3)
    control.time_passed(1.0)
    out = control.data_received(sent, 1.0)
    assert out == b"\x93\x96"  # DC3 SYN: reset (the DC1 asking again follows dc1_every later)
    stats = control.stats
    assert (stats.rewinds, stats.programs, stats.blocks) == (1, 0, 3)
    assert control.sink.getvalue() == b""  # type: ignore[union-attr]  # (abandoned: dropped)
    assert not button.pressed()  # (the control's own press: once)
    assert control.time_passed(1.0 + control.dc1_every) == b"\x11"
    control.data_received(sent, 2.0)  # (the host's second pass, whole)
    assert (control.stats.rewinds, control.stats.programs) == (1, 1)
    assert control.sink.getvalue() == sent  # type: ignore[union-attr]  # (once, from its %)


def test_emulate_rewind_after_and_usr1(tmp_path: Path) -> None:
    """The emulate command's operator: --rewind-after, and SIGUSR1 while a program is read."""
    import re
    import signal
    import subprocess
    import sys

    # 2400 baud 7E2 (218 chars/s), the control not throttling: a pass of the 1,057 bytes
    # takes 4.8 s at the wire's pace (longer on a loaded host, never shorter), no DC3 is sent
    # that a loaded host could see late (it used to throttle at 400 chars/s: an 11th
    # character after a DC3 seen late, alarm 087, in 4 of 20 runs under load).
    src = tmp_path / "p.nc"
    src.write_text(program(60))
    saved = tmp_path / "read.nc"
    proc = subprocess.Popen(
        [sys.executable, "-m", "tapegate", "emulate", "-p", "fanuc-mill", "--baud", "2400",
         "--dc1-every", "0.1", "--rewind-after", "5", "--save", str(saved), "--json"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        assert proc.stderr is not None
        path = proc.stderr.readline().split()[1]
        sender = subprocess.Popen(
            [sys.executable, "-m", "tapegate", "send", str(src), "--port", path, "-p",
             "fanuc-mill", "--baud", "2400", "--xon-timeout", "10", "--progress"],
            stderr=subprocess.PIPE, text=True)
        assert sender.stderr is not None
        lines = Lines(sender.stderr)  # the progress bar's updates are lines too (CR)
        assert lines.until(lambda line: "rewound" in line), lines.seen  # after block 5
        # the second pass is under way: RESET again early in it, as the progress bar shows
        # it, with at least half the pass (2.4 s) left for the signal to land before its end
        # (a RESET after the end asks for the program once more: nobody sends it)
        assert lines.until(lambda line: 20 <= _percent(line) <= 50), lines.seen
        proc.send_signal(signal.SIGUSR1)
        sender.wait(30)
        out, err = proc.communicate(timeout=10)
    finally:
        proc.kill()
    assert lines.until(lambda line: False, 5) is False and lines.ended
    sent = "".join(lines.seen)
    assert sender.returncode == 0, sent
    assert sent.count("sending again from %") == 2
    stats = json.loads(out)
    assert stats["rewinds"] == 2 and stats["programs"] == 1 and stats["errors"] == []
    assert "the operator rewound 2 times" in err
    assert saved.read_text().replace(" \n", "\n") == src.read_text().rstrip("\n")  # TV pad
    assert re.search(r"^sending: 100%", sent, re.M)  # the last pass's bar ends at 100 %


def _percent(line: str) -> int:
    """The percentage on a progress bar line of a pass, sending or paused by the control (on a
    busy machine every refresh of the second pass can fall in a pause), else -1."""
    import re

    m = re.match(r"(?:sending|paused by control):\s+(\d+)%", line)
    return int(m.group(1)) if m else -1


class Lines:
    """The lines of a child's output, read by a thread, waited for with a timeout."""

    def __init__(self, stream: object) -> None:
        import queue

        self.queue: queue.Queue[str | None] = queue.Queue()
        self.seen: list[str] = []
        self.ended = False

        def pump() -> None:
            for line in stream:  # type: ignore[attr-defined]
                self.queue.put(line)
            self.queue.put(None)

        threading.Thread(target=pump, daemon=True).start()

    def until(self, predicate: Callable[[str], bool], timeout: float = 20.0) -> bool:
        """Read lines until one satisfies ``predicate``; False at the end or the timeout."""
        import queue
        import time

        end = time.monotonic() + timeout
        while not self.ended and (left := end - time.monotonic()) > 0:
            try:
                line = self.queue.get(timeout=left)
            except queue.Empty:
                return False
            if line is None:
                self.ended = True
                return False
            self.seen.append(line)
            if predicate(line):
                return True
        return False


def test_the_label_is_sent_and_received_unchanged_and_skipped_by_the_control(
        tmp_path: Path) -> None:
    """Clause 4's identification between % and the first end of block, with characters a
    Fanuc would alarm on in a block and an odd length: sent as written, skipped by the control
    (no TH or TV alarm), kept by receive."""
    label = "%(part 7; rev b$)"
    text = program(6).replace("%(TEST PART)", label)
    src = tmp_path / "p.nc"
    src.write_text(text)
    control = control_for("fanuc-mill", baud=115200)
    emu = Emulator(control, punch=expected_bytes("fanuc-mill", text))
    try:
        received = cli("receive", "--port", emu.path, "-p", "fanuc-mill", "--baud", "115200",
                       "-o", str(tmp_path / "got.nc"), "--timeout", "5")
        sent = cli("send", str(src), "--port", emu.path, "-p", "fanuc-mill", "--baud",
                   "115200", "--xon-timeout", "5")
        emu.wait(5)
    finally:
        emu.stop()
    assert received.exit_code == 0 and sent.exit_code == 0, received.output + sent.output
    assert (tmp_path / "got.nc").read_text().splitlines()[0] == label
    assert control.programs[0].splitlines()[0] == label
    assert control.stats.errors == [] and control.stats.programs == 1


def test_send_shows_a_doubtful_reading_before_the_first_byte(tmp_path: Path) -> None:
    """TG136 (a '(' inside a Fanuc comment, read once) goes out, but only after the warning is
    printed with its line and column, before the summary of what is sent. A CR inside a line,
    read as one block by the check, is refused where it stands, even with --force."""
    src = tmp_path / "n.nc"
    src.write_text("%\nO1000\nG21 G90 G17\nG0 X0. Y0. Z50. (VNMG 332(1))\nM30\n%\n")
    result = cli("send", str(src), "--port", "loop://", "-p", "fanuc-mill", "--flow", "none",
                 "--baud", "115200", "--no-progress")
    assert result.exit_code == 0, result.output
    warned = result.output.index("n.nc:4:26: warning TG136")
    assert warned < result.output.index(" bytes, ") < result.output.index("sent ")
    cr = tmp_path / "cr.nc"
    cr.write_text("%\nO1000\nG21 G90 G17\nG1 Z-5. (A B \r) F50.\nM30\n%\n", newline="")
    pty = open_pty()
    try:
        result = cli("send", str(cr), "--port", pty.path, "-p", "fanuc-mill", "--force")
        assert result.exit_code == 1, result.output
        assert "cr.nc:4:14:" in result.output and "a CR inside the line" in result.output
        assert not _readable(pty.master)  # nothing was sent
    finally:
        pty.close()


def test_restart_at_shows_only_the_warnings_of_lines_it_sends(tmp_path: Path) -> None:
    """A restart sends the lines from its block on: a TG136 before the restart block is not
    said (its line is not sent); one at or after it is, before the first byte."""
    src = tmp_path / "r.nc"
    src.write_text("%\nO1000\nN1 G21 G90 G17 G94\nN2 T1 M06\nN3 G0 X0. Y0. Z50. (A (B))\n"
                   "N4 S1000 M03\nN5 G1 Z-1. F100.\nN6 X10. (C (D))\nN7 X20.\nN8 M30\n%\n")
    for target, said in (("N7", []), ("N6", ["r.nc:8:"]), ("N5", ["r.nc:8:"])):
        result = cli("send", str(src), "--port", "loop://", "-p", "fanuc-mill", "--flow",
                     "none", "--baud", "115200", "--no-progress", "--restart-at", target,
                     "--yes")
        assert result.exit_code == 0, result.output
        shown = [line for line in result.output.splitlines() if "warning TG136" in line]
        assert [where for line in shown for where in ("r.nc:5:", "r.nc:8:") if where in line] \
            == said, (target, result.output)
        assert "r.nc:5:" not in result.output
    result = cli("send", str(src), "--port", "loop://", "-p", "fanuc-mill", "--flow", "none",
                 "--baud", "115200", "--no-progress")
    assert result.exit_code == 0, result.output
    assert "r.nc:5:" in result.output and "r.nc:8:" in result.output


def test_a_refused_restart_shows_the_warnings_it_held(tmp_path: Path) -> None:
    """Review 13, 7: with --restart-at the check's warnings wait for the restart block; when no
    restart can be made (no such block, a shift in force) they were never said. They are, each
    on its line, before the refusal on its own."""
    src = tmp_path / "r.nc"
    src.write_text("%\nO1000\nN1 G21 G90 G17 G94\nN3 G0 X0. Y0. Z50. (A (B))\nN4 G52 X5.\n"
                   "N5 G1 Z-1. F100.\nN6 X10.\nN8 M30\n%\n")
    for target, why in (("N99", "no block N99"), ("N6", "cannot restart here")):
        result = cli("send", str(src), "--port", "loop://", "-p", "fanuc-mill", "--flow",
                     "none", "--baud", "115200", "--no-progress", "--restart-at", target,
                     "--yes")
        assert result.exit_code != 0, result.output
        lines = result.output.splitlines()
        warned = [i for i, line in enumerate(lines) if "r.nc:4:" in line
                  and "warning TG136" in line]
        refused = [i for i, line in enumerate(lines) if why in line]
        assert len(warned) == 1 and len(refused) == 1, (target, result.output)
        assert warned[0] < refused[0] and "r.nc" in lines[refused[0]]
        assert "warning" not in lines[refused[0]] and "TG136" not in lines[refused[0]]


def test_send_restart_at_the_cutting_depth_needs_a_safe_z(tmp_path: Path) -> None:
    """Review 13, 8: where the program never raised Z above its cut, the restart is refused
    (nothing sent) with what it would have sent; the operator's --clearance gives the safe Z,
    and the approach rapids there, over the start point, then feeds down."""
    src = tmp_path / "z.nc"
    src.write_text("%\nO1000\nG21 G90 G54 G00 X0 Y0\nG01 Z-1. F100.\nX10.\nN20 X20.\nM30\n%\n")
    args = ["send", str(src), "--port", "loop://", "-p", "fanuc-mill", "--flow", "none",
            "--baud", "115200", "--no-progress", "--restart-at", "N20", "-y"]
    refused = cli(*args)
    assert refused.exit_code == 1, refused.output
    assert "no height above the start point is known to be clear" in refused.output
    assert "(it would send: G00 Z-1. / G00 X10. Y0)" in refused.output
    assert "send --clearance" in refused.output and " bytes, " not in refused.output
    sent = cli(*args, "--clearance", "50")
    assert sent.exit_code == 0, sent.output
    preamble = sent.output.split("preamble:\n")[1].splitlines()[1:4]
    assert [line.strip() for line in preamble] == ["G00 Z50.", "G00 X10. Y0", "G01 Z-1. F100."]
    alone = cli(*args[:-3], "--clearance", "50")
    assert alone.exit_code == 2 and "--clearance is the approach height of --restart-at" in \
        alone.output


@pytest.mark.parametrize(("given", "said"), [
    ("nan", "'nan' is not a finite number"), ("NaN", "'NaN' is not a finite number"),
    ("inf", "'inf' is not a finite number"), ("-inf", "'-inf' is not a finite number"),
    ("abc", "'abc' is not a number"), ("", "'' is not a number"),
    ("1e999", "1E+999 has more digits before the decimal sign than the profile's Z format "
              "Z+053 holds (5 in metric)"),
    ("123456.789", "123456.789 has more digits"),
    ("1_0", "'1_0' is not a number written in the digits 0-9"),
    ("\uff15\uff10", "'\uff15\uff10' is not a number written in the digits 0-9"),
    ("99999.9999", "99999.9999 has more digits"),  # rounded up to 100000.000 as it is sent
])
def test_send_clearance_that_is_no_height_is_a_usage_error(tmp_path: Path, given: str,
                                                           said: str) -> None:
    """Review 14, 5: ``--clearance nan`` passed click's FloatRange (NaN compares false with
    both ends) and ended in a traceback. Every value that is not a finite number, or has more
    digits than the profile's Z word holds, is a usage error (exit 2) naming the option, and
    nothing is sent."""
    src = tmp_path / "z.nc"
    src.write_text("%\nO1000\nG21 G90 G54 G00 X0 Y0\nG01 Z-1. F100.\nX10.\nN20 X20.\nM30\n%\n")
    result = cli("send", str(src), "--port", "loop://", "-p", "fanuc-mill", "--flow", "none",
                 "--baud", "115200", "--no-progress", "--restart-at", "N20", "-y",
                 "--clearance", given)
    assert result.exit_code == 2, result.output
    assert f"Invalid value for '--clearance': {said}" in result.output
    assert "Traceback" not in result.output and " bytes, " not in result.output
    # a height the format holds is sent, read exactly (no float in between), within the
    # machine's Z travel of 518 mm from the start point Z-1. (review 15, 6)
    sent = cli("send", str(src), "--port", "loop://", "-p", "fanuc-mill", "--flow", "none",
               "--baud", "115200", "--no-progress", "--restart-at", "N20", "-y",
               "--clearance", " 516.999 ")
    assert sent.exit_code == 0 and "G00 Z516.999\n" in sent.output, sent.output


@pytest.mark.parametrize(("clearance", "refused"), [
    ("500", True), ("39.95", True), ("39.9", False), ("2", False)])
def test_send_clearance_past_the_z_travel_is_refused(tmp_path: Path, clearance: str,
                                                     refused: bool) -> None:
    """Review 15, 6: `--clearance 500` on haas-mill (Z -20 to 20 in) was sent as `G00 Z500.`
    from a cut at Z-0.1: it was checked against the Z word's digits only. A clearance more
    than the Z travel above the start point fits no work offset: the restart is refused (exit
    1, nothing sent, no traceback) with the reason; Z39.9 is exactly 40 in above Z-0.1."""
    src = tmp_path / "r1.nc"
    src.write_text("%\nO1000\nG20 G90 G54 G00 X0 Y0\nG01 Z-0.1 F10.\nX1.\nN20 X2.\nM30\n%\n")
    result = cli("send", str(src), "--port", "loop://", "-p", "haas-mill", "--flow", "none",
                 "--baud", "115200", "--no-progress", "--restart-at", "N20", "-y",
                 "--clearance", clearance)
    assert "Traceback" not in result.output
    if refused:
        assert result.exit_code == 1, result.output
        assert (f"r1.nc:6: cannot restart here: the clearance Z{clearance}" in result.output
                and "more than the machine's Z travel (-20 to 20 in)" in result.output), \
            result.output
        assert " bytes, " not in result.output
    else:
        assert result.exit_code == 0, result.output
        assert f"G00 Z{clearance}" in result.output, result.output


@pytest.mark.parametrize("args", [
    ["send", "{file}", "--port", "loop://", "--xon-timeout", "nan"],
    ["send", "{file}", "--port", "loop://", "--xon-timeout", "inf"],
    ["send", "{file}", "--port", "loop://", "--dc3-reaction", "nan"],
    ["send", "{file}", "--port", "loop://", "--dc3-reaction", "inf"],
    ["receive", "--port", "loop://", "-o", "{file}.out", "--timeout", "nan"],
    ["receive", "--port", "loop://", "-o", "{file}.out", "--timeout", "inf"],
    ["receive", "--port", "loop://", "-o", "{file}.out", "--idle", "nan"],
    ["emulate", "--port", "loop://", "--rate", "nan"],
    ["emulate", "--port", "loop://", "--dc1-every", "inf"],
    ["emulate", "--port", "loop://", "--dprnt-every", "nan"],
])
def test_seconds_and_rates_that_are_no_number_are_usage_errors(tmp_path: Path,
                                                               args: list[str]) -> None:
    """The same class as review 14, 5: click's FloatRange lets NaN through every range and an
    infinity through one with no upper end; a wait or a pace of either is no setting. Each is
    a usage error (exit 2) naming the option, before any port is opened."""
    src = tmp_path / "p.nc"
    src.write_text("%\nO1000\nG21 G90\nM30\n%\n")
    result = cli(*[a.format(file=src) for a in args])
    assert result.exit_code == 2, result.output
    assert f"Invalid value for '{args[-2]}': '{args[-1]}' is not a finite number" in \
        result.output, result.output


def test_send_restart_shows_the_keyed_start_and_the_programs_m09(tmp_path: Path) -> None:
    """Review 56d F1: the operator sees what will be sent: after a builder's keyed M13 and the
    program's own M09, `send --restart-at` prints the preamble, the M13 and then the M09,
    before it sends."""
    profile = tmp_path / "m13.toml"
    profile.write_text(
        'base = "fanuc-mill"\nname = "m13"\n[codes]\n'
        'M13 = { function = "spindle CW and coolant on", duration = "spindle", '
        'meaning = "spindle-cw-coolant-on" }\n')
    src = tmp_path / "k1.nc"
    src.write_text("%\nO1\nN30 G21 G17 G90 G40 G80\nN40 G54 G00 X0 Y0\nN50 T1 M06\n"
                   "N60 G43 H1 Z50.\nN70 S1000 M13\nN80 G00 X10. Y10.\nN90 M09\n"
                   "N100 G01 Z-5. F100.\nN110 G01 X50.\nN120 M30\n%\n")
    result = cli("send", str(src), "--port", "loop://", "-p", str(profile), "--flow", "none",
                 "--baud", "115200", "--no-progress", "--restart-at", "N100", "-y")
    assert result.exit_code == 0, result.output
    assert ("restart at N100 (line 10); preamble:\n    G21 G17 G90 G94 G40 G49 G80 G54\n"
            "    T1 M06\n    G97 S1000 M13\n    M09\n    G00 G43 Z50. H1\n    G00 X10. Y10.\n"
            ) in result.output
