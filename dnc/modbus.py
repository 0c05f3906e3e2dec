"""The gateway's Modbus TCP interface for the shop's PLC or SCADA (pymodbus server).

Every port has a block of 16 addresses, port ``i`` (0-based, in the order of the ``[[port]]``
tables) starting at ``16 * i``, in each of the four Modbus tables. The register map is
documented in ``docs/modbus.md``; :data:`INPUT_REGISTERS` and friends below are that map.

Reads are answered from the ports' live :class:`dnc.gateway.PortStatus`. Writes ("send program
N", "abort") are refused with exception 01 (illegal function) unless ``modbus.allow_write =
true``; the server binds to 127.0.0.1 unless configured otherwise. The server runs its own asyncio
loop in a thread; commands reach the port threads through their queues.
"""

from __future__ import annotations

import asyncio
import logging
import struct
import threading
from collections.abc import Sequence
from typing import Any

from pymodbus.constants import ExcCodes
from pymodbus.pdu import ExceptionResponse, ModbusPDU
from pymodbus.pdu.decoders import DecodePDU
from pymodbus.server import ModbusTcpServer
from pymodbus.simulator import SimData, SimDevice
from pymodbus.simulator.simutils import DataType, SimUtils

from dnc import commands
from dnc.gateway import Gateway, PortStatus, Result, State
from dnc.gateway_config import ModbusConfig
from formats.errors import TapegateError

log = logging.getLogger("tapegate.modbus")

BLOCK = 16  # addresses per port in each table

# Input registers (function 4), offsets in the port's block
IR_STATE = 0  # dnc.gateway.State
IR_BYTES_SENT = 1  # uint32, high word first (1-2)
IR_LINE = 3  # uint32 (3-4): line of the block being sent
IR_PROGRAM = 5  # uint32 (5-6): program number being (or last) transferred
IR_ERRORS = 7  # faults since the service started (saturates at 65535)
IR_RESULT = 8  # dnc.gateway.Result of the last transfer
IR_TRANSFERS = 9  # transfers since the service started (saturates)
IR_BYTES_RECEIVED = 10  # uint32 (10-11) of the last program received
IR_DATA_LINES = 12  # DPRNT lines taken as machine data since the service started (saturates)
IR_PARTS = 13  # uint32 (13-14): the last part count a data line gave
IR_DATA_EVENT = 15  # the last event a data line named: 0 none, 1 start, 2 end, 3 other

# Holding registers (functions 3, 6, 16)
HR_PROGRAM = 0  # uint32 (0-1): the program number to send
HR_COMMAND = 2  # write 1: send the program in 0-1 on the next DC1; 2: abort. Reads 0.
CMD_SEND, CMD_ABORT = 1, 2

# Coils (functions 1, 5, 15)
CO_ABORT = 0  # write 1: abort the transfer under way and drop queued programs. Reads 0.

# Discrete inputs (function 2)
DI_ONLINE = 0  # the port is open
DI_BUSY = 1  # receiving, waiting for DC1, sending or paused
DI_FAILED = 2  # the last transfer did not end well

WRITES = frozenset((5, 6, 15, 16, 22, 23))
SERVED = frozenset((1, 2, 3, 4)) | WRITES  # every other function code answers exception 01
_BUSY = (State.RECEIVING, State.WAITING, State.SENDING, State.PAUSED)
_GOOD = (Result.NONE, Result.OK, Result.REQUEST)


def input_registers(status: PortStatus) -> list[int]:
    """The port's 16 input registers."""
    regs = [0] * BLOCK
    regs[IR_STATE] = int(status.state)
    regs[IR_BYTES_SENT:IR_BYTES_SENT + 2] = _u32(status.bytes_sent)
    regs[IR_LINE:IR_LINE + 2] = _u32(status.line)
    regs[IR_PROGRAM:IR_PROGRAM + 2] = _u32(status.program)
    regs[IR_ERRORS] = min(status.errors, 0xFFFF)
    regs[IR_RESULT] = int(status.result)
    regs[IR_TRANSFERS] = min(status.transfers, 0xFFFF)
    regs[IR_BYTES_RECEIVED:IR_BYTES_RECEIVED + 2] = _u32(status.bytes_received)
    regs[IR_DATA_LINES] = min(status.data_lines, 0xFFFF)
    regs[IR_PARTS:IR_PARTS + 2] = _u32(status.parts)
    regs[IR_DATA_EVENT] = status.data_event
    return regs


