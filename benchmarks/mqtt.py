"""MQTT benchmark: many gateways, many machines printing DPRNT data, one mosquitto.

    .venv/bin/python benchmarks/mqtt.py [--gateways 10] [--ports 32] [--off 1] [--every 2.0]
                                        [--steady 30] [--outage 60]

Starts mosquitto (persistent, on a free loopback port), ``--gateways`` ``tapegate serve``
processes with ``[mqtt]`` enabled and ``--off`` more without it, each with ``--ports`` ports.
Each port is a pseudo-terminal (behind a symbolic link) on which this process plays the
machine: every ``--every`` seconds, staggered over the ports, its macro prints one DPRNT line
``PARTS=<n>`` (Haas form, CR LF), ``n`` unique across the run. A subscriber of this process
(a persistent session) receives everything under ``tapegate/#``.

Phases: ``--steady`` seconds of load (messages per second received, latency from the line
written on the pty to the data message received and from the gateway's event time to receipt,
the gateways' CPU with MQTT on and off from /proc); then the broker is stopped for ``--outage``
seconds under the same load, started again, and the benchmark waits until every line written
has arrived: lines lost, duplicates, order (seq per gateway), and the time to drain the queues.
"""

from __future__ import annotations

import argparse
import contextlib
import getpass
import json
import os
import shutil
import socket
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from datetime import datetime
from pathlib import Path
from typing import Any

import paho.mqtt.client as paho
from paho.mqtt.enums import CallbackAPIVersion

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


class Broker:
    def __init__(self, folder: Path):
        self.port = free_port()
        self.folder = folder
        folder.mkdir(parents=True, exist_ok=True)
        self.config = folder / "mosquitto.conf"
        self.config.write_text(
            f"listener {self.port} 127.0.0.1\nallow_anonymous true\npersistence true\n"
            f"persistence_location {folder}/\nlog_dest none\nuser {getpass.getuser()}\n"
            "max_queued_messages 0\nmax_inflight_messages 100\n")
        self.process: subprocess.Popen[bytes] | None = None
        self.exe = shutil.which("mosquitto", path=os.environ.get("PATH", "") + ":/usr/sbin")
        if self.exe is None:
            sys.exit("mosquitto is not installed (apt-get install mosquitto)")

    def start(self) -> None:
        assert self.exe is not None
        self.process = subprocess.Popen([self.exe, "-c", str(self.config)],
                                        stderr=subprocess.DEVNULL)
        end = time.monotonic() + 10
        while time.monotonic() < end:
            try:
                socket.create_connection(("127.0.0.1", self.port), timeout=0.2).close()
                return
            except OSError:
                time.sleep(0.05)
        sys.exit("mosquitto did not start")

    def stop(self) -> None:
        if self.process is not None:
            self.process.terminate()
            self.process.wait(30)
            self.process = None


class Receiver:
    """A persistent session on tapegate/#: the data messages by part number, and counts."""

    def __init__(self, port: int):
        self.lock = threading.Lock()
        self.total = 0
        self.received: dict[int, list[float]] = {}  # parts -> receipt times (monotonic)
        self.event_lag: list[float] = []  # gateway's event time -> receipt, seconds
        self.seqs: dict[str, list[int]] = {}  # gateway -> data seqs in the order received
        self.client = paho.Client(CallbackAPIVersion.VERSION2, client_id="bench-mes",
                                  clean_session=False)
        self.client.on_connect = lambda c, u, f, r, p: c.subscribe("tapegate/#", qos=1)
        self.client.on_message = self.message
        self.client.reconnect_delay_set(1, 1)
        self.client.connect("127.0.0.1", port)
        self.client.loop_start()

    def message(self, client: paho.Client, userdata: Any, m: paho.MQTTMessage) -> None:
        now, wall = time.monotonic(), time.time()
        with self.lock:
            self.total += 1
            if not m.topic.endswith("/data"):
                return
            data = json.loads(m.payload)
            self.received.setdefault(int(data["fields"]["parts"]), []).append(now)
            self.seqs.setdefault(data["gateway"], []).append(data["seq"])
            moment = datetime.fromisoformat(data["time"]).timestamp()
            self.event_lag.append(wall - moment)


