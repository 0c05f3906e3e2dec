"""The stops (^C, SIGTERM, SIGHUP) a command was asked for, kept so that none is lost.

A signal's handler raises its exception wherever the interpreter runs Python code next. Where
that is a finalizer (a ``__del__``, a weak reference's callback: an import's module lock freed,
a collection), the interpreter prints it as "Exception ignored" and goes on: the stop is lost.
A command that then read a FIFO whose writer never ends, or wrote into a pipe nobody reads,
waited for ever (the ^C of `check FIFO`, the SIGTERM of `convert -o -`: 1 CI run in some
hundreds). The handlers note each signal in :data:`TAKEN`, and :func:`heed_stops`, called
before each such wait, raises the stop again. Nothing is imported here (but ``io``, the
interpreter's own): the ``tapegate`` command loads it at its start."""

from __future__ import annotations

import io  # (loaded by the interpreter's start, for its standard streams)

TYPE_CHECKING = False  # typing's, without importing typing
if TYPE_CHECKING:
    from collections.abc import Iterable
    from typing import Any

# the stop signals the handlers took, in order
TAKEN: list[int] = []

_SIGINT = 2  # (signal.SIGINT, without importing signal)


def interrupted(signum: int, frame: object) -> None:
    """^C's handler: ``KeyboardInterrupt``, as the interpreter's, the signal noted."""
    TAKEN.append(signum)
    raise KeyboardInterrupt


def note_interrupts() -> None:
    """^C's handler, where it is still the interpreter's, made :func:`interrupted`; in the main
    thread only. Set by the ``tapegate`` command's entry point (``tapegate.launch.main``), at
    each command's start: the stops noted before are forgotten (review 53, F10: after one ^C,
    a caller's next command stopped at its first wait)."""
    import _signal

    TAKEN.clear()  # (a caller that goes on: a stop obeyed before is not this command's)
    try:
        if _signal.getsignal(_signal.SIGINT) is _signal.default_int_handler:
            _signal.signal(_signal.SIGINT, interrupted)
    except ValueError:  # not the main thread (of the main interpreter)
        pass


def quiet_swallowed_stops() -> None:
    """The interpreter's "Exception ignored in ..." report of a stop that a finalizer swallowed
    (a ^C landing in an import's module-lock callback), not printed: the stop is noted in
    :data:`TAKEN` and raised again by :func:`heed_stops`, so the traceback told of nothing
    lost, and the command's stderr was "Aborted!" under a traceback (1 CI run in some
    hundreds: `convert FIFO` stopped by ^C). Any other exception a finalizer raises is
    reported as before, by the hook that was there. For the ``tapegate`` command's own
    process (:mod:`tapegate.launch`), once."""
    import sys

    before = sys.unraisablehook
    if getattr(before, "quiet_stops", False):
        return

    def hook(unraisable: Any) -> None:
        if TAKEN and isinstance(unraisable.exc_value, KeyboardInterrupt | SystemExit):
            return
        before(unraisable)

    hook.quiet_stops = True  # type: ignore[attr-defined]
    sys.unraisablehook = hook


def heed_stops() -> None:
    """The stop a signal asked for, raised again (``KeyboardInterrupt`` for ^C, else an exit
    with 128 + its number) if one was taken: called before the command waits on something
    that may never come (the next bytes of a FIFO, room in a full pipe)."""
    if TAKEN:
        signum = TAKEN[-1]
        TAKEN.clear()  # (raised once: what handles it goes on without it)
        raise KeyboardInterrupt if signum == _SIGINT else SystemExit(128 + signum)


