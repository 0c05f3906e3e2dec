"""The measure of the "one fast core" issue: whole commands, on a synthetic and a real program,
beside LinuxCNC's interpreter, in one run.

    .venv/bin/python benchmarks/core.py [--blocks 1000000] [--sizes 100000,1000000]
                                        [--only check,convert,parse,api,rs274,peer] [--keep DIR]

``--only`` also takes ``check-text``, ``check-jsonl`` and ``check-sarif`` (the check's other
output formats) and ``restart``.

Programs (built here, in a temporary folder, deleted afterwards unless ``--keep``):

- synthetic: ``benchmarks/program.py`` with ``--clean`` (what a CAM post writes);
- real: ``benchmarks/real_program.py``, the corpus's Fusion 360 Fanuc-post program repeated (needs
  ``../shared/corpus``; skipped with a message without it).

Each command runs in its own process under ``/usr/bin/time -v``: seconds are wall time of the
whole process (start-up included), peak MB its maximum resident set. The commands:

- ``tapegate check FILE -p fanuc-mill --format json > /dev/null`` (all rules);
- ``tapegate convert FILE -o OUT --from fanuc-mill --to implicit-inch.toml --units inch``
  (explicit metric to implicit inch, leading zeros omitted);
- ``tapegate parse FILE --profile fanuc-mill --summary``;
- the Python API: iterating ``parse_stream`` over Block objects;
- ``restart`` (only with ``--only restart``): the walk of ``send --restart-at`` to a block 100
  lines before the program's end, planned in the API (``postproc.restart.plan_restart_text``);
- ``rs274 -g -t TOOLS FILE /dev/null`` on the real program (Debian package linuxcnc-uspace);
- peer ``gcodeparser`` (``pip install gcodeparser``) reading the same programs, where installed.
"""

from __future__ import annotations

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))

import program  # noqa: E402
from real_program import CorpusMissing, build  # noqa: E402

IMPLICIT_INCH = ('name = "implicit-inch"\n'
                 'detailed = "%:/ N07 G02 X+044 Y+044 Z+044 I+044 J+044 K+044 F042 S05 T02 M02*"\n'
                 'units_codes = "G20/G21"\nunits = "inch"\n')
API = ("import sys\nfrom formats.parser import parse_stream, read_chunks, decode_chunks\n"
       "from formats.profile import load_profile\n"
       "n = sum(1 for b in parse_stream(decode_chunks(read_chunks(sys.argv[1])),"
       " load_profile('fanuc-mill').dialect))\n")
# send --restart-at's walk to the block: a restart planned 100 lines before the program's end
RESTART = ("import sys\nfrom formats.profile import load_profile\n"
           "from formats.source import Source\n"
           "from postproc.restart import RestartRefused, plan_restart_text\n"
           "lines = sum(1 for _ in open(sys.argv[1], 'rb'))\n"
           "try:\n    plan = plan_restart_text(Source(sys.argv[1]).chunks(),"
           " load_profile('fanuc-mill'), lines - 100)\n    print(plan.preamble)\n"
           "except RestartRefused as exc:\n    print(exc)\n")
PEER = ("import re, sys\nfrom gcodeparser import parse_gcode_lines\n"
        "text = re.sub(r'\\.(?![0-9])', '.0', open(sys.argv[1]).read())\n"
        "for _ in parse_gcode_lines(text):\n    pass\n")


def timed(argv: list[str], stdout: str | None = None) -> tuple[float, float, int]:
    """(seconds, peak MB, exit code) of a command under /usr/bin/time -v."""
    out = open(stdout, "w") if stdout else subprocess.DEVNULL  # noqa: SIM115
    try:
        proc = subprocess.run(["/usr/bin/time", "-v", *argv], stdout=out,
                              stderr=subprocess.PIPE, text=True, stdin=subprocess.DEVNULL,
                              check=False, cwd=ROOT)
    finally:
        if stdout:
            out.close()  # type: ignore[union-attr]
    err = proc.stderr
    wall = re.search(r"Elapsed \(wall clock\) time.*: (?:(\d+):)?(\d+):(\d+(?:\.\d+)?)", err)
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", err)
    seconds = 0.0
    if wall:
        hours = float(wall.group(1) or 0)
        seconds = hours * 3600 + float(wall.group(2)) * 60 + float(wall.group(3))
    return seconds, (int(rss.group(1)) / 1024 if rss else 0.0), proc.returncode