class Machines:
    """The ports' far ends: every --every seconds each prints PARTS=<n>, staggered."""

    def __init__(self, folder: Path, count: int, every: float):
        self.links: list[Path] = []
        self.masters: list[int] = []
        self.slaves: list[int] = []
        for i in range(count):
            master, slave = os.openpty()
            link = folder / f"tty{i}"
            link.symlink_to(os.ttyname(slave))
            self.masters.append(master)
            self.slaves.append(slave)  # kept open: the pty stays whatever the gateway does
            self.links.append(link)
        self.every = every
        self.written: dict[int, float] = {}  # parts -> when written (monotonic)
        self.lock = threading.Lock()
        self.next = 1
        self.stop = threading.Event()
        self.thread = threading.Thread(target=self.run, daemon=True)

    def run(self) -> None:
        n = len(self.masters)
        start = time.monotonic()
        k = 0
        while not self.stop.is_set():
            at = start + k * self.every / n
            delay = at - time.monotonic()
            if delay > 0 and self.stop.wait(delay):
                break
            with self.lock:
                parts = self.next
                self.next += 1
                self.written[parts] = time.monotonic()
            with contextlib.suppress(OSError):  # a port the gateway has not opened yet
                os.write(self.masters[k % n], f"PARTS={parts}\r\n".encode())
            k += 1


def config(folder: Path, name: str, links: list[Path], broker: int, mqtt: bool) -> Path:
    (folder / "programs").mkdir(parents=True, exist_ok=True)
    text = ['[gateway]\njournal = "journal.jsonl"\n']
    if mqtt:
        text.append(f'[mqtt]\nenabled = true\nbroker = "mqtt://127.0.0.1:{broker}"\n'
                    f'gateway = "{name}"\n')
    for i, link in enumerate(links):
        text.append(f'[[port]]\nname = "p{i}"\nurl = "{link}"\nprofile = "haas-mill"\n'
                    f'programs = "programs"\nreceive = "received"\n')
    path = folder / "gateway.toml"
    path.write_text("".join(text))
    return path