# -- waits a signal always ends ----------------------------------------------------------------
#
# A check of TAKEN before a blocking write or read leaves a window: a signal that lands after
# the interpreter's last look at its pending handlers and before the system call starts runs
# only the C part of the handler (the Python part waits for the next bytecode), and the call
# then blocks for ever on a pipe nobody reads -- the signal already spent, no EINTR to end it
# (the lost wake-up; made every time by stopping the process at libc's write() and sending
# SIGTERM there). The same happens when the kernel hands the signal to another thread. So a
# wait that may never end is a poll() on the file and on the signal module's wakeup fd
# (``signal.set_wakeup_fd``: the C handler writes the signal's number there, before or during
# the poll alike), and the read or write after it is one that cannot block: at most PIPE_BUF
# bytes into a pipe that said it has room (POSIX: such a write is whole and waits only for
# room), one read of what a readable pipe holds.
#
# A poll and a write of 4 KiB each time cost a big report into a pipe 22-33 % more CPU (review
# 62c F4). So a pipe is written through a second, non-blocking open file description of it
# (:func:`_twin`: on Linux, ``/proc/self/fd/N`` opened anew is a new description of the same
# pipe, so the process's own, shared with the shell and the reader's side, keeps its flags):
# a write there takes at once as much as the pipe has room for, or fails with EAGAIN -- it
# never waits, so no signal can be lost in it -- and only then does the poll wait, on the pipe
# and on the wakeup fd. Where no such description can be had (no /proc, the open refused:
# another user's pipe, ``sudo -u USER tapegate ... | cat`` from root's shell, whose inode is
# its maker's, mode 0600: EACCES) or must not be (a pipe in packet mode), the pipe's own
# description is written by ``pwritev2`` with ``RWF_NOWAIT`` (:func:`_nowait`): a flag of the
# one call, not of the description, so nothing shared changes, and the write takes what the
# pipe has room for or fails with EAGAIN, as the twin's does (a kernel whose pipes take the
# flag, as Linux 6.18 here; one whose pipes do not refuses it with EOPNOTSUPP before writing
# a byte, and the writes go on as below). Not a pipe (a socket, a terminal), or neither: the 4,096
# bytes a poll, as above.

PIPE_BUF = 4096  # (select.PIPE_BUF on Linux; POSIX's least)
_POLLIN, _POLLOUT = 0x001, 0x004  # (select.POLLIN, select.POLLOUT, without importing select)


class _Wakeup:
    """The signal module's wakeup fd pointed at a pipe of ours while a wait runs (only the main
    thread can: elsewhere nothing is set and :attr:`fd` is -1, the wait a plain one). What a
    wakeup fd set before us was told is written on to it when we give it back."""

    def __init__(self) -> None:
        self.fd = -1
        self._write = -1
        self._before = -1
        self._seen = b""

    def __enter__(self) -> _Wakeup:
        import _signal
        import os

        read, write = os.pipe2(os.O_NONBLOCK | os.O_CLOEXEC)
        try:
            self._before = _signal.set_wakeup_fd(write, warn_on_full_buffer=False)
        except ValueError:  # not the main thread (of the main interpreter)
            os.close(read)
            os.close(write)
            return self
        self.fd, self._write = read, write
        import _thread

        _MAIN[0] = _thread.get_ident()  # (set_wakeup_fd succeeds in the main thread only)
        return self

    def drain(self) -> None:
        import os

        try:
            while True:
                piece = os.read(self.fd, 256)
                if not piece:
                    return
                self._seen += piece
        except BlockingIOError:
            return

    def __exit__(self, *exc: object) -> None:
        if self.fd < 0:
            return
        import _signal
        import os

        _signal.set_wakeup_fd(self._before)
        self.drain()
        if self._before >= 0 and self._seen:
            try:
                os.write(self._before, self._seen)
            except OSError:  # (its buffer full: told already)
                self._seen = b""
        os.close(self.fd)
        os.close(self._write)
        self.fd = -1


def _ready(fd: int, events: int, wakeup: _Wakeup) -> bool:
    """Waits until ``fd`` has ``events`` (or an error, a hang-up: what the read or the write
    then tells) or a signal came: True for the file, False for a signal (whose handler runs
    as the interpreter returns from the poll; a stop it took is raised by :func:`heed_stops`
    where the exception was swallowed)."""
    import select

    poll = select.poll()
    poll.register(fd, events)
    poll.register(wakeup.fd, _POLLIN)
    ready = dict(poll.poll())
    if wakeup.fd in ready:
        wakeup.drain()
        if _in_main_thread():
            heed_stops()
        return bool(ready.get(fd))
    return True


def _in_main_thread() -> bool:
    """Whether this is the thread the stops are raised in (where signals' handlers run): the
    main thread. A batch's threads that wait in a guarded write leave the stop to it (a map's
    threads are stopped by its own means: ``tapegate.workers``)."""
    import _thread

    return _thread.get_ident() == _MAIN[0]


_MAIN = [-1]  # (the main thread's ident, noted by :class:`_Wakeup` where it is set)


def _pollable(fd: int) -> bool:
    """Whether a write to or read from ``fd`` may wait for ever: a pipe, a socket, a terminal,
    a device -- not a regular file or a block device, whose data the kernel always takes."""
    import os
    import stat

    try:
        mode = os.fstat(fd).st_mode
    except OSError:
        return False
    return not (stat.S_ISREG(mode) or stat.S_ISBLK(mode))


