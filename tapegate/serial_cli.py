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
import signal
import sys
import time
from collections.abc import Callable
from dataclasses import asdict
from pathlib import Path
from typing import Any, TypeVar

import click
from tqdm import tqdm

from dnc.control import Control, ControlStats
from dnc.emulator import RewindButton
from dnc.framing import Framer
from dnc.journal import Journal, Transfer, now_utc, parse_since, read_journal, table
from dnc.link import (
    LinkError,
    Port,
    Rewound,
    chars_per_second,
    describe,
    flow_settings,
    open_port,
    override,
)
from dnc.program import Restart, check, converted_copy, find_restart, program_lines
from dnc.receiver import Receiver
from dnc.session import SendProgress, open_pty, punch, receive_program, run_control, send_frames
from formats.errors import TapegateError
from formats.files import count_lines, sha256_of, write_atomic
from formats.profile import Profile, SerialSettings
from tapegate.cli import get_profile, plural, profile_option, user_errors

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


def link_failed(exc: LinkError) -> None:
    click.echo(f"tapegate: {exc.message}", err=True)
    sys.exit(3)


# ---------------------------------------------------------------------------------------------
# send


class SendBar:
    """The progress bar: bytes, block, rate, ETA, and whether the control holds the line."""

    def __init__(self, total: int, enabled: bool):
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
        self.bar.update(p.sent - self.bar.n)

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
@click.option("--convert", "do_convert", is_flag=True,
              help="Convert to the profile's format on the way (see tapegate convert).")
@click.option("--from", "from_profile", help="Profile the program was written for (--convert; "
                                             "default: detected).")
@click.option("--repeat", is_flag=True, help="Send again from % on the next DC1 (production).")
@click.option("--passes", type=click.IntRange(1), help="With --repeat: stop after this many.")
@click.option("--force", is_flag=True, help="Send even when the check finds errors.")
@click.option("--yes", "-y", is_flag=True, help="Do not ask before sending a restart.")
@click.option("--xon-timeout", type=click.FloatRange(0.1), help="Seconds to wait for DC1.")
@click.option("--dc3-reaction", type=click.FloatRange(0), metavar="SECONDS",
              help="The longest this host may take to see the control's DC3; the sender "
                   "slows down where the allowance would not cover it (default: the "
                   "profile's dc3_reaction, else 0: the wire's pace).")
@click.option("--progress/--no-progress", default=None,
              help="Progress bar (default: when stderr is a terminal).")
@journal_option
@user_errors
def send(file: str, port: str, profile: str | None, restart_at: str | None, do_convert: bool,
         from_profile: str | None, repeat: bool, passes: int | None, force: bool, yes: bool,
         xon_timeout: float | None, dc3_reaction: float | None, progress: bool | None,
         journal: str | None, **kw: Any) -> None:
    """Drip-feed FILE to a control, checked first, paced so a DC3 is never overrun."""
    prof = get_profile(profile, file)
    settings = link_settings(prof, kw)
    settings = override(settings, dc3_reaction=dc3_reaction)
    open(file, "rb").close()
    path, temporary = file, None
    if do_convert:
        source = get_profile(from_profile) if from_profile else None
        temporary, stats = converted_copy(file, prof, source)
        path = temporary
        for note in stats.notes:
            click.echo(f"convert: {note}", err=True)
        click.echo(f"converted for {prof.name}: {stats.changed} words changed", err=True)
    try:
        _send(file, path, prof, settings, port, restart_at, repeat, passes, force, yes,
              xon_timeout, progress, Journal(journal) if journal else None)
    finally:
        if temporary:
            os.unlink(temporary)


