"""``tapegate fleet``: every gateway on an MQTT broker as one shop.

A :class:`Fleet` subscribes to the retained states the gateways publish (``tapegate/+/state``
and ``tapegate/+/port/+/state``, :mod:`dnc.mqtt`) and keeps the newest of each; the command
prints them as one table or one JSON document, keeps the table live (``--watch``), or serves
them read-only in the status page's design (:class:`FleetPage`, ``--web``).

MQTT has no "end of the retained messages": after the subscription is acknowledged the broker
sends them at once, so a snapshot is taken when no message has come for ``quiet`` seconds (or
``timeout`` has passed).
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import logging
import ssl
import threading
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import paho.mqtt.client as paho
from aiohttp import web
from paho.mqtt.enums import CallbackAPIVersion
from paho.mqtt.reasoncodes import ReasonCode

from dnc.journal import now_utc
from dnc.mqtt import use_tls
from dnc.web import _HEADERS, _headers  # the status page's headers, the same here
from formats.errors import TapegateError

log = logging.getLogger("tapegate.fleet")

STATIC = Path(__file__).with_name("static")
MAX_PAYLOAD = 64 * 1024  # a retained state larger than this is no gateway's: ignored


@dataclass(frozen=True)
class BrokerAccess:
    """Where the broker is and how to log in (the same keys as the gateway's [mqtt] table)."""
    scheme: str
    host: str
    port: int
    ca: Path | None = None
    cert: Path | None = None
    key: Path | None = None
    user: str = ""
    password: str | None = None

    @property
    def url(self) -> str:
        host = f"[{self.host}]" if ":" in self.host else self.host
        return f"{self.scheme}://{host}:{self.port}"


class Fleet:
    """The retained states of every gateway on one broker, kept up to date."""

    def __init__(self, access: BrokerAccess):
        self.access = access
        self.lock = threading.Lock()
        self.gateways: dict[str, dict[str, Any]] = {}
        self.ports: dict[str, dict[str, dict[str, Any]]] = {}
        self.ignored = 0  # messages on the topics that are no state (not JSON, wrong shape)
        self.last_message = time.monotonic()
        self.version = 0  # counts the changes
        self.subscribed = threading.Event()
        self.connected = threading.Event()
        self.refused = ""
        client = paho.Client(CallbackAPIVersion.VERSION2, protocol=paho.MQTTv311)
        if access.scheme == "mqtts":
            use_tls(client, access.ca, access.cert, access.key)
        if access.user:
            client.username_pw_set(access.user, access.password)
        client.on_connect = self._on_connect
        client.on_subscribe = self._on_subscribe
        client.on_message = self._on_message
        client.on_disconnect = self._on_disconnect
        client.reconnect_delay_set(1, 5)
        self.client = client

    # -- connecting ----------------------------------------------------------------------------

    def connect(self, timeout: float = 10.0) -> None:
        """Connect and subscribe; :class:`TapegateError` when the broker cannot be reached or
        refuses within ``timeout`` seconds."""
        try:
            self.client.connect(self.access.host, self.access.port, keepalive=30)
        except (OSError, ssl.SSLError) as exc:
            why = getattr(exc, "strerror", None) or str(exc) or type(exc).__name__
            raise TapegateError(f"cannot reach the broker {self.access.url}: {why}",
                                code="mqtt-unavailable") from None
        self.client.loop_start()
        end = time.monotonic() + timeout
        while not self.subscribed.is_set() and not self.refused and time.monotonic() < end:
            self.subscribed.wait(0.05)
        if self.refused or not self.subscribed.is_set():
            self.close()
            raise TapegateError(f"the broker {self.access.url} "
                                + (f"refused: {self.refused}" if self.refused
                                   else f"did not answer within {timeout:g} s"),
                                code="mqtt-unavailable")

    def settle(self, quiet: float = 0.3, timeout: float = 5.0) -> None:
        """Wait until the retained states have come: no message for ``quiet`` seconds."""
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            if time.monotonic() - self.last_message >= quiet:
                return
            time.sleep(0.02)

    def close(self) -> None:
        with contextlib.suppress(Exception):
            self.client.disconnect()
        self.client.loop_stop()

    def _on_connect(self, client: paho.Client, userdata: Any, flags: Any, reason: ReasonCode,
                    properties: Any) -> None:
        if reason.is_failure:
            self.refused = str(reason)
            return
        self.connected.set()
        client.subscribe([("tapegate/+/state", 1), ("tapegate/+/port/+/state", 1)])

    def _on_subscribe(self, client: paho.Client, userdata: Any, mid: int,
                      reasons: list[ReasonCode], properties: Any) -> None:
        if any(r.is_failure for r in reasons):
            self.refused = "the subscription to tapegate/+/state was refused (the ACL?)"
            return
        self.last_message = time.monotonic()
        self.subscribed.set()

    def _on_disconnect(self, client: paho.Client, userdata: Any, flags: Any,
                       reason: ReasonCode, properties: Any) -> None:
        self.connected.clear()

    def _on_message(self, client: paho.Client, userdata: Any, message: paho.MQTTMessage
                    ) -> None:
        self.last_message = time.monotonic()
        parts = message.topic.split("/")
        with self.lock:
            if not message.payload:  # a retained state cleared
                if len(parts) == 3:
                    self.gateways.pop(parts[1], None)
                elif len(parts) == 5:
                    self.ports.get(parts[1], {}).pop(parts[3], None)
                self.version += 1
                return
            try:
                if len(message.payload) > MAX_PAYLOAD:
                    raise ValueError("too large")
                data = json.loads(message.payload.decode("utf-8"))
                if not isinstance(data, dict) or not isinstance(data.get("state"), str):
                    raise ValueError("no state")
            except (UnicodeDecodeError, ValueError):
                self.ignored += 1
                return
            if len(parts) == 3:
                self.gateways[parts[1]] = data
            elif len(parts) == 5:
                self.ports.setdefault(parts[1], {})[parts[3]] = data
            self.version += 1

    # -- what is known -------------------------------------------------------------------------

    def snapshot(self) -> dict[str, Any]:
        """Every gateway (by name) with its ports (in their configured order)."""
        with self.lock:
            names = sorted(set(self.gateways) | set(self.ports))
            gateways = []
            for name in names:
                state = self.gateways.get(name, {})
                ports = sorted(self.ports.get(name, {}).values(),
                               key=lambda p: (p.get("index", 0), str(p.get("name", ""))))
                gateways.append({
                    "name": name,
                    "state": state.get("state", "unknown"),
                    "reason": state.get("reason", ""),
                    "since": state.get("since"),
                    "queued": state.get("queued", 0),
                    "dropped": state.get("dropped", 0),
                    "ports": ports,
                })
            return {"broker": self.access.url, "time": now_utc(), "gateways": gateways}


def table(snapshot: dict[str, Any]) -> str:
    """The snapshot as one table: a row per port (a gateway with no port state, one row)."""
    rows = [("gateway", "state", "#", "port", "port state", "program", "last result",
             "errors", "data", "last event")]
    for g in snapshot["gateways"]:
        state = g["state"] + (f" ({g['reason']})" if g["state"] != "online" and g["reason"]
                              else "")
        if not g["ports"]:
            rows.append((g["name"], state, "", "", "", "", "", "", "", ""))
        for p in g["ports"]:
            # a gateway that is offline cannot say what its ports do now: its last word shows
            port_state = str(p.get("state_words", p.get("state", "")))
            if g["state"] != "online":
                port_state = f"({port_state})"
            rows.append((g["name"], state, str(p.get("index", "")), str(p.get("name", "")),
                         port_state, str(p.get("program") or "-"),
                         str(p.get("result", "")), str(p.get("errors", 0)),
                         str(p.get("data_lines", 0)), str(p.get("message", ""))[:60]))
    widths = [max(len(r[i]) for r in rows) for i in range(len(rows[0]))]
    return "\n".join("  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip()
                     for r in rows)


# -- the read-only fleet page ------------------------------------------------------------------

class FleetPage:
    """``/`` (the page), ``/fleet.json`` (the snapshot) and ``/events`` (the snapshot again at
    each change, server-sent events); GET only, nothing writes."""

    def __init__(self, fleet: Fleet, host: str, port: int):
        self.fleet = fleet
        self.host = host
        self.port = port

    def app(self) -> web.Application:
        app = web.Application(middlewares=[_headers])
        app.router.add_get("/", self._index)
        app.router.add_get("/fleet.json", self._json)
        app.router.add_get("/events", self._events, allow_head=False)
        app.router.add_static("/static/", STATIC)
        return app

    async def _index(self, request: web.Request) -> web.StreamResponse:
        return web.FileResponse(STATIC / "fleet.html")

    async def _json(self, request: web.Request) -> web.StreamResponse:
        return web.json_response(self.fleet.snapshot())

    async def _events(self, request: web.Request) -> web.StreamResponse:
        response = web.StreamResponse(headers={**_HEADERS, "Content-Type": "text/event-stream"})
        await response.prepare(request)
        seen, sent_at = -1, 0.0
        loop = asyncio.get_running_loop()
        try:
            await response.write(b"retry: 2000\n\n")
            while request.transport is not None and not request.transport.is_closing():
                if self.fleet.version != seen or loop.time() - sent_at >= 10.0:
                    seen = self.fleet.version
                    text = json.dumps(self.fleet.snapshot(), separators=(",", ":"))
                    await response.write(f"data: {text}\n\n".encode())
                    sent_at = loop.time()
                await asyncio.sleep(0.5)
        except ConnectionResetError:
            pass
        return response

    def run(self, stop: threading.Event) -> None:
        """Serve until ``stop`` is set; :class:`TapegateError` when the address cannot be
        bound."""

        async def serve() -> None:
            runner = web.AppRunner(self.app(), access_log=None, shutdown_timeout=1.0)
            await runner.setup()
            try:
                await web.TCPSite(runner, self.host, self.port).start()
            except OSError as exc:
                await runner.cleanup()
                raise TapegateError(f"--web: cannot listen on {self.host}:{self.port}: "
                                    f"{exc.strerror or exc}", code="listen-failed") from None
            log.info("fleet page on http://%s:%d/ (read-only)", self.host, self.port)
            while not stop.is_set():
                await asyncio.sleep(0.2)
            await runner.cleanup()

        asyncio.run(serve())
