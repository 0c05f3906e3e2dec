"""`check -j` and `convert -j`: a batch of real files with 1 and 2 (or more) workers.

    .venv/bin/python benchmarks/workers.py [--jobs 1,2] [--copies 200] [--repeat 3]
                                           [--tapegate PATH] [--only TEXT,...]
                                           [--callgrind | --phases] [--large NAME]
                                           [--real DIR [--real-count 200]
                                            [--real-profile NAME | --families TSV]]
                                           [--build LABEL=CHECKOUT ...] [--fifo]

Three batches, each command in its own process under ``/usr/bin/time -v`` (wall seconds of the
whole command by ``time.perf_counter``; its CPU, context switches and the peak resident set of
the largest process, the main one or a worker, by ``time``; see :func:`timed`):

- **shops**: every file of ``../shared/corpus/shops`` (``check -p fanuc-mill --format json``;
  the programs of other families give reading findings, which are work too);
- **copies**: 200 copies of ``Praktikum-CAD-CAM-Modul-12__1001.nc`` (3,157 blocks) in a
  temporary folder: ``check -p haas-mill --format json`` and ``convert --from haas-mill`` to
  implicit inch (``benchmarks/core.py``'s target) into another folder;
- **large copies**: 200 copies of a long real program (``--large``, by default
  ``shops/Mheaton92__PMC__1001.nc``: a Fusion 360 adaptive clearing, 22,167 lines, 590 kB),
  ``check -p haas-mill --format json``: the same start-up against 7 times the work;
- **real files** (``--real DIR``, only when named): the first ``--real-count`` (200) files
  below a folder of real programs the user names (hidden ones left out, sorted by their paths
  below it, as ``tapegate check DIR`` lists them), copied into a temporary folder, checked
  (``check --format json``) and converted (to implicit inch, as the copies) on
  ``--real-profile`` (``fanuc-mill``) or, with ``--families TSV`` (a map written as the
  shops' ``families.tsv``: family, file name, description a line), each on its family's
  profile (``benchmarks/shops.py``'s ``profile_for``: the lathe one where the description
  says turning), the files of no known family on ``--real-profile``. Files of several
  profiles are one command a profile, one after the other, each on its own folder: the
  batch's wall time, CPU and switches are their sum (and each command's start-up counts),
  its peak and exit code the largest. Copies of one program are one file's cost 200 times
  over (its length, its words and their kept verdicts, its report); 200 distinct programs
  differ in length (a long one late in the order may end the batch alone, as in the shops
  folder), in what a block costs and in what they report -- the issue's measure says "200
  real files".

Beside them, **the machine's ceiling**: N processes that only compute (a Python loop of fixed
length, as long as a short batch), started at once, the same ``-j`` column: what the machine
gives N independent processes at that moment, without start-up, files or copies. On a machine
shared with other work this is far below N, and a batch's speed-up is to be read against it.

Each measure is repeated (``--repeat``), the worker counts' runs interleaved (1, 2, 1, 2...) so
that a change of the machine's load falls on each alike; the median and the fastest are
printed, and the speed-up is 1 worker's median over N workers' (the ceiling's: N times 1
process's median over N processes'). CPU s is the CPU time of the
command and its workers (user + system), their median: equal
figures for 1 and N workers mean the workers cost no more work than one process; switches,
the median of the command's context switches (voluntary and not: a thread waiting for another,
or put off its core). The load
average of the machine (``os.getloadavg``, 1 minute) is printed beside each measure: on a
machine shared with other work the wall times stretch with it. The commands run as a user
runs them: ``PYTHONDONTWRITEBYTECODE`` and ``PYTHONUNBUFFERED`` are taken out of their
environment (``.pyc`` files read, stdout buffered).

``--callgrind`` counts instructions instead (``valgrind --tool=callgrind --separate-threads``,
which no load changes; each command once): for ``-j 1`` the whole command; for N workers the
main thread before the work is spread (up to the first thread it starts,
``--dump-before=PyThread_start_new_thread``; for a build that forks worker processes, up to
the fork: a forked child's counters start with its parent's, so each is dumped at the fork,
``--dump-before=PyOS_AfterFork_Child``, and counted from there), the main thread after it,
and each worker's own (a thread; or a process, and then the pool's helper threads of the main
process too; a conversion's commit threads, which fsync and rename the outputs, are listed
among them, last, and with ``-j 1`` its main thread's count up to the first of them is the
"before"). The **ideal speed-up** is the ``-j 1`` count over what N idle cores would run
one after the other: the main thread up to the spreading, then everything after it shared
evenly, ``I(before) + (I(after) + I(workers)) / N``.

``--build LABEL=CHECKOUT`` (repeated) measures several checkouts, each with its built
extension, put first on ``PYTHONPATH`` for the same ``--tapegate`` command (a console script
of the environment, which imports the checkout first): their runs interleaved with the worker
counts' (build A -j 1, -j 2, build B -j 1, -j 2, A again...), so that the machine's load falls
on each alike, each build's speed-up against its own 1 worker.

``--phases`` splits each command's wall time instead (``--repeat`` runs, the median of each
part): the command is run by a driver (:data:`PHASES`) that imports the command's entry
point as its console script does and records, on the clock the benchmark shares with it
(``time.perf_counter``, CLOCK_MONOTONIC), when the first file's work began and the last one's
ended, and each worker's time in its files. **serial** is what no worker shares: from the
process's start to the first file (the interpreter, the imports, the profile, the folder
listed) and from the last file's end to the exit; **work** is the rest. With the serial part S
and the work W1 of one worker and W2 of N, the speed-up is (S + W1) / (S + W2), and the
serial part a speed-up of 1.8 would allow is (W1 - 1.8 W2) / 0.8 (printed as "S for 1.8"):
the arithmetic of a target the start-up bounds, in wall time on this machine. **CPU ms** is the
CPU time of all the workers in their files (each thread's ``time.thread_time``), **wait ms**
their busy time not on a CPU (the busy times' sum less the CPU's): a worker waiting for the
GIL, or for a core. Against ``-j 1``, more CPU for the same files is the two cores slowing each
other (their shared caches, the host); more waiting is the GIL's turns (on an idle machine,
where no other process takes a core).

``--fifo`` runs each command timed (and the ceiling's loops) under ``chrt -f 10``, the
real-time FIFO class: on a machine other users load, the command's threads then take a core
whenever they can run, as on an idle machine, so a check's spread can be read there (each
command ends within a second; the kernel keeps 5 % of each second for other tasks). Not for a
conversion's figures: its outputs' fsyncs wait for the kernel's I/O threads, which stay in
the normal class and so behind the other users' load (docs/benchmarks.md, par82).

Needs ``../shared/corpus`` (or ``$TAPEGATE_CORPUS``).
"""

