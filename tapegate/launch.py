"""The ``tapegate`` command's entry point: a plain ``check`` or ``convert`` is run without
click.

Importing click is most of a one-file check's start-up: about 130M instructions of the 260M
of ``tapegate check FILE -p fanuc-mill``, more than LinuxCNC's ``rs274`` takes for the whole
program; a one-file ``convert`` paid the same. A CAM programmer's CI runs such a command once
per file, and a batch's start-up is the part its threads cannot share, so :func:`main` looks at
the arguments first: when they are ``check`` or ``convert`` (:data:`COMMANDS`), existing files
or folders, and only the options of the command's table in the forms click reads the same
way, it reads them itself and calls the command's body (:func:`tapegate.checking.run_check`,
:func:`tapegate.converting.run_convert`) with the values click would pass. Anything else --
another command, ``--help``, an option not in the table, a required option missing, ``--``, a
missing file or standard input (``-``), a value click would read otherwise (one starting with
``-``, a choice not offered, an output path click's ``Path`` type refuses) -- goes to click's
group (:data:`tapegate.cli.main`) unchanged, so that click stays the one place that reads the
rest and explains every usage error.

tests/test_launch.py holds the two together: every option of a table is one of click's
options of the command with the same names, kind, choices and default, and a table of argument
forms (errors among them) answers the same, byte for byte, both ways.
"""

from __future__ import annotations

import os
import stat
import sys

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from typing import Any

# A command's options read here: each name -> (the parameter of its body, how its value is
# read): "value" (the next argument, or after "=" or, for a short name, attached), "many" (the
# same, repeatable: a tuple in order), "flag" (no value), "positive" (an integer >= 1), "file"
# and "folder" (a value as click's ``Path(dir_okay=False)`` and ``Path(file_okay=False)`` take
# it: a path that does not exist, or one of that kind that can be read), or a tuple of the
# choices. The defaults are click's (tests/test_launch.py compares both).
Kind = str | tuple[str, ...]
CHECK_OPTIONS: dict[str, tuple[str, Kind]] = {
    "-p": ("profile", "value"),
    "--profile": ("profile", "value"),
    "--units": ("units", ("metric", "inch")),
    "--format": ("fmt", ("text", "json", "jsonl", "sarif")),
    "--select": ("select", "many"),
    "--ignore": ("ignore", "many"),
    "--fail-on": ("fail_on", ("error", "warning")),
    "--stats": ("show_stats", "flag"),
    "--all": ("show_all", "flag"),
    "-j": ("jobs", "positive"),
    "--jobs": ("jobs", "positive"),
}
CHECK_DEFAULTS: dict[str, Any] = {
    "profile": None, "units": None, "fmt": "text", "select": (), "ignore": (), "fail_on": "error",
    "show_stats": False, "show_all": False, "jobs": None,
}
ZEROS = ("leading", "trailing", "none")
CONVERT_OPTIONS: dict[str, tuple[str, Kind]] = {
    "-o": ("output", "file"),
    "--output": ("output", "file"),
    "--out-dir": ("out_dir", "folder"),
    "--to": ("to_profile", "value"),
    "--from": ("from_profile", "value"),
    "--from-decimal": ("from_decimal", ("explicit", "implicit", "increments")),
    "--from-zeros": ("from_zeros", ZEROS),
    "--from-units": ("from_units", ("metric", "inch")),
    "--decimal": ("decimal", ("explicit", "implicit")),
    "--zeros": ("zeros", ZEROS),
    "--units": ("units", ("metric", "inch")),
    "--eob": ("eob", ("lf", "crlf")),
    "--spacing": ("spacing", ("keep", "remove", "insert")),
    "--round": ("rounding", ("half-even", "half-up", "error")),  # formats.wordformat.Rounding
    "--allow-unconverted": ("allow_unconverted", "flag"),
    "-j": ("jobs", "positive"),
    "--jobs": ("jobs", "positive"),
    "--verify": ("verify", "flag"),
    "--dry-run": ("dry_run", "flag"),
    "--force": ("force", "flag"),
    "--format": ("fmt", ("text", "json")),
}
CONVERT_DEFAULTS: dict[str, Any] = {
    "output": None, "out_dir": None, "to_profile": None, "from_profile": None,
    "from_decimal": None, "from_zeros": None, "from_units": None, "decimal": None, "zeros": None,
    "units": None,
    "eob": None, "spacing": "keep", "rounding": "half-even", "allow_unconverted": False,
    "jobs": None, "verify": False, "dry_run": False, "force": False, "fmt": "text",
}
# the commands read here: (options, defaults, the parameter of the file arguments, the options
# click requires, the body as "module:function")
COMMANDS: dict[str, tuple[dict[str, tuple[str, Kind]], dict[str, Any], str, tuple[str, ...],
                          str]] = {
    "check": (CHECK_OPTIONS, CHECK_DEFAULTS, "files", (), "tapegate.checking:run_check"),
    "convert": (CONVERT_OPTIONS, CONVERT_DEFAULTS, "inputs", ("to_profile",),
                "tapegate.converting:run_convert"),
}


