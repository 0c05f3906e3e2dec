"""Files spread over threads for ``check`` and ``convert`` (``-j``), reports in the order of
the input, memory flat.

:func:`ordered_map` runs a function on every item in ``jobs`` threads and yields the results
in the items' order. Threads are enough because a file's work is the core's: it checks and
converts whole lines with the GIL released (``crates/python``: ``Checker.check_lines``,
``Converter.convert_lines``, ``ParameterAnalysis.read_lines``), so the threads run side by
side on the cores, and take the GIL only for what Python does per 1 MiB chunk (reading,
decoding) and per file (the checker, the statistics). Nothing is forked, pickled or written to
temporary files, and nothing of ``multiprocessing`` or ``concurrent.futures`` is imported.

A function that writes a report hands its pieces (a checker's 64 KiB slices) to :func:`send`:
they reach the ``receive`` of :func:`ordered_map`, in the main thread, at the item's turn and
before its result, so the output is what one thread writes, in the same calls. Memory stays
flat: at most ``2 * jobs`` items are given out beyond the one whose turn it is, and a thread
whose item is not yet due waits once it holds :data:`PIECES` pieces of it.
"""

from __future__ import annotations

import os
import threading
from collections import deque
from collections.abc import Callable, Iterable, Iterator, Sequence
from typing import Any, TypeVar

T = TypeVar("T")
R = TypeVar("R")

# The pieces of one item held while it waits for its turn (a checker's are 64 KiB: 1 MiB)
PIECES = 16


def default_jobs() -> int:
    """The CPUs this process may run on (``-j``'s default)."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


class _Stopped(BaseException):
    """Raised in a thread by :func:`send` once the map is stopped (an error, SIGTERM, a closed
    pipe in the main thread): its item is abandoned (a BaseException, so that the function's
    own ``except Exception`` lets it through)."""


_local = threading.local()


def send(piece: Any) -> None:
    """In ``func`` of :func:`ordered_map`: hand ``piece`` to the map's ``receive`` (at the
    item's turn, in the main thread; with one job, at once)."""
    _local.send(piece)


def _terminated(signum: int, frame: object) -> None:
    """SIGTERM in the main thread while threads run (a CI job's timeout, `kill`): an exit with
    128 + the signal's number, through the ``finally`` clause that stops the threads."""
    raise SystemExit(128 + signum)


class _Slot:
    """One item given out: its pieces not yet received, then its result or exception."""

    __slots__ = ("pieces", "done", "result", "error")

    def __init__(self) -> None:
        self.pieces: deque[Any] = deque()
        self.done = False
        self.result: Any = None
        self.error: BaseException | None = None


class _Map:
    """The state the threads of one :func:`ordered_map` share, under one condition."""

    def __init__(self, func: Callable[[Any], Any], items: Sequence[Any], window: int) -> None:
        self.func, self.items, self.window = func, items, window
        self.cond = threading.Condition()
        self.slots: dict[int, _Slot] = {}
        self.given = 0  # items given out
        self.due = 0  # the item whose turn it is
        self.stopped = False

    def work(self) -> None:
        """A thread: the next item not given out, while fewer than ``window`` are out (the
        one whose turn it is among them)."""
        cond = self.cond
        while True:
            with cond:
                while (not self.stopped and self.given < len(self.items)
                       and self.given >= self.due + self.window):
                    cond.wait()
                if self.stopped or self.given >= len(self.items):
                    return
                index = self.given
                self.given += 1
                slot = self.slots[index] = _Slot()
            _local.send = lambda piece, slot=slot: self.put(slot, piece)
            try:
                slot.result = self.func(self.items[index])
            except _Stopped:
                return
            except BaseException as exc:  # raised in the main thread at its item's turn
                slot.error = exc
            with cond:
                slot.done = True
                cond.notify_all()

    def put(self, slot: _Slot, piece: Any) -> None:
        with self.cond:
            while len(slot.pieces) >= PIECES and not self.stopped:
                self.cond.wait()
            if self.stopped:
                raise _Stopped
            slot.pieces.append(piece)
            self.cond.notify_all()

    def take(self, index: int) -> tuple[bool, Any]:
        """(False, a piece) of item ``index``, or (True, its slot) once it is done and every
        piece has been taken."""
        with self.cond:
            while True:
                slot = self.slots.get(index)
                if slot is not None:
                    if slot.pieces:
                        piece = slot.pieces.popleft()
                        self.cond.notify_all()
                        return False, piece
                    if slot.done:
                        del self.slots[index]
                        self.due = index + 1
                        self.cond.notify_all()
                        return True, slot
                self.cond.wait()

    def stop(self) -> None:
        with self.cond:
            self.stopped = True
            self.cond.notify_all()


