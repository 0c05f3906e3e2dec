"""The gateway's FTP server: machines on the network fetch and store their programs
(``[ftp]`` and the ``[[port]]`` tables with ``url = "ftp"``; docs/gateway.md).

The protocol is pyftpdlib's (RFC 959, 2228 for AUTH TLS, 3659 for MLSD); this module decides what
a machine may do and routes its transfers through the serial ports' code:

* **Login.** One user per machine (:class:`Machines`, passwords as :mod:`dnc.passwords` hashes),
  no anonymous login. A bad password's reply waits ``login_delay`` seconds, doubling with each
  failure from the address; after ``ban_after`` of them the address is refused for
  ``ban_seconds`` (:class:`LoginGuard`). Every bad password, ban and command before login is
  journalled (direction ``login``).
* **One folder.** A machine sees its program folder and nothing else: an argument names the
  folder (``/``, ``.``) or one entry in it (:func:`ftp_name`); ``..``, other absolute paths,
  NUL, names longer than 255 bytes, hidden names, and symbolic links that leave the folder are
  refused with 550 and journalled ``forbidden``.
* **A download (RETR) is a send**: the name is looked up by the remote-request rules
  (:func:`dnc.requests.find_program`: case ignored, ``O1234`` is ``O1234.nc``), converted and
  checked by :func:`dnc.workflow.checked` as ``tapegate send`` and the serial ports do (a check
  error: 550 with the first errors, journalled ``refused``), then sent and journalled with its
  bytes and SHA-256.
* **An upload (STOR) is a receive**: written into a hidden temporary file in the receive folder
  (:class:`formats.files.PendingFile`), named only when complete, never overwriting
  (``O1234.1.nc``), compared with the program folder's copy (:func:`dnc.compare.compare_programs`)
  and journalled ``ok``, ``differs``, ``failed`` or ``interrupted``. Nothing partial is kept: a
  dropped connection, a full disk, ``max_upload`` (552) or the service stopping leaves no file.
* **Status.** Each transfer shows in its port's :class:`dnc.gateway.PortStatus` (status page,
  Modbus) as a serial transfer does.

Each connection is served in its own thread (pyftpdlib's ``ThreadedFTPServer``): a check or a
conversion of a large program holds up only the machine that asked for it.
"""

from __future__ import annotations

import contextlib
import errno
import hashlib
import logging
import os
import re
import socket
import sys
import threading
import time
from pathlib import Path, PurePosixPath
from typing import TYPE_CHECKING, Any

from pyftpdlib.authorizers import AuthenticationFailed
from pyftpdlib.filesystems import AbstractedFS
from pyftpdlib.handlers import DTPHandler, FTPHandler
from pyftpdlib.handlers.ftp.producers import FileProducer
from pyftpdlib.ioloop import IOLoop
from pyftpdlib.servers import ThreadedFTPServer

from dnc import workflow
from dnc.gateway import Gateway, PortWorker, Result, State, _numeric
from dnc.gateway_config import FtpConfig
from dnc.journal import Transfer, now_utc
from dnc.passwords import Hash, hash_password, parse_hash, verify
from dnc.requests import Forbidden, NotFound, find_program
from formats.errors import TapegateError
from formats.files import PendingFile

log = logging.getLogger("tapegate.ftp")

NAME_MAX = 255  # bytes of a file name (Linux NAME_MAX)
BEFORE_LOGIN_MAX = 10  # commands before login journalled on one connection; then it is closed
LONGEST_DELAY = 30.0  # a bad password's reply never waits longer
# what a machine may do besides reading and storing, with allow_write = true
_WRITES = {"DELE", "RNFR", "RNTO", "MKD", "XMKD", "RMD", "XRMD"}
_NEVER = {"SITE CHMOD", "MFMT", "STOU", "APPE"}  # no machine needs them
# commands whose argument names something in the folder
_NAMED = {"RETR", "STOR", "SIZE", "MDTM", "MLST", "LIST", "NLST", "MLSD", "CWD", "XCWD", "STAT",
          *_WRITES}
# an argument of LIST that is an option of ls, not a name (clients still send them)
_LS_OPTIONS = re.compile(r"^(?:-[A-Za-z]+\s*)+")


