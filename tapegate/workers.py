"""Files spread over threads for ``check`` and ``convert`` (``-j``), reports in the order of
the input, memory flat.

:func:`ordered_map` runs a function on every item in ``jobs`` threads and yields the results
in the items' order. Threads are enough because a file's work is the core's: it checks and
converts whole lines with the GIL released (``crates/python``: ``Checker.check_file``, which
reads the file too, ``Converter.convert_lines``, ``ParameterAnalysis.read_lines``), so the
threads run side by side on the cores, and take the GIL only for what Python does per file
(the checker, the statistics, the report's slices handed over) and, in a conversion, per 1 MiB
chunk (reading, decoding). Nothing is forked or pickled, nothing
of ``multiprocessing`` or ``concurrent.futures`` is imported, and a temporary file is made only
for a report that must wait (below). The threads, their locks and conditions are the
interpreter's own (``_thread``): a check's start-up before them does not import ``threading``.

The thread that calls :func:`ordered_map` (the main thread) is one of the ``jobs`` workers
when the function sends text or nothing (``sizes`` given: ``check`` but SARIF, ``convert``):
``-j 2`` starts one thread, and the main thread does an item itself wherever it would
otherwise wait for the one whose turn it is (:meth:`_Map.take`, :meth:`_Map.here`), handing
on the reports of the items done between its own (an item started early, a long one
during which the window does not move for the threads, only once every thread has one:
:func:`first`). So no third thread
shares two cores, and no working thread is put off its core to hand the reports on; an item
the main thread is given at its turn hands its pieces to ``receive`` at once, as with one
job, and one given before its turn keeps them as a thread's (past the budget, spilled:
nothing here may wait for room, which only the main thread makes). An ``Exception`` of its
function is raised at its turn, as a thread's; ^C (``KeyboardInterrupt``, when the core
hands a slice over or ends a file) and SIGTERM's exit leave at once, the threads stopped
(docs/benchmarks.md, "the main thread as a worker") -- raised in the main thread only where
it waits, does its own item, runs the caller's code or joins the stopped threads (a second
^C there ends the command, the threads left: review 42, finding 6), else at its next such
point, never inside the map's lock and condition code (:func:`_signalled`; review 39,
finding 7).

A function that writes a report hands its pieces (a checker's 64 KiB slices) to :func:`send`:
they reach the ``receive`` of :func:`ordered_map`, in the main thread, at the item's turn and
before its result, so the output is what one thread writes, in the same calls; the main
thread is woken for them :data:`BATCH` at a time, or once :data:`RUN` items are done in a
row (:meth:`_Map._ready`): not once a slice, nor once a short file (each wake-up is a
context switch, a working thread put off its core, and a hand-over of the GIL;
docs/benchmarks.md, "the serial part of `-j 2`", "the main thread woken once for several
files"). Memory stays
flat: at most :data:`WINDOW` items a thread are given out beyond the one whose turn it is, and
the items not yet due hold at most :data:`WAITING` pieces a thread in memory, together (an
item started early, below, :data:`EARLY` of its own); past that, an item's further text
pieces (a report's slices) go to a temporary file of its own, read back at its turn, so that
a file with megabytes of findings does not hold up the threads behind it; other pieces
(SARIF's lists of findings) make the thread wait until they are taken. Where that file cannot
be written (no room, no descriptor: :attr:`_Map.unspilled`), no piece is lost and no input is
blamed: text pieces then wait as other pieces do, told once on stderr, and the main thread's
own item begun before its turn, which cannot wait, is abandoned where its pieces would pass
the bound and done again at its turn, its pieces then handed on at once: memory stays flat
(its function is one whose work may be done twice: a check reads and checks a file, and a
conversion, which sends nothing, never comes here). (The bound is shared,
not one for each item: the same memory at most as ``WINDOW`` items of 2 pieces each, without
spilling the report of every short file finished ahead of its turn.)

The items are given out in their order, except the few whose work would end the batch alone
(:func:`first`, from the sizes of the files): a long file late in a folder, taken where the
order puts it, is checked by one thread while the others have nothing left to do. Those are
started first, the largest first, their reports spilled and written at their turn; at most
:data:`WINDOW` of them a thread, so memory stays flat.
"""

from __future__ import annotations

import _thread
import os
import sys
from _collections import deque

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from collections.abc import Callable, Generator, Iterable, Sequence
    from typing import Any, TypeVar

    T = TypeVar("T")
    R = TypeVar("R")

