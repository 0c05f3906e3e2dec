"""The serial link: settings, wire timing, and a port opened by URL.

Every serial command takes its settings from the profile's ``[serial]`` table, with the same
overrides (``--baud``, ``--data-bits``, ``--parity``, ``--stop-bits``, ``--flow``,
``--parity-mode``, ``--code``). Ports are opened with pyserial's ``serial_for_url``: a device path
(``/dev/ttyUSB0``, ``COM3``), ``rfc2217://host:port`` (serial device servers), ``socket://host:port``
(raw TCP) or ``loop://``.

:class:`Port` is the only place that does I/O for the DNC layer; the protocol state machines in
:mod:`dnc.sender`, :mod:`dnc.receiver` and :mod:`dnc.control` never touch it.
"""

from __future__ import annotations

import contextlib
import os
import select
import stat
import termios
import time
from dataclasses import replace
from typing import Any

import serial

from dnc.sender import FlowSettings, Sender
from formats.errors import TapegateError
from formats.profile import SerialSettings

_PARITY = {"none": serial.PARITY_NONE, "even": serial.PARITY_EVEN, "odd": serial.PARITY_ODD}
WRITE_TIMEOUT = 10.0  # seconds a write may wait for the driver (tty, socket://)
READ_SLICE = 0.01  # read timeout of a port with no descriptor to wait on (rfc2217, loop)


class LinkError(TapegateError):
    """The port cannot be opened, vanished, or the control stopped answering. A transfer's
    error says where it stopped: ``stopped_at`` is (the line of the block reached, 0 before the
    first; the bytes sent), ``None`` until the sending loop (:mod:`dnc.session`) fills it in."""

    default_code = "link"

    def __init__(self, message: str, *, stopped_at: tuple[int, int] | None = None,
                 **fields: Any) -> None:
        super().__init__(message, **fields)
        self.stopped_at = stopped_at


class PortLost(LinkError):
    """The port itself failed or disappeared (a cable pulled, a USB adapter unplugged, a device
    server gone): the gateway closes it and opens it again with backoff."""

    default_code = "link-lost"


class Aborted(LinkError):
    """The transfer was stopped on purpose: an abort request, the service shutting down."""

    default_code = "link-aborted"


class Rewound(LinkError):
    """The control was reset and rewound to ``%`` (DC3 SYN) during the pass: the sender starts
    the program again from its ``%`` on the next DC1, as a tape reader rewinds to its absolute
    rewind stop. Callers that cannot restart treat it as a failed transfer."""

    default_code = "link-rewound"


def frame_bits(s: SerialSettings) -> int:
    """Bits on the wire per character: start + data + parity + stop."""
    return 1 + s.data_bits + (s.parity != "none") + s.stop_bits


def chars_per_second(s: SerialSettings) -> float:
    """The most characters per second the wire can carry (9600 7E2: 872.7)."""
    return s.baud / frame_bits(s)


def describe(s: SerialSettings) -> str:
    parity = s.parity[0].upper()
    how = "UART parity" if s.parity_mode == "uart" else "software parity"
    flow = {"xonxoff": "XON/XOFF", "rtscts": "RTS/CTS", "none": "no flow control"}[s.flow]
    return (f"{s.baud} {s.data_bits}{parity}{s.stop_bits}, {s.code.upper()} code, {how}, "
            f"{flow}, {chars_per_second(s):.1f} chars/s")


def pace(s: SerialSettings) -> float | None:
    """The characters per second tapegate sends at on this link when that is slower than the
    wire, to keep a DC3 seen late within the allowance (:func:`dnc.sender.paced_cps`); ``None``
    when it sends at the wire's pace."""
    flow = flow_settings(s)
    cps = Sender(flow, 0.0).cps
    return cps if cps < flow.cps else None


def flow_settings(s: SerialSettings, *, wait_for_dc1: bool | None = None,
                  xon_timeout: float | None = None,
                  start_timeout: float | None = None) -> FlowSettings:
    """How the sender paces and obeys the control on this link."""
    return FlowSettings(
        cps=chars_per_second(s), flow=s.flow, obey_dc=s.flow_by == "tapegate",
        wait_for_dc1=s.wait_for_dc1 if wait_for_dc1 is None else wait_for_dc1,
        xon_timeout=s.xon_timeout if xon_timeout is None else xon_timeout,
        start_timeout=start_timeout,
        allowance=s.overrun_allowance, char_delay=s.char_delay, line_delay=s.line_delay,
        reaction=s.dc3_reaction or 0.0,  # unset: the wire's pace (the gateway sets its own)
        eob_last=0x80 if s.code == "eia" else (0x0D if s.eob in ("lfcrcr", "crlf") else 0x0A))