def ftp_name(arg: str) -> str:
    """The one entry of the machine's folder an FTP argument names, ``""`` for the folder itself.

    ``/`` is the folder (the FTP root a machine sees), so ``/O1234.nc`` and ``O1234.nc`` name the
    same program. Raises :class:`~dnc.requests.Forbidden` for anything else: ``..``, any other
    absolute path (``/etc/passwd``, ``C:\\...``), a path into a subfolder, NUL, a name longer than
    255 bytes, a hidden name (a file being received is one)."""
    if "\x00" in arg:
        raise Forbidden(f"{_shown(arg)}: a name with NUL in it")
    if len(arg.encode("utf-8", "surrogateescape")) > NAME_MAX:
        raise Forbidden(f"{_shown(arg)}: a name of {len(arg.encode('utf-8', 'replace'))} "
                        f"bytes; at most {NAME_MAX}")
    text = arg.replace("\\", "/")
    if re.match(r"[A-Za-z]:", text):
        raise Forbidden(f"{_shown(arg)}: an absolute path, not a name in the machine's folder")
    if text in ("", ".", "/", "/.", "./"):
        return ""
    text = text.removeprefix("/").removesuffix("/")
    parts = PurePosixPath(text).parts
    if ".." in parts:
        raise Forbidden(f"{_shown(arg)}: '..' would leave the machine's folder")
    if text.startswith("/") or len(parts) != 1:
        raise Forbidden(f"{_shown(arg)}: a path, not a name in the machine's folder")
    if parts[0].startswith("."):
        raise Forbidden(f"{_shown(arg)}: hidden names are not programs")
    return parts[0]


def _shown(text: str) -> str:
    """A name as messages and replies show it: printable, one line, at most 80 characters."""
    clean = "".join(c if c.isprintable() else f"\\x{ord(c):02x}" for c in text)
    return repr(clean[:77] + "..." if len(clean) > 80 else clean)


class LoginGuard:
    """Bad passwords per address: how long each reply waits, and when the address is banned.
    The clock is passed in."""

    def __init__(self, delay: float, ban_after: int, ban_seconds: float):
        self.delay, self.ban_after, self.ban_seconds = delay, ban_after, ban_seconds
        self._lock = threading.Lock()
        self._failures: dict[str, list[float]] = {}
        self._banned: dict[str, float] = {}  # address: until

    def banned(self, address: str, now: float) -> float:
        """Seconds the address is still refused (0: it is not)."""
        with self._lock:
            until = self._banned.get(address, 0.0)
            if until and until <= now:
                del self._banned[address]
            return max(0.0, until - now)

    def failed(self, address: str, now: float) -> tuple[int, float, bool]:
        """A bad password from ``address``: the failures counted (those within ``ban_seconds``),
        how long the reply waits, and whether the address is now banned."""
        with self._lock:
            recent = [t for t in self._failures.get(address, []) if now - t < self.ban_seconds]
            recent.append(now)
            if len(recent) >= self.ban_after:
                self._failures.pop(address, None)
                self._banned[address] = now + self.ban_seconds
                return len(recent), 0.0, True
            self._failures[address] = recent
            return len(recent), min(self.delay * 2 ** (len(recent) - 1), LONGEST_DELAY), False

    def succeeded(self, address: str) -> None:
        with self._lock:
            self._failures.pop(address, None)


class Machines:
    """pyftpdlib's authorizer: one user per FTP machine, checked against its scrypt hash."""

    def __init__(self, workers: list[PortWorker]):
        self.workers = {w.config.ftp_user.lower(): w for w in workers}
        self.hashes: dict[str, Hash] = {user: parse_hash(w.config.ftp_password_hash)
                                        for user, w in self.workers.items()}
        # an unknown user costs as much as a known one: the time tells no names
        self._decoy = parse_hash(hash_password("decoy"))

    def worker(self, username: str) -> PortWorker:
        return self.workers[username.lower()]

    def validate_authentication(self, username: str, password: str, handler: Any) -> None:
        stored = self.hashes.get(username.lower())
        if not verify(stored or self._decoy, password) or stored is None:
            raise AuthenticationFailed("Authentication failed.")

    def get_home_dir(self, username: str) -> str:
        return str(self.worker(username).config.programs)

    def has_perm(self, username: str, perm: str, path: str | None = None) -> bool:
        if perm in "elrw":  # list, read; a store goes to the receive folder
            return True
        return perm in "adfm" and self.worker(username).config.allow_write

    def get_perms(self, username: str) -> str:
        return "elrw" + ("adfm" if self.worker(username).config.allow_write else "")

    def get_msg_login(self, username: str) -> str:
        return f"Logged in: the programs of {self.worker(username).config.name}."

    def get_msg_quit(self, username: str) -> str:
        return "Goodbye."

    def impersonate_user(self, username: str, password: str) -> None:
        pass

    def terminate_impersonation(self, username: str) -> None:
        pass


class MachineFolder(AbstractedFS):  # type: ignore[misc]
    """The machine's folder as its listings show it: no hidden files (uploads being written),
    no links that leave it."""

    def listdir(self, path: str) -> list[str]:
        root = os.path.realpath(self.root)
        shown = []
        for entry in os.listdir(path):
            real = os.path.realpath(os.path.join(path, entry))
            if not entry.startswith(".") and (real == root or real.startswith(root + os.sep)):
                shown.append(entry)
        return shown

    listdirinfo = listdir


