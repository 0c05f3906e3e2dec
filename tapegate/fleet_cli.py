"""``tapegate fleet``: every gateway on an MQTT broker, from the states they publish."""

from __future__ import annotations

import json
import signal
import sys
import threading
from pathlib import Path
from types import FrameType
from typing import Any

import click

from dnc.gateway_config import ConfigError, _listen_address, parse_broker
from formats.errors import TapegateError
from tapegate.common import fail, user_errors
from tapegate.options import FiniteRange


def _access(broker: str, ca: str | None, cert: str | None, key: str | None, user: str | None,
            password_file: str | None) -> Any:
    from dnc.fleet import BrokerAccess

    try:
        scheme, host, port = parse_broker(broker, "--broker")
    except ConfigError as exc:
        raise click.UsageError(exc.message) from None
    if scheme == "mqtt" and (ca or cert or key):
        raise click.UsageError("--ca, --cert and --key are for TLS: give the broker as mqtts://")
    if (cert is None) != (key is None):
        raise click.UsageError("a client certificate needs both --cert and --key")
    if password_file and not user:
        raise click.UsageError("--password-file needs --user")
    password = None
    if password_file:
        try:
            lines = Path(password_file).read_text("utf-8").splitlines()
        except (OSError, UnicodeDecodeError) as exc:
            click.echo(f"tapegate: {password_file}: cannot read the password: "
                       f"{getattr(exc, 'strerror', None) or exc}", err=True)
            sys.exit(2)
        password = lines[0] if lines else ""
    return BrokerAccess(scheme, host, port, ca=Path(ca) if ca else None,
                        cert=Path(cert) if cert else None, key=Path(key) if key else None,
                        user=user or "", password=password)


def _stop_on_signals() -> threading.Event:
    stop = threading.Event()

    def on_signal(number: int, frame: FrameType | None) -> None:
        stop.set()

    signal.signal(signal.SIGTERM, on_signal)
    signal.signal(signal.SIGINT, on_signal)
    return stop


FILE = click.Path(exists=True, dir_okay=False)


@click.command(short_help="Every gateway on an MQTT broker: a table, live, JSON or a page.")
@click.option("--broker", required=True, metavar="URL",
              help="mqtt://host[:port] or mqtts://host[:port] (TLS).")
@click.option("--ca", type=FILE, help="mqtts: the CA certificates to trust.")
@click.option("--cert", type=FILE, help="mqtts: a client certificate (with --key).")
@click.option("--key", type=FILE, help="mqtts: the client certificate's key.")
@click.option("--user", help="The user name on the broker.")
@click.option("--password-file", type=FILE, help="A file whose first line is the password.")
@click.option("--watch", is_flag=True, help="Keep the table live until Ctrl-C.")
@click.option("--json", "as_json", is_flag=True,
              help="One JSON document (with --watch: one a line, at each change).")
@click.option("--web", metavar="HOST:PORT",
              help="Serve the fleet read-only in the status page's design, until Ctrl-C.")
@click.option("--timeout", type=FiniteRange(0.1, 600), default=5.0, show_default=True,
              help="Seconds to wait for the broker and for the retained states.")
@user_errors
def fleet(broker: str, ca: str | None, cert: str | None, key: str | None, user: str | None,
          password_file: str | None, watch: bool, as_json: bool, web: str | None,
          timeout: float) -> None:
    """Show every gateway publishing to the broker and every port of each, from the retained
    states the gateways publish ([mqtt] in their configuration; docs/mqtt.md). Reads only."""
    # paho and aiohttp (the page) are loaded when the command runs, not by `tapegate --help`
    from dnc.fleet import Fleet, FleetPage

    access = _access(broker, ca, cert, key, user, password_file)
    address = None
    if web:
        if watch or as_json:
            raise click.UsageError("--web serves the page; it goes with neither --watch nor "
                                   "--json")
        try:
            address = _listen_address(web, "--web")
        except ConfigError as exc:
            raise click.UsageError(exc.message) from None
    view = Fleet(access)
    try:
        view.connect(timeout)
    except TapegateError as exc:
        fail(exc)
    try:
        view.settle(timeout=timeout)
        if address is not None:
            stop = _stop_on_signals()
            click.echo(f"fleet page on http://{address[0]}:{address[1]}/ (read-only); "
                       "Ctrl-C stops", err=True)
            try:
                FleetPage(view, *address).run(stop)
            except TapegateError as exc:
                fail(exc)
            return
        if not watch:
            _show(view, as_json, broker)
            return
        stop = _stop_on_signals()
        seen = -1
        while not stop.wait(0.5):
            if view.version != seen:
                seen = view.version
                if not as_json:
                    click.echo("\x1b[H\x1b[2J", nl=False)  # the terminal cleared, top left
                _show(view, as_json, broker)
    finally:
        view.close()


def _show(view: Any, as_json: bool, broker: str) -> None:
    from dnc.fleet import table

    snapshot = view.snapshot()
    if as_json:
        click.echo(json.dumps(snapshot, ensure_ascii=False))
    elif snapshot["gateways"]:
        click.echo(table(snapshot))
    else:
        click.echo(f"no gateway has published on {broker}", err=True)