# The items given out beyond the one whose turn it is, per thread: enough that the threads go
# on past a long file to the short ones after it (the shops folder's largest file is a fifth of
# its work), the waiting items holding at most WAITING pieces a thread in memory.
WINDOW = 8
# The pieces (a checker's are 64 KiB) held in memory of the item whose turn it is, which the
# main thread is taking (1 MiB), and of the items not yet due, all together, a thread (1 MiB):
# past them, a not-due item's text pieces are spilled to a temporary file, other pieces make
# its thread wait. (WAITING was 2 pieces for each item, WINDOW of them a thread: the same
# bound, but the shops folder's reports of 250 kB a file spilled 9-20 of their 30.6 MB, 50M
# instructions and the kernel's time to write and read back.)
PIECES = 16
WAITING = 2 * WINDOW
# The pieces held in memory of an item started early (first()), past which it spills: its turn
# is the furthest off, and its report the longest; the budget is for the items near their turn.
EARLY = 2
# The pieces of the item whose turn it is that wake the main thread to take them (all at
# once), before the item is done.
BATCH = PIECES // 2
# The items done in a row, from the one whose turn it is, that wake the main thread to take
# them (:meth:`_Map._ready`).
RUN = 4


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


class _Again(BaseException):
    """Raised in the main thread by :func:`send` where its own item, begun before its turn,
    has a piece that can be neither held within the bound nor spilled (the spill failed): the
    item is abandoned, its pieces dropped, and done again at its turn (:meth:`_Map.take`)."""


_local = _thread._local()


class _Condition:
    """A condition over a lock shared with others: ``threading.Condition``'s ``wait`` (without
    a timeout), ``notify`` and ``notify_all``, on the interpreter's own locks (``_thread``),
    so that a check's start-up does not import ``threading`` (3.1M instructions before the
    first thread, with ``_weakrefset``; docs/benchmarks.md, "the serial start-up without
    threading and functools"). A waiter is a lock of its own, held, that ``notify`` releases;
    the waiting thread takes the shared lock back before it returns, as
    ``threading.Condition.wait`` does."""

    __slots__ = ("_lock", "_waiters")

    def __init__(self, lock: Any) -> None:
        self._lock = lock
        self._waiters: deque[Any] = deque()

    def __enter__(self) -> bool:
        return bool(self._lock.acquire())

    def __exit__(self, *exc: object) -> None:
        self._lock.release()

    def wait(self, guard: _Map | None = None) -> None:
        """Release the shared lock (held by the caller), wait for a ``notify``, take it back.
        With ``guard`` (the main thread's map): a signal may interrupt the wait itself, and
        only it (:func:`_signalled`)."""
        waiter = _thread.allocate_lock()
        waiter.acquire()
        self._waiters.append(waiter)
        self._lock.release()
        woken = False
        try:
            if guard is not None:
                guard.interruptible()
            woken = waiter.acquire()
        finally:
            if guard is not None:
                guard.safe = False
            self._lock.acquire()
            # interrupted (a KeyboardInterrupt), and not notified meanwhile: not left among
            # the waiters
            if not woken and waiter in self._waiters:
                self._waiters.remove(waiter)

    def notify(self, n: int = 1) -> None:
        """Wake up to ``n`` of the threads waiting (the shared lock held)."""
        waiters = self._waiters
        while waiters and n > 0:
            waiters.popleft().release()
            n -= 1

    def notify_all(self) -> None:
        self.notify(len(self._waiters))


def send(piece: Any) -> None:
    """In ``func`` of :func:`ordered_map`: hand ``piece`` to the map's ``receive`` (at the
    item's turn, in the main thread; with one job, at once)."""
    _local.send(piece)


def _signalled(state: _Map, signum: int) -> None:
    """SIGINT (^C), SIGTERM (a CI job's timeout, `kill`) or SIGHUP (where a command makes it an
    exit: its terminal closed) in the main thread while a map's
    threads run: ``KeyboardInterrupt``, or an exit with 128 + the signal's number, through the
    ``finally`` clause that stops the threads -- raised at once where the main thread is at a
    point where an exception is safe (``state.safe``: waiting for a notify, doing its own
    item, running the caller's code, or joining the threads once they are stopped), else
    held (``state.pending``) and raised at its next such point, soon after. Raised anywhere,
    it could land between a lock's acquire and the ``with`` that releases it, or between a
    waiter taken off a condition's list and its release, and the threads' join then waited
    for ever (1 in 15 interrupted `convert -j 2` batches hung so; review 39, finding 7)."""
    error = KeyboardInterrupt() if signum == _SIGINT else SystemExit(128 + signum)
    stops = sys.modules.get("formats.stops")
    if stops is not None:  # (formats.stops.heed_stops: a stop a finalizer swallowed)
        stops.TAKEN.append(signum)
    if state.safe:
        state.safe = False  # (the code that handles it is not a safe point)
        raise error
    if state.pending is None:
        state.pending = error


_SIGINT = 2  # (signal.SIGINT, without importing signal)


