"""Files spread over worker processes for ``check`` and ``convert`` (``-j``), reports in the
order of the input, memory flat.

:func:`ordered_map` runs a function on every item in a pool of processes and yields the
results in the items' order. Given the items' weights (their files' sizes), it hands them out
in **chunks** of consecutive items, large while much is left and smaller towards the end (each
about ``1 / (4 * jobs)`` of what is left, at least :data:`CHUNK_MIN` bytes): a batch of small
files costs a round trip to a worker per chunk, not per file, and the workers still finish
together. At most ``2 * jobs`` chunks are given out at a time, so a slow file holds back only
the few after it: the results waiting for it are small (a conversion's statistics), or a
temporary file on disk (a check's findings, :func:`check_files`), never a growing list in
memory.

A check in a worker writes its findings as the report will print them (text, JSON Lines, the
JSON document's members), in the encoding of the report's stream, into one temporary file per
chunk, and the main process copies each file's bytes into its stdout when that file's turn
comes (``os.sendfile``: the bytes go from file to stream in the kernel, never decoded and
encoded again): stdout is byte for byte what ``-j 1`` writes. SARIF numbers the rules in the
order they first appear across all files, which a worker cannot know: its findings are passed
as records and written by the main process.

Workers are forked where the system can (Linux): they start with the modules and the profile
already loaded.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Iterator, Sequence
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any, TextIO, TypeVar

from formats.records import FrozenRecord, Record, init_fields, record

# multiprocessing, concurrent.futures, pickle and tempfile are imported where a pool is started
# (a fifth of a short check's start-up when imported here): one file checks without them. The
# two classes below are records, not dataclasses: the main process imports this module before
# it starts the workers, and importing dataclasses (with inspect) is 43M instructions there.
if TYPE_CHECKING:
    from formats.profile import Profile
    from postproc.check import CheckStats

T = TypeVar("T")
R = TypeVar("R")

_SARIF_BATCH = 4096  # findings pickled at a time by a worker for the SARIF report
_COPY = 1 << 20  # bytes copied at a time from a worker's findings into the report
# The least weight (bytes of input) of a chunk: about 7 ms of checking, against a round trip
# to a worker of a few tenths of a millisecond.
CHUNK_MIN = 256 * 1024


def default_jobs() -> int:
    """The CPUs this process may run on (``-j``'s default)."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def _context() -> Any:
    import multiprocessing

    methods = multiprocessing.get_all_start_methods()
    return multiprocessing.get_context("fork" if "fork" in methods else "spawn")


_SHARED: list[Any] = []  # what every item of a map needs, given to each worker once
_CHUNK: dict[str, Any] = {}  # what the items of one chunk share in a worker (chunk_scope)


def _share(value: object) -> None:
    """A worker's start: what every item needs, and SIGTERM's default action (a forked worker
    inherits the main process's handler, :func:`_terminated`, which is the main process's)."""
    import signal

    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    _SHARED[:] = [value]


def _terminated(signum: int, frame: object) -> None:
    """SIGTERM in the main process while workers run (a CI job's timeout, `kill`): an exit
    with 128 + the signal's number, through the ``finally`` clauses that stop the workers and
    delete the temporary files, instead of an exit that leaves both behind."""
    raise SystemExit(128 + signum)


def shared() -> Any:
    """In ``func`` of :func:`ordered_map`: the value given as its ``shared``."""
    return _SHARED[0]


def chunk_scope() -> dict[str, Any]:
    """In ``func`` of :func:`ordered_map`: a dict the items of one chunk share (emptied before
    each chunk); the callables in its list ``"close"`` are called when the chunk is done."""
    return _CHUNK


def _run_chunk(func: Callable[[T], R], chunk: list[T]) -> tuple[list[R], BaseException | None]:
    """``func`` on each item of a chunk (in a worker): the results, and the exception that
    stopped it (its item's result is then the last missing)."""
    _CHUNK.clear()
    results: list[R] = []
    try:
        for item in chunk:
            results.append(func(item))
        return results, None
    except Exception as exc:  # raised in the main process at its item's turn
        return results, exc
    finally:
        for close in _CHUNK.get("close", ()):
            close()
        _CHUNK.clear()


def chunks(items: Sequence[T], weights: Sequence[int] | None, jobs: int) -> Iterator[list[T]]:
    """Consecutive items in chunks: one item each without ``weights``; with them, each chunk
    weighs about a quarter of what is left per job, at least :data:`CHUNK_MIN` (a chunk holds
    at least one item)."""
    if weights is None:
        for item in items:
            yield [item]
        return
    left = sum(weights)
    chunk: list[T] = []
    weight = 0
    for item, w in zip(items, weights, strict=True):
        chunk.append(item)
        weight += w
        if weight >= max(left / (4 * jobs), CHUNK_MIN):
            yield chunk
            left -= weight
            chunk, weight = [], 0
    if chunk:
        yield chunk


def ordered_map(func: Callable[[T], R], items: Sequence[T], jobs: int, *,
                shared: object = None, weights: Sequence[int] | None = None) -> Iterator[R]:
    """``func(item)`` for every item, in ``jobs`` processes, yielded in the items' order.
    ``shared`` is what every item needs (the profiles, the options): given to each worker
    once, not with every item, and read there by :func:`shared` (when ``jobs`` is 1 or there
    is one item, nothing is started and the items are done one by one in this process).
    ``weights`` (an item's bytes) hands the items out in chunks (:func:`chunks`; without it,
    one at a time). An exception ``func`` raises is raised here, when its item's turn comes."""
    if jobs <= 1 or len(items) <= 1:
        _share(shared)
        try:
            for chunk in chunks(items, None, 1):  # (here, a chunk would only come later)
                results, error = _run_chunk(func, chunk)
                yield from results
                if error is not None:
                    raise error
        finally:
            _CHUNK.clear()
        return
    import signal
    import threading
    from collections import deque
    from concurrent.futures import Future, ProcessPoolExecutor
    from itertools import islice

    window = 2 * jobs
    # (forked, a worker inherits ``shared`` as it is; spawned, it is pickled once per worker)
    pool = ProcessPoolExecutor(max_workers=min(jobs, len(items)), mp_context=_context(),
                               initializer=_share, initargs=(shared,))
    main_thread = threading.current_thread() is threading.main_thread()
    before = signal.signal(signal.SIGTERM, _terminated) if main_thread else None
    try:
        waiting: deque[Future[tuple[list[R], BaseException | None]]] = deque()
        rest = chunks(items, weights, jobs)
        for chunk in islice(rest, window):
            waiting.append(pool.submit(_run_chunk, func, chunk))
        while waiting:
            results, error = waiting.popleft().result()
            for chunk in islice(rest, 1):
                waiting.append(pool.submit(_run_chunk, func, chunk))
            yield from results
            if error is not None:
                raise error
    except BaseException:
        # stopped (SIGTERM, Ctrl-C, a closed pipe, an error): the workers are stopped too,
        # not waited for through the chunks they hold
        for process in list((getattr(pool, "_processes", None) or {}).values()):
            process.terminate()
        raise
    finally:
        pool.shutdown(wait=True, cancel_futures=True)
        if main_thread:
            signal.signal(signal.SIGTERM, before)


def sizes(paths: Iterable[str]) -> list[int]:
    """The size of each file, the weight :func:`ordered_map` gives it (0 when it cannot be
    read: its error is the worker's to tell)."""
    found = []
    for path in paths:
        try:
            found.append(os.stat(path).st_size)
        except (OSError, ValueError):
            found.append(0)
    return found


def input_files(names: Iterable[str]) -> list[str]:
    """The files named: a folder stands for every file below it, sorted, hidden ones (a name
    starting with ``.``) left out; anything else is taken as it is named (a missing file is
    reported when it is read)."""
    files: list[str] = []
    for name in names:
        path = Path(name)
        if name != "-" and path.is_dir():
            files.extend(str(found) for found in sorted(path.rglob("*"))
                         if found.is_file() and not any(
                             p.startswith(".") for p in found.relative_to(path).parts))
        else:
            files.append(name)
    return files


# ---------------------------------------------------------------------------------------------
# check


@record
class CheckedFile(Record):
    """What a worker sends back for one file: counts, statistics, or why it was not read, and
    where its findings wait (bytes ``start`` to ``end`` of a temporary file the main process
    copies, then deletes with the chunk's last file)."""

    name: str
    counts: dict[str, int]
    stats: CheckStats | None = None
    error: str | None = None
    findings: str | None = None  # the temporary file
    count: int = 0
    start: int = 0
    end: int = 0

    def __init__(self, name: str, counts: dict[str, int], stats: CheckStats | None = None,
                 error: str | None = None, findings: str | None = None, count: int = 0,
                 start: int = 0, end: int = 0) -> None:
        init_fields(self, name, counts, stats, error, findings, count, start, end)


@record
class _CheckJob(FrozenRecord):
    """The settings every file of one ``check`` shares, given to each worker once."""

    profile: Profile
    fmt: str
    select: tuple[str, ...]
    ignore: tuple[str, ...]
    spool: str  # the folder of the temporary files
    encoding: str  # the report stream's, so that its bytes are copied as they are
    errors: str

    def __init__(self, profile: Profile, fmt: str, select: tuple[str, ...],
                 ignore: tuple[str, ...], spool: str, encoding: str, errors: str) -> None:
        init_fields(self, profile, fmt, select, ignore, spool, encoding, errors)


def _spool(job: _CheckJob) -> tuple[str, Any]:
    """The chunk's temporary file of findings (made for its first file), and its stream."""
    scope = chunk_scope()
    if "spool" not in scope:
        import tempfile

        fd, path = tempfile.mkstemp(prefix="check-", dir=job.spool)
        # (closed with the chunk: chunk_scope's "close")
        binary = job.fmt == "sarif"
        out: IO[Any] = open(fd, "wb" if binary else "w",  # noqa: SIM115
                            encoding=None if binary else job.encoding,
                            errors=None if binary else job.errors)
        scope["spool"] = (path, out)
        scope.setdefault("close", []).append(out.close)
    return scope["spool"]  # type: ignore[no-any-return]


def _check_one(item: tuple[str, str]) -> CheckedFile:
    """Check one file, its findings rendered at the end of the chunk's temporary file (in a
    worker): text, JSON and JSON Lines as the core writes them for the report, SARIF as
    records for the main process to number."""
    import pickle

    from formats.errors import TapegateError
    from postproc.check import Checker, iter_check_file
    from postproc.rules import SEVERITY_RANK

    path, name = item
    job: _CheckJob = shared()
    counts = dict.fromkeys(SEVERITY_RANK, 0)
    spool, out = _spool(job)
    binary = job.fmt == "sarif"
    raw = out if binary else out.buffer
    if not binary:
        out.flush()
    result = CheckedFile(name, counts, findings=spool, start=raw.tell())
    try:
        if binary:
            checker, found = iter_check_file(path, job.profile, display=name,
                                             select=job.select, ignore=job.ignore)
            batch: list[tuple[Any, ...]] = []
            for finding in found:
                counts[finding.severity] += 1
                batch.append(tuple(finding))
                if len(batch) == _SARIF_BATCH:
                    pickle.dump(batch, out)
                    batch.clear()
            if batch:
                pickle.dump(batch, out)
        else:
            checker = Checker(job.profile, name, select=job.select, ignore=job.ignore,
                              report=job.fmt)
            try:
                checker.report_file(path, out.write)
            finally:
                counts.update(checker.counts)
    except OSError as exc:
        result.error = f"tapegate: cannot read {name}: {exc.strerror or exc}"
    except TapegateError as exc:  # e.g. not an NC program at all
        from tapegate.common import error_exit

        result.error = error_exit(exc.located(file=name), input_exit=2)[0]
    else:
        result.stats = checker.stats
    finally:  # the findings written before an error are copied too
        result.count = sum(counts.values())
    if not binary:
        out.flush()
    result.end = raw.tell()
    return result


def _copy(path: str, start: int, end: int, out: TextIO) -> None:
    """Bytes ``start`` to ``end`` of a file, as they are, onto ``out`` after what it holds:
    through ``os.sendfile`` to its file descriptor where it has one (stdout), else through its
    binary buffer (a test's capture)."""
    out.flush()
    with open(path, "rb") as source:
        try:
            target = out.fileno()
            while start < end:
                sent = os.sendfile(target, source.fileno(), start, end - start)
                if not sent:
                    raise OSError(f"{path} ended before byte {end}")
                start += sent
            return
        except (AttributeError, ValueError, OSError) as exc:
            import errno
            import io

            if (isinstance(exc, OSError) and not isinstance(exc, io.UnsupportedOperation)
                    and exc.errno not in (errno.EINVAL, errno.ENOSYS, errno.EOPNOTSUPP)):
                raise  # a closed pipe, a full disk: the command's to tell
        source.seek(start)
        binary = getattr(out, "buffer", None)
        while start < end:
            piece = source.read(min(_COPY, end - start))
            if not piece:
                raise OSError(f"{path} ended before byte {end}")
            start += len(piece)
            if binary is not None:
                binary.write(piece)
            else:
                out.write(piece.decode(out.encoding or "utf-8", out.errors or "strict"))
        if binary is not None:
            binary.flush()


def check_files(items: Sequence[tuple[str, str]], profile: Profile, *, fmt: str,
                select: Sequence[str], ignore: Sequence[str], jobs: int,
                writer: Any) -> Iterator[CheckedFile]:
    """Check every (path, name) in ``jobs`` processes; each file's findings are written
    through ``writer`` (the text, JSON, JSON Lines or SARIF report of ``postproc.report``) in
    the order of ``items`` -- text, JSON and JSON Lines copied as bytes onto the report's
    stream -- and its :class:`CheckedFile` yielded after them (its error is for the caller to
    say)."""
    import pickle
    import shutil
    import tempfile

    from postproc.findings import make_finding

    out: Any = getattr(writer, "out", None)  # (SARIF's findings are records, added by the writer)
    spool = tempfile.mkdtemp(prefix="tapegate-check-")
    job = _CheckJob(profile, fmt, tuple(select), tuple(ignore), spool,
                    getattr(out, "encoding", None) or "utf-8",
                    getattr(out, "errors", None) or "strict")
    copied: str | None = None  # the chunk's temporary file being copied
    try:
        for done in ordered_map(_check_one, items, jobs, shared=job,
                                weights=sizes(path for path, _ in items)):
            assert done.findings is not None
            if copied != done.findings:
                if copied is not None:
                    os.unlink(copied)
                copied = done.findings
            if fmt == "sarif":
                with open(done.findings, "rb") as records:
                    records.seek(done.start)
                    while records.tell() < done.end:
                        for fields in pickle.load(records):
                            writer.add(make_finding(fields))
            elif done.count:
                # (the document's first JSON finding opens the array: its ",\n" is dropped)
                start = done.start + (2 if fmt == "json" and writer.open_array() else 0)
                _copy(done.findings, start, done.end, out)
            yield done
    finally:
        shutil.rmtree(spool, ignore_errors=True)
