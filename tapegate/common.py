"""What every ``tapegate`` command shares: file arguments, the profile, the one mapping of
errors to messages and exit codes (:func:`user_errors`), and the lines written to stdout and
stderr (:func:`echo`). Nothing here imports click: a one-file ``check`` runs its command's
body without it (:mod:`tapegate.launch`); click's own parts (the profile option, the usage
error) are in :mod:`tapegate.options`.

Every user error (:class:`formats.errors.TapegateError`) is printed as one located line on
stderr, never as a traceback. Exit codes (README.md, docs/errors.md): 0 done, 1 the input is
bad (parse, tape, conversion or check findings), 2 usage error or a file that cannot be read or
written, 3 the link failed.
"""

from __future__ import annotations

import os
import stat as _stat
import sys

from formats.errors import TapegateError

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from collections.abc import Callable, Iterable, Sequence
    from typing import Any, NoReturn, TypeVar

    from formats.profile import Profile

    F = TypeVar("F", bound=Callable[..., Any])


def echo(text: str, err: bool = False, nl: bool = True) -> None:
    """``text`` and a newline (unless ``nl`` is false) on stdout (stderr with ``err``),
    flushed: what ``click.echo`` writes. A text holding an escape character (ESC, which click
    strips from what is not a terminal), or a stream in an encoding other than UTF-8 (which
    click replaces with its own writer) is handed to click itself, so the bytes are click's in
    every case."""
    stream = sys.stderr if err else sys.stdout
    encoding = (getattr(stream, "encoding", None) or "").lower().replace("-", "")
    if "\x1b" in text or encoding != "utf8":
        import click

        click.echo(text, err=err, nl=nl)
        return
    stream.write(text + "\n" if nl else text)
    stream.flush()


def prepare_streams() -> None:
    """Every command's first step: a report names what it finds (text outside ASCII in a
    comment, a file's name); on a terminal or pipe whose encoding cannot hold a character, it
    is written as an escape (\\xfc) instead of stopping the command with a traceback."""
    for stream in (sys.stdout, sys.stderr):
        reconfigure = getattr(stream, "reconfigure", None)
        if reconfigure is not None and (stream.encoding or "").lower().replace("-", "") != "utf8":
            reconfigure(errors="backslashreplace")


def usage(message: str) -> Exception:
    """click's usage error (:class:`tapegate.options.UsageProblem`, exit 2) for a problem a
    command's body finds itself: imported only when raised, and told by click's ``main`` or,
    for a command read without click, by :func:`tapegate.launch.main` as click tells it."""
    from tapegate.options import UsageProblem

    return UsageProblem(message)


def _transfer_refused(exc: TapegateError) -> str:
    findings = getattr(exc, "findings", [])
    more = " (first 10 shown)" if len(findings) > 10 else ""
    return f"tapegate: not sent: {exc.message}{more}; fix them or use --force"


# How each error is told and what it exits with, first match by code, then by class (the
# classes of the DNC layer are named, not imported: parse, check and convert do not load it).
# "located": the error's own located line; "prefixed": the same after "tapegate: " (the message
# alone where the error has no file: a profile named that does not exist); "message":
# "tapegate: " and the message alone (its text names what failed). ``None`` for the exit code:
# the command's for bad input (1; diff's 2, where 1 means "different").
_BY_CODE: dict[str, tuple[str, int | None]] = {
    "link-settings": ("located", None),  # settings, not a failed link
    "listen-failed": ("message", 3),
    "mqtt-unavailable": ("message", 3),  # the broker cannot be reached, or refuses us
    "mqtt-queue": ("message", 3),
    "journal-missing": ("located", 2),
    "conversion-option": ("message", 2),  # an option the target control cannot honour
}
_BY_CLASS: tuple[tuple[str, str | Callable[[TapegateError], str], int | None], ...] = (
    ("Refused", _transfer_refused, 1),  # dnc.workflow: the check found errors, nothing sent
    ("LinkError", "message", 3),  # dnc.link
    ("ConfigError", "prefixed", 2),  # dnc.gateway_config
    ("ProfileError", "prefixed", 2),
    ("OutputError", "message", 2),
    ("TapegateError", "located", None),
)


def error_exit(exc: TapegateError, input_exit: int = 1) -> tuple[str, int]:
    """The line a command prints for ``exc`` and the code it exits with."""
    found: tuple[str | Callable[[TapegateError], str], int | None] | None = _BY_CODE.get(
        exc.code)
    if found is None:
        names = {cls.__name__ for cls in type(exc).__mro__}
        found = next((how, code) for name, how, code in _BY_CLASS if name in names)
    how, code = found
    text = (how(exc) if callable(how) else
            f"tapegate: {exc.message}" if how == "message" else
            f"tapegate: {exc if exc.file else exc.message}" if how == "prefixed" else str(exc))
    return text, input_exit if code is None else code