class _Slot:
    """One item given out: its pieces not yet received, then its result or exception.

    Pieces of an item not yet due past the map's ``budget`` are spilled: written (bytes as
    they are, a string UTF-8 encoded) at the end of ``spill`` (a temporary file, made at the
    first), their lengths and kinds kept in ``spilled``; ``read_at`` is where the next one to
    be taken begins. Once an item spills,
    every later piece of it does, so that they are taken in the order they were sent. Where
    the spill has failed (:attr:`_Map.unspilled`), an item that has spilled queues its later
    pieces themselves in ``spilled`` (``kept`` of them), after those in its file. ``again``:
    the main thread's item abandoned before its turn, to be done again at it (:class:`_Again`).
    """

    __slots__ = ("index", "early", "pieces", "done", "result", "error", "spill", "spilled",
                 "write_at", "read_at", "kept", "again")

    def __init__(self, index: int, early: bool = False) -> None:
        self.index = index
        self.early = early  # started before the items ahead of it (first())
        self.pieces: deque[Any] = deque()
        self.done = False
        self.result: Any = None
        self.error: BaseException | None = None
        self.spill: int | None = None  # the temporary file's descriptor
        # (length, a str's, None) of a piece in the file; (0, False, the piece) of one kept
        self.spilled: deque[tuple[int, bool, Any]] = deque()
        self.write_at = 0
        self.read_at = 0
        self.kept = 0  # the pieces themselves in ``spilled`` (the spill failed)
        self.again = False

    def close(self) -> None:
        if self.spill is not None:
            os.close(self.spill)
            self.spill = None


def first(sizes: Sequence[int], jobs: int) -> list[int]:
    """The items to start before the others, the largest first: those larger than an item's
    mean size whose own work, started where the order puts it, would end after the rest of
    the batch. With ``jobs`` threads taking the items in order, item ``i`` starts once about
    ``1/jobs`` of the work before it is done and ends about when the rest does if
    ``size[i] * (jobs - 1) > sum(size[i + 1:])`` (the work after it, shared by the other
    threads meanwhile); the mean is the bar below which moving an item changes nothing (a
    batch ends with some item, and one of the mean size is what any order ends with). At most
    ``WINDOW * jobs``."""
    if jobs <= 1 or not sizes:
        return []
    mean = sum(sizes) / len(sizes)
    found: list[int] = []
    after = 0
    for index in range(len(sizes) - 1, -1, -1):
        size = sizes[index]
        if size > mean and size * (jobs - 1) > after:
            found.append(index)
        after += size
    found.sort(key=lambda i: (-sizes[i], i))
    return found[:WINDOW * jobs]


