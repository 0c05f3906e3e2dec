"""The gateway's FTP server with real clients: Python's ftplib and curl (Debian's) as the
machines, plain and explicit FTPS (a certificate made by the openssl command-line tool), against
the gateway started by the test on a free loopback port -- in the test process (threads), or as
``tapegate serve`` where the service itself is under test (SIGTERM, --check).
"""

from __future__ import annotations

import contextlib
import errno
import ftplib
import hashlib
import io
import logging
import os
import shutil
import signal
import socket
import ssl
import struct
import subprocess
import sys
import threading
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

import dnc.ftp as ftp_module
from dnc.ftp import FtpServer, LoginGuard, ftp_name
from dnc.gateway import Gateway, Result, State
from dnc.gateway_config import ConfigError, load_config
from dnc.journal import Transfer, read_journal
from dnc.modbus import input_registers
from dnc.passwords import MalformedHash, hash_password, parse_hash, verify
from dnc.requests import Forbidden
from formats.files import PendingFile
from tests.conftest import corpus_files, needs_corpus
from tests.test_gateway import free_port, until

pytestmark = pytest.mark.timeout(60)
ROOT = Path(__file__).resolve().parents[1]
PASSWORD = "s3cret-mill"
# hashes for the tests are made cheap (N = 1024); the command makes N = 16384
HASH = hash_password(PASSWORD, n=1024)
PROGRAM = "%\nO1234 (FTP TEST)\nG21 G90 G17\nG0 X10. Y10.\nG1 Z-1. F100.\nX20.\nM30\n%\n"
BROKEN = "%\nO2000\nG21 G90\nG0 X10. Y10. Q\nG1 X\nM30\n%\n"

curl = shutil.which("curl")
openssl = shutil.which("openssl")
needs_curl = pytest.mark.skipif(curl is None, reason="curl is not installed (Debian: curl)")
needs_openssl = pytest.mark.skipif(openssl is None, reason="no openssl command")


def ftp_config(tmp: Path, machines: int = 1, *, ftp: str = "", port: str = "",
               gateway: str = "", listen: int | None = None, host: str = "127.0.0.1") -> Path:
    (tmp / "programs").mkdir(exist_ok=True)
    text = [f'[gateway]\njournal = "journal.jsonl"\n{gateway}\n'
            f'[ftp]\nenabled = true\nlisten = "{host}:{listen or free_port()}"\n'
            f"login_delay = 0.01\n{ftp}\n"]
    for i in range(machines):
        text.append(f'[[port]]\nname = "m{i}"\nurl = "ftp"\nftp_user = "mill{i}"\n'
                    f'ftp_password_hash = "{HASH}"\nprofile = "fanuc-mill"\n'
                    f'programs = "programs"\nreceive = "received/m{i}"\n{port}\n')
    path = tmp / "gateway.toml"
    path.write_text("".join(text))
    return path


class Running:
    def __init__(self, tmp: Path, gateway: Gateway, server: FtpServer):
        self.tmp, self.gateway, self.server = tmp, gateway, server
        self.host, self.port = server.address

    def client(self, user: str = "mill0", password: str = PASSWORD, *,
               source: str | None = None) -> ftplib.FTP:
        ftp = ftplib.FTP(timeout=20, source_address=(source, 0) if source else None)
        ftp.connect(self.host, self.port)
        ftp.login(user, password)
        return ftp

    def url(self, name: str = "") -> str:
        return f"ftp://{self.host}:{self.port}/{name}"

    def journal(self) -> list[Transfer]:
        path = self.tmp / "journal.jsonl"
        return read_journal(path).transfers if path.exists() else []

    def records(self, result: str, direction: str | None = None) -> list[Transfer]:
        return [t for t in self.journal()
                if t.result == result and direction in (None, t.direction)]

    def received(self, machine: int = 0) -> list[str]:
        folder = self.tmp / "received" / f"m{machine}"
        return sorted(os.listdir(folder)) if folder.is_dir() else []


@pytest.fixture
def serve(tmp_path: Path, caplog: pytest.LogCaptureFixture) -> Iterator[Callable[..., Running]]:
    """Start a gateway with its FTP server on a configuration; stopped after the test, and no
    traceback logged meanwhile."""
    caplog.set_level(logging.INFO)
    started: list[Running] = []

    def start(config: Path | None = None, **kw: Any) -> Running:
        gateway = Gateway(load_config(config or ftp_config(tmp_path, **kw)))
        server = FtpServer(gateway, gateway.config.ftp)
        server.start()
        gateway.start()
        started.append(Running(tmp_path, gateway, server))
        return started[-1]

    yield start
    for running in started:
        running.server.begin_stop()
        running.gateway.stop()
        running.server.stop()
    tracebacks = [r for r in caplog.records if r.exc_info or "Traceback" in r.getMessage()]
    assert not tracebacks, tracebacks[0].getMessage()


def put(tmp: Path, name: str, text: str | bytes) -> bytes:
    data = text.encode("ascii") if isinstance(text, str) else text
    (tmp / "programs" / name).write_bytes(data)
    return data


def fetch(ftp: ftplib.FTP, name: str) -> bytes:
    out = io.BytesIO()
    ftp.retrbinary(f"RETR {name}", out.write)
    return out.getvalue()


