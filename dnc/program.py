"""What ``send`` sends: the program's lines, optionally converted for the machine and restarted
from a block with a preamble that restores the modal state in force there.

Everything streams from disk: the program is read once to check it, once to find a restart
block (when asked), once to count the bytes and prove every character can be carried by the tape
code, and once while sending. Memory stays flat for a program of any size.
"""

from __future__ import annotations

import os
import tempfile
from collections.abc import Iterator
from dataclasses import dataclass, field

from dnc.framing import split_lines
from formats import _core
from formats.convert import ConvertOptions, ConvertStats, convert_file
from formats.errors import TapegateError
from formats.parser import MAX_BLOCK, whole_lines
from formats.profile import Profile
from formats.source import Source
from postproc.check import Finding, iter_check_file
from postproc.restart import plan_restart_text
from postproc.rules import rule_id
from postproc.state import ModalState


@dataclass
class Restart:
    line: int  # the first block sent after the preamble
    label: str  # how the operator named it (N120)
    state: ModalState
    preamble: list[str] = field(default_factory=list)
    alignment: tuple[str, int] | None = None  # nearest ":" block at or before a sequence number
    # the restart block as sent, where it must write the motion mode it inherits (G02 ...)
    first_block: str | None = None
    notes: list[str] = field(default_factory=list)  # what the operator must know (units)


def converted_copy(path: str, profile: Profile, source: Profile | None) -> tuple[str,
                                                                                ConvertStats]:
    """Convert ``path`` to the profile's format into a temporary file (the caller removes it)."""
    fd, tmp = tempfile.mkstemp(prefix="tapegate-send-", suffix=".nc")
    os.close(fd)
    try:
        stats = convert_file(path, tmp, ConvertOptions(profile, source), overwrite=True,
                             display=path)
    except BaseException:
        os.unlink(tmp)
        raise
    return tmp, stats


# A line no run reaches (TG108): not sent without saying so.
NEVER_RUN = rule_id("NeverRun")


# Warnings of what the control may run otherwise than tapegate read it, shown before a send
# (the program still goes): a '(' inside a Fanuc or Haas comment read once though no source
# settles how the control reads it (TG136), a block skip in the middle of a block (TG128).
SHOWN = frozenset({rule_id("NestedCommentRead"), rule_id("SkipWithinBlock")})


def check(path: str, profile: Profile, display: str) -> tuple[list[Finding], list[Finding]]:
    """The findings that stop a send -- the errors a check finds, and TG108's lines tapegate
    cannot read that it takes as never run (a warning of the check, but no block tapegate has
    read: they are sent as written only with --force, and said) -- and the warnings the
    operator must see before the first byte leaves (:data:`SHOWN`). Other warnings are shown
    by ``tapegate check``, not here."""
    _, findings = iter_check_file(path, profile, display=display)
    stops: list[Finding] = []
    shown: list[Finding] = []
    for f in findings:
        if f.severity == "error" or f.rule == NEVER_RUN:
            stops.append(f)
        elif f.rule in SHOWN:
            shown.append(f)
    return stops, shown


def find_restart(path: str, profile: Profile, target: str, display: str) -> Restart:
    """The block named ``target`` -- a sequence number (``N120``, ``120``) or an alignment label
    (``:1000``, an intermediate rewind stop of clause 4) -- the modal state in force before it
    and the preamble that restores it with a safe approach
    (:func:`postproc.restart.plan_restart_text`; :class:`~postproc.restart.RestartRefused` where
    that cannot be done safely). For a sequence number the nearest alignment block at or before
    it is noted as the safe restart point. Both the search and the walk to the block are the
    core's: no Python object is made per block."""
    text = target.strip().upper()
    prefix = ":" if text.startswith(":") else "N"
    number = text[1:] if text[:1] in ":N" else text
    if not number.isdigit():
        raise TapegateError(f"--restart-at {target!r}: give a sequence number (N120) or an "
                            "alignment label (:1000)", file=display, code="restart-target")
    wanted = int(number)
    line: int | None = None
    alignment: tuple[str, int] | None = None
    for text, before, unread in whole_lines(Source(path).chunks()):
        if unread is not None:  # the last line, without its LF (a block too long: no more)
            if len(text) > MAX_BLOCK or not text:
                break
            text += "\n"
        line, alignment = _core.find_numbered(text[:-1], before, profile.dialect.flags, prefix,
                                              str(wanted), alignment)
        if line is not None:
            break
    if line is None:
        raise TapegateError(f"no block {prefix}{wanted} to restart at", file=display,
                            code="restart-no-block")
    plan = plan_restart_text(Source(path).chunks(), profile, line, display)
    nearest = alignment if prefix == "N" else None
    return Restart(line, f"{prefix}{wanted}", plan.state, plan.preamble, nearest,
                   plan.first_block, plan.notes)


def program_lines(path: str, restart: Restart | None = None) -> Iterator[tuple[int, str]]:
    """Numbered lines of the program as sent. With a restart: the ``%`` line and its
    identification, the preamble (numbered with the restart line), then the program from the
    restart block on (written with the motion mode it inherits, where it must be)."""
    lines = split_lines(Source(path).chunks())
    return lines if restart is None else _restarted(lines, restart)


def _restarted(lines: Iterator[tuple[int, str]], restart: Restart
               ) -> Iterator[tuple[int, str]]:
    started = restored = False
    for number, text in lines:
        if number < restart.line:
            if not started and text.strip():
                started = True
                if text.lstrip().startswith("%"):
                    yield number, text
            continue
        if not restored:
            restored = True
            for block in restart.preamble:
                yield restart.line, block
            if restart.first_block is not None:
                yield number, restart.first_block
                continue
        yield number, text
