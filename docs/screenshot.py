"""Take docs/status-page.png: the gateway's status page in headless Chromium (``make docs``).

Four emulated machines on pseudo-terminals, as in the test suite: mill-1 is in the middle of a
requested program, lathe-2 has punched a program that differs from the program folder's copy,
mill-3 asked for a program that does not exist, and router-4's device server does not answer.
The page is read once it shows all of that, and its picture is written to the path given.

Needs Debian's chromium (``apt-get install chromium``).
"""

from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from dnc.emulator import Emulator  # noqa: E402
from dnc.gateway import Gateway, State  # noqa: E402
from dnc.gateway_config import load_config  # noqa: E402
from dnc.web import StatusPage  # noqa: E402
from tests.browser import Browser  # noqa: E402
from tests.test_dnc_serial import control_for, program  # noqa: E402
from tests.test_gateway import free_port, request  # noqa: E402

CONFIG = """\
[gateway]
journal = "journal.jsonl"
idle = 0.5

[requests]
not_found_message = true

[web]
enabled = true
listen = "127.0.0.1:{web}"

[[port]]
name = "mill-1"
url = "{tmp}/mill-1"
profile = "fanuc-mill"
programs = "programs"
receive = "received/mill-1"

[[port]]
name = "lathe-2"
url = "{tmp}/lathe-2"
profile = "iso-lathe"
programs = "programs"
receive = "received/lathe-2"

[[port]]
name = "mill-3"
url = "{tmp}/mill-3"
profile = "fanuc-mill"
programs = "programs"
receive = "received/mill-3"

[[port]]
name = "router-4"
url = "socket://127.0.0.1:{closed}"
profile = "iso-mill"
programs = "programs"
receive = "received/router-4"
"""


def until(what: str, predicate: object, timeout: float = 60.0) -> None:
    end = time.monotonic() + timeout
    while not predicate():  # type: ignore[operator]
        if time.monotonic() > end:
            raise SystemExit(f"screenshot: {what}: not within {timeout:g} s")
        time.sleep(0.05)


def main(out: Path) -> None:
    with tempfile.TemporaryDirectory(prefix="tapegate-docs-") as name:
        tmp = Path(name)
        (tmp / "programs").mkdir()
        (tmp / "programs" / "O1234.nc").write_text(program(900))
        punched = program(10, number=5678)
        (tmp / "programs" / "O5678.nc").write_text(punched.replace("N9 X13.5", "N9 X99.5"))
        (tmp / "gateway.toml").write_text(CONFIG.format(tmp=tmp, web=free_port(),
                                                        closed=free_port()))
        gateway = Gateway(load_config(tmp / "gateway.toml"))
        page = StatusPage(gateway, gateway.config.web)
        machines = [
            Emulator(control_for("fanuc-mill"), punch=request("(PRG=1234)"),
                     link=tmp / "mill-1"),
            Emulator(control_for("iso-lathe"), punch=punched.encode("ascii"),
                     link=tmp / "lathe-2"),
            Emulator(control_for("fanuc-mill"), punch=request("(PRG=4711)"),
                     link=tmp / "mill-3"),
        ]
        page.start()
        gateway.start()
        try:
            mill = gateway.port(0).status
            until("the other ports' transfers", lambda: gateway.port(1).status.transfers >= 1
                  and gateway.port(2).status.transfers >= 3)
            until("mill-1 at a third of its program", lambda: mill.state in (
                State.SENDING, State.PAUSED) and mill.bytes_sent > mill.bytes_total / 3)
            with Browser(width=1280, height=640) as browser:
                browser.open(gateway.config.web.url)
                browser.wait_for("document.querySelectorAll('#errors li').length >= 3 && "
                                 "document.querySelector('tr[data-port=\"mill-1\"] td.bytes')"
                                 ".innerText.includes('/')")
                browser.screenshot(out)
                if browser.exceptions:
                    raise SystemExit(f"screenshot: the page's script failed: "
                                     f"{browser.exceptions}")
        finally:
            for machine in machines:
                machine.stop()
            gateway.stop()
            page.stop()
    print(f"wrote {out}")


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "docs" / "status-page.png")
