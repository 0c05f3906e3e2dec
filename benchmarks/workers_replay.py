"""`check -j`'s schedule played from each file's CPU time: what the window of
``tapegate.workers`` costs, on a machine too loaded for a wall time to mean anything.

    .venv/bin/python benchmarks/workers_replay.py FOLDER [-p PROFILE] [--runs 3]
                                                  [--windows 8,16,32] [--jobs 2]
                                                  [--handover 0.25]

Each file of FOLDER is checked once per run in this process (``tapegate.checking._check_one``,
``--format json``, the report written to ``/dev/null``), and its CPU time taken
(``time.thread_time``: another process's load lengthens a wall time, much less a thread's CPU
time); the median of the runs is the file's work. Then ``tapegate.workers.ordered_map``'s
rules are played with those times, event by event, for each window: the files given out in
``order`` (``workers.first``'s early ones, then the rest), a thread taking the next one while
it is within the window of the one whose turn it is (``_Map._open``), the main thread one of
the workers (``sizes`` given): at each step it hands on the item whose turn it is if it is
done (``--handover`` ms a MB of its report, for one a thread checked: its pieces written, and
read back where spilled), else takes the next item itself where the window allows
(``_Map.take``'s ``here``), else waits. Printed: the batch's work (the makespan from the first
file to the last item handed on), the work's spread (the files' CPU over it) and the time the
threads waited for the window. Nothing here models the two cores slowing each other or the
GIL's turns: the figures are the schedule's own loss.
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))


def measure(folder: str, profile: str, runs: int) -> tuple[list[str], list[float], list[float]]:
    """(the files, each one's CPU ms, each one's report MB), the files as ``check`` lists them."""
    from tapegate import checking
    from tapegate.checking import _check_one, _profile
    from tapegate.workers import folder_files

    files = [path for path, _ in folder_files(folder)]
    prof = _profile(profile, None, quick=True)
    times: list[list[float]] = [[] for _ in files]
    sizes = [0] * len(files)
    with open(os.devnull, "wb") as sink:
        for _ in range(runs):
            for n, path in enumerate(files):
                written = [0]

                def send(piece: object, written: list[int] = written) -> None:
                    data = piece if isinstance(piece, bytes) else str(piece).encode()
                    written[0] += len(data)
                    sink.write(data)

                start = time.thread_time()
                _check_one((path, path), prof, "json", [], [], send, False, True, False)
                times[n].append((time.thread_time() - start) * 1000)
                sizes[n] = written[0]
    del checking
    return files, [statistics.median(t) for t in times], [s / 1e6 for s in sizes]


def play(cost: list[float], report: list[float], order: list[int], early: int, jobs: int,
         window: int, handover: float) -> tuple[float, float]:
    """(the makespan, the threads' time waiting for the window) of one schedule, in ms."""
    n, threads = len(cost), jobs - 1
    given = due = 0
    done: dict[int, bool] = {}  # item -> checked by a thread (its pieces handed on by main)
    now = 0.0
    busy: list[tuple[int, float] | None] = [None] * threads  # (item, end)
    since: list[float | None] = [None] * threads
    waited = 0.0
    main: tuple[str, int, float] | None = None  # (what, item, end)

    def opened() -> bool:
        return given < early or order[given] < due + window

    while True:
        changed = True
        while changed:
            changed = False
            for k in range(threads):
                if busy[k] is None and given < n and opened():
                    item = order[given]
                    given += 1
                    busy[k] = (item, now + cost[item])
                    if since[k] is not None:
                        waited += now - since[k]  # type: ignore[operator]
                        since[k] = None
                    changed = True
                elif busy[k] is None and given < n and since[k] is None:
                    since[k] = now
            if main is None and due < n:
                if due in done:
                    main = ("hand", due, now + (handover * report[due] if done[due] else 0.0))
                    due += 1
                    changed = True
                elif given < n and (threads <= given < early
                                    or (given >= early and order[given] < due + window)):
                    item = order[given]
                    given += 1
                    main = ("own", item, now + cost[item])
                    changed = True
        if due >= n and main is None:
            return now, waited
        ends = [b[1] for b in busy if b is not None] + ([main[2]] if main else [])
        now = min(ends)
        for k in range(threads):
            b = busy[k]
            if b is not None and b[1] <= now:
                done[b[0]] = True
                busy[k] = None
        if main is not None and main[2] <= now:
            if main[0] == "own":
                done[main[1]] = False
            main = None


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder")
    parser.add_argument("-p", "--profile", default="fanuc-mill")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--windows", default="8,16,32", help="items a thread, comma-separated")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--handover", type=float, default=0.25,
                        help="the main thread's ms a MB of a thread's report (write, read back)")
    args = parser.parse_args()
    from tapegate.workers import first

    files, cost, report = measure(args.folder, args.profile, args.runs)
    sizes = [os.path.getsize(f) for f in files]
    early = first(sizes, args.jobs)
    order = [*early, *(i for i in range(len(files)) if i not in set(early))]
    total = sum(cost)
    print(f"{len(files)} files, {total:.1f} ms of CPU (largest {max(cost):.1f}), "
          f"{sum(report):.1f} MB of reports; {args.jobs} workers, perfect: {total / args.jobs:.1f}")
    print(f"{'window':>6} {'work ms':>8} {'spread':>6} {'window waits ms':>15}")
    for window in (int(w) for w in args.windows.split(",")):
        span, waited = play(cost, report, order, len(early), args.jobs, window * args.jobs,
                            args.handover)
        print(f"{window:>6} {span:>8.1f} {total / span:>6.2f} {waited:>15.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
