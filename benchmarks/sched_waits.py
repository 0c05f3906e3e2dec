"""Where each thread of a `tapegate` command was off its core, from the scheduler's record.

    perf record -e sched:sched_switch --call-graph dwarf,8192 -o DATA -- tapegate ...
    perf script -i DATA -F tid,time,trace,ip,sym > SCRIPT
    python benchmarks/sched_waits.py SCRIPT

Each switch of a thread named ``tapegate*`` off its core is paired with its next switch back
on, and the time between counted by why it left, read from its state and its stack there:

- **R preempted**: runnable, put off its core (another process, a thread woken on that core,
  a kworker): the load's, or a commit thread's wake-up; on a shared machine most of it;
- **S GIL**: waiting for the GIL (``take_gil``);
- **S map lock/cond**: one of ``tapegate.workers``' or Python's locks (a condition's wait:
  the window, the item whose turn it is);
- **S Commits.wait**, **S Commits.submit**: the core's commit pool (``crates/python/src/
  commits.rs``), the main thread waiting for an output's commit, or for the pool's lock;
- **S malloc/mutex**: a Rust mutex or the C library's (a free into another thread's arena);
- **D ...**: uninterruptible, in the kernel (the disk, a folder's lock): the kernel functions
  under the wait, named;
- **S idle thread**: a commit thread with nothing to do.

The main thread is the one with the lowest thread id. Printed: each thread's total and its
classes, the largest first (ms / switches).
"""

from __future__ import annotations

import collections
import re
import sys

HEAD = re.compile(r"\s*(\d+)\s+([\d.]+): prev_comm=(.*?) prev_pid=(\d+) .*prev_state=(\S+) "
                  r"==> next_comm=(.*?) next_pid=(\d+)")
# the kernel's own frames of a sleep, not its cause
PLUMBING = ("__schedule", "schedule", "io_schedule", "bit_wait", "__wait_on", "out_of_line_wait",
            "__folio_lock", "folio_wait", "wait_on_page", "rwsem_down", "down_", "__down",
            "__x64", "do_syscall", "entry_SYSCALL", "jbd2_log_wait", "ext4_sync_file")


def switches(path: str) -> list[dict[str, object]]:
    """Each switch: its time, the thread leaving (id, name, state, stack) and the one coming."""
    found: list[dict[str, object]] = []
    current: list[str] | None = None
    with open(path, encoding="utf-8", errors="replace") as lines:
        for line in lines:
            head = HEAD.match(line)
            if head:
                current = []
                found.append({"t": float(head[2]), "name": head[3], "out": int(head[4]),
                              "state": head[5], "in": int(head[7]), "stack": current})
            elif current is not None and line.strip():
                parts = line.split(None, 1)
                if len(parts) == 2:
                    current.append(parts[1].strip().replace(" (inlined)", ""))
    return found


def why(state: str, stack: list[str]) -> str:
    whole = " ".join(stack)
    if state.startswith("R"):
        return "R preempted"
    if "take_gil" in whole:
        return "S GIL"
    if "Commits::__pymethod_wait" in whole:
        return "S Commits.wait"
    if "pymethod_submit" in whole:
        return f"{state[0]} Commits.submit"
    if "PyThread_acquire_lock" in whole:
        return "S map lock/cond"
    if state[0] == "D":
        if "fsync" in whole:
            return "D fsync"
        cause = [f for f in stack if not f.startswith(PLUMBING)]
        return "D " + " < ".join(cause[:3])
    if "lock_contended" in whole or "lll_lock_wait" in whole:
        return "S malloc/mutex"
    if "start_thread" in whole and "PyEval" not in whole and "pymethod" not in whole:
        return "S idle thread"
    return f"{state[0]} other"


def main() -> int:
    if len(sys.argv) != 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if sys.argv[1:] in (["-h"], ["--help"]) else 2
    try:
        found = switches(sys.argv[1])
    except OSError as exc:
        print(f"{sys.argv[1]}: {exc.strerror}", file=sys.stderr)
        return 2
    names: dict[int, str] = {}
    for switch in found:
        names.setdefault(switch["out"], switch["name"])  # type: ignore[arg-type]
    ours = {tid for tid, name in names.items() if name.startswith("tapegate")}
    if not ours:
        print("no tapegate thread in the record")
        return 1
    left: dict[int, tuple[float, str, list[str]]] = {}
    off: dict[tuple[int, str], list[float]] = collections.defaultdict(lambda: [0, 0.0])
    for switch in found:
        back = switch["in"]
        if back in left:
            since, state, stack = left.pop(back)  # type: ignore[arg-type]
            total = off[(back, why(state, stack))]  # type: ignore[arg-type]
            total[0] += 1
            total[1] += (switch["t"] - since) * 1000  # type: ignore[operator]
        if switch["out"] in ours:
            left[switch["out"]] = (switch["t"], switch["state"], switch["stack"])  # type: ignore
    main_thread = min(ours)
    for tid in sorted(ours):
        rows = sorted(((c, v) for (t, c), v in off.items() if t == tid), key=lambda r: -r[1][1])
        label = "main" if tid == main_thread else names[tid]
        print(f"{label}[{tid}] off {sum(v[1] for _, v in rows):.1f} ms: "
              + ", ".join(f"{c} {v[1]:.1f}/{v[0]:.0f}x" for c, v in rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