class _Transfer:
    """A download or an upload under way, finished once when its data connection closes."""

    def __init__(self, session: _Session, name: str, direction: str):
        self.session, self.name, self.direction = session, name, direction
        self.started = now_utc()
        self.worker = session.worker
        self.closed = self.ended = False
        session.service.transfers_begun()

    def end(self, complete: bool, transmitted: int) -> str | None:
        """Journal the end, once; the reply to give instead of pyftpdlib's (``None``: keep
        it)."""
        if self.ended:
            return None
        self.ended = True
        try:
            return self.finish(complete, transmitted)
        finally:
            self.session.service.transfers_ended()

    def finish(self, complete: bool, transmitted: int) -> str | None:
        raise NotImplementedError

    def close(self) -> None:
        """Closed before its data connection came (the machine went): journalled so."""
        self.end(False, 0)
        self.closed = True


class Download(_Transfer):
    """A program on its way to the machine (a send): the file, the bytes and SHA-256 of what is
    sent (the converted copy, where the port converts)."""

    def __init__(self, session: _Session, name: str, file: Any, size: int, digest: str,
                 blocks: int):
        super().__init__(session, name, "send")
        self.file, self.size, self.digest, self.blocks = file, size, digest, blocks
        status = self.worker.status
        status.program = _numeric(name) or _numeric(Path(name).stem)
        status.file, status.bytes_total, status.bytes_sent, status.line = name, size, 0, 0
        self.worker._set(State.SENDING, f"{name}: sending by FTP")

    def finish(self, complete: bool, transmitted: int) -> str | None:
        self.worker.status.bytes_sent = transmitted
        if complete and transmitted >= self.size:
            self.session.finish("send", self.name, Result.OK, self.started, size=transmitted,
                                blocks=self.blocks, sha256=self.digest)
            log.info("%s: %s sent by FTP (%d bytes)", self.worker.config.name, self.name,
                     transmitted)
            return None
        why = self.session.service.why_stopped()
        error = f"{transmitted} of {self.size} bytes sent: " + (
            "the service stopped" if why else "the machine closed the connection")
        self.session.finish("send", self.name, Result.ABORTED if why else Result.FAILED,
                            self.started, size=transmitted, errors=[error], sha256=self.digest,
                            words=why or "failed")
        log.warning("%s: %s: %s", self.worker.config.name, self.name, error)
        return None


DRAIN_MOST = 16 * 1024 * 1024
"""Bytes of a refused upload (past ``max_upload``, or after its folder failed) read and
dropped, so that its client gets the 552 or 452 on the control connection rather than a reset
data connection."""


class Upload(_Transfer):
    """A program on its way from the machine (a receive): written to a hidden temporary file in
    the receive folder and named only when it is complete."""

    def __init__(self, session: _Session, name: str, pending: PendingFile):
        super().__init__(session, name, "receive")
        self.pending = pending
        self.limit = self.worker.config.max_upload
        self.sha = hashlib.sha256()
        self.size = 0
        self.lines = 0
        self.too_large = False
        self.dropped = 0
        self.error: OSError | None = None
        status = self.worker.status
        status.program = _numeric(Path(name).stem)
        status.bytes_received = 0
        self.worker._set(State.RECEIVING, f"{name}: receiving by FTP")

    def write(self, data: bytes) -> None:
        if self.too_large or self.error is not None or self.size + len(data) > self.limit:
            self.too_large = self.error is None
            self._drop(data)
            return
        try:
            self.pending.write(data)
        except OSError as exc:  # a full disk: nothing is kept, the rest read and dropped
            self.error = exc
            self._drop(data)
            return
        self.sha.update(data)
        self.size += len(data)
        self.lines += data.count(b"\n")
        self.worker.status.bytes_received = self.size

    def _drop(self, data: bytes) -> None:
        """A refused upload (too large, or its folder cannot take it) is read on and dropped
        until the machine's client ends it: a data connection closed with bytes unread is
        reset, and the client would see the reset instead of the 552 or 452 that says why.
        Past DRAIN_MOST the link is cut."""
        self.size += len(data)
        self.dropped += len(data)
        self.worker.status.bytes_received = self.size
        if self.dropped > DRAIN_MOST:
            if self.error is not None:
                raise self.error
            raise OSError(errno.EFBIG, f"larger than max_upload ({self.limit} bytes)")

    def finish(self, complete: bool, transmitted: int) -> str | None:
        session, cfg = self.session, self.worker.config
        why = session.service.why_stopped()
        if self.too_large or self.error is not None or not complete or why:
            self.pending.discard()
            if self.too_large:
                error = f"larger than max_upload = {self.limit} bytes: refused, nothing kept"
                reply = f"552 {self.name}: {error}."
            elif self.error is not None:
                error = f"cannot save in {cfg.receive}: {self.error.strerror or self.error}"
                reply = f"452 {error}; nothing kept."
            else:
                error = (f"{self.size} bytes received: " + ("the service stopped" if why else
                         "the machine dropped the connection") + "; nothing kept")
                reply = None
            result = (Result.FAILED if self.too_large else Result.WRITE_FAILED
                      if self.error is not None else Result.ABORTED)
            words = "interrupted" if result == Result.ABORTED else "failed"
            session.finish("receive", self.name, result, self.started, size=self.size,
                           errors=[error], sha256=self.sha.hexdigest(), words=words)
            log.warning("%s: upload %s: %s", cfg.name, self.name, error)
            return reply
        try:
            path = self.pending.commit(cfg.receive / self.name)
        except OSError as exc:  # fsync or link on a full disk: discarded by commit
            error = f"cannot save in {cfg.receive}: {exc.strerror or exc}"
            session.finish("receive", self.name, Result.WRITE_FAILED, self.started,
                           size=self.size, errors=[error], sha256=self.sha.hexdigest(),
                           words="failed")
            return f"452 {error}; nothing kept."
        errors = session.worker._compare(path, Path(self.name).stem) if cfg.compare else []
        result = Result.DIFFERS if errors else Result.OK
        session.finish("receive", path.name, result, self.started, size=self.size,
                       blocks=self.lines, errors=errors, sha256=self.sha.hexdigest())
        log.info("%s: received %s by FTP (%d bytes)%s", cfg.name, path.name, self.size,
                 f"; differs from the program folder's copy ({len(errors)})" if errors else "")
        if errors:
            return (f"226 Saved as {path.name}; it differs from the program folder's copy: "
                    f"{_one_line(errors[0])}")
        return f"226 Saved as {path.name}."


