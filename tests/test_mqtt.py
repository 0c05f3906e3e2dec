"""The gateway on a real MQTT broker: mosquitto (a Debian package; ``.ci/run`` installs it),
started by the tests on a free loopback port with a configuration file they write.

Gateways run in the test process (threads) or as ``tapegate serve`` (where SIGKILL is under
test); the machines are emulated controls on pseudo-terminals. A subscriber of the tests' own
(paho) reads what the gateways publish. Every wait is on a condition, with a timeout.
"""

from __future__ import annotations

import getpass
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import threading
import time
import urllib.error
import urllib.request
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import paho.mqtt.client as paho
import pytest
from click.testing import CliRunner
from paho.mqtt.enums import CallbackAPIVersion

from dnc.dataline import DEFAULT_PATTERNS, DataPatterns, LineSplitter, data_program
from dnc.emulator import DprntSchedule, Emulator
from dnc.gateway import Gateway, State
from dnc.gateway_config import ConfigError, load_config
from dnc.journal import Journal, Transfer
from dnc.modbus import IR_DATA_EVENT, IR_DATA_LINES, IR_PARTS, input_registers
from dnc.mqtt import Publisher, Spool
from formats.errors import ProfileError
from formats.profile import load_profile
from tapegate.cli import main
from tests.test_dnc_serial import control_for, program
from tests.test_gateway import (
    BAUD,
    free_port,
    journal,
    machine,
    request,
    sent_program,
    until,
    write_config,
)

MOSQUITTO = shutil.which("mosquitto", path=os.pathsep.join(
    [os.environ.get("PATH", ""), "/usr/sbin", "/usr/local/sbin"]))
pytestmark = [pytest.mark.timeout(90),
              pytest.mark.skipif(MOSQUITTO is None, reason="mosquitto is not installed")]


