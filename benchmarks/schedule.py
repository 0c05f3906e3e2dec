"""What the order the files are given out in costs ``check -j N``, in instructions.

    .venv/bin/python benchmarks/schedule.py FOLDER [-p fanuc-mill] [--jobs 2]
                                            [--tapegate "python -P -m tapegate"]

Runs ``tapegate check FOLDER -p P --format json -j 1`` once under callgrind, dumping the counts
each time a file's checker is made (``--dump-before=*Checker::__pymethod___new____``): the
instructions before the first file (the start-up, serial) and each file's own (its check and
report, up to the next file's checker). Then N threads are laid out as list scheduling does it
(a thread that is free takes the next file of the order): the batch ends when the last file
ends, and the **ideal speed-up** on N idle cores is the ``-j 1`` count over the start-up plus
that span. Three orders: the input's, :func:`tapegate.workers.first`'s (its files first, the
rest in order: what ``-j`` does), and all the files by their counts, largest first (the
classic LPT bound, which would hold every report until its turn). The window of items a thread
may run ahead (``WINDOW``) is not modelled. Needs valgrind.
"""

from __future__ import annotations

import argparse
import heapq
import re
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from tapegate.workers import file_sizes, first, input_files  # noqa: E402


def per_file(argv: list[str], out: Path) -> tuple[int, list[int]]:
    """(instructions before the first file, each file's) of ``argv`` under callgrind."""
    subprocess.run(["valgrind", "--tool=callgrind", "--dump-before=*Checker::__pymethod___new____",
                    f"--callgrind-out-file={out}/cg.%p", *argv], stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, check=False)
    parts: dict[int, int] = {}
    for path in out.iterdir():
        name = re.fullmatch(r"cg\.\d+(?:\.(\d+))?", path.name)
        found = re.search(r"^(?:summary|totals): (\d+)", path.read_text(errors="replace"),
                          re.MULTILINE)
        if name and found:  # part n: up to the n-th dump; no part: the rest
            parts[int(name[1]) if name[1] else sys.maxsize] = int(found[1])
    counts = [parts[k] for k in sorted(parts)]
    return counts[0], counts[1:]


def span(order: list[int], cost: list[int], jobs: int) -> int:
    """When the last file ends, ``jobs`` threads each taking the next file of ``order``."""
    free = [0] * jobs
    end = 0
    for index in order:
        start = heapq.heappop(free)
        end = max(end, start + cost[index])
        heapq.heappush(free, start + cost[index])
    return end


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder")
    parser.add_argument("-p", "--profile", default="fanuc-mill")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--tapegate", default=f"{sys.executable} -P -m tapegate")
    args = parser.parse_args()
    files = input_files([args.folder])
    with tempfile.TemporaryDirectory(prefix="tapegate-schedule-") as tmp:
        start, cost = per_file([*shlex.split(args.tapegate), "check", args.folder, "-p",
                                args.profile, "--format", "json", "-j", "1"], Path(tmp))
    if len(cost) != len(files):
        print(f"schedule: {len(cost)} checkers made for {len(files)} files", file=sys.stderr)
        return 1
    whole = start + sum(cost)
    largest = max(range(len(files)), key=lambda i: cost[i])
    print(f"-j 1: {whole / 1e9:.3f}G; before the first file {start / 1e9:.3f}G; the largest, "
          f"{Path(files[largest]).name}, {cost[largest] / 1e9:.3f}G, file {largest + 1} of "
          f"{len(files)}")
    early = first(file_sizes(files), args.jobs)
    orders = {
        "the input's order": list(range(len(files))),
        "first() first": [*early, *(i for i in range(len(files)) if i not in set(early))],
        "largest first (LPT)": sorted(range(len(files)), key=lambda i: -cost[i]),
    }
    for name, order in orders.items():
        end = span(order, cost, args.jobs)
        print(f"{name:22} the files end at {end / 1e9:.3f}G; ideal on {args.jobs}: "
              f"{whole / (start + end):.2f}")
    print("first() starts first:", ", ".join(Path(files[i]).name for i in early) or "none")
    return 0


if __name__ == "__main__":
    sys.exit(main())
