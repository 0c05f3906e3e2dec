"""The transfer journal: an append-only JSON Lines audit log of every transfer.

One line per transfer (port, direction, program, bytes, blocks, start, end, result, errors,
SHA-256 of the content). Each line is written with a single ``write`` on a file opened for
appending and fsync'd before the call returns, so a crash loses nothing already journalled; at
worst the line being written is torn, and readers skip a torn last line and say so.
"""

from __future__ import annotations

import json
import os
from dataclasses import asdict, dataclass, field
from datetime import UTC, datetime
from pathlib import Path

from formats.errors import TapegateError


@dataclass
class Transfer:
    port: str
    direction: str  # send | receive | command (a Modbus write refused)
    program: str
    bytes: int
    blocks: int
    start: str  # ISO 8601, UTC
    end: str
    result: str  # ok | failed | interrupted | parity errors; the gateway adds request,
    # not found, forbidden, bad request, differs, refused, aborted; send and the gateway
    # journal a pass the control abandoned by a reset and rewind as "rewound"
    errors: list[str] = field(default_factory=list)
    sha256: str = ""


def now_utc() -> str:
    return datetime.now(UTC).isoformat(timespec="milliseconds")


class Journal:
    def __init__(self, path: str | Path):
        self.path = Path(path)

    def append(self, transfer: Transfer) -> None:
        line = json.dumps(asdict(transfer), ensure_ascii=False, separators=(",", ":")) + "\n"
        self.path.parent.mkdir(parents=True, exist_ok=True)
        fd = os.open(self.path, os.O_WRONLY | os.O_APPEND | os.O_CREAT, 0o644)
        try:
            os.write(fd, line.encode("utf-8"))
            os.fsync(fd)
        finally:
            os.close(fd)


@dataclass
class Reading:
    transfers: list[Transfer]
    torn: int = 0  # unreadable lines skipped (a crash while writing the last one)


def read_journal(path: str | Path, *, port: str | None = None,
                 since: datetime | None = None) -> Reading:
    """The journal's transfers, optionally of one port and from a moment on."""
    path = Path(path)
    out: list[Transfer] = []
    torn = 0
    try:
        lines = path.read_text("utf-8", errors="replace").splitlines()
    except FileNotFoundError:
        raise TapegateError("no journal here yet", file=str(path),
                            code="journal-missing") from None
    for text in lines:
        if not text.strip():
            continue
        try:
            transfer = Transfer(**json.loads(text))
        except (ValueError, TypeError):
            torn += 1
            continue
        if port is not None and transfer.port != port:
            continue
        if since is not None and _moment(transfer.start) < since:
            continue
        out.append(transfer)
    return Reading(out, torn)


def _moment(text: str) -> datetime:
    moment = datetime.fromisoformat(text)
    return moment if moment.tzinfo else moment.replace(tzinfo=UTC)


def parse_since(text: str) -> datetime:
    """``--since``: an ISO date or date and time (UTC unless it names a zone)."""
    try:
        return _moment(text)
    except ValueError:
        raise TapegateError(f"--since {text!r}: give a date such as 2026-11-21 or "
                            "2026-11-21T08:00", code="usage") from None


def table(transfers: list[Transfer]) -> str:
    rows = [("start", "port", "dir", "program", "bytes", "blocks", "result", "sha256")]
    for t in transfers:
        rows.append((t.start[:19].replace("T", " "), t.port, t.direction, t.program,
                     str(t.bytes), str(t.blocks), t.result + (f" ({len(t.errors)} errors)"
                                                             if t.errors else ""),
                     t.sha256[:12]))
    widths = [max(len(r[i]) for r in rows) for i in range(len(rows[0]))]
    return "\n".join("  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip()
                     for r in rows)
