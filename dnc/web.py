"""The gateway's status page for people (``[web]`` in the configuration; an aiohttp server).

Modbus serves the PLC; this serves a foreman's screen. Read-only, and on 127.0.0.1 unless
configured otherwise:

* ``/`` -- one page (static HTML, script and style sheet in ``dnc/static``): every port's state,
  program, block, bytes and progress, the errors, and the journal's last transfers;
* ``/events`` -- server-sent events: the snapshot below, sent each time it changes (looked at
  twice a second, and sent at least every :data:`HEARTBEAT` seconds); the page listens to it;
* ``/status.json`` -- the same snapshot, for a script or a wall display of one's own.

The snapshot is read, never kept: the ports' live :class:`dnc.gateway.PortStatus` (what the
Modbus interface reads) and the tail of the transfer journal. The server runs its own asyncio
loop in a thread, as the Modbus server does; the port threads never wait for it.

This module is imported only when ``[web] enabled = true``, so that aiohttp is not loaded by
``tapegate --help`` or by a gateway without the page.
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import logging
import os
import threading
from collections.abc import Awaitable, Callable
from dataclasses import asdict
from pathlib import Path
from typing import Any

from aiohttp import web

from dnc.gateway import Gateway, PortWorker, State
from dnc.gateway_config import WebConfig
from dnc.journal import Transfer, now_utc
from formats.errors import TapegateError

log = logging.getLogger("tapegate.web")

STATIC = Path(__file__).with_name("static")
INTERVAL = 0.5  # seconds between two looks at the state, for /events
HEARTBEAT = 10.0  # an event at least this often, so the page can tell the link is alive
TAIL = 256 * 1024  # bytes read from the end of the journal: the last transfers are in them

STATE_WORDS = {
    State.OFFLINE: "offline",
    State.IDLE: "listening",
    State.RECEIVING: "receiving",
    State.WAITING: "waiting for DC1",
    State.SENDING: "sending",
    State.PAUSED: "paused (DC3)",
    State.STOPPED: "stopped",
}
_SENDING = (State.WAITING, State.SENDING, State.PAUSED)
# journal results that are no fault: PortWorker._finish counts every other one in the errors
GOOD = frozenset(("ok", "request", "rewound"))
_HEADERS = {
    "X-Content-Type-Options": "nosniff",
    "Content-Security-Policy": "default-src 'self'; frame-ancestors 'none'",
    "Referrer-Policy": "no-referrer",
    "Cache-Control": "no-store",
}


class JournalTail:
    """The last transfers of the journal file, read again only when the file has changed."""

    def __init__(self, path: Path | None, window: int = TAIL):
        self.path = path
        self.window = window
        self._seen: tuple[int, int] | None = None
        self._transfers: list[Transfer] = []
        self.error = ""  # why the journal cannot be read, if it cannot

    def read(self) -> list[Transfer]:
        """Oldest first."""
        if self.path is None:
            return []
        try:
            with open(self.path, "rb") as f:
                st = os.fstat(f.fileno())
                if (st.st_size, st.st_mtime_ns) == self._seen:
                    return self._transfers
                start = max(0, st.st_size - self.window)
                f.seek(start)
                data = f.read(st.st_size - start)
        except FileNotFoundError:
            self.error = ""
            return []  # nothing journalled yet
        except OSError as exc:
            self.error = f"cannot read the journal {self.path.name}: {exc.strerror}"
            return self._transfers
        lines = data.split(b"\n")
        if start > 0:
            lines = lines[1:]  # the window began inside a line
        transfers = []
        for line in lines:
            if not line.strip():
                continue
            try:
                transfers.append(Transfer(**json.loads(line)))
            except (ValueError, TypeError):
                continue  # a torn line (``tapegate journal`` says so)
        self._seen, self._transfers, self.error = (st.st_size, st.st_mtime_ns), transfers, ""
        return transfers


def port_status(index: int, worker: PortWorker) -> dict[str, Any]:
    """One port, as the page shows it."""
    s, cfg = worker.status, worker.config
    state = State(s.state)
    sending = state in _SENDING
    letter = cfg.profile.program_number or "O"
    number = f"{letter}{s.program}" if s.program else ""
    return {
        "index": index,
        "name": cfg.name,
        "url": cfg.url,
        "profile": cfg.profile.name,
        "state": state.name.lower(),
        "state_code": int(state),
        "state_words": STATE_WORDS[state],
        "busy": sending or state == State.RECEIVING,
        "program": (s.file or number) if sending else number,
        "program_number": s.program,
        "file": s.file,
        "line": s.line,
        "bytes_sent": s.bytes_sent,
        "bytes_total": s.bytes_total,
        "progress": min(s.bytes_sent / s.bytes_total, 1.0) if s.bytes_total else None,
        "bytes_received": s.bytes_received,
        "errors": s.errors,
        "transfers": s.transfers,
        "result": s.result.name.lower().replace("_", " "),
        "result_code": int(s.result),
        "message": s.message,
        "data_lines": s.data_lines,  # DPRNT lines taken as machine data (dnc.dataline)
        "data_last": s.data_last,
        "parts": s.parts,
    }


def snapshot(gateway: Gateway, tail: JournalTail, count: int) -> dict[str, Any]:
    """Everything the page shows: the ports, the errors (ports that are offline now, then the
    journal's transfers that did not end well, newest first) and the last transfers."""
    ports = [port_status(i, w) for i, w in enumerate(gateway.ports)]
    transfers = tail.read()
    errors: list[dict[str, Any]] = [
        {"port": p["name"], "time": None, "result": "offline", "program": "",
         "errors": [p["message"]] if p["message"] else []}
        for p in ports if p["state_code"] == State.OFFLINE]
    if tail.error:
        errors.append({"port": "", "time": None, "result": "journal", "program": "",
                       "errors": [tail.error]})
    faults = [t for t in transfers if t.result not in GOOD][-count:]
    errors += [{"port": t.port, "time": t.end, "result": t.result, "program": t.program,
                "errors": t.errors[:5], "more": max(0, len(t.errors) - 5)}
               for t in reversed(faults)]
    return {
        "time": now_utc(),
        "journal": tail.path.name if tail.path else None,
        "ports": ports,
        "errors": errors,
        "transfers": [asdict(t) for t in reversed(transfers[-count:])],
    }


@web.middleware
async def _headers(request: web.Request,
                   handler: Callable[[web.Request], Awaitable[web.StreamResponse]]
                   ) -> web.StreamResponse:
    try:
        response = await handler(request)
    except web.HTTPException as exc:
        exc.headers.update(_HEADERS)
        raise
    if not response.prepared:  # /events sets its own before it starts streaming
        for key, value in _HEADERS.items():
            response.headers.setdefault(key, value)
    return response


class StatusPage:
    """The web server of a running :class:`dnc.gateway.Gateway`."""

    def __init__(self, gateway: Gateway, config: WebConfig):
        self.gateway = gateway
        self.config = config
        self.tail = JournalTail(gateway.config.journal)
        self.loop: asyncio.AbstractEventLoop | None = None
        self.runner: web.AppRunner | None = None
        self.thread: threading.Thread | None = None
        self.closing: asyncio.Event | None = None

    def snapshot(self) -> dict[str, Any]:
        return snapshot(self.gateway, self.tail, self.config.transfers)

    def app(self) -> web.Application:
        app = web.Application(middlewares=[_headers])
        app.router.add_get("/", self._index)
        app.router.add_get("/status.json", self._status)
        app.router.add_get("/events", self._events, allow_head=False)  # a stream: GET only
        app.router.add_static("/static/", STATIC)
        return app

    async def _index(self, request: web.Request) -> web.StreamResponse:
        return web.FileResponse(STATIC / "index.html")

    async def _status(self, request: web.Request) -> web.StreamResponse:
        return web.json_response(self.snapshot())

    async def _events(self, request: web.Request) -> web.StreamResponse:
        response = web.StreamResponse(headers={**_HEADERS, "Content-Type": "text/event-stream"})
        await response.prepare(request)
        assert self.closing is not None
        last, sent_at = "", 0.0
        loop = asyncio.get_running_loop()
        try:
            await response.write(b"retry: 2000\n\n")
            while not self.closing.is_set():
                if request.transport is None or request.transport.is_closing():
                    break  # the page was closed
                data = self.snapshot()
                moment = data.pop("time")
                key = json.dumps(data, separators=(",", ":"))
                if key != last or loop.time() - sent_at >= HEARTBEAT:
                    data["time"] = moment
                    text = json.dumps(data, separators=(",", ":"))
                    await response.write(f"data: {text}\n\n".encode())
                    last, sent_at = key, loop.time()
                with contextlib.suppress(TimeoutError):
                    await asyncio.wait_for(self.closing.wait(), INTERVAL)
        except ConnectionResetError:  # the page was closed
            pass
        return response

    # -- running -------------------------------------------------------------------------------

    def start(self) -> None:
        """Listen; raises :class:`TapegateError` when the address cannot be bound."""
        ready = threading.Event()
        failure: list[OSError] = []

        async def listen() -> None:
            self.closing = asyncio.Event()
            self.runner = web.AppRunner(self.app(), access_log=None, shutdown_timeout=1.0)
            await self.runner.setup()
            site = web.TCPSite(self.runner, self.config.host, self.config.port)
            await site.start()

        def run() -> None:
            loop = asyncio.new_event_loop()
            self.loop = loop
            asyncio.set_event_loop(loop)
            try:
                loop.run_until_complete(listen())
            except OSError as exc:
                failure.append(exc)
                if self.runner is not None:
                    loop.run_until_complete(self.runner.cleanup())
                loop.close()
                ready.set()
                return
            ready.set()
            loop.run_forever()
            loop.close()

        self.thread = threading.Thread(target=run, name="web", daemon=True)
        self.thread.start()
        ready.wait(10)
        if failure or not ready.is_set():
            why = (failure[0].strerror or str(failure[0])) if failure else "no answer"
            raise TapegateError(f"web: cannot listen on {self.config.host}:{self.config.port}: "
                                f"{why}", code="listen-failed")
        log.info("status page on %s (read-only)", self.config.url)

    def stop(self) -> None:
        loop = self.loop
        if loop is None or loop.is_closed() or self.runner is None:
            return

        async def close() -> None:
            assert self.closing is not None and self.runner is not None
            self.closing.set()
            await self.runner.cleanup()

        try:
            asyncio.run_coroutine_threadsafe(close(), loop).result(5)
        except Exception as exc:  # the loop already ended
            log.debug("web shutdown: %s", exc)
        loop.call_soon_threadsafe(loop.stop)
        if self.thread is not None:
            self.thread.join(5)