from __future__ import annotations

import argparse
import os
import re
import shlex
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from core import IMPLICIT_INCH, ROOT  # noqa: E402
from real_program import SOURCE, corpus_dir  # noqa: E402

# what --fifo puts before each command timed: the real-time FIFO class (chrt(1))
PREFIX: list[str] = []


def timed(argv: list[str], env: dict[str, str]) -> tuple[float, float, int, float, int]:
    """(wall seconds, peak MB, exit code, CPU seconds: user + system, context switches) of a
    command under ``/usr/bin/time -v``, its output thrown away. The wall time is
    ``time.perf_counter`` around the process, not ``time``'s own wall clock, which it reads to
    10 ms: a step of 0.1-0.2 in the speed-up of a 0.1 s batch. (``time`` stays for the peak
    resident set: a process started from this one, by fork or ``posix_spawn``, counts this
    one's pages before its ``exec`` in its ``ru_maxrss``.) ``time``'s own start, about 1 ms,
    is in every run alike."""
    start = time.perf_counter()
    proc = subprocess.run([*PREFIX, "/usr/bin/time", "-v", *argv], stdout=subprocess.DEVNULL,
                          stderr=subprocess.PIPE, text=True, stdin=subprocess.DEVNULL,
                          check=False, cwd=ROOT, env=env)
    wall = time.perf_counter() - start
    said = proc.stderr

    def number(label: str) -> float:
        found = re.search(rf"{label}: ([\d.]+)", said)
        return float(found[1]) if found else 0.0

    cpu = number(r"User time \(seconds\)") + number(r"System time \(seconds\)")
    switches = number("Voluntary context switches") + number("Involuntary context switches")
    return (wall, number(r"Maximum resident set size \(kbytes\)") / 1024, proc.returncode,
            cpu, int(switches))