def _path_taken(value: str, kind: str) -> bool:
    """Whether click's ``Path`` (``exists=False``, ``readable=True``) takes ``value`` as it is
    (its ``convert``): a path that does not exist, or one not of the kind refused (a folder for
    "file", a regular file for "folder") that can be read."""
    try:
        mode = os.stat(value).st_mode
    except OSError:
        return True
    refused = stat.S_ISDIR(mode) if kind == "file" else stat.S_ISREG(mode)
    return not refused and os.access(value, os.R_OK)


def plain(args: list[str]) -> tuple[str, dict[str, Any]] | None:
    """(the command's body, its keyword arguments) for ``args`` (the command line after the
    program's name), or None when click is to read them."""
    command = COMMANDS.get(args[0]) if args else None
    if command is None:
        return None
    options, defaults, positional, required, body = command
    params: dict[str, Any] = dict(defaults)
    files: list[str] = []
    rest = iter(args[1:])
    for arg in rest:
        if not arg.startswith("-"):
            if not os.path.exists(arg):
                return None
            files.append(arg)
            continue
        name: str = arg
        attached: str | None = None  # a value given in the same argument
        if arg.startswith("--"):
            name, eq, given = arg.partition("=")
            attached = given if eq else None
        elif len(arg) > 2:  # -pNAME: a short option's value attached
            name, attached = arg[:2], arg[2:]
        found = options.get(name)
        if found is None:  # --help, --, -, another option: click's
            return None
        key, how = found
        if how == "flag":
            if attached is not None:
                return None
            params[key] = True
            continue
        value = attached if attached is not None else next(rest, None)
        if not value or value.startswith(("-", "=")):
            return None
        if how == "many":
            params[key] = (*params[key], value)
        elif how == "positive":
            if not (value.isascii() and value.isdigit()) or int(value) < 1:
                return None
            params[key] = int(value)
        elif isinstance(how, tuple) and value not in how or (
                how in ("file", "folder") and not _path_taken(value, how)):
            return None  # not a choice, or a path click's Path refuses
        else:
            params[key] = value
    if not files or any(params[key] is None for key in required):
        return None
    params[positional] = tuple(files)
    return body, params