class _Map:
    """The state the threads of one :func:`ordered_map` share, under one condition. The items
    are given out in ``order``: the ``early`` ones (:func:`first`), then the others by their
    index; an early item is given at once, another only within ``window`` of the one whose
    turn it is (which is always the next of the others, once the early ones are out)."""

    def __init__(self, func: Callable[[Any], Any], items: Sequence[Any], window: int,
                 budget: int, early: Sequence[int] = ()) -> None:
        self.func, self.items, self.window = func, items, window
        # the pieces the items not yet due may hold in memory, together; ``held``: how many
        # they hold (the pieces of every slot but the due one's)
        self.budget, self.held = budget, 0
        # One lock, two conditions, so that a thread is woken only for what it waits on: the
        # main thread (``cond``) for a piece or the end of the item whose turn it is, the
        # threads (``space``) for the window moving on or room for a piece. (One condition
        # for both woke every thread at every piece of any item: 1,800-2,600 context switches
        # for the shops folder and 200 copies, 600 now, and 4-8 % of their CPU.)
        lock = _thread.allocate_lock()
        self.cond = _Condition(lock)
        self.space = _Condition(lock)
        self.slots: dict[int, _Slot] = {}
        skipped = set(early)
        self.order = [*early, *(i for i in range(len(items)) if i not in skipped)]
        self.early = len(early)
        # the threads started (the main thread not among them): where every one has been
        # given an early item, the main thread takes the next early one itself
        self.threads = 1 << 30
        self.given = 0  # items given out: the first ``given`` of ``order``
        self.due = 0  # the item whose turn it is
        self.stopped = False
        # the main thread at a point where a signal's exception is safe, and a signal's
        # exception held until it is (_signalled)
        self.safe = False
        self.pending: BaseException | None = None
        # an error a thread met outside an item's function (in the map's own work), raised
        # in the main thread where it would otherwise wait for an item that thread had taken
        self.failure: BaseException | None = None
        # The spill's failure (no room in the temporary folder, no descriptor left, a folder
        # that cannot be written: an OSError) and the folder it names: from then on no piece
        # is spilled, a thread's item not yet due waits for its turn with its pieces (as
        # other pieces than text do), and the main thread takes no item of its own before its
        # turn unless every thread waits so (:meth:`take`); the main thread's own item begun
        # before its turn is done again at its turn (:class:`_Again`), told once on stderr
        # (review 75, N1: the items whose spill failed were told as files that cannot be
        # read, their findings lost; then the main thread's item held its whole report)
        self.unspilled: OSError | None = None
        self.spill_folder = ""
        self.blocked = 0  # the threads waiting in put() for an item not yet due
        self.told = False  # the spill's failure told

    def work(self) -> None:
        """A thread: the next item of ``order``: an early one, or one within ``window`` of
        the one whose turn it is."""
        cond = self.cond
        while True:
            with cond:
                while (not self.stopped and self.given < len(self.items)
                       and not self._open()):
                    cond.notify()  # (the main thread moves the window: woken for it)
                    self.space.wait()
                if self.stopped or self.given >= len(self.items):
                    return
                slot = self._give()
                if self.given in (self.early, self.threads):  # the last started early, or
                    cond.notify()  # every thread has one: the main thread may take the next
            index = slot.index
            _local.send = lambda piece, slot=slot: self.put(slot, piece)
            try:
                slot.result = self.func(self.items[index])
            except _Stopped:
                return
            except BaseException as exc:  # raised in the main thread at its item's turn
                slot.error = exc
            with cond:
                slot.done = True
                if self._ready():
                    cond.notify()

    def _open(self) -> bool:
        """Whether the next item of ``order`` may be given out now (the lock held; not
        stopped, not every item given): an early one, or one within ``window`` of the one
        whose turn it is."""
        return (self.given < self.early
                or self.order[self.given] < self.due + self.window)

    def _give(self) -> _Slot:
        """The next item of ``order``, given out (the lock held; :meth:`_open` true)."""
        index = self.order[self.given]
        slot = self.slots[index] = _Slot(index, self.given < self.early)
        self.given += 1
        return slot

    def here(self, slot: _Slot, receive: Callable[[Any], object] | None) -> None:
        """The main thread's own item (:meth:`take`'s third value), done here: its pieces
        handed to ``receive`` at once if its turn had come when it was given (every item
        before it taken), else kept as a thread's are (:meth:`put`: past the budget, text
        spills and other pieces are held; nothing here waits for room, which only this
        thread makes).
        An ``Exception`` of the function is raised at the item's turn, as a thread's; a
        ``BaseException`` (^C's ``KeyboardInterrupt``, SIGTERM's ``SystemExit``) at once."""
        if slot.index == self.due:  # (``due`` moves in this thread only)
            _local.send = receive
        else:
            _local.send = lambda piece: self._put_here(slot, piece)
        try:
            self.interruptible()  # (the function's own work: a signal's exception is safe)
            slot.result = self.func(self.items[slot.index])
        except _Stopped:  # the map stopped by a thread's failure: raised by take
            return
        except _Again:  # done again at its turn: its pieces dropped (memory stays flat)
            self.safe = False
            with self.cond:
                self._drop(slot)
            return
        except Exception as exc:
            slot.error = exc
        finally:
            self.safe = False
        with self.cond:
            slot.done = True

    def interruptible(self) -> None:
        """The main thread enters a point where a signal's exception is safe: raised now if
        one is held (:func:`_signalled`)."""
        self.safe = True
        if self.pending is not None:
            self.safe = False
            raise self.pending

    def _put_here(self, slot: _Slot, piece: Any) -> None:
        """:meth:`put` for the main thread's own item: no signal's exception in its locks."""
        self.safe = False
        try:
            self.put(slot, piece, True)
        except _Again:
            if not self.told:
                self.told = True
                assert self.unspilled is not None
                _tell(f"tapegate: cannot write the reports waiting for their turn to "
                      f"{self.spill_folder}: {self.unspilled.strerror or self.unspilled}; "
                      f"the files wait for their turn instead")
            raise
        finally:
            self.interruptible()

    def _drop(self, slot: _Slot) -> None:
        """The main thread's own item abandoned before its turn (the lock held): its pieces
        dropped, to be done again at its turn (:meth:`take`)."""
        if not slot.early:
            self.held -= len(slot.pieces)
        slot.pieces.clear()
        slot.spilled.clear()
        slot.kept = 0
        slot.close()
        slot.write_at = slot.read_at = 0
        slot.again = True
        self.space.notify_all()  # (room in the budget)

    def _ready(self) -> bool:
        """Whether the main thread is to be woken now that an item is done (the lock held):
        once the items done in a row from the one whose turn it is are :data:`RUN`, or (the
        one whose turn it is done) the items not yet due hold half their budget, or every
        item has been given out (the batch's end: each item done is taken at once). A thread
        that then waits for the window or for room wakes the main thread before it waits
        (:meth:`work`, :meth:`put`), so the items done are always taken.

        Woken for every item, as before, the main thread took a core from a working thread
        each time (2 threads on 2 cores): in a check of 200 copies, 980 context switches, 360
        of them a thread put off its core; 280 now (docs/benchmarks.md, "the main thread woken
        once for several files")."""
        slots, due = self.slots, self.due
        for n in range(RUN):
            slot = slots.get(due + n)
            if slot is None or not slot.done:
                return n > 0 and (self.given >= len(self.items)
                                  or self.held * 2 >= self.budget)
        return True

    def put(self, slot: _Slot, piece: Any, here: bool = False) -> None:
        """``piece`` of ``slot``'s item, sent by the thread doing it (``here``: the main
        thread, which never waits, as only it makes room): held in memory within the bounds,
        else spilled (text), else waited with for room (a thread) or held past the bounds
        (the main thread: other pieces than text). Where the spill fails (an
        ``OSError``), nothing is lost: :attr:`unspilled` is set and the piece placed again."""
        while True:
            with self.cond:
                while True:
                    if self.stopped:
                        raise _Stopped
                    due = slot.index == self.due
                    if slot.spill is None and (len(slot.pieces) < PIECES if due
                                               else len(slot.pieces) < EARLY if slot.early
                                               else self.held < self.budget):
                        slot.pieces.append(piece)
                        if due:
                            if len(slot.pieces) >= BATCH:
                                self.cond.notify()
                        elif not slot.early:
                            self.held += 1
                        return
                    if isinstance(piece, str | bytes) and (slot.spill is not None or not due):
                        if self.unspilled is None:
                            break
                        if here:  # (never due: given before its turn, and the turn moves
                            raise _Again  # only in this thread) -- it cannot wait for room
                        if due and slot.kept < PIECES:
                            self._keep(slot, piece, due)
                            return
                    elif here:  # other pieces of the main thread's own item: held, as
                        # only it makes room (waiting, it waited for ever: the CI's hang)
                        self._keep(slot, piece, due)
                        return
                    self.cond.notify()  # (the main thread makes the room: woken for it)
                    if due:
                        self.space.wait()
                    else:
                        self.blocked += 1
                        try:
                            self.space.wait()
                        finally:
                            self.blocked -= 1
                if slot.spill is None:
                    try:
                        slot.spill, self.spill_folder = _spill_file()
                    except OSError as exc:
                        self._unspillable(exc, slot)
                        continue
            # written outside the lock: only this thread writes this item's file, and the main
            # thread reads a piece only once its length is in ``spilled``; a report's bytes as
            # they are (JSON: the core's own), a string UTF-8 encoded, read back as it came
            text = isinstance(piece, str)
            data = piece.encode("utf-8", "surrogatepass") if isinstance(piece, str) else piece
            at = slot.write_at
            try:
                while at < slot.write_at + len(data):
                    at += os.pwrite(slot.spill, data[at - slot.write_at:], at)
            except OSError as exc:  # (what it wrote past ``write_at`` is never read)
                with self.cond:
                    self._unspillable(exc, slot)
                continue
            with self.cond:
                slot.write_at = at
                slot.spilled.append((len(data), text, None))
                if slot.index == self.due:
                    self.cond.notify()
            return

    def _unspillable(self, error: OSError, slot: _Slot) -> None:
        """The spill failed with ``error`` (the lock held): no piece is spilled from now on. An
        item whose file holds none yet drops it, and keeps its pieces as one that never
        spilled."""
        if self.unspilled is None:
            self.unspilled = error
            if not self.spill_folder:
                self.spill_folder = error.filename or _temporary_folder()
            self.cond.notify()  # (the main thread: it may have to take an item itself)
        if slot.spill is not None and not slot.spilled:
            slot.close()
            slot.write_at = 0

    def _keep(self, slot: _Slot, piece: Any, due: bool) -> None:
        """``piece`` held in memory where it would have been spilled (the lock held; the spill
        failed) or waited with (the main thread's own item, other pieces than text): after
        the item's other pieces, in its order."""
        if slot.spill is None:
            slot.pieces.append(piece)
            if not due and not slot.early:
                self.held += 1
        else:
            slot.spilled.append((0, False, piece))
            slot.kept += 1
        if due:
            self.cond.notify()

    def take(self, index: int, here: bool = False
             ) -> tuple[list[Any], _Slot | None, _Slot | None]:
        """(the pieces of item ``index`` held in memory, or one spilled piece; its slot once it
        is done and every piece has been taken, else None; None, or with ``here``, an item
        given out to the main thread to do itself (:meth:`here`) where it would wait). Waits
        until the item is done or has :data:`BATCH` pieces or a spilled one: the main thread
        wakes once for a file's report of a few slices, not once a slice."""
        with self.cond:
            while True:
                slot = self.slots.get(index)
                if slot is not None and slot.again:  # (its turn: done again, sent at once)
                    slot.again = False
                    return [], None, slot
                if slot is not None:
                    pieces: list[Any] = []
                    if slot.pieces and (slot.done or slot.spilled
                                        or len(slot.pieces) >= BATCH):
                        # (the pieces in memory were sent before any spilled one)
                        pieces = list(slot.pieces)
                        slot.pieces.clear()
                        if len(pieces) >= PIECES:  # its thread may wait for room
                            self.space.notify_all()
                        if not slot.done or slot.spilled:
                            return pieces, None, None
                    elif slot.spilled:
                        size, text, kept = slot.spilled.popleft()
                        if kept is not None:  # (the spill failed: held in memory)
                            if slot.kept == PIECES:  # its thread may wait for room
                                self.space.notify_all()
                            slot.kept -= 1
                            return [kept], None, None
                        assert slot.spill is not None
                        data = _read(slot.spill, size, slot.read_at)
                        slot.read_at += size
                        return ([data.decode("utf-8", "surrogatepass") if text else data],
                                None, None)
                    if slot.done:
                        slot.close()
                        del self.slots[index]
                        self.due = index + 1
                        coming = self.slots.get(self.due)
                        if coming is not None and not coming.early:
                            self.held -= len(coming.pieces)  # the due item's now
                        self.space.notify_all()  # the window moved; the next item has room
                        return pieces, slot, None
                if self.failure is not None:
                    raise self.failure
                # (an item started early only once every thread has one: a long one, during
                # which nothing is handed on and the window does not move for the threads,
                # but which would otherwise wait for a thread; review 34, finding 3: at -j 2
                # the one thread ran two long files one after the other)
                if here and not self.stopped and self.given < len(self.items) and (
                        self.threads <= self.given < self.early
                        or (self.given >= self.early
                            and self.order[self.given] < self.due + self.window)) and (
                        # the spill failed: only the item whose turn it is, whose pieces go
                        # out at once, unless every thread waits for an item's turn
                        self.unspilled is None or self.order[self.given] == self.due
                        or self.blocked >= self.threads):
                    return [], None, self._give()
                self.cond.wait(self)

    def fail(self, error: BaseException) -> None:
        """A thread's error outside an item's function: the map stops (the other threads end
        at their next item or piece) and the main thread raises ``error`` when it would wait
        for an item, after the items done before it, which it still hands on in order."""
        with self.cond:
            if self.failure is None:
                self.failure = error
            self.stopped = True
            self.cond.notify_all()
            self.space.notify_all()

    def stop(self) -> None:
        with self.cond:
            self.stopped = True
            self.cond.notify_all()
            self.space.notify_all()

    def close(self) -> None:
        """The temporary files of the items not taken (the map stopped early)."""
        for slot in self.slots.values():
            slot.close()