def user_env() -> dict[str, str]:
    """This environment without what a test harness sets and a user does not."""
    return {k: v for k, v in os.environ.items()
            if k not in ("PYTHONDONTWRITEBYTECODE", "PYTHONUNBUFFERED")}


# N processes that only compute, started at once (N: the last argument)
SPIN = ("import subprocess, sys\n"
        "loop = 's = 0\\nfor i in range(6_000_000): s += i'\n"
        "jobs = [subprocess.Popen([sys.executable, '-c', loop])\n"
        "        for _ in range(int(sys.argv[-1]))]\n"
        "sys.exit(max(job.wait() for job in jobs))\n")


def build_env(checkout: str | None) -> dict[str, str]:
    """:func:`user_env`, with ``checkout`` first on ``PYTHONPATH`` (None: as it is)."""
    env = user_env()
    if checkout is not None:
        env["PYTHONPATH"] = checkout
    return env


def instructions(argv: list[str], work: Path,
                 env: dict[str, str] | None = None) -> tuple[int, int, int, list[int]]:
    """(instructions of the main thread of the main process, of it before the work is
    spread, after it, each worker's own: a worker thread's, or a forked process's) of one
    command under callgrind (see the module's docstring)."""
    out = work / "callgrind"
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir()
    subprocess.run(["valgrind", "--tool=callgrind", "--trace-children=yes",
                    "--separate-threads=yes", "--dump-before=PyOS_AfterFork_Child",
                    "--dump-before=PyThread_start_new_thread",
                    f"--callgrind-out-file={out}/cg.%p", *argv], stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, env=env or user_env(), check=False, cwd=ROOT)
    # cg.PID[.PART]-THREAD: PART n is a process's counts up to its n-th dump (a fork, for a
    # child its parent's counts at that moment; or a thread started), no PART the rest of it.
    counts: dict[int, dict[tuple[int, int], int]] = {}
    for path in out.iterdir():
        name = re.fullmatch(r"cg\.(\d+)(?:\.(\d+))?-(\d+)", path.name)
        found = re.search(r"^(?:summary|totals): (\d+)", path.read_text(errors="replace"),
                          re.MULTILINE)
        if name and found:
            pid, part, thread = int(name[1]), int(name[2] or 0), int(name[3])
            counts.setdefault(pid, {})[part, thread] = int(found[1])
    main_pid = min(counts)  # (forked later: a larger process ID)
    main = counts.pop(main_pid)
    whole = sum(n for (_, thread), n in main.items() if thread == 1)
    children = [sum(n for (part, _), n in own.items() if part != 1) for _, own in
                sorted(counts.items())]
    threads = [sum(n for (_, t), n in main.items() if t == thread)
               for thread in sorted({t for _, t in main} - {1})]
    # before: a child's counts at its fork (the least, the first fork), else the main thread's
    # up to the first thread it started
    before = min((own[1, 1] for own in counts.values() if (1, 1) in own),
                 default=main.get((1, 1), whole))
    return whole, before, whole - before, children + threads