def fail(exc: TapegateError, input_exit: int = 1) -> NoReturn:
    """Print ``exc`` as :func:`error_exit` says and exit."""
    text, code = error_exit(exc, input_exit)
    echo(text, err=True)
    sys.exit(code)


def user_errors(func: F) -> F:
    """Every command's errors, told and mapped to exit codes in this one place:
    :class:`TapegateError` by :func:`error_exit`, a file that cannot be read or is not text
    exit 2, a closed output pipe (``| head``) a quiet exit 0."""
    return user_errors_exiting(1)(func)


def user_errors_exiting(input_exit: int) -> Callable[[F], F]:
    """:func:`user_errors` for a command whose code for bad input is ``input_exit`` (``diff``
    and ``check``: 2, as 1 says the programs differ or have findings)."""

    def decorate(command: F) -> F:
        def wrapper(*args: Any, **kwargs: Any) -> Any:
            try:
                return command(*args, **kwargs)
            except TapegateError as exc:
                fail(exc, input_exit)
            except BrokenPipeError:
                # The reader stopped reading: stop at once and quietly, exit 0 -- no traceback,
                # no message, and no exit code that would depend on how far the command had come.
                silence_stdout()
                sys.exit(0)
            except OSError as exc:  # a file that cannot be read, or another system refusal
                what = f"cannot read {exc.filename}: " if exc.filename is not None else ""
                echo(f"tapegate: {what}{exc.strerror or exc}", err=True)
                sys.exit(2)
            except UnicodeDecodeError as exc:  # a binary file where a text file was wanted
                echo(f"tapegate: cannot read a file given: not UTF-8 text ({exc.reason} "
                           f"at byte {exc.start})", err=True)
                sys.exit(2)

        return _wrapping(wrapper, command)

    return decorate


def _wrapping(wrapper: Callable[..., Any], command: F) -> F:
    """``wrapper`` as ``functools.wraps(command)`` leaves it (the name, the docstring, the
    annotations, the attributes click set, ``__wrapped__``), without importing functools
    (with ``types``, 3.3M instructions of a check's start-up before its threads;
    docs/benchmarks.md, "functools")."""
    for name in ("__module__", "__name__", "__qualname__", "__doc__", "__annotations__"):
        try:
            value = getattr(command, name)
        except AttributeError:
            continue
        setattr(wrapper, name, value)
    wrapper.__dict__.update(command.__dict__)
    wrapper.__wrapped__ = command  # type: ignore[attr-defined]
    return wrapper  # type: ignore[return-value]


def silence_stdout() -> None:
    """Point stdout at /dev/null, so that what is still buffered for a closed pipe cannot fail
    again when Python flushes it at exit (the recipe of the ``signal`` module's documentation)."""
    try:
        fd = sys.stdout.fileno()
    except (AttributeError, OSError, ValueError):  # not a real file (a test's capture)
        return
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(devnull, fd)
    finally:
        os.close(devnull)


_SPOOLED: list[Any] = []  # standard input's temporary copies, alive while the command runs


def readable(name: str) -> str:
    """The path a file argument is read from: ``-`` is standard input, copied once to a
    temporary file (a program is read more than once: detection, parameters, conversion);
    any other name as :func:`input_path` takes it."""
    return readable_sized(name)[0]


def readable_sized(name: str) -> tuple[str, int]:
    """:func:`readable`'s path and the size in bytes of what is there (0 where it cannot be
    read), from the same ``stat``: the sizes ``-j`` weighs its files by
    (``tapegate.workers.first``) without a second ``stat`` of each."""
    if name != "-":
        return _input(name)
    spool = _spooled(sys.stdin.buffer)
    return spool, _size(spool)


def input_path(name: str) -> str:
    """The path an input named ``name`` (not ``-``) is read from: itself, but for a pipe given
    by its name (``<(cmd)``, ``/dev/stdin`` piped in, a FIFO) that a writer holds open, which
    is copied to a temporary file as standard input is (read more than once, a pipe gave its
    bytes to the first reading: a check without ``--profile``, ``parse``, ``diff`` and
    ``convert`` of ``<(cat x.nc)`` read an empty program). An ``OSError`` naming it (told as
    "cannot read NAME: ...", exit 2) where it would wait for good or act on a device: a FIFO
    with no writer, a character device, a socket -- never opened to be read
    (:func:`formats.files.opened_stream`; review 42, finding 6). A regular file costs one
    ``stat``."""
    return _input(name)[0]


def _input(name: str) -> tuple[str, int]:
    """:func:`input_path` and the size of what is there (:func:`readable_sized`)."""
    try:
        info = os.stat(name)
    except OSError:  # told when it is read, as before
        return name, 0
    if _stat.S_ISREG(info.st_mode):
        return name, info.st_size
    from formats.files import opened_stream

    stream = opened_stream(name)
    if stream is None:  # a folder
        return name, info.st_size
    fd, head = stream
    with open(fd, "rb") as pipe:
        spool = _spooled(pipe, head, name)
    return spool, _size(spool)