def _run(state: _Map, ended: Any) -> None:
    """A worker thread: :meth:`_Map.work`, then ``ended`` released (its join). An error in
    an item's function is handed to the main thread by :meth:`_Map.work`; one outside it (the
    map's own work: a MemoryError, say) by :meth:`_Map.fail`, so that the main thread raises
    it rather than waiting for ever for the item this thread had taken."""
    try:
        state.work()
    except BaseException as error:
        state.fail(error)
    finally:
        ended.release()


def _temporary_folder() -> str:
    """The folder :func:`_spill_file` tries first (``$TMPDIR``, ``$TEMP``, ``$TMP``, else
    ``/tmp``)."""
    env = os.environ
    return env.get("TMPDIR") or env.get("TEMP") or env.get("TMP") or "/tmp"


def _tell(message: str) -> None:
    """A line on stderr (a warning of the map's own; a closed stderr is let be)."""
    try:
        sys.stderr.write(message + "\n")
        sys.stderr.flush()
    except (OSError, ValueError, AttributeError):
        pass


def _spill_file() -> tuple[int, str]:
    """A temporary file with no name (nothing to remove, whatever ends the process), in the
    folder ``tempfile`` would take first (``$TMPDIR``, ``$TEMP``, ``$TMP``, else ``/tmp``),
    made by ``O_TMPFILE`` where the system and that folder's file system offer it. Only where
    they do not is ``tempfile`` imported (it picks another folder if need be): its import, with
    ``shutil``, ``random``, ``bz2`` and ``lzma``, was 4.5 ms of a ``-j 2`` check of the shops
    folder, work that ``-j 1`` never does (docs/benchmarks.md, "the start-up of ``-j 2``")."""
    flag = getattr(os, "O_TMPFILE", 0)
    if flag:
        folder = _temporary_folder()
        try:
            return os.open(folder, flag | os.O_RDWR | os.O_EXCL | os.O_CLOEXEC, 0o600), folder
        except OSError:  # not offered there, or no such folder: tempfile's way
            pass
    import tempfile

    folder = tempfile.gettempdir()  # (an OSError where no folder can be written)
    try:
        with tempfile.TemporaryFile(buffering=0, dir=folder) as handle:
            return os.dup(handle.fileno()), folder
    except OSError as exc:
        if exc.filename is None:
            exc.filename = folder
        raise


