"""The gateway's configuration file (``tapegate serve --config gateway.toml``).

One TOML file describes the whole gateway: the journal, the request conventions, the Modbus
interface, the status page and one ``[[port]]`` table per machine. Relative paths are relative
to the file. Every error names the key and, where it can be found, the line (``gateway.toml:14:
port[1].profile: no profile named 'fanuk'``); nothing starts until the whole file is valid. The
keys are listed in ``docs/gateway.md``.
"""

from __future__ import annotations

import ipaddress
import re
import tomllib
from dataclasses import dataclass, field, replace
from decimal import Decimal
from pathlib import Path
from typing import Any

from dnc.dataline import DEFAULT_PATTERNS as DATA_PATTERNS
from dnc.passwords import MalformedHash, parse_hash
from dnc.requests import DEFAULT_EXTENSIONS, DEFAULT_PATTERNS, RequestRules
from formats.errors import ProfileError, TapegateError
from formats.profile import (
    Keys,
    Profile,
    SerialSettings,
    data_pattern_problem,
    load_profile,
    serial_settings,
)

# How late the gateway may see a DC3, for ports whose serial settings do not say: many ports
# served by one process on a shared host see their control's DC3 later than a lone `send`
# (docs/benchmarks.md, Gateway); the sender paces itself to keep the allowance (dnc.sender).
DC3_REACTION = 0.004


class ConfigError(TapegateError):
    """A gateway configuration that is malformed or names something that does not exist; its
    ``key`` names the key at fault (``port[1].profile``), which places it on its line."""

    default_code = "config-value"
    unknown_key_code = "config-unknown-key"


@dataclass(frozen=True)
class PortConfig:
    name: str
    url: str
    profile: Profile
    serial: SerialSettings
    programs: Path  # the folder programs are sent from (and requests are served from)
    receive: Path  # the folder punched programs are saved to
    compare: bool = True  # compare a received program with the program folder's copy
    check: bool = True  # refuse to send a program the check finds errors in
    requests: bool = True  # serve remote requests on this port
    convert: bool = False  # FTP: a download is converted to the profile's format on the way
    ftp_user: str = ""  # url = "ftp": the machine logs in to the gateway's FTP server as this
    ftp_password_hash: str = ""  # scrypt$... from `tapegate password`
    max_upload: int = 0  # FTP: largest upload in bytes (552 beyond it)
    allow_write: bool = False  # FTP: DELE, RNFR/RNTO, MKD in the program folder

    @property
    def is_ftp(self) -> bool:
        return self.url == FTP_URL
    # DPRNT lines taken as machine data (dnc.dataline): the port's, else its profile's, else the
    # defaults; () turns data lines off
    data_patterns: tuple[str, ...] = DATA_PATTERNS


@dataclass(frozen=True)
class ModbusConfig:
    enabled: bool = False
    host: str = "127.0.0.1"
    port: int = 5020
    unit: int = 1  # 0: answer every unit id
    allow_write: bool = False


@dataclass(frozen=True)
class WebConfig:
    """The status page for people (:mod:`dnc.web`): read-only, off unless enabled."""
    enabled: bool = False
    host: str = "127.0.0.1"  # loopback unless configured
    port: int = 8080
    transfers: int = 20  # how many of the journal's last transfers (and errors) it shows

    @property
    def url(self) -> str:
        host = f"[{self.host}]" if ":" in self.host else self.host
        return f"http://{host}:{self.port}/"


FTP_URL = "ftp"  # a [[port]] whose machine logs in to the gateway's FTP server


@dataclass(frozen=True)
class FtpConfig:
    """The gateway's FTP server for machines on the network (:mod:`dnc.ftp`)."""
    enabled: bool = False
    host: str = "127.0.0.1"  # loopback unless configured
    port: int = 2121
    passive_ports: tuple[int, int] | None = None  # None: ports the system chooses
    tls_cert: Path | None = None  # explicit FTPS (AUTH TLS) when given with tls_key
    tls_key: Path | None = None
    required: bool = False  # with TLS: plain logins and plain data connections refused
    login_delay: float = 1.0  # a bad password's reply waits this long, doubling per failure
    ban_after: int = 5  # bad passwords from one address before it is refused for a while
    ban_seconds: float = 600.0
    timeout: float = 300.0  # a client silent this long is disconnected

    @property
    def address(self) -> str:
        return f"[{self.host}]:{self.port}" if ":" in self.host else f"{self.host}:{self.port}"


