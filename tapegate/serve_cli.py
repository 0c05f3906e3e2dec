"""``tapegate serve``: the gateway service for all the shop's serial machines."""

from __future__ import annotations

import logging
import signal
import sys
import threading
from types import FrameType

import click

from dnc.gateway import Gateway
from dnc.gateway_config import GatewayConfig, load_config
from dnc.link import describe, pace
from formats.errors import TapegateError
from tapegate.common import fail, user_errors


def summary(config: GatewayConfig) -> str:
    rows = [("#", "port", "url", "profile", "link", "pace", "programs", "receive")]
    for i, p in enumerate(config.ports):
        paced = pace(p.serial)
        if p.is_ftp:  # a machine that logs in to the FTP server: its login, not a link
            rows.append((str(i), p.name, p.url, p.profile.name, f"user {p.ftp_user}", "network",
                         str(p.programs), str(p.receive)))
            continue
        rows.append((str(i), p.name, p.url, p.profile.name, describe(p.serial).split(",")[0],
                     "wire" if paced is None else f"{paced:.0f} chars/s",
                     str(p.programs), str(p.receive)))
    widths = [max(len(r[i]) for r in rows) for i in range(len(rows[0]))]
    lines = ["  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip()
             for r in rows]
    m = config.modbus
    writes = "allowed" if m.allow_write else "refused"
    lines.append(f"journal: {config.journal or 'none'}")
    lines.append(f"modbus: {m.host}:{m.port}, unit {m.unit}, writes {writes}" if m.enabled
                 else "modbus: off")
    lines.append(f"web: {config.web.url} (read-only)" if config.web.enabled else "web: off")
    lines.append(ftp_summary(config))
    q = config.mqtt
    lines.append(f"mqtt: {q.broker} as {q.gateway}, commands "
                 f"{'allowed' if q.allow_commands else 'refused'}, queue {q.queue}"
                 if q.enabled else "mqtt: off")
    return "\n".join(lines)


def ftp_summary(config: GatewayConfig) -> str:
    f = config.ftp
    if not f.enabled:
        return "ftp: off"
    tls = ("FTPS required" if f.required else "FTPS offered (AUTH TLS)") if f.tls_cert \
        else "plain FTP"
    passive = f"passive {f.passive_ports[0]}-{f.passive_ports[1]}" if f.passive_ports \
        else "passive ports from the system"
    machines = [f"{p.name} (user {p.ftp_user}, "
                f"{'writes allowed' if p.allow_write else 'read and store'}, "
                f"max upload {p.max_upload} bytes{', converted' if p.convert else ''})"
                for p in config.ports if p.is_ftp]
    return (f"ftp: {f.address}, {tls}, {passive}, ban after {f.ban_after} bad passwords for "
            f"{f.ban_seconds:g} s; machines: {', '.join(machines) or 'none'}")


@click.command(short_help="Serve every configured port: requests, receive, Modbus, web.")
@click.option("--config", "config_path", required=True, type=click.Path(dir_okay=False),
              help="The gateway configuration (TOML; see docs/gateway.md).")
@click.option("--check", "check_only", is_flag=True,
              help="Check the configuration, show the ports and exit.")
@click.option("--log-level", type=click.Choice(["debug", "info", "warning", "error"]),
              default="info", show_default=True)
@user_errors
def serve(config_path: str, check_only: bool, log_level: str) -> None:
    """Serve every configured port at once: remote requests, auto-receive, journal, Modbus,
    and a read-only status page.

    Runs until SIGTERM or SIGINT (Ctrl-C); transfers under way are then finished within
    gateway.stop_grace seconds or aborted, and journalled either way.
    """
    config = load_config(config_path)
    if check_only:
        click.echo(summary(config))
        return
    handler = logging.StreamHandler(sys.stderr)
    handler.setFormatter(logging.Formatter("%(asctime)s %(levelname)s %(port)s: %(message)s",
                                           defaults={"port": "gateway"}))
    logging.basicConfig(level=log_level.upper(), handlers=[handler])
    logging.getLogger("pymodbus").setLevel(logging.WARNING)
    logging.getLogger("pyftpdlib").setLevel(logging.WARNING)  # a line per command otherwise
    for p in config.ports:
        p.receive.mkdir(parents=True, exist_ok=True)
    gateway = Gateway(config)
    modbus = None
    if config.modbus.enabled:
        # pymodbus, and aiohttp which pymodbus loads when it is installed, are imported only
        # when they are used: not by `tapegate --help` or `serve --check`
        from dnc.modbus import ModbusInterface

        modbus = ModbusInterface(gateway, config.modbus)
    stop = threading.Event()

    def on_signal(number: int, frame: FrameType | None) -> None:
        logging.getLogger("tapegate.gateway").info(
            "%s: stopping", signal.Signals(number).name)
        stop.set()

    signal.signal(signal.SIGTERM, on_signal)
    signal.signal(signal.SIGINT, on_signal)
    if modbus:
        modbus.start()
    page = None
    if config.web.enabled:
        from dnc.web import StatusPage  # aiohttp is loaded only for the page

        page = StatusPage(gateway, config.web)
        try:
            page.start()
        except TapegateError as exc:
            if modbus:
                modbus.stop()
            fail(exc)
    ftp = None
    if config.ftp.enabled:
        from dnc.ftp import FtpServer  # pyftpdlib is loaded only for FTP machines

        ftp = FtpServer(gateway, config.ftp)
        try:
            ftp.start()
        except TapegateError as exc:
            for service in (page, modbus):
                if service:
                    service.stop()
            fail(exc)
    mqtt = None
    if config.mqtt.enabled:
        from dnc.mqtt import Publisher  # paho is loaded only when it is used

        try:
            mqtt = Publisher(gateway, config.mqtt)
            mqtt.start()
        except TapegateError as exc:
            if ftp:
                ftp.stop()
            for running in (page, modbus):
                if running:
                    running.stop()
            fail(exc)
    gateway.start()
    logging.getLogger("tapegate.gateway").info(
        "serving %d port(s); SIGTERM or Ctrl-C stops", len(config.ports))
    while not stop.wait(1.0):
        pass
    if ftp:
        ftp.begin_stop()  # its transfers get the same stop_grace as the ports', at once
    gateway.stop()
    if ftp:
        ftp.stop()
    if mqtt:
        mqtt.stop()
    if page:
        page.stop()
    if modbus:
        modbus.stop()
    logging.getLogger("tapegate.gateway").info("stopped")


@click.command(short_help="Hash an FTP machine's password for the gateway configuration.")
def password() -> None:
    """Read a password on stdin (asked for twice, unechoed, on a terminal) and print its salted
    scrypt hash for a port's ftp_password_hash. The password itself is stored nowhere."""
    from dnc.passwords import hash_password

    if sys.stdin.isatty():
        text = click.prompt("Password", hide_input=True, confirmation_prompt=True,
                            err=True)
    else:
        text = sys.stdin.readline().removesuffix("\n").removesuffix("\r")
    if not text:
        click.echo("tapegate: no password on stdin: give one line with the password", err=True)
        sys.exit(2)
    click.echo(hash_password(text))