def _read(fd: int, size: int, at: int) -> bytes:
    """``size`` bytes of ``fd`` from ``at`` (a short read is read on)."""
    parts = []
    while size:
        part = os.pread(fd, size, at)
        if not part:
            raise OSError(f"a spilled report piece was cut short at byte {at}")
        parts.append(part)
        size -= len(part)
        at += len(part)
    return b"".join(parts)


def ordered_map(func: Callable[[T], R], items: Sequence[T], jobs: int, *,
                receive: Callable[[Any], object] | None = None,
                sizes: Sequence[int] | None = None) -> Generator[R, None, None]:
    """``func(item)`` for every item, in ``jobs`` threads, yielded in the items' order; what
    ``func`` hands to :func:`send` is given to ``receive`` here, at its item's turn, before its
    result. When ``jobs`` is 1 or there is one item, no thread is started: the items are done
    one by one here, and :func:`send` calls ``receive`` at once. An exception ``func`` raises
    is raised here, when its item's turn comes, after the pieces it sent; the items after it
    are abandoned. ``sizes``: each item's work (its file's bytes), from which the items that
    would end the batch alone are started first (:func:`first`); only for a ``func`` that
    sends text or nothing (a thread with other pieces of an item not due waits for its turn,
    and threads all waiting so, each on an item started early, would wait for ever); with
    ``sizes`` the calling thread is one of the ``jobs`` (the module's docstring)."""
    if jobs <= 1 or len(items) <= 1:
        _local.send = receive
        for item in items:
            yield func(item)
        return
    count = min(jobs, len(items))
    state = _Map(func, items, WINDOW * jobs, WAITING * count,
                 first(sizes, jobs) if sizes is not None else ())
    # Text or nothing sent (``sizes`` given): this thread is one of the ``count`` workers,
    # doing an item wherever it would wait for the one whose turn it is, so one thread fewer
    # is started and no working thread is put off its core to hand the reports on. (Other
    # pieces may make a thread wait for room that only this thread makes: it only takes.)
    here = sizes is not None
    # each thread holds its lock until it has ended its work (its join); the threads are
    # the interpreter's own (_thread), as daemon threads: nothing waits for them at the exit
    ended = [_thread.allocate_lock() for _ in range(count - here)]
    state.threads = len(ended)
    # SIGINT's and SIGTERM's handlers before ours (_signalled), once ours are set: set before
    # the threads start, so that no signal's exception lands among the map's locks
    handlers: list[tuple[int, Any]] = []
    started: list[Any] = []
    done = False
    # by signal's C part, which the interpreter loaded at its start: the signal module's
    # import (its enums, 0.7 ms of the main thread's CPU) only turns the handler handed back
    # into an enum, and these are only put back
    import _signal

    try:
        try:
            handlers.append((_signal.SIGTERM, _signal.signal(
                _signal.SIGTERM, lambda signum, frame: _signalled(state, signum))))
            # SIGHUP (the terminal closed) where a command made it an exit anywhere
            # (formats.files.exit_on_termination): held to a safe point as SIGTERM is (review
            # 44, finding 8: 2 of 140 batches so stopped hung in the map's locks)
            hup = getattr(_signal, "SIGHUP", None)  # (none on Windows)
            files = sys.modules.get("formats.files")  # (loaded where that exit was set)
            if (hup is not None and files is not None
                    and _signal.getsignal(hup) is files._exit_signalled):
                handlers.append((hup, _signal.signal(
                    hup, lambda signum, frame: _signalled(state, signum))))
            if _signal.getsignal(_signal.SIGINT) in (_signal.default_int_handler, getattr(
                    sys.modules.get("formats.stops"), "interrupted", None)):
                # (^C's KeyboardInterrupt, the interpreter's or the one that notes it,
                # formats.stops; a SIGINT ignored, or handled by the caller, is left so)
                handlers.append((_signal.SIGINT, _signal.signal(
                    _signal.SIGINT, lambda signum, frame: _signalled(state, signum))))
        except ValueError:  # not the main thread (of the main interpreter): no handler
            pass
        for lock in ended:
            lock.acquire()
            _thread.start_new_thread(_run, (state, lock))
            started.append(lock)
        for index in range(len(items)):
            while True:
                pieces, got, own = state.take(index, here)
                if own is not None:
                    state.here(own, receive)
                    continue
                if receive is not None:
                    state.interruptible()  # (the caller's code)
                    try:
                        for piece in pieces:
                            receive(piece)
                    finally:
                        state.safe = False
                if got is not None:
                    break
            if got.error is not None:
                raise got.error
            state.interruptible()  # (the caller's code, until it asks for the next)
            try:
                yield got.result
            finally:
                state.safe = False
        done = True
    finally:
        # stopped or done: a thread sending stops at once, one in the core at its chunk's end
        state.safe = False
        state.stop()
        joined = False
        try:
            # The join is a safe point: a signal that lands here (the second ^C, SIGTERM) is
            # raised at once and the threads, stopped, daemon threads, are left to the
            # process's end. Held, it had no later point to be raised at: a thread that never
            # came back from the core (an input that never ends) made the command deaf to
            # every ^C (review 42, finding 6). (One held before the join is raised after it,
            # below, as before.)
            state.safe = True
            for lock in started:
                lock.acquire()  # the thread's join
            joined = True
        finally:
            state.safe = False
            if joined:  # (a thread left running may still write its spill file)
                state.close()
            for signum, before in reversed(handlers):
                _signal.signal(signum, before)
    if state.pending is not None and done:  # (a signal held to the end: raised now)
        raise state.pending


