"""``tapegate send``, ``receive`` and ``emulate``: the serial commands.

Every serial command takes the link settings from the profile with the same overrides, and
prints failures as one line naming the block reached. Exit codes: 0 done; 1 the program or the
data is bad (check errors, parity errors, alarms in the emulator); 2 usage or unreadable file;
3 the link failed (port, timeout, control alarm).
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import signal
import sys
import threading
import time
from collections.abc import Callable
from dataclasses import asdict, replace
from decimal import ROUND_CEILING, Decimal
from pathlib import Path
from typing import Any, TypeVar

import click
from tqdm import tqdm

from dnc import workflow
from dnc.control import Control, ControlStats
from dnc.emulator import DprntSchedule, RewindButton, print_data
from dnc.framing import Framer
from dnc.journal import Journal, Transfer, now_utc, parse_since, read_journal, table
from dnc.link import (
    LinkError,
    Port,
    chars_per_second,
    describe,
    flow_settings,
    open_port,
    override,
)
from dnc.program import program_lines
from dnc.receiver import Receiver
from dnc.session import (
    HOST_WAIT,
    SendProgress,
    open_pty,
    punch,
    receive_program,
    run_control,
    wait_hang_up,
)
from dnc.workflow import StopSignals
from formats.errors import OutputError, TapegateError
from formats.files import count_lines, sha256_of, write_atomic
from formats.profile import Profile, SerialSettings
from tapegate.common import get_profile, input_path, plural, user_errors
from tapegate.options import FiniteRange, Height, profile_option

F = TypeVar("F", bound=Callable[..., Any])


def journal_option(func: F) -> F:
    return click.option("--journal", type=click.Path(dir_okay=False),
                        help="Append a record of the transfer to this JSON Lines journal.")(func)


def serial_options(func: F) -> F:
    """The overrides every serial command accepts."""
    options = [
        click.option("--baud", type=click.Choice(["110", "150", "300", "600", "1200", "2400",
                                                  "4800", "9600", "19200", "38400", "57600",
                                                  "115200"]), help="Baud rate."),
        click.option("--data-bits", type=click.Choice(["7", "8"])),
        click.option("--parity", type=click.Choice(["none", "even", "odd"])),
        click.option("--stop-bits", type=click.Choice(["1", "2"])),
        click.option("--flow", type=click.Choice(["xonxoff", "rtscts", "none"])),
        click.option("--parity-mode", type=click.Choice(["uart", "software"]),
                     help="ISO parity by the UART (7E) or set in bit 8 by tapegate (8N)."),
        click.option("--code", type=click.Choice(["iso", "eia"]), help="Tape code."),
    ]
    for option in reversed(options):
        func = option(func)
    return func


def link_settings(prof: Profile, kw: dict[str, Any]) -> SerialSettings:
    number = {k: int(kw.pop(k)) if kw.get(k) is not None else kw.pop(k, None)
              for k in ("baud", "data_bits", "stop_bits")}
    text = {k: kw.pop(k, None) for k in ("parity", "flow", "parity_mode", "code")}
    return override(prof.serial, **number, **text)


def folder_problem(folder: Path) -> str | None:
    """Why files cannot be made in ``folder`` (or in it once made): a part of its path that is
    a file, not a folder. ``None`` where nothing stands in the way (a missing folder is made)."""
    for part in (folder, *folder.parents):
        if part.exists():
            return None if part.is_dir() else f"{part} is not a folder"
    return None


def journal_for(path: str | None) -> workflow.Record | None:
    """The journal to append a transfer's record to, proven writable before anything is sent
    or received: one that cannot be written is an :class:`OutputError` (exit 2)."""
    if path is None:
        return None
    target = Path(path)
    problem = folder_problem(target.parent)
    try:
        if problem:
            raise NotADirectoryError(0, problem)
        target.parent.mkdir(parents=True, exist_ok=True)
        os.close(os.open(target, os.O_WRONLY | os.O_APPEND | os.O_CREAT, 0o644))
    except OSError as exc:
        raise OutputError(f"cannot write the journal {path}: {exc.strerror or exc}") from None
    journal = Journal(target)

    def record(transfer: Transfer) -> None:
        try:
            journal.append(transfer)
        except OSError as exc:  # a full disk
            raise OutputError(f"cannot append to the journal {path}: "
                              f"{exc.strerror or exc}") from None

    return record


# ---------------------------------------------------------------------------------------------
# send


class SendBar:
    """The progress bar: bytes, block, rate, ETA, and whether the control holds the line. It
    ends at 100 % when the closing ``%`` is out: the trailer is not counted, since a control's
    DC3 after the ``%`` ends the pass with trailer still unsent."""

    def __init__(self, total: int, enabled: bool):
        self.total = total
        self.bar = tqdm(total=total, unit="B", unit_scale=True, disable=not enabled,
                        dynamic_ncols=True, desc="sending", leave=True)
        self.state = ""

    def __call__(self, p: SendProgress) -> None:
        if self.bar.disable:
            return
        state = ("waiting for DC1" if p.waiting else "paused by control" if p.paused
                 else "sending")
        if state != self.state:
            self.state = state
            self.bar.set_description(state, refresh=False)
        self.bar.set_postfix_str(f"line {p.line}", refresh=False)
        self.bar.update(min(p.sent, self.total) - self.bar.n)

    def close(self) -> None:
        self.bar.close()


@click.command(short_help="Drip-feed a program to a control, checked and paced.")
@click.argument("file", type=click.Path(dir_okay=False))
@click.option("--port", required=True, help="Port URL: /dev/ttyUSB0, COM3, rfc2217://host:port, "
                                            "socket://host:port, loop://")
@profile_option()
@serial_options
@click.option("--restart-at", "restart_at", help="Restart from this block (N120, or an "
              "alignment label :1000) with a preamble that restores the modal state.")
@click.option("--clearance", type=Height(), metavar="Z",
              help="With --restart-at: the safe height the approach rapids at, in the "
                   "profile's units (the profile's [restart] clearance for this send).")
@click.option("--convert", "do_convert", is_flag=True,
              help="Convert to the profile's format on the way (see tapegate convert).")
@click.option("--from", "from_profile", help="Profile the program was written for (--convert; "
                                             "default: detected).")
@click.option("--repeat", is_flag=True, help="Send again from % on the next DC1 (production).")
@click.option("--passes", type=click.IntRange(1), help="With --repeat: stop after this many.")
@click.option("--force", is_flag=True, help="Send even when the check finds errors.")
@click.option("--yes", "-y", is_flag=True, help="Do not ask before sending a restart.")
@click.option("--xon-timeout", type=FiniteRange(0.1), help="Seconds to wait for DC1.")
@click.option("--dc3-reaction", type=FiniteRange(0), metavar="SECONDS",
              help="The longest this host may take to see the control's DC3; the sender "
                   "slows down where the allowance would not cover it (default: the "
                   "profile's dc3_reaction, else 0: the wire's pace).")
@click.option("--progress/--no-progress", default=None,
              help="Progress bar (default: when stderr is a terminal).")
@journal_option
@user_errors
def send(file: str, port: str, profile: str | None, restart_at: str | None,
         clearance: Decimal | None, do_convert: bool,
         from_profile: str | None, repeat: bool, passes: int | None, force: bool, yes: bool,
         xon_timeout: float | None, dc3_reaction: float | None, progress: bool | None,
         journal: str | None, **kw: Any) -> None:
    """Drip-feed FILE to a control, checked first, paced so a DC3 is never overrun.

    SIGINT (Ctrl-C) or SIGTERM ends the transfer cleanly: it is journalled "interrupted" and
    the command exits 130 (SIGINT) or 143 (SIGTERM)."""
    path = input_path(file)  # (a pipe by its name read from a copy; a device refused)
    prof = get_profile(profile, path)
    if clearance is not None:
        if not restart_at:
            raise click.UsageError("--clearance is the approach height of --restart-at")
        fmt = prof.word_format("Z", prof.default_units)  # rounded up, as the restart will
        if not (fmt.holds(clearance)
                and fmt.holds(clearance.quantize(fmt.resolution, rounding=ROUND_CEILING))):
            raise click.BadParameter(
                f"{clearance} has more digits before the decimal sign than the profile's Z "
                f"format {fmt.spec()} holds ({fmt.before} in {prof.default_units})",
                param_hint="'--clearance'")
        # the operator's safe height, as the profile's own [restart] clearance would be
        prof = replace(prof, restart=replace(prof.restart, clearance=clearance))
    settings = override(link_settings(prof, kw), dc3_reaction=dc3_reaction)
    open(path, "rb").close()
    source = get_profile(from_profile) if do_convert and from_profile else None
    record = journal_for(journal)
    show = sys.stderr.isatty() if progress is None else progress
    with StopSignals() as signals:
        try:
            with workflow.prepare(path, prof, settings, name=file, force=force,
                                  restart_at=restart_at, convert=do_convert, source=source,
                                  on_event=_prepared) as program:
                if program.restart and not yes:
                    _confirm_restart()
                _framed(program)
                _send(program, port, workflow.Passes(repeat, passes, xon_timeout=xon_timeout),
                      record, show, signals)
        except KeyboardInterrupt:  # before the transfer began: nothing was sent
            click.echo(f"tapegate: {signals.name}: interrupted before sending", err=True)
            sys.exit(signals.exit_code)


def _confirm_restart() -> None:
    """A restart moves the machine from the middle of a program: it is sent only once the
    operator has read the preamble and said so, on a terminal by the question, elsewhere (a
    script, a pipe) by ``--yes``. Without either nothing is sent (exit 1)."""
    if not sys.stdin.isatty():
        click.echo("tapegate: not sent: a restart is sent only when confirmed, and there is no "
                   "terminal to ask on; read the preamble above and pass --yes (-y) to send it",
                   err=True)
        sys.exit(1)
    if not click.confirm("send?", err=True):
        sys.exit(1)


def _prepared(event: workflow.Event) -> None:
    """What the preparation found, as messages."""
    if isinstance(event, workflow.Converted):
        for note in event.stats.notes:
            click.echo(f"convert: {note}", err=True)
        click.echo(f"converted for {event.profile}: {event.stats.changed} words changed",
                   err=True)
    elif isinstance(event, workflow.CheckWarnings):
        for finding in event.findings[:10]:
            click.echo(str(finding), err=True)
        if len(event.findings) > 10:
            click.echo(f"tapegate: {len(event.findings) - 10} more such warning(s): see "
                       "tapegate check", err=True)
    elif isinstance(event, workflow.CheckErrors):
        for finding in event.findings[:10]:
            click.echo(str(finding), err=True)
        if event.forced:
            click.echo(f"tapegate: sending despite {len(event.findings)} error(s) (--force)",
                       err=True)
    elif isinstance(event, workflow.RestartFound):
        restart = event.restart
        if restart.alignment:
            label, line = restart.alignment
            click.echo(f"the nearest alignment block before it is {label} (line {line}), an "
                       f"intermediate rewind stop: --restart-at {label} restarts there",
                       err=True)
        click.echo(f"restart at {restart.label} (line {restart.line}); preamble:", err=True)
        for block in restart.preamble:
            click.echo(f"    {block}", err=True)
        if restart.first_block is not None:
            click.echo(f"then line {restart.line} with the motion mode it inherits written in: "
                       f"{restart.first_block.strip()}", err=True)
        for note in restart.notes:
            click.echo(f"note: {note}", err=True)


def _framed(program: workflow.Program) -> None:
    stats, s = program.frame, program.settings
    if stats.left_after_end:
        click.echo(f"{program.name}: {stats.left_after_end} line(s) after the closing % are "
                   "not sent", err=True)
    if stats.cr_by_lf:
        click.echo(f"{program.name}: {stats.cr_by_lf} CR next to LF not sent: the profile's "
                   "end of block ends each block", err=True)
    click.echo(f"{program.name}: {program.total} bytes, {stats.blocks} blocks, {describe(s)}"
               + (f", {stats.padded} blocks padded for the TV check" if stats.padded else ""),
               err=True)


def _send(program: workflow.Program, port_url: str, passes: workflow.Passes,
          record: workflow.Record | None, show: bool, signals: StopSignals) -> None:
    try:
        port = open_port(port_url, program.settings)
    except LinkError as exc:
        if record:
            record(workflow.transfer(port_url, program, None, now_utc(), "failed",
                                     [exc.message]))
        raise
    with signals.transferring():  # from here a signal ends the transfer, journalled
        bar = SendBar(program.through_end, False)

        def shown(event: workflow.Event) -> None:
            nonlocal bar
            if isinstance(event, workflow.Waiting):
                bar = SendBar(program.through_end, show)
            elif isinstance(event, workflow.Progress):
                bar(event.progress)
            elif isinstance(event, workflow.Rewinding):
                bar.close()
                click.echo(f"tapegate: {event.message}; sending again from % on the control's "
                           "next DC1", err=True)
            elif isinstance(event, workflow.PassDone):
                bar(event.progress)
                bar.close()
                which = f"pass {event.number}: " if passes.repeat else ""
                click.echo(which + workflow.summary(event.progress, program.settings), err=True)
                if passes.repeat and (passes.passes is None or event.number < passes.passes):
                    click.echo("waiting for the control's next DC1 (Ctrl-C or SIGTERM to stop)",
                               err=True)

        try:
            outcome = workflow.run(port, program, passes, port_name=port_url, record=record,
                                   on_event=shown, stop=signals)
        finally:
            bar.close()
            port.close()
    if outcome.result != "ok":
        click.echo(f"tapegate: {signals.name}: interrupted at line {outcome.progress.line}, "
                   f"{outcome.progress.sent} bytes sent", err=True)
        sys.exit(signals.exit_code)


# ---------------------------------------------------------------------------------------------
# receive


@click.command(short_help="Receive a program the control punches.")
@click.option("--port", required=True, help="Port URL (see tapegate send).")
@profile_option()
@serial_options
@click.option("-o", "--output", required=True, type=click.Path(),
              help="A folder (the file is named from the program number) or a file name.")
@click.option("--timeout", type=FiniteRange(0.1), help="Give up if nothing arrives within "
                                                      "this many seconds (default: wait).")
@click.option("--idle", type=FiniteRange(0.05), default=5.0, show_default=True,
              help="Seconds of silence that end a program without DC4 or closing %.")
@journal_option
@user_errors
def receive(port: str, profile: str | None, output: str, timeout: float | None, idle: float,
            journal: str | None, **kw: Any) -> None:
    """Receive a program punched by the control (DC2 ... DC4), ISO or EIA detected.

    SIGINT (Ctrl-C) or SIGTERM ends the transfer cleanly: nothing is written, it is journalled
    "interrupted" and the command exits 130 (SIGINT) or 143 (SIGTERM)."""
    prof = get_profile(profile)
    code_given = kw.get("code")
    settings = link_settings(prof, kw)
    target = Path(output)
    folder = target if output.endswith(("/", os.sep)) or target.is_dir() else target.parent
    problem = folder_problem(folder)
    if problem:
        raise OutputError(f"cannot write {output}: {problem}")
    if output.endswith(("/", os.sep)):
        target.mkdir(parents=True, exist_ok=True)
    record = journal_for(journal)
    with StopSignals() as signals:
        try:
            link = open_port(port, settings, receive_parity_marks=True)
        except KeyboardInterrupt:
            click.echo(f"tapegate: {signals.name}: interrupted before receiving", err=True)
            sys.exit(signals.exit_code)
        with signals.transferring():  # from here a signal ends the transfer, journalled
            uart = settings.parity_mode == "uart"
            receiver = Receiver(code=code_given, uart_parity=uart,
                                parity_marks=uart and link.is_tty and settings.parity != "none",
                                idle_timeout=idle, start_timeout=timeout, now=time.monotonic())
            click.echo(f"waiting for the control on {port} ({describe(settings)})", err=True)
            started = now_utc()

            def ended(result: str, errors: list[str], path: Path | None = None) -> None:
                if record:
                    record(Transfer(port, "receive", str(path or ""), receiver.bytes,
                                    count_lines(path) if path else 0, started, now_utc(), result,
                                    errors, sha256_of(path) if path else ""))

            try:
                result = receive_program(link, receiver, target,
                                         program_letter=prof.program_number or "O",
                                         stop=lambda: signals() is not None)
            except (LinkError, OutputError) as exc:  # an output error: a full disk, permissions
                ended("failed", [exc.message])
                raise
            finally:
                link.close()
    if result.reason == "interrupted":
        ended("interrupted", [f"{signals.name} after {receiver.bytes} bytes: nothing written"])
        click.echo(f"tapegate: {signals.name}: interrupted after {receiver.bytes} bytes; "
                   "nothing written", err=True)
        sys.exit(signals.exit_code)
    errors = [f"{i.line}:{i.column}: {i.message()}" for i in result.issues]
    ended("no data" if result.path is None else "parity errors" if errors else "ok", errors,
          result.path)
    if result.path is None:
        click.echo(f"tapegate: nothing received ({result.reason})", err=True)
        sys.exit(3)
    code = (result.code or "iso").upper()
    click.echo(f"received {result.path}: {result.chars} characters from {result.bytes} bytes, "
               f"{code} code, ended by {result.reason}", err=True)
    for issue in result.issues:
        click.echo(f"{result.path}:{issue.line}:{issue.column}: {issue.message()} "
                   "(kept in the file)", err=True)
    if result.issues:
        sys.exit(1)


# ---------------------------------------------------------------------------------------------
# journal


@click.command("journal")
@click.argument("file", type=click.Path(dir_okay=False))
@click.option("--port", help="Only this port.")
@click.option("--since", help="Only transfers from this moment (2026-11-21, 2026-11-21T08:00).")
@click.option("--json", "as_json", is_flag=True, help="The selected lines as JSON Lines.")
@user_errors
def journal_command(file: str, port: str | None, since: str | None, as_json: bool) -> None:
    """Show the transfer journal as a table."""
    try:
        moment = parse_since(since) if since else None
    except TapegateError as exc:  # a usage error: exit 2, as click's own
        raise click.BadParameter(exc.message, param_hint="--since") from None
    reading = read_journal(file, port=port, since=moment)  # none there: journal-missing, exit 2
    if reading.torn and not reading.transfers and moment is None and port is None:
        click.echo(f"{file}: not a transfer journal: none of its {reading.torn} line(s) is a "
                   "record", err=True)
        sys.exit(1)
    if as_json:
        for t in reading.transfers:
            click.echo(json.dumps(asdict(t)))
    else:
        click.echo(table(reading.transfers))
    if reading.torn:
        click.echo(f"{file}: {reading.torn} unreadable line(s) skipped (a transfer cut off "
                   "while being journalled)", err=True)


# ---------------------------------------------------------------------------------------------
# emulate


@click.command(short_help="Emulate a legacy control on a pseudo-terminal.")
@profile_option()
@serial_options
@click.option("--port", help="Attach to this port instead of opening a pseudo-terminal.")
@click.option("--buffer", type=click.IntRange(16), default=256, show_default=True,
              help="The control's input buffer, characters.")
@click.option("--rate", type=FiniteRange(1), help="Characters per second the control "
                                                  "consumes (default: as fast as they come).")
@click.option("--programs", type=click.IntRange(0), default=1, show_default=True,
              help="Programs to read before exiting (0: until interrupted).")
@click.option("--save", type=click.Path(dir_okay=False), help="Save the programs read here.")
@click.option("--punch", "punch_file", type=click.Path(exists=True, dir_okay=False),
              help="Send this program to the host instead (DC2 ... DC4).")
@click.option("--dc1-every", type=FiniteRange(0.01), default=1.0, show_default=True,
              help="Repeat DC1 this often while waiting for a program.")
@click.option("--rewind-after", type=click.IntRange(1), metavar="BLOCKS",
              help="The operator presses RESET and rewinds once, after this many blocks of the "
                   "first program (signal USR1 rewinds at any moment).")
@click.option("--dprnt-every", type=FiniteRange(0.01), metavar="SECONDS",
              help="The control's macro prints machine data every SECONDS: (CYCLE START O1234), "
                   "then (CYCLE END O1234) and PARTS=n, and again (POPEN/DPRNT/PCLOS).")
@click.option("--dprnt-form", type=click.Choice(["fanuc", "haas"]), default="fanuc",
              show_default=True, help="fanuc: DC2, lines ended by LF, DC4; haas: lines ended "
                                      "by CR LF.")
@click.option("--dprnt-program", default="O1234", show_default=True,
              help="The program number in the cycle lines.")
@click.option("--dprnt-cycles", type=click.IntRange(1), metavar="N",
              help="Print N cycles, then exit (default: until interrupted).")
@click.option("--json", "as_json", is_flag=True, help="Statistics as JSON on stdout.")
@user_errors
def emulate(profile: str | None, port: str | None, buffer: int, rate: float | None, programs: int,
            save: str | None, punch_file: str | None, dc1_every: float,
            rewind_after: int | None, dprnt_every: float | None, dprnt_form: str,
            dprnt_program: str, dprnt_cycles: int | None, as_json: bool, **kw: Any) -> None:
    """Behave like a legacy control on a pseudo-terminal: DC1/DC3, alarm 087, TH/TV checks,
    label skip, the operator's reset and rewind, and machine data printed by a macro
    (--dprnt-every)."""
    if not re.fullmatch(r"O\d{1,8}", dprnt_program):
        raise click.UsageError(f"--dprnt-program {dprnt_program!r}: give a program number "
                               "such as O1234")
    prof = get_profile(profile)
    settings = link_settings(prof, kw)
    if save and not Path(save).parent.is_dir():  # found before the control starts, not after
        raise OutputError(f"cannot write {save}: "
                          f"{folder_problem(Path(save).parent) or 'no such folder'}")
    data = None
    if punch_file:
        framer = Framer(settings, file=punch_file)
        data = framer.leader() + b"".join(
            d for _, d in framer.frames(program_lines(punch_file))) + framer.trailer()
        if not framer.stats.blocks:
            raise TapegateError("nothing to punch: the program has no blocks", file=punch_file,
                                code="punch-empty")
    pty = None
    link: Port | None = None
    if port:
        link = open_port(port, settings)
        if link.fd is None:
            click.echo(f"tapegate: {port} has no file descriptor to serve", err=True)
            sys.exit(2)
        fd, path = link.fd, port
    else:
        pty = open_pty()
        fd, path = pty.master, pty.path
    click.echo(f"port: {path}", err=True)
    click.echo(f"emulating {prof.name} ({describe(settings)}), buffer {buffer}, "
               + (f"consuming {rate:g} chars/s" if rate else "not throttling"), err=True)
    try:
        if data is not None:
            sent = punch(fd, data, flow_settings(settings, wait_for_dc1=False), announce=1.0)
            if pty:  # closing the pty would throw away what the host has not read yet
                pty.release()
                wait_hang_up(fd, HOST_WAIT)
            click.echo(f"punched {punch_file}: {sent} bytes", err=True)
            return
        control = Control(cps=chars_per_second(settings), code=settings.code,
                          software_parity=settings.parity_mode == "software", buffer=buffer,
                          rate=rate, allowance=settings.overrun_allowance,
                          tv_check=settings.tv_check, dc1_every=dc1_every,
                          programs=programs or None, now=time.monotonic(),
                          dialect=prof.dialect)
        button = RewindButton(control, rewind_after)
        interrupted = threading.Event()
        done = threading.Event()
        printer = None
        if dprnt_every is not None:
            schedule = DprntSchedule(dprnt_every, dprnt_program, dprnt_form, dprnt_cycles)
            click.echo(f"printing machine data every {dprnt_every:g} s ({dprnt_form} DPRNT)"
                       + (f", {dprnt_cycles} cycle(s)" if dprnt_cycles else ""), err=True)

            def printing() -> None:
                print_data(fd, schedule, interrupted)
                # the cycles are printed: the emulator ends once the host has read the last
                # lines (closing the pty throws away what is unread; a real port's close
                # waits until its output has gone)
                if pty:
                    pty.wait_read(HOST_WAIT, stop=interrupted.is_set)
                done.set()

            printer = threading.Thread(target=printing, daemon=True)
            printer.start()
        previous = None
        if hasattr(signal, "SIGUSR1"):  # kill -USR1 PID: the operator rewinds now
            previous = signal.signal(signal.SIGUSR1, lambda *_: button.press())
        try:
            with contextlib.suppress(KeyboardInterrupt):
                run_control(fd, control, rewind=button.pressed,
                            stop=done.is_set if dprnt_cycles else lambda: False,
                            # (while DPRNT lines are printed the emulator keeps the host's
                            # end, so that the printer can wait until the host has read them;
                            # released under the printer, its wait would end at once)
                            release=pty.release if pty and printer is None else None,
                            linger=HOST_WAIT if pty else 0.5)
        finally:
            interrupted.set()
            done.set()
            if printer is not None:
                printer.join(5)
            if previous is not None:
                signal.signal(signal.SIGUSR1, previous)
        if control.stats.rewinds:
            click.echo(f"the operator rewound {plural(control.stats.rewinds, 'time')}", err=True)
        if save and control.programs:
            for text in control.programs:
                written = write_atomic(Path(save), text.encode("utf-8"), overwrite=False)
                click.echo(f"saved {written}", err=True)
        stats = control.stats
        if as_json:
            click.echo(json.dumps(stats_dict(stats, chars_per_second(settings))))
        else:
            click.echo(stats_text(stats, chars_per_second(settings)), err=True)
        if stats.errors:
            sys.exit(1)
    finally:
        if pty:
            pty.close()
        if link:
            link.close()


def stats_dict(s: ControlStats, cps: float) -> dict[str, Any]:
    span = (s.last - s.first) if s.first is not None else 0.0
    return {"chars": s.chars, "seconds": round(span, 4),
            "utilisation": round(s.utilisation(cps), 4), "programs": s.programs,
            "blocks": s.blocks, "dc3": s.dc3, "rewinds": s.rewinds,
            "most_after_dc3": s.most_after_dc3, "alarm_087": s.alarms_087,
            "th_errors": s.count("TH"), "tv_errors": s.count("TV"),
            "errors": [str(e) for e in s.errors]}


def stats_text(s: ControlStats, cps: float) -> str:
    d = stats_dict(s, cps)
    lines = [
        f"control read {d['programs']} program(s), {d['blocks']} blocks, {d['chars']} characters "
        f"in {d['seconds']:.2f} s (line utilisation {d['utilisation']:.1%})",
        f"DC3 sent {plural(d['dc3'], 'time')}; most characters after a DC3: {d['most_after_dc3']} "
        f"(alarm 087: {d['alarm_087']})",
        f"TH check errors: {d['th_errors']}; TV check errors: {d['tv_errors']}",
    ]
    lines += [f"  {e}" for e in d["errors"][:20]]
    return "\n".join(lines)
