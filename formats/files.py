"""Writing files so that nothing is ever half-written or silently replaced.

:class:`PendingFile` is tapegate's one way to write a file: received programs, conversions, tape
images. The data goes to a hidden temporary file in the target folder, which is fsync'd, given
its name by a rename (or a link, which never replaces a file that appeared meanwhile; on FAT
and exFAT, which have no links, a rename that never replaces one), and the
folder is fsync'd so the name survives a power cut. A target that is no regular file (`-o
/dev/null`, a FIFO, a terminal) is written into, never renamed over: a rename would put a
regular file where the device was (as root, /dev/null itself). The temporary file is created
with mode 0666 and the process's umask, as any file the user creates (a program is for sharing
with the DNC service account); the umask is never changed, so threads writing at the same time
are safe. One that replaces a regular file (``overwrite``, ``--force``) takes that file's
permission bits and, where the system allows it, its owner and group, before its fsync (as
``install -p`` does; review 42, finding 5); a symbolic link there is replaced, not followed,
and the new file is made as a new one is.

The temporary file's making, its commit (the fsync, the rename or link, the file removed if a
step fails) and its removal are the core's (``formats._core``, crates/python/src/commits.rs),
the same steps a batch's commit threads run (``tapegate.converting.Commits``): one
implementation. The core keeps the list of the temporary files not yet named, entered in the
native step that makes each, and removes what is left of it when the process ends (the C
library's ``exit``, after the interpreter's; :func:`sweep` where it ends by ``os._exit``): a
^C (or SIGTERM's exit, which the commands that write files make an exit:
:func:`exit_on_termination`) that lands between a file's making and its commit, in whichever
thread, leaves no ``.part`` behind; only a SIGKILL (or SIGTERM to a program that uses this
module and leaves the signal's default action) can.
"""

from __future__ import annotations

import errno
import os
import stat

from formats import _core, stops
from formats.errors import OutputError

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from pathlib import Path

# (paths are strings here, written as pathlib writes them (:func:`pure`), and a Path is made
# only for a caller that is given one: pathlib's import, with fnmatch, ntpath and
# urllib.parse, was 18M instructions of a conversion's start-up, which its threads cannot
# share; docs/benchmarks.md, "the commits without the GIL")



def sweep() -> int:
    """Every temporary file this process made and has neither named nor removed (a run
    interrupted between a file's making and its commit), removed: how many. The core runs it
    at the process's exit (the C library's ``exit``); ``tapegate.launch.leave`` calls it
    before the ``os._exit`` that skips that. A child forked from this process removes only
    its own."""
    return _core.sweep_pending()


def exit_on_termination() -> None:
    """A command that writes files: SIGTERM (a CI job's timeout, ``kill``) and SIGHUP (its
    terminal closed), where nothing handles them yet, end the process as an exit with 128 +
    the signal's number, not by the signal's default action, which runs no exit function: so
    that :func:`sweep` runs at the exit and a one-file conversion stopped so leaves no hidden
    ``.part`` in the output folder (review 42, finding 4; a batch's threads hold such an exit
    to a safe point of their own: ``tapegate.workers``). A signal a caller handles or ignores
    is left so, and outside the main thread nothing is set. By signal's C part, loaded at the
    interpreter's start (the ``signal`` module's enums are not needed to set a handler)."""
    import _signal

    for signum in (_signal.SIGTERM, _signal.SIGHUP):
        try:
            if _signal.getsignal(signum) == _signal.SIG_DFL:
                _signal.signal(signum, _exit_signalled)
        except ValueError:  # not the main thread (of the main interpreter)
            return


def _exit_signalled(signum: int, frame: object) -> None:
    stops.TAKEN.append(signum)  # (formats.stops.heed_stops: an exit a finalizer swallowed)
    raise SystemExit(128 + signum)