@dataclass(frozen=True)
class MqttConfig:
    """The MQTT publisher (:mod:`dnc.mqtt`): off unless enabled. Topics under
    ``tapegate/<gateway>/`` (docs/mqtt.md)."""
    enabled: bool = False
    scheme: str = "mqtt"  # mqtt | mqtts (TLS)
    host: str = "127.0.0.1"
    port: int = 1883
    gateway: str = ""  # this gateway's name in the topics
    ca: Path | None = None  # mqtts: the CA certificates to trust (default: the system's)
    cert: Path | None = None  # mqtts: this gateway's client certificate and key
    key: Path | None = None
    user: str = ""
    password_file: Path | None = None  # its first line is the password
    client_id: str = ""
    allow_commands: bool = False  # "send program N" and "abort" on .../port/<port>/command
    queue: Path | None = None  # the on-disk queue of events not yet acknowledged
    queue_limit: int = 100_000  # events kept while the broker is away; the oldest dropped
    keepalive: int = 30  # seconds; the broker sends the last will after 1.5 times this
    interval: float = 0.5  # seconds between two looks at the ports' states

    @property
    def broker(self) -> str:
        host = f"[{self.host}]" if ":" in self.host else self.host
        return f"{self.scheme}://{host}:{self.port}"


@dataclass(frozen=True)
class GatewayConfig:
    source: Path
    ports: tuple[PortConfig, ...]
    journal: Path | None = None
    requests: RequestRules = field(default_factory=RequestRules)
    modbus: ModbusConfig = field(default_factory=ModbusConfig)
    web: WebConfig = field(default_factory=WebConfig)
    ftp: FtpConfig = field(default_factory=FtpConfig)
    mqtt: MqttConfig = field(default_factory=MqttConfig)
    request_timeout: float = 300.0  # how long a requested program waits for the DC1
    idle: float = 5.0  # silence that ends a punched program without DC4 or closing %
    retry_first: float = 1.0  # backoff for a port that cannot be opened or vanished
    retry_max: float = 60.0
    stop_grace: float = 0.0  # on SIGTERM, transfers under way may finish within this time


_TOP = {"gateway", "requests", "modbus", "web", "mqtt", "port", "ftp"}
_GATEWAY = {"journal", "request_timeout", "idle", "retry_first", "retry_max", "stop_grace",
            "dc3_reaction"}
_REQUESTS = {"numbers", "patterns", "max_chars", "not_found_message", "message_number",
             "extensions"}
_MODBUS = {"enabled", "host", "port", "unit", "allow_write"}
_WEB = {"enabled", "listen", "transfers"}
_FTP = {"enabled", "listen", "passive_ports", "tls_cert", "tls_key", "required", "login_delay",
        "ban_after", "ban_seconds", "timeout"}
_FTP_PORT = {"ftp_user", "ftp_password_hash", "max_upload", "allow_write"}
_PORT = {"name", "url", "profile", "programs", "receive", "compare", "check", "requests",
         "serial", "convert", "data_patterns", *_FTP_PORT}
_MQTT = {"enabled", "broker", "gateway", "ca", "cert", "key", "user", "password_file",
         "client_id", "allow_commands", "queue", "queue_limit", "keepalive", "interval"}


def load_config(path: str | Path) -> GatewayConfig:
    path = Path(path)
    try:
        text = path.read_text("utf-8")
    except OSError as exc:
        raise ConfigError(f"cannot read the configuration: {exc.strerror}",
                          file=str(path), code="config-unreadable") from None
    except UnicodeDecodeError as exc:
        raise ConfigError(f"cannot read the configuration: not UTF-8 text ({exc.reason} at "
                          f"byte {exc.start})", file=str(path), code="config-unreadable"
                          ) from None
    return config_from_text(text, path)


def config_from_text(text: str, path: Path) -> GatewayConfig:
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ConfigError(f"not valid TOML: {exc}", file=str(path), code="config-toml") from None
    try:
        return _build(data, path.parent)
    except ConfigError as exc:
        raise exc.located(file=str(path), line=_line_of(text, exc.key)) from None