def _fifo(fd: int) -> bool:
    """Whether ``fd`` is a pipe (a FIFO or an anonymous pipe)."""
    import os
    import stat

    try:
        return stat.S_ISFIFO(os.fstat(fd).st_mode)
    except OSError:
        return False


def _flags(fd: int) -> int:
    """The file status flags of ``fd`` (``F_GETFL``'s), read from ``/proc/self/fdinfo`` rather
    than by importing ``fcntl`` on every start whose stdout is a pipe; 0 where not found."""
    import os

    info = os.open(f"/proc/self/fdinfo/{fd}", os.O_RDONLY | os.O_CLOEXEC)
    try:
        text = os.read(info, 512)
    finally:
        os.close(info)
    for line in text.splitlines():
        if line.startswith(b"flags:"):
            return int(line[6:], 8)
    return 0


def _twin(fd: int) -> int:
    """A second open file description of the pipe ``fd`` (a FIFO or an anonymous pipe), for
    writing, non-blocking (``O_NONBLOCK`` set on it alone: ``fd``'s own, shared with other
    processes, is untouched) and closed on exec; -1 where it cannot be had: not a pipe, ``fd``
    not open for writing (a pipe's read end given as stdout: the twin, opened anew, would
    write into it), no ``/proc`` (not Linux), the open refused (a FIFO whose reader left:
    ENXIO), or a pipe in packet mode (``O_DIRECT``, ``pipe2``'s: a twin opened anew would not
    have it, and its writes would run together into one stream; the writes of ``fd`` itself,
    :func:`_nowait`'s or polled, keep the packets)."""
    import os
    import stat

    try:
        if not stat.S_ISFIFO(os.fstat(fd).st_mode):
            return -1
        os.write(fd, b"")  # (EBADF where the pipe is not open for writing: no twin by it)
        if _flags(fd) & os.O_DIRECT:
            return -1
        return os.open(f"/proc/self/fd/{fd}",
                       os.O_WRONLY | os.O_NONBLOCK | os.O_CLOEXEC | os.O_NOCTTY)
    except (OSError, AttributeError):  # (AttributeError: no O_NONBLOCK, not POSIX)
        return -1


def _nowait(fd: int) -> bool:
    """Whether the pipe ``fd``, open for writing, may be written by ``pwritev2`` with
    ``RWF_NOWAIT`` where it has no twin (:func:`_twin`: another user's pipe, packet mode, no
    /proc): a write that never waits, made on ``fd``'s own description without changing its
    flags (a packet-mode pipe keeps its packets). Whether the kernel's pipes take the flag is
    known at the first write only (:class:`_NoWait`)."""
    import os
    import stat

    if not getattr(os, "RWF_NOWAIT", 0) or not hasattr(os, "pwritev"):
        return False
    try:
        if not stat.S_ISFIFO(os.fstat(fd).st_mode):
            return False
        os.write(fd, b"")  # (EBADF where not open for writing)
    except OSError:
        return False
    return True


class _NoWait(Exception):
    """The kernel refused ``RWF_NOWAIT`` on a pipe (EOPNOTSUPP where its pipes do not take
    the flag), before writing a byte: the writes go on polled."""


def _write_ready(twin: int, data: memoryview, wakeup: _Wakeup, main: bool,
                 nowait: bool = False) -> int:
    """Bytes of ``data`` written into the non-blocking description ``twin`` of a pipe (at
    least one), or with ``nowait`` into the pipe's own description ``twin`` by a write that
    cannot wait (:func:`_nowait`; :class:`_NoWait` raised where the kernel refuses it): as
    many as the pipe has room for, at once, and only where it has none a wait in the poll on
    it and on the signal's ``wakeup`` (a stop taken ends it: in the main thread, raised)."""
    import os

    while True:
        try:
            if nowait:
                return os.pwritev(twin, [data], -1, os.RWF_NOWAIT)
            return os.write(twin, data)
        except BlockingIOError:  # (the pipe full: EAGAIN)
            pass
        except OSError as exc:
            import errno

            if nowait and exc.errno in (errno.EOPNOTSUPP, errno.EINVAL):
                raise _NoWait from None
            raise
        while not _ready(twin, _POLLOUT, wakeup):
            if main:
                heed_stops()


