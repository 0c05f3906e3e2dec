"""The gateway's status page (``[web]``): its configuration, its JSON and event stream over plain
HTTP, and the page itself in a real headless browser (Debian's chromium), against a gateway
whose emulated controls are in the middle of a transfer.

The browser tests are skipped where chromium is not installed (``.ci/run`` installs it).
"""

from __future__ import annotations

import http.client
import json
import os
import signal
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request
from collections.abc import Callable, Iterator
from dataclasses import asdict
from pathlib import Path
from typing import Any

import pytest

from dnc.gateway import Gateway, Result, State
from dnc.gateway_config import ConfigError, load_config
from dnc.journal import Journal, Transfer
from dnc.web import JournalTail, StatusPage, snapshot
from tests.browser import CHROMIUM, Browser
from tests.test_dnc_serial import cli, program
from tests.test_gateway import (
    CPS,
    free_port,
    journal,
    machine,
    request,
    sent_program,
    until,
    write_config,
)

pytestmark = pytest.mark.timeout(120)
needs_chromium = pytest.mark.skipif(CHROMIUM is None,
                                    reason="needs Debian's chromium (apt-get install chromium)")
ROOT = Path(__file__).resolve().parents[1]
# a transfer journalled before the gateway started, whose errors hold markup: shown as text
OLD_FAULT = {"port": "m1", "direction": "receive", "program": "O7<b>7</b>.nc", "bytes": 120,
             "blocks": 4, "start": "2026-11-30T08:00:00.000+00:00",
             "end": "2026-11-30T08:00:02.000+00:00", "result": "parity errors",
             "errors": ["O77.nc:3:5: <img src=x onerror=\"document.title='pwned'\">"],
             "sha256": ""}


def web_config(tmp: Path, ports: int, web: str, **kw: str) -> Path:
    path = write_config(tmp, ports, **kw)
    path.write_text(path.read_text() + f"\n[web]\n{web}\n")
    return path


def get(url: str) -> tuple[int, dict[str, str], bytes]:
    try:
        with urllib.request.urlopen(url, timeout=10) as r:
            return r.status, dict(r.headers), r.read()
    except urllib.error.HTTPError as exc:
        return exc.code, dict(exc.headers), exc.read()


def status(base: str) -> dict[str, Any]:
    code, headers, body = get(base + "status.json")
    assert code == 200 and headers["Content-Type"].startswith("application/json")
    return dict(json.loads(body))


@pytest.fixture
def served(tmp_path: Path) -> Iterator[Callable[[Path], tuple[Gateway, str]]]:
    """Start a gateway and its status page; both stopped after the test."""
    started: list[tuple[Gateway, StatusPage]] = []

    def start(config: Path) -> tuple[Gateway, str]:
        gateway = Gateway(load_config(config))
        page = StatusPage(gateway, gateway.config.web)
        page.start()
        gateway.start()
        started.append((gateway, page))
        return gateway, gateway.config.web.url

    yield start
    for gateway, page in started:
        gateway.stop()
        page.stop()


def mid_transfer(tmp: Path, served: Callable[[Path], tuple[Gateway, str]]
                 ) -> tuple[Gateway, str, Any]:
    """Port m0 is configured but has no control behind it (it cannot be opened); the control
    on m1 asked for O1234 and reads it slowly: about 8 s of sending."""
    (tmp / "journal.jsonl").write_text(json.dumps(OLD_FAULT) + "\n")
    sent_program(tmp, "O1234.nc", program(300))
    config = web_config(tmp, 2, f'enabled = true\nlisten = "127.0.0.1:{free_port()}"')
    emu = machine(tmp, 1, punch=request("(PRG=1234)"), buffer=64, rate=CPS / 20)
    gateway, base = served(config)
    return gateway, base, emu


# -- configuration -----------------------------------------------------------------------------