def _build(data: dict[str, Any], base: Path) -> GatewayConfig:
    Keys(data, "", _TOP, ConfigError)
    gw = Keys(_table(data, "gateway"), "gateway.", _GATEWAY, ConfigError)
    journal = gw.get("journal", str, "")
    ports_data = data.get("port", [])
    if not isinstance(ports_data, list) or not ports_data:
        raise ConfigError("no ports: add a [[port]] table for each machine", key="port")
    reaction = _seconds(gw, "dc3_reaction", DC3_REACTION, minimum=0)
    # ports naming one profile share one Profile, and so one compiled machine of the core
    # (formats.machine.machine): compiled once for the whole gateway
    profiles: dict[str, Profile] = {}
    ports = tuple(_port(p, i, base, reaction, profiles) for i, p in enumerate(ports_data))
    names = [p.name for p in ports]
    for name in names:
        if names.count(name) > 1:
            twice = names.index(name, names.index(name) + 1)
            raise ConfigError(f"port[{twice}].name {name!r} is used twice: every port needs "
                              "its own name", key=f"port[{twice}].name")
    # every FTP machine's url is "ftp": one listener, a login each
    urls = [p.url if not p.is_ftp else f"{p.url}:{p.name}" for p in ports]
    for url in urls:
        if urls.count(url) > 1:
            twice = urls.index(url, urls.index(url) + 1)
            raise ConfigError(f"port[{twice}].url {url!r} is used by two ports",
                              key=f"port[{twice}].url")
    ftp = _ftp(_table(data, "ftp"), base)
    _check_ftp_ports(ports, ftp)
    return GatewayConfig(
        source=base, ports=ports, journal=base / journal if journal else None,
        requests=_requests(_table(data, "requests")), modbus=_modbus(_table(data, "modbus")),
        web=_web(_table(data, "web")), ftp=ftp, mqtt=_mqtt(_table(data, "mqtt"), base),
        request_timeout=_seconds(gw, "request_timeout", 300.0),
        idle=_seconds(gw, "idle", 5.0), retry_first=_seconds(gw, "retry_first", 1.0),
        retry_max=_seconds(gw, "retry_max", 60.0),
        stop_grace=_seconds(gw, "stop_grace", 0.0, minimum=0))


def _table(data: dict[str, Any], key: str) -> dict[str, Any]:
    value = data.get(key, {})
    if not isinstance(value, dict):
        raise ConfigError(f"{key} must be a table ([{key}])", key=key)
    return value


def _seconds(keys: Keys, key: str, default: float, minimum: float = 0.01) -> float:
    value = keys.number(key, Decimal(str(default)), Decimal(str(minimum)))
    return float(value if value is not None else default)


def _requests(data: dict[str, Any]) -> RequestRules:
    keys = Keys(data, "requests.", _REQUESTS, ConfigError)
    numbers = _strings(keys, "numbers", ["O9999"])
    patterns = _strings(keys, "patterns", list(DEFAULT_PATTERNS))
    for i, pattern in enumerate(patterns):
        try:
            compiled = re.compile(pattern)
        except re.error as exc:
            raise ConfigError(f"requests.patterns[{i + 1}] is not a regular expression: "
                              f"{exc}", key=f"requests.patterns[{i + 1}]") from None
        if "program" not in compiled.groupindex:
            raise ConfigError(f"requests.patterns[{i + 1}] needs a named group "
                              "(?P<program>...) for the program asked for",
                              key=f"requests.patterns[{i + 1}]")
        unknown = set(compiled.groupindex) - {"program", "block"}
        if unknown:
            raise ConfigError(f"requests.patterns[{i + 1}]: unknown group {sorted(unknown)[0]!r}"
                              "; the groups are program and block",
                              key=f"requests.patterns[{i + 1}]")
    max_chars = keys.get("max_chars", int, 2048)
    if max_chars < 16:
        raise ConfigError("requests.max_chars must be at least 16", key="requests.max_chars")
    message = keys.get("message_number", str, "O9998")
    if not re.fullmatch(r"O\d{1,8}", message):
        raise ConfigError(f"requests.message_number = {message!r}: give a program number such "
                          "as O9998", key="requests.message_number")
    return RequestRules(tuple(numbers), tuple(patterns), max_chars,
                        keys.get("not_found_message", bool, False), message,
                        tuple(_strings(keys, "extensions", list(DEFAULT_EXTENSIONS))))


