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
import termios
import time
from dataclasses import replace
from typing import Any

import serial

from dnc.sender import FlowSettings, Sender
from formats.errors import TapegateError
from formats.profile import SerialSettings

_PARITY = {"none": serial.PARITY_NONE, "even": serial.PARITY_EVEN, "odd": serial.PARITY_ODD}


class LinkError(TapegateError):
    """The port cannot be opened, vanished, or the control stopped answering."""


class PortLost(LinkError):
    """The port itself failed or disappeared (a cable pulled, a USB adapter unplugged, a device
    server gone): the gateway closes it and opens it again with backoff."""


class Aborted(LinkError):
    """The transfer was stopped on purpose: an abort request, the service shutting down."""


class Rewound(LinkError):
    """The control was reset and rewound to ``%`` (DC3 SYN) during the pass: the sender starts
    the program again from its ``%`` on the next DC1, as a tape reader rewinds to its absolute
    rewind stop. Callers that cannot restart treat it as a failed transfer."""


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
        raise LinkError("EIA code is always sent with software parity on 8 data bits")
    if out.parity_mode == "software" and (out.data_bits != 8 or out.parity != "none"):
        raise LinkError("software parity needs 8 data bits and no UART parity "
                        f"(not {out.data_bits} data bits, parity {out.parity})")
    return out


class Port:
    """A pyserial port with the few operations the DNC loops need.

    ``wait(timeout)`` blocks until input is readable or the timeout passes, with ``select`` on
    ports that have a file descriptor and short polls on the others (rfc2217, loop).
    """

    def __init__(self, link: serial.SerialBase, url: str):
        self.link = link
        self.url = url
        fd: int | None = None
        try:
            fd = link.fileno()
        except (AttributeError, NotImplementedError, serial.SerialException, OSError):
            sock = getattr(link, "_socket", None)
            fd = sock.fileno() if sock is not None else None
        self.fd = fd
        self.is_tty = fd is not None and _isatty(fd)

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
            if end is not None and time.monotonic() >= end:
                return False
            time.sleep(0.0005)

    def in_waiting(self) -> int:
        try:
            return int(self.link.in_waiting)
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
            return bytes(self.link.read(max(1, self.in_waiting())))
        except (serial.SerialException, OSError) as exc:
            raise PortLost(f"port {self.url} vanished: {exc}") from None

    def write(self, data: bytes) -> int:
        try:
            if self.fd is not None and self.is_tty:
                return os.write(self.fd, data)
            return int(self.link.write(data) or 0)
        except serial.SerialTimeoutException:
            raise LinkError(f"port {self.url} would not take data "
                            f"for {self.link.write_timeout} s") from None
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
    try:
        link = serial.serial_for_url(
            url, do_not_open=True, baudrate=s.baud, bytesize=s.data_bits,
            parity=_PARITY[s.parity], stopbits=s.stop_bits,
            xonxoff=s.flow == "xonxoff" and s.flow_by == "driver",
            rtscts=s.flow == "rtscts", timeout=0, write_timeout=10)
        link.open()
    except (serial.SerialException, ValueError, OSError) as exc:
        raise LinkError(f"cannot open port {url}: {exc}") from None
    port = Port(link, url)
    if port.is_tty and port.fd is not None:
        os.set_blocking(port.fd, False)  # a write never blocks: the sender re-queues the rest
        if receive_parity_marks and s.parity != "none" and s.parity_mode == "uart":
            _mark_parity_errors(port.fd)
    return port


def _mark_parity_errors(fd: int) -> None:
    attrs = termios.tcgetattr(fd)
    attrs[0] |= termios.INPCK | termios.PARMRK
    attrs[0] &= ~(termios.IGNPAR | termios.ISTRIP)
    termios.tcsetattr(fd, termios.TCSANOW, attrs)
