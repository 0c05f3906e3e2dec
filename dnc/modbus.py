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
import threading
from collections.abc import Sequence

from pymodbus.constants import ExcCodes
from pymodbus.server import ModbusTcpServer
from pymodbus.simulator import SimData, SimDevice
from pymodbus.simulator.simutils import DataType, SimUtils

from dnc.gateway import Gateway, Job, PortStatus, Result, State
from dnc.gateway_config import ModbusConfig
from dnc.journal import Transfer, now_utc
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


class ModbusInterface:
    """The Modbus TCP server of a running :class:`dnc.gateway.Gateway`."""

    def __init__(self, gateway: Gateway, config: ModbusConfig):
        self.gateway = gateway
        self.config = config
        self.size = BLOCK * len(gateway.ports)
        self.loop: asyncio.AbstractEventLoop | None = None
        self.server: ModbusTcpServer | None = None
        self.thread: threading.Thread | None = None

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
                worker = self.gateway.port(i)
                log.info("%s: Modbus asks to send program %d", worker.config.name, number)
                worker.submit(Job(str(number), "modbus"))
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
        why = "writes are disabled (modbus.allow_write = false)"
        log.warning("%s: Modbus write refused (function %d, address %d): %s", name, function,
                    address, why)
        moment = now_utc()
        self.gateway.record(Transfer(name, "command", f"modbus function {function} at "
                                     f"{address}", 0, 0, moment, moment, "refused", [why]))

    def _abort(self, index: int) -> None:
        worker = self.gateway.port(index)
        log.info("%s: Modbus asks to abort", worker.config.name)
        worker.abort()

    # -- running -------------------------------------------------------------------------------

    def start(self) -> None:
        """Listen; raises :class:`TapegateError` when the address cannot be bound."""
        ready = threading.Event()
        failure: list[BaseException] = []

        async def serve() -> None:
            try:
                self.server = ModbusTcpServer(self.device(),
                                              address=(self.config.host, self.config.port))
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
                                f"{self.config.port}: {why}")
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