def override(s: SerialSettings, **changes: Any) -> SerialSettings:
    """The profile's settings with the command line's overrides (``None`` = keep).

    Choosing ``--parity-mode software`` or ``--code eia`` switches the port to 8 data bits
    without parity, since the sender then sets bit 8 itself; the reverse for ``uart``.
    """
    given = {k: v for k, v in changes.items() if v is not None}
    out = replace(s, **given)
    if given.get("code") == "eia" or given.get("parity_mode") == "software":
        out = replace(out, parity_mode="software", data_bits=given.get("data_bits", 8),
                      parity=given.get("parity", "none"))
    elif given.get("parity_mode") == "uart" and out.code == "iso":
        out = replace(out, data_bits=given.get("data_bits", 7), parity=given.get("parity", "even"))
    if out.code == "eia" and out.parity_mode != "software":
        raise LinkError("EIA code is always sent with software parity on 8 data bits",
                        code="link-settings")
    if out.parity_mode == "software" and (out.data_bits != 8 or out.parity != "none"):
        raise LinkError("software parity needs 8 data bits and no UART parity "
                        f"(not {out.data_bits} data bits, parity {out.parity})",
                        code="link-settings")
    return out


class Port:
    """A pyserial port with the few operations the DNC loops need.

    ``wait(timeout)`` blocks until input is readable or the timeout passes. A port with a file
    descriptor (a tty, ``socket://``) is waited on with ``select``. A port without one
    (``rfc2217://``, ``loop://``) is read by a thread of pyserial's into a queue, so its socket
    must never be looked at (the thread would take the DC3 from under a ``select``): such a port
    is opened with a read timeout of :data:`READ_SLICE`, and ``wait`` makes blocking reads of one
    byte through pyserial's public ``read``, which return as soon as a byte is queued, and keeps
    that byte for the next :meth:`read`; the last slice shorter than that is polled.
    """

    def __init__(self, link: serial.SerialBase, url: str):
        self.link = link
        self.url = url
        fd: int | None = None
        if hasattr(link, "fileno"):
            try:
                fd = link.fileno()
            except (NotImplementedError, serial.SerialException, OSError, ValueError):
                fd = None
        self.fd = fd
        self.is_tty = fd is not None and _isatty(fd)
        self.held = b""  # read by wait() on a port without a descriptor, not yet returned

    def wait(self, timeout: float | None) -> bool:
        if self.fd is not None:
            try:
                ready, _, _ = select.select([self.fd], [], [], timeout)
            except (OSError, ValueError) as exc:
                raise PortLost(f"port {self.url} failed: {exc}") from None
            return bool(ready)
        end = None if timeout is None else time.monotonic() + timeout
        while True:
            if self.in_waiting():
                return True
            left = None if end is None else end - time.monotonic()
            if left is not None and left <= 0:
                return False
            if left is None or left >= READ_SLICE:
                self.held = self._read(1)  # wakes as soon as a byte comes, else after a slice
                if self.held:
                    return True
            else:
                time.sleep(min(left, 0.0005))

    def in_waiting(self) -> int:
        try:
            return len(self.held) + int(self.link.in_waiting)
        except (serial.SerialException, OSError) as exc:
            raise PortLost(f"port {self.url} vanished: {exc}") from None

    def read(self) -> bytes:
        """What is waiting (at least one byte when :meth:`wait` said so)."""
        try:
            if self.fd is not None and self.is_tty:
                data = os.read(self.fd, 4096)
                if not data:
                    raise PortLost(f"port {self.url} vanished (end of file)")
                return data
        except OSError as exc:
            raise PortLost(f"port {self.url} vanished: {exc}") from None
        if self.fd is not None:  # socket://: read with no timeout, what is there
            return self._read(4096)
        held, self.held = self.held, b""  # rfc2217, loop: no more than is queued (or a slice)
        waiting = self.in_waiting()
        return held + self._read(waiting) if waiting or not held else held

    def _read(self, size: int) -> bytes:
        try:
            return bytes(self.link.read(max(1, size)))
        except (serial.SerialException, OSError) as exc:
            raise PortLost(f"port {self.url} vanished: {exc}") from None

    def write(self, data: bytes) -> int:
        try:
            if self.fd is not None and self.is_tty:
                return os.write(self.fd, data)
            return int(self.link.write(data) or 0)
        except serial.SerialTimeoutException:
            raise LinkError(f"port {self.url} would not take data "
                            f"for {self.link.write_timeout} s", code="link-timeout") from None
        except BlockingIOError:
            return 0
        except (serial.SerialException, OSError) as exc:
            raise PortLost(f"port {self.url} vanished: {exc}") from None

    def queued(self) -> int | None:
        """Bytes still in the driver's output queue, where the driver can say."""
        if not self.is_tty:
            return None
        try:
            return int(self.link.out_waiting)
        except (serial.SerialException, OSError, AttributeError):
            return None

    def hold_output(self, hold: bool) -> None:
        """Stop (or restart) the driver's transmitter at once: DC3 must not wait for the
        bytes already queued in the driver (termios ``tcflow``)."""
        if self.fd is not None and self.is_tty:
            with contextlib.suppress(termios.error):
                termios.tcflow(self.fd, termios.TCOOFF if hold else termios.TCOON)

    def discard_output(self) -> None:
        """Throw away what the driver still holds for the wire and restart its transmitter: the
        control was reset, so the rest of the old pass must not reach it."""
        if self.fd is not None and self.is_tty:
            with contextlib.suppress(termios.error, serial.SerialException, OSError):
                self.link.reset_output_buffer()
        self.hold_output(False)

    def close(self) -> None:
        with contextlib.suppress(serial.SerialException, OSError):
            self.link.close()