def file_sizes(paths: Iterable[str | OSError]) -> list[int]:
    """Each file's size in bytes (0 for one that cannot be read, or an ``OSError`` for one
    refused unread: it is reported at its turn), the work :func:`first` weighs."""
    sizes = []
    for path in paths:
        try:
            sizes.append(os.stat(path).st_size if isinstance(path, str) else 0)
        except OSError:
            sizes.append(0)
    return sizes


def input_files(names: Iterable[str]) -> list[str]:
    """The files named: a folder stands for every file below it (:func:`folder_files`);
    anything else is taken as it is named (a missing file is reported when it is read)."""
    files: list[str] = []
    for name in names:
        if name != "-" and os.path.isdir(name):
            files.extend(path for path, _ in folder_files(name))
        else:
            files.append(name)
    return files


def folder_files(name: str) -> list[tuple[str, str]]:
    """Every file below the folder ``name`` (symbolic links to files among them, and links that lead
    nowhere, reported when read; folders linked to not entered), sorted by their paths' parts,
    hidden ones (a name starting with ``.``) left out: (its path, its path below the folder). The
    paths are written as ``pathlib`` writes them (:func:`formats.files.pure`; ``Path.rglob``,
    ``relative_to``), without its objects: 17M instructions of a check's listing of 200 files, a
    tenth of what ran before the threads started, and for ``convert`` 0.1 s of 200 files' ``Path``
    work. A folder is read as ``os.walk`` reads it (one that cannot be read is left out), by
    ``os.scandir``: whether an entry is a file comes with its name, without a ``stat`` of each file
    as ``os.path.isfile`` made (docs/benchmarks.md, "the serial ends of `-j 2`")."""
    from formats.files import joined, pure

    root = pure(name)
    found: list[tuple[str, ...]] = []
    _scan(root, (), found)
    return [(joined(root, below), below) for below in map("/".join, sorted(found))]


