"""The gateway's commands from outside, "send program N" and "abort", one code path for every
way in (Modbus holding registers and coil, MQTT command messages): the same refusals, the same
log lines and the same journal records (a ``command`` record), whatever carried them."""

from __future__ import annotations

import logging

from dnc.gateway import Gateway, Job, State
from dnc.journal import Transfer, now_utc

log = logging.getLogger("tapegate.commands")

# how each way in is named in the log ("Modbus asks to send program 1234") and in the journal
# ("modbus send 1234"); it is also the origin of the job
VIA = {"modbus": "Modbus", "mqtt": "MQTT"}


def send_program(gateway: Gateway, index: int, number: int, via: str) -> str:
    """Queue program ``number`` on port ``index``: sent on the control's next DC1, checked
    and looked up as a remote request is. Returns ``"queued"``, or ``"refused"`` when the
    service is stopping; a port that is offline takes it and sends it once it is open again
    (journalled ``queued``, with the reason)."""
    worker = gateway.port(index)
    if worker.status.state == State.STOPPED:
        _not_open(gateway, index, number, "refused", via)
        return "refused"
    if worker.status.state == State.OFFLINE:
        _not_open(gateway, index, number, "queued", via)
    log.info("%s: %s asks to send program %d", worker.config.name, VIA[via], number)
    worker.submit(Job(str(number), via))
    return "queued"


def abort(gateway: Gateway, index: int, via: str) -> None:
    """Abort the transfer under way on port ``index`` and drop the programs queued for it."""
    worker = gateway.port(index)
    log.info("%s: %s asks to abort", worker.config.name, VIA[via])
    worker.abort()


def refuse(gateway: Gateway, port: str, what: str, why: str, result: str = "refused") -> None:
    """A command not carried out (commands disabled, a malformed one): logged and journalled
    as a ``command`` record naming what was asked (``what``) and why."""
    log.warning("%s: %s %s: %s", port, what, result, why)
    moment = now_utc()
    gateway.record(Transfer(port, "command", what, 0, 0, moment, moment, result, [why]))


def _not_open(gateway: Gateway, index: int, number: int, result: str, via: str) -> None:
    """"Send program N" to a port that is not open: ``queued`` for a port that is offline,
    ``refused`` when the service is stopping; logged and journalled either way."""
    worker = gateway.port(index)
    state = "offline" if worker.status.state == State.OFFLINE else "stopped"
    why = f"port {worker.config.name} is {state}: {worker.status.message}"
    log.warning("%s: %s send of program %d %s: %s", worker.config.name, VIA[via], number,
                result, why)
    moment = now_utc()
    gateway.record(Transfer(worker.config.name, "command", f"{via} send {number}", 0, 0, moment,
                            moment, result, [why]))
