"""The gateway's events on an MQTT broker (paho-mqtt): the topics are in ``docs/mqtt.md``.

Under ``tapegate/<gateway>/``:

* ``state``: retained; ``online`` while connected, ``offline`` when the gateway stops, or through
  the broker's last will when it dies or its link does;
* ``port/<port>/state``: retained; the port's entry of ``status.json``, published when it changes
  (looked at every ``interval`` seconds) and all again on every (re)connection;
* ``transfer``: every journal record, QoS 1;
* ``port/<port>/data``: every DPRNT line taken as machine data (:mod:`dnc.dataline`), QoS 1;
* ``port/<port>/command``: subscribed; "send program N" and "abort", carried out only with
  ``allow_commands = true``, through the code path of the Modbus commands (:mod:`dnc.commands`).

Transfer and data messages go through an on-disk queue (:class:`Spool`, SQLite): appended
in the journal's order as the journal is written, published in that order while the broker is
there, deleted only when the broker has acknowledged them (PUBACK). A broker away, a network
down, a gateway restarted: what was not acknowledged is published again, oldest first, when the
broker is back. The queue is bounded (``queue_limit``): when full, the oldest event is dropped
and counted (the journal keeps it; the count is in the ``state`` message and the log). Delivery
is at least once: a message whose PUBACK was lost with the connection comes again, with the
same ``seq``.
"""

from __future__ import annotations

import collections
import contextlib
import json
import logging
import sqlite3
import ssl
import threading
import time
from dataclasses import asdict
from pathlib import Path
from typing import Any

import paho.mqtt.client as paho
from paho.mqtt.enums import CallbackAPIVersion
from paho.mqtt.reasoncodes import ReasonCode

from dnc import commands
from dnc.dataline import DataEvent, DataPatterns
from dnc.gateway import Gateway
from dnc.gateway_config import MqttConfig
from dnc.journal import Transfer, now_utc
from formats.errors import TapegateError

log = logging.getLogger("tapegate.mqtt")

WINDOW = 200  # queued events handed to the client and not yet acknowledged, at most
MAX_COMMAND = 1024  # bytes: a longer command payload is malformed, never decoded
RECONNECT = (1, 5)  # seconds: paho's reconnection backoff, first and longest


def topics(gateway: str) -> dict[str, str]:
    base = f"tapegate/{gateway}"
    return {"state": f"{base}/state", "transfer": f"{base}/transfer",
            "port": f"{base}/port/{{port}}/state", "data": f"{base}/port/{{port}}/data",
            "command": f"{base}/port/+/command"}


def use_tls(client: paho.Client, ca: Path | None, cert: Path | None, key: Path | None,
            what: str = "") -> None:
    """Connect ``client`` by TLS (mqtts://), the broker's certificate verified against ``ca``
    (the system's store when None), with a client certificate where given: the gateway's
    publisher and ``tapegate fleet`` alike."""
    try:
        client.tls_set(ca_certs=str(ca) if ca else None, certfile=str(cert) if cert else None,
                       keyfile=str(key) if key else None, cert_reqs=ssl.CERT_REQUIRED)
    except (ssl.SSLError, OSError, ValueError) as exc:
        raise TapegateError(f"{what}cannot use the TLS files: {exc}",
                            code="mqtt-unavailable") from None