def sha(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


# -- passwords and configuration ------------------------------------------------------------


def test_password_command_prints_a_salted_scrypt_hash() -> None:
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    run = [sys.executable, "-m", "tapegate", "password"]
    first = subprocess.run(run, input="Mill 5 pass\n", capture_output=True, text=True, env=env,
                           timeout=30)
    second = subprocess.run(run, input="Mill 5 pass\n", capture_output=True, text=True,
                            env=env, timeout=30)
    assert first.returncode == 0, first.stderr
    stored = first.stdout.strip()
    assert stored.startswith("scrypt$16384$8$1$") and "Mill 5 pass" not in stored
    assert stored != second.stdout.strip()  # salted
    assert verify(parse_hash(stored), "Mill 5 pass") and not verify(parse_hash(stored), "mill")
    empty = subprocess.run(run, input="", capture_output=True, text=True, env=env, timeout=30)
    assert empty.returncode == 2 and "no password on stdin" in empty.stderr
    assert "Traceback" not in empty.stderr


@pytest.mark.parametrize("text", ["", "scrypt$16384$8$1$abc", "md5$x$y", "scrypt$1000$8$1$"
                                  "AAAAAAAAAAAAAAAAAAAAAA==$" + "A" * 44,
                                  "scrypt$16384$8$1$!!!!$" + "A" * 44])
def test_malformed_hashes_are_refused(text: str) -> None:
    with pytest.raises(MalformedHash):
        parse_hash(text)


@pytest.mark.parametrize(("change", "message", "line", "key"), [
    (("ftp_password_hash = \"" + HASH + "\"", 'ftp_password_hash = "scrypt$1$2"'),
     "port[0].ftp_password_hash: not a hash from `tapegate password`", 13,
     "port[0].ftp_password_hash"),
    (("ftp_password_hash = \"" + HASH + "\"\n", ""), "port[0].ftp_password_hash is missing", 9,
     "port[0].ftp_password_hash"),
    (('ftp_user = "mill0"', 'ftp_user = "anonymous"'), "never anonymous", 12,
     "port[0].ftp_user"),
    (("enabled = true", "enabled = false"), 'port[0].url = "ftp": this machine logs in', 11,
     "port[0].url"),
    (("login_delay = 0.01", 'passive_ports = "60049-60000"'),
     "ftp.passive_ports = '60049-60000': give a range", 7, "ftp.passive_ports"),
    (("login_delay = 0.01", 'tls_cert = "cert.pem"'), "ftp.tls_key is missing", 4,
     "ftp.tls_key"),
    (("login_delay = 0.01", "required = true"), "ftp.required = true needs FTPS", 7,
     "ftp.required"),
    (('url = "ftp"', 'url = "loop://"'), "port[0].ftp_password_hash is only for a machine on "
     "the FTP server", 13, "port[0].ftp_password_hash"),
    (('profile = "fanuc-mill"', 'profile = "fanuc-mill"\nmax_upload = 0'),
     "port[0].max_upload = 0: give a size in bytes", 15, "port[0].max_upload"),
])
def test_config_errors_name_the_key_and_line(tmp_path: Path, change: tuple[str, str],
                                             message: str, line: int, key: str) -> None:
    path = ftp_config(tmp_path, listen=2121)
    text = path.read_text()
    assert change[0] in text
    path.write_text(text.replace(change[0], change[1], 1))
    with pytest.raises(ConfigError) as caught:
        load_config(path)
    assert (caught.value.code, caught.value.key) == ("config-value", key)
    assert (caught.value.file, caught.value.line) == (str(path), line)
    # one code and often one key for several faults (a hash malformed, missing, not for this
    # url): only the wording tells them apart
    assert message in caught.value.message, caught.value.message
    assert str(caught.value).startswith(f"{path}:{line}:"), str(caught.value)


def test_two_machines_cannot_share_a_user(tmp_path: Path) -> None:
    path = ftp_config(tmp_path, 2, listen=2121)
    path.write_text(path.read_text().replace('ftp_user = "mill1"', 'ftp_user = "MILL0"'))
    with pytest.raises(ConfigError) as caught:
        load_config(path)
    assert (caught.value.code, caught.value.key) == ("config-value", "port[1].ftp_user")
    assert "is also port[0]'s" in caught.value.message  # not a bad name (the same key and code)


def test_serve_check_lists_ftp_machines_and_fails_on_a_bad_hash(tmp_path: Path) -> None:
    path = ftp_config(tmp_path, 2, listen=2121, port="allow_write = true")
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    run = [sys.executable, "-m", "tapegate", "serve", "--config", str(path), "--check"]
    ok = subprocess.run(run, capture_output=True, text=True, env=env, timeout=30)
    assert ok.returncode == 0, ok.stderr
    assert "m1    ftp  fanuc-mill  user mill1" in ok.stdout
    assert "ftp: 127.0.0.1:2121, plain FTP" in ok.stdout
    assert "m0 (user mill0, writes allowed" in ok.stdout
    path.write_text(path.read_text().replace("scrypt$1024$", "scrypt$1000$", 1))
    bad = subprocess.run(run, capture_output=True, text=True, env=env, timeout=30)
    assert bad.returncode == 2 and "Traceback" not in bad.stderr
    assert f"{path}:13: port[0].ftp_password_hash" in bad.stderr


# -- names ------------------------------------------------------------------------------------


@pytest.mark.parametrize(("arg", "name"), [("O1234.nc", "O1234.nc"), ("/O1234.nc", "O1234.nc"),
                                           ("", ""), ("/", ""), (".", ""), ("o1234", "o1234")])
def test_names_inside_the_folder(arg: str, name: str) -> None:
    assert ftp_name(arg) == name


@pytest.mark.parametrize("arg", ["../O1234.nc", "..", "/etc/passwd", "//etc/passwd",
                                 "C:\\progs\\O1.nc", "sub/O1.nc", "a\x00b", "O" * 256,
                                 ".ftp.1234.part", "..\\..\\x", "/../x"])
def test_names_that_leave_the_folder_are_forbidden(arg: str) -> None:
    with pytest.raises(Forbidden) as err:
        ftp_name(arg)
    assert err.value.code == "request-forbidden"


def test_login_guard_delays_doubling_then_bans_for_a_while() -> None:
    guard = LoginGuard(0.5, 3, 60)
    assert guard.failed("10.0.0.9", 0) == (1, 0.5, False)
    assert guard.failed("10.0.0.9", 1) == (2, 1.0, False)
    assert guard.banned("10.0.0.9", 1) == 0
    assert guard.failed("10.0.0.9", 2) == (3, 0.0, True)
    assert guard.banned("10.0.0.9", 3) == 59 and guard.banned("10.0.0.8", 3) == 0
    assert guard.banned("10.0.0.9", 62.5) == 0
    assert guard.failed("10.0.0.9", 200)[0] == 1  # old failures are forgotten


# -- transfers --------------------------------------------------------------------------------


def test_download_and_upload_are_byte_exact_and_journalled(serve: Callable[..., Running]
                                                          ) -> None:
    g = serve()
    data = put(g.tmp, "O1234.nc", PROGRAM)
    put(g.tmp, "O2000.nc", PROGRAM.replace("O1234", "O2000"))
    with g.client() as ftp:
        assert fetch(ftp, "O1234.nc") == data
        assert fetch(ftp, "o1234") == data  # the request rules: case, number, extension
        assert sorted(ftp.nlst()) == ["O1234.nc", "O2000.nc"]
        assert sorted(n for n, _ in ftp.mlsd()) == ["O1234.nc", "O2000.nc"]
        lines: list[str] = []
        ftp.retrlines("LIST", lines.append)
        assert len(lines) == 2 and lines[0].endswith("O1234.nc")
        ftp.voidcmd("TYPE I")
        assert ftp.size("O1234") == len(data)
        assert ftp.storbinary("STOR O1234.nc", io.BytesIO(data)).startswith(
            "226 Saved as O1234.nc")
        assert ftp.storbinary("STOR O1234.nc", io.BytesIO(data)).startswith(
            "226 Saved as O1234.1.nc")  # never overwriting
        changed = data.replace(b"X20.", b"X21.")
        reply = ftp.storbinary("STOR O1234.nc", io.BytesIO(changed))
        assert reply.startswith("226 Saved as O1234.2.nc; it differs") and "X21." in reply
    folder = g.tmp / "received" / "m0"
    assert g.received() == ["O1234.1.nc", "O1234.2.nc", "O1234.nc"]  # nothing hidden left
    assert (folder / "O1234.1.nc").read_bytes() == data
    sends = [t for t in g.journal() if t.direction == "send"]
    assert [(t.program, t.result, t.bytes, t.sha256) for t in sends] == [
        ("O1234.nc", "ok", len(data), sha(data))] * 2
    receives = [t for t in g.journal() if t.direction == "receive"]
    assert [(t.program, t.result, t.sha256) for t in receives] == [
        ("O1234.nc", "ok", sha(data)), ("O1234.1.nc", "ok", sha(data)),
        ("O1234.2.nc", "differs", sha(changed))]
    assert "X21." in receives[2].errors[0]
    status = g.gateway.ports[0].status
    assert (status.state, status.result, status.transfers) == (State.IDLE, Result.DIFFERS, 5)
    assert status.program == 1234 and status.bytes_received == len(changed)
    registers = input_registers(status)  # what Modbus shows for the port
    assert registers[0] == State.IDLE and registers[8] == Result.DIFFERS and registers[9] == 5


def test_a_download_with_check_errors_is_refused_with_550(serve: Callable[..., Running]
                                                         ) -> None:
    g = serve()
    put(g.tmp, "O2000.nc", BROKEN)
    with g.client() as ftp, pytest.raises(ftplib.error_perm) as caught:
        fetch(ftp, "O2000")
    reply = str(caught.value)
    assert reply.startswith("550-O2000.nc: the check found 2 error(s); not sent")
    assert "O2000.nc:4:14: error TG100 address Q has no value" in reply
    (refused,) = g.records("refused")
    assert (refused.direction, refused.program, refused.bytes) == ("send", "O2000.nc", 0)
    assert len(refused.errors) == 2 and g.gateway.ports[0].status.result == Result.REFUSED


def test_a_converting_port_sends_what_the_converter_writes(serve: Callable[..., Running],
                                                          tmp_path: Path) -> None:
    from dnc.program import converted_copy
    from formats.profile import load_profile

    g = serve(port="convert = true")
    source = "%\nO3000\nG20 G90\nG0 X1. Y2.\nG1 X1.5 F10.\nM30\n%\n"
    put(g.tmp, "O3000.nc", source)
    expected_path, _ = converted_copy(str(tmp_path / "programs" / "O3000.nc"),
                                      load_profile("fanuc-mill"), None)
    expected = Path(expected_path).read_bytes()
    os.unlink(expected_path)
    with g.client() as ftp:
        ftp.voidcmd("TYPE I")
        with pytest.raises(ftplib.error_perm, match="550 The size is known once"):
            ftp.size("O3000.nc")
        got = fetch(ftp, "O3000.nc")
    assert got == expected
    (sent,) = g.records("ok", "send")
    assert (sent.bytes, sent.sha256) == (len(got), sha(got))


@needs_corpus
def test_a_corpus_program_goes_both_ways_byte_exact(serve: Callable[..., Running]) -> None:
    path = max(corpus_files(), key=lambda p: p.stat().st_size if p.suffix.lower() == ".nc"
               else 0)
    g = serve(port="check = false\ncompare = true")
    data = put(g.tmp, "O5000.nc", path.read_bytes())
    with g.client() as ftp:
        assert fetch(ftp, "O5000.nc") == data
        ftp.storbinary("STOR O5000.nc", io.BytesIO(data))
    assert (g.tmp / "received" / "m0" / "O5000.nc").read_bytes() == data
    assert [(t.direction, t.result, t.sha256) for t in g.journal()] == [
        ("send", "ok", sha(data)), ("receive", "ok", sha(data))]


@needs_curl
def test_curl_lists_downloads_and_uploads(serve: Callable[..., Running],
                                          tmp_path: Path) -> None:
    g = serve()
    data = put(g.tmp, "O1234.nc", PROGRAM)
    auth = ["-sS", "--max-time", "20", "-u", f"mill0:{PASSWORD}"]
    listing = subprocess.run([curl, *auth, g.url()], capture_output=True, text=True,
                             timeout=30, check=True)
    assert listing.stdout.rstrip().endswith("O1234.nc")
    got = subprocess.run([curl, *auth, g.url("O1234")], capture_output=True, timeout=30,
                         check=True)
    assert got.stdout == data
    upload = tmp_path / "up.nc"
    upload.write_bytes(data)
    subprocess.run([curl, *auth, "-T", str(upload), g.url("O1234.nc")], timeout=30, check=True)
    assert (g.tmp / "received" / "m0" / "O1234.nc").read_bytes() == data
    outside = subprocess.run([curl, *auth, g.url("%2Fetc/passwd")], capture_output=True,
                             text=True, timeout=30)
    assert outside.returncode != 0 and not outside.stdout
    (forbidden,) = g.records("forbidden")
    assert forbidden.program == "CWD 'etc'"  # curl's CWD / then CWD etc


@pytest.fixture(scope="module")
def certificate(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    if openssl is None:
        pytest.skip("no openssl command")
    folder = tmp_path_factory.mktemp("tls")
    cert, key = folder / "cert.pem", folder / "key.pem"
    subprocess.run([openssl, "req", "-x509", "-newkey", "rsa:2048", "-nodes", "-keyout",
                    str(key), "-out", str(cert), "-days", "2", "-subj", "/CN=127.0.0.1"],
                   check=True, capture_output=True, timeout=60)
    return cert, key


@needs_curl
def test_ftps_required_refuses_plain_logins(serve: Callable[..., Running],
                                            certificate: tuple[Path, Path],
                                            tmp_path: Path) -> None:
    cert, key = certificate
    g = serve(ftp=f'tls_cert = "{cert}"\ntls_key = "{key}"\nrequired = true')
    data = put(g.tmp, "O1234.nc", PROGRAM)
    with pytest.raises(ftplib.error_perm, match="550 SSL/TLS required"):
        g.client()
    context = ssl.create_default_context(cafile=str(cert))
    context.check_hostname = False
    with ftplib.FTP_TLS(context=context, timeout=20) as ftp:
        ftp.connect(g.host, g.port)
        ftp.login("mill0", PASSWORD)
        ftp.prot_p()
        assert fetch(ftp, "O1234.nc") == data
        ftp.storbinary("STOR O7000.nc", io.BytesIO(data))
    auth = ["-sS", "--max-time", "20", "--ssl-reqd", "--cacert", str(cert), "-u",
            f"mill0:{PASSWORD}"]
    got = subprocess.run([curl, *auth, g.url("O1234.nc")], capture_output=True, timeout=30,
                         check=True)
    assert got.stdout == data
    plain = subprocess.run([curl, "-sS", "-u", f"mill0:{PASSWORD}", g.url("O1234.nc")],
                           capture_output=True, timeout=30)
    assert plain.returncode != 0 and not plain.stdout
    assert g.received() == ["O7000.nc"]
    assert [t.result for t in g.journal() if t.direction != "login"] == ["ok"] * 3
    refused = [t for t in g.journal() if t.direction == "login"]
    assert [(t.program, t.result) for t in refused] == [("mill0", "refused")] * 2
    assert "a plain login where FTPS is required" in refused[0].errors[0]


def test_twenty_machines_at_once(serve: Callable[..., Running]) -> None:
    n = 20
    g = serve(machines=n)
    programs = {i: put(g.tmp, f"O{100 + i}.nc", PROGRAM.replace("O1234", f"O{100 + i}")
                       + f"(MACHINE {i})\n" * 2000) for i in range(n)}
    results: dict[int, bytes] = {}
    failures: list[BaseException] = []
    barrier = threading.Barrier(n)

    def machine(i: int) -> None:
        try:
            with g.client(f"mill{i}") as ftp:
                barrier.wait(20)
                got = fetch(ftp, f"O{100 + i}")
                ftp.storbinary(f"STOR O{100 + i}.nc", io.BytesIO(got))
                results[i] = got
        except BaseException as exc:  # noqa: BLE001 - reported below
            failures.append(exc)

    threads = [threading.Thread(target=machine, args=(i,)) for i in range(n)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(50)
    assert not failures, failures[0]
    assert results == programs
    for i in range(n):
        assert g.received(i) == [f"O{100 + i}.nc"]
        assert (g.tmp / "received" / f"m{i}" / f"O{100 + i}.nc").read_bytes() == programs[i]
    assert len(g.records("ok", "send")) == n and len(g.records("ok", "receive")) == n
    assert all(w.status.transfers == 2 for w in g.gateway.ports)


# -- faults -----------------------------------------------------------------------------------


def test_an_upload_over_max_upload_is_refused_with_552(serve: Callable[..., Running]) -> None:
    g = serve(port="max_upload = 1000")
    with g.client() as ftp:
        with pytest.raises(ftplib.error_perm, match="552 O9000.nc: larger than max_upload"):
            ftp.storbinary("STOR O9000.nc", io.BytesIO(b"G1 X1.\n" * 20000))
        ftp.storbinary("STOR O9001.nc", io.BytesIO(b"%\nO9001\nM30\n%\n"))  # still served
    assert g.received() == ["O9001.nc"]
    (failed,) = g.records("failed")
    assert failed.program == "O9000.nc" and "max_upload = 1000" in failed.errors[0]
    assert failed.bytes == 140000  # read to its end, so its client saw the 552, not a reset


def test_a_refused_upload_past_the_drain_is_cut_and_still_answered_552(
        serve: Callable[..., Running], monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(ftp_module, "DRAIN_MOST", 4000)
    g = serve(port="max_upload = 1000")
    with g.client() as ftp:
        ftp.voidcmd("TYPE I")
        conn = ftp.transfercmd("STOR O9000.nc")
        with contextlib.suppress(OSError):  # the gateway stops reading: a reset is allowed
            conn.sendall(b"G1 X1.\n" * 200000)
        conn.close()
        with pytest.raises(ftplib.error_perm, match="552 O9000.nc: larger than max_upload"):
            ftp.voidresp()
    assert until(lambda: len(g.records("failed")) == 1, 10)
    (failed,) = g.records("failed")
    assert 5000 <= failed.bytes < 1400000 and g.received() == []


def _upload_started(g: Running, name: str) -> tuple[ftplib.FTP, socket.socket]:
    ftp = g.client()
    ftp.voidcmd("TYPE I")
    conn = ftp.transfercmd(f"STOR {name}")
    conn.sendall(b"%\nO4444\n" + b"G1 X1. Y2.\n" * 5000)
    assert until(lambda: g.gateway.ports[0].status.bytes_received > 0, 10)
    return ftp, conn


@pytest.mark.parametrize("how", ["reset", "control first"])
def test_a_machine_dropping_mid_upload_leaves_nothing(serve: Callable[..., Running],
                                                     how: str) -> None:
    g = serve()
    ftp, conn = _upload_started(g, "O4444.nc")
    if how == "reset":  # the data connection torn down (RST), as by a machine switched off
        conn.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack("ii", 1, 0))
        conn.close()
    else:  # the machine's control connection goes first, then its data connection
        ftp.sock.shutdown(socket.SHUT_RDWR)
        ftp.close()
        conn.close()
    assert until(lambda: len(g.journal()) == 1, 10)
    (record,) = g.journal()
    assert (record.direction, record.program, record.result) == ("receive", "O4444.nc",
                                                                "interrupted")
    assert record.bytes > 0 and "nothing kept" in record.errors[0]
    assert g.received() == []  # not even the hidden temporary file
    with g.client() as again:  # and the machine is served again
        again.storbinary("STOR O4445.nc", io.BytesIO(b"%\nO4445\nM30\n%\n"))
    assert g.received() == ["O4445.nc"]


def test_a_full_receive_folder_is_refused_and_journalled(serve: Callable[..., Running],
                                                        monkeypatch: pytest.MonkeyPatch
                                                        ) -> None:
    g = serve()
    real = PendingFile.write
    calls = 0

    def full(self: PendingFile, data: bytes) -> None:
        nonlocal calls
        calls += 1
        if calls > 1:
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        real(self, data)

    monkeypatch.setattr(PendingFile, "write", full)
    with g.client() as ftp, pytest.raises(ftplib.error_temp) as caught:
        ftp.storbinary("STOR O6000.nc", io.BytesIO(b"G1 X1.\n" * 50000))
    assert str(caught.value).startswith("452 cannot save in") and "No space left" in str(
        caught.value)
    assert g.received() == []
    (failed,) = g.journal()
    assert (failed.direction, failed.result) == ("receive", "failed")
    assert "No space left on device" in failed.errors[0]
    assert failed.bytes == 350000  # read to its end, so its client saw the 452, not a reset
    assert g.gateway.ports[0].status.result == Result.WRITE_FAILED


def test_sigterm_mid_transfer_keeps_nothing_partial(tmp_path: Path) -> None:
    # 42 MB: more than loopback's socket buffers hold, so the download is under way when the
    # signal comes however fast the service is (unchecked: the check of 42 MB is not the point)
    config = ftp_config(tmp_path, port="check = false")
    big = put(tmp_path, "O8000.nc", "%\nO8000\n" + "G1 X1. Y2. Z3. F100.\n" * 2_000_000
              + "M30\n%\n")
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    service = subprocess.Popen([sys.executable, "-m", "tapegate", "serve", "--config",
                                str(config)], stderr=subprocess.PIPE, text=True, env=env)
    port = int(load_config(config).ftp.port)
    try:
        def connect() -> ftplib.FTP | None:
            try:
                ftp = ftplib.FTP(timeout=20)
                ftp.connect("127.0.0.1", port)
                ftp.login("mill0", PASSWORD)
                return ftp
            except OSError:
                return None

        assert until(lambda: connect() is not None, 20)
        upload = connect()
        download = connect()
        assert upload is not None and download is not None
        upload.voidcmd("TYPE I")
        data_up = upload.transfercmd("STOR O8001.nc")
        data_up.sendall(b"%\nO8001\n" + b"G1 X1.\n" * 10000)
        download.voidcmd("TYPE I")
        data_down = download.transfercmd("RETR O8000.nc")
        assert len(data_down.recv(65536)) > 0  # sending, and held back by the unread socket
        service.send_signal(signal.SIGTERM)
        _, log = service.communicate(timeout=30)
        data_up.close()
        data_down.close()
    finally:
        if service.poll() is None:
            service.kill()
    assert service.returncode == 0, log
    assert "Traceback" not in log
    records = read_journal(tmp_path / "journal.jsonl").transfers
    assert sorted((t.direction, t.program, t.result) for t in records) == [
        ("receive", "O8001.nc", "interrupted"), ("send", "O8000.nc", "interrupted")]
    sent = next(t for t in records if t.direction == "send")
    assert 0 < sent.bytes < len(big) and sent.sha256 == sha(big)
    assert not (tmp_path / "received" / "m0").exists() or not os.listdir(
        tmp_path / "received" / "m0")


# -- attacks ----------------------------------------------------------------------------------


def test_paths_out_of_the_folder_are_refused_and_journalled(serve: Callable[..., Running],
                                                           tmp_path: Path) -> None:
    outside = tmp_path / "secret.nc"
    outside.write_text("%\nO1\n(SECRET)\nM30\n%\n")
    g = serve()
    put(g.tmp, "O1234.nc", PROGRAM)
    (g.tmp / "programs" / "O6666.nc").symlink_to(outside)
    (g.tmp / "programs" / ".hidden.nc").write_text(PROGRAM)
    attempts = ["RETR ../secret.nc", "RETR /etc/passwd", "RETR O6666.nc", "RETR O6666",
                "RETR .hidden.nc", "RETR a\x00b.nc", "RETR " + "O" * 300, "CWD ..",
                "CWD /tmp", "STOR ../O1.nc", "STOR " + "x" * 1000, "NLST ../",
                "LIST /etc/passwd", "SIZE ../secret.nc", "MLST ../secret.nc"]
    with g.client() as ftp:
        for command in attempts:
            ftp.putcmd(command)
            reply = ftp.getmultiline()
            assert reply.startswith("550 "), (command, reply)
        assert ftp.nlst() == ["O1234.nc"]  # links out and hidden files are not shown
        assert ftp.pwd() == "/"
    forbidden = g.records("forbidden")
    assert len(forbidden) == len(attempts)
    assert all(t.errors and t.errors[0] for t in forbidden)
    assert g.received() == []


def test_writes_are_refused_unless_allowed(serve: Callable[..., Running]) -> None:
    g = serve(machines=2, port="")
    put(g.tmp, "O1234.nc", PROGRAM)
    with g.client() as ftp:
        for command in ("DELE O1234.nc", "RNFR O1234.nc", "MKD sub", "SITE CHMOD 777 O1234.nc",
                        "APPE O1234.nc", "STOU"):
            ftp.putcmd(command)
            assert ftp.getmultiline().startswith("550 "), command
    assert (g.tmp / "programs" / "O1234.nc").exists()
    assert len([t for t in g.records("refused") if t.direction == "command"]) == 6
    with g.client() as ftp:  # the other SITE commands are pyftpdlib's, untouched
        assert ftp.sendcmd("SITE HELP").startswith("214")


def test_allow_write_lets_the_machine_delete_and_rename(serve: Callable[..., Running]) -> None:
    g = serve(port="allow_write = true")
    put(g.tmp, "O1234.nc", PROGRAM)
    with g.client() as ftp:
        ftp.rename("O1234.nc", "O1235.nc")
        ftp.delete("O1235.nc")
        with pytest.raises(ftplib.error_perm):
            ftp.delete("../gateway.toml")
    assert not os.listdir(g.tmp / "programs") and (g.tmp / "gateway.toml").exists()
    assert [(t.program, t.result) for t in g.journal()] == [
        ("RNFR O1234.nc", "ok"), ("RNTO O1235.nc", "ok"), ("DELE O1235.nc", "ok"),
        ("DELE '../gateway.toml'", "forbidden")]


def test_commands_before_login_and_anonymous_are_refused(serve: Callable[..., Running]) -> None:
    g = serve()
    put(g.tmp, "O1234.nc", PROGRAM)
    ftp = ftplib.FTP(timeout=20)
    ftp.connect(g.host, g.port)
    for command in ("RETR O1234.nc", "LIST", "STOR x.nc", "CWD /"):
        ftp.putcmd(command)
        assert ftp.getmultiline().startswith("530 "), command
    with pytest.raises(ftplib.error_perm, match="530"):
        ftp.login()  # anonymous
    ftp.close()
    refused = [t for t in g.journal() if t.direction == "login"]
    assert [t.result for t in refused] == ["refused"] * 4 + ["bad password"]
    assert "RETR before login" in refused[0].errors[0]
    assert refused[-1].program == "anonymous"


def test_a_thousand_bad_passwords_ban_the_address_not_the_machine(
        serve: Callable[..., Running]) -> None:
    g = serve(ftp="ban_after = 5\nban_seconds = 600")
    data = put(g.tmp, "O1234.nc", PROGRAM)
    early = ftplib.FTP(timeout=20, source_address=("127.0.0.2", 0))  # open before the ban
    early.connect(g.host, g.port)
    early.sendcmd("USER mill0")
    refused = 0
    for attempt in range(1000):
        if attempt == 500:  # the machine itself, from its own address, is served meanwhile
            with g.client() as machine:
                assert fetch(machine, "O1234.nc") == data
        ftp = ftplib.FTP(timeout=20, source_address=("127.0.0.2", 0))
        try:
            ftp.connect(g.host, g.port)
            ftp.login("mill0", "guess")
        except ftplib.error_temp as exc:  # 421: refused for a while
            assert str(exc).startswith("421 Too many bad passwords")
            refused += 1
        except ftplib.error_perm as exc:  # 530: a bad password, delayed
            assert str(exc).startswith("530")
        except (EOFError, ConnectionError):
            refused += 1  # the ban's reply and the close crossed the login
        finally:
            ftp.close()
    assert refused >= 990
    with pytest.raises(ftplib.error_temp, match="421 Too many bad passwords"):
        early.sendcmd("PASS s3cret-mill")  # even the right one: not checked while banned
    early.close()
    with g.client() as ftp:
        assert fetch(ftp, "O1234.nc") == data
    logins = [t for t in g.journal() if t.direction == "login"]
    assert [t.result for t in logins] == ["bad password"] * 5 + ["banned"]
    assert "127.0.0.2 refused for 600 s after 5 bad passwords" in logins[-1].errors[0]
    assert len(g.records("ok", "send")) == 2


def test_the_status_page_and_modbus_show_an_ftp_transfer(serve: Callable[..., Running]
                                                         ) -> None:
    from dnc.web import JournalTail, snapshot

    g = serve(port="check = false")
    data = put(g.tmp, "O1234.nc", "%\nO1234\n" + "G1 X1. Y2. Z3. F100.\n" * 2_000_000
               + "M30\n%\n")  # 42 MB: more than the socket buffers, so it is seen under way
    worker = g.gateway.ports[0]
    tail = JournalTail(g.tmp / "journal.jsonl")
    with g.client() as ftp:
        ftp.voidcmd("TYPE I")
        conn = ftp.transfercmd("RETR O1234.nc")
        got = bytearray(conn.recv(65536))
        assert until(lambda: worker.status.state == State.SENDING
                     and worker.status.bytes_sent > 0, 10)
        page = snapshot(g.gateway, tail, 20)["ports"][0]
        assert page["state"] == "sending" and page["busy"] and page["file"] == "O1234.nc"
        assert page["program_number"] == 1234 and 0 < page["progress"] < 1
        registers = input_registers(worker.status)  # what Modbus shows for the port
        assert registers[0] == State.SENDING and (registers[5] << 16 | registers[6]) == 1234
        while chunk := conn.recv(1 << 20):
            got += chunk
        conn.close()
        assert ftp.voidresp().startswith("226")
    assert bytes(got) == data
    page = snapshot(g.gateway, tail, 20)
    port = page["ports"][0]
    assert (port["state"], port["result"], port["transfers"]) == ("idle", "ok", 1)
    assert port["bytes_sent"] == port["bytes_total"] == len(data)
    assert [(t["port"], t["direction"], t["result"]) for t in page["transfers"]] == [
        ("m0", "send", "ok")]
    assert input_registers(worker.status)[8] == Result.OK


def test_a_modbus_send_to_an_ftp_machine_is_refused_and_journalled(
        serve: Callable[..., Running]) -> None:
    from dnc.gateway import Job

    g = serve()
    g.gateway.ports[0].submit(Job("1234", "modbus"))
    assert until(lambda: bool(g.journal()), 10)
    (record,) = g.journal()
    assert (record.direction, record.program, record.result) == ("command", "send 1234",
                                                                "refused")
    assert "fetches its own programs" in record.errors[0]


def test_the_documented_ftp_example_loads(tmp_path: Path) -> None:
    doc = (ROOT / "docs" / "gateway.md").read_text()
    blocks = [block.split("```")[0] for block in doc.split("```toml\n")[1:]]
    example = next(block for block in blocks if 'url = "ftp"' in block)
    path = tmp_path / "gateway.toml"
    path.write_text(example)
    for name in ("mill-5", "haas-7"):
        (tmp_path / "programs" / name).mkdir(parents=True)
    config = load_config(path)
    assert [(p.name, p.ftp_user, p.is_ftp) for p in config.ports] == [
        ("mill-5", "mill5", True), ("haas-7", "haas7", True)]
    assert config.ftp.enabled and config.ftp.passive_ports == (60000, 60049)
    assert verify(parse_hash(config.ports[0].ftp_password_hash), "change-me")


def test_an_overlong_command_line_is_refused_and_journalled_once(
        serve: Callable[..., Running]) -> None:
    g = serve()
    put(g.tmp, "O1234.nc", PROGRAM)
    with g.client() as ftp:
        ftp.sock.sendall(b"RETR " + b"O" * 20000 + b"\r\n")
        ftp.putcmd("NOOP")
        replies = []
        while not replies or not replies[-1].startswith("200"):
            replies.append(ftp.getline())
        assert replies[0].startswith("500 Command too long")
        lines: list[str] = []
        ftp.retrlines("LIST -la", lines.append)  # ls options are no name
        assert len(lines) == 1 and lines[0].endswith("O1234.nc")
    (record,) = g.journal()
    assert (record.port, record.direction, record.result) == ("m0", "command", "refused")
    assert "longer than 2048 bytes" in record.errors[0]


def test_an_upload_may_finish_within_stop_grace(serve: Callable[..., Running]) -> None:
    g = serve(gateway="stop_grace = 10")
    ftp, conn = _upload_started(g, "O4446.nc")
    g.server.begin_stop()  # as SIGTERM does: no new connection, the transfer may finish
    with socket.socket() as late:
        late.settimeout(5)
        assert late.connect_ex((g.host, g.port)) != 0 or late.recv(100) == b""
    stopping = threading.Thread(target=g.server.stop)
    stopping.start()
    conn.sendall(b"M30\n%\n")
    conn.close()
    assert ftp.voidresp().startswith("226 Saved as O4446.nc")
    stopping.join(10)
    assert not stopping.is_alive()  # stopped as soon as the transfer was done, not at 10 s
    assert g.received() == ["O4446.nc"]
    assert [(t.program, t.result) for t in g.journal()] == [("O4446.nc", "ok")]
    ftp.close()


def test_serve_says_why_the_ftp_server_cannot_start(tmp_path: Path) -> None:
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        config = ftp_config(tmp_path, listen=port)
        busy = subprocess.run([sys.executable, "-m", "tapegate", "serve", "--config",
                               str(config)], capture_output=True, text=True, env=env, timeout=30)
    assert busy.returncode == 3 and "Traceback" not in busy.stderr
    assert f"ftp.listen 127.0.0.1:{port}: cannot listen: Address already in use" in busy.stderr
    (tmp_path / "cert.pem").write_text("not a certificate\n")
    (tmp_path / "key.pem").write_text("not a key\n")
    config = ftp_config(tmp_path, ftp='tls_cert = "cert.pem"\ntls_key = "key.pem"')
    bad = subprocess.run([sys.executable, "-m", "tapegate", "serve", "--config", str(config)],
                         capture_output=True, text=True, env=env, timeout=30)
    assert bad.returncode == 3 and "Traceback" not in bad.stderr
    assert "ftp.tls_cert / tls_key: cannot use them" in bad.stderr


def test_a_program_that_cannot_be_read_is_refused_with_550(serve: Callable[..., Running],
                                                          monkeypatch: pytest.MonkeyPatch
                                                          ) -> None:
    from dnc import workflow

    def unreadable(path: str, *args: Any, **kw: Any) -> tuple[str, str | None]:
        raise PermissionError(errno.EACCES, os.strerror(errno.EACCES), path)

    g = serve()
    put(g.tmp, "O1234.nc", PROGRAM)
    monkeypatch.setattr(workflow, "checked", unreadable)  # as for a file of mode 000
    with g.client() as ftp, pytest.raises(ftplib.error_perm,
                                          match="550 O1234.nc: cannot read it: Permission"):
        fetch(ftp, "O1234")
    (failed,) = g.journal()
    assert (failed.direction, failed.program, failed.result) == ("send", "O1234.nc", "failed")


def test_an_ipv6_loopback_listen_address(serve: Callable[..., Running], tmp_path: Path) -> None:
    try:
        with socket.socket(socket.AF_INET6) as probe:
            probe.bind(("::1", 0))
            port = probe.getsockname()[1]
    except OSError:
        pytest.skip("no IPv6 loopback here")
    g = serve(ftp_config(tmp_path, host="[::1]", listen=port))
    data = put(g.tmp, "O1234.nc", PROGRAM)
    assert g.host == "::1"
    with g.client() as ftp:  # EPSV: the data connection over IPv6 too
        assert fetch(ftp, "O1234.nc") == data
        ftp.storbinary("STOR O1234.nc", io.BytesIO(data))
    assert g.received() == ["O1234.nc"]


def test_passive_data_connections_use_the_configured_ports(serve: Callable[..., Running]
                                                          ) -> None:
    first = min(free_port(), 65500)
    g = serve(ftp=f'passive_ports = "{first}-{first + 9}"')
    data = put(g.tmp, "O1234.nc", PROGRAM)
    with g.client() as ftp:
        host, port = ftp.makepasv()
        assert host == "127.0.0.1" and first <= port <= first + 9
        assert fetch(ftp, "O1234.nc") == data


def test_a_download_with_a_doubtful_comment_is_sent_and_its_warning_logged(
        serve: Callable[..., Running], caplog: pytest.LogCaptureFixture) -> None:
    """TG136 (a '(' inside a Fanuc comment, read once) does not stop a download, but the log
    says it, with its line and column, as `send` prints it before the first byte."""
    g = serve()
    data = put(g.tmp, "O2100.nc", "%\nO2100\nG21 G90\nG0 X1. (VNMG 332(1))\nM30\n%\n")
    with g.client() as ftp:
        ftp.voidcmd("TYPE I")
        assert fetch(ftp, "O2100.nc") == data
    warned = [r.getMessage() for r in caplog.records if "TG136" in r.getMessage()]
    assert len(warned) == 1 and "O2100.nc:4:17: warning TG136" in warned[0], warned