def cpu_seconds(pid: int) -> float:
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def quantile(values: list[float], q: float) -> float:
    values = sorted(values)
    return values[min(len(values) - 1, int(q * len(values)))] if values else float("nan")


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--gateways", type=int, default=10, help="gateways with [mqtt] enabled")
    ap.add_argument("--off", type=int, default=1, help="more gateways, [mqtt] off (CPU)")
    ap.add_argument("--ports", type=int, default=32)
    ap.add_argument("--every", type=float, default=2.0, help="seconds between two lines/port")
    ap.add_argument("--steady", type=float, default=30.0)
    ap.add_argument("--outage", type=float, default=60.0)
    args = ap.parse_args()
    tmp = Path(tempfile.mkdtemp(prefix="tapegate-mqtt-bench-"))
    broker = Broker(tmp / "broker")
    broker.start()
    total = args.gateways + args.off
    machines = Machines(tmp, total * args.ports, args.every)
    gateways: list[tuple[str, bool, subprocess.Popen[bytes]]] = []
    for g in range(total):
        on = g < args.gateways
        name = f"hall-{g}" if on else f"off-{g}"
        folder = tmp / name
        folder.mkdir()
        path = config(folder, name, machines.links[g * args.ports:(g + 1) * args.ports],
                      broker.port, on)
        with open(folder / "serve.log", "wb") as log:
            gateways.append((name, on, subprocess.Popen(
                [sys.executable, "-m", "tapegate", "serve", "--config", str(path),
                 "--log-level", "warning"], cwd=ROOT, stdout=subprocess.DEVNULL, stderr=log)))
    receiver = Receiver(broker.port)
    # every gateway online and every port listening (its retained state says idle)
    end = time.monotonic() + 120
    while time.monotonic() < end:
        with receiver.lock:
            ready = receiver.total >= args.gateways * (1 + args.ports)
        if ready:
            break
        time.sleep(0.2)
    time.sleep(2.0)
    print(f"{args.gateways} gateways with MQTT + {args.off} without, {args.ports} ports each "
          f"({total * args.ports} ports), a line per port every {args.every:g} s "
          f"({total * args.ports / args.every:.0f} lines/s in all, "
          f"{args.gateways * args.ports / args.every:.0f} published)")
    machines.thread.start()
    time.sleep(3.0)  # the first lines reach every gateway
    with receiver.lock:
        count0, lag0 = receiver.total, len(receiver.event_lag)
    first_parts = machines.next
    cpu0 = {name: cpu_seconds(p.pid) for name, _, p in gateways}
    t0 = time.monotonic()
    time.sleep(args.steady)
    t1 = time.monotonic()
    cpu1 = {name: cpu_seconds(p.pid) for name, _, p in gateways}
    with receiver.lock:
        count1 = receiver.total
        lags = receiver.event_lag[lag0:]
        last_parts = machines.next
        pty_lags = [receiver.received[n][0] - machines.written[n]
                    for n in range(first_parts, last_parts) if n in receiver.received]
    span = t1 - t0
    rate = (count1 - count0) / span
    print(f"steady {span:.0f} s: {rate:,.0f} messages/s received (all topics), "
          f"{len(pty_lags) / span:,.0f} data lines/s")
    print(f"latency, gateway event -> received: median {statistics.median(lags) * 1000:.0f} ms, "
          f"p99 {quantile(lags, 0.99) * 1000:.0f} ms ({len(lags)} messages)")
    print(f"latency, line written on the pty -> received: median "
          f"{statistics.median(pty_lags) * 1000:.0f} ms, p99 {quantile(pty_lags, 0.99) * 1000:.0f}"
          " ms")
    on = [(cpu1[n] - cpu0[n]) / span for n, o, _ in gateways if o]
    off = [(cpu1[n] - cpu0[n]) / span for n, o, _ in gateways if not o]
    print(f"gateway CPU, MQTT on: mean {statistics.mean(on):.1%} of a core "
          f"(min {min(on):.1%}, max {max(on):.1%})")
    if off:
        print(f"gateway CPU, MQTT off: mean {statistics.mean(off):.1%} of a core "
              f"(min {min(off):.1%}, max {max(off):.1%})")
    if args.outage > 0:
        outage_first = machines.next
        broker.stop()
        t_down = time.monotonic()
        time.sleep(args.outage)
        outage_last = machines.next
        broker.start()
        t_up = time.monotonic()
        # drain: every line written during the outage has arrived
        end = t_up + 600
        published = {n for n in range(outage_first, outage_last)
                     if _gateway_of(n, machines, args) < args.gateways}
        while time.monotonic() < end:
            with receiver.lock:
                missing = [n for n in published if n not in receiver.received]
            if not missing:
                break
            time.sleep(0.1)
        drained = time.monotonic() - t_up
        print(f"outage {t_up - t_down:.0f} s under load: {len(published):,} lines written "
              f"meanwhile on MQTT gateways; after the broker came back, "
              f"{len(published) - len(missing):,} arrived, {len(missing)} missing, "
              f"drained in {drained:.1f} s")
    machines.stop.set()
    machines.thread.join(5)
    stopped = time.monotonic()
    written = [n for n in range(1, machines.next)
               if _gateway_of(n, machines, args) < args.gateways]
    # the queues hold what came meanwhile: wait until every line has arrived (or 300 s)
    while time.monotonic() < stopped + 300:
        with receiver.lock:
            lost = [n for n in written if n not in receiver.received]
        if not lost:
            break
        time.sleep(0.2)
    print(f"after the load stopped, every line had arrived {time.monotonic() - stopped:.1f} s "
          "later" if not lost else f"{len(lost)} lines had not arrived 300 s after the load")
    with receiver.lock:
        dups = sum(len(v) - 1 for v in receiver.received.values())
        disorder = 0  # a message seen for the first time after a later one of its gateway
        for seqs in receiver.seqs.values():
            seen: set[int] = set()
            top = 0
            for seq in seqs:
                if seq not in seen and seq < top:
                    disorder += 1
                seen.add(seq)
                top = max(top, seq)
    print(f"whole run: {len(written):,} lines on MQTT gateways, {len(lost)} lost, "
          f"{dups} delivered twice (at least once: the same seq), {disorder} out of order "
          "(seq per gateway, first deliveries)")
    for _, _, p in gateways:
        p.terminate()
    for _, _, p in gateways:
        p.wait(30)
    receiver.client.loop_stop()
    broker.stop()
    shutil.rmtree(tmp, ignore_errors=True)


def _gateway_of(parts: int, machines: Machines, args: argparse.Namespace) -> int:
    """The gateway that port received line ``parts`` (the writer goes round the ports)."""
    return ((parts - 1) % len(machines.masters)) // args.ports


if __name__ == "__main__":
    main()
