"""tapegate against an independent interpreter, LinuxCNC's ``rs274``, on the same real program.

    .venv/bin/python benchmarks/oracle.py [--blocks 1000000] [--timeout 600] [--keep DIR]

Builds the real program (benchmarks/real_program.py: the corpus's 1001.nc repeated to
``--blocks`` lines) and times, one after the other, each in its own process under
``/usr/bin/time -v`` (peak RSS), with a time limit of ``--timeout`` seconds each:

- ``rs274 -g -t TOOLS.tbl PROGRAM /dev/null < /dev/null``: LinuxCNC's standalone interpreter
  (Debian package linuxcnc-uspace) in batch mode, the canonical machine calls thrown away. The
  tool table is written here from the T words of the program (rs274 stops with "Requested tool N
  not found in the tool table" otherwise). Skipped, with a message, when rs274 is absent.
- ``tapegate check PROGRAM -p fanuc-mill --format json > /dev/null``
- ``tapegate parse PROGRAM --profile fanuc-mill --summary``

Exit codes are shown as they are: rs274 exits 1 at the first error, tapegate check exits 1 when a
finding is an error (the real program has TG601 travel-limit errors for fanuc-mill). blocks/s is
the program's line count over the wall time of the whole process (start-up included).
"""

from __future__ import annotations

import argparse
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))

from real_program import SOURCE, CorpusMissing, build, source_path  # noqa: E402

TIME = "/usr/bin/time"


@dataclass
class Run:
    name: str
    argv: list[str]
    shown: str  # the command as a person would type it
    rc: int | None = None  # None: timed out or not run
    seconds: float = 0.0
    rss_mb: float | None = None
    note: str = ""


def tapegate_exe() -> str | None:
    exe = ROOT / ".venv" / "bin" / "tapegate"
    return str(exe) if exe.exists() else shutil.which("tapegate")


def tool_table(program_source: Path, path: Path) -> None:
    """T1 P1 D.. Z0 for every tool the program names; the diameter from a ``(T1 D=6.35`` header
    comment when there is one (no cutter compensation uses it: it is for the record)."""
    text = program_source.read_text("ascii", "replace")
    diameters = {int(t): d for t, d in re.findall(r"\(T(\d+) D=([0-9.]+)", text)}
    code = re.sub(r"\([^)]*\)", "", text)
    tools = sorted({int(t) for t in re.findall(r"(?<![A-Z])T(\d+)", code)} - {0})
    path.write_text("".join(f"T{t} P{t} D{diameters.get(t, '0')} Z0 ;\n" for t in tools))


def measure(run: Run, timeout: float, stdout: int | None, workdir: Path) -> None:
    timefile = workdir / f"{run.name}.time"
    errfile = workdir / f"{run.name}.err"
    argv = ([TIME, "-v", "-o", str(timefile), *run.argv] if os.path.exists(TIME) else run.argv)
    with open(errfile, "wb") as err:
        t0 = time.perf_counter()
        p = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=stdout, stderr=err,
                             start_new_session=True)
        try:
            out, _ = p.communicate(timeout=timeout)
            run.rc = p.returncode
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)  # the group this run started, nothing else
            p.communicate()
            out = None
            run.note = f"timed out after {timeout:.0f} s (killed)"
        run.seconds = time.perf_counter() - t0
    if timefile.exists():
        m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", timefile.read_text())
        if m:
            run.rss_mb = int(m.group(1)) / 1024
    lines = [ln for ln in errfile.read_text("utf-8", "replace").splitlines()
             if ln.strip() and ln.strip() != "executing"]
    if out:
        run.note = run.note or out.decode("utf-8", "replace").strip().splitlines()[-1]
    elif lines and not run.note:
        run.note = " / ".join(lines[-2:])


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--blocks", type=int, default=1_000_000)
    parser.add_argument("--timeout", type=float, default=600.0, help="seconds per command")
    parser.add_argument("--source", default=SOURCE, help="corpus program to repeat")
    parser.add_argument("--keep", help="write the program and tool table to this folder")
    parser.add_argument("--only", default="rs274,check,parse")
    args = parser.parse_args(argv)
    only = set(args.only.split(","))

    with tempfile.TemporaryDirectory() as tmp:
        work = Path(args.keep) if args.keep else Path(tmp)
        work.mkdir(parents=True, exist_ok=True)
        program = work / "real_program.nc"
        try:
            src = source_path(args.source)
            t = time.perf_counter()
            built = build(program, args.blocks, src)
            made = time.perf_counter() - t
        except CorpusMissing as e:
            print(f"oracle: {e}", file=sys.stderr)
            return 2
        print(f"program: {src.name} x {built.copies:.2f} = {built.blocks:,} blocks, "
              f"{built.bytes / 1e6:.1f} MB, N wrapped {built.wraps} times (built in {made:.1f} s)")

        runs: list[Run] = []
        rs274 = shutil.which("rs274")
        if "rs274" in only and rs274 is None:
            print("rs274: not installed (apt-get install linuxcnc-uspace); skipped")
        elif "rs274" in only:
            lcnc = work / "real_program_linuxcnc.nc"
            build(lcnc, args.blocks, src, linuxcnc=True)
            if lcnc.read_bytes() == program.read_bytes():
                lcnc.unlink()
                lcnc = program
                print("rs274 reads the same file (nothing to strip for LinuxCNC)")
            else:
                print(f"rs274 reads {lcnc.name} (see real_program.linuxcnc_line)")
            tbl = work / "tools.tbl"
            tool_table(src, tbl)
            version = subprocess.run(["dpkg-query", "-W", "-f", "${Version}", "linuxcnc-uspace"],
                                     capture_output=True, text=True, check=False).stdout.strip()
            print(f"rs274: {rs274}, linuxcnc-uspace {version or '(version unknown)'}")
            runs.append(Run("rs274", [rs274, "-g", "-t", str(tbl), str(lcnc), "/dev/null"],
                            f"rs274 -g -t {tbl.name} {lcnc.name} /dev/null < /dev/null"))
        exe = tapegate_exe()
        if exe is None and only & {"check", "parse"}:
            print("tapegate: not found (make test creates .venv); skipped")
        else:
            if "check" in only:
                runs.append(Run("check", [exe, "check", str(program), "-p", "fanuc-mill",
                                          "--format", "json"],
                                f"tapegate check {program.name} -p fanuc-mill --format json "
                                "> /dev/null"))
            if "parse" in only:
                runs.append(Run("parse", [exe, "parse", str(program), "--profile", "fanuc-mill",
                                          "--summary"],
                                f"tapegate parse {program.name} --profile fanuc-mill --summary"))

        for run in runs:
            stdout = subprocess.PIPE if run.name == "parse" else subprocess.DEVNULL
            measure(run, args.timeout, stdout, work)

        print(f"\n{'command':8} {'exit':>4} {'seconds':>9} {'blocks/s':>10} {'peak MB':>8}  note")
        for r in runs:
            rate = f"{built.blocks / r.seconds:10,.0f}" if r.rc is not None else f"{'-':>10}"
            rss = f"{r.rss_mb:8.1f}" if r.rss_mb is not None else f"{'-':>8}"
            rc = f"{r.rc:4d}" if r.rc is not None else f"{'-':>4}"
            print(f"{r.name:8} {rc} {r.seconds:9.2f} {rate} {rss}  {r.note[:110]}")
        print("\ncommands (in " + str(work) + "):")
        for r in runs:
            print("  " + r.shown)
    return 0


if __name__ == "__main__":
    sys.exit(main())