# The driver of --phases: the command's entry point (tapegate.launch.main, the console script's)
# with each file's work timed. A file's work is tapegate.checking._check_one (a check's) or
# tapegate.converting._convert_one (a conversion's), whichever the command runs, with any number
# of workers and files (ordered_map's function calls it; one file, or one worker, calls it
# directly: a batch of several profiles has commands of one file). PYTHONPATH (--build's checkout)
# is put before the current folder, which "-c" puts first, as the console script's import has it.
# The times go to the file named by TAPEGATE_PHASES as "first last exit busy-of-each-thread..."
# and a second line of each thread's CPU time in its files (time.thread_time) at the exit
# (os._exit held until they are written).
PHASES = """\
import os, sys, time, _thread
sys.path[0:0] = [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]
if "convert" in sys.argv:
    import tapegate.converting as command
    name = "_convert_one"
else:
    import tapegate.checking as command
    name = "_check_one"
spans = []
def timing(func):
    def timed(*args, **kwargs):
        start, cpu = time.perf_counter(), time.thread_time()
        try:
            return func(*args, **kwargs)
        finally:
            spans.append((_thread.get_ident(), start, time.perf_counter(),
                          time.thread_time() - cpu))
    return timed
setattr(command, name, timing(getattr(command, name)))
exit_now = os._exit
def written(code=0):
    end = time.perf_counter()
    busy, cpu = {}, {}
    for thread, start, stop, used in spans:
        busy[thread] = busy.get(thread, 0.0) + stop - start
        cpu[thread] = cpu.get(thread, 0.0) + used
    with open(os.environ["TAPEGATE_PHASES"], "w") as out:  # (no file done: no work)
        out.write(" ".join(map(repr, [min((s[1] for s in spans), default=end),
                                      max((s[2] for s in spans), default=end),
                                      end, *busy.values()])))
        out.write("\\n" + " ".join(map(repr, cpu.values())))
    exit_now(code)
os._exit = written
sys.argv[0] = "tapegate"
from tapegate.launch import main
try:
    code = main()
except SystemExit as stop:
    code = stop.code if isinstance(stop.code, int) else 1
written(code or 0)
"""


def phases(argv: list[str], env: dict[str, str], work: Path) -> tuple[float, ...]:
    """(seconds from the start to the first file's work, the work, from the last file's end
    to the driver's exit and the process's end, the CPU seconds of every worker in its files,
    each worker's busy seconds...) of one command (``argv`` without the ``tapegate`` command:
    its arguments) run by :data:`PHASES`."""
    out = work / "phases"
    env = {**env, "TAPEGATE_PHASES": str(out)}
    start = time.perf_counter()
    subprocess.run([*PREFIX, sys.executable, "-c", PHASES, *argv], stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, stdin=subprocess.DEVNULL, check=False,
                   cwd=ROOT, env=env)
    end = time.perf_counter()
    times, cpu = out.read_text().split("\n")
    first, last, exited, *busy = (float(v) for v in times.split())
    return (first - start, last - first, end - last, sum(float(v) for v in cpu.split()), *busy)


def summed(runs: list[tuple[float | int, ...]]) -> tuple[float | int, ...]:
    """The measures of several commands run one after the other (a batch of several
    profiles) as one: each figure summed, a list of each worker's figures summed worker by
    worker (a command with fewer workers counting 0 for the others)."""
    width = max(len(r) for r in runs)
    return tuple(sum(r[k] for r in runs if len(r) > k) for k in range(width))


def real_files(folder: Path, count: int, leave: Path | None = None) -> list[Path]:
    """The first ``count`` files below ``folder`` (hidden ones and ``leave`` left out, folders
    linked to not entered), sorted by their paths below it as ``tapegate check DIR`` lists
    them (``tapegate.workers.folder_files``)."""
    left = leave.resolve() if leave is not None else None
    found: list[tuple[str, Path]] = []
    for top, folders, names in os.walk(folder):  # (a folder linked to is not entered)
        folders[:] = [name for name in folders if not name.startswith(".")]
        for name in names:
            path = Path(top, name)
            if name.startswith(".") or not path.is_file() or path.resolve() == left:
                continue
            found.append(("/".join(path.relative_to(folder).parts), path))
    return [path for _, path in sorted(found)[:count]]