class Spool:
    """The bounded on-disk queue of events not yet acknowledged by the broker, oldest first.
    One SQLite file (WAL): survives the gateway's restart or SIGKILL; each row is one message
    (topic and payload), its ``seq`` the row id (increasing, never reused)."""

    def __init__(self, path: Path, limit: int):
        self.path = path
        self.limit = limit
        self.lock = threading.Lock()
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            self.db = sqlite3.connect(path, check_same_thread=False, isolation_level=None)
            self.db.execute("PRAGMA journal_mode=WAL")
            self.db.execute("PRAGMA synchronous=NORMAL")
            self.db.execute("CREATE TABLE IF NOT EXISTS events (seq INTEGER PRIMARY KEY "
                            "AUTOINCREMENT, topic TEXT NOT NULL, payload TEXT NOT NULL)")
            self.db.execute("CREATE TABLE IF NOT EXISTS counts (name TEXT PRIMARY KEY, "
                            "value INTEGER NOT NULL)")
            self.db.execute("INSERT OR IGNORE INTO counts VALUES ('dropped', 0)")
            self.size = self.db.execute("SELECT count(*) FROM events").fetchone()[0]
            self.dropped = self.db.execute(
                "SELECT value FROM counts WHERE name = 'dropped'").fetchone()[0]
        except (sqlite3.Error, OSError) as exc:
            raise TapegateError(f"mqtt: cannot open the queue {path}: {exc}",
                                code="mqtt-queue") from None

    def offset(self) -> int | None:
        """How far into the journal (bytes) the records have been queued; None: not known
        (a new queue)."""
        with self.lock:
            row = self.db.execute("SELECT value FROM counts WHERE name = 'journal'").fetchone()
            return None if row is None else int(row[0])

    def set_offset(self, offset: int) -> None:
        with self.lock:
            self._offset(offset)

    def _offset(self, offset: int) -> None:
        self.db.execute("INSERT INTO counts VALUES ('journal', ?) ON CONFLICT(name) DO UPDATE "
                        "SET value = excluded.value", (offset,))

    def put(self, messages: list[tuple[str, Any]], offset: int | None = None) -> int:
        """Append the messages of one journal record, ``(topic, make)`` pairs where
        ``make(seq)`` gives the payload (which carries its seq), and with ``offset`` the
        journal's size once the record is queued: all in one transaction, so that a gateway
        killed at any moment has queued the whole record or none of it, and the next start's
        catch-up queues it once. Returns how many old events were dropped to make room."""
        with self.lock:
            self.db.execute("BEGIN")
            try:
                dropped = sum(self._put(topic, make) for topic, make in messages)
                if offset is not None:
                    self._offset(offset)
            except BaseException:
                self.db.execute("ROLLBACK")
                raise
            self.db.execute("COMMIT")
            return dropped

    def _put(self, topic: str, make: Any) -> int:
        dropped = 0
        if self.size >= self.limit:
            self.db.execute("DELETE FROM events WHERE seq = (SELECT min(seq) FROM events)")
            self.db.execute("UPDATE counts SET value = value + 1 WHERE name = 'dropped'")
            self.size -= 1
            self.dropped += 1
            dropped = 1
        seq = (self.db.execute("SELECT seq FROM sqlite_sequence WHERE name = 'events'")
               .fetchone() or (0,))[0] + 1
        self.db.execute("INSERT INTO events (seq, topic, payload) VALUES (?, ?, ?)",
                        (seq, topic, make(seq)))
        self.size += 1
        return dropped

    def after(self, seq: int, count: int) -> list[tuple[int, str, str]]:
        with self.lock:
            return self.db.execute("SELECT seq, topic, payload FROM events WHERE seq > ? "
                                   "ORDER BY seq LIMIT ?", (seq, count)).fetchall()

    def done(self, seqs: list[int]) -> None:
        """The broker acknowledged these."""
        with self.lock:
            deleted = self.db.executemany("DELETE FROM events WHERE seq = ?",
                                          [(s,) for s in seqs]).rowcount
            self.size -= max(deleted, 0)

    def close(self) -> None:
        with self.lock:
            self.db.close()