def _strings(keys: Keys, key: str, default: list[str]) -> list[str]:
    value = keys.get(key, list, default)
    if not all(isinstance(v, str) for v in value):
        raise ConfigError(f"{keys.prefix}{key} must be a list of strings",
                          key=keys.prefix + key)
    return list(value)


def _modbus(data: dict[str, Any]) -> ModbusConfig:
    keys = Keys(data, "modbus.", _MODBUS, ConfigError)
    port = keys.get("port", int, 5020)
    unit = keys.get("unit", int, 1)
    if not 1 <= port <= 65535:
        raise ConfigError(f"modbus.port = {port}: give a TCP port 1-65535", key="modbus.port")
    if not 0 <= unit <= 247:
        raise ConfigError(f"modbus.unit = {unit}: give a unit id 1-247 (0: any)",
                          key="modbus.unit")
    return ModbusConfig(keys.get("enabled", bool, False), keys.get("host", str, "127.0.0.1"),
                        port, unit, keys.get("allow_write", bool, False))


def _web(data: dict[str, Any]) -> WebConfig:
    keys = Keys(data, "web.", _WEB, ConfigError)
    listen = keys.get("listen", str, "127.0.0.1:8080")
    host, port = _listen_address(listen)
    transfers = keys.get("transfers", int, 20)
    if not 1 <= transfers <= 500:
        raise ConfigError(f"web.transfers = {transfers}: give a number of transfers 1-500",
                          key="web.transfers")
    return WebConfig(keys.get("enabled", bool, False), host, port, transfers)


def parse_broker(text: str, key: str = "mqtt.broker") -> tuple[str, str, int]:
    """``mqtt://host[:port]`` or ``mqtts://host[:port]`` as (scheme, host, port); the port is
    1883 for mqtt and 8883 for mqtts unless given. IPv6 addresses in brackets."""
    bad = ConfigError(f"{key} = {text!r}: give mqtt://host[:port] or mqtts://host[:port], "
                      "such as mqtt://127.0.0.1:1883", key=key)
    m = re.fullmatch(r"(?P<scheme>mqtts?)://(?:\[(?P<v6>[0-9A-Fa-f:.]+)\]|"
                     r"(?P<host>[A-Za-z0-9.\-]+))(?::(?P<port>\d{1,5}))?/?", text)
    if not m:
        raise bad
    scheme = m.group("scheme")
    host = m.group("v6") or m.group("host")
    if m.group("v6"):
        try:
            ipaddress.IPv6Address(host)
        except ValueError:
            raise bad from None
    port = int(m.group("port")) if m.group("port") else (8883 if scheme == "mqtts" else 1883)
    if not 1 <= port <= 65535:
        raise ConfigError(f"{key} = {text!r}: the port must be 1-65535", key=key)
    return scheme, host, port