def real_groups(files: list[Path], folder: Path, profile: str,
                families: Path | None) -> dict[str, list[Path]]:
    """``files`` by the profile each is checked on: ``profile``, or with ``families`` (a map
    written as the shops' families.tsv) its family's (``shops.profile_for``, the corrections
    of ``shops.map_entries``), ``profile`` for a file of no known family."""
    known: dict[str, str] = {}
    if families is not None:
        from shops import map_entries, profile_for

        for name, family, description in map_entries(families):
            found = profile_for(family, description)
            if found is not None:
                known[name] = found
    groups: dict[str, list[Path]] = {}
    for path in files:
        below = "/".join(path.relative_to(folder).parts)
        groups.setdefault(known.get(below, known.get(path.name, profile)), []).append(path)
    return groups


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--jobs", default="1,2", help="comma-separated worker counts")
    parser.add_argument("--copies", type=int, default=200)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--tapegate", default=str(ROOT / ".venv" / "bin" / "tapegate"),
                        help="the command measured, split as a shell would "
                             "(\"python -m tapegate\" with PYTHONPATH set works)")
    parser.add_argument("--only", default="",
                        help="the batches whose name holds one of these texts (comma-separated; "
                             "the short batches: --only shops,'200 copies',ceiling)")
    parser.add_argument("--large", default="shops/Mheaton92__PMC__1001.nc",
                        help="the long program of the third batch, in the corpus")
    parser.add_argument("--callgrind", action="store_true",
                        help="count instructions (valgrind) instead of timing")
    parser.add_argument("--phases", action="store_true",
                        help="split each command's wall time into its serial part and its "
                             "files' work (a driver of the entry point)")
    parser.add_argument("--real", metavar="DIR",
                        help="a folder of real programs: its first --real-count files checked "
                             "and converted (the 'real files' batches)")
    parser.add_argument("--real-count", type=int, default=200)
    parser.add_argument("--real-profile", default="fanuc-mill",
                        help="the profile of the real files (of those of no known family, "
                             "with --families)")
    parser.add_argument("--families", metavar="TSV",
                        help="the real files' families, written as shops/families.tsv: each "
                             "file checked and converted from its family's profile")
    parser.add_argument("--build", action="append", default=[], metavar="LABEL=CHECKOUT",
                        help="a checkout put first on PYTHONPATH (repeated: interleaved)")
    parser.add_argument("--fifo", action="store_true",
                        help="time each command in the real-time FIFO class (chrt -f 10): a "
                             "check's spread on a machine others load (not a conversion's)")
    args = parser.parse_args()
    if args.fifo:
        PREFIX[:] = ["chrt", "-f", "10"]
    only = args.only.split(",")
    builds: list[tuple[str, str | None]] = [
        (b.split("=", 1)[0], str(Path(b.split("=", 1)[1]).resolve())) for b in args.build
    ] or [("", None)]

    def chosen(name: str) -> bool:
        return any(text in name for text in only)

    corpus = corpus_dir()
    if not (corpus / "shops").is_dir():
        print(f"corpus not found: {corpus} (set TAPEGATE_CORPUS)", file=sys.stderr)
        return 2
    work = Path(tempfile.mkdtemp(prefix="tapegate-workers-"))
    try:
        copies = work / "copies"
        copies.mkdir()
        for n in range(args.copies):
            shutil.copy(corpus / SOURCE, copies / f"p{n:03d}.nc")
        large = work / "large"
        if chosen(f"check {args.copies} large copies"):  # (the copies take 118 MB)
            large.mkdir()
            for n in range(args.copies):
                shutil.copy(corpus / args.large, large / f"p{n:03d}.nc")
        target = work / "implicit-inch.toml"
        target.write_text(IMPLICIT_INCH)
        shops = [p for p in (corpus / "shops").iterdir() if p.is_file()]
        tg = shlex.split(args.tapegate)
        # each batch: its commands, run one after the other (several for real files of
        # several profiles)
        batches: dict[str, list[list[str]]] = {
            f"check shops ({len(shops)} files)":
                [[*tg, "check", str(corpus / "shops"), "-p", "fanuc-mill", "--format", "json"]],
            f"check {args.copies} copies": [[*tg, "check", str(copies), "-p", "haas-mill",
                                             "--format", "json"]],
            f"convert {args.copies} copies": [[*tg, "convert", str(copies), "--out-dir",
                                               str(work / "out"), "--force", "--from",
                                               "haas-mill", "--to", str(target), "--units",
                                               "inch"]],
            f"check {args.copies} large copies": [[*tg, "check", str(large), "-p", "haas-mill",
                                                   "--format", "json"]],
        }
        if args.real:
            folder = Path(args.real)
            families = Path(args.families) if args.families else None
            picked = real_files(folder, args.real_count, families)
            groups = real_groups(picked, folder, args.real_profile, families)
            checks, converts = [], []
            for n, (profile, paths) in enumerate(sorted(groups.items())):
                group = work / "real" / f"{n}-{profile}"
                group.mkdir(parents=True)
                for path in paths:  # (flat: a name of a file below a subfolder joined by __)
                    shutil.copy(path, group / "__".join(path.relative_to(folder).parts))
                checks.append([*tg, "check", str(group), "-p", profile, "--format", "json"])
                converts.append([*tg, "convert", str(group), "--out-dir",
                                 str(work / "out-real" / group.name), "--force", "--from",
                                 profile, "--to", str(target), "--units", "inch"])
            shown_groups = ", ".join(f"{p} {len(g)}" for p, g in sorted(groups.items()))
            print(f"real files: {len(picked)} of {folder} ({shown_groups})", flush=True)
            batches[f"check {len(picked)} real files"] = checks
            batches[f"convert {len(picked)} real files"] = converts
        batches["the machine's ceiling"] = [[sys.executable, "-c", SPIN]]
        jobs = [int(j) for j in args.jobs.split(",")]
        width = max(len(label) for label, _ in builds)
        if args.phases:
            print(f"{'batch':<34} {'':{width}} {'-j':>3} {'to 1st ms':>9} {'work ms':>8} "
                  f"{'end ms':>7} {'serial':>7} {'busy %':>11} {'CPU ms':>7} {'wait ms':>7} "
                  f"{'work x':>6} "
                  f"{'S for 1.8':>9} {'load':>9}")
        elif args.callgrind:
            print(f"{'batch':<34} {'':{width}} {'-j':>3} {'main G':>7} {'before':>7} "
                  f"{'after':>7} {'workers G':>18} {'ideal':>6}")
        else:
            print(f"{'batch':<34} {'':{width}} {'-j':>3} {'median s':>8} {'min s':>6} "
                  f"{'CPU s':>6} {'switches':>8} {'peak MB':>8} {'speed-up':>8} {'load':>9} rc")
        for name, commands in batches.items():
            if not chosen(name):
                continue
            if args.phases:
                if "ceiling" in name:
                    continue
                load = os.getloadavg()[0]
                for label, checkout in builds:
                    parts: dict[int, list[tuple[float, ...]]] = {j: [] for j in jobs}
                    for _ in range(args.repeat):  # interleaved: 1, 2, 1, 2...
                        for j in jobs:
                            parts[j].append(summed([
                                phases([*argv[len(tg):], "-j", str(j)],
                                       build_env(checkout), work) for argv in commands]))
                    load_after = os.getloadavg()[0]
                    one = statistics.median(p[1] for p in parts[jobs[0]])
                    for j in jobs:
                        own = parts[j]
                        to_first, span, to_end = (statistics.median(p[k] for p in own)
                                                  for k in range(3))
                        busy = [statistics.median(p[4 + k] / p[1] for p in own
                                                  if len(p) > 4 + k)
                                for k in range(max(len(p) for p in own) - 4)]
                        # the workers' time in their files off the CPU: waiting for the GIL,
                        # or put off a core
                        waiting = statistics.median(sum(p[4:]) - p[3] for p in own)
                        shown = "/".join(f"{100 * b:.0f}" for b in busy)
                        needed = (one - 1.8 * span) / 0.8
                        print(f"{name:<34} {label:{width}} {j:>3} {1000 * to_first:>9.1f} "
                              f"{1000 * span:>8.1f} {1000 * to_end:>7.1f} "
                              f"{1000 * (to_first + to_end):>7.1f} {shown:>11} "
                              f"{1000 * statistics.median(p[3] for p in own):>7.1f} "
                              f"{1000 * waiting:>7.1f} {one / span:>6.2f} "
                              f"{1000 * needed if j > 1 else float('nan'):>9.1f} "
                              f"{load:>4.1f}-{load_after:<4.1f}", flush=True)
                continue
            if args.callgrind:
                if "ceiling" in name:
                    continue
                for label, checkout in builds:
                    first = 0
                    for j in jobs:
                        counts = [instructions([*argv, "-j", str(j)], work,
                                               build_env(checkout)) for argv in commands]
                        whole, before, after = (sum(c[k] for c in counts) for k in range(3))
                        workers = list(summed([tuple(c[3]) for c in counts]))
                        first = first or whole
                        ideal = first / (before + (after + sum(workers)) / j) if workers else 1.0
                        shown = " + ".join(f"{w / 1e9:.3f}" for w in workers) or "-"
                        print(f"{name:<34} {label:{width}} {j:>3} {whole / 1e9:>7.3f} "
                              f"{before / 1e9:>7.3f} {after / 1e9:>7.3f} {shown:>18} "
                              f"{ideal:>6.2f}", flush=True)
                continue
            load = os.getloadavg()[0]
            runs: dict[tuple[str, int], list[tuple[float, float, int, float, int]]] = {
                (label, j): [] for label, _ in builds for j in jobs}
            for _ in range(args.repeat):  # interleaved: 1, 2, 1, 2... (each build in turn)
                for label, checkout in builds:
                    if "ceiling" in name and label != builds[0][0]:
                        continue
                    for j in jobs:
                        each = [timed([*argv, "-j", str(j)], env=build_env(checkout))
                                for argv in commands]
                        runs[label, j].append((sum(e[0] for e in each),
                                               max(e[1] for e in each),
                                               max(e[2] for e in each),
                                               sum(e[3] for e in each),
                                               sum(e[4] for e in each)))
            load_after = os.getloadavg()[0]
            for label, _ in builds:
                if "ceiling" in name and label != builds[0][0]:
                    continue
                first_median = statistics.median(r[0] for r in runs[label, jobs[0]])
                for j in jobs:
                    own = runs[label, j]
                    median = statistics.median(r[0] for r in own)
                    times = j if "ceiling" in name else 1  # (N processes: N times the work)
                    print(f"{name:<34} {label:{width}} {j:>3} {median:>8.3f} "
                          f"{min(r[0] for r in own):>6.3f} "
                          f"{statistics.median(r[3] for r in own):>6.3f} "
                          f"{statistics.median(r[4] for r in own):>8.0f} "
                          f"{max(r[1] for r in own):>8.1f} "
                          f"{times * first_median / median:>8.2f} "
                          f"{load:>4.1f}-{load_after:<4.1f} {max(r[2] for r in own)}",
                          flush=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
