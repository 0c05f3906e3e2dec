"""The gateway service: every machine's port served at once (``tapegate serve``).

One thread per port runs the same blocking loops as ``send`` and ``receive``
(:mod:`dnc.session`) around the sans-I/O state machines; the threads share nothing but the
journal (one fsync'd line per transfer) and their :class:`PortStatus`, which the Modbus interface
reads. A port thread:

* opens its port, and opens it again with exponential backoff when it cannot be opened or
  vanishes (a device server rebooting, a USB adapter unplugged);
* listens while idle: whatever the control punches is captured; a remote request
  (:mod:`dnc.requests`) queues the program asked for, anything else is saved to the receive
  folder (atomic, versioned, named from the program number) and compared with the program
  folder's copy;
* sends queued programs (requests, Modbus "send program N") on the control's next DC1, checked
  first and paced exactly as ``tapegate send`` paces them;
* journals every transfer, whatever its end: done, failed, refused, aborted, interrupted by
  the service stopping.

A fault on one port (a control that stops mid-program, a malformed request, a full disk) is
journalled and logged, and that port goes on listening; the other ports never notice.
"""

from __future__ import annotations

import contextlib
import logging
import queue
import sys
import threading
import time
from dataclasses import dataclass
from enum import IntEnum
from pathlib import Path
from typing import Protocol

from dnc import workflow
from dnc.compare import compare_programs
from dnc.dataline import DataEvent, DataPatterns, LineSplitter, Split, data_program
from dnc.gateway_config import GatewayConfig, PortConfig
from dnc.journal import Journal, Transfer, now_utc
from dnc.link import (
    LinkError,
    Port,
    PortLost,
    describe,
    open_port,
)
from dnc.receiver import Receiver
from dnc.requests import (
    BadRequest,
    Forbidden,
    NotFound,
    Request,
    find_program,
    message_program,
    program_key,
    recognise,
)
from dnc.session import capture, program_name, program_number
from formats.errors import TapegateError
from formats.files import PendingFile, count_lines, sha256_of

log = logging.getLogger("tapegate.gateway")

# What a control sends outside a program and that never starts a capture: DC1 and DC3 (flow
# control), DC4 (punch off, after the closing %), and tape fill (NUL, DEL: the trailer after a
# program, or leader before one -- a program's own % starts the capture).
NOT_A_PUNCH = frozenset((0x00, 0x11, 0x13, 0x14, 0x7F))


class State(IntEnum):
    """What a port is doing (Modbus input register 0 of the port)."""
    OFFLINE = 0  # not open: cannot be opened or vanished; retried with backoff
    IDLE = 1  # open, listening
    RECEIVING = 2
    WAITING = 3  # a program is ready; waiting for the control's DC1
    SENDING = 4
    PAUSED = 5  # the control sent DC3
    STOPPED = 6  # the service is stopping or has stopped


class Result(IntEnum):
    """How the port's last transfer ended (Modbus input register 8)."""
    NONE = 0
    OK = 1
    FAILED = 2  # the link failed: timeout, NAK, the port vanished
    ABORTED = 3  # an abort request, or the service stopping
    PARITY_ERRORS = 4  # received with parity errors (kept in the file)
    NOT_FOUND = 5
    FORBIDDEN = 6  # the name reaches outside the program folder
    BAD_REQUEST = 7
    DIFFERS = 8  # received, and differs from the program folder's copy
    REFUSED = 9  # the check found errors in the program: not sent
    WRITE_FAILED = 10  # the receive folder could not be written (full disk, permissions)
    REQUEST = 11  # a remote request was received and queued
    REWOUND = 12  # the control was reset and rewound mid-program; sent again from %