def ordered_map(func: Callable[[T], R], items: Sequence[T], jobs: int, *,
                receive: Callable[[Any], object] | None = None) -> Iterator[R]:
    """``func(item)`` for every item, in ``jobs`` threads, yielded in the items' order; what
    ``func`` hands to :func:`send` is given to ``receive`` here, at its item's turn, before its
    result. When ``jobs`` is 1 or there is one item, no thread is started: the items are done
    one by one here, and :func:`send` calls ``receive`` at once. An exception ``func`` raises
    is raised here, when its item's turn comes, after the pieces it sent; the items after it
    are abandoned."""
    if jobs <= 1 or len(items) <= 1:
        _local.send = receive
        for item in items:
            yield func(item)
        return
    import signal

    state = _Map(func, items, 2 * jobs)
    main_thread = threading.current_thread() is threading.main_thread()
    before = signal.signal(signal.SIGTERM, _terminated) if main_thread else None
    threads = [threading.Thread(target=state.work, name=f"tapegate-{n}", daemon=True)
               for n in range(min(jobs, len(items)))]
    try:
        for thread in threads:
            thread.start()
        for index in range(len(items)):
            while True:
                done, got = state.take(index)
                if done:
                    break
                if receive is not None:
                    receive(got)
            if got.error is not None:
                raise got.error
            yield got.result
    finally:
        # stopped or done: a thread sending stops at once, one in the core at its chunk's end
        state.stop()
        for thread in threads:
            if thread.is_alive():
                thread.join()
        if main_thread:
            signal.signal(signal.SIGTERM, before)


def input_files(names: Iterable[str]) -> list[str]:
    """The files named: a folder stands for every file below it (symbolic links to files
    among them, folders linked to not entered), sorted by their paths' parts, hidden ones (a
    name starting with ``.``) left out; anything else is taken as it is named (a missing file
    is reported when it is read). The paths are written as ``pathlib`` writes them
    (:func:`_pure`), without importing it: 17M instructions, a tenth of what runs before the
    threads start."""
    files: list[str] = []
    for name in names:
        if name != "-" and os.path.isdir(name):
            root = _pure(name)
            found: list[tuple[str, ...]] = []
            for folder, dirs, names_in in os.walk(root):
                dirs[:] = [d for d in dirs if not d.startswith(".")]
                below = () if folder == root else tuple(
                    os.path.relpath(folder, root).split(os.sep))
                found.extend((*below, n) for n in names_in if not n.startswith(".")
                             and os.path.isfile(os.path.join(folder, n)))
            files.extend(os.path.join(root, *parts) if root != "." else os.path.join(*parts)
                         for parts in sorted(found))
        else:
            files.append(name)
    return files


def _pure(name: str) -> str:
    """``str(pathlib.PurePosixPath(name))``: empty and ``.`` parts dropped, ``..`` kept, two
    leading slashes kept as two (POSIX leaves their meaning to the system), more as one."""
    root = "//" if name.startswith("//") and not name.startswith("///") else (
        "/" if name.startswith("/") else "")
    parts = [p for p in name.split("/") if p not in ("", ".")]
    return root + "/".join(parts) or "."