def _mqtt(data: dict[str, Any], base: Path) -> MqttConfig:
    keys = Keys(data, "mqtt.", _MQTT, ConfigError)
    enabled = keys.get("enabled", bool, False)
    scheme, host, port = parse_broker(keys.get("broker", str, "mqtt://127.0.0.1:1883"))
    gateway = keys.get("gateway", str, "")
    if enabled and "gateway" not in data:
        raise ConfigError("mqtt.gateway is missing: name this gateway in the topics, such as "
                          "gateway = \"hall-1\"", key="mqtt")
    if gateway and not re.fullmatch(r"[A-Za-z0-9_.\-]{1,64}", gateway):
        raise ConfigError(f"mqtt.gateway = {gateway!r}: use 1-64 letters, digits, '_', '.', "
                          "'-' (no '/', '+' or '#': it is a topic level)", key="mqtt.gateway")
    files: dict[str, Path | None] = {}
    for key in ("ca", "cert", "key", "password_file"):
        name = keys.get(key, str, "")
        files[key] = _existing_file(base / name, key) if name else None
    if scheme == "mqtt" and any(files[k] for k in ("ca", "cert", "key")):
        raise ConfigError("mqtt.ca, mqtt.cert and mqtt.key are for TLS: give the broker as "
                          "mqtts://",
                          key=f"mqtt.{next(k for k in ('ca', 'cert', 'key') if files[k])}")
    if (files["cert"] is None) != (files["key"] is None):
        raise ConfigError(f"mqtt.{'key' if files['key'] is None else 'cert'} is missing: a "
                          "client certificate needs both cert and key", key="mqtt")
    user = keys.get("user", str, "")
    if files["password_file"] is not None and not user:
        raise ConfigError("mqtt.user is missing: a password_file needs the user it is for",
                          key="mqtt")
    client_id = keys.get("client_id", str, f"tapegate-{gateway}")
    if not re.fullmatch(r"[A-Za-z0-9_.\-]{1,64}", client_id):
        raise ConfigError(f"mqtt.client_id = {client_id!r}: use 1-64 letters, digits, '_', '.', "
                          "'-'", key="mqtt.client_id")
    limit = keys.get("queue_limit", int, 100_000)
    if not 10 <= limit <= 10_000_000:
        raise ConfigError(f"mqtt.queue_limit = {limit}: give a number of events 10-10000000",
                          key="mqtt.queue_limit")
    keepalive = keys.get("keepalive", int, 30)
    if not 5 <= keepalive <= 3600:
        raise ConfigError(f"mqtt.keepalive = {keepalive}: give seconds 5-3600",
                          key="mqtt.keepalive")
    queue = keys.get("queue", str, f"mqtt-{gateway or 'gateway'}.queue")
    return MqttConfig(enabled=enabled, scheme=scheme, host=host, port=port, gateway=gateway,
                      ca=files["ca"], cert=files["cert"], key=files["key"], user=user,
                      password_file=files["password_file"], client_id=client_id,
                      allow_commands=keys.get("allow_commands", bool, False),
                      queue=base / queue, queue_limit=limit, keepalive=keepalive,
                      interval=_seconds(keys, "interval", 0.5, minimum=0.05))


def _existing_file(path: Path, key: str) -> Path:
    try:
        found = path.is_file()
    except OSError as exc:
        raise ConfigError(f"mqtt.{key}: no file {str(path)[:80]!r}: {exc.strerror}",
                          key=f"mqtt.{key}") from None
    if not found:
        raise ConfigError(f"mqtt.{key}: no file {str(path)!r}", key=f"mqtt.{key}")
    return path


def _listen_address(text: str, key: str = "web.listen") -> tuple[str, int]:
    """``127.0.0.1:8080``, ``[::1]:8080``, ``0.0.0.0:8080`` or ``name:8080`` as (host, port)."""
    bad = ConfigError(f"{key} = {text!r}: give an address and a TCP port such as "
                      "127.0.0.1:8080 (or [::1]:8080)", key=key)
    m = re.fullmatch(r"\[(?P<v6>[0-9A-Fa-f:.]+)\]:(?P<port>\d{1,5})|"
                     r"(?P<host>[A-Za-z0-9.\-]+):(?P<port4>\d{1,5})", text)
    if not m:
        raise bad
    host = m.group("v6") or m.group("host")
    port = int(m.group("port") or m.group("port4"))
    if m.group("v6"):
        try:
            ipaddress.IPv6Address(host)
        except ValueError:
            raise bad from None
    elif re.fullmatch(r"[0-9.]+", host):
        try:
            ipaddress.IPv4Address(host)
        except ValueError:
            raise bad from None
    elif not re.fullmatch(r"[A-Za-z0-9](?:[A-Za-z0-9\-]{0,61}[A-Za-z0-9])?"
                          r"(?:\.[A-Za-z0-9](?:[A-Za-z0-9\-]{0,61}[A-Za-z0-9])?)*", host):
        raise bad
    if not 1 <= port <= 65535:
        raise ConfigError(f"{key} = {text!r}: the port must be 1-65535", key=key)
    return host, port