@dataclass
class PortStatus:
    name: str
    state: State = State.OFFLINE
    program: int = 0  # number of the program being (or last) transferred
    bytes_sent: int = 0  # of the send under way, or the last one
    bytes_total: int = 0  # of the send under way, or the last one, as framed (leader to trailer)
    file: str = ""  # name of the program being (or last) sent
    bytes_received: int = 0  # of the last program received
    line: int = 0  # line of the block being sent
    errors: int = 0  # faults since the service started
    result: Result = Result.NONE
    transfers: int = 0  # transfers journalled since the service started
    message: str = ""  # the last thing that happened, in words
    data_lines: int = 0  # DPRNT lines taken as machine data since the service started
    data_last: str = ""  # the last of them
    data_event: int = 0  # the last event a data line named (dnc.dataline.EVENT_CODES; Modbus)
    parts: int = 0  # the last part count a data line gave


@dataclass(frozen=True)
class Job:
    """A program to send on the next DC1."""
    name: str  # as asked for (a file name or a program number)
    origin: str  # "request", "modbus"
    block: int | None = None  # restart from sequence number N<block>
    lines: tuple[str, ...] | None = None  # a message program instead of a file


class Gateway:
    """All the port threads, started and stopped together."""

    def __init__(self, config: GatewayConfig):
        self.config = config
        self.stopping = threading.Event()
        self.stop_deadline: float | None = None
        self.journal_lock = threading.Lock()
        self.journal = Journal(config.journal) if config.journal else None
        self.ports = [PortWorker(self, p) for p in config.ports]
        # told of every journal record and data line, in the journal's order (dnc.mqtt)
        self.listeners: list[Listener] = []

    def start(self) -> None:
        # Port threads wait on I/O and must answer a DC3 within a few character times (under a
        # millisecond at 115200 baud). Python hands the interpreter between threads every 5 ms
        # by default; a shorter interval keeps a busy thread from holding a port's DC3 back.
        sys.setswitchinterval(min(sys.getswitchinterval(), 0.0005))
        for worker in self.ports:
            worker.start()

    def stop(self, timeout: float = 10.0) -> None:
        """Stop every port: transfers under way get ``stop_grace`` seconds to finish, then are
        aborted; either way they are journalled."""
        self.stop_deadline = time.monotonic() + self.config.stop_grace
        self.stopping.set()
        for worker in self.ports:
            worker.join(self.config.stop_grace + timeout)

    def record(self, transfer: Transfer, data: DataEvent | None = None) -> None:
        """Journal a transfer (or, with ``data``, a DPRNT line taken as machine data) and tell
        the listeners, in the journal's order."""
        if self.journal is None and not self.listeners:
            return
        with self.journal_lock:
            if self.journal is not None:
                try:
                    self.journal.append(transfer)
                except OSError as exc:  # a full disk must not stop the ports
                    log.error("journal %s: cannot append: %s", self.journal.path, exc.strerror)
            for listener in self.listeners:
                listener.record(transfer, data)

    def port(self, index: int) -> PortWorker:
        return self.ports[index]


class Listener(Protocol):
    """Told of every journal record, with its data line for a DPRNT line taken as machine data
    (the MQTT publisher, which queues the two as one)."""

    def record(self, transfer: Transfer, data: DataEvent | None) -> None: ...