def _one_line(text: str, most: int = 200) -> str:
    flat = " ".join(text.split())
    return flat if len(flat) <= most else flat[:most - 3] + "..."


class _DataChannel:
    """Mixed into pyftpdlib's data connection: progress into the port's status, and the end
    of a transfer journalled before the reply goes out (so a 226 means "saved and journalled")."""

    cmd_channel: Any
    file_obj: Any
    transfer_finished: bool
    tot_bytes_sent: int
    _closed: bool
    _resp: tuple[str, Any] | None
    broken: OSError | None = None  # the connection was reset, not closed

    def send(self, data: bytes) -> int:
        sent: int = super().send(data)  # type: ignore[misc]
        self.cmd_channel.worker.status.bytes_sent = self.tot_bytes_sent
        return sent

    def handle_close(self) -> None:
        # pyftpdlib reads a connection reset by the peer as its end (and an upload's end as
        # its completion): it calls this from inside the ``except`` of its recv(), so the
        # error is still there to be seen
        exc = sys.exc_info()[1]
        if isinstance(exc, OSError):
            self.broken = exc
        super().handle_close()  # type: ignore[misc]

    def initiate_sendfile(self) -> None:
        super().initiate_sendfile()  # type: ignore[misc]
        self.cmd_channel.worker.status.bytes_sent = self.tot_bytes_sent

    def close(self) -> None:
        transfer = self.file_obj
        if not self._closed and isinstance(transfer, _Transfer | _DownloadFile):
            complete = self.transfer_finished and self.broken is None
            if complete and isinstance(transfer, Upload):
                complete = self.cmd_channel.control_open()
            transmitted = self.get_transmitted_bytes()  # type: ignore[attr-defined]
            reply = transfer.end(complete, transmitted)
            if reply is not None:
                self._resp = (reply, logging.getLogger("pyftpdlib").info)
        super().close()  # type: ignore[misc]