def main(prog_name: str | None = None, clean_exit: bool = False) -> None:
    """``tapegate``: a plain check or conversion (:func:`plain`) run here, anything else by
    click. A plain command ends the process once its output is flushed (:func:`leave`); with
    ``clean_exit`` it raises ``SystemExit`` as click's commands do, for a caller that goes on
    (as ``mypy.main``'s argument of that name)."""
    from formats.stops import guard_stdout, note_interrupts, quiet_swallowed_stops

    if sys.stdout is None:
        # file descriptor 1 closed (`>&-`): Python gives the process no stdout, and a report,
        # a conversion to `-` or a help text would end in a traceback with nothing said;
        # refused before any work, as a file that cannot be written (README, exit codes)
        if sys.stderr is not None:
            sys.stderr.write(
                "tapegate: error: standard output is closed: give it a file or /dev/null\n")
        sys.exit(2)
    note_interrupts()  # (a ^C a finalizer swallows is still obeyed: formats.stops)
    if not clean_exit:
        quiet_swallowed_stops()  # (and not told with a traceback)
    try:
        found = None if "_TAPEGATE_COMPLETE" in os.environ else plain(sys.argv[1:])
        if found is None:
            from tapegate.cli import main as group
        else:
            pause_collector()
            from tapegate.common import prepare_streams

            body, params = found
            module, name = body.split(":")
            # (__import__, not importlib's import_module: the importlib package is not
            # loaded yet)
            run = getattr(__import__(module, fromlist=[name]), name)
            prepare_streams()
            if not clean_exit:
                guard_stdout()  # (a stop ends every write into a pipe: formats.stops)
    except KeyboardInterrupt:  # a ^C in the start-up: told as the command's own (review 53,
        thaw()  # F11: a traceback where the imports took it)
        sys.stderr.write("\nAborted!\n")
        sys.exit(1)
    if found is None:
        try:
            if not clean_exit:
                from tapegate.common import prepare_streams

                prepare_streams()  # (before the stream is made anew: its errors kept)
                guard_stdout()
            invoke = group.invoke

            def told_now(ctx: object) -> object:
                # ^C in the command: told as click's main tells it, but only if stderr takes
                # it now, as on the plain path -- click's own blocking write of "Aborted!"
                # into a pipe nobody reads (`2>&1 | less` left open) waited for ever
                # (review 62c F3)
                try:
                    return invoke(ctx)  # type: ignore[arg-type]
                except KeyboardInterrupt:
                    _tell_now("\nAborted!\n")
                    sys.exit(1)

            group.invoke = told_now  # type: ignore[method-assign]
            group(prog_name=prog_name)
        except SystemExit as done:
            if not clean_exit and _stopped(done):
                _drop_pipes()
                from formats.stops import TAKEN

                # the stop is obeyed: the exit's flush raises it no more (a ^C noted twice,
                # by the handler and by a batch's map, failed that flush: exit 120)
                TAKEN.clear()
            raise
        return
    try:
        try:
            run(**params)
        except KeyboardInterrupt:  # as click's main tells it (unless stderr cannot take it now)
            _tell_now("\nAborted!\n")
            sys.exit(1)
        except Exception as exc:
            # a usage problem the body finds itself (a rule --select names that does not
            # exist) is click's exception: told as click's main tells it
            click = sys.modules.get("click")
            if click is None or not isinstance(exc, click.ClickException):
                raise
            exc.show()
            sys.exit(exc.exit_code)
    except SystemExit as done:
        if not clean_exit:
            if _stopped(done):
                _drop_pipes()
            leave(done.code)
        thaw()
        raise
    except BaseException:
        thaw()
        raise
    if not clean_exit:  # (a conversion that succeeds returns)
        leave(0)
    thaw()


_paused = False  # the collector turned off by pause_collector, until resume_collector
_frozen = False  # what the start-up made moved out of the collector's reach, until thaw


def pause_collector() -> None:
    """The cyclic garbage collector off for the start-up of a plain command: the imports and
    the profile make tens of thousands of objects that live as long as the process, and the
    collector walked them 9-10 times before a batch's first file (1.7 ms of CPU timed by
    ``gc.callbacks``; 6.2M of the 130M instructions ``check -j 2`` runs before its threads
    start, work they cannot share; docs/benchmarks.md, "the serial ends of `-j 2`"). The
    body turns it back on (:func:`resume_collector`) before the files' work."""
    global _paused
    import gc

    if gc.isenabled():
        gc.disable()
        _paused = True


def resume_collector() -> None:
    """The start-up done (the profile loaded, the files listed): what it made is moved out of
    the collector's reach (``gc.freeze``, the pattern of its documentation: turned off early,
    frozen, turned on) and the collector turned back on, so that cycles a file's work leaves
    are freed and memory stays flat. Without the freeze, the first collection after it walked
    all the start-up had made at once (one of 1.6 ms). Nothing if :func:`pause_collector` did
    not turn it off (click's path, a test calling the command's body)."""
    global _paused, _frozen
    if _paused:
        import gc

        gc.freeze()
        gc.enable()
        _paused, _frozen = False, True


def thaw() -> None:
    """The collector as it was before :func:`pause_collector`, before the interpreter's own
    exit or a caller that goes on: what :func:`resume_collector` froze given back to it (a
    frozen object is never finalized, not even at the exit: a module's object with a
    ``__del__``, a file not closed), and the collector on again if the body ended before it
    turned it on (a usage error, a profile that cannot be read)."""
    global _paused, _frozen
    if _paused or _frozen:
        import gc

        if _frozen:
            gc.unfreeze()
        if _paused:
            gc.enable()
        _paused = _frozen = False