def _port(data: Any, number: int, base: Path, reaction: float,
          profiles: dict[str, Profile]) -> PortConfig:
    prefix = f"port[{number}]."
    if not isinstance(data, dict):
        raise ConfigError(f"port[{number}] must be a table ([[port]])", key=f"port[{number}]")
    keys = Keys(data, prefix, _PORT, ConfigError)
    for key in ("name", "url", "profile", "programs", "receive"):
        if key not in data:
            raise ConfigError(f"{prefix}{key} is missing", key=prefix + key,
                              code="config-missing-key")
    name = keys.get("name", str, "")
    if not re.fullmatch(r"[A-Za-z0-9_.\-]{1,40}", name):
        raise ConfigError(f"{prefix}name = {name!r}: use letters, digits, '_', '.', '-'",
                          key=f"{prefix}name")
    profile_name = keys.get("profile", str, "")
    profile_path = base / profile_name
    which = str(profile_path) if profile_name.endswith(".toml") else profile_name
    try:
        profile = profiles.get(which) or profiles.setdefault(which, load_profile(which))
    except ProfileError as exc:
        raise ConfigError(f"{prefix}profile: {exc.message}", key=f"{prefix}profile",
                          code="config-profile") from None
    except OSError as exc:  # a name the system cannot look up (too long, for one)
        raise ConfigError(f"{prefix}profile: no profile named {profile_name[:60]!r}: "
                          f"{exc.strerror}", key=f"{prefix}profile",
                          code="config-profile") from None
    serial = serial_settings(keys.get("serial", dict, {}), profile.serial,
                             prefix=f"{prefix}serial.", error=ConfigError)
    if serial.dc3_reaction is None:
        serial = replace(serial, dc3_reaction=reaction)
    programs = base / keys.get("programs", str, "")
    try:
        found = programs.is_dir()
    except OSError as exc:  # a name the system cannot look up (too long, for one)
        raise ConfigError(f"{prefix}programs: no folder {str(programs)[:80]!r}: "
                          f"{exc.strerror}", key=f"{prefix}programs",
                          code="config-no-folder") from None
    if not found:
        raise ConfigError(f"{prefix}programs: no folder {str(programs)!r}",
                          key=f"{prefix}programs", code="config-no-folder")
    patterns = profile.data_patterns if profile.data_patterns is not None else DATA_PATTERNS
    if "data_patterns" in data:
        patterns = tuple(_strings(keys, "data_patterns", []))
        for i, pattern in enumerate(patterns):
            problem = data_pattern_problem(pattern)
            if problem:
                raise ConfigError(f"{prefix}data_patterns[{i}] {problem}",
                                  key=f"{prefix}data_patterns")
    return PortConfig(name=name, url=keys.get("url", str, ""), profile=profile, serial=serial,
                      programs=programs, receive=base / keys.get("receive", str, ""),
                      compare=keys.get("compare", bool, True),
                      check=keys.get("check", bool, True),
                      requests=keys.get("requests", bool, True),
                      convert=keys.get("convert", bool, False), data_patterns=patterns,
                      **_ftp_port(keys, prefix))


def _line_of(text: str, key: str | None) -> int | None:
    """The line of ``key`` (``port[1].profile`` → the ``profile =`` line of the second
    ``[[port]]`` table: ports count from 0, as in ``serve --check`` and Modbus), or ``None``."""
    m = re.match(r"(port\[(\d+)\]|gateway|requests|modbus|web|ftp|mqtt)?\.?([A-Za-z_]+)?",
                 key or "")
    if not m or not m.group(1):
        return None
    lines = text.splitlines()
    start: int | None
    if m.group(2):
        headers = [i for i, t in enumerate(lines) if re.match(r"\s*\[\[\s*port\s*\]\]", t)]
        index = int(m.group(2))
        if index >= len(headers):
            return None
        start = headers[index]
    else:
        start = next((i for i, t in enumerate(lines)
                      if re.match(rf"\s*\[\s*{m.group(1)}\s*\]", t)), None)
        if start is None:
            return None
    key = m.group(3)
    for i in range(start + 1, len(lines)):
        if re.match(r"\s*\[", lines[i]):
            break
        if key and re.match(rf"\s*{re.escape(key)}\s*=", lines[i]):
            return i + 1
    return start + 1


# -- FTP machines ([ftp] and the [[port]] tables with url = "ftp") ------------------------------