class _Session:
    """Mixed into pyftpdlib's control connection (plain or TLS): one machine's login."""

    service: FtpServer
    authorizer: Machines
    username: str
    authenticated: bool
    remote_ip: str
    proto_cmds: dict[str, dict[str, Any]]
    fs: Any
    _current_type: str
    _restart_position: int
    _last_response: str
    data_channel: Any
    _in_dtp_queue: Any
    socket: socket.socket
    before_login = 0
    asked = ""
    too_long = False

    if TYPE_CHECKING:  # pyftpdlib's, which has no annotations
        def respond(self, resp: str, logfun: Any = None) -> None: ...
        def push(self, data: str) -> None: ...
        def close_when_done(self) -> None: ...
        def push_dtp_data(self, data: Any, isproducer: bool = False, file: Any = None,
                          cmd: str | None = None) -> None: ...

    @property
    def worker(self) -> PortWorker:
        return self.authorizer.worker(self.username)

    # -- what a machine may do ---------------------------------------------------------------

    def pre_process_command(self, line: str, cmd: str, arg: str) -> None:
        known = self.proto_cmds.get(cmd)
        if (cmd == "USER" and self.service.config.required
                and not getattr(self, "_ssl_established", False)):
            self.journal_login(arg, "refused", "a plain login where FTPS is required")
        if not self.authenticated:
            if known is not None and (known["auth"] or (cmd == "STAT" and arg)):
                self.before_login += 1
                self.journal_login(cmd, "refused", f"{cmd} before login")
                if self.before_login >= BEFORE_LOGIN_MAX:
                    self.respond("421 Log in with USER and PASS first; closing.")
                    self.close_when_done()
                    return
            super().pre_process_command(line, cmd, arg)  # type: ignore[misc]
            return
        site = f"SITE {arg.split(' ')[0].upper()}" if cmd == "SITE" and arg else cmd
        if site in _NEVER or (cmd == "STOR" and self._restart_position):
            what = "resuming an upload" if cmd == "STOR" else site
            self._refuse(site, arg, f"{what} is not offered: programs are received whole, "
                         "under their own names")
            return
        if cmd in _WRITES and not self.worker.config.allow_write:
            self._refuse(cmd, arg, f"{cmd} is not allowed on this machine (allow_write = false)")
            return
        if cmd in _NAMED:
            try:
                arg = self._named(cmd, arg)
            except Forbidden as exc:
                self.respond(f"550 {exc.message}.")
                self.finish("command" if cmd != "RETR" else "send", f"{cmd} {_shown(arg)}",
                            Result.FORBIDDEN, now_utc(), errors=[exc.message])
                return
            except NotFound as exc:
                self.respond(f"550 {exc.message}.")
                if cmd == "RETR":
                    self.finish("send", _shown(arg).strip("'\""), Result.NOT_FOUND, now_utc(),
                                errors=[exc.message])
                return
        super().pre_process_command(line, cmd, arg)  # type: ignore[misc]

    def _named(self, cmd: str, arg: str) -> str:
        """The argument confined to the folder and, for a program read, looked up by the
        remote-request rules; what pyftpdlib is given instead of ``arg``."""
        if cmd in ("LIST", "NLST", "STAT"):  # ls options some clients still send: dropped
            arg = _LS_OPTIONS.sub("", arg).strip()
        name = ftp_name(arg)
        cfg = self.worker.config
        if cmd in ("CWD", "XCWD"):
            if name:
                raise Forbidden(f"{_shown(arg)}: a machine sees one folder, its own")
            return "/"
        if not name:
            if cmd in ("RETR", "STOR", "SIZE", "MDTM") or cmd in _WRITES:
                raise Forbidden(f"{cmd} needs a program name")
            return "/"
        self.asked = name
        if cmd in ("RETR", "SIZE", "MDTM", "MLST") or (cmd in ("LIST", "NLST") and name):
            found = find_program(cfg.programs, name, self.service.gateway.config.requests
                                 .extensions)
            return "/" + found.relative_to(Path(os.path.realpath(cfg.programs))).as_posix()
        return "/" + name

    def _refuse(self, cmd: str, arg: str, why: str) -> None:
        self.respond(f"550 {why}.")
        self.finish("command", f"{cmd} {_shown(arg)}" if arg else cmd, Result.FORBIDDEN,
                    now_utc(), errors=[why], words="refused")

    def process_command(self, cmd: str, *args: Any, **kwargs: Any) -> None:
        started = now_utc()
        super().process_command(cmd, *args, **kwargs)  # type: ignore[misc]
        if cmd in _WRITES and self._last_response:  # allow_write: journal what was done
            code = self._last_response[:3]
            self.finish("command", f"{cmd} {self.asked}", Result.OK if code[0] in "23"
                        else Result.FAILED, started,
                        errors=[] if code[0] in "23" else [self._last_response[4:]],
                        words="ok" if code[0] in "23" else "failed")

    def collect_incoming_data(self, data: bytes) -> None:
        before = getattr(self, "_in_buffer_len", 0)
        super().collect_incoming_data(data)  # type: ignore[misc]
        if before + len(data) > 2048 and not self.too_long:  # pyftpdlib answers 500
            self.too_long = True  # journalled once per connection: no flood of records
            self.journal_login("command", "refused", "a command line longer than 2048 bytes",
                               direction="command" if self.authenticated else "login")

    # -- RETR: a send ------------------------------------------------------------------------

    def ftp_SIZE(self, path: str) -> None:
        if self.worker.config.convert:
            self.respond("550 The size is known once the program is converted, on RETR.")
            return
        super().ftp_SIZE(path)  # type: ignore[misc]

    def ftp_RETR(self, file: str) -> str | None:
        cfg = self.worker.config
        started = now_utc()
        name = os.path.basename(file)
        rest = self._restart_position
        self._restart_position = 0
        try:
            path, temporary = workflow.checked(file, cfg.profile, name=name,
                                               check_first=cfg.check, convert=cfg.convert,
                                               on_event=_warned)
        except workflow.Refused as exc:
            first = [" ".join(str(f).split()) for f in exc.findings[:5]]
            self.push(f"550-{name}: {exc.message}; not sent:\r\n")
            for line in first[:-1]:
                self.push(f" {line[:300]}\r\n")
            self.respond(f"550 {first[-1][:300]}" if first else "550 not sent.")
            self.finish("send", name, Result.REFUSED, started,
                        errors=[str(f) for f in exc.findings[:20]])
            log.warning("%s: %s: %s; not sent", cfg.name, name, exc.message)
            return None
        except TapegateError as exc:  # a conversion that cannot be done exactly, say
            self.respond(f"550 {name}: {_one_line(exc.message)}; not sent.")
            self.finish("send", name, Result.REFUSED, started, errors=[str(exc)])
            return None
        except OSError as exc:  # unreadable (permissions), or gone since it was found
            self.respond(f"550 {name}: cannot read it: {exc.strerror or exc}.")
            self.finish("send", name, Result.FAILED, started,
                        errors=[f"cannot read {name}: {exc.strerror or exc}"])
            return None
        try:
            digest, blocks = _digest(path)
            fd = open(path, "rb")  # noqa: SIM115 - closed by the data connection
        except OSError as exc:
            self.respond(f"550 {name}: {exc.strerror or exc}.")
            self.finish("send", name, Result.FAILED, started, errors=[str(exc)])
            return None
        finally:
            if temporary:
                os.unlink(temporary)  # the open file stays readable
        size = os.fstat(fd.fileno()).st_size
        if rest:
            if rest > size:
                fd.close()
                self.respond(f"554 REST position ({rest}) beyond the program ({size} bytes).")
                return None
            fd.seek(rest)
        download = Download(self, name, _Named(fd, name), size - rest, digest, blocks)
        producer = FileProducer(download.file, self._current_type)
        self.push_dtp_data(producer, isproducer=True, file=_DownloadFile(download), cmd="RETR")
        return file

    # -- STOR: a receive ---------------------------------------------------------------------

    def ftp_STOR(self, file: str, mode: str = "w") -> str | None:
        cfg = self.worker.config
        name = self.asked if Path(self.asked).suffix else f"{self.asked}.nc"
        try:
            pending = PendingFile(cfg.receive, "ftp", create=True)
        except (OSError, TapegateError) as exc:
            why = exc.message if isinstance(exc, TapegateError) else (exc.strerror or str(exc))
            self.respond(f"452 {why}.")
            self.finish("receive", name, Result.WRITE_FAILED, now_utc(), errors=[why],
                        words="failed")
            return None
        upload = Upload(self, name, pending)
        if self.data_channel is not None:
            self.respond("125 Data connection already open. Transfer starting.")
            self.data_channel.file_obj = upload
            self.data_channel.enable_receiving(self._current_type, "STOR")
        else:
            self.respond("150 File status okay. About to open data connection.")
            self._in_dtp_queue = (upload, "STOR")
        return file

    # -- logins ------------------------------------------------------------------------------

    def ftp_PASS(self, line: str) -> None:
        """A password from a banned address is not even checked: a connection opened before
        the ban (many at once, say) is refused as a new one would be."""
        left = self.service.guard.banned(self.remote_ip, time.monotonic())
        if left and not self.authenticated:
            self.respond(f"421 Too many bad passwords from {self.remote_ip}: refused for "
                         f"{left:.0f} s more.")
            self.close_when_done()
            return
        super().ftp_PASS(line)  # type: ignore[misc]

    def handle_auth_failed(self, msg: str, password: str) -> None:
        count, delay, banned = self.service.guard.failed(self.remote_ip, time.monotonic())
        user = self.username
        self.journal_login(user, "bad password", f"bad password for user {_shown(user)}, "
                           f"{count} from {self.remote_ip}")
        if banned:
            ban = self.service.config.ban_seconds
            self.journal_login(user, "banned", f"{self.remote_ip} refused for {ban:g} s "
                               f"after {count} bad passwords")
            log.warning("FTP: %d bad passwords from %s: refused for %g s", count,
                        self.remote_ip, ban)
            self.respond(f"421 Too many bad passwords: {self.remote_ip} is refused for "
                         f"{ban:g} s.")
            self.close_when_done()
            return
        self.auth_failed_timeout = delay
        super().handle_auth_failed(msg, password)  # type: ignore[misc]

    def log_exception(self, instance: Any) -> None:
        """pyftpdlib's report of an exception in a connection: a connection the machine reset
        or broke is no fault of the gateway's and gets one line; anything else is logged whole
        (a bug)."""
        exc = sys.exc_info()[1]
        if isinstance(exc, OSError):
            log.warning("FTP %s: connection lost: %s", self.remote_ip,
                        exc.strerror or type(exc).__name__)
        else:
            log.error("FTP %s: unexpected %s in %r", self.remote_ip, type(exc).__name__,
                      instance, exc_info=True)

    def on_login(self, username: str) -> None:
        self.service.guard.succeeded(self.remote_ip)
        log.info("%s: logged in by FTP from %s", self.worker.config.name, self.remote_ip)

    def journal_login(self, program: str, result: str, error: str, *,
                      direction: str = "login") -> None:
        """A login refused, or a command before login: not a transfer of any port's."""
        port = "ftp"
        with contextlib.suppress(KeyError):
            port = self.authorizer.worker(self.username or program).config.name
        now = now_utc()
        self.service.gateway.record(Transfer(port, direction, _shown(program).strip("'\""), 0, 0,
                                             now, now, result, [f"from {self.remote_ip}: "
                                                                f"{error}"]))

    # -- journal, status -----------------------------------------------------------------------

    def finish(self, direction: str, program: str, result: Result, started: str, *,
               size: int = 0, blocks: int = 0, errors: list[str] | None = None,
               sha256: str = "", words: str | None = None) -> None:
        """Journal a transfer of this machine's port and show its end in the port's status."""
        worker = self.worker
        worker._finish(direction, program, result, started, size=size, blocks=blocks,
                       errors=errors, sha256=sha256, words=words)
        worker._set(State.IDLE, worker.status.message)

    def control_open(self) -> bool:
        """Whether the machine's control connection is still there: an upload ends when the
        data connection closes (RFC 959 stream mode), so one whose machine has gone at the same
        moment is no complete program."""
        try:  # the TCP socket itself, under TLS too (a peek at the encrypted bytes)
            raw = socket.socket(fileno=os.dup(self.socket.fileno()))
        except OSError:
            return False
        try:
            data = raw.recv(1, socket.MSG_PEEK | socket.MSG_DONTWAIT)
        except (BlockingIOError, InterruptedError):
            return True
        except OSError:
            return False
        finally:
            raw.close()
        return data != b""