class PendingFile:
    """A file written in pieces and named only at the end (:meth:`commit`).

    Until then the data lives in a hidden temporary file in the target folder; :meth:`discard`
    (or an exception in a ``with`` block) leaves nothing behind, nor does the process's exit
    before the commit (a ^C). Used where the name depends on what arrives (a received
    program is named from its program number) and where the data is too big for memory.
    """

    def __init__(self, folder: str | os.PathLike[str], hint: str = "tapegate", *,
                 create: bool = False):
        """``create`` makes a missing ``folder`` (a receive folder, a layout under --out-dir);
        otherwise a missing folder is an error, as for any file a user names."""
        self.folder = pure(os.fspath(folder))
        if create:
            os.makedirs(self.folder, exist_ok=True)
        try:
            # made and entered in the core's list of temporary files in one step
            fd, self.tmp = _core.pending_file(self.folder, hint)
        except OSError as exc:
            where = joined(self.folder, hint) if hint != "tapegate" else self.folder
            reason = ("no such folder" if isinstance(exc, FileNotFoundError)
                      and not os.path.isdir(self.folder) else exc.strerror or str(exc))
            raise OutputError(f"cannot write {where}: {reason}") from None
        try:
            # (the built-in open, not os.fdopen: no Python step inside, so the descriptor is
            # the file object's or closed by open's own failure, never closed twice -- an
            # os.close here after a ^C inside os.fdopen closed it again: EBADF, which took
            # the place of the KeyboardInterrupt)
            self.file = open(fd, "wb")  # noqa: SIM115 (closed by commit or discard)
        except BaseException:
            _core.discard_file(self.tmp)
            raise
        self.size = 0

    def write(self, data: bytes) -> None:
        self.file.write(data)
        self.size += len(data)

    def commit(self, path: str | os.PathLike[str], *, overwrite: bool = False,
               version: bool = True, sync_folder: bool = True) -> Path:
        """:meth:`name_as`, the path written as a ``Path``."""
        from pathlib import Path

        return Path(self.name_as(path, overwrite=overwrite, version=version,
                                 sync_folder=sync_folder))

    def name_as(self, path: str | os.PathLike[str], *, overwrite: bool = False,
                version: bool = True, sync_folder: bool = True) -> str:
        """fsync and give the file its name; with ``overwrite`` False an existing file is kept
        and a new version name is used (``NAME.1.EXT``...), or with ``version`` False the commit
        fails (:class:`FileExistsError`). Returns the path written. ``sync_folder`` False leaves
        the folder's fsync (the name on disk) to the caller, who syncs it once for many files
        (:func:`sync_folder`); the data is fsync'd before the rename either way, so the name
        never stands for a part of the file. A regular file's commit is the core's
        (``_core.commit_file``, on this thread: the steps a batch's commit threads run); a
        device or a FIFO is written into here. Whatever fails, the temporary file is gone."""
        path = pure(os.fspath(path))
        if is_special(path):  # a device or a FIFO: written into, as a shell's `>` does
            try:
                import shutil

                self.file.close()
                with open(self.tmp, "rb") as data, open(path, "wb") as out:
                    shutil.copyfileobj(data, out)
                return path
            finally:
                self.discard()
        named = _core.commit_file(self.hand_over(), self.tmp, path, overwrite, version)
        if sync_folder:
            _sync_folder(parent(named))
        return named

    def hand_over(self) -> int:
        """The data written flushed, and the temporary file's descriptor given away for a
        commit made in the core (``_core.commit_file``, ``_core.Commits``: the data fsync'd
        before the name is given, the temporary file removed if a step fails): a duplicate,
        which the taker closes; this object's own is closed here. On an error the temporary
        file is removed, as by :meth:`commit`."""
        try:
            self.file.flush()
            fd = os.dup(self.file.fileno())
        except BaseException:
            self.discard()
            raise
        try:
            self.file.close()
        except BaseException:
            os.close(fd)
            self.discard()
            raise
        return fd

    def discard(self) -> None:
        """Remove the temporary file, whatever closing it says (a full disk fails the close
        again: the file must still go)."""
        try:
            if not self.file.closed:
                self.file.close()
        except OSError:
            pass
        finally:
            _core.discard_file(self.tmp)

    def __enter__(self) -> PendingFile:
        return self

    def __exit__(self, kind: object, *rest: object) -> None:
        if kind is not None or not self.file.closed:
            self.discard()


def is_special(path: str | os.PathLike[str]) -> bool:
    """Whether ``path`` names something other than a regular file or a folder (a character
    device such as /dev/null, a FIFO, a socket): output goes into it, it is never replaced."""
    try:
        mode = os.stat(path).st_mode
    except OSError:
        return False
    return not (stat.S_ISREG(mode) or stat.S_ISDIR(mode))