def test_the_page_is_off_unless_enabled_and_on_loopback_by_default(tmp_path: Path) -> None:
    config = load_config(write_config(tmp_path, 1))
    assert not config.web.enabled
    assert "web: off" in cli("serve", "--config", str(write_config(tmp_path, 1)),
                             "--check").output
    path = web_config(tmp_path, 1, "enabled = true")
    config = load_config(path)
    assert (config.web.host, config.web.port, config.web.transfers) == ("127.0.0.1", 8080, 20)
    result = cli("serve", "--config", str(path), "--check")
    assert result.exit_code == 0
    assert "web: http://127.0.0.1:8080/ (read-only)" in result.output
    path = web_config(tmp_path, 1, 'enabled = true\nlisten = "[::1]:8081"\ntransfers = 5')
    config = load_config(path)
    assert (config.web.host, config.web.port, config.web.url) == ("::1", 8081,
                                                                  "http://[::1]:8081/")
    path = web_config(tmp_path, 1, 'enabled = true\nlisten = "shopfloor.local:80"')
    assert load_config(path).web.host == "shopfloor.local"


@pytest.mark.parametrize(("web", "message"), [
    ('listen = "127.0.0.1"', "web.listen = '127.0.0.1': give an address and a TCP port such "
                             "as 127.0.0.1:8080"),
    ('listen = "127.0.0.1:70000"', "web.listen = '127.0.0.1:70000': the port must be 1-65535"),
    ('listen = "300.1.2.3:8080"', "web.listen = '300.1.2.3:8080': give an address"),
    ('listen = "[::g]:8080"', "web.listen = '[::g]:8080': give an address"),
    ('listen = "http://127.0.0.1:8080/"', "give an address and a TCP port"),
    ("listen = 8080", "web.listen must be"),
    ('enabled = "yes"', "web.enabled must be"),
    ("transfers = 0", "web.transfers = 0: give a number of transfers 1-500"),
    ('lisen = "127.0.0.1:8080"', "unknown key web.'lisen'"),
])
def test_a_bad_web_table_is_a_config_error_naming_the_key_and_line(
        tmp_path: Path, web: str, message: str) -> None:
    path = web_config(tmp_path, 1, web)
    with pytest.raises(ConfigError) as err:
        load_config(path)
    line = path.read_text().splitlines().index(web) + 1
    key = "web." + web.split(" =")[0]
    code = "config-unknown-key" if key == "web.lisen" else "config-value"
    assert (err.value.code, err.value.key, err.value.line) == (code, key, line)
    assert str(err.value).startswith(f"{path}:{line}: "), str(err.value)
    result = cli("serve", "--config", str(path))
    assert result.exit_code == 2
    assert message in result.output