def _digest(path: str) -> tuple[str, int]:
    sha = hashlib.sha256()
    lines = 0
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            sha.update(chunk)
            lines += chunk.count(b"\n")
    return sha.hexdigest(), lines


class _Named:
    """An open file under the name the journal gives it."""

    def __init__(self, file: Any, name: str):
        self.file, self.name = file, name

    def __getattr__(self, attr: str) -> Any:
        return getattr(self.file, attr)


class _DownloadFile:
    """What the data connection holds for a download: the transfer (journalled when it closes)
    with the file's own interface, so pyftpdlib can send it with sendfile()."""

    def __init__(self, download: Download):
        self.download = download
        self.name = download.name
        self.closed = False

    def fileno(self) -> int:
        return int(self.download.file.fileno())

    def read(self, size: int = -1) -> bytes:
        return bytes(self.download.file.read(size))

    def tell(self) -> int:
        return int(self.download.file.tell())

    def end(self, complete: bool, transmitted: int) -> str | None:
        return self.download.end(complete, transmitted)

    def close(self) -> None:
        self.download.close()
        self.closed = True
        self.download.file.close()


class _Server(ThreadedFTPServer):  # type: ignore[misc]
    """A threaded server whose stop and lock are its own (pyftpdlib shares them between all
    servers of a process)."""

    poll_timeout = 0.2  # how soon a connection's thread sees the service stopping

    def __init__(self, address: tuple[str, int], handler: type[Any], guard: LoginGuard):
        self._exit = threading.Event()
        self._lock = threading.Lock()
        self.guard = guard
        super().__init__(address, handler, ioloop=IOLoop())

    def handle_accepted(self, sock: socket.socket, addr: tuple[str, int]) -> None:
        """A banned address is told so and closed before any handler exists for it."""
        left = self.guard.banned(addr[0], time.monotonic())
        if not left:
            super().handle_accepted(sock, addr)
            return
        with contextlib.suppress(OSError):
            sock.send(f"421 Too many bad passwords from {addr[0]}: refused for {left:.0f} s "
                      "more.\r\n".encode("ascii"))
        sock.close()