def discrete_inputs(status: PortStatus) -> list[bool]:
    bits = [False] * BLOCK
    bits[DI_ONLINE] = status.state not in (State.OFFLINE, State.STOPPED)
    bits[DI_BUSY] = status.state in _BUSY
    bits[DI_FAILED] = status.result not in _GOOD
    return bits


def _u32(value: int) -> list[int]:
    value = max(0, min(value, 0xFFFFFFFF))
    return [value >> 16, value & 0xFFFF]


# -- requests pymodbus cannot decode, and requests for another unit -----------------------------
#
# The Modbus Application Protocol (V1.1b3, section 7) answers a request the server cannot carry
# out with its own function code + 0x80 and an exception code: 01 for a function code it does
# not serve, 03 for a quantity out of range or a PDU whose length does not match. pymodbus
# answers every request it cannot decode with "80 01" (function code 0), so the request classes
# below are given to the server (``custom_pdu``) in place of its own: they decode what they can
# and answer the exception themselves.


class Rejected(ModbusPDU):
    """A request answered with an exception (the function code is the request's)."""

    exception = ExcCodes.ILLEGAL_FUNCTION
    cause = "unsupported function"
    told: set[tuple[str, int]] = set()  # the causes already logged (one set per server)

    def decode(self, data: bytes) -> None:
        pass

    async def datastore_update(self, context: Any, device_id: int) -> ModbusPDU:
        return _exception(self, self.exception, self.cause, self.told)


class Unsupported(Rejected):
    """A function code the gateway does not serve: exception 01 (illegal function)."""


def _unsupported(code: int, told: set[tuple[str, int]]) -> type[ModbusPDU]:
    return type(f"Unsupported{code}", (Unsupported,), {"function_code": code, "told": told})


def _checked(base: type[ModbusPDU], told: set[tuple[str, int]], allow_write: bool
             ) -> type[ModbusPDU]:
    """``base`` (a pymodbus request class) that answers exception 03 (illegal data value) when
    its PDU is cut short or its quantity or value is out of range, instead of failing to
    decode. The specification checks the function code first: a malformed write while writes
    are disabled is answered 01, as every write then is."""

    class Checked(base):  # type: ignore[misc, valid-type]
        malformed = ""

        def decode(self, data: bytes) -> None:
            try:
                super().decode(data)
            except (ValueError, IndexError, struct.error) as exc:
                self.malformed = "truncated request" if isinstance(
                    exc, (IndexError, struct.error)) else "illegal quantity"
                return
            expected = _length(self.function_code, data)
            if expected is not None and len(data) != expected:
                self.malformed = "request length does not match its byte count"
            elif self.function_code == 5 and data[2:4] not in (b"\x00\x00", b"\xff\x00"):
                self.malformed = "a coil is written 0000 or FF00"

        async def datastore_update(self, context: Any, device_id: int) -> ModbusPDU:
            if self.malformed and self.function_code in WRITES and not allow_write:
                return _exception(self, ExcCodes.ILLEGAL_FUNCTION, "writes are disabled", told)
            if self.malformed:
                return _exception(self, ExcCodes.ILLEGAL_VALUE, self.malformed, told)
            return await super().datastore_update(context, device_id)  # type: ignore[no-any-return]

    Checked.__name__ = Checked.__qualname__ = f"Checked{base.__name__}"
    return Checked


def _length(function: int, data: bytes) -> int | None:
    """The length a request's data must have (after the function code), where it is fixed or
    follows from its byte count."""
    if function in (1, 2, 3, 4, 5, 6):
        return 4
    if function == 22:
        return 6
    if function in (15, 16) and len(data) >= 5:
        return 5 + data[4]
    if function == 23 and len(data) >= 9:
        return 9 + data[8]
    return None