def write_all(fd: int, pieces: Iterable[bytes]) -> int:
    """Each of ``pieces`` written to ``fd`` whole, straight (no stream's buffer), with the
    stops (^C, SIGTERM, SIGHUP) obeyed at once wherever they land, even while the reader of a
    pipe does not read: into a pipe, a socket or a terminal, a piece goes at most
    :data:`PIPE_BUF` bytes at a time, each once a poll says there is room, and the poll ends
    on the signal's wakeup as well. The bytes written; a stop raises its exception with the
    rest unwritten (every byte before it was written, in order). Into a pipe (on Linux),
    through its non-blocking twin (:func:`_twin`), else by writes that cannot wait
    (:func:`_nowait`): each write as large as the pipe takes at once, a poll only where it is
    full."""
    import os

    size = 0
    if _fifo(fd):  # (EBADF at once for a pipe's read end, as a plain write: not a poll for
        os.write(fd, b"")  # ever; no such probe elsewhere: a packet socket sends it)
    if not _pollable(fd):
        for piece in pieces:
            heed_stops()
            view = memoryview(piece)
            while view:
                view = view[os.write(fd, view):]
            size += len(piece)
        return size
    with _Wakeup() as wakeup:
        twin = _twin(fd) if wakeup.fd >= 0 else -1
        nowait = twin < 0 and wakeup.fd >= 0 and _nowait(fd)
        try:
            for piece in pieces:
                view = memoryview(piece)
                while view:
                    heed_stops()
                    if twin >= 0:
                        view = view[_write_ready(twin, view, wakeup, True):]
                        continue
                    if nowait:
                        try:
                            view = view[_write_ready(fd, view, wakeup, True, True):]
                        except _NoWait:
                            nowait = False
                        continue
                    if wakeup.fd >= 0 and not _ready(fd, _POLLOUT, wakeup):
                        continue
                    view = view[os.write(fd, view[:PIPE_BUF] if wakeup.fd >= 0 else view):]
                size += len(piece)
        finally:
            if twin >= 0:
                os.close(twin)
    return size


def read_some(stream: Any, size: int) -> bytes:
    """Up to ``size`` bytes of ``stream`` (what has come: a pipe's next bytes, b"" at its
    end), the read begun only once a poll says there is something to read or a signal's
    wakeup ended the wait, so that a stop that lands just before it still ends the command
    (the copy of a FIFO whose writer never ends). A stream without a file descriptor is read
    as it is."""
    read = getattr(stream, "read1", stream.read)
    try:
        fd = stream.fileno()
    except (AttributeError, OSError, ValueError):
        fd = -1
    if fd < 0 or not _pollable(fd):
        heed_stops()
        return read(size)  # type: ignore[no-any-return]
    with _Wakeup() as wakeup:
        while True:
            heed_stops()
            if wakeup.fd < 0 or _ready(fd, _POLLIN, wakeup):
                return read(size)  # type: ignore[no-any-return]


def write_now(fd: int, data: bytes) -> bool:
    """``data`` (a message of a few bytes) written to ``fd`` if it takes it at once: a file, a
    terminal, a pipe or socket that a poll says has room (at most :data:`PIPE_BUF` bytes
    then); else dropped. Whether it was written. For what a stopped command still says."""
    import os
    import select

    try:
        if _pollable(fd):
            poll = select.poll()
            poll.register(fd, _POLLOUT)
            if not poll.poll(0):
                return False
            data = data[:PIPE_BUF]
        os.write(fd, data)
    except OSError:
        return False
    return True


_GUARDED: list[Any] = []  # (the wakeup of guard_stdout, kept for the process's life)