class FtpServer:
    """The FTP server of a :class:`~dnc.gateway.Gateway`, in its own threads beside the ports,
    the Modbus interface and the status page."""

    def __init__(self, gateway: Gateway, config: FtpConfig):
        self.gateway, self.config = gateway, config
        self.guard = LoginGuard(config.login_delay, config.ban_after, config.ban_seconds)
        self._server: _Server | None = None
        self._thread: threading.Thread | None = None
        self._stopping = threading.Event()
        self._stopped = threading.Event()
        self._deaf = threading.Event()  # the listening socket is closed
        self._deadline = 0.0
        self._active = 0
        self._active_lock = threading.Condition()

    @property
    def address(self) -> tuple[str, int]:
        assert self._server is not None
        host, port = self._server.address[:2]
        return str(host), int(port)

    def start(self) -> None:
        """Listen and serve; a listening address that cannot be had is a
        :class:`~formats.errors.TapegateError`."""
        workers = [w for w in self.gateway.ports if w.config.is_ftp]
        handler = _handler_class(self, Machines(workers))
        try:
            if handler.__name__ == "TlsMachineSession":
                handler.get_ssl_context()  # a certificate or key that cannot be read: now
            self._server = _Server((self.config.host, self.config.port), handler, self.guard)
        except OSError as exc:
            inner = exc.args[0] if exc.args and isinstance(exc.args[0], OSError) else exc
            raise TapegateError(f"ftp.listen {self.config.address}: cannot listen: "
                                f"{inner.strerror or inner}",
                                code="listen-failed") from None  # pyftpdlib wraps it
        except Exception as exc:  # noqa: BLE001 - OpenSSL's own errors: a bad cert or key
            raise TapegateError(f"ftp.tls_cert / tls_key: cannot use them: "
                                f"{type(exc).__name__}: {exc}", code="listen-failed") from None
        self._server.max_cons = 256
        self._thread = threading.Thread(target=self._serve, name="ftp", daemon=True)
        self._thread.start()
        log.info("FTP server on %s for %d machine(s)%s", self.config.address, len(workers),
                 "; FTPS required" if self.config.required else
                 "; FTPS offered" if self.config.tls_cert else "")

    def _serve(self) -> None:
        server = self._server
        assert server is not None
        try:
            while not self._stopping.is_set():
                server.serve_forever(timeout=0.2, blocking=False, handle_exit=False)
            server.ioloop.unregister(server._fileno)  # no new connections
            server.socket.close()
            self._deaf.set()
            with self._active_lock:
                self._active_lock.wait_for(lambda: self._active == 0 or time.monotonic()
                                           >= self._deadline,
                                           max(0.0, self._deadline - time.monotonic()))
            self._stopped.set()
            server.close_all()  # the transfers left are interrupted, and journalled so
        finally:
            self._stopped.set()
            self._deaf.set()

    def begin_stop(self) -> None:
        """Accept no more connections; transfers under way may finish within the gateway's
        ``stop_grace``."""
        self._deadline = time.monotonic() + self.gateway.config.stop_grace
        self._stopping.set()
        if self._thread is not None:
            self._deaf.wait(2)  # within one poll of the serving thread (0.2 s)

    def stop(self, timeout: float = 10.0) -> None:
        """Stop: what is still being transferred after the grace is interrupted (journalled
        ``interrupted``, nothing partial kept)."""
        if not self._stopping.is_set():
            self.begin_stop()
        if self._thread is not None:
            self._thread.join(self.gateway.config.stop_grace + timeout)

    def why_stopped(self) -> str | None:
        return "interrupted" if self._stopped.is_set() else None

    def transfers_begun(self) -> None:
        with self._active_lock:
            self._active += 1

    def transfers_ended(self) -> None:
        with self._active_lock:
            self._active -= 1
            self._active_lock.notify_all()