def _stopped(done: SystemExit) -> bool:
    """Whether the exit is a stop the user or the system asked for: ^C (the exit 1 told
    "Aborted!", raised while the ``KeyboardInterrupt`` was handled) or a signal's exit with
    128 + its number (SIGTERM, SIGHUP: ``formats.files.exit_on_termination``)."""
    if isinstance(done.code, int) and done.code > 128:
        return True
    seen: BaseException | None = done.__context__  # (click's: Abort, raised from the ^C)
    for _ in range(3):
        if seen is None:
            return False
        if isinstance(seen, KeyboardInterrupt):
            return True
        seen = seen.__cause__ or seen.__context__
    return False


def leave(code: object) -> None:
    """The process ended at once with ``code`` once the command is done, its output flushed:
    the interpreter's finalization -- every module's objects freed one by one, the heap given
    back -- is 14.7M instructions, 3-4 ms of CPU, which a batch's threads cannot share: the
    last serial step of ``check -j``, and 12 % of a one-file check's instructions
    (docs/benchmarks.md, "the serial ends of `-j 2`"). ``mypy`` ends so too
    (``util.hard_exit``).
    Returns, for the interpreter's own exit, whenever that could do more than free memory: a
    code that is no integer (printed by the exit), a function registered with ``atexit``
    (coverage, a test's probe), a thread not a daemon still running, standard input copied
    to a temporary file (``tapegate.common.readable``, removed by its object's finalizer), or
    a flush that fails (a closed pipe: told as the exit tells it). A stopped command's pipes
    were pointed at /dev/null before (:func:`_drop_pipes`): the flush here, or the
    interpreter's, never waits on a reader."""
    import atexit

    if not (code is None or isinstance(code, int)) or atexit._ncallbacks():
        return
    threading = sys.modules.get("threading")
    if threading is not None and any(
            not t.daemon and t.is_alive() for t in threading.enumerate()
            if t is not threading.main_thread()):
        return
    common = sys.modules.get("tapegate.common")
    if common is not None and common._SPOOLED:
        return
    try:
        sys.stdout.flush()
        sys.stderr.flush()
    except BaseException:  # (BrokenPipeError, or another error of the streams)
        return
    files = sys.modules.get("formats.files")
    if files is not None:  # the temporary files a ^C left, which the C library's exit (not
        files.sweep()  # taken here) would remove: formats.files.sweep
    os._exit(code or 0)


def _a_pipe(stream: object) -> bool:
    """Whether ``stream`` writes into a pipe or a socket. A command stopped (^C, SIGTERM)
    while its output waited on a reader that does not read (a pager, a DNC link, a job
    runner's pipe) leaves that output unflushed: the flush would wait on the full pipe for
    ever, the stop not obeyed (a CI job's timeout hanging in its turn). A file or a terminal
    always takes the rest, so it is written."""
    import stat

    try:
        mode = os.fstat(stream.fileno()).st_mode  # type: ignore[attr-defined]
    except (AttributeError, OSError, ValueError):
        return False
    return stat.S_ISFIFO(mode) or stat.S_ISSOCK(mode)


def _drop_pipes() -> None:
    """A command stopped (^C, SIGTERM, SIGHUP: :func:`_stopped`): its stdout and stderr, where
    they are a pipe or a socket, pointed at /dev/null (``tapegate.common.silence_stdout``'s
    recipe), so that what still waits in their buffers is dropped, not flushed into a pipe
    whose reader does not read -- which would wait for ever, the stop not obeyed, whether
    :func:`leave` or the interpreter's own exit flushes it (a `convert -o -` or a `check`
    piped into a pager left open, a DNC link, a CI job runner's pipe). What the reader got
    is every byte written before the stop, in order; a file or a terminal always takes the
    rest, so it is written."""
    for stream in (sys.stdout, sys.stderr):
        if _a_pipe(stream):
            try:
                fd = stream.fileno()
                devnull = os.open(os.devnull, os.O_WRONLY)
            except (AttributeError, OSError, ValueError):
                continue
            try:
                os.dup2(devnull, fd)
            finally:
                os.close(devnull)


def _tell_now(text: str) -> None:
    """``text`` on stderr if it takes it now (a terminal, a file, a pipe with room: as
    before), else dropped: a stopped command's message never waits on a pipe nobody reads
    (``2>&1 | less`` left open)."""
    from formats.stops import write_now

    try:
        sys.stderr.flush()
        fd = sys.stderr.fileno()
    except (AttributeError, OSError, ValueError):  # (a test's captured stream)
        sys.stderr.write(text)
        return
    write_now(fd, text.encode())