class Broker:
    """mosquitto on 127.0.0.1:``port``, anonymous, persistent (retained messages and the
    tests' own durable subscriptions survive a restart, as on a plant's broker)."""

    def __init__(self, folder: Path, port: int):
        self.folder = folder
        self.port = port
        self.url = f"mqtt://127.0.0.1:{port}"
        self.process: subprocess.Popen[bytes] | None = None
        folder.mkdir(parents=True, exist_ok=True)
        self.config = folder / "mosquitto.conf"
        self.config.write_text(
            f"listener {port} 127.0.0.1\nallow_anonymous true\n"
            f"persistence true\npersistence_location {folder}/\n"
            f"log_dest file {folder}/mosquitto.log\n"
            f"user {getpass.getuser()}\n"   # as root it would switch to the user 'mosquitto'
            "max_queued_messages 100000\n")

    def start(self) -> None:
        assert MOSQUITTO is not None
        self.process = subprocess.Popen([MOSQUITTO, "-c", str(self.config)],
                                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

        def listening() -> bool:
            try:
                socket.create_connection(("127.0.0.1", self.port), timeout=0.2).close()
                return True
            except OSError:
                return False

        if not until(listening, 10):
            log = self.folder / "mosquitto.log"
            pytest.fail(f"mosquitto did not listen on {self.port}: "
                        f"{log.read_text() if log.exists() else 'no log'}")

    def stop(self) -> None:
        if self.process is not None:
            self.process.terminate()
            self.process.wait(10)
            self.process = None


@pytest.fixture
def broker(tmp_path: Path) -> Iterator[Broker]:
    b = Broker(tmp_path / "broker", free_port())
    b.start()
    yield b
    b.stop()


class Subscriber:
    """The tests' own client on ``tapegate/#``: every message, in the order received.
    ``durable``: a persistent session, so that the broker keeps what comes while it is away."""

    def __init__(self, broker: Broker, *, durable: bool = False, name: str = "tests"):
        self.got: list[tuple[str, Any, int, bool]] = []
        self.lock = threading.Lock()
        self.client = paho.Client(CallbackAPIVersion.VERSION2, client_id=name,
                                  clean_session=not durable, protocol=paho.MQTTv311)
        self.client.on_message = self._message
        self.client.on_connect = lambda c, u, f, r, p: c.subscribe("tapegate/#", qos=1)
        self.client.reconnect_delay_set(1, 1)
        self.client.connect("127.0.0.1", broker.port)
        self.client.loop_start()

    def _message(self, client: paho.Client, userdata: Any, m: paho.MQTTMessage) -> None:
        try:
            payload = json.loads(m.payload)
        except ValueError:
            payload = m.payload
        with self.lock:
            self.got.append((m.topic, payload, m.qos, bool(m.retain)))

    def on(self, suffix: str) -> list[Any]:
        with self.lock:
            return [p for t, p, _, _ in self.got if t.endswith(suffix)]

    def messages(self, suffix: str) -> list[tuple[str, Any, int, bool]]:
        with self.lock:
            return [m for m in self.got if m[0].endswith(suffix)]

    def close(self) -> None:
        self.client.disconnect()
        self.client.loop_stop()


@pytest.fixture
def subscribers() -> Iterator[Callable[..., Subscriber]]:
    made: list[Subscriber] = []

    def make(broker: Broker, **kw: Any) -> Subscriber:
        s = Subscriber(broker, **kw)
        made.append(s)
        return s

    yield make
    for s in made:
        s.close()


def mqtt_config(tmp: Path, ports: int, broker: Broker, gateway: str, *, extra: str = "",
                port: str = "") -> Path:
    config = write_config(tmp, ports, port=port)
    config.write_text(config.read_text() + f'\n[mqtt]\nenabled = true\nbroker = "{broker.url}"\n'
                      f'gateway = "{gateway}"\ninterval = 0.1\n{extra}\n')
    return config


@pytest.fixture
def gateways() -> Iterator[Callable[[Path], tuple[Gateway, Publisher]]]:
    """Gateways with their publishers, in the test process; stopped after the test."""
    started: list[tuple[Gateway, Publisher]] = []

    def start(config: Path) -> tuple[Gateway, Publisher]:
        gateway = Gateway(load_config(config))
        publisher = Publisher(gateway, gateway.config.mqtt)
        publisher.start()
        gateway.start()
        started.append((gateway, publisher))
        return gateway, publisher

    yield start
    for gateway, publisher in started:
        gateway.stop()
        publisher.stop(drain=0.5)


def journal_fields(t: Any) -> dict[str, Any]:
    return {k: v for k, v in t.items() if k not in ("seq", "gateway")}


def serve(config: Path) -> subprocess.Popen[bytes]:
    """``tapegate serve``, its log appended to ``serve.log`` beside the configuration."""
    with open(config.parent / "serve.log", "ab") as log:
        return subprocess.Popen([sys.executable, "-m", "tapegate", "serve", "--config",
                                 str(config), "--log-level", "debug"],
                                stdout=subprocess.DEVNULL, stderr=log,
                                cwd=Path(__file__).parent.parent)


# -- the configuration (no broker needed) ------------------------------------------------------


@pytest.mark.parametrize(("text", "line", "key", "message"), [
    ('broker = "http://h"', 3, "mqtt.broker", "mqtt.broker = 'http://h': give mqtt://host[:port]"),
    ('broker = "mqtt://h:70000"', 3, "mqtt.broker", "the port must be 1-65535"),
    ('gateway = "hall/1"', 3, "mqtt.gateway", "mqtt.gateway = 'hall/1': use 1-64 letters"),
    ('gateway = "g"\nbrokr = "mqtt://h"', 4, "mqtt.brokr", "unknown key mqtt.'brokr'"),
    ('gateway = "g"\nca = "ca.pem"', 4, "mqtt.ca", "mqtt.ca: no file"),
    ('gateway = "g"\nca = "gateway.toml"', 4, "mqtt.ca",
     "are for TLS: give the broker as mqtts://"),
    ('gateway = "g"\nbroker = "mqtts://h"\ncert = "gateway.toml"', 1, "mqtt",
     "mqtt.key is missing"),
    ('gateway = "g"\npassword_file = "gateway.toml"', 1, "mqtt", "mqtt.user is missing"),
    ('gateway = "g"\nqueue_limit = 5', 4, "mqtt.queue_limit", "mqtt.queue_limit = 5"),
    ('gateway = "g"\nallow_commands = "yes"', 4, "mqtt.allow_commands",
     "mqtt.allow_commands must be bool"),
    ('gateway = "g"\nkeepalive = 1', 4, "mqtt.keepalive", "mqtt.keepalive = 1"),
])
def test_mqtt_configuration_errors_name_the_key_and_line(tmp_path: Path, text: str, line: int,
                                                          key: str, message: str) -> None:
    config = write_config(tmp_path, 1)
    # [mqtt] first: its lines are counted from the top of the file (a key that is missing:
    # the line of the [mqtt] header)
    config.write_text(f"[mqtt]\nenabled = true\n{text}\n" + config.read_text())
    with pytest.raises(ConfigError) as err:
        load_config(config)
    code = "config-unknown-key" if key == "mqtt.brokr" else "config-value"
    assert (err.value.code, err.value.key, err.value.line) == (code, key, line), str(err.value)
    # one code, and one key (mqtt.broker, mqtt.ca, the [mqtt] table), for several faults: the
    # wording tells which (a missing key names the table, as its line is the table's)
    assert message in err.value.message
    result = CliRunner().invoke(main, ["serve", "--config", str(config), "--check"])
    assert result.exit_code == 2 and f"gateway.toml:{line}: " in result.output
    assert "Traceback" not in result.output


def test_mqtt_configuration_is_read(tmp_path: Path) -> None:
    (tmp_path / "pass").write_text("s3cret\n")
    (tmp_path / "ca.pem").write_text("")
    config = write_config(tmp_path, 1)
    config.write_text(config.read_text() + '[mqtt]\nenabled = true\n'
                      'broker = "mqtts://[::1]"\ngateway = "hall-1"\nca = "ca.pem"\n'
                      'user = "gw"\npassword_file = "pass"\nallow_commands = true\n')
    m = load_config(config).mqtt
    assert (m.scheme, m.host, m.port, m.gateway, m.user) == ("mqtts", "::1", 8883, "hall-1",
                                                            "gw")
    assert m.allow_commands and m.ca == tmp_path / "ca.pem"
    assert m.queue == tmp_path / "mqtt-hall-1.queue" and m.client_id == "tapegate-hall-1"
    result = CliRunner().invoke(main, ["serve", "--config", str(config), "--check"])
    assert result.exit_code == 0
    assert "mqtt: mqtts://[::1]:8883 as hall-1, commands allowed" in result.output
    assert not load_config(write_config(tmp_path, 1)).mqtt.enabled  # off unless enabled


def test_the_documented_mqtt_table_loads(tmp_path: Path) -> None:
    doc = (Path(__file__).resolve().parents[1] / "docs" / "mqtt.md").read_text()
    table = doc.split("```toml\n")[1].split("```")[0]
    config = write_config(tmp_path, 1)
    config.write_text(config.read_text() + table)
    m = load_config(config).mqtt
    assert m.enabled and m.gateway == "hall-1" and not m.allow_commands
    assert (m.host, m.port, m.queue_limit, m.keepalive) == ("127.0.0.1", 1883, 100_000, 30)


def test_data_patterns_in_the_port_and_the_profile(tmp_path: Path) -> None:
    config = write_config(tmp_path, 1, port="data_patterns = ['LOAD=(?P<load>\\d+)']")
    assert load_config(config).ports[0].data_patterns == (r"LOAD=(?P<load>\d+)",)
    assert load_config(write_config(tmp_path, 1)).ports[0].data_patterns == DEFAULT_PATTERNS
    for bad, why in [("'LOAD=('", "is not a regular expression"),
                     ("'LOAD=\\d+'", "needs at least one named group"),
                     ("'(?P<x>a*)'", "matches an empty line"), ("1", "must be a list of strings")]:
        with pytest.raises(ConfigError) as err:
            load_config(write_config(tmp_path, 1, port=f"data_patterns = [{bad}]"))
        assert (err.value.code, err.value.key) == ("config-value", "port[0].data_patterns")
        assert err.value.line is not None
        assert why in err.value.message  # four faults of one key and code: the wording tells
    profile = tmp_path / "mill.toml"
    profile.write_text('name = "mill"\ndata_patterns = ["SPINDLE=(?P<rpm>\\\\d+)"]\n')
    assert load_profile(str(profile)).data_patterns == (r"SPINDLE=(?P<rpm>\d+)",)
    config = write_config(tmp_path, 1)
    config.write_text(config.read_text().replace('profile = "fanuc-mill"',
                                                 'profile = "mill.toml"'))
    assert load_config(config).ports[0].data_patterns == (r"SPINDLE=(?P<rpm>\d+)",)
    profile.write_text('name = "mill"\ndata_patterns = ["("]\n')
    with pytest.raises(ProfileError) as perr:
        load_profile(str(profile))
    assert (perr.value.code, perr.value.key) == ("profile-value", "data_patterns[0]")
    assert perr.value.file == str(profile)


# -- data lines (pure) -------------------------------------------------------------------------


@pytest.mark.parametrize(("line", "fields"), [
    ("(CYCLE START O1234)", {"event": "CYCLE START", "program": "O1234"}),
    ("CYCLE  END", {"event": "CYCLE END"}),
    ("(PART DONE :0012)", {"event": "PART DONE", "program": "O0012"}),
    ("PARTS=57", {"parts": "57"}),
    ("PARTS       57.", {"parts": "57"}),  # Fanuc: DPRNT[PARTS#3901[80]], sign as a space
    ("PART COUNT: 3", {"parts": "3"}),
    ("TOOL=12", {"name": "TOOL", "value": "12"}),
    ("SPINDLE LOAD=- 45.20", {"name": "SPINDLE LOAD", "value": "-45.20"}),
])
def test_default_patterns_read_the_usual_dprnt_forms(line: str, fields: dict[str, str]) -> None:
    event = DataPatterns(DEFAULT_PATTERNS).match(line)
    assert event is not None and event.fields == fields and event.line == line


@pytest.mark.parametrize("line", ["G01 X10. Y20.", "O1234", "%", "M30", "(TOOL 12 DRILL)",
                                  "#100=5", "N10 G00 X0", "PARTS=", "X" * 300 + "=1"])
def test_program_lines_are_no_data(line: str) -> None:
    assert DataPatterns(DEFAULT_PATTERNS).match(line) is None


def test_the_splitter_cuts_lines_and_hands_a_program_over() -> None:
    s = LineSplitter()
    first = s.feed(b"\x12PARTS=5\r")
    assert first.lines == ["PARTS=5"] and first.replies == b"\x11"
    assert s.feed(b"\n(CYCLE ").lines == [] and s.pending
    assert s.flush().lines == ["(CYCLE"]  # the line went quiet unended
    # bit 8 (even parity) dropped; DC codes and tape fill are no text
    assert s.feed(bytes([ord("T") | 0x80]) + b"OOL=1\x00\x13\n").lines == ["TOOL=1"]
    split = s.feed(b"junk\x00\x00%\nO1\nM30\n%")
    assert split.program_at == 6 and split.lines == [] and not s.pending
    long = s.feed(b"A" * 300 + b"\nB=1\n")
    assert long.dropped == 1 and long.lines == ["B=1"]


def test_a_program_of_data_lines_is_data_and_a_program_is_a_program() -> None:
    patterns = DataPatterns(DEFAULT_PATTERNS)
    events = data_program("%\n(CYCLE END O1)\nPARTS=3\n%\n", 26, patterns)
    assert events is not None and [e.fields for e in events] == [
        {"event": "CYCLE END", "program": "O1"}, {"parts": "3"}]
    assert data_program("%\nO1234\n(CYCLE END O1)\nM30\n%\n", 30, patterns) is None
    assert data_program("%\nPARTS=3\n%\n", 10_000, patterns) is None  # too long for DPRNT
    assert data_program("%\n%\n", 4, patterns) is None
    assert data_program("%\nPARTS=3\n%\n", 12, DataPatterns(())) is None


def test_the_queue_is_bounded_drops_the_oldest_and_survives_a_restart(tmp_path: Path) -> None:
    queue = Spool(tmp_path / "q", 10)
    for _ in range(15):
        queue.put([("t", lambda seq: f"event {seq}")])
    assert (queue.size, queue.dropped) == (10, 5)
    assert [seq for seq, _, _ in queue.after(0, 100)] == list(range(6, 16))  # oldest dropped
    queue.done([6, 7, 99])  # acknowledged (99: never queued, ignored)
    assert queue.size == 8
    queue.close()
    again = Spool(tmp_path / "q", 10)  # the gateway restarted: what was not acknowledged is there
    assert (again.size, again.dropped) == (8, 5)
    assert again.after(7, 2) == [(8, "t", "event 8"), (9, "t", "event 9")]
    again.put([("t", lambda seq: f"event {seq}")])
    assert again.after(15, 5) == [(16, "t", "event 16")]  # a seq is never used twice
    again.close()


# -- against mosquitto -------------------------------------------------------------------------


def test_two_gateways_publish_and_fleet_lists_both(
        tmp_path: Path, broker: Broker, gateways: Callable[..., Any],
        subscribers: Callable[..., Subscriber]) -> None:
    sub = subscribers(broker)
    emulators = []
    for name, ports in (("hall-1", 2), ("hall-2", 1)):
        folder = tmp_path / name
        folder.mkdir()
        emulators += [machine(folder, i) for i in range(ports)]
        gateways(mqtt_config(folder, ports, broker, name))
    try:
        assert until(lambda: len({t for t, *_ in sub.got if t.endswith("/state")}) == 5, 15)
        result = CliRunner().invoke(main, ["fleet", "--broker", broker.url, "--json"])
        assert result.exit_code == 0, result.output
        fleet = json.loads(result.output)
        names = {g["name"]: g for g in fleet["gateways"]}
        assert set(names) == {"hall-1", "hall-2"}
        assert [p["name"] for p in names["hall-1"]["ports"]] == ["m0", "m1"]
        assert [p["name"] for p in names["hall-2"]["ports"]] == ["m0"]
        assert all(g["state"] == "online" for g in names.values())
        assert {p["state"] for g in names.values() for p in g["ports"]} == {"idle"}
        # the retained states, as a later subscriber (a dashboard started afterwards) gets them
        late = subscribers(broker, name="late")
        assert until(lambda: len(late.on("/state")) == 5, 10)
        assert all(retain for *_, retain in late.messages("/state"))
        table = CliRunner().invoke(main, ["fleet", "--broker", broker.url])
        assert table.exit_code == 0
        rows = table.output.splitlines()
        assert rows[0].split()[:4] == ["gateway", "state", "#", "port"]
        assert sum(1 for r in rows if r.startswith("hall-1 ")) == 2
    finally:
        for emu in emulators:
            emu.stop()


def test_transfers_are_qos1_messages_with_the_journals_fields(
        tmp_path: Path, broker: Broker, gateways: Callable[..., Any],
        subscribers: Callable[..., Subscriber]) -> None:
    sub = subscribers(broker)
    sent_program(tmp_path, "O1234.nc", program(10))
    config = mqtt_config(tmp_path, 2, broker, "hall-1")
    asking = machine(tmp_path, 0, punch=request("O9999 (PRG=1234)\nM30"))
    punching = machine(tmp_path, 1, punch=program(5, 5555).encode())
    gateways(config)
    try:
        assert asking.wait(30)
        assert until(lambda: len(journal(tmp_path)) == 3, 20)
        assert until(lambda: len(sub.on("/transfer")) == 3, 10)
    finally:
        asking.stop()
        punching.stop()
    records = [json.loads(line) for line in
               (tmp_path / "journal.jsonl").read_text().splitlines()]
    messages = sub.messages("hall-1/transfer")
    assert [journal_fields(p) for _, p, _, _ in messages] == records
    assert all(qos == 1 and not retain for _, _, qos, retain in messages)
    assert {(r["direction"], r["result"]) for r in records} == {
        ("receive", "request"), ("send", "ok"), ("receive", "ok")}
    seqs = [p["seq"] for _, p, _, _ in messages]
    assert seqs == sorted(seqs) and len(set(seqs)) == 3
    assert all(p["gateway"] == "hall-1" for _, p, _, _ in messages)


def test_a_broker_outage_loses_nothing_and_keeps_the_order(
        tmp_path: Path, broker: Broker, gateways: Callable[..., Any],
        subscribers: Callable[..., Subscriber]) -> None:
    sub = subscribers(broker, durable=True, name="mes")
    config = mqtt_config(tmp_path, 2, broker, "hall-1")
    first = machine(tmp_path, 0, punch=program(3).encode())
    _, publisher = gateways(config)
    assert until(lambda: len(sub.on("/transfer")) == 1, 20)
    first.stop()
    broker.stop()
    assert until(lambda: not publisher.connected.is_set(), 10)
    # the broker is away: a transfer is journalled, and queued on disk
    during = machine(tmp_path, 1, punch=program(4).encode())
    assert until(lambda: len(journal(tmp_path)) == 2, 20)
    assert until(lambda: publisher.spool.size == 1, 5)
    during.stop()
    broker.start()
    assert until(lambda: len(sub.on("/transfer")) >= 2, 20)
    after = machine(tmp_path, 0, punch=program(6).encode())
    assert until(lambda: len(sub.on("/transfer")) >= 3, 20)
    after.stop()
    records = [json.loads(line) for line in
               (tmp_path / "journal.jsonl").read_text().splitlines()]
    got = sub.on("hall-1/transfer")
    assert [journal_fields(p) for p in got] == records  # each once, in the journal's order
    assert [p["seq"] for p in got] == sorted({p["seq"] for p in got})
    assert until(lambda: publisher.spool.size == 0, 5)


def test_restart_republishes_what_the_broker_never_acknowledged_and_sigkill_is_offline(
        tmp_path: Path, broker: Broker, subscribers: Callable[..., Subscriber]) -> None:
    sub = subscribers(broker, durable=True, name="mes")
    config = mqtt_config(tmp_path, 1, broker, "hall-9", extra="keepalive = 5")
    emu = Emulator(control_for("fanuc-mill", baud=BAUD), link=tmp_path / "tty0")
    gateway = serve(config)
    try:
        assert until(lambda: any(p["state"] == "online" for p in sub.on("hall-9/state")), 20)
        broker.stop()
        # the broker is away: the machine prints its data; journalled and queued, not acked
        emu.print_data(DprntSchedule(0.05, cycles=1))
        assert until(lambda: len(journal(tmp_path)) == 3, 20)
        gateway.send_signal(signal.SIGKILL)
        gateway.wait(10)
        broker.start()
        gateway = serve(config)  # what the broker never acknowledged is published again
        assert until(lambda: len(sub.on("hall-9/port/m0/data")) == 3, 20), (
            tmp_path / "serve.log").read_text()
        lines = [p["line"] for p in sub.on("hall-9/port/m0/data")]
        assert lines == ["(CYCLE START O1234)", "(CYCLE END O1234)", "PARTS=1"]
        assert [journal_fields(p) for p in sub.on("hall-9/transfer")] == [
            json.loads(line) for line in (tmp_path / "journal.jsonl").read_text().splitlines()]
        assert until(lambda: sub.on("hall-9/state")[-1]["state"] == "online", 10)
        gateway.send_signal(signal.SIGKILL)  # the broker sees the link drop: the last will
        gateway.wait(10)
        assert until(lambda: sub.on("hall-9/state")[-1]["state"] == "offline", 15)
        will = sub.on("hall-9/state")[-1]
        assert will["reason"] == "lost" and will["gateway"] == "hall-9"
        fleet = CliRunner().invoke(main, ["fleet", "--broker", broker.url, "--json"])
        assert json.loads(fleet.output)["gateways"][0]["state"] == "offline"
    finally:
        if gateway.poll() is None:
            gateway.kill()
            gateway.wait(10)
        emu.stop()


def test_a_record_journalled_but_never_queued_is_published_after_a_restart(
        tmp_path: Path, broker: Broker, subscribers: Callable[..., Subscriber]) -> None:
    """The gateway stopped between the journal's append and the queue's: the journal is the
    record of truth, and the next start queues what it has and the queue has not."""
    sub = subscribers(broker)
    config = mqtt_config(tmp_path, 1, broker, "hall-1")
    Journal(tmp_path / "journal.jsonl").append(Transfer("m0", "receive", "O1.nc", 10, 2, "t0",
                                                        "t0", "ok"))  # before MQTT: not sent
    gateway = Gateway(load_config(config))
    first = Publisher(gateway, gateway.config.mqtt)
    first.start()
    gateway.record(Transfer("m0", "receive", "O2.nc", 10, 2, "t1", "t1", "ok"))
    assert until(lambda: len(sub.on("/transfer")) == 1, 10)
    first.stop()
    # journalled, never queued (as if the process had died between the two)
    gateway.journal.append(Transfer("m0", "send", "O3.nc", 30, 3, "t2", "t2", "failed",  # type: ignore[union-attr]
                                    ["no DC1"]))
    gateway.journal.append(Transfer("m0", "data", "PARTS=7", 7, 1, "t3", "t3", "ok"))  # type: ignore[union-attr]
    with open(tmp_path / "journal.jsonl", "a") as torn:
        torn.write('{"port": "m0", "dire')  # the line the crash cut
    second = Publisher(gateway, gateway.config.mqtt)
    assert second.catch_up() == 2 and second.spool.size == 3
    second.start()  # catch_up again: nothing more
    try:
        assert until(lambda: len(sub.on("/transfer")) == 3 and len(sub.on("/data")) == 1, 10)
        assert [p["program"] for p in sub.on("/transfer")] == ["O2.nc", "O3.nc", "PARTS=7"]
        assert sub.on("/data")[0]["fields"] == {"parts": "7"}
        assert second.spool.size == 0 or until(lambda: second.spool.size == 0, 5)
    finally:
        second.stop()


class Killed(BaseException):
    """SIGKILL at a chosen write of the queue: nothing after it runs."""


@pytest.mark.parametrize("dies_at", [1, 2])
def test_a_data_record_is_queued_once_whichever_queue_write_the_gateway_dies_at(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch, dies_at: int) -> None:
    """A DPRNT line is one journal record and two messages (its transfer and its data): both
    are queued, with the journal's offset, in one write, so a gateway killed at any moment
    queues the record once, on this run or through the next start's catch-up. (Queued in two
    writes, a kill between them left the transfer queued and the offset before the record,
    and the next start queued the transfer again: one message too many.)"""
    config = mqtt_config(tmp_path, 1, Broker(tmp_path / "broker", free_port()), "hall-1")
    Journal(tmp_path / "journal.jsonl").append(Transfer("m0", "receive", "O1.nc", 10, 2, "t0",
                                                        "t0", "ok"))  # before MQTT: not sent
    gateway = Gateway(load_config(config))
    first = Publisher(gateway, gateway.config.mqtt)
    first.catch_up()  # a new queue: from the journal's end on
    gateway.listeners.append(first)
    writes = 0
    put = Spool.put

    def dying(spool: Spool, *args: Any, **kw: Any) -> int:
        nonlocal writes
        writes += 1
        if writes == dies_at:
            raise Killed
        return put(spool, *args, **kw)

    monkeypatch.setattr(Spool, "put", dying)
    event = DataPatterns(DEFAULT_PATTERNS).match("PARTS=7")
    assert event is not None
    record = Transfer("m0", "data", "PARTS=7", 7, 1, "t1", "t1", "ok")
    killed = False
    try:
        gateway.record(record, event)
    except Killed:
        killed = True
    first.spool.close()
    monkeypatch.undo()
    assert killed or dies_at > writes  # died there, or queued the record in fewer writes
    assert [t.program for t in journal(tmp_path)] == ["O1.nc", "PARTS=7"]  # journalled first
    second = Publisher(gateway, gateway.config.mqtt)  # the next start
    try:
        second.catch_up()
        queued = [(topic, json.loads(payload)) for _, topic, payload in second.spool.after(0, 10)]
    finally:
        second.spool.close()
    assert [(topic, p.get("program"), p.get("line")) for topic, p in queued] == [
        ("tapegate/hall-1/transfer", "PARTS=7", None),
        ("tapegate/hall-1/port/m0/data", None, "PARTS=7")]


def test_a_full_queue_logs_its_first_and_tenth_drop_when_a_record_drops_two(
        tmp_path: Path, caplog: pytest.LogCaptureFixture) -> None:
    config = mqtt_config(tmp_path, 1, Broker(tmp_path / "broker", free_port()), "hall-1")
    gateway = Gateway(load_config(config))
    publisher = Publisher(gateway, gateway.config.mqtt)
    publisher.spool.close()
    publisher.spool = Spool(tmp_path / "small.queue", 4)
    event = DataPatterns(DEFAULT_PATTERNS).match("PARTS=7")
    caplog.set_level("WARNING", "tapegate.mqtt")
    try:
        for _ in range(8):  # two messages a record: 0, 0, 2, 4 ... 12 dropped
            publisher.record(Transfer("m0", "data", "PARTS=7", 7, 1, "t1", "t1", "ok"), event)
        assert publisher.spool.dropped == 12
    finally:
        publisher.spool.close()
    logged = [r.getMessage() for r in caplog.records if "queue full" in r.getMessage()]
    assert [m.split("dropped, ")[1].split(" so far")[0] for m in logged] == ["2", "10"], logged


def test_commands_are_refused_unless_allowed(
        tmp_path: Path, broker: Broker, gateways: Callable[..., Any],
        subscribers: Callable[..., Subscriber]) -> None:
    sub = subscribers(broker)
    sent_program(tmp_path, "O1234.nc", program(5))
    gateway, publisher = gateways(mqtt_config(tmp_path, 1, broker, "hall-1"))
    assert until(lambda: publisher.listening.is_set(), 10)
    sub.client.publish("tapegate/hall-1/port/m0/command",
                       json.dumps({"command": "send", "program": 1234}), qos=1)
    assert until(lambda: len(journal(tmp_path)) == 1, 10)
    (refused,) = journal(tmp_path)
    assert (refused.port, refused.direction, refused.program, refused.result) == (
        "m0", "command", "mqtt command", "refused")
    assert refused.errors == ["commands are disabled (mqtt.allow_commands = false)"]
    assert gateway.port(0).jobs.empty()


def test_commands_act_when_allowed_and_malformed_ones_change_nothing(
        tmp_path: Path, broker: Broker, gateways: Callable[..., Any],
        subscribers: Callable[..., Subscriber]) -> None:
    sub = subscribers(broker)
    expected_text = program(5)
    sent_program(tmp_path, "O1234.nc", expected_text)
    emu = machine(tmp_path, 0)
    gateway, publisher = gateways(mqtt_config(tmp_path, 1, broker, "hall-1",
                                              extra="allow_commands = true"))
    assert until(lambda: publisher.listening.is_set(), 10)
    assert until(lambda: gateway.port(0).status.state == State.IDLE, 10)
    topic = "tapegate/hall-1/port/{}/command"
    bad = [
        ("m0", b"send 1234", "not JSON"),
        ("m0", b"\xff\xfe", "not JSON"),
        ("m0", b"[1, 2]", "a command is a JSON object, not list"),
        ("m0", json.dumps({"command": "send", "program": "1234"}).encode(),
         "program must be a program number"),
        ("m0", json.dumps({"command": "send", "program": True}).encode(),
         "program must be a program number"),
        ("m0", json.dumps({"command": "format"}).encode(), "command must be \"send\""),
        ("m0", json.dumps({"command": "abort", "program": 5}).encode(), "abort takes no"),
        ("m0", json.dumps({"command": "send", "program": 1, "x": 1}).encode(), "unknown key"),
        ("m0", b"{" + b" " * 5000 + b"}", "a payload of 5002 bytes"),
        ("m9", json.dumps({"command": "abort"}).encode(), "no port named 'm9'"),
    ]
    for port, payload, _ in bad:
        sub.client.publish(topic.format(port), payload, qos=1)
    assert until(lambda: len(journal(tmp_path)) == len(bad), 10)
    for record, (port, _, why) in zip(journal(tmp_path), bad, strict=True):
        assert (record.direction, record.program, record.result) == (
            "command", "mqtt command", "bad command")
        assert record.port == ("mqtt" if port == "m9" else "m0")
        assert why in record.errors[0], (why, record.errors)
    assert gateway.port(0).jobs.empty() and gateway.port(0).status.transfers == 0
    # and a good one: sent on the control's next DC1, journalled as a Modbus send is
    sub.client.publish(topic.format("m0"), json.dumps({"command": "send", "program": 1234}),
                       qos=1)
    try:
        assert emu.wait(30), "the control did not get its program"
    finally:
        emu.stop()
    assert until(lambda: len(journal(tmp_path)) == len(bad) + 1, 10)
    sent = journal(tmp_path)[-1]
    assert (sent.direction, sent.program, sent.result) == ("send", "O1234.nc", "ok")
    assert emu.control.programs and "O1234" in emu.control.programs[0]
    assert until(lambda: len(sub.on("hall-1/transfer")) == len(bad) + 1, 10)


def test_dprnt_lines_are_data_never_received_programs(
        tmp_path: Path, broker: Broker, gateways: Callable[..., Any],
        subscribers: Callable[..., Subscriber]) -> None:
    sub = subscribers(broker)
    config = mqtt_config(tmp_path, 3, broker, "hall-1")
    fanuc = machine(tmp_path, 0)
    haas = machine(tmp_path, 1)
    gateway, _ = gateways(config)
    # POPEN/PCLOS on a control that frames its output in % as a program: still data
    framed = machine(tmp_path, 2, punch=b"\x12%\n(CYCLE END O5)\nPARTS=9\n%\x14")
    try:
        # the machines print once the gateway listens (before, it would be lost on the line)
        assert until(lambda: all(w.status.state == State.IDLE for w in gateway.ports[:2]), 10)
        fanuc.print_data(DprntSchedule(0.1, "O1234", "fanuc", cycles=2))
        haas.print_data(DprntSchedule(0.1, "O77", "haas", cycles=1, parts=40))
        assert until(lambda: len(sub.on("/data")) == 6 + 3 + 2, 20), sub.on("/data")
    finally:
        for emu in (fanuc, haas, framed):
            emu.stop()
    lines = {port: [p["line"] for p in sub.on(f"hall-1/port/{port}/data")]
             for port in ("m0", "m1", "m2")}
    assert lines["m0"] == ["(CYCLE START O1234)", "(CYCLE END O1234)", "PARTS=1",
                           "(CYCLE START O1234)", "(CYCLE END O1234)", "PARTS=2"]
    assert lines["m1"] == ["(CYCLE START O77)", "(CYCLE END O77)", "PARTS=41"]
    assert lines["m2"] == ["(CYCLE END O5)", "PARTS=9"]
    message = sub.on("hall-1/port/m1/data")[-1]
    assert message["fields"] == {"parts": "41"} and message["port"] == "m1"
    assert not any((tmp_path / "received").rglob("*.nc")), "a data line was saved as a program"
    records = journal(tmp_path)
    assert {(r.direction, r.result) for r in records} == {("data", "ok")}
    assert len(records) == 11
    # counted on the status page and in the Modbus registers
    status = gateway.port(1).status
    assert (status.data_lines, status.data_last, status.parts) == (3, "PARTS=41", 41)
    regs = input_registers(gateway.port(0).status)
    assert regs[IR_DATA_LINES] == 6 and (regs[IR_PARTS] << 16 | regs[IR_PARTS + 1]) == 2
    assert regs[IR_DATA_EVENT] == 2  # the last event: the end of a cycle (PARTS= is none)
    assert until(lambda: sub.on("hall-1/port/m1/state")[-1]["data_lines"] == 3, 5)
    # a real program on the same port is still received
    punching = machine(tmp_path, 1, punch=program(4).encode())
    assert until(lambda: any(r.direction == "receive" for r in journal(tmp_path)), 20)
    punching.stop()
    assert any((tmp_path / "received" / "m1").glob("*.nc"))


def test_emulate_prints_dprnt_lines_on_a_schedule(tmp_path: Path) -> None:
    proc = subprocess.Popen([sys.executable, "-m", "tapegate", "emulate", "-p", "haas-mill",
                             "--dprnt-every", "0.3", "--dprnt-cycles", "2", "--dprnt-form",
                             "haas", "--dprnt-program", "O42"], stderr=subprocess.PIPE,
                            cwd=Path(__file__).parent.parent)
    try:
        assert proc.stderr is not None
        first = proc.stderr.readline().decode()
        assert first.startswith("port: ")
        fd = os.open(first.split(": ", 1)[1].strip(), os.O_RDWR | os.O_NOCTTY)
        data = b""
        end = time.monotonic() + 10
        while data.count(b"\r\n") < 6 and time.monotonic() < end:
            try:
                data += os.read(fd, 1024)
            except OSError:  # EIO: the emulator has exited and closed its side
                break
        os.close(fd)
        assert proc.wait(10) == 0
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait(5)
    text = bytes(b for b in data if b not in (0x11, 0x13)).decode()
    assert text == ("(CYCLE START O42)\r\n(CYCLE END O42)\r\nPARTS=1\r\n"
                    "(CYCLE START O42)\r\n(CYCLE END O42)\r\nPARTS=2\r\n")


def test_emulate_keeps_dprnt_lines_for_a_host_that_reads_late_after_sending_a_program(
        tmp_path: Path) -> None:
    """A host that sends a program, then reads nothing until the printed lines have all
    arrived at its end, still gets every one: the emulator keeps the pty until the host has
    read them (closing it would throw them away; it did once the control had read a program)."""
    import fcntl
    import termios
    import tty
    proc = subprocess.Popen([sys.executable, "-m", "tapegate", "emulate", "-p", "haas-mill",
                             "--baud", "115200", "--dprnt-every", "0.2", "--dprnt-cycles", "2",
                             "--dprnt-form", "haas", "--dprnt-program", "O42"],
                            stderr=subprocess.PIPE, cwd=Path(__file__).parent.parent)
    expected = ("(CYCLE START O42)\r\n(CYCLE END O42)\r\nPARTS=1\r\n"
                "(CYCLE START O42)\r\n(CYCLE END O42)\r\nPARTS=2\r\n")
    try:
        assert proc.stderr is not None
        first = proc.stderr.readline().decode()
        assert first.startswith("port: ")
        fd = os.open(first.split(": ", 1)[1].strip(), os.O_RDWR | os.O_NOCTTY)
        tty.setraw(fd)
        os.write(fd, b"%\nO0001\nG0 X1.\nM30\n%\n")

        def waiting() -> int:
            buf = bytearray(4)
            fcntl.ioctl(fd, termios.FIONREAD, buf)
            return int.from_bytes(buf, sys.byteorder)

        # the condition: every printed byte waits at the host's end, unread
        end = time.monotonic() + 15
        while waiting() < len(expected) and time.monotonic() < end:
            time.sleep(0.02)
        data = b""
        while True:
            try:
                chunk = os.read(fd, 4096) if waiting() else b""
            except OSError:
                break
            if not chunk:
                break
            data += chunk
        os.close(fd)
        proc.wait(15)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait(5)
    text = bytes(b for b in data if b >= 0x20 and b < 0x7F or b in (0x0D, 0x0A)).decode()
    assert text == expected


def test_fleet_says_why_it_cannot_reach_the_broker() -> None:
    port = free_port()  # nobody listens there
    result = CliRunner().invoke(main, ["fleet", "--broker", f"mqtt://127.0.0.1:{port}"])
    assert result.exit_code == 3
    assert f"cannot reach the broker mqtt://127.0.0.1:{port}" in result.output
    bad = CliRunner().invoke(main, ["fleet", "--broker", "tcp://x"])
    assert bad.exit_code == 2 and "--broker = 'tcp://x'" in bad.output
    tls = CliRunner().invoke(main, ["fleet", "--broker", "mqtt://x", "--ca", __file__])
    assert tls.exit_code == 2 and "are for TLS" in tls.output
    # NaN passed click's FloatRange(0.1, 600): compared false with both ends
    nan = CliRunner().invoke(main, ["fleet", "--broker", "mqtt://x", "--timeout", "nan"])
    assert nan.exit_code == 2
    assert "Invalid value for '--timeout': 'nan' is not a finite number" in nan.output


def test_fleet_watch_and_web_page(tmp_path: Path, broker: Broker,
                                  gateways: Callable[..., Any]) -> None:
    emu = machine(tmp_path, 0)
    gateway, publisher = gateways(mqtt_config(tmp_path, 1, broker, "hall-3"))
    root = Path(__file__).parent.parent
    web_port = free_port()
    page = subprocess.Popen([sys.executable, "-m", "tapegate", "fleet", "--broker", broker.url,
                             "--web", f"127.0.0.1:{web_port}"], cwd=root,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    watch = subprocess.Popen([sys.executable, "-m", "tapegate", "fleet", "--broker", broker.url,
                              "--watch", "--json"], cwd=root, stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL)
    try:
        def fleet_json() -> Any:
            try:
                with urllib.request.urlopen(f"http://127.0.0.1:{web_port}/fleet.json",
                                            timeout=2) as r:
                    return json.loads(r.read())
            except OSError:
                return None

        assert until(lambda: (fleet_json() or {}).get("gateways"), 15)
        (g,) = fleet_json()["gateways"]
        assert g["name"] == "hall-3" and g["state"] == "online" and g["ports"][0]["name"] == "m0"
        with urllib.request.urlopen(f"http://127.0.0.1:{web_port}/", timeout=2) as r:
            html = r.read().decode()
            assert "tapegate fleet" in html and "static/status.css" in html
            assert r.headers["X-Content-Type-Options"] == "nosniff"
        with pytest.raises(urllib.error.HTTPError) as refused:  # read-only: GET and HEAD
            urllib.request.urlopen(urllib.request.Request(
                f"http://127.0.0.1:{web_port}/fleet.json", data=b"{}", method="POST"), timeout=2)
        assert refused.value.code == 405
        assert watch.stdout is not None
        first = json.loads(watch.stdout.readline())
        assert [x["name"] for x in first["gateways"]] == ["hall-3"]
        # a change (the gateway stops: its state and its port's) is printed again
        gateway.stop()
        publisher.stop(drain=0.5)
        line = ""
        end = time.monotonic() + 15
        while time.monotonic() < end:
            line = watch.stdout.readline().decode()
            if json.loads(line)["gateways"][0]["state"] == "offline":
                break
        assert json.loads(line)["gateways"][0]["state"] == "offline"
        for proc in (page, watch):
            proc.send_signal(signal.SIGINT)
            assert proc.wait(10) == 0
    finally:
        for proc in (page, watch):
            if proc.poll() is None:
                proc.kill()
                proc.wait(5)
            for stream in (proc.stdout, proc.stderr):
                if stream is not None:
                    stream.close()
        emu.stop()


OPENSSL = shutil.which("openssl")
PASSWD = shutil.which("mosquitto_passwd", path=os.pathsep.join(
    [os.environ.get("PATH", ""), "/usr/bin", "/usr/sbin"]))


def make_certificates(folder: Path) -> None:
    """A CA, a server certificate for 127.0.0.1 and a client certificate, for two days."""
    assert OPENSSL is not None

    def run(*args: str) -> None:
        subprocess.run([OPENSSL, *args], cwd=folder, check=True, capture_output=True,
                       timeout=60)

    run("req", "-x509", "-newkey", "rsa:2048", "-nodes", "-keyout", "ca.key", "-out", "ca.pem",
        "-days", "2", "-subj", "/CN=tapegate test CA")
    (folder / "san.ext").write_text("subjectAltName=IP:127.0.0.1,DNS:localhost\n")
    for name, cn in (("server", "localhost"), ("client", "hall-1")):
        run("req", "-newkey", "rsa:2048", "-nodes", "-keyout", f"{name}.key", "-out",
            f"{name}.csr", "-subj", f"/CN={cn}")
        run("x509", "-req", "-in", f"{name}.csr", "-CA", "ca.pem", "-CAkey", "ca.key",
            "-CAcreateserial", "-out", f"{name}.pem", "-days", "2", "-extfile", "san.ext")


@pytest.mark.skipif(OPENSSL is None or PASSWD is None,
                    reason="openssl or mosquitto_passwd is not installed")
def test_mqtts_with_a_client_certificate_and_a_password(tmp_path: Path,
                                                        gateways: Callable[..., Any]) -> None:
    certs = tmp_path / "certs"
    certs.mkdir()
    make_certificates(certs)
    assert PASSWD is not None
    subprocess.run([PASSWD, "-b", "-c", str(certs / "passwd"), "hall-1", "s3cret"], check=True,
                   capture_output=True, timeout=30)
    broker = Broker(tmp_path / "broker", free_port())
    broker.config.write_text(broker.config.read_text() + (
        f"cafile {certs}/ca.pem\ncertfile {certs}/server.pem\nkeyfile {certs}/server.key\n"
        f"require_certificate true\npassword_file {certs}/passwd\n").replace(
        "allow_anonymous true", "allow_anonymous false"))
    broker.url = broker.url.replace("mqtt://", "mqtts://")
    broker.start()
    try:
        (tmp_path / "pass").write_text("s3cret\n")
        emu = machine(tmp_path, 0)
        config = mqtt_config(tmp_path, 1, broker, "hall-1", extra=(
            'ca = "certs/ca.pem"\ncert = "certs/client.pem"\nkey = "certs/client.key"\n'
            'user = "hall-1"\npassword_file = "pass"'))
        _, publisher = gateways(config)
        assert until(lambda: publisher.connected.is_set(), 15)
        tls = ["--ca", str(certs / "ca.pem"), "--cert", str(certs / "client.pem"), "--key",
               str(certs / "client.key"), "--user", "hall-1"]
        good = tmp_path / "pass"
        result = CliRunner().invoke(main, ["fleet", "--broker", broker.url, "--json", *tls,
                                           "--password-file", str(good)])
        assert result.exit_code == 0, result.output
        (g,) = json.loads(result.output)["gateways"]
        assert (g["name"], g["state"]) == ("hall-1", "online")
        # the wrong password: the broker refuses, fleet says so (exit 3)
        bad = tmp_path / "bad"
        bad.write_text("nope\n")
        refused = CliRunner().invoke(main, ["fleet", "--broker", broker.url, *tls,
                                            "--password-file", str(bad)])
        assert refused.exit_code == 3 and "refused" in refused.output, refused.output
        # no client certificate: the TLS handshake fails
        plain = CliRunner().invoke(main, ["fleet", "--broker", broker.url, "--ca",
                                          str(certs / "ca.pem"), "--timeout", "3"])
        assert plain.exit_code == 3 and "Traceback" not in plain.output, plain.output
        emu.stop()
    finally:
        broker.stop()


def test_a_queue_that_cannot_be_opened_stops_serve_with_exit_3(tmp_path: Path) -> None:
    (tmp_path / "afile").write_text("")
    config = write_config(tmp_path, 1)
    config.write_text(config.read_text() + '[mqtt]\nenabled = true\ngateway = "g"\n'
                      'broker = "mqtt://127.0.0.1:9"\nqueue = "afile/q.queue"\n')
    result = subprocess.run([sys.executable, "-m", "tapegate", "serve", "--config", str(config)],
                            capture_output=True, text=True, timeout=60,
                            cwd=Path(__file__).parent.parent)
    assert result.returncode == 3, result.stderr
    assert "tapegate: mqtt: cannot open the queue" in result.stderr
    assert "afile/q.queue" in result.stderr and "Traceback" not in result.stderr


@pytest.mark.skipif(PASSWD is None, reason="mosquitto_passwd is not installed")
def test_the_documented_acl_lets_only_the_mes_write_commands(
        tmp_path: Path, gateways: Callable[..., Any]) -> None:
    doc = (Path(__file__).resolve().parents[1] / "docs" / "mqtt.md").read_text()
    acl = next(code for code in (block.split("```")[0] for block in doc.split("```text\n")[1:])
               if "tapegate.acl" in code)
    (tmp_path / "acl").write_text(acl)
    assert PASSWD is not None
    for i, (user, password) in enumerate((("hall-1", "pw-gateway"), ("mes", "pw-mes"),
                                          ("dashboard", "pw-dash"))):
        subprocess.run([PASSWD, "-b", *(["-c"] if i == 0 else []), str(tmp_path / "passwd"),
                        user, password], check=True, capture_output=True, timeout=30)
    broker = Broker(tmp_path / "broker", free_port())
    broker.config.write_text(broker.config.read_text().replace(
        "allow_anonymous true", "allow_anonymous false") +
        f"password_file {tmp_path}/passwd\nacl_file {tmp_path}/acl\n")
    broker.start()
    try:
        (tmp_path / "pass").write_text("pw-gateway\n")
        config = mqtt_config(tmp_path, 1, broker, "hall-1", extra=(
            'user = "hall-1"\npassword_file = "pass"\nallow_commands = true'))
        _, publisher = gateways(config)
        assert until(lambda: publisher.listening.is_set(), 10)  # its command topic: allowed

        def client(user: str, password: str) -> paho.Client:
            c = paho.Client(CallbackAPIVersion.VERSION2, client_id=user)
            c.username_pw_set(user, password)
            c.connect("127.0.0.1", broker.port)
            c.loop_start()
            return c

        dashboard, mes = client("dashboard", "pw-dash"), client("mes", "pw-mes")
        seen: list[str] = []
        mes.on_message = lambda c, u, m: seen.append(m.topic)
        mes.subscribe("tapegate/#", qos=1)
        assert until(lambda: "tapegate/hall-1/state" in seen, 10)  # retained, allowed to read
        topic = "tapegate/hall-1/port/m0/command"
        # the dashboard's command is dropped by the broker; the MES's reaches the gateway
        dashboard.publish(topic, b"from the dashboard", qos=1).wait_for_publish(5)
        mes.publish(topic, json.dumps({"command": "format"}), qos=1).wait_for_publish(5)
        assert until(lambda: len(journal(tmp_path)) >= 1, 10)
        # published as a transfer: the gateway may write it and the MES read it
        assert until(lambda: "tapegate/hall-1/transfer" in seen, 10)
        (record,) = journal(tmp_path)
        assert record.result == "bad command" and "command must be" in record.errors[0]
        # the dashboard reads the fleet; what the gateway publishes is allowed
        (tmp_path / "dash").write_text("pw-dash\n")
        fleet = CliRunner().invoke(main, ["fleet", "--broker", f"mqtt://127.0.0.1:{broker.port}",
                                          "--json", "--user", "dashboard", "--password-file",
                                          str(tmp_path / "dash")])
        assert fleet.exit_code == 0, fleet.output
        (g,) = json.loads(fleet.output)["gateways"]
        assert g["state"] == "online" and [p["name"] for p in g["ports"]] == ["m0"]
        for c in (dashboard, mes):
            c.disconnect()
            c.loop_stop()
    finally:
        broker.stop()