def tool_table(path: Path, table: Path) -> None:
    tools = sorted({int(t) for t in re.findall(r"\bT(\d+)", path.read_text(errors="replace"))})
    table.write_text("".join(f"T{t} P{t} D6.0 Z0 ;\n" for t in tools or [1]))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sizes", default="1000000", help="comma-separated block counts")
    parser.add_argument("--only", default="check,convert,parse,api,rs274,peer")
    parser.add_argument("--keep", help="keep the programs in this folder")
    args = parser.parse_args()
    only = set(args.only.split(","))
    tapegate = str(ROOT / ".venv" / "bin" / "tapegate")
    python = str(ROOT / ".venv" / "bin" / "python")
    work = Path(args.keep or tempfile.mkdtemp(prefix="tapegate-bench-"))
    work.mkdir(parents=True, exist_ok=True)
    target = work / "implicit-inch.toml"
    target.write_text(IMPLICIT_INCH)
    rs274 = shutil.which("rs274")
    peer = subprocess.run([python, "-c", "import gcodeparser"], capture_output=True,
                          check=False).returncode == 0
    print(f"{'program':<22} {'command':<34} {'seconds':>8} {'blocks/s':>11} {'peak MB':>8} rc")
    for size in (int(s) for s in args.sizes.split(",")):
        programs: list[tuple[str, Path]] = []
        synthetic = work / f"synthetic-{size}.nc"
        if not synthetic.exists():
            program.write(str(synthetic), size, clean=True)
        programs.append(("synthetic", synthetic))
        real = work / f"real-{size}.nc"
        try:
            if not real.exists():
                build(real, size)
            programs.append(("real", real))
        except CorpusMissing as exc:
            print(f"(real program skipped: {exc})")
        for name, path in programs:
            label = f"{name} {size:,}"
            jobs: list[tuple[str, list[str], str | None]] = []
            if "check" in only:
                jobs.append(("check --format json", [tapegate, "check", str(path), "-p",
                                                     "fanuc-mill", "--format", "json"], None))
            for fmt in ("text", "jsonl", "sarif"):
                if f"check-{fmt}" in only:
                    jobs.append((f"check --format {fmt}",
                                 [tapegate, "check", str(path), "-p", "fanuc-mill", "--format",
                                  fmt], None))
            if "convert" in only:
                jobs.append(("convert metric->implicit inch",
                             [tapegate, "convert", str(path), "-o", str(work / "out.nc"),
                              "--force", "--from", "fanuc-mill", "--to", str(target), "--units",
                              "inch"], None))
            if "parse" in only:
                jobs.append(("parse --summary", [tapegate, "parse", str(path), "--profile",
                                                 "fanuc-mill", "--summary"], None))
            if "api" in only:
                jobs.append(("API: parse_stream Blocks", [python, "-c", API, str(path)], None))
            if "restart" in only:
                jobs.append(("restart near the end", [python, "-c", RESTART, str(path)], None))
            if "peer" in only and peer:
                jobs.append(("peer gcodeparser", [python, "-c", PEER, str(path)], None))
            if "rs274" in only and rs274 and name == "real":
                table = work / "tools.tbl"
                tool_table(path, table)
                jobs.append(("LinuxCNC rs274", [rs274, "-g", "-t", str(table), str(path),
                                                "/dev/null"], None))
            for command, argv, stdout in jobs:
                seconds, rss, rc = timed(argv, stdout)
                rate = size / seconds if seconds else 0
                print(f"{label:<22} {command:<34} {seconds:>8.2f} {rate:>11,.0f} {rss:>8.1f} {rc}",
                      flush=True)
            if (work / "out.nc").exists():
                os.unlink(work / "out.nc")
    if not args.keep:
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