class FdPort(Port):
    """A bare file descriptor as a port: the emulator's end of a pseudo-terminal, a socket.
    Its owner closes it."""

    def __init__(self, fd: int, name: str = "emulator"):
        self.url = name
        self.fd = self.raw = fd
        self.is_tty = False

    def in_waiting(self) -> int:
        return 1 if self.wait(0) else 0

    def read(self) -> bytes:
        try:
            data = os.read(self.raw, 4096)
        except OSError as exc:
            raise PortLost(f"port {self.url} vanished: {exc}") from None
        if not data:
            raise PortLost(f"port {self.url} vanished (end of file)")
        return data

    def write(self, data: bytes) -> int:
        try:
            return os.write(self.raw, data)
        except BlockingIOError:
            return 0
        except OSError as exc:
            raise PortLost(f"port {self.url} vanished: {exc}") from None

    def close(self) -> None:
        pass


def _isatty(fd: int) -> bool:
    try:
        return os.isatty(fd)
    except OSError:
        return False


def open_port(url: str, s: SerialSettings, *, receive_parity_marks: bool = False) -> Port:
    """Open ``url`` with the link settings ``s``.

    Flow control by the driver is asked for only where the profile says so (``flow_by =
    "driver"`` or RTS/CTS); otherwise tapegate reads DC1/DC3 itself. With
    ``receive_parity_marks`` on a local tty with UART parity, the driver marks every character
    that failed its parity check (termios ``PARMRK``) so that the receiver can report it.
    """
    rfc2217 = url.lower().startswith("rfc2217://")
    bits, parity = s.data_bits, _PARITY[s.parity]
    if is_pseudo_terminal(url):
        # No UART: Linux keeps a pty at 8 bits without parity, and refuses (EINVAL) a request
        # that changes nothing else -- the second open of the same pty, whose speed is
        # already set. The bytes are the same either way.
        bits, parity = 8, serial.PARITY_NONE
    try:
        link = serial.serial_for_url(
            _rfc2217_url(url) if rfc2217 else url, do_not_open=True, baudrate=s.baud,
            bytesize=bits, parity=parity, stopbits=s.stop_bits,
            xonxoff=s.flow == "xonxoff" and s.flow_by == "driver",
            rtscts=s.flow == "rtscts", timeout=0)
        # pyserial's rfc2217 client has no write timeout (it refuses one); its socket's own
        # timeout ends a write the server does not take, as a lost port
        if not rfc2217:
            link.write_timeout = WRITE_TIMEOUT
        if not hasattr(link, "fileno"):  # rfc2217, loop: Port.wait reads in slices
            link.timeout = READ_SLICE
        link.open()
    except (serial.SerialException, ValueError, OSError, NotImplementedError) as exc:
        raise LinkError(f"cannot open port {url}: {exc}", code="link-open") from None
    except termios.error as exc:  # the driver refused the settings
        why = exc.args[-1] if exc.args else exc
        raise LinkError(f"cannot open port {url}: the driver refused {describe(s)}: "
                        f"{why}", code="link-open") from None
    port = Port(link, url)
    if port.is_tty and port.fd is not None:
        os.set_blocking(port.fd, False)  # a write never blocks: the sender re-queues the rest
        if receive_parity_marks and s.parity != "none" and s.parity_mode == "uart":
            _mark_parity_errors(port.fd)
    return port


def is_pseudo_terminal(url: str) -> bool:
    """Whether ``url`` names a pseudo-terminal (the emulator's port), itself or through a
    symbolic link: a Unix 98 pty's device number (Linux majors 136-143), or a name under
    ``/dev/pts``."""
    if "://" in url:
        return False
    try:
        info = os.stat(url)
    except OSError:
        return False
    if not stat.S_ISCHR(info.st_mode):
        return False
    return 136 <= os.major(info.st_rdev) <= 143 or os.path.realpath(url).startswith("/dev/pts/")


def _rfc2217_url(url: str) -> str:
    """``url`` with pyserial's ``ign_set_control`` option: the answers to modem-control and
    flow-control requests (DTR, RTS, the server's flow control) are not waited for. A device
    server whose port has no modem lines (ser2net on a pseudo-terminal, some adapters) never
    answers them, and pyserial would give up the open after its network timeout. The port
    settings (baud, data bits, parity, stop bits) are still confirmed by the server."""
    head, _, query = url.partition("?")
    options = [o for o in query.split("&") if o]
    if not any(o.split("=")[0] == "ign_set_control" for o in options):
        options.append("ign_set_control")
    return f"{head}?{'&'.join(options)}"


def _mark_parity_errors(fd: int) -> None:
    attrs = termios.tcgetattr(fd)
    attrs[0] |= termios.INPCK | termios.PARMRK
    attrs[0] &= ~(termios.IGNPAR | termios.ISTRIP)
    termios.tcsetattr(fd, termios.TCSANOW, attrs)
