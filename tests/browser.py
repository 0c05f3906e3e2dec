"""Headless Chromium (Debian's ``chromium`` package) driven over the DevTools protocol.

The status page's tests and ``docs/screenshot.py`` load the page in a real browser and read it
as a person sees it: its text, after its script has run. The protocol is JSON over a websocket
(aiohttp's client, a dependency already); every wait is for a condition, with a timeout.
"""

from __future__ import annotations

import asyncio
import base64
import contextlib
import json
import os
import shutil
import subprocess
import tempfile
import time
from pathlib import Path
from typing import Any

import aiohttp

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")


class BrowserError(RuntimeError):
    pass


class Browser:
    """One headless Chromium with one page; :meth:`close` ends it."""

    def __init__(self, width: int = 1280, height: int = 720, timeout: float = 30.0):
        if CHROMIUM is None:
            raise BrowserError("no chromium: apt-get install chromium")
        self.width, self.height = width, height
        self.profile = Path(tempfile.mkdtemp(prefix="tapegate-chromium-"))
        self.log = open(self.profile / "chromium.log", "wb")  # noqa: SIM115 (closed in close)
        args = [CHROMIUM, "--headless", "--disable-gpu", "--no-first-run",
                "--no-default-browser-check", "--disable-extensions", "--hide-scrollbars",
                "--remote-debugging-address=127.0.0.1", "--remote-debugging-port=0",
                f"--user-data-dir={self.profile}", f"--window-size={width},{height}",
                "about:blank"]
        if os.geteuid() == 0:
            args.insert(1, "--no-sandbox")  # Chromium refuses to run as root with it
        self.process = subprocess.Popen(args, stdout=self.log, stderr=subprocess.STDOUT,
                                        stdin=subprocess.DEVNULL)
        self.exceptions: list[str] = []  # uncaught script errors on the page
        self._id = 0
        self.loop = asyncio.new_event_loop()
        try:
            self.loop.run_until_complete(self._connect(timeout))
        except BaseException:
            self.close()
            raise

    async def _connect(self, timeout: float) -> None:
        active = self.profile / "DevToolsActivePort"
        end = time.monotonic() + timeout
        while not active.exists() or len(active.read_text().split()) < 2:
            if self.process.poll() is not None or time.monotonic() > end:
                raise BrowserError(f"chromium did not start: {self.output()[-2000:]}")
            await asyncio.sleep(0.05)
        port = int(active.read_text().split()[0])
        self.session = aiohttp.ClientSession()
        async with self.session.get(f"http://127.0.0.1:{port}/json/list") as r:
            targets = await r.json()
        page = next(t for t in targets if t["type"] == "page")
        self.ws = await self.session.ws_connect(page["webSocketDebuggerUrl"], max_msg_size=0)
        await self._call("Page.enable", {})
        await self._call("Runtime.enable", {})

    def output(self) -> str:
        self.log.flush()
        return (self.profile / "chromium.log").read_text(errors="replace")

    async def _call(self, method: str, params: dict[str, Any], timeout: float = 30.0) -> Any:
        self._id += 1
        ident = self._id
        await self.ws.send_json({"id": ident, "method": method, "params": params})
        end = time.monotonic() + timeout
        while True:
            left = end - time.monotonic()
            if left <= 0:
                raise BrowserError(f"{method}: no answer within {timeout} s")
            msg = await self.ws.receive(timeout=left)
            if msg.type != aiohttp.WSMsgType.TEXT:
                raise BrowserError(f"{method}: the browser closed the connection")
            data = json.loads(msg.data)
            if data.get("method") == "Runtime.exceptionThrown":
                details = data["params"]["exceptionDetails"]
                self.exceptions.append(details.get("exception", {}).get("description")
                                       or details.get("text", "?"))
            if data.get("id") == ident:
                if "error" in data:
                    raise BrowserError(f"{method}: {data['error']}")
                return data.get("result", {})

    def call(self, method: str, **params: Any) -> Any:
        return self.loop.run_until_complete(self._call(method, params))

    def evaluate(self, expression: str) -> Any:
        """The value of a JavaScript expression on the page (JSON-able)."""
        result = self.call("Runtime.evaluate", expression=expression, returnByValue=True,
                           awaitPromise=True)
        if "exceptionDetails" in result:
            raise BrowserError(f"{expression}: {result['exceptionDetails']}")
        return result["result"].get("value")

    def wait_for(self, expression: str, timeout: float = 20.0) -> Any:
        """The expression's value once it is truthy; :class:`BrowserError` after ``timeout``."""
        end = time.monotonic() + timeout
        while True:
            value = self.evaluate(expression)
            if value:
                return value
            if time.monotonic() > end:
                raise BrowserError(f"still false after {timeout} s: {expression}")
            self.loop.run_until_complete(asyncio.sleep(0.1))

    def open(self, url: str, timeout: float = 20.0) -> None:
        self.call("Page.navigate", url=url)
        self.wait_for(f"document.readyState === 'complete' && location.href === {url!r}",
                      timeout)

    def screenshot(self, path: Path) -> None:
        """A PNG of the whole page (as tall as its content), ``width`` pixels wide."""
        metrics = self.call("Page.getLayoutMetrics")
        height = max(self.height, int(metrics["cssContentSize"]["height"]) + 1)
        self.call("Emulation.setDeviceMetricsOverride", width=self.width, height=height,
                  deviceScaleFactor=1, mobile=False)
        shot = self.call("Page.captureScreenshot", format="png")
        path.write_bytes(base64.b64decode(shot["data"]))

    def close(self) -> None:
        if hasattr(self, "ws"):
            with contextlib.suppress(Exception):
                self.loop.run_until_complete(self.ws.close())
        if hasattr(self, "session"):
            with contextlib.suppress(Exception):
                self.loop.run_until_complete(self.session.close())
        self.loop.close()
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(10)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait(10)
        self.log.close()
        shutil.rmtree(self.profile, ignore_errors=True)

    def __enter__(self) -> Browser:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