def test_the_web_library_is_not_loaded_by_help_or_check(tmp_path: Path) -> None:
    path = web_config(tmp_path, 1, "enabled = true")
    code = ("import sys; from click.testing import CliRunner; from tapegate.cli import main; "
            "r = CliRunner().invoke(main, ['--help']); "
            f"r2 = CliRunner().invoke(main, ['serve', '--config', {str(path)!r}, '--check']); "
            "print(r.exit_code, r2.exit_code, 'serve' in r.output, "
            "'aiohttp' in sys.modules, 'pymodbus' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         cwd=ROOT, timeout=60, check=True).stdout
    assert out.split() == ["0", "0", "True", "False", "False"]


def test_an_address_in_use_is_a_clear_error_exit_3(tmp_path: Path) -> None:
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        modbus = free_port()
        path = web_config(tmp_path, 1, f'enabled = true\nlisten = "127.0.0.1:{port}"',
                          modbus=f"enabled = true\nport = {modbus}")
        service = subprocess.run([sys.executable, "-m", "tapegate", "serve", "--config",
                                  str(path)], capture_output=True, text=True, cwd=ROOT,
                                 timeout=60)
    assert service.returncode == 3, service.stderr
    assert f"tapegate: web: cannot listen on 127.0.0.1:{port}: " in service.stderr
    assert "Traceback" not in service.stderr
    with socket.socket() as again:  # the Modbus server it had started was stopped
        again.bind(("127.0.0.1", modbus))


# -- the journal's tail ------------------------------------------------------------------------


def test_the_tail_of_a_long_journal_is_read_whole_records_only(tmp_path: Path) -> None:
    path = tmp_path / "journal.jsonl"
    journal_file = Journal(path)
    for i in range(200):
        journal_file.append(Transfer("m0", "send", f"O{i}.nc", i, 1, "2026-12-01T08:00:00",
                                     "2026-12-01T08:00:01", "ok"))
    with open(path, "a") as f:
        f.write('{"port": "m0", "direction": "se')  # torn by a crash while writing
    tail = JournalTail(path, window=1000)  # begins inside a record
    transfers = tail.read()
    assert 3 < len(transfers) < 20 and transfers[-1].program == "O199.nc"
    assert [t.bytes for t in transfers] == list(range(200 - len(transfers), 200))
    assert tail.read() is transfers  # unchanged file: not read again
    journal_file.append(Transfer("m0", "receive", "O5.nc", 5, 1, "", "", "differs"))
    assert tail.read()[-1].program == "O199.nc"  # the torn line swallowed the next one
    assert JournalTail(tmp_path / "none.jsonl").read() == []  # nothing journalled yet


def test_a_journal_that_cannot_be_read_is_shown_as_an_error(tmp_path: Path) -> None:
    tail = JournalTail(tmp_path)  # a folder where the file should be
    assert tail.read() == []
    why = f"cannot read the journal {tmp_path.name}: Is a directory"
    assert tail.error == why
    gateway = Gateway(load_config(write_config(tmp_path, 1)))  # not started: port m0 offline
    errors = snapshot(gateway, tail, 5)["errors"]
    assert [(e["port"], e["result"], e["errors"]) for e in errors] == [
        ("m0", "offline", []), ("", "journal", [why])]


# -- JSON and events over plain HTTP -----------------------------------------------------------


def test_status_json_while_a_port_sends_and_another_cannot_be_opened(
        tmp_path: Path, served: Callable[[Path], tuple[Gateway, str]]) -> None:
    gateway, base, emu = mid_transfer(tmp_path, served)
    try:
        def sending() -> bool:
            m1 = status(base)["ports"][1]
            return m1["state"] in ("sending", "paused") and m1["line"] > 0

        assert until(sending)
        first = status(base)
        m0, m1 = first["ports"]
        assert (m0["name"], m0["state"], m0["state_code"]) == ("m0", "offline", State.OFFLINE)
        assert "cannot open" in m0["message"]
        assert (m1["name"], m1["program"], m1["program_number"]) == ("m1", "O1234.nc", 1234)
        assert m1["profile"] == "fanuc-mill" and m1["line"] > 0
        assert 0 < m1["bytes_sent"] < m1["bytes_total"] and 0 < m1["progress"] < 1
        # the same numbers as the Modbus input registers: the port's live status
        assert m1["bytes_total"] == gateway.port(1).status.bytes_total
        assert until(lambda: status(base)["ports"][1]["bytes_sent"] > m1["bytes_sent"])
        errors = first["errors"]
        assert (errors[0]["port"], errors[0]["result"]) == ("m0", "offline")
        assert "cannot open" in errors[0]["errors"][0]
        assert errors[1]["program"] == OLD_FAULT["program"]  # from the journal
        assert [t["program"] for t in first["transfers"]] == ["request 1234", "O7<b>7</b>.nc"]
        assert emu.wait(60)
        assert until(lambda: gateway.port(1).status.result == Result.OK)
        done = status(base)
        assert done["ports"][1]["state"] == "idle" and done["ports"][1]["result"] == "ok"
        newest = done["transfers"][0]
        assert (newest["port"], newest["direction"], newest["program"], newest["result"]) == (
            "m1", "send", "O1234.nc", "ok")
        assert newest == asdict(journal(tmp_path)[-1])
        assert done["journal"] == "journal.jsonl"
    finally:
        emu.stop()


def test_the_server_is_read_only_and_serves_nothing_else(
        tmp_path: Path, served: Callable[[Path], tuple[Gateway, str]]) -> None:
    config = web_config(tmp_path, 1, f'enabled = true\nlisten = "127.0.0.1:{free_port()}"')
    (tmp_path / "secret.txt").write_text("not for the web")
    _, base = served(config)
    code, headers, body = get(base)
    assert code == 200 and b"tapegate gateway" in body
    assert headers["X-Content-Type-Options"] == "nosniff"
    assert "default-src 'self'" in headers["Content-Security-Policy"]
    for asset in ("static/status.js", "static/status.css"):
        assert get(base + asset)[0] == 200
    host, port = "127.0.0.1", int(base.rsplit(":", 1)[1].strip("/"))
    for method, path in (("POST", "/status.json"), ("PUT", "/"), ("DELETE", "/events"),
                         ("HEAD", "/events"), ("POST", "/events")):
        conn = http.client.HTTPConnection(host, port, timeout=10)
        conn.request(method, path, body=b"{}")
        assert conn.getresponse().status == 405, (method, path)
        conn.close()
    for path in ("/nothing", "/static/", "/static/../web.py", "/static/%2e%2e/web.py",
                 "/static/..%2f..%2fsecret.txt", "/gateway.toml"):
        conn = http.client.HTTPConnection(host, port, timeout=10)
        conn.request("GET", path)
        response = conn.getresponse()
        assert response.status in (403, 404), (path, response.status)
        assert b"not for the web" not in response.read()
        conn.close()


def test_events_stream_a_new_snapshot_when_something_changes(
        tmp_path: Path, served: Callable[[Path], tuple[Gateway, str]]) -> None:
    _, base, emu = mid_transfer(tmp_path, served)
    host, port = "127.0.0.1", int(base.rsplit(":", 1)[1].strip("/"))
    conn = http.client.HTTPConnection(host, port, timeout=10)
    try:
        conn.request("GET", "/events")
        response = conn.getresponse()
        assert response.status == 200
        assert response.headers["Content-Type"].startswith("text/event-stream")

        def events() -> Iterator[dict[str, Any]]:
            while True:
                line = response.readline()
                assert line, "the stream ended"
                if line.startswith(b"data: "):
                    yield json.loads(line[6:])

        stream = events()
        seen = []
        end = time.monotonic() + 30
        for event in stream:  # each event differs from the one before (or is a heartbeat)
            m1 = event["ports"][1]
            if m1["state"] in ("sending", "paused"):
                seen.append(m1["bytes_sent"])
            if len(set(seen)) >= 3 or time.monotonic() > end:
                break
        assert len(set(seen)) >= 3 and seen == sorted(seen), seen
    finally:
        conn.close()
        emu.stop()


def test_sigterm_stops_the_page_with_the_gateway(tmp_path: Path) -> None:
    port = free_port()
    config = web_config(tmp_path, 1, f'enabled = true\nlisten = "127.0.0.1:{port}"')
    service = subprocess.Popen([sys.executable, "-m", "tapegate", "serve", "--config",
                                str(config)], stderr=subprocess.PIPE, text=True, cwd=ROOT,
                               env=dict(os.environ, PYTHONPATH=str(ROOT)))
    base = f"http://127.0.0.1:{port}/"

    def answers() -> bool:
        try:
            return status(base)["ports"][0]["name"] == "m0"
        except OSError:
            return False

    try:
        assert until(answers, 30)
        service.send_signal(signal.SIGTERM)
        _, log = service.communicate(timeout=30)
    finally:
        if service.poll() is None:
            service.kill()
    assert service.returncode == 0, log
    assert f"status page on {base} (read-only)" in log
    with pytest.raises(OSError), socket.create_connection(("127.0.0.1", port), timeout=2):
        pass


# -- the page in a browser ---------------------------------------------------------------------


CELL = "(document.querySelector('tr[data-port=\"{port}\"] td.{cell}')?.innerText ?? '')"


@needs_chromium
def test_the_page_in_a_browser_shows_the_ports_and_follows_the_transfer(
        tmp_path: Path, served: Callable[[Path], tuple[Gateway, str]]) -> None:
    # the browser first: its start-up (seconds on a busy machine) must not be taken from the
    # transfer's 8 s, or the page opens on a transfer already over
    with Browser() as browser:
        gateway, base, emu = mid_transfer(tmp_path, served)
        try:
            browser.open(base)

            def cell(port: str, name: str) -> str:
                return str(browser.evaluate(CELL.format(port=port, cell=name)))

            browser.wait_for("document.querySelectorAll('#ports tbody tr').length === 2")
            assert cell("m0", "state") == "offline"
            assert "cannot open" in cell("m0", "message")
            state, block = (CELL.format(port="m1", cell=c) for c in ("state", "block"))
            browser.wait_for(f"['sending', 'paused (DC3)'].includes({state}) "
                             f"&& {block}.startsWith('line ')")
            assert cell("m1", "program") == "O1234.nc"
            assert cell("m1", "block").startswith("line ")

            def sent() -> int:
                text = cell("m1", "bytes")  # "1,002 / 5,069"
                return int(text.split("/")[0].replace(",", "")) if "/" in text else -1

            first = sent()
            assert first >= 0
            # the page updates itself: no reload, the bytes grow
            assert until(lambda: sent() > first, 20), (first, sent())
            assert "%" in cell("m1", "progress")
            assert browser.evaluate("document.getElementById('live').innerText").startswith(
                "live")
            errors = str(browser.evaluate("document.getElementById('errors').innerText"))
            assert "m0 · offline" in errors and "cannot open" in errors
            # what a control punched is shown as text, never run as markup
            assert "<img src=x onerror=" in errors and "O7<b>7</b>.nc" in errors
            assert browser.evaluate("document.querySelectorAll('main img, main b').length") == 0
            assert browser.evaluate("document.title") == "tapegate gateway"
            # the end of the transfer: the port listens again, the send is the last transfer
            assert emu.wait(60)
            browser.wait_for(f"{state} === 'listening'")
            browser.wait_for("document.querySelector('#transfers tbody tr')"
                             "?.innerText.includes('O1234.nc')")
            row = str(browser.evaluate("document.querySelector('#transfers tbody tr')"
                                       ".innerText"))
            assert "send" in row and "ok" in row and "m1" in row
            assert cell("m1", "result") == "ok"
            assert browser.exceptions == []
        finally:
            emu.stop()
    assert gateway.port(1).status.result == Result.OK


@needs_chromium
def test_the_page_says_when_the_gateway_is_gone(tmp_path: Path) -> None:
    config = web_config(tmp_path, 1, f'enabled = true\nlisten = "127.0.0.1:{free_port()}"')
    config.write_text(config.read_text().replace('journal = "journal.jsonl"\n', ""))
    gateway = Gateway(load_config(config))
    page = StatusPage(gateway, gateway.config.web)
    page.start()
    gateway.start()
    try:
        with Browser() as browser:
            browser.open(gateway.config.web.url)
            browser.wait_for("document.getElementById('live').innerText.startsWith('live')")
            assert browser.wait_for("document.getElementById('no-transfers').innerText") == \
                "No journal configured."
            page.stop()
            browser.wait_for("document.getElementById('live').innerText === 'reconnecting…'")
    finally:
        gateway.stop()
        page.stop()