class Publisher:
    """The MQTT side of a running :class:`dnc.gateway.Gateway`: a listener of its journal
    (:meth:`record`), a thread that publishes the queue and the ports' states,
    and paho's network thread, which also receives the commands."""

    def __init__(self, gateway: Gateway, config: MqttConfig):
        assert config.queue is not None
        self.gateway = gateway
        self.config = config
        self.name = config.gateway
        self.topics = topics(config.gateway)
        self.spool = Spool(config.queue, config.queue_limit)
        self.connected = threading.Event()
        self.listening = threading.Event()  # the broker acknowledged the command subscription
        self.stopping = threading.Event()
        self.wake = threading.Event()
        self.acked: collections.deque[int] = collections.deque()  # mids, from paho's thread
        self.inflight: dict[int, int] = {}  # mid -> seq
        self.last_sent = 0  # the newest seq handed to the client
        self.published: dict[str, str] = {}  # port -> the state payload last published
        self.since = now_utc()
        self.told = ""  # the last connection problem logged (each is logged once)
        self.thread: threading.Thread | None = None
        self.client = self._client()

    def _client(self) -> paho.Client:
        cfg = self.config
        client = paho.Client(CallbackAPIVersion.VERSION2, client_id=cfg.client_id,
                             clean_session=True, protocol=paho.MQTTv311)
        client.will_set(self.topics["state"], self._state("offline", "lost"), qos=1,
                        retain=True)
        if cfg.scheme == "mqtts":
            use_tls(client, cfg.ca, cfg.cert, cfg.key, "mqtt: ")
        if cfg.user:
            password = None
            if cfg.password_file is not None:
                try:
                    lines = cfg.password_file.read_text("utf-8").splitlines()
                except (OSError, UnicodeDecodeError) as exc:
                    raise TapegateError(f"mqtt: cannot read the password file "
                                        f"{cfg.password_file}: {exc}",
                                        code="mqtt-unavailable") from None
                password = lines[0] if lines else ""
            client.username_pw_set(cfg.user, password)
        if log.isEnabledFor(logging.DEBUG):  # paho's packets; its "errors" are noise otherwise
            client.enable_logger(logging.getLogger("tapegate.mqtt.paho"))
        client.max_inflight_messages_set(WINDOW)
        client.max_queued_messages_set(0)
        client.reconnect_delay_set(*RECONNECT)
        client.on_connect = self._on_connect
        client.on_disconnect = self._on_disconnect
        client.on_publish = self._on_publish
        client.on_message = self._on_message
        client.on_connect_fail = self._on_connect_fail
        client.on_subscribe = self._on_subscribe
        return client

    # -- the gateway's listener ----------------------------------------------------------------

    def record(self, transfer: Transfer, data: DataEvent | None) -> None:
        """A journal record, just appended (the gateway holds the journal's lock): queued with
        the journal's size, so that a restart knows what was journalled and not queued."""
        self._queue(transfer, data, self._journal_size())

    def _queue(self, transfer: Transfer, data: DataEvent | None, offset: int | None) -> None:
        """A record's transfer message and, for a DPRNT line, its data message (timed at the
        record's end), queued in one write."""
        record = asdict(transfer)
        messages = [(self.topics["transfer"], lambda seq: _json(
            {"seq": seq, "gateway": self.name, **record}))]
        if data is not None:
            port = transfer.port
            messages.append((self.topics["data"].format(port=port), lambda seq: _json(
                {"seq": seq, "gateway": self.name, "port": port, "time": transfer.end,
                 "line": data.line, "pattern": data.pattern, "fields": data.fields})))
        self._put(messages, offset)

    def _journal_size(self) -> int | None:
        path = self.gateway.config.journal
        try:
            return path.stat().st_size if path is not None else None
        except OSError:
            return None

    def catch_up(self) -> int:
        """Queue the journal's records the gateway journalled but never queued: it stopped (a
        crash, SIGKILL, a power cut) between the journal's append and the queue's. Called at
        start, before the ports run; returns how many records were queued. A new queue starts
        from the journal's end (what is journalled before MQTT was enabled is not published)."""
        path = self.gateway.config.journal
        size = self._journal_size()
        if path is None or size is None:
            return 0
        stored = self.spool.offset()
        if stored is None or stored == size:
            self.spool.set_offset(size)
            return 0
        if stored > size:
            log.warning("mqtt: the journal %s is shorter than when its last record was queued "
                        "(rotated?); publishing from its end", path)
            self.spool.set_offset(size)
            return 0
        with open(path, "rb") as f:
            f.seek(stored)
            data = f.read(size - stored)
        patterns = {w.config.name: w.patterns for w in self.gateway.ports}
        count, at = 0, stored
        for raw in data.splitlines(keepends=True):
            at += len(raw)
            if not raw.endswith(b"\n"):
                break  # torn: the gateway died while writing it
            try:
                record = Transfer(**json.loads(raw))
            except (ValueError, TypeError):
                continue  # a torn line, as tapegate journal skips it
            event = (patterns.get(record.port, DataPatterns(())).match(record.program)
                     if record.direction == "data" else None)
            self._queue(record, event, at)
            count += 1
        if count:
            log.warning("mqtt: %d journal record(s) queued that the gateway had journalled but "
                        "not queued (it stopped in between)", count)
        return count

    def _put(self, messages: list[tuple[str, Any]], offset: int | None) -> None:
        try:
            dropped = self.spool.put(messages, offset)
            total = self.spool.dropped  # a record of two messages may drop two: 9 -> 11
            if any(n in (1, 10, 100) or n % 1000 == 0 for n in range(total - dropped + 1,
                                                                     total + 1)):
                log.warning("mqtt queue full (%d events): the oldest dropped, %d so far (the "
                            "journal keeps them)", self.config.queue_limit, self.spool.dropped)
        except sqlite3.Error as exc:  # a full disk must not stop the port
            log.error("mqtt: cannot queue an event in %s: %s", self.spool.path, exc)
        self.wake.set()

    # -- running -------------------------------------------------------------------------------

    def start(self) -> None:
        """Queue what the journal has and the queue has not, then connect in the background
        (the broker may come later: retried every few seconds)."""
        self.catch_up()
        self.gateway.listeners.append(self)
        try:
            self.client.connect_async(self.config.host, self.config.port, self.config.keepalive)
        except (OSError, ValueError) as exc:
            raise TapegateError(f"mqtt: cannot connect to {self.config.broker}: {exc}",
                                code="mqtt-unavailable") from None
        self.client.loop_start()
        self.thread = threading.Thread(target=self._run, name="mqtt", daemon=True)
        self.thread.start()
        log.info("MQTT to %s as %s (topics tapegate/%s/...; commands %s); queue %s",
                 self.config.broker, self.config.client_id, self.name,
                 "allowed" if self.config.allow_commands else "refused", self.spool.path)

    def stop(self, drain: float = 2.0) -> None:
        """Publish the ports' last states and ``offline``, give the queue ``drain`` seconds to
        be acknowledged, and disconnect. What is left stays queued for the next start."""
        if self.stopping.is_set():
            return  # stopped already
        end = time.monotonic() + drain
        while (self.connected.is_set() and (self.spool.size or self.inflight)
               and time.monotonic() < end):
            self.wake.set()
            time.sleep(0.02)
        self.stopping.set()
        self.wake.set()
        if self.thread is not None:
            self.thread.join(5)
        if self.connected.is_set():
            self._ports(force=False)
            info = self.client.publish(self.topics["state"], self._state("offline", "stopped"),
                                       qos=1, retain=True)
            with contextlib.suppress(RuntimeError, ValueError):
                info.wait_for_publish(2)
        self.client.disconnect()
        self.client.loop_stop()
        self._acks()
        if self in self.gateway.listeners:
            self.gateway.listeners.remove(self)
        self.spool.close()

    def _run(self) -> None:
        while not self.stopping.is_set():
            self.wake.wait(self.config.interval)
            self.wake.clear()
            if self.stopping.is_set():
                break
            try:
                self._acks()
                if self.connected.is_set():
                    self._ports(force=False)
                    self._drain()
            except Exception:  # noqa: BLE001 - the publisher's thread must not die
                log.exception("mqtt: publishing failed; going on")
                self.stopping.wait(1.0)

    def _drain(self) -> None:
        room = WINDOW - len(self.inflight)
        if room <= 0:
            return
        for seq, topic, payload in self.spool.after(self.last_sent, room):
            if not self.connected.is_set():
                return
            info = self.client.publish(topic, payload, qos=1)
            if info.rc not in (paho.MQTT_ERR_SUCCESS, paho.MQTT_ERR_NO_CONN):
                return  # the client's queue is full: again on the next round
            # NO_CONN: the client keeps it and sends it when connected again, in order
            self.inflight[info.mid] = seq
            self.last_sent = seq

    def _acks(self) -> None:
        done = []
        while self.acked:
            seq = self.inflight.pop(self.acked.popleft(), None)
            if seq is not None:
                done.append(seq)
        if done:
            self.spool.done(done)
            if not self.spool.size:
                log.debug("mqtt queue empty")

    def _ports(self, force: bool) -> None:
        from dnc.web import port_status  # aiohttp is loaded with it; the status page's entry

        for i, worker in enumerate(self.gateway.ports):
            entry = port_status(i, worker)
            key = _json(entry)
            if not force and self.published.get(worker.config.name) == key:
                continue
            self.published[worker.config.name] = key
            self.client.publish(self.topics["port"].format(port=worker.config.name),
                                _json({"gateway": self.name, "time": now_utc(), **entry}),
                                qos=1, retain=True)

    def _state(self, state: str, reason: str) -> str:
        return _json({"gateway": self.name, "state": state, "reason": reason,
                      "since": self.since if state == "online" else now_utc(),
                      "ports": [p.name for p in self.gateway.config.ports],
                      "queued": self.spool.size, "dropped": self.spool.dropped})

    # -- paho's callbacks (its network thread) -------------------------------------------------

    def _on_connect(self, client: paho.Client, userdata: Any, flags: Any, reason: ReasonCode,
                    properties: Any) -> None:
        if reason.is_failure:
            self._tell(f"the broker {self.config.broker} refused the connection: {reason}")
            return
        self.told = ""
        self.since = now_utc()
        log.info("MQTT connected to %s; %d event(s) queued", self.config.broker,
                 self.spool.size)
        client.publish(self.topics["state"], self._state("online", "connected"), qos=1,
                       retain=True)
        client.subscribe(self.topics["command"], qos=1)
        self.published.clear()  # every port's state again: the broker may have lost them
        self.connected.set()
        self.wake.set()

    def _on_subscribe(self, client: paho.Client, userdata: Any, mid: int,
                      reasons: list[ReasonCode], properties: Any) -> None:
        if any(r.is_failure for r in reasons):
            self._tell(f"the broker refused the subscription to {self.topics['command']} "
                       "(its ACL?): no commands reach this gateway")
        else:
            self.listening.set()

    def _on_disconnect(self, client: paho.Client, userdata: Any, flags: Any,
                       reason: ReasonCode, properties: Any) -> None:
        self.connected.clear()
        self.listening.clear()
        if not self.stopping.is_set():
            self._tell(f"lost the broker {self.config.broker} ({reason}); events are queued "
                       "and published when it is back")

    def _on_connect_fail(self, client: paho.Client, userdata: Any) -> None:
        self._tell(f"cannot reach the broker {self.config.broker}; retrying every "
                   f"{RECONNECT[1]} s, events are queued")

    def _tell(self, why: str) -> None:
        if why != self.told:
            log.warning("MQTT: %s", why)
            self.told = why

    def _on_publish(self, client: paho.Client, userdata: Any, mid: int, reason: ReasonCode,
                    properties: Any) -> None:
        # paho holds its own lock here: only note the mid, the publisher's thread does the rest
        self.acked.append(mid)
        self.wake.set()

    def _on_message(self, client: paho.Client, userdata: Any, message: paho.MQTTMessage
                    ) -> None:
        try:
            self.command(message.topic, bytes(message.payload))
        except Exception:  # noqa: BLE001 - paho's thread must not die on one message
            log.exception("mqtt: a command on %s failed", message.topic[:120])

    # -- commands ------------------------------------------------------------------------------

    def command(self, topic: str, payload: bytes) -> None:
        """One message on ``tapegate/<gateway>/port/<port>/command``: carried out as the
        Modbus command is, or refused, or (malformed) journalled and ignored."""
        name = topic.split("/")[3] if topic.count("/") == 4 else ""
        ports = {w.config.name: i for i, w in enumerate(self.gateway.ports)}
        where = name if name in ports else "mqtt"
        if not self.config.allow_commands:
            commands.refuse(self.gateway, where, "mqtt command",
                            "commands are disabled (mqtt.allow_commands = false)")
            return
        try:
            index, command, number = self._parse(name, ports, payload)
        except ValueError as exc:
            commands.refuse(self.gateway, where, "mqtt command", str(exc), "bad command")
            return
        if command == "abort":
            commands.abort(self.gateway, index, "mqtt")
        else:
            commands.send_program(self.gateway, index, number, "mqtt")

    @staticmethod
    def _parse(name: str, ports: dict[str, int], payload: bytes) -> tuple[int, str, int]:
        if len(payload) > MAX_COMMAND:
            raise ValueError(f"a payload of {len(payload)} bytes; a command is at most "
                             f"{MAX_COMMAND}")
        try:
            data = json.loads(payload.decode("utf-8"))
        except (UnicodeDecodeError, ValueError) as exc:
            raise ValueError(f"not JSON: {exc}") from None
        if not isinstance(data, dict):
            raise ValueError(f"a command is a JSON object, not {type(data).__name__}")
        unknown = sorted(set(data) - {"command", "program"})
        if unknown:
            raise ValueError(f"unknown key {unknown[0][:40]!r}; the keys are command and program")
        command = data.get("command")
        if command not in ("send", "abort"):
            raise ValueError(f"command must be \"send\" or \"abort\", not {_short(command)}")
        number = 0
        if command == "send":
            given = data.get("program")
            if isinstance(given, bool) or not isinstance(given, int) or not (
                    1 <= given <= 99_999_999):
                raise ValueError(f"program must be a program number 1-99999999, not "
                                 f"{_short(given)}")
            number = given
        elif "program" in data:
            raise ValueError("abort takes no program")
        if name not in ports:
            raise ValueError(f"no port named {name[:40]!r} on this gateway")
        return ports[name], command, number


def _short(value: Any) -> str:
    text = json.dumps(value, ensure_ascii=True)
    return text if len(text) <= 40 else text[:37] + "..."


def _json(value: Any) -> str:
    return json.dumps(value, ensure_ascii=False, separators=(",", ":"))