def opened_stream(path: str) -> tuple[int, bytes] | None:
    """How an input named ``path`` (not ``-``) may be read without waiting for good: None for
    a regular file, a folder or a name that is not there (read by its name, where any error is
    told); for a pipe (a FIFO, a process substitution's ``/dev/fd/63``, ``/dev/stdin`` piped
    in) that a writer holds open, ``(its descriptor, the bytes already there)``, the
    descriptor blocking again and the caller's to close. An ``OSError`` naming ``path`` for
    the rest, which is never read: a pipe that no writer holds (reading it would wait for one
    for good: review 42, finding 6), a character or block device, a socket (a device is never
    opened at all: the open of a serial port or a tape drive acts on it).

    A FIFO is opened ``O_NONBLOCK``, which never waits for a writer, and read once: no byte and
    no writer (end of file) is refused; bytes, or none yet with a writer there (``EAGAIN``: a
    writer waiting in its own open counts), is a stream to read to its end. A writer started
    after this (``tapegate check f.nc & cat x > f.nc``) is too late: start it first, or pipe
    into ``-``."""
    try:
        mode = os.stat(path).st_mode
    except OSError:
        return None
    if stat.S_ISREG(mode) or stat.S_ISDIR(mode):
        return None
    if not stat.S_ISFIFO(mode):
        kind = ("a character device" if stat.S_ISCHR(mode) else "a block device"
                if stat.S_ISBLK(mode) else "a socket" if stat.S_ISSOCK(mode) else "no file")
        raise OSError(errno.EINVAL, f"not a regular file but {kind} (- reads standard input)",
                      path)
    fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_CLOEXEC)
    try:
        if not stat.S_ISFIFO(os.fstat(fd).st_mode):  # (replaced since its stat)
            raise OSError(errno.EINVAL, "not a regular file (- reads standard input)", path)
        try:
            head = os.read(fd, 1 << 16)
        except BlockingIOError:  # a writer, nothing written yet
            head, writer = b"", True
        else:
            writer = bool(head)
        if not writer:
            raise OSError(errno.ENXIO, "a pipe (FIFO) with no writer and nothing in it "
                          "(start its writer first, or pipe it into -)", path)
        os.set_blocking(fd, True)
    except BaseException:
        os.close(fd)
        raise
    return fd, head


def write_atomic(path: str | os.PathLike[str], data: bytes, *, overwrite: bool = True) -> Path:
    """Write ``data`` to ``path`` through a temporary file, fsync and rename.

    With ``overwrite`` False an existing file is kept and the data goes to a new version name
    (``NAME.1.EXT``, ``NAME.2.EXT``...); the path actually written is returned.
    """
    path = pure(os.fspath(path))
    with PendingFile(parent(path), os.path.basename(path)) as pending:
        pending.write(data)
        return pending.commit(path, overwrite=overwrite)


def _sync_folder(folder: str | os.PathLike[str]) -> None:
    """fsync a folder, so that a rename in it is on disk (where the system allows it)."""
    try:
        fd = os.open(folder, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass  # some file systems refuse to fsync a folder
    finally:
        os.close(fd)


sync_folder = _sync_folder  # (PendingFile.commit's argument of that name hides it there)


def pure(name: str) -> str:
    """``str(pathlib.PurePosixPath(name))``: empty and ``.`` parts dropped, ``..`` kept, two
    leading slashes kept as two (POSIX leaves their meaning to the system), more as one."""
    root = "//" if name.startswith("//") and not name.startswith("///") else (
        "/" if name.startswith("/") else "")
    parts = [p for p in name.split("/") if p not in ("", ".")]
    return root + "/".join(parts) or "."


def joined(folder: str, below: str) -> str:
    """``str(Path(folder) / below)`` for a ``folder`` written as :func:`pure` writes it and a
    relative ``below`` without empty or ``.`` parts: ``os.path.join``'s, written out (only
    ``/`` and ``//`` end in a slash)."""
    if folder == ".":
        return below
    return folder + below if folder[-1:] == "/" else folder + "/" + below


def parent(path: str) -> str:
    """``str(PurePosixPath(path).parent)`` of a path written as :func:`pure` writes it."""
    if path in ("/", "//", "."):
        return path
    folder = path.rpartition("/")[0]
    if not folder:
        return "/" if path.startswith("/") else "."
    return folder + "/" if folder == "/" else folder


def sha256_of(path: str | os.PathLike[str]) -> str:
    """The SHA-256 of a file, read in chunks (for the transfer journal)."""
    import hashlib

    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 16), b""):
            digest.update(chunk)
    return digest.hexdigest()


def count_lines(path: str | os.PathLike[str]) -> int:
    """Line ends in a file, read in chunks."""
    with open(path, "rb") as f:
        return sum(chunk.count(b"\n") for chunk in iter(lambda: f.read(1 << 16), b""))