class WrongUnit(Rejected):
    """A request for a unit id this gateway is not: exception 0B (gateway target device failed
    to respond), as a gateway answers for a device that is not behind it."""

    exception = ExcCodes.GATEWAY_NO_RESPONSE


def _exception(pdu: ModbusPDU, code: ExcCodes, cause: str, told: set[tuple[str, int]]
               ) -> ExceptionResponse:
    """The exception response to ``pdu``, logged once per cause and function code (or unit):
    a PLC polling with a wrong request must not fill the log. Runs in the server's one asyncio
    loop, so ``told`` needs no lock."""
    key = (cause, pdu.dev_id if isinstance(pdu, WrongUnit) else pdu.function_code)
    if key not in told:
        told.add(key)
        what = (f"unit {pdu.dev_id}" if isinstance(pdu, WrongUnit)
                else f"function {pdu.function_code}")
        log.warning("Modbus: %s (%s) answered exception %02X; not logged again", what, cause,
                    int(code))
    return ExceptionResponse(pdu.function_code, code, device_id=pdu.dev_id,
                             transaction=pdu.transaction_id)


def request_classes(told: set[tuple[str, int]], allow_write: bool
                    ) -> list[type[ModbusPDU]]:
    """The request classes the server decodes with: pymodbus's own for the functions served,
    checked; a class answering exception 01 for every other function code."""
    table = DecodePDU(True).pdu_table
    out: list[type[ModbusPDU]] = []
    for code in range(1, 0x80):
        request = table.get(code, (None, None))[0]
        out.append(_checked(request, told, allow_write) if code in SERVED and request is not None
                   else _unsupported(code, told))
    return out