class PortWorker(threading.Thread):
    def __init__(self, gateway: Gateway, config: PortConfig):
        super().__init__(name=f"port-{config.name}", daemon=True)
        self.gateway = gateway
        self.config = config
        self.status = PortStatus(config.name)
        self.jobs: queue.Queue[Job] = queue.Queue()
        self.aborting = threading.Event()
        self.log = logging.LoggerAdapter(log, {"port": config.name})
        self.patterns = DataPatterns(config.data_patterns)
        self.splitter = LineSplitter()

    # -- requests from outside (Modbus, tests) -------------------------------------------------

    def submit(self, job: Job) -> None:
        self.jobs.put(job)

    def abort(self) -> None:
        """Abort the transfer under way and drop the programs queued."""
        with contextlib.suppress(queue.Empty):
            while True:
                self.jobs.get_nowait()
        self.aborting.set()

    # -- the thread ----------------------------------------------------------------------------

    def run(self) -> None:
        """Open the port and serve it; a port that cannot be opened, that vanishes or whose
        driver fails in a way nobody foresaw is shown offline and opened again with backoff
        (``retry_first`` doubling up to ``retry_max``). The thread ends only when the service
        stops."""
        gw = self.gateway.config
        if self.config.is_ftp:  # the machine logs in to the FTP server (dnc.ftp), which
            self._set(State.IDLE, "FTP: waiting for the machine")  # keeps this status
            while not self.gateway.stopping.is_set():
                with contextlib.suppress(queue.Empty):  # a Modbus "send program N"
                    job = self.jobs.get(timeout=0.5)
                    self.log.warning("send %s refused: an FTP machine fetches its programs",
                                     job.name)
                    self._finish("command", f"send {job.name}", Result.BAD_REQUEST, now_utc(),
                                 errors=["an FTP machine fetches its own programs: nothing "
                                         "can be sent to it"], words="refused")
            self._set(State.STOPPED, "stopped")
            return
        delay = gw.retry_first
        reported = ""
        while not self.gateway.stopping.is_set():
            try:
                port = open_port(self.config.url, self.config.serial, receive_parity_marks=True)
            except Exception as exc:  # noqa: BLE001 - a driver's own failure: retried the same
                why = (exc.message if isinstance(exc, LinkError)
                       else f"cannot open port {self.config.url}: {type(exc).__name__}: {exc}")
                if why != reported:
                    self.log.warning("%s; retrying with backoff up to %g s", why, gw.retry_max,
                                     exc_info=not isinstance(exc, LinkError))
                    reported = why
                self._set(State.OFFLINE, why)
                self.gateway.stopping.wait(delay)
                delay = min(delay * 2, gw.retry_max)
                continue
            reported = ""
            self.log.info("open %s (%s)", self.config.url, describe(self.config.serial))
            self._set(State.IDLE, "listening")
            try:
                self._serve(port)
                delay = gw.retry_first
            except PortLost as exc:
                delay = gw.retry_first
                self.status.errors += 1
                self.log.warning("%s; opening it again", exc.message)
                self._set(State.OFFLINE, exc.message)
            except Exception as exc:  # noqa: BLE001 - the port's thread must not die
                self.status.errors += 1
                why = f"port {self.config.url} failed: {type(exc).__name__}: {exc}"
                self.log.error("%s; opening it again in %g s", why, delay, exc_info=True)
                self._set(State.OFFLINE, why)
                self.gateway.stopping.wait(delay)
                delay = min(delay * 2, gw.retry_max)
            finally:
                port.close()
        self._set(State.STOPPED, "stopped")

    def _serve(self, port: Port) -> None:
        while not self.gateway.stopping.is_set():
            try:
                job = self.jobs.get_nowait()
            except queue.Empty:
                job = None
            if job is not None:
                self.aborting.clear()
                self._send(port, job)
                self._set(State.IDLE, self.status.message)
                continue
            if not port.wait(0.2):
                if self.splitter.pending:
                    self._data_lines(port, self.splitter.flush())
                continue
            data = port.read()
            if self.patterns:  # DPRNT lines before a program's % are data (dnc.dataline)
                split = self.splitter.feed(data)
                self._data_lines(port, split)
                if split.program_at is None:
                    continue
                data = data[split.program_at:]
            if all(b & 0x7F in NOT_A_PUNCH for b in data):
                continue  # e.g. the control's DC1 (ready to read) with nothing queued for it
            self.aborting.clear()
            self._receive(port, data)
            self._set(State.IDLE, self.status.message)

    def _stop_now(self) -> bool:
        if self.aborting.is_set():
            return True
        deadline = self.gateway.stop_deadline
        return self.gateway.stopping.is_set() and (deadline is None
                                                    or time.monotonic() >= deadline)

    def _set(self, state: State, message: str) -> None:
        self.status.state = state
        self.status.message = message

    def _finish(self, direction: str, program: str, result: Result, started: str, *,
                size: int = 0, blocks: int = 0, errors: list[str] | None = None,
                sha256: str = "", words: str | None = None) -> None:
        """Journal a transfer and show its end in the status."""
        text = words or result.name.lower().replace("_", " ")
        self._record(Transfer(self.config.name, direction, program, size, blocks, started,
                              now_utc(), text, errors or [], sha256), result)

    def _record(self, transfer: Transfer, result: Result) -> None:
        self.gateway.record(transfer)
        self.status.result = result
        self.status.transfers += 1
        if result not in (Result.OK, Result.REQUEST, Result.REWOUND):
            self.status.errors += 1
        self.status.message = f"{transfer.direction} {transfer.program}: {transfer.result}"

    # -- receiving -----------------------------------------------------------------------------

    def _receive(self, port: Port, first: bytes) -> None:
        cfg, gw = self.config, self.gateway.config
        s = cfg.serial
        uart = s.parity_mode == "uart"
        receiver = Receiver(uart_parity=uart,
                            parity_marks=uart and port.is_tty and s.parity != "none",
                            idle_timeout=gw.idle, now=time.monotonic())
        started = now_utc()
        before = self.status.message
        self._set(State.RECEIVING, "receiving")
        self.status.bytes_received = 0
        letter = cfg.profile.program_number or "O"
        try:
            with PendingFile(cfg.receive, "received", create=True) as pending:
                got = capture(port, receiver, pending, first=first, stop=self._stop_now)
                self.status.bytes_received = receiver.bytes
                if not got.chars:
                    pending.discard()
                    self.status.message = before  # nothing happened
                    return  # noise on an idle line, or leader only
                number = program_number(got.head, letter)
                self.status.program = _numeric(number)
                if not receiver.done:  # aborted, or the service is stopping: keep what came
                    name = Path(program_name(got.head, letter))
                    path = pending.commit(cfg.receive / f"{name.stem}.partial{name.suffix}")
                    self.log.warning("receive interrupted: kept %s", path.name)
                    self._finish("receive", path.name, Result.ABORTED, started,
                                 size=receiver.bytes, blocks=count_lines(path),
                                 sha256=sha256_of(path), words="interrupted")
                    return
                if cfg.requests and self._request(got.head, got.chars, number, started):
                    pending.discard()
                    return
                events = data_program(got.head, got.chars, self.patterns)
                if events:  # DPRNT lines between POPEN's and PCLOS's %: data, no program
                    pending.discard()
                    self.status.message = before
                    for event in events:
                        self._data(event)
                    return
                path = pending.commit(cfg.receive / program_name(got.head, letter))
        except OSError as exc:
            why = exc.strerror or str(exc)
            self.log.error("cannot save what the control punched in %s: %s", cfg.receive, why)
            self._finish("receive", "", Result.WRITE_FAILED, started, size=receiver.bytes,
                         errors=[f"cannot save in {cfg.receive}: {why}"], words="failed")
            self._drain(port, gw.idle)
            return
        errors = [f"{path.name}:{i.line}:{i.column}: {i.message()}" for i in receiver.issues]
        result = Result.PARITY_ERRORS if errors else Result.OK
        if cfg.compare:
            differences = self._compare(path, Path(program_name(got.head, letter)).stem)
            if differences:
                errors += differences
                result = Result.DIFFERS if result == Result.OK else result
        self.log.info("received %s: %d bytes, %s code, ended by %s%s", path.name,
                      receiver.bytes, (receiver.code or "iso").upper(), receiver.reason,
                      f"; {len(errors)} problem(s)" if errors else "")
        for error in errors[:20]:
            self.log.info("  %s", error)
        self._finish("receive", path.name, result, started, size=receiver.bytes,
                     blocks=count_lines(path), errors=errors, sha256=sha256_of(path))

    def _request(self, head: str, chars: int, number: str | None, started: str) -> bool:
        """Queue the program a punched request asks for. False: it is no request."""
        rules = self.gateway.config.requests
        try:
            request: Request | None = recognise(head, chars, number, rules)
        except BadRequest as exc:
            self.log.warning("bad request: %s; nothing sent", exc.message)
            self._finish("receive", number or "request", Result.BAD_REQUEST, started,
                         size=chars, errors=[exc.message])
            return True
        if request is None:
            return False
        at = f" from N{request.block}" if request.block is not None else ""
        self.log.info("request for %s%s: sent on the next DC1", request.program, at)
        self._finish("receive", f"request {request.program}", Result.REQUEST, started,
                     size=chars)
        self.submit(Job(request.program, "request", request.block))
        return True

    def _compare(self, path: Path, stem: str) -> list[str]:
        """Differences between a received program and the program folder's copy."""
        try:
            copy = find_program(self.config.programs, stem,
                                self.gateway.config.requests.extensions)
        except (NotFound, Forbidden):
            return []
        return compare_programs(copy, path, profile=self.config.profile)

    def _drain(self, port: Port, idle: float) -> None:
        """Read and drop the rest of a program that cannot be kept, until the line is quiet.
        A control's DC1 (ready to read, repeated while it waits) or tape fill is quiet: the
        control is done punching."""
        quiet_since = time.monotonic()
        while not self._stop_now() and time.monotonic() - quiet_since < idle:
            if port.wait(0.2) and not all(b & 0x7F in NOT_A_PUNCH for b in port.read()):
                quiet_since = time.monotonic()

    # -- machine data (DPRNT lines) --------------------------------------------------------------

    def _data_lines(self, port: Port, split: Split) -> None:
        if split.replies:
            port.write(split.replies)
        for line in split.lines:
            event = self.patterns.match(line)
            if event is None:  # outside a program and no data: dropped, as leader always was
                self.log.debug("line outside a program, not data: %r", line[:80])
            else:
                self._data(event)
        if split.dropped:
            self.log.warning("%d line(s) of more than 256 characters outside a program dropped",
                             split.dropped)

    def _data(self, event: DataEvent) -> None:
        """A data line: counted, shown, journalled (direction ``data``) and published."""
        s = self.status
        s.data_lines += 1
        s.data_last = event.line
        if "event" in event.fields:
            s.data_event = event.event_code
        if event.parts is not None:
            s.parts = event.parts
        self.log.info("data: %s", event.line)
        moment = now_utc()
        self.gateway.record(Transfer(self.config.name, "data", event.line, len(event.line), 1,
                                     moment, moment, "ok"), event)

    # -- sending -------------------------------------------------------------------------------

    def _send(self, port: Port, job: Job) -> None:
        """The one send workflow (:mod:`dnc.workflow`), as ``tapegate send`` runs it: checked
        (unless the port says not to), restarted from a request's block, sent again from ``%``
        after a reset and rewind, every end journalled."""
        cfg, gw = self.config, self.gateway.config
        started = now_utc()
        self.status.bytes_sent = self.status.line = 0
        path: Path | None = None
        if job.lines is not None:
            display = f"message {job.lines[1]}"
        else:
            try:
                path = find_program(cfg.programs, job.name, gw.requests.extensions)
            except NotFound as exc:
                self.log.warning("%s (%s); nothing sent", exc.message, job.origin)
                self._finish("send", job.name, Result.NOT_FOUND, started, errors=[exc.message])
                if job.origin == "request" and gw.requests.not_found_message:
                    self.submit(Job(job.name, "message", lines=tuple(message_program(
                        gw.requests.message_number, f"program {job.name} not found"))))
                return
            except Forbidden as exc:
                self.log.warning("%s (%s); nothing sent", exc.message, job.origin)
                self._finish("send", job.name, Result.FORBIDDEN, started, errors=[exc.message])
                return
            display = path.name
        try:
            if path is None:
                program = workflow.prepare_lines(job.lines or (), cfg.serial, name=display)
            else:
                program = workflow.prepare(
                    str(path), cfg.profile, cfg.serial, name=display, check_first=cfg.check,
                    restart_at=None if job.block is None else f"N{job.block}",
                    on_event=self._warned)
        except workflow.Refused as exc:
            self.log.warning("%s: %s; not sent", display, exc.message)
            self._finish("send", display, Result.REFUSED, started,
                         errors=[str(e) for e in exc.findings[:20]])
            return
        except TapegateError as exc:  # no such restart block; a character the code cannot carry
            self.log.warning("%s: %s; not sent", display, exc.message)
            self._finish("send", display, Result.REFUSED, started, errors=[str(exc)])
            return
        self.status.program = _numeric(job.name) or _numeric(_head_number(path))
        self.status.file, self.status.bytes_total = display, program.total
        self._set(State.WAITING, f"{display}: waiting for DC1")
        self.log.info("%s ready (%d bytes, %d blocks): waiting for DC1", display, program.total,
                      program.frame.blocks)

        def shown(event: workflow.Event) -> None:
            if isinstance(event, workflow.Progress):
                p = event.progress
                self.status.bytes_sent = p.sent
                self.status.line = p.line
                self.status.state = (State.WAITING if p.waiting else State.PAUSED if p.paused
                                     else State.SENDING)
            elif isinstance(event, workflow.Rewinding):
                # the tape goes back to its absolute rewind stop: the whole pass again from %
                self.log.warning("%s: %s; sending again from %% on the next DC1", display,
                                 event.message)
                self._set(State.WAITING, f"{display}: rewound, waiting for DC1")

        passes = workflow.Passes(wait_for_dc1=True, start_timeout=gw.request_timeout)
        with program:
            try:
                outcome = workflow.run(port, program, passes, port_name=cfg.name,
                                       record=self._journalled, on_event=shown,
                                       stop=self._stop_why)
            except LinkError as exc:  # journalled "failed"
                self.log.warning("%s: %s", display, exc.message)
                if isinstance(exc, PortLost):
                    raise
                return
        self.status.bytes_sent = outcome.progress.sent
        if outcome.result != "ok":
            self.log.warning("%s: %s after %d bytes", display, outcome.result,
                             outcome.progress.sent)
            return
        self.log.info("%s: %s", display, workflow.summary(outcome.progress, cfg.serial))

    def _warned(self, event: workflow.Event) -> None:
        """The check's warnings of how the control may read the program otherwise than
        tapegate did (dnc.program.SHOWN): logged before the program goes."""
        if isinstance(event, workflow.CheckWarnings):
            for finding in event.findings[:10]:
                self.log.warning("%s", finding)

    def _stop_why(self) -> str | None:
        """Why a send must end now: ``aborted`` (an abort request), ``interrupted`` (the service
        is stopping and the grace has run out), or ``None``."""
        if self.aborting.is_set():
            return "aborted"
        return "interrupted" if self._stop_now() else None

    def _journalled(self, transfer: Transfer) -> None:
        """Journal a record of the send workflow and show its end in the status."""
        self._record(transfer, _RESULTS[transfer.result])


# how the send workflow's journal results show in the status (Modbus input register 8)
_RESULTS = {"ok": Result.OK, "rewound": Result.REWOUND, "failed": Result.FAILED,
            "aborted": Result.ABORTED, "interrupted": Result.ABORTED}


def _numeric(number: str | None) -> int:
    """``O1234`` (or ``1234``) as 1234 for the status; 0 for a name that is no O number."""
    key = program_key(number or "")
    return key[1] % 100_000_000 if key is not None and key[0] == "O" else 0


def _head_number(path: Path | None) -> str | None:
    if path is None:
        return None
    with open(path, encoding="utf-8", errors="replace") as f:
        head = f.read(4096)
    return program_number(head)