def guard_stdout() -> None:
    """Standard output, where it is a pipe or a socket, written by way of :func:`write_all`'s
    waits for the rest of the process: ``sys.stdout`` made anew over a raw writer
    (:class:`_PolledWriter`) whose writes never block where a signal could be lost -- a
    pipe's non-blocking twin, else a poll (the file and the signal's wakeup fd) before each
    write of at most :data:`PIPE_BUF` bytes -- so that every command's report (`check`,
    `parse`, `diff`, the summary of `convert DIR`, click's echo) ends at a stop that lands
    just before a write into a pipe whose reader does not read, as the copy of ``convert -o
    -`` does. The same encoding,
    errors and line buffering as the stream it replaces (flushed first), and its buffering:
    where that stream had none (``python -u``, ``PYTHONUNBUFFERED``: its binary layer the raw
    file, its text written through), the new one has none either, each write made at once
    (review 62c F5: it was buffered, so output came late, and with ``2>&1`` out of order);
    else a buffer of the file's ``st_blksize``, as Python's own ``open`` gives it. Only
    in the main thread, for the ``tapegate`` command's own process (:mod:`tapegate.launch`:
    not for a caller that goes on, whose streams are its own)."""
    import sys

    stream = sys.stdout
    try:
        fd = stream.fileno()
    except (AttributeError, OSError, ValueError):  # (a test's captured stream)
        return
    import os
    import stat

    try:
        mode = os.fstat(fd).st_mode
    except OSError:
        return
    if not (stat.S_ISFIFO(mode) or stat.S_ISSOCK(mode)) or _GUARDED:
        return
    if stat.S_ISFIFO(mode):
        try:
            os.write(fd, b"")  # (a pipe's zero-length write is nothing; a packet socket's is
        except OSError:  # a packet: not there) -- not open for writing (a pipe's read end):
            return  # its writes fail as before
    wakeup = _Wakeup().__enter__()
    if wakeup.fd < 0:  # not the main thread
        return
    _GUARDED.append(wakeup)
    stream.flush()
    raw = _PolledWriter(fd, wakeup)
    line_buffering = bool(getattr(stream, "line_buffering", False))
    if isinstance(getattr(stream, "buffer", None), io.BufferedWriter):
        size = os.fstat(fd).st_blksize
        buffered: io.BufferedIOBase | _PolledWriter = io.BufferedWriter(
            raw, size if size > 1 else io.DEFAULT_BUFFER_SIZE)
        through = bool(getattr(stream, "write_through", False))
    else:  # unbuffered (-u): the text written through to the raw writer, whose writes are whole
        buffered, through = raw, True
    sys.stdout = io.TextIOWrapper(buffered, encoding=stream.encoding,
                                  errors=stream.errors, newline="\n",
                                  line_buffering=line_buffering, write_through=through)


class _PolledWriter(io.RawIOBase):
    """The raw writer under :func:`guard_stdout`'s stream: each write, whole, into the pipe's
    non-blocking twin (:func:`_twin`: as much at once as the pipe takes, a poll on the file and
    on the signal's wakeup fd only where it is full), where there is none into the pipe by
    writes that cannot wait (:func:`_nowait`: another user's pipe, packet mode), or else (a
    socket, an old kernel) at most :data:`PIPE_BUF` bytes each once the poll says there is
    room. Closing it leaves the descriptor, the process's standard output, open. Where the
    descriptor was pointed elsewhere since (a stopped command's stdout made /dev/null,
    ``tapegate.launch._drop_pipes``, ``tapegate.common.silence_stdout``), the twin is closed
    (the writes that cannot wait stop) and the descriptor written: what it holds is what is
    written to."""

    def __init__(self, fd: int, wakeup: _Wakeup) -> None:
        super().__init__()
        self._fd = fd
        self._wakeup = wakeup
        self._twin = _twin(fd)
        self._nowait = self._twin < 0 and _nowait(fd)
        self._pipe = _identity(fd) if self._twin >= 0 or self._nowait else None

    def writable(self) -> bool:
        return True

    def fileno(self) -> int:
        return self._fd

    def isatty(self) -> bool:
        return False  # (a pipe or a socket)

    def write(self, data: Any) -> int:
        import os

        main = _in_main_thread()
        view = memoryview(data).cast("B")
        size = len(view)
        while view:
            if main:
                heed_stops()  # (a stop a batch's map held, or a finalizer swallowed: raised)
            if self._twin >= 0 and self._still_the_pipe():
                view = view[_write_ready(self._twin, view, self._wakeup, main):]
                continue
            if self._nowait and self._still_the_pipe():
                try:
                    view = view[_write_ready(self._fd, view, self._wakeup, main, True):]
                except _NoWait:
                    self._nowait = False
                continue
            while not _ready(self._fd, _POLLOUT, self._wakeup):
                if main:
                    heed_stops()
            view = view[os.write(self._fd, view[:PIPE_BUF]):]
        return size

    def close(self) -> None:
        import os

        if self._twin >= 0:  # (the pipe's reader sees its end once the descriptor is closed)
            os.close(self._twin)
            self._twin = -1
        super().close()

    def _still_the_pipe(self) -> bool:
        """Whether the descriptor is still the pipe the twin was opened on, or the writes that
        cannot wait began on (one ``fstat``); else the twin closed, or those writes ended, for
        good."""
        import os

        if _identity(self._fd) == self._pipe:
            return True
        if self._twin >= 0:
            os.close(self._twin)
            self._twin = -1
        self._nowait = False
        return False


def _identity(fd: int) -> tuple[int, int] | None:
    """(device, inode) of the file ``fd`` is, or None."""
    import os

    try:
        info = os.fstat(fd)
    except OSError:
        return None
    return info.st_dev, info.st_ino