class ModbusInterface:
    """The Modbus TCP server of a running :class:`dnc.gateway.Gateway`."""

    def __init__(self, gateway: Gateway, config: ModbusConfig):
        self.gateway = gateway
        self.config = config
        self.size = BLOCK * len(gateway.ports)
        self.loop: asyncio.AbstractEventLoop | None = None
        self.server: ModbusTcpServer | None = None
        self.thread: threading.Thread | None = None
        self.told: set[tuple[str, int]] = set()

    def screen(self, sending: bool, pdu: ModbusPDU) -> ModbusPDU:
        """Every PDU received, before pymodbus serves it (``trace_pdu``): a request for another
        unit, or with a function code of 128 or more (an exception response is no request),
        is answered with an exception instead of reaching the data store."""
        if sending:
            return pdu
        unit = self.config.unit
        if unit and pdu.dev_id != unit:
            wrong = WrongUnit(dev_id=pdu.dev_id, transaction_id=pdu.transaction_id)
            wrong.cause = f"this gateway is unit {unit}"
            wrong.function_code = pdu.function_code & 0x7F
            wrong.told = self.told
            return wrong
        if pdu.function_code >= 0x80 or isinstance(pdu, ExceptionResponse):
            odd = Unsupported(dev_id=pdu.dev_id, transaction_id=pdu.transaction_id)
            odd.function_code = pdu.function_code & 0x7F
            odd.told = self.told
            return odd
        return pdu

    def device(self) -> SimDevice:
        n = self.size
        return SimDevice(
            self.config.unit,
            simdata=([SimData(0, count=n, values=False, datatype=DataType.BITS)],
                     [SimData(0, count=n, values=False, datatype=DataType.BITS)],
                     [SimData(0, count=n, values=0, datatype=DataType.REGISTERS)],
                     [SimData(0, count=n, values=0, datatype=DataType.REGISTERS)]),
            action=self.action)

    async def action(self, function: int, start: int, address: int, count: int,
                     registers: list[int], values: Sequence[int] | Sequence[bool] | None
                     ) -> ExcCodes | None:
        """Called by pymodbus for every request, before it reads or writes ``registers``."""
        if function in WRITES:
            if values is None:
                return None  # pymodbus reading back what a write function wrote
            if not self.config.allow_write:
                self._refuse(function, address)
                return ExcCodes.ILLEGAL_FUNCTION
            if function in (5, 15):
                return self._coils(address, values)
            return self._holding(start, address, registers, values)
        ports = [w.status for w in self.gateway.ports]
        if function == 4:
            for i in range(address // BLOCK, (address + count - 1) // BLOCK + 1):
                regs = input_registers(ports[i])
                registers[i * BLOCK - start:(i + 1) * BLOCK - start] = regs
        elif function == 2:
            bits = [b for status in ports for b in discrete_inputs(status)]
            registers[:] = SimUtils.bitsToRegisters(bits)[:len(registers)]
        return None

    def _coils(self, address: int, values: Sequence[int] | Sequence[bool]) -> ExcCodes | None:
        for j, value in enumerate(list(values)):
            coil = address + j
            if coil % BLOCK == CO_ABORT and value:
                self._abort(coil // BLOCK)
            if isinstance(values, list):
                values[j] = False  # the coil reads 0 again: the command was taken
        return None

    def _holding(self, start: int, address: int, registers: list[int],
                 values: Sequence[int] | Sequence[bool]) -> ExcCodes | None:
        new = list(registers)
        for j, value in enumerate(values):
            new[address - start + j] = int(value)
        touched = range(address, address + len(values))
        for i in range(address // BLOCK, (address + len(values) - 1) // BLOCK + 1):
            at = i * BLOCK + HR_COMMAND
            if at not in touched:
                continue
            command = new[at - start]
            number = (new[i * BLOCK + HR_PROGRAM - start] << 16) | new[
                i * BLOCK + HR_PROGRAM + 1 - start]
            if command == CMD_SEND:
                if number == 0:
                    return ExcCodes.ILLEGAL_VALUE
                if commands.send_program(self.gateway, i, number, "modbus") == "refused":
                    return ExcCodes.DEVICE_FAILURE
            elif command == CMD_ABORT:
                self._abort(i)
            elif command != 0:
                return ExcCodes.ILLEGAL_VALUE
            if isinstance(values, list):
                values[at - address] = 0  # reads 0 again: the command was taken
        return None

    def _refuse(self, function: int, address: int) -> None:
        """A write while writes are disabled: refused, logged and journalled."""
        index = address // BLOCK
        name = (self.gateway.port(index).config.name if index < len(self.gateway.ports)
                else "modbus")
        commands.refuse(self.gateway, name, f"modbus function {function} at {address}",
                        "writes are disabled (modbus.allow_write = false)")

    def _abort(self, index: int) -> None:
        commands.abort(self.gateway, index, "modbus")

    # -- running -------------------------------------------------------------------------------

    def start(self) -> None:
        """Listen; raises :class:`TapegateError` when the address cannot be bound."""
        ready = threading.Event()
        failure: list[BaseException] = []

        async def serve() -> None:
            try:
                self.server = ModbusTcpServer(self.device(),
                                              address=(self.config.host, self.config.port),
                                              trace_pdu=self.screen,
                                              custom_pdu=request_classes(
                                                  self.told, self.config.allow_write))
                await self.server.serve_forever(background=True)
            except BaseException as exc:
                failure.append(exc)
                ready.set()
                return
            ready.set()
            await self.server.serving

        def run() -> None:
            self.loop = asyncio.new_event_loop()
            asyncio.set_event_loop(self.loop)
            self.loop.run_until_complete(serve())

        self.thread = threading.Thread(target=run, name="modbus", daemon=True)
        self.thread.start()
        ready.wait(10)
        if failure or not ready.is_set():
            why = failure[0] if failure else "no answer"
            raise TapegateError(f"modbus: cannot listen on {self.config.host}:"
                                f"{self.config.port}: {why}", code="listen-failed")
        log.info("Modbus TCP on %s:%d, unit %d, writes %s", self.config.host, self.config.port,
                 self.config.unit, "allowed" if self.config.allow_write else "refused")

    def stop(self) -> None:
        if self.loop is not None and self.server is not None:
            future = asyncio.run_coroutine_threadsafe(self.server.shutdown(), self.loop)
            try:
                future.result(5)
            except Exception as exc:  # the loop already ended
                log.debug("modbus shutdown: %s", exc)
        if self.thread is not None:
            self.thread.join(5)
