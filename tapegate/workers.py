"""Files spread over worker processes for ``check`` and ``convert`` (``-j``), reports in the
order of the input, memory flat.

:func:`ordered_map` runs a function on every item in a pool of processes and yields the
results in the items' order. At most ``2 * jobs`` items are given out at a time, so a slow
file holds back only the few after it: the results waiting for it are small (a conversion's
statistics), or a temporary file on disk (a check's findings, :func:`check_files`), never a
growing list in memory.

A check in a worker writes its findings as the report will print them (text, JSON Lines, the
JSON document's members) into a temporary file, and the main process copies the files into
the report one after the other: stdout is byte for byte what ``-j 1`` writes. SARIF numbers
the rules in the order they first appear across all files, which a worker cannot know: its
findings are passed as records and written by the main process.

Workers are forked where the system can (Linux): they start with the modules and the profile
already loaded.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar

# multiprocessing, concurrent.futures, pickle and tempfile are imported where a pool is started
# (a fifth of a short check's start-up when imported here): one file checks without them
if TYPE_CHECKING:
    from formats.profile import Profile
    from postproc.check import CheckStats

T = TypeVar("T")
R = TypeVar("R")

_SARIF_BATCH = 4096  # findings pickled at a time by a worker for the SARIF report
_COPY = 1 << 20  # characters copied at a time from a worker's findings into the report


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


def _share(value: object) -> None:
    _SHARED[:] = [value]


def shared() -> Any:
    """In ``func`` of :func:`ordered_map`: the value given as its ``shared``."""
    return _SHARED[0]


def ordered_map(func: Callable[[T], R], items: Sequence[T], jobs: int, *,
                shared: object = None) -> Iterator[R]:
    """``func(item)`` for every item, in ``jobs`` processes, yielded in the items' order.
    ``shared`` is what every item needs (the profiles, the options): given to each worker
    once, not with every item, and read there by :func:`shared` (when ``jobs`` is 1 or there
    is one item, nothing is started and the items are done one by one in this process).
    An exception ``func`` raises is raised here, when its item's turn comes."""
    if jobs <= 1 or len(items) <= 1:
        _share(shared)
        for item in items:
            yield func(item)
        return
    from collections import deque
    from concurrent.futures import Future, ProcessPoolExecutor
    from itertools import islice

    window = 2 * jobs
    # (forked, a worker inherits ``shared`` as it is; spawned, it is pickled once per worker)
    pool = ProcessPoolExecutor(max_workers=min(jobs, len(items)), mp_context=_context(),
                               initializer=_share, initargs=(shared,))
    try:
        waiting: deque[Future[R]] = deque()
        rest = iter(items)
        for item in islice(rest, window):
            waiting.append(pool.submit(func, item))
        while waiting:
            result = waiting.popleft().result()
            for item in islice(rest, 1):
                waiting.append(pool.submit(func, item))
            yield result
    finally:
        pool.shutdown(wait=True, cancel_futures=True)


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


@dataclass
class CheckedFile:
    """What a worker sends back for one file: counts, statistics, or why it was not read, and
    where its findings wait (a temporary file the main process copies, then deletes)."""

    name: str
    counts: dict[str, int]
    stats: CheckStats | None = None
    error: str | None = None
    findings: str | None = None  # the temporary file
    count: int = 0


@dataclass(frozen=True)
class _CheckJob:
    """The settings every file of one ``check`` shares, given to each worker once."""

    profile: Profile
    fmt: str
    select: tuple[str, ...]
    ignore: tuple[str, ...]
    spool: str  # the folder of the temporary files


def _check_one(item: tuple[str, str]) -> CheckedFile:
    """Check one file into a temporary file of rendered findings (in a worker)."""
    import pickle
    import tempfile

    from formats.errors import TapegateError
    from postproc.check import Checker, iter_check_file
    from postproc.rules import SEVERITY_RANK

    path, name = item
    job: _CheckJob = shared()
    counts = dict.fromkeys(SEVERITY_RANK, 0)
    fd, spool = tempfile.mkstemp(prefix="check-", dir=job.spool)
    result = CheckedFile(name, counts, findings=spool)
    binary = job.fmt == "sarif"
    with open(fd, "wb" if binary else "w", encoding=None if binary else "utf-8",
              errors=None if binary else "surrogateescape") as out:
        try:
            if binary:  # SARIF: the findings as records, for the main process to number
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
            else:  # text, JSON, JSON Lines: as the core writes them for the report
                checker = Checker(job.profile, name, select=job.select, ignore=job.ignore,
                                  report=job.fmt)
                try:
                    checker.report_file(path, out.write)
                finally:
                    counts.update(checker.counts)
        except OSError as exc:
            result.error = f"tapegate: cannot read {name}: {exc.strerror or exc}"
            return result
        except TapegateError as exc:  # e.g. not an NC program at all
            from tapegate.common import error_exit

            result.error = error_exit(exc.located(file=name), input_exit=2)[0]
            return result
        finally:  # the findings written before an error are copied too
            result.count = sum(counts.values())
    result.stats = checker.stats
    return result


def check_files(items: Sequence[tuple[str, str]], profile: Profile, *, fmt: str,
                select: Sequence[str], ignore: Sequence[str], jobs: int,
                writer: Any) -> Iterator[CheckedFile]:
    """Check every (path, name) in ``jobs`` processes; each file's findings are written
    through ``writer`` (the text, JSON, JSON Lines or SARIF report of ``postproc.report``) in
    the order of ``items``, and its :class:`CheckedFile` yielded after them (its error is for
    the caller to say)."""
    import pickle
    import shutil
    import tempfile

    from postproc.findings import make_finding

    spool = tempfile.mkdtemp(prefix="tapegate-check-")
    job = _CheckJob(profile, fmt, tuple(select), tuple(ignore), spool)
    try:
        for done in ordered_map(_check_one, items, jobs, shared=job):
            assert done.findings is not None
            try:
                if fmt == "sarif":
                    with open(done.findings, "rb") as records:
                        while True:
                            try:
                                batch = pickle.load(records)
                            except EOFError:
                                break
                            for fields in batch:
                                writer.add(make_finding(fields))
                elif done.count:
                    with open(done.findings, encoding="utf-8",
                              errors="surrogateescape") as rendered:
                        for piece in iter(lambda: rendered.read(_COPY), ""):
                            writer.write(piece)
            finally:
                os.unlink(done.findings)
            yield done
    finally:
        shutil.rmtree(spool, ignore_errors=True)