def _ftp(data: dict[str, Any], base: Path) -> FtpConfig:
    keys = Keys(data, "ftp.", _FTP, ConfigError)
    host, port = _listen_address(keys.get("listen", str, "127.0.0.1:2121"), "ftp.listen")
    passive = None
    if "passive_ports" in data:
        text = keys.get("passive_ports", str, "")
        m = re.fullmatch(r"\s*(\d{1,5})\s*-\s*(\d{1,5})\s*", text)
        if not m or not 1024 <= int(m.group(1)) <= int(m.group(2)) <= 65535:
            raise _ftp_error("ftp.passive_ports", f"ftp.passive_ports = {text!r}: give a range "
                             "of TCP ports such as 60000-60049 (1024-65535, first to last)")
        passive = (int(m.group(1)), int(m.group(2)))
    cert, key = (keys.get(k, str, "") for k in ("tls_cert", "tls_key"))
    if bool(cert) != bool(key):
        missing = "ftp.tls_key" if cert else "ftp.tls_cert"
        raise _ftp_error(missing, f"{missing} is missing: FTPS needs both tls_cert and tls_key")
    for name, value in (("tls_cert", cert), ("tls_key", key)):
        if value and not (base / value).is_file():
            raise _ftp_error(f"ftp.{name}", f"ftp.{name}: no file {str(base / value)!r}")
    required = keys.get("required", bool, False)
    if required and not cert:
        raise _ftp_error("ftp.required", "ftp.required = true needs FTPS: give tls_cert and "
                         "tls_key")
    ban_after = keys.get("ban_after", int, 5)
    if not 1 <= ban_after <= 1000:
        raise _ftp_error("ftp.ban_after", f"ftp.ban_after = {ban_after}: give a number of bad "
                         "passwords 1-1000")
    return FtpConfig(keys.get("enabled", bool, False), host, port, passive,
                     base / cert if cert else None, base / key if key else None, required,
                     _seconds(keys, "login_delay", 1.0, minimum=0), ban_after,
                     _seconds(keys, "ban_seconds", 600.0, minimum=0),
                     _seconds(keys, "timeout", 300.0, minimum=1))


def _ftp_port(keys: Keys, prefix: str) -> dict[str, Any]:
    """The FTP keys of a [[port]]: required where url = "ftp", refused elsewhere."""
    data = keys.data
    if data.get("url") != FTP_URL:
        for key in sorted(_FTP_PORT | {"convert"}):
            if key in data:
                raise _ftp_error(prefix + key, f"{prefix}{key} is only for a machine on the "
                                 f'FTP server (url = "{FTP_URL}")')
        return {}
    for key in ("ftp_user", "ftp_password_hash"):
        if key not in data:
            raise _ftp_error(prefix + key, f"{prefix}{key} is missing: an FTP machine logs in "
                             "with its own user and password (hash from `tapegate password`)")
    user = keys.get("ftp_user", str, "")
    if not re.fullmatch(r"[A-Za-z0-9_.\-]{1,32}", user) or user.lower() in ("anonymous", "ftp"):
        raise _ftp_error(prefix + "ftp_user", f"{prefix}ftp_user = {user[:40]!r}: use 1-32 "
                         "letters, digits, '_', '.', '-' (never anonymous or ftp: anonymous "
                         "login is not allowed)")
    stored = keys.get("ftp_password_hash", str, "")
    try:
        parse_hash(stored)
    except MalformedHash as exc:
        raise _ftp_error(prefix + "ftp_password_hash", f"{prefix}ftp_password_hash: {exc}"
                         ) from None
    max_upload = keys.get("max_upload", int, 64 << 20)
    if not 1 <= max_upload <= 1 << 40:
        raise _ftp_error(prefix + "max_upload", f"{prefix}max_upload = {max_upload}: give a "
                         "size in bytes, at least 1")
    return {"ftp_user": user, "ftp_password_hash": stored, "max_upload": max_upload,
            "allow_write": keys.get("allow_write", bool, False)}


def _check_ftp_ports(ports: tuple[PortConfig, ...], ftp: FtpConfig) -> None:
    users: dict[str, int] = {}
    for i, p in enumerate(ports):
        if not p.is_ftp:
            continue
        if not ftp.enabled:
            raise _ftp_error(f"port[{i}].url", f'port[{i}].url = "{FTP_URL}": this machine '
                             "logs in to the gateway's FTP server; enable it with [ftp] "
                             "enabled = true")
        if p.ftp_user.lower() in users:
            raise _ftp_error(f"port[{i}].ftp_user", f"port[{i}].ftp_user {p.ftp_user!r} is "
                             f"also port[{users[p.ftp_user.lower()]}]'s: every FTP machine "
                             "needs its own user")
        users[p.ftp_user.lower()] = i


def _ftp_error(key: str, message: str) -> ConfigError:
    """An error of the FTP keys, naming the key it places on its line (``port[1].ftp_user``):
    the one place that builds them."""
    return ConfigError(message, key=key)