def _send(file: str, path: str, prof: Any, settings: SerialSettings, port_url: str,
          restart_at: str | None, repeat: bool, passes: int | None, force: bool, yes: bool,
          xon_timeout: float | None, progress: bool | None, journal: Journal | None) -> None:
    errors = check(path, prof, file)
    for finding in errors[:10]:
        click.echo(str(finding), err=True)
    if errors:
        more = " (first 10 shown)" if len(errors) > 10 else ""
        if not force:
            click.echo(f"tapegate: not sent: the check found {len(errors)} error(s){more}; "
                       "fix them or use --force", err=True)
            sys.exit(1)
        click.echo(f"tapegate: sending despite {len(errors)} error(s) (--force)", err=True)
    restart: Restart | None = None
    if restart_at:
        restart = find_restart(path, prof, restart_at, file)
        if restart.alignment:
            label, line = restart.alignment
            click.echo(f"the nearest alignment block before it is {label} (line {line}), an "
                       f"intermediate rewind stop: --restart-at {label} restarts there",
                       err=True)
        click.echo(f"restart at {restart.label} (line {restart.line}); preamble:", err=True)
        for block in restart.preamble:
            click.echo(f"    {block}", err=True)
        if not yes and sys.stdin.isatty() and not click.confirm("send?", err=True):
            sys.exit(1)
    framer = Framer(settings, file=file)
    total, digest = framer.measure(program_lines(path, restart))
    stats = framer.stats
    if stats.left_after_end:
        click.echo(f"{file}: {stats.left_after_end} line(s) after the closing % are not sent",
                   err=True)
    click.echo(f"{file}: {total} bytes, {stats.blocks} blocks, {describe(settings)}"
               + (f", {stats.padded} blocks padded for the TV check" if stats.padded else ""),
               err=True)
    show = sys.stderr.isatty() if progress is None else progress
    try:
        port = open_port(port_url, settings)
    except LinkError as exc:
        if journal:
            journal.append(Transfer(port_url, "send", file, 0, 0, now_utc(), now_utc(),
                                    "failed", [exc.message], digest))
        link_failed(exc)
    done = 0
    started = now_utc()
    progress_state = SendProgress()

    def record(result: str, errors: list[str]) -> None:
        if journal:
            journal.append(Transfer(port_url, "send", file, progress_state.sent,
                                    progress_state.lines, started, now_utc(), result, errors,
                                    digest))

    rewound = False
    try:
        while True:
            # after a pass or a rewind the control must ask again (DC1); in production
            # (--repeat) it may take as long as the operator likes
            again = bool(done) or rewound
            flow = flow_settings(settings, wait_for_dc1=True if again else None,
                                 xon_timeout=float("inf") if again and repeat else xon_timeout)
            rewound = False
            bar = SendBar(total, show)
            framer = Framer(settings, file=file)

            def update(p: SendProgress, bar: SendBar = bar) -> None:
                nonlocal progress_state
                progress_state = p
                bar(p)

            started = now_utc()
            try:
                result = send_frames(port, framer.frames(program_lines(path, restart)), flow,
                                     leader=framer.leader(), trailer=framer.trailer(),
                                     total=total, progress=update)
            except Rewound as exc:
                record("rewound", [exc.message])
                click.echo(f"tapegate: {exc.message}; sending again from % on the control's "
                           "next DC1", err=True)
                rewound = True
                continue
            finally:
                bar.close()
            progress_state = result
            done += 1
            record("ok", [])
            _report(result, settings, done if repeat else 0)
            if not repeat or (passes is not None and done >= passes):
                break
            click.echo("waiting for the control's next DC1 (Ctrl-C to stop)", err=True)
    except LinkError as exc:
        record("failed", [exc.message])
        link_failed(exc)
    except KeyboardInterrupt:
        record("interrupted", [])
        click.echo("tapegate: interrupted", err=True)
        sys.exit(130)
    finally:
        port.close()


def _report(p: SendProgress, s: SerialSettings, n: int) -> None:
    cps = chars_per_second(s)
    busy = max(p.elapsed - p.paused_time, 1e-9)
    rate = p.sent / busy
    which = f"pass {n}: " if n else ""
    click.echo(f"{which}sent {p.sent} bytes, {p.lines} lines in {p.elapsed:.2f} s; "
               f"{rate:.0f} chars/s while not paused (the line carries {cps:.0f}); "
               f"paused by the control {plural(p.pauses, 'time')} for {p.paused_time:.2f} s",
               err=True)


# ---------------------------------------------------------------------------------------------
# receive


@click.command(short_help="Receive a program the control punches.")
@click.option("--port", required=True, help="Port URL (see tapegate send).")
@profile_option()
@serial_options
@click.option("-o", "--output", required=True, type=click.Path(),
              help="A folder (the file is named from the program number) or a file name.")
@click.option("--timeout", type=click.FloatRange(0.1), help="Give up if nothing arrives within "
                                                           "this many seconds (default: wait).")
@click.option("--idle", type=click.FloatRange(0.05), default=5.0, show_default=True,
              help="Seconds of silence that end a program without DC4 or closing %.")