def _size(path: str) -> int:
    try:
        return os.stat(path).st_size
    except OSError:
        return 0


def _spooled(stream: Any, head: bytes = b"", name: str = "<stdin>") -> str:
    """``head`` and the rest of ``stream`` copied to a temporary file, kept while the command
    runs: its path. A copy that cannot be written (no room in the temporary folder) is an
    ``OSError`` naming ``name`` that says so, not the input's error."""
    import tempfile

    from formats.files import exit_on_termination
    from formats.stops import read_some

    # SIGTERM and SIGHUP made an exit, so that the copy is removed at the exit as at a ^C
    # (review 53, F14: `check -` so stopped left it in the temporary folder)
    exit_on_termination()
    spool = tempfile.NamedTemporaryFile(prefix="tapegate-stdin-", suffix=".nc")  # noqa: SIM115
    try:
        spool.write(head)
        while True:
            # (what has come, not a full 64 kB; the read begun once something has come or a
            # signal ended the wait, which may otherwise wait for ever on a writer that never
            # ends)
            piece = read_some(stream, 1 << 16)
            if not piece:
                break
            spool.write(piece)
        spool.flush()
    except OSError as exc:
        spool.close()
        if exc.filename is not None:  # (the input's own error)
            raise
        # the copy's: told so, not as the input's (no room in the temporary folder)
        raise OSError(exc.errno, f"cannot copy it to the temporary folder "
                                 f"{os.path.dirname(spool.name)}: {exc.strerror or exc}",
                      name) from None
    _SPOOLED.append(spool)
    return spool.name


def plural(count: int, noun: str, many: str | None = None) -> str:
    """``1 comment``, ``2 comments``, ``1 match``, ``2 matches``."""
    return f"{count} {noun if count == 1 else many or noun + 's'}"


def shown(name: str) -> str:
    """A file argument as messages name it."""
    return "<stdin>" if name == "-" else name


def shown_output(name: str) -> str:
    return "<stdout>" if name == "-" else name


def write_stream(output: str, pieces: Iterable[bytes]) -> int:
    """``-o FILE`` written atomically piece by piece, or ``-o -`` to standard output; the bytes
    written."""
    if output == "-":
        sys.stdout.flush()
        try:
            fd = sys.stdout.fileno()
        except (AttributeError, OSError, ValueError):  # (a test's captured stream)
            fd = -1
        from formats.stops import heed_stops, write_all

        if fd >= 0:
            # past the stream's buffer, in writes a stop always ends (formats.stops): a
            # program copied to a pipe whose reader stops reading (a pager, a DNC link) must
            # end at ^C or SIGTERM, and leave nothing in a buffer that the exit would flush
            # into the same full pipe (the CI timeout of a `convert -o -` stopped so)
            return write_all(fd, pieces)
        size = 0
        for piece in pieces:
            heed_stops()
            sys.stdout.buffer.write(piece)
            size += len(piece)
        sys.stdout.buffer.flush()
        return size
    from pathlib import Path

    from formats.files import PendingFile, exit_on_termination

    exit_on_termination()
    target = Path(output)

    with PendingFile(target.parent, target.name) as pending:
        for piece in pieces:
            pending.write(piece)
        pending.commit(target, overwrite=True)
        return pending.size


def get_profile(name: str | None, file: str | None = None) -> Profile:
    """The named profile; without a name, the neutral one, adjusted to what ``file`` shows."""
    from formats.profile import load_profile, neutral

    if name is not None:
        return load_profile(name)
    notes = ["no --profile: the neutral profile (no machine limits, common characters accepted)"]
    profile = neutral()
    if file is not None and file != "-":
        from formats.convert import detect_source

        try:
            from formats.source import Source

            head = next(iter(Source(file).chunks()), "")
        except OSError:
            head = ""  # the command itself reports an unreadable file
        profile, detected = detect_source(head[:1 << 20])
        notes += [note.removeprefix("source: ") for note in detected]
    echo("tapegate: " + "; ".join(notes), err=True)
    return profile



def table(header: tuple[str, ...], rows: Sequence[tuple[str, ...]]) -> str:
    widths = [max(len(str(r[i])) for r in [header, *rows]) for i in range(len(header))]
    lines = ["  ".join(str(c).ljust(w) for c, w in zip(header, widths, strict=True)).rstrip()]
    lines.append("  ".join("-" * w for w in widths))
    for row in rows:
        lines.append("  ".join(str(c).ljust(w) for c, w in zip(row, widths, strict=True)).rstrip())
    return "\n".join(lines)