def _handler_class(service: FtpServer, machines: Machines) -> type[Any]:
    """pyftpdlib's handlers with the machines' rules mixed in: plain FTP, or explicit FTPS."""
    config = service.config
    attrs: dict[str, Any] = {
        "service": service, "authorizer": machines, "abstracted_fs": MachineFolder,
        "banner": "tapegate gateway FTP: programs of the shop's machines.",
        "timeout": config.timeout, "max_login_attempts": 3, "auth_failed_timeout": 0,
        "passive_ports": (list(range(config.passive_ports[0], config.passive_ports[1] + 1))
                          if config.passive_ports else None),
    }
    if config.tls_cert:
        from pyftpdlib.handlers import TLS_DTPHandler, TLS_FTPHandler  # needs pyOpenSSL

        attrs.update(certfile=str(config.tls_cert), keyfile=str(config.tls_key),
                     tls_control_required=config.required, tls_data_required=config.required,
                     ssl_context=None)
        attrs["dtp_handler"] = type("TlsMachineData", (_DataChannel, TLS_DTPHandler), {})
        return type("TlsMachineSession", (_Session, TLS_FTPHandler), attrs)
    attrs["dtp_handler"] = type("MachineData", (_DataChannel, DTPHandler), {})
    return type("MachineSession", (_Session, FTPHandler), attrs)


def _warned(event: workflow.Event) -> None:
    """The check's warnings of how the control may read the program otherwise than tapegate
    did (dnc.program.SHOWN): logged before the program goes."""
    if isinstance(event, workflow.CheckWarnings):
        for finding in event.findings[:10]:
            log.warning("%s", finding)