def _scan(folder: str, below: tuple[str, ...], found: list[tuple[str, ...]]) -> None:
    """The files of ``folder`` (whose parts below the listed folder are ``below``) and of the
    folders in it, not hidden, added to ``found`` as their parts."""
    try:
        with os.scandir(folder) as entries:
            listed = list(entries)
    except OSError:
        return
    # (the tests written out, not by _is and _listed: 16K instructions a file were the
    # listing's before a batch's threads; docs/benchmarks.md, "the listing")
    for entry in listed:
        name = entry.name
        if name[:1] == ".":
            continue
        try:
            a_folder = entry.is_dir()
        except OSError:
            a_folder = False
        if a_folder:
            if not _is(entry.is_symlink):
                _scan(entry.path, (*below, name), found)
            continue
        try:
            listed_file = entry.is_file()
        except OSError:
            listed_file = False
        if listed_file or _listed(entry):
            found.append((*below, name))


def _is(test: Callable[[], bool]) -> bool:
    """A ``DirEntry``'s test, False where it fails (as ``os.walk`` takes it)."""
    try:
        return test()
    except OSError:
        return False


def _listed(entry: os.DirEntry[str]) -> bool:
    """A folder's entry to read: a file, or a symbolic link that leads nowhere, which is
    listed so that reading it reports it as not read (exit 2) rather than leaving it out
    in silence; folders, pipes and devices are not."""
    return _is(entry.is_file) or (_is(entry.is_symlink) and not os.path.exists(entry.path))