@journal_option
@user_errors
def receive(port: str, profile: str | None, output: str, timeout: float | None, idle: float,
            journal: str | None, **kw: Any) -> None:
    """Receive a program punched by the control (DC2 ... DC4), ISO or EIA detected."""
    prof = get_profile(profile)
    code_given = kw.get("code")
    settings = link_settings(prof, kw)
    target = Path(output)
    if output.endswith(("/", os.sep)):
        target.mkdir(parents=True, exist_ok=True)
    try:
        link = open_port(port, settings, receive_parity_marks=True)
    except LinkError as exc:
        link_failed(exc)
    uart = settings.parity_mode == "uart"
    receiver = Receiver(code=code_given, uart_parity=uart,
                        parity_marks=uart and link.is_tty and settings.parity != "none",
                        idle_timeout=idle, start_timeout=timeout, now=time.monotonic())
    click.echo(f"waiting for the control on {port} ({describe(settings)})", err=True)
    started = now_utc()
    try:
        result = receive_program(link, receiver, target, program_letter=prof.program_number or "O")
    except LinkError as exc:
        if journal:
            Journal(journal).append(Transfer(port, "receive", "", receiver.bytes, 0, started,
                                             now_utc(), "failed", [exc.message]))
        link_failed(exc)
    except KeyboardInterrupt:
        click.echo("tapegate: interrupted; nothing written", err=True)
        sys.exit(130)
    finally:
        link.close()
    if journal:
        errors = [f"{i.line}:{i.column}: {i.message()}" for i in result.issues]
        Journal(journal).append(Transfer(
            port, "receive", str(result.path or ""), result.bytes,
            count_lines(result.path) if result.path else 0, started, now_utc(),
            "no data" if result.path is None else "parity errors" if errors else "ok", errors,
            sha256_of(result.path) if result.path else ""))
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
    reading = read_journal(file, port=port, since=moment)
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
@click.option("--rate", type=click.FloatRange(1), help="Characters per second the control "
                                                        "consumes (default: as fast as they come).")
@click.option("--programs", type=click.IntRange(0), default=1, show_default=True,
              help="Programs to read before exiting (0: until interrupted).")
@click.option("--save", type=click.Path(dir_okay=False), help="Save the programs read here.")
@click.option("--punch", "punch_file", type=click.Path(exists=True, dir_okay=False),
              help="Send this program to the host instead (DC2 ... DC4).")
@click.option("--dc1-every", type=click.FloatRange(0.01), default=1.0, show_default=True,
              help="Repeat DC1 this often while waiting for a program.")
@click.option("--rewind-after", type=click.IntRange(1), metavar="BLOCKS",
              help="The operator presses RESET and rewinds once, after this many blocks of the "
                   "first program (signal USR1 rewinds at any moment).")
@click.option("--json", "as_json", is_flag=True, help="Statistics as JSON on stdout.")
@user_errors
def emulate(profile: str | None, port: str | None, buffer: int, rate: float | None, programs: int,
            save: str | None, punch_file: str | None, dc1_every: float,
            rewind_after: int | None, as_json: bool, **kw: Any) -> None:
    """Behave like a legacy control on a pseudo-terminal: DC1/DC3, alarm 087, TH/TV checks,
    label skip, and the operator's reset and rewind."""
    prof = get_profile(profile)
    settings = link_settings(prof, kw)
    pty = None
    link: Port | None = None
    if port:
        try:
            link = open_port(port, settings)
        except LinkError as exc:
            link_failed(exc)
            return
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
        if punch_file:
            framer = Framer(settings, file=punch_file)
            data = framer.leader() + b"".join(
                d for _, d in framer.frames(program_lines(punch_file))) + framer.trailer()
            sent = punch(fd, data, flow_settings(settings, wait_for_dc1=False), announce=1.0)
            click.echo(f"punched {punch_file}: {sent} bytes", err=True)
            return
        control = Control(cps=chars_per_second(settings), code=settings.code,
                          software_parity=settings.parity_mode == "software", buffer=buffer,
                          rate=rate, allowance=settings.overrun_allowance,
                          tv_check=settings.tv_check, dc1_every=dc1_every,
                          programs=programs or None, now=time.monotonic(),
                          dialect=prof.dialect)
        button = RewindButton(control, rewind_after)
        previous = None
        if hasattr(signal, "SIGUSR1"):  # kill -USR1 PID: the operator rewinds now
            previous = signal.signal(signal.SIGUSR1, lambda *_: button.press())
        try:
            with contextlib.suppress(KeyboardInterrupt):
                run_control(fd, control, rewind=button.pressed)
        finally:
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
    except LinkError as exc:
        link_failed(exc)
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
